//! The rasterizer against the kit's wgpu renderer on the same machine, in one run: the course
//! scene at 640 × 640 on one thread (frames per second), and an icosphere of 1.3 M triangles at
//! 1920 × 1080 with Phong shading, the CPU rasterizer on all cores against `cg_gpu::Gpu::render`
//! (on Mesa's lavapipe where that is the Vulkan driver: the same cores). Prints `name value` lines
//! and the ratios (docs/performance.md).
//!
//! ```text
//! VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json \
//!   cargo run --release -p cg-raster --example raster_vs_gpu -- [REPEATS]
//! ```

use std::path::Path;
use std::time::Instant;

use cg_core::glam::Vec3;
use cg_core::light::{Light, LightKind, LightModel, Material, Specular};
use cg_core::product::MatrixProduct;
use cg_core::scene::{Camera, NormalSource, Object, Projection, Scene, Shading};
use cg_core::shapes::icosphere;
use cg_raster::{Options, render};

/// Best of `repeats` timings of `f` in seconds, after one untimed warm-up call.
fn best(repeats: usize, mut f: impl FnMut()) -> f64 {
    f();
    (0..repeats.max(1))
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
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

fn main() {
    let repeats: usize =
        std::env::args().nth(1).map_or(10, |r| r.parse().expect("REPEATS is a number"));
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/course-sample.toml");
    let course = cg_scene::load(&path).expect("the course scene loads");
    let one = Options { threads: Some(1), ..Options::default() };
    let t = best(repeats * 5, || {
        std::hint::black_box(render(&course, &one).expect("the course scene renders"));
    });
    println!("course_640_1thread_ms {:.3}\ncourse_640_1thread_fps {:.1}", t * 1e3, 1.0 / t);

    let scene = icosphere_scene();
    let all = Options::default();
    let cpu = best(repeats, || {
        std::hint::black_box(render(&scene, &all).expect("the icosphere renders"));
    });
    let cpu_one = best(repeats.div_ceil(2), || {
        std::hint::black_box(render(&scene, &one).expect("the icosphere renders"));
    });
    println!("icosphere_1080p_cpu_all_cores_ms {:.2}", cpu * 1e3);
    println!("icosphere_1080p_cpu_1thread_ms {:.2}", cpu_one * 1e3);
    match cg_gpu::Gpu::new() {
        Ok(gpu) => {
            let options = cg_gpu::Options::default();
            let t = best(repeats, || {
                std::hint::black_box(gpu.render(&scene, &options).expect("the GPU renders"));
            });
            println!("gpu_adapter {}", gpu.adapter_info());
            println!("icosphere_1080p_gpu_ms {:.2}", t * 1e3);
            println!("ratio_cpu_over_gpu {:.2}", cpu / t);
        }
        Err(e) => println!("gpu_unavailable {e}"),
    }
}
