//! An OpenGL-style recorder for the course's `display()`: the same calls as the slides
//! (glLoadIdentity, glTranslatef, glRotatef, glPushMatrix, glPopMatrix, glLightfv with
//! GL_POSITION, glColor3f, drawing a polygon model). [`Gl`] only *records* the calls, in order;
//! the kit replays them to check your frame and to draw it.
//!
//! ```
//! use cg_student::gl::Gl;
//!
//! let mut gl = Gl::new();
//! gl.load_identity();
//! gl.translate(0.0, 0.0, -15.0);
//! gl.rotate(30.0, 1.0, 0.0, 0.0);
//! gl.light_position(0, [10.0, 10.0, 10.0, 1.0]);
//! assert_eq!(gl.calls().len(), 4);
//! ```

use serde::{Deserialize, Serialize};

use crate::mesh::Mesh;
use crate::product::Factor;

/// One recorded call.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum GlCall {
    /// glLoadIdentity()
    LoadIdentity,
    /// glTranslatef(x, y, z)
    Translate([f32; 3]),
    /// glRotatef(angle_deg, x, y, z)
    Rotate {
        /// Degrees, counter-clockwise looking down the axis towards the origin.
        angle_deg: f32,
        /// The axis.
        axis: [f32; 3],
    },
    /// glScalef(x, y, z)
    Scale([f32; 3]),
    /// glMultMatrix with a named factor.
    Mult(Factor),
    /// glPushMatrix()
    PushMatrix,
    /// glPopMatrix()
    PopMatrix,
    /// glLightfv(GL_LIGHTi, GL_POSITION, position)
    LightPosition {
        /// Which light, 0–7.
        light: usize,
        /// The position (`w = 0`: a direction).
        position: [f32; 4],
    },
    /// glColor3f(r, g, b)
    Color([f32; 3]),
    /// Draws a polygon model with the current matrix and colour.
    Draw {
        /// The name given to the draw.
        name: String,
        /// The polygon model, in model space.
        mesh: Mesh,
    },
    /// The course's objects (the ground and the lecture's pyramid), each between glPushMatrix
    /// and glPopMatrix with its transform and colour: see `a2::draw_course_objects`.
    CourseObjects,
}

/// The recording context; see the module docs.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Gl {
    calls: Vec<GlCall>,
}

impl Gl {
    /// A fresh context with nothing recorded.
    #[must_use]
    pub fn new() -> Gl {
        Gl::default()
    }

    /// glLoadIdentity.
    pub fn load_identity(&mut self) {
        self.calls.push(GlCall::LoadIdentity);
    }

    /// glTranslatef(x, y, z).
    pub fn translate(&mut self, x: f32, y: f32, z: f32) {
        self.calls.push(GlCall::Translate([x, y, z]));
    }

    /// glRotatef(angle_deg, x, y, z): counter-clockwise by `angle_deg` **degrees** about the
    /// axis `(x, y, z)`.
    pub fn rotate(&mut self, angle_deg: f32, x: f32, y: f32, z: f32) {
        self.calls.push(GlCall::Rotate { angle_deg, axis: [x, y, z] });
    }

    /// glScalef(x, y, z).
    pub fn scale(&mut self, x: f32, y: f32, z: f32) {
        self.calls.push(GlCall::Scale([x, y, z]));
    }

    /// glMultMatrix with a named factor, so the report can print it with its symbol:
    /// `gl.mult(Factor::rotate(Axis::Y, Param::sym("theta_1", theta)))` does what
    /// `gl.rotate(theta, 0.0, 1.0, 0.0)` does and prints as `Ry(theta_1)`.
    pub fn mult(&mut self, factor: Factor) {
        self.calls.push(GlCall::Mult(factor));
    }

    /// glPushMatrix.
    pub fn push_matrix(&mut self) {
        self.calls.push(GlCall::PushMatrix);
    }

    /// glPopMatrix.
    pub fn pop_matrix(&mut self) {
        self.calls.push(GlCall::PopMatrix);
    }

    /// glLightfv(GL_LIGHTi, GL_POSITION, position): OpenGL multiplies the position by the
    /// model-view matrix *at the time of the call*.
    pub fn light_position(&mut self, light: usize, position: [f32; 4]) {
        self.calls.push(GlCall::LightPosition { light, position });
    }

    /// glColor3f(r, g, b).
    pub fn color(&mut self, r: f32, g: f32, b: f32) {
        self.calls.push(GlCall::Color([r, g, b]));
    }

    /// Draws a polygon model with the current model-view matrix and colour (the course's
    /// `renderPolygon()` between glBegin and glEnd).
    pub fn draw(&mut self, name: &str, mesh: &Mesh) {
        self.calls.push(GlCall::Draw { name: name.to_owned(), mesh: mesh.clone() });
    }

    /// Records the course's objects (see [`GlCall::CourseObjects`]).
    pub(crate) fn course_objects(&mut self) {
        self.calls.push(GlCall::CourseObjects);
    }

    /// Every call recorded so far, in order.
    #[must_use]
    pub fn calls(&self) -> &[GlCall] {
        &self.calls
    }
}
