//! One assignment, one unit: every place the kit's one list (`cg_assign::for_each_assignment!`)
//! cannot derive by itself — the student's and the reference's files, the students' API, the
//! documentation — names every assignment of the list, and each assignment's checks carry its
//! ID. (It lives with the reference solutions, which it runs.) (The command line, the check runner, the report's sections and the grader's files and
//! CSV columns are derived from the list, so they cannot miss one.)

use std::path::{Path, PathBuf};

use cg_assign::{Variants, Which};
use cg_harness::TableVersion;
use cg_harness::unit::task_of;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The places an assignment `id` must appear in, as (file, text that must be in it).
fn places(id: &str) -> Vec<(String, String)> {
    vec![
        (format!("exercises/src/{id}.rs"), format!("{id}.t1")),
        (format!("solutions/src/{id}.rs"), format!("{id}.t1")),
        (format!("crates/student/src/{id}.rs"), "pub struct Impl".to_owned()),
        ("exercises/src/lib.rs".to_owned(), format!("pub mod {id};")),
        // The stand-in of a file that does not compile (exercises/build.rs).
        ("exercises/src/lib.rs".to_owned(), format!("left_out!({id});")),
        (format!("crates/student/src/{id}.rs"), "pub fn left_out() -> Impl".to_owned()),
        ("solutions/src/lib.rs".to_owned(), format!("pub mod {id};")),
        ("crates/student/src/lib.rs".to_owned(), format!("pub mod {id};")),
        (format!("docs/assignments/{id}.md"), format!("{id}.t1")),
        // The worker's table of the student's functions, and the trusted side's stand-ins.
        ("crates/worker/src/tables.rs".to_owned(), format!("pub fn {id}(imp: {id}::Impl)")),
        ("crates/worker/src/tables.rs".to_owned(), format!("$krate::{id}::implementation()")),
        ("crates/worker/src/proxy.rs".to_owned(), format!("pub fn {id}() -> {id}::Impl")),
        ("docs/student-guide.md".to_owned(), format!("(assignments/{id}.md)")),
    ]
}

#[test]
fn every_assignment_of_the_list_has_its_files_and_documentation() {
    let mut missing = Vec::new();
    for &which in Which::ALL {
        for (file, needle) in places(which.id()) {
            let found =
                std::fs::read_to_string(root().join(&file)).is_ok_and(|t| t.contains(&needle));
            if !found {
                missing.push(format!("{file}: no `{needle}`"));
            }
        }
    }
    assert!(missing.is_empty(), "places that miss an assignment:\n{}", missing.join("\n"));
}

#[test]
fn a_missing_assignment_would_be_found() {
    // The test above against an ID the list does not have: every place reports it.
    let absent: Vec<String> = places("a9")
        .into_iter()
        .filter(|(file, needle)| {
            !std::fs::read_to_string(root().join(file)).is_ok_and(|t| t.contains(needle))
        })
        .map(|(file, _)| file)
        .collect();
    assert_eq!(absent.len(), places("a9").len(), "{absent:?}");
}

#[test]
fn each_check_carries_its_assignments_id_and_task() {
    let student = "12345678".parse().unwrap();
    let variants = Variants::for_student(&student, TableVersion::V1);
    let impls = cg_assign::impls!(cg_solutions);
    let mut ids = std::collections::BTreeSet::new();
    for &which in Which::ALL {
        let report = variants.report(which, &impls);
        assert_eq!(report.assignment, which.id());
        assert!(!report.checks.is_empty(), "{which} has no checks");
        for c in &report.checks {
            let prefix = format!("{}.t", which.id());
            assert!(c.id.starts_with(&prefix), "{which}: check {} is not {prefix}…", c.id);
            assert_eq!(c.task, task_of(&c.id), "{}", c.id);
            assert!(ids.insert(c.id.clone()), "check ID {} is used twice", c.id);
            assert!(!c.title.ja.is_empty() && !c.title.en.is_empty(), "{}", c.id);
        }
    }
}

/// The assignment crates in `crates/`: those whose `lib.rs` implements the trait, with the ID
/// their `pub const ID` names.
fn assignment_crates() -> Vec<(PathBuf, String)> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(root().join("crates")).unwrap().flatten() {
        let lib = entry.path().join("src/lib.rs");
        let Ok(text) = std::fs::read_to_string(&lib) else { continue };
        if !text.contains("impl cg_harness::Assignment for") {
            continue;
        }
        let id = text
            .lines()
            .find_map(|l| l.strip_prefix("pub const ID: &str = \""))
            .and_then(|rest| rest.split('"').next())
            .unwrap_or_else(|| panic!("{}: no `pub const ID`", lib.display()));
        found.push((entry.path(), id.to_owned()));
    }
    found.sort();
    found
}

#[test]
fn every_assignment_crate_is_listed_and_has_the_common_layout() {
    let crates = assignment_crates();
    let mut ids: Vec<&str> = crates.iter().map(|(_, id)| id.as_str()).collect();
    ids.sort_unstable();
    let mut listed: Vec<&str> = Which::ALL.iter().map(|w| w.id()).collect();
    listed.sort_unstable();
    // A crate that implements the trait but is not in the list (or the other way round).
    assert_eq!(ids, listed, "assignment crates vs cg_assign::for_each_assignment!");
    for (dir, id) in &crates {
        for file in ["spec.rs", "describe.rs", "checks/mod.rs", "view.rs", "report.rs"] {
            let path = dir.join("src").join(file);
            assert!(path.exists(), "{id}: {} is missing", path.display());
        }
        // One file per task: checks/t1.rs at least.
        assert!(dir.join("src/checks/t1.rs").exists(), "{id}: no checks/t1.rs");
    }
}
