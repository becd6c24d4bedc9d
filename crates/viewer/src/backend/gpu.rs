//! The GPU backend (feature `gpu`): the kit's GPU renderer, `cg_gpu` on wgpu, drawing into a
//! texture that is read back, or presenting to a wgpu surface on the window.

use std::sync::Arc;

use cg_core::image::Image;
use cg_core::lang::{Lang, t};
use cg_core::scene::{Scene, Shading};
use cg_gpu::wgpu;
use winit::window::Window;

use super::{Backend, FrameRequest};
use crate::ViewerError;

/// The kit's GPU renderer (`cg_gpu`, wgpu) as a [`Backend`].
///
/// In a window it presents each frame itself ([`Backend::present`]): the scene becomes a
/// [`cg_gpu::Frame`] for the window surface's format (a non-sRGB one, `Bgra8Unorm` or
/// `Rgba8Unorm`: the kit's colours are written as they are, as OpenGL 1.x did), drawn into the
/// surface's texture. The surface is made on the first frame and configured again when the
/// window's size changes; a frame whose scene differs from the last one only in the camera and
/// the size is moved with [`cg_gpu::Gpu::update_view`] instead of being made again. Screenshots
/// draw that same frame into a texture and read it back ([`Backend::presented_image`]).
/// Without a window ([`Backend::render`]) it renders into a texture and reads it back; the last
/// few scenes rendered that way keep their frames too (a `cg view` frame composes two: the
/// student's and the reference), moved to each new camera and size.
pub struct GpuBackend {
    gpu: cg_gpu::Gpu,
    name: String,
    /// The language of error messages.
    pub lang: Lang,
    /// The surface on the window, made by the first [`Backend::present`].
    surface: Option<WindowSurface>,
    /// The frame last drawn into the surface, and the scene it was made from.
    presented: Option<Presented>,
    /// The surface could not be made (a note was printed): [`Backend::present`] says `None`.
    cannot_present: bool,
    /// Frames made for the surface (not moved): the tests see the reuse.
    frames_made: u64,
    /// The frames of the last [`KEPT_RENDERS`] scenes rendered without presenting, oldest first.
    rendered: Vec<Presented>,
    /// Frames made for [`Backend::render`] (not moved).
    renders_made: u64,
}

/// How many scenes [`Backend::render`] keeps frames for.
const KEPT_RENDERS: usize = 4;

/// A wgpu surface on a window, configured.
struct WindowSurface {
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    window: winit::window::WindowId,
    /// `get_current_texture` said the surface no longer matches the window.
    stale: bool,
}

/// A frame made for the surface's format, and what it was made from.
struct Presented {
    frame: cg_gpu::Frame,
    /// The scene without its camera and size (what [`cg_gpu::Gpu::update_view`] cannot change).
    scene: Scene,
    shading: Option<Shading>,
    /// Whether the frame reached the window since the surface was made (always `false` for a
    /// frame kept for [`Backend::render`]).
    shown: bool,
}

impl Presented {
    /// Whether this frame draws `key` (a scene [`without_view`]) in `shading` into `format`: only
    /// the camera and the size may differ, which [`cg_gpu::Gpu::update_view`] changes.
    fn draws(&self, key: &Scene, shading: Option<Shading>, format: wgpu::TextureFormat) -> bool {
        self.frame.format == format && self.shading == shading && self.scene == *key
    }
}

/// The surface formats the GPU presents in, in order of preference: the non-sRGB ones (the
/// kit's colours are written without conversion) that [`cg_gpu::Gpu::read_back`] reads.
const SURFACE_FORMATS: [wgpu::TextureFormat; 2] =
    [wgpu::TextureFormat::Bgra8Unorm, wgpu::TextureFormat::Rgba8Unorm];

/// `scene` with its camera and size set aside: two scenes equal after this draw the same
/// objects, materials and lights.
fn without_view(scene: &Scene) -> Scene {
    let mut s = scene.clone();
    s.camera = cg_core::scene::Camera::Orbit(cg_core::camera::OrbitCamera::course_sample());
    s.width = 1;
    s.height = 1;
    s
}

/// The surface format to present in, of those the surface offers.
#[must_use]
pub fn surface_format(offered: &[wgpu::TextureFormat]) -> Option<wgpu::TextureFormat> {
    SURFACE_FORMATS.into_iter().find(|f| offered.contains(f))
}

impl GpuBackend {
    /// The first GPU adapter (a real GPU, or Mesa's software Vulkan).
    ///
    /// # Errors
    /// No adapter or no device, as a message in `lang`.
    pub fn new(lang: Lang) -> Result<GpuBackend, String> {
        let gpu = cg_gpu::Gpu::new().map_err(|e| e.message(lang))?;
        let info = gpu.adapter().get_info();
        let kind = if info.device_type == wgpu::DeviceType::Cpu { "GPU/sw" } else { "GPU" };
        Ok(GpuBackend {
            name: format!("{kind} ({})", info.name),
            gpu,
            lang,
            surface: None,
            presented: None,
            cannot_present: false,
            frames_made: 0,
            rendered: Vec::new(),
            renders_made: 0,
        })
    }

    /// Whether the adapter is a real GPU (not a software one such as lavapipe).
    #[must_use]
    pub fn is_hardware(&self) -> bool {
        self.gpu.adapter().get_info().device_type != wgpu::DeviceType::Cpu
    }

    /// The format of the window surface in use, if one was made.
    #[must_use]
    pub fn surface_format(&self) -> Option<wgpu::TextureFormat> {
        self.surface.as_ref().map(|s| s.config.format)
    }

    fn error(&self, e: &cg_gpu::GpuError) -> ViewerError {
        ViewerError::Render(e.message(self.lang))
    }

    /// Runs `f` inside a validation error scope: wgpu's errors as a message instead of its
    /// default handler's panic.
    fn checked<T>(&self, f: impl FnOnce() -> T) -> Result<T, String> {
        let scope = self.gpu.device().push_error_scope(wgpu::ErrorFilter::Validation);
        let value = f();
        match pollster::block_on(scope.pop()) {
            Some(e) => Err(e.to_string()),
            None => Ok(value),
        }
    }

    /// Makes the surface on `window` (`None` with a note, once, when the GPU cannot present
    /// there).
    fn make_surface(&mut self, window: &Arc<Window>) -> Option<WindowSurface> {
        let lang = self.lang;
        let refuse = |this: &mut GpuBackend, why: String| {
            eprintln!(
                "{} {why}",
                t(
                    "GPU はこのウィンドウに直接表示できません。読み戻した画像を表示します:",
                    "the GPU cannot present to this window; showing its read-back image instead:"
                )
                .get(lang)
            );
            this.cannot_present = true;
            None
        };
        let surface = match self.gpu.instance().create_surface(window.clone()) {
            Ok(s) => s,
            Err(e) => return refuse(self, e.to_string()),
        };
        let caps = surface.get_capabilities(self.gpu.adapter());
        let Some(format) = surface_format(&caps.formats) else {
            let why = format!(
                "{} {:?}",
                t("sRGB でない 8 ビットの形式がありません:", "no 8-bit non-sRGB format in")
                    .get(lang),
                caps.formats
            );
            return refuse(self, why);
        };
        let present_mode = if caps.present_modes.contains(&wgpu::PresentMode::Fifo) {
            wgpu::PresentMode::Fifo
        } else if let Some(&mode) = caps.present_modes.first() {
            mode
        } else {
            return refuse(self, "no present mode".to_owned());
        };
        let size = window.inner_size();
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            color_space: wgpu::SurfaceColorSpace::Auto,
            width: size.width.max(1),
            height: size.height.max(1),
            desired_maximum_frame_latency: 2,
            present_mode,
            alpha_mode: wgpu::CompositeAlphaMode::Auto,
            view_formats: vec![],
        };
        if let Err(why) = self.checked(|| surface.configure(self.gpu.device(), &config)) {
            return refuse(self, why);
        }
        Some(WindowSurface { surface, config, window: window.id(), stale: false })
    }

    /// The frame for `scene` at `request`, in `format`: the last one moved to the new camera
    /// and size when only those changed, else a new one.
    fn frame_for(
        &mut self,
        scene: &Scene,
        request: &FrameRequest,
        format: wgpu::TextureFormat,
    ) -> Result<(), ViewerError> {
        let (w, h) = request.size;
        let key = without_view(scene);
        if let Some(p) = &mut self.presented
            && p.draws(&key, request.shading, format)
        {
            return self
                .gpu
                .update_view(&mut p.frame, scene, w, h)
                .map_err(|e| ViewerError::Render(e.message(self.lang)));
        }
        let options = cg_gpu::Options { shading: request.shading, size: Some(request.size) };
        let frame = self.gpu.frame(scene, &options, format).map_err(|e| self.error(&e))?;
        self.frames_made += 1;
        self.presented =
            Some(Presented { frame, scene: key, shading: request.shading, shown: false });
        Ok(())
    }

    /// One attempt to draw the current frame into the surface: `Ok(false)` when the surface
    /// gave no texture (it is then configured or made again for the next attempt).
    fn draw_into_surface(&mut self, window: &Arc<Window>) -> Result<bool, ViewerError> {
        let (Some(target), Some(presented)) = (&mut self.surface, &mut self.presented) else {
            return Ok(false);
        };
        let acquired = {
            // A validation error here goes to the scope, not to wgpu's panicking default handler.
            let scope = self.gpu.device().push_error_scope(wgpu::ErrorFilter::Validation);
            let acquired = target.surface.get_current_texture();
            let _ = pollster::block_on(scope.pop());
            acquired
        };
        let texture = match acquired {
            wgpu::CurrentSurfaceTexture::Success(t) => t,
            wgpu::CurrentSurfaceTexture::Suboptimal(t) => {
                target.stale = true;
                t
            }
            wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => {
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Outdated => {
                target.stale = true;
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Lost => {
                // Made again by the next attempt.
                self.surface = None;
                return Ok(false);
            }
            wgpu::CurrentSurfaceTexture::Validation => {
                return Err(ViewerError::Render(
                    t(
                        "ウィンドウのサーフェスが画像を渡しません（検証エラー）",
                        "the window surface gave no image (a validation error)",
                    )
                    .get(self.lang)
                    .to_owned(),
                ));
            }
        };
        let view = texture.texture.create_view(&wgpu::TextureViewDescriptor::default());
        let gpu = &self.gpu;
        let frame = &presented.frame;
        let drawn = {
            let scope = gpu.device().push_error_scope(wgpu::ErrorFilter::Validation);
            gpu.render_to_view(frame, &view);
            pollster::block_on(scope.pop())
        };
        if let Some(e) = drawn {
            // Dropping the texture unpresented gives it back to the surface.
            drop(texture);
            return Err(ViewerError::Render(e.to_string()));
        }
        window.pre_present_notify();
        gpu.queue().present(texture);
        presented.shown = true;
        Ok(true)
    }
}

impl Backend for GpuBackend {
    fn name(&self) -> &str {
        &self.name
    }

    fn render(&mut self, scene: &Scene, request: &FrameRequest) -> Result<Image, ViewerError> {
        let (w, h) = request.size;
        let (key, format) = (without_view(scene), cg_gpu::READBACK_FORMAT);
        let kept = self.rendered.iter().position(|p| p.draws(&key, request.shading, format));
        let i = match kept {
            Some(i) => {
                self.gpu
                    .update_view(&mut self.rendered[i].frame, scene, w, h)
                    .map_err(|e| self.error(&e))?;
                i
            }
            None => {
                let options =
                    cg_gpu::Options { shading: request.shading, size: Some(request.size) };
                let frame = self.gpu.frame(scene, &options, format).map_err(|e| self.error(&e))?;
                self.renders_made += 1;
                if self.rendered.len() == KEPT_RENDERS {
                    self.rendered.remove(0);
                }
                let shading = request.shading;
                self.rendered.push(Presented { frame, scene: key, shading, shown: false });
                self.rendered.len() - 1
            }
        };
        self.gpu.read_back(&self.rendered[i].frame).map_err(|e| self.error(&e))
    }

    fn present(
        &mut self,
        window: &Arc<Window>,
        scene: &Scene,
        request: &FrameRequest,
    ) -> Option<Result<bool, ViewerError>> {
        if self.cannot_present {
            return None;
        }
        let size = window.inner_size();
        let (w, h) = request.size;
        if (size.width, size.height) != (w, h) || w == 0 || h == 0 {
            // Not the window's size (a resize on its way): show the frame the usual way.
            return None;
        }
        if self.surface.as_ref().is_some_and(|s| s.window != window.id()) {
            self.release_window();
        }
        // Two attempts: the second after the surface was configured or made again.
        for _ in 0..2 {
            if self.surface.is_none() {
                self.surface = Some(self.make_surface(window)?);
                if let Some(p) = &mut self.presented {
                    p.shown = false;
                }
            }
            let Some(target) = &mut self.surface else { return None };
            if target.stale || (target.config.width, target.config.height) != (w, h) {
                target.config.width = w;
                target.config.height = h;
                target.stale = false;
                let (surface, config) = (&target.surface, &target.config);
                let device = self.gpu.device();
                let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
                surface.configure(device, config);
                if let Some(e) = pollster::block_on(scope.pop()) {
                    return Some(Err(ViewerError::Render(e.to_string())));
                }
            }
            let format = target.config.format;
            if let Err(e) = self.frame_for(scene, request, format) {
                return Some(Err(e));
            }
            match self.draw_into_surface(window) {
                Ok(false) => {}
                done => return Some(done),
            }
        }
        Some(Ok(false))
    }

    fn presented_image(&mut self) -> Option<Result<Image, ViewerError>> {
        let presented = self.presented.as_ref().filter(|p| p.shown)?;
        Some(self.gpu.read_back(&presented.frame).map_err(|e| self.error(&e)))
    }

    fn release_window(&mut self) {
        self.presented = None;
        self.surface = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::App;
    use crate::backend::{CpuBackend, RendererChoice, backends_for, default_backends};

    #[test]
    fn the_surface_format_is_a_non_srgb_one_or_none() {
        use wgpu::TextureFormat as F;
        assert_eq!(surface_format(&[F::Bgra8UnormSrgb, F::Bgra8Unorm]), Some(F::Bgra8Unorm));
        assert_eq!(surface_format(&[F::Rgba8UnormSrgb, F::Rgba8Unorm]), Some(F::Rgba8Unorm));
        assert_eq!(surface_format(&[F::Bgra8UnormSrgb, F::Rgba16Float]), None);
        assert_eq!(surface_format(&[]), None);
    }

    /// The window path without a window: the frame kept for the surface follows the camera
    /// (moved, not made again) and is made again when the objects change, and what a
    /// screenshot reads back is the fresh render of the scene of the moment.
    /// The GPU backend, or `None` (with a note that `what` is not tested) where there is no
    /// adapter — never in CI, which has lavapipe.
    fn backend_or_skip(what: &str) -> Option<GpuBackend> {
        match GpuBackend::new(Lang::En) {
            Ok(gpu) => Some(gpu),
            Err(why) => {
                assert!(std::env::var_os("CI").is_none(), "CI has lavapipe: {why}");
                eprintln!("note: no GPU adapter, {what}: {why}");
                None
            }
        }
    }

    /// `scene` rendered by `cg_gpu` on a frame of its own, made for this call.
    fn fresh(gpu: &GpuBackend, scene: &Scene, request: &FrameRequest) -> Image {
        let options = cg_gpu::Options { shading: request.shading, size: Some(request.size) };
        gpu.gpu.render(scene, &options).unwrap().image
    }

    /// A composed frame's renders (`cg view`'s two panels): each scene's frame is made once and
    /// moved to each new camera and size, two scenes keep two frames, and every image is the
    /// fresh render of the scene of the moment.
    #[test]
    fn renders_keep_a_frame_per_scene_and_move_it() {
        let Some(mut gpu) = backend_or_skip("kept render frames are not tested") else {
            return;
        };
        let mut app = crate::CourseApp::course_sample();
        app.size = (80, 60);
        let check = |app: &crate::CourseApp, gpu: &mut GpuBackend, made: u64| {
            let (scene, request) = app.direct_scene().unwrap();
            let image = gpu.render(&scene, &request).unwrap();
            assert_eq!(gpu.renders_made, made, "frames made so far");
            assert_eq!((image.width, image.height), request.size);
            assert_eq!(image.to_rgba8(), fresh(gpu, &scene, &request).to_rgba8());
        };
        check(&app, &mut gpu, 1);
        app.camera.yaw_deg = 40.0;
        app.size = (90, 50);
        check(&app, &mut gpu, 1); // moved and resized, not made again
        let mut other = app.clone();
        other.angle_deg = 30.0; // the objects turn: another scene
        check(&other, &mut gpu, 2);
        app.camera.pitch_deg = -50.0;
        check(&app, &mut gpu, 2); // the first scene's frame was kept
        check(&other, &mut gpu, 2);
        for angle in [60.0, 90.0, 120.0, 150.0] {
            other.angle_deg = angle;
            check(&other, &mut gpu, 2 + (angle / 30.0) as u64 - 1);
        }
        assert_eq!(gpu.rendered.len(), KEPT_RENDERS, "the oldest are dropped");
    }

    #[test]
    fn the_presented_frame_follows_the_camera_and_is_made_again_for_new_geometry() {
        let Some(mut gpu) = backend_or_skip("the presented frame is not tested") else {
            return;
        };
        let chosen = backends_for(RendererChoice::Gpu, Some(1), Lang::En).unwrap();
        assert!(chosen[0].name().starts_with("GPU") && chosen[1].name() == "CPU");
        assert!(gpu.presented_image().is_none(), "nothing presented yet");
        let mut app = crate::CourseApp::course_sample();
        app.size = (80, 60);
        let format = wgpu::TextureFormat::Bgra8Unorm;
        let check = |app: &crate::CourseApp, gpu: &mut GpuBackend, made: u64| {
            let (scene, request) = app.direct_scene().unwrap();
            gpu.frame_for(&scene, &request, format).unwrap();
            assert_eq!(gpu.frames_made, made, "frames made so far");
            gpu.presented.as_mut().unwrap().shown = true;
            let shot = gpu.presented_image().unwrap().unwrap();
            assert_eq!(shot.to_rgba8(), fresh(gpu, &scene, &request).to_rgba8());
        };
        check(&app, &mut gpu, 1);
        app.camera.yaw_deg = 40.0;
        app.camera.pitch_deg = -50.0;
        app.size = (90, 50);
        check(&app, &mut gpu, 1); // moved and resized, not made again
        app.angle_deg = 30.0; // the objects turn: new vertices
        check(&app, &mut gpu, 2);
        gpu.release_window();
        assert!(gpu.presented_image().is_none(), "released");
    }

    #[test]
    fn the_gpu_backend_shows_what_the_cpu_backend_shows() {
        let Some(mut gpu) = backend_or_skip("the GPU backend is not tested") else {
            return;
        };
        assert!(gpu.name().starts_with("GPU"), "{}", gpu.name());
        let scene = cg_harness::course::scene();
        let request = FrameRequest { size: (96, 64), shading: Some(Shading::Phong) };
        let a = gpu.render(&scene, &request).unwrap();
        let b = CpuBackend::default().render(&scene, &request).unwrap();
        assert_eq!((a.width, a.height), (96, 64));
        let worst = a
            .pixels
            .iter()
            .zip(&b.pixels)
            .map(|(p, q)| (*p - *q).abs().max_element())
            .fold(0.0f32, f32::max);
        assert!(worst <= 2.0 / 255.0, "GPU and CPU within 2/255: worst {worst}");
        let backends = default_backends(Some(1), Lang::En);
        assert_eq!(backends.len(), 2, "with an adapter: the CPU and the GPU");
    }
}
