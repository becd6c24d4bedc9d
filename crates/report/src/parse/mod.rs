//! Reading a student's report (Markdown) in the lecture's notation (see the kit's report notation,
//! shared with [`crate::tables`], which writes it):
//!
//! ```text
//! V0 (0.0, 1.0, 0.0)                               a vertex row (anywhere on a line)
//! | V0 | (0.000, 1.000, 0.000) |                   the kit's vertex table
//! | F0 { V0, V3, V1 } | { 0.0, 0.53, 0.85 } |      a face row with its normal (lecture)
//! | F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } | the kit's face table
//! <!-- cg: a2.view.start -->                       a matrix tag: the first pmatrix after it
//! $$ \begin{pmatrix} 1 & 0 & 0 & 0 \\ … \end{pmatrix} $$
//! <!-- cg: a2.view.start.factors -->               the product's factors: every pmatrix up to
//!                                                  the next tag, read as `ID.1`, `ID.2`, …
//! | 3 | 5 | (-2.000, 0.000, 0.000) | (0.300, 0.500) / (1.000, 0.500) |   a texture row
//! <!-- cg: s.spot -->                              a shading table: the table after it
//! | α = 15° | 0.966 | 0.933 | 0.933 |                 (rows by their label, see crate::shading)
//! <!-- cg: a4.formula -->                          the texture formula: `s = …`, `t = …` after it
//!                                                  (see crate::formula)
//! ```
//!
//! The reader is lenient: prose is ignored, and a line is a problem only where it clearly tries to
//! be a row (it starts with `V3 (`, `F2 {`, a texture row's `| i | j | (`, a tagged matrix) and
//! does not parse; the problem names the line, the text and what was expected. Numbers are plain
//! decimals (`-0.8`, `0.53`, `15`, with `−` or `+` allowed) and remember how many decimals were
//! written, so the checker ([`crate::verify`]) can accept correct rounding and nothing else.
//! Full-width `，（）｛｝` are read as their ASCII forms. A value after `=`, `≒` or `≈` is read
//! (`F0 { V0, V3, V1 } ≒ { 0.0, 0.49, 0.87 }`); a face row holds one normal, right after its
//! vertices (a second one, or one after words, is a problem); exponent notation (`4.9e-1`) is
//! named as not read. What is inside an HTML comment `<!-- … -->` (other than a tag) or a code
//! fence is not read, and line numbers stay those of the text.
//!
//! [`polygon_from_text`] turns a vertex and face list alone (a data file, or a hand-made table)
//! into a [`crate::model::PolygonData`], so a student can check a table without the exercises.

use std::collections::HashMap;

use cg_core::lang::{Lang, t};
use cg_harness::Text;

use crate::model::Written;

mod comments;
mod data;
mod expected;
mod matrices;
mod texture;

pub use data::polygon_from_text;
#[cfg(test)]
pub(crate) use data::{LECTURE_SLIDE, line_of};
pub use matrices::FACTORS;

use comments::without_comments;
#[cfg(test)]
use expected::is_exponent_notation;
use expected::{expected_face, expected_normal, expected_number_size, expected_vertex};

/// Which kind of row a [`ParseProblem`] is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RowKind {
    /// A vertex row `V0 (0.0, 1.0, 0.0)`.
    Vertex,
    /// A face row `F0 { V0, V3, V1 }`, with or without its normal.
    Face,
    /// A tagged matrix `<!-- cg: ID -->` … `\begin{pmatrix} … \end{pmatrix}`.
    Matrix,
    /// A texture row `| i | j | (x, y, z) | (s, t) |`.
    Texture,
    /// A tagged table of the shading section (`<!-- cg: s.spot -->` and the table after it).
    Table,
    /// The data as a whole (no vertices, numbering with gaps, a face naming a missing vertex,
    /// from [`polygon_from_text`]), or the text as a whole (a comment `<!--` never closed).
    Data,
}

/// A line that tries to be a row of the notation but does not parse.
#[derive(Clone, Debug, PartialEq)]
pub struct ParseProblem {
    /// The 1-based line; 0 when the problem is about the text as a whole (no vertex rows at all).
    pub line: usize,
    /// The offending text, trimmed, at most 80 characters (cut with `…`).
    pub found: String,
    /// What was expected there, with an example in the notation.
    pub expected: Text,
    /// The kind of row.
    pub kind: RowKind,
}

impl ParseProblem {
    /// `line 12: `F3 { V0, V4 }` — expected three vertex numbers in braces, …` (or in Japanese).
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        let place = match self.line {
            0 => t("全体", "the text"),
            n => Text::new(format!("{n} 行目"), format!("line {n}")),
        };
        let found =
            if self.found.is_empty() { String::new() } else { format!(" `{}` —", self.found) };
        let text = Text::new(
            format!("{}:{found} 期待する書き方: {}", place.ja, self.expected.ja),
            format!("{}:{found} expected {}", place.en, self.expected.en),
        );
        text.get(lang).to_owned()
    }
}

impl std::fmt::Display for ParseProblem {
    /// The English [`ParseProblem::message`].
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message(Lang::En))
    }
}

/// A vertex row: `V3 (-1.0, -0.8, 1.0)`.
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedVertex {
    /// The 1-based line.
    pub line: usize,
    /// The vertex number (3 for `V3`).
    pub index: u32,
    /// x, y, z as written.
    pub coords: [Written; 3],
}

/// A face row: `F0 { V0, V3, V1 }`, optionally with its normal `{ 0.0, 0.53, 0.85 }`.
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedFace {
    /// The 1-based line.
    pub line: usize,
    /// The face number (0 for `F0`).
    pub index: u32,
    /// The vertex numbers in the written order.
    pub vertices: [u32; 3],
    /// The normal as written, when the row has one.
    pub normal: Option<[Written; 3]>,
}

/// A tagged matrix: `<!-- cg: ID -->` and the first `pmatrix` after it, 4×4.
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedMatrix {
    /// The 1-based line of the tag.
    pub line: usize,
    /// The tag's ID (`a1.transform`, `a2.view.start`).
    pub id: String,
    /// The entries by rows, as written (always 4 rows of 4).
    pub rows: Vec<Vec<Written>>,
    /// The 1-based line of each entry, by rows like `rows`.
    pub entry_lines: Vec<Vec<usize>>,
}

/// A texture row: `| 3 | 5 | (-2.000, 0.000, 0.000) | (0.300, 0.500) / (1.000, 0.500) |`.
#[derive(Clone, Debug, PartialEq)]
pub struct ParsedTex {
    /// The 1-based line.
    pub line: usize,
    /// Grid column.
    pub i: u32,
    /// Grid row.
    pub j: u32,
    /// The grid vertex's position as written.
    pub position: [Written; 3],
    /// Its texture coordinates as written (one or more).
    pub tex: Vec<[Written; 2]>,
}

/// Everything [`parse_report`] found, each kind in the order of the text.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ParsedReport {
    /// Vertex rows (each vertex number once).
    pub vertices: Vec<ParsedVertex>,
    /// Face rows (each face number once).
    pub faces: Vec<ParsedFace>,
    /// Tagged 4×4 matrices (each ID once).
    pub matrices: Vec<ParsedMatrix>,
    /// The tags of products whose matrix is written but could not be read (entries that are
    /// not plain numbers, not 4×4, not closed, or no matrix before the next tag or section):
    /// each is a [`ParseProblem`], so the checker does not also say the matrix is missing.
    pub unread_matrices: Vec<String>,
    /// Texture rows (each (i, j) once).
    pub tex: Vec<ParsedTex>,
    /// The tagged tables ([`crate::shading`], and the periods of `a3`, [`crate::periods`]), in
    /// the order of the text.
    pub tables: Vec<crate::shading::ParsedTable>,
    /// The tagged texture formulas of `a4` ([`crate::formula`]), in the order of the text.
    pub formulas: Vec<crate::formula::ParsedFormula>,
}

impl ParsedReport {
    /// Whether nothing was found.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.items() == 0
    }

    /// The rows, matrices, tables and formulas found.
    #[must_use]
    pub fn items(&self) -> usize {
        self.vertices.len()
            + self.faces.len()
            + self.matrices.len()
            + self.tex.len()
            + self.tables.len()
            + self.formulas.len()
    }
}

/// A plain decimal number as the notation writes it: an optional sign (`-`, `+`, the Unicode
/// minus `−`, full-width `－`/`＋`), digits, an optional `.` and decimals (`-0.8`, `0.53`, `15`,
/// `.5`). `None` for anything else (`\cos 30°`, `1e-3`, `0,5`) and for numbers too large to be
/// finite.
#[must_use]
pub fn parse_number(s: &str) -> Option<Written> {
    let text = s.trim();
    let (negative, rest) = match text.chars().next()? {
        c @ ('-' | '−' | '－') => (true, &text[c.len_utf8()..]),
        c @ ('+' | '＋') => (false, &text[c.len_utf8()..]),
        _ => (false, text),
    };
    let (int, frac) = match rest.split_once('.') {
        Some((a, b)) => (a, Some(b)),
        None => (rest, None),
    };
    let digits = |d: &str| d.chars().all(|c| c.is_ascii_digit());
    if !digits(int)
        || !frac.is_none_or(digits)
        || (int.is_empty() && frac.is_none_or(str::is_empty))
    {
        return None;
    }
    let ascii = format!(
        "{}{}.{}",
        if negative { "-" } else { "" },
        if int.is_empty() { "0" } else { int },
        frac.filter(|f| !f.is_empty()).unwrap_or("0")
    );
    let value: f64 = ascii.parse().ok()?;
    if !value.is_finite() {
        return None;
    }
    let decimals = u32::try_from(frac.map_or(0, str::len)).unwrap_or(u32::MAX);
    Some(Written { value, decimals, text: text.to_owned() })
}

// ---------------------------------------------------------------------------------------------
// Scanning a line

/// Full-width punctuation and digits read as ASCII (one char for one char, so the rest of the
/// line stays).
pub(crate) fn normalize(line: &str) -> String {
    // LaTeX's escaped braces `\{ … \}` read as braces (a `\\` row end stays as it is).
    let mut unescaped = String::with_capacity(line.len());
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, chars.peek()) {
            ('\\', Some('\\')) => {
                unescaped.push_str("\\\\");
                chars.next();
            }
            ('\\', Some('{' | '}')) => unescaped.push(' '),
            _ => unescaped.push(c),
        }
    }
    unescaped
        .chars()
        .map(|c| match c {
            '，' | '、' => ',',
            '（' => '(',
            '）' => ')',
            '｛' => '{',
            '｝' => '}',
            '｜' => '|',
            '＝' => '=',
            '：' => ':',
            '．' => '.',
            '\u{3000}' => ' ',
            // Full-width row names (`Ｖ０`, `Ｆ１`): the row was passed over without a word.
            'Ｖ' => 'V',
            'Ｆ' => 'F',
            // Full-width digits (an input method's ０.４９) are the same digits.
            _ => cg_core::text::ascii_digit(c),
        })
        .collect()
}

/// The text clipped to 80 characters (79 and `…`), trimmed.
/// A row as a message quotes it: at most 80 characters, invisible characters named (`<U+200B>`).
/// Reads only as far as it must (the first 80 characters, and past them only up to a character
/// that is not whitespace), so quoting the rest of a long line costs no more than a short one.
pub(crate) fn clip(s: &str) -> String {
    let s = s.trim_start();
    match s.char_indices().nth(80) {
        // Something other than whitespace after the 80th character: the trimmed text is longer.
        Some((at, _)) if s[at..].contains(|c: char| !c.is_whitespace()) => {
            let cut = s.char_indices().nth(79).map_or(s.len(), |(i, _)| i);
            let mut out = cg_core::quote::visible(&s[..cut]);
            out.push('…');
            out
        }
        Some((at, _)) => cg_core::quote::visible(s[..at].trim_end()),
        None => cg_core::quote::visible(s.trim_end()),
    }
}

fn is_ascii_word(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Where a row may start: after indentation, list markers (`-`, `*`, `+`, `1.`), quote marks,
/// table pipes and backticks.
fn skip_markers(line: &str) -> usize {
    let mut pos = 0;
    while let Some(c) = line[pos..].chars().next() {
        if c.is_whitespace() || matches!(c, '|' | '>' | '*' | '+' | '-' | '`' | '・') {
            pos += c.len_utf8();
        } else if c.is_ascii_digit() {
            let rest = &line[pos..];
            let d = rest.len() - rest.trim_start_matches(|x: char| x.is_ascii_digit()).len();
            let list = matches!(rest[d..].chars().next(), Some('.' | ')'))
                && rest[d + 1..].starts_with(char::is_whitespace);
            if list {
                pos += d + 1;
            } else {
                break;
            }
        } else {
            break;
        }
    }
    pos
}

/// Skips what may stand between a row's name and its group: spaces, `|`, `=`, `≒`, `≈`, `:`,
/// `&`, `*`, `` ` ``, `$`.
fn skip_separators(line: &str, mut pos: usize) -> usize {
    while let Some(c) = line[pos..].chars().next() {
        if c.is_whitespace() || matches!(c, '|' | '=' | '≒' | '≈' | ':' | '&' | '*' | '`' | '$')
        {
            pos += c.len_utf8();
        } else {
            break;
        }
    }
    pos
}

/// `letter` followed by digits, as a word of its own (`V12`, not `TV1` or `V1x`): (start, the
/// number if it fits, end).
fn tokens(line: &str, letter: char) -> Vec<(usize, Option<u32>, usize)> {
    let mut out = Vec::new();
    let mut prev: Option<char> = None;
    for (i, c) in line.char_indices() {
        if c == letter && !prev.is_some_and(is_ascii_word) {
            let rest = &line[i + c.len_utf8()..];
            let digits = rest.len() - rest.trim_start_matches(|d: char| d.is_ascii_digit()).len();
            let end = i + c.len_utf8() + digits;
            if digits > 0 && !line[end..].chars().next().is_some_and(is_ascii_word) {
                out.push((i, line[i + c.len_utf8()..end].parse().ok(), end));
            }
        }
        prev = Some(c);
    }
    out
}

/// Why a group did not parse.
#[derive(Clone, Debug, PartialEq)]
enum GroupError {
    /// No closing `)` or `}` on the line.
    Unclosed,
    /// Not the number of entries asked for (the count found), and whether a comma stood between
    /// two digits (`0,5`: a decimal comma, which splits one number in two).
    Count(usize, bool),
    /// An entry that is not a plain number (or not a vertex number).
    NotNumber(String),
}

/// The most bytes a group's content may have: a closing bracket further on is not looked for,
/// and the group reads as not closed (a row of three numbers is far shorter). This keeps a line
/// of many unclosed groups (`V0 (V0 (V0 ( …`) linear to read.
const MAX_GROUP: usize = 1024;

/// The group that opens at `pos` (`(` or `{`): (its content's range, the position after it).
/// A group whose closing bracket is not within [`MAX_GROUP`] bytes is not closed.
fn group(line: &str, pos: usize) -> Option<Result<(usize, usize, usize), GroupError>> {
    let close = match line[pos..].chars().next()? {
        '(' => ')',
        '{' => '}',
        _ => return None,
    };
    let start = pos + 1;
    let mut end = line.len().min(start + MAX_GROUP + 1);
    while !line.is_char_boundary(end) {
        end -= 1;
    }
    Some(match line[start..end].find(close) {
        Some(k) => Ok((start, start + k, start + k + 1)),
        None => Err(GroupError::Unclosed),
    })
}

/// The comma-separated entries of a group, trimmed (none for an empty group).
fn entries(content: &str) -> Vec<&str> {
    if content.trim().is_empty() { Vec::new() } else { content.split(',').map(str::trim).collect() }
}

/// Whether a comma stands right between two digits (`0,5`), as a decimal comma is written; the
/// kit's notation separates numbers with commas, so `(0,5, 1,0, 0)` reads as five numbers.
fn has_decimal_comma(content: &str) -> bool {
    content
        .as_bytes()
        .windows(3)
        .any(|w| w[0].is_ascii_digit() && w[1] == b',' && w[2].is_ascii_digit())
}

/// `n` plain numbers, comma-separated.
fn tuple(content: &str, n: usize) -> Result<Vec<Written>, GroupError> {
    let parts = entries(content);
    if parts.len() != n {
        return Err(GroupError::Count(parts.len(), parts.len() > n && has_decimal_comma(content)));
    }
    parts
        .iter()
        .map(|p| parse_number(p).ok_or_else(|| GroupError::NotNumber((*p).to_owned())))
        .collect()
}

/// The tuple of `n` numbers at `pos`, or, when that group is not one (a derivation such as
/// `V1 = (cos 30°, 0, sin 30°) = (0.866, 0, 0.5)`), the first of the groups after `=` (or `≒`,
/// `≈`) that is.
/// `None` when there is no group at `pos`; otherwise the tuple or the first group's error, and
/// the end of what was read.
fn tuple_chain(
    line: &str,
    pos: usize,
    n: usize,
) -> Option<(Result<Vec<Written>, GroupError>, usize)> {
    let mut first_error = None;
    let mut pos = pos;
    let mut end = pos;
    loop {
        match group(line, pos) {
            None => break,
            Some(Err(e)) => {
                first_error.get_or_insert(e);
                end = line.len();
                break;
            }
            Some(Ok((a, b, after))) => {
                end = after;
                match tuple(&line[a..b], n) {
                    Ok(t) => return Some((Ok(t), after)),
                    Err(e) => {
                        first_error.get_or_insert(e);
                    }
                }
                let next = after + (line[after..].len() - line[after..].trim_start().len());
                if !line[next..].starts_with(['=', '≒', '≈']) {
                    break;
                }
                pos = skip_separators(line, next);
            }
        }
    }
    first_error.map(|e| (Err(e), end))
}

/// A face row's normal: `first`, or when it is a working that goes on with `=`, `≒` or `≈`
/// (`{ 0.0, 0.486, 0.874 } ≒ { 0.0, 0.49, 0.87 }`), the last group of three numbers of the
/// chain, as a shading table's cell is read; and the end of what was read.
fn last_in_chain(line: &str, first: Vec<Written>, end: usize) -> (Option<[Written; 3]>, usize) {
    let (mut normal, mut end) = (first, end);
    loop {
        let next = end + (line[end..].len() - line[end..].trim_start().len());
        if !line[next..].starts_with(['=', '≒', '≈']) {
            break;
        }
        match group(line, skip_separators(line, next)) {
            Some(Ok((a, b, after))) => match tuple(&line[a..b], 3) {
                Ok(t) => (normal, end) = (t, after),
                Err(_) => break,
            },
            _ => break,
        }
    }
    (Some([normal[0].clone(), normal[1].clone(), normal[2].clone()]), end)
}

/// How many `{` after a face row's normal are looked at for a stray normal (a line of a million
/// braces stays linear to read).
const STRAY_GROUPS: usize = 4;

/// A group of three numbers in braces in `line[from..until]` (after a face row's vertices and
/// normal, before the next face): a second normal, or one behind words (`法線 { 1, 0, 0 }`),
/// that the row would otherwise drop without a word.
fn stray_normal(line: &str, from: usize, until: usize) -> Option<&str> {
    line[from..until].match_indices('{').take(STRAY_GROUPS).find_map(|(k, _)| {
        match group(line, from + k) {
            Some(Ok((a, b, after))) if after <= until && tuple(&line[a..b], 3).is_ok() => {
                Some(&line[from + k..after])
            }
            _ => None,
        }
    })
}

/// Whether the group at `pos` holds something like data (a digit or a comma), not words such
/// as `V0 (the apex)`. Reads up to the first digit, comma or closing bracket.
fn looks_like_data(line: &str, pos: usize) -> bool {
    line[pos..]
        .find(|c: char| c.is_ascii_digit() || matches!(c, ',' | ')' | '}'))
        .is_some_and(|k| !matches!(line.as_bytes()[pos + k], b')' | b'}'))
}

/// Three vertex numbers `V0, V3, V1`.
fn face_vertices(content: &str) -> Result<[u32; 3], GroupError> {
    let parts = entries(content);
    if parts.len() != 3 {
        return Err(GroupError::Count(parts.len(), false));
    }
    let mut out = [0u32; 3];
    for (slot, p) in out.iter_mut().zip(&parts) {
        *slot = p
            .strip_prefix(['V', 'v'])
            .filter(|d| !d.is_empty() && d.chars().all(|c| c.is_ascii_digit()))
            .and_then(|d| d.parse().ok())
            .ok_or_else(|| GroupError::NotNumber((*p).to_owned()))?;
    }
    Ok(out)
}

// ---------------------------------------------------------------------------------------------
// The report

struct Reader {
    report: ParsedReport,
    problems: Vec<ParseProblem>,
    /// Problems not kept (past [`MAX_PROBLEMS_PER_LINE`] on a line or [`MAX_PROBLEMS`] in all).
    dropped: usize,
    vertex_at: HashMap<u32, usize>,
    face_at: HashMap<u32, usize>,
    tex_at: HashMap<(u32, u32), usize>,
}

/// The most problems kept for one line: a line of a million `F0 {` is named a few times, not a
/// million (each kept problem costs a quote and a message).
const MAX_PROBLEMS_PER_LINE: usize = 20;

/// The most problems kept in all; the rest are counted in one last problem.
const MAX_PROBLEMS: usize = 1000;

impl Reader {
    fn problem(&mut self, line: usize, found: &str, expected: Text, kind: RowKind) {
        let on_line = self.problems.iter().rev().take_while(|p| p.line == line).count();
        if on_line >= MAX_PROBLEMS_PER_LINE || self.problems.len() >= MAX_PROBLEMS {
            self.dropped += 1;
            return;
        }
        self.problems.push(ParseProblem { line, found: clip(found), expected, kind });
    }

    fn vertex(&mut self, v: ParsedVertex, found: &str) {
        match self.vertex_at.get(&v.index) {
            None => {
                self.vertex_at.insert(v.index, self.report.vertices.len());
                self.report.vertices.push(v);
            }
            Some(&k) => {
                let first = &self.report.vertices[k];
                if !same_numbers(&first.coords, &v.coords) {
                    let expected = Text::new(
                        format!(
                            "頂点番号は 1 回ずつ（V{} は {} 行目に別の座標で書かれています）",
                            v.index, first.line
                        ),
                        format!(
                            "each vertex number once (V{} is already on line {} with other coordinates)",
                            v.index, first.line
                        ),
                    );
                    self.problem(v.line, found, expected, RowKind::Vertex);
                }
            }
        }
    }

    fn face(&mut self, f: ParsedFace, found: &str) {
        match self.face_at.get(&f.index) {
            None => {
                self.face_at.insert(f.index, self.report.faces.len());
                self.report.faces.push(f);
            }
            Some(&k) => {
                let first = &mut self.report.faces[k];
                let same_normal = match (&first.normal, &f.normal) {
                    (Some(a), Some(b)) => same_numbers(a, b),
                    _ => true,
                };
                if first.vertices == f.vertices && same_normal {
                    // The same face mentioned again (in a derivation): keep it, with its normal.
                    if first.normal.is_none() {
                        first.normal = f.normal;
                    }
                } else {
                    let expected = Text::new(
                        format!(
                            "面番号は 1 回ずつ（F{} は {} 行目に別の頂点か法線で書かれています）",
                            f.index, first.line
                        ),
                        format!(
                            "each face number once (F{} is already on line {} with other vertices or another normal)",
                            f.index, first.line
                        ),
                    );
                    let line = f.line;
                    self.problem(line, found, expected, RowKind::Face);
                }
            }
        }
    }

    /// Vertex and face rows of one line.
    fn rows(&mut self, n: usize, line: &str) {
        let start = skip_markers(line);
        for (s, index, e) in tokens(line, 'V') {
            let pos = skip_separators(line, e);
            let Some((result, end)) = tuple_chain(line, pos, 3) else { continue };
            let found = &line[s..end];
            match (result, index) {
                (Ok(t), Some(index)) => {
                    let coords = [t[0].clone(), t[1].clone(), t[2].clone()];
                    self.vertex(ParsedVertex { line: n, index, coords }, found);
                }
                (Ok(_), None) => {
                    let expected = Text::new(
                        "`V0` から始まる、ふつうの大きさの頂点番号",
                        "a vertex number of ordinary size, counting from `V0`",
                    );
                    self.problem(n, found, expected, RowKind::Vertex);
                }
                (Err(err), _) => {
                    if (s == start && looks_like_data(line, pos)) || line[pos..].starts_with('{') {
                        self.problem(n, found, expected_vertex(&err), RowKind::Vertex);
                    }
                }
            }
        }
        let faces = tokens(line, 'F');
        for (k, &(s, index, e)) in faces.iter().enumerate() {
            // What belongs to this face: up to the next face's name on the line.
            let until = faces.get(k + 1).map_or(line.len(), |f| f.0);
            let pos = skip_separators(line, e);
            let strict = (s == start && looks_like_data(line, pos)) || line[pos..].starts_with('{');
            let Some(g) = group(line, pos) else { continue };
            let (a, b, after) = match g {
                Ok(r) => r,
                Err(err) => {
                    if strict {
                        self.problem(n, &line[s..], expected_face(&err), RowKind::Face);
                    }
                    continue;
                }
            };
            let vertices = match face_vertices(&line[a..b]) {
                Ok(v) => v,
                Err(err) => {
                    if strict {
                        self.problem(n, &line[s..after], expected_face(&err), RowKind::Face);
                    }
                    continue;
                }
            };
            let Some(index) = index else {
                let expected = Text::new(
                    "`F0` から始まる、ふつうの大きさの面番号",
                    "a face number of ordinary size, counting from `F0`",
                );
                self.problem(n, &line[s..after], expected, RowKind::Face);
                continue;
            };
            let npos = skip_separators(line, after);
            let (normal, end) = match tuple_chain(line, npos, 3) {
                None => (None, after),
                Some((Ok(t), end)) => last_in_chain(line, t, end),
                Some((Err(err), end)) => {
                    if strict || line[npos..].starts_with('{') {
                        self.problem(n, &line[s..end], expected_normal(&err), RowKind::Face);
                        continue;
                    }
                    (None, after)
                }
            };
            if let Some(extra) = stray_normal(line, end.min(until), until) {
                let expected = if normal.is_some() {
                    Text::new(
                        format!(
                            "面の行に法線は 1 つだけ（`{}` は 2 つ目の法線です）。途中の計算は別の行に書きます",
                            clip(extra)
                        ),
                        format!(
                            "one normal on a face row (`{}` is a second normal); write a working on a line of its own",
                            clip(extra)
                        ),
                    )
                } else {
                    Text::new(
                        format!(
                            "法線は面の頂点のすぐあとに `F0 {{ V0, V3, V1 }} {{ 0.0, 0.49, 0.87 }}` のように（`{}` の前に語句があるので法線として読めません）",
                            clip(extra)
                        ),
                        format!(
                            "the normal right after the face's vertices, like `F0 {{ V0, V3, V1 }} {{ 0.0, 0.49, 0.87 }}` (there are words before `{}`, so it does not read as the normal)",
                            clip(extra)
                        ),
                    )
                };
                self.problem(n, &line[s..until], expected, RowKind::Face);
                continue;
            }
            self.face(ParsedFace { line: n, index, vertices, normal }, &line[s..end]);
        }
    }
}

fn same_numbers(a: &[Written], b: &[Written]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.value == y.value)
}

/// Reads every vertex row, face row, tagged matrix, texture row and tagged shading table
/// ([`crate::shading`]) of a report (Markdown; LaTeX tags `% cg: ID` are read too). Lenient:
/// prose is ignored; a line that clearly tries to be a row but does not parse, a vertex, face,
/// tag or grid vertex given twice with different numbers, a tag with no `pmatrix` (or, for a
/// shading table, no table) after it, a matrix that is not 4×4 and an entry that is not a plain
/// number are [`ParseProblem`]s (in the order of the text), and the row is left out.
/// The same row repeated with the same numbers (a derivation quoting the table) is kept once.
/// Never panics.
#[must_use]
pub fn parse_report(text: &str) -> (ParsedReport, Vec<ParseProblem>) {
    let mut reader = Reader {
        report: ParsedReport::default(),
        problems: Vec::new(),
        dropped: 0,
        vertex_at: HashMap::new(),
        face_at: HashMap::new(),
        tex_at: HashMap::new(),
    };
    let (visible, unclosed) = without_comments(text);
    if let Some((line, found)) = unclosed {
        let expected = Text::new(
            "`-->` で閉じたコメント `<!--`（閉じていないので、ここから後ろはすべてコメントとして読みません）",
            "a comment `<!--` closed by `-->` (it is not closed, so everything after it is a comment and is not read)",
        );
        reader.problem(line, &found, expected, RowKind::Data);
    }
    let lines: Vec<String> = visible.iter().map(|l| normalize(l)).collect();
    for (k, line) in lines.iter().enumerate() {
        reader.rows(k + 1, line);
        reader.tex_row(k + 1, line);
    }
    reader.matrices(&lines.join("\n"));
    let (tables, problems) = crate::shading::parse_tables(&lines);
    reader.report.tables = tables;
    reader.report.formulas = crate::formula::parse_formulas(&lines);
    reader.problems.extend(problems);
    reader.problems.sort_by_key(|p| p.line);
    if reader.dropped > 0 {
        let n = reader.dropped;
        reader.problems.push(ParseProblem {
            line: 0,
            found: String::new(),
            expected: Text::new(
                format!(
                    "上の行を直すこと（読めない所はほかに {n} か所あります。1 行に {MAX_PROBLEMS_PER_LINE} か所、全部で {MAX_PROBLEMS} か所まで示しています）"
                ),
                format!(
                    "the lines above fixed ({n} more places could not be read; at most {MAX_PROBLEMS_PER_LINE} a line and {MAX_PROBLEMS} in all are named)"
                ),
            ),
            kind: RowKind::Data,
        });
    }
    (reader.report, reader.problems)
}

#[cfg(test)]
mod tests;
