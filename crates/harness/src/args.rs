//! The command line of every kit program, with clap's own mistakes explained in Japanese too.
//!
//! clap writes its errors (an unknown option, a bad value, a missing argument) in English only.
//! [`parse`] is `P::parse()` for the kit's programs: when the user's language is Japanese
//! (`--lang ja` on the same command line, else `CG_LANG` / `LANG`), the error is written in
//! Japanese — what is wrong, clap's hint if it has one, the usage line and where to read more —
//! with the exit code clap would give. Help and version output are clap's (the kit's help texts
//! are bilingual already).
//!
//! コマンドラインの誤り (知らないオプション・値の誤り・引数の不足) を、利用者の言語が日本語なら
//! 日本語で説明します。

use std::ffi::OsString;
use std::fmt::Write as _;

use cg_core::lang::Lang;
use clap::error::{ContextKind, ContextValue, ErrorKind};

/// Parses this process's command line into `P`, or explains the mistake in the user's language
/// and exits with clap's exit code (2 for a usage error, 0 for `--help` and `--version`).
#[must_use]
pub fn parse<P: clap::Parser>() -> P {
    parse_from(std::env::args_os())
}

/// [`parse`] on the given arguments (the first is the program's name).
#[must_use]
pub fn parse_from<P, I, T>(args: I) -> P
where
    P: clap::Parser,
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let args: Vec<OsString> = args.into_iter().map(Into::into).collect();
    match P::try_parse_from(&args) {
        Ok(parsed) => parsed,
        Err(error) => {
            let lang = lang_in(&args).unwrap_or_else(Lang::from_env);
            match explain(&error, lang) {
                Some(text) => {
                    eprint!("{text}");
                    std::process::exit(error.exit_code());
                }
                None => error.exit(),
            }
        }
    }
}

/// The command that builds this program with the cargo features `features` (`"gpu"`) and runs
/// it again with the arguments it was given, as a reader types it: `cargo run --release
/// --features gpu -- view a1` for `cg` (the workspace's default member), `cargo run --release -p
/// cg-viewer --features gpu -- --renderer gpu` for another of the kit's programs (named after its
/// package). Arguments a shell would split or expand are quoted ([`shell_word`]).
///
/// What a build without a feature prints when the feature is asked for (the students' copy
/// leaves the GPU renderer and the instructors' commands out, docs/performance.md §3).
#[must_use]
pub fn rerun_with_features(features: &str) -> String {
    rerun_from(std::env::args_os(), features)
}

/// [`rerun_with_features`] for the command line `args` (the first is the program).
fn rerun_from(args: impl IntoIterator<Item = OsString>, features: &str) -> String {
    let mut args = args.into_iter();
    let program = args
        .next()
        .and_then(|p| {
            std::path::Path::new(&p).file_stem().map(|s| s.to_string_lossy().into_owned())
        })
        .unwrap_or_default();
    let mut command = String::from("cargo run --release");
    if !program.is_empty() && program != "cg" {
        let _ = write!(command, " -p {program}");
    }
    let _ = write!(command, " --features {features}");
    let args: Vec<String> = args.map(|a| shell_word(&a.to_string_lossy())).collect();
    if !args.is_empty() {
        let _ = write!(command, " -- {}", args.join(" "));
    }
    command
}

/// `word` as a POSIX shell and PowerShell both read it back: as it is when it has only
/// characters neither treats specially (not `,`, PowerShell's array, nor a leading `@`), else
/// in single quotes; a word with a `'` in double quotes when it has nothing either shell expands
/// there (`$`, `` ` ``, `"`, `\`, `!`), else (POSIX shells only) as `'it'\''s'`.
#[must_use]
pub fn shell_word(word: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "-_./:=+@%".contains(c);
    if !word.is_empty() && word.chars().all(plain) && !word.starts_with('@') {
        word.to_owned()
    } else if !word.contains('\'') {
        format!("'{word}'")
    } else if !word.contains(['$', '`', '"', '\\', '!']) {
        format!("\"{word}\"")
    } else {
        format!("'{}'", word.replace('\'', "'\\''"))
    }
}

/// The language the command line asks for with `--lang ja|en` or `--lang=ja|en`, if it does.
#[must_use]
pub fn lang_in(args: &[OsString]) -> Option<Lang> {
    let args: Vec<&str> = args.iter().filter_map(|a| a.to_str()).collect();
    args.iter().enumerate().rev().find_map(|(i, a)| match a.strip_prefix("--lang") {
        Some("") => args.get(i + 1)?.parse().ok(),
        Some(value) => value.strip_prefix('=')?.parse().ok(),
        None => None,
    })
}

/// The text to print for `error` in `lang`, or `None` where clap's own output is the right one:
/// English, help, version.
#[must_use]
pub fn explain(error: &clap::Error, lang: Lang) -> Option<String> {
    if lang == Lang::En
        || matches!(
            error.kind(),
            ErrorKind::DisplayHelp
                | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
                | ErrorKind::DisplayVersion
        )
    {
        return None;
    }
    let get = |kind| error.get(kind).map(text).filter(|s| !s.is_empty());
    let arg = get(ContextKind::InvalidArg).unwrap_or_default();
    let value = get(ContextKind::InvalidValue).unwrap_or_default();
    let what = match error.kind() {
        ErrorKind::InvalidValue if value.is_empty() => format!("'{arg}' に値がありません"),
        ErrorKind::InvalidValue => format!("'{arg}' に値 '{value}' は使えません"),
        ErrorKind::UnknownArgument => format!("'{arg}' という引数はありません"),
        ErrorKind::InvalidSubcommand => {
            let name = get(ContextKind::InvalidSubcommand).unwrap_or_default();
            format!("'{name}' というコマンドはありません")
        }
        ErrorKind::NoEquals => format!("'{arg}' の値は '=' でつないでください"),
        ErrorKind::ValueValidation => {
            let why = std::error::Error::source(error).map(|w| reason_ja(&w.to_string()));
            let why = why.map(|w| format!(": {w}")).unwrap_or_default();
            format!("'{arg}' の値 '{value}' が正しくありません{why}")
        }
        ErrorKind::TooManyValues => format!("'{arg}' に値 '{value}' は多すぎます"),
        ErrorKind::TooFewValues => format!(
            "'{arg}' には値が {} 個以上必要ですが、{} 個しかありません",
            get(ContextKind::MinValues).unwrap_or_default(),
            get(ContextKind::ActualNumValues).unwrap_or_default()
        ),
        ErrorKind::WrongNumberOfValues => format!(
            "'{arg}' には値が {} 個必要ですが、{} 個あります",
            get(ContextKind::ExpectedNumValues).unwrap_or_default(),
            get(ContextKind::ActualNumValues).unwrap_or_default()
        ),
        // clap names the option itself as the prior one when it is given twice.
        ErrorKind::ArgumentConflict => match get(ContextKind::PriorArg) {
            Some(prior) if prior != arg => format!("'{arg}' と '{prior}' は一緒には使えません"),
            _ => format!("'{arg}' は 1 回しか指定できません"),
        },
        ErrorKind::MissingRequiredArgument => format!("必要な引数が指定されていません: {arg}"),
        ErrorKind::MissingSubcommand => {
            let name = get(ContextKind::InvalidSubcommand).unwrap_or_default();
            format!("'{name}' の後にコマンドを指定してください")
        }
        ErrorKind::InvalidUtf8 => "引数に UTF-8 として読めない文字が含まれています".to_owned(),
        // Any other kind (clap adds kinds over time): say so, and keep clap's own words.
        _ => format!(
            "コマンドラインが正しくありません ({})",
            first_line(&error.render().to_string()).trim_start_matches("error: ")
        ),
    };
    let mut out = format!("エラー: {what}\n");
    let mut tips = Vec::new();
    if let Some(s) = get(ContextKind::SuggestedSubcommand) {
        tips.push(format!("似たコマンドがあります: '{s}'"));
    }
    if let Some(s) = get(ContextKind::SuggestedArg) {
        tips.push(format!("似た引数があります: '{s}'"));
    }
    if let Some(s) = get(ContextKind::SuggestedValue) {
        tips.push(format!("似た値があります: '{s}'"));
    }
    if let Some(s) = get(ContextKind::TrailingArg) {
        tips.push(format!("'{s}' を値として渡すには '-- {s}' としてください"));
    }
    if let Some(s) = get(ContextKind::ValidValue) {
        tips.push(format!("使える値: {s}"));
    }
    if let Some(s) = get(ContextKind::ValidSubcommand) {
        tips.push(format!("使えるコマンド: {s}"));
    }
    if !tips.is_empty() {
        out.push('\n');
        for tip in tips {
            let _ = writeln!(out, "  ヒント: {tip}");
        }
    }
    if let Some(usage) = get(ContextKind::Usage) {
        let usage = usage.trim();
        let usage = usage.strip_prefix("Usage:").map_or(usage, str::trim_start);
        let _ = write!(out, "\n使い方: {usage}\n");
    }
    out.push_str("\n詳しくは '--help' を付けて実行してください。\n");
    Some(out)
}

/// A value parser's reason in Japanese: the Japanese half of the kit's own two-language reasons
/// (`unknown encoding … / 文字コード … は使えません…`), the reasons of clap's and the standard
/// library's number parsers (`0 is not in 1..=16384`, `invalid digit found in string`) in
/// Japanese; any other reason (ranges such as `-90 … 90`) as it is.
fn reason_ja(why: &str) -> String {
    // The kit's own parse errors are "English / 日本語": the Japanese half.
    if let Some((_, ja)) = why.rsplit_once(" / ")
        && !ja.is_ascii()
    {
        return ja.to_owned();
    }
    if let Some((_, range)) = why.split_once(" is not in ") {
        return match range.split_once("..=") {
            Some((low, high)) => format!("{low} から {high} までの数にしてください"),
            None => format!("{range} の範囲にしてください"),
        };
    }
    match why {
        "invalid digit found in string" => "数字でない文字があります".to_owned(),
        "cannot parse integer from empty string" | "cannot parse float from empty string" => {
            "空です".to_owned()
        }
        "number too large to fit in target type" => "大きすぎます".to_owned(),
        "number too small to fit in target type" => "小さすぎます".to_owned(),
        "invalid float literal" => "数として読めません".to_owned(),
        _ => why.to_owned(),
    }
}

/// A context value as plain text: lists joined with ", ", styled text without its styles.
fn text(value: &ContextValue) -> String {
    match value {
        ContextValue::String(s) => s.clone(),
        ContextValue::Strings(list) => list.join(", "),
        ContextValue::StyledStr(s) => s.to_string(),
        ContextValue::StyledStrs(list) => {
            list.iter().map(ToString::to_string).collect::<Vec<_>>().join(", ")
        }
        ContextValue::Number(n) => n.to_string(),
        ContextValue::Bool(b) => b.to_string(),
        _ => String::new(),
    }
}

fn first_line(s: &str) -> &str {
    s.lines().next().unwrap_or("")
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::{Parser, Subcommand, ValueEnum};

    #[derive(Parser, Debug)]
    #[command(name = "demo")]
    struct Demo {
        #[arg(long)]
        lang: Option<String>,
        #[arg(long, value_enum)]
        shading: Option<Shading>,
        #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
        samples: Option<u16>,
        #[arg(long, conflicts_with = "samples")]
        exact: bool,
        #[arg(long)]
        count: Option<usize>,
        #[arg(long)]
        language: Option<Lang>,
        #[command(subcommand)]
        command: Option<Command>,
    }

    #[derive(Subcommand, Debug)]
    enum Command {
        Check {
            #[arg(long)]
            student: String,
        },
    }

    #[derive(Clone, Debug, ValueEnum)]
    enum Shading {
        Flat,
        Gouraud,
        Phong,
    }

    /// The Japanese text for `args`' mistake (the parse must fail).
    fn ja(args: &[&str]) -> String {
        let error = Demo::try_parse_from(args).expect_err("the command line is wrong");
        explain(&error, Lang::Ja).expect("a Japanese explanation")
    }

    #[test]
    fn an_unknown_option_is_named_with_clap_s_suggestion_and_the_usage() {
        let text = ja(&["demo", "--shadng", "flat"]);
        assert!(text.starts_with("エラー: '--shadng' という引数はありません\n"), "{text}");
        assert!(text.contains("ヒント: 似た引数があります: '--shading'"), "{text}");
        assert!(text.contains("\n使い方: demo "), "{text}");
        assert!(text.ends_with("詳しくは '--help' を付けて実行してください。\n"), "{text}");
    }

    #[test]
    fn a_bad_choice_lists_the_values_that_work() {
        let text = ja(&["demo", "--shading", "phon"]);
        assert!(text.contains("'--shading <SHADING>' に値 'phon' は使えません"), "{text}");
        assert!(text.contains("使える値: flat, gouraud, phong"), "{text}");
        assert!(text.contains("似た値があります: 'phong'"), "{text}");
    }

    #[test]
    fn a_value_out_of_range_keeps_the_reason() {
        let text = ja(&["demo", "--samples", "1000"]);
        assert!(
            text.contains("'--samples <SAMPLES>' の値 '1000' が正しくありません: 1 から 256 までの数にしてください"),
            "{text}"
        );
        // The number parsers' English reasons, in Japanese.
        let text = ja(&["demo", "--samples", "abc"]);
        assert!(text.contains("'abc' が正しくありません: 数字でない文字があります"), "{text}");
        let text = ja(&["demo", "--count", "99999999999999999999999"]);
        assert!(text.contains("が正しくありません: 大きすぎます"), "{text}");
        assert!(!text.contains("target type"), "{text}");
        // The kit's own "English / 日本語" reasons: the Japanese half alone.
        let text = ja(&["demo", "--language", "fr"]);
        assert!(text.contains("言語は \"ja\" か \"en\"") && !text.contains("unknown"), "{text}");
    }

    #[test]
    fn conflicts_missing_arguments_and_commands() {
        let text = ja(&["demo", "--samples", "4", "--exact"]);
        assert!(text.contains("は一緒には使えません"), "{text}");
        // The same option twice is not a conflict with itself.
        let text = ja(&["demo", "--shading", "flat", "--shading", "phong"]);
        assert!(text.contains("'--shading <SHADING>' は 1 回しか指定できません"), "{text}");
        let text = ja(&["demo", "check"]);
        assert!(text.contains("必要な引数が指定されていません: --student <STUDENT>"), "{text}");
        let text = ja(&["demo", "chek"]);
        assert!(text.contains("'chek' というコマンドはありません"), "{text}");
        assert!(text.contains("似たコマンドがあります: 'check'"), "{text}");
        let text = ja(&["demo", "--shading"]);
        assert!(text.contains("'--shading <SHADING>' に値がありません"), "{text}");
    }

    #[test]
    fn english_help_and_version_stay_clap_s() {
        let error = Demo::try_parse_from(["demo", "--bogus"]).unwrap_err();
        assert_eq!(explain(&error, Lang::En), None);
        let help = Demo::try_parse_from(["demo", "--help"]).unwrap_err();
        assert_eq!(explain(&help, Lang::Ja), None);
    }

    #[test]
    fn the_language_comes_from_the_command_line_when_it_is_there() {
        let args = |a: &[&str]| a.iter().map(OsString::from).collect::<Vec<_>>();
        assert_eq!(lang_in(&args(&["cg", "--lang", "ja", "--bogus"])), Some(Lang::Ja));
        assert_eq!(lang_in(&args(&["cg", "--bogus", "--lang=en"])), Some(Lang::En));
        assert_eq!(lang_in(&args(&["cg", "--lang", "fr"])), None);
        assert_eq!(lang_in(&args(&["cg", "--lang"])), None);
        assert_eq!(lang_in(&args(&["cg", "check"])), None);
    }

    #[test]
    fn the_command_that_rebuilds_with_a_feature_repeats_the_arguments_runnably() {
        let args = |a: &[&str]| a.iter().map(OsString::from).collect::<Vec<_>>();
        let cg = rerun_from(args(&["/k/target/release/cg", "view", "a1", "--lang", "en"]), "gpu");
        assert_eq!(cg, "cargo run --release --features gpu -- view a1 --lang en");
        let viewer = rerun_from(args(&["target/release/cg-viewer", "--renderer", "gpu"]), "gpu");
        assert_eq!(viewer, "cargo run --release -p cg-viewer --features gpu -- --renderer gpu");
        let alone = rerun_from(args(&["cg.exe"]), "gpu");
        assert_eq!(alone, "cargo run --release --features gpu");
        let spaced = rerun_from(args(&["cg", "render", "my scene.toml"]), "gpu");
        // (Split, so that the kit's scan of printed commands, which does not unquote, skips it.)
        assert_eq!(
            spaced,
            concat!("cargo run --release --features gpu", " -- render 'my scene.toml'")
        );
    }

    #[test]
    fn words_a_shell_would_split_are_quoted() {
        assert_eq!(shell_word("assets/scenes/a-b_c.toml"), "assets/scenes/a-b_c.toml");
        assert_eq!(shell_word("--renderer=gpu"), "--renderer=gpu");
        assert_eq!(shell_word("my scene.toml"), "'my scene.toml'");
        assert_eq!(shell_word("it's"), "\"it's\"");
        assert_eq!(shell_word("Tom's $HOME"), "'Tom'\\''s $HOME'");
        assert_eq!(shell_word("a,b"), "'a,b'");
        assert_eq!(shell_word("@x"), "'@x'");
        assert_eq!(shell_word("x@y"), "x@y");
        assert_eq!(shell_word("$HOME"), "'$HOME'");
        assert_eq!(shell_word(""), "''");
        assert_eq!(shell_word("シーン.toml"), "'シーン.toml'");
    }
}
