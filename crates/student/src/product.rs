//! A transform written as a product of named factors, `T(0, 0, -15) · Rx(30°) · T(0, 1, 0)`, as
//! plain data: what a student's function returns for the report (a1.t4) and what
//! [`Gl::mult`](crate::gl::Gl::mult) records. The kit multiplies and prints it.
//!
//! Factors are listed in the order a program calls glTranslatef / glRotatef / glScalef: the
//! product is `F₀ · F₁ · … · Fₖ`, and the last factor acts on the vertices first.

use glam::{Mat4, Vec3};
use serde::{Deserialize, Serialize};

/// A number in a factor: its value and, optionally, the variable it stands for in the report
/// (`-camera_pitch`, `theta_1`).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Param {
    /// The value (degrees for angles, scene units for lengths).
    pub value: f32,
    /// The symbol the report prints; `None` prints the value.
    pub symbol: Option<String>,
}

impl Param {
    /// A plain number.
    #[must_use]
    pub fn num(value: f32) -> Param {
        Param { value, symbol: None }
    }

    /// A number the report prints as `symbol`: `Param::sym("theta_1", theta)`.
    #[must_use]
    pub fn sym(symbol: impl Into<String>, value: f32) -> Param {
        Param { value, symbol: Some(symbol.into()) }
    }
}

/// The axis of a rotation.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Axis {
    /// Rx
    X,
    /// Ry
    Y,
    /// Rz
    Z,
    /// R(axis), glRotatef's general form (any non-zero axis).
    Any(Vec3),
}

/// One factor of a [`MatrixProduct`].
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Factor {
    /// T(x, y, z): glTranslatef.
    Translate([Param; 3]),
    /// R(angle) about an axis, in degrees, counter-clockwise looking down the axis towards the
    /// origin: glRotatef.
    Rotate {
        /// The axis.
        axis: Axis,
        /// The angle in degrees.
        angle_deg: Param,
    },
    /// S(x, y, z): glScalef.
    Scale([Param; 3]),
    /// P(fovy, aspect, near, far): gluPerspective; depth to `[0, 1]` (wgpu) or, with
    /// `gl_depth`, to `[-1, 1]` (OpenGL).
    Perspective {
        /// Vertical field of view in degrees.
        fovy_deg: f32,
        /// Width / height.
        aspect: f32,
        /// Near plane distance.
        near: f32,
        /// Far plane distance.
        far: f32,
        /// `true`: OpenGL's `[-1, 1]` depth.
        gl_depth: bool,
    },
    /// Any matrix, printed by name (`M`, `V`).
    Matrix {
        /// The name printed in products.
        name: String,
        /// The matrix.
        matrix: Mat4,
    },
}

impl Factor {
    /// T(v) with plain numbers.
    #[must_use]
    pub fn translate(v: Vec3) -> Factor {
        Factor::Translate([Param::num(v.x), Param::num(v.y), Param::num(v.z)])
    }

    /// S(v) with plain numbers.
    #[must_use]
    pub fn scale(v: Vec3) -> Factor {
        Factor::Scale([Param::num(v.x), Param::num(v.y), Param::num(v.z)])
    }

    /// R(angle) about `axis`, the angle in degrees as a [`Param`] (for a symbol).
    #[must_use]
    pub fn rotate(axis: Axis, angle_deg: Param) -> Factor {
        Factor::Rotate { axis, angle_deg }
    }

    /// Rx(angle_deg): glRotatef(angle_deg, 1, 0, 0).
    #[must_use]
    pub fn rotate_x_deg(angle_deg: f32) -> Factor {
        Factor::rotate(Axis::X, Param::num(angle_deg))
    }

    /// Ry(angle_deg): glRotatef(angle_deg, 0, 1, 0).
    #[must_use]
    pub fn rotate_y_deg(angle_deg: f32) -> Factor {
        Factor::rotate(Axis::Y, Param::num(angle_deg))
    }

    /// Rz(angle_deg): glRotatef(angle_deg, 0, 0, 1).
    #[must_use]
    pub fn rotate_z_deg(angle_deg: f32) -> Factor {
        Factor::rotate(Axis::Z, Param::num(angle_deg))
    }

    /// R(angle_deg, axis): glRotatef(angle_deg, x, y, z). An axis along +X, +Y or +Z becomes
    /// [`Axis::X`], [`Axis::Y`] or [`Axis::Z`], so `glRotatef(30, 1, 0, 0)` prints as `Rx(30°)`.
    #[must_use]
    pub fn rotate_deg(angle_deg: f32, axis: Vec3) -> Factor {
        let along = |a: f32, b: f32, c: f32| a > 0.0 && a.is_finite() && b == 0.0 && c == 0.0;
        let axis = if along(axis.x, axis.y, axis.z) {
            Axis::X
        } else if along(axis.y, axis.z, axis.x) {
            Axis::Y
        } else if along(axis.z, axis.x, axis.y) {
            Axis::Z
        } else {
            Axis::Any(axis)
        };
        Factor::rotate(axis, Param::num(angle_deg))
    }

    /// P(fovy, aspect, near, far) with wgpu's `[0, 1]` depth.
    #[must_use]
    pub fn perspective(fovy_deg: f32, aspect: f32, near: f32, far: f32) -> Factor {
        Factor::Perspective { fovy_deg, aspect, near, far, gl_depth: false }
    }

    /// P(fovy, aspect, near, far) with OpenGL's `[-1, 1]` depth (gluPerspective's matrix).
    #[must_use]
    pub fn perspective_gl(fovy_deg: f32, aspect: f32, near: f32, far: f32) -> Factor {
        Factor::Perspective { fovy_deg, aspect, near, far, gl_depth: true }
    }

    /// Any matrix, printed as `name`.
    #[must_use]
    pub fn named(name: impl Into<String>, matrix: Mat4) -> Factor {
        Factor::Matrix { name: name.into(), matrix }
    }
}

/// A product of named factors, left to right in program order.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MatrixProduct {
    /// The factors, leftmost first.
    pub factors: Vec<Factor>,
}

impl MatrixProduct {
    /// The empty product (the identity).
    #[must_use]
    pub fn identity() -> MatrixProduct {
        MatrixProduct { factors: Vec::new() }
    }

    /// This product times `factor` on the right: the next glTranslatef / glRotatef call.
    #[must_use]
    pub fn then(mut self, factor: Factor) -> MatrixProduct {
        self.factors.push(factor);
        self
    }

    /// Appends `factor` on the right, in place.
    pub fn push(&mut self, factor: Factor) {
        self.factors.push(factor);
    }
}
