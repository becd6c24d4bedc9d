//! Poses, shared by the checks and the report: a draw's model matrix with the common camera
//! taken off, how far two poses are apart, which draw is which object, and how a time prints.

use cg_core::gl::{Draw, Gl};
use cg_core::glam::{DMat3, DMat4, DVec3};

use crate::{CAMERA_DISTANCE, CAMERA_PITCH_DEG};

/// The common camera `V = T(0, 0, -15) · Rx(30°)` in f64.
pub(crate) fn view() -> DMat4 {
    DMat4::from_translation(DVec3::new(0.0, 0.0, -f64::from(CAMERA_DISTANCE)))
        * DMat4::from_rotation_x(f64::from(-CAMERA_PITCH_DEG).to_radians())
}

/// A draw's model matrix (world), the camera taken off.
pub(crate) fn model_of(draw: &Draw) -> DMat4 {
    view().inverse() * draw.matrix.as_dmat4()
}

/// `(rotation error ≈ radians, origin error)`, infinite for non-finite input.
pub(crate) fn pose_error(found: DMat4, expected: DMat4) -> (f64, f64) {
    if !found.is_finite() || !expected.is_finite() {
        return (f64::INFINITY, f64::INFINITY);
    }
    let d = DMat3::from_mat4(found) - DMat3::from_mat4(expected);
    let rot = (d.x_axis.length_squared() + d.y_axis.length_squared() + d.z_axis.length_squared())
        .sqrt()
        / std::f64::consts::SQRT_2;
    let pos = (found.w_axis.truncate() - expected.w_axis.truncate()).length();
    (rot, pos)
}

/// How far apart two poses are: the rotation error plus the origin error of [`pose_error`].
pub(crate) fn pose_distance(a: DMat4, b: DMat4) -> f64 {
    let (rot, pos) = pose_error(a, b);
    rot + pos
}

/// A time in seconds as the messages and the report's IDs print it: at most 3 decimals,
/// trailing zeros dropped (`2.5`, `0.017`, `1`).
pub(crate) fn seconds(x: f64) -> String {
    let s = cg_core::notation::fixed64(x, 3);
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// Whether a draw's name means `object`: the same ignoring case, spaces, `_` and `-`; `物体2`
/// also means `object 2`.
pub(crate) fn name_matches(drawn: &str, object: &str) -> bool {
    let norm = |s: &str| -> String {
        s.chars()
            .filter(|c| !c.is_whitespace() && *c != '_' && *c != '-')
            .flat_map(char::to_lowercase)
            .collect::<String>()
            .replace("物体", "object")
    };
    norm(drawn) == norm(object)
}

/// The draws in `gl` whose name means `name`.
pub(crate) fn draws_named<'a>(gl: &'a Gl, name: &str) -> Vec<&'a Draw> {
    gl.draws().iter().filter(|d| name_matches(&d.name, name)).collect()
}
