//! Normalisation: exact (f32 `v / |v|`), the kit's [`cg_core::math::try_normalize`], and the
//! bit-trick reciprocal square root with and without one Newton step.

use std::hint::black_box;

use cg_core::glam::{DVec3, Vec3};
use cg_core::math::try_normalize;

use crate::measure::{Rng, median_time};
use crate::{BenchError, Column, Config, Experiment, Row};

/// The bit-trick approximation of `1/√x` (the "magic constant" 0x5f3759df): a guess from the
/// float's bits, with no Newton step. About 3.4 % relative error.
#[must_use]
#[inline]
pub fn rsqrt_bits(x: f32) -> f32 {
    f32::from_bits(0x5f37_59df_u32.wrapping_sub(x.to_bits() >> 1))
}

/// [`rsqrt_bits`] refined by one Newton step `y·(1.5 − ½x·y²)`: about 0.18 % relative error.
#[must_use]
#[inline]
pub fn rsqrt_newton(x: f32) -> f32 {
    let y = rsqrt_bits(x);
    y * (1.5 - 0.5 * x * y * y)
}

/// A way of normalising a vector.
type Normalise = fn(Vec3) -> Vec3;

const METHODS: [(&str, Normalise); 4] = [
    ("exact f32 (v/|v|)", |v| v / v.length()),
    ("try_normalize (kit)", |v| try_normalize(v).unwrap_or(Vec3::ZERO)),
    ("rsqrt bits + Newton", |v| v * rsqrt_newton(v.length_squared())),
    ("rsqrt bits", |v| v * rsqrt_bits(v.length_squared())),
];

/// The Phong specular `max(R·V, 0)ⁿ` with `R = 2(N·L)N − L`, in f64 from the given (maybe not
/// unit) `n`.
fn phong(n: DVec3, l: DVec3, v: DVec3, exponent: f64) -> f64 {
    let r = 2.0 * n.dot(l) * n - l;
    r.dot(v).max(0.0).powf(exponent)
}

/// Runs the experiment.
///
/// # Errors
/// Never.
pub fn run(config: &Config) -> Result<Experiment, BenchError> {
    let mut rng = Rng::new(0x5eed_0003);
    let count = config.scalar_samples.max(1);
    // Vectors of every direction with lengths 10⁻²…10² (interpolated normals, light vectors).
    let vectors: Vec<Vec3> = (0..count)
        .map(|_| (rng.direction() * 10f64.powf(rng.range(-2.0, 2.0))).as_vec3())
        .collect();
    // Highlight cases: V fixed, L random, N near the mirror direction (R·V within the highlight),
    // scaled by a length in [0.5, 2] as an interpolated normal before normalisation.
    let exponent = 100.0;
    let v = DVec3::Z;
    let highlight: Vec<(Vec3, DVec3)> = (0..count)
        .map(|_| {
            let l = (rng.direction() + DVec3::Z * 1.5).normalize();
            let h = (l + v).normalize();
            let tilt = rng.direction() * rng.range(0.0, 0.08);
            let n = (h + tilt).normalize() * rng.range(0.5, 2.0);
            (n.as_vec3(), l)
        })
        .collect();
    let mut rows = Vec::new();
    for (name, method) in METHODS {
        let mut max_rel = 0.0f64;
        for &x in &vectors {
            let n = method(x).as_dvec3();
            max_rel = max_rel.max((n.length() - 1.0).abs());
        }
        let mut max_highlight = 0.0f64;
        for &(n, l) in &highlight {
            let exact = phong(n.as_dvec3().normalize(), l, v, exponent);
            // The renderer clamps the final colour to [0, 1]; so does this.
            let got = phong(method(n).as_dvec3(), l, v, exponent).min(1.0);
            max_highlight = max_highlight.max((got - exact).abs());
        }
        let time = median_time(config.reps, || {
            let mut sum = Vec3::ZERO;
            for &x in &vectors {
                sum += method(black_box(x));
            }
            sum
        });
        rows.push(Row {
            key: vec![name.into()],
            values: vec![max_rel, max_highlight, time * 1e9 / count as f64],
        });
    }
    Ok(Experiment {
        id: "normalise",
        title: "正規化 / Normalisation",
        about: "ベクトルの正規化 4 通り。長さの最大相対誤差 | |n̂| − 1 | と、n = 100 の Phong ハイライト \
                (ピーク 1、1 で飽和) の最大絶対誤差。時間は 1 ベクトルあたり。\n\n\
                Four ways to normalise a vector: the maximum relative error of the length \
                (| |n̂| − 1 |, over lengths 10⁻²…10²) and the maximum absolute error of a Phong \
                highlight `(R·V)ⁿ` with n = 100 (peak 1, clamped to 1 as the renderers clamp the colour) when N is normalised that way (N near \
                the mirror direction, length 0.5…2 before normalisation). The bit trick is \
                `from_bits(0x5f3759df − bits(x)/2)`, written in this crate (no `unsafe`). Time \
                per vector in a loop the compiler may vectorise."
            .into(),
        keys: vec!["method"],
        columns: vec![
            Column::error("max relative error"),
            Column::error("highlight error at n = 100"),
            Column::value("time/vector [ns]"),
        ],
        rows,
        series_key: 0,
        time_column: 2,
        error_column: 1,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bit_trick_is_within_its_known_bounds() {
        for x in [0.01f32, 0.5, 1.0, 2.0, 3.0, 1e4] {
            let exact = 1.0 / x.sqrt();
            assert!((rsqrt_bits(x) / exact - 1.0).abs() < 0.035, "{x}");
            assert!((rsqrt_newton(x) / exact - 1.0).abs() < 0.0018, "{x}");
        }
    }
}
