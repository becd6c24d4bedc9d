//! The report's tables and matrix products, as fragments for the template: the vertex table, the
//! face table with the derived normals, the model transform and every named matrix as a product
//! (symbolic, numeric, each factor and the tagged result as `pmatrix`), the variables, and the
//! texture-coordinate table and formula.
//!
//! Markdown output follows the shared notation that [`crate::parse`] reads back: vertex rows
//! `| V0 | (0.000, 1.000, 0.000) |`, face rows `| F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } |`,
//! a tag line `<!-- cg: ID -->` right before the `$$ … $$` block whose first `pmatrix` is the
//! 4×4 result, and texture rows `| 3 | 5 | (-2.000, 0.000, 0.000) | (0.300, 0.500) |`. Numbers in
//! tables have exactly three decimals and never print as `-0.000` ([`fixed`]); matrix entries
//! print as [`format_number`] does. LaTeX output is the same content for LuaLaTeX (`amsmath`,
//! `booktabs`, `longtable`), with a `% cg: ID` comment before each tagged result.

use cg_core::glam::{Mat4, Vec2, Vec3};
use cg_core::lang::{Lang, t};
use cg_core::product::{MatrixProduct, format_number};
use cg_core::texture::{Filter, Sampler, Wrap};
use cg_harness::Text;

use crate::model::{NamedMatrix, PolygonData, TextureData};
use crate::parse::FACTORS;
use crate::template::{Format, latex_escape};

/// A component differing from the derived normal by more than this is named in the face table.
pub const NORMAL_NOTE_TOLERANCE: f32 = 0.001;

/// `x` with exactly three decimals, as the kit's tables print numbers: `0.486`, `-0.800`,
/// `1.000`, a 5 rounded up as by hand (`0.3125` → `0.313`, [`cg_core::notation::fixed`]); values
/// that round to zero print as `0.000`, never `-0.000`. Non-finite values print as `NaN`, `inf`,
/// `-inf`.
#[must_use]
pub fn fixed(x: f32) -> String {
    cg_core::notation::fixed(x, 3)
}

/// `(x, y, z)` with [`fixed`] components: `(0.000, 1.000, 0.000)`.
#[must_use]
pub fn tuple3(v: Vec3) -> String {
    format!("({}, {}, {})", fixed(v.x), fixed(v.y), fixed(v.z))
}

/// `{ x, y, z }` with [`fixed`] components: `{ 0.000, 0.486, 0.874 }`.
#[must_use]
pub fn braces3(v: Vec3) -> String {
    format!("{{ {}, {}, {} }}", fixed(v.x), fixed(v.y), fixed(v.z))
}

/// `(s, t)` with [`fixed`] components: `(0.300, 0.500)`.
#[must_use]
pub fn tuple2(v: Vec2) -> String {
    format!("({}, {})", fixed(v.x), fixed(v.y))
}

/// `{ V0, V3, V1 }`.
fn face_vertices(f: [u32; 3]) -> String {
    format!("{{ V{}, V{}, V{} }}", f[0], f[1], f[2])
}

/// A Markdown table cell: `|` escaped, line breaks as spaces.
pub(crate) fn md_cell(text: &str) -> String {
    text.replace('|', "\\|").replace(['\r', '\n'], " ")
}

/// Text for LaTeX: [`latex_escape`], and the two symbols of the products (`·`, `°`) as math.
pub(crate) fn tex_text(text: &str) -> String {
    latex_escape(text).replace('·', "\\(\\cdot\\)").replace('°', "\\(^\\circ\\)")
}

/// A Markdown table from a header and rows of cells (already formatted).
fn md_table(header: &[&str], rows: &[Vec<String>]) -> String {
    let mut out = format!("| {} |\n", header.join(" | "));
    out.push_str(&format!("|{}\n", "---|".repeat(header.len())));
    for row in rows {
        out.push_str(&format!("| {} |\n", row.join(" | ")));
    }
    out
}

/// A LaTeX `longtable` (booktabs rules) from a column spec, a header and rows of cells.
fn tex_table_env(spec: &str, header: &[&str], rows: &[Vec<String>]) -> String {
    let mut out = format!("\\begin{{longtable}}{{{spec}}}\n\\toprule\n");
    out.push_str(&format!("{} \\\\\n\\midrule\n\\endhead\n", header.join(" & ")));
    for row in rows {
        out.push_str(&format!("{} \\\\\n", row.join(" & ")));
    }
    out.push_str("\\bottomrule\n\\end{longtable}\n");
    out
}

/// A table in the given format; LaTeX cells are given already escaped.
pub(crate) fn table(
    format: Format,
    spec: &str,
    header: &[Text],
    lang: Lang,
    rows: &[Vec<String>],
) -> String {
    let header: Vec<&str> = header.iter().map(|h| h.get(lang)).collect();
    let header = header.as_slice();
    match format {
        Format::Markdown => md_table(header, rows),
        Format::Latex => tex_table_env(spec, header, rows),
    }
}

/// A short paragraph in the given format (escaped for LaTeX, quoted for Markdown).
fn note(text: &Text, lang: Lang, format: Format) -> String {
    match format {
        Format::Markdown => format!("> {}\n", text.get(lang).replace('\n', "\n> ")),
        Format::Latex => format!("\\textit{{{}}}\n", tex_text(text.get(lang))),
    }
}

/// The vertex table: `| V0 | (0.000, 1.000, 0.000) |`, one row per vertex.
#[must_use]
pub fn vertex_table(p: &PolygonData, lang: Lang, format: Format) -> String {
    let rows: Vec<Vec<String>> = p
        .vertices
        .iter()
        .enumerate()
        .map(|(k, v)| match format {
            Format::Markdown => vec![format!("V{k}"), tuple3(*v)],
            Format::Latex => vec![format!("V{k}"), format!("${}$", tuple3(*v))],
        })
        .collect();
    let header = match format {
        Format::Markdown => [t("頂点", "vertex"), t("座標 (x, y, z)", "position (x, y, z)")],
        Format::Latex => [t("頂点", "vertex"), t("座標 $(x, y, z)$", "position $(x, y, z)$")],
    };
    table(format, "ll", &header, lang, &rows)
}

/// Why a face has no derived normal: a vertex that does not exist, or no area.
fn no_normal_reason(p: &PolygonData, f: [u32; 3]) -> Text {
    match f.iter().find(|&&v| v as usize >= p.vertices.len()) {
        Some(v) => Text::new(
            format!("法線なし: 頂点 V{v} がありません"),
            format!("no normal: vertex V{v} does not exist"),
        ),
        None => Text::new(
            "法線なし: 縮退した面（面積が 0、または頂点が一直線上）",
            "no normal: degenerate face (zero area, or its vertices lie on one line)",
        ),
    }
}

/// The face table: `| F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } |` with the normal the kit
/// derives from the vertices. A face without a normal says why (degenerate, or a vertex that
/// does not exist). When the student's own normals exist and one differs from the derived
/// normal by more than [`NORMAL_NOTE_TOLERANCE`] in a component (or is missing), a note column
/// names it (the student's normal in square brackets, so it is not read as the face's normal).
#[must_use]
pub fn face_table(p: &PolygonData, lang: Lang, format: Format) -> String {
    let notes: Vec<Option<Text>> = (0..p.faces.len())
        .map(|k| {
            let student = p.student_normals.as_ref()?;
            let derived = p.derived_normals.get(k).copied().flatten();
            match (student.get(k), derived) {
                (None, _) => Some(Text::new(
                    "あなたのプログラムにはこの面の法線がありません",
                    "your program has no normal for this face",
                )),
                (Some(s), Some(d)) => {
                    let differs = (0..3).any(|i| {
                        (s[i] - d[i]).abs() > NORMAL_NOTE_TOLERANCE || (s[i] - d[i]).is_nan()
                    });
                    differs.then(|| {
                        let s = format!("[{}, {}, {}]", fixed(s.x), fixed(s.y), fixed(s.z));
                        Text::new(
                            format!("あなたの法線 {s} は導出した法線と違います"),
                            format!("your normal {s} differs from the derived one"),
                        )
                    })
                }
                (Some(s), None) => {
                    let s = format!("[{}, {}, {}]", fixed(s.x), fixed(s.y), fixed(s.z));
                    Some(Text::new(
                        format!("あなたの法線 {s}: この面の法線は導出できません"),
                        format!("your normal {s}: this face has no derivable normal"),
                    ))
                }
            }
        })
        .collect();
    let with_notes = notes.iter().any(Option::is_some);
    let rows: Vec<Vec<String>> = p
        .faces
        .iter()
        .enumerate()
        .map(|(k, &f)| {
            let normal = p.derived_normals.get(k).copied().flatten();
            let mut row = match format {
                Format::Markdown => vec![
                    format!("F{k}"),
                    face_vertices(f),
                    normal.map_or_else(|| no_normal_reason(p, f).get(lang).to_owned(), braces3),
                ],
                Format::Latex => vec![
                    format!("F{k}"),
                    format!("\\{{ V{}, V{}, V{} \\}}", f[0], f[1], f[2]),
                    normal.map_or_else(
                        || tex_text(no_normal_reason(p, f).get(lang)),
                        |n| format!("$\\{{ {}, {}, {} \\}}$", fixed(n.x), fixed(n.y), fixed(n.z)),
                    ),
                ],
            };
            if with_notes {
                let text = notes[k].as_ref().map_or("", |t| t.get(lang));
                row.push(match format {
                    Format::Markdown => md_cell(text),
                    Format::Latex => tex_text(text),
                });
            }
            row
        })
        .collect();
    let mut header = vec![
        t("面", "face"),
        t("頂点（外側から見て反時計回り）", "vertices (CCW from outside)"),
        t("法線（頂点から導出）", "normal (from the vertices)"),
    ];
    let spec = if with_notes {
        header.push(t("注", "note"));
        "lllp{0.3\\linewidth}"
    } else {
        "lll"
    };
    table(format, spec, &header, lang, &rows)
}

/// `\begin{pmatrix} … \end{pmatrix}` of `m` by rows, entries as [`format_number`] prints them.
fn pmatrix(m: Mat4) -> String {
    let rows: Vec<String> = (0..4)
        .map(|r| {
            let row = m.row(r);
            [row.x, row.y, row.z, row.w].map(format_number).join(" & ")
        })
        .collect();
    format!("\\begin{{pmatrix}} {} \\end{{pmatrix}}", rows.join(" \\\\ "))
}

/// A math block: `$$ … $$` (Markdown) or `\[ … \]` (LaTeX), `lines` joined by line breaks.
fn math_block(lines: &[String], format: Format) -> String {
    match format {
        Format::Markdown => format!("$$\n{}\n$$\n", lines.join("\n")),
        Format::Latex => format!("\\[\n{}\n\\]\n", lines.join("\n")),
    }
}

/// The widest a line of factors may be, in [`math_width`]'s characters: about the text width
/// of an A4 page at 11 pt, less the margins of a display.
const LINE_WIDTH: usize = 62;

/// About how wide a `pmatrix` is set, in characters: each column as wide as its widest entry
/// (commands such as `\mathit{…}` and `\cos` counted by what they print), two characters
/// between columns and three for the parentheses.
fn math_width(pmatrix: &str) -> usize {
    let body =
        pmatrix.trim().trim_start_matches("\\begin{pmatrix}").trim_end_matches("\\end{pmatrix}");
    let printed = |cell: &str| {
        let mut n = 0;
        let mut chars = cell.trim().chars().peekable();
        while let Some(c) = chars.next() {
            match c {
                '{' | '}' => {}
                '\\' => {
                    let mut name = String::new();
                    while let Some(&d) = chars.peek().filter(|d| d.is_ascii_alphabetic()) {
                        name.push(d);
                        chars.next();
                    }
                    // A font command prints its argument; a function name prints itself.
                    if !matches!(name.as_str(), "mathit" | "mathrm" | "left" | "right" | "") {
                        n += name.len().min(3);
                    }
                }
                _ => n += 1,
            }
        }
        n
    };
    let rows: Vec<Vec<usize>> =
        body.split("\\\\").map(|r| r.split('&').map(printed).collect()).collect();
    let columns = rows.iter().map(Vec::len).max().unwrap_or(0);
    let widths: usize = (0..columns)
        .map(|c| rows.iter().filter_map(|r| r.get(c)).max().copied().unwrap_or(0))
        .sum();
    widths + 2 * columns.saturating_sub(1) + 3
}

/// For LaTeX, the factors on as few lines as fit the page ([`LINE_WIDTH`], at most three a line);
/// Markdown keeps one factor per line in a single block.
fn factor_lines(parts: Vec<String>, format: Format) -> Vec<String> {
    if format == Format::Markdown {
        return parts;
    }
    let mut lines: Vec<Vec<String>> = Vec::new();
    let mut width = 0;
    for part in parts {
        let w = math_width(&part);
        match lines.last_mut() {
            Some(line) if line.len() < 3 && width + w <= LINE_WIDTH => {
                line.push(part);
                width += w;
            }
            _ => {
                lines.push(vec![part]);
                width = w;
            }
        }
    }
    if lines.len() <= 1 {
        return lines.into_iter().flatten().collect();
    }
    let chunks: Vec<String> = lines.iter().map(|l| l.join("\n")).collect();
    vec!["\\begin{gathered}".to_owned(), chunks.join(" \\\\\n"), "\\end{gathered}".to_owned()]
}

/// A product's label in running text: `` `T(0, 1, 0) · Rx(30°)` `` or `\texttt{…}`.
fn product_text(label: &str, format: Format) -> String {
    match format {
        Format::Markdown => format!("`{}`", label.replace('`', "'")),
        // A break may follow each `·`: a long product wraps instead of running into the margin.
        Format::Latex => format!(
            "\\texttt{{{}}}",
            tex_text(label).replace("\\(\\cdot\\)", "\\(\\cdot\\)\\allowbreak{}")
        ),
    }
}

/// The parts of one named product: title, symbolic product (when it has symbols), numeric
/// product with each factor as `pmatrix`, then the tag and the 4×4 result.
fn product_block(
    id: &str,
    title: &Text,
    symbolic: &MatrixProduct,
    numeric: &MatrixProduct,
    lang: Lang,
    format: Format,
) -> String {
    let mut out = match format {
        Format::Markdown => format!("**{}**\n\n", md_cell(title.get(lang)).replace('*', "\\*")),
        Format::Latex => format!("\\paragraph{{{}}}\n\n", tex_text(title.get(lang))),
    };
    let result = match numeric.matrix() {
        Ok(m) => m,
        Err(e) => {
            let text = Text::new(
                format!("この行列は計算できません: {e}"),
                format!("this matrix cannot be computed: {e}"),
            );
            out.push_str(&note(&text, lang, format));
            return out;
        }
    };
    let sym_label = symbolic.symbolic();
    if sym_label != numeric.numeric() {
        out.push_str(&format!(
            "{}: {}\n\n",
            t("変数を使った積", "as a product with variables").get(lang),
            product_text(&sym_label, format)
        ));
        if let Ok(latex) = symbolic.latex(true) {
            let parts = latex.lines().map(str::to_owned).collect();
            out.push_str(&math_block(&factor_lines(parts, format), format));
            out.push('\n');
        }
    }
    out.push_str(&format!(
        "{}: {}\n\n",
        t("数値を入れた積", "with this state's numbers").get(lang),
        product_text(&numeric.numeric(), format)
    ));
    let factors: Vec<String> = factor_matrices(numeric).into_iter().map(pmatrix).collect();
    if !factors.is_empty() {
        // Each factor is checked too (`report check`): a tag `ID.factors` before them.
        match format {
            Format::Markdown => out.push_str(&format!("<!-- cg: {id}{FACTORS} -->\n")),
            Format::Latex => out.push_str(&format!("% cg: {id}{FACTORS}\n")),
        }
        out.push_str(&math_block(&factor_lines(factors, format), format));
        out.push('\n');
    }
    out.push_str(&format!("{}:\n\n", t("積（4×4 行列）", "the product (4×4 matrix)").get(lang)));
    let eq = if numeric.factors.is_empty() { "" } else { "= " };
    match format {
        Format::Markdown => out.push_str(&format!("<!-- cg: {id} -->\n")),
        Format::Latex => out.push_str(&format!("% cg: {id}\n")),
    }
    out.push_str(&math_block(&[format!("{eq}{}", pmatrix(result))], format));
    out
}

/// The factors of `product` that are matrices, in order: what the report writes as `pmatrix`
/// after the tag `ID.factors`, and what `report check` compares them with.
#[must_use]
pub fn factor_matrices(product: &MatrixProduct) -> Vec<Mat4> {
    product.factors.iter().filter_map(|f| f.matrix().ok()).collect()
}

/// The model transform of assignment 1 (`a1.transform`): the product, each factor as `pmatrix`,
/// and the tagged result. Without a transform, a note says the model is drawn as defined.
#[must_use]
pub fn transform(p: &PolygonData, lang: Lang, format: Format) -> String {
    match &p.transform {
        Some(t) => product_block(
            "a1.transform",
            &Text::new(
                "モデル変換行列（モデル座標系 → ワールド座標系）",
                "the model matrix (model space → world space)",
            ),
            t,
            t,
            lang,
            format,
        ),
        None => note(
            &Text::new(
                "モデル変換はありません（モデル座標のまま描画）",
                "no model transform (the model is drawn in its own coordinates)",
            ),
            lang,
            format,
        ),
    }
}

/// One named matrix: its title, the product with variables, the product with this state's
/// numbers and each factor as `pmatrix`, then the tagged 4×4 result (tag `m.id`).
#[must_use]
pub fn matrix(m: &NamedMatrix, lang: Lang, format: Format) -> String {
    product_block(&m.id, &m.title, &m.symbolic, &m.numeric, lang, format)
}

/// Every matrix of `ms` as [`matrix`] does, separated by blank lines.
#[must_use]
pub fn matrices(ms: &[NamedMatrix], lang: Lang, format: Format) -> String {
    if ms.is_empty() {
        return note(&Text::new("行列はありません", "no matrices"), lang, format);
    }
    ms.iter().map(|m| matrix(m, lang, format)).collect::<Vec<_>>().join("\n")
}

/// The variables of the products: `| camera_pitch | meaning, operation, range |`.
#[must_use]
pub fn variables(vars: &[(String, Text)], lang: Lang, format: Format) -> String {
    if vars.is_empty() {
        return note(&Text::new("変数はありません", "no variables"), lang, format);
    }
    let rows: Vec<Vec<String>> = vars
        .iter()
        .map(|(name, meaning)| match format {
            Format::Markdown => {
                vec![
                    format!("`{}`", name.replace('`', "'").replace('|', "\\|")),
                    md_cell(meaning.get(lang)),
                ]
            }
            Format::Latex => {
                vec![format!("\\texttt{{{}}}", tex_text(name)), tex_text(meaning.get(lang))]
            }
        })
        .collect();
    let header = [
        t("変数", "variable"),
        t("意味・変化させる操作・範囲", "meaning, the operation that changes it, range"),
    ];
    table(format, "lp{0.65\\linewidth}", &header, lang, &rows)
}

/// The texture-coordinate table: `| i | j | (x, y, z) | (s, t) / (s, t) |`, one row per ground
/// vertex, its coordinates in the order the squares use them.
#[must_use]
pub fn tex_table(tex: &TextureData, lang: Lang, format: Format) -> String {
    let rows: Vec<Vec<String>> = tex
        .rows
        .iter()
        .map(|r| {
            let coords: Vec<String> = r.tex.iter().map(|&v| tuple2(v)).collect();
            match format {
                Format::Markdown => {
                    vec![r.i.to_string(), r.j.to_string(), tuple3(r.position), coords.join(" / ")]
                }
                Format::Latex => vec![
                    r.i.to_string(),
                    r.j.to_string(),
                    format!("${}$", tuple3(r.position)),
                    // Each pair its own formula, so a vertex with several wraps in its column.
                    coords.iter().map(|c| format!("${c}$")).collect::<Vec<_>>().join(" / "),
                ],
            }
        })
        .collect();
    let header = match format {
        Format::Markdown => [
            "i".into(),
            "j".into(),
            t("頂点の位置 (x, y, z)", "vertex position (x, y, z)"),
            t("テクスチャ座標 (s, t)", "texture coordinates (s, t)"),
        ],
        Format::Latex => [
            "$i$".into(),
            "$j$".into(),
            t("頂点の位置 $(x, y, z)$", "vertex position $(x, y, z)$"),
            t("テクスチャ座標 $(s, t)$", "texture coordinates $(s, t)$"),
        ],
    };
    let body = table(format, "rrlp{0.3\\linewidth}", &header, lang, &rows);
    match format {
        Format::Markdown => body,
        // Set small and close: a vertex shared by squares with other coordinates has several.
        Format::Latex => format!("{{\\small\\setlength{{\\tabcolsep}}{{4pt}}\n{body}}}\n"),
    }
}

/// The formula in i and j (in words, from the data) and the mapped rectangle in texture
/// coordinates, `s ∈ [s₀, s₁], t ∈ [t₀, t₁]`.
#[must_use]
pub fn formula(tex: &TextureData, lang: Lang, format: Format) -> String {
    formula_words(&tex.formula, tex, lang, format)
}

/// [`formula`] with `words` for the formula in words.
pub(crate) fn formula_words(words: &Text, tex: &TextureData, lang: Lang, format: Format) -> String {
    let (lo, hi) = tex.region;
    let range = format!(
        "s \\in [{}, {}],\\ t \\in [{}, {}]",
        fixed(lo.x),
        fixed(hi.x),
        fixed(lo.y),
        fixed(hi.y)
    );
    let label = t(
        "貼り付ける範囲（テクスチャ座標、t = 0 が画像の下端）",
        "the mapped region (texture coordinates, t = 0 at the image's bottom edge)",
    );
    let label = label.get(lang);
    match format {
        Format::Markdown => format!("{}\n\n{label}: ${range}$\n", words.get(lang)),
        Format::Latex => {
            format!("{}\n\n{}: ${range}$\n", tex_text(words.get(lang)), tex_text(label))
        }
    }
}

/// The student's sampler (a4.t3) with the OpenGL names, and how many pixels of the image one
/// ground square shows (for the choice of filter); `None` when a4.t3 did not derive.
#[must_use]
pub fn sampler(tex: &TextureData, lang: Lang, format: Format) -> Option<String> {
    Some(sampler_text(tex.sampler?, Some(tex.texels_per_square), lang, format))
}

/// The sampler `s` (a4.t3) with the OpenGL names; with `texels_per_square`, how many pixels of
/// the image one ground square shows; without it (a4.t1 or a4.t2 did not derive: the sampler
/// does not need them), that this follows once they derive.
#[must_use]
pub fn sampler_text(
    s: Sampler,
    texels_per_square: Option<Vec2>,
    lang: Lang,
    format: Format,
) -> String {
    let filter = match s.filter {
        Filter::Nearest => "GL_NEAREST (Filter::Nearest)",
        Filter::Bilinear => "GL_LINEAR (Filter::Bilinear)",
    };
    let wrap = |w: Wrap| match w {
        Wrap::Repeat => "GL_REPEAT (Wrap::Repeat)",
        Wrap::Clamp => "GL_CLAMP_TO_EDGE (Wrap::Clamp)",
    };
    let (u, v) = (wrap(s.wrap_u), wrap(s.wrap_v));
    let pixels = match texels_per_square {
        Some(t) => {
            let (x, y) = (format_number(t.x), format_number(t.y));
            Text::new(
                format!(
                    "地面の四角形 1 つに画像の {x} × {y} ピクセル（画像の横 × 縦、s 方向 × t 方向）が貼られる。"
                ),
                format!(
                    "One ground square shows {x} × {y} pixels of the image (across × up the image, along s × along t)."
                ),
            )
        }
        None => t(
            "（地面の四角形 1 つに貼られるピクセルの数は、a4.t1 と a4.t2 が導出できると書かれます）",
            "(How many pixels of the image one ground square shows is written once a4.t1 and a4.t2 derive.)",
        ),
    };
    let text = Text::new(
        format!("フィルタ: {filter}。折り返し: s 方向 {u}、t 方向 {v}。{}", pixels.ja),
        format!("Filter: {filter}. Wrap: {u} along s, {v} along t. {}", pixels.en),
    );
    let text = text.get(lang);
    match format {
        Format::Markdown => format!("{text}\n"),
        Format::Latex => format!("{}\n", tex_text(text)),
    }
}

#[cfg(test)]
pub(crate) mod tests;
