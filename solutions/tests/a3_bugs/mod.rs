//! The broken answers of a3's tests: each the reference answer with one realistic mistake
//! (`Bug`), and the checks each must fail and pass ([`broken_answers`]).

use super::*;

// ---------------------------------------------------------------------------------------------
// Broken answers. They share the reference solution's layout of `state.params` (params[2i]: the
// angle in degrees or a hop's offset; params[2i + 1]: a hop's height), so each differs from the
// solution in exactly one realistic mistake.
// ---------------------------------------------------------------------------------------------

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub(super) enum Bug {
    None,
    // idle
    WrongPeriod,
    Radians,
    F32Accumulate,
    OneFrameLate,
    ThirtyFps,
    LinearHop,
    /// Every angle with the wrong sign (turns and swings the wrong way), at every frame, exactly:
    /// a wrong pose, not drift.
    MirroredTurn,
    /// A swing's degrees handed to `sin` as radians: `A * (360.0 * frame / 60.0 / T).sin()`.
    SineOfDegrees,
    // display
    NoPushPop,
    ExtraPop,
    MissingPop,
    /// The child's `gl.pop_matrix()` left out: its parent's `pop_matrix()` pops the child's
    /// push, and the parent's transforms stay applied to the objects drawn after it.
    ChildMissingPop,
    /// No push/pop at all, and the last object runs with the first object's period: its wrong
    /// period is measured with the earlier objects' transforms still applied.
    LeakAndWrongPeriod,
    LightBeforeCamera,
    ChildReversed,
    ChildOutsideParent,
    ChildIgnoresParentRotation,
    WrongNames,
    WrongMesh,
    // warm-up
    WarmupNoPushPop,
    WarmupExtraPop,
    WarmupRadians,
    /// Box 2's degrees handed to `sin` as radians: `30.0 * (360.0 * t / 2.0).sin()`.
    WarmupSineOfDegrees,
    WarmupLinearHop,
    WarmupWrongHeight,
}

pub(super) fn idle_with(bug: Bug, spec: &Spec, state: &mut State) {
    if bug != Bug::OneFrameLate {
        state.frame += 1;
    }
    let n = spec.objects.len();
    for (i, object) in spec.objects.iter().enumerate() {
        let own = object.motion.period_frames();
        // WrongPeriod: the first object runs with the next object's period.
        let p = if bug == Bug::WrongPeriod && i == 0 {
            spec.objects[1 % n].motion.period_frames()
        } else if bug == Bug::LeakAndWrongPeriod && i + 1 == n {
            spec.objects[0].motion.period_frames()
        } else {
            own
        };
        let frame = if bug == Bug::ThirtyFps { 2 * state.frame } else { state.frame };
        let u = (frame % p) as f64 / p as f64;
        let (a, b) = match object.motion {
            Motion::Spin { turn, .. }
            | Motion::Orbit { turn, .. }
            | Motion::Satellite { turn, .. } => {
                if bug == Bug::F32Accumulate {
                    // θ += ω·Δt in f32, wrapped: the classic GLUT idle().
                    let step = turn.sign() * 360.0 / object.motion.period_s() * (1.0 / 60.0_f32);
                    let mut theta = state.params[2 * i] + step;
                    if theta >= 360.0 {
                        theta -= 360.0;
                    } else if theta < 0.0 {
                        theta += 360.0;
                    }
                    (f64::from(theta), 0.0)
                } else {
                    (f64::from(turn.sign()) * 360.0 * u, 0.0)
                }
            }
            Motion::Swing { amplitude_deg, period_s, .. } => {
                if bug == Bug::SineOfDegrees {
                    // 360·t/T is in degrees; f64::sin takes radians.
                    let t = state.frame as f64 / 60.0;
                    (f64::from(amplitude_deg) * (360.0 * t / f64::from(period_s)).sin(), 0.0)
                } else if bug == Bug::F32Accumulate {
                    let step = 360.0 / object.motion.period_s() * (1.0 / 60.0_f32);
                    let phase = (state.params[2 * i + 1] + step) % 360.0;
                    state.params[2 * i + 1] = phase;
                    (
                        f64::from(amplitude_deg) * f64::from(phase).to_radians().sin(),
                        f64::from(phase),
                    )
                } else {
                    (f64::from(amplitude_deg) * (TAU * u).sin(), 0.0)
                }
            }
            Motion::Hop { span, height, .. } => {
                let w = if u < 0.5 { 2.0 * u } else { 2.0 - 2.0 * u };
                let s = f64::from(span) * (w - 0.5);
                let half = f64::from(span) / 2.0;
                let y = if bug == Bug::LinearHop {
                    f64::from(height) * (1.0 - (s / half).abs())
                } else {
                    f64::from(height) * (1.0 - (s / half) * (s / half))
                };
                (s, y)
            }
        };
        let a = if bug == Bug::Radians && !matches!(object.motion, Motion::Hop { .. }) {
            a.to_radians()
        } else {
            a
        };
        let a = if bug == Bug::MirroredTurn && !matches!(object.motion, Motion::Hop { .. }) {
            -a
        } else {
            a
        };
        state.params[2 * i] = a as f32;
        state.params[2 * i + 1] = b as f32;
    }
    if bug == Bug::OneFrameLate {
        state.frame += 1;
    }
}

pub(super) fn place(gl: &mut Gl, state: &State, i: usize, object: &Object, bug: Bug) {
    let (a, b) = (state.params[2 * i], state.params[2 * i + 1]);
    let v = |w: WorldAxis| w.vector();
    match object.motion {
        Motion::Spin { position: [x, y, z], axis, .. } => {
            gl.translate(x, y, z);
            let r = v(axis);
            gl.rotate(a, r.x, r.y, r.z);
        }
        Motion::Swing { pivot: [x, y, z], axis, arm, .. } => {
            gl.translate(x, y, z);
            let r = v(axis);
            gl.rotate(a, r.x, r.y, r.z);
            gl.translate(0.0, -arm, 0.0);
        }
        Motion::Hop { center: [x, y, z], along, .. } => {
            let d = v(along) * a;
            gl.translate(x + d.x, y + b, z + d.z);
        }
        Motion::Orbit { center: [x, y, z], radius, .. } => {
            gl.translate(x, y, z);
            gl.rotate(a, 0.0, 1.0, 0.0);
            gl.translate(0.0, 0.0, radius);
        }
        Motion::Satellite { radius, .. } => {
            if bug == Bug::ChildReversed {
                gl.translate(0.0, 0.0, radius);
                gl.rotate(a, 0.0, 1.0, 0.0);
            } else {
                gl.rotate(a, 0.0, 1.0, 0.0);
                gl.translate(0.0, 0.0, radius);
            }
        }
    }
}

pub(super) fn draw(gl: &mut Gl, object: &Object, bug: Bug) {
    let name = if bug == Bug::WrongNames {
        object.name.replace("object ", "obj")
    } else {
        object.name.clone()
    };
    let mesh = if bug == Bug::WrongMesh {
        (&cg_core::shapes::cuboid(Vec3::ONE).unwrap()).into()
    } else {
        object.mesh.clone()
    };
    gl.draw(&name, &mesh);
}

pub(super) fn display_with(bug: Bug, spec: &Spec, state: &State, gl: &mut Gl) {
    gl.load_identity();
    if bug == Bug::LightBeforeCamera {
        gl.light_position(0, [10.0, 10.0, 10.0, 1.0]);
    }
    gl.translate(0.0, 0.0, -15.0);
    gl.rotate(30.0, 1.0, 0.0, 0.0);
    if bug != Bug::LightBeforeCamera {
        gl.light_position(0, [10.0, 10.0, 10.0, 1.0]);
    }
    let no_push_pop = matches!(bug, Bug::NoPushPop | Bug::LeakAndWrongPeriod);
    let push = |gl: &mut Gl| {
        if !no_push_pop {
            gl.push_matrix();
        }
    };
    let pop = |gl: &mut Gl| {
        if !no_push_pop {
            gl.pop_matrix();
        }
    };
    for (i, object) in spec.objects.iter().enumerate() {
        if object.motion.parent().is_some() {
            continue;
        }
        push(gl);
        place(gl, state, i, object, bug);
        draw(gl, object, bug);
        for c in spec.children(i) {
            if bug == Bug::ChildOutsideParent {
                continue;
            }
            push(gl);
            if bug == Bug::ChildIgnoresParentRotation {
                // Back to the camera, then only the parent's position.
                gl.load_identity();
                gl.translate(0.0, 0.0, -15.0);
                gl.rotate(30.0, 1.0, 0.0, 0.0);
                let p = cg_a3::expected_model(spec, i, state.frame).w_axis;
                gl.translate(p.x as f32, p.y as f32, p.z as f32);
            }
            place(gl, state, c, &spec.objects[c], bug);
            draw(gl, &spec.objects[c], bug);
            if bug != Bug::ChildMissingPop {
                pop(gl);
            }
        }
        if bug != Bug::MissingPop {
            pop(gl);
        }
    }
    if bug == Bug::ChildOutsideParent {
        for (c, object) in
            spec.objects.iter().enumerate().filter(|(_, o)| o.motion.parent().is_some())
        {
            push(gl);
            place(gl, state, c, object, bug);
            draw(gl, object, bug);
            pop(gl);
        }
    }
    if bug == Bug::ExtraPop {
        gl.pop_matrix();
    }
}

pub(super) fn warmup_with(bug: Bug, gl: &mut Gl, t: f64) {
    let mesh = cg_student::a3::warmup_box();
    let push = |gl: &mut Gl| {
        if bug != Bug::WarmupNoPushPop {
            gl.push_matrix();
        }
    };
    let pop = |gl: &mut Gl| {
        if bug != Bug::WarmupNoPushPop {
            gl.pop_matrix();
        }
    };
    let deg = |d: f64| if bug == Bug::WarmupRadians { d.to_radians() } else { d } as f32;
    push(gl);
    gl.translate(-3.0, 1.0, 0.0);
    gl.rotate(deg(360.0 * (t / 4.0).rem_euclid(1.0)), 0.0, 1.0, 0.0);
    gl.draw("box 1", &mesh);
    pop(gl);
    push(gl);
    gl.translate(0.0, 1.0, 0.0);
    let swing = if bug == Bug::WarmupSineOfDegrees {
        30.0 * (360.0 * t / 2.0).sin()
    } else {
        30.0 * (TAU * (t / 2.0).rem_euclid(1.0)).sin()
    };
    gl.rotate(deg(swing), 0.0, 0.0, 1.0);
    gl.draw("box 2", &mesh);
    pop(gl);
    push(gl);
    let u = (t / 2.0).rem_euclid(1.0);
    let w = if u < 0.5 { 2.0 * u } else { 2.0 - 2.0 * u };
    let x = 2.0 * w - 1.0;
    let y = match bug {
        Bug::WarmupLinearHop => 1.5 * (1.0 - x.abs()),
        Bug::WarmupWrongHeight => 1.0 * (1.0 - x * x),
        _ => 1.5 * (1.0 - x * x),
    };
    gl.translate((3.0 + x) as f32, (0.3 + y) as f32, 0.0);
    gl.draw("box 3", &mesh);
    pop(gl);
    if bug == Bug::WarmupExtraPop {
        gl.pop_matrix();
    }
}

macro_rules! imp_for {
    ($bug:expr) => {{
        fn idle(spec: &Spec, state: &mut State) {
            idle_with($bug, spec, state)
        }
        fn display(spec: &Spec, state: &State, gl: &mut Gl) {
            display_with($bug, spec, state, gl)
        }
        fn warmup(gl: &mut Gl, t: f64) {
            warmup_with($bug, gl, t)
        }
        Impl { warmup_display: warmup, idle, display }
    }};
}

/// Every broken answer with the checks it must fail and some it must still pass (so the checks
/// name the mistake instead of failing everything).
pub(super) fn broken_answers() -> Vec<(Bug, Impl, &'static [&'static str], &'static [&'static str])>
{
    vec![
        (Bug::None, imp_for!(Bug::None), &[], &[]),
        (
            Bug::WrongPeriod,
            imp_for!(Bug::WrongPeriod),
            &["a3.t1.periods", "a3.t1.ratios", "a3.t2.poses"],
            &["a3.t2.stack", "a3.t2.independent", "a3.t2.light", "a3.t1.drift"],
        ),
        (
            Bug::Radians,
            imp_for!(Bug::Radians),
            &["a3.t1.periods", "a3.t1.ratios", "a3.t1.drift", "a3.t2.poses"],
            &["a3.t2.stack", "a3.t2.light", "a3.t2.objects"],
        ),
        (
            Bug::F32Accumulate,
            imp_for!(Bug::F32Accumulate),
            &["a3.t1.drift"],
            &["a3.t2.poses", "a3.t1.periods", "a3.t1.ratios", "a3.t2.hierarchy"],
        ),
        (
            Bug::SineOfDegrees,
            imp_for!(Bug::SineOfDegrees),
            &["a3.t1.periods", "a3.t1.ratios", "a3.t2.poses"],
            &["a3.t2.stack", "a3.t2.independent", "a3.t2.hierarchy", "a3.t2.light"],
        ),
        (
            Bug::MirroredTurn,
            imp_for!(Bug::MirroredTurn),
            &["a3.t2.poses"],
            &["a3.t1.periods", "a3.t1.ratios", "a3.t1.drift", "a3.t2.stack"],
        ),
        (
            Bug::OneFrameLate,
            imp_for!(Bug::OneFrameLate),
            &["a3.t2.poses"],
            &["a3.t1.periods", "a3.t1.ratios", "a3.t2.stack"],
        ),
        (
            Bug::ThirtyFps,
            imp_for!(Bug::ThirtyFps),
            &["a3.t1.periods", "a3.t2.poses"],
            &["a3.t1.ratios", "a3.t2.stack", "a3.t1.drift"],
        ),
        (
            Bug::LinearHop,
            imp_for!(Bug::LinearHop),
            &["a3.t2.poses"],
            &["a3.t1.periods", "a3.t2.hierarchy"],
        ),
        (
            Bug::NoPushPop,
            imp_for!(Bug::NoPushPop),
            &["a3.t2.poses", "a3.t2.independent"],
            // idle() is right: the leak is display()'s (a3.t2), so a3.t1 is not named to fix.
            &[
                "a3.t2.stack",
                "a3.t2.light",
                "a3.t2.objects",
                "a3.t1.periods",
                "a3.t1.ratios",
                "a3.t1.drift",
            ],
        ),
        (
            Bug::ExtraPop,
            imp_for!(Bug::ExtraPop),
            &["a3.t2.stack"],
            &[
                "a3.t2.poses",
                "a3.t2.independent",
                "a3.t2.hierarchy",
                "a3.t1.periods",
                "a3.t1.drift",
            ],
        ),
        (Bug::MissingPop, imp_for!(Bug::MissingPop), &["a3.t2.stack"], &["a3.t2.light"]),
        (
            Bug::ChildMissingPop,
            imp_for!(Bug::ChildMissingPop),
            &["a3.t2.stack", "a3.t2.independent", "a3.t2.poses"],
            // idle() is right: the parent's transforms left on object 4 are display()'s (a3.t2).
            &["a3.t1.periods", "a3.t1.ratios", "a3.t1.drift", "a3.t2.hierarchy", "a3.t2.light"],
        ),
        (
            Bug::LeakAndWrongPeriod,
            imp_for!(Bug::LeakAndWrongPeriod),
            &["a3.t1.periods", "a3.t1.ratios", "a3.t2.independent"],
            &["a3.t2.light"],
        ),
        (
            Bug::LightBeforeCamera,
            imp_for!(Bug::LightBeforeCamera),
            &["a3.t2.light"],
            &["a3.t2.poses", "a3.t2.stack", "a3.t1.drift"],
        ),
        (
            Bug::ChildReversed,
            imp_for!(Bug::ChildReversed),
            &["a3.t2.hierarchy", "a3.t2.poses"],
            &["a3.t2.independent", "a3.t2.stack", "a3.t1.periods", "a3.t1.drift"],
        ),
        (
            Bug::ChildOutsideParent,
            imp_for!(Bug::ChildOutsideParent),
            &["a3.t2.hierarchy", "a3.t2.poses"],
            &["a3.t2.independent", "a3.t2.stack"],
        ),
        (
            Bug::ChildIgnoresParentRotation,
            imp_for!(Bug::ChildIgnoresParentRotation),
            &["a3.t2.hierarchy", "a3.t2.poses"],
            &["a3.t2.independent", "a3.t2.light"],
        ),
        (
            Bug::WrongNames,
            imp_for!(Bug::WrongNames),
            &["a3.t2.objects", "a3.t2.poses"],
            &["a3.t2.light"],
        ),
        (
            Bug::WrongMesh,
            imp_for!(Bug::WrongMesh),
            &["a3.t2.objects"],
            &["a3.t2.poses", "a3.t2.hierarchy", "a3.t1.drift"],
        ),
        (
            Bug::WarmupNoPushPop,
            imp_for!(Bug::WarmupNoPushPop),
            &["a3.t0.box2", "a3.t0.box3"],
            &["a3.t0.box1", "a3.t0.stack"],
        ),
        (
            Bug::WarmupExtraPop,
            imp_for!(Bug::WarmupExtraPop),
            &["a3.t0.stack"],
            &["a3.t0.box1", "a3.t0.box2", "a3.t0.box3"],
        ),
        (
            Bug::WarmupRadians,
            imp_for!(Bug::WarmupRadians),
            &["a3.t0.box1", "a3.t0.box2"],
            &["a3.t0.box3", "a3.t0.stack"],
        ),
        (
            Bug::WarmupSineOfDegrees,
            imp_for!(Bug::WarmupSineOfDegrees),
            &["a3.t0.box2"],
            &["a3.t0.box1", "a3.t0.box3", "a3.t0.stack"],
        ),
        (
            Bug::WarmupLinearHop,
            imp_for!(Bug::WarmupLinearHop),
            &["a3.t0.box3"],
            &["a3.t0.box1", "a3.t0.box2"],
        ),
        (
            Bug::WarmupWrongHeight,
            imp_for!(Bug::WarmupWrongHeight),
            &["a3.t0.box3"],
            &["a3.t0.stack"],
        ),
    ]
}
