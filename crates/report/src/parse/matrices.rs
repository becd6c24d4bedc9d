//! The tagged matrices of a report: `<!-- cg: ID -->` (or `% cg: ID`) and the first `pmatrix`
//! after it; for an ID ending in `.factors`, every `pmatrix` up to the next tag, one per factor
//! of the product, read as `ID.1`, `ID.2`, …. A `bmatrix`, `Bmatrix`, `matrix` or
//! `smallmatrix` is the same matrix in other brackets and is read as a `pmatrix` is (a
//! `vmatrix` is a determinant, not a matrix). A tag's matrix is looked for only up to the next
//! tag or section (a heading, `\paragraph`, or a line in bold alone, as `report fill` titles
//! each product): the next product's symbolic matrix is never taken for it.

use std::collections::HashMap;

use cg_harness::Text;

use super::{ParsedMatrix, Reader, RowKind, parse_number, same_numbers};

/// The matrix environments read as matrices: the same entries in other brackets.
const ENVIRONMENTS: [&str; 5] = ["pmatrix", "bmatrix", "Bmatrix", "matrix", "smallmatrix"];
/// The end of a factors tag's ID: `a2.view.start.factors`.
pub const FACTORS: &str = ".factors";

/// The first matrix environment ([`ENVIRONMENTS`]) that begins in `region`: where its
/// `\begin{…}` starts and its name.
fn first_matrix(region: &str) -> Option<(usize, &'static str)> {
    region.match_indices("\\begin{").find_map(|(at, open)| {
        let rest = &region[at + open.len()..];
        let name = &rest[..rest.find('}')?];
        ENVIRONMENTS.iter().find(|&&e| e == name).map(|&e| (at, e))
    })
}

/// Whether a line starts a new section of the report: a heading (Markdown `#`, LaTeX
/// `\section` and below), a LaTeX `\paragraph`, or a line in bold alone (`**視野変換行列…**`,
/// the title `report fill` writes before each product).
fn starts_section(line: &str) -> bool {
    let t = line.trim();
    crate::shading::is_heading(t)
        || t.starts_with("\\paragraph")
        || (t.len() > 4 && t.starts_with("**") && t.ends_with("**"))
}

/// A `pmatrix` read: where it ends, and its entries by rows with their lines when it is a 4×4
/// matrix of plain numbers.
struct Pmatrix {
    end: usize,
    entries: Option<Entries>,
}

/// A matrix's entries by rows, and the line of each.
type Entries = (Vec<Vec<crate::model::Written>>, Vec<Vec<usize>>);

/// A tag `<!-- cg: ID -->` (Markdown) or `% cg: ID` (LaTeX): its line, ID and where it ends.
struct Tag {
    line: usize,
    start: usize,
    end: usize,
    id: String,
    text: String,
}

fn valid_id(id: &str) -> bool {
    !id.is_empty() && id.chars().all(|c| c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-'))
}

fn expected_tag() -> Text {
    Text::new(
        "`<!-- cg: a1.transform -->` のような、ID（英数字と `.` `_` `-`）のついたタグ",
        "a tag like `<!-- cg: a1.transform -->` with an ID of letters, digits, `.`, `_` and `-`",
    )
}

/// The tables' tags, when `id` looks like one of them mistyped (the shading set's `s.…`, or
/// with `period` in it): the list to say.
fn table_like(id: &str) -> Option<String> {
    let lower = id.to_ascii_lowercase();
    (lower.starts_with("s.") || lower.contains("period")).then(|| {
        let mut tags: Vec<&str> = cg_assign::cg_shading::report::TABLE_IDS.to_vec();
        tags.push(crate::periods::TABLE_ID);
        tags.join(", ")
    })
}

fn expected_matrix_entry() -> Text {
    Text::new(
        "行列の要素として数そのもの（`\\cos 30°` ではなく `0.866`）",
        "a plain number as the matrix entry (`0.866`, not `\\cos 30°`)",
    )
}

impl Reader {
    fn tags(&mut self, text: &str, line_starts: &[usize]) -> Vec<Tag> {
        let mut tags = Vec::new();
        for (k, line) in text.split('\n').enumerate() {
            let n = k + 1;
            let base = line_starts[k];
            let mut from = 0;
            // The first `-->` at or after a position, as last looked for: (from where, where).
            // The tags of a line are read left to right, so each part of it is searched once.
            let mut next_close: Option<(usize, Option<usize>)> = None;
            while let Some(p) = line[from..].find("<!--") {
                let p = from + p;
                let after = &line[p + 4..];
                let body = after.trim_start();
                from = p + 4;
                let Some(rest) = body.strip_prefix("cg:") else {
                    // `<!-- cg s.spot -->`, `<!-- CG: … -->`: a tag mistyped, not a comment of
                    // the student's; its table or matrix would go unchecked without a word.
                    let cg = body.get(..2).is_some_and(|s| s.eq_ignore_ascii_case("cg"));
                    // `get`: the comment may start with kana (`<!-- メモ -->`), whose byte 2
                    // is inside a character.
                    let next = body.get(2..).and_then(|s| s.chars().next());
                    if cg && next.is_some_and(|c| c.is_whitespace() || c == ':') {
                        let end = line[p..].find("-->").map_or(line.len(), |k| p + k + 3);
                        self.problem(n, &line[p..end], expected_tag(), RowKind::Matrix);
                    }
                    continue;
                };
                let rest_at = line.len() - rest.len();
                let found = match next_close {
                    Some((at, found)) if at <= rest_at && found.is_none_or(|f| f >= rest_at) => {
                        found
                    }
                    _ => line[rest_at..].find("-->").map(|k| rest_at + k),
                };
                next_close = Some((rest_at, found));
                let Some(close) = found.map(|f| f - rest_at) else {
                    self.problem(n, &line[p..], expected_tag(), RowKind::Matrix);
                    continue;
                };
                let id = rest[..close].trim();
                let end = p + 4 + (after.len() - body.len()) + 3 + close + 3;
                if valid_id(id) {
                    tags.push(Tag {
                        line: n,
                        start: base + p,
                        end: base + end,
                        id: id.to_owned(),
                        text: line[p..end].to_owned(),
                    });
                } else {
                    self.problem(n, &line[p..end], expected_tag(), RowKind::Matrix);
                }
                from = end;
            }
            if let Some(rest) = line.trim_start().strip_prefix('%')
                && let Some(id) = rest.trim_start().strip_prefix("cg:")
            {
                let id = id.trim();
                if valid_id(id) {
                    tags.push(Tag {
                        line: n,
                        start: base,
                        end: base + line.len(),
                        id: id.to_owned(),
                        text: line.trim().to_owned(),
                    });
                } else {
                    self.problem(n, line, expected_tag(), RowKind::Matrix);
                }
            }
        }
        tags
    }

    pub(super) fn matrices(&mut self, text: &str) {
        let mut line_starts = vec![0];
        line_starts.extend(text.match_indices('\n').map(|(i, _)| i + 1));
        let tags = self.tags(text, &line_starts);
        let mut seen: HashMap<String, usize> = HashMap::new();
        for (k, tag) in tags.iter().enumerate() {
            // A table's tag (`crate::shading`) or the texture formula's (`crate::formula`): not a
            // matrix.
            if crate::shading::is_table_tag(&tag.id) || tag.id == crate::formula::TAG {
                continue;
            }
            let next_tag = tags.get(k + 1).map_or(text.len(), |t| t.start);
            // Up to the next tag or section, whichever comes first.
            let region_end = line_starts
                .iter()
                .skip(tag.line)
                .take_while(|&&s| s < next_tag)
                .find(|&&s| starts_section(text[s..].split('\n').next().unwrap_or("")))
                .map_or(next_tag, |&s| s);
            // `ID.factors`: every pmatrix up to the next tag, one per factor; else the first.
            let factors = tag.id.ends_with(FACTORS);
            let mut from = tag.end;
            let mut count = 0;
            loop {
                let region = &text[from..region_end.max(from)];
                let Some((b, name)) = first_matrix(region) else {
                    if count == 0 {
                        let expected = if factors {
                            Text::new(
                                "タグのあとに、積の因子の 4×4 行列 `\\begin{pmatrix} … \\end{pmatrix}` を順に",
                                "the product's 4×4 factors as `\\begin{pmatrix} … \\end{pmatrix}`, in order, after the tag",
                            )
                        } else if let Some(env) = ["vmatrix", "Vmatrix"]
                            .into_iter()
                            .find(|e| region.contains(&format!("\\begin{{{e}}}")))
                        {
                            // Bars are a determinant's (or a norm's): no matrix is read from them.
                            Text::new(
                                format!(
                                    "タグのあとに、積の結果の 4×4 行列 `\\begin{{pmatrix}} … \\end{{pmatrix}}`（`{env}` は行列式の記号なので行列としては読みません。`pmatrix` か `bmatrix` にしてください）"
                                ),
                                format!(
                                    "the 4×4 result of the product as `\\begin{{pmatrix}} … \\end{{pmatrix}}` after the tag (a `{env}` is a determinant's bars, not read as a matrix: write `pmatrix` or `bmatrix`)"
                                ),
                            )
                        } else if let Some(tables) = table_like(&tag.id) {
                            // `s.spots`: a table's tag mistyped, not a matrix without its matrix.
                            Text::new(
                                format!("表のタグ（{tables}）のどれか"),
                                format!("one of the tables' tags ({tables})"),
                            )
                        } else {
                            Text::new(
                                "タグのあとに、積の結果の 4×4 行列 `\\begin{pmatrix} … \\end{pmatrix}`",
                                "the 4×4 result of the product as `\\begin{pmatrix} … \\end{pmatrix}` after the tag",
                            )
                        };
                        self.problem(tag.line, &tag.text, expected, RowKind::Matrix);
                        self.unread(tag, factors);
                    }
                    break;
                };
                count += 1;
                let id = if factors { format!("{}.{count}", tag.id) } else { tag.id.clone() };
                let begin = from + b;
                let Some(next) = self.pmatrix(text, &line_starts, (begin, name), region_end) else {
                    self.unread(tag, factors);
                    break;
                };
                from = next.end;
                if let Some((rows, entry_lines)) = next.entries {
                    let m = ParsedMatrix { line: tag.line, id, rows, entry_lines };
                    self.keep(m, tag, &mut seen);
                } else {
                    self.unread(tag, factors);
                }
                if !factors {
                    break;
                }
            }
        }
    }

    /// A product's tag whose matrix is there but could not be read (a problem names it): not
    /// also "no tagged matrix" ([`super::ParsedReport::unread_matrices`]).
    fn unread(&mut self, tag: &Tag, factors: bool) {
        if !factors && !self.report.unread_matrices.contains(&tag.id) {
            self.report.unread_matrices.push(tag.id.clone());
        }
    }

    /// The matrix environment `name` that begins at `begin`: where it ends and, when it is a 4×4
    /// matrix of plain numbers, its entries with their lines (each problem found is recorded).
    /// `None` when it is not closed before `region_end`.
    fn pmatrix(
        &mut self,
        text: &str,
        line_starts: &[usize],
        (begin, name): (usize, &str),
        region_end: usize,
    ) -> Option<Pmatrix> {
        let line_of = |offset: usize| line_starts.partition_point(|&s| s <= offset);
        let end_tag = format!("\\end{{{name}}}");
        let body_start = begin + "\\begin{".len() + name.len() + 1;
        let begin_line = line_of(begin);
        // The line of the `\begin`, up to its line break (the next line's start, less the `\n`).
        let begin_text = &text[line_starts[begin_line - 1]
            ..line_starts.get(begin_line).map_or(text.len(), |&next| next - 1)];
        let Some(e) = text[body_start..region_end.max(body_start)].find(&end_tag) else {
            let expected = Text::new(
                format!("行列を閉じる `{end_tag}`（次のタグや節より前に）"),
                format!("`{end_tag}` closing the matrix (before the next tag or section)"),
            );
            self.problem(begin_line, begin_text, expected, RowKind::Matrix);
            return None;
        };
        let end = body_start + e + end_tag.len();
        let body = &text[body_start..body_start + e];
        let mut rows = Vec::new();
        let mut entry_lines = Vec::new();
        let mut counts = Vec::new();
        let mut ok = true;
        let mut offset = body_start;
        for row in body.split("\\\\") {
            let row_start = offset;
            offset += row.len() + 2;
            // `\\[2pt]`: a row spacing, not an entry.
            let (row, skip) = match row.trim_start().strip_prefix('[') {
                Some(r) if r.contains(']') => {
                    let cut = row.len() - r.len() + r.find(']').unwrap_or(0) + 1;
                    (&row[cut..], cut)
                }
                _ => (row, 0),
            };
            if row.trim().is_empty() {
                continue;
            }
            let mut values = Vec::new();
            let mut lines = Vec::new();
            let mut entry_offset = row_start + skip;
            for entry in row.split('&') {
                let at = entry_offset + (entry.len() - entry.trim_start().len());
                entry_offset += entry.len() + 1;
                let t = entry.trim();
                let inner = t.strip_prefix('{').and_then(|s| s.strip_suffix('}')).unwrap_or(t);
                match parse_number(inner) {
                    Some(w) => {
                        values.push(w);
                        lines.push(line_of(at));
                    }
                    None => {
                        ok = false;
                        let found = if t.is_empty() { row } else { t };
                        self.problem(line_of(at), found, expected_matrix_entry(), RowKind::Matrix);
                    }
                }
            }
            counts.push(row.split('&').count());
            rows.push(values);
            entry_lines.push(lines);
        }
        if counts.len() != 4 || counts.iter().any(|&c| c != 4) {
            let counts: Vec<String> = counts.iter().map(ToString::to_string).collect();
            let expected = Text::new(
                format!(
                    "4×4 行列: `\\\\` で区切った 4 行、それぞれ `&` で区切った 4 つの要素（{} 行あり、要素の数は {}）",
                    counts.len(),
                    counts.join(", ")
                ),
                format!(
                    "a 4×4 matrix: 4 rows separated by `\\\\`, each of 4 entries separated by `&` (found {} rows of {} entries)",
                    counts.len(),
                    counts.join(", ")
                ),
            );
            self.problem(begin_line, begin_text, expected, RowKind::Matrix);
            return Some(Pmatrix { end, entries: None });
        }
        Some(Pmatrix { end, entries: ok.then_some((rows, entry_lines)) })
    }

    /// Keeps a tagged matrix; the same tag again must hold the same numbers.
    fn keep(&mut self, m: ParsedMatrix, tag: &Tag, seen: &mut HashMap<String, usize>) {
        match seen.get(&m.id) {
            None => {
                seen.insert(m.id.clone(), self.report.matrices.len());
                self.report.matrices.push(m);
            }
            Some(&k) => {
                let first = &self.report.matrices[k];
                let same = first.rows.iter().zip(&m.rows).all(|(a, b)| same_numbers(a, b));
                if !same {
                    let expected = Text::new(
                        format!(
                            "タグ `{}` は 1 回ずつ（{} 行目に別の行列があります）",
                            m.id, first.line
                        ),
                        format!(
                            "each tag once (`{}` is already on line {} with another matrix)",
                            m.id, first.line
                        ),
                    );
                    self.problem(tag.line, &tag.text, expected, RowKind::Matrix);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests;
