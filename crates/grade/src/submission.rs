//! Reading a submission — a folder or a `.zip` holding an `exercises/` tree — as hostile input:
//! only `exercises/src/{a1,a2,a3,a4,s}.rs` and `exercises/student.toml` are read, nothing is
//! extracted to disk, and a zip with an absolute or `..` path, a symlink or an oversized entry is
//! refused with the reason.

use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Path, PathBuf};

use crate::Text;
use crate::unread::{Unopened, files_in, nothing_to_grade, other_archive};
use cg_core::lang::Lang;
// A name from a submission (a zip's entry, a file's) as a message quotes it: at most 64
// characters, nothing hidden; messages go to the instructor's terminal, the feedback and
// Moodle's comment.
use cg_core::quote::shown;

/// The student's files, `exercises/src/<id>.rs`: one per assignment, from the kit's one list.
pub const MODULES: &[&str] = cg_assign::IDS;

/// The most bytes one file of a submission may have.
pub const MAX_FILE_BYTES: u64 = 1 << 20;

/// The most entries a zip may hold.
pub const MAX_ZIP_ENTRIES: usize = 10_000;

/// The files taken from a submission.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Files {
    /// `a1` … `s` → the text of `exercises/src/<m>.rs`, for those present.
    pub modules: BTreeMap<String, Vec<u8>>,
    /// `exercises/student.toml`, when present.
    pub student_toml: Option<Vec<u8>>,
    /// The modules that were not UTF-8 (saved as Shift_JIS or UTF-16 by a Japanese editor),
    /// each with the encoding they were read in: grading converts them, since rustc reads
    /// only UTF-8 (a Shift_JIS `a1.rs` made every assignment score 0).
    pub converted: BTreeMap<String, String>,
}

impl Files {
    /// `bytes` as `module`'s file (`None`: `student.toml`).
    pub(crate) fn put(&mut self, module: Option<&str>, bytes: Vec<u8>) {
        match module {
            Some(m) => {
                self.modules.insert(m.to_owned(), bytes);
            }
            None => self.student_toml = Some(bytes),
        }
    }
}

/// The relative paths (inside `exercises/`) of the files a submission contributes.
fn wanted() -> Vec<(String, Option<&'static str>)> {
    let mut w: Vec<(String, Option<&'static str>)> =
        MODULES.iter().map(|m| (format!("exercises/src/{m}.rs"), Some(*m))).collect();
    w.push(("exercises/student.toml".to_owned(), None));
    w
}

fn too_big(name: &str, size: u64) -> Text {
    Text::new(
        format!("{} が大きすぎます（{size} バイト、上限 {MAX_FILE_BYTES}）", shown(name, Lang::Ja)),
        format!("{} is too big ({size} bytes, at most {MAX_FILE_BYTES})", shown(name, Lang::En)),
    )
}

/// Reads the submission at `path` (a folder, or a file ending in `.zip`).
///
/// # Errors
/// Why the submission is refused: unreadable, not a zip or folder, no `exercises/` in it, or (in
/// a zip) an entry with an absolute or `..` path, a symlink, too many or too big entries; a
/// file that reaches outside itself at compile time ([`crate::screen`]).
pub fn read(path: &Path) -> Result<Files, Text> {
    let meta = std::fs::symlink_metadata(path).map_err(|e| {
        let why = Text::io(&e);
        Text::new(format!("読めません: {}", why.ja), format!("cannot be read: {}", why.en))
    })?;
    if meta.file_type().is_symlink() {
        return Err(Text::new(
            "シンボリックリンクは受け付けません",
            "a symbolic link is not accepted as a submission",
        ));
    }
    let files = if meta.is_dir() {
        read_folder(path)?
    } else if path.extension().is_some_and(|e| e.eq_ignore_ascii_case("zip")) && meta.is_file() {
        // Only a plain file: a FIFO named .zip would be waited on for ever.
        read_zip(path)?
    } else {
        let neither =
            Text::new("フォルダでも .zip でもありません", "neither a folder nor a .zip file");
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        // A .7z or .rar handed in for a zip: said as such.
        return Err(match other_archive(&name) {
            Some(why) => Text::new(
                format!("{}。{}", neither.ja, why.ja),
                format!("{}: {}", neither.en, why.en),
            ),
            None => neither,
        });
    };
    screened(files)
}

/// The files, each module in UTF-8 ([`Files::converted`]: one in Shift_JIS or UTF-16 is
/// converted; one that is no text the kit reads is left for rustc to name), unless one reaches
/// outside itself at compile time ([`crate::screen`]).
///
/// # Errors
/// The files and lines that do, with what.
pub(crate) fn screened(mut files: Files) -> Result<Files, Text> {
    for (m, bytes) in &mut files.modules {
        if std::str::from_utf8(bytes).is_err()
            && let Ok((text, encoding)) = cg_core::text::decode(bytes, None)
        {
            *bytes = text.into_bytes();
            files.converted.insert(m.clone(), encoding.name().to_owned());
        }
    }
    let refused: Vec<crate::screen::Refused> = files
        .modules
        .iter()
        .flat_map(|(m, bytes)| {
            crate::screen::screen(&format!("exercises/src/{m}.rs"), &String::from_utf8_lossy(bytes))
        })
        .collect();
    if refused.is_empty() { Ok(files) } else { Err(crate::screen::message(&refused)) }
}

fn no_exercises() -> Text {
    Text::new(
        "exercises/ が見つかりません（exercises/src/a1.rs … と exercises/student.toml を入れてください）",
        "no exercises/ found (it must hold exercises/src/a1.rs … and exercises/student.toml)",
    )
}

/// The folders inside `dir` (itself, and folders at most `depth` levels down) that hold
/// `exercises/`, sorted by path; looked for until more than [`MAX_TREES`] are found.
fn find_bases(dir: &Path, depth: usize, out: &mut Vec<PathBuf>) {
    if std::fs::symlink_metadata(dir.join("exercises")).is_ok_and(|m| m.is_dir()) {
        out.push(dir.to_path_buf());
    }
    if depth == 0 || out.len() > MAX_TREES {
        return;
    }
    let Ok(read) = std::fs::read_dir(dir) else { return };
    let mut entries: Vec<PathBuf> = read
        .flatten()
        // `exercises/` itself is a tree, not a folder that holds one.
        .filter(|e| e.file_type().is_ok_and(|t| t.is_dir()) && e.file_name() != "exercises")
        .map(|e| e.path())
        .collect();
    entries.sort();
    for d in entries {
        find_bases(&d, depth - 1, out);
    }
}

/// The most `exercises/` trees one submission may hold (each is read to be compared).
pub const MAX_TREES: usize = 8;

/// The prefixes (`""`, `"backup/"`) before `exercises/` of the exercises' files among `paths`,
/// each once, shortest first.
pub(crate) fn bases<'a>(paths: impl IntoIterator<Item = &'a str>) -> Vec<String> {
    let wanted = wanted();
    let mut out: Vec<String> = paths
        .into_iter()
        .filter_map(|n| {
            wanted.iter().find_map(|(w, _)| {
                n.strip_suffix(w.as_str()).filter(|p| p.is_empty() || p.ends_with('/'))
            })
        })
        .map(str::to_owned)
        .collect();
    out.sort_by(|a, b| (a.len(), a).cmp(&(b.len(), b)));
    out.dedup();
    out
}

/// A submission with more than [`MAX_TREES`] `exercises/` trees.
pub(crate) fn too_many_trees(count: usize) -> Text {
    Text::new(
        format!(
            "exercises/ が {count} か所以上にあります（上限 {MAX_TREES}）。採点するものを 1 つだけ提出してください"
        ),
        format!(
            "exercises/ is in {count} or more places (at most {MAX_TREES}): hand in only the one to be graded"
        ),
    )
}

/// The one tree to grade of the `exercises/` trees found (each its prefix and files, the
/// shortest prefix first): the only one, or the first when all hold the same files (a folder
/// handed in with its zip). Trees that differ are refused, naming two and a file that differs:
/// which one the student meant is not the grader's to guess (it took the shortest path).
///
/// # Errors
/// No tree, or trees that differ.
pub(crate) fn one_tree(trees: Vec<(String, Files)>) -> Result<Files, Text> {
    let mut trees = trees.into_iter();
    let Some((base, first)) = trees.next() else { return Err(no_exercises()) };
    let others: Vec<(String, Files)> = trees.collect();
    let Some((other, files)) = others.iter().find(|(_, f)| *f != first) else { return Ok(first) };
    let differs = MODULES
        .iter()
        .find(|m| first.modules.get(**m) != files.modules.get(**m))
        .map_or_else(|| "student.toml".to_owned(), |m| format!("src/{m}.rs"));
    let tree = |b: &str, lang| shown(&format!("{b}exercises/"), lang);
    let count = others.len() + 1;
    Err(Text::new(
        format!(
            "exercises/ が {count} か所にあり、中身が違います（{} と {}: {differs} が違います）。採点するものだけを残して提出し直してください",
            tree(&base, Lang::Ja),
            tree(other, Lang::Ja)
        ),
        format!(
            "exercises/ is in {count} places with different files ({} and {}: {differs} differs): hand in only the one to be graded",
            tree(&base, Lang::En),
            tree(other, Lang::En)
        ),
    ))
}

/// The first component of `relative` under `base` that is a symbolic link, as written
/// (`exercises/src`), if any: a link anywhere on the path could point into the kit.
fn symlink_on_path(base: &Path, relative: &str) -> Option<String> {
    let mut path = base.to_path_buf();
    let mut shown = Vec::new();
    for part in relative.split('/') {
        path.push(part);
        shown.push(part);
        if std::fs::symlink_metadata(&path).is_ok_and(|m| m.file_type().is_symlink()) {
            return Some(shown.join("/"));
        }
    }
    None
}

fn read_folder(dir: &Path) -> Result<Files, Text> {
    if let Some(link) = ["exercises"].iter().find_map(|r| symlink_on_path(dir, r)) {
        return Err(symlink_refused(&link));
    }
    let mut found = Vec::new();
    find_bases(dir, 2, &mut found);
    if found.is_empty() {
        return Err(nothing_to_grade(&no_exercises(), &files_in(dir), |_| {
            Some(Unopened::InFolder)
        }));
    }
    if found.len() > MAX_TREES {
        return Err(too_many_trees(found.len()));
    }
    let mut trees = Vec::new();
    for base in found {
        let shown = base.strip_prefix(dir).map_or_else(
            |_| String::new(),
            |p| {
                let p = p.to_string_lossy().replace('\\', "/");
                if p.is_empty() { p } else { format!("{p}/") }
            },
        );
        trees.push((shown, read_tree(&base)?));
    }
    // The shortest path first, as in a zip. An `exercises/` without any of the six files is no
    // tree (in a zip, trees are found by their files).
    trees.sort_by(|a, b| (a.0.len(), &a.0).cmp(&(b.0.len(), &b.0)));
    let empty = |f: &Files| f.modules.is_empty() && f.student_toml.is_none();
    if trees.iter().any(|(_, f)| !empty(f)) {
        trees.retain(|(_, f)| !empty(f));
    }
    one_tree(trees)
}

/// The six files of the `exercises/` tree in `base`.
fn read_tree(base: &Path) -> Result<Files, Text> {
    let mut files = Files::default();
    for (relative, module) in wanted() {
        if let Some(link) = symlink_on_path(base, &relative) {
            return Err(symlink_refused(&link));
        }
        let path = base.join(&relative);
        let Ok(meta) = std::fs::symlink_metadata(&path) else { continue };
        if !meta.is_file() {
            // student.toml that is a folder or a pipe: said as what it is, not "missing".
            if module.is_none() {
                return Err(Text::new(
                    format!("{relative} は普通のファイルではありません（フォルダ・パイプなど）"),
                    format!("{relative} is not a plain file (a folder, a pipe, …)"),
                ));
            }
            continue;
        }
        if meta.len() > MAX_FILE_BYTES {
            return Err(too_big(&relative, meta.len()));
        }
        let bytes = std::fs::read(&path).map_err(|e| {
            let why = Text::io(&e);
            Text::new(
                format!("{relative} を読めません: {}", why.ja),
                format!("cannot read {relative}: {}", why.en),
            )
        })?;
        files.put(module, bytes);
    }
    Ok(files)
}

fn symlink_refused(link: &str) -> Text {
    Text::new(
        format!("{link} はシンボリックリンクです（提出物の中のリンクは受け付けません）"),
        format!("{link} is a symbolic link (no link is accepted inside a submission)"),
    )
}

/// Whether a zip entry's name is unsafe to use as a path: absolute, a drive, or with `..`.
#[must_use]
pub fn unsafe_name(name: &str) -> bool {
    let name = name.replace('\\', "/");
    name.starts_with('/')
        || name.as_bytes().get(1) == Some(&b':')
        || name.split('/').any(|part| part == "..")
}

/// Why a zip cannot be read, in both languages: the zip crate's English words only in the
/// English, and in the Japanese only where the kind is none a student meets (a damaged or cut
/// zip, not a zip, encryption, an unknown compression).
#[must_use]
pub fn zip_reason(e: &zip::result::ZipError) -> Text {
    use zip::result::ZipError as Z;
    let ja = match e {
        Z::Io(io) => return zip_text(&Text::io(io)),
        Z::InvalidArchive(_) => "壊れているか途中で切れているか、zip ではありません",
        Z::UnsupportedArchive(_) | Z::InvalidPassword => {
            "この形式の zip（暗号化されたものなど）は読めません"
        }
        Z::CompressionMethodNotSupported(_) => "この圧縮方式の zip は読めません",
        _ => return zip_text(&Text::new(format!("zip のエラー: {e}"), e.to_string())),
    };
    zip_text(&Text::new(ja, e.to_string()))
}

fn zip_text(why: &Text) -> Text {
    Text::new(
        format!("zip として読めません: {}", why.ja),
        format!("not a readable zip: {}", why.en),
    )
}

fn read_zip(path: &Path) -> Result<Files, Text> {
    let bad = |e: &zip::result::ZipError| zip_reason(e);
    let file = std::fs::File::open(path).map_err(|e| zip_text(&Text::io(&e)))?;
    let mut zip = crate::zipfile::open(file, MAX_ZIP_ENTRIES)?;
    // Every entry is looked at: one hostile entry refuses the whole submission.
    let mut names = Vec::with_capacity(zip.len());
    // Its files but hidden ones, for a refusal that names them.
    let mut files = Vec::new();
    for i in 0..zip.len() {
        let entry = zip.by_index_raw(i).map_err(|e| bad(&e))?;
        // Shift_JIS names (a Japanese Windows' zip) read as such, as in a Moodle download.
        let name = crate::moodle::input::entry_name(&entry)?;
        if unsafe_name(&name) || entry.enclosed_name().is_none() {
            return Err(Text::new(
                format!(
                    "zip の項目 {} の場所が不正です（絶対パスまたは ..）",
                    shown(&name, Lang::Ja)
                ),
                format!("zip entry {} has an unsafe path (absolute or ..)", shown(&name, Lang::En)),
            ));
        }
        if entry.is_symlink() {
            return Err(Text::new(
                format!(
                    "zip の項目 {} はシンボリックリンクです（受け付けません）",
                    shown(&name, Lang::Ja)
                ),
                format!("zip entry {} is a symbolic link (not accepted)", shown(&name, Lang::En)),
            ));
        }
        if entry.size() > MAX_FILE_BYTES.saturating_mul(64) {
            return Err(too_big(&name, entry.size()));
        }
        let name = name.replace('\\', "/");
        if !entry.is_dir() && !crate::moodle::input::hidden(&name) {
            files.push(name.clone());
        }
        names.push(name);
    }
    // Each prefix under which a wanted file lies is a tree; trees that differ are refused.
    let found = bases(names.iter().map(String::as_str));
    if found.is_empty() {
        return Err(nothing_to_grade(&no_exercises(), &files, |_| Some(Unopened::InZip)));
    }
    if found.len() > MAX_TREES {
        return Err(too_many_trees(found.len()));
    }
    let mut trees = Vec::new();
    for base in found {
        let files = zip_tree(&mut zip, &names, &base)?;
        trees.push((base, files));
    }
    one_tree(trees)
}

/// The six files of the tree under `base` in a zip whose entries are `names`.
fn zip_tree<R: Read + std::io::Seek>(
    zip: &mut zip::ZipArchive<R>,
    names: &[String],
    base: &str,
) -> Result<Files, Text> {
    let bad = |e: &zip::result::ZipError| zip_reason(e);
    let wanted = wanted();
    let mut files = Files::default();
    let mut taken: Vec<&str> = Vec::new();
    for (i, name) in names.iter().enumerate() {
        let Some((relative, module)) =
            wanted.iter().find(|(w, _)| name.strip_prefix(base) == Some(w.as_str()))
        else {
            continue;
        };
        // A zip may hold one name twice; which copy an extractor keeps is its own choice, so
        // the kit takes neither.
        if taken.contains(&name.as_str()) {
            return Err(Text::new(
                format!(
                    "zip の中に {} が 2 つあります。zip を作り直してください",
                    shown(name, Lang::Ja)
                ),
                format!("the zip holds {} twice: make the zip again", shown(name, Lang::En)),
            ));
        }
        taken.push(name);
        let entry = zip.by_index(i).map_err(|e| bad(&e))?;
        if entry.size() > MAX_FILE_BYTES {
            return Err(too_big(relative, entry.size()));
        }
        // The declared size may lie: read at most one byte more than allowed.
        let mut bytes = Vec::new();
        entry
            .take(MAX_FILE_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| zip_text(&Text::io(&e)))?;
        if bytes.len() as u64 > MAX_FILE_BYTES {
            return Err(too_big(relative, bytes.len() as u64));
        }
        files.put(*module, bytes);
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A submission folder in a fresh temporary folder, with `exercises/student.toml`.
    fn folder_path(name: &str) -> PathBuf {
        std::env::temp_dir().join(format!("cg-grade-sub-{name}-{}", std::process::id()))
    }

    fn folder(name: &str) -> PathBuf {
        let d = folder_path(name);
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn a_missing_submission_is_said_in_both_languages() {
        let Err(why) = read(&folder_path("absent")) else { panic!("a missing path was read") };
        assert!(why.en.starts_with("cannot be read: "), "{}", why.en);
        assert_eq!(why.ja, "読めません: ファイルまたはフォルダがありません");
    }

    /// A zip with Shift_JIS names (a Japanese Windows' zip, no UTF-8 flag) names its folders
    /// as written: they came out as CP437 (`ë█æΦ1/exercises/`) in a refusal.
    #[test]
    fn shift_jis_names_in_a_zip_are_read_as_such() {
        let dir = folder("sjis-names");
        // 課題1 in Shift_JIS: 89 DB 91 E8 31.
        let folder_name = |tail: &str| {
            let mut n = vec![0x89, 0xdb, 0x91, 0xe8, b'1'];
            n.extend_from_slice(tail.as_bytes());
            n
        };
        let zip = crate::moodle::fake::raw_zip(
            &[
                (folder_name("/exercises/src/a1.rs"), b"// v1".to_vec()),
                (folder_name("b/exercises/src/a1.rs"), b"// v2".to_vec()),
            ],
            false,
        );
        let path = dir.join("sjis.zip");
        std::fs::write(&path, zip).unwrap();
        let why = read(&path).unwrap_err();
        assert!(why.en.contains("(課題1/exercises/ and 課題1b/exercises/"), "{}", why.en);
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A zip that holds one of the exercises' files twice is refused: which copy counts is not
    /// the kit's to guess (it took the last one, silently).
    #[test]
    fn a_zip_with_a_file_twice_is_refused() {
        use std::io::Write as _;
        let dir = folder("zip-twice");
        let path = dir.join("twice.zip");
        let mut z = zip::ZipWriter::new(std::fs::File::create(&path).unwrap());
        let options = zip::write::SimpleFileOptions::default();
        for (name, text) in [
            ("exercises/student.toml", "student = \"20260001\"\n"),
            ("exercises/src/a1.rs", "fn f() {}"),
            // The same path to the kit, written with Windows' separators.
            ("exercises\\student.toml", "student = \"20269999\"\n"),
        ] {
            z.start_file(name, options).unwrap();
            z.write_all(text.as_bytes()).unwrap();
        }
        z.finish().unwrap();
        let why = read(&path).map(|_| ()).unwrap_err();
        assert!(why.en.contains("exercises/student.toml twice"), "{}", why.en);
    }

    /// A file named .zip that is none is said in Japanese, the zip crate's English words only
    /// in the English message.
    #[test]
    fn a_broken_zip_is_said_in_both_languages() {
        let dir = folder("broken-zip");
        let path = dir.join("notzip.zip");
        std::fs::write(&path, b"this is no zip").unwrap();
        let why = read(&path).map(|_| ()).unwrap_err();
        assert!(why.ja.contains("壊れているか途中で切れているか"), "{}", why.ja);
        assert!(!why.ja.contains("EOCD") && !why.ja.contains("archive"), "{}", why.ja);
        assert!(why.en.starts_with("not a readable zip: "), "{}", why.en);
    }

    /// A FIFO named `.zip` in the submissions is refused, not waited on for ever (which hung
    /// the whole class's run). The read runs on a thread so that a hang fails the test.
    #[cfg(unix)]
    #[test]
    fn a_fifo_named_zip_is_refused_not_waited_on() {
        let dir = folder("fifo");
        let fifo = dir.join("pipe.zip");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status();
        if !made.is_ok_and(|s| s.success()) {
            eprintln!("no mkfifo here: not tested");
            return;
        }
        let (tx, rx) = std::sync::mpsc::channel();
        std::thread::spawn(move || tx.send(read(&fifo).map(|_| ())));
        let got = rx.recv_timeout(std::time::Duration::from_secs(30)).expect("read returned");
        let why = got.expect_err("a FIFO is no submission");
        assert!(why.en.contains("neither a folder nor a .zip"), "{}", why.en);
    }

    #[cfg(unix)]
    #[test]
    fn a_symbolic_link_anywhere_on_the_path_is_refused() {
        use std::os::unix::fs::symlink;
        // What the links point at: a folder like the kit's solutions, full marks if read.
        let target = folder("target");
        std::fs::create_dir_all(target.join("src")).unwrap();
        std::fs::write(target.join("src/a1.rs"), "// the kit's answers").unwrap();
        std::fs::write(target.join("student.toml"), "student = \"12345678\"\n").unwrap();

        // exercises/src is a link; the files themselves are plain.
        let sub = folder("src-link");
        std::fs::create_dir_all(sub.join("exercises")).unwrap();
        std::fs::write(sub.join("exercises/student.toml"), "student = \"12345678\"\n").unwrap();
        symlink(target.join("src"), sub.join("exercises/src")).unwrap();
        let e = read(&sub).unwrap_err();
        assert!(e.en.contains("exercises/src is a symbolic link"), "{e:?}");
        assert!(e.ja.contains("exercises/src"), "{e:?}");

        // exercises itself is a link.
        let sub = folder("exercises-link");
        symlink(&target, sub.join("exercises")).unwrap();
        let e = read(&sub).unwrap_err();
        assert!(e.en.contains("exercises is a symbolic link"), "{e:?}");

        // The file is a link.
        let sub = folder("file-link");
        std::fs::create_dir_all(sub.join("exercises/src")).unwrap();
        std::fs::write(sub.join("exercises/student.toml"), "student = \"12345678\"\n").unwrap();
        symlink(target.join("src/a1.rs"), sub.join("exercises/src/a1.rs")).unwrap();
        let e = read(&sub).unwrap_err();
        assert!(e.en.contains("exercises/src/a1.rs is a symbolic link"), "{e:?}");

        // The control: the same files, copied, are read.
        let sub = folder("plain");
        std::fs::create_dir_all(sub.join("exercises/src")).unwrap();
        std::fs::write(sub.join("exercises/student.toml"), "student = \"12345678\"\n").unwrap();
        std::fs::write(sub.join("exercises/src/a1.rs"), "// mine").unwrap();
        let files = read(&sub).unwrap();
        assert_eq!(files.modules["a1"], b"// mine");
        // student.toml that is a folder: said as such (it was "exercises/student.toml is
        // missing"); a module that is a folder is a module not written.
        let sub = folder("toml-folder");
        std::fs::create_dir_all(sub.join("exercises/student.toml")).unwrap();
        std::fs::create_dir_all(sub.join("exercises/src/a2.rs")).unwrap();
        let e = read(&sub).unwrap_err();
        assert!(e.en.contains("exercises/student.toml is not a plain file"), "{e:?}");
        assert!(e.ja.contains("普通のファイルではありません"), "{e:?}");
        std::fs::remove_dir(sub.join("exercises/student.toml")).unwrap();
        assert!(!read(&sub).unwrap().modules.contains_key("a2"));
        for d in ["target", "src-link", "exercises-link", "file-link", "plain", "toml-folder"] {
            let _ = std::fs::remove_dir_all(folder_path(d));
        }
    }

    /// Two `exercises/` trees that differ (a backup beside the work, a folder beside an older
    /// zip's) are refused, naming both and a file that differs: the shortest path was graded
    /// without a word. Two copies of the same files are one submission.
    #[test]
    fn two_trees_that_differ_are_refused_and_two_copies_read() {
        use std::io::Write as _;
        let write = |dir: &Path, base: &str, a1: &str| {
            let ex = dir.join(base).join("exercises");
            std::fs::create_dir_all(ex.join("src")).unwrap();
            std::fs::write(ex.join("student.toml"), "student = \"20260001\"\n").unwrap();
            std::fs::write(ex.join("src/a1.rs"), a1).unwrap();
        };
        let dir = folder("two-trees");
        write(&dir, "", "// new");
        write(&dir, "backup", "// old");
        let why = read(&dir).unwrap_err();
        assert!(
            why.en.contains("exercises/ is in 2 places with different files (exercises/ and backup/exercises/: src/a1.rs differs)"),
            "{}",
            why.en
        );
        assert!(why.ja.contains("backup/exercises/") && why.ja.contains("違います"), "{}", why.ja);
        write(&dir, "backup", "// new");
        assert_eq!(read(&dir).unwrap().modules["a1"], b"// new");
        // An empty `exercises/` beside the work is no second tree.
        std::fs::create_dir_all(dir.join("empty/exercises/src")).unwrap();
        assert_eq!(read(&dir).unwrap().modules["a1"], b"// new");
        // The same in a zip: two versions side by side.
        let path = dir.join("v.zip");
        let mut z = zip::ZipWriter::new(std::fs::File::create(&path).unwrap());
        let options = zip::write::SimpleFileOptions::default();
        for (name, text) in [
            ("v1/exercises/student.toml", "student = \"20260001\"\n"),
            ("v1/exercises/src/a1.rs", "// v1"),
            ("v2/exercises/student.toml", "student = \"20260001\"\n"),
            ("v2/exercises/src/a1.rs", "// v2"),
        ] {
            z.start_file(name, options).unwrap();
            z.write_all(text.as_bytes()).unwrap();
        }
        z.finish().unwrap();
        let why = read(&path).unwrap_err();
        assert!(
            why.en.contains("(v1/exercises/ and v2/exercises/: src/a1.rs differs)"),
            "{}",
            why.en
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A module saved as Shift_JIS or UTF-16 (a Japanese editor's "ANSI" or "Unicode") is read
    /// converted to UTF-8, and named: rustc could not read it, and the error at `pub mod a1;`
    /// made every assignment of the submission score 0. UTF-8 with a BOM is left as it is.
    #[test]
    fn a_module_in_shift_jis_or_utf16_is_converted_and_named() {
        let dir = folder("encodings");
        std::fs::create_dir_all(dir.join("exercises/src")).unwrap();
        std::fs::write(dir.join("exercises/student.toml"), "student = \"20260001\"\n").unwrap();
        // `// 課題1` in Shift_JIS: 課 is 89 DB, 題 91 E8.
        std::fs::write(dir.join("exercises/src/a1.rs"), b"// \x89\xdb\x91\xe81\nfn f() {}\n")
            .unwrap();
        let mut utf16 = vec![0xFF, 0xFE];
        utf16.extend("// 課題2\nfn g() {}\n".encode_utf16().flat_map(u16::to_le_bytes));
        std::fs::write(dir.join("exercises/src/a2.rs"), utf16).unwrap();
        std::fs::write(dir.join("exercises/src/a3.rs"), "\u{feff}// 課題3\n").unwrap();
        let files = read(&dir).unwrap();
        assert_eq!(files.modules["a1"], "// 課題1\nfn f() {}\n".as_bytes());
        assert_eq!(files.modules["a2"], "// 課題2\nfn g() {}\n".as_bytes());
        assert_eq!(files.modules["a3"], "\u{feff}// 課題3\n".as_bytes());
        let converted: Vec<(&str, &str)> =
            files.converted.iter().map(|(m, e)| (m.as_str(), e.as_str())).collect();
        assert_eq!(converted, [("a1", "Shift_JIS"), ("a2", "UTF-16LE")]);
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A submission with no `exercises/` (a folder or a zip given per student), or a file that is
    /// neither, is refused naming what it holds and, where it can be told, why it was not read:
    /// as a Moodle upload is (`moodle::download_tests`). It said only "no exercises/ found".
    #[test]
    fn a_submission_without_exercises_is_refused_naming_what_it_holds() {
        use std::io::Write as _;
        let dir = folder("named");
        let zip = |name: &str, files: &[(&str, &[u8])]| {
            let path = dir.join(name);
            let mut z = zip::ZipWriter::new(std::fs::File::create(&path).unwrap());
            let options = zip::write::SimpleFileOptions::default();
            for (n, bytes) in files {
                z.start_file(*n, options).unwrap();
                z.write_all(bytes).unwrap();
            }
            z.finish().unwrap();
            path
        };
        let lead =
            "no exercises/ found (it must hold exercises/src/a1.rs … and exercises/student.toml)";
        let lead_ja = "exercises/ が見つかりません（exercises/src/a1.rs … と exercises/student.toml を入れてください）";

        // A zip of the loose files: a1.rs is not in exercises/.
        let path = zip("loose.zip", &[("a1.rs", b"fn f() {}"), ("student.toml", b"x")]);
        let why = read(&path).unwrap_err();
        assert_eq!(
            why.en,
            format!(
                "{lead}; it holds a1.rs, student.toml: a1.rs is not in exercises/ (only exercises/src/a1.rs … s.rs and exercises/student.toml are read): hand in the whole exercises/ folder"
            )
        );
        assert_eq!(
            why.ja,
            format!(
                "{lead_ja}。中身: a1.rs、student.toml。a1.rs が exercises/ の中にありません（読むのは exercises/src/a1.rs … s.rs と exercises/student.toml だけです）。exercises/ フォルダごと提出してください"
            )
        );
        // A zip in the zip is not opened.
        let inner = std::fs::read(zip("inner.zip", &[("exercises/student.toml", b"x")])).unwrap();
        let path = zip("outer.zip", &[("inner.zip", &inner)]);
        let why = read(&path).unwrap_err();
        assert!(
            why.en.ends_with("; it holds inner.zip: inner.zip is a zip inside a zip, which is not opened: zip the exercises/ folder itself, once"),
            "{}",
            why.en
        );
        // An empty zip.
        let why = read(&zip("empty.zip", &[])).unwrap_err();
        assert_eq!(
            why.en,
            format!("{lead}; it holds no file: hand in the exercises/ folder as a zip")
        );
        assert_eq!(
            why.ja,
            format!(
                "{lead_ja}。中身: ファイルがありません。exercises/ フォルダを zip にして提出してください"
            )
        );

        // A folder: its files, all the way down; a zip in it is not opened; hidden files are
        // none of them.
        let sub = dir.join("taro");
        std::fs::create_dir_all(sub.join("kadai/src")).unwrap();
        for (n, text) in
            [("kadai/src/main.rs", "fn main() {}"), ("a1.rs.txt", "// a1"), (".DS_Store", "")]
        {
            std::fs::write(sub.join(n), text).unwrap();
        }
        let why = read(&sub).unwrap_err();
        assert!(
            why.en.ends_with("; it holds a1.rs.txt, kadai/src/main.rs: a1.rs.txt is a text file whose name hides .txt: rename it a1.rs (Explorer shows the .txt once View → File name extensions is on)"),
            "{}",
            why.en
        );
        std::fs::write(sub.join("exercises.zip"), &inner).unwrap();
        std::fs::remove_file(sub.join("a1.rs.txt")).unwrap();
        let why = read(&sub).unwrap_err();
        assert!(
            why.en.ends_with("; it holds exercises.zip, kadai/src/main.rs: exercises.zip is a zip inside a folder, which is not opened: hand in the zip itself, or its exercises/ folder unpacked"),
            "{}",
            why.en
        );
        assert!(
            why.ja.contains("exercises.zip はフォルダの中の zip なので開きません。"),
            "{}",
            why.ja
        );

        // A file that is neither a folder nor a zip: a .rar is said to be one.
        let rar = dir.join("taro.rar");
        std::fs::write(&rar, b"Rar!").unwrap();
        let why = read(&rar).unwrap_err();
        assert!(
            why.en.starts_with("neither a folder nor a .zip file: taro.rar is a .rar archive, not a zip, and is not read: zip the exercises/ folder instead"),
            "{}",
            why.en
        );
        assert!(
            why.ja
                .starts_with("フォルダでも .zip でもありません。taro.rar は .rar の圧縮ファイルで"),
            "{}",
            why.ja
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn unsafe_names_are_recognised() {
        assert!(unsafe_name("/etc/passwd"));
        assert!(unsafe_name("../x"));
        assert!(unsafe_name("a/../../x"));
        assert!(unsafe_name("C:\\x"));
        assert!(unsafe_name("a\\..\\x"));
        assert!(!unsafe_name("sub/exercises/src/a1.rs"));
        assert!(!unsafe_name("a..b/x"));
    }
}
