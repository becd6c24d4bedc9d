//! Rays (レイ) and where spawned rays start: offset off their surface by the rounding-error bound
//! of the hit point, so they never hit that surface again at `t ≈ 0`.
//!
//! ## The offset (after pbrt, 3rd ed., section 3.9)
//!
//! Every hit carries `p_error`, a per-component bound on the absolute error of the computed hit
//! point `p` (see [`crate::Hit::p_error`] for how each surface bounds it). The true surface then
//! lies inside the box `p ± p_error`, and that box lies within distance
//! `δ = |n_g|·p_error = Σᵢ |n_g,ᵢ|·p_error,ᵢ` of `p` along the unit geometric normal `n_g`. A
//! spawned ray starts at
//!
//! ```text
//! p' = p ± δ·n_g        (+ when the new direction leaves on the side n_g points to, − otherwise)
//! ```
//!
//! with each coordinate of `p'` then rounded one more float away from `p` ([`f32::next_up`] /
//! [`f32::next_down`]), so the rounding of `p ± δ·n_g` cannot bring it back inside the box. The
//! offset scales with the magnitude of the hit point (and of the transform that placed the
//! surface), so it works at 1e-3 and at 1e4 alike, unlike a fixed epsilon. The intersection
//! routines then reject their own surface behind such an origin: triangles by the conservative
//! `t > Δt` test of the watertight algorithm, spheres and planes because they are solved in f64,
//! whose rounding (~1e-16 relative) is far below the f32-sized offset.

use cg_core::glam::Vec3;

/// A ray `o + t·d` for `t` in `(t_min, t_max]` (光線). `direction` is unit length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts, in world space.
    pub origin: Vec3,
    /// Unit direction, in world space.
    pub direction: Vec3,
    /// Hits at `t ≤ t_min` are ignored (the near plane for primary rays, 0 for spawned rays).
    pub t_min: f32,
    /// Hits at `t > t_max` are ignored (the far plane, a light's distance, or ∞).
    pub t_max: f32,
    /// Skip the back faces of opaque objects, as the rasterizer's back-face culling does (set on
    /// primary rays when the scene culls back faces; never on spawned rays).
    pub cull_back_faces: bool,
}

impl Ray {
    /// A ray from `origin` along the unit `direction`, for every `t > 0`, culling nothing.
    #[must_use]
    pub fn new(origin: Vec3, direction: Vec3) -> Ray {
        Ray { origin, direction, t_min: 0.0, t_max: f32::INFINITY, cull_back_faces: false }
    }

    /// The point at parameter `t`: `o + t·d`.
    #[must_use]
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.direction
    }
}

/// `γ(n) = n·u / (1 − n·u)` with `u = 2⁻²⁴`, the unit roundoff of f32: the bound on the relative
/// error of `n` successive f32 operations (Higham; pbrt's `gamma`).
#[must_use]
#[inline]
pub fn gamma(n: u32) -> f32 {
    let nu = n as f32 * (f32::EPSILON * 0.5);
    nu / (1.0 - nu)
}

/// Where a ray leaving a hit point in `direction` starts: `p` moved along the unit geometric
/// normal `n_g` by `δ = |n_g|·p_error` to the side `direction` leaves on, then one float further
/// outwards per coordinate (see the module docs).
///
/// A `direction` exactly tangent to the surface (`direction·n_g = 0`) goes to the `n_g` side.
/// Non-finite input gives non-finite output (the callers check hits for finiteness first).
#[must_use]
pub fn offset_ray_origin(p: Vec3, p_error: Vec3, n_g: Vec3, direction: Vec3) -> Vec3 {
    let d = n_g.abs().dot(p_error);
    let side = if direction.dot(n_g) < 0.0 { -n_g } else { n_g };
    let mut origin = p + d * side;
    // One more float outwards, also when the bound is 0 (an exactly computed point): the origin
    // is then strictly on the leaving side.
    for i in 0..3 {
        if side[i] > 0.0 {
            origin[i] = origin[i].next_up();
        } else if side[i] < 0.0 {
            origin[i] = origin[i].next_down();
        }
    }
    origin
}
