//! The renderer seam: the viewer draws through a [`Backend`], so the GPU renderer (`cg-gpu`)
//! plugs in beside the CPU rasterizer without changing an [`crate::App`].
//!
//! Two ways to the window: [`Backend::render`] gives an image that the shell shows through
//! softbuffer (the CPU rasterizer, and any app that composes its frame, such as
//! [`crate::SideBySide`]); [`Backend::present`] draws straight into the window (the GPU, onto a
//! wgpu surface) when the app's frame is one scene ([`crate::App::direct_scene`]).
//!
//! The GPU backend is the `gpu` feature (`backend/gpu.rs`): a build without it (the students'
//! copy, by default) draws with the CPU alone, and a request for the GPU says that the build
//! left it out and which command builds it ([`gpu_left_out`]).

use std::sync::Arc;

use cg_core::image::Image;
use cg_core::lang::{Lang, Text, t};
use cg_core::scene::{Scene, Shading};
use winit::window::Window;

use crate::ViewerError;

#[cfg(feature = "gpu")]
mod gpu;
#[cfg(feature = "gpu")]
pub use gpu::{GpuBackend, surface_format};

/// What one frame asks of a renderer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FrameRequest {
    /// Width and height in pixels (the window's).
    pub size: (u32, u32),
    /// The shading mode instead of the scene's, if any.
    pub shading: Option<Shading>,
}

/// A renderer that draws a scene into an [`Image`] (row 0 at the top, linear RGB in `[0, 1]`),
/// and may draw it straight into a window.
///
/// The CPU rasterizer is [`CpuBackend`]; the GPU is `GpuBackend` (feature `gpu`), which renders to a texture
/// and reads it back for [`Backend::render`], and presents to a wgpu surface on the window for
/// [`Backend::present`]. The shell switches between the backends it was given with the `r` key.
pub trait Backend {
    /// A short name for the window title: `"CPU"`, `"GPU"`.
    fn name(&self) -> &str;

    /// Draws `scene` as `request` says.
    ///
    /// # Errors
    /// A [`ViewerError::Render`] naming what could not be drawn.
    fn render(&mut self, scene: &Scene, request: &FrameRequest) -> Result<Image, ViewerError>;

    /// Draws `scene` as `request` says straight into `window` (whose inner size is
    /// `request.size`) and presents it. `None`: this backend does not present by itself (the
    /// default), or cannot present to this window — the shell then calls
    /// [`crate::App::display`] and shows the image through softbuffer. `Some(Ok(true))`: the
    /// frame is in the window; `Some(Ok(false))`: the window had no image to give this time
    /// (timed out, occluded, reconfigured), draw again later.
    ///
    /// The shell calls [`Backend::release_window`] before it draws into the window through
    /// softbuffer again, so a backend may keep what it made for the window until then.
    ///
    /// # Errors
    /// A [`ViewerError::Render`] when the frame cannot be drawn.
    fn present(
        &mut self,
        window: &Arc<Window>,
        scene: &Scene,
        request: &FrameRequest,
    ) -> Option<Result<bool, ViewerError>> {
        let _ = (window, scene, request);
        None
    }

    /// The frame last presented by [`Backend::present`], drawn again into a texture and read
    /// back: what the window shows. `None` when nothing was presented since the last
    /// [`Backend::release_window`].
    ///
    /// # Errors
    /// A [`ViewerError::Render`] when it cannot be read back.
    fn presented_image(&mut self) -> Option<Result<Image, ViewerError>> {
        None
    }

    /// Lets go of the window: drops the surface [`Backend::present`] made for it (and the frame
    /// presented). The shell calls it when another way of drawing takes over the window.
    fn release_window(&mut self) {}
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

/// Whether this build has the GPU renderer (the `gpu` feature; the students' copy leaves it out
/// by default, docs/performance.md §3).
pub const GPU_BUILT: bool = cfg!(feature = "gpu");

/// Why there is no GPU backend. Each build makes one of the two; the other is matched only.
enum NoGpu {
    /// This build has no GPU renderer (no `gpu` feature).
    #[cfg_attr(feature = "gpu", allow(dead_code, reason = "made by builds without `gpu`"))]
    NotBuilt,
    /// It has one, but it found no adapter or device: the message, in the user's language.
    #[cfg_attr(not(feature = "gpu"), allow(dead_code, reason = "made by builds with `gpu`"))]
    Unavailable(String),
}

/// The seam: the GPU as a backend, and whether it is real hardware (else software, such as
/// Mesa's lavapipe).
#[cfg(feature = "gpu")]
fn open_gpu(lang: Lang) -> Result<(Box<dyn Backend>, bool), NoGpu> {
    let gpu = GpuBackend::new(lang).map_err(NoGpu::Unavailable)?;
    let hardware = gpu.is_hardware();
    Ok((Box::new(gpu), hardware))
}

/// The seam, in a build without the GPU renderer.
#[cfg(not(feature = "gpu"))]
fn open_gpu(_lang: Lang) -> Result<(Box<dyn Backend>, bool), NoGpu> {
    Err(NoGpu::NotBuilt)
}

/// What to say when the GPU renderer was asked for in a build without it: that this copy was
/// built without it, and `command`, which builds it and runs the same thing again
/// ([`cg_harness::args::rerun_with_features`]).
#[must_use]
pub fn gpu_left_out(command: &str) -> Text {
    Text::new(
        format!(
            "このキットは GPU レンダラ（wgpu）なしでビルドされています（学生用のコピーでは、最初のビルドを速くするため既定で含めません。演習はすべて CPU でできます）。GPU レンダラを含めてビルドし、同じことを実行するには: {command}"
        ),
        format!(
            "this copy of the kit was built without the GPU renderer (wgpu): the students' copy leaves it out by default so that its first build is faster, and every part of the course runs on the CPU. To build it with the GPU renderer and run the same again: {command}"
        ),
    )
}

/// The renderers a viewer gets: the GPU first when it is real hardware, else the CPU rasterizer
/// first with the software GPU as the second (`r` switches); the CPU alone without an adapter
/// (and a note saying why) or in a build without the GPU renderer (the `r` key says so).
#[must_use]
pub fn default_backends(threads: Option<usize>, lang: Lang) -> Vec<Box<dyn Backend>> {
    let cpu: Box<dyn Backend> = Box::new(CpuBackend { threads, lang });
    match open_gpu(lang) {
        Ok((gpu, true)) => vec![gpu, cpu],
        Ok((gpu, false)) => vec![cpu, gpu],
        Err(NoGpu::Unavailable(why)) => {
            eprintln!("{} {why}", t("GPU は使えません:", "no GPU:").get(lang));
            vec![cpu]
        }
        Err(NoGpu::NotBuilt) => vec![cpu],
    }
}

/// Which renderer draws first (`cg-viewer --renderer`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum RendererChoice {
    /// The GPU first when it is real hardware, else the CPU ([`default_backends`]).
    #[default]
    Auto,
    /// The CPU rasterizer first (the GPU second when there is one).
    Cpu,
    /// The GPU first (the CPU second); an error when there is no GPU adapter.
    Gpu,
}

impl RendererChoice {
    /// `"auto"`, `"cpu"` or `"gpu"` (any case).
    ///
    /// # Errors
    /// Another word, with the three that are understood.
    pub fn parse(s: &str) -> Result<RendererChoice, String> {
        match s.to_ascii_lowercase().as_str() {
            "auto" => Ok(RendererChoice::Auto),
            "cpu" => Ok(RendererChoice::Cpu),
            "gpu" => Ok(RendererChoice::Gpu),
            _ => Err(format!(
                "「{s}」はレンダラではありません（auto, cpu, gpu のどれか） / '{s}' is not a renderer: auto, cpu or gpu"
            )),
        }
    }
}

/// The renderers for `choice`, the one to draw first at the front (`r` switches).
///
/// # Errors
/// [`RendererChoice::Gpu`] without a GPU adapter: a [`ViewerError::Render`] saying why; in a
/// build without the GPU renderer: a [`ViewerError::LeftOut`] with the command that builds it.
pub fn backends_for(
    choice: RendererChoice,
    threads: Option<usize>,
    lang: Lang,
) -> Result<Vec<Box<dyn Backend>>, ViewerError> {
    let cpu: Box<dyn Backend> = Box::new(CpuBackend { threads, lang });
    match choice {
        RendererChoice::Auto => Ok(default_backends(threads, lang)),
        RendererChoice::Cpu => Ok(match open_gpu(lang) {
            Ok((gpu, _)) => vec![cpu, gpu],
            Err(_) => vec![cpu],
        }),
        RendererChoice::Gpu => match open_gpu(lang) {
            Ok((gpu, _)) => Ok(vec![gpu, cpu]),
            Err(NoGpu::Unavailable(why)) => Err(ViewerError::Render(format!(
                "{} {why}",
                t("GPU が指定されましたが使えません:", "the GPU was asked for, but").get(lang)
            ))),
            Err(NoGpu::NotBuilt) => {
                let command = cg_harness::args::rerun_with_features("gpu");
                Err(ViewerError::LeftOut(gpu_left_out(&command)))
            }
        },
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
    fn renderer_choices_parse_in_any_case() {
        assert_eq!(RendererChoice::parse("GPU"), Ok(RendererChoice::Gpu));
        assert_eq!(RendererChoice::parse("cpu"), Ok(RendererChoice::Cpu));
        assert_eq!(RendererChoice::parse("auto"), Ok(RendererChoice::Auto));
        let e = RendererChoice::parse("vulkan").unwrap_err();
        assert!(e.contains("auto, cpu or gpu") && e.contains("レンダラではありません"), "{e}");
        let cpu = backends_for(RendererChoice::Cpu, Some(1), Lang::En).unwrap();
        assert_eq!(cpu[0].name(), "CPU");
    }

    /// A build without the GPU renderer: the window draws with the CPU alone, and asking for
    /// the GPU names the build and the command that builds it, in the user's language.
    #[cfg(not(feature = "gpu"))]
    #[test]
    fn without_the_gpu_feature_the_cpu_draws_and_asking_for_the_gpu_says_how_to_build_it() {
        let backends = default_backends(Some(1), Lang::En);
        assert_eq!(backends.iter().map(|b| b.name()).collect::<Vec<_>>(), ["CPU"]);
        let Err(e) = backends_for(RendererChoice::Gpu, Some(1), Lang::En) else {
            panic!("the GPU was asked for in a build without it");
        };
        // (The program here is the test harness: tests/viewer.rs checks the whole command.)
        let command = cg_harness::args::rerun_with_features("gpu");
        let en = e.message(Lang::En);
        assert!(en.contains("built without the GPU renderer") && en.contains(&command), "{en}");
        let ja = e.message(Lang::Ja);
        assert!(ja.contains("GPU レンダラ（wgpu）なしでビルド") && ja.contains(&command), "{ja}");
    }
}
