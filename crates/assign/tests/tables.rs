//! Table versions 1 and 2 are frozen: a published table never changes under a student.
//!
//! This is deliberately a snapshot. Its expected values are not derived independently — the
//! point is the opposite: they were written once, when each table was published, and must never
//! change. Every assignment's variant for 64 student numbers (the extremes and a spread) is
//! compared with `table-v1.json` and `table-v2.json`. If this test fails, a change altered a
//! published table: undo it, or put the change into a new table version that students opt into.
//! (`CG_BLESS=1` writes a file only when it does not exist yet.)

use std::path::Path;

use cg_assign::Variants;
use cg_harness::{StudentNumber, TableVersion};

fn students() -> Vec<StudentNumber> {
    let mut numbers = vec![
        "00000000".to_owned(),
        "00000001".to_owned(),
        "12345678".to_owned(),
        "99999999".to_owned(),
    ];
    // A spread over the whole range, from a fixed linear congruential sequence.
    let mut x: u64 = 20_260_401;
    while numbers.len() < 64 {
        x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        numbers.push(format!("{:08}", (x >> 33) % 100_000_000));
    }
    numbers.into_iter().map(|n| n.parse().unwrap()).collect()
}

#[test]
fn table_1_never_changes() {
    never_changes(TableVersion::V1);
}

#[test]
fn table_2_never_changes() {
    never_changes(TableVersion::V2);
}

/// Every version has its snapshot (a new version is published with one).
#[test]
fn every_table_has_its_snapshot() {
    for v in TableVersion::ALL {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/table-v{v}.json"));
        assert!(path.exists(), "{}: table {v} has no snapshot", path.display());
    }
}

fn never_changes(version: TableVersion) {
    let table: serde_json::Value =
        students().iter().map(|s| Variants::for_student(s, version).to_json()).collect();
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/table-v{version}.json"));
    let text = serde_json::to_string_pretty(&table).unwrap() + "\n";
    if !path.exists() && std::env::var("CG_BLESS").is_ok_and(|v| v == "1") {
        std::fs::write(&path, &text).unwrap();
    }
    let frozen = std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "{}: {e} (create it once with CG_BLESS=1, when a table is published)",
            path.display()
        )
    });
    if frozen != text {
        let first = frozen.lines().zip(text.lines()).position(|(a, b)| a != b);
        panic!(
            "table {version} changed (first difference at line {}): a published table must never \
             change under a student. Undo the change, or make it a new table version.\n  frozen: {:?}\n  now:    {:?}",
            first.map_or(0, |l| l + 1),
            first.and_then(|l| frozen.lines().nth(l)),
            first.and_then(|l| text.lines().nth(l))
        );
    }
}

#[test]
fn the_64_students_cover_every_assignment_with_different_variants() {
    for version in TableVersion::ALL {
        covers(version);
    }
    // Version 2 draws every assignment from streams of its own.
    let v1: Vec<serde_json::Value> =
        students().iter().map(|s| Variants::for_student(s, TableVersion::V1).to_json()).collect();
    let v2: Vec<serde_json::Value> =
        students().iter().map(|s| Variants::for_student(s, TableVersion::V2).to_json()).collect();
    for id in ["a1", "a2", "a3", "a4", "s"] {
        let same = v1.iter().zip(&v2).filter(|(a, b)| a[id] == b[id]).count();
        assert!(same < 16, "{id}: {same} of 64 students have the same variant in tables 1 and 2");
    }
}

fn covers(version: TableVersion) {
    let all: Vec<serde_json::Value> =
        students().iter().map(|s| Variants::for_student(s, version).to_json()).collect();
    for id in ["a1", "a2", "a3", "a4", "s"] {
        let distinct: std::collections::BTreeSet<String> =
            all.iter().map(|a| a[id].to_string()).collect();
        assert!(
            distinct.len() >= 32,
            "table {version}, {id}: only {} distinct variants among 64 students",
            distinct.len()
        );
    }
}
