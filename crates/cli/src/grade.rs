//! `cg grade <SUBMISSIONS>`: grades every submission with the kit's own checks in a sandbox
//! (instructors); see `cg_grade` and docs/instructor-guide.md.

use std::path::PathBuf;
use std::time::Duration;

use cg_core::lang::Lang;
use cg_grade::{Config, Graded, Options};

/// Options of `cg grade`.
#[derive(clap::Args)]
pub struct Args {
    /// The folder of submissions: each entry a folder or a .zip holding exercises/ / 提出物のフォルダ（各項目がフォルダか .zip）
    submissions: PathBuf,
    /// Where the results go / 結果の出力先
    #[arg(long, default_value = "grades")]
    out: PathBuf,
    /// Points per check (TOML: default = 1, `[points]` by check-ID prefix) / 配点の設定ファイル
    #[arg(long, value_name = "TOML")]
    config: Option<PathBuf>,
    /// Submissions graded at once (default: the number of cores) / 同時に採点する数
    #[arg(long, value_name = "N")]
    jobs: Option<usize>,
    /// Seconds one check may spend in a submission's functions / 1 つのチェックが提出物の関数に使える時間（秒）
    #[arg(long, value_name = "S", default_value_t = 20)]
    time_limit: u64,
    /// Memory the worker running a submission's functions may use, in MB / 提出物の関数を動かすプロセスのメモリ上限（MB）
    #[arg(long, value_name = "MB", default_value_t = 2048)]
    memory_limit: u64,
    /// The class roster (CSV: student, name, entry = the entry's folder or zip name, or its Moodle participant ID): binds each entry to its student / 名簿（CSV: 学生番号・氏名・提出物のフォルダ名か Moodle の参加者 ID）
    #[arg(long, value_name = "CSV")]
    roster: Option<PathBuf>,
    /// Grade even without bubblewrap: the students' code then runs as you, unisolated (every result says so) / bubblewrap なしでも採点する（学生のコードが隔離されずに動きます）
    #[arg(long)]
    unsafe_no_sandbox: bool,
}

/// `cg grade`.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    let kit = crate::kit_path(None, ".");
    if !kit.join("solutions/Cargo.toml").exists() {
        return Err(lang
            .pick(
                "solutions/ がありません（採点は、キット本体のリポジトリで行います）",
                "there is no solutions/ here: grading runs in the kit's own repository",
            )
            .to_owned());
    }
    let config_text = match &args.config {
        Some(path) => {
            std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?
        }
        None => String::new(),
    };
    let config = Config::parse(&config_text).map_err(|e| e.message(lang).to_owned())?;
    let roster = match &args.roster {
        Some(path) => {
            Some(cg_grade::roster::Roster::read(path).map_err(|e| e.get(lang).to_owned())?)
        }
        None => None,
    };
    let isolation = cg_sandbox::detect();
    cg_grade::require_isolation(isolation, args.unsafe_no_sandbox)
        .map_err(|why| why.get(lang).to_owned())?;
    let options = Options {
        kit,
        submissions: args.submissions.clone(),
        out: args.out.clone(),
        config,
        config_text,
        jobs: args
            .jobs
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from)),
        limits: cg_sandbox::Limits {
            wall: Duration::from_secs(args.time_limit.max(1)),
            memory_bytes: args.memory_limit.max(64) << 20,
            ..cg_sandbox::Limits::default()
        },
        build_limit: Duration::from_secs(1800),
        isolation,
        lang,
        roster,
    };
    eprintln!("{}: {}", lang.pick("隔離", "isolation"), isolation.describe(lang));
    let progress = |g: &Graded| {
        let max = g.max_score.map(|m| format!(" / {m}")).unwrap_or_default();
        let note = if g.skipped { lang.pick("（前回の結果）", " (kept)") } else { "" };
        println!("{} ({}): {}{max}{note}", g.name, g.entry, g.score);
    };
    let graded =
        cg_grade::grade(&options, cg_sandbox::launch, &progress).map_err(|e| e.to_string())?;
    println!(
        "{} {} {}: {}",
        graded.len(),
        lang.pick("件の結果", "results in"),
        args.out.display(),
        lang.pick(
            "class.csv, summary.md, <学生番号>.json",
            "class.csv, summary.md, <student>.json"
        )
    );
    Ok(())
}
