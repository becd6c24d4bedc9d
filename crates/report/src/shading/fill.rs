//! The shading section's placeholders: each table after its tag, with a line of the student's
//! numbers before it and, after it, what of the student's functions could not be derived.

use cg_assign::cg_shading::report::{Cell, ShadingData, Table, Value};
use cg_core::lang::{Lang, t};
use cg_core::product::format_number as n;
use cg_harness::Text;

use super::tex_label;
use crate::tables::{md_cell, table};
use crate::template::{Format, not_yet};

/// `x` with exactly three decimals, a 5 rounded up as by hand, never `-0.000`.
pub(crate) fn fixed(x: f64) -> String {
    cg_core::notation::fixed64(x, 3)
}

/// A value as the tables write it: `0.577`, `(0.577, 0.577, 0.577)`, `None`.
pub(crate) fn value_text(v: &Value) -> String {
    match v {
        Value::Number(x) => fixed(*x),
        Value::Vector(c) | Value::Color(c) => {
            format!("({}, {}, {})", fixed(c[0]), fixed(c[1]), fixed(c[2]))
        }
        Value::Nothing => "None".to_owned(),
    }
}

fn value_cell(v: &Value, format: Format) -> String {
    match (format, v) {
        (Format::Latex, Value::Nothing) => "None".to_owned(),
        (Format::Latex, _) => format!("${}$", value_text(v)),
        (Format::Markdown, _) => value_text(v),
    }
}

fn text_cell(text: &str, format: Format) -> String {
    match format {
        Format::Markdown => md_cell(text),
        Format::Latex => tex_label(text),
    }
}

fn cell(c: &Cell, lang: Lang, format: Format) -> String {
    match c {
        Cell::Text(t) => text_cell(t.get(lang), format),
        Cell::Hand(_) => match format {
            Format::Markdown => "✍".to_owned(),
            Format::Latex => "\\yours{}".to_owned(),
        },
        Cell::Given(v) | Cell::Chosen(v) | Cell::Yours { yours: Ok(v), .. } => {
            value_cell(v, format)
        }
        Cell::Yours { yours: Err(_), .. } => {
            text_cell(t("（まだ）", "(not yet)").get(lang), format)
        }
        Cell::Empty => match format {
            Format::Markdown => "—".to_owned(),
            Format::Latex => "---".to_owned(),
        },
    }
}

/// The table after its tag, and a note naming what the student's functions did not give: each
/// reason once in the section (`shown`: the reasons noted under the tables before this one).
pub(crate) fn tagged_table(
    t: &Table,
    lang: Lang,
    format: Format,
    shown: &mut Vec<String>,
) -> String {
    let header: Vec<Text> = t
        .columns
        .iter()
        .map(|c| Text::new(text_cell(&c.ja, format), text_cell(&c.en, format)))
        .collect();
    let rows: Vec<Vec<String>> = t
        .rows
        .iter()
        .map(|r| {
            let mut row = vec![text_cell(r.label.get(lang), format)];
            row.extend(r.cells.iter().map(|c| cell(c, lang, format)));
            row
        })
        .collect();
    // A column of text (formulas, corners) wraps; the others keep their numbers on one line.
    let spec: String = (0..t.columns.len())
        .map(|c| {
            let text = c > 0
                && t.rows.iter().any(|r| {
                    matches!(r.cells.get(c - 1), Some(Cell::Text(x)) if x.en.chars().count() > 16)
                });
            match (text, t.columns.len()) {
                (true, ..=4) => "p{0.3\\linewidth}",
                (true, _) => "p{0.16\\linewidth}",
                (false, _) => "l",
            }
        })
        .collect();
    let tag = match format {
        Format::Markdown => format!("<!-- cg: {} -->\n", t.id),
        Format::Latex => format!("% cg: {}\n", t.id),
    };
    let body = table(format, &spec, &header, lang, &rows);
    let mut out = match format {
        Format::Markdown => tag + &body,
        // Set small and close, so that the numbers the student writes fit the page.
        Format::Latex => {
            let (size, sep) =
                if t.columns.len() > 4 { ("\\footnotesize", 3) } else { ("\\small", 3) };
            format!("{tag}{{{size}\\setlength{{\\tabcolsep}}{{{sep}pt}}\n{body}}}\n")
        }
    };
    let mut why: Vec<String> = Vec::new();
    for c in t.rows.iter().flat_map(|r| &r.cells) {
        if let Cell::Yours { yours: Err(m), .. } = c {
            let text = m.message(lang);
            if !why.contains(&text) {
                why.push(text);
            }
        }
    }
    if !why.is_empty() {
        let fresh: Vec<String> = why.into_iter().filter(|w| !shown.contains(w)).collect();
        let text = if fresh.is_empty() {
            Text::new("上の表と同じ理由", "as for the table above").get(lang).to_owned()
        } else {
            fresh.join("; ")
        };
        shown.extend(fresh);
        out.push('\n');
        out.push_str(&not_yet(&text, lang, format));
        out.push('\n');
    }
    out
}

/// A paragraph before a table.
fn paragraph(text: &Text, lang: Lang, format: Format) -> String {
    format!("{}\n\n", text_cell(text.get(lang), format))
}

fn rgb(c: cg_core::Rgb) -> String {
    format!("({}, {}, {})", n(c.x), n(c.y), n(c.z))
}

/// The placeholders of the shading section (`s.light`, `s.attenuation`, `s.spot`, `s.normals`,
/// `s.refraction`) and their values in `lang` and `format`.
#[must_use]
pub fn values(d: &ShadingData, lang: Lang, format: Format) -> Vec<(&'static str, String)> {
    let s = &d.setup;
    let grey = |c: cg_core::Rgb| n(c.x);
    let light = Text::new(
        format!(
            "あなたの光源と材質: Ia = {}（灰色）、ka = kd = {}、Ii = {}、ks = {}、n = {}、点光源 S = {}、視点 E = {}。色は (r, g, b)。Q はキットが選んだハイライトの中の点（R = V となる点）です。別の点を選ぶときは、Q の行に球の上の点（|Q| = 1）を書きます。report check はそこに書かれた Q から表を導きます。",
            grey(s.ia),
            rgb(s.ka),
            rgb(s.ii),
            grey(s.ks),
            n(s.shininess),
            rgb(s.position),
            rgb(s.eye)
        ),
        format!(
            "Your light and material: Ia = {} (grey), ka = kd = {}, Ii = {}, ks = {}, n = {}, the point light S = {}, the eye E = {}. Colours are (r, g, b). Q is a point of the highlight chosen by the kit (where R = V); to take a point of your own, write it in the row Q (on the sphere, |Q| = 1): report check derives the table from the Q written there.",
            grey(s.ia),
            rgb(s.ka),
            rgb(s.ii),
            grey(s.ks),
            n(s.shininess),
            rgb(s.position),
            rgb(s.eye)
        ),
    );
    let at_p = Text::new("P = (0, 1, 0) での値:", "At P = (0, 1, 0):");
    let at_q = Text::new("ハイライトの中の点 Q での値:", "At Q, a point in the highlight:");
    let [kc, kl, kq] = d.coefficients;
    let attenuation = Text::new(
        format!("kc = {}、kl = {}、kq = {}。", n(kc), n(kl), n(kq)),
        format!("kc = {}, kl = {}, kq = {}.", n(kc), n(kl), n(kq)),
    );
    let (cutoff, exponent) = d.spot_cone;
    let spot = Text::new(
        format!(
            "広がり (cut-off) {}°、指数 {}。スポットライトは点の真上から真下を照らし（S = (0, −1, 0)）、点から見た光源の方向は軸から α の角度: L = (−sin α, cos α, 0)、cos α = −L·S。",
            n(cutoff),
            n(exponent)
        ),
        format!(
            "Cut-off {}°, exponent {}. The spot hangs above the point and shines straight down (S = (0, −1, 0)); the point sees it at the angle α from the axis: L = (−sin α, cos α, 0), cos α = −L·S.",
            n(cutoff),
            n(exponent)
        ),
    );
    let normals = Text::new(
        "原点を中心とする 2 × 2 × 2 の立方体（チェックの立方体、cg_core::shapes::cuboid）の角 (−1, −1, 1) と、その角を共有する三角形（面の向き +z・−x・−y と番号）。",
        "The cube 2 × 2 × 2 about the origin (the checks' cube, cg_core::shapes::cuboid), its corner (−1, −1, 1) and the triangles that share it (named by the side they lie on, +z, −x, −y, and numbered).",
    );
    let (medium, eta) = &d.medium;
    let refraction = Text::new(
        format!(
            "媒質: {}（屈折率 η = {}）。境界は y = 0 の平面、外向きの法線 n = (0, 1, 0)、上が空気 (η = 1)。",
            medium.ja,
            n(*eta)
        ),
        format!(
            "Medium: {} (refractive index η = {}). The surface is the plane y = 0 with the outward normal n = (0, 1, 0), air (η = 1) above.",
            medium.en,
            n(*eta)
        ),
    );
    let mut shown = Vec::new();
    let mut t = |table: &Table| tagged_table(table, lang, format, &mut shown);
    let p = |text: &Text| paragraph(text, lang, format);
    vec![
        (
            "s.light",
            format!("{}{}{}\n{}{}", p(&light), p(&at_p), t(&d.light_p), p(&at_q), t(&d.light_q)),
        ),
        ("s.attenuation", format!("{}{}", p(&attenuation), t(&d.attenuation))),
        ("s.spot", format!("{}{}", p(&spot), t(&d.spot))),
        ("s.normals", format!("{}{}", p(&normals), t(&d.normals))),
        ("s.refraction", format!("{}{}", p(&refraction), t(&d.refraction))),
    ]
}

/// The placeholders of the shading section, for a report without its data.
pub const KEYS: [&str; 5] = ["s.light", "s.attenuation", "s.spot", "s.normals", "s.refraction"];
