//! The shading section on the kit's own stubs (whose kit values derive without the student's
//! code): filled, read back, worked by hand (the ✍ cells written with the kit's values) and
//! checked clean in Markdown and LaTeX; a wrong number is named at its line, a Q of the
//! student's own is followed, and cells read as the notation says.

use cg_assign::Variants;
use cg_assign::cg_shading::report::{Cell, LIGHT_Q, ShadingData, TABLE_IDS, light_table_at};
use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_harness::{StudentNumber, TableVersion};

use super::check::read_for_test as read;
use super::fill::value_text;
use super::{label_matches, row_cells, tag_on};
use crate::fill::{self, Context};
use crate::model::Derived;
use crate::parse::parse_report;
use crate::tables::md_cell;
use crate::template::{self, Format};
use crate::verify::verify;

fn derived(student: &str) -> Derived {
    let n: StudentNumber = student.parse().unwrap();
    let a = Variants::for_student(&n, TableVersion::V1);
    crate::derive::derive(&a, &cg_assign::impls!(cg_exercises)).0
}

fn filled(d: &Derived, lang: Lang, format: Format) -> String {
    template::fill(
        template::template(lang, format),
        &fill::values(d, &Context::default(), lang, format),
    )
    .unwrap()
}

/// `text` with every ✍ (`\yours{}`) cell of the shading tables written with the kit's value, as
/// a student who worked every one out would.
fn by_hand(text: &str, data: &ShadingData, format: Format) -> String {
    let mut table = None;
    let mut out = Vec::new();
    for line in text.lines() {
        if let Some(id) = tag_on(line) {
            table = data.table(&id);
        }
        let (Some(t), Some(cells)) = (table, row_cells(line)) else {
            out.push(line.to_owned());
            continue;
        };
        let Some(row) = t.rows.iter().find(|r| label_matches(&cells[0], &r.label)) else {
            out.push(line.to_owned());
            continue;
        };
        let mut cells = cells;
        for (k, cell) in row.cells.iter().enumerate() {
            if let Cell::Hand(v) = cell {
                cells[k + 1] = match format {
                    Format::Markdown => value_text(v),
                    Format::Latex => format!("${}$", value_text(v)),
                };
            }
        }
        out.push(match format {
            Format::Markdown => {
                let cells: Vec<String> = cells.iter().map(|c| md_cell(c)).collect();
                format!("| {} |", cells.join(" | "))
            }
            Format::Latex => format!("{} \\\\", cells.join(" & ")),
        });
    }
    out.join("\n")
}

#[test]
fn cells_read_a_number_a_tuple_or_the_end_of_a_working() {
    assert_eq!(read("0.577"), Some(vec![0.577]));
    assert_eq!(read("1/√3 = 0.577"), Some(vec![0.577]));
    assert_eq!(read("1/√3 ≈ 0.577"), Some(vec![0.577]));
    assert_eq!(read("$\\cos 15^\\circ \\approx 0.966$"), Some(vec![0.966]));
    assert_eq!(read("34.40°"), Some(vec![34.4]));
    assert_eq!(read("(0.1, -0.2, 0.3)"), Some(vec![0.1, -0.2, 0.3]));
    assert_eq!(read("$(0.100, −0.200, 0.300)$"), Some(vec![0.1, -0.2, 0.3]));
    assert_eq!(read("(a, b) = { 1, 2, 3 }"), Some(vec![1.0, 2.0, 3.0]));
    for skipped_or_bad in ["✍", "—", "None", "\\yours{}", "0.5 (cos 60°)", "1e-3"] {
        assert_eq!(read(skipped_or_bad), None, "{skipped_or_bad}");
    }
}

#[test]
fn the_stubs_fill_every_table_and_a_report_worked_by_hand_checks_clean() {
    for student in ["12345678", "20250003"] {
        let d = derived(student);
        let data = d.s.as_ref().expect("the kit's values derive without the student's code");
        for lang in [Lang::Ja, Lang::En] {
            for format in [Format::Markdown, Format::Latex] {
                let text = filled(&d, lang, format);
                let (parsed, problems) = parse_report(&text);
                assert!(problems.is_empty(), "{student} {lang} {format:?}: {problems:?}");
                let ids: Vec<&str> = parsed.tables.iter().map(|t| t.id.as_str()).collect();
                assert_eq!(ids, TABLE_IDS, "{student} {lang} {format:?}");
                for (t, kit) in parsed.tables.iter().zip(data.tables()) {
                    // The header and every row of the kit's, in order.
                    assert_eq!(t.rows.len(), kit.rows.len() + 1, "{} {format:?}", t.id);
                    for (w, k) in t.rows[1..].iter().zip(&kit.rows) {
                        assert!(label_matches(&w.label, &k.label), "{w:?} {k:?}");
                    }
                }
                // Untouched: only the points P and Q are numbers (the student's cells say
                // "not yet"); nothing is wrong.
                let v = verify(&parsed, &d);
                assert!(v.findings.is_empty(), "{student} {lang} {format:?}: {:#?}", v.findings);
                assert_eq!(v.checked, 6, "{student} {lang} {format:?}");
                // Worked by hand: every ✍ checked, nothing wrong.
                let worked = by_hand(&text, data, format);
                let (parsed, problems) = parse_report(&worked);
                assert!(problems.is_empty(), "{problems:?}");
                let v = verify(&parsed, &d);
                assert!(v.findings.is_empty(), "{student} {lang} {format:?}: {:#?}", v.findings);
                let hand: usize = data
                    .tables()
                    .iter()
                    .flat_map(|t| &t.rows)
                    .flat_map(|r| &r.cells)
                    .map(|c| match c {
                        Cell::Hand(v) => read(&value_text(v)).map_or(0, |n| n.len()),
                        _ => 0,
                    })
                    .sum();
                assert!(hand > 80, "{hand}");
                assert_eq!(v.checked, 6 + hand, "{student} {lang} {format:?}");
            }
        }
    }
}

#[test]
fn on_the_stubs_each_reason_a_table_is_not_derived_is_noted_once() {
    let d = derived("12345678");
    let data = d.s.as_ref().unwrap();
    let section: String = crate::shading::values(data, Lang::En, Format::Markdown)
        .into_iter()
        .map(|(_, v)| v)
        .collect::<Vec<_>>()
        .join("\n");
    let notes: Vec<&str> = section
        .lines()
        .filter_map(|l| l.strip_prefix("> (not derived yet: "))
        .map(|l| l.trim_end_matches(')'))
        .collect();
    assert!(notes.len() >= 3, "{section}");
    let mut reasons: Vec<&str> = notes
        .iter()
        .filter(|n| **n != "as for the table above")
        .flat_map(|n| n.split("; "))
        .collect();
    let all = reasons.len();
    reasons.sort_unstable();
    reasons.dedup();
    assert_eq!(reasons.len(), all, "a reason noted twice: {notes:#?}");
    assert!(notes.contains(&"as for the table above"), "{notes:#?}");
}

#[test]
fn a_wrong_number_is_named_with_its_line_item_and_derived_value() {
    let d = derived("12345678");
    let data = d.s.as_ref().unwrap();
    for lang in [Lang::Ja, Lang::En] {
        let worked = by_hand(&filled(&d, lang, Format::Markdown), data, Format::Markdown);
        // The spot factor at α = 15° (cos² 15° = 0.933 for this student) written as 0.966, the
        // cosine itself: a mistake a student makes.
        let lines: Vec<&str> = worked.lines().collect();
        let at = lines.iter().position(|l| l.starts_with("| α = 15° |")).unwrap();
        let cells = row_cells(lines[at]).unwrap();
        assert_eq!(cells[1..3], ["0.966", "0.933"], "{}", lines[at]);
        let wrong =
            worked.replacen("| α = 15° | 0.966 | 0.933 |", "| α = 15° | 0.966 | 0.966 |", 1);
        let (parsed, _) = parse_report(&wrong);
        let v = verify(&parsed, &d);
        assert_eq!(v.findings.len(), 1, "{:#?}", v.findings);
        let f = &v.findings[0];
        assert_eq!((f.line, f.item.as_str()), (at + 1, "s.spot α = 15° (column 3)"));
        assert_eq!((f.written.as_str(), f.derived.as_str()), ("0.966", "0.933"));
        assert_eq!(f.tolerance.map(|t| (t * 1e3).round()), Some(1.0));
        let m = f.message(Lang::Ja);
        assert!(m.contains(&format!("{} 行目", at + 1)) && m.contains("（3 列目）"), "{m}");
        // A cell that does not read as a number is named too; one with no digits is not checked.
        let odd = worked
            .replacen("| α = 15° | 0.966 | 0.933 |", "| α = 15° | cos 15° | … |", 1)
            .replacen("| d = 5 | 0.571 |", "| d = 5 | 1/1.75 (≈ 0.571) |", 1);
        let (parsed, _) = parse_report(&odd);
        let v = verify(&parsed, &d);
        let items: Vec<&str> = v.findings.iter().map(|f| f.item.as_str()).collect();
        assert_eq!(items, ["s.attenuation d = 5 (column 2)", "s.spot α = 15° (column 2)"]);
    }
}

/// A row deleted from a shading table, or a table cut short by a blank line, is a mistake at
/// the table (its cells went unchecked without a word), as in a3's periods table.
#[test]
fn a_row_missing_from_a_shading_table_is_a_mistake() {
    let d = derived("12345678");
    let data = d.s.as_ref().unwrap();
    let worked = by_hand(&filled(&d, Lang::En, Format::Markdown), data, Format::Markdown);
    let row = worked.lines().find(|l| l.starts_with("| α = 15° |")).unwrap().to_owned();
    let deleted = worked.replacen(&format!("{row}\n"), "", 1);
    let (parsed, _) = parse_report(&deleted);
    let v = verify(&parsed, &d);
    assert_eq!(v.findings.len(), 1, "{:#?}", v.findings);
    assert!(v.findings[0].item.starts_with("s.spot"), "{:#?}", v.findings);
    assert!(v.findings[0].why.en.contains("the table has no row `α = 15°`"), "{:#?}", v.findings);
    let blank = worked.replacen(&format!("{row}\n"), &format!("\n{row}\n"), 1);
    let (parsed, _) = parse_report(&blank);
    let v = verify(&parsed, &d);
    assert!(!v.findings.is_empty(), "a table cut short by a blank line");
}

/// `NaN`, `inf` and `∞` have no digits, and were skipped like `✍` (the count of checked numbers
/// just dropped, exit 0): they are written values that are no finite number, a mistake.
#[test]
fn a_value_that_is_no_finite_number_is_a_mistake() {
    let d = derived("12345678");
    let data = d.s.as_ref().unwrap();
    let worked = by_hand(&filled(&d, Lang::En, Format::Markdown), data, Format::Markdown);
    let at = |text: &str, start: &str| {
        text.lines().position(|l| l.starts_with(start)).map(|k| k + 1).unwrap()
    };
    let cell_of =
        |text: &str, start: &str| row_cells(text.lines().nth(at(text, start) - 1).unwrap());
    for (start, k, to) in [
        ("| d = 1 |", 1, "NaN"),
        ("| d = 1 |", 1, "inf"),
        ("| d = 1 |", 1, "∞"),
        ("| d = 1 |", 1, "1/0 = ∞"),
        ("| d = 1 |", 1, "-Infinity"),
        ("| N |", 2, "(NaN, NaN, NaN)"),
        ("| N |", 2, "(NaN, 1, 0)"),
        ("| N·L |", 2, "NaN"),
    ] {
        let line = at(&worked, start);
        let mut cells = cell_of(&worked, start).unwrap();
        cells[k] = to.to_owned();
        let mut lines: Vec<String> = worked.lines().map(str::to_owned).collect();
        let cells: Vec<String> = cells.iter().map(|c| c.replace('|', "\\|")).collect();
        lines[line - 1] = format!("| {} |", cells.join(" | "));
        let (parsed, problems) = parse_report(&lines.join("\n"));
        assert!(problems.is_empty(), "{problems:?}");
        let v = verify(&parsed, &d);
        assert_eq!(v.findings.len(), 1, "{to}: {:#?}", v.findings);
        let f = &v.findings[0];
        assert_eq!(f.line, line, "{to}");
        assert!(f.why.en.contains("not a finite number"), "{to}: {f:?}");
        assert!(f.why.ja.contains("有限の数ではありません"), "{to}: {f:?}");
    }
    assert_eq!(read("NaN"), None);
    assert_eq!(read("information"), None, "a word is no value");
}

#[test]
fn a_point_q_of_the_students_own_is_followed_and_must_lie_on_the_sphere() {
    let d = derived("12345678");
    let data = d.s.as_ref().unwrap();
    let text = by_hand(&filled(&d, Lang::En, Format::Markdown), data, Format::Markdown);
    let q_line = text.lines().find(|l| l.starts_with("| Q |")).unwrap().to_owned();
    let kit_q = row_cells(&q_line).unwrap()[2].clone();
    // The student's own Q, on the sphere and in the highlight; the table worked at it.
    let own = Vec3::new(0.3, 0.43, 0.851);
    let own_text = "(0.300, 0.430, 0.851)";
    let mut theirs = data.clone();
    theirs.light_q = light_table_at(&data.setup, LIGHT_Q, own);
    let start = text.find("<!-- cg: s.light.q -->").unwrap();
    let end = start + text[start..].find("<!-- cg: s.attenuation -->").unwrap();
    let section = text[start..end].replace(&kit_q, own_text);
    let own_report = format!("{}{}{}", &text[..start], refill(&section, &theirs), &text[end..]);
    let (parsed, problems) = parse_report(&own_report);
    assert!(problems.is_empty(), "{problems:?}");
    let v = verify(&parsed, &d);
    assert!(v.findings.is_empty(), "{:#?}", v.findings);
    assert!(v.notes.iter().all(|n| !n.en.contains("highlight")), "{:?}", v.notes);
    // The kit's numbers at its own Q are wrong at the student's Q: the check follows the Q
    // written, not the kit's.
    let mixed = text.replacen(&kit_q, own_text, 1);
    let (parsed, _) = parse_report(&mixed);
    let v = verify(&parsed, &d);
    assert!(v.findings.iter().any(|f| f.item.starts_with("s.light.q L")), "{:#?}", v.findings);
    // A Q off the sphere is named; one out of the highlight is a note.
    let off = own_report.replacen(own_text, "(0.600, 0.860, 1.702)", 1);
    let (parsed, _) = parse_report(&off);
    let v = verify(&parsed, &d);
    assert!(v.findings.iter().any(|f| f.item == "s.light.q Q (column 3)"), "{:#?}", v.findings);
    let short = own_report.replacen(own_text, "(0.300, 0.430)", 1);
    let (parsed, _) = parse_report(&short);
    let v = verify(&parsed, &d);
    assert!(v.findings.iter().any(|f| f.item == "s.light.q Q (column 3)"), "{:#?}", v.findings);
    let dark = own_report.replacen(own_text, "(0.000, -1.000, 0.000)", 1);
    let (parsed, _) = parse_report(&dark);
    let v = verify(&parsed, &d);
    assert!(v.notes.iter().any(|n| n.en.contains("not in the highlight")), "{:?}", v.notes);
    // A Q of length 0 is named with the point it is checked at, not "Q/|Q|".
    let zero = own_report.replacen(own_text, "(0.000, 0.000, 0.000)", 1);
    let (parsed, _) = parse_report(&zero);
    let v = verify(&parsed, &d);
    let f = v.findings.iter().find(|f| f.item == "s.light.q Q (column 3)").expect("named");
    assert!(f.why.en.contains("(0, 1, 0)") && !f.why.en.contains("Q/|Q|"), "{}", f.why.en);
    // A Q whose length overflows f32 still has its direction: named off the sphere with its
    // length, and checked at Q/|Q| (1e20 was called a Q of length 0; 1e39 was replaced by the
    // kit's Q without a word).
    for far in
        ["(100000000000000000000, 0, 0)", "(100000000000000000000000000000000000000000, 0, 0)"]
    {
        let far_report = own_report.replacen(own_text, far, 1);
        let (parsed, _) = parse_report(&far_report);
        let v = verify(&parsed, &d);
        let f = v.findings.iter().find(|f| f.item == "s.light.q Q (column 3)").expect(far);
        assert!(f.why.en.contains("Q/|Q|") && !f.why.en.contains("length 0"), "{}", f.why.en);
    }
}

/// The light table of `section` (Markdown, its tag first) with the by-hand cells written from
/// `data`'s table at the student's Q.
fn refill(section: &str, data: &ShadingData) -> String {
    let mut out = String::new();
    for line in section.lines() {
        let rewritten = match row_cells(line) {
            Some(cells) if cells.len() == 4 => {
                match data.light_q.rows.iter().find(|r| label_matches(&cells[0], &r.label)) {
                    Some(row) => {
                        let mut cells = cells;
                        if let Cell::Hand(v) = &row.cells[1] {
                            cells[2] = value_text(v);
                        }
                        let cells: Vec<String> = cells.iter().map(|c| md_cell(c)).collect();
                        format!("| {} |", cells.join(" | "))
                    }
                    None => line.to_owned(),
                }
            }
            _ => line.to_owned(),
        };
        out.push_str(&rewritten);
        out.push('\n');
    }
    out
}

#[test]
fn without_shading_data_the_tables_are_a_note_and_a_lone_tag_a_problem() {
    let d = derived("12345678");
    let text = filled(&d, Lang::En, Format::Markdown);
    let (parsed, _) = parse_report(&text);
    let v = verify(&parsed, &Derived::default());
    assert!(v.findings.is_empty());
    assert!(v.notes.iter().any(|n| n.en.contains("no shading data")), "{:?}", v.notes);
    let (parsed, problems) = parse_report("<!-- cg: s.spot -->\n\nno table here\n\n# next\n");
    assert!(parsed.tables[0].rows.is_empty());
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert_eq!(problems[0].line, 1);
    assert!(problems[0].message(Lang::En).contains("the table after the tag `s.spot`"));
    // The tag of a table is not a matrix tag: no "pmatrix expected" problem.
    let (_, problems) = parse_report("<!-- cg: s.attenuation -->\n| d = 1 | 0.909 | — |\n");
    assert!(problems.is_empty(), "{problems:?}");
}

#[test]
fn edited_tables_never_panic_and_every_finding_names_its_line() {
    let d = derived("20250003");
    let data = d.s.as_ref().unwrap();
    let mut seed: u64 = 0x5eed_5ade;
    let mut next = |n: usize| {
        seed = seed.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 33) as usize) % n.max(1)
    };
    const SIGNIFICANT: [char; 22] = [
        '|', '&', '\\', '$', '(', ')', ',', '.', '=', '≈', '-', '0', '5', '9', ' ', '\n', '✍', '°',
        '{', '}', '<', '%',
    ];
    for format in [Format::Markdown, Format::Latex] {
        let text = by_hand(&filled(&d, Lang::Ja, format), data, format);
        let tag = text.find("cg: s.light.p").unwrap();
        let start = text[..tag].rfind('\n').map_or(0, |k| k + 1);
        let section: Vec<char> = text[start..].chars().collect();
        for _ in 0..300 {
            let mut chars = section.clone();
            for _ in 0..1 + next(12) {
                let at = next(chars.len());
                match next(4) {
                    0 => chars[at] = SIGNIFICANT[next(SIGNIFICANT.len())],
                    1 => {
                        chars.remove(at);
                    }
                    2 => chars.insert(at, chars[at]),
                    _ => chars.insert(at, SIGNIFICANT[next(SIGNIFICANT.len())]),
                }
            }
            let edited: String = chars.into_iter().collect();
            let (parsed, problems) = parse_report(&edited);
            let lines = edited.lines().count();
            assert!(problems.iter().all(|p| (1..=lines).contains(&p.line)), "{problems:?}");
            let v = verify(&parsed, &d);
            for f in &v.findings {
                assert!((1..=lines).contains(&f.line), "{f:?}");
                assert!(!f.message(Lang::Ja).is_empty() && !f.message(Lang::En).is_empty());
            }
        }
    }
}

/// What a student's editor and keyboard write is read as the template writes it: full-width
/// digits (`０.９３３`), `≒` before the value, `N・L` (what Shift_JIS keeps of `N·L`) and `15度`
/// as labels; and what cannot be checked is said: a row with a column taken out (which moved
/// every value after it under another heading) is a finding, in Japanese with Japanese words.
#[test]
fn students_ways_of_writing_are_read_and_a_missing_column_is_a_finding() {
    let d = derived("12345678");
    let data = d.s.as_ref().unwrap();
    let worked = by_hand(&filled(&d, Lang::Ja, Format::Markdown), data, Format::Markdown);
    let (parsed, _) = parse_report(&worked);
    let clean = verify(&parsed, &d);
    assert!(clean.findings.is_empty(), "{:#?}", clean.findings);
    let checked = clean.checked;
    let spot = "| α = 15° | 0.966 | 0.933 |";
    assert!(worked.contains(spot), "{worked}");
    // Right values in other forms: still clean, and every number still checked.
    for (from, to) in [
        (spot, "| α = 15度 | ０.９６６ | 0.966² ≒ 0.933 |"),
        (spot, "| $\\alpha = 15^\\circ$ | 0.966 | ０．９３３ |"),
    ] {
        let (parsed, _) = parse_report(&worked.replacen(from, to, 1));
        let v = verify(&parsed, &d);
        assert!(v.findings.is_empty(), "{to}: {:#?}", v.findings);
        assert_eq!(v.checked, checked, "{to}");
    }
    // Wrong values in those forms are found.
    for to in ["| α = 15度 | 0.966 | ０.９６６ |", "| α = 15° | 0.966 | 1/1.03 ≒ 0.966 |"]
    {
        let (parsed, _) = parse_report(&worked.replacen(spot, to, 1));
        let v = verify(&parsed, &d);
        assert_eq!(v.findings.len(), 1, "{to}: {:#?}", v.findings);
        let m = v.findings[0].message(Lang::Ja);
        assert!(m.contains("値は 0.966") && !m.contains("value"), "{m}");
    }
    // N・L is the row N·L: a wrong value there is found, not a note.
    let nl = worked.lines().find(|l| l.starts_with("| N·L |")).expect("an N·L row").to_owned();
    let cells = row_cells(&nl).unwrap();
    let wrong_nl = format!("| N・L | {} |", vec!["0.123"; cells.len() - 1].join(" | "));
    let (parsed, _) = parse_report(&worked.replacen(&nl, &wrong_nl, 1));
    let v = verify(&parsed, &d);
    assert!(!v.findings.is_empty() && v.findings.iter().all(|f| f.item.contains("N")), "{v:#?}");
    // A column taken out of a row: one finding for the row, which says why.
    let short = "| α = 15° | 0.933 |";
    let (parsed, _) = parse_report(&worked.replacen(spot, short, 1));
    let v = verify(&parsed, &d);
    assert_eq!(v.findings.len(), 1, "{:#?}", v.findings);
    let m = v.findings[0].message(Lang::Ja);
    assert!(m.contains("3 列ですが、表は 4 列です"), "{m}");
    // The slots of values hold the cells as written and the kit's row, not the two counts.
    assert!(v.findings[0].written.starts_with("0.933 | "), "{:#?}", v.findings[0]);
    assert_eq!(v.findings[0].derived.split(" | ").count(), 3, "{:#?}", v.findings[0]);
    assert!(v.findings[0].derived.contains("0.966"), "{:#?}", v.findings[0]);
    // A row the table does not have is a note whose list of rows is in the reader's language.
    let extra = format!("{nl}\n| 合計 | 0.5 |");
    let (parsed, _) = parse_report(&worked.replacen(&nl, &extra, 1));
    let v = verify(&parsed, &d);
    let note = v.notes.iter().find(|n| n.ja.contains("合計")).expect("a note on the row");
    assert!(note.ja.contains("環境光") && !note.ja.contains("ambient"), "{}", note.ja);
    assert!(note.en.contains("ambient"), "{}", note.en);
}

/// Labels as a Shift_JIS round trip or a Japanese IME leaves them: `−x 1` comes back as `－x 1`
/// (U+FF0D), and `θ₂` (which Shift_JIS cannot keep) is written `θ2`. Each was reported as a
/// missing row (a false mistake) or as a row the table does not have.
#[test]
fn labels_read_after_a_shift_jis_round_trip() {
    let minus = cg_harness::Text::new("−x 1", "−x 1");
    let theta = cg_harness::Text::new("θ₂", "θ₂");
    for written in ["−x 1", "－x 1", "-x 1", "‐x 1", "–x 1", "—x 1", "―x 1", "－ｘ　１", "－Ｘ 1"]
    {
        assert!(label_matches(written, &minus), "{written}");
    }
    for written in ["θ₂", "θ2", "$θ2$", "θ²", "θ２"] {
        assert!(label_matches(written, &theta), "{written}");
    }
    assert!(!label_matches("θ1", &theta) && !label_matches("θ₁", &theta));
    assert!(!label_matches("x 1", &minus) && !label_matches("－ｙ　１", &minus));
}

/// Labels as a lossy Shift_JIS save leaves them: an editor's `?` for `·` and for `₁`, iconv's
/// `.` for `·`. Each was a false mistake ("the table has no row `N·L`") and a note on a row the
/// table does not have; `θ?` names no row when the table has both `θ₁` and `θ₂`.
#[test]
fn labels_read_after_a_lossy_shift_jis_save_when_they_name_one_row() {
    use super::{kit_row_for, written_row_for};
    use cg_assign::cg_shading::report::Row;
    let row = |l: &str| Row { label: cg_harness::Text::new(l, l), cells: Vec::new() };
    let rows = [row("N·L"), row("R·V"), row("θ₁"), row("θ₂"), row("η·sin θ₁")];
    let named = |w: &str| kit_row_for(w, &[], &rows).map(|r| r.label.en.clone());
    assert_eq!(named("N?L").as_deref(), Some("N·L"));
    assert_eq!(named("N.L").as_deref(), Some("N·L"));
    assert_eq!(named("R?V").as_deref(), Some("R·V"));
    assert_eq!(named("η?sin θ?").as_deref(), Some("η·sin θ₁"));
    // Exact first: `θ1` is θ₁; `θ?` could be either.
    assert_eq!(named("θ1").as_deref(), Some("θ₁"));
    assert_eq!(named("θ?"), None);
    assert_eq!(named("X?Y"), None);
    // The written row of a kit row, the same way.
    let written = [
        super::ParsedRow { line: 3, label: "N?L".into(), cells: Vec::new() },
        super::ParsedRow { line: 4, label: "θ?".into(), cells: Vec::new() },
    ];
    assert_eq!(written_row_for(&written, &rows[0], &rows).map(|r| r.line), Some(3));
    assert!(written_row_for(&written, &rows[2], &rows).is_none());
}

/// A report saved as Shift_JIS by an editor that writes `?` for what Shift_JIS cannot hold (`₁`,
/// `₂`, `·`): every label still names its row — `θ?` is `θ₂` because `θc` is written too — so
/// the check is the UTF-8 report's (it gave a false mistake, "the table has no row `θ₂`", and
/// exit 1). Where a `?` label could still be two rows (`θc` lost as well), the note says which
/// and to save as UTF-8, and the row said missing points at it.
#[test]
fn labels_saved_lossily_name_their_rows_and_one_that_could_be_two_says_so() {
    let d = derived("12345678");
    let data = d.s.as_ref().unwrap();
    for lang in [Lang::Ja, Lang::En] {
        let worked = by_hand(&filled(&d, lang, Format::Markdown), data, Format::Markdown);
        let (parsed, _) = parse_report(&worked);
        let clean = verify(&parsed, &d);
        assert!(clean.findings.is_empty(), "{:#?}", clean.findings);
        let lossy = worked.replace(['₁', '₂', '·'], "?");
        assert!(lossy.contains("| θ? |") && lossy.contains("| θc |"), "{lossy}");
        let (parsed, _) = parse_report(&lossy);
        let v = verify(&parsed, &d);
        assert!(v.findings.is_empty(), "{lang}: {:#?}", v.findings);
        assert_eq!(v.checked, clean.checked, "{lang}");
        assert!(!v.notes.iter().any(|n| n.en.contains('?')), "{lang}: {:#?}", v.notes);

        // θc lost too: `θ?` twice, each could be θc or θ₂.
        let row = lossy.lines().find(|l| l.starts_with("| θc |")).expect("a θc row").to_owned();
        let line = lossy.lines().position(|l| l == row).unwrap() + 1;
        let both = lossy.replacen(&row, &row.replacen("θc", "θ?", 1), 1);
        let (parsed, _) = parse_report(&both);
        let v = verify(&parsed, &d);
        let note = v.notes.iter().find(|n| n.en.contains("`θ?`")).expect("a note on θ?");
        assert!(
            note.en.starts_with(&format!(
                "line {line}: the row `θ?` of table s.refraction could be θc or θ₂"
            )) && note.en.ends_with("save the report as UTF-8"),
            "{note:?}"
        );
        assert!(note.ja.contains("θc・θ₂ のどれか") && note.ja.contains("UTF-8"), "{note:?}");
        let missing = v.findings.iter().find(|f| f.item == "s.refraction θc").expect("θc missing");
        assert!(
            missing.why.en.contains(&format!(
                "(the row `θ?` at line {line} may be it: save the report as UTF-8)"
            )),
            "{missing:?}"
        );
        assert!(missing.why.ja.contains(&format!("{line} 行目の `θ?` がこの行かもしれません")));
    }
}
