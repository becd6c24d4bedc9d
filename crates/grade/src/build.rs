//! Building a slot's kit with a submission's modules: cargo with a time limit, compiler errors
//! read from `--message-format=json` and put on the module they are in. A submission's build
//! runs in the sandbox ([`cargo_build_sandboxed`]): the toolchain, the crates' sources and the
//! kit read-only, offline, a cleared environment, no network, memory and time limits, and only
//! its own target folder writable.

use std::collections::BTreeMap;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Duration;

use cg_core::lang::Text;

use crate::result::tail;

/// How a build ended.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct BuildOutput {
    /// Whether cargo succeeded.
    pub success: bool,
    /// Whether it ran over its time limit and was killed.
    pub timed_out: bool,
    /// Compiler errors by module (`a1` …), each `file:line: message`.
    pub module_errors: BTreeMap<String, Vec<String>>,
    /// Errors in no module of the student's (the kit's files, or cargo itself).
    pub other_errors: Vec<String>,
    /// The end of cargo's stderr.
    pub stderr_tail: String,
}

/// Reads cargo's JSON messages: errors by module (`file:line: message`), and the others
/// ([`cg_assign::local::diagnostics`], which `cg check` reads the student's own build with).
#[must_use]
pub fn parse_messages(stdout: &str) -> (BTreeMap<String, Vec<String>>, Vec<String>) {
    let mut by_module: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut other = Vec::new();
    for d in cg_assign::local::diagnostics(stdout) {
        match d.module {
            Some(m) => by_module.entry(m.to_owned()).or_default().push(d.short),
            None => other.push(d.short),
        }
    }
    for list in by_module.values_mut().chain(std::iter::once(&mut other)) {
        keep_first(list);
    }
    (by_module, other)
}

/// How long one kept compiler error may be, in bytes (a `compile_error!` of a megabyte).
const MAX_ERROR_BYTES: usize = 400;

/// The first [`cg_assign::local::ERRORS_KEPT`] errors, each at most [`MAX_ERROR_BYTES`], and how
/// many more there were: a submission of 30 000 errors (copied into every check's result and
/// feedback) is read as its first few, as `cg check` shows them.
fn keep_first(list: &mut Vec<String>) {
    let kept = cg_assign::local::ERRORS_KEPT;
    let more = list.len().saturating_sub(kept);
    list.truncate(kept);
    for e in list.iter_mut() {
        if e.len() > MAX_ERROR_BYTES {
            let mut end = MAX_ERROR_BYTES;
            while !e.is_char_boundary(end) {
                end -= 1;
            }
            e.truncate(end);
            e.push('…');
        }
    }
    if more > 0 {
        list.push(format!("… (+{more})"));
    }
}

/// Runs `cargo build --release --offline --locked -p <package> --message-format=json` in `kit`
/// with `target` as its target folder, killing it (and the compilers it started) after `limit`.
///
/// # Errors
/// cargo could not be started: why, in both languages.
pub fn cargo_build(
    kit: &Path,
    target: &Path,
    package: &str,
    limit: Duration,
) -> Result<BuildOutput, Text> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command
        .args(["build", "--release", "--offline", "--locked", "--message-format=json", "-p"])
        .arg(package)
        .current_dir(kit)
        .env("CARGO_TARGET_DIR", target)
        // No debug info: nothing in grading reads it, and every submission builds faster.
        .env("CARGO_PROFILE_RELEASE_DEBUG", "0")
        .env_remove("RUSTFLAGS")
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // Its own process group, so a time-out kills the compilers cargo started too (Unix; grading
    // runs on Linux, and elsewhere only cargo itself is killed).
    #[cfg(unix)]
    std::os::unix::process::CommandExt::process_group(&mut command, 0);
    let ran = cg_assign::local::run_captured(&mut command, Some(limit), &|| {})
        .map_err(|e| cannot_start_cargo(&Text::io(&e)))?;
    let (status, timed_out, stdout, stderr) = (ran.status, ran.timed_out, ran.stdout, ran.stderr);
    let (module_errors, other_errors) = parse_messages(&stdout);
    Ok(BuildOutput {
        success: status.is_some_and(|s| s.success()),
        timed_out,
        module_errors,
        other_errors,
        stderr_tail: tail(&stderr, 4000),
    })
}

/// The sandbox's limits for a build: the time limit given; 4 GiB of address space for cargo,
/// rustc and the linker; 512 MiB of `/tmp` (the linker's temporary files); 16 MiB of output.
#[must_use]
pub fn build_limits(limit: Duration) -> cg_sandbox::Limits {
    cg_sandbox::Limits {
        wall: limit,
        memory_bytes: 4 << 30,
        output_bytes: 16 << 20,
        tmp_bytes: 512 << 20,
        workdir_bytes: 64 << 20,
    }
}

/// Where cargo's home appears inside the sandbox: a folder of the private `/tmp`, so that cargo
/// can write its lock files, with the real home's `registry` (the crates' sources) bound into
/// it read-only.
// platform: a path inside the bubblewrap sandbox, used only under Isolation::Bubblewrap (Linux).
const SANDBOX_CARGO_HOME: &str = "/tmp/cargo-home";

/// Why a build did not start: cargo not found, the sandbox not started.
fn cannot_start_cargo(why: &Text) -> Text {
    Text::new(
        format!("cargo を起動できません: {}", why.ja),
        format!("cannot start cargo: {}", why.en),
    )
}

/// The toolchain's root (`rustc --print sysroot`): `bin/cargo` and `bin/rustc` are the real
/// programs (not rustup's proxies, which need rustup's own folders).
fn sysroot() -> Result<std::path::PathBuf, Text> {
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let out = Command::new(rustc)
        .args(["--print", "sysroot"])
        .output()
        .map_err(|e| cannot_start_cargo(&Text::io(&e)))?;
    let text = String::from_utf8_lossy(&out.stdout).trim().to_owned();
    if !out.status.success() || text.is_empty() {
        return Err(cannot_start_cargo(&Text::new(
            "rustc --print sysroot が何も返しません",
            "rustc --print sysroot gave nothing",
        )));
    }
    Ok(text.into())
}

/// cargo's home outside the sandbox: `CARGO_HOME`, else `~/.cargo`.
fn cargo_home() -> Option<std::path::PathBuf> {
    std::env::var_os("CARGO_HOME")
        .map(Into::into)
        .or_else(|| std::env::var_os("HOME").map(|h| Path::new(&h).join(".cargo")))
}

/// [`cargo_build`] in the sandbox under `isolation` ([`build_limits`]): cargo and rustc from the
/// toolchain's root, read-only; the crates' sources read-only; the kit copy read-only (as the
/// work folder: its files bound into a throwaway folder); `target` the only writable place on
/// disk; no network, a cleared environment. Under [`cg_sandbox::Isolation::Limits`] (grading with
/// `--unsafe-no-sandbox`) it is [`cargo_build`] itself.
///
/// # Errors
/// The toolchain could not be found, or the sandbox could not start.
pub fn cargo_build_sandboxed(
    kit: &Path,
    target: &Path,
    package: &str,
    limit: Duration,
    isolation: cg_sandbox::Isolation,
) -> Result<BuildOutput, Text> {
    if isolation != cg_sandbox::Isolation::Bubblewrap {
        return cargo_build(kit, target, package, limit);
    }
    let sysroot = sysroot()?;
    let bin = sysroot.join("bin");
    let registry =
        cargo_home().map(|h| h.join("registry")).filter(|r| r.is_dir()).ok_or_else(|| {
            cannot_start_cargo(&Text::new(
                "cargo のレジストリ（CARGO_HOME/registry）がありません",
                "no cargo registry (CARGO_HOME/registry)",
            ))
        })?;
    std::fs::create_dir_all(target).map_err(|e| Text::io_at(target, &e))?;
    let target = target.canonicalize().map_err(|e| Text::io_at(target, &e))?;
    let path = format!("{}:/usr/bin:/bin", bin.display());
    let job = cg_sandbox::Job {
        program: bin.join("cargo"),
        args: [
            "build",
            "--release",
            "--offline",
            "--locked",
            "--message-format=json",
            "-p",
            package,
        ]
        .map(String::from)
        .to_vec(),
        workdir: kit.to_path_buf(),
        read_only: vec![sysroot.clone()],
        env: vec![
            ("PATH".into(), path),
            ("CARGO_HOME".into(), SANDBOX_CARGO_HOME.into()),
            ("CARGO_TARGET_DIR".into(), target.display().to_string()),
            ("CARGO_PROFILE_RELEASE_DEBUG".into(), "0".into()),
            ("CARGO_TERM_COLOR".into(), "never".into()),
            ("RUSTC".into(), bin.join("rustc").display().to_string()),
        ],
        binds: vec![
            cg_sandbox::Bind { from: target.clone(), to: target, writable: true },
            cg_sandbox::Bind {
                from: registry,
                to: Path::new(SANDBOX_CARGO_HOME).join("registry"),
                writable: false,
            },
        ],
        compiler: true,
    };
    let run = cg_sandbox::run(&job, &build_limits(limit), isolation).map_err(|e| e.text())?;
    let (module_errors, other_errors) = parse_messages(&run.stdout);
    Ok(BuildOutput {
        success: run.ended == cg_sandbox::Ended::Exited(0),
        timed_out: run.ended == cg_sandbox::Ended::TimedOut,
        module_errors,
        other_errors,
        stderr_tail: tail(&run.stderr, 4000),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_go_to_their_module() {
        let line = |file: &str, msg: &str| {
            serde_json::json!({"reason": "compiler-message", "message": {"level": "error",
                "message": msg, "spans": [{"file_name": file, "line_start": 7, "is_primary": true}]}})
            .to_string()
        };
        let stdout = [
            line("exercises/src/a2.rs", "expected `;`, found `}`"),
            line("crates/cli/src/main.rs", "mismatched types"),
            line("exercises/src/a2.rs", "aborting due to 1 previous error"),
            r#"{"reason":"compiler-artifact"}"#.to_owned(),
            "not json".to_owned(),
        ]
        .join("\n");
        let (by, other) = parse_messages(&stdout);
        assert_eq!(by["a2"], vec!["exercises/src/a2.rs:7: expected `;`, found `}`".to_owned()]);
        assert_eq!(by.len(), 1);
        assert_eq!(other, vec!["crates/cli/src/main.rs:7: mismatched types".to_owned()]);
        assert_eq!(cg_assign::local::module_of("src/s.rs"), Some("s"));
        // 30 000 errors, one of them a megabyte long: the first few, each cut, and a count.
        let mut many = vec![line("exercises/src/a1.rs", &"x".repeat(1 << 20))];
        many.extend((0..30_000).map(|k| line("exercises/src/a1.rs", &format!("error {k}"))));
        let (by, _) = parse_messages(&many.join("\n"));
        let kept = cg_assign::local::ERRORS_KEPT;
        assert_eq!(by["a1"].len(), kept + 1);
        assert!(by["a1"][0].len() <= MAX_ERROR_BYTES + '…'.len_utf8(), "{}", by["a1"][0].len());
        assert_eq!(by["a1"][kept], format!("… (+{})", 30_001 - kept));
    }
}
