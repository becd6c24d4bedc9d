//! The kit's Rust sources, for the tests that read them all (`two_languages.rs`, `terms.rs`).

use std::path::{Path, PathBuf};

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        if path.is_dir() {
            if name != "target" && !name.starts_with('.') {
                rust_files(&path, out);
            }
        } else if name.ends_with(".rs") {
            out.push(path);
        }
    }
}

/// What `findings` finds in every Rust file of the kit (`crates/`, `exercises/`, `solutions/`)
/// but the test's own (`this`, its `file!()`), each as `path:finding` with the path from the
/// kit's root, written with `/`. `findings` is given that path and the file's text.
///
/// # Panics
/// When the kit's sources are not found, or a file cannot be read.
pub fn scan(this: &str, findings: impl Fn(&str, &str) -> Vec<String>) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut files = Vec::new();
    for dir in ["crates", "exercises", "solutions"] {
        rust_files(&root.join(dir), &mut files);
    }
    assert!(files.len() > 100, "the kit's sources were not found under {}", root.display());
    let this = Path::new(this).file_name();
    let mut found = Vec::new();
    for file in files.iter().filter(|f| f.file_name() != this) {
        let source = std::fs::read_to_string(file).unwrap();
        let name = file.strip_prefix(&root).unwrap_or(file).to_string_lossy().replace('\\', "/");
        found.extend(findings(&name, &source).into_iter().map(|f| format!("{name}:{f}")));
    }
    found
}
