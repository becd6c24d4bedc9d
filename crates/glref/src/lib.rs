//! # cg-glref — the kit's OpenGL reference
//!
//! Draws a kit [`Scene`] the way the course's OpenGL program would: with OpenGL 1.x
//! fixed-function calls only (glLightfv, glMaterialfv, glShadeModel, glBegin(GL_TRIANGLES) …), in
//! Mesa's off-screen renderer OSMesa, with no display and no GPU. The kit's CPU rasterizer is
//! tested against these images, so "looks like the course's OpenGL sample" is a measurement.
//!
//! How: [`script()`] turns the scene into a plain-text command script, one GL call per line
//! (documented at the top of `tools/glref/glref.c`); [`render`] builds that small C program on
//! first use (into `target/glref/`), runs it on the script and reads back its image.
//!
//! | function | what it does |
//! |---|---|
//! | [`available`] | whether a C compiler and OSMesa are usable here |
//! | [`require`] | the test policy: `true` when available; skip with a note on a student's machine; panic in CI |
//! | [`render`] | the scene drawn by OpenGL, as an [`Image`] |
//! | [`script()`] | the command script for a scene (to read, or to run by hand) |
//!
//! What OpenGL cannot draw is an error, not an approximation: the lecture's light model
//! ([`GlRefError::LectureLightModel`]), Phong shading ([`GlRefError::PhongShading`]) and more
//! than 8 point lights ([`GlRefError::TooManyLights`]). The global terms `kr·Ir` and `kt·It` are
//! the ray tracer's and are not drawn.
//!
//! ## What OSMesa (Mesa 22.3, llvmpipe) does that a rasterizer must match
//!
//! Measured with this program (see `tools/glref/README.md`):
//!
//! - pixel centres at half-integers; an edge through a pixel centre covers it when it is a
//!   *left* or a *bottom* edge as the image is seen (row 0 at the top) — the top-left rule
//!   applied in GL's y-up window coordinates;
//! - lit vertex colours are clamped to `[0, 1]` *before* they are interpolated;
//! - colours and texture coordinates are interpolated perspective-correctly;
//! - a colour is written as `round_half_even(c · 255)` in f32 (the kit's
//!   [`to_unorm8`](cg_core::image::to_unorm8) rounds halves up: they differ only on exact ties);
//! - no dithering (the program disables GL_DITHER); depth test GL_LESS, so of two equal depths
//!   the first drawn stays;
//! - GL_FLAT colours a triangle with its last vertex's lit colour (lit with that vertex's own
//!   normal, position and glColor: its provoking vertex under GL_TRIANGLES).
//!
//! ```
//! use cg_core::lang::Lang;
//!
//! let path = std::path::Path::new("../../assets/scenes/course-sample.toml");
//! let scene = cg_scene::load(path).map_err(|e| e.to_string())?;
//! match cg_glref::render(&scene) {
//!     Ok(image) => assert_eq!((image.width, image.height), (640, 640)),
//!     // No C compiler or OSMesa here: the message says to run `bash scripts/setup.sh`.
//!     Err(e) => eprintln!("{}", e.message(Lang::from_env())),
//! }
//! # Ok::<(), String>(())
//! ```

mod error;
mod program;
mod script;

use std::io::Write as _;
use std::sync::OnceLock;

use cg_core::image::Image;
use cg_core::lang::{Lang, t};
use cg_core::scene::Scene;

pub use error::{GlRefError, install_hint};
pub use program::{SOURCE, cache_dir};
pub use script::{MAX_LIGHTS, MAX_SIDE, script};

/// Whether the OpenGL reference can run here: a C compiler (`$CC`, or `cc`) builds
/// `tools/glref/glref.c` against OSMesa, and the program draws a 1×1 image. Checked once per
/// process.
///
/// # Errors
/// [`GlRefError::NotAvailable`] saying what is missing and what to run (`bash scripts/setup.sh`).
///
/// See also [`require`] for tests.
pub fn available() -> Result<(), GlRefError> {
    static CHECKED: OnceLock<Result<(), String>> = OnceLock::new();
    CHECKED
        .get_or_init(|| {
            let probe = "size 1 1\nclear 0 0 0\nfinish\n";
            match program::run(probe, 1, 1) {
                Ok(_) => Ok(()),
                Err(GlRefError::NotAvailable { detail }) => Err(detail),
                Err(e) => Err(format!("the program was built but cannot draw: {e}")),
            }
        })
        .clone()
        .map_err(|detail| GlRefError::NotAvailable { detail })
}

/// The test policy for the OpenGL reference: `true` when it is [`available`]. When it is not:
/// with the environment variable `CI` set (to anything), panics with the reason — CI must never
/// pass silently without the reference; otherwise returns `false`, so the calling test returns
/// early on a student's machine, and prints `skipped: OpenGL reference not available: …` (why,
/// and what to run) on standard error, once per test process and past the test harness's output
/// capture, so it shows in a plain `cargo test`:
///
/// ```
/// # fn draw_and_compare() {}
/// if !cg_glref::require() {
///     return;
/// }
/// draw_and_compare();
/// ```
///
/// # Panics
/// When the reference is not available and `CI` is set.
#[must_use]
pub fn require() -> bool {
    let Err(e) = available() else {
        return true;
    };
    let lang = Lang::from_env();
    let reason = match &e {
        GlRefError::NotAvailable { detail } => format!("{detail}. {}", install_hint().get(lang)),
        other => other.message(lang),
    };
    if std::env::var_os("CI").is_some() {
        panic!("CI is set, so the OpenGL reference is required, but it is not available: {reason}");
    }
    // Once per process, and past the test harness's capture of eprintln!, so the student sees it.
    static NOTED: std::sync::Once = std::sync::Once::new();
    NOTED.call_once(|| {
        let early = t(
            "（これを必要とするテストは何も確かめずに終わります）",
            " (the tests that need it return early)",
        );
        let early = early.get(lang);
        let _ =
            writeln!(std::io::stderr(), "skipped: OpenGL reference not available: {reason}{early}");
    });
    false
}

/// `scene` drawn by OpenGL 1.x fixed-function calls in OSMesa: a `width × height` image, row 0 at
/// the top, each channel the framebuffer's byte `/ 255` (exact: [`Image::to_rgba8`] gives the
/// bytes back). See [`script()`] for how each part of the scene becomes GL calls.
///
/// The C program is built on first use (a few hundred milliseconds) and cached in
/// [`cache_dir`]; each call then starts it once (a 640×640 scene takes tens of milliseconds).
///
/// # Errors
/// Everything [`script()`] rejects (checked before anything runs, so these errors need no C
/// compiler); [`GlRefError::NotAvailable`] without a C compiler or OSMesa;
/// [`GlRefError::Program`] for a GL error or an OSMesa failure the program reports.
pub fn render(scene: &Scene) -> Result<Image, GlRefError> {
    let text = script(scene)?;
    let image = program::run(&text, scene.width, scene.height)?;
    debug_assert!(image.pixels.iter().all(|c| c.is_finite()));
    Ok(image)
}
