//! Face normals (面の法線) and vertex normals (頂点の法線).
//!
//! Face normals are computed in f64 from edge vectors, so needle triangles and triangles far from
//! the origin keep their direction (NUMERICS.md rows 6–7), and a zero-area face has no normal
//! (`None`, row 1) instead of a NaN or a direction made of rounding noise.

use glam::{DVec3, Vec3};

use crate::math::try_normalize_f64;

/// Twice the area of triangle `(a, b, c)`, as a vector along its normal: `(b − a) × (c − a)`,
/// computed in f64 (edges and products) and returned in f64 so the caller can weight by it.
///
/// Counter-clockwise seen from the side the vector points to. Exactly zero for a repeated corner
/// and for exactly collinear corners whose edge vectors are representable in f64.
#[must_use]
#[inline]
pub fn face_area_vector(a: Vec3, b: Vec3, c: Vec3) -> DVec3 {
    let (a, b, c) = (a.as_dvec3(), b.as_dvec3(), c.as_dvec3());
    (b - a).cross(c - a)
}

/// The unit normal of triangle `(a, b, c)`, counter-clockwise front: `normalise((b−a)×(c−a))`.
///
/// Returns `None` for a degenerate triangle — a repeated corner, coincident or collinear corners —
/// that is, when `|(b−a)×(c−a)|` is at most `8·ε₆₄·|b−a|·|c−a|` (f64 rounding noise), and for
/// non-finite corners. Needle triangles (height 1e-6, base 1) are *not* degenerate and get an
/// accurate normal.
///
/// Edge vectors are taken in f64 from the first corner, so a unit triangle translated to 1e6
/// keeps its normal to within what its f32 positions still say.
///
/// See also [`face_area_vector`] for the unnormalised, area-weighted vector.
#[must_use]
pub fn face_normal(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    face_normal_f64(a, b, c).map(|n| n.as_vec3())
}

/// [`face_normal`] in f64, for oracles and for weighting without a second rounding.
#[must_use]
pub fn face_normal_f64(a: Vec3, b: Vec3, c: Vec3) -> Option<DVec3> {
    if !(a.is_finite() && b.is_finite() && c.is_finite()) {
        return None;
    }
    let (a, b, c) = (a.as_dvec3(), b.as_dvec3(), c.as_dvec3());
    let (e1, e2) = (b - a, c - a);
    let n = e1.cross(e2);
    let noise = 8.0 * f64::EPSILON * e1.length() * e2.length();
    if n.length() <= noise {
        return None;
    }
    try_normalize_f64(n)
}

/// How face normals are weighted when averaged into a vertex normal (頂点の法線 = 隣接する面の法線の平均).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Weighting {
    /// Every adjacent face counts the same (the lecture's plain average).
    Uniform,
    /// Faces weighted by their area (面積に応じた加重平均): the unnormalised cross product.
    Area,
    /// Faces weighted by the corner angle at the vertex (Thürmer & Wüthrich 1998).
    #[default]
    Angle,
    /// Nelson Max (1999): `sin α / (|e₁|·|e₂|)`, exact on spheres.
    Max,
}
