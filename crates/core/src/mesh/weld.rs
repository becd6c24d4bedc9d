//! Welding vertices by position, and the grid hashing it shares with the T-junction search.

use std::collections::HashMap;

use glam::{DVec3, Vec3};

use super::{Mesh, gather};

// ---------------------------------------------------------------------------------------------
// Welding (頂点の統合)

/// The result of [`Mesh::weld_by_position`].
#[derive(Clone, Debug, PartialEq)]
pub struct Welded {
    /// The welded mesh.
    pub mesh: Mesh,
    /// For each old vertex, its vertex in the welded mesh.
    pub remap: Vec<u32>,
    /// The old faces left out of the welded mesh, in increasing order: faces that collapsed
    /// (two corners welded into one, or a repeated index to begin with) and faces with an index
    /// out of range.
    pub removed_faces: Vec<usize>,
}

impl Mesh {
    /// Merges vertices at the same position (頂点の統合), so that faces which meant to share a
    /// vertex, but used duplicates of it, share one index (docs/numerics.md row 3: a seam welded this
    /// way shows no crease).
    ///
    /// Vertices are visited in order; each one joins the lowest-numbered earlier *kept* vertex
    /// within `tolerance` (Euclidean distance, in f64) or is kept itself. So the result is
    /// deterministic, kept vertices keep their order, and every vertex is within `tolerance` of
    /// the vertex it became (clusters do not chain). `tolerance == 0.0` merges bit-equal positions
    /// only, with +0 and −0 equal. A negative or NaN tolerance counts as 0; an infinite one merges
    /// every finite position. Non-finite positions are never merged.
    ///
    /// A merged vertex keeps the first occurrence's normal, texture coordinate and colour: at a
    /// texture seam the two texture coordinates cannot both survive (weld only what should be one
    /// vertex). An attribute vector whose length differs from the vertex count is dropped (`None`).
    ///
    /// Faces whose corners collapse into fewer than three vertices, and faces with an index out
    /// of range, are removed and listed in [`Welded::removed_faces`].
    ///
    /// O(n): positions are hashed on a grid of cell size `tolerance`; each vertex checks its own
    /// and the 26 neighbouring cells.
    ///
    /// See also [`Mesh::validate`], which reports the boundary edges that duplicated vertices
    /// leave.
    #[must_use]
    pub fn weld_by_position(&self, tolerance: f32) -> Welded {
        let n = self.positions.len();
        let mut remap = vec![0u32; n];
        // The old vertex that each new vertex comes from.
        let mut kept: Vec<usize> = Vec::new();
        let keep = |old: usize, kept: &mut Vec<usize>| {
            kept.push(old);
            (kept.len() - 1) as u32
        };
        if tolerance > 0.0 {
            let tol = f64::from(tolerance);
            // A little larger than the tolerance, so that rounding in p / cell cannot put two
            // positions within tolerance more than one cell apart; and at least the positions'
            // largest magnitude over 2⁵⁰, so that p / cell stays far inside i64 (a tolerance of
            // 1e-20 saturated every cell index, all vertices met in a few cells, and loading took
            // hours). A larger cell only adds candidates; f32 positions that far apart in their
            // last bits are never within such a tolerance anyway.
            let largest = self
                .positions
                .iter()
                .filter(|p| p.is_finite())
                .map(|p| f64::from(p.abs().max_element()))
                .fold(0.0, f64::max);
            let cell = (tol * (1.0 + 1e-9)).max(largest * 2f64.powi(-50));
            let grid = Grid { origin: DVec3::ZERO, cell };
            let mut hash = SpatialHash::new(n);
            for (old, p) in self.positions.iter().enumerate() {
                if !p.is_finite() {
                    remap[old] = keep(old, &mut kept);
                    continue;
                }
                let p = p.as_dvec3();
                let [x, y, z] = grid.cell(p);
                let mut best: Option<u32> = None;
                for dx in -1..=1 {
                    for dy in -1..=1 {
                        for dz in -1..=1 {
                            hash.visit(
                                [x.saturating_add(dx), y.saturating_add(dy), z.saturating_add(dz)],
                                |r| {
                                    let q = self.positions[kept[r as usize]].as_dvec3();
                                    if p.distance_squared(q) <= tol * tol
                                        && best.is_none_or(|b| r < b)
                                    {
                                        best = Some(r);
                                    }
                                },
                            );
                        }
                    }
                }
                remap[old] = best.unwrap_or_else(|| {
                    let r = keep(old, &mut kept);
                    hash.insert([x, y, z], r);
                    r
                });
            }
        } else {
            let mut seen: HashMap<[u32; 3], u32> = HashMap::new();
            for (old, p) in self.positions.iter().enumerate() {
                if !p.is_finite() {
                    remap[old] = keep(old, &mut kept);
                    continue;
                }
                // Adding +0 turns −0 into +0 and changes nothing else.
                let bits = (*p + Vec3::ZERO).to_array().map(f32::to_bits);
                remap[old] = *seen.entry(bits).or_insert_with(|| keep(old, &mut kept));
            }
        }

        let mut faces = Vec::with_capacity(self.faces.len());
        let mut removed_faces = Vec::new();
        for (i, f) in self.faces.iter().enumerate() {
            if f.iter().any(|&v| v as usize >= n) {
                removed_faces.push(i);
                continue;
            }
            let [a, b, c] = f.map(|v| remap[v as usize]);
            if a == b || b == c || c == a {
                removed_faces.push(i);
            } else {
                faces.push([a, b, c]);
            }
        }
        let mesh = Mesh {
            positions: kept.iter().map(|&old| self.positions[old]).collect(),
            faces,
            normals: gather(self.normals.as_deref(), n, &kept),
            uvs: gather(self.uvs.as_deref(), n, &kept),
            colors: gather(self.colors.as_deref(), n, &kept),
        };
        Welded { mesh, remap, removed_faces }
    }
}

// ---------------------------------------------------------------------------------------------
// Grid hashing, shared by the T-junction search and welding.

/// A uniform grid of cubic cells.
pub(super) struct Grid {
    pub(super) origin: DVec3,
    pub(super) cell: f64,
}

impl Grid {
    /// The integer coordinates of the cell holding `p` (saturating far outside).
    pub(super) fn cell(&self, p: DVec3) -> [i64; 3] {
        ((p - self.origin) / self.cell).floor().to_array().map(|c| c as i64)
    }
}

/// Items filed by grid cell in a fixed number of buckets (spatial hashing, Teschner et al.
/// 2003): each bucket is a linked list threaded through `next`. Cells that share a bucket only
/// add candidates; callers test every candidate exactly.
pub(super) struct SpatialHash {
    /// First item of each bucket (`u32::MAX`: empty); the bucket count is a power of two.
    head: Vec<u32>,
    /// `(item, next entry)` for each inserted entry.
    entries: Vec<(u32, u32)>,
}

impl SpatialHash {
    /// A table for about `capacity` items.
    pub(super) fn new(capacity: usize) -> SpatialHash {
        let buckets = (2 * capacity).next_power_of_two().max(16);
        SpatialHash { head: vec![u32::MAX; buckets], entries: Vec::with_capacity(capacity) }
    }

    pub(super) fn bucket(&self, [x, y, z]: [i64; 3]) -> usize {
        let h = (x as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15)
            ^ (y as u64).wrapping_mul(0xC2B2_AE3D_27D4_EB4F)
            ^ (z as u64).wrapping_mul(0x1656_67B1_9E37_79F9);
        ((h ^ (h >> 29)) as usize) & (self.head.len() - 1)
    }

    pub(super) fn insert(&mut self, cell: [i64; 3], item: u32) {
        let b = self.bucket(cell);
        self.entries.push((item, self.head[b]));
        self.head[b] = (self.entries.len() - 1) as u32;
    }

    /// Calls `f` with every item in the bucket of `cell` (a superset of the cell's items).
    pub(super) fn visit(&self, cell: [i64; 3], mut f: impl FnMut(u32)) {
        let mut at = self.head[self.bucket(cell)];
        while at != u32::MAX {
            let (item, next) = self.entries[at as usize];
            f(item);
            at = next;
        }
    }
}
