//! Reports handed in inside the submissions (`report/report.md` or `report/report.tex`, where
//! `cg report fill` writes them), read as `cg similarity` reads a class:
//!
//! - carol (a folder) and dave (a zip) hand in the stubs and a report each; dave's report has
//!   carol's vertices: flagged, naming carol, as a `--reports` file would be; with a `--reports`
//!   file for dave, that one is used instead and the summary says so;
//! - a report over the size limit is skipped with a note, and the submission is still compared;
//! - reports in Shift_JIS and UTF-16 are read as the text they are;
//! - a Moodle participant without `student.toml` is bound to the roster's student.

use std::io::Write as _;
use std::path::{Path, PathBuf};

use cg_assign::Variants;
use cg_core::lang::Lang;
use cg_harness::{StudentNumber, TableVersion};
use cg_similarity::inside::MAX_REPORT_BYTES;
use cg_similarity::{Settings, Submission, analyse, read};

const MODULES: [&str; 5] = ["a1", "a2", "a3", "a4", "s"];

const CAROL: &str = "20260001";
const DAVE: &str = "20260004";
const OTHERS: [(&str, &str); 5] = [
    ("frank", "20260005"),
    ("grace", "20260006"),
    ("heidi", "20260007"),
    ("ivan", "20260003"),
    ("judy", "20260002"),
];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

fn stub(m: &str) -> String {
    std::fs::read_to_string(root().join(format!("exercises/src/{m}.rs"))).unwrap()
}

fn temp(name: &str) -> PathBuf {
    let d =
        std::env::temp_dir().join(format!("cg-similarity-inside-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// A submission folder `dir/<entry>` holding the stubs, `student.toml` (when `student` is
/// given) and each of `reports` (a path beside `exercises/`, and its bytes).
fn folder(dir: &Path, entry: &str, student: Option<&str>, reports: &[(&str, Vec<u8>)]) {
    let base = dir.join(entry);
    std::fs::create_dir_all(base.join("exercises/src")).unwrap();
    for m in MODULES {
        std::fs::write(base.join(format!("exercises/src/{m}.rs")), stub(m)).unwrap();
    }
    if let Some(student) = student {
        let toml = format!("student = \"{student}\"\ntable = 1\n");
        std::fs::write(base.join("exercises/student.toml"), toml).unwrap();
    }
    for (path, bytes) in reports {
        let path = base.join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, bytes).unwrap();
    }
}

/// The same as a zip `dir/<entry>.zip`, everything one folder down (`kit/`).
fn zipped(dir: &Path, entry: &str, student: &str, reports: &[(&str, Vec<u8>)]) {
    let mut z =
        zip::ZipWriter::new(std::fs::File::create(dir.join(format!("{entry}.zip"))).unwrap());
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for m in MODULES {
        z.start_file(format!("kit/exercises/src/{m}.rs"), options).unwrap();
        z.write_all(stub(m).as_bytes()).unwrap();
    }
    z.start_file("kit/exercises/student.toml", options).unwrap();
    z.write_all(format!("student = \"{student}\"\n").as_bytes()).unwrap();
    for (path, bytes) in reports {
        z.start_file(format!("kit/{path}"), options).unwrap();
        z.write_all(bytes).unwrap();
    }
    z.finish().unwrap();
}

fn number(s: &str) -> StudentNumber {
    s.parse().unwrap()
}

/// A report's vertex table of `student`'s a1 vertices.
fn report(student: &str) -> String {
    let v = Variants::for_student(&number(student), TableVersion::DEFAULT);
    let mut r = "# レポート\n\n| 頂点 | x | y | z |\n|---|---|---|---|\n".to_owned();
    for (k, p) in cg_a1::SpecExt::expected_vertices(&v.a1).iter().enumerate() {
        r.push_str(&format!("| V{k} | {:.3} | {:.3} | {:.3} |\n", p.x, p.y, p.z));
    }
    r
}

fn index(class: &[Submission], name: &str) -> usize {
    class.iter().position(|s| s.name.starts_with(name)).unwrap_or_else(|| panic!("no {name}"))
}

fn stubs() -> std::collections::BTreeMap<String, String> {
    read::stubs(&root()).unwrap()
}

/// Carol (a folder) with her own report, dave (a zip) with a report of carol's vertices, and
/// four more with the stubs and no report.
fn class(dir: &Path) {
    folder(dir, "carol", Some(CAROL), &[("report/report.md", report(CAROL).into_bytes())]);
    // Dave's fill wrote both, at one time: report.md is read (the .tex is his own).
    zipped(
        dir,
        "dave",
        DAVE,
        &[
            ("report/report.tex", report(DAVE).into_bytes()),
            ("report/report.md", report(CAROL).into_bytes()),
        ],
    );
    for (name, student) in OTHERS {
        folder(dir, name, Some(student), &[]);
    }
}

#[test]
fn reports_inside_the_submissions_are_read_and_a_copied_one_is_flagged_with_whose() {
    let dir = temp("class");
    class(&dir);
    let class = read::class(&dir, false).unwrap();
    let [carol, dave] = ["carol", "dave"].map(|n| index(&class, n));
    // Dave's .tex is named as not read; nobody else has a note.
    let noted: Vec<usize> = (0..class.len()).filter(|&i| !class[i].notes.is_empty()).collect();
    assert_eq!(noted, [dave], "{class:#?}");
    assert!(class[dave].notes[0].en.starts_with("kit/report/report.tex is there too"));
    assert!(class.iter().all(|s| s.refused.is_none()), "{class:#?}");
    assert_eq!(class[carol].report_inside.as_deref(), Some("report/report.md"));
    assert_eq!(class[dave].report_inside.as_deref(), Some("kit/report/report.md"));
    assert_eq!(class[dave].report.as_deref(), Some(report(CAROL).as_str()));
    assert!(class.iter().filter(|s| s.report.is_some()).count() == 2);

    let a = analyse(&class, &stubs(), Settings::default());
    let found: Vec<(&str, &str)> = a
        .cross
        .iter()
        .map(|c| (class[c.submission].name.as_str(), c.finding.part.as_str()))
        .collect();
    assert_eq!(found, [("dave.zip", "report:a1")], "{:#?}", a.cross);
    assert_eq!(a.cross[0].finding.matches, number(CAROL));
    assert_eq!(a.cross[0].sources, [carol]);
    // The note says which file: the one inside the submission.
    let note = cg_similarity::output::cross_note(&a.cross[0], &class[dave], Lang::En);
    assert!(note.contains("the report (a1, kit/report/report.md in the submission)"), "{note}");
    assert!(read::set_aside(&class).is_none());

    // With a --reports file for dave (his own), that one is used, and the summary says so.
    let reports = dir.with_extension("reports");
    let _ = std::fs::remove_dir_all(&reports);
    std::fs::create_dir_all(&reports).unwrap();
    std::fs::write(reports.join(format!("{DAVE}.md")), report(DAVE)).unwrap();
    let mut class = class;
    assert!(read::reports(&reports, &mut class).unwrap().is_empty());
    assert_eq!(class[dave].report.as_deref(), Some(report(DAVE).as_str()));
    assert_eq!(class[dave].report_inside, None);
    assert_eq!(class[dave].report_set_aside.as_deref(), Some("kit/report/report.md"));
    let note = read::set_aside(&class).expect("the summary's note");
    assert!(note.en.contains("used for 1 students whose submissions hold one too"), "{}", note.en);
    assert!(note.ja.contains("--reports"), "{}", note.ja);
    let a = analyse(&class, &stubs(), Settings::default());
    assert!(a.cross.is_empty(), "{:#?}", a.cross);

    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&reports);
}

#[test]
fn an_oversized_report_is_skipped_with_a_note_not_a_failure() {
    let dir = temp("big");
    let big = vec![b'1'; usize::try_from(MAX_REPORT_BYTES).unwrap() + 1];
    folder(&dir, "carol", Some(CAROL), &[("report/report.md", big.clone())]);
    zipped(&dir, "dave", DAVE, &[("report/report.tex", big)]);
    // At the limit exactly: read.
    let at_limit = vec![b'x'; usize::try_from(MAX_REPORT_BYTES).unwrap()];
    folder(&dir, "erin", Some("20260008"), &[("report/report.md", at_limit)]);
    let class = read::class(&dir, false).unwrap();
    for (name, path) in [("carol", "report/report.md"), ("dave", "kit/report/report.tex")] {
        let s = &class[index(&class, name)];
        assert!(s.refused.is_none() && s.modules.len() == 5, "{s:#?}");
        assert_eq!(s.report, None, "{name}");
        assert_eq!(s.notes.len(), 1, "{name}: {:?}", s.notes);
        let note = &s.notes[0];
        assert!(note.en.starts_with(&format!("{path} is too big and was skipped")), "{note:?}");
        assert!(note.ja.contains("大きすぎる"), "{note:?}");
    }
    let erin = &class[index(&class, "erin")];
    assert!(erin.notes.is_empty() && erin.report.as_ref().is_some_and(|r| r.len() == (4 << 20)));
    // Still compared.
    let a = analyse(&class, &stubs(), Settings::default());
    assert_eq!(a.fingerprints.len(), 3);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn reports_in_shift_jis_and_utf16_are_read_as_their_text() {
    let dir = temp("encodings");
    let text = "# レポート 頂点\n| V0 | 1.250 | 0.000 | 2.500 |\n";
    // "# レポート 頂点" in Shift_JIS (CP932), then the rest (ASCII).
    let mut sjis = vec![
        0x23, 0x20, 0x83, 0x8c, 0x83, 0x7c, 0x81, 0x5b, 0x83, 0x67, 0x20, 0x92, 0xb8, 0x93, 0x5f,
    ];
    sjis.extend_from_slice(text.split_once('\n').unwrap().1.as_bytes());
    sjis.splice(15..15, *b"\n");
    assert!(std::str::from_utf8(&sjis).is_err(), "premise: not UTF-8");
    let mut utf16 = vec![0xFF, 0xFE];
    for unit in text.encode_utf16() {
        utf16.extend(unit.to_le_bytes());
    }
    folder(&dir, "carol", Some(CAROL), &[("report/report.md", sjis)]);
    zipped(&dir, "dave", DAVE, &[("report/report.tex", utf16)]);
    let class = read::class(&dir, false).unwrap();
    for name in ["carol", "dave"] {
        let s = &class[index(&class, name)];
        assert!(s.notes.is_empty(), "{name}: {:?}", s.notes);
        assert_eq!(s.report.as_deref(), Some(text), "{name}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_moodle_participant_without_student_toml_is_bound_by_the_roster() {
    let dir = temp("moodle");
    let yamada = "山田 太郎_123456_assignsubmission_file";
    folder(&dir, yamada, None, &[("report/report.md", report(CAROL).into_bytes())]);
    folder(&dir, "Jane Roe_123457_assignsubmission_file", Some(DAVE), &[]);
    let mut class = read::class(&dir, false).unwrap();
    let (y, j) = (index(&class, "山田"), index(&class, "Jane"));
    assert!(class[y].refused.as_ref().is_some_and(|r| r.en.contains("student.toml")));
    assert_eq!(class[y].report_inside.as_deref(), Some("report/report.md"));
    let roster = cg_grade::roster::Roster::parse(
        "student,name,entry\n20260009,山田 太郎,123456\n20260010,Jane Roe,123457\n",
    )
    .unwrap();
    let notes = read::bind(&mut class, &roster);
    assert_eq!(class[y].refused, None);
    assert_eq!(class[y].number(), "20260009");
    // The roster's number wins over student.toml's, with a note.
    assert_eq!(class[j].number(), "20260010");
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(notes[0].en.contains(DAVE) && notes[0].en.contains("20260010"), "{notes:?}");
    // A roster that names none of the entries (the wrong file, or names in its entry column)
    // is said, not silently ignored.
    let wrong =
        cg_grade::roster::Roster::parse("student,name,entry\n20260009,山田 太郎,yamada\n").unwrap();
    let notes = read::bind(&mut class, &wrong);
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(notes[0].ja.contains("名簿のどの行も提出物に結びつきませんでした"), "{notes:?}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A roster entry whose `student.toml` does not read (no quotes round the number, a stray key)
/// is the roster's student, with a note that says why its file was set aside; it used to be
/// compared as "-", its variant's numbers unchecked. Off the roster it stays refused.
#[test]
fn a_roster_entry_with_a_malformed_student_toml_is_the_rosters_student() {
    let dir = temp("malformed");
    folder(&dir, "carol", None, &[]);
    std::fs::write(dir.join("carol/exercises/student.toml"), "student = 20260001\n").unwrap();
    folder(&dir, "erin", None, &[]);
    std::fs::write(dir.join("erin/exercises/student.toml"), "number = \"20260002\"\n").unwrap();
    let mut class = read::class(&dir, false).unwrap();
    let (c, e) = (index(&class, "carol"), index(&class, "erin"));
    for i in [c, e] {
        assert!(class[i].refused.is_some() && class[i].refused_student_toml, "{:?}", class[i]);
    }
    let roster =
        cg_grade::roster::Roster::parse("student,name,entry\n20260001,Carol,carol\n").unwrap();
    let notes = read::bind(&mut class, &roster);
    assert_eq!(class[c].refused, None);
    assert_eq!(class[c].number(), CAROL);
    assert_eq!(notes.len(), 1, "{notes:?}");
    assert!(
        notes[0].en.starts_with("carol: ") && notes[0].en.contains("roster's number 20260001"),
        "{notes:?}"
    );
    assert!(notes[0].ja.contains("名簿の番号 20260001 を使います"), "{notes:?}");
    // Not on the roster: refused as before, compared as "-".
    assert!(class[e].refused.is_some(), "{:?}", class[e]);
    assert_eq!(class[e].number(), "-");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A file in --reports that cannot be read (a PDF) is a note on its student's submission, not
/// the end of the whole run; a report of 2 MB is read (the limit is 4 MiB, as documented).
#[test]
fn a_report_that_cannot_be_read_is_a_note_not_the_end_of_the_run() {
    let dir = temp("reports-bad");
    folder(&dir, "carol", Some(CAROL), &[]);
    folder(&dir, "dave", Some(DAVE), &[]);
    let mut class = read::class(&dir, false).unwrap();
    let reports = dir.with_extension("given");
    std::fs::create_dir_all(&reports).unwrap();
    std::fs::write(reports.join(format!("{CAROL}.pdf")), b"%PDF-1.7\n\x80\xa0\xfd\xfe\xff\x80")
        .unwrap();
    let long = format!("{}\n", report(DAVE)).repeat(2_000_000 / report(DAVE).len().max(1));
    std::fs::write(reports.join(format!("{DAVE}.md")), &long).unwrap();
    let unmatched = read::reports(&reports, &mut class).expect("the run goes on");
    assert!(unmatched.is_empty(), "{unmatched:?}");
    let (c, d) = (index(&class, "carol"), index(&class, "dave"));
    assert!(class[c].report.is_none() && !class[c].notes.is_empty(), "{:?}", class[c].notes);
    assert!(class[c].notes[0].en.contains(".pdf"), "{:?}", class[c].notes);
    assert!(class[d].report.as_ref().is_some_and(|r| r.len() > 1_000_000), "the 2 MB report");
    let _ = std::fs::remove_dir_all(&dir);
    let _ = std::fs::remove_dir_all(&reports);
}
