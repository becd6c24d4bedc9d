//! A student's function that never returns does not hang `cg report`: the watchdog that
//! `cg report` and `report-checker` start ends the command with exit code 3 and says why, in the
//! student's language. The test runs itself a second time as the child that hangs.

use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use cg_assign::Impls;
use cg_core::lang::Lang;
use cg_report::app::{self, DeriveArgs, Kit, Source};

const CHILD: &str = "CG_REPORT_WATCHDOG_CHILD";

/// The reference solutions, but `a1.t1 vertices()` loops forever.
fn kit() -> Kit {
    let mut impls: Impls = cg_assign::impls!(cg_solutions);
    impls.a1.vertices = |_| loop {
        std::hint::spin_loop();
    };
    Kit {
        impls,
        student_file: || PathBuf::from("/nonexistent/student.toml"),
        worker: None,
        time_limit: app::TIME_LIMIT,
    }
}

/// In the child: derive the report with the looping function, under a 1-second watchdog. Run
/// only by the parent test below (as `--ignored`), never on its own.
#[test]
#[ignore = "the child process of a_function_that_never_returns_ends_the_report_command_with_a_message"]
fn child_derives_with_a_function_that_never_returns() {
    let Some(lang) = std::env::var(CHILD).ok() else { return };
    let lang = if lang == "ja" { Lang::Ja } else { Lang::En };
    app::start_watchdog(Duration::from_secs(1), lang);
    let output = std::env::temp_dir().join(format!("cg-report-watchdog-{}", std::process::id()));
    let command = app::Command::Derive(DeriveArgs {
        source: Source { student: Some("12345678".into()), ..Source::default() },
        output,
        no_render: true,
    });
    let _ = app::run(&command, &kit(), lang);
    // Only reached if the watchdog did not end the process.
    std::process::exit(0);
}

fn run_child(lang: &str) -> (Option<i32>, String) {
    let mut child = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "child_derives_with_a_function_that_never_returns",
            "--ignored",
            "--nocapture",
        ])
        .env(CHILD, lang)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > Duration::from_secs(120) {
            let _ = child.kill();
            panic!("the child still runs after 120 s: the watchdog did not stop it");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let mut stderr = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut stderr).unwrap();
    (status.code(), stderr)
}

#[test]
fn a_function_that_never_returns_ends_the_report_command_with_a_message() {
    if std::env::var_os(CHILD).is_some() {
        return;
    }
    let (code, stderr) = run_child("en");
    assert_eq!(code, Some(3), "exit code; stderr:\n{stderr}");
    assert!(
        stderr.contains("your code has run for more than 1 s without returning"),
        "stderr:\n{stderr}"
    );
    let (code, stderr) = run_child("ja");
    assert_eq!(code, Some(3), "exit code; stderr:\n{stderr}");
    assert!(
        stderr.contains("あなたのプログラムが 1 秒を超えても終わりません"),
        "stderr:\n{stderr}"
    );
}
