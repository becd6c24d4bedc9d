//! Table version 1 is frozen: a published table never changes under a student.
//!
//! This is deliberately a snapshot. Its expected values are not derived independently — the
//! point is the opposite: they were written once, when table 1 was published, and must never
//! change. Every assignment's variant for 64 student numbers (the extremes and a spread) is
//! compared with `table-v1.json`. If this test fails, a change altered table 1: undo it, or put
//! the change into a new table version that students opt into. (`CG_BLESS=1` writes the file
//! only when it does not exist yet.)

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
    let table: serde_json::Value =
        students().iter().map(|s| Variants::for_student(s, TableVersion::V1).to_json()).collect();
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/table-v1.json");
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
            "table 1 changed (first difference at line {}): a published table must never change \
             under a student. Undo the change, or make it a new table version.\n  frozen: {:?}\n  now:    {:?}",
            first.map_or(0, |l| l + 1),
            first.and_then(|l| frozen.lines().nth(l)),
            first.and_then(|l| text.lines().nth(l))
        );
    }
}

#[test]
fn the_64_students_cover_every_assignment_with_different_variants() {
    let all: Vec<serde_json::Value> =
        students().iter().map(|s| Variants::for_student(s, TableVersion::V1).to_json()).collect();
    for id in ["a1", "a2", "a3", "a4", "s"] {
        let distinct: std::collections::BTreeSet<String> =
            all.iter().map(|a| a[id].to_string()).collect();
        assert!(
            distinct.len() >= 32,
            "{id}: only {} distinct variants among 64 students",
            distinct.len()
        );
    }
}
