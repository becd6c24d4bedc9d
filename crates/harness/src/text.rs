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

/// `t("日本語", "English")`: a [`Text`] from two string slices.
#[must_use]
pub fn t(ja: &str, en: &str) -> Text {
    Text::new(ja, en)
}
