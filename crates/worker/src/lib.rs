//! # cg-worker — the student's functions in their own process
//!
//! Principle 2 of the kit: student code never shares a process with judgement. A **worker** is
//! a small program built from the student's crate (`exercises/`) and this crate alone: it reads
//! calls on stdin, runs the named student function under `catch_unwind`, and writes the reply on
//! stdout ([`serve()`]). The **caller** ([`Worker`]) lives in the trusted process that holds the
//! checks; it starts the worker, sends one call at a time and waits for the reply within that
//! call's time budget. A function that loops past its budget, aborts, or is killed for its
//! memory fails only the call that ran it: the caller kills the worker, reports
//! [`CallError::TimedOut`] or [`CallError::Crashed`], and starts a fresh worker for the next
//! call.
//!
//! Nothing the worker prints is a result: a reply is only a value for the trusted side to judge
//! (the student's function can return any value anyway). Replies are framed ([`frame`]), so
//! whatever the student prints on stdout (`println!` while debugging) is kept apart and handed
//! back as the student's output, never parsed.
//!
//! This crate has no kit code: the worker links it, so nothing here may compute an answer. Its
//! only link to the course is the students' API (`cg-student`, types and recorders), for
//! [`tables`](mod@tables): each assignment's functions as named handlers.

pub mod cbor;
pub mod client;
pub mod frame;
pub mod proxy;
pub mod serve;
pub mod tables;

pub use client::{CallError, Worker, how_it_ended};

/// Limits this process's memory to `mb` MiB, so that a student's function that allocates
/// without end fails its call instead of taking the machine's memory: its address space on Unix
/// (`RLIMIT_AS`), the memory it may commit on Windows (a job object with a process memory limit,
/// which the process puts itself in). Elsewhere nothing is limited (`Ok(false)`).
///
/// # Errors
/// The system refused the limit.
pub fn limit_memory(mb: u64) -> std::io::Result<bool> {
    let bytes = mb.saturating_mul(1 << 20);
    #[cfg(unix)]
    {
        // platform: rlimits are Unix's.
        rlimit::Resource::AS.set(bytes, bytes)?;
        Ok(true)
    }
    #[cfg(windows)]
    {
        // platform: job objects are Windows'.
        /// `JOB_OBJECT_LIMIT_PROCESS_MEMORY` (winnt.h): `ProcessMemoryLimit` holds.
        const LIMIT_PROCESS_MEMORY: u32 = 0x0000_0100;
        let other = |e: win32job::JobError| std::io::Error::other(e.to_string());
        let job = win32job::Job::create().map_err(other)?;
        let mut info = job.query_extended_limit_info().map_err(other)?;
        info.0.ProcessMemoryLimit = usize::try_from(bytes).unwrap_or(usize::MAX);
        info.0.BasicLimitInformation.LimitFlags |= LIMIT_PROCESS_MEMORY;
        job.set_extended_limit_info(&mut info).map_err(other)?;
        job.assign_current_process().map_err(other)?;
        // The job lives as long as the process: its handle is never closed.
        std::mem::forget(job);
        Ok(true)
    }
    #[cfg(not(any(unix, windows)))]
    {
        let _ = bytes;
        Ok(false)
    }
}

pub use serve::{Handler, serve};

/// The message of a panic's `payload`: the `String` of `panic!("{x}")` or the `&str` of
/// `panic!("text")`; `None` for any other payload (`std::panic::panic_any` of another type).
#[must_use]
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> Option<String> {
    payload
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| payload.downcast_ref::<&str>().map(|s| (*s).to_owned()))
}

/// The text of a stub's panic: what follows `not yet implemented` (`todo!()`) or `not
/// implemented` (`unimplemented!()`), its colon and spaces taken off (`""` for a bare
/// `todo!()`); `None` when `message` is any other panic's.
#[must_use]
pub fn stub_text(message: &str) -> Option<&str> {
    ["not yet implemented", "not implemented"]
        .iter()
        .find_map(|stub| message.strip_prefix(stub))
        .map(|rest| rest.trim_start_matches(':').trim())
}

use serde::{Deserialize, Serialize};

/// Why a call gave no value when it is no fault of the function's own code as such (the worker
/// could not start, a reply that did not read, a `shade_pixel` that asked other questions the
/// second time), in Japanese and English: the worker links no kit code, so it has no `Text` of
/// its own; the trusted side makes one of it.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Reason {
    /// The reason in Japanese.
    pub ja: String,
    /// The reason in English.
    pub en: String,
}

impl Reason {
    /// A reason in both languages.
    #[must_use]
    pub fn new(ja: impl Into<String>, en: impl Into<String>) -> Reason {
        Reason { ja: ja.into(), en: en.into() }
    }

    /// The same detail (a system's or a library's words, untranslated) after a sentence in each
    /// language: `ja: detail`, `en: detail`.
    #[must_use]
    pub fn with_detail(ja: &str, en: &str, detail: &str) -> Reason {
        Reason::new(format!("{ja}: {detail}"), format!("{en}: {detail}"))
    }
}

/// A value on the pipe: CBOR, which carries what a student's function may return and JSON
/// cannot (NaN, ±∞) bit for bit, and reads the kit's tagged enums as JSON does.
pub type Value = ciborium::Value;

/// One call: the function's name (`a1.vertices`) and its arguments. The caller writes a
/// `Call<&A>` of the arguments' own type (no [`Value`] per number of a large mesh); the worker
/// reads a `Call` of pipe [`Value`]s, which each handler reads as its arguments.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Call<A = Value> {
    /// The function, `<assignment>.<name>`.
    pub function: String,
    /// Its arguments, as the function's handler reads them.
    pub args: A,
}

/// `value` as a pipe [`Value`].
///
/// # Errors
/// It does not serialise (a map with keys that are no strings, say).
pub fn to_value(value: &impl Serialize) -> Result<Value, String> {
    Value::serialized(value).map_err(|e| e.to_string())
}

/// A pipe [`Value`] read as `T`.
///
/// # Errors
/// It is not a `T`.
pub fn from_value<T: serde::de::DeserializeOwned>(value: &Value) -> Result<T, String> {
    value.deserialized().map_err(|e| e.to_string())
}

/// A call or reply as the bytes of a frame.
///
/// # Errors
/// It does not serialise.
pub fn encode(message: &impl Serialize) -> Result<Vec<u8>, String> {
    let mut bytes = Vec::new();
    ciborium::into_writer(message, &mut bytes).map_err(|e| e.to_string())?;
    Ok(bytes)
}

/// A frame's bytes as a call or reply.
///
/// # Errors
/// They do not read as a `T`.
pub fn decode<T: serde::de::DeserializeOwned>(bytes: &[u8]) -> Result<T, String> {
    ciborium::from_reader(bytes).map_err(|e| e.to_string())
}

/// The worker's answer to a [`Call`]. The worker writes a `Reply` of pipe [`Value`]s; the
/// caller reads it as `Reply<R>`, the function's own result type, so that a reply costs the
/// caller what its result does, not a [`Value`] per number.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Reply<V = Value> {
    /// What the function returned (and what it changed through `&mut` arguments).
    Value(V),
    /// The function panicked: a `todo!()` (`not yet implemented: …`) or any other panic.
    Panicked {
        /// The panic's message.
        message: String,
        /// `file:line:column`, when known.
        location: Option<String>,
    },
    /// The arguments did not read as the function's (a mismatch of kit and worker).
    BadArguments(String),
    /// No such function in this worker.
    Unknown(String),
    /// The function reached the marker of a stub not started yet
    /// (`cg_student::not_started("a2.t1")`) before it returned or panicked: the markers'
    /// tasks, in the order first reached, and what the call gave otherwise (never a `Stub`).
    /// The caller ([`Worker::call`]) records the markers on its own thread, as the call made
    /// there would have, and reads `reply` as usual: the checks say "not done yet", the view
    /// draws what the stub returned.
    Stub {
        /// The tasks of the markers reached.
        tasks: Vec<String>,
        /// The reply without the markers.
        reply: Box<Reply<V>>,
    },
    /// Not the reply yet: the call runs one of the student's functions, `function` (`a3.idle`,
    /// one of a batch's, see [`proxy::student_functions`]) at `step` (a3's frame), and has for a
    /// while ([`serve::running`]). The caller ([`Worker::call`]) keeps the last one, names it in
    /// a timeout when it is one of the call's functions, and waits on for the reply.
    Running {
        /// The student's function, `<assignment>.<name>`.
        function: String,
        /// How far the batch is (a3: the frame), when it says.
        step: Option<u64>,
    },
}

#[cfg(test)]
mod tests {
    use cg_student::glam::Vec3;

    use super::*;

    /// A call written in its arguments' own type is the same bytes as one written through a
    /// pipe [`Value`] (as the caller wrote it before): floats, NaN, ±∞, integers, texts, options
    /// and the kit's enums alike.
    #[test]
    fn a_call_in_its_own_type_is_the_same_bytes_as_through_a_value() {
        #[derive(Serialize)]
        enum Kind {
            Unit,
            Tuple(u32, f32),
            Named { x: f64 },
        }
        let args = (
            vec![Vec3::new(0.5, -1.0e-30, f32::NAN), Vec3::new(f32::INFINITY, 0.1, 65_504.0)],
            vec![[0u32, 1, 2], [u32::MAX, 7, 300]],
            ("text", Some(-3i64), None::<u8>),
            [Kind::Unit, Kind::Tuple(9, 0.25), Kind::Named { x: std::f64::consts::PI }],
        );
        let direct = encode(&Call { function: "s.test".to_owned(), args: &args }).unwrap();
        let value = to_value(&args).unwrap();
        let through = encode(&Call { function: "s.test".to_owned(), args: value }).unwrap();
        assert_eq!(direct, through);
    }

    /// A panic's message from either payload, none from another; a stub's text from `todo!()`
    /// and `unimplemented!()` with or without a text, none from any other message.
    #[test]
    fn panic_messages_and_stub_texts() {
        let owned: Box<dyn std::any::Any + Send> = Box::new(format!("index {} out of range", 3));
        let borrowed: Box<dyn std::any::Any + Send> = Box::new("attempt to divide by zero");
        let other: Box<dyn std::any::Any + Send> = Box::new(7u32);
        assert_eq!(panic_message(owned.as_ref()).as_deref(), Some("index 3 out of range"));
        assert_eq!(panic_message(borrowed.as_ref()).as_deref(), Some("attempt to divide by zero"));
        assert_eq!(panic_message(other.as_ref()), None);

        assert_eq!(stub_text("not yet implemented: a1.t1: write it"), Some("a1.t1: write it"));
        assert_eq!(stub_text("not yet implemented"), Some(""));
        assert_eq!(stub_text("not implemented: s.t2"), Some("s.t2"));
        assert_eq!(stub_text("index out of bounds: not yet implemented"), None);
        assert_eq!(stub_text("attempt to divide by zero"), None);
    }
}
