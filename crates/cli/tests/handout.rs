//! `cg handout`: the student's copy has no solutions, its stubs are the pristine ones, and it
//! builds, runs and checks on its own (every check "not done yet" or failing, none passing).

use std::path::Path;
use std::process::Command;

mod common;
use common::root;

#[test]
fn the_handout_builds_and_checks_on_its_own_without_solutions() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("handout-copy");
    let _ = std::fs::remove_dir_all(&dir);
    let o = common::cg(&root(), &["handout", dir.to_str().unwrap(), "--lang", "en"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The next command it prints names this folder, runnable as printed.
    let out = String::from_utf8_lossy(&o.stdout);
    let cd = format!("cd {} && cargo run --release -- check", dir.display());
    assert!(out.contains(&cd) && !out.contains("<DIR>"), "{out}");

    // No solutions anywhere: not the folder, not the manifests, not the lock file.
    assert!(!dir.join("solutions").exists());
    for file in ["Cargo.toml", "Cargo.lock", "crates/cli/Cargo.toml"] {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        assert!(
            !text.contains("cg-solutions") && !text.contains("BEGIN SOLUTION"),
            "{file}:\n{text}"
        );
    }
    // The stubs are exactly what the solutions generate.
    for (relative, text) in cg_harness::stubs::generate(&root().join("solutions")).unwrap() {
        let got = std::fs::read_to_string(dir.join("exercises").join(&relative)).unwrap();
        assert_eq!(got, text, "exercises/{}", relative.display());
    }
    assert!(!dir.join("exercises/student.toml").exists(), "no one's student number goes out");

    // It builds offline with the committed lock file, and checks: nothing passes yet.
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("../handout");
    let cargo = |args: &[&str]| {
        Command::new(env!("CARGO"))
            .args(args)
            .current_dir(&dir)
            .env("CARGO_TARGET_DIR", &target)
            // A one-off build: no debug info and no incremental cache to write (faster, and
            // what is tested — that the copy builds and checks — does not depend on either).
            .env("CARGO_PROFILE_DEV_DEBUG", "0")
            .env("CARGO_INCREMENTAL", "0")
            .output()
            .unwrap()
    };
    let build = cargo(&["build", "--offline", "--locked", "--quiet"]);
    assert!(
        build.status.success(),
        "the handout does not build:\n{}",
        String::from_utf8_lossy(&build.stderr)
    );
    let check = cargo(&[
        "run",
        "--offline",
        "--locked",
        "--quiet",
        "--",
        "check",
        "--student",
        "12345678",
        "--json",
    ]);
    assert!(!check.status.success(), "pristine stubs must not pass every check");
    let reports: serde_json::Value = serde_json::from_slice(&check.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&check.stdout)));
    let reports = reports.as_array().unwrap();
    assert_eq!(reports.len(), 5, "a1, a2, a3, a4 and s");
    for r in reports {
        assert!(r["total"].as_u64().unwrap() > 0, "{}: no checks", r["assignment"]);
        assert_eq!(r["passed"], 0, "{}: a pristine stub passed a check", r["assignment"]);
    }
    let _ = std::fs::remove_dir_all(&dir);
}
