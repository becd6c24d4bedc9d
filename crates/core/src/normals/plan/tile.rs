//! One tile's work each frame (see [`super`]): its corners read and checked, its faces' records,
//! each vertex's sums gathered from them and normalised. On x86-64 with AVX2 and FMA the corners,
//! the marking of untrusted corners, the face records, and the sums with their normalisation run
//! as hand-vectorised kernels (through `pulp`, which calls the intrinsics safely once it has
//! checked the CPU); elsewhere as the compiler's code. Both give the same bits.

use multiversion::multiversion;

use super::super::fast::{Record, block_records, exact_record, units};
#[cfg(target_arch = "x86_64")]
use super::super::fast::{transpose4, units4};
use super::super::{DEGENERATE_SINE, F32_UNIT_ROUNDOFF, Kernels};
use super::{CORNER_CAP, FACE_CAP};
use crate::math::difference_of_products_f64;
use glam::Vec3;

/// The sums of each vertex: its faces' records added in ascending face order (4-wide in the
/// AVX copy), as the reference adds them, so the area vector's sum has the reference's bits.
/// The fourth sum is of each face's `|x| + |y| + |z|` (the one-shot kernel's records carry `|n|`
/// there, which is no larger), times `1 + 2⁻¹⁶`: an upper bound of the reference's sum of the
/// vectors' lengths, with room for the rounding of both sums for any number of faces below 2³⁴.
/// The bound is only compared with the length of the sum (cancellation): where it says
/// "cancelled" the vertex is settled exactly, so it never changes a result. It is positive
/// exactly when a usable face touches the vertex (an unusable face's record is zero).
#[multiversion(targets("x86_64+avx2+fma"))]
fn gather(ref_start: &[u32], refs: &[u16], records: &[Record; FACE_CAP], sums: &mut [Record]) {
    let mut previous = ref_start[0] as usize;
    for (s, &end) in sums.iter_mut().zip(&ref_start[1..]) {
        let mut sum = [0.0f64; 4];
        for &r in &refs[previous..end as usize] {
            let x = records[r as usize & (FACE_CAP - 1)];
            sum = [sum[0] + x[0], sum[1] + x[1], sum[2] + x[2], sum[3] + x[3]];
        }
        *s = [sum[0], sum[1], sum[2], sum[3] * GATHER_SLACK];
        previous = end as usize;
    }
}

/// The normals of a tile's vertices into `out` (NaN where the vertex falls back; returns how
/// many): [`gather`], then the one-shot path's normalisation. With [`Kernels::Best`] on x86-64
/// with AVX2 and FMA, four vertices at a time without the sums leaving the registers
/// ([`gather_units_v3`]).
pub(super) fn gather_units(
    ref_start: &[u32],
    refs: &[u16],
    records: &[Record; FACE_CAP],
    sums: &mut [Record],
    out: &mut [Vec3],
    kernels: Kernels,
) -> usize {
    #[cfg(target_arch = "x86_64")]
    if let Some(simd) = kernels.v3() {
        return simd.vectorize(|| gather_units_v3(simd, ref_start, refs, records, out));
    }
    gather(ref_start, refs, records, sums);
    units(sums, out, kernels)
}

/// [`gather`] and [`units4`] four vertices at a time: the four sums in four registers (four
/// chains of additions side by side when the vertices have as many faces, as on most meshes),
/// each as [`gather`] makes it, so the same bits.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn gather_units_v3(
    simd: pulp::x86::V3,
    ref_start: &[u32],
    refs: &[u16],
    records: &[Record; FACE_CAP],
    out: &mut [Vec3],
) -> usize {
    use std::arch::x86_64::__m256d;
    let avx = simd.avx;
    let slack = avx._mm256_setr_pd(1.0, 1.0, 1.0, GATHER_SLACK);
    let record = |r: u16| -> __m256d { bytemuck::cast(records[r as usize & (FACE_CAP - 1)]) };
    let mut unresolved = 0;
    let (groups, rest) = out.as_chunks_mut::<4>();
    for (g, out) in groups.iter_mut().enumerate() {
        let bounds: [u32; 5] = std::array::from_fn(|i| ref_start[4 * g + i]);
        let own = |i: usize| &refs[bounds[i] as usize..bounds[i + 1] as usize];
        let (a, b, c, d) = (own(0), own(1), own(2), own(3));
        let mut sums = [avx._mm256_setzero_pd(); 4];
        if a.len() == b.len() && a.len() == c.len() && a.len() == d.len() {
            for k in 0..a.len() {
                sums[0] = avx._mm256_add_pd(sums[0], record(a[k]));
                sums[1] = avx._mm256_add_pd(sums[1], record(b[k]));
                sums[2] = avx._mm256_add_pd(sums[2], record(c[k]));
                sums[3] = avx._mm256_add_pd(sums[3], record(d[k]));
            }
        } else {
            for (sum, own) in sums.iter_mut().zip([a, b, c, d]) {
                for &r in own {
                    *sum = avx._mm256_add_pd(*sum, record(r));
                }
            }
        }
        let sums: [Record; 4] = [
            bytemuck::cast(avx._mm256_mul_pd(sums[0], slack)),
            bytemuck::cast(avx._mm256_mul_pd(sums[1], slack)),
            bytemuck::cast(avx._mm256_mul_pd(sums[2], slack)),
            bytemuck::cast(avx._mm256_mul_pd(sums[3], slack)),
        ];
        unresolved += units4(simd, &sums, out);
    }
    let done = groups.len() * 4;
    let mut sums = [[0.0; 4]; 3];
    let sums = &mut sums[..rest.len()];
    gather(&ref_start[done..], refs, records, sums);
    unresolved + units(sums, rest, Kernels::Compiled)
}

/// The factor of the length sums' bound (see [`gather`]).
const GATHER_SLACK: f64 = 1.0 + 1.0 / (1u64 << 16) as f64;

/// Where a tile's corners can be trusted, every edge `b − a` of its faces is exact in f64: each
/// coordinate's largest magnitude is at most this many times its smallest non-zero one.
///
/// Why: two f32 numbers are multiples of the smaller one's ulp, which is at least 2⁻²⁴ of it
/// (2⁻¹⁴⁹ for subnormals, also at least 2⁻²⁴ of them), and their difference is below twice the
/// larger; so it has at most `25 + log₂(largest/smallest)` significant bits, here at most 52.
const EXACT_RANGE: f64 = (1u64 << 27) as f64;

/// The records of a tile's faces into `records`: the area vector, bit for bit the reference's,
/// and `|x| + |y| + |z|` (see [`gather`]).
///
/// The shortcut, on a CPU with FMA: the tile's corners are read once, into f64, and checked
/// once ([`mark_untrusted`]): a corner that is not finite, or has a coordinate far smaller than
/// the tile's largest (rounding residue next to a coordinate plane, say), is marked so that its
/// faces go the exact way; among the others every edge is exact in f64. An upper bound `T` of
/// every face's squared degeneracy threshold is taken from the tile's extent (an edge is no
/// longer than the diagonal of the box around the trusted corners, a corner no farther from the
/// origin than the box's farthest corner; see the one-shot kernel for the two thresholds and
/// their squared bounds). Then each face is edges, Kahan's cross product and one comparison: a
/// face whose squared area vector exceeds `T` (with room for rounding) is usable and its vector
/// is the reference's; any other face (a sliver, a needle, a marked corner) goes the exact way,
/// and so does every face of a tile on a CPU without FMA (the one-shot path's kernels). With
/// [`Kernels::Best`] on x86-64 with AVX2 and FMA, the corners, their marking and the faces go
/// through hand-vectorised kernels (the same operations, so the same bits).
#[multiversion(targets("x86_64+avx2+fma"))]
pub(super) fn records(
    positions: &[Vec3],
    locals: &[u32],
    local_faces: &[[u16; 3]],
    faces: &[[u32; 3]],
    corners: &mut [[f64; 4]; CORNER_CAP],
    records: &mut [Record],
    kernels: Kernels,
) {
    let fma = multiversion::target::target_cfg_f!(any(
        target_arch = "aarch64",
        all(target_arch = "x86_64", target_feature = "fma")
    ));
    if kernels == Kernels::NoFma || !fma {
        block_records(positions, faces, records, kernels);
        return;
    }
    let all_corners = corners;
    let corners = &mut all_corners[..locals.len()];
    // While reading the corners: each coordinate's range and smallest non-zero magnitude.
    let (low, high, smallest) = read_corners(positions, locals, corners, kernels);
    // Usually every corner is finite and within EXACT_RANGE (the range is then that of all
    // corners); otherwise the corners that are not are marked, and the range is over the others.
    let mut largest: [f64; 4] = std::array::from_fn(|k| (-low[k]).max(high[k]));
    let clean =
        (0..4).all(|k| largest[k] < f64::INFINITY && smallest[k] * EXACT_RANGE >= largest[k]);
    // (Where every coordinate's range is finite, it is already the largest finite magnitude.)
    if !clean && !largest.iter().all(|l| l.is_finite()) {
        largest = largest_finite(corners);
    }
    let (low, high) = if clean { (low, high) } else { mark_untrusted(corners, largest, kernels) };
    let mut extent = 0.0;
    for k in 0..3 {
        // No trusted corner: no face passes anyway.
        if high[k] >= low[k] {
            extent += (high[k] - low[k]) * (high[k] - low[k]);
        }
    }
    let farthest: f64 = largest[..3].iter().map(|l| l * l).sum();
    // Squared edges are at most `extent` and squared corners at most `farthest` (both rounded:
    // the factors below cover that). The two squared thresholds of the one-shot kernel:
    // D2·l₁·l₂ ≤ D2·extent², and K·P·(l₁ + l₂) ≤ K·farthest·2·extent.
    const K: f64 = 32.0 * F32_UNIT_ROUNDOFF * F32_UNIT_ROUNDOFF;
    const D2: f64 = DEGENERATE_SINE * DEGENERATE_SINE;
    let (extent, farthest) = (extent * 1.001, farthest * 1.001);
    let threshold = (D2 * extent * extent).max(K * farthest * 2.0 * extent) * 1.01;
    // |n| ≥ (|x| + |y| + |z|)/√3, so a face whose sum of magnitudes exceeds √(3·threshold) (with
    // room for rounding) is clearly above its degeneracy threshold.
    let least = (3.0 * threshold).sqrt() * (1.0 + 1e-6);
    if !face_records(&*all_corners, local_faces, least, records, kernels) {
        // Some face is not clearly usable (or has a marked corner: its sum is NaN).
        for (record, &face) in records.iter_mut().zip(faces) {
            // Not above `least`, or NaN.
            if record[3].partial_cmp(&least) != Some(std::cmp::Ordering::Greater) {
                *record = exact_record(positions, face);
            }
        }
    }
}

/// Reads a tile's corners into f64 and returns each coordinate's lowest and highest value and
/// smallest non-zero magnitude (NaN is never taken).
#[inline(always)]
fn read_corners(
    positions: &[Vec3],
    locals: &[u32],
    corners: &mut [[f64; 4]],
    #[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))] kernels: Kernels,
) -> ([f64; 4], [f64; 4], [f64; 4]) {
    #[cfg(target_arch = "x86_64")]
    if let Some(simd) = kernels.v3() {
        return simd.vectorize(|| read_corners_v3(simd, positions, locals, corners));
    }
    let (mut low, mut high) = ([f64::INFINITY; 4], [f64::NEG_INFINITY; 4]);
    let mut smallest = [f64::INFINITY; 4];
    for (corner, &v) in corners.iter_mut().zip(locals) {
        let p = positions[v as usize];
        let c = [f64::from(p.x), f64::from(p.y), f64::from(p.z), 0.0];
        *corner = c;
        for k in 0..4 {
            low[k] = if c[k] < low[k] { c[k] } else { low[k] };
            high[k] = if c[k] > high[k] { c[k] } else { high[k] };
            let a = c[k].abs();
            let a = if a == 0.0 { f64::INFINITY } else { a };
            smallest[k] = if a < smallest[k] { a } else { smallest[k] };
        }
    }
    (low, high, smallest)
}

/// [`read_corners`] with one 4-wide vector per corner, the position of the corner 24 places on
/// asked for ahead of its use (the positions are read all over the mesh).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn read_corners_v3(
    simd: pulp::x86::V3,
    positions: &[Vec3],
    locals: &[u32],
    corners: &mut [[f64; 4]],
) -> ([f64; 4], [f64; 4], [f64; 4]) {
    use std::arch::x86_64::{__m256d, _CMP_EQ_OQ, _MM_HINT_T0};
    let (avx, sse) = (simd.avx, simd.sse);
    let infinity = avx._mm256_set1_pd(f64::INFINITY);
    let (mut low, mut high, mut smallest) =
        (infinity, avx._mm256_set1_pd(f64::NEG_INFINITY), infinity);
    let (zero, sign) = (avx._mm256_setzero_pd(), avx._mm256_set1_pd(-0.0));
    const AHEAD: usize = 24;
    for (i, (corner, &v)) in corners.iter_mut().zip(locals).enumerate() {
        if let Some(&w) = locals.get(i + AHEAD) {
            let at = positions.as_ptr().wrapping_add(w as usize).cast::<i8>();
            sse._mm_prefetch::<_MM_HINT_T0>(at);
        }
        let p = positions[v as usize];
        let c = avx._mm256_cvtps_pd(sse._mm_set_ps(0.0, p.z, p.y, p.x));
        *corner = bytemuck::cast(c);
        // (minpd/maxpd return the second operand when either is NaN: NaN is never taken.)
        low = avx._mm256_min_pd(c, low);
        high = avx._mm256_max_pd(c, high);
        let a = avx._mm256_andnot_pd(sign, c);
        let a = avx._mm256_blendv_pd(a, infinity, avx._mm256_cmp_pd::<_CMP_EQ_OQ>(a, zero));
        smallest = avx._mm256_min_pd(a, smallest);
    }
    let back = |v: __m256d| -> [f64; 4] { bytemuck::cast(v) };
    (back(low), back(high), back(smallest))
}

/// Each coordinate's largest finite magnitude among `corners` (0 when there is none).
#[inline(never)]
fn largest_finite(corners: &[[f64; 4]]) -> [f64; 4] {
    let mut largest = [0.0f64; 4];
    for c in corners {
        for k in 0..4 {
            let a = c[k].abs();
            if a > largest[k] && a < f64::INFINITY {
                largest[k] = a;
            }
        }
    }
    largest
}

/// Marks the corners that [`records`] cannot vouch for, by setting their x to NaN (every
/// face that uses one then fails its test and goes the exact way): a coordinate that is not
/// finite, or not zero but smaller than 2⁻²⁷ of the largest finite magnitude of that coordinate
/// in the tile (`largest`). Among the other corners every edge is exact in f64
/// ([`EXACT_RANGE`]). Returns the lowest and highest value of each coordinate over those.
#[inline(never)]
fn mark_untrusted(
    corners: &mut [[f64; 4]],
    largest: [f64; 4],
    #[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))] kernels: Kernels,
) -> ([f64; 4], [f64; 4]) {
    let floor = largest.map(|l| l / EXACT_RANGE);
    #[cfg(target_arch = "x86_64")]
    if let Some(simd) = kernels.v3() {
        return simd.vectorize(|| mark_untrusted_v3(simd, corners, largest, floor));
    }
    let (mut low, mut high) = ([f64::INFINITY; 4], [f64::NEG_INFINITY; 4]);
    for c in corners.iter_mut() {
        let a = c.map(f64::abs);
        // False for NaN; ±∞ is above any finite `largest`. (The fourth entries are zeros.)
        let trusted = (0..4).all(|k| ((a[k] == 0.0) | (a[k] >= floor[k])) & (a[k] <= largest[k]));
        if trusted {
            for k in 0..4 {
                low[k] = low[k].min(c[k]);
                high[k] = high[k].max(c[k]);
            }
        } else {
            c[0] = f64::NAN;
        }
    }
    (low, high)
}

/// [`mark_untrusted`] with one 4-wide vector per corner.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn mark_untrusted_v3(
    simd: pulp::x86::V3,
    corners: &mut [[f64; 4]],
    largest: [f64; 4],
    floor: [f64; 4],
) -> ([f64; 4], [f64; 4]) {
    use std::arch::x86_64::{__m256d, _CMP_EQ_OQ, _CMP_GE_OQ, _CMP_LE_OQ};
    let avx = simd.avx;
    let (largest, floor): (__m256d, __m256d) = (bytemuck::cast(largest), bytemuck::cast(floor));
    let (zero, sign) = (avx._mm256_setzero_pd(), avx._mm256_set1_pd(-0.0));
    let mut low = avx._mm256_set1_pd(f64::INFINITY);
    let mut high = avx._mm256_set1_pd(f64::NEG_INFINITY);
    for corner in corners.iter_mut() {
        let c: __m256d = bytemuck::cast(*corner);
        let a = avx._mm256_andnot_pd(sign, c);
        // False for NaN; ±∞ is above any finite `largest`. (The fourth entries are zeros.)
        let kept = avx._mm256_and_pd(
            avx._mm256_or_pd(
                avx._mm256_cmp_pd::<_CMP_EQ_OQ>(a, zero),
                avx._mm256_cmp_pd::<_CMP_GE_OQ>(a, floor),
            ),
            avx._mm256_cmp_pd::<_CMP_LE_OQ>(a, largest),
        );
        if avx._mm256_movemask_pd(kept) == 0b1111 {
            low = avx._mm256_min_pd(c, low);
            high = avx._mm256_max_pd(c, high);
        } else {
            corner[0] = f64::NAN;
        }
    }
    (bytemuck::cast(low), bytemuck::cast(high))
}

/// The records `[x, y, z, |x| + |y| + |z|]` of a tile's faces (see [`records`]); `false` when
/// some face's sum of magnitudes is not above `least` (or is NaN).
#[inline(always)]
fn face_records(
    corners: &[[f64; 4]; CORNER_CAP],
    faces: &[[u16; 3]],
    least: f64,
    records: &mut [Record],
    #[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))] kernels: Kernels,
) -> bool {
    #[cfg(target_arch = "x86_64")]
    if let Some(simd) = kernels.v3() {
        return simd.vectorize(|| face_records_v3(simd, corners, faces, least, records));
    }
    face_records_compiled(corners, faces, least, records)
}

/// [`face_records`] as the compiler vectorises it: each face's cross product in one 4-wide
/// vector (the corners' fourth entries are zero).
#[inline(always)]
fn face_records_compiled(
    corners: &[[f64; 4]; CORNER_CAP],
    faces: &[[u16; 3]],
    least: f64,
    records: &mut [Record],
) -> bool {
    let mut all = true;
    for (face, out) in faces.iter().zip(records.iter_mut()) {
        let [a, b, c] = face.map(|v| corners[v as usize & (CORNER_CAP - 1)]);
        let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2], b[3] - a[3]];
        let e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2], c[3] - a[3]];
        // As `face_area_vector` computes it for exact edges (the correction is +0.0):
        // x = e1y·e2z − e1z·e2y, y = e1z·e2x − e1x·e2z, z = e1x·e2y − e1y·e2x.
        let (p, q) = ([e1[1], e1[2], e1[0], e1[3]], [e2[2], e2[0], e2[1], e2[3]]);
        let (r, t) = ([e1[2], e1[0], e1[1], e1[3]], [e2[1], e2[2], e2[0], e2[3]]);
        let n: [f64; 4] =
            std::array::from_fn(|k| difference_of_products_f64(p[k], q[k], r[k], t[k]) + 0.0);
        let magnitude = n[0].abs() + n[1].abs() + n[2].abs();
        all &= magnitude > least;
        *out = [n[0], n[1], n[2], magnitude];
    }
    all
}

/// [`face_records`] four faces at a time in structure-of-arrays form: each corner's vector
/// loaded once and transposed in registers, each component's cross product as
/// [`difference_of_products_f64`] computes it (so the same bits), the records transposed back.
/// The faces past the last multiple of four go through [`face_records_compiled`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn face_records_v3(
    simd: pulp::x86::V3,
    corners: &[[f64; 4]; CORNER_CAP],
    faces: &[[u16; 3]],
    least: f64,
    records: &mut [Record],
) -> bool {
    use std::arch::x86_64::{__m256d, _CMP_GT_OQ};
    let avx = simd.avx;
    let (groups, rest) = faces.as_chunks::<4>();
    let (record_groups, record_rest) = records.split_at_mut(groups.len() * 4);
    let (record_groups, _) = record_groups.as_chunks_mut::<4>();
    let (sign, least4) = (avx._mm256_set1_pd(-0.0), avx._mm256_set1_pd(least));
    let mut all = true;
    // The corners `k` of four faces, as x, y and z of each.
    #[inline(always)]
    fn role(
        simd: pulp::x86::V3,
        corners: &[[f64; 4]; CORNER_CAP],
        f: &[[u16; 3]; 4],
        k: usize,
    ) -> [__m256d; 3] {
        let load =
            |i: usize| -> __m256d { bytemuck::cast(corners[f[i][k] as usize & (CORNER_CAP - 1)]) };
        let [x, y, z, _] = transpose4(simd, [load(0), load(1), load(2), load(3)]);
        [x, y, z]
    }
    // `difference_of_products_f64`, operation for operation, then + 0.0.
    #[inline(always)]
    fn dop(simd: pulp::x86::V3, a: __m256d, b: __m256d, c: __m256d, d: __m256d) -> __m256d {
        let (avx, fma) = (simd.avx, simd.fma);
        let cd = avx._mm256_mul_pd(c, d);
        let err = fma._mm256_fnmadd_pd(c, d, cd);
        let dop = fma._mm256_fmsub_pd(a, b, cd);
        avx._mm256_add_pd(avx._mm256_add_pd(dop, err), avx._mm256_setzero_pd())
    }
    let role = |f, k| role(simd, corners, f, k);
    let dop = |a, b, c, d| dop(simd, a, b, c, d);
    for (f, out) in groups.iter().zip(record_groups) {
        let ([ax, ay, az], [bx, by, bz], [cx, cy, cz]) = (role(f, 0), role(f, 1), role(f, 2));
        let (ux, uy, uz) =
            (avx._mm256_sub_pd(bx, ax), avx._mm256_sub_pd(by, ay), avx._mm256_sub_pd(bz, az));
        let (vx, vy, vz) =
            (avx._mm256_sub_pd(cx, ax), avx._mm256_sub_pd(cy, ay), avx._mm256_sub_pd(cz, az));
        let nx = dop(uy, vz, uz, vy);
        let ny = dop(uz, vx, ux, vz);
        let nz = dop(ux, vy, uy, vx);
        let abs = |v: __m256d| avx._mm256_andnot_pd(sign, v);
        let m = avx._mm256_add_pd(avx._mm256_add_pd(abs(nx), abs(ny)), abs(nz));
        all &= avx._mm256_movemask_pd(avx._mm256_cmp_pd::<_CMP_GT_OQ>(m, least4)) == 0b1111;
        let [r0, r1, r2, r3] = transpose4(simd, [nx, ny, nz, m]);
        *out = [bytemuck::cast(r0), bytemuck::cast(r1), bytemuck::cast(r2), bytemuck::cast(r3)];
    }
    all & face_records_compiled(corners, rest, least, record_rest)
}
