//! The student's copy of the kit — everything but `solutions/`, with the stubs freshly generated,
//! the manifests' solution-only lines dropped and the lock file without the solutions crate —
//! which builds, runs and checks on its own. `cg handout` writes it for students; grading writes
//! one per parallel slot and builds every submission in it.

use std::path::{Path, PathBuf};
use std::process::Command;

use cg_core::lang::Text;
use cg_harness::stubs::{StubError, generate, stub_from_solution};

/// Paths (relative to the kit) that never go into a handout.
pub fn excluded(path: &Path) -> bool {
    let first = path.components().next().map(|c| c.as_os_str().to_string_lossy().into_owned());
    matches!(first.as_deref(), Some("solutions" | "target" | "out" | ".git"))
        || path == Path::new("exercises/student.toml")
}

/// The kit's files: in a git checkout, the files git tracks (`git ls-files`), as `git archive`
/// takes them; otherwise (a copy without `.git`: the autograder's) every file under the kit
/// except the excluded folders, what the kit's `.gitignore` names at its top and symbolic
/// links.
///
/// # Errors
/// A folder of the kit could not be read.
pub fn kit_files(root: &Path) -> Result<Vec<PathBuf>, Text> {
    if let Some(files) = git_listed(root, "--cached") {
        return Ok(files);
    }
    let ignored = top_level_ignored(root);
    let mut files = Vec::new();
    let mut stack = vec![PathBuf::new()];
    while let Some(dir) = stack.pop() {
        let entries =
            std::fs::read_dir(root.join(&dir)).map_err(|e| Text::io_at(&root.join(&dir), &e))?;
        for entry in entries.flatten() {
            let relative = dir.join(entry.file_name());
            let top = dir.as_os_str().is_empty();
            if excluded(&relative) || (top && ignored.iter().any(|i| *i == entry.file_name())) {
                continue;
            }
            // A link is not followed: a link to `..` would copy the kit into itself for ever.
            match entry.file_type() {
                Ok(t) if t.is_dir() => stack.push(relative),
                Ok(t) if t.is_file() => files.push(relative),
                _ => {}
            }
        }
    }
    Ok(files)
}

/// The files of the git checkout `root` that `git ls-files <which>` lists (`--cached`: those it
/// tracks; `--others`: those it neither tracks nor ignores), plain files only; `None` outside a
/// checkout or without git.
fn git_listed(root: &Path, which: &str) -> Option<Vec<PathBuf>> {
    let out = Command::new("git")
        .arg("-C")
        .arg(root)
        .args(["ls-files", "-z", which])
        .args((which == "--others").then_some("--exclude-standard"))
        .output()
        .ok()
        .filter(|o| o.status.success())?;
    Some(
        out.stdout
            .split(|&b| b == 0)
            .filter(|s| !s.is_empty())
            .map(|s| PathBuf::from(String::from_utf8_lossy(s).into_owned()))
            .filter(|p| std::fs::symlink_metadata(root.join(p)).is_ok_and(|m| m.is_file()))
            .collect(),
    )
}

/// The names the kit's `.gitignore` leaves out at its top (`/target`, `/report/`): what a copy
/// without `.git` leaves out too.
fn top_level_ignored(root: &Path) -> Vec<std::ffi::OsString> {
    let text = std::fs::read_to_string(root.join(".gitignore")).unwrap_or_default();
    text.lines()
        .filter_map(|l| l.trim().strip_prefix('/'))
        .map(|l| l.trim_end_matches('/'))
        .filter(|l| !l.is_empty() && !l.contains(['/', '*', '?', '[']))
        .map(Into::into)
        .collect()
}

/// The files of the git checkout `root` that [`kit_files`] leaves out because git neither
/// tracks nor ignores them, said in one line (the first five by name), or nothing when there are
/// none: what a session left in the kit (a grading's `results/`, an old `autograder.zip` with
/// the solutions in it) must not reach the students, and a new kit file not yet committed must
/// not be lost unseen.
#[must_use]
pub fn untracked_note(root: &Path) -> Option<Text> {
    let mut untracked = git_listed(root, "--others")?;
    untracked.retain(|p| !excluded(p));
    untracked.sort();
    if untracked.is_empty() {
        return None;
    }
    let list = |lang| {
        let shown: Vec<String> = untracked
            .iter()
            .take(5)
            .map(|p| cg_core::quote::shown(&p.display().to_string(), lang))
            .collect();
        shown.join(", ")
    };
    let more = untracked.len().saturating_sub(5);
    let (more_ja, more_en) = if more > 0 {
        (format!(" ほか {more} 個"), format!(" and {more} more"))
    } else {
        (String::new(), String::new())
    };
    Some(Text::new(
        format!(
            "git が追跡していないファイル {} 個は入れていません: {}{more_ja}。キットのファイルなら `git add` してから作り直してください",
            untracked.len(),
            list(cg_core::lang::Lang::Ja)
        ),
        format!(
            "left out {} file(s) git does not track: {}{more_en}; if one is part of the kit, `git add` it and make this again",
            untracked.len(),
            list(cg_core::lang::Lang::En)
        ),
    ))
}

/// A solution file whose markers do not pair up, or that could not be read: the kit's own
/// problem, which its maintainer fixes (the marker's words stay in English).
pub fn markers(e: &StubError) -> Text {
    Text::new(
        format!("解答から学生用のコピーを作れません: {e}"),
        format!("the students' copy cannot be made from the solutions: {e}"),
    )
}

/// `Cargo.lock` without the `cg-solutions` package and every mention of it.
pub fn lock_without_solutions(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for (i, block) in text.split("\n[[package]]\n").enumerate() {
        if block.lines().any(|l| l.trim() == "name = \"cg-solutions\"") {
            continue;
        }
        if i > 0 {
            out.push_str("\n[[package]]\n");
        }
        for line in block.split_inclusive('\n') {
            if line.trim() != "\"cg-solutions\"," {
                out.push_str(line);
            }
        }
    }
    out
}

/// Writes the handout of the kit at `root` into `dir`; returns how many files it wrote.
///
/// # Errors
/// A file could not be read or written, or a manifest's solution markers do not pair up.
pub fn write_handout(root: &Path, dir: &Path) -> Result<usize, Text> {
    write_handout_filtered(root, dir, &|_| false)
}

/// [`write_handout`] leaving out the kit's files for which `skip` (given the full path) is true:
/// grading leaves out its own output and the submissions when they lie inside the kit.
///
/// # Errors
/// As [`write_handout`].
pub fn write_handout_filtered(
    root: &Path,
    dir: &Path,
    skip: &dyn Fn(&Path) -> bool,
) -> Result<usize, Text> {
    let err = |p: &Path, e: std::io::Error| Text::io_at(p, &e);
    let mut count = 0;
    let mut put = |relative: &Path, text: &[u8]| -> Result<(), Text> {
        let target = dir.join(relative);
        if let Some(parent) = target.parent() {
            std::fs::create_dir_all(parent).map_err(|e| err(parent, e))?;
        }
        std::fs::write(&target, text).map_err(|e| err(&target, e))?;
        count += 1;
        Ok(())
    };
    for relative in kit_files(root)? {
        if excluded(&relative) || relative.starts_with("exercises") || skip(&root.join(&relative)) {
            continue;
        }
        let source = root.join(&relative);
        let name = relative.file_name().map(|n| n.to_string_lossy().into_owned());
        match name.as_deref() {
            Some("Cargo.toml") => {
                let text = std::fs::read_to_string(&source).map_err(|e| err(&source, e))?;
                let stub = stub_from_solution(&text, &relative.display().to_string(), "#")
                    .map_err(|e| markers(&e))?;
                put(&relative, stub.as_bytes())?;
            }
            Some("Cargo.lock") if relative.parent() == Some(Path::new("")) => {
                let text = std::fs::read_to_string(&source).map_err(|e| err(&source, e))?;
                put(&relative, lock_without_solutions(&text).as_bytes())?;
            }
            _ => {
                let bytes = std::fs::read(&source).map_err(|e| err(&source, e))?;
                put(&relative, &bytes)?;
            }
        }
    }
    // The pristine stubs, generated from the solutions (never the maintainer's working copy),
    // and exercises/'s own files that are not generated (its README).
    for (relative, text) in generate(&root.join("solutions")).map_err(|e| markers(&e))? {
        put(&Path::new("exercises").join(relative), text.as_bytes())?;
    }
    let readme = root.join("exercises/README.md");
    if readme.exists() {
        let bytes = std::fs::read(&readme).map_err(|e| err(&readme, e))?;
        put(Path::new("exercises/README.md"), &bytes)?;
    }
    Ok(count)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lock_file_loses_the_solutions_crate_and_nothing_else() {
        let lock = "version = 4\n\n[[package]]\nname = \"a\"\nversion = \"1.0.0\"\n\n[[package]]\nname = \"cg-cli\"\nversion = \"0.1.0\"\ndependencies = [\n \"a\",\n \"cg-solutions\",\n]\n\n[[package]]\nname = \"cg-solutions\"\nversion = \"0.1.0\"\ndependencies = [\n \"a\",\n]\n";
        let out = lock_without_solutions(lock);
        assert_eq!(
            out,
            "version = 4\n\n[[package]]\nname = \"a\"\nversion = \"1.0.0\"\n\n[[package]]\nname = \"cg-cli\"\nversion = \"0.1.0\"\ndependencies = [\n \"a\",\n]\n"
        );
    }

    #[test]
    fn solutions_and_personal_files_stay_out() {
        assert!(excluded(Path::new("solutions/src/a1.rs")));
        assert!(excluded(Path::new("exercises/student.toml")));
        assert!(excluded(Path::new("target/debug/cg")));
        assert!(!excluded(Path::new("exercises/src/a1.rs")));
        assert!(!excluded(Path::new("crates/core/src/lib.rs")));
    }
}
