//! `cg assignment`, `cg check` and `cg view` end to end: a student's assignment from their
//! number, the record in exercises/student.toml, the checks on the pristine stubs (none pass),
//! and the views as PNG files.

use std::path::PathBuf;

mod common;
use common::{cg, root};

/// A scratch folder with an empty exercises/, so the student file goes there, not into the kit.
fn scratch(test: &str) -> PathBuf {
    let dir = common::scratch("cg-assignments", test);
    std::fs::create_dir_all(dir.join("exercises")).unwrap();
    dir
}

#[test]
fn the_assignment_follows_from_the_number_and_is_recorded_once() {
    let dir = scratch("assignment");
    let o = cg(&dir, &["assignment", "--student", "12345678", "--save", "--lang", "en"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.starts_with("Student number: 12345678"), "{text}");
    for task in ["a1.t1", "a2.t1", "a3.t1", "a4.t1", "s.t1"] {
        assert!(text.contains(task), "{task} missing from the assignment text");
    }
    let record = std::fs::read_to_string(dir.join("exercises/student.toml")).unwrap();
    assert!(record.contains("student = \"12345678\""), "{record}");
    // Recorded: later commands need no number, and print the same assignment.
    let again = cg(&dir, &["assignment", "--lang", "en"]);
    assert_eq!(String::from_utf8_lossy(&again.stdout), text);
    // JSON, whole and for one assignment, is the library's.
    let json: serde_json::Value =
        serde_json::from_slice(&cg(&dir, &["assignment", "--json"]).stdout).unwrap();
    let expected = cg_assign::Variants::for_student(
        &"12345678".parse().unwrap(),
        cg_harness::TableVersion::V1,
    );
    assert_eq!(json, expected.to_json());
    // Each assignment alone is the same JSON, its f32 numbers as written (`"kl": 0.1`).
    for &which in cg_assign::Which::ALL {
        let id = which.id();
        let one: serde_json::Value =
            serde_json::from_slice(&cg(&dir, &["assignment", "--json", "--only", id]).stdout)
                .unwrap();
        assert_eq!(one, expected.to_json()[id], "{id}");
    }
}

/// `--save` over another saved number says what it was and is now, and that the assignment and
/// the checks change with it (it changed them silently); the same number again says nothing.
#[test]
fn saving_another_number_says_what_it_was_and_is_now() {
    let dir = scratch("renumbered");
    let save =
        |n: &str, lang: &str| cg(&dir, &["assignment", "--student", n, "--save", "--lang", lang]);
    let first = save("20261234", "en");
    assert!(first.status.success(), "{}", String::from_utf8_lossy(&first.stderr));
    assert!(!String::from_utf8_lossy(&first.stderr).contains("was"));
    let same = save("20261234", "en");
    assert!(!String::from_utf8_lossy(&same.stderr).contains("is now"));
    let other = save("20261235", "en");
    let err = String::from_utf8_lossy(&other.stderr);
    assert!(other.status.success(), "{err}");
    assert!(err.contains("the student number was 20261234 and is now 20261235"), "{err}");
    assert!(err.contains("checks"), "{err}");
    let back = save("20261234", "ja");
    let err = String::from_utf8_lossy(&back.stderr);
    assert!(err.contains("学生番号を 20261235 から 20261234 に変更しました"), "{err}");
}

#[test]
fn a_bad_or_missing_number_says_what_to_do() {
    let dir = scratch("missing");
    let o = cg(&dir, &["check", "a1", "--lang", "ja"]);
    assert_eq!(o.status.code(), Some(2), "no student number is bad input (exit status 2)");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--save") && err.contains("student.toml"), "{err}");
    let o = cg(&dir, &["assignment", "--student", "1234567x", "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.code() == Some(2) && err.contains("8 digits") && err.contains("'x'"), "{err}");
    // No cargo to build the student's functions with: said in Japanese, the system's reason
    // too (it was "No such file or directory (os error 2)").
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_cg"))
        .args(["check", "a1", "--student", "12345678", "--lang", "ja"])
        .current_dir(root())
        .env("CARGO", dir.join("no-such-cargo"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("cargo を起動できません（") && !err.contains("os error"), "{err}");
}

#[test]
fn checks_on_the_pristine_stubs_all_fail_and_say_not_done_yet() {
    let o = cg(&root(), &["check", "a1", "--student", "12345678", "--json"]);
    assert_eq!(o.status.code(), Some(1), "stubs do not pass: mistakes found (exit status 1)");
    let reports: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let r = &reports[0];
    assert_eq!(r["assignment"], "a1");
    assert!(r["total"].as_u64().unwrap() > 5);
    assert_eq!(r["passed"], 0);
    assert!(r["checks"].as_array().unwrap().iter().all(|c| c["status"] == "not_done"), "{r}");
    let o = cg(&root(), &["check", "a1", "--student", "12345678", "--lang", "ja"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("まだです: a1.t1") && text.contains("進み具合: 0/"), "{text}");
    // The stubs that run so the view still draws (a2, a3, s.t5, s.t6) carry a marker,
    // `cg_student::not_started("a2.t1");`: not done yet either, never "to fix".
    for (which, tasks) in [("a2", "a2.t1, a2.t2, a2.t3"), ("a3", "a3.t0, a3.t1, a3.t2")] {
        let o = cg(&root(), &["check", which, "--student", "12345678", "--json"]);
        assert_eq!(o.status.code(), Some(1), "{which}: not done is no pass (exit status 1)");
        let reports: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let r = &reports[0];
        assert_eq!(r["passed"], 0, "{r}");
        assert!(r["checks"].as_array().unwrap().iter().all(|c| c["status"] == "not_done"), "{r}");
        let o = cg(&root(), &["check", which, "--student", "12345678", "--lang", "en"]);
        let text = String::from_utf8_lossy(&o.stdout);
        assert!(text.contains(&format!("; not done yet: {tasks}\n")), "{text}");
        assert!(!text.contains("to fix") && !text.contains('✗'), "{text}");
    }
    let o = cg(&root(), &["check", "s", "--student", "12345678", "--json"]);
    let reports: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    // Every check of the shading set is "not done yet" on the stubs (s.t5 and s.t6 by markers).
    let checks = reports[0]["checks"].as_array().unwrap();
    assert!(checks.iter().any(|c| c["task"] == "s.t6"), "{checks:?}");
    assert!(checks.iter().all(|c| c["status"] == "not_done"), "{checks:?}");
}

#[test]
fn views_are_drawn_for_the_student_and_the_reference() {
    let out = scratch("view").join("png");
    let o = cg(
        &root(),
        &["view", "a1", "--student", "12345678", "-o", out.to_str().unwrap(), "--lang", "en"],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8_lossy(&o.stdout);
    // The stubs are not done, so only the reference is drawn; the student's side says why.
    assert!(text.contains("yours: not done yet"), "{text}");
    assert!(out.join("view-a1-reference.png").exists(), "{text}");
    let warm = cg(
        &root(),
        &[
            "view",
            "a3",
            "--warmup",
            "--time",
            "1",
            "--student",
            "12345678",
            "-o",
            out.to_str().unwrap(),
        ],
    );
    assert!(warm.status.success(), "{}", String::from_utf8_lossy(&warm.stderr));
    assert!(out.join("view-a3-warmup-reference.png").exists());
    let wrong = cg(&root(), &["view", "a1", "--warmup", "--student", "12345678"]);
    assert!(!wrong.status.success(), "--warmup is for a3 only");
}

/// A display that is named but does not answer (`DISPLAY=:99`, no X server there; no Wayland):
/// `view` says in a sentence why no window opens, without winit's source path, and draws the
/// same PNG files as `--png` (not the viewer's generic `view.png`).
#[test]
fn a_dead_display_falls_back_to_the_views_own_png_files() {
    let out = scratch("view-dead-display").join("png");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_cg"))
        .args(["view", "a1", "--student", "12345678", "-o", out.to_str().unwrap(), "--lang", "en"])
        .current_dir(root())
        .env("DISPLAY", ":99")
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("CG_NO_WINDOW")
        .output()
        .unwrap();
    let (stdout, stderr) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{stderr}");
    assert!(stderr.contains("no window can be opened"), "{stderr}");
    assert!(!stderr.contains(".rs:"), "no source path in the message: {stderr}");
    assert!(out.join("view-a1-reference.png").exists(), "{stdout}");
    assert!(!out.join("view.png").exists(), "{stdout}");
    assert!(stdout.contains("yours: not done yet"), "{stdout}");
}

/// The window's options where no window opens are an error that names them, before any PNG
/// file: `--screenshot` wrote nothing with exit 0, with a dead display or none, and with
/// `--png` (now the parser's error).
#[test]
fn the_windows_options_without_a_window_are_an_error() {
    let out = scratch("view-window-options");
    let shot = out.join("shot.png");
    let base = ["view", "a1", "--student", "12345678", "--lang", "en", "-o"];
    for (display, extra) in [
        (Some(":99"), vec!["--screenshot", shot.to_str().unwrap()]),
        (None, vec!["--frames", "3", "--paused"]),
        (None, vec!["--png", "--screenshot", shot.to_str().unwrap()]),
    ] {
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_cg"));
        command.args(base).arg(out.join("png")).args(&extra).current_dir(root());
        command.env_remove("WAYLAND_DISPLAY").env_remove("CG_NO_WINDOW").env_remove("DISPLAY");
        if let Some(d) = display {
            command.env("DISPLAY", d);
        }
        let o = command.output().unwrap();
        let stderr = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{extra:?}: {stderr}");
        let named = extra
            .iter()
            .filter(|a| a.starts_with("--") && **a != "--png")
            .all(|a| stderr.contains(a));
        assert!(named, "{extra:?}: {stderr}");
        assert!(!out.join("png").exists() && !shot.exists(), "{extra:?}: nothing drawn");
    }
    // -o naming a file: said as such (it was the system's "already exists").
    std::fs::write(out.join("a-file"), "").unwrap();
    let o = cg(&root(), &[&base[..], &[out.join("a-file").to_str().unwrap(), "--png"]].concat());
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("a-file is a file, not a folder"), "{stderr}");
}

#[test]
fn one_task_or_one_check_is_checked_alone() {
    let ids = |args: &[&str]| -> Vec<String> {
        let o = cg(&root(), args);
        let reports: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        reports[0]["checks"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c["id"].as_str().unwrap().to_owned())
            .collect()
    };
    let all = ids(&["check", "a1", "--student", "12345678", "--json"]);
    let task = ids(&["check", "a1.t2", "--student", "12345678", "--json"]);
    let expected: Vec<String> = all.iter().filter(|id| id.starts_with("a1.t2.")).cloned().collect();
    assert!(expected.len() >= 2 && expected.len() < all.len(), "{all:?}");
    assert_eq!(task, expected, "exactly the task's checks, in order");
    let one = ids(&["check", "a1.t2.count", "--student", "12345678", "--json"]);
    assert_eq!(one, ["a1.t2.count"]);
    // A name that selects nothing is bad input, and the message lists the tasks.
    let o = cg(&root(), &["check", "a1.t9", "--student", "12345678", "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("a1.t9") && err.contains("a1.t1, a1.t2, a1.t3"), "{err}");
    let o = cg(&root(), &["check", "a9.t1", "--student", "12345678"]);
    assert_eq!(o.status.code(), Some(2));
}
