//! The report's data for `s` (`cg_shading::report`), for one fixed student (12345678, table 1):
//! every kit value against numbers worked out here from the lecture's formulas in f64 (not from
//! `cg_core`), the student's cells against a student written here from the same formulas, and
//! a stub, a panic and a stub's marker each one `Missing` of its function, never a crash.

use cg_core::Rgb;
use cg_core::glam::{DVec3, Vec3};
use cg_harness::{StudentNumber, TableVersion, VariantRng};
use cg_shading::report::{
    ATTENUATION, Cell, LIGHT_P, LIGHT_Q, NORMALS, REFRACTION, SPOT, ShadingData, TABLE_IDS, Table,
    Value, highlight_factor, report,
};
use cg_shading::{Impl, Pixel, Shading, Spec};
use cg_student::mesh::Mesh;

fn spec() -> Spec {
    let student: StudentNumber = "12345678".parse().unwrap();
    let spec = cg_shading::variant(&mut VariantRng::new(&student, TableVersion::V1, "s"));
    // What `cg assignment --student 12345678 --only s` prints: the numbers below are for these.
    assert_eq!(spec.material.color.rgb, [0.8, 0.2, 0.2]);
    assert_eq!((spec.material.ks, spec.material.shininess), (1.0, 100.0));
    assert_eq!(spec.light.position, [10.0, 10.0, 10.0]);
    assert_eq!((spec.light.color.rgb, spec.light.ambient), ([1.0, 1.0, 1.0], 0.2));
    let a = spec.attenuation;
    assert_eq!((a.kc, a.kl, a.kq), (1.0, 0.1, 0.01));
    assert_eq!((spec.spot.cutoff_deg, spec.spot.exponent), (30.0, 2.0));
    assert_eq!(spec.medium.eta, 1.77);
    spec
}

// --- a student written from the lecture's formulas ------------------------------------------

fn ambient(ia: Rgb, ka: Rgb) -> Rgb {
    ia * ka
}
fn diffuse(ii: Rgb, kd: Rgb, n: Vec3, l: Vec3) -> Rgb {
    ii * kd * n.dot(l).max(0.0)
}
fn specular(ii: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> Rgb {
    let nl = n.dot(l);
    let rv = (2.0 * nl * n - l).dot(v);
    if nl <= 0.0 || rv <= 0.0 { Rgb::ZERO } else { ii * ks * rv.min(1.0).powf(shininess) }
}
fn attenuation(kc: f32, kl: f32, kq: f32, d: f32) -> f32 {
    1.0 / (kc + kl * d + kq * d * d).max(1e-6)
}
fn spot_factor(l: Vec3, s: Vec3, cutoff_deg: f32, exponent: f32) -> f32 {
    let cos = -l.dot(s.normalize());
    if cutoff_deg > 90.0 {
        1.0
    } else if cos < cutoff_deg.to_radians().cos() {
        0.0
    } else {
        cos.max(0.0).powf(exponent)
    }
}
fn normals(mesh: &Mesh, area: bool) -> Vec<Vec3> {
    let mut sum = vec![Vec3::ZERO; mesh.positions.len()];
    for f in &mesh.faces {
        let [a, b, c] = f.map(|k| mesh.positions[k as usize]);
        let n = (b - a).cross(c - a);
        let n = if area { n } else { n.normalize_or_zero() };
        for &k in f {
            sum[k as usize] += n;
        }
    }
    sum.into_iter().map(Vec3::normalize_or_zero).collect()
}
fn vertex_normals(mesh: &Mesh) -> Vec<Vec3> {
    normals(mesh, false)
}
fn vertex_normals_area(mesh: &Mesh) -> Vec<Vec3> {
    normals(mesh, true)
}
fn shade_pixel(_: Shading, p: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    light(p.positions[0], p.face_normal)
}
fn reflect(i: Vec3, n: Vec3) -> Vec3 {
    i - 2.0 * i.dot(n) * n
}
fn refract(i: Vec3, n: Vec3, n1: f32, n2: f32) -> Option<Vec3> {
    let (n, eta) = if i.dot(n) > 0.0 { (-n, n2 / n1) } else { (n, n1 / n2) };
    let cos = -i.dot(n);
    let k = 1.0 - eta * eta * (1.0 - cos * cos);
    (k >= 0.0).then(|| (eta * i + (eta * cos - k.sqrt()) * n).normalize())
}

fn student() -> Impl {
    Impl {
        ambient,
        diffuse,
        specular,
        attenuation,
        spot_factor,
        vertex_normals,
        vertex_normals_area,
        shade_pixel,
        reflect,
        refract,
    }
}

// --- reading the tables ----------------------------------------------------------------------

fn row<'a>(t: &'a Table, label: &str) -> &'a [Cell] {
    &t.rows.iter().find(|r| r.label.en == label).unwrap_or_else(|| panic!("{label}")).cells
}

fn numbers(v: Value) -> Vec<f64> {
    match v {
        Value::Number(x) => vec![x],
        Value::Vector(c) | Value::Color(c) => c.to_vec(),
        Value::Nothing => Vec::new(),
    }
}

/// The kit's value of a cell and, when the student has one there, theirs: both `expected`.
fn assert_cell(t: &Table, label: &str, k: usize, expected: &[f64], tolerance: f64) {
    let cell = &row(t, label)[k];
    let mut values = vec![cell.kit().unwrap_or_else(|| panic!("{label}: no value"))];
    if let Cell::Yours { yours, .. } = cell {
        values.push(*yours.as_ref().unwrap_or_else(|m| panic!("{label}: {m:?}")));
    }
    for v in values {
        let got = numbers(v);
        assert_eq!(got.len(), expected.len(), "{} {label}: {v:?}", t.id);
        for (g, e) in got.iter().zip(expected) {
            assert!((g - e).abs() <= tolerance, "{} {label}: {got:?}, expected {expected:?}", t.id);
        }
    }
}

fn unit(v: DVec3) -> [f64; 3] {
    v.normalize().to_array()
}

/// The light model at `point` on the unit sphere, worked out in f64: the rows of a light table.
fn light_rows(point: DVec3) -> Vec<(&'static str, Vec<f64>)> {
    let (ka, ii, ia, ks, n) = (DVec3::new(0.8, 0.2, 0.2), DVec3::ONE, 0.2, 1.0, 100.0);
    let nn = point.normalize();
    let v = (DVec3::new(0.0, 1.0, 3.5) - nn).normalize();
    let l = (DVec3::splat(10.0) - nn).normalize();
    let nl = nn.dot(l);
    let r = 2.0 * nl * nn - l;
    let rv = r.dot(v);
    let amb = ia * ka;
    let dif = ii * ka * nl.max(0.0);
    let spe = if nl > 0.0 && rv > 0.0 { ii * ks * rv.powf(n) } else { DVec3::ZERO };
    vec![
        ("N", nn.to_array().to_vec()),
        ("V", v.to_array().to_vec()),
        ("L", l.to_array().to_vec()),
        ("R", r.to_array().to_vec()),
        ("N·L", vec![nl]),
        ("R·V", vec![rv]),
        ("ambient", amb.to_array().to_vec()),
        ("diffuse", dif.to_array().to_vec()),
        ("specular", spe.to_array().to_vec()),
        ("I", (amb + dif + spe).to_array().to_vec()),
    ]
}

fn derived() -> ShadingData {
    let (data, missing) = report(&spec(), &student());
    assert!(missing.is_empty(), "{missing:?}");
    data.unwrap()
}

#[test]
fn the_light_model_at_p_follows_the_formulas() {
    let d = derived();
    let t = &d.light_p;
    assert_eq!(t.id, LIGHT_P);
    assert_cell(t, "P", 1, &[0.0, 1.0, 0.0], 0.0);
    // By hand: L = (10, 9, 10)/√281, N·L = 9/√281 = 0.5369, R = (−10, 9, −10)/√281,
    // R·V = −10/√281 < 0 so no highlight at P; diffuse = 0.5369·(0.8, 0.2, 0.2).
    let s = 281f64.sqrt();
    assert_cell(t, "L", 1, &[10.0 / s, 9.0 / s, 10.0 / s], 1e-6);
    assert_cell(t, "R", 1, &[-10.0 / s, 9.0 / s, -10.0 / s], 1e-6);
    assert_cell(t, "R", 2, &[-10.0 / s, 9.0 / s, -10.0 / s], 1e-6);
    assert_cell(t, "N·L", 1, &[9.0 / s], 1e-6);
    assert_cell(t, "R·V", 1, &[-10.0 / s], 1e-6);
    assert_cell(t, "ambient", 2, &[0.16, 0.04, 0.04], 1e-6);
    assert_cell(t, "diffuse", 2, &[0.8 * 9.0 / s, 0.2 * 9.0 / s, 0.2 * 9.0 / s], 1e-6);
    assert_cell(t, "specular", 2, &[0.0, 0.0, 0.0], 0.0);
    for (label, expected) in light_rows(DVec3::Y) {
        assert_cell(t, label, 1, &expected, 1e-6);
    }
    assert_cell(t, "V", 1, &[0.0, 0.0, 1.0], 0.0);
}

#[test]
fn q_is_the_centre_of_the_highlight_and_its_table_follows_the_formulas() {
    let d = derived();
    let t = &d.light_q;
    assert_eq!(t.id, LIGHT_Q);
    let q = match row(t, "Q")[1] {
        Cell::Chosen(Value::Vector(q)) => DVec3::from_array(q),
        ref other => panic!("{other:?}"),
    };
    // Three decimals, on the sphere up to that rounding.
    for x in q.to_array() {
        assert!(((x * 1000.0).round() - x * 1000.0).abs() < 1e-3, "{q}");
    }
    assert!((q.length() - 1.0).abs() < 2e-3, "{q}");
    let rows = light_rows(q);
    let rv = rows.iter().find(|r| r.0 == "R·V").unwrap().1[0];
    assert!(rv > 0.9999, "R·V = {rv} at Q: the centre of the highlight");
    for (label, expected) in rows {
        assert_cell(t, label, 1, &expected, 1e-4);
        if matches!(row(t, label)[2], Cell::Yours { .. }) {
            assert_cell(t, label, 2, &expected, 1e-4);
        }
    }
    // The specular term is nearly the full Ii·ks there.
    assert!(highlight_factor(&d.setup, q.as_vec3()) > 0.99);
    assert_cell(t, "specular", 2, &[1.0, 1.0, 1.0], 0.02);
}

#[test]
fn attenuation_spot_normals_and_refraction_follow_the_formulas() {
    let d = derived();
    assert_eq!(d.tables().map(|t| t.id), TABLE_IDS);
    let t = &d.attenuation;
    assert_eq!(t.id, ATTENUATION);
    for (label, dist) in [("d = 1", 1.0), ("d = 5", 5.0), ("d = 10", 10.0), ("d = 20", 20.0)] {
        let a: f64 = 1.0 / (1.0 + 0.1 * dist + 0.01 * dist * dist);
        assert_cell(t, label, 0, &[a], 1e-6);
        assert_cell(t, label, 1, &[a], 1e-6);
    }
    let t = &d.spot;
    assert_eq!(t.id, SPOT);
    for (label, alpha) in [("α = 0°", 0.0), ("α = 15°", 15.0), ("α = 29°", 29.0), ("α = 31°", 31.0)]
    {
        let cos = f64::to_radians(alpha).cos();
        let factor = if alpha <= 30.0 { cos * cos } else { 0.0 };
        assert_cell(t, label, 0, &[cos], 1e-12);
        assert_cell(t, label, 1, &[factor], 1e-6);
        assert_cell(t, label, 2, &[factor], 1e-6);
    }
    // The corner (−1, −1, 1) of the 2 × 2 × 2 cube: two triangles of the front (+z), one of the
    // left side (−x), two of the bottom (−y), each of area 2; both averages (−1, −2, 2)/3.
    let t = &d.normals;
    assert_eq!(t.id, NORMALS);
    assert_eq!(t.rows.len(), 7, "{:?}", t.rows);
    for (label, n) in [
        ("+z 1", [0.0, 0.0, 1.0]),
        ("+z 2", [0.0, 0.0, 1.0]),
        ("−x 1", [-1.0, 0.0, 0.0]),
        ("−y 1", [0.0, -1.0, 0.0]),
        ("−y 2", [0.0, -1.0, 0.0]),
    ] {
        assert_cell(t, label, 1, &n, 1e-7);
        assert_cell(t, label, 2, &[2.0], 1e-12);
    }
    let corner = unit(DVec3::new(-1.0, -2.0, 2.0));
    for label in ["plain average", "area-weighted"] {
        assert_cell(t, label, 1, &corner, 1e-7);
        assert_cell(t, label, 3, &corner, 1e-6);
    }
    // Sapphire, η = 1.77: θc = asin(1/1.77) = 34.40°; from air at 30°, sin θ₂ = 0.5/1.77,
    // θ₂ = 16.41°, t = (sin θ₂, −cos θ₂, 0); from inside at 60°, 1.77·sin 60° = 1.533 > 1.
    let t = &d.refraction;
    assert_eq!(t.id, REFRACTION);
    let eta = f64::from(1.77f32);
    let sin2 = 0.5 / eta;
    let theta2 = sin2.asin().to_degrees();
    assert_cell(t, "θc", 1, &[(1.0 / eta).asin().to_degrees()], 1e-9);
    assert!((34.39..34.41).contains(&(1.0 / eta).asin().to_degrees()));
    assert_cell(t, "sin θ₂", 1, &[sin2], 1e-9);
    assert_cell(t, "θ₂", 1, &[theta2], 1e-4);
    assert_cell(t, "θ₂", 2, &[theta2], 1e-3);
    let dir = [sin2, -(1.0 - sin2 * sin2).sqrt(), 0.0];
    assert_cell(t, "t", 1, &dir, 1e-6);
    assert_cell(t, "t", 2, &dir, 1e-6);
    assert_cell(t, "η·sin θ₁", 1, &[eta * 3f64.sqrt() / 2.0], 1e-9);
    assert_eq!(row(t, "t (from inside)")[1], Cell::Hand(Value::Nothing));
    assert!(matches!(row(t, "t (from inside)")[2], Cell::Yours { yours: Ok(Value::Nothing), .. }));
}

#[allow(clippy::todo)]
fn ambient_todo(_: Rgb, _: Rgb) -> Rgb {
    todo!("s.t1: the ambient term")
}

fn attenuation_panics(_: f32, _: f32, _: f32, d: f32) -> f32 {
    assert!(d < 3.0, "d is too far");
    1.0
}

fn normals_marked(mesh: &Mesh) -> Vec<Vec3> {
    cg_student::not_started("s.t5");
    vec![Vec3::Y; mesh.positions.len()]
}

fn normals_short(_: &Mesh) -> Vec<Vec3> {
    vec![Vec3::Y]
}

#[test]
fn a_stub_a_panic_and_a_marker_are_each_one_missing_and_the_kit_values_stay() {
    let imp = Impl {
        ambient: ambient_todo,
        attenuation: attenuation_panics,
        vertex_normals: normals_marked,
        vertex_normals_area: normals_short,
        ..student()
    };
    let (data, missing) = report(&spec(), &imp);
    let data = data.unwrap();
    let found: Vec<(&str, &str)> =
        missing.iter().map(|m| (m.task.as_str(), m.why.en.as_str())).collect();
    assert_eq!(missing.len(), 4, "{found:#?}");
    assert!(found.iter().any(|(t, w)| *t == "s.t1" && w.starts_with("ambient() is not written")));
    assert!(found.iter().any(|(t, w)| *t == "s.t4" && w.contains("panicked: d is too far")));
    assert!(found.iter().any(|(t, w)| *t == "s.t5" && w.contains("not_started(\"s.t5\")")));
    assert!(found.iter().any(|(t, w)| *t == "s.t5" && w.contains("1 normals for 8 vertices")));
    // The kit's values are all there; the student's cells say why they are not.
    assert!(matches!(
        row(&data.light_p, "ambient")[2],
        Cell::Yours { kit: Value::Color(_), yours: Err(_) }
    ));
    assert!(matches!(row(&data.light_p, "I")[2], Cell::Yours { yours: Err(_), .. }));
    assert!(matches!(row(&data.attenuation, "d = 1")[1], Cell::Yours { yours: Ok(_), .. }));
    assert!(matches!(row(&data.attenuation, "d = 5")[1], Cell::Yours { yours: Err(_), .. }));
    assert!(cg_student::take_not_started().is_empty(), "the marker is not left behind");
}

#[test]
#[allow(clippy::todo)]
fn the_kits_own_stubs_leave_every_function_missing_without_a_crash() {
    let stubs = Impl {
        ambient: ambient_todo,
        diffuse: |_, _, _, _| todo!(),
        specular: |_, _, _, _, _, _| todo!(),
        attenuation: |_, _, _, _| todo!(),
        spot_factor: |_, _, _, _| todo!(),
        vertex_normals: normals_marked,
        vertex_normals_area: |_| todo!(),
        shade_pixel,
        reflect: |_, _| todo!(),
        refract: |_, _, _, _| todo!(),
    };
    let (data, missing) = report(&spec(), &stubs);
    assert!(data.is_ok());
    let tasks: Vec<&str> = missing.iter().map(|m| m.task.as_str()).collect();
    assert_eq!(tasks, ["s.t1", "s.t2", "s.t3", "s.t4", "s.t4", "s.t5", "s.t5", "s.t7", "s.t8"]);
}
