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

/// An open window starts again when the student's functions are rebuilt (`cg watch` rebuilds
/// their worker, `cg-check-runner`, on every save): the window is opened, the worker's program
/// replaced as a rebuild replaces it (a new file with a new time stamp, renamed into place), and
/// the view opens again, started with the time it had reached.
#[test]
fn an_open_view_starts_again_when_its_program_is_rebuilt() {
    if !xvfb_run_available() {
        return;
    }
    let dir = scratch("view-window", "reload");
    // The worker built first, outside the window's time limit (a first build takes a while).
    let built = common::cg(&root(), &["check", "a1.t1.count", "--student", "12345678"]);
    assert!(built.status.code().is_some_and(|c| c <= 1), "{built:?}");
    let worker = cg_assign::local::worker_program();
    assert!(worker.is_file(), "{}", worker.display());
    let rebuild = {
        let worker = worker.clone();
        std::thread::spawn(move || {
            std::thread::sleep(std::time::Duration::from_secs(6));
            // What a rebuild does: a new file put in the old one's place, with a new time stamp.
            let new = worker.with_extension("new");
            std::fs::copy(&worker, &new).unwrap();
            let file = std::fs::File::open(&new).unwrap();
            file.set_modified(std::time::SystemTime::now() + std::time::Duration::from_secs(5))
                .unwrap();
            std::fs::rename(&new, &worker).unwrap();
        })
    };
    let out = Command::new("timeout")
        .args(["-s", "TERM", "20", "xvfb-run", "-a", "-s", "-screen 0 1600x900x24"])
        .arg(env!("CARGO_BIN_EXE_cg"))
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
