//! Images that renderers draw into (フレームバッファ): linear RGB in `[0, 1]` per pixel, row 0 at
//! the *top* (the order PNG files and screens use), converted to 8 bits the way OpenGL converts a
//! colour for an 8-bit framebuffer: clamp to `[0, 1]`, multiply by 255, round to nearest.

use crate::Rgb;
use crate::lang::{Lang, Text};

/// The largest image side the kit renders, in pixels: the rasterizer's fixed-point window
/// coordinates (8 sub-pixel bits with a ±2²⁰-pixel guard band) and OSMesa (`OSMESA_MAX_WIDTH`)
/// both stop there. Every renderer, `cg-glref` and the scene loader use this one constant.
pub const MAX_SIDE: u32 = 16_384;

/// The most pixels one image may have: 64 M (8192 × 8192). A renderer holds the colour buffer
/// (12 bytes a pixel), a depth buffer (4) and an 8-bit copy to write (4), so this bounds a
/// render's image memory to about 1.3 GB — a 16384 × 16384 image would need 5 GB.
pub const MAX_PIXELS: u64 = 64 * 1024 * 1024;

/// Why an image size cannot be rendered.
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub enum SizeError {
    /// A side of zero pixels.
    #[error("the image size {width}×{height} has no pixels: width and height must be at least 1")]
    ZeroSize {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// A side longer than [`MAX_SIDE`].
    #[error("the image size {width}×{height} is too large: each side can be at most {MAX_SIDE}")]
    TooLarge {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
    /// More than [`MAX_PIXELS`] pixels in all.
    #[error(
        "the image size {width}×{height} has too many pixels: at most {MAX_PIXELS} (8192×8192) in all"
    )]
    TooManyPixels {
        /// The width asked for.
        width: u32,
        /// The height asked for.
        height: u32,
    },
}

impl SizeError {
    /// The message for a student in `lang` (the English one is also the `Display`).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let ja = match *self {
            SizeError::ZeroSize { width, height } => format!(
                "画像の大きさ {width}×{height} にはピクセルがありません。幅と高さは 1 以上にしてください"
            ),
            SizeError::TooLarge { width, height } => format!(
                "画像の大きさ {width}×{height} は大きすぎます。幅と高さは {MAX_SIDE} 以下にしてください"
            ),
            SizeError::TooManyPixels { width, height } => format!(
                "画像の大きさ {width}×{height} はピクセルが多すぎます。ピクセル数は全部で {MAX_PIXELS}（8192×8192）以下にしてください"
            ),
        };
        Text::new(ja, self.to_string())
    }
}

/// Checks that a `width × height` image can be rendered: both sides at least 1 and at most
/// [`MAX_SIDE`], and at most [`MAX_PIXELS`] pixels in all (checked in that order).
///
/// # Errors
/// The first rule broken, as a [`SizeError`].
pub fn check_size(width: u32, height: u32) -> Result<(), SizeError> {
    if width == 0 || height == 0 {
        return Err(SizeError::ZeroSize { width, height });
    }
    if width > MAX_SIDE || height > MAX_SIDE {
        return Err(SizeError::TooLarge { width, height });
    }
    if u64::from(width) * u64::from(height) > MAX_PIXELS {
        return Err(SizeError::TooManyPixels { width, height });
    }
    Ok(())
}

/// An RGB image, row 0 at the top. Pixel `(x, y)` is `pixels[y·width + x]`; its centre is at
/// `(x + ½, y + ½)` in window coordinates measured from the top-left corner.
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width × height` colours, row by row from the top.
    pub pixels: Vec<Rgb>,
}

impl Image {
    /// An image filled with one colour (glClearColor + glClear).
    #[must_use]
    pub fn new(width: u32, height: u32, fill: Rgb) -> Image {
        Image { width, height, pixels: vec![fill; width as usize * height as usize] }
    }

    /// The colour at `(x, y)`, `None` outside the image.
    #[must_use]
    pub fn get(&self, x: u32, y: u32) -> Option<Rgb> {
        (x < self.width && y < self.height).then(|| self.pixels[self.index(x, y)])
    }

    /// Sets the colour at `(x, y)`; does nothing outside the image.
    pub fn set(&mut self, x: u32, y: u32, color: Rgb) {
        if x < self.width && y < self.height {
            let i = self.index(x, y);
            self.pixels[i] = color;
        }
    }

    fn index(&self, x: u32, y: u32) -> usize {
        y as usize * self.width as usize + x as usize
    }

    /// The image as RGBA8, row 0 at the top, alpha 255 (see [`to_unorm8`]).
    #[must_use]
    pub fn to_rgba8(&self) -> Vec<[u8; 4]> {
        self.pixels.iter().map(|c| [to_unorm8(c.x), to_unorm8(c.y), to_unorm8(c.z), 255]).collect()
    }

    /// An image from RGBA8 pixels, row 0 at the top (alpha is dropped).
    ///
    /// Returns `None` when `pixels.len() != width · height`.
    #[must_use]
    pub fn from_rgba8(width: u32, height: u32, pixels: &[[u8; 4]]) -> Option<Image> {
        (pixels.len() == width as usize * height as usize).then(|| Image {
            width,
            height,
            pixels: pixels
                .iter()
                .map(|p| Rgb::new(p[0] as f32, p[1] as f32, p[2] as f32) / 255.0)
                .collect(),
        })
    }
}

/// One colour channel to 8 bits as OpenGL writes it to an 8-bit framebuffer: clamp to `[0, 1]`,
/// then `round(c · 255)`. NaN becomes 0.
#[must_use]
#[inline]
pub fn to_unorm8(c: f32) -> u8 {
    if c.is_nan() {
        return 0;
    }
    // In [0, 255] after the clamp, so the cast is exact.
    (c.clamp(0.0, 1.0) * 255.0).round() as u8
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unorm8_clamps_and_rounds_to_nearest() {
        assert_eq!(to_unorm8(0.0), 0);
        assert_eq!(to_unorm8(1.0), 255);
        assert_eq!(to_unorm8(2.0), 255);
        assert_eq!(to_unorm8(-1.0), 0);
        assert_eq!(to_unorm8(f32::NAN), 0);
        assert_eq!(to_unorm8(0.5), 128, "127.5 rounds half away from zero");
        assert_eq!(to_unorm8(127.4 / 255.0), 127);
        assert_eq!(to_unorm8(127.6 / 255.0), 128);
    }

    #[test]
    fn sizes_are_checked_side_first_then_pixel_count() {
        assert_eq!(check_size(1, 1), Ok(()));
        assert_eq!(check_size(MAX_SIDE, 4096), Ok(()), "exactly 64 M pixels");
        assert_eq!(check_size(0, 5), Err(SizeError::ZeroSize { width: 0, height: 5 }));
        assert_eq!(
            check_size(MAX_SIDE + 1, 1),
            Err(SizeError::TooLarge { width: MAX_SIDE + 1, height: 1 })
        );
        let e = check_size(MAX_SIDE, 4097).unwrap_err();
        assert_eq!(e, SizeError::TooManyPixels { width: MAX_SIDE, height: 4097 });
        assert!(e.message(Lang::En).contains("16384×4097"), "{}", e.message(Lang::En));
        assert!(e.message(Lang::Ja).contains("ピクセル数"), "{}", e.message(Lang::Ja));
    }

    #[test]
    fn images_round_trip_through_rgba8() {
        let mut img = Image::new(3, 2, Rgb::new(0.5, 0.5, 0.8));
        img.set(2, 1, Rgb::new(1.0, 0.0, 0.2));
        img.set(9, 9, Rgb::ONE);
        let rgba = img.to_rgba8();
        assert_eq!(rgba[5], [255, 0, 51, 255]);
        let back = Image::from_rgba8(3, 2, &rgba).unwrap();
        assert_eq!(back.get(2, 1), Some(Rgb::new(1.0, 0.0, 0.2)));
        assert_eq!(back.get(3, 0), None);
        assert!(Image::from_rgba8(3, 3, &rgba).is_none());
    }
}
