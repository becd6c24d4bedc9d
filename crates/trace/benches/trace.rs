//! Benchmarks of the ray tracer (`cargo bench -p cg-trace`):
//!
//! - `glass-mirror 256²`: the shipped glass-and-mirror scene at 256 × 256, all defaults (exact
//!   spheres and ground, shadows, depth 5, exact Fresnel), on all cores;
//! - `bvh build 100k`: the binned-SAH BVH over a 100 000-triangle torus (400 × 125 segments);
//! - `torus 100k 256²`: that torus on the ground, traced at 256 × 256 with shadows (primary and
//!   shadow rays through the BVH), BVH build included;
//! - `torus 100k intersect 256²`: the primary rays' closest hits alone, on one thread.

use std::hint::black_box;
use std::path::Path;

use cg_core::glam::Vec3;
use cg_core::light::Material;
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{NormalSource, Object, Scene};
use cg_trace::bvh::Bvh;
use cg_trace::{Options, Stats, Tracer};
use criterion::{Criterion, criterion_group, criterion_main};

fn shipped(name: &str) -> Scene {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../../assets/scenes/{name}.toml"));
    cg_scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

fn torus_scene() -> Scene {
    let mut scene = shipped("course-sample");
    scene.objects.retain(|o| o.name == "ground");
    let mesh = cg_core::shapes::torus(2.0, 0.7, 400, 125).unwrap();
    assert_eq!(mesh.face_count(), 100_000);
    scene.objects.push(Object {
        name: "torus".into(),
        mesh,
        normals: NormalSource::Vertex {
            weighting: cg_core::normals::Weighting::Area,
            crease_deg: None,
        },
        material: Material::from_color(Vec3::new(0.9, 0.5, 0.2)),
        transform: MatrixProduct::identity()
            .then(Factor::translate(Vec3::new(0.0, 1.0, 0.0)))
            .then(Factor::rotate_x_deg(60.0)),
        texture: None,
        weld: None,
        analytic: None,
    });
    scene
}

fn benches(c: &mut Criterion) {
    let glass = shipped("glass-mirror");
    let options = Options { size: Some((256, 256)), ..Options::default() };
    c.bench_function("glass-mirror 256²", |b| {
        b.iter(|| cg_trace::render(black_box(&glass), &options).unwrap())
    });

    let torus = torus_scene();
    let tris: Vec<[Vec3; 3]> = {
        let mesh = &torus.objects[1].mesh;
        (0..mesh.face_count()).map(|f| mesh.triangle(f)).collect()
    };
    c.bench_function("bvh build 100k", |b| b.iter(|| Bvh::build(black_box(&tris))));
    c.bench_function("torus 100k 256²", |b| {
        b.iter(|| cg_trace::render(black_box(&torus), &options).unwrap())
    });
    let tracer = Tracer::new(&torus, &options).unwrap();
    c.bench_function("torus 100k intersect 256²", |b| {
        b.iter(|| {
            let mut stats = Stats::default();
            let mut hits = 0u32;
            for y in 0..256 {
                for x in 0..256 {
                    let ray = tracer.generate_ray(x, y);
                    hits += u32::from(tracer.intersect(&ray, &mut stats).is_some());
                }
            }
            (hits, stats.bvh_nodes_visited)
        })
    });
}

criterion_group! {
    name = trace;
    config = Criterion::default().sample_size(10);
    targets = benches
}
criterion_main!(trace);
