//! The faces of a convex solid from its vertices alone (trusted side, for the kit's reference
//! picture): every plane through three vertices with all the others on one side holds a face;
//! the vertices on it, in turn about the outward normal, are split into a fan of triangles,
//! counter-clockwise seen from outside. Computed in f64, with a tolerance of 1e-5 of the size
//! (the vertices are f32); the solids of the assignment have at
//! most a few dozen vertices, so the O(n⁴) search costs nothing.

use cg_core::glam::{DVec3, Vec3};

/// The triangles of the convex hull of `points`, counter-clockwise seen from outside, as
/// indices into `points`; none for fewer than four points not in one plane.
#[must_use]
pub fn faces(points: &[Vec3]) -> Vec<[u32; 3]> {
    let p: Vec<DVec3> = points.iter().map(|v| v.as_dvec3()).collect();
    let n = p.len();
    if n < 4 {
        return Vec::new();
    }
    let centre = p.iter().sum::<DVec3>() / n as f64;
    let scale = p.iter().map(|q| (*q - centre).length()).fold(0.0, f64::max).max(1e-12);
    let eps = 1e-5 * scale;
    let mut planes: Vec<(DVec3, f64)> = Vec::new();
    let mut out = Vec::new();
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let normal = (p[j] - p[i]).cross(p[k] - p[i]);
                if normal.length() <= eps * scale {
                    continue;
                }
                let mut normal = normal.normalize();
                let inward = normal.dot(centre - p[i]);
                // A plane through the centre: the points are flat, no solid.
                if inward.abs() <= eps {
                    continue;
                }
                if inward > 0.0 {
                    normal = -normal;
                }
                let d = normal.dot(p[i]);
                if p.iter().any(|q| normal.dot(*q) - d > eps) {
                    continue;
                }
                if planes.iter().any(|(m, e)| (*m - normal).length() < 1e-5 && (e - d).abs() < eps)
                {
                    continue;
                }
                planes.push((normal, d));
                let on: Vec<usize> =
                    (0..n).filter(|&m| (normal.dot(p[m]) - d).abs() <= eps).collect();
                out.extend(fan(&p, &on, normal));
            }
        }
    }
    out
}

/// The polygon of the points `on` (one plane, outward `normal`) as a fan of triangles from its
/// first corner in turn, counter-clockwise about `normal`.
fn fan(p: &[DVec3], on: &[usize], normal: DVec3) -> Vec<[u32; 3]> {
    let centre = on.iter().map(|&m| p[m]).sum::<DVec3>() / on.len() as f64;
    let u = (p[on[0]] - centre).normalize();
    let w = normal.cross(u);
    let mut ring: Vec<(f64, usize)> = on
        .iter()
        .map(|&m| {
            let d = p[m] - centre;
            (d.dot(w).atan2(d.dot(u)), m)
        })
        .collect();
    ring.sort_by(|a, b| a.0.total_cmp(&b.0));
    let corner = |k: usize| ring[k].1 as u32;
    (1..ring.len() - 1).map(|k| [corner(0), corner(k), corner(k + 1)]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every face turns counter-clockwise seen from outside: its normal points away from the
    /// centre, and the faces close the surface (each edge in exactly two faces, once each way).
    fn closed_and_outward(points: &[Vec3], faces: &[[u32; 3]]) {
        let centre = points.iter().copied().sum::<Vec3>() / points.len() as f32;
        let mut edges = std::collections::BTreeMap::new();
        for f in faces {
            let [a, b, c] = f.map(|i| points[i as usize]);
            assert!((b - a).cross(c - a).dot(a - centre) > 0.0, "{f:?} faces inward");
            for (x, y) in [(f[0], f[1]), (f[1], f[2]), (f[2], f[0])] {
                *edges.entry((x, y)).or_insert(0) += 1;
            }
        }
        for (&(x, y), &count) in &edges {
            assert_eq!(count, 1, "edge {x}–{y} used twice the same way");
            assert_eq!(edges.get(&(y, x)), Some(&1), "edge {x}–{y} has no neighbour");
        }
    }

    #[test]
    fn a_cube_has_twelve_triangles_closed_and_outward() {
        let points: Vec<Vec3> = (0..8)
            .map(|i| Vec3::new((i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32))
            .collect();
        let faces = faces(&points);
        assert_eq!(faces.len(), 12);
        closed_and_outward(&points, &faces);
    }

    #[test]
    fn every_solid_of_the_assignment_closes() {
        use crate::spec::SpecExt;
        for n in 0..200u32 {
            let student = format!("{:08}", 20_260_000 + n * 37).parse().unwrap();
            let spec = crate::variant(&mut cg_harness::VariantRng::new(
                &student,
                cg_harness::TableVersion::V1,
                crate::ID,
            ));
            let points = spec.expected_vertices();
            let faces = faces(&points);
            closed_and_outward(&points, &faces);
            // Euler, for a closed triangulated surface with every vertex on it: V = 2 + F/2.
            assert_eq!(points.len(), 2 + faces.len() / 2, "{spec:?}");
        }
    }

    #[test]
    fn too_few_or_flat_points_have_no_faces() {
        assert!(faces(&[Vec3::ZERO, Vec3::X, Vec3::Y]).is_empty());
        assert!(faces(&[Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(1.0, 1.0, 0.0)]).is_empty());
    }
}
