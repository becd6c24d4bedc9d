//! What an assignment's report data is made of, shared by every assignment's `report.rs`: a
//! part that could not be derived ([`Missing`]), a part's result ([`Part`]), and a matrix the
//! report shows ([`NamedMatrix`]). The report crate (`cg-report`) formats these; each
//! assignment derives its own part from the student's functions
//! ([`crate::Assignment::report`]).

use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::product::{MatrixProduct, format_number};

use crate::check::{Outcome, stub_message};
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
    /// A stub says its own words once, without the task's ID that [`Missing::message`] leads
    /// with: `s.t1: ambient() はまだ書かれていません（環境光 Ia·ka を返す）` /
    /// `s.t1: ambient() is not written yet (return the ambient term Ia·ka)`.
    #[must_use]
    pub fn from_outcome(task: &str, function: &str, outcome: Outcome) -> Missing {
        let why = match &outcome {
            Outcome::NotDone { message } => not_written(task, function, message),
            other => other.of_function(function),
        };
        Missing::new(task, why)
    }
}

/// `function はまだ書かれていません（…）` / `function is not written yet (…)`, with the stub's
/// words in each language ([`stub_message`]); the ID of `task` is left out (the line names it
/// already), the ID of another task's stub that was reached is kept.
fn not_written(task: &str, function: &str, message: &str) -> Text {
    let is_id = |s: &str| !s.is_empty() && !s.contains(' ') && s.contains(".t");
    let (id, words) = match message.split_once(':') {
        Some((id, rest)) if is_id(id.trim()) => (id.trim(), rest.trim()),
        _ if is_id(message.trim()) => (message.trim(), ""),
        _ => ("", message.trim()),
    };
    let said = |lang: Lang| {
        let words = stub_message(words, lang);
        match (id, words.is_empty()) {
            ("", _) => words,
            _ if id == task => words,
            (_, true) => id.to_owned(),
            _ => format!("{id}: {words}"),
        }
    };
    let (ja, en) = (said(Lang::Ja), said(Lang::En));
    Text::new(
        if ja.is_empty() {
            format!("{function} はまだ書かれていません")
        } else {
            format!("{function} はまだ書かれていません（{ja}）")
        },
        if en.is_empty() {
            format!("{function} is not written yet")
        } else {
            format!("{function} is not written yet ({en})")
        },
    )
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

#[cfg(test)]
mod tests {
    use super::*;

    fn not_done(message: &str) -> Outcome {
        Outcome::NotDone { message: message.to_owned() }
    }

    #[test]
    fn a_stub_says_its_words_once_without_the_tasks_id() {
        let m = Missing::from_outcome(
            "s.t1",
            "ambient()",
            not_done("s.t1: 環境光 Ia·ka を返す / return the ambient term Ia·ka"),
        );
        assert_eq!(
            m.message(Lang::Ja),
            "s.t1: ambient() はまだ書かれていません（環境光 Ia·ka を返す）"
        );
        assert_eq!(
            m.message(Lang::En),
            "s.t1: ambient() is not written yet (return the ambient term Ia·ka)"
        );
        // A marker's words (`cg_student::not_started`), and a stub without words.
        let marker = "s.t5: 書き始めたら cg_student::not_started(\"s.t5\"); の行を消します / delete the line cg_student::not_started(\"s.t5\"); when you start writing it";
        let m = Missing::from_outcome("s.t5", "vertex_normals()", not_done(marker));
        assert_eq!(
            m.message(Lang::Ja),
            "s.t5: vertex_normals() はまだ書かれていません（書き始めたら cg_student::not_started(\"s.t5\"); の行を消します）"
        );
        assert!(m.message(Lang::En).ends_with(
            "yet (delete the line cg_student::not_started(\"s.t5\"); when you start writing it)"
        ));
        let bare = Missing::from_outcome("a2.t1", "motion()", not_done("a2.t1"));
        assert_eq!(bare.message(Lang::Ja), "a2.t1: motion() はまだ書かれていません");
        assert_eq!(bare.message(Lang::En), "a2.t1: motion() is not written yet");
        // Another task's stub reached on the way keeps its ID; English-only words stay out of
        // the Japanese.
        let other = Missing::from_outcome("a1.t3", "face_normals()", not_done("a1.t1: list them"));
        assert_eq!(
            other.message(Lang::En),
            "a1.t3: face_normals() is not written yet (a1.t1: list them)"
        );
        assert_eq!(
            other.message(Lang::Ja),
            "a1.t3: face_normals() はまだ書かれていません（a1.t1）"
        );
        for m in [&m, &bare, &other] {
            for lang in [Lang::Ja, Lang::En] {
                let text = m.message(lang);
                assert!(!text.contains("））") && !text.contains("))"), "{text}");
            }
        }
    }

    #[test]
    fn other_outcomes_are_said_as_before() {
        let panicked = Outcome::Panicked { message: "boom".to_owned(), location: None };
        let m = Missing::from_outcome("a1.t1", "vertices()", panicked.clone());
        assert_eq!(m.why, panicked.of_function("vertices()"));
    }
}
