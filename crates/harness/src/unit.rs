//! One assignment, one unit: what the kit needs of an assignment crate.
//!
//! Each assignment crate implements [`Assignment`] once, on a unit struct (`A1`, …).
//! `cg-assign` lists the implementations once
//! (`cg_assign::for_each_assignment!`), and every other place that needs "every assignment" —
//! `cg assignment`, `cg check`, `cg view`, the check runner, the report, the grader and its CSV
//! columns — is derived from that list. Adding an assignment is described in
//! `docs/adding-an-assignment.md`.
//!
//! The trait lives on the trusted side: `exercises/` (the student's crate) cannot name it.

use std::fmt::Debug;

use cg_core::lang::Lang;
use cg_core::scene::Scene;

use crate::check::CheckResult;
use crate::report::Part;
use crate::text::Text;
use crate::variant::VariantRng;

/// An assignment: its ID and title, its per-student spec, the functions a student writes, its
/// description, checks and view.
pub trait Assignment: 'static {
    /// The ID (`a1` … `a4`, `s`): the prefix of every task and check ID (`a1.t2.closed`), the
    /// name of the student's file `exercises/src/<ID>.rs` and of the variant stream.
    const ID: &'static str;
    /// The title as the course names it: (Japanese, English).
    const TITLE: (&'static str, &'static str);
    /// The time, in seconds, that a still picture of it shows in the report.
    const REPORT_TIME: f64 = 0.0;
    /// Whether the report has a section for it (its description and `render-<ID>.png`).
    const IN_REPORT: bool = true;
    /// Whether its view is seen through the student's own camera (the viewer then leaves the
    /// camera to the student's code instead of orbiting).
    const OWN_CAMERA: bool = false;
    /// Whether it has an in-class warm-up (`cg view <ID> --warmup`, see [`Assignment::warmup`]).
    const WARMUP: bool = false;

    /// One student's variant of the assignment.
    type Spec: Clone + Debug + PartialEq + Send + Sync + 'static;
    /// The functions a student writes (the table in `cg_student::<ID>::Impl`).
    type Impl: Copy + Debug + Send + Sync + 'static;
    /// What the report shows of it (its `report.rs`): `()` for an assignment without a
    /// section in the report.
    type Report: Clone + Debug + PartialEq + Send + Sync + 'static;

    /// The variant drawn from the student's frozen stream (see [`crate::variant`]).
    fn variant(rng: &mut VariantRng) -> Self::Spec;
    /// The assignment text for one student, in `lang`.
    fn describe(spec: &Self::Spec, lang: Lang) -> String;
    /// The spec as `cg assignment --json` prints it (usually [`json`] of the spec).
    fn spec_json(spec: &Self::Spec) -> Json;
    /// Every check of the student's functions against the spec; each check's ID starts with
    /// [`Assignment::ID`] and names its task (`a1.t2.closed` belongs to task `a1.t2`).
    fn checks(spec: &Self::Spec, imp: &Self::Impl) -> Vec<CheckResult>;
    /// The scene the student's functions draw at `time_s` (what `cg view` shows), or why there
    /// is none.
    ///
    /// # Errors
    /// The student's functions returned something that cannot be drawn; the text says what.
    fn view(spec: &Self::Spec, imp: &Self::Impl, time_s: f64) -> Result<Scene, Text>;
    /// The report's data from the student's functions, or why it cannot be derived, with the
    /// smaller parts it had to leave out (see [`crate::report`]). Every call of the student's
    /// code goes through [`crate::check::guarded`]: a `todo!()` or a panic is a
    /// [`Missing`](crate::report::Missing),
    /// never a crash.
    fn report(spec: &Self::Spec, imp: &Self::Impl) -> Part<Self::Report>;
    /// The reference picture's scene at `time_s`: what [`Self::view`] shows for a correct
    /// answer, built on the trusted side from the kit's own oracle (never from a student's or
    /// the reference solutions' code), so that the students' copy, which has no solutions, shows
    /// it beside the student's result. `None` where the kit has no such oracle.
    fn reference_view(spec: &Self::Spec, time_s: f64) -> Option<Scene> {
        let _ = (spec, time_s);
        None
    }
    /// Labels for [`Self::view`]'s picture: where (as fractions of the picture's width and
    /// height from its top-left corner) and the word written there, centred (`cg view s` names
    /// its three spheres). None by default.
    fn view_labels(spec: &Self::Spec) -> Vec<([f32; 2], &'static str)> {
        let _ = spec;
        Vec::new()
    }
    /// After how many seconds the view repeats, for an assignment that moves (`cg view a3
    /// --strip N` draws N frames over it); `None` for a still picture.
    fn view_period_s(spec: &Self::Spec) -> Option<f64> {
        let _ = spec;
        None
    }
    /// The in-class warm-up drawn by the student's functions at `time_s`, for an assignment
    /// with [`Assignment::WARMUP`].
    fn warmup(imp: &Self::Impl, time_s: f64) -> Option<Scene> {
        let _ = (imp, time_s);
        None
    }
}

/// JSON, as the kit writes it.
pub type Json = serde_json::Value;

/// `value` as JSON (`null` for a value serde cannot write, which no spec of the kit is).
pub fn json(value: &impl serde::Serialize) -> Json {
    serde_json::to_value(value).unwrap_or(serde_json::Value::Null)
}

/// The task a check ID belongs to: `a1.t2.closed` → `a1.t2`; an ID with fewer than two dots is
/// its own task.
#[must_use]
pub fn task_of(check_id: &str) -> &str {
    match check_id.match_indices('.').nth(1) {
        Some((i, _)) => &check_id[..i],
        None => check_id,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_check_names_its_task() {
        assert_eq!(task_of("a1.t2.closed"), "a1.t2");
        assert_eq!(task_of("s.t5.phong.specular"), "s.t5");
        assert_eq!(task_of("a3.t1"), "a3.t1");
        assert_eq!(task_of("a3"), "a3");
    }
}
