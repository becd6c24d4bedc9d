//! The limits that keep every scene that loads drawable, and drawn alike by the three renderers
//! (the CPU rasterizer, the ray tracer and the GPU renderer all work in f32): where the world may
//! be, how narrow or wide the view, how near the near plane and how deep the depth range, how
//! large the transforms' products, how many faces and point lights (area-light samples counted) in all.
//!
//! The checks run while the file is loaded, after every value has been read on its own, and name
//! the line and key that goes beyond a limit — the transform step, the shape parameter, the
//! model, the camera or projection key — so a scene that loads never fails later in a renderer
//! without a line number, nor draws differently in each. `docs/scene-format.md` ("Limits")
//! documents each limit and why it is there.

mod text;

use cg_core::glam::{DVec3, Mat4, Vec3};
use cg_core::light::{Light, LightKind};
use cg_core::normals::normal_matrix;
use cg_core::product::MatrixProduct;
use cg_core::scene::{Camera, Object, Scene};

pub use text::{LimitError, Matrix, WorldPoint};

use crate::error::{ErrorKind, Expected, SceneError};
use crate::format::{Geometry, ObjectSpec, SceneSpec};
use crate::reader::{At, Source, Table, Value};

/// The largest coordinate, in absolute value, of any point of a scene in world space — every
/// vertex of every object after its transform, the camera's eye and target: 1e4 on each axis.
///
/// f32 keeps 24 significant bits: up to 1e4 neighbouring values are at most 2⁻¹⁰ ≈ 0.001 apart,
/// so a triangle of size 1 keeps its shape to 0.1 % (and the view transform's cancellation moves
/// it by no more on screen). At 8e6 they are 1 apart and a unit triangle collapses — the
/// rasterizer drew such a triangle unlit and the ray tracer dropped it. 1e4 is 2000 times the
/// course's ground (±5).
pub const MAX_COORDINATE: f32 = 1.0e4;

/// The narrowest field of view, `fovy_deg`: 1°. A pixel of the largest window (16384 pixels
/// high) then spans 1.1e-6 rad, about 18 times f32's relative rounding of a position (6e-8);
/// at 1e-15° the three renderers drew three different pictures.
pub const MIN_FOVY_DEG: f32 = 1.0;

/// The widest field of view, `fovy_deg`: 179° (beyond it the scene is squeezed into the middle of
/// the image; 180° has no projection at all).
pub const MAX_FOVY_DEG: f32 = 179.0;

/// The nearest near plane: 1e-4, finer than f32 positions are apart at [`MAX_COORDINATE`]
/// (0.001), and far below anything the course uses (1).
pub const MIN_NEAR: f32 = 1.0e-4;

/// The largest `far / near`: 1e6. Depth from near to far is stored in f32 (`[0, 1]`), where a
/// distance `d` is resolved to about `6e-8 · d² / near`: at this ratio 6 % of the distance at
/// the far plane, beyond it surfaces far away get the same depth (z-fighting) and the renderers
/// disagree. The course's is 500; `near = 1e-10, far = 3.4e38` drew 2 pixels in the rasterizer
/// and nothing in the ray tracer.
pub const MAX_DEPTH_RATIO: f32 = 1.0e6;

/// The most faces (triangles) of all objects of a scene together: 5 000 000 — one shape of
/// [`crate::MAX_SHAPE_FACES`] and more besides; about 1.5 GB of memory while rendering (four
/// shapes of 4 000 000 faces took 4.6 GB and 20 s). Built-in shapes are counted from their
/// parameters before any mesh is built; OBJ models as each is loaded.
pub const MAX_SCENE_FACES: u64 = 5_000_000;

/// The most point lights of a scene: 1024, each directional, point or spot light counting one
/// and each area light its samples (e.g. one area light of 32 × 32, or four of 16 × 16). Each is
/// one more light to evaluate, and one more shadow ray to trace, at every pixel: 1024 take about
/// 10 s to ray-trace at 640 × 640 on two cores (four area lights of 256 × 256 took 8 s at
/// 32 × 32 pixels; 10 000 point lights ran past a minute).
pub const MAX_POINT_LIGHTS: u64 = 1024;

// One shape of the most faces and a ground fit in a scene; the nearest near plane still leaves a
// depth range of 100.
const _: () = assert!(MAX_SCENE_FACES > crate::shape::MAX_SHAPE_FACES);
const _: () = assert!(MIN_NEAR * MAX_DEPTH_RATIO >= 99.9);

/// The checks that need no mesh, made before any is built: the camera's eye and target, the
/// projection, the product of projection and view, the area lights' samples, and each object's
/// transform step by step.
pub(crate) fn check_spec(spec: &SceneSpec, root: &Table<'_>) -> Result<(), SceneError> {
    let scene = &spec.scene;
    check_camera(&scene.camera, root)?;
    check_projection(scene, root)?;
    check_point_lights(&scene.lights, root)?;
    // Both were built while the file was read; an error here is one more safety net.
    let camera = || table(root, "camera");
    let view = scene
        .view_product()
        .and_then(|v| v.matrix())
        .map_err(|e| error_at(root, [], camera().as_ref(), ErrorKind::Transform(e)))?;
    for (index, object) in spec.objects.iter().enumerate() {
        check_steps(&object.transform, view, root, index)?;
    }
    Ok(())
}

/// The checks on the built meshes: every vertex of every object within [`MAX_COORDINATE`] in
/// world space.
pub(crate) fn check_scene(scene: &Scene, root: &Table<'_>) -> Result<(), SceneError> {
    scene
        .objects
        .iter()
        .enumerate()
        .try_for_each(|(index, object)| check_world(object, index, root))
}

/// The faces of the built-in shapes in `objects` together, counted from their parameters; more
/// than [`MAX_SCENE_FACES`] is an error at the parameter that sets the count of the shape that
/// goes over (the shape's table for shapes with a fixed count).
pub(crate) fn shape_faces(objects: &[ObjectSpec], src: &Source<'_>) -> Result<u64, SceneError> {
    let mut total = 0u64;
    for object in objects {
        if let Geometry::Shape(shape, at) = &object.geometry {
            total = total.saturating_add(shape.face_count());
            if total > MAX_SCENE_FACES {
                let place = shape.count_parameter().map_or(&at.table, |p| at.of(p));
                let e = LimitError::SceneFaces { faces: total };
                return Err(place.error(src, ErrorKind::Limit(e)));
            }
        }
    }
    Ok(total)
}

/// Adds the `faces` of an OBJ model (named at `at`, its `mesh` key), counted from its lines
/// before it is loaded, to `total`; more than [`MAX_SCENE_FACES`] is an error there.
pub(crate) fn add_model_faces(
    total: &mut u64,
    faces: u64,
    at: &At,
    src: &Source<'_>,
) -> Result<(), SceneError> {
    *total = total.saturating_add(faces);
    if *total > MAX_SCENE_FACES {
        return Err(at.error(src, ErrorKind::Limit(LimitError::SceneFaces { faces: *total })));
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Camera, projection, lights

/// The eye and the target within [`MAX_COORDINATE`]. An orbit camera's eye is blamed on
/// `distance`, or on `target` when `distance` is left out.
fn check_camera(camera: &Camera, root: &Table<'_>) -> Result<(), SceneError> {
    let t = table(root, "camera");
    let get = |key: &str| t.as_ref().and_then(|t| t.get(key));
    let (eye, target, eye_keys): (Vec3, Vec3, &[&str]) = match camera {
        Camera::Orbit(orbit) => (orbit.eye_position(), orbit.target, &["distance", "target"]),
        Camera::LookAt { eye, target, .. } => (*eye, *target, &["eye"]),
    };
    for (point, position, keys) in
        [(WorldPoint::Target, target, &["target"][..]), (WorldPoint::Eye, eye, eye_keys)]
    {
        if beyond(position.as_dvec3()) {
            let e = LimitError::Coordinate { point, position: position.to_array() };
            let places = keys.iter().map(|k| get(k));
            return Err(error_at(root, places, t.as_ref(), ErrorKind::Limit(e)));
        }
    }
    Ok(())
}

/// The near plane and the depth ratio within their limits, and the projection times the view
/// invertible in f32 (the field of view is checked where it is read: `format::read_projection`).
fn check_projection(scene: &Scene, root: &Table<'_>) -> Result<(), SceneError> {
    let t = table(root, "projection");
    let get = |key: &str| t.as_ref().and_then(|t| t.get(key));
    let fail = |keys: &[&str], e: LimitError| {
        error_at(root, keys.iter().map(|k| get(k)), t.as_ref(), ErrorKind::Limit(e))
    };
    let p = scene.projection;
    if p.near < MIN_NEAR {
        return Err(fail(&["near"], LimitError::Near { near: p.near }));
    }
    // With 1e-6 of room for decimal values whose f32 ratio is just above the limit
    // (`near = 0.0001, far = 100`).
    if f64::from(p.far) / f64::from(p.near) > f64::from(MAX_DEPTH_RATIO) * (1.0 + 1e-6) {
        return Err(fail(&["far", "near"], LimitError::DepthRatio { near: p.near, far: p.far }));
    }
    let matrices = scene.view_product().and_then(|v| v.matrix()).and_then(|view| {
        let projection = scene.projection_matrix()?;
        Ok((view, projection))
    });
    match matrices {
        Ok((view, projection)) if view_projection_invertible(view, projection) => Ok(()),
        Ok(_) => {
            let at = t.or_else(|| table(root, "camera"));
            Err(error_at(root, [], at.as_ref(), ErrorKind::Limit(LimitError::ViewProjection)))
        }
        // Both were built while the file was read.
        Err(e) => Err(error_at(root, [], t.as_ref(), ErrorKind::Transform(e))),
    }
}

/// Whether `projection · view` is finite in f32 and it and `view` have finite inverses in f64,
/// as the ray tracer inverts them (`cg_trace`'s camera) to turn pixels into rays.
pub(crate) fn view_projection_invertible(view: Mat4, projection: Mat4) -> bool {
    let (v, p) = (view.as_dmat4(), projection.as_dmat4());
    let pv = p * v;
    let finite_inverse = |m: cg_core::glam::DMat4| {
        let d = m.determinant();
        d != 0.0 && d.is_finite() && m.inverse().is_finite()
    };
    (projection * view).is_finite() && finite_inverse(pv) && finite_inverse(v)
}

/// At most [`MAX_POINT_LIGHTS`] point lights, an area light counting its samples; the error is
/// at the `samples` of the area light that goes over, or at the light.
fn check_point_lights(lights: &[Light], root: &Table<'_>) -> Result<(), SceneError> {
    let mut total = 0u64;
    for (index, light) in lights.iter().enumerate() {
        total += match light.kind {
            LightKind::Area { samples: [nu, nv], .. } => u64::from(nu) * u64::from(nv),
            _ => 1,
        };
        if total > MAX_POINT_LIGHTS {
            let t = element(root, "lights", index);
            let samples = t.as_ref().and_then(|t| t.get("samples"));
            let e = ErrorKind::Limit(LimitError::PointLights { lights: total });
            return Err(error_at(root, [samples], t.as_ref(), e));
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// Objects

/// The model matrix, the model-view matrix (the view times it, multiplied as
/// `Scene::model_view_product` does) and the normal matrix of the steps up to each step, all
/// finite in f32; the error is at the first step where one is not.
fn check_steps(
    transform: &MatrixProduct,
    view: Mat4,
    root: &Table<'_>,
    object: usize,
) -> Result<(), SceneError> {
    let (mut model, mut model_view) = (Mat4::IDENTITY, view);
    for (step, factor) in transform.factors.iter().enumerate() {
        // Every factor was checked when it was read.
        let m =
            factor.matrix().map_err(|e| step_error(root, object, step, ErrorKind::Transform(e)))?;
        model *= m;
        model_view *= m;
        let overflow = if !model.is_finite() {
            Some(Matrix::Model)
        } else if !model_view.is_finite() {
            Some(Matrix::ModelView)
        } else if !normal_matrix(model).is_finite() {
            Some(Matrix::Normal)
        } else {
            None
        };
        if let Some(matrix) = overflow {
            let kind = ErrorKind::Limit(LimitError::StepOverflow { matrix });
            return Err(step_error(root, object, step, kind));
        }
    }
    Ok(())
}

/// Whether `p` lies beyond [`MAX_COORDINATE`] on some axis (or is not finite).
fn beyond(p: DVec3) -> bool {
    // (`max_element` passes NaN over, so finiteness first.)
    !p.is_finite() || p.abs().max_element() > f64::from(MAX_COORDINATE)
}

/// Every vertex of `object` within [`MAX_COORDINATE`] in world space (its model matrix applied
/// in f64, as the ray tracer does). The first vertex beyond is named, at the step that took the
/// vertices there ([`blame`]), or at the shape or model that has them there already.
fn check_world(object: &Object, index: usize, root: &Table<'_>) -> Result<(), SceneError> {
    // Checked step by step before the meshes were built.
    let Ok(model) = object.transform.matrix() else { return Ok(()) };
    let m = model.as_dmat4();
    let Some((vertex, world)) = object
        .mesh
        .positions
        .iter()
        .map(|&p| m.transform_point3(p.as_dvec3()))
        .enumerate()
        .find(|&(_, w)| beyond(w))
    else {
        return Ok(());
    };
    let e = LimitError::Coordinate {
        point: WorldPoint::Vertex(vertex),
        position: world.as_vec3().to_array(),
    };
    let kind = ErrorKind::Limit(e);
    let t = element(root, "objects", index);
    Err(match blame(&object.transform, &object.mesh.positions) {
        Blame::Step(step) => step_error(root, index, step, kind),
        Blame::Geometry => {
            let geometry = t.as_ref().and_then(|t| t.get("shape").or_else(|| t.get("mesh")));
            error_at(root, [geometry], t.as_ref(), kind)
        }
        Blame::Transform => {
            let transform = t.as_ref().and_then(|t| t.get("transform"));
            error_at(root, [transform], t.as_ref(), kind)
        }
    })
}

/// What put an object's vertices beyond [`MAX_COORDINATE`].
#[derive(Debug, PartialEq, Eq)]
enum Blame {
    /// This transform step (its index).
    Step(usize),
    /// The shape or the model: beyond before any step, and no step brings them back.
    Geometry,
    /// The transform as a whole (only its f32 product is beyond: rounding at the limit).
    Transform,
}

/// The step whose action takes the vertices beyond [`MAX_COORDINATE`] for good. The steps act
/// on the vertices from the last to the first (the last one written acts first), each applied
/// in f64; the step blamed is the one after which some vertex is beyond, with none of the steps
/// after it bringing every vertex back.
fn blame(transform: &MatrixProduct, positions: &[Vec3]) -> Blame {
    let mut points: Vec<DVec3> = positions.iter().map(|p| p.as_dvec3()).collect();
    let outside = |points: &[DVec3]| points.iter().any(|&p| beyond(p));
    let in_model_space = outside(&points);
    let mut was = in_model_space;
    let mut blamed = None;
    for (step, factor) in transform.factors.iter().enumerate().rev() {
        let Ok(m) = factor.matrix() else { return Blame::Transform };
        let m = m.as_dmat4();
        for p in &mut points {
            *p = m.transform_point3(*p);
        }
        let now = outside(&points);
        if now && !was {
            blamed = Some(step);
        } else if !now {
            blamed = None;
        }
        was = now;
    }
    match blamed {
        Some(step) => Blame::Step(step),
        None if in_model_space && was => Blame::Geometry,
        None => Blame::Transform,
    }
}

// ---------------------------------------------------------------------------------------------
// Places in the file

/// The table `root.key`, if the file has it.
fn table<'a>(root: &Table<'a>, key: &str) -> Option<Table<'a>> {
    root.get(key)?.table().ok()
}

/// The table `root.key[index]` of an array of tables (`[[objects]]`, `[[lights]]`).
fn element<'a>(root: &Table<'a>, key: &str, index: usize) -> Option<Table<'a>> {
    root.get(key)?.array(Expected::ArrayOfTables).ok()?.into_iter().nth(index)?.table().ok()
}

/// An error at the first of `places` the file has, else at `table`, else at the file.
fn error_at<'a>(
    root: &Table<'a>,
    places: impl IntoIterator<Item = Option<Value<'a>>>,
    table: Option<&Table<'a>>,
    kind: ErrorKind,
) -> SceneError {
    match places.into_iter().flatten().next() {
        Some(v) => v.error(kind),
        None => table.unwrap_or(root).error(kind),
    }
}

/// An error at step `step` of the transform of object `object`: at its operation's value
/// (`objects[1].transform[1].scale`), else at the step, the transform or the object.
fn step_error(root: &Table<'_>, object: usize, step: usize, kind: ErrorKind) -> SceneError {
    let t = element(root, "objects", object);
    let transform = t.as_ref().and_then(|t| t.get("transform"));
    let step_table = transform
        .as_ref()
        .and_then(|v| v.array(Expected::ArrayOfTables).ok()?.into_iter().nth(step)?.table().ok());
    let operation = step_table.as_ref().and_then(|s| {
        let op = s.keys().into_iter().find(|&k| k != "axis")?;
        s.get(op)
    });
    match (operation, step_table) {
        (Some(v), _) => v.error(kind),
        (None, Some(s)) => s.error(kind),
        (None, None) => error_at(root, [transform], t.as_ref(), kind),
    }
}

#[cfg(test)]
pub(crate) mod tests;
