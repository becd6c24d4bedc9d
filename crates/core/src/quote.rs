//! Text from the user's files, as an error message shows it: short, and with nothing hidden.
//!
//! A message that echoes a word of the input must stay readable whatever the word is: a
//! 2 MB "word" is cut to its start and its length, and a character that cannot be seen (a
//! zero-width space pasted from a web page, a BOM in the middle of a line, a control
//! character) is written as its code point, so the student can find it.
//! エラーメッセージに入力の語を示すときは、長すぎる語を切り詰め、見えない文字を U+XXXX で示します。

use crate::lang::{Lang, Text};

/// At most this many characters of a word are shown.
pub const MAX_SHOWN_CHARS: usize = 64;

/// `word` for a message in `lang`: at most [`MAX_SHOWN_CHARS`] characters, then `…` and the
/// word's whole length in characters; each invisible or control character written as `<U+200B>`.
///
/// ```
/// use cg_core::{lang::Lang, quote::shown};
/// assert_eq!(shown("v1\u{200B}", Lang::En), "v1<U+200B>");
/// let long = "x".repeat(2_000_000);
/// assert_eq!(shown(&long, Lang::En), format!("{}… (2000000 characters)", "x".repeat(64)));
/// assert_eq!(shown(&long, Lang::Ja), format!("{}…（全 2000000 文字）", "x".repeat(64)));
/// ```
#[must_use]
pub fn shown(word: &str, lang: Lang) -> String {
    let total = word.chars().count();
    let mut out = visible(&word.chars().take(MAX_SHOWN_CHARS).collect::<String>());
    if total > MAX_SHOWN_CHARS {
        let count = Text::new(format!("…（全 {total} 文字）"), format!("… ({total} characters)"));
        out.push_str(count.get(lang));
    }
    out
}

/// The bytes of a CSV file the instructor opens in a spreadsheet: its UTF-8 text after a
/// byte-order mark. Without the mark, Excel on Japanese Windows reads a CSV file as Shift_JIS and
/// garbles every Japanese name in it; CSV readers skip the mark (the `csv` crate, Python's
/// `utf-8-sig`, LibreOffice).
///
/// ```
/// assert_eq!(cg_core::quote::spreadsheet_file("a,b\n"), b"\xef\xbb\xbfa,b\n");
/// ```
#[must_use]
pub fn spreadsheet_file(text: &str) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(text.len() + 3);
    bytes.extend_from_slice("\u{feff}".as_bytes());
    bytes.extend_from_slice(text.as_bytes());
    bytes
}

/// A cell of a CSV file the instructor opens in a spreadsheet, from text a student controls (a
/// submission's file name, a Moodle full name): one that begins with `=`, `+`, `-`, `@`, a tab
/// or a carriage return would be read as a formula (`=HYPERLINK(…)`), so it gets a leading `'`,
/// which spreadsheets take as "text" and do not show. Anything else is returned as it is.
///
/// ```
/// use cg_core::quote::spreadsheet_cell;
/// assert_eq!(spreadsheet_cell("=HYPERLINK(\"http://x\")"), "'=HYPERLINK(\"http://x\")");
/// assert_eq!(spreadsheet_cell("+1+2"), "'+1+2");
/// assert_eq!(spreadsheet_cell("Taro Yamada_777"), "Taro Yamada_777");
/// ```
#[must_use]
pub fn spreadsheet_cell(text: &str) -> std::borrow::Cow<'_, str> {
    if text.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        std::borrow::Cow::Owned(format!("'{text}"))
    } else {
        std::borrow::Cow::Borrowed(text)
    }
}

/// `text` with each invisible or control character (but the tab) written as `<U+200B>`.
#[must_use]
pub fn visible(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if invisible(c) {
            out.push_str(&format!("<U+{:04X}>", u32::from(c)));
        } else {
            out.push(c);
        }
    }
    out
}

/// A character that shows as nothing, or moves the text around it: controls (but the tab), the
/// zero-width and bidirectional formatting characters, the BOM, soft hyphen, and the other
/// Unicode format characters the course's text could meet.
fn invisible(c: char) -> bool {
    (c.is_control() && c != '\t')
        || matches!(c,
            '\u{00AD}'                // soft hyphen
            | '\u{034F}'              // combining grapheme joiner
            | '\u{061C}'              // Arabic letter mark
            | '\u{115F}' | '\u{1160}' // Hangul fillers
            | '\u{180E}'              // Mongolian vowel separator
            | '\u{200B}'..='\u{200F}' // zero-width space, joiners, direction marks
            | '\u{202A}'..='\u{202E}' // bidirectional embeddings and overrides
            | '\u{2060}'..='\u{206F}' // word joiner, invisible operators, bidi isolates
            | '\u{3164}'              // Hangul filler
            | '\u{FE00}'..='\u{FE0F}' // variation selectors
            | '\u{FEFF}'              // BOM / zero-width no-break space
            | '\u{FFA0}'              // halfwidth Hangul filler
            | '\u{FFF9}'..='\u{FFFB}' // interlinear annotation
        )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_visible_words_are_unchanged() {
        for w in ["pyramid", "頂点", "1.5e3", "a b", "tab\there", ""] {
            assert_eq!(shown(w, Lang::En), w);
        }
    }

    #[test]
    fn invisible_characters_are_named() {
        assert_eq!(shown("\u{200B}scale", Lang::En), "<U+200B>scale");
        assert_eq!(shown("x\u{FEFF}", Lang::En), "x<U+FEFF>");
        assert_eq!(shown("a\u{202E}b", Lang::En), "a<U+202E>b");
        assert_eq!(shown("nul\0", Lang::En), "nul<U+0000>");
        assert_eq!(shown("cr\r", Lang::En), "cr<U+000D>");
    }

    #[test]
    fn long_words_are_cut_with_their_length() {
        let word = "あ".repeat(100);
        let s = shown(&word, Lang::Ja);
        assert!(s.starts_with(&"あ".repeat(MAX_SHOWN_CHARS)), "{s}");
        assert!(s.ends_with("…（全 100 文字）"), "{s}");
        assert_eq!(shown(&"y".repeat(MAX_SHOWN_CHARS), Lang::En), "y".repeat(MAX_SHOWN_CHARS));
    }
}
