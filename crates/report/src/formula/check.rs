//! Checking the texture formula: each of `s` and `t`, evaluated at every ground vertex `(i, j)`,
//! against the texture coordinates the kit derived there (the table's, from the student's
//! program). At a vertex with several coordinates (on the edge of a repeat block) each must be
//! one the formula gives (with `mod`, the block's far edge gives both ends). The first vertex
//! where it is wrong is named, with how many are; `s` and `t` swapped are named as such.

use cg_core::glam::Vec2;
use cg_harness::Text;

use super::{Equation, ParsedFormula, TAG};
use crate::model::{TexRow, TextureData};
use crate::verify::{Checker, Finding};

/// How far a formula's value may be from the derived coordinate: half a hundredth, so that
/// coefficients rounded to their written digits pass (`0.033·i` for `i/30`) and one grid step
/// off (at least 0.0125) does not.
pub const TOLERANCE: f64 = 0.005;

/// A number of the messages: at most four decimals, trailing zeros trimmed.
fn show(x: f64) -> String {
    if !x.is_finite() {
        return "NaN".to_owned();
    }
    let s = cg_core::notation::fixed64(x, 4);
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

fn component(v: Vec2, name: char) -> f64 {
    f64::from(if name == 's' { v.x } else { v.y })
}

/// The vertices where `eq` (read as the coordinate `as_name`) does not give every derived
/// coordinate, in the table's order (j-major).
fn wrong_at<'a>(
    expr: &super::Expr,
    rows: &'a [TexRow],
    as_name: char,
) -> Vec<(&'a TexRow, Vec<f64>)> {
    let mut out = Vec::new();
    for row in rows {
        let values = expr.eval(f64::from(row.i), f64::from(row.j));
        let fits = row.tex.iter().all(|&d| {
            let d = component(d, as_name);
            values.iter().any(|v| (v - d).abs() <= TOLERANCE + 1e-9)
        });
        if !fits {
            out.push((row, values));
        }
    }
    out
}

fn derived_text(row: &TexRow, name: char) -> String {
    let parts: Vec<String> =
        row.tex.iter().map(|&d| crate::tables::fixed(component(d, name) as f32)).collect();
    parts.join(" / ")
}

fn values_text(values: &[f64]) -> String {
    values.iter().map(|&v| show(v)).collect::<Vec<_>>().join(" / ")
}

fn wrong(c: &mut Checker, eq: &Equation, wrong: &[(&TexRow, Vec<f64>)], total: usize) {
    let Some((row, values)) = wrong.first() else { return };
    let (name, (i, j), n) = (eq.name, (row.i, row.j), wrong.len());
    let (v, d) = (values_text(values), derived_text(row, name));
    let text = &eq.text;
    c.out.findings.push(Finding {
        line: eq.line,
        item: format!("{TAG} {name} at ({i}, {j})"),
        written: format!("{name}({i}, {j}) = {v}"),
        derived: d.clone(),
        tolerance: Some(TOLERANCE),
        why: Text::new(
            format!(
                "式 `{text}` は格子点 (i, j) = ({i}, {j}) で {name} = {v} になりますが、そこのテクスチャ座標（表の値、あなたのプログラムから導出）は {name} = {d} です。{total} 個の格子点のうち {n} 個で違います（最初の 1 つを示しています）"
            ),
            format!(
                "the formula `{text}` gives {name} = {v} at the grid vertex (i, j) = ({i}, {j}), but the texture coordinates there (the table's, derived from your program) have {name} = {d}; it is wrong at {n} of the {total} grid vertices (the first is named)"
            ),
        ),
    });
}

fn swapped(c: &mut Checker, s: &Equation, t: &Equation, first: &TexRow) {
    let (i, j) = (first.i, first.j);
    let d: Vec<String> = first.tex.iter().map(|&d| crate::tables::tuple2(d)).collect();
    c.out.findings.push(Finding {
        line: s.line,
        item: format!("{TAG} s, t"),
        written: format!("{} / {}", s.text, t.text),
        derived: format!("(s, t)({i}, {j}) = {}", d.join(" / ")),
        tolerance: Some(TOLERANCE),
        why: Text::new(
            format!(
                "s と t が入れ替わっています: s の式 `{}` はすべての格子点で t の値に、t の式 `{}` は s の値になります",
                s.text, t.text
            ),
            format!(
                "s and t are swapped: the formula for s, `{}`, gives the t coordinate at every grid vertex, and the formula for t, `{}`, the s coordinate",
                s.text, t.text
            ),
        ),
    });
}

/// A note for an equation that is missing or does not read; the readable equation otherwise.
fn readable<'a>(c: &mut Checker, f: &'a ParsedFormula, name: char) -> Option<&'a Equation> {
    let Some(eq) = f.equation(name) else {
        c.note(
            format!(
                "{} 行目: タグ {TAG} のあとに `{name} = …` の式がないので確かめていません",
                f.line
            ),
            format!(
                "line {}: there is no `{name} = …` after the tag {TAG}, so it was not checked",
                f.line
            ),
        );
        return None;
    };
    match &eq.expr {
        Ok(_) => Some(eq),
        Err(why) => {
            c.note(
                format!(
                    "{} 行目: {name} の式を読めませんでした（{}）。`{name} = 0.25 + i/16` のように i と j の式で書きます: `{}`",
                    eq.line, why.ja, eq.text
                ),
                format!(
                    "could not read the formula at line {}: {name}: {}; write it in i and j, like `{name} = 0.25 + i/16`: `{}`",
                    eq.line, why.en, eq.text
                ),
            );
            None
        }
    }
}

/// Checks every tagged formula `written` against the texture coordinates of `tex` (see the
/// module); a report without the formula, and a formula without texture data, are notes.
pub(crate) fn verify(c: &mut Checker, written: &[ParsedFormula], tex: Option<&TextureData>) {
    let Some(tex) = tex else {
        if !written.is_empty() {
            c.note(
                format!("テクスチャのデータがないので、式 {TAG} は確かめていません"),
                format!("there is no texture data, so the formula {TAG} was not checked"),
            );
        }
        return;
    };
    if written.is_empty() {
        c.note(
            format!("レポートにタグ付きのテクスチャ座標の式がありません: {TAG}"),
            format!("no tagged texture formula found in the report: {TAG}"),
        );
        return;
    }
    let rows = &tex.rows;
    for f in written {
        let s = readable(c, f, 's');
        let t = readable(c, f, 't');
        let check = |eq: Option<&Equation>, as_name: char| {
            eq.and_then(|e| e.expr.as_ref().ok()).map(|x| wrong_at(x, rows, as_name))
        };
        let (s_wrong, t_wrong) = (check(s, 's'), check(t, 't'));
        c.out.checked += usize::from(s_wrong.is_some()) + usize::from(t_wrong.is_some());
        if let (Some(se), Some(te), Some(sw), Some(tw)) = (s, t, &s_wrong, &t_wrong)
            && !sw.is_empty()
            && !tw.is_empty()
            && check(s, 't').is_some_and(|w| w.is_empty())
            && check(t, 's').is_some_and(|w| w.is_empty())
        {
            swapped(c, se, te, sw[0].0);
            continue;
        }
        for (eq, w) in [(s, s_wrong), (t, t_wrong)] {
            if let (Some(eq), Some(w)) = (eq, w) {
                wrong(c, eq, &w, rows.len());
            }
        }
    }
}
