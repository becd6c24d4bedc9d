//! Rasterizer speed: the course's sample scene at its own 640 × 640 (Gouraud), on one core and on
//! all cores, and an icosphere of 1.3 M triangles at 1920 × 1080 with Phong shading.
//!
//! `cargo bench -p cg-raster` (add `-- course` or `-- icosphere` to run one group).

use std::hint::black_box;
use std::path::Path;

mod common;

use cg_core::scene::Shading;
use cg_raster::{Options, render};
use common::icosphere_scene;
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
