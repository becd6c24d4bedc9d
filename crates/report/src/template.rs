//! The report template (`report-template/`, Markdown and LaTeX, Japanese and English) and its
//! filling: every `{{name}}` placeholder is replaced by the derived table, figure, matrix or
//! image of that name.

use std::collections::BTreeMap;

use cg_core::lang::{Lang, Text};

/// Markdown or LaTeX.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Format {
    /// `report.md`: GitHub-style Markdown with `$$ … $$` math and SVG figures.
    Markdown,
    /// `report.tex`: LaTeX for LuaLaTeX, TikZ figures.
    Latex,
}

impl Format {
    /// The file name of the filled report.
    #[must_use]
    pub fn file_name(self) -> &'static str {
        match self {
            Format::Markdown => "report.md",
            Format::Latex => "report.tex",
        }
    }
}

/// The template text, compiled into the kit.
#[must_use]
pub fn template(lang: Lang, format: Format) -> &'static str {
    match (lang, format) {
        (Lang::Ja, Format::Markdown) => include_str!("../../../report-template/ja/report.md"),
        (Lang::En, Format::Markdown) => include_str!("../../../report-template/en/report.md"),
        (Lang::Ja, Format::Latex) => include_str!("../../../report-template/ja/report.tex"),
        (Lang::En, Format::Latex) => include_str!("../../../report-template/en/report.tex"),
    }
}

/// Every placeholder a template uses, with the 1-based line of its first use, in order.
#[must_use]
pub fn placeholders(text: &str) -> Vec<(usize, String)> {
    let mut found: Vec<(usize, String)> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let mut rest = line;
        while let Some(start) = rest.find("{{") {
            let after = &rest[start + 2..];
            let Some(end) = after.find("}}") else { break };
            let name = after[..end].trim().to_owned();
            if !found.iter().any(|(_, n)| *n == name) {
                found.push((i + 1, name));
            }
            rest = &after[end + 2..];
        }
    }
    found
}

/// A placeholder the values do not provide.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "line {line}: the template asks for {{{{{name}}}}}, which the report checker does not know (known: {known})"
)]
pub struct TemplateError {
    /// The line of the placeholder.
    pub line: usize,
    /// Its name.
    pub name: String,
    /// The names that exist, comma-separated.
    pub known: String,
}

/// Replaces every `{{name}}` in `text` by `values[name]`.
///
/// # Errors
/// The first placeholder `values` does not know, with its line and the known names.
pub fn fill(text: &str, values: &BTreeMap<String, String>) -> Result<String, TemplateError> {
    for (line, name) in placeholders(text) {
        if !values.contains_key(&name) {
            let known: Vec<&str> = values.keys().map(String::as_str).collect();
            return Err(TemplateError { line, name, known: known.join(", ") });
        }
    }
    let mut out = String::with_capacity(text.len() * 2);
    let mut rest = text;
    while let Some(start) = rest.find("{{") {
        out.push_str(&rest[..start]);
        let after = &rest[start + 2..];
        match after.find("}}") {
            Some(end) => {
                let name = after[..end].trim();
                out.push_str(values.get(name).map_or("", String::as_str));
                rest = &after[end + 2..];
            }
            None => {
                out.push_str("{{");
                rest = after;
            }
        }
    }
    out.push_str(rest);
    Ok(out)
}

/// The text put where a value could not be derived yet (a task still `todo!()`), in the
/// report's language and format: it says what is missing and why, and stays visible.
#[must_use]
pub fn not_yet(why: &str, lang: Lang, format: Format) -> String {
    let text =
        Text::new(format!("（まだ導出できません: {why}）"), format!("(not derived yet: {why})"));
    let text = text.get(lang);
    match format {
        Format::Markdown => format!("> {text}"),
        Format::Latex => format!("\\textbf{{{}}}", latex_escape(text)),
    }
}

/// The text put where an assignment's result is not drawn (`why`: `--no-render`), in the
/// report's language and format, as visible as [`not_yet`]'s.
#[must_use]
pub fn not_drawn(why: &str, lang: Lang, format: Format) -> String {
    let text = Text::new(format!("（描いていません: {why}）"), format!("(not drawn: {why})"));
    let text = text.get(lang);
    match format {
        Format::Markdown => format!("> {text}"),
        Format::Latex => format!("\\textbf{{{}}}", latex_escape(text)),
    }
}

/// Text made safe for LaTeX: `\ { } $ & # ^ _ % ~` escaped, `--` kept as two hyphens (a command
/// line's `--release`, not an en dash), and the symbols the text fonts lack (`≤ ≥ θ φ ω π η ⁶ ⁿ
/// ₁ …`) set in math or as super- and subscripts.
#[must_use]
pub fn latex_escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '{' | '}' | '$' | '&' | '#' | '_' | '%' => {
                out.push('\\');
                out.push(c);
            }
            '^' => out.push_str("\\textasciicircum{}"),
            '~' => out.push_str("\\textasciitilde{}"),
            '-' if chars.peek() == Some(&'-') => out.push_str("-{}"),
            '≤' => out.push_str("$\\le$"),
            '≥' => out.push_str("$\\ge$"),
            '≠' => out.push_str("$\\ne$"),
            '±' => out.push_str("$\\pm$"),
            '∈' => out.push_str("$\\in$"),
            '∞' => out.push_str("$\\infty$"),
            'α' => out.push_str("$\\alpha$"),
            'β' => out.push_str("$\\beta$"),
            'γ' => out.push_str("$\\gamma$"),
            'θ' => out.push_str("$\\theta$"),
            'φ' => out.push_str("$\\varphi$"),
            'ω' => out.push_str("$\\omega$"),
            'π' => out.push_str("$\\pi$"),
            'η' => out.push_str("$\\eta$"),
            'ⁿ' => out.push_str("\\textsuperscript{n}"),
            '₀'..='₉' => {
                let digit = char::from_digit(c as u32 - '₀' as u32, 10).unwrap_or('0');
                out.push_str(&format!("\\textsubscript{{{digit}}}"));
            }
            '⁰' | '¹' | '²' | '³' | '⁴' | '⁵' | '⁶' | '⁷' | '⁸' | '⁹' | '⁻' => {
                let plain = match c {
                    '⁰' => '0',
                    '¹' => '1',
                    '²' => '2',
                    '³' => '3',
                    '⁴' => '4',
                    '⁵' => '5',
                    '⁶' => '6',
                    '⁷' => '7',
                    '⁸' => '8',
                    '⁹' => '9',
                    _ => '-',
                };
                out.push_str(&format!("\\textsuperscript{{{plain}}}"));
            }
            _ => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_assignment_in_the_report_has_its_text_and_picture_in_every_template() {
        for lang in [Lang::Ja, Lang::En] {
            for format in [Format::Markdown, Format::Latex] {
                let names: Vec<String> =
                    placeholders(template(lang, format)).into_iter().map(|(_, n)| n).collect();
                for which in cg_assign::Which::ALL.iter().filter(|w| w.in_report()) {
                    for part in ["assignment", "render"] {
                        let name = format!("{which}.{part}");
                        assert!(names.contains(&name), "{lang:?} {format:?}: no {{{{{name}}}}}");
                    }
                }
                // And none for an assignment the list does not have.
                assert!(!names.iter().any(|n| n.starts_with("a9.")));
            }
        }
    }

    #[test]
    fn every_template_uses_the_same_placeholders() {
        let reference: Vec<String> = placeholders(template(Lang::Ja, Format::Markdown))
            .into_iter()
            .map(|(_, n)| n)
            .collect();
        assert!(reference.contains(&"a1.face_table".to_owned()), "{reference:?}");
        for (lang, format) in
            [(Lang::En, Format::Markdown), (Lang::Ja, Format::Latex), (Lang::En, Format::Latex)]
        {
            let names: Vec<String> =
                placeholders(template(lang, format)).into_iter().map(|(_, n)| n).collect();
            assert_eq!(names, reference, "{lang} {format:?}");
        }
    }

    #[test]
    fn filling_replaces_every_placeholder_and_names_unknown_ones() {
        let values: BTreeMap<String, String> =
            [("a".to_owned(), "A".to_owned()), ("b.c".to_owned(), "{{not again}}".to_owned())]
                .into();
        assert_eq!(fill("x {{a}} y {{ b.c }} {{a}}", &values).unwrap(), "x A y {{not again}} A");
        let e = fill("ok\nthen {{nope}}", &values).unwrap_err();
        assert_eq!((e.line, e.name.as_str()), (2, "nope"));
        assert!(e.to_string().contains("known: a, b.c"), "{e}");
        assert_eq!(fill("a {{ unclosed", &values).unwrap(), "a {{ unclosed");
    }

    #[test]
    fn latex_text_is_escaped_and_missing_values_stay_visible() {
        assert_eq!(latex_escape("a_1 & 50% {x}"), "a\\_1 \\& 50\\% \\{x\\}");
        assert_eq!(latex_escape("--release, 0 ≤ θ"), "-{}-release, 0 $\\le$ $\\theta$");
        assert_eq!(latex_escape("10⁻⁶"), "10\\textsuperscript{-}\\textsuperscript{6}");
        assert_eq!(
            latex_escape("θ₁, (R·V)ⁿ"),
            "$\\theta$\\textsubscript{1}, (R·V)\\textsuperscript{n}"
        );
        assert_eq!(latex_escape("η × Σ"), "$\\eta$ × Σ");
        assert!(not_yet("a1.t1", Lang::Ja, Format::Markdown).contains("まだ導出できません: a1.t1"));
        assert_eq!(not_yet("a1.t1", Lang::En, Format::Latex), "\\textbf{(not derived yet: a1.t1)}");
    }
}
