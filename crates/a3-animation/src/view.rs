//! The scene the student's functions draw (`a3`): [`view`] (the spec's animation at a time),
//! [`warmup_view`] (the warm-up's boxes), the frames they come from ([`record_frame`],
//! [`warmup_frame`], [`replay`]) and the course's ground under them; and the kit's reference
//! picture, [`reference()`], drawn from the oracle.

use cg_core::gl::Gl;
use cg_core::product::Factor;
use cg_core::scene::Scene;
use cg_harness::Text;

use crate::{
    CAMERA_DISTANCE, CAMERA_PITCH_DEG, DRIFT_FRAMES, FPS, Impl, LIGHT0_POSITION, Spec, State,
    camera_product, expected_model,
};

/// Sets the common camera and the light, as the warm-up's `display()` does before the boxes:
/// `glLoadIdentity`, `T(0, 0, -15)`, `Rx(30°)`, `glLightfv(GL_LIGHT0, GL_POSITION, (10, 10, 10, 1))`
/// — on the student's recorder, so the call numbers of a replayed frame count them.
pub(crate) fn camera_and_light(gl: &mut cg_student::gl::Gl) {
    gl.load_identity();
    gl.translate(0.0, 0.0, -CAMERA_DISTANCE);
    gl.rotate(-CAMERA_PITCH_DEG, 1.0, 0.0, 0.0);
    gl.light_position(0, LIGHT0_POSITION);
}

/// The state after `frames` calls of `idle` from the start.
fn run_idle(spec: &Spec, imp: &Impl, frames: u64) -> State {
    let mut state = State::new();
    for _ in 0..frames {
        (imp.idle)(spec, &mut state);
    }
    state
}

/// The frame after `frames` calls of `idle` from the start, as `display` records it: every
/// draw's model-view matrix as a product of named factors (with the student's symbols where
/// `gl.mult(Factor::rotate(…, Param::sym(…)))` was used), the light, the stack errors — what a
/// report derives the transforms from.
#[must_use]
pub fn record_frame(spec: &Spec, imp: &Impl, frames: u64) -> Gl {
    let state = run_idle(spec, imp, frames);
    let mut rec = cg_student::gl::Gl::new();
    (imp.display)(spec, &state, &mut rec);
    replay(&rec)
}

/// A student's recorded frame replayed on the kit's [`Gl`]: the draws (with their model-view
/// matrices), lights and stack errors the same calls give in OpenGL. This assignment draws no
/// course objects.
#[must_use]
pub fn replay(recorded: &cg_student::gl::Gl) -> Gl {
    Gl::replay(recorded, &|_| {})
}

/// The longest time [`view`] animates to (s): 10⁶ frames. `cg view --time` is checked against it.
pub const VIEW_MAX_S: f64 = DRIFT_FRAMES as f64 / FPS as f64;

/// The scene that shows `imp`'s result at time `time_s` (seconds): `idle` called
/// `round(60·time_s)` times from the start, but at least once, then `display` recorded and drawn
/// in eye space on the course's ground (the ground with the kit's camera, so a wrong camera shows
/// as objects off the ground). A frame that draws nothing shows the ground alone.
///
/// At least one `idle()`: before it, `display()` reads `State::new()`, whose parameters are all
/// 0 whatever they mean in the student's own layout, so that picture says nothing (the report
/// skips it too) and could not be compared with the kit's reference.
///
/// # Errors
/// A time that is negative, not finite or beyond 10⁶ frames.
pub fn view(spec: &Spec, imp: &Impl, time_s: f64) -> Result<Scene, Text> {
    if !time_s.is_finite() || !(0.0..=VIEW_MAX_S).contains(&time_s) {
        return Err(Text::new(
            format!(
                "時刻は 0 以上 {VIEW_MAX_S:.0} 秒以下にしてください（{time_s} が指定されました）"
            ),
            format!("the time must be between 0 and {VIEW_MAX_S:.0} s (got {time_s})"),
        ));
    }
    Ok(on_ground(&record_frame(spec, imp, frame_at(time_s))))
}

/// The frame [`view`] draws at `time_s`: `round(60·time_s)`, at least 1.
fn frame_at(time_s: f64) -> u64 {
    ((time_s * f64::from(FPS)).round() as u64).max(1)
}

/// The kit's reference picture ([`cg_harness::Assignment::reference_view`]): [`view`]'s scene
/// for a correct answer, from the oracle alone. At [`view`]'s frame (frame 1 for a time [`view`]
/// rejects), `display()` as `a3.t2` asks for it on the kit's [`Gl`]: the common camera and the
/// light, then each object between `glPushMatrix` and `glPopMatrix` with its colour and its model
/// matrix (the oracle's [`expected_model`], in f64 at the exact phase; a child's includes its
/// parent's), parents first, each followed by its children, as a correct `display()` nests them.
/// On the course's ground, as [`view`].
#[must_use]
pub fn reference(spec: &Spec, time_s: f64) -> Scene {
    let frame = if time_s.is_finite() && (0.0..=VIEW_MAX_S).contains(&time_s) {
        frame_at(time_s)
    } else {
        1
    };
    let mut gl = Gl::new();
    gl.load_identity();
    gl.translate(0.0, 0.0, -CAMERA_DISTANCE);
    gl.rotate(-CAMERA_PITCH_DEG, 1.0, 0.0, 0.0);
    gl.light_position(0, LIGHT0_POSITION);
    let roots = (0..spec.objects.len()).filter(|&i| spec.objects[i].motion.parent().is_none());
    for i in roots.flat_map(|i| std::iter::once(i).chain(spec.children(i))) {
        let object = &spec.objects[i];
        gl.push_matrix();
        let model = expected_model(spec, i, frame).as_mat4();
        gl.mult(Factor::named(format!("M_{}", i + 1), model));
        let [r, g, b] = object.color;
        gl.color(r, g, b);
        gl.draw(&object.name, &cg_core::mesh::Mesh::from(&object.mesh));
        gl.pop_matrix();
    }
    on_ground(&gl)
}

/// The warm-up's frame at time `t` (s): the camera and light set, then `warmup_display`.
#[must_use]
pub fn warmup_frame(imp: &Impl, t: f64) -> Gl {
    let mut rec = cg_student::gl::Gl::new();
    camera_and_light(&mut rec);
    (imp.warmup_display)(&mut rec, t);
    replay(&rec)
}

/// The warm-up's three boxes at time `t` (s), drawn like [`view`].
#[must_use]
pub fn warmup_view(imp: &Impl, t: f64) -> Scene {
    on_ground(&warmup_frame(imp, t))
}

/// A recorded frame as a scene on the course's stage, with the course's ground added in eye
/// space.
fn on_ground(gl: &Gl) -> Scene {
    let mut scene = gl.to_scene(&cg_harness::course::stage());
    let view = cg_harness::course::scene().view_product().unwrap_or_else(|_| camera_product());
    let mut ground = cg_harness::course::ground_only().objects;
    for g in &mut ground {
        g.transform = view.concat(&g.transform);
    }
    ground.append(&mut scene.objects);
    scene.objects = ground;
    scene
}

#[cfg(test)]
mod tests {
    use cg_core::glam::DMat4;

    use super::*;
    use crate::SpecExt;
    use crate::spec::spec_of;

    #[test]
    fn the_view_rejects_bad_times() {
        fn nothing(_: &mut cg_student::gl::Gl, _: f64) {}
        fn idle(_: &Spec, s: &mut State) {
            s.frame += 1;
        }
        fn display(_: &Spec, _: &State, _: &mut cg_student::gl::Gl) {}
        let imp = Impl { warmup_display: nothing, idle, display };
        let spec = spec_of(12_345_678);
        assert!(view(&spec, &imp, -1.0).is_err());
        assert!(view(&spec, &imp, f64::NAN).is_err());
        assert!(view(&spec, &imp, 1e9).is_err());
        let scene = view(&spec, &imp, 1.0).unwrap();
        assert_eq!(scene.objects.len(), 1, "the ground alone");
        assert_eq!(warmup_view(&imp, 0.0).objects.len(), 1);
    }

    /// The drawn object named `name`'s model matrix (world), the camera taken off.
    fn drawn_model(scene: &Scene, name: &str) -> DMat4 {
        let object = scene.objects.iter().find(|o| o.name == name).expect("drawn");
        crate::pose::view().inverse() * object.transform.matrix().unwrap().as_dmat4()
    }

    #[test]
    fn the_reference_draws_the_oracles_poses_on_the_ground() {
        for n in [12_345_678, 20_260_002, 31_415_926] {
            let spec = spec_of(n);
            for time_s in [0.37 * spec.common_period_s(), 1.6] {
                let frame = (time_s * 60.0).round() as u64;
                let scene = reference(&spec, time_s);
                assert_eq!(scene.objects.len(), 1 + spec.objects.len(), "the ground and each");
                assert_eq!(scene.objects[0].name, "ground");
                for (i, object) in spec.objects.iter().enumerate() {
                    let m = drawn_model(&scene, &object.name);
                    assert!(m.abs_diff_eq(expected_model(&spec, i, frame), 1e-4), "{n} {i}");
                    let drawn = scene.objects.iter().find(|o| o.name == object.name).unwrap();
                    assert_eq!(drawn.material.kd.to_array(), object.color);
                }
            }
        }
    }

    #[test]
    fn the_view_starts_after_the_first_idle_as_the_reference_does() {
        fn nothing(_: &mut cg_student::gl::Gl, _: f64) {}
        fn idle(_: &Spec, s: &mut State) {
            s.frame += 1;
        }
        // Draws its first object only once idle() has run exactly once.
        fn display(spec: &Spec, s: &State, gl: &mut cg_student::gl::Gl) {
            if s.frame == 1 {
                gl.draw(&spec.objects[0].name, &spec.objects[0].mesh);
            }
        }
        let imp = Impl { warmup_display: nothing, idle, display };
        let spec = spec_of(20_260_002);
        assert_eq!(view(&spec, &imp, 0.0).unwrap().objects.len(), 2, "frame 1 at t = 0");
        assert_eq!(view(&spec, &imp, 1.0 / 60.0).unwrap().objects.len(), 2);
        assert_eq!(view(&spec, &imp, 2.0 / 60.0).unwrap().objects.len(), 1, "frame 2");
        let name = &spec.objects[0].name;
        let at_start = drawn_model(&reference(&spec, 0.0), name);
        assert!(at_start.abs_diff_eq(expected_model(&spec, 0, 1), 1e-5));
        assert!(!at_start.abs_diff_eq(expected_model(&spec, 0, 30), 1e-3), "it moves");
    }
}
