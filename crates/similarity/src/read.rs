//! The class, read exactly as `cg grade` reads it ([`cg_grade::moodle::input`]: a folder of
//! folders and zips, or Moodle's "download all submissions", each read as hostile input and
//! bounded), the stubs the students were given, the reports (inside each submission, or from a
//! folder of their own) and the roster.

use std::collections::BTreeMap;
use std::path::Path;

use cg_core::lang::Text;
use cg_grade::submission::{MAX_FILE_BYTES, MODULES};
use cg_harness::TableVersion;

use crate::Submission;

/// The submissions of `path` (see [`cg_grade::moodle::input::entries`]), each marked
/// `reference` or not, this year's each with the report inside it ([`crate::inside`]). An
/// entry that cannot be read is kept with the reason (and compared with nothing).
///
/// # Errors
/// The folder or zip itself cannot be read.
pub fn class(path: &Path, reference: bool) -> Result<Vec<Submission>, Text> {
    let entries = cg_grade::moodle::input::entries(path)?;
    Ok(entries
        .iter()
        .map(|entry| {
            let mut s = Submission { name: entry.name.clone(), reference, ..Submission::default() };
            match entry.read() {
                Ok(files) => {
                    if !reference {
                        let (found, notes) =
                            crate::inside::report(entry, crate::inside::MAX_REPORT_BYTES);
                        if let Some(found) = found {
                            s.report = Some(found.text);
                            s.report_inside = Some(found.path);
                        }
                        s.notes = notes;
                    }
                    for (m, bytes) in files.modules {
                        s.modules.insert(m, String::from_utf8_lossy(&bytes).into_owned());
                    }
                    match files.student_toml.as_deref().map(student_file) {
                        Some(Ok(file)) => s.student = Some(file),
                        Some(Err(why)) => s.refused = Some(why),
                        None => s.refused = Some(no_student_toml()),
                    }
                    s.refused_student_toml = s.refused.is_some();
                }
                Err(why) => s.refused = Some(why),
            }
            s
        })
        .collect())
}

fn no_student_toml() -> Text {
    Text::new("exercises/student.toml がありません", "exercises/student.toml is missing")
}

/// Binds this year's submissions to the roster's students, as `cg grade --roster` does: an
/// entry on the roster is the roster's student, whatever its `student.toml` says; an entry
/// without a usable `student.toml` (none, or one that does not read) is the roster's student
/// too (with the latest table), where `cg grade` would refuse it, since only the number is
/// needed here. Returns a note for each number changed and each `student.toml` set aside.
#[must_use]
pub fn bind(class: &mut [Submission], roster: &cg_grade::roster::Roster) -> Vec<Text> {
    let mut notes = Vec::new();
    let mut bound = 0;
    for s in class.iter_mut().filter(|s| !s.reference) {
        let Some(row) = roster.find(&s.name) else { continue };
        bound += 1;
        match &mut s.student {
            Some(file) if file.student != row.student => {
                notes.push(Text::new(
                    format!(
                        "{}: student.toml は {}、名簿は {}: 名簿の番号を使います",
                        s.name, file.student, row.student
                    ),
                    format!(
                        "{}: student.toml says {}, the roster {}: the roster's is used",
                        s.name, file.student, row.student
                    ),
                ));
                file.student = row.student.clone();
            }
            Some(_) => {}
            None if s.refused_student_toml => {
                if let Some(why) = s.refused.take().filter(|why| *why != no_student_toml()) {
                    notes.push(Text::new(
                        format!("{}: {}: 名簿の番号 {} を使います", s.name, why.ja, row.student),
                        format!(
                            "{}: {}: the roster's number {} is used",
                            s.name, why.en, row.student
                        ),
                    ));
                }
                s.student = Some(cg_assign::StudentFile {
                    student: row.student.clone(),
                    table: TableVersion::DEFAULT,
                });
                s.refused = None;
                s.refused_student_toml = false;
            }
            None => {}
        }
    }
    // A roster that names none of the entries is the wrong file or the wrong column: said,
    // not ignored.
    if bound == 0 && class.iter().any(|s| !s.reference) {
        notes.push(Text::new(
            "名簿のどの行も提出物に結びつきませんでした。名簿の entry 列には、提出物のフォルダ名・zip の名前・Moodle の参加者 ID を書きます（名簿は使っていません）",
            "no entry of the roster names a submission: its entry column holds the submissions' folder or zip names, or Moodle's participant IDs (the roster was not used)",
        ));
    }
    notes
}

/// `exercises/student.toml` from its bytes, as the kit reads the student's own record
/// ([`cg_assign::parse_student_file`]: UTF-8, UTF-16 or Shift_JIS, every mistake in both
/// languages).
///
/// # Errors
/// Not text or not TOML, no `student` in quotes, an unknown key, a malformed number or an
/// unknown table.
pub fn student_file(bytes: &[u8]) -> Result<cg_assign::StudentFile, Text> {
    cg_assign::parse_student_file(bytes, "exercises/student.toml").map_err(|e| e.text())
}

/// The stubs as handed out: `<kit>/exercises/src/<m>.rs` for every module (`cg sync-stubs`
/// writes them from solutions/ with the solutions taken out; the handout copies them).
///
/// # Errors
/// A stub is missing, too big or unreadable.
pub fn stubs(kit: &Path) -> Result<BTreeMap<String, String>, Text> {
    let mut out = BTreeMap::new();
    for m in MODULES {
        let path = kit.join("exercises/src").join(format!("{m}.rs"));
        out.insert((*m).to_owned(), text_file(&path, MAX_FILE_BYTES)?);
    }
    Ok(out)
}

/// A text file of at most `limit` bytes, in any encoding the kit reads.
fn text_file(path: &Path, limit: u64) -> Result<String, Text> {
    let shown = path.display();
    let bytes = cg_core::text::read_bounded(path, limit).map_err(|e| {
        let why = e.text_without_option();
        Text::new(
            format!("{shown} を読めません: {}", why.ja),
            format!("cannot read {shown}: {}", why.en),
        )
    })?;
    cg_core::text::decode(&bytes, None).map(|(text, _)| text).map_err(|e| {
        let why = e.text_without_option();
        Text::new(format!("{shown}: {}", why.ja), format!("{shown}: {}", why.en))
    })
}

/// Attaches the reports in `dir` to this year's submissions: each file whose name holds a
/// student number (`20260001.md`, `report-20260001.txt`) goes to that student's submissions,
/// in place of a report found inside one (kept in `report_set_aside`: [`set_aside`]).
/// Returns the files that matched no one.
///
/// A report that cannot be read (over [`crate::inside::MAX_REPORT_BYTES`], not text: a PDF)
/// is a note on its students' submissions, which are compared without it, as a report inside a
/// submission is.
///
/// # Errors
/// The folder cannot be read.
pub fn reports(dir: &Path, class: &mut [Submission]) -> Result<Vec<String>, Text> {
    let folder = crate::inside::folder(dir, crate::inside::MAX_REPORT_BYTES)?;
    let mut unmatched = folder.unnamed;
    for (number, (path, found)) in folder.by_student {
        let mut owners = class
            .iter_mut()
            .filter(|s| {
                !s.reference && s.student.as_ref().is_some_and(|f| f.student.as_str() == number)
            })
            .peekable();
        if owners.peek().is_none() {
            unmatched
                .push(path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into()));
            continue;
        }
        for s in owners {
            match &found {
                Ok(found) => {
                    s.report = Some(found.text.clone());
                    s.report_file = Some(path.display().to_string());
                    s.report_set_aside = s.report_inside.take().or(s.report_set_aside.take());
                }
                Err(why) => s.notes.push(why.clone()),
            }
        }
    }
    unmatched.sort();
    Ok(unmatched)
}

/// What the summary says once when `--reports` had a report for students whose submissions
/// hold one too: that the `--reports` one was used, for how many.
#[must_use]
pub fn set_aside(class: &[Submission]) -> Option<Text> {
    let n = class.iter().filter(|s| s.report_set_aside.is_some()).count();
    (n > 0).then(|| {
        Text::new(
            format!(
                "提出物の中にもレポートがある {n} 人は --reports のレポートを使いました（提出物の中のものは使いません）"
            ),
            format!(
                "the --reports report was used for {n} students whose submissions hold one too (theirs was set aside)"
            ),
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn student_files_and_report_names_are_read() {
        let f = student_file(b"student = \"20260001\"\ntable = 1\n").unwrap();
        assert_eq!(f.student.as_str(), "20260001");
        assert!(student_file(b"student = 20260001\n").is_err());
        assert!(student_file(b"student = \"2026\"\n").is_err());
        assert!(student_file(b"student = \"20260001\"\ntable = 99\n").is_err());
        // As the kit reads the student's own record: UTF-16 (Notepad's "Unicode"), an unknown
        // key refused, a number without quotes told how to write it, in Japanese too.
        let mut utf16 = vec![0xFF, 0xFE];
        utf16.extend("student = \"20260001\"\r\n".encode_utf16().flat_map(u16::to_le_bytes));
        assert_eq!(student_file(&utf16).unwrap().student.as_str(), "20260001");
        let e = student_file(b"student = \"20260001\"\nname = \"x\"\n").unwrap_err();
        assert!(e.ja.contains("`name` というキーはありません"), "{}", e.ja);
        let e = student_file(b"student = 20260001\n").unwrap_err();
        assert!(e.ja.contains("student = \"20260001\"") && e.ja.contains("引用符"), "{}", e.ja);
        assert_eq!(crate::inside::eight_digits("report-20260001.md"), Some("20260001"));
        assert_eq!(crate::inside::eight_digits("2026000123.md"), None);
        assert_eq!(crate::inside::eight_digits("x1_20260002_v2.txt"), Some("20260002"));
    }
}
