//! What `report check` found, and how it is said.

use std::fmt::Write as _;
use std::path::PathBuf;

use cg_core::lang::{Lang, t};
use cg_core::text::Encoding;
use cg_harness::Text;

use super::read_notes;
use crate::derive::Missing;
use crate::parse::ParseProblem;
use crate::verify::Verification;

/// What `check` found.
#[derive(Clone, Debug)]
pub struct CheckOutcome {
    /// The report checked (or the data file, checked on its own).
    pub report: PathBuf,
    /// Lines that tried to be rows and did not parse.
    pub problems: Vec<ParseProblem>,
    /// The numbers that do not follow from the data.
    pub verification: Verification,
    /// What could not be derived (those tables were not checked).
    pub missing: Vec<Missing>,
    /// The files read (the report, the data file), each with the encoding it was read in.
    pub read: Vec<(PathBuf, Encoding)>,
    /// The rows, matrices, tables and formulas read in the notation
    /// ([`crate::parse::ParsedReport::items`]): with none checked, whether the report had none to read
    /// or its parts could not be derived.
    pub items: usize,
}

impl CheckOutcome {
    /// Whether the report is free of mistakes the checker can see, and it saw something: a
    /// report in which no number was checked (no table in a form the checker reads, or an
    /// empty file) is not a success.
    #[must_use]
    pub fn ok(&self) -> bool {
        self.problems.is_empty()
            && self.verification.findings.is_empty()
            && self.verification.checked > 0
    }

    /// For the terminal.
    #[must_use]
    pub fn render(&self, lang: Lang) -> String {
        let mut out = format!(
            "{} {}\n",
            t("レポートの確認:", "checking the report").get(lang),
            self.report.display()
        );
        out.push_str(&read_notes(&self.read, "  · ", lang));
        for p in &self.problems {
            let _ = writeln!(out, "  ✗ {}", p.message(lang));
        }
        for f in &self.verification.findings {
            let _ = writeln!(out, "  ✗ {}", f.message(lang));
        }
        if self.verification.findings.iter().any(|f| f.tolerance.is_some()) {
            let a = crate::verify::accepted();
            let a = Text::new(format!("（{}）", a.ja), format!("({})", a.en));
            let _ = writeln!(out, "    {}", a.get(lang));
        }
        // What was not checked and why (a file that does not compile) before the notes that
        // follow from it ("there is no polygon data").
        for m in &self.missing {
            let _ = writeln!(
                out,
                "  · {} {}",
                t("確かめられません:", "not checked:").get(lang),
                m.message(lang)
            );
        }
        for n in &self.verification.notes {
            let _ = writeln!(out, "  · {}", n.get(lang));
        }
        let _ = writeln!(out, "{}", self.summary().get(lang));
        out
    }

    /// The mistakes found against the numbers checked, and the parts not checked: the last line
    /// of [`CheckOutcome::render`] (and `cg grade`'s line of a report).
    #[must_use]
    pub fn summary(&self) -> Text {
        let wrong = self.mistakes();
        let checked = self.verification.checked;
        let parts = self.missing.len();
        // The parts not checked, said after the count of mistakes too (it was left out there).
        let unchecked = Text::new(
            format!("{parts} 個の部分は確かめられていません（上の「確かめられません」）。"),
            format!(
                "{parts} {} not checked (\"not checked\" above).",
                if parts == 1 { "part was" } else { "parts were" }
            ),
        );
        let items = self.items;
        if wrong == 0 && checked == 0 && items > 0 {
            // Rows were read, but nothing to compare them with: their parts not derived (a
            // function that does not return), or rows of nothing the data has (the notes).
            if parts > 0 {
                Text::new(
                    format!(
                        "確かめられた数値は 1 つもありません。行・行列・表を {items} 個読みましたが、その部分のデータが導出できませんでした。{}",
                        unchecked.ja
                    ),
                    format!(
                        "no number was checked: {items} rows, matrices or tables were read, but their parts could not be derived. {}",
                        unchecked.en
                    ),
                )
            } else {
                Text::new(
                    format!(
                        "確かめられた数値は 1 つもありません。行・行列・表を {items} 個読みましたが、データにあるものはありませんでした（上の注を見てください）。"
                    ),
                    format!(
                        "no number was checked: {items} rows, matrices or tables were read, but none is of the data (see the notes above)."
                    ),
                )
            }
        } else if wrong == 0 && checked == 0 {
            let none = Text::new(
                "確かめられた数値は 1 つもありません。キットが読む書き方の表（`V0 (0.0, 1.0, 0.0)` の頂点の行、`F0 { V0, V3, V1 } { 0.0, 0.49, 0.87 }` の面の行、`<!-- cg: s.light.p -->` のようなタグのついた表）が見つかりませんでした。`cargo run --release -- report fill` が書くひな形の書き方に合わせてください",
                "no number was checked: the report has no table in a form the checker reads (vertex rows `V0 (0.0, 1.0, 0.0)`, face rows `F0 { V0, V3, V1 } { 0.0, 0.49, 0.87 }`, tables after a tag such as `<!-- cg: s.light.p -->`); write them as `cargo run --release -- report fill` writes them in the template",
            );
            if parts == 0 {
                none
            } else {
                Text::new(
                    format!("{}。{}", none.ja, unchecked.ja),
                    format!("{}. {}", none.en, unchecked.en),
                )
            }
        } else if wrong == 0 && parts > 0 {
            // Not a mistake (a part not done yet is no mistake), but not the whole report either.
            Text::new(
                format!(
                    "数値 {checked} 個を確かめ、データから導かれない数値はありませんでした。ただし {}",
                    unchecked.ja
                ),
                format!(
                    "{checked} numbers checked; every one follows from the data. {}",
                    unchecked.en
                ),
            )
        } else if wrong == 0 {
            Text::new(
                format!("数値 {checked} 個を確かめ、データから導かれない数値はありませんでした。"),
                format!("{checked} numbers checked; every one follows from the data."),
            )
        } else if parts > 0 {
            Text::new(
                format!(
                    "数値 {checked} 個を確かめ、{wrong} 件の誤りがありました。ほかに {}",
                    unchecked.ja
                ),
                format!(
                    "{checked} numbers checked; {wrong} {}. {}",
                    if wrong == 1 { "mistake" } else { "mistakes" },
                    unchecked.en
                ),
            )
        } else {
            Text::new(
                format!("数値 {checked} 個を確かめ、{wrong} 件の誤りがありました。"),
                format!(
                    "{checked} numbers checked; {wrong} {}.",
                    if wrong == 1 { "mistake" } else { "mistakes" }
                ),
            )
        }
    }

    /// The lines that do not read and the numbers that do not follow, together.
    #[must_use]
    pub fn mistakes(&self) -> usize {
        self.problems.len() + self.verification.findings.len()
    }

    /// For tools.
    #[must_use]
    pub fn to_json(&self, lang: Lang) -> serde_json::Value {
        serde_json::json!({
            "report": self.report.display().to_string(),
            "ok": self.ok(),
            "checked": self.verification.checked,
            "mistakes": self.mistakes(),
            "summary": self.summary().get(lang),
            "problems": self.problems.iter().map(|p| serde_json::json!({
                "line": p.line, "found": p.found, "message": p.message(lang),
            })).collect::<Vec<_>>(),
            "findings": self.verification.findings.iter().map(|f| serde_json::json!({
                "line": f.line, "item": f.item, "written": f.written, "derived": f.derived,
                "tolerance": f.tolerance, "message": f.message(lang),
            })).collect::<Vec<_>>(),
            "notes": self.verification.notes.iter().map(|n| n.get(lang)).collect::<Vec<_>>(),
            "not_checked": self.missing.iter().map(|m| m.message(lang)).collect::<Vec<_>>(),
            "read": self.read.iter().map(|(file, encoding)| serde_json::json!({
                "file": file.display().to_string(), "encoding": encoding.name(),
            })).collect::<Vec<_>>(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::verify::Finding;

    /// What a written number must be is said once under the findings that compare numbers,
    /// not at the end of each (it ended every ✗ line); not at all when none compares numbers.
    #[test]
    fn what_is_accepted_is_said_once() {
        let finding = |line: usize, tolerance: Option<f64>| Finding {
            line,
            item: format!("V{line}"),
            written: "(1.0, 0.0, 0.0)".to_owned(),
            derived: "(0.0, 0.0, 0.0)".to_owned(),
            tolerance,
            why: Text::new(
                "x は 1.0 ですが導出値は 0.0（差 1）",
                "x is 1.0 but follows as 0.0 (off by 1)",
            ),
        };
        let outcome = |findings: Vec<Finding>| CheckOutcome {
            report: PathBuf::from("report.md"),
            problems: Vec::new(),
            verification: Verification { findings, checked: 9, notes: Vec::new() },
            missing: Vec::new(),
            read: Vec::new(),
            items: 3,
        };
        let two = outcome(vec![finding(3, Some(0.001)), finding(4, Some(0.001))]);
        let en = two.render(Lang::En);
        assert_eq!(en.matches("correct to its last written digit").count(), 1, "{en}");
        assert!(en.contains("\n    (a number is accepted when it is correct to its last written digit (rounded or cut off))\n"), "{en}");
        let ja = two.render(Lang::Ja);
        assert_eq!(ja.matches("四捨五入でも切り捨てでも").count(), 1, "{ja}");
        assert!(ja.contains("    （数値は、書いた最後の桁まで正しければ"), "{ja}");
        let order = outcome(vec![finding(3, None)]).render(Lang::En);
        assert!(!order.contains("last written digit"), "{order}");
    }
}
