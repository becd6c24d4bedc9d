//! The progress of `cg grade` and `cg grade-one`: a plain line per submission (stdout, for
//! logs) and, when stderr is a terminal, an `indicatif` bar under them — building, N of M
//! graded, time left. Not a terminal (a log, a test): the bar hides itself.

use std::io::IsTerminal as _;
use std::time::Duration;

use cg_core::lang::{Lang, Text, t};
use cg_grade::Graded;
use cg_grade::progress::Event;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// The plain line of one submission.
#[must_use]
pub fn line(g: &Graded, lang: Lang) -> String {
    let max = g.max_score.map(|m| format!(" / {m}")).unwrap_or_default();
    let note = if g.skipped { t("（前回の結果）", " (kept)") } else { Text::default() };
    let note = note.get(lang);
    // The report in short (graded entries only): summary.md says the rest.
    let report = g.report.map(|r| format!(" · {}", r.text().get(lang))).unwrap_or_default();
    let flag = g.flag.as_ref().map(|f| format!(" [{}]", f.get(lang))).unwrap_or_default();
    // Not graded: said on the line, which read as a graded 0.
    let flag = match &g.problem {
        Some(why) => format!("{flag} — {}", why.get(lang)),
        None => flag,
    };
    // The entry's name is the student's (a zip's name, a Moodle full name): a control character
    // in it (an escape sequence that would drive the instructor's terminal) is shown as its code.
    let line = format!("{} ({}): {}{max}{note}{report}{flag}", g.name, g.entry, g.score);
    cg_core::quote::visible(&line)
}

/// The lines and the bar.
pub struct Progress {
    bar: ProgressBar,
    lang: Lang,
}

impl Progress {
    /// A bar on stderr when it is a terminal, hidden otherwise.
    #[must_use]
    pub fn new(lang: Lang) -> Progress {
        let target = if std::io::stderr().is_terminal() {
            ProgressDrawTarget::stderr()
        } else {
            ProgressDrawTarget::hidden()
        };
        let bar = ProgressBar::with_draw_target(None, target);
        bar.set_style(spinner());
        Progress { bar, lang }
    }

    /// Shows `event`.
    pub fn event(&self, event: Event<'_>) {
        match event {
            Event::Reading => {
                self.bar.set_message(
                    t("提出物とキットを読んでいます", "reading the submissions and the kit")
                        .get(self.lang)
                        .to_owned(),
                );
                self.bar.enable_steady_tick(Duration::from_millis(200));
            }
            Event::Graded(g) => {
                let text = line(g, self.lang);
                self.bar.suspend(|| println!("{text}"));
                if !g.skipped {
                    self.bar.inc(1);
                }
            }
            Event::Start { entries, kept } => {
                self.style(
                    t(
                        "{spinner} {msg} [{bar:30}] {pos}/{len} 件採点 · {elapsed}",
                        "{spinner} {msg} [{bar:30}] {pos}/{len} graded · {elapsed}",
                    )
                    .get(self.lang),
                );
                self.bar.set_length((entries - kept.min(entries)) as u64);
                self.bar.set_position(0);
                self.bar.set_message("");
            }
            Event::Building => {
                self.bar.set_message(
                    t(
                        "キットをビルドしています（最初の 1 回）",
                        "building the kit (once, the first time)",
                    )
                    .get(self.lang)
                    .to_owned(),
                );
            }
            Event::Built => {
                self.style(
                    t(
                        "{spinner} [{bar:30}] {pos}/{len} 件採点 · 残り {eta} · {elapsed}",
                        "{spinner} [{bar:30}] {pos}/{len} graded · {eta} left · {elapsed}",
                    )
                    .get(self.lang),
                );
                self.bar.set_message("");
                self.bar.reset_eta();
            }
        }
    }

    fn style(&self, template: &str) {
        if let Ok(style) = ProgressStyle::with_template(template) {
            self.bar.set_style(style.progress_chars("=> "));
        }
    }

    /// Takes the bar off the terminal.
    pub fn finish(&self) {
        self.bar.finish_and_clear();
    }
}

fn spinner() -> ProgressStyle {
    ProgressStyle::with_template("{spinner} {msg} · {elapsed}")
        .unwrap_or_else(|_| ProgressStyle::default_spinner())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An entry's name is the student's: an escape sequence in it (here OSC 52, which writes the
    /// instructor's clipboard) reaches the terminal as its code, not as the sequence.
    #[test]
    fn a_control_character_in_an_entry_name_is_shown_as_its_code() {
        let g = Graded {
            entry: "\u{1b}]52;c;ZXZpbA==\u{7}Taro.zip".to_owned(),
            name: "Taro.zip".to_owned(),
            score: 3.0,
            max_score: Some(5.0),
            skipped: false,
            flag: None,
            problem: None,
            report: None,
        };
        let text = line(&g, Lang::En);
        assert!(!text.contains('\u{1b}') && !text.contains('\u{7}'), "{text:?}");
        assert!(text.contains("<U+001B>]52;c;ZXZpbA==<U+0007>Taro.zip"), "{text}");
    }

    /// A refused entry's line says so: it read `_x.zip (x.zip): 0`, a graded 0.
    #[test]
    fn a_refused_entry_says_so_on_its_line() {
        let value = serde_json::json!({
            "score": 0.0,
            "cg": { "refused": "no exercises/ found\nmore", "refused_ja": "exercises/ が見つかりません" },
        });
        let g = Graded {
            entry: "x.zip".to_owned(),
            name: "_x.zip".to_owned(),
            score: 0.0,
            max_score: None,
            skipped: false,
            flag: None,
            problem: cg_grade::result::problem(&value),
            report: None,
        };
        assert_eq!(line(&g, Lang::En), "_x.zip (x.zip): 0 — refused: no exercises/ found");
        assert_eq!(
            line(&g, Lang::Ja),
            "_x.zip (x.zip): 0 — 受け付けられません: exercises/ が見つかりません"
        );
        let graded = Graded { problem: None, ..g };
        assert_eq!(line(&graded, Lang::En), "_x.zip (x.zip): 0");
    }

    /// A graded entry's line says its report in short: the numbers checked and the mistakes,
    /// or that there is none.
    #[test]
    fn a_graded_entrys_line_says_its_report_in_short() {
        let mut result = serde_json::json!({
            "score": 3.0,
            "max_score": 5.0,
            "cg": { "report": { "checked": 1806, "mistakes": 4, "not_checked": [], "whole": false } },
        });
        let g = |result: &serde_json::Value| Graded {
            entry: "x.zip".to_owned(),
            name: "20260001".to_owned(),
            score: 3.0,
            max_score: Some(5.0),
            skipped: false,
            flag: None,
            problem: None,
            report: cg_grade::progress::Brief::of(result),
        };
        assert_eq!(
            line(&g(&result), Lang::En),
            "20260001 (x.zip): 3 / 5 · report: 1806 numbers, 4 mistakes"
        );
        assert_eq!(
            line(&g(&result), Lang::Ja),
            "20260001 (x.zip): 3 / 5 · レポート: 数値 1806 個、誤り 4 件"
        );
        result["cg"]["report"] = serde_json::Value::Null;
        assert_eq!(line(&g(&result), Lang::En), "20260001 (x.zip): 3 / 5 · no report");
    }
}
