//! Student-facing text exists in Japanese and English.

use cg_core::lang::Lang;
use serde::Serialize;

/// A sentence in Japanese and English.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, Serialize)]
pub struct Text {
    /// 日本語
    pub ja: String,
    /// English
    pub en: String,
}

impl Text {
    /// A text from its two versions.
    #[must_use]
    pub fn new(ja: impl Into<String>, en: impl Into<String>) -> Text {
        Text { ja: ja.into(), en: en.into() }
    }

    /// The version in `lang`.
    #[must_use]
    pub fn get(&self, lang: Lang) -> &str {
        match lang {
            Lang::Ja => &self.ja,
            Lang::En => &self.en,
        }
    }

    /// Whether both versions are empty.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.ja.is_empty() && self.en.is_empty()
    }
}

impl From<&str> for Text {
    /// The same words in both languages: numbers, symbols, names (`V3`, `t = 2.5 s`).
    fn from(s: &str) -> Text {
        Text::new(s, s)
    }
}

impl From<String> for Text {
    /// The same words in both languages: numbers, symbols, names (`V3`, `t = 2.5 s`).
    fn from(s: String) -> Text {
        Text { ja: s.clone(), en: s }
    }
}

impl From<&String> for Text {
    /// The same words in both languages.
    fn from(s: &String) -> Text {
        Text::from(s.as_str())
    }
}

impl std::fmt::Display for Text {
    /// The English version (for logs and test messages; students get [`Text::get`]).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.en)
    }
}

/// `t("日本語", "English")`: a [`Text`] from two string slices.
#[must_use]
pub fn t(ja: &str, en: &str) -> Text {
    Text::new(ja, en)
}
