//! The light tables ([`super::LIGHT_P`], [`super::LIGHT_Q`]): the light model at a point of the
//! unit sphere, by the kit's `cg_core::light` and `cg_core::optics`, and the student's terms.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light;
use cg_core::optics;
use cg_harness::Text;
use cg_harness::report::Missing;

use super::{Cell, LIGHT_P, LightSetup, Row, Student, Table, Value, point_text, same, t};

/// Everything about the light model at `point` (normalised onto the unit sphere).
struct LightAt {
    n: Vec3,
    v: Vec3,
    l: Vec3,
    r: Vec3,
    ambient: Rgb,
    diffuse: Rgb,
    specular: Rgb,
}

fn light_at(setup: &LightSetup, point: Vec3) -> LightAt {
    let n = point.normalize_or(Vec3::Y);
    let v = (setup.eye - n).normalize_or(Vec3::Z);
    let l = (setup.position - n).normalize_or(Vec3::Y);
    LightAt {
        n,
        v,
        l,
        r: optics::reflect(-l, n),
        ambient: light::ambient(setup.ia, setup.ka),
        diffuse: light::diffuse(setup.ii, setup.kd, n, l),
        specular: light::specular_phong(setup.ii, setup.ks, n, l, v, setup.shininess),
    }
}

/// The kit's point Q in the highlight: the point of the unit sphere whose normal halves the
/// directions to the light and to the eye (so R = V there, the brightest point of the highlight),
/// rounded to three decimals as the report writes it.
#[must_use]
pub fn highlight_point(setup: &LightSetup) -> Vec3 {
    let mut q = Vec3::Y;
    for _ in 0..100 {
        let l = (setup.position - q).normalize_or(Vec3::Y);
        let v = (setup.eye - q).normalize_or(Vec3::Z);
        q = (l + v).normalize_or(Vec3::Y);
    }
    let round = |x: f32| ((f64::from(x) * 1000.0).round() / 1000.0) as f32;
    Vec3::new(round(q.x), round(q.y), round(q.z))
}

/// The specular factor `max(R·V, 0)ⁿ` at `point`: how far into the highlight it is (1 at its
/// brightest).
#[must_use]
pub fn highlight_factor(setup: &LightSetup, point: Vec3) -> f64 {
    let a = light_at(setup, point);
    let rv = f64::from(a.r.dot(a.v)).clamp(0.0, 1.0);
    rv.powf(f64::from(setup.shininess))
}

fn light_columns() -> Vec<Text> {
    vec![
        t("量", "quantity"),
        t("式", "formula"),
        t("手計算 ✍", "by hand ✍"),
        t("あなたの関数", "your functions"),
    ]
}

/// The light table `id` ([`LIGHT_P`] or [`super::LIGHT_Q`]) at `point` on the unit sphere; the
/// student's cells from `imp` (all [`Missing`] without one: the kit's values alone, as the
/// checker derives them at a point the student chose).
pub(super) fn light_table(
    id: &'static str,
    setup: &LightSetup,
    point: Vec3,
    student: &mut Student,
) -> Table {
    let a = light_at(setup, point);
    let (nl, rv) = (a.n.dot(a.l), a.r.dot(a.v));
    let total = a.ambient + a.diffuse + a.specular;
    let (name, point_cell) = if id == LIGHT_P {
        ("P", Cell::Given(Value::vector(point)))
    } else {
        ("Q", Cell::Chosen(Value::vector(point)))
    };
    let eye = point_text(setup.eye);
    let light_pos = point_text(setup.position);
    let rgb = |c: Rgb| -> Result<Value, Text> { Ok(Value::color(c)) };
    let s = setup;
    let r_cell = student.cell(
        Value::vector(a.r),
        "s.t7",
        "reflect()",
        |imp| (imp.reflect)(-a.l, a.n),
        |r| Ok(Value::vector(r)),
    );
    let ambient = student.cell(
        Value::color(a.ambient),
        "s.t1",
        "ambient()",
        |imp| (imp.ambient)(s.ia, s.ka),
        rgb,
    );
    let diffuse = student.cell(
        Value::color(a.diffuse),
        "s.t2",
        "diffuse()",
        |imp| (imp.diffuse)(s.ii, s.kd, a.n, a.l),
        rgb,
    );
    let specular = student.cell(
        Value::color(a.specular),
        "s.t3",
        "specular()",
        |imp| (imp.specular)(s.ii, s.ks, a.n, a.l, a.v, s.shininess),
        rgb,
    );
    let sum = match (&ambient, &diffuse, &specular) {
        (
            Cell::Yours { yours: Ok(Value::Color(x)), .. },
            Cell::Yours { yours: Ok(Value::Color(y)), .. },
            Cell::Yours { yours: Ok(Value::Color(z)), .. },
        ) => Ok(Value::Color([0, 1, 2].map(|k| x[k] + y[k] + z[k]))),
        _ => Err([&ambient, &diffuse, &specular]
            .into_iter()
            .find_map(|c| match c {
                Cell::Yours { yours: Err(m), .. } => Some(m.clone()),
                _ => None,
            })
            .unwrap_or_else(|| Missing::new("s.t1", Text::new("", "")))),
    };
    let hand = |v: Value| Cell::Hand(v);
    let row = |label: Text, formula: Text, cells: [Cell; 2]| {
        let [a, b] = cells;
        Row { label, cells: vec![Cell::Text(formula), a, b] }
    };
    let rows = vec![
        row(
            same(name),
            t("球（半径 1）の上の点", "the point on the sphere (radius 1)"),
            [point_cell, Cell::Empty],
        ),
        row(
            same("N"),
            Text::new(format!("N = {name}/|{name}|"), format!("N = {name}/|{name}|")),
            [hand(Value::vector(a.n)), Cell::Empty],
        ),
        row(
            same("V"),
            Text::new(
                format!("V = (E − {name})/|E − {name}|、視点 E = {eye}"),
                format!("V = (E − {name})/|E − {name}|, the eye E = {eye}"),
            ),
            [hand(Value::vector(a.v)), Cell::Empty],
        ),
        row(
            same("L"),
            Text::new(
                format!("L = (S − {name})/|S − {name}|、光源 S = {light_pos}"),
                format!("L = (S − {name})/|S − {name}|, the light S = {light_pos}"),
            ),
            [hand(Value::vector(a.l)), Cell::Empty],
        ),
        row(
            same("R"),
            same("R = 2(N·L)N − L = reflect(−L, N)"),
            [hand(Value::vector(a.r)), r_cell],
        ),
        row(same("N·L"), same(""), [hand(Value::Number(f64::from(nl))), Cell::Empty]),
        row(same("R·V"), same(""), [hand(Value::Number(f64::from(rv))), Cell::Empty]),
        row(t("環境光", "ambient"), same("Ia·ka"), [hand(Value::color(a.ambient)), ambient]),
        row(
            t("拡散反射光", "diffuse"),
            same("Ii·kd·max(N·L, 0)"),
            [hand(Value::color(a.diffuse)), diffuse],
        ),
        row(
            t("鏡面反射光", "specular"),
            same("Ii·ks·max(R·V, 0)^n"),
            [hand(Value::color(a.specular)), specular],
        ),
        row(
            same("I"),
            t(
                "環境光 + 拡散反射光 + 鏡面反射光（0〜1 に切る前）",
                "ambient + diffuse + specular (before clamping to 0…1)",
            ),
            [hand(Value::color(total)), Cell::Yours { kit: Value::color(total), yours: sum }],
        ),
    ];
    Table { id, columns: light_columns(), rows }
}

/// The kit's light table `id` at `point` (the student's cells left empty): what the checker
/// compares a light table with when the student chose their own point Q.
#[must_use]
pub fn light_table_at(setup: &LightSetup, id: &'static str, point: Vec3) -> Table {
    light_table(id, setup, point, &mut Student { imp: None, notes: Vec::new() })
}
