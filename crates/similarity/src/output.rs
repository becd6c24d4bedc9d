//! What `cg similarity` writes: `similarity.csv` (one row per listed pair and per cross-variant
//! finding, for a spreadsheet or a script) and `similarity.html` ([`crate::html`]: the same,
//! with the matching regions side by side).

use std::path::Path;

use cg_core::lang::{Lang, Text, t};

use crate::{Analysis, Submission, variant};

/// The CSV's columns (stable names, for scripts).
pub const COLUMNS: [&str; 12] = [
    "kind",
    "a",
    "a_student",
    "b",
    "b_student",
    "score",
    "shared_fingerprints",
    "shared_lines_a",
    "shared_lines_b",
    "cluster",
    "flags",
    "note",
];

/// Whether two submissions give the same student number.
#[must_use]
pub fn same_number(a: &Submission, b: &Submission) -> bool {
    a.student.is_some() && a.number() == b.number()
}

/// A student-controlled name as a spreadsheet cell ([`cg_core::quote::spreadsheet_cell`]).
fn cell(name: &str) -> String {
    cg_core::quote::spreadsheet_cell(name).into_owned()
}

/// `similarity.csv`: a `pair` row for each listed pair (best first), then a `cross-variant` row
/// for each finding (`a` the submission, `b` the student whose variant it follows, `score` the
/// evidence, `note` the numbers). `flags`: `reference` when one side is an earlier year's,
/// `cross-variant` when a side is also flagged so. The names are spreadsheet-safe: one that
/// begins like a formula gets a leading `'`.
///
/// # Errors
/// The CSV writer's error (never for a `Vec`).
pub fn csv_text(class: &[Submission], analysis: &Analysis, lang: Lang) -> Result<String, String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(COLUMNS).map_err(|e| e.to_string())?;
    let flagged = |i: usize| analysis.cross.iter().any(|c| c.submission == i);
    for p in &analysis.pairs {
        let (a, b) = (&class[p.a], &class[p.b]);
        let mut flags = Vec::new();
        if a.reference || b.reference {
            flags.push("reference");
        }
        if flagged(p.a) || flagged(p.b) {
            flags.push("cross-variant");
        }
        // A resubmission, or a student's own earlier year: listed (student.toml is the
        // student's to write, so it hides nothing), and said.
        if same_number(a, b) {
            flags.push("same-number");
        }
        let regions: Vec<String> = p
            .regions
            .iter()
            .map(|r| {
                format!(
                    "{}.rs:{}-{} ~ {}.rs:{}-{}",
                    r.module_a, r.lines_a.0, r.lines_a.1, r.module_b, r.lines_b.0, r.lines_b.1
                )
            })
            .collect();
        w.write_record([
            "pair".to_owned(),
            cell(&a.name),
            a.number(),
            cell(&b.name),
            b.number(),
            format!("{:.3}", p.score),
            p.shared.to_string(),
            p.lines_a.to_string(),
            p.lines_b.to_string(),
            p.cluster.map(|c| c.to_string()).unwrap_or_default(),
            flags.join(" "),
            regions.join("; "),
        ])
        .map_err(|e| e.to_string())?;
    }
    for c in &analysis.cross {
        let s = &class[c.submission];
        let f = &c.finding;
        w.write_record([
            "cross-variant".to_owned(),
            cell(&s.name),
            s.number(),
            cell(&c.sources.iter().map(|i| class[*i].name.clone()).collect::<Vec<_>>().join(" ")),
            if f.ambiguous {
                std::iter::once(&f.matches)
                    .chain(&f.also)
                    .map(ToString::to_string)
                    .collect::<Vec<_>>()
                    .join(" ")
            } else {
                f.matches.to_string()
            },
            format!("{:.2}", f.evidence),
            String::new(),
            String::new(),
            String::new(),
            String::new(),
            if f.ambiguous { format!("{} ambiguous", f.part) } else { f.part.clone() },
            cross_note(c, s, lang),
        ])
        .map_err(|e| e.to_string())?;
    }
    let bytes = w.into_inner().map_err(|e| e.to_string())?;
    String::from_utf8(bytes).map_err(|e| e.to_string())
}

/// One line on a cross-variant finding in the submission `s`: which part (for a report, which
/// file: the `--reports` one, or the one inside the submission), whose variant, which numbers.
#[must_use]
pub fn cross_note(c: &crate::Cross, s: &crate::Submission, lang: Lang) -> String {
    let f = &c.finding;
    let part = if f.part.starts_with(variant::REPORT) {
        let m = variant::assignment(&f.part);
        let from = match (&s.report_file, &s.report_inside) {
            (Some(file), _) => Text::new(format!("、{file}"), format!(", {file}")),
            (None, Some(inside)) => {
                Text::new(format!("、提出物の {inside}"), format!(", {inside} in the submission"))
            }
            (None, None) => Text::new(String::new(), String::new()),
        };
        Text::new(format!("レポート（{m}{}）", from.ja), format!("the report ({m}{})", from.en))
            .get(lang)
            .to_owned()
    } else {
        format!("exercises/src/{}.rs", f.part)
    };
    let numbers: Vec<String> =
        f.numbers.iter().map(|(k, label)| format!("{} ({label})", variant::show(*k))).collect();
    let also = if f.ambiguous {
        let list: Vec<String> = f.also.iter().map(ToString::to_string).collect();
        Text::new(
            format!(" どの学生の課題か判別できません（{} か {}）", f.matches, list.join("、")),
            format!(" cannot tell whose: {} or {}", f.matches, list.join(", ")),
        )
        .get(lang)
        .to_owned()
    } else if f.also.is_empty() {
        String::new()
    } else {
        let list: Vec<String> = f.also.iter().map(ToString::to_string).collect();
        format!(" {} {}", t("同じく一致:", "also matching:").get(lang), list.join(", "))
    };
    Text::new(
        format!(
            "{part} の数値は {} の課題から出ています（本人の課題にない数値 {} 個、重み {:.1}、本人の課題だけの数値の重み {:.1}）: {}{also}",
            f.matches,
            f.numbers.len(),
            f.evidence,
            f.own_evidence,
            numbers.join(", ")
        ),
        format!(
            "the numbers of {part} follow from {}'s variant ({} numbers not in the student's own, weight {:.1}; the own variant's numbers weigh {:.1}): {}{also}",
            f.matches,
            f.numbers.len(),
            f.evidence,
            f.own_evidence,
            numbers.join(", ")
        ),
    )
    .get(lang)
    .to_owned()
}

/// Writes `similarity.csv` and `similarity.html` into `out` (made if missing).
///
/// # Errors
/// The folder or a file cannot be written, with the path.
pub fn write(
    out: &Path,
    class: &[Submission],
    analysis: &Analysis,
    lang: Lang,
) -> Result<(), String> {
    let io = |p: &Path, e: std::io::Error| Text::io_at(p, &e).get(lang).to_owned();
    std::fs::create_dir_all(out).map_err(|e| io(out, e))?;
    let csv = csv_text(class, analysis, lang)?;
    let path = out.join("similarity.csv");
    // Opened in Excel on Japanese Windows, where a file without the byte-order mark garbles
    // Japanese names.
    std::fs::write(&path, cg_core::quote::spreadsheet_file(&csv)).map_err(|e| io(&path, e))?;
    let html = crate::html::page(class, analysis, lang);
    let path = out.join("similarity.html");
    std::fs::write(&path, html).map_err(|e| io(&path, e))
}
