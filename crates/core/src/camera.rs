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

use glam::Vec3;

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
