//! The kit writes each term one way (docs/conventions.md, "Terms / 用語"): the same concept gets
//! the same word in each language, the lecture's word for the lecture's concepts. This test reads
//! the string literals of every Rust file of the kit and fails on the variants that were removed,
//! naming the word to use instead. Comments are not read.

mod sources;

/// The removed variants and the word to use instead. A variant is looked for in the literal
/// between its quotes (`"確認"` is the whole literal `確認`); where the word to use contains the
/// variant (`表の版` in `課題表の版`), the word to use does not count as the variant.
const FORBIDDEN: [(&str, &str); 23] = [
    ("表の版", "課題表の版"),
    ("画素", "ピクセル"),
    ("頂点法線", "頂点の法線"),
    ("世界座標", "ワールド座標系"),
    ("視点座標", "カメラ座標系"),
    ("視野変換", "視点の変換"),
    ("カメラの変換", "視点の変換"),
    ("カットオフ", "広がり (cut-off)"),
    ("光源計算", "光源処理"),
    ("\"確認\"", "\"チェック\" (the `check` command)"),
    ("確認: cargo", "チェック: cargo"),
    ("グーロー", "グロー"),
    ("レンダラー", "レンダラ"),
    ("チャネル", "チャンネル"),
    ("カンマ", "コンマ"),
    ("Student ID", "student number"),
    ("world coordinates", "world space"),
    ("model coordinates", "model space"),
    ("camera coordinates", "camera space"),
    ("eye space", "camera space"),
    ("eye-space", "camera-space"),
    ("camera transform", "view transform"),
    ("Gourad", "Gouraud"),
];

/// The string literals of `source` with the line each starts on, as written (quotes and escapes
/// kept), read with Rust's own lexer (`proc-macro2`): comments, doc comments (`#[doc = …]` to the
/// lexer), char literals and lifetimes are not string literals.
fn literals(source: &str) -> Result<Vec<(usize, String)>, String> {
    use proc_macro2::{Delimiter, TokenStream, TokenTree};
    fn walk(tokens: TokenStream, out: &mut Vec<(usize, String)>) {
        let mut tokens = tokens.into_iter().peekable();
        while let Some(token) = tokens.next() {
            match token {
                // `#[doc = "…"]` and `#![doc = "…"]` are doc comments: not read.
                TokenTree::Punct(p) if p.as_char() == '#' => {
                    if matches!(tokens.peek(), Some(TokenTree::Punct(p)) if p.as_char() == '!') {
                        tokens.next();
                    }
                    if let Some(TokenTree::Group(g)) = tokens.peek()
                        && g.delimiter() == Delimiter::Bracket
                        && g.stream().into_iter().next().is_some_and(|t| t.to_string() == "doc")
                    {
                        tokens.next();
                    }
                }
                TokenTree::Group(g) => walk(g.stream(), out),
                TokenTree::Literal(l) => {
                    let text = l.to_string();
                    if text.ends_with('"') || text.ends_with('#') {
                        out.push((l.span().start().line, text));
                    }
                }
                TokenTree::Ident(_) | TokenTree::Punct(_) => {}
            }
        }
    }
    let tokens: TokenStream = source.parse().map_err(|e| format!("not Rust: {e}"))?;
    let mut out = Vec::new();
    walk(tokens, &mut out);
    Ok(out)
}

/// Where a variant is written on purpose: the file, the variant, and why.
const KEPT: [(&str, &str, &str); 1] = [(
    "crates/grade/src/report.rs",
    "Student ID",
    "the label of the report templates before 2026-11-29: reports filled from them are still read",
)];

/// The removed variants in `source`, as `line: variant → word to use: "literal"`.
fn findings(source: &str) -> Vec<String> {
    findings_but(source, &[])
}

/// [`findings`], without the variants in `kept`.
fn findings_but(source: &str, kept: &[&str]) -> Vec<String> {
    let literals = match literals(source) {
        Ok(l) => l,
        Err(e) => return vec![e],
    };
    let mut found = Vec::new();
    for (line, text) in literals {
        // The literal as written, with its quotes (`"確認"` is the whole literal 確認).
        let quoted = text.trim_start_matches(['r', 'b', '#']).trim_end_matches('#').to_owned();
        let text = quoted.trim_matches('"');
        for (bad, good) in FORBIDDEN.into_iter().filter(|(bad, _)| !kept.contains(bad)) {
            let rest = if good.contains(bad) { quoted.replace(good, "") } else { quoted.clone() };
            if rest.contains(bad) {
                let shown: String = text.chars().take(100).collect();
                found.push(format!("{line}: {bad} → {good}: \"{shown}\""));
            }
        }
    }
    found
}

#[test]
fn one_word_for_each_term() {
    let found = sources::scan(file!(), |name, source| {
        let kept: Vec<&str> =
            KEPT.iter().filter(|(f, ..)| *f == name).map(|(_, variant, _)| *variant).collect();
        findings_but(source, &kept)
    });
    assert!(
        found.is_empty(),
        "write each term one way (docs/conventions.md, \"Terms / 用語\"):\n{}",
        found.join("\n")
    );
}

#[test]
fn the_scan_finds_each_removed_variant_in_literals_only() {
    for bad in [
        "let s = t(\"各画素の色\", \"each pixel's colour\");",
        "let s = t(\"表の版 {v}\", \"table {v}\");",
        "    t(\"確認\", \"Check\").get(lang),",
        "\"確認: cargo run --release -- check a2\\n\",",
        "let s = r#\"the \"camera transform\" here\"#;",
        "let s = \"first line \\\n    Student ID\";",
        "let c = '\"'; let s = \"視野変換行列\";",
    ] {
        assert_eq!(findings(bad).len(), 1, "{bad}");
    }
    for good in [
        "let s = t(\"課題表の版 {v}\", \"table version {v}\");",
        "let s = t(\"ピクセルごとに光源処理\", \"lighting per pixel\");",
        "// 画素 in a comment",
        "/// the camera transform, in a doc comment",
        "let s = t(\"確認してください\", \"check that\"); // 画素",
        "fn f<'a>(x: &'a str) -> char { '画' }",
        "//! 画素 in a crate's doc\n#![doc = \"the camera transform\"]\nfn f() {}",
    ] {
        assert!(findings(good).is_empty(), "{good}: {:?}", findings(good));
    }
}
