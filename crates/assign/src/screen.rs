//! The second line behind the build's sandbox: a submission's files may not reach outside
//! themselves at compile time. Grading refuses such a submission ([`screen`]); `cg check`
//! leaves such a file out and says why (`crate::local`), so that a student hears of it before
//! submitting. [`other_files`] finds the modules kept in files of their own (`mod geom;`),
//! which grading does not read: such a file does not compile there. Each file is read as Rust tokens (comments and string contents
//! are not tokens, so a word in them does not count) and refused, with its file, line and
//! what, when it uses:
//!
//! - `include!`, `include_str!`, `include_bytes!`: read another file into the program;
//! - `env!`, `option_env!`: read the grader's environment (`HOME`, `PWD`) into the feedback;
//! - `#[path = …]`: compile another file as a module (the kit's own solutions);
//! - `extern crate`: link a crate the exercise does not name;
//! - `proc_macro`, `global_asm!`, `asm!`, `#[link…]`: code generators and foreign code.
//!
//! The macros are refused wherever their name appears before `!`, also inside a
//! `macro_rules!` body or behind a path (`std::include_str!`), so no macro can hide them.

use proc_macro2::{Delimiter, TokenStream, TokenTree};

use cg_harness::Text;

/// One refused use: the file, the line (1-based) and what it is.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refused {
    /// `exercises/src/a1.rs`.
    pub file: String,
    /// The line.
    pub line: usize,
    /// What was found: `include_str!`, `#[path]`, `extern crate`.
    pub what: String,
}

/// Macros that read files or the environment at compile time, or bring in foreign code.
const MACROS: [&str; 7] =
    ["include", "include_str", "include_bytes", "env", "option_env", "global_asm", "asm"];

/// Attributes that reach outside the file, wherever they stand in an attribute (also inside
/// `#[cfg_attr(all(), path = …)]`, which applies them all the same).
const ATTRIBUTES: [&str; 6] =
    ["path", "link", "link_name", "proc_macro", "proc_macro_derive", "proc_macro_attribute"];

/// Every refused use in `text`, the file `file`. A first line `#!…` that is not an attribute
/// is left out, as the compiler leaves it out. A file the lexer does not read (which the
/// compiler may still read: a line `#!/x )` made the lexer fail, and everything after it went
/// unscreened) is screened word by word instead.
#[must_use]
pub fn screen(file: &str, text: &str) -> Vec<Refused> {
    let text = without_shebang(text);
    let mut found = Vec::new();
    match text.parse::<TokenStream>() {
        Ok(tokens) => walk(file, tokens, &mut found),
        Err(_) => by_words(file, text, &mut found),
    }
    // The lexer keeps each text read in a map per thread for its spans; a class's files
    // would stay there until grading ends (`walk` keeps lines, not spans).
    proc_macro2::extra::invalidate_current_thread_spans();
    found.sort_by_key(|r| r.line);
    found
}

/// `text` without its first line when that line is a shebang (`#!` not followed by `[`, as the
/// compiler reads it), the line kept empty so that lines keep their numbers.
fn without_shebang(text: &str) -> &str {
    let Some(rest) = text.strip_prefix("#!") else { return text };
    if rest.trim_start().starts_with('[') {
        return text;
    }
    text.find('\n').map_or("", |end| &text[end..])
}

/// The screen of a file the lexer does not read: each line's words, comments and strings
/// included (stricter than the tokens: the file reads as no Rust the screen knows, so nothing in
/// it is taken for harmless).
fn by_words(file: &str, text: &str, found: &mut Vec<Refused>) {
    let is_word = |c: char| c.is_alphanumeric() || c == '_';
    for (n, line) in text.lines().enumerate() {
        let attribute = line.contains("#[") || line.contains("#![");
        let mut refuse = |what: String| {
            found.push(Refused { file: file.to_owned(), line: n + 1, what });
        };
        let mut start = None;
        // Word boundaries at characters' own boundaries (the line may hold Japanese).
        for (i, c) in line.char_indices().chain(std::iter::once((line.len(), ' '))) {
            match (start, is_word(c)) {
                (None, true) => start = Some(i),
                (Some(s), false) => {
                    let (word, after) = (&line[s..i], line[i..].trim_start());
                    if MACROS.contains(&word) && after.starts_with('!') {
                        refuse(format!("{word}!"));
                    }
                    if word == "extern" && after.starts_with("crate") {
                        refuse("extern crate".to_owned());
                    }
                    if attribute && ATTRIBUTES.contains(&word) {
                        refuse(format!("#[{word}]"));
                    }
                    start = None;
                }
                _ => {}
            }
        }
    }
}

/// Every group of `tokens`, each read as a flat list by `visit`. Iterative, with a list of the
/// groups still to read: a file of 40 000 nested brackets would overflow the thread's stack if
/// each group were a call, and abort the grading of the whole class.
fn each_group(tokens: TokenStream, mut visit: impl FnMut(&[TokenTree])) {
    let mut groups = vec![tokens];
    while let Some(tokens) = groups.pop() {
        let tokens: Vec<TokenTree> = tokens.into_iter().collect();
        visit(&tokens);
        groups.extend(tokens.iter().filter_map(|tt| match tt {
            TokenTree::Group(g) => Some(g.stream()),
            _ => None,
        }));
    }
}

/// Every refused use in `tokens`, the file `file`.
fn walk(file: &str, tokens: TokenStream, found: &mut Vec<Refused>) {
    each_group(tokens, |tokens| flat(file, tokens, found));
}

/// One group's own tokens (its groups are read by [`each_group`]).
fn flat(file: &str, tokens: &[TokenTree], found: &mut Vec<Refused>) {
    let refuse = |found: &mut Vec<Refused>, tt: &TokenTree, what: String| {
        found.push(Refused { file: file.to_owned(), line: tt.span().start().line, what });
    };
    for (k, tt) in tokens.iter().enumerate() {
        match tt {
            TokenTree::Ident(ident) => {
                let name = ident.to_string();
                let next = tokens.get(k + 1);
                let bang = matches!(next, Some(TokenTree::Punct(p)) if p.as_char() == '!');
                if bang && MACROS.contains(&name.as_str()) {
                    refuse(found, tt, format!("{name}!"));
                }
                if name == "extern" && matches!(next, Some(TokenTree::Ident(c)) if c == "crate") {
                    refuse(found, tt, "extern crate".to_owned());
                }
            }
            TokenTree::Punct(p) if p.as_char() == '#' => {
                // `#[attr …]` or `#![attr …]`: the group's first word.
                let group = match (tokens.get(k + 1), tokens.get(k + 2)) {
                    (Some(TokenTree::Group(g)), _) => Some(g),
                    (Some(TokenTree::Punct(b)), Some(TokenTree::Group(g)))
                        if b.as_char() == '!' =>
                    {
                        Some(g)
                    }
                    _ => None,
                };
                if let Some(g) = group.filter(|g| g.delimiter() == Delimiter::Bracket)
                    && let Some(name) = attribute_reaching_out(g.stream())
                {
                    refuse(found, tt, format!("#[{name}]"));
                }
            }
            _ => {}
        }
    }
}

/// The modules of `text` (the file `file`) kept in files of their own, `mod geom;`, each with
/// its line and `mod geom;` as its `what`. Grading reads only the assignments' own files
/// (`exercises/src/a1.rs`, …), so such a module does not compile there. A file the lexer does
/// not read gives none (the compiler names its errors).
#[must_use]
pub fn other_files(file: &str, text: &str) -> Vec<Refused> {
    let mut found = Vec::new();
    if let Ok(tokens) = without_shebang(text).parse::<TokenStream>() {
        each_group(tokens, |tokens| {
            for (k, w) in tokens.windows(3).enumerate() {
                if let [TokenTree::Ident(m), TokenTree::Ident(name), TokenTree::Punct(semi)] = w
                    && m == "mod"
                    && semi.as_char() == ';'
                    && !test_only(&tokens[..k])
                {
                    let line = m.span().start().line;
                    found.push(Refused {
                        file: file.to_owned(),
                        line,
                        what: format!("mod {name};"),
                    });
                }
            }
        });
    }
    proc_macro2::extra::invalidate_current_thread_spans();
    found.sort_by_key(|r| r.line);
    found
}

/// Whether the item that `before` ends just before is `#[cfg(test)]`: its attributes and
/// visibility (`pub`, `pub(crate)`) read backwards. Such a module (`#[cfg(test)] mod tests;`)
/// is never built by grading, so its file is not needed there.
fn test_only(before: &[TokenTree]) -> bool {
    let mut k = before.len();
    loop {
        match before[..k] {
            [.., TokenTree::Ident(ref i)] if i == "pub" => k -= 1,
            [.., TokenTree::Ident(ref i), TokenTree::Group(ref g)]
                if i == "pub" && g.delimiter() == Delimiter::Parenthesis =>
            {
                k -= 2;
            }
            [.., TokenTree::Punct(ref hash), TokenTree::Group(ref g)]
                if hash.as_char() == '#' && g.delimiter() == Delimiter::Bracket =>
            {
                let attr: String = g.stream().to_string().split_whitespace().collect();
                if attr == "cfg(test)" {
                    return true;
                }
                k -= 2;
            }
            _ => return false,
        }
    }
}

/// The first name of [`ATTRIBUTES`] anywhere in an attribute's tokens, its groups included
/// (`cfg_attr(all(), path = …)`, `cfg_attr(x, cfg_attr(y, link(…)))`).
fn attribute_reaching_out(tokens: TokenStream) -> Option<String> {
    let mut groups = vec![tokens];
    while let Some(tokens) = groups.pop() {
        for tt in tokens {
            match tt {
                TokenTree::Ident(i) if ATTRIBUTES.contains(&i.to_string().as_str()) => {
                    return Some(i.to_string());
                }
                TokenTree::Group(g) => groups.push(g.stream()),
                _ => {}
            }
        }
    }
    None
}

/// The message for `refused` (at least one): each use with its file and line, and why.
#[must_use]
pub fn message(refused: &[Refused]) -> Text {
    let list: Vec<String> =
        refused.iter().map(|r| format!("{}:{}: {}", r.file, r.line, r.what)).collect();
    let list = list.join(", ");
    Text::new(
        format!(
            "提出物が自分のファイルの外を読もうとしています（{list}）。include!・include_str!・include_bytes!・env!・option_env!・#[path]・extern crate は使えません。課題に必要なものは cg_student から使えます"
        ),
        format!(
            "the submission reaches outside its own files ({list}): include!, include_str!, include_bytes!, env!, option_env!, #[path] and extern crate are not accepted; what the exercises need comes from cg_student"
        ),
    )
}

/// What `cg check` says of a file that grading would refuse (`refused`, of one file): each use,
/// and that grading refuses the whole submission for it.
#[must_use]
pub fn refused_locally(refused: &[Refused]) -> Text {
    let m = message(refused);
    Text::new(
        format!("採点では、このファイルのために提出物全体が受け付けられません（0 点）: {}", m.ja),
        format!("grading refuses the whole submission (0 points) for this file: {}", m.en),
    )
}

/// What `cg check` says of a module kept in a file of its own (`r`, from [`other_files`]) in
/// the file of assignment `module` (`a1`).
#[must_use]
pub fn other_file_message(r: &Refused, module: &str) -> Text {
    let name = r.what.trim_start_matches("mod ").trim_end_matches(';');
    Text::new(
        format!(
            "{}:{}: `{}` は別のファイル（exercises/src/{module}/{name}.rs など）を読みますが、採点で読むのは exercises/src/ の課題のファイル（a1.rs … s.rs）と student.toml だけなので、採点ではコンパイルできません。`mod {name} {{ … }}` のように {module}.rs の中に書いてください",
            r.file, r.line, r.what
        ),
        format!(
            "{}:{}: `{}` reads another file (exercises/src/{module}/{name}.rs or the like), but grading reads only the assignments' files in exercises/src/ (a1.rs … s.rs) and student.toml, so it does not compile there: write it inside {module}.rs as `mod {name} {{ … }}`",
            r.file, r.line, r.what
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn whats(text: &str) -> Vec<(usize, String)> {
        screen("a1.rs", text).into_iter().map(|r| (r.line, r.what)).collect()
    }

    /// 40 000 nested brackets (a hostile file of 80 KB) are read without overflowing the
    /// stack (which aborted the whole class's grading), and what hides at the bottom is found.
    #[test]
    fn the_lexers_map_of_texts_is_emptied_after_each_file() {
        // A span from before `screen` resolves only while the lexer's map still holds every
        // text it read (see `cg_similarity::tokenize::tokens`).
        let stream: TokenStream = "x".parse().unwrap();
        let TokenTree::Ident(x) = stream.into_iter().next().unwrap() else { panic!() };
        assert_eq!(x.span().start().line, 1);
        assert!(screen("a.rs", "fn f() {}").is_empty());
        let after = std::panic::catch_unwind(|| x.span().start());
        assert!(after.is_err(), "the span still resolves: the texts read are still held");
    }

    #[test]
    fn deeply_nested_brackets_are_read_without_overflowing_the_stack() {
        let depth = 40_000;
        let deep = format!(
            "fn f() {{ let x = {}include_str!(\"/etc/passwd\"){}; }}",
            "(".repeat(depth),
            ")".repeat(depth)
        );
        assert_eq!(whats(&deep), [(1, "include_str!".to_owned())]);
    }

    #[test]
    fn every_way_out_is_refused_with_its_line() {
        let attacks = [
            ("#[path = \"/kit/solutions/src/a1.rs\"]\nmod r;", (1, "#[path]")),
            ("const P: &str = include_str!(\"/etc/passwd\");", (1, "include_str!")),
            ("const Z: &[u8] = include_bytes!(\"/dev/zero\");", (1, "include_bytes!")),
            ("\ninclude!(\"/kit/solutions/src/a1.rs\");", (2, "include!")),
            ("fn f() -> &'static str { env!(\"HOME\") }", (1, "env!")),
            ("fn f() -> Option<&'static str> { option_env!(\"PWD\") }", (1, "option_env!")),
            ("extern crate cg_core;", (1, "extern crate")),
            ("fn f() { let _ = core::include_str!(\"/etc/passwd\"); }", (1, "include_str!")),
            // Hidden inside a macro of the student's own.
            ("macro_rules! m { () => { include_str!(\"/etc/passwd\") } }", (1, "include_str!")),
            ("#![path = \"x\"]", (1, "#[path]")),
            ("#[doc = include_str!(\"/etc/passwd\")]\nfn f() {}", (1, "include_str!")),
            ("#[link(name = \"c\")]\nunsafe extern \"C\" {}", (1, "#[link]")),
            ("fn f() { unsafe { core::arch::asm!(\"nop\") } }", (1, "asm!")),
            // An attribute applied through cfg_attr is applied all the same.
            ("#[cfg_attr(all(), path = \"/kit/solutions/src/a1.rs\")]\nmod r;", (1, "#[path]")),
            ("#[cfg_attr(all(), cfg_attr(all(), link(name = \"c\")))]", (1, "#[link]")),
            // A first line the compiler leaves out (a shebang) that the lexer cannot read: what
            // follows is screened all the same.
            ("#!/x )\nconst P: &str = include_str!(\"/etc/passwd\");", (2, "include_str!")),
            // A file the lexer does not read, screened word by word.
            (
                "fn f( {\n// 頂点\nconst P: &str = include_str !(\"/etc/passwd\");",
                (3, "include_str!"),
            ),
            ("fn f( {\n#[cfg_attr(all(), path = \"x\")] mod r;", (2, "#[path]")),
        ];
        for (text, (line, what)) in attacks {
            assert_eq!(whats(text), [(line, what.to_owned())], "{text}");
        }
    }

    #[test]
    fn words_in_comments_and_strings_and_ordinary_code_pass() {
        let fine = r#"
//! include_str!("/etc/passwd") in a comment is only words.
/// env!("HOME") in a doc comment too.
use cg_student::a1::Spec;
pub fn vertices(spec: &Spec) -> Vec<cg_student::glam::Vec3> {
    let env = "include_bytes!(\"x\")"; // a string
    let path = std::path::Path::new("path");
    let _ = (env, path, spec);
    todo!("a1.t1: write it")
}
#[must_use]
pub fn extern_name() -> &'static str { "extern crate" }
"#;
        assert_eq!(whats(fine), []);
        // Not Rust the lexer reads, with nothing that reaches out: left to the compiler.
        assert_eq!(whats("fn f( {\n// 頂点の path と環境\nlet x = 1;"), []);
        // An inner attribute on the first line is no shebang, and harmless ones pass.
        assert_eq!(whats("#![allow(dead_code)]\n#[cfg_attr(test, derive(Debug))]\nstruct S;"), []);
    }

    #[test]
    fn modules_in_files_of_their_own_are_found_with_their_lines() {
        let text = "//! mod in_a_comment;\nmod geom;\npub(crate) mod util;\nmod inline { pub fn f() {} }\nfn f() { let s = \"mod s;\"; }\nmod outer {\n    mod inner;\n}\n";
        let found: Vec<(usize, String)> =
            other_files("a1.rs", text).into_iter().map(|r| (r.line, r.what)).collect();
        assert_eq!(
            found,
            [
                (2, "mod geom;".to_owned()),
                (3, "mod util;".to_owned()),
                (7, "mod inner;".to_owned())
            ]
        );
        // Not screened as a refusal: grading builds the file, and the compiler names it.
        assert_eq!(whats(text), []);
        // A module for tests only is never built by grading: not named (it was, and `cg check`
        // left the whole file out). Another `cfg` may be built: named.
        let text = "#[cfg(test)]\nmod tests;\n#[cfg(test)]\n#[allow(unused)]\npub(crate) mod more;\n#[allow(unused)] #[cfg( test )] pub mod t2;\n#[cfg(feature = \"x\")]\nmod x;\n";
        let found: Vec<(usize, String)> =
            other_files("a1.rs", text).into_iter().map(|r| (r.line, r.what)).collect();
        assert_eq!(found, [(8, "mod x;".to_owned())]);
        let m = other_file_message(&other_files("exercises/src/a1.rs", "mod geom;")[0], "a1");
        assert!(m.ja.starts_with("exercises/src/a1.rs:1: `mod geom;` は別のファイル"), "{}", m.ja);
        assert!(m.en.contains("write it inside a1.rs as `mod geom { … }`"), "{}", m.en);
    }

    /// A file with a byte-order mark (Notepad's "UTF-8 (BOM 付き)"; rustc skips it) is read as
    /// the same file without: a comment naming `env!` is no use of it, and `mod geom;` is found.
    #[test]
    fn a_byte_order_mark_is_skipped_as_rustc_skips_it() {
        assert_eq!(whats("\u{feff}// env! は使いません\nfn f() {}\n"), []);
        assert_eq!(whats("\u{feff}const P: &str = env!(\"HOME\");\n"), [(1, "env!".to_owned())]);
        let found: Vec<(usize, String)> = other_files("a1.rs", "\u{feff}mod geom;\n")
            .into_iter()
            .map(|r| (r.line, r.what))
            .collect();
        assert_eq!(found, [(1, "mod geom;".to_owned())]);
    }

    #[test]
    fn the_message_names_each_use_in_both_languages() {
        let r = screen("exercises/src/a1.rs", "\n\nconst P: &str = include_str!(\"/etc/passwd\");");
        let m = message(&r);
        assert!(m.en.contains("exercises/src/a1.rs:3: include_str!"), "{}", m.en);
        assert!(m.ja.contains("exercises/src/a1.rs:3: include_str!"), "{}", m.ja);
        assert!(m.ja.contains("使えません"));
    }
}
