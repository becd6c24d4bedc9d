//! docs/numerics.md rows 12 (refraction) and 13 (Schlick from inside), and property tests of the
//! optics: each case against an f64 oracle computed here, on the same f32 inputs, independently of
//! `cg_core::optics` (Snell's law through angles, Fresnel's sine and tangent laws).

use cg_core::glam::{DVec3, Vec3};
use cg_core::optics::{Interface, fresnel_dielectric, reflect, refract, schlick};
use cg_testkit::{Inputs, assert_approx_eq, ulps};
use proptest::prelude::*;

const EPS: f64 = f32::EPSILON as f64;

// ---------------------------------------------------------------------------------------------
// f64 oracles

/// `sin θ` and `cos θ` of the angle between `-i` and `n` (incidence on the side of `n`), from the
/// f32 vectors in f64: `atan2(|i × n|, −i·n)` is accurate at every angle.
fn angle_f64(i: Vec3, n: Vec3) -> f64 {
    let (i, n) = (i.as_dvec3().normalize(), n.as_dvec3().normalize());
    i.cross(n).length().atan2(-i.dot(n))
}

/// The sine of the angle between a direction and a normal (either orientation).
fn sin_to_normal(d: Vec3, n: Vec3) -> f64 {
    let (d, n) = (d.as_dvec3(), n.as_dvec3());
    d.cross(n).length() / (d.length() * n.length())
}

/// Total internal reflection by Snell's law in angles: η₁ sin θ₁ > η₂.
fn tir_f64(i: Vec3, n: Vec3, eta: f64) -> bool {
    eta * angle_f64(i, n).sin() > 1.0
}

/// Exact dielectric reflectance by Fresnel's sine and tangent laws (a different formulation from
/// the kit's cosine form): r_s = −sin(θᵢ−θₜ)/sin(θᵢ+θₜ), r_p = tan(θᵢ−θₜ)/tan(θᵢ+θₜ).
fn fresnel_oracle(cos_i: f64, eta_i: f64, eta_t: f64) -> f64 {
    let theta_i = cos_i.clamp(0.0, 1.0).acos();
    let sin_t = eta_i / eta_t * theta_i.sin();
    if sin_t >= 1.0 {
        return 1.0;
    }
    let theta_t = sin_t.asin();
    if theta_i < 1e-9 {
        // Normal incidence: 0/0 in the angle forms; the limit is ((η₁−η₂)/(η₁+η₂))².
        return ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
    }
    let rs = -(theta_i - theta_t).sin() / (theta_i + theta_t).sin();
    let rp = (theta_i - theta_t).tan() / (theta_i + theta_t).tan();
    0.5 * (rs * rs + rp * rp)
}

/// Schlick's formula with a given cosine, in f64.
fn schlick_with_cos(cos: f64, eta_i: f64, eta_t: f64) -> f64 {
    let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
    r0 + (1.0 - r0) * (1.0 - cos).powi(5)
}

/// A unit direction at angle `theta` from `-n` in the plane of `n` and `tangent` (unit,
/// orthogonal), travelling towards the surface, rounded to f32.
fn incident(n: DVec3, tangent: DVec3, theta: f64) -> Vec3 {
    (tangent * theta.sin() - n * theta.cos()).as_vec3()
}

/// A seeded orthonormal pair (n, tangent), generic so no component is zero.
fn frame(inputs: &mut Inputs) -> (DVec3, DVec3) {
    let n = inputs.unit_vec3().as_dvec3().normalize();
    let a = inputs.unit_vec3().as_dvec3();
    let tangent = (a - n * a.dot(n)).normalize();
    (n, tangent)
}

/// The naive f32 refraction of many textbooks: k = 1 − η²(1 − (i·n)²), t = ηi + (η cos − √k)n.
fn refract_naive(i: Vec3, n: Vec3, eta: f32) -> Option<Vec3> {
    let cos_i = -i.dot(n);
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    (k >= 0.0).then(|| eta * i + (eta * cos_i - k.sqrt()) * n)
}

/// Checks a refracted direction against Snell's law, unit length and the plane of i and n.
fn check_transmitted(i: Vec3, n: Vec3, t: Vec3, eta_1: f64, eta_2: f64, what: &str) {
    // |t| − 1: each component is correctly rounded from a unit f64 vector (≤ 2⁻²⁴ relative), so
    // the length is within 2⁻²⁴ ≈ 6e-8 of 1; 2ε = 2.4e-7 leaves room.
    let len = t.as_dvec3().length();
    assert!((len - 1.0).abs() <= 2.0 * EPS, "{what}: |t| = {len}, i = {i}, n = {n}");
    // Snell residual: sin θₜ of the f32 result moves by ≤ ~2⁻²⁴ per component, times η₂ ≤ 2.5:
    // ≤ 3e-7 in all; the row asks for 1e-6.
    let residual = eta_1 * sin_to_normal(i, n) - eta_2 * sin_to_normal(t, n);
    assert!(
        residual.abs() <= 1e-6,
        "{what}: Snell residual {residual:e}, i = {i}, n = {n}, t = {t}"
    );
    // In the plane of i and n: the triple product, relative to |i × n| (skipped at normal
    // incidence, where the plane is not defined); same rounding argument, 1e-6.
    let (i64, n64, t64) = (i.as_dvec3(), n.as_dvec3(), t.as_dvec3());
    let cross = i64.cross(n64);
    if cross.length() > 1e-3 {
        let off = cross.dot(t64) / cross.length();
        assert!(off.abs() <= 1e-6, "{what}: out of plane by {off:e}");
    }
    // On the far side: t·n ≤ 0 (n faces the incident side); grazing results may round to +ε.
    assert!(t64.dot(n64) <= 2.0 * EPS, "{what}: t·n = {} > 0", t64.dot(n64));
}

// ---------------------------------------------------------------------------------------------
// Row 12: refraction

#[test]
fn row12_refraction_at_normal_incidence_passes_straight() {
    // Oracle: θᵢ = 0 ⇒ θₜ = 0 for every η, so t = i. (A naive f32 formula passes too; this guards
    // formulas that build a tangent from normalise(i × n), NaN here.)
    let mut inputs = Inputs::seeded(12_001);
    for k in 0..200 {
        let n = if k == 0 { Vec3::Y } else { inputs.unit_vec3() };
        let i = -n;
        for eta in [1.0 / 2.5, 1.0 / 1.5, 1.0, 1.33, 1.5, 2.5] {
            let t =
                refract(i, n, eta).unwrap_or_else(|| panic!("TIR at normal incidence, η {eta}"));
            for c in 0..3 {
                // 2 ulp: t is i renormalised in f64 (≤ 1 ulp) and rounded once (≤ ½ ulp).
                assert!(ulps(t[c], i[c]) <= 2, "η {eta}: t = {t} vs i = {i}");
            }
        }
    }
}

#[test]
fn row12_critical_angle_tir_decision_agrees_with_f64() {
    // The f32 angles nearest the critical angle θc = asin(η₂/η₁) and 64 neighbours each side, in
    // generic frames; for each f32 direction the oracle is Snell's law through its f64 angle. The
    // kit may disagree only within 1 ulp (of θc as f32) of the critical angle.
    let mut inputs = Inputs::seeded(12_002);
    let mut naive_disagreements = 0;
    let mut checked = 0;
    for (eta_1, eta_2) in [(1.5, 1.0), (2.5, 1.0), (1.33, 1.0), (1.5, 1.33), (1.0001, 1.0)] {
        let eta = (eta_1 / eta_2) as f32;
        let eta64 = f64::from(eta);
        let critical = (1.0 / eta64).asin();
        let ulp =
            f64::from(critical as f32) - f64::from(f32::from_bits((critical as f32).to_bits() - 1));
        for frame_index in 0..20 {
            let (n64, tangent) =
                if frame_index == 0 { (DVec3::Y, DVec3::X) } else { frame(&mut inputs) };
            let n = n64.as_vec3();
            let mut theta = f32::from_bits((critical as f32).to_bits() - 64);
            for _ in 0..=128 {
                let i = incident(n64, tangent, f64::from(theta));
                let actual = angle_f64(i, n);
                let oracle_tir = tir_f64(i, n, eta64);
                let got = refract(i, n, eta);
                if (actual - critical).abs() > ulp {
                    checked += 1;
                    assert_eq!(
                        got.is_none(),
                        oracle_tir,
                        "η {eta}: θ = {actual} (θc = {critical}, {} ulp away), i = {i}, n = {n}",
                        (actual - critical) / ulp
                    );
                    if refract_naive(i, n, eta).is_none() != oracle_tir {
                        naive_disagreements += 1;
                    }
                }
                if let Some(t) = got {
                    check_transmitted(i, n, t, eta64, 1.0, "near the critical angle");
                }
                theta = f32::from_bits(theta.to_bits() + 1);
            }
        }
    }
    assert!(checked > 10_000, "{checked}");
    // The premise: the naive f32 formula (1 − cos² in f32) decides wrongly next to θc.
    assert!(naive_disagreements > 0, "the naive formula agreed everywhere ({checked} cases)");
}

#[test]
fn row12_grazing_incidence() {
    // cos θᵢ → 0 (1e-1 … 1e-8 and exactly 0). Into glass (η = 1/1.5): refracted at just under
    // the critical angle, sin θₜ = sin θᵢ / 1.5 (Snell); out of glass (η = 1.5): TIR, F = 1.
    let mut inputs = Inputs::seeded(12_003);
    for frame_index in 0..20 {
        let (n64, tangent) =
            if frame_index == 0 { (DVec3::Y, DVec3::X) } else { frame(&mut inputs) };
        let n = n64.as_vec3();
        for e in [1, 2, 3, 4, 5, 6, 7, 8] {
            for delta in [10f64.powi(-e), 0.0] {
                let i = incident(n64, tangent, std::f64::consts::FRAC_PI_2 - delta);
                if i.as_dvec3().dot(n.as_dvec3()) > 0.0 {
                    continue; // rounded past tangent (in f64, as the kit decides): from the other side
                }
                let t = refract(i, n, 1.0 / 1.5).expect("into glass never reflects totally");
                check_transmitted(i, n, t, 1.0, 1.5, "grazing into glass");
                let it = Interface::at(i, n, 1.0, 1.5).unwrap();
                assert!(it.entering && it.cos_i <= 1e-1 && it.cos_i >= 0.0);
                // Grazing reflectance tends to 1: F(cos) within 2·cos·(…) of 1; the oracle says.
                let f = fresnel_dielectric(it.cos_i, 1.0, 1.5);
                assert_approx_eq!(
                    f64::from(f),
                    fresnel_oracle(f64::from(it.cos_i), 1.0, 1.5),
                    abs = 1e-6,
                    "F grazing, cos {}",
                    it.cos_i
                );
                assert_eq!(refract(i, n, 1.5), None, "grazing out of glass is TIR");
                assert_eq!(fresnel_dielectric(it.cos_i, 1.5, 1.0), 1.0);
            }
        }
    }
    // Exactly tangent: F = 1 (r_s = r_p = −1), and the refracted ray leaves at θc.
    assert_eq!(fresnel_dielectric(0.0, 1.0, 1.5), 1.0);
    let t = refract(Vec3::X, Vec3::Y, 1.0 / 1.5).unwrap();
    assert_approx_eq!(sin_to_normal(t, Vec3::Y), 1.0 / 1.5, abs = 1e-7);
}

#[test]
fn row12_eta_one_passes_straight() {
    // η = 1: θₜ = θᵢ, t = i. Within 2 ulp per component (renormalising i in f64, one rounding),
    // including grazing directions. The naive f32 formula bends grazing rays: √(1 − (1 − c²))
    // is not c when 1 − c² rounds to 1 (c < 2.4e-4).
    let mut inputs = Inputs::seeded(12_004);
    let mut naive_bent = 0;
    for k in 0..2000 {
        let (n64, tangent) = frame(&mut inputs);
        let n = n64.as_vec3();
        let theta = if k % 2 == 0 {
            inputs.uniform(0.0, std::f64::consts::FRAC_PI_2)
        } else {
            std::f64::consts::FRAC_PI_2 - 10f64.powf(inputs.uniform(-7.0, -2.0))
        };
        let i = incident(n64, tangent, theta);
        if i.dot(n) >= 0.0 {
            continue;
        }
        let t = refract(i, n, 1.0).expect("η = 1 never reflects totally");
        for c in 0..3 {
            assert!(ulps(t[c], i[c]) <= 2, "θ {theta}: t = {t}, i = {i}");
        }
        let naive = refract_naive(i, n, 1.0).unwrap();
        if (0..3).any(|c| ulps(naive[c], i[c]) > 4) {
            naive_bent += 1;
        }
    }
    assert!(naive_bent > 100, "the naive formula bent only {naive_bent} grazing rays");
}

#[test]
fn row12_hit_from_inside_flips_normal_and_inverts_eta() {
    // A glass slab (η 1.5 inside, air outside), outward normal +Y at the top face.
    let n_g = Vec3::Y;
    // From inside, travelling up at 30°: sin θₜ = 1.5 sin 30° = 0.75 (Snell, f64).
    let i = Vec3::new(30f32.to_radians().sin(), 30f32.to_radians().cos(), 0.0);
    let it = Interface::at(i, n_g, 1.0, 1.5).unwrap();
    assert!(!it.entering);
    assert_eq!(it.n, -n_g, "inside hits flip n");
    assert_eq!((it.eta_i, it.eta_t, it.eta), (1.5, 1.0, 1.5), "and invert η");
    assert_approx_eq!(it.cos_i, 30f32.to_radians().cos(), abs = 1e-7);
    let t = refract(i, it.n, it.eta).expect("30° inside glass is below θc = 41.8°");
    check_transmitted(i, it.n, t, 1.5, 1.0, "leaving glass");
    assert_approx_eq!(sin_to_normal(t, n_g), 0.75, abs = 1e-6);
    assert!(t.y > 0.0, "the ray leaves upwards");
    // The wrong call (geometric normal and η = 1/1.5 as if entering) bends it the wrong way.
    let wrong = refract(i, n_g, 1.0 / 1.5).unwrap();
    assert!((sin_to_normal(wrong, n_g) - 0.75).abs() > 0.3, "premise: {wrong}");

    // Entering from outside: the normal and η as given.
    let i = Vec3::new(0.6, -0.8, 0.0);
    let it = Interface::at(i, n_g, 1.0, 1.5).unwrap();
    assert!(it.entering);
    assert_eq!((it.n, it.eta_i, it.eta_t), (n_g, 1.0, 1.5));
    assert_approx_eq!(it.eta, 1.0 / 1.5, abs = 1e-7);
    let t = refract(i, it.n, it.eta).unwrap();
    check_transmitted(i, it.n, t, 1.0, 1.5, "entering glass");

    // Random hits from both sides, random η in [1, 2.5]: Snell with the right indices.
    let mut inputs = Inputs::seeded(12_005);
    for _ in 0..2000 {
        let i = inputs.unit_vec3();
        let n_g = inputs.unit_vec3();
        let eta_inside = inputs.uniform_f32(1.0, 2.5);
        let it = Interface::at(i, n_g, 1.0, eta_inside).unwrap();
        assert_eq!(it.entering, i.dot(n_g) <= 0.0);
        assert!(it.n.dot(i) <= 1e-7, "n on the incident side");
        match refract(i, it.n, it.eta) {
            Some(t) => check_transmitted(
                i,
                it.n,
                t,
                f64::from(it.eta_i),
                f64::from(it.eta_t),
                "either side",
            ),
            None => assert!(
                f64::from(it.eta_i) * sin_to_normal(i, n_g) >= f64::from(it.eta_t) * (1.0 - 1e-6),
                "TIR only past θc"
            ),
        }
    }
    assert_eq!(Interface::at(Vec3::ZERO, Vec3::Y, 1.0, 1.5), None);
    assert_eq!(Interface::at(Vec3::X, Vec3::new(f32::NAN, 1.0, 0.0), 1.0, 1.5), None);
}

#[test]
fn row12_total_internal_reflection_reflects_everything() {
    // Inside glass past θc = 41.81°: refract is None, F = 1 (exact and Schlick), and the mirror
    // direction keeps the angle and stays inside.
    for deg in [41.9f32, 45.0, 60.0, 89.0, 89.999] {
        let i = Vec3::new(deg.to_radians().sin(), deg.to_radians().cos(), 0.0);
        let it = Interface::at(i, Vec3::Y, 1.0, 1.5).unwrap();
        assert!(tir_f64(i, it.n, 1.5), "premise: {deg}° is past θc");
        assert_eq!(refract(i, it.n, it.eta), None, "{deg}°");
        assert_eq!(fresnel_dielectric(it.cos_i, it.eta_i, it.eta_t), 1.0, "{deg}°");
        assert_eq!(schlick(it.cos_i, it.eta_i, it.eta_t), 1.0, "{deg}°");
        let r = reflect(i, it.n);
        assert!(r.y < 0.0, "stays inside");
        assert_approx_eq!(r.length(), 1.0, abs = 2.0 * EPS);
        assert_approx_eq!(r.dot(it.n), -i.dot(it.n), abs = 2.0 * EPS);
    }
}

#[test]
fn row12_snell_residual_and_unit_length_over_random_directions() {
    // Seeded directions, η in [1, 2.5] both ways (into and out of the denser medium), angles
    // uniform and log-uniformly close to 0°, θc and 90°.
    let mut inputs = Inputs::seeded(12_006);
    let (mut transmitted, mut reflected) = (0, 0);
    let cases = if cfg!(debug_assertions) { 20_000 } else { 200_000 };
    for k in 0..cases {
        let (n64, tangent) = frame(&mut inputs);
        let n = n64.as_vec3();
        let eta_dense = inputs.uniform(1.0, 2.5);
        let (eta_1, eta_2) = if inputs.coin() { (1.0, eta_dense) } else { (eta_dense, 1.0) };
        let eta = (eta_1 / eta_2) as f32;
        let critical = (1.0 / f64::from(eta)).min(1.0).asin();
        let offset = 10f64.powf(inputs.uniform(-7.0, -1.0));
        let theta = match k % 4 {
            0 => inputs.uniform(0.0, std::f64::consts::FRAC_PI_2),
            1 => offset,
            2 => std::f64::consts::FRAC_PI_2 - offset,
            _ => critical + if inputs.coin() { offset } else { -offset },
        };
        let i = incident(n64, tangent, theta.min(std::f64::consts::FRAC_PI_2));
        if i.as_dvec3().dot(n.as_dvec3()) > 0.0 {
            continue;
        }
        let oracle_tir = tir_f64(i, n, f64::from(eta));
        match refract(i, n, eta) {
            Some(t) => {
                transmitted += 1;
                assert!(!oracle_tir, "transmitted past θc: i = {i}, n = {n}, η = {eta}");
                check_transmitted(i, n, t, eta_1, eta_2, "random");
            }
            None => {
                reflected += 1;
                assert!(oracle_tir, "TIR below θc: i = {i}, n = {n}, η = {eta}");
            }
        }
    }
    assert!(transmitted > cases / 3 && reflected > cases / 10, "{transmitted} / {reflected}");
}

// ---------------------------------------------------------------------------------------------
// Row 13: Schlick from inside the denser medium

/// Angles 0..90° in fine steps, as cosines.
fn cosines(steps: usize) -> impl Iterator<Item = f32> {
    (0..=steps).map(move |k| ((k as f64 / steps as f64) * std::f64::consts::FRAC_PI_2).cos() as f32)
}

#[test]
fn row13_schlick_from_inside_uses_the_transmitted_cosine() {
    // Oracle: Schlick's formula evaluated in f64 with cos θₜ from Snell's law. Tolerance 1e-6:
    // the kit computes cos θₜ in f64 and the polynomial in f32 (a few ε on values ≤ 1).
    for (eta_i, eta_t) in [(1.5f32, 1.0f32), (2.5, 1.0), (1.33, 1.0), (1.5, 1.33)] {
        let (ni, nt) = (f64::from(eta_i), f64::from(eta_t));
        for cos_i in cosines(20_000) {
            let sin_t = ni / nt * (1.0 - f64::from(cos_i).powi(2)).max(0.0).sqrt();
            let got = schlick(cos_i, eta_i, eta_t);
            if sin_t >= 1.0 {
                assert_eq!(got, 1.0, "TIR → 1 (cos {cos_i}, {eta_i} → {eta_t})");
            } else {
                let cos_t = (1.0 - sin_t * sin_t).sqrt();
                assert_approx_eq!(
                    f64::from(got),
                    schlick_with_cos(cos_t, ni, nt),
                    abs = 1e-6,
                    "cos_i {cos_i}, {eta_i} → {eta_t}"
                );
            }
        }
    }
}

#[test]
fn row13_schlick_total_internal_reflection_is_one() {
    let critical = (1.0f64 / 1.5).asin();
    for theta in [critical + 1e-6, critical + 1e-3, 0.8, 1.2, std::f64::consts::FRAC_PI_2] {
        let cos_i = theta.cos() as f32;
        assert_eq!(schlick(cos_i, 1.5, 1.0), 1.0, "θ {theta}");
        assert_eq!(fresnel_dielectric(cos_i, 1.5, 1.0), 1.0, "θ {theta}");
    }
}

#[test]
fn row13_schlick_error_against_exact_and_the_wrong_cosine() {
    // Against Fresnel's exact laws (f64 oracle), over 40 001 angles in [0°, 90°]. Measured maxima
    // (f64, 2·10⁵ angles): 0.03569 absolute and 23.2 % relative for glass, outside near 85° and
    // inside near 41.6° — the same curve, since F(θᵢ inside) = F(θₜ outside). Bounds: 0.036 and
    // 0.233. The wrong cosine (cos θᵢ inside, no TIR) is off by 0.959 just past θc = 41.8°.
    let mut worst = [0.0f64; 3];
    let mut worst_rel = 0.0f64;
    for cos_i in cosines(40_000) {
        let c = f64::from(cos_i);
        for (k, (eta_i, eta_t)) in [(1.0f32, 1.5f32), (1.5, 1.0)].into_iter().enumerate() {
            let exact = fresnel_oracle(c, f64::from(eta_i), f64::from(eta_t));
            let err = (f64::from(schlick(cos_i, eta_i, eta_t)) - exact).abs();
            worst[k] = worst[k].max(err);
            worst_rel = worst_rel.max(err / exact);
            // The exact function of the kit against the oracle: 1e-6 (f64 inside, one rounding;
            // the oracle's angle forms lose ~1e-9 near normal incidence).
            assert_approx_eq!(
                f64::from(fresnel_dielectric(cos_i, eta_i, eta_t)),
                exact,
                abs = 1e-6,
                "cos {cos_i}, {eta_i} → {eta_t}"
            );
        }
        let wrong = schlick_with_cos(c, 1.5, 1.0);
        worst[2] = worst[2].max((wrong - fresnel_oracle(c, 1.5, 1.0)).abs());
    }
    assert!(worst[0] <= 0.036 && worst[0] > 0.035, "outside: {}", worst[0]);
    assert!(worst[1] <= 0.036 && worst[1] > 0.035, "inside: {}", worst[1]);
    assert!(worst_rel <= 0.233, "relative: {worst_rel}");
    assert!(worst[2] > 0.95, "the wrong cosine's error: {}", worst[2]);
}

#[test]
fn fresnel_handles_its_edges() {
    // Normal incidence: ((1 − 1.5)/(1 + 1.5))² = 0.04; equal indices: 0; NaN: 1, never NaN.
    assert_approx_eq!(fresnel_dielectric(1.0, 1.0, 1.5), 0.04, abs = 1e-8);
    assert_approx_eq!(fresnel_dielectric(1.0, 1.5, 1.0), 0.04, abs = 1e-8);
    assert_eq!(fresnel_dielectric(0.3, 1.5, 1.5), 0.0);
    assert_eq!(fresnel_dielectric(f32::NAN, 1.0, 1.5), 1.0);
    assert_eq!(fresnel_dielectric(0.5, f32::NAN, 1.5), 1.0);
    assert_eq!(schlick(0.5, f32::NAN, 1.5), 1.0);
    // The sign of cos is ignored, values above 1 are clamped.
    assert_eq!(fresnel_dielectric(-0.5, 1.0, 1.5), fresnel_dielectric(0.5, 1.0, 1.5));
    assert_eq!(schlick(1.5, 1.0, 1.5), schlick(1.0, 1.0, 1.5));
}

// ---------------------------------------------------------------------------------------------
// Property tests (seeded)

fn config() -> ProptestConfig {
    cg_testkit::prop::config(2_000, 0x0b71c5)
}

/// A unit vector from a uniform point in the cube, normalised in f64 and rounded once.
fn unit() -> impl Strategy<Value = Vec3> {
    (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0)
        .prop_filter("not too short", |(x, y, z)| x * x + y * y + z * z > 1e-2)
        .prop_map(|(x, y, z)| DVec3::new(x, y, z).normalize().as_vec3())
}

prop_compose! {
    /// Log-uniform magnitude in [1e-10, 1e10] with both signs per component.
    fn any_vector()(e in proptest::array::uniform3(-10.0f64..10.0),
                    s in proptest::array::uniform3(proptest::bool::ANY)) -> Vec3 {
        let c = |k: usize| if s[k] { 10f64.powf(e[k]) } else { -(10f64.powf(e[k])) };
        DVec3::new(c(0), c(1), c(2)).as_vec3()
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn reflect_preserves_length_and_angle(i in any_vector(), n in unit()) {
        let r = reflect(i, n);
        let (li, lr) = (i.as_dvec3().length(), r.as_dvec3().length());
        // A handful of f32 roundings on magnitudes ≤ |i|: 8ε·|i|.
        prop_assert!((lr - li).abs() <= 8.0 * EPS * li, "|r| {lr} vs |i| {li}");
        let (nr, ni) = (n.as_dvec3().dot(r.as_dvec3()), n.as_dvec3().dot(i.as_dvec3()));
        prop_assert!((nr + ni).abs() <= 8.0 * EPS * li, "n·r {nr} vs −n·i {}", -ni);
    }

    #[test]
    fn refract_obeys_snell_and_stays_in_the_plane(
        i in unit(), n in unit(), eta_dense in 1.0f64..2.5, into in proptest::bool::ANY,
    ) {
        let i = if i.as_dvec3().dot(n.as_dvec3()) > 0.0 { -i } else { i };
        let (eta_1, eta_2) = if into { (1.0, eta_dense) } else { (eta_dense, 1.0) };
        let eta = (eta_1 / eta_2) as f32;
        match refract(i, n, eta) {
            Some(t) => check_transmitted(i, n, t, f64::from(eta), 1.0, "proptest"),
            None => prop_assert!(f64::from(eta) * sin_to_normal(i, n) > 1.0 - 1e-12),
        }
    }

    #[test]
    fn fresnel_is_a_fraction(cos in -2.0f32..2.0, a in 0.1f32..4.0, b in 0.1f32..4.0) {
        let f = fresnel_dielectric(cos, a, b);
        let s = schlick(cos, a, b);
        prop_assert!((0.0..=1.0).contains(&f), "F = {f}");
        prop_assert!((0.0..=1.0).contains(&s), "Schlick = {s}");
        // T = 1 − F is the transmitted fraction; both in [0, 1].
        prop_assert!((0.0..=1.0).contains(&(1.0 - f)));
    }

    #[test]
    fn schlick_is_exact_at_normal_incidence(a in 0.1f32..4.0, b in 0.1f32..4.0) {
        // R₀ in f32 (4 roundings) against the exact f64 value: 4 ulp-sized relative steps.
        let exact = fresnel_oracle(1.0, f64::from(a), f64::from(b));
        let got = f64::from(schlick(1.0, a, b));
        prop_assert!((got - exact).abs() <= 1e-9 + 8.0 * EPS * exact, "{got} vs {exact}");
        let kit_exact = f64::from(fresnel_dielectric(1.0, a, b));
        prop_assert!((kit_exact - exact).abs() <= 1e-9 + EPS * exact, "{kit_exact} vs {exact}");
    }
}
