//! The bridge from the students' API (`cg-student`, plain data and recorders) to the kit's own
//! types: a student's mesh, named-factor product and recorded `display()` become the [`Mesh`],
//! [`MatrixProduct`] and [`Gl`] that the checks and renderers work with.
//!
//! Every conversion is total: whatever a student returns converts, and the checks then say what
//! is wrong with it (an index out of range, a zero rotation axis, an unbalanced stack).

use cg_student::gl::{Gl as Recorded, GlCall};
use cg_student::mesh::Mesh as StudentMesh;
use cg_student::product as student;

use crate::gl::Gl;
use crate::mesh::Mesh;
use crate::product::{Axis, Factor, MatrixProduct, Param};

impl From<StudentMesh> for Mesh {
    fn from(mesh: StudentMesh) -> Mesh {
        Mesh::new(mesh.positions, mesh.faces)
    }
}

impl From<&StudentMesh> for Mesh {
    fn from(mesh: &StudentMesh) -> Mesh {
        Mesh::new(mesh.positions.clone(), mesh.faces.clone())
    }
}

impl From<&Mesh> for StudentMesh {
    /// The positions and faces (what a student's functions are given); other attributes dropped.
    fn from(mesh: &Mesh) -> StudentMesh {
        StudentMesh::new(mesh.positions.clone(), mesh.faces.clone())
    }
}

impl From<student::Param> for Param {
    fn from(p: student::Param) -> Param {
        Param { value: p.value, symbol: p.symbol }
    }
}

impl From<student::Axis> for Axis {
    fn from(a: student::Axis) -> Axis {
        match a {
            student::Axis::X => Axis::X,
            student::Axis::Y => Axis::Y,
            student::Axis::Z => Axis::Z,
            student::Axis::Any(v) => Axis::Any(v),
        }
    }
}

impl From<student::Factor> for Factor {
    fn from(f: student::Factor) -> Factor {
        let three = |[x, y, z]: [student::Param; 3]| [x.into(), y.into(), z.into()];
        match f {
            student::Factor::Translate(p) => Factor::Translate(three(p)),
            student::Factor::Rotate { axis, angle_deg } => {
                Factor::Rotate { axis: axis.into(), angle_deg: angle_deg.into() }
            }
            student::Factor::Scale(p) => Factor::Scale(three(p)),
            student::Factor::Perspective { fovy_deg, aspect, near, far, gl_depth } => {
                Factor::Perspective { fovy_deg, aspect, near, far, gl_depth }
            }
            student::Factor::Matrix { name, matrix } => Factor::Matrix { name, matrix },
        }
    }
}

impl From<student::MatrixProduct> for MatrixProduct {
    fn from(p: student::MatrixProduct) -> MatrixProduct {
        MatrixProduct { factors: p.factors.into_iter().map(Factor::from).collect() }
    }
}

/// The kit's factors as the students' API spells them: for tests and tools that stand in for a
/// student (a hand-written `display()` that multiplies a factor the kit computed).
impl From<Param> for student::Param {
    fn from(p: Param) -> student::Param {
        student::Param { value: p.value, symbol: p.symbol }
    }
}

impl From<Axis> for student::Axis {
    fn from(a: Axis) -> student::Axis {
        match a {
            Axis::X => student::Axis::X,
            Axis::Y => student::Axis::Y,
            Axis::Z => student::Axis::Z,
            Axis::Any(v) => student::Axis::Any(v),
        }
    }
}

impl From<Factor> for student::Factor {
    fn from(f: Factor) -> student::Factor {
        let three = |[x, y, z]: [Param; 3]| [x.into(), y.into(), z.into()];
        match f {
            Factor::Translate(p) => student::Factor::Translate(three(p)),
            Factor::Rotate { axis, angle_deg } => {
                student::Factor::Rotate { axis: axis.into(), angle_deg: angle_deg.into() }
            }
            Factor::Scale(p) => student::Factor::Scale(three(p)),
            Factor::Perspective { fovy_deg, aspect, near, far, gl_depth } => {
                student::Factor::Perspective { fovy_deg, aspect, near, far, gl_depth }
            }
            Factor::Matrix { name, matrix } => student::Factor::Matrix { name, matrix },
        }
    }
}

impl From<MatrixProduct> for student::MatrixProduct {
    fn from(p: MatrixProduct) -> student::MatrixProduct {
        student::MatrixProduct { factors: p.factors.into_iter().map(Into::into).collect() }
    }
}

impl Gl {
    /// Replays a student's recorded `display()` call by call on a fresh context, so the draws,
    /// lights and stack errors are what the same calls would give in OpenGL. `course_objects`
    /// draws what [`GlCall::CourseObjects`] stands for (the assignment knows its objects).
    pub fn replay(recorded: &Recorded, course_objects: &dyn Fn(&mut Gl)) -> Gl {
        let mut gl = Gl::new();
        for call in recorded.calls() {
            match call {
                GlCall::LoadIdentity => gl.load_identity(),
                GlCall::Translate([x, y, z]) => gl.translate(*x, *y, *z),
                GlCall::Rotate { angle_deg, axis: [x, y, z] } => gl.rotate(*angle_deg, *x, *y, *z),
                GlCall::Scale([x, y, z]) => gl.scale(*x, *y, *z),
                GlCall::Mult(factor) => gl.mult(factor.clone().into()),
                GlCall::PushMatrix => gl.push_matrix(),
                GlCall::PopMatrix => gl.pop_matrix(),
                GlCall::LightPosition { light, position } => gl.light_position(*light, *position),
                GlCall::Color([r, g, b]) => gl.color(*r, *g, *b),
                GlCall::Draw { name, mesh } => gl.draw(name, &Mesh::from(mesh)),
                GlCall::CourseObjects => course_objects(&mut gl),
            }
        }
        gl
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    #[test]
    fn a_replayed_recording_gives_what_the_same_calls_give() {
        let mut rec = Recorded::new();
        rec.load_identity();
        rec.translate(0.0, 0.0, -15.0);
        rec.mult(student::Factor::rotate(student::Axis::X, student::Param::sym("a", 30.0)));
        rec.light_position(0, [1.0, 2.0, 3.0, 1.0]);
        rec.color(1.0, 0.0, 0.0);
        rec.push_matrix();
        rec.draw("tri", &StudentMesh::new(vec![Vec3::X, Vec3::Y, Vec3::Z], vec![[0, 1, 2]]));
        rec.pop_matrix();
        rec.pop_matrix();
        let gl = Gl::replay(&rec, &|_| {});
        assert_eq!(gl.draws().len(), 1);
        assert_eq!(gl.draws()[0].model_view.symbolic(), "T(0, 0, -15) · Rx(a)");
        assert_eq!(gl.draws()[0].color, Vec3::new(1.0, 0.0, 0.0));
        assert_eq!(gl.lights().len(), 1);
        assert_eq!(gl.errors().len(), 1, "the unbalanced glPopMatrix is recorded");
    }

    #[test]
    fn a_product_goes_there_and_back_unchanged() {
        let p = MatrixProduct::identity()
            .then(Factor::translate(Vec3::new(1.0, -2.0, 3.0)))
            .then(Factor::rotate(Axis::Any(Vec3::ONE), Param::sym("t", 12.0)))
            .then(Factor::scale(Vec3::splat(2.0)))
            .then(Factor::perspective(45.0, 1.5, 0.1, 100.0))
            .then(Factor::named("M", glam::Mat4::IDENTITY));
        let there: student::MatrixProduct = p.clone().into();
        assert_eq!(MatrixProduct::from(there), p);
    }
}
