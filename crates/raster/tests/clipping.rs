//! NUMERICS row 21: triangles crossing the near plane, or behind the camera, are clipped
//! correctly; nothing behind the eye is drawn; nothing is divided by w ≤ 0; no NaN anywhere.
//!
//! The oracle is the analytic projection, in f64, of the part of each triangle in front of the
//! near plane (clipped by hand here), compared pixel by pixel away from its edges.

mod common;

use cg_core::Rgb;
use cg_core::glam::{DVec2, DVec3, Vec3};
use cg_raster::{Options, Output, render};
use common::{Pinhole, inside_by, looking_down_z, object, triangle, unlit};

const RED: Rgb = Rgb::new(1.0, 0.0, 0.0);
/// RED and black in 8 bits (colours are compared after the rounding to the framebuffer: the
/// interpolated colour of a constant-coloured triangle can differ from it in the last bit).
const RED8: [u8; 4] = [255, 0, 0, 255];
const BLACK8: [u8; 4] = [0, 0, 0, 255];

/// No NaN or infinity in the colour or depth buffer, and every depth in `[0, 1]`.
fn assert_finite(out: &Output) {
    for (i, c) in out.image.pixels.iter().enumerate() {
        assert!(
            c.is_finite() && c.min_element() >= 0.0 && c.max_element() <= 1.0,
            "pixel {i} is {c}"
        );
    }
    for (i, z) in out.depth.iter().enumerate() {
        assert!((0.0..=1.0).contains(z), "depth {i} is {z}");
    }
}

/// `polygon` (view space, z ≤ −near) cut at the near plane by hand: the part with z ≤ −near.
fn clip_near(polygon: &[DVec3], near: f64) -> Vec<DVec3> {
    let mut out = Vec::new();
    for i in 0..polygon.len() {
        let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
        let (da, db) = (-a.z - near, -b.z - near);
        if da >= 0.0 {
            out.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            out.push(a + (b - a) * (da / (da - db)));
        }
    }
    out
}

/// Draws `corners` (view space = world space) as one red, unlit triangle on black and checks every
/// pixel against the analytic projection of its part in front of the near plane: pixels whose
/// centres lie more than `margin` pixels inside it are red with the depth of the triangle's plane
/// there, pixels more than `margin` outside are black with depth 1.
fn assert_clipped_like_the_analytic_projection(
    name: &str,
    corners: [Vec3; 3],
    size: u32,
) -> Output {
    let mut scene = looking_down_z(size, size, 90.0);
    scene.cull_back_faces = false;
    scene.objects.push(object(name, triangle(corners[0], corners[1], corners[2]), unlit(RED)));
    let out = render(&scene, &Options::default()).unwrap();
    assert_finite(&out);

    let camera = Pinhole::of(&scene);
    let visible = clip_near(&corners.map(Vec3::as_dvec3), camera.near);
    let on_screen: Vec<DVec2> = visible.iter().map(|&p| camera.window(p)).collect();
    let [a, b, c] = corners.map(Vec3::as_dvec3);
    let normal = (b - a).cross(c - a);
    let margin = 0.01;
    let rgba = out.image.to_rgba8();
    let (mut inside, mut outside) = (0, 0);
    for y in 0..size {
        for x in 0..size {
            let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let at = (y * size + x) as usize;
            let (color, depth) = (rgba[at], out.depth[at]);
            let d = if on_screen.len() >= 3 { inside_by(&on_screen, centre) } else { -1.0 };
            if d > margin {
                inside += 1;
                // The window depth where the ray through `w` meets the triangle's plane.
                let plane_depth = |w: DVec2| {
                    let ray = camera.ray(w);
                    camera.depth((ray * (normal.dot(a) / normal.dot(ray))).z)
                };
                let expected = plane_depth(centre);
                // Corners are snapped to 1/256 pixel (up to 1/512 per axis), which moves the
                // interpolated plane: allow the depth change over 2/256 pixel, plus f32 rounding.
                let step = 2.0 / 256.0;
                let slope = (plane_depth(centre + DVec2::X * step) - expected).abs()
                    + (plane_depth(centre + DVec2::Y * step) - expected).abs();
                let tolerance = slope + 1e-6;
                assert_eq!(
                    color, RED8,
                    "{name}: pixel ({x}, {y}) is {d:.3} px inside the visible part but not drawn"
                );
                assert!(
                    (f64::from(depth) - expected).abs() < tolerance,
                    "{name}: depth at ({x}, {y}) is {depth}, the plane is at {expected} (tolerance {tolerance:.2e})"
                );
            } else if d < -margin {
                outside += 1;
                assert_eq!(
                    color, BLACK8,
                    "{name}: pixel ({x}, {y}) is {:.3} px outside the visible part but drawn",
                    -d
                );
                assert_eq!(depth, 1.0, "{name}: depth written outside at ({x}, {y})");
            }
        }
    }
    assert!(
        inside + outside > (size * size) as usize * 9 / 10,
        "{name}: premise: most pixels are decided"
    );
    out
}

#[test]
fn row21_a_triangle_crossing_the_near_plane_is_clipped_to_its_visible_part() {
    // A floor triangle (y = −1) from 4 units ahead to 3 units behind the eye: only the part at
    // z ≤ −1 is drawn; its projection reaches the bottom of the image.
    let out = assert_clipped_like_the_analytic_projection(
        "floor crossing the near plane",
        [Vec3::new(-2.0, -1.0, -4.0), Vec3::new(2.0, -1.0, -4.0), Vec3::new(0.0, -1.0, 3.0)],
        32,
    );
    assert_eq!(out.stats.triangles_clipped, 1);
    assert!(
        out.stats.triangles_drawn >= 2,
        "the clipped quadrilateral is drawn as a fan: {}",
        out.stats
    );

    // Standing up, one corner far behind and to the side: the clipped part is a thin wedge.
    assert_clipped_like_the_analytic_projection(
        "wall crossing the near plane",
        [Vec3::new(-3.0, -2.0, -6.0), Vec3::new(1.0, 3.0, -2.0), Vec3::new(4.0, -1.0, 5.0)],
        32,
    );
}

#[test]
fn row21_a_corner_exactly_at_the_eye_is_never_divided_by() {
    // w = 0 at the eye: the corner is clipped away before the perspective divide.
    let out = assert_clipped_like_the_analytic_projection(
        "corner at the eye",
        [Vec3::ZERO, Vec3::new(3.0, -1.0, -5.0), Vec3::new(-3.0, -1.0, -5.0)],
        24,
    );
    assert_eq!(out.stats.triangles_clipped, 1);
    // A corner on the eye plane (z = 0, w = 0) beside the eye.
    assert_clipped_like_the_analytic_projection(
        "corner on the eye plane",
        [Vec3::new(2.0, 0.5, 0.0), Vec3::new(1.0, -1.0, -5.0), Vec3::new(-3.0, -1.0, -4.0)],
        24,
    );
}

#[test]
fn row21_a_triangle_behind_the_eye_draws_nothing() {
    for corners in [
        // Entirely behind the eye (z > 0): its mirror image through the eye would be on screen.
        [Vec3::new(-1.0, -1.0, 4.0), Vec3::new(1.0, -1.0, 4.0), Vec3::new(0.0, 1.0, 4.0)],
        // Between the eye and the near plane.
        [Vec3::new(-1.0, -1.0, -0.5), Vec3::new(1.0, -1.0, -0.5), Vec3::new(0.0, 1.0, -0.9)],
        // Touching the eye, the rest behind.
        [Vec3::ZERO, Vec3::new(1.0, -1.0, 3.0), Vec3::new(-1.0, 1.0, 3.0)],
    ] {
        let mut scene = looking_down_z(16, 16, 90.0);
        scene.cull_back_faces = false;
        scene.objects.push(object(
            "behind",
            triangle(corners[0], corners[1], corners[2]),
            unlit(RED),
        ));
        let out = render(&scene, &Options::default()).unwrap();
        assert_finite(&out);
        assert!(
            out.image.to_rgba8().iter().all(|&c| c == BLACK8),
            "{corners:?}: something was drawn"
        );
        assert!(out.depth.iter().all(|&z| z == 1.0), "{corners:?}: a depth was written");
        assert_eq!(out.stats.fragments, 0, "{corners:?}: {}", out.stats);
        assert_eq!(out.stats.triangles_outside, 1, "{corners:?}: {}", out.stats);
    }
}

#[test]
fn row21_a_huge_floor_through_both_clip_planes_ends_at_the_far_horizon() {
    // A floor a million units wide, from behind the eye to far beyond the far plane: clipped at
    // the near plane, the far plane and the guard band (its corners would be ~10¹¹ pixels off
    // screen). It must fill exactly the rows below where the far plane cuts it: y = −1 at
    // z = −far projects to y_ndc = −f/far.
    let size = 32;
    let mut scene = looking_down_z(size, size, 90.0);
    let r = 1.0e6;
    let floor = cg_core::mesh::Mesh::new(
        vec![
            Vec3::new(-r, -1.0, r),
            Vec3::new(r, -1.0, r),
            Vec3::new(r, -1.0, -r),
            Vec3::new(-r, -1.0, -r),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    scene.objects.push(object("floor", floor, unlit(RED)));
    let out = render(&scene, &Options::default()).unwrap();
    assert_finite(&out);
    let camera = Pinhole::of(&scene);
    let horizon = camera.window(DVec3::new(0.0, -1.0, -camera.far)).y;
    assert!(
        (16.0..16.5).contains(&horizon),
        "premise: the far edge lies between two rows of centres, at {horizon}"
    );
    let rgba = out.image.to_rgba8();
    for y in 0..size {
        for x in 0..size {
            let drawn = rgba[(y * size + x) as usize] == RED8;
            let expected = f64::from(y) + 0.5 > horizon;
            assert_eq!(
                drawn, expected,
                "pixel ({x}, {y}): drawn {drawn}, the far horizon is at y = {horizon:.3}"
            );
        }
    }
    assert_eq!(out.stats.triangles_clipped, 2, "{}", out.stats);
}
