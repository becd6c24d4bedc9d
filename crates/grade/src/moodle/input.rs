//! The entries `cg grade` grades, from a submissions folder or from Moodle's "Download all
//! submissions" (the zip, or the folder it unpacks to).
//!
//! An ordinary entry (a folder or a `.zip` with `exercises/`) is read by
//! [`submission::read`]. The items of a Moodle download are grouped by participant ID (a
//! participant's folders, plugin by plugin, and flat files): one entry each, named after its
//! `…_assignsubmission_file` folder (the flat form: after the 3.1–4.0 folder its files start
//! with). A participant's upload is read as hostile input, as a submission is: nothing is
//! extracted to disk, links and `..` paths are refused, every read is bounded. The six files
//! are found, in this order of preference:
//!
//! 1. an `exercises/` tree, in the upload or in a zip of it (several must hold the same
//!    files: trees that differ are refused, naming two); a file of the six beside the tree
//!    (a corrected `a1.rs` uploaded next to the zip) is taken when the tree lacks it, refused
//!    when it differs from the tree's;
//! 2. loose files `a1.rs` … `s.rs` and `student.toml`, in the upload or in a zip of it (each
//!    name at most once).
//!
//! Zip entry names are UTF-8 (with or without the zip's UTF-8 flag), else Shift_JIS (a
//! Japanese Windows' zip), else CP437, so Japanese folder names arrive as Moodle wrote them.

use std::collections::BTreeMap;
use std::io::{Cursor, Read, Seek};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use super::Name;
use super::upload::{Taken, resolve};
use crate::Text;
use crate::submission::{self, Files, MAX_FILE_BYTES, MAX_ZIP_ENTRIES};
use cg_core::lang::Lang;
use cg_core::quote::shown;

/// The largest zip a participant's upload may hold inside the download's zip (read into memory,
/// never extracted; a zip in an unpacked download is read in place, whatever its size).
pub const MAX_UPLOAD_ZIP_BYTES: u64 = 256 << 20;

/// The most items a Moodle download may hold.
pub const MAX_DOWNLOAD_ENTRIES: usize = 200_000;

/// How deep a participant's folder is looked into.
const MAX_DEPTH: usize = 8;

/// The most candidate files (the six files' names, anywhere in it) one upload may hold, and
/// their most bytes together: a few copies of the exercises are a student's backups; thousands
/// of `a1.rs` of a megabyte each (a 4 MB zip) would take gigabytes of memory before the
/// duplicates are seen.
pub const MAX_CANDIDATES: usize = 256;
/// See [`MAX_CANDIDATES`].
pub const MAX_CANDIDATE_BYTES: u64 = 32 << 20;

/// One entry to grade.
#[derive(Clone, Debug)]
pub struct Entry {
    /// Its name: the file or folder in the submissions folder, or a Moodle participant's
    /// folder name (`<full name>_<ID>_assignsubmission_file`, with a trailing `_` for 3.1–4.0
    /// and the flat form).
    pub name: String,
    source: Source,
}

#[derive(Clone, Debug)]
enum Source {
    /// A folder or a `.zip` of the submissions folder.
    Path(PathBuf),
    /// A Moodle participant in an unpacked download: its folders and flat files, each with the
    /// path inside the upload it stands for.
    Folder(Vec<(String, PathBuf)>),
    /// A Moodle participant in the download's zip: its items (index, path inside the upload).
    Zip(Arc<PathBuf>, Vec<(usize, String)>),
    /// An item of a Moodle download that is no participant's.
    Refused(Text),
}

/// Where an entry's files are ([`Entry::origin`]).
#[derive(Clone, Copy, Debug)]
pub enum Origin<'a> {
    /// A folder or a `.zip` of the submissions folder.
    Path(&'a Path),
    /// A Moodle participant in an unpacked download: its folders and flat files, each with the
    /// path inside the upload it stands for.
    Folder(&'a [(String, PathBuf)]),
    /// A Moodle participant in the download's zip: the zip, and its items (index, path inside
    /// the upload).
    Zip(&'a Path, &'a [(usize, String)]),
    /// An item of a Moodle download that is no participant's.
    Refused,
}

impl Entry {
    /// One submission on its own, named after its file or folder: what `cg grade-one` grades
    /// (Gradescope's `/autograder/submission`). A `.zip` is read as an entry of a submissions
    /// folder; a folder as a Moodle participant's upload (an `exercises/` tree, in it or in a
    /// zip of it, else the loose files `a1.rs` … `s.rs` and `student.toml`), since students
    /// upload the files one by one as often as the folder.
    #[must_use]
    pub fn single(path: &Path) -> Entry {
        let name = path
            .file_name()
            .map_or_else(|| "submission".to_owned(), |n| n.to_string_lossy().into_owned());
        let folder = std::fs::symlink_metadata(path).is_ok_and(|m| m.is_dir());
        let source = if folder {
            Source::Folder(vec![(String::new(), path.to_path_buf())])
        } else {
            Source::Path(path.to_path_buf())
        };
        Entry { name, source }
    }

    /// The Moodle participant, when the entry is one.
    #[must_use]
    pub fn participant(&self) -> Option<Name> {
        match self.source {
            Source::Path(_) | Source::Refused(_) => None,
            Source::Folder(_) | Source::Zip(..) => Name::parse(&self.name),
        }
    }

    /// Where the entry's files are, for a tool that reads more of them than the six
    /// (`cg similarity` reads the report).
    #[must_use]
    pub fn origin(&self) -> Origin<'_> {
        match &self.source {
            Source::Path(path) => Origin::Path(path),
            Source::Folder(roots) => Origin::Folder(roots),
            Source::Zip(zip, items) => Origin::Zip(zip, items),
            Source::Refused(_) => Origin::Refused,
        }
    }

    /// Reads the entry's six files (see the module's documentation).
    ///
    /// # Errors
    /// Why the entry is refused: as [`submission::read`]; for a Moodle participant also an
    /// upload with no six files, a name found twice, a link, an unsafe path or a zip too big.
    pub fn read(&self) -> Result<Files, Text> {
        match &self.source {
            Source::Path(path) => submission::read(path),
            Source::Refused(why) => Err(why.clone()),
            Source::Folder(roots) => {
                let mut taken = Taken::default();
                let found = from_folder(roots, &mut taken)?;
                resolve(found, &taken)
            }
            Source::Zip(zip, items) => {
                let mut taken = Taken::default();
                let found = from_zip(zip, items, &mut taken)?;
                resolve(found, &taken)
            }
        }
    }
}

pub(super) fn text(ja: String, en: String) -> Text {
    Text::new(ja, en)
}

fn cannot_read(what: &str, e: &std::io::Error) -> Text {
    let why = Text::io(e);
    text(format!("{what} を読めません: {}", why.ja), format!("cannot read {what}: {}", why.en))
}

/// The entries of `submissions`: a folder (its entries; Moodle participants grouped), or the
/// zip of Moodle's "Download all submissions". Sorted by name.
///
/// # Errors
/// The folder or zip cannot be read; the zip is no Moodle download, has an unsafe path
/// (absolute or `..`) or too many items.
pub fn entries(submissions: &Path) -> Result<Vec<Entry>, Text> {
    let shown = submissions.display().to_string();
    // The instructor's own path may be a link (`~/Downloads` to another disk): followed here,
    // once; the links inside a submission are still refused.
    let real = submissions.canonicalize().map_err(|e| cannot_read(&shown, &e))?;
    let submissions = real.as_path();
    let meta = std::fs::symlink_metadata(submissions).map_err(|e| cannot_read(&shown, &e))?;
    let mut list = if meta.is_dir() {
        from_download_folder(&descend(submissions))?
    } else if meta.is_file()
        && submissions.extension().is_some_and(|e| e.eq_ignore_ascii_case("zip"))
    {
        from_download_zip(submissions)?
    } else {
        return Err(text(
            format!("{shown}: 提出物のフォルダでも Moodle のダウンロード（.zip）でもありません"),
            format!("{shown}: neither a folder of submissions nor a Moodle download (.zip)"),
        ));
    };
    list.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(list)
}

/// The folder itself, or its only subfolder when that holds a Moodle download and the folder
/// holds nothing else (a download unpacked into a folder of its own).
fn descend(dir: &Path) -> PathBuf {
    let top = visible(dir);
    if let [only] = top.as_slice()
        && !participants(&top)
        && only.file_type().is_ok_and(|t| t.is_dir())
        && participants(&visible(&only.path()))
    {
        return only.path();
    }
    dir.to_path_buf()
}

/// The entries of a folder, but what macOS leaves beside a download it unzipped (`__MACOSX/`,
/// `.DS_Store`) and other hidden ones.
fn visible(dir: &Path) -> Vec<std::fs::DirEntry> {
    std::fs::read_dir(dir)
        .map(|r| r.flatten().filter(|e| !hidden(&e.file_name().to_string_lossy())))
        .map(Iterator::collect)
        .unwrap_or_default()
}

/// Whether a folder's `entries` hold a Moodle participant's folder or file.
fn participants(entries: &[std::fs::DirEntry]) -> bool {
    entries.iter().any(|e| Name::parse(&e.file_name().to_string_lossy()).is_some())
}

/// A participant's items while the download is read.
#[derive(Default)]
struct Group {
    /// Each item's first path component and its parts.
    names: Vec<(String, Name)>,
    roots: Vec<(String, PathBuf)>,
    items: Vec<(usize, String)>,
}

impl Group {
    /// The entry's name: the participant's `assignsubmission_file` folder as written, else the
    /// folder its flat files (or another plugin's) stand for.
    fn name(&self) -> String {
        let folder =
            self.names.iter().find(|(_, n)| n.plugin == super::FILE_PLUGIN && n.is_folder());
        if let Some((raw, _)) = folder {
            return raw.clone();
        }
        let file = self.names.iter().find(|(_, n)| n.plugin == super::FILE_PLUGIN);
        file.or_else(|| self.names.first()).map(|(_, n)| n.folder()).unwrap_or_default()
    }
}

fn join(a: &str, b: &str) -> String {
    match (a.is_empty(), b.is_empty()) {
        (true, _) => b.to_owned(),
        (_, true) => a.to_owned(),
        _ => format!("{a}/{b}"),
    }
}

fn from_download_folder(dir: &Path) -> Result<Vec<Entry>, Text> {
    let shown = dir.display().to_string();
    let mut list = Vec::new();
    let mut groups: BTreeMap<String, Group> = BTreeMap::new();
    for e in std::fs::read_dir(dir).map_err(|e| cannot_read(&shown, &e))?.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        if hidden(&name) {
            continue;
        }
        match Name::parse(&name) {
            // A Moodle download inside the folder (kept beside the unpacked one, or unzipped
            // into a folder of its own next to `__MACOSX/`) is no one student's submission: it
            // was graded as the one participant whose `exercises/` lay two levels down.
            None if holds_a_download(&e.path()) => list.push(Entry {
                source: Source::Refused(text(
                    format!(
                        "{name} は Moodle のダウンロード（参加者のフォルダ <氏名>_<参加者 ID>_assignsubmission_file を含む）で、1 人の提出物ではありません。cg grade にはそれ自体（{}）を渡してください",
                        e.path().display()
                    ),
                    format!(
                        "{name} is a Moodle download (it holds participants' folders, <name>_<participant ID>_assignsubmission_file), not one student's submission: give it itself to cg grade ({})",
                        e.path().display()
                    ),
                )),
                name,
            }),
            None => list.push(Entry { name, source: Source::Path(e.path()) }),
            Some(n) => {
                let g = groups.entry(n.participant.clone()).or_default();
                g.roots.push((n.rest.clone().unwrap_or_default(), e.path()));
                g.names.push((name, n));
            }
        }
    }
    for g in groups.into_values() {
        let mut roots = g.roots.clone();
        roots.sort();
        list.push(Entry { name: g.name(), source: Source::Folder(roots) });
    }
    Ok(list)
}

/// Whether `path` (an entry of a submissions folder) holds a Moodle download: a participant's
/// folder or file at its top or one folder down (a folder, or a zip's entries).
fn holds_a_download(path: &Path) -> bool {
    let Ok(meta) = std::fs::symlink_metadata(path) else { return false };
    if meta.is_dir() {
        let top = visible(path);
        return participants(&top)
            || top.iter().any(|e| {
                e.file_type().is_ok_and(|t| t.is_dir()) && participants(&visible(&e.path()))
            });
    }
    if !(meta.is_file() && is_zip(&path.to_string_lossy())) {
        return false;
    }
    let Ok(file) = std::fs::File::open(path) else { return false };
    let Ok(mut zip) = crate::zipfile::open(file, MAX_DOWNLOAD_ENTRIES) else { return false };
    let moodle = |name: &str| name.split('/').take(2).any(|part| Name::parse(part).is_some());
    (0..zip.len()).any(|i| {
        zip.by_index_raw(i).ok().and_then(|e| entry_name(&e).ok()).is_some_and(|n| moodle(&n))
    })
}

/// A zip entry's name: its bytes as UTF-8 when they are UTF-8 (flagged or not), else as
/// Shift_JIS (what a Japanese Windows writes without the flag), else as CP437 (the zip
/// format's own); `\` as `/`.
pub(crate) fn entry_name<R: Read + ?Sized>(
    entry: &zip::read::ZipFile<'_, R>,
) -> Result<String, Text> {
    let raw = entry.name_raw();
    let name = match std::str::from_utf8(raw) {
        Ok(s) => s.to_owned(),
        Err(_) => match cg_core::text::decode(raw, Some(cg_core::text::Encoding::ShiftJis)) {
            Ok((s, _)) => s,
            Err(_) => entry.name().map_err(|e| bad_zip(&e))?.into_owned(),
        },
    };
    Ok(name.replace('\\', "/"))
}

fn bad_zip(e: &zip::result::ZipError) -> Text {
    submission::zip_reason(e)
}

fn unsafe_path(name: &str) -> Text {
    text(
        format!("zip の項目 {} の場所が不正です（絶対パスまたは ..）", shown(name, Lang::Ja)),
        format!("zip entry {} has an unsafe path (absolute or ..)", shown(name, Lang::En)),
    )
}

fn link_refused(name: &str) -> Text {
    text(
        format!("{} はシンボリックリンクです（受け付けません）", shown(name, Lang::Ja)),
        format!("{} is a symbolic link (not accepted)", shown(name, Lang::En)),
    )
}

fn from_download_zip(path: &Path) -> Result<Vec<Entry>, Text> {
    let shown = path.display().to_string();
    let in_download = |t: Text| {
        text(
            format!("Moodle のダウンロード {shown}: {}", t.ja),
            format!("the Moodle download {shown}: {}", t.en),
        )
    };
    let file = std::fs::File::open(path).map_err(|e| cannot_read(&shown, &e))?;
    let mut zip = crate::zipfile::open(file, MAX_DOWNLOAD_ENTRIES).map_err(in_download)?;
    let mut names = Vec::with_capacity(zip.len());
    for i in 0..zip.len() {
        let entry = zip.by_index_raw(i).map_err(|e| in_download(bad_zip(&e)))?;
        let name = entry_name(&entry).map_err(in_download)?;
        if submission::unsafe_name(&name) {
            return Err(in_download(unsafe_path(&name)));
        }
        names.push((name, entry.is_dir()));
    }
    // A download zipped again inside a folder of its own: that folder is looked through. What
    // macOS adds when it zips (`__MACOSX/`, `.DS_Store`) is no folder of the download's.
    let top = |n: &str| n.split('/').next().unwrap_or("").to_owned();
    let system = |n: &str| {
        let t = top(n);
        t == "__MACOSX" || t.starts_with('.')
    };
    let mut tops = names.iter().map(|(n, _)| n).filter(|n| !system(n)).map(|n| top(n));
    let strip = match tops.next() {
        Some(first) if first.is_empty() || Name::parse(&first).is_some() => String::new(),
        Some(first) if tops.all(|t| t == first) => format!("{first}/"),
        _ => String::new(),
    };
    let shared = Arc::new(path.to_path_buf());
    let mut groups: BTreeMap<String, Group> = BTreeMap::new();
    let mut strays: BTreeMap<String, ()> = BTreeMap::new();
    for (i, (name, dir)) in names.iter().enumerate() {
        let name = name.strip_prefix(&strip).unwrap_or(name);
        let (first, tail) = name.split_once('/').unwrap_or((name, ""));
        if first.is_empty() || first.starts_with('.') || first == "__MACOSX" {
            continue;
        }
        match Name::parse(first) {
            Some(n) => {
                let g = groups.entry(n.participant.clone()).or_default();
                if !g.names.iter().any(|(raw, _)| raw == first) {
                    g.names.push((first.to_owned(), n.clone()));
                }
                if !dir {
                    g.items.push((i, join(n.rest.as_deref().unwrap_or(""), tail)));
                }
            }
            None => {
                strays.insert(first.to_owned(), ());
            }
        }
    }
    if groups.is_empty() {
        return Err(in_download(text(
            "参加者のフォルダ（<氏名>_<参加者 ID>_assignsubmission_file）がありません".into(),
            "no participant's folder (<name>_<participant ID>_assignsubmission_file) in it".into(),
        )));
    }
    let mut list: Vec<Entry> = groups
        .into_values()
        .map(|g| Entry { name: g.name(), source: Source::Zip(Arc::clone(&shared), g.items) })
        .collect();
    for stray in strays.into_keys() {
        list.push(Entry {
            source: Source::Refused(text(
                format!("Moodle のダウンロードの中の {stray} は参加者のフォルダではありません"),
                format!("{stray} in the Moodle download is not a participant's folder"),
            )),
            name: stray,
        });
    }
    Ok(list)
}

/// The files of an upload that may matter: the six files by name, and zips (looked into);
/// not what macOS adds (`._exercises.zip` beside a zip on a USB stick, `__MACOSX/`) or any
/// other hidden file, which was read as a broken zip and refused the upload.
fn candidate(rel: &str) -> bool {
    !hidden(rel) && (is_zip(rel) || wanted_name(basename(rel)))
}

/// Whether a path has a hidden part (`.DS_Store`, `._a1.rs`, `.git/`) or is under `__MACOSX/`.
pub(crate) fn hidden(rel: &str) -> bool {
    rel.split('/').any(|part| part.starts_with('.') || part == "__MACOSX")
}

/// Whether a path's name ends in `.zip` (any case).
pub(crate) fn is_zip(rel: &str) -> bool {
    basename(rel).rsplit_once('.').is_some_and(|(_, e)| e.eq_ignore_ascii_case("zip"))
}

/// A path's last part.
pub(crate) fn basename(rel: &str) -> &str {
    rel.rsplit('/').next().unwrap_or(rel)
}

/// The six files' paths inside `exercises/`'s parent, with their module (`None`:
/// `student.toml`).
pub(super) fn wanted() -> Vec<(String, Option<&'static str>)> {
    let mut w: Vec<(String, Option<&'static str>)> =
        submission::MODULES.iter().map(|m| (format!("exercises/src/{m}.rs"), Some(*m))).collect();
    w.push(("exercises/student.toml".to_owned(), None));
    w
}

/// Whether `name` is one of the six files' names (`a1.rs` … `s.rs`, `student.toml`).
pub(crate) fn wanted_name(name: &str) -> bool {
    wanted().iter().any(|(w, _)| basename(w) == name)
}

pub(super) fn too_big(name: &str, size: u64, limit: u64) -> Text {
    text(
        format!("{} が大きすぎます（{size} バイト、上限 {limit}）", shown(name, Lang::Ja)),
        format!("{} is too big ({size} bytes, at most {limit})", shown(name, Lang::En)),
    )
}

/// Reads at most `limit + 1` bytes (so a file over the limit is known to be).
fn bounded(reader: impl Read, limit: u64, rel: &str) -> Result<Vec<u8>, Text> {
    let mut bytes = Vec::new();
    reader.take(limit + 1).read_to_end(&mut bytes).map_err(|e| cannot_read(rel, &e))?;
    Ok(bytes)
}

fn from_folder(
    roots: &[(String, PathBuf)],
    taken: &mut Taken,
) -> Result<Vec<(String, Vec<u8>)>, Text> {
    let mut found = Vec::new();
    let mut seen = 0usize;
    let mut stack: Vec<(String, PathBuf, usize)> =
        roots.iter().map(|(rel, path)| (rel.clone(), path.clone(), 0)).collect();
    while let Some((rel, path, depth)) = stack.pop() {
        let shown = if rel.is_empty() {
            path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default()
        } else {
            rel.clone()
        };
        let meta = std::fs::symlink_metadata(&path).map_err(|e| cannot_read(&shown, &e))?;
        if meta.file_type().is_symlink() {
            return Err(link_refused(&shown));
        }
        if meta.is_dir() {
            if depth >= MAX_DEPTH {
                continue;
            }
            for e in std::fs::read_dir(&path).map_err(|e| cannot_read(&shown, &e))?.flatten() {
                seen += 1;
                if seen > MAX_ZIP_ENTRIES {
                    return Err(text(
                        format!("ファイルが多すぎます（上限 {MAX_ZIP_ENTRIES}）"),
                        format!("too many files (at most {MAX_ZIP_ENTRIES})"),
                    ));
                }
                let name = e.file_name().to_string_lossy().into_owned();
                stack.push((join(&rel, &name), e.path(), depth + 1));
            }
        } else if meta.is_file() {
            taken.saw(&rel);
            if !candidate(&rel) {
                continue;
            }
            let file = std::fs::File::open(&path).map_err(|e| cannot_read(&rel, &e))?;
            if is_zip(&rel) {
                found.extend(inside(&rel, file, taken)?);
            } else {
                found.push(taken.add(&rel, bounded(file, MAX_FILE_BYTES, &rel)?)?);
            }
        }
    }
    found.sort();
    Ok(found)
}

fn from_zip(
    path: &Path,
    items: &[(usize, String)],
    taken: &mut Taken,
) -> Result<Vec<(String, Vec<u8>)>, Text> {
    let file =
        std::fs::File::open(path).map_err(|e| cannot_read(&path.display().to_string(), &e))?;
    let mut zip = crate::zipfile::open(file, MAX_DOWNLOAD_ENTRIES)?;
    let mut found = Vec::new();
    for (i, rel) in items {
        let entry = zip.by_index(*i).map_err(|e| bad_zip(&e))?;
        if entry.is_symlink() {
            return Err(link_refused(rel));
        }
        if entry.is_dir() {
            continue;
        }
        taken.saw(rel);
        if !candidate(rel) {
            continue;
        }
        if !is_zip(rel) {
            found.push(taken.add(rel, bounded(entry, MAX_FILE_BYTES, rel)?)?);
            continue;
        }
        if entry.size() > MAX_UPLOAD_ZIP_BYTES {
            return Err(too_big(rel, entry.size(), MAX_UPLOAD_ZIP_BYTES));
        }
        // The declared size may lie: the read is bounded too.
        let bytes = bounded(entry, MAX_UPLOAD_ZIP_BYTES, rel)?;
        if bytes.len() as u64 > MAX_UPLOAD_ZIP_BYTES {
            return Err(too_big(rel, bytes.len() as u64, MAX_UPLOAD_ZIP_BYTES));
        }
        found.extend(inside(rel, Cursor::new(bytes), taken)?);
    }
    found.sort();
    Ok(found)
}

/// The six files' candidates inside a participant's zip, named `<zip>/<path>`. Every entry is
/// looked at: one hostile entry (an unsafe path, a link) refuses the upload.
fn inside(
    rel: &str,
    reader: impl Read + Seek,
    taken: &mut Taken,
) -> Result<Vec<(String, Vec<u8>)>, Text> {
    let within = |t: Text| text(format!("{rel}: {}", t.ja), format!("{rel}: {}", t.en));
    let mut zip = crate::zipfile::open(reader, MAX_ZIP_ENTRIES).map_err(within)?;
    taken.opened.push(rel.to_owned());
    let mut found = Vec::new();
    for i in 0..zip.len() {
        let entry = zip.by_index(i).map_err(|e| within(bad_zip(&e)))?;
        let name = entry_name(&entry).map_err(within)?;
        if submission::unsafe_name(&name) || entry.enclosed_name().is_none() {
            return Err(within(unsafe_path(&name)));
        }
        if entry.is_symlink() {
            return Err(within(link_refused(&name)));
        }
        if entry.is_dir() || hidden(&name) {
            continue;
        }
        let name = format!("{rel}/{name}");
        taken.saw(&name);
        if !wanted_name(basename(&name)) {
            continue;
        }
        let bytes = bounded(entry, MAX_FILE_BYTES, &name)?;
        found.push(taken.add(&name, bytes)?);
    }
    Ok(found)
}
