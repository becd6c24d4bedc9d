//! The default app: the course's sample scene with the sample program's mouse mapping
//! ([`cg_core::camera::OrbitCamera`], [`cg_core::camera::MouseState`]), a spinning object, and
//! keys for the shading mode and the light model. All its logic is plain data, tested without a
//! window.

use cg_core::camera::{MouseButton, MouseState, OrbitCamera};
use cg_core::glam::Vec3;
use cg_core::image::Image;
use cg_core::lang::{Text, t};
use cg_core::light::{LightModel, Specular};
use cg_core::product::{Axis, Factor, Param};
use cg_core::scene::{Camera, Scene, Shading};

use crate::ViewerError;
use crate::app::{App, Control};
use crate::backend::{Backend, FrameRequest};

/// Which light model lights the scene: the lecture's term-by-term model or OpenGL 1.x's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightChoice {
    /// The lecture's model with Phong's (R·V)ⁿ specular.
    Lecture,
    /// OpenGL 1.x fixed-function lighting (the sample program's).
    OpenGl,
}

/// The keys and drags of the course app, for the help text: `(key, what it does)`, both in
/// Japanese and English. `gpu`: whether this build has the GPU renderer ([`crate::GPU_BUILT`]);
/// without it there is no other renderer for `r` to switch to, so `r` is not listed.
#[must_use]
pub fn controls(gpu: bool) -> Vec<(Text, Text)> {
    let mut rows = vec![
        (
            t("右ドラッグ", "right-drag"),
            t("上下で仰角、左右で方位角", "pitch (up/down) and yaw (left/right)"),
        ),
        (t("左ドラッグ", "left-drag"), t("上下で距離", "distance (up/down)")),
        (
            t("f / g / p", "f / g / p"),
            t("フラット / グロー / フォンシェーディング", "flat / Gouraud / Phong shading"),
        ),
        (t("l", "l"), t("講義の光のモデル / OpenGL の光のモデル", "lecture / OpenGL light model")),
    ];
    if gpu {
        rows.push((
            t("r", "r"),
            t(
                "次のレンダラ（CPU ラスタライザ / GPU、アダプタがあるとき）",
                "next renderer (CPU rasterizer / GPU, when an adapter exists)",
            ),
        ));
    }
    rows.extend([
        (t("space", "space"), t("アニメーションの一時停止 / 再開", "pause / resume the animation")),
        (t("s", "s"), t("スクリーンショットを保存（PNG）", "save a screenshot (PNG)")),
        (t("q / Esc", "q / Esc"), t("終了", "quit")),
    ]);
    rows
}

/// The course's sample program as an [`App`]: the scene, the orbit camera, the mouse state, the
/// shading mode, the light model and the animation angle.
///
/// The animation (the sample's `idle()`) turns every object not named `ground` about its own +Y
/// axis by [`CourseApp::spin_deg_per_s`]: its transform gets `· Ry(angle)` appended.
#[derive(Clone, Debug)]
pub struct CourseApp {
    /// The scene as loaded; [`CourseApp::scene`] derives each frame's scene from it.
    pub base: Scene,
    /// camera_yaw, camera_pitch, camera_distance and their clamps.
    pub camera: OrbitCamera,
    /// drag_mouse_l/m/r and last_mouse_x/y.
    pub mouse: MouseState,
    /// The shading mode (f, g, p).
    pub shading: Shading,
    /// The light model (l).
    pub light: LightChoice,
    /// Whether the animation is paused (space).
    pub paused: bool,
    /// The animation angle in degrees, in `[0, 360)`.
    pub angle_deg: f32,
    /// Animation speed in degrees per second.
    pub spin_deg_per_s: f32,
    /// The window size, from [`App::reshape`].
    pub size: (u32, u32),
}

impl CourseApp {
    /// The course's sample scene (`assets/scenes/course-sample.toml`, compiled in).
    #[must_use]
    pub fn course_sample() -> CourseApp {
        CourseApp::new(cg_harness::course::scene())
    }

    /// An app for any scene. An orbit camera is taken as it is; a look-at camera becomes the
    /// orbit camera with the same eye and target (pitch and distance clamped to the course's
    /// limits, so an eye below the target is moved up to pitch 0).
    #[must_use]
    pub fn new(scene: Scene) -> CourseApp {
        let camera = match scene.camera {
            Camera::Orbit(c) => c,
            Camera::LookAt { eye, target, .. } => orbit_from_eye(eye, target),
        };
        let light = match scene.light_model {
            LightModel::OpenGl { .. } => LightChoice::OpenGl,
            LightModel::Lecture { .. } => LightChoice::Lecture,
        };
        CourseApp {
            camera,
            mouse: MouseState::new(),
            shading: scene.shading,
            light,
            paused: false,
            angle_deg: 0.0,
            spin_deg_per_s: 45.0,
            size: (scene.width, scene.height),
            base: scene,
        }
    }

    /// The scene of the current state: the camera, shading, light model and animation angle
    /// applied to [`CourseApp::base`]. The headless render of this scene at [`CourseApp::size`]
    /// is what the window shows.
    #[must_use]
    pub fn scene(&self) -> Scene {
        let mut s = self.base.clone();
        s.camera = Camera::Orbit(self.camera);
        s.shading = self.shading;
        let local_viewer = s.light_model.local_viewer();
        s.light_model = match self.light {
            LightChoice::OpenGl => LightModel::OpenGl { local_viewer },
            LightChoice::Lecture => LightModel::Lecture { specular: Specular::Phong, local_viewer },
        };
        s.width = self.size.0;
        s.height = self.size.1;
        if self.angle_deg != 0.0 {
            for o in s.objects.iter_mut().filter(|o| o.name != "ground") {
                o.transform =
                    o.transform.clone().then(Factor::rotate(Axis::Y, Param::num(self.angle_deg)));
            }
        }
        s
    }

    /// The shading mode's name.
    #[must_use]
    pub fn shading_name(&self) -> &'static str {
        match self.shading {
            Shading::Flat => "Flat",
            Shading::Gouraud => "Gouraud",
            Shading::Phong => "Phong",
        }
    }
}

/// The orbit camera whose eye is at `eye` looking at `target` (the course's limits).
fn orbit_from_eye(eye: Vec3, target: Vec3) -> OrbitCamera {
    let mut c = OrbitCamera::course_sample();
    let d = eye - target;
    let distance = d.length();
    if !distance.is_finite() || distance <= 0.0 {
        return c;
    }
    let l = c.limits;
    c.target = target;
    c.distance = distance.max(l.distance_min).min(l.distance_max);
    c.pitch_deg = (-(d.y / distance).clamp(-1.0, 1.0).asin().to_degrees())
        .max(l.pitch_min_deg)
        .min(l.pitch_max_deg);
    c.yaw_deg = cg_core::math::wrap_degrees(d.x.atan2(d.z).to_degrees());
    c
}

impl App for CourseApp {
    fn title(&self) -> String {
        format!(
            "cg viewer — {} — {} · {} light model{}",
            self.base.name,
            self.shading_name(),
            match self.light {
                LightChoice::OpenGl => "OpenGL",
                LightChoice::Lecture => "lecture",
            },
            if self.paused { " · paused" } else { "" }
        )
    }

    fn status(&self) -> String {
        format!(
            "yaw={} pitch={} distance={} angle={} shading={} light={} size={}x{}",
            self.camera.yaw_deg,
            self.camera.pitch_deg,
            self.camera.distance,
            self.angle_deg,
            self.shading_name().to_lowercase(),
            match self.light {
                LightChoice::OpenGl => "opengl",
                LightChoice::Lecture => "lecture",
            },
            self.size.0,
            self.size.1
        )
    }

    fn window_size(&self) -> (u32, u32) {
        (self.base.width, self.base.height)
    }

    fn display(&mut self, renderer: &mut dyn Backend) -> Result<Image, ViewerError> {
        renderer.render(&self.scene(), &FrameRequest { size: self.size, shading: None })
    }

    fn direct_scene(&self) -> Option<(Scene, FrameRequest)> {
        Some((self.scene(), FrameRequest { size: self.size, shading: None }))
    }

    fn reshape(&mut self, width: u32, height: u32) {
        if width > 0 && height > 0 {
            self.size = (width, height);
        }
    }

    fn mouse(&mut self, button: MouseButton, pressed: bool, x: f32, y: f32, control: &mut Control) {
        self.mouse.mouse(button, pressed, x, y);
        let _ = control;
    }

    fn motion(&mut self, x: f32, y: f32, control: &mut Control) {
        let before = self.camera;
        self.mouse.motion(x, y, &mut self.camera);
        if self.camera != before {
            control.post_redisplay();
        }
    }

    /// The sample's `idle()`: unless paused, advances the angle and posts a redisplay (always,
    /// so the animation keeps going; the first call after a pause has `dt_seconds` 0).
    fn idle(&mut self, dt_seconds: f32, control: &mut Control) {
        if self.paused {
            return;
        }
        control.post_redisplay();
        if !(dt_seconds.is_finite() && dt_seconds > 0.0) {
            return;
        }
        // At most a quarter second per step, so a stalled frame does not jump the animation.
        let step = self.spin_deg_per_s * dt_seconds.min(0.25);
        if step.is_finite() {
            self.angle_deg = cg_core::math::wrap_degrees(self.angle_deg + step);
        }
    }

    fn keyboard(&mut self, key: char, x: f32, y: f32, control: &mut Control) {
        let _ = (x, y);
        match key.to_ascii_lowercase() {
            'f' => self.shading = Shading::Flat,
            'g' => self.shading = Shading::Gouraud,
            'p' => self.shading = Shading::Phong,
            'l' => {
                self.light = match self.light {
                    LightChoice::OpenGl => LightChoice::Lecture,
                    LightChoice::Lecture => LightChoice::OpenGl,
                };
            }
            'r' => control.next_renderer(),
            ' ' => self.paused = !self.paused,
            's' => {
                control.screenshot();
                return;
            }
            'q' | '\x1b' => {
                control.quit();
                return;
            }
            _ => return,
        }
        control.post_redisplay();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn app() -> CourseApp {
        CourseApp::course_sample()
    }

    #[test]
    fn starts_as_the_sample_program() {
        let a = app();
        assert_eq!(a.camera, OrbitCamera::course_sample());
        assert_eq!(a.size, (640, 640));
        assert_eq!(a.shading, Shading::Gouraud);
        assert_eq!(a.light, LightChoice::OpenGl);
        assert_eq!(a.scene().camera, Camera::Orbit(OrbitCamera::course_sample()));
    }

    #[test]
    fn right_drag_down_lowers_the_pitch_and_right_drag_right_lowers_the_yaw() {
        let mut a = app();
        let mut c = Control::new();
        a.mouse(MouseButton::Right, true, 100.0, 100.0, &mut c);
        a.motion(100.0, 120.0, &mut c);
        assert!(c.redisplay_requested());
        assert_eq!(a.camera.pitch_deg, -50.0);
        a.motion(110.0, 120.0, &mut c);
        assert_eq!(a.camera.yaw_deg, 350.0);
        // Clamped at -90.
        a.motion(110.0, 400.0, &mut c);
        assert_eq!(a.camera.pitch_deg, -90.0);
        a.mouse(MouseButton::Right, false, 110.0, 400.0, &mut c);
        let before = a.camera;
        let mut c = Control::new();
        a.motion(0.0, 0.0, &mut c);
        assert_eq!(a.camera, before, "no drag without a button");
        assert!(!c.redisplay_requested());
    }

    #[test]
    fn left_drag_changes_the_distance_with_a_lower_limit() {
        let mut a = app();
        let mut c = Control::new();
        a.mouse(MouseButton::Left, true, 10.0, 10.0, &mut c);
        a.motion(10.0, 20.0, &mut c);
        assert!((a.camera.distance - 17.0).abs() < 1e-5);
        a.motion(10.0, -1000.0, &mut c);
        assert_eq!(a.camera.distance, a.camera.limits.distance_min);
        assert_eq!(a.camera.pitch_deg, -30.0, "left-drag leaves the pitch alone");
    }

    #[test]
    fn keys_switch_modes_and_ask_the_shell() {
        let mut a = app();
        for (key, shading) in [('f', Shading::Flat), ('p', Shading::Phong), ('g', Shading::Gouraud)]
        {
            let mut c = Control::new();
            a.keyboard(key, 0.0, 0.0, &mut c);
            assert_eq!(a.shading, shading);
            assert_eq!(a.scene().shading, shading);
            assert!(c.redisplay_requested());
        }
        let mut c = Control::new();
        a.keyboard('l', 0.0, 0.0, &mut c);
        assert_eq!(a.light, LightChoice::Lecture);
        assert!(matches!(a.scene().light_model, LightModel::Lecture { local_viewer: false, .. }));
        a.keyboard('L', 0.0, 0.0, &mut c);
        assert_eq!(a.light, LightChoice::OpenGl);
        a.keyboard(' ', 0.0, 0.0, &mut c);
        assert!(a.paused);
        assert!(a.title().contains("paused"));
        for (key, check) in [
            ('s', Control::screenshot_requested as fn(&Control) -> bool),
            ('r', Control::next_renderer_requested),
            ('q', Control::quit_requested),
            ('\x1b', Control::quit_requested),
        ] {
            let mut c = Control::new();
            a.keyboard(key, 0.0, 0.0, &mut c);
            assert!(check(&c), "key {key:?}");
        }
        let mut c = Control::new();
        a.keyboard('z', 0.0, 0.0, &mut c);
        assert_eq!(c, Control::new(), "an unused key asks nothing");
    }

    #[test]
    fn idle_spins_the_object_unless_paused() {
        let mut a = app();
        let mut c = Control::new();
        a.idle(0.0, &mut c);
        assert!(c.redisplay_requested(), "the animation keeps going from dt = 0");
        assert_eq!(a.angle_deg, 0.0);
        a.idle(1.0, &mut c);
        assert!((a.angle_deg - 11.25).abs() < 1e-4, "a stalled frame counts as 0.25 s");
        a.idle(0.1, &mut c);
        assert!((a.angle_deg - 15.75).abs() < 1e-4);
        assert!(c.redisplay_requested());
        let s = a.scene();
        let pyramid = s.objects.iter().find(|o| o.name == "pyramid").unwrap();
        let ground = s.objects.iter().find(|o| o.name == "ground").unwrap();
        assert_ne!(pyramid.transform, a.base.objects[1].transform);
        assert_eq!(ground.transform, a.base.objects[0].transform);
        a.paused = true;
        let mut c = Control::new();
        a.idle(0.1, &mut c);
        assert!(!c.redisplay_requested());
        a.paused = false;
        a.idle(f32::NAN, &mut c);
        a.idle(-1.0, &mut c);
        assert!((a.angle_deg - 15.75).abs() < 1e-4);
    }

    #[test]
    fn reshape_sets_the_frame_size_and_ignores_zero() {
        let mut a = app();
        a.reshape(320, 200);
        a.reshape(0, 100);
        assert_eq!(a.size, (320, 200));
        assert_eq!((a.scene().width, a.scene().height), (320, 200));
    }

    #[test]
    fn a_look_at_camera_becomes_the_same_orbit() {
        let c = orbit_from_eye(Vec3::new(0.0, 7.5, 15.0 * 0.866_025_4), Vec3::ZERO);
        assert!((c.pitch_deg + 30.0).abs() < 1e-3);
        assert!((c.distance - 15.0).abs() < 1e-3);
        assert!(c.yaw_deg.abs() < 1e-3 || (c.yaw_deg - 360.0).abs() < 1e-3);
        let below = orbit_from_eye(Vec3::new(0.0, -5.0, 5.0), Vec3::ZERO);
        assert_eq!(below.pitch_deg, 0.0);
        assert_eq!(orbit_from_eye(Vec3::ZERO, Vec3::ZERO), OrbitCamera::course_sample());
    }

    #[test]
    fn every_key_is_explained_in_japanese_and_english() {
        let japanese = |s: &str| {
            s.chars().any(|c| matches!(c, '\u{3040}'..='\u{30ff}' | '\u{4e00}'..='\u{9fff}'))
        };
        for gpu in [true, false] {
            for (key, what) in controls(gpu) {
                assert!(japanese(&what.ja), "{key}: {}", what.ja);
                assert!(!what.en.is_empty() && !japanese(&what.en), "{key}: {}", what.en);
                // The drags are named in the reader's language, the keys are keys.
                assert!(!key.en.contains(|c: char| japanese(&c.to_string())), "{}", key.en);
                assert!(!key.ja.contains("drag"), "{}", key.ja);
            }
        }
    }

    #[test]
    fn the_renderer_key_is_listed_only_where_there_is_a_second_renderer() {
        let keys = |gpu: bool| controls(gpu).into_iter().map(|(k, _)| k.en).collect::<Vec<_>>();
        assert!(keys(true).contains(&"r".to_owned()));
        assert!(!keys(false).contains(&"r".to_owned()), "{:?}", keys(false));
        assert!(
            controls(false).iter().all(|(_, w)| !w.en.contains("GPU") && !w.ja.contains("GPU"))
        );
    }
}
