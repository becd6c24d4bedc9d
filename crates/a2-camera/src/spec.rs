//! The per-student variant (table version 1, frozen); the assignment text is in `describe.rs`.

use easy_ext::ext;

use cg_core::lang::{Lang, Text, t};
use cg_harness::VariantRng;

use crate::show::{self, Var};
use crate::{CameraState, DragAxis, Gesture, MouseButton, Operation, Pan, Spec};

const fn plain(button: MouseButton) -> Gesture {
    Gesture { button, shift: false }
}

const fn shifted(button: MouseButton) -> Gesture {
    Gesture { button, shift: true }
}

const L: Gesture = plain(MouseButton::Left);
const M: Gesture = plain(MouseButton::Middle);
const R: Gesture = plain(MouseButton::Right);
const SL: Gesture = shifted(MouseButton::Left);
const SM: Gesture = shifted(MouseButton::Middle);
const SR: Gesture = shifted(MouseButton::Right);

/// Table v1 — the gestures of (rotate: yaw on dx and pitch on dy, distance, pan), after
/// programs students meet: the course's own (right rotates, left zooms), swapped, Blender-like
/// (middle rotates, Shift + middle pans), Maya-like, and layouts with Shift. Frozen.
pub(crate) const LAYOUTS: [(Gesture, Gesture, Gesture); 8] =
    [(R, L, M), (L, R, M), (M, R, SM), (L, M, R), (R, SR, L), (L, SL, R), (R, M, SR), (M, SM, L)];

/// Table v1 — degrees per pixel for yaw and pitch (the course: 1.0). Frozen.
pub(crate) const ROTATE_DEG_PER_PX: [f32; 5] = [0.25, 0.5, 1.0, 1.5, 2.0];
/// Table v1 — scene units per pixel for the distance (the course's extension: 0.2). Frozen.
pub(crate) const DISTANCE_PER_PX: [f32; 5] = [0.05, 0.1, 0.2, 0.25, 0.5];
/// Table v1 — scene units per pixel for the target. Frozen.
pub(crate) const PAN_PER_PX: [f32; 4] = [0.01, 0.02, 0.025, 0.05];
/// Table v1 — (pitch_min, pitch_max) in degrees (the course: −90, 0). Frozen.
pub(crate) const PITCH_RANGES: [(f32, f32); 6] =
    [(-90.0, 0.0), (-90.0, 90.0), (-90.0, -10.0), (-80.0, 0.0), (-85.0, 30.0), (-60.0, 60.0)];
/// Table v1 — closest distance. Frozen.
pub(crate) const DISTANCE_MIN: [f32; 4] = [1.5, 2.0, 3.0, 5.0];
/// Table v1 — farthest distance. Frozen.
pub(crate) const DISTANCE_MAX: [f32; 4] = [25.0, 30.0, 40.0, 50.0];
/// Table v1 — the target's limit (the ground is ±5). Frozen.
pub(crate) const PAN_LIMIT: [f32; 3] = [3.0, 4.0, 5.0];
/// Table v1 — camera_yaw at start. Frozen.
pub(crate) const START_YAW: [f32; 6] = [0.0, 30.0, 45.0, 90.0, 180.0, 315.0];
/// Table v1 — camera_pitch at start (inside every pitch range). Frozen.
pub(crate) const START_PITCH: [f32; 4] = [-20.0, -30.0, -40.0, -45.0];
/// Table v1 — camera_distance at start (inside every distance range). Frozen.
pub(crate) const START_DISTANCE: [f32; 4] = [10.0, 12.0, 15.0, 20.0];

/// `sign · value`, from a draw of 0 or 1 (`negative_first`: draw 0 is the negative sign).
fn signed(rng: &mut VariantRng, value: f32, negative_first: bool) -> f32 {
    let negative = (rng.below(2) == 0) == negative_first;
    if negative { -value } else { value }
}

/// The student's variant, drawn from the frozen stream of their number and table version.
///
/// Table version 1 draws, in this order: the layout (8), whether there is a pan (2), the
/// distance drag's direction (2: up/down as in the course, or left/right), yaw speed (5) and
/// sign (2: the course's `−=` first), pitch speed and sign (the course's `−=` first), distance
/// speed and sign (the course's `+=` first), the pitch range (6), the closest (4) and farthest
/// (4) distance, the start yaw (6), pitch (4) and distance (4); then, with a pan, the speed and
/// sign of target_x and of target_z and the limit (3). Every number is an exact entry of a
/// table above: no arithmetic on random bits.
#[must_use]
pub fn variant(rng: &mut VariantRng) -> Spec {
    let (rotate, zoom, pan_gesture) = *rng.pick(&LAYOUTS);
    let has_pan = rng.below(2) == 1;
    let zoom_axis = if rng.below(2) == 0 { DragAxis::Vertical } else { DragAxis::Horizontal };
    let yaw_speed = *rng.pick(&ROTATE_DEG_PER_PX);
    let yaw = Operation {
        gesture: rotate,
        axis: DragAxis::Horizontal,
        per_px: signed(rng, yaw_speed, true),
    };
    let pitch_speed = *rng.pick(&ROTATE_DEG_PER_PX);
    let pitch = Operation {
        gesture: rotate,
        axis: DragAxis::Vertical,
        per_px: signed(rng, pitch_speed, true),
    };
    let distance_speed = *rng.pick(&DISTANCE_PER_PX);
    let distance =
        Operation { gesture: zoom, axis: zoom_axis, per_px: signed(rng, distance_speed, false) };
    let (pitch_min, pitch_max) = *rng.pick(&PITCH_RANGES);
    let distance_min = *rng.pick(&DISTANCE_MIN);
    let distance_max = *rng.pick(&DISTANCE_MAX);
    let start = CameraState {
        camera_yaw: *rng.pick(&START_YAW),
        camera_pitch: *rng.pick(&START_PITCH),
        camera_distance: *rng.pick(&START_DISTANCE),
        target_x: 0.0,
        target_z: 0.0,
    };
    let pan = has_pan.then(|| {
        let x_speed = *rng.pick(&PAN_PER_PX);
        let x = Operation {
            gesture: pan_gesture,
            axis: DragAxis::Horizontal,
            per_px: signed(rng, x_speed, false),
        };
        let z_speed = *rng.pick(&PAN_PER_PX);
        let z = Operation {
            gesture: pan_gesture,
            axis: DragAxis::Vertical,
            per_px: signed(rng, z_speed, false),
        };
        Pan { x, z, limit: *rng.pick(&PAN_LIMIT) }
    });
    Spec { start, yaw, pitch, pitch_min, pitch_max, distance, distance_min, distance_max, pan }
}

/// The spec's variables as the kit lists them.
#[ext(SpecVars)]
pub(crate) impl Spec {
    /// The spec's operations with the variable each one drives, in the report's order.
    fn operations(&self) -> Vec<(Var, Operation)> {
        let mut ops =
            vec![(Var::Yaw, self.yaw), (Var::Pitch, self.pitch), (Var::Distance, self.distance)];
        if let Some(pan) = &self.pan {
            ops.push((Var::TargetX, pan.x));
            ops.push((Var::TargetZ, pan.z));
        }
        ops
    }

    /// The range a variable is kept in, in words: `wrapped into [0, 360)`, `-90 ≤ camera_pitch
    /// ≤ 0 (clamped)`.
    fn range_text(&self, var: Var) -> Text {
        let n = show::num;
        let name = var.name();
        let clamp = |lo: f32, hi: f32| {
            Text::new(
                format!("{} ≤ {name} ≤ {} に制限", n(lo), n(hi)),
                format!("clamped to {} ≤ {name} ≤ {}", n(lo), n(hi)),
            )
        };
        match var {
            Var::Yaw => t(
                "0 ≤ camera_yaw < 360 に折り返す（360 → 0、-1 → 359）",
                "wrapped into 0 ≤ camera_yaw < 360 (360 → 0, -1 → 359)",
            ),
            Var::Pitch => clamp(self.pitch_min, self.pitch_max),
            Var::Distance => clamp(self.distance_min, self.distance_max),
            Var::TargetX | Var::TargetZ => {
                let l = self.pan.map_or(0.0, |p| p.limit);
                clamp(-l, l)
            }
        }
    }
}

/// What the kit says about a spec: its variables and its assignment text.
#[ext(SpecExt)]
pub impl Spec {
    /// Each camera variable with what changes it and how — the explanation the
    /// report gives for every variable of the view transform (各変数の説明: どのような操作により、
    /// どのように変化する変数か): `("camera_yaw", "右ボタンで左右にドラッグ: camera_yaw -= 0.5 * dx
    /// [度] …")`.
    fn variables(&self) -> Vec<(String, Text)> {
        self.operations()
            .into_iter()
            .map(|(var, op)| {
                let (meaning, gesture) = (var.meaning(), show::gesture_held(op.gesture));
                let (axis, direction) =
                    (show::axis_words(op.axis), show::direction_words(var, &op));
                let (formula, range) = (show::formula(var, &op), self.range_text(var));
                let text = Text::new(
                    format!(
                        "{}（{}）: {}{}ドラッグ — {formula}（{}）。{}",
                        var.name(),
                        meaning.ja,
                        gesture.ja,
                        axis.ja,
                        direction.ja,
                        range.ja,
                    ),
                    format!(
                        "{} ({}): drag {} {} — {formula} ({}); {}",
                        var.name(),
                        meaning.en,
                        axis.en,
                        gesture.en,
                        direction.en,
                        range.en,
                    ),
                );
                (var.name().to_owned(), text)
            })
            .collect()
    }

    /// The assignment text for this variant, in `lang`: the operations with this student's
    /// numbers, the tasks a2.t1–a2.t3, and what the report must show.
    fn describe(&self, lang: Lang) -> String {
        crate::describe::describe(self, lang)
    }
}
