//! What a submission without the six files holds, said in its refusal: its files (the first
//! few) and, where one of them tells, why none was read (a `.7z` for a zip, `a1.rs.txt` from
//! Windows' hidden extensions, a zip in a zip, an empty zip). Shared by the readers of a
//! submissions folder ([`crate::submission`]) and of a Moodle upload ([`crate::moodle::input`]).

use std::path::Path;

use cg_core::lang::Lang;
use cg_core::quote::shown;

use crate::Text;
use crate::submission::MAX_ZIP_ENTRIES;

/// How many of a submission's files a refusal names; the rest are counted.
const NAMED: usize = 5;

/// Where a zip of a submission lies that was not looked into ([`nothing_to_grade`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Unopened {
    /// In a zip: no zip inside a zip is opened.
    InZip,
    /// In a folder given as one submission (an entry of a submissions folder, not a Moodle
    /// participant's).
    InFolder,
}

/// The refusal of a submission in which none of the six files was found (a folder or a zip of
/// a submissions folder, a Moodle participant's upload): `lead` (what was not found), what it
/// holds (`files`: its files but hidden ones, as paths inside it, a zip's as `<zip>/<path>`;
/// the first [`NAMED`] in name order, each shortened, then how many more) and, where one of
/// them tells, why nothing was read (one sentence, [`why_unread`]); else the advice to hand in
/// `exercises/` as a zip. `unopened` says, of a zip among `files`, where it lies when it was
/// not looked into (`None`: it was, so its files are among `files`).
pub(crate) fn nothing_to_grade(
    lead: &Text,
    files: &[String],
    unopened: impl Fn(&str) -> Option<Unopened>,
) -> Text {
    let mut sorted: Vec<&str> = files.iter().map(String::as_str).collect();
    sorted.sort_unstable();
    let list = |lang: Lang, sep: &str| {
        sorted.iter().take(NAMED).map(|n| shown(n, lang)).collect::<Vec<String>>().join(sep)
    };
    let rest = sorted.len().saturating_sub(NAMED);
    let held = if sorted.is_empty() {
        Text::new("中身: ファイルがありません", "it holds no file")
    } else if rest == 0 {
        Text::new(
            format!("中身: {}", list(Lang::Ja, "、")),
            format!("it holds {}", list(Lang::En, ", ")),
        )
    } else {
        Text::new(
            format!("中身: {} ほか {rest} 個", list(Lang::Ja, "、")),
            format!("it holds {} and {rest} more", list(Lang::En, ", ")),
        )
    };
    let why = why_unread(&sorted, &unopened).unwrap_or_else(|| {
        Text::new(
            "exercises/ フォルダを zip にして提出してください",
            "hand in the exercises/ folder as a zip",
        )
    });
    Text::new(
        format!("{}。{}。{}", lead.ja, held.ja, why.ja),
        format!("{}; {}: {}", lead.en, held.en, why.en),
    )
}

/// Why a submission of `files` (sorted) gave none of the six files, when one of them tells, in
/// this order: an archive of another kind (a `.7z`), a text file whose name hides `.txt`
/// (`a1.rs.txt`: Windows hides the extension), a zip not looked into, an empty zip, one of the
/// six out of `exercises/`, `.rs` files of other names.
fn why_unread(files: &[&str], unopened: &dyn Fn(&str) -> Option<Unopened>) -> Option<Text> {
    use crate::moodle::input::{basename, is_zip, wanted_name};
    let first = |why: &dyn Fn(&str) -> Option<Text>| files.iter().find_map(|n| why(n));
    let name = |n: &str| (shown(n, Lang::Ja), shown(n, Lang::En));
    /// One of the six's name, when `n`'s is that and `.txt`.
    fn txt_stem(n: &str) -> Option<&str> {
        let base = basename(n);
        let stem = base.len().checked_sub(4).and_then(|i| base.get(..i))?;
        (base[stem.len()..].eq_ignore_ascii_case(".txt") && wanted_name(stem)).then_some(stem)
    }
    let hides_txt = |n: &str| {
        let stem = txt_stem(n)?;
        let (ja, en) = name(n);
        let alike = files.iter().filter(|m| txt_stem(m).is_some()).count() - 1;
        let (alike_ja, alike_en) = if alike > 0 {
            (format!("（ほか {alike} 個も同じです）"), format!(" (and {alike} more like it)"))
        } else {
            (String::new(), String::new())
        };
        Some(Text::new(
            format!(
                "{ja} は名前の最後の .txt が隠れたテキストファイルです{alike_ja}。名前を {stem} に変えてください（エクスプローラーの［表示］で［ファイル名拡張子］を入れると .txt が見えます）"
            ),
            format!(
                "{en} is a text file whose name hides .txt{alike_en}: rename it {stem} (Explorer shows the .txt once View → File name extensions is on)"
            ),
        ))
    };
    let closed = |n: &str| {
        let (ja, en) = name(n);
        match unopened(n)? {
            Unopened::InZip => Some(Text::new(
                format!(
                    "{ja} は zip の中の zip なので開きません。exercises/ フォルダそのものを 1 回だけ zip にしてください"
                ),
                format!(
                    "{en} is a zip inside a zip, which is not opened: zip the exercises/ folder itself, once"
                ),
            )),
            Unopened::InFolder => Some(Text::new(
                format!(
                    "{ja} はフォルダの中の zip なので開きません。zip そのものか、展開した exercises/ フォルダを提出してください"
                ),
                format!(
                    "{en} is a zip inside a folder, which is not opened: hand in the zip itself, or its exercises/ folder unpacked"
                ),
            )),
        }
    };
    let empty = |n: &str| {
        let inside = |m: &&str| m.strip_prefix(n).is_some_and(|rest| rest.starts_with('/'));
        let (ja, en) = name(n);
        (unopened(n).is_none() && !files.iter().any(inside)).then(|| {
            Text::new(
                format!(
                    "{ja} にはファイルが入っていません。exercises/ フォルダを zip にし直してください"
                ),
                format!("{en} holds no file: zip the exercises/ folder again"),
            )
        })
    };
    let misplaced = |n: &str| {
        let (ja, en) = name(n);
        wanted_name(basename(n)).then(|| {
            Text::new(
                format!(
                    "{ja} が exercises/ の中にありません（読むのは exercises/src/a1.rs … s.rs と exercises/student.toml だけです）。exercises/ フォルダごと提出してください"
                ),
                format!(
                    "{en} is not in exercises/ (only exercises/src/a1.rs … s.rs and exercises/student.toml are read): hand in the whole exercises/ folder"
                ),
            )
        })
    };
    let other_rs = |n: &str| {
        basename(n).to_ascii_lowercase().ends_with(".rs").then(|| {
            Text::new(
                "a1.rs … s.rs という名前の .rs ファイルがありません（採点するのは exercises/src/ のその名前のファイルだけです）",
                "no .rs file in it is named a1.rs … s.rs (only those, in exercises/src/, are graded)",
            )
        })
    };
    first(&|n| other_archive(n))
        .or_else(|| first(&hides_txt))
        .or_else(|| first(&|n| if is_zip(n) { closed(n) } else { None }))
        .or_else(|| first(&|n| if is_zip(n) { empty(n) } else { None }))
        .or_else(|| first(&misplaced))
        .or_else(|| first(&other_rs))
}

/// The ends of the names of archives the kit does not read (7-Zip's, WinRAR's, a tar), the
/// longer first.
const OTHER_ARCHIVES: &[&str] = &[
    ".tar.gz", ".tar.bz2", ".tar.xz", ".tar.zst", ".7z", ".rar", ".tgz", ".tar", ".gz", ".bz2",
    ".xz", ".zst", ".lzh", ".zipx", ".cab",
];

/// Why `name` (a file of a submission, or the submission itself) is not read when it is an
/// archive of another kind than zip: what it is, and how to make a zip.
pub(crate) fn other_archive(name: &str) -> Option<Text> {
    let base = crate::moodle::input::basename(name).to_ascii_lowercase();
    let kind = OTHER_ARCHIVES.iter().find(|k| base.len() > k.len() && base.ends_with(*k))?;
    Some(Text::new(
        format!(
            "{} は {kind} の圧縮ファイルで、zip ではないので読めません。exercises/ フォルダを zip にして提出し直してください（Windows ではエクスプローラーでフォルダを右クリック →［送る］→［圧縮 (zip 形式) フォルダー］、macOS では［圧縮］）",
            shown(name, Lang::Ja)
        ),
        format!(
            "{} is a {kind} archive, not a zip, and is not read: zip the exercises/ folder instead (in Windows' Explorer, right-click it → Send to → Compressed (zipped) folder; on macOS, Compress)",
            shown(name, Lang::En)
        ),
    ))
}

/// The files in `dir` but hidden ones (paths inside it), for a refusal that names them
/// ([`nothing_to_grade`]): links are not followed, at most 8 folders down and
/// [`MAX_ZIP_ENTRIES`] entries are looked at.
pub(crate) fn files_in(dir: &Path) -> Vec<String> {
    let mut out = Vec::new();
    let mut seen = 0usize;
    let mut stack = vec![(String::new(), dir.to_path_buf(), 0usize)];
    while let Some((rel, path, depth)) = stack.pop() {
        let Ok(read) = std::fs::read_dir(&path) else { continue };
        for e in read.flatten() {
            seen += 1;
            if seen > MAX_ZIP_ENTRIES {
                return out;
            }
            let name = e.file_name().to_string_lossy().into_owned();
            let rel = if rel.is_empty() { name } else { format!("{rel}/{name}") };
            if crate::moodle::input::hidden(&rel) {
                continue;
            }
            match e.file_type() {
                Ok(t) if t.is_dir() => {
                    if depth < 8 {
                        stack.push((rel, e.path(), depth + 1));
                    }
                }
                Ok(_) => out.push(rel),
                Err(_) => {}
            }
        }
    }
    out
}
