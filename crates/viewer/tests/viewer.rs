//! The viewer binary end to end: without a display (PNG files), and in a window under Xvfb driven
//! by xdotool, its screenshots compared with the headless render of the same state — drawn by
//! the CPU through softbuffer, and presented by the GPU (lavapipe in CI) to a wgpu surface.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use cg_core::camera::OrbitCamera;
use cg_core::scene::Shading;
use cg_testkit::images::{Tolerance, assert_images_match, read_png};
use cg_viewer::{CourseApp, LightChoice};

const BIN: &str = env!("CARGO_BIN_EXE_cg-viewer");

/// A fresh, empty folder for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cg-viewer-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn text(out: &Output) -> String {
    format!(
        "status {:?}\n--- stdout\n{}\n--- stderr\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// The `key=value` pairs of the last `saved PATH (…)` line: the state the screenshot shows.
fn saved_state(stdout: &str) -> Vec<(String, String)> {
    let line = stdout.lines().rev().find(|l| l.starts_with("saved ")).expect("a 'saved' line");
    state_of(line)
}

fn state_of(line: &str) -> Vec<(String, String)> {
    let inside = &line[line.find('(').unwrap() + 1..line.rfind(')').unwrap()];
    inside
        .split_whitespace()
        .filter_map(|kv| kv.split_once('='))
        .map(|(k, v)| (k.to_owned(), v.to_owned()))
        .collect()
}

/// Every `saved PATH (…)` line in order: the file and the state it shows.
#[cfg(feature = "gpu")]
fn saved_all(stdout: &str) -> Vec<(PathBuf, Vec<(String, String)>)> {
    stdout
        .lines()
        .filter(|l| l.starts_with("saved "))
        .map(|l| {
            let path = l["saved ".len()..l.find(" (").unwrap()].to_owned();
            (PathBuf::from(path), state_of(l))
        })
        .collect()
}

fn get<'a>(state: &'a [(String, String)], key: &str) -> &'a str {
    &state.iter().find(|(k, _)| k == key).unwrap_or_else(|| panic!("no {key} in {state:?}")).1
}

/// The course app in `state`, rendered by cg_raster without a window.
fn headless_render(state: &[(String, String)]) -> (Vec<[u8; 4]>, u32, u32) {
    let mut app = CourseApp::course_sample();
    let f = |k: &str| get(state, k).parse::<f32>().unwrap();
    app.camera = OrbitCamera {
        yaw_deg: f("yaw"),
        pitch_deg: f("pitch"),
        distance: f("distance"),
        ..app.camera
    };
    app.angle_deg = f("angle");
    app.shading = match get(state, "shading") {
        "flat" => Shading::Flat,
        "phong" => Shading::Phong,
        _ => Shading::Gouraud,
    };
    app.light =
        if get(state, "light") == "lecture" { LightChoice::Lecture } else { LightChoice::OpenGl };
    let (w, h) = get(state, "size").split_once('x').unwrap();
    let (w, h) = (w.parse().unwrap(), h.parse().unwrap());
    app.size = (w, h);
    let out = cg_raster::render(&app.scene(), &cg_raster::Options::default()).unwrap();
    (out.image.to_rgba8(), w, h)
}

fn assert_png_is_headless_render(name: &str, png: &Path, state: &[(String, String)]) {
    assert_png_is_headless_render_within(name, png, state, 0);
}

/// As [`assert_png_is_headless_render`], every channel within `per_channel`/255 (the GPU's
/// frames: within 2/255 of the CPU rasterizer's, `crates/gpu/tests/compare.rs`).
fn assert_png_is_headless_render_within(
    name: &str,
    png: &Path,
    state: &[(String, String)],
    per_channel: u8,
) {
    let (actual, w, h) = read_png(png).unwrap_or_else(|| panic!("{} is not a PNG", png.display()));
    let (expected, ew, eh) = headless_render(state);
    assert_eq!((w, h), (ew, eh), "screenshot size");
    assert_images_match(name, &actual, &expected, w, h, Tolerance::all_within(per_channel));
}

#[test]
fn without_a_display_it_renders_a_png_and_says_so() {
    let dir = scratch("nodisplay");
    let out = Command::new(BIN)
        .env("CG_LANG", "en")
        .env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .args(["--frames", "3", "--width", "160", "--height", "120", "--out"])
        .arg(&dir)
        .output()
        .unwrap();
    let all = text(&out);
    assert!(out.status.success(), "{all}");
    assert!(all.contains("no window can be opened"), "{all}");
    let png = dir.join("view.png");
    let state = saved_state(&String::from_utf8_lossy(&out.stdout));
    // Three frames, two idle steps of 1/60 s at 45°/s.
    let angle: f32 = get(&state, "angle").parse().unwrap();
    assert!((angle - 1.5).abs() < 1e-5, "{all}");
    assert_eq!(get(&state, "size"), "160x120");
    assert_png_is_headless_render("nodisplay", &png, &state);
}

#[test]
fn headless_writes_the_screenshot_path_in_the_shading_asked_for() {
    let dir = scratch("headless");
    let shot = dir.join("sub/shot.png");
    let out = Command::new(BIN)
        .env("CG_LANG", "en")
        .args(["--headless", "--paused", "--shading", "phong", "--width", "96", "--height", "64"])
        .arg("--screenshot")
        .arg(&shot)
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", text(&out));
    let state = saved_state(&String::from_utf8_lossy(&out.stdout));
    assert_eq!(get(&state, "shading"), "phong");
    assert_eq!(get(&state, "angle"), "0");
    assert_png_is_headless_render("headless-phong", &shot, &state);
}

#[test]
fn a_missing_scene_file_is_an_error_message_not_a_panic() {
    let out = Command::new(BIN)
        .env("CG_LANG", "en")
        .args(["--headless", "no/such/scene.toml"])
        .output()
        .unwrap();
    let all = text(&out);
    assert_eq!(out.status.code(), Some(2), "{all}");
    assert!(all.contains("error:") && all.contains("scene.toml"), "{all}");
    assert!(!all.contains("panicked"), "{all}");
    // The same in Japanese (`--lang ja`, or CG_LANG=ja).
    let out = Command::new(BIN)
        .args(["--headless", "--lang", "ja", "no/such/scene.toml"])
        .output()
        .unwrap();
    let all = text(&out);
    assert_eq!(out.status.code(), Some(2), "{all}");
    assert!(all.contains("エラー:") && all.contains("読めません"), "{all}");
}

/// Whether the window tests can run: xvfb-run and xdotool on PATH. Without them the test is
/// skipped with a note, except under CI, where that is a failure.
fn xvfb_available(test: &str) -> bool {
    let found = |tool: &str| {
        Command::new("sh")
            .args(["-c", &format!("command -v {tool}")])
            .output()
            .is_ok_and(|o| o.status.success())
    };
    if found("xvfb-run") && found("xdotool") {
        return true;
    }
    assert!(
        std::env::var_os("CI").is_none(),
        "{test}: xvfb-run and xdotool are needed under CI (apt-get install xvfb xauth xdotool)"
    );
    eprintln!(
        "note: {test} skipped: xvfb-run or xdotool is missing (apt-get install xvfb xauth xdotool)"
    );
    false
}

/// One Xvfb server at a time: `xvfb-run -a` picks a free display number, but two started at
/// the same moment can pick the same one.
static XVFB: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Runs `script` under a fresh Xvfb server with `$BIN` set to the viewer.
fn under_xvfb(script: &str) -> Output {
    let _one = XVFB.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
    Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1024x768x24", "bash", "-c", script])
        .env("BIN", BIN)
        .env("CG_LANG", "en")
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .unwrap()
}

#[test]
fn window_right_drag_and_screenshot_match_the_headless_render() {
    if !xvfb_available("window_right_drag_and_screenshot_match_the_headless_render") {
        return;
    }
    let dir = scratch("xvfb-drag");
    let shot = dir.join("drag.png");
    // Right-drag 40 px down and 30 px right: pitch −30 − 40 = −70, yaw 0 − 30 = 330. Then `s`
    // (the app's own screenshot, read back from the window) and `q`.
    let script = format!(
        r#"set -u
timeout 90 "$BIN" --paused --width 320 --height 320 --screenshot '{shot}' --out '{dir}' &
PID=$!
WID=$(timeout 30 xdotool search --sync --onlyvisible --name 'cg viewer' | head -1)
[ -n "$WID" ] || {{ echo "no window"; kill $PID; exit 3; }}
sleep 0.5
xdotool mousemove --window $WID 100 100 mousedown 3 \
  mousemove --window $WID 100 120 mousemove --window $WID 115 130 mousemove --window $WID 130 140 mouseup 3
sleep 0.5
xdotool windowfocus --sync $WID
xdotool key s
sleep 0.5
xdotool key q
wait $PID
"#,
        shot = shot.display(),
        dir = dir.display()
    );
    let out = under_xvfb(&script);
    let all = text(&out);
    assert!(out.status.success(), "{all}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(stdout.matches("saved ").count(), 2, "the s key and the exit both save: {all}");
    let state = saved_state(&stdout);
    assert_eq!(get(&state, "pitch"), "-70", "{all}");
    assert_eq!(get(&state, "yaw"), "330", "{all}");
    assert_eq!(get(&state, "source"), "window", "read back from the window: {all}");
    assert_png_is_headless_render("xvfb-drag", &shot, &state);
}

#[test]
fn window_frames_limit_exits_by_itself_and_the_animation_runs() {
    if !xvfb_available("window_frames_limit_exits_by_itself_and_the_animation_runs") {
        return;
    }
    let dir = scratch("xvfb-frames");
    let shot = dir.join("frames.png");
    let script = format!(
        "timeout 90 \"$BIN\" --frames 4 --shading flat --width 200 --height 150 --screenshot '{}'",
        shot.display()
    );
    let out = under_xvfb(&script);
    let all = text(&out);
    assert!(out.status.success(), "{all}");
    let state = saved_state(&String::from_utf8_lossy(&out.stdout));
    assert_eq!(get(&state, "pitch"), "-30", "{all}");
    assert_eq!(get(&state, "source"), "window", "{all}");
    // The animation ran (idle between frames); the screenshot's state is the last frame's.
    assert!(get(&state, "angle").parse::<f32>().unwrap() > 0.0, "{all}");
    assert_png_is_headless_render("xvfb-frames", &shot, &state);
}

/// Runs `script` with `$BIN` set to the viewer under a fresh weston compositor with its headless
/// backend (a Wayland session with no X server: `DISPLAY` removed), in a runtime folder of its
/// own. `None` when weston is missing, except under CI, where that is a failure.
fn under_weston(test: &str, script: &str) -> Option<Output> {
    let found = Command::new("sh")
        .args(["-c", "command -v weston"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        assert!(
            std::env::var_os("CI").is_none(),
            "{test}: weston is needed under CI (apt-get install weston)"
        );
        eprintln!("note: {test} skipped: weston is missing (apt-get install weston)");
        return None;
    }
    let runtime = scratch(&format!("{test}-runtime"));
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&runtime, std::fs::Permissions::from_mode(0o700)).unwrap();
    }
    let socket = "cg-viewer-test";
    let mut weston = Command::new("weston")
        .args(["--backend=headless-backend.so", &format!("--socket={socket}"), "--idle-time=0"])
        .env("XDG_RUNTIME_DIR", &runtime)
        .env_remove("DISPLAY")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let started = std::time::Instant::now();
    while !runtime.join(socket).exists() && started.elapsed() < std::time::Duration::from_secs(20) {
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    let out = Command::new("bash")
        .args(["-c", script])
        .env("BIN", BIN)
        .env("CG_LANG", "en")
        .env("XDG_RUNTIME_DIR", &runtime)
        .env("WAYLAND_DISPLAY", socket)
        .env_remove("DISPLAY")
        .output()
        .unwrap();
    let _ = weston.kill();
    let _ = weston.wait();
    Some(out)
}

#[test]
fn a_wayland_window_draws_its_frames_and_the_screenshot_matches_the_headless_render() {
    let test = "wayland-frames";
    let dir = scratch(test);
    let shot = dir.join("frames.png");
    let script = format!(
        "timeout 90 \"$BIN\" --frames 6 --shading flat --width 200 --height 150 --screenshot '{}'",
        shot.display()
    );
    let Some(out) = under_weston(test, &script) else { return };
    let all = text(&out);
    assert!(out.status.success(), "{all}");
    assert!(!all.contains("no window can be opened"), "a window on Wayland: {all}");
    let state = saved_state(&String::from_utf8_lossy(&out.stdout));
    assert_eq!(get(&state, "pitch"), "-30", "{all}");
    // Drawn in the window (softbuffer cannot read a Wayland window back: the frame drawn).
    assert_eq!(get(&state, "source"), "frame", "{all}");
    assert!(get(&state, "angle").parse::<f32>().unwrap() > 0.0, "{all}");
    assert_png_is_headless_render(test, &shot, &state);
}

/// Whether the GPU window tests can run: Xvfb and xdotool ([`xvfb_available`]) and a GPU
/// adapter (lavapipe in CI). Without an adapter the test is skipped with a note, except under CI.
#[cfg(feature = "gpu")]
fn gpu_window_available(test: &str) -> bool {
    if !xvfb_available(test) {
        return false;
    }
    match cg_viewer::GpuBackend::new(cg_core::lang::Lang::En) {
        Ok(_) => true,
        Err(why) => {
            assert!(std::env::var_os("CI").is_none(), "{test}: CI has lavapipe: {why}");
            eprintln!("note: {test} skipped: no GPU adapter ({why})");
            false
        }
    }
}

#[cfg(feature = "gpu")]
#[test]
fn window_gpu_presents_to_its_surface_and_the_screenshot_matches_the_cpu() {
    let test = "window_gpu_presents_to_its_surface_and_the_screenshot_matches_the_cpu";
    if !gpu_window_available(test) {
        return;
    }
    let dir = scratch("xvfb-gpu");
    let shot = dir.join("gpu.png");
    let script = format!(
        "timeout 120 \"$BIN\" --renderer gpu --frames 5 --shading phong --width 200 --height 150 \
         --screenshot '{}' --out '{}'",
        shot.display(),
        dir.display()
    );
    let out = under_xvfb(&script);
    let all = text(&out);
    assert!(out.status.success(), "{all}");
    assert!(!all.contains("cannot present"), "the GPU presented to the window: {all}");
    let state = saved_state(&String::from_utf8_lossy(&out.stdout));
    // The frame the GPU presented, drawn again into a texture and read back…
    assert_eq!(get(&state, "source"), "presented", "{all}");
    // …is what the window shows: X11 reads the window's pixels back (nothing else ever drew
    // into this window, so a frame that never reached it would show as a large difference).
    assert_eq!(get(&state, "window_diff"), "0", "{all}");
    assert_eq!(get(&state, "shading"), "phong", "{all}");
    // Five frames with the animation running: the state is the last frame's.
    assert!(get(&state, "angle").parse::<f32>().unwrap() > 0.0, "{all}");
    assert_png_is_headless_render_within("xvfb-gpu", &shot, &state, 2);
}

#[cfg(feature = "gpu")]
#[test]
fn window_r_switches_cpu_gpu_cpu_and_every_screenshot_matches() {
    let test = "window_r_switches_cpu_gpu_cpu_and_every_screenshot_matches";
    if !gpu_window_available(test) {
        return;
    }
    let dir = scratch("xvfb-switch");
    // CPU (softbuffer), `s`; `r` to the GPU (softbuffer's surface dropped, a wgpu surface made),
    // `s`; `r` back to the CPU (the wgpu surface dropped, softbuffer's made again), `s`; `r` to
    // the GPU once more (a new wgpu surface on the same window), `s`; the window resized (the
    // surface configured again), `s`; then `q`.
    let script = format!(
        r#"set -u
timeout 120 "$BIN" --renderer cpu --paused --width 160 --height 120 --out '{dir}' &
PID=$!
WID=$(timeout 30 xdotool search --sync --onlyvisible --name 'cg viewer' | head -1)
[ -n "$WID" ] || {{ echo "no window"; kill $PID; exit 3; }}
sleep 0.5
xdotool windowfocus --sync $WID
for k in s r s r s r s; do xdotool key $k; sleep 1; done
xdotool windowsize --sync $WID 200 100
sleep 1
xdotool key s
sleep 1
xdotool key q
wait $PID
"#,
        dir = dir.display()
    );
    let out = under_xvfb(&script);
    let all = text(&out);
    assert!(out.status.success(), "{all}");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(stdout.matches("renderer: ").count(), 3, "three switches: {all}");
    let saved = saved_all(&stdout);
    assert_eq!(saved.len(), 5, "five screenshots: {all}");
    let sources: Vec<&str> = saved.iter().map(|(_, s)| get(s, "source")).collect();
    assert_eq!(sources, ["window", "presented", "window", "presented", "presented"], "{all}");
    assert_eq!(get(&saved[3].1, "size"), "160x120", "{all}");
    assert_eq!(get(&saved[4].1, "size"), "200x100", "after the resize: {all}");
    for (k, (png, state)) in saved.iter().enumerate() {
        assert_eq!(png, &dir.join(format!("screenshot-{:03}.png", k + 1)), "{all}");
        if get(state, "source") == "presented" {
            assert_eq!(get(state, "window_diff"), "0", "shot {}: {all}", k + 1);
            assert_png_is_headless_render_within(&format!("xvfb-switch-{k}"), png, state, 2);
        } else {
            // Back on the CPU, the window shows softbuffer's image again, exactly.
            assert_png_is_headless_render(&format!("xvfb-switch-{k}"), png, state);
        }
    }
}

/// A build without the GPU renderer (the students' copy): `--renderer gpu` says so, in the
/// user's language, with the command that builds it and runs the same again (exit status 2).
#[cfg(not(feature = "gpu"))]
#[test]
fn without_the_gpu_feature_asking_for_the_gpu_gives_the_command_that_builds_it() {
    let dir = scratch("no-gpu");
    let d = dir.to_str().unwrap();
    for (lang, says) in
        [("en", "built without the GPU renderer"), ("ja", "GPU レンダラ（wgpu）なしでビルド")]
    {
        let args = ["--renderer", "gpu", "--headless", "--frames", "1", "--out", d, "--lang", lang];
        let out = Command::new(BIN).args(args).output().unwrap();
        let all = text(&out);
        assert_eq!(out.status.code(), Some(2), "{all}");
        assert!(all.contains(says), "{all}");
        let command =
            format!("cargo run --release -p cg-viewer --features gpu -- {}", args.join(" "));
        assert!(all.contains(&command), "{command}\n{all}");
        assert!(std::fs::read_dir(&dir).unwrap().next().is_none(), "nothing drawn: {all}");
    }
}
