//! The spec's answers, computed independently of the student's code: the motion mapping, the
//! view matrix (from `cg_core::camera::OrbitCamera`) and the usual wrong view matrices, by which
//! a failing check says *what* is off.

use cg_core::camera::OrbitCamera;
use cg_core::glam::{Mat4, Vec3};
use cg_core::math::wrap_degrees;
use cg_core::product::{Axis, Factor, MatrixProduct, Param};
use cg_core::transform::{rotate_x_deg, rotate_y_deg, translate};
use cg_harness::Text;
use cg_harness::text::t;

use crate::show::Var;
use crate::{CameraState, Drag, DragAxis, Operation, Spec};

/// The change `op` makes for `drag`: `per_px · dx` or `per_px · dy` when the drag's button and
/// Shift are the operation's, `None` otherwise.
pub(crate) fn change(op: &Operation, drag: &Drag) -> Option<f32> {
    if drag.button != op.gesture.button || drag.shift != op.gesture.shift {
        return None;
    }
    let d = match op.axis {
        DragAxis::Horizontal => drag.dx,
        DragAxis::Vertical => drag.dy,
    };
    Some(op.per_px * d)
}

/// `x` kept in `[lo, hi]`.
fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    x.max(lo).min(hi)
}

/// What `motion()` must do for one drag: each variable whose operation the drag is changes by
/// its amount, then yaw wraps into `[0, 360)` and the others are clamped to their ranges.
pub(crate) fn motion(spec: &Spec, s: &mut CameraState, drag: &Drag) {
    if let Some(c) = change(&spec.yaw, drag) {
        s.camera_yaw = wrap_degrees(s.camera_yaw + c);
    }
    if let Some(c) = change(&spec.pitch, drag) {
        s.camera_pitch = clamp(s.camera_pitch + c, spec.pitch_min, spec.pitch_max);
    }
    if let Some(c) = change(&spec.distance, drag) {
        s.camera_distance = clamp(s.camera_distance + c, spec.distance_min, spec.distance_max);
    }
    if let Some(pan) = &spec.pan {
        if let Some(c) = change(&pan.x, drag) {
            s.target_x = clamp(s.target_x + c, -pan.limit, pan.limit);
        }
        if let Some(c) = change(&pan.z, drag) {
            s.target_z = clamp(s.target_z + c, -pan.limit, pan.limit);
        }
    }
}

/// The view matrix `T(0, 0, −d) · Rx(−pitch) · Ry(−yaw) · T(−target_x, 0, −target_z)`, by the
/// core's orbit camera.
pub(crate) fn view_matrix(s: &CameraState) -> Mat4 {
    OrbitCamera {
        yaw_deg: s.camera_yaw,
        pitch_deg: s.camera_pitch,
        distance: s.camera_distance,
        target: Vec3::new(s.target_x, 0.0, s.target_z),
        ..OrbitCamera::course_sample()
    }
    .view_matrix()
}

/// The view with the report's names (the target factor only `with_target`).
pub(crate) fn view_product(with_target: bool, s: &CameraState) -> MatrixProduct {
    let product = MatrixProduct::identity()
        .then(Factor::Translate([
            Param::num(0.0),
            Param::num(0.0),
            Param::sym("-camera_distance", -s.camera_distance),
        ]))
        .then(Factor::rotate(Axis::X, Param::sym("-camera_pitch", -s.camera_pitch)))
        .then(Factor::rotate(Axis::Y, Param::sym("-camera_yaw", -s.camera_yaw)));
    if !with_target {
        return product;
    }
    product.then(Factor::Translate([
        Param::sym("-target_x", -s.target_x),
        Param::num(0.0),
        Param::sym("-target_z", -s.target_z),
    ]))
}

/// Whether two matrices agree entry by entry within `1e-4 · (1 + |expected|)` (rotation entries
/// are at most 1, translations at most about 60: f32 rounding of the products stays below
/// 1e-5 there, while the smallest real mistake — an angle off by a quarter degree — moves an
/// entry by more than 4e-3).
pub(crate) fn matrices_close(actual: &Mat4, expected: &Mat4) -> bool {
    let (a, e) = (actual.to_cols_array(), expected.to_cols_array());
    a.iter().zip(e.iter()).all(|(a, e)| (a - e).abs() <= 1e-4 * (1.0 + e.abs()))
}

/// The usual wrong view matrices, each with what it means. A hypothesis explains a student's
/// camera when it gives the student's matrix at every sampled state.
pub(crate) struct Hypothesis {
    pub(crate) matrix: fn(&CameraState) -> Mat4,
    pub(crate) cause: fn() -> Text,
}

fn parts(s: &CameraState) -> (Mat4, Mat4, Mat4, Mat4) {
    (
        translate(Vec3::new(0.0, 0.0, -s.camera_distance)),
        rotate_x_deg(-s.camera_pitch),
        rotate_y_deg(-s.camera_yaw),
        translate(Vec3::new(-s.target_x, 0.0, -s.target_z)),
    )
}

fn with(s: &CameraState, var: Var, f: impl Fn(f32) -> f32) -> Mat4 {
    let mut s = *s;
    let value = f(var.get(&s));
    var.set(&mut s, value);
    view_matrix(&s)
}

/// Whether `m`'s bottom row is (0, 0, 0, 1) within `1e-4`, as every product of rotations and
/// translations has: only then is it a view transform with an eye to compute.
pub(crate) fn bottom_row_is_0001(m: &Mat4) -> bool {
    (m.row(3) - cg_core::glam::Vec4::W).abs().max_element() <= 1e-4
}

fn transposed() -> Text {
    t(
        "行列が転置されています: 平行移動が 4 列目ではなく下の行に入っています。glam の Mat4 は列優先（Mat4::from_cols_array は列ごとに読み、glMultMatrixf と同じ）なので、行ごとに書いた行列なら .transpose() してから渡すか、gl.translate / gl.rotate で作ってください",
        "the matrix is transposed: the translation is in the bottom row instead of the 4th column. glam's Mat4 is column-major (Mat4::from_cols_array reads column by column, as glMultMatrixf does): transpose a matrix written row by row before passing it, or build the view with gl.translate / gl.rotate",
    )
}

/// The hypotheses, most specific first.
pub(crate) fn hypotheses() -> Vec<Hypothesis> {
    vec![
        Hypothesis { matrix: |s| view_matrix(s).transpose(), cause: transposed },
        Hypothesis {
            matrix: |s| {
                let (d, rx, ry, tt) = parts(s);
                d * ry * rx * tt
            },
            cause: || {
                t(
                    "回転の順序が逆です（Ry(-camera_yaw) を Rx(-camera_pitch) より先に掛けている）。行列の積は順序で結果が変わり、glRotatef は後に呼んだものほど先に頂点に作用します",
                    "the rotations are in the wrong order (Ry(-camera_yaw) before Rx(-camera_pitch)): the order of a product matters, and the glRotatef called last acts on the vertices first",
                )
            },
        },
        Hypothesis {
            matrix: |s| {
                let (d, rx, ry, tt) = parts(s);
                rx * ry * tt * d
            },
            cause: translate_last,
        },
        Hypothesis {
            matrix: |s| {
                let (d, rx, ry, tt) = parts(s);
                rx * ry * d * tt
            },
            cause: translate_last,
        },
        Hypothesis {
            matrix: |s| {
                let (d, rx, ry, tt) = parts(s);
                d * tt * rx * ry
            },
            cause: || {
                t(
                    "注視点の平行移動 T(-target_x, 0, -target_z) が回転より前（左）にあります。注視点を原点に移してから回転するので、回転の後（右端）に掛けます",
                    "the target's translation T(-target_x, 0, -target_z) comes before (left of) the rotations: move the target to the origin first, i.e. multiply it last (rightmost)",
                )
            },
        },
        Hypothesis {
            matrix: |s| {
                let (d, _, _, tt) = parts(s);
                d * rotate_x_deg(-s.camera_yaw) * rotate_y_deg(-s.camera_pitch) * tt
            },
            cause: || {
                t(
                    "回転軸が入れ替わっています: camera_pitch は X 軸 (1, 0, 0)、camera_yaw は Y 軸 (0, 1, 0) まわりの回転です",
                    "the rotation axes are swapped: camera_pitch turns about X (1, 0, 0), camera_yaw about Y (0, 1, 0)",
                )
            },
        },
        Hypothesis {
            matrix: |s| {
                let mut r = *s;
                r.camera_pitch = s.camera_pitch.to_radians();
                r.camera_yaw = s.camera_yaw.to_radians();
                view_matrix(&r)
            },
            cause: || {
                t(
                    "角度をラジアンで渡しています。glRotatef（gl.rotate）の角度は度です（変換は不要）",
                    "the angles are given in radians: glRotatef (gl.rotate) takes degrees (no conversion needed)",
                )
            },
        },
        Hypothesis {
            matrix: |s| with(s, Var::Pitch, f32::to_radians),
            cause: || {
                t(
                    "camera_pitch をラジアンで渡しています。glRotatef（gl.rotate）の角度は度です",
                    "camera_pitch is given in radians: glRotatef (gl.rotate) takes degrees",
                )
            },
        },
        Hypothesis {
            matrix: |s| with(s, Var::Yaw, f32::to_radians),
            cause: || {
                t(
                    "camera_yaw をラジアンで渡しています。glRotatef（gl.rotate）の角度は度です",
                    "camera_yaw is given in radians: glRotatef (gl.rotate) takes degrees",
                )
            },
        },
        Hypothesis {
            matrix: |s| {
                let mut r = *s;
                r.camera_pitch = -s.camera_pitch;
                r.camera_yaw = -s.camera_yaw;
                view_matrix(&r)
            },
            cause: || {
                t(
                    "両方の回転の符号が逆です: カメラを動かす代わりに世界を逆向きに動かすので、Rx(-camera_pitch)・Ry(-camera_yaw) とマイナスを付けます",
                    "both rotations have the wrong sign: the view moves the world the opposite way to the camera, hence Rx(-camera_pitch) and Ry(-camera_yaw)",
                )
            },
        },
        Hypothesis {
            matrix: |s| with(s, Var::Pitch, |v| -v),
            cause: || {
                t(
                    "camera_pitch の回転の符号が逆です（Rx(-camera_pitch) のはず）",
                    "the sign of the camera_pitch rotation is flipped (it is Rx(-camera_pitch))",
                )
            },
        },
        Hypothesis {
            matrix: |s| with(s, Var::Yaw, |v| -v),
            cause: || {
                t(
                    "camera_yaw の回転の符号が逆です（Ry(-camera_yaw) のはず）",
                    "the sign of the camera_yaw rotation is flipped (it is Ry(-camera_yaw))",
                )
            },
        },
        Hypothesis {
            matrix: |s| with(s, Var::Distance, |v| -v),
            cause: || {
                t(
                    "camera_distance の平行移動の符号が逆です: カメラは -Z 方向を見るので、物体を T(0, 0, -camera_distance) で奥へ移します",
                    "the sign of the camera_distance translation is flipped: the camera looks down -Z, so the world moves away by T(0, 0, -camera_distance)",
                )
            },
        },
        Hypothesis {
            matrix: |s| with(s, Var::Distance, |_| 15.0),
            cause: || {
                t(
                    "camera_distance を使わず、サンプルの 15 のままです",
                    "camera_distance is not used: the sample's constant 15 is still there",
                )
            },
        },
        Hypothesis {
            matrix: |s| with(s, Var::Yaw, |_| 0.0),
            cause: || {
                t(
                    "camera_yaw の回転 Ry(-camera_yaw) がありません",
                    "the camera_yaw rotation Ry(-camera_yaw) is missing",
                )
            },
        },
        Hypothesis {
            matrix: |s| with(s, Var::Pitch, |_| 0.0),
            cause: || {
                t(
                    "camera_pitch の回転 Rx(-camera_pitch) がありません",
                    "the camera_pitch rotation Rx(-camera_pitch) is missing",
                )
            },
        },
        Hypothesis {
            matrix: |s| {
                let mut r = *s;
                r.target_x = -s.target_x;
                r.target_z = -s.target_z;
                view_matrix(&r)
            },
            cause: || {
                t(
                    "注視点の平行移動の符号が逆です: 注視点を原点へ移すので T(-target_x, 0, -target_z) です",
                    "the target's translation has the wrong sign: it moves the target to the origin, T(-target_x, 0, -target_z)",
                )
            },
        },
        Hypothesis {
            matrix: |s| {
                let mut r = *s;
                r.target_x = 0.0;
                r.target_z = 0.0;
                view_matrix(&r)
            },
            cause: || {
                t(
                    "注視点の平行移動 T(-target_x, 0, -target_z) がありません",
                    "the target's translation T(-target_x, 0, -target_z) is missing",
                )
            },
        },
    ]
}

fn translate_last() -> Text {
    t(
        "平行移動 T(0, 0, -camera_distance) が回転の後（右）にあります。カメラからの距離は回転した後の視線方向（-Z）に取るので、最初（左端）に掛けます",
        "the translation T(0, 0, -camera_distance) comes after (right of) the rotations: the distance is along the viewing direction (-Z) after rotating, so it is the first (leftmost) factor",
    )
}

/// The cause for a student's matrices `actual[i]` at `states[i]` (only the finite ones are
/// looked at): the first hypothesis that gives all of them, else which part of the matrix is
/// off — the rotation (camera_pitch, camera_yaw) or the translation (camera_distance, target).
pub(crate) fn diagnose_view(states: &[CameraState], actual: &[Mat4]) -> Text {
    let pairs: Vec<(&CameraState, &Mat4)> =
        states.iter().zip(actual).filter(|(_, m)| m.is_finite()).collect();
    if pairs.is_empty() {
        return t(
            "行列が有限の値になりません（NaN か無限大）",
            "the matrix is not finite (NaN or infinity)",
        );
    }
    if pairs.iter().all(|(_, m)| **m == Mat4::IDENTITY) {
        return t(
            "camera() が行列を変えていません（まだ何もしていない）: カメラが原点にあるのと同じです",
            "camera() does not change the matrix (it does nothing yet): as if the camera sat at the origin",
        );
    }
    for h in hypotheses() {
        if pairs.iter().all(|(s, m)| matrices_close(m, &(h.matrix)(s))) {
            return (h.cause)();
        }
    }
    // Which part is off, at the first state where the student's matrix is wrong.
    let Some((s, m)) = pairs.into_iter().find(|(s, m)| !matrices_close(m, &view_matrix(s))) else {
        return Text::default();
    };
    if !bottom_row_is_0001(m) {
        // The translation in the bottom row and none in the 4th column: written row by row.
        let (row, column) = (m.row(3).truncate(), m.col(3).truncate());
        if row.abs().max_element() > 1e-4 && column.abs().max_element() <= 1e-4 {
            return transposed();
        }
        return t(
            "下の行が (0, 0, 0, 1) ではありません: 回転と平行移動の積なら必ず (0, 0, 0, 1) です（行列が転置されているか、射影などほかの変換が入っていませんか）",
            "the bottom row is not (0, 0, 0, 1), as it is for every product of rotations and translations: is the matrix transposed, or does it hold another transform (a projection)?",
        );
    }
    let e = view_matrix(s);
    let rotation_ok = (0..3).all(|c| {
        let (a, b) = (m.col(c).truncate(), e.col(c).truncate());
        (a - b).abs().max_element() <= 2e-4
    });
    if rotation_ok {
        t(
            "回転の部分（左上 3×3）は合っていて、平行移動の部分（4 列目）が違います: camera_distance か注視点の平行移動を確かめてください",
            "the rotation part (upper-left 3×3) is right and the translation part (4th column) is not: look at camera_distance and the target's translation",
        )
    } else {
        t(
            "回転の部分（左上 3×3）が違います: camera_pitch・camera_yaw の回転（軸・符号・単位・順序）を確かめてください",
            "the rotation part (upper-left 3×3) is off: look at the camera_pitch and camera_yaw rotations (axis, sign, unit, order)",
        )
    }
}

/// Pixels of `op`'s drag that change its variable by `amount` for a correct answer, as drags
/// of at most 20 pixels.
fn drags_for(op: &Operation, amount: f32) -> Vec<Drag> {
    let px = amount / op.per_px;
    let steps = (px.abs() / 20.0).ceil().max(1.0);
    let each = px / steps;
    let (dx, dy) = match op.axis {
        DragAxis::Horizontal => (each, 0.0),
        DragAxis::Vertical => (0.0, each),
    };
    let drag = Drag { button: op.gesture.button, shift: op.gesture.shift, dx, dy };
    vec![drag; steps as usize]
}

/// The scripted drags of [`crate::view()`]: yaw +40° (+30° per second of `time_s`, reduced by
/// 360°), pitch −15°, distance +5, and with a pan the target by (+1, −1) — for a correct
/// `motion()`.
pub(crate) fn demo_drags(spec: &Spec, time_s: f64) -> Vec<Drag> {
    let time_s = if time_s.is_finite() { time_s } else { 0.0 };
    let yaw = (40.0 + 30.0 * time_s).rem_euclid(360.0) as f32;
    let mut drags = drags_for(&spec.yaw, yaw);
    drags.extend(drags_for(&spec.pitch, -15.0));
    drags.extend(drags_for(&spec.distance, 5.0));
    if let Some(pan) = &spec.pan {
        drags.extend(drags_for(&pan.x, 1.0));
        drags.extend(drags_for(&pan.z, -1.0));
    }
    drags
}

/// The view transform the spec asks for, with the report's names:
/// `T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw)`, then
/// `T(-target_x, 0, -target_z)` when the spec has a pan. Its matrix is the one of
/// `cg_core::camera::OrbitCamera::view_matrix` for the state.
#[must_use]
pub fn expected_product(spec: &Spec, state: &CameraState) -> MatrixProduct {
    view_product(spec.pan.is_some(), state)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Gesture, MouseButton};
    use cg_core::camera::MouseState;

    /// The course's own mapping as a spec: right-drag turns (yaw −= dx, pitch −= dy, 1°/px),
    /// left-drag dy zooms (+0.2/px), pitch in [−90, 0], distance at least 2.
    fn course_spec() -> Spec {
        let right = Gesture { button: MouseButton::Right, shift: false };
        let left = Gesture { button: MouseButton::Left, shift: false };
        Spec {
            start: CameraState {
                camera_yaw: 0.0,
                camera_pitch: -30.0,
                camera_distance: 15.0,
                target_x: 0.0,
                target_z: 0.0,
            },
            yaw: Operation { gesture: right, axis: DragAxis::Horizontal, per_px: -1.0 },
            pitch: Operation { gesture: right, axis: DragAxis::Vertical, per_px: -1.0 },
            pitch_min: -90.0,
            pitch_max: 0.0,
            distance: Operation { gesture: left, axis: DragAxis::Vertical, per_px: 0.2 },
            distance_min: 2.0,
            distance_max: f32::MAX,
            pan: None,
        }
    }

    #[test]
    fn the_motion_oracle_is_the_cores_course_camera_for_the_course_mapping() {
        let spec = course_spec();
        let mut camera = OrbitCamera::course_sample();
        let mut mouse = MouseState::new();
        let mut s = spec.start;
        let mut rng = cg_harness::VariantRng::from_seed(7);
        let (mut x, mut y) = (320.0f32, 320.0f32);
        for _ in 0..500 {
            let button = *rng.pick(&[MouseButton::Left, MouseButton::Right]);
            let core_button = match button {
                MouseButton::Left => cg_core::camera::MouseButton::Left,
                _ => cg_core::camera::MouseButton::Right,
            };
            mouse.mouse(core_button, true, x, y);
            let (dx, dy) = (rng.range(-60, 60) as f32, rng.range(-60, 60) as f32);
            (x, y) = (x + dx, y + dy);
            mouse.motion(x, y, &mut camera);
            mouse.mouse(core_button, false, x, y);
            motion(&spec, &mut s, &Drag { button, shift: false, dx, dy });
            assert!((s.camera_yaw - camera.yaw_deg).abs() < 1e-3, "{s:?} {camera:?}");
            assert!((s.camera_pitch - camera.pitch_deg).abs() < 1e-3, "{s:?} {camera:?}");
            assert!((s.camera_distance - camera.distance).abs() < 1e-3, "{s:?} {camera:?}");
        }
    }

    #[test]
    fn every_usual_mistake_gives_another_matrix() {
        let s = CameraState {
            camera_yaw: 37.0,
            camera_pitch: -23.0,
            camera_distance: 13.5,
            target_x: 1.25,
            target_z: -0.75,
        };
        let right = view_matrix(&s);
        for (i, h) in hypotheses().iter().enumerate() {
            assert!(!matrices_close(&(h.matrix)(&s), &right), "hypothesis {i}");
            assert!(!(h.cause)().ja.is_empty() && !(h.cause)().en.is_empty());
        }
        // And the named product is the same matrix.
        let named = view_product(true, &s).matrix().unwrap();
        assert!(matrices_close(&named, &right));
    }

    #[test]
    fn the_demo_drags_do_what_they_say_for_a_correct_motion() {
        let mut spec = course_spec();
        spec.yaw.per_px = 1.5;
        for time_s in [0.0, 2.0, 1e6, f64::NAN] {
            let mut s = spec.start;
            for d in demo_drags(&spec, time_s) {
                motion(&spec, &mut s, &d);
            }
            let t = if time_s.is_finite() { time_s } else { 0.0 };
            let yaw = (40.0 + 30.0 * t).rem_euclid(360.0) as f32;
            let d = (s.camera_yaw - wrap_degrees(yaw)).abs();
            assert!(d.min(360.0 - d) < 1e-2, "{time_s}: {s:?}");
            assert!((s.camera_pitch + 45.0).abs() < 1e-3, "{s:?}");
            assert!((s.camera_distance - 20.0).abs() < 1e-3, "{s:?}");
        }
    }
}
