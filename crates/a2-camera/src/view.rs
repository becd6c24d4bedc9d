//! The scene the student's functions draw: [`view`], the kit's reference picture
//! ([`reference()`]), the course's objects ([`draw_course_objects`]) and the replay of a recorded
//! frame ([`replay`]) that the checks and the report use too.

use std::any::Any;
use std::panic::AssertUnwindSafe;
use std::sync::LazyLock;

use cg_core::Rgb;
use cg_core::gl::Gl;
use cg_core::mesh::Mesh;
use cg_core::product::MatrixProduct;
use cg_core::scene::Scene;
use cg_harness::Text;
use cg_harness::check::{Outcome, guarded};
use cg_harness::text::t;
use cg_worker::CallError;

use crate::{Impl, LIGHT0_POSITION, Spec};
use crate::{oracle, show};

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
/// A `motion()` not written yet (a `todo!()`) leaves the camera where it starts. One that
/// panics on a drag gives no picture (it would show the camera before that drag, unlike the
/// reference for no reason the student could see): the error names `motion()`, its message and
/// place, and the drag with the state it started from. A call that ran out of time, crashed the
/// worker or found the file not compiling goes on as it came (a panic with the call's
/// [`CallError`]), as `display()`'s would, so that `cg view` says so.
///
/// While `display()` is the stub with its marker (`cg_student::not_started("a2.t3")`) and draws
/// nothing, the view panics as a stub's `todo!()` does (quietly, with `resume_unwind`): a
/// `guarded` call around it reads "not done yet" ([`Outcome::NotDone`]).
///
/// # Errors
/// What keeps the result from being drawn, in words for the student: a `display()` that draws
/// nothing, or a `motion()` that panicked.
pub fn view(spec: &Spec, imp: &Impl, time_s: f64) -> Result<Scene, Text> {
    let mut state = spec.start;
    let drags = oracle::demo_drags(spec, time_s);
    for (k, drag) in drags.iter().enumerate() {
        let mut next = state;
        match guarded(|| panics_only(|| (imp.motion)(spec, &mut next, drag))) {
            Ok(Ok(())) => state = next,
            // Out of time, a crash, …: on as it came.
            Ok(Err(payload)) => std::panic::resume_unwind(payload),
            Err(Outcome::NotDone { .. }) => break,
            // A panic (`panics_only` lets nothing else through).
            Err(panicked) => {
                let on = show::drag(drag);
                let from = show::state(&state, spec.pan.is_some());
                let (n, why) = (drags.len(), panicked.of_function("motion()"));
                return Err(Text::new(
                    format!(
                        "{}。ドラッグ: {}（開始時 {from}。表示のためのドラッグ {n} 回中 {} 回目）。このドラッグより前のカメラの絵になってしまうので描きません",
                        why.ja,
                        on.ja,
                        k + 1
                    ),
                    format!(
                        "{}, on the drag {} from {from} (the view's drag {} of {n}); not drawn, as it would show the camera before that drag",
                        why.en,
                        on.en,
                        k + 1
                    ),
                ));
            }
        }
    }
    let mut rec = cg_student::gl::Gl::new();
    let before = cg_student::take_not_started();
    (imp.display)(&mut rec, &state);
    let reached = cg_student::take_not_started();
    // Put back for a check around the view (the report's), as the markers were.
    for task in before.iter().chain(&reached) {
        cg_student::not_started(task);
    }
    let gl = replay(&rec);
    if gl.draws().is_empty() {
        if reached.iter().any(|task| task == "a2.t3") {
            // The stub with its marker: not done yet, as a `todo!()` in it would say (and no
            // mistake: `cg view` ends with 0).
            let not_yet = t(
                "まだ何も描かれていません。display() で視点の変換・光源・物体を設定してください",
                "nothing is drawn yet: display() sets the camera, the light and the objects",
            );
            let message = format!("not yet implemented: a2.t3: {} / {}", not_yet.ja, not_yet.en);
            std::panic::resume_unwind(Box::new(message));
        }
        return Err(t(
            "何も描かれていません: display()（a2.t3）で視点の変換・光源・物体を設定し、draw_course_objects(gl) で描きます",
            "nothing is drawn: display() (a2.t3) sets the camera, the light and the objects, and draws them with draw_course_objects(gl)",
        ));
    }
    Ok(gl.to_scene(&cg_harness::course::stage()))
}

/// Calls `f`, a student's function: a panic of its own code (on this thread, or the worker's
/// [`CallError::Panicked`]) goes on, for the `guarded` around to read with its place; any other
/// end of the call (out of time, a crash, a file that does not compile) comes back as its
/// payload, to go on unchanged after that `guarded`.
fn panics_only(f: impl FnOnce()) -> Result<(), Box<dyn Any + Send>> {
    std::panic::catch_unwind(AssertUnwindSafe(f)).or_else(|payload| {
        match payload.downcast_ref::<CallError>() {
            Some(CallError::Panicked { .. }) | None => std::panic::resume_unwind(payload),
            Some(_) => Err(payload),
        }
    })
}

/// The kit's reference picture ([`cg_harness::Assignment::reference_view`]): [`view`]'s scene
/// for a correct answer, from the oracle alone. The scripted drags of [`view`] move the camera
/// by the `a2.t1` oracle's `motion()`, and the frame is `display()` as `a2.t3` asks for it on
/// the kit's [`Gl`]: the identity, the view transform of the `a2.t2` oracle
/// ([`crate::expected_product`]), the light at [`LIGHT0_POSITION`] after it (fixed in the
/// world), then [`draw_course_objects`].
#[must_use]
pub fn reference(spec: &Spec, time_s: f64) -> Scene {
    let mut state = spec.start;
    for drag in oracle::demo_drags(spec, time_s) {
        oracle::motion(spec, &mut state, &drag);
    }
    let mut gl = Gl::new();
    gl.load_identity();
    for factor in oracle::expected_product(spec, &state).factors {
        gl.mult(factor);
    }
    gl.light_position(0, LIGHT0_POSITION);
    draw_course_objects(&mut gl);
    gl.to_scene(&cg_harness::course::stage())
}

#[cfg(test)]
mod tests {
    use cg_core::glam::{Mat4, Vec3};
    use cg_core::light::LightKind;
    use cg_harness::{StudentNumber, TableVersion, VariantRng};

    use super::*;
    use crate::CameraState;

    /// Each object's matrix (eye space) and light 0's eye-space position.
    fn geometry(scene: &Scene) -> (Vec<(String, Mat4)>, Vec3) {
        let objects =
            scene.objects.iter().map(|o| (o.name.clone(), o.transform.matrix().unwrap())).collect();
        let LightKind::Point { position } = scene.lights[0].kind else { panic!("a point light") };
        (objects, position)
    }

    fn same(a: &Scene, b: &Scene) -> bool {
        let ((oa, la), (ob, lb)) = (geometry(a), geometry(b));
        oa.len() == ob.len()
            && oa.iter().zip(&ob).all(|((na, ma), (nb, mb))| na == nb && ma.abs_diff_eq(*mb, 1e-4))
            && la.abs_diff_eq(lb, 1e-3)
    }

    // A hand-written answer on the student's side of the API (not the reference solutions):
    // the oracle's motion, the course's camera, the light after it, the course's objects.
    fn motion(spec: &Spec, s: &mut CameraState, drag: &crate::Drag) {
        oracle::motion(spec, s, drag);
    }
    fn still(_: &Spec, _: &mut CameraState, _: &crate::Drag) {}
    fn camera(gl: &mut cg_student::gl::Gl, s: &CameraState) {
        gl.translate(0.0, 0.0, -s.camera_distance);
        gl.rotate(-s.camera_pitch, 1.0, 0.0, 0.0);
        gl.rotate(-s.camera_yaw, 0.0, 1.0, 0.0);
        gl.translate(-s.target_x, 0.0, -s.target_z);
    }
    fn display(gl: &mut cg_student::gl::Gl, s: &CameraState) {
        gl.load_identity();
        camera(gl, s);
        gl.light_position(0, LIGHT0_POSITION);
        cg_student::a2::draw_course_objects(gl);
    }
    fn light_first(gl: &mut cg_student::gl::Gl, s: &CameraState) {
        gl.load_identity();
        gl.light_position(0, LIGHT0_POSITION);
        camera(gl, s);
        cg_student::a2::draw_course_objects(gl);
    }

    #[test]
    fn the_reference_is_a_correct_answers_view_and_not_a_wrong_ones() {
        let right = Impl { motion, camera, display };
        let unmoved = Impl { motion: still, ..right };
        let early_light = Impl { display: light_first, ..right };
        for number in ["12345678", "20260002", "31415926"] {
            let student: StudentNumber = number.parse().unwrap();
            let spec = crate::variant(&mut VariantRng::new(&student, TableVersion::V1, crate::ID));
            for time_s in [0.0, 1.6, 7.3] {
                let reference = reference(&spec, time_s);
                assert_eq!(reference.objects.len(), 2, "the ground and the pyramid");
                assert!(
                    same(&reference, &view(&spec, &right, time_s).unwrap()),
                    "{number} {time_s}"
                );
                assert!(!same(&reference, &view(&spec, &unmoved, time_s).unwrap()));
                assert!(!same(&reference, &view(&spec, &early_light, time_s).unwrap()));
            }
        }
    }
}
