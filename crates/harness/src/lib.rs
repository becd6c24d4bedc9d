//! # cg-harness — what every assignment shares
//!
//! - [`text`]: student-facing text in Japanese and English ([`Text`]).
//! - [`check`]: a check's result says what was expected, what was found, where, the usual cause
//!   and a hint; [`check::run`] turns a `todo!()` stub into "not done yet" and a panic into a
//!   report, never a crash; [`check::Report`] prints a line per check and a progress summary,
//!   or JSON.
//! - [`variant`]: the student number, the table version, and the frozen random stream each
//!   assignment draws its variant from — a published table never changes under a student.
//! - [`course`]: the course's sample scene, compiled into the kit (the base every assignment's
//!   view draws on).
//! - [`stubs`]: the student's stubs generated from the reference solutions' `BEGIN SOLUTION` /
//!   `END SOLUTION` and `BEGIN STUB` / `END STUB` markers, so the two never drift apart.
//!
//! Task IDs (`a1.t2`) name a task everywhere: the stub, its checks (`a1.t2.closed`), the
//! assignment text, the report section and the grade file.

pub mod check;
pub mod course;
pub mod stubs;
pub mod text;
pub mod variant;

pub use check::{CheckResult, Failure, Outcome, Report};
pub use text::Text;
pub use variant::{StudentNumber, TableVersion, VariantRng};
