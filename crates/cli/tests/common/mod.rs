//! What the command-line tests share: the kit's root, running `cg` in a folder with the language
//! variables cleared, and scratch folders under the test target directory.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The kit's root folder.
pub fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

/// Runs the `cg` binary in `dir` with `args`, in English unless `args` has `--lang`: no
/// language taken from the tester's environment or system.
pub fn cg(dir: &Path, args: &[&str]) -> Output {
    cg_testkit::no_language_from_the_tester(&mut Command::new(env!("CARGO_BIN_EXE_cg")))
        .args(args)
        .current_dir(dir)
        // Never a window from the tests (a developer's desktop has a display).
        .env_remove("DISPLAY")
        .output()
        .expect("the cg binary runs")
}

/// An empty folder `<target tmp>/<group>/<test>`, made afresh.
pub fn scratch(group: &str, test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(group).join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
