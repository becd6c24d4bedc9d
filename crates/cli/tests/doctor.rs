//! `cg doctor`: what works on this machine and why, each problem with its fix, in both
//! languages — without a display or a GPU, and without hanging on a driver that does not answer.

mod common;

use std::path::Path;
use std::process::{Command, Output};
#[cfg(feature = "gpu")]
use std::time::{Duration, Instant};

use common::{cg, root, scratch};

/// A Vulkan driver file that is not there: the GPU probe then finds no adapter, quickly, on any
/// machine (the loader reads `VK_DRIVER_FILES` first, so that one is removed).
const NO_DRIVER: &str = "/nonexistent.json";

/// Runs `cg doctor ARGS` in `dir` as `common::cg` runs `cg` (no language from the environment,
/// no display), also without Wayland, with a runtime folder of its own (`DIR/runtime`) and no
/// Vulkan driver; then `env` on top (`None` removes a variable).
fn doctor(dir: &Path, args: &[&str], env: &[(&str, Option<&str>)]) -> Output {
    let runtime = dir.join("runtime");
    std::fs::create_dir_all(&runtime).unwrap();
    let mut command = Command::new(env!("CARGO_BIN_EXE_cg"));
    cg_testkit::no_language_from_the_tester(&mut command);
    command.arg("doctor").args(args).current_dir(dir);
    for key in
        ["DISPLAY", "WAYLAND_DISPLAY", "VK_DRIVER_FILES", "VK_ADD_DRIVER_FILES", "WGPU_BACKEND"]
    {
        command.env_remove(key);
    }
    command.env("XDG_RUNTIME_DIR", &runtime).env("VK_ICD_FILENAMES", NO_DRIVER);
    for (key, value) in env {
        match value {
            Some(v) => command.env(key, v),
            None => command.env_remove(key),
        };
    }
    command.output().expect("the cg binary runs")
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Stdout and stderr, for failure messages.
fn all(out: &Output) -> String {
    format!("{}\n--- stderr ---\n{}", stdout(out), String::from_utf8_lossy(&out.stderr))
}

/// A folder with an `exercises/` of its own (so the kit's own student file is not read).
fn kit_dir(test: &str) -> std::path::PathBuf {
    let dir = scratch("doctor", test);
    std::fs::create_dir_all(dir.join("exercises")).unwrap();
    dir
}

/// The lines after `line` that are its fixes (`→ fix:` / `→ 対処:`).
fn fixes_after<'a>(text: &'a str, line: &str) -> Vec<&'a str> {
    text.lines()
        .skip_while(|l| !l.contains(line))
        .skip(1)
        .take_while(|l| l.trim_start().starts_with('→'))
        .collect()
}

#[test]
fn without_a_display_it_says_so_and_names_the_fix_in_both_languages() {
    let dir = kit_dir("no-display");
    let en = doctor(&dir, &["--lang", "en"], &[]);
    let text = stdout(&en);
    assert!(en.status.success(), "{}", all(&en));
    let line = "✗ no window can be opened (neither WAYLAND_DISPLAY nor DISPLAY is set)";
    assert!(text.contains(line), "{}", all(&en));
    let fixes = fixes_after(&text, line);
    assert!(fixes.iter().all(|f| f.trim_start().starts_with("→ fix: ")), "{fixes:?}");
    assert!(fixes.iter().any(|f| f.contains("PNG files to out/")), "{fixes:?}");
    // The CPU renderers always work, and the summary says the course runs here.
    assert!(text.contains("✓ CPU rasterizer"), "{text}");
    assert!(text.contains("✓ ray tracer"), "{text}");
    assert!(text.contains("every part of the course runs on this machine"), "{text}");

    let ja = doctor(&dir, &[], &[("CG_LANG", Some("ja"))]);
    let text = stdout(&ja);
    assert!(ja.status.success(), "{}", all(&ja));
    let line = "✗ ウィンドウを開けません (WAYLAND_DISPLAY も DISPLAY も設定されていません)";
    assert!(text.contains(line), "{}", all(&ja));
    let fixes = fixes_after(&text, line);
    assert!(fixes.iter().all(|f| f.trim_start().starts_with("→ 対処: ")), "{fixes:?}");
    assert!(fixes.iter().any(|f| f.contains("out/ に PNG")), "{fixes:?}");
    assert!(text.contains("✓ CPU ラスタライザ"), "{text}");
    for english in ["no window", "fix:", "works", "not set", "renderers"] {
        assert!(!text.contains(english), "English {english:?} in the Japanese report:\n{text}");
    }
}

#[cfg(target_os = "linux")]
#[test]
fn a_display_that_is_named_but_not_there_is_no_window() {
    let dir = kit_dir("display-gone");
    let out = doctor(&dir, &[], &[("DISPLAY", Some(":59999"))]);
    let text = stdout(&out);
    assert!(out.status.success(), "{}", all(&out));
    let socket = "✗ the X server's socket /tmp/.X11-unix/X59999 does not exist";
    assert!(text.contains(socket), "{}", all(&out));
    assert!(!fixes_after(&text, socket).is_empty(), "{text}");
    assert!(text.contains("✗ no window can be opened (the display named by"), "{text}");
    assert!(!text.contains("✓ a window can be opened"), "{text}");
}

#[test]
fn a_runtime_folder_that_does_not_exist_is_named_with_its_fix() {
    let dir = kit_dir("runtime-missing");
    let missing = dir.join("no-such-runtime");
    let missing = missing.to_str().unwrap();
    let out = doctor(&dir, &[], &[("XDG_RUNTIME_DIR", Some(missing))]);
    let text = stdout(&out);
    assert!(out.status.success(), "{}", all(&out));
    let line = format!("✗ XDG_RUNTIME_DIR={missing}: the folder does not exist");
    assert!(text.contains(&line), "{}", all(&out));
    let fixes = fixes_after(&text, &line);
    assert!(!fixes.is_empty() && fixes[0].contains("→ fix: "), "{text}");

    let ja = doctor(&dir, &["--lang", "ja"], &[("XDG_RUNTIME_DIR", Some(missing))]);
    let text = stdout(&ja);
    let line = format!("✗ XDG_RUNTIME_DIR={missing} のフォルダがありません");
    assert!(text.contains(&line), "{}", all(&ja));
    assert!(!fixes_after(&text, &line).is_empty(), "{text}");

    // A folder that is there is no problem.
    let fine = doctor(&dir, &[], &[]);
    assert!(!stdout(&fine).contains("✗ XDG_RUNTIME_DIR"), "{}", all(&fine));
}

#[cfg(feature = "gpu")]
#[test]
fn a_missing_vulkan_driver_is_an_explanation_not_a_crash() {
    let dir = kit_dir("no-vulkan");
    let out = doctor(&dir, &[], &[("VK_ICD_FILENAMES", Some(NO_DRIVER))]);
    let text = stdout(&out);
    assert!(out.status.success(), "{}", all(&out));
    assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"), "{}", all(&out));
    // The variable is named as the cause, with its fix…
    let variable = format!("✗ VK_ICD_FILENAMES={NO_DRIVER}: {NO_DRIVER} does not exist");
    assert!(text.contains(&variable), "{}", all(&out));
    assert!(fixes_after(&text, &variable).iter().any(|f| f.contains("unset VK_ICD_FILENAMES")));
    // …and the GPU line is an explanation with fixes, after which the report goes on.
    let gpu = text.lines().find(|l| l.contains("GPU renderer (")).expect("a GPU line");
    assert!(gpu.trim_start().starts_with("✗ GPU renderer"), "{text}");
    assert!(gpu.contains("no GPU adapter found"), "{text}");
    let fixes = fixes_after(&text, gpu);
    assert!(fixes.iter().any(|f| f.contains("mesa-vulkan-drivers")), "{fixes:?}");
    assert!(text.contains("the kit\n"), "the report goes on after the GPU: {text}");
}

#[cfg(feature = "gpu")]
#[cfg(unix)]
#[test]
fn a_driver_that_never_answers_is_given_up_on_in_time() {
    // A Vulkan driver file that is a pipe nobody writes to: the loader waits on it forever.
    let dir = kit_dir("hung-driver");
    let fifo = dir.join("hung-driver.json");
    let made = Command::new("mkfifo").arg(&fifo).status().is_ok_and(|s| s.success());
    if !made {
        eprintln!("note: skipped: mkfifo is missing");
        return;
    }
    let start = Instant::now();
    let out = doctor(
        &dir,
        &["--gpu-timeout", "1"],
        &[("VK_ICD_FILENAMES", Some(fifo.to_str().unwrap()))],
    );
    let took = start.elapsed();
    let text = stdout(&out);
    assert!(out.status.success(), "{}", all(&out));
    assert!(took < Duration::from_secs(30), "took {took:?}: {}", all(&out));
    let gpu = text.lines().find(|l| l.contains("GPU renderer (")).expect("a GPU line");
    assert!(gpu.trim_start().starts_with('✗'), "{text}");
    // A loader that refuses the pipe instead of reading it finds no adapter: also an answer.
    assert!(
        gpu.contains("did not answer within 1 s") || gpu.contains("no GPU adapter found"),
        "{text}"
    );
    assert!(!fixes_after(&text, gpu).is_empty(), "{text}");
}

#[test]
fn json_is_one_flat_object_of_the_findings() {
    let dir = kit_dir("json");
    let out = doctor(&dir, &["--json"], &[]);
    assert!(out.status.success(), "{}", all(&out));
    let value: serde_json::Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {}", all(&out)));
    let object = value.as_object().expect("an object");
    for (key, v) in object {
        assert!(!v.is_object() && !v.is_array(), "{key} is not flat: {v}");
    }
    assert_eq!(object["window"], false);
    assert_eq!(object["display"], serde_json::Value::Null);
    assert_eq!(object["xdg_runtime_dir_ok"], true);
    assert_eq!(object["cpu_raster"], true);
    assert_eq!(object["cpu_trace"], true);
    assert_eq!(object["gpu"], false);
    assert_eq!(object["gpu_built"], cfg!(feature = "gpu"));
    assert!(object["gpu_error"].as_str().is_some_and(|e| !e.is_empty()), "{value}");
    assert_eq!(object["vk_icd_filenames"], NO_DRIVER);
    assert_eq!(object["student"], serde_json::Value::Null);
    assert!(object["problems"].as_u64().is_some_and(|n| n >= 2), "{value}");
    assert_eq!(object["release_build"], !cfg!(debug_assertions));
}

#[test]
fn the_student_number_is_found_or_its_recording_is_the_fix() {
    let dir = kit_dir("student");
    let out = doctor(&dir, &[], &[]);
    let text = stdout(&out);
    let line = "student.toml does not exist";
    assert!(text.contains(line), "{}", all(&out));
    assert!(
        fixes_after(&text, line).iter().any(|f| f.contains("assignment --student 12345678 --save")),
        "{text}"
    );

    std::fs::write(dir.join("exercises/student.toml"), "student = \"01234567\"\n").unwrap();
    let out = doctor(&dir, &["--lang", "ja"], &[]);
    assert!(stdout(&out).contains("✓ 学生番号 01234567"), "{}", all(&out));

    std::fs::write(dir.join("exercises/student.toml"), "student = 1234567\n").unwrap();
    let out = doctor(&dir, &[], &[]);
    let text = stdout(&out);
    assert!(text.contains("must be in quotes"), "{}", all(&out));
    assert!(text.contains("→ fix: edit "), "{text}");
}

#[test]
fn the_help_lists_doctor_and_its_options_but_not_the_probe() {
    let out = cg(&root(), &["--help"]);
    assert!(stdout(&out).contains("doctor"), "{}", all(&out));
    let out = cg(&root(), &["doctor", "--help"]);
    let text = stdout(&out);
    assert!(out.status.success(), "{}", all(&out));
    for option in ["--json", "--gpu-timeout", "--lang"] {
        assert!(text.contains(option), "{option}: {text}");
    }
    assert!(!text.contains("--gpu-probe"), "{text}");
    // A limit of 0 s is a usage error, not a report without a GPU.
    let out = cg(&root(), &["doctor", "--gpu-timeout", "0"]);
    assert_eq!(out.status.code(), Some(2), "{}", all(&out));
}

/// A build without the GPU renderer (the students' copy): the GPU line is a note, not a problem,
/// that says so in the user's language and gives the command that builds it and runs the report
/// again; no GPU is probed.
#[cfg(not(feature = "gpu"))]
#[test]
fn without_the_gpu_feature_the_gpu_line_is_a_note_with_the_command_that_builds_it() {
    let dir = kit_dir("no-gpu");
    for (lang, name, says) in [
        ("en", "· GPU renderer (", "built without the GPU renderer"),
        ("ja", "· GPU レンダラ（", "GPU レンダラ（wgpu）なしでビルド"),
    ] {
        let out = doctor(&dir, &["--lang", lang], &[]);
        let text = stdout(&out);
        assert!(out.status.success(), "{}", all(&out));
        let gpu = text.lines().find(|l| l.trim_start().starts_with(name)).expect("a GPU line");
        assert!(gpu.contains(says), "{text}");
        let command = format!("cargo run --release --features gpu -- doctor --lang {lang}");
        assert!(gpu.contains(&command), "{command}\n{text}");
    }
}
