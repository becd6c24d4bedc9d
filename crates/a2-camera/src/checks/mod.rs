//! The checks of `a2`: the ordered list ([`checks`]) and what the checks of several tasks
//! share (the student's view matrix at a state). The checks of each task are in `t1.rs`
//! (`motion()`), `t2.rs` (`camera()`) and `t3.rs` (`display()`).

mod t1;
mod t2;
mod t3;

use std::any::Any;
use std::panic::{self, AssertUnwindSafe};

use cg_core::glam::Mat4;
use cg_core::lang::Lang;
use cg_harness::check;
use cg_harness::text::t;
use cg_harness::{CheckResult, Text};
use cg_student::gl::Gl as Recorder;
use cg_worker::CallError;

use crate::show::Var;
use crate::spec::SpecVars;
use crate::{CameraState, Impl, Spec};

use t1::{changes_by_amount, clamped, only_listed_drags, sequence, yaw_wraps};
use t2::{pole_states, view_matches, view_states};
use t3::{light_after_camera, objects_in_place, stack_balanced, starts_from_identity};

/// Every check of this assignment for `spec`, run against `imp`.
///
/// | check | what |
/// |---|---|
/// | `a2.t1.yaw`, `a2.t1.pitch`, `a2.t1.distance`, `a2.t1.pan` | each variable changes by the spec's amount per pixel of its own drag (sign, speed, degrees) |
/// | `a2.t1.buttons` | a drag changes only the variables the spec gives it (other buttons, Shift, the other direction change nothing) |
/// | `a2.t1.wrap` | camera_yaw wraps into `[0, 360)` across 360 and 0, also over many turns |
/// | `a2.t1.pitch_range`, `a2.t1.distance_range`, `a2.t1.pan_range` | clamped at both ends (the pole −90° included), and a drag back moves at once |
/// | `a2.t1.sequence` | 150 mixed drags (diagonal ones too) from the start give the spec's state after every drag |
/// | `a2.t2.view` | the view matrix equals `T(0, 0, −d) · Rx(−pitch) · Ry(−yaw) · T(−target)`; a mismatch names the variable or the order that is off |
/// | `a2.t2.pole` | the same at pitch ±90° (no look-at with an up vector), finite |
/// | `a2.t3.light` | light 0 is at `V · (10, 10, 10, 1)` in eye space: set after the camera |
/// | `a2.t3.objects` | the ground drawn with `V`, the pyramid with `V · T(0, 1, 0)` |
/// | `a2.t3.stack` | something drawn, push/pop balanced, no GL errors |
/// | `a2.t3.identity` | `display()` starts from glLoadIdentity: the frame does not depend on the previous one |
///
/// `a2.t1.pan` and `a2.t1.pan_range` exist only for specs with a pan.
#[must_use]
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    // a2.t1 (the pan ones only when the spec has a pan)
    let mut out = Vec::new();
    for (var, op) in spec.operations() {
        if var == Var::TargetZ {
            continue; // a2.t1.pan checks target_x and target_z together
        }
        let (id, title) = match var {
            Var::Yaw => ("a2.t1.yaw", t("camera_yaw の変化量", "how camera_yaw changes")),
            Var::Pitch => ("a2.t1.pitch", t("camera_pitch の変化量", "how camera_pitch changes")),
            Var::Distance => {
                ("a2.t1.distance", t("camera_distance の変化量", "how camera_distance changes"))
            }
            _ => ("a2.t1.pan", t("注視点の移動量", "how the target moves")),
        };
        let mut ops = vec![(var, op)];
        if let (Var::TargetX, Some(pan)) = (var, &spec.pan) {
            ops.push((Var::TargetZ, pan.z));
        }
        out.push(check::run(id, title, || {
            ops.iter().try_for_each(|(var, op)| changes_by_amount(spec, imp, *var, op))
        }));
    }
    out.push(check::run(
        "a2.t1.buttons",
        t(
            "指定のボタン・方向のドラッグだけが変数を変える",
            "only the listed buttons and directions change a variable",
        ),
        || only_listed_drags(spec, imp),
    ));
    out.push(check::run(
        "a2.t1.wrap",
        t("camera_yaw を 0〜360 に折り返す", "camera_yaw wraps into [0, 360)"),
        || yaw_wraps(spec, imp),
    ));
    out.push(check::run(
        "a2.t1.pitch_range",
        t("camera_pitch の範囲の制限", "camera_pitch is clamped"),
        || clamped(spec, imp, Var::Pitch, &spec.pitch, spec.pitch_min, spec.pitch_max),
    ));
    out.push(check::run(
        "a2.t1.distance_range",
        t("camera_distance の範囲の制限", "camera_distance is clamped"),
        || clamped(spec, imp, Var::Distance, &spec.distance, spec.distance_min, spec.distance_max),
    ));
    if let Some(pan) = spec.pan {
        out.push(check::run(
            "a2.t1.pan_range",
            t("注視点の範囲の制限", "the target is clamped"),
            || {
                clamped(spec, imp, Var::TargetX, &pan.x, -pan.limit, pan.limit)?;
                clamped(spec, imp, Var::TargetZ, &pan.z, -pan.limit, pan.limit)
            },
        ));
    }
    out.push(check::run(
        "a2.t1.sequence",
        t(
            "いろいろなドラッグを続けたあとの変数（斜めのドラッグを含む）",
            "the variables after a long mix of drags (diagonal ones too)",
        ),
        || sequence(spec, imp),
    ));
    // a2.t2
    out.extend([
        check::run("a2.t2.view", t("視点の変換行列", "the view transform"), || {
            view_matches(spec, imp, &view_states(spec))
        }),
        check::run(
            "a2.t2.pole",
            t(
                "真上・真下から見た視点の変換行列（camera_pitch = ±90°）",
                "the view transform looking straight down or up (camera_pitch = ±90°)",
            ),
            || view_matches(spec, imp, &pole_states(spec)),
        ),
    ]);
    // a2.t3
    out.extend([
        check::run(
            "a2.t3.light",
            t(
                "光源の位置を視点の変換の後に設定（ワールド座標系に固定）",
                "the light is set after the camera (fixed in the world)",
            ),
            || light_after_camera(spec, imp),
        ),
        check::run(
            "a2.t3.objects",
            t("地面と四角すいの位置", "where the ground and the pyramid are drawn"),
            || objects_in_place(spec, imp),
        ),
        check::run(
            "a2.t3.stack",
            t(
                "何かが描かれ、glPushMatrix と glPopMatrix が対応し、GL のエラーがない",
                "something is drawn, push and pop match, no GL errors",
            ),
            || stack_balanced(spec, imp),
        ),
        check::run(
            "a2.t3.identity",
            t(
                "display() が単位行列から始まる（前のフレームに依存しない）",
                "display() starts from the identity (no dependence on the previous frame)",
            ),
            || starts_from_identity(spec, imp),
        ),
    ]);
    out
}

/// Calls one of the student's functions, `f`, for a check. A panic in it goes on to the check
/// with the call written after its message — `too far ← motion(spec, &mut CameraState { … },
/// &Drag { … })` — so that the check's "your code panicked" line names the input, as a ✗ line's
/// "where" does; the panic's place (`exercises/src/a2.rs:64:32`) is kept. `call` writes the
/// call as Rust (it reads the same in both languages). A stub's `todo!()`, a call that ran out
/// of time and the worker's other ends of a call go on unchanged.
pub(crate) fn calling<T>(call: impl FnOnce() -> String, f: impl FnOnce() -> T) -> T {
    match panic::catch_unwind(AssertUnwindSafe(f)) {
        Ok(value) => value,
        Err(payload) => panic::resume_unwind(with_call(payload, call)),
    }
}

/// A panic's `payload` with `call` after its message: a worker's [`CallError::Panicked`] (the
/// place inside it), or the message of a panic on this thread (the check's panic hook has kept
/// its place). Any other payload, and a stub's `todo!()`, as it is.
fn with_call(payload: Box<dyn Any + Send>, call: impl FnOnce() -> String) -> Box<dyn Any + Send> {
    let panicked = match payload.downcast_ref::<CallError>() {
        Some(CallError::Panicked { message, location }) => {
            Some((message.clone(), Some(location.clone())))
        }
        Some(_) => None,
        None => cg_worker::panic_message(payload.as_ref()).map(|message| (message, None)),
    };
    match panicked {
        Some((message, in_worker)) if cg_worker::stub_text(&message).is_none() => {
            let message = format!("{message} ← {}", call());
            match in_worker {
                Some(location) => Box::new(CallError::Panicked { message, location }),
                None => Box::new(message),
            }
        }
        _ => payload,
    }
}

/// What the student's camera leaves on a fresh context at `s`: the matrix, or what went wrong.
pub(crate) fn student_view(imp: &Impl, s: &CameraState) -> Result<Mat4, (Text, Text)> {
    let mut rec = Recorder::new();
    calling(|| format!("camera(gl, &{s:?})"), || (imp.camera)(&mut rec, s));
    let gl = crate::replay(&rec);
    if let Some(e) = gl.errors().first() {
        return Err((
            Text::new(
                format!("{}: {}", e.function, e.error.message(Lang::Ja)),
                format!("{}: {}", e.function, e.error.message(Lang::En)),
            ),
            Text::new(
                format!("camera() の {} がエラーです: {}", e.function, e.error.message(Lang::Ja)),
                format!("{} in camera() is an error: {}", e.function, e.error.message(Lang::En)),
            ),
        ));
    }
    gl.model_view().matrix().map_err(|e| {
        (
            e.text(),
            Text::new(
                format!("camera() の変換が不正です: {}", e.message(Lang::Ja)),
                format!("camera() builds an invalid transform: {}", e.message(Lang::En)),
            ),
        )
    })
}
