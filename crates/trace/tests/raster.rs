//! The ray tracer against the rasterizer (`cg_raster`, the renderer the tests trust) on opaque
//! scenes (k_r = k_t = 0) with shadows off: both light every pixel with the same light model
//! (Phong shading) through the same camera and projection, so the images must agree.
//!
//! Tolerance: at least 99 % of the pixels away from silhouettes within 2/255 per channel.
//! Silhouette pixels — where the two renderers disagree about whether a surface covers the pixel
//! centre, and their neighbours — are excepted: the rasterizer snaps vertices to 1/256 pixel and
//! decides edge pixels by its fill rule, the tracer by the exact ray. Elsewhere the hit points
//! differ only by rounding (the rasterizer interpolates positions and normals perspective-correctly
//! from snapped vertices, the tracer intersects the triangle), which moves a colour by well under
//! one step except in the sharpest highlights.

mod common;

use cg_core::scene::{Scene, Shading};
use cg_trace::{Options, Stats, Tracer};

struct Agreement {
    compared: usize,
    within: usize,
    silhouette: usize,
    max_diff: u8,
}

/// Compares the tracer's and the rasterizer's images of `scene` at `size`², Phong shading.
fn compare(scene: &Scene, size: u32, analytic: bool) -> Agreement {
    let raster = cg_raster::render(
        scene,
        &cg_raster::Options {
            shading: Some(Shading::Phong),
            size: Some((size, size)),
            ..cg_raster::Options::default()
        },
    )
    .unwrap();
    let options = Options {
        shading: Some(Shading::Phong),
        size: Some((size, size)),
        shadows: false,
        analytic,
        ..Options::default()
    };
    let tracer = Tracer::new(scene, &options).unwrap();
    let traced = tracer.render();
    assert_eq!((traced.stats.reflection_rays, traced.stats.refraction_rays), (0, 0));
    let n = size as usize;
    let covered_traced: Vec<bool> = (0..n * n)
        .map(|i| {
            let ray = tracer.generate_ray((i % n) as u32, (i / n) as u32);
            tracer.intersect(&ray, &mut Stats::default()).is_some()
        })
        .collect();
    let covered_raster: Vec<bool> = raster.depth.iter().map(|&d| d < 1.0).collect();
    let (a, b) = (traced.image.to_rgba8(), raster.image.to_rgba8());
    let mut result = Agreement { compared: 0, within: 0, silhouette: 0, max_diff: 0 };
    for y in 0..n {
        for x in 0..n {
            let i = y * n + x;
            // A silhouette pixel: the renderers disagree about coverage here or next door.
            let near_edge = (y.saturating_sub(1)..=(y + 1).min(n - 1)).any(|yy| {
                (x.saturating_sub(1)..=(x + 1).min(n - 1)).any(|xx| {
                    let j = yy * n + xx;
                    covered_traced[j] != covered_traced[i]
                        || covered_raster[j] != covered_raster[i]
                        || covered_traced[j] != covered_raster[j]
                })
            });
            if near_edge {
                result.silhouette += 1;
                continue;
            }
            let d = (0..3).map(|c| a[i][c].abs_diff(b[i][c])).max().unwrap_or(0);
            result.compared += 1;
            result.within += usize::from(d <= 2);
            result.max_diff = result.max_diff.max(d);
        }
    }
    result
}

fn assert_agree(name: &str, scene: &Scene, size: u32, analytic: bool) {
    let r = compare(scene, size, analytic);
    let percent = 100.0 * r.within as f64 / r.compared as f64;
    eprintln!(
        "{name} (analytic {analytic}): {percent:.3} % of {} pixels within 2/255, max {}/255, {} silhouette pixels excepted",
        r.compared, r.max_diff, r.silhouette
    );
    assert!(r.silhouette * 10 < r.compared, "{name}: {} silhouette pixels?", r.silhouette);
    assert!(
        percent >= 99.0,
        "{name}: only {percent:.3} % of {} pixels within 2/255 of the rasterizer (max difference {}/255)",
        r.compared,
        r.max_diff
    );
}

#[test]
fn an_opaque_phong_sphere_traced_equals_the_rasterizers() {
    assert_agree("sphere-phong", &common::shipped("sphere-phong"), 96, true);
}

#[test]
fn the_course_scene_traced_equals_the_rasterizers_phong_image() {
    // The pyramid's face normals and the ground, under OpenGL's light model (infinite viewer),
    // exact ground and its grid alike.
    let scene = common::shipped("course-sample");
    assert_agree("course-sample", &scene, 96, true);
    assert_agree("course-sample", &scene, 96, false);
    assert_agree("textured-ground", &common::shipped("textured-ground"), 96, true);
}
