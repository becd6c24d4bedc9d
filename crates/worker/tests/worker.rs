//! The caller and the worker over a real pipe, with the fixture worker: values come back, a
//! `todo!()` is a panic with its message, a stub's marker comes back with its value (or panic),
//! an endless loop fails only its own call (and the next call gets a fresh worker), an abort is a
//! crash, and the student's prints never break a reply.

use std::time::{Duration, Instant};

use cg_worker::{CallError, Worker};

fn worker() -> Worker {
    Worker::new(env!("CARGO_BIN_EXE_cg-worker-fixture"), Vec::<String>::new())
}

const BUDGET: Duration = Duration::from_secs(5);

/// The fixture's `loop` ran out of `limit` (or, `earlier`, was not run: it had already).
fn timed_out(limit: Duration, earlier: bool) -> CallError {
    CallError::TimedOut { limit, function: "loop".to_owned(), earlier }
}

/// What a call through the proxy gave: its value, or the [`CallError`] it raised.
fn outcome(f: &dyn Fn() -> i64) -> Result<i64, Option<CallError>> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f))
        .map_err(|e| e.downcast::<CallError>().map(|e| *e).ok())
}

#[test]
fn values_and_changed_arguments_come_back() {
    let mut w = worker();
    assert_eq!(w.call::<_, i64>("add", &(2, 3), BUDGET), Ok(5));
    assert_eq!(w.call::<_, Vec<f32>>("grow", &vec![0.25f32], BUDGET), Ok(vec![0.25, 1.5]));
    // Each is said in both languages, for the Japanese feedback as for the English.
    let broken = |r: Result<i64, CallError>, ja: &str, en: &str| match r {
        Err(CallError::Broken(why)) => {
            assert!(why.ja.contains(ja) && why.en.contains(en), "{why:?}");
        }
        other => panic!("{other:?}"),
    };
    broken(w.call("nothing", &(), BUDGET), "ワーカーに関数 nothing がありません", "no function");
    broken(w.call("add", &"x", BUDGET), "add が引数を読めませんでした", "could not read");
    // A value of another type than the caller expects is no value.
    match w.call::<_, String>("add", &(1, 1), BUDGET) {
        Err(CallError::Broken(why)) => assert!(why.ja.contains("別の型の値"), "{why:?}"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_todo_is_a_panic_with_its_message_and_the_worker_goes_on() {
    let mut w = worker();
    match w.call::<_, i64>("todo", &(), BUDGET) {
        Err(CallError::Panicked { message, location }) => {
            assert_eq!(message, "not yet implemented: t.t1: write it");
            assert!(location.is_some_and(|l| l.contains("fixture.rs")));
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(w.call::<_, i64>("add", &(1, 1), BUDGET), Ok(2));
}

#[test]
fn a_stubs_marker_comes_back_with_the_reply_and_is_recorded_on_the_callers_thread() {
    let mut w = worker();
    let _ = cg_student::take_not_started();
    // The stub's value, for the view; its marker, for the checks.
    assert_eq!(w.call::<_, i64>("stub", &7, BUDGET), Ok(7));
    assert_eq!(cg_student::take_not_started(), ["t.t2"]);
    match w.call::<_, i64>("stub_panic", &(), BUDGET) {
        Err(CallError::Panicked { message, .. }) => assert_eq!(message, "index out of bounds"),
        other => panic!("{other:?}"),
    }
    assert_eq!(cg_student::take_not_started(), ["t.t3"]);
    // A call that reaches no marker records none, and no marker is left over in the worker.
    assert_eq!(w.call::<_, i64>("add", &(1, 1), BUDGET), Ok(2));
    assert!(cg_student::take_not_started().is_empty());
}

#[test]
fn an_endless_loop_fails_its_own_call_only() {
    let mut w = worker();
    let started = Instant::now();
    let budget = Duration::from_millis(300);
    assert_eq!(w.call::<_, i64>("loop", &(), budget), Err(timed_out(budget, false)));
    assert!(started.elapsed() < Duration::from_secs(3), "{:?}", started.elapsed());
    // The next call runs in a fresh worker.
    assert_eq!(w.call::<_, i64>("add", &(4, 5), BUDGET), Ok(9));
}

/// a3's batch of frames runs `idle` and `display` in turn: when one of them loops, the timeout
/// names that one and the frame the worker said it was at (`a3.idle@5`: the call that makes
/// frame 5; `a3.display@9`: drawing frame 9, the first asked from 5 on), not the batch; the
/// caller keeps only a function of the call's own batch (the fixture's `a1.faces` says it runs
/// `a3.display` and is named `a1.faces` all the same).
#[test]
fn a_timeout_in_a_batch_names_the_function_and_the_frame_the_worker_said() {
    let budget = Duration::from_millis(800);
    let spec = cg_worker::tables::A3Spec(cg_student::a3::Spec { objects: Vec::new(), unit_s: 1.0 });
    for (which, named) in [("idle", "a3.idle@5"), ("display", "a3.display@9")] {
        let mut w = Worker::new(env!("CARGO_BIN_EXE_cg-worker-fixture"), ["--a3-loop", which]);
        // Frames before the loop come back.
        let early: Vec<(cg_student::a3::State, cg_student::gl::Gl)> =
            w.call("a3.frames", &(&spec, vec![1u64, 4]), BUDGET).unwrap();
        assert_eq!(early.iter().map(|(s, _)| s.frame).collect::<Vec<_>>(), [1, 4]);
        let r = w.call::<_, Vec<(cg_student::a3::State, cg_student::gl::Gl)>>(
            "a3.frames",
            &(&spec, vec![1u64, 3, 9]),
            budget,
        );
        assert_eq!(
            r,
            Err(CallError::TimedOut { limit: budget, function: named.to_owned(), earlier: false }),
            "{which}"
        );
    }
    let mut w = worker();
    assert_eq!(
        w.call::<_, i64>("a1.faces", &(), budget),
        Err(CallError::TimedOut { limit: budget, function: "a1.faces".to_owned(), earlier: false })
    );
    // The worker's reports never reach a reply: the next call's value is its own.
    assert_eq!(w.call::<_, i64>("add", &(2, 2), BUDGET), Ok(4));
}

#[test]
fn an_abort_is_a_crash_of_that_call_with_the_workers_stderr() {
    let mut w = worker();
    match w.call::<_, i64>("abort", &(), BUDGET) {
        // Said in each language, not as the system's English (`signal: 6 (SIGABRT)`).
        #[cfg(unix)]
        Err(CallError::Crashed { status, .. }) => {
            assert!(status.ja.starts_with("シグナル 6（SIGABRT）で終了しました"), "{status:?}");
            assert!(status.en.starts_with("it was ended by signal 6 (SIGABRT)"), "{status:?}");
        }
        #[cfg(not(unix))]
        Err(CallError::Crashed { status, .. }) => assert!(!status.ja.is_empty(), "{status:?}"),
        other => panic!("{other:?}"),
    }
    assert_eq!(w.call::<_, i64>("add", &(1, 2), BUDGET), Ok(3));
}

/// A call of `exit()` is said with its code, and a stack overflow as one, in both languages.
#[test]
fn an_exit_and_a_stack_overflow_are_said_as_what_they_are() {
    let mut w = worker();
    for code in [0, 3] {
        match w.call::<_, i64>("exit", &code, BUDGET) {
            Err(CallError::Crashed { status, .. }) => {
                assert!(
                    status.ja.starts_with(&format!("終了コード {code} で終了しました")),
                    "{status:?}"
                );
                assert!(
                    status.en.starts_with(&format!("it exited with code {code}")),
                    "{status:?}"
                );
                assert!(!status.ja.contains("exit status"), "{status:?}");
            }
            other => panic!("{other:?}"),
        }
    }
    match w.call::<_, u64>("recurse", &1u64, Duration::from_secs(30)) {
        Err(CallError::Crashed { status, stderr }) => {
            assert!(status.ja.starts_with("スタックが溢れました"), "{status:?} {stderr}");
            assert!(status.en.starts_with("its stack overflowed"), "{status:?}");
        }
        other => panic!("{other:?}"),
    }
    assert_eq!(w.call::<_, i64>("add", &(1, 2), BUDGET), Ok(3));
}

#[test]
fn prints_are_kept_apart_from_replies() {
    let mut w = worker();
    assert_eq!(w.call::<_, i64>("print", &21, BUDGET), Ok(42));
    assert_eq!(w.call::<_, i64>("print", &1, BUDGET), Ok(2));
    let printed = String::from_utf8_lossy(&w.printed).into_owned();
    assert_eq!(printed, "debugging: x = 21\ndebugging: x = 1\n");
}

/// The worker's own memory limit (`limit_memory`, as cg-check-runner's `--memory-mb` sets it)
/// stops a function that allocates without end: the call is a crash with the allocator's
/// message, and the next call runs in a fresh worker. Linux (RLIMIT_AS) and Windows (a job
/// object's process memory limit); macOS's RLIMIT_AS is not known to hold, so not asserted there.
#[cfg(any(target_os = "linux", windows))]
#[test]
fn the_memory_limit_stops_a_hoarding_function() {
    let mut w = Worker::new(env!("CARGO_BIN_EXE_cg-worker-fixture"), ["--memory-mb", "256"]);
    // Within the limit it returns.
    assert_eq!(w.call::<_, usize>("hoard", &64u64, BUDGET), Ok(1));
    match w.call::<_, usize>("hoard", &4096u64, Duration::from_secs(60)) {
        Err(CallError::Crashed { stderr, status }) => {
            assert!(stderr.contains("memory allocation"), "{stderr}");
            assert!(status.ja.starts_with("メモリの上限を超えました"), "{status:?}");
            assert!(status.en.starts_with("it went over the memory limit"), "{status:?}");
        }
        other => panic!("4 GiB under a limit of 256 MiB: {other:?}"),
    }
    assert_eq!(w.call::<_, i64>("add", &(1, 2), BUDGET), Ok(3));
}

#[test]
fn a_module_left_out_is_answered_with_its_errors_and_the_others_still_run() {
    let errors = vec!["error: expected `;`".to_owned()];
    let left_out = [("a1".to_owned(), errors.clone())].into_iter().collect();
    let mut w = worker().without_modules(left_out);
    // Only the module's own functions (`a1.…`), not one whose name merely starts alike.
    assert_eq!(
        w.call::<_, i64>("a1.vertices", &(), BUDGET),
        Err(CallError::DoesNotCompile { module: "a1".into(), errors })
    );
    assert_eq!(w.call::<_, i64>("add", &(2, 3), BUDGET), Ok(5));
    assert!(matches!(w.call::<_, i64>("a10.x", &(), BUDGET), Err(CallError::Broken(_))));
    assert_eq!(w.modules_left_out().len(), 1);
}

/// Under `with_worker_until_timeout` (the report's calls), a call outside a check that ran out of
/// time makes every later call outside a check fail at once as timed out, instead of each
/// waiting for the whole budget; a check still gets its own budget and a fresh worker; the
/// worker counts the timeout. Under `with_worker` (a window's calls) the next call runs.
#[test]
fn after_a_timeout_outside_a_check_later_calls_outside_one_fail_at_once() {
    use cg_worker::proxy;
    let budget = Duration::from_millis(300);
    let (results, w) = proxy::with_worker_until_timeout(worker(), budget, || {
        let first = outcome(&|| proxy::call("loop", &()));
        let later = outcome(&|| proxy::call("add", &(4, 5)));
        proxy::begin_check();
        let in_a_check = outcome(&|| proxy::call("add", &(4, 5)));
        // The report's table cell, in a check of its own, that runs the looping function again.
        let started = Instant::now();
        let looped = outcome(&|| proxy::call("loop", &()));
        let took = started.elapsed();
        proxy::end_check();
        (first, later, in_a_check, looped, took)
    });
    assert_eq!(results.0, Err(Some(timed_out(budget, false))));
    assert_eq!(results.1, Err(Some(timed_out(budget, true))), "would be Ok(9) without");
    assert_eq!(results.2, Ok(9));
    assert_eq!(results.3, Err(Some(timed_out(budget, true))), "not waited for again");
    assert!(results.4 < Duration::from_millis(100), "{:?}", results.4);
    assert_eq!(w.timeouts, 1);
    let (results, w) = proxy::with_worker(worker(), budget, || {
        let first = outcome(&|| proxy::call("loop", &()));
        (first, outcome(&|| proxy::call("add", &(4, 5))))
    });
    assert_eq!(results, (Err(Some(timed_out(budget, false))), Ok(9)));
    assert_eq!(w.timeouts, 1);
}

/// An endless loop in a student's function costs the time limit once in a check run, not once
/// per check that calls it (three of a1's checks call `face_normals`: 60 s): in a later check
/// (`begin_judged_check`, as `cg_harness::check::run` starts them) a call of a function that ran
/// out of time fails at once, naming it, while the other functions still run; a call outside
/// such a check (a view's) runs it again.
#[test]
fn a_function_that_ran_out_of_time_is_not_run_again_by_later_checks() {
    use cg_worker::proxy;
    let limit = Duration::from_millis(300);
    let check = |f: &dyn Fn() -> i64| {
        proxy::begin_judged_check();
        let started = Instant::now();
        let result = outcome(f);
        proxy::end_check();
        (result, started.elapsed())
    };
    let (results, w) = proxy::with_worker(worker(), limit, || {
        let first = check(&|| proxy::call("loop", &()));
        let again = check(&|| proxy::call("loop", &()));
        let other = check(&|| proxy::call("add", &(4, 5)));
        proxy::begin_check();
        let viewed = outcome(&|| proxy::call("loop", &()));
        proxy::end_check();
        (first, again, other, viewed)
    });
    let (first, again, other, viewed) = results;
    assert_eq!(first.0, Err(Some(timed_out(limit, false))));
    assert!(first.1 >= limit, "{:?}", first.1);
    assert_eq!(again.0, Err(Some(timed_out(limit, true))), "the function is named");
    assert!(again.1 < Duration::from_millis(100), "not waited for again: {:?}", again.1);
    assert_eq!(other.0, Ok(9));
    assert_eq!(viewed, Err(Some(timed_out(limit, false))), "outside a check run it runs");
    assert_eq!(w.timeouts, 2);

    // Grading runs it again in every check: it may answer other inputs.
    let (again, w) = std::thread::spawn(move || {
        proxy::rerun_timed_out(true);
        proxy::with_worker(w, limit, || {
            let _ = check(&|| proxy::call("loop", &()));
            check(&|| proxy::call("loop", &()))
        })
    })
    .join()
    .unwrap();
    assert_eq!(again.0, Err(Some(timed_out(limit, false))), "run again when grading");
    assert!(again.1 >= limit, "{:?}", again.1);
    assert_eq!(w.timeouts, 4);
}

/// A check begun inside a check (`guarded` around a view's call of `motion()`, inside a check or
/// the report's drawing) is judged as the outer one is, and its end gives the outer one its
/// judgement back: a function that already ran out of time fails at once inside it and after it.
/// (The inner end cleared the judgement: the loop was waited for again.)
#[test]
fn a_check_inside_a_check_is_judged_as_the_outer_one() {
    use cg_worker::proxy;
    let limit = Duration::from_millis(1000);
    let (results, w) = proxy::with_worker(worker(), limit, || {
        proxy::begin_judged_check();
        let first = outcome(&|| proxy::call("loop", &()));
        proxy::end_check();
        proxy::begin_judged_check();
        proxy::begin_check();
        let started = Instant::now();
        let inside = outcome(&|| proxy::call("loop", &()));
        let inside_took = started.elapsed();
        proxy::end_check();
        let after = outcome(&|| proxy::call("loop", &()));
        let other = outcome(&|| proxy::call("add", &(4, 5)));
        proxy::end_check();
        // Outside any check (a view's own calls), the function runs again.
        proxy::begin_check();
        let viewed = outcome(&|| proxy::call("loop", &()));
        proxy::end_check();
        (first, inside, inside_took, after, other, viewed)
    });
    let (first, inside, inside_took, after, other, viewed) = results;
    assert_eq!(first, Err(Some(timed_out(limit, false))));
    assert_eq!(inside, Err(Some(timed_out(limit, true))), "judged inside the judged check");
    assert!(inside_took < Duration::from_millis(200), "not waited for again: {inside_took:?}");
    assert_eq!(after, Err(Some(timed_out(limit, true))), "the outer check goes on judged");
    assert_eq!(other, Ok(9));
    assert_eq!(viewed, Err(Some(timed_out(limit, false))), "a view's check is not judged");
    assert_eq!(w.timeouts, 2);
    // A view's many calls inside one `guarded` (the s view's pixels, longer than one budget on a
    // loaded machine: CI's handout test) are not held to the outer one's budget.
    let short = Duration::from_millis(200);
    let (later, _) = proxy::with_worker(worker(), short, || {
        proxy::begin_check();
        std::thread::sleep(Duration::from_millis(300));
        proxy::begin_check();
        let inside = outcome(&|| proxy::call("add", &(1, 2)));
        proxy::end_check();
        let after = outcome(&|| proxy::call("add", &(3, 4)));
        proxy::end_check();
        (inside, after)
    });
    assert_eq!(later, (Ok(3), Ok(7)));
}

/// A panic's message is the student's: one of 20 MB comes back cut to MAX_MESSAGE_BYTES, with
/// its length, so a report never holds it whole.
#[test]
fn a_huge_panic_message_is_cut() {
    let mut w = worker();
    match w.call::<_, i64>("shout", &(20usize << 20), BUDGET) {
        Err(CallError::Panicked { message, .. }) => {
            assert!(message.len() < cg_worker::client::MAX_MESSAGE_BYTES + 64, "{}", message.len());
            assert!(
                message.ends_with(&format!("… ({} bytes)", 20usize << 20)),
                "{}",
                &message[4000..]
            );
        }
        other => panic!("{:?}", other.map(|_| ())),
    }
}

/// A worker whose thread writes replies without end, unasked: the caller holds at most one
/// waiting reply (the worker blocks on its pipe), and a reply not the call's stops the worker.
/// The caller's memory grew by the pipe's speed, gigabytes in a second, until the system ended
/// the whole grading.
#[cfg(target_os = "linux")]
#[test]
fn replies_written_unasked_do_not_fill_the_callers_memory() {
    let before = rss_mb();
    let mut w = worker();
    let flood = w.call::<_, i64>("flood", &(), BUDGET);
    let broken = |r: &Result<i64, CallError>| matches!(r, Err(CallError::Broken(_)));
    assert!(matches!(flood, Ok(1)) || broken(&flood), "{flood:?}");
    // Until the first reply written unasked is read — at the next call on a quiet machine; a
    // loaded one may take seconds to encode the first 4 MiB — each call is answered with its
    // own value, never with one written unasked, and the caller holds two or three frames of
    // 4 MiB at most while the worker floods (the unbounded queue held hundreds). The reply
    // written unasked is no value, and stops the worker.
    let mut seen = broken(&flood);
    let started = std::time::Instant::now();
    while !seen && started.elapsed() < Duration::from_secs(60) {
        std::thread::sleep(Duration::from_millis(800));
        let grown = rss_mb().saturating_sub(before);
        assert!(grown < 200, "the caller grew by {grown} MiB");
        let next = w.call::<_, i64>("add", &(2, 3), BUDGET);
        assert!(matches!(next, Ok(5)) || broken(&next), "{next:?}");
        seen = broken(&next);
    }
    assert!(seen, "no reply written unasked was read in a minute");
    // A fresh worker answers the call after.
    assert_eq!(w.call::<_, i64>("add", &(2, 3), BUDGET), Ok(5));
}

/// A reply of more items than [`cg_worker::cbor::MAX_ITEMS`] is refused before it is decoded:
/// decoded as values, each one-byte number on the pipe took the caller 32 bytes (a frame of
/// 256 MiB, about 8 GiB); the worker is stopped, and a fresh one answers the next call.
#[cfg(target_os = "linux")]
#[test]
fn a_reply_of_too_many_items_is_refused_before_it_is_decoded() {
    let mut w = worker();
    let before = rss_mb();
    // The reply is `{"Value": [n numbers]}`: a map, its key, the list and the numbers.
    let too_many = cg_worker::cbor::MAX_ITEMS - 2;
    match w.call::<_, Vec<u8>>("items", &too_many, Duration::from_secs(60)) {
        Err(CallError::Broken(why)) => {
            assert!(why.en.contains("too large") && why.en.contains("more than"), "{why:?}");
            assert!(why.ja.contains("大きすぎる"), "{why:?}");
        }
        other => panic!("{:?}", other.map(|v| v.len())),
    }
    let grown = rss_mb().saturating_sub(before);
    // The frame itself (16 MiB), not 32 bytes per item (512 MiB).
    assert!(grown < 200, "the caller grew by {grown} MiB");
    // One fewer is read, as a list of numbers (not a value per number).
    let fits = w.call::<_, Vec<u8>>("items", &(too_many - 1), Duration::from_secs(60)).unwrap();
    assert_eq!(fits.len(), too_many - 1);
}

/// This process's resident memory, in MiB.
#[cfg(target_os = "linux")]
fn rss_mb() -> u64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let line = status.lines().find(|l| l.starts_with("VmRSS:")).unwrap();
    line.split_whitespace().nth(1).unwrap().parse::<u64>().unwrap() / 1024
}
