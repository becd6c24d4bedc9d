//! Reading a [`Frame`] back into host memory.
//!
//! The texture a frame is drawn into and the mappable buffer the GPU copies it to are made on
//! the first read-back and kept in the frame for the next ones (a window's screenshots, `cg
//! view`'s panels, a benchmark's frames), as a window keeps its framebuffer; a frame moved to
//! another size by [`Gpu::update_view`] gets new ones on its next read-back. On a real GPU each
//! new texture and buffer is a driver allocation; on lavapipe, fresh pages the system clears.
//! [`Gpu::read_back_into`] also writes into the caller's [`Image`], as the CPU rasterizer's
//! `Prepared::draw_into` does, so a loop of frames allocates nothing.

use std::sync::PoisonError;

use cg_core::Rgb;
use cg_core::image::Image;

use crate::{Frame, Gpu, GpuError, READBACK_FORMAT};

/// A read-back target of one size and format and the buffer it is copied into.
#[derive(Debug)]
pub(crate) struct Readback {
    width: u32,
    height: u32,
    target: wgpu::Texture,
    view: wgpu::TextureView,
    buffer: wgpu::Buffer,
    /// Bytes per row in `buffer`: the row padded to wgpu's copy alignment.
    padded: u32,
}

impl Gpu {
    /// Draws `frame` (made for [`READBACK_FORMAT`], or for `Bgra8Unorm` — a window surface's
    /// usual format, so a window can save the very frame it presented) and reads it back into a
    /// new [`Image`]; see [`Gpu::read_back_into`].
    ///
    /// # Errors
    /// As [`Gpu::read_back_into`].
    pub fn read_back(&self, frame: &Frame) -> Result<Image, GpuError> {
        let mut image = Image { width: 0, height: 0, pixels: Vec::new() };
        self.read_back_into(frame, &mut image)?;
        Ok(image)
    }

    /// Draws `frame` and reads it back into `image`, replacing its size and pixels: the same
    /// image as [`Gpu::read_back`], without allocating when `image` already holds a frame of
    /// this size. The target and buffer are the frame's own, made on its first read-back.
    ///
    /// # Errors
    /// [`GpuError::Wgpu`] for a frame of another format than [`READBACK_FORMAT`] or
    /// `Bgra8Unorm`, or an error wgpu reports (after which the next read-back starts with a new
    /// target and buffer).
    pub fn read_back_into(&self, frame: &Frame, image: &mut Image) -> Result<(), GpuError> {
        let bgra = match frame.format {
            READBACK_FORMAT => false,
            wgpu::TextureFormat::Bgra8Unorm => true,
            other => {
                return Err(GpuError::Wgpu(format!(
                    "read_back needs a frame made for {READBACK_FORMAT:?} or Bgra8Unorm, not \
                     {other:?}"
                )));
            }
        };
        let mut slot = frame.readback.lock().unwrap_or_else(PoisonError::into_inner);
        let size = (frame.width, frame.height);
        let readback = match slot.take() {
            Some(r) if (r.width, r.height) == size => r,
            _ => self.readback_target(frame),
        };
        self.draw_and_copy(frame, &readback, bgra, image)?;
        // Kept only after a read-back that worked: a buffer left mapped, or waiting to be, by an
        // error is dropped with it.
        *slot = Some(readback);
        Ok(())
    }

    /// A new texture `frame` can be drawn into with [`Gpu::render_to_view`] (through a view of
    /// it) and copied from: its size and colour format, a render attachment and a copy source.
    #[must_use]
    pub fn target(&self, frame: &Frame) -> wgpu::Texture {
        self.device.create_texture(&wgpu::TextureDescriptor {
            label: Some("cg-gpu target"),
            size: wgpu::Extent3d {
                width: frame.width,
                height: frame.height,
                depth_or_array_layers: 1,
            },
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: frame.format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        })
    }

    fn readback_target(&self, frame: &Frame) -> Readback {
        let (width, height) = (frame.width, frame.height);
        let target = self.target(frame);
        let view = target.create_view(&wgpu::TextureViewDescriptor::default());
        let padded = (width * 4).div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT)
            * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let buffer = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("cg-gpu readback"),
            size: u64::from(padded) * u64::from(height),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        Readback { width, height, target, view, buffer, padded }
    }

    /// Draws `frame` into `readback`'s target, copies it to the buffer, maps it and unpacks it
    /// into `image`.
    fn draw_and_copy(
        &self,
        frame: &Frame,
        readback: &Readback,
        bgra: bool,
        image: &mut Image,
    ) -> Result<(), GpuError> {
        let wgpu_error = |e: &dyn std::fmt::Display| GpuError::Wgpu(e.to_string());
        let (width, height) = (readback.width, readback.height);
        let scope = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        self.render_to_view(frame, &readback.view);
        let mut encoder = self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("cg-gpu readback"),
        });
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture: &readback.target,
                mip_level: 0,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &readback.buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(readback.padded),
                    rows_per_image: Some(height),
                },
            },
            wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
        );
        self.queue.submit([encoder.finish()]);
        if let Some(e) = pollster::block_on(scope.pop()) {
            return Err(wgpu_error(&e));
        }
        let slice = readback.buffer.slice(..);
        let (sender, receiver) = std::sync::mpsc::channel();
        slice.map_async(wgpu::MapMode::Read, move |r| {
            let _ = sender.send(r);
        });
        self.device.poll(wgpu::PollType::wait_indefinitely()).map_err(|e| wgpu_error(&e))?;
        receiver.recv().map_err(|e| wgpu_error(&e))?.map_err(|e| wgpu_error(&e))?;
        let unpacked = slice.get_mapped_range().map(|data| {
            unpack(&data, readback.padded as usize, width as usize, bgra, &mut image.pixels);
        });
        readback.buffer.unmap();
        unpacked.map_err(|e| wgpu_error(&e))?;
        image.width = width;
        image.height = height;
        Ok(())
    }
}

/// Replaces `out` with the colours of the RGBA8 (or BGRA8) rows in `data`, each `padded` bytes
/// long and holding `width` pixels, alpha dropped: bit for bit [`Image::from_rgba8`]'s
/// `channel / 255`, looked up.
fn unpack(data: &[u8], padded: usize, width: usize, bgra: bool, out: &mut Vec<Rgb>) {
    let unit: [f32; 256] = std::array::from_fn(|i| i as f32 / 255.0);
    out.clear();
    out.reserve(width * (data.len() / padded.max(1)));
    for row in data.chunks(padded) {
        out.extend(row[..width * 4].chunks_exact(4).map(|p| {
            let (r, b) = if bgra { (p[2], p[0]) } else { (p[0], p[2]) };
            Rgb::new(unit[usize::from(r)], unit[usize::from(p[1])], unit[usize::from(b)])
        }));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every byte value, in both channel orders, with padding after each row: the same colours
    /// as [`Image::from_rgba8`], bit for bit, and nothing from the padding.
    #[test]
    fn unpack_is_from_rgba8_bit_for_bit() {
        let (width, height, padded) = (64_usize, 4_usize, 256 + 32);
        let mut data = vec![0xAB_u8; padded * height];
        let mut rgba = Vec::new();
        for y in 0..height {
            for x in 0..width {
                let i = y * width + x;
                let p = [i as u8, (255 - i % 256) as u8, (i * 7 % 256) as u8, 9];
                data[y * padded + x * 4..][..4].copy_from_slice(&p);
                rgba.push(p);
            }
        }
        let expected = Image::from_rgba8(width as u32, height as u32, &rgba).unwrap();
        let mut out = vec![Rgb::ONE; 3];
        unpack(&data, padded, width, false, &mut out);
        assert_eq!(out.len(), width * height);
        let bits = |v: &[Rgb]| v.iter().map(|c| c.to_array().map(f32::to_bits)).collect::<Vec<_>>();
        assert_eq!(bits(&out), bits(&expected.pixels));
        unpack(&data, padded, width, true, &mut out);
        let swapped: Vec<Rgb> = expected.pixels.iter().map(|c| Rgb::new(c.z, c.y, c.x)).collect();
        assert_eq!(bits(&out), bits(&swapped));
    }
}
