//! The language of student-facing text: every message the kit shows a student exists in Japanese
//! and English. [`Text`] holds a message in both; [`Lang`] says which one a reader gets
//! ([`Text::get`]).

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

/// Japanese or English.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Lang {
    /// 日本語
    Ja,
    /// English
    #[default]
    En,
}

impl Lang {
    /// The environment variables that choose the language, first one set wins.
    pub const VARIABLES: [&'static str; 4] = ["CG_LANG", "LC_ALL", "LC_MESSAGES", "LANG"];

    /// The language from the environment: the first of [`Lang::VARIABLES`] (`CG_LANG`, then
    /// `LC_ALL`, `LC_MESSAGES`, `LANG`) that is set and not empty; when none is, as on Windows,
    /// whose terminals set none of them, the user's language as the system keeps it (the
    /// Windows display language, the macOS preferred language, the `LANGUAGE` list on Linux).
    /// Japanese when it starts with `ja` (`ja_JP.UTF-8`, `ja-JP`), English otherwise
    /// ([`Lang::choose`]).
    #[must_use]
    pub fn from_env() -> Lang {
        let values = Lang::VARIABLES.map(|k| std::env::var(k).ok());
        Lang::choose(&values, sys_locale::get_locale)
    }

    /// [`Lang::from_env`] without the environment: `values`, the variables' values in order
    /// (`None` for one not set); `system`, the system's locale (`ja-JP`), asked only when no
    /// value is set and not empty. A value set to anything that does not start with `ja`
    /// (`C`, `C.UTF-8`, `en_US.UTF-8`) chooses English, as it always did.
    #[must_use]
    pub fn choose(values: &[Option<String>], system: impl FnOnce() -> Option<String>) -> Lang {
        let japanese = |v: &str| v.trim().to_ascii_lowercase().starts_with("ja");
        match values.iter().flatten().find(|v| !v.is_empty()) {
            Some(v) => {
                if japanese(v) {
                    Lang::Ja
                } else {
                    Lang::En
                }
            }
            None => system().filter(|l| japanese(l)).map_or(Lang::En, |_| Lang::Ja),
        }
    }
}

impl fmt::Display for Lang {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Lang::Ja => "ja",
            Lang::En => "en",
        })
    }
}

/// The error of parsing a [`Lang`] from text.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown language {0:?}: use \"ja\" or \"en\" / 言語は \"ja\" か \"en\" で指定してください"
)]
pub struct UnknownLang(pub String);

impl FromStr for Lang {
    type Err = UnknownLang;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s.to_ascii_lowercase().as_str() {
            "ja" | "jp" | "japanese" | "日本語" => Ok(Lang::Ja),
            "en" | "english" => Ok(Lang::En),
            _ => Err(UnknownLang(s.to_owned())),
        }
    }
}

/// A sentence in Japanese and English.
#[derive(Clone, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
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

    /// The operating system's reason for a failed file operation: in English its own words
    /// (`No such file or directory (os error 2)`), in Japanese what happened, for the kinds a
    /// student meets (no such file, no permission, a folder, a full disk, …); the system's words
    /// follow only where the kind is none of those.
    #[must_use]
    pub fn io(e: &std::io::Error) -> Text {
        use std::io::ErrorKind as K;
        let ja = match e.kind() {
            K::NotFound => "ファイルまたはフォルダがありません",
            K::PermissionDenied => "権限がありません（読み書きが許可されていません）",
            K::IsADirectory => "フォルダです（ファイルを指定してください）",
            K::NotADirectory => "パスの途中にフォルダではないものがあります",
            K::AlreadyExists => "同じ名前のものがすでにあります",
            K::StorageFull | K::QuotaExceeded => "ディスクの空きがありません",
            K::ReadOnlyFilesystem => "読み取り専用の場所です",
            K::InvalidFilename => {
                "ファイル名が正しくありません（長すぎるか、使えない文字があります）"
            }
            K::FileTooLarge => "ファイルが大きすぎます",
            K::UnexpectedEof => "ファイルが途中で終わっています",
            K::InvalidData => "中身を読み取れません",
            K::ResourceBusy | K::ExecutableFileBusy => "ほかのプログラムが使用中です",
            K::DirectoryNotEmpty => "フォルダが空ではありません",
            K::CrossesDevices => "別のドライブへは移動できません",
            _ => return Text::new(format!("OS のエラー: {e}"), e.to_string()),
        };
        Text::new(ja, e.to_string())
    }

    /// [`Text::io`] after the path it happened to: `out/a.png: 権限がありません…` /
    /// `out/a.png: Permission denied (os error 13)`.
    #[must_use]
    pub fn io_at(path: &std::path::Path, e: &std::io::Error) -> Text {
        let why = Text::io(e);
        let shown = path.display();
        Text::new(format!("{shown}: {}", why.ja), format!("{shown}: {}", why.en))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_variables_come_first_and_the_system_only_when_none_is_set() {
        let set = |v: [Option<&str>; 4]| v.map(|v| v.map(str::to_owned));
        let asked = |locale: &'static str| move || Some(locale.to_owned());
        let never =
            || -> Option<String> { panic!("the system is asked only when no variable is set") };
        // Windows' PowerShell and cmd set none: the system's locale decides.
        assert_eq!(Lang::choose(&set([None; 4]), asked("ja-JP")), Lang::Ja);
        assert_eq!(Lang::choose(&set([None; 4]), asked("en-US")), Lang::En);
        assert_eq!(Lang::choose(&set([None; 4]), || None), Lang::En);
        // Empty counts as not set.
        assert_eq!(Lang::choose(&set([Some(""), None, None, Some("")]), asked("ja")), Lang::Ja);
        // The first variable set wins, in order, over the system.
        assert_eq!(
            Lang::choose(&set([Some("ja"), None, None, Some("en_US.UTF-8")]), never),
            Lang::Ja
        );
        assert_eq!(
            Lang::choose(&set([Some("en"), None, None, Some("ja_JP.UTF-8")]), never),
            Lang::En
        );
        assert_eq!(Lang::choose(&set([None, None, None, Some("ja_JP.UTF-8")]), never), Lang::Ja);
        assert_eq!(
            Lang::choose(&set([None, Some("C"), None, Some("ja_JP.UTF-8")]), never),
            Lang::En
        );
        // `LANG=C` (or C.UTF-8, POSIX) is a choice, as before: English, whatever the system says.
        for c in ["C", "C.UTF-8", "POSIX"] {
            assert_eq!(Lang::choose(&set([None, None, None, Some(c)]), never), Lang::En, "{c}");
        }
    }

    #[test]
    fn parses_both_languages_and_rejects_others() {
        assert_eq!("ja".parse::<Lang>(), Ok(Lang::Ja));
        assert_eq!("EN".parse::<Lang>(), Ok(Lang::En));
        assert!("fr".parse::<Lang>().is_err());
        assert_eq!(t("面", "face").get(Lang::Ja), "面");
        assert_eq!(t("面", "face").get(Lang::En), "face");
    }
}
