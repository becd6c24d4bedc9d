//! The trusted side: start a worker, call its functions one at a time, each within a time
//! budget; a call that runs over, or a worker that dies, fails that call alone.

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::io::{BufReader, Read, Write};
use std::path::PathBuf;
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::mpsc::{Receiver, RecvTimeoutError, sync_channel};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

use crate::{Call, Reason, Reply, cbor, decode, encode, frame};

/// How much of the end of a worker's stderr is kept.
pub const STDERR_TAIL: usize = 2000;

/// Why a call gave no value.
#[derive(Clone, Debug, PartialEq)]
pub enum CallError {
    /// The function panicked: `message` is `not yet implemented: …` for a `todo!()`.
    Panicked {
        /// The panic's message.
        message: String,
        /// Where, when known.
        location: Option<String>,
    },
    /// It ran past its time budget and the worker was stopped; or, with `earlier`, it was not
    /// run at all, because `function` had already run past its budget in an earlier check
    /// ([`crate::proxy`]).
    TimedOut {
        /// The time limit.
        limit: Duration,
        /// The worker's function that was running when the time ran out (`a1.face_normals`;
        /// a batch such as `a3.frames` runs several of the student's, see
        /// [`crate::proxy::student_functions`]: then the one of them the worker said it was
        /// running, [`Reply::Running`], with its step when it said one, `a3.idle@401`
        /// ([`crate::proxy::split_step`]); the batch's name when it said nothing).
        function: String,
        /// Not run now: `function` ran out of time in an earlier check, and this call would
        /// have run it again.
        earlier: bool,
    },
    /// The worker ended during the call (an abort, a memory limit, a stack overflow): how, and
    /// the end of what it wrote on stderr.
    Crashed {
        /// How it ended, in both languages ([`how_it_ended`]).
        status: Reason,
        /// The end of its stderr.
        stderr: String,
    },
    /// The worker could not be started, or its reply did not read (a mismatch of kit and
    /// worker, or a student's program that wrote a frame of its own), or a `shade_pixel` asked
    /// other questions the second time: why, in both languages.
    Broken(Reason),
    /// The function's module did not compile, so the worker was built without it
    /// ([`Worker::without_modules`]): the module (`a1`) and the compiler's errors in it, the
    /// first as the compiler shows it.
    DoesNotCompile {
        /// `a1`, `a2`, … (`exercises/src/<module>.rs`).
        module: String,
        /// The compiler's errors in that file, `file:line: message` (the first one whole).
        errors: Vec<String>,
    },
}

/// A running worker and what is needed to start another.
pub struct Worker {
    program: PathBuf,
    args: Vec<OsString>,
    env: Vec<(String, String)>,
    clear_env: bool,
    dir: Option<PathBuf>,
    running: Option<Running>,
    /// The modules the worker was built without, because they did not compile, with the
    /// compiler's errors in each: a call of one of their functions is answered here.
    without: BTreeMap<String, Vec<String>>,
    /// What the student's functions printed on stdout, in order.
    pub printed: Vec<u8>,
    /// How many calls ran out of their time (the worker was stopped each time).
    pub timeouts: usize,
}

struct Running {
    child: Child,
    stdin: ChildStdin,
    /// The end of what it wrote on stderr (at most [`STDERR_TAIL`] bytes, read on a thread so
    /// that a worker printing without end never blocks on a full pipe).
    stderr: Arc<Mutex<Vec<u8>>>,
    /// Each frame read from the worker's stdout (payload or end, and the prints before it).
    replies: Receiver<std::io::Result<frame::Read>>,
}

impl std::fmt::Debug for Worker {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Worker").field("program", &self.program).finish_non_exhaustive()
    }
}

impl Worker {
    /// A worker that runs `program args…` (started at the first call), with `RUST_BACKTRACE=0`
    /// (a crash's stderr is its message, not a backtrace of the worker's loop).
    #[must_use]
    pub fn new<A: Into<OsString>>(
        program: impl Into<PathBuf>,
        args: impl IntoIterator<Item = A>,
    ) -> Worker {
        Worker {
            program: program.into(),
            args: args.into_iter().map(Into::into).collect(),
            env: vec![("RUST_BACKTRACE".to_owned(), "0".to_owned())],
            clear_env: false,
            dir: None,
            running: None,
            without: BTreeMap::new(),
            printed: Vec::new(),
            timeouts: 0,
        }
    }

    /// The program the worker runs.
    #[must_use]
    pub fn program(&self) -> &std::path::Path {
        &self.program
    }

    /// The same worker running `program` instead (a copy of its program, say).
    #[must_use]
    pub fn with_program(mut self, program: impl Into<PathBuf>) -> Worker {
        self.stop();
        self.program = program.into();
        self
    }

    /// The same worker, built without `modules` (each with the compiler's errors that kept it
    /// out): a call of `a1.vertices` when `a1` is one of them gives
    /// [`CallError::DoesNotCompile`] without reaching the worker.
    #[must_use]
    pub fn without_modules(mut self, modules: BTreeMap<String, Vec<String>>) -> Worker {
        self.without = modules;
        self
    }

    /// The modules the worker was built without, with their compiler errors.
    #[must_use]
    pub fn modules_left_out(&self) -> &BTreeMap<String, Vec<String>> {
        &self.without
    }

    /// The same worker started with only the variables given by [`Worker::env`] (a sandbox's
    /// launch line, which sets the whole environment).
    #[must_use]
    pub fn clear_env(mut self) -> Worker {
        self.clear_env = true;
        self
    }

    /// The same worker started in `dir`.
    #[must_use]
    pub fn current_dir(mut self, dir: impl Into<PathBuf>) -> Worker {
        self.dir = Some(dir.into());
        self
    }

    /// The same worker with `key=value` added to its environment.
    #[must_use]
    pub fn env(mut self, key: impl Into<String>, value: impl Into<String>) -> Worker {
        self.env.push((key.into(), value.into()));
        self
    }

    fn start(&mut self) -> Result<&mut Running, CallError> {
        if self.running.is_none() {
            let mut command = Command::new(&self.program);
            if self.clear_env {
                command.env_clear();
            }
            if let Some(dir) = &self.dir {
                command.current_dir(dir);
            }
            let mut child = command
                .args(&self.args)
                .envs(self.env.iter().map(|(k, v)| (k, v)))
                .stdin(Stdio::piped())
                .stdout(Stdio::piped())
                .stderr(Stdio::piped())
                .spawn()
                .map_err(|e| {
                    let program = self.program.display();
                    CallError::Broken(Reason::with_detail(
                        &format!("ワーカー {program} を起動できません"),
                        &format!("cannot start the worker {program}"),
                        &e.to_string(),
                    ))
                })?;
            let (Some(stdin), Some(stdout), Some(mut err)) =
                (child.stdin.take(), child.stdout.take(), child.stderr.take())
            else {
                return Err(CallError::Broken(Reason::new(
                    "ワーカーとのパイプがありません",
                    "no pipes to the worker",
                )));
            };
            let stderr = Arc::new(Mutex::new(Vec::new()));
            let tail = Arc::clone(&stderr);
            std::thread::spawn(move || {
                let mut buf = [0u8; 4096];
                while let Ok(n @ 1..) = err.read(&mut buf) {
                    if let Ok(mut t) = tail.lock() {
                        t.extend_from_slice(&buf[..n]);
                        let excess = t.len().saturating_sub(STDERR_TAIL);
                        t.drain(..excess);
                    }
                }
            });
            // At most one reply waits: a worker that writes frames without being asked (a
            // thread of the student's) blocks on its pipe, instead of filling this process.
            let (send, replies) = sync_channel(1);
            std::thread::spawn(move || {
                let mut out = BufReader::new(stdout);
                loop {
                    let next = frame::read(&mut out);
                    let end = !matches!(next, Ok((Some(_), _)));
                    if send.send(next).is_err() || end {
                        return;
                    }
                }
            });
            self.running = Some(Running { child, stdin, stderr, replies });
        }
        self.running.as_mut().ok_or_else(|| {
            CallError::Broken(Reason::new(
                "ワーカーが起動していません",
                "the worker is not started",
            ))
        })
    }

    /// Stops the worker (the next call starts a fresh one).
    pub fn stop(&mut self) {
        if let Some(mut r) = self.running.take() {
            let _ = r.child.kill();
            let _ = r.child.wait();
        }
    }

    /// Calls `function` with `args` and waits at most `budget` for its reply. The markers of
    /// stubs not started (`cg_student::not_started`) that the function reached in the worker
    /// are recorded on this thread too, as if the function had run here
    /// (`cg_student::take_not_started` reads them).
    ///
    /// # Errors
    /// The function panicked, ran over, crashed the worker, or the reply did not read.
    pub fn call<A, R>(&mut self, function: &str, args: &A, budget: Duration) -> Result<R, CallError>
    where
        A: serde::Serialize,
        R: serde::de::DeserializeOwned,
    {
        let module = function.split('.').next().unwrap_or_default();
        if let Some(errors) = self.without.get(module) {
            return Err(CallError::DoesNotCompile {
                module: module.to_owned(),
                errors: errors.clone(),
            });
        }
        let unsent = |e: String| {
            CallError::Broken(Reason::with_detail(
                &format!("{function} の引数を送れません"),
                &format!("cannot send {function}'s arguments"),
                &e,
            ))
        };
        let call = Call { function: function.to_owned(), args };
        let bytes = encode(&call).map_err(unsent)?;
        let running = self.start()?;
        let sent = frame::write(&mut running.stdin, &bytes).is_ok();
        let deadline = Instant::now().checked_add(budget);
        // The student's function the worker last said it runs (a batch's), and its step.
        let mut now: Option<(String, Option<u64>)> = None;
        let payload = loop {
            let answer = match (sent, &self.running) {
                (true, Some(r)) => {
                    let left =
                        deadline.map_or(budget, |d| d.saturating_duration_since(Instant::now()));
                    r.replies.recv_timeout(left)
                }
                _ => Err(RecvTimeoutError::Disconnected),
            };
            match answer {
                Ok(Ok((Some(payload), printed))) => {
                    self.keep_printed(&printed);
                    match running_report(&payload) {
                        // Kept only when it is one of this call's functions: the worker says,
                        // this side decides what it names.
                        Some((f, step)) => {
                            if crate::proxy::student_functions(function).contains(&f.as_str()) {
                                now = Some((f, step));
                            }
                        }
                        None => break payload,
                    }
                }
                Ok(Ok((None, printed))) => {
                    self.keep_printed(&printed);
                    return Err(self.crashed());
                }
                Ok(Err(e)) => {
                    self.stop();
                    return Err(CallError::Broken(Reason::with_detail(
                        "ワーカーの返事を受け取れません",
                        "cannot take the worker's reply",
                        &e.to_string(),
                    )));
                }
                Err(RecvTimeoutError::Timeout) => {
                    self.stop();
                    self.timeouts += 1;
                    let function = match now {
                        Some((f, step)) => crate::proxy::with_step(&f, step),
                        None => function.to_owned(),
                    };
                    return Err(CallError::TimedOut { limit: budget, function, earlier: false });
                }
                Err(RecvTimeoutError::Disconnected) => return Err(self.crashed()),
            }
        };
        let read = read_payload(function, &payload);
        drop(payload);
        // A reply that is not the call's (another type, no such function, too large): the
        // worker is not in step with this side; the next call starts a fresh one.
        if matches!(read, Err(CallError::Broken(_))) {
            self.stop();
        }
        read
    }

    /// Keeps what the student printed, up to [`frame::MAX_PRINTED`] bytes in all.
    fn keep_printed(&mut self, printed: &[u8]) {
        let room = frame::MAX_PRINTED.saturating_sub(self.printed.len());
        self.printed.extend_from_slice(&printed[..printed.len().min(room)]);
    }

    /// The worker ended during a call: how, with the end of its stderr.
    fn crashed(&mut self) -> CallError {
        let Some(mut r) = self.running.take() else {
            return CallError::Broken(Reason::new(
                "ワーカーが動いていません",
                "the worker is not running",
            ));
        };
        // Its output closed; it may still run (a worker that closed stdout and sleeps, where
        // nothing else stops it): a moment to end, then it is stopped.
        let until = std::time::Instant::now() + Duration::from_millis(500);
        while matches!(r.child.try_wait(), Ok(None)) && std::time::Instant::now() < until {
            std::thread::sleep(Duration::from_millis(5));
        }
        if matches!(r.child.try_wait(), Ok(None)) {
            let _ = r.child.kill();
        }
        let status = r.child.wait();
        // The reader thread ends with the pipe; give it a moment to take the last bytes.
        let until = std::time::Instant::now() + Duration::from_millis(200);
        while Arc::strong_count(&r.stderr) > 1 && std::time::Instant::now() < until {
            std::thread::sleep(Duration::from_millis(5));
        }
        let bytes = r.stderr.lock().map(|t| t.clone()).unwrap_or_default();
        let stderr = String::from_utf8_lossy(&bytes).into_owned();
        CallError::Crashed { status: how_it_ended(status.as_ref().ok(), &stderr), stderr }
    }
}

/// How a worker ended during a call, in both languages: the cause its stderr names (Rust's
/// allocator failing under the memory limit, a stack overflow), else its exit code (a call of
/// `exit()`) or the signal that ended it. The system's own words (`exit status: 0`,
/// `signal: 6 (SIGABRT)`) stood in the Japanese sentence before.
#[must_use]
pub fn how_it_ended(status: Option<&std::process::ExitStatus>, stderr: &str) -> Reason {
    if stderr.contains("memory allocation of ") {
        return Reason::new(
            "メモリの上限を超えました（メモリを確保できませんでした）。大きすぎる Vec や終わらない push がないか確認してください",
            "it went over the memory limit (an allocation failed): look for a Vec too large or a push that never ends",
        );
    }
    if stderr.contains("has overflowed its stack") {
        return Reason::new(
            "スタックが溢れました。再帰が深すぎないか（終わらない再帰）、大きな配列をローカル変数にしていないか確認してください",
            "its stack overflowed: look for recursion too deep (or without end), or a very large local array",
        );
    }
    let code = status.and_then(std::process::ExitStatus::code);
    if let Some(code) = code {
        return Reason::new(
            format!("終了コード {code} で終了しました。exit() を呼んでいないか確認してください"),
            format!("it exited with code {code}: look for a call of exit()"),
        );
    }
    match status.and_then(signal) {
        Some(n) => {
            let ja = signal_name(n).map_or_else(|| format!("{n} "), |s| format!("{n}（{s}）"));
            let name_en = signal_name(n).map(|s| format!(" ({s})")).unwrap_or_default();
            Reason::new(
                format!(
                    "シグナル {ja}で終了しました。exit()・abort() の呼び出し、スタックの溢れ（深すぎる再帰）、メモリの使いすぎがないか確認してください"
                ),
                format!(
                    "it was ended by signal {n}{name_en}: look for a call of exit() or abort(), a stack overflow (recursion too deep) or too much memory"
                ),
            )
        }
        None => Reason::new(
            "終わり方がわかりません。exit()・abort() の呼び出し、スタックの溢れ、メモリの使いすぎがないか確認してください",
            "how it ended is not known: look for a call of exit() or abort(), a stack overflow or too much memory",
        ),
    }
}

/// The signal that ended a process (Unix).
#[cfg(unix)]
fn signal(status: &std::process::ExitStatus) -> Option<i32> {
    std::os::unix::process::ExitStatusExt::signal(status)
}

/// The signal that ended a process: none on this system.
#[cfg(not(unix))]
fn signal(_: &std::process::ExitStatus) -> Option<i32> {
    None
}

/// The usual name of signal `n` on Linux and macOS, where they agree.
fn signal_name(n: i32) -> Option<&'static str> {
    Some(match n {
        4 => "SIGILL",
        6 => "SIGABRT",
        8 => "SIGFPE",
        9 => "SIGKILL",
        11 => "SIGSEGV",
        13 => "SIGPIPE",
        15 => "SIGTERM",
        _ => return None,
    })
}

/// What a call's reply gives. The markers of a [`Reply::Stub`] are recorded on this thread
/// (`cg_student::not_started`), as the function called here would have recorded them; its inner
/// reply is read as any other.
/// The most bytes of a panic's message (or another text of the worker's) kept.
pub const MAX_MESSAGE_BYTES: usize = 4096;
/// The most bytes of a panic's location kept.
const MAX_LOCATION_BYTES: usize = 256;

/// `text` as it is, or its first `max` bytes (at a character's boundary) and how long it was.
fn cut(text: String, max: usize) -> String {
    if text.len() <= max {
        return text;
    }
    let mut end = max;
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}… ({} bytes)", &text[..end], text.len())
}

/// The largest [`Reply::Running`] read as one: the name of a function and a number.
const MAX_RUNNING_BYTES: usize = 512;

/// A small payload that is a [`Reply::Running`]: the function and step it names.
fn running_report(payload: &[u8]) -> Option<(String, Option<u64>)> {
    if payload.len() > MAX_RUNNING_BYTES {
        return None;
    }
    match decode::<Reply<serde::de::IgnoredAny>>(payload) {
        Ok(Reply::Running { function, step }) => Some((function, step)),
        _ => None,
    }
}

/// A reply's bytes as `function`'s result: read straight into `R` (no [`Value`](crate::Value)
/// per number), after its items are counted ([`cbor::items`]: at most [`cbor::MAX_ITEMS`]).
fn read_payload<R: serde::de::DeserializeOwned>(
    function: &str,
    payload: &[u8],
) -> Result<R, CallError> {
    if let Err(e) = cbor::items(payload, cbor::MAX_ITEMS) {
        return Err(CallError::Broken(Reason::with_detail(
            &format!("{function} の返事は読めません（大きすぎるか、壊れています）"),
            &format!("{function}'s reply is not read (too large, or malformed)"),
            &e,
        )));
    }
    match decode::<Reply<R>>(payload) {
        Ok(reply) => read_reply(function, reply),
        // Well formed, but not of the function's type.
        Err(e) if decode::<Reply<serde::de::IgnoredAny>>(payload).is_ok() => {
            Err(CallError::Broken(Reason::with_detail(
                &format!("{function} が別の型の値を返しました"),
                &format!("{function} returned a value of another type"),
                &e,
            )))
        }
        Err(e) => Err(CallError::Broken(Reason::with_detail(
            "ワーカーの返事が読めません",
            "the worker's reply does not read",
            &e,
        ))),
    }
}

fn read_reply<R>(function: &str, reply: Reply<R>) -> Result<R, CallError> {
    match reply {
        Reply::Value(v) => Ok(v),
        // The student's own words, cut to a size a report can hold: a panic of 200 MB in every
        // function once filled the grader's memory.
        Reply::Panicked { message, location } => Err(CallError::Panicked {
            message: cut(message, MAX_MESSAGE_BYTES),
            location: location.map(|l| cut(l, MAX_LOCATION_BYTES)),
        }),
        Reply::BadArguments(why) => Err(CallError::Broken(Reason::with_detail(
            &format!("{function} が引数を読めませんでした"),
            &format!("{function} could not read its arguments"),
            &cut(why, MAX_MESSAGE_BYTES),
        ))),
        Reply::Unknown(name) => {
            let name = cut(name, MAX_LOCATION_BYTES);
            Err(CallError::Broken(Reason::new(
                format!("ワーカーに関数 {name} がありません"),
                format!("the worker has no function {name}"),
            )))
        }
        // Only ever alone in a frame (taken before a reply is read), never the reply.
        Reply::Running { .. } => Err(CallError::Broken(Reason::new(
            format!("{function}: 返事の中に実行中の知らせがあります"),
            format!("{function}: a report of progress inside a reply"),
        ))),
        Reply::Stub { tasks, reply } => {
            if matches!(*reply, Reply::Stub { .. }) {
                return Err(CallError::Broken(Reason::new(
                    format!("{function}: スタブの返事の中にスタブの返事があります"),
                    format!("{function}: a stub's reply inside another"),
                )));
            }
            for task in &tasks {
                cg_student::not_started(task);
            }
            read_reply(function, *reply)
        }
    }
}

impl Drop for Worker {
    fn drop(&mut self) {
        if let Some(r) = self.running.as_mut() {
            let _ = r.stdin.flush();
        }
        self.stop();
    }
}
