//! # 課題 4: テクスチャマッピング / Assignment 4: texture mapping
//!
//! 用意された画像（`assets/textures/a4-prepared.png`、512 × 512 ピクセル、8 × 8 のマス）の一部を、
//! 授業の地面（10 × 10 の四角形）に貼ります。どの範囲を、どの向きで、何回繰り返すかは学生番号ごと
//! に違います: `cargo run --release -- assignment --only a4` で表示されます。
//!
//! Map a part of the prepared image (`assets/textures/a4-prepared.png`, 512 × 512 pixels in 8 × 8
//! cells) onto the course's ground (10 × 10 squares). Which region, turned which way and repeated
//! how often is your own: `cargo run --release -- assignment --only a4` prints it.
//!
//! | | |
//! |---|---|
//! | テクスチャ座標 / texture coordinates | `(s, t) = (0, 0)` は画像の**左下**、`(1, 1)` は右上 / the image's **bottom-left** corner, `(1, 1)` its top-right (OpenGL) |
//! | マス / cells | 列 `A`–`H` は左から右、行 `1`–`8` は**上から下** / columns `A`–`H` left to right, rows `1`–`8` **top to bottom** |
//! | 地面 / ground | 頂点 `(i, j)`（`i, j = 0…10`）は `(i*1 - 5, 0, j*1 - 5)`。カメラは +z 側の上から見る / vertex `(i, j)` at `(i*1 - 5, 0, j*1 - 5)`; the camera looks from +z, above |
//! | 四角形 / square `(i, j)` | 頂点 `(i, j), (i, j+1), (i+1, j+1), (i+1, j)` の順に描く / drawn through `(i, j), (i, j+1), (i+1, j+1), (i+1, j)` |
//!
//! Check: `cargo run --release -- check a4`; look: `cargo run --release -- view a4` (PNG under
//! `out/`).

use cg_student::a4::{Impl, Sampler, Spec, TexRange};
use cg_student::glam::Vec2;
// BEGIN SOLUTION
use cg_student::a4::{Filter, Wrap};
// END SOLUTION

/// **a4.t1** — the texture-coordinate range of your region (テクスチャ座標の範囲).
///
/// Input: `spec.region`, your rectangle of cells: `column` (0 = `A`, the left one), `row` (0 =
/// row `1`, the **top** one), `columns` and `rows` (how many). Output: the range in texture
/// coordinates, `s_min ≤ s ≤ s_max` (left to right), `t_min ≤ t ≤ t_max` (bottom to top), each
/// in `[0, 1]`. The answers are multiples of 1/8; they are checked within 1e-6.
///
/// Hint: the image has `cg_student::a4::CELLS` = 8 columns and rows, so one cell is 1/8 wide
/// and high. `s` counts from the left like the columns, but `t` counts from the **bottom** while
/// the rows count from the top: row 1 is `t = 7/8 … 1`.
///
/// 入力: `spec.region`（マスの長方形。`column` は列の番号で 0 が `A`、`row` は行の番号で 0 が一番**上**の
/// 行 `1`、`columns`・`rows` はその数）。出力: テクスチャ座標での範囲（`s` は左から右、`t` は下から上、
/// どれも 0〜1）。ヒント: 1 マスの幅は 1/8。`t` は**下**から数えるが、行は上から数える（行 1 は
/// `t = 7/8〜1`）。
#[must_use]
pub fn tex_range(spec: &Spec) -> TexRange {
    // BEGIN SOLUTION
    let r = &spec.region;
    let cells = cg_student::a4::CELLS;
    let size = cells as f32;
    TexRange {
        s_min: r.column as f32 / size,
        s_max: (r.column + r.columns) as f32 / size,
        // Rows count from the top; t counts from the bottom.
        t_min: (cells - (r.row + r.rows)) as f32 / size,
        t_max: (cells - r.row) as f32 / size,
    }
    // END SOLUTION
    // BEGIN STUB
    // todo!(
    //     "a4.t1: 自分の領域のテクスチャ座標の範囲を返す / the texture-coordinate range of your region"
    // )
    // END STUB
}

/// **a4.t2** — the texture coordinates of the four corners of ground square `(i, j)`
/// (四角形 (i, j) の頂点のテクスチャ座標).
///
/// Input: your `spec` and the square `(i, j)`, `i, j = 0…9` (the course draws the ground with
/// two loops over `i` and `j`). Output: the texture coordinates `(s, t)` of its corners in
/// drawing order: vertex `(i, j)`, `(i, j+1)`, `(i+1, j+1)`, `(i+1, j)` — at `(i − 5, 0, j − 5)`,
/// `(i − 5, 0, j + 1 − 5)`, … Checked within 1e-5.
///
/// What is checked: the ground's four corners get the region's corners as your assignment's
/// table says; with `spec.repeat = n`, every block of `10 / n` × `10 / n` squares covers exactly
/// the region; squares of one block that share a vertex give it the same coordinate; inside a
/// block the coordinates are one linear formula in `i` and `j`; the region is turned
/// (`spec.rotation_deg`, counter-clockwise as the camera sees it) and mirrored (`spec.mirrored`)
/// as asked.
///
/// Hint: first write down the region's corners (from [`tex_range`]) and, from your assignment's
/// table, which ground corner each lands on. Then, for a corner `(a, b)` of the block
/// (`a = i % k`, or `i % k + 1` for the far corner, with `k = 10 / n`), `a as f32 / k as f32` goes
/// from 0 to 1 across the block; with no turn the region's left-to-right follows `i`, and its
/// bottom-to-top follows `j` *backwards* (the camera looks from +z). Compute `a` and `b` before
/// converting to `f32`, but divide only after converting (`i / 10` is 0 for every `i < 10` in
/// integers).
///
/// 入力: `spec` と四角形 `(i, j)`（`i, j = 0〜9`）。出力: 4 頂点 `(i, j)`, `(i, j+1)`, `(i+1, j+1)`,
/// `(i+1, j)` のテクスチャ座標（この順）。ヒント: まず範囲の 4 隅の座標と、それが地面のどの隅に
/// 来るか（課題の表）を書き出す。繰り返しが `n` なら 1 つのまとまりは `k = 10 / n` 個の四角形で、
/// まとまりの中の位置は `i % k`（右・奥の頂点は `i % k + 1`）。回さないときは、範囲の左→右が `i`
/// の向き、下→上が `j` の**逆**向き（カメラは +z 側から見る）。整数のまま割らない（`i / 10` は 0）。
#[must_use]
pub fn tex_coords(spec: &Spec, i: u32, j: u32) -> [Vec2; 4] {
    // BEGIN SOLUTION
    let range = tex_range(spec);
    let k = 10 / spec.repeat; // squares along one side of a block
    let (a, b) = (i % k, j % k); // where the square is inside its block
    let corner = |a: u32, b: u32| {
        // (p, q): how far across the block, 0…1, along i (+x) and along j (+z).
        let p = a as f32 / k as f32;
        let q = b as f32 / k as f32;
        // (x, y): where in the region, 0…1, to its right and to its top. Unturned and
        // unmirrored, the region stands upright in front of the camera: right = +x, top = −z.
        let (x, y) = match spec.rotation_deg {
            90 => (1.0 - q, 1.0 - p),
            180 => (1.0 - p, q),
            270 => (q, p),
            _ => (p, 1.0 - q),
        };
        // The mirror comes before the turn, so it is undone after it.
        let x = if spec.mirrored { 1.0 - x } else { x };
        Vec2::new(
            range.s_min + x * (range.s_max - range.s_min),
            range.t_min + y * (range.t_max - range.t_min),
        )
    };
    [corner(a, b), corner(a, b + 1), corner(a + 1, b + 1), corner(a + 1, b)]
    // END SOLUTION
    // BEGIN STUB
    // todo!(
    //     "a4.t2: 四角形 (i, j) の 4 頂点のテクスチャ座標を返す / the texture coordinates of the corners of square (i, j)"
    // )
    // END STUB
}

/// **a4.t3** — how the texture is sampled (フィルタと折り返し): glTexParameteri's
/// GL_TEXTURE_MIN/MAG_FILTER and GL_TEXTURE_WRAP_S/T.
///
/// Output: a `Sampler { filter, wrap_u, wrap_v }` (`cg_student::a4::{Filter, Wrap}`):
/// `Filter::Nearest` (GL_NEAREST) or `Filter::Bilinear` (GL_LINEAR) — your choice, say why in the
/// report — and the wrap modes along `s` (`wrap_u`) and `t` (`wrap_v`), `Wrap::Repeat`
/// (GL_REPEAT) or `Wrap::Clamp` (GL_CLAMP_TO_EDGE), which are checked.
///
/// Hint: what does GL_REPEAT repeat — the whole image, or a part of it? Your coordinates from
/// [`tex_coords`] already repeat the region and stay inside `[0, 1]`; think about what happens
/// where they reach exactly 0 or 1.
///
/// 出力: `Sampler { filter, wrap_u, wrap_v }`。フィルタは GL_NEAREST か GL_LINEAR（理由をレポートに）、
/// 折り返しは GL_REPEAT か GL_CLAMP_TO_EDGE。ヒント: GL_REPEAT が繰り返すのは画像全体か、その一部か。
/// `tex_coords` の座標はすでに範囲を繰り返していて 0〜1 に収まる。座標がちょうど 0 や 1 のところで
/// 何が起きるかを考える。
#[must_use]
pub fn sampler() -> Sampler {
    // BEGIN SOLUTION
    Sampler { filter: Filter::Bilinear, wrap_u: Wrap::Clamp, wrap_v: Wrap::Clamp }
    // END SOLUTION
    // BEGIN STUB
    // todo!("a4.t3: フィルタと折り返しを返す / the filter and the wrap modes")
    // END STUB
}

/// The functions of this module, for the checks and the view.
#[must_use]
pub fn implementation() -> Impl {
    Impl { tex_range, tex_coords, sampler }
}
