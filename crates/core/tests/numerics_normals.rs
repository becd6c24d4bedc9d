//! docs/numerics.md rows 1–9 and 19: the hard cases of face normals, vertex normals, cross products,
//! normalisation and normal transforms.
//!
//! Every test compares the kit with an oracle computed independently on the *same f32 inputs* —
//! exact integer arithmetic (`exact_cross`), analytic normals, or f64 — with a tolerance stated
//! and justified where it is used, and checks its own premise: that the naive computation fails
//! on the same inputs.

use std::f64::consts::PI;

use cg_core::math::{cross_f64, cross_kahan, try_normalize};
use cg_core::mesh::Mesh;
use cg_core::normals::{
    Fallback, Weighting, face_normal, face_normal_f64, face_normals, smooth_normals,
    transform_normal, vertex_normals,
};
use cg_testkit::Inputs;
use glam::{DQuat, DVec3, Mat3, Mat4, Vec3};

const ALL: [Weighting; 4] = [Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max];

/// A unit vector rounded to f32 is within this angle of the f64 vector it came from: each
/// component moves by at most half an ulp, ≤ 2⁻²⁵ for components below 1, so the vector moves
/// by at most √3·2⁻²⁵ ≈ 5.2e-8 rad. 1e-7 leaves room for the last f64 roundings (≤ 1e-9).
const F32_DIRECTION: f64 = 1e-7;

/// Loop counts: smaller in debug builds so `cargo test` stays fast.
const SAMPLES: usize = if cfg!(debug_assertions) { 2_000 } else { 20_000 };

// ---------------------------------------------------------------------------------------------
// Oracles and builders

/// The angle between two directions, `atan2(|a×b|, a·b)` in f64 (accurate near 0 and π).
fn angle(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// `x = m·2^e` exactly, for a finite f32.
fn split(x: f32) -> (i128, i32) {
    let bits = x.to_bits();
    let sign = if bits >> 31 == 1 { -1 } else { 1 };
    let exp = ((bits >> 23) & 0xff) as i32;
    let frac = i128::from(bits & 0x7f_ffff);
    if exp == 0 { (sign * frac, -149) } else { (sign * (frac | 0x80_0000), exp - 150) }
}

/// The exact cross product `(b−a)×(c−a)` of f32 corners in integer arithmetic: every coordinate
/// is an integer times 2^e for the smallest e, so the edges and products are exact in i128.
/// Panics (a broken test input, not a kit bug) when the coordinates span more than 2⁶⁰.
fn exact_cross(a: Vec3, b: Vec3, c: Vec3) -> [i128; 3] {
    let coords = [a.to_array(), b.to_array(), c.to_array()];
    let parts = coords.map(|p| p.map(split));
    let e_min = parts.iter().flatten().filter(|(m, _)| *m != 0).map(|&(_, e)| e).min().unwrap_or(0);
    let int = parts.map(|p| {
        p.map(|(m, e)| {
            if m == 0 {
                return 0;
            }
            let shift = (e - e_min) as u32;
            assert!(shift + 24 <= 60, "oracle: coordinates of {a} {b} {c} span too far");
            m << shift
        })
    });
    let e1 = [0, 1, 2].map(|i| int[1][i] - int[0][i]);
    let e2 = [0, 1, 2].map(|i| int[2][i] - int[0][i]);
    [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
}

/// The exact unit normal of an f32 triangle (rounded once to f64, relative error ≤ 2⁻⁵³ per
/// component before normalising), or `None` when it is exactly degenerate.
fn exact_normal(a: Vec3, b: Vec3, c: Vec3) -> Option<DVec3> {
    let n = exact_cross(a, b, c);
    if n == [0; 3] {
        return None;
    }
    let v = DVec3::new(n[0] as f64, n[1] as f64, n[2] as f64);
    Some(v / v.abs().max_element()).map(|u| u / u.length())
}

/// The naive face normal a student would write: f32 edges, f32 cross, glam's `normalize`.
fn naive_normal(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    (b - a).cross(c - a).normalize()
}

/// The angle between an f32 result and a f64 oracle; π (the worst) for a non-finite or zero
/// result, so that a NaN can never pass a tolerance.
fn error(got: Vec3, oracle: DVec3) -> f64 {
    let g = got.as_dvec3();
    if !g.is_finite() || g == DVec3::ZERO { PI } else { angle(g, oracle) }
}

/// The cube [-1, 1]³ as 8 vertices and 12 triangles: vertex `i` has coordinates
/// `(2·bit0 − 1, 2·bit1 − 1, 2·bit2 − 1)`; each side is the quad `[q0, q1, q2, q3]`
/// (counter-clockwise from outside) split into `[q0, q1, q2]` and `[q0, q2, q3]`, so `q0` and
/// `q2` get two triangles of that side and `q1`, `q3` one.
fn cube(half: f32, center: Vec3) -> Mesh {
    let positions = (0..8)
        .map(|i| {
            let bit = |k: u32| if i >> k & 1 == 1 { half } else { -half };
            center + Vec3::new(bit(0), bit(1), bit(2))
        })
        .collect();
    let quads = [
        [1, 3, 7, 5], // +X
        [0, 4, 6, 2], // −X
        [2, 6, 7, 3], // +Y
        [0, 1, 5, 4], // −Y
        [4, 5, 7, 6], // +Z
        [0, 2, 3, 1], // −Z
    ];
    let faces = quads.iter().flat_map(|&[a, b, c, d]| [[a, b, c], [a, c, d]]).collect();
    Mesh::new(positions, faces)
}

/// A capped cylinder, radius 1, y from −1 to 1, `slices` sides: bottom ring `0..n`, top ring
/// `n..2n`, bottom centre `2n`, top centre `2n + 1`; sides are quads split into two triangles,
/// caps are fans. Counter-clockwise from outside (checked by the tests that use it).
fn cylinder(slices: u32) -> Mesh {
    let n = slices;
    let mut positions = Vec::new();
    for y in [-1.0, 1.0] {
        for i in 0..n {
            let t = 2.0 * PI * f64::from(i) / f64::from(n);
            // On a 2⁻²⁴ grid (exact in f32), so cos 90° is 0 and not 6e-17: the exact oracle
            // needs the coordinates of a triangle within 2³⁶ of each other.
            let snap = |v: f64| (v * f64::from(1u32 << 24)).round() / f64::from(1u32 << 24);
            positions.push(DVec3::new(snap(t.cos()), y, snap(t.sin())).as_vec3());
        }
    }
    positions.push(Vec3::new(0.0, -1.0, 0.0));
    positions.push(Vec3::new(0.0, 1.0, 0.0));
    let mut faces = Vec::new();
    for i in 0..n {
        let j = (i + 1) % n;
        let (b0, b1, t0, t1) = (i, j, n + i, n + j);
        faces.push([b0, t0, t1]);
        faces.push([b0, t1, b1]);
        faces.push([2 * n, b0, b1]);
        faces.push([2 * n + 1, t1, t0]);
    }
    Mesh::new(positions, faces)
}

/// A random rotation (uniform axis, uniform angle), in f64.
fn rotation(s: &mut Inputs) -> DQuat {
    DQuat::from_axis_angle(s.unit_vec3().as_dvec3().normalize(), s.uniform(0.0, 2.0 * PI))
}

// ---------------------------------------------------------------------------------------------
// Row 1

/// A fan of six triangles around `center` on a gently curved surface, counter-clockwise from +z
/// (vertices 0 = center, 1..=6 ring).
fn fan(center: Vec3) -> Mesh {
    let mut positions = vec![center];
    for k in 0..6 {
        let t = f64::from(k) * PI / 3.0 + 0.2;
        let bump = 0.15 * f64::from(k % 3) - 0.1;
        positions.push(center + DVec3::new(t.cos(), t.sin(), bump).as_vec3());
    }
    let faces = (0..6).map(|k| [0, 1 + k, 1 + (k + 1) % 6]).collect();
    Mesh::new(positions, faces)
}

#[test]
fn row01_zero_area_triangles() {
    // Exactly collinear corners with awkward bits: a = x·(1, 3, 7), b = (1, 3, 7), c = 3·b, with
    // x ≈ 0.3·2⁻²⁰ a 21-bit fraction, so 3x and 7x are exact in f32 (the three points are exactly
    // on one line) but 1 − x, 3 − 3x and 7 − 7x round differently in f32.
    let x = ((0.3 * f64::from(1u32 << 21)).round() * 2f64.powi(-41)) as f32;
    let line = Vec3::new(1.0, 3.0, 7.0);
    let (a, b, c) = (line * x, line, line * 3.0);
    assert_eq!(exact_cross(a, b, c), [0; 3], "premise: the corners are exactly collinear");
    let p = Vec3::new(0.3, -0.7, 1.1);
    let q = Vec3::new(2.5, 0.1, -4.0);
    let cases =
        [("repeated corner", p, p, q), ("coincident corners", q, p, q), ("collinear", a, b, c)];
    for (what, a, b, c) in cases {
        assert_eq!(face_normal(a, b, c), None, "{what}");
        assert_eq!(face_normal_f64(a, b, c), None, "{what}");
    }
    // Premise: the naive f32 normal is NaN for the repeated corner (0/0), and for the collinear
    // triangle its f32 edges are no longer parallel, so it normalises rounding noise into a
    // confident-looking unit vector.
    assert!(naive_normal(p, p, q).is_nan(), "premise: naive gives NaN for a repeated corner");
    let noise = naive_normal(a, b, c);
    assert!(noise.is_finite() && (noise.length() - 1.0).abs() < 1e-6, "premise: {noise}");

    // A fan around b, plus degenerate faces sharing its vertices: a repeated index, a coincident
    // duplicate of a ring vertex, and the collinear triangle through b.
    let clean = fan(b);
    let mut dirty = clean.clone();
    let ring1 = dirty.positions[1];
    dirty.positions.extend([a, c, ring1]); // 7 = a, 8 = c, 9 = duplicate of 1
    dirty.faces.extend([[0, 0, 2], [7, 0, 8], [0, 1, 9], [3, 3, 3]]);
    assert_eq!(face_normals(&dirty)[6..], [None; 4]);
    for w in ALL {
        let want = vertex_normals(&clean, w);
        let got = vertex_normals(&dirty, w);
        assert!(got.normals.iter().all(|n| n.is_finite()), "{w:?}: no NaN anywhere");
        // Degenerate faces contribute nothing: bit-for-bit the normals without them.
        assert_eq!(got.normals[..7], want.normals[..], "{w:?}: neighbours unaffected");
        assert!(want.fallbacks.is_empty());
        let degenerate_only = [7u32, 8, 9].map(|v| (v, Fallback::Degenerate));
        assert_eq!(got.fallbacks, degenerate_only, "{w:?}");
        assert_eq!(got.normals[7..], [Vec3::ZERO; 3], "{w:?}: flagged zero, not NaN");
    }

    // Premise of "never normalise before weighting": the naive uniform average at b (unit f32
    // face normals summed) is NaN with the repeated-index face, and tilted by the collinear
    // face's noise without it.
    let naive_uniform = |m: &Mesh, skip_nan_faces: bool| {
        let mut sum = Vec3::ZERO;
        for f in m.faces.iter().filter(|f| f.contains(&0)) {
            let n = naive_normal(
                m.positions[f[0] as usize],
                m.positions[f[1] as usize],
                m.positions[f[2] as usize],
            );
            if !(skip_nan_faces && n.is_nan()) {
                sum += n;
            }
        }
        sum.normalize()
    };
    assert!(naive_uniform(&dirty, false).is_nan(), "premise: one NaN face poisons the vertex");
    let tilt = error(
        naive_uniform(&dirty, true),
        vertex_normals(&clean, Weighting::Uniform).normals[0].as_dvec3(),
    );
    assert!(
        tilt > 2f64.to_radians(),
        "premise: the noise normal tilts the vertex by {}°",
        tilt.to_degrees()
    );

    // A sliver: the third corner is the f32-rounded midpoint of an edge of a flat, tilted fan,
    // so the three corners are collinear in intent but not exactly (rounding moved m off the
    // line). Its exact normal is rounding noise; the kit treats it as degenerate, so no
    // weighting — not even uniform or angle, which give it a full weight — lets it tilt the
    // vertex normals around it.
    let tilt = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 0.5).normalize(), 0.7);
    let flat = {
        let center = DVec3::new(0.31, -0.17, 0.23);
        let mut positions = vec![center.as_vec3()];
        for k in 0..6 {
            let t = f64::from(k) * PI / 3.0 + 0.2;
            positions.push((center + tilt * DVec3::new(t.cos(), t.sin(), 0.0)).as_vec3());
        }
        Mesh::new(positions, (0..6).map(|k| [0, 1 + k, 1 + (k + 1) % 6]).collect())
    };
    let plane = (tilt * DVec3::Z).normalize();
    let (c0, r0) = (flat.positions[0], flat.positions[1]);
    let m = (c0 + r0) * 0.5;
    assert_ne!(exact_cross(c0, r0, m), [0; 3], "premise: rounding moved m off the line");
    let noise_normal = exact_normal(c0, r0, m).unwrap();
    let off = angle(noise_normal, plane).min(angle(-noise_normal, plane));
    assert!(off > 10f64.to_radians(), "premise: its exact normal is {}° off", off.to_degrees());
    assert_eq!(face_normal(c0, r0, m), None, "collinear within rounding: no normal");
    let mut sliver = flat.clone();
    sliver.positions.push(m); // V7
    sliver.faces.push([0, 1, 7]);
    for w in ALL {
        let want = vertex_normals(&flat, w).normals;
        let got = vertex_normals(&sliver, w);
        assert_eq!(got.normals[..7], want[..], "{w:?}: the sliver tilts nothing");
        assert_eq!(got.fallbacks, [(7, Fallback::Degenerate)], "{w:?}");
        assert!(error(got.normals[0], plane) < F32_DIRECTION * 4.0, "{w:?}: centre normal");
    }
    assert!(
        sliver
            .validate()
            .problems()
            .iter()
            .any(|p| p.describe(cg_core::lang::Lang::En).contains("F6")),
        "validation names the sliver"
    );

    // A face with an index out of range has no normal and contributes nothing; nothing panics.
    let mut broken = clean.clone();
    broken.faces.push([0, 1, 99]);
    assert_eq!(face_normals(&broken)[6], None);
    assert_eq!(
        vertex_normals(&broken, Weighting::Angle).normals,
        vertex_normals(&clean, Weighting::Angle).normals
    );
}

// ---------------------------------------------------------------------------------------------
// Row 2

#[test]
fn row02_all_degenerate_and_cancelling_faces() {
    // V0 is used only by degenerate faces, V4 by none.
    let p = [Vec3::ZERO, Vec3::X, Vec3::new(2.0, 0.0, 0.0), Vec3::Y, Vec3::splat(5.0)];
    let m = Mesh::new(p.to_vec(), vec![[0, 1, 2], [0, 0, 3], [1, 2, 3]]);
    for w in ALL {
        let vn = vertex_normals(&m, w);
        assert_eq!(vn.normals[0], Vec3::ZERO, "{w:?}");
        assert_eq!(vn.normals[4], Vec3::ZERO, "{w:?}");
        assert_eq!(vn.fallbacks, [(0, Fallback::Degenerate), (4, Fallback::Isolated)], "{w:?}");
        assert!(vn.normals.iter().all(|n| n.is_finite()));
    }

    // The same triangle twice, back to back: every sum cancels under every weighting. The
    // documented fallback is the normal of the largest adjacent face, the lower F-number on a
    // tie: F0, whose normal is +z.
    let tri = vec![Vec3::ZERO, Vec3::X, Vec3::Y];
    let m = Mesh::new(tri.clone(), vec![[0, 1, 2], [0, 2, 1]]);
    for w in ALL {
        let vn = vertex_normals(&m, w);
        assert_eq!(vn.normals, [Vec3::Z; 3], "{w:?}");
        assert_eq!(
            vn.fallbacks,
            [0u32, 1, 2].map(|v| (v, Fallback::Cancelled { face: 0 })),
            "{w:?}"
        );
    }
    // Premise: the naive average of the unit normals is exactly zero, and glam makes it NaN.
    let naive = naive_normal(tri[0], tri[1], tri[2]) + naive_normal(tri[0], tri[2], tri[1]);
    assert_eq!(naive, Vec3::ZERO);
    assert!(naive.normalize().is_nan(), "premise: normalising the cancelled sum gives NaN");

    // Back to back at V0 = 0 with the second face three times larger ([0, 1, 2] on e₁, e₂ and
    // [0, 4, 3] on 3e₁, 3e₂, exact on a 1/64 grid). Their angles at V0 are equal, but computed
    // as atan2(|n|, e₁·e₂) from 9× larger arguments they often differ in the last bit, so the
    // angle-weighted sum is rounding noise (~1e-16), not exactly zero. It must still count as
    // cancelled: normalising the noise would give an arbitrary direction.
    let mut s = Inputs::seeded(2);
    let mut noisy = 0;
    let grid = |s: &mut Inputs| s.int(-640, 640) as f32 / 64.0;
    for _ in 0..SAMPLES / 10 {
        let e1 = Vec3::new(grid(&mut s), grid(&mut s), grid(&mut s));
        let e2 = Vec3::new(grid(&mut s), grid(&mut s), grid(&mut s));
        let Some(n) = face_normal_f64(Vec3::ZERO, e1, e2) else { continue };
        let m = Mesh::new(vec![Vec3::ZERO, e1, e2, 3.0 * e1, 3.0 * e2], vec![[0, 1, 2], [0, 4, 3]]);
        for w in [Weighting::Uniform, Weighting::Angle] {
            let vn = vertex_normals(&m, w);
            // F1 has the larger area.
            assert_eq!(
                vn.fallbacks.first(),
                Some(&(0, Fallback::Cancelled { face: 1 })),
                "{w:?} {e1} {e2}"
            );
            assert_eq!(vn.normals[0], (-n).as_vec3(), "{w:?} {e1} {e2}");
        }
        // The premise, with the angle formula evaluated here in plain f64 (exact products).
        let corner = |a: DVec3, b: DVec3| a.cross(b).length().atan2(a.dot(b));
        let (a, b) = (e1.as_dvec3(), e2.as_dvec3());
        noisy += usize::from(corner(a, b) != corner(3.0 * b, 3.0 * a));
    }
    assert!(noisy > SAMPLES / 200, "premise: the angle sums are not exactly zero ({noisy})");

    // Back to back with different sizes at V0: F0 small (+z), F1 twice as large (−z).
    let p = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0)];
    let m = Mesh::new(p, vec![[0, 1, 2], [0, 4, 3]]);
    // Uniform and angle weights cancel exactly (equal unit normals, equal angles): the larger
    // face wins. Area weights do not cancel (4:1 for F1). Max weights do not either: they
    // favour the *smaller* face (1/|e|² per face), which is what makes Max exact on spheres.
    let expect = [
        (Weighting::Uniform, -Vec3::Z, Some(Fallback::Cancelled { face: 1 })),
        (Weighting::Angle, -Vec3::Z, Some(Fallback::Cancelled { face: 1 })),
        (Weighting::Area, -Vec3::Z, None),
        (Weighting::Max, Vec3::Z, None),
    ];
    for (w, normal, fallback) in expect {
        let vn = vertex_normals(&m, w);
        assert_eq!(vn.normals[0], normal, "{w:?}");
        assert_eq!(vn.fallbacks.iter().find(|(v, _)| *v == 0).map(|f| f.1), fallback, "{w:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Row 4

#[test]
fn row04_cube_corner_weightings() {
    let mut seen_19_5 = false;
    for (half, center) in [(1.0, Vec3::ZERO), (0.5, Vec3::new(3.0, -2.0, 1.25))] {
        let m = cube(half, center);
        let one_over_sqrt3 = (1.0 / 3f64.sqrt()) as f32;
        for (v, &p) in m.positions.iter().enumerate() {
            let diagonal = (p - center).signum();
            // Analytic expectation for area and uniform weights (all 12 triangles have the same
            // area, so both weight a side by how many of its triangles touch the corner):
            // Σ count_axis · axis, from the mesh's topology and the axis normals.
            let mut weighted = DVec3::ZERO;
            for f in m.faces.iter().filter(|f| f.contains(&(v as u32))) {
                let [a, b, c] = f.map(|i| m.positions[i as usize]);
                let n = exact_normal(a, b, c).unwrap();
                assert_eq!(n.abs().max_element(), 1.0, "cube faces are axis-aligned");
                weighted += n;
            }
            let expected_deg = angle(weighted, diagonal.as_dvec3()).to_degrees();
            // With counts (2, 1, 1) this is acos(4/√18) = 19.47°; with (1, 2, 2) acos(5/√27) =
            // 15.79°; with equal counts 0.
            seen_19_5 |= (expected_deg - (4.0 / 18f64.sqrt()).acos().to_degrees()).abs() < 1e-9;
            for w in [Weighting::Angle, Weighting::Max] {
                let n = vertex_normals(&m, w).normals[v];
                for k in 0..3 {
                    // "Exactly" (±1, ±1, ±1)/√3: each component within 2 ulp of 1/√3 rounded.
                    let ulps = cg_testkit::ulps(n[k], diagonal[k] * one_over_sqrt3);
                    assert!(ulps <= 2, "{w:?} V{v} component {k}: {n} ({ulps} ulp)");
                }
            }
            for w in [Weighting::Area, Weighting::Uniform] {
                let n = vertex_normals(&m, w).normals[v];
                let got_deg = angle(n.as_dvec3(), diagonal.as_dvec3()).to_degrees();
                // Same direction as the analytic sum, up to f32 rounding of the result (1e-7
                // rad = 6e-6°).
                assert!(
                    (got_deg - expected_deg).abs() < 1e-5,
                    "{w:?} V{v}: {got_deg}° vs {expected_deg}°"
                );
            }
        }
    }
    assert!(seen_19_5, "premise: some corner has the (2, 1, 1) pattern that is 19.5° off");
}

// ---------------------------------------------------------------------------------------------
// Row 5

#[test]
fn row05_crease_splitting_keeps_hard_edges() {
    // Cube: every edge is 90° > 30°, so every face keeps its own normal at its corners.
    let m = cube(1.0, Vec3::ZERO);
    for w in ALL {
        let s = smooth_normals(&m, w, Some(30.0));
        let normals = s.normals.as_ref().unwrap();
        assert_eq!(s.vertex_count(), 24, "{w:?}: each corner splits into its 3 sides");
        assert_eq!(s.faces.len(), m.faces.len());
        for (f, face) in s.faces.iter().enumerate() {
            let [a, b, c] = m.faces[f].map(|i| m.positions[i as usize]);
            let face_n = exact_normal(a, b, c).unwrap().as_vec3(); // an axis, exactly
            for (k, &i) in face.iter().enumerate() {
                assert_eq!(
                    s.positions[i as usize], m.positions[m.faces[f][k] as usize],
                    "positions copied exactly"
                );
                assert_eq!(normals[i as usize], face_n, "{w:?}: F{f} corner {k}");
            }
        }
    }
    // Premise: without splitting the cube corners are smoothed (diagonal-ish, not face normals).
    let unsplit = smooth_normals(&m, Weighting::Angle, None);
    assert_eq!(unsplit.vertex_count(), 8);
    assert!(unsplit.normals.unwrap().iter().all(|n| n.abs().min_element() > 0.5));

    // Cylinder with 24 sides (15° apart ≤ 30°): caps hard, sides smooth.
    let n = 24;
    let m = cylinder(n);
    for f in 0..m.face_count() {
        let [a, b, c] = m.triangle(f);
        let centroid = (a + b + c).as_dvec3() / 3.0;
        assert!(exact_normal(a, b, c).unwrap().dot(centroid) > 0.0, "builder: F{f} faces outwards");
    }
    for w in ALL {
        let s = smooth_normals(&m, w, Some(30.0));
        let normals = s.normals.as_ref().unwrap();
        // Every ring vertex splits into a cap copy and a side copy; the centres do not split.
        assert_eq!(s.vertex_count(), 2 * 2 * n as usize + 2, "{w:?}");
        for (f, face) in s.faces.iter().enumerate() {
            let side = f % 4 < 2;
            for &i in face {
                let (p, normal) = (s.positions[i as usize].as_dvec3(), normals[i as usize]);
                if !side {
                    // Cap corners: exactly ±y (every cap triangle's normal is exactly ±y).
                    assert_eq!(normal, Vec3::new(0.0, p.y.signum() as f32, 0.0), "{w:?} cap F{f}");
                    continue;
                }
                let radial = DVec3::new(p.x, 0.0, p.z);
                let err = error(normal, radial);
                // Angle and Max weights see the two adjacent side quads symmetrically (each
                // quad adds 90° × its normal, or 1/(w·h) × its normal, however it is split), so
                // the normal is radial up to position rounding: ≤ ½ ulp (6e-8) over a 0.26-long
                // edge tilts a side face by ≤ 5e-7 rad; 2e-6 leaves a 4× margin.
                // Area and uniform weights count the two triangles of a split quad separately,
                // so they are off by up to half the angle between adjacent quads (7.5°) — the
                // cone of the adjacent face normals — and not tighter.
                let tolerance = match w {
                    Weighting::Angle | Weighting::Max => 2e-6,
                    Weighting::Area | Weighting::Uniform => (7.5f64).to_radians(),
                };
                assert!(err <= tolerance, "{w:?} side F{f}: {normal} is {err} rad off radial");
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Row 6

#[test]
fn row06_needle_triangle_normal() {
    let mut s = Inputs::seeded(6);
    let (mut worst_same, mut worst_naive) = (0.0f64, 0.0f64);
    for i in 0..SAMPLES {
        // The ideal needle: base 1 along x, apex at height 1e-6 somewhere above the base
        // (sample 0: axis-aligned, unit scale, no offset), then rotated, scaled log-uniformly
        // over 1e-3..1e3 and moved by up to its own size.
        let t = if i == 0 { 0.5 } else { s.uniform(-0.5, 1.5) };
        let ideal = [DVec3::ZERO, DVec3::X, DVec3::new(t, 1e-6, 0.0)];
        let (r, scale, offset) = if i == 0 {
            (DQuat::IDENTITY, 1.0, DVec3::ZERO)
        } else {
            let scale = s.log_uniform(-3.0, 3.0).abs();
            (rotation(&mut s), scale, s.vec3_in_cube(1.0).as_dvec3() * scale)
        };
        let placed = ideal.map(|p| offset + r * p * scale);
        let [a, b, c] = placed.map(DVec3::as_vec3);
        let n_ideal = r * DVec3::Z;

        // 1. Against the exact normal of the same f32 corners: f32 rounding of the result only.
        let oracle = exact_normal(a, b, c).expect("a needle is not degenerate");
        let got = face_normal(a, b, c).expect("a needle has a normal");
        let same = error(got, oracle);
        assert!(
            same <= F32_DIRECTION,
            "sample {i}: {same} rad from the exact normal ({a} {b} {c})"
        );
        if i == 0 {
            assert_eq!(got, Vec3::Z, "axis-aligned needle: exact");
        }
        worst_same = worst_same.max(same);

        // 2. End to end, against the ideal needle: within what rounding the corners to f32 can
        // do. Moving corner k by δₖ tilts the plane about the opposite edge by at most δₖ/hₖ
        // (hₖ = the altitude from corner k); to first order the tilts add. The second-order
        // terms are below (Σ δ/h)² ≤ 0.1 of the sum here, hence the factor 1.25.
        let two_area = (placed[1] - placed[0]).cross(placed[2] - placed[0]).length();
        let bound: f64 = (0..3)
            .map(|k| {
                let opposite = (placed[(k + 2) % 3] - placed[(k + 1) % 3]).length();
                let h = two_area / opposite;
                (placed[k] - [a, b, c][k].as_dvec3()).length() / h
            })
            .sum();
        let end_to_end = error(got, n_ideal);
        assert!(
            end_to_end <= 1.25 * bound + F32_DIRECTION,
            "sample {i}: {end_to_end} > bound {bound}"
        );

        worst_naive = worst_naive.max(error(naive_normal(a, b, c), oracle));
    }
    // Premise: the naive f32 normal ((b−a)×(c−a) in f32, then normalize) loses the needle: its
    // f32 edges and the cancelling f32 products are off by ~ε₃₂/1e-6 ≈ 0.1 relative.
    assert!(worst_naive > 1e3 * F32_DIRECTION, "premise: naive worst {worst_naive} rad");
    assert!(worst_same <= F32_DIRECTION);
}

// ---------------------------------------------------------------------------------------------
// Row 7

#[test]
fn row07_translated_unit_triangle() {
    let mut s = Inputs::seeded(7);
    for offset in [1e4f32, 1e5, 1e6] {
        // The unit right triangle: at these offsets o + 1 is still exact in f32 (ulp ≤ 1/16),
        // so the exact normal is +z.
        let o = Vec3::new(1.1, -0.7, 1.3) * offset;
        let (a, b, c) = (o, o + Vec3::X, o + Vec3::Y);
        assert_eq!(exact_normal(a, b, c), Some(DVec3::Z));
        assert_eq!(face_normal(a, b, c), Some(Vec3::Z), "at {offset}: from edge vectors, exact");

        // Rotated unit triangles at the same distance: against the exact normal of the rounded
        // corners, only the f32 rounding of the result remains.
        let (mut worst_position_f32, mut worst_position_f64) = (0.0f64, 0.0f64);
        for _ in 0..SAMPLES / 10 {
            let r = rotation(&mut s);
            let center = s.unit_vec3().as_dvec3() * f64::from(offset);
            let [a, b, c] = [DVec3::ZERO, DVec3::X, DVec3::Y].map(|p| (center + r * p).as_vec3());
            let oracle = exact_normal(a, b, c).unwrap();
            let got = face_normal(a, b, c).unwrap();
            assert!(error(got, oracle) <= F32_DIRECTION, "at {offset}: {a} {b} {c}");
            // The position form a×b + b×c + c×a (= the same vector in exact arithmetic).
            let pf = a.cross(b) + b.cross(c) + c.cross(a);
            worst_position_f32 =
                worst_position_f32.max(error(try_normalize(pf).unwrap_or(Vec3::ZERO), oracle));
            let (a64, b64, c64) = (a.as_dvec3(), b.as_dvec3(), c.as_dvec3());
            let pf = a64.cross(b64) + b64.cross(c64) + c64.cross(a64);
            worst_position_f64 = worst_position_f64.max(angle(pf, oracle));
        }
        // Premise: the position form cancels products of size offset² to get a result of size
        // 1; in f32 (ulp of 1e8..1e12 is 8..65536) nothing of it is left.
        assert!(
            worst_position_f32 > 0.5,
            "premise at {offset}: position form in f32 {worst_position_f32}"
        );
        // (In f64 the position form happens to survive for f32 corners up to ~1e6: the
        // products of two f32 values are exact in f64 and their sums still fit in 53 bits.
        // Recorded here so that a change of that luck is noticed; the edge form needs none.)
        assert!(worst_position_f64 <= F32_DIRECTION, "{worst_position_f64}");
    }
}

// ---------------------------------------------------------------------------------------------
// Row 8

#[test]
fn row08_cross_of_parallel_vectors_is_exactly_zero() {
    // Note: glam's `Vec3A::cross` may be compiled with fused multiply-adds (with the `fma` target
    // feature its SSE path uses `_mm_fnmadd_ps`), and a fused `a·b − round(b·a)` is the rounding
    // error of the product, not 0. The kit therefore never uses `Vec3A::cross` for predicates
    // (is this face degenerate?) and compares its results with tolerances only.
    let mut s = Inputs::seeded(8);
    let mut fused_nonzero = 0;
    for _ in 0..SAMPLES {
        // |components| ≤ 1e18, so the f32 products (≤ 1e36) cannot overflow.
        let v = s.vec3_log_uniform(-18.0, 18.0);
        for w in [v, -v] {
            assert_eq!(v.cross(w), Vec3::ZERO, "Vec3::cross({v}, {w})");
            assert_eq!(cross_kahan(v, w), Vec3::ZERO, "cross_kahan({v}, {w})");
            assert_eq!(cross_f64(v, w), Vec3::ZERO, "cross_f64({v}, {w})");
        }
        // cross_f64 has no overflow limit: the f32 products are exact in f64.
        let big = s.vec3_log_uniform(-45.0, 38.5);
        assert_eq!(cross_f64(big, big), Vec3::ZERO, "cross_f64({big}, {big})");
        assert_eq!(cross_f64(big, -big), Vec3::ZERO, "cross_f64({big}, -{big})");
        // The premise of the note: the fused form of the same component is not zero.
        if v.y.mul_add(v.z, -(v.z * v.y)) != 0.0 {
            fused_nonzero += 1;
        }
    }
    assert!(fused_nonzero > SAMPLES / 2, "premise: fused cross(v, v) ≠ 0 ({fused_nonzero})");
    // Beyond 1.8e19 the f32 products overflow and the f32 forms give ∞ − ∞ = NaN; only the f64
    // form stays exactly zero. (A documented limit, not a kit promise for f32 crosses.)
    let huge = Vec3::splat(1e20);
    assert!(huge.cross(huge).is_nan());
    assert_eq!(cross_f64(huge, huge), Vec3::ZERO);
}

// ---------------------------------------------------------------------------------------------
// Row 9

#[test]
fn row09_normalise_extreme_magnitudes() {
    let mut s = Inputs::seeded(9);
    // Tolerance per component: v/m (½ ulp), the length of a vector whose largest component is
    // exactly 1 (three squares, two sums, a square root: ≤ 2 ulp(1) relative), and the last
    // division (½ ulp): ≤ 3 ulp(1) = 3·2⁻²³ of absolute error on components ≤ 1.
    let tolerance = 3.0 * f64::from(f32::EPSILON);
    let (mut glam_tiny_broken, mut glam_huge_zero, mut glam_gives_up) = (0, 0, 0);
    for i in 0..SAMPLES {
        // Half the samples: a unit direction scaled by 10^[-44, 38.5]; half: every component
        // drawn log-uniformly over the whole f32 range with both signs (wildly different sizes).
        let v = if i % 2 == 0 {
            (s.unit_vec3().as_dvec3() * s.log_uniform(-44.0, 38.5).abs()).as_vec3()
        } else {
            s.vec3_log_uniform(-45.0, 38.5)
        };
        if v == Vec3::ZERO {
            assert_eq!(try_normalize(v), None);
            continue;
        }
        let oracle = v.as_dvec3() / v.as_dvec3().length(); // f64: no overflow, no underflow
        let n = try_normalize(v).unwrap_or_else(|| panic!("None for the finite non-zero {v:?}"));
        let diff = (n.as_dvec3() - oracle).abs().max_element();
        assert!(
            diff <= tolerance,
            "try_normalize({v:?}) = {n:?}, oracle {oracle:?}, diff {diff:e}"
        );

        let length = v.as_dvec3().length();
        let right =
            |n: Vec3| n.is_finite() && (n.as_dvec3() - oracle).abs().max_element() <= tolerance;
        if length < 1e-19 && !right(v.normalize()) {
            glam_tiny_broken += 1;
        }
        if length > 2e19 && v.normalize() == Vec3::ZERO {
            glam_huge_zero += 1;
        }
        if !(1e-19..=2e19).contains(&length) && !v.try_normalize().is_some_and(right) {
            glam_gives_up += 1;
        }
    }
    // Premise: where |v|² underflows glam's normalize gives ∞, NaN or a wrong direction, where it
    // overflows it gives the zero vector, and glam's own fallible sibling answers None or wrong.
    // (About 16% of the samples have |v| < 1e-19 and 38% |v| > 2e19.)
    assert!(glam_tiny_broken > SAMPLES / 10, "premise: glam broken on {glam_tiny_broken} tiny");
    assert!(glam_huge_zero > SAMPLES / 5, "premise: glam zero on {glam_huge_zero} huge");
    assert!(glam_gives_up > SAMPLES / 3, "premise: glam try_normalize fails {glam_gives_up}");
    assert!(Vec3::new(1e-30, 0.0, 0.0).normalize().is_nan(), "1e-30·x: 0·∞ = NaN");
    assert_eq!(Vec3::new(1e30, 1e30, 0.0).normalize(), Vec3::ZERO);
    assert_eq!(try_normalize(Vec3::new(1e-30, 0.0, 0.0)), Some(Vec3::X));
    assert_eq!(
        try_normalize(Vec3::new(1e30, 1e30, 0.0)),
        Some(Vec3::new(1.0, 1.0, 0.0).normalize())
    );

    for bad in [
        Vec3::ZERO,
        -Vec3::ZERO,
        Vec3::new(f32::INFINITY, 0.0, 0.0),
        Vec3::new(1.0, f32::NEG_INFINITY, 1.0),
        Vec3::new(f32::NAN, 1.0, 0.0),
        Vec3::splat(f32::NAN),
    ] {
        assert_eq!(try_normalize(bad), None, "{bad}");
        assert!(!bad.normalize().is_finite(), "premise: glam's normalize({bad}) is not finite");
    }
}

// ---------------------------------------------------------------------------------------------
// Row 19

/// Two f64 edges perpendicular to `n` with `e₁ × e₂ = n` (for a unit `n`): a triangle whose
/// normal is `n`.
fn edges_for(n: DVec3) -> (DVec3, DVec3) {
    let helper = if n.x.abs() < 0.5 { DVec3::X } else { DVec3::Y };
    let e1 = n.cross(helper).normalize();
    (e1, n.cross(e1))
}

/// `normalise((A·e₁) × (A·e₂))` in f64 for the f32 matrix `m`, with the length before
/// normalising and a bound on its rounding error (each product A·e has error ≤ 3u·|A||e|).
fn transformed_normal(m: Mat4, n: Vec3) -> (DVec3, f64, f64) {
    let a = Mat3::from_mat4(m).as_dmat3();
    let (e1, e2) = edges_for(n.as_dvec3().normalize());
    let c = (a * e1).cross(a * e2);
    let norm_a =
        (a.x_axis.length_squared() + a.y_axis.length_squared() + a.z_axis.length_squared()).sqrt();
    (c / c.length(), c.length(), 16.0 * f64::EPSILON * norm_a * norm_a)
}

/// The inverse-transpose rule that the cofactor matrix replaces.
fn inverse_transpose(m: Mat4, n: Vec3) -> Vec3 {
    (Mat3::from_mat4(m).inverse().transpose() * n).normalize()
}

#[test]
fn row19_normal_transform_mirror_nonuniform_singular() {
    let mut s = Inputs::seeded(19);
    let mut mirror_flipped = 0;
    let mut cases = 0;
    for i in 0..SAMPLES / 4 {
        let r1 = rotation(&mut s).as_quat();
        let r2 = rotation(&mut s).as_quat();
        // Scale factors log-uniform in 10^[-1.5, 1.5] (the cofactors then span at most 1e6, so
        // the f64 oracle stays accurate to 1e-9); even samples mirror one axis.
        let mut k = Vec3::new(
            s.log_uniform(-1.5, 1.5).abs() as f32,
            s.log_uniform(-1.5, 1.5).abs() as f32,
            s.log_uniform(-1.5, 1.5).abs() as f32,
        );
        let mirror = i % 2 == 0;
        if mirror {
            k.x = -k.x;
        }
        let m = Mat4::from_translation(s.vec3_in_cube(100.0))
            * Mat4::from_quat(r1)
            * Mat4::from_scale(k)
            * Mat4::from_quat(r2);
        let n = s.unit_vec3();
        let (oracle, length, rounding) = transformed_normal(m, n);
        let got = transform_normal(m, n).expect("a non-singular matrix keeps every normal");
        // f32 rounding of the result, plus the oracle's own rounding relative to its length.
        let tolerance = F32_DIRECTION + rounding / length;
        assert!(error(got, oracle) <= tolerance, "M = {m}, n = {n}: {got} vs {oracle}");
        let it = error(inverse_transpose(m, n), oracle);
        if mirror {
            // Premise: the inverse-transpose points the other way under a mirror.
            if it > PI - 1e-3 {
                mirror_flipped += 1;
            }
        } else {
            // … and points the right way without one (it is cof/det, det > 0), up to its f32
            // arithmetic (an f32 inverse loses up to ~κ·ε₃₂ with κ ≤ 1e3 here).
            assert!(it <= 1e-3, "inverse-transpose without mirror: {it}");
        }
        cases += 1;
    }
    assert_eq!(mirror_flipped, cases / 2, "premise: inverse-transpose wrong on every mirror");

    // A plain mirror: the triangle's normal is mirrored *and* negated (its winding flips).
    let mirror = Mat4::from_scale(Vec3::new(-1.0, 1.0, 1.0));
    let n = Vec3::new(0.6, 0.0, 0.8);
    assert_eq!(transform_normal(mirror, n), Some(Vec3::new(0.6, 0.0, -0.8)));
    assert_eq!(inverse_transpose(mirror, n), Vec3::new(-0.6, 0.0, 0.8), "premise");

    // Singular: scale(1, 1, 0) flattens everything onto z = 0. A surface with a z-component in
    // its normal becomes part of that plane (normal ±z); a surface containing the z-axis
    // (normal x) is squashed to a line and has no normal.
    let flat = Mat4::from_scale(Vec3::new(1.0, 1.0, 0.0));
    for n in [Vec3::new(0.6, 0.0, 0.8), Vec3::new(0.0, -0.6, -0.8), Vec3::new(0.48, 0.6, 0.64)] {
        let (oracle, _, _) = transformed_normal(flat, n);
        assert_eq!(transform_normal(flat, n), Some(oracle.as_vec3()), "{n}");
        assert!(
            !inverse_transpose(flat, n).is_finite(),
            "premise: inverse-transpose of a singular matrix"
        );
    }
    let (_, length, rounding) = transformed_normal(flat, Vec3::X);
    assert!(length <= rounding, "oracle: the image triangle is a segment");
    assert_eq!(transform_normal(flat, Vec3::X), None);

    // Singular and rotated: a random rank-2 matrix whose third column equals its first. Its
    // image triangles all lie in one plane, spanned by the two distinct columns.
    for _ in 0..SAMPLES / 20 {
        let (c0, c1) = (s.vec3_in_cube(2.0), s.vec3_in_cube(2.0));
        let m = Mat4::from_mat3(Mat3::from_cols(c0, c1, c0));
        let n = s.unit_vec3();
        let (oracle, length, rounding) = transformed_normal(m, n);
        match transform_normal(m, n) {
            Some(got) => {
                assert!(error(got, oracle) <= F32_DIRECTION + rounding / length, "{m} {n}")
            }
            // None only where the image is (numerically) a segment.
            None => assert!(length <= 1e-6 * rounding / f64::EPSILON, "{m} {n}: {length}"),
        }
        assert!(!inverse_transpose(m, n).is_finite() || Mat3::from_mat4(m).determinant() != 0.0);
    }
    // The normal (1, 2, 1)/√6 has equal x and z exactly, so cof·n = (n₀ − n₂)·(c₁×c₀) = 0.
    let m = Mat4::from_mat3(Mat3::from_cols(
        Vec3::new(1.0, 2.0, 0.5),
        Vec3::new(-1.0, 0.5, 3.0),
        Vec3::new(1.0, 2.0, 0.5),
    ));
    let n = Vec3::new(1.0, 2.0, 1.0).normalize();
    assert_eq!(n.x, n.z);
    assert_eq!(transform_normal(m, n), None);
}

// ---------------------------------------------------------------------------------------------
// Row 3: duplicated seam vertices

/// A UV sphere whose seam column is duplicated, as a textured sphere is stored: columns
/// `0..=slices`, column `slices` a bit-exact copy of column 0 (a different index, the same
/// position), one vertex at each pole. Rows `1..stacks`, ring vertex `(row, col)` at
/// `1 + (row − 1)·(slices + 1) + col`.
fn seam_sphere(slices: u32, stacks: u32) -> Mesh {
    let cols = slices + 1;
    let mut positions = vec![Vec3::Y];
    for row in 1..stacks {
        let theta = PI * f64::from(row) / f64::from(stacks);
        for col in 0..cols {
            let phi = 2.0 * PI * f64::from(col % slices) / f64::from(slices);
            let p = DVec3::new(theta.sin() * phi.cos(), theta.cos(), -theta.sin() * phi.sin());
            positions.push(p.as_vec3());
        }
    }
    let south = positions.len() as u32;
    positions.push(-Vec3::Y);
    let ring = |row: u32, col: u32| 1 + (row - 1) * cols + col;
    let mut faces = Vec::new();
    for col in 0..slices {
        faces.push([0, ring(1, col), ring(1, col + 1)]);
        for row in 1..stacks - 1 {
            let (a, b) = (ring(row, col), ring(row, col + 1));
            let (c, d) = (ring(row + 1, col), ring(row + 1, col + 1));
            faces.push([a, c, d]);
            faces.push([a, d, b]);
        }
        faces.push([south, ring(stacks - 1, col + 1), ring(stacks - 1, col)]);
    }
    Mesh::new(positions, faces)
}

#[test]
fn row03_duplicated_seam_vertices_crease_until_welded() {
    let (slices, stacks) = (24, 12);
    let mesh = seam_sphere(slices, stacks);
    let cols = slices + 1;
    let ring = |row: u32, col: u32| (1 + (row - 1) * cols + col) as usize;
    // Premise: the two seam copies share their position exactly but not their index.
    assert_eq!(mesh.positions[ring(3, 0)], mesh.positions[ring(3, slices)]);
    assert!(!mesh.validate().is_closed(), "an unwelded seam leaves boundary edges");

    for weighting in ALL {
        let unwelded = vertex_normals(&mesh, weighting).normals;
        let welded_mesh = mesh.weld_by_position(0.0);
        assert_eq!(welded_mesh.removed_faces, Vec::<usize>::new());
        assert!(welded_mesh.mesh.validate().is_clean(), "welding closes the sphere");
        let welded = vertex_normals(&welded_mesh.mesh, weighting).normals;
        for row in 1..stacks {
            let (a, b) = (ring(row, 0), ring(row, slices));
            // Without welding each copy sees only the faces on its side of the seam, so the two
            // normals part by about one slice of azimuth, 360°/slices, scaled by the ring's
            // radius sin θ (the normals' horizontal part). That is the visible crease.
            let crease = angle(unwelded[a].as_dvec3(), unwelded[b].as_dvec3());
            let theta = PI * f64::from(row) / f64::from(stacks);
            let expected = 2.0 * PI / f64::from(slices) * theta.sin();
            assert!(
                (0.5 * expected..=1.5 * expected).contains(&crease),
                "{weighting:?} row {row}: crease {:.3}° not near {:.3}°",
                crease.to_degrees(),
                expected.to_degrees()
            );
            // Welded, the seam vertex is like every other vertex of its ring: the mesh is symmetric
            // under a half turn about Y (slices is even), which takes column slices/2 to the
            // seam, so the two normals are equal after that rotation, up to f32 rounding.
            let seam = welded_mesh.remap[a] as usize;
            assert_eq!(seam, welded_mesh.remap[b] as usize, "both copies become one vertex");
            let other = welded_mesh.remap[ring(row, slices / 2)] as usize;
            let n = welded[other].as_dvec3();
            let turned = DVec3::new(-n.x, n.y, -n.z);
            let gap = angle(welded[seam].as_dvec3(), turned);
            assert!(gap < 1e-6, "{weighting:?} row {row}: seam normal {gap} rad from its ring's");
            assert!(gap < 1e-3 * crease, "welding removed the crease ({weighting:?} row {row})");
        }
    }
}
