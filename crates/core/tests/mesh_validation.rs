//! Mesh validation and welding. Each finding is shown on a small hand-made mesh that has exactly
//! that mistake, and the test asserts that exactly that is reported. The fixtures are checked
//! independently first (each face's normal points away from its solid's centre).

use std::collections::HashSet;

use cg_core::glam::{DQuat, DVec3, Vec2, Vec3};
use cg_core::lang::Lang;
use cg_core::mesh::{Mesh, MeshError, Orientation, Problem, T_JUNCTION_TOLERANCE};
use cg_core::shapes::{grid, lecture_pyramid, uv_sphere};
use cg_testkit::{Inputs, assert_approx_eq};

/// The unit cube [0, 1]³, written out by hand:
///
/// V0 (0,0,0) V1 (1,0,0) V2 (1,1,0) V3 (0,1,0) V4 (0,0,1) V5 (1,0,1) V6 (1,1,1) V7 (0,1,1);
/// F0, F1 back (z = 0); F2, F3 front; F4, F5 bottom; F6, F7 top; F8, F9 left; F10, F11 right.
fn cube() -> Mesh {
    let positions = vec![
        Vec3::new(0.0, 0.0, 0.0),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(1.0, 1.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(0.0, 0.0, 1.0),
        Vec3::new(1.0, 0.0, 1.0),
        Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(0.0, 1.0, 1.0),
    ];
    let faces = vec![
        [0, 3, 2],
        [0, 2, 1],
        [4, 5, 6],
        [4, 6, 7],
        [0, 1, 5],
        [0, 5, 4],
        [3, 7, 6],
        [3, 6, 2],
        [0, 4, 7],
        [0, 7, 3],
        [1, 2, 6],
        [1, 6, 5],
    ];
    Mesh::new(positions, faces)
}

/// The cube with V8, the midpoint of the front-bottom edge V4–V5, used by the front side only:
/// F2, F3 become `{V4, V8, V7}`, `{V8, V6, V7}`, and `{V8, V5, V6}` is appended as F12, while the
/// bottom's F5 `{V0, V5, V4}` still runs along the whole edge V5→V4.
fn cube_with_t_junction() -> Mesh {
    let mut m = cube();
    m.positions.push(Vec3::new(0.5, 0.0, 1.0));
    m.faces[2] = [4, 8, 7];
    m.faces[3] = [8, 6, 7];
    m.faces.push([8, 5, 6]);
    m
}

/// Two tetrahedra touching only at V0 (the origin): V1–V3 on +X, +Y, +Z, V4–V6 on −X, −Y, −Z.
fn bow_tie() -> Mesh {
    let positions =
        vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z, Vec3::NEG_X, Vec3::NEG_Y, Vec3::NEG_Z];
    let faces = vec![
        [0, 2, 1],
        [0, 1, 3],
        [0, 3, 2],
        [1, 2, 3],
        [0, 4, 5],
        [0, 6, 4],
        [0, 5, 6],
        [4, 6, 5],
    ];
    Mesh::new(positions, faces)
}

/// Fixture check, independent of `validate`: the listed faces' normals (by the lecture's
/// `(b−a)×(c−a)`) point away from `centre`.
fn assert_faces_point_away(m: &Mesh, faces: std::ops::Range<usize>, centre: Vec3) {
    for f in faces {
        let [a, b, c] = m.triangle(f);
        let n = (b - a).cross(c - a);
        assert!(n.dot((a + b + c) / 3.0 - centre) > 0.0, "fixture F{f} faces inward");
    }
}

fn reversed([a, b, c]: [u32; 3]) -> [u32; 3] {
    [a, c, b]
}

/// The V/F tokens of a text (`V1`, `F12`), so that `F1` does not match inside `F12`.
fn tokens(text: &str) -> HashSet<&str> {
    text.split(|c: char| !c.is_ascii_alphanumeric()).filter(|t| !t.is_empty()).collect()
}

#[test]
fn fixtures_face_outward() {
    assert_faces_point_away(&cube(), 0..12, Vec3::splat(0.5));
    let t = cube_with_t_junction();
    assert_faces_point_away(&t, 0..13, Vec3::splat(0.5));
    let b = bow_tie();
    assert_faces_point_away(&b, 0..4, Vec3::splat(0.25));
    assert_faces_point_away(&b, 4..8, Vec3::splat(-0.25));
}

#[test]
fn cube_is_clean_closed_and_outward() {
    let v = cube().validate();
    assert!(v.is_clean(), "{:#?}", v.problems());
    assert!(v.is_closed() && v.is_manifold() && v.is_consistently_wound());
    assert_eq!(v.orientation(), Some(Orientation::Outward));
    assert_eq!(v.edge_count(), 18, "12 cube edges and 6 diagonals");
    assert_approx_eq!(v.signed_volume().unwrap(), 1.0, abs = 1e-12);
}

#[test]
fn one_reversed_face_is_named_on_its_three_edges() {
    let mut m = cube();
    m.faces[4] = reversed(m.faces[4]);
    let v = m.validate();
    // Each edge of the reversed F4 is now traversed the same way by F4 and its neighbour.
    let [a, b, c] = m.faces[4];
    let mut expected: HashSet<[u32; 2]> = [[a, b], [b, c], [c, a]].into_iter().collect();
    assert_eq!(v.problems().len(), 3, "{:#?}", v.problems());
    for p in v.problems() {
        let Problem::InconsistentWinding { edge, faces } = p else { panic!("unexpected {p:?}") };
        assert!(expected.remove(edge), "edge {edge:?} reported twice or not F4's");
        assert!(faces.contains(&4), "{p:?} does not name F4");
        let other = if faces[0] == 4 { faces[1] } else { faces[0] };
        let f = m.faces[other];
        assert!(
            [[f[0], f[1]], [f[1], f[2]], [f[2], f[0]]].contains(edge),
            "F{other} does not traverse {edge:?}"
        );
    }
    assert!(v.is_closed() && v.is_manifold() && !v.is_consistently_wound());
    assert_eq!((v.orientation(), v.signed_volume()), (None, None));
}

#[test]
fn whole_cube_reversed_is_inward() {
    let mut m = cube();
    m.faces.iter_mut().for_each(|f| *f = reversed(*f));
    let v = m.validate();
    assert_eq!(v.orientation(), Some(Orientation::Inward));
    assert_approx_eq!(v.signed_volume().unwrap(), -1.0, abs = 1e-12);
    assert!(
        matches!(v.problems(), [Problem::InwardFacing { signed_volume }] if *signed_volume < 0.0),
        "{:#?}",
        v.problems()
    );
}

#[test]
fn removed_face_leaves_its_three_edges_open() {
    let mut m = cube();
    let gone = m.faces.remove(4);
    let v = m.validate();
    // The neighbours traverse the missing face's edges the other way round.
    let [a, b, c] = gone;
    let mut expected: HashSet<[u32; 2]> = [[b, a], [c, b], [a, c]].into_iter().collect();
    assert_eq!(v.problems().len(), 3, "{:#?}", v.problems());
    for p in v.problems() {
        let Problem::BoundaryEdge { edge, face } = p else { panic!("unexpected {p:?}") };
        assert!(expected.remove(edge), "{edge:?}");
        let f = m.faces[*face];
        assert!([[f[0], f[1]], [f[1], f[2]], [f[2], f[0]]].contains(edge), "{p:?}");
    }
    assert!(!v.is_closed() && v.is_manifold() && v.is_consistently_wound());
    assert_eq!(v.orientation(), None);
}

#[test]
fn row03_duplicated_vertex_leaves_boundary_edges_and_welding_fixes_it() {
    // The bottom faces F4, F5 use V8, a copy of V0, instead of V0 itself (a typical mistake when
    // each side is typed in separately; docs/numerics.md row 3's seam vertices).
    let mut m = cube();
    m.positions.push(m.positions[0]);
    m.faces[4] = [8, 1, 5];
    m.faces[5] = [8, 5, 4];
    let v = m.validate();
    // V8's edges to V1 and V4 are on one side of the seam, V0's on the other: the neighbouring
    // faces F1 {V0, V2, V1} and F8 {V0, V4, V7} no longer share them.
    let expected = vec![
        Problem::BoundaryEdge { edge: [1, 0], face: 1 },
        Problem::BoundaryEdge { edge: [0, 4], face: 8 },
        Problem::BoundaryEdge { edge: [8, 1], face: 4 },
        Problem::BoundaryEdge { edge: [4, 8], face: 5 },
    ];
    assert_eq!(v.problems(), expected.as_slice());

    let welded = m.weld_by_position(0.0);
    assert_eq!(welded.remap, vec![0, 1, 2, 3, 4, 5, 6, 7, 0]);
    assert!(welded.removed_faces.is_empty());
    assert_eq!(welded.mesh, cube(), "the weld restores the hand-made cube exactly");
    assert!(welded.mesh.validate().is_clean());
}

/// A soup of 40 000 small separate triangles in a unit square and one triangle 9 000 away: the
/// T-junction search's cells follow the edges' median length, not the bounding box (1 024 cells
/// along it put the whole cluster in one cell, and every boundary edge met every candidate:
/// minutes, hours at 800 000 triangles). One triangle's corner placed inside another's edge is
/// found among them.
#[test]
fn a_cluster_and_a_stray_triangle_are_searched_cell_by_cell() {
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for i in 0..200 {
        for j in 0..200 {
            let o = Vec3::new(i as f32 * 0.005, j as f32 * 0.005, 0.0);
            let k = positions.len() as u32;
            positions.extend([o, o + Vec3::new(0.002, 0.0, 0.0), o + Vec3::new(0.0, 0.002, 0.0)]);
            faces.push([k, k + 1, k + 2]);
        }
    }
    // The stray triangle, and a corner on the middle of the first triangle's bottom edge.
    let k = positions.len() as u32;
    positions.extend([
        Vec3::splat(9000.0),
        Vec3::new(9001.0, 9000.0, 0.0),
        Vec3::new(9000.0, 9001.0, 0.0),
    ]);
    faces.push([k, k + 1, k + 2]);
    let k = positions.len() as u32;
    positions.extend([
        Vec3::new(0.001, 0.0, 0.0),
        Vec3::new(0.001, -0.002, 0.0),
        Vec3::new(0.003, -0.002, 0.0),
    ]);
    faces.push([k, k + 2, k + 1]);
    let v = Mesh::new(positions, faces).validate();
    let t: Vec<&Problem> =
        v.problems().iter().filter(|p| matches!(p, Problem::TJunction { .. })).collect();
    assert_eq!(t, [&Problem::TJunction { vertex: k, edge: [0, 1], face: 0 }]);
}

#[test]
fn t_junction_names_vertex_edge_and_face() {
    let v = cube_with_t_junction().validate();
    // Nothing else: the boundary edges V5–V4, V4–V8, V8–V5 all lie along the T-junction's edge.
    assert_eq!(v.problems(), &[Problem::TJunction { vertex: 8, edge: [5, 4], face: 5 }]);
    assert!(!v.is_closed(), "the mesh is still open along the crack");

    // The fix: split F5 {V0, V5, V4} at V8 too.
    let mut fixed = cube_with_t_junction();
    fixed.faces[5] = [0, 5, 8];
    fixed.faces.push([0, 8, 4]);
    let v = fixed.validate();
    assert!(v.is_clean(), "{:#?}", v.problems());
    assert_approx_eq!(v.signed_volume().unwrap(), 1.0, abs = 1e-12);
}

#[test]
fn t_junction_tolerance_is_relative_to_the_edge() {
    // V8 off the edge V5–V4 (length 1) by 10× less than the tolerance: still a T-junction. By 10×
    // more: a vertex that is merely near the edge, so the crack's three edges are plain
    // boundary edges.
    for (offset, is_t_junction) in
        [(0.1 * T_JUNCTION_TOLERANCE, true), (10.0 * T_JUNCTION_TOLERANCE, false)]
    {
        for scale in [1.0f32, 1e-4, 1e4] {
            let mut m = cube_with_t_junction();
            m.positions[8].y = offset as f32;
            m.positions.iter_mut().for_each(|p| *p *= scale);
            let v = m.validate();
            let t = v.problems().iter().filter(|p| matches!(p, Problem::TJunction { .. })).count();
            let b =
                v.problems().iter().filter(|p| matches!(p, Problem::BoundaryEdge { .. })).count();
            assert_eq!(
                (t, b),
                if is_t_junction { (1, 0) } else { (0, 3) },
                "offset {offset}, scale {scale}"
            );
        }
    }
}

#[test]
fn t_junction_far_from_the_origin_is_found() {
    // At 1e4 the f32 spacing is ~1e-3 of the unit cube: the midpoint is exactly representable,
    // and the tolerance adds the position rounding, so it is still found.
    let mut m = cube_with_t_junction();
    m.positions.iter_mut().for_each(|p| *p += Vec3::new(1.0e4, -2.5e4, 1.0e4));
    assert_eq!(m.validate().problems(), &[Problem::TJunction { vertex: 8, edge: [5, 4], face: 5 }]);
}

#[test]
fn t_junctions_along_a_long_edge_are_all_found_among_many_candidates() {
    // A 40×40 grid over x ∈ [−10, 0] meets a single quad {A, B, C, D} over x ∈ [0, 10] along
    // x = 0: they share only the ends A, B of the quad's edge A–B (length 10), so the grid's 39
    // other border vertices on x = 0 are T-junctions on it. Far away, 3000 tiny loose triangles
    // add 9000 boundary edges: with that many candidates the search must use its grid (cells
    // ~0.06 long), walking along A–B when it is turned diagonal, visiting its box when not.
    let mut inputs = Inputs::seeded(0x7a0c);
    let mut m = grid(40, 10.0).unwrap();
    m.normals = None;
    m.uvs = None;
    m.positions.iter_mut().for_each(|p| p.x -= 5.0);
    let seam: Vec<u32> = (0..=40).map(|j| j * 41 + 40).collect();
    let (a, b) = (seam[0], seam[40]);
    let (c, d) = (m.positions.len() as u32, m.positions.len() as u32 + 1);
    m.positions.extend([Vec3::new(10.0, 0.0, 5.0), Vec3::new(10.0, 0.0, -5.0)]);
    let quad = m.faces.len();
    m.faces.extend([[a, b, c], [a, c, d]]);
    for _ in 0..3000 {
        let base = m.positions.len() as u32;
        let centre = Vec3::new(40.0, 0.0, 0.0) + inputs.vec3_in_cube(10.0);
        m.positions.extend((0..3).map(|_| centre + inputs.vec3_in_cube(0.03)));
        m.faces.push([base, base + 1, base + 2]);
    }
    for turned in [false, true] {
        let mut m = m.clone();
        if turned {
            let q = DQuat::from_axis_angle(DVec3::new(1.0, -2.0, 0.5).normalize(), 1.1);
            m.positions.iter_mut().for_each(|p| *p = (q * p.as_dvec3()).as_vec3());
        }
        let v = m.validate();
        let found: Vec<&Problem> =
            v.problems().iter().filter(|p| matches!(p, Problem::TJunction { .. })).collect();
        let expected: Vec<Problem> = seam[1..40]
            .iter()
            .map(|&vertex| Problem::TJunction { vertex, edge: [a, b], face: quad })
            .collect();
        assert_eq!(found, expected.iter().collect::<Vec<_>>(), "turned: {turned}");
    }
}

#[test]
fn fin_is_a_non_manifold_edge_naming_all_three_faces() {
    // F12 hangs off the cube's edge V0–V1 (shared by F1 and F4) into the outside.
    let mut m = cube();
    m.positions.push(Vec3::new(0.5, -1.0, -1.0));
    m.faces.push([0, 1, 8]);
    let v = m.validate();
    // The fin's two free edges are open, as any fin's are; nothing else.
    let expected = vec![
        Problem::BoundaryEdge { edge: [8, 0], face: 12 },
        Problem::BoundaryEdge { edge: [1, 8], face: 12 },
        Problem::NonManifoldEdge { edge: [0, 1], faces: vec![1, 4, 12] },
    ];
    assert_eq!(v.problems(), expected.as_slice());
    assert!(!v.is_manifold());
    assert_eq!(v.signed_volume(), None);
}

#[test]
fn bow_tie_vertex_is_named() {
    let v = bow_tie().validate();
    assert_eq!(v.problems(), &[Problem::NonManifoldVertex { vertex: 0, fans: 2 }]);
    assert!(v.is_closed() && !v.is_manifold() && v.is_consistently_wound());
    // Still a closed surface with a volume: two tetrahedra of 1/6 each.
    assert_eq!(v.orientation(), Some(Orientation::Outward));
    assert_approx_eq!(v.signed_volume().unwrap(), 1.0 / 3.0, abs = 1e-12);
}

#[test]
fn row01_degenerate_faces_are_named() {
    // A repeated index: reported, and left out of the edge checks (so the cube stays closed).
    let mut m = cube();
    m.faces.push([0, 0, 1]);
    let v = m.validate();
    assert_eq!(v.problems(), &[Problem::RepeatedIndex { face: 12, vertices: [0, 0, 1] }]);
    assert!(v.is_closed());
    assert_eq!(v.orientation(), Some(Orientation::Outward));

    // Three different but collinear vertices: a sliver {V4, V5, V8} filling the T-junction's
    // crack. It closes the mesh (each of its edges pairs with the crack's), so the zero area is
    // the only finding, and the volume stays finite and exact.
    let mut m = cube_with_t_junction();
    m.faces.push([4, 5, 8]);
    let v = m.validate();
    assert_eq!(v.problems(), &[Problem::ZeroArea { face: 13, vertices: [4, 5, 8] }]);
    assert_approx_eq!(v.signed_volume().unwrap(), 1.0, abs = 1e-12);

    // Coincident (distinct) vertices are zero-area too.
    let m = Mesh::new(vec![Vec3::ONE, Vec3::ONE, Vec3::ZERO], vec![[0, 1, 2]]);
    assert!(m.validate().problems().contains(&Problem::ZeroArea { face: 0, vertices: [0, 1, 2] }));
}

#[test]
fn structural_errors_are_all_reported_without_panic() {
    let mut m = cube();
    m.uvs = Some(vec![Vec2::ZERO; 3]);
    m.positions[3] = Vec3::new(0.0, f32::NAN, 0.0);
    m.positions[6].z = f32::INFINITY;
    m.faces.push([0, 1, 8]);
    m.faces.push([99, 1, 2]);
    let v = m.validate();
    let expected: Vec<Problem> = [
        MeshError::AttributeLength { attribute: "uvs", len: 3, expected: 8 },
        MeshError::NonFinitePosition { vertex: 3, position: m.positions[3] },
        MeshError::NonFinitePosition { vertex: 6, position: m.positions[6] },
        MeshError::IndexOutOfRange { face: 12, corner: 2, index: 8, vertex_count: 8 },
        MeshError::IndexOutOfRange { face: 13, corner: 0, index: 99, vertex_count: 8 },
    ]
    .into_iter()
    .map(Problem::Structure)
    .collect();
    // NaN ≠ NaN, so compare the descriptions where a NaN is inside.
    assert_eq!(v.problems().len(), expected.len(), "{:#?}", v.problems());
    for (got, want) in v.problems().iter().zip(&expected) {
        assert_eq!(got.describe(Lang::En), want.describe(Lang::En));
    }
    assert!(!v.is_closed() && !v.is_manifold() && !v.is_consistently_wound());
    assert_eq!((v.edge_count(), v.orientation(), v.signed_volume()), (0, None, None));
    // The cheap check stops at the first.
    assert!(matches!(m.check_indices(), Err(MeshError::AttributeLength { .. })));
    // Welding does not panic either: out-of-range faces are removed, NaN is never merged.
    let w = m.weld_by_position(0.5);
    assert_eq!(w.removed_faces, vec![12, 13]);
    assert_eq!(w.mesh.uvs, None, "a uv vector of the wrong length is dropped");
}

#[test]
fn lecture_pyramid_is_clean_and_outward() {
    let v = lecture_pyramid().validate();
    assert!(v.is_clean(), "{:#?}", v.problems());
    assert_eq!(v.orientation(), Some(Orientation::Outward));
    // Base 2 × 2 at y = −0.8, apex at y = 1: (1/3)·4·1.8 = 2.4 (−0.8 is not exact in f32).
    assert_approx_eq!(v.signed_volume().unwrap(), 2.4, rel = 1e-7);
    assert_eq!(v.edge_count(), 9, "V − E + F = 5 − 9 + 6 = 2");
}

#[test]
fn ground_grid_is_open_with_exactly_its_40_border_edges() {
    let g = grid(10, 10.0).unwrap();
    let v = g.validate();
    assert_eq!(v.problems().len(), 40, "{:#?}", v.problems());
    for p in v.problems() {
        let Problem::BoundaryEdge { edge: [a, b], .. } = p else { panic!("unexpected {p:?}") };
        // Both ends on the border of the ±5 square, one unit apart along it.
        let (pa, pb) = (g.positions[*a as usize], g.positions[*b as usize]);
        let on_border = |p: Vec3| p.x.abs() == 5.0 || p.z.abs() == 5.0;
        assert!(on_border(pa) && on_border(pb) && pa.distance(pb) == 1.0, "{p:?}");
        assert!(pa.x == pb.x && pa.x.abs() == 5.0 || pa.z == pb.z && pa.z.abs() == 5.0, "{p:?}");
    }
    assert!(!v.is_closed() && v.is_manifold() && v.is_consistently_wound());
    assert_eq!((v.orientation(), v.signed_volume()), (None, None));
    // A disc: V − E + F = 1, with E = 10·11 + 11·10 edges along the lines and 100 diagonals.
    assert_eq!(v.edge_count(), 320);
}

#[test]
fn unreferenced_vertex_is_a_minor_finding() {
    let mut m = cube();
    m.positions.push(Vec3::splat(0.5));
    let v = m.validate();
    assert_eq!(v.problems(), &[Problem::UnreferencedVertex { vertex: 8 }]);
    assert!(v.problems()[0].is_minor());
    assert!(!v.is_clean() && v.is_closed());
    assert_eq!(v.orientation(), Some(Orientation::Outward));
}

#[test]
fn back_to_back_faces_enclose_no_volume() {
    let m = Mesh::new(vec![Vec3::X, Vec3::Y, Vec3::new(0.3, 0.4, 2.0)], vec![[0, 1, 2], [0, 2, 1]]);
    let v = m.validate();
    assert!(v.is_closed() && v.is_consistently_wound());
    assert!(matches!(v.problems(), [Problem::ZeroVolume { .. }]), "{:#?}", v.problems());
    assert_eq!(v.orientation(), None, "neither side is outside");
}

#[test]
fn empty_mesh_is_clean_but_not_closed() {
    let v = Mesh::default().validate();
    assert!(v.is_clean() && !v.is_closed());
    assert_eq!((v.edge_count(), v.orientation()), (0, None));
}

#[test]
fn far_from_the_origin_the_signed_volume_uses_the_centroid() {
    // A cube of edge 125, turned, its corners rounded to multiples of 1/8: at the origin every
    // triple product a·(b×c) is exact in f64, so the volume there is exact — the oracle. Moved by
    // ~1.5·2²⁰, where the f32 spacing is exactly 1/8 (the cube spans 1000 of those steps), the
    // positions stay exact, so the volume must not change at all.
    let turn = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7);
    let mut m = cube();
    for p in &mut m.positions {
        let q = turn * ((p.as_dvec3() - 0.5) * 125.0);
        *p = ((q * 8.0).round() / 8.0).as_vec3();
    }
    let origin_based = |m: &Mesh| -> f64 {
        let six_v: f64 = (0..m.face_count())
            .map(|f| {
                let [a, b, c] = m.triangle(f).map(|p| p.as_dvec3());
                a.dot(b.cross(c))
            })
            .sum();
        six_v / 6.0
    };
    let exact = origin_based(&m);
    assert_approx_eq!(exact, 125f64.powi(3), rel = 0.01, "the rounded cube is still about 125³");
    assert_eq!(m.validate().signed_volume(), Some(exact));

    let offset = Vec3::new(1.5 * 1_048_576.0, -1.25 * 1_048_576.0, 1.75 * 1_048_576.0);
    let moved: Vec<Vec3> = m.positions.iter().map(|&p| p + offset).collect();
    for (p, q) in m.positions.iter().zip(&moved) {
        assert_eq!(q.as_dvec3() - offset.as_dvec3(), p.as_dvec3(), "the move is exact in f32");
    }
    m.positions = moved;
    let v = m.validate();
    assert!(v.is_clean(), "{:#?}", v.problems());
    // Relative to the centroid (exact here) the terms are as small as at the origin: exact.
    assert_eq!(v.signed_volume(), Some(exact));
    // The premise: about the origin the terms are ~1e13 and cancel to ~1e6, and their products
    // need more than 53 bits; f64 keeps the error small (~1e-8 relative here) but not zero.
    let naive = origin_based(&m);
    assert_ne!(naive, exact, "the origin-based sum happened to be exact");
    assert_approx_eq!(naive, exact, rel = 1e-7, "and it is not wildly off either");
}

#[test]
fn describe_names_the_right_numbers_in_both_languages() {
    let winding = Problem::InconsistentWinding { edge: [1, 3], faces: [0, 4] };
    assert_eq!(
        winding.describe(Lang::En),
        "edge V1–V3 is used by F0 and F4 in the same direction: one of them is wound the wrong way"
    );
    let cases: Vec<(Problem, &[&str])> = vec![
        (winding.clone(), &["V1", "V3", "F0", "F4"]),
        (Problem::RepeatedIndex { face: 7, vertices: [1, 1, 3] }, &["F7", "V1", "V3"]),
        (Problem::ZeroArea { face: 7, vertices: [1, 2, 3] }, &["F7", "V1", "V2", "V3"]),
        (Problem::BoundaryEdge { edge: [3, 5], face: 2 }, &["V3", "V5", "F2"]),
        (
            Problem::NonManifoldEdge { edge: [0, 1], faces: vec![1, 4, 12] },
            &["V0", "V1", "F1", "F4", "F12"],
        ),
        (Problem::NonManifoldVertex { vertex: 4, fans: 2 }, &["V4"]),
        (Problem::TJunction { vertex: 8, edge: [5, 4], face: 5 }, &["V8", "V5", "V4", "F5"]),
        (Problem::InwardFacing { signed_volume: -1.0 }, &[]),
        (Problem::ZeroVolume { signed_volume: 0.0 }, &[]),
        (Problem::UnreferencedVertex { vertex: 9 }, &["V9"]),
        (
            Problem::Structure(MeshError::IndexOutOfRange {
                face: 3,
                corner: 1,
                index: 5,
                vertex_count: 5,
            }),
            &["F3", "V5", "V0", "V4"],
        ),
        (
            Problem::Structure(MeshError::AttributeLength {
                attribute: "normals",
                len: 2,
                expected: 5,
            }),
            &[],
        ),
        (
            Problem::Structure(MeshError::NonFinitePosition { vertex: 2, position: Vec3::NAN }),
            &["V2"],
        ),
    ];
    for (problem, names) in cases {
        let (ja, en) = (problem.describe(Lang::Ja), problem.describe(Lang::En));
        assert_ne!(ja, en, "{problem:?}");
        assert!(ja.chars().any(|c| ('\u{3040}'..='\u{30ff}').contains(&c)), "not Japanese: {ja}");
        for text in [&ja, &en] {
            let found = tokens(text);
            for name in names {
                assert!(found.contains(name), "{name} missing from {text:?}");
            }
            // No stray F/V numbers: every V/F token is one of the expected names.
            for t in &found {
                let numbered = t.len() > 1 && t[1..].bytes().all(|b| b.is_ascii_digit());
                if numbered && (t.starts_with('V') || t.starts_with('F')) {
                    assert!(names.contains(t), "unexpected {t} in {text:?}");
                }
            }
        }
        let hint = problem.hint();
        assert!(!hint.ja.is_empty() && !hint.en.is_empty());
        assert_ne!(hint.ja, hint.en);
        assert_eq!(problem.to_string(), en, "Display is the English description");
    }
}

#[test]
fn large_meshes_validate_without_quadratic_work() {
    // 100k faces in release (milliseconds); smaller in debug. No timing is asserted: the sorting
    // and grid hashing keep it O(n log n); an O(n²) T-junction search would not finish here.
    let (slices, stacks) = if cfg!(debug_assertions) { (64, 64) } else { (256, 200) };
    let sphere = uv_sphere(1.0, slices, stacks).unwrap();
    assert!(sphere.validate().is_clean());
    // The worst case for the T-junction search: a triangle soup, every edge a boundary edge and
    // every vertex a candidate (each position six times).
    let mut soup = Mesh::default();
    for f in 0..sphere.face_count() {
        let base = soup.positions.len() as u32;
        soup.positions.extend(sphere.triangle(f));
        soup.faces.push([base, base + 1, base + 2]);
    }
    let v = soup.validate();
    assert_eq!(v.problems().len(), 3 * soup.face_count());
    assert!(v.problems().iter().all(|p| matches!(p, Problem::BoundaryEdge { .. })));
    // Welding the soup gives back the sphere: its vertex count, and the same triangles (the
    // vertices are numbered by first use now, not as the sphere numbers them).
    let w = soup.weld_by_position(0.0);
    assert_eq!(w.mesh.vertex_count(), sphere.vertex_count());
    assert!(w.removed_faces.is_empty());
    assert!((0..sphere.face_count()).all(|f| w.mesh.triangle(f) == sphere.triangle(f)));
    assert!(w.mesh.validate().is_clean());
}

// ---------------------------------------------------------------------------------------------
// Welding

#[test]
fn weld_exact_merges_bit_equal_positions_and_both_zeros() {
    let p = Vec3::new(0.1, 2.0, -3.0);
    let m = Mesh::new(
        vec![
            p,
            Vec3::new(0.1, 2.0, -3.000_000_2), // one ulp away: not merged by an exact weld
            p,
            Vec3::new(-0.0, 0.0, 0.0),
            Vec3::ZERO,
            Vec3::new(0.0, -0.0, -0.0),
            Vec3::NAN,
            Vec3::NAN,
        ],
        vec![[0, 1, 3], [2, 1, 4], [0, 2, 5]],
    );
    let w = m.weld_by_position(0.0);
    assert_eq!(w.remap, vec![0, 1, 0, 2, 2, 2, 3, 4], "NaN positions are never merged");
    assert_eq!(w.removed_faces, vec![2], "{{V0, V2, V5}} collapsed");
    assert_eq!(w.mesh.faces, vec![[0, 1, 2], [0, 1, 2]]);
    // The first occurrence is kept: −0 here.
    assert!(w.mesh.positions[2].x.is_sign_negative());
    // A negative or NaN tolerance is an exact weld (compared without the NaN positions, since
    // NaN ≠ NaN).
    for tolerance in [-1.0, f32::NAN] {
        let other = m.weld_by_position(tolerance);
        assert_eq!(
            (&other.remap, &other.mesh.faces, &other.removed_faces),
            (&w.remap, &w.mesh.faces, &w.removed_faces)
        );
    }
}

#[test]
fn weld_tolerance_does_not_chain() {
    // 0 → kept; 0.6t → joins V0; 1.2t → more than t from V0, the only kept vertex, so kept (even
    // though it is within t of the second one); 1.9t → joins the vertex at 1.2t.
    let t = 0.01f32;
    let xs = [0.0, 0.6 * t, 1.2 * t, 1.9 * t];
    let m = Mesh::new(xs.iter().map(|&x| Vec3::new(x, 5.0, -7.0)).collect(), vec![]);
    assert_eq!(m.weld_by_position(t).remap, vec![0, 0, 1, 1]);
    // An infinite tolerance merges every finite position.
    assert_eq!(m.weld_by_position(f32::INFINITY).remap, vec![0, 0, 0, 0]);
}

/// The welding rule, by brute force: each vertex joins the lowest-numbered earlier kept vertex
/// within the tolerance (f64 distance), or is kept.
fn weld_oracle(positions: &[Vec3], tolerance: f64) -> Vec<u32> {
    let mut kept: Vec<usize> = Vec::new();
    let mut remap = Vec::new();
    for (i, p) in positions.iter().enumerate() {
        let near =
            kept.iter().position(|&k| positions[k].as_dvec3().distance(p.as_dvec3()) <= tolerance);
        remap.push(near.unwrap_or_else(|| {
            kept.push(i);
            kept.len() - 1
        }) as u32);
    }
    remap
}

#[test]
fn weld_matches_the_brute_force_rule() {
    // Clusters of points around random centres at large offsets, jittered on the scale of the
    // tolerance (so pairs straddle cell borders and the tolerance itself), in random order.
    let mut inputs = Inputs::seeded(0x3e1d);
    for round in 0..20 {
        let tolerance = inputs.log_uniform(-4.0, 0.0).abs();
        let offset = inputs.vec3_log_uniform(0.0, 4.0);
        let centres: Vec<Vec3> =
            (0..30).map(|_| offset + inputs.vec3_in_cube(20.0 * tolerance as f32)).collect();
        let positions: Vec<Vec3> = (0..600)
            .map(|_| {
                let c = centres[inputs.int(0, 30) as usize];
                c + inputs.vec3_in_cube(1.5 * tolerance as f32)
            })
            .collect();
        let m = Mesh::new(positions.clone(), vec![]);
        let w = m.weld_by_position(tolerance as f32);
        let expected = weld_oracle(&positions, f64::from(tolerance as f32));
        assert_eq!(w.remap, expected, "round {round}, seed {}", inputs.seed());
        // Kept vertices keep their order and their positions.
        for (i, p) in positions.iter().enumerate() {
            let kept = w.mesh.positions[w.remap[i] as usize];
            assert!(kept.as_dvec3().distance(p.as_dvec3()) <= f64::from(tolerance as f32));
        }
    }
}

#[test]
fn weld_keeps_the_first_occurrence_attributes() {
    // A texture seam: V0 and V2 share a position but not a texture coordinate. Only V0's survives.
    let mut m =
        Mesh::new(vec![Vec3::ZERO, Vec3::X, Vec3::ZERO, Vec3::Y], vec![[0, 1, 3], [2, 3, 1]]);
    m.uvs = Some(vec![
        Vec2::new(0.0, 0.0),
        Vec2::new(0.5, 0.0),
        Vec2::new(1.0, 0.0),
        Vec2::new(0.5, 1.0),
    ]);
    m.normals = Some(vec![Vec3::Z, Vec3::Z, Vec3::NEG_Z, Vec3::Z]);
    m.colors = Some(vec![Vec3::X, Vec3::Y, Vec3::Z, Vec3::ONE]);
    let w = m.weld_by_position(0.0);
    assert_eq!(w.remap, vec![0, 1, 0, 2]);
    assert_eq!(
        w.mesh.uvs,
        Some(vec![Vec2::new(0.0, 0.0), Vec2::new(0.5, 0.0), Vec2::new(0.5, 1.0)])
    );
    assert_eq!(w.mesh.normals, Some(vec![Vec3::Z, Vec3::Z, Vec3::Z]));
    assert_eq!(w.mesh.colors, Some(vec![Vec3::X, Vec3::Y, Vec3::ONE]));
    assert_eq!(w.mesh.faces, vec![[0, 1, 2], [0, 2, 1]]);
}

#[test]
fn weld_removes_collapsed_faces_and_lists_them() {
    // F1's corners V3 and V4 are 1e-4 apart: a weld at 1e-3 collapses it; F0 and F2 survive.
    let m = Mesh::new(
        vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z, Vec3::new(0.0, 0.0, 1.0001), Vec3::ONE],
        vec![[0, 1, 2], [3, 4, 5], [1, 2, 4], [2, 2, 5]],
    );
    let w = m.weld_by_position(1e-3);
    assert_eq!(w.remap, vec![0, 1, 2, 3, 3, 4]);
    assert_eq!(w.removed_faces, vec![1, 3], "F1 collapsed; F3 had a repeated index already");
    assert_eq!(w.mesh.faces, vec![[0, 1, 2], [1, 2, 3]]);
    assert_eq!(w.mesh.positions.len(), 5);
    // Nothing collapses at a tolerance below the gap.
    assert_eq!(m.weld_by_position(1e-5).removed_faces, vec![3]);
}

#[test]
fn weld_is_deterministic_and_linear_on_100k_vertices() {
    // 100k vertices: 50k random points, each once more with a jitter far below the tolerance,
    // shuffled. No timing is asserted; the grid hashing keeps it O(n) (an O(n²) weld would take
    // minutes here).
    let mut inputs = Inputs::seeded(0x57e1d);
    let n = 50_000;
    let base: Vec<Vec3> = (0..n).map(|_| inputs.vec3_in_cube(100.0)).collect();
    let mut positions: Vec<Vec3> = base.clone();
    positions.extend(base.iter().map(|&p| p + inputs.vec3_in_cube(1e-6)));
    for i in (1..positions.len()).rev() {
        positions.swap(i, inputs.int(0, i as i64 + 1) as usize);
    }
    let m = Mesh::new(positions.clone(), vec![]);
    let w = m.weld_by_position(1e-4);
    // Random points in a 200-wide cube are ≥ 1e-4 apart with overwhelming probability (the
    // expected number of closer pairs is ~1e-9), so exactly the twins merge.
    assert_eq!(w.mesh.vertex_count(), n);
    for (i, p) in positions.iter().enumerate() {
        let r = w.remap[i] as usize;
        assert!(w.mesh.positions[r].distance(*p) <= 1e-4, "V{i}");
    }
    assert_eq!(m.weld_by_position(1e-4), w, "the same input gives the same result");
    // A tolerance far below the positions' precision (1e-20): the cell indices stayed inside
    // i64 (they saturated, every vertex met every other in a few cells, and a grid of two
    // million vertices took hours to load). Only the exact twins merge.
    let mut exact = base.clone();
    exact.extend(base.iter().take(1000));
    let w = Mesh::new(exact, vec![]).weld_by_position(1e-20);
    assert_eq!(w.mesh.vertex_count(), n);
    assert!(w.remap[n..].iter().enumerate().all(|(k, &r)| r as usize == w.remap[k] as usize));
}
