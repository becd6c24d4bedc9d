//! Assignment `a4` — テクスチャマッピング (texture mapping).
//!
//! 「指定された通りに、あらかじめ用意されている画像を読み込み、その一部を、地面にマッピングする。
//! レポートには、テクスチャ座標の範囲や計算方法を示すこと。」 Each student gets a region of the
//! [prepared image](prepared_image) (a rectangle of its named cells), an orientation (turned by
//! quarter turns, perhaps mirrored) and a repeat count, and writes:
//!
//! | task | function (`exercises/src/a4.rs`) | what |
//! |---|---|---|
//! | `a4.t1` | `tex_range(spec) -> TexRange` | the region's texture-coordinate range |
//! | `a4.t2` | `tex_coords(spec, i, j) -> [Vec2; 4]` | the coordinates of the corners of ground square `(i, j)` |
//! | `a4.t3` | `sampler() -> Sampler` | filter and wrap modes |
//!
//! ## Conventions
//!
//! | what | convention |
//! |---|---|
//! | texture coordinates | `(s, t) = (0, 0)` is the image's bottom-left corner, `(1, 1)` its top-right (OpenGL, [`cg_core::texture`]) |
//! | cells | spreadsheet names: columns `A`–`H` left to right, rows `1`–`8` **top to bottom**; pixels from the top-left corner |
//! | ground | the course's 10 × 10 squares: vertex `(i, j)`, `i, j = 0…10`, at `(i·1 − 5, 0, j·1 − 5)`; square `(i, j)` has the corners `(i, j), (i, j+1), (i+1, j+1), (i+1, j)` ([`CORNER_STEPS`]), the triangles of [`cg_core::shapes::grid`] |
//! | orientation | as the course's camera sees the ground (from +z, above): screen right = +x (i grows), screen up = −z (j shrinks); turns counter-clockwise as seen from there; a mirror is left–right, before the turn |
//! | repeat | by the coordinates: `repeat × repeat` blocks of `10 / repeat` squares, each showing the whole region; the vertices on a block's edge belong to two blocks and so to two coordinates. GL_REPEAT cannot do this (it repeats the *whole* image), so the wrap mode is GL_CLAMP_TO_EDGE |
//!
//! Every assignment crate has the same shape (the command line and the tests rely on it):
//! [`ID`], a per-student [`Spec`] drawn by [`variant`] and described by [`Spec::describe`], the
//! exercise API [`Impl`], [`checks`] and [`view`].

mod checks;
mod prepared;
mod spec;
mod view;

use cg_core::glam::Vec2;
use cg_core::texture::Sampler;
use serde::Serialize;

pub use checks::checks;
pub use prepared::{
    CELL_PIXELS, CELLS, FRAME_COLOR, IMAGE_PIXELS, INK_COLOR, cell_color, cell_name, column_name,
    prepared_image,
};
pub use spec::{CORNER_STEPS, Corner, GroundCorner, Region, Spec, variant};
pub use view::{Coordinates, coordinates, ground_mesh, view};

/// The assignment's ID, the prefix of its task IDs (`a4.t1`, …).
pub const ID: &str = "a4";

/// Squares along each side of the course's ground (10 × 10, one unit each).
pub const SQUARES: u32 = 10;

/// A rectangle in texture coordinates: `s` from `s_min` to `s_max` (left to right), `t` from
/// `t_min` to `t_max` (bottom to top). `(0, 0)` is the image's bottom-left corner.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
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
