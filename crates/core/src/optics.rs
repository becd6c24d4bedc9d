//! Optics for the global terms k_r·I_r and k_t·I_t: mirror reflection, refraction by Snell's law
//! (スネルの法則 n₁ sin θ₁ = n₂ sin θ₂) with total internal reflection, and Fresnel reflectance
//! (exact for dielectrics, and Schlick's approximation).
//!
//! Conventions: `i` is the incident direction, travelling *towards* the surface; `n` is the unit
//! normal on the incident side (`i·n ≤ 0`); `eta = η_i / η_t`, the index of the incident side
//! over the index of the transmitted side. A ray tracer gets all three from a hit with
//! [`Interface::at`], which flips the normal and inverts η for hits from inside.
//!
//! The reflectance F is the fraction of light reflected; the transmitted fraction is
//! `T = 1 − F`, so `F + T = 1` by construction, and F is in `[0, 1]` for every input.
//! Under total internal reflection (全反射) F = 1 and [`refract`] returns `None`.

use glam::{DVec3, Vec3};

use crate::math::try_normalize_f64;

/// The mirror direction of `i` about the unit normal `n`: `i − 2(i·n)n` (正反射方向).
///
/// `i` travels towards the surface; the result travels away from it. The length of `i` is kept
/// (exactly in exact arithmetic; within a few ulp in f32), and `n·r = −n·i`. Either orientation of
/// `n` gives the same result.
///
/// See also [`refract`].
#[must_use]
#[inline]
pub fn reflect(i: Vec3, n: Vec3) -> Vec3 {
    i - 2.0 * i.dot(n) * n
}

/// The refracted direction of `i` at an interface by Snell's law `η_i sin θ_i = η_t sin θ_t`,
/// with `eta = η_i / η_t`; `None` under total internal reflection (全反射, `η sin θ_i > 1`).
///
/// Preconditions: `i` and `n` unit (they are renormalised in f64, so f32 rounding of a unit vector
/// does not move the critical angle), `n` on the incident side (`i·n ≤ 0`; when it is not, `n` is
/// flipped — only its orientation, `eta` is used as given: see [`Interface::at`]), `eta > 0`.
///
/// Computed in f64 with `cos²θ_t = (1 − η²) + η²·cos²θ_i`, which is accurate near grazing
/// incidence and near the critical angle, and with the transmitted direction
/// `t = η·i + (η cos θ_i − cos θ_t)·n`, normalised and rounded once to f32. So the result is unit
/// length within 1 ulp per component, lies in the plane of `i` and `n`, obeys Snell's law within
/// f32 rounding, and the TIR decision is exact for the given f32 inputs up to f64 rounding. At
/// normal incidence and for `eta = 1` the direction is `i` (`cos θ_t = cos θ_i` exactly).
/// Exactly at the critical angle (`cos θ_t = 0`) the result is the grazing tangent direction.
///
/// Returns `None` also when `i` or `n` is zero or not finite, or `eta` is not positive and finite
/// (no direction exists); the caller treats every `None` as total reflection.
///
/// See also [`reflect`], [`Interface::at`], [`fresnel_dielectric`].
#[must_use]
pub fn refract(i: Vec3, n: Vec3, eta: f32) -> Option<Vec3> {
    if !(eta > 0.0 && eta.is_finite()) {
        return None;
    }
    let i = try_normalize_f64(i.as_dvec3())?;
    let mut n = try_normalize_f64(n.as_dvec3())?;
    let mut cos_i = -i.dot(n);
    if cos_i < 0.0 {
        n = -n;
        cos_i = -cos_i;
    }
    let eta = f64::from(eta);
    // η_t = 1 relative to η_i = eta, so this is cos²θ_t itself.
    let cos2_t = scaled_cos2_transmitted(cos_i, eta, 1.0);
    if cos2_t < 0.0 {
        return None;
    }
    let t: DVec3 = eta * i + (eta * cos_i - cos2_t.sqrt()) * n;
    try_normalize_f64(t).map(DVec3::as_vec3)
}

/// Everything a ray tracer needs at a hit on a transparent surface, from either side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interface {
    /// The unit normal on the incident side (`i·n ≤ 0`): the geometric normal when entering, its
    /// opposite when leaving.
    pub n: Vec3,
    /// η of the side the ray comes from.
    pub eta_i: f32,
    /// η of the side the ray goes into.
    pub eta_t: f32,
    /// `eta_i / eta_t`, the ratio [`refract`] takes.
    pub eta: f32,
    /// `cos θ_i = −i·n`, in `[0, 1]`.
    pub cos_i: f32,
    /// `true` when the ray enters the object (it travels against the outward geometric normal).
    pub entering: bool,
}

impl Interface {
    /// The interface a ray travelling in direction `i` meets at a surface with outward
    /// `geometric_normal`, between a medium of index `eta_outside` and the object's `eta_inside`
    /// ([`crate::light::Material::eta`]).
    ///
    /// A hit from inside (`i·n_g > 0`) flips the normal and inverts η (docs/numerics.md row 12); a ray
    /// exactly tangent to the surface (`i·n_g = 0`) counts as entering. `i` and the normal need
    /// not be unit length.
    ///
    /// Returns `None` when `i` or `geometric_normal` is zero or not finite.
    ///
    /// See also [`refract`], [`fresnel_dielectric`], [`schlick`].
    #[must_use]
    pub fn at(i: Vec3, geometric_normal: Vec3, eta_outside: f32, eta_inside: f32) -> Option<Self> {
        let i = try_normalize_f64(i.as_dvec3())?;
        let n_g = try_normalize_f64(geometric_normal.as_dvec3())?;
        let i_dot_n = i.dot(n_g);
        let entering = i_dot_n <= 0.0;
        let (n, eta_i, eta_t) =
            if entering { (n_g, eta_outside, eta_inside) } else { (-n_g, eta_inside, eta_outside) };
        Some(Interface {
            n: n.as_vec3(),
            eta_i,
            eta_t,
            eta: eta_i / eta_t,
            cos_i: i_dot_n.abs().min(1.0) as f32,
            entering,
        })
    }
}

/// `η_t²·cos²θ_t = η_t² − η_i²·sin²θ_i` (Snell's law) as `(η_t − η_i)(η_t + η_i) + η_i²·cos²θ_i`:
/// without `1 − cos²θ_i`, so nothing cancels near normal incidence, and accurate near grazing
/// incidence and the critical angle. Negative under total internal reflection, zero at the
/// critical angle.
#[inline]
fn scaled_cos2_transmitted(cos_i: f64, eta_i: f64, eta_t: f64) -> f64 {
    (eta_t - eta_i) * (eta_t + eta_i) + eta_i * eta_i * cos_i * cos_i
}

/// `cos θ_t` on the transmitted side; `None` under total internal reflection, at the critical
/// angle (`cos θ_t = 0`) and for NaN input.
#[inline]
fn cos_transmitted(cos_i: f64, eta_i: f64, eta_t: f64) -> Option<f64> {
    let nt2_cos2_t = scaled_cos2_transmitted(cos_i, eta_i, eta_t);
    (nt2_cos2_t > 0.0).then(|| nt2_cos2_t.sqrt() / eta_t)
}

/// `|cos|` clamped to `[0, 1]`, NaN taken as 0 (grazing).
#[inline]
fn clean_cos(cos: f32) -> f32 {
    let c = cos.abs();
    if c.is_nan() { 0.0 } else { c.min(1.0) }
}

/// The exact Fresnel reflectance of a dielectric interface for unpolarised light:
/// `F = (r_s² + r_p²) / 2` with
/// `r_s = (η_i cos θ_i − η_t cos θ_t) / (η_i cos θ_i + η_t cos θ_t)` and
/// `r_p = (η_t cos θ_i − η_i cos θ_t) / (η_t cos θ_i + η_i cos θ_t)`.
///
/// `cos_i` is `cos θ_i` on the incident side (its sign is ignored; clamped to 1); `eta_i`, `eta_t`
/// are the indices of the incident and transmitted sides (> 0). Computed in f64.
///
/// F = 1 under total internal reflection and at the critical angle; F = 1 at grazing incidence
/// (`cos_i = 0`); F = 0 when `eta_i == eta_t` (no interface). Always in `[0, 1]`: NaN input gives
/// 1 (everything reflected), never NaN. The transmitted fraction is `1 − F`.
///
/// See also [`schlick`] (faster, approximate), [`Interface::at`].
#[must_use]
pub fn fresnel_dielectric(cos_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    if eta_i == eta_t {
        return 0.0;
    }
    let c = f64::from(clean_cos(cos_i));
    let (ni, nt) = (f64::from(eta_i), f64::from(eta_t));
    let Some(cos_t) = cos_transmitted(c, ni, nt) else {
        return 1.0;
    };
    let r_s = (ni * c - nt * cos_t) / (ni * c + nt * cos_t);
    let r_p = (nt * c - ni * cos_t) / (nt * c + ni * cos_t);
    let f = 0.5 * (r_s * r_s + r_p * r_p);
    if f.is_nan() { 1.0 } else { f.clamp(0.0, 1.0) as f32 }
}

/// Schlick's approximation of [`fresnel_dielectric`]: `F ≈ R₀ + (1 − R₀)(1 − cos θ)⁵` with
/// `R₀ = ((η_i − η_t) / (η_i + η_t))²`.
///
/// `cos θ` is the cosine on the *less dense* side: `cos_i` when going into a denser medium
/// (`eta_i ≤ eta_t`), but the transmitted-side `cos θ_t` when leaving a denser one
/// (`eta_i > eta_t`; docs/numerics.md row 13). Using `cos_i` there ignores total internal reflection
/// and is off by up to 0.96 for glass just past the critical angle.
///
/// `cos_i` as in [`fresnel_dielectric`] (sign ignored, clamped to 1). Returns 1 under total
/// internal reflection and at the critical angle. At normal incidence it equals the exact value,
/// `R₀`. Always in `[0, 1]`: NaN input gives 1. Computed in f32, except `cos θ_t` (f64).
///
/// Error against the exact value for glass (η = 1.5), measured by the row 13 test: at most 0.036
/// absolute and 23.3 % relative, near 85° going in and near 41.6° coming out (the same curve,
/// since the exact F of θ_i inside equals F of θ_t outside).
///
/// See also [`fresnel_dielectric`].
#[must_use]
pub fn schlick(cos_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    let c = clean_cos(cos_i);
    let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
    let cos = if eta_i > eta_t {
        // cos θ_t in f64 (as in `fresnel_dielectric`): near the critical angle cos²θ_t is a
        // small difference of O(1) numbers, and an f32 rounding there would move F by ~1e-3.
        match cos_transmitted(f64::from(c), f64::from(eta_i), f64::from(eta_t)) {
            Some(cos_t) => cos_t as f32,
            None => return 1.0,
        }
    } else {
        c
    };
    let m = 1.0 - cos;
    let f = r0 + (1.0 - r0) * m * m * m * m * m;
    if f.is_nan() { 1.0 } else { f.clamp(0.0, 1.0) }
}
