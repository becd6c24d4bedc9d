//! The ray tracer against the rasterizer (`cg_raster`, the renderer the tests trust) on opaque
//! scenes (k_r = k_t = 0) with shadows off: both light every pixel with the same light model
//! through the same camera and projection, so the images must agree — in Phong shading (every
//! point lit with the interpolated normal), and in flat shading on triangles (each face lit once,
//! at its centroid, with its face normal).
//!
//! Tolerance: **every pixel away from silhouettes within 2/255 per channel, and at least 99.9 %
//! of them within 1/255** (measured: all within 1/255 on every scene here). Silhouette pixels —
//! where the two renderers disagree about whether a surface covers the pixel centre, and their
//! neighbours — are excepted: the rasterizer snaps vertices to 1/256 pixel and decides edge
//! pixels by its fill rule, the tracer by the exact ray. Elsewhere the hit points differ only by
//! rounding (the rasterizer interpolates positions and normals perspective-correctly from
//! snapped vertices, the tracer intersects the triangle), which moves a colour by less than one
//! step even in spot-specular's highlight (n = 64); the second 1/255 is margin for another
//! platform's `powf`. Pixels whose hit point lies within 0.05° of a spot light's cut-off cone are
//! excepted too: the spot factor jumps there, so rounding decides (6 such pixels differ by up to
//! 68/255 on spot-specular at 96², all on the rim).
mod common;

use cg_core::light::LightKind;
use cg_core::scene::{Scene, Shading};
use cg_trace::{Options, Stats, Tracer};

struct Agreement {
    compared: usize,
    within: usize,
    silhouette: usize,
    max_diff: u8,
}

/// Compares the tracer's and the rasterizer's images of `scene` at `size`² in `shading`.
fn compare(scene: &Scene, size: u32, analytic: bool, shading: Shading) -> Agreement {
    let raster = cg_raster::render(
        scene,
        &cg_raster::Options {
            shading: Some(shading),
            size: Some((size, size)),
            ..cg_raster::Options::default()
        },
    )
    .unwrap();
    let options = Options {
        shading: Some(shading),
        size: Some((size, size)),
        shadows: false,
        analytic,
        ..Options::default()
    };
    let tracer = Tracer::new(scene, &options).unwrap();
    let traced = tracer.render();
    assert_eq!((traced.stats.reflection_rays, traced.stats.refraction_rays), (0, 0));
    assert_eq!(traced.shading, shading, "Flat and Phong are traced as asked");
    let n = size as usize;
    let covered_traced: Vec<bool> = (0..n * n)
        .map(|i| {
            let ray = tracer.generate_ray((i % n) as u32, (i / n) as u32);
            tracer.intersect(&ray, &mut Stats::default()).is_some()
        })
        .collect();
    let covered_raster: Vec<bool> = raster.depth.iter().map(|&d| d < 1.0).collect();
    // Pixels whose hit point lies within 0.05° of a spot light's cone: the spot factor jumps
    // there (from cos^e(cut-off) to 0), so rounding of the hit point decides the colour.
    let on_a_rim: Vec<bool> = (0..n * n)
        .map(|i| {
            let ray = tracer.generate_ray((i % n) as u32, (i / n) as u32);
            let Some(hit) = tracer.intersect(&ray, &mut Stats::default()) else { return false };
            scene.lights.iter().any(|light| match light.kind {
                LightKind::Spot { position, direction, cutoff_deg, .. } => {
                    let to_p = (hit.p - position).as_dvec3();
                    let angle = to_p.angle_between(direction.as_dvec3()).to_degrees();
                    (angle - f64::from(cutoff_deg)).abs() < 0.05
                }
                _ => false,
            })
        })
        .collect();
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
            if near_edge || on_a_rim[i] {
                result.silhouette += 1;
                continue;
            }
            let d = (0..3).map(|c| a[i][c].abs_diff(b[i][c])).max().unwrap_or(0);
            result.compared += 1;
            result.within += usize::from(d <= 1);
            result.max_diff = result.max_diff.max(d);
        }
    }
    result
}

fn assert_agree(name: &str, scene: &Scene, size: u32, analytic: bool, shading: Shading) {
    let r = compare(scene, size, analytic, shading);
    let percent = 100.0 * r.within as f64 / r.compared as f64;
    eprintln!(
        "{name} ({shading:?}, analytic {analytic}): {percent:.3} % of {} pixels within 1/255, max {}/255, {} silhouette and spot-rim pixels excepted",
        r.compared, r.max_diff, r.silhouette
    );
    assert!(r.silhouette * 10 < r.compared, "{name}: {} silhouette pixels?", r.silhouette);
    assert!(
        r.max_diff <= 2 && percent >= 99.9,
        "{name} ({shading:?}): {percent:.3} % of {} pixels within 1/255 of the rasterizer, max difference {}/255 (allowed: 99.9 %, 2/255)",
        r.compared,
        r.max_diff
    );
}

#[test]
fn an_opaque_phong_sphere_traced_equals_the_rasterizers() {
    assert_agree("sphere-phong", &common::shipped("sphere-phong"), 96, true, Shading::Phong);
}

#[test]
fn the_course_scene_traced_equals_the_rasterizers_phong_image() {
    // The pyramid's face normals and the ground, under OpenGL's light model (infinite viewer),
    // exact ground and its grid alike.
    let scene = common::shipped("course-sample");
    assert_agree("course-sample", &scene, 96, true, Shading::Phong);
    assert_agree("course-sample", &scene, 96, false, Shading::Phong);
    assert_agree("textured-ground", &common::shipped("textured-ground"), 96, true, Shading::Phong);
}

#[test]
fn the_spot_light_and_its_highlight_traced_equal_the_rasterizers() {
    // An infinite viewer *with* specular: V is the camera's backward axis in both, and the spot
    // light's cone, exponent and attenuation and the n = 64 highlight on the smooth sphere come
    // out the same.
    let scene = common::shipped("spot-specular");
    assert_agree("spot-specular", &scene, 96, true, Shading::Phong);
}

#[test]
fn flat_shading_traced_equals_the_rasterizers() {
    // Each triangle lit once at its centroid with its face normal, in both renderers: the
    // pyramid's faces and each ground cell (triangles, so `analytic: false`: the exact ground
    // square has no faces) under a point light, where lighting the hit point instead of the
    // centroid would shade each face unevenly.
    let scene = common::shipped("course-sample");
    assert_agree("course-sample", &scene, 96, false, Shading::Flat);
    assert_agree("spot-specular", &common::shipped("spot-specular"), 96, false, Shading::Flat);
}
