//! Built-in shapes: the lecture's pyramid, the ground grid, boxes, spheres, cylinders, cones,
//! tori, prisms and pyramids with k sides. Every closed shape is counter-clockwise seen from
//! outside and passes [`crate::mesh::Mesh::validate`].

use glam::{Vec2, Vec3};

use crate::mesh::Mesh;

/// A shape parameter out of range, naming the shape and the parameter.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{shape}: {parameter} = {value} is out of range ({expected})")]
pub struct ShapeError {
    /// The shape (`grid`, `uv_sphere`, …).
    pub shape: &'static str,
    /// The parameter (`divisions`, `radius`, …).
    pub parameter: &'static str,
    /// The value given, as text.
    pub value: String,
    /// What is allowed (`an integer ≥ 1`, `finite and > 0`).
    pub expected: &'static str,
}

pub(crate) fn check_positive(
    shape: &'static str,
    parameter: &'static str,
    v: f32,
) -> Result<f32, ShapeError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(ShapeError { shape, parameter, value: v.to_string(), expected: "finite and > 0" })
    }
}

pub(crate) fn check_count(
    shape: &'static str,
    parameter: &'static str,
    v: u32,
    min: u32,
    max: u32,
    expected: &'static str,
) -> Result<u32, ShapeError> {
    if (min..=max).contains(&v) {
        Ok(v)
    } else {
        Err(ShapeError { shape, parameter, value: v.to_string(), expected })
    }
}

/// The lecture's pyramid (四角すい), exactly as on the slides:
///
/// | vertex | position | | face | vertices |
/// |---|---|---|---|---|
/// | V0 | (0, 1, 0) | | F0 | {V0, V3, V1} |
/// | V1 | (1, -0.8, 1) | | F1 | {V0, V2, V4} |
/// | V2 | (1, -0.8, -1) | | F2 | {V0, V1, V2} |
/// | V3 | (-1, -0.8, 1) | | F3 | {V0, V4, V3} |
/// | V4 | (-1, -0.8, -1) | | F4 | {V1, V3, V2} |
/// | | | | F5 | {V4, V2, V3} |
///
/// Counter-clockwise seen from outside; F0's normal is (0, 0.4856, 0.8742).
#[must_use]
pub fn lecture_pyramid() -> Mesh {
    Mesh::new(
        vec![
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(1.0, -0.8, 1.0),
            Vec3::new(1.0, -0.8, -1.0),
            Vec3::new(-1.0, -0.8, 1.0),
            Vec3::new(-1.0, -0.8, -1.0),
        ],
        vec![[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]],
    )
}

/// The ground: a `divisions × divisions` grid of squares in the plane y = 0, `size` wide, centred
/// on the origin, facing +Y. The course's ground is `grid(10, 10.0)`: vertex `(i, j)` sits at
/// `(i·size/n − size/2, 0, j·size/n − size/2)` with index `j·(n+1) + i`, texture coordinate
/// `(i/n, j/n)` and normal +Y; square `(i, j)` is the triangles
/// `{(i,j), (i,j+1), (i+1,j+1)}` and `{(i,j), (i+1,j+1), (i+1,j)}` (counter-clockwise from above).
///
/// # Errors
/// `divisions` outside `1..=4096`, or `size` not finite and positive.
pub fn grid(divisions: u32, size: f32) -> Result<Mesh, ShapeError> {
    let n = check_count("grid", "divisions", divisions, 1, 4096, "an integer in 1..=4096")?;
    let size = check_positive("grid", "size", size)?;
    let row = n + 1;
    let mut positions = Vec::with_capacity((row * row) as usize);
    let mut uvs = Vec::with_capacity(positions.capacity());
    for j in 0..=n {
        for i in 0..=n {
            let (u, v) = (i as f32 / n as f32, j as f32 / n as f32);
            positions.push(Vec3::new(u * size - size / 2.0, 0.0, v * size - size / 2.0));
            uvs.push(Vec2::new(u, v));
        }
    }
    let mut faces = Vec::with_capacity((2 * n * n) as usize);
    for j in 0..n {
        for i in 0..n {
            let at = |i: u32, j: u32| j * row + i;
            faces.push([at(i, j), at(i, j + 1), at(i + 1, j + 1)]);
            faces.push([at(i, j), at(i + 1, j + 1), at(i + 1, j)]);
        }
    }
    let count = positions.len();
    let mut mesh = Mesh::new(positions, faces);
    mesh.normals = Some(vec![Vec3::Y; count]);
    mesh.uvs = Some(uvs);
    Ok(mesh)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::normals::face_normal;

    #[test]
    fn pyramid_side_normal_is_the_lectures() {
        let m = lecture_pyramid();
        let [a, b, c] = m.triangle(0);
        let n = face_normal(a, b, c).unwrap();
        // (V3−V0)×(V1−V0) = (0, 2, 3.6) ∥ (0, 1, 1.8) → (0, 0.4856, 0.8742). The slide's table
        // prints { 0.0, 0.53, 0.85 }, which does not follow from its own vertices (it is the
        // normal for an apex at y = 0.8); the kit prints the derived value.
        let exact = Vec3::new(0.0, 1.0, 1.8).normalize();
        assert!((n - exact).abs().max_element() < 1e-6, "{n} vs {exact}");
    }

    #[test]
    fn grid_faces_up_and_rejects_bad_sizes() {
        let g = grid(10, 10.0).unwrap();
        assert_eq!(g.vertex_count(), 121);
        assert_eq!(g.face_count(), 200);
        for f in 0..g.face_count() {
            let [a, b, c] = g.triangle(f);
            assert_eq!(face_normal(a, b, c), Some(Vec3::Y), "face {f}");
        }
        assert_eq!(g.positions[0], Vec3::new(-5.0, 0.0, -5.0));
        assert_eq!(g.positions[120], Vec3::new(5.0, 0.0, 5.0));
        assert!(grid(0, 1.0).is_err());
        assert!(grid(4, f32::NAN).is_err());
        assert!(grid(4, -1.0).is_err());
    }
}

// ---------------------------------------------------------------------------------------------
// The shapes below are centred on the origin with +Y as their axis, closed, manifold, welded
// (no duplicated vertices) and counter-clockwise seen from outside.

/// A box `size.x × size.y × size.z` centred on the origin: 8 vertices, 12 triangles.
///
/// # Errors
/// A size component not finite and positive.
pub fn cuboid(size: Vec3) -> Result<Mesh, ShapeError> {
    let _ = size;
    todo!("shapes: cuboid")
}

/// A UV sphere: `slices` meridians (≥ 3), `stacks` bands between the poles (≥ 2), one vertex at
/// each pole.
///
/// # Errors
/// `radius` not finite and positive, or counts out of range.
pub fn uv_sphere(radius: f32, slices: u32, stacks: u32) -> Result<Mesh, ShapeError> {
    let _ = (radius, slices, stacks);
    todo!("shapes: uv_sphere")
}

/// An icosahedron subdivided `subdivisions` times (each time every triangle becomes four),
/// vertices pushed onto the sphere: 20·4^s faces.
///
/// # Errors
/// `radius` not finite and positive, or `subdivisions` above the documented limit.
pub fn icosphere(radius: f32, subdivisions: u32) -> Result<Mesh, ShapeError> {
    let _ = (radius, subdivisions);
    todo!("shapes: icosphere")
}

/// A capped cylinder from y = −height/2 to +height/2 with `slices` ≥ 3 sides.
///
/// # Errors
/// Non-positive or non-finite sizes, or `slices` out of range.
pub fn cylinder(radius: f32, height: f32, slices: u32) -> Result<Mesh, ShapeError> {
    let _ = (radius, height, slices);
    todo!("shapes: cylinder")
}

/// A capped cone: base circle at y = −height/2, apex at +height/2, `slices` ≥ 3 sides.
///
/// # Errors
/// Non-positive or non-finite sizes, or `slices` out of range.
pub fn cone(radius: f32, height: f32, slices: u32) -> Result<Mesh, ShapeError> {
    let _ = (radius, height, slices);
    todo!("shapes: cone")
}

/// A torus around +Y in the XZ plane: ring radius `major`, tube radius `minor` (< `major`).
///
/// # Errors
/// Non-positive or non-finite radii, `minor ≥ major`, or segment counts below 3.
pub fn torus(
    major: f32,
    minor: f32,
    major_segments: u32,
    minor_segments: u32,
) -> Result<Mesh, ShapeError> {
    let _ = (major, minor, major_segments, minor_segments);
    todo!("shapes: torus")
}

/// A right prism over a regular `sides`-gon (≥ 3) with circumradius `radius`, from y = −height/2
/// to +height/2.
///
/// # Errors
/// Non-positive or non-finite sizes, or `sides` out of range.
pub fn prism(sides: u32, radius: f32, height: f32) -> Result<Mesh, ShapeError> {
    let _ = (sides, radius, height);
    todo!("shapes: prism")
}

/// A pyramid over a regular `sides`-gon (≥ 3) with circumradius `radius`: base at y = −height/2,
/// apex at +height/2.
///
/// # Errors
/// Non-positive or non-finite sizes, or `sides` out of range.
pub fn pyramid(sides: u32, radius: f32, height: f32) -> Result<Mesh, ShapeError> {
    let _ = (sides, radius, height);
    todo!("shapes: pyramid")
}

/// A frustum (truncated pyramid) over a regular `sides`-gon: circumradius `bottom_radius` at
/// y = −height/2 and `top_radius` at +height/2.
///
/// # Errors
/// Non-positive or non-finite sizes, or `sides` out of range.
pub fn frustum(
    sides: u32,
    bottom_radius: f32,
    top_radius: f32,
    height: f32,
) -> Result<Mesh, ShapeError> {
    let _ = (sides, bottom_radius, top_radius, height);
    todo!("shapes: frustum")
}

/// A regular octahedron with its six vertices at distance `radius` on the axes.
///
/// # Errors
/// `radius` not finite and positive.
pub fn octahedron(radius: f32) -> Result<Mesh, ShapeError> {
    let _ = radius;
    todo!("shapes: octahedron")
}
