//! docs/numerics.md rows 14–17: the specular power, Blinn's half vector, lights on the shaded point
//! and spot lights with equal cones. Each case against an f64 oracle written here from the
//! documented rule, on the same f32 inputs, and each states what the naive code would do.

use cg_core::Rgb;
use cg_core::glam::{DVec3, Vec3};
use cg_core::light::{
    Attenuation, Light, LightKind, LightModel, MIN_ATTENUATION_DENOMINATOR, Material, Specular,
    Terms, attenuation, shade, specular_blinn, specular_phong, spot_factor,
};
use cg_testkit::{Inputs, assert_approx_eq};

const EPS: f64 = f32::EPSILON as f64;
const WHITE: Rgb = Rgb::ONE;

fn unit(x: f32, y: f32, z: f32) -> Vec3 {
    DVec3::new(f64::from(x), f64::from(y), f64::from(z)).normalize().as_vec3()
}

fn assert_finite(t: &Terms, what: &str) {
    for (name, v) in [
        ("emission", t.emission),
        ("ambient", t.ambient),
        ("diffuse", t.diffuse),
        ("specular", t.specular),
    ] {
        assert!(v.is_finite(), "{what}: {name} = {v}");
    }
}

/// The kit's specular rule in f64: 0 unless N·L > 0 and cos > 0; then cosⁿ (cos ≤ 1).
fn specular_oracle(n_dot_l: f64, cos: f64, shininess: f64) -> f64 {
    if n_dot_l > 0.0 && cos > 0.0 { cos.min(1.0).powf(shininess.max(0.0)) } else { 0.0 }
}

/// R·V and N·H in f64 from the f32 vectors.
fn cosines_f64(n: Vec3, l: Vec3, v: Vec3) -> (f64, f64, f64) {
    let (n, l, v) = (n.as_dvec3(), l.as_dvec3(), v.as_dvec3());
    let n_dot_l = n.dot(l);
    let r = 2.0 * n_dot_l * n - l;
    let h = l + v;
    let n_dot_h = if h.length() > 0.0 { n.dot(h / h.length()) } else { 0.0 };
    (n_dot_l, r.dot(v), n_dot_h)
}

// ---------------------------------------------------------------------------------------------
// Row 14: the specular power

#[test]
fn row14_specular_with_negative_r_dot_v_is_zero_not_nan() {
    // N = +Y, L at 45°: R = (−1, 1, 0)/√2. V leans the other way: R·V = −0.39 < 0.
    let (n, l) = (Vec3::Y, unit(1.0, 1.0, 0.0));
    let v = unit(1.0, 0.2, 0.0);
    let (_, r_dot_v, _) = cosines_f64(n, l, v);
    assert!(r_dot_v < 0.0, "premise: R·V = {r_dot_v}");
    // The premise: powf of a negative base is NaN for a fractional n and positive for an even n.
    assert!((r_dot_v as f32).powf(2.5).is_nan());
    assert!((r_dot_v as f32).powf(2.0) > 0.0);
    for shininess in [0.0, 0.5, 1.0, 2.0, 2.5, 128.0, 1e4] {
        assert_eq!(specular_phong(WHITE, WHITE, n, l, v, shininess), Rgb::ZERO, "n = {shininess}");
    }
}

#[test]
fn row14_no_specular_when_the_light_is_behind() {
    // N·L < 0 and N·L = 0 (exactly), with V on the mirror direction so that R·V = 1 > 0: a
    // specular without the N·L test would shine here, through the surface.
    let n = Vec3::Y;
    for l in [unit(1.0, -0.1, 0.0), Vec3::X, unit(0.3, -1.0, 0.2)] {
        let r = 2.0 * n.dot(l) * n - l;
        let v = unit(r.x, r.y, r.z);
        let (n_dot_l, r_dot_v, _) = cosines_f64(n, l, v);
        assert!(n_dot_l <= 0.0 && r_dot_v > 0.99, "premise: N·L {n_dot_l}, R·V {r_dot_v}");
        for shininess in [0.0, 0.5, 2.5, 50.0] {
            assert_eq!(specular_phong(WHITE, WHITE, n, l, v, shininess), Rgb::ZERO);
            assert_eq!(specular_blinn(WHITE, WHITE, n, l, v, shininess), Rgb::ZERO);
        }
    }
}

#[test]
fn row14_exponent_zero_follows_the_kits_rule() {
    // n = 0: cos⁰ = 1 where cos > 0 (full ks·I), 0 where cos ≤ 0 — a plain clamp-then-powf gives
    // 0⁰ = 1 there, lighting the whole hemisphere away from the highlight.
    assert_eq!(0f32.powf(0.0), 1.0, "premise");
    let (n, l) = (Vec3::Y, unit(1.0, 1.0, 0.0));
    let ks = Rgb::new(0.25, 0.5, 1.0);
    let toward = unit(-1.0, 1.2, 0.0); // R·V > 0
    let away = unit(1.0, 0.2, 0.0); // R·V < 0
    assert_eq!(specular_phong(WHITE, ks, n, l, toward, 0.0), ks);
    assert_eq!(specular_phong(WHITE, ks, n, l, away, 0.0), Rgb::ZERO);
    // Blinn: N·H ≤ 0 needs V below the surface, with L above.
    let below = unit(-1.0, -3.0, 0.0);
    let (_, _, n_dot_h) = cosines_f64(n, l, below);
    assert!(n_dot_h < 0.0, "premise {n_dot_h}");
    assert_eq!(specular_blinn(WHITE, ks, n, l, below, 0.0), Rgb::ZERO);
    assert_eq!(specular_blinn(WHITE, ks, n, l, toward, 0.0), ks);
    // Negative and NaN exponents are taken as 0 (documented).
    assert_eq!(specular_phong(WHITE, ks, n, l, toward, -3.0), ks);
    assert_eq!(specular_phong(WHITE, ks, n, l, toward, f32::NAN), ks);
}

#[test]
fn row14_fractional_exponents_match_f64_and_never_nan() {
    // Seeded directions (including the degenerate V = R, V = −L, N·L = 0 ones), n fractional.
    // Tolerance: R·V and N·H carry a few ε of rounding (8ε covers the dot products, the
    // reflection and the normalisation), moved through d(cosⁿ)/dcos = n·cosⁿ⁻¹, plus 4ε relative
    // for powf and the products.
    let mut inputs = Inputs::seeded(14_004);
    let mut lit = 0;
    for k in 0..20_000 {
        let n = inputs.unit_vec3();
        let l = inputs.unit_vec3();
        let v = match k % 5 {
            0 => -l,
            1 => {
                let r = 2.0 * n.dot(l) * n - l;
                unit(r.x, r.y, r.z)
            }
            _ => inputs.unit_vec3(),
        };
        let shininess = [0.0f32, 0.5, 1.0, 2.5, 7.3, 100.25][k % 6];
        let s = f64::from(shininess);
        let (n_dot_l, r_dot_v, n_dot_h) = cosines_f64(n, l, v);
        for (got, cos, name) in [
            (specular_phong(WHITE, WHITE, n, l, v, shininess).x, r_dot_v, "phong"),
            (specular_blinn(WHITE, WHITE, n, l, v, shininess).x, n_dot_h, "blinn"),
        ] {
            assert!(got.is_finite(), "{name}: {got} for n = {s}");
            let expected = specular_oracle(n_dot_l, cos, s);
            // Where the oracle's cos is within rounding of 0 the rule may go either way.
            if n_dot_l.abs() < 8.0 * EPS || cos.abs() < 8.0 * EPS {
                continue;
            }
            let slope = if s == 0.0 { 0.0 } else { s * cos.clamp(0.0, 1.0).powf(s - 1.0) };
            let tol = slope * 8.0 * EPS + 4.0 * EPS * expected + 1e-30;
            assert_approx_eq!(f64::from(got), expected, abs = tol, "{name}, n = {s}, cos = {cos}");
            if expected > 0.0 {
                lit += 1;
            }
        }
    }
    assert!(lit > 5_000, "{lit}");
}

// ---------------------------------------------------------------------------------------------
// Row 15: Blinn's half vector with L = −V

#[test]
fn row15_blinn_with_light_opposite_the_viewer_is_zero() {
    // L = N (light overhead, N·L = 1 > 0), V = −L: L + V = 0, no half vector.
    let (n, l) = (Vec3::Y, Vec3::Y);
    let v = -l;
    assert!((l + v).normalize().is_nan(), "premise: glam's normalize is NaN here");
    // … and the usual pow(max(N·H, 0), n) turns that NaN into max(NaN, 0) = 0 (Rust's f32::max;
    // NaN in many shader compilers), then 0⁰ = 1: full specular at n = 0 from an undefined H.
    assert_eq!(n.dot((l + v).normalize()).max(0.0).powf(0.0), 1.0, "premise");
    for shininess in [0.0, 0.5, 1.0, 30.0] {
        let s = specular_blinn(WHITE, WHITE, n, l, v, shininess);
        assert_eq!(s, Rgb::ZERO, "n = {shininess}");
    }
    // Generic directions, exactly opposite: the same.
    let mut inputs = Inputs::seeded(15_001);
    for _ in 0..1000 {
        let l = inputs.unit_vec3();
        let n = if inputs.coin() { l } else { inputs.unit_vec3() };
        assert_eq!(specular_blinn(WHITE, WHITE, n, l, -l, 8.0), Rgb::ZERO);
    }
    // Nearly opposite (V = −L turned by ~1e-7 rad): L + V is exact in f32 (Sterbenz), so H is
    // well defined; the result matches the f64 oracle on the same inputs within 1e-5 (the
    // direction of H is only as good as the few-ulp difference it comes from).
    for k in 1..=20 {
        let l = unit(0.3, 1.0, 0.1);
        let v = (-l.as_dvec3() + DVec3::new(1e-7, -2e-7 * f64::from(k), 1e-7)).as_vec3();
        let got = specular_blinn(WHITE, WHITE, Vec3::Y, l, v, 2.0).x;
        let (n_dot_l, _, n_dot_h) = cosines_f64(Vec3::Y, l, v);
        assert!(got.is_finite());
        assert_approx_eq!(f64::from(got), specular_oracle(n_dot_l, n_dot_h, 2.0), abs = 1e-5);
    }
}

#[test]
fn row15_opengl_shading_with_light_opposite_the_viewer_is_finite() {
    // The whole equation (OpenGL mode uses Blinn): light straight above, viewer straight below.
    let light = Light {
        kind: LightKind::Directional { to_light: Vec3::Y },
        ambient: Rgb::splat(0.1),
        diffuse: Rgb::splat(0.8),
        specular: WHITE,
        attenuation: Attenuation::default(),
    };
    let material = Material { ks: WHITE, shininess: 16.0, ..Material::default() };
    let model = LightModel::OpenGl { local_viewer: false };
    let t = shade(model, Rgb::splat(0.2), &[light], &material, Vec3::ZERO, Vec3::Y, -Vec3::Y);
    assert_finite(&t, "L = −V");
    assert_eq!(t.specular, Rgb::ZERO);
    // Diffuse is the oracle's max(N·L, 0)·kd·Id = 1·0.8·0.8.
    assert_approx_eq!(t.diffuse, Rgb::splat(0.64), abs = 1e-7);
}

// ---------------------------------------------------------------------------------------------
// Row 16: a light at distance → 0

/// The documented attenuation in f64: 1 / max(kc + kl·d + kq·d², 1e-6).
fn attenuation_oracle(kc: f64, kl: f64, kq: f64, d: f64) -> f64 {
    1.0 / (kc + kl * d + kq * d * d).max(f64::from(MIN_ATTENUATION_DENOMINATOR))
}

#[test]
fn row16_attenuation_is_finite_at_zero_distance() {
    let att = Attenuation { constant: 0.0, linear: 0.0, quadratic: 1.0 };
    // The premise: the plain formula is infinite at d = 0 and at d = 1e-30 (d² underflows).
    for d in [0.0f32, 1e-30] {
        assert!((1.0 / (att.quadratic * d * d)).is_infinite());
    }
    for d in [0.0f32, 1e-30, 1e-10, 1e-4, 1e-3, 1e-2, 1.0, 10.0, 1e10, 1e18] {
        let got = attenuation(att, d);
        let expected = attenuation_oracle(0.0, 0.0, 1.0, f64::from(d));
        assert!(got.is_finite() && got >= 0.0, "d = {d}: {got}");
        // A few roundings (d², the sum, the division): 4ε relative.
        assert_approx_eq!(f64::from(got), expected, rel = 4.0 * EPS, "d = {d}");
    }
    assert_eq!(attenuation(att, 0.0), 1e6);
    // Far away: 1/d² = 1e-60 rounds to 0 in f32 (d² overflows to ∞; 1/∞ = 0, not NaN).
    assert_eq!(attenuation(att, 1e30), 0.0);
    // All three zero: the cap, not ∞.
    let none = Attenuation { constant: 0.0, linear: 0.0, quadratic: 0.0 };
    assert_eq!(attenuation(none, 0.0), 1e6);
    // d = ∞: 0·∞ would be NaN; a zero coefficient contributes nothing.
    assert_eq!(attenuation(Attenuation::default(), f32::INFINITY), 1.0);
    assert_eq!(
        attenuation(Attenuation { linear: 0.5, ..Attenuation::default() }, f32::INFINITY),
        0.0
    );
    assert_eq!(attenuation(att, f32::NAN), 0.0);
}

#[test]
fn row16_point_and_spot_lights_on_the_point_are_finite() {
    // p at the origin, N = +Y, the light at d·u for d = 0, 1e-30, 1e-10 and u = (0.6, 0.8, 0):
    // L = u while d > 0 (the kit's normalise scales first; glam's would be NaN at 1e-30 and
    // the plain distance would underflow to 0), L = N at d = 0 (documented fallback). Attenuation
    // kc = kl = 0, kq = 1: capped at 1e6. Expected terms from the oracle in f64.
    let att = Attenuation { constant: 0.0, linear: 0.0, quadratic: 1.0 };
    let material = Material { ks: Rgb::splat(0.5), shininess: 10.0, ..Material::default() };
    let n = Vec3::Y;
    let v = unit(0.0, 1.0, 1.0);
    let u = Vec3::new(0.6, 0.8, 0.0);
    let global = Rgb::splat(0.2);
    for d in [0.0f32, 1e-30, 1e-10] {
        let position = u * d;
        assert!(d == 0.0 || position != Vec3::ZERO, "premise: {d}·u is representable");
        let kinds = [
            LightKind::Point { position },
            LightKind::Spot {
                position,
                direction: -Vec3::Y,
                cutoff_deg: 60.0,
                exponent: 2.0,
                inner_deg: None,
            },
        ];
        for kind in kinds {
            let is_spot = matches!(kind, LightKind::Spot { .. });
            let light = Light {
                kind,
                ambient: Rgb::splat(0.1),
                diffuse: Rgb::splat(0.8),
                specular: WHITE,
                attenuation: att,
            };
            let l = if d == 0.0 { n } else { u };
            match light.direction_from(Vec3::ZERO) {
                None => assert_eq!(d, 0.0, "no direction only on the point"),
                Some((l_got, distance)) => {
                    // One rounding of u·d, one of the f64 normalisation: 2ε.
                    assert_approx_eq!(l_got, u, abs = 2.0 * EPS, "d = {d}");
                    assert_approx_eq!(f64::from(distance), f64::from(d), rel = 4.0 * EPS);
                }
            }
            // Oracle: the OpenGL equation in f64 with the documented L and attenuation.
            let (n64, l64, v64) = (n.as_dvec3(), l.as_dvec3(), v.as_dvec3());
            let a = attenuation_oracle(0.0, 0.0, 1.0, f64::from(d));
            let spot = if is_spot { (-l64.dot(-DVec3::Y)).powi(2) } else { 1.0 };
            assert!(!is_spot || -l64.dot(-DVec3::Y) >= 60f64.to_radians().cos(), "in the cone");
            let h = (l64 + v64).normalize();
            let expected_diffuse = a * spot * n64.dot(l64).max(0.0) * 0.8 * 0.8;
            let expected_specular = a * spot * n64.dot(h).max(0.0).powf(10.0) * 0.5;
            let expected_ambient = 0.2 * 0.2 + a * spot * 0.2 * 0.1;
            for model in [
                LightModel::OpenGl { local_viewer: false },
                LightModel::Lecture { specular: Specular::Blinn, local_viewer: false },
            ] {
                let t =
                    shade(model, global, std::slice::from_ref(&light), &material, Vec3::ZERO, n, v);
                assert_finite(&t, &format!("d = {d}, {model:?}"));
                // Relative 8ε: a handful of f32 operations on each term.
                let tol = |x: f64| 8.0 * EPS * x;
                assert_approx_eq!(
                    f64::from(t.diffuse.x),
                    expected_diffuse,
                    abs = tol(expected_diffuse)
                );
                assert_approx_eq!(
                    f64::from(t.specular.x),
                    expected_specular,
                    abs = tol(expected_specular)
                );
                if matches!(model, LightModel::OpenGl { .. }) {
                    assert_approx_eq!(
                        f64::from(t.ambient.x),
                        expected_ambient,
                        abs = tol(expected_ambient)
                    );
                }
            }
        }
    }
    // Far from the origin, an offset of 1e-30 vanishes in f32: the light is on the point.
    let p = Vec3::new(1e6, 0.0, 0.0);
    let light = Light {
        kind: LightKind::Point { position: p + Vec3::new(1e-30, 0.0, 0.0) },
        ambient: Rgb::ZERO,
        diffuse: WHITE,
        specular: WHITE,
        attenuation: att,
    };
    assert_eq!(light.direction_from(p), None);
    let t = shade(LightModel::OpenGl { local_viewer: true }, global, &[light], &material, p, n, v);
    assert_finite(&t, "far");
    assert_approx_eq!(t.diffuse, Rgb::splat(0.8e6), rel = 4.0 * EPS);
}

// ---------------------------------------------------------------------------------------------
// Row 17: spot light with inner = outer cone

/// A unit direction from the light to a point at `deg` degrees from the spot axis −Y, and its L.
fn l_at(deg: f64) -> Vec3 {
    let r = deg.to_radians();
    let from_light = DVec3::new(r.sin(), -r.cos(), 0.0);
    (-from_light).as_vec3()
}

/// The angle from the axis −Y of the f32 direction `l`, in degrees (f64).
fn angle_deg(l: Vec3) -> f64 {
    let d = -l.as_dvec3();
    d.cross(-DVec3::Y).length().atan2(d.dot(-DVec3::Y)).to_degrees()
}

#[test]
fn row17_spot_with_inner_equal_to_cutoff_is_a_hard_step() {
    // The premise: the plain smooth step divides by cos(inner) − cos(cutoff) = 0 (NaN at the rim).
    let c = 30f32.to_radians().cos();
    let naive_t = (c - c) / (c - c);
    assert!(naive_t.is_nan());
    // Oracle: 1 inside the cone (exponent 0), 0 outside, by the f64 angle of the f32 direction;
    // within 1e-5° of the rim (the f32 direction's own resolution is ~3e-6°) either is allowed.
    for exponent in [0.0f32, 2.0] {
        for inner in [Some(30.0f32), Some(45.0), None] {
            let mut inside_count = 0;
            for k in 0..=60_000 {
                let deg = f64::from(k) * 1e-3; // 0° … 60°
                let l = l_at(deg);
                let got = spot_factor(l, -Vec3::Y, 30.0, exponent, inner);
                assert!(got.is_finite() && (0.0..=1.0).contains(&got), "{got} at {deg}°");
                let actual = angle_deg(l);
                if (actual - 30.0).abs() < 1e-5 {
                    continue;
                }
                let expected = if actual < 30.0 {
                    actual.to_radians().cos().powf(f64::from(exponent))
                } else {
                    0.0
                };
                assert_approx_eq!(
                    f64::from(got),
                    expected,
                    abs = 1e-6,
                    "{actual}°, inner {inner:?}"
                );
                inside_count += usize::from(got > 0.0);
            }
            assert!(inside_count > 29_000, "{inside_count}");
        }
    }
    // Exactly on the rim, where the plain step is 0/0: a zero-width cone (cutoff = inner = 0°)
    // lights exactly its axis (cos α = 1 = cos 0° in f64), with 1 and not NaN.
    assert_eq!(spot_factor(Vec3::Y, -Vec3::Y, 0.0, 0.0, Some(0.0)), 1.0);
    assert_eq!(spot_factor(unit(1e-3, 1.0, 0.0), -Vec3::Y, 0.0, 0.0, Some(0.0)), 0.0);
    // Just inside and just outside the rim: full and nothing.
    assert_eq!(spot_factor(l_at(30.0 - 1e-4), -Vec3::Y, 30.0, 0.0, Some(30.0)), 1.0);
    assert_eq!(spot_factor(l_at(30.0 + 1e-4), -Vec3::Y, 30.0, 0.0, Some(30.0)), 0.0);
}

#[test]
fn row17_smooth_step_is_monotone_between_inner_and_cutoff() {
    // inner 20°, cutoff 30°: 1·cosᵉ inside 20°, 0 outside 30°, and between them the Hermite step
    // in cos, t²(3 − 2t), t = (cos α − cos 30°)/(cos 20° − cos 30°) — written here in f64. Never
    // increasing with the angle. Tolerance 1e-6: the kit computes in f64 from the f32 L (angle
    // resolution ~3e-6°, slope of the step ≤ 0.15 per degree) and rounds once.
    for exponent in [0.0f32, 3.0] {
        let mut previous = f32::INFINITY;
        for k in 0..=40_000 {
            let deg = f64::from(k) * 1e-3;
            let l = l_at(deg);
            let got = spot_factor(l, -Vec3::Y, 30.0, exponent, Some(20.0));
            assert!(got <= previous, "not monotone at {deg}°: {got} > {previous}");
            previous = got;
            let a = angle_deg(l).to_radians();
            let (ci, co) = (20f64.to_radians().cos(), 30f64.to_radians().cos());
            let expected = if a.cos() < co {
                0.0
            } else {
                let t = ((a.cos() - co) / (ci - co)).clamp(0.0, 1.0);
                a.cos().powf(f64::from(exponent)) * t * t * (3.0 - 2.0 * t)
            };
            assert_approx_eq!(f64::from(got), expected, abs = 1e-6, "{deg}°");
        }
        assert_eq!(previous, 0.0);
    }
}

#[test]
fn row17_shading_with_equal_cones_and_opengl_ignoring_inner() {
    // Through `shade`: the lecture mode applies the (hard) step, OpenGL mode ignores `inner_deg`
    // and uses its own cone with the exponent. Finite everywhere, 0 outside the cone in both.
    let spot = |inner| Light {
        kind: LightKind::Spot {
            position: Vec3::new(0.0, 5.0, 0.0),
            direction: -Vec3::Y,
            cutoff_deg: 30.0,
            exponent: 1.0,
            inner_deg: inner,
        },
        ambient: Rgb::ZERO,
        diffuse: WHITE,
        specular: Rgb::ZERO,
        attenuation: Attenuation::default(),
    };
    let material = Material::from_color(WHITE);
    let lecture = LightModel::Lecture { specular: Specular::Phong, local_viewer: false };
    let gl = LightModel::OpenGl { local_viewer: false };
    for x in [0.0f32, 1.0, 2.0, 2.8, 2.9, 3.0, 4.0] {
        // tan 30° · 5 = 2.887: x ≤ 2.8 inside, x ≥ 2.9 outside.
        let p = Vec3::new(x, 0.0, 0.0);
        let to_light = (Vec3::new(0.0, 5.0, 0.0) - p).as_dvec3();
        let cos_alpha = to_light.normalize().y;
        let inside = cos_alpha >= 30f64.to_radians().cos();
        let n_dot_l = cos_alpha; // N = +Y
        for (model, inner) in [(lecture, Some(30.0)), (gl, Some(30.0)), (gl, Some(10.0))] {
            let t = shade(model, Rgb::ZERO, &[spot(inner)], &material, p, Vec3::Y, Vec3::Y);
            assert_finite(&t, "spot");
            let gl_factor = if inside { cos_alpha } else { 0.0 };
            assert_approx_eq!(f64::from(t.diffuse.x), gl_factor * n_dot_l, abs = 1e-6, "x = {x}");
        }
    }
}
