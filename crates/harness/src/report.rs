//! What an assignment's report data is made of, shared by every assignment's `report.rs`: a
//! part that could not be derived ([`Missing`]), a part's result ([`Part`]), and a matrix the
//! report shows ([`NamedMatrix`]). The report crate (`cg-report`) formats these; each
//! assignment derives its own part from the student's functions
//! ([`crate::Assignment::report`]).

use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::product::{MatrixProduct, format_number};

use crate::check::Outcome;
use crate::text::Text;

/// A part of the report that could not be derived: the student's function is still a stub,
/// panicked, or returned data the report cannot use.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Missing {
    /// The task whose function is at fault (`a1.t2`).
    pub task: String,
    /// Why, for the student.
    pub why: Text,
}

impl Missing {
    /// A missing part of `task`, and why.
    #[must_use]
    pub fn new(task: impl Into<String>, why: Text) -> Missing {
        Missing { task: task.into(), why }
    }

    /// `a1.t2: …` in `lang`.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        format!("{}: {}", self.task, self.why.get(lang))
    }

    /// What a guarded call of `function` (`faces()`) ended with, as a missing part of `task`.
    #[must_use]
    pub fn from_outcome(task: &str, function: &str, outcome: Outcome) -> Missing {
        Missing::new(task, outcome.of_function(function))
    }
}

/// A part's data (or why there is none) and the smaller parts it had to leave out.
pub type Part<T> = (Result<T, Missing>, Vec<Missing>);

/// The data of a [`Part`], with what it left out added to `missing`; `None` (and the part
/// itself in `missing`) when it could not be derived.
pub fn take<T>((result, notes): Part<T>, missing: &mut Vec<Missing>) -> Option<T> {
    let value = match result {
        Ok(value) => Some(value),
        Err(m) => {
            missing.push(m);
            None
        }
    };
    missing.extend(notes);
    value
}

/// A matrix the report must show: symbolically and at one stated state or time.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedMatrix {
    /// A stable ID, used as the tag in the template (`a2.view.start`, `a3.object2.t1.5`).
    pub id: String,
    /// What it is and at which state/time (`視野変換行列（初期状態）`).
    pub title: Text,
    /// The product with variables (`T(0, 0, -camera_distance) · Rx(-camera_pitch)`).
    pub symbolic: MatrixProduct,
    /// The product with this state's numbers.
    pub numeric: MatrixProduct,
    /// Each variable with its explanation (which operation changes it, how, its range).
    pub variables: Vec<(String, Text)>,
}

/// `(x, y, z)` with the kit's numbers.
#[must_use]
pub fn vec3_text(v: Vec3) -> String {
    format!("({}, {}, {})", format_number(v.x), format_number(v.y), format_number(v.z))
}
