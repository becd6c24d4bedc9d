//! The report inside a submission ([`crate::inside`]), checked as `cg report check` checks it
//! on the student's machine: the data derived from the submission's own functions, called in its
//! worker in the sandbox after its checks, and the report's numbers parsed and verified against
//! that data here, in the grader's process ([`cg_report::parse`], [`cg_report::verify`]).
//!
//! Not scored: the result (`cg.report`), the output, the feedback, Moodle's comment, class.csv
//! and summary.md say what was found, for the instructor to weigh.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::time::Duration;

use cg_assign::{Derived, Impls, Variants};
use cg_core::lang::{Lang, t};
use cg_report::app::CheckOutcome;
use serde_json::{Value, json};

use crate::Text;
use crate::inside::Found;
use crate::result::{md_code, md_words};

/// The largest report read: the student's own `cg report check`'s limit, so that grading reads
/// every report the student saw checked.
pub const MAX_BYTES: u64 = cg_report::app::MAX_REPORT_BYTES;

/// What grading found of the report in a submission.
#[derive(Clone, Debug, Default)]
pub struct Facts {
    /// The report's check, when one was found and read.
    pub checked: Option<CheckOutcome>,
    /// What the instructor and the student should know besides the check: a report found but
    /// not read (too big, not text) or not checked (the functions could not run), the other
    /// reports found and not read, a PDF where no text report is, the template not filled, a
    /// report filled for another student number.
    pub notes: Vec<Text>,
    /// The student number the report says it is for, when it is not the graded student's (its
    /// template line `- Student number: …`, `\author{学生番号 …}`): a flag.
    pub claims: Option<String>,
    /// The time its check took (deriving the data in the worker, and verifying).
    pub time: Option<Duration>,
}

/// What the report's text says of itself for `student`: the number it was filled for when
/// that is another ([`Facts::claims`]), and a note when it is the template not filled (its
/// `{{student}}` still there).
pub(crate) fn about(text: &str, student: &str) -> (Option<String>, Option<Text>) {
    if text.contains("{{student}}") {
        let note = t(
            "レポートは cg report fill を実行する前のひな形のままです。`cargo run --release -- report fill` で表・行列・図を埋めてから書いてください",
            "The report is the template before cg report fill: run `cargo run --release -- report fill` to fill in its tables, matrices and figures, then write in it.",
        );
        return (None, Some(note));
    }
    // "Student ID" is the label of the templates before 2026-11-29; reports filled from them
    // are still read.
    let line = text.lines().take(60).find(|l| {
        l.contains("Student number") || l.contains("Student ID") || l.contains("学生番号")
    });
    let number = line.and_then(crate::inside::eight_digits).filter(|n| *n != student);
    let note = number.map(|n| {
        Text::new(
            format!("レポートの学生番号は {n} で、採点した学生（{student}）のものではありません。"),
            format!(
                "The report says it is for student {n}, not for the student graded ({student})."
            ),
        )
    });
    (number.map(str::to_owned), note)
}

/// Checks `found` against the data `assignment`'s functions give in `worker` (each call within
/// `per_call`; after one runs out of time the others fail at once, as in `cg report check`),
/// with what its text says of itself ([`about`]) added to `notes`. Nothing is derived for a
/// report without one number in the notation (`report.md` still the template, say).
pub(crate) fn check(
    assignment: &Variants,
    (found, notes): (&Found, &[Text]),
    worker: cg_worker::Worker,
    per_call: Duration,
) -> Facts {
    let begun = std::time::Instant::now();
    let (claims, note) = about(&found.text, assignment.student.as_str());
    let (parsed, problems) = cg_report::parse::parse_report(&found.text);
    let (derived, missing) = if parsed.is_empty() {
        (Derived::default(), Vec::new())
    } else {
        cg_worker::proxy::with_worker_until_timeout(worker, per_call, || {
            assignment.derive(&Impls::worker())
        })
        .0
    };
    let verification = cg_report::verify::verify_with(&parsed, &derived, Some(assignment));
    let path = PathBuf::from(&found.path);
    let outcome = CheckOutcome {
        report: path.clone(),
        problems,
        verification,
        missing,
        read: vec![(path, found.encoding)],
        items: parsed.items(),
    };
    Facts {
        checked: Some(outcome),
        notes: notes.iter().cloned().chain(note).collect(),
        claims,
        time: Some(begun.elapsed()),
    }
}

/// The report of a submission whose grading stopped before the checks (its build failed or ran
/// over the limit) into `facts`: the report found is said not checked, and why (nothing said
/// it, and the result, the feedback and class.csv read as if the submission held none), before
/// the notes on it. Nothing for a report already checked or said (the worker died:
/// `run_checks` says so), a submission graded, or one refused (its reader looks for no report).
pub(crate) fn not_graded(
    facts: &mut crate::result::Facts,
    (found, notes): &(Option<Found>, Vec<Text>),
) {
    let said = facts.report.checked.is_some() || !facts.report.notes.is_empty();
    if said || facts.fatal.is_none() {
        return;
    }
    let mut all = Vec::new();
    if let Some(Found { path, .. }) = found {
        all.push(Text::new(
            format!("{path} は採点できなかったので確かめていません"),
            format!("{path} was not checked: grading failed"),
        ));
    }
    all.extend(notes.iter().cloned());
    facts.report.notes = all;
}

/// The result's `cg.report`: `null` when the submission holds no report, else the check
/// ([`CheckOutcome::to_json`], with `text`, its whole account for the feedback) or the notes of
/// a report not read. Never scored (`"scored": false`).
#[must_use]
pub fn to_json(facts: &Facts, lang: Lang) -> Value {
    let notes: Vec<&str> = facts.notes.iter().map(|n| n.get(lang)).collect();
    match &facts.checked {
        Some(outcome) => {
            let mut v = outcome.to_json(lang);
            v["text"] = json!(outcome.render(lang));
            v["scored"] = json!(false);
            v["notes_grading"] = json!(notes);
            v["claims"] = json!(facts.claims);
            // Every part checked, every number right, no table missing, the student's own: what
            // the summary counts (`ok` alone leaves out the parts not derived and the tables
            // missing). The grader's other notes (another file beside it) are the student's to
            // read, not the report's fault.
            v["whole"] = json!(
                outcome.ok()
                    && outcome.missing.is_empty()
                    && outcome.verification.notes.is_empty()
                    && facts.claims.is_none()
            );
            v
        }
        None if notes.is_empty() => Value::Null,
        None => json!({ "scored": false, "notes_grading": notes, "claims": facts.claims }),
    }
}

/// The line of the result's output: `report (not scored): report/report.md: 42 numbers
/// checked; …`, or why it was not read; `None` without a report.
#[must_use]
pub fn line(report: &Value, lang: Lang) -> Option<String> {
    let head = t("レポート（点数には入りません）", "Report (not scored)");
    let head = head.get(lang);
    if let Some(summary) = report["summary"].as_str() {
        let file = report["report"].as_str().unwrap_or("");
        return Some(format!("{head}: {file}: {summary}"));
    }
    let notes: Vec<&str> =
        report["notes_grading"].as_array()?.iter().filter_map(Value::as_str).collect();
    (!notes.is_empty()).then(|| format!("{head}: {}", notes.join(" ")))
}

/// Where the report is looked for, said where none was found.
fn where_looked() -> Text {
    t(
        "提出物にレポート（report/report.md か report/report.tex）はありませんでした。レポートの数値も確かめてほしいときは、report フォルダを exercises フォルダと一緒に zip にするか、report.md（または report.tex）を zip と並べて提出してください。",
        "The submission holds no report (report/report.md or report/report.tex). To have its numbers checked too, zip the report folder together with the exercises folder, or upload report.md (or report.tex) beside the zip.",
    )
}

/// The feedback's section on the report: the account `cg report check` prints, or why it was
/// not read, or where a report would be found.
#[must_use]
pub fn feedback_section(report: &Value, lang: Lang) -> String {
    let mut md = format!(
        "## {}\n\n",
        t("レポートの数値（点数には入りません）", "The report's numbers (not scored)").get(lang)
    );
    let notes: Vec<&str> = report["notes_grading"]
        .as_array()
        .map(|n| n.iter().filter_map(Value::as_str).collect())
        .unwrap_or_default();
    for n in &notes {
        let _ = writeln!(md, "- {}", md_words(n));
    }
    if !notes.is_empty() {
        md.push('\n');
    }
    if let Some(text) = report["text"].as_str() {
        md.push_str(&crate::result::code_block(text));
        md.push_str("\n\n");
        // The file checked, as the student's kit has it (`report check` alone reads report.md).
        let file = report["report"].as_str().unwrap_or("");
        let name = file.rsplit('/').next().unwrap_or(file);
        let local = if name.eq_ignore_ascii_case("report.tex") {
            "report check report/report.tex"
        } else {
            "report check"
        };
        let _ = writeln!(
            md,
            "{} `cargo run --release -- {local}`\n",
            t("手元でも同じように確かめられます:", "The same check on your own machine:").get(lang)
        );
    } else if notes.is_empty() {
        let _ = writeln!(md, "{}\n", where_looked().get(lang));
    }
    md
}

/// The class.csv columns of a result's report ([`csv_cells`]).
pub const CSV_COLUMNS: [&str; 4] =
    ["report", "report_checked", "report_mistakes", "report_not_checked"];

/// The class.csv cells of a result's report: its file (or, for one found but not read, why),
/// the numbers checked, the mistakes and the parts not checked (all empty without a report).
#[must_use]
pub fn csv_cells(result: &Value) -> [String; 4] {
    let r = &result["cg"]["report"];
    let count = |k: &str| r[k].as_u64().map(|n| n.to_string()).unwrap_or_default();
    let file = r["report"]
        .as_str()
        .map_or_else(|| r["notes_grading"][0].as_str().unwrap_or("").to_owned(), str::to_owned);
    let not_checked = r["not_checked"].as_array().map(|a| a.len().to_string()).unwrap_or_default();
    [file, count("checked"), count("mistakes"), not_checked]
}

/// The summary's section on the reports: how many submissions held one, how many of those were
/// whole (every part checked, every number right, no table missing, the student's own), the others with what is
/// wrong or missing (most mistakes first; one not read with why), and the items the class got
/// wrong most often (the rows the checker could not read as one item; at a tie, in
/// natural order: `F2` before `F10`). Empty when no graded result has one.
#[must_use]
pub fn summary_section(results: &[Value], lang: Lang) -> String {
    let graded: Vec<&Value> = results.iter().filter(|r| r.get("max_score").is_some()).collect();
    let with: Vec<&Value> =
        graded.iter().copied().filter(|r| r["cg"]["report"].is_object()).collect();
    if with.is_empty() {
        return String::new();
    }
    let read: Vec<&Value> =
        with.iter().copied().filter(|r| r["cg"]["report"]["checked"].is_u64()).collect();
    let whole = |r: &Value| r["cg"]["report"]["whole"] == true;
    let clean = read.iter().filter(|r| whole(r)).count();
    let mut out = format!(
        "\n## {}\n\n",
        t("レポートの数値（点数には入りません）", "Reports' numbers (not scored)").get(lang)
    );
    let (n, of, r) = (with.len(), graded.len(), read.len());
    let _ = writeln!(
        out,
        "{}\n",
        Text::new(
            format!(
                "採点した {of} 件のうち {n} 件にレポートがあり、{r} 件を読みました。そのうち {clean} 件は、すべての部分を確かめられ、数値がすべてデータから導かれ、足りない表もありませんでした。"
            ),
            format!(
                "{n} of the {of} graded submissions hold a report; {r} were read. In {clean}, every part was checked, every number follows from the data and no table is missing."
            ),
        )
        .get(lang)
    );
    // Every report that is not whole, read or not: what its check said, and how many notes.
    let mut wrong: Vec<(u64, String)> = with
        .iter()
        .filter(|r| !whole(r))
        .map(|r| {
            let rep = &r["cg"]["report"];
            let mistakes = rep["mistakes"].as_u64().unwrap_or(0);
            let notes = rep["notes"].as_array().map_or(0, Vec::len)
                + rep["notes_grading"].as_array().map_or(0, Vec::len);
            let said = match rep["summary"].as_str() {
                Some(summary) if notes > 0 => format!(
                    "{summary} {}",
                    Text::new(
                        format!("（注 {notes} 件）"),
                        format!("({notes} {})", if notes == 1 { "note" } else { "notes" })
                    )
                    .get(lang)
                ),
                Some(summary) => summary.to_owned(),
                // Not read: why.
                None => rep["notes_grading"][0].as_str().unwrap_or("").to_owned(),
            };
            let line = format!(
                "- {} ({}): {}",
                md_code(r["cg"]["submission"].as_str().unwrap_or(""), lang),
                md_code(r["cg"]["student"].as_str().unwrap_or("?"), lang),
                md_words(&said)
            );
            (mistakes, line)
        })
        .collect();
    wrong.sort_by(|a, b| b.0.cmp(&a.0).then_with(|| a.1.cmp(&b.1)));
    if !wrong.is_empty() {
        let _ = writeln!(
            out,
            "{}\n\n{}\n",
            t(
                "誤り・確かめられなかった部分・注のあるレポート（読めなかったものも）:",
                "Reports with mistakes, parts not checked or notes (and those not read):"
            )
            .get(lang),
            wrong.into_iter().map(|(_, l)| l).collect::<Vec<_>>().join("\n")
        );
    }
    // The items most often wrong, as the findings name them (`F2 normal`, `a2.view.start (row
    // 1, column 4)`), each student counted once per item; the rows the checker could not read
    // (mistakes too) as one item.
    let mut items: BTreeMap<String, usize> = BTreeMap::new();
    let mut unreadable = 0;
    for r in &read {
        let rep = &r["cg"]["report"];
        let mut seen = std::collections::BTreeSet::new();
        for f in rep["findings"].as_array().map(Vec::as_slice).unwrap_or_default() {
            if let Some(item) = f["item"].as_str() {
                seen.insert(item.to_owned());
            }
        }
        for item in seen {
            *items.entry(item).or_default() += 1;
        }
        if rep["problems"].as_array().is_some_and(|p| !p.is_empty()) {
            unreadable += 1;
        }
    }
    // Each item's cell: a finding's item as code; the rows not read in words, after the
    // findings of as many students.
    let mut items: Vec<(String, usize, bool)> = items
        .into_iter()
        .map(|(item, count)| (item, count, false))
        .chain((unreadable > 0).then(|| (String::new(), unreadable, true)))
        .collect();
    items.sort_by(|a, b| b.1.cmp(&a.1).then(a.2.cmp(&b.2)).then_with(|| natural_cmp(&a.0, &b.0)));
    if !items.is_empty() {
        let _ = writeln!(
            out,
            "| {} | {} |\n|---|---:|",
            t("誤りの多い項目", "item most often wrong").get(lang),
            t("人数", "students").get(lang)
        );
        for (item, count, rows) in items.iter().take(MOST_COMMON) {
            let cell = if *rows {
                t("読めなかった行", "a row the checker could not read").get(lang).to_owned()
            } else {
                md_code(item, lang).replace('|', "\\|")
            };
            let _ = writeln!(out, "| {cell} | {count} |");
        }
        if items.len() > MOST_COMMON {
            let _ = writeln!(
                out,
                "\n{}",
                Text::new(
                    format!("（ほか {} 項目）", items.len() - MOST_COMMON),
                    format!("({} more items)", items.len() - MOST_COMMON),
                )
                .get(lang)
            );
        }
    }
    out
}

/// The summary's note on the files of `--reports` that no graded entry took (a number no one
/// handed in under, a name without a number): empty when there is none.
#[must_use]
pub fn unused_section(names: &[String], lang: Lang) -> String {
    if names.is_empty() {
        return String::new();
    }
    let list: Vec<String> = names.iter().map(|n| format!("- {}", md_code(n, lang))).collect();
    format!(
        "\n## {}\n\n{}\n\n{}\n",
        t("使われなかった --reports のファイル", "Files of --reports not used").get(lang),
        t(
            "ファイル名に採点した学生の番号（8 桁）がないので、どの提出物のレポートとしても確かめていません。",
            "Their names hold no graded student's number (8 digits): they were checked as no one's report.",
        )
        .get(lang),
        list.join("\n")
    )
}

/// The most items the summary's table of reports' mistakes lists.
const MOST_COMMON: usize = 20;

/// `a` and `b` in natural order: runs of digits compared as numbers (`F2` before `F10`,
/// `row 9` before `row 10`), the rest as text.
fn natural_cmp(a: &str, b: &str) -> std::cmp::Ordering {
    use std::cmp::Ordering;
    let (mut a, mut b) = (a, b);
    loop {
        let (Some(x), Some(y)) = (a.chars().next(), b.chars().next()) else {
            return a.len().cmp(&b.len());
        };
        if x.is_ascii_digit() && y.is_ascii_digit() {
            let run = |s: &str| s.find(|c: char| !c.is_ascii_digit()).unwrap_or(s.len());
            let (da, db) = (&a[..run(a)], &b[..run(b)]);
            // Leading zeros aside, the longer run is the larger number; at a tie, the digits.
            let (na, nb) = (da.trim_start_matches('0'), db.trim_start_matches('0'));
            let order =
                na.len().cmp(&nb.len()).then_with(|| na.cmp(nb)).then(da.len().cmp(&db.len()));
            if order != Ordering::Equal {
                return order;
            }
            (a, b) = (&a[da.len()..], &b[db.len()..]);
        } else {
            let order = x.cmp(&y);
            if order != Ordering::Equal {
                return order;
            }
            (a, b) = (&a[x.len_utf8()..], &b[y.len_utf8()..]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A graded result holding `report` (`null`: none).
    fn graded(entry: &str, report: Value) -> Value {
        json!({"score": 1.0, "max_score": 2.0, "cg": {"student": entry, "submission": entry, "report": report}})
    }

    /// A report read: `checked` numbers, a finding per item, `parts` parts not checked.
    fn read(checked: u64, items: &[&str], parts: usize) -> Value {
        let findings: Vec<Value> = items.iter().map(|i| json!({"item": i})).collect();
        let ok = checked > 0 && items.is_empty();
        json!({
            "report": "report/report.md",
            "ok": ok,
            "whole": ok && parts == 0,
            "checked": checked,
            "mistakes": items.len(),
            "summary": format!("{checked} numbers checked; {} mistakes.", items.len()),
            "findings": findings,
            "not_checked": vec!["a1.t1: not written yet"; parts],
            "notes": [],
            "notes_grading": [],
        })
    }

    #[test]
    fn the_summary_counts_the_whole_reports_and_lists_the_others_most_mistakes_first() {
        let class = [
            graded("clean", read(24, &[], 0)),
            graded("one", read(24, &["V1"], 0)),
            graded("three", read(24, &["V1", "F0 normal", "V1"], 0)),
            graded("nothing", read(0, &[], 0)),
            // Every number right, but a part not checked (its function loops): not whole.
            graded("part", read(24, &[], 1)),
            graded("unread", json!({"scored": false, "notes_grading": ["report.md is too big"]})),
            graded("none", Value::Null),
            // Refused: not among the graded, whatever it holds.
            json!({"score": 0.0, "cg": {"submission": "refused", "report": read(24, &[], 0)}}),
        ];
        let md = summary_section(&class, Lang::En);
        assert!(
            md.contains(
                "6 of the 7 graded submissions hold a report; 5 were read. In 1, every part was checked"
            ),
            "{md}"
        );
        // Most mistakes first; the whole one not listed; the rest listed, the unread with why.
        let listed: Vec<&str> = md.lines().filter(|l| l.starts_with("- ")).collect();
        assert_eq!(listed.len(), 5, "{md}");
        assert!(listed[0].starts_with("- `three`") && listed[1].starts_with("- `one`"), "{md}");
        let rest = &listed[2..];
        assert!(rest.iter().any(|l| l.starts_with("- `nothing`")), "{md}");
        assert!(rest.iter().any(|l| l.starts_with("- `part`")), "{md}");
        assert!(rest.iter().any(|l| l.contains("`report.md is too big`")), "{md}");
        // Each student counted once per item.
        assert!(md.contains("| `V1` | 2 |\n| `F0 normal` | 1 |"), "{md}");
        assert!(summary_section(&class[6..], Lang::Ja).is_empty());
        let ja = summary_section(&class, Lang::Ja);
        assert!(ja.contains("採点した 7 件のうち 6 件にレポートがあり"), "{ja}");
    }

    #[test]
    fn a_report_not_read_is_said_with_why_and_none_is_null() {
        let notes = Facts { notes: vec![t("大きすぎます", "too big")], ..Facts::default() };
        let v = to_json(&notes, Lang::En);
        assert_eq!(line(&v, Lang::En).as_deref(), Some("Report (not scored): too big"));
        // class.csv says why in the report's column (it was as empty as for no report).
        let cells = csv_cells(&graded("x", v));
        assert_eq!(cells, ["too big".to_owned(), String::new(), String::new(), String::new()]);
        let none = to_json(&Facts::default(), Lang::En);
        assert!(none.is_null() && line(&none, Lang::En).is_none());
        let cells = csv_cells(&graded("x", read(24, &["V1"], 2)));
        assert_eq!(cells, ["report/report.md".to_owned(), "24".into(), "1".into(), "2".into()]);
    }

    /// The rows the checker could not read are mistakes: the table of items counts them (each
    /// student once), as one item in words; items of as many students are in natural order.
    #[test]
    fn the_table_of_items_counts_the_rows_not_read_and_orders_numbers_as_numbers() {
        let with_problems = |items: &[&str], problems: usize| {
            let mut r = read(24, items, 0);
            let rows: Vec<Value> = (0..problems)
                .map(|i| json!({"line": i + 3, "found": "F3 { V0 }", "message": "?"}))
                .collect();
            r["problems"] = json!(rows);
            r["mistakes"] = json!(items.len() + problems);
            r["ok"] = json!(false);
            r["whole"] = json!(false);
            r
        };
        let class = [
            graded("a", with_problems(&["F10 normal", "F2 normal"], 2)),
            graded("b", with_problems(&["F10 normal", "F2 normal"], 1)),
            graded("c", with_problems(&["F9 normal"], 0)),
        ];
        let md = summary_section(&class, Lang::En);
        assert!(
            md.contains(
                "| `F2 normal` | 2 |\n| `F10 normal` | 2 |\n| a row the checker could not read | 2 |\n| `F9 normal` | 1 |"
            ),
            "{md}"
        );
        let ja = summary_section(&class, Lang::Ja);
        assert!(ja.contains("| 読めなかった行 | 2 |"), "{ja}");
        use std::cmp::Ordering::{Equal, Greater, Less};
        assert_eq!(natural_cmp("F2", "F10"), Less);
        assert_eq!(natural_cmp("a2.view (row 10, column 4)", "a2.view (row 9, column 4)"), Greater);
        assert_eq!(natural_cmp("V01", "V1"), Greater);
        assert_eq!(natural_cmp("V1", "V1"), Equal);
        assert_eq!(natural_cmp("V1", "V1 x"), Less);
        assert_eq!(natural_cmp("s.refraction θ₂", "s.refraction θ₁"), Greater);
    }

    /// A report filled for another number is said (a copy's plainest sign), the template not
    /// filled is told what to run, and a report of the student's own number says nothing.
    #[test]
    fn what_a_report_says_of_itself_is_noted() {
        let other = "# Report\n\n- Student number: 20260011\n";
        let (claims, note) = about(other, "20260010");
        assert_eq!(claims.as_deref(), Some("20260011"));
        assert!(note.unwrap().en.contains("for student 20260011, not for the student graded"));
        let latex = "\\author{学生番号 20260011\\quad 氏名}";
        assert_eq!(about(latex, "20260010").0.as_deref(), Some("20260011"));
        assert_eq!(about(other, "20260011"), (None, None));
        // A report filled from the template before "Student number" was its label.
        assert_eq!(about("- Student ID: 20260011\n", "20260010").0.as_deref(), Some("20260011"));
        let (claims, note) = about("- Student number: {{student}}\n", "20260010");
        assert!(claims.is_none());
        assert!(note.unwrap().ja.contains("cargo run --release -- report fill"));
    }
}
