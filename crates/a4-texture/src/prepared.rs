//! The prepared image (あらかじめ用意されている画像) of assignment 4, drawn by code so the kit
//! needs no file to check or show it: `assets/textures/a4-prepared.png` is this image, written by
//! `CG_BLESS=1 cargo test -p cg-a4 --test prepared_image` and checked against it by that test.
//!
//! 512 × 512 pixels in 8 × 8 cells of 64 × 64, named like a spreadsheet: columns `A`–`H` from left
//! to right, rows `1`–`8` from **top to bottom** (`A1` is the top-left cell, `H8` the
//! bottom-right one), as an image viewer shows the picture. Each cell has
//!
//! - its own background colour: the hue says the column (A red, B orange, C yellow, D green,
//!   E teal, F blue, G purple, H pink), the strength the row (row 1 palest, row 8 strongest);
//! - a dark frame 2 pixels wide, so cell edges show on the ground;
//! - an arrow (▲) pointing to the image's top, and its name (`C4`) in a 5 × 7 pixel font drawn
//!   4 times larger: mirrored, the two characters swap places and read as mirror writing; upside
//!   down, the arrow points down.
//!
//! In texture coordinates (`(0, 0)` = the image's bottom-left corner, as in OpenGL) the cell in
//! column `c` (A = 0) and row `r` (row 1 = 0, counted from the top) covers
//! `s ∈ [c/8, (c+1)/8]`, `t ∈ [(7−r)/8, (8−r)/8]`.

use cg_core::texture::Texture;

pub use cg_student::a4::CELLS;
/// Pixels (texels) along each side of one cell.
pub const CELL_PIXELS: u32 = 64;
/// Pixels along each side of the prepared image.
pub const IMAGE_PIXELS: u32 = CELLS * CELL_PIXELS;

/// The name of the cell in `column` (0 = `A`, left) and `row` (0 = row `1`, top): `"C4"` for
/// column 2, row 3. Columns past `H` and rows past `8` are named all the same (`"J10"`), so
/// messages about coordinates outside the image can say where they point.
#[must_use]
pub fn cell_name(column: u32, row: u32) -> String {
    format!("{}{}", column_name(column), row + 1)
}

/// The letter of `column` (0 = `A`); columns past `Z` are all `Z`.
#[must_use]
pub fn column_name(column: u32) -> char {
    char::from_u32(u32::from(b'A') + column.min(25)).unwrap_or('Z')
}

/// The hue of each column, A to H: red, orange, yellow, green, teal, blue, purple, pink.
const HUES: [[u32; 3]; CELLS as usize] = [
    [230, 60, 60],
    [240, 150, 40],
    [230, 210, 40],
    [70, 180, 70],
    [40, 180, 180],
    [60, 110, 230],
    [150, 80, 220],
    [230, 90, 180],
];

/// The background colour of a cell: its column's hue mixed with white, `20 + 8·row` percent of
/// the hue (row 0, the top one, palest). Integer arithmetic, so every machine draws the same.
#[must_use]
pub fn cell_color(column: u32, row: u32) -> [u8; 4] {
    let hue = HUES[column.min(CELLS - 1) as usize];
    let percent = 20 + 8 * row.min(CELLS - 1);
    let mix = |h: u32| ((255 * (100 - percent) + h * percent + 50) / 100) as u8;
    [mix(hue[0]), mix(hue[1]), mix(hue[2]), 255]
}

/// The frame around each cell.
pub const FRAME_COLOR: [u8; 4] = [70, 70, 70, 255];
/// The arrow and the name.
pub const INK_COLOR: [u8; 4] = [20, 20, 20, 255];
/// The frame's width in pixels.
const FRAME: u32 = 2;
/// Glyph pixels are drawn as `SCALE × SCALE` squares.
const SCALE: u32 = 4;

/// A 5 × 7 glyph, top row first, `#` = ink.
type Glyph = [&'static str; 7];

/// The glyphs the names need: `A`–`H`, `1`–`8`.
fn glyph(c: char) -> Option<Glyph> {
    Some(match c {
        'A' => [".###.", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"],
        'B' => ["####.", "#...#", "#...#", "####.", "#...#", "#...#", "####."],
        'C' => [".###.", "#...#", "#....", "#....", "#....", "#...#", ".###."],
        'D' => ["####.", "#...#", "#...#", "#...#", "#...#", "#...#", "####."],
        'E' => ["#####", "#....", "#....", "####.", "#....", "#....", "#####"],
        'F' => ["#####", "#....", "#....", "####.", "#....", "#....", "#...."],
        'G' => [".###.", "#...#", "#....", "#.###", "#...#", "#...#", ".###."],
        'H' => ["#...#", "#...#", "#...#", "#####", "#...#", "#...#", "#...#"],
        '1' => ["..#..", ".##..", "..#..", "..#..", "..#..", "..#..", ".###."],
        '2' => [".###.", "#...#", "....#", "...#.", "..#..", ".#...", "#####"],
        '3' => ["#####", "...#.", "..#..", "...#.", "....#", "#...#", ".###."],
        '4' => ["...#.", "..##.", ".#.#.", "#..#.", "#####", "...#.", "...#."],
        '5' => ["#####", "#....", "####.", "....#", "....#", "#...#", ".###."],
        '6' => ["..##.", ".#...", "#....", "####.", "#...#", "#...#", ".###."],
        '7' => ["#####", "....#", "...#.", "..#..", ".#...", ".#...", ".#..."],
        '8' => [".###.", "#...#", "#...#", ".###.", "#...#", "#...#", ".###."],
        _ => return None,
    })
}

/// Where the parts of a cell are, in pixels from the cell's *top-left* corner (x right, y down).
mod layout {
    use super::SCALE;
    /// The arrow's tip row; row `k` below it spans columns `31 − k ..= 32 + k`.
    pub const ARROW_TOP: u32 = 5;
    /// Rows of the arrow's head.
    pub const ARROW_HEAD: u32 = 10;
    /// The stem below the head: rows `ARROW_TOP + ARROW_HEAD ..` this many, columns 30–33.
    pub const ARROW_STEM: u32 = 5;
    /// The name's top row.
    pub const TEXT_TOP: u32 = 24;
    /// The first glyph's left column; the second starts `5·SCALE + SCALE` further right.
    pub const TEXT_LEFT: u32 = 10;
    /// The distance from one glyph's left column to the next one's.
    pub const ADVANCE: u32 = 6 * SCALE;
}

/// Whether the pixel at `(x, y)` of a cell (from its top-left corner) is ink of its name `name`.
fn is_name_ink(name: &str, x: u32, y: u32) -> bool {
    use layout::{ADVANCE, TEXT_LEFT, TEXT_TOP};
    let (Some(dx), Some(dy)) = (x.checked_sub(TEXT_LEFT), y.checked_sub(TEXT_TOP)) else {
        return false;
    };
    let (k, gx, gy) = (dx / ADVANCE, (dx % ADVANCE) / SCALE, dy / SCALE);
    let Some(g) = name.chars().nth(k as usize).and_then(glyph) else {
        return false;
    };
    g.get(gy as usize).and_then(|row| row.as_bytes().get(gx as usize)) == Some(&b'#')
}

/// Whether the pixel at `(x, y)` of a cell (from its top-left corner) is part of the arrow.
fn is_arrow(x: u32, y: u32) -> bool {
    use layout::{ARROW_HEAD, ARROW_STEM, ARROW_TOP};
    let Some(k) = y.checked_sub(ARROW_TOP) else {
        return false;
    };
    if k < ARROW_HEAD {
        (31 - k..=32 + k).contains(&x)
    } else {
        k < ARROW_HEAD + ARROW_STEM && (30..=33).contains(&x)
    }
}

/// The colour of pixel `(x, y)` of the image, measured from its *top-left* corner.
fn pixel(x: u32, y: u32) -> [u8; 4] {
    let (column, row) = (x / CELL_PIXELS, y / CELL_PIXELS);
    let (cx, cy) = (x % CELL_PIXELS, y % CELL_PIXELS);
    let last = CELL_PIXELS - FRAME;
    if cx < FRAME || cy < FRAME || cx >= last || cy >= last {
        FRAME_COLOR
    } else if is_arrow(cx, cy) || is_name_ink(&cell_name(column, row), cx, cy) {
        INK_COLOR
    } else {
        cell_color(column, row)
    }
}

/// The prepared image as a texture (row 0 = the image's bottom row, so `(s, t) = (0, 0)` is its
/// bottom-left corner, the bottom-left of cell `A8`). Deterministic: the same texels on every
/// machine.
#[must_use]
pub fn prepared_image() -> Texture {
    let texels = (0..IMAGE_PIXELS)
        .flat_map(|y| (0..IMAGE_PIXELS).map(move |x| (x, y)))
        .map(|(x, y)| pixel(x, IMAGE_PIXELS - 1 - y))
        .collect();
    Texture { width: IMAGE_PIXELS, height: IMAGE_PIXELS, texels }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Texel of the image at `(x, y)` measured from the top-left corner.
    fn at(image: &Texture, x: u32, y: u32) -> [u8; 4] {
        image.texel(x, IMAGE_PIXELS - 1 - y)
    }

    #[test]
    fn names_follow_the_spreadsheet() {
        assert_eq!(cell_name(0, 0), "A1");
        assert_eq!(cell_name(2, 3), "C4");
        assert_eq!(cell_name(7, 7), "H8");
    }

    #[test]
    fn every_cell_has_its_own_colour_readable_under_black_ink() {
        let mut seen = std::collections::HashSet::new();
        for c in 0..CELLS {
            for r in 0..CELLS {
                let color = cell_color(c, r);
                assert!(seen.insert(color), "{} repeats a colour", cell_name(c, r));
                // Relative luminance (ITU-R BT.709 weights on the 8-bit values) well above the ink's.
                let [red, green, blue, _] = color.map(f32::from);
                let luma = 0.2126 * red + 0.7152 * green + 0.0722 * blue;
                assert!(luma > 100.0, "{}: luminance {luma}", cell_name(c, r));
            }
        }
    }

    #[test]
    fn the_top_left_cell_is_a1_and_the_image_is_drawn_top_row_first() {
        let image = prepared_image();
        assert_eq!((image.width, image.height, image.texels.len()), (512, 512, 512 * 512));
        // A background pixel of each corner cell (right of the name, above the frame).
        assert_eq!(at(&image, 58, 58), cell_color(0, 0), "A1 at the top left");
        assert_eq!(at(&image, 512 - 6, 58), cell_color(7, 0), "H1 at the top right");
        assert_eq!(at(&image, 58, 512 - 6), cell_color(0, 7), "A8 at the bottom left");
        // Texture coordinate (0, 0) is the bottom-left corner: cell A8's frame.
        assert_eq!(image.texel(0, 0), FRAME_COLOR);
        assert_eq!(image.texel(5, 5), cell_color(0, 7));
    }

    #[test]
    fn the_arrow_points_up_and_the_names_are_not_mirror_symmetric() {
        let image = prepared_image();
        for c in 0..CELLS {
            for r in 0..CELLS {
                let (x0, y0) = (c * CELL_PIXELS, r * CELL_PIXELS);
                let ink = |x: u32, y: u32| at(&image, x0 + x, y0 + y) == INK_COLOR;
                // The arrow: one pixel pair wide at its tip, wider below, ink nowhere above it.
                let width = |y: u32| (0..CELL_PIXELS).filter(|&x| ink(x, y)).count();
                assert_eq!(width(layout::ARROW_TOP), 2, "{}", cell_name(c, r));
                assert!(width(layout::ARROW_TOP + 9) > 10, "{}", cell_name(c, r));
                assert_eq!(width(layout::ARROW_TOP - 1), 0, "{}", cell_name(c, r));
                // The name's block reads differently mirrored left-right and upside down.
                let block: Vec<Vec<bool>> = (layout::TEXT_TOP..layout::TEXT_TOP + 7 * SCALE)
                    .map(|y| (10..54).map(|x| ink(x, y)).collect())
                    .collect();
                let mirrored: Vec<Vec<bool>> =
                    block.iter().map(|row| row.iter().rev().copied().collect()).collect();
                assert!(block.iter().flatten().filter(|&&b| b).count() > 100);
                assert_ne!(block, mirrored, "{} reads the same mirrored", cell_name(c, r));
                // Upside down, the whole cell differs (names such as B8 are symmetric top to
                // bottom in a 5 × 7 font; the arrow is not).
                let cell: Vec<Vec<bool>> = (FRAME..CELL_PIXELS - FRAME)
                    .map(|y| (FRAME..CELL_PIXELS - FRAME).map(|x| ink(x, y)).collect())
                    .collect();
                let upside_down: Vec<Vec<bool>> = cell.iter().rev().cloned().collect();
                assert_ne!(cell, upside_down, "{} reads the same upside down", cell_name(c, r));
            }
        }
    }
}
