//! The scenes the rasterizer's benchmark and its comparison with the GPU both draw (one copy:
//! `benches/raster.rs` has `mod common;`, `examples/raster_vs_gpu.rs` includes it by path).

use cg_core::glam::Vec3;
use cg_core::light::{Light, LightKind, LightModel, Material, Specular};
use cg_core::product::MatrixProduct;
use cg_core::scene::{Camera, NormalSource, Object, Projection, Scene, Shading};
use cg_core::shapes::icosphere;

/// One unit sphere of `icosphere(1, 8)` (1 310 720 faces) seen from 3 units away, its given
/// normals the exact sphere normals (so the benchmark measures drawing, not normal averaging).
pub fn icosphere_scene() -> Scene {
    let mut mesh = icosphere(1.0, 8).expect("level 8 is allowed");
    mesh.normals = Some(mesh.positions.iter().map(|p| p.normalize()).collect());
    Scene {
        name: "icosphere-8".into(),
        width: 1920,
        height: 1080,
        clear_color: Vec3::new(0.5, 0.5, 0.8),
        camera: Camera::LookAt { eye: Vec3::new(0.0, 0.0, 3.0), target: Vec3::ZERO, up: Vec3::Y },
        projection: Projection { fovy_deg: 45.0, near: 1.0, far: 500.0 },
        light_model: LightModel::Lecture { specular: Specular::Phong, local_viewer: true },
        global_ambient: Vec3::splat(0.2),
        lights: vec![Light {
            kind: LightKind::Point { position: Vec3::new(10.0, 10.0, 10.0) },
            ambient: Vec3::splat(0.1),
            diffuse: Vec3::splat(0.8),
            specular: Vec3::ONE,
            attenuation: Default::default(),
        }],
        shading: Shading::Phong,
        cull_back_faces: true,
        objects: vec![Object {
            name: "icosphere".into(),
            mesh,
            normals: NormalSource::Given,
            material: Material {
                ka: Vec3::new(0.2, 0.3, 0.8),
                kd: Vec3::new(0.2, 0.3, 0.8),
                ks: Vec3::splat(0.9),
                shininess: 60.0,
                ..Material::default()
            },
            transform: MatrixProduct::identity(),
            texture: None,
            weld: None,
            analytic: None,
        }],
        textures: vec![],
    }
}
