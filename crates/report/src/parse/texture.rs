//! The texture-coordinate rows of a report: `| i | j | (x, y, z) | (s, t) / (s, t) |` in
//! Markdown, or `i & j & $(x, y, z)$ & $(s, t)$ / $(s, t)$ \\` as `report fill` writes them in
//! LaTeX; each grid vertex once.

use cg_harness::Text;

use super::expected::{detail, join};
use super::{GroupError, ParsedTex, Reader, RowKind, group, same_numbers, tuple};
use crate::model::Written;

/// A texture row as the notation writes it (in the row's own form: a Markdown table's, or
/// LaTeX's as `report fill` writes it), and why this one did not read.
fn expected_tex(why: Text, latex: bool) -> Text {
    let row = if latex {
        "`i & j & $(x, y, z)$ & $(s, t)$ / $(s, t)$ \\\\`"
    } else {
        "`| i | j | (x, y, z) | (s, t) / (s, t) |`"
    };
    join(
        Text::new(
            format!(
                "テクスチャ座標の行 {row}: 格子点の位置を 3 つの数で、テクスチャ座標を ` / ` で区切った 2 つの数の組で"
            ),
            format!(
                "a texture row {row}: the grid vertex's position as three numbers and its texture coordinates as pairs separated by ` / `"
            ),
        ),
        why,
    )
}

impl Reader {
    /// Keeps a texture row; the same grid vertex again must hold the same numbers.
    fn tex(&mut self, t: ParsedTex, found: &str) {
        match self.tex_at.get(&(t.i, t.j)) {
            None => {
                self.tex_at.insert((t.i, t.j), self.report.tex.len());
                self.report.tex.push(t);
            }
            Some(&k) => {
                let first = &self.report.tex[k];
                let same = same_numbers(&first.position, &t.position)
                    && first.tex.len() == t.tex.len()
                    && first.tex.iter().zip(&t.tex).all(|(a, b)| same_numbers(a, b));
                if !same {
                    let expected = Text::new(
                        format!(
                            "格子点 ({}, {}) は 1 回ずつ（{} 行目に別の値で書かれています）",
                            t.i, t.j, first.line
                        ),
                        format!(
                            "each grid vertex ({}, {}) once (it is already on line {} with other numbers)",
                            t.i, t.j, first.line
                        ),
                    );
                    self.problem(t.line, found, expected, RowKind::Texture);
                }
            }
        }
    }

    /// A texture row, when the line is a table row whose cells start `| i | j | (`, or the same
    /// row as `report fill` writes it in LaTeX, `0 & 0 & $(x, y, z)$ & $(s, t)$ / $(s, t)$ \\`
    /// (math delimiters `$`, `\(`, `\)` are not part of a cell's numbers).
    pub(super) fn tex_row(&mut self, n: usize, line: &str) {
        let trimmed = line.trim();
        let latex = !trimmed.starts_with('|');
        let Some(cells) = crate::shading::row_cells(trimmed) else { return };
        let cells: Vec<String> = cells
            .iter()
            .map(|c| c.replace("\\(", "").replace("\\)", "").replace('$', "").trim().to_owned())
            .collect();
        let int = |s: &str| {
            if !s.is_empty() && s.chars().all(|c| c.is_ascii_digit()) {
                s.parse::<u32>().ok()
            } else {
                None
            }
        };
        let (Some(i), Some(j)) =
            (cells.first().and_then(|c| int(c)), cells.get(1).and_then(|c| int(c)))
        else {
            return;
        };
        let Some(pos_cell) = cells.get(2).filter(|c| c.starts_with('(')) else { return };
        let position = match whole_tuple(pos_cell, 3) {
            Ok(t) => [t[0].clone(), t[1].clone(), t[2].clone()],
            Err(err) => {
                let why = match err {
                    GroupError::NotNumber(_) => detail(&err, "数", "a plain number"),
                    _ => detail(&err, "位置の数", "numbers in the position"),
                };
                self.problem(n, trimmed, expected_tex(why, latex), RowKind::Texture);
                return;
            }
        };
        let Some(tex_cell) = cells.get(3).filter(|c| !c.is_empty()) else {
            let why = Text::new(
                "（テクスチャ座標がありません）",
                " (the texture coordinates are missing)",
            );
            self.problem(n, trimmed, expected_tex(why, latex), RowKind::Texture);
            return;
        };
        let mut tex = Vec::new();
        for part in tex_cell.split('/') {
            match whole_tuple(part, 2) {
                Ok(t) => tex.push([t[0].clone(), t[1].clone()]),
                Err(err) => {
                    let why = match err {
                        GroupError::NotNumber(_) => detail(&err, "数", "a plain number"),
                        _ => detail(&err, "座標の組の数", "numbers in a coordinate pair"),
                    };
                    self.problem(n, trimmed, expected_tex(why, latex), RowKind::Texture);
                    return;
                }
            }
        }
        self.tex(ParsedTex { line: n, i, j, position, tex }, trimmed);
    }
}

/// A cell that is exactly one parenthesised tuple of `n` numbers.
fn whole_tuple(cell: &str, n: usize) -> Result<Vec<Written>, GroupError> {
    let cell = cell.trim();
    match group(cell, 0) {
        Some(Ok((a, b, after))) if cell[after..].trim().is_empty() => tuple(&cell[a..b], n),
        Some(Ok(_)) => Err(GroupError::NotNumber(cell.to_owned())),
        Some(Err(e)) => Err(e),
        None => Err(GroupError::NotNumber(cell.to_owned())),
    }
}

#[cfg(test)]
mod tests {
    use super::super::parse_report;

    /// A texture row that does not read is shown the row's form in its own notation: LaTeX's
    /// in a LaTeX report (it was the Markdown table's there too).
    #[test]
    fn a_texture_row_is_shown_in_its_own_notation() {
        let latex = "3 & 0 & $(0.5, 0, x)$ & $(0.1, 0.2)$ \\\\\n";
        let (_, problems) = parse_report(latex);
        assert_eq!(problems.len(), 1, "{problems:?}");
        let said = &problems[0].expected;
        assert!(said.en.contains("`i & j & $(x, y, z)$ & $(s, t)$ / $(s, t)$ \\\\`"), "{said:?}");
        assert!(said.ja.contains("`i & j & $(x, y, z)$"), "{said:?}");
        assert!(!said.en.contains("| i | j |"), "{said:?}");
        let markdown = "| 3 | 0 | (0.5, 0, x) | (0.1, 0.2) |\n";
        let (_, problems) = parse_report(markdown);
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(problems[0].expected.en.contains("`| i | j | (x, y, z) | (s, t) / (s, t) |`"));
    }
}
