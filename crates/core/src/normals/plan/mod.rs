//! Area-weighted vertex normals of a mesh whose faces stay fixed while its positions move (an
//! animation, a deforming model): a [`NormalsPlan`] is made once from the faces, and each frame's
//! call reuses it. Bit for bit [`vertex_normals_reference`](super::vertex_normals_reference) with
//! [`Weighting::Area`], as the one-shot fast path is.
//!
//! Why a gather gives the reference's bits: the reference adds, for every vertex, the record
//! `[x, y, z, |n|]` of each face that uses it (the exact area vector and its length; zeros for an
//! unusable face) to sums that start at +0.0, face after face. A vertex that adds the records of
//! its own faces in ascending face order performs the same f64 additions in the same order, so
//! its sums have the same bits, and so has everything computed from them. (A face that lists a
//! vertex twice has no area; its zero record changes no bit of a sum that starts at +0.0.)
//!
//! How the plan keeps the work local: the vertices are cut into *tiles* of at most
//! [`VERTEX_CAP`] vertices whose faces number at most [`FACE_CAP`]. Per frame, each tile reads
//! its corners once into f64 and checks them once (all finite, each coordinate's magnitudes close
//! enough for every edge to be exact in f64; a corner that is not is marked), computes its
//! faces' records ([`tile::records`]: edges, Kahan's cross product with hardware FMA, one
//! comparison against a degeneracy bound taken from the tile's extent; the rare face that fails
//! goes the exact way) into a buffer that stays in the core's cache, gathers them for its
//! vertices, and normalises them (the one-shot path's kernel); tiles run on all cores. On x86-64
//! with AVX2 and FMA these steps are hand-vectorised ([`tile`]); the bits are the same.
//! A face whose corners lie in different tiles is computed once per tile, so the plan picks, of
//! two cuttings, the one that repeats fewer faces (see [`NormalsPlan::new`]): runs of
//! consecutive vertex numbers (the results go straight to the output), or patches grown
//! breadth-first over the mesh (a renumbering; the results go through one more pass that puts
//! them back in the mesh's order). A vertex with more than [`BIG`] faces, or whose normal the
//! fast steps cannot vouch for (no usable face, cancelling faces), is settled afterwards by the
//! reference's own arithmetic. On a CPU without FMA the records come from the one-shot path's
//! kernel instead. docs/performance.md has the figures.

use std::cell::RefCell;
use std::collections::VecDeque;
use std::ops::Range;

use glam::Vec3;
use rayon::prelude::*;

use super::fast::Record;
use super::{Accumulator, Kernels, VertexNormals, Weighting, corner_geometry};
use crate::lang::{Lang, Text};
use crate::mesh::{Mesh, MeshError};

mod tile;

/// Faces per tile at most: their records (32 B each, 64 KiB) stay in the core's cache.
const FACE_CAP: usize = 2048;
/// Vertices per tile at most.
const VERTEX_CAP: usize = 1024;
/// A tile's corners at most (the distinct corners of its faces), a power of two.
const CORNER_CAP: usize = 8192;
const _: () = assert!(3 * FACE_CAP <= CORNER_CAP && FACE_CAP.is_power_of_two());
/// A vertex with more faces than this takes no part in the tiles (it would fill one on its own):
/// it is settled by the reference's arithmetic each frame.
const BIG: usize = 256;
/// Below this many faces the tiles run on one thread.
const PARALLEL_FACES: usize = 1 << 14;
/// Vertices per task of the pass that puts the normals back in the mesh's order.
const PERMUTE_TASK: usize = 1 << 14;
/// The renumbered cutting is taken when it repeats this fraction of the faces fewer than
/// consecutive numbers do (it costs one more pass over the vertices).
const RENUMBER_GAIN: f64 = 0.15;

thread_local! {
    /// Each thread's buffers for one tile (352 KiB), allocated once per thread, not per frame.
    static TILE_BUFFERS: RefCell<TileBuffers> = const {
        RefCell::new(TileBuffers { records: Vec::new(), sums: Vec::new(), corners: Vec::new() })
    };
}

/// One thread's buffers for one tile.
struct TileBuffers {
    /// The record `[x, y, z, m]` of each face of the tile: its area vector and `|x| + |y| + |z|`
    /// (`|n|` where the one-shot path's kernel or the exact code made it).
    records: Vec<Record>,
    /// Each vertex's sums `[x, y, z, m]`, `m` an upper bound of the reference's length sum.
    sums: Vec<Record>,
    /// The tile's corners in f64, `[x, y, z, 0]`.
    corners: Vec<[f64; 4]>,
}

/// Why a [`NormalsPlan`] could not be made, or could not be used with the positions given.
///
/// `Display` gives the English message; [`PlanError::message`] gives it in either language.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PlanError {
    /// A face refers to a vertex that does not exist (always
    /// [`MeshError::IndexOutOfRange`]).
    #[error("the faces cannot be used: {0}")]
    Mesh(MeshError),
    /// The positions are not one per vertex of the plan.
    #[error("the plan was made for {expected} vertices, but {found} positions were given")]
    PositionCount {
        /// The vertex count the plan was made for.
        expected: usize,
        /// How many positions were given.
        found: usize,
    },
    /// More than 2³² − 1 vertices or corners (3 per face): the plan numbers them with `u32`.
    #[error("the mesh is too large for a plan: {faces} faces and {vertices} vertices")]
    TooLarge {
        /// The face count.
        faces: usize,
        /// The vertex count.
        vertices: usize,
    },
}

impl PlanError {
    /// The message for a student in `lang` (the `Display` text is the English one).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let ja = match self {
            PlanError::Mesh(e) => format!("面が使えません: {}", e.text().ja),
            PlanError::PositionCount { expected, found } => format!(
                "この計画は頂点 {expected} 個のメッシュ用ですが、位置が {found} 個与えられました"
            ),
            PlanError::TooLarge { faces, vertices } => {
                format!("計画を作るにはメッシュが大きすぎます: 面 {faces} 枚、頂点 {vertices} 個")
            }
        };
        Text::new(ja, self.to_string())
    }
}

/// A plan for the area-weighted vertex normals of a mesh with fixed faces and moving positions
/// (頂点の位置だけが毎フレーム変わるメッシュの頂点法線): made once from the faces, then
/// [`NormalsPlan::area_normals_into`] gives each frame's normals, bit for bit
/// [`vertex_normals_reference`](super::vertex_normals_reference)`(mesh, Weighting::Area)` —
/// fallbacks included — into an output it reuses, so a frame allocates nothing.
///
/// ```
/// use cg_core::normals::{NormalsPlan, VertexNormals, Weighting, vertex_normals_reference};
/// use cg_core::shapes::icosphere;
///
/// let mut mesh = icosphere(1.0, 3).unwrap();
/// let mut plan = NormalsPlan::for_mesh(&mesh).unwrap();
/// let mut out = VertexNormals::default();
/// for frame in 0..3 {
///     // The mesh moves (its faces stay); the plan is reused.
///     let squash = 1.0 + 0.1 * frame as f32;
///     mesh.positions.iter_mut().for_each(|p| p.y /= squash);
///     plan.area_normals_into(&mesh.positions, &mut out).unwrap();
///     assert_eq!(out, vertex_normals_reference(&mesh, Weighting::Area));
/// }
/// // Positions for another mesh are refused, not misread.
/// assert!(plan.area_normals_into(&mesh.positions[1..], &mut out).is_err());
/// ```
///
/// The plan holds the faces and a tiling of the mesh (about 65 bytes per face in all) and, where
/// it renumbers the vertices, a buffer of one normal per vertex; the latter is why a call takes
/// `&mut self`. Each thread that runs a tile keeps 352 KiB of buffers for the life of the thread.
/// docs/performance.md has the figures (it is about twice as fast as the one-shot
/// [`vertex_normals`](super::vertex_normals) on the same positions).
#[derive(Clone, Debug)]
pub struct NormalsPlan {
    vertex_count: usize,
    /// The mesh's faces, for the vertices settled by the reference's arithmetic.
    faces: Vec<[u32; 3]>,
    /// The faces of vertex `v` (ascending) are `vertex_faces[vertex_face_start[v]..][..]`.
    vertex_face_start: Vec<u32>,
    vertex_faces: Vec<u32>,
    /// Tile `t` owns the vertices `tile_vertex_start[t]..tile_vertex_start[t + 1]` of the plan's
    /// order and computes the faces `tile_face_start[t]..tile_face_start[t + 1]` of `tile_faces`
    /// (in ascending face order, the corners as the mesh numbers them).
    tile_vertex_start: Vec<u32>,
    tile_face_start: Vec<u32>,
    tile_faces: Vec<[u32; 3]>,
    /// The same faces with their corners numbered within the tile: tile `t`'s corners are
    /// `local_vertices[tile_local_start[t]..tile_local_start[t + 1]]`, in order of first use.
    tile_local_start: Vec<u32>,
    local_vertices: Vec<u32>,
    local_faces: Vec<[u16; 3]>,
    /// The tile-local face slots of the `i`-th vertex of the plan's order (ascending):
    /// `refs[ref_start[i]..ref_start[i + 1]]`.
    ref_start: Vec<u32>,
    refs: Vec<u16>,
    /// Where each vertex of the mesh stands in the plan's order; `None` when that order is the
    /// mesh's own.
    position_in_order: Option<Vec<u32>>,
    /// The normals in the plan's order (only when it renumbers).
    in_order: Vec<Vec3>,
}

/// A cutting of the vertices into tiles, before its local tables are built.
struct Tiling {
    /// The vertices in tile order.
    order: Vec<u32>,
    vertex_start: Vec<u32>,
    /// Each tile's faces (ascending within a tile).
    face_ids: Vec<u32>,
    face_start: Vec<u32>,
}

impl NormalsPlan {
    /// The plan for `mesh`'s faces (its positions are not looked at).
    ///
    /// # Errors
    /// As [`NormalsPlan::new`].
    pub fn for_mesh(mesh: &Mesh) -> Result<NormalsPlan, PlanError> {
        NormalsPlan::new(&mesh.faces, mesh.positions.len())
    }

    /// The plan for a mesh of `vertex_count` vertices with these faces. It tries two cuttings
    /// into tiles — runs of consecutive vertex numbers, and patches grown breadth-first — and
    /// keeps the one that computes fewer faces twice (a renumbering must save 15 % of the
    /// faces to pay for its extra pass). Takes about as long as 20 to
    /// 30 frames.
    ///
    /// # Errors
    /// [`PlanError::Mesh`] ([`MeshError::IndexOutOfRange`]) naming the first face corner whose
    /// index is not below `vertex_count`; [`PlanError::TooLarge`] for more than 2³² − 1 vertices
    /// or corners.
    pub fn new(faces: &[[u32; 3]], vertex_count: usize) -> Result<NormalsPlan, PlanError> {
        let limit = u32::MAX as usize;
        if vertex_count > limit || faces.len() > limit / 3 {
            return Err(PlanError::TooLarge { faces: faces.len(), vertices: vertex_count });
        }
        for (face, corners) in faces.iter().enumerate() {
            for (corner, &index) in corners.iter().enumerate() {
                if index as usize >= vertex_count {
                    let e = MeshError::IndexOutOfRange { face, corner, index, vertex_count };
                    return Err(PlanError::Mesh(e));
                }
            }
        }
        // The faces of every vertex, in ascending face order (a counting sort).
        let mut vertex_face_start = vec![0u32; vertex_count + 1];
        for &v in faces.iter().flatten() {
            vertex_face_start[v as usize + 1] += 1;
        }
        for v in 0..vertex_count {
            vertex_face_start[v + 1] += vertex_face_start[v];
        }
        let mut fill = vertex_face_start.clone();
        let mut vertex_faces = vec![0u32; 3 * faces.len()];
        for (f, face) in faces.iter().enumerate() {
            for &v in face {
                vertex_faces[fill[v as usize] as usize] = f as u32;
                fill[v as usize] += 1;
            }
        }
        drop(fill);
        let faces_of = |v: usize| {
            &vertex_faces[vertex_face_start[v] as usize..vertex_face_start[v + 1] as usize]
        };
        let runs = tiling(faces, vertex_count, &faces_of, false);
        let patches = tiling(faces, vertex_count, &faces_of, true);
        let renumber =
            (patches.face_ids.len() as f64) < (1.0 - RENUMBER_GAIN) * runs.face_ids.len() as f64;
        let tiling = if renumber { patches } else { runs };

        // The local tables: each tile's faces, and each vertex's slots among them.
        let mut slot = vec![0u16; faces.len()];
        let mut ref_start = Vec::with_capacity(vertex_count + 1);
        ref_start.push(0u32);
        let mut refs = Vec::with_capacity(3 * faces.len());
        for t in 0..tiling.vertex_start.len() - 1 {
            let tile_faces = &tiling.face_ids[span(&tiling.face_start, t)];
            for (i, &f) in tile_faces.iter().enumerate() {
                slot[f as usize] = i as u16;
            }
            for &v in &tiling.order[span(&tiling.vertex_start, t)] {
                let own = faces_of(v as usize);
                if own.len() <= BIG {
                    refs.extend(own.iter().map(|&f| slot[f as usize]));
                }
                ref_start.push(refs.len() as u32);
            }
        }
        let tile_faces: Vec<[u32; 3]> =
            tiling.face_ids.iter().map(|&f| faces[f as usize]).collect();
        let mut tile_local_start = vec![0u32];
        let mut local_vertices = Vec::with_capacity(vertex_count + vertex_count / 4);
        let mut local_faces = Vec::with_capacity(tile_faces.len());
        let (mut stamp, mut local_of) = (vec![u32::MAX; vertex_count], vec![0u16; vertex_count]);
        for t in 0..tiling.vertex_start.len() - 1 {
            let first = local_vertices.len();
            let mut local = |v: u32, local_vertices: &mut Vec<u32>| {
                if stamp[v as usize] != t as u32 {
                    stamp[v as usize] = t as u32;
                    local_of[v as usize] = (local_vertices.len() - first) as u16;
                    local_vertices.push(v);
                }
                local_of[v as usize]
            };
            for face in &tile_faces[span(&tiling.face_start, t)] {
                local_faces.push(face.map(|v| local(v, &mut local_vertices)));
            }
            tile_local_start.push(local_vertices.len() as u32);
        }
        let position_in_order = renumber.then(|| {
            let mut at = vec![0u32; vertex_count];
            for (i, &v) in tiling.order.iter().enumerate() {
                at[v as usize] = i as u32;
            }
            at
        });
        Ok(NormalsPlan {
            vertex_count,
            faces: faces.to_vec(),
            vertex_face_start,
            vertex_faces,
            tile_vertex_start: tiling.vertex_start,
            tile_face_start: tiling.face_start,
            tile_faces,
            tile_local_start,
            local_vertices,
            local_faces,
            ref_start,
            refs,
            in_order: if renumber { vec![Vec3::ZERO; vertex_count] } else { Vec::new() },
            position_in_order,
        })
    }

    /// The number of vertices the plan was made for.
    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.vertex_count
    }

    /// The number of faces.
    #[must_use]
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    /// How many face records a frame computes per face of the mesh (1.0 when no face is shared
    /// by two tiles), and whether the plan renumbers the vertices: for the benchmark's notes.
    #[must_use]
    pub fn layout(&self) -> (f64, bool) {
        let ratio = self.tile_faces.len() as f64 / self.faces.len().max(1) as f64;
        (ratio, self.position_in_order.is_some())
    }

    /// The area-weighted vertex normals for `positions` (one per vertex, in the mesh's order),
    /// written into `out` — its `normals` resized to the vertex count, its `fallbacks` cleared
    /// and refilled — bit for bit what
    /// [`vertex_normals_reference`](super::vertex_normals_reference)`(mesh, Weighting::Area)`
    /// gives for a mesh with these faces and positions (and what
    /// [`vertex_normals`](super::vertex_normals) gives). Once `out` has held a result for this
    /// plan, nothing is allocated.
    ///
    /// # Errors
    /// [`PlanError::PositionCount`] when `positions` is not one per vertex of the plan (`out` is
    /// then left as it was).
    pub fn area_normals_into(
        &mut self,
        positions: &[Vec3],
        out: &mut VertexNormals,
    ) -> Result<(), PlanError> {
        self.run(positions, out, Kernels::Best)
    }

    /// [`NormalsPlan::area_normals_into`] with the face kernel of a CPU without FMA, whatever
    /// this CPU has: for the tests, which must cover both kernels on any machine.
    ///
    /// # Errors
    /// As [`NormalsPlan::area_normals_into`].
    #[doc(hidden)]
    pub fn area_normals_into_without_fma(
        &mut self,
        positions: &[Vec3],
        out: &mut VertexNormals,
    ) -> Result<(), PlanError> {
        self.run(positions, out, Kernels::NoFma)
    }

    /// [`NormalsPlan::area_normals_into`] without the hand-vectorised kernels, as on a CPU with
    /// FMA but without AVX2 (an ARM Mac, say), whatever this CPU has: for the tests.
    ///
    /// # Errors
    /// As [`NormalsPlan::area_normals_into`].
    #[doc(hidden)]
    pub fn area_normals_into_without_simd(
        &mut self,
        positions: &[Vec3],
        out: &mut VertexNormals,
    ) -> Result<(), PlanError> {
        self.run(positions, out, Kernels::Compiled)
    }

    fn run(
        &mut self,
        positions: &[Vec3],
        out: &mut VertexNormals,
        kernels: Kernels,
    ) -> Result<(), PlanError> {
        let n = self.vertex_count;
        if positions.len() != n {
            return Err(PlanError::PositionCount { expected: n, found: positions.len() });
        }
        if out.normals.len() != n {
            out.normals.clear();
            out.normals.resize(n, Vec3::ZERO);
        }
        out.fallbacks.clear();
        let parallel = self.faces.len() >= PARALLEL_FACES && rayon::current_num_threads() > 1;
        let mut in_order = std::mem::take(&mut self.in_order);
        let tiles = 0..self.tile_vertex_start.len() - 1;
        let work = Work { plan: self, positions, kernels, parallel };
        let unresolved = if let Some(at) = &self.position_in_order {
            let unresolved = work.tiles(tiles, &mut in_order);
            let put_back = |(out, at): (&mut [Vec3], &[u32])| {
                for (normal, &i) in out.iter_mut().zip(at) {
                    *normal = in_order[i as usize];
                }
            };
            if parallel {
                out.normals
                    .par_chunks_mut(PERMUTE_TASK)
                    .zip(at.par_chunks(PERMUTE_TASK))
                    .for_each(put_back);
            } else {
                put_back((&mut out.normals, at));
            }
            unresolved
        } else {
            work.tiles(tiles, &mut out.normals)
        };
        self.in_order = in_order;
        if unresolved > 0 {
            self.settle(positions, out);
        }
        Ok(())
    }

    /// Gives the vertices whose normal is NaN (the fast steps could not vouch for it) the
    /// reference's normal and fallback, with the reference's own arithmetic.
    fn settle(&self, positions: &[Vec3], out: &mut VertexNormals) {
        for (v, normal) in out.normals.iter_mut().enumerate() {
            if !normal.x.is_nan() {
                continue;
            }
            let mut acc = Accumulator::default();
            for &f in &self.vertex_faces[span(&self.vertex_face_start, v)] {
                acc.touched = true;
                let corners = self.faces[f as usize].map(|i| positions[i as usize]);
                if let Some(g) = corner_geometry(corners) {
                    acc.add(f, &g, 0, Weighting::Area);
                }
            }
            let (unit, fallback) = acc.resolve();
            *normal = unit;
            if let Some(why) = fallback {
                out.fallbacks.push((v as u32, why));
            }
        }
    }
}

/// The range `start[i]..start[i + 1]`.
#[inline]
fn span(start: &[u32], i: usize) -> Range<usize> {
    start[i] as usize..start[i + 1] as usize
}

/// Cuts the vertices into tiles: in their own order (`patches` false), or in patches grown
/// breadth-first from a seed (the lowest-numbered vertex not yet taken, or where the last patch
/// stopped), each patch taking vertices until one more would exceed [`FACE_CAP`] faces or
/// [`VERTEX_CAP`] vertices. Vertices with more than [`BIG`] faces join a tile without faces.
fn tiling<'a>(
    faces: &[[u32; 3]],
    vertex_count: usize,
    faces_of: &dyn Fn(usize) -> &'a [u32],
    patches: bool,
) -> Tiling {
    let mut t = Tiling {
        order: Vec::with_capacity(vertex_count),
        vertex_start: vec![0],
        face_ids: Vec::with_capacity(faces.len() * 3 / 2),
        face_start: vec![0],
    };
    let mut taken_by = vec![u32::MAX; faces.len()];
    let mut assigned = vec![false; vertex_count];
    let mut queue = VecDeque::new();
    let (mut seed, mut tile, mut tile_faces, mut tile_vertices) = (0usize, 0u32, 0usize, 0usize);
    let close = |t: &mut Tiling| {
        let first = *t.face_start.last().unwrap_or(&0) as usize;
        t.face_ids[first..].sort_unstable();
        // The tile's vertices in the mesh's order: its positions are then read, and its normals
        // put back, in ascending addresses.
        let first = *t.vertex_start.last().unwrap_or(&0) as usize;
        t.order[first..].sort_unstable();
        t.face_start.push(t.face_ids.len() as u32);
        t.vertex_start.push(t.order.len() as u32);
    };
    loop {
        let next = loop {
            match queue.pop_front() {
                Some(v) if assigned[v] => {}
                Some(v) => break Some(v),
                None => {
                    while seed < vertex_count && assigned[seed] {
                        seed += 1;
                    }
                    break (seed < vertex_count).then_some(seed);
                }
            }
        };
        let Some(v) = next else { break };
        let own = faces_of(v);
        let big = own.len() > BIG;
        let new =
            if big { 0 } else { own.iter().filter(|&&f| taken_by[f as usize] != tile).count() };
        if tile_vertices == VERTEX_CAP || tile_faces + new > FACE_CAP {
            close(&mut t);
            (tile, tile_faces, tile_vertices) = (tile + 1, 0, 0);
            queue.clear();
        }
        assigned[v] = true;
        t.order.push(v as u32);
        tile_vertices += 1;
        for &f in own {
            if !big && taken_by[f as usize] != tile {
                taken_by[f as usize] = tile;
                t.face_ids.push(f);
                tile_faces += 1;
            }
            if patches {
                queue.extend(
                    faces[f as usize].iter().map(|&w| w as usize).filter(|&w| !assigned[w]),
                );
            }
        }
    }
    if tile_vertices > 0 {
        close(&mut t);
    }
    t
}

/// One frame's work over the tiles.
struct Work<'a> {
    plan: &'a NormalsPlan,
    positions: &'a [Vec3],
    kernels: Kernels,
    parallel: bool,
}

impl Work<'_> {
    /// The normals of the vertices of `tiles`, in the plan's order, into `out`; returns how many
    /// are NaN (to be settled).
    fn tiles(&self, tiles: Range<usize>, out: &mut [Vec3]) -> usize {
        let starts = &self.plan.tile_vertex_start;
        if self.parallel && tiles.len() > 1 {
            let mid = tiles.start + tiles.len() / 2;
            let (left, right) = out.split_at_mut((starts[mid] - starts[tiles.start]) as usize);
            let (a, b) = rayon::join(
                || self.tiles(tiles.start..mid, left),
                || self.tiles(mid..tiles.end, right),
            );
            return a + b;
        }
        TILE_BUFFERS.with_borrow_mut(|buffers| {
            let TileBuffers { records, sums, corners } = buffers;
            records.resize(FACE_CAP, [0.0; 4]);
            sums.resize(VERTEX_CAP, [0.0; 4]);
            corners.resize(CORNER_CAP, [0.0; 4]);
            // Fixed sizes, so that the kernels' masked indices need no bounds checks.
            let records: &mut [Record; FACE_CAP] = records.as_mut_slice().try_into().unwrap();
            let corners: &mut [[f64; 4]; CORNER_CAP] = corners.as_mut_slice().try_into().unwrap();
            let mut unresolved = 0;
            let mut out = out;
            for t in tiles {
                let plan = self.plan;
                let in_tile = span(&plan.tile_face_start, t);
                let faces = &plan.tile_faces[in_tile.clone()];
                let vertices = span(starts, t);
                let locals = &plan.local_vertices[span(&plan.tile_local_start, t)];
                tile::records(
                    self.positions,
                    locals,
                    &plan.local_faces[in_tile],
                    faces,
                    corners,
                    &mut records[..faces.len()],
                    self.kernels,
                );
                let sums = &mut sums[..vertices.len()];
                let ref_start = &plan.ref_start[vertices.start..=vertices.end];
                let (here, rest) = std::mem::take(&mut out).split_at_mut(vertices.len());
                unresolved +=
                    tile::gather_units(ref_start, &plan.refs, records, sums, here, self.kernels);
                out = rest;
            }
            unresolved
        })
    }
}
