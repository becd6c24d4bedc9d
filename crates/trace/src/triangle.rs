//! The ray–triangle test: the *watertight* algorithm of Woop, Benthin and Wald, "Watertight
//! Ray/Triangle Intersection" (JCGT 2013), in the form of pbrt (3rd ed., section 3.6.2), with
//! pbrt's conservative bound on `t` and on the error of the hit point.
//!
//! Why this one and not Möller–Trumbore: the ray is sheared so it runs along +z through the
//! origin, and each edge is tested by a 2D edge function of the sheared corners. Two triangles
//! sharing an edge compute that edge's function from the *same* two corners, with the same
//! operations, so a ray through the shared edge hits at least one of them — no cracks where
//! rays slip between triangles of a closed mesh (Möller–Trumbore computes each triangle's
//! barycentrics from its own first corner, so the two sides round differently). Edge functions
//! that round to exactly 0 are recomputed in f64, so rays through a vertex or along an edge are
//! decided exactly. Hits at `t ≤ Δt`, where `Δt` bounds the rounding error of `t`, are rejected,
//! so a ray spawned off a triangle ([`crate::ray::offset_ray_origin`]) does not hit it again.

use cg_core::glam::Vec3;

use crate::ray::{Ray, gamma};

/// What [`intersect_triangle`] found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    /// The ray parameter of the hit, in `(ray.t_min, ray.t_max]` and above its rounding bound.
    pub t: f32,
    /// Barycentric weights `(b0, b1, b2)` of the corners `p0, p1, p2`; each in `[0, 1]`, summing
    /// to 1 within rounding.
    pub barycentric: Vec3,
    /// The hit point `b0·p0 + b1·p1 + b2·p2`.
    pub p: Vec3,
    /// Bound on the absolute error of `p`, per coordinate: `γ₇·Σᵢ |bᵢ·pᵢ|` (pbrt 3.9.3).
    pub p_error: Vec3,
}

/// The per-ray part of the watertight test: which axis the ray runs along, and the shear that
/// makes it run along +z. Computed once per ray, used for every triangle.
#[derive(Clone, Copy, Debug)]
pub struct RaySetup {
    origin: Vec3,
    t_min: f32,
    /// The far end of the ray; the BVH shrinks it to the closest hit found so far.
    pub(crate) t_max: f32,
    /// The axes permuted to x, y, z: z is the direction's largest component.
    k: [usize; 3],
    shear: Vec3,
}

impl RaySetup {
    /// The setup for `ray` (its direction must be non-zero and finite).
    #[must_use]
    pub fn new(ray: &Ray) -> RaySetup {
        let d = ray.direction;
        let a = d.abs();
        let kz = if a.x > a.y {
            if a.x > a.z { 0 } else { 2 }
        } else if a.y > a.z {
            1
        } else {
            2
        };
        let kx = (kz + 1) % 3;
        let ky = (kx + 1) % 3;
        let (dx, dy, dz) = (d[kx], d[ky], d[kz]);
        RaySetup {
            origin: ray.origin,
            t_min: ray.t_min,
            t_max: ray.t_max,
            k: [kx, ky, kz],
            shear: Vec3::new(-dx / dz, -dy / dz, 1.0 / dz),
        }
    }
}

/// Intersects the ray of `setup` with triangle `(p0, p1, p2)` (both sides), by the watertight
/// algorithm (see the module docs). Returns the hit when there is one with `t` in
/// `(t_min, t_max]` and above the bound on its rounding error, `None` otherwise.
///
/// A degenerate triangle (zero area, seen edge-on) is never hit: its determinant is 0. Non-finite
/// corners give no hit.
#[must_use]
#[inline]
pub fn intersect_triangle(setup: &RaySetup, p0: Vec3, p1: Vec3, p2: Vec3) -> Option<TriangleHit> {
    let [kx, ky, kz] = setup.k;
    let permute = |p: Vec3| {
        let q = p - setup.origin;
        Vec3::new(q[kx], q[ky], q[kz])
    };
    let (mut a, mut b, mut c) = (permute(p0), permute(p1), permute(p2));
    let s = setup.shear;
    a.x += s.x * a.z;
    a.y += s.y * a.z;
    b.x += s.x * b.z;
    b.y += s.y * b.z;
    c.x += s.x * c.z;
    c.y += s.y * c.z;

    // Edge functions: e0 is opposite p0, so it weights p0.
    let mut e0 = b.x * c.y - b.y * c.x;
    let mut e1 = c.x * a.y - c.y * a.x;
    let mut e2 = a.x * b.y - a.y * b.x;
    if e0 == 0.0 || e1 == 0.0 || e2 == 0.0 {
        let d = |p: Vec3, q: Vec3| {
            (f64::from(p.x) * f64::from(q.y) - f64::from(p.y) * f64::from(q.x)) as f32
        };
        e0 = d(b, c);
        e1 = d(c, a);
        e2 = d(a, b);
    }
    if (e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0) {
        return None;
    }
    let det = e0 + e1 + e2;
    if det == 0.0 || !det.is_finite() {
        return None;
    }

    a.z *= s.z;
    b.z *= s.z;
    c.z *= s.z;
    let t_scaled = e0 * a.z + e1 * b.z + e2 * c.z;
    if det < 0.0 && (t_scaled >= 0.0 || t_scaled < setup.t_max * det) {
        return None;
    }
    if det > 0.0 && (t_scaled <= 0.0 || t_scaled > setup.t_max * det) {
        return None;
    }
    let inv_det = 1.0 / det;
    let t = t_scaled * inv_det;

    // pbrt 3.9.4: a conservative bound Δt on the error of t; only t > Δt counts as in front.
    let max_zt = a.z.abs().max(b.z.abs()).max(c.z.abs());
    let delta_z = gamma(3) * max_zt;
    let max_xt = a.x.abs().max(b.x.abs()).max(c.x.abs());
    let max_yt = a.y.abs().max(b.y.abs()).max(c.y.abs());
    let delta_x = gamma(5) * (max_xt + max_zt);
    let delta_y = gamma(5) * (max_yt + max_zt);
    let delta_e = 2.0 * (gamma(2) * max_xt * max_yt + delta_y * max_xt + delta_x * max_yt);
    let max_e = e0.abs().max(e1.abs()).max(e2.abs());
    let delta_t =
        3.0 * (gamma(3) * max_e * max_zt + delta_e * max_zt + delta_z * max_e) * inv_det.abs();
    if t <= delta_t || t <= setup.t_min || t > setup.t_max {
        return None;
    }

    let barycentric = Vec3::new(e0 * inv_det, e1 * inv_det, e2 * inv_det);
    let p = barycentric.x * p0 + barycentric.y * p1 + barycentric.z * p2;
    let abs_sum =
        (barycentric.x * p0).abs() + (barycentric.y * p1).abs() + (barycentric.z * p2).abs();
    Some(TriangleHit { t, barycentric, p, p_error: gamma(7) * abs_sum })
}
