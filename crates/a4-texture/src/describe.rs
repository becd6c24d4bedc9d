//! The assignment text of `a4`, like the course's assignment program prints it, in Japanese and
//! English ([`SpecExt::describe`]).

use std::fmt::Write as _;

use cg_core::lang::{Lang, Text, t};

use crate::prepared::{CELL_PIXELS, CELLS, IMAGE_PIXELS, column_name};
use crate::spec::{Corner, RegionExt, Spec, SpecExt, SpecOracle};

/// The assignment text for `spec`, in `lang`: what [`SpecExt::describe`] returns.
pub(crate) fn describe(spec: &Spec, lang: Lang) -> String {
    let r = &spec.region;
    let [x0, y0, x1, y1] = r.pixels();
    let k = spec.block();
    let n = spec.repeat;
    let mut out = String::new();
    let _ =
        writeln!(out, "{}", t("4. テクスチャマッピング (a4)", "4. Texture mapping (a4)").get(lang));
    let _ = writeln!(
        out,
        "  {}",
        t(
            "指定された通りに、あらかじめ用意されている画像を読み込み、その一部を、地面にマッピングする。",
            "Load the prepared image and map the part of it given below onto the ground, as specified.",
        ).get(lang)
    );
    let _ = writeln!(
        out,
        "  {}",
        t(
            "レポートには、テクスチャ座標の範囲や計算方法を示すこと。",
            "The report shows the range of the texture coordinates and how they are computed."
        )
        .get(lang)
    );
    let _ = writeln!(out);
    let image = Text::new(
        format!(
            "  用意された画像: assets/textures/a4-prepared.png（{IMAGE_PIXELS} × {IMAGE_PIXELS} ピクセル）。{CELLS} × {CELLS} のマス（各 {CELL_PIXELS} × {CELL_PIXELS} ピクセル）に\n    表計算ソフトのように名前がある: 列 A〜H は左から右、行 1〜8 は上から下（A1 が左上）。各マスの矢印は画像の上を指す。\n  地面: 授業の 10 × 10 の四角形。頂点 (i, j)（i, j = 0〜10）の位置は (i*1 - 5, 0, j*1 - 5)。"
        ),
        format!(
            "  The prepared image: assets/textures/a4-prepared.png ({IMAGE_PIXELS} × {IMAGE_PIXELS} pixels), {CELLS} × {CELLS} cells of {CELL_PIXELS} × {CELL_PIXELS} pixels\n    named like a spreadsheet: columns A–H from left to right, rows 1–8 from top to bottom (A1 is the top-left cell); the arrow in each cell points to the image's top.\n  The ground: the course's 10 × 10 squares; vertex (i, j) (i, j = 0…10) is at (i*1 - 5, 0, j*1 - 5)."
        ),
    );
    let _ = writeln!(out, "{}", image.get(lang));
    let _ = writeln!(out);
    let (first_column, last_column) =
        (column_name(r.column), column_name(r.column + r.columns - 1));
    let (first_row, last_row) = (r.row + 1, r.row + r.rows);
    let name = r.name();
    // One column or one row is named alone (`column A`), not as a range from it to itself.
    let columns = if r.columns == 1 {
        Text::new(format!("列 {first_column}"), format!("column {first_column}"))
    } else {
        Text::new(
            format!("列 {first_column}〜{last_column}"),
            format!("columns {first_column}–{last_column}"),
        )
    };
    let rows = if r.rows == 1 {
        Text::new(format!("行 {first_row}"), format!("row {first_row}"))
    } else {
        Text::new(format!("行 {first_row}〜{last_row}"), format!("rows {first_row}–{last_row}"))
    };
    let region = Text::new(
        format!(
            "  範囲: {name}（{}、{}）= 画像の左上の角からピクセル x = {x0}〜{x1}、y = {y0}〜{y1}",
            columns.ja, rows.ja
        ),
        format!(
            "  Region: {name} ({}, {}) = pixels x = {x0}…{x1}, y = {y0}…{y1} from the image's top-left corner",
            columns.en, rows.en
        ),
    );
    let _ = writeln!(out, "{}", region.get(lang));
    let _ = writeln!(
        out,
        "  {}: {}",
        t("向き", "Orientation").get(lang),
        orientation_text(spec).get(lang)
    );
    for corner in Corner::ALL {
        let g = spec.ground_corner_of(corner);
        let (name, cell, to) = (corner.name(), r.corner_cell(corner), g.text());
        let line = Text::new(
            format!("    範囲の{}（マス {cell}）→ {}", name.ja, to.ja),
            format!("    the region's {} (cell {cell}) → {}", name.en, to.en),
        );
        let _ = writeln!(out, "{}", line.get(lang));
    }
    if n == 1 {
        let _ = writeln!(
            out,
            "  {}",
            t(
                "繰り返し: なし（地面全体に範囲を 1 回）",
                "Repeat: none (the region once, over the whole ground)"
            )
            .get(lang)
        );
    } else {
        let repeat = Text::new(
            format!(
                "  繰り返し: {n} × {n}。地面を {k} × {k} 個の四角形のまとまり {n} × {n} 個に分け、どのまとまりにも範囲全体を同じ向きで貼る（まとまりの手前の左の角には、上の表で地面の手前の左の隅に来る角、など）"
            ),
            format!(
                "  Repeat: {n} × {n}: the ground is {n} × {n} blocks of {k} × {k} squares, and every block shows the whole region the same way (a block's near-left corner gets what the table gives the ground's near-left corner, and so on)"
            ),
        );
        let _ = writeln!(out, "{}", repeat.get(lang));
    }
    let _ = writeln!(out);
    let _ = writeln!(out, "               {}", t("奥 (-z)", "far (-z)").get(lang));
    let _ = writeln!(out, "      (0, 0) +----------+ (10, 0)");
    let _ = writeln!(out, "   -x        |{}|        +x", t("   地面   ", "  ground  ").get(lang));
    let _ = writeln!(out, "     (0, 10) +----------+ (10, 10)");
    let _ =
        writeln!(out, "               {}", t("手前 (+z)、カメラ", "near (+z), camera").get(lang));
    let _ = writeln!(out);
    let tasks: [(&str, Text); 3] = [
        (
            "a4.t1",
            t(
                "tex_range: 範囲のテクスチャ座標 s_min, s_max, t_min, t_max を求める（(s, t) = (0, 0) は画像の左下、(1, 1) は右上。行は上から数えることに注意）",
                "tex_range: the region's texture-coordinate range s_min, s_max, t_min, t_max ((s, t) = (0, 0) is the image's bottom-left corner, (1, 1) its top-right; mind that rows count from the top)",
            ),
        ),
        (
            "a4.t2",
            t(
                "tex_coords: 四角形 (i, j)（i, j = 0〜9）の 4 頂点のテクスチャ座標を、描く順 (i, j), (i, j+1), (i+1, j+1), (i+1, j) で、i と j から計算する",
                "tex_coords: the texture coordinates of the 4 corners of square (i, j) (i, j = 0…9), in drawing order (i, j), (i, j+1), (i+1, j+1), (i+1, j), computed from i and j",
            ),
        ),
        (
            "a4.t3",
            t(
                "sampler: フィルタ（GL_NEAREST か GL_LINEAR、理由をレポートに）と、画像の一部を座標で繰り返すのに合う折り返し（GL_REPEAT か GL_CLAMP_TO_EDGE）",
                "sampler: the filter (GL_NEAREST or GL_LINEAR; say why in the report) and the wrap modes (GL_REPEAT or GL_CLAMP_TO_EDGE) that suit a part of an image repeated by its coordinates",
            ),
        ),
    ];
    for (id, task) in tasks {
        let _ = writeln!(out, "  {id}  {}", task.get(lang));
    }
    let _ = writeln!(out);
    let _ = writeln!(out, "  {}", t("レポートに書くこと:", "The report shows:").get(lang));
    let report = [
        t(
            "テクスチャ座標の範囲（s_min〜s_max、t_min〜t_max の表）と、マス・ピクセルからの求め方（a4.t1）",
            "the range of the texture coordinates (a table of s_min…s_max, t_min…t_max) and how it follows from the cells and pixels (a4.t1)",
        ),
        t(
            "頂点 (i, j) のテクスチャ座標を i と j で表す式と、各変数の説明。繰り返しがあれば i, j をまとまりの大きさで割った余りを使う（a4.t2）",
            "the formula of the texture coordinates of vertex (i, j) in i and j, each variable explained; with a repeat, in the remainders of i and j divided by the block size (a4.t2)",
        ),
        t(
            "地面の 4 隅（と、まとまりの角）のテクスチャ座標の表",
            "a table of the texture coordinates at the ground's 4 corners (and the blocks' corners)",
        ),
        t(
            "図: 画像上の範囲とその 4 隅、地面の 4 隅、どの角がどこへ行くか",
            "a figure: the region on the image with its 4 corners, the ground's 4 corners, which goes where",
        ),
        t(
            "フィルタと折り返しの設定とその理由（a4.t3）、結果の画像（cargo run --release -- view a4）",
            "the filter and wrap settings and why (a4.t3), and a picture of the result (cargo run --release -- view a4)",
        ),
    ];
    for line in report {
        let _ = writeln!(out, "    - {}", line.get(lang));
    }
    let _ = writeln!(
        out,
        "  {}: cargo run --release -- check a4    {}: cargo run --release -- view a4",
        t("チェック", "Check").get(lang),
        t("表示", "View").get(lang)
    );
    out
}

/// The orientation in words: `turned 90° counter-clockwise…`.
fn orientation_text(spec: &Spec) -> Text {
    let turn = match spec.rotation_deg {
        90 => t(
            "カメラから（上から）見て反時計回りに 90° 回す（画像の上が左、−x の向き）",
            "turned 90° counter-clockwise as seen from the camera (from above): the image's top points left (−x)",
        ),
        180 => t(
            "180° 回す（画像の上が手前、+z の向き）",
            "turned 180°: the image's top points towards the camera (+z)",
        ),
        270 => t(
            "カメラから（上から）見て時計回りに 90° 回す（画像の上が右、+x の向き）",
            "turned 90° clockwise as seen from the camera (from above): the image's top points right (+x)",
        ),
        _ => t(
            "回さない（カメラから見て正立。画像の上が奥、−z の向き）",
            "not turned: upright as seen from the camera, the image's top away from it (−z)",
        ),
    };
    if spec.mirrored {
        Text::new(
            format!("左右反転（名前が鏡文字に見える）してから、{}", turn.ja),
            format!("mirrored left to right (the names read as mirror writing), then {}", turn.en),
        )
    } else {
        Text::new(format!("左右反転なし、{}", turn.ja), format!("not mirrored, {}", turn.en))
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
        // It ends as a1's, a2's and a3's do: the commands that check and show it.
        let en = s.describe(Lang::En);
        let last = en.lines().last().unwrap_or_default();
        assert_eq!(
            last,
            "  Check: cargo run --release -- check a4    View: cargo run --release -- view a4"
        );
        assert!(s.describe(Lang::Ja).contains("鏡文字"));
        assert!(s.describe(Lang::En).contains("counter-clockwise"));
    }
}
