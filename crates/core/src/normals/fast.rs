//! The fast path of area-weighted vertex normals: bit for bit
//! [`vertex_normals_reference`](super::vertex_normals_reference), several times faster.
//!
//! The reference adds every usable face's area vector `(b−a)×(c−a)` (computed exactly as
//! [`face_area_vector`](super::face_area_vector) does) and its length to each corner's vertex,
//! face after face. The sums depend on that order, so this path keeps it — per vertex — while it
//! works on all cores:
//!
//! 1. The faces go in blocks of [`BLOCK`]. For a block, every face's record `[x, y, z, |n|]`
//!    (zeros for an unusable face) is computed in parallel, [`LANES`] faces at a time in
//!    structure-of-arrays form so the compiler vectorises the arithmetic; on a CPU with FMA
//!    (nearly every x86-64 since 2013, every 64-bit ARM) the exact cross product is Kahan's
//!    difference of products with hardware fused multiply-adds, in a copy of the code compiled
//!    for AVX2 + FMA and selected at run time by the `multiversion` crate. A face this shortcut
//!    cannot vouch for goes the reference's way.
//! 2. One thread adds block k's records to the vertices' sums, in face order — so every sum is
//!    formed in the reference's order — while the other threads compute block k + 1's records
//!    into a second buffer (and the adding thread joins them when it is done). The records stay
//!    in the cache between the two steps.
//! 3. Every vertex is normalised in parallel, vectorised as step 1; the rare vertex with no
//!    usable face or with cancelling normals is settled afterwards as the reference does.
//!
//! docs/performance.md has the figures, and why this order of work (a vertex range per thread
//! for the additions was tried: every thread then reads every face, and the additions did not
//! get faster).

use glam::{DVec3, Vec3};
use multiversion::multiversion;
use rayon::prelude::*;

use super::{
    CANCEL_FRACTION, DEGENERATE_SINE, F32_UNIT_ROUNDOFF, Fallback, Kernels, VertexNormals,
    corner_geometry, face_geometry,
};
use crate::math::{difference_of_products_f64, try_normalize_f64};
use crate::mesh::Mesh;

/// Faces per block: their records (32 B each, 2 MiB) stay in the cache from the moment they are
/// computed until they are added to the vertices (16 384 to 131 072 measured alike).
const BLOCK: usize = 1 << 16;
/// Faces per task of a block's record step.
const TASK: usize = 2048;
/// Below this many faces one thread does everything: handing work to other threads would cost
/// more than it saves.
const PARALLEL_FACES: usize = 1 << 14;
/// Vertices per task of the last step.
const VERTEX_TASK: usize = 8192;
/// Faces (vertices) computed together by the vectorised kernels: enough for the compiler's loop
/// vectoriser, small enough for the stack.
const LANES: usize = 64;

/// How far on either side of a unit vector's component the f32 rounding is tried
/// ([`quick_unit_f32`]): more than the distance between `v · (1/|v|)` and the reference's
/// `(v/m)/|v/m|`.
const UNIT_SLACK: f64 = 1.0 / (1u64 << 46) as f64;

/// One face's contribution: its area vector and the vector's length, `[x, y, z, |n|]`.
pub(super) type Record = [f64; 4];

/// [`vertex_normals`](super::vertex_normals) with [`Weighting::Area`](super::Weighting::Area) on
/// a mesh whose indices are all in range (`None` otherwise): bit for bit the reference.
///
/// The sums start at +0.0, as the reference's do; an unusable face adds +0.0, which changes no
/// bit (a sum that starts at +0.0 is never −0.0). A vertex whose length sum stays zero is either
/// isolated or used only by unusable faces; which one is settled in one more pass over the faces,
/// only when such a vertex exists.
///
/// `kernels` may hold back what this CPU has (for tests and benchmarks).
pub(super) fn area_vertex_normals(mesh: &Mesh, kernels: Kernels) -> Option<VertexNormals> {
    let n = mesh.positions.len();
    let faces = &mesh.faces;
    let parallel = faces.len() >= PARALLEL_FACES && rayon::current_num_threads() > 1;

    // Zeroed in parallel (the sums of the reference start at +0.0).
    let mut sums: Vec<Record> = Vec::with_capacity(n);
    if parallel {
        sums.par_extend(rayon::iter::repeat_n([0.0; 4], n));
    } else {
        sums.resize(n, [0.0; 4]);
    }
    // Two buffers of records: while one thread adds block k to the sums (in face order, as the
    // reference does), the others compute the records of block k + 1 in the other buffer.
    let block_of = |b: usize| &faces[b * BLOCK..((b + 1) * BLOCK).min(faces.len())];
    let records = |b: usize, out: &mut [Record]| -> bool {
        let block = block_of(b);
        let out = &mut out[..block.len()];
        if parallel {
            out.par_chunks_mut(TASK)
                .zip(block.par_chunks(TASK))
                .all(|(out, faces)| block_records(&mesh.positions, faces, out, kernels))
        } else {
            block_records(&mesh.positions, block, out, kernels)
        }
    };
    let blocks = faces.len().div_ceil(BLOCK);
    let size = BLOCK.min(faces.len());
    let (mut current, mut next) = (vec![[0.0; 4]; size], vec![[0.0; 4]; size]);
    if blocks > 0 && !records(0, &mut current) {
        return None;
    }
    for b in 0..blocks {
        let block = block_of(b);
        let add = |sums: &mut [Record]| scatter(block, &current, sums);
        let in_range = if b + 1 < blocks {
            if parallel {
                rayon::join(|| add(&mut sums), || records(b + 1, &mut next)).1
            } else {
                add(&mut sums);
                records(b + 1, &mut next)
            }
        } else {
            add(&mut sums);
            true
        };
        if !in_range {
            return None;
        }
        std::mem::swap(&mut current, &mut next);
    }
    drop((current, next));

    // Every normal, or NaN where the vertex needs a second look; then those vertices.
    let mut normals: Vec<Vec3> = Vec::with_capacity(n);
    let unresolved = if parallel {
        normals.par_extend(rayon::iter::repeat_n(Vec3::ZERO, n));
        normals
            .par_chunks_mut(VERTEX_TASK)
            .zip(sums.par_chunks(VERTEX_TASK))
            .map(|(out, sums)| units(sums, out, kernels))
            .sum()
    } else {
        normals.resize(n, Vec3::ZERO);
        units(&sums, &mut normals, kernels)
    };
    let mut fallbacks: Vec<(u32, Fallback)> = if unresolved == 0 {
        Vec::new()
    } else {
        (0..n)
            .filter(|&v| normals[v].x.is_nan())
            .map(|v| (v as u32, provisional(&sums[v])))
            .collect()
    };
    for &(v, _) in &fallbacks {
        normals[v as usize] = Vec3::ZERO;
    }
    if !fallbacks.is_empty() {
        settle(mesh, &mut normals, &mut fallbacks);
    }
    Some(VertexNormals { normals, fallbacks })
}

/// Adds the records of `faces` to the sums of their corners' vertices, in face order (one 4-wide
/// addition per corner in the AVX copy). The indices were checked by [`block_records`].
#[multiversion(targets("x86_64+avx2+fma"))]
fn scatter(faces: &[[u32; 3]], records: &[Record], sums: &mut [Record]) {
    for (face, r) in faces.iter().zip(records) {
        for &v in face {
            if let Some(s) = sums.get_mut(v as usize) {
                *s = [s[0] + r[0], s[1] + r[1], s[2] + r[2], s[3] + r[3]];
            }
        }
    }
}

/// The unit normal of a vertex from its sums, as the reference's accumulator gives it, or NaN
/// when the vertex falls back (no usable face, or cancelling normals: see [`provisional`]).
#[inline]
pub(super) fn unit_or_nan(s: &Record) -> Vec3 {
    let (sum, magnitude) = (DVec3::new(s[0], s[1], s[2]), s[3]);
    if magnitude > 0.0
        && let length = sum.length()
        && length > CANCEL_FRACTION * magnitude
        && let Some(unit) =
            quick_unit_f32(sum, length).or_else(|| try_normalize_f64(sum).map(DVec3::as_vec3))
    {
        unit
    } else {
        Vec3::NAN
    }
}

/// [`unit_or_nan`] of every vertex: [`LANES`] at a time in structure-of-arrays form (vectorised; a
/// copy for AVX2 + FMA chosen at run time), each vertex for which the shortcut of
/// [`quick_unit_f32`] does not vouch going through [`unit_or_nan`] itself. Returns how many
/// vertices got NaN (they fall back).
#[multiversion(targets("x86_64+avx2+fma"))]
pub(super) fn units(
    sums: &[Record],
    out: &mut [Vec3],
    #[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))] kernels: Kernels,
) -> usize {
    #[cfg(target_arch = "x86_64")]
    if let Some(simd) = kernels.v3() {
        return simd.vectorize(|| units_v3(simd, sums, out));
    }
    let mut unresolved = 0;
    let (groups, rest) = sums.as_chunks::<LANES>();
    let (out_groups, out_rest) = out.split_at_mut(groups.len() * LANES);
    for (s, out) in groups.iter().zip(out_groups.chunks_exact_mut(LANES)) {
        let component = |j: usize| -> [f64; LANES] { std::array::from_fn(|i| s[i][j]) };
        let (x, y, z, m) = (component(0), component(1), component(2), component(3));
        let mut u = [[0.0f32; LANES]; 3];
        let mut ok = [false; LANES];
        for i in 0..LANES {
            // `DVec3::length` and `quick_unit_f32`, operation for operation, without branches.
            let length = (x[i] * x[i] + y[i] * y[i] + z[i] * z[i]).sqrt();
            let inverse = 1.0 / length;
            let (ux, uy, uz) = (x[i] * inverse, y[i] * inverse, z[i] * inverse);
            let (lx, ly, lz) =
                (ux * (1.0 - UNIT_SLACK), uy * (1.0 - UNIT_SLACK), uz * (1.0 - UNIT_SLACK));
            let (hx, hy, hz) =
                (ux * (1.0 + UNIT_SLACK), uy * (1.0 + UNIT_SLACK), uz * (1.0 + UNIT_SLACK));
            // A finite length means finite components; NaN fails every comparison.
            ok[i] = (m[i] > 0.0)
                & (length > CANCEL_FRACTION * m[i])
                & (length < f64::INFINITY)
                & (lx as f32 == hx as f32)
                & (ly as f32 == hy as f32)
                & (lz as f32 == hz as f32);
            u[0][i] = lx as f32;
            u[1][i] = ly as f32;
            u[2][i] = lz as f32;
        }
        for (i, normal) in out.iter_mut().enumerate() {
            *normal = if ok[i] { Vec3::new(u[0][i], u[1][i], u[2][i]) } else { unit_or_nan(&s[i]) };
        }
        if !ok.iter().fold(true, |all, &ok| all & ok) {
            unresolved += out.iter().filter(|n| n.x.is_nan()).count();
        }
    }
    for (s, normal) in rest.iter().zip(out_rest) {
        *normal = unit_or_nan(s);
        unresolved += usize::from(normal.x.is_nan());
    }
    unresolved
}

/// [`units`] four vertices at a time in AVX2 registers ([`units4`]).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn units_v3(simd: pulp::x86::V3, sums: &[Record], out: &mut [Vec3]) -> usize {
    let mut unresolved = 0;
    let (groups, rest) = sums.as_chunks::<4>();
    let (out_groups, out_rest) = out.split_at_mut(groups.len() * 4);
    let (out_groups, _) = out_groups.as_chunks_mut::<4>();
    for (s, out) in groups.iter().zip(out_groups) {
        unresolved += units4(simd, s, out);
    }
    for (s, normal) in rest.iter().zip(out_rest) {
        *normal = unit_or_nan(s);
        unresolved += usize::from(normal.x.is_nan());
    }
    unresolved
}

/// Four 4-wide vectors as the rows of a 4 × 4 matrix, transposed: four records `[x, y, z, m]`
/// become the x, y, z and m of all four, and back.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn transpose4(
    simd: pulp::x86::V3,
    [r0, r1, r2, r3]: [std::arch::x86_64::__m256d; 4],
) -> [std::arch::x86_64::__m256d; 4] {
    let avx = simd.avx;
    let (t0, t1) = (avx._mm256_unpacklo_pd(r0, r1), avx._mm256_unpackhi_pd(r0, r1));
    let (t2, t3) = (avx._mm256_unpacklo_pd(r2, r3), avx._mm256_unpackhi_pd(r2, r3));
    [
        avx._mm256_permute2f128_pd::<0x20>(t0, t2),
        avx._mm256_permute2f128_pd::<0x20>(t1, t3),
        avx._mm256_permute2f128_pd::<0x31>(t0, t2),
        avx._mm256_permute2f128_pd::<0x31>(t1, t3),
    ]
}

/// [`unit_or_nan`] of four vertices in AVX2 registers: the sums transposed in registers, the
/// same operations lane by lane as [`units`] (so the same bits), the f32 results interleaved
/// back into `Vec3`s by shuffles and stored 48 bytes at once. Returns how many got NaN.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn units4(simd: pulp::x86::V3, s: &[Record; 4], out: &mut [Vec3; 4]) -> usize {
    use std::arch::x86_64::{__m128, __m256d, _CMP_GT_OQ, _CMP_LT_OQ};
    let (avx, sse) = (simd.avx, simd.sse);
    let (below, above) =
        (avx._mm256_set1_pd(1.0 - UNIT_SLACK), avx._mm256_set1_pd(1.0 + UNIT_SLACK));
    let load = |i: usize| -> __m256d { bytemuck::cast(s[i]) };
    let [x, y, z, m] = transpose4(simd, [load(0), load(1), load(2), load(3)]);
    let squared = avx._mm256_add_pd(
        avx._mm256_add_pd(avx._mm256_mul_pd(x, x), avx._mm256_mul_pd(y, y)),
        avx._mm256_mul_pd(z, z),
    );
    let length = avx._mm256_sqrt_pd(squared);
    let inverse = avx._mm256_div_pd(avx._mm256_set1_pd(1.0), length);
    let unit = |c| avx._mm256_mul_pd(c, inverse);
    let (ux, uy, uz) = (unit(x), unit(y), unit(z));
    let f32s = |c, f| avx._mm256_cvtpd_ps(avx._mm256_mul_pd(c, f));
    let low = [f32s(ux, below), f32s(uy, below), f32s(uz, below)];
    let high = [f32s(ux, above), f32s(uy, above), f32s(uz, above)];
    let same = sse._mm_and_ps(
        sse._mm_and_ps(sse._mm_cmpeq_ps(low[0], high[0]), sse._mm_cmpeq_ps(low[1], high[1])),
        sse._mm_cmpeq_ps(low[2], high[2]),
    );
    let usable = avx._mm256_and_pd(
        avx._mm256_and_pd(
            avx._mm256_cmp_pd::<_CMP_GT_OQ>(m, avx._mm256_setzero_pd()),
            avx._mm256_cmp_pd::<_CMP_GT_OQ>(
                length,
                avx._mm256_mul_pd(avx._mm256_set1_pd(CANCEL_FRACTION), m),
            ),
        ),
        avx._mm256_cmp_pd::<_CMP_LT_OQ>(length, avx._mm256_set1_pd(f64::INFINITY)),
    );
    let ok = sse._mm_movemask_ps(same) & avx._mm256_movemask_pd(usable);
    let [a, b, c] = low;
    let (xy_low, xy_high) = (sse._mm_unpacklo_ps(a, b), sse._mm_unpackhi_ps(a, b));
    let t = sse._mm_shuffle_ps::<0b11_10_00_00>(c, xy_low);
    let o0 = sse._mm_shuffle_ps::<0b10_00_01_00>(xy_low, t);
    let v = sse._mm_shuffle_ps::<0b01_01_11_11>(xy_low, c);
    let o1 = sse._mm_shuffle_ps::<0b01_00_10_00>(v, xy_high);
    let w = sse._mm_shuffle_ps::<0b11_10_11_10>(xy_high, c);
    let o2 = sse._mm_shuffle_ps::<0b11_01_00_10>(w, w);
    *bytemuck::cast_mut::<[Vec3; 4], [f32; 12]>(out) =
        bytemuck::cast::<[__m128; 3], _>([o0, o1, o2]);
    let mut unresolved = 0;
    if ok != 0b1111 {
        for (i, normal) in out.iter_mut().enumerate() {
            if ok & (1 << i) == 0 {
                *normal = unit_or_nan(&s[i]);
                unresolved += usize::from(normal.x.is_nan());
            }
        }
    }
    unresolved
}

/// Why a vertex for which [`unit_or_nan`] gave NaN falls back, as far as its sums tell:
/// `Degenerate` for a zero length sum (isolated or degenerate: [`settle`] tells), else
/// `Cancelled { face: u32::MAX }` ([`settle`] finds the face).
fn provisional(s: &Record) -> Fallback {
    if s[3] <= 0.0 { Fallback::Degenerate } else { Fallback::Cancelled { face: u32::MAX } }
}

/// Settles the vertices that fall back: a zero length sum is `Isolated` when no face uses
/// the vertex, `Degenerate` otherwise; cancelling normals take the unit normal of the largest
/// usable face at the vertex (the first of equal ones), as the reference's accumulator keeps it.
fn settle(mesh: &Mesh, normals: &mut [Vec3], fallbacks: &mut [(u32, Fallback)]) {
    const NONE: u32 = u32::MAX;
    let mut slot = vec![NONE; normals.len()];
    for (k, &(v, _)) in fallbacks.iter().enumerate() {
        slot[v as usize] = k as u32;
    }
    let mut touched = vec![false; fallbacks.len()];
    let mut largest: Vec<Option<(f64, u32, DVec3)>> = vec![None; fallbacks.len()];
    for (f, face) in mesh.faces.iter().enumerate() {
        let mut geometry = None;
        for &v in face {
            let k = slot[v as usize];
            if k == NONE {
                continue;
            }
            touched[k as usize] = true;
            if !matches!(fallbacks[k as usize].1, Fallback::Cancelled { .. }) {
                continue;
            }
            let g = *geometry.get_or_insert_with(|| face_geometry(mesh, f));
            if let Some(g) = g {
                let area = g.area_vector.length();
                let best = &mut largest[k as usize];
                if best.is_none_or(|(l, _, _)| area > l) {
                    *best = Some((area, f as u32, g.unit));
                }
            }
        }
    }
    for (k, (v, why)) in fallbacks.iter_mut().enumerate() {
        match why {
            Fallback::Degenerate if !touched[k] => *why = Fallback::Isolated,
            Fallback::Cancelled { .. } => {
                // A cancelled vertex has a usable face: its length sum is positive.
                if let Some((_, face, unit)) = largest[k] {
                    normals[*v as usize] = unit.as_vec3();
                    *why = Fallback::Cancelled { face };
                }
            }
            _ => {}
        }
    }
}

/// The record of `face` (indices in range) as the reference computes it (zeros for an unusable
/// face).
pub(super) fn exact_record(positions: &[Vec3], face: [u32; 3]) -> Record {
    corner_geometry(face.map(|v| positions[v as usize])).map_or([0.0; 4], |g| {
        let v = g.area_vector;
        [v.x, v.y, v.z, v.length()]
    })
}

/// The records of `faces` (corners in `positions`) into `out`; `false` (and nothing computed)
/// when an index is out of range.
///
/// Compiled twice by `multiversion`: for x86-64 with AVX2 and FMA, chosen at run time when the
/// CPU has them, and for the target the kit is built for. With FMA (also every aarch64 build)
/// eight faces at a time go through [`lane_records`]; without it every face goes through
/// [`quick_area_record`], which avoids the fused multiply-adds a plain x86-64 build would call a
/// library function for.
#[multiversion(targets("x86_64+avx2+fma"))]
pub(super) fn block_records(
    positions: &[Vec3],
    faces: &[[u32; 3]],
    out: &mut [Record],
    kernels: Kernels,
) -> bool {
    let n = positions.len();
    if faces.iter().flatten().fold(0, |m, &v| m.max(v)) as usize >= n {
        return false;
    }
    let fma = multiversion::target::target_cfg_f!(any(
        target_arch = "aarch64",
        all(target_arch = "x86_64", target_feature = "fma")
    ));
    if kernels == Kernels::NoFma || !fma {
        for (&face, record) in faces.iter().zip(out.iter_mut()) {
            let [a, b, c] = face.map(|v| positions[v as usize]);
            *record = quick_area_record(a, b, c).unwrap_or_else(|| exact_record(positions, face));
        }
        return true;
    }
    // The corners' coordinates of a group of faces, one array per coordinate.
    let mut scratch = [[0.0f32; LANES]; 9];
    let (groups, rest) = faces.as_chunks::<LANES>();
    let (out_groups, out_rest) = out.split_at_mut(groups.len() * LANES);
    let (out_groups, _) = out_groups.as_chunks_mut::<LANES>();
    for (faces, out) in groups.iter().zip(out_groups) {
        let ok = lane_records(&mut scratch, positions, faces, out);
        if !ok.iter().fold(true, |all, &ok| all & ok) {
            for (i, record) in out.iter_mut().enumerate() {
                if !ok[i] {
                    *record = exact_record(positions, faces[i]);
                }
            }
        }
    }
    if let Some(&pad) = rest.first() {
        // The last group, padded with its own first face (whose extra records are dropped).
        let mut group = [pad; LANES];
        group[..rest.len()].copy_from_slice(rest);
        let mut records = [[0.0; 4]; LANES];
        let ok = lane_records(&mut scratch, positions, &group, &mut records);
        for (i, record) in out_rest.iter_mut().enumerate() {
            *record = if ok[i] { records[i] } else { exact_record(positions, rest[i]) };
        }
    }
    true
}

/// [`LANES`] faces at once (structure of arrays, so the compiler vectorises every step): for each
/// face, whether the shortcut vouches for its record, and the record. For a CPU with FMA.
///
/// The shortcut: both edges exact in f64 ([`difference_fits`], which also rules out non-finite
/// corners), the cross product as [`cross_kahan_f64`](crate::math::cross_kahan_f64)
/// computes it, and the degeneracy test of [`quick_area_record`] (squared upper bounds of the
/// noise with room for their rounding). Then the record has the reference's bits.
#[inline(always)]
fn lane_records(
    p: &mut [[f32; LANES]; 9],
    positions: &[Vec3],
    faces: &[[u32; 3]; LANES],
    out: &mut [Record; LANES],
) -> [bool; LANES] {
    for (i, face) in faces.iter().enumerate() {
        for (k, &v) in face.iter().enumerate() {
            let q = positions[v as usize];
            p[3 * k][i] = q.x;
            p[3 * k + 1][i] = q.y;
            p[3 * k + 2][i] = q.z;
        }
    }
    let [ax, ay, az, bx, by, bz, cx, cy, cz] = &*p;
    // On the f32 coordinates, eight lanes at a time: whether both edges are exact in f64 (see
    // `difference_fits`), and the largest coordinate magnitude.
    let mut exact = [false; LANES];
    let mut largest = [0.0f32; LANES];
    for i in 0..LANES {
        exact[i] = difference_fits(ax[i], bx[i])
            & difference_fits(ay[i], by[i])
            & difference_fits(az[i], bz[i])
            & difference_fits(ax[i], cx[i])
            & difference_fits(ay[i], cy[i])
            & difference_fits(az[i], cz[i]);
        largest[i] = [ay[i], az[i], bx[i], by[i], bz[i], cx[i], cy[i], cz[i]]
            .iter()
            .fold(ax[i].abs(), |m, c| m.max(c.abs()));
    }
    let mut ok = [false; LANES];
    const K: f64 = 32.0 * F32_UNIT_ROUNDOFF * F32_UNIT_ROUNDOFF;
    const D2: f64 = DEGENERATE_SINE * DEGENERATE_SINE;
    // Then in f64, four lanes at a time (the coordinates widened here, not one by one above).
    for i in 0..LANES {
        let (ax, ay, az) = (f64::from(ax[i]), f64::from(ay[i]), f64::from(az[i]));
        let (bx, by, bz) = (f64::from(bx[i]), f64::from(by[i]), f64::from(bz[i]));
        let (cx, cy, cz) = (f64::from(cx[i]), f64::from(cy[i]), f64::from(cz[i]));
        let (e1x, e1y, e1z) = (bx - ax, by - ay, bz - az);
        let (e2x, e2y, e2z) = (cx - ax, cy - ay, cz - az);
        let x = difference_of_products_f64(e1y, e2z, e1z, e2y) + 0.0;
        let y = difference_of_products_f64(e1z, e2x, e1x, e2z) + 0.0;
        let z = difference_of_products_f64(e1x, e2y, e1y, e2x) + 0.0;
        let l1 = e1x * e1x + e1y * e1y + e1z * e1z;
        let l2 = e2x * e2x + e2y * e2y + e2z * e2z;
        // max |corner|² ≤ 3·(largest coordinate)².
        let pm = 3.0 * f64::from(largest[i]) * f64::from(largest[i]);
        let exact_noise = D2 * l1 * l2;
        let round_noise = K * pm * (l1 + l2);
        let noise = if exact_noise > round_noise { exact_noise } else { round_noise };
        let length_squared = x * x + y * y + z * z;
        ok[i] = exact[i] & (length_squared > noise * (1.0 + 1e-6));
        out[i] = [x, y, z, length_squared.sqrt()];
    }
    ok
}

/// Whether `b − a` is exact in f64, from the exponents of the two f32 numbers: with exponents
/// `E_max ≥ E_min` (a subnormal counted as −126), the difference is a multiple of `2^(E_min−23)`
/// below `2^(E_max+2)` in magnitude, so it has at most `E_max − E_min + 25` significant bits:
/// at most 53 when the exponents differ by 28 or less. A zero operand makes it exact too; an
/// infinite or NaN operand never passes. (Stricter than TwoSum's test: a difference it rejects
/// goes the exact way.)
#[inline(always)]
fn difference_fits(a: f32, b: f32) -> bool {
    let (ea, eb) = ((a.to_bits() >> 23) & 0xff, (b.to_bits() >> 23) & 0xff);
    let finite = (ea != 0xff) & (eb != 0xff);
    finite & ((ea.max(1).abs_diff(eb.max(1)) <= 28) | (a == 0.0) | (b == 0.0))
}

/// The significand field of an f64.
const SIGNIFICAND: u64 = (1 << 52) - 1;

/// How many significant bits (1..=53) the widest of `v`'s components has, for finite normal
/// numbers and zeros (an edge of f32 corners is never an f64 subnormal).
#[inline]
fn significant_bits(v: DVec3) -> u32 {
    let field = (v.x.to_bits() | v.y.to_bits() | v.z.to_bits()) & SIGNIFICAND;
    53 - (field | (1 << 52)).trailing_zeros()
}

/// Whether `to − from`, rounded to f64, is exact (the `lo` of
/// [`exact_edge`](super::exact_edge) is zero).
#[inline]
fn edge_is_exact(from: DVec3, to: DVec3, hi: DVec3) -> bool {
    let y = -from;
    let y_part = hi - to;
    let x_part = hi - y_part;
    (to - x_part) + (y - y_part) == DVec3::ZERO
}

/// One face of the fast path on a CPU without FMA: `[x, y, z, |n|]` with `n` the area vector
/// that [`usable_area_vector`](super::usable_area_vector) returns and `|n|` its `length()`, bit
/// for bit, or `None` when this shortcut cannot vouch for the bits (the caller then takes
/// [`face_geometry`]).
///
/// The shortcut: when both edges are exact in f64 and the significant bits of the widest
/// components of the two edges add up to at most 53, every product in the cross product is exact,
/// so the plain `a·b − c·d` rounds once, exactly like Kahan's difference of products (whose
/// error term is then an exact zero): the same bits, without the fused multiply-adds that cost a
/// library call per product on a CPU target without FMA. The degeneracy test compares squared
/// lengths against upper bounds of the noise and only accepts a face whose squared area vector
/// is 1 + 10⁻⁶ times above them (far beyond their rounding); any other face goes the exact way.
#[inline]
fn quick_area_record(a: Vec3, b: Vec3, c: Vec3) -> Option<Record> {
    if !(a.is_finite() && b.is_finite() && c.is_finite()) {
        return None;
    }
    let (ad, bd, cd) = (a.as_dvec3(), b.as_dvec3(), c.as_dvec3());
    let (e1, e2) = (bd - ad, cd - ad);
    if !(edge_is_exact(ad, bd, e1) && edge_is_exact(ad, cd, e2))
        || significant_bits(e1) + significant_bits(e2) > 53
    {
        return None;
    }
    let n =
        DVec3::new(e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z, e1.x * e2.y - e1.y * e2.x)
            + DVec3::ZERO;
    // Squared upper bounds of the two noises of `usable_area_vector`. `rounding_noise` is at most
    // √3·(|d₁|·|e₂| + |e₁|·|d₂|) (each component of `abs_cross(x, y)` is at most |x|·|y|) with
    // |dᵢ| ≤ 2u·max|corner|, so its square is at most 24u²·P·(|e₁|² + |e₂|²), P = max|corner|²;
    // 32u² leaves room for the rounding of these few operations.
    let (l1, l2) = (e1.length_squared(), e2.length_squared());
    let p = ad.length_squared().max(bd.length_squared()).max(cd.length_squared());
    let exact_noise = DEGENERATE_SINE * DEGENERATE_SINE * l1 * l2;
    let noise = exact_noise.max(32.0 * F32_UNIT_ROUNDOFF * F32_UNIT_ROUNDOFF * p * (l1 + l2));
    let length_squared = n.length_squared();
    (length_squared > noise * (1.0 + 1e-6)).then(|| [n.x, n.y, n.z, length_squared.sqrt()])
}

/// `try_normalize_f64(v).map(DVec3::as_vec3)` for a finite `v` of length `length`
/// (`v.length()`), with one division instead of six, or `None` when this shortcut cannot vouch
/// for the bits.
///
/// `v · (1/length)` is within 4 units of f64 rounding (u = 2⁻⁵³) of the exact unit vector, and
/// `try_normalize_f64`'s `(v/m)/|v/m|` within 6 of it, so the two are within 2⁻⁴⁹ relative of
/// each other. When `x·(1 − 2⁻⁴⁶)` and `x·(1 + 2⁻⁴⁶)` round to the same f32 for every component
/// `x` of the shortcut, so does everything in between, the reference included. Otherwise (a
/// component within 2⁻⁴⁶ of an f32 rounding boundary, once in ~10⁷) the caller divides.
#[inline]
fn quick_unit_f32(v: DVec3, length: f64) -> Option<Vec3> {
    if !(v.is_finite() && length > 0.0 && length.is_finite()) {
        return None;
    }
    let unit = v * (1.0 / length);
    let (low, high) =
        ((unit * (1.0 - UNIT_SLACK)).as_vec3(), (unit * (1.0 + UNIT_SLACK)).as_vec3());
    (low == high).then_some(low)
}
