//! What the AVX2 kernels (`pipeline/cover/v3.rs`, `span/v3.rs`) share: eight lanes' colours
//! interleaved into `Rgb`s, and a bit mask as lanes.

use std::arch::x86_64::__m256;

use pulp::x86::V3;

/// Eight lanes' red, green and blue registers as eight interleaved `Rgb`s, in three registers
/// (`r₀g₀b₀r₁g₁b₁r₂g₂`, `b₂r₃g₃b₃r₄g₄b₄r₅`, `g₅b₅r₆g₆b₆r₇g₇b₇`): within each 128-bit half the
/// three shuffles make `r₀g₀b₀r₁`, `g₁b₁r₂g₂` and `b₂r₃g₃b₃` (and the same from lanes 4–7), which
/// the half swaps put in order.
#[inline(always)]
pub(crate) fn interleave(simd: V3, [r, g, b]: [__m256; 3]) -> [__m256; 3] {
    let avx = simd.avx;
    let r0r2g0g2 = avx._mm256_shuffle_ps::<0x88>(r, g);
    let g1g3b1b3 = avx._mm256_shuffle_ps::<0xdd>(g, b);
    let b0b2r1r3 = avx._mm256_shuffle_ps::<0xd8>(b, r);
    let a = avx._mm256_shuffle_ps::<0x88>(r0r2g0g2, b0b2r1r3);
    let m = avx._mm256_shuffle_ps::<0xd8>(g1g3b1b3, r0r2g0g2);
    let c = avx._mm256_shuffle_ps::<0xdd>(b0b2r1r3, g1g3b1b3);
    [
        avx._mm256_permute2f128_ps::<0x20>(a, m),
        avx._mm256_permute2f128_ps::<0x30>(c, a),
        avx._mm256_permute2f128_ps::<0x31>(m, c),
    ]
}

/// Lane k all ones where bit k of `bits` is set, zero elsewhere (eight lanes).
#[inline(always)]
pub(crate) fn lane_mask(simd: V3, bits: u32) -> __m256 {
    let avx = simd.avx;
    let each = avx._mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
    let set = simd.avx2._mm256_and_si256(avx._mm256_set1_epi32(bits as i32), each);
    avx._mm256_castsi256_ps(simd.avx2._mm256_cmpeq_epi32(set, each))
}

#[cfg(test)]
mod tests {
    use cg_core::Rgb;

    use super::*;

    #[test]
    fn interleave_puts_each_lanes_channels_together() {
        let Some(simd) = V3::try_new() else { return };
        let channel = |c: f32| -> __m256 {
            bytemuck::cast(std::array::from_fn::<f32, 8, _>(|k| c * 10.0 + k as f32))
        };
        let got =
            bytemuck::cast::<[__m256; 3], [Rgb; 8]>(interleave(simd, [0.0, 1.0, 2.0].map(channel)));
        let expected: [Rgb; 8] =
            std::array::from_fn(|k| Rgb::new(k as f32, 10.0 + k as f32, 20.0 + k as f32));
        assert_eq!(got, expected);
    }

    #[test]
    fn a_lane_mask_has_the_bits_lanes() {
        let Some(simd) = V3::try_new() else { return };
        for bits in [0, 1, 0x80, 0b1010_0110, 0xff] {
            let lanes = bytemuck::cast::<__m256, [u32; 8]>(lane_mask(simd, bits));
            let expected: [u32; 8] =
                std::array::from_fn(|k| if bits >> k & 1 != 0 { u32::MAX } else { 0 });
            assert_eq!(lanes, expected, "{bits:#b}");
        }
    }
}
