//! What goes back into Moodle, under `<out>/moodle/`:
//!
//! - `grades.csv`: the assignment's offline grading worksheet, as "Download grading worksheet"
//!   (評定ワークシートをダウンロードする) writes it — the columns Identifier, Full name, Email
//!   address, Status, Grade, Maximum grade, Grade can be changed, Last modified (submission),
//!   Last modified (grade), Feedback comments, named in the course's Moodle language; UTF-8
//!   with a BOM (Moodle's download has one and its upload removes it). Moodle's upload finds
//!   the columns Identifier, Grade, Last modified (grade) and Feedback comments by these names
//!   in the language of the account that uploads, and the participant by the number after
//!   "Participant " (参加者). The grade is the score scaled to the assignment's maximum grade;
//!   a submission that could not be graded has no grade (Moodle then keeps its own).
//! - `feedback.zip`: for "Upload multiple feedback files in a zip" (複数のフィードバックファイルを
//!   ZIP でアップロードする): one folder per participant, named as in the download, with the
//!   student's feedback in Japanese and English (`feedback-ja.md`, `feedback-en.md`: every
//!   check's result, as the grader wrote it) and any other file the grader left for that
//!   student under `<out>/feedback/<result>/` (pictures, when there are).

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::Path;

use cg_core::lang::{Lang, Text, t};
use cg_core::time::civil;
use serde_json::Value;

use super::Name;
use crate::{GradeError, Graded, write_atomic};

/// How the Moodle files are written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// The course's Moodle language: the worksheet's column names and texts.
    pub lang: Lang,
    /// The assignment's maximum grade in Moodle (its "Maximum grade"): scores are scaled to it.
    pub max_grade: f64,
    /// The time written as the grades' last modification (Unix seconds).
    pub now: u64,
}

/// The worksheet's columns in Moodle's English language pack (`mod_assign`'s `recordid`,
/// core `fullname`, `email`, `mod_assign`'s `status`, core `grade`, `mod_assign`'s
/// `maxgrade`, `gradecanbechanged`, `lastmodifiedsubmission`, `lastmodifiedgrade`, and
/// `assignfeedback_comments`' name).
pub const COLUMNS_EN: [&str; 10] = [
    "Identifier",
    "Full name",
    "Email address",
    "Status",
    "Grade",
    "Maximum grade",
    "Grade can be changed",
    "Last modified (submission)",
    "Last modified (grade)",
    "Feedback comments",
];

/// The same columns in Moodle's Japanese language pack (`ja`). Checked against the pack's
/// `mod_assign` strings (branch MOODLE_31_STABLE and, for the older ones, MOODLE_24_STABLE):
/// `recordid` ID, `status` ステータス, `maxgrade` 最大評点, `gradecanbechanged` 評点変更可,
/// `lastmodifiedsubmission` 最終更新日時 (提出), `lastmodifiedgrade` 最終更新日時 (評定),
/// `hiddenuser` 参加者, `submissionstatus_submitted` 評定のために提出済み; core's `fullname`
/// フルネーム, `email` メールアドレス and `grade` 評点, and `assignfeedback_comments`' name
/// フィードバックコメント, as Japanese Moodle sites show them.
pub const COLUMNS_JA: [&str; 10] = [
    "ID",
    "フルネーム",
    "メールアドレス",
    "ステータス",
    "評点",
    "最大評点",
    "評点変更可",
    "最終更新日時 (提出)",
    "最終更新日時 (評定)",
    "フィードバックコメント",
];

/// The worksheet's column names in `lang`.
#[must_use]
pub fn columns(lang: Lang) -> [&'static str; 10] {
    match lang {
        Lang::Ja => COLUMNS_JA,
        Lang::En => COLUMNS_EN,
    }
}

/// A participant's identifier in the worksheet: `mod_assign`'s `hiddenuser` and the ID
/// (`Participant 1234567`, `参加者1234567`).
#[must_use]
pub fn identifier(participant: &str, lang: Lang) -> String {
    format!("{}{participant}", t("参加者", "Participant ").get(lang))
}

/// The feedback file of each language.
#[must_use]
pub fn feedback_file(lang: Lang) -> String {
    format!("feedback-{lang}.md")
}

/// A time as the worksheet writes it: `2026-05-20 05:30:00 UTC` (read by PHP's `strtotime`,
/// as Moodle's upload reads it).
#[must_use]
pub fn utc(unix: u64) -> String {
    let (year, month, day, hour, minute, second) = civil(unix);
    format!("{year:04}-{month:02}-{day:02} {hour:02}:{minute:02}:{second:02} UTC")
}

/// A time as a zip entry's (the zip format's range, 1980 to 2107; the earliest outside it).
fn zip_time(unix: u64) -> zip::DateTime {
    let (year, month, day, hour, minute, second) = civil(unix);
    let n = |v: i64| u8::try_from(v).unwrap_or(0);
    let m = |v: u64| u8::try_from(v).unwrap_or(0);
    zip::DateTime::from_date_and_time(
        u16::try_from(year).unwrap_or(0),
        n(month),
        n(day),
        m(hour),
        m(minute),
        m(second),
    )
    .unwrap_or_default()
}

/// A Markdown code block of `text` ([`crate::result::code_block`]) and a line end.
fn block(text: &str) -> String {
    crate::result::code_block(text) + "\n"
}

fn number(v: &Value) -> String {
    v.as_f64().map(|x| format!("{}", (x * 1000.0).round() / 1000.0)).unwrap_or_else(|| "-".into())
}

/// A student's feedback in Markdown, from their result (`<out>/<student>.json`) in `lang`:
/// the scores, the grader's summary, each failed check with what it found, and the passed
/// checks.
#[must_use]
pub fn feedback_md(result: &Value, lang: Lang) -> String {
    let cg = &result["cg"];
    let mut md = format!("# {}\n\n", t("採点結果", "Grading results").get(lang));
    let _ = writeln!(
        md,
        "- {}: {}",
        t("学生番号", "student").get(lang),
        cg["student"].as_str().unwrap_or("?")
    );
    let _ = writeln!(
        md,
        "- {}: {}",
        t("提出物", "submission").get(lang),
        crate::result::md_code(cg["submission"].as_str().unwrap_or(""), lang)
    );
    if result.get("max_score").is_some() {
        let _ = writeln!(
            md,
            "- {}: {} / {}\n",
            t("点数", "score").get(lang),
            number(&result["score"]),
            number(&result["max_score"])
        );
    } else {
        // Not `0 / -`: a refused or unfinished grading has no score to read.
        let _ = writeln!(
            md,
            "- {}: {}\n",
            t("点数", "score").get(lang),
            t(
                "なし（採点されていません。理由は下の概要にあります）",
                "none (not graded: the summary below says why)"
            )
            .get(lang)
        );
    }
    if let Some(per) = cg["assignments"].as_object().filter(|p| !p.is_empty()) {
        let _ = writeln!(
            md,
            "| {} | {} | {} |\n|---|---:|---:|",
            t("課題", "assignment").get(lang),
            t("点数", "score").get(lang),
            t("満点", "out of").get(lang)
        );
        for (m, s) in per {
            let _ = writeln!(md, "| {m} | {} | {} |", number(&s["score"]), number(&s["max_score"]));
        }
        md.push('\n');
    }
    let _ = write!(
        md,
        "## {}\n\n{}\n",
        t("概要", "Summary").get(lang),
        block(result["output"].as_str().unwrap_or(""))
    );
    let tests = result["tests"].as_array().map(Vec::as_slice).unwrap_or_default();
    let (passed, failed): (Vec<&Value>, Vec<&Value>) =
        tests.iter().partition(|t| t["status"] == "passed");
    if !failed.is_empty() {
        let _ = write!(
            md,
            "## {} ({})\n\n",
            t("不合格のチェック", "Failed checks").get(lang),
            failed.len()
        );
        for test in failed {
            let _ = write!(
                md,
                "### {}\n\n{} {} / {}\n\n{}\n",
                test["name"].as_str().unwrap_or("?"),
                t("点数", "score").get(lang),
                number(&test["score"]),
                number(&test["max_score"]),
                block(test["output"].as_str().unwrap_or(""))
            );
        }
    }
    if !passed.is_empty() {
        let _ = write!(
            md,
            "## {} ({})\n\n",
            t("合格したチェック", "Passed checks").get(lang),
            passed.len()
        );
        for test in passed {
            let _ = writeln!(md, "- {}", test["name"].as_str().unwrap_or("?"));
        }
        md.push('\n');
    }
    if result.get("max_score").is_some() {
        md.push_str(&crate::report::feedback_section(&cg["report"], lang));
    }
    md
}

/// Writes a student's feedback files into `dir` (made afresh): [`feedback_md`] of the result
/// in each language.
///
/// # Errors
/// The folder or a file could not be written.
pub fn write_feedback(dir: &Path, ja: &Value, en: &Value) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    for (lang, result) in [(Lang::Ja, ja), (Lang::En, en)] {
        write_atomic(&dir.join(feedback_file(lang)), feedback_md(result, lang).as_bytes())?;
    }
    Ok(())
}

/// One row of the worksheet.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The participant ID.
    pub participant: String,
    /// The full name: the roster's, else the download's; empty under blind marking.
    pub full_name: String,
    /// The grade, already scaled to the maximum grade; `None` when there is none to give.
    pub grade: Option<f64>,
    /// The feedback comment (HTML, as Moodle's comment editor keeps it).
    pub comment: String,
}

fn html(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The worksheet's text: a BOM, the header and a row per participant.
///
/// # Errors
/// The CSV could not be written (not expected: it is written to memory).
pub fn worksheet(rows: &[Row], settings: &Settings) -> Result<String, String> {
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::CRLF).from_writer(Vec::new());
    w.write_record(columns(settings.lang)).map_err(|e| e.to_string())?;
    let grade = |x: f64| format!("{x:.2}");
    let status = t("評定のために提出済み", "Submitted for grading");
    let status = status.get(settings.lang);
    let modified = utc(settings.now);
    for r in rows {
        w.write_record([
            identifier(&r.participant, settings.lang).as_str(),
            // Moodle matches the rows by their identifier; the name is for the instructor's
            // spreadsheet, where one that begins like a formula must stay text.
            &cg_core::quote::spreadsheet_cell(&r.full_name),
            "",
            status,
            &r.grade.map(grade).unwrap_or_default(),
            &grade(settings.max_grade),
            // "Grade can be changed": not read by the upload (assignfeedback_offline's importer
            // reads the identifier, the grade, its last-modified time and the feedback columns
            // only), so the same word in both languages.
            "Yes",
            "-",
            &modified,
            &r.comment,
        ])
        .map_err(|e| e.to_string())?;
    }
    let bytes = w.into_inner().map_err(|e| e.to_string())?;
    Ok(format!("\u{feff}{}", String::from_utf8_lossy(&bytes)))
}

/// A participant's folder in the feedback zip: its name and its files (name, bytes).
pub type Folder = (String, Vec<(String, Vec<u8>)>);

/// The feedback zip of the participants' folders, its entries dated `now` (Unix seconds).
///
/// # Errors
/// The zip could not be written (not expected: it is written to memory).
pub fn feedback_zip(folders: &[Folder], now: u64) -> Result<Vec<u8>, String> {
    let mut z = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated)
        .last_modified_time(zip_time(now));
    for (folder, files) in folders {
        z.add_directory(format!("{folder}/"), options).map_err(|e| e.to_string())?;
        for (name, bytes) in files {
            z.start_file(format!("{folder}/{name}"), options).map_err(|e| e.to_string())?;
            z.write_all(bytes).map_err(|e| e.to_string())?;
        }
    }
    Ok(z.finish().map_err(|e| e.to_string())?.into_inner())
}

/// The feedback comment of a result: the score, each assignment's, and where the details are.
pub(crate) fn comment(result: &Value, lang: Lang) -> String {
    let cg = &result["cg"];
    if result.get("max_score").is_none() {
        let why = crate::result::not_graded(cg, lang).unwrap_or("");
        let why = why.lines().next().unwrap_or("");
        let file = feedback_file(lang);
        // A refusal is the submission's (what was handed in), not a grading that failed.
        let text = if cg["refused"].is_string() {
            Text::new(
                format!(
                    "提出物を受け付けられませんでした（理由: {why}）。詳しくはフィードバックファイル {file} を見てください。"
                ),
                format!(
                    "The submission was refused ({why}). The details are in the feedback file {file}."
                ),
            )
        } else {
            Text::new(
                format!(
                    "採点できませんでした（理由: {why}）。詳しくはフィードバックファイル {file} を見てください。"
                ),
                format!(
                    "Could not be graded ({why}). The details are in the feedback file {file}."
                ),
            )
        };
        return html(text.get(lang));
    }
    let per: Vec<String> = cg["assignments"]
        .as_object()
        .map(|p| {
            p.iter()
                .map(|(m, s)| format!("{m} {}/{}", number(&s["score"]), number(&s["max_score"])))
                .collect()
        })
        .unwrap_or_default();
    let (score, max) = (number(&result["score"]), number(&result["max_score"]));
    let file = feedback_file(lang);
    let text = Text::new(
        format!(
            "チェックの結果: {score} / {max}（{}）。チェックごとの結果はフィードバックファイル {file} にあります。",
            per.join("、")
        ),
        format!(
            "Checks: {score} / {max} ({}). Each check's result is in the feedback file {file}.",
            per.join(", ")
        ),
    );
    let mut comment = text.get(lang).to_owned();
    if let Some(line) = crate::report::line(&cg["report"], lang) {
        // Sentences run on in Japanese; a space between them in English.
        comment.push_str(t("", " ").get(lang));
        comment.push_str(&line);
    }
    html(&comment)
}

/// What [`write()`] wrote.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Written {
    /// Participants in the worksheet and the zip.
    pub participants: usize,
    /// Of them, those with a grade.
    pub graded: usize,
}

/// The files a student's feedback folder holds: `<out>/feedback/<result>/`'s plain files, or,
/// when there is none, the feedback rendered from the result alone (in its own language).
fn feedback_files(out: &Path, name: &str, result: &Value) -> Vec<(String, Vec<u8>)> {
    let dir = out.join("feedback").join(name);
    let mut files: Vec<(String, Vec<u8>)> = std::fs::read_dir(&dir)
        .map(|r| {
            r.flatten()
                .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
                .filter_map(|e| {
                    let n = e.file_name().to_string_lossy().into_owned();
                    (!n.starts_with('.')).then_some(n)
                })
                .filter_map(|n| std::fs::read(dir.join(&n)).ok().map(|b| (n, b)))
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    if files.is_empty() {
        let lang = if result["output"].as_str().is_some_and(|o| o.starts_with("学生番号")) {
            Lang::Ja
        } else {
            Lang::En
        };
        files.push((feedback_file(lang), feedback_md(result, lang).into_bytes()));
    }
    files
}

/// A file of Moodle's that could not be made in memory (`grades.csv`, `feedback.zip`).
fn not_made(dir: &Path, name: &str, e: &str) -> GradeError {
    let shown = dir.display();
    GradeError::Io(Text::new(
        format!("{shown}: {name} を作れません: {e}"),
        format!("{shown}: cannot make {name}: {e}"),
    ))
}

/// Writes `<out>/moodle/grades.csv` and `<out>/moodle/feedback.zip` for the Moodle
/// participants among `graded` (their results are read from `<out>`); `None` when there is
/// none.
///
/// # Errors
/// A result could not be read, or a file not written.
pub fn write(
    out: &Path,
    graded: &[Graded],
    settings: &Settings,
) -> Result<Option<Written>, GradeError> {
    let io = |p: &Path, e: &std::io::Error| GradeError::at(p, e);
    let mut found: Vec<(Name, &Graded, Value)> = Vec::new();
    for g in graded {
        let Some(name) = Name::parse(&g.entry) else { continue };
        let path = out.join(format!("{}.json", g.name));
        let text = std::fs::read_to_string(&path).map_err(|e| io(&path, &e))?;
        let value: Value = serde_json::from_str(&text).map_err(|e| crate::not_json(&path, &e))?;
        found.push((name, g, value));
    }
    if found.is_empty() {
        return Ok(None);
    }
    found.sort_by(|a, b| {
        let id = |n: &Name| n.participant.parse::<u64>().unwrap_or(u64::MAX);
        id(&a.0).cmp(&id(&b.0)).then_with(|| a.1.entry.cmp(&b.1.entry))
    });
    let mut rows = Vec::new();
    let mut folders = Vec::new();
    for (name, g, value) in &found {
        let max = value["max_score"].as_f64().filter(|m| *m > 0.0);
        let grade = max.map(|m| value["score"].as_f64().unwrap_or(0.0) / m * settings.max_grade);
        // Under blind marking the worksheet names nobody, as Moodle's own.
        let roster = value["cg"]["roster"]["name"].as_str().filter(|n| !n.is_empty());
        let full_name = match roster {
            _ if name.is_blind() => String::new(),
            Some(n) => n.to_owned(),
            None => name.full_name.clone(),
        };
        rows.push(Row {
            participant: name.participant.clone(),
            full_name,
            grade,
            comment: comment(value, settings.lang),
        });
        folders.push((name.folder(), feedback_files(out, &g.name, value)));
    }
    let dir = out.join("moodle");
    std::fs::create_dir_all(&dir).map_err(|e| io(&dir, &e))?;
    let csv = worksheet(&rows, settings).map_err(|e| not_made(&dir, "grades.csv", &e))?;
    let path = dir.join("grades.csv");
    write_atomic(&path, csv.as_bytes()).map_err(|e| io(&path, &e))?;
    let zip =
        feedback_zip(&folders, settings.now).map_err(|e| not_made(&dir, "feedback.zip", &e))?;
    let path = dir.join("feedback.zip");
    write_atomic(&path, &zip).map_err(|e| io(&path, &e))?;
    Ok(Some(Written {
        participants: rows.len(),
        graded: rows.iter().filter(|r| r.grade.is_some()).count(),
    }))
}
