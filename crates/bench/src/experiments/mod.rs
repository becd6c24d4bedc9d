//! The experiments, one module each, and the scenes they share.

pub mod face_normals;
pub mod features;
pub mod fresnel;
pub mod normalise;
pub mod shading;
pub mod trace;
pub mod vertex_normals;

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::image::Image;
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular};
use cg_core::mesh::Mesh;
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{Analytic, Camera, NormalSource, Object, Projection, Scene, Shading};

use crate::BenchError;

/// A scene with no objects: `size × size`, looking at the origin from `eye`, the lecture's Phong
/// model with a local viewer, global ambient 0.2, black background.
pub(crate) fn empty_scene(name: &str, size: u32, eye: Vec3) -> Scene {
    Scene {
        name: name.into(),
        width: size,
        height: size,
        clear_color: Rgb::ZERO,
        camera: Camera::LookAt { eye, target: Vec3::ZERO, up: Vec3::Y },
        projection: Projection { fovy_deg: 45.0, near: 0.5, far: 100.0 },
        light_model: LightModel::Lecture { specular: Specular::Phong, local_viewer: true },
        global_ambient: Rgb::splat(0.2),
        lights: vec![],
        shading: Shading::Phong,
        cull_back_faces: true,
        objects: vec![],
        textures: vec![],
    }
}

/// A point light at `position`, white diffuse and specular, no ambient, no attenuation.
pub(crate) fn point_light(position: Vec3) -> Light {
    Light {
        kind: LightKind::Point { position },
        ambient: Rgb::ZERO,
        diffuse: Rgb::ONE,
        specular: Rgb::ONE,
        attenuation: Attenuation::default(),
    }
}

/// An object from a mesh, placed by `transform`, with `normals` and `material`.
pub(crate) fn object(
    name: &str,
    mesh: Mesh,
    normals: NormalSource,
    material: Material,
    transform: MatrixProduct,
) -> Object {
    Object {
        name: name.into(),
        mesh,
        normals,
        material,
        transform,
        texture: None,
        weld: None,
        analytic: None,
    }
}

/// An icosphere of radius `radius` at `center` whose vertex normals are the exact sphere normals
/// (so shading differences are the shading mode's alone), known to the tracer as an exact sphere.
pub(crate) fn sphere(
    name: &str,
    radius: f32,
    level: u32,
    center: Vec3,
    material: Material,
) -> Result<Object, BenchError> {
    let mut mesh =
        cg_core::shapes::icosphere(radius, level).map_err(|e| BenchError::Render(e.to_string()))?;
    mesh.normals = Some(mesh.positions.iter().map(|p| p.normalize_or_zero()).collect());
    let transform = MatrixProduct::identity().then(Factor::translate(center));
    let mut o = object(name, mesh, NormalSource::Given, material, transform);
    o.analytic = Some(Analytic::Sphere { radius });
    Ok(o)
}

/// A ground square of side `size` at height `y`, 10 × 10 cells, exact plane for the tracer.
pub(crate) fn ground(size: f32, y: f32, material: Material) -> Result<Object, BenchError> {
    let mesh = cg_core::shapes::grid(10, size).map_err(|e| BenchError::Render(e.to_string()))?;
    let transform = MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, y, 0.0)));
    let mut o = object("ground", mesh, NormalSource::Face, material, transform);
    o.analytic = Some(Analytic::Plane { size });
    Ok(o)
}

/// A plain material: ambient and diffuse `color`, no specular.
pub(crate) fn matte(color: Rgb) -> Material {
    Material { ka: color, kd: color, ..Material::default() }
}

/// Root-mean-square difference of two images over the pixels where `mask` is true (every pixel
/// when `mask` is `None`), over all three channels. 0 for no pixels or different sizes.
pub(crate) fn rms(a: &Image, b: &Image, mask: Option<&[bool]>) -> f64 {
    if a.pixels.len() != b.pixels.len() {
        return f64::NAN;
    }
    let mut sum = 0.0f64;
    let mut n = 0usize;
    for (i, (p, q)) in a.pixels.iter().zip(&b.pixels).enumerate() {
        if mask.is_none_or(|m| m.get(i).copied().unwrap_or(false)) {
            let d = (*p - *q).as_dvec3();
            sum += d.length_squared();
            n += 3;
        }
    }
    if n == 0 { 0.0 } else { (sum / n as f64).sqrt() }
}

/// The rasterizer on one thread.
pub(crate) fn raster(
    scene: &Scene,
    shading: Option<Shading>,
) -> Result<cg_raster::Output, BenchError> {
    let options = cg_raster::Options { shading, threads: Some(1), ..cg_raster::Options::default() };
    cg_raster::render(scene, &options).map_err(|e| BenchError::Render(e.to_string()))
}

/// The ray tracer on one thread with `options` otherwise.
pub(crate) fn trace(
    scene: &Scene,
    options: &cg_trace::Options,
) -> Result<cg_trace::Output, BenchError> {
    let options = cg_trace::Options { threads: Some(1), ..options.clone() };
    cg_trace::render(scene, &options).map_err(|e| BenchError::Render(e.to_string()))
}
