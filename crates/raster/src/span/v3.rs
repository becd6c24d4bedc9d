//! The course scene's case of a span written out in AVX2 registers (pulp's `V3`, checked at run
//! time; the workspace has no `unsafe`): every lane a certified triangle's ([`super::queue`]'s
//! one normal per triangle) and lit by [`super::light_lanes_plain`] (no attenuation, no spot or
//! area light, no specular term). The compiler's copy of [`super::shade_fragments`] writes each
//! stage's sixteen lanes to memory and reads them back in the next; here each group of eight
//! lanes stays in registers from the perspective correction to the clamped colour.
//!
//! The same operations in the same order as [`super::fragments`], [`super::directions`] and
//! [`super::light_lanes_plain`], lane for lane: no fused multiply-add, IEEE division and square
//! root, compares that are false on NaN where Rust's are. So the same bits;
//! `the_registers_are_the_compilers_span_bit_for_bit` checks them against the compiler's copy.
//! Where a lane needs more — a weight the certified normal does not cover, a light L that
//! [`super::units64`] cannot take by its shortcut — nothing is written and the caller takes the
//! compiler's copy for the whole span.

use std::arch::x86_64::{__m256, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LT_OQ};

use cg_core::Rgb;
use cg_core::light::LightCounts;
use cg_core::math::DIRECT_UNIT_MIN;
use pulp::x86::V3;

use super::{Gathered, LANES, Stage, V3 as Lanes3};
use crate::simd::interleave;

/// Lanes in a group: one AVX register of f32.
const G: usize = 8;
/// Groups in a span.
const GROUPS: usize = LANES / G;

/// Group `h` of a lane array, as a register.
macro_rules! load {
    ($lanes:expr, $h:expr) => {
        bytemuck::cast::<[f32; G], __m256>($lanes.as_chunks::<G>().0[$h])
    };
}

/// Channel `c` (x, y, z) of sixteen 3-vectors.
#[inline(always)]
fn channel(v: &Lanes3, c: usize) -> &[f32; LANES] {
    match c {
        0 => &v.x,
        1 => &v.y,
        _ => &v.z,
    }
}

/// A span for [`Plain::shade`]: [`super::shade_fragments`]'s first `len` lanes at screen-space
/// barycentrics `screen` (their triangles' attributes `g`), where the stage's lights are plain
/// and its material has no specular term. The perspective-correct barycentrics go into `b`, the
/// clamped colours into `aos` as `Rgb`s where it is given (a whole span, `len` = [`LANES`]) or
/// else into `lit`, the light model's counts into `counts`.
pub(super) struct Plain<'a, 'b, 'c> {
    pub(super) stage: &'a Stage<'c>,
    pub(super) screen: &'a Lanes3,
    pub(super) g: &'a Gathered,
    pub(super) len: usize,
    pub(super) b: &'b mut Lanes3,
    pub(super) lit: &'b mut Lanes3,
    pub(super) aos: Option<&'b mut [Rgb; LANES]>,
    pub(super) counts: &'b mut LightCounts,
}

impl Plain<'_, '_, '_> {
    /// Lights the span in pulp's AVX2 context (not through a closure: a closure's call is not
    /// always inlined there, and the intrinsics in it would then be calls). `false`, with
    /// nothing written, where a lane needs the compiler's copy.
    #[inline(always)]
    pub(super) fn shade(self, simd: V3) -> bool {
        struct Call<'a, 'b, 'c>(V3, Plain<'a, 'b, 'c>);
        impl pulp::NullaryFnOnce for Call<'_, '_, '_> {
            type Output = bool;
            #[inline(always)]
            fn call(self) -> bool {
                shade_plain(self.0, self.1)
            }
        }
        simd.vectorize(Call(simd, self))
    }
}

/// [`Plain::shade`] in the AVX2 context.
#[inline(always)]
fn shade_plain(simd: V3, plain: Plain<'_, '_, '_>) -> bool {
    let Plain { stage, screen, g, len, b, lit, aos, counts } = plain;
    // No closure here calls an intrinsic: a closure is a function of its own, compiled without
    // AVX, so the intrinsics in it would not be inlined.
    let avx = simd.avx;
    let Stage { lights, material, colored } = *stage;
    let (zero, one, infinity) =
        (avx._mm256_setzero_ps(), avx._mm256_set1_ps(1.0), avx._mm256_set1_ps(f32::INFINITY));
    let (zero_d, min_d, infinity_d, one_d) = (
        avx._mm256_setzero_pd(),
        avx._mm256_set1_pd(DIRECT_UNIT_MIN),
        avx._mm256_set1_pd(f64::INFINITY),
        avx._mm256_set1_pd(1.0),
    );
    let mut certified: u32 = 0;
    for i in 0..LANES {
        certified |= u32::from(g.certified[i]) << i;
    }
    let opengl = !lights.lecture;
    // Each stage for both groups before the next: two independent chains for the core to
    // overlap (the square roots' and divisions' latency bounds a span, not their count).
    // `perspective`.
    let mut w = [[zero; 3]; GROUPS];
    for h in 0..GROUPS {
        let s = [load!(screen.x, h), load!(screen.y, h), load!(screen.z, h)];
        for k in 0..3 {
            w[h][k] = avx._mm256_mul_ps(s[k], load!(g.inv_w[k], h));
        }
        let sum = avx._mm256_add_ps(avx._mm256_add_ps(w[h][0], w[h][1]), w[h][2]);
        let ok = avx._mm256_and_ps(
            avx._mm256_cmp_ps::<_CMP_GT_OQ>(sum, zero),
            avx._mm256_cmp_ps::<_CMP_LT_OQ>(sum, infinity),
        );
        for k in 0..3 {
            w[h][k] = avx._mm256_blendv_ps(s[k], avx._mm256_div_ps(w[h][k], sum), ok);
        }
    }
    // `fragments`' test for the certified normal: weights ≥ 0, not all zero; a lane past
    // `len` counts as passing it.
    for h in 0..GROUPS {
        let w = &w[h];
        let non_negative = avx._mm256_and_ps(
            avx._mm256_and_ps(
                avx._mm256_cmp_ps::<_CMP_GE_OQ>(w[0], zero),
                avx._mm256_cmp_ps::<_CMP_GE_OQ>(w[1], zero),
            ),
            avx._mm256_cmp_ps::<_CMP_GE_OQ>(w[2], zero),
        );
        let positive = avx._mm256_or_ps(
            avx._mm256_or_ps(
                avx._mm256_cmp_ps::<_CMP_GT_OQ>(w[0], zero),
                avx._mm256_cmp_ps::<_CMP_GT_OQ>(w[1], zero),
            ),
            avx._mm256_cmp_ps::<_CMP_GT_OQ>(w[2], zero),
        );
        let weights = avx._mm256_movemask_ps(avx._mm256_and_ps(non_negative, positive)) as u32;
        let group = (certified >> (G * h)) & 0xff;
        let past = if len >= G * (h + 1) { 0 } else { (0xff << len.saturating_sub(G * h)) & 0xff };
        if (group & weights) | past != 0xff {
            return false;
        }
    }
    // `interpolate`: the position, and k_a = k_d = the colour where the points have their own
    // (`reflectances`), else the material's.
    let mut p = [[zero; 3]; GROUPS];
    let (mut ka, mut kd) = ([[zero; 3]; GROUPS], [[zero; 3]; GROUPS]);
    let (material_ka, material_kd) = (material.ka.to_array(), material.kd.to_array());
    for h in 0..GROUPS {
        for c in 0..3 {
            p[h][c] = avx._mm256_add_ps(
                avx._mm256_add_ps(
                    avx._mm256_mul_ps(w[h][0], load!(channel(&g.p[0], c), h)),
                    avx._mm256_mul_ps(w[h][1], load!(channel(&g.p[1], c), h)),
                ),
                avx._mm256_mul_ps(w[h][2], load!(channel(&g.p[2], c), h)),
            );
            if colored {
                ka[h][c] = avx._mm256_add_ps(
                    avx._mm256_add_ps(
                        avx._mm256_mul_ps(w[h][0], load!(channel(&g.color[0], c), h)),
                        avx._mm256_mul_ps(w[h][1], load!(channel(&g.color[1], c), h)),
                    ),
                    avx._mm256_mul_ps(w[h][2], load!(channel(&g.color[2], c), h)),
                );
                kd[h][c] = ka[h][c];
            } else {
                ka[h][c] = avx._mm256_set1_ps(material_ka[c]);
                kd[h][c] = avx._mm256_set1_ps(material_kd[c]);
            }
        }
    }
    let mut n = [[zero; 3]; GROUPS];
    for h in 0..GROUPS {
        n[h] = [load!(g.unit.x, h), load!(g.unit.y, h), load!(g.unit.z, h)];
    }
    // `light_lanes_plain`.
    let global = lights.ambient.to_array();
    let mut ambient = [[zero; 3]; GROUPS];
    let mut diffuse = [[zero; 3]; GROUPS];
    for h in 0..GROUPS {
        for c in 0..3 {
            ambient[h][c] = avx._mm256_mul_ps(avx._mm256_set1_ps(global[c]), ka[h][c]);
        }
    }
    for span_light in &lights.lights {
        let light = &span_light.light;
        // `SpanLight::to_light`; L = N where the light has no direction from the point.
        let mut l = n;
        match (span_light.directional, span_light.position) {
            (Some((dl, _)), _) => {
                if !dl.is_nan() {
                    let dl = dl.to_array();
                    for h in 0..GROUPS {
                        for c in 0..3 {
                            l[h][c] = avx._mm256_set1_ps(dl[c]);
                        }
                    }
                }
            }
            (_, Some(to)) => {
                // `directions`, four lanes of f64 at a time: the four quarters' chains side by
                // side.
                let to = to.to_array();
                let mut v = [[zero_d; 3]; 2 * GROUPS];
                let mut squared = [zero_d; 2 * GROUPS];
                for q in 0..2 * GROUPS {
                    let (h, upper) = (q / 2, q % 2 == 1);
                    for c in 0..3 {
                        let part = if upper {
                            avx._mm256_extractf128_ps::<1>(p[h][c])
                        } else {
                            avx._mm256_castps256_ps128(p[h][c])
                        };
                        v[q][c] =
                            avx._mm256_sub_pd(avx._mm256_set1_pd(to[c]), avx._mm256_cvtps_pd(part));
                    }
                    squared[q] = avx._mm256_add_pd(
                        avx._mm256_add_pd(
                            avx._mm256_mul_pd(v[q][0], v[q][0]),
                            avx._mm256_mul_pd(v[q][1], v[q][1]),
                        ),
                        avx._mm256_mul_pd(v[q][2], v[q][2]),
                    );
                }
                let mut valid = 0;
                for q in 0..2 * GROUPS {
                    let ok = avx._mm256_and_pd(
                        avx._mm256_cmp_pd::<_CMP_GE_OQ>(squared[q], min_d),
                        avx._mm256_cmp_pd::<_CMP_LT_OQ>(squared[q], infinity_d),
                    );
                    valid |= avx._mm256_movemask_pd(ok) << (4 * q);
                }
                if valid != (1 << LANES) - 1 {
                    return false;
                }
                let mut inverse = [zero_d; 2 * GROUPS];
                for q in 0..2 * GROUPS {
                    inverse[q] = avx._mm256_sqrt_pd(squared[q]);
                }
                for q in 0..2 * GROUPS {
                    inverse[q] = avx._mm256_div_pd(one_d, inverse[q]);
                }
                for h in 0..GROUPS {
                    for c in 0..3 {
                        let low =
                            avx._mm256_cvtpd_ps(avx._mm256_mul_pd(v[2 * h][c], inverse[2 * h]));
                        let high = avx._mm256_cvtpd_ps(
                            avx._mm256_mul_pd(v[2 * h + 1][c], inverse[2 * h + 1]),
                        );
                        l[h][c] = avx._mm256_set_m128(high, low);
                    }
                }
            }
            (None, None) => {}
        }
        let (ca, cd) = (light.ambient.to_array(), light.diffuse.to_array());
        for h in 0..GROUPS {
            if opengl {
                for c in 0..3 {
                    ambient[h][c] = avx._mm256_add_ps(
                        ambient[h][c],
                        avx._mm256_mul_ps(avx._mm256_set1_ps(ca[c]), ka[h][c]),
                    );
                }
            }
            // `dot`, then `positive_part`, then `add_term` with the scale 1.
            let (n, l) = (&n[h], &l[h]);
            let dot = avx._mm256_add_ps(
                avx._mm256_add_ps(avx._mm256_mul_ps(n[0], l[0]), avx._mm256_mul_ps(n[1], l[1])),
                avx._mm256_mul_ps(n[2], l[2]),
            );
            let f = avx._mm256_and_ps(avx._mm256_cmp_ps::<_CMP_GT_OQ>(dot, zero), dot);
            for c in 0..3 {
                let term = avx._mm256_mul_ps(avx._mm256_set1_ps(cd[c]), kd[h][c]);
                diffuse[h][c] = avx._mm256_add_ps(diffuse[h][c], avx._mm256_mul_ps(term, f));
            }
        }
    }
    // `e + ambient + diffuse + 0.0`, clamped as `clamp_channel`: into `aos` as interleaved
    // colours where it is given, else into `lit`.
    let e = material.emission.to_array();
    let mut aos = aos.map(bytemuck::cast_mut::<[Rgb; LANES], [[[f32; G]; 3]; GROUPS]>);
    for h in 0..GROUPS {
        let mut rgb = [zero; 3];
        for c in 0..3 {
            let v = avx._mm256_add_ps(
                avx._mm256_add_ps(
                    avx._mm256_add_ps(avx._mm256_set1_ps(e[c]), ambient[h][c]),
                    diffuse[h][c],
                ),
                zero,
            );
            rgb[c] = avx
                ._mm256_and_ps(avx._mm256_cmp_ps::<_CMP_GT_OQ>(v, zero), avx._mm256_min_ps(v, one));
        }
        match &mut aos {
            Some(aos) => aos[h] = bytemuck::cast(interleave(simd, rgb)),
            None => {
                for (lanes, c) in [(&mut lit.x, 0), (&mut lit.y, 1), (&mut lit.z, 2)] {
                    lanes.as_chunks_mut::<G>().0[h] = bytemuck::cast(rgb[c]);
                }
            }
        }
        for (lanes, c) in [(&mut b.x, 0), (&mut b.y, 1), (&mut b.z, 2)] {
            lanes.as_chunks_mut::<G>().0[h] = bytemuck::cast(w[h][c]);
        }
    }
    let lanes = len as u64;
    counts.evaluations += lanes;
    for _ in &lights.lights {
        counts.lights += lanes;
        counts.visibility_queries += lanes;
        counts.diffuse += lanes;
    }
    true
}

#[cfg(test)]
mod tests {
    use cg_core::Rgb;
    use cg_core::glam::Vec3;
    use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular};

    use super::super::tests::Cases;
    use super::super::{Points, SpanLights, certified, clamp_channel, fragments, light};
    use super::*;

    fn bits(v: &Lanes3, len: usize) -> Vec<[u32; 3]> {
        (0..len).map(|i| v.get(i).to_array().map(f32::to_bits)).collect()
    }

    /// The registers against the compiler's `fragments`, `light` and clamp on random spans of
    /// certified triangles, in both light models, with and without the points' own colours, at
    /// 16, 5 and 1 lanes; and refused, with nothing written, where a lane needs more: a weight
    /// below zero, a triangle without a certified normal, a point on a light.
    #[test]
    fn the_registers_are_the_compilers_span_bit_for_bit() {
        let Some(simd) = V3::try_new() else { return };
        let on_light = Vec3::new(0.25, 2.0, -0.75);
        let light_at = |kind| Light {
            kind,
            ambient: Rgb::new(0.1, 0.2, 0.05),
            diffuse: Rgb::new(0.9, 0.7, 0.8),
            specular: Rgb::ONE,
            attenuation: Attenuation::default(),
        };
        let lights = [
            light_at(LightKind::Directional { to_light: Vec3::new(1.0, 1.0, 0.5) }),
            light_at(LightKind::Point { position: on_light }),
            light_at(LightKind::Point { position: Vec3::new(-3.0, 1.0, 2.0) }),
        ];
        let material = Material {
            ka: Rgb::new(0.3, 0.2, 0.1),
            kd: Rgb::new(0.6, 0.5, 0.4),
            ks: Rgb::ZERO,
            emission: Rgb::new(0.01, 0.02, 0.03),
            ..Material::default()
        };
        let (eye, backward) = (Vec3::new(0.5, 0.25, 8.0), Vec3::Z);
        let mut cases = Cases(0x9e37_79b9_7f4a_7c15);
        let (mut taken, mut refused) = (0, 0);
        for model in [
            LightModel::Lecture { specular: Specular::Phong, local_viewer: false },
            LightModel::OpenGl { local_viewer: true },
        ] {
            let spans = SpanLights::new(model, Rgb::splat(0.1), &lights, eye, backward);
            assert!(spans.plain, "{model:?}: plain lights");
            for colored in [false, true] {
                let stage = Stage { lights: &spans, material: &material, colored };
                for len in [LANES, 5, 1] {
                    for round in 0..60 {
                        let mut g = Gathered::default();
                        let mut normals = [Lanes3::default(); 3];
                        for i in 0..LANES {
                            let n = cases.vec() * 3.0;
                            let unit = certified(n);
                            for k in 0..3 {
                                g.inv_w[k][i] = (cases.next() + 1.0) + 0.1;
                                g.p[k].set(i, cases.vec() * 3.0);
                                normals[k].set(i, n);
                                g.color[k].set(i, cases.vec().abs());
                            }
                            g.unit.set(i, unit.unwrap_or_default());
                            g.certified[i] = unit.is_some();
                        }
                        let mut screen = Lanes3::default();
                        for i in 0..LANES {
                            screen.set(i, cases.vec().abs() + Vec3::splat(0.01));
                        }
                        // What must be refused.
                        let negative = round % 7 == 0;
                        if negative {
                            screen.set(3, Vec3::new(-0.2, 0.6, 0.6));
                        }
                        let uncertified = round % 5 == 0;
                        if uncertified {
                            g.certified[2] = false;
                        }
                        let lit_from_on = round % 11 == 0;
                        if lit_from_on {
                            // Lane 0's point exactly on the second light: no L there.
                            screen.set(0, Vec3::X);
                            for k in 0..3 {
                                g.p[k].set(0, on_light);
                            }
                        }
                        let must_refuse =
                            (negative && 3 < len) || (uncertified && 2 < len) || lit_from_on;

                        // The compiler's copy.
                        let mut points = Points { len, ..Points::default() };
                        let mut expected_b = Lanes3::default();
                        let mut corners = |c: &mut [Lanes3; 3]| *c = normals;
                        let keep = fragments(
                            &screen,
                            &g,
                            colored,
                            &mut expected_b,
                            &mut points,
                            &mut corners,
                        );
                        for i in 0..len {
                            if !keep[i] {
                                points.n.set(i, Vec3::Z);
                            }
                        }
                        let (mut expected, mut expected_counts) =
                            (Lanes3::default(), LightCounts::default());
                        light(&stage, &points, &mut expected, &mut expected_counts);
                        for channel in [&mut expected.x, &mut expected.y, &mut expected.z] {
                            channel.iter_mut().for_each(|x| *x = clamp_channel(*x));
                        }

                        let (mut b, mut lit, mut counts) =
                            (Lanes3::default(), Lanes3::default(), LightCounts::default());
                        let took = Plain {
                            stage: &stage,
                            screen: &screen,
                            g: &g,
                            len,
                            b: &mut b,
                            lit: &mut lit,
                            aos: None,
                            counts: &mut counts,
                        }
                        .shade(simd);
                        // A whole span, its colours interleaved.
                        let mut aos = [Rgb::NAN; LANES];
                        let (mut b_aos, mut unused) = (Lanes3::default(), Lanes3::default());
                        let took_aos = len == LANES
                            && Plain {
                                stage: &stage,
                                screen: &screen,
                                g: &g,
                                len,
                                b: &mut b_aos,
                                lit: &mut unused,
                                aos: Some(&mut aos),
                                counts: &mut LightCounts::default(),
                            }
                            .shade(simd);
                        let case = format!("{model:?}, colored {colored}, {len} lanes, {round}");
                        if !took {
                            refused += 1;
                            assert!(must_refuse, "{case}: refused");
                            assert_eq!(bits(&lit, LANES), bits(&Lanes3::default(), LANES));
                            assert_eq!(counts, LightCounts::default(), "{case}: no counts");
                            continue;
                        }
                        taken += 1;
                        assert!(!must_refuse, "{case}: taken");
                        assert_eq!(bits(&b, len), bits(&expected_b, len), "{case}: b");
                        assert_eq!(bits(&lit, len), bits(&expected, len), "{case}: colours");
                        assert_eq!(took_aos, len == LANES, "{case}: interleaved");
                        if took_aos {
                            let aos: Vec<_> =
                                aos.iter().map(|c| c.to_array().map(f32::to_bits)).collect();
                            assert_eq!(aos, bits(&expected, len), "{case}: interleaved colours");
                            assert_eq!(bits(&unused, LANES), bits(&Lanes3::default(), LANES));
                        }
                        assert_eq!(counts, expected_counts, "{case}: the counts");
                    }
                }
            }
        }
        assert!(taken > 300 && refused > 80, "{taken} taken, {refused} refused");
    }
}
