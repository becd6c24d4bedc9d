//! The built-in shapes: each is closed, manifold, welded and counter-clockwise seen from outside
//! over a range of parameters; its vertex and face counts follow from its numbering (checked
//! against Euler's formula); its geometry against analytic facts; bad parameters are errors.

use std::collections::HashSet;
use std::f64::consts::PI;

use cg_core::glam::{DVec3, Vec3};
use cg_core::mesh::{Mesh, Orientation};
use cg_core::shapes::{
    ShapeError, cone, cuboid, cylinder, frustum, icosphere, octahedron, prism, pyramid, torus,
    uv_sphere,
};
use cg_testkit::assert_approx_eq;

/// Rounding each coordinate of an exact (f64) point to f32 moves it by at most 0.5 ulp per
/// component, and one ulp of `x` is at most `ε₃₂·|x|`; so a point computed at distance `d` from
/// something lands within `0.5·√3·ε₃₂·max|coordinate|` of that distance. One ε of the largest
/// coordinate covers it.
const F32_POSITION: f64 = f32::EPSILON as f64;

/// Relative tolerance for polyhedral volumes against their exact formula: each of the F terms
/// `a·(b×c)` is exact in f64 up to ~1e-16 relative, but the positions themselves were rounded to
/// f32 (relative 6e-8 per coordinate, so ~2e-7 per volume term); 1e-6 leaves a factor 5.
const VOLUME_REL: f64 = 1e-6;

/// Checks everything every closed shape promises: clean, outward, the expected counts, Euler's
/// formula for the given genus, no duplicated positions.
fn assert_closed_shape(name: &str, mesh: &Mesh, vertices: usize, faces: usize, genus: i64) {
    assert_eq!(mesh.vertex_count(), vertices, "{name}: vertex count");
    assert_eq!(mesh.face_count(), faces, "{name}: face count");
    let v = mesh.validate();
    assert!(v.is_clean(), "{name}: {:#?}", v.problems());
    assert!(v.is_closed() && v.is_manifold() && v.is_consistently_wound(), "{name}");
    assert_eq!(v.orientation(), Some(Orientation::Outward), "{name}");
    // Every edge has two faces: E = 3F/2, and Euler: V − E + F = 2 − 2·genus.
    assert_eq!(2 * v.edge_count(), 3 * faces, "{name}: edges");
    let euler = vertices as i64 - v.edge_count() as i64 + faces as i64;
    assert_eq!(euler, 2 - 2 * genus, "{name}: Euler characteristic");
    // Welded: no two vertices share a position (−0 and +0 counted equal), and no −0 at all, so
    // vertex tables never print "-0.0".
    let distinct: HashSet<[u32; 3]> =
        mesh.positions.iter().map(|p| (*p + Vec3::ZERO).to_array().map(f32::to_bits)).collect();
    assert_eq!(distinct.len(), vertices, "{name}: duplicated positions");
    for (i, p) in mesh.positions.iter().enumerate() {
        assert!(p.is_finite(), "{name}: V{i} = {p}");
        for c in p.to_array() {
            assert!(!(c == 0.0 && c.is_sign_negative()), "{name}: V{i} = {p:?} has −0");
        }
    }
}

fn volume(mesh: &Mesh) -> f64 {
    mesh.validate().signed_volume().expect("closed and consistently wound")
}

/// The area of a regular n-gon with circumradius r: n triangles of area r²·sin(2π/n)/2.
fn polygon_area(n: u32, r: f64) -> f64 {
    f64::from(n) / 2.0 * r * r * (2.0 * PI / f64::from(n)).sin()
}

/// A frustum of a pyramid with parallel similar bases of areas a1, a2 and height h.
fn frustum_volume(a1: f64, a2: f64, h: f64) -> f64 {
    h / 3.0 * (a1 + a2 + (a1 * a2).sqrt())
}

/// Asserts that `f` rejects each value with an error naming `shape` and `parameter`.
fn assert_rejects<T: std::fmt::Debug>(
    shape: &str,
    parameter: &str,
    values: &[T],
    f: impl Fn(&T) -> Result<Mesh, ShapeError>,
) {
    for v in values {
        match f(v) {
            Err(e) => {
                assert_eq!((e.shape, e.parameter), (shape, parameter), "{shape}({v:?}): {e}");
                assert!(e.to_string().contains(parameter), "{e}");
            }
            Ok(_) => panic!("{shape}: {parameter} = {v:?} was accepted"),
        }
    }
}

const BAD_SIZES: [f32; 5] = [0.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY];

#[test]
fn cuboid_is_the_documented_box() {
    for size in [Vec3::ONE, Vec3::new(1.0, 2.0, 3.0), Vec3::new(1e-3, 5.0, 1e3), Vec3::splat(1e6)] {
        let m = cuboid(size).unwrap();
        assert_closed_shape("cuboid", &m, 8, 12, 0);
        let h = size / 2.0;
        // The doc comment's table: bottom ring front-left, front-right, back-right, back-left.
        let bottom = [(-1.0, 1.0), (1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)];
        for (i, (sx, sz)) in bottom.iter().enumerate() {
            assert_eq!(m.positions[i], Vec3::new(sx * h.x, -h.y, sz * h.z), "V{i}");
            assert_eq!(m.positions[i + 4], Vec3::new(sx * h.x, h.y, sz * h.z), "V{}", i + 4);
        }
        assert_eq!(
            &m.faces[8..],
            &[[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7]],
            "caps as documented"
        );
        let exact = f64::from(size.x) * f64::from(size.y) * f64::from(size.z);
        assert_approx_eq!(volume(&m), exact, rel = VOLUME_REL);
    }
    assert_rejects("cuboid", "size.x", &BAD_SIZES, |&x| cuboid(Vec3::new(x, 1.0, 1.0)));
    assert_rejects("cuboid", "size.y", &BAD_SIZES, |&y| cuboid(Vec3::new(1.0, y, 1.0)));
    assert_rejects("cuboid", "size.z", &BAD_SIZES, |&z| cuboid(Vec3::new(1.0, 1.0, z)));
}

#[test]
fn uv_sphere_vertices_lie_on_the_sphere() {
    for radius in [1.0f32, 0.01, 250.0] {
        for slices in 3..=9 {
            for stacks in 2..=6 {
                let m = uv_sphere(radius, slices, stacks).unwrap();
                let (n, s) = (slices as usize, stacks as usize);
                assert_closed_shape("uv_sphere", &m, n * (s - 1) + 2, 2 * n * (s - 1), 0);
                let r = f64::from(radius);
                for (i, p) in m.positions.iter().enumerate() {
                    let tol = F32_POSITION * r;
                    assert_approx_eq!(
                        p.as_dvec3().length(),
                        r,
                        abs = tol,
                        "V{i} of {slices}×{stacks}"
                    );
                }
                // Numbering: south pole first, north pole last, V1 on the first ring at +X.
                assert_eq!(m.positions[0], Vec3::new(0.0, -radius, 0.0));
                assert_eq!(m.positions[m.vertex_count() - 1], Vec3::new(0.0, radius, 0.0));
                let phi = PI / f64::from(stacks);
                let v1 = DVec3::new(r * phi.sin(), -r * phi.cos(), 0.0);
                assert_approx_eq!(m.positions[1].as_dvec3(), v1, abs = F32_POSITION * r);
            }
        }
    }
    // The largest counts stay clean (thin bands near the poles are not degenerate).
    assert_closed_shape("uv_sphere", &uv_sphere(1.0, 4096, 2).unwrap(), 4096 + 2, 2 * 4096, 0);
    assert_closed_shape("uv_sphere", &uv_sphere(1.0, 3, 4096).unwrap(), 3 * 4095 + 2, 6 * 4095, 0);
}

#[test]
fn uv_sphere_volume_is_a_stack_of_frustums() {
    // Each band's quads are planar trapezoids, so the polyhedron is exactly a stack of regular
    // n-gon frusta between the rings (pyramids at the poles): an oracle independent of the mesh.
    let (r, n, m) = (2.0f64, 128u32, 64u32);
    let ring = |j: u32| {
        let phi = PI * f64::from(j) / f64::from(m);
        (-r * phi.cos(), polygon_area(n, r * phi.sin()))
    };
    let exact: f64 = (0..m)
        .map(|j| {
            let ((y0, a0), (y1, a1)) = (ring(j), ring(j + 1));
            frustum_volume(a0, a1, y1 - y0)
        })
        .sum();
    let got = volume(&uv_sphere(r as f32, n, m).unwrap());
    assert_approx_eq!(got, exact, rel = VOLUME_REL);
    // And the analytic ball: the inscribed polyhedron is smaller, by at most ~1.5ψ² relative where
    // ψ = π/64 + π/128 bounds the angular radius of a face (1 − cos³ψ ≈ 1.5ψ²): 3.4e-3 here.
    let ball = 4.0 / 3.0 * PI * r.powi(3);
    let psi = PI / f64::from(m) + PI / f64::from(n);
    assert!(got < ball && got > ball * (1.0 - 1.5 * psi * psi), "{got} vs {ball}");
}

#[test]
fn uv_sphere_rejects_bad_parameters() {
    assert_rejects("uv_sphere", "radius", &BAD_SIZES, |&r| uv_sphere(r, 8, 4));
    assert_rejects("uv_sphere", "slices", &[0, 2, 4097], |&s| uv_sphere(1.0, s, 4));
    assert_rejects("uv_sphere", "stacks", &[0, 1, 4097], |&s| uv_sphere(1.0, 8, s));
}

#[test]
fn icosphere_counts_radius_and_volume() {
    let levels = if cfg!(debug_assertions) { 5 } else { 7 };
    let mut previous_deficit = f64::INFINITY;
    for s in 0..=levels {
        let r = 3.0f32;
        let m = icosphere(r, s).unwrap();
        let four_s = 4usize.pow(s);
        assert_closed_shape("icosphere", &m, 10 * four_s + 2, 20 * four_s, 0);
        for (i, p) in m.positions.iter().enumerate() {
            let tol = F32_POSITION * f64::from(r);
            assert_approx_eq!(p.as_dvec3().length(), f64::from(r), abs = tol, "V{i}, level {s}");
        }
        // The inscribed polyhedron lacks O(h²) of the ball; each level halves the edges, so the
        // deficit drops by about 4 (asserting 3 leaves room for the uneven triangles).
        let ball = 4.0 / 3.0 * PI * f64::from(r).powi(3);
        let deficit = 1.0 - volume(&m) / ball;
        assert!(deficit > 0.0 && deficit < previous_deficit / 3.0, "level {s}: {deficit}");
        previous_deficit = deficit;
    }
    // Level 0 is the regular icosahedron: all 30 edges equally long, poles on the Y axis.
    let m = icosphere(1.0, 0).unwrap();
    assert_eq!(m.positions[0], Vec3::NEG_Y);
    assert_eq!(m.positions[11], Vec3::Y);
    let mut lengths: Vec<f64> = m
        .faces
        .iter()
        .flat_map(|&[a, b, c]| [(a, b), (b, c), (c, a)])
        .map(|(a, b)| {
            m.positions[a as usize].as_dvec3().distance(m.positions[b as usize].as_dvec3())
        })
        .collect();
    lengths.sort_by(f64::total_cmp);
    // The edge of an icosahedron inscribed in the unit sphere: 4/√(10 + 2√5) = 1.0515.
    let edge = 4.0 / (10.0 + 2.0 * 5f64.sqrt()).sqrt();
    assert_approx_eq!(lengths[0], edge, abs = 4.0 * F32_POSITION);
    assert_approx_eq!(lengths[lengths.len() - 1], edge, abs = 4.0 * F32_POSITION);

    assert_rejects("icosphere", "radius", &BAD_SIZES, |&r| icosphere(r, 1));
    assert_rejects("icosphere", "subdivisions", &[9, 100, u32::MAX], |&s| icosphere(1.0, s));
}

#[test]
fn cylinder_is_a_capped_prism_with_centres() {
    for n in [3u32, 4, 5, 7, 16, 64, 4096] {
        let (r, h) = (1.5f32, 4.0f32);
        let m = cylinder(r, h, n).unwrap();
        let nu = n as usize;
        assert_closed_shape("cylinder", &m, 2 * nu + 2, 4 * nu, 0);
        for (i, p) in m.positions[..2 * nu].iter().enumerate() {
            let y = if i < nu { -h / 2.0 } else { h / 2.0 };
            assert_eq!(p.y, y, "V{i}");
            let rho = p.as_dvec3().with_y(0.0).length();
            assert_approx_eq!(rho, f64::from(r), abs = F32_POSITION * f64::from(r), "V{i}");
        }
        assert_eq!(m.positions[2 * nu], Vec3::new(0.0, -h / 2.0, 0.0), "bottom centre");
        assert_eq!(m.positions[2 * nu + 1], Vec3::new(0.0, h / 2.0, 0.0), "top centre");
        let exact = polygon_area(n, f64::from(r)) * f64::from(h);
        assert_approx_eq!(volume(&m), exact, rel = VOLUME_REL, "{n} slices");
        if n >= 64 {
            // Against πr²h: the n-gon has sin(2π/n)·n/(2π) of the circle's area, 1 − x²/6 for
            // x = 2π/n; allow that deficit (plus rounding) and no more.
            let x = 2.0 * PI / f64::from(n);
            let analytic = PI * f64::from(r * r * h);
            assert_approx_eq!(volume(&m), analytic, rel = x * x / 6.0 + VOLUME_REL);
        }
    }
    assert_rejects("cylinder", "radius", &BAD_SIZES, |&r| cylinder(r, 1.0, 8));
    assert_rejects("cylinder", "height", &BAD_SIZES, |&h| cylinder(1.0, h, 8));
    assert_rejects("cylinder", "slices", &[0, 2, 4097], |&n| cylinder(1.0, 1.0, n));
}

#[test]
fn cone_apex_base_and_volume() {
    for n in [3u32, 4, 6, 17, 256, 4096] {
        let (r, h) = (2.0f32, 3.0f32);
        let m = cone(r, h, n).unwrap();
        let nu = n as usize;
        assert_closed_shape("cone", &m, nu + 2, 2 * nu, 0);
        assert!(m.positions[..nu].iter().all(|p| p.y == -h / 2.0), "base ring at −h/2");
        assert_eq!(m.positions[nu], Vec3::new(0.0, -h / 2.0, 0.0), "base centre");
        assert_eq!(m.positions[nu + 1], Vec3::new(0.0, h / 2.0, 0.0), "apex");
        let exact = polygon_area(n, f64::from(r)) * f64::from(h) / 3.0;
        assert_approx_eq!(volume(&m), exact, rel = VOLUME_REL, "{n} slices");
        if n >= 256 {
            let x = 2.0 * PI / f64::from(n);
            let analytic = PI * f64::from(r * r * h) / 3.0;
            assert_approx_eq!(volume(&m), analytic, rel = x * x / 6.0 + VOLUME_REL);
        }
    }
    assert_rejects("cone", "radius", &BAD_SIZES, |&r| cone(r, 1.0, 8));
    assert_rejects("cone", "height", &BAD_SIZES, |&h| cone(1.0, h, 8));
    assert_rejects("cone", "slices", &[0, 2, 4097], |&n| cone(1.0, 1.0, n));
}

#[test]
fn torus_vertices_lie_on_the_tube() {
    for (n, m) in [(3u32, 3u32), (4, 3), (3, 7), (12, 8), (48, 24)] {
        for (big, small) in [(2.0f32, 0.5f32), (1.0, 0.999), (100.0, 0.01)] {
            let t = torus(big, small, n, m).unwrap();
            let count = (n * m) as usize;
            assert_closed_shape("torus", &t, count, 2 * count, 1);
            let (big, small) = (f64::from(big), f64::from(small));
            for (i, p) in t.positions.iter().enumerate() {
                let p = p.as_dvec3();
                // Distance from the ring (the circle of radius `major` in the XZ plane).
                let from_ring = DVec3::new(p.with_y(0.0).length() - big, p.y, 0.0).length();
                let tol = F32_POSITION * (big + small);
                assert_approx_eq!(from_ring, small, abs = tol, "V{i} of torus {n}×{m}");
            }
            let first = DVec3::new(big + small, 0.0, 0.0);
            assert_approx_eq!(t.positions[0].as_dvec3(), first, abs = F32_POSITION * (big + small));
            assert!(t.positions[1].y > 0.0, "the tube's second vertex is above the first");
            // Every segment between two meridian planes Δθ apart sweeps the tube's m-gon along
            // chords: volume sin(Δθ)·∫ρ dA = sin(Δθ)·R·area(m-gon) (Pappus, discretely).
            let dtheta = 2.0 * PI / f64::from(n);
            let exact = f64::from(n) * dtheta.sin() * big * polygon_area(m, small);
            // Rounding moves each vertex by up to 0.87·ε₃₂·(R + r), which is relative to the tube
            // radius r, not to the coordinates: the m-gon's area then changes by up to twice that
            // over r (2e-3 for R = 100, r = 0.01).
            let rel = VOLUME_REL + 2.0 * F32_POSITION * (big + small) / small;
            assert_approx_eq!(volume(&t), exact, rel = rel, "torus {n}×{m}, R {big}, r {small}");
        }
    }
    // Fine tessellation against 2π²Rr²: the two polygon factors lose x²/6 each (x = 2π/n, 2π/m).
    let (n, m) = (192u32, 96u32);
    let t = torus(3.0, 1.0, n, m).unwrap();
    let (xn, xm) = (2.0 * PI / f64::from(n), 2.0 * PI / f64::from(m));
    let analytic = 2.0 * PI * PI * 3.0;
    assert_approx_eq!(volume(&t), analytic, rel = (xn * xn + xm * xm) / 6.0 + VOLUME_REL);

    assert_rejects("torus", "major", &BAD_SIZES, |&r| torus(r, 0.5, 8, 8));
    assert_rejects("torus", "minor", &BAD_SIZES, |&r| torus(2.0, r, 8, 8));
    assert_rejects("torus", "minor", &[2.0f32, 3.0], |&r| torus(2.0, r, 8, 8));
    assert_rejects("torus", "major_segments", &[0, 2, 4097], |&n| torus(2.0, 0.5, n, 8));
    assert_rejects("torus", "minor_segments", &[0, 2, 4097], |&n| torus(2.0, 0.5, 8, n));
}

#[test]
fn prism_frustum_and_pyramid_have_their_polygon_volumes() {
    for n in [3u32, 4, 5, 6, 8, 13, 100, 4096] {
        let nu = n as usize;
        let (r, h) = (1.25f32, 2.5f32);
        let p = prism(n, r, h).unwrap();
        assert_closed_shape("prism", &p, 2 * nu, 4 * nu - 4, 0);
        assert_eq!(p.positions[0], Vec3::new(r, -h / 2.0, 0.0), "V0 at +X on the bottom");
        assert_eq!(p.positions[nu], Vec3::new(r, h / 2.0, 0.0), "Vn above V0");
        let area = polygon_area(n, f64::from(r));
        assert_approx_eq!(volume(&p), area * f64::from(h), rel = VOLUME_REL, "prism {n}");

        let f = frustum(n, r, 0.5, h).unwrap();
        assert_closed_shape("frustum", &f, 2 * nu, 4 * nu - 4, 0);
        let exact = frustum_volume(area, polygon_area(n, 0.5), f64::from(h));
        assert_approx_eq!(volume(&f), exact, rel = VOLUME_REL, "frustum {n}");
        // Wider at the top works too.
        let g = frustum(n, 0.5, r, h).unwrap();
        assert_approx_eq!(volume(&g), exact, rel = VOLUME_REL, "upside-down frustum {n}");

        let y = pyramid(n, r, h).unwrap();
        assert_closed_shape("pyramid", &y, nu + 1, 2 * nu - 2, 0);
        assert_eq!(y.positions[nu], Vec3::new(0.0, h / 2.0, 0.0), "apex at +h/2");
        assert!(y.positions[..nu].iter().all(|p| p.y == -h / 2.0), "base at −h/2");
        for (i, q) in y.positions[..nu].iter().enumerate() {
            let rho = q.as_dvec3().with_y(0.0).length();
            assert_approx_eq!(rho, f64::from(r), abs = F32_POSITION * f64::from(r), "V{i}");
        }
        assert_approx_eq!(volume(&y), area * f64::from(h) / 3.0, rel = VOLUME_REL, "pyramid {n}");
    }
    // Quarter turns are exact: a square prism has its corners on the axes, with exact zeros.
    let square = prism(4, 1.0, 2.0).unwrap();
    let expected = [Vec3::X, Vec3::NEG_Z, Vec3::NEG_X, Vec3::Z].map(|v| v - Vec3::Y);
    assert_eq!(&square.positions[..4], &expected);

    for (shape, f) in [
        ("prism", (|n, r, h| prism(n, r, h)) as fn(u32, f32, f32) -> Result<Mesh, ShapeError>),
        ("pyramid", |n, r, h| pyramid(n, r, h)),
    ] {
        assert_rejects(shape, "radius", &BAD_SIZES, |&r| f(5, r, 1.0));
        assert_rejects(shape, "height", &BAD_SIZES, |&h| f(5, 1.0, h));
        assert_rejects(shape, "sides", &[0, 1, 2, 4097], |&n| f(n, 1.0, 1.0));
    }
    assert_rejects("frustum", "bottom_radius", &BAD_SIZES, |&r| frustum(5, r, 1.0, 1.0));
    assert_rejects("frustum", "top_radius", &BAD_SIZES, |&r| frustum(5, 1.0, r, 1.0));
    assert_rejects("frustum", "height", &BAD_SIZES, |&h| frustum(5, 1.0, 1.0, h));
    assert_rejects("frustum", "sides", &[2, 4097], |&n| frustum(n, 1.0, 1.0, 1.0));
}

#[test]
fn octahedron_is_the_documented_table() {
    for r in [1.0f32, 1e-3, 1e4] {
        let m = octahedron(r).unwrap();
        assert_closed_shape("octahedron", &m, 6, 8, 0);
        let table =
            [Vec3::NEG_Y, Vec3::X, Vec3::NEG_Z, Vec3::NEG_X, Vec3::Z, Vec3::Y].map(|v| v * r);
        assert_eq!(m.positions, table);
        // Eight tetrahedra (origin, face) of volume r³/6.
        assert_approx_eq!(volume(&m), 4.0 / 3.0 * f64::from(r).powi(3), rel = VOLUME_REL);
    }
    assert_rejects("octahedron", "radius", &BAD_SIZES, |&r| octahedron(r));
}

#[test]
fn shapes_are_centred_on_the_origin() {
    // "Centred" means the bounding box: symmetric in y (a cone's apex at +h/2, its base at −h/2),
    // and the +Y axis inside it.
    let shapes = [
        cuboid(Vec3::new(1.0, 2.0, 3.0)).unwrap(),
        uv_sphere(1.0, 7, 5).unwrap(),
        icosphere(1.0, 2).unwrap(),
        cylinder(1.0, 2.0, 9).unwrap(),
        cone(1.0, 2.0, 9).unwrap(),
        torus(2.0, 0.5, 9, 5).unwrap(),
        prism(4, 1.0, 2.0).unwrap(),
        pyramid(4, 1.0, 2.0).unwrap(),
        frustum(4, 2.0, 1.0, 2.0).unwrap(),
        octahedron(1.0).unwrap(),
    ];
    for (i, m) in shapes.iter().enumerate() {
        let lo = m.positions.iter().fold(Vec3::INFINITY, |a, &p| a.min(p));
        let hi = m.positions.iter().fold(Vec3::NEG_INFINITY, |a, &p| a.max(p));
        assert_eq!(lo.y, -hi.y, "shape {i}: y range {lo} … {hi}");
        // Odd polygons are not symmetric in x and z, but the axis is inside: x and z straddle 0.
        assert!(lo.x < 0.0 && hi.x > 0.0 && lo.z < 0.0 && hi.z > 0.0, "shape {i}");
    }
}
