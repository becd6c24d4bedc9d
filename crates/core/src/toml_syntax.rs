//! TOML's syntax errors in both languages. The parser (the `toml` crate's) words its messages in
//! English only — `missing assignment between key-value pairs, expected `=`` — and they reached
//! Japanese readers inside a Japanese sentence. Each message it can give is one of a fixed set
//! of descriptions, then the tokens it expected: both are put into Japanese here, and a message
//! not in the set (a newer parser's) is kept as it is.

use std::ops::Range;

use crate::lang::Text;

/// The parser's descriptions and their Japanese.
const DESCRIPTIONS: &[(&str, &str)] = &[
    ("carriage return must be followed by newline", "CR の後には改行（LF）が必要です"),
    ("missing opening quote", "始めの引用符がありません"),
    ("missing comma between array elements", "配列の要素の間にコンマがありません"),
    ("integers with a radix cannot be signed", "0x・0o・0b の整数には符号を付けられません"),
    ("radix must be lowercase", "0x・0o・0b は小文字で書きます"),
    ("missing assignment between key-value pairs", "キーと値の間に = がありません"),
    ("missing escaped value", "\\ の後の文字がありません"),
    ("unexpected leading zero", "数の先頭に 0 は書けません"),
    ("unclosed array table", "[[ ]] が閉じていません"),
    ("missing key for inline table element", "インラインテーブルの要素にキーがありません"),
    ("missing inline table opening", "インラインテーブルの始めの { がありません"),
    ("missing array opening", "配列の始めの [ がありません"),
    ("invalid unquoted key", "引用符なしのキーに使えない文字があります"),
    ("cannot recurse further; max recursion depth met", "入れ子が深すぎます"),
    ("unquoted keys cannot be empty", "引用符なしのキーは空にできません"),
    ("invalid multi-line basic string", "複数行の文字列（\"\"\"）が正しくありません"),
    ("invalid basic string", "文字列（\"…\"）が正しくありません"),
    ("unexpected sign", "ここに符号は書けません"),
    ("unexpected key or value", "ここにキーや値は書けません"),
    ("unexpected content", "ここに余分なものがあります"),
    ("unexpected content between comment and newline", "コメントの中に使えない文字があります"),
    ("unexpected `=` in array", "配列の中に = は書けません"),
    ("unclosed table", "[ ] が閉じていません"),
    ("unclosed inline table", "インラインテーブル { } が閉じていません"),
    ("unclosed array", "配列 [ ] が閉じていません"),
    ("too few unicode value digits", "\\u・\\U の後の 16 進の桁が足りません"),
    ("string values must be quoted", "文字列の値は引用符で囲みます"),
    ("redundant numeric sign", "符号が 2 つあります"),
    ("redundant integer number prefix", "0x・0o・0b が 2 つあります"),
    ("missing value", "値がありません"),
    ("missing value for key", "キーの値がありません"),
    ("missing table open", "テーブルの始めの [ がありません"),
    ("missing comment start", "コメントの始めの # がありません"),
    ("missing comma between key-value pairs", "キーと値の組の間にコンマがありません"),
    ("keys cannot be multi-line literal strings", "キーに複数行の文字列（'''）は使えません"),
    ("keys cannot be multi-line basic strings", "キーに複数行の文字列（\"\"\"）は使えません"),
    ("key with no value", "キーの後に = と値がありません"),
    ("invalid value", "値が正しくありません"),
    ("invalid key-value pair", "キーと値の組が正しくありません"),
    ("invalid inline table element", "インラインテーブルの要素が正しくありません"),
    ("invalid comment character", "コメントに使えない文字があります"),
    ("extra comma in inline table", "インラインテーブルのコンマが余分です"),
    ("extra comma in array", "配列のコンマが余分です"),
    ("extra assignment between key-value pairs", "= が余分です"),
    ("extra `=`", "= が余分です"),
    ("`_` may only go between digits", "_ は数字と数字の間にだけ書けます"),
    ("duplicate key", "同じキーが 2 回書かれています"),
    ("recursion limit", "入れ子が深すぎます"),
    ("integer number overflowed", "整数が大きすぎます"),
    ("floating-point number overflowed", "小数が大きすぎます"),
];

/// What the parser says it expected, and its Japanese.
const EXPECTED: &[(&str, &str)] = &[
    ("basic string", "文字列"),
    ("characters", "文字"),
    ("digits", "数字"),
    ("key", "キー"),
    ("letters", "英字"),
    ("literal string", "文字列"),
    ("multi-line basic string", "複数行の文字列"),
    ("non-double-quote visible characters", "\" 以外の見える文字"),
    ("non-single-quote characters", "' 以外の文字"),
    ("non-single-quote visible characters", "' 以外の見える文字"),
    ("numbers", "数字"),
    ("printable characters", "表示できる文字"),
    ("unicode hexadecimal value", "16 進の文字コード"),
    ("value", "値"),
    ("newline", "改行"),
];

/// The parser's `message` in both languages (the English as the parser wrote it).
#[must_use]
pub fn message(message: &str) -> Text {
    let (description, expected) = match message.split_once(", expected ") {
        Some((d, e)) => (d, Some(e)),
        None => (message, None),
    };
    // An integer past i64 (`table = 99999999999999999999`) comes from the parser's serde side:
    // "invalid type: integer `…` as i128, expected any valid TOML value".
    if let Some(n) = message
        .strip_prefix("invalid type: integer `")
        .and_then(|rest| rest.split_once("` as i128"))
        .map(|(n, _)| n)
    {
        let n = crate::quote::shown(n, crate::lang::Lang::Ja);
        return Text::new(
            format!("整数 {n} が大きすぎます（TOML の整数は ±9223372036854775807 まで）"),
            message,
        );
    }
    let Some(&(_, ja)) = DESCRIPTIONS.iter().find(|(en, _)| *en == description) else {
        return Text::new(message, message);
    };
    let ja = match expected {
        None => ja.to_owned(),
        Some("nothing") => format!("{ja}（ここで終わるはずです）"),
        Some(list) => {
            let words: Vec<&str> = list
                .split(", ")
                .map(|w| EXPECTED.iter().find(|(en, _)| *en == w).map_or(w, |(_, ja)| *ja))
                .collect();
            format!("{ja}（ここに来るはずのもの: {}）", words.join("、"))
        }
    };
    Text::new(ja, message)
}

/// The parser's `message` about `text` at `span`, with its line and column (1-based; the
/// column counts characters), in both languages: `3 行 7 列: …` / `line 3, column 7: …`. When
/// that line has a character a Japanese input method types in place of TOML's (see
/// [`typed_by_an_input_method`]), it is named after the message, with what to type instead.
#[must_use]
pub fn at(text: &str, message: &str, span: Option<Range<usize>>) -> Text {
    let said = self::message(message);
    let Some(span) = span else { return said };
    let said = located(text, span.start, &said);
    match typed_by_an_input_method(text, span.start) {
        Some(hint) => Text::new(
            format!("{}。{}", said.ja, hint.ja),
            format!("{}. {}", said.en, capitalized(&hint.en)),
        ),
        None => said,
    }
}

/// The first character on the line of `offset` (a byte of `text`) that a Japanese input method
/// types in place of TOML's, outside strings and comments — a full-width space (U+3000) around
/// `=`, a typographic quote (“ ” ‘ ’, U+201C, U+201D, U+2018, U+2019) around a string, a
/// full-width digit (`１`, U+FF11) — or a typographic quote inside a string that the line does
/// not close (`"12345678”`): named with its line, column and code point, and what to type
/// instead. `None` when there is none (then the parser's message says it all).
#[must_use]
pub fn typed_by_an_input_method(text: &str, offset: usize) -> Option<Text> {
    let start = offset.min(text.len());
    let start = (0..=start).rev().find(|&i| text.is_char_boundary(i)).unwrap_or(0);
    let line_start = text[..start].rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[start..].find('\n').map_or(text.len(), |i| start + i);
    let line = &text[line_start..line_end];
    let number = text[..line_start].matches('\n').count() + 1;
    // The full-width quote `＂` (U+FF02) is typed for `"` as the typographic ones are.
    let typographic =
        |c: char| matches!(c, '\u{201C}' | '\u{201D}' | '\u{2018}' | '\u{2019}' | '\u{FF02}');
    // The quote that opened the string the scan is in (`"` or `'`), and its column (0-based).
    let mut string: Option<(char, usize)> = None;
    let mut escaped = false;
    let mut found = None;
    for (column, (i, c)) in line.char_indices().enumerate() {
        match string {
            Some(('"', _)) if escaped => escaped = false,
            Some(('"', _)) if c == '\\' => escaped = true,
            Some((quote, _)) if c == quote => string = None,
            Some(_) => {}
            // A comment, or a multi-line string: what follows is not TOML's syntax.
            None if c == '#' || line[i..].starts_with("\"\"\"") || line[i..].starts_with("'''") => {
                break;
            }
            None if c == '"' || c == '\'' => string = Some((c, column)),
            None if c == '\u{3000}'
                || c == '＝'
                || typographic(c)
                || ('０'..='９').contains(&c) =>
            {
                found = Some((column, c));
                break;
            }
            None => {}
        }
    }
    // A string the line does not close: a typographic quote in it (`"12345678”`).
    if found.is_none()
        && let Some((_, opened)) = string
    {
        found = line.chars().enumerate().skip(opened + 1).find(|&(_, c)| typographic(c));
    }
    let (column, c) = found?;
    let (line, column, code) = (number, column + 1, format!("U+{:04X}", u32::from(c)));
    Some(match c {
        '\u{3000}' => Text::new(
            format!(
                "{line} 行 {column} 列の「\u{3000}」は全角スペース（{code}）です。半角スペースにしてください"
            ),
            format!(
                "the character at line {line}, column {column} is a full-width space ({code}): type a half-width space instead"
            ),
        ),
        '＝' => Text::new(
            format!(
                "{line} 行 {column} 列の「＝」（{code}）は全角の等号です。半角の = にしてください"
            ),
            format!(
                "the character at line {line}, column {column}, `＝` ({code}), is a full-width equals sign: type the half-width = instead"
            ),
        ),
        '０'..='９' => {
            let digit = crate::text::ascii_digit(c);
            Text::new(
                format!(
                    "{line} 行 {column} 列の「{c}」（{code}）は全角の数字です。半角の数字 {digit} にしてください"
                ),
                format!(
                    "the character at line {line}, column {column}, `{c}` ({code}), is a full-width digit: type the half-width digit {digit} instead"
                ),
            )
        }
        _ => Text::new(
            format!(
                "{line} 行 {column} 列の「{c}」（{code}）は日本語入力の引用符で、TOML の引用符ではありません。半角の二重引用符 \" で囲んでください"
            ),
            format!(
                "the character at line {line}, column {column}, `{c}` ({code}), is a typographic quote, not TOML's: type straight double quotes \" instead"
            ),
        ),
    })
}

fn capitalized(s: &str) -> String {
    let mut chars = s.chars();
    chars.next().map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}

/// `said` about the place `offset` (a byte) of `text`, with its line and column (1-based; the
/// column counts characters): `3 行 7 列: …` / `line 3, column 7: …`.
#[must_use]
pub fn located(text: &str, offset: usize, said: &Text) -> Text {
    let start = offset.min(text.len());
    let start = (0..=start).rev().find(|&i| text.is_char_boundary(i)).unwrap_or(0);
    let before = &text[..start];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().unwrap_or("").chars().count() + 1;
    Text::new(
        format!("{line} 行 {column} 列: {}", said.ja),
        format!("line {line}, column {column}: {}", said.en),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The parser's own message for `text`.
    fn parsed(text: &str) -> (String, Option<Range<usize>>) {
        let e = text.parse::<toml::Table>().unwrap_err();
        (e.message().to_owned(), e.span())
    }

    #[test]
    fn the_parsers_messages_are_said_in_japanese_with_their_place() {
        let (m, span) = parsed("student = \"1\"\ntable 3\n");
        let t = at("student = \"1\"\ntable 3\n", &m, span);
        assert_eq!(t.ja, "2 行 7 列: キーの後に = と値がありません（ここに来るはずのもの: `=`）");
        assert_eq!(t.en, format!("line 2, column 7: {m}"));
        assert!(m.starts_with("key with no value"), "{m}");
        // Every Japanese text has no English word of the parser's left in it.
        for text in ["a = [1 2]", "a = \"x", "a = 01", "[a\n", "a = 1\na = 2", "a = 1_", "a = +-1"]
        {
            let (m, span) = parsed(text);
            let t = at(text, &m, span);
            assert!(
                !t.ja.chars().any(|c| c.is_ascii_lowercase() && c != 'x'),
                "{text:?}: {m:?} → {:?}",
                t.ja
            );
            assert!(t.en.ends_with(&m), "{t:?}");
        }
    }

    #[test]
    fn an_integer_past_i64_is_said_in_japanese() {
        let text = "table = 99999999999999999999\n";
        let e = text.parse::<toml::Table>().unwrap_err();
        let t = at(text, e.message(), e.span());
        assert!(t.ja.contains("整数 99999999999999999999 が大きすぎます"), "{t:?}");
        assert!(!t.ja.contains("invalid type"), "{t:?}");
        assert!(t.en.contains("invalid type: integer"), "{t:?}");
    }

    /// `at` of each file's parse error names the character at `(line, column)`: `ja` and `en`
    /// found in the two languages, with the place and what to type instead.
    fn assert_named(cases: &[(&str, (usize, usize), &str, &str)], instead: (&str, &str)) {
        for &(text, (line, column), ja, en) in cases {
            let (m, span) = parsed(text);
            let t = at(text, &m, span);
            let (where_ja, where_en) =
                (format!("{line} 行 {column} 列の"), format!("at line {line}, column {column}"));
            assert!(t.ja.contains(&where_ja) && t.ja.contains(ja), "{text:?}: {}", t.ja);
            assert!(t.en.contains(&where_en) && t.en.contains(en), "{text:?}: {}", t.en);
            assert!(t.ja.contains(instead.0), "{text:?}: {}", t.ja);
            assert!(t.en.contains(instead.1), "{text:?}: {}", t.en);
            // The parser's own message is still said, in both languages.
            assert!(t.en.contains(&m), "{text:?}: {}", t.en);
            assert!(t.ja.starts_with(&at_without_hint(text, &m)), "{text:?}: {}", t.ja);
        }
    }

    /// The parser's message at its place, as it was said before the hints.
    fn at_without_hint(text: &str, m: &str) -> String {
        let (_, span) = parsed(text);
        located(text, span.map_or(0, |s| s.start), &message(m)).ja
    }

    /// A full-width space (U+3000) around `=` or after a value: `name　= "山田"`.
    #[test]
    fn a_full_width_space_is_named() {
        let space = ("全角スペース（U+3000）", "a full-width space (U+3000)");
        assert_named(
            &[
                ("name\u{3000}= \"山田\"\n", (1, 5), space.0, space.1),
                ("student = \"12345678\"\ntable\u{3000}=\u{3000}3\n", (2, 6), space.0, space.1),
                ("student = \"1\"\u{3000}\n", (1, 14), space.0, space.1),
            ],
            ("半角スペースにしてください", "type a half-width space instead"),
        );
    }

    /// Typographic quotes around a string (“ ” U+201C U+201D, ‘ ’ U+2018 U+2019), or closing one
    /// opened with `"`.
    #[test]
    fn typographic_quotes_are_named() {
        assert_named(
            &[
                ("student = “12345678”\n", (1, 11), "「“」（U+201C）", "`“` (U+201C)"),
                ("student = ‘12345678’\n", (1, 11), "「‘」（U+2018）", "`‘` (U+2018)"),
                ("student = \"12345678”\n", (1, 20), "「”」（U+201D）", "`”` (U+201D)"),
                ("student = ＂12345678＂\n", (1, 11), "「＂」（U+FF02）", "`＂` (U+FF02)"),
            ],
            ("半角の二重引用符 \" で囲んでください", "type straight double quotes \" instead"),
        );
    }

    /// Full-width digits (`table = １`, U+FF11), with the half-width digit to type.
    #[test]
    fn full_width_digits_are_named() {
        assert_named(
            &[
                ("student = \"1\"\ntable = １\n", (2, 9), "「１」（U+FF11）", "`１` (U+FF11)"),
                ("table = 1２\n", (1, 10), "「２」（U+FF12）", "`２` (U+FF12)"),
            ],
            ("全角の数字です。半角の数字", "is a full-width digit: type the half-width digit"),
        );
        let (m, span) = parsed("table = １\n");
        let t = at("table = １\n", &m, span);
        assert!(t.ja.contains("半角の数字 1 にしてください"), "{}", t.ja);
        assert!(t.en.contains("half-width digit 1 instead"), "{}", t.en);
    }

    /// A full-width equals sign (`student ＝ "…"`, U+FF1D), with the half-width one to type.
    #[test]
    fn a_full_width_equals_sign_is_named() {
        assert_named(
            &[("student ＝ \"12345678\"\n", (1, 9), "「＝」（U+FF1D）", "`＝` (U+FF1D)")],
            (
                "全角の等号です。半角の = にしてください",
                "full-width equals sign: type the half-width = instead",
            ),
        );
    }

    /// No hint where there is no such character, or where it is inside a string or a comment
    /// (a name with a full-width space, a comment with typographic quotes).
    #[test]
    fn no_hint_for_a_correct_file_or_a_character_in_a_string_or_comment() {
        for text in [
            "student = \"12345678\"\ntable = 3\n",
            "# 山田\u{3000}太郎の “student.toml” １\nstudent = \"12345678\" # ‘メモ’\u{3000}\ntable = 3\n",
        ] {
            assert!(text.parse::<toml::Table>().is_ok(), "{text:?}");
            // Said at any place of the file: the message and its place, nothing more.
            for (i, _) in text.char_indices() {
                let said = at(text, "missing value", Some(i..i));
                assert_eq!(said, located(text, i, &message("missing value")), "{text:?} at {i}");
            }
        }
        // An error elsewhere: the full-width space inside a string is not named.
        let text = "student = \"山田\u{3000}太郎\" x\n";
        let (m, span) = parsed(text);
        let t = at(text, &m, span.clone());
        assert!(!t.ja.contains("U+3000") && !t.en.contains("U+3000"), "{t:?}");
        assert_eq!(t, located(text, span.unwrap().start, &message(&m)));
    }

    #[test]
    fn a_message_not_in_the_set_is_kept_and_columns_count_characters() {
        assert_eq!(message("something new"), Text::new("something new", "something new"));
        // 3 characters of kana (9 bytes) before the place: column 4.
        let t = at("あいう=", "missing value", Some(9..10));
        assert_eq!(t.ja, "1 行 4 列: 値がありません");
        // A span inside a character, or past the end, is taken at the character.
        assert!(at("あ", "missing value", Some(1..2)).ja.starts_with("1 行 1 列"));
        assert!(at("a", "missing value", Some(99..100)).ja.starts_with("1 行 2 列"));
        assert_eq!(at("a", "missing value", None).ja, "値がありません");
    }
}
