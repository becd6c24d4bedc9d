//! The worker's side: read calls, run the student's function, write replies. Untrusted code
//! runs here, so nothing here decides anything: it only carries values.

use std::cell::RefCell;
use std::io::{self, BufReader};
use std::panic::{self, AssertUnwindSafe};
use std::sync::{Mutex, PoisonError};
use std::time::Duration;

use crate::{Call, Reply, Value, decode, encode, frame, from_value, to_value};

/// A function the worker offers: its arguments in, its result out, as pipe values (`Err`: the
/// arguments did not read as the function's).
pub type Handler = Box<dyn Fn(Value) -> Result<Value, String>>;

thread_local! {
    /// The location of the last panic on this thread.
    static LOCATION: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Which of the student's functions the call being served runs now ([`running`]), for the
/// watcher of [`serve`].
#[derive(Debug, Default)]
struct Progress {
    /// The student's function (`a3.idle`) and its step (a3's frame), while a call runs one.
    now: Option<(&'static str, Option<u64>)>,
    /// Counts the changes of `now`: the watcher reports a `now` that has not changed for one
    /// [`WATCH`] (a function that runs long, or loops), once.
    changes: u64,
    /// The change last reported.
    reported: u64,
}

static PROGRESS: Mutex<Progress> =
    Mutex::new(Progress { now: None, changes: 0, reported: u64::MAX });

/// How often the watcher looks at [`PROGRESS`].
const WATCH: Duration = Duration::from_millis(50);

/// A batch handler ([`crate::tables`](mod@crate::tables)) is about to call the student's `function` (`a3.idle`) at
/// `step` (a3's frame): said so that, when that call runs long (an endless loop), the caller
/// can name it and the frame in its timeout instead of the whole batch. Cheap: a lock and two
/// stores, no output. The worker only reports it ([`Reply::Running`]): the caller decides.
pub fn running(function: &'static str, step: Option<u64>) {
    let mut p = PROGRESS.lock().unwrap_or_else(PoisonError::into_inner);
    p.now = Some((function, step));
    p.changes = p.changes.wrapping_add(1);
}

/// The call being served ended: nothing is running.
fn idle() {
    let mut p = PROGRESS.lock().unwrap_or_else(PoisonError::into_inner);
    p.now = None;
    p.changes = p.changes.wrapping_add(1);
}

/// The watcher's loop: every [`WATCH`], a [`running`] function that has not changed since the
/// last look is written as a [`Reply::Running`] frame, once, while [`PROGRESS`] is held (so the
/// call's own reply, written after [`idle`] takes the lock, always comes after it).
fn watch() {
    let mut seen = u64::MAX;
    loop {
        std::thread::sleep(WATCH);
        let mut p = PROGRESS.lock().unwrap_or_else(PoisonError::into_inner);
        if let Some((function, step)) = p.now
            && p.changes == seen
            && p.reported != seen
        {
            let reply: Reply = Reply::Running { function: function.to_owned(), step };
            let Ok(bytes) = encode(&reply) else { return };
            if frame::write(&mut io::stdout().lock(), &bytes).is_err() {
                return;
            }
            p.reported = seen;
        }
        seen = p.changes;
    }
}

/// Runs the worker's loop over stdin and stdout until stdin ends: for each [`Call`], the
/// handler of that name under `catch_unwind`, its [`Reply`] framed on stdout. Panics are
/// replies, never printed (the hook records only their location). A watcher thread says which
/// of the student's functions a batch runs when one runs long ([`running`]); where no thread
/// can be started, nothing is said and the calls are served all the same.
///
/// # Errors
/// stdin or stdout failed (the caller went away).
pub fn serve(handlers: &[(&str, Handler)]) -> io::Result<()> {
    panic::set_hook(Box::new(|info| {
        let location = info.location().map(|l| format!("{}:{}:{}", l.file(), l.line(), l.column()));
        LOCATION.with(|l| *l.borrow_mut() = location);
    }));
    let _ = std::thread::Builder::new()
        .name("cg-worker-watch".into())
        .stack_size(64 << 10)
        .spawn(watch);
    let mut input = BufReader::new(io::stdin().lock());
    loop {
        let (payload, _) = frame::read(&mut input)?;
        let Some(payload) = payload else { return Ok(()) };
        let reply = match decode::<Call>(&payload) {
            Err(e) => Reply::BadArguments(format!("not a call: {e}")),
            Ok(call) => match handlers.iter().find(|(name, _)| *name == call.function) {
                None => Reply::Unknown(call.function),
                Some((_, handler)) => run(handler, call.args),
            },
        };
        let bytes = encode(&reply).map_err(io::Error::other)?;
        frame::write(&mut io::stdout().lock(), &bytes)?;
    }
}

/// The handler's reply, wrapped in [`Reply::Stub`] when the student's function reached a stub's
/// marker (`cg_student::not_started`).
fn run(handler: &Handler, args: Value) -> Reply {
    let _ = cg_student::take_not_started();
    let reply = run_unmarked(handler, args);
    idle();
    let tasks = cg_student::take_not_started();
    if tasks.is_empty() { reply } else { Reply::Stub { tasks, reply: Box::new(reply) } }
}

fn run_unmarked(handler: &Handler, args: Value) -> Reply {
    match panic::catch_unwind(AssertUnwindSafe(|| handler(args))) {
        Ok(Ok(value)) => Reply::Value(value),
        Ok(Err(why)) => Reply::BadArguments(why),
        Err(payload) => Reply::Panicked {
            message: crate::panic_message(payload.as_ref())
                .unwrap_or_else(|| "(no message)".to_owned()),
            location: LOCATION.with(|l| l.borrow_mut().take()),
        },
    }
}

/// A [`Handler`] from a function of one argument type to one result type (a tuple for several
/// arguments; the changed `&mut` arguments go in the result).
pub fn handler<A, R>(f: impl Fn(A) -> R + 'static) -> Handler
where
    A: serde::de::DeserializeOwned,
    R: serde::Serialize,
{
    Box::new(move |args| {
        let a: A = from_value(&args)?;
        to_value(&f(a))
    })
}
