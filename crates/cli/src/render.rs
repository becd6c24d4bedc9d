//! `cg render [SCENE]`: draws a scene to a PNG file with one of the kit's renderers and says what
//! it cost and what it enabled; and the kit's main job, the course's sample scene in every
//! shading mode.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use cg_core::features::Features;
use cg_core::image::Image;
use cg_core::lang::{Lang, Text, t};
use cg_core::scene::{Scene, Shading};

/// Which renderer draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Renderer {
    /// The CPU rasterizer (flat, Gouraud, Phong; the local light model) / CPU ラスタライザ
    Raster,
    /// The Whitted ray tracer (shadows, k_r·I_r, k_t·I_t) / レイトレーシング
    Trace,
    /// The GPU renderer (wgpu; WGSL generated for the scene's features; the students' copy builds it with `--features gpu`) / GPU レンダラ（学生用のコピーでは --features gpu を付けてビルド）
    Gpu,
}

/// Fresnel reflectance on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum FresnelArg {
    /// The exact dielectric Fresnel equations / 厳密なフレネルの式
    Exact,
    /// Schlick's approximation / Schlick の近似
    Schlick,
}

/// A shading mode on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ShadingArg {
    /// Flat: one colour per face / フラットシェーディング
    Flat,
    /// Gouraud: vertex colours interpolated / グローシェーディング
    Gouraud,
    /// Phong: normals interpolated, lit per pixel / フォンシェーディング
    Phong,
}

impl From<ShadingArg> for Shading {
    fn from(s: ShadingArg) -> Shading {
        match s {
            ShadingArg::Flat => Shading::Flat,
            ShadingArg::Gouraud => Shading::Gouraud,
            ShadingArg::Phong => Shading::Phong,
        }
    }
}

/// Options of `cg render`.
#[derive(clap::Args)]
pub struct Args {
    /// The scene file (default: the course's sample scene) / シーンファイル
    scene: Option<PathBuf>,
    /// Which renderer / レンダラ
    #[arg(long, value_enum, default_value_t = Renderer::Raster)]
    renderer: Renderer,
    /// Shading mode instead of the scene's / シェーディングの方法（省略時はシーンの指定）
    #[arg(long, value_enum)]
    shading: Option<ShadingArg>,
    /// The PNG file to write (default: out/SCENE-RENDERER-SHADING.png) / 出力する PNG ファイル
    #[arg(short, long, value_name = "PNG")]
    output: Option<PathBuf>,
    /// Image width in pixels, 1–16384 (default: the scene's; alone, the height follows the
    /// scene's aspect ratio) / 画像の幅（ピクセル、1〜16384。省略時はシーンの幅。幅だけ指定すると高さはシーンの縦横比から決まります）
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
    width: Option<u32>,
    /// Image height in pixels, 1–16384 / 画像の高さ（ピクセル、1〜16384）
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=16384))]
    height: Option<u32>,
    /// Threads, 1–256 (default: all cores; the image is the same for any count) / スレッド数（1〜256。省略時はすべてのコア。結果は同じです）
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
    threads: Option<u16>,
    /// Ray tracer: how many reflections/refractions deep rays go / レイの最大の深さ
    #[arg(long, default_value_t = 5, value_parser = clap::value_parser!(u32).range(0..=64))]
    max_depth: u32,
    /// Ray tracer: Fresnel reflectance / フレネル反射率の計算
    #[arg(long, value_enum, default_value_t = FresnelArg::Exact)]
    fresnel: FresnelArg,
    /// Ray tracer: no shadow rays / 影を計算しない
    #[arg(long)]
    no_shadows: bool,
    /// The scene file's encoding: utf-8, utf-16le, utf-16be or shift_jis (default: detected) / シーンファイルの文字コード（省略時は自動判別）
    #[arg(long, value_name = "ENCODING")]
    encoding: Option<cg_core::text::Encoding>,
}

/// The ray tracer's settings from the command line.
#[derive(Clone, Copy)]
struct TraceSettings {
    max_depth: u32,
    fresnel: FresnelArg,
    shadows: bool,
}

impl Default for TraceSettings {
    fn default() -> TraceSettings {
        TraceSettings { max_depth: 5, fresnel: FresnelArg::Exact, shadows: true }
    }
}

/// One rendering, done.
struct Rendered {
    image: Image,
    shading: Shading,
    millis: f64,
    report: String,
}

/// `cg render`: loads, draws, writes, reports.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    let path = crate::kit_path(args.scene.as_deref(), crate::COURSE_SAMPLE);
    let scene = cg_scene::load_encoded(&path, args.encoding).map_err(|e| {
        let said = e.describe(lang);
        match args.scene.as_deref().filter(|_| !path.exists()).and_then(assignment_hint) {
            Some(hint) => format!("{said}\n{}", hint.get(lang)),
            None => said,
        }
    })?;
    let size = size(&scene, args.width, args.height).map_err(|e| e.get(lang).to_owned())?;
    if args.renderer == Renderer::Raster
        && (args.max_depth != 5 || args.fresnel != FresnelArg::Exact || args.no_shadows)
    {
        eprintln!(
            "{}",
            t(
                "注意: --max-depth, --fresnel, --no-shadows はレイトレーサ（--renderer trace）の設定です。ラスタライザでは使いません",
                "note: --max-depth, --fresnel and --no-shadows are ray-tracer settings (--renderer trace); the rasterizer ignores them",
            ).get(lang)
        );
    }
    let asked = args.shading.map(Shading::from).unwrap_or(scene.shading);
    if args.renderer == Renderer::Trace && asked != Shading::Phong {
        eprintln!("{}", trace_shading_note(asked).get(lang));
    }
    let settings = TraceSettings {
        max_depth: args.max_depth,
        fresnel: args.fresnel,
        shadows: !args.no_shadows,
    };
    let r = draw(
        &scene,
        args.renderer,
        args.shading.map(Shading::from),
        size,
        args.threads.map(usize::from),
        settings,
        lang,
    )?;
    let output = match &args.output {
        Some(p) => p.clone(),
        None => PathBuf::from("out").join(format!(
            "{}-{}-{}.png",
            file_stem(&path),
            renderer_name(args.renderer),
            shading_name(r.shading).en.to_lowercase()
        )),
    };
    write(&output, &r.image, args.output.is_none(), lang)?;
    // With the picture on standard output (`-o /dev/stdout > a.png`) the words go to standard
    // error, or they would land in the PNG.
    let words = format!(
        "{} {} — {}, {}, {} × {}, {:.1} ms\n{}{}: {}",
        t("描画しました", "rendered").get(lang),
        path.display(),
        renderer_label(args.renderer).get(lang),
        shading_name(r.shading).get(lang),
        r.image.width,
        r.image.height,
        r.millis,
        r.report,
        t("出力", "wrote").get(lang),
        output.display()
    );
    if is_device(&output) {
        eprintln!("{words}");
    } else {
        println!("{words}");
    }
    if nothing_drawn(&scene, &r.image) {
        eprintln!("{}", nothing_drawn_note().get(lang));
    }
    Ok(())
}

/// Said when the ray tracer is asked for flat or Gouraud shading, which it draws its own way
/// (`cg_trace::Options::shading`).
fn trace_shading_note(asked: Shading) -> Text {
    if asked == Shading::Gouraud {
        t(
            "注意: レイトレーサにはグローシェーディングがありません（補間する頂点の色を持たないため）。当たった点ごとに光源処理をするフォンシェーディングで描きます",
            "note: the ray tracer has no Gouraud shading (it has no vertex colours to interpolate): it lights every point a ray hits, as Phong shading",
        )
    } else {
        t(
            "注意: レイトレーサのフラットシェーディングは三角形の面ごとに 1 回光源処理をします。正確な球と平面（sphere・grid）には面がないので、当たった点ごとに光源処理をします",
            "note: the ray tracer's flat shading lights each triangle once; exact spheres and planes (sphere, grid shapes) have no faces and are lit at every point a ray hits",
        )
    }
}

/// Said when a scene with faces to draw gives a picture of the clear colour alone.
fn nothing_drawn_note() -> Text {
    t(
        "注意: 絵は背景色だけで、物体はどれも写っていません。カメラが物体の方を向いていないか、前方・後方クリップ面（near・far）の外にあるか、物体が視野の外にあります。`cg inspect` でカメラと物体の位置を確かめてください",
        "note: the picture is the clear colour alone: no object is in it. The camera may look away from the objects, the near and far planes may cut them off, or they lie outside the field of view; `cg inspect` shows the camera and where the objects are",
    )
}

/// Whether `scene` has faces to draw and `image` is nothing but its clear colour (compared as
/// the PNG stores it, 8 bits a channel, as the GPU's read-back gives it).
fn nothing_drawn(scene: &Scene, image: &Image) -> bool {
    let clear = Image::new(1, 1, scene.clear_color).to_rgba8()[0];
    scene.objects.iter().any(|o| o.mesh.face_count() > 0)
        && image.to_rgba8().iter().all(|&p| p == clear)
}

/// The shiny sphere of the main job's strip (the lecture's light model with a specular term).
const SHINY_SPHERE: &str = "assets/scenes/sphere-phong.toml";
/// The main job's strip of the three shading modes on the shiny sphere, under `out/`.
pub const SHADING_STRIP: &str = "lecture11-shading.png";
/// Each picture of the strip is this many pixels square.
const STRIP_SIDE: u32 = 320;

/// The last line of the main job: what to run next. Before a student number is recorded
/// (`recorded`: exercises/student.toml reads), the guide's next step, the student's own
/// assignments; then the tour of the scene.
fn next_steps(recorded: bool) -> Text {
    let tour = t(
        "`cargo run --release -- inspect`（頂点・面・法線・変換行列）、`cargo run --release -- render --help`（ほかのシーンや設定）",
        "`cargo run --release -- inspect` (vertices, faces, normals, matrices), `cargo run --release -- render --help` (other scenes and settings)",
    );
    if recorded {
        Text::new(format!("次に: {}", tour.ja), format!("Next: {}", tour.en))
    } else {
        Text::new(
            format!(
                "次に、自分の課題を表示し、学生番号を記録します（12345678 を自分の 8 桁の学生番号に）: `cargo run --release -- assignment --student 12345678 --save`。そのあとは {}",
                tour.ja
            ),
            format!(
                "Next, print your assignments and record your student number (your 8 digits in place of 12345678): `cargo run --release -- assignment --student 12345678 --save`. After that: {}",
                tour.en
            ),
        )
    }
}

/// What `render` adds when the scene it was given is no file but an assignment's ID (`a1`): the
/// command that shows an assignment. `None` for any other name.
fn assignment_hint(given: &Path) -> Option<Text> {
    let id = given.to_str().filter(|s| cg_assign::IDS.contains(s))?;
    Some(Text::new(
        format!("`{id}` は課題です。課題の結果を見るには: `cargo run --release -- view {id}`"),
        format!("`{id}` is an assignment: to look at it, run `cargo run --release -- view {id}`"),
    ))
}

/// The kit's main job: the course's sample scene drawn in every shading mode to PNG files, and
/// the shiny sphere in the three modes side by side, labelled.
pub fn main_job(lang: Lang) -> Result<(), String> {
    let path = crate::kit_path(None, crate::COURSE_SAMPLE);
    let scene = cg_scene::load(&path).map_err(|e| e.describe(lang))?;
    let dir = PathBuf::from("out");
    println!(
        "{} {} ({} × {}):",
        t("授業のサンプルシーンを描画します", "Drawing the course's sample scene").get(lang),
        path.display(),
        scene.width,
        scene.height
    );
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let r = draw(
            &scene,
            Renderer::Raster,
            Some(shading),
            None,
            None,
            TraceSettings::default(),
            lang,
        )?;
        let file =
            dir.join(format!("course-sample-{}.png", shading_name(shading).en.to_lowercase()));
        write(&file, &r.image, true, lang)?;
        println!(
            "  {:<24} {:>7.1} ms  {}",
            shading_name(shading).get(lang),
            r.millis,
            file.display()
        );
    }
    // The course scene has no specular term, so its three pictures look alike. Lecture 11's
    // point is the highlight: a shiny sphere in the three modes, side by side and labelled.
    let sphere_path = crate::kit_path(None, SHINY_SPHERE);
    let sphere = cg_scene::load(&sphere_path).map_err(|e| e.describe(lang))?;
    let mut pictures = Vec::new();
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let r = draw(
            &sphere,
            Renderer::Raster,
            Some(shading),
            Some((STRIP_SIDE, STRIP_SIDE)),
            None,
            TraceSettings::default(),
            lang,
        )?;
        pictures.push((r.image, shading_name(shading).en.to_uppercase()));
    }
    let row: Vec<(&Image, &str)> = pictures.iter().map(|(i, l)| (i, l.as_str())).collect();
    let strip = crate::label::labelled_row(&row, 2);
    let file = dir.join(SHADING_STRIP);
    write(&file, &strip, true, lang)?;
    println!(
        "{}:\n  {}",
        t(
            "第11回の要点、鏡面反射のある球をフラット・グロー・フォンシェーディングで並べた図",
            "Lecture 11 in one picture: a shiny sphere in flat, Gouraud and Phong shading"
        )
        .get(lang),
        file.display()
    );
    let recorded =
        cg_assign::read_student_file(&crate::kit_path(None, "exercises").join("student.toml"))
            .is_ok();
    println!("{}", next_steps(recorded).get(lang));
    // With a display, the course's program itself: the scene in a window, the sample's mouse
    // mapping and keys (CG_NO_WINDOW=1 keeps to the PNGs).
    if cg_viewer::display_available() && std::env::var_os("CG_NO_WINDOW").is_none() {
        println!(
            "{}",
            t("ウィンドウで表示します（閉じると終了）:", "Opening the viewer (close it to end):")
                .get(lang)
        );
        let options = cg_viewer::ViewerOptions { scene: Some(path), lang, ..Default::default() };
        cg_viewer::run(&options).map_err(|e| e.message(lang))?;
    }
    Ok(())
}

/// A file name made from the scene file's name: only letters and digits (kana and kanji too, so
/// `赤 1.toml` and `青 1.toml` do not both become `__1`), `.`, `_` and `-`; anything else (a
/// space, a separator, a character Windows forbids) becomes `_`, so the default output stays
/// inside `out/` whatever the scene is called.
fn file_stem(path: &Path) -> String {
    let stem = path.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let safe: String = stem
        .chars()
        .map(|c| if c.is_alphanumeric() || matches!(c, '.' | '_' | '-') { c } else { '_' })
        .collect();
    let safe = safe.trim_start_matches('.').to_owned();
    if safe.is_empty() { "scene".to_owned() } else { safe }
}

/// The image size: the scene's, or the given width and/or height (one alone keeps the aspect).
///
/// # Errors
/// The side that keeps the aspect rounds to 0 or exceeds [`cg_core::image::MAX_SIDE`] (a scene
/// of an extreme aspect): it was clamped, which changed the field of view without a word.
fn size(
    scene: &Scene,
    width: Option<u32>,
    height: Option<u32>,
) -> Result<Option<(u32, u32)>, Text> {
    let max = u64::from(cg_core::image::MAX_SIDE);
    let keep = |given: u32, this: u32, other: u32, (option, ja, en): (&str, &str, &str)| {
        // Rounded; `this` ≥ 1 because the scene loader checks sizes.
        let kept =
            (u64::from(given) * u64::from(other) + u64::from(this) / 2) / u64::from(this.max(1));
        if (1..=max).contains(&kept) {
            return Ok(kept as u32);
        }
        let (w, h) = (scene.width, scene.height);
        Err(Text::new(
            format!(
                "{option} {given} でシーンの縦横比（{w}×{h}）を保つと{ja}が {kept} になり、1〜{max} に収まりません。両方（--width と --height）を指定してください"
            ),
            format!(
                "{option} {given} with the scene's aspect ({w}×{h}) makes the {en} {kept}, outside 1 to {max}: give both --width and --height"
            ),
        ))
    };
    Ok(match (width, height) {
        (None, None) => None,
        (Some(w), Some(h)) => Some((w, h)),
        (Some(w), None) => {
            Some((w, keep(w, scene.width, scene.height, ("--width", "高さ", "height"))?))
        }
        (None, Some(h)) => {
            Some((keep(h, scene.height, scene.width, ("--height", "幅", "width"))?, h))
        }
    })
}

fn draw(
    scene: &Scene,
    renderer: Renderer,
    shading: Option<Shading>,
    size: Option<(u32, u32)>,
    threads: Option<usize>,
    trace: TraceSettings,
    lang: Lang,
) -> Result<Rendered, String> {
    let start = Instant::now();
    match renderer {
        Renderer::Raster => {
            let options =
                cg_raster::Options { shading, size, threads, ..cg_raster::Options::default() };
            let out = cg_raster::render(scene, &options).map_err(|e| e.message(lang))?;
            let millis = start.elapsed().as_secs_f64() * 1e3;
            let report = report(&out.features, out.stats.list(), lang);
            Ok(Rendered { image: out.image, shading: out.shading, millis, report })
        }
        Renderer::Trace => {
            let options = cg_trace::Options {
                size,
                threads,
                shading,
                max_depth: trace.max_depth,
                fresnel: match trace.fresnel {
                    FresnelArg::Exact => cg_trace::Fresnel::Exact,
                    FresnelArg::Schlick => cg_trace::Fresnel::Schlick,
                },
                shadows: trace.shadows,
                ..cg_trace::Options::default()
            };
            let rows = size.map_or(scene.height, |(_, h)| h);
            let progress = RowProgress::new(rows, lang);
            let out = cg_trace::render_with(scene, &options, &|| progress.row())
                .map_err(|e| e.message(lang))?;
            progress.finish();
            let millis = start.elapsed().as_secs_f64() * 1e3;
            let report = report(&out.features, out.stats.list(), lang);
            // What the tracer did: it traces Gouraud as Phong, and says so.
            Ok(Rendered { image: out.image, shading: out.shading, millis, report })
        }
        #[cfg(feature = "gpu")]
        Renderer::Gpu => {
            let gpu = cg_gpu::Gpu::new().map_err(|e| e.message(lang))?;
            let setup = start.elapsed().as_secs_f64() * 1e3;
            let start = Instant::now();
            let out = cg_gpu::Gpu::render(&gpu, scene, &cg_gpu::Options { shading, size })
                .map_err(|e| e.message(lang))?;
            let millis = start.elapsed().as_secs_f64() * 1e3;
            let mut report = report(&out.features, Vec::new(), lang);
            let _ = writeln!(
                report,
                "  {}: {}\n  {}: {}\n  {}: {setup:.1} ms",
                t("アダプタ", "adapter").get(lang),
                gpu.adapter_info(),
                t("シェーダに含めたもの", "in the generated shader").get(lang),
                out.enabled.iter().map(|n| n.get(lang)).collect::<Vec<_>>().join(", "),
                t("デバイスの準備", "device set-up").get(lang),
            );
            Ok(Rendered { image: out.image, shading: out.shading, millis, report })
        }
        // A build without the GPU renderer (the students' copy): the command that builds it.
        #[cfg(not(feature = "gpu"))]
        Renderer::Gpu => {
            let command = cg_harness::args::rerun_with_features("gpu");
            Err(cg_viewer::gpu_left_out(&command).get(lang).to_owned())
        }
    }
}

/// What the renderer enabled and skipped (from the scene's features) and the non-zero counters.
fn report(features: &Features, counts: Vec<(Text, u64)>, lang: Lang) -> String {
    let mut out = String::new();
    for line in features.describe(lang).lines() {
        let _ = writeln!(out, "  {line}");
    }
    let counts: Vec<String> = counts
        .into_iter()
        .filter(|(_, n)| *n > 0)
        .map(|(name, n)| format!("{} {n}", name.get(lang)))
        .collect();
    if !counts.is_empty() {
        let _ = writeln!(out, "  {}: {}", t("処理", "work").get(lang), counts.join(", "));
    }
    out
}

/// Writes the PNG. The default folder `out/` is made when missing; a folder the user named must
/// exist (a typo in `-o` is not silently turned into new folders), and the file must be named
/// `.png`, the only format the kit writes.
fn write(path: &Path, image: &Image, made_here: bool, lang: Lang) -> Result<(), String> {
    let png = path.extension().is_some_and(|e| e.eq_ignore_ascii_case("png"));
    // `dir/.png` ends with .png, but is a name without a stem (the path has no extension).
    let bare = path.file_name().is_some_and(|n| n.eq_ignore_ascii_case(".png"));
    if !png && !is_device(path) {
        let why = if bare {
            t(
                "ファイル名が .png だけです。.png の前に名前を付けてください（例: out/picture.png）",
                "the file name is only .png: put a name before it (out/picture.png)",
            )
        } else {
            t(
                "書き出せるのは PNG だけです。ファイル名を .png で終えてください",
                "the kit writes PNG files only: name the output file .png",
            )
        };
        return Err(format!("{}: {}", path.display(), why.get(lang)));
    }
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        if made_here {
            std::fs::create_dir_all(dir).map_err(|e| {
                format!(
                    "{} {}: {}",
                    t("フォルダを作れません", "cannot create the folder").get(lang),
                    dir.display(),
                    cg_core::lang::Text::io(&e).get(lang)
                )
            })?;
        } else if !dir.is_dir() {
            let why = if dir.exists() {
                t(
                    "フォルダではありません（同じ名前のファイルがあります）",
                    "not a folder (a file has this name)",
                )
            } else {
                t(
                    "このフォルダはありません（-o のフォルダは先に作ってください）",
                    "no such folder (make the folder of -o first)",
                )
            };
            return Err(format!("{}: {}", dir.display(), why.get(lang)));
        }
    }
    cg_scene::save_png(path, image).map_err(|e| e.describe(lang))
}

/// A device such as `/dev/null`, `/dev/stdout` or `/dev/fd/1` (no extension to ask for): a path
/// under `/dev` without an extension. A file named with one (`/dev/shm/a.jpg`) is a file.
fn is_device(path: &Path) -> bool {
    path.starts_with("/dev") && path.extension().is_none()
}

fn renderer_name(r: Renderer) -> &'static str {
    match r {
        Renderer::Raster => "raster",
        Renderer::Trace => "trace",
        Renderer::Gpu => "gpu",
    }
}

fn renderer_label(r: Renderer) -> Text {
    match r {
        Renderer::Raster => t("CPU ラスタライザ", "CPU rasterizer"),
        Renderer::Trace => t("レイトレーサ（Whitted）", "Whitted ray tracer"),
        Renderer::Gpu => t("GPU レンダラ（wgpu）", "GPU renderer (wgpu)"),
    }
}

/// The shading mode's name as the lecture says it.
pub fn shading_name(s: Shading) -> Text {
    match s {
        Shading::Flat => t("フラットシェーディング", "Flat"),
        Shading::Gouraud => t("グローシェーディング", "Gouraud"),
        Shading::Phong => t("フォンシェーディング", "Phong"),
    }
}

/// The ray tracer's progress on a terminal's stderr, one line rewritten in place: the rows done
/// and the time left, from the first second on (a render that ends sooner shows nothing). A
/// large scene (8192² pixels, glass, many lights) takes hours, and ran without a word. Not a
/// terminal (a log, a test): nothing.
struct RowProgress {
    rows: u32,
    done: std::sync::atomic::AtomicU32,
    start: Instant,
    /// When the line was last written (so at most twice a second), and whether it was.
    shown: std::sync::Mutex<Option<Instant>>,
    terminal: bool,
    lang: Lang,
}

impl RowProgress {
    fn new(rows: u32, lang: Lang) -> RowProgress {
        use std::io::IsTerminal as _;
        RowProgress {
            rows,
            done: std::sync::atomic::AtomicU32::new(0),
            start: Instant::now(),
            shown: std::sync::Mutex::new(None),
            terminal: std::io::stderr().is_terminal(),
            lang,
        }
    }

    /// One more row is done.
    fn row(&self) {
        let done = self.done.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
        if !self.terminal {
            return;
        }
        let elapsed = self.start.elapsed();
        let Ok(mut shown) = self.shown.lock() else { return };
        let due = shown.map_or(elapsed.as_secs_f64() >= 1.0, |at| at.elapsed().as_millis() >= 500);
        if !due {
            return;
        }
        *shown = Some(Instant::now());
        eprint!("\r{}", progress_line(done, self.rows, elapsed.as_secs_f64(), self.lang));
    }

    /// Clears the line, when one was shown.
    fn finish(&self) {
        if self.shown.lock().is_ok_and(|s| s.is_some()) {
            eprint!("\r{:60}\r", "");
        }
    }
}

/// `ray tracing: 120/640 rows (19 %), about 3 min left`.
fn progress_line(done: u32, rows: u32, seconds: f64, lang: Lang) -> String {
    let left = seconds * f64::from(rows.saturating_sub(done)) / f64::from(done.max(1));
    let left = if left >= 90.0 {
        format!("{:.0} {}", (left / 60.0).ceil(), t("分", "min").get(lang))
    } else {
        format!("{:.0} {}", left.ceil(), t("秒", "s").get(lang))
    };
    let percent = u64::from(done) * 100 / u64::from(rows.max(1));
    Text::new(
        format!("レイトレーシング: {done}/{rows} 行（{percent} %）、残り約 {left}  "),
        format!("ray tracing: {done}/{rows} rows ({percent} %), about {left} left  "),
    )
    .get(lang)
    .to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tracers_progress_says_rows_and_time_left_in_both_languages() {
        assert_eq!(
            progress_line(160, 640, 60.0, Lang::En),
            "ray tracing: 160/640 rows (25 %), about 3 min left  "
        );
        assert_eq!(
            progress_line(320, 640, 20.0, Lang::Ja),
            "レイトレーシング: 320/640 行（50 %）、残り約 20 秒  "
        );
        // No row done yet: no division by zero.
        assert!(progress_line(0, 640, 1.0, Lang::En).starts_with("ray tracing: 0/640 rows (0 %)"));
    }

    #[test]
    fn a_picture_of_the_clear_colour_alone_is_noted_only_when_there_was_something_to_draw() {
        let mut scene = cg_scene::load(&crate::kit_path(None, crate::COURSE_SAMPLE)).unwrap();
        let clear = Image::new(4, 3, scene.clear_color);
        assert!(nothing_drawn(&scene, &clear));
        // As the GPU reads it back: the same colour in 8 bits.
        let bytes = clear.to_rgba8();
        assert!(nothing_drawn(&scene, &Image::from_rgba8(4, 3, &bytes).unwrap()));
        // One pixel drawn: no note.
        let mut drawn = clear.clone();
        drawn.pixels[5] = cg_core::Rgb::new(1.0, 0.0, 0.0);
        assert!(!nothing_drawn(&scene, &drawn));
        // Nothing to draw: an empty scene's picture is what it should be.
        scene.objects.clear();
        assert!(!nothing_drawn(&scene, &clear));
    }

    #[test]
    fn the_first_run_points_to_the_assignment_until_a_number_is_recorded() {
        let first = next_steps(false);
        for s in [&first.ja, &first.en] {
            assert!(s.contains("`cargo run --release -- assignment --student 12345678 --save`"));
            assert!(s.contains("`cargo run --release -- inspect`"), "{s}");
        }
        let later = next_steps(true);
        assert!(!later.en.contains("assignment") && !later.ja.contains("--save"), "{later:?}");
        assert!(later.en.starts_with("Next: `cargo run --release -- inspect`"), "{}", later.en);
    }

    #[test]
    fn an_assignments_id_given_as_the_scene_points_to_view() {
        for id in ["a1", "a2", "a3", "a4", "s"] {
            let hint = assignment_hint(Path::new(id)).unwrap();
            let command = format!("`cargo run --release -- view {id}`");
            assert!(hint.en.contains(&command) && hint.ja.contains(&command), "{hint:?}");
            assert!(hint.en.starts_with(&format!("`{id}` is an assignment")), "{}", hint.en);
        }
        assert_eq!(assignment_hint(Path::new("a5")), None);
        assert_eq!(assignment_hint(Path::new("scenes/a1")), None);
        assert_eq!(assignment_hint(Path::new("a1.toml")), None);
    }

    #[test]
    fn default_output_names_stay_inside_out() {
        assert_eq!(file_stem(Path::new("assets/scenes/course-sample.toml")), "course-sample");
        assert_eq!(file_stem(Path::new("../../x/../../escaped.toml")), "escaped");
        assert_eq!(file_stem(Path::new("/tmp/シーン 1.toml")), "シーン_1");
        assert_ne!(file_stem(Path::new("赤 1.toml")), file_stem(Path::new("青 1.toml")));
        assert_eq!(file_stem(Path::new("a<b>:c|d?e*f\"g.toml")), "a_b__c_d_e_f_g");
        assert_eq!(file_stem(Path::new("..toml")), "scene");
        assert_eq!(file_stem(Path::new("")), "scene");
    }
}
