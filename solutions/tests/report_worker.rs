//! `cg report` with the student's functions in a worker, as `cg report` runs them: a function
//! that never returns costs the parts that call it, and the time limit once; every other
//! assignment is derived and drawn as it would be without it.
//!
//! The worker is this test program started again with `CG_REPORT_SERVE` set: the test
//! `serve_when_asked` then serves the reference solutions, a3's `idle()` looping forever at its
//! seventh call (each looping call noted in the file `CG_REPORT_LOOPS` names).

use std::path::PathBuf;
use std::sync::atomic::{AtomicU32, Ordering};
use std::time::Duration;

use cg_assign::Impls;
use cg_core::lang::Lang;
use cg_harness::exit::Ending;
use cg_report::app::{self, DeriveArgs, FillArgs, Kit, Source};

const SERVE: &str = "CG_REPORT_SERVE";
const LOOPS: &str = "CG_REPORT_LOOPS";

/// When started with `CG_REPORT_SERVE`, serve the solutions with a3's `idle()` looping at its
/// seventh call (and test nothing).
#[test]
fn serve_when_asked() {
    if std::env::var_os(SERVE).is_none() {
        return;
    }
    let mut handlers = cg_worker::tables!(cg_solutions);
    handlers.retain(|(name, _)| !name.starts_with("a3."));
    let idle_loops_at_frame_7 = |spec: &cg_student::a3::Spec, state: &mut cg_student::a3::State| {
        static CALLS: AtomicU32 = AtomicU32::new(0);
        if CALLS.fetch_add(1, Ordering::Relaxed) + 1 == 7 {
            if let Some(log) = std::env::var_os(LOOPS) {
                let mut file =
                    std::fs::OpenOptions::new().create(true).append(true).open(log).unwrap();
                std::io::Write::write_all(&mut file, b"loops\n").unwrap();
            }
            loop {
                std::hint::spin_loop();
            }
        }
        (cg_solutions::a3::implementation().idle)(spec, state);
    };
    let imp =
        cg_student::a3::Impl { idle: idle_loops_at_frame_7, ..cg_solutions::a3::implementation() };
    handlers.extend(cg_worker::tables::a3(imp));
    cg_worker::serve(&handlers).unwrap();
    std::process::exit(0);
}

/// The file where the worker notes each call of `idle()` that loops.
fn loops_file() -> PathBuf {
    std::env::temp_dir().join(format!("cg-report-worker-loops-{}", std::process::id()))
}

/// The kit of `cg report`, its worker this program serving the solutions with the looping
/// `idle()`, each call given 3 s. The shading set's functions run in this process: through a
/// worker of a debug build its pictures take 45 s, and nothing here is about them.
fn kit() -> Kit {
    Kit {
        impls: Impls { s: cg_solutions::s::implementation(), ..Impls::worker() },
        student_file: || PathBuf::from("/nonexistent/student.toml"),
        worker: Some(|_| {
            let me = std::env::current_exe().map_err(|e| e.to_string())?;
            let args = ["serve_when_asked", "--exact", "--nocapture", "--test-threads=1", "-q"];
            Ok(cg_worker::Worker::new(me, args)
                .env(SERVE, "1")
                .env(LOOPS, loops_file().display().to_string()))
        }),
        time_limit: Duration::from_secs(3),
    }
}

/// An endless loop in a3's `idle()` (a2 correct) left out a2's picture too ("a2: not run: idle
/// (exercises/src/a3.rs) did not finish in an earlier check"), and a3's picture waited the whole
/// time limit a second time for the same `idle()`. Now a2 is drawn, and a3's picture says once
/// that `idle()` ran out of time above; `idle()` looped once in all.
#[test]
fn a3s_endless_idle_leaves_out_only_a3s_parts_and_is_waited_for_once() {
    let dir = std::env::temp_dir().join(format!("cg-report-worker-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_file(loops_file());
    let command = app::Command::Fill(FillArgs {
        derive: DeriveArgs {
            source: Source { student: Some("20250003".into()), ..Source::default() },
            output: dir.clone(),
            no_render: false,
        },
        force: false,
    });
    let ending = app::run(&command, &kit(), Lang::En).unwrap();
    assert_eq!(ending, Ending::TimedOut);
    let loops = std::fs::read_to_string(loops_file()).unwrap_or_default();
    assert_eq!(loops.lines().count(), 1, "idle() was waited for once");
    let fragment = |name: &str| std::fs::read_to_string(dir.join("fragments").join(name)).unwrap();
    // Every other assignment's picture is drawn.
    for id in ["a1", "a2", "a4", "s"] {
        let md = fragment(&format!("{id}.render.md"));
        assert!(md.contains(&format!("render-{id}.png")), "{id}: {md}");
        assert!(dir.join(format!("render-{id}.png")).is_file(), "{id}");
    }
    // The other parts derive: a2's matrices, a4's table and sampler.
    for name in ["a2.matrices.md", "a4.table.md", "a4.sampler.md", "a1.face_table.md"] {
        assert!(!fragment(name).contains("not derived yet"), "{name}: {}", fragment(name));
    }
    // a3's: idle() stopped once, the picture not drawn because of it.
    let a3 = fragment("a3.render.md");
    assert!(a3.contains("a3.t1: idle (exercises/src/a3.rs) was stopped"), "{a3}");
    assert!(a3.contains("after the time limit of 3 s"), "{a3}");
    assert!(a3.contains("a3: not drawn: idle (exercises/src/a3.rs) ran out of time above"), "{a3}");
    assert!(!a3.contains("earlier check"), "{a3}");
    assert!(fragment("a3.matrices.md").contains("not derived yet: a3.t1: idle"));
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_file(loops_file());
}
