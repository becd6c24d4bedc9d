//! `report-checker` — the report checker on its own: `report-checker derive|fill|check`, the
//! same commands as `cg report …` (one implementation, [`cg_report::app`]).

use std::process::ExitCode;

use cg_core::lang::Lang;
use clap::Parser;

#[derive(Parser)]
#[command(
    name = "report-checker",
    version,
    about = "The report checker: derives your report's tables, figures and matrices, fills the template, checks your numbers / レポートの表・図・行列の導出、ひな形の作成、数値の確認"
)]
struct Cli {
    /// Language of the output: ja or en (default: from CG_LANG or LANG, else the system's language) / 出力の言語（省略時は CG_LANG・LANG、なければシステムの言語）
    #[arg(long, global = true, value_name = "ja|en")]
    lang: Option<Lang>,
    #[command(subcommand)]
    command: cg_report::app::Command,
}

fn main() -> ExitCode {
    let cli: Cli = cg_harness::args::parse();
    let lang = cli.lang.unwrap_or_else(Lang::from_env);
    let result = cg_report::app::run(&cli.command, &cg_report::app::Kit::exercises(), lang);
    // The kit's exit statuses: 0 ok, 1 mistakes found, 2 bad input or usage, 3 out of time.
    cg_harness::exit::finish(result, lang)
}
