//! Rasterize and depth-test a run of pixels of a row at a time (issue 18): the edge functions,
//! the screen-space barycentrics and the depths of eight ([`SIMPLE`]) or sixteen ([`STAGED`])
//! pixels as lanes the compiler vectorises, in an AVX2 copy chosen at run time. Flat and Gouraud
//! colours without a texture are written here, eight at a time; every other fragment is handed
//! back in runs of sixteen, which fill one of Phong's spans ([`crate::span::LANES`]).
//!
//! The edge functions are f64 lanes: integers, exact below 2⁵³, so each step is exact and each
//! conversion to f32 rounds once, as from the integer; a triangle reaching so far into the guard
//! band that they could exceed that takes i64 lanes. Narrow triangles (most of a
//! dense mesh's, 1–2 pixels wide) stay pixel by pixel in [`super::tile`]: a run would be mostly
//! empty lanes.
//!
//! The same pixels with the same numbers, in the same order, as pixel by pixel: each lane's edge
//! functions are the integers [`super::tile`]'s rasterizer steps through, converted to f32 with
//! one rounding, and each lane's depth, test, perspective correction and colour are its
//! arithmetic, operation for operation.

// Lane loops index several arrays by the lane, the structure-of-arrays idiom the vectoriser
// reads best.
#![allow(clippy::needless_range_loop)]

use cg_core::Rgb;
use cg_core::glam::Vec3;
use multiversion::multiversion;

use super::tile::{Target, edge_setup};
use super::{Edges, Rect};
use crate::span::{self, V3N};

#[cfg(target_arch = "x86_64")]
mod v3;

/// Which copy of the run loop a triangle takes: the same pixels and bits from each (the tests
/// run both on any machine).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kernels {
    /// The best this CPU has: on x86-64 with AVX2 and FMA, the one written in AVX2 registers
    /// (`cover/v3.rs`) for the f64 edge functions.
    Best,
    /// The compiler's (vectorised for AVX2 where the CPU has it): a CPU without AVX2, and the
    /// tests.
    #[cfg_attr(not(test), allow(dead_code))]
    Compiled,
}

/// Pixels of a row rasterized at once where the colour is made here (flat, Gouraud).
pub(super) const SIMPLE: usize = 8;
/// Pixels of a row rasterized at once where the fragments go to the fragment stage (Phong's
/// spans take [`crate::span::LANES`] at a time).
pub(super) const STAGED: usize = 16;
/// One bit per pixel of a run (at most 32).
pub(super) type Mask = u32;

/// A triangle whose colour needs neither a texture nor the light model per fragment.
pub(super) enum Simple {
    /// Flat: the face's colour, clamped.
    Flat(Rgb),
    /// Gouraud: the corners' colours, interpolated.
    Gouraud(Gouraud),
    /// Anything else: the fragment stage, fragment by fragment.
    No,
}

/// Gouraud's corners, for a run of fragments at once.
pub(super) struct Gouraud {
    inv_w: [f32; 3],
    colors: [Rgb; 3],
}

impl Gouraud {
    pub(super) fn new(inv_w: [f32; 3], colors: [Rgb; 3]) -> Gouraud {
        Gouraud { inv_w, colors }
    }
}

/// `W` pixels of a row, `x..x + W`, that passed the depth test (bit `k` of `passed` for pixel
/// `x + k`), with their screen-space barycentrics, waiting for their fragment stage.
#[derive(Clone, Copy, Debug)]
pub(super) struct Run<const W: usize> {
    pub(super) x: u32,
    pub(super) y: u32,
    pub(super) passed: Mask,
    pub(super) b: V3N<W>,
}

/// Rasterizes `edges` within `rect`, depth-tests every covered pixel against `target`'s depth
/// (window depth `z` at the corners, GL_LESS, written on a pass) and gives the fragments that
/// passed their colour: `simple`'s where it has one, otherwise as [`Run`]s pushed to `runs`.
/// Gives the covered and passed pixel counts.
///
/// The fill rule and the edge functions are [`super::tile`]'s rasterizer's: the pixels whose
/// biased edge functions are all ≥ 0, in rows from the top, left to right.
#[multiversion(targets("x86_64+avx2+fma"))]
#[allow(clippy::too_many_arguments)]
pub(super) fn cover<'t, const W: usize>(
    edges: &Edges,
    rect: Rect,
    z: [f32; 3],
    simple: &Simple,
    target: &mut Target<'t>,
    runs: &mut Vec<Run<W>>,
    #[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))] kernels: Kernels,
) -> (u64, u64) {
    let [bx0, by0, bx1, by1] = edges.bbox;
    let (x0, y0) = (bx0.max(rect.x0), by0.max(rect.y0));
    let (x1, y1) = (bx1.min(rect.x1.saturating_sub(1)), by1.min(rect.y1.saturating_sub(1)));
    if x0 > x1 || y0 > y1 {
        return (0, 0);
    }
    let z = Vec3::from(z);
    // The edge functions as f64 lanes: integers below 2⁵³ in magnitude, so every step is exact,
    // and the conversion to f32 rounds once, as from the integer. With every corner and every
    // pixel centre visited (the lanes past the bounding box too) within ±g of the origin, in
    // 1/256 pixel, |e| ≤ 2g·2g + 2g·2g + 1: below 2⁵² when g < 2²⁴ (65 536 pixels). A triangle
    // reaching farther into the guard band takes i64 lanes.
    let reach = edges.x.iter().chain(&edges.y).map(|&c| i64::from(c).abs()).max().unwrap_or(0);
    let visited = (i64::from(x1.max(y1)) + W as i64 + 1) * super::ONE;
    let area = [x0, y0, x1, y1];
    if reach.max(visited) >= 1 << 24 {
        return runs_of::<i64, W>(edges, area, z, simple, target, runs);
    }
    #[cfg(target_arch = "x86_64")]
    if kernels == Kernels::Best
        && let Some(simd) = pulp::x86::V3::try_new()
    {
        return v3::Runs { edges, area, z, simple, target, runs }.cover(simd);
    }
    runs_of::<f64, W>(edges, area, z, simple, target, runs)
}

/// An edge function's lane: the exact integer, as an f64 (below 2⁵³) or as itself.
trait Edge: Copy + std::ops::Add<Output = Self> + std::ops::Sub<Output = Self> {
    fn from_i64(e: i64) -> Self;
    fn non_negative(self) -> bool;
    /// `e as f32`, rounded once.
    fn to_f32(self) -> f32;
}

impl Edge for f64 {
    #[inline(always)]
    fn from_i64(e: i64) -> f64 {
        e as f64
    }
    #[inline(always)]
    fn non_negative(self) -> bool {
        self >= 0.0
    }
    #[inline(always)]
    fn to_f32(self) -> f32 {
        self as f32
    }
}

impl Edge for i64 {
    #[inline(always)]
    fn from_i64(e: i64) -> i64 {
        e
    }
    #[inline(always)]
    fn non_negative(self) -> bool {
        self >= 0
    }
    #[inline(always)]
    fn to_f32(self) -> f32 {
        self as f32
    }
}

/// [`cover`]'s rows over the pixels `[x0, y0, x1, y1]` (inclusive), `W` pixels at a time, with
/// the edge functions as `E` lanes.
#[inline(always)]
fn runs_of<E: Edge, const W: usize>(
    edges: &Edges,
    [x0, y0, x1, y1]: [u32; 4],
    z: Vec3,
    simple: &Simple,
    target: &mut Target<'_>,
    runs: &mut Vec<Run<W>>,
) -> (u64, u64) {
    let inv_area = 1.0 / edges.area2 as f32;
    let (row, step_x, step_y, bias) = edge_setup(edges, x0, y0);
    let lanes: [[E; W]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|k| E::from_i64(k as i64 * step_x[i])));
    let step_w = step_x.map(|s| E::from_i64(s * W as i64));
    let (step_y, bias) = (step_y.map(E::from_i64), bias.map(E::from_i64));
    let mut row = row.map(E::from_i64);
    let (mut covered_count, mut passed_count) = (0u64, 0u64);
    for py in y0..=y1 {
        let mut e0 = row;
        let mut x = x0;
        let r = (py - target.y0) as usize;
        while x <= x1 {
            let n = (x1 - x + 1).min(W as u32);
            let e: [[E; W]; 3] =
                std::array::from_fn(|i| std::array::from_fn(|k| e0[i] + lanes[i][k]));
            // `&`, not `&&`: every lane's test at once, without a branch per lane.
            let mut covered: Mask = 0;
            for k in 0..W {
                let inside = e[0][k].non_negative()
                    & e[1][k].non_negative()
                    & e[2][k].non_negative()
                    & ((k as u32) < n);
                covered |= Mask::from(inside) << k;
            }
            for i in 0..3 {
                e0[i] = e0[i] + step_w[i];
            }
            let at = x;
            x += W as u32;
            if covered == 0 {
                continue;
            }
            // Screen-space (linear) barycentrics from the unbiased edge functions: window depth
            // is linear on the screen.
            let mut b = V3N::<W>::default();
            for k in 0..W {
                b.x[k] = (e[0][k] - bias[0]).to_f32() * inv_area;
                b.y[k] = (e[1][k] - bias[1]).to_f32() * inv_area;
                b.z[k] = (e[2][k] - bias[2]).to_f32() * inv_area;
            }
            let column = (at - target.x0) as usize;
            let passed = depth_test(&b, z, covered, &mut target.depth[r][column..]);
            covered_count += u64::from(covered.count_ones());
            passed_count += u64::from(passed.count_ones());
            if passed != 0 {
                shade(simple, &b, passed, &mut target.color[r][column..], runs, at, py);
            }
        }
        for i in 0..3 {
            row[i] = row[i] + step_y[i];
        }
    }
    (covered_count, passed_count)
}

/// The colour of the `W` pixels from `color[0]` that `passed` holds: `simple`'s, or else a
/// [`Run`] for the fragment stage.
#[inline(always)]
fn shade<const W: usize>(
    simple: &Simple,
    b: &V3N<W>,
    passed: Mask,
    color: &mut [Rgb],
    runs: &mut Vec<Run<W>>,
    x: u32,
    y: u32,
) {
    #[inline(always)]
    fn write<const W: usize>(passed: Mask, color: &mut [Rgb], c: impl Fn(usize) -> Rgb) {
        // Every lane passed (W ≤ 32 bits of the mask).
        let all = Mask::MAX >> (Mask::BITS - W as u32);
        if passed == all && color.len() >= W {
            for k in 0..W {
                color[k] = c(k);
            }
        } else {
            // A select per lane, not a branch: at a triangle's edge which lanes passed is
            // not predictable.
            for k in 0..color.len().min(W) {
                let new = c(k);
                color[k] = if passed >> k & 1 != 0 { new } else { color[k] };
            }
        }
    }
    match simple {
        Simple::Flat(c) => write::<W>(passed, color, |_| *c),
        Simple::Gouraud(g) => {
            // As the fragment stage: perspective-correct barycentrics, then
            // `b.x·c₀ + b.y·c₁ + b.z·c₂`, clamped.
            // Spelled out: `array::map`'s closures are not always inlined into the AVX2 copy.
            let inv_w = [[g.inv_w[0]; W], [g.inv_w[1]; W], [g.inv_w[2]; W]];
            let colors = [
                V3N::<W>::splat(g.colors[0]),
                V3N::<W>::splat(g.colors[1]),
                V3N::<W>::splat(g.colors[2]),
            ];
            let mut weights = V3N::default();
            span::perspective(b, &inv_w, &mut weights);
            let mut lit = V3N::default();
            span::interpolate(&weights, &colors, &mut lit);
            for k in 0..W {
                lit.x[k] = channel(lit.x[k]);
                lit.y[k] = channel(lit.y[k]);
                lit.z[k] = channel(lit.z[k]);
            }
            write::<W>(passed, color, |k| lit.get(k));
        }
        Simple::No => runs.push(Run { x, y, passed, b: *b }),
    }
}

/// [`span::saturate`] of one channel.
#[inline(always)]
fn channel(x: f32) -> f32 {
    if x > 0.0 { x.min(1.0) } else { 0.0 }
}

/// The depth test (隠面消去, Z バッファ法) of `W` pixels of a row (`covered`: bit `k` for pixel
/// `k`, all within `depth`): GL_LESS against the buffer cleared to 1, each covered pixel's window
/// depth `b·z` clamped to `[0, 1]`; on a pass the depth is written. It runs before the fragment
/// stage (early depth test, as GPUs do when a fragment cannot be discarded): the same image,
/// without shading hidden fragments. Gives the pixels that passed.
#[inline(always)]
fn depth_test<const W: usize>(b: &V3N<W>, z: Vec3, covered: Mask, depth: &mut [f32]) -> Mask {
    #[inline(always)]
    fn lanes<const W: usize>(b: &V3N<W>, z: Vec3, covered: Mask, stored: &mut [f32; W]) -> Mask {
        let mut passed: Mask = 0;
        for k in 0..W {
            // glam's dot: (x·x' + y·y') + z·z'.
            let d = (b.x[k] * z.x + b.y[k] * z.y + b.z[k] * z.z).clamp(0.0, 1.0);
            // `&`, not `&&`: a select per lane, not a branch.
            let pass = (covered >> k & 1 != 0) & (d < stored[k]);
            stored[k] = if pass { d } else { stored[k] };
            passed |= Mask::from(pass) << k;
        }
        passed
    }
    match depth.first_chunk_mut::<W>() {
        // A whole run (all but a tile's last, short one): the buffer's own lanes.
        Some(stored) => lanes(b, z, covered, stored),
        None => {
            let n = depth.len();
            let mut stored = [0.0f32; W];
            stored[..n].copy_from_slice(depth);
            let passed = lanes(b, z, covered, &mut stored);
            depth.copy_from_slice(&stored[..n]);
            passed
        }
    }
}

#[cfg(test)]
mod tests {
    //! Runs of pixels against the pixel-by-pixel rasterizer, bit for bit: the same pixels in the
    //! same order, the same barycentrics, depths and Gouraud colours.

    use super::*;
    use crate::pipeline::primitive::{Cull, snap, triangle_setup};
    use crate::pipeline::tile::rasterize;
    use crate::pipeline::{GUARD_BAND_PIXELS, ScreenVertex};
    use crate::span::tests::Cases;

    /// In `[0, 1)`.
    fn unit(cases: &mut Cases) -> f32 {
        (cases.next() + 1.0) * 0.5
    }

    const WIDTH: u32 = 101;
    const HEIGHT: u32 = 77;

    /// What the pixel-by-pixel path gives a tile: each covered pixel's position and
    /// barycentrics, and whether it passed the depth test, in order, with the depths after.
    type Seen = (Vec<(u32, u32, [u32; 3], bool)>, Vec<u32>);

    fn buffers() -> (Vec<Vec<Rgb>>, Vec<Vec<f32>>) {
        (
            vec![vec![Rgb::ZERO; WIDTH as usize]; HEIGHT as usize],
            vec![vec![1.0; WIDTH as usize]; HEIGHT as usize],
        )
    }

    fn target<'a>(color: &'a mut [Vec<Rgb>], depth: &'a mut [Vec<f32>]) -> Target<'a> {
        Target {
            color: color.iter_mut().map(Vec::as_mut_slice).collect(),
            depth: depth.iter_mut().map(Vec::as_mut_slice).collect(),
            x0: 0,
            y0: 0,
        }
    }

    fn bits(b: Vec3) -> [u32; 3] {
        b.to_array().map(f32::to_bits)
    }

    #[test]
    fn runs_are_the_pixel_by_pixel_rasterizer_bit_for_bit() {
        let mut cases = Cases(0x853c_49e6_748f_ea9b);
        let rect = Rect { x0: 0, y0: 0, x1: WIDTH, y1: HEIGHT };
        let (mut wide, mut tested) = (0, 0);
        for round in 0..3000 {
            // Corners anywhere around the image, snapped to the pixel grid now and then (edges
            // through pixel centres), and far into the guard band now and then.
            let reach = match round % 10 {
                0 => GUARD_BAND_PIXELS * 0.9,
                1 => 3000.0,
                _ => 160.0,
            };
            let corner = |cases: &mut Cases| {
                let mut p = [cases.next(), cases.next()].map(|t| t * reach + 50.0);
                if round % 3 == 0 {
                    p = p.map(|v| v.round() + 0.5);
                }
                ScreenVertex { x: snap(p[0]), y: snap(p[1]), ..ScreenVertex::default() }
            };
            let s = [corner(&mut cases), corner(&mut cases), corner(&mut cases)];
            let Ok((edges, _)) = triangle_setup(s, Cull::None, WIDTH, HEIGHT) else { continue };
            let z = [unit(&mut cases), unit(&mut cases), unit(&mut cases)];
            let inv_w =
                [unit(&mut cases) + 0.1, unit(&mut cases) * 3.0 + 0.1, unit(&mut cases) + 0.5];
            let colors = [0, 1, 2]
                .map(|_| Rgb::new(unit(&mut cases), unit(&mut cases) * 2.0, -unit(&mut cases)));
            tested += 1;
            let reach = edges.x.iter().chain(&edges.y).map(|&c| i64::from(c).abs()).max();
            wide += usize::from(reach >= Some(1 << 24));

            // The pixel-by-pixel path, over a depth buffer already holding something.
            let (mut color, mut depth) = buffers();
            for (y, row) in depth.iter_mut().enumerate() {
                for (x, d) in row.iter_mut().enumerate() {
                    *d = ((x * 7 + y * 13) % 17) as f32 / 16.0;
                    // Colours the lanes that do not pass must keep.
                    color[y][x] = Rgb::new(x as f32, y as f32, -1.0);
                }
            }
            let before = depth.clone();
            let inv_area = 1.0 / edges.area2 as f32;
            let mut expected: Seen = (Vec::new(), Vec::new());
            let mut expected_color = color.clone();
            rasterize(&edges, rect, |x, y, e| {
                let b = Vec3::new(e[0] as f32, e[1] as f32, e[2] as f32) * inv_area;
                let d = b.dot(Vec3::from(z)).clamp(0.0, 1.0);
                let stored = &mut depth[y as usize][x as usize];
                let pass = d < *stored;
                if pass {
                    *stored = d;
                    // The fragment stage's Gouraud colour.
                    let weighted = b * Vec3::from(inv_w);
                    let sum = weighted.x + weighted.y + weighted.z;
                    let w = if sum > 0.0 && sum.is_finite() { weighted / sum } else { b };
                    let c = w.x * colors[0] + w.y * colors[1] + w.z * colors[2];
                    expected_color[y as usize][x as usize] = span::saturate(c);
                }
                expected.0.push((x, y, bits(b), pass));
            });
            expected.1 = depth.iter().flatten().map(|d| d.to_bits()).collect();

            let passed: Vec<_> = expected.0.iter().filter(|p| p.3).copied().collect();
            let covered = expected.0.len() as u64;
            let colors_bits = |c: &[Vec<Rgb>]| -> Vec<[u32; 3]> {
                c.iter().flatten().map(|c| c.to_array().map(f32::to_bits)).collect()
            };
            let flat = Rgb::new(0.25, 0.5, 0.75);
            let mut expected_flat = color.clone();
            for &(x, y, _, _) in &passed {
                expected_flat[y as usize][x as usize] = flat;
            }
            for kernels in [Kernels::Best, Kernels::Compiled] {
                let round = format!("round {round}, {kernels:?}");
                // Runs of sixteen, handed back.
                let (mut color16, mut depth16) = (color.clone(), before.clone());
                let mut runs = Vec::new();
                let counts = cover::<STAGED>(
                    &edges,
                    rect,
                    z,
                    &Simple::No,
                    &mut target(&mut color16, &mut depth16),
                    &mut runs,
                    kernels,
                );
                let mut got: Vec<(u32, u32, [u32; 3], bool)> = Vec::new();
                for run in &runs {
                    for k in (0..STAGED).filter(|k| run.passed >> k & 1 != 0) {
                        got.push((run.x + k as u32, run.y, bits(run.b.get(k)), true));
                    }
                }
                assert_eq!(got, passed, "{round}: the pixels that passed, in order");
                assert_eq!(counts, (covered, passed.len() as u64), "{round}: the counts");
                let depths: Vec<u32> = depth16.iter().flatten().map(|d| d.to_bits()).collect();
                assert_eq!(depths, expected.1, "{round}: the depth buffer");
                assert_eq!(colors_bits(&color16), colors_bits(&color), "{round}: no colour");

                // Runs of eight, Gouraud's and flat colours made here.
                for (simple, expected_color) in [
                    (Simple::Gouraud(Gouraud::new(inv_w, colors)), &expected_color),
                    (Simple::Flat(flat), &expected_flat),
                ] {
                    let (mut color8, mut depth8) = (color.clone(), before.clone());
                    let mut none = Vec::new();
                    let mut t = target(&mut color8, &mut depth8);
                    let counts =
                        cover::<SIMPLE>(&edges, rect, z, &simple, &mut t, &mut none, kernels);
                    assert_eq!(counts, (covered, passed.len() as u64), "{round}: the counts");
                    assert!(none.is_empty());
                    assert_eq!(
                        colors_bits(&color8),
                        colors_bits(expected_color),
                        "{round}: colours"
                    );
                    let depths: Vec<u32> = depth8.iter().flatten().map(|d| d.to_bits()).collect();
                    assert_eq!(depths, expected.1, "{round}: the depth buffer");
                }
            }
        }
        assert!(tested > 2000 && wide > 100, "{tested} triangles, {wide} through i64 lanes");
    }
}
