//! The template's values: every placeholder of `report-template/` filled from the derived data,
//! in the report's language and format. A part that could not be derived (a task still a stub)
//! is filled with a visible "not derived yet: a1.t2 …" so the report still compiles and says
//! what is missing.

use std::collections::BTreeMap;

use cg_core::lang::{Lang, t};

use crate::derive::Missing;
use crate::figures::{self, View};
use crate::formula;
use crate::model::Derived;
use crate::periods;
use crate::shading;
use crate::tables;
use crate::template::{Format, latex_escape, not_drawn, not_yet};

/// The files the figures and images of a filled report refer to, relative to the report (they
/// are written next to it by [`crate::app`]).
pub mod files {
    use crate::figures::View;

    /// The SVG of a view of the polygon model.
    #[must_use]
    pub fn view_svg(view: View) -> &'static str {
        match view {
            View::Front => "a1-front.svg",
            View::Top => "a1-top.svg",
            View::Side => "a1-side.svg",
            View::Perspective => "a1-perspective.svg",
        }
    }

    /// The prepared image of assignment 4.
    pub const TEXTURE_PNG: &str = "a4-texture.png";
    /// The prepared image with the mapped rectangle outlined.
    pub const TEXTURE_SVG: &str = "a4-region.svg";

    /// The rendered result of assignment `id` (`a1` … `a4`, `s`).
    #[must_use]
    pub fn render_png(id: &str) -> String {
        format!("render-{id}.png")
    }
}

/// The views every report shows, in order.
pub const VIEWS: [View; 4] = [View::Front, View::Top, View::Side, View::Perspective];

/// What the template's placeholders are filled with, besides the derived data.
#[derive(Clone, Debug, Default)]
pub struct Context {
    /// The student number, if known.
    pub student: Option<String>,
    /// The variant table, if known.
    pub table: Option<String>,
    /// Each assignment's text (`a1` … `a4`, `s`), as `cg assignment` prints it.
    pub assignments: BTreeMap<String, String>,
    /// The assignments whose rendered image was written (`a1` … `a4`, `s`).
    pub renders: Vec<String>,
    /// Whether drawing was turned off (`--no-render`): the rendered images' places say so,
    /// instead of "not derived yet".
    pub no_render: bool,
    /// The student's sampler (a4.t3) when the rest of a4 did not derive: it needs nothing of
    /// a4.t1 or a4.t2, so its fragment shows it all the same.
    pub sampler: Option<cg_core::texture::Sampler>,
    /// What could not be derived, and why.
    pub missing: Vec<Missing>,
    /// The student's assignment, when known: what follows from it alone (the periods of `a3`,
    /// [`crate::periods`]) is filled from it, even while the student's functions are stubs.
    pub variants: Option<cg_assign::Variants>,
}

/// "Not derived yet", naming the tasks of `part` (`a1`, …; `a1.t4` for one task) that are
/// missing.
fn missing_text(ctx: &Context, part: &str, lang: Lang, format: Format) -> String {
    let why: Vec<String> =
        ctx.missing.iter().filter(|m| m.task.starts_with(part)).map(|m| m.message(lang)).collect();
    let why = if why.is_empty() { part.to_owned() } else { why.join("; ") };
    not_yet(&why, lang, format)
}

/// Plain text (an assignment's description) as a block that keeps its lines.
fn text_block(text: &str, format: Format) -> String {
    match format {
        Format::Markdown => format!("```text\n{}\n```", text.trim_end()),
        Format::Latex => {
            let mut out = String::from("\\begin{quote}\\small\n");
            for line in text.trim_end().lines() {
                let body = line.trim_start();
                let indent = line.len() - body.len();
                if body.is_empty() {
                    out.push_str("\\medskip\n");
                    continue;
                }
                if indent > 0 {
                    out.push_str(&format!("\\hspace*{{{:.1}em}}", indent as f32 * 0.5));
                }
                out.push_str(&latex_escape(body));
                out.push_str("\\par\n");
            }
            out.push_str("\\end{quote}");
            out
        }
    }
}

/// An image file (a PNG or an SVG written next to the report).
fn image(file: &str, caption: &str, format: Format) -> String {
    match format {
        Format::Markdown => format!("![{caption}]({file})"),
        Format::Latex => format!(
            "\\begin{{center}}\n\\includegraphics[width=0.6\\linewidth]{{{file}}}\\\\\n{}\n\\end{{center}}",
            latex_escape(caption)
        ),
    }
}

/// Every placeholder's value for `derived` in `lang` and `format`.
#[must_use]
pub fn values(
    derived: &Derived,
    ctx: &Context,
    lang: Lang,
    format: Format,
) -> BTreeMap<String, String> {
    let mut v = BTreeMap::new();
    let mut put = |k: &str, s: String| {
        v.insert(k.to_owned(), s);
    };
    let unknown = t("（未設定: `cg assignment --save`）", "(not set: `cg assignment --save`)");
    let unknown = unknown.get(lang);
    let plain = |s: &str| match format {
        Format::Markdown => s.to_owned(),
        Format::Latex => latex_escape(s),
    };
    put("student", plain(ctx.student.as_deref().unwrap_or(unknown)));
    put("table", plain(ctx.table.as_deref().unwrap_or(unknown)));
    for id in cg_assign::Which::ALL.iter().filter(|w| w.in_report()).map(|w| w.id()) {
        let text = ctx
            .assignments
            .get(id)
            .map_or_else(|| missing_text(ctx, id, lang, format), |t| text_block(t, format));
        put(&format!("{id}.assignment"), text);
        let render = if ctx.renders.iter().any(|r| r == id) {
            let caption = match id {
                "s" => t(
                    "実行結果: 左からフラット・グロー・フォンシェーディング",
                    "the result: flat, Gouraud and Phong shading, from the left",
                ),
                _ => t("実行結果", "the result"),
            };
            image(&files::render_png(id), caption.get(lang), format)
        } else if ctx.no_render {
            not_drawn("--no-render", lang, format)
        } else {
            missing_text(ctx, id, lang, format)
        };
        put(&format!("{id}.render"), render);
    }

    match &derived.a1 {
        Some(p) => {
            put("a1.vertex_table", tables::vertex_table(p, lang, format));
            put("a1.face_table", tables::face_table(p, lang, format));
            let figs: Vec<String> = VIEWS
                .iter()
                .map(|&view| match format {
                    Format::Markdown => {
                        format!("![{}]({})", view.title().get(lang), files::view_svg(view))
                    }
                    Format::Latex => figures::tikz(&figures::layout(p, view), lang),
                })
                .collect();
            put("a1.figures", figs.join("\n\n"));
            put(
                "a1.transform",
                if p.transform.is_some() {
                    tables::transform(p, lang, format)
                } else {
                    missing_text(ctx, "a1.t4", lang, format)
                },
            );
        }
        None => {
            for k in ["a1.vertex_table", "a1.face_table", "a1.figures", "a1.transform"] {
                put(k, missing_text(ctx, "a1", lang, format));
            }
        }
    }

    match &derived.a2 {
        Some(c) => {
            let vars = c.matrices.first().map(|m| m.variables.as_slice()).unwrap_or_default();
            put("a2.variables", tables::variables(vars, lang, format));
            put("a2.matrices", tables::matrices(&c.matrices, lang, format));
        }
        None => {
            for k in ["a2.variables", "a2.matrices"] {
                put(k, missing_text(ctx, "a2", lang, format));
            }
        }
    }

    // The periods follow from the assignment alone: a tagged table that `report check` reads
    // back; without the assignment, the derived part's words.
    match (&ctx.variants, &derived.a3) {
        (Some(a), _) => put("a3.periods", periods::values(&a.a3, lang, format)),
        (None, Some(a)) => put("a3.periods", plain(a.periods.get(lang))),
        (None, None) => put("a3.periods", missing_text(ctx, "a3", lang, format)),
    }
    match &derived.a3 {
        Some(a) => {
            let all: Vec<_> = a.objects.iter().flat_map(|(_, ms)| ms.iter().cloned()).collect();
            put("a3.matrices", tables::matrices(&all, lang, format));
        }
        None => put("a3.matrices", missing_text(ctx, "a3", lang, format)),
    }

    match &derived.a4 {
        Some(tex) => {
            put("a4.formula", formula::values(tex, lang, format));
            put("a4.table", tables::tex_table(tex, lang, format));
            put(
                "a4.sampler",
                tables::sampler(tex, lang, format)
                    .unwrap_or_else(|| missing_text(ctx, "a4.t3", lang, format)),
            );
            put(
                "a4.figure",
                match format {
                    Format::Markdown => format!(
                        "![{}]({})",
                        t("貼り付けた範囲", "the mapped region").get(lang),
                        files::TEXTURE_SVG
                    ),
                    Format::Latex => figures::texture_tikz(tex, files::TEXTURE_PNG, lang),
                },
            );
        }
        None => {
            for k in ["a4.formula", "a4.table", "a4.figure"] {
                put(k, missing_text(ctx, "a4", lang, format));
            }
            // The sampler needs nothing of the rest: said on its own.
            let sampler = match ctx.sampler {
                Some(s) => tables::sampler_text(s, None, lang, format),
                None if ctx.missing.iter().any(|m| m.task.starts_with("a4.t3")) => {
                    missing_text(ctx, "a4.t3", lang, format)
                }
                None => missing_text(ctx, "a4", lang, format),
            };
            put("a4.sampler", sampler);
        }
    }

    match &derived.s {
        Some(d) => {
            for (k, value) in shading::values(d, lang, format) {
                put(k, value);
            }
        }
        None => {
            for k in shading::KEYS {
                put(k, missing_text(ctx, "s", lang, format));
            }
        }
    }
    v
}
