//! Unit tests of what the integration tests (`tests/limits.rs`) cannot reach through a scene
//! file, and the samples of every message for `error::tests`.

use cg_core::glam::{Mat4, Vec3};
use cg_core::lang::Lang;
use cg_core::product::{Factor, MatrixProduct};
use cg_core::transform::perspective;

use super::text::number;
use super::*;

/// A sample of every variant and branch of [`LimitError`], for the message tests of `error`
/// (every message one clean line in each language).
pub(crate) fn samples() -> Vec<LimitError> {
    let all = vec![
        LimitError::StepOverflow { matrix: Matrix::Model },
        LimitError::StepOverflow { matrix: Matrix::ModelView },
        LimitError::StepOverflow { matrix: Matrix::Normal },
        LimitError::Coordinate {
            point: WorldPoint::Vertex(2),
            position: [8e6, 0.5, f32::INFINITY],
        },
        LimitError::Coordinate { point: WorldPoint::Eye, position: [0.0, 1e5, 15.0] },
        LimitError::Coordinate { point: WorldPoint::Target, position: [3.4e38, 0.0, 0.0] },
        LimitError::FieldOfView { fovy_deg: 1e-15 },
        LimitError::Near { near: 1e-20 },
        LimitError::DepthRatio { near: 0.01, far: 1e5 },
        LimitError::ViewProjection,
        LimitError::SceneFaces { faces: 16_000_000 },
        LimitError::PointLights { lights: 262_144 },
    ];
    // Exhaustive: a new variant does not compile until it has a sample above.
    for e in &all {
        match e {
            LimitError::StepOverflow { .. }
            | LimitError::Coordinate { .. }
            | LimitError::FieldOfView { .. }
            | LimitError::Near { .. }
            | LimitError::DepthRatio { .. }
            | LimitError::ViewProjection
            | LimitError::SceneFaces { .. }
            | LimitError::PointLights { .. } => {}
        }
    }
    all
}

#[test]
fn numbers_in_messages_are_short() {
    assert_eq!(number(3.4e38), "3.4e38");
    assert_eq!(number(8e6), "8e6");
    assert_eq!(number(1e-20), "1e-20");
    assert_eq!(number(10000.0), "10000");
    assert_eq!(number(0.5), "0.5");
    assert_eq!(number(0.0), "0");
    assert_eq!(number(f32::INFINITY), "inf");
    let e = LimitError::Coordinate { point: WorldPoint::Vertex(2), position: [8e6, 0.5, 0.0] };
    assert!(e.text().en.starts_with("vertex V2 of this object is at [8e6, 0.5, 0] in world space"));
    assert!(e.text().get(Lang::Ja).contains("頂点 V2 がワールド座標で [8e6, 0.5, 0]"));
}

/// The limits as documented: a unit triangle at the largest coordinate keeps its shape to 0.1 %,
/// and the narrowest view leaves a pixel of the largest window well above f32's rounding.
#[test]
fn the_limits_are_what_their_documentation_says() {
    let spacing = |x: f32| f32::from_bits(x.to_bits() + 1) - x;
    assert!(spacing(MAX_COORDINATE) <= 1e-3, "{}", spacing(MAX_COORDINATE));
    assert!(spacing(8e6) >= 0.5, "at 8e6 a unit triangle collapses");
    let pixel = f64::from(MIN_FOVY_DEG).to_radians() / f64::from(cg_core::image::MAX_SIDE);
    let ratio = pixel / f64::from(f32::EPSILON / 2.0);
    assert!((17.0..19.0).contains(&ratio), "{ratio}");
    assert_eq!(MAX_POINT_LIGHTS, 32 * 32);
}

/// The ray tracer inverts projection × view: a singular view (a camera that cannot exist in a
/// scene file) is refused, the course's camera is not.
#[test]
fn view_projection_must_be_invertible() {
    let p = perspective(45.0, 1.0, 1.0, 500.0).unwrap();
    let view = Mat4::from_translation(Vec3::new(0.0, 0.0, -15.0));
    assert!(view_projection_invertible(view, p));
    assert!(!view_projection_invertible(Mat4::from_scale(Vec3::new(1.0, 0.0, 1.0)), p));
    assert!(!view_projection_invertible(Mat4::from_scale(Vec3::splat(3e38)), p));
    // The largest projection the limits allow with the farthest camera they allow.
    let p = perspective(MIN_FOVY_DEG, 1.0 / 16384.0, MIN_NEAR, MIN_NEAR * MAX_DEPTH_RATIO).unwrap();
    let view = Mat4::from_translation(Vec3::splat(-2.0 * MAX_COORDINATE));
    assert!(view_projection_invertible(view, p));
}

/// The step blamed for vertices beyond the limit: the one after which they are beyond for
/// good, the steps acting from the last to the first.
#[test]
fn the_step_that_moves_the_vertices_away_is_blamed() {
    let product = |factors: Vec<Factor>| MatrixProduct { factors };
    let far = Factor::translate(Vec3::new(8e6, 0.0, 0.0));
    let back = Factor::translate(Vec3::new(-8e6, 0.0, 0.0));
    let unit = [Vec3::ZERO, Vec3::X, Vec3::Y];
    assert_eq!(blame(&product(vec![far.clone()]), &unit), Blame::Step(0));
    // T(8e6) · S(2): the scale acts first, the translation takes them away.
    let twice = Factor::scale(Vec3::splat(2.0));
    assert_eq!(blame(&product(vec![far.clone(), twice.clone()]), &unit), Blame::Step(0));
    assert_eq!(blame(&product(vec![twice.clone(), far.clone()]), &unit), Blame::Step(1));
    // Away and back again, then away by the first step: the first step.
    assert_eq!(
        blame(&product(vec![far.clone(), back.clone(), far.clone()]), &unit),
        Blame::Step(0)
    );
    // A model far away already, moved further: the model.
    let distant = [Vec3::new(2e4, 0.0, 0.0), Vec3::new(2e4, 1.0, 0.0)];
    assert_eq!(blame(&product(vec![twice]), &distant), Blame::Geometry);
    assert_eq!(blame(&product(vec![]), &distant), Blame::Geometry);
    // ... or brought back by one step and taken away by another.
    assert_eq!(
        blame(&product(vec![far, Factor::scale(Vec3::splat(1e-4))]), &distant),
        Blame::Step(0)
    );
}
