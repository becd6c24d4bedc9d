//! Area-weighted vertex normals of the kit's icosphere at subdivision 7 (327 680 faces) and 8
//! (1 310 720 faces): the fast path of `vertex_normals` against the plain loop it is tested
//! against bit for bit (`vertex_normals_reference`), and the per-frame call of a `NormalsPlan`
//! (for positions that move while the faces stay; the plan is made once, outside the timing, and
//! making it is timed on its own).
//!
//! `cargo bench -p cg-core --bench normals`. The side-by-side comparison with trimesh and Open3D
//! is `scripts/compare-normals.py` (docs/performance.md).

use std::hint::black_box;

use cg_core::normals::{
    NormalsPlan, VertexNormals, Weighting, vertex_normals, vertex_normals_reference,
};
use cg_core::shapes::icosphere;
use criterion::{Criterion, Throughput, criterion_group, criterion_main};

fn normals(c: &mut Criterion) {
    for level in [7, 8] {
        let mesh = icosphere(1.0, level).expect("levels up to 8 are allowed");
        let mut group = c.benchmark_group(format!("vertex_normals area icosphere({level})"));
        group.sample_size(10);
        group.throughput(Throughput::Elements(mesh.faces.len() as u64));
        group.bench_function("fast", |b| {
            b.iter(|| vertex_normals(black_box(&mesh), Weighting::Area))
        });
        let mut plan = NormalsPlan::for_mesh(&mesh).expect("the indices are in range");
        let mut out = VertexNormals::default();
        group.bench_function("plan, per frame", |b| {
            b.iter(|| {
                plan.area_normals_into(black_box(&mesh.positions), &mut out).expect("valid");
                black_box(&mut out);
            })
        });
        group.bench_function("plan, made once", |b| {
            b.iter(|| NormalsPlan::for_mesh(black_box(&mesh)).expect("valid"))
        });
        group.bench_function("reference", |b| {
            b.iter(|| vertex_normals_reference(black_box(&mesh), Weighting::Area))
        });
        group.finish();
    }
}

criterion_group!(benches, normals);
criterion_main!(benches);
