//! `exercises/student.toml`: the student's number and table, recorded once.

use std::path::Path;

use cg_core::lang::{Lang, Text};
use cg_core::quote::shown;
use cg_harness::{StudentNumber, TableVersion};

/// What `exercises/student.toml` records.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct StudentFile {
    /// The student number.
    pub student: StudentNumber,
    /// The table the student works from.
    pub table: TableVersion,
}

/// Why `exercises/student.toml` could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}", self.message(Lang::En))]
pub enum StudentFileError {
    /// There is no such file yet.
    Missing {
        /// Where it was looked for.
        path: String,
    },
    /// It is there but cannot be read: a folder, no permission, too large, not text
    /// ([`cg_core::text::ReadError`]; UTF-8, UTF-16 and Shift_JIS are read).
    Unreadable {
        /// The file.
        path: String,
        /// Why, in both languages.
        why: Text,
    },
    /// It is not valid, or lacks `student`.
    Invalid {
        /// The file.
        path: String,
        /// What is wrong, in both languages (a syntax error with the TOML parser's message and
        /// line, an unknown or missing key, a number without quotes).
        reason: Text,
    },
    /// `student` is not an 8-digit number.
    Number {
        /// The file.
        path: String,
        /// Why.
        error: cg_harness::variant::StudentNumberError,
    },
    /// `table` names no table.
    Table {
        /// The file.
        path: String,
        /// What was written.
        given: String,
    },
}

impl StudentFileError {
    /// The message in `lang`, with what to do.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            StudentFileError::Missing { path } => Text::new(
                format!(
                    "{path} がありません。最初に一度だけ学生番号を記録してください: cargo run --release -- assignment --student 12345678 --save（12345678 を自分の学生番号に）"
                ),
                format!(
                    "{path} does not exist. Record your student number once: cargo run --release -- assignment --student 12345678 --save (with your own number)"
                ),
            ),
            StudentFileError::Unreadable { path, why } => {
                Text::new(format!("{path}: {}", why.ja), format!("{path}: {}", why.en))
            }
            StudentFileError::Invalid { path, reason } => Text::new(
                format!("{path} を読めません: {}（例: student = \"12345678\"）", reason.ja),
                format!("{path} cannot be read: {} (example: student = \"12345678\")", reason.en),
            ),
            StudentFileError::Number { path, error } => {
                let error = error.text();
                Text::new(format!("{path}: {}", error.ja), format!("{path}: {}", error.en))
            }
            StudentFileError::Table { path, given } => Text::new(
                format!(
                    "{path}: table = {} という課題表の版はありません（{} を使ってください）",
                    shown(given, Lang::Ja),
                    known_tables(" か ")
                ),
                format!(
                    "{path}: there is no table {} (use {})",
                    shown(given, Lang::En),
                    known_tables(" or ")
                ),
            ),
        }
    }
}

/// The table versions there are, as a student writes them (`1 or 2`).
fn known_tables(or: &str) -> String {
    let n: Vec<String> = TableVersion::ALL.iter().map(ToString::to_string).collect();
    n.join(or)
}

/// The largest `student.toml` read (a record is two short lines; anything larger is the wrong
/// file).
const MAX_STUDENT_FILE_BYTES: u64 = 64 << 10;

/// Reads `exercises/student.toml` (or another path), in UTF-8, UTF-16 or Shift_JIS as an editor
/// wrote it, at most 64 KiB.
///
/// # Errors
/// A missing, unreadable or malformed file, a bad number, an unknown table — each with what to
/// do.
pub fn read_student_file(path: &Path) -> Result<StudentFile, StudentFileError> {
    let file = path.display().to_string();
    match read_bytes(path)? {
        Some(bytes) => parse_student_file(&bytes, &file),
        None => Err(StudentFileError::Missing { path: file }),
    }
}

/// The bytes of a record or a course file, at most 64 KiB; `None` when there is no file.
fn read_bytes(path: &Path) -> Result<Option<Vec<u8>>, StudentFileError> {
    use cg_core::text::ReadError;
    let file = path.display().to_string();
    match cg_core::text::read_bounded(path, MAX_STUDENT_FILE_BYTES) {
        Ok(bytes) => Ok(Some(bytes)),
        Err(_) if !path.exists() => Ok(None),
        Err(ReadError::TooLarge { .. }) => Err(too_large(file)),
        Err(e) => Err(StudentFileError::Unreadable { path: file, why: e.text_without_option() }),
    }
}

/// The text of a record's or a course file's bytes, in UTF-8, UTF-16 or Shift_JIS.
fn decoded(bytes: &[u8], file: &str) -> Result<String, StudentFileError> {
    let (text, _) = cg_core::text::decode(bytes, None).map_err(|e| {
        let why = cg_core::text::ReadError::from(e).text_without_option();
        StudentFileError::Unreadable { path: file.to_owned(), why }
    })?;
    Ok(text)
}

fn too_large(path: String) -> StudentFileError {
    StudentFileError::Unreadable {
        path,
        why: Text::new(
            format!(
                "{} KiB を超えています。学生番号を記録するファイルにしては大きすぎます",
                MAX_STUDENT_FILE_BYTES >> 10
            ),
            format!(
                "it is larger than {} KiB, too large for the record of a student number",
                MAX_STUDENT_FILE_BYTES >> 10
            ),
        ),
    }
}

/// [`read_student_file`] of a record's bytes (from a submission's zip), named `file` in the
/// errors: the same encodings, limit and mistakes.
///
/// # Errors
/// As [`read_student_file`], but for a missing file.
pub fn parse_student_file(bytes: &[u8], file: &str) -> Result<StudentFile, StudentFileError> {
    let file = file.to_owned();
    if bytes.len() as u64 > MAX_STUDENT_FILE_BYTES {
        return Err(too_large(file));
    }
    let text = decoded(bytes, &file)?;
    let invalid = |reason: Text| StudentFileError::Invalid { path: file.clone(), reason };
    // A number without quotes (`student = 01234567`) is refused before TOML reads it: TOML
    // drops its leading zeros, or calls a leading zero an error.
    if let Some(digits) = unquoted_number(&text) {
        let (ja, en) = (shown(&digits, Lang::Ja), shown(&digits, Lang::En));
        return Err(invalid(Text::new(
            format!("student = {ja} は引用符で囲んでください: student = \"{ja}\""),
            format!("student = {en} must be in quotes: student = \"{en}\""),
        )));
    }
    // Read with each key's and value's place, so that every mistake names its line.
    let doc = toml::de::DeTable::parse(&text).map_err(|e| invalid(syntax_error(&text, &e)))?;
    let at =
        |offset: usize, said: Text| invalid(cg_core::toml_syntax::located(&text, offset, &said));
    let doc = doc.get_ref();
    if let Some((key, _)) = doc
        .iter()
        .filter(|(k, _)| !matches!(k.get_ref().as_ref(), "student" | "table"))
        .min_by_key(|(k, _)| k.span().start)
    {
        let start = key.span().start;
        let key: &str = key.get_ref();
        return Err(at(
            start,
            Text::new(
                format!(
                    "`{}` というキーはありません（書けるのは student と table）",
                    shown(key, Lang::Ja)
                ),
                format!(
                    "there is no key `{}` (the keys are student and table)",
                    shown(key, Lang::En)
                ),
            ),
        ));
    }
    let digits = match doc.get("student") {
        Some(v) => match v.get_ref() {
            toml::de::DeValue::String(s) => s.to_string(),
            _ => {
                return Err(at(
                    v.span().start,
                    Text::new(
                        "student は引用符で囲んだ 8 桁の数字にしてください",
                        "student must be 8 digits in quotes",
                    ),
                ));
            }
        },
        None => return Err(invalid(Text::new("student がありません", "student is missing"))),
    };
    let student =
        digits.parse().map_err(|error| StudentFileError::Number { path: file.clone(), error })?;
    let table = table_in(doc, &text, &file)?.unwrap_or(TableVersion::DEFAULT);
    Ok(StudentFile { student, table })
}

/// A TOML syntax error of a record or a course file, with its line.
fn syntax_error(text: &str, e: &toml::de::Error) -> Text {
    let said = cg_core::toml_syntax::at(text, e.message(), e.span());
    Text::new(
        format!("TOML の書き方の誤りです（構文エラー）: {}", said.ja),
        format!("TOML syntax error: {}", said.en),
    )
}

/// The `table = N` of a record or a course file, when it has one.
fn table_in(
    doc: &toml::de::DeTable<'_>,
    text: &str,
    file: &str,
) -> Result<Option<TableVersion>, StudentFileError> {
    let Some(v) = doc.get("table") else { return Ok(None) };
    // As written (`9`, `"1"`, `99999999999999999999`).
    let given = text.get(v.span()).unwrap_or_default().to_owned();
    let table = given.trim_matches('"').parse();
    table.map(Some).map_err(|_| StudentFileError::Table { path: file.to_owned(), given })
}

/// The course's file beside the record, `exercises/course.toml`: the table version the class
/// uses (`table = 2`), written by `cg handout --table 2` into the students' copy.
pub const COURSE_FILE: &str = "course.toml";

/// The course's table version from [`COURSE_FILE`] beside `record` (`exercises/student.toml`):
/// what a student gets when they name none and have no record of their own. `None` without
/// the file.
///
/// # Errors
/// An unreadable or malformed course file, a key other than `table`, an unknown table: each
/// with the file and the line.
pub fn course_table(record: &Path) -> Result<Option<TableVersion>, StudentFileError> {
    let path = record.with_file_name(COURSE_FILE);
    let file = path.display().to_string();
    let Some(bytes) = read_bytes(&path)? else { return Ok(None) };
    let text = decoded(&bytes, &file)?;
    let invalid = |reason: Text| StudentFileError::Invalid { path: file.clone(), reason };
    let doc = toml::de::DeTable::parse(&text).map_err(|e| invalid(syntax_error(&text, &e)))?;
    let doc = doc.get_ref();
    if let Some((key, _)) = doc
        .iter()
        .filter(|(k, _)| k.get_ref().as_ref() != "table")
        .min_by_key(|(k, _)| k.span().start)
    {
        let said = Text::new(
            format!(
                "`{}` というキーはありません（書けるのは table だけ）",
                shown(key.get_ref(), Lang::Ja)
            ),
            format!("there is no key `{}` (the only key is table)", shown(key.get_ref(), Lang::En)),
        );
        return Err(invalid(cg_core::toml_syntax::located(&text, key.span().start, &said)));
    }
    table_in(doc, &text, &file)
}

/// The digits of a `student = 0123…` line without quotes, as written.
fn unquoted_number(text: &str) -> Option<String> {
    text.lines().find_map(|line| {
        let (key, value) = line.split_once('=')?;
        let value = value.split('#').next().unwrap_or_default().trim();
        let digits = !value.is_empty() && value.bytes().all(|b| b.is_ascii_digit());
        (key.trim() == "student" && digits).then(|| value.to_owned())
    })
}

/// Writes `exercises/student.toml` (or another path): to a file beside it, then renamed over
/// it, so a full disk or a failed write never leaves the record empty.
///
/// # Errors
/// The file cannot be written; the message says which file and why, in both languages.
pub fn write_student_file(path: &Path, record: &StudentFile) -> Result<(), Text> {
    let text = format!(
        "# Your student number, recorded once (cargo run --release -- assignment --student N --save).\n\
         # 学生番号（最初に一度だけ記録します）。\n\
         student = \"{}\"\ntable = {}\n",
        record.student, record.table
    );
    cg_core::fs::write_atomic(path, text.as_bytes()).map_err(|e| Text::io_at(path, &e))
}

/// What recording `new` over the record `old` changes, said to the student: the number (or the
/// table) it was and is now, and that the assignments, and so the checks, follow from it. `None`
/// when nothing changes.
#[must_use]
pub fn record_change(old: &StudentFile, new: &StudentFile) -> Option<Text> {
    let follows = Text::new(
        "課題は学生番号と課題表の版から決まるので、課題もチェックの内容も変わります",
        "your assignments follow from the number and the table, so they change, and so do the checks",
    );
    let (ja, en) = if old.student != new.student {
        (
            format!("学生番号を {} から {} に変更しました", old.student, new.student),
            format!("the student number was {} and is now {}", old.student, new.student),
        )
    } else if old.table != new.table {
        (
            format!("課題表の版を {} から {} に変更しました", old.table, new.table),
            format!("the table was {} and is now {}", old.table, new.table),
        )
    } else {
        return None;
    };
    Some(Text::new(format!("{ja}。{}", follows.ja), format!("{en}: {}", follows.en)))
}

/// The student a command is about: `given` (a `--student` option) when there is one, with
/// `table`, else the table of their own record in `file` (`exercises/student.toml`), else the
/// course's ([`course_table`]), else version 1; without `given`, the record in `file`, with
/// `table` replacing its table when given.
///
/// # Errors
/// A malformed student number, or a missing or malformed student file, as a message in `lang`.
pub fn resolve_student(
    given: Option<&str>,
    table: Option<TableVersion>,
    file: &Path,
    lang: Lang,
) -> Result<StudentFile, String> {
    match given {
        Some(n) => {
            let student: StudentNumber =
                n.parse().map_err(|e: cg_harness::variant::StudentNumberError| e.message(lang))?;
            // The student's own record keeps its table; else the course's; else version 1.
            let recorded = || {
                let record = read_student_file(file).ok()?;
                (record.student == student).then_some(record.table)
            };
            let table = match table.or_else(recorded) {
                Some(t) => t,
                None => course_table(file)
                    .map_err(|e| e.message(lang))?
                    .unwrap_or(TableVersion::DEFAULT),
            };
            Ok(StudentFile { student, table })
        }
        None => {
            let mut record = read_student_file(file).map_err(|e| e.message(lang))?;
            if let Some(t) = table {
                record.table = t;
            }
            Ok(record)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dir(name: &str) -> std::path::PathBuf {
        let d = std::env::temp_dir().join(format!("cg-assign-{name}-{}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    /// The course's table (exercises/course.toml, from `cg handout --table 2`) is what a
    /// student without a record of their own gets; their own record keeps its table; a
    /// malformed course file is named with its line.
    #[test]
    fn the_courses_table_is_the_default_and_a_record_keeps_its_own() {
        let d = dir("course");
        let record = d.join("student.toml");
        let resolve = |n: Option<&str>| resolve_student(n, None, &record, Lang::En);
        // Neither file: version 1.
        assert_eq!(resolve(Some("20261234")).unwrap().table, TableVersion::V1);
        std::fs::write(d.join(COURSE_FILE), "# the course\ntable = 2\n").unwrap();
        assert_eq!(course_table(&record), Ok(Some(TableVersion::V2)));
        assert_eq!(resolve(Some("20261234")).unwrap().table, TableVersion::V2);
        // A record of one's own keeps its table; another number's record does not lend its.
        std::fs::write(&record, "student = \"20261234\"\ntable = 1\n").unwrap();
        assert_eq!(resolve(Some("20261234")).unwrap().table, TableVersion::V1);
        assert_eq!(resolve(None).unwrap().table, TableVersion::V1);
        assert_eq!(resolve(Some("20269999")).unwrap().table, TableVersion::V2);
        // `--table` wins over both.
        let given = resolve_student(Some("20261234"), Some(TableVersion::V2), &record, Lang::En);
        assert_eq!(given.unwrap().table, TableVersion::V2);
        // Mistakes in the course file: named, with the line.
        for (text, en) in [
            ("table = 9\n", "there is no table 9 (use 1 or 2)"),
            ("\ntables = 2\n", "line 2"),
            ("table = \n", "TOML syntax error"),
        ] {
            std::fs::write(d.join(COURSE_FILE), text).unwrap();
            let e = resolve(Some("20269999")).unwrap_err();
            assert!(e.contains("course.toml") && e.contains(en), "{text:?}: {e}");
        }
        let _ = std::fs::remove_dir_all(&d);
    }

    #[test]
    fn a_changed_record_says_what_it_was_and_is_now() {
        let record = |n: &str, table| StudentFile { student: n.parse().unwrap(), table };
        let old = record("20261234", TableVersion::V1);
        assert_eq!(record_change(&old, &old.clone()), None);
        let note = record_change(&old, &record("20261235", TableVersion::V1)).unwrap();
        assert!(note.en.starts_with("the student number was 20261234 and is now 20261235"));
        assert!(note.en.contains("so do the checks"), "{}", note.en);
        assert!(
            note.ja.starts_with("学生番号を 20261234 から 20261235 に変更しました。"),
            "{}",
            note.ja
        );
        assert!(note.ja.contains("チェック"), "{}", note.ja);
    }

    #[test]
    fn the_student_file_round_trips_and_explains_mistakes() {
        let d = dir("file");
        let path = d.join("student.toml");
        let e = read_student_file(&path).unwrap_err();
        assert!(e.message(Lang::Ja).contains("--save"), "{e}");
        let record = StudentFile { student: "01234567".parse().unwrap(), table: TableVersion::V1 };
        write_student_file(&path, &record).unwrap();
        assert_eq!(read_student_file(&path), Ok(record));
        for (text, en, ja) in [
            ("student = 1234567\n", "in quotes", "引用符で囲んで"),
            // A leading zero: TOML would call it an error; the hint keeps the zero.
            ("student = 01234567 # mine\n", "student = \"01234567\"", "student = \"01234567\""),
            ("student = 12345678.0\n", "8 digits in quotes", "8 桁の数字"),
            ("student = \"1234567\"\n", "8 digits", "8 桁"),
            (
                "# mine\nstudent = \"12345678\"\nstudnet = \"12345678\"\n",
                "line 3, column 1: there is no key `studnet`",
                "3 行 1 列: `studnet` というキーはありません",
            ),
            (
                "table = 1\nstudent = [1, 2]\n",
                "line 2, column 11: student must be 8 digits in quotes",
                "2 行 11 列: student は引用符で囲んだ",
            ),
            (
                "student = \"12345678\"\ntable = 99999999999999999999\n",
                "99999999999999999999",
                "99999999999999999999",
            ),
            ("table = 1\n", "student is missing", "student がありません"),
            ("student = \"12345678\"\ntable = 9\n", "no table 9", "table = 9"),
            (
                "student = \"1\"\nstudent = \"2\"\n",
                "TOML syntax error: line 2, column 1: duplicate key",
                "構文エラー）: 2 行 1 列: 同じキーが 2 回書かれています",
            ),
            (
                "student = \"12345678\"\ntable 1\n",
                "line 2, column 7: key with no value",
                "2 行 7 列: キーの後に = と値がありません（ここに来るはずのもの: `=`）",
            ),
        ] {
            std::fs::write(&path, text).unwrap();
            let e = read_student_file(&path).unwrap_err();
            assert!(e.message(Lang::En).contains(en), "{text:?}: {}", e.message(Lang::En));
            assert!(e.message(Lang::Ja).contains(ja), "{text:?}: {}", e.message(Lang::Ja));
        }
        std::fs::remove_dir_all(&d).ok();
    }

    /// The record as an editor writes it (UTF-16 with its BOM, Shift_JIS with a Japanese
    /// comment) is read; a file that is there but cannot be read is not called missing, and a
    /// large one is refused without reading it all.
    #[test]
    fn the_student_file_is_read_in_the_students_encodings_and_bounded() {
        let d = dir("encodings");
        let path = d.join("student.toml");
        let text = "# 私の学生番号\r\nstudent = \"20260001\"\r\n";
        let mut utf16 = vec![0xFF, 0xFE];
        utf16.extend(text.encode_utf16().flat_map(u16::to_le_bytes));
        // "# 私の学生番号" in Shift_JIS.
        let mut sjis = b"# \x8e\x84\x82\xcc\x8aw\x90\xb6\x94\xd4\x8d\x86\r\n".to_vec();
        sjis.extend_from_slice(b"student = \"20260001\"\r\n");
        for bytes in [utf16, sjis] {
            std::fs::write(&path, &bytes).unwrap();
            let record = read_student_file(&path).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(record.student.as_str(), "20260001");
        }
        std::fs::remove_file(&path).unwrap();
        std::fs::create_dir(&path).unwrap();
        let e = read_student_file(&path).unwrap_err();
        assert!(matches!(e, StudentFileError::Unreadable { .. }), "{e}");
        assert!(!e.message(Lang::Ja).contains("os error"), "{}", e.message(Lang::Ja));
        std::fs::remove_dir(&path).unwrap();
        let mut big = b"student = \"20260001\"\n#".to_vec();
        big.resize(10 << 20, b'x');
        std::fs::write(&path, &big).unwrap();
        let e = read_student_file(&path).unwrap_err();
        assert!(e.message(Lang::En).contains("too large"), "{e}");
        assert!(e.message(Lang::En).len() < 300, "{e}");
        std::fs::remove_dir_all(&d).ok();
    }
}
