//! End-to-end tests of `cg render` and of the kit's main job (no arguments): the files they write
//! are exactly what the renderer library draws, and mistakes get clear errors.

use std::path::Path;

use cg_core::scene::Shading;

mod common;
use common::{cg as cg_in, root};

fn scratch(test: &str) -> std::path::PathBuf {
    common::scratch("cg-render", test)
}

fn png(path: &Path) -> (Vec<[u8; 4]>, u32, u32) {
    let img = image::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())).to_rgba8();
    let (w, h) = img.dimensions();
    (img.pixels().map(|p| p.0).collect(), w, h)
}

fn library(scene: &str, shading: Shading, size: Option<(u32, u32)>) -> Vec<[u8; 4]> {
    let scene = cg_scene::load(&root().join(scene)).unwrap();
    let options =
        cg_raster::Options { shading: Some(shading), size, ..cg_raster::Options::default() };
    cg_raster::render(&scene, &options).unwrap().image.to_rgba8()
}

#[test]
fn render_writes_exactly_what_the_rasterizer_draws() {
    let dir = scratch("render");
    let out = dir.join("sphere.png");
    let o = cg_in(
        &root(),
        &[
            "render",
            "assets/scenes/sphere-phong.toml",
            "--shading",
            "gouraud",
            "--width",
            "80",
            "--height",
            "60",
            "-o",
            out.to_str().unwrap(),
            "--lang",
            "en",
        ],
    );
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{text}\n{}", String::from_utf8_lossy(&o.stderr));
    let (pixels, w, h) = png(&out);
    assert_eq!((w, h), (80, 60));
    assert_eq!(
        pixels,
        library("assets/scenes/sphere-phong.toml", Shading::Gouraud, Some((80, 60)))
    );
    // It says what it drew, what it enabled and skipped, and where the file is.
    assert!(text.contains("CPU rasterizer, Gouraud, 80 × 60"), "{text}");
    assert!(text.contains("enabled: ") && text.contains("specular"), "{text}");
    assert!(text.contains("skipped: ") && text.contains("textures"), "{text}");
    assert!(text.contains(&format!("wrote: {}", out.display())), "{text}");
}

#[test]
fn the_ray_tracer_draws_through_the_same_command() {
    let dir = scratch("trace");
    let out = dir.join("gm.png");
    let o = cg_in(
        &root(),
        &[
            "render",
            "assets/scenes/glass-mirror.toml",
            "--renderer",
            "trace",
            "--width",
            "48",
            "--max-depth",
            "2",
            "--fresnel",
            "schlick",
            "--no-shadows",
            "-o",
            out.to_str().unwrap(),
            "--lang",
            "en",
        ],
    );
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{text}\n{}", String::from_utf8_lossy(&o.stderr));
    let scene = cg_scene::load(&root().join("assets/scenes/glass-mirror.toml")).unwrap();
    let options = cg_trace::Options {
        size: Some((48, 48)),
        max_depth: 2,
        fresnel: cg_trace::Fresnel::Schlick,
        shadows: false,
        ..cg_trace::Options::default()
    };
    let expected = cg_trace::render(&scene, &options).unwrap();
    let (pixels, w, h) = png(&out);
    assert_eq!((w, h), (48, 48));
    assert_eq!(pixels, expected.image.to_rgba8());
    assert!(text.contains("Whitted ray tracer") && text.contains("reflection rays"), "{text}");
    assert!(!text.contains("shadow rays"), "--no-shadows casts none: {text}");
    assert!(text.contains("deepest ray 2"), "--max-depth 2: {text}");
    // Shading modes the tracer draws its own way are named; Phong is its own.
    for (shading, note) in [
        ("gouraud", Some("no Gouraud shading")),
        ("flat", Some("flat shading lights each triangle once")),
        ("phong", None),
    ] {
        let args = ["render", "assets/scenes/glass-mirror.toml", "--renderer", "trace"];
        let rest =
            ["--width", "16", "--shading", shading, "-o", out.to_str().unwrap(), "--lang", "en"];
        let o = cg_in(&root(), &[&args[..], &rest[..]].concat());
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(o.status.success(), "{shading}: {err}");
        match note {
            Some(note) => assert!(err.contains(note), "{shading}: {err}"),
            None => assert!(!err.contains("note:"), "{shading}: {err}"),
        }
    }
}

#[test]
fn a_width_alone_keeps_the_scenes_aspect() {
    let dir = scratch("aspect");
    let out = dir.join("a.png");
    let o = cg_in(&root(), &["render", "--width", "64", "-o", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The course scene is 640 × 640, so 64 wide is 64 high.
    let (_, w, h) = png(&out);
    assert_eq!((w, h), (64, 64));
    // A scene 1 wide and 4096 high: 8 wide keeps its aspect at 32 768 high, past the largest
    // side. Said, with exit 2 (the height was clamped to 16 384, the picture squeezed).
    let scene = dir.join("tall.toml");
    std::fs::write(&scene, "format = 1\n[window]\nwidth = 1\nheight = 4096\n").unwrap();
    let o = cg_in(&dir, &["render", scene.to_str().unwrap(), "--width", "8", "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("makes the height 32768, outside 1 to 16384"), "{err}");
}

#[test]
fn the_main_job_draws_the_course_sample_in_every_shading_mode() {
    let dir = scratch("main-job");
    let o = cg_in(&dir, &["--lang", "en"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{text}\n{}", String::from_utf8_lossy(&o.stderr));
    let mut images = Vec::new();
    for (name, shading) in
        [("flat", Shading::Flat), ("gouraud", Shading::Gouraud), ("phong", Shading::Phong)]
    {
        let file = dir.join(format!("out/course-sample-{name}.png"));
        let (pixels, w, h) = png(&file);
        assert_eq!((w, h), (640, 640), "{name}");
        assert_eq!(pixels, library("assets/scenes/course-sample.toml", shading, None), "{name}");
        assert!(text.contains(&format!("out/course-sample-{name}.png")), "says where: {text}");
        images.push(pixels);
    }
    assert_ne!(images[0], images[1], "flat and Gouraud differ");
    // Lecture 11 in one picture: the shiny sphere in the three modes, side by side, each
    // exactly the rasterizer's picture at 320 × 320, with a label strip under them.
    let (strip, w, h) = png(&dir.join("out/lecture11-shading.png"));
    assert!(text.contains("out/lecture11-shading.png"), "says where: {text}");
    assert_eq!((w, h), (960, 320 + 24));
    let mut panels = Vec::new();
    for (k, shading) in [Shading::Flat, Shading::Gouraud, Shading::Phong].into_iter().enumerate() {
        let panel: Vec<[u8; 4]> = (0..320)
            .flat_map(|y| (0..320).map(move |x| y * 960 + k * 320 + x))
            .map(|i| strip[i])
            .collect();
        let expected = library("assets/scenes/sphere-phong.toml", shading, Some((320, 320)));
        assert!(panel == expected, "panel {k} is the rasterizer's {shading:?} picture");
        panels.push(panel);
    }
    // The three visibly differ: flat's facets everywhere, and Gouraud's smeared highlight
    // against Phong's round one (pixels apart by more than 8/255; measured: 1695 and 504).
    let apart = |a: &[[u8; 4]], b: &[[u8; 4]]| {
        a.iter().zip(b).filter(|(p, q)| (0..3).any(|c| p[c].abs_diff(q[c]) > 8)).count()
    };
    assert!(apart(&panels[0], &panels[1]) > 1000, "flat and Gouraud look alike");
    assert!(apart(&panels[1], &panels[2]) > 100, "Gouraud and Phong look alike");
    // Each label strip has ink (white text) under its picture.
    for k in 0..3 {
        let ink = (320..h)
            .flat_map(|y| (k * 320..(k + 1) * 320).map(move |x| (y * w + x) as usize))
            .any(|i| strip[i] == [255, 255, 255, 255]);
        assert!(ink, "label {k}");
    }
}

/// `render a1`: an assignment's ID where a scene file goes is said to be one, with the command
/// that shows it (it was "a1: cannot read the file" alone).
#[test]
fn an_assignments_id_as_the_scene_points_to_view() {
    let dir = scratch("assignment-id");
    for (lang, said) in [("en", "`a1` is an assignment"), ("ja", "`a1` は課題です")] {
        let o = cg_in(&dir, &["render", "a1", "--lang", lang]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains(said) && err.contains("`cargo run --release -- view a1`"), "{err}");
    }
    // A real file named like an ID is drawn as any scene is.
    std::fs::copy(root().join("assets/scenes/sphere-phong.toml"), dir.join("s")).unwrap();
    let o = cg_in(&dir, &["render", "s", "--width", "8", "-o", "s.png", "--lang", "en"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn mistakes_are_clear_errors() {
    let dir = scratch("errors");
    // A folder in the way of the output file.
    std::fs::create_dir_all(dir.join("taken.png")).unwrap();
    let o = cg_in(
        &root(),
        &["render", "-o", dir.join("taken.png").to_str().unwrap(), "--width", "8", "--lang", "en"],
    );
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("taken.png") && !err.contains("panicked"), "{err}");
    // In Japanese, the system's reason in Japanese too (not "Is a directory (os error 21)").
    let taken = dir.join("taken.png");
    let o =
        cg_in(&root(), &["render", "-o", taken.to_str().unwrap(), "--width", "8", "--lang", "ja"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("フォルダです") && !err.contains("os error"), "{err}");
    // Only PNG is written: a .jpg name is refused, not filled with PNG bytes.
    let jpg = dir.join("picture.jpg");
    let o =
        cg_in(&root(), &["render", "-o", jpg.to_str().unwrap(), "--width", "8", "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("picture.jpg") && err.contains("PNG files only"), "{err}");
    assert!(!jpg.exists(), "nothing is written under a .jpg name");
    // `.png` alone ends with .png but has no name: said so (it was "name the file .png").
    let bare = dir.join(".png");
    let o =
        cg_in(&root(), &["render", "-o", bare.to_str().unwrap(), "--width", "8", "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("the file name is only .png: put a name before it"), "{err}");
    // A folder named in -o must exist: a typo does not make new folders.
    let nested = dir.join("no").join("such").join("x.png");
    let o =
        cg_in(&root(), &["render", "-o", nested.to_str().unwrap(), "--width", "8", "--lang", "ja"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("このフォルダはありません") && err.contains("such"), "{err}");
    assert!(!dir.join("no").exists(), "no folder was made");
    // A file where -o's folder belongs is said to be one.
    std::fs::write(dir.join("plain"), "a file").unwrap();
    let under = dir.join("plain").join("x.png");
    let o =
        cg_in(&root(), &["render", "-o", under.to_str().unwrap(), "--width", "8", "--lang", "ja"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("フォルダではありません") && err.contains("plain"), "{err}");
    // Under /dev, a name with an extension is a file like any other: not a .jpg of PNG bytes.
    if Path::new("/dev/shm").is_dir() {
        let shm = format!("/dev/shm/cg-render-{}.jpg", std::process::id());
        let o = cg_in(&root(), &["render", "-o", &shm, "--width", "8", "--lang", "en"]);
        assert_eq!(o.status.code(), Some(2), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(!Path::new(&shm).exists());
    }
    // A failed write is an error, never "wrote:" with exit status 0.
    if Path::new("/dev/full").exists() {
        let o = cg_in(&root(), &["render", "-o", "/dev/full", "--width", "8", "--lang", "en"]);
        let (out, err) = (String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
        assert_eq!(o.status.code(), Some(2), "{out}{err}");
        assert!(!out.contains("wrote:") && err.contains("/dev/full"), "{out}{err}");
    }
    // A file that never ends is refused at the limit, not read until the memory is full.
    if Path::new("/dev/zero").exists() {
        let o = cg_in(&root(), &["render", "/dev/zero", "--lang", "en"]);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{err}");
        assert!(err.contains("/dev/zero") && err.contains("larger than 64 MiB"), "{err}");
    }
    // Unknown renderer and a zero width are refused by the argument parser (exit code 2).
    for args in [
        &["render", "--renderer", "opengl"][..],
        &["render", "--width", "0"][..],
        &["render", "--threads", "0"][..],
        &["render", "--threads", "100000"][..],
    ] {
        let o = cg_in(&root(), args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
    }
    // Japanese messages.
    let o = cg_in(&root(), &["render", "no/such.toml", "--lang", "ja"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.starts_with("エラー") && err.contains("no/such.toml"), "{err}");
    assert!(
        err.contains("ファイルまたはフォルダがありません") && !err.contains("No such"),
        "{err}"
    );
    // The argument parser's own mistakes, in Japanese too (language from --lang or CG_LANG),
    // with clap's exit code; English stays clap's text.
    let o = cg_in(&root(), &["render", "--widht", "8", "--lang", "ja"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.starts_with("エラー: '--widht' という引数はありません"), "{err}");
    assert!(err.contains("似た引数があります: '--width'"), "{err}");
    let o = cg_in(&root(), &["render", "--renderer", "opengl", "--lang=ja"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("に値 'opengl' は使えません") && err.contains("使える値:"), "{err}");
    let o = cg_in(&root(), &["render", "--width", "0", "--lang", "en"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.starts_with("error: invalid value '0' for '--width <WIDTH>'"), "{err}");
}

#[cfg(feature = "gpu")]
#[test]
fn the_gpu_renderer_draws_the_course_sample_and_says_what_its_shader_contains() {
    let dir = scratch("gpu");
    let file = dir.join("gpu.png");
    let out = cg_in(
        &root(),
        &["--lang", "en", "render", "--renderer", "gpu", "-o", file.to_str().unwrap()],
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() && stderr.contains("no GPU adapter") {
        assert!(std::env::var_os("CI").is_none(), "CI has lavapipe (scripts/setup.sh):\n{stderr}");
        eprintln!("note: no GPU adapter here; the GPU render command is not tested");
        return;
    }
    assert!(out.status.success(), "{stdout}\n{stderr}");
    assert!(stdout.contains("in the generated shader: ambient, diffuse, point lights"), "{stdout}");
    assert!(stdout.contains("adapter:"), "{stdout}");
    let gpu = image::open(&file).unwrap().to_rgb8();
    let cpu_file = dir.join("cpu.png");
    let out = cg_in(&root(), &["render", "-o", cpu_file.to_str().unwrap()]);
    assert!(out.status.success());
    let cpu = image::open(&cpu_file).unwrap().to_rgb8();
    assert_eq!(gpu.dimensions(), cpu.dimensions());
    let worst = gpu
        .pixels()
        .zip(cpu.pixels())
        .flat_map(|(a, b)| a.0.iter().zip(b.0).map(|(p, q)| p.abs_diff(q)).collect::<Vec<_>>())
        .max()
        .unwrap();
    assert!(worst <= 2, "GPU and CPU agree within 2/255 (worst {worst})");
}

/// A build without the GPU renderer (the students' copy): `--renderer gpu` says so in the user's
/// language, with the command that builds it and draws the same picture, and writes nothing.
#[cfg(not(feature = "gpu"))]
#[test]
fn without_the_gpu_feature_the_gpu_renderer_gives_the_command_that_builds_it() {
    let dir = scratch("no-gpu");
    let file = dir.join("gpu.png");
    let png = file.to_str().unwrap();
    for (lang, says) in
        [("en", "built without the GPU renderer"), ("ja", "GPU レンダラ（wgpu）なしでビルド")]
    {
        let args = ["render", "--renderer", "gpu", "-o", png, "--lang", lang];
        let out = cg_in(&root(), &args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(says), "{err}");
        let command = format!("cargo run --release --features gpu -- {}", args.join(" "));
        assert!(err.contains(&command), "{command}\n{err}");
        assert!(!file.exists(), "{err}");
    }
}

/// `-o /dev/stdout > a.png` leaves a PNG and nothing else on standard output (the words go to
/// standard error, or they would land inside the picture); and a standard error whose reader
/// has gone (`2>&1 | head`) ends the command quietly, as a closed standard output does, not in
/// a panic.
#[cfg(unix)]
#[test]
fn a_picture_on_standard_output_is_only_the_png_and_a_closed_pipe_is_no_panic() {
    let o = cg_in(&root(), &["render", "--width", "32", "-o", "/dev/stdout", "--lang", "en"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let iend = [0, 0, 0, 0, b'I', b'E', b'N', b'D', 0xAE, 0x42, 0x60, 0x82];
    assert!(
        o.stdout.starts_with(b"\x89PNG\r\n\x1a\n") && o.stdout.ends_with(&iend),
        "standard output is not one PNG: {:?}",
        String::from_utf8_lossy(&o.stdout[o.stdout.len().saturating_sub(200)..])
    );
    assert_eq!(image::load_from_memory(&o.stdout).unwrap().width(), 32);
    let words = String::from_utf8_lossy(&o.stderr);
    assert!(words.contains("rendered") && words.contains("wrote: /dev/stdout"), "{words}");

    // The ray tracer's note on flat shading goes to standard error, here a pipe nobody reads.
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_cg"))
        .args(["render", "--renderer", "trace", "--shading", "flat", "--width", "8"])
        .args(["-o", "/dev/null", "--lang", "ja"])
        .current_dir(root())
        .stdout(std::process::Stdio::null())
        .stderr(writer)
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(141), "{status}");
}
