//! Moodle's assignment activity on both sides of `cg grade`.
//!
//! In ([`input`]): the file that Moodle's "Download all submissions" (すべての提出をダウンロードする)
//! gives, as it comes — the zip, or the folder it unpacks to. Each participant's files sit in a
//! folder `<full name>_<participant ID>_assignsubmission_file` (Moodle 4.1 and later) or
//! `…_assignsubmission_file_` (3.1 to 4.0), or, when the download was not "in folders", are
//! flat files `<full name>_<participant ID>_assignsubmission_file_<file>`. The upload itself is
//! a zip or loose files. Moodle replaces `_` in a name by a space, so the first `_` ends the
//! name; with blind marking the name is "Participant" (参加者). The participant ID is not the
//! student number: the roster (`--roster`, its `entry` column) or the submission's
//! `exercises/student.toml` binds the two, and a disagreement between them is flagged.
//!
//! Out ([`output`]): the assignment's offline grading worksheet (`moodle/grades.csv`, the
//! columns and names of "Download grading worksheet", in the course's Moodle language) and the
//! feedback files as "Upload multiple feedback files in a zip" takes them
//! (`moodle/feedback.zip`: one folder per participant, named as in the download).
//!
//! The formats follow Moodle's own code (`mod/assign/locallib.php`'s download,
//! `mod/assign/gradingtable.php`'s worksheet, `mod/assign/feedback/offline/importgradeslib.php`
//! and `mod/assign/feedback/file/importziplib.php`, which split a folder name on its first
//! four `_`) and its English and Japanese language packs.

pub mod input;
pub mod output;
mod upload;

#[cfg(test)]
mod download_tests;
#[cfg(test)]
pub(crate) mod fake;
#[cfg(test)]
mod output_tests;

/// The submission plugins' folder word: `<name>_<ID>_assignsubmission_<plugin>`.
pub const SUBMISSION_PLUGINS: &str = "assignsubmission";

/// The plugin of uploaded files: the folder every feedback file goes into.
pub const FILE_PLUGIN: &str = "file";

/// The name Moodle gives a participant under blind marking, in its English and Japanese
/// language packs (`get_string('participant', 'assign')`).
pub const BLIND_NAMES: [&str; 2] = ["Participant", "参加者"];

/// The first path component of an item of Moodle's download, taken apart.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Name {
    /// The participant's full name as Moodle wrote it (a blind-marking name included).
    pub full_name: String,
    /// The participant ID (Moodle's unique ID of the user in this assignment).
    pub participant: String,
    /// The submission plugin: `file`, `onlinetext`, …
    pub plugin: String,
    /// What follows the plugin: `None` for a folder of Moodle 4.1 and later, `Some("")` for a
    /// folder of 3.1 to 4.0 (the trailing `_`), `Some(file)` for the flat form.
    pub rest: Option<String>,
}

impl Name {
    /// Takes a name apart: `<name>_<digits>_assignsubmission_<plugin>[_<rest>]`, or `None`.
    #[must_use]
    pub fn parse(component: &str) -> Option<Name> {
        let marker = format!("_{SUBMISSION_PLUGINS}_");
        let at = component.find(&marker)?;
        let before = &component[..at];
        let cut = before.rfind('_')?;
        let (full_name, participant) = (&before[..cut], &before[cut + 1..]);
        if participant.is_empty() || !participant.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        let after = &component[at + marker.len()..];
        let (plugin, rest) = match after.split_once('_') {
            Some((plugin, rest)) => (plugin, Some(rest.to_owned())),
            None => (after, None),
        };
        if plugin.is_empty() || !plugin.bytes().all(|b| b.is_ascii_alphanumeric()) {
            return None;
        }
        Some(Name {
            full_name: full_name.to_owned(),
            participant: participant.to_owned(),
            plugin: plugin.to_owned(),
            rest,
        })
    }

    /// Whether the name is blind marking's ("Participant", "参加者", perhaps with the ID).
    #[must_use]
    pub fn is_blind(&self) -> bool {
        BLIND_NAMES.iter().any(|word| {
            self.full_name.strip_prefix(word).is_some_and(|tail| {
                let tail = tail.trim();
                tail.is_empty() || tail.bytes().all(|b| b.is_ascii_digit())
            })
        })
    }

    /// Whether this is a folder (Moodle 4.1 and later, or 3.1 to 4.0), not a flat file.
    #[must_use]
    pub fn is_folder(&self) -> bool {
        self.rest.as_deref().is_none_or(str::is_empty)
    }

    /// The participant's folder as Moodle's feedback upload reads it: the download's own name
    /// for a folder; for the flat form, the 3.1–4.0 folder `<name>_<ID>_assignsubmission_<plugin>_`
    /// (every version reads it). A `_` in the name (never in Moodle's own) becomes a space, as
    /// Moodle's importer splits on the first `_`. So do `\`, `:` and control characters (never
    /// in Moodle's own names): in a crafted folder's name, `a\..\..\x` would be a path to an
    /// extractor on Windows, outside the feedback zip's folder.
    #[must_use]
    pub fn folder(&self) -> String {
        let tail = if self.rest.is_none() { "" } else { "_" };
        let name: String = self
            .full_name
            .chars()
            .map(|c| if matches!(c, '_' | '\\' | ':') || c.is_control() { ' ' } else { c })
            .collect();
        format!("{}_{}_{SUBMISSION_PLUGINS}_{}{tail}", name, self.participant, self.plugin)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_form_of_moodle_name_is_taken_apart() {
        let n = Name::parse("山田 太郎_1234567_assignsubmission_file").unwrap();
        assert_eq!(
            (n.full_name.as_str(), n.participant.as_str(), n.plugin.as_str(), n.rest.clone()),
            ("山田 太郎", "1234567", "file", None)
        );
        assert!(n.is_folder() && !n.is_blind());
        assert_eq!(n.folder(), "山田 太郎_1234567_assignsubmission_file");
        let old = Name::parse("Jane Roe_42_assignsubmission_file_").unwrap();
        assert_eq!(old.rest.as_deref(), Some(""));
        assert!(old.is_folder());
        assert_eq!(old.folder(), "Jane Roe_42_assignsubmission_file_");
        let flat = Name::parse("Jane Roe_42_assignsubmission_file_handin_v2.zip").unwrap();
        assert_eq!(flat.rest.as_deref(), Some("handin_v2.zip"));
        assert!(!flat.is_folder());
        assert_eq!(flat.folder(), "Jane Roe_42_assignsubmission_file_");
        for blind in [
            "Participant_1234567_assignsubmission_file",
            "Participant 1234567_1234567_assignsubmission_file",
            "参加者_1234567_assignsubmission_file_",
        ] {
            assert!(Name::parse(blind).unwrap().is_blind(), "{blind}");
        }
        assert!(!Name::parse("Participanta_1_assignsubmission_file").unwrap().is_blind());
        let online = Name::parse("A B_7_assignsubmission_onlinetext_onlinetext.html").unwrap();
        assert_eq!(online.plugin, "onlinetext");
        // A name with `_` (never Moodle's own): the ID is the last number before the plugin.
        let odd = Name::parse("a_b_9_assignsubmission_file").unwrap();
        assert_eq!((odd.full_name.as_str(), odd.participant.as_str()), ("a_b", "9"));
        assert_eq!(odd.folder(), "a b_9_assignsubmission_file");
        // A crafted folder's name that would be a path on Windows stays one folder.
        let crafted = Name::parse("a\\..\\..\\x:y_9_assignsubmission_file").unwrap();
        assert_eq!(crafted.folder(), "a .. .. x y_9_assignsubmission_file");
        for not in [
            "20260001-taro",
            "x_assignsubmission_file",
            "a_b_assignsubmission_file",
            "a_1_assignsubmission_",
            "a_1_assignsubmission_fi le",
        ] {
            assert_eq!(Name::parse(not), None, "{not}");
        }
    }
}
