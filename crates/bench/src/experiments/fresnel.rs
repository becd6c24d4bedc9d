//! Fresnel reflectance: exact ([`fresnel_dielectric`]) against Schlick's approximation
//! ([`schlick`], which uses the cosine on the less dense side), and against Schlick with the
//! incident cosine on both sides (a common mistake: no total internal reflection), for glass,
//! outside (1 → 1.5) and inside (1.5 → 1).

use std::hint::black_box;

use cg_core::optics::{fresnel_dielectric, schlick};

use crate::measure::median_time;
use crate::{BenchError, Column, Config, Experiment, Row};

/// Schlick's formula with `cos θ_i` whichever side the light comes from: wrong inside a denser
/// medium (no total internal reflection; docs/numerics.md row 13). For comparison only.
#[must_use]
pub fn schlick_incident_cosine(cos_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
    r0 + (1.0 - r0) * (1.0 - cos_i.abs().min(1.0)).powi(5)
}

type Reflectance = fn(f32, f32, f32) -> f32;

/// Runs the experiment.
///
/// # Errors
/// Never.
pub fn run(config: &Config) -> Result<Experiment, BenchError> {
    let methods: [(&str, Reflectance); 3] = [
        ("exact", fresnel_dielectric),
        ("Schlick (kit)", schlick),
        ("Schlick, cos θ_i inside", schlick_incident_cosine),
    ];
    let count = config.scalar_samples.max(2);
    // Incidence angles uniform in [0°, 90°].
    let cosines: Vec<f32> = (0..count)
        .map(|k| (std::f64::consts::FRAC_PI_2 * k as f64 / (count - 1) as f64).cos() as f32)
        .collect();
    let mut rows = Vec::new();
    for (side, eta_i, eta_t) in [("outside 1→1.5", 1.0f32, 1.5f32), ("inside 1.5→1", 1.5, 1.0)]
    {
        let exact: Vec<f64> =
            cosines.iter().map(|&c| f64::from(fresnel_dielectric(c, eta_i, eta_t))).collect();
        for (name, method) in methods {
            let (mut max_abs, mut sum_abs, mut max_rel, mut sum_rel) = (0.0f64, 0.0, 0.0f64, 0.0);
            let mut tir_wrong = 0u32;
            for (&c, &e) in cosines.iter().zip(&exact) {
                let got = f64::from(method(c, eta_i, eta_t));
                let abs = (got - e).abs();
                let rel = abs / e.max(f64::MIN_POSITIVE);
                max_abs = max_abs.max(abs);
                max_rel = max_rel.max(rel);
                sum_abs += abs;
                sum_rel += rel;
                if e == 1.0 && got != 1.0 {
                    tir_wrong += 1;
                }
            }
            let n = cosines.len() as f64;
            let time = median_time(config.reps, || {
                let mut s = 0.0f32;
                for &c in &cosines {
                    s += method(black_box(c), eta_i, eta_t);
                }
                s
            });
            rows.push(Row {
                key: vec![name.into(), side.into()],
                values: vec![
                    max_abs,
                    sum_abs / n,
                    max_rel,
                    sum_rel / n,
                    f64::from(tir_wrong),
                    time * 1e9 / n,
                ],
            });
        }
    }
    Ok(Experiment {
        id: "fresnel",
        title: "フレネル反射率 / Fresnel reflectance",
        about: "ガラス (η = 1.5) の厳密なフレネル反射率と Schlick の近似の差。入射角 0°〜90° を等間隔に。\
                `TIR wrong` は全反射 (厳密値 1) なのに 1 を返さなかった角度の数。\n\n\
                Exact dielectric Fresnel reflectance for glass (η = 1.5) against Schlick's \
                approximation, going in (outside) and coming out (inside), at incidence angles \
                spaced evenly over 0°…90°. The kit's `schlick` uses the cosine on the less dense \
                side and returns 1 under total internal reflection; `Schlick, cos θ_i inside` is \
                the textbook formula with the incident cosine (no TIR). `TIR wrong` counts angles \
                under total internal reflection (exact F = 1) where a method did not return 1. \
                Relative error is against the exact value (≥ 0.04 here)."
            .into(),
        keys: vec!["method", "side"],
        columns: vec![
            Column::error("max abs error"),
            Column::error("mean abs error"),
            Column::error("max rel error"),
            Column::error("mean rel error"),
            Column::value("TIR wrong"),
            Column::value("time/call [ns]"),
        ],
        rows,
        series_key: 0,
        time_column: 5,
        error_column: 0,
    })
}
