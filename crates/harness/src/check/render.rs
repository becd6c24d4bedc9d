//! [`Report::render`]: a report as text, each explanation said once.
//!
//! A typo in one face made six dependent checks each repeat the same five lines; a file that
//! did not compile said so under each of its 13 checks, a panic repeated its two lines 14 times,
//! and the stubs said "not done yet" once per check (163 lines for `cg check` on the stubs). Now
//! a check whose explanation was already shown says "（同上）" / "(same as above)" (or names
//! the check it was shown under, when another explanation came between), the not-done checks of
//! a task share one line (39 lines in all on the stubs), and a file that does not compile is one
//! line that lists the checks it stops, with its errors under it. Every check's ID is still
//! shown.

use std::fmt::Write as _;

use cg_core::lang::Lang;

use super::{CheckResult, Failure, Outcome, Report, stub_message};
use crate::text::{Text, t};

/// How many lines of a file's compiler errors `cg check` shows, once per file.
const COMPILE_LINES: usize = 24;

/// How some checks are shown.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Layout {
    /// One check: a line with its mark, ID and title, then its explanation's lines.
    Check,
    /// The checks of a task not done yet, with the same message: one line, the IDs then the
    /// message (no title: the stub's message says what to write).
    NotDone,
    /// The checks a file that does not compile stops: one line for the file that lists them,
    /// then the compiler's errors.
    File,
}

/// Checks shown together, and what explains them.
struct Block<'a> {
    layout: Layout,
    mark: &'static str,
    checks: Vec<&'a CheckResult>,
    /// The explanation's lines in the reader's language, without their indentation (none for a
    /// check that passed).
    detail: Vec<String>,
}

impl Report {
    /// A line per check (✓ pass, ✗ fail, … not done yet, ! panicked, ran out of time, crashed
    /// or did not compile) with, for each problem, what was expected and found, where, the usual
    /// cause and a hint; then a progress summary.
    ///
    /// Each explanation is said once: a check whose explanation is the one shown just above
    /// (the same panic, the same failure, the same stub) says "（同上）" / "(same as above)"
    /// after its title, or "(same as `<check>`)" when another came between; the checks of a task
    /// that are not done yet with the same message share one line, their IDs then the message;
    /// a file that does not compile
    /// is one line listing how many checks, and which, it stops, with the compiler's errors
    /// under it. The counts and [`Report::to_json`] are those of every check.
    #[must_use]
    pub fn render(&self, lang: Lang) -> String {
        let mut out = String::new();
        let width = self.checks.iter().map(|c| c.id.chars().count()).max().unwrap_or(0);
        // Each explanation shown, with the check it was shown under.
        let mut shown: Vec<(&[String], &str)> = Vec::new();
        // The last explanation shown or referred to ("same as above" refers to it).
        let mut above: Option<&[String]> = None;
        let blocks = self.blocks(lang);
        for b in &blocks {
            let first = b.checks.first().map_or("", |c| c.id.as_str());
            let earlier = shown.iter().find(|(d, _)| !b.detail.is_empty() && *d == b.detail);
            let same = earlier.map(|(_, id)| {
                if above == Some(b.detail.as_slice()) {
                    t("（同上）", "(same as above)")
                } else {
                    Text::new(format!("（{id} と同じ）"), format!("(same as {id})"))
                }
            });
            match b.layout {
                Layout::NotDone => {
                    let ids: Vec<&str> = b.checks.iter().map(|c| c.id.as_str()).collect();
                    let said = match &same {
                        Some(same) => Text::new(
                            format!("まだです{}", same.ja),
                            format!("not done yet {}", same.en),
                        )
                        .get(lang)
                        .to_owned(),
                        None => b.detail.join(" "),
                    };
                    let _ = writeln!(out, "  {} {}  {said}", b.mark, ids.join(", "));
                }
                Layout::File => {
                    let mut lines = b.detail.iter();
                    if let Some(head) = lines.next() {
                        let _ = writeln!(out, "  {} {head}", b.mark);
                    }
                    for line in lines {
                        let _ = writeln!(out, "      {line}");
                    }
                }
                Layout::Check => {
                    for c in &b.checks {
                        let title = c.title.get(lang);
                        let _ = write!(out, "  {} {:<width$}  {title}", b.mark, c.id);
                        if let Some(same) = &same {
                            let _ = write!(out, "  {}", same.get(lang));
                        }
                        out.push('\n');
                    }
                    if same.is_none() {
                        for line in &b.detail {
                            let _ = writeln!(out, "      {line}");
                        }
                    }
                }
            }
            if !b.detail.is_empty() {
                if earlier.is_none() {
                    shown.push((&b.detail, first));
                }
                above = Some(&b.detail);
            }
        }
        self.summary(&mut out, lang);
        out
    }

    /// The checks in the order of the report, as they are shown together (see [`Report::render`]).
    fn blocks(&self, lang: Lang) -> Vec<Block<'_>> {
        let mut blocks: Vec<Block<'_>> = Vec::new();
        for c in &self.checks {
            let (layout, mark, detail) = match &c.outcome {
                Outcome::Pass => (Layout::Check, "✓", Vec::new()),
                Outcome::Fail(f) => (Layout::Check, "✗", failure(f, lang)),
                Outcome::NotDone { message } => {
                    let line = format!(
                        "{}: {}",
                        t("まだです", "not done yet").get(lang),
                        stub_message(message, lang)
                    );
                    if let Some(last) = blocks.last_mut()
                        && last.layout == Layout::NotDone
                        && last.checks.iter().all(|l| l.task == c.task)
                        && last.detail == [line.as_str()]
                    {
                        last.checks.push(c);
                        continue;
                    }
                    (Layout::NotDone, "…", vec![line])
                }
                Outcome::DoesNotCompile { module, errors } => {
                    let listed = blocks.iter().any(|b| {
                        b.layout == Layout::File
                            && matches!(&b.checks[0].outcome,
                                Outcome::DoesNotCompile { module: m, .. } if m == module)
                    });
                    if listed {
                        continue;
                    }
                    // Every check this file stops, listed here once.
                    let stopped: Vec<&CheckResult> = self
                        .checks
                        .iter()
                        .filter(|o| {
                            matches!(&o.outcome,
                                Outcome::DoesNotCompile { module: m, .. } if m == module)
                        })
                        .collect();
                    let mut detail = vec![does_not_compile(module, &stopped).get(lang).to_owned()];
                    detail.extend(
                        errors
                            .iter()
                            .flat_map(|e| e.lines())
                            .take(COMPILE_LINES)
                            .map(|line| format!("  | {line}")),
                    );
                    blocks.push(Block { layout: Layout::File, mark: "!", checks: stopped, detail });
                    continue;
                }
                Outcome::Panicked { message, location } => {
                    let mut detail = vec![format!(
                        "{}: {message}",
                        t("プログラムが異常終了しました（panic）", "your code panicked").get(lang)
                    )];
                    if let Some(l) = location {
                        detail.push(format!("{}: {l}", t("場所", "at").get(lang)));
                    }
                    (Layout::Check, "!", detail)
                }
                Outcome::TimedOut { .. } | Outcome::Broken { .. } | Outcome::Crashed { .. } => {
                    let mut detail: Vec<String> =
                        c.outcome.describe().map(|d| d.get(lang).to_owned()).into_iter().collect();
                    if let Outcome::Crashed { stderr, .. } = &c.outcome {
                        let tail: Vec<&str> = stderr.lines().rev().take(5).collect();
                        detail.extend(tail.into_iter().rev().map(|line| format!("  | {line}")));
                    }
                    (Layout::Check, "!", detail)
                }
            };
            blocks.push(Block { layout, mark, checks: vec![c], detail });
        }
        blocks
    }

    /// The last line: the checks that pass, the tasks not done, to fix, the files that do not
    /// compile.
    fn summary(&self, out: &mut String, lang: Lang) {
        let _ = write!(
            out,
            "{}: {}/{} {}",
            t("進み具合", "progress").get(lang),
            self.passed(),
            self.total(),
            t("個のチェックに合格", "checks pass").get(lang)
        );
        let not_done = self.tasks_not_done();
        if !not_done.is_empty() {
            let _ = write!(
                out,
                "; {}: {}",
                t("未完成の課題", "not done yet").get(lang),
                not_done.join(", ")
            );
        }
        let failing = self.tasks_failing();
        if !failing.is_empty() {
            let _ = write!(
                out,
                "; {}: {}",
                t("直すところのある課題", "to fix").get(lang),
                failing.join(", ")
            );
        }
        let broken = self.files_not_compiling();
        if !broken.is_empty() {
            let _ = write!(
                out,
                "; {}: {}",
                t("コンパイルできないファイル", "does not compile").get(lang),
                broken.join(", ")
            );
        }
        out.push('\n');
    }
}

/// A failure's lines: expected, actual, where, the usual cause (unless it says what "actual"
/// says already) and the hint.
fn failure(f: &Failure, lang: Lang) -> Vec<String> {
    let mut lines = vec![
        format!("{}: {}", t("期待する値", "expected").get(lang), f.expected.get(lang)),
        format!("{}: {}", t("実際の値  ", "actual  ").get(lang), f.actual.get(lang)),
    ];
    if let Some(l) = &f.location {
        lines.push(format!("{}: {}", t("場所      ", "where   ").get(lang), l.get(lang)));
    }
    if !f.cause.is_empty() && f.cause.get(lang) != f.actual.get(lang) {
        lines.push(format!(
            "{}: {}",
            t("よくある原因", "usual cause").get(lang),
            f.cause.get(lang)
        ));
    }
    if !f.hint.is_empty() {
        lines.push(format!("{}: {}", t("ヒント", "hint").get(lang), f.hint.get(lang)));
    }
    lines
}

/// The line of a file that does not compile: which, and the checks it stops.
fn does_not_compile(module: &str, stopped: &[&CheckResult]) -> Text {
    let n = stopped.len();
    let ids: Vec<&str> = stopped.iter().map(|c| c.id.as_str()).collect();
    let ids = ids.join(", ");
    let checks = if n == 1 { "1 check".to_owned() } else { format!("{n} checks") };
    Text::new(
        format!(
            "exercises/src/{module}.rs がコンパイルできないため、この課題のチェック {n} 個を実行していません: {ids}"
        ),
        format!(
            "exercises/src/{module}.rs does not compile, so {checks} of this assignment did not run: {ids}"
        ),
    )
}
