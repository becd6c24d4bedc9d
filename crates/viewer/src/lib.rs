//! # cg-viewer — the kit's interactive viewer
//!
//! A window with the callbacks of the course's GLUT sample program (display, reshape, mouse,
//! motion, idle, keyboard: see [`App`] for the table that maps them one to one), drawing through
//! a renderer [`Backend`]: the CPU rasterizer ([`CpuBackend`], `cg_raster::render` into a
//! softbuffer surface) or the GPU (`GpuBackend`, which presents to a wgpu surface on the window
//! itself); `r` switches between them. The GPU is the `gpu` feature (default in the kit's own
//! repository, left out of the students' copy to shorten its first build): without it the window
//! draws with the CPU, and asking for the GPU says how to build it ([`backend::gpu_left_out`]).
//!
//! The default app ([`CourseApp`]) is the course's sample scene with the sample's mouse mapping
//! (`cg_core::camera::OrbitCamera`): right-drag changes the pitch (dy) and the yaw (dx),
//! left-drag the distance; keys: see [`course::controls`]. The title shows the mode, the renderer and
//! the frame time.
//!
//! Without a display (no `DISPLAY`, or the window cannot be opened) [`run`] renders the view to a
//! PNG file instead and says so; it never panics for want of a window.
//!
//! ```no_run
//! let options = cg_viewer::ViewerOptions { frames: Some(1), ..Default::default() };
//! cg_viewer::run(&options).unwrap();
//! ```
//!
//! A program of one's own is an [`App`]: the sample program's callbacks as methods. This one
//! draws the course's scene and turns the camera in `idle()`:
//!
//! ```
//! use cg_core::image::Image;
//! use cg_viewer::{App, Backend, Control, CpuBackend, FrameRequest, ViewerError, ViewerOptions};
//!
//! struct Turntable { scene: cg_core::scene::Scene, yaw: f32, size: (u32, u32) }
//!
//! impl App for Turntable {
//!     fn title(&self) -> String { format!("turntable, yaw {}", self.yaw) }
//!     fn display(&mut self, renderer: &mut dyn Backend) -> Result<Image, ViewerError> {
//!         let mut scene = self.scene.clone();
//!         if let cg_core::scene::Camera::Orbit(c) = &mut scene.camera { c.yaw_deg = self.yaw; }
//!         renderer.render(&scene, &FrameRequest { size: self.size, shading: None })
//!     }
//!     fn reshape(&mut self, width: u32, height: u32) { self.size = (width, height); }
//!     fn idle(&mut self, dt: f32, control: &mut Control) {
//!         self.yaw = (self.yaw + 90.0 * dt) % 360.0;
//!         control.post_redisplay(); // glutPostRedisplay()
//!     }
//! }
//!
//! let mut app = Turntable { scene: cg_harness::course::scene(), yaw: 0.0, size: (0, 0) };
//! let dir = std::env::temp_dir().join("cg-viewer-doc");
//! let options = ViewerOptions {
//!     size: Some((64, 48)),
//!     frames: Some(2),
//!     screenshot: Some(dir.join("turntable.png")),
//!     ..ViewerOptions::default()
//! };
//! cg_viewer::run_headless(&mut app, vec![Box::new(CpuBackend::default())], &options)?;
//! assert!((app.yaw - 1.5).abs() < 1e-4); // one idle step of 1/60 s between the two frames
//! # Ok::<(), ViewerError>(())
//! ```

pub mod app;
pub mod backend;
pub mod course;
pub mod side;
mod watch;
mod window;

use std::path::{Path, PathBuf};

use cg_core::image::Image;
use cg_core::lang::{Lang, Text, t};
use cg_core::scene::Shading;

pub use app::{App, Control};
#[cfg(feature = "gpu")]
pub use backend::GpuBackend;
pub use backend::{
    Backend, CpuBackend, FrameRequest, GPU_BUILT, RendererChoice, backends_for, default_backends,
    gpu_left_out, to_0rgb, write_0rgb,
};
pub use course::{CourseApp, LightChoice};
pub use side::{SideBySide, Source};

/// Why the viewer stopped with an error.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum ViewerError {
    /// The scene file could not be loaded (the message names the file, line and key).
    #[error("{0}")]
    Scene(String),
    /// A frame could not be rendered.
    #[error("cannot render the frame: {0}")]
    Render(String),
    /// A PNG file could not be written.
    #[error("cannot save {path}: {message}")]
    Save {
        /// The file.
        path: PathBuf,
        /// Why.
        message: String,
    },
    /// The window failed after it had been shown.
    #[error("the window failed: {0}")]
    Window(String),
    /// Something this build left out was asked for (the GPU renderer without the `gpu`
    /// feature): the message says so and gives the command that builds it.
    #[error("{}", .0.en)]
    LeftOut(Text),
}

impl ViewerError {
    /// The message in `lang` (the `Display` text is the English one).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let ja = match self {
            ViewerError::Scene(_) => self.to_string(),
            ViewerError::Render(m) => format!("フレームを描画できません: {m}"),
            ViewerError::Save { path, message } => {
                format!("{} を保存できません: {message}", path.display())
            }
            ViewerError::Window(m) => format!("ウィンドウでエラーが起きました: {m}"),
            ViewerError::LeftOut(text) => text.ja.clone(),
        };
        Text::new(ja, self.to_string())
    }
}

/// How [`run`] runs. `ViewerOptions::default()`: the course's sample scene in a window until it
/// is closed, PNGs to `out/` when there is no display.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ViewerOptions {
    /// The scene file; `None`: the course's sample scene.
    pub scene: Option<PathBuf>,
    /// The shading mode at start instead of the scene's.
    pub shading: Option<Shading>,
    /// The window (or image) size instead of the scene's.
    pub size: Option<(u32, u32)>,
    /// Stop after this many frames have been shown (rendered, without a display).
    pub frames: Option<u64>,
    /// Save the last frame here as a PNG (and the `s` key saves here too).
    pub screenshot: Option<PathBuf>,
    /// Where PNGs go without `screenshot` (the `s` key's numbered files, the headless view);
    /// `None`: `out`.
    pub out_dir: Option<PathBuf>,
    /// Start with the animation paused.
    pub paused: bool,
    /// Never open a window: render PNGs as without a display.
    pub headless: bool,
    /// Threads for the CPU rasterizer; `None`: all cores.
    pub threads: Option<usize>,
    /// Which renderer draws first ([`backends_for`]); without a display only that one (the CPU
    /// for [`RendererChoice::Auto`]).
    pub renderer: RendererChoice,
    /// The language of messages.
    pub lang: Lang,
    /// A window ends with [`WindowEnd::Changed`] when this file changes and then stays the same
    /// (`cg view` watches its own program, rebuilt by `cg watch` when the student saves, and
    /// starts the new one with the same view).
    pub reload_on_change: Option<PathBuf>,
}

/// How [`run_window`] ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum WindowEnd {
    /// The window was closed, or the app quit, or the frame limit was reached.
    Closed,
    /// No window could be opened (why); nothing was drawn.
    NoWindow(String),
    /// [`ViewerOptions::reload_on_change`] changed: the window closed so that the caller can
    /// start again.
    Changed,
}

/// Whether a window can probably be opened here: on Linux and the BSDs, a Wayland compositor
/// (`WAYLAND_DISPLAY`) or an X server (`DISPLAY`) is named (winit asks Wayland first, then X11);
/// elsewhere (Windows, macOS), true. [`run`] falls back to PNGs, saying why, when the window
/// still cannot be opened.
#[must_use]
pub fn display_available() -> bool {
    if cfg!(any(
        target_os = "linux",
        target_os = "freebsd",
        target_os = "openbsd",
        target_os = "netbsd",
        target_os = "dragonfly"
    )) {
        ["WAYLAND_DISPLAY", "DISPLAY"]
            .iter()
            .any(|k| std::env::var_os(k).is_some_and(|v| !v.is_empty()))
    } else {
        true
    }
}

/// Runs the default app ([`CourseApp`] on `options.scene` or the course's sample scene) with the
/// renderers `options.renderer` picks ([`backends_for`]): in a window when there is a display,
/// else to a PNG file (with the CPU, or the GPU when it was asked for).
///
/// # Errors
/// The scene cannot be loaded, the GPU was asked for and there is none, a frame cannot be
/// rendered, a PNG cannot be written, or the window fails after it was shown.
pub fn run(options: &ViewerOptions) -> Result<(), ViewerError> {
    let scene = match &options.scene {
        None => cg_harness::course::scene(),
        Some(path) => {
            cg_scene::load(path).map_err(|e| ViewerError::Scene(e.describe(options.lang)))?
        }
    };
    let mut app = CourseApp::new(scene);
    if let Some(s) = options.shading {
        app.shading = s;
    }
    app.paused = options.paused;
    print_keys(options.lang);
    let backends =
        if (options.headless || !display_available()) && options.renderer != RendererChoice::Gpu {
            vec![Box::new(CpuBackend { threads: options.threads, lang: options.lang })
                as Box<dyn Backend>]
        } else {
            backends_for(options.renderer, options.threads, options.lang)?
        };
    run_app(&mut app, backends, options)
}

/// Prints the keys and drags the viewer understands.
pub fn print_keys(lang: Lang) {
    print!("{}", keys_text(lang, GPU_BUILT));
}

/// [`print_keys`]' lines: the controls of [`course::controls`] in `lang`, their names padded
/// to one column (a full-width character takes two).
#[must_use]
pub fn keys_text(lang: Lang, gpu: bool) -> String {
    let mut out = format!("{}\n", t("操作:", "controls:").get(lang));
    for (key, what) in course::controls(gpu) {
        let key = key.get(lang);
        let width: usize =
            key.chars()
                .map(|c| {
                    if matches!(c, '\u{3000}'..='\u{9fff}' | '\u{ff00}'..='\u{ffef}') {
                        2
                    } else {
                        1
                    }
                })
                .sum();
        let pad = " ".repeat(12usize.saturating_sub(width));
        out.push_str(&format!("  {key}{pad} {}\n", what.get(lang)));
    }
    out
}

/// Runs `app` (GLUT's `glutMainLoop`) with `backends` (the first draws; `r` switches): in a
/// window when one can be opened, else headless ([`run_headless`]) with a note saying so.
///
/// # Errors
/// As [`run`]; also when `backends` is empty.
pub fn run_app<A: App>(
    app: &mut A,
    backends: Vec<Box<dyn Backend>>,
    options: &ViewerOptions,
) -> Result<(), ViewerError> {
    let mut shared = Shared::new(backends, options)?;
    if !options.headless {
        match window_or_reason(app, &mut shared, options)? {
            WindowEnd::Closed | WindowEnd::Changed => return Ok(()),
            WindowEnd::NoWindow(reason) => eprintln!("{}", no_window(&reason, options.lang)),
        }
    }
    headless(app, &mut shared)
}

/// Runs `app` in a window only: [`WindowEnd::NoWindow`] when no window could be opened (nothing
/// is drawn then: the caller decides what to do instead, as `cg view` draws its own PNG files),
/// [`WindowEnd::Changed`] when the watched file changed.
///
/// # Errors
/// As [`run_app`].
pub fn run_window<A: App>(
    app: &mut A,
    backends: Vec<Box<dyn Backend>>,
    options: &ViewerOptions,
) -> Result<WindowEnd, ViewerError> {
    let mut shared = Shared::new(backends, options)?;
    window_or_reason(app, &mut shared, options)
}

/// The window, or why there is none.
fn window_or_reason<A: App>(
    app: &mut A,
    shared: &mut Shared,
    options: &ViewerOptions,
) -> Result<WindowEnd, ViewerError> {
    if !display_available() {
        return Ok(WindowEnd::NoWindow(
            t(
                "WAYLAND_DISPLAY も DISPLAY も設定されていません",
                "neither WAYLAND_DISPLAY nor DISPLAY is set",
            )
            .get(options.lang)
            .to_owned(),
        ));
    }
    match window::run(app, shared) {
        Outcome::Done => Ok(WindowEnd::Closed),
        Outcome::Changed => Ok(WindowEnd::Changed),
        Outcome::Failed(e) => Err(e),
        Outcome::NoDisplay(reason) => Ok(WindowEnd::NoWindow(reason)),
    }
}

/// "No window can be opened (why); rendering to PNG files instead", in `lang`.
#[must_use]
pub fn no_window(reason: &str, lang: Lang) -> String {
    format!(
        "{} ({reason}){}",
        t("ウィンドウを開けません", "no window can be opened").get(lang),
        t("。代わりに PNG ファイルに描画します", "; rendering to PNG files instead").get(lang)
    )
}

/// Renders `app` without a window: `init`, `reshape` to the window size, then `frames` frames
/// (default 1) with `idle(1/60 s)` between them; saves the last frame to the screenshot path or
/// `OUT/view.png`, and says where.
///
/// # Errors
/// As [`run_app`].
pub fn run_headless<A: App>(
    app: &mut A,
    backends: Vec<Box<dyn Backend>>,
    options: &ViewerOptions,
) -> Result<(), ViewerError> {
    let mut shared = Shared::new(backends, options)?;
    headless(app, &mut shared)
}

fn headless<A: App>(app: &mut A, shared: &mut Shared) -> Result<(), ViewerError> {
    let (w, h) = shared.options.size.unwrap_or_else(|| app.window_size());
    app.init();
    app.reshape(w.max(1), h.max(1));
    let frames = shared.options.frames.unwrap_or(1).max(1);
    let mut image = app.display(shared.backend_mut())?;
    for _ in 1..frames {
        let mut control = Control::new();
        app.idle(1.0 / 60.0, &mut control);
        image = app.display(shared.backend_mut())?;
    }
    let path = match &shared.options.screenshot {
        Some(p) => p.clone(),
        None => shared.out_dir().join("view.png"),
    };
    shared.save(&path, &image, &app.status())
}

/// How the window run ended.
pub(crate) enum Outcome {
    /// Closed or quit normally.
    Done,
    /// No window could be opened (the reason); nothing was shown.
    NoDisplay(String),
    /// An error after the window was shown.
    Failed(ViewerError),
    /// The watched file changed ([`ViewerOptions::reload_on_change`]).
    Changed,
}

/// What the shell and the headless path share: options, backends, screenshots.
pub(crate) struct Shared {
    pub(crate) options: ViewerOptions,
    backends: Vec<Box<dyn Backend>>,
    current: usize,
    screenshots: u32,
}

impl Shared {
    fn new(
        backends: Vec<Box<dyn Backend>>,
        options: &ViewerOptions,
    ) -> Result<Shared, ViewerError> {
        if backends.is_empty() {
            return Err(ViewerError::Render("no renderer was given to the viewer".to_owned()));
        }
        Ok(Shared { options: options.clone(), backends, current: 0, screenshots: 0 })
    }

    pub(crate) fn backend(&self) -> &dyn Backend {
        self.backends[self.current].as_ref()
    }

    pub(crate) fn backend_mut(&mut self) -> &mut dyn Backend {
        self.backends[self.current].as_mut()
    }

    /// The index of the backend that draws now.
    pub(crate) fn current(&self) -> usize {
        self.current
    }

    /// The backend with index `k`.
    pub(crate) fn backend_at_mut(&mut self, k: usize) -> Option<&mut dyn Backend> {
        Some(self.backends.get_mut(k)?.as_mut())
    }

    /// Every backend but `except` lets go of the window ([`Backend::release_window`]).
    pub(crate) fn release_windows(&mut self, except: Option<usize>) {
        for (k, b) in self.backends.iter_mut().enumerate() {
            if Some(k) != except {
                b.release_window();
            }
        }
    }

    /// The `r` key: the next backend, or a note that there is only one.
    pub(crate) fn next_backend(&mut self) {
        if self.backends.len() < 2 {
            let lang = self.options.lang;
            if backend::GPU_BUILT {
                println!(
                    "{} {}",
                    t(
                        "使えるレンダラは 1 つだけです（GPU のアダプタがありません）:",
                        "only one renderer is available (no GPU adapter was found):"
                    )
                    .get(lang),
                    self.backend().name()
                );
            } else {
                let why = backend::gpu_left_out(&cg_harness::args::rerun_with_features("gpu"));
                let name = self.backend().name();
                println!(
                    "{}",
                    Text::new(
                        format!("使えるレンダラは 1 つだけです: {name}。{}", why.ja),
                        format!("only one renderer is available, the {name}: {}", why.en),
                    )
                    .get(lang)
                );
            }
            return;
        }
        self.current = (self.current + 1) % self.backends.len();
        println!(
            "{} {}",
            t("レンダラ:", "renderer:").get(self.options.lang),
            self.backend().name()
        );
    }

    pub(crate) fn out_dir(&self) -> PathBuf {
        self.options.out_dir.clone().unwrap_or_else(|| PathBuf::from("out"))
    }

    /// Where the `s` key saves: the `--screenshot` path, else `OUT/screenshot-NNN.png`.
    pub(crate) fn screenshot_path(&mut self) -> PathBuf {
        if let Some(p) = &self.options.screenshot {
            return p.clone();
        }
        self.screenshots += 1;
        self.out_dir().join(format!("screenshot-{:03}.png", self.screenshots))
    }

    /// Writes `image` to `path` (creating its folder) and prints `saved PATH (STATUS)`.
    pub(crate) fn save(&self, path: &Path, image: &Image, status: &str) -> Result<(), ViewerError> {
        save_png(path, image)?;
        println!(
            "{} {} ({status})",
            t("保存しました:", "saved").get(self.options.lang),
            path.display()
        );
        Ok(())
    }
}

/// Writes `image` to `path` as a PNG, creating the folder.
///
/// # Errors
/// [`ViewerError::Save`] naming the file and why.
pub fn save_png(path: &Path, image: &Image) -> Result<(), ViewerError> {
    let err = |message: String| ViewerError::Save { path: path.to_owned(), message };
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).map_err(|e| err(e.to_string()))?;
    }
    cg_scene::save_png(path, image).map_err(|e| err(e.describe(Lang::En)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::Rgb;

    #[test]
    fn errors_read_in_both_languages() {
        let e = ViewerError::Save { path: PathBuf::from("out/a.png"), message: "disk full".into() };
        assert_eq!(e.message(Lang::En), "cannot save out/a.png: disk full");
        assert_eq!(e.message(Lang::Ja), "out/a.png を保存できません: disk full");
        let w = ViewerError::Window("lost".into());
        assert_ne!(w.message(Lang::Ja), w.message(Lang::En));
        assert!(w.message(Lang::Ja).contains("lost"));
        // A scene error already comes in the chosen language.
        assert_eq!(ViewerError::Scene("x".into()).message(Lang::Ja), "x");
    }

    #[test]
    fn the_controls_are_listed_in_the_readers_language_in_one_column() {
        let ja = keys_text(Lang::Ja, false);
        assert!(ja.starts_with("操作:\n"), "{ja}");
        assert!(
            ja.contains("  右ドラッグ   上下で仰角") && ja.contains("  左ドラッグ   上下で距離"),
            "{ja}"
        );
        assert!(!ja.contains("drag") && !ja.contains("レンダラ"), "{ja}");
        assert!(ja.contains("  q / Esc      終了"), "{ja}");
        let en = keys_text(Lang::En, true);
        assert!(
            en.contains("  right-drag   pitch") && en.contains("  r            next renderer"),
            "{en}"
        );
    }

    /// A backend that fills the frame with one colour.
    struct Fill(&'static str, Rgb);

    impl Backend for Fill {
        fn name(&self) -> &str {
            self.0
        }

        fn render(
            &mut self,
            _: &cg_core::scene::Scene,
            r: &FrameRequest,
        ) -> Result<Image, ViewerError> {
            Ok(Image::new(r.size.0, r.size.1, self.1))
        }
    }

    #[test]
    fn the_r_key_cycles_through_the_backends_and_one_backend_stays() {
        let options = ViewerOptions::default();
        let mut shared = Shared::new(
            vec![Box::new(Fill("A", Rgb::ZERO)), Box::new(Fill("B", Rgb::ONE))],
            &options,
        )
        .unwrap();
        assert_eq!(shared.backend().name(), "A");
        shared.next_backend();
        assert_eq!(shared.backend().name(), "B");
        shared.next_backend();
        assert_eq!(shared.backend().name(), "A");
        let mut one = Shared::new(vec![Box::new(CpuBackend::default())], &options).unwrap();
        one.next_backend();
        assert_eq!(one.backend().name(), "CPU");
        assert!(Shared::new(Vec::new(), &options).is_err());
    }

    #[test]
    fn screenshots_are_numbered_unless_a_path_is_given() {
        let options = ViewerOptions { out_dir: Some("shots".into()), ..ViewerOptions::default() };
        let mut shared = Shared::new(vec![Box::new(CpuBackend::default())], &options).unwrap();
        assert_eq!(shared.screenshot_path(), Path::new("shots/screenshot-001.png"));
        assert_eq!(shared.screenshot_path(), Path::new("shots/screenshot-002.png"));
        let options =
            ViewerOptions { screenshot: Some("a.png".into()), ..ViewerOptions::default() };
        let mut shared = Shared::new(vec![Box::new(CpuBackend::default())], &options).unwrap();
        assert_eq!(shared.screenshot_path(), Path::new("a.png"));
        assert_eq!(
            Shared::new(vec![Box::new(CpuBackend::default())], &ViewerOptions::default())
                .unwrap()
                .out_dir(),
            Path::new("out")
        );
    }

    #[test]
    fn pixels_are_0rgb_rounded_as_opengl_and_clamped() {
        let mut image = Image::new(2, 1, Rgb::new(1.0, 0.5, 0.0));
        image.set(1, 0, Rgb::new(2.0, -1.0, f32::NAN));
        assert_eq!(to_0rgb(&image), [0x00ff_8000, 0x00ff_0000]);
    }

    #[test]
    fn a_bad_scene_is_an_error_that_names_the_file() {
        let options = ViewerOptions {
            scene: Some("no/such/scene.toml".into()),
            headless: true,
            ..ViewerOptions::default()
        };
        let e = run(&options).unwrap_err();
        assert!(matches!(e, ViewerError::Scene(_)));
        assert!(e.to_string().contains("scene.toml"), "{e}");
    }

    #[test]
    fn an_unwritable_screenshot_is_an_error() {
        let file = std::env::temp_dir().join(format!("cg-viewer-unit-{}", std::process::id()));
        std::fs::write(&file, b"a file, not a folder").unwrap();
        let options = ViewerOptions {
            size: Some((8, 8)),
            screenshot: Some(file.join("x.png")),
            ..ViewerOptions::default()
        };
        let mut app = CourseApp::course_sample();
        let e =
            run_headless(&mut app, vec![Box::new(CpuBackend::default())], &options).unwrap_err();
        assert!(matches!(e, ViewerError::Save { .. }), "{e}");
        let _ = std::fs::remove_file(&file);
    }
}
