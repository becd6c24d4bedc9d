//! Flat, Gouraud and Phong shading × tessellation × specular exponent, against the exact sphere
//! lit at every pixel.
//!
//! The scene: a unit sphere (an icosphere whose vertex normals are the exact sphere normals, so
//! only the shading mode differs) lit by one point light, seen by a local viewer, in the
//! lecture's Phong model. The material puts the specular term alone in the blue channel
//! (`k_a`, `k_d` have no blue, `k_s = (0, 0, 1)`), so the highlight's peak is the blue channel's
//! maximum. The reference is the ray tracer's image of the *exact* sphere (no shadows, no global
//! terms), lit at every pixel with the exact normal. Errors are taken over the pixels both
//! images cover (the tessellated silhouette lies inside the exact one).

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::Material;
use cg_core::scene::{Scene, Shading};

use super::{empty_scene, point_light, raster, rms, sphere};
use crate::measure::median_time;
use crate::{BenchError, Column, Config, Experiment, Row};

/// The sphere scene at icosphere `level` with specular exponent `n`.
///
/// # Errors
/// Never for the levels the configurations use (an icosphere level above the kit's limit).
pub fn scene(size: u32, level: u32, n: f32) -> Result<Scene, BenchError> {
    let mut s = empty_scene("shading", size, Vec3::new(0.0, 0.0, 3.2));
    s.lights.push(point_light(Vec3::new(4.0, 5.0, 10.0)));
    let material = Material {
        ka: Rgb::new(0.25, 0.2, 0.0),
        kd: Rgb::new(0.6, 0.5, 0.0),
        ks: Rgb::new(0.0, 0.0, 1.0),
        shininess: n,
        ..Material::default()
    };
    s.objects.push(sphere("sphere", 1.0, level, Vec3::ZERO, material)?);
    Ok(s)
}

/// Runs the experiment.
///
/// # Errors
/// [`BenchError::Render`] if a renderer refuses the scene.
pub fn run(config: &Config) -> Result<Experiment, BenchError> {
    let mut rows = Vec::new();
    for &n in &config.exponents {
        for &level in &config.levels {
            let scene = scene(config.shading_size, level, n)?;
            let reference_options =
                cg_trace::Options { shadows: false, max_depth: 0, ..cg_trace::Options::default() };
            let tracer = cg_trace::Tracer::new(
                &scene,
                &cg_trace::Options { threads: Some(1), ..reference_options },
            )
            .map_err(|e| BenchError::Render(e.to_string()))?;
            let reference = tracer.render().image;
            let mut stats = cg_trace::Stats::default();
            let (w, h) = (scene.width, scene.height);
            let exact_mask: Vec<bool> = (0..h)
                .flat_map(|y| (0..w).map(move |x| (x, y)))
                .map(|(x, y)| tracer.intersect(&tracer.generate_ray(x, y), &mut stats).is_some())
                .collect();
            let reference_peak = peak(&reference.pixels, &exact_mask);
            for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
                let out = raster(&scene, Some(shading))?;
                let mask: Vec<bool> = out
                    .depth
                    .iter()
                    .zip(&exact_mask)
                    .map(|(&d, &exact)| d < 1.0 && exact)
                    .collect();
                let error = rms(&out.image, &reference, Some(&mask));
                let retained = peak(&out.image.pixels, &mask) / reference_peak;
                let time = median_time(config.reps, || raster(&scene, Some(shading)));
                rows.push(Row {
                    key: vec![name(shading).into(), level.to_string(), format!("{n}")],
                    values: vec![
                        error,
                        retained,
                        (1.0 - retained).abs(),
                        time * 1e3,
                        out.stats.lighting_evaluations as f64,
                        scene.objects[0].mesh.face_count() as f64,
                    ],
                });
            }
        }
    }
    Ok(Experiment {
        id: "shading",
        title: "シェーディング方式 / Shading modes",
        about: format!(
            "単位球 (頂点の法線は厳密な球の法線) を点光源 1 つ・局所視点・講義の Phong モデルで描き、\
             レイトレーサが厳密な球をピクセルごとに照らした画像と比べる。鏡面反射光は青チャンネルだけに入れ、\
             ハイライトのピークはその最大値。{s}×{s} ピクセル、ラスタライザ 1 スレッド。\n\n\
             A unit sphere (icosphere; vertex normals the exact sphere normals) under one point \
             light, local viewer, the lecture's Phong model, against the ray tracer's exact sphere \
             lit at every pixel. The specular term alone is in the blue channel, so the highlight \
             peak is its maximum. `peak retained` = the rendered peak / the reference peak; `peak \
             error` = |1 − retained|; RMS over the pixels both images cover, in [0, 1] colour \
             units. {s}×{s} pixels; the rasterizer on one thread. Level L has 20·4^L triangles.",
            s = config.shading_size
        ),
        keys: vec!["shading", "level", "n"],
        columns: vec![
            Column::error("RMS error"),
            Column::value("peak retained"),
            Column::error("peak error"),
            Column::value("time/frame [ms]"),
            Column::value("lighting evaluations"),
            Column::value("triangles"),
        ],
        rows,
        series_key: 0,
        time_column: 3,
        error_column: 0,
    })
}

fn name(shading: Shading) -> &'static str {
    match shading {
        Shading::Flat => "flat",
        Shading::Gouraud => "Gouraud",
        Shading::Phong => "Phong",
    }
}

/// The largest blue value over the masked pixels.
fn peak(pixels: &[Rgb], mask: &[bool]) -> f64 {
    pixels.iter().zip(mask).filter(|(_, m)| **m).map(|(p, _)| f64::from(p.z)).fold(0.0, f64::max)
}
