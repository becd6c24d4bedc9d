//! "Only what the scene needs": the rasterizer, the ray tracer and the GPU renderer on one scene
//! with and without each feature. Each feature is measured three ways: absent (the renderer skips
//! the term, as [`cg_core::scene::Scene::features`] says), present with a coefficient too small to
//! see (the term is computed and changes nothing visible: the cost of *not* skipping), and present
//! in full.
//!
//! The GPU renderer (`cg_gpu`) skips by generating its WGSL from the scene's features: its rows
//! count the terms the shader contains (`cg_gpu::enabled`) and the shader's length. They are
//! timed on a prepared `cg_gpu::Frame` ([`Config::gpu_draws`] draws and one wait, no readback)
//! at [`Config::features_gpu_size`]. Without an adapter (no Vulkan driver), or in a build without
//! the `gpu` feature (the students' copy), the GPU rows are absent and the experiment's text says
//! why (and, for the build, which command measures them).

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

/// The GPU's rows: the kit's GPU renderer (`cg_gpu`) on the variants it can draw.
#[cfg(feature = "gpu")]
mod gpu {
    use cg_core::scene::Scene;
    use cg_gpu::{Gpu, GpuError};

    use super::{VARIANTS, median_time, rms};
    use crate::{Config, Row};

    /// Whether the GPU renderer draws what the variant asks for: not the tracer's shadows, nor
    /// reflection or transmission (they need rays).
    fn gpu_can_draw(scene: &Scene, options: &cg_trace::Options) -> bool {
        let f = scene.features();
        !options.shadows && !f.reflection && !f.transmission
    }

    /// What the GPU measured for one variant.
    struct GpuMeasure {
        /// Seconds per frame.
        time: f64,
        /// The frame read back.
        image: cg_core::image::Image,
        /// Terms in the generated shader ([`cg_gpu::enabled`]).
        terms: usize,
        /// Lines of the generated WGSL.
        lines: usize,
    }

    /// Prepares `scene` once at `config.features_gpu_size`, then times `config.gpu_draws` draws into
    /// one target followed by one wait (median over `config.reps` runs, divided by the draws), and
    /// reads the frame back once, untimed.
    fn gpu_measure(gpu: &Gpu, scene: &Scene, config: &Config) -> Result<GpuMeasure, GpuError> {
        use cg_gpu::wgpu;
        let size = config.features_gpu_size;
        let options = cg_gpu::Options { shading: None, size: Some((size, size)) };
        let frame = gpu.frame(scene, &options, cg_gpu::READBACK_FORMAT)?;
        let device = gpu.device();
        let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
        let target = gpu.target(&frame);
        let view = target.create_view(&wgpu::TextureViewDescriptor::default());
        let draws = config.gpu_draws.max(1);
        let mut failure = None;
        let time = median_time(config.reps, || {
            for _ in 0..draws {
                gpu.render_to_view(&frame, &view);
            }
            if let Err(e) = device.poll(wgpu::PollType::wait_indefinitely()) {
                failure = Some(e.to_string());
            }
        }) / f64::from(draws);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(GpuError::Wgpu(e.to_string()));
        }
        if let Some(e) = failure {
            return Err(GpuError::Wgpu(e));
        }
        let image = gpu.read_back(&frame)?;
        Ok(GpuMeasure {
            time,
            image,
            terms: cg_gpu::enabled(&frame.features).len(),
            lines: frame.shader.lines().count(),
        })
    }

    /// The GPU's rows for every variant it can draw, keyed `GPU (<adapter>)`, with RMS against its
    /// own `none` image.
    fn gpu_rows(gpu: &Gpu, key: &str, base: &Scene, config: &Config) -> Result<Vec<Row>, GpuError> {
        let base_trace = cg_trace::Options { shadows: false, ..cg_trace::Options::default() };
        let mut none = None;
        let mut rows = Vec::new();
        for (name, tweak) in VARIANTS {
            let mut scene = base.clone();
            let mut options = base_trace.clone();
            tweak(&mut scene, &mut options);
            if !gpu_can_draw(&scene, &options) {
                continue;
            }
            let m = gpu_measure(gpu, &scene, config)?;
            let reference = none.get_or_insert_with(|| m.image.clone());
            let nan = f64::NAN;
            rows.push(Row {
                key: vec![key.into(), name.into()],
                values: vec![
                    m.time * 1e3,
                    rms(&m.image, reference, None),
                    nan,
                    nan,
                    nan,
                    nan,
                    m.terms as f64,
                    m.lines as f64,
                ],
            });
        }
        Ok(rows)
    }

    /// The adapter's name up to its first parenthesis (`llvmpipe (LLVM 15.0.7, 256 bits)` →
    /// `llvmpipe`).
    fn short_name(gpu: &Gpu) -> String {
        let name = gpu.adapter().get_info().name;
        let short = name.split(" (").next().unwrap_or(&name).trim();
        if short.is_empty() { "adapter".into() } else { short.to_string() }
    }

    /// The GPU's rows for every variant it can draw (none without an adapter), and the
    /// experiment's paragraph about them (or about why there are none).
    pub(super) fn rows(base: &Scene, config: &Config) -> (Vec<Row>, String) {
        let mut found = Vec::new();
        let gpu = Gpu::new().and_then(|gpu| {
            let name = short_name(&gpu);
            let key = format!("GPU ({name})");
            let rows = gpu_rows(&gpu, &key, base, config)?;
            Ok((gpu.adapter_info(), rows))
        });
        let text = match gpu {
            Ok((adapter, rows)) => {
                found = rows;
                let on_cpu = adapter.contains("llvmpipe");
                let cpu_ja = if on_cpu {
                    "lavapipe (llvmpipe) は CPU で動く Vulkan 実装で、すべてのコアを使う。"
                } else {
                    ""
                };
                let cpu_en = if on_cpu {
                    " Lavapipe (llvmpipe) is a Vulkan implementation on the CPU and uses every core."
                } else {
                    ""
                };
                format!(
                    "GPU の行 ({adapter}) は {g}×{g} ピクセル: 用意したフレーム (`cg_gpu::Frame`) への \
                     {k} 回の描画と 1 回の待ちの時間を {k} で割ったもので、読み戻しは含まない \
                     (小さな画像では提出ごとの固定費が時間の大半になるため、CPU の行より大きな画像で\
                     測る)。RMS は GPU 自身の「なし」の画像との差。GPU のシェーダ (WGSL) は \
                     `Scene::features` から生成され、使わない項のコードを含まない: `GPU shader terms` \
                     はシェーダに含まれる項の数 (`cg_gpu::enabled`)、`WGSL lines` はその行数。影と反射は\
                     レイトレーサだけの機能なので GPU の行はない。{cpu_ja}\n\n\
                     The GPU rows ({adapter}) are {g} × {g} pixels: the time of {k} draws into a \
                     prepared frame (`cg_gpu::Frame`) and one wait, divided by {k}, without the \
                     readback (measured larger than the CPU rows because at small sizes the fixed \
                     cost of a submission would dominate). Their RMS is against the GPU's own `none` \
                     image. The GPU's shader (WGSL) is generated from `Scene::features` and has no \
                     code for unused terms: `GPU shader terms` counts the terms it contains \
                     (`cg_gpu::enabled`), `WGSL lines` its length. Shadows and reflection are the \
                     tracer's alone: no GPU rows.{cpu_en}",
                    g = config.features_gpu_size,
                    k = config.gpu_draws.max(1),
                )
            }
            Err(e) => format!(
                "GPU の行はありません: {}\n\nNo GPU rows: {}",
                e.message(cg_core::lang::Lang::Ja),
                e.message(cg_core::lang::Lang::En)
            ),
        };
        (found, text)
    }
}

/// A build without the `gpu` feature (the students' copy by default): no GPU rows, and the
/// command that measures them.
#[cfg(not(feature = "gpu"))]
mod gpu {
    use cg_core::scene::Scene;

    use crate::{Config, Row};

    /// No rows; the paragraph says why and which command builds the GPU renderer.
    pub(super) fn rows(_base: &Scene, _config: &Config) -> (Vec<Row>, String) {
        let command = "cargo run --release --features gpu -- bench";
        let text = format!(
            "GPU の行はありません: このビルドは GPU レンダラ（wgpu）を含みません（学生用のコピーの\
             既定。ビルドを速くするため）。GPU の行を測るには `{command}`。\n\n\
             No GPU rows: this build leaves the GPU renderer (wgpu) out (the students' copy's \
             default, to build faster). To measure them: `{command}`."
        );
        (Vec::new(), text)
    }
}

/// Runs the experiment: two rows (rasterizer, ray tracer) per variant, and one GPU row per
/// variant the GPU can draw when an adapter exists.
///
/// # Errors
/// [`BenchError::Render`] if a CPU renderer refuses the scene. A GPU that is missing or fails
/// is no error: its rows are left out and [`Experiment::about`] says why.
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
    for row in &mut rows {
        row.values.extend([f64::NAN, f64::NAN]);
    }
    let (gpu_rows, gpu_text) = gpu::rows(&base, config);
    rows.extend(gpu_rows);
    Ok(Experiment {
        id: "features",
        title: "シーンに必要なものだけ / Only what the scene needs",
        about: format!(
            "球と床、点光源 1 つの基本シーンに機能を 1 つずつ加える。係数がごく小さい行 (k_s = 1e-6、\
             k_l = 1e-7、白いテクスチャ、範囲 180° のスポット) は画像がほぼ変わらないのに項を計算する: \
             「なし」の行との時間差が、使わない項を省くことで節約している時間。{s}×{s} ピクセル、Phong \
             シェーディング、CPU の描画は 1 スレッド。\n\n\
             A sphere on a ground under one point light, then one feature at a time. The rows \
             with a coefficient too small to see (k_s = 1e-6, k_l = 1e-7, a white texture, a \
             spot light without a cone) compute the term yet leave the image as it was: their \
             time minus the `none` row's is what skipping an unused term saves (the renderers \
             skip by `Scene::features`, and count what they evaluate). `RMS vs none` is the \
             image difference from the base scene; the last column is texture samples for the \
             rasterizer and shadow + secondary rays for the tracer (shadows off except in the \
             `shadows` row). {s} × {s} pixels, Phong shading, the CPU renderers on one \
             thread.\n\n{gpu_text}",
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
            Column::value("GPU shader terms"),
            Column::value("WGSL lines"),
        ],
        rows,
        series_key: 0,
        time_column: 0,
        error_column: 1,
    })
}
