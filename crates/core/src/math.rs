//! Robust scalar and vector primitives that the rest of the kit builds on.
//!
//! Each function states what it guarantees and what it does on zero, non-finite and degenerate
//! input. Where glam's own operation is fragile (its `normalize` returns NaN for tiny vectors and
//! 0 for huge ones, `Vec3A::cross` may fuse multiply-adds so `cross(v, v) != 0`), the kit uses the
//! functions here instead.

use glam::{DVec3, Vec3};

/// `a·b − c·d` with Kahan's algorithm: the error is at most 1.5 ulp of the result, even when the
/// two products nearly cancel (a plain `a * b - c * d` can lose every significant bit).
///
/// Uses [`f32::mul_add`]; on hardware with FMA that is one instruction, elsewhere a correctly
/// rounded library call (slower, same result).
///
/// Non-finite input gives a non-finite result, as the plain expression would.
///
/// See also [`cross_kahan`], and pbrt-v4's `DifferenceOfProducts`.
#[must_use]
#[inline]
pub fn difference_of_products(a: f32, b: f32, c: f32, d: f32) -> f32 {
    let cd = c * d;
    // err is exactly c·d − round(c·d)
    let err = (-c).mul_add(d, cd);
    let dop = a.mul_add(b, -cd);
    dop + err
}

/// The cross product `a × b` with every component from [`difference_of_products`] (≤ 1.5 ulp each).
///
/// `cross_kahan(v, v)` and `cross_kahan(v, -v)` are exactly zero for every finite `v`.
///
/// See also [`cross_f64`] (more accurate, also exact-zero on parallel input) and
/// [`Vec3::cross`] (fast, may lose all bits on nearly parallel input).
#[must_use]
#[inline]
pub fn cross_kahan(a: Vec3, b: Vec3) -> Vec3 {
    Vec3::new(
        difference_of_products(a.y, b.z, a.z, b.y),
        difference_of_products(a.z, b.x, a.x, b.z),
        difference_of_products(a.x, b.y, a.y, b.x),
    )
}

/// The f64 sibling of [`difference_of_products`]: `a·b − c·d` within 1.5 ulp, and exactly 0 when
/// `a·b = c·d` exactly.
#[must_use]
#[inline]
pub fn difference_of_products_f64(a: f64, b: f64, c: f64, d: f64) -> f64 {
    let cd = c * d;
    // err is exactly c·d − round(c·d)
    let err = (-c).mul_add(d, cd);
    let dop = a.mul_add(b, -cd);
    dop + err
}

/// The f64 sibling of [`cross_kahan`]: every component from [`difference_of_products_f64`].
#[must_use]
#[inline]
pub fn cross_kahan_f64(a: DVec3, b: DVec3) -> DVec3 {
    DVec3::new(
        difference_of_products_f64(a.y, b.z, a.z, b.y),
        difference_of_products_f64(a.z, b.x, a.x, b.z),
        difference_of_products_f64(a.x, b.y, a.y, b.x),
    )
}

/// The cross product `a × b` computed in f64 and rounded once to f32.
///
/// The products of two f32 values are exact in f64, so each component is the correctly rounded
/// f32 of the exact value up to one f64 rounding (≤ 0.5 ulp + 2⁻²⁹ ulp). `cross_f64(v, v) == 0`.
#[must_use]
#[inline]
pub fn cross_f64(a: Vec3, b: Vec3) -> Vec3 {
    a.as_dvec3().cross(b.as_dvec3()).as_vec3()
}

/// `v / |v|` for every finite, non-zero `v`, however large or small; `None` for the zero vector
/// and for any non-finite component (±∞, NaN).
///
/// The vector is first divided by its largest absolute component, so the squared length can
/// neither overflow (|v| > 1.8e19) nor underflow (|v| < 1e-19) — where glam's `normalize`
/// returns 0 or NaN. The result has length 1 within 2 ulp.
///
/// See also [`try_normalize_f64`], [`normalize_or`].
#[must_use]
#[inline]
pub fn try_normalize(v: Vec3) -> Option<Vec3> {
    if !v.is_finite() {
        return None;
    }
    let m = v.abs().max_element();
    if m == 0.0 {
        return None;
    }
    let u = v / m;
    Some(u / u.length())
}

/// The f64 sibling of [`try_normalize`], with the same promises.
#[must_use]
#[inline]
pub fn try_normalize_f64(v: DVec3) -> Option<DVec3> {
    if !v.is_finite() {
        return None;
    }
    let m = v.abs().max_element();
    if m == 0.0 {
        return None;
    }
    let u = v / m;
    Some(u / u.length())
}

/// Below this squared length [`try_unit_and_length_f64`] takes [`try_normalize_f64`]'s way:
/// a component whose square underflows could then matter.
pub const DIRECT_UNIT_MIN: f64 = f64::from_bits((1023 - 600) << 52);

/// `v/|v|` and `|v|` in f64, or `None` for a zero or non-finite `v`: the unit vector the
/// lights' directions (L, V) and the interpolated normals use, in the cheap form
/// `v · (1/√(v·v))` — one square root and one division for the three components, where
/// [`try_normalize_f64`] divides six times — whenever `v·v` lies in `[2⁻⁶⁰⁰, f64::MAX]`.
///
/// Every vector those callers pass qualifies: its components are zero or differences of two
/// f32s, or sums of products of two f32s, so of magnitude within `[2⁻²⁹⁸, 2²⁶⁰]`, and neither
/// the squares nor the sum can overflow or lose anything to underflow. Each component is within
/// 5 units of f64 rounding (u = 2⁻⁵³, relative) of the exact unit vector's, and
/// [`try_normalize_f64`]'s within 6: rounded to f32 the two agree, but where a component lies
/// within 2⁻⁴⁹ (relative) of an f32 rounding boundary, and differ there by one ulp of f32.
/// Where `v·v` lies outside that range it is [`try_normalize_f64`] with `v.length()`. `|v|` is
/// `DVec3::length`'s, bit for bit.
#[must_use]
#[inline]
pub fn try_unit_and_length_f64(v: DVec3) -> Option<(DVec3, f64)> {
    let squared = v.length_squared();
    if (DIRECT_UNIT_MIN..f64::INFINITY).contains(&squared) {
        let length = squared.sqrt();
        Some((v * (1.0 / length), length))
    } else {
        try_normalize_f64(v).map(|u| (u, v.length()))
    }
}

/// [`try_normalize`], or `fallback` (returned as given) when `v` is zero or not finite.
#[must_use]
#[inline]
pub fn normalize_or(v: Vec3, fallback: Vec3) -> Vec3 {
    try_normalize(v).unwrap_or(fallback)
}

/// An angle in degrees reduced to `[0, 360)`, as the course wraps `camera_yaw`.
///
/// Exact for every finite input (`rem_euclid` is exact); a result that would round up to 360
/// (tiny negative input) is returned as 0. Non-finite input is returned unchanged.
#[must_use]
pub fn wrap_degrees(angle_deg: f32) -> f32 {
    if !angle_deg.is_finite() {
        return angle_deg;
    }
    let r = angle_deg.rem_euclid(360.0);
    if r >= 360.0 { 0.0 } else { r }
}

/// The angle between two non-zero vectors in radians, computed in f64 with `atan2(|a×b|, a·b)`
/// (accurate for nearly parallel and nearly opposite vectors, unlike `acos(a·b)`).
///
/// Returns `None` when either vector is zero or not finite.
#[must_use]
pub fn angle_between(a: Vec3, b: Vec3) -> Option<f64> {
    let a = try_normalize_f64(a.as_dvec3())?;
    let b = try_normalize_f64(b.as_dvec3())?;
    Some(a.cross(b).length().atan2(a.dot(b)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn difference_of_products_survives_cancellation() {
        // a·b and c·d agree in all but the last bits: the naive f32 result is 0 or garbage.
        let a = 1.0 + f32::EPSILON;
        let b = 1.0 - f32::EPSILON;
        let exact = f64::from(a) * f64::from(b) - 1.0;
        let got = difference_of_products(a, b, 1.0, 1.0);
        assert_eq!(f64::from(got), exact, "Kahan's form is exact here");
        assert_ne!(f64::from(a * b - 1.0), exact, "the naive form is not (this test's premise)");
    }

    #[test]
    fn kahan_f64_is_exactly_zero_for_equal_products() {
        let (a, b) = (0.1f64, 0.3f64);
        assert_eq!(difference_of_products_f64(a, b, b, a), 0.0);
        // The plain fused form is not: fma(a, b, −round(b·a)) is the rounding error of b·a.
        assert_ne!(a.mul_add(b, -(b * a)), 0.0, "premise: the fused form leaves a residual");
    }

    #[test]
    fn crosses_of_parallel_vectors_are_exactly_zero() {
        let v = Vec3::new(0.1, -3.7e5, 2.5e-7);
        for w in [v, -v, v * 2.0] {
            assert_eq!(cross_kahan(v, w), Vec3::ZERO, "cross_kahan({v}, {w})");
            assert_eq!(cross_f64(v, w), Vec3::ZERO, "cross_f64({v}, {w})");
        }
    }

    #[test]
    fn try_normalize_covers_every_finite_nonzero_magnitude() {
        for e in -45..=38 {
            let v = (glam::DVec3::new(3.0, -4.0, 12.0) / 13.0 * 10f64.powi(e)).as_vec3();
            if v == Vec3::ZERO {
                continue;
            }
            let n = try_normalize(v).unwrap_or_else(|| panic!("None for {v:?}"));
            assert!(
                (n.length() - 1.0).abs() <= 2.0 * f32::EPSILON,
                "|n| = {} for 1e{e}",
                n.length()
            );
            // Below 1e-37 the input itself is subnormal and has lost its direction to rounding.
            if e >= -37 {
                assert!(
                    n.dot(Vec3::new(3.0, -4.0, 12.0) / 13.0) > 0.99999,
                    "direction kept for 1e{e}"
                );
            }
        }
        assert_eq!(try_normalize(Vec3::ZERO), None);
        assert_eq!(try_normalize(Vec3::new(f32::INFINITY, 0.0, 0.0)), None);
        assert_eq!(try_normalize(Vec3::new(0.0, f32::NAN, 1.0)), None);
        assert_eq!(normalize_or(Vec3::ZERO, Vec3::Y), Vec3::Y);
    }

    #[test]
    fn unit_and_length_agrees_with_the_careful_normalisation() {
        use rand::rngs::StdRng;
        use rand::{RngExt, SeedableRng};
        let mut rng = StdRng::seed_from_u64(18);
        // Differences of two f32s of every magnitude (the lights' L and V), subnormals included.
        let f32_value = |rng: &mut StdRng| -> f32 {
            let v = f32::from_bits(rng.random::<u32>() & 0x7fff_ffff);
            let v = if v.is_finite() { v } else { 1.0 };
            if rng.random::<bool>() { v } else { -v }
        };
        let (mut vectors, mut one_ulp) = (0, 0);
        for _ in 0..200_000 {
            let scale = 2f32.powi(rng.random_range(-140..120));
            let a = Vec3::new(f32_value(&mut rng), f32_value(&mut rng), f32_value(&mut rng));
            let b = a + Vec3::new(rng.random(), rng.random(), rng.random()) * scale;
            let v = b.as_dvec3() - a.as_dvec3();
            let (Some((unit, length)), Some(careful)) =
                (try_unit_and_length_f64(v), try_normalize_f64(v))
            else {
                assert!(
                    try_unit_and_length_f64(v).is_none() && try_normalize_f64(v).is_none(),
                    "{v}"
                );
                continue;
            };
            vectors += 1;
            assert_eq!(length.to_bits(), v.length().to_bits(), "{v}");
            for k in 0..3 {
                assert!(
                    (unit[k] - careful[k]).abs() <= 10.0 * f64::EPSILON / 2.0 * careful[k].abs(),
                    "{v}: {unit} against {careful}"
                );
                let (u, c) = (unit[k] as f32, careful[k] as f32);
                assert!(u == c || u.to_bits().abs_diff(c.to_bits()) == 1, "{v}: {u} against {c}");
                one_ulp += usize::from(u != c);
            }
        }
        assert!(vectors > 100_000, "{vectors}");
        // Rounded to f32 they differ only where a component lies next to a rounding boundary.
        assert!(one_ulp * 10_000 < vectors, "{one_ulp} of {vectors}");
        // Zero and non-finite vectors have no direction; tiny and huge ones take the careful way.
        assert_eq!(try_unit_and_length_f64(DVec3::ZERO), None);
        assert_eq!(try_unit_and_length_f64(DVec3::new(f64::NAN, 0.0, 1.0)), None);
        assert_eq!(try_unit_and_length_f64(DVec3::new(f64::INFINITY, 0.0, 1.0)), None);
        for v in [DVec3::new(3e-300, 4e-300, 0.0), DVec3::new(3e200, -4e200, 0.0)] {
            let (unit, _) = try_unit_and_length_f64(v).unwrap();
            assert_eq!(unit, try_normalize_f64(v).unwrap(), "{v}");
            assert!((unit - DVec3::new(0.6, v.y.signum() * 0.8, 0.0)).length() < 1e-15, "{unit}");
        }
    }

    #[test]
    fn wrap_degrees_stays_in_range() {
        assert_eq!(wrap_degrees(370.0), 10.0);
        assert_eq!(wrap_degrees(-10.0), 350.0);
        assert_eq!(wrap_degrees(360.0), 0.0);
        let tiny = wrap_degrees(-1e-7);
        assert!((0.0..360.0).contains(&tiny), "{tiny}");
    }

    #[test]
    fn angle_between_is_accurate_near_parallel() {
        let a = Vec3::X;
        let b = Vec3::new(1.0, 1e-6, 0.0);
        let got = angle_between(a, b).unwrap();
        assert!((got - 1e-6).abs() < 1e-12, "{got}");
        assert!((angle_between(a, -a).unwrap() - std::f64::consts::PI).abs() < 1e-15);
        assert_eq!(angle_between(a, Vec3::ZERO), None);
    }
}
