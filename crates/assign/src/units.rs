//! What is derived from the list ([`crate::for_each_assignment!`]): [`Which`], [`IDS`],
//! [`Variants`] and [`Impls`], and the dispatch from an assignment's ID to its unit.

use std::fmt::Write as _;

use cg_core::lang::{Lang, t};
use cg_core::scene::Scene;
use cg_harness::check::Report;
use cg_harness::report::{Missing, take};
use cg_harness::unit::Json;
use cg_harness::{Assignment as Unit, CheckResult, StudentNumber, TableVersion, Text, VariantRng};

macro_rules! derive_from_list {
    (() $($id:ident : $unit:path,)*) => {
        /// One of the assignments (the command line's `a1|a2|a3|a4|s`).
        #[allow(non_camel_case_types)]
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Which {
            $(
                #[doc = concat!("`", stringify!($id), "`")]
                $id,
            )*
        }

        /// Every assignment's ID, in the list's order (`a1` … `s`): the files a submission
        /// holds (`exercises/src/<id>.rs`) and the grade table's columns.
        pub const IDS: &[&str] = &[$(<$unit as Unit>::ID,)*];

        impl Which {
            /// Every assignment, in the list's order.
            pub const ALL: &'static [Which] = &[$(Which::$id,)*];

            /// The assignment's ID (`a1`), as in the reports.
            #[must_use]
            pub fn id(self) -> &'static str {
                match self { $(Which::$id => <$unit as Unit>::ID,)* }
            }

            /// The title as the course names it.
            #[must_use]
            pub fn title(self) -> Text {
                let (ja, en) = match self { $(Which::$id => <$unit as Unit>::TITLE,)* };
                Text::new(ja, en)
            }

            /// Whether the report has a section for it.
            #[must_use]
            pub fn in_report(self) -> bool {
                match self { $(Which::$id => <$unit as Unit>::IN_REPORT,)* }
            }

            /// The time (s) the report's picture of it shows.
            #[must_use]
            pub fn report_time(self) -> f64 {
                match self { $(Which::$id => <$unit as Unit>::REPORT_TIME,)* }
            }

            /// Whether its view is seen through the student's own camera.
            #[must_use]
            pub fn own_camera(self) -> bool {
                match self { $(Which::$id => <$unit as Unit>::OWN_CAMERA,)* }
            }

            /// Whether it has an in-class warm-up (`cg view <id> --warmup`).
            #[must_use]
            pub fn has_warmup(self) -> bool {
                match self { $(Which::$id => <$unit as Unit>::WARMUP,)* }
            }
        }

        /// Every assignment's variant for one student.
        #[derive(Clone, Debug, PartialEq)]
        pub struct Variants {
            /// The student number.
            pub student: StudentNumber,
            /// The table the variants come from.
            pub table: TableVersion,
            $(
                #[doc = concat!("The variant of `", stringify!($id), "`.")]
                pub $id: <$unit as Unit>::Spec,
            )*
        }

        /// What the report shows of each assignment (its `report.rs`) for one student; only the
        /// polygon model (`a1`) when the report is made from a data file.
        #[derive(Clone, Debug, Default, PartialEq)]
        pub struct Derived {
            /// The student number, when derived from a student's exercises.
            pub student: Option<String>,
            $(
                #[doc = concat!("`", stringify!($id), "`'s part, when it could be derived.")]
                pub $id: Option<<$unit as Unit>::Report>,
            )*
        }

        /// The functions a student writes, one table per assignment (see [`crate::impls!`]).
        #[derive(Clone, Copy, Debug)]
        pub struct Impls {
            $(
                #[doc = concat!("`exercises/src/", stringify!($id), ".rs`")]
                pub $id: <$unit as Unit>::Impl,
            )*
        }

        impl Impls {
            /// The student's functions as run by the worker that is current on this thread
            /// (`cg_worker::proxy::with_worker`): what the kit's checks call when the student's
            /// code runs in a process of its own.
            #[must_use]
            pub fn worker() -> Impls {
                Impls { $($id: cg_worker::proxy::$id(),)* }
            }
        }

        impl Variants {
            /// `student`'s assignments in table `table`. Each assignment draws from its own
            /// stream, so adding a draw to one never changes another.
            #[must_use]
            pub fn for_student(student: &StudentNumber, table: TableVersion) -> Variants {
                let rng = |id: &str| VariantRng::new(student, table, id);
                Variants {
                    student: student.clone(),
                    table,
                    $($id: <$unit as Unit>::variant(&mut rng(<$unit as Unit>::ID)),)*
                }
            }

            /// One assignment's text in `lang`.
            #[must_use]
            pub fn describe_one(&self, which: Which, lang: Lang) -> String {
                match which { $(Which::$id => <$unit as Unit>::describe(&self.$id, lang),)* }
            }

            /// One assignment's spec as JSON, its f32 numbers as written (`0.1`, not
            /// `0.10000000149011612`; [`cg_harness::tidy_f32_numbers`]).
            #[must_use]
            pub fn spec_json(&self, which: Which) -> Json {
                let mut value = match which {
                    $(Which::$id => <$unit as Unit>::spec_json(&self.$id),)*
                };
                cg_harness::tidy_f32_numbers(&mut value);
                value
            }

            /// One assignment's checks against the student's functions.
            #[must_use]
            pub fn checks(&self, which: Which, impls: &Impls) -> Vec<CheckResult> {
                match which {
                    $(Which::$id => <$unit as Unit>::checks(&self.$id, &impls.$id),)*
                }
            }

            /// One assignment's scene at `time_s`, drawn by the student's functions.
            ///
            /// # Errors
            /// What the student's functions returned that cannot be drawn.
            pub fn view(&self, which: Which, impls: &Impls, time_s: f64) -> Result<Scene, Text> {
                match which {
                    $(Which::$id => <$unit as Unit>::view(&self.$id, &impls.$id, time_s),)*
                }
            }

            /// The kit's own reference picture of `which` at `time_s`
            /// ([`cg_harness::Assignment::reference_view`]), where it has one.
            #[must_use]
            pub fn reference_view(&self, which: Which, time_s: f64) -> Option<Scene> {
                match which {
                    $(Which::$id => <$unit as Unit>::reference_view(&self.$id, time_s),)*
                }
            }

            /// After how many seconds `which`'s view repeats (`None`: a still picture).
            #[must_use]
            pub fn view_period_s(&self, which: Which) -> Option<f64> {
                match which {
                    $(Which::$id => <$unit as Unit>::view_period_s(&self.$id),)*
                }
            }

            /// The labels of `which`'s view: world points and the words written there.
            #[must_use]
            pub fn view_labels(&self, which: Which) -> Vec<([f32; 2], &'static str)> {
                match which {
                    $(Which::$id => <$unit as Unit>::view_labels(&self.$id),)*
                }
            }

            /// Everything the report needs from the student's functions: each assignment in the
            /// report on its own, so a missing part leaves its field `None` while the others
            /// derive. The list names every part (and every smaller piece, such as the
            /// student's own normals) that could not be derived.
            #[must_use]
            pub fn derive(&self, impls: &Impls) -> (Derived, Vec<Missing>) {
                let mut missing = Vec::new();
                let derived = Derived {
                    student: Some(self.student.to_string()),
                    $($id: if <$unit as Unit>::IN_REPORT {
                        take(<$unit as Unit>::report(&self.$id, &impls.$id), &mut missing)
                    } else {
                        None
                    },)*
                };
                (derived, missing)
            }

            /// One assignment's in-class warm-up at `time_s`; `None` for one without.
            #[must_use]
            pub fn warmup(which: Which, impls: &Impls, time_s: f64) -> Option<Scene> {
                match which { $(Which::$id => <$unit as Unit>::warmup(&impls.$id, time_s),)* }
            }
        }

        #[cfg(test)]
        #[test]
        fn each_entry_of_the_list_is_named_by_its_units_id() {
            $(assert_eq!(stringify!($id), <$unit as Unit>::ID);)*
        }
    };
}

crate::for_each_assignment!(derive_from_list!());

impl Which {
    /// The assignment with this ID.
    #[must_use]
    pub fn from_id(id: &str) -> Option<Which> {
        Which::ALL.iter().copied().find(|w| w.id() == id)
    }
}

impl std::fmt::Display for Which {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.id())
    }
}

impl clap::ValueEnum for Which {
    fn value_variants<'a>() -> &'a [Self] {
        Which::ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        let title = self.title();
        Some(
            clap::builder::PossibleValue::new(self.id())
                .help(format!("{} / {}", title.ja, title.en)),
        )
    }
}

impl Variants {
    /// The whole assignment text in `lang`, or one assignment's.
    #[must_use]
    pub fn describe(&self, lang: Lang, only: Option<Which>) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{}: {}  ({} {})",
            t("学生番号", "Student number").get(lang),
            self.student,
            t("課題表", "table").get(lang),
            self.table
        );
        let _ = writeln!(
            out,
            "{}\n",
            t("コンピューターグラフィックス レポート課題", "Computer graphics: report assignments")
                .get(lang)
        );
        for &which in Which::ALL {
            if only.is_none_or(|o| o == which) {
                let _ = writeln!(out, "{}\n", self.describe_one(which, lang).trim_end());
            }
        }
        out
    }

    /// The assignments as JSON (`student`, `table`, and one object per assignment).
    #[must_use]
    pub fn to_json(&self) -> Json {
        let mut map = serde_json::Map::new();
        map.insert("student".to_owned(), cg_harness::unit::json(&self.student));
        map.insert("table".to_owned(), cg_harness::unit::json(&self.table));
        for &which in Which::ALL {
            map.insert(which.id().to_owned(), self.spec_json(which));
        }
        Json::Object(map)
    }

    /// One assignment's check report for the student's functions.
    #[must_use]
    pub fn report(&self, which: Which, impls: &Impls) -> Report {
        Report {
            assignment: which.id().to_owned(),
            student: Some(self.student.to_string()),
            checks: self.checks(which, impls),
        }
    }

    /// The check reports of `which`, the student's functions running in `worker` (a process of
    /// their own: a worker built from the student's crate, `cg-check-runner`), each check's calls
    /// within `per_check`. The checks run here, in the caller's process; a call that loops,
    /// crashes or panics ends only the check that made it. The worker comes back with what the
    /// student's code printed.
    #[must_use]
    pub fn reports_in_worker(
        &self,
        which: &[Which],
        worker: cg_worker::Worker,
        per_check: std::time::Duration,
    ) -> (Vec<Report>, cg_worker::Worker) {
        cg_worker::proxy::with_worker(worker, per_check, || {
            let impls = Impls::worker();
            which.iter().map(|&w| self.report(w, &impls)).collect()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn assignments_are_deterministic_and_differ_between_students() {
        let a: StudentNumber = "12345678".parse().unwrap();
        let one = Variants::for_student(&a, TableVersion::V1);
        assert_eq!(one, Variants::for_student(&a, TableVersion::V1));
        let other = Variants::for_student(&"87654321".parse().unwrap(), TableVersion::V1);
        assert_ne!(one, other);
        let text = one.describe(Lang::Ja, None);
        assert!(text.starts_with("学生番号: 12345678"), "{text}");
        assert_eq!(one.to_json()["student"], "12345678");
    }

    #[test]
    fn which_reads_back_every_id_and_nothing_else() {
        for &w in Which::ALL {
            assert_eq!(Which::from_id(w.id()), Some(w));
            assert!(!w.title().ja.is_empty() && !w.title().en.is_empty());
        }
        assert_eq!(Which::from_id("a5"), None);
        assert_eq!(IDS.len(), Which::ALL.len());
    }

    #[test]
    fn the_command_line_lists_every_assignment_with_its_title() {
        use clap::ValueEnum as _;
        for &which in Which::ALL {
            let value = which.to_possible_value().unwrap();
            assert_eq!(value.get_name(), which.id());
            let Text { ja, en } = which.title();
            let help = value.get_help().unwrap().to_string();
            assert!(help.contains(&ja) && help.contains(&en), "{help}");
            assert_eq!(Which::from_str(which.id(), false), Ok(which));
        }
        assert!(Which::from_str("a9", false).is_err());
        // `cg assignment --json` has an object per assignment.
        let json = Variants::for_student(&"12345678".parse().unwrap(), TableVersion::V1).to_json();
        for &which in Which::ALL {
            assert!(json[which.id()].is_object(), "{which}: {json}");
        }
    }
}
