//! `cg report …` and `report-checker` from the command line, on the kit's own (stub) exercises
//! and on a data file.

mod common;

use common::{cg, root, scratch};

#[test]
fn fill_on_the_stubs_writes_a_report_that_says_what_is_missing() {
    let dir = scratch("report", "stubs");
    let out_dir = dir.join("report");
    let out = cg(
        &root(),
        &[
            "--lang",
            "ja",
            "report",
            "fill",
            "--student",
            "20250003",
            "--no-render",
            "-o",
            out_dir.to_str().unwrap(),
        ],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}\n{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("a1.t1"), "the summary names the missing tasks:\n{stdout}");
    let md = std::fs::read_to_string(out_dir.join("report.md")).unwrap();
    assert!(md.contains("まだ導出できません") && md.contains("a1.t1"), "{md}");
    assert!(!md.contains("{{"), "every placeholder filled");
    assert!(md.contains("20250003"));
    let tex = std::fs::read_to_string(out_dir.join("report.tex")).unwrap();
    assert!(tex.contains("\\begin{document}") && !tex.contains("{{"), "{tex}");
}

#[test]
fn check_with_data_alone_names_the_slides_wrong_normals() {
    let data = root().join("assets/report/lecture-pyramid.md");
    for (lang, word) in [("en", "F0 normal"), ("ja", "F0")] {
        let out =
            cg(&root(), &["--lang", lang, "report", "check", "--data", data.to_str().unwrap()]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(1), "mistakes fail the command:\n{stdout}");
        assert!(stdout.contains(word), "{stdout}");
        for face in ["F1", "F2", "F3"] {
            assert!(stdout.contains(face), "{face}:\n{stdout}");
        }
        assert!(!stdout.contains("F4") && !stdout.contains("F5"), "F4, F5 are right:\n{stdout}");
        assert!(stdout.contains("0.4856"), "the derived value is named:\n{stdout}");
    }
    // The same table with the normals that do follow: clean, exit 0.
    let dir = scratch("report", "data-clean");
    let text = std::fs::read_to_string(&data)
        .unwrap()
        .replace("0.53, 0.85", "0.49, 0.87")
        .replace("0.53, -0.85", "0.49, -0.87")
        .replace("{ 0.85, 0.53", "{ 0.87, 0.49")
        .replace("{ -0.85, 0.53", "{ -0.87, 0.49");
    let fixed = dir.join("pyramid.md");
    std::fs::write(&fixed, text).unwrap();
    let out = cg(&dir, &["--lang", "en", "report", "check", "--data", "pyramid.md"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    // A report in which no number could be checked (empty, or its table in columns the checker
    // does not read, with a wrong z) is no success: exit 1, and the summary says what to write.
    std::fs::write(dir.join("empty.md"), "").unwrap();
    std::fs::write(
        dir.join("columns.md"),
        "| | x | y | z |\n|---|---|---|---|\n| V0 | 0.0 | 1.0 | 0.0 |\n| V1 | 1.0 | -0.8 | 9.0 |\n",
    )
    .unwrap();
    for (report, lang, words) in [
        ("empty.md", "en", "no number was checked"),
        ("columns.md", "ja", "確かめられた数値は 1 つもありません"),
    ] {
        let out = cg(&dir, &["--lang", lang, "report", "check", report, "--data", "pyramid.md"]);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert_eq!(out.status.code(), Some(1), "{report}: {stdout}");
        assert!(stdout.contains(words) && stdout.contains("V0 (0.0, 1.0, 0.0)"), "{stdout}");
    }
}

#[test]
fn bad_input_gets_a_clear_error_not_a_panic() {
    let dir = scratch("report", "bad");
    std::fs::write(dir.join("broken.md"), "V0 (0.0, 1.0)\nF0 { V0, V1 }\n").unwrap();
    let out = cg(&dir, &["--lang", "en", "report", "check", "--data", "broken.md"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    // Bad input is exit status 2, as report-checker says for the same file.
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("line 1") && stderr.contains("line 2"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    let out = cg(&dir, &["--lang", "ja", "report", "check", "missing.md", "--data", "broken.md"]);
    assert_eq!(out.status.code(), Some(2));
    // A data file past the 8 MiB a report may have is refused before it is read (63 MiB of
    // vertex lines took 1.9 GB).
    let big = "V0 (0.0, 1.0, 0.0)\n".repeat((8 << 20) / 19 + 1);
    std::fs::write(dir.join("big.md"), big).unwrap();
    let out = cg(&dir, &["--lang", "en", "report", "check", "--data", "big.md"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("big.md") && stderr.contains("8 MiB"), "{stderr}");
    // With --json, the error is JSON on stdout too (it was plain text only).
    let out = cg(&dir, &["--lang", "en", "report", "check", "--data", "broken.md", "--json"]);
    assert_eq!(out.status.code(), Some(2));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    assert!(json["error"].as_str().unwrap().contains("line 1"), "{json}");
    // --student means nothing beside --data: refused, not silently ignored (even when malformed).
    let out =
        cg(&dir, &["--lang", "en", "report", "check", "--data", "broken.md", "--student", "12ab"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--student") && stderr.contains("--data"), "{stderr}");
    // A number that starts with '-' reaches the kit's own check of student numbers.
    let out = cg(&dir, &["--lang", "en", "report", "derive", "--student", "-12345678"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("8 digits") && !stderr.contains("unexpected argument"), "{stderr}");
    let out = cg(&dir, &["--lang", "en", "report", "check", "missing.md", "--student", "20250003"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("missing.md") && !stderr.contains("panicked"), "{stderr}");
}

#[test]
fn derive_writes_the_figures_of_a_data_file() {
    let dir = scratch("report", "derive-data");
    let data = root().join("assets/report/lecture-pyramid.md");
    let out = cg(&dir, &["report", "derive", "--data", data.to_str().unwrap(), "-o", "derived"]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    for name in [
        "a1-front.svg",
        "a1-top.svg",
        "a1-side.svg",
        "a1-perspective.svg",
        "fragments/a1.face_table.md",
    ] {
        assert!(dir.join("derived").join(name).is_file(), "{name}");
    }
    let faces = std::fs::read_to_string(dir.join("derived/fragments/a1.face_table.md")).unwrap();
    assert!(faces.contains("{ 0.000, 0.486, 0.874 }"), "{faces}");
}
