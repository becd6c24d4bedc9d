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

#[test]
fn the_shading_sets_spheres_are_labelled() {
    let dir = scratch("cg-view-camera", "labels");
    let out = dir.to_str().unwrap();
    let o = cg(&root(), &["view", "s", "--student", "12345678", "--png", "-o", out]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Both pictures: the student's (the pristine stubs still draw) and the reference.
    for side in ["yours", "reference"] {
        let image = image::open(dir.join(format!("view-s-{side}.png"))).unwrap().to_rgba8();
        let (w, h) = image.dimensions();
        // White label ink on the ground in front of each sphere (the spheres end above it).
        for third in 0..3 {
            let ink = (h * 55 / 100..h * 62 / 100)
                .flat_map(|y| (third * w / 3..(third + 1) * w / 3).map(move |x| (x, y)))
                .filter(|&(x, y)| image.get_pixel(x, y).0 == [255, 255, 255, 255])
                .count();
            assert!(ink > 20, "{side}: no label under sphere {third} ({ink} white pixels)");
        }
    }
}

#[test]
fn the_view_writes_the_difference_and_leaves_no_stale_picture() {
    let dir = scratch("cg-view-camera", "difference");
    let out = dir.to_str().unwrap();
    // a4's stubs draw a picture of their own: the difference is written and counted.
    let o =
        cg(&root(), &["view", "a4", "--student", "12345678", "--png", "-o", out, "--lang", "en"]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{stdout}");
    assert!(
        stdout.contains("pixels differ by more than 2/255") && stdout.contains("view-a4-diff.png")
    );
    let load = |name: &str| image::open(dir.join(name)).unwrap().to_rgba8();
    let (yours, reference, diff) =
        (load("view-a4-yours.png"), load("view-a4-reference.png"), load("view-a4-diff.png"));
    // Each difference pixel is 4 × |yours − reference| (clamped), black where they agree.
    for ((p, q), d) in yours.pixels().zip(reference.pixels()).zip(diff.pixels()).step_by(97) {
        for c in 0..3 {
            let expected = (u32::from(p[c].abs_diff(q[c])) * 4).min(255);
            assert!(u32::from(d[c]).abs_diff(expected) <= 1, "{p:?} {q:?} {d:?}");
        }
    }
    // a1's stubs are not done: no picture of yours and no difference, not even older ones.
    for stale in ["view-a1-yours.png", "view-a1-diff.png"] {
        std::fs::copy(dir.join("view-a4-yours.png"), dir.join(stale)).unwrap();
    }
    let o = cg(&root(), &["view", "a1", "--student", "12345678", "--png", "-o", out]);
    assert!(o.status.success());
    assert!(!dir.join("view-a1-yours.png").exists() && !dir.join("view-a1-diff.png").exists());
    assert!(dir.join("view-a1-reference.png").exists());
}

#[test]
fn a_strip_lays_out_one_period_of_the_animation() {
    let dir = scratch("cg-view-camera", "strip");
    let out = dir.to_str().unwrap();
    let o = cg(&root(), &["view", "a3", "--student", "12345678", "-o", out, "--strip", "4"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // Named as a strip: the single frame's pictures (view-a3-*.png) stay as they are.
    assert!(!dir.join("view-a3-reference.png").exists(), "a strip has names of its own");
    let strip = image::open(dir.join("view-a3-strip-reference.png")).unwrap().to_rgba8();
    // Four half-size frames (320 × 320) in one row, each over its time's label strip.
    assert_eq!(strip.dimensions(), (4 * 320, 320 + 24));
    let frame = |k: u32| -> Vec<[u8; 4]> {
        (0..320)
            .flat_map(|y| (0..320).map(move |x| (k * 320 + x, y)))
            .map(|(x, y)| strip.get_pixel(x, y).0)
            .collect()
    };
    assert_ne!(frame(0), frame(1), "the animation moves between frames");
    // A still view has no period to lay out.
    let o = cg(&root(), &["view", "a1", "--student", "12345678", "-o", out, "--strip", "4"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("--strip"), "{err}");
}
