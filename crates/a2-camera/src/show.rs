//! How the assignment prints things: variables, gestures, drags, states, matrices, and the
//! student's view transform with the report's names.

use cg_core::glam::{Mat4, Vec4};
use cg_core::lang::{Lang, t};
use cg_core::product::{Factor, MatrixProduct, Param, format_number};
use cg_harness::Text;
use cg_harness::check::Outcome;

use crate::spec::SpecVars;
use crate::{CameraState, Drag, DragAxis, Gesture, Impl, MouseButton, Operation, Spec};

/// A camera variable.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Var {
    Yaw,
    Pitch,
    Distance,
    TargetX,
    TargetZ,
}

impl Var {
    pub(crate) const ALL: [Var; 5] =
        [Var::Yaw, Var::Pitch, Var::Distance, Var::TargetX, Var::TargetZ];

    /// The variable's name in the program and the report.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Var::Yaw => "camera_yaw",
            Var::Pitch => "camera_pitch",
            Var::Distance => "camera_distance",
            Var::TargetX => "target_x",
            Var::TargetZ => "target_z",
        }
    }

    /// What it means, in a few words.
    pub(crate) fn meaning(self) -> Text {
        match self {
            Var::Yaw => {
                t("Y 軸まわりのカメラの向き・方位角 [度]", "turn about the Y axis, degrees")
            }
            Var::Pitch => t("カメラの仰角 [度]", "elevation, degrees"),
            Var::Distance => t("注視点からカメラまでの距離", "from the target to the camera"),
            Var::TargetX => t("注視点の x 座標", "the target's x"),
            Var::TargetZ => t("注視点の z 座標", "the target's z"),
        }
    }

    /// The unit printed after a value: `°` for the angles, nothing for lengths.
    pub(crate) fn unit(self) -> &'static str {
        match self {
            Var::Yaw | Var::Pitch => "°",
            _ => "",
        }
    }

    pub(crate) fn get(self, s: &CameraState) -> f32 {
        match self {
            Var::Yaw => s.camera_yaw,
            Var::Pitch => s.camera_pitch,
            Var::Distance => s.camera_distance,
            Var::TargetX => s.target_x,
            Var::TargetZ => s.target_z,
        }
    }

    pub(crate) fn set(self, s: &mut CameraState, value: f32) {
        match self {
            Var::Yaw => s.camera_yaw = value,
            Var::Pitch => s.camera_pitch = value,
            Var::Distance => s.camera_distance = value,
            Var::TargetX => s.target_x = value,
            Var::TargetZ => s.target_z = value,
        }
    }
}

/// A number as the kit prints it (`15`, `-0.5`, `0.025`).
pub(crate) fn num(x: f32) -> String {
    format_number(x)
}

/// A number with its sign always shown (`+10`, `-4`).
pub(crate) fn signed_num(x: f32) -> String {
    if x > 0.0 { format!("+{}", num(x)) } else { num(x) }
}

/// `value` of `var` with its unit: `30°`, `15`.
pub(crate) fn value(var: Var, x: f32) -> String {
    format!("{}{}", num(x), var.unit())
}

/// "Left", "Shift+Right": the gesture in the short form of the English locations.
pub(crate) fn gesture_short(g: Gesture) -> String {
    let b = match g.button {
        MouseButton::Left => "Left",
        MouseButton::Middle => "Middle",
        MouseButton::Right => "Right",
    };
    if g.shift { format!("Shift+{b}") } else { b.to_owned() }
}

/// "右ボタン", "Shift + 左ボタン" / "right button", "Shift + left button".
pub(crate) fn gesture(g: Gesture) -> Text {
    let (ja, en) = match g.button {
        MouseButton::Left => ("左ボタン", "left button"),
        MouseButton::Middle => ("中ボタン", "middle button"),
        MouseButton::Right => ("右ボタン", "right button"),
    };
    if g.shift { Text::new(format!("Shift + {ja}"), format!("Shift + {en}")) } else { t(ja, en) }
}

/// How a drag is made with `g`, after the drag's direction: "Shift + 左ボタンで" / "with the left
/// button and Shift held" ("drag up and down (dy) with the left button and Shift held").
pub(crate) fn gesture_held(g: Gesture) -> Text {
    let words = gesture(Gesture { shift: false, ..g });
    if g.shift {
        Text::new(
            format!("Shift + {}で", words.ja),
            format!("with the {} and Shift held", words.en),
        )
    } else {
        Text::new(format!("{}で", words.ja), format!("with the {}", words.en))
    }
}

/// "左右に (dx)" / "left and right (dx)".
pub(crate) fn axis_words(axis: DragAxis) -> Text {
    match axis {
        DragAxis::Horizontal => t("左右に（dx）", "left and right (dx)"),
        DragAxis::Vertical => t("上下に（dy）", "up and down (dy)"),
    }
}

/// `dx` or `dy`.
pub(crate) fn axis_symbol(axis: DragAxis) -> &'static str {
    match axis {
        DragAxis::Horizontal => "dx",
        DragAxis::Vertical => "dy",
    }
}

/// The C-style update: `camera_yaw -= 0.5 * dx`.
pub(crate) fn formula(var: Var, op: &Operation) -> String {
    let (sign, speed) = if op.per_px < 0.0 { ("-=", -op.per_px) } else { ("+=", op.per_px) };
    format!("{} {sign} {} * {}", var.name(), num(speed), axis_symbol(op.axis))
}

/// "右へドラッグすると増える" / "dragging right increases it".
pub(crate) fn direction_words(var: Var, op: &Operation) -> Text {
    let up = op.per_px > 0.0;
    let step = num(op.per_px.abs());
    let unit = var.unit();
    let (ja_way, en_way) = match op.axis {
        DragAxis::Horizontal => ("右", "right"),
        DragAxis::Vertical => ("下", "down"),
    };
    let (ja_change, en_change) =
        if up { ("増える", "increases") } else { ("減る", "decreases") };
    Text::new(
        format!("{ja_way}へドラッグすると{ja_change}、1 ピクセルで {step}{unit}"),
        format!("dragging {en_way} {en_change} it, {step}{unit} per pixel"),
    )
}

/// Every gesture the checks try: the three buttons, each with and without Shift.
pub(crate) const ALL_GESTURES: [Gesture; 6] = [
    Gesture { button: MouseButton::Left, shift: false },
    Gesture { button: MouseButton::Middle, shift: false },
    Gesture { button: MouseButton::Right, shift: false },
    Gesture { button: MouseButton::Left, shift: true },
    Gesture { button: MouseButton::Middle, shift: true },
    Gesture { button: MouseButton::Right, shift: true },
];

/// The gestures the spec does not use, listed in words.
pub(crate) fn unused_gestures(spec: &Spec, lang: Lang) -> String {
    let used: Vec<Gesture> = spec.operations().iter().map(|(_, op)| op.gesture).collect();
    let unused: Vec<String> = ALL_GESTURES
        .iter()
        .filter(|g| !used.contains(g))
        .map(|&g| gesture(g).get(lang).to_owned())
        .collect();
    unused.join(t("、", ", ").get(lang))
}

/// `camera_yaw = 30°, camera_pitch = -30°, camera_distance = 15[, target = (1, -0.5)]`.
pub(crate) fn state(s: &CameraState, with_target: bool) -> String {
    let mut out = format!(
        "camera_yaw = {}°, camera_pitch = {}°, camera_distance = {}",
        num(s.camera_yaw),
        num(s.camera_pitch),
        num(s.camera_distance)
    );
    if with_target {
        out.push_str(&format!(", target_x = {}, target_z = {}", num(s.target_x), num(s.target_z)));
    }
    out
}

/// `右ボタン dx = +10 dy = 0` / `Right dx = +10 dy = 0`.
pub(crate) fn drag(d: &Drag) -> Text {
    let g = Gesture { button: d.button, shift: d.shift };
    let (dx, dy) = (signed_num(d.dx), signed_num(d.dy));
    Text::new(
        format!("{} dx = {dx} dy = {dy}", gesture(g).ja),
        format!("{} dx = {dx} dy = {dy}", gesture_short(g)),
    )
}

/// The rows of a matrix on one line: `[1 0 0 0; 0 0.866 0.5 0; …]`.
pub(crate) fn matrix(m: &Mat4) -> String {
    let rows: Vec<String> = (0..4)
        .map(|r| {
            let row = m.row(r);
            [row.x, row.y, row.z, row.w].iter().map(|&x| num(x)).collect::<Vec<_>>().join(" ")
        })
        .collect();
    format!("[{}]", rows.join("; "))
}

/// `(x, y, z, w)`.
pub(crate) fn vec4(v: Vec4) -> String {
    format!("({}, {}, {}, {})", num(v.x), num(v.y), num(v.z), num(v.w))
}

/// The state [`crate::camera_product`] runs the camera at: every value (and its negative)
/// different from every other and from 0 and ±1, so each number in the product names one
/// variable.
pub(crate) const PROBE: CameraState = CameraState {
    camera_yaw: 37.0,
    camera_pitch: -23.0,
    camera_distance: 13.5,
    target_x: 1.25,
    target_z: -0.75,
};

/// `product` with every parameter that equals a variable of `s` (or its negative) named after
/// it: `Rx(23°)` becomes `Rx(-camera_pitch)` when `s.camera_pitch` is −23. Parameters that
/// already have a symbol keep it. Meant for [`PROBE`], whose values are all distinct.
pub(crate) fn symbolize(product: &MatrixProduct, s: &CameraState) -> MatrixProduct {
    let name = |p: &Param| -> Param {
        if p.symbol.is_some() {
            return p.clone();
        }
        for var in Var::ALL {
            let v = var.get(s);
            let close = |a: f32, b: f32| (a - b).abs() <= 1e-4 * b.abs().max(1.0);
            if close(p.value, v) {
                return Param::sym(var.name(), p.value);
            }
            if close(p.value, -v) {
                return Param::sym(format!("-{}", var.name()), p.value);
            }
        }
        p.clone()
    };
    let factors = product
        .factors
        .iter()
        .map(|f| match f {
            Factor::Translate(p) => Factor::Translate([name(&p[0]), name(&p[1]), name(&p[2])]),
            Factor::Scale(p) => Factor::Scale([name(&p[0]), name(&p[1]), name(&p[2])]),
            Factor::Rotate { axis, angle_deg } => {
                Factor::Rotate { axis: *axis, angle_deg: name(angle_deg) }
            }
            other => other.clone(),
        })
        .collect();
    MatrixProduct { factors }
}

/// The view transform as the student's [`Impl::camera`] builds it, with the report's names:
/// `T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw) · T(-target_x, 0, -target_z)`
/// for the reference answer. Print it with [`MatrixProduct::symbolic`] or
/// [`MatrixProduct::latex`].
///
/// The camera is run once at a probe state whose values are all different (yaw 37°, pitch −23°,
/// distance 13.5, target (1.25, −0.75)); every number of a factor that equals one of them, or
/// its negative, is named after its variable. Numbers that match none (a constant, or an angle
/// in radians) stay numbers, which itself shows a mistake.
///
/// # Errors
/// What keeps the product from being read (a stub not written yet, a panic), in words.
pub fn camera_product(imp: &Impl) -> Result<MatrixProduct, Text> {
    run_camera(imp, &PROBE).map(|product| symbolize(&product, &PROBE))
}

/// The view transform the student's [`Impl::camera`] builds at `s`, with the report's names
/// where [`camera_product`] finds them: each number that the run at [`PROBE`] names keeps its
/// name, with its value at `s`. So a check that names the state `s` shows the numbers of `s`
/// (`Rx(0.5236°)` for camera_pitch = −30° given in radians), never the probe's. When the two
/// runs build different factors (a camera() that branches on the state), the numbers alone.
///
/// # Errors
/// As [`camera_product`], for the run at `s`.
pub(crate) fn camera_product_at(imp: &Impl, s: &CameraState) -> Result<MatrixProduct, Text> {
    let at_s = run_camera(imp, s)?;
    let named = camera_product(imp).ok().and_then(|named| named_like(&at_s, &named));
    Ok(named.unwrap_or(at_s))
}

/// `product` with the symbols of `named`, factor by factor, where both have the same factors
/// (kinds and axes); `None` where they do not.
fn named_like(product: &MatrixProduct, named: &MatrixProduct) -> Option<MatrixProduct> {
    if product.factors.len() != named.factors.len() {
        return None;
    }
    let name = |p: &Param, n: &Param| match (&p.symbol, &n.symbol) {
        (None, Some(symbol)) => Param::sym(symbol.clone(), p.value),
        _ => p.clone(),
    };
    let three = |p: &[Param; 3], n: &[Param; 3]| {
        [name(&p[0], &n[0]), name(&p[1], &n[1]), name(&p[2], &n[2])]
    };
    let factors = product.factors.iter().zip(&named.factors).map(|(f, n)| match (f, n) {
        (Factor::Translate(p), Factor::Translate(n)) => Some(Factor::Translate(three(p, n))),
        (Factor::Scale(p), Factor::Scale(n)) => Some(Factor::Scale(three(p, n))),
        (
            Factor::Rotate { axis, angle_deg },
            Factor::Rotate { axis: named_axis, angle_deg: named_angle },
        ) if axis == named_axis => {
            Some(Factor::Rotate { axis: *axis, angle_deg: name(angle_deg, named_angle) })
        }
        (Factor::Matrix { .. }, Factor::Matrix { .. })
        | (Factor::Perspective { .. }, Factor::Perspective { .. }) => Some(f.clone()),
        _ => None,
    });
    Some(MatrixProduct { factors: factors.collect::<Option<Vec<_>>>()? })
}

/// The product the student's camera() leaves on a fresh context at `s`, or why there is none.
fn run_camera(imp: &Impl, s: &CameraState) -> Result<MatrixProduct, Text> {
    let mut rec = cg_student::gl::Gl::new();
    match cg_harness::check::guarded(|| (imp.camera)(&mut rec, s)) {
        Ok(()) => Ok(crate::replay(&rec).model_view().clone()),
        Err(Outcome::NotDone { message }) => {
            Err(Text::new(format!("まだです: {message}"), format!("not done yet: {message}")))
        }
        Err(other) => {
            let message = match other {
                Outcome::Panicked { message, .. } => message,
                _ => String::new(),
            };
            Err(Text::new(
                format!("camera()（a2.t2）が異常終了しました（panic）: {message}"),
                format!("camera() (a2.t2) panicked: {message}"),
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::product::Axis;

    #[test]
    fn the_probe_names_each_number_once() {
        let p = MatrixProduct::identity()
            .then(Factor::translate(cg_core::glam::Vec3::new(0.0, 0.0, -13.5)))
            .then(Factor::rotate(Axis::X, Param::num(23.0)))
            .then(Factor::rotate(Axis::Y, Param::num(-37.0)))
            .then(Factor::translate(cg_core::glam::Vec3::new(-1.25, 0.0, 0.75)))
            .then(Factor::rotate(Axis::X, Param::num(0.4014)));
        assert_eq!(
            symbolize(&p, &PROBE).symbolic(),
            "T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw) · T(-target_x, 0, -target_z) · Rx(0.4014°)"
        );
    }

    #[test]
    fn formulas_read_like_c() {
        let op = Operation {
            gesture: Gesture { button: MouseButton::Right, shift: false },
            axis: DragAxis::Vertical,
            per_px: -1.0,
        };
        assert_eq!(formula(Var::Pitch, &op), "camera_pitch -= 1 * dy");
        let words = direction_words(Var::Pitch, &op);
        assert_eq!(words.en, "dragging down decreases it, 1° per pixel");
        assert_eq!(words.ja, "下へドラッグすると減る、1 ピクセルで 1°");
        let pan = Operation { axis: DragAxis::Horizontal, per_px: 0.25, ..op };
        let words = direction_words(Var::TargetX, &pan);
        assert_eq!(words.en, "dragging right increases it, 0.25 per pixel");
        assert_eq!(words.ja, "右へドラッグすると増える、1 ピクセルで 0.25");
        let d = Drag { button: MouseButton::Left, shift: true, dx: 10.0, dy: -4.0 };
        assert_eq!(drag(&d).en, "Shift+Left dx = +10 dy = -4");
        assert_eq!(drag(&d).ja, "Shift + 左ボタン dx = +10 dy = -4");
    }
}
