//! The worker's side: read calls, run the student's function, write replies. Untrusted code
//! runs here, so nothing here decides anything: it only carries values.

use std::cell::RefCell;
use std::io::{self, BufReader};
use std::panic::{self, AssertUnwindSafe};

use crate::{Call, Reply, Value, decode, encode, frame, from_value, to_value};

/// A function the worker offers: its arguments in, its result out, as pipe values (`Err`: the
/// arguments did not read as the function's).
pub type Handler = Box<dyn Fn(Value) -> Result<Value, String>>;

thread_local! {
    /// The location of the last panic on this thread.
    static LOCATION: RefCell<Option<String>> = const { RefCell::new(None) };
}

/// Runs the worker's loop over stdin and stdout until stdin ends: for each [`Call`], the
/// handler of that name under `catch_unwind`, its [`Reply`] framed on stdout. Panics are
/// replies, never printed (the hook records only their location).
///
/// # Errors
/// stdin or stdout failed (the caller went away).
pub fn serve(handlers: &[(&str, Handler)]) -> io::Result<()> {
    panic::set_hook(Box::new(|info| {
        let location = info.location().map(|l| format!("{}:{}:{}", l.file(), l.line(), l.column()));
        LOCATION.with(|l| *l.borrow_mut() = location);
    }));
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
    let tasks = cg_student::take_not_started();
    if tasks.is_empty() { reply } else { Reply::Stub { tasks, reply: Box::new(reply) } }
}

fn run_unmarked(handler: &Handler, args: Value) -> Reply {
    match panic::catch_unwind(AssertUnwindSafe(|| handler(args))) {
        Ok(Ok(value)) => Reply::Value(value),
        Ok(Err(why)) => Reply::BadArguments(why),
        Err(payload) => Reply::Panicked {
            message: payload
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
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
