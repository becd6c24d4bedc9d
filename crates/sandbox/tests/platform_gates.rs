//! The kit builds and runs where the students are (Windows, macOS, Linux): a Unix- or
//! Linux-only API outside the platform's own module must be gated (`#[cfg(unix)]`,
//! `#[cfg(target_os = "linux")]`) or say, in a `// platform:` comment just above, what happens
//! elsewhere. The sandbox (`crates/sandbox/src/lib.rs`) is that module: it detects at run time
//! what the machine offers. Tests (the `#[cfg(test)] mod tests` at a file's end, a test module
//! in a file of its own, `tests.rs` or `*_tests.rs`, and `tests/`) are not scanned: they run on
//! Linux in CI. `scripts/check-platforms.sh` (run by CI) also
//! compiles the workspace for Windows and macOS.

use std::path::{Path, PathBuf};

/// What only Unix or only Linux has.
const UNIX_ONLY: [&str; 7] =
    ["std::os::unix", "\"/proc", "\"/dev/", "\"bwrap\"", "\"prlimit\"", "libc::", "\"/tmp/"];

/// The platform's own module (it checks at run time), and its hostile test fixture (a Linux
/// program attacking the Linux sandbox).
const PLATFORM_MODULES: [&str; 2] =
    ["crates/sandbox/src/lib.rs", "crates/sandbox/src/bin/hostile.rs"];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn sources(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let path = entry.path();
        if path.is_dir() {
            sources(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Every ungated use in `text`: (line, the API).
fn ungated(text: &str) -> Vec<(usize, &'static str)> {
    let lines: Vec<&str> = text.lines().collect();
    let mut found = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        if line.trim_start().starts_with("#[cfg(test)]")
            && lines.get(k + 1).is_some_and(|l| l.trim_start().starts_with("mod tests"))
        {
            break;
        }
        if line.trim_start().starts_with("//") {
            continue;
        }
        for api in UNIX_ONLY {
            if !line.contains(api) {
                continue;
            }
            let gate = lines[k.saturating_sub(2)..=k].iter().any(|l| {
                l.contains("cfg(unix)")
                    || l.contains("cfg(target_os = \"linux\")")
                    || l.contains("// platform:")
            });
            if !gate {
                found.push((k + 1, api));
            }
        }
    }
    found
}

#[test]
fn unix_only_apis_are_gated_outside_the_platform_module() {
    let mut files = Vec::new();
    for entry in std::fs::read_dir(root().join("crates")).unwrap().flatten() {
        let src = entry.path().join("src");
        if src.is_dir() {
            sources(&src, &mut files);
        }
    }
    files.sort();
    assert!(files.len() > 50, "the kit's sources were found: {}", files.len());
    let mut problems = Vec::new();
    for file in files {
        let relative =
            file.strip_prefix(root()).unwrap_or(&file).to_string_lossy().replace('\\', "/");
        let relative = relative.trim_start_matches("./").to_owned();
        if PLATFORM_MODULES.iter().any(|m| relative.ends_with(m)) {
            continue;
        }
        // A test module in a file of its own (`#[cfg(test)] mod tests;`): tests are not scanned.
        if relative.ends_with("/tests.rs") || relative.ends_with("_tests.rs") {
            continue;
        }
        let text = std::fs::read_to_string(&file).unwrap();
        for (line, api) in ungated(&text) {
            problems.push(format!("{relative}:{line}: {api}"));
        }
    }
    assert!(
        problems.is_empty(),
        "Unix-only APIs used without a #[cfg(unix)] / #[cfg(target_os = \"linux\")] gate or a \
         `// platform:` comment (the kit must build on Windows):\n{}",
        problems.join("\n")
    );
}

#[test]
fn the_scan_finds_what_it_looks_for() {
    // The attack the guard exists for: the unconditional import that kept Windows from building.
    let bad = "use std::os::unix::process::CommandExt;\nfn f() { let _ = std::fs::read(\"/proc/self\"); }\n";
    assert_eq!(ungated(bad), [(1, "std::os::unix"), (2, "\"/proc")]);
    let gated = "#[cfg(unix)]\nuse std::os::unix::process::CommandExt;\n// platform: elsewhere empty\nlet x = \"/proc/cpuinfo\";\n";
    assert_eq!(ungated(gated), []);
    let in_tests = "fn f() {}\n#[cfg(test)]\nmod tests {\n    use std::os::unix::fs::symlink;\n}\n";
    assert_eq!(ungated(in_tests), []);
}
