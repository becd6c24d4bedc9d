//! Seeded inputs for the checks, and how numbers are printed in their messages.
//!
//! The checks draw their random cases from fixed seeds (the same cases for every student and
//! every run), from SplitMix64 ([`VariantRng::from_seed`]); floats are made from the top 24 bits
//! of each draw, so every value is exact and the same on every machine.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_harness::VariantRng;
use cg_harness::text::Text;

/// A seeded source of check inputs.
pub(crate) struct Inputs(VariantRng);

impl Inputs {
    pub(crate) fn new(seed: u64) -> Inputs {
        Inputs(VariantRng::from_seed(seed))
    }

    /// Uniform in `[0, 1)`, a multiple of 2⁻²⁴.
    pub(crate) fn unit_interval(&mut self) -> f32 {
        (self.0.next_u64() >> 40) as f32 / (1u32 << 24) as f32
    }

    /// Uniform in `[lo, hi)`.
    pub(crate) fn range(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.unit_interval()
    }

    /// A uniformly distributed unit vector (rejection from the cube).
    pub(crate) fn unit_vector(&mut self) -> Vec3 {
        loop {
            let v = Vec3::new(self.range(-1.0, 1.0), self.range(-1.0, 1.0), self.range(-1.0, 1.0));
            let len2 = v.length_squared();
            if (0.01..=1.0).contains(&len2) {
                return v / len2.sqrt();
            }
        }
    }

    /// A colour with channels in `[lo, hi)`.
    pub(crate) fn color(&mut self, lo: f32, hi: f32) -> Rgb {
        Rgb::new(self.range(lo, hi), self.range(lo, hi), self.range(lo, hi))
    }

    /// A unit vector within about `spread` (radians, small) of the unit vector `around`.
    pub(crate) fn near(&mut self, around: Vec3, spread: f32) -> Vec3 {
        let v = around + spread * self.unit_vector() * self.unit_interval();
        v.normalize_or(around)
    }
}

/// A number with 4 decimals (NaN and infinities spelled out).
pub(crate) fn num(x: f32) -> String {
    cg_core::notation::fixed(x, 4)
}

/// A vector or colour as `(x, y, z)` with 4 decimals.
pub(crate) fn vec(v: Vec3) -> String {
    format!("({}, {}, {})", num(v.x), num(v.y), num(v.z))
}

/// An optional direction: the vector, or `None`.
pub(crate) fn opt(v: Option<Vec3>) -> String {
    v.map_or_else(|| "None".to_owned(), vec)
}

/// `name: values` in each language: a case's name in Japanese and English, its values (numbers
/// and symbols) shared.
pub(crate) fn case_at(name: &Text, values: &str) -> Text {
    Text::new(format!("{}: {values}", name.ja), format!("{}: {values}", name.en))
}

/// `ランダムな入力 3` / `random case 3`.
pub(crate) fn random_case(i: usize) -> Text {
    Text::new(format!("ランダムな入力 {i}"), format!("random case {i}"))
}

/// The largest per-component difference, NaN when either side has a NaN.
pub(crate) fn max_diff(a: Vec3, b: Vec3) -> f32 {
    let d = (a - b).abs();
    if d.is_nan() { f32::NAN } else { d.max_element() }
}

/// `|a − b| ≤ abs + rel·|b|` per component (never true with a NaN).
pub(crate) fn close(actual: Vec3, expected: Vec3, abs: f32, rel: f32) -> bool {
    let d = (actual - expected).abs();
    let limit = Vec3::splat(abs) + rel * expected.abs();
    d.cmple(limit).all() && actual.is_finite()
}

/// A scalar version of [`close`].
pub(crate) fn close1(actual: f32, expected: f32, abs: f32, rel: f32) -> bool {
    (actual - expected).abs() <= abs + rel * expected.abs() && actual.is_finite()
}
