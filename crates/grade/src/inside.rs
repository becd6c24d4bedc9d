//! The report a student hands in with the code: `report/report.md` or `report/report.tex`, where
//! `cg report fill` writes it, next to `exercises/` in the submission (a folder, a zip, a Moodle
//! participant's upload and the zips in it), or loose at the top of an upload or of a zip in it.
//! `cg grade` checks its numbers ([`crate::report`]); `cg similarity` compares them.
//!
//! The submission is read as `cg grade` reads it: only listed, never extracted; links, `..`
//! paths and folders named `target` or starting with `.` are not followed; a participant's zip
//! is read into memory only up to [`MAX_UPLOAD_ZIP_BYTES`]. The report is read in the encoding
//! the student's editor wrote it in (UTF-8, UTF-16 or Shift_JIS, detected as `cg report` does:
//! [`cg_core::text::decode`]), and skipped, with a note, when over the caller's limit or not
//! text. When both `report.md` and `report.tex` are there (the fill writes both), the one changed
//! last is the one the student wrote in; `report.md` when they were changed at once; a note names
//! the others found. A PDF of the report, where no text one is, is named in a note.

use std::io::{Cursor, Read};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::moodle::input::MAX_DOWNLOAD_ENTRIES;
use crate::moodle::input::{Entry, MAX_UPLOAD_ZIP_BYTES, Origin};
use crate::submission::{MAX_ZIP_ENTRIES, MODULES, unsafe_name};
use crate::zipfile;
use cg_core::lang::Text;
use cg_core::text::Encoding;

/// The largest report `cg similarity` reads: 4 MiB (a report is some tens of KiB; its figures
/// are other files; the class's reports are held together). `cg grade` reads one at a time, up
/// to the student's own check's limit ([`crate::report::MAX_BYTES`]).
pub const MAX_REPORT_BYTES: u64 = 4 << 20;

/// The report's names, in the order preferred when both were changed at once.
pub const REPORT_NAMES: [&str; 2] = ["report.md", "report.tex"];

/// How deep a submission folder is looked into (the folder holding `exercises/` is at most two
/// levels down, as `cg grade` finds it, and the report two below that).
const PATH_DEPTH: usize = 4;

/// How deep a Moodle participant's folder is looked into, as `cg grade` does.
const UPLOAD_DEPTH: usize = 8;

/// A report found in a submission.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    /// Where, inside the submission (`report/report.md`, `kit.zip/report/report.tex`).
    pub path: String,
    /// Its text.
    pub text: String,
    /// The encoding it was read in.
    pub encoding: Encoding,
}

#[derive(Clone, Debug)]
enum Loc {
    File(PathBuf),
    Zip(Arc<PathBuf>, usize),
    Bytes(Arc<Vec<u8>>, usize),
}

/// A file of the submission that may matter: an exercise file (to find the base) or a report.
#[derive(Clone, Debug)]
struct Item {
    rel: String,
    /// At the top of its upload or zip.
    top: bool,
    size: u64,
    /// When it was last changed (seconds; comparable within one submission).
    time: i64,
    loc: Loc,
}

fn basename(rel: &str) -> &str {
    rel.rsplit('/').next().unwrap_or(rel)
}

fn is_report(rel: &str) -> bool {
    REPORT_NAMES.iter().any(|n| basename(rel).eq_ignore_ascii_case(n))
}

/// The exercise files' paths as `cg grade` finds them (under the base).
fn exercise_paths() -> Vec<String> {
    let mut w: Vec<String> = MODULES.iter().map(|m| format!("exercises/src/{m}.rs")).collect();
    w.push("exercises/student.toml".to_owned());
    w
}

fn wanted(rel: &str) -> bool {
    is_report(rel) || is_pdf(rel) || exercise_paths().iter().any(|w| basename(w) == basename(rel))
}

fn is_zip(rel: &str) -> bool {
    basename(rel).rsplit_once('.').is_some_and(|(_, e)| e.eq_ignore_ascii_case("zip"))
}

fn join(a: &str, b: &str) -> String {
    match (a.is_empty(), b.is_empty()) {
        (true, _) => b.to_owned(),
        (_, true) => a.to_owned(),
        _ => format!("{a}/{b}"),
    }
}

/// The report in `entry`, if one is there (at most `limit` bytes), and notes: on a report found
/// but skipped (too big, not text), on the other reports found and not read (of `report.md`
/// and `report.tex` only one is), and on a PDF of the report found where no text one is.
#[must_use]
pub fn report(entry: &Entry, limit: u64) -> (Option<Found>, Vec<Text>) {
    let mut items = Vec::new();
    match entry.origin() {
        Origin::Path(path) => {
            if std::fs::symlink_metadata(path).is_ok_and(|m| m.is_dir()) {
                walk("", path, PATH_DEPTH, false, &mut items);
            } else if is_zip(&path.to_string_lossy()) {
                list_disk_zip(path, None, "", false, &mut items);
            }
        }
        Origin::Folder(roots) => {
            for (rel, path) in roots {
                walk(rel, path, UPLOAD_DEPTH, true, &mut items);
            }
        }
        Origin::Zip(path, chosen) => list_disk_zip(path, Some(chosen), "", true, &mut items),
        Origin::Refused => {}
    }
    let mut notes = Vec::new();
    let chosen = choose(&items);
    let found = chosen.and_then(|item| match read(item, limit) {
        Ok(found) => Some(found),
        Err(why) => {
            notes.push(why);
            None
        }
    });
    if let Some(chosen) = chosen {
        // The others a student may have meant (two uploads, a `.tex` edited beside the `.md`).
        // Not the fill's other file beside it, older: the one the student changed last is read.
        let older_sibling =
            |i: &Item| parent(&i.rel) == parent(&chosen.rel) && i.time < chosen.time;
        for other in
            items.iter().filter(|i| candidate(i) && i.rel != chosen.rel && !older_sibling(i))
        {
            let (it, that) = (&other.rel, &chosen.rel);
            notes.push(Text::new(
                format!(
                    "{it} もありますが、読んだのは {that} だけです（exercises/ の隣の report/ のもの、同じ場所なら後で変更したほう、同時なら report.md）。書いたほうだけを提出してください"
                ),
                format!(
                    "{it} is there too, but only {that} was read (the one in the report/ beside exercises/; of two in one place, the one changed last, report.md at a tie): hand in only the one you wrote in"
                ),
            ));
        }
    } else if let Some(pdf) = items.iter().find(|i| is_pdf(&i.rel) && in_place(i)) {
        let it = &pdf.rel;
        notes.push(Text::new(
            format!(
                "{it} は PDF なので数値を確かめられません。report/report.md（または report.tex）も提出してください"
            ),
            format!(
                "{it} is a PDF, whose numbers cannot be checked: hand in report/report.md (or report.tex) too"
            ),
        ));
    }
    (found, notes)
}

/// A PDF (of the report, when [`in_place`]).
fn is_pdf(rel: &str) -> bool {
    basename(rel).to_ascii_lowercase().ends_with(".pdf")
}

/// Where a report is looked for: in a `report/` folder, or at the top of an upload or a zip.
fn in_place(item: &Item) -> bool {
    item.top || basename(parent(&item.rel)).eq_ignore_ascii_case("report")
}

/// The folder a path lies in (`""` at the top).
fn parent(rel: &str) -> &str {
    rel.rsplit_once('/').map_or("", |(d, _)| d)
}

/// A report [`choose`] may take: `report.md` or `report.tex` where reports are looked for.
fn candidate(item: &Item) -> bool {
    is_report(&item.rel) && in_place(item)
}

/// The report to read: in the folder holding `exercises/` (its `report/`), else in the
/// shallowest `report/` folder, else loose at the top of an upload or a zip; of `report.md`
/// and `report.tex` in one folder, the one changed last (`report.md` at a tie).
fn choose(items: &[Item]) -> Option<&Item> {
    let exercises = exercise_paths();
    let base = items
        .iter()
        .filter_map(|i| {
            exercises.iter().find_map(|w| {
                i.rel.strip_suffix(w.as_str()).filter(|p| p.is_empty() || p.ends_with('/'))
            })
        })
        .min_by_key(|p| (p.len(), p.to_string()));
    let in_report = |rel: &str| basename(parent(rel)).eq_ignore_ascii_case("report");
    let reports: Vec<&Item> = items.iter().filter(|i| candidate(i)).collect();
    let rank = |i: &Item| {
        let here = base.is_some_and(|b| parent(&i.rel) == format!("{b}report"));
        (!here, !in_report(&i.rel), i.rel.matches('/').count(), parent(&i.rel).to_owned())
    };
    let best = reports.iter().map(|i| rank(i)).min()?;
    reports.into_iter().filter(|i| rank(i) == best).min_by_key(|i| {
        let md = basename(&i.rel).eq_ignore_ascii_case(REPORT_NAMES[0]);
        (std::cmp::Reverse(i.time), !md, i.rel.clone())
    })
}

fn too_big(rel: &str, size: u64, limit: u64) -> Text {
    Text::new(
        format!("{rel} が大きすぎるので読みません（{size} バイト、上限 {limit}）"),
        format!("{rel} is too big and was skipped ({size} bytes, at most {limit})"),
    )
}

fn unreadable_io(rel: &str, e: &std::io::Error) -> Text {
    skipped(rel, &Text::io(e))
}

fn skipped(rel: &str, why: &Text) -> Text {
    Text::new(
        format!("{rel} を読めないので飛ばします: {}", why.ja),
        format!("{rel} cannot be read and was skipped: {}", why.en),
    )
}

/// Reads `reader` up to one byte over the limit (the size a zip declares may lie).
fn bounded(reader: impl Read, rel: &str, limit: u64) -> Result<Vec<u8>, Text> {
    let mut bytes = Vec::new();
    reader.take(limit + 1).read_to_end(&mut bytes).map_err(|e| unreadable_io(rel, &e))?;
    if bytes.len() as u64 > limit {
        return Err(too_big(rel, bytes.len() as u64, limit));
    }
    Ok(bytes)
}

fn from_zip<R: Read + std::io::Seek>(
    mut zip: zip::ZipArchive<R>,
    at: usize,
    rel: &str,
    limit: u64,
) -> Result<Vec<u8>, Text> {
    let entry = zip.by_index(at).map_err(|e| skipped(rel, &crate::submission::zip_reason(&e)))?;
    bounded(entry, rel, limit)
}

fn read(item: &Item, limit: u64) -> Result<Found, Text> {
    let rel = item.rel.as_str();
    if item.size > limit {
        return Err(too_big(rel, item.size, limit));
    }
    let bytes = match &item.loc {
        Loc::File(path) if !path.is_file() => {
            return Err(skipped(
                rel,
                &Text::new("ふつうのファイルではありません", "not a plain file"),
            ));
        }
        Loc::File(path) => {
            bounded(std::fs::File::open(path).map_err(|e| unreadable_io(rel, &e))?, rel, limit)?
        }
        Loc::Zip(path, at) => {
            let file = std::fs::File::open(path.as_path()).map_err(|e| unreadable_io(rel, &e))?;
            let zip = zipfile::open(file, MAX_DOWNLOAD_ENTRIES).map_err(|t| skipped(rel, &t))?;
            from_zip(zip, *at, rel, limit)?
        }
        Loc::Bytes(bytes, at) => {
            let zip = zipfile::open(Cursor::new(bytes.as_slice()), MAX_ZIP_ENTRIES)
                .map_err(|t| skipped(rel, &t))?;
            from_zip(zip, *at, rel, limit)?
        }
    };
    let (text, encoding) = cg_core::text::decode(&bytes, None).map_err(|e| {
        // Not `--encoding`'s advice: the student's file is what is read, not a command's.
        let t = e.text_without_option();
        Text::new(
            format!("{rel} を文字として読めないので飛ばします: {}", t.ja),
            format!("{rel} is not text and was skipped: {}", t.en),
        )
    })?;
    Ok(Found { path: rel.to_owned(), text, encoding })
}

/// The reports of a folder of their own (`--reports` of `cg grade` and `cg similarity`), by
/// student number.
#[derive(Clone, Debug, Default)]
pub struct Folder {
    /// Each student number's report file, read, or why it could not be (too big, not text: a
    /// PDF).
    pub by_student: std::collections::BTreeMap<String, (PathBuf, Result<Found, Text>)>,
    /// The files whose names hold no student number.
    pub unnamed: Vec<String>,
}

/// The reports in `dir`: each plain file whose name holds a student number (`20260001.md`,
/// `report-20260001.txt`: [`eight_digits`]) is that student's, read as a report inside a
/// submission is (at most `limit` bytes, in the encoding detected). Of two for one
/// number, the one changed last, `.md` at a tie (as inside a submission). Hidden files, links
/// and folders are not read.
///
/// # Errors
/// The folder cannot be read.
pub fn folder(dir: &Path, limit: u64) -> Result<Folder, Text> {
    let shown = dir.display();
    let list = std::fs::read_dir(dir).map_err(|e| {
        let why = Text::io(&e);
        Text::new(
            format!("{shown} を読めません: {}", why.ja),
            format!("cannot read {shown}: {}", why.en),
        )
    })?;
    let mut names: Vec<PathBuf> = list.flatten().map(|e| e.path()).collect();
    names.sort();
    let mut out = Folder::default();
    let mut chosen: std::collections::BTreeMap<String, Item> = std::collections::BTreeMap::new();
    for path in names.into_iter().take(MAX_ZIP_ENTRIES) {
        let Ok(meta) = std::fs::symlink_metadata(&path) else { continue };
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        if !meta.is_file() || name.starts_with('.') {
            continue;
        }
        let Some(number) = eight_digits(&name) else {
            out.unnamed.push(name);
            continue;
        };
        // Named by its file name alone (the student's feedback shows it; the instructor's
        // folder is none of theirs).
        let rel = name.clone();
        let item =
            Item { rel, top: true, size: meta.len(), time: seconds(&meta), loc: Loc::File(path) };
        let later = |a: &Item| {
            let md = basename(&a.rel).to_ascii_lowercase().ends_with(".md");
            (a.time, md)
        };
        match chosen.get(number) {
            Some(kept) if later(kept) >= later(&item) => {}
            _ => {
                chosen.insert(number.to_owned(), item);
            }
        }
    }
    for (number, item) in chosen {
        let Loc::File(path) = &item.loc else { continue };
        out.by_student.insert(number, (path.clone(), read(&item, limit)));
    }
    Ok(out)
}

/// The first run of exactly eight digits in `name`: the student number a report's file name
/// holds.
#[must_use]
pub fn eight_digits(name: &str) -> Option<&str> {
    let bytes = name.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_digit() {
            let start = i;
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
            if i - start == 8 {
                return Some(&name[start..i]);
            }
        } else {
            i += 1;
        }
    }
    None
}

fn seconds(meta: &std::fs::Metadata) -> i64 {
    meta.modified()
        .ok()
        .and_then(|t| t.duration_since(std::time::UNIX_EPOCH).ok())
        .map_or(0, |d| i64::try_from(d.as_secs()).unwrap_or(i64::MAX))
}

/// The files that may matter under `path` (standing for `rel`): no link followed, no folder
/// named `target` or starting with `.`, at most [`MAX_ZIP_ENTRIES`] looked at; with `zips`,
/// the zips in it looked into.
fn walk(rel: &str, path: &Path, depth: usize, zips: bool, out: &mut Vec<Item>) {
    let mut seen = 0usize;
    let mut stack = vec![(rel.to_owned(), path.to_path_buf(), 0usize)];
    while let Some((rel, path, level)) = stack.pop() {
        let Ok(meta) = std::fs::symlink_metadata(&path) else { continue };
        if meta.file_type().is_symlink() {
            continue;
        }
        if meta.is_dir() {
            let name = basename(&rel);
            if level >= depth || (level > 0 && (name == "target" || name.starts_with('.'))) {
                continue;
            }
            let Ok(list) = std::fs::read_dir(&path) else { continue };
            for e in list.flatten() {
                seen += 1;
                if seen > MAX_ZIP_ENTRIES {
                    return;
                }
                let name = e.file_name().to_string_lossy().into_owned();
                stack.push((join(&rel, &name), e.path(), level + 1));
            }
        } else if meta.is_file() && zips && is_zip(&rel) {
            list_disk_zip(&path, None, &rel, false, out);
        } else if meta.is_file() && wanted(&rel) {
            let top = level <= 1 && !rel.contains('/');
            out.push(Item {
                rel,
                top,
                size: meta.len(),
                time: seconds(&meta),
                loc: Loc::File(path),
            });
        }
    }
}

/// A zip entry's name as `cg grade` reads it: UTF-8, else Shift_JIS, else the zip's own; `\`
/// as `/`.
fn entry_name(raw: &[u8], fallback: &str) -> String {
    let name = match std::str::from_utf8(raw) {
        Ok(s) => s.to_owned(),
        Err(_) => cg_core::text::decode(raw, Some(Encoding::ShiftJis))
            .map_or_else(|_| fallback.to_owned(), |(s, _)| s),
    };
    name.replace('\\', "/")
}

/// A zip's date as seconds from year 0 (local time, as the zip stores it).
fn zip_seconds(t: Option<zip::DateTime>) -> i64 {
    let Some(t) = t else { return 0 };
    let days = i64::from(t.year()) * 372 + i64::from(t.month()) * 31 + i64::from(t.day());
    days * 86_400 + i64::from(t.hour()) * 3600 + i64::from(t.minute()) * 60 + i64::from(t.second())
}

/// The files that may matter in the zip at `path` (only the items `chosen`, with the paths
/// they stand for, when given: a Moodle download's participant), each named `prefix/…`; with
/// `zips`, the zips in it looked into (one level, as `cg grade` does).
fn list_disk_zip(
    path: &Path,
    chosen: Option<&[(usize, String)]>,
    prefix: &str,
    zips: bool,
    out: &mut Vec<Item>,
) {
    // Only a plain file: a FIFO named .zip would be waited on for ever.
    if !path.is_file() {
        return;
    }
    let Ok(file) = std::fs::File::open(path) else { return };
    // A Moodle download (its participant's items chosen) may hold a whole class.
    let most = if chosen.is_some() { MAX_DOWNLOAD_ENTRIES } else { MAX_ZIP_ENTRIES };
    let Ok(mut zip) = zipfile::open(file, most) else { return };
    let shared = Arc::new(path.to_path_buf());
    let all: Vec<(usize, Option<String>)> = match chosen {
        Some(items) => items.iter().map(|(i, rel)| (*i, Some(rel.clone()))).collect(),
        None => (0..zip.len()).map(|i| (i, None)).collect(),
    };
    // The inner zips kept in memory for their reports, together at most one upload's largest
    // zip: twelve inner zips of 250 MB took 3 GB.
    let mut kept = 0u64;
    for (i, given) in all {
        let Some((rel, size, time)) = zip.by_index_raw(i).ok().and_then(|e| {
            if e.is_dir() || e.is_symlink() {
                return None;
            }
            let name =
                given.unwrap_or_else(|| entry_name(e.name_raw(), &e.name().unwrap_or_default()));
            (!unsafe_name(&name)).then(|| (name, e.size(), zip_seconds(e.last_modified())))
        }) else {
            continue;
        };
        let top = !rel.contains('/');
        let rel = join(prefix, &rel);
        if zips && is_zip(&rel) {
            let room = MAX_UPLOAD_ZIP_BYTES.saturating_sub(kept);
            if size > room {
                continue;
            }
            let Ok(entry) = zip.by_index(i) else { continue };
            let mut bytes = Vec::new();
            if entry.take(room + 1).read_to_end(&mut bytes).is_err() || bytes.len() as u64 > room {
                continue;
            }
            kept += bytes.len() as u64;
            list_bytes_zip(Arc::new(bytes), &rel, out);
        } else if wanted(&rel) {
            out.push(Item { rel, top, size, time, loc: Loc::Zip(Arc::clone(&shared), i) });
        }
    }
}

/// The files that may matter in a zip inside an upload, each named `prefix/…`.
fn list_bytes_zip(bytes: Arc<Vec<u8>>, prefix: &str, out: &mut Vec<Item>) {
    let Ok(mut zip) = zipfile::open(Cursor::new(bytes.as_slice()), MAX_ZIP_ENTRIES) else {
        return;
    };
    for i in 0..zip.len() {
        let Ok(e) = zip.by_index_raw(i) else { continue };
        let name = entry_name(e.name_raw(), &e.name().unwrap_or_default());
        if e.is_dir() || e.is_symlink() || unsafe_name(&name) || !wanted(&name) {
            continue;
        }
        let (top, size, time) = (!name.contains('/'), e.size(), zip_seconds(e.last_modified()));
        out.push(Item {
            rel: join(prefix, &name),
            top,
            size,
            time,
            loc: Loc::Bytes(Arc::clone(&bytes), i),
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn item(rel: &str, time: i64) -> Item {
        Item {
            rel: rel.to_owned(),
            top: !rel.contains('/'),
            size: 1,
            time,
            loc: Loc::File(rel.into()),
        }
    }

    /// A folder of reports (`--reports`): each by the student number in its name, the one
    /// changed last of two, `.md` at a tie; a name without a number is unnamed; a hidden file is
    /// not read; one that is not text is that student's, with why.
    #[test]
    fn a_folder_of_reports_is_read_by_student_number() {
        let dir = std::env::temp_dir().join(format!("cg-inside-folder-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let write = |name: &str, bytes: &[u8], age_s: u64| {
            let path = dir.join(name);
            std::fs::write(&path, bytes).unwrap();
            let when = std::time::SystemTime::now() - std::time::Duration::from_secs(age_s);
            std::fs::File::options().write(true).open(&path).unwrap().set_modified(when).unwrap();
        };
        write("20260001.md", b"V0 (1.0, 0.0, 0.0)\n", 100);
        // Two for 20260002: the newer .tex, not the older .md.
        write("report-20260002.md", b"old", 100);
        write("report-20260002.tex", b"new", 10);
        // Two for 20260003 changed at once: the .md.
        write("20260003.tex", b"tex", 50);
        write("20260003.md", b"md", 50);
        write("notes.txt", b"x", 0);
        write(".20260004.md", b"hidden", 0);
        write("20260005.pdf", b"%PDF-1.4\x00\x01\x02\xff\xfe\x00", 0);
        std::fs::create_dir_all(dir.join("20260006")).unwrap();
        let f = folder(&dir, MAX_REPORT_BYTES).unwrap();
        let text = |n: &str| f.by_student[n].1.as_ref().map(|r| r.text.clone());
        assert_eq!(text("20260001").unwrap(), "V0 (1.0, 0.0, 0.0)\n");
        assert_eq!(text("20260002").unwrap(), "new");
        assert_eq!(text("20260003").unwrap(), "md");
        assert!(text("20260005").unwrap_err().en.contains("not text"), "{:?}", f.by_student);
        let numbers: Vec<&str> = f.by_student.keys().map(String::as_str).collect();
        assert_eq!(numbers, ["20260001", "20260002", "20260003", "20260005"]);
        assert_eq!(f.unnamed, ["notes.txt"]);
        assert!(
            folder(&dir.join("missing"), MAX_REPORT_BYTES)
                .unwrap_err()
                .en
                .starts_with("cannot read")
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// Of report.md and report.tex changed at once, report.md is read and report.tex named as
    /// not checked (a student who edited the .tex heard nothing); a PDF alone is named as one
    /// (it was "no report").
    #[test]
    fn the_reports_not_read_are_named() {
        let dir = std::env::temp_dir().join(format!("cg-inside-others-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("exercises/src")).unwrap();
        std::fs::create_dir_all(dir.join("report")).unwrap();
        std::fs::write(dir.join("exercises/student.toml"), "student = \"20260001\"\n").unwrap();
        let when = std::time::SystemTime::now() - std::time::Duration::from_secs(60);
        for name in ["report/report.md", "report/report.tex"] {
            std::fs::write(dir.join(name), name).unwrap();
            std::fs::File::options()
                .write(true)
                .open(dir.join(name))
                .unwrap()
                .set_modified(when)
                .unwrap();
        }
        let entry = Entry::single(&dir);
        let (found, notes) = report(&entry, MAX_REPORT_BYTES);
        assert_eq!(found.unwrap().path, "report/report.md");
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0]
                .en
                .starts_with("report/report.tex is there too, but only report/report.md was read"),
            "{}",
            notes[0].en
        );
        // The .md changed later: it is the one written in, and the older .tex is no news.
        std::fs::File::options()
            .write(true)
            .open(dir.join("report/report.md"))
            .unwrap()
            .set_modified(std::time::SystemTime::now())
            .unwrap();
        assert_eq!(report(&entry, MAX_REPORT_BYTES).1, []);
        // A PDF alone.
        std::fs::remove_file(dir.join("report/report.md")).unwrap();
        std::fs::remove_file(dir.join("report/report.tex")).unwrap();
        std::fs::write(dir.join("report/report.pdf"), b"%PDF-1.4").unwrap();
        let (found, notes) = report(&entry, MAX_REPORT_BYTES);
        assert!(found.is_none());
        assert_eq!(notes.len(), 1, "{notes:?}");
        assert!(
            notes[0].en.starts_with("report/report.pdf is a PDF, whose numbers cannot be checked"),
            "{}",
            notes[0].en
        );
        assert!(notes[0].ja.contains("PDF なので数値を確かめられません"), "{}", notes[0].ja);
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn the_report_next_to_exercises_and_changed_last_is_chosen() {
        let chosen = |items: &[Item]| choose(items).map(|i| i.rel.clone());
        let kit = [
            item("kit/exercises/src/a1.rs", 0),
            item("kit/report/report.md", 5),
            item("kit/report/report.tex", 9),
            item("kit/report-template/ja/report.md", 20),
            item("old/report/report.md", 30),
        ];
        assert_eq!(chosen(&kit).as_deref(), Some("kit/report/report.tex"));
        let mut tie = kit.to_vec();
        tie[2].time = 5;
        assert_eq!(chosen(&tie).as_deref(), Some("kit/report/report.md"));
        // A loose report of an upload whose exercises/ is in a zip.
        let loose = [item("exercises.zip/exercises/student.toml", 0), item("report.md", 0)];
        assert_eq!(chosen(&loose).as_deref(), Some("report.md"));
        // A template's copy is no report.
        assert_eq!(chosen(&kit[3..4]), None);
    }
}
