//! Face-normal precision: a naive f32 cross product, Kahan's f32 cross product
//! ([`cg_core::math::cross_kahan`]), the kit's [`face_normal`] (f32) and [`face_normal_f64`],
//! against an exact oracle, on needle triangles and on unit triangles far from the origin.

use std::hint::black_box;

use cg_core::glam::{DVec3, Vec3};
use cg_core::math::cross_kahan;
use cg_core::normals::{face_normal, face_normal_f64};

use crate::measure::{Rng, mean_p99_max, median_time};
use crate::{BenchError, Column, Config, Experiment, Row};

/// `a·b` exactly, as an unevaluated sum `hi + lo` (FMA).
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// `a + b` exactly, as `hi + lo` (Knuth).
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a·b − c·d` to about 2⁻¹⁰⁶ relative: both products exact, their difference summed in
/// double-double.
fn dop_exact(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let (p, pe) = two_product(a, b);
    let (q, qe) = two_product(c, d);
    let (s, se) = two_sum(p, -q);
    s + (se + (pe - qe))
}

/// The oracle: the unit normal of the f32 corners, from exact f64 edges (the difference of two
/// f32 numbers within 2²⁹ of each other in magnitude is exact in f64) and a cross product
/// computed to double-double accuracy.
#[must_use]
pub fn oracle(a: Vec3, b: Vec3, c: Vec3) -> Option<DVec3> {
    let (e1, e2) = (b.as_dvec3() - a.as_dvec3(), c.as_dvec3() - a.as_dvec3());
    let n = DVec3::new(
        dop_exact(e1.y, e2.z, e1.z, e2.y),
        dop_exact(e1.z, e2.x, e1.x, e2.z),
        dop_exact(e1.x, e2.y, e1.y, e2.x),
    );
    let len = n.length();
    (len > 0.0 && len.is_finite()).then(|| n / len)
}

/// The naive normal: f32 edges, f32 cross product, f32 normalisation.
#[must_use]
pub fn naive(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    cg_core::math::try_normalize((b - a).cross(c - a))
}

/// f32 edges and Kahan's f32 cross product (FMA), normalised in f32.
#[must_use]
pub fn kahan_f32(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    cg_core::math::try_normalize(cross_kahan(b - a, c - a))
}

/// The test triangles of one case.
fn triangles(case: &str, count: usize, rng: &mut Rng) -> Vec<[Vec3; 3]> {
    (0..count)
        .map(|_| {
            // A random orthonormal frame.
            let u = rng.direction();
            let v = u.any_orthonormal_vector();
            let w = u.cross(v);
            let angle = rng.range(0.0, std::f64::consts::TAU);
            let v = v * angle.cos() + w * angle.sin();
            let (origin, a, b, cc) = match case {
                "needle" => {
                    // Base 1 along u, height 10^-3 .. 10^-6, near the origin.
                    let h = 10f64.powf(rng.range(-6.0, -3.0));
                    let o = rng.direction() * rng.unit();
                    (o, DVec3::ZERO, u, u * rng.range(0.2, 0.8) + v * h)
                }
                _ => {
                    // A well-shaped unit triangle 10^3 .. 10^6 from the origin.
                    let o = rng.direction() * 10f64.powf(rng.range(3.0, 6.0));
                    (o, DVec3::ZERO, u, u * 0.3 + v * 0.9)
                }
            };
            [origin + a, origin + b, origin + cc].map(|p| p.as_vec3())
        })
        .collect()
}

fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// Runs the experiment.
///
/// # Errors
/// Never.
pub fn run(config: &Config) -> Result<Experiment, BenchError> {
    type Method = fn(Vec3, Vec3, Vec3) -> Option<DVec3>;
    let methods: [(&str, Method); 4] = [
        ("naive f32", |a, b, c| naive(a, b, c).map(Vec3::as_dvec3)),
        ("Kahan f32", |a, b, c| kahan_f32(a, b, c).map(Vec3::as_dvec3)),
        ("face_normal (f32)", |a, b, c| face_normal(a, b, c).map(Vec3::as_dvec3)),
        ("face_normal_f64", face_normal_f64),
    ];
    let mut rows = Vec::new();
    let mut rng = Rng::new(0x5eed_0002);
    for case in ["needle", "far offset"] {
        let tris = triangles(case, config.face_samples, &mut rng);
        let oracles: Vec<Option<DVec3>> = tris.iter().map(|t| oracle(t[0], t[1], t[2])).collect();
        for (name, method) in methods {
            let mut angles = Vec::new();
            let mut missing = 0u32;
            for (t, o) in tris.iter().zip(&oracles) {
                let Some(o) = o else { continue };
                match method(t[0], t[1], t[2]) {
                    Some(n) => angles.push(angle(n, *o)),
                    None => missing += 1,
                }
            }
            let (mean, p99, max) = mean_p99_max(&mut angles);
            let time = median_time(config.reps, || {
                for t in &tris {
                    black_box(method(black_box(t[0]), black_box(t[1]), black_box(t[2])));
                }
            });
            rows.push(Row {
                key: vec![name.into(), case.into()],
                values: vec![mean, p99, max, f64::from(missing), time * 1e9 / tris.len() as f64],
            });
        }
    }
    Ok(Experiment {
        id: "face-normals",
        title: "面の法線の精度 / Face-normal precision",
        about: "f32 の頂点から面の法線を求める 4 通りの方法と、正確な外積 (f64 の辺と double-double の積和) \
                との角度 [rad]。針状三角形 (底辺 1、高さ 1e-6〜1e-3) と、原点から 1e3〜1e6 離れた単位三角形。\n\n\
                The angle in radians between four ways of computing a face normal from f32 corners \
                and an oracle (exact f64 edges, cross product in double-double), on needle \
                triangles (base 1, height 10⁻⁶…10⁻³, random orientation) and on unit triangles \
                10³…10⁶ from the origin. `naive f32`: f32 edges and cross; `Kahan f32`: f32 edges, \
                `cg_core::math::cross_kahan`; `face_normal`: the kit's (exact edges in f64, Kahan \
                cross with FMA), rounded to f32, and its f64 form. `missing` counts triangles a \
                method called degenerate."
            .into(),
        keys: vec!["method", "triangles"],
        columns: vec![
            Column::error("mean angle [rad]"),
            Column::error("p99 angle [rad]"),
            Column::error("max angle [rad]"),
            Column::value("missing"),
            Column::value("time/normal [ns]"),
        ],
        rows,
        series_key: 0,
        time_column: 4,
        error_column: 2,
    })
}
