//! `cg grade <SUBMISSIONS>`: grades every submission with the kit's own checks in a sandbox
//! (instructors); see `cg_grade` and docs/instructor-guide.md.

use std::path::{Path, PathBuf};
use std::time::Duration;

use cg_core::lang::{Lang, Text, t};
use cg_grade::{Config, Graded, Options};

/// Options of `cg grade`.
#[derive(clap::Args)]
pub struct Args {
    /// The folder of submissions (each entry a folder or a .zip holding exercises/), or Moodle's "Download all submissions" as it comes (the .zip or its folder) / 提出物のフォルダ（各項目がフォルダか .zip）、または Moodle の「すべての提出をダウンロードする」の .zip かそのフォルダ
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
    #[arg(long, value_name = "S", default_value_t = cg_assign::local::CALL_LIMIT.as_secs(), value_parser = clap::value_parser!(u64).range(crate::TIME_LIMIT_S))]
    time_limit: u64,
    /// Memory the worker running a submission's functions may use, in MB / 提出物の関数を動かすプロセスのメモリ上限（MB）
    #[arg(long, value_name = "MB", default_value_t = cg_assign::local::MEMORY_MB, value_parser = clap::value_parser!(u64).range(crate::MEMORY_LIMIT_MIB))]
    memory_limit: u64,
    /// The class roster (CSV: student, name, entry = the entry's folder or zip name, or its Moodle participant ID): binds each entry to its student / 名簿（CSV: 学生番号・氏名・提出物のフォルダ名か Moodle の参加者 ID）
    #[arg(long, value_name = "CSV")]
    roster: Option<PathBuf>,
    /// A folder of reports handed in on their own, each file named with its student number (20260001.md, report-20260001.tex): its numbers checked (not scored) instead of the report inside that student's submission / 別に提出されたレポートのフォルダ（ファイル名に学生番号を含める）。提出物の中のレポートの代わりに、その数値を確かめます（点数には入りません）
    #[arg(long, value_name = "DIR")]
    reports: Option<PathBuf>,
    /// The language of the course's Moodle, for moodle/grades.csv's column names: ja or en (default: the output's) / Moodle の言語（moodle/grades.csv の列名。既定: 出力の言語）
    #[arg(long, value_name = "ja|en")]
    moodle_lang: Option<Lang>,
    /// The Moodle assignment's maximum grade: scores are scaled to it in moodle/grades.csv / Moodle の課題の最大評点（moodle/grades.csv の評点はこれに換算）
    #[arg(long, value_name = "POINTS", default_value_t = 100.0)]
    moodle_max_grade: f64,
    /// Grade even without bubblewrap: the students' code then runs as you, unisolated (every result says so) / bubblewrap なしでも採点する（学生のコードが隔離されずに動きます）
    #[arg(long)]
    unsafe_no_sandbox: bool,
}

/// What `cg grade` and `cg grade-one` start from: the kit (with its solutions), the grading
/// configuration and its text, and the sandbox.
pub(crate) struct Setup {
    pub kit: PathBuf,
    pub config: Config,
    pub config_text: String,
    pub isolation: cg_sandbox::Isolation,
}

impl Setup {
    /// Finds the kit, reads `config`, and requires the sandbox (or `unsafe_no_sandbox`).
    pub(crate) fn new(
        config: Option<&std::path::Path>,
        unsafe_no_sandbox: bool,
        lang: Lang,
    ) -> Result<Setup, String> {
        let kit = crate::instructor::kit_root(&t("採点は、", "grading runs in"), lang)?;
        // Read as the kit reads a text file (UTF-8, UTF-16, Shift_JIS), at most 1 MiB: a
        // FIFO or /dev/zero is an error, not a hang or the machine's memory.
        let config_text = match config {
            Some(path) => cg_core::text::read_bounded(path, 1 << 20)
                .and_then(|bytes| Ok(cg_core::text::decode(&bytes, None)?.0))
                .map_err(|e| {
                    let why = e.text_without_option();
                    format!("{}: {}", path.display(), why.get(lang))
                })?,
            None => String::new(),
        };
        let config = Config::parse(&config_text).map_err(|e| e.message(lang).to_owned())?;
        let isolation = cg_sandbox::detect();
        cg_grade::require_isolation(isolation, unsafe_no_sandbox)
            .map_err(|why| why.get(lang).to_owned())?;
        eprintln!("{}: {}", t("隔離", "isolation").get(lang), isolation.describe(lang));
        Ok(Setup { kit, config, config_text, isolation })
    }
}

/// The limits of one run of the student's code: `time_limit` seconds, `memory_limit` MiB.
pub(crate) fn limits(time_limit: u64, memory_limit: u64) -> cg_sandbox::Limits {
    cg_sandbox::Limits {
        wall: Duration::from_secs(time_limit.max(1)),
        memory_bytes: memory_limit.max(64).saturating_mul(1 << 20),
        ..cg_sandbox::Limits::default()
    }
}

/// Why `cg grade` ends as bad input (exit 2) although it wrote every result: it saw entries in
/// `submissions` and graded none of them (each refused, or not gradable: a wrong folder given,
/// every upload a `.rar`). `None` when one was graded; an empty folder is an error before this.
/// A class of which some were graded ends 0: the count line says how many were not.
#[must_use]
pub fn nothing_graded(graded: &[Graded], submissions: &Path) -> Option<Text> {
    if graded.is_empty() || graded.iter().any(|g| g.problem.is_none()) {
        return None;
    }
    let count = graded.len();
    let shown = cg_core::quote::visible(&submissions.display().to_string());
    Some(Text::new(
        format!(
            "{shown} の {count} 件はどれも採点されていません（理由は上の各行と summary.md の「採点できなかった提出物」）。{shown} が提出物のフォルダか Moodle の「すべての提出をダウンロードする」のものか確かめてください"
        ),
        format!(
            "none of the {count} entries of {shown} was graded (why: on each line above and in summary.md's \"Not graded\"): check that {shown} is the folder of submissions or Moodle's \"Download all submissions\""
        ),
    ))
}

/// `cg grade`.
///
/// # Errors
/// What stopped it (printed, exit 2); also when every entry it saw was refused
/// ([`nothing_graded`]), after writing their results.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    if !(args.moodle_max_grade.is_finite() && args.moodle_max_grade > 0.0) {
        return Err(t(
            "--moodle-max-grade は正の数にしてください",
            "--moodle-max-grade must be a positive number",
        )
        .get(lang)
        .to_owned());
    }
    let roster = match &args.roster {
        Some(path) => {
            Some(cg_grade::roster::Roster::read(path).map_err(|e| e.get(lang).to_owned())?)
        }
        None => None,
    };
    let setup = Setup::new(args.config.as_deref(), args.unsafe_no_sandbox, lang)?;
    let options = Options {
        kit: setup.kit,
        submissions: args.submissions.clone(),
        out: args.out.clone(),
        config: setup.config,
        config_text: setup.config_text,
        jobs: args
            .jobs
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from)),
        limits: limits(args.time_limit, args.memory_limit),
        build_limit: Duration::from_secs(1800),
        isolation: setup.isolation,
        lang,
        roster,
        reports: args.reports.clone(),
    };
    // A line per submission (logs), and a bar on a terminal: building, N of M, time left.
    let progress = crate::progress::Progress::new(lang);
    let graded = cg_grade::grade_with(&options, cg_sandbox::launch, &|e| progress.event(e), None);
    progress.finish();
    let graded = graded.map_err(|e| e.message(lang).to_owned())?;
    println!(
        "{} {} {}: {}",
        graded.len(),
        t("件の結果", "results in").get(lang),
        args.out.display(),
        t(
            "class.csv, summary.md, <学生番号>.json, feedback/",
            "class.csv, summary.md, <student>.json, feedback/"
        )
        .get(lang)
    );
    if let Some(reports) = cg_grade::progress::reports_line(&graded) {
        println!("{}", reports.get(lang));
    }
    let flagged = graded.iter().filter(|g| g.flag.is_some()).count();
    if flagged > 0 {
        println!(
            "{flagged} {}",
            t(
                "件に確認の印があります（class.csv の flag 列、summary.md）",
                "flagged for a look (class.csv's flag column, summary.md)"
            )
            .get(lang)
        );
    }
    let not_graded = graded.iter().filter(|g| g.problem.is_some()).count();
    if not_graded > 0 {
        println!(
            "{not_graded} {}",
            t(
                "件は採点されていません（理由は各行と summary.md の「採点できなかった提出物」）",
                "not graded (why: on each line and in summary.md's \"Not graded\")"
            )
            .get(lang)
        );
    }
    let now = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let settings = cg_grade::moodle::output::Settings {
        lang: args.moodle_lang.unwrap_or(lang),
        max_grade: args.moodle_max_grade,
        now,
    };
    if let Some(w) = cg_grade::moodle::output::write(&args.out, &graded, &settings)
        .map_err(|e| e.message(lang).to_owned())?
    {
        println!(
            "Moodle: {}/moodle/grades.csv, feedback.zip ({} {}, {} {})",
            args.out.display(),
            w.participants,
            t("人", "participants").get(lang),
            w.graded,
            t("人に評点", "with a grade").get(lang)
        );
    }
    // Results written, none graded: not exit 0, which read as a class graded.
    match nothing_graded(&graded, &args.submissions) {
        Some(why) => Err(why.get(lang).to_owned()),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn entry(name: &str, problem: Option<&str>) -> Graded {
        Graded {
            entry: name.to_owned(),
            name: format!("_{name}"),
            score: 0.0,
            max_score: None,
            skipped: false,
            flag: None,
            problem: problem
                .map(|p| Text::new(format!("受け付けられません: {p}"), format!("refused: {p}"))),
            report: None,
        }
    }

    /// Every entry refused (a wrong folder given, every upload a .rar) is not a class graded: it
    /// ended 0, as a class all graded does. Some graded and some refused still ends 0.
    #[test]
    fn a_run_that_graded_none_of_its_entries_says_so() {
        let folder = Path::new("Downloads/wrong");
        let refused = [entry("a.rar", Some("not a zip")), entry("b.pdf", Some("no exercises/"))];
        let why = nothing_graded(&refused, folder).expect("nothing graded");
        assert_eq!(
            why.en,
            "none of the 2 entries of Downloads/wrong was graded (why: on each line above and in summary.md's \"Not graded\"): check that Downloads/wrong is the folder of submissions or Moodle's \"Download all submissions\""
        );
        assert!(
            why.ja.starts_with("Downloads/wrong の 2 件はどれも採点されていません"),
            "{}",
            why.ja
        );
        // One graded: the count line says the rest.
        let mut some = refused.to_vec();
        some.push(entry("c.zip", None));
        assert_eq!(nothing_graded(&some, folder), None);
        // Kept from an earlier run, all refused: still nothing graded.
        let kept: Vec<Graded> =
            refused.iter().map(|g| Graded { skipped: true, ..g.clone() }).collect();
        assert!(nothing_graded(&kept, folder).is_some());
        assert_eq!(nothing_graded(&[], folder), None);
    }
}
