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
//! exercise API [`Impl`], [`checks()`] and [`view()`].

mod checks;
mod describe;
mod oracle;
pub mod report;
mod show;
mod spec;
mod view;

pub use cg_core::gl::Gl;
pub use checks::checks;
pub use oracle::expected_product;
pub use show::camera_product;
pub use spec::{SpecExt, variant};
pub use view::{draw_course_objects, reference, replay, view};

/// The assignment's ID, the prefix of its task IDs (`a2.t1`, …).
pub const ID: &str = "a2";

pub use cg_student::a2::{
    CameraState, Drag, DragAxis, Gesture, Impl, LIGHT0_POSITION, MouseButton, Operation, Pan, Spec,
};

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

    fn reference_view(spec: &Spec, time_s: f64) -> Option<cg_core::scene::Scene> {
        Some(view::reference(spec, time_s))
    }
}
