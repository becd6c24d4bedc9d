//! Face and vertex normals on whole meshes: accuracy against analytic normals (sphere,
//! ellipsoid, torus), the meshes a renderer draws ([`prepare_normals`], [`face_split`],
//! [`smooth_normals`]), the degeneracy threshold, and Phong interpolation (docs/numerics.md row 18).

use std::f64::consts::PI;

use cg_core::mesh::{Mesh, MeshError};
use cg_core::normals::{
    NormalsError, Weighting, face_normal, face_normal_f64, face_normals, face_split,
    interpolate_normal, normal_matrix, prepare_normals, smooth_normals, transform_normal,
    vertex_normals,
};
use cg_core::scene::NormalSource;
use cg_core::shapes::lecture_pyramid;
use glam::{DVec3, Mat4, Vec2, Vec3};

const ALL: [Weighting; 4] = [Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max];

fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// A closed test surface and its analytic normals. Quads are all split along the same diagonal,
/// as simple builders do (so area and uniform weights see an asymmetric fan at every vertex).
/// Counter-clockwise from outside is checked against the analytic normal by [`worst_errors`].
struct Grid {
    mesh: Mesh,
    /// The analytic unit normal at every vertex, from the f32 position.
    analytic: Vec<DVec3>,
}

/// A UV sphere (`slices` around, `stacks` bands) scaled by `radii` (an ellipsoid unless equal).
fn uv_ellipsoid(radii: DVec3, slices: u32, stacks: u32) -> Grid {
    let mut positions = vec![DVec3::new(0.0, radii.y, 0.0).as_vec3()];
    for i in 1..stacks {
        let phi = PI * f64::from(i) / f64::from(stacks);
        for j in 0..slices {
            let theta = 2.0 * PI * f64::from(j) / f64::from(slices);
            let unit = DVec3::new(phi.sin() * theta.cos(), phi.cos(), phi.sin() * theta.sin());
            positions.push((unit * radii).as_vec3());
        }
    }
    positions.push(DVec3::new(0.0, -radii.y, 0.0).as_vec3());
    let south = positions.len() as u32 - 1;
    let at = |i: u32, j: u32| 1 + (i - 1) * slices + j % slices;
    let mut faces = Vec::new();
    for j in 0..slices {
        faces.push([0, at(1, j + 1), at(1, j)]);
        faces.push([south, at(stacks - 1, j), at(stacks - 1, j + 1)]);
    }
    for i in 1..stacks - 1 {
        for j in 0..slices {
            let (a, b, c, d) = (at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
            faces.push([a, b, c]);
            faces.push([a, c, d]);
        }
    }
    // ∇(x²/a² + y²/b² + z²/c²) at the f32 position.
    let analytic = positions.iter().map(|p| (p.as_dvec3() / (radii * radii)).normalize()).collect();
    Grid { mesh: Mesh::new(positions, faces), analytic }
}

/// A torus around +y: ring radius `major`, tube radius `minor`.
fn torus(major: f64, minor: f64, around: u32, tube: u32) -> Grid {
    let mut positions = Vec::new();
    for i in 0..around {
        let theta = 2.0 * PI * f64::from(i) / f64::from(around);
        for j in 0..tube {
            let phi = 2.0 * PI * f64::from(j) / f64::from(tube);
            let r = major + minor * phi.cos();
            positions
                .push(DVec3::new(r * theta.cos(), minor * phi.sin(), r * theta.sin()).as_vec3());
        }
    }
    let at = |i: u32, j: u32| (i % around) * tube + j % tube;
    let mut faces = Vec::new();
    for i in 0..around {
        for j in 0..tube {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            faces.push([a, d, c]);
            faces.push([a, c, b]);
        }
    }
    // From the nearest point of the core circle to p.
    let analytic = positions
        .iter()
        .map(|p| {
            let p = p.as_dvec3();
            let core = DVec3::new(p.x, 0.0, p.z).normalize() * major;
            (p - core).normalize()
        })
        .collect();
    Grid { mesh: Mesh::new(positions, faces), analytic }
}

/// Checks the builder's winding, then returns, per weighting, the largest angle (rad) between
/// the vertex normal and the analytic normal, after checking the cone property at every vertex:
/// every weighting is a positive combination of the unit normals of the adjacent faces, so the
/// vertex normal is never farther from the analytic normal than the farthest adjacent face
/// normal (a spherical cap of radius < 90° is convex).
fn worst_errors(g: &Grid) -> [f64; 4] {
    let m = &g.mesh;
    let mut cone = vec![0.0f64; m.vertex_count()];
    for f in 0..m.face_count() {
        let [a, b, c] = m.triangle(f);
        let n = face_normal_f64(a, b, c).unwrap();
        for &v in &m.faces[f] {
            let e = angle(n, g.analytic[v as usize]);
            assert!(e < PI / 2.0, "builder: F{f} faces inwards");
            cone[v as usize] = cone[v as usize].max(e);
        }
    }
    ALL.map(|w| {
        let vn = vertex_normals(m, w);
        assert!(vn.fallbacks.is_empty(), "{w:?}: {:?}", vn.fallbacks);
        let mut worst = 0.0f64;
        for (v, n) in vn.normals.iter().enumerate() {
            let e = angle(n.as_dvec3(), g.analytic[v]);
            // 1e-7: the f32 rounding of the result.
            assert!(
                e <= cone[v] + 1e-7,
                "{w:?} V{v}: {e} outside the cone of its faces {}",
                cone[v]
            );
            worst = worst.max(e);
        }
        worst
    })
}

#[test]
fn sphere_vertex_normals_against_p_over_norm_p() {
    // A 48 × 24 UV sphere: the angular step is Δ = 180°/24 = 7.5°.
    let coarse = worst_errors(&uv_ellipsoid(DVec3::ONE, 48, 24));
    let fine = worst_errors(&uv_ellipsoid(DVec3::ONE, 96, 48));
    let [uniform, area, angle_w, max] = coarse;
    let step = 7.5f64.to_radians();
    // Max (1999) is exact when a vertex and its neighbours lie on one sphere: only the f32
    // rounding of the positions remains, ½ ulp ≈ 3e-8 over the shortest edge near the poles
    // (2π·sin 7.5°/48 ≈ 0.017) tilts a face by ≤ 2e-6 rad; 1e-5 leaves a 5× margin.
    assert!(max <= 1e-5 && fine[3] <= 1e-5, "Max: {max}, {}", fine[3]);
    // The others follow from the split quads' asymmetry: first order in Δ for uniform and area
    // weights, second order for angle weights. Tolerances are stated as fractions of Δ (measured:
    // 0.10Δ, 0.17Δ, 0.021Δ); the convergence check below is what makes them meaningful.
    assert!(uniform <= 0.15 * step, "uniform {}°", uniform.to_degrees());
    assert!(area <= 0.25 * step, "area {}°", area.to_degrees());
    assert!(angle_w <= 0.03 * step, "angle {}°", angle_w.to_degrees());
    // Halving the step halves the first-order errors and quarters the second-order one.
    assert!(fine[0] <= 0.55 * uniform && fine[1] <= 0.55 * area, "{fine:?} vs {coarse:?}");
    assert!(fine[2] <= 0.3 * angle_w, "{fine:?} vs {coarse:?}");
    // Max is the most accurate on spheres, by far.
    assert!(max * 1000.0 < angle_w.min(uniform).min(area));
}

#[test]
fn ellipsoid_and_torus_vertex_normals_against_analytic_normals() {
    // Ellipsoid with radii 2, 1, 0.5 (a 4:1 aspect ratio): no weighting is exact, all converge.
    let radii = DVec3::new(2.0, 1.0, 0.5);
    let coarse = worst_errors(&uv_ellipsoid(radii, 48, 24));
    let fine = worst_errors(&uv_ellipsoid(radii, 96, 48));
    for (k, w) in ALL.iter().enumerate() {
        // Every weighting within half the angular step (7.5°) at 48 × 24 (measured ≤ 0.36Δ, the
        // worst near the stretched poles), and at least first-order convergence (ratio ≤ 0.6;
        // measured 0.52–0.55 for uniform and area, 0.26 for angle and Max).
        assert!(coarse[k] <= 0.5 * 7.5f64.to_radians(), "{w:?}: {}°", coarse[k].to_degrees());
        assert!(fine[k] <= 0.6 * coarse[k], "{w:?}: {} → {}", coarse[k], fine[k]);
    }
    // Torus with radii 2 and 0.5; angular steps 7.5° around and 15° across the tube.
    let coarse = worst_errors(&torus(2.0, 0.5, 48, 24));
    let fine = worst_errors(&torus(2.0, 0.5, 96, 48));
    for (k, w) in ALL.iter().enumerate().take(3) {
        // Within 0.5° at 48 × 24 (measured 0.16°–0.31°), and second-order convergence here
        // (ratio ≤ 0.3; measured 0.25): the torus grid is symmetric about every vertex's
        // meridian and parallel, which cancels the first-order term.
        assert!(coarse[k] <= 0.5f64.to_radians(), "{w:?}: {}°", coarse[k].to_degrees());
        assert!(fine[k] <= 0.3 * coarse[k], "{w:?}: {} → {}", coarse[k], fine[k]);
    }
    // Max is again the most accurate (measured at the f32 rounding floor, ~1e-6 rad).
    assert!(coarse[3] * 100.0 < coarse[..3].iter().copied().fold(f64::INFINITY, f64::min));
}

/// The normal of triangle (a, b, c) of f32 corners, in f64 from the exact f64 edges — enough
/// for the small exact-edge cases below (products of 24-bit numbers are exact in f64).
fn f64_normal(a: Vec3, b: Vec3, c: Vec3) -> DVec3 {
    (b.as_dvec3() - a.as_dvec3()).cross(c.as_dvec3() - a.as_dvec3()).normalize()
}

#[test]
fn face_split_of_the_lecture_pyramid() {
    let m = lecture_pyramid();
    let flat = face_split(&m);
    assert_eq!(flat.vertex_count(), 18);
    assert_eq!(flat.face_count(), 6);
    let normals = flat.normals.as_ref().unwrap();
    for (f, face) in m.faces.iter().enumerate() {
        let [a, b, c] = face.map(|i| m.positions[i as usize]);
        let expected = f64_normal(a, b, c);
        assert_eq!(
            flat.faces[f],
            [3 * f as u32, 3 * f as u32 + 1, 3 * f as u32 + 2],
            "F{f} keeps its number"
        );
        for (k, &v) in flat.faces[f].iter().enumerate() {
            let v = v as usize;
            assert_eq!(flat.positions[v], m.positions[face[k] as usize], "F{f} corner {k}");
            assert!(
                angle(normals[v].as_dvec3(), expected) <= 1e-7,
                "F{f} corner {k}: {}",
                normals[v]
            );
        }
    }
    // F0 {V0, V3, V1}: (V3−V0)×(V1−V0) = (0, 3.6, 2)·… ∥ (0, 1, 1.8), the value the report
    // prints as (0, 0.4856, 0.8742).
    let f0 = normals[0];
    let [v0, v3, v1] = [0, 3, 1].map(|i| m.positions[i].as_dvec3());
    let derived = (v3 - v0).cross(v1 - v0).normalize();
    assert!(angle(f0.as_dvec3(), derived) <= 1e-7);
    assert_eq!([f0.x, f0.y, f0.z].map(|x| (x * 1e4).round() / 1e4), [0.0, 0.4856, 0.8742]);
    assert_eq!(normals[1], f0);
    assert_eq!(normals[2], f0);
}

#[test]
fn prepare_normals_for_each_source() {
    let pyramid = lecture_pyramid();
    assert_eq!(prepare_normals(&pyramid, NormalSource::Face), Ok(face_split(&pyramid)));
    let vertex = NormalSource::Vertex { weighting: Weighting::Angle, crease_deg: Some(30.0) };
    let smooth = prepare_normals(&pyramid, vertex).unwrap();
    assert_eq!(smooth, smooth_normals(&pyramid, Weighting::Angle, Some(30.0)));
    // Every edge of the pyramid is sharper than 30°: every face is flat, as with face_split.
    for (f, face) in smooth.faces.iter().enumerate() {
        let [a, b, c] = pyramid.faces[f].map(|i| pyramid.positions[i as usize]);
        for &v in face {
            let n = smooth.normals.as_ref().unwrap()[v as usize];
            assert!(angle(n.as_dvec3(), f64_normal(a, b, c)) <= 1e-7, "F{f}");
        }
    }
    // A smooth sphere (7.5° between neighbours) is not split at all.
    let sphere = uv_ellipsoid(DVec3::ONE, 48, 24).mesh;
    let prepared = prepare_normals(&sphere, vertex).unwrap();
    assert_eq!(prepared.positions, sphere.positions);
    assert_eq!(prepared.faces, sphere.faces);
    assert_eq!(prepared.normals, Some(vertex_normals(&sphere, Weighting::Angle).normals));

    // Given: the mesh's own normals, normalised.
    let mut given = pyramid.clone();
    given.normals = Some(vec![Vec3::new(0.0, 2.0, 0.0); 5]);
    let out = prepare_normals(&given, NormalSource::Given).unwrap();
    assert_eq!(out.normals, Some(vec![Vec3::Y; 5]));
    assert_eq!((out.positions, out.faces), (pyramid.positions.clone(), pyramid.faces.clone()));
    given.normals.as_mut().unwrap()[3] = Vec3::ZERO;
    let err = prepare_normals(&given, NormalSource::Given).unwrap_err();
    assert_eq!(err, NormalsError::Unusable { vertex: 3, normal: Vec3::ZERO });
    assert!(err.to_string().contains("V3") && err.message(cg_core::lang::Lang::Ja).contains("V3"));
    given.normals.as_mut().unwrap()[3] = Vec3::new(f32::NAN, 1.0, 0.0);
    assert!(matches!(
        prepare_normals(&given, NormalSource::Given),
        Err(NormalsError::Unusable { vertex: 3, .. })
    ));
    assert_eq!(prepare_normals(&pyramid, NormalSource::Given), Err(NormalsError::Missing));
    given.normals = Some(vec![Vec3::Y; 4]);
    assert!(matches!(
        prepare_normals(&given, NormalSource::Given),
        Err(NormalsError::Mesh(MeshError::AttributeLength {
            attribute: "normals",
            len: 4,
            expected: 5
        }))
    ));

    // A broken mesh is an error for every source, never a panic.
    let mut broken = pyramid.clone();
    broken.faces.push([0, 1, 7]);
    for source in [NormalSource::Face, vertex, NormalSource::Given] {
        let err = prepare_normals(&broken, source).unwrap_err();
        assert!(
            matches!(err, NormalsError::Mesh(MeshError::IndexOutOfRange { face: 6, .. })),
            "{err}"
        );
    }
}

/// The unit cube [0, 1]³ with per-vertex uvs and colours (as an OBJ loader might give it).
fn attributed_cube() -> Mesh {
    let positions: Vec<Vec3> = (0..8)
        .map(|i| Vec3::new((i & 1) as f32, (i >> 1 & 1) as f32, (i >> 2 & 1) as f32))
        .collect();
    let quads =
        [[1, 3, 7, 5], [0, 4, 6, 2], [2, 6, 7, 3], [0, 1, 5, 4], [4, 5, 7, 6], [0, 2, 3, 1]];
    let faces = quads.iter().flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]]).collect();
    let mut m = Mesh::new(positions.clone(), faces);
    m.uvs = Some(positions.iter().map(|p| Vec2::new(p.x, p.y + 0.5 * p.z)).collect());
    m.colors = Some(positions.clone());
    m
}

#[test]
fn smooth_normals_splits_keep_attributes_and_numbering() {
    let cube = attributed_cube();
    // Without a crease angle: the same vertices, the normals of vertex_normals.
    for w in ALL {
        let s = smooth_normals(&cube, w, None);
        assert_eq!(
            (s.positions.clone(), s.faces.clone()),
            (cube.positions.clone(), cube.faces.clone())
        );
        assert_eq!(s.normals, Some(vertex_normals(&cube, w).normals));
        // 180° joins across every edge: the same as no crease on this closed manifold mesh.
        assert_eq!(smooth_normals(&cube, w, Some(180.0)), s);
    }
    // With 30°: 24 vertices; vertex i < 8 is still (a copy of) input vertex i; uvs and colours
    // travel with every copy.
    let s = smooth_normals(&cube, Weighting::Angle, Some(30.0));
    assert_eq!(s.vertex_count(), 24);
    assert_eq!(s.positions[..8], cube.positions[..]);
    let (uvs, colors) = (s.uvs.as_ref().unwrap(), s.colors.as_ref().unwrap());
    for (f, face) in s.faces.iter().enumerate() {
        for (k, &v) in face.iter().enumerate() {
            let source = cube.faces[f][k] as usize;
            assert_eq!(s.positions[v as usize], cube.positions[source]);
            assert_eq!(uvs[v as usize], cube.uvs.as_ref().unwrap()[source]);
            assert_eq!(colors[v as usize], cube.colors.as_ref().unwrap()[source]);
        }
    }
    // A NaN or negative crease angle joins nothing: one vertex per corner, face normals.
    for crease in [f32::NAN, -1.0] {
        let s = smooth_normals(&cube, Weighting::Angle, Some(crease));
        assert_eq!(s.vertex_count(), 36);
        let normals = s.normals.unwrap();
        for (f, face) in s.faces.iter().enumerate() {
            let [a, b, c] = cube.faces[f].map(|i| cube.positions[i as usize]);
            assert!(face.iter().all(|&v| Some(normals[v as usize]) == face_normal(a, b, c)));
        }
    }
    // Degenerate faces join the first usable group (no extra vertex, no NaN); an isolated
    // vertex keeps its slot with a zero normal.
    let mut m = cube.clone();
    m.positions.push(Vec3::splat(9.0)); // V8: isolated
    m.uvs.as_mut().unwrap().push(Vec2::ZERO);
    m.colors.as_mut().unwrap().push(Vec3::ZERO);
    m.faces.push([7, 7, 3]);
    let s = smooth_normals(&m, Weighting::Angle, Some(30.0));
    assert_eq!(s.vertex_count(), 25);
    let normals = s.normals.unwrap();
    assert!(normals.iter().all(|n| n.is_finite()));
    assert_eq!(normals[8], Vec3::ZERO);
    assert_eq!(s.positions[8], Vec3::splat(9.0));
}

#[test]
fn degeneracy_threshold_is_far_below_any_real_surface() {
    // Sine of the angle at a: 1e-20 is a (very thin) triangle whose normal is exactly +z;
    // 1e-22 is below 2⁻⁷⁰ ≈ 8.5e-22 and counts as degenerate.
    let (a, b) = (Vec3::ZERO, Vec3::X);
    assert_eq!(face_normal(a, b, Vec3::new(1.0, 1e-20, 0.0)), Some(Vec3::Z));
    assert_eq!(face_normal(a, b, Vec3::new(1.0, 1e-22, 0.0)), None);

    // A nearly collinear triangle whose edges have ~50 significant bits (one corner ~1e-9, the
    // others ~1): b and c are on the line through 0 along d = (1, 2, 3), so
    // (b−a)×(c−a) = (c−b)×a = 1.25·(d × a) exactly, and d × a is exact in f64 (small integers
    // times f32 values on a common grid). That is the oracle.
    let d = Vec3::new(1.0, 2.0, 3.0);
    let a = Vec3::new(1.7670994e-9, 3.5341494e-9, 5.301234e-9);
    let (b, c) = (d * 1.5, d * 2.75);
    let oracle = d.as_dvec3().cross(a.as_dvec3()).normalize();
    // Its area vector (~3e-16) is far below what rounding b and c (~1e1) to f32 can move it by
    // (~1e-6): the three corners are collinear within their own precision, so the face has no
    // normal — a direction made of rounding noise would be a silent wrong value.
    assert_eq!(face_normal(a, b, c), None);
    // Premise: a plain f64 cross product rounds the ~1e0 products and loses the 1e-15 result:
    // it is degrees off from the exact vector, which face_area_vector keeps.
    let plain = (b.as_dvec3() - a.as_dvec3()).cross(c.as_dvec3() - a.as_dvec3());
    assert!(angle(plain, oracle) > 1f64.to_radians(), "premise: {}", angle(plain, oracle));
    // The unnormalised vector is the same exact quantity.
    let area = cg_core::normals::face_area_vector(a, b, c);
    assert!(
        angle(area, oracle) <= 1e-9
            && (area.length() / (1.25 * d.as_dvec3().cross(a.as_dvec3()).length()) - 1.0).abs()
                < 1e-9
    );
}

#[test]
fn face_and_vertex_normals_survive_bad_input() {
    let mut m = lecture_pyramid();
    m.positions[4] = Vec3::new(f32::NAN, 0.0, 0.0);
    m.faces.push([0, 1, 42]);
    let fnormals = face_normals(&m);
    assert_eq!(fnormals.len(), 7);
    // F1 {0,2,4}, F3 {0,4,3}, F5 {4,2,3} touch the NaN vertex; F6 refers to a missing one.
    for f in [1, 3, 5, 6] {
        assert_eq!(fnormals[f], None, "F{f}");
    }
    assert!(fnormals[0].is_some() && fnormals[2].is_some() && fnormals[4].is_some());
    for w in ALL {
        let vn = vertex_normals(&m, w);
        assert!(vn.normals.iter().all(|n| n.is_finite()), "{w:?}");
        assert_eq!(vn.fallbacks, [(4, cg_core::normals::Fallback::Degenerate)], "{w:?}");
        let s = smooth_normals(&m, w, Some(30.0));
        assert!(s.normals.as_ref().unwrap().iter().all(|n| n.is_finite()));
        assert_eq!(s.face_count(), 6, "the face with a missing vertex is left out");
        assert_eq!(face_split(&m).face_count(), 6);
    }
    assert_eq!(face_normal(Vec3::ZERO, Vec3::X, Vec3::new(0.0, f32::INFINITY, 0.0)), None);
}

#[test]
fn interpolate_normal_falls_back_to_the_face_normal_row18() {
    let face = Vec3::Z;
    // Exactly opposite vertex normals, half way between: N = 0.
    let n = Vec3::new(0.6, 0.0, 0.8);
    assert_eq!(interpolate_normal([n, -n, Vec3::Y], Vec3::new(0.5, 0.5, 0.0), face), face);
    // Premise: the naive renormalisation is NaN there.
    assert!((n * 0.5 + (-n) * 0.5).normalize().is_nan());
    // Nearly opposite: the sum is rounding noise (here 1e-9 of its terms, below 2⁻²⁶).
    let m = -Vec3::new(0.6, 1e-9, 0.8);
    assert_eq!(interpolate_normal([n, m, Vec3::Y], Vec3::new(0.5, 0.5, 0.0), face), face);
    // Non-finite weights fall back too.
    assert_eq!(interpolate_normal([n, n, n], Vec3::new(f32::NAN, 0.5, 0.5), face), face);
    // Elsewhere: the f64 renormalised interpolation, to f32 rounding (1e-7 rad).
    let normals = [Vec3::new(0.6, 0.0, 0.8), Vec3::Y, Vec3::new(-0.28, 0.96, 0.0)];
    for (w0, w1) in [(0.2, 0.3), (1.0, 0.0), (0.0, 0.0), (0.49, 0.5), (0.999, 0.0005)] {
        let w = Vec3::new(w0, w1, 1.0 - w0 - w1);
        let expected = (normals[0].as_dvec3() * f64::from(w.x)
            + normals[1].as_dvec3() * f64::from(w.y)
            + normals[2].as_dvec3() * f64::from(w.z))
        .normalize();
        let got = interpolate_normal(normals, w, face);
        assert!(
            angle(got.as_dvec3(), expected) <= 1e-7 && (got.length() - 1.0).abs() < 1e-6,
            "{w}: {got}"
        );
    }
}

#[test]
fn normal_matrix_is_the_cofactor_matrix() {
    // Rotation: cof(R) = det(R)·R⁻ᵀ = R.
    let r = Mat4::from_rotation_y(0.7) * Mat4::from_rotation_x(-0.3);
    let diff = (normal_matrix(r) - glam::Mat3::from_mat4(r)).abs().to_cols_array();
    assert!(diff.iter().all(|d| *d <= 2.0 * f32::EPSILON), "{diff:?}");
    // Scale (2, 3, 4): cofactors (12, 8, 6) on the diagonal, exactly; translation ignored.
    let m = Mat4::from_translation(Vec3::new(5.0, 6.0, 7.0))
        * Mat4::from_scale(Vec3::new(2.0, 3.0, 4.0));
    assert_eq!(normal_matrix(m), glam::Mat3::from_diagonal(Vec3::new(12.0, 8.0, 6.0)));
    assert_eq!(transform_normal(m, Vec3::X), Some(Vec3::X));
    // Singular scale (1, 1, 0): still defined.
    let flat = Mat4::from_scale(Vec3::new(1.0, 1.0, 0.0));
    assert_eq!(normal_matrix(flat), glam::Mat3::from_diagonal(Vec3::new(0.0, 0.0, 1.0)));
    // Identity: a unit normal comes back (normalised); zero and non-finite normals do not.
    assert_eq!(
        transform_normal(Mat4::IDENTITY, Vec3::new(0.0, 3.0, 4.0)),
        Some(Vec3::new(0.0, 0.6, 0.8))
    );
    assert_eq!(transform_normal(Mat4::IDENTITY, Vec3::ZERO), None);
    assert_eq!(transform_normal(Mat4::IDENTITY, Vec3::new(f32::NAN, 0.0, 1.0)), None);
    assert_eq!(transform_normal(Mat4::from_scale(Vec3::splat(f32::INFINITY)), Vec3::Z), None);
}
