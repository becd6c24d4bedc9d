//! The fast path of `vertex_normals(mesh, Weighting::Area)` against the plain loop
//! (`vertex_normals_reference`), bit for bit: on icospheres near and far from the origin, and on
//! seeded random meshes full of what the fast path must hand to the exact code — repeated and
//! collinear corners, slivers through rounded midpoints, needles, corners with wide exponent
//! ranges, back-to-back faces that cancel, isolated vertices, non-finite corners, indices out of
//! range.

mod common;

use cg_core::mesh::Mesh;
use cg_core::normals::{
    Fallback, Weighting, area_vertex_normals_without_fma, area_vertex_normals_without_simd,
    vertex_normals, vertex_normals_reference,
};
use cg_core::shapes::icosphere;
use cg_testkit::Inputs;
use common::{bits, large_random_mesh, random_mesh};
use glam::Vec3;

/// Every set of the fast path's kernels (the one this CPU picks, the compiler's with FMA, and the
/// one a CPU without FMA runs) gives the reference's bits.
fn assert_same(mesh: &Mesh, what: &str) {
    let reference = bits(&vertex_normals_reference(mesh, Weighting::Area));
    assert_eq!(bits(&vertex_normals(mesh, Weighting::Area)), reference, "{what}");
    if let Some(compiled) = area_vertex_normals_without_simd(mesh) {
        assert_eq!(bits(&compiled), reference, "{what} (kernels without SIMD)");
    }
    if let Some(portable) = area_vertex_normals_without_fma(mesh) {
        assert_eq!(bits(&portable), reference, "{what} (kernel without FMA)");
    }
}

#[test]
fn icospheres_near_and_far_from_the_origin() {
    // Level 5 and up (20 480 faces and more) take the parallel path; 6 has 5 blocks of faces.
    for level in 0..=6 {
        let sphere = icosphere(1.0, level).unwrap();
        assert_same(&sphere, &format!("icosphere level {level}"));
        for (scale, offset) in [(1e-3, 0.0), (1e3, 0.0), (1.0, 1e3), (1.0, 1e6), (1e-20, 1e-18)] {
            let mut moved = sphere.clone();
            for p in &mut moved.positions {
                *p = *p * scale + Vec3::new(offset, -offset, 0.5 * offset);
            }
            assert_same(&moved, &format!("icosphere level {level} ×{scale} +{offset}"));
        }
    }
}

#[test]
fn random_meshes_with_every_hard_case() {
    let mut s = Inputs::seeded(0x0a3e_a5e1);
    let mut cancelled = 0;
    for case in 0..3000 {
        let mesh = random_mesh(&mut s);
        let reference = vertex_normals_reference(&mesh, Weighting::Area);
        cancelled += common::cancelled(&reference);
        assert_same(&mesh, &format!("case {case} (seed {:#x})", s.seed()));
    }
    assert!(cancelled > 100, "premise: the meshes have cancelling vertices ({cancelled})");
}

/// Many random meshes side by side in one mesh of more than 300 000 faces: the parallel path
/// (several blocks of faces, one vertex range per thread) on every hard case at once, with the
/// vertices numbered in random order so that faces straddle the threads' vertex ranges.
#[test]
fn one_large_mesh_with_every_hard_case_in_random_vertex_order() {
    let mut s = Inputs::seeded(0x1a29_e5e5);
    let big = large_random_mesh(&mut s, 300_000);
    let reference = vertex_normals_reference(&big, Weighting::Area);
    let count =
        |what: fn(&Fallback) -> bool| reference.fallbacks.iter().filter(|(_, f)| what(f)).count();
    assert!(
        count(|f| matches!(f, Fallback::Cancelled { .. })) > 1000,
        "premise: cancelling vertices"
    );
    assert!(count(|f| *f == Fallback::Isolated) > 1000, "premise: isolated vertices");
    assert!(count(|f| *f == Fallback::Degenerate) > 100, "premise: degenerate-only vertices");
    assert_same(&big, "one large mesh");
}

#[test]
fn an_index_out_of_range_gives_the_reference_result() {
    let mut mesh = icosphere(1.0, 1).unwrap();
    mesh.faces.push([0, 1, 9999]);
    assert_same(&mesh, "index out of range");
    let vn = vertex_normals(&mesh, Weighting::Area);
    assert!(vn.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-6));
}

#[test]
fn the_fast_path_agrees_with_the_sphere() {
    // Independent of the reference: area-weighted normals of a fine icosphere are within 3 mrad (the faces are
    // not all alike) of p/|p|, and no vertex falls back.
    let sphere = icosphere(1.0, 5).unwrap();
    let vn = vertex_normals(&sphere, Weighting::Area);
    assert!(vn.fallbacks.is_empty());
    for (p, n) in sphere.positions.iter().zip(&vn.normals) {
        let angle = p.normalize().angle_between(*n);
        assert!(angle < 3e-3, "{p} {n} {angle}");
    }
}
