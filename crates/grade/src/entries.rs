//! The class's entries, read, hashed for the resume key and named for their results: the
//! roster's binding, the entries that claim one student number, and names made unique.

use std::collections::BTreeMap;

use crate::{GradeError, Hasher, Options, Text, moodle, result, submission};

/// The most characters of an entry's name a result's file name keeps (a name of 237 bytes
/// made the temporary file's name too long for the file system, and the run failed).
const MAX_NAME_CHARS: usize = 80;

/// A name safe as a file name: letters (kana and kanji too), digits, `-`, `_` and `.` (not
/// leading), others `_`, at most 80 characters.
#[must_use]
pub fn file_name(raw: &str) -> String {
    let s: String = raw
        .chars()
        .map(|c| if c.is_alphanumeric() || matches!(c, '-' | '_' | '.') { c } else { '_' })
        .collect();
    let s: String = s.trim_start_matches('.').chars().take(MAX_NAME_CHARS).collect();
    if s.is_empty() { "_".to_owned() } else { s }
}

/// A submission without `student.toml`, said for both ways of handing in (the `exercises/`
/// folder, or the files one by one), with how to make it (it said `exercises/student.toml is
/// missing`, a path the loose files do not have, and no fix).
#[must_use]
pub(crate) fn no_student_file() -> Text {
    Text::new(
        "student.toml（学生番号の記録）が提出物にありません。exercises/ フォルダごと提出するか、a1.rs などと一緒に exercises/student.toml も提出してください。まだ作っていなければ: cargo run --release -- assignment --student 12345678 --save（12345678 を自分の学生番号に）",
        "student.toml (the record of your student number) is not in the submission: hand in the whole exercises/ folder, or exercises/student.toml with a1.rs and the others. To make it first: cargo run --release -- assignment --student 12345678 --save (with your own number)",
    )
}

/// One submission waiting to be graded.
pub(crate) struct Pending {
    pub(crate) entry: String,
    pub(crate) name: String,
    /// The other entries that claim the same student number.
    pub(crate) same_number: Vec<String>,
    /// What the roster says of the entry (with `--roster`).
    pub(crate) roster: Option<result::RosterMark>,
    pub(crate) hash: String,
    pub(crate) files: Result<(submission::Files, cg_assign::StudentFile), Text>,
    /// The report inside the submission ([`crate::inside`]), and why one found was not read.
    pub(crate) report: (Option<crate::inside::Found>, Vec<Text>),
}

/// The entries of the submissions folder (or of a Moodle download: [`moodle::input`]), read
/// and hashed, with their result names.
pub(crate) fn collect(
    options: &Options,
    kit_hash: &str,
    folder: Option<&crate::inside::Folder>,
) -> Result<Vec<Pending>, GradeError> {
    let entries = moodle::input::entries(&options.submissions).map_err(GradeError::Io)?;
    // An empty folder is a wrong path, not a class with no work: said, not an empty table and
    // exit 0.
    if entries.is_empty() {
        let shown = options.submissions.display();
        return Err(GradeError::Io(Text::new(
            format!(
                "{shown} に提出物がありません（空のフォルダです）。Moodle の「すべての提出をダウンロード」の zip か、それを展開したフォルダ、または提出物（フォルダか .zip）を入れたフォルダを指定してください"
            ),
            format!(
                "{shown} holds no submission (the folder is empty): give Moodle's \"Download all submissions\" zip or the folder it unpacks to, or a folder of submissions (folders or .zip files)"
            ),
        )));
    }
    collect_from(options, kit_hash, entries, folder)
}

/// [`collect`] of the given entries; each one's report from `folder` (`--reports`) when it has
/// the student's, else from inside the submission.
pub(crate) fn collect_from(
    options: &Options,
    kit_hash: &str,
    entries: Vec<moodle::input::Entry>,
    folder: Option<&crate::inside::Folder>,
) -> Result<Vec<Pending>, GradeError> {
    let mut used: BTreeMap<String, Vec<String>> = BTreeMap::new();
    let mut pending = Vec::new();
    for source in entries {
        let entry = source.name.clone();
        let files = source.read().and_then(|files| {
            let toml = files.student_toml.clone().ok_or_else(no_student_file)?;
            let student = cg_assign::parse_student_file(&toml, "exercises/student.toml")
                .map_err(|e| e.text())?;
            Ok((files, student))
        });
        // The roster binds the entry to its student: the number graded (and its variant) is
        // the roster's; a different number in student.toml is kept to be flagged.
        let mut files = files;
        let mark = options.roster.as_ref().map(|r| match r.find(&entry) {
            None => result::RosterMark { listed: false, name: None, claimed: None, student: None },
            Some(row) => {
                let mut claimed = None;
                if let Ok((_, student)) = &mut files
                    && student.student != row.student
                {
                    claimed = Some(student.student.to_string());
                    student.student = row.student.clone();
                }
                result::RosterMark {
                    listed: true,
                    name: Some(row.name.clone()),
                    claimed,
                    student: Some(row.student.to_string()),
                }
            }
        });
        // The report of a submission that is graded (its numbers are checked against its
        // functions): the student's in `--reports`, else the one inside the submission.
        let report = match &files {
            Err(_) => (None, Vec::new()),
            Ok((_, student)) => {
                match folder.and_then(|f| f.by_student.get(student.student.as_str())) {
                    Some((_, Ok(found))) => (Some(found.clone()), Vec::new()),
                    Some((_, Err(why))) => (None, vec![why.clone()]),
                    None => crate::inside::report(&source, crate::report::MAX_BYTES),
                }
            }
        };
        let mut h = Hasher::default();
        h.add(kit_hash.as_bytes());
        // The entry's name is in the result (a kept result named the upload it was made from,
        // not this one).
        h.add(entry.as_bytes());
        h.add(options.config_text.as_bytes());
        h.add(&options.limits.wall.as_millis().to_le_bytes());
        h.add(&options.limits.memory_bytes.to_le_bytes());
        // The results' words are in the run's language: another language grades again (a
        // result kept from an English run was handed out under --lang ja).
        h.add(options.lang.to_string().as_bytes());
        if let Some(m) = &mark {
            h.add(format!("{m:?}").as_bytes());
        }
        let base = match &files {
            Ok((f, student)) => {
                for (m, bytes) in &f.modules {
                    h.add(m.as_bytes());
                    h.add(bytes);
                }
                h.add(f.student_toml.as_deref().unwrap_or_default());
                // The report changed is checked again (a result kept had the old one's numbers).
                if let Some(found) = &report.0 {
                    h.add(found.path.as_bytes());
                    h.add(found.text.as_bytes());
                }
                for note in &report.1 {
                    h.add(note.en.as_bytes());
                }
                student.student.to_string()
            }
            Err(why) => {
                h.add(b"refused");
                h.add(why.en.as_bytes());
                // On the roster, a refused entry's result is its student's (an earlier graded
                // `<student>.json` stood beside the refusal, and was what the guide says to read).
                match mark.as_ref().and_then(|m| m.student.clone()) {
                    Some(student) => student,
                    None => format!("_{}", file_name(&entry)),
                }
            }
        };
        used.entry(base.clone()).or_default().push(entry.clone());
        pending.push(Pending {
            entry,
            name: base,
            same_number: Vec::new(),
            roster: mark,
            hash: h.hex(),
            files,
            report,
        });
    }
    // Entries that claim one student number: none takes the student's file; each is named
    // after its entry too and flagged, whichever sorts first (an impostor could sort first).
    for p in &mut pending {
        let claims = &used[&p.name];
        if claims.len() > 1 {
            p.same_number = claims.iter().filter(|e| **e != p.entry).cloned().collect();
            p.name = format!("{}~{}", p.name, file_name(&p.entry));
        }
    }
    // Two entries whose names are alike once made file names (`山田.zip` and `佐藤.zip` outside
    // the letters kept, names cut at the same length, a number claimed with a name made alike on
    // purpose) would write one result over the other: each such name gets its entry's hash.
    let mut names: BTreeMap<String, usize> = BTreeMap::new();
    for p in &pending {
        *names.entry(p.name.to_lowercase()).or_default() += 1;
    }
    for p in &mut pending {
        if names[&p.name.to_lowercase()] > 1 {
            let mut h = Hasher::default();
            h.add(p.entry.as_bytes());
            p.name = format!("{}~{}", p.name, &h.hex()[..8]);
        }
    }
    Ok(pending)
}
