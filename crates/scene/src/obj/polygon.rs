//! An OBJ face of four or more corners into triangles. tobj alone splits every polygon as a fan
//! from its first corner, which folds a concave face: part of the fan lies outside the polygon,
//! facing the other way, and part of the polygon is left uncovered — a wrong picture, drawn
//! without a word. Here:
//!
//! - where the fan covers the polygon exactly (every convex face, and a concave one whose first
//!   corner sees every other), it is kept, triangle for triangle as tobj made it;
//! - otherwise a polygon that does not cross or touch itself is split by ear clipping
//!   (the `earcut` crate) in its plane, every triangle turned as the polygon is, and checked to
//!   cover exactly the polygon's area;
//! - a polygon that crosses itself has no inside to split, and is an error, as is a concave one
//!   of more than [`MAX_CONCAVE_CORNERS`] corners (bounded time).
//!
//! The plane: the polygon's area vector (Newell's normal, `Σ (pᵢ − p₀) × (pᵢ₊₁ − p₀)`, in f64),
//! and the polygon projected along its largest axis, so that a non-planar face (a twisted quad)
//! is split as it looks from that side.

use cg_core::glam::{DVec2, DVec3, Vec3};
use earcut::Earcut;

/// The most corners of a face that its fan would fold (a concave face): the test that it does
/// not cross itself compares every pair of its edges.
pub const MAX_CONCAVE_CORNERS: usize = 1024;

/// Why an OBJ face of four or more corners could not be split into triangles
/// ([`crate::ErrorKind::ObjPolygon`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PolygonProblem {
    /// Two of its edges cross or touch (a bow tie, a star, a corner on another edge): it has no
    /// inside to split.
    Crosses,
    /// Concave, with more than [`MAX_CONCAVE_CORNERS`] corners.
    TooManyCorners {
        /// [`MAX_CONCAVE_CORNERS`].
        max: usize,
    },
    /// Ear clipping gave triangles that do not cover it exactly (corners or edges within
    /// rounding of one another).
    NotCovered,
}

/// Splits polygons; keeps earcut's buffers from one polygon to the next.
#[derive(Default)]
pub(crate) struct Splitter {
    earcut: Earcut<f64>,
    points: Vec<DVec2>,
    kept: Vec<usize>,
    ring: Vec<DVec2>,
    triangles: Vec<u32>,
}

impl Splitter {
    /// Appends to `out` the triangles of the polygon whose corners are the vertices `corners`
    /// (at `positions`), in order.
    pub(crate) fn split(
        &mut self,
        corners: &[u32],
        positions: &[Vec3],
        out: &mut Vec<[u32; 3]>,
    ) -> Result<(), PolygonProblem> {
        let fan = |out: &mut Vec<[u32; 3]>| {
            out.extend(corners.windows(2).skip(1).map(|w| [corners[0], w[0], w[1]]));
        };
        let p = |i: usize| positions[corners[i] as usize].as_dvec3();
        let n = corners.len();
        let fan_area = |i: usize| (p(i) - p(0)).cross(p(i + 1) - p(0));
        let normal = (1..n - 1).fold(DVec3::ZERO, |sum, i| sum + fan_area(i));
        let Some(axes) = plane(normal) else {
            // No area at all. Every corner on one line: nothing to fold, and nothing to draw
            // (the fan's triangles are degenerate, as before). Otherwise its parts cancel, as a
            // bow tie's two halves do: a polygon that does not cross itself has an area.
            if (1..n - 1).all(|i| fan_area(i) == DVec3::ZERO) {
                fan(out);
                return Ok(());
            }
            return Err(PolygonProblem::Crosses);
        };
        self.points.clear();
        self.points.extend((0..n).map(|i| axes(p(i))));
        if fan_covers(&self.points) {
            fan(out);
            return Ok(());
        }
        if n > MAX_CONCAVE_CORNERS {
            return Err(PolygonProblem::TooManyCorners { max: MAX_CONCAVE_CORNERS });
        }
        // Corners at the same place as the one before add nothing (earcut drops them too).
        self.kept.clear();
        for i in 0..n {
            let previous = self.kept.last().copied().unwrap_or(n - 1);
            if self.points[i] != self.points[previous] {
                self.kept.push(i);
            }
        }
        self.ring.clear();
        self.ring.extend(self.kept.iter().map(|&i| self.points[i]));
        let ring = &self.ring;
        if crosses(ring) {
            return Err(PolygonProblem::Crosses);
        }
        self.earcut.earcut(ring.iter().map(|q| q.to_array()), &[] as &[u32], &mut self.triangles);
        let area = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a) / 2.0;
        let polygon: f64 = (1..ring.len() - 1).map(|i| area(ring[0], ring[i], ring[i + 1])).sum();
        let mut covered = 0.0;
        let start = out.len();
        for t in self.triangles.chunks_exact(3) {
            let [a, b, c] = [t[0], t[1], t[2]].map(|k| k as usize);
            let signed = area(ring[a], ring[b], ring[c]);
            covered += signed.abs();
            let vertex = |k: usize| corners[self.kept[k]];
            // Turned as the polygon is (positive in its plane's axes), whatever earcut's order.
            out.push(if signed < 0.0 {
                [vertex(a), vertex(c), vertex(b)]
            } else {
                [vertex(a), vertex(b), vertex(c)]
            });
        }
        if (covered - polygon).abs() > 1e-9 * polygon {
            out.truncate(start);
            return Err(PolygonProblem::NotCovered);
        }
        Ok(())
    }
}

/// The projection onto the plane of the largest of `normal`'s components, its axes ordered so
/// that the polygon turns counter-clockwise (positive area) there; `None` for a polygon of no
/// area (or not finite).
fn plane(normal: DVec3) -> Option<impl Fn(DVec3) -> DVec2> {
    let a = normal.abs();
    if !(a.max_element() > 0.0 && a.is_finite()) {
        return None;
    }
    // x-axis: (y, z) turns as normal.x; y-axis: (z, x); z-axis: (x, y).
    let (axis, sign) = if a.x >= a.y && a.x >= a.z {
        (0, normal.x)
    } else if a.y >= a.z {
        (1, normal.y)
    } else {
        (2, normal.z)
    };
    let (u, v) = [(1, 2), (2, 0), (0, 1)][axis];
    let (u, v) = if sign > 0.0 { (u, v) } else { (v, u) };
    Some(move |p: DVec3| DVec2::new(p[u], p[v]))
}

/// Whether the fan from the first corner covers the polygon `q` (turning counter-clockwise)
/// exactly: each fan triangle turns counter-clockwise (or has no area) and together they turn
/// less than once around the first corner, so they neither overlap nor fold.
fn fan_covers(q: &[DVec2]) -> bool {
    // A fan triangle whose area is within rounding of zero (a corner on the line through the
    // first corner and the next) is taken as flat, not as turning back.
    const FLAT: f64 = 1e-9;
    let mut turn = 0.0;
    for w in q[1..].windows(2) {
        let (a, b) = (w[0] - q[0], w[1] - q[0]);
        let cross = a.perp_dot(b);
        if cross < -FLAT * a.length() * b.length() {
            return false;
        }
        turn += cross.max(0.0).atan2(a.dot(b));
    }
    turn < std::f64::consts::TAU * (1.0 - FLAT)
}

/// Whether two edges of the closed ring `q` cross or touch, other than neighbours at their
/// shared corner (a neighbour that doubles back along the other counts).
fn crosses(q: &[DVec2]) -> bool {
    let n = q.len();
    if n < 3 {
        return true;
    }
    let orient = |a: DVec2, b: DVec2, c: DVec2| (b - a).perp_dot(c - a);
    // `c` on the segment `ab`, given that the three are collinear.
    let within = |a: DVec2, b: DVec2, c: DVec2| {
        c.x >= a.x.min(b.x) && c.x <= a.x.max(b.x) && c.y >= a.y.min(b.y) && c.y <= a.y.max(b.y)
    };
    let meet = |a: DVec2, b: DVec2, c: DVec2, d: DVec2| {
        let (d1, d2) = (orient(a, b, c), orient(a, b, d));
        let (d3, d4) = (orient(c, d, a), orient(c, d, b));
        if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
            && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
        {
            return true;
        }
        (d1 == 0.0 && within(a, b, c))
            || (d2 == 0.0 && within(a, b, d))
            || (d3 == 0.0 && within(c, d, a))
            || (d4 == 0.0 && within(c, d, b))
    };
    for i in 0..n {
        let (a, b) = (q[i], q[(i + 1) % n]);
        // The next edge turns back along this one.
        let c = q[(i + 2) % n];
        if orient(a, b, c) == 0.0 && (b - a).dot(c - b) < 0.0 {
            return true;
        }
        for j in i + 2..n {
            if i == 0 && j == n - 1 {
                continue;
            }
            if meet(a, b, q[j], q[(j + 1) % n]) {
                return true;
            }
        }
    }
    false
}
