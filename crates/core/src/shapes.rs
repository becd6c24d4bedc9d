//! Built-in shapes: the lecture's pyramid, the ground grid, boxes, spheres, cylinders, cones,
//! tori, prisms and pyramids with k sides. Every closed shape is counter-clockwise seen from
//! outside and passes [`crate::mesh::Mesh::validate`].

use std::collections::HashMap;

use glam::{Vec2, Vec3};

use crate::lang::{Lang, Text, t};
use crate::mesh::Mesh;

/// A shape parameter out of range, naming the shape and the parameter.
///
/// `Display` gives the English message; [`ShapeError::message`] gives it in either language.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{shape}: {parameter} = {value} is out of range ({expected})")]
pub struct ShapeError {
    /// The shape (`grid`, `uv_sphere`, …).
    pub shape: &'static str,
    /// The parameter (`divisions`, `radius`, …).
    pub parameter: &'static str,
    /// The value given, as text.
    pub value: String,
    /// What is allowed (`Display`: `an integer in 1..=4096`, `finite and > 0`).
    pub expected: Allowed,
}

/// The values a shape parameter allows, for [`ShapeError`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Allowed {
    /// A finite length > 0.
    Positive,
    /// An integer in `min..=max`.
    Count {
        /// The smallest allowed.
        min: u32,
        /// The largest allowed.
        max: u32,
    },
    /// A finite length > 0 and below another parameter's value (a torus's `minor < major`).
    PositiveBelow {
        /// The other parameter.
        other: &'static str,
    },
}

impl Allowed {
    /// What is allowed: `an integer in 3..=4096` / `3 以上 4096 以下の整数`.
    #[must_use]
    pub fn text(self) -> Text {
        match self {
            Allowed::Positive => t("0 より大きい有限の数", "finite and > 0"),
            Allowed::Count { min, max } => Text::new(
                format!("{min} 以上 {max} 以下の整数"),
                format!("an integer in {min}..={max}"),
            ),
            Allowed::PositiveBelow { other } => Text::new(
                format!("0 より大きく {other} より小さい有限の数"),
                format!("finite, > 0 and < {other}"),
            ),
        }
    }

    /// [`Allowed::text`] in `lang`.
    #[must_use]
    pub fn describe(self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl std::fmt::Display for Allowed {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.describe(Lang::En))
    }
}

impl ShapeError {
    /// The message for a student in `lang`: `grid: divisions = 5000 is out of range (an integer
    /// in 1..=4096)` / `grid の divisions = 5000 は範囲外です（1 以上 4096 以下の整数でなければなりません）`.
    /// The English one is the `Display` text.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let ShapeError { shape, parameter, value, expected } = self;
        let expected = expected.text();
        Text::new(
            format!(
                "{shape} の {parameter} = {value} は範囲外です（{}でなければなりません）",
                expected.ja
            ),
            format!("{shape}: {parameter} = {value} is out of range ({})", expected.en),
        )
    }
}

pub(crate) fn check_positive(
    shape: &'static str,
    parameter: &'static str,
    v: f32,
) -> Result<f32, ShapeError> {
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(ShapeError { shape, parameter, value: v.to_string(), expected: Allowed::Positive })
    }
}

pub(crate) fn check_count(
    shape: &'static str,
    parameter: &'static str,
    v: u32,
    min: u32,
    max: u32,
) -> Result<u32, ShapeError> {
    if (min..=max).contains(&v) {
        Ok(v)
    } else {
        let expected = Allowed::Count { min, max };
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
    let n = check_count("grid", "divisions", divisions, 1, MAX_SEGMENTS)?;
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

// ---------------------------------------------------------------------------------------------
// The shapes below are centred on the origin with +Y as their axis, closed, manifold, welded
// (no duplicated vertices) and counter-clockwise seen from outside.
//
// A "ring" of n vertices at height y and radius r has vertex k at angle θ_k = 360°·k/n about +Y,
// starting at +X: (r·cos θ_k, y, −r·sin θ_k). That is +X rotated by θ_k about +Y (glRotatef(θ_k,
// 0, 1, 0)), so the ring runs counter-clockwise seen from above.

/// The largest grid `divisions`, and the largest `slices`, `stacks`, `sides` and segment counts.
pub const MAX_SEGMENTS: u32 = 4096;
/// The largest icosphere subdivision level (20·4⁸ = 1 310 720 faces).
pub const MAX_SUBDIVISIONS: u32 = 8;

/// `(cos, sin)` of the angle `turn · numerator / denominator` turns, in f64, exact at multiples
/// of a quarter turn (so a square's corners have exact zeros, not 6e-17).
fn cos_sin_turn(numerator: u32, denominator: u32) -> (f64, f64) {
    let (k, n) = (u64::from(numerator), u64::from(denominator));
    if (4 * k) % n == 0 {
        return match (4 * k / n) % 4 {
            0 => (1.0, 0.0),
            1 => (0.0, 1.0),
            2 => (-1.0, 0.0),
            _ => (0.0, -1.0),
        };
    }
    let angle = std::f64::consts::TAU * k as f64 / n as f64;
    (angle.cos(), angle.sin())
}

/// `p` rounded to f32, with −0 written as +0 (vertex tables should not print `-0.0`).
fn no_negative_zero(p: glam::DVec3) -> Vec3 {
    p.as_vec3() + Vec3::ZERO
}

/// Appends a ring of `n` vertices at height `y` and radius `r`, vertex k at 360°·k/n from +X.
fn push_ring(positions: &mut Vec<Vec3>, n: u32, r: f64, y: f64) {
    for k in 0..n {
        let (c, s) = cos_sin_turn(k, n);
        positions.push(no_negative_zero(glam::DVec3::new(r * c, y, -r * s)));
    }
}

/// The side quads between ring `bottom..bottom+n` and ring `top..top+n`, each as the triangles
/// `{B_k, B_k+1, T_k+1}` and `{B_k, T_k+1, T_k}` (k + 1 taken modulo n).
fn push_band(faces: &mut Vec<[u32; 3]>, n: u32, bottom: u32, top: u32) {
    for k in 0..n {
        let k1 = (k + 1) % n;
        faces.push([bottom + k, bottom + k1, top + k1]);
        faces.push([bottom + k, top + k1, top + k]);
    }
}

/// A closed solid over two rings of `n` vertices, `bottom` (V0..V(n−1)) and `top` (Vn..V(2n−1)),
/// with side quads and caps fanned from each ring's first vertex.
fn ring_solid(positions: Vec<Vec3>, n: u32) -> Mesh {
    let mut faces = Vec::with_capacity(4 * n as usize - 4);
    push_band(&mut faces, n, 0, n);
    for k in 1..n - 1 {
        faces.push([0, k + 1, k]);
    }
    for k in 1..n - 1 {
        faces.push([n, n + k, n + k + 1]);
    }
    Mesh::new(positions, faces)
}

/// A box `size.x × size.y × size.z` centred on the origin (直方体; a "box" elsewhere): 8
/// vertices, 12 triangles. With `(x, y, z) = size / 2`:
///
/// | vertex | position | | vertex | position |
/// |---|---|---|---|---|
/// | V0 | (−x, −y, +z) | | V4 | (−x, +y, +z) |
/// | V1 | (+x, −y, +z) | | V5 | (+x, +y, +z) |
/// | V2 | (+x, −y, −z) | | V6 | (+x, +y, −z) |
/// | V3 | (−x, −y, −z) | | V7 | (−x, +y, −z) |
///
/// Bottom ring first (front-left, front-right, back-right, back-left: counter-clockwise seen
/// from above), then the top ring above it. Faces: the sides F0–F7 (`{V0, V1, V5}`,
/// `{V0, V5, V4}` at the front (+Z), then right, back, left), the bottom F8 `{V0, V2, V1}`, F9
/// `{V0, V3, V2}` and the top F10 `{V4, V5, V6}`, F11 `{V4, V6, V7}`.
///
/// # Errors
/// A size component not finite and positive.
#[doc(alias = "box")]
pub fn cuboid(size: Vec3) -> Result<Mesh, ShapeError> {
    let x = check_positive("cuboid", "size.x", size.x)? / 2.0;
    let y = check_positive("cuboid", "size.y", size.y)? / 2.0;
    let z = check_positive("cuboid", "size.z", size.z)? / 2.0;
    let corners = [(-x, z), (x, z), (x, -z), (-x, -z)];
    let positions =
        [-y, y].iter().flat_map(|&h| corners.map(|(cx, cz)| Vec3::new(cx, h, cz))).collect();
    Ok(ring_solid(positions, 4))
}

/// A UV sphere (球) of radius `radius`: `slices` meridians and `stacks` bands from pole to pole,
/// `slices·(stacks − 1) + 2` vertices and `2·slices·(stacks − 1)` triangles.
///
/// Numbering from the bottom up: V0 is the south pole (0, −r, 0); then `stacks − 1` rings of
/// `slices` vertices, ring j = 1, 2, … at polar angle φ_j = 180°·j/stacks from the south pole
/// (height −r·cos φ_j, radius r·sin φ_j), its vertex k at V(1 + (j−1)·slices + k) and at angle
/// 360°·k/slices about +Y from +X; the last vertex is the north pole (0, r, 0). Faces from the
/// bottom up: the `slices` triangles around the south pole, then two per quad band by band, then
/// the `slices` triangles around the north pole.
///
/// # Errors
/// `radius` not finite and positive; `slices` outside 3..=4096; `stacks` outside 2..=4096.
pub fn uv_sphere(radius: f32, slices: u32, stacks: u32) -> Result<Mesh, ShapeError> {
    let r = f64::from(check_positive("uv_sphere", "radius", radius)?);
    let n = check_count("uv_sphere", "slices", slices, 3, MAX_SEGMENTS)?;
    let m = check_count("uv_sphere", "stacks", stacks, 2, MAX_SEGMENTS)?;
    let rings = m - 1;
    let north = 1 + rings * n;
    let mut positions = Vec::with_capacity(north as usize + 1);
    positions.push(Vec3::new(0.0, -radius, 0.0));
    for j in 1..m {
        // φ_j = 180°·j/m = 360°·j/(2m) from the south pole.
        let (c, s) = cos_sin_turn(j, 2 * m);
        push_ring(&mut positions, n, r * s, -r * c);
    }
    positions.push(Vec3::new(0.0, radius, 0.0));

    let ring = |j: u32| 1 + (j - 1) * n;
    let mut faces = Vec::with_capacity(2 * (n * rings) as usize);
    for k in 0..n {
        faces.push([0, ring(1) + (k + 1) % n, ring(1) + k]);
    }
    for j in 1..rings {
        push_band(&mut faces, n, ring(j), ring(j + 1));
    }
    for k in 0..n {
        faces.push([ring(rings) + k, ring(rings) + (k + 1) % n, north]);
    }
    Ok(Mesh::new(positions, faces))
}

/// An icosahedron (正二十面体) subdivided `subdivisions` times, each time every triangle split
/// into four by its edge midpoints, every vertex pushed onto the sphere of radius `radius`:
/// `10·4^s + 2` vertices and `20·4^s` triangles.
///
/// Numbering: the icosahedron first — V0 the south pole (0, −r, 0); V1–V5 a ring at height
/// −r/√5, radius 2r/√5, at 0°, 72°, … about +Y from +X; V6–V10 a ring at +r/√5 turned by 36°;
/// V11 the north pole — then each level's edge midpoints in order of creation (face by face,
/// edges `ab`, `bc`, `ca`). Face `{a, b, c}` becomes `{a, ab, ca}`, `{ab, b, bc}`, `{ca, bc, c}`,
/// `{ab, bc, ca}`, in that order.
///
/// # Errors
/// `radius` not finite and positive, or `subdivisions` above 8 (1 310 720 faces).
pub fn icosphere(radius: f32, subdivisions: u32) -> Result<Mesh, ShapeError> {
    use glam::DVec3;
    let r = f64::from(check_positive("icosphere", "radius", radius)?);
    let levels = check_count("icosphere", "subdivisions", subdivisions, 0, MAX_SUBDIVISIONS)?;
    let (h, rho) = (1.0 / 5f64.sqrt(), 2.0 / 5f64.sqrt());
    let mut unit = vec![DVec3::NEG_Y];
    for (y, phase) in [(-h, 0), (h, 1)] {
        for k in 0..5 {
            let (c, s) = cos_sin_turn(2 * k + phase, 10);
            unit.push(DVec3::new(rho * c, y, -rho * s));
        }
    }
    unit.push(DVec3::Y);
    let (lower, upper) = (|k: u32| 1 + k % 5, |k: u32| 6 + k % 5);
    let mut faces = Vec::with_capacity(20 << (2 * levels));
    for k in 0..5 {
        faces.push([0, lower(k + 1), lower(k)]);
    }
    for k in 0..5 {
        faces.push([lower(k), lower(k + 1), upper(k)]);
        faces.push([lower(k + 1), upper(k + 1), upper(k)]);
    }
    for k in 0..5 {
        faces.push([upper(k), upper(k + 1), 11]);
    }

    for _ in 0..levels {
        let mut midpoints: HashMap<(u32, u32), u32> = HashMap::with_capacity(faces.len() * 3 / 2);
        let mut midpoint = |a: u32, b: u32, unit: &mut Vec<DVec3>| {
            *midpoints.entry((a.min(b), a.max(b))).or_insert_with(|| {
                unit.push((unit[a as usize] + unit[b as usize]).normalize());
                (unit.len() - 1) as u32
            })
        };
        let mut finer = Vec::with_capacity(faces.len() * 4);
        for [a, b, c] in faces {
            let ab = midpoint(a, b, &mut unit);
            let bc = midpoint(b, c, &mut unit);
            let ca = midpoint(c, a, &mut unit);
            finer.extend([[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]);
        }
        faces = finer;
    }
    Ok(Mesh::new(unit.iter().map(|&u| no_negative_zero(u * r)).collect(), faces))
}

/// A capped cylinder (円柱) of radius `radius` from y = −height/2 to +height/2 with `slices` sides:
/// `2·slices + 2` vertices and `4·slices` triangles.
///
/// Numbering: V0..V(n−1) the bottom ring (vertex k at 360°·k/n about +Y from +X), Vn..V(2n−1)
/// the top ring above it, V(2n) the bottom centre, V(2n+1) the top centre. Faces: the sides
/// (`{Vk, Vk+1, Vn+k+1}`, `{Vk, Vn+k+1, Vn+k}` for k = 0..n), then the bottom cap fanned from
/// its centre, then the top cap. (A [`prism`] has no centre vertices.)
///
/// # Errors
/// `radius` or `height` not finite and positive, or `slices` outside 3..=4096.
pub fn cylinder(radius: f32, height: f32, slices: u32) -> Result<Mesh, ShapeError> {
    let r = f64::from(check_positive("cylinder", "radius", radius)?);
    let y = f64::from(check_positive("cylinder", "height", height)?) / 2.0;
    let n = check_count("cylinder", "slices", slices, 3, MAX_SEGMENTS)?;
    let mut positions = Vec::with_capacity(2 * n as usize + 2);
    push_ring(&mut positions, n, r, -y);
    push_ring(&mut positions, n, r, y);
    positions.push(Vec3::new(0.0, -y as f32, 0.0));
    positions.push(Vec3::new(0.0, y as f32, 0.0));
    let (bottom, top) = (2 * n, 2 * n + 1);
    let mut faces = Vec::with_capacity(4 * n as usize);
    push_band(&mut faces, n, 0, n);
    for k in 0..n {
        faces.push([bottom, (k + 1) % n, k]);
    }
    for k in 0..n {
        faces.push([top, n + k, n + (k + 1) % n]);
    }
    Ok(Mesh::new(positions, faces))
}

/// A capped cone (円すい): base circle of radius `radius` at y = −height/2, apex at +height/2,
/// `slices` sides: `slices + 2` vertices and `2·slices` triangles.
///
/// Numbering: V0..V(n−1) the base ring (vertex k at 360°·k/n about +Y from +X), Vn the base
/// centre, V(n+1) the apex. Faces: the sides `{Vk, Vk+1, V(n+1)}` for k = 0..n, then the base
/// fanned from its centre. (A [`pyramid`] has no centre vertex.)
///
/// # Errors
/// `radius` or `height` not finite and positive, or `slices` outside 3..=4096.
pub fn cone(radius: f32, height: f32, slices: u32) -> Result<Mesh, ShapeError> {
    let r = f64::from(check_positive("cone", "radius", radius)?);
    let y = check_positive("cone", "height", height)? / 2.0;
    let n = check_count("cone", "slices", slices, 3, MAX_SEGMENTS)?;
    let mut positions = Vec::with_capacity(n as usize + 2);
    push_ring(&mut positions, n, r, f64::from(-y));
    positions.push(Vec3::new(0.0, -y, 0.0));
    positions.push(Vec3::new(0.0, y, 0.0));
    let (centre, apex) = (n, n + 1);
    let mut faces = Vec::with_capacity(2 * n as usize);
    for k in 0..n {
        faces.push([k, (k + 1) % n, apex]);
    }
    for k in 0..n {
        faces.push([centre, (k + 1) % n, k]);
    }
    Ok(Mesh::new(positions, faces))
}

/// A torus (トーラス) around +Y in the XZ plane: ring radius `major`, tube radius `minor`
/// (< `major`), `major_segments · minor_segments` vertices and twice as many triangles (genus 1:
/// V − E + F = 0).
///
/// Numbering: vertex (i, j) is V(i·minor_segments + j): i around the ring, at θ_i =
/// 360°·i/major_segments about +Y from +X; j around the tube, at φ_j = 360°·j/minor_segments from
/// the outer equator, upward first. Its position is `c + minor·(cos φ_j·d + sin φ_j·Y)` with
/// `d = (cos θ_i, 0, −sin θ_i)` and `c = major·d`. Quad (i, j) is the triangles
/// `{(i,j), (i+1,j), (i+1,j+1)}` and `{(i,j), (i+1,j+1), (i,j+1)}`, ordered by i, then j.
///
/// # Errors
/// A radius not finite and positive, `minor ≥ major`, or a segment count outside 3..=4096.
pub fn torus(
    major: f32,
    minor: f32,
    major_segments: u32,
    minor_segments: u32,
) -> Result<Mesh, ShapeError> {
    let big = f64::from(check_positive("torus", "major", major)?);
    let small = f64::from(check_positive("torus", "minor", minor)?);
    if minor >= major {
        return Err(ShapeError {
            shape: "torus",
            parameter: "minor",
            value: minor.to_string(),
            expected: Allowed::PositiveBelow { other: "major" },
        });
    }
    let n = check_count("torus", "major_segments", major_segments, 3, MAX_SEGMENTS)?;
    let m = check_count("torus", "minor_segments", minor_segments, 3, MAX_SEGMENTS)?;
    let mut positions = Vec::with_capacity((n * m) as usize);
    for i in 0..n {
        let (ct, st) = cos_sin_turn(i, n);
        for j in 0..m {
            let (cp, sp) = cos_sin_turn(j, m);
            let rho = big + small * cp;
            positions.push(no_negative_zero(glam::DVec3::new(rho * ct, small * sp, -rho * st)));
        }
    }
    let at = |i: u32, j: u32| (i % n) * m + j % m;
    let mut faces = Vec::with_capacity(2 * (n * m) as usize);
    for i in 0..n {
        for j in 0..m {
            faces.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
            faces.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
        }
    }
    Ok(Mesh::new(positions, faces))
}

/// A right prism (角柱) over a regular `sides`-gon with circumradius `radius`, from y = −height/2
/// to +height/2: `2·sides` vertices and `4·sides − 4` triangles.
///
/// Numbering: V0..V(n−1) the bottom polygon (vertex k at 360°·k/n about +Y from +X, so V0 is
/// at (radius, −height/2, 0)), Vn..V(2n−1) the top polygon above it. Faces: the sides
/// (`{Vk, Vk+1, Vn+k+1}`, `{Vk, Vn+k+1, Vn+k}` for k = 0..n), then the bottom fanned from V0
/// (`{V0, Vk+1, Vk}`, k = 1, …, n−2), then the top fanned from Vn (`{Vn, Vn+k, Vn+k+1}`, k = 1, …, n−2).
///
/// # Errors
/// `radius` or `height` not finite and positive, or `sides` outside 3..=4096.
pub fn prism(sides: u32, radius: f32, height: f32) -> Result<Mesh, ShapeError> {
    frustum_named("prism", sides, radius, radius, height)
}

/// A pyramid (角すい) over a regular `sides`-gon with circumradius `radius`: base at
/// y = −height/2, apex at +height/2, `sides + 1` vertices and `2·sides − 2` triangles.
///
/// Numbering: V0..V(n−1) the base polygon (vertex k at 360°·k/n about +Y from +X), Vn the apex
/// (0, height/2, 0). Faces: the sides `{Vk, Vk+1, Vn}` for k = 0..n, then the base fanned from
/// V0 (`{V0, Vk+1, Vk}`, k = 1, …, n−2). (The lecture's pyramid, [`lecture_pyramid`], numbers its
/// apex V0 instead.)
///
/// # Errors
/// `radius` or `height` not finite and positive, or `sides` outside 3..=4096.
pub fn pyramid(sides: u32, radius: f32, height: f32) -> Result<Mesh, ShapeError> {
    let r = f64::from(check_positive("pyramid", "radius", radius)?);
    let y = check_positive("pyramid", "height", height)? / 2.0;
    let n = check_count("pyramid", "sides", sides, 3, MAX_SEGMENTS)?;
    let mut positions = Vec::with_capacity(n as usize + 1);
    push_ring(&mut positions, n, r, f64::from(-y));
    positions.push(Vec3::new(0.0, y, 0.0));
    let mut faces = Vec::with_capacity(2 * n as usize - 2);
    for k in 0..n {
        faces.push([k, (k + 1) % n, n]);
    }
    for k in 1..n - 1 {
        faces.push([0, k + 1, k]);
    }
    Ok(Mesh::new(positions, faces))
}

/// A frustum (角すい台, a truncated pyramid) over a regular `sides`-gon: circumradius
/// `bottom_radius` at y = −height/2 and `top_radius` at +height/2, `2·sides` vertices and
/// `4·sides − 4` triangles, numbered as a [`prism`].
///
/// # Errors
/// A radius or `height` not finite and positive (a zero top radius is a [`pyramid`]), or
/// `sides` outside 3..=4096.
pub fn frustum(
    sides: u32,
    bottom_radius: f32,
    top_radius: f32,
    height: f32,
) -> Result<Mesh, ShapeError> {
    frustum_named("frustum", sides, bottom_radius, top_radius, height)
}

/// [`frustum`] and [`prism`], with the shape's name for errors.
fn frustum_named(
    shape: &'static str,
    sides: u32,
    bottom_radius: f32,
    top_radius: f32,
    height: f32,
) -> Result<Mesh, ShapeError> {
    let (bottom_name, top_name) =
        if shape == "prism" { ("radius", "radius") } else { ("bottom_radius", "top_radius") };
    let bottom = f64::from(check_positive(shape, bottom_name, bottom_radius)?);
    let top = f64::from(check_positive(shape, top_name, top_radius)?);
    let y = f64::from(check_positive(shape, "height", height)?) / 2.0;
    let n = check_count(shape, "sides", sides, 3, MAX_SEGMENTS)?;
    let mut positions = Vec::with_capacity(2 * n as usize);
    push_ring(&mut positions, n, bottom, -y);
    push_ring(&mut positions, n, top, y);
    Ok(ring_solid(positions, n))
}

/// A regular octahedron (正八面体) with its six vertices at distance `radius` on the axes:
/// V0 (0, −r, 0); the ring V1 (r, 0, 0), V2 (0, 0, −r), V3 (−r, 0, 0), V4 (0, 0, r); V5 (0, r, 0).
/// Faces: the bottom F0 `{V0, V2, V1}`, F1 `{V0, V3, V2}`, F2 `{V0, V4, V3}`, F3 `{V0, V1, V4}`,
/// then the top F4 `{V1, V2, V5}`, F5 `{V2, V3, V5}`, F6 `{V3, V4, V5}`, F7 `{V4, V1, V5}`.
///
/// # Errors
/// `radius` not finite and positive.
pub fn octahedron(radius: f32) -> Result<Mesh, ShapeError> {
    let r = check_positive("octahedron", "radius", radius)?;
    let mut positions = vec![Vec3::new(0.0, -r, 0.0)];
    push_ring(&mut positions, 4, f64::from(r), 0.0);
    positions.push(Vec3::new(0.0, r, 0.0));
    let ring = |k: u32| 1 + k % 4;
    let mut faces: Vec<[u32; 3]> = (0..4).map(|k| [0, ring(k + 1), ring(k)]).collect();
    faces.extend((0..4).map(|k| [ring(k), ring(k + 1), 5]));
    Ok(Mesh::new(positions, faces))
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
