//! How a long grading run goes, for a front end to show ([`crate::grade_with`]): `cg grade`
//! draws a progress bar from these on a terminal (building, N of M graded, time left) and
//! prints its plain lines for logs.

use cg_core::lang::t;
use serde_json::Value;

use crate::{Graded, Text};

/// One step of a grading run, in the order they come.
#[derive(Clone, Copy, Debug)]
pub enum Event<'a> {
    /// The kit and the submissions are being read and hashed.
    Reading,
    /// An entry whose result was kept (same hash: [`Graded::skipped`]) or just graded. Kept
    /// entries come before [`Event::Start`], graded ones after.
    Graded(&'a Graded),
    /// Everything is read: `entries` in all, `kept` of them already graded.
    Start {
        /// The entries of the run.
        entries: usize,
        /// Those whose result was kept.
        kept: usize,
    },
    /// The kit's handout is being built (slot 0: the whole kit's first build) and copied to
    /// the other slots; only when something is left to grade.
    Building,
    /// The slots are ready: grading starts.
    Built,
}

/// A graded submission's report in short, for its progress line ([`Graded::report`]) and the
/// run's last lines ([`reports_line`]); summary.md says the rest.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Brief {
    /// The submission holds no report.
    None,
    /// A report found but not read (too big, not text): its notes say why.
    NotRead,
    /// A report checked.
    Checked {
        /// The numbers checked.
        numbers: u64,
        /// The mistakes (rows not read among them).
        mistakes: u64,
        /// The parts not checked (their functions did not give the data).
        not_checked: u64,
        /// Every part checked, every number right, no table missing, the student's own
        /// (the result's `cg.report.whole`).
        whole: bool,
    },
}

impl Brief {
    /// The brief of a result's report ([`crate::report::to_json`]); `None` for a result not
    /// graded (refused, or grading failed: its line says why).
    #[must_use]
    pub fn of(result: &Value) -> Option<Brief> {
        result.get("max_score")?;
        let report = &result["cg"]["report"];
        let count = |key: &str| report[key].as_u64().unwrap_or(0);
        Some(match report["checked"].as_u64() {
            _ if !report.is_object() => Brief::None,
            None => Brief::NotRead,
            Some(numbers) => Brief::Checked {
                numbers,
                mistakes: count("mistakes"),
                not_checked: report["not_checked"].as_array().map_or(0, |a| a.len() as u64),
                whole: report["whole"] == true,
            },
        })
    }

    /// `report: 1806 numbers, 4 mistakes`, `report not read`, `no report`.
    #[must_use]
    pub fn text(self) -> Text {
        match self {
            Brief::None => t("レポートなし", "no report"),
            Brief::NotRead => t("レポートは読めませんでした", "report not read"),
            Brief::Checked { numbers, mistakes, not_checked, .. } => {
                let mut said = Text::new(
                    format!("レポート: 数値 {numbers} 個、誤り {mistakes} 件"),
                    format!(
                        "report: {numbers} {}, {mistakes} {}",
                        if numbers == 1 { "number" } else { "numbers" },
                        if mistakes == 1 { "mistake" } else { "mistakes" }
                    ),
                );
                if not_checked > 0 {
                    said.ja.push_str(&format!("、確かめられなかった部分 {not_checked} つ"));
                    said.en.push_str(&format!(", {not_checked} not checked"));
                }
                said
            }
        }
    }
}

/// The run's line on the reports: how many of the graded submissions' reports were read, and
/// how many of those are whole (every part checked, every number right), with where the rest is
/// said. `None` when no graded submission holds one.
#[must_use]
pub fn reports_line(graded: &[Graded]) -> Option<Text> {
    let briefs: Vec<Brief> = graded.iter().filter_map(|g| g.report).collect();
    if briefs.iter().all(|b| *b == Brief::None) {
        return None;
    }
    let read = briefs.iter().filter(|b| matches!(b, Brief::Checked { .. })).count();
    let whole = briefs.iter().filter(|b| matches!(b, Brief::Checked { whole: true, .. })).count();
    Some(Text::new(
        format!(
            "レポート: {read} 件を読み、{whole} 件はすべて確かめられて誤りなし（summary.md の「レポートの数値」）"
        ),
        format!(
            "reports: {read} read, {whole} whole (every part checked, every number right; summary.md's \"Reports' numbers\")"
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::lang::Lang;
    use serde_json::json;

    fn graded(result: &Value) -> Graded {
        Graded {
            entry: "x.zip".to_owned(),
            name: "x".to_owned(),
            score: 0.0,
            max_score: result["max_score"].as_f64(),
            skipped: false,
            flag: None,
            problem: None,
            report: Brief::of(result),
        }
    }

    /// Each graded result's report in short, and the run's count of those read and whole; a
    /// result not graded says nothing of its report (its line says why it was not graded).
    #[test]
    fn the_reports_are_said_in_short_and_counted() {
        let report = |checked: u64, mistakes: u64, parts: usize, whole: bool| {
            json!({"max_score": 5.0, "cg": {"report": {
                "checked": checked, "mistakes": mistakes, "whole": whole,
                "not_checked": vec!["a1.t1"; parts],
            }}})
        };
        let results = [
            report(1806, 0, 0, true),
            report(1806, 4, 0, false),
            report(1800, 0, 2, false),
            json!({"max_score": 5.0, "cg": {"report": {"notes_grading": ["report.md is too big"]}}}),
            json!({"max_score": 5.0, "cg": {"report": null}}),
            json!({"cg": {"error": "the build ran over its limit", "report": {"notes_grading": ["x"]}}}),
        ];
        let class: Vec<Graded> = results.iter().map(graded).collect();
        let said: Vec<Option<String>> =
            class.iter().map(|g| g.report.map(|b| b.text().en)).collect();
        assert_eq!(
            said,
            [
                Some("report: 1806 numbers, 0 mistakes".to_owned()),
                Some("report: 1806 numbers, 4 mistakes".to_owned()),
                Some("report: 1800 numbers, 0 mistakes, 2 not checked".to_owned()),
                Some("report not read".to_owned()),
                Some("no report".to_owned()),
                None,
            ]
        );
        let line = reports_line(&class).expect("reports");
        assert_eq!(
            line.en,
            "reports: 3 read, 1 whole (every part checked, every number right; summary.md's \"Reports' numbers\")"
        );
        assert!(line.get(Lang::Ja).starts_with("レポート: 3 件を読み、1 件は"), "{}", line.ja);
        // None holds one: no line.
        assert_eq!(reports_line(&class[4..]), None);
    }
}
