//! # cg-sandbox — running a submission that must not be trusted
//!
//! [`run`] starts a program with a wall-clock limit (the whole process group is killed when it
//! runs over), a memory limit, a limit on what it prints, no network, a file system that is
//! read-only except for its work folder and `/tmp`, both of a fixed size, and nothing else to
//! start. How much of that the machine can enforce is [`Isolation`]: [`detect`] picks the
//! strongest available and [`Isolation::describe`] says what it does and does not enforce.
//!
//! ## How
//!
//! - **Limits** come from `prlimit` (util-linux) around the whole run: address space
//!   ([`Limits::memory_bytes`]), the size of a file it writes (the same number), no core
//!   dumps. rlimits are inherited, so under bubblewrap `prlimit` wraps `bwrap` itself and the
//!   sandbox holds no tool at all. Without `prlimit` (not a Debian/Ubuntu system) only the wall
//!   clock and the output limit hold: [`prlimit_available`] tells.
//! - **What it writes**: under bubblewrap every writable place is a tmpfs of a fixed size —
//!   the private `/tmp` ([`Limits::tmp_bytes`]) and the work folder ([`Limits::workdir_bytes`])
//!   — so a write past it fails with `ENOSPC`. A tmpfs lives in memory but outside the address
//!   space `RLIMIT_AS` counts: a run holds at most `memory_bytes + tmp_bytes + workdir_bytes` of
//!   the machine's memory, and nothing on its disk. Under [`Isolation::Limits`] the program
//!   writes the real work folder and `/tmp`: each file is bounded (`RLIMIT_FSIZE`), the total is
//!   not.
//! - **Wall clock**: the run starts in its own process group; past [`Limits::wall`] the group is
//!   killed (`kill -KILL -PGID`, and the leader through [`std::process::Child::kill`]). Under
//!   bubblewrap the program also lives in its own PID namespace that dies with `bwrap`
//!   (`--die-with-parent`), so nothing it started survives.
//! - **Output**: stdout and stderr are read on threads; [`Limits::output_bytes`] of each are
//!   kept, the rest is read and dropped ([`Run::output_cut`]), so a program that prints without
//!   end cannot block on a full pipe or fill the memory of the grader.
//! - **Bubblewrap** ([`Isolation::Bubblewrap`]): a new root holding only `/lib*` and
//!   `/usr/lib*` (read-only: the dynamic loader and the libraries), the program (read-only),
//!   [`Job::read_only`] (read-only), [`Job::workdir`] (writable, see below), a private `/tmp`,
//!   a minimal read-only `/dev` (its devices still work), no `/proc`; the root itself is
//!   read-only. The private `/tmp` is a throwaway tmpfs of [`Limits::tmp_bytes`]: when a bound
//!   folder lies under `/tmp` its parents exist there too and a write into them succeeds inside
//!   the sandbox but never reaches the real file system. The work folder is a throwaway tmpfs
//!   of [`Limits::workdir_bytes`] too, with each entry the real folder held when the run
//!   started bound into it read-only (a symbolic link recreated as the link it is): the program
//!   reads its inputs and writes new files beside them, and none of its writes reach the real
//!   folder. (The inputs are bound, not copied: they cost no room in the tmpfs and no file
//!   descriptors to hand to `bwrap`, and the program cannot change them.) `bwrap` older than
//!   0.5 has no `--size`, fails [`detect`]'s trial run and gives [`Isolation::Limits`]. No
//!   `/bin`, `/usr/bin` or `/sbin`: there is no shell or other tool to start. Every namespace
//!   is new (no network: only a loopback without addresses), the user inside is `nobody`
//!   (65534) with no capabilities, a new session (no terminal), and the environment is only
//!   [`Job::env`] plus `HOME`. A seccomp filter lets it start threads but no process (not even
//!   a copy of itself, whose file is in the sandbox): `fork`, `vfork` and `clone` without
//!   `CLONE_THREAD` fail (x86_64 and aarch64; elsewhere no filter). The filter reaches `bwrap`
//!   on the program's stdin, so the program finds its stdin closed.
//!
//! Not limited: the number of threads, and CPU time beyond the wall clock (a program may keep
//! every core busy until it is killed); the number of files it creates in its tmpfs (each empty
//! file costs the kernel memory, about a kilobyte, that no size counts, until the run ends);
//! under [`Isolation::Limits`], processes the program starts, other than through the process
//! group, which is killed, and the total it writes to disk (only each file is bounded).
//!
//! ## Environment
//!
//! The program gets [`Job::env`], plus `HOME` = the work folder and `MALLOC_ARENA_MAX=2` unless
//! the job sets them. The latter keeps glibc from reserving 64 MiB of address space per thread
//! arena, which would count against the memory limit for a multi-threaded program that uses
//! little memory.
//!
//! ## Exit status under bubblewrap
//!
//! `bwrap` reports a program killed by signal *n* as the exit status 128 + *n*; [`run`] reads
//! 129 to 192 back as [`Ended::Signalled`] (a program that calls `exit(134)` itself is taken
//! for one killed by signal 6).

use std::ffi::OsString;
use std::io::{Read, Write};
#[cfg(unix)]
use std::os::unix::process::CommandExt;
use std::path::{Path, PathBuf};
use std::process::{Command, ExitStatus, Stdio};
use std::sync::OnceLock;
use std::sync::mpsc;
use std::time::{Duration, Instant};

use cg_core::lang::{Lang, Text, t};

/// How strongly a run is isolated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Isolation {
    /// bubblewrap: read-only root with only the program and its libraries, a sized throwaway
    /// work folder and private /tmp, no network, own PID namespace, no new processes (seccomp);
    /// plus the rlimits.
    Bubblewrap,
    /// rlimits only (prlimit): time, memory, file size (each file; the total written is not
    /// bounded); no file-system or network isolation.
    /// Without `prlimit` on the machine, only the wall clock and the output limit
    /// ([`prlimit_available`]).
    Limits,
}

impl Isolation {
    /// What this isolation enforces and what it does not, in `lang`.
    #[must_use]
    pub fn describe(self, lang: Lang) -> String {
        match self {
            Isolation::Bubblewrap => t(
                "bubblewrap: 時間・メモリ・出力の制限、ネットワークなし、書き込みは容量制限つきの使い捨ての作業フォルダと /tmp のみ、ほかのプログラムは起動不可",
                "bubblewrap: time, memory and output limits, no network, writes only to a throwaway work folder and /tmp of limited size, no other programs to start",
            ).get(lang)
                .to_owned(),
            Isolation::Limits => t(
                "制限のみ（bubblewrap が使えません）: 時間・メモリ・出力の制限（書き込みはファイル1つずつの大きさのみ制限し、合計は制限なし）。ファイルとネットワークは隔離されません",
                "limits only (bubblewrap is not available): time, memory and output limits (the size of each file written, not their total); files and network are NOT isolated",
            ).get(lang)
                .to_owned(),
        }
    }
}

/// The strongest isolation this machine offers, checked by running `/bin/true` under
/// bubblewrap exactly as [`run`] would (bubblewrap present but not allowed to create
/// namespaces, as in many containers, gives [`Isolation::Limits`]). The answer is computed once
/// per process and then remembered.
#[must_use]
pub fn detect() -> Isolation {
    static DETECTED: OnceLock<Isolation> = OnceLock::new();
    *DETECTED
        .get_or_init(|| if bubblewrap_works() { Isolation::Bubblewrap } else { Isolation::Limits })
}

/// Whether `prlimit` (util-linux) is on this machine, i.e. whether the memory and file-size
/// limits are enforced. Without it, only the wall clock and the output limit hold.
#[must_use]
pub fn prlimit_available() -> bool {
    tool("prlimit").is_some()
}

/// Runs `/bin/true` under bubblewrap in a fresh empty folder.
fn bubblewrap_works() -> bool {
    if tool("bwrap").is_none() {
        return false;
    }
    let Some(program) =
        ["/bin/true", "/usr/bin/true"].into_iter().map(PathBuf::from).find(|p| p.is_file())
    else {
        return false;
    };
    let Ok(workdir) = fresh_dir("detect") else {
        return false;
    };
    let job = Job {
        program,
        args: Vec::new(),
        workdir: workdir.clone(),
        read_only: Vec::new(),
        env: Vec::new(),
        ..Job::default()
    };
    let limits = Limits { wall: Duration::from_secs(20), ..Limits::default() };
    let ok = matches!(
        run(&job, &limits, Isolation::Bubblewrap),
        Ok(Run { ended: Ended::Exited(0), .. })
    );
    let _ = std::fs::remove_dir_all(&workdir);
    ok
}

/// A new empty folder under the system's temporary folder.
fn fresh_dir(what: &str) -> std::io::Result<PathBuf> {
    static COUNT: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let n = COUNT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("cg-sandbox-{what}-{}-{n}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir)?;
    Ok(dir)
}

/// A system tool by name: the first executable file of that name on `PATH`, then in the usual
/// system folders (a grader started with an empty `PATH` still finds them).
fn tool(name: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH").unwrap_or_default();
    std::env::split_paths(&path)
        .chain(
            ["/usr/bin", "/bin", "/usr/sbin", "/sbin", "/usr/local/bin"]
                .into_iter()
                .map(PathBuf::from),
        )
        .filter(|d| d.is_absolute())
        .map(|d| d.join(name))
        .find(|p| p.is_file())
}

/// What a run may do.
///
/// Under [`Isolation::Bubblewrap`] a run holds at most `memory_bytes + tmp_bytes +
/// workdir_bytes` of the machine's memory: its address space, plus its private `/tmp` and its
/// work folder, two tmpfs that live in memory but outside the address space (the sizes are not
/// taken out of `memory_bytes`). It writes nothing to the disk.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Wall-clock time; the process group is killed after it.
    pub wall: Duration,
    /// Address space in bytes (`RLIMIT_AS`). Also the largest file the program may write
    /// (`RLIMIT_FSIZE`; a write beyond it fails, or `SIGXFSZ` ends the program).
    pub memory_bytes: u64,
    /// Bytes of stdout and of stderr kept; the rest is dropped (and the run marked).
    pub output_bytes: usize,
    /// Under bubblewrap, the size of the private `/tmp` (a tmpfs): a write past it fails with
    /// `ENOSPC`. Held in memory, on top of `memory_bytes`. 0 is taken as one page. Under
    /// [`Isolation::Limits`], `/tmp` is the machine's and not bounded in total.
    pub tmp_bytes: u64,
    /// Under bubblewrap, the size of the work folder (a tmpfs over [`Job::workdir`]; what the
    /// folder held before the run is bound into it read-only and does not count): a write past
    /// it fails with `ENOSPC`. Held in memory, on top of `memory_bytes`. 0 is taken as one page.
    /// Under [`Isolation::Limits`], the work folder is the real one, on disk, and only each file
    /// is bounded (by `memory_bytes`), not the total.
    pub workdir_bytes: u64,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits {
            wall: Duration::from_secs(60),
            memory_bytes: 2 << 30,
            output_bytes: 4 << 20,
            tmp_bytes: 64 << 20,
            workdir_bytes: 64 << 20,
        }
    }
}

/// A folder seen inside the sandbox at another place than its own (bubblewrap only).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Bind {
    /// The folder.
    pub from: PathBuf,
    /// Where the program sees it.
    pub to: PathBuf,
    /// Whether the program may write it (its writes reach the real folder).
    pub writable: bool,
}

/// What to run.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Job {
    /// The program (an absolute path; under bubblewrap it is bound read-only).
    pub program: PathBuf,
    /// Its arguments.
    pub args: Vec<String>,
    /// Its working folder (writable). Under bubblewrap the program sees a throwaway tmpfs of
    /// [`Limits::workdir_bytes`] here, with what the folder holds when the run starts bound into
    /// it read-only: it reads its inputs and writes new files, and what it writes is dropped at
    /// the end of the run (only stdout and stderr come back). Under [`Isolation::Limits`] it is
    /// the real folder and the writes stay.
    pub workdir: PathBuf,
    /// Other folders it may read (read-only), besides the program and the system libraries.
    pub read_only: Vec<PathBuf>,
    /// Environment variables it gets (nothing else is inherited but PATH-free basics).
    pub env: Vec<(String, String)>,
    /// Folders bound in at other places, or writable (bubblewrap only; ignored under
    /// [`Isolation::Limits`], where the program sees the real file system).
    pub binds: Vec<Bind>,
    /// A compiler's run (cargo, rustc and the linker): it may start processes (no seccomp
    /// filter), and sees `/usr` and `/etc/alternatives` (read-only: the C compiler and linker)
    /// and its own `/proc`.
    pub compiler: bool,
}

/// How a run ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Ended {
    /// It exited with this status.
    Exited(i32),
    /// A signal ended it (e.g. 9 after the memory limit, 6 on abort).
    Signalled(i32),
    /// It ran over the wall-clock limit and was killed.
    TimedOut,
}

/// A finished run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Run {
    /// How it ended.
    pub ended: Ended,
    /// What it printed (at most `Limits::output_bytes`).
    pub stdout: String,
    /// What it printed on stderr (at most `Limits::output_bytes`).
    pub stderr: String,
    /// Whether output was cut at the limit.
    pub output_cut: bool,
    /// How long it ran.
    pub wall: Duration,
    /// The isolation it ran under.
    pub isolation: Isolation,
}

/// Why a run could not be started.
#[derive(Debug, thiserror::Error)]
pub enum SandboxError {
    /// The program or a helper tool could not be started.
    #[error("cannot start {program}: {}", why.en)]
    Start {
        /// What was started.
        program: String,
        /// Why it failed, in both languages.
        why: Text,
    },
}

impl SandboxError {
    /// The error in both languages (its `Display` is the English).
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            SandboxError::Start { program, why } => Text::new(
                format!("{program} を起動できません: {}", why.ja),
                format!("cannot start {program}: {}", why.en),
            ),
        }
    }
}

/// A [`SandboxError::Start`] for `program`.
fn start_error(program: &Path, why: Text) -> SandboxError {
    SandboxError::Start { program: program.display().to_string(), why }
}

/// The folders of the dynamic loader and the system libraries, bound read-only under
/// bubblewrap (or recreated as the symbolic links they are, on a merged-`/usr` system).
const LIBRARY_DIRS: [&str; 8] =
    ["/lib", "/lib64", "/lib32", "/libx32", "/usr/lib", "/usr/lib64", "/usr/lib32", "/usr/libx32"];

/// How long [`run`] waits for the output of a finished program when something it started
/// outside the process group still holds its pipes (possible only under [`Isolation::Limits`]).
const OUTPUT_GRACE: Duration = Duration::from_millis(500);

/// The command line of `job` under `limits` with `isolation` (see [`run`]'s errors).
fn prepare(job: &Job, limits: &Limits, isolation: Isolation) -> Result<Prepared, SandboxError> {
    let program = job.program.canonicalize().ok().filter(|p| p.is_file()).ok_or_else(|| {
        start_error(&job.program, t("プログラムのファイルがありません", "no such program file"))
    })?;
    let workdir = job.workdir.canonicalize().ok().filter(|p| p.is_dir()).ok_or_else(|| {
        let shown = job.workdir.display();
        start_error(
            &job.program,
            Text::new(
                format!("作業フォルダ {shown} がありません"),
                format!("no work folder {shown}"),
            ),
        )
    })?;
    let mut read_only = Vec::new();
    for dir in &job.read_only {
        let canon = dir.canonicalize().map_err(|e| {
            let why = Text::io_at(dir, &e);
            start_error(
                &job.program,
                Text::new(
                    format!("読み取り専用のフォルダ {}", why.ja),
                    format!("read-only folder {}", why.en),
                ),
            )
        })?;
        read_only.push(canon);
    }
    let mut env = job.env.clone();
    for (key, value) in
        [("HOME", workdir.display().to_string()), ("MALLOC_ARENA_MAX", "2".to_owned())]
    {
        if !env.iter().any(|(k, _)| k == key) {
            env.push((key.to_owned(), value));
        }
    }

    // prlimit first: its limits are inherited by bwrap and by everything inside.
    let mut argv: Vec<OsString> = Vec::new();
    if let Some(prlimit) = tool("prlimit") {
        argv.push(prlimit.into());
        argv.push(format!("--as={}", limits.memory_bytes).into());
        argv.push(format!("--fsize={}", limits.memory_bytes).into());
        argv.push("--core=0".into());
        argv.push("--".into());
    }
    match isolation {
        Isolation::Bubblewrap => {
            let bwrap = tool("bwrap").ok_or_else(|| {
                start_error(
                    &job.program,
                    t("bwrap（bubblewrap）が入っていません", "bwrap (bubblewrap) is not installed"),
                )
            })?;
            let inputs = inputs(&workdir).map_err(|e| {
                let why = Text::io_at(&workdir, &e);
                start_error(
                    &job.program,
                    Text::new(
                        format!("作業フォルダ {}", why.ja),
                        format!("work folder {}", why.en),
                    ),
                )
            })?;
            argv.push(bwrap.into());
            let extra = extra_bwrap_args(job);
            argv.extend(bwrap_args(&program, &workdir, &inputs, &read_only, &env, limits, &extra));
            if !job.compiler && no_new_processes_filter().is_some() {
                argv.extend(["--seccomp".into(), "0".into()]);
            }
            argv.push("--".into());
            argv.push(program.clone().into());
        }
        Isolation::Limits => argv.push(program.clone().into()),
    }
    argv.extend(job.args.iter().map(OsString::from));

    let filter = match isolation {
        Isolation::Bubblewrap if !job.compiler => no_new_processes_filter(),
        Isolation::Bubblewrap | Isolation::Limits => None,
    };
    Ok(Prepared { argv, workdir, env, filter })
}

/// A long-lived program's command line in the sandbox, for a caller that speaks to it over its
/// stdin and stdout (the worker of the student's functions, `cg-worker`): the same walls as
/// [`run`] (`prlimit`, bubblewrap, the seccomp filter), with stdin left to the caller. Start it
/// with the environment cleared and [`Launch::env`] set; stop it by killing it (bubblewrap
/// takes down everything inside with it, `--die-with-parent`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Launch {
    /// The program to start.
    pub program: PathBuf,
    /// Its arguments.
    pub args: Vec<OsString>,
    /// Its whole environment.
    pub env: Vec<(String, String)>,
    /// The folder to start it in.
    pub workdir: PathBuf,
}

/// `job` under `limits` with `isolation`, as a [`Launch`]. The wall clock is the caller's
/// ([`Limits::wall`] is not applied here), and so is the output. Under bubblewrap the seccomp
/// filter goes to `bwrap` through a file, `<workdir>.seccomp`, opened on file descriptor 3 by
/// `/bin/sh` (`exec … 3<file`), so the program's stdin is free.
///
/// # Errors
/// As [`run`], or the filter's file could not be written.
pub fn launch(job: &Job, limits: &Limits, isolation: Isolation) -> Result<Launch, SandboxError> {
    let Prepared { mut argv, workdir, env, filter } = prepare(job, limits, isolation)?;
    let Some(filter) = filter else {
        let program = PathBuf::from(argv.remove(0));
        return Ok(Launch { program, args: argv, env, workdir });
    };
    let file = workdir.with_extension("seccomp");
    std::fs::write(&file, filter).map_err(|e| start_error(&job.program, Text::io_at(&file, &e)))?;
    if let Some(i) = argv.windows(2).position(|w| w[0] == "--seccomp" && w[1] == "0") {
        argv[i + 1] = "3".into();
    }
    let mut args: Vec<OsString> =
        vec!["-c".into(), "exec \"$@\" 3<\"$0\"".into(), file.into_os_string()];
    args.extend(argv);
    Ok(Launch { program: PathBuf::from("/bin/sh"), args, env, workdir })
}

/// A run's command line, before it starts.
struct Prepared {
    /// The program (`prlimit`, `bwrap` or the job's program) and its arguments.
    argv: Vec<OsString>,
    /// The work folder, canonical.
    workdir: PathBuf,
    /// The environment (nothing else is inherited).
    env: Vec<(String, String)>,
    /// The seccomp filter `bwrap --seccomp 0` reads on its stdin, when there is one.
    filter: Option<Vec<u8>>,
}

/// Runs `job` under `limits` with `isolation`.
///
/// The program's stdin is empty (closed under bubblewrap); its stdout and stderr are captured (up to
/// [`Limits::output_bytes`] each). Returns once the program has ended (or was killed at the
/// wall-clock limit) and its output is read.
///
/// # Errors
/// The program could not be started at all: it is not a file, the work folder or a read-only
/// folder does not exist, or `bwrap` (for [`Isolation::Bubblewrap`]) is missing.
pub fn run(job: &Job, limits: &Limits, isolation: Isolation) -> Result<Run, SandboxError> {
    let Prepared { argv, workdir, env, filter } = prepare(job, limits, isolation)?;
    let mut command = Command::new(&argv[0]);
    command
        .args(&argv[1..])
        .current_dir(&workdir)
        .env_clear()
        .envs(env.iter().map(|(k, v)| (k, v)))
        .stdin(if filter.is_some() { Stdio::piped() } else { Stdio::null() })
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // Its own process group, so a time-out kills what it started too (Unix; elsewhere the
    // program alone: only a student's own `check` runs there, never grading).
    #[cfg(unix)]
    command.process_group(0);
    let started = Instant::now();
    let mut child = command
        .spawn()
        .map_err(|e| start_error(&job.program, Text::io_at(Path::new(&argv[0]), &e)))?;
    if let (Some(filter), Some(mut stdin)) = (filter, child.stdin.take()) {
        // bwrap reads it whole (`--seccomp 0`) before it starts the program; a few hundred
        // bytes fit in the pipe, so this does not block.
        let _ = stdin.write_all(&filter);
    }
    let cap = limits.output_bytes;
    let stdout = child.stdout.take().map(|r| reader(r, cap));
    let stderr = child.stderr.take().map(|r| reader(r, cap));

    let deadline = started + limits.wall;
    let mut pause = Duration::from_millis(1);
    let (status, timed_out) = loop {
        match child.try_wait() {
            Ok(Some(status)) => break (Some(status), false),
            Ok(None) => {}
            Err(_) => break (None, false),
        }
        let now = Instant::now();
        if now >= deadline {
            // The leader is not reaped yet, so its group ID cannot have been reused.
            kill_group(child.id());
            let _ = child.kill();
            break (child.wait().ok(), true);
        }
        std::thread::sleep(pause.min(deadline - now));
        pause = (pause * 2).min(Duration::from_millis(20));
    };
    let wall = started.elapsed();
    // Anything left in the group (under Limits: children it started) goes too; it would
    // otherwise keep the pipes open.
    kill_group(child.id());

    let grace = Instant::now() + OUTPUT_GRACE;
    let (stdout, cut_out) = collect(stdout, grace);
    let (stderr, cut_err) = collect(stderr, grace);
    let ended = if timed_out {
        Ended::TimedOut
    } else {
        match status {
            Some(status) => ended(status, isolation),
            None => Ended::Signalled(9),
        }
    };
    Ok(Run { ended, stdout, stderr, output_cut: cut_out || cut_err, wall, isolation })
}

/// What the work folder holds when a run starts: each entry, with the target of those that are
/// symbolic links (recreated as links under bubblewrap, not followed), sorted by name.
fn inputs(workdir: &Path) -> std::io::Result<Vec<(PathBuf, Option<PathBuf>)>> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(workdir)? {
        let path = entry?.path();
        let link = if std::fs::symlink_metadata(&path)?.file_type().is_symlink() {
            Some(std::fs::read_link(&path)?)
        } else {
            None
        };
        found.push((path, link));
    }
    found.sort();
    Ok(found)
}

/// A size for `bwrap --size`, which refuses 0 (the tmpfs rounds it up to a page).
fn tmpfs_size(bytes: u64) -> OsString {
    bytes.max(1).to_string().into()
}

/// The arguments of `bwrap` for one run (without the final `-- program args`): `inputs` is what
/// the work folder holds ([`inputs`]).
fn bwrap_args(
    program: &Path,
    workdir: &Path,
    inputs: &[(PathBuf, Option<PathBuf>)],
    read_only: &[PathBuf],
    env: &[(String, String)],
    limits: &Limits,
    extra: &[OsString],
) -> Vec<OsString> {
    let mut a: Vec<OsString> = Vec::new();
    let mut push = |items: &[&std::ffi::OsStr]| a.extend(items.iter().map(|s| s.to_os_string()));
    push(&[
        "--unshare-all".as_ref(),
        "--unshare-user".as_ref(),
        "--uid".as_ref(),
        "65534".as_ref(),
        "--gid".as_ref(),
        "65534".as_ref(),
        "--cap-drop".as_ref(),
        "ALL".as_ref(),
        "--die-with-parent".as_ref(),
        "--new-session".as_ref(),
        "--clearenv".as_ref(),
    ]);
    for dir in LIBRARY_DIRS {
        let path = Path::new(dir);
        match std::fs::symlink_metadata(path) {
            Ok(m) if m.file_type().is_symlink() => {
                if let Ok(target) = std::fs::read_link(path) {
                    push(&["--symlink".as_ref(), target.as_os_str(), path.as_os_str()]);
                }
            }
            Ok(m) if m.is_dir() => {
                push(&["--ro-bind".as_ref(), path.as_os_str(), path.as_os_str()])
            }
            _ => {}
        }
    }
    // Every writable place is a sized tmpfs: /tmp and the work folder. /dev (also a tmpfs, with
    // no size) is made read-only; its devices stay usable.
    let tmp_size = tmpfs_size(limits.tmp_bytes);
    push(&["--size".as_ref(), tmp_size.as_os_str(), "--tmpfs".as_ref(), "/tmp".as_ref()]);
    push(&["--dev".as_ref(), "/dev".as_ref(), "--remount-ro".as_ref(), "/dev".as_ref()]);
    // Outer folders first, so that a folder inside another is mounted over it, not hidden by it;
    // the work folder's tmpfs before what it held, which is bound into it.
    enum Mount<'a> {
        ReadOnly,
        Work,
        Link(&'a Path),
    }
    let mut mounts: Vec<(&Path, Mount)> =
        read_only.iter().map(|p| (p.as_path(), Mount::ReadOnly)).collect();
    mounts.push((workdir, Mount::Work));
    mounts.extend(inputs.iter().map(|(path, link)| {
        (path.as_path(), link.as_deref().map_or(Mount::ReadOnly, Mount::Link))
    }));
    mounts.sort_by_key(|(p, _)| p.components().count());
    let work_size = tmpfs_size(limits.workdir_bytes);
    for (path, how) in mounts {
        match how {
            Mount::ReadOnly => push(&["--ro-bind".as_ref(), path.as_os_str(), path.as_os_str()]),
            Mount::Work => push(&[
                "--size".as_ref(),
                work_size.as_os_str(),
                "--tmpfs".as_ref(),
                path.as_os_str(),
            ]),
            Mount::Link(target) => {
                push(&["--symlink".as_ref(), target.as_os_str(), path.as_os_str()])
            }
        }
    }
    push(&["--ro-bind".as_ref(), program.as_os_str(), program.as_os_str()]);
    push(&["--chdir".as_ref(), workdir.as_os_str()]);
    for (k, v) in env {
        push(&["--setenv".as_ref(), k.as_ref(), v.as_ref()]);
    }
    a.extend(extra.iter().cloned());
    a.push("--remount-ro".into());
    a.push("/".into());
    a
}

/// What a job adds to bubblewrap's mounts (before the root is made read-only): for a compiler,
/// `/usr`, `/bin`, `/sbin` and `/etc/alternatives` read-only and its own `/proc`; then its [`Job::binds`], outer ones
/// first, each read-only unless writable.
fn extra_bwrap_args(job: &Job) -> Vec<OsString> {
    let mut a: Vec<OsString> = Vec::new();
    if job.compiler {
        for dir in ["/usr", "/bin", "/sbin"] {
            let path = Path::new(dir);
            match std::fs::symlink_metadata(path) {
                Ok(m) if m.file_type().is_symlink() => {
                    if let Ok(target) = std::fs::read_link(path) {
                        a.extend(["--symlink".into(), target.into_os_string(), dir.into()]);
                    }
                }
                Ok(m) if m.is_dir() => a.extend(["--ro-bind".into(), dir.into(), dir.into()]),
                _ => {}
            }
        }
        // Debian's `cc` and `ld` are links through /etc/alternatives (only that of /etc).
        if Path::new("/etc/alternatives").is_dir() {
            a.extend(["--ro-bind".into(), "/etc/alternatives".into(), "/etc/alternatives".into()]);
        }
        a.extend(["--proc".into(), "/proc".into()]);
    }
    let mut binds: Vec<&Bind> = job.binds.iter().collect();
    binds.sort_by_key(|b| b.to.components().count());
    for b in binds {
        let how = if b.writable { "--bind" } else { "--ro-bind" };
        a.extend([how.into(), b.from.clone().into_os_string(), b.to.clone().into_os_string()]);
    }
    a
}

/// The system call numbers and audit architecture the filter of
/// [`no_new_processes_filter`] needs: `(arch, clone, clone3, [fork, vfork])`.
#[cfg(target_arch = "x86_64")]
const SYSCALLS: Option<(u32, u32, u32, &[u32])> = Some((0xC000_003E, 56, 435, &[57, 58]));
#[cfg(target_arch = "aarch64")]
const SYSCALLS: Option<(u32, u32, u32, &[u32])> = Some((0xC000_00B7, 220, 435, &[]));
#[cfg(not(any(target_arch = "x86_64", target_arch = "aarch64")))]
const SYSCALLS: Option<(u32, u32, u32, &[u32])> = None;

/// A seccomp program (classic BPF, as `bwrap --seccomp` reads it) that lets the program start
/// threads but no processes: `clone` without `CLONE_THREAD`, `fork` and `vfork` fail with
/// `EPERM`, `clone3` with `ENOSYS` (glibc then falls back to `clone`, whose flags the filter can
/// read); a system call of another architecture ends the program. Without it, a program could
/// start copies of itself (its own file is in the sandbox, so it can be executed), say a fork
/// bomb. `None` on architectures the filter does not know (then only bubblewrap's other walls
/// hold).
fn no_new_processes_filter() -> Option<Vec<u8>> {
    const LD_W_ABS: u16 = 0x20;
    const JEQ_K: u16 = 0x15;
    const JGE_K: u16 = 0x35;
    const JSET_K: u16 = 0x45;
    const RET_K: u16 = 0x06;
    const ALLOW: u32 = 0x7fff_0000;
    const KILL_PROCESS: u32 = 0x8000_0000;
    const EPERM: u32 = 0x0005_0000 | 1;
    const ENOSYS: u32 = 0x0005_0000 | 38;
    const CLONE_THREAD: u32 = 0x0001_0000;
    // x32 system calls on x86_64 carry this bit; none is allowed.
    const X32_BIT: u32 = 0x4000_0000;
    let (arch, clone, clone3, forks) = SYSCALLS?;
    // (code, jump if true, jump if false, k); jumps count the instructions skipped.
    let mut p: Vec<(u16, u8, u8, u32)> = vec![
        (LD_W_ABS, 0, 0, 4), // seccomp_data.arch
        (JEQ_K, 1, 0, arch),
        (RET_K, 0, 0, KILL_PROCESS),
        (LD_W_ABS, 0, 0, 0), // seccomp_data.nr
        (JGE_K, 0, 1, X32_BIT),
        (RET_K, 0, 0, EPERM),
        (JEQ_K, 0, 1, clone3),
        (RET_K, 0, 0, ENOSYS),
    ];
    for &nr in forks {
        p.push((JEQ_K, 0, 1, nr));
        p.push((RET_K, 0, 0, EPERM));
    }
    p.extend([
        (JEQ_K, 0, 3, clone),
        (LD_W_ABS, 0, 0, 16), // the low half of seccomp_data.args[0]: clone's flags
        (JSET_K, 1, 0, CLONE_THREAD),
        (RET_K, 0, 0, EPERM),
        (RET_K, 0, 0, ALLOW),
    ]);
    let mut bytes = Vec::with_capacity(p.len() * 8);
    for (code, jt, jf, k) in p {
        bytes.extend_from_slice(&code.to_ne_bytes());
        bytes.extend([jt, jf]);
        bytes.extend_from_slice(&k.to_ne_bytes());
    }
    Some(bytes)
}

/// Kills the process group `pgid` with the `kill` tool (std has no safe `killpg`).
fn kill_group(pgid: u32) {
    if let Some(kill) = tool("kill") {
        let _ = Command::new(kill)
            .args(["-KILL", "--", &format!("-{pgid}")])
            .stdin(Stdio::null())
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .status();
    }
}

/// How a finished program's status reads.
fn ended(status: ExitStatus, isolation: Isolation) -> Ended {
    #[cfg(unix)]
    if let Some(signal) = std::os::unix::process::ExitStatusExt::signal(&status) {
        return Ended::Signalled(signal);
    }
    match (status.code(), isolation) {
        (Some(code @ 129..=192), Isolation::Bubblewrap) => Ended::Signalled(code - 128),
        (Some(code), _) => Ended::Exited(code),
        (None, _) => Ended::Signalled(9),
    }
}

/// What a reader thread hands back: the bytes kept and whether some were dropped.
type Captured = (Vec<u8>, bool);

/// Reads `r` to its end on a thread, keeping the first `cap` bytes.
fn reader(mut r: impl Read + Send + 'static, cap: usize) -> mpsc::Receiver<Captured> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let mut kept = Vec::new();
        let mut cut = false;
        let mut buf = vec![0u8; 64 << 10];
        loop {
            match r.read(&mut buf) {
                Ok(0) => break,
                Ok(n) => {
                    let room = cap.saturating_sub(kept.len());
                    if n > room {
                        cut = true;
                    }
                    kept.extend_from_slice(&buf[..n.min(room)]);
                }
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(_) => break,
            }
        }
        let _ = tx.send((kept, cut));
    });
    rx
}

/// The output of a reader, waiting for it until `until` at most; text at most `cap` bytes.
fn collect(rx: Option<mpsc::Receiver<Captured>>, until: Instant) -> (String, bool) {
    let Some(rx) = rx else {
        return (String::new(), false);
    };
    let wait = until.saturating_duration_since(Instant::now());
    match rx.recv_timeout(wait) {
        Ok((bytes, cut)) => text(bytes, cut),
        // Still held open by something outside the group: what it kept is lost with it.
        Err(_) => (String::new(), true),
    }
}

/// Bytes as text of at most as many bytes: a character cut at the end is dropped, invalid
/// bytes become U+FFFD (and the text is cut again if that made it longer).
fn text(mut bytes: Vec<u8>, mut cut: bool) -> (String, bool) {
    let cap = bytes.len();
    if let Err(e) = std::str::from_utf8(&bytes)
        && e.error_len().is_none()
        && cut
    {
        bytes.truncate(e.valid_up_to());
    }
    let mut s = String::from_utf8_lossy(&bytes).into_owned();
    if s.len() > cap {
        let mut end = cap;
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        s.truncate(end);
        cut = true;
    }
    (s, cut)
}

#[cfg(test)]
mod tests;
