//! # cg-assign — the list of assignments, and one student's assignments
//!
//! **The one list.** [`for_each_assignment!`] names every assignment crate's unit (an
//! implementation of [`cg_harness::Assignment`]) once, with the module of the student's file
//! (`exercises/src/<id>.rs`). Everything that needs "every assignment" is derived from it:
//! [`Which`] (the `a1|a2|…` argument of `cg assignment`, `cg check`, `cg view` and the check
//! runner), [`Variants`] (every variant of one student), [`Impls`] (the student's functions,
//! built by [`impls!`] from `cg_exercises` or `cg_solutions`), the report's sections and the
//! grader's files and CSV columns ([`IDS`]). Adding an assignment: `docs/adding-an-assignment.md`.
//!
//! **One student's assignments.** Like the course's `opengl_report2019.exe`: from a student
//! number, every assignment's variant (which polyhedron, which camera operations, which
//! animations, which texture region), drawn from the frozen stream of [`cg_harness::variant`]
//! for a [`TableVersion`](cg_harness::TableVersion), printed in Japanese or English, or as JSON
//! for tools.
//!
//! The student records their number once, in `exercises/student.toml`:
//!
//! ```toml
//! student = "12345678"
//! table = 1
//! ```

pub mod local;
pub mod screen;
mod student_file;
mod units;

pub use student_file::{
    COURSE_FILE, StudentFile, StudentFileError, course_table, parse_student_file,
    read_student_file, record_change, resolve_student, write_student_file,
};
pub use units::{Derived, IDS, Impls, Variants, Which};

// The assignment crates, for the list's expansions in other crates (they name the crates
// through `cg_assign` only, so a new assignment is one dependency here).
#[doc(hidden)]
pub use {cg_a1, cg_a2, cg_a3, cg_a4, cg_shading};

/// **The list of assignments**, in the order every listing uses: `id: unit,` for each, where
/// `id` is the assignment's ID (`a1`), which is also the module of the student's file
/// (`exercises/src/a1.rs`, `cg_exercises::a1`), and `unit` its [`cg_harness::Assignment`].
///
/// `for_each_assignment!(path::to::callback!(args))` expands to
/// `path::to::callback! { (args) a1: …, a2: …, … }`: a callback macro derives what it needs
/// from the list. A test (`tests/units.rs`) fails when an assignment is missing from a place
/// derived by hand (its files, its documentation).
#[macro_export]
macro_rules! for_each_assignment {
    ($($callback:ident)::+ ! $args:tt) => {
        $($callback)::+! { $args
            a1: $crate::cg_a1::A1,
            a2: $crate::cg_a2::A2,
            a3: $crate::cg_a3::A3,
            a4: $crate::cg_a4::A4,
            s: $crate::cg_shading::S,
        }
    };
}

/// The student's functions from a crate laid out like `exercises/` (`cg_exercises` or
/// `cg_solutions`): an [`Impls`] with `<crate>::<id>::implementation()` for each assignment.
#[macro_export]
macro_rules! impls {
    ($krate:ident) => {
        $crate::for_each_assignment!($crate::__impls_from!($krate))
    };
}

#[doc(hidden)]
#[macro_export]
macro_rules! __impls_from {
    (($krate:ident) $($id:ident : $unit:path,)*) => {
        $crate::Impls { $($id: $krate::$id::implementation(),)* }
    };
}
