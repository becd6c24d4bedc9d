//! `cg view --yaw --pitch --distance`: the PNG view from another side (the bottom of a model),
//! for the views whose camera is the orbit camera; a clear refusal where the student's own
//! display() sets the camera, and for values out of range.

mod common;

use common::{cg, root, scratch};

/// The reference picture of `cg view a1` with `extra` options, as PNG bytes' pixels.
fn a1_reference(test: &str, extra: &[&str]) -> Vec<u8> {
    let dir = scratch("cg-view-camera", test);
    let out = dir.to_str().unwrap();
    let mut args = vec!["view", "a1", "--student", "12345678", "--png", "-o", out, "--lang", "en"];
    args.extend_from_slice(extra);
    let o = cg(&root(), &args);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{stdout}{}", String::from_utf8_lossy(&o.stderr));
    let file = dir.join("view-a1-reference.png");
    assert!(stdout.contains("view-a1-reference.png"), "{stdout}");
    image::open(&file).unwrap().to_rgba8().into_raw()
}

#[test]
fn the_orbit_camera_moves_to_the_side_and_below() {
    let default = a1_reference("default", &[]);
    // The options given as the scene already has them: the same picture.
    let same = a1_reference("same", &["--yaw", "0", "--pitch", "-30", "--distance", "15"]);
    let below = a1_reference("below", &["--pitch", "60"]);
    let turned = a1_reference("turned", &["--yaw", "-90"]);
    let far = a1_reference("far", &["--distance", "40"]);
    assert_ne!(below, default, "from below is another picture");
    assert_ne!(turned, default);
    assert_ne!(far, default);
    assert_ne!(below, turned);
    // The a1 view's camera is the course sample's (yaw 0, pitch −30, distance 15).
    assert!(same == default, "the same camera given on the command line");
}

#[test]
fn a_camera_set_by_the_students_display_is_not_moved_and_values_are_checked() {
    let dir = scratch("cg-view-camera", "refused");
    let out = dir.to_str().unwrap();
    let o =
        cg(&root(), &["view", "a3", "--student", "12345678", "--png", "-o", out, "--yaw", "10"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--yaw") && stderr.contains("display()"), "{stderr}");
    let o = cg(&root(), &["view", "a1", "--png", "--pitch", "100", "--lang", "ja"]);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--pitch") && stderr.contains("-90 … 90"), "{stderr}");
    let o = cg(&root(), &["view", "a1", "--png", "--distance", "nan"]);
    assert_eq!(o.status.code(), Some(2));
}
