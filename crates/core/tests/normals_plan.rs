//! `NormalsPlan`, the area-weighted vertex normals of a mesh whose faces stay fixed while its
//! positions move, against the plain loop (`vertex_normals_reference`), bit for bit, frame after
//! frame with one plan: on icospheres near and far from the origin (numbered as the kit makes
//! them, and at random), on seeded random meshes full of every hard case (shared with
//! `normals_fast.rs`), on one large mesh of them in random vertex order, and on fans whose centre
//! has more faces than a tile takes. Every set of kernels (the hand-vectorised ones this CPU
//! picks, the compiler's with FMA, and those of a CPU without FMA). Faces out of range and
//! positions of the wrong length are errors.

mod common;

use cg_core::lang::Lang;
use cg_core::mesh::{Mesh, MeshError};
use cg_core::normals::{
    Fallback, NormalsPlan, PlanError, VertexNormals, Weighting, vertex_normals_reference,
};
use cg_core::shapes::icosphere;
use cg_testkit::Inputs;
use common::{bits, corner, large_random_mesh, random_mesh, shuffled};
use glam::Vec3;

/// Every set of the plan's kernels (the hand-vectorised ones this CPU may pick, the compiler's
/// with FMA, and those of a CPU without FMA) gives the reference's bits for `mesh`'s positions,
/// written over whatever `out` held before.
fn assert_frame(plan: &mut NormalsPlan, mesh: &Mesh, out: &mut VertexNormals, what: &str) {
    let reference = bits(&vertex_normals_reference(mesh, Weighting::Area));
    plan.area_normals_into(&mesh.positions, out).unwrap();
    assert_eq!(bits(out), reference, "{what}");
    plan.area_normals_into_without_simd(&mesh.positions, out).unwrap();
    assert_eq!(bits(out), reference, "{what} (kernels without SIMD)");
    plan.area_normals_into_without_fma(&mesh.positions, out).unwrap();
    assert_eq!(bits(out), reference, "{what} (kernel without FMA)");
}

/// Frames of a moving icosphere with one plan: a wave along y, then scaled and moved far from
/// the origin, then squashed flat (every face's normal turns to ±y; the poles' faces cancel).
fn animate(sphere: &Mesh, what: &str) -> (f64, bool) {
    let mut plan = NormalsPlan::for_mesh(sphere).unwrap();
    let mut out = VertexNormals::default();
    let mut frame = sphere.clone();
    for t in 0..3 {
        for (p, q) in frame.positions.iter_mut().zip(&sphere.positions) {
            *p = *q + Vec3::new(0.0, 0.2 * (5.0 * q.x + t as f32).sin(), 0.0);
        }
        assert_frame(&mut plan, &frame, &mut out, &format!("{what}, wave {t}"));
    }
    for (scale, offset) in [(1e-3, 0.0), (1e3, 0.0), (1.0, 1e3), (1.0, 1e6), (1e-20, 1e-18)] {
        for (p, q) in frame.positions.iter_mut().zip(&sphere.positions) {
            *p = *q * scale + Vec3::new(offset, -offset, 0.5 * offset);
        }
        assert_frame(&mut plan, &frame, &mut out, &format!("{what} ×{scale} +{offset}"));
    }
    for (p, q) in frame.positions.iter_mut().zip(&sphere.positions) {
        *p = Vec3::new(q.x, 0.0, q.z);
    }
    assert_frame(&mut plan, &frame, &mut out, &format!("{what}, squashed flat"));
    plan.layout()
}

#[test]
fn moving_icospheres_near_and_far_from_the_origin() {
    // Level 5 and up (20 480 faces and more) run the tiles on all cores; level 6 has 40 or more.
    let mut s = Inputs::seeded(0x09a1_e5e7);
    let mut renumbered = [false; 2];
    for level in 0..=6 {
        let sphere = icosphere(1.0, level).unwrap();
        let (_, r) = animate(&sphere, &format!("icosphere level {level}"));
        renumbered[usize::from(r)] = true;
        let (_, r) = animate(&shuffled(&sphere, &mut s), &format!("shuffled level {level}"));
        renumbered[usize::from(r)] = true;
    }
    assert_eq!(renumbered, [true, true], "premise: both layouts of the plan are exercised");
}

/// Moves every vertex of a random mesh to a new random corner, now and then one to infinity or
/// NaN.
fn move_at_random(mesh: &mut Mesh, s: &mut Inputs) {
    for p in &mut mesh.positions {
        if s.coin() {
            *p = corner(s);
        }
    }
    if s.int(0, 10) == 0 {
        let k = s.int(0, mesh.positions.len() as i64) as usize;
        mesh.positions[k].x = if s.coin() { f32::NAN } else { f32::NEG_INFINITY };
    }
}

#[test]
fn random_meshes_with_every_hard_case_frame_after_frame() {
    let mut s = Inputs::seeded(0x9a1e_0001);
    let mut cancelled = 0;
    // One output for all meshes: each call resizes it and clears the fallbacks.
    let mut out = VertexNormals::default();
    for case in 0..2000 {
        let mut mesh = random_mesh(&mut s);
        let original = mesh.positions.clone();
        let mut plan = NormalsPlan::for_mesh(&mesh).unwrap();
        for frame in 0..3 {
            let reference = vertex_normals_reference(&mesh, Weighting::Area);
            cancelled += common::cancelled(&reference);
            let what = format!("case {case} frame {frame} (seed {:#x})", s.seed());
            assert_frame(&mut plan, &mesh, &mut out, &what);
            move_at_random(&mut mesh, &mut s);
        }
        // Back to the first positions: nothing of the frames between is left over.
        mesh.positions = original;
        assert_frame(&mut plan, &mesh, &mut out, &format!("case {case}, first positions again"));
    }
    assert!(cancelled > 100, "premise: the meshes have cancelling vertices ({cancelled})");
}

#[test]
fn one_large_mesh_with_every_hard_case_in_random_vertex_order() {
    let mut s = Inputs::seeded(0x9a1e_0002);
    let mut big = large_random_mesh(&mut s, 300_000);
    let mut plan = NormalsPlan::for_mesh(&big).unwrap();
    let mut out = VertexNormals::default();
    for frame in 0..2 {
        let reference = vertex_normals_reference(&big, Weighting::Area);
        let count = |what: fn(&Fallback) -> bool| {
            reference.fallbacks.iter().filter(|(_, f)| what(f)).count()
        };
        assert!(count(|f| matches!(f, Fallback::Cancelled { .. })) > 1000, "premise: cancelling");
        assert!(count(|f| *f == Fallback::Isolated) > 1000, "premise: isolated vertices");
        assert!(count(|f| *f == Fallback::Degenerate) > 100, "premise: degenerate-only vertices");
        assert_frame(&mut plan, &big, &mut out, &format!("one large mesh, frame {frame}"));
        move_at_random(&mut big, &mut s);
    }
}

/// A fan of `n` faces around a centre vertex (V0), on a wavy rim.
fn fan(n: u32, wave: f32) -> Mesh {
    let mut positions = vec![Vec3::new(0.0, 1.0, 0.0)];
    positions.extend((0..n).map(|k| {
        let a = std::f32::consts::TAU * k as f32 / n as f32;
        Vec3::new(a.cos(), wave * (3.0 * a).sin(), a.sin())
    }));
    let faces = (0..n).map(|k| [0, 1 + (k + 1) % n, 1 + k]).collect();
    Mesh::new(positions, faces)
}

#[test]
fn a_vertex_with_more_faces_than_a_tile_takes() {
    for n in [3, 255, 256, 257, 5000, 70_000] {
        let mut mesh = fan(n, 0.0);
        let mut plan = NormalsPlan::for_mesh(&mesh).unwrap();
        let mut out = VertexNormals::default();
        for wave in [0.0, 0.3, -2.0] {
            mesh = Mesh { positions: fan(n, wave).positions, ..mesh };
            assert_frame(&mut plan, &mesh, &mut out, &format!("fan of {n}, wave {wave}"));
        }
        // The centre folded flat onto the rim's plane and the rim closed up: its faces cancel.
        mesh.positions[0] = Vec3::ZERO;
        assert_frame(&mut plan, &mesh, &mut out, &format!("fan of {n}, flat"));
    }
}

#[test]
fn empty_and_faceless_meshes() {
    let mut out =
        VertexNormals { normals: vec![Vec3::ONE; 7], fallbacks: vec![(3, Fallback::Isolated)] };
    let mut plan = NormalsPlan::new(&[], 0).unwrap();
    plan.area_normals_into(&[], &mut out).unwrap();
    assert_eq!(out, VertexNormals::default());
    let mesh = Mesh::new(vec![Vec3::X; 4], vec![]);
    let mut plan = NormalsPlan::for_mesh(&mesh).unwrap();
    assert_frame(&mut plan, &mesh, &mut out, "four isolated vertices");
    assert_eq!(out.fallbacks.len(), 4);
}

#[test]
fn an_index_out_of_range_is_an_error() {
    let mut mesh = icosphere(1.0, 1).unwrap();
    let n = mesh.positions.len();
    mesh.faces.insert(5, [0, n as u32, 1]);
    let e = NormalsPlan::for_mesh(&mesh).unwrap_err();
    let expected =
        MeshError::IndexOutOfRange { face: 5, corner: 1, index: n as u32, vertex_count: n };
    assert_eq!(e, PlanError::Mesh(expected));
    assert!(e.message(Lang::En).contains("F5"), "{}", e.message(Lang::En));
    assert!(!e.message(Lang::Ja).is_empty());
    assert!(matches!(NormalsPlan::new(&[[0, 1, u32::MAX]], 3), Err(PlanError::Mesh(_))));
    assert!(matches!(
        NormalsPlan::new(&[], u32::MAX as usize + 1),
        Err(PlanError::TooLarge { faces: 0, .. })
    ));
}

#[test]
fn positions_of_the_wrong_length_are_an_error() {
    let mesh = icosphere(1.0, 2).unwrap();
    let n = mesh.positions.len();
    let mut plan = NormalsPlan::for_mesh(&mesh).unwrap();
    let mut out = VertexNormals::default();
    plan.area_normals_into(&mesh.positions, &mut out).unwrap();
    let before = out.clone();
    for found in [0, n - 1, n + 1] {
        let mut positions = mesh.positions.clone();
        positions.resize(found, Vec3::X);
        let e = plan.area_normals_into(&positions, &mut out).unwrap_err();
        assert_eq!(e, PlanError::PositionCount { expected: n, found });
        assert_eq!(out, before, "the output is left as it was");
        assert!(e.message(Lang::Ja).contains(&n.to_string()));
    }
    // The plan still works afterwards.
    assert_frame(&mut plan, &mesh, &mut out, "after the errors");
}
