//! What the report lacks, as notes (not findings: a row left out is no wrong number): the
//! vertex and face tables missing altogether, the rows of the derived model that the tables
//! leave out, and the list they name (the first [`NAMED`] by name and the rest counted, so a
//! large model does not name every row in one line).

use std::collections::HashSet;

use cg_harness::Text;

use super::Checker;
use crate::model::PolygonData;
use crate::parse::ParsedReport;

/// How many items a note names; the rest are counted.
pub(super) const NAMED: usize = 10;

/// `V6, F8, F9`, the first [`NAMED`] of `names`, and the rest counted in `unit_ja` (`面`, `行`):
/// `… ほか 3 面` / `… and 3 more`.
pub(super) fn named(names: &[String], unit_ja: &str) -> Text {
    let list = names.iter().take(NAMED).cloned().collect::<Vec<_>>().join(", ");
    match names.len().saturating_sub(NAMED) {
        0 => Text::new(list.clone(), list),
        more => {
            Text::new(format!("{list} ほか {more} {unit_ja}"), format!("{list} and {more} more"))
        }
    }
}

/// The vertex or face table missing altogether (or a face table without normals).
pub(super) fn tables_missing(c: &mut Checker, report: &ParsedReport) {
    if report.vertices.is_empty() {
        c.note("レポートに頂点の表がありません", "no vertex table found in the report");
    }
    if report.faces.is_empty() {
        c.note("レポートに面の表がありません", "no face table found in the report");
    } else if report.faces.iter().all(|f| f.normal.is_none()) {
        c.note("面の表に法線がありません", "the face table has no normals");
    }
}

/// The vertices and faces of the derived model that the report's tables leave out: a note
/// naming them, not a finding (the exit code stays). Only for a table the report has (a table
/// missing altogether is [`tables_missing`]'s note).
pub(super) fn rows_missing(c: &mut Checker, report: &ParsedReport, polygon: &PolygonData) {
    let mut names = Vec::new();
    if !report.vertices.is_empty() {
        let written: HashSet<u32> = report.vertices.iter().map(|v| v.index).collect();
        let count = u32::try_from(polygon.vertices.len()).unwrap_or(u32::MAX);
        names.extend((0..count).filter(|k| !written.contains(k)).map(|k| format!("V{k}")));
    }
    if !report.faces.is_empty() {
        let written: HashSet<u32> = report.faces.iter().map(|f| f.index).collect();
        let count = u32::try_from(polygon.faces.len()).unwrap_or(u32::MAX);
        names.extend((0..count).filter(|k| !written.contains(k)).map(|k| format!("F{k}")));
    }
    if names.is_empty() {
        return;
    }
    let list = named(&names, "行");
    c.note(
        format!(
            "{}: 導出したモデルにあるこの {} 行がレポートの表にありません（書かなかった行は確かめていませんが、誤りには数えません）",
            list.ja,
            names.len()
        ),
        format!(
            "{}: the derived model has {} {} the report's tables leave out (not checked, and not counted as mistakes)",
            list.en,
            names.len(),
            if names.len() == 1 { "row" } else { "rows" }
        ),
    );
}
