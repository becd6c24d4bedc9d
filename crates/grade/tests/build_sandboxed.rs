//! A submission's build runs in the sandbox: what compiles outside it because it reaches the
//! machine at compile time fails inside, and what the build writes outside its target folder
//! never reaches the disk. The attacks are a small crate of its own (no dependencies: it builds
//! in seconds): `include_str!` of a system file (the token screen refuses it in a submission;
//! this is the second wall), and a build script that writes beside the sources and reads a file
//! of the grader's. Each is shown to succeed without the sandbox.

use std::path::{Path, PathBuf};
use std::time::Duration;

use cg_grade::build::{cargo_build, cargo_build_sandboxed};
use cg_sandbox::{Isolation, detect};

const LIMIT: Duration = Duration::from_secs(300);

/// A fresh crate `name` with `lib` as its src/lib.rs and `build` as its build.rs (if any).
fn probe(name: &str, lib: &str, build: Option<&str>) -> (PathBuf, PathBuf) {
    let base = Path::new(env!("CARGO_TARGET_TMPDIR")).join("build-sandboxed").join(name);
    let _ = std::fs::remove_dir_all(&base);
    let src = base.join("src");
    std::fs::create_dir_all(src.join("src")).unwrap();
    std::fs::write(
        src.join("Cargo.toml"),
        format!(
            "[package]\nname = \"{name}\"\nversion = \"0.1.0\"\nedition = \"2021\"\n\n[workspace]\n"
        ),
    )
    .unwrap();
    std::fs::write(
        src.join("Cargo.lock"),
        format!("version = 4\n\n[[package]]\nname = \"{name}\"\nversion = \"0.1.0\"\n"),
    )
    .unwrap();
    std::fs::write(src.join("src/lib.rs"), lib).unwrap();
    if let Some(b) = build {
        std::fs::write(src.join("build.rs"), b).unwrap();
    }
    (src.canonicalize().unwrap(), base.join("target"))
}

fn sandboxed() -> bool {
    let ok = detect() == Isolation::Bubblewrap;
    if !ok {
        assert!(std::env::var_os("CI").is_none(), "CI installs bubblewrap (scripts/setup.sh)");
        eprintln!("note: no bubblewrap here: the sandboxed build is not tested");
    }
    ok
}

#[test]
fn a_file_outside_cannot_be_read_at_compile_time() {
    if !sandboxed() {
        return;
    }
    let lib = "pub const S: &str = include_str!(\"/etc/hostname\");\n";
    let (src, target) = probe("reads_etc", lib, None);
    let outside = cargo_build(&src, &target, "reads_etc", LIMIT).unwrap();
    assert!(outside.success, "the attack works without the sandbox: {outside:?}");
    let _ = std::fs::remove_dir_all(&target);
    let inside =
        cargo_build_sandboxed(&src, &target, "reads_etc", LIMIT, Isolation::Bubblewrap).unwrap();
    assert!(!inside.success, "{inside:?}");
    let errors = inside.module_errors.values().flatten().chain(&inside.other_errors);
    assert!(errors.clone().any(|e| e.contains("/etc/hostname")), "{inside:?}");
}

#[test]
fn a_build_writes_only_its_target_folder_and_reads_nothing_beside_it() {
    if !sandboxed() {
        return;
    }
    // A file of the grader's beside the sources: readable without the sandbox, not within.
    let secret = Path::new(env!("CARGO_TARGET_TMPDIR")).join("build-sandboxed/secret.txt");
    std::fs::create_dir_all(secret.parent().unwrap()).unwrap();
    std::fs::write(&secret, "grades").unwrap();
    let build = format!(
        "fn main() {{\n    let _ = std::fs::write(\"escaped.txt\", \"x\");\n    \
         if std::fs::read_to_string({:?}).is_ok() {{ panic!(\"read the grader's file\") }}\n}}\n",
        secret.canonicalize().unwrap()
    );
    let (src, target) = probe("writes_beside", "pub fn f() {}\n", Some(&build));
    let inside =
        cargo_build_sandboxed(&src, &target, "writes_beside", LIMIT, Isolation::Bubblewrap)
            .unwrap();
    assert!(inside.success, "{inside:?}");
    assert!(!src.join("escaped.txt").exists(), "a write beside the sources reached the disk");
    assert!(target.join("release").is_dir(), "the target folder is written");
    // Without the sandbox the same build script writes its file and reads the grader's.
    let _ = std::fs::remove_dir_all(&target);
    let outside = cargo_build(&src, &target, "writes_beside", LIMIT).unwrap();
    assert!(!outside.success, "{outside:?}");
    assert!(outside.stderr_tail.contains("read the grader's file"), "{outside:?}");
    assert!(src.join("escaped.txt").exists());
}
