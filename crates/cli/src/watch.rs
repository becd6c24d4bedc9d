//! `cg watch [ID]`: the checks again on every save, as rustlings does it.
//!
//! On each change under `exercises/` (the `notify` crate's native events, or polling where
//! those fail or `--poll` asks, e.g. WSL2 under /mnt/c), the kit is rebuilt and checked by a
//! new process (`cargo run --release -- check --json`: the running `cg` was built from the old
//! code), and a board is printed: every task of every assignment as a mark, the progress, and the
//! checks of the task in focus. Keys: `h` the hint of the first failing check, `n` the next
//! task, `r` run again, `q` quit. On a terminal they act at once; from a pipe, one per line.
//! 保存するたびにチェックをやり直します。キー: h ヒント、n 次のタスク、r やり直し、q 終了。

use std::io::{BufRead, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::mpsc::{Receiver, Sender, channel};
use std::time::Duration;

use cg_core::lang::{Lang, Text, t};
use notify::Watcher;
use serde_json::Value;

/// Options of `cg watch`.
#[derive(clap::Args)]
pub struct Args {
    /// An assignment (a1 … s) or a task (a3.t1) to check; default: all / 課題かタスク（省略するとすべて）
    #[arg(value_name = "ID", value_parser = crate::assignments::selection)]
    which: Option<crate::assignments::Selection>,
    /// The student number (default: exercises/student.toml) / 学生番号
    #[arg(long, value_name = "NUMBER", allow_hyphen_values = true)]
    student: Option<String>,
    /// Look for changes by polling every second instead of the system's file events (for
    /// folders where those do not arrive, e.g. WSL2 under /mnt/c) / ファイルの変更をポーリングで調べる
    #[arg(long)]
    poll: bool,
    /// The folder to watch (default: the kit's exercises/) / 監視するフォルダ
    #[arg(long, value_name = "DIR", hide = true)]
    dir: Option<PathBuf>,
}

/// What the loop waits for.
enum Event {
    /// A file under the watched folder changed.
    Changed,
    /// A key (or a line's first character from a pipe); `None` when the input ended.
    Key(Option<char>),
}

/// One check as the board shows it, from `cg check --json`.
struct Check {
    id: String,
    task: String,
    status: String,
    json: Value,
}

/// `cg watch`.
///
/// # Errors
/// The folder to watch is missing, the student number (`--student` or exercises/student.toml)
/// does not read, or the checks cannot be started at all (no cargo): each said before the first
/// build, or as soon as it is known, rather than a board that waits for a save that cannot help.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    // As `cg check` would refuse them, before a build.
    crate::assignments::student(args.student.as_deref(), None, lang)?;
    let dir = args.dir.clone().unwrap_or_else(|| cg_harness::kit_path(None, "exercises"));
    if !dir.is_dir() {
        return Err(format!(
            "{}: {}",
            dir.display(),
            t("フォルダがありません", "no such folder").get(lang)
        ));
    }
    let (tx, rx) = channel();
    let _watcher = watch(&dir, args.poll || wsl_windows_drive(&dir), tx.clone(), lang)?;
    let terminal = Terminal::start();
    keys(tx, terminal.raw);
    let mut focus: Option<String> = None;
    let mut checks = check(args, lang, &terminal)?;
    loop {
        board(&checks, focus.as_deref(), lang, &terminal);
        match wait(&rx) {
            Event::Changed | Event::Key(Some('r')) => checks = check(args, lang, &terminal)?,
            Event::Key(Some('n')) => focus = next_task(&checks, focus.as_deref()),
            Event::Key(Some('h')) => hint(&checks, focus.as_deref(), lang, &terminal),
            Event::Key(Some('q') | None) => break,
            Event::Key(Some(_)) => {}
        }
    }
    terminal.say(t("終了します。", "Bye.").get(lang));
    Ok(())
}

/// The next event, after letting a burst of file events settle (an editor's save is several).
fn wait(rx: &Receiver<Event>) -> Event {
    let event = rx.recv().unwrap_or(Event::Key(None));
    if let Event::Changed = event {
        while let Ok(e) = rx.recv_timeout(Duration::from_millis(300)) {
            if let Event::Key(k) = e {
                return Event::Key(k);
            }
        }
    }
    event
}

/// Watches `dir` for changes of Rust and TOML files: native events, or polling.
fn watch(
    dir: &Path,
    poll: bool,
    tx: Sender<Event>,
    lang: Lang,
) -> Result<Box<dyn Watcher>, String> {
    let handler = move |res: notify::Result<notify::Event>| {
        if let Ok(event) = res
            && !event.kind.is_access()
            && event.paths.iter().any(|p| p.extension().is_some_and(|e| e == "rs" || e == "toml"))
        {
            let _ = tx.send(Event::Changed);
        }
    };
    let mode = notify::RecursiveMode::Recursive;
    if !poll {
        let native = notify::recommended_watcher(handler.clone())
            .and_then(|mut w| w.watch(dir, mode).map(|()| w));
        if let Ok(w) = native {
            return Ok(Box::new(w));
        }
    }
    let config = notify::Config::default().with_poll_interval(Duration::from_secs(1));
    let mut w = notify::PollWatcher::new(handler, config).map_err(|e| e.to_string())?;
    w.watch(dir, mode).map_err(|e| {
        format!("{}: {} ({e})", dir.display(), t("監視できません", "cannot watch it").get(lang))
    })?;
    Ok(Box::new(w))
}

/// A Windows drive seen from WSL (`/mnt/c/…`), where inotify never hears the editor's saves.
fn wsl_windows_drive(dir: &Path) -> bool {
    let wsl = std::env::var_os("WSL_DISTRO_NAME").is_some();
    let on_drive = dir.canonicalize().is_ok_and(|d| d.starts_with("/mnt/"));
    wsl && on_drive
}

/// Sends the keys: single keys from a terminal in raw mode, else the first character of each
/// line of the input.
fn keys(tx: Sender<Event>, raw: bool) {
    std::thread::spawn(move || {
        if raw {
            use crossterm::event::{Event as Term, KeyCode, KeyEventKind, KeyModifiers};
            while let Ok(event) = crossterm::event::read() {
                if let Term::Key(k) = event
                    && k.kind == KeyEventKind::Press
                {
                    let key = match k.code {
                        KeyCode::Char('c') if k.modifiers.contains(KeyModifiers::CONTROL) => 'q',
                        KeyCode::Char(c) => c,
                        KeyCode::Esc => 'q',
                        _ => continue,
                    };
                    if tx.send(Event::Key(Some(key))).is_err() {
                        return;
                    }
                }
            }
        } else {
            for line in std::io::stdin().lock().lines() {
                let Ok(line) = line else { break };
                if let Some(c) = line.trim().chars().next()
                    && tx.send(Event::Key(Some(c))).is_err()
                {
                    return;
                }
            }
        }
        let _ = tx.send(Event::Key(None));
    });
}

/// The checks, from a new process built from the code as it is now, in this run's language. A
/// build that fails prints the compiler's first error and gives no checks.
///
/// # Errors
/// The process cannot be started (no cargo): no save can mend that.
fn check(args: &Args, lang: Lang, terminal: &Terminal) -> Result<Vec<Check>, String> {
    terminal.say(t("ビルドしてチェックしています…", "Building and checking…").get(lang));
    let mut checker = checker();
    let program = checker.get_program().to_string_lossy().into_owned();
    let command = checker.args(["check", "--json", "--lang", t("ja", "en").get(lang)]);
    command.args(args.which.iter().map(crate::assignments::Selection::id));
    if let Some(s) = &args.student {
        command.args(["--student", s]);
    }
    let output = match command.output() {
        Ok(o) => o,
        Err(e) => {
            return Err(Text::new(
                format!("チェックを起動できません（{program}: {}）", Text::io(&e).ja),
                format!("cannot start the checks ({program}: {})", Text::io(&e).en),
            )
            .get(lang)
            .to_owned());
        }
    };
    let reports: Value = match serde_json::from_slice(&output.stdout) {
        Ok(v) => v,
        Err(_) => {
            let stderr = String::from_utf8_lossy(&output.stderr);
            let first: Vec<&str> =
                stderr.lines().skip_while(|l| !l.starts_with("error")).take(12).collect();
            let text = if first.is_empty() { stderr.lines().take(12).collect() } else { first };
            terminal.say(&format!(
                "{}\n{}",
                t(
                    "ビルドかチェックが失敗しました（直して保存すると、もう一度チェックします）:",
                    "The build or the checks failed (fix it and save, and the checks run again):"
                )
                .get(lang),
                text.join("\n")
            ));
            return Ok(Vec::new());
        }
    };
    let mut checks = Vec::new();
    for report in reports.as_array().into_iter().flatten() {
        for c in report["checks"].as_array().into_iter().flatten() {
            checks.push(Check {
                id: c["id"].as_str().unwrap_or_default().to_owned(),
                task: c["task"].as_str().unwrap_or_default().to_owned(),
                status: c["status"].as_str().unwrap_or_default().to_owned(),
                json: c.clone(),
            });
        }
    }
    Ok(checks)
}

/// The command that checks: `cargo run --release -q -- ` in the kit's root (with the features
/// this `cg` was built with, [`features`]), or the program `CG_WATCH_CHECKER` names (the tests:
/// the `cg` they built).
fn checker() -> Command {
    if let Some(program) = std::env::var_os("CG_WATCH_CHECKER") {
        return Command::new(program);
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command.args(["run", "--release", "-q"]);
    command.args(features());
    command.arg("--");
    command.current_dir(cg_harness::kit_path(None, "."));
    command
}

/// cargo's options for the features this `cg` was built with, so that the checks run by the
/// same build instead of one with other features (a students' copy started with `cargo run
/// --release --features gpu -- watch` would otherwise be rebuilt without the GPU renderer, and
/// back again at the next `--features gpu`).
fn features() -> Vec<String> {
    let on: Vec<&str> = [
        ("reference", cfg!(feature = "reference")),
        ("gpu", cfg!(feature = "gpu")),
        ("instructor", cfg!(feature = "instructor")),
    ]
    .into_iter()
    .filter_map(|(name, built)| built.then_some(name))
    .collect();
    let mut options = vec!["--no-default-features".to_owned()];
    if !on.is_empty() {
        options.extend(["--features".to_owned(), on.join(",")]);
    }
    options
}

/// The tasks in order, each once.
fn tasks(checks: &[Check]) -> Vec<&str> {
    let mut tasks: Vec<&str> = Vec::new();
    for c in checks {
        if !tasks.contains(&c.task.as_str()) {
            tasks.push(&c.task);
        }
    }
    tasks
}

/// The task in focus: the one chosen with `n` if it is still there, else the first not done.
fn focused<'a>(checks: &'a [Check], focus: Option<&str>) -> Option<&'a str> {
    let all = tasks(checks);
    focus.and_then(|f| all.iter().find(|t| **t == f).copied()).or_else(|| {
        all.into_iter().find(|t| checks.iter().any(|c| c.task == *t && c.status != "pass"))
    })
}

/// The task after the one in focus that is not done, round the end.
fn next_task(checks: &[Check], focus: Option<&str>) -> Option<String> {
    let all = tasks(checks);
    let open: Vec<&str> = all
        .iter()
        .copied()
        .filter(|t| checks.iter().any(|c| c.task == *t && c.status != "pass"))
        .collect();
    let current = focused(checks, focus);
    let at = current.and_then(|f| open.iter().position(|t| *t == f));
    let next = match at {
        Some(i) => open.get(i + 1).or(open.first()),
        None => open.first(),
    };
    next.map(|t| (*t).to_owned())
}

fn mark(status: &str) -> char {
    match status {
        "pass" => '✓',
        "not_done" => '…',
        _ => '✗',
    }
}

/// The board: a line per assignment with a mark per task, the progress, and the checks of the
/// task in focus.
fn board(checks: &[Check], focus: Option<&str>, lang: Lang, terminal: &Terminal) {
    if checks.is_empty() {
        terminal.say(t("[r] もう一度  [q] 終了", "[r] run again  [q] quit").get(lang));
        return;
    }
    terminal.say(&board_text(checks, focus, lang));
}

/// The text of the [`board`] of some checks. Each explanation once: a check whose expected and
/// actual values are those shown under an earlier one says "（同上）" / "(same as above)".
fn board_text(checks: &[Check], focus: Option<&str>, lang: Lang) -> String {
    let mut text = String::new();
    let mut line = String::new();
    let mut assignment = "";
    for task in tasks(checks) {
        let a = task.split('.').next().unwrap_or_default();
        if a != assignment {
            if !line.is_empty() {
                text.push_str(&line);
                text.push('\n');
            }
            line = format!("{a:<3}");
            assignment = a;
        }
        let of_task: Vec<&Check> = checks.iter().filter(|c| c.task == task).collect();
        let status = if of_task.iter().all(|c| c.status == "pass") {
            "pass"
        } else if of_task.iter().any(|c| !matches!(c.status.as_str(), "pass" | "not_done")) {
            "fail"
        } else {
            "not_done"
        };
        line.push_str(&format!(" {}{}", mark(status), task.split('.').nth(1).unwrap_or_default()));
    }
    text.push_str(&line);
    text.push('\n');
    let passed = checks.iter().filter(|c| c.status == "pass").count();
    // Worded as `cg check`'s summary.
    let total = checks.len();
    text.push_str(
        Text::new(
            format!("進み具合: {passed}/{total} 個のチェックに合格\n"),
            format!("progress: {passed}/{total} checks pass\n"),
        )
        .get(lang),
    );
    match focused(checks, focus) {
        None => {
            text.push_str(t("すべてのチェックが通りました！\n", "Every check passes!\n").get(lang))
        }
        Some(task) => {
            text.push_str(&format!("── {task} ──\n"));
            let mut said = std::collections::BTreeSet::new();
            for c in checks.iter().filter(|c| c.task == task) {
                let title = c.json["title"][t("ja", "en").get(lang)].as_str().unwrap_or_default();
                let mut values = String::new();
                for (key, ja, en) in
                    [("expected", "期待する値", "expected"), ("actual", "実際の値", "actual")]
                {
                    if let Some(v) = c.json[key][t("ja", "en").get(lang)].as_str() {
                        values.push_str(&format!("      {}: {v}\n", t(ja, en).get(lang)));
                    }
                }
                let same = !values.is_empty() && !said.insert(values.clone());
                let same = if same {
                    t("  （同上）", "  (same as above)").get(lang).to_owned()
                } else {
                    String::new()
                };
                text.push_str(&format!("  {} {:<24} {title}{same}\n", mark(&c.status), c.id));
                if same.is_empty() {
                    text.push_str(&values);
                }
                // Why it gave no value (a stub not written yet, a panic, a timeout), in the
                // board's language as `cg check` says it, once, not under each of its checks.
                let why = serde_json::from_value::<cg_harness::check::CheckResult>(c.json.clone())
                    .ok()
                    .and_then(|r| r.outcome.describe());
                if let Some(why) = why.as_ref().map(|w| w.get(lang))
                    && said.insert(why.to_owned())
                {
                    text.push_str(&format!("      {why}\n"));
                }
                // A file that does not compile: its first error, once.
                if let Some(first) = compile_errors(c).first()
                    && said.insert((*first).to_owned())
                {
                    for l in first.lines() {
                        text.push_str(&format!("      | {l}\n"));
                    }
                }
            }
        }
    }
    text.push_str(
        t(
            "[h] ヒント  [n] 次のタスク  [r] もう一度  [q] 終了（保存するとチェックし直します）",
            "[h] hint  [n] next task  [r] run again  [q] quit (saving runs the checks again)",
        )
        .get(lang),
    );
    text
}

/// The usual cause and the hint of the first check of the task in focus that does not pass.
fn hint(checks: &[Check], focus: Option<&str>, lang: Lang, terminal: &Terminal) {
    let task = focused(checks, focus);
    let first = checks.iter().find(|c| Some(c.task.as_str()) == task && c.status != "pass");
    let Some(c) = first else {
        terminal.say(
            t(
                "ヒントはありません（通っていないチェックがありません）",
                "No hint: no check is failing.",
            )
            .get(lang),
        );
        return;
    };
    let mut text = format!("{} {}:", t("ヒント", "hint for").get(lang), c.id);
    let mut any = false;
    for (key, ja, en) in [("cause", "よくある原因", "usual cause"), ("hint", "ヒント", "hint")]
    {
        if let Some(v) = c.json[key][t("ja", "en").get(lang)].as_str() {
            text.push_str(&format!("\n  {}: {v}", t(ja, en).get(lang)));
            any = true;
        }
    }
    let errors = compile_errors(c);
    if !errors.is_empty() {
        let module = c.json["module"].as_str().unwrap_or_default();
        text.push_str(&format!(
            "\n  {}",
            Text::new(
                format!("exercises/src/{module}.rs がコンパイルできません。最初のエラーから直してください:"),
                format!("exercises/src/{module}.rs does not compile; fix the first error first:"),
            )
            .get(lang)
        ));
        for l in errors.iter().flat_map(|e| e.lines()) {
            text.push_str(&format!("\n    {l}"));
        }
    } else if !any {
        let m = c.json["message"].as_str().unwrap_or_default();
        text.push_str(&format!(
            "\n  {} {m}",
            t(
                "まだ書いていない関数です。関数のコメントの説明とヒントを読んでください:",
                "not written yet; read the function's comment for its contract and hint:"
            )
            .get(lang)
        ));
    }
    terminal.say(&text);
}

/// The compiler's errors of a check whose file did not compile (its JSON's `errors`).
fn compile_errors(c: &Check) -> Vec<&str> {
    c.json["errors"]
        .as_array()
        .map(|a| a.iter().filter_map(Value::as_str).collect())
        .unwrap_or_default()
}

/// The terminal: raw mode (single keys) when input and output are a terminal, restored on exit.
struct Terminal {
    raw: bool,
}

impl Terminal {
    fn start() -> Terminal {
        let tty = std::io::stdin().is_terminal() && std::io::stdout().is_terminal();
        let raw = tty && crossterm::terminal::enable_raw_mode().is_ok();
        Terminal { raw }
    }

    /// Prints `text` and a blank line (`\r\n` in raw mode, where `\n` does not return).
    fn say(&self, text: &str) {
        let mut out = std::io::stdout().lock();
        let text = if self.raw { text.replace('\n', "\r\n") } else { text.to_owned() };
        let end = if self.raw { "\r\n\r\n" } else { "\n\n" };
        let _ = write!(out, "{text}{end}");
        let _ = out.flush();
    }
}

impl Drop for Terminal {
    fn drop(&mut self) {
        if self.raw {
            let _ = crossterm::terminal::disable_raw_mode();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(id: &str, json: Value) -> Check {
        let task = id.rsplit_once('.').map_or(id, |(task, _)| task).to_owned();
        let status = json["status"].as_str().unwrap_or_default().to_owned();
        Check { id: id.to_owned(), task, status, json }
    }

    /// A wrong face fails the checks that need valid faces with the same values: they are shown
    /// once, the other checks of the task say "(same as above)", and every ID is still there.
    #[test]
    fn the_same_values_are_shown_once_on_the_board() {
        let failed = |id: &str| {
            check(
                id,
                serde_json::json!({
                    "id": id, "task": "a1.t2", "status": "fail",
                    "title": {"ja": id, "en": id},
                    "expected": {"ja": "a1.t2.indices に合格する面", "en": "faces that pass a1.t2.indices"},
                    "actual": {"ja": "頂点 V4 はありません", "en": "there is no vertex V4"},
                    "where": null, "cause": {"ja": "", "en": ""}, "hint": {"ja": "", "en": ""},
                }),
            )
        };
        let checks = [failed("a1.t2.closed"), failed("a1.t2.winding"), failed("a1.t2.outward")];
        for (lang, values, same) in [
            (Lang::En, "there is no vertex V4", "(same as above)"),
            (Lang::Ja, "頂点 V4 はありません", "（同上）"),
        ] {
            let text = board_text(&checks, Some("a1.t2"), lang);
            // The progress worded as `cg check` words it.
            let progress =
                Text::new("進み具合: 0/3 個のチェックに合格", "progress: 0/3 checks pass");
            assert!(text.contains(progress.get(lang)), "{text}");
            assert_eq!(text.matches(values).count(), 1, "{text}");
            assert_eq!(text.matches(same).count(), 2, "{text}");
            for c in &checks {
                assert!(text.contains(&c.id), "{text}");
            }
        }
    }
}
