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
use cg_core::texture::{Filter, Wrap};
use cg_harness::Text;

use crate::model::{NamedMatrix, PolygonData, TextureData};
use crate::parse::FACTORS;
use crate::template::{Format, latex_escape};

/// A component differing from the derived normal by more than this is named in the face table.
pub const NORMAL_NOTE_TOLERANCE: f32 = 0.001;

/// `x` with exactly three decimals, as the kit's tables print numbers: `0.486`, `-0.800`,
/// `1.000`; values that round to zero print as `0.000`, never `-0.000`. Non-finite values print
/// as `NaN`, `inf`, `-inf`.
#[must_use]
pub fn fixed(x: f32) -> String {
    if x.is_nan() {
        return "NaN".to_owned();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.to_owned();
    }
    let s = format!("{:.3}", f64::from(x));
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_owned(),
        _ => s,
    }
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
        t("頂点（外側から見て反時計回り）", "vertices (counter-clockwise from outside)"),
        t("法線（頂点から導出）", "normal (derived from the vertices)"),
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

/// Groups of at most three factors per line for LaTeX (a page is not wide enough for more);
/// Markdown keeps one factor per line in a single block.
fn factor_lines(parts: Vec<String>, format: Format) -> Vec<String> {
    match format {
        Format::Markdown => parts,
        Format::Latex if parts.len() <= 3 => parts,
        Format::Latex => {
            let chunks: Vec<String> = parts.chunks(3).map(|c| c.join("\n")).collect();
            let mut lines = vec!["\\begin{gathered}".to_owned()];
            lines.push(chunks.join(" \\\\\n"));
            lines.push("\\end{gathered}".to_owned());
            lines
        }
    }
}

/// A product's label in running text: `` `T(0, 1, 0) · Rx(30°)` `` or `\texttt{…}`.
fn product_text(label: &str, format: Format) -> String {
    match format {
        Format::Markdown => format!("`{}`", label.replace('`', "'")),
        Format::Latex => format!("\\texttt{{{}}}", tex_text(label)),
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
                "the model matrix (model coordinates → world coordinates)",
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
                    format!("${}$", coords.join(" / ")),
                ],
            }
        })
        .collect();
    let header = match format {
        Format::Markdown => [
            "i".into(),
            "j".into(),
            t("頂点の位置 (x, y, z)", "vertex position (x, y, z)"),
            t("テクスチャ座標 (s, tex)", "texture coordinates (s, tex)"),
        ],
        Format::Latex => [
            "$i$".into(),
            "$j$".into(),
            t("頂点の位置 $(x, y, z)$", "vertex position $(x, y, z)$"),
            t("テクスチャ座標 $(s, tex)$", "texture coordinates $(s, tex)$"),
        ],
    };
    table(format, "rrll", &header, lang, &rows)
}

/// The formula in i and j (in words, from the data) and the mapped rectangle in texture
/// coordinates, `s ∈ [s₀, s₁], t ∈ [t₀, t₁]`.
#[must_use]
pub fn formula(tex: &TextureData, lang: Lang, format: Format) -> String {
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
        Format::Markdown => format!("{}\n\n{label}: ${range}$\n", tex.formula.get(lang)),
        Format::Latex => {
            format!("{}\n\n{}: ${range}$\n", tex_text(tex.formula.get(lang)), tex_text(label))
        }
    }
}

/// The student's sampler (a4.t3) with the OpenGL names, and how many pixels of the image one
/// ground square shows (for the choice of filter); `None` when a4.t3 did not derive.
#[must_use]
pub fn sampler(tex: &TextureData, lang: Lang, format: Format) -> Option<String> {
    let s = tex.sampler?;
    let filter = match s.filter {
        Filter::Nearest => "GL_NEAREST (Filter::Nearest)",
        Filter::Bilinear => "GL_LINEAR (Filter::Bilinear)",
    };
    let wrap = |w: Wrap| match w {
        Wrap::Repeat => "GL_REPEAT (Wrap::Repeat)",
        Wrap::Clamp => "GL_CLAMP_TO_EDGE (Wrap::Clamp)",
    };
    let (u, v) = (wrap(s.wrap_u), wrap(s.wrap_v));
    let (x, y) = (format_number(tex.texels_per_square.x), format_number(tex.texels_per_square.y));
    let text = Text::new(
        format!(
            "フィルタ: {filter}。折り返し: s 方向 {u}、t 方向 {v}。地面の四角形 1 つに画像の {x} × {y} 画素が貼られる。"
        ),
        format!(
            "Filter: {filter}. Wrap: {u} along s, {v} along t. One ground square shows {x} × {y} pixels of the image."
        ),
    );
    let text = text.get(lang);
    Some(match format {
        Format::Markdown => format!("{text}\n"),
        Format::Latex => format!("{}\n", tex_text(text)),
    })
}

#[cfg(test)]
pub(crate) mod tests {
    use cg_core::product::{Axis, Factor, Param};
    use cg_core::texture::{Sampler, Texture};

    use super::*;
    use crate::derive::polygon_from_data;
    use crate::model::TexRow;

    /// The lecture's pyramid, normals derived by the kit.
    pub(crate) fn pyramid() -> PolygonData {
        let v = vec![
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(1.0, -0.8, 1.0),
            Vec3::new(1.0, -0.8, -1.0),
            Vec3::new(-1.0, -0.8, 1.0),
            Vec3::new(-1.0, -0.8, -1.0),
        ];
        let f = vec![[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]];
        polygon_from_data(Text::new("四角すい", "pyramid"), v, f, None)
    }

    /// The camera of the course at its start: `T(0, 0, -15) · Rx(30°)` with symbols.
    pub(crate) fn camera() -> NamedMatrix {
        let product = |d: f32, pitch: f32| {
            MatrixProduct::identity()
                .then(Factor::Translate([
                    Param::num(0.0),
                    Param::num(0.0),
                    Param::sym("-camera_distance", d),
                ]))
                .then(Factor::rotate(Axis::X, Param::sym("-camera_pitch", pitch)))
        };
        NamedMatrix {
            id: "a2.view.start".to_owned(),
            title: Text::new(
                "視野変換行列（初期状態、100% の_距離）",
                "view matrix (start, 100% of_distance)",
            ),
            symbolic: product(-15.0, 30.0),
            numeric: MatrixProduct::identity()
                .then(Factor::translate(Vec3::new(0.0, 0.0, -15.0)))
                .then(Factor::rotate_x_deg(30.0)),
            variables: vec![(
                "camera_pitch".to_owned(),
                Text::new(
                    "右ドラッグで変化、範囲 [-90, 0]、100% は_なし",
                    "right drag; range [-90, 0]; 100% no_limit",
                ),
            )],
        }
    }

    /// The numbers of the first `\begin{pmatrix} … \end{pmatrix}` after `tag` in `text`.
    pub(crate) fn tagged_matrix(text: &str, tag: &str) -> Vec<Vec<f64>> {
        let after = &text[text.find(tag).expect("tag present") + tag.len()..];
        let start = after.find("\\begin{pmatrix}").expect("pmatrix after the tag")
            + "\\begin{pmatrix}".len();
        let end = after[start..].find("\\end{pmatrix}").expect("pmatrix closed") + start;
        after[start..end]
            .split("\\\\")
            .map(|row| {
                row.split('&').map(|x| x.trim().parse::<f64>().expect("a plain number")).collect()
            })
            .collect()
    }

    /// Checks that `\begin{X}`/`\end{X}` pair up in order and that unescaped braces balance.
    pub(crate) fn assert_balanced(tex: &str) {
        let mut stack: Vec<String> = Vec::new();
        let mut rest = tex;
        loop {
            let next = [("\\begin{", true), ("\\end{", false)]
                .into_iter()
                .filter_map(|(word, open)| rest.find(word).map(|k| (k, word, open)))
                .min_by_key(|(k, _, _)| *k);
            let Some((k, word, open)) = next else { break };
            let after = &rest[k + word.len()..];
            let end = after.find('}').expect("environment name closed");
            let name = &after[..end];
            if open {
                stack.push(name.to_owned());
            } else {
                assert_eq!(
                    stack.pop().as_deref(),
                    Some(name),
                    "unbalanced \\end{{{name}}} in\n{tex}"
                );
            }
            rest = &after[end..];
        }
        assert!(stack.is_empty(), "unclosed environments {stack:?} in\n{tex}");
        let mut depth = 0i32;
        let mut chars = tex.lines().flat_map(|l| {
            // A `%` comment line (the tags) ends at the line's end.
            let l = if l.trim_start().starts_with('%') { "" } else { l };
            l.chars().chain(std::iter::once('\n')).collect::<Vec<_>>()
        });
        while let Some(c) = chars.next() {
            match c {
                '\\' => {
                    chars.next();
                }
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    assert!(depth >= 0, "a `}}` closes nothing in\n{tex}");
                }
                _ => {}
            }
        }
        assert_eq!(depth, 0, "unbalanced braces in\n{tex}");
    }

    /// Every `_` and `%` of `tex` is escaped, except in `% cg:` tag lines and `_{` subscripts.
    fn assert_escaped(tex: &str) {
        for line in tex.lines().filter(|l| !l.starts_with("% cg: ")) {
            let b = line.as_bytes();
            for (k, &c) in b.iter().enumerate() {
                if c == b'_' || c == b'%' {
                    assert!(k > 0 && b[k - 1] == b'\\', "unescaped {:?} in {line:?}", c as char);
                }
            }
        }
    }

    #[test]
    fn the_balance_check_fails_on_broken_latex() {
        for bad in [
            "\\begin{a}\\end{b}",
            "\\begin{a}",
            "{x",
            "x}",
            "\\{x}",
            "\\begin{a}\\begin{b}\\end{a}\\end{b}",
        ] {
            assert!(std::panic::catch_unwind(|| assert_balanced(bad)).is_err(), "{bad}");
        }
        assert_balanced("\\begin{a} \\{ x \\} {y} \\\\ \n% cg: a_b {\n\\end{a}");
    }

    #[test]
    fn numbers_have_three_decimals_and_no_negative_zero() {
        assert_eq!(fixed(0.485_643), "0.486");
        assert_eq!(fixed(-0.8), "-0.800");
        assert_eq!(fixed(1.0), "1.000");
        assert_eq!(fixed(-0.0), "0.000");
        assert_eq!(fixed(-0.000_4), "0.000");
        assert_eq!(fixed(-0.000_6), "-0.001");
        assert_eq!(fixed(f32::NAN), "NaN");
        assert_eq!(tuple2(Vec2::new(0.3, 0.5)), "(0.300, 0.500)");
    }

    #[test]
    fn vertex_table_has_a_row_per_vertex_in_the_notation() {
        let md = vertex_table(&pyramid(), Lang::Ja, Format::Markdown);
        let lines: Vec<&str> = md.lines().collect();
        assert_eq!(lines.len(), 2 + 5, "{md}");
        assert_eq!(lines[2], "| V0 | (0.000, 1.000, 0.000) |");
        assert_eq!(lines[5], "| V3 | (-1.000, -0.800, 1.000) |");
        assert!(lines[0].contains("頂点"));
        assert!(vertex_table(&pyramid(), Lang::En, Format::Markdown).contains("| vertex |"));
    }

    #[test]
    fn face_table_prints_the_derived_normals() {
        let md = face_table(&pyramid(), Lang::En, Format::Markdown);
        let lines: Vec<&str> = md.lines().collect();
        assert_eq!(lines.len(), 2 + 6, "{md}");
        // (V3 − V0) × (V1 − V0) = (0, 2, 3.6), /|…| = (0, 0.4856, 0.8742): not the slide's 0.53, 0.85.
        assert_eq!(lines[2], "| F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } |");
        assert_eq!(lines[4], "| F2 | { V0, V1, V2 } | { 0.874, 0.486, 0.000 } |");
        assert_eq!(lines[6], "| F4 | { V1, V3, V2 } | { 0.000, -1.000, 0.000 } |");
        assert!(!md.contains("-0.000"), "{md}");
        assert_eq!(
            lines[0].matches('|').count(),
            4,
            "no note column without the student's normals"
        );
    }

    #[test]
    fn face_table_notes_the_students_differing_normals() {
        let mut p = pyramid();
        // The slide's table: F0–F3 do not follow from the vertices, F4 and F5 do.
        p.student_normals = Some(vec![
            Vec3::new(0.0, 0.53, 0.85),
            Vec3::new(0.0, 0.53, -0.85),
            Vec3::new(0.85, 0.53, 0.0),
            Vec3::new(-0.85, 0.53, 0.0),
            Vec3::new(0.0, -1.0, 0.0),
            Vec3::new(0.0, -1.0, 0.0),
        ]);
        let md = face_table(&p, Lang::En, Format::Markdown);
        let lines: Vec<&str> = md.lines().collect();
        assert_eq!(lines[0].matches('|').count(), 5, "{md}");
        for (k, line) in lines[2..].iter().enumerate() {
            assert_eq!(line.contains("differs"), k < 4, "F{k}: {line}");
        }
        assert!(
            lines[2].starts_with("| F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } |"),
            "{}",
            lines[2]
        );
        assert!(lines[2].contains("[0.000, 0.530, 0.850]"), "{}", lines[2]);
        let tex = face_table(&p, Lang::Ja, Format::Latex);
        assert_balanced(&tex);
        assert!(tex.contains("違います"));
    }

    #[test]
    fn a_face_without_a_normal_says_why() {
        let mut p = pyramid();
        p.faces.push([0, 0, 1]);
        p.faces.push([0, 1, 9]);
        p.derived_normals.push(None);
        p.derived_normals.push(None);
        let md = face_table(&p, Lang::En, Format::Markdown);
        assert!(md.contains("| F6 | { V0, V0, V1 } | no normal: degenerate face"), "{md}");
        assert!(md.contains("| F7 | { V0, V1, V9 } | no normal: vertex V9 does not exist"), "{md}");
        assert_balanced(&face_table(&p, Lang::Ja, Format::Latex));
    }

    #[test]
    fn a_matrix_shows_its_products_and_the_tagged_result() {
        let m = camera();
        let md = matrix(&m, Lang::En, Format::Markdown);
        assert!(md.contains("`T(0, 0, -camera_distance) · Rx(-camera_pitch)`"), "{md}");
        assert!(md.contains("`T(0, 0, -15) · Rx(30°)`"), "{md}");
        assert!(md.contains("\\cos(-\\mathit{camera\\_pitch})"), "{md}");
        // The tag line, then `$$`, then the result: T(0, 0, -15) · Rx(30°) by hand.
        assert!(md.contains("<!-- cg: a2.view.start -->\n$$\n= \\begin{pmatrix}"), "{md}");
        let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
        let want =
            [[1.0, 0.0, 0.0, 0.0], [0.0, c, -s, 0.0], [0.0, s, c, -15.0], [0.0, 0.0, 0.0, 1.0]];
        let got = tagged_matrix(&md, "<!-- cg: a2.view.start -->");
        assert_eq!(got.len(), 4);
        for (r, row) in got.iter().enumerate() {
            assert_eq!(row.len(), 4);
            for (k, x) in row.iter().enumerate() {
                assert!((x - want[r][k]).abs() < 1e-4, "({r}, {k}): {x} vs {}", want[r][k]);
            }
        }
        // Each factor appears numerically before the result, after its own tag: two symbolic
        // pmatrices, the factors' tag and two numeric ones, then the result's tag.
        let factors_tag = md.find("<!-- cg: a2.view.start.factors -->").unwrap();
        let result_tag = md.find("<!-- cg: a2.view.start -->").unwrap();
        let count = |s: &str| s.matches("\\begin{pmatrix}").count();
        assert_eq!(count(&md[..factors_tag]), 2, "two symbolic factors: {md}");
        assert_eq!(count(&md[factors_tag..result_tag]), 2, "two numeric factors: {md}");
        let tex = matrix(&m, Lang::Ja, Format::Latex);
        assert_balanced(&tex);
        assert_escaped(&tex);
        assert!(tex.contains("% cg: a2.view.start\n\\[\n= \\begin{pmatrix}"), "{tex}");
        assert_eq!(tagged_matrix(&tex, "% cg: a2.view.start\n"), got);
        let both = matrices(&[m.clone(), m], Lang::En, Format::Markdown);
        assert_eq!(both.matches("<!-- cg: a2.view.start -->").count(), 2);
    }

    #[test]
    fn long_products_wrap_in_latex_and_stay_balanced() {
        let mut m = camera();
        for k in 0..5 {
            m.numeric.push(Factor::rotate_y_deg(10.0 * k as f32));
            m.symbolic
                .push(Factor::rotate(Axis::Y, Param::sym(format!("yaw_{k}"), 10.0 * k as f32)));
        }
        m.numeric.push(Factor::rotate_deg(20.0, Vec3::new(1.0, 1.0, 0.0)));
        m.symbolic
            .push(Factor::rotate(Axis::Any(Vec3::new(1.0, 1.0, 0.0)), Param::sym("spin", 20.0)));
        let tex = matrix(&m, Lang::En, Format::Latex);
        assert_balanced(&tex);
        assert!(tex.contains("\\begin{gathered}"), "{tex}");
        assert!(tex.contains("yaw\\_3"), "{tex}");
    }

    #[test]
    fn the_model_transform_is_tagged_a1_transform() {
        let mut p = pyramid();
        let none = transform(&p, Lang::En, Format::Markdown);
        assert!(!none.contains("cg:"), "{none}");
        assert!(none.contains("no model transform"));
        p.transform =
            Some(MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, 1.0, 0.0))));
        let md = transform(&p, Lang::Ja, Format::Markdown);
        let got = tagged_matrix(&md, "<!-- cg: a1.transform -->");
        assert_eq!(got[1], vec![0.0, 1.0, 0.0, 1.0], "{md}");
        assert!(!md.contains("変数を使った積"), "no symbols, no symbolic product: {md}");
        let tex = transform(&p, Lang::Ja, Format::Latex);
        assert_balanced(&tex);
        assert!(tex.contains("% cg: a1.transform"));
    }

    #[test]
    fn names_with_underscores_and_percent_are_escaped() {
        let m = camera();
        let tex = variables(&m.variables, Lang::En, Format::Latex);
        assert_balanced(&tex);
        assert_escaped(&tex);
        assert!(tex.contains("\\texttt{camera\\_pitch}"), "{tex}");
        assert!(tex.contains("100\\% no\\_limit"), "{tex}");
        let md = variables(&m.variables, Lang::Ja, Format::Markdown);
        assert!(md.contains("| `camera_pitch` | 右ドラッグで変化"), "{md}");
        assert!(variables(&[], Lang::En, Format::Markdown).contains("no variables"));
        let tex = matrix(&m, Lang::En, Format::Latex);
        assert!(tex.contains("100\\% of\\_distance"), "{tex}");
    }

    pub(crate) fn texture_data() -> TextureData {
        let rows = (0..=10)
            .flat_map(|j| (0..=10).map(move |i| (i, j)))
            .map(|(i, j)| TexRow {
                i,
                j,
                position: Vec3::new(i as f32 - 5.0, 0.0, j as f32 - 5.0),
                tex: if (i, j) == (3, 5) {
                    vec![Vec2::new(0.3, 0.5), Vec2::new(1.0, 0.5)]
                } else {
                    vec![Vec2::new(0.25 + 0.05 * i as f32, 0.5 + 0.05 * j as f32)]
                },
            })
            .collect();
        TextureData {
            rows,
            formula: Text::new(
                "s = 0.25 + 0.05 i, t = 0.5 + 0.05 j",
                "s = 0.25 + 0.05 i, t = 0.5 + 0.05 j",
            ),
            region: (Vec2::new(0.25, 0.5), Vec2::new(0.75, 1.0)),
            image: Texture::new(200, 100, vec![[255, 255, 255, 255]; 200 * 100])
                .expect("a valid texture"),
            sampler: Some(Sampler {
                filter: Filter::Nearest,
                wrap_u: Wrap::Clamp,
                wrap_v: Wrap::Repeat,
            }),
            texels_per_square: Vec2::new(10.0, 5.0),
        }
    }

    #[test]
    fn the_sampler_line_names_the_opengl_modes_and_the_pixels_per_square() {
        let mut t = texture_data();
        let en = sampler(&t, Lang::En, Format::Markdown).unwrap();
        assert_eq!(
            en,
            "Filter: GL_NEAREST (Filter::Nearest). Wrap: GL_CLAMP_TO_EDGE (Wrap::Clamp) along s, \
             GL_REPEAT (Wrap::Repeat) along t. One ground square shows 10 × 5 pixels of \
             the image.\n"
        );
        let ja = sampler(&t, Lang::Ja, Format::Latex).unwrap();
        assert!(ja.contains("s 方向 GL\\_CLAMP\\_TO\\_EDGE"), "{ja}");
        assert!(ja.contains("10 × 5 画素"), "{ja}");
        t.sampler = None;
        assert_eq!(sampler(&t, Lang::En, Format::Markdown), None);
    }

    #[test]
    fn texture_table_has_every_grid_vertex() {
        let t = texture_data();
        let md = tex_table(&t, Lang::En, Format::Markdown);
        let lines: Vec<&str> = md.lines().collect();
        assert_eq!(lines.len(), 2 + 121);
        assert!(
            lines.contains(&"| 3 | 5 | (-2.000, 0.000, 0.000) | (0.300, 0.500) / (1.000, 0.500) |"),
            "{md}"
        );
        assert_eq!(lines[2], "| 0 | 0 | (-5.000, 0.000, -5.000) | (0.250, 0.500) |");
        assert!(!md.contains("-0.000"));
        let tex = tex_table(&t, Lang::Ja, Format::Latex);
        assert_balanced(&tex);
        assert_eq!(tex.matches(" \\\\\n").count(), 1 + 121, "header and one line per vertex");
        let f = formula(&t, Lang::En, Format::Markdown);
        assert!(f.contains("s \\in [0.250, 0.750],\\ t \\in [0.500, 1.000]"), "{f}");
        assert_balanced(&formula(&t, Lang::Ja, Format::Latex));
    }

    #[test]
    fn latex_fragments_are_balanced() {
        let mut p = pyramid();
        p.transform =
            Some(MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, 1.0, 0.0))));
        for lang in [Lang::Ja, Lang::En] {
            for tex in [
                vertex_table(&p, lang, Format::Latex),
                face_table(&p, lang, Format::Latex),
                transform(&p, lang, Format::Latex),
                matrices(&[camera()], lang, Format::Latex),
                matrices(&[], lang, Format::Latex),
            ] {
                assert_balanced(&tex);
            }
        }
    }
}
