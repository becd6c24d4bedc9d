//! Building `tools/glref/glref.c` on first use, running it, and reading its image.
//!
//! The C source is compiled into this crate (`include_str!`), so the library needs no path into
//! the repository at run time. The executable is cached as `glref-<hash>` in the `glref/` folder
//! of the workspace's `target/` directory, where `<hash>` covers the source and the compiler
//! command: editing `glref.c` (which rebuilds this crate) or changing `$CC` builds a new one.
//! Each build goes to a temporary name and is renamed into place, so test processes running at
//! once never see a half-written executable.

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;

use cg_core::image::Image;

use crate::error::GlRefError;

/// The C program (see its header for the command script).
pub const SOURCE: &str = include_str!("../../../tools/glref/glref.c");

/// Where the executable is cached: `$CG_GLREF_CACHE` when set; otherwise the `glref/` folder of
/// the Cargo target directory that holds the running executable (found by the `CACHEDIR.TAG`
/// Cargo writes there), or else of this workspace's `target/` (doc tests run from elsewhere);
/// otherwise the system's temporary folder.
#[must_use]
pub fn cache_dir() -> PathBuf {
    if let Some(dir) = std::env::var_os("CG_GLREF_CACHE") {
        return PathBuf::from(dir);
    }
    let is_target = |dir: &Path| dir.join("CACHEDIR.TAG").is_file();
    let from_exe = std::env::current_exe()
        .ok()
        .and_then(|exe| exe.ancestors().skip(1).find(|dir| is_target(dir)).map(Path::to_path_buf));
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../target");
    from_exe
        .or_else(|| is_target(&workspace).then_some(workspace))
        .map_or_else(|| std::env::temp_dir().join("cg-glref"), |target| target.join("glref"))
}

/// The C compiler and its leading arguments: `$CC` split at spaces (`ccache gcc` works), or `cc`.
fn compiler() -> Vec<String> {
    let words: Vec<String> = std::env::var("CC")
        .ok()
        .map(|cc| cc.split_whitespace().map(str::to_owned).collect())
        .unwrap_or_default();
    if words.is_empty() { vec!["cc".to_owned()] } else { words }
}

/// The flags after the compiler: C99, optimised, linked against OSMesa (which also exports the
/// GL 1.x functions; linking libGL as well would mix two GL implementations).
const FLAGS: [&str; 3] = ["-std=c99", "-O2", "-Wall"];
const LIBS: [&str; 2] = ["-lOSMesa", "-lm"];

/// 64-bit FNV-1a: a stable name for the source and compiler command (not for security).
fn fnv1a(parts: &[&str]) -> u64 {
    let mut hash = 0xcbf2_9ce4_8422_2325_u64;
    for part in parts {
        for byte in part.bytes().chain([0]) {
            hash ^= u64::from(byte);
            hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
    hash
}

/// The executable, built once per process (and once per source version across processes).
///
/// # Errors
/// [`GlRefError::NotAvailable`] when there is no C compiler, no OSMesa header or library, or the
/// cache folder cannot be written; the detail quotes the compiler.
pub fn executable() -> Result<PathBuf, GlRefError> {
    static BUILT: OnceLock<Result<PathBuf, String>> = OnceLock::new();
    BUILT.get_or_init(build).clone().map_err(|detail| GlRefError::NotAvailable { detail })
}

fn build() -> Result<PathBuf, String> {
    let cc = compiler();
    let mut key: Vec<&str> = vec![SOURCE];
    key.extend(cc.iter().map(String::as_str));
    key.extend(FLAGS);
    key.extend(LIBS);
    let dir = cache_dir();
    let exe = dir.join(format!("glref-{:016x}", fnv1a(&key)));
    if exe.is_file() {
        return Ok(exe);
    }
    std::fs::create_dir_all(&dir)
        .map_err(|e| format!("cannot create the cache folder {}: {e}", dir.display()))?;
    // Unique per process and thread, so concurrent builds never write the same file.
    let unique = format!("{}-{:?}", std::process::id(), std::thread::current().id())
        .replace(|c: char| !c.is_ascii_alphanumeric(), "");
    let source = dir.join(format!("glref-{unique}.c"));
    let partial = dir.join(format!("glref-{unique}.partial"));
    std::fs::write(&source, SOURCE)
        .map_err(|e| format!("cannot write {}: {e}", source.display()))?;
    let output = Command::new(&cc[0])
        .args(&cc[1..])
        .args(FLAGS)
        .arg("-o")
        .arg(&partial)
        .arg(&source)
        .args(LIBS)
        .stdin(Stdio::null())
        .output();
    let _ = std::fs::remove_file(&source);
    let output =
        output.map_err(|e| format!("cannot run the C compiler `{}`: {e}", cc.join(" ")))?;
    if !output.status.success() {
        let _ = std::fs::remove_file(&partial);
        let stderr = String::from_utf8_lossy(&output.stderr);
        let hint = if stderr.contains("osmesa.h") {
            "the OSMesa header GL/osmesa.h is missing (package libosmesa6-dev)"
        } else if stderr.contains("-lOSMesa") || stderr.contains("OSMesa") {
            "the OSMesa library is missing (package libosmesa6-dev)"
        } else {
            "the C compiler failed"
        };
        return Err(format!("{hint}; `{}` said: {}", cc.join(" "), last_lines(&stderr, 6)));
    }
    std::fs::rename(&partial, &exe)
        .map_err(|e| format!("cannot move the program to {}: {e}", exe.display()))?;
    Ok(exe)
}

/// Runs the program on `script` and reads its image.
///
/// The child gets `GALLIUM_DRIVER=llvmpipe`, so OSMesa draws with Mesa's llvmpipe whatever the
/// environment says (softpipe, its other software driver, rasterizes edges differently).
///
/// # Errors
/// [`GlRefError::NotAvailable`] when the program cannot be built or started;
/// [`GlRefError::Program`] when it reports an error; [`GlRefError::BadOutput`] when its image is
/// not the `width × height` PPM it should be.
pub fn run(script: &str, width: u32, height: u32) -> Result<Image, GlRefError> {
    let exe = executable()?;
    let mut child = Command::new(&exe)
        .env("GALLIUM_DRIVER", "llvmpipe")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| GlRefError::NotAvailable {
            detail: format!("cannot start {}: {e}", exe.display()),
        })?;
    // Write the script from another thread while this one reads the image, so neither pipe can
    // fill up and stall the other.
    let mut stdin = child.stdin.take();
    let text = script.to_owned();
    let writer = std::thread::spawn(move || {
        // A write error means the program stopped early; its exit status says why.
        if let Some(stdin) = stdin.as_mut() {
            let _ = stdin.write_all(text.as_bytes());
        }
    });
    // Reads standard output and standard error together, then waits.
    let output = child.wait_with_output().map_err(|e| GlRefError::NotAvailable {
        detail: format!("cannot read from {}: {e}", exe.display()),
    });
    let _ = writer.join();
    let output = output?;
    let status = output.status;
    if !status.success() {
        let stderr = String::from_utf8_lossy(&output.stderr);
        return Err(GlRefError::Program {
            status: status.to_string(),
            stderr: last_lines(&stderr, 12),
        });
    }
    read_ppm(&output.stdout, width, height)
}

/// Reads the program's `P6` image (`P6\n<w> <h>\n255\n` and RGB bytes, top row first) as an
/// [`Image`] with each channel `u8 / 255` (exact: [`Image::to_rgba8`] gives the bytes back).
///
/// # Errors
/// [`GlRefError::BadOutput`] for anything else, or another size than `width × height`.
pub fn read_ppm(bytes: &[u8], width: u32, height: u32) -> Result<Image, GlRefError> {
    let bad = |detail: String| GlRefError::BadOutput { detail };
    let header = format!("P6\n{width} {height}\n255\n");
    let Some(data) = bytes.strip_prefix(header.as_bytes()) else {
        let start = String::from_utf8_lossy(&bytes[..bytes.len().min(32)]).into_owned();
        return Err(bad(format!("expected the header {header:?}, found {start:?}")));
    };
    let n = width as usize * height as usize;
    if data.len() != 3 * n {
        return Err(bad(format!("expected {} bytes of pixels, found {}", 3 * n, data.len())));
    }
    let rgba: Vec<[u8; 4]> = data.chunks_exact(3).map(|p| [p[0], p[1], p[2], 255]).collect();
    Image::from_rgba8(width, height, &rgba)
        .ok_or_else(|| bad(format!("{} pixels do not make a {width}×{height} image", rgba.len())))
}

/// The last `n` lines of a program's message, trimmed.
fn last_lines(text: &str, n: usize) -> String {
    let lines: Vec<&str> = text.lines().filter(|l| !l.trim().is_empty()).collect();
    lines[lines.len().saturating_sub(n)..].join(" / ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ppm_reads_back_exactly_and_a_wrong_one_is_an_error() {
        let mut ppm = b"P6\n2 1\n255\n".to_vec();
        ppm.extend([0, 128, 255, 1, 2, 3]);
        let img = read_ppm(&ppm, 2, 1).unwrap();
        assert_eq!(img.to_rgba8(), vec![[0, 128, 255, 255], [1, 2, 3, 255]]);
        assert_eq!(img.pixels[0].y, 128.0 / 255.0);
        assert!(matches!(read_ppm(&ppm, 1, 2), Err(GlRefError::BadOutput { .. })));
        assert!(matches!(read_ppm(&ppm[..15], 2, 1), Err(GlRefError::BadOutput { .. })));
        assert!(matches!(read_ppm(b"", 2, 1), Err(GlRefError::BadOutput { .. })));
    }

    #[test]
    fn the_cache_name_changes_with_the_source_and_the_compiler() {
        let a = fnv1a(&["int main(void) { return 0; }", "cc"]);
        assert_ne!(a, fnv1a(&["int main(void) { return 1; }", "cc"]));
        assert_ne!(a, fnv1a(&["int main(void) { return 0; }", "clang"]));
        // Part boundaries count: ("ab", "c") is not ("a", "bc").
        assert_ne!(fnv1a(&["ab", "c"]), fnv1a(&["a", "bc"]));
        assert_eq!(a, fnv1a(&["int main(void) { return 0; }", "cc"]));
    }
}
