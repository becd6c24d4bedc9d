//! Indexed triangle meshes (ポリゴンモデル): positions, faces and optional per-vertex attributes,
//! with validation that names the offending faces and edges, and welding by position.
//!
//! A face `[a, b, c]` is front-facing when `a → b → c` runs counter-clockwise seen from outside;
//! its normal is `(p_b − p_a) × (p_c − p_a)` normalised (see [`crate::normals::face_normal`]).

use std::collections::HashSet;
use std::ops::ControlFlow;

use glam::{DVec3, Vec2, Vec3};

/// An indexed triangle mesh. Vertex `i` has `positions[i]` and, where present, `normals[i]`,
/// `uvs[i]` and `colors[i]`; every attribute vector present has one entry per vertex.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions in model space (モデル座標系).
    pub positions: Vec<Vec3>,
    /// Triangles as three vertex indices, counter-clockwise seen from outside.
    pub faces: Vec<[u32; 3]>,
    /// Per-vertex unit normals, when the mesh carries them.
    pub normals: Option<Vec<Vec3>>,
    /// Per-vertex texture coordinates, `(0, 0)` = the image's bottom-left corner.
    pub uvs: Option<Vec<Vec2>>,
    /// Per-vertex colours (with colour-material they set k_a and k_d, as glColor does).
    pub colors: Option<Vec<Vec3>>,
}

impl Mesh {
    /// A mesh with positions and faces and no other attributes. Indices are not checked here:
    /// call [`Mesh::validate`] (or [`Mesh::check_indices`]) before trusting them.
    #[must_use]
    pub fn new(positions: Vec<Vec3>, faces: Vec<[u32; 3]>) -> Mesh {
        Mesh { positions, faces, normals: None, uvs: None, colors: None }
    }

    /// Number of vertices.
    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    #[must_use]
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    /// The three corner positions of face `f`.
    ///
    /// # Panics
    /// When `f` or one of its indices is out of range; call [`Mesh::check_indices`] first on
    /// meshes from user input.
    #[must_use]
    pub fn triangle(&self, f: usize) -> [Vec3; 3] {
        self.faces[f].map(|i| self.positions[i as usize])
    }

    /// Cheap structural check, enough to make every index-based function safe: every face index
    /// is in range, every attribute vector has one entry per vertex, every position is finite.
    ///
    /// # Errors
    /// The first [`MeshError`] found, naming the face, corner, vertex or attribute.
    /// [`Mesh::validate`] reports all of them.
    pub fn check_indices(&self) -> Result<(), MeshError> {
        let mut first = None;
        self.visit_structural_errors(|e| {
            first = Some(e);
            ControlFlow::Break(())
        });
        first.map_or(Ok(()), Err)
    }

    /// Calls `visit` with every structural error, in the order of [`Mesh::check_indices`]:
    /// attribute lengths, then non-finite positions, then out-of-range indices.
    fn visit_structural_errors(&self, mut visit: impl FnMut(MeshError) -> ControlFlow<()>) {
        let n = self.positions.len();
        for (name, len) in [
            ("normals", self.normals.as_ref().map(Vec::len)),
            ("uvs", self.uvs.as_ref().map(Vec::len)),
            ("colors", self.colors.as_ref().map(Vec::len)),
        ] {
            if let Some(len) = len.filter(|&len| len != n) {
                let e = MeshError::AttributeLength { attribute: name, len, expected: n };
                if visit(e).is_break() {
                    return;
                }
            }
        }
        for (vertex, &position) in self.positions.iter().enumerate() {
            if !position.is_finite()
                && visit(MeshError::NonFinitePosition { vertex, position }).is_break()
            {
                return;
            }
        }
        for (face, f) in self.faces.iter().enumerate() {
            for (corner, &index) in f.iter().enumerate() {
                if index as usize >= n {
                    let e = MeshError::IndexOutOfRange { face, corner, index, vertex_count: n };
                    if visit(e).is_break() {
                        return;
                    }
                }
            }
        }
    }
}

/// A structural error that makes a mesh unusable (as opposed to a validation finding such as an
/// open boundary, which is reported by [`Mesh::validate`]).
///
/// `Display` gives the English message; [`MeshError::message`] gives it in either language,
/// [`MeshError::text`] in both.
#[derive(Clone, Debug, PartialEq)]
pub enum MeshError {
    /// A face refers to a vertex that does not exist.
    IndexOutOfRange {
        /// The face (F-number).
        face: usize,
        /// Which corner of the face, 0..3.
        corner: usize,
        /// The index found there.
        index: u32,
        /// How many vertices the mesh has.
        vertex_count: usize,
    },
    /// An attribute vector does not have one entry per vertex.
    AttributeLength {
        /// `normals`, `uvs` or `colors`.
        attribute: &'static str,
        /// How many entries it has.
        len: usize,
        /// How many it should have (the vertex count).
        expected: usize,
    },
    /// A position has an infinite or NaN coordinate.
    NonFinitePosition {
        /// The vertex (V-number).
        vertex: usize,
        /// Its position.
        position: Vec3,
    },
}

// ---------------------------------------------------------------------------------------------
// Validation (ポリゴンモデルの検査)

/// The tolerance of the T-junction test, relative to the edge length: vertex V counts as lying on
/// edge A–B when its distance from the segment is at most `T_JUNCTION_TOLERANCE · |AB|` (plus the
/// rounding of the f32 positions, `2·ε₃₂·max|coordinate|`), and it is farther than that from both
/// ends. 1e-5 is about 100 f32 ulps of the edge length: a midpoint computed in f32 passes, a
/// vertex visibly off the edge (more than 0.001 % of its length) does not.
pub const T_JUNCTION_TOLERANCE: f64 = 1e-5;

/// Which way the faces of a closed, consistently wound mesh face.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Orientation {
    /// Counter-clockwise seen from outside: normals point outward (the kit's convention).
    Outward,
    /// Clockwise seen from outside: every normal points inward (表裏が逆).
    Inward,
}

/// One finding of [`Mesh::validate`], naming the faces (F-numbers), edges and vertices
/// (V-numbers) involved. Edges are written `[from, to]`; where the direction matters (a boundary
/// edge, a winding mistake) it is the direction in which the named face(s) traverse it.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// An index out of range, an attribute of the wrong length or a non-finite position. When any
    /// is present, the other checks (which need valid indices) are skipped.
    Structure(MeshError),
    /// A face uses the same vertex twice (`F7 { V1, V1, V3 }`): it has no area. Such faces take no
    /// part in the edge checks.
    RepeatedIndex {
        /// The face.
        face: usize,
        /// Its three vertex indices.
        vertices: [u32; 3],
    },
    /// A face with three different vertices but zero area: they coincide or lie on one line
    /// ([`crate::normals::face_normal`] is `None`).
    ZeroArea {
        /// The face.
        face: usize,
        /// Its three vertex indices.
        vertices: [u32; 3],
    },
    /// An edge used by one face only: the mesh is not closed there. Legitimate for open meshes
    /// such as the ground grid; the caller decides whether it matters.
    BoundaryEdge {
        /// The edge, in the direction the face traverses it.
        edge: [u32; 2],
        /// The one face that uses it.
        face: usize,
    },
    /// An edge used by more than two faces (a fin, or a duplicated face).
    NonManifoldEdge {
        /// The edge, smaller index first.
        edge: [u32; 2],
        /// Every face that uses it, in increasing order.
        faces: Vec<usize>,
    },
    /// Two faces traverse their shared edge in the same direction: one of them is wound the
    /// wrong way (頂点の順番が逆).
    InconsistentWinding {
        /// The edge, in the direction both faces traverse it.
        edge: [u32; 2],
        /// The two faces, in increasing order.
        faces: [usize; 2],
    },
    /// The faces around a vertex form more than one fan (a bow-tie): two parts touch only at
    /// this vertex.
    NonManifoldVertex {
        /// The vertex.
        vertex: u32,
        /// How many separate fans meet there (≥ 2).
        fans: usize,
    },
    /// A vertex lies strictly inside another face's edge without being one of its corners: the
    /// faces on the two sides do not share their edges (see [`T_JUNCTION_TOLERANCE`]). The
    /// boundary edges along that edge are part of this finding and are not listed again.
    TJunction {
        /// The vertex on the edge.
        vertex: u32,
        /// The edge it lies on, in the direction `face` traverses it.
        edge: [u32; 2],
        /// The face that uses the edge but not the vertex.
        face: usize,
    },
    /// A closed, consistently wound mesh whose signed volume is negative: every face is wound
    /// clockwise seen from outside.
    InwardFacing {
        /// The signed volume (negative).
        signed_volume: f64,
    },
    /// A closed, consistently wound mesh that encloses no volume (faces back to back, a flat
    /// model): its orientation is undefined.
    ZeroVolume {
        /// The signed volume (zero up to rounding).
        signed_volume: f64,
    },
    /// A vertex that no face uses. A lesser finding: it changes nothing that is drawn
    /// (see [`Problem::is_minor`]).
    UnreferencedVertex {
        /// The vertex.
        vertex: u32,
    },
}

/// The result of [`Mesh::validate`]: every finding, and the facts the checks established.
#[derive(Clone, Debug, PartialEq)]
pub struct Validation {
    problems: Vec<Problem>,
    edge_count: usize,
    /// `false` when structural problems stopped the checks.
    checked: bool,
    closed: bool,
    manifold: bool,
    consistent: bool,
    signed_volume: Option<f64>,
    orientation: Option<Orientation>,
}

impl Validation {
    /// Every finding, in a fixed order: structure, degenerate faces, boundary edges, non-manifold
    /// edges, winding, non-manifold vertices, T-junctions, orientation, unreferenced vertices
    /// (each by increasing face, edge or vertex number).
    #[must_use]
    pub fn problems(&self) -> &[Problem] {
        &self.problems
    }

    /// Nothing found, not even a minor finding. An open mesh (the ground grid) is not clean: it
    /// has boundary edges; see [`Validation::is_closed`].
    #[must_use]
    pub fn is_clean(&self) -> bool {
        self.problems.is_empty()
    }

    /// Every edge is used by at least two faces (no boundary edges), and the mesh has a face.
    /// `false` when structural problems stopped the checks.
    #[must_use]
    pub fn is_closed(&self) -> bool {
        self.checked && self.closed
    }

    /// No edge is used by more than two faces and no vertex is a bow-tie. `false` when structural
    /// problems stopped the checks.
    #[must_use]
    pub fn is_manifold(&self) -> bool {
        self.checked && self.manifold
    }

    /// No two faces traverse a shared edge in the same direction (edges used by more than two
    /// faces are not judged). `false` when structural problems stopped the checks.
    #[must_use]
    pub fn is_consistently_wound(&self) -> bool {
        self.checked && self.consistent
    }

    /// Outward or inward, for a closed, consistently wound mesh with no edge used by more than
    /// two faces that encloses a volume; `None` otherwise.
    #[must_use]
    pub fn orientation(&self) -> Option<Orientation> {
        self.orientation
    }

    /// The signed volume enclosed (divergence theorem, f64, relative to the vertex centroid),
    /// positive when the faces face outward. `None` unless the mesh is closed, consistently
    /// wound and has no edge used by more than two faces.
    #[must_use]
    pub fn signed_volume(&self) -> Option<f64> {
        self.signed_volume
    }

    /// The number of distinct edges (unordered vertex pairs) of the faces with three different
    /// vertices; 0 when structural problems stopped the checks. For a closed mesh of genus 0,
    /// `V − E + F = 2`.
    #[must_use]
    pub fn edge_count(&self) -> usize {
        self.edge_count
    }
}

impl Mesh {
    /// Checks the mesh as a polygon model (ポリゴンモデル) and names every problem: structural
    /// errors, degenerate faces, boundary edges, edges used by more than two faces, inconsistent
    /// winding, bow-tie vertices, T-junctions, inward orientation and unreferenced vertices (see
    /// [`Problem`]). The report's requirement "adjacent polygons share their edges"
    /// (隣接するポリゴンが辺を共有する) holds when the result is clean.
    ///
    /// Structural errors (an index out of range, an attribute of the wrong length, a NaN or
    /// infinite position) are all reported, and then the other checks are skipped; nothing
    /// panics. Faces with a repeated index are reported and take no part in the edge checks.
    ///
    /// T-junctions are searched on boundary edges (a vertex inside another face's edge always
    /// leaves some): a vertex counts when it is within [`T_JUNCTION_TOLERANCE`] times the edge's
    /// length of it (plus the f32 rounding of the positions) and farther than that from both ends.
    ///
    /// The orientation comes from the signed volume `Σ (a−o)·((b−o)×(c−o))/6` over the faces
    /// `{a, b, c}` (divergence theorem), in f64 relative to the centroid `o` of the vertices, so
    /// the terms stay small far from the origin. It is the whole mesh's: one part turned inside
    /// out within a larger outward part is not noticed. The volume counts as zero when it is at
    /// most 1e-9 of `Σ |(a−o)·((b−o)×(c−o))|/6` (faces back to back).
    ///
    /// An open mesh such as [`crate::shapes::grid`] legitimately has boundary edges: the caller
    /// decides whether [`Validation::is_closed`] matters.
    ///
    /// O(n log n) in the number of faces (sorting edges; grid hashing for T-junctions): 100k
    /// faces take tens of milliseconds in release, a 100k-face triangle soup (every edge open)
    /// about 0.3 s.
    ///
    /// See also [`Mesh::check_indices`] (cheap, first structural error only) and
    /// [`Mesh::weld_by_position`] (fixes duplicated vertices).
    #[must_use]
    pub fn validate(&self) -> Validation {
        let mut structural = Vec::new();
        self.visit_structural_errors(|e| {
            structural.push(Problem::Structure(e));
            ControlFlow::Continue(())
        });
        if !structural.is_empty() {
            return Validation {
                problems: structural,
                edge_count: 0,
                checked: false,
                closed: false,
                manifold: false,
                consistent: false,
                signed_volume: None,
                orientation: None,
            };
        }

        // Degenerate faces. Faces with three different vertices form the topology.
        let mut degenerate = Vec::new();
        let mut topology: Vec<usize> = Vec::with_capacity(self.faces.len());
        for (face, &vertices) in self.faces.iter().enumerate() {
            let [a, b, c] = vertices;
            if a == b || b == c || c == a {
                degenerate.push(Problem::RepeatedIndex { face, vertices });
                continue;
            }
            topology.push(face);
            let [pa, pb, pc] = self.triangle(face);
            if crate::normals::face_normal(pa, pb, pc).is_none() {
                degenerate.push(Problem::ZeroArea { face, vertices });
            }
        }

        let edges = self.classify_edges(&topology);
        let fans = self.non_manifold_vertices(&topology);
        let t_junctions = self.t_junctions(&edges.boundary);

        // Boundary edges along a T-junction's edge belong to that finding.
        let explained = explained_boundary_edges(&t_junctions);
        let boundary: Vec<Problem> = edges
            .boundary
            .iter()
            .filter(|&&(edge, _)| !explained.contains(&sorted_edge(edge)))
            .map(|&(edge, face)| Problem::BoundaryEdge { edge, face })
            .collect();

        let closed = !topology.is_empty() && edges.boundary.is_empty();
        let consistent = edges.inconsistent.is_empty();
        let manifold = edges.non_manifold.is_empty() && fans.is_empty();
        let (signed_volume, orientation, orientation_problem) =
            if closed && consistent && edges.non_manifold.is_empty() {
                let (volume, magnitude) = self.signed_volume(&topology);
                if volume.abs() <= 1e-9 * magnitude {
                    (Some(volume), None, Some(Problem::ZeroVolume { signed_volume: volume }))
                } else if volume > 0.0 {
                    (Some(volume), Some(Orientation::Outward), None)
                } else {
                    let p = Problem::InwardFacing { signed_volume: volume };
                    (Some(volume), Some(Orientation::Inward), Some(p))
                }
            } else {
                (None, None, None)
            };

        let mut referenced = vec![false; self.positions.len()];
        for f in &self.faces {
            for &i in f {
                referenced[i as usize] = true;
            }
        }
        let unreferenced = referenced
            .iter()
            .enumerate()
            .filter(|&(_, &r)| !r)
            .map(|(v, _)| Problem::UnreferencedVertex { vertex: v as u32 });

        let mut problems = degenerate;
        problems.extend(boundary);
        problems.extend(edges.non_manifold);
        problems.extend(edges.inconsistent);
        problems.extend(fans);
        problems.extend(t_junctions.iter().map(|&(vertex, edge, face)| Problem::TJunction {
            vertex,
            edge,
            face,
        }));
        problems.extend(orientation_problem);
        problems.extend(unreferenced);
        Validation {
            problems,
            edge_count: edges.count,
            checked: true,
            closed,
            manifold,
            consistent,
            signed_volume,
            orientation,
        }
    }

    /// Groups the half-edges of the `topology` faces by their unordered vertex pair (sorting,
    /// O(n log n)) and classifies each edge by how many faces use it and in which direction.
    fn classify_edges(&self, topology: &[usize]) -> EdgeReport {
        // (smaller vertex, larger vertex, face, traversed from smaller to larger)
        let mut half_edges: Vec<(u32, u32, usize, bool)> = Vec::with_capacity(3 * topology.len());
        for &face in topology {
            let [a, b, c] = self.faces[face];
            for (from, to) in [(a, b), (b, c), (c, a)] {
                half_edges.push((from.min(to), from.max(to), face, from < to));
            }
        }
        half_edges.sort_unstable();

        let mut report = EdgeReport::default();
        for group in half_edges.chunk_by(|x, y| (x.0, x.1) == (y.0, y.1)) {
            report.count += 1;
            let (lo, hi) = (group[0].0, group[0].1);
            let directed = |forward: bool| if forward { [lo, hi] } else { [hi, lo] };
            match group {
                [(_, _, face, forward)] => report.boundary.push((directed(*forward), *face)),
                [(_, _, f, forward_f), (_, _, g, forward_g)] => {
                    if forward_f == forward_g {
                        report.inconsistent.push(Problem::InconsistentWinding {
                            edge: directed(*forward_f),
                            faces: [*f, *g],
                        });
                    }
                }
                _ => report.non_manifold.push(Problem::NonManifoldEdge {
                    edge: [lo, hi],
                    faces: group.iter().map(|h| h.2).collect(),
                }),
            }
        }
        report
    }

    /// Vertices whose faces form more than one fan. Two faces around vertex `v` are in the same
    /// fan when a chain of faces joins them, each sharing an edge `v–w` with the next.
    fn non_manifold_vertices(&self, topology: &[usize]) -> Vec<Problem> {
        let around = CornersByVertex::new(self, topology.iter().copied());
        let mut problems = Vec::new();
        let mut pairs: Vec<(u32, usize)> = Vec::new();
        let mut parent: Vec<usize> = Vec::new();
        for v in 0..self.positions.len() {
            let corners = around.at(v);
            if corners.len() < 2 {
                continue;
            }
            pairs.clear();
            for (local, &(face, _)) in corners.iter().enumerate() {
                for &w in &self.faces[face as usize] {
                    if w as usize != v {
                        pairs.push((w, local));
                    }
                }
            }
            pairs.sort_unstable();
            parent.clear();
            parent.extend(0..corners.len());
            let mut fans = corners.len();
            for pair in pairs.windows(2) {
                if pair[0].0 == pair[1].0 && union(&mut parent, pair[0].1, pair[1].1) {
                    fans -= 1;
                }
            }
            if fans > 1 {
                problems.push(Problem::NonManifoldVertex { vertex: v as u32, fans });
            }
        }
        problems
    }

    /// Vertices lying strictly inside a boundary edge of a face that does not use them:
    /// `(vertex, edge, face)`, ordered by edge and then vertex. The candidates (ends of boundary
    /// edges) are hashed on a uniform grid of cells about one edge long; each edge visits the
    /// cells of its bounding box, or, for a long diagonal edge, the cells along it.
    fn t_junctions(&self, boundary: &[([u32; 2], usize)]) -> Vec<(u32, [u32; 2], usize)> {
        if boundary.is_empty() {
            return Vec::new();
        }
        let at = |v: u32| self.positions[v as usize].as_dvec3();
        let mut candidates: Vec<u32> = boundary.iter().flat_map(|(e, _)| *e).collect();
        candidates.sort_unstable();
        candidates.dedup();

        let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
        for &v in &candidates {
            lo = lo.min(at(v));
            hi = hi.max(at(v));
        }
        // Cells about as long as the middle edge (the median: a few far-off or long edges do
        // not change it), but never so small that a cell's index leaves i64. Sized by the
        // bounding box instead (1024 cells along it), a cluster of 100 000 small edges and one
        // stray triangle far off shared a single cell, and every edge met every candidate:
        // hours. An edge whose cells would outnumber the candidates tests the candidates.
        let mut lengths: Vec<f64> =
            boundary.iter().map(|([a, b], _)| at(*a).distance(at(*b))).collect();
        let middle = lengths.len() / 2;
        let median = *lengths.select_nth_unstable_by(middle, f64::total_cmp).1;
        let mut cell = median.max((hi - lo).max_element() / 1e12);
        if !(cell > 0.0 && cell.is_finite()) {
            cell = 1.0;
        }
        let grid = Grid { origin: lo, cell };
        let mut hash = SpatialHash::new(candidates.len());
        for &v in &candidates {
            hash.insert(grid.cell(at(v)), v);
        }

        let mut found = Vec::new();
        let mut last_edge = vec![usize::MAX; self.positions.len()];
        for (e, &([a, b], face)) in boundary.iter().enumerate() {
            let third = self.faces[face].into_iter().find(|&v| v != a && v != b);
            let (pa, pb) = (at(a), at(b));
            let d = pb - pa;
            let length = d.length();
            if length == 0.0 {
                continue;
            }
            let largest = pa.abs().max(pb.abs()).max_element();
            let r = T_JUNCTION_TOLERANCE * length + 2.0 * f64::from(f32::EPSILON) * largest;
            let mut test = |v: u32| {
                if v == a || v == b || Some(v) == third || last_edge[v as usize] == e {
                    return;
                }
                last_edge[v as usize] = e;
                let t = (at(v) - pa).dot(d) / (length * length);
                let off_line = (at(v) - (pa + t * d)).length();
                if off_line <= r && t * length > r && (1.0 - t) * length > r {
                    found.push((v, [a, b], face));
                }
            };
            // Either every cell of the bounding box grown by r …
            let (low, high) = (grid.cell(pa.min(pb) - r), grid.cell(pa.max(pb) + r));
            let box_cells: f64 =
                (0..3).map(|i| high[i].saturating_sub(low[i]) as f64 + 1.0).product();
            // … or, every c along the edge, the cells within k of that point: every point
            // within r of the edge is within c/2 + r ≤ k·c of one of these points.
            let steps = (length / cell).ceil().max(1.0);
            let k = (0.5 + r / cell).ceil();
            let walk_cells = (steps + 1.0) * (2.0 * k + 1.0).powi(3);
            if box_cells.min(walk_cells) >= candidates.len() as f64 {
                candidates.iter().for_each(|&v| test(v));
            } else if box_cells <= walk_cells {
                for x in low[0]..=high[0] {
                    for y in low[1]..=high[1] {
                        for z in low[2]..=high[2] {
                            hash.visit([x, y, z], &mut test);
                        }
                    }
                }
            } else {
                let (steps, k) = (steps as usize, k as i64);
                for s in 0..=steps {
                    let [x, y, z] = grid.cell(pa + d * (s as f64 / steps as f64));
                    for dx in -k..=k {
                        for dy in -k..=k {
                            for dz in -k..=k {
                                hash.visit(
                                    [
                                        x.saturating_add(dx),
                                        y.saturating_add(dy),
                                        z.saturating_add(dz),
                                    ],
                                    &mut test,
                                );
                            }
                        }
                    }
                }
            }
        }
        found.sort_unstable_by_key(|&(v, edge, face)| (sorted_edge(edge), v, face));
        found
    }

    /// The signed volume of the `topology` faces relative to the vertex centroid, and the sum of
    /// the absolute values of the terms (the scale its rounding is judged against).
    fn signed_volume(&self, topology: &[usize]) -> (f64, f64) {
        let mut used = vec![false; self.positions.len()];
        for &face in topology {
            for &v in &self.faces[face] {
                used[v as usize] = true;
            }
        }
        let (sum, count) = self
            .positions
            .iter()
            .zip(&used)
            .filter(|(_, u)| **u)
            .fold((DVec3::ZERO, 0usize), |(s, n), (p, _)| (s + p.as_dvec3(), n + 1));
        let centroid = sum / count.max(1) as f64;
        let (mut volume, mut magnitude) = (0.0, 0.0);
        for &face in topology {
            let [a, b, c] = self.triangle(face).map(|p| p.as_dvec3() - centroid);
            let six_v = a.dot(b.cross(c));
            volume += six_v;
            magnitude += six_v.abs();
        }
        (volume / 6.0, magnitude / 6.0)
    }
}

/// Edges grouped by use.
#[derive(Default)]
struct EdgeReport {
    /// Distinct edges.
    count: usize,
    /// Edges used once, in their face's direction, with the face.
    boundary: Vec<([u32; 2], usize)>,
    /// `Problem::NonManifoldEdge`s.
    non_manifold: Vec<Problem>,
    /// `Problem::InconsistentWinding`s.
    inconsistent: Vec<Problem>,
}

fn sorted_edge([a, b]: [u32; 2]) -> [u32; 2] {
    [a.min(b), a.max(b)]
}

/// The root of `x`'s set in a union-find forest (`parent[r] == r` at a root), with path halving.
pub(crate) fn find_root(parent: &mut [usize], mut x: usize) -> usize {
    while parent[x] != x {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    x
}

/// Joins the sets of `a` and `b` in a union-find forest, the smaller root becoming the root of
/// both; `true` when they were different sets.
pub(crate) fn union(parent: &mut [usize], a: usize, b: usize) -> bool {
    let (x, y) = (find_root(parent, a), find_root(parent, b));
    parent[x.max(y)] = x.min(y);
    x != y
}

/// The corners of some faces grouped by vertex, as a compressed adjacency list (頂点に隣接する面):
/// the corners at vertex `v` are `corners[start[v]..start[v + 1]]`, each `(face, k)` with
/// `faces[face][k] == v`, in face order.
pub(crate) struct CornersByVertex {
    /// Where each vertex's corners begin; `start[vertex_count]` is the number of corners.
    pub start: Vec<usize>,
    /// `(face, corner)` pairs, grouped by vertex.
    pub corners: Vec<(u32, u8)>,
}

impl CornersByVertex {
    /// The corners of `faces` (face numbers, increasing, each face's indices in range).
    pub(crate) fn new(mesh: &Mesh, faces: impl Iterator<Item = usize> + Clone) -> Self {
        let n = mesh.positions.len();
        let mut start = vec![0usize; n + 1];
        for f in faces.clone() {
            for &v in &mesh.faces[f] {
                start[v as usize + 1] += 1;
            }
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut corners = vec![(0u32, 0u8); start[n]];
        for f in faces {
            for (k, &v) in mesh.faces[f].iter().enumerate() {
                corners[fill[v as usize]] = (f as u32, k as u8);
                fill[v as usize] += 1;
            }
        }
        CornersByVertex { start, corners }
    }

    /// The corners at vertex `v`.
    pub(crate) fn at(&self, v: usize) -> &[(u32, u8)] {
        &self.corners[self.start[v]..self.start[v + 1]]
    }
}

/// `attribute[source[i]]` for every `i`, when the attribute is present with one entry per vertex
/// (`vertex_count`); `None` otherwise.
pub(crate) fn gather<T: Copy>(
    attribute: Option<&[T]>,
    vertex_count: usize,
    source: &[usize],
) -> Option<Vec<T>> {
    let attribute = attribute.filter(|a| a.len() == vertex_count)?;
    Some(source.iter().map(|&v| attribute[v]).collect())
}

/// The boundary edges (unordered) that lie along the edge of a T-junction: both ends are the
/// edge's ends or vertices found on it.
fn explained_boundary_edges(t_junctions: &[(u32, [u32; 2], usize)]) -> HashSet<[u32; 2]> {
    let mut explained = HashSet::new();
    for group in t_junctions.chunk_by(|x, y| sorted_edge(x.1) == sorted_edge(y.1)) {
        let mut on_edge: Vec<u32> = group.iter().map(|t| t.0).collect();
        on_edge.extend(group[0].1);
        for (i, &p) in on_edge.iter().enumerate() {
            for &q in &on_edge[i + 1..] {
                explained.insert(sorted_edge([p, q]));
            }
        }
    }
    explained
}

mod text;
mod weld;

pub use weld::Welded;
use weld::{Grid, SpatialHash};

#[cfg(test)]
mod text_tests;
