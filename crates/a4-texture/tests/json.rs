//! `cg assignment --json` shows a4's variant exactly as table version 1 froze it: the plain data
//! now lives in the students' crate (which cannot work out the cell names, pixels or corners),
//! and [`cg_a4::Presented`] adds the worked-out fields. Compared with the `a4` part of
//! `crates/assign/tests/table-v1.json` for its 64 students, built as that test builds them.

use std::path::Path;

use cg_a4::{Corner, Presented, Region, Spec};
use cg_harness::{StudentNumber, TableVersion, VariantRng};

/// The 64 student numbers of `crates/assign/tests/table_v1.rs`, in its order.
fn students() -> Vec<StudentNumber> {
    let mut numbers = vec![
        "00000000".to_owned(),
        "00000001".to_owned(),
        "12345678".to_owned(),
        "99999999".to_owned(),
    ];
    let mut x: u64 = 20_260_401;
    while numbers.len() < 64 {
        x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        numbers.push(format!("{:08}", (x >> 33) % 100_000_000));
    }
    numbers.into_iter().map(|n| n.parse().unwrap()).collect()
}

#[test]
fn the_json_is_table_1_as_frozen() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../assign/tests/table-v1.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let frozen: Vec<serde_json::Value> = serde_json::from_str(&text).expect("the table parses");
    let students = students();
    assert_eq!(frozen.len(), students.len());
    for (student, frozen) in students.iter().zip(&frozen) {
        assert_eq!(frozen["student"], serde_json::json!(student.to_string()));
        let spec = cg_a4::variant(&mut VariantRng::new(student, TableVersion::V1, cg_a4::ID));
        let now = serde_json::to_value(Presented(&spec)).expect("serialises");
        assert_eq!(
            serde_json::to_string_pretty(&now).unwrap(),
            serde_json::to_string_pretty(&frozen["a4"]).unwrap(),
            "student {student}"
        );
    }
}

#[test]
fn serialize_spec_is_presented_as_a_field() {
    #[derive(serde::Serialize)]
    struct Wrapper {
        #[serde(serialize_with = "cg_a4::serialize_spec")]
        a4: Spec,
    }
    let spec = Spec {
        region: Region { column: 2, row: 3, columns: 2, rows: 2 },
        rotation_deg: 0,
        mirrored: false,
        repeat: 1,
    };
    let value = serde_json::to_value(Wrapper { a4: spec }).unwrap();
    assert_eq!(value["a4"], serde_json::to_value(Presented(&spec)).unwrap());
    assert_eq!(value["a4"]["region"]["first"], "C4");
    assert_eq!(value["a4"]["region"]["pixels"], serde_json::json!([128, 192, 256, 320]));
    let corners = &value["a4"]["corners"];
    assert_eq!(corners.as_array().map(Vec::len), Some(Corner::ALL.len()));
    assert_eq!(
        corners[0],
        serde_json::json!({"corner": "bottom_left", "cell": "C5", "ground": "near_left", "vertex": [0, 10]})
    );
}
