//! Texture sampling at the hard coordinates of docs/numerics.md row 23: exactly 0 and 1, negative,
//! huge (1e6), non-finite — nearest and bilinear, repeat and clamp.
//!
//! Every texel of the test textures encodes its own position (`R = 40·x + 7`, `G = 60·y + 11`),
//! so the expected colour is computed here from the coordinate alone, in f64, with OpenGL's
//! texel-centre convention — never read back from the texture under test.

use cg_core::glam::{DVec4, Vec2, Vec4};
use cg_core::texture::{Filter, Sampler, TexEnv, Texture, TextureError, Wrap, wrap_coordinate};
use cg_testkit::{Inputs, assert_approx_eq};

/// `assert_approx_eq!` per channel: the test kit compares f32 vectors, the oracle here is f64.
#[track_caller]
fn assert_rgba(actual: Vec4, expected: DVec4, abs: f64, what: &str) {
    for i in 0..4 {
        assert_approx_eq!(
            f64::from(actual[i]),
            expected[i],
            abs = abs,
            "channel {i} of {actual} vs {expected}: {what}"
        );
    }
}

/// The texel a position encodes, as stored.
fn encoded(x: u32, y: u32) -> [u8; 4] {
    [(40 * x + 7) as u8, (60 * y + 11) as u8, 3, 255]
}

/// The same texel as RGBA in [0, 1], in f64.
fn encoded_f64(x: i64, y: i64) -> DVec4 {
    DVec4::new((40 * x + 7) as f64, (60 * y + 11) as f64, 3.0, 255.0) / 255.0
}

/// 5 × 3: odd, non-power-of-two sizes, where scaling a huge coordinate to texels loses bits.
fn texture() -> Texture {
    Texture::from_fn(5, 3, encoded).unwrap()
}

fn sampler(filter: Filter, wrap: Wrap) -> Sampler {
    Sampler { filter, wrap_u: wrap, wrap_v: wrap }
}

/// The exact fractional part of an f32 coordinate (exact in f64: the f32 has ≤ 24 significant bits).
fn frac(s: f32) -> f64 {
    let s = f64::from(s);
    s - s.floor()
}

/// The oracle's texel index under GL_NEAREST along a side of `n` texels.
fn nearest_oracle(s: f32, n: u32, wrap: Wrap) -> i64 {
    let n = f64::from(n);
    let x = match wrap {
        Wrap::Repeat => frac(s) * n,
        Wrap::Clamp => f64::from(s).clamp(0.0, 1.0) * n,
    };
    (x.floor() as i64).min(n as i64 - 1)
}

/// The oracle's GL_LINEAR neighbours and weight along a side of `n` texels.
fn linear_oracle(s: f32, n: u32, wrap: Wrap) -> (i64, i64, f64) {
    let r = match wrap {
        Wrap::Repeat => frac(s),
        Wrap::Clamp => f64::from(s).clamp(0.0, 1.0),
    };
    let u = r * f64::from(n) - 0.5;
    let i0 = u.floor();
    let n = i64::from(n);
    let place = |i: i64| match wrap {
        Wrap::Repeat => i.rem_euclid(n),
        Wrap::Clamp => i.clamp(0, n - 1),
    };
    (place(i0 as i64), place(i0 as i64 + 1), u - i0)
}

fn bilinear_oracle(uv: Vec2, w: u32, h: u32, wrap: Wrap) -> DVec4 {
    let (x0, x1, a) = linear_oracle(uv.x, w, wrap);
    let (y0, y1, b) = linear_oracle(uv.y, h, wrap);
    let bottom = encoded_f64(x0, y0) * (1.0 - a) + encoded_f64(x1, y0) * a;
    let top = encoded_f64(x0, y1) * (1.0 - a) + encoded_f64(x1, y1) * a;
    bottom * (1.0 - b) + top * b
}

fn as_u8(c: Vec4) -> [u8; 4] {
    (c * 255.0).round().to_array().map(|v| v as u8)
}

/// The nearest texel is ambiguous only when the exact `frac·n` lies within the f32 product's
/// rounding of a texel boundary; such coordinates are skipped (none of the fixed cases are).
fn near_boundary(s: f32, n: u32) -> bool {
    let x = frac(s) * f64::from(n);
    let d = (x - x.round()).abs();
    d > 0.0 && d < 1e-5
}

#[test]
fn row23_texture_new_checks_size_and_texel_count() {
    assert_eq!(Texture::new(0, 3, vec![]), Err(TextureError::ZeroSize { width: 0, height: 3 }));
    assert!(matches!(Texture::from_fn(2, 0, encoded), Err(TextureError::ZeroSize { .. })));
    assert_eq!(
        Texture::new(2, 2, vec![[0; 4]; 3]),
        Err(TextureError::TexelCount { width: 2, height: 2, expected: 4, got: 3 })
    );
    let t = texture();
    // Row 0 is the bottom row: texel (x, y) is stored at y·w + x.
    assert_eq!(t.texels[2 * 5 + 4], encoded(4, 2));
    assert_eq!(t.texel(4, 2), encoded(4, 2));
    assert_eq!(t.texel(0, 0), encoded(0, 0));
    assert!(
        !TextureError::ZeroSize { width: 0, height: 0 }
            .describe(cg_core::lang::Lang::Ja)
            .is_empty()
    );
}

#[test]
fn row23_coordinates_exactly_0_and_1_are_exact_at_the_edges() {
    let t = texture();
    let (w, h) = (5, 3);
    let first = Vec4::from_array(encoded(0, 0).map(f32::from)) / 255.0;
    let last = Vec4::from_array(encoded(w - 1, h - 1).map(f32::from)) / 255.0;
    for filter in [Filter::Nearest, Filter::Bilinear] {
        let clamp = sampler(filter, Wrap::Clamp);
        // Clamp-to-edge: 0 is the first texel, 1 the last one, exactly (no blend with a neighbour).
        assert_eq!(t.sample(Vec2::ZERO, clamp), first, "{filter:?} clamp at 0");
        assert_eq!(t.sample(Vec2::ONE, clamp), last, "{filter:?} clamp at 1");
        assert_eq!(t.sample(Vec2::splat(-0.0), clamp), first, "{filter:?} clamp at -0");
        // Repeat: 1 is the same point as 0.
        let repeat = sampler(filter, Wrap::Repeat);
        assert_eq!(t.sample(Vec2::ONE, repeat), t.sample(Vec2::ZERO, repeat), "{filter:?} 1 ≡ 0");
    }
    // Nearest + repeat at 0 (and 1) is the first texel; just below 1 is the last texel.
    let nearest = sampler(Filter::Nearest, Wrap::Repeat);
    assert_eq!(as_u8(t.sample(Vec2::ONE, nearest)), encoded(0, 0));
    let below_one = 1.0 - f32::EPSILON / 2.0;
    assert_eq!(as_u8(t.sample(Vec2::splat(below_one), nearest)), encoded(4, 2));
    // Bilinear + repeat at 0: the seam, halfway between the last and the first texel centres.
    let seam =
        (encoded_f64(4, 2) + encoded_f64(0, 2) + encoded_f64(4, 0) + encoded_f64(0, 0)) / 4.0;
    let got = t.sample(Vec2::ZERO, sampler(Filter::Bilinear, Wrap::Repeat));
    assert_rgba(got, seam, 1e-6, "bilinear repeat at the seam");
    // At texel centres bilinear returns the texel itself (weights exactly 0 or 1).
    for (x, y) in [(0, 0), (2, 1), (4, 2)] {
        let uv = Vec2::new((x as f32 + 0.5) / 5.0, (y as f32 + 0.5) / 3.0);
        for wrap in [Wrap::Repeat, Wrap::Clamp] {
            let c = t.sample(uv, sampler(Filter::Bilinear, wrap));
            assert_rgba(c, encoded_f64(x, y), 1e-6, &format!("centre of ({x}, {y})"));
        }
    }
}

#[test]
fn row23_wrap_coordinate_reduces_into_the_unit_interval() {
    // Repeat: always in [0, 1) — even where `s - floor(s)` rounds to 1 (s = -1e-9): the naive
    // fractional part returns 1.0 there, which would wrap onto the *first* texel instead of the last.
    assert_eq!(wrap_coordinate(-1e-9, Wrap::Repeat), 1.0 - f32::EPSILON / 2.0);
    assert_eq!(-1e-9_f32 - (-1e-9_f32).floor(), 1.0, "premise: the naive form reaches 1");
    for s in [0.0, 1.0, -1.0, -3.0, 1e6, 3e38, -0.0] {
        assert_eq!(wrap_coordinate(s, Wrap::Repeat), 0.0, "integer {s}");
    }
    assert_eq!(wrap_coordinate(1e6 + 0.25, Wrap::Repeat), 0.25);
    assert_eq!(wrap_coordinate(-0.25, Wrap::Repeat), 0.75);
    assert_eq!(wrap_coordinate(-1e6 - 0.25, Wrap::Repeat), 0.75);
    assert_eq!(wrap_coordinate(1.5, Wrap::Clamp), 1.0);
    assert_eq!(wrap_coordinate(-7.0, Wrap::Clamp), 0.0);
    assert_eq!(wrap_coordinate(0.3, Wrap::Clamp), 0.3);

    let mut rng = Inputs::seeded(23);
    for _ in 0..20_000 {
        let s = rng.log_uniform_f32(-12.0, 9.0);
        let r = wrap_coordinate(s, Wrap::Repeat);
        assert!((0.0..1.0).contains(&r), "repeat({s}) = {r}");
        // The reduction is exact (up to the one rounding described for -1 < s < 0): compare with
        // the f64 fractional part, tolerance one f32 ulp of 1.
        assert_approx_eq!(f64::from(r), frac(s), abs = f64::from(f32::EPSILON), "s = {s}");
        if s >= 0.0 || s <= -1.0 {
            assert_eq!(f64::from(r), frac(s), "exact for s = {s}");
        }
        assert_eq!(wrap_coordinate(s, Wrap::Clamp), s.clamp(0.0, 1.0));
    }
}

#[test]
fn row23_negative_coordinates_repeat_and_clamp() {
    let t = texture();
    let mut rng = Inputs::seeded(2323);
    for _ in 0..5_000 {
        let uv =
            Vec2::new(-rng.log_uniform_f32(-8.0, 3.0).abs(), -rng.log_uniform_f32(-8.0, 3.0).abs());
        // Clamp: every negative coordinate is the first row / column.
        let c = t.sample(uv, sampler(Filter::Nearest, Wrap::Clamp));
        assert_eq!(as_u8(c), encoded(0, 0), "clamp nearest at {uv}");
        let c = t.sample(uv, sampler(Filter::Bilinear, Wrap::Clamp));
        assert_rgba(c, encoded_f64(0, 0), 1e-6, &format!("clamp bilinear at {uv}"));
        // Repeat: the texel the oracle finds from the exact fractional part.
        if !(near_boundary(uv.x, 5) || near_boundary(uv.y, 3)) {
            let c = t.sample(uv, sampler(Filter::Nearest, Wrap::Repeat));
            let (x, y) =
                (nearest_oracle(uv.x, 5, Wrap::Repeat), nearest_oracle(uv.y, 3, Wrap::Repeat));
            assert_eq!(as_u8(c), encoded(x as u32, y as u32), "repeat nearest at {uv}");
        }
        // Bilinear: weight error ≤ n·2⁻²³ from the two f32 roundings of `s·n − ½` (plus 2⁻²⁴ from the
        // reduction of -1 < s < 0), times a texel difference ≤ 1, plus the lerps' roundings: < 1e-5.
        let c = t.sample(uv, sampler(Filter::Bilinear, Wrap::Repeat));
        assert_rgba(c, bilinear_oracle(uv, 5, 3, Wrap::Repeat), 1e-5, &format!("at {uv}"));
    }
}

#[test]
fn row23_huge_coordinates_sample_like_their_fractional_part() {
    let t = texture();
    // 1e6 + 0.25 is exact in f32 (ulp 0.0625 there) and samples exactly like 0.25.
    for filter in [Filter::Nearest, Filter::Bilinear] {
        let s = sampler(filter, Wrap::Repeat);
        assert_eq!(
            t.sample(Vec2::new(1e6 + 0.25, 1e6 + 0.5), s),
            t.sample(Vec2::new(0.25, 0.5), s),
            "{filter:?}"
        );
    }
    // Scaling before reducing fails here: (1e6 + 0.1875)·5 = 5000000.9375 rounds to 5000001 in
    // f32, which lands in texel 1 instead of texel 0 (0.1875·5 = 0.9375).
    let s = 1e6_f32 + 0.1875;
    assert_eq!(((s * 5.0).floor() as i64).rem_euclid(5), 1, "premise: the naive index is wrong");
    let c = t.sample(Vec2::new(s, 0.5), sampler(Filter::Nearest, Wrap::Repeat));
    assert_eq!(as_u8(c), encoded(0, 1));

    let mut rng = Inputs::seeded(2_300_023);
    for _ in 0..5_000 {
        // Offsets 1e4…1e7 with both signs, plus a fraction, rounded once to f32.
        let offset = |rng: &mut Inputs| rng.log_uniform(4.0, 7.0).round() + rng.uniform(0.0, 1.0);
        let uv = Vec2::new(offset(&mut rng) as f32, offset(&mut rng) as f32);
        if !(near_boundary(uv.x, 5) || near_boundary(uv.y, 3)) {
            let c = t.sample(uv, sampler(Filter::Nearest, Wrap::Repeat));
            let (x, y) =
                (nearest_oracle(uv.x, 5, Wrap::Repeat), nearest_oracle(uv.y, 3, Wrap::Repeat));
            assert_eq!(as_u8(c), encoded(x as u32, y as u32), "repeat nearest at {uv}");
        }
        // Same bound as above; scaling first would give weight errors up to 0.25 at 1e6·5.
        let c = t.sample(uv, sampler(Filter::Bilinear, Wrap::Repeat));
        assert_rgba(c, bilinear_oracle(uv, 5, 3, Wrap::Repeat), 1e-5, &format!("at {uv}"));
        // Clamp: positive huge is the last texel, negative huge the first.
        let c = t.sample(uv, sampler(Filter::Nearest, Wrap::Clamp));
        let expect = |s: f32, n: u32| if s > 0.0 { n - 1 } else { 0 };
        assert_eq!(as_u8(c), encoded(expect(uv.x, 5), expect(uv.y, 3)), "clamp at {uv}");
    }
}

#[test]
fn row23_in_range_coordinates_match_the_oracle() {
    let t = texture();
    let mut rng = Inputs::seeded(230);
    for _ in 0..5_000 {
        let uv = Vec2::new(rng.uniform_f32(0.0, 1.0), rng.uniform_f32(0.0, 1.0));
        for wrap in [Wrap::Repeat, Wrap::Clamp] {
            if !(near_boundary(uv.x, 5) || near_boundary(uv.y, 3)) {
                let c = t.sample(uv, sampler(Filter::Nearest, wrap));
                let (x, y) = (nearest_oracle(uv.x, 5, wrap), nearest_oracle(uv.y, 3, wrap));
                assert_eq!(as_u8(c), encoded(x as u32, y as u32), "{wrap:?} nearest at {uv}");
            }
            let c = t.sample(uv, sampler(Filter::Bilinear, wrap));
            assert_rgba(c, bilinear_oracle(uv, 5, 3, wrap), 1e-5, &format!("{wrap:?} at {uv}"));
        }
    }
    // Mixed wrap modes: u repeats, v clamps.
    let mixed = Sampler { filter: Filter::Nearest, wrap_u: Wrap::Repeat, wrap_v: Wrap::Clamp };
    assert_eq!(as_u8(t.sample(Vec2::new(1.1, 1.1), mixed)), encoded(0, 2));
    assert_eq!(TexEnv::default(), TexEnv::Modulate);
}

#[test]
fn row23_non_finite_coordinates_give_transparent_black() {
    let t = texture();
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        for filter in [Filter::Nearest, Filter::Bilinear] {
            for wrap in [Wrap::Repeat, Wrap::Clamp] {
                for uv in [Vec2::new(bad, 0.5), Vec2::new(0.5, bad)] {
                    assert_eq!(
                        t.sample(uv, sampler(filter, wrap)),
                        Vec4::ZERO,
                        "{uv} {filter:?} {wrap:?}"
                    );
                }
            }
        }
    }
    // A texture built by hand with no texels samples as transparent black instead of panicking.
    let broken = Texture { width: 4, height: 4, texels: vec![] };
    assert_eq!(broken.sample(Vec2::splat(0.5), Sampler::default()), Vec4::ZERO);
    let empty = Texture { width: 0, height: 0, texels: vec![] };
    assert_eq!(empty.sample(Vec2::splat(0.5), Sampler::default()), Vec4::ZERO);
}
