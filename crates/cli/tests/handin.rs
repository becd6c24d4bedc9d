//! `cg handin`: the zip holds exactly what grading reads — the six files and the report grading
//! would choose — reads back with the `zip` crate and (where the instructors' commands are
//! built) as `cg grade` reads a submission; what grading would refuse, or no student number,
//! stops it with a message and no zip.

mod common;

use std::path::Path;
use std::time::{Duration, SystemTime};

use common::{cg, root, scratch};

const MODULES: [&str; 5] = ["a1", "a2", "a3", "a4", "s"];

/// A student's folder: the kit's stubs as exercises/src, a student number, and both reports,
/// report.tex changed last.
fn student(dir: &Path) {
    std::fs::create_dir_all(dir.join("exercises/src")).unwrap();
    for m in MODULES {
        let from = root().join(format!("exercises/src/{m}.rs"));
        std::fs::copy(from, dir.join(format!("exercises/src/{m}.rs"))).unwrap();
    }
    std::fs::write(dir.join("exercises/student.toml"), "student = \"20261234\"\n").unwrap();
    std::fs::create_dir_all(dir.join("report")).unwrap();
    std::fs::write(dir.join("report/report.md"), "# レポート\n\nV0 (0.0, 1.0, 0.0)\n").unwrap();
    std::fs::write(dir.join("report/report.tex"), "\\section{レポート}\n").unwrap();
    let earlier = SystemTime::now() - Duration::from_secs(3600);
    let md = std::fs::File::options().write(true).open(dir.join("report/report.md")).unwrap();
    md.set_modified(earlier).unwrap();
    // The PDF made from report.md before report.tex was changed: older than the report taken.
    std::fs::write(dir.join("report/report.pdf"), PDF).unwrap();
    let pdf = std::fs::File::options().write(true).open(dir.join("report/report.pdf")).unwrap();
    pdf.set_modified(earlier).unwrap();
}

/// A report's PDF: bytes that are no text.
const PDF: &[u8] = b"%PDF-1.7\n%\xe2\xe3\xcf\xd3\n1 0 obj\n<< >>\nendobj\n\x00\xff%%EOF\n";

fn names(zip: &Path) -> Vec<String> {
    let mut archive = zip::ZipArchive::new(std::fs::File::open(zip).unwrap()).unwrap();
    (0..archive.len()).map(|k| archive.by_index(k).unwrap().name().unwrap().into_owned()).collect()
}

#[test]
fn the_zip_holds_what_grading_reads_and_reads_back() {
    let dir = scratch("handin", "reads_back");
    student(&dir);
    // (A scratch folder holds no kit to build the checks in: the handout's test runs them.)
    let out = cg(&dir, &["handin", "--no-check"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}\n{}", String::from_utf8_lossy(&out.stderr));
    let zip = dir.join("handin/20261234.zip");
    assert!(stdout.contains("wrote handin/20261234.zip ("), "{stdout}");
    assert!(stdout.contains("report/report.md is left out"), "{stdout}");
    assert!(stdout.contains("`cargo run --release -- check`"), "{stdout}");
    let mut expected: Vec<String> = vec!["exercises/student.toml".to_owned()];
    expected.extend(MODULES.map(|m| format!("exercises/src/{m}.rs")));
    expected.push("report/report.tex".to_owned());
    expected.push("report/report.pdf".to_owned());
    assert_eq!(names(&zip), expected);
    assert!(stdout.contains("report/report.pdf is older than report/report.tex"), "{stdout}");
    // Every file's bytes come back as they are.
    let mut archive = zip::ZipArchive::new(std::fs::File::open(&zip).unwrap()).unwrap();
    for name in &expected {
        let mut bytes = Vec::new();
        std::io::Read::read_to_end(&mut archive.by_name(name).unwrap(), &mut bytes).unwrap();
        assert_eq!(bytes, std::fs::read(dir.join(name)).unwrap(), "{name}");
    }
    // As `cg grade` reads a submission: all six files.
    #[cfg(feature = "instructor")]
    {
        let files = cg_grade::submission::read(&zip).expect("read as a submission");
        assert_eq!(files.modules.len(), 5);
        assert_eq!(files.student_toml.as_deref(), Some(&b"student = \"20261234\"\n"[..]));
        // The report read is the text one; the PDF beside it is set aside without a note.
        let entry = cg_grade::moodle::input::Entry::single(&zip);
        let (found, notes) = cg_grade::inside::report(&entry, cg_grade::inside::MAX_REPORT_BYTES);
        assert_eq!(found.map(|f| f.path), Some("report/report.tex".to_owned()), "{notes:?}");
        assert!(notes.is_empty(), "{notes:?}");
    }

    // In Japanese, to a file of one's choosing; report.md alone is taken.
    std::fs::remove_file(dir.join("report/report.tex")).unwrap();
    let out = cg(&dir, &["--lang", "ja", "handin", "--no-check", "--out", "up.zip"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    assert!(stdout.starts_with("up.zip を書きました（"), "{stdout}");
    assert!(stdout.contains("次に: この zip を Moodle に上げます"), "{stdout}");
    // Made at the same time as report.md: not older.
    assert!(!stdout.contains("より古いファイル"), "{stdout}");
    let names = names(&dir.join("up.zip"));
    assert_eq!(names[names.len() - 2..], ["report/report.md", "report/report.pdf"]);
}

/// A PDF alone is said to be unchecked by grading; a PDF too big for the zip is left out, with
/// what to do; a PDF newer than the report is taken without a note.
#[test]
fn the_reports_pdf_goes_in_when_it_can() {
    let dir = scratch("handin", "pdf");
    student(&dir);
    std::fs::remove_file(dir.join("report/report.md")).unwrap();
    std::fs::remove_file(dir.join("report/report.tex")).unwrap();
    let out = cg(&dir, &["handin", "--no-check"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    assert!(stdout.contains("only the PDF: grading cannot check the numbers of a PDF"), "{stdout}");
    assert_eq!(
        names(&dir.join("handin/20261234.zip")).last().map(String::as_str),
        Some("report/report.pdf")
    );

    // Made after the report: no note. Too big: left out, the zip still written.
    std::fs::write(dir.join("report/report.md"), "# Report\n").unwrap();
    let pdf = std::fs::File::options().write(true).open(dir.join("report/report.pdf")).unwrap();
    pdf.set_modified(SystemTime::now() + Duration::from_secs(60)).unwrap();
    let out = cg(&dir, &["handin", "--no-check"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success() && !stdout.contains("older"), "{stdout}");
    pdf.set_len((20 << 20) + 1).unwrap();
    let out = cg(&dir, &["--lang", "ja", "handin", "--no-check"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}");
    assert!(
        stdout
            .contains("report/report.pdf は 20.0 MiB あり、zip には入れていません（上限 20 MiB）"),
        "{stdout}"
    );
    assert_eq!(
        names(&dir.join("handin/20261234.zip")).last().map(String::as_str),
        Some("report/report.md")
    );
}

#[test]
fn what_grading_refuses_or_no_student_number_stops_it() {
    let dir = scratch("handin", "refused");
    student(&dir);
    // A file that reads outside itself: grading would score the whole submission 0.
    let a1 = dir.join("exercises/src/a1.rs");
    let text = std::fs::read_to_string(&a1).unwrap();
    std::fs::write(&a1, format!("{text}\nconst X: &str = include_str!(\"../../secret.txt\");\n"))
        .unwrap();
    let out = cg(&dir, &["handin"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("exercises/src/a1.rs:") && stderr.contains("include_str!"), "{stderr}");
    assert!(!dir.join("handin").exists());
    // The same saved as Shift_JIS (grading converts it, then refuses it).
    // (Its ASCII, and `ー` as Shift_JIS's 81 5B: not UTF-8; the stub's other Japanese left out.)
    let sjis = |text: &str| {
        text.chars()
            .flat_map(|c| match c {
                'ー' => vec![0x81, 0x5B],
                c if c.is_ascii() => vec![c as u8],
                _ => vec![],
            })
            .collect::<Vec<u8>>()
    };
    let hostile = format!("// ー\n{text}\nconst X: &str = include_str!(\"../../secret.txt\");\n");
    std::fs::write(&a1, sjis(&hostile)).unwrap();
    let out = cg(&dir, &["handin"]);
    assert_eq!(out.status.code(), Some(2), "{}", String::from_utf8_lossy(&out.stdout));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("exercises/src/a1.rs:") && stderr.contains("include_str!"), "{stderr}");
    assert!(!dir.join("handin").exists());
    // A module kept in a file of its own: grading reads only the assignments' files.
    std::fs::write(&a1, format!("{text}\nmod helper;\n")).unwrap();
    let out = cg(&dir, &["handin"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("`mod helper;` reads another file"), "{stderr}");
    assert!(!dir.join("handin").exists());
    // Shift_JIS with nothing refused: handed in as it is, with the note to save it as UTF-8.
    std::fs::write(&a1, sjis(&format!("// ー\n{text}"))).unwrap();
    let out = cg(&dir, &["handin", "--no-check"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.starts_with("exercises/src/a1.rs is saved as Shift_JIS."), "{stdout}");
    std::fs::remove_dir_all(dir.join("handin")).unwrap();
    // No student number recorded: says how to record it.
    std::fs::write(&a1, text).unwrap();
    std::fs::remove_file(dir.join("exercises/student.toml")).unwrap();
    let out = cg(&dir, &["handin"]);
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("`cargo run --release -- assignment --student <student number> --save`"),
        "{stderr}"
    );
    assert!(!dir.join("handin").exists());
}
