//! Transform builders (translate, rotate, scale, perspective, look-at) and the application of a
//! matrix to points, vectors and normals, kept apart by name.
//!
//! Every builder returns glam's column-major [`Mat4`] for column vectors (`m * v`), so a program
//! that calls `glTranslatef(…); glRotatef(…);` builds `translate(…) * rotate_deg(…)`: the last call
//! acts on the vertices first (モデル座標系→ワールド座標系→カメラ座標系).
//!
//! | OpenGL / GLU | here |
//! |---|---|
//! | `glTranslatef(x, y, z)` | [`translate`] |
//! | `glRotatef(θ, x, y, z)` (degrees) | [`rotate_deg`], [`rotate_x_deg`], [`rotate_y_deg`], [`rotate_z_deg`] |
//! | `glScalef(x, y, z)` | [`scale`] |
//! | `gluPerspective(fovy, aspect, near, far)` | [`perspective_gl`] (`[-1, 1]` depth), [`perspective`] (wgpu's `[0, 1]`) |
//! | `gluLookAt(eye, target, up)` | [`look_at`] |
//!
//! Rotations are counter-clockwise looking from `+axis` towards the origin, as glRotatef's. The
//! degree versions reduce the angle exactly, so multiples of 90° give exact 0 and ±1 entries
//! (`Rx(90°)` prints as clean 0/1, where `90f32.to_radians().sin_cos()` leaves 6e-8 for 0).
//!
//! Points, directions and normals transform differently: [`transform_point`] (w = 1),
//! [`transform_vector`] (w = 0), [`project_point`] (homogeneous divide). Normals need the cofactor
//! matrix: see also `crate::normals::transform_normal`.

use glam::{DVec3, Mat4, Vec3, Vec4};

use crate::lang::{Lang, Text};
use crate::math::{angle_between, try_normalize, try_normalize_f64};

/// [`look_at`] refuses an `up` vector closer than this to the view direction (or its opposite),
/// in degrees.
///
/// Below it the camera's roll is decided by the rounding of the inputs rather than by the user:
/// an f32 `up` is only known to a relative 6e-8, which turns the roll by about
/// `6e-8 / sin(angle)`, 0.02° at this threshold and 180° at exactly parallel (gluLookAt returns
/// NaN there).
pub const LOOK_AT_MIN_UP_ANGLE_DEG: f64 = 0.01;

/// Why a transform could not be built. Each message names the offending value;
/// [`TransformError::text`] gives it in Japanese and English, [`TransformError::message`] in
/// either (`Display` is the English one).
#[derive(Clone, Debug, PartialEq)]
pub enum TransformError {
    /// A rotation axis that is zero or not finite (glRotatef needs a direction).
    RotationAxis {
        /// The axis as given.
        axis: Vec3,
    },
    /// A parameter that must be finite is ±∞ or NaN.
    NotFinite {
        /// Which parameter (`translation`, `rotation angle`, `scale`, …).
        what: &'static str,
        /// The value as given.
        value: f32,
    },
    /// A named matrix factor with a non-finite entry.
    MatrixNotFinite {
        /// The factor's name.
        name: String,
        /// The first non-finite entry found.
        value: f32,
    },
    /// Perspective: `near` is not a positive (normal) finite number.
    NearPlane {
        /// The near plane distance as given.
        near: f32,
    },
    /// Perspective: `far` is not finite or not beyond `near`.
    FarPlane {
        /// The near plane distance.
        near: f32,
        /// The far plane distance as given.
        far: f32,
    },
    /// Perspective: the depth mapping of `near` and `far` overflows f32 (far only a few ulps
    /// beyond a huge near).
    DepthRange {
        /// The near plane distance.
        near: f32,
        /// The far plane distance.
        far: f32,
    },
    /// Perspective: the vertical field of view is not strictly between 0° and 180°.
    FieldOfView {
        /// The field of view in degrees as given.
        fovy_deg: f32,
    },
    /// Perspective: the aspect ratio is not a positive finite number (or so extreme that the
    /// x scale over- or underflows).
    AspectRatio {
        /// Width / height as given.
        aspect: f32,
    },
    /// Look-at: a non-finite eye, target or up.
    LookAtNotFinite {
        /// The eye as given.
        eye: Vec3,
        /// The target as given.
        target: Vec3,
        /// The up vector as given.
        up: Vec3,
    },
    /// Look-at: the eye is at the target, so there is no view direction.
    EyeAtTarget {
        /// The common point.
        eye: Vec3,
    },
    /// Look-at: `up` is zero or (nearly) parallel to the view direction, so the roll is undefined.
    UpParallelToView {
        /// The up vector as given.
        up: Vec3,
        /// The view direction `target − eye`, normalised.
        direction: Vec3,
        /// The angle between up and the view direction's line, in degrees (0 for a zero up).
        angle_deg: f64,
    },
    /// A result entry overflows f32 although every input was valid.
    Overflow {
        /// What overflowed.
        what: &'static str,
    },
    /// A factor of a [`crate::product::MatrixProduct`] is invalid.
    InFactor {
        /// The factor's index, 0 = leftmost.
        index: usize,
        /// What is wrong with it.
        source: Box<TransformError>,
    },
}

impl TransformError {
    /// The message for a student in `lang`, naming the offending value.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message for a student in both languages, naming the offending value.
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            TransformError::RotationAxis { axis } => Text::new(
                format!(
                    "回転軸 {axis} がゼロまたは有限でない値です（glRotatef には長さのある方向が必要です）"
                ),
                format!(
                    "rotation axis {axis} is zero or not finite: glRotatef needs a non-zero direction"
                ),
            ),
            TransformError::NotFinite { what, value } => Text::new(
                format!("{what} = {value} が有限の値ではありません"),
                format!("{what} = {value} is not finite"),
            ),
            TransformError::MatrixNotFinite { name, value } => Text::new(
                format!("行列 {name} に有限でない要素 {value} があります"),
                format!("matrix {name} has a non-finite entry {value}"),
            ),
            TransformError::NearPlane { near } => Text::new(
                format!(
                    "透視投影: near = {near:e} は正の有限値（非正規化数ではない値）でなければなりません"
                ),
                format!(
                    "perspective: near = {near:e} must be a finite, normal (not subnormal) number > 0"
                ),
            ),
            TransformError::FarPlane { near, far } => Text::new(
                format!(
                    "透視投影: far = {far} は有限で near = {near} より大きくなければなりません"
                ),
                format!("perspective: far = {far} must be finite and greater than near = {near}"),
            ),
            TransformError::DepthRange { near, far } => Text::new(
                format!("透視投影: near = {near} と far = {far} が近すぎて奥行きを表せません"),
                format!(
                    "perspective: near = {near} and far = {far} are too close for an f32 depth mapping"
                ),
            ),
            TransformError::FieldOfView { fovy_deg } => Text::new(
                format!(
                    "透視投影: 視野角 fovy = {fovy_deg}° は 0° より大きく 180° より小さくなければなりません"
                ),
                format!("perspective: fovy = {fovy_deg}° must lie strictly between 0° and 180°"),
            ),
            TransformError::AspectRatio { aspect } => Text::new(
                format!(
                    "透視投影: アスペクト比 aspect = {aspect:e} は正の有限値で、投影行列があふれない大きさでなければなりません"
                ),
                format!(
                    "perspective: aspect = {aspect:e} must be a finite number > 0, not so extreme that the projection overflows"
                ),
            ),
            TransformError::LookAtNotFinite { eye, target, up } => Text::new(
                format!(
                    "look_at: 視点 {eye}・注視点 {target}・上方向 {up} は有限の値でなければなりません"
                ),
                format!("look_at: eye {eye}, target {target} and up {up} must be finite"),
            ),
            TransformError::EyeAtTarget { eye } => Text::new(
                format!("look_at: 視点と注視点が同じ点 {eye} です（視線の方向が決まりません）"),
                format!("look_at: eye and target are the same point {eye}: no view direction"),
            ),
            TransformError::UpParallelToView { up, direction, angle_deg } => Text::new(
                format!(
                    "look_at: 上方向 {up} が視線方向 {direction} とほぼ平行です（{angle_deg}°、最小 {LOOK_AT_MIN_UP_ANGLE_DEG}°）"
                ),
                format!(
                    "look_at: up {up} is within {angle_deg}° of the view direction {direction} (minimum {LOOK_AT_MIN_UP_ANGLE_DEG}°)"
                ),
            ),
            TransformError::Overflow { what } => {
                // `what` is one of the kit's own names; each has its Japanese.
                let ja = match *what {
                    "the product" => "変換の積",
                    "look_at translation" => "look_at の平行移動",
                    other => other,
                };
                Text::new(format!("{ja}が f32 の範囲を超えます"), format!("{what} overflows f32"))
            }
            TransformError::InFactor { index, source } => {
                let source = source.text();
                Text::new(
                    format!("積の {index} 番目の因子: {}", source.ja),
                    format!("factor {index} of the product: {}", source.en),
                )
            }
        }
    }
}

impl std::fmt::Display for TransformError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message(Lang::En))
    }
}

impl std::error::Error for TransformError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            TransformError::InFactor { source, .. } => Some(source.as_ref()),
            _ => None,
        }
    }
}

/// T(v): the translation by `v` (glTranslatef).
///
/// Non-finite components give a matrix with non-finite entries; `crate::product::Factor::matrix`
/// is the checking sibling.
#[must_use]
#[inline]
pub fn translate(v: Vec3) -> Mat4 {
    Mat4::from_translation(v)
}

/// S(v): the scale by `v` along the axes (glScalef).
///
/// A zero component gives a singular matrix (legal, as in OpenGL); a negative one mirrors.
/// Non-finite components give non-finite entries.
#[must_use]
#[inline]
pub fn scale(v: Vec3) -> Mat4 {
    Mat4::from_scale(v)
}

/// `(sin, cos)` of an angle in degrees, with the angle reduced exactly first: multiples of 90°
/// give exact 0 and ±1 (never −0), other angles the f64 values of the exact reduced angle.
///
/// NaN for a non-finite angle.
#[must_use]
pub(crate) fn sin_cos_deg(angle_deg: f32) -> (f64, f64) {
    if !angle_deg.is_finite() {
        return (f64::NAN, f64::NAN);
    }
    // f32 `%` is exact; so is the f64 subtraction (24-bit significands, small exponent range).
    let r = f64::from(angle_deg % 360.0); // (-360, 360)
    let k = (r / 90.0).round(); // -4..=4
    let rem = r - 90.0 * k; // [-45, 45], exact
    let (s, c) = rem.to_radians().sin_cos();
    let (s, c) = match (k as i32).rem_euclid(4) {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    };
    // `+ 0.0` turns −0 into +0 so printed matrices show `0`.
    (s + 0.0, c + 0.0)
}

/// The glRotatef matrix for a unit `axis` and the sine and cosine of the angle, in f64, rounded
/// once to f32. For an axis `X`, `Y` or `Z` it equals [`rotate_x`] etc. entry for entry.
fn axis_rotation(axis: DVec3, s: f64, c: f64) -> Mat4 {
    let DVec3 { x, y, z } = axis;
    let t = 1.0 - c;
    // Rows of the OpenGL reference page; glam takes columns.
    let rows = [
        [x * x * t + c, x * y * t - z * s, x * z * t + y * s],
        [y * x * t + z * s, y * y * t + c, y * z * t - x * s],
        [x * z * t - y * s, y * z * t + x * s, z * z * t + c],
    ];
    let e = |r: usize, col: usize| (rows[r][col] + 0.0) as f32;
    Mat4::from_cols(
        Vec4::new(e(0, 0), e(1, 0), e(2, 0), 0.0),
        Vec4::new(e(0, 1), e(1, 1), e(2, 1), 0.0),
        Vec4::new(e(0, 2), e(1, 2), e(2, 2), 0.0),
        Vec4::W,
    )
}

/// Rx(angle): rotation about +X by `angle` radians, counter-clockwise looking from +X towards
/// the origin (rows `[1 0 0; 0 c −s; 0 s c]`).
///
/// A non-finite angle gives NaN entries. See also [`rotate_x_deg`] (exact at multiples of 90°).
#[must_use]
pub fn rotate_x(angle: f32) -> Mat4 {
    let (s, c) = f64::from(angle).sin_cos();
    axis_rotation(DVec3::X, s, c)
}

/// Ry(angle): rotation about +Y by `angle` radians, counter-clockwise looking from +Y towards
/// the origin (rows `[c 0 s; 0 1 0; −s 0 c]`).
///
/// A non-finite angle gives NaN entries. See also [`rotate_y_deg`].
#[must_use]
pub fn rotate_y(angle: f32) -> Mat4 {
    let (s, c) = f64::from(angle).sin_cos();
    axis_rotation(DVec3::Y, s, c)
}

/// Rz(angle): rotation about +Z by `angle` radians, counter-clockwise looking from +Z towards
/// the origin (rows `[c −s 0; s c 0; 0 0 1]`).
///
/// A non-finite angle gives NaN entries. See also [`rotate_z_deg`].
#[must_use]
pub fn rotate_z(angle: f32) -> Mat4 {
    let (s, c) = f64::from(angle).sin_cos();
    axis_rotation(DVec3::Z, s, c)
}

/// R(angle, axis): rotation by `angle` radians about `axis` (any length), counter-clockwise
/// looking from the tip of `axis` towards the origin.
///
/// # Errors
/// [`TransformError::RotationAxis`] for a zero or non-finite axis (normalised with
/// [`crate::math::try_normalize`], so tiny and huge axes are fine);
/// [`TransformError::NotFinite`] for a non-finite angle.
///
/// See also [`rotate_deg`].
pub fn rotate(angle: f32, axis: Vec3) -> Result<Mat4, TransformError> {
    if !angle.is_finite() {
        return Err(TransformError::NotFinite { what: "rotation angle", value: angle });
    }
    let unit = unit_axis(axis)?;
    let (s, c) = f64::from(angle).sin_cos();
    Ok(axis_rotation(unit, s, c))
}

/// The axis normalised in f64 (after the f32 check of `try_normalize`, so both agree on what is
/// zero).
fn unit_axis(axis: Vec3) -> Result<DVec3, TransformError> {
    try_normalize(axis)
        .and_then(|_| try_normalize_f64(axis.as_dvec3()))
        .ok_or(TransformError::RotationAxis { axis })
}

/// Rx in degrees, like `glRotatef(angle_deg, 1, 0, 0)`; exact 0/±1 entries at multiples of 90°.
///
/// A non-finite angle gives NaN entries. See also [`rotate_x`].
#[must_use]
pub fn rotate_x_deg(angle_deg: f32) -> Mat4 {
    let (s, c) = sin_cos_deg(angle_deg);
    axis_rotation(DVec3::X, s, c)
}

/// Ry in degrees, like `glRotatef(angle_deg, 0, 1, 0)`; exact 0/±1 entries at multiples of 90°.
///
/// A non-finite angle gives NaN entries. See also [`rotate_y`].
#[must_use]
pub fn rotate_y_deg(angle_deg: f32) -> Mat4 {
    let (s, c) = sin_cos_deg(angle_deg);
    axis_rotation(DVec3::Y, s, c)
}

/// Rz in degrees, like `glRotatef(angle_deg, 0, 0, 1)`; exact 0/±1 entries at multiples of 90°.
///
/// A non-finite angle gives NaN entries. See also [`rotate_z`].
#[must_use]
pub fn rotate_z_deg(angle_deg: f32) -> Mat4 {
    let (s, c) = sin_cos_deg(angle_deg);
    axis_rotation(DVec3::Z, s, c)
}

/// glRotatef(angle_deg, x, y, z): rotation by `angle_deg` degrees about `axis` (any length),
/// counter-clockwise looking from the tip of `axis` towards the origin. The angle is reduced
/// exactly, so multiples of 90° about a coordinate axis give exact 0/±1 entries, and
/// `rotate_deg(a, Vec3::X)` equals [`rotate_x_deg`]`(a)`.
///
/// # Errors
/// [`TransformError::RotationAxis`] for a zero or non-finite axis;
/// [`TransformError::NotFinite`] for a non-finite angle.
///
/// See also [`rotate`] (radians).
pub fn rotate_deg(angle_deg: f32, axis: Vec3) -> Result<Mat4, TransformError> {
    if !angle_deg.is_finite() {
        return Err(TransformError::NotFinite { what: "rotation angle", value: angle_deg });
    }
    let unit = unit_axis(axis)?;
    let (s, c) = sin_cos_deg(angle_deg);
    Ok(axis_rotation(unit, s, c))
}

/// gluPerspective(fovy_deg, aspect, near, far) with wgpu's `[0, 1]` depth (透視投影).
///
/// Right-handed view space, the camera looks down −Z: a point at `z = −near` maps to depth 0,
/// at `z = −far` to depth 1; `y = ±tan(fovy/2)·|z|` maps to `y = ±1`, and x is divided by
/// `aspect` as well. The entries are computed in f64 and rounded once.
///
/// # Errors
/// Each bad parameter gives its own variant naming the value (docs/numerics.md row 20):
/// [`TransformError::NearPlane`] for `near ≤ 0`, non-finite or subnormal;
/// [`TransformError::FarPlane`] for `far ≤ near` or non-finite;
/// [`TransformError::FieldOfView`] for `fovy` outside `(0°, 180°)` (so `fovy → 0` and `→ 180`
/// fail once the matrix would over- or underflow, and exactly 0 and 180 always);
/// [`TransformError::AspectRatio`] for `aspect ≤ 0`, non-finite or so extreme that the x scale
/// over- or underflows; [`TransformError::DepthRange`] when `far` is so close to a huge `near`
/// that the depth entries overflow.
///
/// See also [`perspective_gl`], [`project_point`].
pub fn perspective(
    fovy_deg: f32,
    aspect: f32,
    near: f32,
    far: f32,
) -> Result<Mat4, TransformError> {
    perspective_with_depth(fovy_deg, aspect, near, far, false)
}

/// gluPerspective exactly: the same as [`perspective`] but with OpenGL's `[-1, 1]` depth
/// (`z = −near` → −1, `z = −far` → +1).
///
/// # Errors
/// As [`perspective`].
pub fn perspective_gl(
    fovy_deg: f32,
    aspect: f32,
    near: f32,
    far: f32,
) -> Result<Mat4, TransformError> {
    perspective_with_depth(fovy_deg, aspect, near, far, true)
}

fn perspective_with_depth(
    fovy_deg: f32,
    aspect: f32,
    near: f32,
    far: f32,
    gl_depth: bool,
) -> Result<Mat4, TransformError> {
    if !(near.is_normal() && near > 0.0) {
        return Err(TransformError::NearPlane { near });
    }
    if !(far.is_finite() && far > near) {
        return Err(TransformError::FarPlane { near, far });
    }
    if !(fovy_deg > 0.0 && fovy_deg < 180.0) {
        return Err(TransformError::FieldOfView { fovy_deg });
    }
    if !(aspect.is_finite() && aspect > 0.0) {
        return Err(TransformError::AspectRatio { aspect });
    }
    // f = cot(fovy / 2)
    let f = 1.0 / (f64::from(fovy_deg) * 0.5).to_radians().tan();
    let fx = f / f64::from(aspect);
    let (n, fa) = (f64::from(near), f64::from(far));
    let (a, b) = if gl_depth {
        ((fa + n) / (n - fa), 2.0 * fa * n / (n - fa))
    } else {
        (fa / (n - fa), fa * n / (n - fa))
    };
    let (f, fx, a, b) = (f as f32, fx as f32, a as f32, b as f32);
    if !f.is_normal() {
        return Err(TransformError::FieldOfView { fovy_deg });
    }
    if !fx.is_normal() {
        return Err(TransformError::AspectRatio { aspect });
    }
    if !(a.is_normal() && b.is_normal()) {
        return Err(TransformError::DepthRange { near, far });
    }
    Ok(Mat4::from_cols(
        Vec4::new(fx, 0.0, 0.0, 0.0),
        Vec4::new(0.0, f, 0.0, 0.0),
        Vec4::new(0.0, 0.0, a, -1.0),
        Vec4::new(0.0, 0.0, b, 0.0),
    ))
}

/// gluLookAt(eye, target, up): the view matrix (ワールド座標系→カメラ座標系) of a camera at `eye`
/// looking at `target`, with `up` projected to the screen's +Y.
///
/// The eye maps to the origin and the target onto −Z; the rotation part is orthonormal with
/// rows `s = normalise(f × up)`, `u = s × f`, `−f`, where `f = normalise(target − eye)`, all in
/// f64 and rounded once.
///
/// # Errors
/// [`TransformError::LookAtNotFinite`] for a non-finite input;
/// [`TransformError::EyeAtTarget`] for `eye == target`;
/// [`TransformError::UpParallelToView`] for a zero `up` or one within
/// [`LOOK_AT_MIN_UP_ANGLE_DEG`] of the view direction or its opposite (gluLookAt returns NaN
/// there; docs/numerics.md row 10); [`TransformError::Overflow`] when the translation overflows f32.
///
/// See also [`crate::camera::OrbitCamera::view_matrix`], which has no up vector and is defined
/// at every pitch.
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Result<Mat4, TransformError> {
    if !(eye.is_finite() && target.is_finite() && up.is_finite()) {
        return Err(TransformError::LookAtNotFinite { eye, target, up });
    }
    // f64: the difference of two f32 values cannot overflow there and is zero only when equal.
    let e = eye.as_dvec3();
    let f = try_normalize_f64(target.as_dvec3() - e).ok_or(TransformError::EyeAtTarget { eye })?;
    let direction = f.as_vec3();
    let angle = angle_between(up, direction).unwrap_or(0.0);
    let angle_deg = angle.min(std::f64::consts::PI - angle).to_degrees();
    if angle_deg < LOOK_AT_MIN_UP_ANGLE_DEG {
        return Err(TransformError::UpParallelToView { up, direction, angle_deg });
    }
    let err = TransformError::UpParallelToView { up, direction, angle_deg };
    let up_unit = try_normalize_f64(up.as_dvec3()).ok_or(err.clone())?;
    let s = try_normalize_f64(f.cross(up_unit)).ok_or(err)?;
    let u = s.cross(f);
    let t = DVec3::new(-s.dot(e), -u.dot(e), f.dot(e)).as_vec3();
    if !t.is_finite() {
        return Err(TransformError::Overflow { what: "look_at translation" });
    }
    let (s, u, f) = (s.as_vec3(), u.as_vec3(), f.as_vec3());
    Ok(Mat4::from_cols(
        Vec4::new(s.x, u.x, -f.x, 0.0),
        Vec4::new(s.y, u.y, -f.y, 0.0),
        Vec4::new(s.z, u.z, -f.z, 0.0),
        t.extend(1.0),
    ))
}

/// `M·(p, 1)` without the homogeneous divide: a point under an affine transform (model, view).
///
/// For a projection use [`project_point`]. Non-finite input gives non-finite output.
///
/// See also [`transform_vector`], `crate::normals::transform_normal`.
#[must_use]
#[inline]
pub fn transform_point(m: Mat4, p: Vec3) -> Vec3 {
    (m * p.extend(1.0)).truncate()
}

/// `M·(v, 0)`: a direction or offset, unaffected by translation.
///
/// Not for normals under non-uniform scale or mirroring: see also
/// `crate::normals::transform_normal`.
#[must_use]
#[inline]
pub fn transform_vector(m: Mat4, v: Vec3) -> Vec3 {
    (m * v.extend(0.0)).truncate()
}

/// `M·(p, 1)` followed by the homogeneous divide (透視除算): clip space to normalised device
/// coordinates.
///
/// Returns `None` when `w ≤ 0` (the point is at or behind the eye) or when anything is not
/// finite, never a point mirrored through the eye or a NaN.
#[must_use]
pub fn project_point(m: Mat4, p: Vec3) -> Option<Vec3> {
    let h = m * p.extend(1.0);
    if !(h.w > 0.0 && h.is_finite()) {
        return None;
    }
    let r = h.truncate() / h.w;
    r.is_finite().then_some(r)
}

#[cfg(test)]
mod text_tests {
    use super::*;

    /// Every variant, and both branches of the ones whose message has two.
    fn samples() -> Vec<TransformError> {
        let all = vec![
            TransformError::RotationAxis { axis: Vec3::ZERO },
            TransformError::NotFinite { what: "translation", value: f32::NAN },
            TransformError::MatrixNotFinite { name: "T".into(), value: f32::INFINITY },
            TransformError::NearPlane { near: 1e-40 },
            TransformError::FarPlane { near: 1.0, far: 0.5 },
            TransformError::DepthRange { near: 1e30, far: 1.000_001e30 },
            TransformError::FieldOfView { fovy_deg: 180.0 },
            TransformError::AspectRatio { aspect: -1.0 },
            TransformError::LookAtNotFinite { eye: Vec3::ZERO, target: Vec3::X, up: Vec3::NAN },
            TransformError::EyeAtTarget { eye: Vec3::ONE },
            TransformError::UpParallelToView {
                up: Vec3::Z,
                direction: Vec3::NEG_Z,
                angle_deg: 0.001,
            },
            TransformError::Overflow { what: "the product" },
            TransformError::InFactor {
                index: 2,
                source: Box::new(TransformError::NearPlane { near: 0.0 }),
            },
        ];
        // Exhaustive: a new variant does not compile until it has a sample above.
        for e in &all {
            match e {
                TransformError::RotationAxis { .. }
                | TransformError::NotFinite { .. }
                | TransformError::MatrixNotFinite { .. }
                | TransformError::NearPlane { .. }
                | TransformError::FarPlane { .. }
                | TransformError::DepthRange { .. }
                | TransformError::FieldOfView { .. }
                | TransformError::AspectRatio { .. }
                | TransformError::LookAtNotFinite { .. }
                | TransformError::EyeAtTarget { .. }
                | TransformError::UpParallelToView { .. }
                | TransformError::Overflow { .. }
                | TransformError::InFactor { .. } => {}
            }
        }
        all
    }

    /// Both languages' messages of `e` (and `message` gives the same).
    fn text_of(e: &TransformError) -> Text {
        let text = e.text();
        assert_eq!([e.message(Lang::Ja), e.message(Lang::En)], [&*text.ja, &*text.en]);
        text
    }

    #[test]
    fn every_message_is_one_clean_line_in_each_language() {
        let messages = samples().into_iter().map(|e| {
            let text = text_of(&e);
            assert_eq!(e.to_string(), text.en);
            (format!("{e:?}"), text.ja, text.en)
        });
        cg_testkit::text::assert_clean_lines(messages, false, true);
    }
}
