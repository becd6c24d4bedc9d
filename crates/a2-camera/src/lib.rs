//! Assignment `a2` — 視点操作インターフェースの拡張 (camera interface).
//!
//! The course's sample program turns its camera with the right mouse button
//! (`camera_pitch −= dy`, clamped to [−90°, 0°]) and sets the view in `display()`:
//!
//! ```c
//! glTranslatef(0.0, 0.0, -camera_distance);
//! glRotatef(-camera_pitch, 1.0, 0.0, 0.0);
//! glRotatef(-camera_yaw, 0.0, 1.0, 0.0);
//! glLightfv(GL_LIGHT0, GL_POSITION, light0_position);   // after the camera: fixed in the world
//! ```
//!
//! Each student extends it with their own mouse operations ([`Spec`]): which button (with or
//! without Shift) and which drag direction changes which camera variable — `camera_yaw`,
//! `camera_pitch`, `camera_distance` and, for some, the target `target_x` / `target_z` — by how
//! much per pixel, within which range. The student writes three functions ([`Impl`], in
//! `exercises/src/a2.rs`):
//!
//! | task | function | what |
//! |---|---|---|
//! | `a2.t1` | `motion(spec, state, drag)` | GLUT's `motion()`: the variables change per pixel of drag, clamped and wrapped |
//! | `a2.t2` | `camera(gl, state)` | the view transform `T(0, 0, −camera_distance) · Rx(−camera_pitch) · Ry(−camera_yaw) · T(−target_x, 0, −target_z)` |
//! | `a2.t3` | `display(gl, state)` | identity, the camera, the light at (10, 10, 10, 1), the course's objects ([`draw_course_objects`]) |
//!
//! The report shows the view transform as a product of rotations and translations and explains
//! each variable: [`camera_product`] prints the product *as the student's code builds it*, with
//! the variables' names; [`Spec::variables`] says which operation changes each variable.
//!
//! Every assignment crate has the same shape (the command line and the tests rely on it):
//! [`ID`], a per-student [`Spec`] drawn by [`variant`] and described by [`Spec::describe`], the
//! exercise API [`Impl`], [`checks`] and [`view`].

mod checks_camera;
mod checks_display;
mod checks_motion;
mod oracle;
pub mod report;
mod show;
mod spec;

use std::sync::LazyLock;

use cg_core::Rgb;
use cg_core::mesh::Mesh;
use cg_core::product::MatrixProduct;
use cg_core::scene::Scene;
use cg_harness::check::Outcome;
use cg_harness::text::t;
use cg_harness::{CheckResult, Text};

pub use cg_core::gl::Gl;
pub use spec::{SpecExt, variant};

/// The assignment's ID, the prefix of its task IDs (`a2.t1`, …).
pub const ID: &str = "a2";

pub use cg_student::a2::{
    CameraState, Drag, DragAxis, Gesture, Impl, LIGHT0_POSITION, MouseButton, Operation, Pan, Spec,
};

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
    let mut out = checks_motion::checks(spec, imp);
    out.extend(checks_camera::checks(spec, imp));
    out.extend(checks_display::checks(spec, imp));
    out
}

/// The objects of the course's sample scene (the ground and the pyramid), from
/// `cg_harness::course::scene()`: name, polygon model, colour and model transform.
static COURSE_OBJECTS: LazyLock<Vec<(String, Mesh, Rgb, MatrixProduct)>> = LazyLock::new(|| {
    cg_harness::course::scene()
        .objects
        .into_iter()
        .map(|o| (o.name, o.mesh, o.material.kd, o.transform))
        .collect()
});

/// Draws the course's objects as the sample's `display()` does, each between glPushMatrix and
/// glPopMatrix with its colour: the ground (10 × 10 squares at y = 0, colour (0.5, 0.8, 0.5))
/// and the lecture's pyramid after `glTranslatef(0, 1, 0)`.
///
/// Call it after the camera and the light; it leaves the matrix stack as it found it.
pub fn draw_course_objects(gl: &mut cg_core::gl::Gl) {
    for (name, mesh, color, transform) in COURSE_OBJECTS.iter() {
        gl.push_matrix();
        for factor in &transform.factors {
            gl.mult(factor.clone());
        }
        gl.color(color.x, color.y, color.z);
        gl.draw(name, mesh);
        gl.pop_matrix();
    }
}

/// A student's recorded frame replayed on the kit's [`Gl`], with [`draw_course_objects`] for
/// the course's objects: the draws, lights and stack errors the same calls give in OpenGL.
#[must_use]
pub fn replay(recorded: &cg_student::gl::Gl) -> Gl {
    Gl::replay(recorded, &draw_course_objects)
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
    let probe = show::PROBE;
    let mut rec = cg_student::gl::Gl::new();
    match cg_harness::check::guarded(|| (imp.camera)(&mut rec, &probe)) {
        Ok(()) => Ok(show::symbolize(replay(&rec).model_view(), &probe)),
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

/// The view transform the spec asks for, with the report's names:
/// `T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw)`, then
/// `T(-target_x, 0, -target_z)` when the spec has a pan. Its matrix is the one of
/// `cg_core::camera::OrbitCamera::view_matrix` for the state.
#[must_use]
pub fn expected_product(spec: &Spec, state: &CameraState) -> MatrixProduct {
    oracle::view_product(spec.pan.is_some(), state)
}

/// The scene that shows `imp`'s result at time `time_s`: from the spec's start, the student's
/// `motion()` replays a scripted drag — the yaw drag that turns the camera by 40° (plus 30° per
/// second of `time_s`), the pitch drag that lowers the pitch by 15°, the distance drag that
/// moves the camera 5 farther away and, with a pan, the target moved by (1, −1) — and the student's
/// `display()` draws the frame. A wrong sign or speed shows as another viewpoint than the
/// reference's; a light set before the camera as other shading on the ground and the pyramid.
///
/// # Errors
/// What keeps the result from being drawn, in words for the student: nothing drawn yet.
pub fn view(spec: &Spec, imp: &Impl, time_s: f64) -> Result<Scene, Text> {
    let mut state = spec.start;
    for drag in oracle::demo_drags(spec, time_s) {
        let mut next = state;
        // A motion() not written yet (or panicking) leaves the camera where it starts.
        if cg_harness::check::guarded(|| (imp.motion)(spec, &mut next, &drag)).is_err() {
            break;
        }
        state = next;
    }
    let mut rec = cg_student::gl::Gl::new();
    (imp.display)(&mut rec, &state);
    let gl = replay(&rec);
    if gl.draws().is_empty() {
        return Err(t(
            "まだ何も描かれていません: display()（a2.t3）で視点の変換・光源・物体を設定してください",
            "nothing is drawn yet: display() (a2.t3) sets the camera, the light and the objects",
        ));
    }
    Ok(gl.to_scene(&cg_harness::course::stage()))
}

/// Assignment 2 as a unit of the kit: what `cg assignment`, `cg check`, `cg view`, the report and the
/// grader need of it (see [`cg_harness::Assignment`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct A2;

impl cg_harness::Assignment for A2 {
    const ID: &'static str = ID;
    const TITLE: (&'static str, &'static str) =
        ("視点操作インターフェースの拡張", "camera interface");
    const OWN_CAMERA: bool = true;
    type Spec = Spec;
    type Impl = Impl;
    type Report = report::CameraData;

    fn variant(rng: &mut cg_harness::VariantRng) -> Spec {
        variant(rng)
    }

    fn describe(spec: &Spec, lang: cg_core::lang::Lang) -> String {
        SpecExt::describe(spec, lang)
    }

    fn spec_json(spec: &Spec) -> cg_harness::unit::Json {
        cg_harness::unit::json(spec)
    }

    fn checks(spec: &Spec, imp: &Impl) -> Vec<cg_harness::CheckResult> {
        checks(spec, imp)
    }

    fn report(spec: &Spec, imp: &Impl) -> cg_harness::report::Part<report::CameraData> {
        report::camera_part(spec, imp)
    }

    fn view(
        spec: &Spec,
        imp: &Impl,
        time_s: f64,
    ) -> Result<cg_core::scene::Scene, cg_harness::Text> {
        view(spec, imp, time_s)
    }
}
