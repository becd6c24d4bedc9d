//! The report end to end with [`Config::tiny`]: every experiment's table and SVG are there, the
//! SVGs are well-formed XML, every measured error is finite, and the errors are ordered as
//! theory says. No assertion on any time.

use std::path::PathBuf;

use cg_bench::{Config, Experiment, Machine, Report};

const IDS: [&str; 8] = [
    "shading",
    "vertex-normals",
    "face-normals",
    "normalise",
    "fresnel",
    "area-light",
    "ray-depth",
    "features",
];

fn out_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cg-bench-test-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

fn experiment<'a>(report: &'a Report, id: &str) -> &'a Experiment {
    report.experiments.iter().find(|e| e.id == id).unwrap_or_else(|| panic!("no experiment {id}"))
}

fn value(e: &Experiment, key: &[&str], column: &str) -> f64 {
    e.value(key, column).unwrap_or_else(|| panic!("{}: no {key:?} / {column}", e.id))
}

#[test]
fn the_tiny_report_is_complete_finite_and_ordered_as_theory_says() {
    let config = Config::tiny();
    let machine = Machine { cpu: "test cpu".into(), cores: 1, commit: "0123abc".into() };
    let mut seen = Vec::new();
    let report = cg_bench::run(&config, machine, |id| seen.push(id.to_string())).unwrap();
    assert_eq!(seen, IDS, "every experiment runs, in report order");

    // Structure: the Markdown names the machine and commit, has a table and a plot per
    // experiment, and every SVG is there and parses.
    let dir = out_dir();
    let md_path = dir.join("docs").join("speed-vs-error.md");
    std::fs::create_dir_all(md_path.parent().unwrap()).unwrap();
    let written = report.write(&md_path).unwrap();
    assert_eq!(written.len(), IDS.len() + 1);
    let md = std::fs::read_to_string(&md_path).unwrap();
    assert!(md.contains("test cpu") && md.contains("0123abc"), "machine and commit:\n{md}");
    for id in IDS {
        let e = experiment(&report, id);
        assert!(!e.rows.is_empty(), "{id} has rows");
        assert!(md.contains(&format!("![{id}](speed-vs-error/{id}.svg)")), "{id}'s plot is linked");
        let header = format!("| {} |", e.keys[0]);
        assert!(md.contains(&header), "{id}'s table header");
        assert!(md.contains(&format!("## {}", e.title)), "{id}'s heading");
        let svg_path = dir.join("docs").join("speed-vs-error").join(format!("{id}.svg"));
        let svg = std::fs::read_to_string(&svg_path).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap_or_else(|err| panic!("{id}.svg: {err}"));
        assert_eq!(doc.root_element().tag_name().name(), "svg");
        assert!(!svg.contains("plot failed"), "{id}.svg was drawn");
        assert!(doc.descendants().filter(|n| n.has_tag_name("circle")).count() >= e.rows.len());
        for row in &e.rows {
            assert_eq!(row.key.len(), e.keys.len());
            assert_eq!(row.values.len(), e.columns.len());
            for (c, v) in e.columns.iter().zip(&row.values) {
                if c.error {
                    assert!(v.is_finite() && *v >= 0.0, "{id} {:?} {}: {v}", row.key, c.name);
                }
            }
        }
        // At least one point is on the Pareto front, and the table marks it.
        assert!(cg_bench::measure::pareto_front(&e.points()).contains(&true), "{id}");
    }
    assert!(md.matches(" ✓ |").count() >= IDS.len(), "Pareto marks in the tables");
    let _ = std::fs::remove_dir_all(&dir);

    // Shading: Phong keeps the highlight better than Gouraud at every tessellation, and more
    // triangles bring Gouraud closer to the reference.
    let shading = experiment(&report, "shading");
    for level in &config.levels {
        for n in &config.exponents {
            let (level, n) = (level.to_string(), n.to_string());
            let phong = value(shading, &["Phong", &level, &n], "peak error");
            let gouraud = value(shading, &["Gouraud", &level, &n], "peak error");
            assert!(phong < gouraud, "level {level}, n {n}: Phong {phong} vs Gouraud {gouraud}");
            let phong_evals = value(shading, &["Phong", &level, &n], "lighting evaluations");
            let gouraud_evals = value(shading, &["Gouraud", &level, &n], "lighting evaluations");
            assert!(phong_evals > gouraud_evals, "Phong lights every pixel");
        }
    }
    let n = config.exponents[0].to_string();
    let (coarse, fine) = (config.levels[0].to_string(), config.levels[1].to_string());
    assert!(
        value(shading, &["Gouraud", &fine, &n], "RMS error")
            < value(shading, &["Gouraud", &coarse, &n], "RMS error")
    );

    // Vertex normals: Max is exact on spheres (every vertex on the sphere), angle beats area.
    let vn = experiment(&report, "vertex-normals");
    for mesh in ["UV sphere", "jittered sphere"] {
        let max = value(vn, &["Max", mesh], "max angle [°]");
        let angle = value(vn, &["angle", mesh], "mean angle [°]");
        let area = value(vn, &["area", mesh], "mean angle [°]");
        assert!(max < 1e-3, "{mesh}: Max {max}°");
        assert!(angle < area, "{mesh}: angle {angle}° vs area {area}°");
    }

    // Face normals on needles: f64 ≤ the kit's f32 ≤ naive f32.
    let fnrm = experiment(&report, "face-normals");
    let needle = |m: &str| value(fnrm, &[m, "needle"], "max angle [rad]");
    let (f64_, kit, naive) =
        (needle("face_normal_f64"), needle("face_normal (f32)"), needle("naive f32"));
    assert!(f64_ <= kit && kit <= naive, "f64 {f64_} kit {kit} naive {naive}");
    assert!(kit < 1e-6 && naive > 1e-4, "kit {kit} naive {naive}");
    assert_eq!(value(fnrm, &["face_normal (f32)", "needle"], "missing"), 0.0);

    // Normalisation: the Newton step makes the bit trick far better; exact is exact to f32.
    let norm = experiment(&report, "normalise");
    let rel = |m: &str| value(norm, &[m], "max relative error");
    assert!(rel("exact f32 (v/|v|)") < 1e-6);
    assert!(rel("rsqrt bits + Newton") < rel("rsqrt bits") / 10.0);
    assert!(rel("rsqrt bits") > 0.01);

    // Fresnel: Schlick is not exact; the kit's handles total internal reflection, the naive
    // one does not.
    let fr = experiment(&report, "fresnel");
    for side in ["outside 1→1.5", "inside 1.5→1"] {
        assert!(value(fr, &["Schlick (kit)", side], "max abs error") > 0.0);
        assert!(value(fr, &["Schlick (kit)", side], "max abs error") < 0.05);
        assert_eq!(value(fr, &["exact", side], "max abs error"), 0.0);
    }
    assert_eq!(value(fr, &["Schlick (kit)", "inside 1.5→1"], "TIR wrong"), 0.0);
    assert!(value(fr, &["Schlick, cos θ_i inside", "inside 1.5→1"], "TIR wrong") > 0.0);
    assert!(value(fr, &["Schlick, cos θ_i inside", "inside 1.5→1"], "max abs error") > 0.5);

    // Area light: more samples, closer to the converged image.
    let area = experiment(&report, "area-light");
    let errors: Vec<f64> = area.rows.iter().map(|r| r.values[0]).collect();
    assert!(errors.first() > errors.last(), "{errors:?}");
    // Ray depth: deeper, closer to depth 16.
    let depth = experiment(&report, "ray-depth");
    let errors: Vec<f64> = depth.rows.iter().map(|r| r.values[0]).collect();
    assert!(errors.first() > errors.last(), "{errors:?}");

    // Only what the scene needs: an absent term is not computed; a present one is.
    let f = experiment(&report, "features");
    let base = ["rasterizer", "none (diffuse, point light)"];
    assert_eq!(value(f, &base, "specular terms"), 0.0);
    assert_eq!(value(f, &base, "attenuations"), 0.0);
    assert!(value(f, &["rasterizer", "specular, k_s = 1e-6"], "specular terms") > 0.0);
    assert!(value(f, &["rasterizer", "attenuation, k_l = 1e-7"], "attenuations") > 0.0);
    assert!(value(f, &["rasterizer", "specular, k_s = 1e-6"], "RMS vs none") < 1.0 / 255.0);
    assert!(value(f, &["rasterizer", "texture, white"], "texture samples / rays") > 0.0);
    assert!(value(f, &["ray tracer", "shadows (tracer)"], "texture samples / rays") > 0.0);
    assert_eq!(value(f, &["ray tracer", base[1]], "texture samples / rays"), 0.0);
}

/// A `--out` the report cannot take is said before any experiment runs, in both languages: a
/// folder (it failed after the whole run, leaving the SVGs in it), a name without an extension
/// (whose SVG folder is the file itself, so it could never succeed).
#[test]
fn an_out_the_report_cannot_take_is_refused_before_it_runs() {
    let dir = out_dir();
    std::fs::create_dir_all(&dir).unwrap();
    for (out, said) in [
        (dir.clone(), "is a folder"),
        (dir.join("plots/"), "is a folder"),
        (dir.join("report"), "has no extension"),
    ] {
        let e = cg_bench::check_out(&out).unwrap_err();
        let en = e.message(cg_core::lang::Lang::En);
        assert!(en.starts_with("--out ") && en.contains(said), "{en}");
        assert!(!e.message(cg_core::lang::Lang::Ja).contains(said));
    }
    cg_bench::check_out(&dir.join("report.md")).unwrap();
    assert_eq!(std::fs::read_dir(&dir).unwrap().count(), 0, "nothing written");
    let _ = std::fs::remove_dir_all(&dir);
}
