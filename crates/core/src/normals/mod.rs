//! Face normals (面の法線), vertex normals (頂点の法線), crease-angle splitting, and the
//! transformation of normals.
//!
//! Face normals are computed in f64 from edge vectors, with an error bound small enough that a
//! zero-area face is recognised exactly (`None`, docs/numerics.md row 1) and every other face gets a
//! normal correct to f32 precision — needle triangles and triangles far from the origin included
//! (rows 6–7). Vertex normals average the face normals of the faces around a vertex (頂点に隣接する
//! 全ての面の法線を平均) with one of four [`Weighting`]s, accumulating in f64; a vertex that cannot
//! get an average gets a documented [`Fallback`], never a NaN (row 2).
//!
//! | what a renderer needs | function |
//! |---|---|
//! | one normal per face | [`face_normal`], [`face_normals`] |
//! | one normal per vertex | [`vertex_normals`] |
//! | the same each frame, for fixed faces and moving positions | [`NormalsPlan`] (area weights) |
//! | vertices split at hard edges (稜線) | [`smooth_normals`] |
//! | every face flat (glNormal per face) | [`face_split`] |
//! | the mesh for a [`NormalSource`] | [`prepare_normals`] |
//! | normals under a model transform | [`normal_matrix`], [`transform_normal`] |
//! | the Phong-shading normal inside a face | [`interpolate_normal`] |

use glam::{DMat3, DVec3, Mat3, Mat4, Vec3};

use crate::lang::{Lang, Text};
use crate::math::{
    cross_f64, cross_kahan_f64, try_normalize, try_normalize_f64, try_unit_and_length_f64,
};
use crate::mesh::{CornersByVertex, Mesh, MeshError, find_root, gather, union};
use crate::scene::NormalSource;

mod fast;
mod plan;

pub use plan::{NormalsPlan, PlanError};

/// Which kernels a fast path may use: all that this CPU has, or fewer, for the tests (which must
/// cover every kernel on any machine) and the benchmarks. Every choice gives the same bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kernels {
    /// The best this CPU has: on x86-64 with AVX2 and FMA, the hand-vectorised kernels.
    Best,
    /// The compiler's code, with FMA where the CPU has it (as on an ARM Mac).
    Compiled,
    /// The code a CPU without FMA runs (plain x86-64).
    NoFma,
}

impl Kernels {
    /// The token of the hand-vectorised kernels (AVX2 and FMA), where they may run.
    #[cfg(target_arch = "x86_64")]
    #[inline]
    fn v3(self) -> Option<pulp::x86::V3> {
        if self == Kernels::Best { pulp::x86::V3::try_new() } else { None }
    }
}

// ---------------------------------------------------------------------------------------------
// Face normals

/// A face is degenerate when `|(b−a)×(c−a)| ≤ DEGENERATE_SINE·|b−a|·|c−a|`, i.e. when the sine of
/// its angle at `a` is at most 2⁻⁷⁰ ≈ 8.5·10⁻²².
///
/// Why this value: [`face_area_vector`] computes the cross product of the *exact* edge vectors
/// with an error of at most `4u·|n| + 21u²·|b−a|·|c−a|` (u = 2⁻⁵³; see [`exact_edge`] and
/// [`cross_kahan_f64`]). A zero-area triangle therefore yields at most `21u² ≈ 2⁻¹⁰¹·|b−a|·|c−a|`,
/// 2³¹ times below the threshold, and a face above the threshold has its normal tilted by at most
/// `4u + 21u²/2⁻⁷⁰ < 3·10⁻¹⁰` rad, far below f32 resolution (6·10⁻⁸). A plain f64 cross product
/// would not do: once the edges have more than 26 significant bits its products round, and a
/// nearly collinear triangle (sine ~1e-15) comes out degrees off (see the test
/// `degeneracy_threshold_is_far_below_any_real_surface`), so no threshold near ε₆₄ is safe for it.
const DEGENERATE_SINE: f64 = 1.0 / (1u128 << 70) as f64;

/// A weighted sum of unit normals "cancels" when its length is at most this fraction of the sum
/// of the lengths of its terms.
///
/// Why this value: every term is correct to a few f64 ulps (≤ 4ε₆₄ of its length), so the sum is
/// off by at most `4ε₆₄·Σ|terms|` = 2⁻⁵⁰·Σ. A sum longer than 2⁻²⁶·Σ therefore has a direction
/// correct to 2⁻²⁴ (one f32 ulp); a shorter one is rounding noise, not a direction.
const CANCEL_FRACTION: f64 = 1.0 / (1u64 << 26) as f64;

/// The edge `to − from` as an unevaluated f64 sum `hi + lo` that is *exact* (Knuth's TwoSum).
///
/// `hi` is the rounded difference; `lo` is zero whenever the difference fits in f64, which is the
/// case unless the two coordinates differ in magnitude by more than 2²⁹ (`|lo| ≤ 2⁻⁵³·|hi|`).
#[inline]
fn exact_edge(from: Vec3, to: Vec3) -> (DVec3, DVec3) {
    let (x, y) = (to.as_dvec3(), -from.as_dvec3());
    let hi = x + y;
    let y_part = hi - x;
    let x_part = hi - y_part;
    let lo = (x - x_part) + (y - y_part);
    (hi, lo)
}

/// Twice the area of triangle `(a, b, c)`, as a vector along its normal: `(b − a) × (c − a)`,
/// computed in f64 and returned in f64 so the caller can weight by it.
///
/// Counter-clockwise seen from the side the vector points to. The edges are taken exactly (as
/// f64 pairs) and the products with Kahan's difference of products, so the result is within
/// `4u·|n| + 21u²·|b−a|·|c−a|` (u = 2⁻⁵³) of the exact cross product of the f32 corners: exactly
/// zero for a repeated corner and for exactly collinear corners whose edges fit in f64 (every
/// triangle whose coordinates agree in magnitude within 2²⁹), and accurate for needle triangles.
///
/// Non-finite corners give a non-finite vector.
///
/// See also [`face_normal`], which also decides whether the face is degenerate.
#[must_use]
#[inline]
pub fn face_area_vector(a: Vec3, b: Vec3, c: Vec3) -> DVec3 {
    let (e1, d1) = exact_edge(a, b);
    let (e2, d2) = exact_edge(a, c);
    // (e1 + d1) × (e2 + d2) = e1×e2 + (e1×d2 + d1×e2) + d1×d2; the last term is ≤ u²·|e1||e2|.
    // The correction is zero unless an edge did not fit in f64.
    let correction = if d1 == DVec3::ZERO && d2 == DVec3::ZERO {
        DVec3::ZERO
    } else {
        e1.cross(d2) + d1.cross(e2)
    };
    cross_kahan_f64(e1, e2) + correction
}

/// Half an ulp of f32, relative: rounding a real number to f32 moves it by at most `u·|x|`.
const F32_UNIT_ROUNDOFF: f64 = 1.0 / (1u32 << 24) as f64;

/// How far rounding the corners to f32 can move the area vector `(b−a)×(c−a)`, component-wise:
/// each coordinate is within `u·|x|` of the value it stands for, so edge component `k` is within
/// `δe_k = u·(|from_k| + |to_k|)`, and the cross product within
/// `|δe₁| ×ₐ |e₂| + |e₁| ×ₐ |δe₂|` where `×ₐ` is the cross product's pattern with every term
/// added in absolute value (the second-order term `δe₁ ×ₐ δe₂` is below `u` of these).
///
/// A face whose area vector is no longer than this bound is collinear *within the precision of
/// its own coordinates* (rounding could turn its normal any way at all) — a sliver whose third corner is the f32-rounded midpoint of an edge,
/// say: its "normal" is rounding noise and may point anywhere, and weighted like a real face it
/// tilts its neighbours' vertex normals by tens of degrees (docs/numerics.md row 1). The bound is
/// per component, so an axis-aligned triangle whose small coordinate is exact — `(0,0,0)`,
/// `(1,0,0)`, `(1,1e-20,0)` — is not affected; a needle of height 1e-6 and base 1 stays
/// above it even rotated and moved by its own size (row 6), and a unit triangle keeps its normal up
/// to 1e6 from the origin (row 7).
fn rounding_noise(a: Vec3, b: Vec3, c: Vec3, e1: DVec3, e2: DVec3) -> f64 {
    rounding_noise_vector(a, b, c, e1, e2).length()
}

/// The vector whose length is [`rounding_noise`].
#[inline]
fn rounding_noise_vector(a: Vec3, b: Vec3, c: Vec3, e1: DVec3, e2: DVec3) -> DVec3 {
    let (a, b, c) = (a.as_dvec3().abs(), b.as_dvec3().abs(), c.as_dvec3().abs());
    let (d1, d2) = ((a + b) * F32_UNIT_ROUNDOFF, (a + c) * F32_UNIT_ROUNDOFF);
    let (e1, e2) = (e1.abs(), e2.abs());
    let abs_cross = |x: DVec3, y: DVec3| {
        DVec3::new(x.y * y.z + x.z * y.y, x.z * y.x + x.x * y.z, x.x * y.y + x.y * y.x)
    };
    abs_cross(d1, e2) + abs_cross(e1, d2)
}

/// The area vector of a usable face: `None` for a degenerate face (see [`face_normal`]).
#[inline]
fn usable_area_vector(a: Vec3, b: Vec3, c: Vec3) -> Option<DVec3> {
    if !(a.is_finite() && b.is_finite() && c.is_finite()) {
        return None;
    }
    let n = face_area_vector(a, b, c);
    let (e1, e2) = (b.as_dvec3() - a.as_dvec3(), c.as_dvec3() - a.as_dvec3());
    let exact_noise = DEGENERATE_SINE * e1.length() * e2.length();
    let noise = exact_noise.max(rounding_noise(a, b, c, e1, e2));
    if n.length() <= noise { None } else { Some(n) }
}

/// The unit normal of triangle `(a, b, c)` (面の法線), counter-clockwise front:
/// `normalise((b−a)×(c−a))`.
///
/// Returns `None` for a degenerate triangle — a repeated corner, coincident or collinear corners,
/// collinear also within the precision of their f32 coordinates (a sliver whose third corner is
/// a rounded edge midpoint) — that is, when `|(b−a)×(c−a)|` is at most
/// `max(2⁻⁷⁰·|b−a|·|c−a|, R)` — the first bound is the f64 computation's own rounding, `R` the
/// most that rounding the corners to f32 can move the vector, component by component — and for
/// non-finite corners. Needle triangles (height 1e-6, base 1) are *not* degenerate and get a
/// normal correct to f32 rounding.
///
/// Edge vectors are taken exactly in f64 from the first corner, so a unit triangle translated to
/// 1e6 keeps its normal to within what its f32 positions still say (never from the position form
/// `a×b + b×c + c×a`, which cancels catastrophically far from the origin).
///
/// See also [`face_area_vector`] for the unnormalised, area-weighted vector, [`face_normals`] for
/// a whole mesh.
#[must_use]
pub fn face_normal(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    face_normal_f64(a, b, c).map(|n| n.as_vec3())
}

/// [`face_normal`] in f64, for oracles and for weighting without a second rounding.
#[must_use]
pub fn face_normal_f64(a: Vec3, b: Vec3, c: Vec3) -> Option<DVec3> {
    usable_area_vector(a, b, c).and_then(try_normalize_f64)
}

/// The face normal of every face of `mesh`, in face order (F0, F1, …).
///
/// `None` for a degenerate face (see [`face_normal`]) and for a face that refers to a vertex
/// that does not exist; never panics.
#[must_use]
pub fn face_normals(mesh: &Mesh) -> Vec<Option<Vec3>> {
    (0..mesh.faces.len()).map(|f| face_geometry(mesh, f).map(|g| g.unit.as_vec3())).collect()
}

/// The corners of face `f` if every index is in range.
#[inline]
fn corners(mesh: &Mesh, f: usize) -> Option<[Vec3; 3]> {
    let [a, b, c] = mesh.faces[f];
    Some([
        *mesh.positions.get(a as usize)?,
        *mesh.positions.get(b as usize)?,
        *mesh.positions.get(c as usize)?,
    ])
}

/// What the weighting schemes need to know about one usable face.
#[derive(Clone, Copy, Debug)]
struct FaceGeometry {
    /// Corners in f64.
    p: [DVec3; 3],
    /// `(b−a)×(c−a)`, never normalised before weighting.
    area_vector: DVec3,
    /// `area_vector / |area_vector|`.
    unit: DVec3,
}

impl FaceGeometry {
    /// The weighted contribution of this face to the normal of its corner `k` (0, 1 or 2).
    fn contribution(&self, k: usize, weighting: Weighting) -> DVec3 {
        // Edges from corner k to the next two corners, in winding order: e1 × e2 = area_vector.
        let e1 = self.p[(k + 1) % 3] - self.p[k];
        let e2 = self.p[(k + 2) % 3] - self.p[k];
        match weighting {
            Weighting::Uniform => self.unit,
            Weighting::Area => self.area_vector,
            // The corner angle as atan2(|e1×e2|, e1·e2): accurate at every angle, unlike acos.
            Weighting::Angle => self.unit * self.area_vector.length().atan2(e1.dot(e2)),
            Weighting::Max => self.area_vector / (e1.length_squared() * e2.length_squared()),
        }
    }
}

/// The geometry of face `f`, or `None` when it is degenerate or refers to a missing vertex.
fn face_geometry(mesh: &Mesh, f: usize) -> Option<FaceGeometry> {
    corner_geometry(corners(mesh, f)?)
}

/// The geometry of the face with corners `[a, b, c]`, or `None` when it is degenerate.
#[inline]
fn corner_geometry([a, b, c]: [Vec3; 3]) -> Option<FaceGeometry> {
    let area_vector = usable_area_vector(a, b, c)?;
    let unit = try_normalize_f64(area_vector)?;
    Some(FaceGeometry { p: [a, b, c].map(Vec3::as_dvec3), area_vector, unit })
}

// ---------------------------------------------------------------------------------------------
// Vertex normals

/// How face normals are weighted when averaged into a vertex normal (頂点の法線 = 隣接する面の法線の平均).
///
/// Every scheme is a positive combination of the unit normals of the adjacent faces, so the
/// vertex normal always lies within the cone those face normals span. Degenerate faces contribute
/// nothing under every scheme.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Weighting {
    /// Every adjacent face counts the same (the lecture's plain average): the unit face normals
    /// are summed. Depends on how the surface happens to be triangulated.
    Uniform,
    /// Faces weighted by their area (面積に応じた加重平均): the unnormalised cross products are
    /// summed. The cheapest; depends on the triangulation too.
    Area,
    /// Faces weighted by the corner angle at the vertex (Thürmer & Wüthrich 1998): independent of
    /// how a flat region is triangulated; the most robust on irregular meshes.
    #[default]
    Angle,
    /// Nelson Max (1999): each face adds `(e₁ × e₂) / (|e₁|²·|e₂|²)` = `n·sin α / (|e₁|·|e₂|)`,
    /// with `e₁`, `e₂` the edges leaving the vertex. Exact when the vertex and its neighbours lie
    /// on a sphere.
    Max,
}

/// Why a vertex did not get an averaged normal, and what it got instead.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Fallback {
    /// No face uses the vertex (孤立した頂点). Its normal is the zero vector.
    Isolated,
    /// Every face that uses the vertex is degenerate (zero area, a non-finite corner, or a corner
    /// index out of range). Its normal is the zero vector; those faces cover no pixel.
    Degenerate,
    /// The weighted face normals cancel (back-to-back faces, 裏表に重なった面): their sum is
    /// shorter than 2⁻²⁶ of the sum of their lengths, so it has no direction. The normal is the
    /// unit normal of `face`, the adjacent usable face with the largest area (the lowest face
    /// number among equal areas).
    Cancelled {
        /// The face (F-number) whose normal was used.
        face: u32,
    },
}

/// The result of [`vertex_normals`]: one normal per vertex, and the vertices that fell back.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VertexNormals {
    /// One normal per vertex (V0, V1, …): unit length, or the zero vector where [`Fallback`] says
    /// no usable face touches the vertex. Never NaN.
    pub normals: Vec<Vec3>,
    /// The vertices (V-numbers, increasing) whose normal is not a weighted average, and why.
    pub fallbacks: Vec<(u32, Fallback)>,
}

/// The weighted sum of face normals at one vertex (or one smooth group of corners), in f64.
#[derive(Clone, Copy, Debug, Default)]
struct Accumulator {
    sum: DVec3,
    /// Σ |contribution|, the scale against which cancellation is judged.
    magnitude: f64,
    /// Whether any face (usable or not) uses the vertex.
    touched: bool,
    /// The largest usable face so far: (|area vector|, face, unit normal).
    largest: Option<(f64, u32, DVec3)>,
}

impl Accumulator {
    fn add(&mut self, face: u32, g: &FaceGeometry, corner: usize, weighting: Weighting) {
        let c = g.contribution(corner, weighting);
        self.sum += c;
        self.magnitude += c.length();
        self.touched = true;
        let area = g.area_vector.length();
        if self.largest.is_none_or(|(largest, _, _)| area > largest) {
            self.largest = Some((area, face, g.unit));
        }
    }

    /// The vertex normal, or the fallback and its value.
    fn resolve(&self) -> (Vec3, Option<Fallback>) {
        let Some((_, face, unit)) = self.largest else {
            let why = if self.touched { Fallback::Degenerate } else { Fallback::Isolated };
            return (Vec3::ZERO, Some(why));
        };
        if self.sum.length() > CANCEL_FRACTION * self.magnitude
            && let Some(n) = try_normalize_f64(self.sum)
        {
            return (n.as_vec3(), None);
        }
        (unit.as_vec3(), Some(Fallback::Cancelled { face }))
    }
}

/// Vertex normals (頂点の法線): at every vertex, the weighted average of the normals of the faces
/// that use it (頂点に隣接する全ての面の法線を平均), normalised.
///
/// Weights are applied to the *unnormalised* cross product (area, Max) or to the exact unit
/// normal (uniform, angle) and summed in f64. Degenerate faces (see [`face_normal`]) and faces
/// that refer to a missing vertex contribute nothing, so they never disturb their neighbours.
///
/// A vertex with no usable face gets the zero vector, and a vertex whose weighted normals cancel
/// (back-to-back faces) gets the normal of its largest adjacent face; both are listed in
/// [`VertexNormals::fallbacks`] with the reason ([`Fallback`]). Never NaN, never panics.
///
/// Speed: [`Weighting::Area`] on a mesh whose indices are all in range takes a fast path
/// (parallel over faces on all cores, one flat f64 array, no per-face allocation) that gives
/// bit for bit the result of [`vertex_normals_reference`], the plain loop that every weighting
/// uses otherwise (docs/performance.md has the figures). For a mesh whose positions move every
/// frame while its faces stay, a [`NormalsPlan`] made once gives the same bits faster.
///
/// See also [`smooth_normals`] (the same with hard edges kept), [`Weighting`].
#[must_use]
pub fn vertex_normals(mesh: &Mesh, weighting: Weighting) -> VertexNormals {
    if weighting == Weighting::Area
        && let Some(fast) = fast::area_vertex_normals(mesh, Kernels::Best)
    {
        return fast;
    }
    vertex_normals_reference(mesh, weighting)
}

/// The fast path of [`vertex_normals`] with [`Weighting::Area`] as it runs on a CPU without FMA
/// (plain x86-64), whatever this CPU has: for the tests, which must cover both kernels on any
/// machine, and for the benchmark. `None` where `vertex_normals` would take the plain loop (an
/// index out of range).
#[doc(hidden)]
#[must_use]
pub fn area_vertex_normals_without_fma(mesh: &Mesh) -> Option<VertexNormals> {
    fast::area_vertex_normals(mesh, Kernels::NoFma)
}

/// The fast path of [`vertex_normals`] with [`Weighting::Area`] without the hand-vectorised
/// kernels, as it runs on a CPU with FMA but without AVX2 (an ARM Mac, say), whatever this CPU
/// has: for the tests. `None` as for [`area_vertex_normals_without_fma`].
#[doc(hidden)]
#[must_use]
pub fn area_vertex_normals_without_simd(mesh: &Mesh) -> Option<VertexNormals> {
    fast::area_vertex_normals(mesh, Kernels::Compiled)
}

/// [`vertex_normals`] as one plain sequential loop over the faces, for every weighting: the
/// definition the fast path of [`vertex_normals`] is tested against (bit for bit), and the
/// baseline of its benchmark.
#[must_use]
pub fn vertex_normals_reference(mesh: &Mesh, weighting: Weighting) -> VertexNormals {
    let mut acc = vec![Accumulator::default(); mesh.positions.len()];
    for (f, face) in mesh.faces.iter().enumerate() {
        let geometry = face_geometry(mesh, f);
        for (k, &v) in face.iter().enumerate() {
            let Some(a) = acc.get_mut(v as usize) else { continue };
            a.touched = true;
            if let Some(g) = &geometry {
                a.add(f as u32, g, k, weighting);
            }
        }
    }
    let mut normals = Vec::with_capacity(acc.len());
    let mut fallbacks = Vec::new();
    for (v, a) in acc.iter().enumerate() {
        let (n, fallback) = a.resolve();
        normals.push(n);
        if let Some(why) = fallback {
            fallbacks.push((v as u32, why));
        }
    }
    VertexNormals { normals, fallbacks }
}

// ---------------------------------------------------------------------------------------------
// Meshes ready to draw

/// The mesh with its vertices split at hard edges (稜線), carrying vertex normals: where the
/// dihedral angle between two faces that share an edge exceeds `crease_deg`, the two faces get
/// separate copies of the edge's vertices, so hard edges keep their face normals and smooth
/// regions share averaged normals (面の法線と頂点の法線の使い分け). A scene's `normals = "smooth"` uses 30°.
///
/// Around each vertex, the faces are grouped: two faces sharing an edge at the vertex are in the
/// same group when the angle between their normals is at most `crease_deg`; each group becomes one
/// vertex with the [`vertex_normals`]-style weighted average of its faces. `None` splits nothing
/// (the result's normals are exactly [`vertex_normals`]); with `Some(_)` faces that meet at a
/// vertex without sharing an edge there (a "bow-tie") are split too, whatever the angle.
///
/// Layout of the result: vertex `i` is still the first group of input vertex `i` (so an unsplit
/// mesh keeps its numbering); extra copies follow, in vertex order. Faces keep their order.
/// Positions are copied exactly, and uvs and colours go with every copy. Normals are unit
/// length, except the zero vector at a vertex that no usable face touches (an isolated vertex,
/// or one used only by degenerate faces, which cover no pixel); a group whose normals cancel gets
/// the normal of its largest face, as in [`vertex_normals`].
///
/// Degenerate faces join the group of the first usable face at each corner. A negative or NaN
/// `crease_deg` joins no two faces (every edge hard, vertices shared only by a face with itself).
/// Faces that refer to a missing vertex are left out (the faces after one then move down a
/// number) and attributes whose length is not the
/// vertex count are dropped (call [`Mesh::check_indices`] first; [`prepare_normals`] does).
///
/// See also [`face_split`] (every edge hard), [`prepare_normals`].
#[must_use]
pub fn smooth_normals(mesh: &Mesh, weighting: Weighting, crease_deg: Option<f32>) -> Mesh {
    let n = mesh.positions.len();
    let in_range = |f: &[u32; 3]| f.iter().all(|&i| (i as usize) < n);
    let geometry: Vec<Option<FaceGeometry>> =
        (0..mesh.faces.len()).map(|f| face_geometry(mesh, f)).collect();

    // The corners at every vertex, in face order.
    let usable = (0..mesh.faces.len()).filter(|&f| in_range(&mesh.faces[f]));
    let CornersByVertex { start, corners: at_vertex } = CornersByVertex::new(mesh, usable);

    // Group the corners of each vertex; `group_of[c]` is the group of corner c within its vertex.
    let crease_rad = crease_deg.map(|d| f64::from(d).to_radians());
    let mut group_of = vec![0u32; at_vertex.len()];
    let mut groups_at = vec![0u32; n];
    for v in 0..n {
        let corners = &at_vertex[start[v]..start[v + 1]];
        let groups = group_corners(mesh, v as u32, corners, &geometry, crease_rad);
        groups_at[v] = groups.iter().max().map_or(0, |g| g + 1);
        group_of[start[v]..start[v + 1]].copy_from_slice(&groups);
    }

    // Output vertex of (v, group): group 0 keeps v; extra groups are numbered after all inputs.
    let mut first_extra = vec![0u32; n];
    let mut next = n as u32;
    for v in 0..n {
        first_extra[v] = next;
        next += groups_at[v].saturating_sub(1);
    }
    let out_index = |v: usize, g: u32| if g == 0 { v as u32 } else { first_extra[v] + g - 1 };
    let total = next as usize;
    let mut source = vec![0usize; total];
    let mut acc = vec![Accumulator::default(); total];
    for v in 0..n {
        source[v] = v;
        for g in 1..groups_at[v] {
            source[out_index(v, g) as usize] = v;
        }
        for (c, &(f, k)) in at_vertex[start[v]..start[v + 1]].iter().enumerate() {
            let a = &mut acc[out_index(v, group_of[start[v] + c]) as usize];
            a.touched = true;
            if let Some(geom) = &geometry[f as usize] {
                a.add(f, geom, k as usize, weighting);
            }
        }
    }
    let mut faces = Vec::with_capacity(mesh.faces.len());
    let mut fill = start;
    for face in mesh.faces.iter().filter(|f| in_range(f)) {
        faces.push(face.map(|v| {
            let c = fill[v as usize];
            fill[v as usize] += 1;
            out_index(v as usize, group_of[c])
        }));
    }

    Mesh {
        positions: source.iter().map(|&v| mesh.positions[v]).collect(),
        faces,
        normals: Some(acc.iter().map(|a| a.resolve().0).collect()),
        uvs: gather(mesh.uvs.as_deref(), n, &source),
        colors: gather(mesh.colors.as_deref(), n, &source),
    }
}

/// Groups the corners at vertex `v`, given as (face, corner) in face order. With no crease
/// angle, all corners form one group. Otherwise two usable corners join when their faces share an
/// edge at `v` and the angle between their normals is at most `crease_rad`; unusable corners
/// (degenerate faces) join the group of the first usable corner. Returns the group of every
/// corner, numbered from 0 in order of first appearance, the first usable corner's group first.
fn group_corners(
    mesh: &Mesh,
    v: u32,
    corners: &[(u32, u8)],
    geometry: &[Option<FaceGeometry>],
    crease_rad: Option<f64>,
) -> Vec<u32> {
    let Some(limit) = crease_rad else {
        return vec![0; corners.len()];
    };
    let geometry_of = |c: usize| geometry[corners[c].0 as usize].as_ref();
    let mut parent: Vec<usize> = (0..corners.len()).collect();
    // (other end of an edge at v, corner), sorted: corners listing the same end share that edge.
    let mut ends: Vec<(u32, usize)> = Vec::with_capacity(2 * corners.len());
    for (c, &(f, _)) in corners.iter().enumerate() {
        if geometry_of(c).is_some() {
            ends.extend(mesh.faces[f as usize].iter().filter(|&&w| w != v).map(|&w| (w, c)));
        }
    }
    ends.sort_unstable();
    for run in ends.chunk_by(|a, b| a.0 == b.0) {
        for (i, &(_, c)) in run.iter().enumerate() {
            for &(_, d) in &run[i + 1..] {
                let (Some(a), Some(b)) = (geometry_of(c), geometry_of(d)) else { continue };
                // The dihedral angle as the angle between the normals, in the atan2 form.
                if a.unit.cross(b.unit).length().atan2(a.unit.dot(b.unit)) <= limit {
                    union(&mut parent, c, d);
                }
            }
        }
    }
    let first_usable = (0..corners.len()).find(|&c| geometry_of(c).is_some());
    if let Some(anchor) = first_usable {
        for c in (0..corners.len()).filter(|&c| geometry_of(c).is_none()) {
            parent[c] = anchor;
        }
    }
    let anchor = first_usable.unwrap_or(0);
    let mut number = vec![u32::MAX; corners.len()];
    let mut next = 0;
    let mut out = vec![0u32; corners.len()];
    for c in std::iter::once(anchor).chain(0..corners.len()).filter(|&c| c < corners.len()) {
        let r = find_root(&mut parent, c);
        if number[r] == u32::MAX {
            number[r] = next;
            next += 1;
        }
        out[c] = number[r];
    }
    out
}

/// The mesh with every face on its own three vertices, each carrying the face normal (面の法線:
/// flat faces, as `glNormal` once per face in the course's sample program).
///
/// Face `i` of the result is face `i` of `mesh`, on vertices `3i, 3i+1, 3i+2` (so F-numbers
/// stay, as long as every face's indices are in range). Positions are copied exactly, and uvs and colours go with each corner. A degenerate
/// face is kept, with the zero vector as its normal at all three corners: it covers no pixel,
/// and the zero normal marks it (see [`face_normals`] for which ones).
///
/// Faces that refer to a missing vertex are left out (the faces after one then move down a
/// number) and attributes whose length is not the
/// vertex count are dropped (call [`Mesh::check_indices`] first; [`prepare_normals`] does).
///
/// See also [`smooth_normals`], [`prepare_normals`].
#[must_use]
pub fn face_split(mesh: &Mesh) -> Mesh {
    let n = mesh.positions.len();
    let kept: Vec<usize> = (0..mesh.faces.len()).filter(|&f| corners(mesh, f).is_some()).collect();
    let corner_ids: Vec<usize> =
        kept.iter().flat_map(|&f| mesh.faces[f].map(|v| v as usize)).collect();
    let normals = kept
        .iter()
        .flat_map(|&f| {
            let [a, b, c] = mesh.triangle(f);
            [face_normal(a, b, c).unwrap_or(Vec3::ZERO); 3]
        })
        .collect();
    Mesh {
        positions: corner_ids.iter().map(|&v| mesh.positions[v]).collect(),
        faces: (0..kept.len() as u32).map(|i| [3 * i, 3 * i + 1, 3 * i + 2]).collect(),
        normals: Some(normals),
        uvs: gather(mesh.uvs.as_deref(), n, &corner_ids),
        colors: gather(mesh.colors.as_deref(), n, &corner_ids),
    }
}

/// Why [`prepare_normals`] could not give a mesh its shading normals.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum NormalsError {
    /// The mesh itself is unusable (an index out of range, a wrong attribute length, a
    /// non-finite position).
    #[error("the mesh cannot be used: {0}")]
    Mesh(#[from] MeshError),
    /// `NormalSource::Given`, but the mesh has no normals.
    #[error(
        "the normals are to be given by the mesh, but it has none: give one normal per vertex, or use face or vertex normals"
    )]
    Missing,
    /// A given normal is zero, infinite or NaN, so it has no direction.
    #[error(
        "vertex V{vertex} has the normal {normal}, which has no direction (zero, infinite or NaN)"
    )]
    Unusable {
        /// The vertex (V-number).
        vertex: usize,
        /// The normal found there.
        normal: Vec3,
    },
}

impl NormalsError {
    /// The message for a student in `lang` (the `Display` text is the English one).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let ja = match self {
            NormalsError::Mesh(e) => format!("メッシュが使えません: {}", e.text().ja),
            NormalsError::Missing => "法線はメッシュに与えられているはずですが、ありません。頂点ごとに1つずつ法線を与えるか、面の法線か頂点の法線を使ってください".to_owned(),
            NormalsError::Unusable { vertex, normal } => format!(
                "頂点 V{vertex} の法線 {normal} は向きを持ちません (ゼロ・無限大・NaN のいずれか)"
            ),
        };
        Text::new(ja, self.to_string())
    }
}

/// The mesh a renderer draws for `source`, with one unit normal per vertex:
///
/// | `source` | result |
/// |---|---|
/// | `Face` | [`face_split`]: every face flat (its degenerate faces carry a zero normal) |
/// | `Vertex { weighting, crease_deg }` | [`smooth_normals`]`(mesh, weighting, crease_deg)` |
/// | `Given` | the mesh as it is, its own normals normalised |
///
/// # Errors
/// [`NormalsError::Mesh`] when [`Mesh::check_indices`] fails; for `Given`,
/// [`NormalsError::Missing`] when the mesh has no normals and [`NormalsError::Unusable`] naming
/// the first vertex whose normal is zero, infinite or NaN.
pub fn prepare_normals(mesh: &Mesh, source: NormalSource) -> Result<Mesh, NormalsError> {
    mesh.check_indices()?;
    match source {
        NormalSource::Face => Ok(face_split(mesh)),
        NormalSource::Vertex { weighting, crease_deg } => {
            Ok(smooth_normals(mesh, weighting, crease_deg))
        }
        NormalSource::Given => {
            let given = mesh.normals.as_ref().ok_or(NormalsError::Missing)?;
            let normals = given
                .iter()
                .enumerate()
                .map(|(vertex, &normal)| {
                    try_normalize(normal).ok_or(NormalsError::Unusable { vertex, normal })
                })
                .collect::<Result<Vec<_>, _>>()?;
            Ok(Mesh { normals: Some(normals), ..mesh.clone() })
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Normals under transforms, and inside a face

/// The normal matrix of `m`: the cofactor matrix of its upper 3×3 part `A`,
/// `cof(A) = det(A)·A⁻ᵀ`, whose columns are `a₁×a₂`, `a₂×a₀`, `a₀×a₁` for the columns `aᵢ` of `A`.
///
/// It maps the normal of any triangle to the (unnormalised) normal of the transformed triangle:
/// `cof(A)·(e₁×e₂) = (A·e₁)×(A·e₂)`. Unlike the inverse-transpose it is defined for singular
/// matrices and keeps that identity under a mirror (det < 0). Translation and the projective row
/// are ignored (model and view matrices are affine). Each entry is computed in f64 and rounded
/// once. Non-finite entries of `m` give non-finite entries.
///
/// See also [`transform_normal`], which also normalises.
#[must_use]
pub fn normal_matrix(m: Mat4) -> Mat3 {
    let a = Mat3::from_mat4(m);
    Mat3::from_cols(
        cross_f64(a.y_axis, a.z_axis),
        cross_f64(a.z_axis, a.x_axis),
        cross_f64(a.x_axis, a.y_axis),
    )
}

/// The unit normal, after transforming a surface by `m`, of a surface whose normal was `n`:
/// `normalise(cof(A)·n)` with `A` the upper 3×3 part of `m` (see [`normal_matrix`]), so that
/// for a triangle with edges `e₁`, `e₂` and normal `n ∥ e₁×e₂` the result is
/// `normalise((A·e₁)×(A·e₂))`, the normal of the transformed triangle with its corners in the
/// same order.
///
/// Correct under non-uniform scale and under a mirror (det < 0), where the inverse-transpose
/// flips the sign: a mirrored triangle turns clockwise, and this is the normal of its
/// counter-clockwise side (for a closed mesh whose faces faced outwards, it now points inwards,
/// consistent with the mirrored winding; a renderer that flips its front-face winding for
/// det < 0 should negate it).
///
/// Returns `None` when the transformed normal vanishes — a singular `m` that squashes the
/// surface to a line or a point (`scale(1, 1, 0)` and `n = x`) — or is shorter than 2²⁴ times its
/// f64 rounding error (its direction would not be known to f32 precision), and for a zero or
/// non-finite `n` or `m`. Computed in f64.
#[must_use]
pub fn transform_normal(m: Mat4, n: Vec3) -> Option<Vec3> {
    let a = Mat3::from_mat4(m).as_dmat3();
    // Each cofactor is a difference of two exact products (f32·f32 fits in f64): one rounding.
    let cof = DMat3::from_cols(
        a.y_axis.cross(a.z_axis),
        a.z_axis.cross(a.x_axis),
        a.x_axis.cross(a.y_axis),
    );
    let n = n.as_dvec3();
    let r = cof * n;
    // |r_i − exact| ≤ 3u·Σ_j |cof_ij|·|n_j| (one rounding per entry, two in the sum).
    let abs = DMat3::from_cols(cof.x_axis.abs(), cof.y_axis.abs(), cof.z_axis.abs());
    let error = 3.0 * (f64::EPSILON / 2.0) * (abs * n.abs()).length();
    // (Written so that a NaN length also returns None.)
    let trusted = r.length() > f64::from(1u32 << 24) * error;
    if trusted { try_normalize_f64(r).map(DVec3::as_vec3) } else { None }
}

/// The Phong-shading normal at a point of a face (フォンシェーディング): the vertex normals
/// interpolated with the barycentric weights and renormalised, `N' = N/|N|` with
/// `N = Σ wᵢ·Nᵢ` (computed in f64).
///
/// Falls back to `face_normal` (returned as given; pass the face's unit normal) when `N`
/// vanishes — the vertex normals nearly cancel at this point (nearly opposite normals, NUMERICS
/// row 18), i.e. `|N|` is at most 2⁻²⁶ of `Σ |wᵢ|·|Nᵢ|` — and when an input is not finite.
///
/// See also [`vertex_normals`], [`face_normal`].
#[must_use]
pub fn interpolate_normal(normals: [Vec3; 3], barycentric: Vec3, face_normal: Vec3) -> Vec3 {
    let w = barycentric.as_dvec3();
    let [n0, n1, n2] = normals.map(Vec3::as_dvec3);
    let sum = n0 * w.x + n1 * w.y + n2 * w.z;
    let magnitude = w.x.abs() * n0.length() + w.y.abs() * n1.length() + w.z.abs() * n2.length();
    if let Some((n, length)) = try_unit_and_length_f64(sum)
        && length > CANCEL_FRACTION * magnitude
    {
        return n.as_vec3();
    }
    face_normal
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_edge_is_exact() {
        // 1 − 1e-12 (with 1e-12 rounded to f32) needs 64 bits: hi + lo must still be exact.
        let (from, to) = (Vec3::splat(1e-12), Vec3::ONE);
        let (hi, lo) = exact_edge(from, to);
        assert_ne!(lo, DVec3::ZERO, "premise: the difference does not fit in f64");
        // lo = (to − from) − hi = (1 − hi) − x, and both steps are exact here (Sterbenz, and a
        // difference of two values on a 2⁻⁶³ grid below 2⁻⁵²).
        let x = f64::from(1e-12f32);
        assert_eq!((1.0 - hi.x) - x, lo.x);
        let (hi, lo) = exact_edge(Vec3::ONE, Vec3::new(2.0, 3.0, 4.0));
        assert_eq!((hi, lo), (DVec3::new(1.0, 2.0, 3.0), DVec3::ZERO));
    }
}
