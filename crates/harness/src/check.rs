//! Checks that explain themselves: what was expected, what was found, where, the usual cause
//! and a hint — and a runner that never crashes on a student's code.
//!
//! ```
//! use cg_harness::check::{self, Failure};
//! use cg_harness::text::t;
//!
//! let closed = check::run("a1.t2.closed", t("閉じている", "closed"), || {
//!     Err(Failure::new("every edge shared by two faces", "edge V1–V3 in F2 only")
//!         .at("edge V1–V3")
//!         .cause(t("面が足りない", "a face is missing"))
//!         .hint(t("F2 の隣の面を確認", "look at F2's neighbours")))
//! });
//! assert!(!closed.passed());
//! let stub = check::run("a1.t3.normals", t("法線", "normals"), || {
//!     todo!("a1.t3: write the face normals")
//! });
//! assert!(matches!(stub.outcome, check::Outcome::NotDone { .. }));
//! ```

use std::cell::{Cell, RefCell};
use std::fmt::Write as _;
use std::panic::{self, AssertUnwindSafe};
use std::sync::{Mutex, Once};
use std::time::{Duration, Instant};

use cg_core::lang::Lang;
use serde::Serialize;

use crate::text::Text;
use cg_worker::CallError;

/// Why a check failed, in the words a student needs — every part in Japanese and English
/// (numbers and names convert from a plain string, the same in both languages).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Failure {
    /// What the check expected (numbers, a list, a property).
    pub expected: Text,
    /// What it found.
    pub actual: Text,
    /// Where: a vertex `V3`, a face `F2`, an edge `V1–V3`, a time `t = 2.5 s`, a pixel.
    #[serde(rename = "where")]
    pub location: Option<Text>,
    /// What usually causes this.
    pub cause: Text,
    /// What to try.
    pub hint: Text,
}

impl Failure {
    /// A failure with what was expected and what was found.
    #[must_use]
    pub fn new(expected: impl Into<Text>, actual: impl Into<Text>) -> Failure {
        Failure { expected: expected.into(), actual: actual.into(), ..Failure::default() }
    }

    /// Where the problem is.
    #[must_use]
    pub fn at(mut self, location: impl Into<Text>) -> Failure {
        self.location = Some(location.into());
        self
    }

    /// The usual cause.
    #[must_use]
    pub fn cause(mut self, cause: Text) -> Failure {
        self.cause = cause;
        self
    }

    /// A hint.
    #[must_use]
    pub fn hint(mut self, hint: Text) -> Failure {
        self.hint = hint;
        self
    }
}

/// How a check ended.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum Outcome {
    /// It passed.
    Pass,
    /// It ran and found a mistake.
    Fail(Failure),
    /// The code it calls is still a stub (`todo!()` / `unimplemented!()`): not done yet.
    NotDone {
        /// The stub's message, e.g. `a1.t3: write the face normals`.
        message: String,
    },
    /// The student's code panicked (an index out of range, an `unwrap` on `None`, …).
    Panicked {
        /// The panic message.
        message: String,
        /// `file:line:column` of the panic, when known.
        location: Option<String>,
    },
    /// The student's function ran past the check's time limit (an endless loop?); the worker
    /// running it was stopped, and the other checks went on in a fresh one.
    TimedOut {
        /// The check's time limit, in milliseconds.
        limit_ms: u64,
    },
    /// The worker running the student's function ended during the call: an abort, a stack
    /// overflow, the memory limit, an `exit()`; or its reply did not read.
    Crashed {
        /// How it ended, as the system says it (`signal: 6 (SIGABRT)`, `exit status: 0`).
        how: String,
        /// The end of what it wrote on stderr.
        stderr: String,
    },
}

impl Outcome {
    /// The outcome of a call of the student's function that gave no value ([`CallError`]).
    #[must_use]
    pub fn of_call(error: &CallError) -> Outcome {
        match error {
            CallError::Panicked { message, location } => {
                Outcome::of_panic(message.clone(), location.clone())
            }
            CallError::TimedOut(limit) => {
                Outcome::TimedOut { limit_ms: u64::try_from(limit.as_millis()).unwrap_or(u64::MAX) }
            }
            CallError::Crashed { status, stderr } => {
                Outcome::Crashed { how: status.clone(), stderr: stderr.clone() }
            }
            CallError::Broken(why) => Outcome::Crashed { how: why.clone(), stderr: String::new() },
        }
    }

    /// A panic's outcome: [`Outcome::NotDone`] for a stub's `todo!()` or `unimplemented!()`,
    /// [`Outcome::Panicked`] for any other.
    #[must_use]
    pub fn of_panic(message: String, location: Option<String>) -> Outcome {
        if let Some(rest) = message.strip_prefix("not yet implemented") {
            Outcome::NotDone { message: rest.trim_start_matches(':').trim().to_owned() }
        } else if let Some(rest) = message.strip_prefix("not implemented") {
            Outcome::NotDone { message: rest.trim_start_matches(':').trim().to_owned() }
        } else {
            Outcome::Panicked { message, location }
        }
    }

    /// What a student's function that gave no value ended with, in one line of both languages
    /// (`None` for [`Outcome::Pass`] and [`Outcome::Fail`]).
    #[must_use]
    pub fn describe(&self) -> Option<Text> {
        Some(match self {
            Outcome::Pass | Outcome::Fail(_) => return None,
            Outcome::NotDone { message } => Text::new(
                format!("まだです: {}", stub_message(message, Lang::Ja)),
                format!("not done yet: {}", stub_message(message, Lang::En)),
            ),
            Outcome::Panicked { message, location } => {
                let at = location.as_ref().map(|l| format!(" ({l})")).unwrap_or_default();
                Text::new(
                    format!("プログラムが異常終了しました（panic）: {message}{at}"),
                    format!("your code panicked: {message}{at}"),
                )
            }
            Outcome::TimedOut { limit_ms } => {
                let seconds = seconds(*limit_ms);
                Text::new(
                    format!(
                        "制限時間 {seconds} 秒を超えても終わらないため止めました。無限ループになっていないか確認してください。"
                    ),
                    format!(
                        "stopped after the time limit of {seconds} s: does your code loop forever?"
                    ),
                )
            }
            Outcome::Crashed { how: status, .. } => Text::new(
                format!(
                    "あなたの関数を実行していたプロセスが途中で終了しました（{status}）。exit() の呼び出し、スタックの溢れ（深すぎる再帰）、メモリの使いすぎを確認してください。"
                ),
                format!(
                    "the process running your function ended during the call ({status}): look for a call of exit(), a stack overflow (recursion too deep) or too much memory"
                ),
            ),
        })
    }
}

/// Milliseconds as seconds, without a fraction when there is none.
fn seconds(ms: u64) -> String {
    if ms.is_multiple_of(1000) {
        (ms / 1000).to_string()
    } else {
        format!("{:.1}", ms as f64 / 1000.0)
    }
}

/// One check's result.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct CheckResult {
    /// The check's ID, `<task>.<name>`: `a1.t2.closed`.
    pub id: String,
    /// The task it belongs to: `a1.t2`.
    pub task: String,
    /// What it checks, in a few words.
    pub title: Text,
    /// How it ended.
    #[serde(flatten)]
    pub outcome: Outcome,
}

impl CheckResult {
    /// Whether the check passed.
    #[must_use]
    pub fn passed(&self) -> bool {
        self.outcome == Outcome::Pass
    }
}

thread_local! {
    /// Whether this thread is inside [`run`] (its panics are reported, not printed).
    static IN_CHECK: Cell<bool> = const { Cell::new(false) };
    /// The location of the last panic on this thread inside a check.
    static PANIC_LOCATION: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// The check now running, and since when (for the [`watchdog`]).
static CURRENT: Mutex<Option<(String, Instant)>> = Mutex::new(None);

fn install_hook() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let previous = panic::take_hook();
        panic::set_hook(Box::new(move |info| {
            if IN_CHECK.with(Cell::get) {
                let location =
                    info.location().map(|l| format!("{}:{}:{}", l.file(), l.line(), l.column()));
                PANIC_LOCATION.with(|p| *p.borrow_mut() = location);
            } else {
                previous(info);
            }
        }));
    });
}

/// Runs one check, `id` (`a1.t2.closed`; its task, `a1.t2`, is derived from it). `body` returns
/// `Ok(())` or the [`Failure`] it found; a `todo!()` or `unimplemented!()` inside it (a stub not
/// written yet) becomes [`Outcome::NotDone`], any other panic [`Outcome::Panicked`] with its
/// message and location. Nothing is printed for those panics; other threads' panics print as
/// usual. When the student's functions run in a worker (`cg_worker::proxy`), the check's calls
/// share one time budget, and a call that gave no value ends the check with
/// [`Outcome::of_call`].
pub fn run(id: &str, title: Text, body: impl FnOnce() -> Result<(), Failure>) -> CheckResult {
    install_hook();
    if let Ok(mut current) = CURRENT.lock() {
        *current = Some((id.to_owned(), Instant::now()));
    }
    let was_in_check = IN_CHECK.with(|c| c.replace(true));
    cg_worker::proxy::begin_check();
    let result = panic::catch_unwind(AssertUnwindSafe(body));
    cg_worker::proxy::end_check();
    IN_CHECK.with(|c| c.set(was_in_check));
    if let Ok(mut current) = CURRENT.lock() {
        *current = None;
    }
    let outcome = match result {
        Ok(Ok(())) => Outcome::Pass,
        Ok(Err(failure)) => Outcome::Fail(failure),
        Err(payload) => {
            let location = PANIC_LOCATION.with(|p| p.borrow_mut().take());
            if let Some(error) = payload.downcast_ref::<CallError>() {
                Outcome::of_call(error)
            } else {
                let message = payload
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
                    .unwrap_or_else(|| "(no message)".to_owned());
                Outcome::of_panic(message, location)
            }
        }
    };
    CheckResult { id: id.to_owned(), task: crate::unit::task_of(id).to_owned(), title, outcome }
}

/// The name [`guarded`] runs under (what the [`watchdog`] sees).
const GUARDED: &str = "guarded";

/// Calls `f` (a student's function, outside any check) and turns a panic into the [`Outcome`] a
/// check would report: [`Outcome::NotDone`] for a stub, [`Outcome::Panicked`] otherwise.
///
/// # Errors
/// The outcome when `f` panicked.
pub fn guarded<T>(f: impl FnOnce() -> T) -> Result<T, Outcome> {
    let mut value = None;
    let result = run(GUARDED, crate::text::Text::default(), || {
        value = Some(f());
        Ok(())
    });
    match (result.outcome, value) {
        (Outcome::Pass, Some(v)) => Ok(v),
        (outcome, _) => Err(outcome),
    }
}

/// Starts a thread that ends the process (exit code 3) when one check — or one [`guarded`] call
/// of a student's function — runs longer than `limit` (a student's loop that never ends), after
/// printing which check it was in `lang`. For the command line; tests do not use it.
pub fn watchdog(limit: Duration, lang: Lang) {
    std::thread::spawn(move || {
        loop {
            std::thread::sleep(Duration::from_millis(100));
            let over = CURRENT.lock().ok().and_then(|c| {
                c.as_ref().filter(|(_, since)| since.elapsed() > limit).map(|(id, _)| id.clone())
            });
            if let Some(id) = over {
                let seconds = limit.as_secs_f64();
                eprintln!(
                    "{}",
                    match (lang, id.as_str()) {
                        // A student's function called outside a check (`guarded`: the report).
                        (Lang::Ja, GUARDED) => format!(
                            "あなたのプログラムが {seconds} 秒を超えても終わりません。無限ループになっていないか確認してください。"
                        ),
                        (Lang::En, GUARDED) => format!(
                            "your code has run for more than {seconds} s without returning: does it loop forever?"
                        ),
                        (Lang::Ja, _) => format!(
                            "チェック {id} が {seconds} 秒を超えても終わりません。無限ループになっていないか確認してください。"
                        ),
                        (Lang::En, _) => format!(
                            "check {id} has run for more than {seconds} s: does your code loop forever?"
                        ),
                    }
                );
                std::process::exit(3);
            }
        }
    });
}

/// A stub's `todo!()` message in one language. Stub messages read `"<task>: <text>"`, where the
/// text is English, Japanese, or `"<日本語> / <English>"`; the task ID is kept in both languages
/// and only the text in `lang` is shown (none when the stub has no text in that language).
#[must_use]
pub fn stub_message(message: &str, lang: Lang) -> String {
    let is_id = |s: &str| !s.is_empty() && !s.contains(' ') && s.contains(".t");
    let (id, rest) = match message.split_once(':') {
        Some((id, rest)) if is_id(id.trim()) => (id.trim(), rest.trim()),
        _ if is_id(message.trim()) => (message.trim(), ""),
        _ => ("", message.trim()),
    };
    // Kana, kanji and full-width punctuation (not the · and ² of formulas).
    let japanese = |s: &str| {
        s.chars().any(|c| matches!(c, '\u{3000}'..='\u{30ff}' | '\u{4e00}'..='\u{9fff}' | '\u{ff00}'..='\u{ffef}'))
    };
    let (ja, en) = match rest.split_once(" / ") {
        Some((a, b)) if japanese(a) && !japanese(b) => (a.trim(), b.trim()),
        _ if japanese(rest) => (rest, ""),
        _ => ("", rest),
    };
    let text = match lang {
        Lang::Ja => ja,
        Lang::En => en,
    };
    match (id.is_empty(), text.is_empty()) {
        (true, _) => text.to_owned(),
        (false, true) => id.to_owned(),
        (false, false) if lang == Lang::Ja => format!("{id}（{text}）"),
        (false, false) => format!("{id}: {text}"),
    }
}

/// The results of one assignment's checks for one student.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Report {
    /// `a1`, `a2`, `a3`, `a4` or `s`.
    pub assignment: String,
    /// The student number the variant was drawn for, when there is one.
    pub student: Option<String>,
    /// Every check, in order.
    pub checks: Vec<CheckResult>,
}

impl Report {
    /// How many checks passed.
    #[must_use]
    pub fn passed(&self) -> usize {
        self.checks.iter().filter(|c| c.passed()).count()
    }

    /// How many checks there are.
    #[must_use]
    pub fn total(&self) -> usize {
        self.checks.len()
    }

    /// Whether every check passed.
    #[must_use]
    pub fn all_passed(&self) -> bool {
        self.passed() == self.total()
    }

    /// The tasks with at least one check not done yet, in order.
    #[must_use]
    pub fn tasks_not_done(&self) -> Vec<&str> {
        self.tasks_where(|o| matches!(o, Outcome::NotDone { .. }))
    }

    /// The tasks with at least one failing, panicking, timed-out or crashed check, in order.
    #[must_use]
    pub fn tasks_failing(&self) -> Vec<&str> {
        self.tasks_where(|o| !matches!(o, Outcome::Pass | Outcome::NotDone { .. }))
    }

    fn tasks_where(&self, pick: impl Fn(&Outcome) -> bool) -> Vec<&str> {
        let mut tasks: Vec<&str> = Vec::new();
        for c in self.checks.iter().filter(|c| pick(&c.outcome)) {
            if !tasks.contains(&c.task.as_str()) {
                tasks.push(&c.task);
            }
        }
        tasks
    }

    /// A line per check (✓ pass, ✗ fail, … not done yet, ! panicked) with, for each problem, what
    /// was expected and found, where, the usual cause and a hint; then a progress summary.
    #[must_use]
    pub fn render(&self, lang: Lang) -> String {
        let t = |ja: &'static str, en: &'static str| lang.pick(ja, en);
        let mut out = String::new();
        let width = self.checks.iter().map(|c| c.id.chars().count()).max().unwrap_or(0);
        for c in &self.checks {
            let (mark, detail) = match &c.outcome {
                Outcome::Pass => ("✓", None),
                Outcome::Fail(f) => ("✗", Some(f)),
                Outcome::NotDone { .. } => ("…", None),
                Outcome::Panicked { .. } | Outcome::TimedOut { .. } | Outcome::Crashed { .. } => {
                    ("!", None)
                }
            };
            let _ = writeln!(out, "  {mark} {:<width$}  {}", c.id, c.title.get(lang));
            match &c.outcome {
                Outcome::NotDone { message } => {
                    let _ = writeln!(
                        out,
                        "      {}: {}",
                        t("まだです", "not done yet"),
                        stub_message(message, lang)
                    );
                }
                Outcome::Panicked { message, location } => {
                    let _ = writeln!(
                        out,
                        "      {}: {message}",
                        t("プログラムが異常終了しました（panic）", "your code panicked")
                    );
                    if let Some(l) = location {
                        let _ = writeln!(out, "      {}: {l}", t("場所", "at"));
                    }
                }
                Outcome::TimedOut { .. } | Outcome::Crashed { .. } => {
                    if let Some(text) = c.outcome.describe() {
                        let _ = writeln!(out, "      {}", text.get(lang));
                    }
                    if let Outcome::Crashed { stderr, .. } = &c.outcome {
                        for line in
                            stderr.lines().rev().take(5).collect::<Vec<_>>().into_iter().rev()
                        {
                            let _ = writeln!(out, "        | {line}");
                        }
                    }
                }
                _ => {}
            }
            if let Some(f) = detail {
                let _ = writeln!(
                    out,
                    "      {}: {}",
                    t("期待する値", "expected"),
                    f.expected.get(lang)
                );
                let _ =
                    writeln!(out, "      {}: {}", t("実際の値  ", "actual  "), f.actual.get(lang));
                if let Some(l) = &f.location {
                    let _ = writeln!(out, "      {}: {}", t("場所      ", "where   "), l.get(lang));
                }
                if !f.cause.is_empty() {
                    let _ = writeln!(
                        out,
                        "      {}: {}",
                        t("よくある原因", "usual cause"),
                        f.cause.get(lang)
                    );
                }
                if !f.hint.is_empty() {
                    let _ = writeln!(out, "      {}: {}", t("ヒント", "hint"), f.hint.get(lang));
                }
            }
        }
        let _ = write!(
            out,
            "{}: {}/{} {}",
            t("進み具合", "progress"),
            self.passed(),
            self.total(),
            t("個のチェックに合格", "checks pass")
        );
        let not_done = self.tasks_not_done();
        if !not_done.is_empty() {
            let _ = write!(out, "; {}: {}", t("未完成の課題", "not done yet"), not_done.join(", "));
        }
        let failing = self.tasks_failing();
        if !failing.is_empty() {
            let _ =
                write!(out, "; {}: {}", t("直すところのある課題", "to fix"), failing.join(", "));
        }
        out.push('\n');
        out
    }

    /// The report as JSON: `{assignment, student, passed, total, checks: [{id, task, title,
    /// status, …}]}`.
    #[must_use]
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "assignment": self.assignment,
            "student": self.student,
            "passed": self.passed(),
            "total": self.total(),
            "checks": self.checks,
        })
    }
}

#[cfg(test)]
// The stubs students get are `todo!()`s: the runner must understand them.
#[allow(clippy::todo)]
mod tests {
    use super::*;
    use crate::text::t;

    #[test]
    fn outcomes_are_told_apart() {
        let pass = run("x.t1.a", t("a", "a"), || Ok(()));
        assert!(pass.passed());
        let fail = run("x.t1.b", t("b", "b"), || Err(Failure::new("1", "2").at("V3")));
        assert!(matches!(&fail.outcome, Outcome::Fail(f) if f.location == Some("V3".into())));
        let stub = run("x.t2.c", t("c", "c"), || todo!("x.t2: write it"));
        assert_eq!(stub.outcome, Outcome::NotDone { message: "x.t2: write it".into() });
        let bare = run("x.t2.d", t("d", "d"), || unimplemented!());
        assert!(matches!(bare.outcome, Outcome::NotDone { .. }), "{bare:?}");
        let oops = run("x.t3.e", t("e", "e"), || {
            let v: Vec<u32> = Vec::new();
            let i = v.len() + 2;
            Err(Failure::new(v[i].to_string(), ""))
        });
        match &oops.outcome {
            Outcome::Panicked { message, location } => {
                assert!(message.contains("index out of bounds"), "{message}");
                assert!(
                    location.as_deref().is_some_and(|l| l.contains("check.rs")),
                    "{location:?}"
                );
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn stub_messages_are_shown_in_one_language() {
        let both = "s.t1: 環境光 Ia·ka を返す / return the ambient term Ia·ka";
        assert_eq!(stub_message(both, Lang::Ja), "s.t1（環境光 Ia·ka を返す）");
        assert_eq!(stub_message(both, Lang::En), "s.t1: return the ambient term Ia·ka");
        let english = "a1.t1: list the vertices";
        assert_eq!(stub_message(english, Lang::Ja), "a1.t1");
        assert_eq!(stub_message(english, Lang::En), "a1.t1: list the vertices");
        assert_eq!(stub_message("a2.t1", Lang::Ja), "a2.t1");
        // Formulas keep their slashes; text without an ID is shown as it is.
        let formula = "s.t4: return 1/(kc + kl·d + kq·d²)";
        assert_eq!(stub_message(formula, Lang::En), "s.t4: return 1/(kc + kl·d + kq·d²)");
        assert_eq!(stub_message("", Lang::En), "");
    }

    #[test]
    fn guarded_calls_return_values_or_outcomes() {
        assert_eq!(guarded(|| 41 + 1), Ok(42));
        assert!(matches!(
            guarded(|| -> u32 { todo!("x.t1: later") }),
            Err(Outcome::NotDone { .. })
        ));
        assert!(matches!(guarded(|| -> u32 { panic!("boom") }), Err(Outcome::Panicked { .. })));
    }

    #[test]
    fn the_report_explains_and_summarises() {
        let report = Report {
            assignment: "a1".into(),
            student: Some("12345678".into()),
            checks: vec![
                run("a1.t1.count", t("頂点の数", "vertex count"), || Ok(())),
                run("a1.t2.closed", t("閉じている", "closed"), || {
                    Err(Failure::new("every edge in two faces", "V1–V3 in F2 only")
                        .at("edge V1–V3")
                        .cause(t("面が足りない", "a missing face"))
                        .hint(t("F2 の隣を見る", "look next to F2")))
                }),
                run("a1.t3.normals", t("法線", "normals"), || todo!("a1.t3: normals")),
            ],
        };
        assert_eq!((report.passed(), report.total()), (1, 3));
        let en = report.render(Lang::En);
        for needle in [
            "✓ a1.t1.count",
            "✗ a1.t2.closed",
            "expected: every edge",
            "actual  : V1–V3",
            "where   : edge V1–V3",
            "usual cause: a missing face",
            "hint: look next to F2",
            "… a1.t3.normals",
            "not done yet: a1.t3: normals",
            "progress: 1/3 checks pass; not done yet: a1.t3; to fix: a1.t2",
        ] {
            assert!(en.contains(needle), "{needle:?} missing from:\n{en}");
        }
        let ja = report.render(Lang::Ja);
        assert!(
            ja.contains("期待する値")
                && ja.contains("よくある原因: 面が足りない")
                && ja.contains("進み具合: 1/3"),
            "{ja}"
        );
        let json = report.to_json();
        assert_eq!(json["passed"], 1);
        assert_eq!(json["checks"][1]["status"], "fail");
        assert_eq!(json["checks"][1]["where"]["en"], "edge V1–V3");
        assert_eq!(json["checks"][1]["cause"]["ja"], "面が足りない");
        assert_eq!(json["checks"][2]["status"], "not_done");
        assert_eq!(json["checks"][2]["message"], "a1.t3: normals");
    }
}
