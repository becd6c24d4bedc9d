//! The periods table on the kit's own stubs (the periods follow from the assignment alone):
//! filled in both languages and formats, read back and checked clean; a wrong period or
//! amplitude is named with its object, column and the expected value; units are accepted.

use cg_assign::Variants;
use cg_core::lang::{Lang, t};
use cg_harness::{StudentNumber, TableVersion};

use super::*;
use crate::fill::{self, Context};
use crate::model::Derived;
use crate::parse::{line_of, parse_report};
use crate::shading::row_cells;
use crate::template::{self, Format};
use crate::verify::{Verification, verify, verify_with};

const STUDENTS: [&str; 3] = ["12345678", "20260002", "24000007"];

fn assignment(student: &str) -> Variants {
    let n: StudentNumber = student.parse().unwrap();
    Variants::for_student(&n, TableVersion::V1)
}

/// The filled report of the stubs (a3's functions not written: the table is there all the same).
fn filled(a: &Variants, lang: Lang, format: Format) -> (String, Derived) {
    let derived = crate::derive::derive(a, &cg_assign::impls!(cg_exercises)).0;
    assert!(derived.a3.is_none(), "the stubs derive no animation");
    let ctx = Context { variants: Some(a.clone()), ..Context::default() };
    let text = template::fill(
        template::template(lang, format),
        &fill::values(&derived, &ctx, lang, format),
    )
    .unwrap();
    (text, derived)
}

fn check(text: &str, derived: &Derived, a: &Variants) -> Verification {
    let (report, problems) = parse_report(text);
    assert!(problems.is_empty(), "{problems:?}");
    verify_with(&report, derived, Some(a))
}

/// `text` with cell `k` (0 = the label) of the row whose label is `label` replaced by `to`;
/// and the row's line.
fn edit_cell(text: &str, label: &str, k: usize, to: &str) -> (String, usize) {
    let mut at = 0;
    let lines: Vec<String> = text
        .lines()
        .enumerate()
        .map(|(n, line)| {
            let Some(cells) = row_cells(line).filter(|c| c[0] == label && at == 0) else {
                return line.to_owned();
            };
            at = n + 1;
            let mut cells = cells;
            cells[k] = to.to_owned();
            if line.trim_start().starts_with('|') {
                format!("| {} |", cells.join(" | "))
            } else {
                format!("{} \\\\", cells.join(" & "))
            }
        })
        .collect();
    assert!(at > 0, "no row {label:?}");
    (lines.join("\n"), at)
}

fn label(n: usize, lang: Lang) -> String {
    Text::new(format!("物体{n}"), format!("object {n}")).get(lang).to_owned()
}

fn findings(v: &Verification) -> Vec<(usize, &str)> {
    v.findings.iter().map(|f| (f.line, f.item.as_str())).collect()
}

#[test]
fn the_filled_table_reads_back_and_checks_clean_in_both_languages_and_formats() {
    for student in STUDENTS {
        let a = assignment(student);
        let kit = table(&a.a3);
        assert_eq!(kit.rows.len(), a.a3.objects.len() + 1, "one row per object, and the whole");
        for lang in [Lang::Ja, Lang::En] {
            for format in [Format::Markdown, Format::Latex] {
                let (text, derived) = filled(&a, lang, format);
                let tag = match format {
                    Format::Markdown => "<!-- cg: a3.periods -->",
                    Format::Latex => "% cg: a3.periods",
                };
                assert!(text.contains(tag), "{student} {lang} {format:?}");
                let (report, _) = parse_report(&text);
                let table = report.tables.iter().find(|t| t.id == TABLE_ID).unwrap();
                assert_eq!(table.rows.len(), kit.rows.len() + 1, "the header and every row");
                let v = check(&text, &derived, &a);
                assert!(v.findings.is_empty(), "{student} {lang} {format:?}: {:#?}", v.findings);
                let notes: Vec<&str> = v.notes.iter().map(|n| n.en.as_str()).collect();
                assert!(!notes.iter().any(|n| n.contains("a3.periods")), "{notes:?}");
                // Every period, the whole's, and each amplitude, radius, arm, span and height.
                let numbers: usize =
                    kit.rows.iter().flat_map(|r| &r.cells).filter(|c| c.kit().is_some()).count();
                assert!(numbers > kit.rows.len(), "{student}");
                let without = verify(&parse_report(&text).0, &derived);
                assert!(
                    v.checked >= without.checked + numbers,
                    "{student}: {} checked with the assignment, {} without",
                    v.checked,
                    without.checked
                );
            }
        }
    }
}

#[test]
fn a_wrong_period_is_named_with_its_object_column_and_the_expected_value() {
    let a = assignment(STUDENTS[0]);
    let period = a.a3.objects[1].motion.period_s();
    for lang in [Lang::Ja, Lang::En] {
        for format in [Format::Markdown, Format::Latex] {
            let (text, derived) = filled(&a, lang, format);
            let wrong = format!("{}", period + 1.0);
            let (text, line) = edit_cell(&text, &label(2, lang), 2, &wrong);
            let v = check(&text, &derived, &a);
            let item = format!("a3.periods {} (column 3)", label(2, lang));
            assert_eq!(findings(&v), [(line, item.as_str())], "{lang} {format:?}");
            let f = &v.findings[0];
            assert_eq!(f.written, wrong);
            let shown: f64 = f.derived.parse().unwrap();
            assert!((shown - f64::from(period)).abs() < 1e-9, "{f:?}");
            let message = f.message(lang);
            assert!(message.contains(&f.derived), "{message}");
            let place = t("物体2（3 列目）", "object 2 (column 3)");
            assert!(message.contains(place.get(lang)), "{message}");
        }
    }
}

#[test]
fn a_period_may_carry_its_unit_and_the_whole_periods_row_is_checked() {
    let a = assignment(STUDENTS[1]);
    let period = format_number(a.a3.objects[0].motion.period_s());
    let longer = if period.contains('.') { format!("{period}0") } else { format!("{period}.0") };
    for (lang, format, written) in [
        (Lang::En, Format::Markdown, format!("{period} s")),
        (Lang::En, Format::Markdown, format!("{longer} sec")),
        (Lang::Ja, Format::Markdown, format!("{period}秒")),
        (Lang::Ja, Format::Markdown, format!("{period} 秒")),
        (Lang::En, Format::Latex, format!("${period}\\,\\mathrm{{s}}$")),
        (Lang::Ja, Format::Latex, format!("{period}~\\text{{s}}")),
        (Lang::En, Format::Markdown, format!("T = {period} s")),
    ] {
        let (text, derived) = filled(&a, lang, format);
        let (text, _) = edit_cell(&text, &label(1, lang), 2, &written);
        let v = check(&text, &derived, &a);
        assert!(v.findings.is_empty(), "{written:?}: {:#?}", v.findings);
    }
    // The whole animation's period: one period of an object is not it.
    let (text, derived) = filled(&a, Lang::En, Format::Markdown);
    let (text, line) = edit_cell(&text, "all", 2, &format!("{period} s"));
    let v = check(&text, &derived, &a);
    assert_eq!(findings(&v), [(line, "a3.periods all (column 3)")]);
}

#[test]
fn a_wrong_amplitude_or_span_is_named_too() {
    // A student whose variant has a swing or a hop: its first number after the period.
    let (a, n, k) = STUDENTS
        .iter()
        .map(|s| assignment(s))
        .find_map(|a| {
            let kit = table(&a.a3);
            let found = kit.rows.iter().enumerate().find_map(|(n, r)| {
                r.cells.iter().skip(2).position(|c| c.kit().is_some()).map(|k| (n, k + 3))
            });
            found.map(|(n, k)| (a, n + 1, k))
        })
        .expect("a variant with an amplitude, a radius or a span");
    let (text, derived) = filled(&a, Lang::En, Format::Markdown);
    let (text, line) = edit_cell(&text, &label(n, Lang::En), k, "99.5");
    let v = check(&text, &derived, &a);
    let item = format!("a3.periods object {n} (column {})", k + 1);
    assert_eq!(findings(&v), [(line, item.as_str())]);
}

#[test]
fn without_the_assignment_or_without_the_table_it_is_a_note() {
    let a = assignment(STUDENTS[2]);
    let (text, derived) = filled(&a, Lang::En, Format::Markdown);
    let (report, _) = parse_report(&text);
    let v = verify(&report, &derived);
    assert!(v.findings.is_empty());
    assert!(v.notes.iter().any(|n| n.en.contains("the periods table a3.periods was not checked")));
    let cut = text.replace("<!-- cg: a3.periods -->", "");
    let v = check(&cut, &derived, &a);
    assert!(
        v.notes.iter().any(|n| n.en == "no tagged periods table found in the report: a3.periods")
    );
    assert!(v.notes.iter().any(|n| n.ja.contains("周期の表がありません")));
    // A row the kit does not have: a note naming it; and the row it replaced is missing.
    let (text, _) = edit_cell(&text, "object 1", 0, "object 9");
    let v = check(&text, &derived, &a);
    let items: Vec<&str> = v.findings.iter().map(|f| f.item.as_str()).collect();
    assert_eq!(items, ["a3.periods object 1"], "{:#?}", v.findings);
    let line = line_of(&text, "| object 9 |");
    assert!(
        v.notes
            .iter()
            .any(|n| n.en.starts_with(&format!("line {line}: table a3.periods has no row"))),
        "{:?}",
        v.notes
    );
}

/// A number written in a "—" cell (a value the motion does not have) was passed over: it is
/// named with the motion; so is a period written as `NaN`, `inf` or `∞`.
#[test]
fn a_number_where_the_motion_has_none_and_a_period_that_is_no_number_are_mistakes() {
    let a = assignment(STUDENTS[0]);
    let spin = a.a3.objects.iter().position(|o| matches!(o.motion, Motion::Spin { .. }));
    for lang in [Lang::Ja, Lang::En] {
        for format in [Format::Markdown, Format::Latex] {
            let (text, derived) = filled(&a, lang, format);
            // The whole animation has no amplitude (column 4), whatever the student.
            let (wrong, line) = edit_cell(&text, t("全体", "all").get(lang), 3, "30");
            let v = check(&wrong, &derived, &a);
            let item = format!("a3.periods {} (column 4)", t("全体", "all").get(lang));
            assert_eq!(findings(&v), [(line, item.as_str())], "{lang} {format:?}");
            let f = &v.findings[0];
            assert_eq!((f.written.as_str(), f.derived.as_str()), ("30", "—"));
            assert!(f.why.en.contains("has no amplitude (°)"), "{:?}", f.why);
            assert!(f.why.ja.contains("「振幅（°）」の値はありません"), "{:?}", f.why);
            if let Some(k) = spin {
                // A spin has no radius or height either.
                let (wrong, line) = edit_cell(&text, &label(k + 1, lang), 4, "1.5");
                let v = check(&wrong, &derived, &a);
                assert_eq!(v.findings.len(), 1, "{:#?}", v.findings);
                assert_eq!(v.findings[0].line, line);
            }
            for bad in ["NaN", "inf", "∞"] {
                let (wrong, line) = edit_cell(&text, &label(1, lang), 2, bad);
                let v = check(&wrong, &derived, &a);
                assert_eq!(findings(&v).len(), 1, "{bad}: {:#?}", v.findings);
                assert_eq!(v.findings[0].line, line);
                assert!(v.findings[0].why.en.contains("not a finite number"));
            }
        }
    }
}

/// A table cut short by a blank line (the rows after it are outside the table), or with a row
/// deleted, passed without a word: each missing row is a mistake.
#[test]
fn rows_missing_from_the_table_are_mistakes() {
    let a = assignment(STUDENTS[1]);
    let objects = a.a3.objects.len();
    for lang in [Lang::Ja, Lang::En] {
        let (text, derived) = filled(&a, lang, Format::Markdown);
        // A row deleted.
        let row = format!("| {} |", label(2, lang));
        let deleted: String =
            text.lines().filter(|l| !l.starts_with(&row)).map(|l| format!("{l}\n")).collect();
        let v = check(&deleted, &derived, &a);
        let item = format!("a3.periods {}", label(2, lang));
        let items: Vec<&str> = v.findings.iter().map(|f| f.item.as_str()).collect();
        assert_eq!(items, [item.as_str()], "{lang}");
        let f = &v.findings[0];
        assert!(f.why.en.contains("no row `object 2`"), "{:?}", f.why);
        assert!(f.why.ja.contains("「物体2」の行がありません"), "{:?}", f.why);
        // A blank line after the header: no row is in the table.
        let first = format!("| {} |", label(1, lang));
        let blank = text.replacen(&first, &format!("\n{first}"), 1);
        let v = check(&blank, &derived, &a);
        assert_eq!(v.findings.len(), objects + 1, "{lang}: {:#?}", v.findings);
        let header = line_of(&blank, "|---|");
        assert!(v.findings.iter().all(|f| f.line == header - 1), "{:#?}", v.findings);
    }
}

/// A table in an HTML comment or a code fence is not read (it was, and checked as if written).
#[test]
fn a_table_in_a_comment_or_a_fence_is_not_read() {
    let a = assignment(STUDENTS[2]);
    let (text, derived) = filled(&a, Lang::En, Format::Markdown);
    let tag = "<!-- cg: a3.periods -->";
    // Commented out after the tag: the tag has no table (a problem of the reader).
    let commented = text.replacen(tag, &format!("{tag}\n<!--"), 1).replacen(
        "Ratio of the periods",
        "-->\nRatio of the periods",
        1,
    );
    let (report, problems) = parse_report(&commented);
    assert_eq!(problems.len(), 1, "{problems:#?}");
    assert_eq!(problems[0].line, line_of(&commented, tag));
    assert!(report.tables.iter().any(|t| t.id == TABLE_ID && t.rows.is_empty()));
    // In a fence with its tag: no table (a note, as for a report without it).
    let fenced = text.replacen(tag, &format!("```\n{tag}"), 1).replacen(
        "Ratio of the periods",
        "```\nRatio of the periods",
        1,
    );
    let v = check(&fenced, &derived, &a);
    assert!(v.findings.is_empty(), "{:#?}", v.findings);
    assert!(
        v.notes.iter().any(|n| n.en == "no tagged periods table found in the report: a3.periods")
    );
}
