//! `cg view` in a window (under Xvfb): the student's result and the reference side by side. The
//! window's own pixels (read back by the viewer's screenshot) show the reference exactly as the
//! PNG path draws it, and the student's stub panel empty.

mod common;

use std::process::Command;

use common::{root, scratch};

fn xvfb_run_available() -> bool {
    let found = Command::new("sh")
        .args(["-c", "command -v xvfb-run"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        assert!(std::env::var_os("CI").is_none(), "xvfb-run is needed under CI (scripts/setup.sh)");
        eprintln!("note: the window test of cg view is skipped: xvfb-run is missing");
    }
    found
}

#[test]
fn view_opens_a_window_with_yours_and_the_reference_side_by_side() {
    if !xvfb_run_available() {
        return;
    }
    let dir = scratch("view-window", "a1");
    let shot = dir.join("window.png");
    let out = Command::new("xvfb-run")
        .args(["-a", "-s", "-screen 0 1600x900x24"])
        .arg(env!("CARGO_BIN_EXE_cg"))
        .args(["--lang", "en", "view", "a1", "--student", "12345678", "--frames", "2", "--paused"])
        .arg("--screenshot")
        .arg(&shot)
        .arg("-o")
        .arg(&dir)
        .current_dir(root())
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("CG_NO_WINDOW")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{stdout}\n{stderr}");
    assert!(!stderr.contains("no window can be opened"), "a window opened:\n{stderr}");
    assert!(stdout.contains("yours: not done yet"), "the stub panel says why:\n{stdout}");

    // The same views as PNG files (no display).
    let png = common::cg(
        &root(),
        &["view", "a1", "--student", "12345678", "-o", dir.to_str().unwrap(), "--png"],
    );
    assert!(png.status.success(), "{}", String::from_utf8_lossy(&png.stderr));
    let window = image::open(&shot).unwrap().to_rgb8();
    let reference = image::open(dir.join("view-a1-reference.png")).unwrap().to_rgb8();
    let (w, h) = reference.dimensions();
    assert_eq!(window.dimensions(), (2 * w, h), "two panels of the reference's size");
    let mut differ = 0;
    for y in 0..h {
        for x in 1..w {
            let (a, b) = (window.get_pixel(w + x, y), reference.get_pixel(x, y));
            if a.0.iter().zip(b.0).any(|(p, q)| p.abs_diff(q) > 1) {
                differ += 1;
            }
        }
        let empty = window.get_pixel(w / 2, y);
        assert!(
            empty.0.iter().all(|&c| c.abs_diff(38) <= 1),
            "the stub's panel is grey: {empty:?}"
        );
    }
    assert_eq!(differ, 0, "the reference panel shows the reference as the PNG path draws it");
}

/// An open window starts again when its program is rebuilt (`cg watch` rebuilds it on every
/// save): the program is copied, the window opened from the copy, the copy's time stamp changed
/// as a rebuild changes it, and the view opens again, the same program started with the time it
/// had reached.
#[test]
fn an_open_view_starts_again_when_its_program_is_rebuilt() {
    if !xvfb_run_available() {
        return;
    }
    let dir = scratch("view-window", "reload");
    let program = dir.join(if cfg!(windows) { "cg.exe" } else { "cg" });
    std::fs::copy(env!("CARGO_BIN_EXE_cg"), &program).unwrap();
    let rebuild = {
        let program = program.clone();
        std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_secs(6));
            // What a rebuild does: a new file put in the old one's place, with a new time stamp.
            let new = program.with_extension("new");
            std::fs::copy(env!("CARGO_BIN_EXE_cg"), &new).unwrap();
            let file = std::fs::File::open(&new).unwrap();
            file.set_modified(std::time::SystemTime::now() + std::time::Duration::from_secs(5))
                .unwrap();
            std::fs::rename(&new, &program).unwrap();
        })
    };
    let out = Command::new("timeout")
        .args(["-s", "TERM", "14", "xvfb-run", "-a", "-s", "-screen 0 1600x900x24"])
        .arg(&program)
        .args(["--lang", "en", "view", "a1", "--student", "12345678", "-o"])
        .arg(&dir)
        .current_dir(root())
        .env_remove("WAYLAND_DISPLAY")
        .env_remove("CG_NO_WINDOW")
        .env_remove("CG_VIEW_RESUME")
        .output()
        .unwrap();
    rebuild.join().unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("no window can be opened"), "a window opened:\n{stderr}");
    assert!(
        stdout.contains("the program was rebuilt: opening the view again"),
        "the view says why it closed:\n{stdout}\n{stderr}"
    );
    assert_eq!(stdout.matches("controls:").count(), 2, "opened twice:\n{stdout}");
}
