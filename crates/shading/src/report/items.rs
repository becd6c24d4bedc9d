//! The attenuation, spot, cube-corner and refraction tables, by the kit's `cg_core::light`,
//! `cg_core::normals` and `cg_core::optics`, and the student's outputs for the same inputs.

use cg_core::glam::{DVec3, Vec3};
use cg_core::light::{self, Attenuation};
use cg_core::mesh::Mesh;
use cg_core::normals::{Weighting, face_area_vector, face_normal, vertex_normals};
use cg_core::optics::{self, Interface};
use cg_core::product::format_number;
use cg_core::shapes::cuboid;
use cg_harness::Text;
use cg_student::mesh::Mesh as StudentMesh;

use super::{
    ATTENUATION, CUBE_CORNER, Cell, DISTANCES, NORMALS, REFRACTION, Row, SPOT, Student,
    THETA_AIR_DEG, THETA_INSIDE_DEG, Table, Value, point_text, same, t,
};
use crate::{Impl, Spec};

pub(super) fn attenuation_table(spec: &Spec, student: &mut Student) -> Table {
    let a = spec.attenuation;
    let att = Attenuation { constant: a.kc, linear: a.kl, quadratic: a.kq };
    let rows = DISTANCES
        .iter()
        .map(|&d| {
            let kit = Value::Number(f64::from(light::attenuation(att, d)));
            let yours = student.cell(
                kit,
                "s.t4",
                "attenuation()",
                |imp| (imp.attenuation)(a.kc, a.kl, a.kq, d),
                |x| Ok(Value::Number(f64::from(x))),
            );
            Row {
                label: same(&format!("d = {}", format_number(d))),
                cells: vec![Cell::Hand(kit), yours],
            }
        })
        .collect();
    Table {
        id: ATTENUATION,
        columns: vec![
            t("距離", "distance"),
            t("1/(kc + kl·d + kq·d²) 手計算 ✍", "1/(kc + kl·d + kq·d²) by hand ✍"),
            t("あなたの attenuation()", "your attenuation()"),
        ],
        rows,
    }
}

/// The angles of the spot table, degrees: 0, cut-off/2, cut-off ∓ 1.
#[must_use]
pub fn spot_angles(cutoff_deg: f32) -> [f32; 4] {
    [0.0, cutoff_deg / 2.0, cutoff_deg - 1.0, cutoff_deg + 1.0]
}

/// The spot's axis (it hangs above the point and shines straight down) and the direction `L`
/// from a point that sees it at `alpha_deg` from the axis: `(−sin α, cos α, 0)`.
#[must_use]
pub fn spot_geometry(alpha_deg: f32) -> (Vec3, Vec3) {
    let a = alpha_deg.to_radians();
    (Vec3::NEG_Y, Vec3::new(-a.sin(), a.cos(), 0.0))
}

pub(super) fn spot_table(spec: &Spec, student: &mut Student) -> Table {
    let (cutoff, exponent) = (spec.spot.cutoff_deg, spec.spot.exponent);
    let rows = spot_angles(cutoff)
        .iter()
        .map(|&alpha| {
            let (axis, l) = spot_geometry(alpha);
            let kit = Value::Number(f64::from(light::spot_factor(l, axis, cutoff, exponent, None)));
            let cos = Value::Number(f64::from(alpha).to_radians().cos());
            let yours = student.cell(
                kit,
                "s.t4",
                "spot_factor()",
                |imp| (imp.spot_factor)(l, axis, cutoff, exponent),
                |x| Ok(Value::Number(f64::from(x))),
            );
            Row {
                label: same(&format!("α = {}°", format_number(alpha))),
                cells: vec![Cell::Hand(cos), Cell::Hand(kit), yours],
            }
        })
        .collect();
    Table {
        id: SPOT,
        columns: vec![
            t("軸からの角度", "angle from the axis"),
            t("cos α 手計算 ✍", "cos α by hand ✍"),
            t("係数 手計算 ✍", "factor by hand ✍"),
            t("あなたの spot_factor()", "your spot_factor()"),
        ],
        rows,
    }
}

/// `+z 1`, `−x 1`, …: the side of the cube a triangle lies on, numbered along that side.
fn side_label(n: Vec3, seen: &mut Vec<String>) -> String {
    let (axis, value) = [("x", n.x), ("y", n.y), ("z", n.z)]
        .into_iter()
        .max_by(|a, b| a.1.abs().total_cmp(&b.1.abs()))
        .unwrap_or(("y", 1.0));
    let side = format!("{}{axis}", if value < 0.0 { "−" } else { "+" });
    seen.push(side.clone());
    let k = seen.iter().filter(|s| **s == side).count();
    format!("{side} {k}")
}

/// The student's vertex normal at the cube's corner from `normals` (one per vertex).
fn corner_normal(normals: Vec<Vec3>, vertices: usize, function: &str) -> Result<Value, Text> {
    if normals.len() != vertices {
        return Err(Text::new(
            format!("{function} の法線が {} 個あります（頂点は {vertices} 個）", normals.len()),
            format!("{function} returns {} normals for {vertices} vertices", normals.len()),
        ));
    }
    Ok(Value::vector(normals[CUBE_CORNER as usize]))
}

pub(super) fn normals_table(student: &mut Student) -> Table {
    let cube: Mesh = cuboid(Vec3::splat(2.0)).unwrap_or_default();
    let count = cube.positions.len();
    let mut seen = Vec::new();
    let mut rows: Vec<Row> = cube
        .faces
        .iter()
        .filter(|f| f.contains(&CUBE_CORNER))
        .filter_map(|&[a, b, c]| {
            let p = [a, b, c].map(|k| cube.positions[k as usize]);
            let n = face_normal(p[0], p[1], p[2])?;
            let area = face_area_vector(p[0], p[1], p[2]).length() / 2.0;
            let corners = p.map(point_text).join(", ");
            Some(Row {
                label: same(&side_label(n, &mut seen)),
                cells: vec![
                    Cell::Text(same(&corners)),
                    Cell::Hand(Value::vector(n)),
                    Cell::Hand(Value::Number(area)),
                    Cell::Empty,
                ],
            })
        })
        .collect();
    let student_mesh = StudentMesh::from(&cube);
    for (label, weighting, function, task) in [
        (t("単純平均", "plain average"), Weighting::Uniform, "vertex_normals()", "s.t5"),
        (t("面積加重平均", "area-weighted"), Weighting::Area, "vertex_normals_area()", "s.t5"),
    ] {
        let kit = vertex_normals(&cube, weighting).normals;
        let kit = Value::vector(kit.get(CUBE_CORNER as usize).copied().unwrap_or(Vec3::ZERO));
        let yours = student.cell(
            kit,
            task,
            function,
            |imp| match weighting {
                Weighting::Area => (imp.vertex_normals_area)(&student_mesh),
                _ => (imp.vertex_normals)(&student_mesh),
            },
            |normals| corner_normal(normals, count, function),
        );
        let formula = match weighting {
            Weighting::Area => t("Σ (b−a)×(c−a) を正規化", "Σ (b−a)×(c−a), normalised"),
            _ => t("Σ 面の単位法線 を正規化", "Σ unit face normals, normalised"),
        };
        rows.push(Row {
            label,
            cells: vec![Cell::Text(formula), Cell::Hand(kit), Cell::Empty, yours],
        });
    }
    Table {
        id: NORMALS,
        columns: vec![
            t("三角形", "triangle"),
            t("頂点", "corners"),
            t("法線 手計算 ✍", "normal by hand ✍"),
            t("面積 手計算 ✍", "area by hand ✍"),
            t("あなたの関数", "your functions"),
        ],
        rows,
    }
}

/// The angle between `t` and `−n` in degrees (the angle of refraction).
fn angle_deg(t: Vec3, n: Vec3) -> f64 {
    let t = t.as_dvec3().normalize_or_zero();
    (-t.dot(n.as_dvec3())).clamp(-1.0, 1.0).acos().to_degrees()
}

/// The incident direction at `theta_deg` from the normal (0, 1, 0): from air above (travelling
/// down), or from inside (travelling up).
#[must_use]
pub fn incident(theta_deg: f64, from_inside: bool) -> Vec3 {
    let a = theta_deg.to_radians();
    let y = if from_inside { a.cos() } else { -a.cos() };
    DVec3::new(a.sin(), y, 0.0).as_vec3()
}

pub(super) fn refraction_table(spec: &Spec, student: &mut Student) -> Table {
    let eta = spec.medium.eta;
    let n = Vec3::Y;
    let kit_refract = |i: Vec3| {
        let iface = Interface::at(i, n, 1.0, eta)?;
        optics::refract(i, iface.n, iface.eta)
    };
    let (i_air, i_inside) = (incident(THETA_AIR_DEG, false), incident(THETA_INSIDE_DEG, true));
    let t_air = kit_refract(i_air);
    let t_inside = kit_refract(i_inside);
    let as_value = |t: Option<Vec3>| t.map_or(Value::Nothing, Value::vector);
    let eta64 = f64::from(eta);
    let critical = (1.0 / eta64).asin().to_degrees();
    let sin2 = THETA_AIR_DEG.to_radians().sin() / eta64;
    let theta2 = t_air.map_or(Value::Nothing, |t| Value::Number(angle_deg(t, n)));
    let call = |i: Vec3| move |imp: &Impl| (imp.refract)(i, n, 1.0, eta);
    let yours_theta2 = student.cell(theta2, "s.t8", "refract()", call(i_air), |t| {
        Ok(t.map_or(Value::Nothing, |t| Value::Number(angle_deg(t, n))))
    });
    let yours_t =
        student.cell(as_value(t_air), "s.t8", "refract()", call(i_air), |t| Ok(as_value(t)));
    let yours_inside =
        student.cell(as_value(t_inside), "s.t8", "refract()", call(i_inside), |t| Ok(as_value(t)));
    let e = format_number(eta);
    let i_text =
        |i: Vec3| format!("({}, {}, {})", tables_fixed(i.x), tables_fixed(i.y), tables_fixed(i.z));
    let rows = vec![
        Row {
            label: same("θc"),
            cells: vec![
                Cell::Text(Text::new(
                    format!("sin θc = 1/η = 1/{e}（度）"),
                    format!("sin θc = 1/η = 1/{e} (degrees)"),
                )),
                Cell::Hand(Value::Number(critical)),
                Cell::Empty,
            ],
        },
        Row {
            label: same("sin θ₂"),
            cells: vec![
                Cell::Text(Text::new(
                    format!("空気から θ₁ = 30°: sin θ₂ = sin 30°/{e}"),
                    format!("from air at θ₁ = 30°: sin θ₂ = sin 30°/{e}"),
                )),
                Cell::Hand(Value::Number(sin2)),
                Cell::Empty,
            ],
        },
        Row {
            label: same("θ₂"),
            cells: vec![
                Cell::Text(t("屈折角（度）", "the angle of refraction (degrees)")),
                Cell::Hand(theta2),
                yours_theta2,
            ],
        },
        Row {
            label: same("t"),
            cells: vec![
                Cell::Text(Text::new(
                    format!("refract(i, n, 1, {e})、i = {}、n = (0, 1, 0)", i_text(i_air)),
                    format!("refract(i, n, 1, {e}), i = {}, n = (0, 1, 0)", i_text(i_air)),
                )),
                Cell::Hand(as_value(t_air)),
                yours_t,
            ],
        },
        Row {
            label: same("η·sin θ₁"),
            cells: vec![
                Cell::Text(Text::new(
                    format!("内側から θ₁ = 60°: {e}·sin 60°（1 を超えると全反射）"),
                    format!(
                        "from inside at θ₁ = 60°: {e}·sin 60° (above 1: total internal reflection)"
                    ),
                )),
                Cell::Hand(Value::Number(eta64 * THETA_INSIDE_DEG.to_radians().sin())),
                Cell::Empty,
            ],
        },
        Row {
            label: t("t（内側から）", "t (from inside)"),
            cells: vec![
                Cell::Text(Text::new(
                    format!("refract(i, n, 1, {e})、i = {}（全反射なら None）", i_text(i_inside)),
                    format!(
                        "refract(i, n, 1, {e}), i = {} (None under total internal reflection)",
                        i_text(i_inside)
                    ),
                )),
                Cell::Hand(as_value(t_inside)),
                yours_inside,
            ],
        },
    ];
    Table {
        id: REFRACTION,
        columns: vec![
            t("量", "quantity"),
            t("式と入力", "formula and inputs"),
            t("手計算 ✍", "by hand ✍"),
            t("あなたの refract()", "your refract()"),
        ],
        rows,
    }
}

/// `x` with three decimals, `0.000` for a value that rounds to zero.
fn tables_fixed(x: f32) -> String {
    cg_core::notation::fixed(x, 3)
}
