//! `cg-check-runner`: prints a student's check reports as JSON (see the crate's documentation).

use std::io::Write;
use std::process::ExitCode;
use std::time::Duration;

use cg_assign::{Variants, Which};
use cg_check_runner::{report, to_json};
use cg_core::lang::Lang;
use cg_harness::check::Report;
use clap::Parser;

/// Runs a student's checks and prints the reports as JSON / 学生のチェックを実行し、結果を JSON で出力
#[derive(Parser)]
#[command(name = "cg-check-runner", version)]
struct Args {
    /// The student number (default: exercises/student.toml) / 学生番号
    #[arg(long, value_name = "NUMBER")]
    student: Option<String>,
    /// Only this assignment (default: all) / この課題だけ（省略するとすべて）
    #[arg(long, value_enum)]
    only: Option<Which>,
    /// Seconds one check may run before it is taken for an endless loop / 1 つのチェックの制限時間（秒）
    #[arg(long, default_value_t = 20)]
    time_limit: u64,
    /// Language of messages: ja or en (default: from CG_LANG or LANG) / メッセージの言語
    #[arg(long, value_name = "ja|en")]
    lang: Option<Lang>,
}

fn main() -> ExitCode {
    let args: Args = cg_harness::args::parse();
    let lang = args.lang.unwrap_or_else(Lang::from_env);
    let file = cg_harness::kit_path(None, "exercises").join("student.toml");
    let record = match cg_assign::resolve_student(args.student.as_deref(), None, &file, lang) {
        Ok(r) => r,
        Err(message) => {
            eprintln!("{}: {message}", lang.pick("エラー", "error"));
            return ExitCode::from(2);
        }
    };
    let a = Variants::for_student(&record.student, record.table);
    cg_harness::check::watchdog(Duration::from_secs(args.time_limit.max(1)), lang);
    let which: Vec<Which> = args.only.map_or_else(|| Which::ALL.to_vec(), |w| vec![w]);
    let reports: Vec<Report> = which.iter().map(|&w| report(w, &a)).collect();
    let json = serde_json::to_string_pretty(&to_json(&reports)).unwrap_or_default();
    // A reader that went away (`| head`) is no error of the student's: end quietly.
    if writeln!(std::io::stdout().lock(), "{json}").is_err() {
        return ExitCode::from(141);
    }
    if reports.iter().all(Report::all_passed) { ExitCode::SUCCESS } else { ExitCode::FAILURE }
}
