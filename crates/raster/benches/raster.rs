//! Rasterizer speed: the course's sample scene at its own 640 × 640 (Gouraud), on one core and on
//! all cores, and an icosphere of 1.3 M triangles at 1920 × 1080 with Phong shading.
//!
//! `cargo bench -p cg-raster` (add `-- course` or `-- icosphere` to run one group).

use std::hint::black_box;
use std::path::Path;

use cg_core::glam::Vec3;
use cg_core::light::{Light, LightKind, LightModel, Material, Specular};
use cg_core::product::MatrixProduct;
use cg_core::scene::{Camera, NormalSource, Object, Projection, Scene, Shading};
use cg_core::shapes::icosphere;
use cg_raster::{Options, render};
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

fn course(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/course-sample.toml");
    let scene = cg_scene::load(&path).expect("the course scene loads");
    let mut group = c.benchmark_group("course-sample 640x640 gouraud");
    group.throughput(Throughput::Elements(1));
    for (name, threads) in [("1 thread", Some(1)), ("all cores", None)] {
        let options = Options { shading: Some(Shading::Gouraud), threads, ..Options::default() };
        group.bench_function(name, |b| b.iter(|| render(black_box(&scene), &options).unwrap()));
    }
    group.finish();
}

/// One unit sphere of `icosphere(1, 8)` (1 310 720 faces) seen from 3 units away, its given
/// normals the exact sphere normals (so the benchmark measures drawing, not normal averaging).
fn icosphere_scene() -> Scene {
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

fn icosphere_phong(c: &mut Criterion) {
    let scene = icosphere_scene();
    let mut group = c.benchmark_group("icosphere(1, 8) 1920x1080 phong");
    group.sample_size(10);
    group.throughput(Throughput::Elements(scene.objects[0].mesh.face_count() as u64));
    for (name, threads) in [("1 thread", Some(1)), ("all cores", None)] {
        let options = Options { threads, ..Options::default() };
        group.bench_function(name, |b| b.iter(|| render(black_box(&scene), &options).unwrap()));
    }
    group.finish();
}

criterion_group!(benches, course, icosphere_phong);
criterion_main!(benches);
