//! The student's functions of this kit's own `exercises/`, in a worker (principle 2): what
//! `cg check`, `cg view` and `cg report` call. The front end (`cg`) does not link the
//! exercises; [`worker`] builds `cg-check-runner` from them with cargo, in the profile and target
//! folder of the running program, and the calls go to that program over a pipe
//! ([`Impls::worker`](crate::Impls::worker)).
//!
//! **A file that does not compile is left out**, so that the other assignments still run: the
//! compiler's errors are read from cargo's JSON messages ([`diagnostics`]), each file with an
//! error is named in `CG_EXERCISES_LEFT_OUT` (exercises/build.rs turns it into a stand-in module)
//! and the build is tried again. The worker then answers every call of that file's functions
//! with the compiler's errors ([`cg_worker::Worker::without_modules`]), so each check, picture
//! and report part that needs them says "does not compile" and shows where.

use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use cg_core::lang::{Lang, t};
use cg_worker::Worker;

use crate::IDS;

/// The package of the worker program.
pub const WORKER_PACKAGE: &str = "cg-check-runner";

/// The variable exercises/build.rs reads: the modules to leave out, `a1,s`.
pub const LEFT_OUT_VARIABLE: &str = "CG_EXERCISES_LEFT_OUT";

/// How many of a file's compiler errors are kept (the first one whole).
pub const ERRORS_KEPT: usize = 8;

/// One compiler error, from cargo's `--message-format=json`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic {
    /// The student's module the error is in (`a1` for `exercises/src/a1.rs`), when it is in one.
    pub module: Option<&'static str>,
    /// `file:line: message`.
    pub short: String,
    /// The error as the compiler shows it (with the source line and the caret), without colour.
    pub rendered: String,
}

/// The module a compiler message's file belongs to: `exercises/src/a2.rs` → `a2`.
#[must_use]
pub fn module_of(file: &str) -> Option<&'static str> {
    let file = file.replace('\\', "/");
    IDS.iter().copied().find(|m| {
        let name = format!("src/{m}.rs");
        file == name || file.ends_with(&format!("exercises/{name}"))
    })
}

/// The errors in cargo's JSON messages (`stdout` of `cargo build --message-format=json`), in
/// order; each goes to the module of its primary span, or else of any span in a student
/// module, its notes' included.
#[must_use]
pub fn diagnostics(stdout: &str) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for line in stdout.lines() {
        let Ok(v) = serde_json::from_str::<serde_json::Value>(line) else { continue };
        if v["reason"] != "compiler-message" || v["message"]["level"] != "error" {
            continue;
        }
        let text = v["message"]["message"].as_str().unwrap_or("").to_owned();
        if text.starts_with("aborting due to") || text.starts_with("could not compile") {
            continue;
        }
        let spans = v["message"]["spans"].as_array().cloned().unwrap_or_default();
        let primary = spans.iter().find(|s| s["is_primary"] == true).or(spans.first());
        let place = primary.map(|s| {
            (
                s["file_name"].as_str().unwrap_or("?").to_owned(),
                s["line_start"].as_u64().unwrap_or(0),
            )
        });
        // Else a note's span: a module file that cannot be read (saved as Shift_JIS) is an error
        // at `pub mod a1;` in lib.rs, with a note at the byte of a1.rs that is not UTF-8; it
        // stopped every assignment (in grading, all scored 0).
        let children = v["message"]["children"].as_array().cloned().unwrap_or_default();
        let child_spans =
            children.iter().flat_map(|c| c["spans"].as_array().cloned().unwrap_or_default());
        let module = place
            .as_ref()
            .and_then(|(f, _)| module_of(f))
            .or_else(|| spans.iter().find_map(|s| s["file_name"].as_str().and_then(module_of)))
            .or_else(|| {
                child_spans.into_iter().find_map(|s| s["file_name"].as_str().and_then(module_of))
            });
        let short = match &place {
            Some((file, line)) => format!("{file}:{line}: {text}"),
            None => text,
        };
        let rendered = v["message"]["rendered"].as_str().unwrap_or(&short).trim_end().to_owned();
        out.push(Diagnostic { module, short, rendered });
    }
    out
}

/// The errors of each module: the first as the compiler shows it, the others one line each, at
/// most [`ERRORS_KEPT`].
fn by_module(diagnostics: &[Diagnostic], lang: Lang) -> BTreeMap<String, Vec<String>> {
    let mut out: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for d in diagnostics {
        if let Some(m) = d.module {
            let errors = out.entry(m.to_owned()).or_default();
            if errors.is_empty() {
                errors.push(d.rendered.clone());
                // The compiler's hint for a crate it does not know leads to exercises/Cargo.toml,
                // where an added crate passes here and scores 0 in grading.
                if d.rendered.contains("cargo add") {
                    errors.push(only_std_and_cg_student().get(lang).to_owned());
                }
            } else if errors.len() < ERRORS_KEPT {
                errors.push(d.short.clone());
            }
        }
    }
    out
}

/// What the kit adds to the compiler's `cargo add` hint.
fn only_std_and_cg_student() -> cg_core::lang::Text {
    t(
        "（キットより）演習で使えるのは標準ライブラリと cg_student だけです。exercises/Cargo.toml にクレートを足さないでください（採点ではキットのままの Cargo.toml でビルドします）",
        "(from the kit) the exercises can use the standard library and cg_student only: do not add crates to exercises/Cargo.toml (grading builds with the kit's own Cargo.toml)",
    )
}

/// Where the worker is built: the profile's folder of the running program (`target/release`,
/// when it runs from a cargo target folder, as `cargo run` runs it) and the profile's name for
/// cargo (`release`, `dev`); else `<root>/target/release`.
fn build_place(root: &Path) -> (PathBuf, String) {
    let exe = std::env::current_exe().ok();
    let mut dir = exe.as_deref().and_then(Path::parent).map(Path::to_path_buf).unwrap_or_default();
    // A test program (target/debug/deps/…): the profile's folder is the one above.
    if dir.file_name().is_some_and(|n| n == "deps") {
        dir.pop();
    }
    // Cargo marks each target folder with CACHEDIR.TAG.
    let in_target = dir.parent().is_some_and(|p| p.join("CACHEDIR.TAG").is_file());
    match dir.file_name().and_then(|n| n.to_str()) {
        Some("debug") if in_target => (dir, "dev".to_owned()),
        Some(name) if in_target => {
            let name = name.to_owned();
            (dir, name)
        }
        _ => (root.join("target").join("release"), "release".to_owned()),
    }
}

/// How one `cargo build` of the worker ended.
struct Build {
    success: bool,
    diagnostics: Vec<Diagnostic>,
    stderr: String,
}

/// `cargo build --profile <profile> -p cg-check-runner --message-format=json` of the kit at
/// `root`, into the target folder above `profile_dir`, leaving out `left_out`. Says on stderr
/// what it is doing when it takes more than two seconds (the first build after a fresh copy).
fn cargo_build(
    root: &Path,
    profile_dir: &Path,
    profile: &str,
    left_out: &[String],
    lang: Lang,
) -> Result<Build, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let target = profile_dir.parent().unwrap_or(profile_dir);
    let mut command = Command::new(&cargo);
    command
        .args(["build", "--message-format=json", "--profile", profile, "-p", WORKER_PACKAGE])
        .arg("--manifest-path")
        .arg(root.join("Cargo.toml"))
        .arg("--target-dir")
        .arg(target)
        .env(LEFT_OUT_VARIABLE, left_out.join(","))
        .stdin(Stdio::null());
    let say = || {
        let building = t(
            "exercises/ のあなたの関数をビルドしています…",
            "building your functions in exercises/…",
        );
        eprintln!("{}", building.get(lang));
    };
    let ran = run_captured(&mut command, None, &say).map_err(|e| {
        let why = cg_core::lang::Text::io(&e);
        cg_core::lang::Text::new(
            format!(
                "cargo を起動できません（{}）。Rust が入っているか、`cargo --version` で確かめてください",
                why.ja
            ),
            format!("cannot start cargo ({}); is Rust installed? Try `cargo --version`", why.en),
        )
        .get(lang)
        .to_owned()
    })?;
    let (success, stdout, stderr) =
        (ran.status.is_some_and(|s| s.success()), ran.stdout, ran.stderr);
    Ok(Build { success, diagnostics: diagnostics(&stdout), stderr })
}

/// How a program run by [`run_captured`] ended.
#[derive(Debug)]
pub struct Captured {
    /// Its exit status; `None` when it ran over its limit and was killed.
    pub status: Option<std::process::ExitStatus>,
    /// Whether it ran over its limit.
    pub timed_out: bool,
    /// Its whole stdout.
    pub stdout: String,
    /// Its whole stderr.
    pub stderr: String,
}

/// Runs `command` (a build: cargo) with its stdout and stderr read whole on threads of their
/// own, so that neither pipe blocks it; kills it after `limit`, when given (on Unix its whole
/// process group, so the compilers it started go too: set one with `process_group(0)`), and
/// calls `slow` once when it has run for two seconds (to say what is going on).
///
/// # Errors
/// The program could not be started, or waited for.
pub fn run_captured(
    command: &mut Command,
    limit: Option<Duration>,
    slow: &dyn Fn(),
) -> std::io::Result<Captured> {
    let mut child = command.stdout(Stdio::piped()).stderr(Stdio::piped()).spawn()?;
    let read_all = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut s = Vec::new();
            let _ = r.read_to_end(&mut s);
            String::from_utf8_lossy(&s).into_owned()
        })
    };
    let out = child.stdout.take().map(|s| read_all(Box::new(s)));
    let err = child.stderr.take().map(|s| read_all(Box::new(s)));
    let started = Instant::now();
    let mut said = false;
    let mut timed_out = false;
    let status = loop {
        if let Some(status) = child.try_wait()? {
            break Some(status);
        }
        if limit.is_some_and(|l| started.elapsed() > l) {
            timed_out = true;
            #[cfg(unix)]
            let _ = Command::new("kill").arg("-KILL").arg(format!("-{}", child.id())).status();
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        if !said && started.elapsed() > Duration::from_secs(2) {
            said = true;
            slow();
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let stdout = out.and_then(|h| h.join().ok()).unwrap_or_default();
    let stderr = err.and_then(|h| h.join().ok()).unwrap_or_default();
    Ok(Captured { status, timed_out, stdout, stderr })
}

/// The student's functions of the kit at `root` (the folder of `exercises/`), built into the
/// running program's target folder and run as a worker limited to `memory_mb` MiB; each file
/// that does not compile is left out, with its errors ([`Worker::modules_left_out`]).
///
/// # Errors
/// cargo could not be started, or the exercises do not build even with every failing file left
/// out (an error elsewhere: in lib.rs, Cargo.toml or the kit), as a message in `lang`.
pub fn worker(root: &Path, memory_mb: u64, lang: Lang) -> Result<Worker, String> {
    let (profile_dir, profile) = build_place(root);
    if let Some(why) = added_dependencies(root) {
        return Err(why.get(lang).to_owned());
    }
    let mut left_out: BTreeMap<String, Vec<String>> = not_gradable(root, lang);
    loop {
        let names: Vec<String> = left_out.keys().cloned().collect();
        let build = cargo_build(root, &profile_dir, &profile, &names, lang)?;
        if build.success {
            break;
        }
        let blamed: BTreeMap<String, Vec<String>> = by_module(&build.diagnostics, lang)
            .into_iter()
            .filter(|(m, _)| !left_out.contains_key(m))
            .collect();
        if blamed.is_empty() {
            let errors: Vec<&str> = build.diagnostics.iter().map(|d| d.rendered.as_str()).collect();
            if errors.is_empty() {
                // No compiler error: cargo itself failed (on Windows, typically the worker's
                // program still running in an open `cg view` window, which cannot be replaced).
                return Err(format!(
                    "{}\n{}",
                    t(
                        "あなたの関数（exercises/）をビルドできません（cargo のエラー）。Windows では、開いている `cargo run --release -- view …` のウィンドウを閉じてからやり直してください:",
                        "your functions (exercises/) could not be built (cargo failed). On Windows, close an open `cargo run --release -- view …` window and try again:",
                    )
                    .get(lang),
                    build.stderr.trim_end()
                ));
            }
            return Err(format!(
                "{}\n{}",
                t(
                    "あなたの関数（exercises/）をビルドできません。課題のファイル（a1.rs など）以外にエラーがあります:",
                    "your functions (exercises/) do not build; there are errors outside the assignments' files (a1.rs, …):",
                )
                .get(lang),
                errors.join("\n")
            ));
        }
        left_out.extend(blamed);
    }
    let program = profile_dir.join(format!("{WORKER_PACKAGE}{}", std::env::consts::EXE_SUFFIX));
    Ok(Worker::new(program, ["--memory-mb".to_owned(), memory_mb.max(64).to_string()])
        .without_modules(left_out))
}

/// The dependencies `exercises/Cargo.toml` has as the kit gives it: the students' API alone
/// (a test checks this against the kit's own file).
pub const EXERCISE_DEPENDENCIES: [&str; 1] = ["cg-student"];

/// Why the student's build would not be the grader's, when a crate has been added to
/// `exercises/Cargo.toml` (`rand = "0.8"`, as the compiler's `cargo add` hint suggests): grading
/// builds the submitted files with the kit's own manifest, so every file that uses the crate
/// scores 0 there while `cg check` passed it. `None` when the manifest adds none (or does not
/// read as TOML: cargo names that).
#[must_use]
pub fn added_dependencies(root: &Path) -> Option<cg_core::lang::Text> {
    let path = root.join("exercises").join("Cargo.toml");
    let text = std::fs::read_to_string(&path).ok()?;
    let manifest: toml::Table = text.parse().ok()?;
    // The manifest itself and each `[target.'cfg(…)']` table.
    let targets = manifest.get("target").and_then(toml::Value::as_table);
    let scopes = std::iter::once(&manifest)
        .chain(targets.into_iter().flat_map(|t| t.values().filter_map(toml::Value::as_table)));
    let tables: Vec<&toml::Table> = scopes
        .flat_map(|t| {
            ["dependencies", "build-dependencies"].into_iter().filter_map(|k| t.get(k)?.as_table())
        })
        .collect();
    let mut added: Vec<&str> = tables
        .iter()
        .flat_map(|t| t.keys())
        .map(String::as_str)
        .filter(|name| !EXERCISE_DEPENDENCIES.contains(name))
        .collect();
    added.sort_unstable();
    added.dedup();
    if added.is_empty() {
        return None;
    }
    let list = added.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ");
    Some(cg_core::lang::Text::new(
        format!(
            "exercises/Cargo.toml にクレート {list} が足されています。採点では提出した exercises/src/ のファイルをキットのままの Cargo.toml でビルドするので、足したクレートは使えず、それを使うファイルは 0 点になります。使えるのは標準ライブラリと cg_student だけです。exercises/Cargo.toml から足した行を消してください"
        ),
        format!(
            "exercises/Cargo.toml has the crate(s) {list} added. Grading builds the submitted files of exercises/src/ with the kit's own Cargo.toml, so an added crate cannot be used there and a file that uses it scores 0. Only the standard library and cg_student can be used: remove the added lines from exercises/Cargo.toml"
        ),
    ))
}

/// The assignments' files that grading would not build as they are, each with why in `lang`:
/// a file grading refuses ([`crate::screen::screen`]: the whole submission scores 0 for it), or
/// one with a module kept in a file of its own ([`crate::screen::other_files`]: grading reads
/// only the assignments' files, so it does not compile there). `cg check` leaves them out as it
/// leaves out a file that does not compile, so that the student hears of it before submitting;
/// they passed here and scored 0 in grading.
fn not_gradable(root: &Path, lang: Lang) -> BTreeMap<String, Vec<String>> {
    let mut out = BTreeMap::new();
    for module in IDS {
        let file = format!("exercises/src/{module}.rs");
        let Ok(bytes) = std::fs::read(root.join(&file)) else { continue };
        let text = match String::from_utf8(bytes) {
            Ok(text) => text,
            Err(e) => {
                // Saved as Shift_JIS or UTF-16: rustc reads only UTF-8 (its English error
                // stopped every assignment); what a text the kit can read is said is named.
                if let Ok((_, encoding)) = cg_core::text::decode(e.as_bytes(), None) {
                    let why = not_utf8(&file, encoding.name()).get(lang).to_owned();
                    out.insert((*module).to_owned(), vec![why]);
                }
                continue;
            }
        };
        let mut why = Vec::new();
        let refused = crate::screen::screen(&file, &text);
        if !refused.is_empty() {
            why.push(crate::screen::refused_locally(&refused).get(lang).to_owned());
        }
        for r in crate::screen::other_files(&file, &text) {
            why.push(crate::screen::other_file_message(&r, module).get(lang).to_owned());
        }
        if !why.is_empty() {
            out.insert((*module).to_owned(), why);
        }
    }
    out
}

/// What `cg check` says of an assignment's file saved in `encoding` (Shift_JIS, UTF-16): Rust
/// reads only UTF-8, and how to save it so.
#[must_use]
pub fn not_utf8(file: &str, encoding: &str) -> cg_core::lang::Text {
    // What VS Code's status bar shows for it.
    let shown = match encoding {
        "Shift_JIS" => "Shift JIS",
        "UTF-16LE" => "UTF-16 LE",
        "UTF-16BE" => "UTF-16 BE",
        other => other,
    };
    cg_core::lang::Text::new(
        format!(
            "{file} は {encoding} で保存されています。Rust のソースファイルは UTF-8 でなければならないので、このままではビルドできません。エディタで文字コードを UTF-8 にして保存し直してください（VS Code: 右下の文字コードの表示「{shown}」→「エンコード付きで保存」→「UTF-8」。メモ帳: 「名前を付けて保存」の文字コードで「UTF-8」）。採点では UTF-8 に直して読みます"
        ),
        format!(
            "{file} is saved as {encoding}. Rust source files must be UTF-8, so it cannot be built as it is: save it again as UTF-8 in your editor (VS Code: click \"{shown}\" at the bottom right → \"Save with Encoding\" → \"UTF-8\"; Notepad: \"Save as\" with the encoding \"UTF-8\"). Grading reads it converted to UTF-8"
        ),
    )
}

/// The kit this program runs in: the folder above `exercises/` (the current folder's, or the
/// kit's this program was built from: `cg_harness::kit_path`).
fn this_kit() -> PathBuf {
    let exercises = cg_harness::kit_path(None, "exercises");
    let exercises = exercises.canonicalize().unwrap_or(exercises);
    exercises.parent().map_or(exercises.clone(), Path::to_path_buf)
}

/// [`worker`] for the kit this program runs in.
///
/// # Errors
/// As [`worker`].
pub fn worker_for_this_kit(memory_mb: u64, lang: Lang) -> Result<Worker, String> {
    worker(&this_kit(), memory_mb, lang)
}

/// [`worker_for_this_kit`] for a window that stays open while `cg watch` rebuilds the worker.
/// On Windows a running program cannot be replaced, so the window's worker runs from a copy of
/// its own (`cg-check-runner-view-<process>.exe` beside it) and the rebuild goes ahead; the
/// copies of earlier views that no longer run are removed first (a running one cannot be).
/// Elsewhere the rebuild replaces the file while the old program runs on, and no copy is made.
///
/// # Errors
/// As [`worker`]; or the copy could not be made.
pub fn worker_for_a_window(memory_mb: u64, lang: Lang) -> Result<Worker, String> {
    let worker = worker_for_this_kit(memory_mb, lang)?;
    if cfg!(windows) { run_from_a_copy(worker) } else { Ok(worker) }
}

/// `worker` running from a copy of its program, `<program>-view-<this process>` beside it, the
/// copies of earlier views removed where they can be ([`worker_for_a_window`]).
///
/// # Errors
/// The copy could not be made.
fn run_from_a_copy(worker: Worker) -> Result<Worker, String> {
    let program = worker.program().to_path_buf();
    let dir = program.parent().map(Path::to_path_buf).unwrap_or_default();
    let prefix = format!("{WORKER_PACKAGE}-view-");
    if let Ok(entries) = std::fs::read_dir(&dir) {
        for entry in entries.flatten() {
            if entry.file_name().to_string_lossy().starts_with(&prefix) {
                // In use by another open view: Windows refuses, and it stays.
                let _ = std::fs::remove_file(entry.path());
            }
        }
    }
    let copy = dir.join(format!("{prefix}{}{}", std::process::id(), std::env::consts::EXE_SUFFIX));
    std::fs::copy(&program, &copy).map_err(|e| format!("{}: {e}", copy.display()))?;
    Ok(worker.with_program(copy))
}

/// The memory a worker of `cg view`, `cg report` and `cg handin` may use, in MiB, and the default
/// of `--memory-limit` (`cg check`, `cg grade`, `cg grade-one`).
pub const MEMORY_MB: u64 = 2048;

/// The time one call of a student's function may take in `cg view`, `cg report` and `cg handin`,
/// and the default of `--time-limit` (`cg check`, `cg grade`, `cg grade-one`).
pub const CALL_LIMIT: Duration = Duration::from_secs(20);

/// The worker program [`worker_for_this_kit`] builds: what a window watches for a rebuild.
#[must_use]
pub fn worker_program() -> PathBuf {
    let (profile_dir, _) = build_place(&this_kit());
    profile_dir.join(format!("{WORKER_PACKAGE}{}", std::env::consts::EXE_SUFFIX))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The encoding is named as VS Code's status bar shows it, whichever it is (it said "Shift
    /// JIS" for a UTF-16 file too).
    #[test]
    fn a_file_not_in_utf8_is_named_as_the_editor_shows_it() {
        let sjis = not_utf8("exercises/src/a3.rs", "Shift_JIS");
        assert!(sjis.en.contains("click \"Shift JIS\" at the bottom right"), "{}", sjis.en);
        assert!(sjis.ja.contains("右下の文字コードの表示「Shift JIS」"), "{}", sjis.ja);
        let utf16 = not_utf8("exercises/src/a3.rs", "UTF-16LE");
        assert!(utf16.en.starts_with("exercises/src/a3.rs is saved as UTF-16LE."), "{}", utf16.en);
        assert!(
            utf16.en.contains("click \"UTF-16 LE\"") && !utf16.en.contains("Shift"),
            "{}",
            utf16.en
        );
        assert!(utf16.ja.contains("「UTF-16 LE」") && !utf16.ja.contains("Shift"), "{}", utf16.ja);
    }

    #[test]
    fn a_window_runs_its_worker_from_a_copy_and_old_copies_go() {
        let dir = std::env::temp_dir().join(format!("cg-local-copy-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let exe = std::env::consts::EXE_SUFFIX;
        let program = dir.join(format!("{WORKER_PACKAGE}{exe}"));
        std::fs::write(&program, b"the worker").unwrap();
        let stale = dir.join(format!("{WORKER_PACKAGE}-view-1{exe}"));
        std::fs::write(&stale, b"an old view's").unwrap();
        let other = dir.join("cg-check-runner.d");
        std::fs::write(&other, b"kept").unwrap();
        let worker = run_from_a_copy(Worker::new(&program, Vec::<String>::new())).unwrap();
        let copy = dir.join(format!("{WORKER_PACKAGE}-view-{}{exe}", std::process::id()));
        assert_eq!(worker.program(), copy);
        assert_eq!(std::fs::read(&copy).unwrap(), b"the worker");
        assert!(!stale.exists() && other.exists() && program.exists());
        let _ = std::fs::remove_dir_all(&dir);
    }

    fn message(file: &str, line: u64, text: &str) -> String {
        serde_json::json!({
            "reason": "compiler-message",
            "message": {
                "level": "error",
                "message": text,
                "rendered": format!("error: {text}\n --> {file}:{line}:5\n"),
                "spans": [{"file_name": file, "line_start": line, "is_primary": true}],
            }
        })
        .to_string()
    }

    #[test]
    fn errors_go_to_their_module_the_first_whole() {
        let out = [
            message("exercises/src/a1.rs", 12, "expected `;`"),
            message("exercises/src/a1.rs", 20, "mismatched types"),
            message("exercises/src/s.rs", 3, "cannot find value `x`"),
            message("crates/check-runner/src/lib.rs", 28, "no function"),
            r#"{"reason":"compiler-message","message":{"level":"error","message":"aborting due to 2 previous errors","spans":[]}}"#.to_owned(),
            "not json".to_owned(),
        ]
        .join("\n");
        let d = diagnostics(&out);
        assert_eq!(d.len(), 4, "{d:?}");
        assert_eq!(d[3].module, None);
        let m = by_module(&d, Lang::En);
        assert_eq!(m.keys().collect::<Vec<_>>(), ["a1", "s"]);
        assert!(m["a1"][0].starts_with("error: expected `;`\n --> exercises/src/a1.rs:12"));
        assert_eq!(m["a1"][1], "exercises/src/a1.rs:20: mismatched types");
        assert_eq!(module_of("C:\\kit\\exercises\\src\\a4.rs"), Some("a4"));
        // A file saved as Shift_JIS: the error is at `pub mod a1;` in lib.rs, its note at
        // a1.rs (cargo's JSON as it came). It stopped every assignment; it is a1's.
        let unreadable = serde_json::json!({
            "reason": "compiler-message",
            "message": {
                "level": "error",
                "message": "couldn't read `exercises/src/a1.rs`: stream did not contain valid UTF-8",
                "spans": [{"file_name": "exercises/src/lib.rs", "line_start": 47, "is_primary": true}],
                "children": [{
                    "message": "byte `137` is not valid utf-8",
                    "spans": [{"file_name": "exercises/src/a1.rs", "line_start": 1, "is_primary": true}],
                }],
            }
        });
        assert_eq!(diagnostics(&unreadable.to_string())[0].module, Some("a1"));
        assert_eq!(module_of("exercises/src/lib.rs"), None);
        assert_eq!(module_of("solutions/src/a1.rs"), None);
    }

    /// The compiler's `cargo add` hint for a crate it does not know gets the kit's word that
    /// only std and cg_student can be used (it led students to exercises/Cargo.toml).
    #[test]
    fn the_cargo_add_hint_gets_the_kits_word() {
        let hint = "unresolved import `rand`\nhelp: if you wanted to use a crate named `rand`, use `cargo add rand` to add it to your `Cargo.toml`";
        let d = diagnostics(&message("exercises/src/a2.rs", 1, hint));
        let m = by_module(&d, Lang::Ja);
        assert_eq!(m["a2"].len(), 2, "{m:?}");
        assert!(m["a2"][1].contains("標準ライブラリと cg_student だけ"), "{m:?}");
        let d = diagnostics(&message("exercises/src/a2.rs", 1, "mismatched types"));
        assert_eq!(by_module(&d, Lang::Ja)["a2"].len(), 1);
    }

    fn kit_with(manifest: &str, files: &[(&str, &str)]) -> PathBuf {
        let dir = std::env::temp_dir().join(format!(
            "cg-local-{}-{}",
            std::process::id(),
            hash_of(manifest, files)
        ));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("exercises/src")).unwrap();
        std::fs::write(dir.join("exercises/Cargo.toml"), manifest).unwrap();
        for (name, text) in files {
            std::fs::write(dir.join("exercises/src").join(name), text).unwrap();
        }
        dir
    }

    fn hash_of(manifest: &str, files: &[(&str, &str)]) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        (manifest, files).hash(&mut h);
        h.finish()
    }

    /// The kit's own manifest adds nothing; a crate added under any dependency table is named.
    #[test]
    fn a_crate_added_to_the_exercises_manifest_is_named() {
        let kit_root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        assert_eq!(added_dependencies(&kit_root), None, "the kit's own exercises/Cargo.toml");
        let own = std::fs::read_to_string(kit_root.join("exercises/Cargo.toml")).unwrap();
        let own: toml::Table = own.parse().unwrap();
        let deps: Vec<&String> = own["dependencies"].as_table().unwrap().keys().collect();
        assert_eq!(deps, EXERCISE_DEPENDENCIES, "EXERCISE_DEPENDENCIES follows the kit's file");
        for (manifest, named) in [
            ("[dependencies]\ncg-student.workspace = true\nrand = \"0.8\"\n", "`rand`"),
            ("[build-dependencies]\ncc = \"1\"\n", "`cc`"),
            ("[target.'cfg(unix)'.dependencies]\nlibc = \"0.2\"\n", "`libc`"),
        ] {
            let dir = kit_with(manifest, &[]);
            let why = added_dependencies(&dir).expect(manifest);
            assert!(why.en.contains(&format!("has the crate(s) {named} added")), "{}", why.en);
            assert!(why.ja.contains(&format!("クレート {named} が足されています")), "{}", why.ja);
            let _ = std::fs::remove_dir_all(&dir);
        }
    }

    /// A file grading refuses, and one with a module in a file of its own, are left out here
    /// with why; a file of neither is not (they passed `cg check` and scored 0 in grading).
    #[test]
    fn files_grading_would_not_build_are_left_out_with_why() {
        let dir = kit_with(
            "[dependencies]\ncg-student.workspace = true\n",
            &[
                ("a1.rs", "mod geom;\npub fn f() {}\n"),
                ("a2.rs", "pub const P: &str = include_str!(\"/etc/passwd\");\n"),
                ("a3.rs", "mod inline { pub fn f() {} }\n"),
            ],
        );
        // a4.rs saved as Shift_JIS (a Japanese Windows editor's "ANSI"): named with how to save
        // it as UTF-8 (rustc's English error stopped every assignment).
        // `// 課題4` in Shift_JIS: 課 is 89 DB, 題 91 E8.
        let sjis = b"// \x89\xdb\x91\xe84\npub fn f() {}\n";
        std::fs::write(dir.join("exercises/src/a4.rs"), sjis).unwrap();
        let left = not_gradable(&dir, Lang::En);
        assert_eq!(left.keys().collect::<Vec<_>>(), ["a1", "a2", "a4"], "{left:?}");
        assert!(
            left["a4"][0].starts_with(
                "exercises/src/a4.rs is saved as Shift_JIS. Rust source files must be UTF-8"
            ),
            "{left:?}"
        );
        assert!(not_gradable(&dir, Lang::Ja)["a4"][0].contains("UTF-8 にして保存し直してください"));
        assert!(left["a1"][0].starts_with("exercises/src/a1.rs:1: `mod geom;` reads another file"));
        assert!(left["a2"][0].starts_with("grading refuses the whole submission (0 points)"));
        assert!(left["a2"][0].contains("exercises/src/a2.rs:1: include_str!"), "{left:?}");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
