//! The course's sample scene (`assets/scenes/course-sample.toml`) drawn by OpenGL: where the
//! pyramid, the ground and the background are, by the kit's own view and projection.
//!
//! The image is written to `target/test-images/glref-course-sample.png` to be looked at.

mod common;

use std::path::Path;

use cg_core::glam::{Vec2, Vec3};
use cg_core::shapes::lecture_pyramid;
use common::*;

/// The pyramid's colour (1.0, 0.6, 0.2) keeps red > green > blue under any white light; the
/// ground's (0.5, 0.8, 0.5) has green on top, the background (0.5, 0.5, 0.8) blue.
fn is_pyramid(p: [u8; 3]) -> bool {
    p[0] > p[1] + 8 && p[1] > p[2] + 8
}

fn is_ground(p: [u8; 3]) -> bool {
    p[1] > p[0] + 8 && p[1] > p[2] + 8
}

/// The convex hull of `points`, counter-clockwise in screen space as a y-up viewer sees it
/// (monotone chain).
fn convex_hull(mut points: Vec<Vec2>) -> Vec<Vec2> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    let mut hull: Vec<Vec2> = Vec::new();
    for pass in 0..2 {
        let start = hull.len();
        for &p in &points {
            while hull.len() >= start + 2
                && (hull[hull.len() - 1] - hull[hull.len() - 2]).perp_dot(p - hull[hull.len() - 2])
                    <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
        if pass == 0 {
            points.reverse();
        }
    }
    hull
}

/// How far `p` lies outside the convex polygon `hull` at least (the largest distance past one of
/// its edge lines; ≤ 0 inside).
fn outside_distance(hull: &[Vec2], p: Vec2) -> f32 {
    let n = hull.len();
    (0..n)
        .map(|i| {
            let (a, b) = (hull[i], hull[(i + 1) % n]);
            -(b - a).perp_dot(p - a) / (b - a).length()
        })
        .fold(f32::NEG_INFINITY, f32::max)
}

#[test]
fn the_course_sample_shows_the_pyramid_where_it_projects_on_the_ground_under_the_background() {
    if !cg_glref::require() {
        return;
    }
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/scenes/course-sample.toml");
    let s = cg_scene::load(Path::new(path)).unwrap();
    let (w, h) = (s.width, s.height);
    let image = cg_glref::render(&s).unwrap_or_else(|e| panic!("{e}"));
    let rgba = image.to_rgba8();
    let out = cg_testkit::images::output_dir().join("glref-course-sample.png");
    cg_testkit::images::write_png(&out, &rgba, w, h);
    let pixels: Vec<[u8; 3]> = rgba.iter().map(|&[r, g, b, _]| [r, g, b]).collect();
    let at = |x: u32, y: u32| pixels[(y * w + x) as usize];
    let note = format!("(the image: {})", out.display());

    // The pyramid, moved up by glTranslatef(0, 1, 0), projected by the kit's matrices.
    let pyramid = lecture_pyramid();
    let screen: Vec<Vec2> = pyramid.positions.iter().map(|&p| project(&s, p + Vec3::Y)).collect();
    let mut inside_checked = 0;
    for face in &pyramid.faces {
        let t = face.map(|i| screen[i as usize]);
        if screen_area2(t[0], t[1], t[2]) <= 0.0 {
            continue; // faces away from the camera: culled
        }
        // Pixels whose centres lie at least 2 px inside the projected face.
        let (lo, hi) = (t[0].min(t[1]).min(t[2]), t[0].max(t[1]).max(t[2]));
        for y in lo.y as u32..=hi.y as u32 {
            for x in lo.x as u32..=hi.x as u32 {
                let centre = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
                if inside_distances(t, centre).iter().all(|&d| d >= 2.0) {
                    inside_checked += 1;
                    assert!(
                        is_pyramid(at(x, y)),
                        "pixel ({x}, {y}) lies inside the pyramid's face {face:?} but shows {:?} {note}",
                        at(x, y)
                    );
                }
            }
        }
    }
    assert!(inside_checked > 1000, "only {inside_checked} pixels inside the visible faces");

    // The ground's corners (±5, 0, ±5) and the pyramid's outline on the screen.
    let ground: Vec<Vec2> = [(-5.0, -5.0), (5.0, -5.0), (5.0, 5.0), (-5.0, 5.0)]
        .map(|(x, z)| project(&s, Vec3::new(x, 0.0, z)))
        .to_vec();
    let ground_hull = convex_hull(ground);
    let pyramid_hull = convex_hull(screen);
    let (mut ground_checked, mut background_checked) = (0, 0);
    for y in 0..h {
        for x in 0..w {
            let centre = Vec2::new(x as f32 + 0.5, y as f32 + 0.5);
            let p = at(x, y);
            let off_pyramid = outside_distance(&pyramid_hull, centre);
            if off_pyramid < 3.0 {
                continue;
            }
            assert!(
                !is_pyramid(p),
                "pixel ({x}, {y}) lies {off_pyramid:.1} px outside the pyramid's outline but shows its colour {p:?} {note}"
            );
            let off_ground = outside_distance(&ground_hull, centre);
            if off_ground >= 3.0 {
                background_checked += 1;
                assert_eq!(
                    p, BACKGROUND,
                    "pixel ({x}, {y}) lies outside the ground and the pyramid {note}"
                );
            } else if off_ground <= -3.0 {
                ground_checked += 1;
                assert!(is_ground(p), "pixel ({x}, {y}) lies on the ground but shows {p:?} {note}");
            }
        }
    }
    assert!(
        ground_checked > 50_000 && background_checked > 50_000,
        "{ground_checked} {background_checked}"
    );
    // The top corners are sky: the camera looks down at 30°.
    assert_eq!(at(0, 0), BACKGROUND);
    assert_eq!(at(w - 1, 0), BACKGROUND);
}
