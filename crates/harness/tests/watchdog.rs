//! The command line's watchdog ([`cg_harness::check::watchdog`]) ends the process when a check
//! runs past its limit — also when a `guarded` call inside the check has ended before (it used to
//! clear the watchdog's record, and the rest of the outer check was no longer watched). The
//! watchdog ends the process, so the test runs itself again as a child that does it.

use std::process::Command;
use std::time::Duration;

use cg_core::lang::Lang;
use cg_harness::check;
use cg_harness::text::t;

/// Set in the child's environment: the child runs the check that never ends.
const CHILD: &str = "CG_HARNESS_WATCHDOG_CHILD";

const NAME: &str = "a_check_past_its_limit_ends_the_process_after_a_guarded_call_inside_it";

#[test]
fn a_check_past_its_limit_ends_the_process_after_a_guarded_call_inside_it() {
    if std::env::var_os(CHILD).is_some() {
        check::watchdog(Duration::from_millis(300), Lang::En);
        let _ = check::run("t.t1.slow", t("遅いチェック", "a slow check"), || {
            assert_eq!(check::guarded(|| 1), Ok(1));
            // The student's loop that does not end, after the guarded call.
            std::thread::sleep(Duration::from_secs(20));
            Ok(())
        });
        println!("the check ended, not watched");
        std::process::exit(0);
    }
    let me = std::env::current_exe().expect("the test's own program");
    let out = Command::new(me)
        .args(["--exact", NAME, "--nocapture", "--test-threads=1"])
        .env(CHILD, "1")
        .output()
        .expect("the child runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(3), "stdout:\n{stdout}\nstderr:\n{stderr}");
    assert!(
        stderr.contains("check t.t1.slow has run for more than 0.3 s"),
        "stdout:\n{stdout}\nstderr:\n{stderr}"
    );
}
