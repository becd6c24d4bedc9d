//! The instructors' commands and what lies in the kit's folder: `cg handout` and
//! `cg autograder` take the files git tracks, so what a session left in the kit (an old
//! `autograder.zip` with the solutions, a grading's `results/`, a folder of submissions) never
//! reaches the students; they run from any folder of the kit; a handout is not written into
//! the kit; and limits a clock or a byte count cannot hold are refused by the parser.

use std::path::Path;
use std::process::Command;

mod common;
use common::{root, scratch};

fn git(dir: &Path, args: &[&str]) {
    let ok = Command::new("git").arg("-C").arg(dir).args(args).status().unwrap().success();
    assert!(ok, "git {args:?}");
}

#[test]
fn a_handout_takes_the_files_git_tracks_from_any_folder_of_the_kit() {
    if !root().join(".git").exists() {
        eprintln!("note: skipped: the kit is not a git checkout");
        return;
    }
    let dir = scratch("instructor-paths", "handout");
    let kit = dir.join("kit");
    git(&dir, &["clone", "-q", root().to_str().unwrap(), kit.to_str().unwrap()]);
    // What a session leaves in the kit: none of it is the kit's.
    for (file, text) in [
        ("autograder.zip", "PK old zip with solutions/src/a1.rs"),
        ("results/12345678.json", "{\"score\": 74}"),
        ("submissions/alice/exercises/src/a1.rs", "// alice's answer"),
        ("exam-answers.txt", "secret"),
    ] {
        std::fs::create_dir_all(kit.join(file).parent().unwrap()).unwrap();
        std::fs::write(kit.join(file), text).unwrap();
    }
    // Run from a folder of the kit, as git runs.
    let copy = dir.join("copy 2026");
    let o = common::cg(&kit.join("docs"), &["handout", copy.to_str().unwrap(), "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(copy.join("README.md").is_file() && copy.join("exercises/src/a1.rs").is_file());
    for left_out in ["autograder.zip", "results", "submissions", "exam-answers.txt", "solutions"] {
        assert!(!copy.join(left_out).exists(), "{left_out} was handed out");
    }
    // Said, as the untracked files they are (the ignored ones need no word).
    assert!(err.contains("left out 1 file(s) git does not track: exam-answers.txt"), "{err}");
    // Into the kit: refused, nothing written.
    let o = common::cg(&kit, &["handout", "copy2026", "--lang", "ja"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("copy2026 はキットのフォルダの中です"), "{err}");
    assert!(!kit.join("copy2026").exists());
    // A file where the folder should be.
    let o = common::cg(&kit, &["handout", "README.md", "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("README.md is a file, not a folder"), "{err}");
    // Outside any kit (the system's temporary folder: the scratch folder lies in this kit's
    // target/): said where to run it.
    let outside = std::env::temp_dir().join(format!("cg-no-kit-{}", std::process::id()));
    std::fs::create_dir_all(&outside).unwrap();
    let o = common::cg(&outside, &["handout", "elsewhere", "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("no solutions/ in this folder or above it"), "{err}");
    assert!(!outside.join("elsewhere").exists());
    let _ = std::fs::remove_dir_all(&outside);
    let _ = std::fs::remove_dir_all(&dir);
}

/// A time limit past the clock's end panicked (exit 101 without a word); a memory limit of
/// 2⁴⁴ MiB wrapped to 0 bytes, and every check failed, blamed on the student, with exit 0. Both
/// are the parser's errors now, before anything is built.
#[test]
fn limits_a_clock_or_a_byte_count_cannot_hold_are_refused() {
    let huge = u64::MAX.to_string();
    for args in [
        vec!["check", "a1", "--time-limit", &huge],
        vec!["check", "a1", "--memory-limit", "17592186044416"],
        vec!["grade-one", "nowhere", "--time-limit", "86401"],
        vec!["grade-one", "nowhere", "--memory-limit", "17592186044416"],
        vec!["grade", "nowhere", "--memory-limit", "32"],
    ] {
        let o = common::cg(&root(), &[&args[..], &["--lang", "ja"]].concat());
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains("までの数にしてください"), "{args:?}: {err}");
    }
}

/// A submission that cannot be graded at all (an empty folder: no exercises/) gets its
/// results.json with score 0 and why, and exit 2, so that a batch system's job tells "nothing
/// could be graded" from "graded 0" (it ended 0).
#[test]
fn grade_one_of_a_submission_it_cannot_grade_ends_with_exit_2() {
    let dir = scratch("instructor-paths", "grade-one");
    std::fs::create_dir_all(dir.join("empty")).unwrap();
    let out = dir.join("results");
    let o = common::cg(
        &root(),
        &[
            "grade-one",
            dir.join("empty").to_str().unwrap(),
            "--out",
            out.to_str().unwrap(),
            "--work",
            dir.join("work").to_str().unwrap(),
            "--unsafe-no-sandbox",
            "--lang",
            "en",
        ],
    );
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("not graded: "), "{err}");
    let r: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("results.json")).unwrap()).unwrap();
    assert_eq!(r["score"].as_f64(), Some(0.0), "{r}");
    let _ = std::fs::remove_dir_all(&dir);
}
