//! The trusted side's stand-ins for the student's functions: each assignment's `Impl` whose
//! functions call the worker ([`a1()`] … [`s()`]), so that the kit's checks, which take an
//! `Impl`, run unchanged in a process that does not link the student's code.
//!
//! [`with_worker`] makes a [`Worker`] the current one on this thread for the length of a
//! closure; every stand-in calls it. A call that gives no value raises its [`CallError`] as a
//! panic payload (`std::panic::panic_any`), which `cg_harness::check::run` turns into the
//! check's outcome: a `todo!()` is "not done yet" as before, a panic is a panic with the
//! student's own message and location, a call past its budget "timed out", a worker that died
//! "crashed". A stub that runs and carries its marker (`cg_student::not_started`) gives its
//! value, and the marker comes back with it and is recorded on this thread ([`Worker::call`]), so
//! the check says "not done yet" as it does with the function in process. Nothing the worker
//! prints is read as a result: a reply is a value of the function's return type, for the check
//! to judge.
//!
//! **Budgets.** A check's calls share one budget, [`Session::per_check`], from the moment the
//! check starts ([`begin_check`], called by `check::run`); a call outside any check has the
//! whole budget to itself. A check begun inside another (`guarded`, a view's call of `motion()`,
//! inside a check or a report's drawing) is judged as the outer one is, and its end gives the
//! outer one its judgement back (it ended it, so that a function that had already run out of time
//! was waited for again). Its budget is its own, and after it the outer check's calls have the
//! whole budget each, as a view's many calls inside one `guarded` need (the s view's pixels take
//! longer than one budget on a loaded machine). Under [`with_worker_until_timeout`] (the report, which calls the
//! student's functions outside checks, part after part) a call outside a check that ran out of
//! time makes every later one fail at once as timed out, instead of costing the budget again
//! for every part; [`Worker::timeouts`] says afterwards that it happened.
//!
//! **A function that ran out of time is not run again by the checks.** In a check started with
//! [`begin_judged_check`] (`cg_harness::check::run`: the checks of `cg check` and the grader,
//! not a window's or the report's calls), a call that would run a student's function that already
//! ran out of time in this session fails at once, [`CallError::TimedOut`] with `earlier` and
//! the function that ran out, instead of waiting for the whole budget once more: an endless loop
//! in `face_normals` cost 20 s in each of a1's three checks that call it. So do all the calls
//! under [`with_worker_until_timeout`] (the report: a looping shading function was waited for in
//! every cell of its table). Grading waits again ([`rerun_timed_out`]): a function that loops on
//! one input may answer another.
//!
//! **Batches.** Where a check would call a function many times (a3's frames, s's pixels), it
//! asks [`active`] and, when the functions are the worker's, uses one batch call instead
//! ([`a3_frames`], [`shade_pixels`]): the same calls of the student's functions
//! in the same order, run in the worker, one round trip.

use std::cell::RefCell;
use std::time::{Duration, Instant};

use cg_student::gl::Gl;
use cg_student::glam::Vec3;
use cg_student::s::{Pixel, Shading};
use cg_student::{Rgb, a1, a2, a3, a4, s};
use serde::Serialize;
use serde::de::DeserializeOwned;

use crate::tables::{A3Spec, Queries};
use crate::{CallError, Reason, Worker};

/// The worker the stand-ins call, and the time each check may spend in it.
#[derive(Debug)]
pub struct Session {
    /// The worker.
    pub worker: Worker,
    /// The time one check's calls may take together (and one call outside a check).
    pub per_check: Duration,
    /// When the running check's budget ends.
    deadline: Option<Instant>,
    /// Whether calls outside a check fail at once after one has timed out.
    until_timeout: bool,
    /// Whether the running check is one of a check run ([`begin_judged_check`]): a call of a
    /// function in `timed_out` then fails at once.
    judged: bool,
    /// The worker's functions whose calls ran out of time, in order, each once.
    timed_out: Vec<String>,
    /// The checks around the running one, innermost last: each one's judged flag, put back
    /// when the check inside it ends ([`end_check`]).
    outer: Vec<bool>,
}

impl Session {
    fn new(worker: Worker, per_check: Duration, until_timeout: bool) -> Session {
        Session {
            worker,
            per_check,
            deadline: None,
            until_timeout,
            judged: false,
            timed_out: Vec::new(),
            outer: Vec::new(),
        }
    }
}

thread_local! {
    static CURRENT: RefCell<Option<Session>> = const { RefCell::new(None) };
    /// Whether the checks of this thread run a function again after it ran out of time
    /// ([`rerun_timed_out`]).
    static RERUN: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Grading (`cg grade`): whether the checks on this thread call a student's function again after
/// it ran out of time in an earlier check. A function that loops on one input may answer another,
/// and a grade counts every check it can pass, so grading waits again; `cg check` does not (an
/// endless loop cost the student 20 s in each check that called it).
pub fn rerun_timed_out(on: bool) {
    RERUN.with(|r| r.set(on));
}

/// Runs `f` with `worker` as this thread's current worker (the stand-ins' functions call it),
/// each check's calls sharing `per_check`; gives the worker back afterwards (with what the
/// student's code printed in [`Worker::printed`]).
pub fn with_worker<T>(worker: Worker, per_check: Duration, f: impl FnOnce() -> T) -> (T, Worker) {
    session(Session::new(worker, per_check, false), f)
}

/// [`with_worker`], where a call outside a check that runs out of time makes every later call
/// outside a check fail at once (see the module's documentation): for the report.
pub fn with_worker_until_timeout<T>(
    worker: Worker,
    per_check: Duration,
    f: impl FnOnce() -> T,
) -> (T, Worker) {
    session(Session::new(worker, per_check, true), f)
}

fn session<T>(session: Session, f: impl FnOnce() -> T) -> (T, Worker) {
    /// Puts the previous session back, also when `f` panics (the worker is then dropped,
    /// which stops it).
    struct Restore(Option<Option<Session>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            if let Some(previous) = self.0.take() {
                CURRENT.with(|c| *c.borrow_mut() = previous);
            }
        }
    }
    let restore = Restore(Some(CURRENT.with(|c| c.borrow_mut().replace(session))));
    let value = f();
    let session = CURRENT.with(|c| c.borrow_mut().take());
    drop(restore);
    match session {
        Some(session) => (value, session.worker),
        // `f` cannot take the session: every nested `with_worker` puts it back.
        None => unreachable!("the session is put back by every nested with_worker"),
    }
}

/// Whether the student's functions on this thread are the worker's (inside [`with_worker`]).
#[must_use]
pub fn active() -> bool {
    CURRENT.with(|c| c.borrow().is_some())
}

/// A check starts: its calls share the session's budget from now on (nothing without a worker).
pub fn begin_check() {
    begin(false);
}

/// A check of a check run starts (`cg_harness::check::run`): as [`begin_check`], and a call that
/// would run a student's function that already ran out of time in this session fails at once
/// (see the module's documentation).
pub fn begin_judged_check() {
    begin(true);
}

fn begin(judged: bool) {
    CURRENT.with(|c| {
        if let Some(s) = c.borrow_mut().as_mut() {
            // Inside a check (a `guarded` call of a view inside a check or a report's drawing)
            // the calls stay judged as that check's are.
            let outer_judged = !s.outer.is_empty() && s.judged;
            s.outer.push(s.judged);
            // A budget past the clock's end is no deadline at all (not a panic).
            s.deadline = Instant::now().checked_add(s.per_check);
            s.judged = judged || outer_judged;
        }
    });
}

/// The check ended: calls outside a check get the whole budget again, and the check around it,
/// if any, its judgement.
pub fn end_check() {
    CURRENT.with(|c| {
        if let Some(s) = c.borrow_mut().as_mut() {
            s.deadline = None;
            s.judged = s.outer.pop().unwrap_or(false);
        }
    });
}

/// A timeout's function with the step the worker said it was at: `a3.idle@401` (a3: the
/// frame), or the function alone.
#[must_use]
pub fn with_step(function: &str, step: Option<u64>) -> String {
    match step {
        Some(step) => format!("{function}@{step}"),
        None => function.to_owned(),
    }
}

/// A timeout's function and the step after it, if any ([`with_step`]): `a3.idle@401` →
/// (`a3.idle`, 401).
#[must_use]
pub fn split_step(function: &str) -> (&str, Option<u64>) {
    match function.rsplit_once('@').map(|(f, step)| (f, step.parse().ok())) {
        Some((f, Some(step))) => (f, Some(step)),
        _ => (function, None),
    }
}

/// The student's functions a call of the worker's `function` runs: itself, or for a batch the
/// functions it runs (`a3.frames`: `a3.idle` and `a3.display`). A step after the name
/// (`a3.idle@401`, [`with_step`]) is left off.
#[must_use]
pub fn student_functions(function: &str) -> Vec<&str> {
    match split_step(function).0 {
        "a3.frames" => vec!["a3.idle", "a3.display"],
        "s.shade_pixels_queries" | "s.shade_pixels" => vec!["s.shade_pixel"],
        other => vec![other],
    }
}

/// Whether a call of `function` runs every student's function that a call of `timed_out` runs
/// (and so would run out of time again): `a3.frames` after `a3.idle`, not `a3.idle` after
/// `a3.frames` (it may have been `display` that looped).
fn runs_again(timed_out: &str, function: &str) -> bool {
    let now = student_functions(function);
    student_functions(timed_out).iter().all(|f| now.contains(f))
}

/// Calls `function` in the current worker within the check's budget: its value, or the
/// [`CallError`] raised as a panic payload.
///
/// # Panics
/// With a [`CallError`] payload when the call gives no value (see the module's documentation).
pub fn call<A: Serialize, R: DeserializeOwned>(function: &str, args: &A) -> R {
    let result = CURRENT.with(|c| {
        let mut current = c.borrow_mut();
        let Some(session) = current.as_mut() else {
            return Err(CallError::Broken(Reason::new(
                format!("{function}: ワーカーが動いていません"),
                format!("{function}: no worker is running"),
            )));
        };
        let limit = session.per_check;
        let not_run = |function: &str| CallError::TimedOut {
            limit,
            function: function.to_owned(),
            earlier: true,
        };
        if (session.judged || session.until_timeout)
            && !RERUN.with(std::cell::Cell::get)
            && let Some(earlier) = session.timed_out.iter().find(|t| runs_again(t, function))
        {
            return Err(not_run(earlier));
        }
        let budget = match session.deadline {
            None if session.until_timeout && session.worker.timeouts > 0 => {
                let earlier = session.timed_out.first().map_or(function, String::as_str);
                return Err(not_run(earlier));
            }
            None => limit,
            Some(end) => end.saturating_duration_since(Instant::now()),
        };
        if budget.is_zero() {
            // The check's budget was spent before this call.
            return Err(CallError::TimedOut {
                limit,
                function: function.to_owned(),
                earlier: false,
            });
        }
        // `function` (the batch's name) or, when the worker said, the student's function of the
        // batch that ran out (`a3.idle@401`): a later call that runs that one is not run again.
        match session.worker.call(function, args, budget) {
            Err(CallError::TimedOut { function, .. }) => {
                if !session.timed_out.contains(&function) {
                    session.timed_out.push(function.clone());
                }
                Err(CallError::TimedOut { limit, function, earlier: false })
            }
            other => other,
        }
    });
    result.unwrap_or_else(|e| std::panic::panic_any(e))
}

/// a1's functions, in the worker.
#[must_use]
pub fn a1() -> a1::Impl {
    a1::Impl {
        vertices: |spec| call("a1.vertices", spec),
        faces: |spec| call("a1.faces", spec),
        face_normals: |spec| call("a1.face_normals", spec),
        model_transform: |spec| call("a1.model_transform", spec),
    }
}

/// a2's functions, in the worker (a `&mut` argument is sent, and replaced by what comes back).
#[must_use]
pub fn a2() -> a2::Impl {
    a2::Impl {
        motion: |spec, state, drag| *state = call("a2.motion", &(spec, &*state, drag)),
        camera: |gl, state| *gl = call("a2.camera", &(&*gl, state)),
        display: |gl, state| *gl = call("a2.display", &(&*gl, state)),
    }
}

/// a3's functions, in the worker.
#[must_use]
pub fn a3() -> a3::Impl {
    a3::Impl {
        warmup_display: |gl, t| *gl = call("a3.warmup_display", &(&*gl, t)),
        idle: |spec, state| *state = call("a3.idle", &(A3Spec(spec.clone()), &*state)),
        display: |spec, state, gl| {
            *gl = call("a3.display", &(A3Spec(spec.clone()), state, &*gl));
        },
    }
}

/// a4's functions, in the worker.
#[must_use]
pub fn a4() -> a4::Impl {
    a4::Impl {
        tex_range: |spec| call("a4.tex_range", spec),
        tex_coords: |spec, i, j| call("a4.tex_coords", &(spec, i, j)),
        sampler: || call("a4.sampler", &()),
    }
}

/// The shading set's functions, in the worker (`shade_pixel`: [`shade_pixels`] of one pixel).
#[must_use]
pub fn s() -> s::Impl {
    s::Impl {
        ambient: |ia, ka| call("s.ambient", &(ia, ka)),
        diffuse: |ii, kd, n, l| call("s.diffuse", &(ii, kd, n, l)),
        specular: |ii, ks, n, l, v, shininess| call("s.specular", &(ii, ks, n, l, v, shininess)),
        attenuation: |kc, kl, kq, d| call("s.attenuation", &(kc, kl, kq, d)),
        spot_factor: |l, axis, cutoff, exponent| {
            call("s.spot_factor", &(l, axis, cutoff, exponent))
        },
        vertex_normals: |mesh| call("s.vertex_normals", mesh),
        vertex_normals_area: |mesh| call("s.vertex_normals_area", mesh),
        shade_pixel: |mode, pixel, light| {
            shade_pixels(mode, std::slice::from_ref(pixel), light).pop().unwrap_or(Vec3::NAN)
        },
        reflect: |i, n| call("s.reflect", &(i, n)),
        refract: |i, n, n1, n2| call("s.refract", &(i, n, n1, n2)),
    }
}

/// a3: from the start, `idle` up to each frame count in turn, then `display` on a fresh
/// recorder: the state and the recording of each frame (the worker's `a3.frames`).
///
/// # Panics
/// With a [`CallError`] payload, as [`call`].
#[must_use]
pub fn a3_frames(spec: &a3::Spec, frames: &[u64]) -> Vec<(a3::State, Gl)> {
    let out: Vec<(a3::State, Gl)> = call("a3.frames", &(A3Spec(spec.clone()), frames));
    if out.len() != frames.len() {
        let (got, asked) = (out.len(), frames.len());
        std::panic::panic_any(CallError::Broken(Reason::new(
            format!("a3.frames: {asked} フレームを頼んで {got} フレームが返りました"),
            format!("a3.frames: {got} frames for {asked} asked"),
        )));
    }
    out
}

/// s: `shade_pixel` of each pixel in `mode` with the kit's `light`, in two round trips for any
/// number of pixels: the worker lists what each pixel asks `light`, the kit lights those points
/// here, and the worker runs the function again with those answers (see [`crate::tables`](mod@crate::tables)).
///
/// # Panics
/// With a [`CallError`] payload, as [`call`]; a pixel that asked other questions the second
/// time (a function that is not deterministic) is a [`CallError::Broken`].
#[must_use]
pub fn shade_pixels(
    mode: Shading,
    pixels: &[Pixel],
    light: &dyn Fn(Vec3, Vec3) -> Rgb,
) -> Vec<Rgb> {
    let queries: Vec<Queries> = call("s.shade_pixels_queries", &(mode, pixels));
    if queries.len() != pixels.len() {
        let (got, asked) = (queries.len(), pixels.len());
        std::panic::panic_any(CallError::Broken(Reason::new(
            format!(
                "s.shade_pixels_queries: ピクセル {asked} 個に問い合わせの列が {got} 個返りました"
            ),
            format!("s.shade_pixels_queries: {got} lists for {asked} pixels"),
        )));
    }
    let answers: Vec<Vec<Rgb>> =
        queries.iter().map(|q| q.iter().map(|&(p, n)| light(p, n)).collect()).collect();
    let colours: Result<Vec<Rgb>, Reason> =
        call("s.shade_pixels", &(mode, pixels, &queries, &answers));
    match colours {
        Ok(c) if c.len() == pixels.len() => c,
        Ok(c) => std::panic::panic_any(CallError::Broken(Reason::new(
            format!("s.shade_pixels: ピクセル {} 個に色が {} 個返りました", pixels.len(), c.len()),
            format!("s.shade_pixels: {} colours for {} pixels", c.len(), pixels.len()),
        ))),
        Err(why) => std::panic::panic_any(CallError::Broken(Reason::new(
            format!("shade_pixel: {}", why.ja),
            format!("shade_pixel: {}", why.en),
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A batch runs several of the student's functions: it is not run again after one of them
    /// ran out of time, but that one still runs after the batch did (the batch's other function
    /// may have been the one that looped).
    #[test]
    fn a_batch_is_not_run_after_one_of_its_functions_ran_out_of_time() {
        assert_eq!(student_functions("a3.frames"), ["a3.idle", "a3.display"]);
        assert!(runs_again("a1.face_normals", "a1.face_normals"));
        assert!(!runs_again("a1.face_normals", "a1.faces"));
        assert!(runs_again("a3.idle", "a3.frames"));
        assert!(runs_again("a3.frames", "a3.frames"));
        assert!(!runs_again("a3.frames", "a3.idle") && !runs_again("a3.frames", "a3.display"));
        assert!(runs_again("s.shade_pixels_queries", "s.shade_pixels"));
        // The function a batch's worker said ran out, with its frame (a3.idle@401).
        assert!(runs_again("a3.idle@401", "a3.frames") && runs_again("a3.display@2", "a3.frames"));
        assert!(!runs_again("a3.display@2", "a3.idle") && runs_again("a3.idle@401", "a3.idle"));
    }

    #[test]
    fn a_step_follows_the_function_after_an_at_sign() {
        assert_eq!(with_step("a3.idle", Some(401)), "a3.idle@401");
        assert_eq!(with_step("a1.faces", None), "a1.faces");
        assert_eq!(split_step("a3.idle@401"), ("a3.idle", Some(401)));
        assert_eq!(split_step("a3.frames"), ("a3.frames", None));
        assert_eq!(split_step("a3.idle@x"), ("a3.idle@x", None));
        assert_eq!(student_functions("a3.display@7"), ["a3.display"]);
    }
}
