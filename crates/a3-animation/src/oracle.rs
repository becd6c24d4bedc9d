//! What each object's model matrix (モデル座標系→ワールド座標系) must be: computed in f64 from the
//! exact phase `u = (frame mod P) / P` (an independent oracle: the motion's formula, not the
//! reference solution's calls), and the same transform as a product of named factors for
//! messages and the report (`T(0, 1, 0) · Ry(theta_1) · T(0, 0, 2)`).

use std::f64::consts::TAU;

use cg_core::glam::{DMat4, DVec3, Vec3};
use cg_core::product::{Axis, Factor, MatrixProduct, Param};

use crate::{Motion, Object, Spec, WorldAxis};

/// How a motion can be evaluated wrongly on purpose, to name a student's mistake.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Variation {
    /// Multiplies every angle (π/180: the angle was meant in radians).
    pub angle_scale: f64,
    /// Multiplies every angle's sign (−1: the wrong way round).
    pub sign: f64,
    /// Rotation and translation in the other order (`T · R` instead of `R · T` and so on).
    pub reversed: bool,
    /// Another period (frames) in place of the motion's own.
    pub period: Option<u64>,
    /// What a swing's sine is taken of.
    pub sine: Sine,
}

/// What a swing's `θ = A·sin(…)` is evaluated of: the specified radians, or the degrees of the
/// phase handed to `sin` as they are (`(360.0 * t / T).sin()`, the common mistake: `f64::sin`
/// takes radians).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Sine {
    /// `sin(2π·u)`, as specified.
    Radians,
    /// `sin(360·u)` of the phase `u = (t/T) mod 1` (reduced by the period first).
    DegreesOfPhase,
    /// `sin(360·t/T)` of the time not reduced by the period.
    DegreesOfTime,
}

impl Variation {
    /// The motion as specified.
    pub(crate) const EXACT: Variation = Variation {
        angle_scale: 1.0,
        sign: 1.0,
        reversed: false,
        period: None,
        sine: Sine::Radians,
    };
    /// Angles in radians handed to a function that takes degrees.
    pub(crate) const RADIANS: Variation =
        Variation { angle_scale: std::f64::consts::PI / 180.0, ..Variation::EXACT };
    /// The other way round.
    pub(crate) const MIRRORED: Variation = Variation { sign: -1.0, ..Variation::EXACT };
    /// Rotation and translation swapped.
    pub(crate) const REVERSED: Variation = Variation { reversed: true, ..Variation::EXACT };
    /// A swing's sine taken of the degrees of its phase, `sin(360·u)`.
    pub(crate) const SINE_OF_DEGREES: Variation =
        Variation { sine: Sine::DegreesOfPhase, ..Variation::EXACT };
    /// A swing's sine taken of the degrees of the unreduced time, `sin(360·t/T)`.
    pub(crate) const SINE_OF_DEGREES_OF_TIME: Variation =
        Variation { sine: Sine::DegreesOfTime, ..Variation::EXACT };
    /// Both ways of handing degrees to `sin` ([`Sine`]).
    pub(crate) const SINES_OF_DEGREES: [Variation; 2] =
        [Variation::SINE_OF_DEGREES, Variation::SINE_OF_DEGREES_OF_TIME];
}

/// The phase `u ∈ [0, 1)` at `frame` of a motion with a period of `period` frames, exactly.
pub(crate) fn phase_at(frame: u64, period: u64) -> f64 {
    let p = period.max(1);
    (frame % p) as f64 / p as f64
}

fn rot(axis: WorldAxis, deg: f64) -> DMat4 {
    let a = deg.to_radians();
    match axis {
        WorldAxis::X => DMat4::from_rotation_x(a),
        WorldAxis::Y => DMat4::from_rotation_y(a),
        WorldAxis::Z => DMat4::from_rotation_z(a),
    }
}

fn tr(v: DVec3) -> DMat4 {
    DMat4::from_translation(v)
}

fn d3(a: [f32; 3]) -> DVec3 {
    Vec3::from_array(a).as_dvec3()
}

/// `(offset along the path, height)` of a hop at phase `u`: `w` goes 0 → 1 → 0 linearly,
/// `s = span·(w − 1/2)`, `y = 4·height·w·(1 − w)`.
pub(crate) fn hop_at(span: f64, height: f64, u: f64) -> (f64, f64) {
    let w = if u < 0.5 { 2.0 * u } else { 2.0 - 2.0 * u };
    (span * (w - 0.5), 4.0 * height * w * (1.0 - w))
}

/// The motion's own angle (degrees) at phase `u`, or `None` for a hop.
pub(crate) fn angle_at(motion: &Motion, u: f64) -> Option<f64> {
    angle_with(motion, u, u, Sine::Radians)
}

/// [`angle_at`] with a swing's sine taken as `sine` says; `cycles` is the time in periods,
/// not reduced (`t/T`, of which `u` is the fraction).
fn angle_with(motion: &Motion, u: f64, cycles: f64, sine: Sine) -> Option<f64> {
    match *motion {
        Motion::Spin { turn, .. } | Motion::Orbit { turn, .. } | Motion::Satellite { turn, .. } => {
            Some(f64::from(turn.sign()) * 360.0 * u)
        }
        Motion::Swing { amplitude_deg, .. } => {
            let s = match sine {
                Sine::Radians => (TAU * u).sin(),
                Sine::DegreesOfPhase => (360.0 * u).sin(),
                Sine::DegreesOfTime => (360.0 * cycles).sin(),
            };
            Some(f64::from(amplitude_deg) * s)
        }
        Motion::Hop { .. } => None,
    }
}

/// The motion's matrix relative to its parent (the world for independent objects) at phase
/// `u`, evaluated with `v`.
pub(crate) fn local(motion: &Motion, u: f64, v: Variation) -> DMat4 {
    local_at(motion, u, u, v)
}

/// [`local`] at the time `cycles` periods from the start (`t/T`, not reduced; `u` is its
/// fraction), which a swing's sine of unreduced degrees ([`Sine::DegreesOfTime`]) needs.
pub(crate) fn local_at(motion: &Motion, u: f64, cycles: f64, v: Variation) -> DMat4 {
    let angle = angle_with(motion, u, cycles, v.sine).map_or(0.0, |a| a * v.angle_scale * v.sign);
    let pair = |r: DMat4, t: DMat4| if v.reversed { t * r } else { r * t };
    match *motion {
        Motion::Spin { position, axis, .. } => pair(tr(d3(position)), rot(axis, angle)),
        Motion::Swing { pivot, axis, arm, .. } => {
            tr(d3(pivot)) * pair(rot(axis, angle), tr(DVec3::new(0.0, -f64::from(arm), 0.0)))
        }
        Motion::Hop { center, along, span, height, .. } => {
            let (s, y) = hop_at(f64::from(span), f64::from(height), u);
            tr(d3(center) + along.vector().as_dvec3() * s + DVec3::new(0.0, y, 0.0))
        }
        Motion::Orbit { center, radius, .. } => {
            tr(d3(center))
                * pair(rot(WorldAxis::Y, angle), tr(DVec3::new(0.0, 0.0, f64::from(radius))))
        }
        Motion::Satellite { radius, .. } => {
            pair(rot(WorldAxis::Y, angle), tr(DVec3::new(0.0, 0.0, f64::from(radius))))
        }
    }
}

/// Object `index`'s model matrix (world, without the camera) at `frame`: its motion at its
/// exact phase, after its parent's matrix for a child. An index out of range gives the identity.
#[must_use]
pub fn expected_model(spec: &Spec, index: usize, frame: u64) -> DMat4 {
    expected_model_with(spec, index, frame, Variation::EXACT, 0)
}

/// [`expected_model`] with the object's own motion (not its parent's) evaluated with `v`.
pub(crate) fn expected_model_with(
    spec: &Spec,
    index: usize,
    frame: u64,
    v: Variation,
    depth: usize,
) -> DMat4 {
    let Some(object) = spec.objects.get(index) else { return DMat4::IDENTITY };
    let period = v.period.unwrap_or_else(|| object.motion.period_frames()).max(1);
    let own = local_at(&object.motion, phase_at(frame, period), frame as f64 / period as f64, v);
    match object.motion.parent() {
        // A parent never is a child itself; the depth guard keeps a hand-made cycle finite.
        Some(p) if p != index && depth < 8 => {
            expected_model_with(spec, p, frame, Variation::EXACT, depth + 1) * own
        }
        _ => own,
    }
}

/// A warm-up box's model matrix at time `t` (s), from its phase `(t / T) mod 1` in f64.
#[must_use]
pub fn warmup_model(object: &Object, t: f64) -> DMat4 {
    warmup_model_with(object, t, Variation::EXACT)
}

pub(crate) fn warmup_model_with(object: &Object, t: f64, v: Variation) -> DMat4 {
    let cycles = t / f64::from(object.motion.period_s());
    let u = cycles.rem_euclid(1.0);
    local_at(&object.motion, if u >= 1.0 { 0.0 } else { u }, cycles, v)
}

/// Object `index`'s model transform at `frame` as the report writes it, each factor in program
/// order with its variable named (`theta_2`, `x_3`, `y_3`, for object 2 and 3) and its value at
/// that frame: `T(0, 1, 0) · Ry(theta_2) · T(0, 0, 2)`. A child's product starts with its
/// parent's. An index out of range gives the empty product.
#[must_use]
pub fn model_product(spec: &Spec, index: usize, frame: u64) -> MatrixProduct {
    product_with(spec, index, frame, 0)
}

fn product_with(spec: &Spec, index: usize, frame: u64, depth: usize) -> MatrixProduct {
    let Some(object) = spec.objects.get(index) else { return MatrixProduct::identity() };
    let u = phase_at(frame, object.motion.period_frames());
    let base = match object.motion.parent() {
        Some(p) if p != index && depth < 8 => product_with(spec, p, frame, depth + 1),
        _ => MatrixProduct::identity(),
    };
    base.concat(&local_product(&object.motion, index + 1, u))
}

/// The motion's own factors (relative to its parent, or the world) at phase `u`, its variables
/// named after object number `n`: `theta_n`, and `x_n` (or `z_n`) and `y_n` for a hop.
pub(crate) fn local_product(motion: &Motion, n: usize, u: f64) -> MatrixProduct {
    let angle = angle_at(motion, u).unwrap_or(0.0) as f32;
    let theta = Param::sym(format!("theta_{n}"), angle);
    let t = |v: [f32; 3]| Factor::translate(Vec3::from_array(v));
    let r = |axis: WorldAxis| {
        let a = match axis {
            WorldAxis::X => Axis::X,
            WorldAxis::Y => Axis::Y,
            WorldAxis::Z => Axis::Z,
        };
        Factor::rotate(a, theta.clone())
    };
    let base = MatrixProduct::identity();
    match *motion {
        Motion::Spin { position, axis, .. } => base.then(t(position)).then(r(axis)),
        Motion::Swing { pivot, axis, arm, .. } => {
            let p = base.then(t(pivot)).then(r(axis));
            if arm == 0.0 { p } else { p.then(t([0.0, -arm, 0.0])) }
        }
        Motion::Hop { center, along, span, height, .. } => {
            let (s, y) = hop_at(f64::from(span), f64::from(height), u);
            let (s, y) = (s as f32, y as f32);
            let sym = |c: &str, v: f32| Param::sym(format!("{c}_{n}"), v);
            let zero = Param::num(0.0);
            let offset = match along {
                WorldAxis::X => [sym("x", s), sym("y", y), zero],
                WorldAxis::Z => [zero, sym("y", y), sym("z", s)],
                // Not in the tables; a vertical hop would just add the offsets.
                WorldAxis::Y => [zero.clone(), sym("y", y + s), zero],
            };
            base.then(t(center)).then(Factor::Translate(offset))
        }
        Motion::Orbit { center, radius, .. } => {
            base.then(t(center)).then(r(WorldAxis::Y)).then(t([0.0, 0.0, radius]))
        }
        Motion::Satellite { radius, .. } => base.then(r(WorldAxis::Y)).then(t([0.0, 0.0, radius])),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Shape, Turn, new_object, warmup_objects};

    fn close(a: DMat4, b: DMat4) -> bool {
        a.abs_diff_eq(b, 1e-5)
    }

    #[test]
    fn the_lectures_orbit_starts_in_front_and_turns_counter_clockwise_from_above() {
        let m =
            Motion::Orbit { center: [0.0, 1.0, 0.0], radius: 1.5, turn: Turn::Ccw, period_s: 4.0 };
        let at = |u: f64| local(&m, u, Variation::EXACT).transform_point3(DVec3::ZERO);
        assert!(at(0.0).abs_diff_eq(DVec3::new(0.0, 1.0, 1.5), 1e-12));
        // A quarter period on: +X (front → right → back → left seen from +Y is counter-clockwise).
        assert!(at(0.25).abs_diff_eq(DVec3::new(1.5, 1.0, 0.0), 1e-12));
        // The symbolic product multiplies out to the same matrix.
        let spec = Spec {
            objects: vec![new_object("object 1", Shape::Sphere { radius: 0.4 }, [1.0; 3], m)],
            unit_s: 1.0,
        };
        let p = model_product(&spec, 0, 60);
        assert_eq!(p.symbolic(), "T(0, 1, 0) · Ry(theta_1) · T(0, 0, 1.5)");
        assert_eq!(p.numeric(), "T(0, 1, 0) · Ry(90°) · T(0, 0, 1.5)");
        assert!(close(p.matrix().unwrap().as_dmat4(), expected_model(&spec, 0, 60)));
    }

    #[test]
    fn hops_and_swings_follow_their_formulas() {
        // Hop: −end, top, +end, top, −end.
        for (u, s, y) in [(0.0, -1.0, 0.0), (0.25, 0.0, 1.5), (0.5, 1.0, 0.0), (0.75, 0.0, 1.5)] {
            let (gs, gy) = hop_at(2.0, 1.5, u);
            assert!((gs - s).abs() < 1e-12 && (gy - y).abs() < 1e-12, "u = {u}: {gs}, {gy}");
            // The height is the parabola of the offset: y = h·(1 − (2s/span)²).
            assert!((gy - 1.5 * (1.0 - gs * gs)).abs() < 1e-12);
        }
        let box2 = &warmup_objects()[1];
        assert!(close(warmup_model(box2, 0.5), tr(DVec3::Y) * rot(WorldAxis::Z, 30.0)));
        assert!(close(warmup_model(box2, 1.5), tr(DVec3::Y) * rot(WorldAxis::Z, -30.0)));
        // A pendulum hangs below its pivot.
        let m = Motion::Swing {
            pivot: [0.0, 2.5, 0.0],
            axis: WorldAxis::Z,
            amplitude_deg: 45.0,
            arm: 1.5,
            period_s: 2.0,
        };
        let bob = local(&m, 0.0, Variation::EXACT).transform_point3(DVec3::ZERO);
        assert!(bob.abs_diff_eq(DVec3::new(0.0, 1.0, 0.0), 1e-12));
    }

    /// Degrees handed to `sin` (issue 7): the swing's angle is `A·sin(360·u)` of the reduced
    /// phase or `A·sin(360·t/T)` of the unreduced time, read as radians; the turns and hops are
    /// as specified.
    #[test]
    fn degrees_in_a_sine_are_read_as_radians() {
        let swing = Motion::Swing {
            pivot: [0.0, 1.0, 0.0],
            axis: WorldAxis::Z,
            amplitude_deg: 30.0,
            arm: 0.0,
            period_s: 2.0,
        };
        let rz = |deg: f64| tr(DVec3::Y) * rot(WorldAxis::Z, deg);
        let (u, cycles) = (0.05, 3.05);
        let at = |v| local_at(&swing, u, cycles, v);
        assert!(close(at(Variation::EXACT), rz(30.0 * (TAU * u).sin())));
        assert!(close(at(Variation::SINE_OF_DEGREES), rz(30.0 * (360.0 * u).sin())));
        assert!(close(at(Variation::SINE_OF_DEGREES_OF_TIME), rz(30.0 * (360.0 * cycles).sin())));
        let box2 = &warmup_objects()[1];
        let t = 0.35;
        assert!(close(
            warmup_model_with(box2, t, Variation::SINE_OF_DEGREES_OF_TIME),
            rz(30.0 * (360.0 * t / 2.0).sin())
        ));
        let spin =
            Motion::Spin { position: [0.0; 3], axis: WorldAxis::Y, turn: Turn::Ccw, period_s: 4.0 };
        for v in Variation::SINES_OF_DEGREES {
            assert!(close(local_at(&spin, u, cycles, v), local(&spin, u, Variation::EXACT)));
        }
    }

    #[test]
    fn a_child_moves_in_its_parents_coordinates() {
        let parent =
            Motion::Orbit { center: [0.0, 1.0, 0.0], radius: 2.0, turn: Turn::Ccw, period_s: 4.0 };
        let child =
            Motion::Satellite { parent_index: 0, radius: 1.0, turn: Turn::Cw, period_s: 2.0 };
        let o = |m| new_object("o", Shape::Sphere { radius: 0.3 }, [1.0; 3], m);
        let spec = Spec { objects: vec![o(parent), o(child)], unit_s: 2.0 };
        for frame in [0, 17, 60, 100, 239] {
            let p = expected_model(&spec, 0, frame);
            let c = expected_model(&spec, 1, frame);
            let rel = p.inverse() * c;
            let u = phase_at(frame, 120);
            assert!(close(rel, rot(WorldAxis::Y, -360.0 * u) * tr(DVec3::Z)), "frame {frame}");
            let prod = model_product(&spec, 1, frame);
            assert!(close(prod.matrix().unwrap().as_dmat4(), c), "frame {frame}");
        }
        assert_eq!(
            model_product(&spec, 1, 0).symbolic(),
            "T(0, 1, 0) · Ry(theta_1) · T(0, 0, 2) · Ry(theta_2) · T(0, 0, 1)"
        );
    }
}
