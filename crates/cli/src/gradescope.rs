//! `cg grade-one <SUBMISSION> --out <DIR>`: one submission graded as `cg grade` grades each,
//! with Gradescope's `results.json` (Gradescope and any batch system that runs one container
//! per submission); `cg autograder --out autograder.zip`: the package Gradescope runs. See
//! `cg_grade::gradescope` and docs/instructor-guide.md.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use cg_core::lang::{Lang, t};
use cg_grade::{Options, gradescope};
use cg_harness::exit::Ending;

/// Options of `cg grade-one`.
#[derive(clap::Args)]
pub struct GradeOneArgs {
    /// The submission: a folder or a .zip holding exercises/ (Gradescope: /autograder/submission) / 提出物（exercises/ を含むフォルダか .zip）
    submission: PathBuf,
    /// Where results.json (Gradescope's format), STUDENT.json and feedback/ go / results.json（Gradescope の形式）・学生番号.json・feedback/ の出力先
    #[arg(long, default_value = "results")]
    out: PathBuf,
    /// The work folder: the kit's built copy, reused from run to run (default: --out) / 作業フォルダ（ビルドしたキットのコピー。既定: --out）
    #[arg(long, value_name = "DIR")]
    work: Option<PathBuf>,
    /// Points per check (TOML, as cg grade's) / 配点の設定ファイル（cg grade と同じ）
    #[arg(long, value_name = "TOML")]
    config: Option<PathBuf>,
    /// Seconds one check may spend in the submission's functions / 1 つのチェックが提出物の関数に使える時間（秒）
    #[arg(long, value_name = "S", default_value_t = cg_assign::local::CALL_LIMIT.as_secs(), value_parser = clap::value_parser!(u64).range(crate::TIME_LIMIT_S))]
    time_limit: u64,
    /// Memory the worker running the submission's functions may use, in MB / 提出物の関数を動かすプロセスのメモリ上限（MB）
    #[arg(long, value_name = "MB", default_value_t = cg_assign::local::MEMORY_MB, value_parser = clap::value_parser!(u64).range(crate::MEMORY_LIMIT_MIB))]
    memory_limit: u64,
    /// Grade even without bubblewrap: the student's code then runs unisolated (the result says so) / bubblewrap なしでも採点する（学生のコードが隔離されずに動きます）
    #[arg(long)]
    unsafe_no_sandbox: bool,
}

/// Options of `cg autograder`.
#[derive(clap::Args)]
pub struct AutograderArgs {
    /// The zip to write (upload it as the assignment's autograder on Gradescope) / 書き出す zip（Gradescope の課題のオートグレーダーとしてアップロード）
    #[arg(long, default_value = "autograder.zip")]
    out: PathBuf,
}

/// `cg grade-one`: on any failure still writes `results.json` (score 0, the reason).
pub fn grade_one(args: &GradeOneArgs, lang: Lang) -> Result<Ending, String> {
    let started = Instant::now();
    let result = grade_one_inner(args, lang);
    if let Err(why) = &result {
        let value = gradescope::failure_json(why, started.elapsed());
        let path = args.out.join("results.json");
        let text = serde_json::to_string_pretty(&value).unwrap_or_default();
        let written = std::fs::create_dir_all(&args.out)
            .and_then(|()| cg_grade::write_atomic(&path, text.as_bytes()));
        if let Err(e) = written {
            eprintln!("{}", cg_core::lang::Text::io_at(&path, &e).get(lang));
        }
    }
    result
}

fn grade_one_inner(args: &GradeOneArgs, lang: Lang) -> Result<Ending, String> {
    let setup = crate::grade::Setup::new(args.config.as_deref(), args.unsafe_no_sandbox, lang)?;
    let options = Options {
        kit: setup.kit,
        submissions: args.submission.clone(),
        out: args.work.clone().unwrap_or_else(|| args.out.clone()),
        config: setup.config,
        config_text: setup.config_text,
        jobs: 1,
        limits: crate::grade::limits(args.time_limit, args.memory_limit),
        build_limit: Duration::from_secs(1800),
        isolation: setup.isolation,
        lang,
        roster: None,
        reports: None,
    };
    let progress = crate::progress::Progress::new(lang);
    let one =
        gradescope::grade_one(&options, &args.submission, &args.out, cg_sandbox::launch, &|e| {
            progress.event(e)
        });
    progress.finish();
    let one = one.map_err(|e| e.message(lang).to_owned())?;
    // A slip of the kit's against the specification is the instructor's to see (stdout), not a
    // reason to take the student's score away.
    for p in gradescope::problems(&one.results) {
        eprintln!("results.json: {p}");
    }
    println!(
        "{}: {} ({})",
        one.path.display(),
        one.results["score"],
        t("Gradescope の形式", "Gradescope's format").get(lang)
    );
    // Not graded at all (no student.toml, not a zip, …): its results.json says why with score
    // 0; the exit status says it too, so that a batch system's job tells "nothing could be
    // graded" from "graded 0".
    if let Some(why) = cg_grade::result::not_graded(&one.results["extra_data"]["cg"], lang) {
        // The reason may quote a name from the submission: no escape of its reaches the terminal.
        eprintln!(
            "{}: {}",
            t("採点できませんでした", "not graded").get(lang),
            cg_core::quote::visible(why)
        );
        return Ok(Ending::BadInput);
    }
    Ok(Ending::Ok)
}

/// `cg autograder`.
pub fn autograder(args: &AutograderArgs, lang: Lang) -> Result<(), String> {
    let kit = crate::instructor::kit_root(
        &t("オートグレーダーは、", "the autograder is made from"),
        lang,
    )?;
    let count = gradescope::package::write_zip(&kit, &args.out, lang)
        .map_err(|e| e.get(lang).to_owned())?;
    if let Some(note) = cg_grade::handout::untracked_note(&kit) {
        eprintln!("{}", note.get(lang));
    }
    println!(
        "{} {} (setup.sh, run_autograder, {count} {})",
        t("オートグレーダーを書きました:", "wrote the autograder to").get(lang),
        args.out.display(),
        t(
            "ファイル（solutions/ を含む。学生に配らないでください）",
            "files, solutions/ included: never hand it out"
        )
        .get(lang)
    );
    Ok(())
}
