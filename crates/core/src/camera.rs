//! The orbit camera of the course's sample program (視点操作), and the mouse state that the GLUT
//! callbacks `mouse()` and `motion()` keep.
//!
//! ```c
//! glTranslatef(0.0, 0.0, -camera_distance);
//! glRotatef(-camera_pitch, 1.0, 0.0, 0.0);
//! glRotatef(-camera_yaw, 0.0, 1.0, 0.0);   // the usual extension
//! ```
//!
//! The view matrix is built from yaw and pitch directly (never from a look-at with an up vector),
//! so it is defined at pitch ±90° and never flips when crossing the pole.
//!
//! Sign conventions, read off the GL calls above (ワールド座標系→カメラ座標系):
//!
//! | variable | meaning | the eye, in world space |
//! |---|---|---|
//! | `camera_pitch` (仰角) | negative looks down on the target; −90° looks straight down | above the target when pitch < 0: `y = −distance·sin(pitch)` |
//! | `camera_yaw` | turns the camera about +Y, counter-clockwise seen from above | `x = distance·cos(pitch)·sin(yaw)`, `z = distance·cos(pitch)·cos(yaw)` |
//! | `camera_distance` | from the target to the eye | yaw 0, pitch 0: on +Z looking down −Z |
//!
//! So the course's camera (pitch −30°, distance 15) sits at `(0, 15·sin 30°, 15·cos 30°)`.
//! Mouse mapping (the sample's `motion()`): right-drag down (dy > 0) lowers the pitch (looks more
//! from above), right-drag right (dx > 0) lowers the yaw, left-drag down moves the camera away.

use glam::{Mat4, Vec3};

use crate::math::wrap_degrees;
use crate::product::{Factor, MatrixProduct, Param};
use crate::transform::{rotate_x_deg, rotate_y_deg, sin_cos_deg, translate};

/// Ranges, clamps and speeds of the mouse mapping. [`CameraLimits::default`] is the course's.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraLimits {
    /// Lowest pitch in degrees (course: -90).
    pub pitch_min_deg: f32,
    /// Highest pitch in degrees (course: 0).
    pub pitch_max_deg: f32,
    /// Closest distance to the target (course extension: 2.0).
    pub distance_min: f32,
    /// Farthest distance (course: none, `f32::INFINITY`).
    pub distance_max: f32,
    /// Degrees per pixel of right-drag, for pitch (dy) and yaw (dx) (course: 1.0).
    pub rotate_deg_per_px: f32,
    /// Distance per pixel of left-drag dy (course extension: 0.2).
    pub zoom_per_px: f32,
    /// Whether right-drag dx changes yaw (the usual extension; the bare sample has no yaw).
    pub yaw_enabled: bool,
}

/// The camera of the sample program: it looks at `target` from `distance` away, raised by
/// `pitch_deg` (negative = looking down) and turned by `yaw_deg` about +Y.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrbitCamera {
    /// camera_yaw in degrees, kept in `[0, 360)`.
    pub yaw_deg: f32,
    /// camera_pitch in degrees, kept in `[pitch_min_deg, pitch_max_deg]`.
    pub pitch_deg: f32,
    /// camera_distance, kept in `[distance_min, distance_max]`.
    pub distance: f32,
    /// The point the camera orbits (the sample: the origin).
    pub target: Vec3,
    /// Clamps and speeds.
    pub limits: CameraLimits,
}

/// A mouse button, as GLUT names them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MouseButton {
    /// GLUT_LEFT_BUTTON
    Left,
    /// GLUT_MIDDLE_BUTTON
    Middle,
    /// GLUT_RIGHT_BUTTON
    Right,
}

impl Default for CameraLimits {
    /// The course's: pitch in [-90°, 0°], distance ≥ 2, 1° per pixel, 0.2 units per pixel, yaw on.
    fn default() -> CameraLimits {
        CameraLimits {
            pitch_min_deg: -90.0,
            pitch_max_deg: 0.0,
            distance_min: 2.0,
            distance_max: f32::INFINITY,
            rotate_deg_per_px: 1.0,
            zoom_per_px: 0.2,
            yaw_enabled: true,
        }
    }
}

/// `x` clamped to `[lo, hi]` without panicking on odd limits (NaN limits are ignored, `lo > hi`
/// gives `hi`), unlike `f32::clamp`.
fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    x.max(lo).min(hi)
}

impl Default for OrbitCamera {
    /// [`OrbitCamera::course_sample`].
    fn default() -> OrbitCamera {
        OrbitCamera::course_sample()
    }
}

impl OrbitCamera {
    /// The sample program's camera at start: yaw 0°, pitch −30°, distance 15, looking at the
    /// origin, with the course's [`CameraLimits::default`].
    #[must_use]
    pub fn course_sample() -> OrbitCamera {
        OrbitCamera {
            yaw_deg: 0.0,
            pitch_deg: -30.0,
            distance: 15.0,
            target: Vec3::ZERO,
            limits: CameraLimits::default(),
        }
    }

    /// Right-drag by `(dx, dy)` pixels (the sample's `motion()` with the right button held):
    /// `camera_pitch −= dy · rotate_deg_per_px`, clamped to `[pitch_min_deg, pitch_max_deg]`; when
    /// `yaw_enabled`, `camera_yaw −= dx · rotate_deg_per_px`, wrapped to `[0, 360)`.
    ///
    /// A non-finite delta (or one whose product with the speed overflows) is ignored, so the state
    /// never becomes NaN or ∞.
    pub fn right_drag(&mut self, dx: f32, dy: f32) {
        let l = self.limits;
        let pitch = self.pitch_deg - dy * l.rotate_deg_per_px;
        if pitch.is_finite() {
            self.pitch_deg = clamp(pitch, l.pitch_min_deg, l.pitch_max_deg);
        }
        if l.yaw_enabled {
            let yaw = self.yaw_deg - dx * l.rotate_deg_per_px;
            if yaw.is_finite() {
                self.yaw_deg = wrap_degrees(yaw);
            }
        }
    }

    /// Left-drag by `(dx, dy)` pixels (the lecture's extension): `camera_distance += dy ·
    /// zoom_per_px`, clamped to `[distance_min, distance_max]` (一定値以上は近づかないように制限);
    /// `dx` is unused.
    ///
    /// A non-finite delta (or an overflowing product) is ignored.
    pub fn left_drag(&mut self, dx: f32, dy: f32) {
        let _ = dx;
        let l = self.limits;
        let distance = self.distance + dy * l.zoom_per_px;
        if distance.is_finite() {
            self.distance = clamp(distance, l.distance_min, l.distance_max);
        }
    }

    /// The view matrix (ワールド座標系→カメラ座標系)
    /// `T(0, 0, −distance) · Rx(−pitch) · Ry(−yaw) · T(−target)`, rotations in exact degrees.
    ///
    /// Defined and orthonormal in its rotation part at every pitch, ±90° included, and continuous
    /// in pitch across the poles (no up vector, no roll flip; docs/numerics.md row 10). Non-finite
    /// fields (never produced by the mouse mapping) give non-finite entries; the checked sibling
    /// is `view_product().matrix()`.
    ///
    /// See also [`OrbitCamera::view_product`], [`crate::transform::look_at`].
    #[must_use]
    pub fn view_matrix(&self) -> Mat4 {
        translate(Vec3::new(0.0, 0.0, -self.distance))
            * rotate_x_deg(-self.pitch_deg)
            * rotate_y_deg(-self.yaw_deg)
            * translate(-self.target)
    }

    /// The view as the report writes it:
    /// `T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw)`, followed by
    /// `T(-target_x, -target_y, -target_z)` only when the target is not the origin (the sample
    /// has no such factor). Its matrix equals [`OrbitCamera::view_matrix`].
    #[must_use]
    pub fn view_product(&self) -> MatrixProduct {
        let product = MatrixProduct::identity()
            .then(Factor::Translate([
                Param::num(0.0),
                Param::num(0.0),
                Param::sym("-camera_distance", -self.distance),
            ]))
            .then(Factor::rotate(
                crate::product::Axis::X,
                Param::sym("-camera_pitch", -self.pitch_deg),
            ))
            .then(Factor::rotate(
                crate::product::Axis::Y,
                Param::sym("-camera_yaw", -self.yaw_deg),
            ));
        if self.target == Vec3::ZERO {
            return product;
        }
        let t = -self.target;
        product.then(Factor::Translate([
            Param::sym("-target_x", t.x),
            Param::sym("-target_y", t.y),
            Param::sym("-target_z", t.z),
        ]))
    }

    /// Where the eye is in world space:
    /// `target + distance · (cos(pitch)·sin(yaw), −sin(pitch), cos(pitch)·cos(yaw))`, the inverse
    /// view matrix applied to the origin (computed in f64 from the exact-degree sines and
    /// cosines, rounded once).
    #[must_use]
    pub fn eye_position(&self) -> Vec3 {
        let (sp, cp) = sin_cos_deg(self.pitch_deg);
        let (sy, cy) = sin_cos_deg(self.yaw_deg);
        let d = f64::from(self.distance);
        let offset = glam::DVec3::new(d * cp * sy, -d * sp, d * cp * cy);
        (self.target.as_dvec3() + offset).as_vec3()
    }
}

/// The mouse state of the sample program, kept by its GLUT callbacks `mouse()` and `motion()`:
/// which buttons are held (`drag_mouse_l`, `drag_mouse_m`, `drag_mouse_r`) and where the pointer
/// was last seen (`last_mouse_x`, `last_mouse_y`), in window pixels, y down.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MouseState {
    /// The left button is held (left-drag zooms).
    pub drag_mouse_l: bool,
    /// The middle button is held (unused by the camera).
    pub drag_mouse_m: bool,
    /// The right button is held (right-drag rotates).
    pub drag_mouse_r: bool,
    /// The last pointer x.
    pub last_mouse_x: f32,
    /// The last pointer y.
    pub last_mouse_y: f32,
}

impl MouseState {
    /// No button held, pointer at (0, 0).
    #[must_use]
    pub fn new() -> MouseState {
        MouseState::default()
    }

    /// GLUT's `mouse(button, state, x, y)`: records whether `button` is now held and remembers
    /// the position, so the next [`MouseState::motion`] measures the drag from here.
    ///
    /// A non-finite position is not remembered (the button state still is).
    pub fn mouse(&mut self, button: MouseButton, pressed: bool, x: f32, y: f32) {
        match button {
            MouseButton::Left => self.drag_mouse_l = pressed,
            MouseButton::Middle => self.drag_mouse_m = pressed,
            MouseButton::Right => self.drag_mouse_r = pressed,
        }
        self.remember(x, y);
    }

    /// GLUT's `motion(x, y)`: with the right button held, [`OrbitCamera::right_drag`] by the
    /// movement since the last position; with the left button held, [`OrbitCamera::left_drag`];
    /// then remembers the position.
    ///
    /// A non-finite position is ignored entirely (no camera change, not remembered).
    pub fn motion(&mut self, x: f32, y: f32, camera: &mut OrbitCamera) {
        if !(x.is_finite() && y.is_finite()) {
            return;
        }
        let (dx, dy) = (x - self.last_mouse_x, y - self.last_mouse_y);
        if self.drag_mouse_r {
            camera.right_drag(dx, dy);
        }
        if self.drag_mouse_l {
            camera.left_drag(dx, dy);
        }
        self.remember(x, y);
    }

    fn remember(&mut self, x: f32, y: f32) {
        if x.is_finite() && y.is_finite() {
            self.last_mouse_x = x;
            self.last_mouse_y = y;
        }
    }
}
