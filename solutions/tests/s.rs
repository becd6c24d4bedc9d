//! Assignment s (第11回 シェーディング): the instructor's proof that the checks work.
//!
//! - every check passes on the reference solutions for students covering every option of every
//!   variant table;
//! - every check fails on the pristine stubs;
//! - realistic broken answers fail exactly the checks they should, and every check is failed by
//!   at least one of them;
//! - failure messages say what was expected, what was found, where, why and what to try, in
//!   Japanese and English;
//! - the variant tables keep the lecture's point visible (a highlight that Gouraud loses) for
//!   every combination that matters;
//! - the view shows the student's shading on the course's stage.

// The assignment crates, through the kit's one list (cg-assign).
use cg_assign::cg_shading;

use std::collections::{BTreeMap, BTreeSet};
use std::sync::OnceLock;

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::lang::{Lang, t};
use cg_harness::check::Outcome;
use cg_harness::{CheckResult, StudentNumber, TableVersion, VariantRng};
use cg_shading::render::kit_image;
use cg_shading::{Impl, Pixel, Shading, Spec};
use cg_solutions::s as solution;
use cg_student::mesh::Mesh;

mod common;

/// Students whose variants together use every option of every table (see
/// `students_cover_every_option`).
const STUDENTS: [&str; 8] = [
    "24020993", "24020881", "24020664", "24014539", "24020692", "24020979", "24020944", "24020923",
];

fn spec_of(student: &str) -> Spec {
    let n: StudentNumber = student.parse().unwrap();
    cg_shading::variant(&mut VariantRng::new(&n, TableVersion::V1, cg_shading::ID))
}

fn failing(results: &[CheckResult]) -> BTreeSet<String> {
    results.iter().filter(|c| !c.passed()).map(|c| c.id.clone()).collect()
}

fn all_ids() -> BTreeSet<String> {
    cg_shading::checks(&spec_of(STUDENTS[0]), &solution::implementation())
        .into_iter()
        .map(|c| c.id)
        .collect()
}

/// The options a spec uses, one string per table.
fn options(s: &Spec) -> Vec<String> {
    vec![
        format!("colour {}", s.material.color.en),
        format!("ks {}", s.material.ks),
        format!("n {}", s.material.shininess),
        format!("light colour {}", s.light.color.en),
        format!("light at {:?}", s.light.position),
        format!("Ia {}", s.light.ambient),
        format!("attenuation {:?}", (s.attenuation.kc, s.attenuation.kl, s.attenuation.kq)),
        format!("cut-off {}", s.spot.cutoff_deg),
        format!("spot exponent {}", s.spot.exponent),
        format!("sphere {}×{}", s.sphere.slices, s.sphere.stacks),
        format!("medium {}", s.medium.en),
    ]
}

fn every_option() -> BTreeSet<String> {
    use cg_shading::spec::*;
    let mut all = BTreeSet::new();
    all.extend(COLORS.iter().map(|c| format!("colour {}", c.en)));
    all.extend(SPECULAR.iter().map(|k| format!("ks {k}")));
    all.extend(SHININESS.iter().map(|n| format!("n {n}")));
    all.extend(LIGHT_COLORS.iter().map(|c| format!("light colour {}", c.en)));
    all.extend(LIGHT_POSITIONS.iter().map(|p| format!("light at {p:?}")));
    all.extend(AMBIENT.iter().map(|a| format!("Ia {a}")));
    all.extend(ATTENUATIONS.iter().map(|a| format!("attenuation {:?}", (a.kc, a.kl, a.kq))));
    all.extend(SPOT_CUTOFFS.iter().map(|c| format!("cut-off {c}")));
    all.extend(SPOT_EXPONENTS.iter().map(|e| format!("spot exponent {e}")));
    all.extend(SPHERES.iter().map(|s| format!("sphere {}×{}", s.slices, s.stacks)));
    all.extend(MEDIA.iter().map(|m| format!("medium {}", m.en)));
    all
}

#[test]
fn students_cover_every_option() {
    let used: BTreeSet<String> = STUDENTS.iter().flat_map(|s| options(&spec_of(s))).collect();
    let missing: Vec<_> = every_option().difference(&used).cloned().collect();
    assert!(missing.is_empty(), "options no test student has: {missing:?}");
    // A few dozen consecutive students see every option too (the tables are not lopsided).
    let used: BTreeSet<String> =
        (0..60).flat_map(|k| options(&spec_of(&format!("{:08}", 20_250_000 + k)))).collect();
    let missing: Vec<_> = every_option().difference(&used).cloned().collect();
    assert!(missing.is_empty(), "options 60 consecutive students never get: {missing:?}");
}

#[test]
fn variants_are_deterministic_and_differ_between_students() {
    assert_eq!(spec_of("12345678"), spec_of("12345678"));
    let json = |s: &str| {
        let a = cg_assign::Variants::for_student(&s.parse().unwrap(), TableVersion::V1);
        assert_eq!(a.s, spec_of(s), "cg-assign draws the same variant");
        a.to_json()["s"].clone()
    };
    let distinct: BTreeSet<String> = STUDENTS.iter().map(|s| json(s).to_string()).collect();
    assert_eq!(distinct.len(), STUDENTS.len());
    let first = json(STUDENTS[0]);
    for key in ["material", "light", "attenuation", "spot", "sphere", "medium"] {
        assert!(first.get(key).is_some(), "{key} in {first}");
    }
}

#[test]
fn every_check_passes_on_the_solutions() {
    for student in STUDENTS {
        let spec = spec_of(student);
        let results = cg_shading::checks(&spec, &solution::implementation());
        let report = cg_harness::Report {
            assignment: "s".into(),
            student: Some(student.into()),
            checks: results.clone(),
        };
        assert!(report.all_passed(), "student {student}:\n{}", report.render(Lang::En));
        assert!(results.len() >= 20);
    }
}

#[test]
fn every_check_fails_on_the_stubs() {
    let spec = spec_of(STUDENTS[1]);
    let results = cg_shading::checks(&spec, &cg_exercises::s::implementation());
    for c in &results {
        assert!(!c.passed(), "{} passes on the stub", c.id);
    }
    // Checks calling a todo!() say "not done yet", and so do those of s.t5 and s.t6, whose
    // stubs run (the view needs normals and colours) with their markers,
    // `cg_student::not_started("s.t5");` and `("s.t6")`. (Without its marker, s.t6's magenta
    // placeholder fails with an explanation that names it: `cg-shading`'s own tests.)
    for c in &results {
        match &c.outcome {
            Outcome::NotDone { message } => assert!(message.starts_with(&c.task), "{c:?}"),
            other => panic!("{}: {other:?}", c.id),
        }
    }
    let average = results.iter().find(|c| c.id == "s.t5.average").expect("s.t5.average");
    let Outcome::NotDone { message } = &average.outcome else { panic!("{average:?}") };
    assert!(message.contains("cg_student::not_started(\"s.t5\");"), "{average:?}");
}

/// s.t5's stub without its marker (a student who deleted the line and kept the placeholder) is
/// judged: its checks fail, naming the placeholder; with the marker and a right answer, its
/// checks are still "not done yet" (the marker wins while it is there).
#[test]
fn the_s_t5_marker_wins_while_it_is_there() {
    let spec = spec_of(STUDENTS[1]);
    let unmarked = Impl {
        vertex_normals: |mesh| vec![Vec3::Y; mesh.positions.len()],
        vertex_normals_area: solution::vertex_normals_area,
        ..solution::implementation()
    };
    let vertex_normals_checks = |imp: &Impl| -> Vec<_> {
        cg_shading::checks(&spec, imp).into_iter().filter(|c| c.task == "s.t5").collect()
    };
    let judged = vertex_normals_checks(&unmarked);
    assert!(judged.iter().any(|c| !c.passed()), "{judged:?}");
    for c in judged.iter().filter(|c| !c.passed()) {
        let Outcome::Fail(f) = &c.outcome else { panic!("{c:?}") };
        assert!(f.cause.en.contains("placeholder"), "{c:?}");
    }
    let marked = Impl {
        vertex_normals: |mesh| {
            cg_student::not_started("s.t5");
            solution::vertex_normals(mesh)
        },
        ..solution::implementation()
    };
    for c in cg_shading::checks(&spec, &marked) {
        match c.id.as_str() {
            "s.t5.average" | "s.t5.degenerate" => {
                assert!(matches!(c.outcome, Outcome::NotDone { .. }), "{c:?}");
            }
            // Checks that never call vertex_normals are judged (and pass).
            _ => assert!(c.passed(), "{c:?}"),
        }
    }
}

/// s.t6's stub without its marker (the line deleted, the magenta placeholder kept) is judged:
/// its pixel checks fail, naming the placeholder.
#[test]
fn the_s_t6_placeholder_without_its_marker_is_named() {
    let spec = spec_of(STUDENTS[1]);
    let unmarked =
        Impl { shade_pixel: |_, _, _| Rgb::new(1.0, 0.0, 1.0), ..solution::implementation() };
    let judged: Vec<_> =
        cg_shading::checks(&spec, &unmarked).into_iter().filter(|c| c.task == "s.t6").collect();
    assert!(!judged.is_empty() && judged.iter().all(|c| !c.passed()), "{judged:?}");
    let named = judged.iter().filter(
        |c| matches!(&c.outcome, Outcome::Fail(f) if f.cause.en.contains("placeholder magenta")),
    );
    assert!(named.count() >= 3, "{judged:?}");
}

// ---------------------------------------------------------------------------------------------
// Broken answers of the kinds students hand in

fn specular_no_clamp(ii: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, e: f32) -> Rgb {
    if n.dot(l) <= 0.0 {
        return Rgb::ZERO;
    }
    ii * ks * solution::reflect(-l, n).dot(v).powf(e)
}

fn specular_max_then_powf(ii: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, e: f32) -> Rgb {
    // Clamped, but 0⁰ = 1 is left in: n = 0 lights the far side.
    if n.dot(l) <= 0.0 {
        return Rgb::ZERO;
    }
    ii * ks * solution::reflect(-l, n).dot(v).max(0.0).powf(e)
}

fn specular_reflect_l(ii: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, e: f32) -> Rgb {
    if n.dot(l) <= 0.0 {
        return Rgb::ZERO;
    }
    let rv = solution::reflect(l, n).dot(v);
    if rv <= 0.0 { Rgb::ZERO } else { ii * ks * rv.powf(e) }
}

fn specular_from_behind(ii: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, e: f32) -> Rgb {
    let rv = solution::reflect(-l, n).dot(v);
    if rv <= 0.0 { Rgb::ZERO } else { ii * ks * rv.powf(e) }
}

fn diffuse_unclamped(ii: Rgb, kd: Rgb, n: Vec3, l: Vec3) -> Rgb {
    ii * kd * n.dot(l)
}

fn ambient_without_ia(_ia: Rgb, ka: Rgb) -> Rgb {
    ka
}

fn attenuation_linear_d(kc: f32, kl: f32, kq: f32, d: f32) -> f32 {
    1.0 / (kc + kl * d + kq * d).max(1e-6)
}

fn attenuation_unclamped(kc: f32, kl: f32, kq: f32, d: f32) -> f32 {
    1.0 / (kc + kl * d + kq * d * d)
}

fn spot_degrees_as_radians(l: Vec3, s: Vec3, cutoff_deg: f32, exponent: f32) -> f32 {
    if cutoff_deg > 90.0 {
        return 1.0;
    }
    let cos_alpha = -l.dot(s);
    if cos_alpha < cutoff_deg.cos() {
        return 0.0;
    }
    cos_alpha.max(0.0).powf(exponent)
}

fn spot_wrong_sign(l: Vec3, s: Vec3, cutoff_deg: f32, exponent: f32) -> f32 {
    solution::spot_factor(-l, s, cutoff_deg, exponent)
}

fn normals_unnormalised(mesh: &Mesh) -> Vec<Vec3> {
    let mut sums = vec![Vec3::ZERO; mesh.positions.len()];
    for face in &mesh.faces {
        let [a, b, c] = face.map(|v| mesh.positions[v as usize]);
        if let Some(n) = cg_core::normals::face_normal(a, b, c) {
            for &v in face {
                sums[v as usize] += n;
            }
        }
    }
    sums.iter().map(|s| *s / 3.0).collect()
}

fn area_normals_unnormalised(mesh: &Mesh) -> Vec<Vec3> {
    let mut sums = vec![Vec3::ZERO; mesh.positions.len()];
    for face in &mesh.faces {
        let [a, b, c] = face.map(|v| mesh.positions[v as usize]);
        for &v in face {
            sums[v as usize] += (b - a).cross(c - a) * 0.5;
        }
    }
    sums
}

fn normals_nan_on_degenerate(mesh: &Mesh) -> Vec<Vec3> {
    let mut sums = vec![Vec3::ZERO; mesh.positions.len()];
    for face in &mesh.faces {
        let [a, b, c] = face.map(|v| mesh.positions[v as usize]);
        let n = (b - a).cross(c - a).normalize();
        for &v in face {
            sums[v as usize] += n;
        }
    }
    sums.iter().map(|s| s.normalize()).collect()
}

fn shade(pixel: &Pixel, mode: Shading, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    solution::shade_pixel(mode, pixel, light)
}

fn phong_unnormalised(mode: Shading, px: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    let [w0, w1, w2] = px.weights;
    match mode {
        Shading::Phong => light(
            w0 * px.positions[0] + w1 * px.positions[1] + w2 * px.positions[2],
            w0 * px.normals[0] + w1 * px.normals[1] + w2 * px.normals[2],
        ),
        _ => shade(px, mode, light),
    }
}

fn phong_without_fallback(mode: Shading, px: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    let [w0, w1, w2] = px.weights;
    match mode {
        Shading::Phong => light(
            w0 * px.positions[0] + w1 * px.positions[1] + w2 * px.positions[2],
            (w0 * px.normals[0] + w1 * px.normals[1] + w2 * px.normals[2]).normalize(),
        ),
        _ => shade(px, mode, light),
    }
}

fn gouraud_per_pixel(mode: Shading, px: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    match mode {
        Shading::Gouraud => shade(px, Shading::Phong, light),
        _ => shade(px, mode, light),
    }
}

fn phong_interpolates_colours(mode: Shading, px: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    match mode {
        Shading::Phong => shade(px, Shading::Gouraud, light),
        _ => shade(px, mode, light),
    }
}

fn flat_with_a_vertex_normal(mode: Shading, px: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    match mode {
        Shading::Flat => light(px.positions[0], px.normals[0]),
        _ => shade(px, mode, light),
    }
}

fn flat_at_the_last_corner(mode: Shading, px: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    // OpenGL's GL_FLAT habit: the colour of the provoking (last) vertex, with the face normal.
    match mode {
        Shading::Flat => light(px.positions[2], px.face_normal),
        _ => shade(px, mode, light),
    }
}

fn reflect_wrong_sign(i: Vec3, n: Vec3) -> Vec3 {
    i + 2.0 * i.dot(n) * n
}

fn refract_without_tir(i: Vec3, n: Vec3, n1: f32, n2: f32) -> Option<Vec3> {
    let (mut n, mut from, mut to) = (n, n1, n2);
    let mut cos_i = -i.dot(n);
    if cos_i < 0.0 {
        n = -n;
        cos_i = -cos_i;
        std::mem::swap(&mut from, &mut to);
    }
    let eta = from / to;
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    Some((eta * i + (eta * cos_i - k.sqrt()) * n).normalize())
}

fn refract_eta_inverted(i: Vec3, n: Vec3, n1: f32, n2: f32) -> Option<Vec3> {
    solution::refract(i, n, n2, n1)
}

fn refract_inside_not_flipped(i: Vec3, n: Vec3, n1: f32, n2: f32) -> Option<Vec3> {
    let cos_i = -i.dot(n);
    let eta = n1 / n2;
    let k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);
    if k < 0.0 {
        return None;
    }
    Some((eta * i + (eta * cos_i - k.sqrt()) * n).normalize())
}

/// Every broken answer: its name, the solution with one realistic bug, and exactly the checks
/// that must fail for it.
fn broken() -> Vec<(&'static str, Impl, Vec<&'static str>)> {
    let ok = solution::implementation();
    vec![
        ("ambient without Ia", Impl { ambient: ambient_without_ia, ..ok }, vec!["s.t1.ambient"]),
        (
            "N·L not clamped (negative diffuse)",
            Impl { diffuse: diffuse_unclamped, ..ok },
            vec!["s.t2.diffuse", "s.t2.facing_away"],
        ),
        (
            "no clamp before powf (NaN, or a highlight on the back)",
            Impl { specular: specular_no_clamp, ..ok },
            vec!["s.t3.specular", "s.t3.hard_cases"],
        ),
        (
            "max(R·V, 0).powf(n): 0⁰ = 1 at n = 0",
            Impl { specular: specular_max_then_powf, ..ok },
            vec!["s.t3.hard_cases"],
        ),
        (
            "R = reflect(L, N) instead of reflect(−L, N)",
            Impl { specular: specular_reflect_l, ..ok },
            vec!["s.t3.specular", "s.t3.mirror", "s.t3.hard_cases"],
        ),
        (
            "specular where N·L ≤ 0",
            Impl { specular: specular_from_behind, ..ok },
            vec!["s.t3.specular", "s.t3.hard_cases"],
        ),
        (
            "attenuation with d instead of d²",
            Impl { attenuation: attenuation_linear_d, ..ok },
            vec!["s.t4.attenuation"],
        ),
        (
            "attenuation without a floor (infinite at d = 0, kc = 0)",
            Impl { attenuation: attenuation_unclamped, ..ok },
            vec!["s.t4.attenuation"],
        ),
        (
            "spot cut-off in degrees compared with radians",
            Impl { spot_factor: spot_degrees_as_radians, ..ok },
            vec!["s.t4.spot"],
        ),
        ("spot cos α = +L·S", Impl { spot_factor: spot_wrong_sign, ..ok }, vec!["s.t4.spot"]),
        (
            "vertex normals not normalised",
            Impl {
                vertex_normals: normals_unnormalised,
                vertex_normals_area: area_normals_unnormalised,
                ..ok
            },
            vec!["s.t5.average", "s.t5.area_weighted", "s.t5.degenerate"],
        ),
        (
            "area-weighted normals as the plain average",
            Impl { vertex_normals_area: solution::vertex_normals, ..ok },
            vec!["s.t5.area_weighted", "s.t5.degenerate"],
        ),
        (
            "degenerate faces normalised (NaN)",
            Impl { vertex_normals: normals_nan_on_degenerate, ..ok },
            vec!["s.t5.degenerate"],
        ),
        (
            "flat shading with a vertex normal",
            Impl { shade_pixel: flat_with_a_vertex_normal, ..ok },
            vec!["s.t6.flat", "s.t6.image_flat"],
        ),
        (
            "flat shading lit at the last corner (GL_FLAT's provoking vertex)",
            Impl { shade_pixel: flat_at_the_last_corner, ..ok },
            vec!["s.t6.flat", "s.t6.image_flat"],
        ),
        (
            "Gouraud lit per pixel (that is Phong)",
            Impl { shade_pixel: gouraud_per_pixel, ..ok },
            vec!["s.t6.gouraud", "s.t6.image_gouraud", "s.t6.highlight"],
        ),
        (
            "Phong without renormalising the interpolated normal",
            Impl { shade_pixel: phong_unnormalised, ..ok },
            vec!["s.t6.phong", "s.t6.image_phong", "s.t6.highlight"],
        ),
        (
            "Phong interpolating colours (that is Gouraud)",
            Impl { shade_pixel: phong_interpolates_colours, ..ok },
            vec!["s.t6.phong", "s.t6.image_phong", "s.t6.highlight"],
        ),
        (
            "Phong without the face-normal fallback (NaN where normals cancel)",
            Impl { shade_pixel: phong_without_fallback, ..ok },
            vec!["s.t6.phong"],
        ),
        (
            "reflect with the wrong sign",
            Impl { reflect: reflect_wrong_sign, ..ok },
            vec!["s.t7.reflect"],
        ),
        (
            "refract without total internal reflection (NaN)",
            Impl { refract: refract_without_tir, ..ok },
            vec!["s.t8.refract", "s.t8.total_reflection", "s.t8.hard_cases"],
        ),
        (
            "refract with η inverted",
            Impl { refract: refract_eta_inverted, ..ok },
            vec!["s.t8.refract", "s.t8.total_reflection", "s.t8.hard_cases"],
        ),
        (
            "refract from inside without flipping n or swapping the indices",
            Impl { refract: refract_inside_not_flipped, ..ok },
            vec!["s.t8.refract", "s.t8.total_reflection", "s.t8.hard_cases"],
        ),
    ]
}

/// The checks of every broken answer, run once for all the tests below (on one student).
struct Run {
    name: &'static str,
    expected: BTreeSet<String>,
    results: Vec<CheckResult>,
}

fn broken_runs() -> &'static [Run] {
    static RUNS: OnceLock<Vec<Run>> = OnceLock::new();
    RUNS.get_or_init(|| {
        let spec = spec_of(STUDENTS[2]);
        broken()
            .into_iter()
            .map(|(name, imp, expected)| Run {
                name,
                expected: expected.iter().map(|s| (*s).to_owned()).collect(),
                results: cg_shading::checks(&spec, &imp),
            })
            .collect()
    })
}

#[test]
fn broken_answers_fail_exactly_their_checks() {
    let mut caught = BTreeSet::new();
    let mut problems = Vec::new();
    for run in broken_runs() {
        let got = failing(&run.results);
        if got != run.expected {
            problems
                .push(format!("{}: expected {:?} to fail, got {got:?}", run.name, run.expected));
        }
        for c in &run.results {
            if let Outcome::Panicked { message, .. } = &c.outcome {
                problems.push(format!("{}: {} panicked: {message}", run.name, c.id));
            }
        }
        caught.extend(got);
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    let never: Vec<_> = all_ids().difference(&caught).cloned().collect();
    assert!(never.is_empty(), "checks no broken answer fails: {never:?}");
}

#[test]
fn failures_explain_themselves_in_both_languages() {
    let mut seen = 0;
    for run in broken_runs() {
        for c in &run.results {
            let Outcome::Fail(f) = &c.outcome else { continue };
            seen += 1;
            let at = format!("{} / {}", run.name, c.id);
            assert!(!f.expected.is_empty() && !f.actual.is_empty(), "{at}: {f:?}");
            assert!(f.location.as_ref().is_some_and(|l| !l.is_empty()), "{at}: no location");
            for text in [&f.cause, &f.hint] {
                assert!(!text.ja.is_empty() && !text.en.is_empty(), "{at}: {text:?}");
                assert!(!text.ja.is_ascii(), "{at}: Japanese text {text:?}");
            }
            assert!(!c.title.ja.is_empty() && !c.title.en.is_empty());
        }
    }
    assert!(seen >= 30, "{seen}");
}

/// The usual cause each broken answer gets (what a student reads first), and where.
#[test]
fn causes_name_the_mistake() {
    let cases: [(&str, &str, &str, &str); 22] = [
        ("ambient without Ia", "s.t1.ambient", "Ia is missing", "Ia ="),
        ("N·L not clamped (negative diffuse)", "s.t2.facing_away", "negative", "N·L ="),
        (
            "no clamp before powf (NaN, or a highlight on the back)",
            "s.t3.hard_cases",
            "NaN",
            "R·V < 0",
        ),
        ("max(R·V, 0).powf(n): 0⁰ = 1 at n = 0", "s.t3.hard_cases", "0⁰ = 1", "n = 0"),
        ("R = reflect(L, N) instead of reflect(−L, N)", "s.t3.mirror", "reflect(L, N)", "V = R"),
        ("specular where N·L ≤ 0", "s.t3.hard_cases", "N·L ≤ 0", "N·L"),
        ("attenuation with d instead of d²", "s.t4.attenuation", "d²", "d ="),
        (
            "attenuation without a floor (infinite at d = 0, kc = 0)",
            "s.t4.attenuation",
            "infinite",
            "d = 0",
        ),
        ("spot cut-off in degrees compared with radians", "s.t4.spot", "degrees", "cutoff ="),
        ("spot cos α = +L·S", "s.t4.spot", "wrong sign", "α ="),
        ("vertex normals not normalised", "s.t5.average", "not normalised", "vertex V"),
        (
            "area-weighted normals as the plain average",
            "s.t5.area_weighted",
            "plain average",
            "mesh \"fan\"",
        ),
        ("degenerate faces normalised (NaN)", "s.t5.degenerate", "NaN", "zero-area"),
        ("flat shading with a vertex normal", "s.t6.flat", "a vertex normal is used", "face F"),
        (
            "flat shading lit at the last corner (GL_FLAT's provoking vertex)",
            "s.t6.flat",
            "lit at a corner",
            "face F",
        ),
        ("Gouraud lit per pixel (that is Phong)", "s.t6.gouraud", "Phong", "weights"),
        (
            "Gouraud lit per pixel (that is Phong)",
            "s.t6.highlight",
            "Gouraud image shows the highlight",
            "highlight",
        ),
        (
            "Phong without renormalising the interpolated normal",
            "s.t6.phong",
            "not renormalised",
            "weights",
        ),
        (
            "Phong interpolating colours (that is Gouraud)",
            "s.t6.highlight",
            "Phong image loses",
            "highlight",
        ),
        (
            "Phong without the face-normal fallback (NaN where normals cancel)",
            "s.t6.phong",
            "normals cancel",
            "cancel",
        ),
        ("reflect with the wrong sign", "s.t7.reflect", "sign", "i ="),
        ("refract with η inverted", "s.t8.refract", "inverted", "n1 ="),
    ];
    let more = [
        (
            "refract without total internal reflection (NaN)",
            "s.t8.total_reflection",
            "NaN",
            "leaving the medium",
        ),
        (
            "refract from inside without flipping n or swapping the indices",
            "s.t8.hard_cases",
            "not flipped",
            "from inside",
        ),
    ];
    for (name, id, needle, place) in cases.into_iter().chain(more) {
        let run = broken_runs().iter().find(|r| r.name == name).unwrap_or_else(|| panic!("{name}"));
        let c = run.results.iter().find(|c| c.id == id).unwrap();
        let Outcome::Fail(f) = &c.outcome else { panic!("{name} / {id}: {:?}", c.outcome) };
        assert!(
            f.cause.en.contains(needle),
            "{name} / {id}: {:?} should mention {needle:?}",
            f.cause.en
        );
        let at = f.location.as_ref().map_or("", |l| l.en.as_str());
        assert!(at.contains(place), "{name} / {id}: where {at:?} should mention {place:?}");
    }
}

/// The lecture's point must be visible for every variant: for every sphere, light position,
/// exponent and k_s of the tables (the object's and the light's colours only tint it), the
/// kit's Phong image has a highlight that its Gouraud image loses, of at least 60 pixels, and the
/// solution's images match the kit's exactly there.
#[test]
fn every_table_combination_has_a_highlight_that_gouraud_loses() {
    use cg_shading::spec::*;
    let base = spec_of(STUDENTS[0]);
    let mut smallest = (usize::MAX, String::new());
    for sphere in SPHERES {
        for position in LIGHT_POSITIONS {
            for (k, shininess) in SHININESS.into_iter().enumerate() {
                // Every exponent with every light position and sphere; k_s and the colours
                // cycle along (their effect is a tint and the clamp at 1).
                let ks = SPECULAR[k % SPECULAR.len()];
                let color = COLORS[(k + position.len()) % COLORS.len()];
                let mut spec = base;
                spec.sphere = sphere;
                spec.light.position = position;
                spec.material = MaterialSpec { color, ks, shininess };
                let scene = cg_shading::scenes::check_scene(&spec);
                let (g, p) = (
                    kit_image(&scene, Some(Shading::Gouraud)).unwrap(),
                    kit_image(&scene, Some(Shading::Phong)).unwrap(),
                );
                let region = g
                    .pixels
                    .iter()
                    .zip(&p.pixels)
                    .filter(|(a, b)| (**b - **a).max_element() > 0.1)
                    .count();
                if region < smallest.0 {
                    smallest = (region, format!("{spec:?}"));
                }
            }
        }
    }
    assert!(
        smallest.0 >= 60,
        "the highlight Gouraud loses has only {} pixels for {}",
        smallest.0,
        smallest.1
    );
}

#[test]
fn the_assignment_text_names_every_task_and_the_numbers() {
    for student in STUDENTS {
        let spec = spec_of(student);
        for lang in [Lang::Ja, Lang::En] {
            let text = spec.describe(lang);
            for task in 1..=8 {
                assert!(text.contains(&format!("s.t{task}")), "{lang}: s.t{task} in\n{text}");
            }
            let name = t(spec.material.color.ja, spec.material.color.en);
            let name = name.get(lang);
            let medium = t(spec.medium.ja, spec.medium.en);
            let medium = medium.get(lang);
            for needle in [
                name.to_owned(),
                medium.to_owned(),
                cg_core::product::format_number(spec.material.shininess),
                cg_core::product::format_number(spec.medium.eta),
                format!("{}°", cg_core::product::format_number(spec.spot.cutoff_deg)),
                format!("{}", spec.sphere.faces()),
            ] {
                assert!(text.contains(&needle), "{lang}: {needle:?} in\n{text}");
            }
        }
        assert!(spec.describe(Lang::Ja).contains("レポート"));
        assert!(spec.describe(Lang::En).contains("report"));
    }
}

/// The view draws the course's stage with three spheres; the solution's spheres are the kit's
/// own flat, Gouraud and Phong renders of that stage, the stub's are magenta.
#[test]
fn the_view_shows_the_students_shading_on_the_stage() {
    let spec = spec_of(STUDENTS[5]);
    let shown = |imp: &Impl| {
        let scene = cg_shading::view(&spec, imp, 0.0).unwrap();
        kit_image(&scene, None).unwrap()
    };
    let mine = shown(&solution::implementation());
    let stub = shown(&cg_exercises::s::implementation());
    let stage = cg_shading::scenes::stage_scene(&spec);
    assert_eq!((mine.width, mine.height), (stage.width, stage.height));
    let g = cg_shading::render::gbuffer(&stage, stage.width, stage.height).unwrap();
    let kit: Vec<_> = [Shading::Flat, Shading::Gouraud, Shading::Phong]
        .into_iter()
        .map(|m| kit_image(&stage, Some(m)).unwrap())
        .collect();
    let first_sphere = stage.objects.len() - 3;
    let mut counts: BTreeMap<usize, (usize, usize, usize)> = BTreeMap::new();
    for (i, texel) in g.texels.iter().enumerate() {
        let Some((face, _)) = texel else { continue };
        let object = g.faces[*face as usize].object;
        let entry = counts.entry(object).or_default();
        entry.0 += 1;
        let reference = if object >= first_sphere { &kit[object - first_sphere] } else { &kit[1] };
        let d = [mine.pixels[i], reference.pixels[i]]
            .map(|c| [c.x, c.y, c.z].map(cg_core::image::to_unorm8));
        if (0..3).all(|k| d[0][k].abs_diff(d[1][k]) <= 2) {
            entry.1 += 1;
        }
        if object >= first_sphere && stub.pixels[i] == Rgb::new(1.0, 0.0, 1.0) {
            entry.2 += 1;
        }
    }
    assert_eq!(counts.len(), 4, "the ground and three spheres are seen: {counts:?}");
    for (object, (seen, same, magenta)) in counts {
        assert!(seen > 2000, "object {object}: {seen} pixels");
        assert!(
            same as f64 >= 0.995 * seen as f64,
            "object {object}: {same} of {seen} as the kit draws it"
        );
        if object >= first_sphere {
            assert_eq!(magenta, seen, "the stub's sphere {object} is magenta");
        }
    }
}

/// The identifiers that are plain words and that the Japanese report and assignment text
/// really use, as code: the student's functions and their parameters (`ambient(ia, ka)`,
/// `diffuse`, `specular(…, shininess)`, `attenuation`, `spot_factor(…, exponent)`,
/// `vertex_normals(mesh)`, `shade_pixel(mode, pixel, light)`, `reflect`, `refract`), the
/// methods the hints name (`powf`, `normalize`), Rust's `None`, and the file to edit,
/// `exercises/src/s.rs`. (Identifiers shaped like code — `cutoff_deg`, `normalize_or_zero`,
/// `pixel.face_normal` — need no listing; see `common::english_words`.)
const CODE_WORDS: &[&str] = &[
    "ambient",
    "diffuse",
    "specular",
    "shininess",
    "attenuation",
    "exponent",
    "mesh",
    "mode",
    "pixel",
    "light",
    "reflect",
    "refract",
    "powf",
    "normalize",
    "None",
    "exercises",
];

#[test]
fn reports_read_in_one_language() {
    let mut problems = Vec::new();
    // The broken answers on their student, run once above; the stubs and the describe text on
    // every student; the broken answers again on two other students.
    for run in broken_runs() {
        let report = cg_harness::check::Report {
            assignment: cg_shading::ID.into(),
            student: Some(STUDENTS[2].into()),
            checks: run.results.clone(),
        };
        problems.extend(common::report_problems(run.name, &report, CODE_WORDS));
    }
    for (k, student) in STUDENTS.iter().enumerate() {
        let spec = spec_of(student);
        let mut answers = vec![("the stubs", cg_exercises::s::implementation())];
        if k == 0 || k == 5 {
            answers.extend(broken().into_iter().map(|(name, imp, _)| (name, imp)));
        }
        for (name, imp) in answers {
            let report = cg_harness::check::Report {
                assignment: cg_shading::ID.into(),
                student: Some((*student).into()),
                checks: cg_shading::checks(&spec, &imp),
            };
            problems.extend(common::report_problems(
                &format!("{name} / {student}"),
                &report,
                CODE_WORDS,
            ));
        }
        problems.extend(common::language_problems(
            &format!("describe / {student}"),
            &spec.describe(Lang::Ja),
            &spec.describe(Lang::En),
            CODE_WORDS,
        ));
    }
    common::assert_no_problems(&problems);
}
