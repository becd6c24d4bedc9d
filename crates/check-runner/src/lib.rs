//! # cg-check-runner — the student's functions in a process of their own
//!
//! The kit's checks never run in the same process as a student's code (principle 2). This crate
//! is the other process: a **worker** ([`cg_worker`]) that offers every function of the
//! student's `exercises/` as a named handler ([`cg_worker::tables`](mod@cg_worker::tables)) and runs each call it is
//! sent. It links the student's crate (`cg-exercises`), the students' API and the worker's
//! protocol, and nothing of the kit's checks, oracles or renderers: it decides nothing and
//! prints no result. The trusted side (`cg check`, `cg grade`) holds the checks and calls these
//! functions over the worker's pipe, each call within its budget.
//!
//! The grader builds this crate from each submission's `exercises/` and starts its program,
//! `cg-check-runner`, in the sandbox (cg-sandbox); `cg check`, `cg view` and `cg report` build it
//! from the student's own `exercises/`, leaving out a file that does not compile
//! (`cg_assign::local`), and start it as well.
//!
//! ```text
//! cg-check-runner [--memory-mb N]
//! ```
//!
//! It reads calls on stdin until stdin ends. `--memory-mb` limits its memory (Unix: its address
//! space; Windows: a job object's process memory limit; the grader limits it from outside as
//! well).

use cg_worker::serve::Handler;

/// Every function of the student's exercises, by name (`a1.vertices`, …).
#[must_use]
pub fn handlers() -> Vec<(&'static str, Handler)> {
    cg_worker::tables!(cg_exercises)
}

/// Serves the student's functions on stdin and stdout until stdin ends.
///
/// # Errors
/// stdin or stdout failed.
pub fn serve() -> std::io::Result<()> {
    cg_worker::serve(&handlers())
}

pub use cg_worker::limit_memory;

/// The worker's command line: `[--memory-mb N]`; the limit, when given.
///
/// # Errors
/// An argument that is not `--memory-mb` with a number of MiB.
pub fn parse_args(args: &[String]) -> Result<Option<u64>, String> {
    match args {
        [] => Ok(None),
        [flag, n] if flag == "--memory-mb" => {
            n.parse().map(Some).map_err(|_| format!("--memory-mb: {n:?} is not a number of MiB"))
        }
        other => Err(format!(
            "usage: cg-check-runner [--memory-mb N] (the kit starts this program; it was given {other:?})"
        )),
    }
}
