//! `cg-check-runner` end to end: the worker serves the kit's pristine stubs (each call a panic
//! with the stub's `todo!()` message, the worker going on; or, for a stub that runs, its value
//! with its marker), refuses a bad command line, serves the same under the grading sandbox's
//! launch line (bubblewrap, with its seccomp filter on a descriptor of its own, so stdin stays
//! the worker's), and links nothing of the kit's checks.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Duration;

use cg_student::a1;
use cg_student::gl::Gl;
use cg_student::glam::Vec3;
use cg_worker::{CallError, Worker};

const BUDGET: Duration = Duration::from_secs(20);

fn runner() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_cg-check-runner"))
}

/// An a1 spec as `cg assignment --json` writes it (the first of the frozen table).
fn spec() -> a1::Spec {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assign/tests/table-v1.json");
    let table: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap();
    serde_json::from_value(table[0]["a1"].clone()).unwrap()
}

fn expect_todo(r: Result<Vec<Vec3>, CallError>, task: &str) {
    match r {
        Err(CallError::Panicked { message, location }) => {
            assert!(message.starts_with(&format!("not yet implemented: {task}")), "{message}");
            assert!(location.is_some_and(|l| l.contains("exercises/src/")));
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn the_stubs_are_served_and_each_call_is_its_todo() {
    let mut w = Worker::new(runner(), ["--memory-mb", "1024"]);
    expect_todo(w.call("a1.vertices", &spec(), BUDGET), "a1.t1");
    expect_todo(w.call("a1.face_normals", &spec(), BUDGET), "a1.t3");
    // An unknown function and arguments of another type are no value, and the worker goes on.
    assert!(matches!(w.call::<_, u8>("a9.nothing", &(), BUDGET), Err(CallError::Broken(_))));
    assert!(matches!(w.call::<_, u8>("a1.vertices", &"x", BUDGET), Err(CallError::Broken(_))));
    expect_todo(w.call("a1.vertices", &spec(), BUDGET), "a1.t1");
    // A stub that runs (a2's, so the view still draws) gives its value, and its marker
    // (`cg_student::not_started`) comes back with it, for the checks.
    let _ = cg_student::take_not_started();
    let state = cg_student::a2::CameraState {
        camera_yaw: 0.0,
        camera_pitch: -30.0,
        camera_distance: 15.0,
        target_x: 0.0,
        target_z: 0.0,
    };
    let gl: Gl = w.call("a2.camera", &(Gl::new(), state), BUDGET).unwrap();
    assert!(gl.calls().is_empty(), "{gl:?}");
    assert_eq!(cg_student::take_not_started(), ["a2.t2"]);
}

#[test]
fn a_bad_command_line_is_refused_with_its_usage() {
    for args in [&["--memory-mb", "lots"][..], &["--only", "a1"]] {
        let o = Command::new(runner()).args(args).output().unwrap();
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(err.contains("--memory-mb"), "{err}");
    }
}

#[test]
fn under_the_sandboxs_launch_line_it_serves_the_same() {
    use cg_sandbox::{Isolation, Job, Limits, detect};
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("check-runner-sandbox");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let isolation = detect();
    if isolation != Isolation::Bubblewrap {
        assert!(std::env::var_os("CI").is_none(), "bubblewrap does not work on this CI machine");
        eprintln!("note: bubblewrap is not usable here; the worker runs under rlimits only");
    }
    let job = Job {
        program: runner(),
        args: Vec::new(),
        workdir: dir.clone(),
        read_only: Vec::new(),
        env: Vec::new(),
        ..Job::default()
    };
    let l = cg_sandbox::launch(&job, &Limits::default(), isolation).unwrap();
    if isolation == Isolation::Bubblewrap {
        assert_eq!(l.program, Path::new("/bin/sh"));
        assert!(dir.with_extension("seccomp").is_file());
    }
    let mut w = Worker::new(l.program, l.args).clear_env().current_dir(l.workdir);
    for (k, v) in l.env {
        w = w.env(k, v);
    }
    expect_todo(w.call("a1.vertices", &spec(), BUDGET), "a1.t1");
    expect_todo(w.call("a1.face_normals", &spec(), BUDGET), "a1.t3");
}

#[test]
fn it_links_the_students_crate_and_the_workers_protocol_only() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let deps = |manifest: &Path| -> Vec<String> {
        let text = std::fs::read_to_string(manifest).unwrap();
        let value: toml::Table = toml::from_str(&text).unwrap();
        let mut names: Vec<String> = Vec::new();
        for table in ["dependencies"] {
            if let Some(t) = value.get(table).and_then(|t| t.as_table()) {
                names.extend(t.keys().cloned());
            }
        }
        if let Some(targets) = value.get("target").and_then(|t| t.as_table()) {
            for t in targets.values() {
                if let Some(d) = t.get("dependencies").and_then(|d| d.as_table()) {
                    names.extend(d.keys().cloned());
                }
            }
        }
        names.sort();
        names
    };
    assert_eq!(deps(&root.join("Cargo.toml")), ["cg-exercises", "cg-worker"]);
    assert_eq!(
        deps(&root.join("../worker/Cargo.toml")),
        ["cg-student", "ciborium", "rlimit", "serde", "win32job"],
        "cg-worker is linked into the worker: nothing of the kit's checks may come with it"
    );
}
