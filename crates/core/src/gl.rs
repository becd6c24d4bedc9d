//! An OpenGL-style recording context for the course's `display()` callback: the same calls as
//! the slides (glLoadIdentity, glTranslatef, glRotatef, glPushMatrix, glPopMatrix, glLightfv
//! with GL_POSITION, glColor3f, drawing a polygon model), but instead of drawing, [`Gl`] records
//! what each call did — every model-view matrix as a product of named factors, every light
//! position as OpenGL stores it (transformed by the model-view matrix *at the time of the
//! call*), every stack error — so checks can explain a student's frame and renderers can draw it.
//!
//! ```
//! use cg_core::gl::Gl;
//! use cg_core::shapes::lecture_pyramid;
//!
//! // The course's display(): camera, then the light (so it stays fixed in the world), then the
//! // object.
//! let mut gl = Gl::new();
//! gl.load_identity();
//! gl.translate(0.0, 0.0, -15.0);
//! gl.rotate(30.0, 1.0, 0.0, 0.0);
//! gl.light_position(0, [10.0, 10.0, 10.0, 1.0]);
//! gl.push_matrix();
//! gl.translate(0.0, 1.0, 0.0);
//! gl.draw("pyramid", &lecture_pyramid());
//! gl.pop_matrix();
//! assert_eq!(gl.draws()[0].model_view.numeric(), "T(0, 0, -15) · Rx(30°) · T(0, 1, 0)");
//! assert!(gl.errors().is_empty());
//! ```

use glam::{Mat4, Vec3, Vec4};

use crate::Rgb;
use crate::light::{LightKind, Material};
use crate::mesh::Mesh;
use crate::product::{Factor, MatrixProduct};
use crate::scene::{Camera, NormalSource, Object, Scene};
use crate::stack::{MatrixStack, StackError};

/// One recorded draw call: what was drawn, with which model-view matrix and colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Draw {
    /// The name given to the draw call (`"box 1"`, `"pyramid"`).
    pub name: String,
    /// The polygon model, in model space.
    pub mesh: Mesh,
    /// The model-view matrix at the time of the call, as named factors since the last
    /// `load_identity` (モデル座標系→カメラ座標系).
    pub model_view: MatrixProduct,
    /// The same matrix multiplied out.
    pub matrix: Mat4,
    /// The current colour (glColor3f; with colour material, k_a = k_d = this).
    pub color: Rgb,
    /// The index of the call among all calls of the frame (0-based).
    pub call: usize,
}

/// One recorded `glLightfv(GL_LIGHTi, GL_POSITION, p)`.
#[derive(Clone, Debug, PartialEq)]
pub struct LightPosition {
    /// Which light, 0–7.
    pub light: usize,
    /// The position as given (`w = 0`: a direction).
    pub given: Vec4,
    /// What OpenGL stores: the model-view matrix at the time of the call times `given`, in eye
    /// space (カメラ座標系).
    pub eye: Vec4,
    /// The model-view matrix at the time of the call, as named factors.
    pub model_view: MatrixProduct,
    /// The index of the call.
    pub call: usize,
}

/// A call OpenGL would have flagged (glGetError).
#[derive(Clone, Debug, PartialEq)]
pub struct GlError {
    /// The name of the call (`glPopMatrix`).
    pub function: &'static str,
    /// What went wrong.
    pub error: StackError,
    /// The index of the call.
    pub call: usize,
}

/// The recording context; see the module docs.
#[derive(Clone, Debug, PartialEq)]
pub struct Gl {
    stack: MatrixStack,
    color: Rgb,
    lights: Vec<LightPosition>,
    draws: Vec<Draw>,
    errors: Vec<GlError>,
    calls: usize,
}

impl Default for Gl {
    fn default() -> Gl {
        Gl::new()
    }
}

impl Gl {
    /// A fresh context: identity model-view matrix, white colour, nothing recorded.
    #[must_use]
    pub fn new() -> Gl {
        Gl {
            stack: MatrixStack::new(),
            color: Rgb::ONE,
            lights: Vec::new(),
            draws: Vec::new(),
            errors: Vec::new(),
            calls: 0,
        }
    }

    fn call(&mut self, function: &'static str, result: Result<(), StackError>) {
        if let Err(error) = result {
            self.errors.push(GlError { function, error, call: self.calls });
        }
        self.calls += 1;
    }

    /// glLoadIdentity.
    pub fn load_identity(&mut self) {
        self.stack.load_identity();
        self.call("glLoadIdentity", Ok(()));
    }

    /// glTranslatef(x, y, z).
    pub fn translate(&mut self, x: f32, y: f32, z: f32) {
        let r = self.stack.translate(Vec3::new(x, y, z));
        self.call("glTranslatef", r);
    }

    /// glRotatef(angle_deg, x, y, z): counter-clockwise by `angle_deg` degrees about the axis.
    /// A zero axis is recorded as an error (GL_INVALID_VALUE) and changes nothing.
    pub fn rotate(&mut self, angle_deg: f32, x: f32, y: f32, z: f32) {
        let r = self.stack.rotate_deg(angle_deg, Vec3::new(x, y, z));
        self.call("glRotatef", r);
    }

    /// glScalef(x, y, z).
    pub fn scale(&mut self, x: f32, y: f32, z: f32) {
        let r = self.stack.scale(Vec3::new(x, y, z));
        self.call("glScalef", r);
    }

    /// glMultMatrix with a named factor, so a report can print it symbolically
    /// (`Factor::rotate(Axis::Y, Param::sym("theta", 30.0))` prints as `Ry(theta)`).
    pub fn mult(&mut self, factor: Factor) {
        let r = self.stack.mult(factor);
        self.call("glMultMatrixf", r);
    }

    /// glPushMatrix. Beyond the stack's depth it is recorded as GL_STACK_OVERFLOW and ignored.
    pub fn push_matrix(&mut self) {
        let r = self.stack.push();
        self.call("glPushMatrix", r);
    }

    /// glPopMatrix. With nothing pushed it is recorded as GL_STACK_UNDERFLOW and ignored.
    pub fn pop_matrix(&mut self) {
        let r = self.stack.pop();
        self.call("glPopMatrix", r);
    }

    /// glLightfv(GL_LIGHTi, GL_POSITION, position): OpenGL multiplies the position by the
    /// current model-view matrix and keeps the result in eye space. A light index above 7 is
    /// ignored (OpenGL guarantees 8 lights).
    pub fn light_position(&mut self, light: usize, position: [f32; 4]) {
        if light < 8 {
            let given = Vec4::from_array(position);
            self.lights.retain(|l| l.light != light);
            self.lights.push(LightPosition {
                light,
                given,
                eye: self.stack.top() * given,
                model_view: self.stack.top_product().clone(),
                call: self.calls,
            });
        }
        self.call("glLightfv", Ok(()));
    }

    /// glColor3f(r, g, b).
    pub fn color(&mut self, r: f32, g: f32, b: f32) {
        self.color = Rgb::new(r, g, b);
        self.call("glColor3f", Ok(()));
    }

    /// Draws a polygon model with the current model-view matrix and colour (the course's
    /// `renderPolygon()` between glBegin and glEnd).
    pub fn draw(&mut self, name: &str, mesh: &Mesh) {
        self.draws.push(Draw {
            name: name.to_owned(),
            mesh: mesh.clone(),
            model_view: self.stack.top_product().clone(),
            matrix: self.stack.top(),
            color: self.color,
            call: self.calls,
        });
        self.call("draw", Ok(()));
    }

    /// Everything drawn, in order.
    #[must_use]
    pub fn draws(&self) -> &[Draw] {
        &self.draws
    }

    /// The last position set for each light, in the order they were set.
    #[must_use]
    pub fn lights(&self) -> &[LightPosition] {
        &self.lights
    }

    /// Every call OpenGL would have flagged, in order.
    #[must_use]
    pub fn errors(&self) -> &[GlError] {
        &self.errors
    }

    /// How deep the matrix stack is now (1 = nothing pushed): a frame that ends above 1 pushed
    /// more than it popped.
    #[must_use]
    pub fn depth(&self) -> usize {
        self.stack.depth()
    }

    /// The current model-view matrix as named factors.
    #[must_use]
    pub fn model_view(&self) -> &MatrixProduct {
        self.stack.top_product()
    }

    /// The recorded frame as a scene a renderer can draw: everything in eye space (the camera at
    /// the origin looking down −Z, so each draw's model-view matrix is its object's transform),
    /// window, projection, light model, light colours and attenuation from `template`, light `i`
    /// at the eye-space position recorded for it (a light never positioned stays where OpenGL
    /// puts it by default: `(0, 0, 1, 0)` in eye space, a light from behind the viewer), each
    /// object coloured by its glColor with colour material and drawn with face normals (one
    /// glNormal per face, as the course draws).
    #[must_use]
    pub fn to_scene(&self, template: &Scene) -> Scene {
        let mut scene = template.clone();
        scene.camera = Camera::LookAt { eye: Vec3::ZERO, target: Vec3::NEG_Z, up: Vec3::Y };
        for (i, light) in scene.lights.iter_mut().enumerate() {
            let eye = self.lights.iter().find(|l| l.light == i).map_or(Vec4::Z, |l| l.eye);
            light.kind = if eye.w == 0.0 {
                LightKind::Directional { to_light: eye.truncate() }
            } else {
                match light.kind {
                    LightKind::Spot { direction, cutoff_deg, exponent, inner_deg, .. } => {
                        LightKind::Spot {
                            position: eye.truncate() / eye.w,
                            direction,
                            cutoff_deg,
                            exponent,
                            inner_deg,
                        }
                    }
                    _ => LightKind::Point { position: eye.truncate() / eye.w },
                }
            };
        }
        scene.objects = self
            .draws
            .iter()
            .map(|d| Object {
                name: d.name.clone(),
                mesh: d.mesh.clone(),
                normals: NormalSource::Face,
                material: Material::from_color(d.color),
                transform: d.model_view.clone(),
                texture: None,
                weld: None,
                analytic: None,
            })
            .collect();
        scene
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::lecture_pyramid;
    use crate::stack::DEFAULT_MAX_DEPTH;
    use crate::transform::{rotate_x_deg, translate};

    fn course_camera(gl: &mut Gl) {
        gl.load_identity();
        gl.translate(0.0, 0.0, -15.0);
        gl.rotate(30.0, 1.0, 0.0, 0.0);
    }

    #[test]
    fn a_light_set_after_the_camera_stays_in_the_world() {
        let mut gl = Gl::new();
        course_camera(&mut gl);
        gl.light_position(0, [10.0, 10.0, 10.0, 1.0]);
        let view = translate(Vec3::new(0.0, 0.0, -15.0)) * rotate_x_deg(30.0);
        let expected = view * Vec4::new(10.0, 10.0, 10.0, 1.0);
        assert!((gl.lights()[0].eye - expected).abs().max_element() < 1e-5);
        // The classic mistake: the light set before the camera moves with the camera.
        let mut early = Gl::new();
        early.load_identity();
        early.light_position(0, [10.0, 10.0, 10.0, 1.0]);
        course_camera(&mut early);
        assert_eq!(early.lights()[0].eye, Vec4::new(10.0, 10.0, 10.0, 1.0));
        // Setting a light again replaces it.
        gl.light_position(0, [0.0, 1.0, 0.0, 0.0]);
        assert_eq!(gl.lights().len(), 1);
    }

    #[test]
    fn push_and_pop_scope_the_model_transform_and_errors_are_recorded() {
        let mut gl = Gl::new();
        course_camera(&mut gl);
        gl.push_matrix();
        gl.translate(0.0, 1.0, 0.0);
        gl.color(1.0, 0.5, 0.0);
        gl.draw("a", &lecture_pyramid());
        gl.pop_matrix();
        gl.draw("b", &lecture_pyramid());
        assert_eq!(gl.draws()[0].model_view.numeric(), "T(0, 0, -15) · Rx(30°) · T(0, 1, 0)");
        assert_eq!(gl.draws()[1].model_view.numeric(), "T(0, 0, -15) · Rx(30°)");
        assert_eq!(gl.draws()[0].color, Rgb::new(1.0, 0.5, 0.0));
        assert_eq!(gl.depth(), 1);
        assert!(gl.errors().is_empty());
        gl.pop_matrix();
        gl.rotate(10.0, 0.0, 0.0, 0.0);
        assert_eq!(gl.errors().len(), 2);
        assert_eq!(gl.errors()[0].function, "glPopMatrix");
        assert_eq!(gl.errors()[0].error, StackError::Underflow);
        assert_eq!(gl.errors()[1].function, "glRotatef");
        for _ in 0..DEFAULT_MAX_DEPTH {
            gl.push_matrix();
        }
        assert!(matches!(gl.errors().last().unwrap().error, StackError::Overflow { .. }));
    }

    #[test]
    fn a_recorded_frame_becomes_an_eye_space_scene() {
        let mut gl = Gl::new();
        course_camera(&mut gl);
        gl.light_position(0, [10.0, 10.0, 10.0, 1.0]);
        gl.translate(0.0, 1.0, 0.0);
        gl.draw("pyramid", &lecture_pyramid());
        let template = crate::scene::tests_support::course_like_scene();
        let s = gl.to_scene(&template);
        assert_eq!(s.view_product().unwrap().matrix().unwrap(), Mat4::IDENTITY);
        assert_eq!(s.objects.len(), 1);
        assert_eq!(s.objects[0].transform, gl.draws()[0].model_view);
        let LightKind::Point { position } = s.lights[0].kind else {
            panic!("{:?}", s.lights[0].kind)
        };
        assert!((position - gl.lights()[0].eye.truncate()).abs().max_element() < 1e-6);
        // A light never positioned is OpenGL's default, (0, 0, 1, 0) in eye space.
        let s = Gl::new().to_scene(&template);
        assert_eq!(s.lights[0].kind, LightKind::Directional { to_light: Vec3::Z });
    }
}
