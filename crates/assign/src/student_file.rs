//! `exercises/student.toml`: the student's number and table, recorded once.

use std::path::Path;

use cg_core::lang::{Lang, Text};
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
    /// It is not valid, or lacks `student`.
    Invalid {
        /// The file.
        path: String,
        /// What is wrong (the TOML parser's message, with the line).
        reason: String,
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
            StudentFileError::Invalid { path, reason } => Text::new(
                format!("{path} を読めません: {reason}（例: student = \"12345678\"）"),
                format!("{path} cannot be read: {reason} (example: student = \"12345678\")"),
            ),
            StudentFileError::Number { path, error } => {
                let error = error.text();
                Text::new(format!("{path}: {}", error.ja), format!("{path}: {}", error.en))
            }
            StudentFileError::Table { path, given } => Text::new(
                format!("{path}: table = {given} という課題表はありません（1 を使ってください）"),
                format!("{path}: there is no table {given} (use 1)"),
            ),
        }
    }
}

#[derive(serde::Deserialize)]
#[serde(deny_unknown_fields)]
struct RawStudentFile {
    student: toml::Value,
    table: Option<toml::Value>,
}

/// Reads `exercises/student.toml` (or another path).
///
/// # Errors
/// A missing or malformed file, a bad number, an unknown table — each with what to do.
pub fn read_student_file(path: &Path) -> Result<StudentFile, StudentFileError> {
    let shown = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .map_err(|_| StudentFileError::Missing { path: shown.clone() })?;
    let raw: RawStudentFile = toml::from_str(&text)
        .map_err(|e| StudentFileError::Invalid { path: shown.clone(), reason: e.to_string() })?;
    let digits = match &raw.student {
        toml::Value::String(s) => s.clone(),
        // A number written without quotes loses leading zeros, so it is refused with the reason.
        other => {
            return Err(StudentFileError::Invalid {
                path: shown,
                reason: format!("student = {other} must be in quotes: student = \"{other}\""),
            });
        }
    };
    let student =
        digits.parse().map_err(|error| StudentFileError::Number { path: shown.clone(), error })?;
    let table = match raw.table {
        None => TableVersion::LATEST,
        Some(v) => {
            let given = v.to_string();
            given
                .trim_matches('"')
                .parse()
                .map_err(|_| StudentFileError::Table { path: shown, given })?
        }
    };
    Ok(StudentFile { student, table })
}

/// Writes `exercises/student.toml` (or another path).
///
/// # Errors
/// The file cannot be written; the message says which file and why.
pub fn write_student_file(path: &Path, record: &StudentFile) -> Result<(), String> {
    let text = format!(
        "# Your student number, recorded once (cargo run --release -- assignment --student N --save).\n\
         # 学生番号（最初に一度だけ記録します）。\n\
         student = \"{}\"\ntable = {}\n",
        record.student, record.table
    );
    std::fs::write(path, text).map_err(|e| format!("{}: {e}", path.display()))
}

/// The student a command is about: `given` (a `--student` option) when there is one, with
/// `table` or the newest table; else the record in `file` (`exercises/student.toml`), with
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
            Ok(StudentFile { student, table: table.unwrap_or(TableVersion::LATEST) })
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

    #[test]
    fn the_student_file_round_trips_and_explains_mistakes() {
        let d = dir("file");
        let path = d.join("student.toml");
        let e = read_student_file(&path).unwrap_err();
        assert!(e.message(Lang::Ja).contains("--save"), "{e}");
        let record = StudentFile { student: "01234567".parse().unwrap(), table: TableVersion::V1 };
        write_student_file(&path, &record).unwrap();
        assert_eq!(read_student_file(&path), Ok(record));
        for (text, needle) in [
            ("student = 1234567\n", "in quotes"),
            ("student = \"1234567\"\n", "8 digits"),
            ("studnet = \"12345678\"\n", "unknown field"),
            ("student = \"12345678\"\ntable = 9\n", "no table 9"),
        ] {
            std::fs::write(&path, text).unwrap();
            let e = read_student_file(&path).unwrap_err();
            assert!(e.message(Lang::En).contains(needle), "{text:?}: {}", e.message(Lang::En));
        }
        std::fs::remove_dir_all(&d).ok();
    }
}
