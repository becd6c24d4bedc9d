//! Scenes built in code for the tracer's tests.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular};
use cg_core::mesh::Mesh;
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{Analytic, Camera, NormalSource, Object, Projection, Scene, Shading};

/// The shipped scene `name` (`assets/scenes/<name>.toml`).
pub fn shipped(name: &str) -> Scene {
    let path = assets().join(format!("scenes/{name}.toml"));
    cg_scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

pub fn assets() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets")
}

/// An object with `mesh`, `material`, the model transform `transform` (factors in program
/// order) and smooth normals.
pub fn object(name: &str, mesh: Mesh, material: Material, transform: Vec<Factor>) -> Object {
    Object {
        name: name.into(),
        mesh,
        normals: NormalSource::Vertex {
            weighting: cg_core::normals::Weighting::Angle,
            crease_deg: None,
        },
        material,
        transform: transform.into_iter().fold(MatrixProduct::identity(), MatrixProduct::then),
        texture: None,
        weld: None,
        analytic: None,
    }
}

/// The exact sphere of `radius` (and its 64 × 32 mesh for the triangle path).
pub fn sphere(name: &str, radius: f32, material: Material, transform: Vec<Factor>) -> Object {
    let mesh = cg_core::shapes::uv_sphere(radius, 64, 32).unwrap();
    Object {
        analytic: Some(Analytic::Sphere { radius }),
        ..object(name, mesh, material, transform)
    }
}

/// The exact square of side `size` in the model's y = 0 (and its 4 × 4 grid), facing +Y.
pub fn plane(name: &str, size: f32, material: Material, transform: Vec<Factor>) -> Object {
    let mesh = cg_core::shapes::grid(4, size).unwrap();
    Object {
        analytic: Some(Analytic::Plane { size }),
        normals: NormalSource::Face,
        ..object(name, mesh, material, transform)
    }
}

/// Glass: k_t = 1 (k_r = 0), η = 1.5, no local light.
pub fn glass(eta: f32) -> Material {
    Material {
        ka: Rgb::ZERO,
        kd: Rgb::ZERO,
        ks: Rgb::ZERO,
        kt: Rgb::ONE,
        eta,
        ..Material::default()
    }
}

/// A perfect mirror: k_r = 1, no local light.
pub fn mirror() -> Material {
    Material { ka: Rgb::ZERO, kd: Rgb::ZERO, ks: Rgb::ZERO, kr: Rgb::ONE, ..Material::default() }
}

pub fn point_light(position: Vec3) -> Light {
    Light {
        kind: LightKind::Point { position },
        ambient: Rgb::splat(0.1),
        diffuse: Rgb::splat(0.8),
        specular: Rgb::ONE,
        attenuation: Attenuation::default(),
    }
}

/// A `width × height` scene of `objects` seen from `eye` towards `target`, lit by one point
/// light at (10, 10, 10), lecture model with Phong specular, local viewer, no culling.
pub fn scene(objects: Vec<Object>, eye: Vec3, target: Vec3, width: u32, height: u32) -> Scene {
    Scene {
        name: "test".into(),
        width,
        height,
        clear_color: Rgb::new(0.5, 0.5, 0.8),
        camera: Camera::LookAt { eye, target, up: Vec3::Y },
        projection: Projection { fovy_deg: 45.0, near: 1.0, far: 500.0 },
        light_model: LightModel::Lecture { specular: Specular::Phong, local_viewer: true },
        global_ambient: Rgb::splat(0.2),
        lights: vec![point_light(Vec3::splat(10.0))],
        shading: Shading::Phong,
        cull_back_faces: false,
        objects,
        textures: vec![],
    }
}

/// The perpendicular distance, in f64, of point `q` from the line through `o` along unit `d`.
pub fn distance_from_line(q: Vec3, o: Vec3, d: Vec3) -> f64 {
    let (q, o, d) = (q.as_dvec3(), o.as_dvec3(), d.as_dvec3().normalize());
    let v = q - o;
    (v - v.dot(d) * d).length()
}
