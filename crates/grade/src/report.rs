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

/// What grading found of the report in a submission.
#[derive(Clone, Debug, Default)]
pub struct Facts {
    /// The report's check, when one was found and read.
    pub checked: Option<CheckOutcome>,
    /// A report found but not read (too big, not text), or not checked (the functions could not
    /// run): why.
    pub notes: Vec<Text>,
    /// The time its check took (deriving the data in the worker, and verifying).
    pub time: Option<Duration>,
}

/// Checks `found` against the data `assignment`'s functions give in `worker` (each call within
/// `per_call`; after one runs out of time the others fail at once, as in `cg report check`).
/// Nothing is derived for a report without one number in the notation (`report.md` still the
/// template, say).
pub(crate) fn check(
    assignment: &Variants,
    found: &Found,
    worker: cg_worker::Worker,
    per_call: Duration,
) -> (CheckOutcome, cg_worker::Worker) {
    let (parsed, problems) = cg_report::parse::parse_report(&found.text);
    let ((derived, missing), worker) = if parsed.is_empty() {
        ((Derived::default(), Vec::new()), worker)
    } else {
        cg_worker::proxy::with_worker_until_timeout(worker, per_call, || {
            assignment.derive(&Impls::worker())
        })
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
    (outcome, worker)
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
            v
        }
        None if notes.is_empty() => Value::Null,
        None => json!({ "scored": false, "notes_grading": notes }),
    }
}

/// The line of the result's output: `report (not scored): report/report.md: 42 numbers
/// checked; …`, or why it was not read; `None` without a report.
#[must_use]
pub fn line(report: &Value, lang: Lang) -> Option<String> {
    let head = t("レポート（点数には入りません）", "report (not scored)");
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
        "提出物にレポート（report/report.md か report/report.tex）はありませんでした。レポートの数値も確かめてほしいときは、report フォルダを exercises フォルダと一緒に zip にするか、report.md（または report.tex）を zip と並べて提出してください",
        "the submission holds no report (report/report.md or report/report.tex). To have its numbers checked too, zip the report folder together with the exercises folder, or upload report.md (or report.tex) beside the zip",
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
    if let Some(text) = report["text"].as_str() {
        md.push_str(&crate::result::code_block(text));
        md.push_str("\n\n");
        let _ = writeln!(
            md,
            "{}\n",
            t(
                "手元でも同じように確かめられます: cargo run --release -- report check",
                "The same check on your own machine: cargo run --release -- report check"
            )
            .get(lang)
        );
    } else if let Some(notes) = report["notes_grading"].as_array() {
        for n in notes.iter().filter_map(Value::as_str) {
            let _ = writeln!(md, "- {}", md_words(n));
        }
        md.push('\n');
    } else {
        let _ = writeln!(md, "{}\n", where_looked().get(lang));
    }
    md
}

/// The class.csv cells of a result's report: its file, the numbers checked and the mistakes
/// (all empty without a report read).
#[must_use]
pub fn csv_cells(result: &Value) -> [String; 3] {
    let r = &result["cg"]["report"];
    let count = |k: &str| r[k].as_u64().map(|n| n.to_string()).unwrap_or_default();
    [r["report"].as_str().unwrap_or("").to_owned(), count("checked"), count("mistakes")]
}

/// The summary's section on the reports: how many submissions held one, how many of those
/// had every number checked follow from the data, the students with mistakes (most first),
/// and the items the class got wrong most often. Empty when no graded result has one.
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
    let clean = read.iter().filter(|r| r["cg"]["report"]["ok"] == true).count();
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
                "採点した {of} 件のうち {n} 件にレポートがあり、{r} 件を読んで、{clean} 件は確かめた数値がすべてデータから導かれました（数値が 1 つもないものは含みません）。"
            ),
            format!(
                "{n} of the {of} graded submissions hold a report; {r} were read, and in {clean} every number checked follows from the data (one with no number checked is not counted)."
            ),
        )
        .get(lang)
    );
    let mut wrong: Vec<(u64, String)> = read
        .iter()
        .filter(|r| r["cg"]["report"]["ok"] != true)
        .map(|r| {
            let rep = &r["cg"]["report"];
            let mistakes = rep["mistakes"].as_u64().unwrap_or(0);
            let line = format!(
                "- {} ({}): {}",
                md_code(r["cg"]["submission"].as_str().unwrap_or(""), lang),
                md_code(r["cg"]["student"].as_str().unwrap_or("?"), lang),
                md_words(rep["summary"].as_str().unwrap_or(""))
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
                "誤りのある（または確かめられなかった）レポート:",
                "Reports with mistakes (or nothing checked):"
            )
            .get(lang),
            wrong.into_iter().map(|(_, l)| l).collect::<Vec<_>>().join("\n")
        );
    }
    // The items most often wrong, as the findings name them (`F2 normal`, `a2.view.start (row
    // 1, column 4)`), each student counted once per item.
    let mut items: BTreeMap<String, usize> = BTreeMap::new();
    for r in &read {
        let mut seen = std::collections::BTreeSet::new();
        for f in r["cg"]["report"]["findings"].as_array().map(Vec::as_slice).unwrap_or_default() {
            if let Some(item) = f["item"].as_str() {
                seen.insert(item.to_owned());
            }
        }
        for item in seen {
            *items.entry(item).or_default() += 1;
        }
    }
    let mut items: Vec<(String, usize)> = items.into_iter().collect();
    items.sort_by(|a, b| b.1.cmp(&a.1).then_with(|| a.0.cmp(&b.0)));
    if !items.is_empty() {
        let _ = writeln!(
            out,
            "| {} | {} |\n|---|---:|",
            t("誤りの多い項目", "item most often wrong").get(lang),
            t("人数", "students").get(lang)
        );
        for (item, count) in items.iter().take(MOST_COMMON) {
            let _ = writeln!(out, "| {} | {count} |", md_code(item, lang).replace('|', "\\|"));
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A graded result holding `report` (`null`: none).
    fn graded(entry: &str, report: Value) -> Value {
        json!({"score": 1.0, "max_score": 2.0, "cg": {"student": entry, "submission": entry, "report": report}})
    }

    fn read(checked: u64, items: &[&str]) -> Value {
        let findings: Vec<Value> = items.iter().map(|i| json!({"item": i})).collect();
        json!({
            "report": "report/report.md",
            "ok": checked > 0 && items.is_empty(),
            "checked": checked,
            "mistakes": items.len(),
            "summary": format!("{checked} numbers checked; {} mistakes.", items.len()),
            "findings": findings,
        })
    }

    #[test]
    fn the_summary_counts_the_reports_and_lists_the_mistakes_most_first() {
        let class = [
            graded("clean", read(24, &[])),
            graded("one", read(24, &["V1"])),
            graded("three", read(24, &["V1", "F0 normal", "V1"])),
            graded("nothing", read(0, &[])),
            graded("unread", json!({"scored": false, "notes_grading": ["report.md is too big"]})),
            graded("none", Value::Null),
            // Refused: not among the graded, whatever it holds.
            json!({"score": 0.0, "cg": {"submission": "refused", "report": read(24, &[])}}),
        ];
        let md = summary_section(&class, Lang::En);
        assert!(
            md.contains(
                "5 of the 6 graded submissions hold a report; 4 were read, and in 1 every number checked follows"
            ),
            "{md}"
        );
        // Most mistakes first; the clean one not listed; nothing checked listed.
        let listed: Vec<&str> = md.lines().filter(|l| l.starts_with("- ")).collect();
        assert_eq!(listed.len(), 3, "{md}");
        assert!(listed[0].starts_with("- `three`") && listed[1].starts_with("- `one`"), "{md}");
        assert!(listed[2].starts_with("- `nothing`"), "{md}");
        // Each student counted once per item.
        assert!(md.contains("| `V1` | 2 |\n| `F0 normal` | 1 |"), "{md}");
        assert!(summary_section(&class[5..], Lang::Ja).is_empty());
        let ja = summary_section(&class, Lang::Ja);
        assert!(ja.contains("採点した 6 件のうち 5 件にレポートがあり"), "{ja}");
    }

    #[test]
    fn a_report_not_read_is_said_with_why_and_none_is_null() {
        let notes = Facts { notes: vec![t("大きすぎます", "too big")], ..Facts::default() };
        let v = to_json(&notes, Lang::En);
        assert_eq!(line(&v, Lang::En).as_deref(), Some("report (not scored): too big"));
        assert_eq!(csv_cells(&graded("x", v)), [String::new(), String::new(), String::new()]);
        let none = to_json(&Facts::default(), Lang::En);
        assert!(none.is_null() && line(&none, Lang::En).is_none());
        let cells = csv_cells(&graded("x", read(24, &["V1"])));
        assert_eq!(cells, ["report/report.md".to_owned(), "24".into(), "1".into()]);
    }
}
