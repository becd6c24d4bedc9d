//! The course's orbit camera and the GLUT-style mouse state, tested without a window.
//! docs/numerics.md row 10 (the orbit camera at and across pitch ±90°).
//!
//! Sign conventions are checked against the GL calls of the sample program:
//! `glTranslatef(0, 0, -camera_distance); glRotatef(-camera_pitch, 1, 0, 0);
//! glRotatef(-camera_yaw, 0, 1, 0);` and its `motion()`:
//! `camera_pitch -= (my - last_mouse_y) * 1.0;`.

use cg_core::camera::{CameraLimits, MouseButton, MouseState, OrbitCamera};
use cg_core::glam::{DMat4, DVec3, DVec4, Mat4, Vec3};
use cg_core::transform::{look_at, transform_point};
use cg_testkit::prop::log_uniform;
use cg_testkit::{Approx, assert_approx_eq};
use proptest::prelude::*;

fn config(cases: u32) -> ProptestConfig {
    cg_testkit::prop::config(cases, 0xca4e_0a10)
}

/// The view matrix from the GL calls, in f64 from the same f32 fields: rows of
/// T(0, 0, −d) · Rx(−pitch) · Ry(−yaw) · T(−target), written out by hand.
fn view_f64(c: &OrbitCamera) -> DMat4 {
    let (p, y) = (-f64::from(c.pitch_deg).to_radians(), -f64::from(c.yaw_deg).to_radians());
    let t = DMat4::from_cols(
        DVec4::X,
        DVec4::Y,
        DVec4::Z,
        DVec4::new(0.0, 0.0, -f64::from(c.distance), 1.0),
    );
    // Rows [1 0 0; 0 cos −sin; 0 sin cos] and [cos 0 sin; 0 1 0; −sin 0 cos], as columns.
    let rx = DMat4::from_cols(
        DVec4::X,
        DVec4::new(0.0, p.cos(), p.sin(), 0.0),
        DVec4::new(0.0, -p.sin(), p.cos(), 0.0),
        DVec4::W,
    );
    let ry = DMat4::from_cols(
        DVec4::new(y.cos(), 0.0, -y.sin(), 0.0),
        DVec4::Y,
        DVec4::new(y.sin(), 0.0, y.cos(), 0.0),
        DVec4::W,
    );
    let tt = DMat4::from_translation(-c.target.as_dvec3());
    t * rx * ry * tt
}

fn rotation_error(m: Mat4) -> f64 {
    let r = cg_core::glam::DMat3::from_mat4(m.as_dmat4());
    DMat4::from_mat3(r.transpose() * r)
        .max_abs_diff(&DMat4::IDENTITY)
        .max((r.determinant() - 1.0).abs())
}

#[test]
fn course_sample_is_the_sample_programs_start() {
    let c = OrbitCamera::course_sample();
    assert_eq!((c.yaw_deg, c.pitch_deg, c.distance, c.target), (0.0, -30.0, 15.0, Vec3::ZERO));
    assert_eq!(c.limits, CameraLimits::default());
    assert_eq!(OrbitCamera::default(), c);
}

#[test]
fn course_view_matrix_equals_translate_rotate_built_independently() {
    // T(0, 0, −15) · Rx(30°) by rows: [1 0 0 0; 0 c −s 0; 0 s c −15; 0 0 0 1], c = cos 30°,
    // s = sin 30° = 1/2.
    let (c, s) = (3f64.sqrt() / 2.0, 0.5);
    let expected = DMat4::from_cols(
        DVec4::X,
        DVec4::new(0.0, c, s, 0.0),
        DVec4::new(0.0, -s, c, 0.0),
        DVec4::new(0.0, 0.0, -15.0, 1.0),
    );
    let cam = OrbitCamera::course_sample();
    // Each entry is one correctly rounded f32 of its f64 value: half an ulp of 15 is 5e-7.
    assert_approx_eq!(cam.view_matrix(), expected.as_mat4(), abs = 1e-6);
    assert_eq!(cam.view_product().matrix().unwrap(), cam.view_matrix());
    // The object drawn after glTranslatef(0, 1, 0): its origin lands at (0, c, s − 15).
    let o = transform_point(cam.view_matrix(), Vec3::Y);
    assert_approx_eq!(o, Vec3::new(0.0, c as f32, (s - 15.0) as f32), abs = 1e-6);
}

#[test]
fn course_eye_is_above_and_in_front_of_the_target() {
    // Pitch −30° looks down from above: eye = (0, 15 sin 30°, 15 cos 30°).
    let eye = OrbitCamera::course_sample().eye_position();
    let want = DVec3::new(0.0, 15.0 * 0.5, 15.0 * 3f64.sqrt() / 2.0).as_vec3();
    assert_approx_eq!(eye, want, abs = 1e-6);
    // Yaw 90° swings the eye from +Z to +X (counter-clockwise seen from above).
    let c = OrbitCamera { yaw_deg: 90.0, pitch_deg: 0.0, ..OrbitCamera::course_sample() };
    assert_eq!(c.eye_position(), Vec3::new(15.0, 0.0, 0.0));
    // At pitch −90° the eye is straight above.
    let c = OrbitCamera { pitch_deg: -90.0, ..OrbitCamera::course_sample() };
    assert_eq!(c.eye_position(), Vec3::new(0.0, 15.0, 0.0));
}

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn view_matrix_matches_the_gl_calls_and_the_eye(
        yaw in 0.0f32..360.0,
        pitch in -180.0f32..180.0,
        distance in 0.1f32..1000.0,
        target in (log_uniform(-2.0, 3.0), log_uniform(-2.0, 3.0), log_uniform(-2.0, 3.0)),
    ) {
        let limits = CameraLimits { pitch_min_deg: -180.0, pitch_max_deg: 180.0, ..CameraLimits::default() };
        let c = OrbitCamera { yaw_deg: yaw, pitch_deg: pitch, distance, target: Vec3::new(target.0, target.1, target.2), limits };
        let v = c.view_matrix();
        // Entries are rounded f32 products of up to four factors: a few ulps of the largest
        // magnitude involved (distance + |target|).
        let scale = f64::from(distance) + c.target.as_dvec3().length();
        let tol = 8.0 * f64::from(f32::EPSILON) * scale.max(1.0);
        let d = v.as_dmat4().max_abs_diff(&view_f64(&c));
        prop_assert!(d <= tol, "view vs f64 oracle: {d:e} > {tol:e}");
        prop_assert!(rotation_error(v) <= 1e-6, "rotation part not orthonormal");
        let vp = c.view_product().matrix().unwrap();
        prop_assert!(vp.as_dmat4().max_abs_diff(&v.as_dmat4()) <= tol, "view_product ≠ view_matrix");
        // The eye is where the inverse view sends the origin (f64 inverse of the f64 oracle).
        let eye = view_f64(&c).inverse().transform_point3(DVec3::ZERO);
        let got = c.eye_position().as_dvec3();
        prop_assert!((got - eye).length() <= tol, "eye {got} vs {eye}");
        // And the view sends the eye to the origin and the target onto −Z at `distance`.
        let t = v.as_dmat4().transform_point3(c.target.as_dvec3());
        prop_assert!(t.truncate().length() <= tol, "target ↦ {t}");
        prop_assert!((t.z + f64::from(distance)).abs() <= tol, "target depth {}", t.z);
    }

    #[test]
    fn mouse_mapping_keeps_the_state_in_range(
        drags in proptest::collection::vec((any::<bool>(), log_uniform(-3.0, 12.0), log_uniform(-3.0, 12.0)), 1..40)
    ) {
        let mut c = OrbitCamera::course_sample();
        for (right, dx, dy) in drags {
            if right { c.right_drag(dx, dy) } else { c.left_drag(dx, dy) }
            prop_assert!((-90.0..=0.0).contains(&c.pitch_deg), "pitch {}", c.pitch_deg);
            prop_assert!((0.0..360.0).contains(&c.yaw_deg), "yaw {}", c.yaw_deg);
            prop_assert!(c.distance >= 2.0 && c.distance.is_finite(), "distance {}", c.distance);
        }
    }
}

#[test]
fn right_drag_follows_the_sample_motion() {
    let mut c = OrbitCamera::course_sample();
    // Dragging down by 10 px: camera_pitch −= 10 · 1.0.
    c.right_drag(0.0, 10.0);
    assert_eq!(c.pitch_deg, -40.0);
    c.right_drag(0.0, -25.0);
    assert_eq!(c.pitch_deg, -15.0);
    // Clamped to [−90, 0].
    c.right_drag(0.0, -100.0);
    assert_eq!(c.pitch_deg, 0.0);
    c.right_drag(0.0, 1000.0);
    assert_eq!(c.pitch_deg, -90.0);
    // Yaw: camera_yaw −= dx, wrapped to [0, 360).
    c.right_drag(10.0, 0.0);
    assert_eq!(c.yaw_deg, 350.0);
    c.right_drag(-370.0, 0.0);
    assert_eq!(c.yaw_deg, 0.0);
    c.right_drag(-725.0, 0.0);
    assert_eq!(c.yaw_deg, 5.0);
    // The bare sample has no yaw.
    let mut bare = OrbitCamera {
        limits: CameraLimits { yaw_enabled: false, ..CameraLimits::default() },
        ..OrbitCamera::course_sample()
    };
    bare.right_drag(50.0, 5.0);
    assert_eq!((bare.yaw_deg, bare.pitch_deg), (0.0, -35.0));
}

#[test]
fn left_drag_zooms_and_stops_at_the_minimum_distance() {
    let mut c = OrbitCamera::course_sample();
    c.left_drag(123.0, 10.0); // distance += 10 · 0.2; dx unused
    assert_approx_eq!(c.distance, 17.0, abs = 1e-6);
    c.left_drag(0.0, -1000.0);
    assert_eq!(c.distance, 2.0, "一定値以上は近づかないように制限");
    c.left_drag(0.0, 1e30);
    assert!(c.distance.is_finite() && c.distance > 1e28);
    assert_eq!((c.pitch_deg, c.yaw_deg), (-30.0, 0.0), "zoom does not rotate");
}

#[test]
fn non_finite_deltas_are_ignored() {
    let mut c = OrbitCamera::course_sample();
    let before = c;
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        c.right_drag(bad, bad);
        c.left_drag(bad, bad);
    }
    assert_eq!(c, before);
    // A finite delta whose product with the speed overflows is ignored too.
    let mut fast = OrbitCamera {
        limits: CameraLimits {
            rotate_deg_per_px: 1e30,
            zoom_per_px: 1e30,
            ..CameraLimits::default()
        },
        ..OrbitCamera::course_sample()
    };
    fast.right_drag(1e30, 1e30);
    fast.left_drag(0.0, 1e30);
    assert!(fast.yaw_deg.is_finite() && fast.pitch_deg.is_finite() && fast.distance.is_finite());
    // Odd limits (min > max) do not panic, unlike f32::clamp.
    let mut odd = OrbitCamera {
        limits: CameraLimits {
            pitch_min_deg: 10.0,
            pitch_max_deg: -10.0,
            ..CameraLimits::default()
        },
        ..OrbitCamera::course_sample()
    };
    odd.right_drag(0.0, 1.0);
    assert!(odd.pitch_deg.is_finite());
}

#[test]
fn mouse_state_mirrors_the_glut_callbacks() {
    let mut cam = OrbitCamera::course_sample();
    let mut mouse = MouseState::new();
    // Moving without a button does nothing to the camera but tracks the pointer.
    mouse.motion(100.0, 100.0, &mut cam);
    assert_eq!(cam, OrbitCamera::course_sample());
    // Right button down at (100, 100), drag to (90, 110): pitch −= 10, yaw −= −10.
    mouse.mouse(MouseButton::Right, true, 100.0, 100.0);
    mouse.motion(90.0, 110.0, &mut cam);
    assert_eq!((cam.pitch_deg, cam.yaw_deg), (-40.0, 10.0));
    // The drag is measured from the last position, not the press.
    mouse.motion(90.0, 115.0, &mut cam);
    assert_eq!(cam.pitch_deg, -45.0);
    mouse.mouse(MouseButton::Right, false, 90.0, 115.0);
    mouse.motion(0.0, 0.0, &mut cam);
    assert_eq!(cam.pitch_deg, -45.0, "released: no rotation");
    // Left button: zoom by dy · 0.2 from where it was pressed.
    mouse.mouse(MouseButton::Left, true, 50.0, 50.0);
    mouse.motion(80.0, 60.0, &mut cam);
    assert_approx_eq!(cam.distance, 17.0, abs = 1e-6);
    assert_eq!(cam.pitch_deg, -45.0, "left-drag does not rotate");
    // Both buttons: both effects, like the sample's two independent `if`s.
    mouse.mouse(MouseButton::Right, true, 80.0, 60.0);
    mouse.motion(80.0, 65.0, &mut cam);
    assert_eq!(cam.pitch_deg, -50.0);
    assert_approx_eq!(cam.distance, 18.0, abs = 1e-6);
    // The middle button is tracked but moves nothing.
    let mut other = MouseState::new();
    other.mouse(MouseButton::Middle, true, 0.0, 0.0);
    let before = cam;
    other.motion(10.0, 10.0, &mut cam);
    assert!(other.drag_mouse_m);
    assert_eq!(cam, before);
    // A non-finite pointer position is ignored entirely.
    mouse.motion(f32::NAN, 1e6, &mut cam);
    assert_eq!((mouse.last_mouse_x, mouse.last_mouse_y), (80.0, 65.0));
    assert_eq!(cam.pitch_deg, -50.0);
}

// ---------------------------------------------------------------------------------------------
// docs/numerics.md row 10: orbit camera at pitch ±90°, and across the pole.

fn wide(pitch: f32) -> OrbitCamera {
    OrbitCamera {
        pitch_deg: pitch,
        limits: CameraLimits {
            pitch_min_deg: -180.0,
            pitch_max_deg: 180.0,
            ..CameraLimits::default()
        },
        ..OrbitCamera::course_sample()
    }
}

#[test]
fn row10_orbit_camera_at_pitch_plus_minus_90_is_finite_and_orthonormal() {
    for (pitch, s) in [(-90.0f32, 1.0f32), (90.0, -1.0)] {
        for yaw in [0.0f32, 45.0, 90.0, 271.5] {
            let c = OrbitCamera { yaw_deg: yaw, ..wide(pitch) };
            let v = c.view_matrix();
            assert!(v.is_finite(), "pitch {pitch}, yaw {yaw}: {v}");
            assert!(rotation_error(v) <= 1e-6, "pitch {pitch}, yaw {yaw}: not orthonormal");
            // Exact oracle: at pitch ∓90° (s = ±1) the view is T(0, 0, −15) · Rx(±90°), rows
            // [1 0 0 0; 0 0 −s 0; 0 s 0 −15; 0 0 0 1].
            if yaw == 0.0 {
                let want = Mat4::from_cols_array(&[
                    1., 0., 0., 0., 0., 0., s, 0., 0., -s, 0., 0., 0., 0., -15., 1.,
                ]);
                assert_eq!(v, want, "pitch {pitch}");
                assert_eq!(c.eye_position(), Vec3::new(0.0, 15.0 * s, 0.0));
            }
            assert_approx_eq!(
                transform_point(v, c.eye_position()),
                Vec3::ZERO,
                abs = 4e-6,
                "the eye maps to the origin"
            );
        }
    }
}

#[test]
fn row10_orbit_camera_crosses_the_pole_without_roll_flip() {
    // Sweep pitch from −80° to −100° in 0.01° steps. A rotation by δ changes each entry by at most
    // δ (in radians); the translation column (0, 0, −15) does not change. Rounding adds ≤ 1e-6.
    let step = 0.01f32;
    let bound = f64::from(step).to_radians() + 1e-6;
    let n = 2000;
    let mut prev = wide(-80.0).view_matrix();
    for i in 1..=n {
        let pitch = -80.0 - step * i as f32;
        let v = wide(pitch).view_matrix();
        let d = v.as_dmat4().max_abs_diff(&prev.as_dmat4());
        assert!(d <= bound, "jump of {d} at pitch {pitch}");
        prev = v;
    }

    // Premise: a look-at camera with a fixed up = +Y flips its roll by 180° across the pole
    // (and fails at it), so a look-at-based orbit camera would fail the test above.
    let eye = |p: f32| wide(p).eye_position();
    let a = look_at(eye(-89.9), Vec3::ZERO, Vec3::Y).unwrap();
    let b = look_at(eye(-90.1), Vec3::ZERO, Vec3::Y).unwrap();
    assert!(
        a.as_dmat4().max_abs_diff(&b.as_dmat4()) > 1.0,
        "premise: look_at flips across the pole"
    );
    assert!(look_at(eye(-90.0), Vec3::ZERO, Vec3::Y).is_err(), "and has no answer on it");
}
