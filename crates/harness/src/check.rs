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
use std::panic::{self, AssertUnwindSafe};
use std::sync::{Mutex, Once};
use std::time::{Duration, Instant};

use cg_core::lang::Lang;
use serde::{Deserialize, Serialize};

use crate::text::Text;
use cg_worker::CallError;

/// Why a check failed, in the words a student needs — every part in Japanese and English
/// (numbers and names convert from a plain string, the same in both languages).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
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
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
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
    /// running it was stopped, and the other checks went on in a fresh one. Or, with `earlier`,
    /// the check did not run it at all: it had already run past the limit in an earlier check
    /// of this run (`cg_worker::proxy`), and would have cost the whole limit again.
    TimedOut {
        /// The check's time limit, in milliseconds.
        limit_ms: u64,
        /// The worker's function that was running when the time ran out (`a1.face_normals`;
        /// of a batch such as `a3.frames`, the student's function the worker said it was
        /// running and its frame, `a3.idle@401`, see `cg_worker::proxy::split_step`), when
        /// known ([`describe`](Outcome::describe) names it with its file, and the frame).
        #[serde(default, skip_serializing_if = "Option::is_none")]
        function: Option<String>,
        /// Not run: `function` ran out of time in an earlier check.
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        earlier: bool,
    },
    /// No value came back, and not for the function's running as such: the worker could not
    /// start, its reply did not read, or a `shade_pixel` asked other questions the second time
    /// (`CallError::Broken`).
    Broken {
        /// Why, in both languages.
        why: Text,
    },
    /// The worker running the student's function ended during the call: an abort, a stack
    /// overflow, the memory limit, an `exit()`.
    Crashed {
        /// How it ended, and what to look for (`cg_worker::how_it_ended`).
        how: Text,
        /// The end of what it wrote on stderr.
        stderr: String,
    },
    /// The student's file of this assignment did not compile, so its functions could not run
    /// (the other assignments were built without it and still run).
    DoesNotCompile {
        /// `a1`, … : the file `exercises/src/<module>.rs`.
        module: String,
        /// The compiler's errors in that file, the first one whole.
        errors: Vec<String>,
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
            CallError::TimedOut { limit, function, earlier } => Outcome::TimedOut {
                limit_ms: u64::try_from(limit.as_millis()).unwrap_or(u64::MAX),
                function: Some(function.clone()),
                earlier: *earlier,
            },
            CallError::Crashed { status, stderr } => {
                let how = Text::new(status.ja.clone(), status.en.clone());
                Outcome::Crashed { how, stderr: stderr.clone() }
            }
            CallError::Broken(why) => {
                Outcome::Broken { why: Text::new(why.ja.clone(), why.en.clone()) }
            }
            CallError::DoesNotCompile { module, errors } => {
                Outcome::DoesNotCompile { module: module.clone(), errors: errors.clone() }
            }
        }
    }

    /// A panic's outcome: [`Outcome::NotDone`] for a stub's `todo!()` or `unimplemented!()`,
    /// [`Outcome::Panicked`] for any other.
    #[must_use]
    pub fn of_panic(message: String, location: Option<String>) -> Outcome {
        match cg_worker::stub_text(&message) {
            Some(text) => Outcome::NotDone { message: text.to_owned() },
            None => Outcome::Panicked { message, location },
        }
    }

    /// Why a call of the student's `function` (`faces()`) gave no value, led by its name, in
    /// both languages.
    #[must_use]
    pub fn of_function(&self, function: &str) -> Text {
        match self {
            Outcome::NotDone { message } => Text::new(
                // `a1.t3（面の法線）` has its own brackets: after a colon, not inside more.
                format!("{function} はまだ書かれていません: {}", stub_message(message, Lang::Ja)),
                format!("{function} is not written yet ({})", stub_message(message, Lang::En)),
            ),
            Outcome::Panicked { message, location } => {
                let at = location.as_ref().map(|l| format!(" ({l})")).unwrap_or_default();
                Text::new(
                    format!("{function} が異常終了しました（panic）: {message}{at}"),
                    format!("{function} panicked: {message}{at}"),
                )
            }
            // It names the function itself, with its file.
            Outcome::TimedOut { function: Some(_), .. } => self.describe().unwrap_or_default(),
            other @ (Outcome::TimedOut { .. }
            | Outcome::Broken { .. }
            | Outcome::Crashed { .. }
            | Outcome::DoesNotCompile { .. }) => {
                let text = other.describe().unwrap_or_default();
                Text::new(format!("{function}: {}", text.ja), format!("{function}: {}", text.en))
            }
            Outcome::Pass | Outcome::Fail(_) => Text::new(
                format!("{function} の結果が得られませんでした"),
                format!("{function} gave no result"),
            ),
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
            Outcome::TimedOut { limit_ms, function: Some(function), earlier } => {
                let seconds = seconds(*limit_ms);
                let (file, names) = student_function(function);
                let frame = cg_worker::proxy::split_step(function).1;
                if let (Some(frame), false) = (frame, earlier) {
                    Text::new(
                        format!(
                            "{file} の {} がフレーム {frame} で制限時間 {seconds} 秒を超えても終わらないため止めました。無限ループになっていないか確認してください。",
                            names.ja
                        ),
                        format!(
                            "{} ({file}) was stopped at frame {frame} after the time limit of {seconds} s: does it loop forever?",
                            names.en
                        ),
                    )
                } else if *earlier {
                    Text::new(
                        format!(
                            "実行していません: {file} の {} は前のチェックで制限時間 {seconds} 秒内に終わりませんでした（上を参照）",
                            names.ja
                        ),
                        format!(
                            "not run: {} ({file}) did not finish in an earlier check (above)",
                            names.en
                        ),
                    )
                } else {
                    Text::new(
                        format!(
                            "{file} の {} が制限時間 {seconds} 秒を超えても終わらないため止めました。無限ループになっていないか確認してください。",
                            names.ja
                        ),
                        format!(
                            "{} ({file}) was stopped after the time limit of {seconds} s: does it loop forever?",
                            names.en
                        ),
                    )
                }
            }
            Outcome::TimedOut { limit_ms, function: None, .. } => {
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
            Outcome::Broken { why } => Text::new(
                format!("あなたの関数の結果を受け取れませんでした: {}", why.ja),
                format!("no result came back from your function: {}", why.en),
            ),
            Outcome::Crashed { how, .. } => Text::new(
                format!("あなたの関数を実行していたプロセスが途中で終了しました: {}。", how.ja),
                format!("the process running your function ended during the call: {}", how.en),
            ),
            Outcome::DoesNotCompile { module, .. } => Text::new(
                format!(
                    "exercises/src/{module}.rs がコンパイルできないため、この課題の関数は実行していません（ほかの課題は実行しています）"
                ),
                format!(
                    "exercises/src/{module}.rs does not compile, so this assignment's functions did not run (the other assignments did)"
                ),
            ),
        })
    }
}

/// The file and the name, in both languages, of the student's functions a call of the worker's
/// `function` runs: `a1.face_normals` → `exercises/src/a1.rs`, `face_normals`; `a3.frames` →
/// `exercises/src/a3.rs`, `idle か display` / `idle or display`; `a3.idle@401` (the worker said
/// which one ran, and at which frame) → `exercises/src/a3.rs`, `idle`.
#[must_use]
pub fn student_function(function: &str) -> (String, Text) {
    let module = function.split('.').next().unwrap_or_default();
    let names: Vec<&str> = cg_worker::proxy::student_functions(function)
        .into_iter()
        .map(|f| f.split_once('.').map_or(f, |(_, name)| name))
        .collect();
    let file = format!("exercises/src/{module}.rs");
    (file, Text::new(names.join(" か "), names.join(" or ")))
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
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
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
    let mut result = run_unmarked(id, title, true, body);
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

/// [`run`] without the stub markers (the runner of [`guarded`]); `judged` for a check of [`run`],
/// whose calls of a function that already ran out of time fail at once
/// (`cg_worker::proxy::begin_judged_check`).
fn run_unmarked(
    id: &str,
    title: Text,
    judged: bool,
    body: impl FnOnce() -> Result<(), Failure>,
) -> CheckResult {
    install_hook();
    // A check inside a check (a `guarded` call in a check's body) is watched while it runs; then
    // the outer one again, from its own start.
    let outer = CURRENT.lock().ok().and_then(|mut c| c.replace((id.to_owned(), Instant::now())));
    if judged {
        cg_worker::proxy::begin_judged_check();
    } else {
        cg_worker::proxy::begin_check();
    }
    // Set only around `catch_unwind`: a panic the hook keeps quiet is always caught and reported.
    let was_in_check = IN_CHECK.with(|c| c.replace(true));
    let result = panic::catch_unwind(AssertUnwindSafe(body));
    IN_CHECK.with(|c| c.set(was_in_check));
    cg_worker::proxy::end_check();
    if let Ok(mut current) = CURRENT.lock() {
        *current = outer;
    }
    let outcome = match result {
        Ok(Ok(())) => Outcome::Pass,
        Ok(Err(failure)) => Outcome::Fail(failure),
        Err(payload) => {
            let location = PANIC_LOCATION.with(|p| p.borrow_mut().take());
            if let Some(error) = payload.downcast_ref::<CallError>() {
                Outcome::of_call(error)
            } else {
                let message = cg_worker::panic_message(payload.as_ref())
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
    let result = run_unmarked(GUARDED, crate::text::Text::default(), false, || {
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
        self.tasks_where(|o| {
            !matches!(o, Outcome::Pass | Outcome::NotDone { .. } | Outcome::DoesNotCompile { .. })
        })
    }

    /// The student's files that did not compile (`exercises/src/a1.rs`), in order.
    #[must_use]
    pub fn files_not_compiling(&self) -> Vec<String> {
        let mut files: Vec<String> = Vec::new();
        for c in &self.checks {
            if let Outcome::DoesNotCompile { module, .. } = &c.outcome {
                let file = format!("exercises/src/{module}.rs");
                if !files.contains(&file) {
                    files.push(file);
                }
            }
        }
        files
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

mod render;

#[cfg(test)]
// The stubs students get are `todo!()`s: the runner must understand them.
#[allow(clippy::todo)]
mod tests;
