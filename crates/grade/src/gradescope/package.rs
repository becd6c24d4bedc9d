//! `cg autograder`: the zip Gradescope runs. At its root, `setup.sh` (Gradescope runs it once,
//! as root, when it builds the autograder's image: the system packages grading needs, Rust, the
//! kit's `cg` built, and the pristine kit built once in the work folder so each submission
//! rebuilds only its own crate) and `run_autograder` (per submission: `cg grade-one
//! /autograder/submission --out /autograder/results`, and a `results.json` with score 0 and the
//! reason even when grading fails), beside the kit's source *with* `solutions/` — grading
//! makes its handouts and stubs from it — which Gradescope unpacks into `/autograder/source`.
//! `AUTOGRADER_ROOT` (default `/autograder`) moves the whole tree, for tests.

use std::io::Write as _;
use std::path::{Path, PathBuf};

use cg_core::lang::{Lang, Text, t};

use crate::handout::{excluded, kit_files};

/// `setup.sh` of the autograder zip. The system packages are the grading part of the kit's
/// `scripts/setup.sh` (a C toolchain to link, bubblewrap for the sandbox), installed the same
/// idempotent way.
pub const SETUP_SH: &str = r#"#!/usr/bin/env bash
# The cg kit's Gradescope autograder: run once, as root, when Gradescope builds the image.
# キットの Gradescope 用オートグレーダー: イメージを作るときに 1 回だけ root で実行されます。
set -euo pipefail
ROOT="${AUTOGRADER_ROOT:-/autograder}"
SOURCE="$ROOT/source"

# The grading part of scripts/setup.sh: a C compiler and libc to link, bubblewrap for the
# sandbox, curl to install Rust (pkg-config for build scripts that look before they dlopen).
PACKAGES=(ca-certificates curl gcc libc6-dev pkg-config bubblewrap)
if command -v apt-get >/dev/null 2>&1; then
  missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    if [ "$(id -u)" -ne 0 ]; then SUDO=sudo; else SUDO=; fi
    export DEBIAN_FRONTEND=noninteractive
    $SUDO apt-get update -qq
    $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
  fi
else
  echo "setup: not Debian/Ubuntu: install ${PACKAGES[*]} yourself" >&2
fi

# Rust (rustup, minimal profile), unless cargo is already there.
if ! command -v cargo >/dev/null 2>&1; then
  if [ ! -x "$HOME/.cargo/bin/cargo" ]; then
    curl --proto '=https' --tlsv1.2 -sSf https://sh.rustup.rs | sh -s -- -y --profile minimal --default-toolchain stable
  fi
  export PATH="$HOME/.cargo/bin:$PATH"
fi

# The kit's crates (grading builds offline) and its `cg`: grading needs the reference and the
# instructors' commands, not the GPU renderer (wgpu and its tree), so that is left out.
cd "$SOURCE"
cargo fetch --locked
cargo build --release --locked -p cg-cli --no-default-features --features reference,instructor

# The pristine stubs graded once: the work folder's slot is built, so a submission rebuilds
# only the student's crate and the worker.
warm="$(mktemp -d)"
mkdir -p "$warm/pristine/exercises"
cp -r "$SOURCE/exercises/src" "$warm/pristine/exercises/"
printf 'student = "12345678"\n' > "$warm/pristine/exercises/student.toml"
unsafe=()
if [ "${CG_UNSAFE_NO_SANDBOX:-0}" = 1 ]; then unsafe=(--unsafe-no-sandbox); fi
"$SOURCE/target/release/cg" grade-one "$warm/pristine" --out "$warm/out" --work "$ROOT/work" "${unsafe[@]}" \
  || echo "setup: grading the pristine stubs failed: each submission builds the kit itself" >&2
rm -rf "$warm"
"#;

/// `run_autograder` of the autograder zip; `@LANG@` is replaced by the results' language.
pub const RUN_AUTOGRADER: &str = r#"#!/usr/bin/env bash
# The cg kit's Gradescope autograder: grades /autograder/submission into
# /autograder/results/results.json, which exists even when grading fails (score 0, the reason).
# 提出物を採点して results.json を書きます（採点できなくても、0 点と理由を書きます）。
set -u
ROOT="${AUTOGRADER_ROOT:-/autograder}"
RESULTS="$ROOT/results"
CG="${CG_BIN:-$ROOT/source/target/release/cg}"
export PATH="$HOME/.cargo/bin:$PATH"
mkdir -p "$RESULTS"
rm -f "$RESULTS/results.json"
log="$(mktemp)"
unsafe=()
if [ "${CG_UNSAFE_NO_SANDBOX:-0}" = 1 ]; then unsafe=(--unsafe-no-sandbox); fi
cd "$ROOT/source" 2>/dev/null || cd "$ROOT"
"$CG" grade-one "$ROOT/submission" --out "$RESULTS" --work "$ROOT/work" \
  --lang "${CG_LANG:-@LANG@}" "${unsafe[@]}" >"$log" 2>&1
status=$?
cat "$log"
if [ ! -s "$RESULTS/results.json" ]; then
  # cg could not even start: the end of its output, as a JSON string. The cut may fall inside
  # a character of Japanese output: its trailing bytes (0x80-0xBF) at the start are dropped,
  # so that the JSON is UTF-8.
  reason="$(tail -c 3000 "$log" | LC_ALL=C sed -e '1s/^[\x80-\xbf]*//' | tr -d '\000-\011\013-\037' | sed -e 's/\\/\\\\/g' -e 's/"/\\"/g' | awk '{printf "%s\\n", $0}')"
  printf '{"score": 0.0, "output": "grading failed (exit %s) / 採点できませんでした:\\n%s", "output_format": "text", "visibility": "visible", "stdout_visibility": "hidden", "tests": []}\n' \
    "$status" "$reason" >"$RESULTS/results.json"
fi
rm -f "$log"
exit 0
"#;

/// `run_autograder` with its results in `lang`.
#[must_use]
pub fn run_autograder(lang: Lang) -> String {
    RUN_AUTOGRADER.replace("@LANG@", t("ja", "en").get(lang))
}

/// Writes the autograder zip of the kit at `kit` to `out`: `setup.sh` and `run_autograder`
/// (executable) at its root with the kit's files — what a handout leaves out but grading needs
/// included (`solutions/`), not `target/`, `out/`, `.git/`, `exercises/student.toml` nor
/// `out` itself; returns how many of the kit's files it holds.
///
/// # Errors
/// A kit file could not be read, or the zip written.
pub fn write_zip(kit: &Path, out: &Path, lang: Lang) -> Result<usize, Text> {
    refuse_out(out)?;
    let target = out.canonicalize().ok();
    let mut files = kit_files(kit)?;
    // Outside a git checkout the kit's listing leaves solutions/ out, as a handout does.
    if !files.iter().any(|f| f.starts_with("solutions")) {
        files.extend(walk(kit, Path::new("solutions")));
    }
    files.retain(|f| !excluded(f) || f.starts_with("solutions"));
    files.retain(|f| {
        target.as_ref().is_none_or(|t| kit.join(f).canonicalize().ok().as_ref() != Some(t))
    });
    files.retain(|f| f != Path::new("setup.sh") && f != Path::new("run_autograder"));
    files.sort();
    let mut z = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let plain = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated)
        .unix_permissions(0o644);
    let executable = plain.unix_permissions(0o755);
    let err = |e: &dyn std::fmt::Display| {
        Text::new(format!("zip を作れません: {e}"), format!("cannot make the zip: {e}"))
    };
    for (name, text) in
        [("setup.sh", SETUP_SH.to_owned()), ("run_autograder", run_autograder(lang))]
    {
        z.start_file(name, executable).map_err(|e| err(&e))?;
        z.write_all(text.as_bytes()).map_err(|e| err(&e))?;
    }
    for f in &files {
        let bytes = std::fs::read(kit.join(f)).map_err(|e| Text::io_at(f, &e))?;
        let name = f.to_string_lossy().replace('\\', "/");
        z.start_file(name, plain.unix_permissions(mode(&kit.join(f)))).map_err(|e| err(&e))?;
        z.write_all(&bytes).map_err(|e| err(&e))?;
    }
    let bytes = z.finish().map_err(|e| err(&e))?.into_inner();
    crate::write_atomic(out, &bytes).map_err(|e| Text::io_at(out, &e))?;
    Ok(files.len())
}

/// Whether `out` may take the zip: not a folder (nor a name ending in `/`), and, when it is
/// there, a zip (an old autograder) — never another file, which the zip would replace
/// (`--out README.md` did).
fn refuse_out(out: &Path) -> Result<(), Text> {
    let shown = out.display();
    let named_folder = out.as_os_str().to_string_lossy().ends_with(['/', '\\']);
    if named_folder || out.is_dir() {
        return Err(Text::new(
            format!(
                "{shown} はフォルダです。zip のファイル名（autograder.zip など）を指定してください"
            ),
            format!("{shown} is a folder: give the zip a file name (autograder.zip, say)"),
        ));
    }
    let Ok(meta) = std::fs::metadata(out) else { return Ok(()) };
    let mut head = [0u8; 4];
    let is_zip = meta.is_file()
        && std::fs::File::open(out)
            .and_then(|mut f| std::io::Read::read_exact(&mut f, &mut head))
            .is_ok()
        && (head == *b"PK\x03\x04" || head == *b"PK\x05\x06");
    if is_zip || !meta.is_file() {
        // An old zip is replaced; a device (`/dev/null`) is written to.
        return Ok(());
    }
    Err(Text::new(
        format!(
            "{shown} は zip ではないファイルで、上書きすると失われます。新しい名前を指定してください"
        ),
        format!(
            "{shown} is a file that is not a zip, which the zip would replace: give a new name"
        ),
    ))
}

/// A kit file's mode in the zip: executable when it is (the kit's scripts), else 0644.
fn mode(path: &Path) -> u32 {
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        if std::fs::metadata(path).is_ok_and(|m| m.permissions().mode() & 0o111 != 0) {
            return 0o755;
        }
    }
    let _ = path;
    0o644
}

/// The files under `kit/dir`, relative to `kit`, without build folders.
fn walk(kit: &Path, dir: &Path) -> Vec<PathBuf> {
    let mut files = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(kit.join(&dir)).into_iter().flatten().flatten() {
            let relative = dir.join(entry.file_name());
            match entry.file_type() {
                Ok(t) if t.is_dir() && entry.file_name() != "target" => stack.push(relative),
                Ok(t) if t.is_file() => files.push(relative),
                _ => {}
            }
        }
    }
    files
}
