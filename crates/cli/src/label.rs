//! Labels on the pictures `cg` puts side by side: a few ASCII words in font8x8's public-domain
//! 8 × 8 font, scaled by whole pixels, and a row of pictures with a label under each.

use cg_core::Rgb;
use cg_core::image::Image;

/// The height of a label strip under a picture, in pixels, for text `scale` times 8 pixels high.
#[must_use]
pub fn strip_height(scale: u32) -> u32 {
    8 * scale + 8
}

/// Draws `text` (ASCII; anything else is left blank) with its top-left corner at `(x, y)`, each
/// font pixel `scale` × `scale` image pixels. Pixels outside the image are skipped.
pub fn draw_text(image: &mut Image, x: u32, y: u32, text: &str, scale: u32, color: Rgb) {
    for (k, c) in text.chars().enumerate() {
        let Some(rows) = font8x8::legacy::BASIC_LEGACY.get(c as usize) else { continue };
        let left = x + k as u32 * 8 * scale;
        for (row, bits) in rows.iter().enumerate() {
            for col in 0..8 {
                if bits >> col & 1 == 1 {
                    for dy in 0..scale {
                        for dx in 0..scale {
                            image.set(left + col * scale + dx, y + row as u32 * scale + dy, color);
                        }
                    }
                }
            }
        }
    }
}

/// The width of `text` drawn at `scale`, in pixels.
#[must_use]
pub fn text_width(text: &str, scale: u32) -> u32 {
    text.chars().count() as u32 * 8 * scale
}

/// The pictures side by side (all of one size), each with its label centred in a dark strip
/// under it.
///
/// # Panics
/// When the pictures differ in size (the caller draws them alike).
#[must_use]
pub fn labelled_row(pictures: &[(&Image, &str)], scale: u32) -> Image {
    let (w, h) = pictures.first().map_or((0, 0), |(p, _)| (p.width, p.height));
    let strip = strip_height(scale);
    let mut out = Image::new(w * pictures.len() as u32, h + strip, Rgb::splat(0.15));
    for (i, (picture, label)) in pictures.iter().enumerate() {
        assert_eq!((picture.width, picture.height), (w, h), "pictures of one size");
        let x0 = i as u32 * w;
        for y in 0..h {
            for x in 0..w {
                out.set(x0 + x, y, picture.pixels[(y * w + x) as usize]);
            }
        }
        let tx = x0 + w.saturating_sub(text_width(label, scale)) / 2;
        draw_text(&mut out, tx, h + 4, label, scale, Rgb::ONE);
    }
    out
}

/// Writes each label's word centred at its place (fractions of the width and height from the
/// top-left corner): white with a dark shadow, so it reads on any ground. A label whose text
/// would start off the picture is skipped.
pub fn at_places(image: &mut Image, labels: &[([f32; 2], &str)]) {
    let (w, h) = (image.width, image.height);
    let scale = (w / 320).clamp(1, 4);
    for &([u, v], word) in labels {
        let left = u * w as f32 - text_width(word, scale) as f32 / 2.0;
        let top = v * h as f32;
        if !(0.0..w as f32).contains(&left) || !(0.0..h as f32).contains(&top) {
            continue;
        }
        let (left, top) = (left as u32, top as u32);
        draw_text(image, left + scale, top + scale, word, scale, Rgb::splat(0.05));
        draw_text(image, left, top, word, scale, Rgb::ONE);
    }
}

/// [`labelled_row`]s of at most `columns` pictures, one under the other (a last, shorter row is
/// filled out with the background).
#[must_use]
pub fn labelled_grid(pictures: &[(&Image, &str)], columns: usize, scale: u32) -> Image {
    let rows: Vec<Image> =
        pictures.chunks(columns.max(1)).map(|row| labelled_row(row, scale)).collect();
    let width = rows.iter().map(|r| r.width).max().unwrap_or(0);
    let height = rows.iter().map(|r| r.height).sum();
    let mut out = Image::new(width, height, Rgb::splat(0.15));
    let mut top = 0;
    for row in &rows {
        for y in 0..row.height {
            for x in 0..row.width {
                out.set(x, top + y, row.pixels[(y * row.width + x) as usize]);
            }
        }
        top += row.height;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_is_drawn_where_asked_and_nowhere_else() {
        let mut image = Image::new(40, 20, Rgb::ZERO);
        draw_text(&mut image, 4, 2, "F", 1, Rgb::ONE);
        let ink: Vec<(u32, u32)> = (0..20)
            .flat_map(|y| (0..40).map(move |x| (x, y)))
            .filter(|&(x, y)| image.get(x, y) == Some(Rgb::ONE))
            .collect();
        assert!(!ink.is_empty(), "an F has ink");
        assert!(ink.iter().all(|&(x, y)| (4..12).contains(&x) && (2..10).contains(&y)), "{ink:?}");
        // The F's top bar is a full row of ink; its bottom row is blank (font8x8's F).
        let top_bar = (4..12).filter(|&x| image.get(x, 2) == Some(Rgb::ONE)).count();
        assert!(top_bar >= 6, "{top_bar}");
        // Off the image: no panic, nothing drawn.
        draw_text(&mut image, 38, 18, "PHONG", 3, Rgb::ONE);
    }

    #[test]
    fn a_labelled_row_keeps_each_picture_and_adds_its_label() {
        let red = Image::new(64, 32, Rgb::new(1.0, 0.0, 0.0));
        let blue = Image::new(64, 32, Rgb::new(0.0, 0.0, 1.0));
        let row = labelled_row(&[(&red, "FLAT"), (&blue, "PHONG")], 1);
        assert_eq!((row.width, row.height), (128, 32 + strip_height(1)));
        assert_eq!(row.get(10, 10), Some(Rgb::new(1.0, 0.0, 0.0)));
        assert_eq!(row.get(100, 10), Some(Rgb::new(0.0, 0.0, 1.0)));
        let ink = |x0: u32, x1: u32| {
            (32..row.height).any(|y| (x0..x1).any(|x| row.get(x, y) == Some(Rgb::ONE)))
        };
        assert!(ink(0, 64) && ink(64, 128), "each picture has its label");
    }

    #[test]
    fn labels_are_centred_at_their_places_and_skipped_off_the_picture() {
        let mut image = Image::new(320, 200, Rgb::ZERO);
        at_places(&mut image, &[([0.5, 0.5], "AB"), ([1.2, 0.5], "OFF"), ([0.5, -0.1], "UP")]);
        let white: Vec<(u32, u32)> = (0..200)
            .flat_map(|y| (0..320).map(move |x| (x, y)))
            .filter(|&(x, y)| image.get(x, y) == Some(Rgb::ONE))
            .collect();
        // "AB" is 16 pixels wide at scale 1, centred on x = 160, from y = 100 down.
        assert!(!white.is_empty());
        assert!(white.iter().all(|&(x, y)| (152..168).contains(&x) && (100..108).contains(&y)));
    }
}
