//! The assignment text of `a4`, like the course's assignment program prints it, in Japanese and
//! English ([`SpecExt::describe`]).

use std::fmt::Write as _;

use cg_core::lang::Lang;

use crate::prepared::{CELL_PIXELS, CELLS, IMAGE_PIXELS, column_name};
use crate::spec::{Corner, RegionExt, Spec, SpecExt, SpecOracle};

/// The assignment text for `spec`, in `lang`: what [`SpecExt::describe`] returns.
pub(crate) fn describe(spec: &Spec, lang: Lang) -> String {
    let l = |ja: &'static str, en: &'static str| lang.pick(ja, en);
    let r = &spec.region;
    let [x0, y0, x1, y1] = r.pixels();
    let k = spec.block();
    let n = spec.repeat;
    let mut out = String::new();
    let _ = writeln!(out, "{}", l("4. テクスチャマッピング (a4)", "4. Texture mapping (a4)"));
    let _ = writeln!(
        out,
        "  {}",
        l(
            "指定された通りに、あらかじめ用意されている画像を読み込み、その一部を、地面にマッピングする。",
            "Load the prepared image and map the part of it given below onto the ground, as specified."
        )
    );
    let _ = writeln!(
        out,
        "  {}",
        l(
            "レポートには、テクスチャ座標の範囲や計算方法を示すこと。",
            "The report shows the range of the texture coordinates and how they are computed."
        )
    );
    let _ = writeln!(out);
    match lang {
        Lang::Ja => {
            let _ = writeln!(
                out,
                "  用意された画像: assets/textures/a4-prepared.png（{IMAGE_PIXELS} × {IMAGE_PIXELS} 画素）。{CELLS} × {CELLS} のマス（各 {CELL_PIXELS} × {CELL_PIXELS} 画素）に"
            );
            let _ = writeln!(
                out,
                "    表計算ソフトのように名前がある: 列 A〜H は左から右、行 1〜8 は上から下（A1 が左上）。各マスの矢印は画像の上を指す。"
            );
            let _ = writeln!(
                out,
                "  地面: 授業の 10 × 10 の四角形。頂点 (i, j)（i, j = 0〜10）の位置は (i*1 - 5, 0, j*1 - 5)。"
            );
        }
        Lang::En => {
            let _ = writeln!(
                out,
                "  The prepared image: assets/textures/a4-prepared.png ({IMAGE_PIXELS} × {IMAGE_PIXELS} pixels), {CELLS} × {CELLS} cells of {CELL_PIXELS} × {CELL_PIXELS} pixels"
            );
            let _ = writeln!(
                out,
                "    named like a spreadsheet: columns A–H from left to right, rows 1–8 from top to bottom (A1 is the top-left cell); the arrow in each cell points to the image's top."
            );
            let _ = writeln!(
                out,
                "  The ground: the course's 10 × 10 squares; vertex (i, j) (i, j = 0…10) is at (i*1 - 5, 0, j*1 - 5)."
            );
        }
    }
    let _ = writeln!(out);
    let (first_column, last_column) =
        (column_name(r.column), column_name(r.column + r.columns - 1));
    let (first_row, last_row) = (r.row + 1, r.row + r.rows);
    let _ = match lang {
        Lang::Ja => writeln!(
            out,
            "  範囲: {}（列 {first_column}〜{last_column}、行 {first_row}〜{last_row}）= 画像の左上の角から画素 x = {x0}〜{x1}、y = {y0}〜{y1}",
            r.name()
        ),
        Lang::En => writeln!(
            out,
            "  Region: {} (columns {first_column}–{last_column}, rows {first_row}–{last_row}) = pixels x = {x0}…{x1}, y = {y0}…{y1} from the image's top-left corner",
            r.name()
        ),
    };
    let _ = writeln!(out, "  {}: {}", l("向き", "Orientation"), orientation_text(spec, lang));
    for corner in Corner::ALL {
        let g = spec.ground_corner_of(corner);
        let (name, cell, to) = (corner.name(), r.corner_cell(corner), g.describe(lang));
        let _ = match lang {
            Lang::Ja => writeln!(out, "    範囲の{}（マス {cell}）→ {to}", name.ja),
            Lang::En => writeln!(out, "    the region's {} (cell {cell}) → {to}", name.en),
        };
    }
    if n == 1 {
        let _ = writeln!(
            out,
            "  {}",
            l(
                "繰り返し: なし（地面全体に範囲を 1 回）",
                "Repeat: none (the region once, over the whole ground)"
            )
        );
    } else {
        let _ = match lang {
            Lang::Ja => writeln!(
                out,
                "  繰り返し: {n} × {n}。地面を {k} × {k} 個の四角形のまとまり {n} × {n} 個に分け、どのまとまりにも範囲全体を同じ向きで貼る（まとまりの手前の左の角には、上の表で地面の手前の左の隅に来る角、など）"
            ),
            Lang::En => writeln!(
                out,
                "  Repeat: {n} × {n}: the ground is {n} × {n} blocks of {k} × {k} squares, and every block shows the whole region the same way (a block's near-left corner gets what the table gives the ground's near-left corner, and so on)"
            ),
        };
    }
    let _ = writeln!(out);
    let _ = writeln!(out, "               {}", l("奥 (-z)", "far (-z)"));
    let _ = writeln!(out, "      (0, 0) +----------+ (10, 0)");
    let _ = writeln!(out, "   -x        |{}|        +x", l("   地面   ", "  ground  "));
    let _ = writeln!(out, "     (0, 10) +----------+ (10, 10)");
    let _ = writeln!(out, "               {}", l("手前 (+z)、カメラ", "near (+z), camera"));
    let _ = writeln!(out);
    let tasks: [(&str, &str, &str); 3] = [
        (
            "a4.t1",
            "tex_range: 範囲のテクスチャ座標 s_min, s_max, t_min, t_max を求める（(s, t) = (0, 0) は画像の左下、(1, 1) は右上。行は上から数えることに注意）",
            "tex_range: the region's texture-coordinate range s_min, s_max, t_min, t_max ((s, t) = (0, 0) is the image's bottom-left corner, (1, 1) its top-right; mind that rows count from the top)",
        ),
        (
            "a4.t2",
            "tex_coords: 四角形 (i, j)（i, j = 0〜9）の 4 頂点のテクスチャ座標を、描く順 (i, j), (i, j+1), (i+1, j+1), (i+1, j) で、i と j から計算する",
            "tex_coords: the texture coordinates of the 4 corners of square (i, j) (i, j = 0…9), in drawing order (i, j), (i, j+1), (i+1, j+1), (i+1, j), computed from i and j",
        ),
        (
            "a4.t3",
            "sampler: フィルタ（GL_NEAREST か GL_LINEAR、理由をレポートに）と、画像の一部を座標で繰り返すのに合う折り返し（GL_REPEAT か GL_CLAMP_TO_EDGE）",
            "sampler: the filter (GL_NEAREST or GL_LINEAR; say why in the report) and the wrap modes (GL_REPEAT or GL_CLAMP_TO_EDGE) that suit a part of an image repeated by its coordinates",
        ),
    ];
    for (id, ja, en) in tasks {
        let _ = writeln!(out, "  {id}  {}", lang.pick(ja, en));
    }
    let _ = writeln!(out);
    let _ = writeln!(out, "  {}", l("レポートに書くこと:", "The report shows:"));
    let report: [(&str, &str); 5] = [
        (
            "テクスチャ座標の範囲（s_min〜s_max、t_min〜t_max の表）と、マス・画素からの求め方（a4.t1）",
            "the range of the texture coordinates (a table of s_min…s_max, t_min…t_max) and how it follows from the cells and pixels (a4.t1)",
        ),
        (
            "頂点 (i, j) のテクスチャ座標を i と j で表す式と、各変数の説明。繰り返しがあれば i, j をまとまりの大きさで割った余りを使う（a4.t2）",
            "the formula of the texture coordinates of vertex (i, j) in i and j, each variable explained; with a repeat, in the remainders of i and j divided by the block size (a4.t2)",
        ),
        (
            "地面の 4 隅（と、まとまりの角）のテクスチャ座標の表",
            "a table of the texture coordinates at the ground's 4 corners (and the blocks' corners)",
        ),
        (
            "図: 画像上の範囲とその 4 隅、地面の 4 隅、どの角がどこへ行くか",
            "a figure: the region on the image with its 4 corners, the ground's 4 corners, which goes where",
        ),
        (
            "フィルタと折り返しの設定とその理由（a4.t3）、結果の画像（cargo run --release -- view a4）",
            "the filter and wrap settings and why (a4.t3), and a picture of the result (cargo run --release -- view a4)",
        ),
    ];
    for (ja, en) in report {
        let _ = writeln!(out, "    - {}", lang.pick(ja, en));
    }
    out
}

/// The orientation in words: `turned 90° counter-clockwise…`.
fn orientation_text(spec: &Spec, lang: Lang) -> String {
    let turn = match (spec.rotation_deg, lang) {
        (90, Lang::Ja) => {
            "カメラから（上から）見て反時計回りに 90° 回す（画像の上が左、−x の向き）"
        }
        (90, Lang::En) => {
            "turned 90° counter-clockwise as seen from the camera (from above): the image's top points left (−x)"
        }
        (180, Lang::Ja) => "180° 回す（画像の上が手前、+z の向き）",
        (180, Lang::En) => "turned 180°: the image's top points towards the camera (+z)",
        (270, Lang::Ja) => "カメラから（上から）見て時計回りに 90° 回す（画像の上が右、+x の向き）",
        (270, Lang::En) => {
            "turned 90° clockwise as seen from the camera (from above): the image's top points right (+x)"
        }
        (_, Lang::Ja) => "回さない（カメラから見て正立。画像の上が奥、−z の向き）",
        (_, Lang::En) => {
            "not turned: upright as seen from the camera, the image's top away from it (−z)"
        }
    };
    match (spec.mirrored, lang) {
        (false, Lang::Ja) => format!("左右反転なし、{turn}"),
        (false, Lang::En) => format!("not mirrored, {turn}"),
        (true, Lang::Ja) => format!("左右反転（名前が鏡文字に見える）してから、{turn}"),
        (true, Lang::En) => {
            format!("mirrored left to right (the names read as mirror writing), then {turn}")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::spec;

    #[test]
    fn the_text_names_the_tasks_and_the_region_in_both_languages() {
        let s = spec(90, true, 2);
        for (lang, pixels) in [(Lang::Ja, "x = 128〜256"), (Lang::En, "x = 128…256")] {
            let text = s.describe(lang);
            for needle in ["a4.t1", "a4.t2", "a4.t3", "C4–D5", pixels, "(10, 10)", "2 × 2"] {
                assert!(text.contains(needle), "{needle:?} missing from:\n{text}");
            }
        }
        assert!(s.describe(Lang::Ja).contains("鏡文字"));
        assert!(s.describe(Lang::En).contains("counter-clockwise"));
    }
}
