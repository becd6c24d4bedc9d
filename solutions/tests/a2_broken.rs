//! Assignment a2: deliberately broken answers of the kinds students hand in, each the reference
//! answer with one realistic bug. Each test asserts which checks fail for it (exactly), that
//! their messages say what, where and why in both languages, and that every check of the
//! assignment fails for at least one of them.

// The assignment crates, through the kit's one list (cg-assign).
use cg_assign::cg_a2;

use std::collections::BTreeSet;

use cg_a2::SpecExt as _;
use cg_a2::{CameraState, Drag, DragAxis, Impl, LIGHT0_POSITION, MouseButton, Operation, Spec};
use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::product::Factor;
use cg_harness::check::Outcome;
use cg_harness::{CheckResult, StudentNumber, TableVersion, VariantRng};
use cg_student::gl::Gl;

mod common;

/// A student with every kind of check: a pan, the pitch range [−90, 90] (both poles), yaw
/// 1.5°/px, pitch 2°/px, distance on Shift + left dx, rotate on the left button.
const STUDENT: &str = "20260021";

fn spec() -> Spec {
    spec_of(STUDENT)
}

fn spec_of(student: &str) -> Spec {
    let n: StudentNumber = student.parse().unwrap();
    cg_a2::variant(&mut VariantRng::new(&n, TableVersion::V1, cg_a2::ID))
}

// The bugs, one per broken answer. 0 is none: that answer must pass everything (so each broken
// answer differs from a correct one by its bug alone).
const NONE: u8 = 0;
const RADIANS: u8 = 1; // the angle changes converted with to_radians
const PITCH_SIGN: u8 = 2; // camera_pitch += instead of -= (drag up moves the wrong way)
const NO_CLAMP: u8 = 3; // camera_pitch never clamped
const NO_WRAP: u8 = 4; // camera_yaw grows past 360
const PERCENT_WRAP: u8 = 5; // camera_yaw % 360.0: negative values stay negative
const DISTANCE_WRONG_BUTTON: u8 = 6; // distance on a button the spec does not use
const COURSE_SPEED: u8 = 7; // yaw at the course's 1°/px instead of the spec's
const IGNORES_SHIFT: u8 = 8; // only the button compared, not Shift
const ELSE_IF: u8 = 9; // a diagonal drag changes only one of yaw and pitch
const ONLY_LOWER_LIMIT: u8 = 10; // distance limited only from below (一定値以上は近づかない)
const PAN_SIGN: u8 = 11; // target_x the wrong way
const PAN_NO_CLAMP: u8 = 12; // the target leaves the ground
const DISTANCE_UNREACHABLE: u8 = 13; // distance in an `else if` after a block taking its button

/// The reference's motion(), written the way students do (a block per variable), with `BUG`.
fn motion_with<const BUG: u8>(spec: &Spec, s: &mut CameraState, drag: &Drag) {
    let matches = |op: &Operation| {
        drag.button == op.gesture.button && (BUG == IGNORES_SHIFT || drag.shift == op.gesture.shift)
    };
    let pixels = |op: &Operation| match op.axis {
        DragAxis::Horizontal => drag.dx,
        DragAxis::Vertical => drag.dy,
    };
    let angle = |x: f32| if BUG == RADIANS { x.to_radians() } else { x };
    let mut yaw_changed = false;
    if matches(&spec.yaw) && pixels(&spec.yaw) != 0.0 {
        let speed = if BUG == COURSE_SPEED { spec.yaw.per_px.signum() } else { spec.yaw.per_px };
        let yaw = s.camera_yaw + angle(speed * pixels(&spec.yaw));
        s.camera_yaw = match BUG {
            NO_WRAP => yaw,
            PERCENT_WRAP => yaw % 360.0,
            _ => yaw.rem_euclid(360.0),
        };
        yaw_changed = true;
    }
    if matches(&spec.pitch) && !(BUG == ELSE_IF && yaw_changed) {
        let change = angle(spec.pitch.per_px * pixels(&spec.pitch));
        let pitch =
            if BUG == PITCH_SIGN { s.camera_pitch - change } else { s.camera_pitch + change };
        s.camera_pitch =
            if BUG == NO_CLAMP { pitch } else { pitch.clamp(spec.pitch_min, spec.pitch_max) };
    }
    let distance_drag = if BUG == DISTANCE_WRONG_BUTTON {
        // The first button (with or without Shift) that the spec leaves free.
        let used: Vec<_> =
            [Some(spec.yaw.gesture), Some(spec.distance.gesture), spec.pan.map(|p| p.x.gesture)]
                .into_iter()
                .flatten()
                .collect();
        let free = [MouseButton::Left, MouseButton::Middle, MouseButton::Right]
            .into_iter()
            .flat_map(|button| [false, true].map(|shift| cg_a2::Gesture { button, shift }))
            .find(|g| !used.contains(g))
            .unwrap();
        drag.button == free.button && drag.shift == free.shift
    } else if BUG == DISTANCE_UNREACHABLE {
        // `if drag.button == Left { … } else if drag.button == Left && drag.shift { distance }`:
        // the first block takes every drag of the rotation's button, Shift or not.
        matches(&spec.distance) && drag.button != spec.yaw.gesture.button
    } else {
        matches(&spec.distance)
    };
    if distance_drag {
        let d = s.camera_distance + spec.distance.per_px * pixels(&spec.distance);
        s.camera_distance = if BUG == ONLY_LOWER_LIMIT {
            d.max(spec.distance_min)
        } else {
            d.clamp(spec.distance_min, spec.distance_max)
        };
    }
    if let Some(pan) = spec.pan {
        let limit = |v: f32| if BUG == PAN_NO_CLAMP { v } else { v.clamp(-pan.limit, pan.limit) };
        if matches(&pan.x) {
            let sign = if BUG == PAN_SIGN { -1.0 } else { 1.0 };
            s.target_x = limit(s.target_x + sign * pan.x.per_px * pixels(&pan.x));
        }
        if matches(&pan.z) {
            s.target_z = limit(s.target_z + pan.z.per_px * pixels(&pan.z));
        }
    }
}

const CAMERA_RADIANS: u8 = 21; // glRotatef given radians
const CAMERA_ORDER: u8 = 22; // Ry before Rx
const CAMERA_TRANSLATE_LAST: u8 = 23; // the distance after the rotations
const CAMERA_PITCH_SIGN: u8 = 24; // Rx(+camera_pitch)
const CAMERA_LOOK_AT: u8 = 25; // a look-at with up = +Y (undefined at the poles)
const CAMERA_NO_TARGET: u8 = 26; // the target's translation forgotten
const CAMERA_TRANSPOSED: u8 = 27; // the view matrix written row by row into glam's Mat4

/// The reference's camera() with `BUG`.
fn camera_with<const BUG: u8>(gl: &mut Gl, s: &CameraState) {
    let angle = |x: f32| if BUG == CAMERA_RADIANS { x.to_radians() } else { x };
    match BUG {
        CAMERA_TRANSPOSED => {
            use cg_core::glam::Mat4;
            let v = Mat4::from_translation(Vec3::new(0.0, 0.0, -s.camera_distance))
                * Mat4::from_rotation_x((-s.camera_pitch).to_radians())
                * Mat4::from_rotation_y((-s.camera_yaw).to_radians())
                * Mat4::from_translation(Vec3::new(-s.target_x, 0.0, -s.target_z));
            gl.mult(Factor::named("V", v.transpose()).into());
        }
        CAMERA_LOOK_AT => {
            let target = Vec3::new(s.target_x, 0.0, s.target_z);
            let (sp, cp) = s.camera_pitch.to_radians().sin_cos();
            let (sy, cy) = s.camera_yaw.to_radians().sin_cos();
            let eye = target + s.camera_distance * Vec3::new(cp * sy, -sp, cp * cy);
            let view = cg_core::transform::look_at(eye, target, Vec3::Y).unwrap();
            gl.mult(Factor::named("LookAt", view).into());
        }
        CAMERA_TRANSLATE_LAST => {
            gl.rotate(-s.camera_pitch, 1.0, 0.0, 0.0);
            gl.rotate(-s.camera_yaw, 0.0, 1.0, 0.0);
            gl.translate(0.0, 0.0, -s.camera_distance);
            gl.translate(-s.target_x, 0.0, -s.target_z);
        }
        CAMERA_ORDER => {
            gl.translate(0.0, 0.0, -s.camera_distance);
            gl.rotate(-s.camera_yaw, 0.0, 1.0, 0.0);
            gl.rotate(-s.camera_pitch, 1.0, 0.0, 0.0);
            gl.translate(-s.target_x, 0.0, -s.target_z);
        }
        _ => {
            gl.translate(0.0, 0.0, -s.camera_distance);
            let pitch = if BUG == CAMERA_PITCH_SIGN { s.camera_pitch } else { -s.camera_pitch };
            gl.rotate(angle(pitch), 1.0, 0.0, 0.0);
            gl.rotate(angle(-s.camera_yaw), 0.0, 1.0, 0.0);
            if BUG != CAMERA_NO_TARGET {
                gl.translate(-s.target_x, 0.0, -s.target_z);
            }
        }
    }
}

const LIGHT_BEFORE_CAMERA: u8 = 31; // the classic mistake
const OBJECTS_BEFORE_CAMERA: u8 = 32; // drawn, then the camera
const NO_LOAD_IDENTITY: u8 = 33; // the view piles up frame after frame
const PUSH_WITHOUT_POP: u8 = 34; // a push left on the stack
const NO_CAMERA: u8 = 35; // camera() never called from display()

/// The reference's display() calling the camera() with bug `CAMERA` (a student's display calls
/// their own camera).
fn display_calling<const CAMERA: u8>(gl: &mut Gl, s: &CameraState) {
    gl.load_identity();
    camera_with::<CAMERA>(gl, s);
    gl.light_position(0, LIGHT0_POSITION);
    cg_student::a2::draw_course_objects(gl);
}

/// The reference's display() with `BUG`.
fn display_with<const BUG: u8>(gl: &mut Gl, s: &CameraState) {
    let camera = cg_solutions::a2::camera;
    if BUG != NO_LOAD_IDENTITY {
        gl.load_identity();
    }
    if BUG == PUSH_WITHOUT_POP {
        gl.push_matrix();
    }
    match BUG {
        LIGHT_BEFORE_CAMERA => {
            gl.light_position(0, LIGHT0_POSITION);
            camera(gl, s);
            cg_student::a2::draw_course_objects(gl);
        }
        OBJECTS_BEFORE_CAMERA => {
            cg_student::a2::draw_course_objects(gl);
            camera(gl, s);
            gl.light_position(0, LIGHT0_POSITION);
        }
        _ => {
            if BUG != NO_CAMERA {
                camera(gl, s);
            }
            gl.light_position(0, LIGHT0_POSITION);
            cg_student::a2::draw_course_objects(gl);
        }
    }
}

fn reference() -> Impl {
    cg_solutions::a2::implementation()
}

/// The broken answers: name, the answer, the checks that must fail (exactly these).
fn broken() -> Vec<(&'static str, Impl, Vec<&'static str>)> {
    let m = |motion: fn(&Spec, &mut CameraState, &Drag)| Impl { motion, ..reference() };
    let c = |camera: fn(&mut Gl, &CameraState), display: fn(&mut Gl, &CameraState)| Impl {
        camera,
        display,
        ..reference()
    };
    let d = |display: fn(&mut Gl, &CameraState)| Impl { display, ..reference() };
    // A wrong camera, called by the student's display(), also moves the light and the objects
    // away from the spec's V: the display checks compare with the spec's view (and say "fix
    // a2.t2 first").
    let camera_and_display = |checks: &[&'static str]| {
        let mut v = checks.to_vec();
        v.extend(["a2.t3.light", "a2.t3.objects"]);
        v
    };
    vec![
        (
            "radians for degrees in motion()",
            m(motion_with::<RADIANS>),
            vec!["a2.t1.yaw", "a2.t1.pitch", "a2.t1.wrap", "a2.t1.pitch_range", "a2.t1.sequence"],
        ),
        (
            "pitch the wrong way",
            m(motion_with::<PITCH_SIGN>),
            vec!["a2.t1.pitch", "a2.t1.pitch_range", "a2.t1.sequence"],
        ),
        ("no pitch clamp", m(motion_with::<NO_CLAMP>), vec!["a2.t1.pitch_range", "a2.t1.sequence"]),
        ("no yaw wrap", m(motion_with::<NO_WRAP>), vec!["a2.t1.wrap", "a2.t1.sequence"]),
        (
            "yaw wrapped with %",
            m(motion_with::<PERCENT_WRAP>),
            vec!["a2.t1.wrap", "a2.t1.sequence"],
        ),
        (
            "distance on the wrong button",
            m(motion_with::<DISTANCE_WRONG_BUTTON>),
            vec!["a2.t1.distance", "a2.t1.buttons", "a2.t1.distance_range", "a2.t1.sequence"],
        ),
        (
            "yaw at the course's speed",
            m(motion_with::<COURSE_SPEED>),
            vec!["a2.t1.yaw", "a2.t1.wrap", "a2.t1.sequence"],
        ),
        ("Shift ignored", m(motion_with::<IGNORES_SHIFT>), vec!["a2.t1.buttons", "a2.t1.sequence"]),
        ("else-if for a diagonal drag", m(motion_with::<ELSE_IF>), vec!["a2.t1.sequence"]),
        (
            "distance limited only from below",
            m(motion_with::<ONLY_LOWER_LIMIT>),
            vec!["a2.t1.distance_range", "a2.t1.sequence"],
        ),
        (
            "target_x the wrong way",
            m(motion_with::<PAN_SIGN>),
            vec!["a2.t1.pan", "a2.t1.pan_range", "a2.t1.sequence"],
        ),
        (
            "no target clamp",
            m(motion_with::<PAN_NO_CLAMP>),
            vec!["a2.t1.pan_range", "a2.t1.sequence"],
        ),
        (
            "distance behind an else-if that never comes",
            m(motion_with::<DISTANCE_UNREACHABLE>),
            vec!["a2.t1.distance", "a2.t1.distance_range", "a2.t1.sequence"],
        ),
        (
            "the view matrix transposed",
            c(camera_with::<CAMERA_TRANSPOSED>, display_calling::<CAMERA_TRANSPOSED>),
            camera_and_display(&["a2.t2.view", "a2.t2.pole"]),
        ),
        (
            "glRotatef given radians",
            c(camera_with::<CAMERA_RADIANS>, display_calling::<CAMERA_RADIANS>),
            camera_and_display(&["a2.t2.view", "a2.t2.pole"]),
        ),
        (
            "rotations in the wrong order",
            c(camera_with::<CAMERA_ORDER>, display_calling::<CAMERA_ORDER>),
            camera_and_display(&["a2.t2.view", "a2.t2.pole"]),
        ),
        (
            "translation after the rotations",
            c(camera_with::<CAMERA_TRANSLATE_LAST>, display_calling::<CAMERA_TRANSLATE_LAST>),
            camera_and_display(&["a2.t2.view", "a2.t2.pole"]),
        ),
        (
            "pitch rotation with the wrong sign",
            c(camera_with::<CAMERA_PITCH_SIGN>, display_calling::<CAMERA_PITCH_SIGN>),
            camera_and_display(&["a2.t2.view", "a2.t2.pole"]),
        ),
        (
            "a look-at with up = +Y",
            c(camera_with::<CAMERA_LOOK_AT>, display_calling::<CAMERA_LOOK_AT>),
            vec!["a2.t2.pole"],
        ),
        (
            "the target forgotten",
            c(camera_with::<CAMERA_NO_TARGET>, display_calling::<CAMERA_NO_TARGET>),
            camera_and_display(&["a2.t2.view", "a2.t2.pole"]),
        ),
        (
            "the light set before the camera",
            d(display_with::<LIGHT_BEFORE_CAMERA>),
            vec!["a2.t3.light"],
        ),
        (
            "objects drawn before the camera",
            d(display_with::<OBJECTS_BEFORE_CAMERA>),
            vec!["a2.t3.objects"],
        ),
        ("no glLoadIdentity", d(display_with::<NO_LOAD_IDENTITY>), vec!["a2.t3.identity"]),
        ("a push without its pop", d(display_with::<PUSH_WITHOUT_POP>), vec!["a2.t3.stack"]),
        ("camera() not called", d(display_with::<NO_CAMERA>), vec!["a2.t3.light", "a2.t3.objects"]),
    ]
}

fn failing(results: &[CheckResult]) -> BTreeSet<&str> {
    results.iter().filter(|r| !r.passed()).map(|r| r.id.as_str()).collect()
}

#[test]
fn the_student_has_every_kind_of_check() {
    let spec = spec();
    assert!(spec.pan.is_some());
    assert_eq!((spec.pitch_min, spec.pitch_max), (-90.0, 90.0));
    assert!(spec.yaw.per_px.abs() != 1.0, "COURSE_SPEED must differ from the spec");
    assert!(spec.distance.gesture.shift, "IGNORES_SHIFT needs a Shift gesture");
    assert_eq!(spec.distance.gesture.button, spec.yaw.gesture.button);
}

#[test]
fn the_bug_free_versions_pass_everything() {
    let spec = spec();
    let clean = Impl {
        motion: motion_with::<NONE>,
        camera: camera_with::<NONE>,
        display: display_with::<NONE>,
    };
    assert!(failing(&cg_a2::checks(&spec, &clean)).is_empty());
}

#[test]
fn each_broken_answer_fails_exactly_its_checks_and_says_why() {
    let spec = spec();
    let all: BTreeSet<String> =
        cg_a2::checks(&spec, &reference()).into_iter().map(|r| r.id).collect();
    let mut caught = BTreeSet::new();
    for (name, imp, expected) in broken() {
        let results = cg_a2::checks(&spec, &imp);
        let failed = failing(&results);
        let expected: BTreeSet<&str> = expected.into_iter().collect();
        assert_eq!(failed, expected, "{name}");
        for r in results.iter().filter(|r| !r.passed()) {
            caught.insert(r.id.clone());
            match &r.outcome {
                Outcome::Fail(f) => {
                    assert!(!f.expected.is_empty() && !f.actual.is_empty(), "{name}: {}", r.id);
                    assert!(f.location.as_ref().is_some_and(|l| !l.is_empty()), "{name}: {}", r.id);
                    for text in [&f.cause, &f.hint] {
                        assert!(
                            !text.ja.is_empty() && !text.en.is_empty(),
                            "{name}: {}: {f:?}",
                            r.id
                        );
                    }
                }
                // A look-at with an up vector fails at the pole: `look_at(..).unwrap()` panics.
                Outcome::Panicked { .. } => assert_eq!(r.id, "a2.t2.pole", "{name}"),
                other => panic!("{name}: {} is {other:?}", r.id),
            }
        }
    }
    let missed: Vec<&String> = all.iter().filter(|id| !caught.contains(*id)).collect();
    assert!(missed.is_empty(), "no broken answer fails {missed:?}");
}

/// The cause a check gives for a broken answer, in English.
fn cause(imp: &Impl, id: &str) -> String {
    let results = cg_a2::checks(&spec(), imp);
    let r = results.iter().find(|r| r.id == id).unwrap();
    match &r.outcome {
        Outcome::Fail(f) => format!(
            "{} | {} | {} | {}",
            f.cause.en,
            f.expected,
            f.actual,
            f.location.clone().unwrap_or_default()
        ),
        other => panic!("{id}: {other:?}"),
    }
}

#[test]
fn the_causes_name_the_mistake() {
    let cases: Vec<(Impl, &str, &str)> = vec![
        (Impl { motion: motion_with::<RADIANS>, ..reference() }, "a2.t1.yaw", "radians"),
        (
            Impl { motion: motion_with::<PITCH_SIGN>, ..reference() },
            "a2.t1.pitch",
            "wrong way (sign)",
        ),
        (
            Impl { motion: motion_with::<COURSE_SPEED>, ..reference() },
            "a2.t1.yaw",
            "by 1 per pixel instead of 1.5",
        ),
        (Impl { motion: motion_with::<NO_CLAMP>, ..reference() }, "a2.t1.pitch_range", "(the pole"),
        (
            Impl { motion: motion_with::<NO_CLAMP>, ..reference() },
            "a2.t1.pitch_range",
            "leaves its range",
        ),
        (
            Impl { motion: motion_with::<NO_WRAP>, ..reference() },
            "a2.t1.wrap",
            "360 and more are not wrapped",
        ),
        (
            Impl { motion: motion_with::<PERCENT_WRAP>, ..reference() },
            "a2.t1.wrap",
            "keeps the sign",
        ),
        (
            Impl { motion: motion_with::<DISTANCE_WRONG_BUTTON>, ..reference() },
            "a2.t1.distance",
            "instead of the Shift + left button",
        ),
        (
            Impl { motion: motion_with::<DISTANCE_WRONG_BUTTON>, ..reference() },
            "a2.t1.buttons",
            "the wrong button",
        ),
        (
            Impl { motion: motion_with::<IGNORES_SHIFT>, ..reference() },
            "a2.t1.buttons",
            "Shift is not tested",
        ),
        (
            Impl { motion: motion_with::<DISTANCE_WRONG_BUTTON>, ..reference() },
            "a2.t1.buttons",
            "camera_distance stays 15 (this drag changes nothing)",
        ),
        (
            Impl { motion: motion_with::<DISTANCE_UNREACHABLE>, ..reference() },
            "a2.t1.distance",
            "camera_distance does not change with any drag: motion() never changes it (is the code for it behind an else if",
        ),
        (Impl { motion: motion_with::<ELSE_IF>, ..reference() }, "a2.t1.sequence", "else-if"),
        (Impl { motion: motion_with::<NO_WRAP>, ..reference() }, "a2.t1.sequence", "not wrapped"),
        (
            Impl { motion: motion_with::<NO_CLAMP>, ..reference() },
            "a2.t1.sequence",
            "camera_pitch leaves its range",
        ),
        (
            Impl { motion: motion_with::<ONLY_LOWER_LIMIT>, ..reference() },
            "a2.t1.distance_range",
            "leaves its range",
        ),
        (
            Impl { motion: motion_with::<PAN_SIGN>, ..reference() },
            "a2.t1.pan",
            "target_x changes the wrong way",
        ),
        (
            Impl {
                camera: camera_with::<CAMERA_RADIANS>,
                display: display_calling::<CAMERA_RADIANS>,
                ..reference()
            },
            "a2.t2.view",
            "radians",
        ),
        (
            Impl {
                camera: camera_with::<CAMERA_ORDER>,
                display: display_calling::<CAMERA_ORDER>,
                ..reference()
            },
            "a2.t2.view",
            "wrong order",
        ),
        (
            Impl {
                camera: camera_with::<CAMERA_ORDER>,
                display: display_calling::<CAMERA_ORDER>,
                ..reference()
            },
            "a2.t2.view",
            "builds T(0, 0, -camera_distance) · Ry(-camera_yaw) · Rx(-camera_pitch)",
        ),
        (
            Impl {
                camera: camera_with::<CAMERA_TRANSLATE_LAST>,
                display: display_calling::<CAMERA_TRANSLATE_LAST>,
                ..reference()
            },
            "a2.t2.view",
            "comes after (right of) the rotations",
        ),
        (
            Impl {
                camera: camera_with::<CAMERA_PITCH_SIGN>,
                display: display_calling::<CAMERA_PITCH_SIGN>,
                ..reference()
            },
            "a2.t2.view",
            "camera_pitch rotation is flipped",
        ),
        (
            Impl {
                camera: camera_with::<CAMERA_NO_TARGET>,
                display: display_calling::<CAMERA_NO_TARGET>,
                ..reference()
            },
            "a2.t2.view",
            "translation T(-target_x, 0, -target_z) is missing",
        ),
        (
            Impl {
                camera: camera_with::<CAMERA_ORDER>,
                display: display_calling::<CAMERA_ORDER>,
                ..reference()
            },
            "a2.t3.light",
            "fix a2.t2 first",
        ),
        (
            Impl {
                camera: camera_with::<CAMERA_TRANSPOSED>,
                display: display_calling::<CAMERA_TRANSPOSED>,
                ..reference()
            },
            "a2.t2.view",
            "the matrix is transposed: the translation is in the bottom row",
        ),
        (
            Impl { display: display_with::<LIGHT_BEFORE_CAMERA>, ..reference() },
            "a2.t3.light",
            "set before the camera",
        ),
        (
            Impl { display: display_with::<LIGHT_BEFORE_CAMERA>, ..reference() },
            "a2.t3.light",
            "model-view matrix was I",
        ),
        (
            Impl { display: display_with::<OBJECTS_BEFORE_CAMERA>, ..reference() },
            "a2.t3.objects",
            "without the view transform",
        ),
        (
            Impl { display: display_with::<NO_LOAD_IDENTITY>, ..reference() },
            "a2.t3.identity",
            "gl.load_identity()",
        ),
        (
            Impl { display: display_with::<PUSH_WITHOUT_POP>, ..reference() },
            "a2.t3.stack",
            "a push without its pop",
        ),
    ];
    for (imp, id, needle) in cases {
        let text = cause(&imp, id);
        assert!(text.contains(needle), "{id}: {needle:?} not in {text:?}");
    }
}

/// A transposed view matrix is named as such, and no eye is computed from it: its bottom row is
/// said instead (it read "eye at (0, 0, 0)" and "the rotation part is off").
#[test]
fn a_transposed_view_shows_its_bottom_row_not_an_eye() {
    let imp = Impl {
        camera: camera_with::<CAMERA_TRANSPOSED>,
        display: display_calling::<CAMERA_TRANSPOSED>,
        ..reference()
    };
    let text = cause(&imp, "a2.t2.view");
    let actual = text.split(" | ").nth(2).unwrap();
    assert!(!actual.contains("eye at"), "{actual}");
    assert!(actual.contains("bottom row ("), "{actual}");
    assert!(actual.contains("not (0, 0, 0, 1)"), "{actual}");
}

/// The product a2.t2.view shows is the student's at the state its "where" names: camera_pitch
/// in radians shows that state's radians (0.5236 for −30°), not a hidden probe state's
/// (0.4014 for −23°), with the report's names where they apply.
#[test]
fn the_shown_product_is_at_the_state_named_in_where() {
    let imp = Impl {
        camera: camera_with::<CAMERA_RADIANS>,
        display: display_calling::<CAMERA_RADIANS>,
        ..reference()
    };
    let text = cause(&imp, "a2.t2.view");
    let (actual, location) = (text.split(" | ").nth(2).unwrap(), text.split(" | ").nth(3).unwrap());
    // The first state is the spec's start.
    let s = spec().start;
    assert!(location.starts_with("state 1 of "), "{location}");
    let radians = |deg: f32| cg_core::product::format_number(deg.to_radians());
    let pitch = format!("Rx({}°)", radians(-s.camera_pitch));
    assert!(actual.contains(&pitch), "{pitch} not in {actual}");
    assert!(
        actual.contains("at this state your camera() builds T(0, 0, -camera_distance) · "),
        "{actual}"
    );
    assert!(!actual.contains("0.4014") && !actual.contains("0.6458"), "{actual}");
}

/// A panic in the student's function during a check names the call and its input (the state
/// and the drag), as every ✗ line says where, and keeps the panic's place.
#[test]
fn a_panic_in_a_check_names_the_input() {
    fn too_far(spec: &Spec, s: &mut CameraState, drag: &Drag) {
        assert!(drag.dx.abs() < 10.0, "too far: {}", drag.dx);
        motion_with::<NONE>(spec, s, drag);
    }
    let results = cg_a2::checks(&spec(), &Impl { motion: too_far, ..reference() });
    let yaw = results.iter().find(|r| r.id == "a2.t1.yaw").unwrap();
    let Outcome::Panicked { message, location } = &yaw.outcome else { panic!("{:?}", yaw.outcome) };
    assert!(message.starts_with("too far: "), "{message}");
    assert!(
        message.contains(" ← motion(spec, &mut CameraState { camera_yaw: 100.0, "),
        "{message}"
    );
    assert!(message.contains(", &Drag { button: "), "{message}");
    assert!(location.as_deref().is_some_and(|l| l.contains("a2_broken.rs:")), "{location:?}");
    // The camera's too: a look-at at the pole.
    let look_at = Impl {
        camera: camera_with::<CAMERA_LOOK_AT>,
        display: display_calling::<CAMERA_LOOK_AT>,
        ..reference()
    };
    let results = cg_a2::checks(&spec(), &look_at);
    let pole = results.iter().find(|r| r.id == "a2.t2.pole").unwrap();
    let Outcome::Panicked { message, .. } = &pole.outcome else { panic!("{:?}", pole.outcome) };
    assert!(
        message.contains(" ← camera(gl, &CameraState { camera_yaw: 0.0, camera_pitch: -90.0"),
        "{message}"
    );
}

/// The identifiers that are plain words and that the Japanese report and assignment text
/// really use, as code: the student's functions and their parameters (`motion(spec, state,
/// drag)`, `camera(gl, state)`, `display()`), Rust's `else`, the `Shift` key, and `glam` (the
/// math library whose `Mat4` the students' code uses). (Identifiers
/// shaped like code — `camera_pitch`, `gl.translate`, `GL_LIGHT0` — need no listing; see
/// `common::english_words`.)
const CODE_WORDS: &[&str] =
    &["motion", "spec", "state", "drag", "camera", "display", "else", "Shift", "glam"];

/// Students of other layouts (Middle and Right buttons, no pan, other ranges), for the texts
/// that depend on the spec.
const MORE_STUDENTS: [&str; 4] = ["20260001", "20260002", "20260005", "20260013"];

#[test]
fn reports_read_in_one_language() {
    let mut problems = Vec::new();
    for student in std::iter::once(STUDENT).chain(MORE_STUDENTS) {
        let spec = spec_of(student);
        let answers = std::iter::once(("the stubs", cg_exercises::a2::implementation()))
            .chain(broken().into_iter().map(|(name, imp, _)| (name, imp)));
        for (name, imp) in answers {
            let report = cg_harness::check::Report {
                assignment: cg_a2::ID.into(),
                student: Some(student.into()),
                checks: cg_a2::checks(&spec, &imp),
            };
            let context = format!("{name} / {student}");
            problems.extend(common::report_problems(&context, &report, CODE_WORDS));
            // The stubs' view is "not done yet" (a stub's panic), no words of its own.
            if let Ok(Err(why)) = cg_harness::check::guarded(|| cg_a2::view(&spec, &imp, 0.0)) {
                problems.extend(common::language_problems(
                    &format!("view: {context}"),
                    &why.ja,
                    &why.en,
                    CODE_WORDS,
                ));
            }
        }
        problems.extend(common::language_problems(
            &format!("describe / {student}"),
            &spec.describe(Lang::Ja),
            &spec.describe(Lang::En),
            CODE_WORDS,
        ));
    }
    common::assert_no_problems(&problems);
}
