//! Moodle out: the worksheet and the feedback zip of fake results, parsed back as Moodle's
//! upload parses them (the columns by name, the participant after "Participant ", each
//! folder split on its first four `_`).

use std::io::Read as _;
use std::path::Path;

use cg_core::lang::{Lang, t};
use serde_json::{Value, json};

use super::Name;
use super::output::{self, Settings};
use crate::Graded;

/// A result in the grader's shape, in `lang`: two checks of a1 (one failed), one of s.
fn result(entry: &str, student: &str, roster_name: Option<&str>, lang: Lang) -> Value {
    json!({
        "score": 3.0,
        "max_score": 4.0,
        "output": format!("{}: {student}\n{}: {entry}\na1: 2 / 3\ns: 1 / 1\n", t("学生番号", "student").get(lang), t("提出物", "submission").get(lang)),
        "tests": [
            {"name": format!("a1.t1.count: {}", t("頂点の数", "vertex count").get(lang)), "number": "a1.t1.count", "score": 2.0, "max_score": 2.0, "status": "passed", "output": ""},
            {"name": format!("a1.t2.winding: {}", t("面の向き", "winding").get(lang)), "number": "a1.t2.winding", "score": 0.0, "max_score": 1.0, "status": "failed",
             "output": format!("{}: F0 {{ V0, V3, V1 }}\n```not a fence```", t("期待", "expected").get(lang))},
            {"name": "s.t1.ambient: Ia·ka", "number": "s.t1.ambient", "score": 1.0, "max_score": 1.0, "status": "passed", "output": ""},
        ],
        "cg": {
            "student": student,
            "submission": entry,
            "roster": roster_name.map(|n| json!({"listed": true, "name": n, "claimed": null})),
            "assignments": {"a1": {"score": 2.0, "max_score": 3.0}, "s": {"score": 1.0, "max_score": 1.0}},
        },
    })
}

fn refused(entry: &str) -> Value {
    json!({
        "score": 0.0,
        "output": format!("student: ?\nsubmission: {entry}\nrefused: evil.zip: zip entry ../../x.rs has an unsafe path\n"),
        "tests": [],
        "cg": {"student": null, "submission": entry, "refused": "evil.zip: zip entry ../../x.rs has an unsafe path (absolute or ..)", "assignments": {}},
    })
}

fn graded(entry: &str, name: &str) -> Graded {
    Graded {
        entry: entry.into(),
        name: name.into(),
        score: 0.0,
        max_score: None,
        skipped: false,
        flag: None,
        problem: None,
        report: None,
    }
}

/// The fake results under `out`, as `cg grade` leaves them, and their list.
fn class(out: &Path) -> Vec<Graded> {
    let write = |name: &str, v: &Value| {
        std::fs::write(out.join(format!("{name}.json")), serde_json::to_string(v).unwrap())
            .unwrap();
    };
    let mut list = Vec::new();
    for (entry, name, roster) in [
        ("山田 太郎_1001_assignsubmission_file", "20260001", Some("山田 太郎")),
        ("Participant_1004_assignsubmission_file", "20260004", Some("Blind One")),
        ("John Smith_1003_assignsubmission_file_", "20260003", None),
        ("01-correct.zip", "20260009", None),
    ] {
        write(name, &result(entry, name, roster, Lang::En));
        let ja = result(entry, name, roster, Lang::Ja);
        output::write_feedback(
            &out.join("feedback").join(name),
            &ja,
            &result(entry, name, roster, Lang::En),
        )
        .unwrap();
        list.push(graded(entry, name));
    }
    // A picture the grader left for one student goes with the text.
    std::fs::write(out.join("feedback/20260001/a1-diff.png"), b"\x89PNG").unwrap();
    // A result with no feedback folder (graded before there were any): rendered from it.
    write("20260002", &result("Jane Roe_1002_assignsubmission_file_", "20260002", None, Lang::En));
    list.push(graded("Jane Roe_1002_assignsubmission_file_", "20260002"));
    write("_Mallory_1007_assignsubmission_file", &refused("Mallory_1007_assignsubmission_file"));
    list.push(graded("Mallory_1007_assignsubmission_file", "_Mallory_1007_assignsubmission_file"));
    list
}

/// Moodle's reading of a folder name in a feedback zip (`importziplib.php`:
/// `explode('_', $pathpart, 5)`): the participant ID and the plugin, or `None`.
fn moodle_reads(part: &str) -> Option<(String, String, String)> {
    let info: Vec<&str> = part.splitn(5, '_').collect();
    (info.len() >= 4 && info[1].bytes().all(|b| b.is_ascii_digit()) && !info[1].is_empty())
        .then(|| (info[1].to_owned(), info[2].to_owned(), info[3].to_owned()))
}

#[test]
fn the_worksheet_and_the_feedback_zip_round_trip() {
    let out = super::fake::scratch("out");
    let list = class(&out);
    for lang in [Lang::En, Lang::Ja] {
        let settings = Settings { lang, max_grade: 20.0, now: 1_700_000_000 };
        let written = output::write(&out, &list, &settings).unwrap().unwrap();
        assert_eq!(written, output::Written { participants: 5, graded: 4 });

        // The worksheet: a BOM, Moodle's columns, a row per participant by ID.
        let bytes = std::fs::read(out.join("moodle/grades.csv")).unwrap();
        assert!(bytes.starts_with(b"\xEF\xBB\xBF"), "no BOM");
        let mut reader = csv::Reader::from_reader(&bytes[3..]);
        let header: Vec<String> = reader.headers().unwrap().iter().map(str::to_owned).collect();
        assert_eq!(header, output::columns(lang));
        let col = |name: &str| header.iter().position(|h| h == name).unwrap();
        let c = output::columns(lang);
        let (id, full, grade, max, modified, comment) =
            (col(c[0]), col(c[1]), col(c[4]), col(c[5]), col(c[8]), col(c[9]));
        let rows: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
        let hidden = t("参加者", "Participant ");
        let hidden = hidden.get(lang);
        let got: Vec<(String, &str, &str, &str)> = rows
            .iter()
            .map(|r| {
                // What Moodle's upload does: strip "Participant " and read the number.
                let number = r[id].strip_prefix(hidden).unwrap().to_owned();
                (number, &r[full], &r[grade], &r[max])
            })
            .collect();
        assert_eq!(
            got,
            [
                ("1001".to_owned(), "山田 太郎", "15.00", "20.00"),
                ("1002".to_owned(), "Jane Roe", "15.00", "20.00"),
                ("1003".to_owned(), "John Smith", "15.00", "20.00"),
                // Blind marking: no name, even with the roster's.
                ("1004".to_owned(), "", "15.00", "20.00"),
                // Refused: no grade (Moodle keeps its own), the reason in the comment.
                ("1007".to_owned(), "Mallory", "", "20.00"),
            ]
        );
        assert!(rows.iter().all(|r| &r[modified] == "2023-11-14 22:13:20 UTC"));
        let first = &rows[0][comment];
        let expected = t("チェックの結果: 3 / 4（a1 2/3、s 1/1）", "Checks: 3 / 4 (a1 2/3, s 1/1)");
        let expected = expected.get(lang);
        assert!(first.starts_with(expected), "{first}");
        assert!(rows[4][comment].contains("../../x.rs"), "{}", &rows[4][comment]);

        // The zip: every folder is a participant's as Moodle reads it, named as downloaded.
        let zip_bytes = std::fs::read(out.join("moodle/feedback.zip")).unwrap();
        let mut zip = zip::ZipArchive::new(std::io::Cursor::new(zip_bytes)).unwrap();
        let mut files: Vec<(String, String)> = Vec::new();
        for i in 0..zip.len() {
            let mut f = zip.by_index(i).unwrap();
            let name = std::str::from_utf8(f.name_raw()).unwrap().to_owned();
            let t = f.last_modified().unwrap();
            assert_eq!((t.year(), t.month(), t.day(), t.hour()), (2023, 11, 14, 22), "{name}");
            if f.is_dir() {
                continue;
            }
            let mut text = String::new();
            let _ = f.read_to_string(&mut text);
            files.push((name, text));
        }
        let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(
            names,
            [
                "山田 太郎_1001_assignsubmission_file/a1-diff.png",
                "山田 太郎_1001_assignsubmission_file/feedback-en.md",
                "山田 太郎_1001_assignsubmission_file/feedback-ja.md",
                "Jane Roe_1002_assignsubmission_file_/feedback-en.md",
                "John Smith_1003_assignsubmission_file_/feedback-en.md",
                "John Smith_1003_assignsubmission_file_/feedback-ja.md",
                "Participant_1004_assignsubmission_file/feedback-en.md",
                "Participant_1004_assignsubmission_file/feedback-ja.md",
                "Mallory_1007_assignsubmission_file/feedback-en.md",
            ]
        );
        for (name, text) in &files {
            let folder = name.split('/').next().unwrap();
            let (participant, subtype, plugin) = moodle_reads(folder).unwrap();
            assert_eq!((subtype.as_str(), plugin.as_str()), ("assignsubmission", "file"));
            assert_eq!(Name::parse(folder).unwrap().participant, participant);
            let row = rows.iter().find(|r| r[id] == format!("{hidden}{participant}"));
            assert!(row.is_some(), "{name}: no worksheet row");
            if name.ends_with("-ja.md") {
                assert!(text.contains("# 採点結果") && text.contains("面の向き"), "{text}");
            } else if name.ends_with("-en.md") && !name.starts_with("Mallory") {
                assert!(text.contains("## Failed checks (1)"), "{text}");
                assert!(text.contains("### a1.t2.winding: winding"), "{text}");
                // The check's output, in a fence longer than the backticks in it.
                assert!(
                    text.contains("````text\nexpected: F0 { V0, V3, V1 }\n```not a fence```\n````"),
                    "{text}"
                );
                assert!(text.contains("- s.t1.ambient: Ia·ka"), "{text}");
            }
        }
    }
    // No Moodle participant: nothing written.
    let plain = [graded("01-correct.zip", "20260009")];
    let settings = Settings { lang: Lang::En, max_grade: 100.0, now: 0 };
    let _ = std::fs::remove_dir_all(out.join("moodle"));
    assert_eq!(output::write(&out, &plain, &settings).unwrap(), None);
    assert!(!out.join("moodle").exists());
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn times_are_written_in_utc_as_strtotime_reads_them() {
    assert_eq!(output::utc(0), "1970-01-01 00:00:00 UTC");
    assert_eq!(output::utc(951_782_400), "2000-02-29 00:00:00 UTC");
    assert_eq!(output::utc(1_700_000_000), "2023-11-14 22:13:20 UTC");
    assert_eq!(output::utc(4_102_444_799), "2099-12-31 23:59:59 UTC");
}

#[test]
fn the_identifier_is_what_moodles_upload_strips() {
    assert_eq!(output::identifier("1234567", Lang::En), "Participant 1234567");
    assert_eq!(output::identifier("1234567", Lang::Ja), "参加者1234567");
}

/// A Moodle full name that begins like a formula is text in the worksheet (Moodle matches the
/// rows by their identifier, which is unchanged).
#[test]
fn a_full_name_like_a_formula_is_text_in_the_worksheet() {
    let rows = [super::output::Row {
        participant: "777".to_owned(),
        full_name: "=HYPERLINK(\"http://evil\")".to_owned(),
        grade: Some(5.0),
        comment: String::new(),
    }];
    let settings = super::output::Settings { lang: Lang::En, max_grade: 10.0, now: 0 };
    let csv = super::output::worksheet(&rows, &settings).unwrap();
    let row = csv.lines().nth(1).unwrap();
    assert!(row.starts_with("Participant 777,\"'=HYPERLINK("), "{row}");
}

/// A result's report as `cg grade` writes it (`cg.report`): 12 numbers checked, V1 wrong.
fn with_report(mut result: Value) -> Value {
    result["cg"]["report"] = json!({
        "report": "report/report.md",
        "ok": false,
        "checked": 12,
        "mistakes": 1,
        "summary": "12 numbers checked; 1 mistake.",
        "findings": [{"line": 6, "item": "V1", "message": "line 6: V1: …"}],
        "text": "checking the report report/report.md\n  ✗ line 6: V1: written `(1.5, 0.0, 0.0)`\n12 numbers checked; 1 mistake.\n",
        "scored": false,
    });
    result
}

#[test]
fn a_refusal_a_failed_grading_and_a_report_are_each_said_as_what_they_are() {
    // A refusal is the submission's: said so, in both languages (both said "could not be
    // graded", as a grading that failed on the machine says).
    let no = refused("evil.zip");
    let en = output::comment(&no, Lang::En);
    assert!(en.starts_with("The submission was refused (evil.zip: zip entry ../../x.rs"), "{en}");
    let ja = output::comment(&no, Lang::Ja);
    assert!(ja.starts_with("提出物を受け付けられませんでした（理由: evil.zip"), "{ja}");
    let mut failed = refused("slow.zip");
    failed["cg"]["refused"] = Value::Null;
    failed["cg"]["error"] = json!("the build ran over its limit of 600 s");
    let en = output::comment(&failed, Lang::En);
    assert!(en.starts_with("Could not be graded (the build ran over its limit"), "{en}");
    // Its feedback has no score to read (it said `0 / -`), and no report section.
    for lang in [Lang::En, Lang::Ja] {
        let md = output::feedback_md(&no, lang);
        assert!(!md.contains("0 / -"), "{md}");
        let none = t("- 点数: なし（採点されていません", "- score: none (not graded");
        assert!(md.contains(none.get(lang)), "{md}");
        assert!(!md.contains("report/report.md"), "{md}");
    }

    // A graded result's report: the comment's last sentence, the feedback's last section (the
    // account in a fence, and the command that checks it at home).
    let graded = with_report(result("x", "20260001", None, Lang::En));
    let en = output::comment(&graded, Lang::En);
    assert!(
        en.ends_with(". Report (not scored): report/report.md: 12 numbers checked; 1 mistake."),
        "{en}"
    );
    let md = output::feedback_md(&graded, Lang::En);
    let section = md.split("## The report's numbers (not scored)\n\n").nth(1).expect("a section");
    assert!(section.starts_with("```text\nchecking the report report/report.md\n"), "{md}");
    assert!(section.contains("cargo run --release -- report check"), "{md}");
    // Without a report, where one would be found.
    let md = output::feedback_md(&result("x", "20260001", None, Lang::Ja), Lang::Ja);
    assert!(
        md.contains("提出物にレポート（report/report.md か report/report.tex）はありませんでした"),
        "{md}"
    );
}
