//! `cg watch`: the first board, a save that runs the checks again, the keys from a pipe (h, n,
//! q), and a build that fails. The checks run through the `cg` the tests built
//! (`CG_WATCH_CHECKER`), on a scratch folder (`--dir`), so nothing is rebuilt in release.

mod common;

use std::io::{BufRead, BufReader, Write};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, channel};
use std::time::{Duration, Instant};

use common::{root, scratch};

struct Watch {
    child: Child,
    stdin: ChildStdin,
    lines: Receiver<String>,
    seen: String,
}

impl Watch {
    fn start(dir: &std::path::Path, checker: &str, lang: &str) -> Watch {
        let mut child = Command::new(env!("CARGO_BIN_EXE_cg"))
            .args(["watch", "a1", "--student", "12345678", "--lang", lang, "--dir"])
            .arg(dir)
            .current_dir(root())
            .env("CG_WATCH_CHECKER", checker)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::inherit())
            .spawn()
            .unwrap();
        let stdin = child.stdin.take().unwrap();
        let stdout = child.stdout.take().unwrap();
        let (tx, lines) = channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stdout).lines().map_while(Result::ok) {
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        Watch { child, stdin, lines, seen: String::new() }
    }

    /// Waits until the output has `needle` `times` times in all (at most 60 s).
    fn until(&mut self, needle: &str, times: usize) {
        let start = Instant::now();
        while self.seen.matches(needle).count() < times {
            let left = Duration::from_secs(60).saturating_sub(start.elapsed());
            match self.lines.recv_timeout(left) {
                Ok(line) => {
                    self.seen.push_str(&line);
                    self.seen.push('\n');
                }
                Err(_) => panic!("no {needle:?} ×{times} within 60 s; output:\n{}", self.seen),
            }
        }
    }

    fn key(&mut self, key: &str) {
        writeln!(self.stdin, "{key}").unwrap();
    }

    fn finish(mut self) -> String {
        let start = Instant::now();
        loop {
            if let Some(status) = self.child.try_wait().unwrap() {
                assert!(status.success(), "{status}\n{}", self.seen);
                break;
            }
            assert!(start.elapsed() < Duration::from_secs(30), "no exit after q:\n{}", self.seen);
            std::thread::sleep(Duration::from_millis(50));
        }
        while let Ok(line) = self.lines.recv_timeout(Duration::from_millis(200)) {
            self.seen.push_str(&line);
            self.seen.push('\n');
        }
        self.seen
    }
}

#[test]
fn a_save_runs_the_checks_again_and_the_keys_answer() {
    let dir = scratch("cg-watch", "save");
    std::fs::write(dir.join("a1.rs"), "// the student's file\n").unwrap();
    let mut w = Watch::start(&dir, env!("CARGO_BIN_EXE_cg"), "en");
    w.until("[h] hint", 1);
    assert!(w.seen.contains("a1  …t1 …t2 …t3 …t4"), "{}", w.seen);
    assert!(w.seen.contains("── a1.t1 ──") && w.seen.contains("a1.t1.count"), "{}", w.seen);
    // A save: built and checked again.
    std::thread::sleep(Duration::from_millis(300));
    std::fs::write(dir.join("a1.rs"), "// the student's file, edited\n").unwrap();
    w.until("Building and checking", 2);
    w.until("[h] hint", 2);
    // h: the first failing check's hint (here: not written yet, with the stub's message).
    w.key("h");
    w.until("hint for a1.t1.count", 1);
    // n: the next task in focus.
    w.key("n");
    w.until("── a1.t2 ──", 1);
    w.key("q");
    let seen = w.finish();
    assert!(seen.contains("Bye."), "{seen}");
}

#[test]
fn a_failed_build_is_shown_and_watching_goes_on() {
    let dir = scratch("cg-watch", "broken");
    // A checker that fails as a build does: no JSON, a compiler error on stderr.
    let script = dir.join("broken-build.sh");
    std::fs::write(
        &script,
        "#!/bin/sh\necho 'error[E0425]: cannot find value `x` in this scope' >&2\necho ' --> exercises/src/a1.rs:3:5' >&2\nexit 101\n",
    )
    .unwrap();
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&script, std::fs::Permissions::from_mode(0o755)).unwrap();
    }
    #[cfg(not(unix))]
    return;
    let mut w = Watch::start(&dir, script.to_str().unwrap(), "ja");
    w.until("[r] もう一度", 1);
    assert!(w.seen.contains("ビルドかチェックが失敗しました"), "{}", w.seen);
    assert!(w.seen.contains("error[E0425]") && w.seen.contains("a1.rs:3:5"), "{}", w.seen);
    w.key("r");
    w.until("ビルドかチェックが失敗しました", 2);
    w.key("q");
    w.finish();
}

/// The board speaks the run's language: the checks run with `--lang`, and a stub's words are
/// said as `cg check` says them (`まだです: …`), not the stub's English message.
#[test]
fn the_board_is_in_the_runs_language() {
    let dir = scratch("cg-watch", "japanese");
    std::fs::write(dir.join("a1.rs"), "// the student's file\n").unwrap();
    let mut w = Watch::start(&dir, env!("CARGO_BIN_EXE_cg"), "ja");
    w.until("[h] ヒント", 1);
    assert!(w.seen.contains("まだです: "), "{}", w.seen);
    assert!(!w.seen.contains("list the vertices"), "{}", w.seen);
    w.key("q");
    w.finish();
}

/// What no save can mend is said at once with exit 2, as `cg check` says it: an ID that is no
/// assignment, a student number that does not read, checks that cannot start at all (no
/// cargo). The board used to wait for a save ("fix it and save"), and end 0.
#[test]
fn what_no_save_can_mend_ends_the_watch_with_exit_2() {
    let dir = scratch("cg-watch", "refused");
    for (args, checker, said) in [
        (vec!["watch", "a9"], env!("CARGO_BIN_EXE_cg"), "a1"),
        (vec!["watch", "a1", "--student", "1"], env!("CARGO_BIN_EXE_cg"), "8"),
        (vec!["watch", "a1", "--student", "12345678"], "/no/such/cargo", "cannot start the checks"),
    ] {
        let o = Command::new(env!("CARGO_BIN_EXE_cg"))
            .args(&args)
            .args(["--lang", "en", "--dir"])
            .arg(&dir)
            .current_dir(root())
            .env("CG_WATCH_CHECKER", checker)
            .stdin(Stdio::null())
            .output()
            .unwrap();
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
        assert!(err.contains(said), "{args:?}: {err}");
        assert!(!String::from_utf8_lossy(&o.stdout).contains("fix it and save"), "{args:?}");
    }
}
