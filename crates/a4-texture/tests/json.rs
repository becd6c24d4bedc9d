//! a4's spec as `cg assignment --json` shows it: the plain data lives in the students' crate
//! (which cannot work out the cell names, pixels or corners), and [`cg_a4::Presented`] adds the
//! worked-out fields. That the whole output is still table version 1 as frozen is
//! `crates/assign/tests/tables.rs`'s test (it serialises through `serialize_spec`).

use cg_a4::{Corner, Presented, Region, Spec};

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
