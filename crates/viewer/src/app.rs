//! The application side of the viewer: the GLUT callbacks as a trait ([`App`]) and what a
//! callback may ask of the window shell ([`Control`]).

use cg_core::camera::MouseButton;
use cg_core::image::Image;

use crate::ViewerError;
use crate::backend::Backend;

/// What a callback asks the window shell to do once it returns: GLUT's `glutPostRedisplay()`,
/// `exit(0)`, and the viewer's own screenshot and renderer switch.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Control {
    redisplay: bool,
    quit: bool,
    screenshot: bool,
    next_renderer: bool,
}

impl Control {
    /// No request.
    #[must_use]
    pub fn new() -> Control {
        Control::default()
    }

    /// `glutPostRedisplay()`: draw a new frame (call [`App::display`]) soon.
    pub fn post_redisplay(&mut self) {
        self.redisplay = true;
    }

    /// `exit(0)`: close the window and return from [`crate::run`].
    pub fn quit(&mut self) {
        self.quit = true;
    }

    /// Save the last frame drawn as a PNG (the `--screenshot` path, or a numbered file in the
    /// output folder).
    pub fn screenshot(&mut self) {
        self.screenshot = true;
    }

    /// Switch to the next renderer ([`Backend`]) the shell has.
    pub fn next_renderer(&mut self) {
        self.next_renderer = true;
    }

    /// Whether [`Control::post_redisplay`] was called.
    #[must_use]
    pub fn redisplay_requested(&self) -> bool {
        self.redisplay
    }

    /// Whether [`Control::quit`] was called.
    #[must_use]
    pub fn quit_requested(&self) -> bool {
        self.quit
    }

    /// Whether [`Control::screenshot`] was called.
    #[must_use]
    pub fn screenshot_requested(&self) -> bool {
        self.screenshot
    }

    /// Whether [`Control::next_renderer`] was called.
    #[must_use]
    pub fn next_renderer_requested(&self) -> bool {
        self.next_renderer
    }
}

/// A program for the viewer, written as the course's GLUT program is: one method per callback.
///
/// | GLUT (the sample program) | here | when the shell calls it |
/// |---|---|---|
/// | `glutInitWindowSize(640, 640)` | [`App::window_size`] | once, before the window opens |
/// | `environment()` (initialisation after `glutCreateWindow`) | [`App::init`] | once, before the first frame |
/// | `glutDisplayFunc(display)` | [`App::display`] | for every frame; returns the image instead of drawing into GL |
/// | `glutReshapeFunc(reshape)` | [`App::reshape`] | when the window's size changes (and once at start) |
/// | `glutMouseFunc(mouse)` | [`App::mouse`] | a button pressed or released, with the pointer position |
/// | `glutMotionFunc(motion)` | [`App::motion`] | the pointer moves while a button is held |
/// | `glutIdleFunc(idle)` | [`App::idle`] | when no events wait, with the seconds since the last call |
/// | `glutKeyboardFunc(keyboard)` | [`App::keyboard`] | a key typed, as GLUT's `unsigned char` (Esc is `'\x1b'`) |
/// | `glutPostRedisplay()` | [`Control::post_redisplay`] | inside any callback |
/// | `glutSwapBuffers()` | — | the shell presents the image [`App::display`] returns (or the GPU presents [`App::direct_scene`]) |
/// | `glutMainLoop()` | [`crate::run_app`] | runs until [`Control::quit`] or the window closes |
///
/// Positions are window pixels, x right, y down from the top-left corner, as GLUT gives them.
pub trait App {
    /// The window's title: the mode the app is in. The shell appends the renderer and the frame
    /// time.
    fn title(&self) -> String;

    /// A one-line description of the state, printed when a screenshot is saved (tests read it).
    fn status(&self) -> String {
        self.title()
    }

    /// The window size asked for at start, in pixels (`glutInitWindowSize`).
    fn window_size(&self) -> (u32, u32) {
        (640, 640)
    }

    /// One-time setup before the first frame (the sample's `environment()`).
    fn init(&mut self) {}

    /// Draws one frame with `renderer` at the size last given to [`App::reshape`] and returns it.
    ///
    /// # Errors
    /// A [`ViewerError`] when the frame cannot be drawn; the shell stops and returns it.
    fn display(&mut self, renderer: &mut dyn Backend) -> Result<Image, ViewerError>;

    /// The frame as one scene drawn at the window's size with nothing over it, when it is: what
    /// [`App::display`] would draw, as the scene and the request it would pass to
    /// [`Backend::render`]. A backend that presents by itself (the GPU) then draws it straight
    /// into the window instead of calling [`App::display`]. `None` (the default): the frame is
    /// composed ([`crate::SideBySide`]) or drawn over, and [`App::display`] makes every frame.
    fn direct_scene(&self) -> Option<(cg_core::scene::Scene, crate::FrameRequest)> {
        None
    }

    /// The window is now `width × height` pixels (never 0).
    fn reshape(&mut self, width: u32, height: u32);

    /// A mouse button was pressed (`pressed`) or released at `(x, y)`.
    fn mouse(&mut self, button: MouseButton, pressed: bool, x: f32, y: f32, control: &mut Control) {
        let _ = (button, pressed, x, y, control);
    }

    /// The pointer moved to `(x, y)` with a button held.
    fn motion(&mut self, x: f32, y: f32, control: &mut Control) {
        let _ = (x, y, control);
    }

    /// Nothing else to do: advance the animation by `dt_seconds` and post a redisplay if it
    /// changed anything.
    fn idle(&mut self, dt_seconds: f32, control: &mut Control) {
        let _ = (dt_seconds, control);
    }

    /// A key was typed with the pointer at `(x, y)`. `key` is the character (Esc `'\x1b'`, space
    /// `' '`, Enter `'\r'`); keys without a character are not passed on, as in GLUT's keyboard
    /// callback.
    fn keyboard(&mut self, key: char, x: f32, y: f32, control: &mut Control) {
        let _ = (key, x, y, control);
    }
}
