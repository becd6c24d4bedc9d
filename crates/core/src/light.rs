//! The light model (光のモデル) of lecture 11:
//!
//! ```text
//! I = Ia·ka + Σᵢ Iᵢ·[kd (N·L) + ks (R·V)ⁿ] + kr·Ir + kt·It
//!     環境光      拡散反射光   鏡面反射光(局所)   鏡面反射光・透過光(大域)
//! ```
//!
//! Materials, the four light types of the lecture (平行光源, 点光源, スポットライト光源, 面光源), and
//! the per-term evaluation of the *local* model (局所照明モデル). The global terms `kr·Ir` and
//! `kt·It` need rays: the ray tracer adds them to [`Terms::total`] (see [`crate::optics`]). Every
//! renderer clamps the final colour to `[0, 1]` per channel at the very end, as OpenGL does; the
//! functions here never clamp, so the report and the benchmark can show each term as computed.
//!
//! ## The terms, one function each
//!
//! | term | function | formula |
//! |---|---|---|
//! | 環境光 | [`ambient`] | `Ia·ka` |
//! | 拡散反射光 (Lambert) | [`diffuse`] | `Iᵢ·kd·max(N·L, 0)` |
//! | 鏡面反射光 (Phong) | [`specular_phong`] | `Iᵢ·ks·max(R·V, 0)ⁿ`, `R = 2(N·L)N − L`, only where `N·L > 0` |
//! | 鏡面反射光 (Blinn) | [`specular_blinn`] | `Iᵢ·ks·max(N·H, 0)ⁿ`, `H = normalise(L + V)`, only where `N·L > 0` |
//! | 減衰 | [`attenuation`] | `1 / max(kc + kl·d + kq·d², 1e-6)` ([`MIN_ATTENUATION_DENOMINATOR`]) |
//! | スポット | [`spot_factor`] | `0` outside the cone, `max(−L·S, 0)^e` inside (× an optional smooth step) |
//!
//! The kit's rule for the specular power: a cosine `≤ 0` (or `N·L ≤ 0`) gives **no** specular,
//! whatever the exponent — also for `n = 0`, where `0⁰ = 1` would give full specular wherever
//! the cosine is ≤ 0. The cosine is clamped *before* `powf` (`(-0.5f32).powf(2.5)` is NaN). The
//! OpenGL specification leaves `0⁰` open; Mesa's fixed-function path follows the same rule (it
//! evaluates the power only when `N·H > 0`).
//!
//! ## The two models of [`shade`]
//!
//! Vectors: `N` the unit normal, `L` the unit vector to the light, `V` the unit vector to the
//! viewer, all in one space (world). `attᵢ` is [`attenuation`] (1 for directional lights) and
//! `spotᵢ` is [`spot_factor`] (1 for lights that are not spot lights). `e` is the emission.
//!
//! [`LightModel::OpenGl`], the OpenGL 1.x fixed-function equation (specification 2.14.1):
//!
//! ```text
//! c = e + ka·Ia + Σᵢ attᵢ·spotᵢ·[ ka·Ia,ᵢ + max(N·L, 0)·kd·Id,ᵢ + fᵢ·max(N·Ĥ, 0)ˢ·ks·Is,ᵢ ]
//!     fᵢ = 1 if N·L > 0 else 0,   Ĥ = normalise(L + V)
//! ```
//!
//! [`LightModel::Lecture`], the lecture's terms:
//!
//! ```text
//! c = e + ka·(Ia + Σᵢ Ia,ᵢ) + Σᵢ attᵢ·spotᵢ·[ max(N·L, 0)·kd·Id,ᵢ + fᵢ·max(X, 0)ⁿ·ks·Is,ᵢ ]
//!     X = R·V (Phong, R = 2(N·L)N − L) or N·Ĥ (Blinn)
//! ```
//!
//! | | `Lecture` | `OpenGl` |
//! |---|---|---|
//! | specular | Phong `(R·V)ⁿ` or Blinn `(N·H)ⁿ` ([`Specular`]) | Blinn `(N·Ĥ)ˢ` |
//! | per-light ambient `ka·Ia,ᵢ` | not attenuated, not spot-scaled (環境光は明るさ一定) | multiplied by `attᵢ·spotᵢ` |
//! | spot cone | GL's cone and exponent × the smooth step of `inner_deg` | GL's cone and exponent; `inner_deg` ignored |
//! | attenuation | on diffuse and specular | on ambient, diffuse and specular |
//! | global ambient, emission, the diffuse formula | the same | the same |
//!
//! With Blinn specular, no attenuation (kc = 1, kl = kq = 0) and no spot lights, the two models
//! give the same colour. In both, an area light is shaded as its [`Light::point_lights`] (which
//! shine only to the front side of the parallelogram).
//!
//! Both take `V` from the caller: the unit vector from the point to the eye for a local viewer,
//! the camera's backward axis (eye space `(0, 0, 1)`) for OpenGL's default infinite viewer
//! ([`LightModel::view_vector`]). GL_COLOR_MATERIAL is the caller's business too: it passes
//! `ka = kd =` the vertex colour ([`Material::from_color`]).
//!
//! ## Degenerate input (docs/numerics.md rows 14–17)
//!
//! - A light exactly on the shaded point has no direction: `L` is taken as `N` (the light falls
//!   straight on) and `d = 0` ([`Light::direction_from`] returns `None`).
//! - `d → 0` with `kc = 0`: the attenuation is capped at `1 / MIN_ATTENUATION_DENOMINATOR = 1e6`,
//!   finite (the final clamp makes such a point white).
//! - Blinn with `L = −V`: `H` does not exist; the specular is 0.
//! - A spot light with `inner_deg == cutoff_deg` is a hard step.

use glam::Vec3;

use crate::Rgb;
use crate::math::{cross_f64, try_normalize, try_normalize_f64, try_unit_and_length_f64};
use crate::optics::reflect;

/// The reflection properties of a surface (物体の反射特性). Every `k` is RGB.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// k_a, ambient reflectance (環境光の反射係数).
    pub ka: Rgb,
    /// k_d, diffuse reflectance (拡散反射係数).
    pub kd: Rgb,
    /// k_s, specular reflectance (鏡面反射係数).
    pub ks: Rgb,
    /// n, the specular exponent (shininess, ハイライトの鋭さ), ≥ 0.
    pub shininess: f32,
    /// k_r, the weight of the mirror-reflected colour I_r (ray tracer only).
    pub kr: Rgb,
    /// k_t, the weight of the transmitted colour I_t (ray tracer only).
    pub kt: Rgb,
    /// η, the refractive index of the inside of the object (屈折率), ≥ 1 for real materials.
    pub eta: f32,
    /// Emitted colour (GL_EMISSION), added unlit.
    pub emission: Rgb,
}

/// Distance attenuation `1 / (kc + kl·d + kq·d²)` of point, spot and area lights.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attenuation {
    /// kc, GL_CONSTANT_ATTENUATION (default 1).
    pub constant: f32,
    /// kl, GL_LINEAR_ATTENUATION (default 0).
    pub linear: f32,
    /// kq, GL_QUADRATIC_ATTENUATION (default 0).
    pub quadratic: f32,
}

/// Where light comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind {
    /// 平行光源: light from one direction, infinitely far away (GL position `(x, y, z, 0)`).
    /// `to_light` points from the surface *towards* the light; it need not be unit length.
    Directional {
        /// From the surface towards the light (GL_POSITION's xyz with w = 0).
        to_light: Vec3,
    },
    /// 点光源: light from a position, in all directions, attenuated with distance.
    Point {
        /// Where the light is.
        position: Vec3,
    },
    /// スポットライト光源: a point light that shines only inside a cone around `direction`.
    Spot {
        /// Where the light is.
        position: Vec3,
        /// The direction the spot points to (need not be unit length).
        direction: Vec3,
        /// Half-angle of the cone in degrees, `(0, 90]`, or 180 for no cone (GL_SPOT_CUTOFF).
        cutoff_deg: f32,
        /// Falloff exponent towards the rim, ≥ 0 (GL_SPOT_EXPONENT).
        exponent: f32,
        /// Optional inner half-angle in degrees: full intensity inside it, a smooth step between it
        /// and `cutoff_deg`; equal angles give a hard step. Ignored in OpenGL-compatible mode.
        inner_deg: Option<f32>,
    },
    /// 面光源: a parallelogram `corner + s·edge_u + t·edge_v` (s, t in [0, 1]) approximated, as the
    /// lecture says, by a grid of `samples[0] × samples[1]` point lights, each carrying
    /// `1 / (samples[0]·samples[1])` of the light's colours.
    Area {
        /// One corner of the parallelogram.
        corner: Vec3,
        /// The first edge from `corner`.
        edge_u: Vec3,
        /// The second edge from `corner`; the light shines to the side of `edge_u × edge_v`.
        edge_v: Vec3,
        /// Point lights along `edge_u` and `edge_v` (each ≥ 1; 0 is taken as 1). The cost is
        /// `samples[0]·samples[1]` point lights per shaded point.
        samples: [u32; 2],
    },
}

/// A light source in world space (the course sets the light after the camera, so it stays fixed in
/// the world). Colours follow OpenGL: separate ambient, diffuse and specular intensities I_i.
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Type and geometry.
    pub kind: LightKind,
    /// Ambient intensity this light adds (GL_AMBIENT).
    pub ambient: Rgb,
    /// Diffuse intensity I_i (GL_DIFFUSE).
    pub diffuse: Rgb,
    /// Specular intensity I_i (GL_SPECULAR).
    pub specular: Rgb,
    /// Distance attenuation (ignored for directional lights).
    pub attenuation: Attenuation,
}

/// The specular term of the lecture's model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Specular {
    /// Phong: `(R·V)ⁿ`, R the mirror direction of L (the lecture's formula).
    #[default]
    Phong,
    /// Blinn: `(N·H)ⁿ`, H = normalise(L + V) (what OpenGL computes).
    Blinn,
}

/// Which equation lights the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightModel {
    /// The lecture's model, term by term (see the module docs).
    Lecture {
        /// Phong (R·V) or Blinn (N·H) specular.
        specular: Specular,
        /// `true`: V points to the eye from each point; `false`: V is the camera's backward axis.
        /// Read by [`LightModel::view_vector`]; [`shade`] takes V from its caller.
        local_viewer: bool,
    },
    /// OpenGL 1.x fixed-function lighting, exactly as its specification (section 2.14.1) states:
    /// Blinn specular with H = normalise(L + V), global ambient, per-light ambient
    /// attenuated and spot-scaled, specular only where N·L > 0, infinite viewer unless
    /// `local_viewer` (GL_LIGHT_MODEL_LOCAL_VIEWER).
    OpenGl {
        /// GL_LIGHT_MODEL_LOCAL_VIEWER. Read by [`LightModel::view_vector`]; [`shade`] takes V
        /// from its caller.
        local_viewer: bool,
    },
}

impl Default for Material {
    /// OpenGL's default material: k_a 0.2, k_d 0.8, k_s 0, n 0, no emission; and the kit's
    /// defaults for the global terms: k_r = k_t = 0, η = 1.
    fn default() -> Material {
        Material {
            ka: Rgb::splat(0.2),
            kd: Rgb::splat(0.8),
            ks: Rgb::ZERO,
            shininess: 0.0,
            kr: Rgb::ZERO,
            kt: Rgb::ZERO,
            eta: 1.0,
            emission: Rgb::ZERO,
        }
    }
}

impl Material {
    /// The material glColor3f gives under GL_COLOR_MATERIAL (GL_AMBIENT_AND_DIFFUSE): k_a = k_d =
    /// `color`, everything else [`Material::default`].
    ///
    /// See also [`Material::with_color`], which keeps the other values of a material.
    #[must_use]
    pub fn from_color(color: Rgb) -> Material {
        Material { ka: color, kd: color, ..Material::default() }
    }

    /// This material with k_a = k_d = `color` and everything else kept: what a vertex colour
    /// (glColor under GL_COLOR_MATERIAL with GL_AMBIENT_AND_DIFFUSE) makes of the object's
    /// material at a point. `None` (no vertex colours) gives the material unchanged.
    ///
    /// See also [`Material::from_color`].
    #[must_use]
    #[inline]
    pub fn with_color(&self, color: Option<Rgb>) -> Material {
        match color {
            Some(c) => Material { ka: c, kd: c, ..self.clone() },
            None => self.clone(),
        }
    }
}

impl Default for Attenuation {
    /// No attenuation: kc = 1, kl = kq = 0 (OpenGL's default).
    fn default() -> Attenuation {
        Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 }
    }
}

/// The smallest attenuation denominator the kit allows: `kc + kl·d + kq·d²` is raised to at
/// least this value, so [`attenuation`] is at most `1e6` (finite when `d → 0` with `kc = 0`).
pub const MIN_ATTENUATION_DENOMINATOR: f32 = 1.0e-6;

/// What evaluations of the light model did, counted *inside* [`shade_with_visibility_counted`]
/// as it does it (not predicted by the caller): the proof of "only what the scene needs". Sums
/// over any number of evaluations (`+=`).
///
/// | counter | counted when |
/// |---|---|
/// | `evaluations` | the light model is evaluated at a point (once per call) |
/// | `lights` | a point light (or one sample of an area light) is visited |
/// | `attenuations` | [`attenuation`] is computed: never for directional lights or OpenGL's default (1, 0, 0) |
/// | `spot_factors` | [`spot_factor`] is computed (spot lights and area-light samples) |
/// | `visibility_queries` | the visibility callback is asked (a light that reaches the point) |
/// | `diffuse` | a diffuse term is computed (the light is visible) |
/// | `specular` | a specular term is computed (visible, and the material's k_s ≠ 0) |
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct LightCounts {
    /// Evaluations of the light model (points lit).
    pub evaluations: u64,
    /// Point lights visited (an area light counts its samples).
    pub lights: u64,
    /// Distance attenuations computed (光の減衰).
    pub attenuations: u64,
    /// Spot factors computed (スポットライト光源, and the front-side test of area-light samples).
    pub spot_factors: u64,
    /// Calls of the visibility callback (a ray tracer's shadow-ray questions).
    pub visibility_queries: u64,
    /// Diffuse terms computed (拡散反射光).
    pub diffuse: u64,
    /// Specular terms computed (鏡面反射光).
    pub specular: u64,
}

impl std::ops::AddAssign for LightCounts {
    fn add_assign(&mut self, o: LightCounts) {
        self.evaluations += o.evaluations;
        self.lights += o.lights;
        self.attenuations += o.attenuations;
        self.spot_factors += o.spot_factors;
        self.visibility_queries += o.visibility_queries;
        self.diffuse += o.diffuse;
        self.specular += o.specular;
    }
}

/// The local terms of the light model at one point, kept apart so the report and the benchmark
/// can show each. RGB, not clamped.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Terms {
    /// The material's emission e (GL_EMISSION), unlit.
    pub emission: Rgb,
    /// 環境光 `Ia·ka` (global and per-light ambient).
    pub ambient: Rgb,
    /// 拡散反射光 `Σ Iᵢ·kd·(N·L)`.
    pub diffuse: Rgb,
    /// 鏡面反射光 (局所照明) `Σ Iᵢ·ks·(R·V)ⁿ` or its Blinn form.
    pub specular: Rgb,
}

impl Terms {
    /// `emission + ambient + diffuse + specular`, not clamped: the ray tracer adds `kr·Ir + kt·It`
    /// to it, and every renderer clamps to `[0, 1]` at the end (as OpenGL does).
    #[must_use]
    pub fn total(&self) -> Rgb {
        self.emission + self.ambient + self.diffuse + self.specular
    }
}

/// 環境光 `Ia·ka` (per channel).
///
/// See also [`shade`], which sums the global and per-light ambient as each model says.
#[must_use]
#[inline]
pub fn ambient(ia: Rgb, ka: Rgb) -> Rgb {
    ia * ka
}

/// 拡散反射光 by Lambert's cosine law (ランバートの余弦則): `Iᵢ·kd·max(N·L, 0)`.
///
/// `n` and `l` are unit vectors; `l` points from the surface towards the light. Light from behind
/// the surface (`N·L ≤ 0`) gives 0; so does a NaN dot product.
///
/// See also [`specular_phong`], [`specular_blinn`].
#[must_use]
#[inline]
pub fn diffuse(intensity: Rgb, kd: Rgb, n: Vec3, l: Vec3) -> Rgb {
    intensity * kd * positive_part(n.dot(l))
}

/// 鏡面反射光 by Phong's model, the lecture's formula: `Iᵢ·ks·max(R·V, 0)ⁿ` with the mirror
/// direction `R = reflect(−L, N) = 2(N·L)N − L`.
///
/// `n`, `l`, `v` are unit vectors; `l` points to the light, `v` to the viewer; `shininess` is n ≥ 0.
///
/// Zero when `N·L ≤ 0` (light from behind) and when `R·V ≤ 0` — also for `n = 0`, where a plain
/// `powf` would give `0⁰ = 1` (docs/numerics.md row 14). `R·V` is clamped to `[0, 1]` *before* `powf`,
/// so a fractional n never meets a negative base (`(-0.5f32).powf(2.5)` is NaN). A negative or
/// NaN `shininess` is taken as 0. Never NaN for finite input.
///
/// See also [`specular_blinn`] (what OpenGL computes), [`crate::optics::reflect`].
#[must_use]
pub fn specular_phong(intensity: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> Rgb {
    if n.dot(l) > 0.0 {
        intensity * ks * specular_power(reflect(-l, n).dot(v), shininess)
    } else {
        Rgb::ZERO
    }
}

/// 鏡面反射光 by Blinn's half vector, as OpenGL computes it: `Iᵢ·ks·max(N·H, 0)ⁿ` with
/// `H = normalise(L + V)`.
///
/// `n`, `l`, `v` are unit vectors; `l` points to the light, `v` to the viewer; `shininess` is n ≥ 0.
///
/// Zero when `N·L ≤ 0`, when `N·H ≤ 0` (also for `n = 0`), and when `L = −V`, where `H` does not
/// exist (docs/numerics.md row 15: glam's `normalize` would return NaN; the kit uses
/// [`try_normalize`]). A negative or NaN `shininess` is taken as 0. Never NaN for finite input.
///
/// See also [`specular_phong`].
#[must_use]
pub fn specular_blinn(intensity: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> Rgb {
    if n.dot(l) > 0.0
        && let Some(h) = try_normalize(l + v)
    {
        intensity * ks * specular_power(n.dot(h), shininess)
    } else {
        Rgb::ZERO
    }
}

/// `max(x, 0)`, with NaN taken as 0.
#[inline]
fn positive_part(x: f32) -> f32 {
    if x > 0.0 { x } else { 0.0 }
}

/// `cosⁿ` for the specular term with the kit's rule: 0 when `cos ≤ 0` (or NaN) whatever n;
/// `cos` clamped to at most 1 so rounding cannot push the factor above 1.
#[inline]
fn specular_power(cos: f32, shininess: f32) -> f32 {
    if cos > 0.0 { cos.min(1.0).powf(positive_part(shininess)) } else { 0.0 }
}

/// Distance attenuation (光の減衰) `1 / (kc + kl·d + kq·d²)`, as OpenGL defines it.
///
/// Precondition: `d ≥ 0`, coefficients ≥ 0 (OpenGL rejects negative ones).
///
/// The denominator is clamped to at least [`MIN_ATTENUATION_DENOMINATOR`] (`1e-6`), so the result
/// is finite and at most `1e6` — also when the light sits on the point (`d = 0`) with `kc = 0`,
/// where the plain formula divides by zero (docs/numerics.md row 16). A term whose coefficient is 0
/// contributes 0 even for `d = ∞` (the plain `0·∞` is NaN), so `d = ∞` gives `1/kc`, or 0 when
/// `kl` or `kq` is positive. NaN input gives 0 (no light). Directional lights are not attenuated
/// ([`Light::needs_attenuation`]).
#[must_use]
pub fn attenuation(att: Attenuation, d: f32) -> f32 {
    fn term(k: f32, x: f32) -> f32 {
        if k == 0.0 { 0.0 } else { k * x }
    }
    let denominator = att.constant + term(att.linear, d) + term(att.quadratic, d * d);
    if denominator.is_nan() {
        return 0.0;
    }
    1.0 / denominator.max(MIN_ATTENUATION_DENOMINATOR)
}

/// The spot light factor (スポットライト光源) for a point that sees the light in unit direction `l`.
///
/// With `cos α = −L·Ŝ` (Ŝ = the normalised `direction`, the angle α between the spot's axis and
/// the ray from the light to the point), OpenGL's rule (specification 2.14.1):
/// - `cutoff_deg = 180`: 1 (no cone; `exponent` and `inner_deg` are ignored);
/// - outside the cone, `cos α < cos(cutoff)`: 0;
/// - inside: `max(cos α, 0)^exponent`.
///
/// `inner_deg` (the lecture mode's extension; OpenGL mode passes `None`) multiplies the inside
/// value by a smooth step in `cos α`: 1 for `α ≤ inner`, 0 at `α = cutoff`, Hermite
/// `t²(3 − 2t)` with `t = (cos α − cos cutoff) / (cos inner − cos cutoff)` in between. When
/// `inner ≥ cutoff` (in particular `inner == cutoff`) there is no band: a hard step at the cone,
/// without the division by zero of the plain smooth step (docs/numerics.md row 17).
///
/// Angles in degrees; `cutoff_deg` is clamped to `[0, 90]` except that any value above 90 (OpenGL
/// accepts only 180 there) or NaN means no cone; `inner_deg` is clamped to `[0, cutoff]`. The
/// cosines are computed in f64, so `cutoff_deg = 90` is the half-space `cos α > 0`. A negative or
/// NaN `exponent` is taken as 0. A zero or non-finite `direction` gives 0 (the spot lights
/// nothing).
#[must_use]
pub fn spot_factor(
    l: Vec3,
    direction: Vec3,
    cutoff_deg: f32,
    exponent: f32,
    inner_deg: Option<f32>,
) -> f32 {
    if cutoff_deg.is_nan() || cutoff_deg > 90.0 {
        return 1.0;
    }
    let Some(s) = try_normalize_f64(direction.as_dvec3()) else {
        return 0.0;
    };
    let cos_alpha = -l.as_dvec3().dot(s);
    let cutoff = f64::from(cutoff_deg.max(0.0));
    let cos_cutoff = cutoff.to_radians().cos();
    if cos_alpha.is_nan() || cos_alpha < cos_cutoff {
        return 0.0;
    }
    // cos α ≥ cos(90°) = 6.1e-17 > 0 here, so the power never sees 0⁰ or a negative base.
    let mut factor = cos_alpha.min(1.0).powf(f64::from(positive_part(exponent)));
    if let Some(inner_deg) = inner_deg {
        let inner = f64::from(inner_deg.max(0.0));
        if inner < cutoff {
            let cos_inner = inner.to_radians().cos();
            // cos is strictly decreasing on [0°, 90°]: cos_inner > cos_cutoff, no division by 0.
            let t = ((cos_alpha - cos_cutoff) / (cos_inner - cos_cutoff)).clamp(0.0, 1.0);
            factor *= t * t * (3.0 - 2.0 * t);
        }
    }
    factor as f32
}

impl Light {
    /// The unit direction L from `p` towards the light, and the distance d to it (`f32::INFINITY`
    /// for a directional light). For an area light, towards its centre ([`shade`] uses
    /// [`Light::point_lights`] instead).
    ///
    /// Computed in f64 from the f32 positions, so lights very close to `p` (1e-30) or very far
    /// away keep an exact direction and distance.
    ///
    /// Returns `None` when there is no direction: the light sits exactly on `p`, a directional
    /// light has a zero `to_light`, or a coordinate is not finite. [`shade`] then takes `L = N`
    /// and `d = 0` (docs/numerics.md row 16).
    #[must_use]
    pub fn direction_from(&self, p: Vec3) -> Option<(Vec3, f32)> {
        let position = match &self.kind {
            LightKind::Directional { to_light } => {
                return try_normalize(*to_light).map(|l| (l, f32::INFINITY));
            }
            LightKind::Point { position } | LightKind::Spot { position, .. } => *position,
            LightKind::Area { corner, edge_u, edge_v, .. } => *corner + 0.5 * (*edge_u + *edge_v),
        };
        let (l, d) = try_unit_and_length_f64(position.as_dvec3() - p.as_dvec3())?;
        Some((l.as_vec3(), d as f32))
    }

    /// Whether the light's distance attenuation changes anything: never for a directional light
    /// (OpenGL's `att = 1`), and not when the coefficients are OpenGL's default (1, 0, 0).
    #[must_use]
    pub fn needs_attenuation(&self) -> bool {
        !matches!(self.kind, LightKind::Directional { .. })
            && self.attenuation != Attenuation::default()
    }

    /// The point lights that stand for this light, as the lecture says of 面光源 (沢山の点光源の
    /// 集まりと考える): for an area light, one per cell of its `samples[0] × samples[1]` grid, at
    /// the cell centre `corner + (i + ½)/samples[0]·edge_u + (j + ½)/samples[1]·edge_v`, each
    /// with the light's ambient, diffuse and specular colours divided by the sample count and the
    /// light's attenuation. Every other light yields itself, once.
    ///
    /// The area light shines to the side of `edge_u × edge_v` only: each sample is a
    /// [`LightKind::Spot`] with that axis, `cutoff_deg = 90` and `exponent = 0` (a point light
    /// limited to the front half-space). A degenerate parallelogram (parallel or zero edges) has
    /// no front side; its samples are plain [`LightKind::Point`] lights.
    ///
    /// A sample count of 0 is taken as 1 (no panic on a scene's data; the scene loader reports
    /// it). The cost of shading is one point light per sample.
    pub fn point_lights(&self) -> impl Iterator<Item = Light> + '_ {
        let single = match self.kind {
            LightKind::Area { .. } => None,
            _ => Some(self.clone()),
        };
        let grid = match self.kind {
            LightKind::Area { corner, edge_u, edge_v, samples } => {
                let [nu, nv] = samples.map(|s| u64::from(s.max(1)));
                let axis = try_normalize(cross_f64(edge_u, edge_v));
                let share = (1.0 / (nu as f64 * nv as f64)) as f32;
                Some((corner, edge_u, edge_v, nu, nv, axis, share))
            }
            _ => None,
        };
        let count = grid.map_or(0, |(_, _, _, nu, nv, _, _)| nu.saturating_mul(nv));
        single.into_iter().chain((0..count).filter_map(move |k| {
            let (corner, edge_u, edge_v, nu, nv, axis, share) = grid?;
            let (i, j) = (k % nu, k / nu);
            let s = ((i as f64 + 0.5) / nu as f64) as f32;
            let t = ((j as f64 + 0.5) / nv as f64) as f32;
            let position = corner + s * edge_u + t * edge_v;
            let kind = match axis {
                Some(direction) => LightKind::Spot {
                    position,
                    direction,
                    cutoff_deg: 90.0,
                    exponent: 0.0,
                    inner_deg: None,
                },
                None => LightKind::Point { position },
            };
            Some(Light {
                kind,
                ambient: self.ambient * share,
                diffuse: self.diffuse * share,
                specular: self.specular * share,
                attenuation: self.attenuation,
            })
        }))
    }
}

impl LightModel {
    /// Whether V points to the eye from each point (GL_LIGHT_MODEL_LOCAL_VIEWER).
    #[must_use]
    pub fn local_viewer(self) -> bool {
        match self {
            LightModel::Lecture { local_viewer, .. } | LightModel::OpenGl { local_viewer } => {
                local_viewer
            }
        }
    }

    /// The unit vector V towards the viewer that [`shade`] expects at point `p`, all in world
    /// space: `normalise(eye − p)` for a local viewer, otherwise `backward` — the camera's
    /// backward axis (its +Z, eye space `(0, 0, 1)`: OpenGL's infinite viewer), assumed unit.
    ///
    /// A local viewer whose eye sits exactly on `p` falls back to `backward`.
    #[must_use]
    pub fn view_vector(self, p: Vec3, eye: Vec3, backward: Vec3) -> Vec3 {
        if self.local_viewer() {
            try_unit_and_length_f64(eye.as_dvec3() - p.as_dvec3())
                .map_or(backward, |(v, _)| v.as_vec3())
        } else {
            backward
        }
    }
}

/// The local light model at point `p`: emission, ambient, diffuse and specular, evaluated by
/// `model` (see the module docs for both equations and how they differ).
///
/// `p`, `n`, `v` are in one space (world, where the lights are); `n` is the unit normal, `v` the
/// unit vector towards the viewer ([`LightModel::view_vector`]: for an infinite viewer the
/// camera's backward axis). `global_ambient` is Ia (GL_LIGHT_MODEL_AMBIENT). Area lights are
/// shaded as their [`Light::point_lights`]. Specular work is skipped when `ks = 0`.
///
/// Degenerate cases: a light exactly on `p` lights it along `N` with `d = 0` and the capped
/// [`attenuation`]; `L = −V` gives no Blinn specular; every factor is finite, so the terms are
/// finite for finite input. The result is not clamped ([`Terms::total`]).
#[must_use]
pub fn shade(
    model: LightModel,
    global_ambient: Rgb,
    lights: &[Light],
    material: &Material,
    p: Vec3,
    n: Vec3,
    v: Vec3,
) -> Terms {
    shade_with_visibility(model, global_ambient, lights, material, p, n, v, |_, _, _| 1.0)
}

/// [`shade`] with shadows: `visibility(light, l, d)` is called once per point light (each sample
/// of an area light) that reaches `p` with a non-zero attenuation and spot factor, with the unit
/// direction `l` from `p` towards it and its distance `d` (∞ for directional lights), and
/// returns the fraction of it that is not blocked, in `[0, 1]` (a ray tracer casts a shadow ray
/// there). It scales that light's diffuse and specular terms; ambient light is never shadowed.
/// A visibility of exactly 0 skips the light's diffuse and specular work.
///
/// `shade(..)` is `shade_with_visibility(.., |_, _, _| 1.0)`.
///
/// See also [`shade_with_visibility_counted`], which also counts the work it does.
#[must_use]
#[allow(clippy::too_many_arguments)]
pub fn shade_with_visibility(
    model: LightModel,
    global_ambient: Rgb,
    lights: &[Light],
    material: &Material,
    p: Vec3,
    n: Vec3,
    v: Vec3,
    visibility: impl FnMut(&Light, Vec3, f32) -> f32,
) -> Terms {
    let mut counts = LightCounts::default();
    shade_with_visibility_counted(
        model,
        global_ambient,
        lights,
        material,
        p,
        n,
        v,
        visibility,
        &mut counts,
    )
}

/// [`shade_with_visibility`], adding to `counts` what it does as it does it ([`LightCounts`]):
/// the renderers report these counts, so "no specular work when every k_s is 0" and "no
/// attenuation for directional lights" are measured where the work happens. The same terms,
/// bit for bit.
#[must_use]
#[allow(clippy::too_many_arguments)]
pub fn shade_with_visibility_counted(
    model: LightModel,
    global_ambient: Rgb,
    lights: &[Light],
    material: &Material,
    p: Vec3,
    n: Vec3,
    v: Vec3,
    mut visibility: impl FnMut(&Light, Vec3, f32) -> f32,
    counts: &mut LightCounts,
) -> Terms {
    counts.evaluations += 1;
    let (lecture, specular_kind) = match model {
        LightModel::Lecture { specular, .. } => (true, specular),
        LightModel::OpenGl { .. } => (false, Specular::Blinn),
    };
    let mut terms = Terms { emission: material.emission, ..Terms::default() };
    if lecture {
        // 環境光は明るさ一定: neither attenuated nor spot-scaled.
        let ia = lights.iter().fold(global_ambient, |sum, light| sum + light.ambient);
        terms.ambient = ambient(ia, material.ka);
    } else {
        terms.ambient = ambient(global_ambient, material.ka);
    }
    let with_specular = material.ks != Rgb::ZERO;
    for light in lights.iter().flat_map(Light::point_lights) {
        counts.lights += 1;
        let (l, d) = light.direction_from(p).unwrap_or((n, 0.0));
        // Only what the light needs: no attenuation arithmetic for directional lights and for
        // OpenGL's default (1, 0, 0), whose factor is exactly 1.
        let att = if light.needs_attenuation() {
            counts.attenuations += 1;
            attenuation(light.attenuation, d)
        } else {
            1.0
        };
        let spot = match light.kind {
            LightKind::Spot { direction, cutoff_deg, exponent, inner_deg, .. } => {
                counts.spot_factors += 1;
                spot_factor(l, direction, cutoff_deg, exponent, inner_deg.filter(|_| lecture))
            }
            _ => 1.0,
        };
        let scale = att * spot;
        if scale == 0.0 {
            continue;
        }
        if !lecture {
            terms.ambient += scale * ambient(light.ambient, material.ka);
        }
        counts.visibility_queries += 1;
        let seen = visibility(&light, l, d);
        if seen <= 0.0 || seen.is_nan() {
            continue;
        }
        let scale = scale * seen.min(1.0);
        counts.diffuse += 1;
        terms.diffuse += scale * diffuse(light.diffuse, material.kd, n, l);
        if with_specular {
            counts.specular += 1;
            let (ks, shininess) = (material.ks, material.shininess);
            terms.specular += scale
                * match specular_kind {
                    Specular::Phong => specular_phong(light.specular, ks, n, l, v, shininess),
                    Specular::Blinn => specular_blinn(light.specular, ks, n, l, v, shininess),
                };
        }
    }
    terms
}

#[cfg(test)]
mod tests;
