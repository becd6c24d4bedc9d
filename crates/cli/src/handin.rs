//! `cg handin`: what grading reads — the six files of `exercises/` and the report — in one zip
//! to upload to Moodle, after what grading would refuse is looked for.
//!
//! The zip holds `exercises/student.toml`, `exercises/src/a1.rs` … `s.rs` and, when there is
//! one, the report grading would read (`report/report.md` or `report.tex`: of both, the one
//! changed last, `report.md` at a tie, as `cg grade` chooses), nothing else: no build output,
//! no other report for grading to set aside. A file grading refuses (one that reads outside
//! itself: `include_str!`, `#[path]`, …) stops it, as the whole submission would score 0.

use std::path::{Path, PathBuf};
use std::time::UNIX_EPOCH;

use cg_assign::IDS;
use cg_core::lang::{Lang, Text, t};

mod zipfile;

/// Options of `cg handin`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Where to write the zip (default: `handin/<student number>.zip`) / zip の書き出し先（既定: `handin/<学生番号>.zip`）
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
}

/// A file put in the zip: its name there and where it is.
struct Taken {
    name: String,
    path: PathBuf,
}

/// When `path` was last changed, in seconds since 1970 (0 when it cannot be told).
fn modified(path: &Path) -> i64 {
    std::fs::metadata(path)
        .and_then(|m| m.modified())
        .ok()
        .and_then(|t| t.duration_since(UNIX_EPOCH).ok())
        .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(i64::MAX))
}

/// The report grading would read from `report/`: of `report.md` and `report.tex`, the one
/// changed last (whole seconds, as a zip keeps them), `report.md` at a tie; and the one left
/// out, if any.
fn report(root: &Path) -> (Option<Taken>, Option<String>) {
    let found: Vec<Taken> = ["report.md", "report.tex"]
        .iter()
        .map(|f| Taken { name: format!("report/{f}"), path: root.join("report").join(f) })
        .filter(|f| f.path.is_file())
        .collect();
    let mut found = found.into_iter();
    match (found.next(), found.next()) {
        (Some(md), Some(tex)) if modified(&tex.path) > modified(&md.path) => {
            (Some(tex), Some(md.name))
        }
        (Some(md), Some(tex)) => (Some(md), Some(tex.name)),
        (one, _) => (one, None),
    }
}

/// Writes the zip for the student of `exercises/student.toml` under the kit's `root` (or at
/// `args.out`) and says what it holds and what to do with it.
///
/// # Errors
/// No student number recorded; a file missing, unreadable or one that grading refuses; the zip
/// cannot be written. Each as a message in `lang`.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    let exercises = crate::kit_path(None, "exercises");
    let root = exercises.parent().map_or_else(|| PathBuf::from("."), Path::to_path_buf);
    let record = cg_assign::read_student_file(&exercises.join("student.toml")).map_err(|e| {
        let save = "`cargo run --release -- assignment --student <学生番号> --save`";
        let save_en = "`cargo run --release -- assignment --student <student number> --save`";
        format!(
            "{}\n{}",
            e.message(lang),
            Text::new(
                format!("提出する前に学生番号を記録してください: {save}"),
                format!("record your student number before handing in: {save_en}"),
            )
            .get(lang)
        )
    })?;
    let mut taken = vec![Taken {
        name: "exercises/student.toml".to_owned(),
        path: exercises.join("student.toml"),
    }];
    let mut missing = Vec::new();
    for module in IDS {
        let name = format!("exercises/src/{module}.rs");
        let path = root.join(&name);
        if !path.is_file() {
            missing.push(name);
            continue;
        }
        // What grading refuses makes the whole submission score 0: said here, not found there.
        if let Ok(text) = std::fs::read_to_string(&path) {
            let refused = cg_assign::screen::screen(&name, &text);
            if !refused.is_empty() {
                return Err(cg_assign::screen::message(&refused).get(lang).to_owned());
            }
        }
        taken.push(Taken { name, path });
    }
    if !missing.is_empty() {
        return Err(Text::new(
            format!(
                "{} がありません。採点では、ない課題のチェックは 0 点です。キットの exercises/ から消してしまったときは、配られたキットから戻してください",
                missing.join("・")
            ),
            format!(
                "{} missing: grading scores the checks of a missing file 0. If you deleted it from the kit's exercises/, put it back from the kit you were given",
                missing.join(", ")
            ),
        )
        .get(lang)
        .to_owned());
    }
    let (report, other) = report(&root);
    taken.extend(report);
    let mut entries = Vec::new();
    for f in &taken {
        let bytes = std::fs::read(&f.path).map_err(|e| {
            Text::new(
                format!("{} を読めません: {}", f.path.display(), Text::io(&e).ja),
                format!("cannot read {}: {}", f.path.display(), Text::io(&e).en),
            )
            .get(lang)
            .to_owned()
        })?;
        entries.push(zipfile::Entry { name: f.name.clone(), bytes, modified: modified(&f.path) });
    }
    let zip = zipfile::write(&entries).map_err(|e| e.to_string())?;
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| root.join("handin").join(format!("{}.zip", record.student.as_str())));
    let written = out
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .map_or(Ok(()), std::fs::create_dir_all)
        .and_then(|()| std::fs::write(&out, &zip));
    written.map_err(|e| {
        Text::new(
            format!("{} を書けません: {}", out.display(), Text::io(&e).ja),
            format!("cannot write {}: {}", out.display(), Text::io(&e).en),
        )
        .get(lang)
        .to_owned()
    })?;
    print!("{}", said(&out, &entries, zip.len(), other.as_deref()).get(lang));
    Ok(())
}

/// What `run` prints: the zip, its files, and what to do next.
fn said(out: &Path, entries: &[zipfile::Entry], size: usize, other: Option<&str>) -> Text {
    let list: String =
        entries.iter().map(|e| format!("  {} ({} B)\n", e.name, e.bytes.len())).collect();
    let mut text = Text::new(
        format!("{} を書きました（{size} B）:\n{list}", out.display()),
        format!("wrote {} ({size} B):\n{list}", out.display()),
    );
    let report = match (entries.iter().any(|e| e.name.starts_with("report/")), other) {
        (true, Some(other)) => Text::new(
            format!(
                "{other} は入れていません（採点が読むのは変更の新しいほうのレポートだけです）\n"
            ),
            format!("{other} is left out (grading reads the report changed last only)\n"),
        ),
        (true, None) => Text::default(),
        (false, _) => t(
            "レポート（report/report.md か report.tex）がないので入れていません。レポートは授業の指示どおりに提出してください\n",
            "no report (report/report.md or report.tex) to put in: hand in the report as the course says\n",
        ),
    };
    let next = t(
        "次に: この zip を Moodle に上げます（出し直すときは前のファイルを消してから）。その前に `cargo run --release -- check` で、止まる・外されるファイルがないことを確かめてください。\n",
        "next: upload this zip to Moodle (to hand in again, delete the old file first). Before that, make sure with `cargo run --release -- check` that no file is stopped or left out.\n",
    );
    for part in [report, next] {
        text.ja.push_str(&part.ja);
        text.en.push_str(&part.en);
    }
    text
}
