//! [`super::cover`]'s f64 path written out in AVX2 registers (pulp's `V3`, checked at run time;
//! the workspace has no `unsafe`). The compiler's copy of the same loop keeps the lanes' masks as
//! bits and turns them back into lanes at each step, and stores colours one lane at a time; here
//! eight pixels (a group) stay in registers from the edge functions to the colours:
//!
//! - the three edge functions as two f64 registers each, tested ≥ 0 and reduced to a bit mask;
//! - the barycentrics converted to f32 once, the depth made, clamped and tested against the
//!   depth buffer's own eight lanes, and written back with a blend;
//! - Flat's and Gouraud's colours made in registers and stored as eight interleaved `Rgb`s
//!   (three registers, [`interleave`]), blended with the old colours where a lane did not pass.
//!
//! The same operations in the same order as [`super::runs_of`], lane for lane: no fused
//! multiply-add, IEEE division, compares that are false on NaN where Rust's are, and clamps whose
//! operands keep Rust's NaN behaviour. So the same bits; the tests check both copies against
//! the pixel-by-pixel rasterizer.

use std::arch::x86_64::{__m256, __m256d, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ};

use cg_core::Rgb;
use cg_core::glam::Vec3;
use pulp::x86::V3;

use super::{Gouraud, Mask, Run, Simple, Target, edge_setup};
use crate::pipeline::Edges;
use crate::simd::{interleave, lane_mask};
use crate::span::V3N;

/// Pixels in a group: one AVX register of f32.
const G: usize = 8;
/// The most groups a run has (a [`Mask`] holds 32 lanes).
const MAX_GROUPS: usize = Mask::BITS as usize / G;
/// A group's lanes in a [`Mask`].
const GROUP: Mask = (1 << G) - 1;

/// A triangle's runs for [`Runs::cover`]: [`super::runs_of`]'s arguments, the f64 edge
/// functions of `edges` over the pixels `area` (`[x0, y0, x1, y1]`, inclusive), `W` pixels at a
/// time (a multiple of eight, at most 32) in groups of eight.
pub(super) struct Runs<'a, 'b, 't, const W: usize> {
    pub(super) edges: &'a Edges,
    pub(super) area: [u32; 4],
    pub(super) z: Vec3,
    pub(super) simple: &'a Simple,
    pub(super) target: &'b mut Target<'t>,
    pub(super) runs: &'b mut Vec<Run<W>>,
}

impl<const W: usize> Runs<'_, '_, '_, W> {
    /// Rasterizes, depth-tests and shades the runs in pulp's AVX2 context (not through a
    /// closure: a closure's call is not always inlined there, and the intrinsics in it would
    /// then be calls). Gives the covered and passed pixel counts.
    #[inline(always)]
    pub(super) fn cover(self, simd: V3) -> (u64, u64) {
        struct Call<'a, 'b, 't, const W: usize>(V3, Runs<'a, 'b, 't, W>);
        impl<const W: usize> pulp::NullaryFnOnce for Call<'_, '_, '_, W> {
            type Output = (u64, u64);
            #[inline(always)]
            fn call(self) -> (u64, u64) {
                runs_of(self.0, self.1)
            }
        }
        simd.vectorize(Call(simd, self))
    }
}

/// [`Runs::cover`] in the AVX2 context.
#[inline(always)]
fn runs_of<const W: usize>(simd: V3, runs: Runs<'_, '_, '_, W>) -> (u64, u64) {
    let Runs { edges, area: [x0, y0, x1, y1], z, simple, target, runs } = runs;
    const { assert!(W.is_multiple_of(G) && W / G <= MAX_GROUPS) };
    let groups = W / G;
    let avx = simd.avx;
    let inv_area = avx._mm256_set1_ps(1.0 / edges.area2 as f32);
    let (row, step_x, step_y, bias) = edge_setup(edges, x0, y0);
    // No closure here calls an intrinsic: a closure is a function of its own, compiled without
    // AVX, so the intrinsics in it would not be inlined.
    // Lane k's offset from its run's first pixel, k·step_x, per edge (exact integers below 2⁵³,
    // as in the compiler's copy).
    let mut offsets = [[0.0f64; Mask::BITS as usize]; 3];
    let (mut step_w, mut step_y_f, mut row_f) = ([0.0f64; 3], [0.0f64; 3], [0.0f64; 3]);
    let mut bias_v = [avx._mm256_setzero_pd(); 3];
    for i in 0..3 {
        for (k, offset) in offsets[i].iter_mut().enumerate() {
            *offset = (k as i64 * step_x[i]) as f64;
        }
        step_w[i] = (step_x[i] * W as i64) as f64;
        step_y_f[i] = step_y[i] as f64;
        row_f[i] = row[i] as f64;
        bias_v[i] = avx._mm256_set1_pd(bias[i] as f64);
    }
    let (step_y, bias, mut row) = (step_y_f, bias_v, row_f);
    let zero = avx._mm256_setzero_pd();
    let depth = Depth::new(simd, z);
    let shader = Shader::new(simple);
    let (mut covered_count, mut passed_count) = (0u64, 0u64);
    for py in y0..=y1 {
        let mut e0 = row;
        let mut x = x0;
        let r = (py - target.y0) as usize;
        while x <= x1 {
            let n = (x1 - x + 1).min(W as u32);
            let start =
                [avx._mm256_set1_pd(e0[0]), avx._mm256_set1_pd(e0[1]), avx._mm256_set1_pd(e0[2])];
            let mut e = [[[zero; 2]; 3]; MAX_GROUPS];
            let mut covered: Mask = 0;
            for g in 0..groups {
                for h in 0..2 {
                    let k = G * g + 4 * h;
                    for i in 0..3 {
                        let offset: __m256d = bytemuck::cast(
                            *offsets[i][k..].first_chunk::<4>().expect("four lanes"),
                        );
                        e[g][i][h] = avx._mm256_add_pd(start[i], offset);
                    }
                    let [a, b, c] = [e[g][0][h], e[g][1][h], e[g][2][h]];
                    let inside = avx._mm256_and_pd(
                        avx._mm256_and_pd(
                            avx._mm256_cmp_pd::<_CMP_GE_OQ>(a, zero),
                            avx._mm256_cmp_pd::<_CMP_GE_OQ>(b, zero),
                        ),
                        avx._mm256_cmp_pd::<_CMP_GE_OQ>(c, zero),
                    );
                    covered |= (avx._mm256_movemask_pd(inside) as Mask) << (G * g + 4 * h);
                }
            }
            // Only the lanes within the bounding box.
            covered &= if n >= Mask::BITS { Mask::MAX } else { (1 << n) - 1 };
            for i in 0..3 {
                e0[i] += step_w[i];
            }
            let at = x;
            x += W as u32;
            if covered == 0 {
                continue;
            }
            let column = (at - target.x0) as usize;
            let mut passed: Mask = 0;
            let mut b = [[avx._mm256_setzero_ps(); 3]; MAX_GROUPS];
            for g in 0..groups {
                // Screen-space (linear) barycentrics from the unbiased edge functions: window
                // depth is linear on the screen.
                for i in 0..3 {
                    let low = avx._mm256_cvtpd_ps(avx._mm256_sub_pd(e[g][i][0], bias[i]));
                    let high = avx._mm256_cvtpd_ps(avx._mm256_sub_pd(e[g][i][1], bias[i]));
                    b[g][i] = avx._mm256_mul_ps(avx._mm256_set_m128(high, low), inv_area);
                }
                let lanes = covered >> (G * g) & GROUP;
                if lanes != 0 {
                    let depths = &mut target.depth[r][column + G * g..];
                    passed |= depth.test(&b[g], lanes, depths) << (G * g);
                }
            }
            covered_count += u64::from(covered.count_ones());
            passed_count += u64::from(passed.count_ones());
            if passed == 0 {
                continue;
            }
            match &shader {
                Shader::Colors(colors) => {
                    for g in 0..groups {
                        let lanes = passed >> (G * g) & GROUP;
                        if lanes != 0 {
                            let lit = colors.lit(simd, &b[g]);
                            write(simd, lit, lanes, &mut target.color[r][column + G * g..]);
                        }
                    }
                }
                Shader::Staged => {
                    let mut lanes = V3N::<W>::default();
                    let (xs, ys, zs) = (
                        lanes.x.as_chunks_mut::<G>().0,
                        lanes.y.as_chunks_mut::<G>().0,
                        lanes.z.as_chunks_mut::<G>().0,
                    );
                    for g in 0..groups {
                        let [bx, by, bz] = b[g];
                        (xs[g], ys[g], zs[g]) =
                            (bytemuck::cast(bx), bytemuck::cast(by), bytemuck::cast(bz));
                    }
                    runs.push(Run { x: at, y: py, passed, b: lanes });
                }
            }
        }
        for i in 0..3 {
            row[i] += step_y[i];
        }
    }
    (covered_count, passed_count)
}

/// The depth test of eight lanes, as [`super::depth_test`].
struct Depth {
    simd: V3,
    z: [__m256; 3],
}

impl Depth {
    #[inline(always)]
    fn new(simd: V3, z: Vec3) -> Depth {
        let avx = simd.avx;
        Depth {
            simd,
            z: [avx._mm256_set1_ps(z.x), avx._mm256_set1_ps(z.y), avx._mm256_set1_ps(z.z)],
        }
    }

    /// Tests the `covered` lanes (bit k for `depth[k]`; every covered lane is within `depth`),
    /// writes the depths that pass, and gives those lanes.
    #[inline(always)]
    fn test(&self, b: &[__m256; 3], covered: Mask, depth: &mut [f32]) -> Mask {
        let avx = self.simd.avx;
        let [zx, zy, zz] = self.z;
        // glam's dot: (x·x' + y·y') + z·z', then clamped to [0, 1] (NaN kept, as f32::clamp).
        let d = avx._mm256_add_ps(
            avx._mm256_add_ps(avx._mm256_mul_ps(b[0], zx), avx._mm256_mul_ps(b[1], zy)),
            avx._mm256_mul_ps(b[2], zz),
        );
        let d = avx
            ._mm256_min_ps(avx._mm256_set1_ps(1.0), avx._mm256_max_ps(avx._mm256_setzero_ps(), d));
        let lanes = lane_mask(self.simd, covered);
        // A tile's last few pixels go through a copy.
        let mut copy = [0.0; G];
        let n = depth.len().min(G);
        let stored = match depth.first_chunk_mut::<G>() {
            Some(stored) => stored,
            None => {
                copy[..n].copy_from_slice(depth);
                &mut copy
            }
        };
        let old: __m256 = bytemuck::cast(*stored);
        let pass = avx._mm256_and_ps(avx._mm256_cmp_ps::<_CMP_LT_OQ>(d, old), lanes);
        *stored = bytemuck::cast(avx._mm256_blendv_ps(old, d, pass));
        if n < G {
            depth.copy_from_slice(&copy[..n]);
        }
        avx._mm256_movemask_ps(pass) as Mask
    }
}

/// Where a run's fragments go once they passed (made once per triangle, on the stack: its
/// size does not matter).
#[allow(clippy::large_enum_variant)]
enum Shader {
    /// Their colours, made here ([`Simple::Flat`], [`Simple::Gouraud`]).
    Colors(Colors),
    /// To the fragment stage, as [`Run`]s ([`Simple::No`]).
    Staged,
}

impl Shader {
    #[inline(always)]
    fn new(simple: &Simple) -> Shader {
        let splat3 =
            |c: [f32; 3]| -> [__m256; 3] { bytemuck::cast([[c[0]; G], [c[1]; G], [c[2]; G]]) };
        match simple {
            Simple::Flat(c) => Shader::Colors(Colors::Flat(splat3(c.to_array()))),
            Simple::Gouraud(Gouraud { inv_w, colors }) => Shader::Colors(Colors::Gouraud {
                inv_w: splat3(*inv_w),
                colors: [
                    splat3(colors[0].to_array()),
                    splat3(colors[1].to_array()),
                    splat3(colors[2].to_array()),
                ],
            }),
            Simple::No => Shader::Staged,
        }
    }
}

/// Flat's or Gouraud's colours of eight lanes, channel by channel (in registers: its size
/// does not matter).
#[allow(clippy::large_enum_variant)]
enum Colors {
    Flat([__m256; 3]),
    Gouraud { inv_w: [__m256; 3], colors: [[__m256; 3]; 3] },
}

impl Colors {
    /// The colours of the eight lanes at screen-space barycentrics `b`, as red, green and blue
    /// registers: Gouraud's as [`super::shade`] makes them (perspective-correct barycentrics,
    /// `b.x·c₀ + b.y·c₁ + b.z·c₂`, each channel clamped with NaN taken as 0).
    #[inline(always)]
    fn lit(&self, simd: V3, b: &[__m256; 3]) -> [__m256; 3] {
        let avx = simd.avx;
        match self {
            Colors::Flat(c) => *c,
            Colors::Gouraud { inv_w, colors } => {
                // span::perspective.
                let mut w = [avx._mm256_setzero_ps(); 3];
                for i in 0..3 {
                    w[i] = avx._mm256_mul_ps(b[i], inv_w[i]);
                }
                let sum = avx._mm256_add_ps(avx._mm256_add_ps(w[0], w[1]), w[2]);
                let ok = avx._mm256_and_ps(
                    avx._mm256_cmp_ps::<_CMP_GT_OQ>(sum, avx._mm256_setzero_ps()),
                    avx._mm256_cmp_ps::<_CMP_LT_OQ>(sum, avx._mm256_set1_ps(f32::INFINITY)),
                );
                for i in 0..3 {
                    w[i] = avx._mm256_blendv_ps(b[i], avx._mm256_div_ps(w[i], sum), ok);
                }
                // span::interpolate, then the clamp of `super::channel`.
                let mut lit = [avx._mm256_setzero_ps(); 3];
                for c in 0..3 {
                    let v = avx._mm256_add_ps(
                        avx._mm256_add_ps(
                            avx._mm256_mul_ps(w[0], colors[0][c]),
                            avx._mm256_mul_ps(w[1], colors[1][c]),
                        ),
                        avx._mm256_mul_ps(w[2], colors[2][c]),
                    );
                    lit[c] = avx._mm256_and_ps(
                        avx._mm256_cmp_ps::<_CMP_GT_OQ>(v, avx._mm256_setzero_ps()),
                        avx._mm256_min_ps(v, avx._mm256_set1_ps(1.0)),
                    );
                }
                lit
            }
        }
    }
}

/// The `passed` lanes (bit k for `color[k]`, all within `color`) of the channel registers
/// `rgb` written into `color`; the others keep their colour.
#[inline(always)]
fn write(simd: V3, rgb: [__m256; 3], passed: Mask, color: &mut [Rgb]) {
    let avx = simd.avx;
    let new = interleave(simd, rgb);
    match color.first_chunk_mut::<G>() {
        Some(color) => {
            let color = bytemuck::cast_mut::<[Rgb; G], [[f32; G]; 3]>(color);
            if passed == GROUP {
                *color = bytemuck::cast(new);
            } else {
                let lanes = lane_mask(simd, passed);
                let lanes = interleave(simd, [lanes; 3]);
                for i in 0..3 {
                    let old: __m256 = bytemuck::cast(color[i]);
                    color[i] = bytemuck::cast(avx._mm256_blendv_ps(old, new[i], lanes[i]));
                }
            }
        }
        None => {
            // A tile's last few pixels, lane by lane.
            let new = bytemuck::cast::<[__m256; 3], [Rgb; G]>(new);
            for (k, c) in color.iter_mut().enumerate() {
                if passed >> k & 1 != 0 {
                    *c = new[k];
                }
            }
        }
    }
}
