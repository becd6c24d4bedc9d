//! The report's data for `s`: none yet. The report template has no section for the shading set
//! (the student's-day issue adds one); until then [`crate::S`] says so (`IN_REPORT = false`) and
//! its report data is `()`. This file is where that section's data will be derived, from the
//! same helpers as the checks.

use cg_harness::report::Part;

use crate::{Impl, Spec};

/// Nothing to derive yet (see the module).
pub fn report(spec: &Spec, imp: &Impl) -> Part<()> {
    let _ = (spec, imp);
    (Ok(()), Vec::new())
}
