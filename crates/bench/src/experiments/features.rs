//! "Only what the scene needs": the rasterizer and the ray tracer on one scene with and without
//! each feature. Each feature is measured three ways: absent (the renderer skips the term, as
//! [`cg_core::scene::Scene::features`] says), present with a coefficient too small to see (the
//! term is computed and changes nothing visible: the cost of *not* skipping), and present in
//! full.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{LightKind, Material};
use cg_core::scene::{Scene, TextureUse};
use cg_core::texture::{Sampler, TexEnv, Texture};

use super::{empty_scene, ground, matte, point_light, raster, rms, sphere, trace};
use crate::measure::median_time;
use crate::{BenchError, Column, Config, Experiment, Row};

/// The base scene: a matte sphere on a matte ground, one point light without attenuation,
/// Phong shading (lighting per pixel, so skipped terms show).
///
/// # Errors
/// Never for the sizes used.
pub fn base_scene(size: u32) -> Result<Scene, BenchError> {
    let mut s = empty_scene("features", size, Vec3::new(0.0, 2.5, 5.5));
    s.lights.push(point_light(Vec3::new(3.0, 6.0, 4.0)));
    s.objects.push(ground(8.0, -1.0, matte(Rgb::new(0.7, 0.7, 0.6)))?);
    s.objects.push(sphere("sphere", 1.0, 4, Vec3::ZERO, matte(Rgb::new(0.8, 0.3, 0.2)))?);
    Ok(s)
}

type Tweak = fn(&mut Scene, &mut cg_trace::Options);

fn sphere_material(s: &mut Scene) -> &mut Material {
    &mut s.objects[1].material
}

fn spot(s: &mut Scene, cutoff_deg: f32) {
    if let LightKind::Point { position } = s.lights[0].kind {
        s.lights[0].kind = LightKind::Spot {
            position,
            direction: -position,
            cutoff_deg,
            exponent: 0.0,
            inner_deg: None,
        };
    }
}

fn texture(s: &mut Scene, checker: bool) {
    let t = Texture::from_fn(8, 8, |x, y| {
        if checker && (x + y) % 2 == 1 { [90, 90, 90, 255] } else { [255, 255, 255, 255] }
    });
    if let Ok(t) = t {
        s.textures.push(t);
        s.objects[0].texture =
            Some(TextureUse { texture: 0, sampler: Sampler::default(), env: TexEnv::Modulate });
    }
}

const VARIANTS: [(&str, Tweak); 11] = [
    ("none (diffuse, point light)", |_, _| {}),
    ("specular, k_s = 1e-6", |s, _| {
        let m = sphere_material(s);
        m.ks = Rgb::splat(1e-6);
        m.shininess = 32.0;
    }),
    ("specular, k_s = 0.6", |s, _| {
        let m = sphere_material(s);
        m.ks = Rgb::splat(0.6);
        m.shininess = 32.0;
    }),
    ("attenuation, k_l = 1e-7", |s, _| s.lights[0].attenuation.linear = 1e-7),
    ("attenuation, k_l = 0.05", |s, _| s.lights[0].attenuation.linear = 0.05),
    ("spot, cut-off 180° (no cone)", |s, _| spot(s, 180.0)),
    ("spot, cut-off 20°", |s, _| spot(s, 20.0)),
    ("texture, white", |s, _| texture(s, false)),
    ("texture, checker", |s, _| texture(s, true)),
    ("shadows (tracer)", |_, o| o.shadows = true),
    ("reflection, k_r = 0.3", |s, _| sphere_material(s).kr = Rgb::splat(0.3)),
];

/// Runs the experiment.
///
/// # Errors
/// [`BenchError::Render`] if a renderer refuses the scene.
pub fn run(config: &Config) -> Result<Experiment, BenchError> {
    let base = base_scene(config.features_size)?;
    let base_trace = cg_trace::Options { shadows: false, ..cg_trace::Options::default() };
    let raster_base = raster(&base, None)?.image;
    let trace_base = trace(&base, &base_trace)?.image;
    let mut rows = Vec::new();
    for (name, tweak) in VARIANTS {
        let mut scene = base.clone();
        let mut options = base_trace.clone();
        tweak(&mut scene, &mut options);
        let r = raster(&scene, None)?;
        let r_time = median_time(config.reps, || raster(&scene, None));
        let st = &r.stats;
        rows.push(Row {
            key: vec!["rasterizer".into(), name.into()],
            values: vec![
                r_time * 1e3,
                rms(&r.image, &raster_base, None),
                st.lighting_evaluations as f64,
                st.specular_evaluations as f64,
                st.attenuation_evaluations as f64,
                st.texture_samples as f64,
            ],
        });
        let t = trace(&scene, &options)?;
        let t_time = median_time(config.reps, || trace(&scene, &options));
        let st = &t.stats;
        rows.push(Row {
            key: vec!["ray tracer".into(), name.into()],
            values: vec![
                t_time * 1e3,
                rms(&t.image, &trace_base, None),
                st.lighting_evaluations as f64,
                st.specular_evaluations as f64,
                st.attenuation_evaluations as f64,
                (st.shadow_rays + st.reflection_rays + st.refraction_rays) as f64,
            ],
        });
    }
    Ok(Experiment {
        id: "features",
        title: "シーンに必要なものだけ / Only what the scene needs",
        about: format!(
            "球と床、点光源 1 つの基本シーンに機能を 1 つずつ加える。係数がごく小さい行 (k_s = 1e-6、\
             k_l = 1e-7、白いテクスチャ、範囲 180° のスポット) は画像がほぼ変わらないのに項を計算する: \
             「なし」の行との時間差が、使わない項を省くことで節約している時間。{s}×{s} 画素、Phong \
             シェーディング、1 スレッド。\n\n\
             A sphere on a ground under one point light, then one feature at a time. The rows \
             with a coefficient too small to see (k_s = 1e-6, k_l = 1e-7, a white texture, a \
             spot light without a cone) compute the term yet leave the image as it was: their \
             time minus the `none` row's is what skipping an unused term saves (the renderers \
             skip by `Scene::features`, and count what they evaluate). `RMS vs none` is the \
             image difference from the base scene; the last column is texture samples for the \
             rasterizer and shadow + secondary rays for the tracer (shadows off except in the \
             `shadows` row). {s} × {s} pixels, Phong shading, one thread.",
            s = config.features_size
        ),
        keys: vec!["renderer", "feature"],
        columns: vec![
            Column::value("time/frame [ms]"),
            Column::error("RMS vs none"),
            Column::value("lighting evaluations"),
            Column::value("specular terms"),
            Column::value("attenuations"),
            Column::value("texture samples / rays"),
        ],
        rows,
        series_key: 0,
        time_column: 0,
        error_column: 1,
    })
}
