//! How a long grading run goes, for a front end to show ([`crate::grade_with`]): `cg grade`
//! draws a progress bar from these on a terminal (building, N of M graded, time left) and
//! prints its plain lines for logs.

use crate::Graded;

/// One step of a grading run, in the order they come.
#[derive(Clone, Copy, Debug)]
pub enum Event<'a> {
    /// The kit and the submissions are being read and hashed.
    Reading,
    /// An entry whose result was kept (same hash: [`Graded::skipped`]) or just graded. Kept
    /// entries come before [`Event::Start`], graded ones after.
    Graded(&'a Graded),
    /// Everything is read: `entries` in all, `kept` of them already graded.
    Start {
        /// The entries of the run.
        entries: usize,
        /// Those whose result was kept.
        kept: usize,
    },
    /// The kit's handout is being built (slot 0: the whole kit's first build) and copied to
    /// the other slots; only when something is left to grade.
    Building,
    /// The slots are ready: grading starts.
    Built,
}
