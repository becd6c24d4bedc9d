//! Which way each face of a closed model points ([`face_outwardness`]): what "outward" means in
//! the data-alone check ([`super::verify_data`]).

use std::collections::HashMap;

use cg_core::glam::{DVec3, Vec3};

/// Which way each face points in a closed model: `Some(true)` when its vertex order makes its
/// normal point outward, `Some(false)` inward, `None` when it cannot be judged (the face is
/// degenerate or names a missing vertex, or its connected part is not closed, not orientable or
/// encloses no volume).
///
/// Faces are oriented consistently across shared edges within each connected part (two faces
/// agree when they traverse their shared edge in opposite directions); the part's signed volume
/// `Σ (a−o)·((b−o)×(c−o))/6` in f64 relative to the centroid `o` of its vertices then says which
/// of the two consistent orientations is outward. So a single face wound the wrong way is named
/// even in a non-convex model, and a model turned inside out has every face named. Never panics.
#[must_use]
pub fn face_outwardness(vertices: &[Vec3], faces: &[[u32; 3]]) -> Vec<Option<bool>> {
    let usable: Vec<bool> = faces
        .iter()
        .map(|f| {
            f.iter().all(|&k| vertices.get(k as usize).is_some_and(|p| p.is_finite()))
                && f[0] != f[1]
                && f[1] != f[2]
                && f[0] != f[2]
        })
        .collect();
    let key = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut edges: HashMap<(u32, u32), Vec<(usize, bool)>> = HashMap::new();
    for (fi, f) in faces.iter().enumerate() {
        if usable[fi] {
            for e in 0..3 {
                let (a, b) = (f[e], f[(e + 1) % 3]);
                edges.entry(key(a, b)).or_default().push((fi, a < b));
            }
        }
    }
    let mut flip: Vec<Option<bool>> = vec![None; faces.len()];
    let mut result = vec![None; faces.len()];
    for seed in 0..faces.len() {
        if flip[seed].is_some() || !usable[seed] {
            continue;
        }
        flip[seed] = Some(false);
        let mut part = vec![seed];
        let mut queue = vec![seed];
        let (mut closed, mut orientable) = (true, true);
        while let Some(f) = queue.pop() {
            let ff = flip[f].unwrap_or(false);
            for e in 0..3 {
                let (a, b) = (faces[f][e], faces[f][(e + 1) % 3]);
                let Some(list) = edges.get(&key(a, b)) else { continue };
                if list.len() != 2 {
                    closed = false;
                    continue;
                }
                let forward = a < b;
                for &(g, g_forward) in list {
                    if g == f {
                        continue;
                    }
                    // g agrees with f when it runs the edge the other way (after both flips).
                    let want = g_forward ^ !(forward ^ ff);
                    match flip[g] {
                        None => {
                            flip[g] = Some(want);
                            part.push(g);
                            queue.push(g);
                        }
                        Some(x) if x != want => orientable = false,
                        Some(_) => {}
                    }
                }
            }
        }
        if !closed || !orientable {
            continue;
        }
        let mut used: Vec<u32> = part.iter().flat_map(|&f| faces[f]).collect();
        used.sort_unstable();
        used.dedup();
        let o = used.iter().map(|&k| vertices[k as usize].as_dvec3()).sum::<DVec3>()
            / used.len() as f64;
        let (mut volume, mut scale) = (0.0f64, 0.0f64);
        for &f in &part {
            let [a, b, c] = faces[f].map(|k| vertices[k as usize].as_dvec3() - o);
            let v = if flip[f] == Some(true) { a.dot(c.cross(b)) } else { a.dot(b.cross(c)) };
            volume += v;
            scale += v.abs();
        }
        if volume.is_nan() || volume.abs() <= 1e-9 * scale {
            continue;
        }
        for &f in &part {
            let flipped = flip[f] == Some(true);
            result[f] = Some(if volume > 0.0 { !flipped } else { flipped });
        }
    }
    result
}
