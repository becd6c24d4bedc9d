//! The student's stubs, generated from the reference solutions so the two never drift apart.
//!
//! In a solution file (`solutions/src/*.rs`):
//!
//! ```text
//! pub fn vertices(spec: &Spec) -> Vec<Vec3> {
//!     // BEGIN SOLUTION
//!     let h = spec.height / 2.0;
//!     vec![…]
//!     // END SOLUTION
//!     // BEGIN STUB
//!     // todo!("a1.t1: list the vertices of your polyhedron")
//!     // END STUB
//! }
//! ```
//!
//! The stub (`exercises/src/*.rs`) drops the solution block and uncomments the stub block (the
//! first `// ` after the indentation of each line goes); the marker lines themselves disappear;
//! every other line is copied as it is. `solutions/Cargo.toml` becomes `exercises/Cargo.toml`
//! with the package renamed and lines between `# BEGIN SOLUTION` / `# END SOLUTION` dropped.

use std::path::{Path, PathBuf};

/// A marker out of place in a solution file.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{file}:{line}: {message}")]
pub struct StubError {
    /// The file (relative to the solutions folder).
    pub file: String,
    /// The 1-based line.
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Block {
    Plain,
    Solution,
    Stub,
}

/// The stub text of one solution source file (see the module docs). `file` names it in errors.
///
/// # Errors
/// A marker inside another block, an `END` without its `BEGIN`, a block never closed, or a
/// stub line that is not a comment.
pub fn stub_from_solution(text: &str, file: &str, comment: &str) -> Result<String, StubError> {
    let error = |line: usize, message: &str| StubError {
        file: file.to_owned(),
        line,
        message: message.to_owned(),
    };
    let begin_solution = format!("{comment} BEGIN SOLUTION");
    let end_solution = format!("{comment} END SOLUTION");
    let begin_stub = format!("{comment} BEGIN STUB");
    let end_stub = format!("{comment} END STUB");
    let mut out = String::with_capacity(text.len());
    let mut block = Block::Plain;
    let mut opened = 0;
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        let trimmed = line.trim();
        let marker = [&begin_solution, &end_solution, &begin_stub, &end_stub]
            .into_iter()
            .position(|m| trimmed == m.as_str());
        match (marker, block) {
            (Some(0), Block::Plain) => (block, opened) = (Block::Solution, n),
            (Some(2), Block::Plain) => (block, opened) = (Block::Stub, n),
            (Some(1), Block::Solution) | (Some(3), Block::Stub) => block = Block::Plain,
            (Some(0 | 2), _) => {
                return Err(error(n, &format!("a BEGIN inside the block opened on line {opened}")));
            }
            (Some(_), Block::Plain) => return Err(error(n, "an END without its BEGIN")),
            (Some(_), _) => {
                return Err(error(
                    n,
                    &format!("the wrong END for the block opened on line {opened}"),
                ));
            }
            (None, Block::Plain) => {
                out.push_str(line);
                out.push('\n');
            }
            (None, Block::Solution) => {}
            (None, Block::Stub) => {
                let indent = &line[..line.len() - line.trim_start().len()];
                let rest = line.trim_start();
                let body = rest
                    .strip_prefix(&format!("{comment} "))
                    .or_else(|| rest.strip_prefix(comment).filter(|r| r.is_empty()))
                    .ok_or_else(|| {
                        error(
                            n,
                            &format!("a stub line must be a comment starting with `{comment} `"),
                        )
                    })?;
                if body.is_empty() {
                    out.push('\n');
                } else {
                    out.push_str(indent);
                    out.push_str(body);
                    out.push('\n');
                }
            }
        }
    }
    if block != Block::Plain {
        return Err(error(opened, "this block is never closed"));
    }
    Ok(out)
}

/// Every file of the exercises crate as the solutions crate at `solutions` generates it:
/// `Cargo.toml`, `build.rs` and every `src/**/*.rs`, as (path relative to the crate, contents), sorted.
///
/// # Errors
/// A file that cannot be read, or a marker out of place.
pub fn generate(solutions: &Path) -> Result<Vec<(PathBuf, String)>, StubError> {
    let io = |path: &Path, e: std::io::Error| StubError {
        file: path.display().to_string(),
        line: 0,
        message: e.to_string(),
    };
    let manifest = solutions.join("Cargo.toml");
    let text = std::fs::read_to_string(&manifest).map_err(|e| io(&manifest, e))?;
    let text = stub_from_solution(&text, "Cargo.toml", "#")?
        .replace("name = \"cg-solutions\"", "name = \"cg-exercises\"");
    let mut files = vec![(PathBuf::from("Cargo.toml"), text)];
    // The build script that leaves out a module that does not compile (the same in both).
    let script = solutions.join("build.rs");
    if script.exists() {
        let text = std::fs::read_to_string(&script).map_err(|e| io(&script, e))?;
        files.push((PathBuf::from("build.rs"), stub_from_solution(&text, "build.rs", "//")?));
    }
    let mut stack = vec![solutions.join("src")];
    while let Some(dir) = stack.pop() {
        let entries = std::fs::read_dir(&dir).map_err(|e| io(&dir, e))?;
        for entry in entries {
            let path = entry.map_err(|e| io(&dir, e))?.path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let relative = path.strip_prefix(solutions).unwrap_or(&path).to_path_buf();
                let text = std::fs::read_to_string(&path).map_err(|e| io(&path, e))?;
                let stub = stub_from_solution(&text, &relative.display().to_string(), "//")?;
                files.push((relative, stub));
            }
        }
    }
    files.sort();
    Ok(files)
}

/// The files of `exercises` that differ from what `solutions` generates (missing ones too), as
/// relative paths, sorted. Empty when the two are in sync.
///
/// # Errors
/// As [`generate`].
pub fn out_of_sync(solutions: &Path, exercises: &Path) -> Result<Vec<PathBuf>, StubError> {
    Ok(generate(solutions)?
        .into_iter()
        .filter(|(path, text)| {
            std::fs::read_to_string(exercises.join(path)).ok().as_deref() != Some(text)
        })
        .map(|(path, _)| path)
        .collect())
}

/// Writes every generated file into `exercises` (creating folders), returning the paths that
/// changed.
///
/// # Errors
/// As [`generate`], or a file that cannot be written.
pub fn write(solutions: &Path, exercises: &Path) -> Result<Vec<PathBuf>, StubError> {
    let mut changed = Vec::new();
    for (path, text) in generate(solutions)? {
        let target = exercises.join(&path);
        if std::fs::read_to_string(&target).ok().as_deref() == Some(text.as_str()) {
            continue;
        }
        if let Some(dir) = target.parent() {
            std::fs::create_dir_all(dir).map_err(|e| StubError {
                file: dir.display().to_string(),
                line: 0,
                message: e.to_string(),
            })?;
        }
        std::fs::write(&target, text).map_err(|e| StubError {
            file: target.display().to_string(),
            line: 0,
            message: e.to_string(),
        })?;
        changed.push(path);
    }
    Ok(changed)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SOLUTION: &str = "\
use glam::Vec3;

/// a1.t1: the vertices.
pub fn vertices() -> Vec<Vec3> {
    // BEGIN SOLUTION
    vec![Vec3::ZERO]
    // END SOLUTION
    // BEGIN STUB
    // // TODO a1.t1
    //
    // todo!(\"a1.t1: list the vertices\")
    // END STUB
}
";

    #[test]
    fn solutions_become_stubs() {
        let stub = stub_from_solution(SOLUTION, "a1.rs", "//").unwrap();
        assert_eq!(
            stub,
            "use glam::Vec3;\n\n/// a1.t1: the vertices.\npub fn vertices() -> Vec<Vec3> {\n    // TODO a1.t1\n\n    todo!(\"a1.t1: list the vertices\")\n}\n"
        );
    }

    #[test]
    fn misplaced_markers_are_named_with_their_line() {
        let cases = [
            ("// BEGIN SOLUTION\n// BEGIN STUB\n", 2, "inside"),
            ("x\n// END SOLUTION\n", 2, "without its BEGIN"),
            ("// BEGIN SOLUTION\n// END STUB\n", 2, "wrong END"),
            ("a\n// BEGIN STUB\n// x\n", 2, "never closed"),
            ("// BEGIN STUB\nnot a comment\n// END STUB\n", 2, "must be a comment"),
        ];
        for (text, line, needle) in cases {
            let e = stub_from_solution(text, "f.rs", "//").unwrap_err();
            assert_eq!(e.line, line, "{text:?}: {e}");
            assert!(e.message.contains(needle), "{text:?}: {e}");
            assert!(e.to_string().starts_with(&format!("f.rs:{line}: ")), "{e}");
        }
    }

    #[test]
    fn manifests_use_hash_comments() {
        let text = "[package]\nname = \"cg-solutions\"\n[dev-dependencies]\n# BEGIN SOLUTION\ncg-exercises = { path = \"../exercises\" }\n# END SOLUTION\n";
        let stub = stub_from_solution(text, "Cargo.toml", "#").unwrap();
        assert_eq!(stub, "[package]\nname = \"cg-solutions\"\n[dev-dependencies]\n");
    }
}
