//! Checks of the kit's messages as text: each language one clean line, Japanese in the Japanese
//! text, no English sentence inside it, no Japanese in the English one. Every error type's
//! text test uses these, so the rules are written once.

/// Hiragana, katakana or a CJK ideograph.
#[must_use]
pub fn kana_or_kanji(c: char) -> bool {
    matches!(c, '\u{3040}'..='\u{30ff}' | '\u{4e00}'..='\u{9fff}')
}

/// Japanese script or Japanese punctuation and full-width forms (`、` `（` `：`).
#[must_use]
pub fn japanese(c: char) -> bool {
    kana_or_kanji(c) || matches!(c, '\u{3000}'..='\u{303f}' | '\u{ff00}'..='\u{ffef}')
}

/// Runs of two or more ASCII words with only spaces between them (`is not finite`): an English
/// sentence fragment. Names and formulas inside a Japanese sentence (`grid の divisions`,
/// `max_depth = 1000`, `(NaN, 0, 0)`) stand alone; single letters (`x y z`) are coordinates;
/// commands in backquotes (`` `bash scripts/setup.sh` ``) are left out.
#[must_use]
pub fn english_fragments(text: &str) -> Vec<String> {
    let prose: String = text.split('`').step_by(2).collect::<Vec<_>>().join(" ");
    let is_word = |w: &&str| w.chars().filter(char::is_ascii_alphabetic).count() >= 2;
    prose
        .split(|c: char| !(c == ' ' || c == '_' || c.is_ascii_alphanumeric()))
        .flat_map(|segment| {
            let words: Vec<&str> = segment.split_whitespace().collect();
            words
                .windows(2)
                .filter(|w| is_word(&w[0]) && is_word(&w[1]))
                .map(|w| w.join(" "))
                .collect::<Vec<String>>()
        })
        .collect()
}

/// What is wrong with a message in Japanese (`ja`) and English (`en`) as one clean line in each
/// language, each problem with the language and the text; empty when nothing. With
/// `no_english_in_ja`, an English fragment ([`english_fragments`]) in `ja` is a problem too.
#[must_use]
pub fn line_problems(ja: &str, en: &str, no_english_in_ja: bool) -> Vec<String> {
    let mut found = Vec::new();
    for (lang, s) in [("ja", ja), ("en", en)] {
        let mut complain = |why: &str| found.push(format!("({lang}) {why}: {s:?}"));
        if s.is_empty() {
            complain("empty");
        }
        if s.trim() != s {
            complain("whitespace at an end");
        }
        if s.contains("  ") {
            complain("a run of spaces");
        }
        if s.contains(['\n', '\r', '\t']) {
            complain("a line break or tab");
        }
        if lang == "ja" && !s.chars().any(kana_or_kanji) {
            complain("no Japanese");
        }
        if lang == "ja" && no_english_in_ja && !english_fragments(s).is_empty() {
            complain("English words in the Japanese text");
        }
        if lang == "en" && s.chars().any(japanese) {
            complain("Japanese in the English text");
        }
    }
    found
}

/// Fails with every problem of `messages` — each `(what, ja, en)`, `what` naming it in the
/// report — as [`line_problems`] finds them, and, with `distinct`, every message that reads the
/// same in both languages.
///
/// # Panics
/// When any message has a problem; the panic lists them all.
#[track_caller]
pub fn assert_clean_lines(
    messages: impl IntoIterator<Item = (String, String, String)>,
    no_english_in_ja: bool,
    distinct: bool,
) {
    let mut found = Vec::new();
    for (what, ja, en) in messages {
        for p in line_problems(&ja, &en, no_english_in_ja) {
            found.push(format!("{what} {p}"));
        }
        if distinct && ja == en {
            found.push(format!("{what}: the same in both languages: {en:?}"));
        }
    }
    assert!(found.is_empty(), "{} problems:\n{}", found.len(), found.join("\n"));
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_rule_catches_its_fault() {
        assert_eq!(line_problems("面がありません", "no faces", true), Vec::<String>::new());
        let bad = [
            ("面が  ありません", "no faces", "a run of spaces"),
            ("面がありません ", "no faces", "whitespace at an end"),
            ("面が\nありません", "no faces", "a line break"),
            ("no faces", "no faces", "no Japanese"),
            ("面がありません: is not finite", "no faces", "English words"),
            ("面がありません", "no 面", "Japanese in the English"),
            ("", "no faces", "empty"),
        ];
        for (ja, en, why) in bad {
            let found = line_problems(ja, en, true);
            assert!(found.iter().any(|p| p.contains(why)), "{ja:?}/{en:?}: {found:?}");
        }
        let same = || vec![("x".to_owned(), "面".to_owned(), "面".to_owned())];
        assert!(std::panic::catch_unwind(|| assert_clean_lines(same(), true, true)).is_err());
        // Names stand alone in a Japanese sentence.
        assert_eq!(english_fragments("grid の divisions は (NaN, 0, 0)"), Vec::<String>::new());
    }
}
