//! Speed against error (速度と誤差): the kit's benchmark report.
//!
//! Every experiment of docs/numerics.md's second table runs on this machine in one run, measures what
//! each choice costs (median wall-clock time over repeated runs, [`std::time::Instant`]) and how
//! far it lands from a reference, and becomes a table and an SVG plot (error against time, the
//! Pareto front marked) in `docs/speed-vs-error.md`:
//!
//! | id | experiment | reference |
//! |---|---|---|
//! | `shading` | flat / Gouraud / Phong × tessellation × exponent n | the ray tracer's exact sphere, lit per pixel |
//! | `vertex-normals` | uniform / area / angle / Max weights on four meshes | analytic surface normals |
//! | `face-normals` | naive f32, Kahan f32, the kit's `face_normal` (f32, f64) | an exact (double-double) cross product |
//! | `normalise` | exact, the kit's `try_normalize`, bit-trick rsqrt ± one Newton step | f64 |
//! | `fresnel` | exact, Schlick, Schlick on the wrong side | [`cg_core::optics::fresnel_dielectric`] |
//! | `area-light` | area-light samples per side | many samples |
//! | `ray-depth` | the tracer's `max_depth` | depth 16 |
//! | `features` | each renderer (rasterizer, ray tracer, GPU) with and without each feature | the scene without it |
//!
//! Nothing here asserts a time: the figures are for the report (docs/numerics.md lists figures seen
//! elsewhere, for comparison). The errors are deterministic (seeded inputs); the times are not.
//!
//! Entry points: [`run`] measures and returns a [`Report`]; [`Report::write`] writes the
//! Markdown and the SVGs.

use cg_core::lang::{Text, t};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

pub mod experiments;
pub mod measure;
pub mod plot;

/// How big and how often: [`Config::full`] for the committed report, [`Config::quick`] for
/// `cg bench --quick` (under a minute in a release build), [`Config::tiny`] for the tests (debug
/// builds).
#[derive(Clone, Debug, PartialEq)]
pub struct Config {
    /// A name for the report header (`full`, `quick`, `tiny`).
    pub name: &'static str,
    /// Repetitions of each timed run (the median is reported).
    pub reps: usize,
    /// Image side of the shading experiment, pixels.
    pub shading_size: u32,
    /// Icosphere subdivision levels of the shading experiment.
    pub levels: Vec<u32>,
    /// Specular exponents n of the shading experiment.
    pub exponents: Vec<f32>,
    /// Resolution of the vertex-normal meshes (segments around; the rest follows).
    pub mesh_segments: u32,
    /// Triangles per case in the face-normal experiment.
    pub face_samples: usize,
    /// Vectors (normalisation) and angles (Fresnel) per case.
    pub scalar_samples: usize,
    /// Image side of the ray-traced experiments, pixels.
    pub trace_size: u32,
    /// Area-light samples per side (k × k point lights).
    pub area_samples: Vec<u32>,
    /// Samples per side of the converged area-light reference.
    pub area_reference: u32,
    /// Ray depths compared against [`Config::depth_reference`].
    pub depths: Vec<u32>,
    /// The converged ray depth.
    pub depth_reference: u32,
    /// Image side of the "only what the scene needs" experiment, pixels (the CPU renderers).
    pub features_size: u32,
    /// Image side of the same experiment's GPU rows, pixels: larger, so that the shading and not
    /// the fixed cost of a submission dominates the time.
    pub features_gpu_size: u32,
    /// Draws per timed GPU run: the GPU's time per frame is `draws` draws into a prepared frame
    /// and one wait, divided by `draws`.
    pub gpu_draws: u32,
}

impl Config {
    /// The committed report: every knob at the sizes docs/numerics.md discusses.
    #[must_use]
    pub fn full() -> Config {
        Config {
            name: "full",
            reps: 11,
            shading_size: 256,
            levels: vec![1, 2, 3, 4, 5],
            exponents: vec![8.0, 32.0, 128.0],
            mesh_segments: 64,
            face_samples: 20_000,
            scalar_samples: 200_000,
            trace_size: 128,
            area_samples: vec![1, 2, 3, 4, 6, 8],
            area_reference: 32,
            depths: vec![0, 1, 2, 3, 4, 6, 8],
            depth_reference: 16,
            // 512: the time saved by a skipped term shows above the noise (at 256 it hardly did).
            features_size: 512,
            // Lavapipe on 2 cores: about 1.2 ms a frame at 64 × 64 whatever the shader (the fixed
            // cost), about 50 ms at 1024 × 1024: the shading dominates.
            features_gpu_size: 1024,
            gpu_draws: 2,
        }
    }

    /// `cg bench --quick`: smaller images, fewer repetitions; under a minute in a release build.
    #[must_use]
    pub fn quick() -> Config {
        Config {
            name: "quick",
            reps: 3,
            shading_size: 128,
            levels: vec![1, 2, 3, 4],
            exponents: vec![8.0, 32.0, 128.0],
            mesh_segments: 32,
            face_samples: 4_000,
            scalar_samples: 40_000,
            trace_size: 64,
            area_samples: vec![1, 2, 4, 8],
            area_reference: 16,
            depths: vec![0, 1, 2, 4],
            depth_reference: 16,
            features_size: 128,
            features_gpu_size: 512,
            gpu_draws: 4,
        }
    }

    /// The smallest configuration that still shows every ordering the tests check; for debug
    /// builds.
    #[must_use]
    pub fn tiny() -> Config {
        Config {
            name: "tiny",
            reps: 1,
            shading_size: 64,
            levels: vec![1, 3],
            exponents: vec![128.0],
            mesh_segments: 16,
            face_samples: 500,
            scalar_samples: 2_000,
            trace_size: 24,
            area_samples: vec![1, 4],
            area_reference: 8,
            depths: vec![0, 2],
            depth_reference: 8,
            features_size: 48,
            features_gpu_size: 64,
            gpu_draws: 2,
        }
    }
}

/// One column of an experiment's table.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// Header (English; units in brackets).
    pub name: &'static str,
    /// Whether the column is an error measure (the tests check every one is finite).
    pub error: bool,
}

impl Column {
    /// A column of measured errors.
    #[must_use]
    pub fn error(name: &'static str) -> Column {
        Column { name, error: true }
    }

    /// Any other numeric column (times, counts).
    #[must_use]
    pub fn value(name: &'static str) -> Column {
        Column { name, error: false }
    }
}

/// One row: the knobs (text) and the measurements (numbers, in [`Experiment::columns`] order).
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The knob settings, in [`Experiment::keys`] order.
    pub key: Vec<String>,
    /// The measurements, in [`Experiment::columns`] order; NaN where a measure does not apply to
    /// the row (the table shows `—`).
    pub values: Vec<f64>,
}

/// One experiment: a table, and which of its columns the plot shows.
#[derive(Clone, Debug, PartialEq)]
pub struct Experiment {
    /// Short id: the SVG is `<id>.svg`.
    pub id: &'static str,
    /// Title, Japanese / English.
    pub title: &'static str,
    /// What was measured and against what, a Markdown paragraph (Japanese and English).
    pub about: String,
    /// Names of the knob columns.
    pub keys: Vec<&'static str>,
    /// The measured columns.
    pub columns: Vec<Column>,
    /// The rows.
    pub rows: Vec<Row>,
    /// Which key column names a plot series (points of one series share a colour).
    pub series_key: usize,
    /// The plot's x column (a time).
    pub time_column: usize,
    /// The plot's y column (an error).
    pub error_column: usize,
}

impl Experiment {
    /// The value of `column` in the row whose keys are `key` (all of them, in order).
    #[must_use]
    pub fn value(&self, key: &[&str], column: &str) -> Option<f64> {
        let c = self.columns.iter().position(|col| col.name == column)?;
        let row =
            self.rows.iter().find(|r| r.key.iter().map(String::as_str).eq(key.iter().copied()))?;
        row.values.get(c).copied()
    }

    /// The values of `column` in every row whose keys match `pattern` (`None` matches anything).
    #[must_use]
    pub fn values_where(&self, pattern: &[Option<&str>], column: &str) -> Vec<(Vec<String>, f64)> {
        let Some(c) = self.columns.iter().position(|col| col.name == column) else {
            return Vec::new();
        };
        self.rows
            .iter()
            .filter(|r| pattern.iter().zip(&r.key).all(|(p, k)| p.is_none_or(|p| p == k.as_str())))
            .filter_map(|r| Some((r.key.clone(), *r.values.get(c)?)))
            .collect()
    }

    /// (time, error) of every row, as plotted.
    #[must_use]
    pub fn points(&self) -> Vec<(f64, f64)> {
        self.rows
            .iter()
            .map(|r| (r.values[self.time_column], r.values[self.error_column]))
            .collect()
    }
}

/// The machine and the commit the report ran on.
#[derive(Clone, Debug, PartialEq)]
pub struct Machine {
    /// The CPU model (`model name` of `/proc/cpuinfo`), or `unknown`.
    pub cpu: String,
    /// Logical cores available to this process.
    pub cores: usize,
    /// `git rev-parse HEAD` of the kit, or `unknown`.
    pub commit: String,
}

impl Machine {
    /// Reads `/proc/cpuinfo`, the available parallelism and the git commit of `repo` (the
    /// current directory when `None`). Never fails: what cannot be read is `unknown`.
    #[must_use]
    pub fn detect(repo: Option<&Path>) -> Machine {
        // platform: Linux's /proc; elsewhere the read fails and the CPU is "unknown".
        let cpu = std::fs::read_to_string("/proc/cpuinfo")
            .ok()
            .and_then(|s| {
                s.lines()
                    .find(|l| l.starts_with("model name"))
                    .and_then(|l| l.split_once(':'))
                    .map(|(_, v)| v.trim().to_string())
            })
            .unwrap_or_else(|| "unknown".into());
        let cores = std::thread::available_parallelism().map_or(1, usize::from);
        let mut git = std::process::Command::new("git");
        if let Some(dir) = repo {
            git.current_dir(dir);
        }
        let commit = git
            .args(["rev-parse", "HEAD"])
            .output()
            .ok()
            .filter(|o| o.status.success())
            .and_then(|o| String::from_utf8(o.stdout).ok())
            .map(|s| s.trim().to_string())
            .filter(|s| !s.is_empty())
            .unwrap_or_else(|| "unknown".into());
        Machine { cpu, cores, commit }
    }
}

/// Every experiment's results, and where they ran.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// The configuration used.
    pub config: Config,
    /// The machine and commit.
    pub machine: Machine,
    /// The experiments, in report order.
    pub experiments: Vec<Experiment>,
}

/// Something went wrong running or writing the report.
#[derive(Debug)]
pub enum BenchError {
    /// A renderer refused a scene the bench built (a bug in the bench).
    Render(String),
    /// Writing the Markdown or an SVG failed.
    Io {
        /// The file.
        path: PathBuf,
        /// Why, in both languages ([`Text::io`]).
        reason: Text,
    },
    /// `--out` cannot take the report: a folder, or a name without an extension (whose SVG
    /// folder would be the file itself). Said before anything runs.
    Out {
        /// The path given.
        path: PathBuf,
        /// Why, in both languages.
        reason: Text,
    },
}

impl BenchError {
    /// The message in `lang`.
    #[must_use]
    pub fn message(&self, lang: cg_core::lang::Lang) -> String {
        match self {
            BenchError::Render(e) => {
                format!("{}: {e}", t("描画に失敗しました", "rendering failed").get(lang))
            }
            BenchError::Io { path, reason } => Text::new(
                format!("{} に書き込めません: {}", path.display(), reason.ja),
                format!("cannot write {}: {}", path.display(), reason.en),
            )
            .get(lang)
            .to_owned(),
            BenchError::Out { path, reason } => {
                format!("--out {}: {}", path.display(), reason.get(lang))
            }
        }
    }
}

/// Whether the report can be written to `markdown` (see [`Report::write`]): a file name with an
/// extension (`report.md`; the SVGs go into the folder named without it), not a folder. Checked
/// by `cg bench` before its experiments run, so a wrong `--out` does not cost the whole run.
///
/// # Errors
/// [`BenchError::Out`] with why.
pub fn check_out(markdown: &Path) -> Result<(), BenchError> {
    let refuse = |ja: &str, en: &str| {
        Err(BenchError::Out { path: markdown.to_path_buf(), reason: Text::new(ja, en) })
    };
    if markdown.is_dir() || markdown.as_os_str().to_string_lossy().ends_with(['/', '\\']) {
        return refuse(
            "フォルダです。Markdown のファイル名（report.md など）を指定してください",
            "is a folder: give the Markdown file's name (report.md, say)",
        );
    }
    if markdown.extension().is_none() {
        return refuse(
            "拡張子がありません（図は拡張子を除いた名前のフォルダに書くので、同じ名前になります）。report.md のように指定してください",
            "has no extension (the plots go to the folder of its name without one, which would be the file itself): give report.md, say",
        );
    }
    Ok(())
}

impl std::fmt::Display for BenchError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message(cg_core::lang::Lang::En))
    }
}

impl std::error::Error for BenchError {}

/// Runs every experiment with `config`; `progress` is called with each experiment's id before
/// it starts.
///
/// # Errors
/// [`BenchError::Render`] when a renderer refuses one of the bench's own scenes.
pub fn run(
    config: &Config,
    machine: Machine,
    mut progress: impl FnMut(&str),
) -> Result<Report, BenchError> {
    use experiments as e;
    let mut experiments = Vec::new();
    type Step = fn(&Config) -> Result<Experiment, BenchError>;
    let steps: [(&str, Step); 8] = [
        ("shading", e::shading::run),
        ("vertex-normals", e::vertex_normals::run),
        ("face-normals", e::face_normals::run),
        ("normalise", e::normalise::run),
        ("fresnel", e::fresnel::run),
        ("area-light", e::trace::area_light),
        ("ray-depth", e::trace::ray_depth),
        ("features", e::features::run),
    ];
    for (id, step) in steps {
        progress(id);
        experiments.push(step(config)?);
    }
    Ok(Report { config: config.clone(), machine, experiments })
}

/// A number for a table: 4 significant digits, scientific when very small or large; NaN (a
/// measure that does not apply to the row, such as a CPU counter on a GPU row) is `—`.
#[must_use]
pub fn format_value(x: f64) -> String {
    if x.is_nan() {
        "—".into()
    } else if x == 0.0 {
        "0".into()
    } else if !x.is_finite() {
        format!("{x}")
    } else if x.fract() == 0.0 && x.abs() < 1e9 {
        format!("{x:.0}")
    } else if x.abs() >= 1e-3 && x.abs() < 1e5 {
        let digits = (3 - x.abs().log10().floor() as i32).clamp(0, 6) as usize;
        format!("{x:.digits$}")
    } else {
        format!("{x:.3e}")
    }
}

impl Report {
    /// The Markdown of the report; `svg_dir` is how the Markdown refers to the SVG folder.
    #[must_use]
    pub fn markdown(&self, svg_dir: &str) -> String {
        let mut s = String::new();
        let m = &self.machine;
        let _ = writeln!(s, "# 速度と誤差 / Speed against error\n");
        let _ = writeln!(
            s,
            "生成: `cargo run --release -- bench` (設定 `{}`)。手で編集しないでください。\n\
             Generated by `cargo run --release -- bench` (configuration `{}`); do not edit by hand.\n",
            self.config.name, self.config.name
        );
        let _ = writeln!(s, "| | |\n|---|---|");
        let _ = writeln!(s, "| CPU | {} |", m.cpu);
        let _ = writeln!(s, "| コア / cores | {} |", m.cores);
        let _ = writeln!(s, "| コミット / commit | `{}` |", m.commit);
        let _ = writeln!(s, "| 繰り返し / repetitions | {} (median) |\n", self.config.reps);
        let _ = writeln!(
            s,
            "時間は壁時計の中央値、描画は 1 スレッド。誤差は固定した乱数の入力で決定的。図は誤差対時間 \
             (両対数)、◯ で囲んだ点と線がパレート最前線 (より速くより正確な選択肢がない点)。\n\
             Times are wall-clock medians; renderers run on one thread. Errors are deterministic \
             (seeded inputs). Each plot shows error against time (log–log); the circled points \
             joined by a line are the Pareto front (no other choice is both faster and more \
             accurate). Zero errors are drawn at the bottom of the plot. The table's `Pareto` \
             column marks the same points. docs/numerics.md lists figures seen elsewhere, for comparison.\n"
        );
        for e in &self.experiments {
            let _ = writeln!(s, "## {}\n", e.title);
            let _ = writeln!(s, "{}\n", e.about);
            let _ = writeln!(s, "![{}]({}/{}.svg)\n", e.id, svg_dir, e.id);
            let front = measure::pareto_front(&e.points());
            let mut header: Vec<&str> = e.keys.clone();
            header.extend(e.columns.iter().map(|c| c.name));
            header.push("Pareto");
            let _ = writeln!(s, "| {} |", header.join(" | "));
            let _ = writeln!(s, "|{}", "---|".repeat(header.len()));
            for (row, on_front) in e.rows.iter().zip(front) {
                let mut cells: Vec<String> = row.key.clone();
                cells.extend(row.values.iter().map(|&v| format_value(v)));
                cells.push(if on_front { "✓".into() } else { String::new() });
                let _ = writeln!(s, "| {} |", cells.join(" | "));
            }
            s.push('\n');
        }
        s
    }

    /// Writes the Markdown to `markdown` and one SVG per experiment into the folder beside it
    /// named after it without the extension (`docs/speed-vs-error.md` →
    /// `docs/speed-vs-error/<id>.svg`), creating folders as needed.
    ///
    /// # Errors
    /// [`BenchError::Io`] when a file cannot be written.
    pub fn write(&self, markdown: &Path) -> Result<Vec<PathBuf>, BenchError> {
        let stem = markdown
            .file_stem()
            .map_or_else(|| "speed-vs-error".into(), |s| s.to_string_lossy().into_owned());
        let dir = markdown.with_file_name(&stem);
        check_out(markdown)?;
        let io = |path: &Path, e: &std::io::Error| BenchError::Io {
            path: path.to_path_buf(),
            reason: Text::io(e),
        };
        std::fs::create_dir_all(&dir).map_err(|e| io(&dir, &e))?;
        let mut written = Vec::new();
        for e in &self.experiments {
            let path = dir.join(format!("{}.svg", e.id));
            let svg = plot::svg(e);
            std::fs::write(&path, svg).map_err(|err| io(&path, &err))?;
            written.push(path);
        }
        std::fs::write(markdown, self.markdown(&stem)).map_err(|e| io(markdown, &e))?;
        written.push(markdown.to_path_buf());
        Ok(written)
    }
}
