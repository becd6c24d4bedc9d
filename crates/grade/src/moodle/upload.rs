//! An upload's six files, from its candidates ([`super::input`] reads them from a Moodle
//! participant's folders or zip, and counts them here): an `exercises/` tree, with what is
//! beside it, else the loose files, as [`super::input`]'s documentation says.

use super::input::{MAX_CANDIDATE_BYTES, MAX_CANDIDATES, basename, hidden, text, too_big, wanted};
use crate::Text;
use crate::submission::{self, Files, MAX_FILE_BYTES, MAX_ZIP_ENTRIES};
use cg_core::lang::Lang;
use cg_core::quote::shown;

/// What an upload's candidates have taken so far, against [`MAX_CANDIDATES`] and
/// [`MAX_CANDIDATE_BYTES`]; and what the upload holds, for a refusal that names it when none of
/// the six files is there ([`crate::unread::nothing_to_grade`]).
#[derive(Default)]
pub(super) struct Taken {
    files: usize,
    bytes: u64,
    /// The upload's files but hidden ones (paths inside it; a zip's as `<zip>/<path>`), the
    /// first [`MAX_ZIP_ENTRIES`] seen.
    pub(super) held: Vec<String>,
    /// The zips looked into (every zip of the upload is; a zip inside one is not).
    pub(super) opened: Vec<String>,
}

impl Taken {
    /// `rel`, a file of the upload, seen.
    pub(super) fn saw(&mut self, rel: &str) {
        if self.held.len() < MAX_ZIP_ENTRIES && !hidden(rel) {
            self.held.push(rel.to_owned());
        }
    }

    /// `bytes` read for `rel`, or the upload refused when it is past the limits.
    pub(super) fn add(&mut self, rel: &str, bytes: Vec<u8>) -> Result<(String, Vec<u8>), Text> {
        self.files += 1;
        self.bytes += bytes.len() as u64;
        if self.files > MAX_CANDIDATES || self.bytes > MAX_CANDIDATE_BYTES {
            return Err(text(
                format!(
                    "提出物に課題のファイル（a1.rs などの名前のもの）が多すぎます（{rel} まで {} 個、{} バイト。上限 {MAX_CANDIDATES} 個、{MAX_CANDIDATE_BYTES} バイト）",
                    self.files, self.bytes
                ),
                format!(
                    "the upload holds too many of the exercises' files (files named a1.rs and the like: {} files, {} bytes up to {rel}; at most {MAX_CANDIDATES} files and {MAX_CANDIDATE_BYTES} bytes)",
                    self.files, self.bytes
                ),
            ));
        }
        Ok((rel.to_owned(), bytes))
    }
}

/// The six files among an upload's candidates (its files of those names, and those in its
/// zips), as the module's documentation says, screened. An upload with none of them is refused
/// naming what it holds (`taken`), and why it was not read where that can be told (a `.7z`, an
/// `a1.rs.txt`, a zip inside a zip: [`crate::unread::nothing_to_grade`]).
pub(super) fn resolve(files: Vec<(String, Vec<u8>)>, taken: &Taken) -> Result<Files, Text> {
    let wanted = wanted();
    // 1. An exercises/ tree; several must hold the same files.
    let bases = submission::bases(files.iter().map(|(rel, _)| rel.as_str()));
    if bases.len() > submission::MAX_TREES {
        return Err(submission::too_many_trees(bases.len()));
    }
    let out = if bases.is_empty() {
        loose(&files, &wanted)?
    } else {
        let mut trees = Vec::new();
        for base in &bases {
            trees.push((base.clone(), tree(&files, &wanted, base)?));
        }
        let chosen = submission::one_tree(trees)?;
        beside_tree(&files, &wanted, &bases, chosen)?
    };
    if out.modules.is_empty() && out.student_toml.is_none() {
        let lead = text(
            "exercises/ も a1.rs … s.rs・student.toml も見つかりません".into(),
            "neither exercises/ nor a1.rs … s.rs and student.toml found".into(),
        );
        // Every zip of the upload is opened: one that was not lies inside another.
        let unopened = |zip: &str| {
            (!taken.opened.iter().any(|o| o == zip)).then_some(crate::unread::Unopened::InZip)
        };
        return Err(crate::unread::nothing_to_grade(&lead, &taken.held, unopened));
    }
    submission::screened(out)
}

/// Puts `bytes` for `module` (`None`: `student.toml`) into `out`, unless too big.
fn put(out: &mut Files, rel: &str, module: Option<&str>, bytes: &[u8]) -> Result<(), Text> {
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(too_big(rel, bytes.len() as u64, MAX_FILE_BYTES));
    }
    out.put(module, bytes.to_vec());
    Ok(())
}

/// The files of the tree under `base`.
fn tree(
    files: &[(String, Vec<u8>)],
    wanted: &[(String, Option<&'static str>)],
    base: &str,
) -> Result<Files, Text> {
    let mut out = Files::default();
    for (w, module) in wanted {
        let path = format!("{base}{w}");
        let same: Vec<&(String, Vec<u8>)> = files.iter().filter(|(rel, _)| *rel == path).collect();
        match same.as_slice() {
            [] => {}
            [(rel, bytes)] => put(&mut out, rel, *module, bytes)?,
            // One path twice (a zip that holds it twice): which one is meant is not for the
            // grader to guess, as for a submission read from a folder or a zip.
            _ => {
                return Err(text(
                    format!("{} が 2 つ以上あります", shown(&path, Lang::Ja)),
                    format!("{} is there more than once", shown(&path, Lang::En)),
                ));
            }
        }
    }
    Ok(out)
}

/// `w`'s name found more than once (`several`), with the first few, each shortened (an upload
/// may hold hundreds).
fn more_than_once(w: &str, several: &[&(String, Vec<u8>)]) -> Text {
    let few = |lang: Lang, sep: &str| {
        let mut names: Vec<String> = several.iter().take(5).map(|(r, _)| shown(r, lang)).collect();
        if several.len() > 5 {
            names.push(format!("… (+{})", several.len() - 5));
        }
        names.join(sep)
    };
    text(
        format!(
            "{} が複数あります（{}）。exercises/ フォルダごと提出してください",
            basename(w),
            few(Lang::Ja, "、")
        ),
        format!(
            "{} is there more than once ({}): hand in the exercises/ folder",
            basename(w),
            few(Lang::En, ", ")
        ),
    )
}

/// 2. Loose files, each name once.
fn loose(
    files: &[(String, Vec<u8>)],
    wanted: &[(String, Option<&'static str>)],
) -> Result<Files, Text> {
    let mut out = Files::default();
    for (w, module) in wanted {
        let same: Vec<&(String, Vec<u8>)> =
            files.iter().filter(|(rel, _)| basename(rel) == basename(w)).collect();
        match same.as_slice() {
            [] => {}
            [(rel, bytes)] => put(&mut out, rel, *module, bytes)?,
            several => return Err(more_than_once(w, several)),
        }
    }
    Ok(out)
}

/// The tree's files with what the upload holds beside the trees — a file of the six at the top
/// of the upload (a corrected `a1.rs` uploaded next to the zip) or in the folder that holds
/// `exercises/` — : a copy of the same text is nothing; a file the tree lacks is taken; one that
/// differs from the tree's is refused, naming both (it was ignored without a word). Files
/// deeper down are not beside it: the kit's own `crates/student/src/a1.rs` in a whole kit
/// uploaded, a backup folder.
fn beside_tree(
    files: &[(String, Vec<u8>)],
    wanted: &[(String, Option<&'static str>)],
    bases: &[String],
    mut chosen: Files,
) -> Result<Files, Text> {
    let beside = |rel: &str| {
        let folder = &rel[..rel.len() - basename(rel).len()];
        folder.is_empty() || bases.iter().any(|b| b == folder)
    };
    for (w, module) in wanted {
        let outside: Vec<&(String, Vec<u8>)> =
            files.iter().filter(|(rel, _)| basename(rel) == basename(w) && beside(rel)).collect();
        let Some((first, bytes)) = outside.first() else { continue };
        let current = match module {
            Some(m) => chosen.modules.get(*m),
            None => chosen.student_toml.as_ref(),
        };
        match current {
            Some(tree) => {
                if let Some((rel, _)) = outside.iter().find(|(_, b)| b != tree) {
                    let path = format!("{}{w}", bases[0]);
                    return Err(text(
                        format!(
                            "{} が exercises/ の中（{}）と外（{}）にあり、中身が違います。どちらを採点するか決められないので、正しいほうだけを exercises/ に入れて提出し直してください",
                            basename(w),
                            shown(&path, Lang::Ja),
                            shown(rel, Lang::Ja)
                        ),
                        format!(
                            "{} is both in exercises/ ({}) and outside it ({}), with different text: which one to grade cannot be told, so put the right one in exercises/ and hand in again",
                            basename(w),
                            shown(&path, Lang::En),
                            shown(rel, Lang::En)
                        ),
                    ));
                }
            }
            None => {
                if outside.iter().any(|(_, b)| b != bytes) {
                    return Err(more_than_once(w, &outside));
                }
                put(&mut chosen, first, *module, bytes)?;
            }
        }
    }
    Ok(chosen)
}
