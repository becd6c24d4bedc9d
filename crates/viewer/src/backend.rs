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
