//! The kit's fuzz test (issue 17): seeded edits of every shipped scene, model and texture.
//!
//! For each edited input:
//! - nothing panics, and each input is done within a bound of time (a hang detector, not a
//!   speed measurement: [`PER_INPUT`]) and the whole run within a bound of memory ([`PEAK_RSS`]);
//! - an input that is rejected gets an error that names the file, and the line of the scene or
//!   model file wherever the mistake has one (only whole-file problems, such as an OBJ file
//!   without faces or a corrupt PNG, may have none);
//! - a scene that loads is drawn by the rasterizer and by the ray tracer at 16 × 16: neither
//!   fails, and every pixel is finite. "A scene that loads never fails later in a renderer."
//!
//! Seeded (`cg_testkit::Inputs`), so a failure repeats; the failing input is printed whole.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use cg_scene::{ErrorKind, SceneError};
use cg_testkit::Inputs;

/// The longest one input may take, parsing and both renderers together (debug build).
const PER_INPUT: Duration = Duration::from_secs(20);
/// The most memory the whole test may hold (resident set, high-water mark; Linux only).
const PEAK_RSS: u64 = 2 << 30;

fn assets() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets")
}

/// How many edits per input file.
fn cases() -> usize {
    if cfg!(debug_assertions) { 150 } else { 1_500 }
}

/// `text` with `edits` random edits: a byte replaced by a random byte or by one that means
/// something in the formats (digits, signs, exponents, brackets, `nan`, `inf`), deleted, or
/// duplicated; or a number replaced by an extreme one (huge, tiny, zero, negative).
fn mutate(rng: &mut Inputs, text: &[u8], edits: usize) -> Vec<u8> {
    const SIGNIFICANT: &[u8] = b"[]{}=\",.#\n-+0123456789eE_ abcinfx/";
    let mut bytes = text.to_vec();
    for _ in 0..edits {
        if bytes.is_empty() {
            break;
        }
        let at = rng.int(0, bytes.len() as i64) as usize;
        match rng.int(0, 6) {
            0 => bytes[at] = rng.int(0, 256) as u8,
            1 => bytes[at] = SIGNIFICANT[rng.int(0, SIGNIFICANT.len() as i64) as usize],
            2 => {
                bytes.remove(at);
            }
            3 => bytes.insert(at, bytes[at]),
            4 => {
                // The number around `at`, if any, replaced by an extreme one.
                const EXTREME: &[&str] = &[
                    "3.4e38", "-3.4e38", "1e30", "1e20", "8e6", "1e6", "16384", "1e-10", "1e-20",
                    "1e-45", "0.0", "-0.0", "0", "-1", "1e-15", "179.99", "180.0", "4096",
                ];
                let is_num = |b: u8| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'-');
                if bytes[at].is_ascii_digit() {
                    let start =
                        (0..at).rev().take_while(|&i| is_num(bytes[i])).last().unwrap_or(at);
                    let end = (at..bytes.len()).find(|&i| !is_num(bytes[i])).unwrap_or(bytes.len());
                    let pick = EXTREME[rng.int(0, EXTREME.len() as i64) as usize];
                    bytes.splice(start..end, pick.bytes());
                }
            }
            _ => bytes.insert(at, b'9'),
        }
    }
    bytes
}

/// Whole-file problems: they have no line to name.
fn whole_file(kind: &ErrorKind) -> bool {
    matches!(
        kind,
        ErrorKind::Read { .. }
            | ErrorKind::FileTooLarge { .. }
            | ErrorKind::Obj(_)
            | ErrorKind::ObjNoFaces
            | ErrorKind::ObjPartial { .. }
            | ErrorKind::ObjBadNormal { .. }
            | ErrorKind::ObjBadUv { .. }
            | ErrorKind::Mesh(_)
            | ErrorKind::NotPng
            | ErrorKind::PngTooLarge { .. }
            | ErrorKind::Png { .. }
            | ErrorKind::Texture(_)
    )
}

/// Checks a rejection: it names the file it is about, and a line unless it is a whole-file
/// problem of a model or a texture.
fn check_rejection(e: &SceneError, input: &str) {
    let en = e.to_string();
    let ja = e.describe(cg_core::lang::Lang::Ja);
    assert!(!e.file.as_os_str().is_empty(), "no file named: {en}\n--- input:\n{input}");
    assert!(
        e.position.is_some() || whole_file(&e.kind),
        "no line named: {en}\n--- input:\n{input}"
    );
    assert!(en.len() < 2_000 && ja.len() < 2_000, "a message stays short: {en}");
    assert!(!en.contains("NaN") && !en.contains("panicked"), "{en}");
}

/// Draws an accepted scene with both CPU renderers, small: no error, every pixel finite.
fn draw(scene: &cg_core::scene::Scene, input: &str) {
    let size = Some((16, 16));
    let raster = cg_raster::render(scene, &cg_raster::Options { size, ..Default::default() });
    let image = match raster {
        Ok(out) => out.image,
        Err(e) => panic!("the scene loaded, the rasterizer failed: {e}\n--- input:\n{input}"),
    };
    assert!(image.pixels.iter().all(|c| c.is_finite()), "raster NaN\n--- input:\n{input}");
    let trace = cg_trace::render(scene, &cg_trace::Options { size, ..Default::default() });
    let image = match trace {
        Ok(out) => out.image,
        Err(e) => panic!("the scene loaded, the ray tracer failed: {e}\n--- input:\n{input}"),
    };
    assert!(image.pixels.iter().all(|c| c.is_finite()), "trace NaN\n--- input:\n{input}");
}

/// Runs `one` on `input`, within [`PER_INPUT`].
fn timed(input: &str, one: impl FnOnce()) {
    let start = Instant::now();
    one();
    let took = start.elapsed();
    assert!(took < PER_INPUT, "one input took {took:?} (bound {PER_INPUT:?})\n--- input:\n{input}");
}

/// The resident set's high-water mark in bytes (`VmHWM`), where the system says.
fn peak_rss() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

#[test]
fn edited_scenes_load_and_draw_or_are_refused_with_their_line() {
    let dir = assets().join("scenes");
    let mut names: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    names.sort();
    assert!(names.len() >= 6, "the shipped scenes: {names:?}");
    let mut rng = Inputs::seeded(0xF022);
    let (mut ok, mut refused) = (0, 0);
    for path in &names {
        let text = std::fs::read(path).unwrap();
        // Every shipped scene loads and draws as it is.
        let original = String::from_utf8(text.clone()).unwrap();
        draw(&cg_scene::parse(&original, path).unwrap(), &original);
        for i in 0..cases() {
            let edited = String::from_utf8_lossy(&mutate(&mut rng, &text, 1 + i % 3)).into_owned();
            timed(&edited, || match cg_scene::parse(&edited, path) {
                Ok(scene) => {
                    ok += 1;
                    draw(&scene, &edited);
                }
                Err(e) => {
                    refused += 1;
                    check_rejection(&e, &edited);
                }
            });
        }
    }
    eprintln!("{ok} edited scenes loaded and drawn, {refused} refused");
    assert!(ok > 0 && refused > 0, "{ok} edited scenes loaded, {refused} refused");
    if let Some(peak) = peak_rss() {
        assert!(peak < PEAK_RSS, "peak resident memory {peak} bytes (bound {PEAK_RSS})");
    }
}

#[test]
fn edited_models_and_textures_load_or_are_refused_clearly() {
    let mut rng = Inputs::seeded(0x0B17);
    let (mut ok, mut refused) = (0, 0);
    let model = assets().join("models/pyramid.obj");
    let text = std::fs::read(&model).unwrap();
    for i in 0..cases() * 4 {
        let edited = String::from_utf8_lossy(&mutate(&mut rng, &text, 1 + i % 3)).into_owned();
        timed(&edited, || match cg_scene::parse_obj(&edited, &model) {
            Ok(mesh) => {
                ok += 1;
                assert!(mesh.positions.iter().all(|p| p.is_finite()), "{edited}");
                mesh.check_indices().unwrap();
            }
            Err(e) => {
                refused += 1;
                check_rejection(&e, &edited);
            }
        });
    }
    for name in ["orientation.png", "a4-prepared.png"] {
        let path = assets().join("textures").join(name);
        let png = std::fs::read(&path).unwrap();
        for i in 0..cases() {
            let edited = mutate(&mut rng, &png, 1 + i % 3);
            timed(name, || match cg_scene::decode_png(&edited, &path) {
                Ok(t) => {
                    ok += 1;
                    assert_eq!(t.texels.len(), (t.width * t.height) as usize);
                }
                Err(e) => {
                    refused += 1;
                    check_rejection(&e, name);
                }
            });
        }
    }
    assert!(ok > 0 && refused > 0, "{ok} edited files loaded, {refused} refused");
}
