//! The window shell: winit's event loop calling the [`App`]'s callbacks, the frame presented
//! through softbuffer — or, when the renderer presents by itself (the GPU on a wgpu surface) and
//! the app's frame is one scene ([`App::direct_scene`]), by the renderer.
//!
//! The window has one of the two at a time: softbuffer's surface is dropped once the GPU has
//! presented, and made again (the GPU's surface released first) when the CPU draws again.

use std::num::NonZeroU32;
use std::sync::Arc;
use std::time::Instant;

use cg_core::camera::MouseButton;
use cg_core::image::Image;
use softbuffer::{Context, Surface};
use winit::application::ApplicationHandler;
use winit::dpi::PhysicalSize;
use winit::event::{ElementState, KeyEvent, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

use crate::app::{App, Control};
use crate::backend::write_0rgb;
use crate::watch::{POLL, Watch};
use crate::{Outcome, Shared, ViewerError};

/// A window and its softbuffer surface.
struct Open {
    window: Arc<Window>,
    /// The title last set: set again only when it changes (on Wayland every `set_title` is a
    /// request on the socket, and a title per event can fill it faster than the compositor
    /// reads, which winit takes for a broken connection).
    title: String,
    context: Context<Arc<Window>>,
    /// softbuffer's surface; `None` while a backend presents by itself.
    surface: Option<Surface<Arc<Window>, Arc<Window>>>,
}

/// What the window shows.
enum Shown {
    /// An image drawn by [`App::display`], shown through softbuffer.
    Image(Image),
    /// A frame the backend with this index presented itself.
    Presented(usize),
}

/// The state the event loop drives.
struct Shell<'a, A: App> {
    app: &'a mut A,
    shared: &'a mut Shared,
    open: Option<Open>,
    cursor: (f32, f32),
    buttons: u8,
    last_idle: Option<Instant>,
    last_shown: Option<Shown>,
    /// `app.status()` when the last frame was drawn (the state it shows; idle may have moved on).
    last_status: String,
    frames: u64,
    frame_ms: f64,
    outcome: Outcome,
    /// [`crate::ViewerOptions::reload_on_change`], looked at while the window waits.
    watch: Option<Watch>,
}

impl<A: App> Shell<'_, A> {
    fn fail(&mut self, event_loop: &ActiveEventLoop, error: ViewerError) {
        self.outcome = Outcome::Failed(error);
        event_loop.exit();
    }

    /// The window could not be opened: fall back to PNGs when no frame was shown yet.
    fn no_window(&mut self, event_loop: &ActiveEventLoop, reason: String) {
        self.outcome = if self.frames == 0 {
            Outcome::NoDisplay(reason)
        } else {
            Outcome::Failed(ViewerError::Window(reason))
        };
        event_loop.exit();
    }

    /// What the window shows, read back from it (softbuffer's `fetch`, X11 does it), when it is
    /// the size of the last frame: a screenshot of the window itself, not of the frame handed to
    /// it. `None` where the platform cannot read back.
    fn window_pixels(&mut self) -> Option<Image> {
        let Some(Shown::Image(frame)) = &self.last_shown else { return None };
        let open = self.open.as_mut()?;
        let pixels = open.surface.as_mut()?.fetch().ok()?;
        let rgba: Vec<[u8; 4]> = pixels
            .iter()
            .map(|p| {
                let [_, r, g, b] = p.to_be_bytes();
                [r, g, b, 255]
            })
            .collect();
        Image::from_rgba8(frame.width, frame.height, &rgba)
    }

    /// What a window a backend presented to shows, read through a softbuffer surface made for
    /// the moment (X11 reads the window's pixels back), `width × height` pixels. `None` where
    /// the platform cannot read back.
    fn presented_window_pixels(&self, width: u32, height: u32) -> Option<Image> {
        let open = self.open.as_ref()?;
        let mut surface = Surface::new(&open.context, open.window.clone()).ok()?;
        surface.resize(NonZeroU32::new(width)?, NonZeroU32::new(height)?).ok()?;
        let pixels = surface.fetch().ok()?;
        let rgba: Vec<[u8; 4]> = pixels
            .iter()
            .map(|p| {
                let [_, r, g, b] = p.to_be_bytes();
                [r, g, b, 255]
            })
            .collect();
        Image::from_rgba8(width, height, &rgba)
    }

    /// The window's pixels (`"window"`), else the last frame drawn (`"frame"`); the frame a
    /// backend presented, drawn again and read back (`"presented"`, with how far the window's
    /// own pixels are from it where they can be read: ` window_diff=N`, the largest difference
    /// of a channel in 1/255).
    fn screenshot(&mut self) -> Result<Option<(Image, String)>, ViewerError> {
        if let Some(Shown::Presented(k)) = self.last_shown {
            let image = match self.shared.backend_at_mut(k).and_then(|b| b.presented_image()) {
                Some(Ok(image)) => image,
                Some(Err(e)) => return Err(e),
                None => return Ok(None),
            };
            let mut source = "presented".to_owned();
            if let Some(window) = self.presented_window_pixels(image.width, image.height) {
                let diff = window
                    .to_rgba8()
                    .iter()
                    .zip(image.to_rgba8())
                    .flat_map(|(a, b)| (0..3).map(move |c| a[c].abs_diff(b[c])))
                    .max()
                    .unwrap_or(0);
                source.push_str(&format!(" window_diff={diff}"));
            }
            return Ok(Some((image, source)));
        }
        if let Some(image) = self.window_pixels() {
            return Ok(Some((image, "window".to_owned())));
        }
        match &self.last_shown {
            Some(Shown::Image(image)) => Ok(Some((image.clone(), "frame".to_owned()))),
            _ => Ok(None),
        }
    }

    fn set_title(&mut self) {
        let title = format!(
            "{} — {} — {:.1} ms",
            self.app.title(),
            self.shared.backend().name(),
            self.frame_ms
        );
        if let Some(open) = &mut self.open
            && open.title != title
        {
            open.window.set_title(&title);
            open.title = title;
        }
    }

    /// Carries out what a callback asked.
    fn control(&mut self, event_loop: &ActiveEventLoop, control: Control) {
        if control.next_renderer_requested() {
            self.shared.next_backend();
        }
        if control.screenshot_requested() {
            let saved = self.screenshot().and_then(|shot| match shot {
                Some((image, source)) => {
                    let path = self.shared.screenshot_path();
                    let status = format!("{} source={source}", self.last_status);
                    self.shared.save(&path, &image, &status)
                }
                None => Ok(()),
            });
            if let Err(e) = saved {
                self.fail(event_loop, e);
                return;
            }
        }
        if control.quit_requested() {
            event_loop.exit();
            return;
        }
        if (control.redisplay_requested() || control.next_renderer_requested())
            && let Some(open) = &self.open
        {
            open.window.request_redraw();
        }
        self.set_title();
    }

    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        let Some(open) = &self.open else { return };
        let window = open.window.clone();
        let size = window.inner_size();
        let (Some(w), Some(h)) = (NonZeroU32::new(size.width), NonZeroU32::new(size.height)) else {
            return; // minimised
        };
        self.app.reshape(w.get(), h.get());
        let start = Instant::now();
        let current = self.shared.current();
        let presented = match self.app.direct_scene() {
            Some((scene, request)) => {
                // One surface on the window at a time: the other backends let go of theirs.
                self.shared.release_windows(Some(current));
                self.shared.backend_mut().present(&window, &scene, &request)
            }
            None => None,
        };
        match presented {
            Some(Err(e)) => return self.fail(event_loop, e),
            Some(Ok(shown)) => {
                // The backend has the window now: softbuffer lets go (made again when the CPU
                // draws).
                if let Some(open) = &mut self.open {
                    open.surface = None;
                }
                if !shown {
                    // No image from the surface this time (reconfigured, timed out): again.
                    window.request_redraw();
                    return;
                }
                self.frame_ms = start.elapsed().as_secs_f64() * 1000.0;
                self.last_status = self.app.status();
                self.last_shown = Some(Shown::Presented(current));
            }
            None => {
                if !self.draw_image(event_loop, &window, w, h, start) {
                    return;
                }
            }
        }
        self.frames += 1;
        self.set_title();
        match self.shared.options.frames {
            Some(n) if self.frames >= n => event_loop.exit(),
            // A scripted run (`--frames N`) draws frame after frame until it has N.
            Some(_) => window.request_redraw(),
            None => {}
        }
    }

    /// The frame as an image from [`App::display`], shown through softbuffer. `false` when the
    /// shell has stopped (the outcome says why).
    fn draw_image(
        &mut self,
        event_loop: &ActiveEventLoop,
        window: &Arc<Window>,
        w: NonZeroU32,
        h: NonZeroU32,
        start: Instant,
    ) -> bool {
        // softbuffer takes the window back: no backend keeps a surface on it.
        self.shared.release_windows(None);
        let Some(open) = &mut self.open else { return false };
        if open.surface.is_none() {
            match Surface::new(&open.context, window.clone()) {
                Ok(surface) => open.surface = Some(surface),
                Err(e) => {
                    self.no_window(event_loop, e.to_string());
                    return false;
                }
            }
        }
        if let Some(Err(e)) = open.surface.as_mut().map(|s| s.resize(w, h)) {
            self.no_window(event_loop, e.to_string());
            return false;
        }
        let image = match self.app.display(self.shared.backend_mut()) {
            Ok(image) => image,
            Err(e) => {
                self.fail(event_loop, e);
                return false;
            }
        };
        self.frame_ms = start.elapsed().as_secs_f64() * 1000.0;
        self.last_status = self.app.status();
        let Some(surface) = self.open.as_mut().and_then(|o| o.surface.as_mut()) else {
            return false;
        };
        let mut buffer = match surface.buffer_mut() {
            Ok(b) => b,
            Err(e) => {
                let reason = e.to_string();
                self.no_window(event_loop, reason);
                return false;
            }
        };
        buffer.fill(0);
        if image.width == w.get() && image.height == h.get() {
            write_0rgb(&image, &mut buffer);
        }
        window.pre_present_notify();
        if let Err(e) = buffer.present() {
            let reason = e.to_string();
            self.no_window(event_loop, reason);
            return false;
        }
        self.last_shown = Some(Shown::Image(image));
        true
    }
}

impl<A: App> ApplicationHandler for Shell<'_, A> {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.open.is_some() {
            return;
        }
        let (w, h) = self.shared.options.size.unwrap_or_else(|| self.app.window_size());
        let attributes = Window::default_attributes()
            .with_title(self.app.title())
            .with_inner_size(PhysicalSize::new(w.max(1), h.max(1)));
        let window = match event_loop.create_window(attributes) {
            Ok(w) => Arc::new(w),
            Err(e) => return self.no_window(event_loop, e.to_string()),
        };
        let context = match Context::new(window.clone()) {
            Ok(c) => c,
            Err(e) => return self.no_window(event_loop, e.to_string()),
        };
        let surface = match Surface::new(&context, window.clone()) {
            Ok(s) => s,
            Err(e) => return self.no_window(event_loop, e.to_string()),
        };
        self.app.init();
        self.app.reshape(w.max(1), h.max(1));
        self.open = Some(Open { window, title: String::new(), context, surface: Some(surface) });
        self.set_title();
        if let Some(open) = &self.open {
            open.window.request_redraw();
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let mut control = Control::new();
        match event {
            WindowEvent::CloseRequested => {
                event_loop.exit();
                return;
            }
            WindowEvent::RedrawRequested => return self.redraw(event_loop),
            WindowEvent::Resized(size) => {
                if size.width > 0 && size.height > 0 {
                    self.app.reshape(size.width, size.height);
                    control.post_redisplay();
                }
            }
            WindowEvent::CursorMoved { position, .. } => {
                let (x, y) = (position.x as f32, position.y as f32);
                self.cursor = (x, y);
                if self.buttons != 0 {
                    self.app.motion(x, y, &mut control);
                }
            }
            WindowEvent::MouseInput { state, button, .. } => {
                let (button, bit) = match button {
                    winit::event::MouseButton::Left => (MouseButton::Left, 1),
                    winit::event::MouseButton::Middle => (MouseButton::Middle, 2),
                    winit::event::MouseButton::Right => (MouseButton::Right, 4),
                    _ => return,
                };
                let pressed = state == ElementState::Pressed;
                if pressed {
                    self.buttons |= bit;
                } else {
                    self.buttons &= !bit;
                }
                self.app.mouse(button, pressed, self.cursor.0, self.cursor.1, &mut control);
            }
            WindowEvent::KeyboardInput {
                event: KeyEvent { logical_key, state: ElementState::Pressed, .. },
                ..
            } => {
                let key = match &logical_key {
                    Key::Named(NamedKey::Escape) => Some('\x1b'),
                    Key::Named(NamedKey::Space) => Some(' '),
                    Key::Named(NamedKey::Enter) => Some('\r'),
                    Key::Named(NamedKey::Tab) => Some('\t'),
                    Key::Named(NamedKey::Backspace) => Some('\x08'),
                    Key::Character(s) => s.chars().next(),
                    _ => None,
                };
                if let Some(key) = key {
                    self.app.keyboard(key, self.cursor.0, self.cursor.1, &mut control);
                }
            }
            _ => return,
        }
        self.control(event_loop, control);
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if self.open.is_none() {
            return;
        }
        let now = Instant::now();
        if let Some(watch) = &mut self.watch
            && watch.due(now)
            && watch.changed(now)
        {
            self.outcome = Outcome::Changed;
            event_loop.exit();
            return;
        }
        let dt = self.last_idle.map_or(0.0, |t| now.duration_since(t).as_secs_f32());
        self.last_idle = Some(now);
        let mut control = Control::new();
        self.app.idle(dt, &mut control);
        // GLUT calls idle() whenever nothing else happens: keep polling while the app animates,
        // sleep until the next event when it does not.
        event_loop.set_control_flow(if control.redisplay_requested() {
            ControlFlow::Poll
        } else {
            self.last_idle = None;
            // Wake up now and then to look at the watched file.
            match self.watch {
                Some(_) => ControlFlow::WaitUntil(now + POLL),
                None => ControlFlow::Wait,
            }
        });
        self.control(event_loop, control);
    }
}

/// The event loop on the display the environment names: on Linux and the BSDs, Wayland when
/// `WAYLAND_DISPLAY` is set, else X11 (so winit does not first try, and have libwayland
/// complain about, a Wayland it was not asked for); elsewhere the system's own.
fn new_event_loop() -> Result<EventLoop<()>, winit::error::EventLoopError> {
    let mut builder = EventLoop::builder();
    #[cfg(any(
        target_os = "linux",
        target_os = "freebsd",
        target_os = "openbsd",
        target_os = "netbsd",
        target_os = "dragonfly"
    ))]
    {
        // platform: winit's Wayland and X11 backends exist on these systems only.
        use winit::platform::wayland::EventLoopBuilderExtWayland;
        use winit::platform::x11::EventLoopBuilderExtX11;
        if std::env::var_os("WAYLAND_DISPLAY").is_some_and(|v| !v.is_empty()) {
            builder.with_wayland();
        } else {
            builder.with_x11();
        }
    }
    builder.build()
}

/// A window system's error as a sentence: winit's `"os error at <its source file>:<line>: …"`
/// without the source location (which says nothing to a student).
pub(crate) fn tidy_reason(reason: &str) -> String {
    reason
        .strip_prefix("os error at ")
        .and_then(|rest| rest.find(".rs:").map(|at| &rest[at..]))
        .and_then(|rest| rest.split_once(": "))
        .map_or_else(|| reason.to_owned(), |(_, why)| why.to_owned())
}

/// Opens the window and runs the event loop until the app quits, the window closes or the frame
/// limit is reached. [`Outcome::NoDisplay`] when no window could be opened.
pub(crate) fn run<A: App>(app: &mut A, shared: &mut Shared) -> Outcome {
    // winit panics (instead of returning an error) when the event loop is created off the main
    // thread on Linux: that, too, means "no window here".
    let event_loop = match std::panic::catch_unwind(new_event_loop) {
        Ok(Ok(l)) => l,
        Ok(Err(e)) => return Outcome::NoDisplay(tidy_reason(&e.to_string())),
        Err(_) => {
            return Outcome::NoDisplay(
                "the window's event loop can only run on the main thread".to_owned(),
            );
        }
    };
    event_loop.set_control_flow(ControlFlow::Wait);
    let watch = shared.options.reload_on_change.clone().map(Watch::new);
    let mut shell = Shell {
        app,
        shared,
        open: None,
        cursor: (0.0, 0.0),
        buttons: 0,
        last_idle: None,
        last_shown: None,
        last_status: String::new(),
        frames: 0,
        frame_ms: 0.0,
        outcome: Outcome::Done,
        watch,
    };
    if let Err(e) = event_loop.run_app(&mut shell) {
        if shell.frames == 0 && matches!(shell.outcome, Outcome::Done) {
            return Outcome::NoDisplay(tidy_reason(&e.to_string()));
        }
        return Outcome::Failed(ViewerError::Window(e.to_string()));
    }
    if matches!(shell.outcome, Outcome::Done)
        && let Some(path) = shell.shared.options.screenshot.clone()
    {
        let saved = shell.screenshot().and_then(|shot| match shot {
            Some((image, source)) => {
                let status = format!("{} source={source}", shell.last_status);
                shell.shared.save(&path, &image, &status)
            }
            None => Ok(()),
        });
        if let Err(e) = saved {
            shell.shared.release_windows(None);
            return Outcome::Failed(e);
        }
    }
    // The backends' surfaces go before the window does.
    shell.shared.release_windows(None);
    shell.outcome
}
