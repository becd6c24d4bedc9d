//! The `report-checker` binary: the same commands as `cg report`, on a data file (the kit's
//! exercises are stubs here, so the data-alone mode is what it can check without solutions).

use std::path::Path;
use std::process::Command;

fn root() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

fn report_checker(args: &[&str]) -> std::process::Output {
    cg_testkit::no_language_from_the_tester(&mut Command::new(env!("CARGO_BIN_EXE_report-checker")))
        .args(args)
        .current_dir(root())
        .output()
        .unwrap()
}

#[test]
fn checks_a_data_file_and_fails_on_the_slides_normals() {
    let out =
        report_checker(&["--lang", "ja", "check", "--data", "assets/report/lecture-pyramid.md"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{stdout}");
    assert!(stdout.contains("F0") && stdout.contains("F3") && !stdout.contains("F5"), "{stdout}");
    let json = report_checker(&["check", "--json", "--data", "assets/report/lecture-pyramid.md"]);
    let value: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(value["ok"], false);
    let items: Vec<&str> =
        value["findings"].as_array().unwrap().iter().map(|f| f["item"].as_str().unwrap()).collect();
    assert_eq!(items, ["F0 normal", "F1 normal", "F2 normal", "F3 normal"]);
}

#[test]
fn a_missing_file_is_an_error_with_its_name() {
    let out = report_checker(&["--lang", "en", "check", "--data", "no-such-table.md"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("no-such-table.md"), "{stderr}");
    let help = report_checker(&["--help"]);
    let text = String::from_utf8_lossy(&help.stdout);
    for command in ["derive", "fill", "check"] {
        assert!(text.contains(command), "{text}");
    }
}

/// A report whose numbers all follow but some of whose parts could not be checked (a function
/// not written yet) says so in its last line; it used to end with "every one follows" alone.
/// Not a mistake: a part not done yet is none, so it is still `ok`.
#[test]
fn the_summary_counts_the_parts_not_checked() {
    use cg_core::lang::{Lang, Text};
    let outcome = cg_report::app::CheckOutcome {
        report: "report.md".into(),
        problems: Vec::new(),
        verification: cg_report::verify::Verification { checked: 12, ..Default::default() },
        missing: vec![cg_harness::report::Missing::new(
            "a3",
            Text::new("a3.t1 はまだ書かれていません", "a3.t1 is not written yet"),
        )],
        read: Vec::new(),
        items: 0,
    };
    assert!(outcome.ok());
    let en = outcome.render(Lang::En);
    let last = en.lines().last().unwrap();
    assert_eq!(
        last,
        "12 numbers checked; every one follows from the data. 1 part was not checked (\"not checked\" above)."
    );
    let ja = outcome.render(Lang::Ja);
    assert!(ja.lines().last().unwrap().contains("ただし 1 個の部分は確かめられていません"), "{ja}");
    // With a mistake too, the last line still counts the parts not checked (it said only
    // "1 mistake", and the guide promises the count on the last line).
    let finding = cg_report::verify::Finding {
        line: 7,
        item: "V3".into(),
        written: "(1.0, 0.0, 0.0)".into(),
        derived: "(-1.0, 0.0, 0.0)".into(),
        tolerance: Some(0.01),
        why: Text::new("x が違います", "x is off"),
    };
    let two_missing = vec![outcome.missing[0].clone(), outcome.missing[0].clone()];
    let wrong = cg_report::app::CheckOutcome {
        verification: cg_report::verify::Verification {
            checked: 12,
            findings: vec![finding],
            ..Default::default()
        },
        missing: two_missing,
        ..outcome.clone()
    };
    assert!(!wrong.ok());
    let en = wrong.render(Lang::En);
    assert_eq!(
        en.lines().last().unwrap(),
        "12 numbers checked; 1 mistake. 2 parts were not checked (\"not checked\" above).",
    );
    let ja = wrong.render(Lang::Ja);
    assert_eq!(
        ja.lines().last().unwrap(),
        "数値 12 個を確かめ、1 件の誤りがありました。ほかに 2 個の部分は確かめられていません（上の「確かめられません」）。",
    );
    // Nothing checked at all: the parts not checked are still counted.
    let none = cg_report::app::CheckOutcome {
        verification: cg_report::verify::Verification::default(),
        ..outcome.clone()
    };
    let ja = none.render(Lang::Ja);
    assert!(
        ja.lines().last().unwrap().starts_with("確かめられた数値は 1 つもありません。")
            && ja.ends_with("。1 個の部分は確かめられていません（上の「確かめられません」）。\n"),
        "{ja}"
    );
    let en = none.render(Lang::En);
    assert!(
        en.lines().last().unwrap().starts_with("no number was checked: ")
            && en.ends_with(". 1 part was not checked (\"not checked\" above).\n"),
        "{en}"
    );
    // Rows read, but their part not derived: said so, not "the report has no table" (it said
    // that of a vertex table whose vertices() never returned).
    let underived = cg_report::app::CheckOutcome { items: 9, ..none.clone() };
    let en = underived.render(Lang::En);
    assert_eq!(
        en.lines().last().unwrap(),
        "no number was checked: 9 rows, matrices or tables were read, but their parts could not be derived. 1 part was not checked (\"not checked\" above).",
    );
    let ja = underived.render(Lang::Ja);
    assert!(
        ja.contains("行・行列・表を 9 個読みましたが、その部分のデータが導出できませんでした。"),
        "{ja}"
    );
    let of_nothing = cg_report::app::CheckOutcome { missing: Vec::new(), ..underived };
    let en = of_nothing.render(Lang::En);
    assert!(en.ends_with("but none is of the data (see the notes above).\n"), "{en}");
    let all = cg_report::app::CheckOutcome { missing: Vec::new(), ..outcome };
    assert!(
        all.render(Lang::En).ends_with("12 numbers checked; every one follows from the data.\n")
    );
}
