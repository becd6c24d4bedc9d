//! The GPU rows of "only what the scene needs" ([`cg_bench::experiments::features`]) with
//! [`Config::tiny`]: present on any adapter wgpu finds (Mesa's lavapipe in CI), one per variant the
//! GPU can draw, with finite times, RMS 0 for the base scene and above 0 where a feature is
//! visible, and a smaller shader where the scene needs less. No assertion on any time's size.
//!
//! Without an adapter the GPU rows must be absent and the text must say why (in Japanese and
//! English) — unless `CI` is set: there a missing adapter is a failure, as in crates/gpu's tests.
//! In a build without the `gpu` feature (the students' copy) the rows are absent and the text
//! gives the command that measures them.

use cg_bench::Config;
#[cfg(feature = "gpu")]
use cg_bench::Experiment;

#[cfg(feature = "gpu")]
const NONE: &str = "none (diffuse, point light)";
#[cfg(feature = "gpu")]
/// The variants the GPU draws (all but the tracer's shadows and reflection).
const GPU_VARIANTS: [&str; 9] = [
    NONE,
    "specular, k_s = 1e-6",
    "specular, k_s = 0.6",
    "attenuation, k_l = 1e-7",
    "attenuation, k_l = 0.05",
    "spot, cut-off 180° (no cone)",
    "spot, cut-off 20°",
    "texture, white",
    "texture, checker",
];

#[cfg(feature = "gpu")]
/// The adapter's name up to its first parenthesis, or `None` (with a note) where there is none.
fn adapter() -> Option<String> {
    match cg_gpu::Gpu::new() {
        Ok(gpu) => {
            let name = gpu.adapter().get_info().name;
            Some(name.split(" (").next().unwrap_or(&name).trim().to_string())
        }
        Err(e) if std::env::var_os("CI").is_some() => panic!("CI is set and {e}"),
        Err(e) => {
            eprintln!("note: no GPU rows expected: {e}");
            None
        }
    }
}

#[cfg(feature = "gpu")]
fn gpu_value(e: &Experiment, key: &str, variant: &str, column: &str) -> f64 {
    e.value(&[key, variant], column).unwrap_or_else(|| panic!("no row {key} / {variant}"))
}

#[cfg(feature = "gpu")]
#[test]
fn the_gpu_rows_skip_what_the_scene_does_not_need() {
    let adapter = adapter();
    let e = cg_bench::experiments::features::run(&Config::tiny()).unwrap();
    let gpu_rows: Vec<_> = e.rows.iter().filter(|r| r.key[0].starts_with("GPU")).collect();
    let md = cg_bench::Report {
        config: Config::tiny(),
        machine: cg_bench::Machine { cpu: "cpu".into(), cores: 1, commit: "c".into() },
        experiments: vec![e.clone()],
    }
    .markdown("svg");

    let Some(adapter) = adapter else {
        assert!(gpu_rows.is_empty(), "no adapter, yet GPU rows: {gpu_rows:?}");
        assert!(e.about.contains("No GPU rows") && e.about.contains("GPU の行はありません"));
        return;
    };
    let key = format!("GPU ({adapter})");

    // One row per variant the GPU can draw, none for the tracer's own features.
    let variants: Vec<&str> = gpu_rows.iter().map(|r| r.key[1].as_str()).collect();
    assert_eq!(variants, GPU_VARIANTS, "GPU rows");
    assert!(gpu_rows.iter().all(|r| r.key[0] == key), "{key}: {gpu_rows:?}");
    assert!(e.about.contains("GPU") && e.about.contains("64 × 64"), "{}", e.about);

    for v in GPU_VARIANTS {
        let t = gpu_value(&e, &key, v, "time/frame [ms]");
        assert!(t.is_finite() && t > 0.0, "{v}: time {t}");
        // The CPU counters do not apply to a GPU row (shown as —); the shader's do.
        assert!(gpu_value(&e, &key, v, "lighting evaluations").is_nan(), "{v}");
        assert!(gpu_value(&e, &key, v, "GPU shader terms") >= 2.0, "{v}: ambient and diffuse");
        assert!(gpu_value(&e, &key, v, "WGSL lines") > 10.0, "{v}");
    }
    // And the shader's counters do not apply to a CPU row.
    assert!(e.value(&["rasterizer", NONE], "WGSL lines").is_some_and(f64::is_nan));
    assert!(md.contains("| — |"), "NaN cells are shown as —");
    assert!(!md.contains("NaN"), "{md}");

    // RMS against the GPU's own base image: 0 for the base itself, above 0 where the feature
    // changes what is seen, below one level of 8 bits where the coefficient is too small to see.
    let rms = |v: &str| gpu_value(&e, &key, v, "RMS vs none");
    assert_eq!(rms(NONE), 0.0);
    for v in ["specular, k_s = 0.6", "texture, checker", "spot, cut-off 20°"] {
        assert!(rms(v) > 1e-3, "{v} is visible on the GPU: RMS {}", rms(v));
    }
    for v in ["specular, k_s = 1e-6", "attenuation, k_l = 1e-7", "texture, white"] {
        assert!(rms(v) < 1.0 / 255.0, "{v} is invisible on the GPU: RMS {}", rms(v));
    }

    // Only what the scene needs: the base scene's shader has fewer terms and fewer lines than
    // one with a (tiny) specular term, and than one with attenuation or a texture. A GPU given a
    // shader with every term would have equal counts.
    let terms = |v: &str| gpu_value(&e, &key, v, "GPU shader terms");
    let lines = |v: &str| gpu_value(&e, &key, v, "WGSL lines");
    for v in ["specular, k_s = 1e-6", "attenuation, k_l = 1e-7", "texture, white"] {
        assert!(terms(NONE) < terms(v), "terms: none {} vs {v} {}", terms(NONE), terms(v));
        assert!(lines(NONE) < lines(v), "lines: none {} vs {v} {}", lines(NONE), lines(v));
    }
    assert_eq!(terms("specular, k_s = 1e-6"), terms("specular, k_s = 0.6"), "same features");
}

#[test]
fn a_measure_that_does_not_apply_is_a_dash() {
    assert_eq!(cg_bench::format_value(f64::NAN), "—");
    assert_eq!(cg_bench::format_value(0.0), "0");
    assert_eq!(cg_bench::format_value(12.5), "12.50");
}

#[cfg(not(feature = "gpu"))]
#[test]
fn without_the_gpu_feature_the_text_gives_the_command_that_measures_the_gpu_rows() {
    let e = cg_bench::experiments::features::run(&Config::tiny()).unwrap();
    assert!(e.rows.iter().all(|r| !r.key[0].starts_with("GPU")), "{:?}", e.rows);
    for says in
        ["No GPU rows", "GPU の行はありません", "`cargo run --release --features gpu -- bench`"]
    {
        assert!(e.about.contains(says), "{says:?} in {}", e.about);
    }
}
