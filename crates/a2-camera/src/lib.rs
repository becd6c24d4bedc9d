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
use serde::Serialize;

pub use cg_core::camera::MouseButton;
pub use cg_core::gl::Gl;
pub use spec::variant;

/// The assignment's ID, the prefix of its task IDs (`a2.t1`, …).
pub const ID: &str = "a2";

/// The course's light position, `light0_position = { 10.0, 10.0, 10.0, 1.0 }` (a point light:
/// w = 1), in world coordinates. `display()` (a2.t3) sets it *after* the camera, so OpenGL
/// multiplies it by the view matrix and the light stays fixed in the world.
pub const LIGHT0_POSITION: [f32; 4] = [10.0, 10.0, 10.0, 1.0];

/// The camera variables of the program (the sample's global variables), the state that
/// `motion()` changes and `display()` draws from.
///
/// | field | unit | meaning |
/// |---|---|---|
/// | `camera_yaw` | degrees | turn of the camera about +Y (方位角), kept in `[0, 360)` |
/// | `camera_pitch` | degrees | elevation (仰角); negative looks down on the target, −90 straight down |
/// | `camera_distance` | scene units | from the target to the camera |
/// | `target_x`, `target_z` | scene units | the point the camera looks at (注視点), on the ground `y = 0` |
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct CameraState {
    /// camera_yaw in degrees.
    pub camera_yaw: f32,
    /// camera_pitch in degrees.
    pub camera_pitch: f32,
    /// camera_distance in scene units.
    pub camera_distance: f32,
    /// The target's x (注視点の x 座標).
    pub target_x: f32,
    /// The target's z (注視点の z 座標).
    pub target_z: f32,
}

/// A button with or without Shift held when it was pressed (GLUT: `glutGetModifiers()` in
/// `mouse()`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub struct Gesture {
    /// The button held during the drag.
    #[serde(serialize_with = "show::serialize_button")]
    pub button: MouseButton,
    /// Whether Shift was held.
    pub shift: bool,
}

/// One call of GLUT's `motion(x, y)` while a button is held: which button, whether Shift was
/// held when it was pressed, and how far the pointer moved since the last call, in pixels
/// (`dx = x − last_mouse_x`, positive to the **right**; `dy = y − last_mouse_y`, positive
/// **down**: GLUT's window coordinates have y down). Both are whole numbers of pixels in GLUT;
/// the checks use whole numbers too.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Drag {
    /// The button held (`drag_mouse_l`, `drag_mouse_m`, `drag_mouse_r` in the sample).
    pub button: MouseButton,
    /// Whether Shift was held when the button was pressed.
    pub shift: bool,
    /// Pixels moved to the right since the last `motion()` (left: negative).
    pub dx: f32,
    /// Pixels moved down since the last `motion()` (up: negative).
    pub dy: f32,
}

/// Which component of a drag an operation reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DragAxis {
    /// `dx`: dragging left and right.
    Horizontal,
    /// `dy`: dragging up and down.
    Vertical,
}

/// One mouse operation of the spec: while `gesture` is dragged, the variable changes by
/// `per_px × d`, where `d` is the drag's `dx` ([`DragAxis::Horizontal`]) or `dy`
/// ([`DragAxis::Vertical`]). The sign of `per_px` is the direction: the sample's pitch is
/// `per_px = −1.0` on `Vertical` (`camera_pitch −= 1.0 × dy`: dragging down lowers it).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Operation {
    /// The button (and Shift) that drives it.
    pub gesture: Gesture,
    /// `dx` or `dy`.
    pub axis: DragAxis,
    /// Change per pixel, with its sign: degrees for angles, scene units for lengths.
    pub per_px: f32,
}

/// Moving the target (注視点) on the ground: `target_x` by `x`, `target_z` by `z`, each kept in
/// `[−limit, limit]`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Pan {
    /// How target_x changes.
    pub x: Operation,
    /// How target_z changes.
    pub z: Operation,
    /// `|target_x|` and `|target_z|` stay at most this (the ground is ±5).
    pub limit: f32,
}

/// What one student must build: their mouse operations, ranges and starting state.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Spec {
    /// The variables when the program starts (the sample: yaw 0°, pitch −30°, distance 15).
    pub start: CameraState,
    /// How camera_yaw changes; it wraps into `[0, 360)`.
    pub yaw: Operation,
    /// How camera_pitch changes.
    pub pitch: Operation,
    /// The lowest camera_pitch in degrees (−90: looking straight down).
    pub pitch_min: f32,
    /// The highest camera_pitch in degrees.
    pub pitch_max: f32,
    /// How camera_distance changes.
    pub distance: Operation,
    /// The closest camera_distance (一定値以上は近づかないように制限).
    pub distance_min: f32,
    /// The farthest camera_distance.
    pub distance_max: f32,
    /// How the target moves, for students who have it; without it the target stays at the
    /// origin.
    pub pan: Option<Pan>,
}

/// The functions a student writes (see `exercises/src/a2.rs`).
#[derive(Clone, Copy, Debug)]
pub struct Impl {
    /// a2.t1 — GLUT's `motion()`: changes `state` for one drag as the spec says.
    pub motion: fn(&Spec, &mut CameraState, &Drag),
    /// a2.t2 — the view transform (ワールド座標系→カメラ座標系), multiplied onto the current
    /// matrix with glTranslatef / glRotatef-style calls.
    pub camera: fn(&mut Gl, &CameraState),
    /// a2.t3 — `display()`: identity, [`Impl::camera`], the light, the course's objects.
    pub display: fn(&mut Gl, &CameraState),
}

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
pub fn draw_course_objects(gl: &mut Gl) {
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
    let mut gl = Gl::new();
    match cg_harness::check::guarded(|| (imp.camera)(&mut gl, &probe)) {
        Ok(()) => Ok(show::symbolize(gl.model_view(), &probe)),
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
    let mut gl = Gl::new();
    (imp.display)(&mut gl, &state);
    if gl.draws().is_empty() {
        return Err(t(
            "まだ何も描かれていません: display()（a2.t3）で視点の変換・光源・物体を設定してください",
            "nothing is drawn yet: display() (a2.t3) sets the camera, the light and the objects",
        ));
    }
    Ok(gl.to_scene(&cg_harness::course::stage()))
}
