//! Assignment `a4` — テクスチャマッピング (texture mapping): your variant ([`Spec`]: a [`Region`]
//! of the prepared image, an orientation, a repeat count), the range you compute ([`TexRange`]),
//! the sampler you choose ([`Sampler`], [`Filter`], [`Wrap`]) and the three functions you write
//! ([`Impl`]). Plain data: the kit computes the expected ranges and coordinates on its own side,
//! out of your crate's reach.
//!
//! 課題 `a4`（テクスチャマッピング）: あなたの課題（画像の範囲・向き・繰り返し）、テクスチャ座標の範囲、
//! フィルタと折り返しの設定、あなたが書く関数の表。答えを計算する関数はここにはありません。
//!
//! | what | convention |
//! |---|---|
//! | texture coordinates | `(s, t) = (0, 0)` is the image's **bottom-left** corner, `(1, 1)` its top-right (OpenGL) |
//! | cells | spreadsheet names: columns `A`–`H` left to right, rows `1`–`8` **top to bottom** ([`CELLS`] of each) |
//! | ground | [`SQUARES`] × [`SQUARES`] squares: vertex `(i, j)`, `i, j = 0…10`, at `(i·1 − 5, 0, j·1 − 5)`; square `(i, j)` is drawn through its corners in the order of [`CORNER_STEPS`] |

use crate::left_out;
use glam::Vec2;
use serde::{Deserialize, Serialize};

/// Cells along each side of the prepared image (columns `A`–`H`, rows `1`–`8`): one cell is
/// 1/8 of the image wide and high.
pub const CELLS: u32 = 8;

/// Squares along each side of the course's ground (10 × 10, one unit each).
pub const SQUARES: u32 = 10;

/// The corners of square `(i, j)` in drawing order as `(di, dj)` steps from vertex `(i, j)`:
/// `(i, j), (i, j+1), (i+1, j+1), (i+1, j)`, counter-clockwise seen from above; the ground's
/// triangles are `{0, 1, 2}` and `{0, 2, 3}` of these.
pub const CORNER_STEPS: [(u32, u32); 4] = [(0, 0), (0, 1), (1, 1), (1, 0)];

/// A rectangle of cells of the prepared image, counted like a spreadsheet: `column` 0 is `A`
/// (left), `row` 0 is row `1` (**top**).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Region {
    /// The leftmost column (0 = `A`).
    pub column: u32,
    /// The top row (0 = row `1`, the image's top row of cells).
    pub row: u32,
    /// How many columns (≥ 1).
    pub columns: u32,
    /// How many rows (≥ 1).
    pub rows: u32,
}

/// What one student must build: which region of the prepared image goes onto the ground, turned
/// which way, repeated how often. `cargo run --release -- assignment --only a4` prints it, with
/// the table of which corner of the region lands on which corner of the ground.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Spec {
    /// The region of the prepared image (cells, counted from the top-left like a spreadsheet).
    pub region: Region,
    /// How far the region is turned, counter-clockwise as seen from the course's camera (from
    /// above): 0, 90, 180 or 270 degrees. At 0 (unmirrored) the region stands upright in front of
    /// the camera: its top away from the camera (−z), its right to the right (+x).
    pub rotation_deg: u32,
    /// Whether the region is mirrored left to right before it is turned (its names then read
    /// as mirror writing).
    pub mirrored: bool,
    /// How many times the region repeats along each side of the ground (1, 2 or 5): the ground's
    /// 10 × 10 squares form `repeat × repeat` blocks of `10/repeat` squares a side, and each
    /// block shows the whole region the same way.
    pub repeat: u32,
}

/// A rectangle in texture coordinates: `s` from `s_min` to `s_max` (left to right), `t` from
/// `t_min` to `t_max` (bottom to top). `(0, 0)` is the image's bottom-left corner.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TexRange {
    /// The left edge (`s` of the region's left side).
    pub s_min: f32,
    /// The right edge.
    pub s_max: f32,
    /// The bottom edge (`t` of the region's bottom side).
    pub t_min: f32,
    /// The top edge.
    pub t_max: f32,
}

/// How the texture is filtered: GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Filter {
    /// GL_NEAREST: the nearest texel.
    Nearest,
    /// GL_LINEAR: a blend of the four nearest texels (the default).
    #[default]
    Bilinear,
}

/// What happens to texture coordinates outside `[0, 1]`: GL_TEXTURE_WRAP_S / GL_TEXTURE_WRAP_T.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Wrap {
    /// GL_REPEAT: the whole image repeats (OpenGL's default).
    #[default]
    Repeat,
    /// GL_CLAMP_TO_EDGE: the image's edge texels continue.
    Clamp,
}

/// The filter and the wrap modes of the texture (glTexParameteri). `Sampler::default()` stands
/// for OpenGL's defaults: GL_LINEAR (GL_TEXTURE_MAG_FILTER's) and GL_REPEAT.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Sampler {
    /// GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER.
    pub filter: Filter,
    /// GL_TEXTURE_WRAP_S (along `s`).
    pub wrap_u: Wrap,
    /// GL_TEXTURE_WRAP_T (along `t`).
    pub wrap_v: Wrap,
}

/// The functions a student writes (see `exercises/src/a4.rs`).
#[derive(Clone, Copy, Debug)]
pub struct Impl {
    /// `a4.t1`: the region's texture-coordinate range.
    pub tex_range: fn(&Spec) -> TexRange,
    /// `a4.t2`: the texture coordinates of the corners of square `(i, j)` (`i, j = 0…9`), in the
    /// order of [`CORNER_STEPS`].
    pub tex_coords: fn(&Spec, u32, u32) -> [Vec2; 4],
    /// `a4.t3`: the sampler (filter, wrap modes).
    pub sampler: fn() -> Sampler,
}

impl Impl {
    /// For the kit, not for your code: what stands in for `exercises/src/a4.rs` while that file
    /// does not compile, so that the other assignments still build and run. The kit never calls
    /// these functions: it says the file does not compile instead.
    #[must_use]
    pub fn left_out() -> Impl {
        Impl {
            tex_range: |_| left_out("a4"),
            tex_coords: |_, _, _| left_out("a4"),
            sampler: || left_out("a4"),
        }
    }
}
