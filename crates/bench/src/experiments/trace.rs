//! The ray tracer's knobs: area-light samples (against a converged many-sample image) and ray
//! depth (against depth [`crate::Config::depth_reference`]).

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{Attenuation, Light, LightKind, Material};
use cg_core::scene::Scene;

use super::{empty_scene, ground, matte, point_light, rms, sphere, trace};
use crate::measure::median_time;
use crate::{BenchError, Column, Config, Experiment, Row};

/// A sphere on the ground under a 2 × 2 area light of `k × k` samples.
///
/// # Errors
/// Never for the sizes used.
pub fn area_scene(size: u32, k: u32) -> Result<Scene, BenchError> {
    let mut s = empty_scene("area-light", size, Vec3::new(0.0, 3.0, 6.0));
    s.lights.push(Light {
        kind: LightKind::Area {
            corner: Vec3::new(-1.0, 3.5, -1.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 2.0),
            samples: [k, k],
        },
        ambient: Rgb::ZERO,
        diffuse: Rgb::ONE,
        specular: Rgb::ONE,
        attenuation: Attenuation::default(),
    });
    s.objects.push(ground(8.0, -1.0, matte(Rgb::new(0.8, 0.8, 0.7)))?);
    let material =
        Material { ks: Rgb::splat(0.4), shininess: 32.0, ..matte(Rgb::new(0.8, 0.3, 0.2)) };
    s.objects.push(sphere("sphere", 1.0, 3, Vec3::new(0.0, 0.2, 0.0), material)?);
    Ok(s)
}

/// A mirror sphere, a glass sphere and a reflective ground under one point light.
///
/// # Errors
/// Never for the sizes used.
pub fn depth_scene(size: u32) -> Result<Scene, BenchError> {
    let mut s = empty_scene("ray-depth", size, Vec3::new(0.0, 1.5, 6.0));
    s.clear_color = Rgb::new(0.5, 0.5, 0.8);
    s.lights.push(point_light(Vec3::new(3.0, 6.0, 5.0)));
    let floor = Material { kr: Rgb::splat(0.4), ..matte(Rgb::new(0.5, 0.5, 0.45)) };
    s.objects.push(ground(10.0, -1.0, floor)?);
    let mirror = Material {
        kr: Rgb::splat(0.85),
        ks: Rgb::splat(0.5),
        shininess: 64.0,
        ..matte(Rgb::splat(0.1))
    };
    s.objects.push(sphere("mirror", 1.0, 3, Vec3::new(-1.1, 0.0, 0.0), mirror)?);
    let glass = Material {
        kt: Rgb::splat(0.9),
        eta: 1.5,
        ks: Rgb::splat(0.5),
        shininess: 64.0,
        ..matte(Rgb::splat(0.05))
    };
    s.objects.push(sphere("glass", 0.8, 3, Vec3::new(1.1, -0.2, 0.8), glass)?);
    Ok(s)
}

/// Area-light samples per side against a converged image.
///
/// # Errors
/// [`BenchError::Render`] if the tracer refuses the scene.
pub fn area_light(config: &Config) -> Result<Experiment, BenchError> {
    let options = cg_trace::Options { max_depth: 0, ..cg_trace::Options::default() };
    let reference = trace(&area_scene(config.trace_size, config.area_reference)?, &options)?.image;
    let mut rows = Vec::new();
    for &k in &config.area_samples {
        let scene = area_scene(config.trace_size, k)?;
        let out = trace(&scene, &options)?;
        let time = median_time(config.reps, || trace(&scene, &options));
        rows.push(Row {
            key: vec!["ray tracer".into(), format!("{k}×{k}")],
            values: vec![
                rms(&out.image, &reference, None),
                time * 1e3,
                out.stats.shadow_rays as f64,
            ],
        });
    }
    Ok(Experiment {
        id: "area-light",
        title: "面光源のサンプル数 / Area-light samples",
        about: format!(
            "2×2 の面光源を k×k 個の点光源で近似し (影あり)、{r}×{r} の画像との RMS 差。{s}×{s} ピクセル、1 スレッド。\n\n\
             A 2 × 2 area light approximated by k × k point lights (the lecture's 面光源), with \
             shadows, against the same scene at {r} × {r} samples: RMS difference over all \
             pixels in [0, 1] colour units. The ray tracer at {s} × {s} pixels on one thread.",
            r = config.area_reference,
            s = config.trace_size
        ),
        keys: vec!["renderer", "samples"],
        columns: vec![
            Column::error("RMS error"),
            Column::value("time/frame [ms]"),
            Column::value("shadow rays"),
        ],
        rows,
        series_key: 0,
        time_column: 1,
        error_column: 0,
    })
}

/// Ray depth against a deep reference.
///
/// # Errors
/// [`BenchError::Render`] if the tracer refuses the scene.
pub fn ray_depth(config: &Config) -> Result<Experiment, BenchError> {
    let scene = depth_scene(config.trace_size)?;
    let at = |max_depth| cg_trace::Options { max_depth, ..cg_trace::Options::default() };
    let reference = trace(&scene, &at(config.depth_reference))?.image;
    let mut rows = Vec::new();
    for &d in &config.depths {
        let options = at(d);
        let out = trace(&scene, &options)?;
        let time = median_time(config.reps, || trace(&scene, &options));
        let s = &out.stats;
        rows.push(Row {
            key: vec!["ray tracer".into(), d.to_string()],
            values: vec![
                rms(&out.image, &reference, None),
                time * 1e3,
                (s.reflection_rays + s.refraction_rays) as f64,
            ],
        });
    }
    Ok(Experiment {
        id: "ray-depth",
        title: "レイの深さ / Ray depth",
        about: format!(
            "鏡の球、ガラスの球 (η = 1.5)、反射する床。最大深さ d の画像と深さ {r} の画像との RMS 差。\
             {s}×{s} ピクセル、1 スレッド。\n\n\
             A mirror sphere, a glass sphere (η = 1.5, exact Fresnel) and a reflective floor: \
             the image at maximum depth d against depth {r} (same adaptive pruning, weight < \
             1/1024): RMS difference in [0, 1] colour units. The ray tracer at {s} × {s} pixels \
             on one thread.",
            r = config.depth_reference,
            s = config.trace_size
        ),
        keys: vec!["renderer", "max depth"],
        columns: vec![
            Column::error("RMS error"),
            Column::value("time/frame [ms]"),
            Column::value("secondary rays"),
        ],
        rows,
        series_key: 0,
        time_column: 1,
        error_column: 0,
    })
}
