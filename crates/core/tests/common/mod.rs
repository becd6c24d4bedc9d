//! Meshes shared by the tests of the fast paths of area-weighted vertex normals
//! (`normals_fast.rs`, the one-shot path; `normals_plan.rs`, the plan for moving positions): seeded
//! random meshes full of what a fast path must hand to the exact code — repeated and collinear
//! corners, slivers through rounded midpoints, needles, corners with wide exponent ranges,
//! back-to-back faces that cancel, isolated vertices, non-finite corners — and the comparison
//! by bits.

// Each test crate that includes this module uses only part of it.
#![allow(dead_code)]

use cg_core::mesh::Mesh;
use cg_core::normals::{Fallback, VertexNormals};
use cg_testkit::Inputs;
use glam::Vec3;

/// The normals as bits (so −0.0 and +0.0 differ, and NaN would be seen), and the fallbacks.
pub fn bits(v: &VertexNormals) -> (Vec<[u32; 3]>, Vec<(u32, Fallback)>) {
    (v.normals.iter().map(|n| n.to_array().map(f32::to_bits)).collect(), v.fallbacks.clone())
}

/// A corner for a random mesh: ordinary, tiny, huge, or with wide-ranging exponents.
pub fn corner(s: &mut Inputs) -> Vec3 {
    match s.int(0, 5) {
        0 => s.vec3_in_cube(1.0),
        1 => s.vec3_log_uniform(-30.0, 30.0),
        2 => s.vec3_in_cube(1.0) + Vec3::splat(1e6),
        3 => s.vec3_log_uniform(-8.0, 2.0),
        _ => s.vec3_in_cube(1e-3),
    }
}

pub fn random_mesh(s: &mut Inputs) -> Mesh {
    let n = s.int(3, 60) as usize;
    let mut positions: Vec<Vec3> = (0..n).map(|_| corner(s)).collect();
    let mut faces = Vec::new();
    let index = |s: &mut Inputs| s.int(0, n as i64) as u32;
    for _ in 0..s.int(1, 120) {
        let [a, b, c] = [index(s), index(s), index(s)];
        match s.int(0, 8) {
            // A sliver through the rounded midpoint of an edge (collinear within f32).
            0 => {
                positions.push((positions[a as usize] + positions[b as usize]) * 0.5);
                faces.push([a, b, positions.len() as u32 - 1]);
            }
            // A needle: the third corner a hair off the edge.
            1 => {
                let (p, q) = (positions[a as usize], positions[b as usize]);
                positions.push(p.lerp(q, 0.3) + Vec3::new(0.0, 1e-6, 1e-7));
                faces.push([a, b, positions.len() as u32 - 1]);
            }
            // Back to back: the same face twice, opposite windings (their normals cancel).
            2 => faces.extend([[a, b, c], [a, c, b]]),
            // A repeated corner.
            3 => faces.push([a, a, c]),
            _ => faces.push([a, b, c]),
        }
    }
    // A few isolated vertices, and now and then a corner that is not finite.
    positions.extend((0..s.int(0, 3)).map(|_| corner(s)));
    if s.int(0, 10) == 0 {
        let k = s.int(0, n as i64) as usize;
        positions[k].y = if s.coin() { f32::NAN } else { f32::INFINITY };
    }
    Mesh { positions, faces, normals: None, uvs: None, colors: None }
}

/// Random meshes side by side in one mesh of at least `faces` faces, with the vertices numbered
/// in random order (Fisher–Yates with the seeded stream) so that faces straddle any range of
/// vertex numbers.
pub fn large_random_mesh(s: &mut Inputs, faces: usize) -> Mesh {
    let mut big = Mesh { positions: vec![], faces: vec![], normals: None, uvs: None, colors: None };
    while big.faces.len() < faces {
        let mut part = random_mesh(s);
        let offset = big.positions.len() as u32;
        big.positions.append(&mut part.positions);
        big.faces.extend(part.faces.iter().map(|f| f.map(|v| v + offset)));
    }
    shuffled(&big, s)
}

/// The mesh with its vertices renumbered at random (the faces follow).
pub fn shuffled(mesh: &Mesh, s: &mut Inputs) -> Mesh {
    let n = mesh.positions.len();
    let mut order: Vec<u32> = (0..n as u32).collect();
    for i in (1..n).rev() {
        order.swap(i, s.int(0, i as i64 + 1) as usize);
    }
    let mut positions = vec![Vec3::ZERO; n];
    for (old, &new) in order.iter().enumerate() {
        positions[new as usize] = mesh.positions[old];
    }
    let faces = mesh.faces.iter().map(|f| f.map(|v| order[v as usize])).collect();
    Mesh::new(positions, faces)
}

/// How many vertices of `normals` fell back because their faces' normals cancel.
pub fn cancelled(normals: &VertexNormals) -> usize {
    normals.fallbacks.iter().filter(|(_, f)| matches!(f, Fallback::Cancelled { .. })).count()
}
