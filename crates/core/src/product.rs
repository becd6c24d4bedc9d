//! A transform written as a *product of named factors*, as the report asks:
//! `T(0, 0, -15) · Rx(30°) · T(0, 1, 0)`, symbolically (`Rx(-camera_pitch)`), numerically, as the
//! 4×4 matrices side by side, and as LaTeX `pmatrix`.
//!
//! Factors are listed in the order a program calls glTranslatef / glRotatef / glScalef, so the
//! product is `F₀ · F₁ · … · Fₖ` and the last factor acts on the vertices first.

use glam::{Mat4, Vec3};

/// A number in a factor: its value and, optionally, the variable it stands for in the report
/// (`-camera_pitch`, `theta_cycle`, `camera_distance`).
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// The value (degrees for angles, scene units for lengths).
    pub value: f32,
    /// The symbol printed by the symbolic forms; `None` prints the value there too.
    pub symbol: Option<String>,
}

/// The axis of a rotation factor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Axis {
    /// Rx
    X,
    /// Ry
    Y,
    /// Rz
    Z,
    /// R(axis), glRotatef's general form; the axis need not be unit length but must be non-zero.
    Any(Vec3),
}

/// One factor of a [`MatrixProduct`].
#[derive(Clone, Debug, PartialEq)]
pub enum Factor {
    /// T(x, y, z) — glTranslatef.
    Translate([Param; 3]),
    /// R(angle) about an axis, angle in degrees, counter-clockwise looking down the axis towards
    /// the origin — glRotatef.
    Rotate {
        /// The axis.
        axis: Axis,
        /// The angle in degrees.
        angle_deg: Param,
    },
    /// S(x, y, z) — glScalef.
    Scale([Param; 3]),
    /// P(fovy, aspect, near, far) — gluPerspective, with depth mapped to `[0, 1]` (wgpu) or, when
    /// `gl_depth`, to `[-1, 1]` (OpenGL).
    Perspective {
        /// Vertical field of view in degrees.
        fovy_deg: f32,
        /// Width / height.
        aspect: f32,
        /// Near plane distance (> 0).
        near: f32,
        /// Far plane distance (> near).
        far: f32,
        /// `true`: OpenGL's `[-1, 1]` depth; `false`: wgpu's `[0, 1]`.
        gl_depth: bool,
    },
    /// Any matrix, printed by name (`M`, `V`, `LookAt`).
    Matrix {
        /// The name printed in products (`V`, `LookAt`).
        name: String,
        /// The matrix.
        matrix: Mat4,
    },
}

/// A product of named factors, left to right in program order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MatrixProduct {
    /// The factors, leftmost first.
    pub factors: Vec<Factor>,
}
