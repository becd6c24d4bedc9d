//! # cg-check-runner — a student's checks, and nothing else
//!
//! The grader builds this crate from each submission's `exercises/` and runs its program,
//! `cg-check-runner`, in the sandbox (cg-sandbox): it prints every assignment's check report as
//! JSON on stdout, exactly what `cg check --json` prints, using the kit's check code (the
//! assignment crates, listed once in `cg-assign`) against the submission's `cg-exercises`. It depends on
//! nothing else, so a rebuild after a submission's files change is small; it never uses the
//! network and writes no files.
//!
//! ```text
//! cg-check-runner [--student NUMBER] [--only ID] [--time-limit SECONDS] [--lang ja|en]
//! ```
//!
//! Exit status: 0 every check passed; 1 some did not (the reports are printed all the same);
//! 2 the student could not be found (no `--student` and no readable `exercises/student.toml`:
//! a message on stderr, nothing on stdout); 3 a check ran past the time limit (the watchdog of
//! `cg_harness::check`; nothing on stdout).

use cg_assign::{Impls, Variants, Which};
use cg_harness::check::Report;

/// The functions the student wrote: `exercises/src/<id>.rs` of every assignment, as built.
#[must_use]
pub fn exercises() -> Impls {
    cg_assign::impls!(cg_exercises)
}

/// The checks of one assignment against the student's exercises (`cg-exercises` as built).
#[must_use]
pub fn report(which: Which, a: &Variants) -> Report {
    a.report(which, &exercises())
}

/// The reports as the JSON array `cg check --json` prints.
#[must_use]
pub fn to_json(reports: &[Report]) -> serde_json::Value {
    serde_json::Value::Array(reports.iter().map(Report::to_json).collect())
}
