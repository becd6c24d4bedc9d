//! The renderer seam: the viewer draws through a [`Backend`], so the GPU renderer (`cg-gpu`)
//! plugs in beside the CPU rasterizer without changing an [`crate::App`].

use cg_core::image::Image;
use cg_core::lang::Lang;
use cg_core::scene::{Scene, Shading};

use crate::ViewerError;

/// What one frame asks of a renderer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameRequest {
    /// Width and height in pixels (the window's).
    pub size: (u32, u32),
    /// The shading mode instead of the scene's, if any.
    pub shading: Option<Shading>,
}

/// A renderer that draws a scene into an [`Image`] (row 0 at the top, linear RGB in `[0, 1]`).
///
/// The CPU rasterizer is [`CpuBackend`]. A GPU renderer implements the same trait (render to a
/// texture and read it back, or later present to the window itself); the shell switches between
/// the backends it was given with the `r` key.
pub trait Backend {
    /// A short name for the window title: `"CPU"`, `"GPU"`.
    fn name(&self) -> &str;

    /// Draws `scene` as `request` says.
    ///
    /// # Errors
    /// A [`ViewerError::Render`] naming what could not be drawn.
    fn render(&mut self, scene: &Scene, request: &FrameRequest) -> Result<Image, ViewerError>;
}

/// The kit's CPU rasterizer (`cg_raster::render`) as a [`Backend`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CpuBackend {
    /// Threads that draw the tiles; `None`: all cores (the image is the same for any count).
    pub threads: Option<usize>,
    /// The language of error messages.
    pub lang: Lang,
}

impl Backend for CpuBackend {
    fn name(&self) -> &str {
        "CPU"
    }

    fn render(&mut self, scene: &Scene, request: &FrameRequest) -> Result<Image, ViewerError> {
        let options = cg_raster::Options {
            shading: request.shading,
            size: Some(request.size),
            threads: self.threads,
            tile_size: None,
        };
        cg_raster::render(scene, &options)
            .map(|out| out.image)
            .map_err(|e| ViewerError::Render(e.message(self.lang)))
    }
}

/// The kit's GPU renderer (`cg_gpu`, wgpu) as a [`Backend`]: each frame is rendered on the
/// GPU into a texture and read back, then shown like the CPU's image, so both backends show
/// exactly what their headless renders give.
pub struct GpuBackend {
    gpu: cg_gpu::Gpu,
    name: String,
    /// The language of error messages.
    pub lang: Lang,
}

impl GpuBackend {
    /// The first GPU adapter (a real GPU, or Mesa's software Vulkan).
    ///
    /// # Errors
    /// No adapter or no device, as a message in `lang`.
    pub fn new(lang: Lang) -> Result<GpuBackend, String> {
        let gpu = cg_gpu::Gpu::new().map_err(|e| e.message(lang))?;
        let info = gpu.adapter().get_info();
        let kind = if info.device_type == cg_gpu::wgpu::DeviceType::Cpu { "GPU/sw" } else { "GPU" };
        Ok(GpuBackend { name: format!("{kind} ({})", info.name), gpu, lang })
    }

    /// Whether the adapter is a real GPU (not a software one such as lavapipe).
    #[must_use]
    pub fn is_hardware(&self) -> bool {
        self.gpu.adapter().get_info().device_type != cg_gpu::wgpu::DeviceType::Cpu
    }
}

impl Backend for GpuBackend {
    fn name(&self) -> &str {
        &self.name
    }

    fn render(&mut self, scene: &Scene, request: &FrameRequest) -> Result<Image, ViewerError> {
        let options = cg_gpu::Options { shading: request.shading, size: Some(request.size) };
        self.gpu
            .render(scene, &options)
            .map(|out| out.image)
            .map_err(|e| ViewerError::Render(e.message(self.lang)))
    }
}

/// The renderers a viewer gets: the GPU first when it is real hardware, else the CPU rasterizer
/// first with the software GPU as the second (`r` switches); the CPU alone without an adapter
/// (and a note saying why).
#[must_use]
pub fn default_backends(threads: Option<usize>, lang: Lang) -> Vec<Box<dyn Backend>> {
    let cpu = CpuBackend { threads, lang };
    match GpuBackend::new(lang) {
        Ok(gpu) if gpu.is_hardware() => vec![Box::new(gpu), Box::new(cpu)],
        Ok(gpu) => vec![Box::new(cpu), Box::new(gpu)],
        Err(why) => {
            eprintln!("{} {why}", lang.pick("GPU は使えません:", "no GPU:"));
            vec![Box::new(cpu)]
        }
    }
}

/// An [`Image`] as softbuffer's pixels: one `u32` per pixel, `0x00RRGGBB`, row 0 at the top,
/// each channel converted as OpenGL does ([`cg_core::image::to_unorm8`]).
#[must_use]
pub fn to_0rgb(image: &Image) -> Vec<u32> {
    let mut out = vec![0; image.pixels.len()];
    write_0rgb(image, &mut out);
    out
}

/// [`to_0rgb`] into `out`; pixels beyond the image (or beyond `out`) are left as they are.
pub fn write_0rgb(image: &Image, out: &mut [u32]) {
    use cg_core::image::to_unorm8;
    for (dst, c) in out.iter_mut().zip(&image.pixels) {
        *dst = (u32::from(to_unorm8(c.x)) << 16)
            | (u32::from(to_unorm8(c.y)) << 8)
            | u32::from(to_unorm8(c.z));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_gpu_backend_shows_what_the_cpu_backend_shows() {
        let mut gpu = match GpuBackend::new(Lang::En) {
            Ok(gpu) => gpu,
            Err(why) => {
                assert!(std::env::var_os("CI").is_none(), "CI has lavapipe: {why}");
                eprintln!("note: no GPU adapter, the GPU backend is not tested: {why}");
                return;
            }
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
