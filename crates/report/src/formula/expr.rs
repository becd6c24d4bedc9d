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

/// `text` as tokens, each with its line (`first_line` for the first); `$`, `&`, spaces and
/// LaTeX's spacing and sizing commands are left out.
pub(crate) fn tokens(text: &str, first_line: usize) -> Vec<(usize, Tok)> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut line = first_line;
    let mut k = 0;
    while let Some(&c) = chars.get(k) {
        k += 1;
        let tok = match c {
            '\n' => {
                out.push((line, Tok::Newline));
                line += 1;
                continue;
            }
            c if c.is_whitespace() || matches!(c, '$' | '&' | '~') => continue,
            '0'..='9' | '.' if c != '.' || chars.get(k).is_some_and(char::is_ascii_digit) => {
                let start = k - 1;
                while chars.get(k).is_some_and(char::is_ascii_digit) {
                    k += 1;
                }
                if chars.get(k) == Some(&'.') && chars.get(k + 1).is_some_and(char::is_ascii_digit)
                {
                    k += 1;
                    while chars.get(k).is_some_and(char::is_ascii_digit) {
                        k += 1;
                    }
                }
                let digits: String = chars[start..k].iter().collect();
                let digits = if digits.starts_with('.') { format!("0{digits}") } else { digits };
                match digits.parse::<f64>() {
                    Ok(x) if x.is_finite() => Tok::Num(x),
                    _ => Tok::Other(digits),
                }
            }
            c if c.is_ascii_alphabetic() => {
                let start = k - 1;
                while chars.get(k).is_some_and(char::is_ascii_alphabetic) {
                    k += 1;
                }
                let word: String = chars[start..k].iter().collect();
                if word == "mod" {
                    Tok::Op('%')
                } else if word.chars().all(|c| matches!(c, 'i' | 'j')) {
                    // `ij` is i·j, as juxtaposition reads.
                    for c in word.chars() {
                        out.push((line, Tok::Var(c)));
                    }
                    continue;
                } else {
                    Tok::Word(word)
                }
            }
            '\\' => {
                let start = k;
                while chars.get(k).is_some_and(char::is_ascii_alphabetic) {
                    k += 1;
                }
                let name: String = chars[start..k].iter().collect();
                match name.as_str() {
                    "" => match chars.get(k) {
                        Some('\\') => {
                            k += 1;
                            Tok::Sep
                        }
                        // Spacing, and the math delimiters `\[ \] \( \)`.
                        Some(',' | ';' | '!' | ':' | ' ' | '[' | ']' | '(' | ')') => {
                            k += 1;
                            continue;
                        }
                        Some(&c) => {
                            k += 1;
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
                    // `\operatorname{mod}`, `\mathrm{mod}`, `\text{mod}`: the word inside reads.
                    "operatorname" | "mathrm" | "text" | "textrm" | "mathit" => {
                        if chars.get(k) == Some(&'{') {
                            let close = chars[k..].iter().position(|&c| c == '}');
                            if let Some(close) = close {
                                let inner: String = chars[k + 1..k + close].iter().collect();
                                let inner = inner.trim();
                                if inner == "mod" {
                                    k += close + 1;
                                    out.push((line, Tok::Op('%')));
                                    continue;
                                }
                                if matches!(inner, "i" | "j") {
                                    k += close + 1;
                                    out.push((line, Tok::Var(inner.chars().next().unwrap_or('i'))));
                                    continue;
                                }
                            }
                        }
                        continue;
                    }
                    "begin" | "end" => {
                        // `\begin{aligned}`: the environment's name is not part of the formula.
                        if chars.get(k) == Some(&'{')
                            && let Some(close) = chars[k..].iter().position(|&c| c == '}')
                        {
                            k += close + 1;
                        }
                        continue;
                    }
                    _ => Tok::Other(format!("\\{name}")),
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
        out.push((line, tok));
    }
    out
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
