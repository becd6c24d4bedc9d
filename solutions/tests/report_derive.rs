//! The report's derivation (`cg_report::derive`) on the reference solutions: for students
//! covering every family of every assignment, every part derives, and each derived number agrees
//! with an oracle that does not come from the derivation — a1's normals are unit and point out
//! of the solid, a2's view matrices are a2's own `expected_product` at the stated mouse states
//! (reached by a motion written here from the spec's words), a3's model matrices are
//! `cg_a3::expected_model` at the stated times, a4's rows are the bilinear blend of the corner
//! coordinates the spec's orientation table puts at each block corner. The symbolic products
//! name the variables and multiply out to the numeric ones.

// The assignment crates, through the kit's one list (cg-assign).
use cg_assign::{cg_a1, cg_a2, cg_a3, cg_a4};

use cg_a1::ShapeExt as _;
use cg_a2::report::{camera, camera_drags};
use cg_a2::{CameraState, Drag, DragAxis, Operation};
use cg_a3::SpecExt as _;
use cg_a3::report::{animation, animation_times};
use cg_a4::RegionExt as _;
use cg_a4::SpecExt as _;
use cg_assign::Impls;
use cg_assign::Variants;
use cg_core::glam::{DVec2, DVec3, Mat4, Vec2};
use cg_core::product::{Factor, MatrixProduct, Param};
use cg_harness::{StudentNumber, TableVersion};
use cg_report::derive::derive;
use cg_report::model::{NamedMatrix, TextureData};

/// The reference answers.
fn solutions() -> Impls {
    cg_assign::impls!(cg_solutions)
}

fn assignment(number: u32) -> Variants {
    let student: StudentNumber = format!("{number:08}").parse().unwrap();
    Variants::for_student(&student, TableVersion::V1)
}

/// Students that together cover every a1 family, a2 with and without a pan, a3's parent
/// orbiting and hopping with 3 and 4 objects, and every a4 repeat, turn and mirror: picked
/// greedily, in order, from a range of numbers (the variants are frozen, so the pick is too).
fn students() -> Vec<Variants> {
    let mut seen = std::collections::BTreeSet::new();
    let mut picked = Vec::new();
    for number in 20_260_000..20_260_400 {
        let a = assignment(number);
        let family = format!("{:?}", std::mem::discriminant(&a.a1.shape));
        let parent =
            a.a3.objects
                .iter()
                .find(|o| {
                    o.motion.parent().is_none()
                        && a.a3.objects.iter().any(|c| c.motion.parent().is_some())
                })
                .map(|o| format!("{:?}", std::mem::discriminant(&o.motion)));
        let features = [
            format!("a1 {family}"),
            format!("a2 pan {}", a.a2.pan.is_some()),
            format!("a3 {} objects", a.a3.objects.len()),
            format!("a3 parent {parent:?}"),
            format!("a4 repeat {}", a.a4.repeat),
            format!("a4 turn {} {}", a.a4.rotation_deg, a.a4.mirrored),
        ];
        let new = features.iter().filter(|f| !seen.contains(*f)).count();
        if new > 0 {
            seen.extend(features);
            picked.push(a);
        }
    }
    assert!(
        seen.iter().filter(|f| f.starts_with("a1 ")).count() == cg_a1::FAMILIES.len(),
        "{seen:?}"
    );
    assert!(seen.iter().filter(|f| f.starts_with("a4 turn")).count() == 8, "{seen:?}");
    picked
}

/// Entry by entry within `1e-4 · (1 + |expected|)`.
fn close(a: &Mat4, e: &Mat4) -> bool {
    a.to_cols_array()
        .iter()
        .zip(e.to_cols_array().iter())
        .all(|(a, e)| (a - e).abs() <= 1e-4 * (1.0 + e.abs()))
}

/// The symbolic product multiplies out to the numeric one, which prints no symbol.
fn symbolic_is_numeric(m: &NamedMatrix) {
    let (s, n) = (m.symbolic.matrix().unwrap(), m.numeric.matrix().unwrap());
    assert_eq!(s, n, "{}: {} vs {}", m.id, m.symbolic.symbolic(), m.numeric.numeric());
    assert_eq!(m.numeric.symbolic(), m.numeric.numeric(), "{}", m.id);
}

#[test]
fn everything_derives_for_the_reference_answers() {
    for a in students() {
        let (d, missing) = derive(&a, &solutions());
        assert!(missing.is_empty(), "{}: {missing:?}", a.student);
        assert_eq!(d.student.as_deref(), Some(a.student.to_string().as_str()));
        assert!(d.a1.is_some() && d.a2.is_some(), "{}", a.student);
        assert!(d.a3.is_some() && d.a4.is_some(), "{}", a.student);
    }
}

// --- a1 ------------------------------------------------------------------------------------

#[test]
fn a1_normals_are_unit_outward_and_the_students_own() {
    for a in students() {
        let p = cg_a1::report::polygon(&a.a1, &solutions().a1).unwrap();
        assert_eq!(p.vertices.len(), a.a1.shape.vertex_count());
        assert_eq!(p.faces.len(), a.a1.shape.face_count());
        let v: Vec<DVec3> = p.vertices.iter().map(|v| v.as_dvec3()).collect();
        // Every family is convex: a face's outward normal points away from the centre.
        let centre = v.iter().copied().sum::<DVec3>() / v.len() as f64;
        let student = p.student_normals.as_ref().unwrap();
        for (k, (f, n)) in p.faces.iter().zip(&p.derived_normals).enumerate() {
            let n = n.unwrap().as_dvec3();
            assert!((n.length() - 1.0).abs() < 1e-6, "{} F{k}: |n| = {}", a.student, n.length());
            let mid = (v[f[0] as usize] + v[f[1] as usize] + v[f[2] as usize]) / 3.0;
            assert!(n.dot(mid - centre) > 1e-3, "{} F{k} points inward: {n}", a.student);
            // The face's edges are perpendicular to it.
            for (x, y) in [(0, 1), (1, 2), (2, 0)] {
                let e = (v[f[y] as usize] - v[f[x] as usize]).normalize();
                assert!(n.dot(e).abs() < 1e-6, "{} F{k}", a.student);
            }
            assert!((student[k].as_dvec3() - n).length() < 1e-5, "{} F{k}", a.student);
        }
        let t = p.transform.unwrap().matrix().unwrap();
        let pl = a.a1.placement;
        let origin = t.transform_point3(cg_core::glam::Vec3::ZERO);
        assert!((origin - cg_core::glam::Vec3::new(pl.x, pl.y, pl.z)).length() < 1e-5);
    }
}

// --- a2 ------------------------------------------------------------------------------------

/// `motion()` as the spec's words say: the operation whose button and Shift the drag has adds
/// `per_px` times its `dx` or `dy`; yaw wraps into [0, 360), the others are clamped.
fn spec_motion(spec: &cg_a2::Spec, s: &mut CameraState, d: &Drag) {
    let change = |op: &Operation| {
        if d.button != op.gesture.button || d.shift != op.gesture.shift {
            return None;
        }
        Some(match op.axis {
            DragAxis::Horizontal => op.per_px * d.dx,
            DragAxis::Vertical => op.per_px * d.dy,
        })
    };
    if let Some(c) = change(&spec.yaw) {
        s.camera_yaw = (s.camera_yaw + c).rem_euclid(360.0);
    }
    if let Some(c) = change(&spec.pitch) {
        s.camera_pitch = (s.camera_pitch + c).clamp(spec.pitch_min, spec.pitch_max);
    }
    if let Some(c) = change(&spec.distance) {
        s.camera_distance = (s.camera_distance + c).clamp(spec.distance_min, spec.distance_max);
    }
    if let Some(pan) = &spec.pan {
        if let Some(c) = change(&pan.x) {
            s.target_x = (s.target_x + c).clamp(-pan.limit, pan.limit);
        }
        if let Some(c) = change(&pan.z) {
            s.target_z = (s.target_z + c).clamp(-pan.limit, pan.limit);
        }
    }
}

#[test]
fn a2_view_matrices_are_a2s_own_at_the_stated_states() {
    for a in students() {
        let spec = &a.a2;
        let c = camera(spec, &solutions().a2).unwrap();
        let plan = camera_drags(spec);
        assert_eq!(c.matrices.len(), plan.len(), "{}", a.student);
        let mut names = vec!["camera_yaw", "camera_pitch", "camera_distance"];
        if spec.pan.is_some() {
            names.extend(["target_x", "target_z"]);
        }
        let mut states = Vec::new();
        for (m, (id, drags)) in c.matrices.iter().zip(&plan) {
            assert_eq!(&m.id, id);
            let mut s = spec.start;
            for d in drags {
                spec_motion(spec, &mut s, d);
            }
            let expected = cg_a2::expected_product(spec, &s).matrix().unwrap();
            let found = m.numeric.matrix().unwrap();
            assert!(close(&found, &expected), "{} {id}: {} at {s:?}", a.student, m.numeric);
            symbolic_is_numeric(m);
            let text = m.symbolic.symbolic();
            for name in &names {
                assert!(text.contains(name), "{} {id}: {name} not in {text}", a.student);
            }
            let listed: Vec<&str> = m.variables.iter().map(|(n, _)| n.as_str()).collect();
            assert_eq!(listed, names, "{}", a.student);
            assert!(m.variables.iter().all(|(_, t)| !t.ja.is_empty() && !t.en.is_empty()));
            // The title states the state the drags reach.
            let distance = cg_core::product::format_number(s.camera_distance);
            assert!(m.title.en.contains(&format!("camera_distance = {distance}")), "{}", m.title);
            states.push(s);
        }
        // The drags change what they say.
        assert_ne!(states[1].camera_yaw, states[0].camera_yaw, "{}", a.student);
        assert_ne!(states[2].camera_distance, states[0].camera_distance, "{}", a.student);
        if spec.pan.is_some() {
            assert_ne!(states[3].target_x, 0.0, "{}", a.student);
        }
    }
}

// --- a3 ------------------------------------------------------------------------------------

/// Checks `matrices` (of object `i`) against a3's oracle at the stated times.
fn check_object(a: &Variants, i: usize, matrices: &[NamedMatrix], times: &[f64]) {
    let spec = &a.a3;
    assert_eq!(matrices.len(), times.len());
    for (m, &t) in matrices.iter().zip(times) {
        let frame = (t * 60.0).round() as u64;
        let expected = cg_a3::expected_model(spec, i, frame).as_mat4();
        let found = m.numeric.matrix().unwrap();
        assert!(close(&found, &expected), "{} {}: {} vs oracle", a.student, m.id, m.numeric);
        assert!(m.id.starts_with(&format!("a3.object{}.t", i + 1)), "{}", m.id);
        assert!(m.id.ends_with(&format!(".t{}", cg_core::product::format_number(t as f32))));
        symbolic_is_numeric(m);
        // Every variable listed appears in the product, each explained from the spec.
        let text = m.symbolic.symbolic();
        assert!(!m.variables.is_empty(), "{} {}: {text}", a.student, m.id);
        for (name, explanation) in &m.variables {
            assert!(text.contains(name.as_str()), "{} {}: {name} not in {text}", a.student, m.id);
            assert!(!explanation.en.contains("matches none"), "{} {name}: {explanation}", m.id);
            assert!(explanation.en.starts_with(name.as_str()), "{explanation}");
        }
    }
}

#[test]
fn a3_model_matrices_are_the_oracles_at_the_stated_times() {
    for a in students() {
        let d = animation(&a.a3, &solutions().a3).unwrap();
        let times = animation_times(&a.a3);
        assert_eq!(times.len(), 3, "{times:?}");
        assert_eq!(d.objects.len(), a.a3.objects.len());
        for (i, (name, matrices)) in d.objects.iter().enumerate() {
            assert_eq!(name, &a.a3.objects[i].name);
            check_object(&a, i, matrices, &times);
            // The reference names its own variables: theta_n for a turn.
            if !matches!(a.a3.objects[i].motion, cg_a3::Motion::Hop { .. }) {
                let text = matrices[1].symbolic.symbolic();
                assert!(text.contains(&format!("theta_{}", i + 1)), "{}: {text}", a.student);
            }
        }
        let ratios: Vec<String> = a.a3.period_ratios().iter().map(u64::to_string).collect();
        assert!(d.periods.en.contains(&ratios.join(" : ")), "{}", d.periods);
        assert!(d.periods.ja.contains(&ratios.join(" : ")), "{}", d.periods.ja);
    }
}

/// `p` with every parameter a plain number (as `gl.translate` and `gl.rotate` record it).
fn plain(f: &Factor) -> Factor {
    let num = |p: &Param| Param::num(p.value);
    match f {
        Factor::Translate(p) => Factor::Translate([num(&p[0]), num(&p[1]), num(&p[2])]),
        Factor::Rotate { axis, angle_deg } => {
            Factor::Rotate { axis: *axis, angle_deg: num(angle_deg) }
        }
        other => other.clone(),
    }
}

/// The reference's frame drawn with plain numbers only (no `Param::sym`): the matrices are the
/// same, the names must then come from the derivation's own matching.
fn plain_display(spec: &cg_a3::Spec, state: &cg_a3::State, gl: &mut cg_student::gl::Gl) {
    let mut reference = cg_student::gl::Gl::new();
    cg_solutions::a3::display(spec, state, &mut reference);
    for draw in cg_a3::replay(&reference).draws() {
        gl.load_identity();
        for f in &draw.model_view.factors {
            gl.mult(plain(f).into());
        }
        gl.draw(&draw.name, &(&draw.mesh).into());
    }
}

#[test]
fn a3_plain_numbers_are_named_after_the_specs_variables() {
    let imp = cg_a3::Impl { display: plain_display, ..solutions().a3 };
    for a in students() {
        let d = animation(&a.a3, &imp).unwrap();
        let times = animation_times(&a.a3);
        for (i, (_, matrices)) in d.objects.iter().enumerate() {
            check_object(&a, i, matrices, &times);
            // a3's own product names the same variables (theta_n, x_n / z_n, y_n).
            let own = cg_a3::model_product(&a.a3, i, 0).symbolic();
            let text = matrices[1].symbolic.symbolic();
            assert_eq!(text, own, "{} object {}", a.student, i + 1);
        }
    }
}

// --- a4 ------------------------------------------------------------------------------------

/// The coordinate the spec puts at `(p, q)` of a block (0…1 along i and j): the bilinear blend
/// of the coordinates of the region's corners the orientation table puts at the block's
/// corners, the region worked from its pixels.
fn expected_at(spec: &cg_a4::Spec, p: f64, q: f64) -> DVec2 {
    let size = f64::from(cg_a4::IMAGE_PIXELS);
    let [x0, y0, x1, y1] = spec.region.pixels().map(f64::from);
    let coord = |g: cg_a4::GroundCorner| {
        let (x, y) = spec.corner_at(g).xy();
        let s = if x == 0 { x0 / size } else { x1 / size };
        let t = if y == 0 { 1.0 - y1 / size } else { 1.0 - y0 / size };
        DVec2::new(s, t)
    };
    use cg_a4::GroundCorner::*;
    coord(FarLeft) * ((1.0 - p) * (1.0 - q))
        + coord(FarRight) * (p * (1.0 - q))
        + coord(NearRight) * (p * q)
        + coord(NearLeft) * ((1.0 - p) * q)
}

/// The distinct expected coordinates of vertex `(i, j)`, square by square in drawing order.
fn expected_row(spec: &cg_a4::Spec, i: u32, j: u32) -> Vec<DVec2> {
    let k = 10 / spec.repeat;
    let mut out: Vec<DVec2> = Vec::new();
    for sj in [j.wrapping_sub(1), j] {
        for si in [i.wrapping_sub(1), i] {
            if si >= 10 || sj >= 10 {
                continue;
            }
            let (a, b) = (si % k + (i - si), sj % k + (j - sj));
            let uv = expected_at(spec, f64::from(a) / f64::from(k), f64::from(b) / f64::from(k));
            if !out.iter().any(|o| (*o - uv).abs().max_element() < 1e-9) {
                out.push(uv);
            }
        }
    }
    out
}

fn check_texture(a: &Variants, t: &TextureData) {
    let spec = &a.a4;
    assert_eq!(t.rows.len(), 121);
    for row in &t.rows {
        let expected = expected_row(spec, row.i, row.j);
        assert_eq!(
            row.tex.len(),
            expected.len(),
            "{} ({}, {}): {:?}",
            a.student,
            row.i,
            row.j,
            row.tex
        );
        for (got, e) in row.tex.iter().zip(&expected) {
            assert!(
                (got.as_dvec2() - *e).abs().max_element() < 1e-5,
                "{} ({}, {})",
                a.student,
                row.i,
                row.j
            );
        }
    }
    let size = cg_a4::IMAGE_PIXELS as f32;
    let [x0, y0, x1, y1] = spec.region.pixels().map(|x| x as f32);
    assert_eq!(
        t.region,
        (Vec2::new(x0 / size, 1.0 - y1 / size), Vec2::new(x1 / size, 1.0 - y0 / size))
    );
    assert!(
        t.formula.en.contains(&spec.region.name()) && t.formula.ja.contains(&spec.region.name())
    );
}

#[test]
fn a4_rows_are_the_specs_coordinates() {
    let mut edges = 0;
    for a in students() {
        let t = cg_a4::report::texture(&a.a4, &solutions().a4).unwrap();
        check_texture(&a, &t);
        edges += t.rows.iter().filter(|r| r.tex.len() > 1).count();
    }
    assert!(
        edges > 0,
        "some student repeats the region: vertices on block edges have two or four coordinates"
    );
}

#[test]
fn a_camera_with_its_own_names_keeps_them() {
    // A camera that multiplies a factor it named itself (`Param::sym`) keeps that name; the
    // plain numbers after it are named by the derivation.
    fn camera_mult(gl: &mut cg_student::gl::Gl, s: &CameraState) {
        gl.mult(cg_a2::expected_product(&cg_a2_spec(), s).factors[0].clone().into());
        gl.rotate(-s.camera_pitch, 1.0, 0.0, 0.0);
        gl.rotate(-s.camera_yaw, 0.0, 1.0, 0.0);
    }
    fn cg_a2_spec() -> cg_a2::Spec {
        assignment(12_345_678).a2
    }
    let spec = cg_a2_spec();
    let imp = cg_a2::Impl { camera: camera_mult, ..solutions().a2 };
    let c = camera(&spec, &imp).unwrap();
    let m: &MatrixProduct = &c.matrices[0].symbolic;
    assert!(
        m.symbolic().starts_with("T(0, 0, -camera_distance) · Rx(-camera_pitch)"),
        "{}",
        m.symbolic()
    );
}
