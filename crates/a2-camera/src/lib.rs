//! Assignment `a2` — 視点操作インターフェースの拡張 (camera interface).
//!
//! Every assignment crate has the same shape (the command line and the tests rely on it):
//! [`ID`], a per-student [`Spec`] drawn by [`variant`] and described by [`Spec::describe`], the
//! exercise API [`Impl`] (the functions a student writes, in `exercises/src/a2.rs`),
//! [`checks`] and [`view`].

use cg_core::lang::Lang;
use cg_core::scene::Scene;
use cg_harness::{CheckResult, Text, VariantRng};
use serde::Serialize;

/// The assignment's ID, the prefix of its task IDs (`a2.t1`, …).
pub const ID: &str = "a2";

/// What one student must build.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Spec {}

/// The student's variant, drawn from the frozen stream of their number and table version.
#[must_use]
pub fn variant(rng: &mut VariantRng) -> Spec {
    let _ = rng;
    Spec {}
}

impl Spec {
    /// The assignment text for this variant, in `lang`.
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        lang.pick("視点操作インターフェースの拡張", "camera interface").to_owned()
    }
}

/// The functions a student writes (see `exercises/src/a2.rs`).
#[derive(Clone, Copy, Debug)]
pub struct Impl {}

/// Every check of this assignment for `spec`, run against `imp`.
#[must_use]
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    let _ = (spec, imp);
    Vec::new()
}

/// The scene that shows `imp`'s result at time `time_s` (seconds; for animations).
///
/// # Errors
/// What keeps the result from being drawn, in words for the student.
pub fn view(spec: &Spec, imp: &Impl, time_s: f64) -> Result<Scene, Text> {
    let _ = (spec, imp, time_s);
    Ok(cg_harness::course::scene())
}
