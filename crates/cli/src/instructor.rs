//! The instructors' commands — `handout`, `grade`, `grade-one`, `autograder`, `similarity` — and
//! the seam of cg-cli's `instructor` feature.
//!
//! The kit's own repository builds them by default. The students' copy (`cg handout`) builds
//! without them, so that its first `cargo build --release` does not compile the grading
//! pipeline, the sandbox, the copy finder, zip and the progress bar (issue 18,
//! docs/performance.md §3). There they are hidden from `cg --help`; a student who types one
//! (from the README or the instructors' guide, both in the copy) is told what it is and gets the
//! command that builds it, instead of clap's "unrecognized subcommand".
//!
//! 教員用のコマンド（handout・grade・grade-one・autograder・similarity）。学生用のコピーはこれらを
//! 含めずにビルドします（最初のビルドを速くするため）。`cg --help` には出ず、入力すると理由と、
//! これらを含めてビルドするコマンドを表示します。

use cg_core::lang::Lang;
#[cfg(not(feature = "instructor"))]
use cg_core::lang::{Text, t};
use cg_harness::exit::Ending;

/// The instructors' subcommands, as `cg`'s own ([`crate::Command`] flattens them in).
#[cfg(feature = "instructor")]
#[derive(clap::Subcommand)]
pub enum Command {
    /// Write the students' copy of the kit, without solutions/ (instructors) / 学生に配るコピーを作る（教員用）
    Handout(crate::handout::Args),
    /// Grade every submission (a folder, a zip, or Moodle's "download all submissions") with the kit's own checks, in a sandbox; Moodle's grading worksheet and feedback zip back (instructors) / 提出物（フォルダ・zip・Moodle の一括ダウンロード）をまとめて採点し、Moodle 用の評定ワークシートとフィードバックを書く（教員用）
    Grade(crate::grade::Args),
    /// Grade one submission as `cg grade` grades each, with Gradescope's results.json (Gradescope, or a batch system's job per submission) / 提出物 1 件を採点し、Gradescope の results.json を書く（Gradescope や、提出物ごとにジョブを動かすバッチシステム用。教員用）
    GradeOne(crate::gradescope::GradeOneArgs),
    /// Write the autograder zip Gradescope runs (setup.sh, run_autograder, the kit with solutions/; never hand it out) / Gradescope が動かすオートグレーダーの zip を書く（solutions/ を含むので配らないこと。教員用）
    Autograder(crate::gradescope::AutograderArgs),
    /// Look for copies: code fingerprinted by winnowing (stubs excluded, earlier years as references), the pairs above a threshold side by side, and numbers from another student's variant; writes similarity.html and similarity.csv (instructors) / コピーの検出: コードの指紋（スタブを除き、過去の年度と比較）、しきい値以上の組の対照表示、ほかの学生の課題の数値。similarity.html と similarity.csv を書く（教員用）
    Similarity(crate::similarity::Args),
}

/// Runs an instructors' command.
#[cfg(feature = "instructor")]
pub fn run(command: &Command, lang: Lang) -> Result<Ending, String> {
    let ok = |r: Result<(), String>| r.map(|()| Ending::Ok);
    match command {
        Command::Handout(args) => ok(crate::handout::run(args, lang)),
        Command::Grade(args) => ok(crate::grade::run(args, lang)),
        Command::GradeOne(args) => crate::gradescope::grade_one(args, lang),
        Command::Autograder(args) => ok(crate::gradescope::autograder(args, lang)),
        Command::Similarity(args) => crate::similarity::run(args, lang),
    }
}

/// The instructors' subcommands in a build without them: hidden, each takes whatever follows it
/// (`--help` too) and says how to build it.
#[cfg(not(feature = "instructor"))]
#[derive(clap::Subcommand)]
pub enum Command {
    #[command(hide = true, disable_help_flag = true)]
    Handout(LeftOut),
    #[command(hide = true, disable_help_flag = true)]
    Grade(LeftOut),
    #[command(hide = true, disable_help_flag = true)]
    GradeOne(LeftOut),
    #[command(hide = true, disable_help_flag = true)]
    Autograder(LeftOut),
    #[command(hide = true, disable_help_flag = true)]
    Similarity(LeftOut),
}

/// Whatever follows a left-out command's name, taken so that any arguments parse; the command
/// printed back repeats them from the process's own ([`cg_harness::args::rerun_with_features`]).
#[cfg(not(feature = "instructor"))]
#[derive(clap::Args)]
pub struct LeftOut {
    #[arg(num_args = 0.., allow_hyphen_values = true, trailing_var_arg = true)]
    #[allow(dead_code, reason = "taken, never read: see the struct's comment")]
    rest: Vec<std::ffi::OsString>,
}

/// An instructors' command in a build without them: why it is not here, and the command that
/// builds it (the arguments as given). The exit status is 2, as for a command `cg` does not know.
#[cfg(not(feature = "instructor"))]
pub fn run(command: &Command, lang: Lang) -> Result<Ending, String> {
    let name = match command {
        Command::Handout(_) => "handout",
        Command::Grade(_) => "grade",
        Command::GradeOne(_) => "grade-one",
        Command::Autograder(_) => "autograder",
        Command::Similarity(_) => "similarity",
    };
    let in_kit = std::env::current_dir()
        .is_ok_and(|here| here.ancestors().any(|d| d.join("solutions/Cargo.toml").is_file()));
    let command = cg_harness::args::rerun_with_features("instructor");
    Err(said(name, in_kit, &command).get(lang).to_owned())
}

/// What the left-out command `name` says, `in_kit`: whether the current folder is in the kit's
/// own repository (solutions/ at or above it). The instructors' commands work on that repository
/// only: in a copy without solutions/ (the students') the command that builds them could not
/// help, so it says where they run instead.
#[cfg(not(feature = "instructor"))]
fn said(name: &str, in_kit: bool, command: &str) -> Text {
    if in_kit { left_out(name, command) } else { elsewhere(name) }
}

/// What an instructors' command says in a copy without solutions/: it is run in the kit's own
/// repository.
#[cfg(not(feature = "instructor"))]
pub fn elsewhere(name: &str) -> Text {
    let what = if name == "handout" {
        t("学生用のコピーを作る", "that makes the students' copy")
    } else {
        t("採点などの", "for grading and the like")
    };
    Text::new(
        format!(
            "`{name}` は{}教員用のコマンドで、キット本体のリポジトリ（solutions/ があるもの）で教員が実行します。このコピーには solutions/ がないので、ここでは使えません",
            what.ja
        ),
        format!(
            "`{name}` is an instructors' command {}: the instructor runs it in the kit's own repository, the one with solutions/. This copy has no solutions/, so it cannot run here",
            what.en
        ),
    )
}

/// What an instructors' command says in a build without them: that it is one, where it runs,
/// and `command`, which builds it.
#[cfg(not(feature = "instructor"))]
pub fn left_out(name: &str, command: &str) -> Text {
    Text::new(
        format!(
            "`{name}` は教員用のコマンドです。学生用のコピーは、最初のビルドを速くするため教員用のコマンド（handout, grade, grade-one, autograder, similarity）を含めずにビルドします。教員用のコマンドはキット本体のリポジトリ（solutions/ があるもの）で使います。このコピーで教員用のコマンドを含めてビルドするには: {command}"
        ),
        format!(
            "`{name}` is an instructors' command: the students' copy is built without them (handout, grade, grade-one, autograder, similarity), so that its first build is faster. They are meant for the kit's own repository, the one with solutions/. To build them in this copy: {command}"
        ),
    )
}

#[cfg(all(test, not(feature = "instructor")))]
mod tests {
    use clap::{CommandFactory, Parser};

    use super::*;
    use crate::Cli;

    /// A build without them: `cg --help` does not list them, and each still parses, whatever
    /// follows it (`--help` too), so that its own message can answer.
    #[test]
    fn the_instructors_commands_are_hidden_and_each_takes_what_follows_it() {
        let help = Cli::command().render_long_help().to_string();
        for name in ["handout", "grade", "grade-one", "autograder", "similarity"] {
            assert!(!help.contains(&format!("\n  {name} ")), "{name} in:\n{help}");
        }
        for args in [
            &["cg", "grade", "submissions/", "--out", "grades", "--lang", "ja"][..],
            &["cg", "grade", "--help"],
            &["cg", "handout"],
            &["cg", "--lang", "ja", "similarity", "subs", "--threshold", "0.5"],
            &["cg", "grade-one", "--unsafe-no-sandbox"],
            &["cg", "autograder", "-o", "a.zip"],
        ] {
            let cli = Cli::try_parse_from(args).unwrap_or_else(|e| panic!("{args:?}: {e}"));
            assert!(matches!(cli.command, Some(crate::Command::Instructor(_))), "{args:?}");
        }
    }

    #[test]
    fn the_message_names_the_command_and_gives_the_one_that_builds_it() {
        let command = "cargo run --release --features instructor -- grade subs";
        let text = left_out("grade", command);
        for s in [&text.en, &text.ja] {
            assert!(
                s.contains("`grade`") && s.contains(command) && s.contains("solutions/"),
                "{s}"
            );
        }
        assert!(text.en.contains("instructors' command"), "{}", text.en);
        assert!(text.ja.contains("教員用のコマンド"), "{}", text.ja);
    }

    /// An instructors' command in a copy without solutions/ (the students') says where it runs
    /// instead of a build command that could not help; in the kit's own repository it gives the
    /// command.
    #[test]
    fn an_instructors_command_outside_the_kit_says_where_it_runs() {
        let command = "cargo run --release --features instructor -- handout /tmp/x";
        assert_eq!(said("handout", false, command), elsewhere("handout"));
        assert_eq!(said("handout", true, command), left_out("handout", command));
        assert_eq!(said("grade", false, command), elsewhere("grade"));
        assert!(elsewhere("handout").en.contains("makes the students' copy"));
        for s in [&elsewhere("grade").ja, &elsewhere("grade").en] {
            assert!(s.contains("solutions/") && !s.contains("--features"), "{s}");
        }
    }
}

/// The kit's own repository: the folder at or above the current one that holds
/// `solutions/Cargo.toml` (so an instructors' command runs from any folder of it, as git does),
/// canonical. `why` says what needs it (`配布用のコピーは` / `a handout is made from`).
///
/// # Errors
/// No such folder: said with where to run the command.
#[cfg(feature = "instructor")]
pub(crate) fn kit_root(
    why: &cg_core::lang::Text,
    lang: Lang,
) -> Result<std::path::PathBuf, String> {
    let here = std::env::current_dir().unwrap_or_default();
    here.ancestors()
        .find(|dir| dir.join("solutions/Cargo.toml").is_file())
        .map(|dir| dir.canonicalize().unwrap_or_else(|_| dir.to_path_buf()))
        .ok_or_else(|| {
            cg_core::lang::Text::new(
                format!(
                    "このフォルダにも上のフォルダにも solutions/ がありません（{}キット本体のリポジトリで実行します）",
                    why.ja
                ),
                format!(
                    "there is no solutions/ in this folder or above it ({} the kit's own repository: run it there)",
                    why.en
                ),
            )
            .get(lang)
            .to_owned()
        })
}
