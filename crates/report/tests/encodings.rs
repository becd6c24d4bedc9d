//! Reports and data tables as students' editors save them: the same table (`fixtures/encodings/`,
//! written by Python's codecs) in UTF-8, UTF-8 with a BOM and CRLF, Shift_JIS (CP932) with CRLF
//! and UTF-16LE with a BOM and CRLF, each copied to `山田 太郎/レポート 1.md` and checked by the
//! `report-checker` binary (the same commands as `cg report`).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const FIXTURES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/fixtures/encodings");

fn fixture(name: &str) -> Vec<u8> {
    std::fs::read(Path::new(FIXTURES).join(name)).unwrap()
}

/// A fresh folder `山田 太郎` under a scratch folder of this test.
fn student_folder(name: &str) -> PathBuf {
    cg_testkit::student_folder("cg-report-encodings", name)
}

fn remove(dir: &Path) {
    cg_testkit::remove_student_folder(dir);
}

fn report_checker(args: &[&str]) -> Output {
    cg_testkit::no_language_from_the_tester(&mut Command::new(env!("CARGO_BIN_EXE_report-checker")))
        .args(args)
        .output()
        .unwrap()
}

/// `check --json --data FILE`: the findings' (item, line) and the encoding named for the file.
fn check_json(file: &Path, extra: &[&str]) -> (Vec<(String, u64)>, String) {
    let file = file.to_str().unwrap();
    let mut args = vec!["check", "--json", "--data", file];
    args.extend_from_slice(extra);
    let out = report_checker(&args);
    assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
    let value: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let findings = value["findings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| (f["item"].as_str().unwrap().to_owned(), f["line"].as_u64().unwrap()))
        .collect();
    assert_eq!(value["read"][0]["file"], file);
    (findings, value["read"][0]["encoding"].as_str().unwrap().to_owned())
}

#[test]
fn every_encoding_gives_the_same_findings_and_is_named() {
    let utf8 = fixture("pyramid-utf8.md");
    let sjis = fixture("pyramid-shift_jis-crlf.md");
    // Premises: the fixtures are what the names say.
    assert!(std::str::from_utf8(&sjis).is_err() && sjis.windows(2).any(|w| w == b"\r\n"));
    assert!(fixture("pyramid-utf16le-bom-crlf.md").starts_with(b"\xFF\xFE#\0"));

    let dir = student_folder("same");
    let path = dir.join("レポート 1.md");
    std::fs::write(&path, &utf8).unwrap();
    let (expected, encoding) = check_json(&path, &[]);
    assert_eq!(encoding, "UTF-8");
    let items: Vec<&str> = expected.iter().map(|(item, _)| item.as_str()).collect();
    assert_eq!(items, ["F0 normal", "F1 normal", "F2 normal", "F3 normal"]);
    for (name, encoding) in [
        ("pyramid-utf8-bom-crlf.md", "UTF-8 (BOM)"),
        ("pyramid-shift_jis-crlf.md", "Shift_JIS"),
        ("pyramid-utf16le-bom-crlf.md", "UTF-16LE"),
    ] {
        std::fs::write(&path, fixture(name)).unwrap();
        assert_eq!(check_json(&path, &[]), (expected.clone(), encoding.to_owned()), "{name}");
    }
    // Named on the command line, the same.
    std::fs::write(&path, &sjis).unwrap();
    assert_eq!(check_json(&path, &["--encoding", "cp932"]), (expected, "Shift_JIS".to_owned()));
    remove(&dir);
}

#[test]
fn the_summary_says_when_a_file_was_not_read_as_utf8() {
    let dir = student_folder("summary");
    let path = dir.join("レポート 1.md");
    let data = path.to_str().unwrap();
    std::fs::write(&path, fixture("pyramid-shift_jis-crlf.md")).unwrap();
    let out = report_checker(&["--lang", "ja", "check", "--data", data]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains(&format!("· {data}: Shift_JIS として読みました")), "{stdout}");
    let out = report_checker(&["--lang", "en", "check", "--data", data]);
    assert!(String::from_utf8_lossy(&out.stdout).contains(": read as Shift_JIS"));

    // `derive` from the data: the summary says so too; what it writes is UTF-8.
    let output = dir.join("出力 先");
    let out = report_checker(&[
        "--lang",
        "en",
        "derive",
        "--no-render",
        "--data",
        data,
        "-o",
        output.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{stdout}{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.starts_with(&format!("{data}: read as Shift_JIS\nwritten to ")), "{stdout}");
    let mut written = 0;
    for entry in std::fs::read_dir(output.join("fragments")).unwrap() {
        let bytes = std::fs::read(entry.unwrap().path()).unwrap();
        assert!(std::str::from_utf8(&bytes).is_ok() && !bytes.starts_with(b"\xEF\xBB\xBF"));
        written += 1;
    }
    assert!(written > 0);

    // UTF-8, with or without a BOM, needs no mention.
    std::fs::write(&path, fixture("pyramid-utf8-bom-crlf.md")).unwrap();
    let out = report_checker(&["--lang", "en", "check", "--data", data]);
    assert!(!String::from_utf8_lossy(&out.stdout).contains("read as"));
    remove(&dir);
}

#[test]
fn unreadable_text_names_the_place_and_what_to_do() {
    let dir = student_folder("refused");
    let path = dir.join("レポート 1.md");
    let data = path.to_str().unwrap();
    // Latin-1: neither UTF-8 nor Shift_JIS.
    std::fs::write(&path, b"V0 (0.0, 1.0, 0.0)\r\n# caf\xE9 au lait\r\n").unwrap();
    let out = report_checker(&["--lang", "en", "check", "--data", data]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(data), "{stderr}");
    assert!(stderr.contains("neither UTF-8 nor Shift_JIS"), "{stderr}");
    assert!(stderr.contains("line 2, column 6"), "{stderr}");
    assert!(stderr.contains("`--encoding shift_jis`"), "{stderr}");
    let out = report_checker(&["--lang", "ja", "check", "--data", data]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("2 行 6 文字目") && stderr.contains("エンコード: UTF-8"), "{stderr}");

    // Shift_JIS named as UTF-8: refused where UTF-8 stops.
    std::fs::write(&path, fixture("pyramid-shift_jis-crlf.md")).unwrap();
    let out = report_checker(&["--lang", "en", "check", "--data", data, "--encoding", "utf-8"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("not UTF-8 as `--encoding` says: line 1, column 3"), "{stderr}");

    // An encoding the kit does not know: the command line says which it does.
    let out = report_checker(&["check", "--data", data, "--encoding", "latin1"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("utf-16le") && stderr.contains("shift_jis"), "{stderr}");
    remove(&dir);
}
