//! The kit's checks with the student's functions in a worker process (`cg check` and
//! `cg grade`'s path) report exactly what they report with the functions in process: on the
//! reference solutions and on the pristine stubs, for several students. And a worker whose
//! functions exit after printing a forged report, loop, abort or allocate without end fails only
//! the checks that called them, with outcomes decided here, never read from what it printed.
//!
//! The worker is this test program started again with `CG_SERVE` set: the test
//! `serve_when_asked` then serves the tables it names instead of testing.

use std::time::{Duration, Instant};

use cg_assign::{Impls, Variants, Which};
use cg_harness::TableVersion;
use cg_harness::check::{Outcome, Report};
use cg_student::a1;
use cg_worker::Worker;

const STUDENTS: &[&str] = &["12345678", "20240917", "87654321"];

/// When started with `CG_SERVE=<tables>`, serve them on stdin/stdout (and test nothing).
#[test]
fn serve_when_asked() {
    let Ok(which) = std::env::var("CG_SERVE") else { return };
    if std::env::var_os("CG_TEST_MEMORY").is_some() {
        assert!(cg_check_runner::limit_memory(1024).unwrap(), "rlimits are Unix's");
    }
    let handlers = match which.as_str() {
        "solutions" => cg_worker::tables!(cg_solutions),
        "exercises" => cg_worker::tables!(cg_exercises),
        "hostile" => hostile(),
        other => panic!("CG_SERVE={other}"),
    };
    cg_worker::serve(&handlers).unwrap();
    std::process::exit(0);
}

/// This program as a worker serving `tables`.
fn worker(tables: &str) -> Worker {
    let me = std::env::current_exe().unwrap();
    let args = ["serve_when_asked", "--exact", "--nocapture", "--test-threads=1", "-q"];
    Worker::new(me, args.map(String::from).to_vec()).env("CG_SERVE", tables)
}

fn in_worker(a: &Variants, tables: &str, per_check: Duration) -> Vec<Report> {
    a.reports_in_worker(Which::ALL, worker(tables), per_check).0
}

/// For every student, the reports of `impls` in process and of the worker serving `tables`:
/// equal; `check` is told each local report.
fn same_in_worker_and_in_process(impls: &Impls, tables: &str, check: impl Fn(&str, &Report)) {
    for student in STUDENTS {
        let a = Variants::for_student(&student.parse().unwrap(), TableVersion::DEFAULT);
        let local: Vec<Report> = Which::ALL.iter().map(|&w| a.report(w, impls)).collect();
        let remote = in_worker(&a, tables, Duration::from_secs(120));
        assert_eq!(local, remote, "{student}");
        for r in &local {
            check(student, r);
        }
    }
}

#[test]
fn the_solutions_in_a_worker_get_the_reports_they_get_in_process() {
    same_in_worker_and_in_process(&cg_assign::impls!(cg_solutions), "solutions", |student, r| {
        assert!(r.all_passed(), "{student}: {}", r.render(cg_core::lang::Lang::En));
    });
}

#[test]
fn the_stubs_in_a_worker_get_the_reports_they_get_in_process() {
    same_in_worker_and_in_process(&cg_assign::impls!(cg_exercises), "exercises", |student, r| {
        assert_eq!(r.passed(), 0, "{student}: {}", r.render(cg_core::lang::Lang::En));
        // The stubs that run carry markers (`cg_student::not_started`), which come back over the
        // pipe with the replies: their checks are "not done yet" in the worker too.
        for c in &r.checks {
            if matches!(r.assignment.as_str(), "a2" | "a3")
                || matches!(c.task.as_str(), "s.t5" | "s.t6")
            {
                assert!(
                    matches!(c.outcome, Outcome::NotDone { .. }),
                    "{student}: {} is {:?}",
                    c.id,
                    c.outcome
                );
            }
        }
    });
}

/// The reference solutions, with a1's functions at their worst: `vertices` prints a forged
/// report that says every check passed and exits 0; `faces` loops forever; `face_normals`
/// allocates without end. `model_transform` is the reference's.
fn hostile() -> Vec<(&'static str, cg_worker::Handler)> {
    let mut handlers = cg_worker::tables!(cg_solutions);
    handlers.retain(|(name, _)| !name.starts_with("a1."));
    let imp = a1::Impl {
        vertices: |_| {
            println!(r#"[{{"assignment":"a1","passed":9,"total":9,"checks":[]}}]"#);
            std::process::exit(0)
        },
        faces: |_| loop {
            std::hint::spin_loop();
        },
        face_normals: |_| {
            let mut hoard: Vec<Vec<u8>> = Vec::new();
            loop {
                hoard.push(vec![1; 1 << 28]);
            }
        },
        ..cg_solutions::a1::implementation()
    };
    handlers.extend(cg_worker::tables::a1(imp));
    handlers
}

#[test]
fn a_hostile_function_fails_only_the_checks_that_call_it() {
    let a = Variants::for_student(&STUDENTS[0].parse().unwrap(), TableVersion::DEFAULT);
    let per_check = Duration::from_secs(2);
    let local = a.report(Which::a1, &cg_assign::impls!(cg_solutions));
    let started = Instant::now();
    let (reports, worker) = a.reports_in_worker(
        &[Which::a1, Which::a4],
        worker("hostile").env("CG_TEST_MEMORY", "1"),
        per_check,
    );
    let elapsed = started.elapsed();
    let (a1, a4) = (&reports[0], &reports[1]);
    // The trusted side's list of checks, not the forged one.
    assert_eq!(a1.total(), local.total());
    let ids = |r: &Report| r.checks.iter().map(|c| c.id.clone()).collect::<Vec<_>>();
    assert_eq!(ids(a1), ids(&local));
    let outcomes: Vec<&Outcome> = a1.checks.iter().map(|c| &c.outcome).collect();
    assert!(
        outcomes.iter().any(|o| matches!(o, Outcome::Crashed { how, .. }
            if how.en.starts_with("it exited with code 0") && how.ja.starts_with("終了コード 0 "))),
        "the exit(0) is a crash: {outcomes:#?}"
    );
    assert!(outcomes.iter().any(|o| matches!(o, Outcome::TimedOut { limit_ms: 2000, .. })));
    assert!(
        outcomes.iter().any(|o| matches!(o, Outcome::Crashed { stderr, .. }
            if stderr.contains("memory allocation"))),
        "the hoard ends at the worker's memory limit: {outcomes:#?}"
    );
    assert!(a1.passed() < a1.total(), "{}", a1.render(cg_core::lang::Lang::En));
    // model_transform's checks call nothing else: they still pass.
    for c in a1.checks.iter().filter(|c| c.task == "a1.t4") {
        assert!(c.passed(), "{c:?}");
    }
    // Another assignment in the same worker is untouched.
    assert!(a4.all_passed(), "{}", a4.render(cg_core::lang::Lang::En));
    // What the student printed is kept apart, never read as a result.
    let printed = String::from_utf8_lossy(&worker.printed);
    assert!(printed.contains("\"passed\":9"), "{printed}");
    // Each check that hit the loop cost at most its budget.
    let timed_out = outcomes.iter().filter(|o| matches!(o, Outcome::TimedOut { .. })).count();
    assert!(elapsed < per_check * (timed_out as u32 + 10), "{elapsed:?}");
}

#[test]
fn the_worker_impls_panic_with_a_call_error_outside_a_worker() {
    // A stand-in called with no worker is a check that got no result, not a pass: said so in
    // both languages.
    let impls = Impls::worker();
    let a = Variants::for_student(&STUDENTS[0].parse().unwrap(), TableVersion::DEFAULT);
    let r = a.report(Which::a4, &impls);
    assert_eq!(r.passed(), 0);
    assert!(
        r.checks.iter().all(|c| matches!(&c.outcome, Outcome::Broken { why }
            if why.en.ends_with("no worker is running") && why.ja.ends_with("ワーカーが動いていません"))),
        "{r:?}"
    );
}
