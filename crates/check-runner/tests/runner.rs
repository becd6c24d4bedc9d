//! `cg-check-runner` end to end on the kit's pristine stubs (nothing passes; assignment 1's
//! checks all say "not done yet"), with the student from `--student` or from
//! `exercises/student.toml`, and under the grading sandbox.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const STUDENT: &str = "12345678";

fn runner() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_cg-check-runner"))
}

/// Runs the runner in `dir` with `args`, with no language taken from the environment.
fn run(dir: &Path, args: &[&str]) -> Output {
    Command::new(runner())
        .args(args)
        .current_dir(dir)
        .env_remove("CG_LANG")
        .env_remove("LANG")
        .env_remove("LC_ALL")
        .env_remove("LC_MESSAGES")
        .output()
        .expect("the runner starts")
}

/// An empty folder `<target tmp>/check-runner/<test>` holding an empty `exercises/`, so that
/// `exercises/student.toml` is looked for there, not in the kit.
fn scratch(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("check-runner").join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(dir.join("exercises")).unwrap();
    dir.canonicalize().unwrap()
}

fn json(o: &Output) -> serde_json::Value {
    serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&o.stdout)))
}

#[test]
fn the_stubs_pass_nothing_and_every_assignment_is_reported() {
    let dir = scratch("stubs");
    let o = run(&dir, &["--student", STUDENT]);
    assert_eq!(o.status.code(), Some(1), "{}", String::from_utf8_lossy(&o.stderr));
    let reports = json(&o);
    let reports = reports.as_array().unwrap();
    let ids: Vec<&str> = reports.iter().map(|r| r["assignment"].as_str().unwrap()).collect();
    assert_eq!(ids, ["a1", "a2", "a3", "a4", "s"]);
    for r in reports {
        let checks = r["checks"].as_array().unwrap();
        assert_eq!(r["student"], STUDENT);
        assert_eq!(r["passed"], 0, "{r}");
        assert_eq!(r["total"].as_u64(), Some(checks.len() as u64));
        assert!(checks.len() >= 5, "{r}");
        assert!(checks.iter().all(|c| c["status"] != "pass"), "{r}");
        let prefix = format!("{}.t", r["assignment"].as_str().unwrap());
        assert!(checks.iter().all(|c| c["id"].as_str().unwrap().starts_with(&prefix)), "{r}");
    }
    // Assignment 1's stubs are todo!()s: every check says so.
    let a1 = reports[0]["checks"].as_array().unwrap();
    assert!(a1.iter().all(|c| c["status"] == "not_done"), "{a1:?}");
    assert!(a1[0]["message"].as_str().unwrap().starts_with("a1.t1"), "{:?}", a1[0]);

    // --only gives that assignment's report alone, the same as in the whole.
    let only = run(&dir, &["--student", STUDENT, "--only", "a4"]);
    assert_eq!(only.status.code(), Some(1));
    assert_eq!(json(&only), serde_json::Value::Array(vec![reports[3].clone()]));
}

#[test]
fn the_student_comes_from_the_student_file_when_not_given() {
    let dir = scratch("file");
    let o = run(&dir, &["--only", "a1", "--lang", "en"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(o.stdout.is_empty());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("student.toml"), "{err}");

    let record = cg_assign::StudentFile {
        student: STUDENT.parse().unwrap(),
        table: cg_harness::TableVersion::LATEST,
    };
    cg_assign::write_student_file(&dir.join("exercises/student.toml"), &record).unwrap();
    let from_file = run(&dir, &["--only", "a1"]);
    let given = run(&dir, &["--only", "a1", "--student", STUDENT]);
    assert_eq!(from_file.status.code(), Some(1));
    assert_eq!(json(&from_file)[0]["student"], STUDENT);
    assert_eq!(from_file.stdout, given.stdout);
    // Another student's variant is another report.
    let other = run(&dir, &["--only", "a1", "--student", "87654321"]);
    assert_eq!(json(&other)[0]["student"], "87654321");
}

#[test]
fn under_the_sandbox_it_prints_the_same() {
    use cg_sandbox::{Ended, Job, Limits, detect};
    let dir = scratch("sandbox");
    let outside = run(&dir, &["--student", STUDENT]);
    let isolation = detect();
    if isolation != cg_sandbox::Isolation::Bubblewrap {
        assert!(std::env::var_os("CI").is_none(), "bubblewrap does not work on this CI machine");
        eprintln!("note: bubblewrap is not usable here; the run is under rlimits only");
    }
    let job = Job {
        program: runner(),
        args: vec!["--student".into(), STUDENT.into()],
        workdir: dir.clone(),
        read_only: Vec::new(),
        env: Vec::new(),
    };
    let r = cg_sandbox::run(&job, &Limits::default(), isolation).unwrap();
    assert_eq!(r.ended, Ended::Exited(1), "{r:?}");
    assert!(!r.output_cut);
    assert_eq!(r.stdout.as_bytes(), outside.stdout.as_slice());
}
