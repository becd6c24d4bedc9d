//! The sandbox against a program that misbehaves on purpose (`cg-sandbox-hostile`, a test
//! fixture of this crate): each way of misbehaving is stopped or contained, and a program that
//! behaves gets its work done.
//!
//! Tests that need bubblewrap are skipped with a note where [`detect`] finds it unusable,
//! unless `CI` is set: CI installs it (scripts/setup.sh) and must run them.

use std::path::{Path, PathBuf};
use std::time::Duration;

use cg_sandbox::{Ended, Isolation, Job, Limits, Run, SandboxError, detect, run};

fn hostile() -> PathBuf {
    PathBuf::from(env!("CARGO_BIN_EXE_cg-sandbox-hostile"))
}

/// A fresh folder, removed at the end of the test.
struct Dir(PathBuf);

impl Dir {
    fn new(name: &str) -> Dir {
        let d = std::env::temp_dir().join(format!("cg-sandbox-test-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        Dir(d.canonicalize().unwrap())
    }
}

impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

fn job(mode: &str, arg: Option<&Path>, workdir: &Dir) -> Job {
    let mut args = vec![mode.to_owned()];
    args.extend(arg.map(|p| p.display().to_string()));
    Job {
        program: hostile(),
        args,
        workdir: workdir.0.clone(),
        read_only: Vec::new(),
        env: Vec::new(),
        ..Job::default()
    }
}

fn limits() -> Limits {
    Limits {
        wall: Duration::from_secs(30),
        memory_bytes: 1 << 30,
        output_bytes: 1 << 20,
        ..Limits::default()
    }
}

/// Whether bubblewrap works here; a note (or, under CI, a failure) when it does not.
fn bubblewrap(test: &str) -> bool {
    if detect() == Isolation::Bubblewrap {
        return true;
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "{test}: bubblewrap does not work on this CI machine (scripts/setup.sh installs it)"
    );
    eprintln!("{test}: skipped, bubblewrap is not usable here");
    false
}

/// The isolations to try a test under: always Limits, and Bubblewrap where it works.
fn isolations(test: &str) -> Vec<Isolation> {
    let mut all = vec![Isolation::Limits];
    if bubblewrap(test) {
        all.push(Isolation::Bubblewrap);
    }
    all
}

fn go(job: &Job, limits: &Limits, isolation: Isolation) -> Run {
    let r = run(job, limits, isolation).unwrap();
    assert_eq!(r.isolation, isolation);
    r
}

#[test]
fn a_program_that_behaves_writes_its_folder_and_is_heard() {
    for iso in isolations("ok") {
        let wd = Dir::new(&format!("ok-{iso:?}"));
        let r = go(&job("ok", None, &wd), &limits(), iso);
        assert_eq!(r.ended, Ended::Exited(0), "{iso:?}: {r:?}");
        assert_eq!(r.stdout, "done\n", "{iso:?}");
        assert!(!r.output_cut);
        // Under bubblewrap the write went to the run's throwaway work folder.
        let kept = std::fs::read_to_string(wd.0.join("result.txt")).ok();
        let expected = (iso == Isolation::Limits).then(|| "fine".to_owned());
        assert_eq!(kept, expected, "{iso:?}");
    }
}

#[test]
fn a_panic_is_exit_status_101_with_its_message() {
    for iso in isolations("panic") {
        let wd = Dir::new(&format!("panic-{iso:?}"));
        let r = go(&job("panic", None, &wd), &limits(), iso);
        assert_eq!(r.ended, Ended::Exited(101), "{iso:?}: {r:?}");
        assert!(r.stderr.contains("hostile: panicking on purpose"), "{iso:?}: {}", r.stderr);
    }
}

#[test]
fn an_endless_loop_is_killed_at_the_wall_clock_limit_and_stays_dead() {
    for iso in isolations("loop") {
        let wd = Dir::new(&format!("loop-{iso:?}"));
        let limits = Limits { wall: Duration::from_secs(1), ..limits() };
        let r = go(&job("loop", None, &wd), &limits, iso);
        assert_eq!(r.ended, Ended::TimedOut, "{iso:?}: {r:?}");
        assert!(r.wall >= Duration::from_secs(1), "{iso:?}: {:?}", r.wall);
        assert!(r.wall < Duration::from_secs(6), "{iso:?}: killed only after {:?}", r.wall);
        // It ran (it printed ticks), and its output was read to the end: nothing it started
        // still holds the pipes.
        assert!(r.stdout.starts_with(".."), "{iso:?}: the loop never ran: {r:?}");
        assert!(!r.output_cut, "{iso:?}: something still holds its output");
        // Nothing ticks after the kill (under bubblewrap the ticks never reach the real folder).
        let ticks = || std::fs::metadata(wd.0.join("ticks")).map_or(0, |m| m.len());
        let before = ticks();
        assert_eq!(before > 0, iso == Isolation::Limits, "{iso:?}: {before} ticks on disk");
        std::thread::sleep(Duration::from_millis(300));
        assert_eq!(ticks(), before, "{iso:?}: still running after the kill");
    }
}

#[test]
fn allocating_without_bound_stops_at_the_memory_limit() {
    for iso in isolations("alloc") {
        let wd = Dir::new(&format!("alloc-{iso:?}"));
        let limits = Limits { memory_bytes: 256 << 20, ..limits() };
        let r = go(&job("alloc", None, &wd), &limits, iso);
        if !cg_sandbox::prlimit_available() {
            eprintln!("alloc: skipped, no prlimit on this machine");
            return;
        }
        assert_ne!(r.ended, Ended::Exited(0), "{iso:?}");
        assert_ne!(r.ended, Ended::TimedOut, "{iso:?}");
        // Rust aborts when an allocation fails.
        assert_eq!(r.ended, Ended::Signalled(6), "{iso:?}: {r:?}");
        assert!(r.stderr.contains("memory allocation"), "{iso:?}: {}", r.stderr);
        let held: Vec<usize> = r
            .stdout
            .lines()
            .filter_map(|l| l.strip_prefix("holding ")?.strip_suffix(" MiB")?.parse().ok())
            .collect();
        let most = held.last().copied().unwrap_or(0);
        assert!(most >= 64, "{iso:?}: stopped too early, at {most} MiB");
        assert!(most < 256, "{iso:?}: held {most} MiB under a 256 MiB limit");
    }
}

#[test]
fn endless_output_is_cut_at_the_limit_and_does_not_block() {
    for iso in isolations("print") {
        let wd = Dir::new(&format!("print-{iso:?}"));
        let r = go(&job("print", None, &wd), &limits(), iso);
        assert_eq!(r.ended, Ended::Exited(0), "{iso:?}: {}", r.stderr.len());
        assert!(r.output_cut, "{iso:?}");
        // 100 MB printed, the first MiB kept; stderr (1 MB) fits whole.
        assert_eq!(r.stdout.len(), 1 << 20, "{iso:?}");
        assert!(r.stdout.bytes().all(|b| b == b'x'));
        assert_eq!(r.stderr.len(), 1_000_000, "{iso:?}");
    }
}

#[test]
fn the_environment_is_only_the_jobs_and_home_is_the_work_folder() {
    for iso in isolations("env") {
        let wd = Dir::new(&format!("env-{iso:?}"));
        let mut j = job("env", None, &wd);
        j.env.push(("CG_GIVEN".into(), "yes".into()));
        let r = go(&j, &limits(), iso);
        assert_eq!(r.ended, Ended::Exited(0), "{iso:?}");
        let vars: Vec<&str> = r.stdout.lines().collect();
        assert!(vars.contains(&"CG_GIVEN=yes"), "{iso:?}: {vars:?}");
        assert!(vars.contains(&format!("HOME={}", wd.0.display()).as_str()), "{iso:?}: {vars:?}");
        // cargo sets these for the test process; the program must not see them.
        assert!(std::env::var_os("CARGO_MANIFEST_DIR").is_some());
        assert!(!vars.iter().any(|v| v.starts_with("CARGO")), "{iso:?}: {vars:?}");
        assert!(!vars.iter().any(|v| v.starts_with("PATH=")), "{iso:?}: {vars:?}");
    }
}

#[test]
fn under_bubblewrap_nothing_outside_the_work_folder_can_be_written() {
    if !bubblewrap("write-outside") {
        return;
    }
    let wd = Dir::new("write-wd");
    let outside = Dir::new("write-outside");
    let target = outside.0.join("escaped.txt");
    let r = go(&job("write-outside", Some(&target), &wd), &limits(), Isolation::Bubblewrap);
    assert!(!target.exists(), "{r:?}");
    assert!(!Path::new("/etc/cg-sandbox-hostile").exists());
    assert!(r.stdout.contains(&format!("denied: {}", target.display())), "{}", r.stdout);
    assert!(r.stdout.contains("denied: /etc/cg-sandbox-hostile"), "{}", r.stdout);
    assert_eq!(r.ended, Ended::Exited(0));

    // /dev is a tmpfs too, with no size: it is read-only (its devices still work).
    let r = go(
        &job("write-outside", Some(Path::new("/dev/shm/x")), &wd),
        &limits(),
        Isolation::Bubblewrap,
    );
    assert!(r.stdout.contains("denied: /dev/shm/x"), "{r:?}");
    assert_eq!(r.ended, Ended::Exited(0), "{r:?}");

    // A read-only folder is readable and not writable.
    let shared = Dir::new("write-ro");
    std::fs::write(shared.0.join("given.txt"), "given").unwrap();
    let mut j = job("read", Some(&shared.0.join("given.txt")), &wd);
    j.read_only.push(shared.0.clone());
    let r = go(&j, &limits(), Isolation::Bubblewrap);
    assert_eq!(r.stdout, "read: given\n", "{r:?}");
    let mut j = job("write-outside", Some(&shared.0.join("given.txt")), &wd);
    j.read_only.push(shared.0.clone());
    let r = go(&j, &limits(), Isolation::Bubblewrap);
    assert!(r.stdout.contains("denied"), "{r:?}");
    assert_eq!(std::fs::read_to_string(shared.0.join("given.txt")).unwrap(), "given");
}

#[test]
fn under_bubblewrap_folders_not_given_cannot_be_read() {
    if !bubblewrap("read") {
        return;
    }
    let wd = Dir::new("read-wd");
    let secret = Dir::new("read-secret");
    std::fs::write(secret.0.join("solution.rs"), "the answer").unwrap();
    let r = go(
        &job("read", Some(&secret.0.join("solution.rs")), &wd),
        &limits(),
        Isolation::Bubblewrap,
    );
    assert_eq!(r.ended, Ended::Exited(1), "{r:?}");
    assert!(!r.stdout.contains("the answer"), "{r:?}");
    assert!(r.stdout.contains("denied"), "{r:?}");
}

#[test]
fn under_bubblewrap_no_other_program_can_be_started() {
    if !bubblewrap("spawn") {
        return;
    }
    let wd = Dir::new("spawn");
    let r = go(&job("spawn", None, &wd), &limits(), Isolation::Bubblewrap);
    assert_eq!(r.ended, Ended::Exited(1), "{r:?}");
    assert!(!r.stdout.contains("spawned"), "{r:?}");
    assert_eq!(r.stdout.matches("spawn failed").count(), 4, "{r:?}");
    // Itself too: its own file is in the sandbox, but no new process may start.
    let me = hostile().canonicalize().unwrap();
    assert!(r.stdout.starts_with(&format!("spawn failed: {}", me.display())), "{r:?}");
}

#[test]
fn threads_still_work_where_processes_do_not() {
    for iso in isolations("threads") {
        let wd = Dir::new(&format!("threads-{iso:?}"));
        let r = go(&job("threads", None, &wd), &limits(), iso);
        assert_eq!(r.ended, Ended::Exited(0), "{iso:?}: {r:?}");
        assert_eq!(r.stdout, "threads: 100\n", "{iso:?}");
    }
}

#[test]
fn under_bubblewrap_there_is_no_network() {
    if !bubblewrap("net") {
        return;
    }
    let wd = Dir::new("net");
    let r = go(&job("net", None, &wd), &limits(), Isolation::Bubblewrap);
    assert_eq!(r.ended, Ended::Exited(1), "{r:?}");
    assert!(r.stdout.starts_with("net failed"), "{r:?}");
}

#[test]
fn what_cannot_be_started_is_an_error_not_a_run() {
    let wd = Dir::new("errors");
    for iso in [Isolation::Limits, Isolation::Bubblewrap] {
        let mut j = job("ok", None, &wd);
        j.program = wd.0.join("no-such-program");
        assert!(matches!(run(&j, &limits(), iso), Err(SandboxError::Start { .. })), "{iso:?}");
        let mut j = job("ok", None, &wd);
        j.workdir = wd.0.join("no-such-folder");
        assert!(matches!(run(&j, &limits(), iso), Err(SandboxError::Start { .. })), "{iso:?}");
        let mut j = job("ok", None, &wd);
        j.read_only.push(wd.0.join("no-such-folder"));
        let e = run(&j, &limits(), iso).unwrap_err();
        // Said in both languages: the grader's Japanese feedback had this English.
        let text = e.text();
        assert!(text.ja.contains("を起動できません: 読み取り専用のフォルダ"), "{text:?}");
        assert!(text.ja.contains("no-such-folder") && !text.ja.contains("read-only"), "{text:?}");
        assert_eq!(text.en, e.to_string());
        assert!(
            text.en.contains("cannot start") && text.en.contains("read-only folder"),
            "{text:?}"
        );
    }
}

/// What a `fill-*` run of the fixture reports: the bytes it wrote, and whether a write failed
/// (with its message) rather than the fixture giving up at its own cap.
fn filled(r: &Run) -> (u64, Option<&str>) {
    let line =
        r.stdout.lines().find(|l| l.starts_with("wrote ")).unwrap_or_else(|| panic!("{r:?}"));
    let bytes = line["wrote ".len()..].split(' ').next().and_then(|b| b.parse().ok());
    (bytes.unwrap_or_else(|| panic!("{r:?}")), line.split_once(", then: ").map(|(_, e)| e))
}

/// The limits for a fill test: the fixture's files (1 MiB each) are far under the per-file
/// limit (`memory_bytes`); the tmpfs are 8 MiB, and the fixture gives up at 64 MiB.
fn fill_limits() -> Limits {
    Limits { memory_bytes: 256 << 20, tmp_bytes: 8 << 20, workdir_bytes: 8 << 20, ..limits() }
}

#[test]
fn under_bubblewrap_filling_tmp_stops_at_its_size() {
    if !bubblewrap("fill-tmp") {
        return;
    }
    let wd = Dir::new("fill-tmp");
    let limits = fill_limits();
    let r = go(&job("fill-tmp", Some(Path::new("64")), &wd), &limits, Isolation::Bubblewrap);
    let (wrote, failed) = filled(&r);
    eprintln!("fill-tmp: {}", r.stdout.trim());
    // The write failed with ENOSPC, after at most the size of /tmp (and most of it: the limit is
    // the tmpfs, not something else that stopped it early).
    assert_eq!(r.ended, Ended::Exited(1), "{r:?}");
    assert!(failed.is_some_and(|e| e.contains("os error 28")), "{r:?}");
    assert!(wrote <= limits.tmp_bytes, "{wrote} bytes in a /tmp of {}", limits.tmp_bytes);
    assert!(wrote >= limits.tmp_bytes / 2, "stopped early: {r:?}");
    // Nothing reached the real /tmp or the work folder.
    assert!(!Path::new("/tmp/cg-sandbox-hostile-fill-0").exists());
    assert_eq!(std::fs::read_dir(&wd.0).unwrap().count(), 0);
}

#[test]
fn under_bubblewrap_filling_the_work_folder_stops_at_its_size() {
    if !bubblewrap("fill-workdir") {
        return;
    }
    let wd = Dir::new("fill-workdir");
    std::fs::write(wd.0.join("given.txt"), "given").unwrap();
    let limits = fill_limits();
    let r = go(&job("fill-workdir", Some(Path::new("64")), &wd), &limits, Isolation::Bubblewrap);
    let (wrote, failed) = filled(&r);
    eprintln!("fill-workdir: {}", r.stdout.trim());
    assert_eq!(r.ended, Ended::Exited(1), "{r:?}");
    assert!(failed.is_some_and(|e| e.contains("os error 28")), "{r:?}");
    assert!(wrote <= limits.workdir_bytes, "{wrote} bytes in a folder of {}", limits.workdir_bytes);
    assert!(wrote >= limits.workdir_bytes / 2, "stopped early: {r:?}");
    // Many files, each far under the per-file limit: only the total stopped it.
    let files: u64 =
        r.stdout.split(" in ").nth(1).and_then(|t| t.split(' ').next()?.parse().ok()).unwrap_or(0);
    assert!(files >= 8, "{r:?}");
    // None of it reached the disk: the real folder holds what it held.
    let names: Vec<_> = std::fs::read_dir(&wd.0).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names, ["given.txt"]);
    assert_eq!(std::fs::read_to_string(wd.0.join("given.txt")).unwrap(), "given");
}

#[test]
fn under_bubblewrap_the_work_folder_holds_its_inputs_read_only() {
    if !bubblewrap("inputs") {
        return;
    }
    let wd = Dir::new("inputs");
    std::fs::create_dir_all(wd.0.join("exercises")).unwrap();
    std::fs::write(wd.0.join("exercises/student.toml"), "id = 1").unwrap();
    std::os::unix::fs::symlink("exercises/student.toml", wd.0.join("link")).unwrap();
    let inside = |rel: &str| wd.0.join(rel);
    // Readable, also through a link (recreated as a link, resolved inside).
    for rel in ["exercises/student.toml", "link"] {
        let r = go(&job("read", Some(&inside(rel)), &wd), &limits(), Isolation::Bubblewrap);
        assert_eq!(r.stdout, "read: id = 1\n", "{rel}: {r:?}");
    }
    // Not writable, nor is a folder it held; a new file beside them is (and is dropped).
    for rel in ["exercises/student.toml", "exercises/new.txt"] {
        let r =
            go(&job("write-outside", Some(&inside(rel)), &wd), &limits(), Isolation::Bubblewrap);
        assert!(r.stdout.contains(&format!("denied: {}", inside(rel).display())), "{r:?}");
    }
    let r =
        go(&job("write-outside", Some(&inside("new.txt")), &wd), &limits(), Isolation::Bubblewrap);
    assert!(r.stdout.contains(&format!("written: {}", inside("new.txt").display())), "{r:?}");
    assert_eq!(std::fs::read_to_string(inside("exercises/student.toml")).unwrap(), "id = 1");
    assert!(!inside("new.txt").exists());
    assert!(!inside("exercises/new.txt").exists());
}
