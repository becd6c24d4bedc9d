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

use crate::text::{Text, t};
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
    /// The code it calls is still a stub (`todo!()` / `unimplemented!()`, or a stub that runs
    /// with its marker `cg_student::not_started("a2.t1")`, see [`run`]): not done yet.
    NotDone {
        /// The stub's message, e.g. `a1.t3: write the face normals` ([`marker_message`] for a
        /// marker).
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

thread_local! {
    /// The checks selected on this thread (`cg check a3.t1`, `cg check a1.t2.winding`): `None`
    /// runs every check. Per thread, so tests running side by side do not see each other's; a
    /// check run on another thread is run, and [`Report::keep_only`] drops it all the same.
    static ONLY: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Whether `only` (an assignment `a3`, a task `a3.t1` or a check `a1.t2.winding`) selects the
/// check `id`: the same ID, or one under it.
#[must_use]
pub fn selects(only: &str, id: &str) -> bool {
    id == only || id.strip_prefix(only).is_some_and(|rest| rest.starts_with('.'))
}

/// Runs `f` with only the checks `only` [`selects`] being run; the others give a placeholder
/// [`Outcome::Pass`] without running, which [`Report::keep_only`] drops. `None` runs every check.
pub fn run_only<R>(only: Option<&str>, f: impl FnOnce() -> R) -> R {
    struct Reset;
    impl Drop for Reset {
        fn drop(&mut self) {
            ONLY.with(|o| *o.borrow_mut() = None);
        }
    }
    ONLY.with(|o| *o.borrow_mut() = only.map(str::to_owned));
    let _reset = Reset;
    f()
}

/// Runs one check, `id` (`a1.t2.closed`; its task, `a1.t2`, is derived from it). `body` returns
/// `Ok(())` or the [`Failure`] it found; a `todo!()` or `unimplemented!()` inside it (a stub not
/// written yet) becomes [`Outcome::NotDone`], any other panic [`Outcome::Panicked`] with its
/// message and location. Nothing is printed for those panics; other threads' panics print as
/// usual. When the student's functions run in a worker (`cg_worker::proxy`), the check's calls
/// share one time budget, and a call that gave no value ends the check with
/// [`Outcome::of_call`].
///
/// **Stubs that run.** A stub that must still run (so the view draws around an unfinished
/// assignment) is not a `todo!()` but carries a marker, `cg_student::not_started("a2.t1")`.
/// When the student's functions reached a marker during the check (on this thread, or in the
/// worker: it comes back with the call's reply), the check is [`Outcome::NotDone`] whatever it
/// found — passed, failed or panicked: the marker wins while it is there, and the student
/// deletes it when they start ([`marker_message`] says so). A call that ran out of time or
/// crashed the worker is reported as such. [`guarded`] calls (the view, the report) ignore the
/// markers.
pub fn run(id: &str, title: Text, body: impl FnOnce() -> Result<(), Failure>) -> CheckResult {
    if let Some(only) = ONLY.with(|o| o.borrow().clone())
        && !selects(&only, id)
    {
        // Not selected by `cg check a3.t1`: not run. [`Report::keep_only`] drops it.
        let task = crate::unit::task_of(id).to_owned();
        return CheckResult { id: id.to_owned(), task, title, outcome: Outcome::Pass };
    }
    let outer = cg_student::take_not_started();
    let mut result = run_unmarked(id, title, body);
    let reached = cg_student::take_not_started();
    // Put back what was reached before this check (a check inside a check's body).
    for task in &outer {
        cg_student::not_started(task);
    }
    if let Some(message) = marker_message(&result.task, &reached)
        && matches!(result.outcome, Outcome::Pass | Outcome::Fail(_) | Outcome::Panicked { .. })
    {
        result.outcome = Outcome::NotDone { message };
    }
    result
}

/// The [`Outcome::NotDone`] message for the stub markers `reached` (tasks, in the order first
/// reached) during a check of `task`: the check's own task's marker when it was reached, else
/// the first; `None` when none was.
///
/// The message reads `"<task>: <日本語> / <English>"` as a `todo!()`'s does ([`stub_message`]
/// shows one language), telling the student which line to delete.
#[must_use]
pub fn marker_message(task: &str, reached: &[String]) -> Option<String> {
    let marker = reached.iter().find(|m| *m == task).or_else(|| reached.first())?;
    Some(format!(
        "{marker}: 書き始めたら cg_student::not_started(\"{marker}\"); の行を消します / \
         delete the line cg_student::not_started(\"{marker}\"); when you start writing it"
    ))
}

/// [`run`] without the stub markers (the runner of [`guarded`]).
fn run_unmarked(id: &str, title: Text, body: impl FnOnce() -> Result<(), Failure>) -> CheckResult {
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
/// check would report: [`Outcome::NotDone`] for a stub's `todo!()`, [`Outcome::Panicked`]
/// otherwise. A stub's marker (`cg_student::not_started`) changes nothing here: what the stub
/// returned is the value (the view draws it), and the marker is left for the check around the
/// call, if any.
///
/// # Errors
/// The outcome when `f` panicked.
pub fn guarded<T>(f: impl FnOnce() -> T) -> Result<T, Outcome> {
    let mut value = None;
    let result = run_unmarked(GUARDED, crate::text::Text::default(), || {
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
                // A student's function called outside a check (`guarded`: the report).
                let message = if id == GUARDED {
                    Text::new(
                        format!(
                            "あなたのプログラムが {seconds} 秒を超えても終わりません。無限ループになっていないか確認してください。"
                        ),
                        format!(
                            "your code has run for more than {seconds} s without returning: does it loop forever?"
                        ),
                    )
                } else {
                    Text::new(
                        format!(
                            "チェック {id} が {seconds} 秒を超えても終わりません。無限ループになっていないか確認してください。"
                        ),
                        format!(
                            "check {id} has run for more than {seconds} s: does your code loop forever?"
                        ),
                    )
                };
                eprintln!("{}", message.get(lang));
                std::process::exit(i32::from(crate::exit::Ending::TimedOut.code()));
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
    let with_id = Text::new(
        if ja.is_empty() || id.is_empty() {
            format!("{id}{ja}")
        } else {
            format!("{id}（{ja}）")
        },
        if en.is_empty() || id.is_empty() { format!("{id}{en}") } else { format!("{id}: {en}") },
    );
    with_id.get(lang).to_owned()
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

    /// Keeps the checks `only` [`selects`] (after [`run_only`]), and returns the tasks of every
    /// check the report had, in order (for a message when none was selected).
    pub fn keep_only(&mut self, only: &str) -> Vec<String> {
        let mut tasks: Vec<String> = Vec::new();
        for c in &self.checks {
            if !tasks.contains(&c.task) {
                tasks.push(c.task.clone());
            }
        }
        self.checks.retain(|c| selects(only, &c.id));
        tasks
    }

    /// Whether a check ran out of time (the command's exit status is then 3,
    /// [`crate::exit::Ending::TimedOut`]).
    #[must_use]
    pub fn timed_out(&self) -> bool {
        self.checks.iter().any(|c| matches!(c.outcome, Outcome::TimedOut { .. }))
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
                        t("まだです", "not done yet").get(lang),
                        stub_message(message, lang)
                    );
                }
                Outcome::Panicked { message, location } => {
                    let _ = writeln!(
                        out,
                        "      {}: {message}",
                        t("プログラムが異常終了しました（panic）", "your code panicked").get(lang)
                    );
                    if let Some(l) = location {
                        let _ = writeln!(out, "      {}: {l}", t("場所", "at").get(lang));
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
                    t("期待する値", "expected").get(lang),
                    f.expected.get(lang)
                );
                let _ = writeln!(
                    out,
                    "      {}: {}",
                    t("実際の値  ", "actual  ").get(lang),
                    f.actual.get(lang)
                );
                if let Some(l) = &f.location {
                    let _ = writeln!(
                        out,
                        "      {}: {}",
                        t("場所      ", "where   ").get(lang),
                        l.get(lang)
                    );
                }
                if !f.cause.is_empty() {
                    let _ = writeln!(
                        out,
                        "      {}: {}",
                        t("よくある原因", "usual cause").get(lang),
                        f.cause.get(lang)
                    );
                }
                if !f.hint.is_empty() {
                    let _ = writeln!(
                        out,
                        "      {}: {}",
                        t("ヒント", "hint").get(lang),
                        f.hint.get(lang)
                    );
                }
            }
        }
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

    /// A stub that runs: the marker's line, then what the stub does.
    fn marked_stub(task: &str) -> u32 {
        cg_student::not_started(task);
        0
    }

    #[test]
    fn a_stubs_marker_makes_its_checks_not_done_whatever_they_found() {
        // Passed, failed or panicked: the marker wins while it is there.
        let pass = run("x.t1.a", t("a", "a"), || {
            let _ = marked_stub("x.t1");
            Ok(())
        });
        let fail =
            run("x.t1.b", t("b", "b"), || Err(Failure::new("1", marked_stub("x.t1").to_string())));
        let oops = run("x.t1.c", t("c", "c"), || {
            let _ = marked_stub("x.t1");
            panic!("index out of bounds")
        });
        for r in [&pass, &fail, &oops] {
            let Outcome::NotDone { message } = &r.outcome else { panic!("{r:?}") };
            assert!(message.starts_with("x.t1: "), "{message}");
            assert!(message.contains("cg_student::not_started(\"x.t1\");"), "{message}");
            assert_eq!(
                stub_message(message, Lang::En),
                "x.t1: delete the line cg_student::not_started(\"x.t1\"); when you start writing it"
            );
            assert!(stub_message(message, Lang::Ja).starts_with("x.t1（書き始めたら"), "{message}");
        }
        // The marker of the check's own task is named, else the first reached.
        let own = run("x.t2.d", t("d", "d"), || {
            let _ = marked_stub("x.t1") + marked_stub("x.t2");
            Ok(())
        });
        assert!(
            matches!(&own.outcome, Outcome::NotDone { message } if message.starts_with("x.t2:"))
        );
        let other =
            run("x.t3.e", t("e", "e"), || Err(Failure::new("1", marked_stub("x.t1").to_string())));
        assert!(
            matches!(&other.outcome, Outcome::NotDone { message } if message.starts_with("x.t1:"))
        );
        // The marker counts for the check that reached it only: the next check is judged.
        let _ = marked_stub("x.t1");
        let later = run("x.t1.f", t("f", "f"), || Err(Failure::new("1", "2")));
        assert!(matches!(later.outcome, Outcome::Fail(_)), "{later:?}");
        assert!(cg_student::take_not_started() == ["x.t1"], "what came before is put back");
        // Without the marker (the student deleted it), the code is judged.
        let written = run("x.t1.g", t("g", "g"), || Err(Failure::new("1", "2")));
        assert!(matches!(written.outcome, Outcome::Fail(_)), "{written:?}");
    }

    #[test]
    fn guarded_calls_ignore_the_markers_and_leave_them_to_the_check() {
        assert_eq!(guarded(|| marked_stub("x.t1")), Ok(0), "the view draws what the stub gives");
        assert_eq!(cg_student::take_not_started(), ["x.t1"]);
        let check = run("x.t1.a", t("a", "a"), || {
            let _ = guarded(|| marked_stub("x.t1"));
            Ok(())
        });
        assert!(matches!(check.outcome, Outcome::NotDone { .. }), "{check:?}");
        assert_eq!(marker_message("x.t1", &[]), None);
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
    fn a_selection_names_an_id_or_what_is_under_it() {
        assert!(selects("a1.t1", "a1.t1.count") && selects("a1.t1.count", "a1.t1.count"));
        assert!(selects("a1", "a1.t2.winding"));
        assert!(!selects("a1.t1", "a1.t10.count"), "t1 is not t10");
        assert!(!selects("a1.t2.count", "a1.t2.counted") && !selects("a2", "a1.t2.x"));
        // Under run_only, a check not selected is not run; keep_only drops it.
        let ran = std::cell::Cell::new(0);
        let checks = run_only(Some("x.t1"), || {
            ["x.t1.a", "x.t2.b", "x.t1.c"].map(|id| {
                run(id, t("", ""), || {
                    ran.set(ran.get() + 1);
                    Err(Failure::new("1", "2"))
                })
            })
        });
        assert_eq!(ran.get(), 2, "x.t2.b did not run");
        let mut report = Report { assignment: "x".into(), student: None, checks: checks.to_vec() };
        assert_eq!(report.keep_only("x.t1"), ["x.t1", "x.t2"]);
        let kept: Vec<&str> = report.checks.iter().map(|c| c.id.as_str()).collect();
        assert_eq!(kept, ["x.t1.a", "x.t1.c"]);
        // Afterwards every check runs again.
        assert!(!run("x.t2.b", t("", ""), || Err(Failure::new("1", "2"))).passed());
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
        assert!(!report.timed_out(), "a failure and a stub are not a timeout");
        let mut late = report.clone();
        late.checks[1].outcome = Outcome::TimedOut { limit_ms: 5000 };
        assert!(late.timed_out(), "exit status 3 for `cg check`");
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
