//! Reading a texture-coordinate formula: `s = 0.25 + i/16`, `t = (j + 2) / 8 * 0.5`,
//! `s = 0.125 i`, `s = 0.25 + 0.025·(i mod 5)`, and their LaTeX forms (`\frac{i}{16}`, `\cdot`,
//! `\times`, `\bmod`, `\left( … \right)`, `−`). An expression is arithmetic in `i` and `j`:
//! numbers, `+ − · × * / ÷`, `mod` (`%`, `\bmod`), parentheses and braces, and a product written
//! by juxtaposition (`0.125 i`, `2(i + 1)`). It is evaluated, not solved, so any such arithmetic
//! reads; what it gives is checked at every ground vertex (`check`).
//!
//! Bounded: at most [`MAX_TOKENS`] tokens and [`MAX_DEPTH`] nested groups; never panics.

use cg_harness::Text;

/// The most tokens one equation may have.
pub const MAX_TOKENS: usize = 400;
/// The most nested groups (parentheses, braces, signs) one expression may have.
pub const MAX_DEPTH: usize = 48;
/// The most values an expression may take at one vertex (see [`Expr::eval`]).
const MAX_VALUES: usize = 8;

/// A token of a formula, with its 1-based line.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Tok {
    /// A number.
    Num(f64),
    /// `i` or `j`.
    Var(char),
    /// A word of ASCII letters that is not `i`, `j` or `mod` (`s`, `t`, `p`, `where`).
    Word(String),
    /// `+`, `-`, `*`, `/`, `%` (mod).
    Op(char),
    /// `(` or `{`.
    Open(char),
    /// `)` or `}`.
    Close(char),
    /// `=`.
    Eq,
    /// `\frac` (`\dfrac`, `\tfrac`).
    Frac,
    /// Ends an equation: `,`, `;`, `、`, `。`, a full stop, `\\`, `\quad`.
    Sep,
    /// A line break.
    Newline,
    /// Anything else, as written.
    Other(String),
}

/// The most tokens kept after the last separator, line break or word `s`/`t`: more than an
/// expression may have ([`MAX_TOKENS`]) with room for the `s(i, j) =` before it, so an
/// expression that runs past it is too long whether or not the rest is kept.
const RUN_LIMIT: usize = MAX_TOKENS + 16;
/// The most tokens kept on one line; the rest of a longer line is left out.
const LINE_LIMIT: usize = 8 * MAX_TOKENS;

/// The tokens read so far, within [`RUN_LIMIT`] and [`LINE_LIMIT`]: what a formula of any length
/// needs for its equations to read as they would in full (one running past the limit is too long
/// either way), in memory that does not grow with the line.
struct Kept {
    out: Vec<(usize, Tok)>,
    /// Tokens kept since the last separator, line break or `s`/`t`.
    run: usize,
    /// Tokens kept on this line.
    on_line: usize,
}

impl Kept {
    fn line_full(&self) -> bool {
        self.on_line >= LINE_LIMIT
    }

    fn push(&mut self, line: usize, tok: Tok) {
        let resets = match &tok {
            Tok::Newline => {
                self.on_line = 0;
                true
            }
            Tok::Sep => true,
            Tok::Word(w) => w == "s" || w == "t",
            _ => false,
        };
        if self.line_full() {
            return;
        }
        if resets {
            self.run = 0;
        } else if self.run >= RUN_LIMIT {
            return;
        } else {
            self.run += 1;
        }
        if tok != Tok::Newline {
            self.on_line += 1;
        }
        self.out.push((line, tok));
    }
}

/// `text` as tokens, each with its line (`first_line` for the first); `$`, `&`, spaces and
/// LaTeX's spacing and sizing commands are left out. Bounded: past [`RUN_LIMIT`] tokens of one
/// expression and [`LINE_LIMIT`] tokens of one line, the tokens are not kept (the expression is
/// too long to read, [`MAX_TOKENS`], either way).
pub(crate) fn tokens(text: &str, first_line: usize) -> Vec<(usize, Tok)> {
    let bytes = text.as_bytes();
    let digit_at = |k: usize| bytes.get(k).is_some_and(u8::is_ascii_digit);
    let alpha_at = |k: usize| bytes.get(k).is_some_and(u8::is_ascii_alphabetic);
    let mut kept = Kept { out: Vec::new(), run: 0, on_line: 0 };
    let mut line = first_line;
    // The first `}` at or after a position, as last looked for (for `\begin{…}`): (from, where).
    let mut next_close: Option<(usize, Option<usize>)> = None;
    // `k` is a byte offset, always at a character's start.
    let mut k = 0;
    'chars: while let Some(c) = text[k..].chars().next() {
        k += c.len_utf8();
        if c != '\n' && kept.line_full() {
            k = text[k..].find('\n').map_or(text.len(), |n| k + n);
            continue;
        }
        let tok = match c {
            '\n' => {
                kept.push(line, Tok::Newline);
                line += 1;
                continue;
            }
            c if c.is_whitespace() || matches!(c, '$' | '&' | '~') => continue,
            '0'..='9' | '.' if c != '.' || digit_at(k) => {
                let start = k - 1;
                while digit_at(k) {
                    k += 1;
                }
                if bytes.get(k) == Some(&b'.') && digit_at(k + 1) {
                    k += 1;
                    while digit_at(k) {
                        k += 1;
                    }
                }
                let digits = &text[start..k];
                let digits =
                    if digits.starts_with('.') { format!("0{digits}") } else { digits.to_owned() };
                match digits.parse::<f64>() {
                    Ok(x) if x.is_finite() => Tok::Num(x),
                    _ => Tok::Other(digits),
                }
            }
            c if c.is_ascii_alphabetic() => {
                let start = k - 1;
                while alpha_at(k) {
                    k += 1;
                }
                let word = &text[start..k];
                if word == "mod" {
                    Tok::Op('%')
                } else if word.chars().all(|c| matches!(c, 'i' | 'j')) {
                    // `ij` is i·j, as juxtaposition reads.
                    for c in word.chars() {
                        kept.push(line, Tok::Var(c));
                    }
                    continue;
                } else {
                    Tok::Word(word.to_owned())
                }
            }
            '\\' => {
                let start = k;
                while alpha_at(k) {
                    k += 1;
                }
                match &text[start..k] {
                    "" => match text[k..].chars().next() {
                        Some('\\') => {
                            k += 1;
                            Tok::Sep
                        }
                        // Spacing, and the math delimiters `\[ \] \( \)`.
                        Some(',' | ';' | '!' | ':' | ' ' | '[' | ']' | '(' | ')') => {
                            k += 1;
                            continue;
                        }
                        Some(c) => {
                            k += c.len_utf8();
                            Tok::Other(format!("\\{c}"))
                        }
                        None => Tok::Other("\\".to_owned()),
                    },
                    "cdot" | "times" | "ast" => Tok::Op('*'),
                    "div" => Tok::Op('/'),
                    "bmod" | "mod" => Tok::Op('%'),
                    "frac" | "dfrac" | "tfrac" => Tok::Frac,
                    "quad" | "qquad" => Tok::Sep,
                    "left" | "right" | "big" | "Big" | "bigl" | "bigr" | "Bigl" | "Bigr" => {
                        continue;
                    }
                    // `\operatorname{mod}`, `\mathrm{mod}`, `\text{mod}`: the word inside reads
                    // (when the braces hold it alone, spaces aside).
                    "operatorname" | "mathrm" | "text" | "textrm" | "mathit" => {
                        if bytes.get(k) == Some(&b'{') {
                            let inside = text[k + 1..].trim_start();
                            for (word, tok) in
                                [("mod", Tok::Op('%')), ("i", Tok::Var('i')), ("j", Tok::Var('j'))]
                            {
                                let rest = inside.strip_prefix(word).map(str::trim_start);
                                if let Some(rest) = rest.filter(|r| r.starts_with('}')) {
                                    k = text.len() - rest.len() + 1;
                                    kept.push(line, tok);
                                    continue 'chars;
                                }
                            }
                        }
                        continue;
                    }
                    "begin" | "end" => {
                        // `\begin{aligned}`: the environment's name is not part of the formula.
                        if bytes.get(k) == Some(&b'{') {
                            let close = match next_close {
                                Some((from, found))
                                    if from <= k && found.is_none_or(|f| f >= k) =>
                                {
                                    found
                                }
                                _ => text[k..].find('}').map(|c| k + c),
                            };
                            next_close = Some((k, close));
                            if let Some(close) = close {
                                k = close + 1;
                            }
                        }
                        continue;
                    }
                    name => Tok::Other(format!("\\{name}")),
                }
            }
            '+' | '＋' => Tok::Op('+'),
            '-' | '−' | '–' | '－' => Tok::Op('-'),
            '*' | '·' | '⋅' | '×' | '∗' | '＊' => Tok::Op('*'),
            '/' | '÷' | '／' => Tok::Op('/'),
            '%' => Tok::Op('%'),
            '(' | '（' | '[' => Tok::Open('('),
            ')' | '）' | ']' => Tok::Close(')'),
            '{' => Tok::Open('{'),
            '}' => Tok::Close('}'),
            '=' | '＝' => Tok::Eq,
            ',' | ';' | '、' | '。' | '，' | '；' | '.' => Tok::Sep,
            c => Tok::Other(c.to_string()),
        };
        kept.push(line, tok);
    }
    kept.out
}

/// A variable of the formula.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Var {
    /// The grid column `i` (0…10).
    I,
    /// The grid row `j` (0…10).
    J,
}

/// An expression in `i` and `j`.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// A number.
    Num(f64),
    /// `i` or `j`.
    Var(Var),
    /// `−a`.
    Neg(Box<Expr>),
    /// `a op b` with `op` one of `+ - * / %`.
    Bin(char, Box<Expr>, Box<Expr>),
}

impl Expr {
    /// The values the expression takes at the grid vertex `(i, j)`: one, or where a `mod` is 0
    /// at a positive argument (a vertex on a block's far edge, shared by two blocks), also the
    /// value with the divisor there (the block's own squares use `p = 1` at that edge). At most
    /// a few; a division by zero gives NaN.
    #[must_use]
    pub fn eval(&self, i: f64, j: f64) -> Vec<f64> {
        match self {
            Expr::Num(x) => vec![*x],
            Expr::Var(Var::I) => vec![i],
            Expr::Var(Var::J) => vec![j],
            Expr::Neg(a) => a.eval(i, j).into_iter().map(|x| -x).collect(),
            Expr::Bin(op, a, b) => {
                let (a, b) = (a.eval(i, j), b.eval(i, j));
                let mut out: Vec<f64> = Vec::new();
                for &x in &a {
                    for &y in &b {
                        let mut push = |v: f64| {
                            if out.len() < MAX_VALUES
                                && !out
                                    .iter()
                                    .any(|w| (w - v).abs() < 1e-12 || (w.is_nan() && v.is_nan()))
                            {
                                out.push(v);
                            }
                        };
                        match op {
                            '+' => push(x + y),
                            '-' => push(x - y),
                            '*' => push(x * y),
                            '/' => push(if y == 0.0 { f64::NAN } else { x / y }),
                            _ => {
                                if y == 0.0 || !y.is_finite() {
                                    push(f64::NAN);
                                    continue;
                                }
                                let r = x.rem_euclid(y.abs());
                                push(r);
                                if r.abs() < 1e-9 && x > 1e-9 {
                                    push(y.abs());
                                }
                            }
                        }
                    }
                }
                out
            }
        }
    }
}

/// Why an expression does not read.
pub(crate) fn unreadable(ja: impl Into<String>, en: impl Into<String>) -> Text {
    Text::new(ja, en)
}

/// What a token looks like in a message.
fn shown(t: &Tok) -> String {
    match t {
        Tok::Num(x) => format!("{x}"),
        Tok::Var(c) => c.to_string(),
        Tok::Word(w) | Tok::Other(w) => w.chars().take(20).collect(),
        Tok::Op('%') => "mod".to_owned(),
        Tok::Op(c) | Tok::Open(c) | Tok::Close(c) => c.to_string(),
        Tok::Eq => "=".to_owned(),
        Tok::Frac => "\\frac".to_owned(),
        Tok::Sep => ",".to_owned(),
        Tok::Newline => "↵".to_owned(),
    }
}

/// Reads one expression from `toks` (all of them).
///
/// # Errors
/// Why it does not read: empty, too long, an unknown name (`p`), a stray symbol, a missing `)`.
pub(crate) fn parse(toks: &[Tok]) -> Result<Expr, Text> {
    if toks.is_empty() {
        return Err(unreadable("式がありません", "there is no expression"));
    }
    if toks.len() > MAX_TOKENS {
        return Err(unreadable("式が長すぎます", "the expression is too long"));
    }
    let mut p = Parser { toks, at: 0, depth: 0 };
    let e = p.sum()?;
    match p.toks.get(p.at) {
        None => Ok(e),
        Some(Tok::Close(_)) => {
            Err(unreadable("閉じ括弧 `)` に対応する `(` がありません", "a `)` without its `(`"))
        }
        Some(t) => Err(p.unexpected(t)),
    }
}

struct Parser<'a> {
    toks: &'a [Tok],
    at: usize,
    depth: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.toks.get(self.at)
    }

    fn unexpected(&self, t: &Tok) -> Text {
        match t {
            Tok::Word(w) => {
                let w: String = w.chars().take(20).collect();
                unreadable(
                    format!("`{w}` は読めません（s と t は i と j の式で書きます）"),
                    format!("`{w}` does not read (write s and t in i and j)"),
                )
            }
            t => {
                let s = shown(t);
                unreadable(
                    format!("`{s}` はここでは読めません"),
                    format!("`{s}` does not read here"),
                )
            }
        }
    }

    fn deeper(&mut self) -> Result<(), Text> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(unreadable("括弧の入れ子が深すぎます", "too many nested parentheses"));
        }
        Ok(())
    }

    /// `a (+|−) b …`
    fn sum(&mut self) -> Result<Expr, Text> {
        let mut e = self.product()?;
        while let Some(Tok::Op(op @ ('+' | '-'))) = self.peek() {
            let op = *op;
            self.at += 1;
            let b = self.product()?;
            e = Expr::Bin(op, Box::new(e), Box::new(b));
        }
        Ok(e)
    }

    /// `a (·|/|mod) b …`, and `a b` (juxtaposition) as `a · b`.
    fn product(&mut self) -> Result<Expr, Text> {
        let mut e = self.unary()?;
        loop {
            let op = match self.peek() {
                Some(Tok::Op(op @ ('*' | '/' | '%'))) => {
                    let op = *op;
                    self.at += 1;
                    op
                }
                Some(Tok::Num(_) | Tok::Var(_) | Tok::Open(_) | Tok::Frac) => '*',
                _ => return Ok(e),
            };
            let b = self.unary()?;
            e = Expr::Bin(op, Box::new(e), Box::new(b));
        }
    }

    /// `−a`, `+a`, or a factor.
    fn unary(&mut self) -> Result<Expr, Text> {
        match self.peek() {
            Some(Tok::Op(op @ ('+' | '-'))) => {
                let negative = *op == '-';
                self.at += 1;
                self.deeper()?;
                let a = self.unary()?;
                self.depth -= 1;
                Ok(if negative { Expr::Neg(Box::new(a)) } else { a })
            }
            _ => self.factor(),
        }
    }

    /// A number, `i`, `j`, `( … )`, `{ … }` or `\frac{a}{b}`.
    fn factor(&mut self) -> Result<Expr, Text> {
        let Some(t) = self.peek().cloned() else {
            return Err(unreadable("式が途中で終わっています", "the expression ends too early"));
        };
        self.at += 1;
        match t {
            Tok::Num(x) => Ok(Expr::Num(x)),
            Tok::Var('j') => Ok(Expr::Var(Var::J)),
            Tok::Var(_) => Ok(Expr::Var(Var::I)),
            Tok::Open(open) => {
                self.deeper()?;
                let e = self.sum()?;
                self.depth -= 1;
                match self.peek() {
                    Some(Tok::Close(close)) if (*close == '}') == (open == '{') => {
                        self.at += 1;
                        Ok(e)
                    }
                    _ => Err(unreadable(
                        format!("閉じ括弧 `{}` がありません", if open == '{' { '}' } else { ')' }),
                        format!("a closing `{}` is missing", if open == '{' { '}' } else { ')' }),
                    )),
                }
            }
            Tok::Frac => {
                self.deeper()?;
                let a = self.factor()?;
                let b = self.factor()?;
                self.depth -= 1;
                Ok(Expr::Bin('/', Box::new(a), Box::new(b)))
            }
            t => {
                self.at -= 1;
                Err(self.unexpected(&t))
            }
        }
    }
}
