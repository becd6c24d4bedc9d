//! The periods of assignment 3 (`a3.periods`): one row per object — its motion, its period in
//! seconds and the numbers of its motion (a swing's amplitude in degrees, a radius, a
//! pendulum's arm, a hop's span and height) — and a last row, the period after which the whole
//! animation repeats. They follow from the assignment alone (the student's variant), so the
//! table is filled and checked even while the student's functions are stubs.
//!
//! The table is written and read in the notation of the shading section's tables
//! ([`crate::shading`]): the tag `<!-- cg: a3.periods -->` (LaTeX `% cg: a3.periods`), rows found
//! by their label (`object 2` or `物体2`), each number checked with the tolerance of every other
//! number of the report; a period may carry its unit (`4 s`, `4秒`, `4\,\mathrm{s}`). Every row
//! must be there (a missing row is a mistake), and a number in a `—` cell, a value the motion
//! does not have, is a mistake too.
//!
//! ```text
//! <!-- cg: a3.periods -->
//! | object | motion | period (s) | amplitude (°) | radius, arm or span | height |
//! |---|---|---|---|---|---|
//! | object 1 | spin about Y (counter-clockwise) | 3.000 | — | — | — |
//! | object 2 | pendulum about X (arm length) | 4.500 | 45.000 | 1.500 | — |
//! ```

use cg_assign::Variants;
use cg_assign::cg_a3::{Motion, Spec, SpecExt as _, Turn, WorldAxis};
use cg_assign::cg_shading::report::{Cell, Row, Table, Value};
use cg_core::lang::Lang;
use cg_core::product::format_number;
use cg_harness::Text;

use crate::shading::{ParsedTable, check_complete, check_table, tagged_table};
use crate::template::Format;
use crate::verify::Checker;

/// The tag of the periods table.
pub const TABLE_ID: &str = "a3.periods";

fn axis(a: WorldAxis) -> &'static str {
    match a {
        WorldAxis::X => "X",
        WorldAxis::Y => "Y",
        WorldAxis::Z => "Z",
    }
}

fn turn(t: Turn) -> Text {
    match t {
        Turn::Ccw => Text::new("反時計回り", "counter-clockwise"),
        Turn::Cw => Text::new("時計回り", "clockwise"),
    }
}

/// The motion in a few words, naming what the number columns hold.
fn motion_text(motion: &Motion) -> Text {
    match *motion {
        Motion::Spin { axis: a, turn: t, .. } => Text::new(
            format!("自転（{} 軸まわり、{}）", axis(a), turn(t).ja),
            format!("spin about {} ({})", axis(a), turn(t).en),
        ),
        Motion::Swing { axis: a, arm, .. } if arm > 0.0 => Text::new(
            format!("振り子（{} 軸まわり、腕の長さ）", axis(a)),
            format!("pendulum about {} (arm length)", axis(a)),
        ),
        Motion::Swing { axis: a, .. } => Text::new(
            format!("往復回転（{} 軸まわり）", axis(a)),
            format!("back-and-forth about {}", axis(a)),
        ),
        Motion::Hop { along, .. } => Text::new(
            format!("放物往復移動（{} 方向、幅と高さ）", axis(along)),
            format!("hop along {} (span, height)", axis(along)),
        ),
        Motion::Orbit { turn: t, .. } => Text::new(
            format!("公転（半径、上から見て{}）", turn(t).ja),
            format!("orbit (radius; {} from above)", turn(t).en),
        ),
        Motion::Satellite { parent_index, turn: t, .. } => {
            let p = parent_index + 1;
            Text::new(
                format!("物体{p}のまわりを回る（半径、{}）", turn(t).ja),
                format!("round object {p} (radius; {})", turn(t).en),
            )
        }
    }
}

fn number(x: f32) -> Cell {
    Cell::Given(Value::Number(f64::from(x)))
}

/// The kit's periods table for `spec` (see the module).
#[must_use]
pub fn table(spec: &Spec) -> Table {
    let mut rows: Vec<Row> = spec
        .objects
        .iter()
        .enumerate()
        .map(|(i, o)| {
            let n = i + 1;
            let m = &o.motion;
            let (amplitude, distance, height) = match *m {
                Motion::Spin { .. } => (Cell::Empty, Cell::Empty, Cell::Empty),
                Motion::Swing { amplitude_deg, arm, .. } => {
                    let arm = if arm > 0.0 { number(arm) } else { Cell::Empty };
                    (number(amplitude_deg), arm, Cell::Empty)
                }
                Motion::Hop { span, height, .. } => (Cell::Empty, number(span), number(height)),
                Motion::Orbit { radius, .. } | Motion::Satellite { radius, .. } => {
                    (Cell::Empty, number(radius), Cell::Empty)
                }
            };
            Row {
                label: Text::new(format!("物体{n}"), format!("object {n}")),
                cells: vec![
                    Cell::Text(motion_text(m)),
                    number(m.period_s()),
                    amplitude,
                    distance,
                    height,
                ],
            }
        })
        .collect();
    rows.push(Row {
        label: Text::new("全体", "all"),
        cells: vec![
            Cell::Text(Text::new(
                "全体の繰り返し（周期の最小公倍数）",
                "the whole animation repeats (least common multiple)",
            )),
            Cell::Given(Value::Number(spec.common_period_s())),
            Cell::Empty,
            Cell::Empty,
            Cell::Empty,
        ],
    });
    Table {
        id: TABLE_ID,
        columns: vec![
            Text::new("物体", "object"),
            Text::new("運動", "motion"),
            Text::new("周期（秒）", "period (s)"),
            Text::new("振幅（°）", "amplitude (°)"),
            Text::new("半径・腕・幅", "radius, arm or span"),
            Text::new("高さ", "height"),
        ],
        rows,
    }
}

/// The ratio of the periods and their unit, in words (not checked: the table holds the numbers).
fn ratio_text(spec: &Spec) -> Text {
    let ratios: Vec<String> = spec.period_ratios().iter().map(u64::to_string).collect();
    let ratios = ratios.join(" : ");
    let names = |word: &str| {
        (1..=spec.objects.len()).map(|n| format!("{word}{n}")).collect::<Vec<_>>().join(" : ")
    };
    let unit = format_number(spec.unit_s);
    Text::new(
        format!("周期の比 {} = {ratios}（単位 {unit} 秒）。", names("物体")),
        format!("Ratio of the periods {} = {ratios} (unit {unit} s).", names("object ")),
    )
}

/// The placeholder `a3.periods`: the tagged table, then the ratio of the periods.
#[must_use]
pub fn values(spec: &Spec, lang: Lang, format: Format) -> String {
    let body = tagged_table(&table(spec), lang, format, &mut Vec::new());
    let ratio = ratio_text(spec);
    let ratio = match format {
        Format::Markdown => ratio.get(lang).to_owned(),
        Format::Latex => crate::shading::tex_label(ratio.get(lang)),
    };
    format!("{body}\n{ratio}\n")
}

/// Why the cell `k` of the kit's row `row` has no value: its motion has no such number.
fn no_value(kit: &Table, row: &Row, k: usize) -> Text {
    let motion = match row.cells.first() {
        Some(Cell::Text(m)) => m.clone(),
        _ => Text::default(),
    };
    let column = kit.columns.get(k + 1).cloned().unwrap_or_default();
    Text::new(
        format!(
            "{} の運動（{}）には「{}」の値はありません。この欄は「—」のままにします",
            row.label.ja, motion.ja, column.ja
        ),
        format!(
            "the motion of {} ({}) has no {}: leave this cell as “—”",
            row.label.en, motion.en, column.en
        ),
    )
}

/// Checks the written periods tables against the assignment's (`None`: the report was checked
/// without one, so a written table is a note); a report without the table is a note.
pub(crate) fn verify(c: &mut Checker, written: &[ParsedTable], assignment: Option<&Variants>) {
    let tables: Vec<&ParsedTable> = written.iter().filter(|t| t.id == TABLE_ID).collect();
    let Some(a) = assignment else {
        if !tables.is_empty() {
            c.note(
                "課題（学生番号）がわからないので、周期の表 a3.periods は確かめていません",
                "without the assignment (the student number), the periods table a3.periods was not checked",
            );
        }
        return;
    };
    if tables.is_empty() {
        c.note(
            "レポートにタグ付きの周期の表がありません: a3.periods",
            "no tagged periods table found in the report: a3.periods",
        );
        return;
    }
    let kit = table(&a.a3);
    for t in tables {
        check_table(c, t, &kit);
        check_complete(c, t, &kit, |row, k| no_value(&kit, row, k));
    }
}

#[cfg(test)]
mod tests;
