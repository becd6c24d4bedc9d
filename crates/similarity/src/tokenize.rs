//! Rust source as normalised tokens, as MOSS and JPlag read a program: comments (doc comments
//! too) are dropped, every identifier is one token kind and every literal one kind per literal
//! kind (a string, a character, an integer, a float …), while keywords, punctuation and
//! brackets are kept as they are. Renaming a variable, changing a number or rewording a message
//! therefore changes nothing; changing the program's shape does.
//!
//! The lexer is proc-macro2's (syn's, the one `cg grade`'s screen uses), with line numbers.
//! A file it cannot read (unbalanced brackets, a stray character: code that would not compile
//! either) is read again with its brackets blanked out, and failing that line by line, so an
//! unfinished submission is still compared.

use proc_macro2::{Delimiter, TokenStream, TokenTree};

/// What a token is, after normalisation: the only thing winnowing hashes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// Any identifier (a variable, a function, a type, a lifetime's name).
    Ident,
    /// A keyword, by its index in [`KEYWORDS`].
    Keyword(u8),
    /// One punctuation character (`::` is two).
    Punct(char),
    /// An opening bracket: `(`, `[` or `{`.
    Open(char),
    /// A closing bracket: `)`, `]` or `}`.
    Close(char),
    /// A literal, by its kind.
    Literal(LiteralKind),
}

/// The kinds of literal, each one token kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum LiteralKind {
    /// `"…"`, `r"…"`, `r#"…"#`.
    Str,
    /// `b"…"`, `br"…"`.
    ByteStr,
    /// `c"…"`.
    CStr,
    /// `'x'`.
    Char,
    /// `b'x'`.
    Byte,
    /// `42`, `0xff`, `7u32`.
    Int,
    /// `1.5`, `1e-3`, `2f32`.
    Float,
}

/// One token: its kind, its line (1-based) and, for a number, its value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Token {
    /// The normalised kind.
    pub kind: Kind,
    /// The line it starts on, 1-based.
    pub line: usize,
    /// The value of a numeric literal (for the cross-variant check, never hashed).
    pub number: Option<f64>,
}

/// Rust's keywords (strict and reserved, 2024 edition), kept as themselves.
pub const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut",
    "pub", "ref", "return", "self", "Self", "static", "struct", "super", "trait", "true", "type",
    "unsafe", "use", "where", "while", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "try", "typeof", "unsized", "virtual", "yield",
];

/// The tokens of `source`, comments and doc attributes (`#[doc = …]`, which `///` becomes)
/// left out.
///
/// The lexer keeps every text it read, for its spans, in a map per thread until the thread
/// ends: `cg similarity` reads a whole class on a few threads, and a crafted submission held
/// about 1 GB there. The map is emptied once the tokens are taken (they keep lines, not spans).
#[must_use]
pub fn tokens(source: &str) -> Vec<Token> {
    let out = read_tokens(source);
    proc_macro2::extra::invalidate_current_thread_spans();
    out
}

/// [`tokens`], the lexer's map left as it is.
fn read_tokens(source: &str) -> Vec<Token> {
    if let Ok(stream) = source.parse::<TokenStream>() {
        let mut out = Vec::new();
        walk(stream, 0, &mut out);
        return out;
    }
    // Unbalanced brackets: blank them out (same lengths, so the lines stay).
    let blanked: String =
        source.chars().map(|c| if "()[]{}".contains(c) { ' ' } else { c }).collect();
    if let Ok(stream) = blanked.parse::<TokenStream>() {
        let mut out = Vec::new();
        walk(stream, 0, &mut out);
        return out;
    }
    // Still not Rust (an unterminated string or comment): line by line, skipping what fails.
    let mut out = Vec::new();
    for (i, line) in blanked.lines().enumerate() {
        if let Ok(stream) = line.parse::<TokenStream>() {
            walk(stream, i, &mut out);
        }
    }
    out
}

/// The tokens of `stream`, groups opened and closed in place. Iterative, with a stack of the
/// groups being read: a file of 40 000 nested brackets (a hostile submission) would overflow
/// the thread's stack if each group were a call, and abort the whole class's run.
fn walk(stream: TokenStream, line_offset: usize, out: &mut Vec<Token>) {
    // Each open group: its trees, the next to read, and its closing token.
    let mut stack: Vec<(Vec<TokenTree>, usize, Option<Token>)> =
        vec![(stream.into_iter().collect(), 0, None)];
    while let Some((trees, i, _)) = stack.last_mut() {
        let Some(tt) = trees.get(*i) else {
            if let Some((_, _, Some(close))) = stack.pop() {
                out.push(close);
            }
            continue;
        };
        let line = tt.span().start().line + line_offset;
        match tt {
            TokenTree::Punct(p) if p.as_char() == '#' && doc_attribute(&trees[*i + 1..]) => {
                // `#[doc …]` or `#![doc …]`: a comment in disguise.
                *i += if matches!(trees.get(*i + 1), Some(TokenTree::Punct(_))) { 3 } else { 2 };
                continue;
            }
            TokenTree::Group(g) => {
                let g = g.clone();
                *i += 1;
                let close = match g.delimiter() {
                    Delimiter::Parenthesis => Some(('(', ')')),
                    Delimiter::Bracket => Some(('[', ']')),
                    Delimiter::Brace => Some(('{', '}')),
                    Delimiter::None => None,
                };
                let close = close.map(|(open, close)| {
                    out.push(Token { kind: Kind::Open(open), line, number: None });
                    let end = g.span_close().start().line + line_offset;
                    Token { kind: Kind::Close(close), line: end, number: None }
                });
                stack.push((g.stream().into_iter().collect(), 0, close));
                continue;
            }
            TokenTree::Ident(ident) => {
                let name = ident.to_string();
                let name = name.strip_prefix("r#").unwrap_or(&name);
                let kind = KEYWORDS
                    .iter()
                    .position(|k| *k == name)
                    .and_then(|k| u8::try_from(k).ok())
                    .map_or(Kind::Ident, Kind::Keyword);
                out.push(Token { kind, line, number: None });
            }
            TokenTree::Punct(p) => {
                out.push(Token { kind: Kind::Punct(p.as_char()), line, number: None });
            }
            TokenTree::Literal(lit) => {
                let text = lit.to_string();
                let kind = literal_kind(&text);
                let number = match kind {
                    LiteralKind::Int | LiteralKind::Float => number(&text),
                    _ => None,
                };
                out.push(Token { kind: Kind::Literal(kind), line, number });
            }
        }
        *i += 1;
    }
}

/// Whether `rest` (what follows a `#`) is `[doc …]` or `![doc …]`.
fn doc_attribute(rest: &[TokenTree]) -> bool {
    let group = match rest {
        [TokenTree::Group(g), ..] => g,
        [TokenTree::Punct(p), TokenTree::Group(g), ..] if p.as_char() == '!' => g,
        _ => return false,
    };
    group.delimiter() == Delimiter::Bracket
        && matches!(group.stream().into_iter().next(), Some(TokenTree::Ident(i)) if i == "doc")
}

/// The kind of a literal, from its text.
#[must_use]
pub fn literal_kind(text: &str) -> LiteralKind {
    let first = text.chars().next().unwrap_or('0');
    if text.starts_with("b'") {
        LiteralKind::Byte
    } else if text.starts_with("b\"") || text.starts_with("br") {
        LiteralKind::ByteStr
    } else if text.starts_with("c\"") || text.starts_with("cr") {
        LiteralKind::CStr
    } else if first == '\'' {
        LiteralKind::Char
    } else if first == '"' || first == 'r' {
        LiteralKind::Str
    } else if is_float(text) {
        LiteralKind::Float
    } else {
        LiteralKind::Int
    }
}

fn is_float(text: &str) -> bool {
    let lower = text.to_ascii_lowercase();
    if lower.starts_with("0x") || lower.starts_with("0o") || lower.starts_with("0b") {
        return false;
    }
    lower.contains('.') || lower.contains('e') || lower.ends_with("f32") || lower.ends_with("f64")
}

/// The value of a numeric literal (`1_000`, `0x1f`, `2.5f32`, `1e-3`), if it has one.
#[must_use]
pub fn number(text: &str) -> Option<f64> {
    let text: String = text.chars().filter(|c| *c != '_').collect();
    let lower = text.to_ascii_lowercase();
    for (prefix, radix) in [("0x", 16), ("0o", 8), ("0b", 2)] {
        if let Some(digits) = lower.strip_prefix(prefix) {
            let digits = digits.trim_end_matches(|c: char| !c.is_digit(radix));
            return u64::from_str_radix(digits, radix).ok().map(|v| v as f64);
        }
    }
    const SUFFIXES: [&str; 14] = [
        "f32", "f64", "i128", "u128", "isize", "usize", "i16", "u16", "i32", "u32", "i64", "u64",
        "i8", "u8",
    ];
    let body = SUFFIXES.iter().find_map(|s| lower.strip_suffix(s)).unwrap_or(&lower);
    body.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// The code of the hints in `source`'s comments: every `` `…` `` span and every fenced block of
/// its comment lines (`//`, `///`, `//!`), in order. The stubs' hints are base code: students
/// are told to write them.
#[must_use]
pub fn comment_code(source: &str) -> Vec<String> {
    let mut blocks: Vec<String> = Vec::new();
    let mut current = String::new();
    for line in source.lines() {
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix("//") {
            let rest = rest.strip_prefix(['/', '!']).unwrap_or(rest);
            current.push_str(rest);
            current.push('\n');
        } else if !current.is_empty() {
            blocks.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        blocks.push(current);
    }
    let mut code = Vec::new();
    for block in blocks {
        let mut fenced = false;
        let mut fence = String::new();
        let mut prose = String::new();
        for line in block.lines() {
            if line.trim_start().starts_with("```") {
                if fenced {
                    code.push(std::mem::take(&mut fence));
                }
                fenced = !fenced;
            } else if fenced {
                fence.push_str(line);
                fence.push('\n');
            } else {
                prose.push_str(line);
                prose.push('\n');
            }
        }
        // Inline spans: the text between the 1st and 2nd backtick, the 3rd and 4th, …
        code.extend(prose.split('`').skip(1).step_by(2).map(str::to_owned));
    }
    // The hints are written for people (`…`, `θ`): other characters become spaces.
    code.into_iter()
        .map(|c| c.chars().map(|ch| if ch.is_ascii() { ch } else { ' ' }).collect())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(source: &str) -> Vec<Kind> {
        tokens(source).into_iter().map(|t| t.kind).collect()
    }

    /// 40 000 nested brackets are read without overflowing the stack (which aborted the whole
    /// run), each bracket a token.
    #[test]
    fn the_lexers_map_of_texts_is_emptied_after_each_file() {
        // A span from before `tokens` points into the map; emptied, the map no longer knows
        // it (proc-macro2 then panics on its use). Not emptied, every text read stays there.
        let stream: TokenStream = "x".parse().unwrap();
        let TokenTree::Ident(x) = stream.into_iter().next().unwrap() else { panic!() };
        assert_eq!(x.span().start().line, 1);
        let _ = tokens(&"let x = 1;\n".repeat(1000));
        let after = std::panic::catch_unwind(|| x.span().start());
        assert!(after.is_err(), "the span still resolves: the texts read are still held");
    }

    #[test]
    fn deeply_nested_brackets_are_read_without_overflowing_the_stack() {
        let depth = 40_000;
        let deep = format!("fn f() {{ let x = {}1{}; }}", "(".repeat(depth), ")".repeat(depth));
        let tokens = tokens(&deep);
        let opens = tokens.iter().filter(|t| t.kind == Kind::Open('(')).count();
        assert_eq!(opens, depth + 1);
    }

    #[test]
    fn renaming_and_rewording_change_nothing_but_the_shape_does() {
        let a =
            "/// Sum.\nfn total(xs: &[f32]) -> f32 { let mut s = 0.0; for x in xs { s += x; } s }";
        let b = "// mine\nfn add_up(values: &[f32]) -> f32 {\n    let mut acc = 1.5; // start\n    for v in values { acc += v; }\n    acc\n}";
        assert_eq!(kinds(a), kinds(b));
        // A different shape: `while` for `for`, a call for the literal.
        let c = "fn total(xs: &[f32]) -> f32 { let mut s = zero(); while x in xs { s += x; } s }";
        assert_ne!(kinds(a), kinds(c));
        // An integer is not a float; a string is neither.
        assert_ne!(kinds("let a = 1;"), kinds("let a = 1.0;"));
        assert_ne!(kinds("let a = \"1\";"), kinds("let a = 1;"));
        assert_eq!(kinds("let a = \"x\";"), kinds("let b = r#\"another\"#;"));
    }

    #[test]
    fn keywords_brackets_and_lines_are_kept_and_doc_attributes_dropped() {
        let t = tokens("//! Module.\n#[doc = \"hidden\"]\nfn f() {\n  g(1.5f32, 0x10)\n}\n");
        let k: Vec<Kind> = t.iter().map(|t| t.kind).collect();
        let fn_kw = Kind::Keyword(KEYWORDS.iter().position(|k| *k == "fn").unwrap() as u8);
        assert_eq!(
            k,
            [
                fn_kw,
                Kind::Ident,
                Kind::Open('('),
                Kind::Close(')'),
                Kind::Open('{'),
                Kind::Ident,
                Kind::Open('('),
                Kind::Literal(LiteralKind::Float),
                Kind::Punct(','),
                Kind::Literal(LiteralKind::Int),
                Kind::Close(')'),
                Kind::Close('}'),
            ]
        );
        assert_eq!(t[0].line, 3);
        assert_eq!(t[7].line, 4);
        assert_eq!(t[7].number, Some(1.5));
        assert_eq!(t[9].number, Some(16.0));
        assert_eq!(t[11].line, 5, "a closing bracket is on its own line");
        // #[test] is an attribute, not a comment.
        assert_eq!(kinds("#[test] fn f() {}").len(), 10);
    }

    #[test]
    fn unbalanced_code_is_still_read() {
        let t = tokens("fn f() {\n  let x = 2.5;\n");
        assert!(t.iter().any(|t| t.number == Some(2.5) && t.line == 2), "{t:?}");
        let t = tokens("let s = \"open\nlet y = 3.25;\n");
        assert!(t.iter().any(|t| t.number == Some(3.25) && t.line == 2), "{t:?}");
    }

    #[test]
    fn numbers_are_read_with_their_suffixes_and_separators() {
        assert_eq!(number("1_000"), Some(1000.0));
        assert_eq!(number("2.5f32"), Some(2.5));
        assert_eq!(number("7u8"), Some(7.0));
        assert_eq!(number("1e-3"), Some(0.001));
        assert_eq!(number("0b101"), Some(5.0));
        assert_eq!(literal_kind("2f32"), LiteralKind::Float);
        assert_eq!(literal_kind("0xef"), LiteralKind::Int);
        assert_eq!(literal_kind("b'a'"), LiteralKind::Byte);
        assert_eq!(literal_kind("br\"a\""), LiteralKind::ByteStr);
        assert_eq!(literal_kind("c\"a\""), LiteralKind::CStr);
    }

    #[test]
    fn the_hints_in_comments_are_found() {
        let src = "/// Hint: `(vb - va).cross(vc - va)` and\n/// ```\n/// let x = 1;\n/// ```\nfn f() {}\n// `a\n// b`\n";
        let mut code: Vec<String> = comment_code(src).iter().map(|c| c.trim().to_owned()).collect();
        code.sort();
        assert_eq!(code, ["(vb - va).cross(vc - va)", "a\n b", "let x = 1;"]);
        // Code outside comments is not a hint.
        assert!(comment_code("let s = \"`x`\";").is_empty());
    }
}
