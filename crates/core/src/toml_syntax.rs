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
/// column counts characters), in both languages: `3 行 7 列: …` / `line 3, column 7: …`.
#[must_use]
pub fn at(text: &str, message: &str, span: Option<Range<usize>>) -> Text {
    let said = self::message(message);
    match span {
        Some(span) => located(text, span.start, &said),
        None => said,
    }
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
