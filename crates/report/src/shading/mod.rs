//! The shading section (assignment `s`): its tables written into the template ([`values`]), read
//! back from a report ([`parse_tables`]) and checked against the kit's values (by
//! [`crate::verify::verify`]).
//!
//! The data is `s`'s own (`cg_shading::report`, [`crate::model::ShadingData`]): six tables, each with a tag, rows found by
//! their label (the first column) and cells that hold either text, a number to work out by hand
//! (`✍`), a given number, or the student's function's output. The notation:
//!
//! ```text
//! <!-- cg: s.spot -->                                   the tag (LaTeX: % cg: s.spot)
//! | angle from the axis | cos α by hand ✍ | factor by hand ✍ | your spot_factor() |
//! |---|---|---|---|
//! | α = 15° | 0.966 | 0.933 | 0.933 |                   a row: its label, then its cells
//! ```
//!
//! The notation is shared: the periods of `a3` ([`crate::periods`]) are such a table too, written
//! and checked by the same code (`tagged_table`, `check_table`).
//!
//! A table is the run of rows (Markdown `| … |`, or LaTeX `… & … \\`) after its tag, up to the
//! next tag, heading, blank line after the rows or `\end{…}`. A cell is checked when the kit's
//! row has a number there and the cell holds digits: a plain number (`0.933`), three numbers in
//! parentheses (`(0.577, 0.577, 0.577)`), or a working that ends in one (`1/√3 = 0.577`, the
//! value after the last `=` or `≈`; a trailing unit `°`, `s` or `秒` is allowed). A cell without
//! digits (`✍`, `—`, `None`) is not checked; `NaN`, `inf` and `∞` are values that are no finite
//! number, a mistake. The point Q of `s.light.q` may be the student's own: the kit derives
//! that table from the Q written in it.

use cg_assign::cg_shading::report::TABLE_IDS;
use cg_core::lang::Lang;

use crate::parse::{ParseProblem, RowKind, clip, normalize};
use crate::tables::tex_text;

mod check;
mod fill;

pub(crate) use check::{check_complete, check_table, verify};
pub(crate) use fill::tagged_table;
pub use fill::{KEYS, values};

/// Whether `id` is the tag of a table in this notation: a shading table, or the periods of `a3`
/// ([`crate::periods::TABLE_ID`]), which share it (the matrix reader leaves those alone).
#[must_use]
pub fn is_table_tag(id: &str) -> bool {
    TABLE_IDS.contains(&id) || id == crate::periods::TABLE_ID
}

/// One row of a tagged table as written.
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedRow {
    /// The 1-based line.
    pub line: usize,
    /// The first cell, trimmed.
    pub label: String,
    /// The other cells, trimmed, in order.
    pub cells: Vec<String>,
}

/// A tagged table of the shading section as written.
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedTable {
    /// The 1-based line of the tag.
    pub line: usize,
    /// The tag's ID (one of [`TABLE_IDS`]).
    pub id: String,
    /// Its rows (the header too; a separator row `|---|` is left out).
    pub rows: Vec<ParsedRow>,
}

/// The ID of a tag on `line` (`<!-- cg: ID -->` or `% cg: ID`), whatever the ID.
pub(crate) fn tag_on(line: &str) -> Option<String> {
    if let Some(rest) = line.trim_start().strip_prefix('%')
        && let Some(id) = rest.trim_start().strip_prefix("cg:")
    {
        return Some(id.trim().to_owned());
    }
    let start = line.find("<!--")?;
    let rest = line[start + 4..].trim_start().strip_prefix("cg:")?;
    let end = rest.find("-->")?;
    Some(rest[..end].trim().to_owned())
}

/// The cells of a table row: Markdown `| a | b |`, or LaTeX `a & b \\`.
pub(crate) fn row_cells(line: &str) -> Option<Vec<String>> {
    let trimmed = line.trim();
    if let Some(inner) = trimmed.strip_prefix('|') {
        let inner = inner.strip_suffix('|').filter(|i| !i.ends_with('\\')).unwrap_or(inner);
        // `\|` is a `|` inside a cell (`|E − P|`), not a column break.
        let mut cells = vec![String::new()];
        let mut chars = inner.chars().peekable();
        while let Some(c) = chars.next() {
            match c {
                '\\' if chars.peek() == Some(&'|') => {
                    chars.next();
                    if let Some(s) = cells.last_mut() {
                        s.push('|');
                    }
                }
                '|' => cells.push(String::new()),
                _ => {
                    if let Some(s) = cells.last_mut() {
                        s.push(c);
                    }
                }
            }
        }
        return Some(cells.into_iter().map(|c| c.trim().to_owned()).collect());
    }
    let body = trimmed.strip_suffix("\\hline").unwrap_or(trimmed).trim_end();
    let body = body.strip_suffix("\\\\")?;
    // `\&` is an escaped ampersand inside a cell, not a column break.
    let cells: Vec<String> =
        body.replace("\\&", "\u{0}").split('&').map(|c| c.trim().replace('\u{0}', "\\&")).collect();
    (cells.len() > 1).then_some(cells)
}

/// Whether the row is a Markdown separator (`|---|:--:|`).
fn is_separator(cells: &[String]) -> bool {
    cells.iter().all(|c| !c.is_empty() && c.chars().all(|x| matches!(x, '-' | ':' | ' ')))
}

/// Whether the line ends a table region: a heading.
pub(crate) fn is_heading(line: &str) -> bool {
    let t = line.trim_start();
    t.starts_with('#')
        || t.starts_with("\\section")
        || t.starts_with("\\subsection")
        || t.starts_with("\\subsubsection")
}

/// Every shading table of `lines` (the report's lines, as the reader normalises them), and the
/// tags with no table after them as problems.
#[must_use]
pub fn parse_tables(lines: &[String]) -> (Vec<ParsedTable>, Vec<ParseProblem>) {
    let mut tables = Vec::new();
    let mut problems = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        let Some(id) = tag_on(line).filter(|id| is_table_tag(id)) else { continue };
        let mut rows = Vec::new();
        for (j, next) in lines.iter().enumerate().skip(k + 1) {
            let started = !rows.is_empty();
            if tag_on(next).is_some() || is_heading(next) {
                break;
            }
            if let Some(cells) = row_cells(next) {
                if is_separator(&cells) {
                    continue;
                }
                let mut cells = cells.into_iter();
                let label = cells.next().unwrap_or_default();
                rows.push(ParsedRow { line: j + 1, label, cells: cells.collect() });
                continue;
            }
            let t = next.trim();
            if started && (t.is_empty() || t.starts_with("\\end{") || !t.starts_with('\\')) {
                break;
            }
        }
        if rows.is_empty() {
            problems.push(ParseProblem {
                line: k + 1,
                found: clip(line),
                expected: cg_harness::Text::new(
                    format!("タグ `{id}` のあとに、その表（`| 量 | … |` の行）"),
                    format!("the table after the tag `{id}` (rows `| quantity | … |`)"),
                ),
                kind: RowKind::Table,
            });
        }
        tables.push(ParsedTable { line: k + 1, id, rows });
    }
    (tables, problems)
}

/// A label or text of the tables for LaTeX: escaped as the other tables' text is (the symbols
/// the fonts lack set in math), `✍` left out (LaTeX marks the cells to write with `\yours{}`)
/// and `…` as `\dots`.
#[must_use]
pub fn tex_label(text: &str) -> String {
    tex_text(&text.replace(" ✍", "").replace('✍', "")).replace('…', "\\dots{}")
}

/// A label as the checker compares it: read as the report reader reads a line, without spaces,
/// `$`, `\(`, `\)`, backticks, asterisks and braces, `−` (and the full-width `－` a Shift_JIS
/// file keeps of it, or the other dashes) as `-`, a Japanese middle dot (`N・L`, what a Shift_JIS
/// file keeps of `N·L`) or a dot operator as `·`, subscript digits (`θ₂`, which Shift_JIS cannot
/// keep) and superscript digits as digits, full-width letters and signs (`－ｘ　１`, as an IME
/// writes them) as ASCII, `度` and `^\circ` as `°`, in lower case.
fn canonical(label: &str) -> String {
    normalize(label)
        .replace("\\(", "")
        .replace("\\)", "")
        .replace("^\\circ", "°")
        .replace("\\circ", "°")
        .replace('度', "°")
        .chars()
        // Full-width ASCII (U+FF01–FF5E) is ASCII: `ｘ` is `x`, `＄` is `$`.
        .map(|c| match c {
            '\u{ff01}'..='\u{ff5e}' => char::from_u32(u32::from(c) - 0xfee0).unwrap_or(c),
            _ => c,
        })
        .filter(|c| !c.is_whitespace() && !matches!(c, '$' | '`' | '*' | '{' | '}'))
        .map(|c| match c {
            // `−x 1` comes back from Shift_JIS as `－x 1` (U+FF0D, made `-` above with the other
            // full-width signs), and an IME writes it so.
            '−' | '﹣' | '\u{2010}'..='\u{2015}' => '-',
            '・' | '･' | '⋅' | '∙' => '·',
            // `θ₂` cannot be kept in Shift_JIS: a student writes `θ2`.
            '₀'..='₉' => char::from_digit(u32::from(c) - u32::from('₀'), 10).unwrap_or(c),
            '⁰' | '⁴'..='⁹' => {
                char::from_digit(u32::from(c) - u32::from('⁰'), 10).unwrap_or(c)
            }
            '¹' => '1',
            '²' => '2',
            '³' => '3',
            _ => c,
        })
        .flat_map(char::to_lowercase)
        .collect()
}

/// Whether a written label names the row labelled `label` (in either language, as Markdown or
/// as LaTeX writes it).
fn label_matches(written: &str, label: &cg_harness::Text) -> bool {
    let w = canonical(written);
    [Lang::Ja, Lang::En].iter().any(|&lang| {
        let l = label.get(lang);
        w == canonical(l) || w == canonical(&tex_label(l))
    })
}

/// Whether `written` names `label` once what a Shift_JIS save loses is allowed for: an editor
/// writes `?` for a character the file cannot keep (`·` of `N·L`, `₁` of `θ₁`), iconv's
/// transliteration `.` for `·`. Each `?` stands for any one character, a `.` for `·`.
fn label_matches_loosely(written: &str, label: &cg_harness::Text) -> bool {
    let w: Vec<char> = canonical(written).chars().collect();
    if !w.iter().any(|c| matches!(c, '?' | '.')) {
        return false;
    }
    [Lang::Ja, Lang::En].iter().any(|&lang| {
        let l = label.get(lang);
        [canonical(l), canonical(&tex_label(l))].iter().any(|l| {
            let l: Vec<char> = l.chars().collect();
            l.len() == w.len()
                && w.iter().zip(&l).all(|(a, b)| a == b || *a == '?' || (*a == '.' && *b == '·'))
        })
    })
}

/// The kit's row the written label `label` names: the one it names ([`label_matches`]), else
/// the only one it could name once a Shift_JIS save's losses are allowed ([`rows_it_could_be`]).
pub(crate) fn kit_row_for<'a>(
    label: &str,
    written: &[ParsedRow],
    rows: &'a [cg_assign::cg_shading::report::Row],
) -> Option<&'a cg_assign::cg_shading::report::Row> {
    rows.iter().find(|r| label_matches(label, &r.label)).or_else(|| {
        let loose = loose_rows(label, written, rows);
        (loose.len() == 1).then(|| loose[0])
    })
}

/// The kit's rows the written label `label` could name once a Shift_JIS save's losses are
/// allowed — each `?` any one character, a `.` for `·` — leaving out those another written row
/// names exactly (`θ?` is `θ₂` where `θc` is written too). Empty when it names one exactly.
fn loose_rows<'a>(
    label: &str,
    written: &[ParsedRow],
    rows: &'a [cg_assign::cg_shading::report::Row],
) -> Vec<&'a cg_assign::cg_shading::report::Row> {
    if rows.iter().any(|r| label_matches(label, &r.label)) {
        return Vec::new();
    }
    let named_by_another = |r: &cg_assign::cg_shading::report::Row| {
        written.iter().any(|w| w.label != label && label_matches(&w.label, &r.label))
    };
    rows.iter().filter(|r| label_matches_loosely(label, &r.label) && !named_by_another(r)).collect()
}

/// The kit's rows a written label could name, when it could name more than one ([`loose_rows`]):
/// `θ?` of a table with `θ₁` and `θ₂` written as `θ?` both. Empty otherwise.
pub(crate) fn rows_it_could_be<'a>(
    label: &str,
    written: &[ParsedRow],
    rows: &'a [cg_assign::cg_shading::report::Row],
) -> Vec<&'a cg_assign::cg_shading::report::Row> {
    let loose = loose_rows(label, written, rows);
    if loose.len() > 1 { loose } else { Vec::new() }
}

/// The written row that names `kit_row` of `rows` ([`kit_row_for`]).
pub(crate) fn written_row_for<'a>(
    written: &'a [ParsedRow],
    kit_row: &cg_assign::cg_shading::report::Row,
    rows: &[cg_assign::cg_shading::report::Row],
) -> Option<&'a ParsedRow> {
    written
        .iter()
        .find(|r| kit_row_for(&r.label, written, rows).is_some_and(|k| std::ptr::eq(k, kit_row)))
}

#[cfg(test)]
mod tests;
