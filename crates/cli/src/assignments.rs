//! `cg assignment`, `cg check` and `cg sync-stubs`: a student's own assignment, their
//! checks, and (for the kit's maintainers) the stubs regenerated from the solutions. `cg view`
//! is in [`crate::view`].

use std::path::PathBuf;
use std::time::Duration;

use cg_assign::{StudentFile, Variants, Which, write_student_file};
use cg_core::lang::{Lang, t};
use cg_harness::check::Report;
use cg_harness::exit::Ending;
use cg_harness::{TableVersion, Text};

/// Where the student's files are: `exercises/` of the kit being run.
fn exercises_dir() -> PathBuf {
    crate::kit_path(None, "exercises")
}

/// The student: `--student` when given, else `exercises/student.toml`.
pub(crate) fn student(
    given: Option<&str>,
    table: Option<TableVersion>,
    lang: Lang,
) -> Result<StudentFile, String> {
    cg_assign::resolve_student(given, table, &exercises_dir().join("student.toml"), lang)
}

/// Options of `cg assignment`.
#[derive(clap::Args)]
pub struct AssignmentArgs {
    /// Your 8-digit student number (default: the one in exercises/student.toml) / 学生番号（8 桁）
    #[arg(long, value_name = "NUMBER", allow_hyphen_values = true)]
    student: Option<String>,
    /// The variant table: 1 or 2 (default: the one in exercises/student.toml, else 1) / 課題表の版
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    table: Option<TableVersion>,
    /// Only this assignment / この課題だけ表示
    #[arg(long, value_enum)]
    only: Option<Which>,
    /// Print JSON for tools / JSON で出力
    #[arg(long)]
    json: bool,
    /// Record the number in exercises/student.toml, once / 学生番号を exercises/student.toml に記録
    #[arg(long)]
    save: bool,
}

/// `cg assignment`: prints one student's assignments.
pub fn assignment(args: &AssignmentArgs, lang: Lang) -> Result<(), String> {
    let record = student(args.student.as_deref(), args.table, lang)?;
    if args.save {
        let path = exercises_dir().join("student.toml");
        let before = cg_assign::read_student_file(&path).ok();
        write_student_file(&path, &record).map_err(|e| e.get(lang).to_owned())?;
        eprintln!("{} {}", t("記録しました:", "recorded in").get(lang), path.display());
        // Another number saved over the one recorded changes every check: said, not silent.
        if let Some(note) = before.and_then(|old| cg_assign::record_change(&old, &record)) {
            eprintln!("{}", note.get(lang));
        }
    }
    let a = Variants::for_student(&record.student, record.table);
    if args.json {
        let value = match args.only {
            None => a.to_json(),
            Some(w) => a.spec_json(w),
        };
        println!("{}", serde_json::to_string_pretty(&value).unwrap_or_default());
    } else {
        print!("{}", a.describe(lang, args.only));
    }
    Ok(())
}

/// What `cg check` runs: an assignment, and within it a task or one check.
#[derive(Clone, Debug)]
pub struct Selection {
    which: Which,
    /// `a3.t1` or `a1.t2.winding`; `None` for the whole assignment.
    only: Option<String>,
}

impl Selection {
    /// The ID as given: `a1`, `a3.t1`, `a1.t2.winding`.
    pub(crate) fn id(&self) -> String {
        self.only.clone().unwrap_or_else(|| self.which.id().to_owned())
    }
}

/// `a1`, `a3.t1` or `a1.t2.winding`: the assignment from the first part of the ID.
pub(crate) fn selection(s: &str) -> Result<Selection, String> {
    // `A3`, `A1.T2.Winding`: the IDs are lower case.
    let s = s.to_ascii_lowercase();
    let s = s.as_str();
    let assignment = s.split('.').next().unwrap_or_default();
    let ids: Vec<&str> = Which::ALL.iter().map(|w| w.id()).collect();
    let which = Which::from_id(assignment)
        .ok_or_else(|| format!("{} (a3, a3.t1, a1.t2.winding, …)", ids.join(", ")))?;
    let only = (s != assignment).then(|| s.to_owned());
    Ok(Selection { which, only })
}

/// Options of `cg check`.
#[derive(clap::Args)]
pub struct CheckArgs {
    /// An assignment (a1, a2, a3, a4, s), a task (a3.t1) or one check (a1.t2.winding); default:
    /// all / 課題・タスク・チェック（例: a1、a3.t1、a1.t2.winding。省略するとすべて）
    #[arg(value_name = "ID", value_parser = selection)]
    which: Option<Selection>,
    /// The student number (default: exercises/student.toml) / 学生番号
    #[arg(long, value_name = "NUMBER", allow_hyphen_values = true)]
    student: Option<String>,
    /// Print JSON for tools / JSON で出力
    #[arg(long)]
    json: bool,
    /// Seconds one check may spend in your functions before it is taken for an endless loop / 1 つのチェックの制限時間（秒）
    #[arg(long, value_name = "S", default_value_t = cg_assign::local::CALL_LIMIT.as_secs(), value_parser = clap::value_parser!(u64).range(crate::TIME_LIMIT_S))]
    time_limit: u64,
    /// MiB of memory your functions may use (Linux and Windows; set on macOS) / あなたの関数が使えるメモリ（MiB、Linux と Windows。macOS では設定のみ）
    #[arg(long, value_name = "MIB", default_value_t = cg_assign::local::MEMORY_MB, value_parser = clap::value_parser!(u64).range(crate::MEMORY_LIMIT_MIB))]
    memory_limit: u64,
}

/// `cg check`: runs the student's checks. Exit status 0 when every check passes, 1 when one
/// fails or is not done yet, 3 when one ran out of time.
///
/// The checks run here; the student's functions run in a worker, `cg-check-runner` built from
/// exercises/ ([`cg_assign::local`]), each check's calls within `--time-limit` and the worker's
/// memory within `--memory-limit`: a function that loops, crashes or allocates without end fails
/// only the checks that called it, and a file that does not compile only its assignment's.
pub fn check(args: &CheckArgs, lang: Lang) -> Result<Ending, String> {
    let record = student(args.student.as_deref(), None, lang)?;
    let a = Variants::for_student(&record.student, record.table);
    let which: Vec<Which> =
        args.which.as_ref().map_or_else(|| Which::ALL.to_vec(), |s| vec![s.which]);
    let only = args.which.as_ref().and_then(|s| s.only.as_deref());
    let worker = cg_assign::local::worker_for_this_kit(args.memory_limit, lang)?;
    let per_check = Duration::from_secs(args.time_limit.max(1));
    let (mut reports, worker) =
        cg_harness::check::run_only(only, || a.reports_in_worker(&which, worker, per_check));
    if let Some(only) = only {
        for r in &mut reports {
            let ids: Vec<String> = r.checks.iter().map(|c| c.id.clone()).collect();
            let tasks = r.keep_only(only);
            if r.checks.is_empty() {
                return Err(no_such_check(only, &tasks, &ids).get(lang).to_owned());
            }
        }
    }
    let printed = String::from_utf8_lossy(&worker.printed).into_owned();
    if args.json {
        let value = serde_json::Value::Array(reports.iter().map(Report::to_json).collect());
        println!("{}", serde_json::to_string_pretty(&value).unwrap_or_default());
    } else {
        for r in &reports {
            println!(
                "{} {} — {} {}",
                t("課題", "assignment").get(lang),
                r.assignment,
                t("学生番号", "student").get(lang),
                record.student
            );
            print!("{}", r.render(lang));
            println!();
        }
    }
    if !printed.is_empty() {
        // On stderr, so that `--json` stays JSON.
        eprintln!("{}", t("あなたの関数が出力した内容:", "what your functions printed:").get(lang));
        eprint!("{printed}");
        if !printed.ends_with('\n') {
            eprintln!();
        }
    }
    Ok(if reports.iter().any(Report::timed_out) {
        Ending::TimedOut
    } else {
        Ending::passed(reports.iter().all(Report::all_passed))
    })
}

/// No task or check `only` among the assignment's `tasks` and check `ids`: the one meant, when
/// one is a slip of the keyboard away (`a3.t1.drif`: a3.t1.drift), and the tasks.
fn no_such_check(only: &str, tasks: &[String], ids: &[String]) -> Text {
    let meant = tasks
        .iter()
        .chain(ids)
        .map(|id| (strsim::levenshtein(only, id), id))
        .filter(|(d, _)| *d <= 2)
        .min()
        .map(|(_, id)| id);
    let tasks = tasks.join(", ");
    let mut text = Text::new(
        format!("{only} という名前のタスクもチェックもありません。"),
        format!("there is no task or check {only}; "),
    );
    if let Some(meant) = meant {
        text.ja.push_str(&format!("{meant} のことですか？ "));
        text.en.push_str(&format!("did you mean {meant}? "));
    }
    text.ja.push_str(&format!("この課題のタスク: {tasks}"));
    text.en.push_str(&format!("the tasks of this assignment are {tasks}"));
    text
}

/// `cg sync-stubs`: regenerates exercises/ from solutions/ (the kit's maintainers only).
pub fn sync_stubs(lang: Lang) -> Result<(), String> {
    let solutions = crate::kit_path(None, "solutions");
    if !solutions.join("Cargo.toml").exists() {
        return Err(t(
            "solutions/ がありません（学生用のコピーでは使えないコマンドです）",
            "there is no solutions/ here (this command is for the kit's own repository)",
        )
        .get(lang)
        .to_owned());
    }
    let changed =
        cg_harness::stubs::write(&solutions, &exercises_dir()).map_err(|e| e.to_string())?;
    for path in &changed {
        println!("{} exercises/{}", t("更新:", "updated").get(lang), path.display());
    }
    if changed.is_empty() {
        println!("{}", t("exercises/ は最新です", "exercises/ is up to date").get(lang));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use clap::Parser as _;

    use crate::Cli;

    /// `A3` and `A1.T2.Winding` are `a3` and `a1.t2.winding`; a check ID one slip away is
    /// named (`a3.t1.drif`: "did you mean a3.t1.drift?"), one far from every ID is not.
    #[test]
    fn an_id_in_capitals_or_a_slip_away_finds_its_check() {
        let s = super::selection("A1.T2.Winding").unwrap();
        assert_eq!((s.which.id(), s.id()), ("a1", "a1.t2.winding".to_owned()));
        assert!(super::selection("a9").is_err());
        let tasks = ["a3.t1".to_owned(), "a3.t2".to_owned()];
        let ids = ["a3.t1.periods".to_owned(), "a3.t1.drift".to_owned()];
        let text = super::no_such_check("a3.t1.drif", &tasks, &ids);
        assert_eq!(
            text.en,
            "there is no task or check a3.t1.drif; did you mean a3.t1.drift? the tasks of this assignment are a3.t1, a3.t2"
        );
        assert!(text.ja.contains("a3.t1.drift のことですか？"), "{}", text.ja);
        let far = super::no_such_check("a3.t9.spin", &tasks, &ids);
        assert!(!far.en.contains("did you mean"), "{}", far.en);
    }

    /// A negative number for an option that takes a number is a bad value of that option, not
    /// "there is no argument '-1'".
    #[test]
    fn a_negative_number_is_a_bad_value_not_an_unknown_argument() {
        for args in [
            &["cg", "assignment", "--table", "-1"][..],
            &["cg", "inspect", "--max-rows", "-1"],
            &["cg", "report", "check", "--table", "-1"],
        ] {
            let e = Cli::try_parse_from(args).err().unwrap_or_else(|| panic!("{args:?} was taken"));
            assert_ne!(e.kind(), clap::error::ErrorKind::UnknownArgument, "{args:?}: {e}");
            assert!(e.to_string().contains("-1"), "{args:?}: {e}");
        }
    }
}
