//! `cg` — the kit's command line.
//!
//! A thin front: parse the arguments, load what they name, call the libraries, print. Every
//! command prints Japanese or English (`--lang ja|en`, default from `CG_LANG` / `LANG`, else the
//! system's language: `cg_core::lang::Lang::from_env`).
//!
//! A library with a one-line binary (`src/main.rs`): the library's compilation can start as
//! soon as its dependencies' interfaces are known, beside theirs, where a binary would wait for
//! all of them to finish (about 8 s at the end of a cold build on 2 cores; docs/performance.md §3).

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use cg_core::lang::Lang;
use cg_harness::exit::Ending;
use clap::{Parser, Subcommand};

mod assignments;
mod bench;
mod doctor;
#[cfg(feature = "instructor")]
mod grade;
#[cfg(feature = "instructor")]
mod gradescope;
mod handin;
#[cfg(feature = "instructor")]
mod handout;
mod inspect;
mod instructor;
mod label;
#[cfg(test)]
mod printed;
#[cfg(feature = "instructor")]
mod progress;
mod reload;
mod render;
#[cfg(feature = "instructor")]
mod similarity;
mod view;
mod watch;

/// The seconds `--time-limit` may give one check: from one to a day. A larger value overflowed
/// the deadline's clock (a panic without a word).
const TIME_LIMIT_S: std::ops::RangeInclusive<u64> = 1..=86_400;

/// The MiB `--memory-limit` may give the worker: from 64 (less cannot start it) to 1 TiB. A
/// larger value wrapped to 0 bytes when made bytes, and every check then failed.
const MEMORY_LIMIT_MIB: std::ops::RangeInclusive<u64> = 64..=1 << 20;

/// The course's sample scene, relative to the kit's root.
const COURSE_SAMPLE: &str = "assets/scenes/course-sample.toml";

#[derive(Parser)]
#[command(
    name = "cg",
    version,
    about = "Computer-graphics teaching kit (lecture 11: shading) / CG 演習キット（第11回 シェーディング）",
    long_about = "Computer-graphics teaching kit (lecture 11: shading).\n\
                  CG 演習キット（第11回 シェーディング）。\n\n\
                  Without a command, draws the course's sample scene in every shading mode to out/.\n\
                  コマンドを省略すると、授業のサンプルシーンを 3 種類のシェーディングで描画して out/ に保存します。"
)]
struct Cli {
    /// Language of the output: ja or en (default: from CG_LANG or LANG, else the system's language) / 出力の言語（省略時は CG_LANG・LANG、なければシステムの言語）
    #[arg(long, global = true, value_name = "ja|en")]
    lang: Option<Lang>,
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Print a scene: mesh checks, vertex and face tables with face normals, model-view matrices
    /// as named products / シーンの頂点・面・法線・変換行列を表示
    Inspect(inspect::Args),
    /// Draw a scene to a PNG file and say what it cost / シーンを PNG に描画
    Render(render::Args),
    /// Print your assignments, from your student number / 学生番号から自分の課題を表示
    Assignment(assignments::AssignmentArgs),
    /// Check your exercises against your assignment / 自分の課題をチェック
    Check(assignments::CheckArgs),
    /// Check again on every save of your exercises (keys: h hint, n next, r rerun, q quit) / 保存するたびにチェック
    Watch(watch::Args),
    /// Draw your result (and the reference) to PNG files / 自分の結果（と参考解答）を描画
    View(view::ViewArgs),
    /// Your report: derive its tables and figures, fill the template, check your numbers / レポート: 表・図の導出、ひな形の作成、数値の確認
    #[command(subcommand)]
    Report(cg_report::app::Command),
    /// Put what grading reads (the six files of exercises/ and your report) in one zip to upload / 採点が読むファイル（exercises/ の 6 ファイルとレポート）を提出用の zip に
    Handin(handin::Args),
    // The kit maintainers' commands: they work on the kit's own repository (solutions/, docs/).
    // In a build without the instructors' commands (the students' copy, which has no solutions/)
    // they are hidden from `cg --help`, as the instructors' commands are.
    /// Regenerate exercises/ from solutions/ (kit maintainers) / solutions/ から exercises/ を生成（キット管理者用）
    #[cfg_attr(not(feature = "instructor"), command(hide = true))]
    SyncStubs,
    /// Measure speed against error and write docs/speed-vs-error.md with its plots (kit maintainers) / 速度と誤差を測り docs/speed-vs-error.md に書く（キット管理者用）
    #[cfg_attr(not(feature = "instructor"), command(hide = true))]
    Bench(bench::Args),
    // The instructors' commands: handout, grade, grade-one, autograder, similarity (feature
    // `instructor`; in a build without it, such as the students' copy, hidden, and each says
    // how to build it).
    #[command(flatten)]
    Instructor(instructor::Command),
    /// Which renderers and windows work on this machine, and why, each problem with its fix / このマシンで使えるレンダラとウィンドウ、使えない理由と対処
    Doctor(doctor::Args),
}

/// Ends quietly when the reader of our output goes away (`cg check | head`, or
/// `cg render 2>&1 | head`): printing to a closed pipe makes `println!` and `eprintln!` panic,
/// which is no error of the user's. Other panics print as usual.
fn quiet_on_closed_pipe() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let message = cg_worker::panic_message(info.payload()).unwrap_or_default();
        let printing = message.contains("failed printing to stdout")
            || message.contains("failed printing to stderr");
        if printing && message.contains("Broken pipe") {
            std::process::exit(141);
        }
        default(info);
    }));
}

/// Runs `cg` with the process's arguments, and says how it ended (0 ok, 1 mistakes found, 2 bad
/// input or usage, 3 the student's code ran out of time).
pub fn main() -> ExitCode {
    quiet_on_closed_pipe();
    let cli: Cli = cg_harness::args::parse();
    // `--lang` after a command that takes every argument as it comes (an instructors' command
    // in a build without them) is not parsed as the option: it still sets the language.
    let lang = cli
        .lang
        .or_else(|| cg_harness::args::lang_in(&std::env::args_os().collect::<Vec<_>>()))
        .unwrap_or_else(Lang::from_env);
    let ok = |r: Result<(), String>| r.map(|()| Ending::Ok);
    let result = match cli.command {
        Some(Command::Inspect(args)) => ok(inspect::run(&args, lang)),
        Some(Command::Render(args)) => ok(render::run(&args, lang)),
        Some(Command::Assignment(args)) => ok(assignments::assignment(&args, lang)),
        Some(Command::Check(args)) => assignments::check(&args, lang),
        Some(Command::View(args)) => view::run(&args, lang),
        Some(Command::Watch(args)) => ok(watch::run(&args, lang)),
        Some(Command::Report(command)) => {
            cg_report::app::run(&command, &cg_report::app::Kit::exercises(), lang)
        }
        Some(Command::SyncStubs) => ok(assignments::sync_stubs(lang)),
        Some(Command::Bench(args)) => ok(bench::run(&args, lang)),
        Some(Command::Instructor(command)) => instructor::run(&command, lang),
        Some(Command::Handin(args)) => handin::run(&args, lang),
        Some(Command::Doctor(args)) => ok(doctor::run(&args, lang)),
        None => ok(render::main_job(lang)),
    };
    // 0 ok, 1 mistakes found, 2 bad input or usage, 3 the student's code ran out of time.
    cg_harness::exit::finish(result, lang)
}

/// Resolves a path the user gave; for the kit's own default files, falls back to the kit's root
/// when the command runs from another directory.
fn kit_path(given: Option<&Path>, default: &str) -> PathBuf {
    cg_harness::kit_path(given, default)
}

#[cfg(test)]
mod tests {
    use clap::CommandFactory;

    use super::*;

    /// The kit maintainers' commands are listed, marked as theirs, where the instructors' are
    /// built (the kit's own repository); in the students' copy (no solutions/) `cg --help`
    /// leaves them out, as it leaves out the instructors' commands.
    #[test]
    fn the_maintainers_commands_are_listed_only_in_the_kits_own_build() {
        let help = Cli::command().render_long_help().to_string();
        for name in ["sync-stubs", "bench"] {
            let line = help.lines().find(|l| l.starts_with(&format!("  {name} ")));
            if cfg!(feature = "instructor") {
                let line = line.unwrap_or_else(|| panic!("{name} not in:\n{help}"));
                assert!(line.contains("(kit maintainers)"), "{line}");
                assert!(line.contains("（キット管理者用）"), "{line}");
            } else {
                assert!(line.is_none(), "{name} in:\n{help}");
            }
        }
        // Hidden, they still run (and say that they need the kit's own repository).
        assert!(matches!(
            Cli::try_parse_from(["cg", "sync-stubs"]).map(|c| c.command),
            Ok(Some(Command::SyncStubs))
        ));
    }
}
