//! Reading a submission — a folder or a `.zip` holding an `exercises/` tree — as hostile input:
//! only `exercises/src/{a1,a2,a3,a4,s}.rs` and `exercises/student.toml` are read, nothing is
//! extracted to disk, and a zip with an absolute or `..` path, a symlink or an oversized entry is
//! refused with the reason.

use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Path, PathBuf};

use crate::Text;
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
        return Err(Text::new(
            "フォルダでも .zip でもありません",
            "neither a folder nor a .zip file",
        ));
    };
    screened(files)
}

/// The files, unless one reaches outside itself at compile time ([`crate::screen`]).
///
/// # Errors
/// The files and lines that do, with what.
pub(crate) fn screened(files: Files) -> Result<Files, Text> {
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

/// The folder inside `dir` (itself, or a folder at most two levels down) that holds `exercises/`.
fn find_base(dir: &Path, depth: usize) -> Option<PathBuf> {
    let ex = dir.join("exercises");
    if std::fs::symlink_metadata(&ex).is_ok_and(|m| m.is_dir()) {
        return Some(dir.to_path_buf());
    }
    if depth == 0 {
        return None;
    }
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .ok()?
        .flatten()
        .filter(|e| e.file_type().is_ok_and(|t| t.is_dir()))
        .map(|e| e.path())
        .collect();
    entries.sort();
    entries.into_iter().find_map(|d| find_base(&d, depth - 1))
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
    let base = find_base(dir, 2).ok_or_else(no_exercises)?;
    let mut files = Files::default();
    for (relative, module) in wanted() {
        if let Some(link) = symlink_on_path(&base, &relative) {
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
        match module {
            Some(m) => {
                files.modules.insert(m.to_owned(), bytes);
            }
            None => files.student_toml = Some(bytes),
        }
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
    for i in 0..zip.len() {
        let entry = zip.by_index_raw(i).map_err(|e| bad(&e))?;
        let name = entry.name().map_err(|e| bad(&e))?.into_owned();
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
        names.push(name.replace('\\', "/"));
    }
    // The shortest prefix under which a wanted file lies is the submission's base.
    let wanted = wanted();
    let base = names
        .iter()
        .filter_map(|n| {
            wanted.iter().find_map(|(w, _)| {
                n.strip_suffix(w.as_str()).filter(|p| p.is_empty() || p.ends_with('/'))
            })
        })
        .min_by_key(|p| (p.len(), p.to_string()))
        .map(str::to_owned)
        .ok_or_else(no_exercises)?;
    let mut files = Files::default();
    let mut taken: Vec<&str> = Vec::new();
    for (i, name) in names.iter().enumerate() {
        let Some((relative, module)) =
            wanted.iter().find(|(w, _)| name.strip_prefix(base.as_str()) == Some(w.as_str()))
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
        match module {
            Some(m) => {
                files.modules.insert((*m).to_owned(), bytes);
            }
            None => files.student_toml = Some(bytes),
        }
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
