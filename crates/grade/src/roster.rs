//! The class roster (`cg grade --roster roster.csv`): who is who. Each row binds one
//! submission entry to one student, so the result file, the variant graded and the class table
//! follow the roster, not the number a submission writes in its `student.toml`.
//!
//! The file is CSV with a header naming three columns, in any order and with any others beside
//! them: `student` (学生番号, the 8-digit number), `name` (氏名) and `entry` (提出物): the
//! entry's folder or zip name in the submissions folder, or its Moodle participant ID (the
//! digits of Moodle's `<name>_<ID>_assignsubmission_file_` folders). UTF-8 (with or without a
//! BOM), UTF-16 with a BOM or Shift_JIS, as `cg_core::text` reads it: what Excel and Moodle
//! write. Commas separate the columns, or tabs when the header has more tabs than commas
//! (Excel's 「Unicode テキスト」 is tab-separated UTF-16).
//!
//! ```csv
//! student,name,entry
//! 20260001,山田 太郎,123456
//! 20260002,Jane Roe,20260002-roe.zip
//! ```

use std::collections::BTreeMap;
use std::path::Path;

use cg_core::lang::Text;
use cg_harness::StudentNumber;

/// One row: a student and the entry that is theirs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    /// The student number.
    pub student: StudentNumber,
    /// The name, as the roster writes it.
    pub name: String,
    /// The entry's name or Moodle participant ID.
    pub entry: String,
    /// The roster's line (for messages).
    pub line: u64,
}

/// The roster's rows.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Roster {
    /// Every row, in the file's order.
    pub rows: Vec<Row>,
}

/// The column names each column is known by (English, Japanese).
const COLUMNS: [(&str, &[&str]); 3] = [
    ("student", &["student", "student number", "学生番号", "学籍番号"]),
    ("name", &["name", "氏名", "名前"]),
    ("entry", &["entry", "submission", "participant", "提出物", "参加者", "参加者 ID", "参加者ID"]),
];

/// A roster's `entry` as Moodle's grading worksheet writes a participant in its ID column
/// (`Participant 2004`, `参加者2004`): the participant ID; anything else as it is. The kit's own
/// grades.csv writes that column, so a roster copied from it matched nobody.
fn participant_id(entry: &str) -> &str {
    let digits = ["Participant", "participant", "参加者"]
        .iter()
        .find_map(|p| entry.strip_prefix(p))
        .map(str::trim_start)
        .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()));
    digits.unwrap_or(entry)
}

/// Moodle's folder of one participant's files, `<name>_<ID>_assignsubmission_<plugin>_`:
/// the participant ID.
#[must_use]
pub fn moodle_participant(entry: &str) -> Option<&str> {
    let at = entry.find("_assignsubmission_")?;
    let before = &entry[..at];
    let id = &before[before.rfind('_')? + 1..];
    (!id.is_empty() && id.bytes().all(|b| b.is_ascii_digit())).then_some(id)
}

impl Roster {
    /// Reads a roster file (see the module's documentation).
    ///
    /// # Errors
    /// The file cannot be read, or a row is wrong: the file, the line and what.
    pub fn read(path: &Path) -> Result<Roster, Text> {
        let (text, _) = cg_core::text::read(path, None).map_err(|e| {
            let t = e.text();
            Text::new(
                format!("{}: {}", path.display(), t.ja),
                format!("{}: {}", path.display(), t.en),
            )
        })?;
        Roster::parse(&text).map_err(|t| {
            Text::new(
                format!("{}:{}", path.display(), t.ja),
                format!("{}:{}", path.display(), t.en),
            )
        })
    }

    /// Parses a roster's text. An error starts with the line: `3: …`.
    ///
    /// # Errors
    /// No header, a column missing, a row with a bad student number or no entry, or a student
    /// number or an entry given twice.
    pub fn parse(text: &str) -> Result<Roster, Text> {
        // Excel's 「Unicode テキスト」 (UTF-16, what keeps Japanese names whatever the system's
        // code page) separates by tabs: the header's line says which.
        let header_line = text.lines().find(|l| !l.trim().is_empty()).unwrap_or("");
        let tabs = header_line.matches('\t').count();
        let delimiter = if tabs > header_line.matches(',').count() { b'\t' } else { b',' };
        let mut reader = csv::ReaderBuilder::new()
            .delimiter(delimiter)
            .flexible(true)
            .trim(csv::Trim::All)
            .from_reader(text.as_bytes());
        let header = reader.headers().map_err(|e| csv_error(1, &e))?.clone();
        let mut at = [0usize; 3];
        for (k, (key, names)) in COLUMNS.iter().enumerate() {
            at[k] = header
                .iter()
                .position(|h| names.iter().any(|n| h.eq_ignore_ascii_case(n)))
                .ok_or_else(|| {
                    Text::new(
                        format!("1: 見出しの行に列 `{key}`（{}）がありません", names.join("、")),
                        format!(
                            "1: the header has no column `{key}` (one of: {})",
                            names.join(", ")
                        ),
                    )
                })?;
            // Two columns for one key (`student` and `学籍番号`): which one is meant is not
            // for the reader to guess.
            let count =
                header.iter().filter(|h| names.iter().any(|n| h.eq_ignore_ascii_case(n))).count();
            if count > 1 {
                return Err(Text::new(
                    format!(
                        "1: 見出しの行に列 `{key}`（{}）が {count} つあります。1 つにしてください",
                        names.join("、")
                    ),
                    format!(
                        "1: the header has {count} columns for `{key}` (one of: {}); keep one",
                        names.join(", ")
                    ),
                ));
            }
        }
        let mut rows: Vec<Row> = Vec::new();
        let mut by_student: BTreeMap<String, u64> = BTreeMap::new();
        let mut by_entry: BTreeMap<String, u64> = BTreeMap::new();
        let mut record = csv::StringRecord::new();
        // The lines before `counted` bytes, counted once as the reader moves on (counting from
        // the start for each record made a 3 MB roster take half a minute).
        let (mut counted, mut lines_before) = (0usize, 0u64);
        loop {
            // The record's line: the first line with text at or after where the reader stood
            // (csv skips blank lines; its record positions do not count them).
            let start = usize::try_from(reader.position().byte()).unwrap_or(0).min(text.len());
            if start >= counted {
                lines_before +=
                    text.as_bytes()[counted..start].iter().filter(|&&b| b == b'\n').count() as u64;
                counted = start;
            }
            let line0 = lines_before + 1;
            if !reader.read_record(&mut record).map_err(|e| csv_error(line0, &e))? {
                break;
            }
            let blank = text.as_bytes()[start..]
                .iter()
                .take_while(|&&b| b == b'\n' || b == b'\r')
                .filter(|&&b| b == b'\n')
                .count() as u64;
            let line = line0 + blank;
            if record.iter().all(str::is_empty) {
                continue;
            }
            // A quote never closed takes the rest of the file as one field: said as such, not
            // as whatever column then comes up empty.
            let end = usize::try_from(reader.position().byte()).unwrap_or(0).min(text.len());
            if end == text.len()
                && record.iter().any(|f| f.contains(['\n', '\r']))
                && text.as_bytes()[start..].iter().filter(|&&b| b == b'"').count() % 2 == 1
            {
                return Err(Text::new(
                    format!(
                        "{line}: この行で開いた引用符 \" が閉じていません（ファイルの終わりまでが 1 つの欄になります）"
                    ),
                    format!(
                        "{line}: a quote \" opened on this line is never closed (the rest of the file would be one field)"
                    ),
                ));
            }
            let field = |k: usize| record.get(at[k]).unwrap_or("").to_owned();
            let student: StudentNumber =
                field(0).parse().map_err(|e: cg_harness::variant::StudentNumberError| {
                    Text::new(
                        format!("{line}: student: {}", e.message(cg_core::lang::Lang::Ja)),
                        format!("{line}: student: {}", e.message(cg_core::lang::Lang::En)),
                    )
                })?;
            let entry = participant_id(&field(2)).to_owned();
            if entry.is_empty() {
                return Err(Text::new(
                    format!(
                        "{line}: 学生 {student} の entry（提出物のフォルダ名か Moodle の参加者 ID）が空です（提出していない学生も、Moodle の評定ワークシートの ID 列の値（参加者2004 など）を書けば「提出物のない学生」に並びます）"
                    ),
                    format!(
                        "{line}: entry is empty for student {student} (the entry's folder name or Moodle participant ID; for a student who handed nothing in, write the ID column of Moodle's grading worksheet, Participant 2004 say, and they are listed among the students with no entry)"
                    ),
                ));
            }
            if let Some(first) = by_student.insert(student.to_string(), line) {
                return Err(Text::new(
                    format!("{line}: 学生番号 {student} は {first} 行目にもあります"),
                    format!("{line}: student {student} is on line {first} too"),
                ));
            }
            if let Some(first) = by_entry.insert(entry.clone(), line) {
                return Err(Text::new(
                    format!("{line}: entry \"{entry}\" は {first} 行目にもあります"),
                    format!("{line}: entry \"{entry}\" is on line {first} too"),
                ));
            }
            rows.push(Row { student, name: field(1), entry, line });
        }
        Ok(Roster { rows })
    }

    /// The row of a submissions folder's entry: the one naming it exactly, else (for a Moodle
    /// folder) the one with its participant ID.
    #[must_use]
    pub fn find(&self, entry: &str) -> Option<&Row> {
        self.rows.iter().find(|r| r.entry == entry).or_else(|| {
            let id = moodle_participant(entry)?;
            self.rows.iter().find(|r| r.entry == id)
        })
    }
}

fn csv_error(line: u64, e: &csv::Error) -> Text {
    let line = e.position().map_or(line, csv::Position::line);
    Text::new(format!("{line}: CSV として読めません: {e}"), format!("{line}: not CSV: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_bind_entries_by_name_or_moodle_participant() {
        let text = "\u{feff}学生番号,氏名,提出物,メモ\r\n20260001,山田 太郎,123456,\r\n\r\n20260002,Jane Roe,20260002-roe.zip,late\r\n";
        let r = Roster::parse(text).unwrap();
        assert_eq!(r.rows.len(), 2, "{:?}", r.rows);
        assert_eq!(r.rows[0].name, "山田 太郎");
        let moodle = "山田 太郎_123456_assignsubmission_file_";
        assert_eq!(moodle_participant(moodle), Some("123456"));
        assert_eq!(r.find(moodle).map(|r| r.student.to_string()), Some("20260001".into()));
        assert_eq!(r.find("20260002-roe.zip").map(|r| r.line), Some(4));
        assert!(r.find("20260002-roe").is_none());
        assert!(r.find("someone_999_assignsubmission_file_").is_none());
        assert_eq!(moodle_participant("a_b_assignsubmission_file_"), None);
        assert_eq!(moodle_participant("plain-folder"), None);
        // A stray quote inside a last row's field, and a quoted name over two lines, are not an
        // unclosed quote.
        let r = Roster::parse("student,name,entry\n20260001,\"Roe,\nJane\",e\n20260002,J \"J,f")
            .unwrap();
        assert_eq!(r.rows.len(), 2, "{:?}", r.rows);
        assert_eq!(r.rows[1].name, "J \"J");
    }

    /// A roster Excel saved as 「Unicode テキスト」: UTF-16LE with a BOM, tab-separated, CRLF.
    /// It was refused ("the header has no column `student`": tabs were no separator); a name
    /// with a comma in it stays one cell.
    #[test]
    fn excel_unicode_text_is_read() {
        let text =
            "学生番号\t氏名\t提出物\r\n20260001\t山田 太郎\t123456\r\n20260002\tRoe, Jane\t777\r\n";
        let mut bytes = vec![0xFF, 0xFE];
        bytes.extend(text.encode_utf16().flat_map(u16::to_le_bytes));
        let path = std::env::temp_dir().join(format!("cg-roster-utf16-{}.txt", std::process::id()));
        std::fs::write(&path, bytes).unwrap();
        let r = Roster::read(&path);
        let _ = std::fs::remove_file(&path);
        let r = r.unwrap();
        assert_eq!(r.rows.len(), 2, "{:?}", r.rows);
        assert_eq!(r.rows[0].name, "山田 太郎");
        assert_eq!(r.rows[1].name, "Roe, Jane");
        assert_eq!(r.find("777").map(|r| r.student.to_string()), Some("20260002".into()));
        // The grading worksheet's ID column (`参加者2004`, `Participant 2001`) is the participant.
        let r = Roster::parse(
            "学生番号,氏名,参加者ID\n20260001,a,参加者2004\n20260002,b,Participant 2001\n",
        )
        .unwrap();
        let moodle = |id: &str| format!("x_{id}_assignsubmission_file");
        assert_eq!(r.find(&moodle("2004")).map(|r| r.student.to_string()), Some("20260001".into()));
        assert_eq!(r.find(&moodle("2001")).map(|r| r.student.to_string()), Some("20260002".into()));
        // A comma-separated roster with a tab in a cell stays comma-separated.
        let r = Roster::parse("student,name,entry\n20260001,a\tb,e\n").unwrap();
        assert_eq!(r.rows[0].name, "a\tb");
    }

    #[test]
    fn a_wrong_roster_is_refused_with_its_line() {
        let cases = [
            ("number,name\n1,a\n", "1: the header has no column `student`"),
            ("student,name,entry\n2026000x,a,e\n", "2: student: a student number is 8 digits"),
            ("student,name,entry\n20260001,a,\n", "2: entry is empty for student 20260001"),
            (
                "student,name,entry\n20260001,a,e\n20260002,\"Roe, Jane,f\n20260003,c,g\n",
                "3: a quote \" opened on this line is never closed",
            ),
            (
                "student,name,entry\n20260001,a,e\n20260001,b,f\n",
                "3: student 20260001 is on line 2 too",
            ),
            ("student,name,entry\n20260001,a,e\n20260002,b,e\n", "3: entry \"e\" is on line 2 too"),
            (
                "student,学籍番号,name,entry\n20260001,20260009,a,e\n",
                "1: the header has 2 columns for `student`",
            ),
        ];
        for (text, expected) in cases {
            let e = Roster::parse(text).unwrap_err();
            assert!(e.en.starts_with(expected), "{text:?}: {}", e.en);
            assert!(e.ja.chars().any(cg_testkit::text::kana_or_kanji), "{}", e.ja);
        }
    }
}
