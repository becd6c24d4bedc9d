//! Every command the kit prints runs as printed (principle 4): each `cargo run --release -- …`
//! written in the kit's messages, hints, stubs, templates and documents parses through `cg`'s
//! own argument parser. A usage synopsis with placeholders (`<DIR>`, `[--student N]`) is not a
//! command and is skipped; a command without `--release` is a fault of its own.

use std::path::{Path, PathBuf};

use clap::Parser;

use crate::Cli;

const PREFIX: &str = "cargo run --release -- ";

/// `cargo run --release`, then `--` or one of [`FEATURES`] and `--`: what starts a command of `cg`.
const RUN: &str = "cargo run --release ";

/// The features a printed command may build before `--`: the students' copy builds the GPU
/// renderer and the instructors' commands only when asked (`--features gpu -- render --renderer
/// gpu`). This test runs on the kit's own build, which has them all.
const FEATURES: [&str; 2] = ["--features gpu -- ", "--features instructor -- "];

/// The text files of the kit a student or an instructor reads commands in.
fn files(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let path = entry.path();
        let name = entry.file_name().to_string_lossy().into_owned();
        if path.is_dir() {
            if !matches!(name.as_str(), "target" | ".git" | "node_modules") {
                files(&path, out);
            }
        } else if ["rs", "md", "tex", "toml", "txt"]
            .iter()
            .any(|e| path.extension().is_some_and(|x| x == *e))
        {
            out.push(path);
        }
    }
}

/// Whether the word at the start of `text` is a file name (`課題1.zip`, `out/図.png`): it has a
/// `.` or `/` and ends in an ASCII letter or digit. A Japanese sentence after a command does not.
fn names_a_file(text: &str) -> bool {
    let word = text.split_whitespace().next().unwrap_or_default();
    word.contains(['.', '/']) && word.chars().last().is_some_and(|c| c.is_ascii_alphanumeric())
}

/// The commands after [`PREFIX`] (or [`RUN`] and one of [`FEATURES`]) in `text`: each up to the
/// end of its line, quote, backquote,
/// table cell, parenthesis, a run of two spaces (an aligned comment) or the first non-ASCII
/// character (the Japanese sentence around it); an ellipsis `…` is kept (a placeholder).
fn commands(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    for (at, _) in text.match_indices(RUN) {
        let after = &text[at + RUN.len()..];
        let Some(skip) = std::iter::once("-- ")
            .chain(FEATURES)
            .find_map(|p| after.starts_with(p).then_some(p.len()))
        else {
            continue;
        };
        let rest = &after[skip..];
        let mut end = rest.len();
        for (i, c) in rest.char_indices() {
            if c == '…' {
                // `--student …`: a placeholder, kept so the command counts as a synopsis.
                end = i + c.len_utf8();
                break;
            }
            if !c.is_ascii() && names_a_file(&rest[i..]) {
                // A Japanese file name (`課題1のダウンロード.zip`): an argument the reader
                // replaces, kept as a placeholder.
                end = i + c.len_utf8();
                break;
            }
            if !c.is_ascii() || matches!(c, '`' | '"' | '\\' | '|' | '(' | ')' | '\n' | '\r' | '#')
            {
                end = i;
                break;
            }
            if rest[i..].starts_with("  ") {
                end = i;
                break;
            }
        }
        let command = rest[..end].trim().trim_end_matches(['.', ',', ';', ':']).trim();
        found.push(command.to_owned());
    }
    found
}

#[test]
fn every_command_the_kit_prints_parses() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut paths = Vec::new();
    for dir in ["crates", "exercises", "solutions", "docs", "assets", "scripts"] {
        files(&root.join(dir), &mut paths);
    }
    paths.push(root.join("README.md"));
    let (mut parsed, mut synopses) = (0, 0);
    let mut failures = Vec::new();
    for path in &paths {
        let Ok(text) = std::fs::read_to_string(path) else { continue };
        // This file's own examples are not commands.
        if path.ends_with("cli/src/printed.rs") {
            continue;
        }
        for command in commands(&text) {
            if command.contains(['<', '[', '{', '…']) || !command.is_ascii() {
                synopses += 1;
                continue;
            }
            let args = std::iter::once("cg").chain(command.split_whitespace());
            match Cli::try_parse_from(args) {
                Ok(_) => parsed += 1,
                Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelp => parsed += 1,
                Err(e) => failures.push(format!(
                    "{}: `{PREFIX}{command}`: {}",
                    path.strip_prefix(&root).unwrap_or(path).display(),
                    e.to_string().lines().next().unwrap_or_default()
                )),
            }
        }
    }
    assert!(failures.is_empty(), "commands that do not parse:\n{}", failures.join("\n"));
    // The kit prints many; a scan that finds none is broken, not clean.
    assert!(parsed >= 60, "only {parsed} commands found ({synopses} synopses)");
}

#[test]
fn the_scan_finds_commands_where_they_are_written() {
    let text = "Run `cargo run --release -- check a1` then\n\
                cargo run --release -- view a4 で見る\n\
                \"… (cargo run --release -- view s) …\"\n\
                cargo run --release -- check s    View: cargo run --release -- view s\n\
                cargo run --release -- report check <report.md>\n\
                then `cargo run --release -- check a1 --student …` (yours)\n\
                cargo run --release -- grade 課題1のダウンロード.zip --out grades\n\
                cargo run --release --features gpu -- render --renderer gpu で GPU\n\
                cargo run --release --features instructor -- grade subs\n\
                cargo run --release -p cg-viewer --features gpu -- --renderer gpu\n\
                cargo run --release --locked -- check";
    assert_eq!(
        commands(text),
        [
            "check a1",
            "view a4",
            "view s",
            "check s",
            "view s",
            "report check <report.md>",
            "check a1 --student …",
            "grade 課",
            "render --renderer gpu",
            "grade subs"
        ]
    );
    // A command that cannot parse is caught: the test above would fail on it.
    assert!(Cli::try_parse_from(["cg", "view", "a9"]).is_err());
    assert!(Cli::try_parse_from(["cg", "check", "--nope"]).is_err());
}

#[test]
fn no_command_of_the_kit_drops_release() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut paths = Vec::new();
    for dir in ["crates", "exercises", "solutions", "docs", "assets"] {
        files(&root.join(dir), &mut paths);
    }
    paths.push(root.join("README.md"));
    let debug_run: Vec<String> = paths
        .iter()
        .filter(|p| !p.ends_with("cli/src/printed.rs"))
        .filter_map(|p| {
            let text = std::fs::read_to_string(p).ok()?;
            text.contains(concat!("cargo run ", "-- ")).then(|| p.display().to_string())
        })
        .collect();
    // A debug build of every crate beside the release one: minutes, and another target folder.
    assert!(debug_run.is_empty(), "`cargo run -- …` without --release in: {debug_run:?}");
}
