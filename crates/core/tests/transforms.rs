//! Transform builders: rotations, perspective, look-at, point/vector application.
//! docs/numerics.md row 20 (perspective parameters) and the look-at half of row 10.
//!
//! Oracles are analytic (f64 trigonometry, Rodrigues' formula, the defining properties of each
//! matrix), never the builders' own output.

use cg_core::glam::{DMat4, DVec3, Mat4, Vec3};
use cg_core::transform::{
    LOOK_AT_MIN_UP_ANGLE_DEG, TransformError, look_at, perspective, perspective_gl, project_point,
    rotate, rotate_deg, rotate_x, rotate_x_deg, rotate_y, rotate_y_deg, rotate_z, rotate_z_deg,
    scale, transform_point, transform_vector, translate,
};
use cg_testkit::assert_approx_eq;
use cg_testkit::prop::{log_uniform, vec3};
use proptest::prelude::*;

fn config(cases: u32) -> ProptestConfig {
    cg_testkit::prop::config(cases, 0x7a11_5f0e)
}

/// Angles in degrees: small, typical and huge (animation angles that were never reduced).
fn angle_deg() -> impl Strategy<Value = f32> {
    prop_oneof![-720.0f32..720.0, log_uniform(-6.0, 7.0)]
}

/// `max |Mᵀ·M − I|` over the 3×3 rotation part and `det − 1`, in f64 from the f32 entries.
fn orthonormality_error(m: Mat4) -> (f64, f64) {
    let d = m.as_dmat4();
    let r = cg_core::glam::DMat3::from_mat4(d);
    let e = (r.transpose() * r - cg_core::glam::DMat3::IDENTITY)
        .to_cols_array()
        .iter()
        .fold(0.0f64, |a, x| a.max(x.abs()));
    (e, r.determinant() - 1.0)
}

/// The homogeneous row and column of an affine matrix are exactly (0, 0, 0, 1).
fn assert_affine(m: Mat4, what: &str) {
    assert_eq!(m.row(3).to_array(), [0.0, 0.0, 0.0, 1.0], "{what}: bottom row");
}

// Each entry is one f64 value rounded to f32 (≤ 2⁻²⁴ relative, entries ≤ 1): a dot product of
// three such entries is off by at most 3·2·2⁻²⁴ ≈ 3.6e-7, det by about as much. 1e-6 leaves room.
const ORTHO_TOL: f64 = 1e-6;

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn rotations_are_orthonormal_with_det_one(
        a_deg in angle_deg(),
        a_rad in prop_oneof![-10.0f32..10.0, log_uniform(-6.0, 5.0)],
        axis in vec3(-20.0, 20.0),
    ) {
        let cases = [
            ("rotate_x_deg", rotate_x_deg(a_deg)),
            ("rotate_y_deg", rotate_y_deg(a_deg)),
            ("rotate_z_deg", rotate_z_deg(a_deg)),
            ("rotate_deg", rotate_deg(a_deg, axis).unwrap()),
            ("rotate_x", rotate_x(a_rad)),
            ("rotate_y", rotate_y(a_rad)),
            ("rotate_z", rotate_z(a_rad)),
            ("rotate", rotate(a_rad, axis).unwrap()),
        ];
        for (name, m) in cases {
            let (ortho, det) = orthonormality_error(m);
            prop_assert!(ortho <= ORTHO_TOL, "{name}({a_deg}°/{a_rad} rad, {axis}): |RᵀR − I| = {ortho:e}");
            prop_assert!(det.abs() <= ORTHO_TOL, "{name}: det − 1 = {det:e}");
            assert_affine(m, name);
            prop_assert_eq!(m.col(3).to_array(), [0.0, 0.0, 0.0, 1.0], "{} translates", name);
        }
    }

    /// Rodrigues' formula in f64 on the same f32 angle and axis is the oracle:
    /// `v cos θ + (k × v) sin θ + k (k·v)(1 − cos θ)`.
    #[test]
    fn rotate_deg_matches_rodrigues_in_f64(
        a_deg in angle_deg(),
        axis in vec3(-20.0, 20.0),
        v in vec3(-3.0, 3.0),
    ) {
        let k = axis.as_dvec3().normalize();
        let theta = (f64::from(a_deg) % 360.0).to_radians();
        let vd = v.as_dvec3();
        let expected = vd * theta.cos() + k.cross(vd) * theta.sin() + k * k.dot(vd) * (1.0 - theta.cos());
        let got = transform_vector(rotate_deg(a_deg, axis).unwrap(), v).as_dvec3();
        // Entries within ~1e-7 (see ORTHO_TOL), three products summed: 4e-7·|v| plus the final
        // rounding of the components.
        let tol = 4e-7 * vd.length() + 1e-7 * vd.length();
        prop_assert!((got - expected).length() <= tol, "R({a_deg}°, {axis})·{v}: {got} vs {expected}");
        // The radian form agrees on the same angle.
        let got_rad = transform_vector(rotate(theta as f32, axis).unwrap(), v).as_dvec3();
        prop_assert!((got_rad - expected).length() <= tol + 1e-7 * vd.length(), "rotate: {got_rad} vs {expected}");
    }

    #[test]
    fn degree_rotations_match_f64_trigonometry(a in angle_deg()) {
        // The exact reduction makes the f32 result the f64 sin/cos of the *given* f32 angle,
        // rounded once: within half an ulp of 1 (6e-8) plus the f64 error.
        let t = f64::from(a).to_radians();
        let (s, c) = (t.sin(), t.cos());
        let rx = DMat4::from_cols_array(&[1., 0., 0., 0., 0., c, s, 0., 0., -s, c, 0., 0., 0., 0., 1.]);
        let ry = DMat4::from_cols_array(&[c, 0., -s, 0., 0., 1., 0., 0., s, 0., c, 0., 0., 0., 0., 1.]);
        let rz = DMat4::from_cols_array(&[c, s, 0., 0., -s, c, 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.]);
        // f64 to_radians of angles up to 1e7 loses ~1e7·1e-16 = 1e-9 rad: far below 1e-7.
        assert_approx_eq!(rotate_x_deg(a), rx.as_mat4(), abs = 1e-7, "Rx({a}°)");
        assert_approx_eq!(rotate_y_deg(a), ry.as_mat4(), abs = 1e-7, "Ry({a}°)");
        assert_approx_eq!(rotate_z_deg(a), rz.as_mat4(), abs = 1e-7, "Rz({a}°)");
    }
}

#[test]
fn degree_rotations_are_exact_at_multiples_of_90() {
    // Premise: the plain radian route leaves rounding noise where a 0 belongs.
    let naive = Mat4::from_rotation_x(90f32.to_radians());
    assert_ne!(naive.y_axis.y, 0.0, "premise: cos(to_radians(90)) is not 0 in f32");

    for k in -12i32..=12 {
        // Offsets chosen so that the sum stays exactly representable in f32 (< 2²⁴).
        for offset in [0.0f32, 360.0 * 1000.0, -360.0 * 1e4] {
            let a = 90.0 * k as f32 + offset;
            // Exact oracle: (sin, cos) of k·90°.
            let (s, c) =
                [(0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)][k.rem_euclid(4) as usize];
            let rx = Mat4::from_cols_array(&[
                1., 0., 0., 0., 0., c, s, 0., 0., -s, c, 0., 0., 0., 0., 1.,
            ]);
            let ry = Mat4::from_cols_array(&[
                c, 0., -s, 0., 0., 1., 0., 0., s, 0., c, 0., 0., 0., 0., 1.,
            ]);
            let rz = Mat4::from_cols_array(&[
                c, s, 0., 0., -s, c, 0., 0., 0., 0., 1., 0., 0., 0., 0., 1.,
            ]);
            for (name, got, want) in [
                ("Rx", rotate_x_deg(a), rx),
                ("Ry", rotate_y_deg(a), ry),
                ("Rz", rotate_z_deg(a), rz),
                ("R(X)", rotate_deg(a, Vec3::X * 3.0).unwrap(), rx),
                ("R(Y)", rotate_deg(a, Vec3::Y * 0.5).unwrap(), ry),
                ("R(Z)", rotate_deg(a, Vec3::Z * 1e-30).unwrap(), rz),
            ] {
                assert_eq!(got, want, "{name}({a}°) must be exact");
                // No −0: printed matrices show 0, not -0.
                for x in got.to_cols_array() {
                    assert!(x != 0.0 || x.is_sign_positive(), "{name}({a}°) has a -0 entry");
                }
            }
        }
    }
    // A huge exact multiple of 360°: 90·2³⁰ (7 significant bits) is the identity, exactly.
    assert_eq!(rotate_x_deg(90.0 * 2f32.powi(30)), Mat4::IDENTITY);
    assert_eq!(rotate_z_deg(-90.0 * 2f32.powi(31)), Mat4::IDENTITY);
}

#[test]
fn rotate_deg_about_a_coordinate_axis_equals_the_axis_builder() {
    for a in [0.0f32, 12.5, -30.0, 45.0, 77.7, 200.0, -1234.5] {
        assert_eq!(rotate_deg(a, Vec3::X).unwrap(), rotate_x_deg(a), "{a}° about X");
        assert_eq!(rotate_deg(a, Vec3::Y * 7.0).unwrap(), rotate_y_deg(a), "{a}° about Y");
        assert_eq!(rotate_deg(a, Vec3::Z).unwrap(), rotate_z_deg(a), "{a}° about Z");
    }
}

#[test]
fn rotations_turn_counter_clockwise_like_gl_rotate() {
    // Looking from +axis towards the origin, +90° turns the next axis onto the one after.
    assert_eq!(transform_vector(rotate_z_deg(90.0), Vec3::X), Vec3::Y);
    assert_eq!(transform_vector(rotate_x_deg(90.0), Vec3::Y), Vec3::Z);
    assert_eq!(transform_vector(rotate_y_deg(90.0), Vec3::Z), Vec3::X);
    // 120° about (1, 1, 1) cycles X → Y → Z.
    let r = rotate_deg(120.0, Vec3::ONE).unwrap();
    assert_approx_eq!(transform_vector(r, Vec3::X), Vec3::Y, abs = 1e-6);
    assert_approx_eq!(transform_vector(r, Vec3::Y), Vec3::Z, abs = 1e-6);
    // The radian forms agree with the degree forms.
    assert_approx_eq!(rotate_y(std::f32::consts::FRAC_PI_3), rotate_y_deg(60.0), abs = 1e-7);
}

#[test]
fn rotate_rejects_zero_and_non_finite_axes_and_angles() {
    for axis in [Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 1.0), Vec3::new(0.0, f32::INFINITY, 0.0)] {
        assert!(
            matches!(rotate_deg(30.0, axis), Err(TransformError::RotationAxis { axis: a }) if a.to_array().iter().zip(axis.to_array()).all(|(x, y)| x.to_bits() == y.to_bits())),
            "axis {axis}"
        );
        assert!(matches!(rotate(0.5, axis), Err(TransformError::RotationAxis { .. })), "{axis}");
    }
    // Tiny and huge axes are fine (normalised by scaling first; glam's normalize would give
    // NaN and 0 here).
    assert_approx_eq!(rotate_deg(90.0, Vec3::Z * 1e-30).unwrap(), rotate_z_deg(90.0), abs = 0.0);
    assert_approx_eq!(rotate_deg(90.0, Vec3::Z * 3e38).unwrap(), rotate_z_deg(90.0), abs = 0.0);
    assert!(matches!(
        rotate_deg(f32::NAN, Vec3::X),
        Err(TransformError::NotFinite { what: "rotation angle", .. })
    ));
    let msg = rotate_deg(30.0, Vec3::ZERO).unwrap_err().to_string();
    assert!(msg.contains("rotation axis") && msg.contains("[0, 0, 0]"), "{msg}");
}

#[test]
fn points_translate_and_vectors_do_not() {
    let t = translate(Vec3::new(1.0, 2.0, 3.0));
    assert_eq!(transform_point(t, Vec3::new(1.0, 1.0, 1.0)), Vec3::new(2.0, 3.0, 4.0));
    assert_eq!(transform_vector(t, Vec3::new(1.0, 1.0, 1.0)), Vec3::new(1.0, 1.0, 1.0));
    let s = scale(Vec3::new(2.0, -1.0, 0.5));
    assert_eq!(transform_point(s, Vec3::new(1.0, 1.0, 1.0)), Vec3::new(2.0, -1.0, 0.5));
    assert_eq!(transform_vector(s, Vec3::new(4.0, 4.0, 4.0)), Vec3::new(8.0, -4.0, 2.0));
    // glTranslatef then glRotatef: the rotation acts first.
    let m = t * rotate_z_deg(90.0);
    assert_eq!(transform_point(m, Vec3::X), Vec3::new(1.0, 3.0, 3.0));
}

// ---------------------------------------------------------------------------------------------
// Perspective: properties of gluPerspective.

fn perspective_inputs() -> impl Strategy<Value = (f32, f32, f32, f32)> {
    (1.0f32..179.0, -1.5f64..1.5, -3.0f64..3.0, -2.0f64..5.0).prop_map(|(fovy, ea, en, er)| {
        let near = 10f64.powf(en) as f32;
        let far = (f64::from(near) * (1.0 + 10f64.powf(er))) as f32;
        (fovy, 10f64.powf(ea) as f32, near, far)
    })
}

/// Depth (NDC z) of the view-space point `(0, 0, −dist)`, projected in f64 from the f32 matrix
/// (the matrix is under test, the projection arithmetic is not).
fn depth(m: Mat4, dist: f32) -> f64 {
    let h = m.as_dmat4() * DVec3::new(0.0, 0.0, -f64::from(dist)).extend(1.0);
    h.z / h.w
}

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn perspective_maps_near_to_0_and_far_to_1((fovy, aspect, near, far) in perspective_inputs()) {
        let m = perspective(fovy, aspect, near, far).unwrap();
        // depth(d) = far/(far−near)·(1 − near/d). Rounding the entries a = far/(near−far) and
        // b = near·a by 2⁻²⁴ each moves depth by up to 2⁻²⁴·(|a| + |b|/d) ≤ 2⁻²³·far/(far−near).
        let cond = f64::from(far) / (f64::from(far) - f64::from(near));
        let tol = 4.0 * f64::from(f32::EPSILON) * cond;
        assert_approx_eq!(depth(m, near), 0.0, abs = tol, "near plane, {near}..{far}");
        assert_approx_eq!(depth(m, far), 1.0, abs = tol, "far plane, {near}..{far}");
        // In between, depth increases with distance and stays inside [0, 1].
        let mid = ((f64::from(near) * f64::from(far)).sqrt()) as f32;
        let dm = depth(m, mid);
        prop_assert!((0.0..=1.0).contains(&dm), "mid depth {dm}");
        prop_assert_eq!(m.row(3).to_array(), [0.0, 0.0, -1.0, 0.0], "w = −z");
    }

    #[test]
    fn perspective_gl_maps_near_to_minus_1_and_far_to_1((fovy, aspect, near, far) in perspective_inputs()) {
        let m = perspective_gl(fovy, aspect, near, far).unwrap();
        // As above with a = (far+near)/(near−far), b = 2·far·near/(near−far): twice the terms.
        let cond = f64::from(far) / (f64::from(far) - f64::from(near));
        let tol = 8.0 * f64::from(f32::EPSILON) * cond;
        assert_approx_eq!(depth(m, near), -1.0, abs = tol, "near plane, {near}..{far}");
        assert_approx_eq!(depth(m, far), 1.0, abs = tol, "far plane, {near}..{far}");
        // The same x and y as the [0, 1] variant: only depth differs.
        let w = perspective(fovy, aspect, near, far).unwrap();
        prop_assert_eq!(m.x_axis, w.x_axis);
        prop_assert_eq!(m.y_axis, w.y_axis);
    }

    #[test]
    fn perspective_fovy_edge_maps_to_y_plus_minus_1_and_aspect_scales_x(
        (fovy, aspect, near, far) in perspective_inputs(),
        t in 0.0f64..1.0,
    ) {
        // A point on the top edge of the view volume at distance d: y = tan(fovy/2)·d.
        let d = f64::from(near) + t * (f64::from(far) - f64::from(near));
        let half = (f64::from(fovy) / 2.0).to_radians().tan();
        for m in [perspective(fovy, aspect, near, far).unwrap(), perspective_gl(fovy, aspect, near, far).unwrap()] {
            let md = m.as_dmat4();
            let project = |p: DVec3| {
                let h = md * p.extend(1.0);
                h.truncate() / h.w
            };
            // One rounding of f = cot(fovy/2) to f32: 2⁻²⁴ relative, doubled for slack.
            let tol = 2.0 * f64::from(f32::EPSILON);
            let top = project(DVec3::new(0.0, half * d, -d));
            let bottom = project(DVec3::new(0.0, -half * d, -d));
            assert_approx_eq!(top.y, 1.0, abs = tol, "top edge, fovy {fovy}");
            assert_approx_eq!(bottom.y, -1.0, abs = tol, "bottom edge, fovy {fovy}");
            // x reaches ±1 at aspect·tan(fovy/2)·d: the aspect ratio widens the view.
            let a = f64::from(aspect);
            let right = project(DVec3::new(a * half * d, 0.0, -d));
            assert_approx_eq!(right.x, 1.0, abs = 2.0 * tol, "right edge, aspect {aspect}");
        }
    }
}

#[test]
fn perspective_agrees_with_glam_on_the_course_projection() {
    // An independent implementation as a second oracle: gluPerspective(45°, 1, 1, 500).
    let ours = perspective(45.0, 1.0, 1.0, 500.0).unwrap();
    let glam =
        cg_core::glam::camera::rh::proj::directx::perspective(45f32.to_radians(), 1.0, 1.0, 500.0);
    assert_approx_eq!(ours, glam, rel = 1e-6);
    let ours_gl = perspective_gl(45.0, 640.0 / 480.0, 1.0, 500.0).unwrap();
    let glam_gl = cg_core::glam::camera::rh::proj::opengl::perspective(
        45f32.to_radians(),
        640.0 / 480.0,
        1.0,
        500.0,
    );
    assert_approx_eq!(ours_gl, glam_gl, rel = 1e-6);
}

#[test]
fn project_point_refuses_points_at_or_behind_the_eye() {
    let p = perspective(45.0, 1.0, 1.0, 500.0).unwrap();
    assert!(project_point(p, Vec3::new(0.0, 0.0, -10.0)).is_some());
    assert_eq!(project_point(p, Vec3::new(0.0, 0.0, 0.0)), None, "w = 0 at the eye");
    assert_eq!(project_point(p, Vec3::new(1.0, 2.0, 5.0)), None, "behind the eye: w < 0");
    assert_eq!(project_point(p, Vec3::new(f32::NAN, 0.0, -10.0)), None);
    // An affine matrix has w = 1 everywhere: project_point is transform_point then.
    let t = translate(Vec3::ONE);
    assert_eq!(project_point(t, Vec3::X), Some(transform_point(t, Vec3::X)));
}

// ---------------------------------------------------------------------------------------------
// docs/numerics.md row 20: perspective with near → 0, fov → 0 or 180°, aspect 0 → a clear error.

#[test]
fn row20_perspective_near_not_positive_is_an_error() {
    // Premise: the plain formula (glam's) at near = 0 is finite but maps every point to depth 1,
    // a silent wrong value rather than an error.
    let naive = cg_core::glam::camera::rh::proj::directx::perspective(0.8, 1.0, 0.0, 500.0);
    assert!(naive.is_finite());
    assert_eq!(depth(naive, 1.0), depth(naive, 400.0), "premise: depth carries no information");

    for near in [0.0, -0.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY, 1e-40] {
        let err = perspective(45.0, 1.0, near, 500.0).unwrap_err();
        assert!(
            matches!(err, TransformError::NearPlane { near: n } if n.to_bits() == near.to_bits()),
            "near = {near}: {err:?}"
        );
        assert!(err.to_string().contains(&format!("near = {near:e}")), "{err}");
        assert!(matches!(
            perspective_gl(45.0, 1.0, near, 500.0),
            Err(TransformError::NearPlane { .. })
        ));
    }
    // Near → 0 but still a normal positive number is valid, and the near plane still maps to 0.
    let m = perspective(45.0, 1.0, 1e-6, 500.0).unwrap();
    assert_approx_eq!(depth(m, 1e-6), 0.0, abs = 4.0 * f64::from(f32::EPSILON));
}

#[test]
fn row20_perspective_far_not_beyond_near_is_an_error() {
    for far in [1.0f32, 0.5, -500.0, f32::NAN, f32::INFINITY] {
        let err = perspective(45.0, 1.0, 1.0, far).unwrap_err();
        assert!(matches!(err, TransformError::FarPlane { near: 1.0, .. }), "far = {far}: {err:?}");
        assert!(err.to_string().contains(&format!("far = {far}")), "{err}");
    }
    // Far one ulp beyond a huge near: the depth entries overflow f32 → its own error, not ∞.
    let near = 3e38f32;
    let far = f32::from_bits(near.to_bits() + 1);
    assert!(matches!(perspective(45.0, 1.0, near, far), Err(TransformError::DepthRange { .. })));
}

#[test]
fn row20_perspective_fovy_0_or_180_is_an_error() {
    for fovy in [0.0f32, -0.0, -45.0, 180.0, 270.0, f32::NAN, f32::INFINITY] {
        let err = perspective(fovy, 1.0, 1.0, 500.0).unwrap_err();
        assert!(
            matches!(err, TransformError::FieldOfView { fovy_deg } if fovy_deg.to_bits() == fovy.to_bits()),
            "fovy = {fovy}: {err:?}"
        );
        assert!(err.to_string().contains(&format!("fovy = {fovy}°")), "{err}");
    }
    // fovy → 0 overflows cot(fovy/2) in f32 before it reaches 0: an error too, not ∞.
    assert!(matches!(perspective(1e-40, 1.0, 1.0, 500.0), Err(TransformError::FieldOfView { .. })));
    // Just inside the range the matrix is valid and finite.
    for fovy in [1e-30f32, 1e-3, 179.99, f32::from_bits(180f32.to_bits() - 1)] {
        let m = perspective(fovy, 1.0, 1.0, 500.0).unwrap();
        assert!(m.is_finite() && m.y_axis.y > 0.0, "fovy {fovy}: {m}");
    }
}

#[test]
fn row20_perspective_aspect_0_is_an_error() {
    for aspect in [0.0f32, -0.0, -1.0, f32::NAN, f32::INFINITY] {
        let err = perspective(45.0, aspect, 1.0, 500.0).unwrap_err();
        assert!(
            matches!(err, TransformError::AspectRatio { aspect: a } if a.to_bits() == aspect.to_bits()),
            "aspect = {aspect}: {err:?}"
        );
        assert!(err.to_string().contains(&format!("aspect = {aspect}")), "{err}");
    }
    // aspect → 0 overflows the x scale f/aspect: an error, not ∞.
    assert!(matches!(
        perspective(45.0, 1e-39, 1.0, 500.0),
        Err(TransformError::AspectRatio { .. })
    ));
}

#[test]
fn row20_perspective_is_finite_or_an_error_for_any_input() {
    // Seeded sweep over hostile values: never a matrix with ∞ or NaN.
    let mut inputs = cg_testkit::Inputs::seeded(20);
    let special =
        [0.0f32, -0.0, f32::MIN_POSITIVE, 1e-40, f32::MAX, f32::INFINITY, f32::NAN, 180.0];
    for _ in 0..2000 {
        let pick = |inputs: &mut cg_testkit::Inputs| {
            if inputs.coin() {
                special[inputs.int(0, special.len() as i64) as usize]
            } else {
                inputs.log_uniform_f32(-40.0, 38.0)
            }
        };
        let (fovy, aspect, near, far) =
            (pick(&mut inputs), pick(&mut inputs), pick(&mut inputs), pick(&mut inputs));
        let results =
            [perspective(fovy, aspect, near, far), perspective_gl(fovy, aspect, near, far)];
        for m in results.into_iter().flatten() {
            assert!(m.is_finite(), "P({fovy}, {aspect}, {near}, {far}) = {m}");
            assert!(near > 0.0 && far > near && fovy > 0.0 && fovy < 180.0 && aspect > 0.0);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Look-at (gluLookAt) and the look-at half of docs/numerics.md row 10.

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn look_at_is_orthonormal_maps_eye_to_origin_and_target_onto_minus_z(
        eye in vec3(-3.0, 4.0),
        offset in vec3(-3.0, 3.0),
        up in vec3(-2.0, 2.0),
    ) {
        let target = eye + offset;
        prop_assume!(target != eye);
        let dir = (target.as_dvec3() - eye.as_dvec3()).normalize();
        let angle = up.as_dvec3().normalize().dot(dir).abs().acos().to_degrees();
        prop_assume!(angle > 0.1);
        let m = look_at(eye, target, up).unwrap();
        let (ortho, det) = orthonormality_error(m);
        prop_assert!(ortho <= ORTHO_TOL, "|RᵀR − I| = {ortho:e}");
        prop_assert!(det.abs() <= ORTHO_TOL, "det − 1 = {det:e}");
        assert_affine(m, "look_at");
        // In f64 from the f32 matrix: R·eye + t cancels to 0 up to the rounding of R and t,
        // about 2⁻²⁴·|eye| each (×3 components): tolerance 4e-7·|eye|.
        let md = m.as_dmat4();
        let scale = eye.as_dvec3().length().max(target.as_dvec3().length());
        let e = md.transform_point3(eye.as_dvec3());
        prop_assert!(e.length() <= 4e-7 * scale, "eye ↦ {e}");
        // The target lands on −Z at its distance.
        let t = md.transform_point3(target.as_dvec3());
        let dist = (target.as_dvec3() - eye.as_dvec3()).length();
        prop_assert!(t.x.abs() <= 4e-7 * scale && t.y.abs() <= 4e-7 * scale, "target ↦ {t}");
        assert_approx_eq!(t.z, -dist, abs = 4e-7 * scale);
        // Up stays up: it projects onto +Y of the view, never onto −Y.
        prop_assert!(transform_vector(m, up).y > 0.0);
    }
}

#[test]
fn look_at_agrees_with_glam_and_the_trivial_camera() {
    // A camera on +Z looking at the origin is just T(0, 0, −5).
    assert_eq!(
        look_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y).unwrap(),
        translate(Vec3::new(0.0, 0.0, -5.0))
    );
    let (eye, target, up) = (Vec3::new(3.0, 4.0, 5.0), Vec3::new(0.0, 1.0, 0.0), Vec3::Y);
    let glam = cg_core::glam::camera::rh::view::look_at_mat4(eye, target, up);
    assert_approx_eq!(look_at(eye, target, up).unwrap(), glam, abs = 1e-6);
}

#[test]
fn row10_look_at_up_parallel_to_view_is_an_error() {
    let eye = Vec3::new(0.0, 10.0, 0.0);
    // Premise: glam's look-at (gluLookAt's formula) returns NaN here.
    assert!(cg_core::glam::camera::rh::view::look_at_mat4(eye, Vec3::ZERO, Vec3::Y).is_nan());
    for up in [Vec3::Y, -Vec3::Y, Vec3::Y * 1e-30, Vec3::Y * 3e38, Vec3::ZERO] {
        let err = look_at(eye, Vec3::ZERO, up).unwrap_err();
        assert!(matches!(err, TransformError::UpParallelToView { .. }), "up {up}: {err:?}");
    }
    // The threshold: twice inside is refused, twice outside is accepted (exact f64 angles).
    let tilt = |deg: f64| {
        let t = deg.to_radians();
        DVec3::new(t.sin(), -t.cos(), 0.0).as_vec3()
    };
    assert!(matches!(
        look_at(eye, Vec3::ZERO, tilt(LOOK_AT_MIN_UP_ANGLE_DEG / 2.0)),
        Err(TransformError::UpParallelToView { .. })
    ));
    let m = look_at(eye, Vec3::ZERO, tilt(LOOK_AT_MIN_UP_ANGLE_DEG * 2.0)).unwrap();
    assert!(m.is_finite());
    assert!(orthonormality_error(m).0 <= ORTHO_TOL);
    let msg = look_at(eye, Vec3::ZERO, Vec3::Y).unwrap_err().to_string();
    assert!(msg.contains("up [0, 1, 0]"), "{msg}");
}

#[test]
fn row10_look_at_eye_equal_target_is_an_error() {
    for p in [Vec3::ZERO, Vec3::new(1e30, -2.0, 3.0), Vec3::splat(f32::MIN_POSITIVE)] {
        let err = look_at(p, p, Vec3::Y).unwrap_err();
        assert!(matches!(err, TransformError::EyeAtTarget { eye } if eye == p), "{p}: {err:?}");
    }
    // Premise: glam's version gives NaN.
    assert!(cg_core::glam::camera::rh::view::look_at_mat4(Vec3::ONE, Vec3::ONE, Vec3::Y).is_nan());
    // Nearly equal (one ulp apart) is a valid camera; far-apart huge values do not overflow.
    let e = Vec3::new(1.0, 0.0, 0.0);
    let t = Vec3::new(f32::from_bits(1f32.to_bits() + 1), 0.0, 0.0);
    let m = look_at(e, t, Vec3::Y).unwrap();
    assert!(m.is_finite());
    let m = look_at(Vec3::new(-3e38, 0.0, 0.0), Vec3::new(3e38, 0.0, 0.0), Vec3::Y);
    assert!(
        matches!(m, Ok(m) if m.is_finite()) || matches!(m, Err(TransformError::Overflow { .. }))
    );
}

#[test]
fn row10_look_at_non_finite_input_is_an_error() {
    let bad = [Vec3::new(f32::NAN, 0.0, 0.0), Vec3::new(0.0, f32::INFINITY, 0.0)];
    for b in bad {
        for (eye, target, up) in
            [(b, Vec3::ZERO, Vec3::Y), (Vec3::Z, b, Vec3::Y), (Vec3::Z, Vec3::ZERO, b)]
        {
            assert!(
                matches!(look_at(eye, target, up), Err(TransformError::LookAtNotFinite { .. })),
                "{eye} {target} {up}"
            );
        }
    }
}
