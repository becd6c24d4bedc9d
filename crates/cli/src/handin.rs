//! `cg handin`: what grading reads — the six files of `exercises/` and the report — in one zip
//! to upload to Moodle, after what grading would refuse is looked for.
//!
//! The zip holds `exercises/student.toml`, `exercises/src/a1.rs` … `s.rs` and, when there is
//! one, the report grading would read (`report/report.md` or `report.tex`: of both, the one
//! changed last, `report.md` at a tie, as `cg grade` chooses) with its PDF (`report/report.pdf`,
//! what the teacher reads; grading sets a PDF beside a text report aside), nothing else: no
//! build output, no other report for grading to set aside. A PDF older than the report is said
//! (made before the last change), one over [`MAX_PDF_BYTES`] left out with what to do. Each assignment's file is read as grading reads it
//! (one saved as Shift_JIS or UTF-16 converted, with a note to save it as UTF-8, which `cg
//! check` needs) and screened as grading screens it: a file grading refuses (one that reads
//! outside itself: `include_str!`, `#[path]`, …: the whole submission would score 0), a module
//! kept in a file of its own (`mod helper;`: it does not compile in grading) or a file that is no
//! text stops it.
//!
//! Then, unless `--no-check`, the checks run as `cg check` runs them (and grading will), and one
//! line an assignment says how many pass and which tasks are not done; a file that does not
//! compile (grading scores its assignment 0) is said, the zip still written, and the exit status
//! is 1.

use std::path::{Path, PathBuf};
use std::time::UNIX_EPOCH;

use cg_assign::{IDS, Variants, Which};
use cg_core::lang::{Lang, Text, t};
use cg_harness::exit::Ending;

mod zipfile;

/// Options of `cg handin`.
#[derive(Debug, clap::Args)]
pub struct Args {
    /// Where to write the zip (default: `handin/<student number>.zip`) / zip の書き出し先（既定: `handin/<学生番号>.zip`）
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Do not run the checks first (they run as `check` runs them, and say what grading would stop) / 先にチェックを実行しない
    #[arg(long)]
    pub no_check: bool,
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

/// The largest report PDF put in the zip (a report's PDF is some hundreds of KiB; scanned pages
/// or full-size screenshots make tens of MiB, more than a Moodle course usually takes).
pub const MAX_PDF_BYTES: u64 = 20 << 20;

/// The report's PDF, `report/report.pdf`, when there is one: taken, or left out (too big) with
/// why; and a note when it is older than `text`, the report taken (the PDF was made before the
/// report's last change).
fn report_pdf(root: &Path, text: Option<&Taken>) -> (Option<Taken>, Option<Text>) {
    let pdf = Taken { name: "report/report.pdf".to_owned(), path: root.join("report/report.pdf") };
    let Some(meta) = std::fs::metadata(&pdf.path).ok().filter(std::fs::Metadata::is_file) else {
        return (None, None);
    };
    if meta.len() > MAX_PDF_BYTES {
        let (mib, max) = (meta.len() as f64 / f64::from(1 << 20), MAX_PDF_BYTES >> 20);
        let mib = cg_core::notation::fixed64(mib, 1);
        return (
            None,
            Some(Text::new(
                format!(
                    "report/report.pdf は {mib} MiB あり、zip には入れていません（上限 {max} MiB）。画像を小さくして PDF を作り直すか、授業の指示どおりに別に提出してください"
                ),
                format!(
                    "report/report.pdf is {mib} MiB and is left out of the zip (at most {max} MiB): make the PDF again with smaller images, or hand it in as the course says"
                ),
            )),
        );
    }
    let stale = text.filter(|t| modified(&t.path) > modified(&pdf.path)).map(|t| {
        let name = &t.name;
        Text::new(
            format!(
                "report/report.pdf は {name} より古いファイルです。{name} を直した後なら、PDF を作り直してからもう一度 handin してください"
            ),
            format!(
                "report/report.pdf is older than {name}: if you changed {name} after making the PDF, make it again and hand in again"
            ),
        )
    });
    (Some(pdf), stale)
}

/// Writes the zip for the student of `exercises/student.toml` under the kit's `root` (or at
/// `args.out`) and says what it holds and what to do with it.
///
/// # Errors
/// No student number recorded; a file missing, unreadable or one that grading refuses; the zip
/// cannot be written. Each as a message in `lang`.
pub fn run(args: &Args, lang: Lang) -> Result<Ending, String> {
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
    let mut notes = Vec::new();
    let mut converted = Vec::new();
    for module in IDS {
        let name = format!("exercises/src/{module}.rs");
        let path = root.join(&name);
        if !path.is_file() {
            missing.push(name);
            continue;
        }
        if let Some(note) = screened(&name, module, &path).map_err(|e| e.get(lang).to_owned())? {
            notes.push(note);
            converted.push(name.clone());
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
    let checked = if args.no_check { None } else { Some(checks(&record, &converted, lang)?) };
    let (report, other) = report(&root);
    let (pdf, pdf_note) = report_pdf(&root, report.as_ref());
    taken.extend(report);
    taken.extend(pdf);
    notes.extend(pdf_note);
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
    for note in &notes {
        println!("{}", note.get(lang));
    }
    if let Some(checked) = &checked {
        print!("{}", checked.said.get(lang));
    }
    print!("{}", said(&out, &entries, zip.len(), other.as_deref(), checked.is_some()).get(lang));
    Ok(match &checked {
        Some(c) if c.stopped => {
            eprintln!("{}", t(
                "zip は書きましたが、コンパイルできないファイルがあります。その課題は採点で 0 点です。直してからもう一度 handin してください",
                "the zip is written, but a file does not compile: its assignment scores 0 in grading. Fix it and hand in again",
            ).get(lang));
            Ending::Mistakes
        }
        _ => Ending::Ok,
    })
}

/// What the checks said, one line an assignment, and whether a file grading would build does
/// not compile.
struct Checked {
    said: Text,
    stopped: bool,
}

/// Runs every check as `cg check` does (the student's functions built into a worker, 20 s a
/// check, 2 GiB), and says per assignment how far it is: what grading will score. A file saved
/// as Shift_JIS or UTF-16 (`converted`: grading converts it) is said to be unchecked here, not
/// to fail to compile.
///
/// # Errors
/// The worker cannot be built (a crate added to exercises/Cargo.toml, an error outside the
/// assignments' files), as `cg check` says it.
fn checks(
    record: &cg_assign::StudentFile,
    converted: &[String],
    lang: Lang,
) -> Result<Checked, String> {
    eprintln!("{}", t(
        "採点と同じチェックを実行しています（初回はあなたの関数のビルドに時間がかかります）…",
        "running the checks as grading runs them (the first time, building your functions takes a while)…",
    ).get(lang));
    let variants = Variants::for_student(&record.student, record.table);
    let worker = cg_assign::local::worker_for_this_kit(cg_assign::local::MEMORY_MB, lang)?;
    let (reports, _) = variants.reports_in_worker(Which::ALL, worker, cg_assign::local::CALL_LIMIT);
    let mut said = t("チェック（採点と同じもの）:\n", "the checks (as grading runs them):\n");
    let mut stopped = false;
    for r in &reports {
        let file = format!("exercises/src/{}.rs", r.assignment);
        let line = if !r.files_not_compiling().is_empty() && converted.contains(&file) {
            Text::new(
                format!(
                    "ここではチェックしていません（{file} が UTF-8 でないため。上を参照）。採点では UTF-8 に直して読みます"
                ),
                format!(
                    "not checked here ({file} is not UTF-8: see above); grading reads it converted"
                ),
            )
        } else if !r.files_not_compiling().is_empty() {
            stopped = true;
            Text::new(
                format!(
                    "{file} がコンパイルできません。採点ではこの課題が 0 点です。`cargo run --release -- check {}` で場所が分かります",
                    r.assignment
                ),
                format!(
                    "{file} does not compile: grading scores this assignment 0. `cargo run --release -- check {}` shows where",
                    r.assignment
                ),
            )
        } else {
            let mut line = Text::new(
                format!("{}/{} 個のチェックに合格", r.passed(), r.total()),
                format!("{}/{} checks pass", r.passed(), r.total()),
            );
            let not_done = r.tasks_not_done();
            if !not_done.is_empty() {
                line.ja.push_str(&format!("、未完成: {}", not_done.join(", ")));
                line.en.push_str(&format!("; not done yet: {}", not_done.join(", ")));
            }
            if r.timed_out() {
                line.ja.push_str("、制限時間を超えた関数があります（採点でも同じく止められます）");
                line.en.push_str("; a function ran out of time (grading stops it too)");
            }
            line
        };
        said.ja.push_str(&format!("  {:<3} {}\n", r.assignment, line.ja));
        said.en.push_str(&format!("  {:<3} {}\n", r.assignment, line.en));
    }
    Ok(Checked { said, stopped })
}

/// `path` (assignment `module`'s file, `name` in the zip) read as grading reads it — converted
/// to UTF-8 from Shift_JIS or UTF-16 — and screened as grading screens it.
///
/// # Errors
/// What grading refuses (the whole submission scores 0 for it), a module in a file of its own
/// (grading reads only the assignments' files: it does not compile there, the assignment scores
/// 0), a file that is not text: said here, not found there. `Ok(Some(note))` for a file grading
/// converts, which the student's own `check` cannot build.
fn screened(name: &str, module: &str, path: &Path) -> Result<Option<Text>, Text> {
    let bytes = std::fs::read(path).map_err(|e| {
        Text::new(
            format!("{} を読めません: {}", path.display(), Text::io(&e).ja),
            format!("cannot read {}: {}", path.display(), Text::io(&e).en),
        )
    })?;
    let (text, note) = match String::from_utf8(bytes) {
        Ok(text) => (text, None),
        Err(e) => {
            let (text, encoding) = cg_core::text::decode(e.as_bytes(), None).map_err(|e| {
                let why = e.text_without_option();
                Text::new(format!("{name}: {}", why.ja), format!("{name}: {}", why.en))
            })?;
            (text, Some(cg_assign::local::not_utf8(name, encoding.name())))
        }
    };
    let refused = cg_assign::screen::screen(name, &text);
    if !refused.is_empty() {
        return Err(cg_assign::screen::message(&refused));
    }
    if let Some(r) = cg_assign::screen::other_files(name, &text).first() {
        return Err(cg_assign::screen::other_file_message(r, module));
    }
    Ok(note)
}

/// What `run` prints: the zip, its files, and what to do next.
fn said(
    out: &Path,
    entries: &[zipfile::Entry],
    size: usize,
    other: Option<&str>,
    checked: bool,
) -> Text {
    let list: String =
        entries.iter().map(|e| format!("  {} ({} B)\n", e.name, e.bytes.len())).collect();
    let mut text = Text::new(
        format!("{} を書きました（{size} B）:\n{list}", out.display()),
        format!("wrote {} ({size} B):\n{list}", out.display()),
    );
    let text_report =
        entries.iter().any(|e| e.name.starts_with("report/") && !e.name.ends_with(".pdf"));
    let pdf = entries.iter().any(|e| e.name == "report/report.pdf");
    let report = match (text_report, other) {
        (true, Some(other)) => Text::new(
            format!(
                "{other} は入れていません（採点が読むのは変更の新しいほうのレポートだけです）\n"
            ),
            format!("{other} is left out (grading reads the report changed last only)\n"),
        ),
        (true, None) => Text::default(),
        (false, _) if pdf => t(
            "report/report.md も report.tex もないので、レポートは PDF だけです。採点は PDF の数値を確かめられないので、PDF の元のファイル（report.md か report.tex）も report/ に置いてもう一度 handin してください\n",
            "neither report/report.md nor report.tex is there, only the PDF: grading cannot check the numbers of a PDF, so put the file you made it from (report.md or report.tex) in report/ too and hand in again\n",
        ),
        (false, _) => t(
            "レポート（report/report.md か report.tex）がないので入れていません。レポートは授業の指示どおりに提出してください\n",
            "no report (report/report.md or report.tex) to put in: hand in the report as the course says\n",
        ),
    };
    let next = if checked {
        t(
            "次に: この zip を Moodle に上げます（出し直すときは前のファイルを消してから）。\n",
            "next: upload this zip to Moodle (to hand in again, delete the old file first).\n",
        )
    } else {
        t(
            "次に: この zip を Moodle に上げます（出し直すときは前のファイルを消してから）。その前に `cargo run --release -- check` で、止まる・外されるファイルがないことを確かめてください。\n",
            "next: upload this zip to Moodle (to hand in again, delete the old file first). Before that, make sure with `cargo run --release -- check` that no file is stopped or left out.\n",
        )
    };
    for part in [report, next] {
        text.ja.push_str(&part.ja);
        text.en.push_str(&part.en);
    }
    text
}
