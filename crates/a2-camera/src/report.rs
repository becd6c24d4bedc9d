//! The report's data for `a2`: the view matrix at the stated mouse states, numerically and
//! with the camera variables named (see [`cg_harness::symbolic`]).

use cg_core::glam::Mat4;
use cg_core::lang::Lang;
use cg_core::product::{MatrixProduct, format_number};
use cg_harness::Text;
use cg_harness::check::{Outcome, guarded};
use cg_harness::report::{Missing, NamedMatrix, Part};
use cg_harness::symbolic::{Var, drop_constant_identities, numeric, symbolize};

use crate::{CameraState, Drag, DragAxis, Gesture, Impl, Operation, Spec, SpecExt as _};

/// Assignment 2: the view transform.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraData {
    /// The view matrix at the stated mouse states.
    pub matrices: Vec<NamedMatrix>,
}

/// Pixels per call of `motion()` in the stated drags (GLUT calls it every few pixels).
const DRAG_STEP_PX: f32 = 10.0;

/// The mouse state the camera is probed at: every value (and its negative) distinct, and
/// distinct from 0 and ±1, inside every spec's ranges. The target stays at the origin for a spec
/// without a pan.
fn camera_probe(spec: &Spec) -> CameraState {
    let pan = spec.pan.is_some();
    CameraState {
        camera_yaw: 37.0,
        camera_pitch: -23.0,
        camera_distance: 13.5,
        target_x: if pan { 1.25 } else { 0.0 },
        target_z: if pan { -0.75 } else { 0.0 },
    }
}

/// The camera variables of `spec` with their values in `s`.
fn camera_vars(spec: &Spec, s: &CameraState) -> Vec<Var> {
    let var = |name: &str, value| Var { name: name.to_owned(), value };
    let mut vars = vec![
        var("camera_yaw", s.camera_yaw),
        var("camera_pitch", s.camera_pitch),
        var("camera_distance", s.camera_distance),
    ];
    if spec.pan.is_some() {
        vars.push(var("target_x", s.target_x));
        vars.push(var("target_z", s.target_z));
    }
    vars
}

/// One stated drag: `px` pixels along `op`'s drag direction (right for dx, down for dy), in
/// calls of `motion()` of at most [`DRAG_STEP_PX`] pixels.
fn drag_along(op: &Operation, px: f32) -> (Vec<Drag>, Text) {
    let steps = (px.abs() / DRAG_STEP_PX).ceil().max(1.0);
    let each = px / steps;
    let (dx, dy, ja, en) = match op.axis {
        DragAxis::Horizontal => (each, 0.0, "右へ", "right"),
        DragAxis::Vertical => (0.0, each, "下へ", "down"),
    };
    let drag = Drag { button: op.gesture.button, shift: op.gesture.shift, dx, dy };
    let n = format_number(px);
    (vec![drag; steps as usize], Text::new(format!("{ja} {n} ピクセル"), format!("{n} px {en}")))
}

/// A stated state: its ID, the drags from the start that reach it, and those drags in words.
struct CameraStep {
    id: &'static str,
    drags: Vec<Drag>,
    words: Option<Text>,
}

/// The stated mouse states of `spec`: the start; the rotation drag (40 px along yaw's drag,
/// then 20 px along pitch's); the distance drag (20 px); with a pan, 40 px along each of the
/// target's drags. Each is reached from the start.
fn camera_steps(spec: &Spec) -> Vec<CameraStep> {
    // "右ボタンで右へ 40 ピクセル、下へ 20 ピクセル" from (operation, pixels) pairs.
    let step = |id: &'static str, moves: &[(&Operation, f32)]| {
        let mut drags = Vec::new();
        let (mut ja, mut en): (Vec<String>, Vec<String>) = (Vec::new(), Vec::new());
        let mut last: Option<Gesture> = None;
        for (op, px) in moves {
            let (d, words) = drag_along(op, *px);
            drags.extend(d);
            if last == Some(op.gesture) {
                ja.push(words.ja);
                en.push(words.en);
            } else {
                let g = crate::show::gesture_held(op.gesture);
                ja.push(format!("{}{}", g.ja, words.ja));
                en.push(format!("{} {}", words.en, g.en));
            }
            last = Some(op.gesture);
        }
        let words = Text::new(ja.join("、"), en.join(", then "));
        CameraStep { id, drags, words: Some(words) }
    };
    let mut steps = vec![
        CameraStep { id: "a2.view.start", drags: Vec::new(), words: None },
        step("a2.view.rotate", &[(&spec.yaw, 40.0), (&spec.pitch, 20.0)]),
        step("a2.view.zoom", &[(&spec.distance, 20.0)]),
    ];
    if let Some(pan) = &spec.pan {
        steps.push(step("a2.view.pan", &[(&pan.x, 40.0), (&pan.z, 40.0)]));
    }
    steps
}

/// The stated mouse states of the view matrices [`camera`] derives: each ID (`a2.view.start`,
/// `a2.view.rotate`, `a2.view.zoom`, and `a2.view.pan` with a pan) with the calls of `motion()`
/// that reach it from `spec.start` (none for the start).
#[must_use]
pub fn camera_drags(spec: &Spec) -> Vec<(String, Vec<Drag>)> {
    camera_steps(spec).into_iter().map(|s| (s.id.to_owned(), s.drags)).collect()
}

/// `camera_yaw = 30°, camera_pitch = -30°, camera_distance = 15[, target_x = …, target_z = …]`.
fn camera_state_text(spec: &Spec, s: &CameraState) -> String {
    let n = format_number;
    let mut out = format!(
        "camera_yaw = {}°, camera_pitch = {}°, camera_distance = {}",
        n(s.camera_yaw),
        n(s.camera_pitch),
        n(s.camera_distance)
    );
    if spec.pan.is_some() {
        out.push_str(&format!(", target_x = {}, target_z = {}", n(s.target_x), n(s.target_z)));
    }
    out
}

fn state_finite(s: &CameraState) -> bool {
    [s.camera_yaw, s.camera_pitch, s.camera_distance, s.target_x, s.target_z]
        .iter()
        .all(|x| x.is_finite())
}

/// The student's view matrix at `state`: what `camera()` multiplies onto a fresh context.
fn record_camera(imp: &Impl, state: &CameraState) -> Result<MatrixProduct, Outcome> {
    guarded(|| {
        let mut rec = cg_student::gl::Gl::new();
        (imp.camera)(&mut rec, state);
        crate::replay(&rec).model_view().clone()
    })
}

/// The view matrix (world → camera) the student's `camera()` (a2.t2) multiplies, at the stated
/// mouse states: the start, and the states the student's `motion()` (a2.t1) reaches by the
/// drags of [`camera_drags`] (each stated in the title, with the variables it reaches). Each
/// matrix is given numerically and symbolically (each number that is a camera variable named
/// after it), with every variable of the spec explained, its range included.
///
/// A `motion()` not written yet (or panicking, or moving nothing) leaves the start alone.
///
/// # Errors
/// `camera()` not written, panicking, or giving no usable matrix at the start.
pub fn camera(spec: &Spec, imp: &Impl) -> Result<CameraData, Missing> {
    camera_part(spec, imp).0
}

/// [`camera`] with the smaller parts it had to leave out (a `motion()` that fails): the report
/// data of [`crate::A2`].
pub fn camera_part(spec: &Spec, imp: &Impl) -> Part<CameraData> {
    let mut notes = Vec::new();
    let fail = |why: Text| (Err(Missing::new("a2.t2", why)), Vec::new());
    let start_product = match record_camera(imp, &spec.start) {
        Ok(p) => p,
        Err(o) => return (Err(Missing::from_outcome("a2.t2", "camera()", o)), Vec::new()),
    };
    let probe_state = camera_probe(spec);
    let probe = match record_camera(imp, &probe_state) {
        Ok(p) => p,
        Err(o) => return (Err(Missing::from_outcome("a2.t2", "camera()", o)), Vec::new()),
    };
    match (start_product.matrix(), probe.matrix()) {
        (Ok(a), Ok(b)) if a == Mat4::IDENTITY && b == Mat4::IDENTITY => {
            return fail(Text::new(
                "camera() がまだ行列を変えていません（カメラが原点にあるのと同じです）",
                "camera() does not change the matrix yet (as if the camera sat at the origin)",
            ));
        }
        (Ok(_), Ok(_)) => {}
        (Err(e), _) | (_, Err(e)) => {
            return fail(Text::new(
                format!("camera() の積が行列になりません: {}", e.message(Lang::Ja)),
                format!("camera()'s product is not a matrix: {}", e.message(Lang::En)),
            ));
        }
    }

    // The states, through the student's motion().
    let mut states: Vec<(&'static str, Option<Text>, CameraState)> = Vec::new();
    let mut motion_failed = false;
    for step in camera_steps(spec) {
        if step.drags.is_empty() {
            states.push((step.id, step.words, spec.start));
            continue;
        }
        if motion_failed {
            continue;
        }
        let reached = guarded(|| {
            let mut s = spec.start;
            for d in &step.drags {
                (imp.motion)(spec, &mut s, d);
            }
            s
        });
        match reached {
            Ok(s) if state_finite(&s) => states.push((step.id, step.words, s)),
            Ok(s) => notes.push(Missing::new(
                "a2.t1",
                Text::new(
                    format!(
                        "motion() の後の変数が有限の値ではありません: {}",
                        camera_state_text(spec, &s)
                    ),
                    format!(
                        "motion() leaves variables that are not finite: {}",
                        camera_state_text(spec, &s)
                    ),
                ),
            )),
            Err(o) => {
                notes.push(Missing::from_outcome("a2.t1", "motion()", o));
                motion_failed = true;
            }
        }
    }
    if states.len() > 1 && states.iter().all(|(_, _, s)| *s == spec.start) {
        notes.push(Missing::new(
            "a2.t1",
            Text::new(
                "motion() がどの変数も変えていません: ドラッグしても初期状態のままなので、初期状態の行列だけを示します",
                "motion() changes no variable: every drag leaves the start, so only the start's matrix is shown",
            ),
        ));
        states.truncate(1);
    }

    // The student's products at each state; a state whose product is no matrix is left out.
    let mut recorded: Vec<(&'static str, Option<Text>, CameraState, MatrixProduct)> = Vec::new();
    for (id, words, s) in states {
        let product =
            if id == "a2.view.start" { Ok(start_product.clone()) } else { record_camera(imp, &s) };
        match product {
            Ok(p) if p.matrix().is_ok() => recorded.push((id, words, s, p)),
            Ok(_) => notes.push(Missing::new(
                "a2.t2",
                Text::new(
                    format!("camera() の積が {} で行列になりません", camera_state_text(spec, &s)),
                    format!(
                        "camera()'s product is not a matrix at {}",
                        camera_state_text(spec, &s)
                    ),
                ),
            )),
            Err(o) => notes.push(Missing::from_outcome("a2.t2", "camera()", o)),
        }
    }

    let mut products: Vec<MatrixProduct> = vec![probe];
    products.extend(recorded.iter().map(|r| r.3.clone()));
    drop_constant_identities(&mut products);
    let vars = camera_vars(spec, &probe_state);
    let variables = spec.variables();
    let matrices = recorded
        .iter()
        .zip(&products[1..])
        .map(|((id, words, s, _), product)| {
            let (symbolic, _) = symbolize(&products[0], product, &vars);
            let state = camera_state_text(spec, s);
            let title = match words {
                None => Text::new(
                    format!("視点の変換行列（初期状態: {state}）"),
                    format!("view matrix (at the start: {state})"),
                ),
                Some(w) => Text::new(
                    format!("視点の変換行列（初期状態から{}ドラッグした後: {state}）", w.ja),
                    format!("view matrix (after dragging {} from the start: {state})", w.en),
                ),
            };
            NamedMatrix {
                id: (*id).to_owned(),
                title,
                symbolic,
                numeric: numeric(product),
                variables: variables.clone(),
            }
        })
        .collect();
    (Ok(CameraData { matrices }), notes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_harness::{StudentNumber, TableVersion, VariantRng};

    #[test]
    fn camera_drags_state_each_state() {
        let student: StudentNumber = "12345678".parse().unwrap();
        let spec = crate::variant(&mut VariantRng::new(&student, TableVersion::V1, crate::ID));
        let drags = camera_drags(&spec);
        assert_eq!(drags[0], ("a2.view.start".to_owned(), Vec::new()));
        assert_eq!(drags.len(), if spec.pan.is_some() { 4 } else { 3 });
        // 40 px along yaw's drag then 20 px along pitch's, 10 px per motion() call.
        let rotate = &drags[1].1;
        assert_eq!(rotate.len(), 6);
        let total = |f: fn(&Drag) -> f32| rotate.iter().map(f).sum::<f32>();
        assert_eq!((total(|d| d.dx), total(|d| d.dy)), (40.0, 20.0));
    }
}
