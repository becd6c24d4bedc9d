//! Assignment `a2` — 視点操作インターフェースの拡張 (camera interface): your mouse operations
//! ([`Spec`]), the camera variables ([`CameraState`]), one drag ([`Drag`]) and the three
//! functions you write ([`Impl`]). Plain data and the [`Gl`] recorder: the kit computes the
//! expected view transform on its own side, out of your crate's reach.

use crate::left_out;
use serde::{Deserialize, Serialize};

use crate::gl::Gl;

/// A mouse button, as GLUT names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MouseButton {
    /// GLUT_LEFT_BUTTON
    Left,
    /// GLUT_MIDDLE_BUTTON
    Middle,
    /// GLUT_RIGHT_BUTTON
    Right,
}

/// The course's light position, `light0_position = { 10.0, 10.0, 10.0, 1.0 }` (a point light:
/// w = 1), in world space. `display()` (a2.t3) sets it *after* the camera, so OpenGL
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
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Gesture {
    /// The button held during the drag.
    pub button: MouseButton,
    /// Whether Shift was held.
    pub shift: bool,
}

/// One call of GLUT's `motion(x, y)` while a button is held: which button, whether Shift was
/// held when it was pressed, and how far the pointer moved since the last call, in pixels
/// (`dx = x − last_mouse_x`, positive to the **right**; `dy = y − last_mouse_y`, positive
/// **down**: GLUT's window coordinates have y down). Both are whole numbers of pixels in GLUT;
/// the checks use whole numbers too.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
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
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
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
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pan {
    /// How target_x changes.
    pub x: Operation,
    /// How target_z changes.
    pub z: Operation,
    /// `|target_x|` and `|target_z|` stay at most this (the ground is ±5).
    pub limit: f32,
}

/// What one student must build: their mouse operations, ranges and starting state.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
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

impl Impl {
    /// For the kit, not for your code: what stands in for `exercises/src/a2.rs` while that file
    /// does not compile, so that the other assignments still build and run. The kit never calls
    /// these functions: it says the file does not compile instead.
    #[must_use]
    pub fn left_out() -> Impl {
        Impl {
            motion: |_, _, _| left_out("a2"),
            camera: |_, _| left_out("a2"),
            display: |_, _| left_out("a2"),
        }
    }
}

/// Draws the course's objects as the sample's `display()` does, each between glPushMatrix and
/// glPopMatrix with its colour: the ground (10 × 10 squares at y = 0, colour (0.5, 0.8, 0.5))
/// and the lecture's pyramid after `glTranslatef(0, 1, 0)`.
///
/// Call it after the camera and the light; it leaves the matrix stack as it found it.
///
/// 授業の物体（地面と角すい）を描きます。視点の変換と光源の後に呼んでください。
pub fn draw_course_objects(gl: &mut Gl) {
    gl.course_objects();
}
