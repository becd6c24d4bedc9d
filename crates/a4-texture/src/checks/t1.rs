//! `a4.t1`, `tex_range`: the region's s range and t range against the exact oracle
//! ([`RegionOracle::range`]), with the likely mistake named (pixels, the whole image, s and t
//! swapped, rows counted from the top).

use cg_core::notation::decimal;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::Impl;
use crate::prepared::{CELLS, column_name};
use crate::spec::{RegionExt, RegionOracle, Spec};

/// `a4.t1`'s tolerance.
const TOL_RANGE: f32 = 1e-6;

/// Whether two f32 values agree within `tol` (false for NaN).
fn close(a: f32, b: f32, tol: f32) -> bool {
    (a - b).abs() <= tol
}

pub(super) fn s_range(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let got = (imp.tex_range)(spec);
    let want = spec.region.range();
    if close(got.s_min, want.s_min, TOL_RANGE) && close(got.s_max, want.s_max, TOL_RANGE) {
        return Ok(());
    }
    let r = &spec.region;
    let [x0, _, x1, _] = r.pixels();
    let is = |a: f32, b: f32| close(got.s_min, a, TOL_RANGE) && close(got.s_max, b, TOL_RANGE);
    let cause = if is(0.0, 1.0) {
        t("画像全体の範囲になっている", "this is the whole image, not the region")
    } else if is(x0 as f32, x1 as f32) {
        t(
            "ピクセルの値のまま: テクスチャ座標は画像の幅 512 で割った 0〜1 の値",
            "these are pixels: texture coordinates are 0…1, the pixels divided by the image's width 512",
        )
    } else if is(want.t_min, want.t_max) {
        t("s と t（列と行）を取り違えている", "s and t (columns and rows) are swapped")
    } else {
        t(
            "列 A が s = 0〜1/8、列 B が 1/8〜2/8、…: 左端は（最初の列の番号）/8、右端は（最後の列の番号 + 1）/8",
            "column A is s = 0…1/8, column B 1/8…2/8, …: the left edge is (first column's index)/8, the right edge (last column's index + 1)/8",
        )
    };
    Err(Failure::new(
        format!("s_min = {}, s_max = {}", decimal(want.s_min, 4), decimal(want.s_max, 4)),
        format!("s_min = {}, s_max = {}", decimal(got.s_min, 4), decimal(got.s_max, 4)),
    )
    .at({
        let columns = if r.columns == 1 {
            column_name(r.column).to_string()
        } else {
            format!("{}–{}", column_name(r.column), column_name(r.column + r.columns - 1))
        };
        Text::new(
            format!("tex_range、範囲 {}、列 {columns}", r.name()),
            format!("tex_range, region {}: columns {columns}", r.name()),
        )
    })
    .cause(cause)
    .hint(t(
        "s は画像の左端で 0、右端で 1。マスは 8 列なので 1 列の幅は 1/8",
        "s is 0 at the image's left edge and 1 at its right edge; there are 8 columns, each 1/8 wide",
    )))
}

pub(super) fn t_range(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let got = (imp.tex_range)(spec);
    let want = spec.region.range();
    if close(got.t_min, want.t_min, TOL_RANGE) && close(got.t_max, want.t_max, TOL_RANGE) {
        return Ok(());
    }
    let r = &spec.region;
    let [_, y0, _, y1] = r.pixels();
    let n = CELLS as f32;
    let is = |a: f32, b: f32| close(got.t_min, a, TOL_RANGE) && close(got.t_max, b, TOL_RANGE);
    let cause = if is(r.row as f32 / n, (r.row + r.rows) as f32 / n) {
        t(
            "行を上から数えたまま t にしている: t は画像の下端で 0、上端で 1（テクスチャ座標 (0, 0) は画像の左下）。上下が反転して貼られる",
            "the rows are counted from the top, but t grows from the bottom (texture coordinate (0, 0) is the image's bottom-left corner): the region would come out flipped top to bottom, and from the wrong rows",
        )
    } else if is(0.0, 1.0) {
        t("画像全体の範囲になっている", "this is the whole image, not the region")
    } else if is(y0 as f32, y1 as f32) || is(512.0 - y1 as f32, 512.0 - y0 as f32) {
        t(
            "ピクセルの値のまま: テクスチャ座標は画像の高さ 512 で割った 0〜1 の値",
            "these are pixels: texture coordinates are 0…1, the pixels divided by the image's height 512",
        )
    } else if is(want.s_min, want.s_max) {
        t("s と t（列と行）を取り違えている", "s and t (columns and rows) are swapped")
    } else {
        t(
            "行 1 が t = 7/8〜1、行 8 が t = 0〜1/8: 下端は (8 − 最後の行の番号)/8、上端は (8 − 最初の行の番号 + 1)/8",
            "row 1 is t = 7/8…1 and row 8 is t = 0…1/8: the bottom edge is (8 − last row)/8, the top edge (8 − first row + 1)/8",
        )
    };
    Err(Failure::new(
        format!("t_min = {}, t_max = {}", decimal(want.t_min, 4), decimal(want.t_max, 4)),
        format!("t_min = {}, t_max = {}", decimal(got.t_min, 4), decimal(got.t_max, 4)),
    )
    .at({
        let rows = if r.rows == 1 {
            (r.row + 1).to_string()
        } else {
            format!("{}–{}", r.row + 1, r.row + r.rows)
        };
        Text::new(
            format!("tex_range、範囲 {}、行 {rows}", r.name()),
            format!("tex_range, region {}: rows {rows}", r.name()),
        )
    })
    .cause(cause)
    .hint(t(
        "ピクセルの y は上から、t は下から数える: t = 1 − y / 512",
        "pixel y counts from the top, t from the bottom: t = 1 − y / 512",
    )))
}
