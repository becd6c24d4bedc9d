//! Rasterizer speed, each scene prepared once ([`cg_raster::Prepared`]) and drawn into the last
//! frame's buffers, as a window redraws: the course's sample scene at its own 640 × 640 in
//! Gouraud and Phong shading, on one core and on all cores, and an icosphere of 1.3 M triangles
//! at 1920 × 1080 in both modes on all cores. `examples/raster_vs_gpu.rs` times the same rows
//! against the GPU renderer.
//!
//! `cargo bench -p cg-raster` (add `-- course` or `-- icosphere` to run one group).

use std::hint::black_box;
use std::path::Path;

mod common;

use cg_core::scene::{Scene, Shading};
use cg_raster::{Options, Prepared, SceneLighting};
use common::icosphere_scene;
use criterion::{BenchmarkGroup, Criterion, Throughput, criterion_group, criterion_main};

/// One benchmark: `scene` with `options`, prepared once, each iteration one frame.
fn frame(
    group: &mut BenchmarkGroup<'_, criterion::measurement::WallTime>,
    name: &str,
    scene: &Scene,
    options: Options,
) {
    let ready = Prepared::new(scene, &options, &SceneLighting).unwrap();
    let mut last = Some(ready.draw().unwrap());
    group.bench_function(name, |b| {
        b.iter(|| last = Some(black_box(ready.draw_into(last.take().unwrap()).unwrap())));
    });
}

fn course(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/course-sample.toml");
    let scene = cg_scene::load(&path).expect("the course scene loads");
    let mut group = c.benchmark_group("course-sample 640x640");
    group.throughput(Throughput::Elements(1));
    for shading in [Shading::Gouraud, Shading::Phong] {
        for (cores, threads) in [("1 thread", Some(1)), ("all cores", None)] {
            let options = Options { shading: Some(shading), threads, ..Options::default() };
            frame(&mut group, &format!("{shading:?}, {cores}"), &scene, options);
        }
    }
    group.finish();
}

fn icosphere(c: &mut Criterion) {
    let scene = icosphere_scene();
    let mut group = c.benchmark_group("icosphere(1, 8) 1920x1080");
    group.sample_size(10);
    group.throughput(Throughput::Elements(scene.objects[0].mesh.face_count() as u64));
    for shading in [Shading::Gouraud, Shading::Phong] {
        let options = Options { shading: Some(shading), ..Options::default() };
        frame(&mut group, &format!("{shading:?}, all cores"), &scene, options);
    }
    group.finish();
}

criterion_group!(benches, course, icosphere);
criterion_main!(benches);
