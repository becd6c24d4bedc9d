//! The instructor's proof for assignment a1 (polygon model): every check passes on the reference
//! solution for students of every shape family and numbering; every check fails on the pristine
//! stubs; each broken answer of a kind students really hand in fails exactly the checks meant
//! to catch it (and explains itself, in both languages, naming the place); the view draws the
//! student's own normals.

// The assignment crates, through the kit's one list (cg-assign).
use cg_assign::cg_a1;

use std::collections::{BTreeSet, HashSet};

use cg_a1::ShapeExt as _;
use cg_a1::SpecDescribe as _;
use cg_a1::{Impl, Order, RidgeAxis, Shape, Spec, Turn};
use cg_core::glam::{Mat4, Vec3};
use cg_core::lang::Lang;
use cg_core::scene::NormalSource;
use cg_harness::check::{CheckResult, Outcome, guarded};
use cg_harness::{StudentNumber, TableVersion, VariantRng};
use cg_solutions::a1 as sol;
use cg_student::product::{Factor, MatrixProduct};

mod common;

/// Students chosen so that every family, both orders, both ring directions, both ridge axes and
/// every number of sides 3–8 occur (asserted below).
const STUDENTS: [&str; 11] = [
    "20250000", "20250001", "20250003", "20250004", "20250005", "20250009", "20250012", "20250017",
    "20250031", "20250033", "12345678",
];

/// Every check ID of the assignment, in order.
const IDS: [&str; 14] = [
    "a1.t1.count",
    "a1.t1.positions",
    "a1.t2.indices",
    "a1.t2.degenerate",
    "a1.t2.closed",
    "a1.t2.manifold",
    "a1.t2.winding",
    "a1.t2.outward",
    "a1.t2.count",
    "a1.t2.surface",
    "a1.t3.count",
    "a1.t3.unit",
    "a1.t3.normals",
    "a1.t4.placement",
];

fn spec_of(student: &str) -> Spec {
    let n: StudentNumber = student.parse().unwrap();
    cg_a1::variant(&mut VariantRng::new(&n, TableVersion::V1, cg_a1::ID))
}

fn failing(results: &[CheckResult]) -> BTreeSet<String> {
    results.iter().filter(|c| !c.passed()).map(|c| c.id.clone()).collect()
}

fn family(spec: &Spec) -> &'static str {
    match spec.shape {
        Shape::Pyramid { .. } => "pyramid",
        Shape::Prism { .. } => "prism",
        Shape::Frustum { .. } => "frustum",
        Shape::Tower { .. } => "tower",
        Shape::Bipyramid { .. } => "bipyramid",
        Shape::Octahedron { .. } => "octahedron",
        Shape::House { .. } => "house",
        Shape::Wedge { .. } => "wedge",
    }
}

#[test]
fn the_chosen_students_cover_every_option() {
    let specs: Vec<Spec> = STUDENTS.iter().map(|s| spec_of(s)).collect();
    let families: HashSet<&str> = specs.iter().map(family).collect();
    assert_eq!(families.len(), cg_a1::FAMILIES.len(), "{families:?}");
    for f in cg_a1::FAMILIES {
        assert!(families.contains(f), "{f}");
    }
    let orders: HashSet<Order> = specs.iter().map(|s| s.numbering.order).collect();
    let rings: HashSet<Turn> = specs.iter().map(|s| s.numbering.ring).collect();
    assert_eq!((orders.len(), rings.len()), (2, 2));
    let ridges: HashSet<RidgeAxis> = specs
        .iter()
        .filter_map(|s| match s.shape {
            Shape::House { ridge, .. } => Some(ridge),
            _ => None,
        })
        .collect();
    assert_eq!(ridges.len(), 2);
    let sides: BTreeSet<u32> = specs
        .iter()
        .filter_map(|s| match s.shape {
            Shape::Pyramid { sides, .. }
            | Shape::Prism { sides, .. }
            | Shape::Frustum { sides, .. }
            | Shape::Tower { sides, .. }
            | Shape::Bipyramid { sides, .. } => Some(sides),
            _ => None,
        })
        .collect();
    assert_eq!(sides, (3..=8).collect());
    assert!(specs.iter().any(|s| s.placement.y > 0.0), "a hovering model");
}

#[test]
fn every_check_passes_on_the_solution() {
    for s in STUDENTS {
        let spec = spec_of(s);
        let results = cg_a1::checks(&spec, &sol::implementation());
        let ids: Vec<&str> = results.iter().map(|c| c.id.as_str()).collect();
        assert_eq!(ids, IDS, "student {s}");
        assert!(failing(&results).is_empty(), "student {s} ({spec:?}): {results:#?}");
    }
}

#[test]
fn every_variant_of_many_students_is_solvable() {
    for n in 0..300u32 {
        let student = format!("{:08}", 31_000_000 + n * 37);
        let spec = spec_of(&student);
        let results = cg_a1::checks(&spec, &sol::implementation());
        assert!(failing(&results).is_empty(), "student {student} ({spec:?}): {results:#?}");
    }
}

#[test]
fn every_check_fails_on_the_pristine_stubs() {
    for s in STUDENTS {
        let results = cg_a1::checks(&spec_of(s), &cg_exercises::a1::implementation());
        assert_eq!(results.len(), IDS.len());
        for c in &results {
            match &c.outcome {
                Outcome::NotDone { message } => {
                    assert!(message.starts_with(&c.task), "{}: {message}", c.id);
                }
                other => panic!("{} on the stubs: {other:?}", c.id),
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Broken answers, each the solution with one realistic bug.

/// Normals of `faces` over `vertices` as a student computes them: (b − a) × (c − a), normalised
/// (an index out of range gives the zero vector, where a student's code would panic).
fn normals_of(vertices: &[Vec3], faces: &[[u32; 3]]) -> Vec<Vec3> {
    faces
        .iter()
        .map(|f| {
            let p = |i: u32| vertices.get(i as usize).copied();
            match (p(f[0]), p(f[1]), p(f[2])) {
                (Some(a), Some(b), Some(c)) => (b - a).cross(c - a).normalize_or_zero(),
                _ => Vec3::ZERO,
            }
        })
        .collect()
}

// a1.t3: normals.
fn n_flipped(s: &Spec) -> Vec<Vec3> {
    sol::face_normals(s).into_iter().map(|n| -n).collect()
}
fn n_swapped_operands(s: &Spec) -> Vec<Vec3> {
    // (Vc − Va) × (Vb − Va): the classic swap, the same as flipped.
    let v = sol::vertices(s);
    let f = sol::faces(s);
    f.iter()
        .map(|&[a, b, c]| {
            let (a, b, c) = (v[a as usize], v[b as usize], v[c as usize]);
            (c - a).cross(b - a).normalize()
        })
        .collect()
}
fn n_unnormalised(s: &Spec) -> Vec<Vec3> {
    let v = sol::vertices(s);
    sol::faces(s)
        .iter()
        .map(|&[a, b, c]| {
            let (a, b, c) = (v[a as usize], v[b as usize], v[c as usize]);
            (b - a).cross(c - a)
        })
        .collect()
}
fn n_one_nan(s: &Spec) -> Vec<Vec3> {
    // Face 1's normal a NaN, as normalising a zero vector by hand gives.
    let mut n = sol::face_normals(s);
    n[1] = Vec3::ZERO / Vec3::ZERO.length();
    n
}
fn n_b_minus_a_cross_c_minus_b(s: &Spec) -> Vec<Vec3> {
    // (b − a) × (c − b) = (b − a) × (c − a): the same vector, so this is *not* a mistake.
    let v = sol::vertices(s);
    sol::faces(s)
        .iter()
        .map(|&[a, b, c]| {
            let (a, b, c) = (v[a as usize], v[b as usize], v[c as usize]);
            (b - a).cross(c - b).normalize()
        })
        .collect()
}
fn n_positions_crossed(s: &Spec) -> Vec<Vec3> {
    let v = sol::vertices(s);
    sol::faces(s)
        .iter()
        .map(|&[a, b, _]| v[a as usize].cross(v[b as usize]).normalize_or(Vec3::Y))
        .collect()
}
fn n_copied(s: &Spec) -> Vec<Vec3> {
    // Face 2's normal copied from a neighbour of face 2 with a different normal.
    let mut n = sol::face_normals(s);
    let f = sol::faces(s);
    let neighbour = (0..f.len())
        .find(|&g| {
            g != 2
                && f[g].iter().filter(|i| f[2].contains(i)).count() == 2
                && (n[g] - n[2]).length() > 0.1
        })
        .unwrap();
    n[2] = n[neighbour];
    n
}
fn n_per_vertex(s: &Spec) -> Vec<Vec3> {
    // One "normal" per vertex, pointing away from the model's middle.
    let v = sol::vertices(s);
    let centre = v.iter().copied().sum::<Vec3>() / v.len() as f32;
    v.iter().map(|p| (*p - centre).normalize()).collect()
}
fn n_in_world(s: &Spec) -> Vec<Vec3> {
    let turn = Mat4::from_rotation_y(s.placement.angle_deg.to_radians());
    sol::face_normals(s).into_iter().map(|n| turn.transform_vector3(n)).collect()
}
fn n_rounded(s: &Spec) -> Vec<Vec3> {
    normals_of(&v_rounded(s), &sol::faces(s)).into_iter().map(round3).collect()
}
fn n_third_decimal_off(s: &Spec) -> Vec<Vec3> {
    let mut n = sol::face_normals(s);
    n[1].x += 0.0015;
    n
}

fn round3(v: Vec3) -> Vec3 {
    (v * 1000.0).round() / 1000.0
}

// a1.t2: faces (their normals follow from the faces, as in a student's code).
fn f_one_reversed(s: &Spec) -> Vec<[u32; 3]> {
    let mut f = sol::faces(s);
    f[2].swap(1, 2);
    f
}
fn n_one_reversed(s: &Spec) -> Vec<Vec3> {
    normals_of(&sol::vertices(s), &f_one_reversed(s))
}
fn f_all_reversed(s: &Spec) -> Vec<[u32; 3]> {
    sol::faces(s).into_iter().map(|[a, b, c]| [a, c, b]).collect()
}
fn n_all_reversed(s: &Spec) -> Vec<Vec3> {
    normals_of(&sol::vertices(s), &f_all_reversed(s))
}
fn v_duplicated(s: &Spec) -> Vec<Vec3> {
    let mut v = sol::vertices(s);
    let first = sol::faces(s)[0][0];
    v.push(v[first as usize]);
    v
}
fn v_last_missing(s: &Spec) -> Vec<Vec3> {
    let mut v = sol::vertices(s);
    v.pop();
    v
}
fn f_duplicated(s: &Spec) -> Vec<[u32; 3]> {
    // F0 uses the copy instead of sharing the vertex.
    let mut f = sol::faces(s);
    f[0][0] = sol::vertices(s).len() as u32;
    f
}
fn n_duplicated(s: &Spec) -> Vec<Vec3> {
    normals_of(&v_duplicated(s), &f_duplicated(s))
}
fn f_missing(s: &Spec) -> Vec<[u32; 3]> {
    let mut f = sol::faces(s);
    f.pop();
    f
}
fn n_missing(s: &Spec) -> Vec<Vec3> {
    normals_of(&sol::vertices(s), &f_missing(s))
}
fn f_from_one(s: &Spec) -> Vec<[u32; 3]> {
    sol::faces(s).into_iter().map(|f| f.map(|i| i + 1)).collect()
}
fn f_repeated_index(s: &Spec) -> Vec<[u32; 3]> {
    let mut f = sol::faces(s);
    f[3][1] = f[3][0];
    f
}
fn n_repeated_index(s: &Spec) -> Vec<Vec3> {
    normals_of(&sol::vertices(s), &f_repeated_index(s))
}
fn f_face_twice(s: &Spec) -> Vec<[u32; 3]> {
    let mut f = sol::faces(s);
    f.push(f[1]);
    f
}
fn n_face_twice(s: &Spec) -> Vec<Vec3> {
    normals_of(&sol::vertices(s), &f_face_twice(s))
}
/// The spec with the other ring direction.
fn other_ring(s: &Spec) -> Spec {
    let mut o = *s;
    o.numbering.ring = match s.numbering.ring {
        Turn::Ccw => Turn::Cw,
        Turn::Cw => Turn::Ccw,
    };
    o
}
/// The spec with the other part order.
fn other_order(s: &Spec) -> Spec {
    let mut o = *s;
    o.numbering.order = match s.numbering.order {
        Order::BottomUp => Order::TopDown,
        Order::TopDown => Order::BottomUp,
    };
    o
}
fn v_renumbered(s: &Spec) -> Vec<Vec3> {
    sol::vertices(&other_ring(s))
}
fn f_renumbered(s: &Spec) -> Vec<[u32; 3]> {
    sol::faces(&other_ring(s))
}
fn n_renumbered(s: &Spec) -> Vec<Vec3> {
    sol::face_normals(&other_ring(s))
}
fn f_for_other_numbering(s: &Spec) -> Vec<[u32; 3]> {
    // The faces were written for another numbering (apex first, say) and never updated.
    sol::faces(&other_order(s))
}
fn n_for_other_numbering(s: &Spec) -> Vec<Vec3> {
    normals_of(&sol::vertices(s), &f_for_other_numbering(s))
}
/// The spec with its radius (or width) doubled: the diameter taken for the radius.
fn doubled(s: &Spec) -> Spec {
    let mut o = *s;
    match &mut o.shape {
        Shape::Pyramid { radius, .. }
        | Shape::Prism { radius, .. }
        | Shape::Tower { radius, .. }
        | Shape::Bipyramid { radius, .. }
        | Shape::Octahedron { radius } => *radius *= 2.0,
        Shape::Frustum { bottom_radius, top_radius, .. } => {
            *bottom_radius *= 2.0;
            *top_radius *= 2.0;
        }
        Shape::House { width, .. } | Shape::Wedge { width, .. } => *width *= 2.0,
    }
    o
}
fn v_doubled(s: &Spec) -> Vec<Vec3> {
    sol::vertices(&doubled(s))
}
fn n_doubled(s: &Spec) -> Vec<Vec3> {
    sol::face_normals(&doubled(s))
}
fn v_centred(s: &Spec) -> Vec<Vec3> {
    let v = sol::vertices(s);
    let top = v.iter().map(|p| p.y).fold(0.0, f32::max);
    v.into_iter().map(|p| p - Vec3::new(0.0, top / 2.0, 0.0)).collect()
}
fn v_placed(s: &Spec) -> Vec<Vec3> {
    let m = cg_core::product::MatrixProduct::from(sol::model_transform(s)).matrix().unwrap();
    sol::vertices(s).into_iter().map(|p| m.transform_point3(p)).collect()
}
fn n_placed(s: &Spec) -> Vec<Vec3> {
    normals_of(&v_placed(s), &sol::faces(s))
}
fn v_rounded(s: &Spec) -> Vec<Vec3> {
    sol::vertices(s).into_iter().map(round3).collect()
}

// a1.t4: the placement.
fn t(s: &Spec) -> Vec3 {
    Vec3::new(s.placement.x, s.placement.y, s.placement.z)
}
fn m_radians(s: &Spec) -> MatrixProduct {
    MatrixProduct::identity()
        .then(Factor::translate(t(s)))
        .then(Factor::rotate_y_deg(s.placement.angle_deg.to_radians()))
}
fn m_degrees_into_cos(s: &Spec) -> MatrixProduct {
    // A hand-built matrix with cos(30.0): the degrees taken as radians.
    let a = s.placement.angle_deg;
    MatrixProduct::identity()
        .then(Factor::translate(t(s)))
        .then(Factor::named("Ry", Mat4::from_rotation_y(a)))
}
fn m_reversed_order(s: &Spec) -> MatrixProduct {
    MatrixProduct::identity()
        .then(Factor::rotate_y_deg(s.placement.angle_deg))
        .then(Factor::translate(t(s)))
}
fn m_negative_angle(s: &Spec) -> MatrixProduct {
    MatrixProduct::identity()
        .then(Factor::translate(t(s)))
        .then(Factor::rotate_y_deg(-s.placement.angle_deg))
}
fn m_no_rotation(s: &Spec) -> MatrixProduct {
    MatrixProduct::identity().then(Factor::translate(t(s)))
}
fn m_typed_matrix(s: &Spec) -> MatrixProduct {
    // The student's own matrix, typed with three decimals: accepted.
    let exact =
        Mat4::from_translation(t(s)) * Mat4::from_rotation_y(s.placement.angle_deg.to_radians());
    let typed =
        Mat4::from_cols_array(&exact.to_cols_array().map(|x| (x * 1000.0).round() / 1000.0));
    MatrixProduct::identity().then(Factor::named("M", typed))
}

/// One broken answer: what it is, the checks that must fail, the ones that may also fail, and
/// words the failure of a named check must use (English cause).
struct Broken {
    name: &'static str,
    imp: Impl,
    must: &'static [&'static str],
    may: &'static [&'static str],
    says: &'static [(&'static str, &'static str)],
}

type VerticesFn = fn(&Spec) -> Vec<Vec3>;
type FacesFn = fn(&Spec) -> Vec<[u32; 3]>;
type TransformFn = fn(&Spec) -> MatrixProduct;

/// The solution with some of its functions replaced.
fn solution_with(
    vertices: Option<VerticesFn>,
    faces: Option<FacesFn>,
    face_normals: Option<VerticesFn>,
    model_transform: Option<TransformFn>,
) -> Impl {
    let s = sol::implementation();
    Impl {
        vertices: vertices.unwrap_or(s.vertices),
        faces: faces.unwrap_or(s.faces),
        face_normals: face_normals.unwrap_or(s.face_normals),
        model_transform: model_transform.unwrap_or(s.model_transform),
    }
}

const TOPOLOGY: &[&str] = &[
    "a1.t2.degenerate",
    "a1.t2.closed",
    "a1.t2.manifold",
    "a1.t2.winding",
    "a1.t2.outward",
    "a1.t2.surface",
];

fn broken_answers() -> Vec<Broken> {
    let n = |f: fn(&Spec) -> Vec<Vec3>| solution_with(None, None, Some(f), None);
    let m = |f: fn(&Spec) -> MatrixProduct| solution_with(None, None, None, Some(f));
    vec![
        Broken {
            name: "normals with the sign flipped",
            imp: n(n_flipped),
            must: &["a1.t3.normals"],
            may: &[],
            says: &[("a1.t3.normals", "points the wrong way")],
        },
        Broken {
            name: "normals as (Vc − Va) × (Vb − Va)",
            imp: n(n_swapped_operands),
            must: &["a1.t3.normals"],
            may: &[],
            says: &[("a1.t3.normals", "operands are swapped")],
        },
        Broken {
            name: "normals not normalised",
            imp: n(n_unnormalised),
            must: &["a1.t3.unit", "a1.t3.normals"],
            may: &[],
            says: &[("a1.t3.unit", "not normalised"), ("a1.t3.normals", "not normalised")],
        },
        Broken {
            // Said as a NaN, not as "not normalised".
            name: "a normal of NaN",
            imp: n(n_one_nan),
            must: &["a1.t3.unit", "a1.t3.normals"],
            may: &[],
            says: &[
                ("a1.t3.unit", "F1's normal has a NaN"),
                ("a1.t3.normals", "F1's normal has a NaN"),
            ],
        },
        Broken {
            name: "normals from position vectors (Va × Vb)",
            imp: n(n_positions_crossed),
            must: &["a1.t3.normals"],
            may: &[],
            says: &[],
        },
        Broken {
            name: "one face's normal copied from a neighbour",
            imp: n(n_copied),
            must: &["a1.t3.normals"],
            may: &[],
            says: &[("a1.t3.normals", "copied from a neighbouring face")],
        },
        Broken {
            name: "one normal per vertex",
            imp: n(n_per_vertex),
            must: &["a1.t3.count"],
            may: &["a1.t3.normals"],
            says: &[("a1.t3.count", "one normal per vertex")],
        },
        Broken {
            name: "normals turned by the placement",
            imp: n(n_in_world),
            must: &["a1.t3.normals"],
            may: &[],
            says: &[("a1.t3.normals", "turned by the placement")],
        },
        Broken {
            name: "a normal's third decimal wrong",
            imp: n(n_third_decimal_off),
            must: &["a1.t3.normals"],
            may: &["a1.t3.unit"],
            says: &[],
        },
        Broken {
            name: "one face wound the wrong way",
            imp: solution_with(None, Some(f_one_reversed), Some(n_one_reversed), None),
            must: &["a1.t2.winding", "a1.t2.outward"],
            may: &[],
            says: &[("a1.t2.winding", "F2"), ("a1.t2.outward", "F2 is clockwise")],
        },
        Broken {
            name: "every face wound the wrong way (inward)",
            imp: solution_with(None, Some(f_all_reversed), Some(n_all_reversed), None),
            must: &["a1.t2.outward"],
            may: &[],
            says: &[("a1.t2.outward", "every normal points inward")],
        },
        Broken {
            name: "a duplicated vertex instead of a shared index",
            imp: solution_with(Some(v_duplicated), Some(f_duplicated), Some(n_duplicated), None),
            must: &["a1.t1.count", "a1.t1.positions", "a1.t2.closed"],
            may: &[],
            says: &[
                ("a1.t1.count", "defined twice"),
                ("a1.t1.positions", "not in the table, is at the same position"),
                ("a1.t2.closed", "duplicated vertex"),
            ],
        },
        Broken {
            name: "the last vertex left out",
            imp: solution_with(Some(v_last_missing), None, None, None),
            must: &["a1.t1.count", "a1.t1.positions", "a1.t2.indices"],
            // The faces name the missing vertex: the checks after a1.t2.indices wait for it.
            may: &[
                "a1.t2.degenerate",
                "a1.t2.closed",
                "a1.t2.manifold",
                "a1.t2.winding",
                "a1.t2.outward",
                "a1.t2.surface",
                "a1.t2.count",
                "a1.t3.normals",
            ],
            says: &[("a1.t1.positions", "nothing from V")],
        },
        Broken {
            name: "a missing face",
            imp: solution_with(None, Some(f_missing), Some(n_missing), None),
            must: &["a1.t2.closed", "a1.t2.count"],
            may: &[],
            says: &[("a1.t2.closed", "seems to be missing"), ("a1.t2.count", "missing")],
        },
        Broken {
            name: "face indices counted from 1",
            imp: solution_with(None, Some(f_from_one), None, None),
            must: &["a1.t2.indices", "a1.t3.normals"],
            may: TOPOLOGY,
            says: &[("a1.t2.indices", "count from 1")],
        },
        Broken {
            name: "a face with a repeated index",
            imp: solution_with(None, Some(f_repeated_index), Some(n_repeated_index), None),
            must: &["a1.t2.degenerate", "a1.t3.unit"],
            may: TOPOLOGY,
            says: &[("a1.t2.degenerate", "F3")],
        },
        Broken {
            name: "a face listed twice",
            imp: solution_with(None, Some(f_face_twice), Some(n_face_twice), None),
            must: &["a1.t2.manifold", "a1.t2.count"],
            may: &[],
            says: &[("a1.t2.manifold", "one face defined twice")],
        },
        Broken {
            name: "vertices numbered by another rule (faces follow)",
            imp: solution_with(Some(v_renumbered), Some(f_renumbered), Some(n_renumbered), None),
            must: &["a1.t1.positions"],
            may: &[],
            says: &[("a1.t1.positions", "numbered by another rule")],
        },
        Broken {
            name: "faces written for another numbering",
            imp: solution_with(
                None,
                Some(f_for_other_numbering),
                Some(n_for_other_numbering),
                None,
            ),
            must: &[],
            may: TOPOLOGY,
            says: &[],
        },
        Broken {
            name: "the diameter taken for the radius (a wrong dimension)",
            imp: solution_with(Some(v_doubled), None, Some(n_doubled), None),
            must: &["a1.t1.positions"],
            may: &[],
            says: &[("a1.t1.positions", "size differs")],
        },
        Broken {
            name: "the model centred on the origin",
            imp: solution_with(Some(v_centred), None, None, None),
            must: &["a1.t1.positions"],
            may: &[],
            says: &[("a1.t1.positions", "centred on the origin")],
        },
        Broken {
            name: "the placement built into the vertices",
            imp: solution_with(Some(v_placed), None, Some(n_placed), None),
            must: &["a1.t1.positions"],
            may: &[],
            says: &[("a1.t1.positions", "placed in the world")],
        },
        Broken {
            name: "radians for degrees in the placement",
            imp: m(m_radians),
            must: &["a1.t4.placement"],
            may: &[],
            says: &[("a1.t4.placement", "in radians where degrees are expected")],
        },
        Broken {
            name: "degrees into cos and sin",
            imp: m(m_degrees_into_cos),
            must: &["a1.t4.placement"],
            may: &[],
            says: &[("a1.t4.placement", "went into cos and sin as radians")],
        },
        Broken {
            name: "rotation and translation in the wrong order",
            imp: m(m_reversed_order),
            must: &["a1.t4.placement"],
            may: &[],
            says: &[("a1.t4.placement", "wrong order")],
        },
        Broken {
            name: "the angle's sign",
            imp: m(m_negative_angle),
            must: &["a1.t4.placement"],
            may: &[],
            says: &[("a1.t4.placement", "wrong way")],
        },
        Broken {
            name: "the rotation left out",
            imp: m(m_no_rotation),
            must: &["a1.t4.placement"],
            may: &[],
            says: &[("a1.t4.placement", "rotation is missing")],
        },
    ]
}

/// Answers that differ from the solution but are right: the checks must accept them.
fn accepted_answers() -> Vec<(&'static str, Impl)> {
    vec![
        (
            "normals as (b − a) × (c − b) (the same vector)",
            solution_with(None, None, Some(n_b_minus_a_cross_c_minus_b), None),
        ),
        (
            "vertices and normals with three decimals",
            solution_with(Some(v_rounded), None, Some(n_rounded), None),
        ),
        (
            "a hand-typed matrix with three decimals",
            solution_with(None, None, None, Some(m_typed_matrix)),
        ),
    ]
}

fn assert_explains(c: &CheckResult, context: &str) {
    match &c.outcome {
        Outcome::Fail(f) => {
            assert!(!f.expected.is_empty() && !f.actual.is_empty(), "{context}: {f:?}");
            let at = f.location.as_ref().map_or("", |l| l.en.as_str());
            assert!(!at.is_empty(), "{context}: no location: {f:?}");
            for text in [&f.cause, &f.hint] {
                assert!(!text.ja.is_empty() && !text.en.is_empty(), "{context}: {f:?}");
                assert!(
                    text.ja.chars().any(|ch| ('\u{3040}'..='\u{30ff}').contains(&ch)),
                    "{context}: the Japanese text has no kana: {}",
                    text.ja
                );
            }
        }
        other => panic!("{context}: expected a failure, got {other:?}"),
    }
}

#[test]
fn broken_answers_fail_the_checks_meant_to_catch_them() {
    let mut caught: BTreeSet<String> = BTreeSet::new();
    for b in broken_answers() {
        for s in STUDENTS {
            let spec = spec_of(s);
            let results = cg_a1::checks(&spec, &b.imp);
            let failed = failing(&results);
            let context = format!("{} / student {s} ({})", b.name, family(&spec));
            assert!(!failed.is_empty(), "{context}: nothing failed");
            for id in b.must {
                assert!(failed.contains(*id), "{context}: {id} passed; failing: {failed:?}");
            }
            for id in &failed {
                assert!(
                    b.must.contains(&id.as_str()) || b.may.contains(&id.as_str()),
                    "{context}: {id} failed too: {:#?}",
                    results.iter().find(|c| &c.id == id)
                );
            }
            for c in results.iter().filter(|c| !c.passed()) {
                assert_explains(c, &format!("{context}: {}", c.id));
            }
            for (id, words) in b.says {
                let c = results.iter().find(|c| c.id == *id).unwrap();
                let Outcome::Fail(f) = &c.outcome else { panic!("{context}: {c:?}") };
                let said = format!(
                    "{} {} {}",
                    f.cause.en,
                    f.actual,
                    f.location.as_ref().map_or("", |l| l.en.as_str())
                );
                assert!(said.contains(words), "{context}: {id} does not say {words:?}: {f:#?}");
            }
            caught.extend(failed);
        }
    }
    let all: BTreeSet<String> = IDS.iter().map(|s| (*s).to_owned()).collect();
    assert_eq!(caught, all, "every check fails for at least one broken answer");
}

#[test]
fn right_answers_written_differently_pass() {
    for (name, imp) in accepted_answers() {
        for s in STUDENTS {
            let results = cg_a1::checks(&spec_of(s), &imp);
            assert!(failing(&results).is_empty(), "{name} / student {s}: {results:#?}");
        }
    }
}

#[test]
fn failures_name_the_vertex_the_face_and_the_edge() {
    // A hexagonal pyramid, apex first, base clockwise.
    let spec = spec_of("12345678");
    assert!(matches!(spec.shape, Shape::Pyramid { sides: 6, .. }), "{spec:?}");
    let b = solution_with(Some(v_renumbered), Some(f_renumbered), Some(n_renumbered), None);
    let c = cg_a1::checks(&spec, &b);
    let Outcome::Fail(f) = &c[1].outcome else { panic!("{:?}", c[1]) };
    // Apex first either way; the base runs the other way round from V1: V2 and V6 swap places.
    assert_eq!(f.location.as_ref().map(|l| l.en.as_str()), Some("V2, V3, V5, V6"), "{f:#?}");
    assert!(f.cause.ja.contains("上から見て時計回り"), "{}", f.cause.ja);
    let missing = solution_with(None, Some(f_missing), Some(n_missing), None);
    let c = cg_a1::checks(&spec, &missing);
    let closed = c.iter().find(|c| c.id == "a1.t2.closed").unwrap();
    let Outcome::Fail(f) = &closed.outcome else { panic!("{closed:?}") };
    assert!(f.location.as_ref().unwrap().en.as_str().starts_with("edge V"), "{f:#?}");
    let last = *sol::faces(&spec).last().unwrap();
    let mut named = last;
    // The named face is the missing one, up to where the cycle starts.
    let words = &f.cause.en;
    assert!(
        (0..3).any(|r| {
            named = [last[r], last[(r + 1) % 3], last[(r + 2) % 3]];
            words.contains(&format!("{{ V{}, V{}, V{} }}", named[0], named[1], named[2]))
        }),
        "{words} does not name {last:?}"
    );
}

#[test]
fn the_text_has_the_tasks_and_the_numbers_in_both_languages() {
    for s in STUDENTS {
        let spec = spec_of(s);
        let (ja, en) = (spec.describe(Lang::Ja), spec.describe(Lang::En));
        for id in ["a1.t1", "a1.t2", "a1.t3", "a1.t4"] {
            assert!(ja.contains(id) && en.contains(id), "{s}: {id}");
        }
        for f in ["vertices(spec)", "faces(spec)", "face_normals(spec)", "model_transform(spec)"] {
            assert!(ja.contains(f) && en.contains(f), "{s}: {f}");
        }
        let v = spec.shape.vertex_count();
        assert!(en.contains(&format!("({v} vertices)")), "{s}: {en}");
        assert!(ja.contains(&format!("全部で {v} 個")), "{s}: {ja}");
        let f = spec.shape.face_count();
        assert!(en.contains(&format!("= {f} faces")) && ja.contains(&format!("= {f} 個")), "{s}");
        let last = format!("V{}", v - 1);
        assert!(en.contains(&last) && ja.contains(&last), "{s}: the numbering reaches {last}");
        let angle = cg_core::product::format_number(spec.placement.angle_deg);
        assert!(en.contains(&format!("{angle}°")) && ja.contains(&format!("{angle}°")), "{s}");
        assert!(ja.contains("三面図") && en.contains("three views"), "{s}");
        assert!(ja.contains("法線") && en.contains("normal"), "{s}");
    }
}

// ---------------------------------------------------------------------------------------------
// The view

#[test]
fn the_view_lights_each_face_with_the_students_own_normal() {
    for s in STUDENTS {
        let spec = spec_of(s);
        for imp in [sol::implementation(), solution_with(None, None, Some(n_flipped), None)] {
            let scene = cg_a1::view(&spec, &imp, 0.0).unwrap();
            let names: Vec<&str> = scene.objects.iter().map(|o| o.name.as_str()).collect();
            assert_eq!(names, ["ground", "model"]);
            let model = &scene.objects[1];
            assert_eq!(model.normals, NormalSource::Given);
            assert_eq!(model.transform, (imp.model_transform)(&spec).into());
            let (v, f, n) = ((imp.vertices)(&spec), (imp.faces)(&spec), (imp.face_normals)(&spec));
            assert_eq!(model.mesh.faces.len(), f.len());
            let corner_normals = model.mesh.normals.as_ref().unwrap();
            for (i, face) in f.iter().enumerate() {
                for k in 0..3 {
                    let corner = model.mesh.faces[i][k] as usize;
                    assert_eq!(model.mesh.positions[corner], v[face[k] as usize]);
                    assert_eq!(corner_normals[corner], n[i], "student {s}, F{i}");
                }
            }
            assert!(scene.cull_back_faces, "a face wound the wrong way shows as a hole");
        }
    }
}

#[test]
fn the_view_shows_what_is_done_and_explains_what_keeps_it_from_drawing() {
    let spec = spec_of(STUDENTS[0]);
    // Nothing written yet: "not done yet" for the caller to print.
    let stub = cg_exercises::a1::implementation();
    assert!(matches!(guarded(|| cg_a1::view(&spec, &stub, 0.0)), Err(Outcome::NotDone { .. })));
    // Vertices and faces written: the model is drawn with derived normals at the origin.
    let half = Impl { vertices: sol::vertices, faces: sol::faces, ..stub };
    let scene = guarded(|| cg_a1::view(&spec, &half, 0.0)).unwrap().unwrap();
    assert_eq!(scene.objects[1].normals, NormalSource::Face);
    assert_eq!(scene.objects[1].transform.matrix().unwrap(), Mat4::IDENTITY);
    // Problems the renderer cannot draw are explained in both languages.
    for imp in [
        solution_with(None, None, Some(n_per_vertex), None),
        solution_with(None, Some(f_from_one), None, None),
        solution_with(None, None, Some(|s| vec![Vec3::ZERO; sol::faces(s).len()]), None),
    ] {
        let why = cg_a1::view(&spec, &imp, 0.0).unwrap_err();
        assert!(!why.ja.is_empty() && !why.en.is_empty(), "{why:?}");
    }
}

// ---------------------------------------------------------------------------------------------
// One language at a time

/// The identifiers that are plain words and that the Japanese report and assignment text
/// really use, as code: the student's functions `vertices(spec)` and `faces`, and the OpenGL
/// program's `display()`. (Identifiers shaped like code — `face_normals`, `n.normalize`,
/// `glRotatef` — need no listing; see `common::english_words`.)
const CODE_WORDS: &[&str] = &["vertices", "faces", "spec", "display"];

#[test]
fn reports_read_in_one_language() {
    let mut problems = Vec::new();
    let answers = std::iter::once(("the stubs", cg_exercises::a1::implementation()))
        .chain(broken_answers().into_iter().map(|b| (b.name, b.imp)));
    for (name, imp) in answers {
        for s in STUDENTS {
            let report = cg_harness::check::Report {
                assignment: cg_a1::ID.into(),
                student: Some(s.into()),
                checks: cg_a1::checks(&spec_of(s), &imp),
            };
            problems.extend(common::report_problems(&format!("{name} / {s}"), &report, CODE_WORDS));
        }
    }
    for s in STUDENTS {
        let spec = spec_of(s);
        problems.extend(common::language_problems(
            &format!("describe / {s}"),
            &spec.describe(Lang::Ja),
            &spec.describe(Lang::En),
            CODE_WORDS,
        ));
    }
    common::assert_no_problems(&problems);
}
