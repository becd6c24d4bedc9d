//! Checking the shading section's tables: every number written in a cell where the kit's row has
//! a value, against that value, with the tolerance of every other number of the report
//! ([`crate::verify::tolerance`]).

use cg_assign::cg_shading::report::{
    Cell, LIGHT_Q, Row, ShadingData, TABLE_IDS, Table, Value, highlight_factor, light_table_at,
};
use cg_core::glam::{DVec3, Vec3};
use cg_core::lang::Lang;
use cg_harness::Text;

use super::fill::value_text;
use super::{ParsedRow, ParsedTable, canonical, kit_row_for, rows_it_could_be, written_row_for};
use crate::model::Written;
use crate::parse::{clip, normalize, parse_number};
use crate::verify::{Checker, Finding};

/// What a cell holds, as far as the checker is concerned.
#[derive(Clone, Debug, PartialEq)]
enum Written3 {
    /// No digits: not a value (`✍`, `—`, `None`, words).
    Skip,
    /// Digits that are not a plain number or a tuple of them.
    Bad,
    /// A value that is no finite number: `NaN`, `inf`, `∞` (alone or in a tuple).
    NotFinite,
    /// The numbers written: one, or the entries of a tuple.
    Numbers(Vec<Written>),
}

/// `text` without a trailing unit of an angle or a time: `45°`, `45度`, `4 s`, `4秒`, `4 sec`,
/// `4\,\mathrm{s}` (the thin space is gone already), `4~\text{s}`.
fn without_unit(text: &str) -> &str {
    let s = text.trim();
    for latex in ["\\mathrm{s}", "\\text{s}", "\\textrm{s}", "\\text{秒}", "\\mathrm{sec}"] {
        if let Some(head) = s.strip_suffix(latex) {
            return head.trim_end_matches([' ', '~']).trim();
        }
    }
    for unit in ["°", "度", "秒", "sec", "s"] {
        if let Some(head) = s.strip_suffix(unit) {
            return head.trim_end_matches([' ', '~']).trim();
        }
    }
    s
}

/// A cell's value: the text after the last `=`, `≈` or `≒` (a working that ends in its value),
/// without `$`, `\(`, `\)`, backticks and a trailing unit ([`without_unit`]); one plain number,
/// or numbers in `( )`, `{ }` or `[ ]`. Full-width digits and punctuation read as ASCII, as in
/// every other row of the report ([`normalize`]).
fn read_cell(text: &str) -> Written3 {
    let text = normalize(text);
    // `NaN`, `inf` and `∞` have no digits, but they are written values, and wrong ones.
    if !text.chars().any(|c| c.is_ascii_digit()) && !not_finite(&text) {
        return Written3::Skip;
    }
    let mut s = text.replace("\\approx", "≈").replace("^\\circ", "°").replace("\\circ", "°");
    for x in ["\\(", "\\)", "\\,", "\\;", "\\!", "\\left", "\\right"] {
        s = s.replace(x, "");
    }
    let s: String = s.chars().filter(|c| !matches!(c, '$' | '`' | '*')).collect();
    let last = s.rsplit(['=', '≈', '≒']).next().unwrap_or("").trim();
    let last = without_unit(last);
    let inner = [('(', ')'), ('{', '}'), ('[', ']')]
        .iter()
        .find_map(|&(open, close)| last.strip_prefix(open)?.strip_suffix(close));
    let parts: Vec<&str> = match inner {
        Some(inner) => inner.split(',').map(str::trim).collect(),
        None => vec![last],
    };
    if parts.iter().any(|p| not_finite(p)) {
        return Written3::NotFinite;
    }
    match parts.iter().map(|p| parse_number(p)).collect::<Option<Vec<Written>>>() {
        Some(numbers) if !numbers.is_empty() => Written3::Numbers(numbers),
        _ => Written3::Bad,
    }
}

/// Whether `text` names a value that is no finite number: a word `NaN`, `inf`, `infinity`
/// (any case, with a sign) or `∞`.
fn not_finite(text: &str) -> bool {
    text.contains('∞')
        || text
            .split(|c: char| !c.is_ascii_alphabetic())
            .any(|w| ["nan", "inf", "infinity"].iter().any(|n| w.eq_ignore_ascii_case(n)))
}

/// The item of a finding: `s.spot α = 15° (column 3)` (column 1 is the label).
fn item(table: &str, row: &ParsedRow, cell: usize) -> String {
    format!("{table} {} (column {})", clip(&row.label), cell + 2)
}

/// A finding about a cell that holds the wrong kind of value (or a value where there is none).
fn wrong_kind(c: &mut Checker, row: &ParsedRow, k: usize, item: String, kit: &Value, why: Text) {
    c.out.checked += 1;
    c.out.findings.push(Finding {
        line: row.line,
        item,
        written: clip(&row.cells[k]),
        derived: value_text(kit),
        tolerance: None,
        why,
    });
}

/// Checks one written cell against the kit's value.
fn cell(c: &mut Checker, table: &str, row: &ParsedRow, k: usize, kit: &Value) {
    let text = &row.cells[k];
    let it = item(table, row, k);
    let numbers = match read_cell(text) {
        Written3::Skip => return,
        Written3::Bad => {
            let why = Text::new(
                "数として読めません: 数そのもの（`0.577`）か括弧で囲んだ 3 つの数（`(0.577, 0.577, 0.577)`）、途中の式を書くときは最後に `= 0.577` と値を書きます",
                "this does not read as a number: write a plain number (`0.577`) or three numbers in parentheses (`(0.577, 0.577, 0.577)`); after a working, end with `= 0.577`",
            );
            wrong_kind(c, row, k, it, kit, why);
            return;
        }
        Written3::NotFinite => {
            let why = Text::new(
                "書かれた値は有限の数ではありません（NaN・inf・∞）。計算を見直して、有限の数を書きます",
                "the written value is not a finite number (NaN, inf, ∞): check the working and write a finite number",
            );
            wrong_kind(c, row, k, it, kit, why);
            return;
        }
        Written3::Numbers(n) => n,
    };
    match (kit, numbers.len()) {
        (Value::Number(d), 1) => c.tuple(row.line, it, &numbers, &[*d], &["value"], false),
        (Value::Vector(d), 3) => c.tuple(row.line, it, &numbers, d, &["x", "y", "z"], false),
        (Value::Color(d), 3) => c.tuple(row.line, it, &numbers, d, &["r", "g", "b"], false),
        (Value::Nothing, _) => {
            let why = Text::new(
                "ここには値がありません: 全反射で屈折光はありません（None）",
                "there is no value here: under total internal reflection there is no refracted ray (None)",
            );
            wrong_kind(c, row, k, it, kit, why);
        }
        (Value::Number(_), count) => {
            let why = Text::new(
                format!("数が 1 つのはずですが {count} 個あります"),
                format!("one number is expected here, {count} are written"),
            );
            wrong_kind(c, row, k, it, kit, why);
        }
        (Value::Vector(_) | Value::Color(_), count) => {
            let why = Text::new(
                format!("括弧で囲んだ 3 つの数のはずですが {count} 個あります"),
                format!("three numbers in parentheses are expected here, {count} are written"),
            );
            wrong_kind(c, row, k, it, kit, why);
        }
    }
}

/// The kit's table to check `written` against: `kit` itself, or for [`LIGHT_Q`] the table at the
/// point written in its row Q (checked to lie on the sphere, and noted when it is not in the
/// highlight).
fn kit_for(c: &mut Checker, written: &ParsedTable, kit: &Table, data: &ShadingData) -> Table {
    if written.id != LIGHT_Q {
        return kit.clone();
    }
    let Some((row, k, written_point)) = chosen_point(written, kit) else { return kit.clone() };
    // |Q| and its direction in f64: Q = (1e20, 0, 0) has a direction, though its length
    // overflows f32 (it was called a Q of length 0, and 1e39 was replaced by the kit's Q).
    let length = written_point.length();
    let point = written_point.normalize_or_zero().as_vec3();
    let it = item(&written.id, row, k);
    c.out.checked += 3;
    if (length - 1.0).abs() > 0.01 {
        c.out.findings.push(Finding {
            line: row.line,
            item: it,
            written: clip(&row.cells[k]),
            derived: "|Q| = 1".to_owned(),
            tolerance: Some(0.01),
            // A Q of no length has no direction: the table is checked where the kit's
            // normalisation falls back to, (0, 1, 0) (`normalize_or(Vec3::Y)`).
            why: if point.normalize_or_zero() == Vec3::ZERO {
                Text::new(
                    "Q は半径 1 の球の上の点です。長さ 0 の Q には方向がないので、表は球の上の点 (0, 1, 0) で確かめます",
                    "Q is a point on the sphere of radius 1; a Q of length 0 has no direction, so the table is checked at (0, 1, 0), a point of the sphere",
                )
            } else {
                Text::new(
                    format!(
                        "Q は半径 1 の球の上の点です（|Q| = {length:.4}）。表はこの方向の球の上の点 Q/|Q| で確かめます"
                    ),
                    format!(
                        "Q is a point on the sphere of radius 1 (|Q| = {length:.4}); the table is checked at Q/|Q|, the point of the sphere in its direction"
                    ),
                )
            },
        });
    }
    let factor = highlight_factor(&data.setup, point);
    if factor < 0.5 {
        c.note(
            format!(
                "{} 行目: Q はハイライトの中にありません（max(R·V, 0)^n = {factor:.3}、ハイライトの中心で 1）",
                row.line
            ),
            format!(
                "line {}: Q is not in the highlight (max(R·V, 0)^n = {factor:.3}, 1 at its centre)",
                row.line
            ),
        );
    }
    light_table_at(&data.setup, LIGHT_Q, point)
}

/// The written row of the chosen point, its cell and the point, when it reads as three numbers.
fn chosen_point<'a>(
    written: &'a ParsedTable,
    kit: &Table,
) -> Option<(&'a ParsedRow, usize, DVec3)> {
    for kit_row in &kit.rows {
        let Some(k) = kit_row.cells.iter().position(|c| matches!(c, Cell::Chosen(_))) else {
            continue;
        };
        let row = written_row_for(&written.rows, kit_row, &kit.rows)?;
        let Written3::Numbers(n) = read_cell(row.cells.get(k)?) else { return None };
        let [x, y, z] = n.as_slice() else { return None };
        let p = DVec3::new(x.value, y.value, z.value);
        return p.is_finite().then_some((row, k, p));
    }
    None
}

/// Checks one written tagged table against the kit's `kit` (the same ID): each row found by its
/// label, each cell where the kit's row has a value; a row whose label the kit does not know is a
/// note when it holds numbers. Shared by every tagged table ([`crate::periods`] too).
pub(crate) fn check_table(c: &mut Checker, table: &ParsedTable, kit: &Table) {
    for row in &table.rows {
        let Some(kit_row) = kit_row_for(&row.label, &table.rows, &kit.rows) else {
            let could_be = rows_it_could_be(&row.label, &table.rows, &kit.rows);
            if !could_be.is_empty() {
                let list = |lang: Lang, or: &str| {
                    could_be.iter().map(|r| r.label.get(lang)).collect::<Vec<_>>().join(or)
                };
                c.note(
                    format!(
                        "{} 行目: 表 {} の行 `{}` は {} のどれか決められないので確かめていません。`?` は Shift_JIS で保存したとき書けない文字の代わりにエディタが書く文字です。レポートを UTF-8 で保存してください",
                        row.line,
                        table.id,
                        clip(&row.label),
                        list(Lang::Ja, "・")
                    ),
                    format!(
                        "line {}: the row `{}` of table {} could be {}, so it was not checked: a `?` is what an editor writes for a character Shift_JIS cannot hold; save the report as UTF-8",
                        row.line,
                        clip(&row.label),
                        table.id,
                        list(Lang::En, " or ")
                    ),
                );
                continue;
            }
            if row.cells.iter().any(|t| matches!(read_cell(t), Written3::Numbers(_))) {
                let known = |lang: Lang| {
                    kit.rows.iter().map(|r| r.label.get(lang)).collect::<Vec<_>>().join(", ")
                };
                c.note(
                    format!(
                        "{} 行目: 表 {} に `{}` という行はないので確かめていません（あるのは {}）",
                        row.line,
                        table.id,
                        clip(&row.label),
                        known(Lang::Ja)
                    ),
                    format!(
                        "line {}: table {} has no row `{}`, so it was not checked (rows: {})",
                        row.line,
                        table.id,
                        clip(&row.label),
                        known(Lang::En)
                    ),
                );
            }
            continue;
        };
        // Cells are found by their place: a column taken out or put in moves every value after
        // it under another heading, where it would be skipped or misjudged.
        if row.cells.len() != kit_row.cells.len() && kit_row.cells.iter().any(|k| k.kit().is_some())
        {
            let (got, want) = (row.cells.len() + 1, kit_row.cells.len() + 1);
            c.out.checked += 1;
            // The cells as written against the kit's row, not the two counts in the slots of
            // values (it read "written 5, derived 4").
            c.out.findings.push(Finding {
                line: row.line,
                item: format!("{} {}", table.id, clip(&row.label)),
                written: clip(&row.cells.join(" | ")),
                derived: kit_cells(kit_row, written_in(table, kit), true),
                tolerance: None,
                why: Text::new(
                    format!(
                        "この行は {got} 列ですが、表は {want} 列です。値は列の位置で確かめるので、列を消したり足したりせず、書かない欄は空けておいてください"
                    ),
                    format!(
                        "this row has {got} columns where the table has {want}: values are checked by their column, so keep every column and leave the ones you do not fill empty"
                    ),
                ),
            });
            continue;
        }
        for (k, kit_cell) in kit_row.cells.iter().enumerate().take(row.cells.len()) {
            // The chosen point is read by `kit_for`; here only when it is not three numbers.
            if matches!(kit_cell, Cell::Chosen(_))
                && matches!(read_cell(&row.cells[k]), Written3::Numbers(ref n) if n.len() == 3)
            {
                continue;
            }
            if let Some(value) = kit_cell.kit() {
                cell(c, &table.id, row, k, &value);
            }
        }
    }
}

/// The language a written table is in (a row label in the kit's Japanese), for the labels and
/// text cells the kit shows back.
fn written_in(table: &ParsedTable, kit: &Table) -> Lang {
    let in_japanese = table
        .rows
        .iter()
        .any(|r| kit.rows.iter().any(|k| canonical(&r.label) == canonical(&k.label.ja)));
    if in_japanese { Lang::Ja } else { Lang::En }
}

/// The kit's row `kit_row` as cells joined by ` | `: each value, `—` where there is none, and,
/// when `text` is set, its text cells in `lang` (so that each column has its place).
fn kit_cells(kit_row: &Row, lang: Lang, text: bool) -> String {
    kit_row
        .cells
        .iter()
        .filter_map(|k| match k {
            Cell::Text(t) => text.then(|| t.get(lang).to_owned()),
            _ => Some(k.kit().map_or_else(|| "—".to_owned(), |v| value_text(&v))),
        })
        .collect::<Vec<_>>()
        .join(" | ")
}

/// For a table whose every row must be written (the periods of `a3`), after [`check_table`]:
/// each row of the kit's that the written table lacks is a finding (a table cut short by a blank
/// line, or with a row deleted, is wrong, not "not written yet"), and so is a number (or `NaN`)
/// written in a cell where the kit's row has no value (`—`), `no_value(row, k)` saying why there
/// is none. A table with no rows at all is a problem of the reader already.
pub(crate) fn check_complete(
    c: &mut Checker,
    table: &ParsedTable,
    kit: &Table,
    no_value: impl Fn(&Row, usize) -> Text,
) {
    if table.rows.is_empty() {
        return;
    }
    let written_in = written_in(table, kit);
    let last_line = table.rows.last().map_or(table.line, |r| r.line);
    for kit_row in &kit.rows {
        let Some(row) = written_row_for(&table.rows, kit_row, &kit.rows) else {
            let label = kit_row.label.get(written_in);
            // A row whose label lost a character in a Shift_JIS save may be this one.
            let lossy = table.rows.iter().find(|r| {
                rows_it_could_be(&r.label, &table.rows, &kit.rows)
                    .iter()
                    .any(|k| std::ptr::eq(*k, kit_row))
            });
            let hint = lossy.map_or_else(Text::default, |r| {
                Text::new(
                    format!(
                        "（{} 行目の `{}` がこの行かもしれません。レポートを UTF-8 で保存してください）",
                        r.line,
                        clip(&r.label)
                    ),
                    format!(
                        " (the row `{}` at line {} may be it: save the report as UTF-8)",
                        clip(&r.label),
                        r.line
                    ),
                )
            });
            c.out.checked += 1;
            c.out.findings.push(Finding {
                line: last_line,
                item: format!("{} {label}", table.id),
                written: "—".to_owned(),
                derived: kit_cells(kit_row, written_in, false),
                tolerance: None,
                why: Text::new(
                    format!(
                        "表に「{}」の行がありません{}。すべての行を書きます（表は最初の空行までなので、表の途中に空行を入れないでください）",
                        kit_row.label.ja, hint.ja
                    ),
                    format!(
                        "the table has no row `{}`{}: write every row (a table ends at its first blank line, so keep blank lines out of it)",
                        kit_row.label.en, hint.en
                    ),
                ),
            });
            continue;
        };
        if row.cells.len() != kit_row.cells.len() {
            continue; // named by `check_table`
        }
        for (k, kit_cell) in kit_row.cells.iter().enumerate() {
            if !matches!(kit_cell, Cell::Empty)
                || !matches!(read_cell(&row.cells[k]), Written3::Numbers(_) | Written3::NotFinite)
            {
                continue;
            }
            c.out.checked += 1;
            c.out.findings.push(Finding {
                line: row.line,
                item: item(&table.id, row, k),
                written: clip(&row.cells[k]),
                derived: "—".to_owned(),
                tolerance: None,
                why: no_value(kit_row, k),
            });
        }
    }
}

/// Checks the shading section's tables `written` against `data` (see the module); a table the
/// report lacks, a row whose label the kit does not know, and tables without data are notes.
pub(crate) fn verify(c: &mut Checker, written: &[ParsedTable], data: Option<&ShadingData>) {
    let Some(data) = data else {
        if written.iter().any(|t| TABLE_IDS.contains(&t.id.as_str())) {
            c.note(
                "シェーディングのデータがないので、シェーディングの表は確かめていません",
                "there is no shading data, so the shading tables were not checked",
            );
        }
        return;
    };
    for table in written {
        let Some(kit) = data.table(&table.id) else { continue };
        let kit = kit_for(c, table, kit, data);
        check_table(c, table, &kit);
        // Every row the fill wrote must stay: a deleted row (or a blank line that ends the table
        // early) left its cells unchecked without a word.
        check_complete(c, table, &kit, |_, _| {
            Text::new(
                "この欄に値はありません。「—」のままにします",
                "this cell has no value: leave it as “—”",
            )
        });
    }
    let missing: Vec<&str> =
        TABLE_IDS.iter().copied().filter(|id| !written.iter().any(|t| t.id == *id)).collect();
    if !missing.is_empty() {
        let list = missing.join(", ");
        c.note(
            format!("レポートにタグ付きのシェーディングの表がありません: {list}"),
            format!("no tagged shading table found in the report for: {list}"),
        );
    }
}

#[cfg(test)]
pub(super) fn read_for_test(text: &str) -> Option<Vec<f64>> {
    match read_cell(text) {
        Written3::Numbers(n) => Some(n.iter().map(|w| w.value).collect()),
        _ => None,
    }
}
