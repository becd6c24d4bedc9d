//! Scenes that change with time, side by side: `cg view a1` shows the student's result and the
//! reference in one window, both at the same time `t` and from the same camera.
//!
//! Each panel is a [`Source`]: a function from the time to a scene (an assignment's `view`
//! function). The camera, shading and light-model keys are those of [`CourseApp`]; `idle()`
//! advances the time instead of spinning the objects. A source whose camera is the student's
//! own work (assignment 2) keeps it: [`Source::own_camera`].

use cg_core::Rgb;
use cg_core::camera::MouseButton;
use cg_core::image::Image;
use cg_core::scene::{Camera, Scene};

use crate::ViewerError;
use crate::app::{App, Control};
use crate::backend::{Backend, FrameRequest};
use crate::course::CourseApp;

/// The scene of a panel at a time (seconds), or why there is none (a task not done yet).
pub type SceneAt = Box<dyn FnMut(f64) -> Result<Scene, String>>;

/// One panel.
pub struct Source {
    /// Its label in the title (`yours`, `reference`).
    pub label: String,
    /// Its scene at time `t`.
    pub scene_at: SceneAt,
    /// Keep the scene's own camera (the mouse does not move it).
    pub own_camera: bool,
}

/// The panels, the time and the shared view state.
pub struct SideBySide {
    /// The panels, left to right.
    pub sources: Vec<Source>,
    /// Camera, mouse, shading, light model, pause and window size (its `base` is the first
    /// panel's scene at the start; its spin is off).
    pub view: CourseApp,
    /// The animation time in seconds.
    pub time: f64,
    /// Each panel's message when it could not be drawn in the last frame.
    pub problems: Vec<Option<String>>,
    /// A name for the title (`a1`).
    pub name: String,
}

/// The grey of a panel that could not be drawn, and of the line between panels.
const EMPTY: Rgb = Rgb::splat(0.15);
const DIVIDER: Rgb = Rgb::splat(0.6);

impl SideBySide {
    /// Panels at time `time`; the first panel's scene at that time sets the camera, the shading
    /// mode, the light model and the window size (each panel gets its share of the width).
    ///
    /// # Errors
    /// When no panel has a scene at the start.
    pub fn new(name: &str, mut sources: Vec<Source>, time: f64) -> Result<SideBySide, String> {
        let mut first = Err(String::new());
        for s in &mut sources {
            first = (s.scene_at)(time);
            if first.is_ok() {
                break;
            }
        }
        let base = first?;
        let n = u32::try_from(sources.len()).unwrap_or(1).max(1);
        let mut view = CourseApp::new(base);
        view.spin_deg_per_s = 0.0;
        view.size = (view.base.width.saturating_mul(n), view.base.height);
        let problems = vec![None; sources.len()];
        Ok(SideBySide { sources, view, time, problems, name: name.to_owned() })
    }

    /// The scene of panel `k` at the current time, with the view's camera (unless the panel
    /// keeps its own), shading and light model.
    ///
    /// # Errors
    /// Why the panel has no scene.
    pub fn scene(&mut self, k: usize) -> Result<Scene, String> {
        let size = self.panel_size();
        let time = self.time;
        let source = self.sources.get_mut(k).ok_or_else(|| format!("no panel {k}"))?;
        let own = (source.scene_at)(time)?;
        let own_camera = source.own_camera;
        let mut view = self.view.clone();
        view.size = size;
        let camera: Camera = own.camera;
        view.base = own;
        let mut scene = view.scene();
        if own_camera {
            scene.camera = camera;
        }
        Ok(scene)
    }

    /// The size of one panel.
    #[must_use]
    pub fn panel_size(&self) -> (u32, u32) {
        let n = u32::try_from(self.sources.len()).unwrap_or(1).max(1);
        ((self.view.size.0 / n).max(1), self.view.size.1.max(1))
    }
}

impl App for SideBySide {
    fn title(&self) -> String {
        let labels: Vec<&str> = self.sources.iter().map(|s| s.label.as_str()).collect();
        format!(
            "cg view {} — {} — t = {:.2} s — {}{}",
            self.name,
            labels.join(" | "),
            self.time,
            self.view.shading_name(),
            if self.view.paused { " · paused" } else { "" }
        )
    }

    fn status(&self) -> String {
        let mut s = format!("t={:.3} {}", self.time, self.view.status());
        for (source, problem) in self.sources.iter().zip(&self.problems) {
            if let Some(p) = problem {
                s.push_str(&format!("; {}: {p}", source.label));
            }
        }
        s
    }

    fn window_size(&self) -> (u32, u32) {
        self.view.size
    }

    fn display(&mut self, renderer: &mut dyn Backend) -> Result<Image, ViewerError> {
        let (w, h) = (self.view.size.0.max(1), self.view.size.1.max(1));
        let (pw, ph) = self.panel_size();
        let mut out = Image::new(w, h, EMPTY);
        for k in 0..self.sources.len() {
            let x0 = u32::try_from(k).unwrap_or(0) * pw;
            match self.scene(k) {
                Ok(scene) => {
                    self.problems[k] = None;
                    let image =
                        renderer.render(&scene, &FrameRequest { size: (pw, ph), shading: None })?;
                    for y in 0..image.height.min(h) {
                        for x in 0..image.width.min(w.saturating_sub(x0)) {
                            if let Some(c) = image.get(x, y) {
                                out.set(x0 + x, y, c);
                            }
                        }
                    }
                }
                Err(why) => self.problems[k] = Some(why),
            }
            if k > 0 {
                for y in 0..h {
                    out.set(x0, y, DIVIDER);
                }
            }
        }
        Ok(out)
    }

    fn reshape(&mut self, width: u32, height: u32) {
        self.view.reshape(width, height);
    }

    fn mouse(&mut self, button: MouseButton, pressed: bool, x: f32, y: f32, control: &mut Control) {
        self.view.mouse(button, pressed, x, y, control);
    }

    fn motion(&mut self, x: f32, y: f32, control: &mut Control) {
        self.view.motion(x, y, control);
    }

    /// Advances the time (at most a quarter second per step) unless paused.
    fn idle(&mut self, dt_seconds: f32, control: &mut Control) {
        if self.view.paused {
            return;
        }
        control.post_redisplay();
        if dt_seconds.is_finite() && dt_seconds > 0.0 {
            self.time += f64::from(dt_seconds.min(0.25));
        }
    }

    fn keyboard(&mut self, key: char, x: f32, y: f32, control: &mut Control) {
        self.view.keyboard(key, x, y, control);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::CpuBackend;
    use cg_core::scene::Shading;

    fn course(label: &str, own_camera: bool) -> Source {
        Source {
            label: label.to_owned(),
            scene_at: Box::new(|_| Ok(cg_harness::course::scene())),
            own_camera,
        }
    }

    #[test]
    fn two_panels_show_the_same_scene_side_by_side() {
        let mut app =
            SideBySide::new("test", vec![course("yours", false), course("reference", false)], 0.0)
                .unwrap();
        app.reshape(64, 24);
        let mut cpu = CpuBackend { threads: Some(1), ..CpuBackend::default() };
        let image = app.display(&mut cpu).unwrap();
        assert_eq!((image.width, image.height), (64, 24));
        let single = cpu
            .render(&app.scene(0).unwrap(), &FrameRequest { size: (32, 24), shading: None })
            .unwrap();
        for y in 0..24 {
            for x in 1..32 {
                assert_eq!(image.get(x, y), single.get(x, y), "left panel at ({x}, {y})");
                assert_eq!(image.get(32 + x, y), single.get(x, y), "right panel at ({x}, {y})");
            }
            assert_eq!(image.get(32, y), Some(DIVIDER));
        }
    }

    #[test]
    fn a_panel_without_a_scene_is_grey_and_says_why() {
        let missing = Source {
            label: "yours".to_owned(),
            scene_at: Box::new(|_| Err("a1.t1: not done yet".to_owned())),
            own_camera: false,
        };
        let mut app =
            SideBySide::new("a1", vec![missing, course("reference", false)], 0.0).unwrap();
        app.reshape(40, 20);
        let image = app.display(&mut CpuBackend::default()).unwrap();
        assert_eq!(image.get(5, 5), Some(EMPTY));
        assert!(app.status().contains("yours: a1.t1: not done yet"), "{}", app.status());
        let none = Source {
            label: "x".into(),
            scene_at: Box::new(|_| Err("no".into())),
            own_camera: false,
        };
        assert!(SideBySide::new("a1", vec![none], 0.0).is_err());
    }

    #[test]
    fn time_runs_unless_paused_and_the_keys_drag_and_own_camera_behave() {
        let mut app =
            SideBySide::new("a2", vec![course("yours", true), course("ref", false)], 0.0).unwrap();
        let mut c = Control::new();
        app.idle(0.1, &mut c);
        assert!((app.time - 0.1).abs() < 1e-6 && c.redisplay_requested());
        app.idle(5.0, &mut c);
        assert!((app.time - 0.35).abs() < 1e-6, "a stall advances at most 0.25 s");
        app.keyboard(' ', 0.0, 0.0, &mut c);
        app.idle(0.1, &mut c);
        assert!((app.time - 0.35).abs() < 1e-6, "paused");
        app.keyboard('p', 0.0, 0.0, &mut c);
        assert_eq!(app.scene(1).unwrap().shading, Shading::Phong);
        let start = app.scene(0).unwrap().camera;
        app.mouse(MouseButton::Right, true, 10.0, 10.0, &mut c);
        app.motion(10.0, 30.0, &mut c);
        assert_eq!(app.scene(0).unwrap().camera, start, "the student's own camera stays");
        assert_ne!(app.scene(1).unwrap().camera, start, "the other panel follows the drag");
    }
}
