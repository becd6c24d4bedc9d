//! The texture formula of assignment 4 (`a4.formula`): the texture coordinates `s` and `t` of
//! the ground vertex `(i, j)` as formulas in `i` and `j`, written after a tag so that
//! `report check` reads them back and evaluates them at every ground vertex.
//!
//! ```text
//! <!-- cg: a4.formula -->                        the tag (LaTeX: % cg: a4.formula)
//! $$
//! \begin{aligned}
//! s &= 0.25 + 0.025 \cdot i \\                   each equation `s = …`, `t = …` (or `s(i, j) = …`)
//! t &= 0.625 - 0.025 \cdot j
//! \end{aligned}
//! $$
//! ```
//!
//! The formula is what follows the tag up to a blank line after it, the next tag or a heading
//! (at most [`REGION_LINES`] lines). An equation starts at `s =` or `t =` and ends at a line
//! break (unless the line ends in an operator), `,`, `;`, a full stop, `\\` or `\quad`; its
//! expression is read by [`expr`]: `s = 0.25 + i/16`, `t = (j + 2) / 8 * 0.5`, `s = 0.125 i`,
//! `\frac{i}{16}`, `(i \bmod 5)`. `check` evaluates it against the texture coordinates the kit
//! derived (the table's) and names the first vertex where it is wrong; an equation that does not
//! read is a note naming its line.

use cg_core::lang::{Lang, t};
use cg_harness::Text;

use crate::model::TextureData;
use crate::shading::{is_heading, tag_on};
use crate::tables;
use crate::template::Format;

mod check;
pub mod expr;

pub(crate) use check::verify;
use expr::{Expr, Tok};

/// The tag of the texture formula.
pub const TAG: &str = "a4.formula";
/// The most lines after the tag that are read as the formula.
pub const REGION_LINES: usize = 16;

/// One equation after the tag: `s = …` or `t = …`.
#[derive(Clone, Debug, PartialEq)]
pub struct Equation {
    /// The 1-based line where it starts.
    pub line: usize,
    /// `'s'` or `'t'`.
    pub name: char,
    /// The equation as written (clipped), for messages.
    pub text: String,
    /// The expression, or why it does not read.
    pub expr: Result<Expr, cg_harness::Text>,
}

/// A tagged texture formula as written.
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedFormula {
    /// The 1-based line of the tag.
    pub line: usize,
    /// The equations found after it, in order.
    pub equations: Vec<Equation>,
}

impl ParsedFormula {
    /// The first equation for `name` (`'s'` or `'t'`).
    #[must_use]
    pub fn equation(&self, name: char) -> Option<&Equation> {
        self.equations.iter().find(|e| e.name == name)
    }
}

/// Every tagged texture formula of `lines` (the report's lines, as the reader normalises them).
#[must_use]
pub fn parse_formulas(lines: &[String]) -> Vec<ParsedFormula> {
    let mut out = Vec::new();
    for (k, line) in lines.iter().enumerate() {
        if tag_on(line).as_deref() != Some(TAG) {
            continue;
        }
        let mut region: Vec<(usize, &str)> = Vec::new();
        for (j, next) in lines.iter().enumerate().skip(k + 1).take(REGION_LINES) {
            if tag_on(next).is_some() || is_heading(next) {
                break;
            }
            if next.trim().is_empty() && region.iter().any(|(_, l)| l.contains('=')) {
                break;
            }
            region.push((j + 1, next));
        }
        let Some(&(first, _)) = region.first() else {
            out.push(ParsedFormula { line: k + 1, equations: Vec::new() });
            continue;
        };
        let text: Vec<&str> = region.iter().map(|(_, l)| *l).collect();
        out.push(ParsedFormula { line: k + 1, equations: equations(&text.join("\n"), first) });
    }
    out
}

/// The equations `s = …` and `t = …` of `text` (its first line is `first_line`).
#[must_use]
pub fn equations(text: &str, first_line: usize) -> Vec<Equation> {
    let toks = expr::tokens(text, first_line);
    let lines: Vec<&str> = text.lines().collect();
    let mut out = Vec::new();
    let mut k = 0;
    while k < toks.len() {
        let Some(after) = equation_start(&toks, k) else {
            k += 1;
            continue;
        };
        let (line, Tok::Word(name)) = &toks[k] else {
            k += 1;
            continue;
        };
        let name = name.chars().next().unwrap_or('s');
        // The expression: up to a separator, the next equation, or a line break that does not
        // follow an operator.
        let mut body: Vec<Tok> = Vec::new();
        let mut end = after;
        while let Some((_, tok)) = toks.get(end) {
            match tok {
                Tok::Sep => break,
                Tok::Newline => {
                    let open = matches!(
                        body.last(),
                        None | Some(Tok::Op(_) | Tok::Open(_) | Tok::Frac | Tok::Eq)
                    );
                    if !open {
                        break;
                    }
                }
                _ if equation_start(&toks, end).is_some() => break,
                t => body.push(t.clone()),
            }
            end += 1;
        }
        let source = lines.get(line.saturating_sub(first_line)).copied().unwrap_or("");
        out.push(Equation { line: *line, name, text: shown(source), expr: expr::parse(&body) });
        k = end.max(k + 1);
    }
    out
}

/// A line of a formula as messages quote it: without the math delimiters (`$`, `\[`, `\]`), the
/// alignment marks `&` and a closing `\\`, clipped.
fn shown(line: &str) -> String {
    let mut s = line.replace(['$', '&'], "").replace("\\[", "").replace("\\]", "");
    s = s.trim().trim_end_matches("\\\\").trim().to_owned();
    crate::parse::clip(&s)
}

/// Where the expression of an equation starting at `k` begins: after `s =`, `t =`,
/// `s(i, j) =`, `s_{ij} =`; `None` when no equation starts there.
fn equation_start(toks: &[(usize, Tok)], k: usize) -> Option<usize> {
    let (_, Tok::Word(w)) = toks.get(k)? else { return None };
    if w != "s" && w != "t" {
        return None;
    }
    let mut at = k + 1;
    // `s(i, j)`, `s_{ij}` (the `_` reads as another symbol): up to the `=` on the same line.
    if !matches!(toks.get(at), Some((_, Tok::Eq))) {
        let arguments = toks[at..].iter().take(8).position(|(_, t)| matches!(t, Tok::Eq))?;
        let allowed = toks[at..at + arguments].iter().all(|(_, t)| {
            matches!(t, Tok::Open(_) | Tok::Close(_) | Tok::Var(_) | Tok::Sep)
                || matches!(t, Tok::Other(o) if o == "_")
        });
        if !allowed || arguments == 0 {
            return None;
        }
        at += arguments;
    }
    matches!(toks.get(at), Some((_, Tok::Eq))).then_some(at + 1)
}

/// The kit's formula in `i` and `j` from the assignment's words (`In i and j: s = …, t = ….`),
/// each expression as written there; `None` when the words do not hold it (or it does not
/// read back).
fn kit_formula(tex: &TextureData) -> Option<(String, String)> {
    let rest = tex.formula.en.split_once("In i and j: ")?.1;
    let (both, _) = rest.split_once(". Range")?;
    let (s, t) = both.split_once(", t = ")?;
    let s = s.strip_prefix("s = ")?;
    let reads = |e: &str| expr::parse(&body(e)).is_ok();
    (reads(s) && reads(t)).then(|| (s.to_owned(), t.to_owned()))
}

/// The tokens of an expression alone.
fn body(e: &str) -> Vec<Tok> {
    expr::tokens(e, 1).into_iter().map(|(_, t)| t).filter(|t| *t != Tok::Newline).collect()
}

/// An expression of the assignment's words as math: `0.25 + 0.025·(i mod 5)` →
/// `0.25 + 0.025 \cdot (i \bmod 5)`.
fn math(e: &str) -> String {
    e.replace('·', " \\cdot ").replace('−', "-").replace(" mod ", " \\bmod ")
}

/// The tagged formula: `s` and `t` in `i` and `j`, one equation a line.
#[must_use]
pub fn block(tex: &TextureData, format: Format) -> Option<String> {
    let (s, t) = kit_formula(tex)?;
    let body =
        format!("\\begin{{aligned}}\ns &= {} \\\\\nt &= {}\n\\end{{aligned}}", math(&s), math(&t));
    Some(match format {
        Format::Markdown => format!("<!-- cg: {TAG} -->\n$$\n{body}\n$$\n"),
        Format::Latex => format!("% cg: {TAG}\n\\[\n{body}\n\\]\n"),
    })
}

/// The assignment's words without their sentence of the formula in `i` and `j` (`In i and j:
/// s = …, t = ….`), which the tagged formula states instead: one place to edit, and that one
/// checked. `None` when the words do not hold it as expected.
fn words_without_formula(words: &Text) -> Option<Text> {
    let cut = |text: &str, start: &str, end: &str| -> Option<String> {
        let a = text.find(start)?;
        let b = a + text[a..].find(end)? + end.len();
        Some(format!("{}{}", &text[..a], text[b..].trim_start()))
    };
    Some(Text::new(cut(&words.ja, "i と j で書くと", "。")?, cut(&words.en, "In i and j:", ". ")?))
}

/// The placeholder `a4.formula`: the formula and the mapped region in words
/// ([`tables::formula`]), then the tagged formula in `i` and `j` that `report check` evaluates
/// (the words leave that formula to it).
#[must_use]
pub fn values(tex: &TextureData, lang: Lang, format: Format) -> String {
    let (Some(b), Some(words)) = (block(tex, format), words_without_formula(&tex.formula)) else {
        return tables::formula(tex, lang, format);
    };
    let words = tables::formula_words(&words, tex, lang, format);
    let lead = t(
        "i と j で書いた式（report check がすべての格子点で確かめます）:",
        "In i and j (report check evaluates it at every grid vertex):",
    );
    let edge = far_edge(tex).map(|e| format!("\n{}\n", e.get(lang))).unwrap_or_default();
    format!("{words}\n{}\n\n{b}{edge}", lead.get(lang))
}

/// For a formula with `mod` (a repeated region): how it reads at a block's far edge, where the
/// `mod` is 0 but the squares before the edge take its divisor (the assignment's `i % k + 1` for
/// a square's far corners), with the ground's far corner as the example, its coordinates from
/// the table. Read literally there, the formula would give the corner (0, 0)'s coordinates.
fn far_edge(tex: &TextureData) -> Option<Text> {
    let (s, t) = kit_formula(tex)?;
    if !s.contains(" mod ") && !t.contains(" mod ") {
        return None;
    }
    let corner = tex.rows.iter().max_by_key(|r| (r.i, r.j))?;
    let (i, j) = (corner.i, corner.j);
    let st = tables::tuple2(*corner.tex.first()?);
    Some(Text::new(
        format!(
            "まとまりの奥・右の端の格子点（i や j は 0 でないのに mod が 0 になる所）では、端の手前の四角形については、その mod を割る数（mod 2 なら 2）と読みます（課題のとおり四角形の右・奥の頂点は (i mod k) + 1。report check もそう読みます）。例えば地面の角 ({i}, {j}) は (s, t) = {st} です。"
        ),
        format!(
            "At a grid vertex on a block's far edge (where a mod is 0 although i or j is not), read that mod as its divisor (2 for mod 2) for the squares before the edge (a square's far corners use (i mod k) + 1, as the assignment says; report check reads it so too): the ground's corner ({i}, {j}), for example, has (s, t) = {st}."
        ),
    ))
}

#[cfg(test)]
mod tests;
