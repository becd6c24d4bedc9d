//! The scene the student's functions draw: [`view`], the course's objects
//! ([`draw_course_objects`]) and the replay of a recorded frame ([`replay`]) that the checks
//! and the report use too.

use std::sync::LazyLock;

use cg_core::Rgb;
use cg_core::gl::Gl;
use cg_core::mesh::Mesh;
use cg_core::product::MatrixProduct;
use cg_core::scene::Scene;
use cg_harness::Text;
use cg_harness::text::t;

use crate::oracle;
use crate::{Impl, Spec};

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
pub fn draw_course_objects(gl: &mut cg_core::gl::Gl) {
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

/// A student's recorded frame replayed on the kit's [`Gl`], with [`draw_course_objects`] for
/// the course's objects: the draws, lights and stack errors the same calls give in OpenGL.
#[must_use]
pub fn replay(recorded: &cg_student::gl::Gl) -> Gl {
    Gl::replay(recorded, &draw_course_objects)
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
    let mut rec = cg_student::gl::Gl::new();
    (imp.display)(&mut rec, &state);
    let gl = replay(&rec);
    if gl.draws().is_empty() {
        return Err(t(
            "まだ何も描かれていません: display()（a2.t3）で視点の変換・光源・物体を設定してください",
            "nothing is drawn yet: display() (a2.t3) sets the camera, the light and the objects",
        ));
    }
    Ok(gl.to_scene(&cg_harness::course::stage()))
}
