//! Deriving the report's data, from the student's own exercises or from data alone.
//!
//! Each assignment derives its own part in its crate (`cg_a1::report`, … beside its checks,
//! sharing their helpers), from the student's `Impl` and `Spec`; [`derive()`] gathers every
//! part of the assignments in the report ([`cg_assign::Variants::derive`]), each on its own, so
//! a part whose function is still a stub (or panics, or returns unusable data) is [`Missing`]
//! while the others still derive. The shading part (`s`) always derives — its numbers follow
//! from the assignment alone — and names each of the student's functions it could not call. A data file gives the polygon model alone
//! ([`polygon_from_data`]).

use cg_assign::{Derived, Impls, Variants, Which};

pub use cg_assign::cg_a1::report::polygon_from_data;
pub use cg_harness::report::Missing;

/// Everything the report needs from `assignment`'s student, from `impls` (see the module).
#[must_use]
pub fn derive(assignment: &Variants, impls: &Impls) -> (Derived, Vec<Missing>) {
    assignment.derive(impls)
}

macro_rules! derive_one_from_list {
    (() $($id:ident : $unit:path,)*) => {
        /// One assignment's part of [`derive()`] into `derived` (nothing for one without a
        /// section in the report), what it could not derive added to `missing`: the report
        /// derives (and draws) one assignment at a time, so that a function of one assignment
        /// that ran out of time holds up none of the others' (`crate::app`).
        pub fn derive_one(
            assignment: &Variants,
            which: Which,
            impls: &Impls,
            derived: &mut Derived,
            missing: &mut Vec<Missing>,
        ) {
            match which {
                $(Which::$id => if <$unit as cg_harness::Assignment>::IN_REPORT {
                    derived.$id = cg_harness::report::take(
                        <$unit as cg_harness::Assignment>::report(&assignment.$id, &impls.$id),
                        missing,
                    );
                },)*
            }
        }
    };
}

cg_assign::for_each_assignment!(derive_one_from_list!());

#[cfg(test)]
mod tests {
    use super::*;

    use cg_assign::cg_shading::report::Cell;
    use cg_core::lang::Lang;
    use cg_harness::{StudentNumber, TableVersion};

    // --- the pristine stubs --------------------------------------------------------------

    /// The assignments derived one at a time ([`derive_one`], as the report does) give what
    /// [`derive()`] gives, the missing parts in the same order.
    #[test]
    fn one_at_a_time_is_the_same_as_all_at_once() {
        let student: StudentNumber = "20260002".parse().unwrap();
        let assignment = Variants::for_student(&student, TableVersion::V1);
        let impls = cg_assign::impls!(cg_exercises);
        let mut derived = Derived { student: Some(student.to_string()), ..Derived::default() };
        let mut missing = Vec::new();
        for &which in Which::ALL {
            derive_one(&assignment, which, &impls, &mut derived, &mut missing);
        }
        assert_eq!((derived, missing), derive(&assignment, &impls));
    }

    #[test]
    fn the_stubs_leave_every_part_missing_with_its_task_and_nothing_panics() {
        for number in ["12345678", "20260002", "24000007"] {
            let student: StudentNumber = number.parse().unwrap();
            let assignment = Variants::for_student(&student, TableVersion::V1);
            let (derived, missing) = derive(&assignment, &cg_assign::impls!(cg_exercises));
            assert_eq!(derived.student.as_deref(), Some(number));
            assert!(derived.a1.is_none() && derived.a2.is_none());
            assert!(derived.a3.is_none() && derived.a4.is_none());
            // The shading section's own values follow from the assignment alone; every cell of
            // the student's functions is missing.
            let s = derived.s.as_ref().expect("the kit's shading values derive");
            for cell in s.tables().iter().flat_map(|t| &t.rows).flat_map(|r| &r.cells) {
                if let Cell::Yours { yours, .. } = cell {
                    assert!(yours.is_err(), "{cell:?}");
                }
            }
            let tasks: Vec<&str> = missing.iter().map(|m| m.task.as_str()).collect();
            // Vertices are todo!(), camera() does nothing, display() draws nothing,
            // tex_range() is todo!(); each shading function is todo!() but vertex_normals(),
            // which runs with its marker.
            assert_eq!(
                tasks,
                [
                    "a1.t1", "a2.t2", "a3.t2", "a4.t1", "s.t1", "s.t2", "s.t3", "s.t4", "s.t4",
                    "s.t5", "s.t5", "s.t7", "s.t8"
                ],
                "{missing:?}"
            );
            for m in &missing {
                assert!(m.message(Lang::En).starts_with(&format!("{}: ", m.task)));
                assert!(!m.why.ja.is_empty() && !m.why.en.is_empty(), "{m:?}");
            }
            assert!(missing[0].why.en.contains("not written yet"), "{:?}", missing[0]);
            assert!(missing[0].why.ja.contains("まだ書かれていません"), "{:?}", missing[0]);
        }
    }
}
