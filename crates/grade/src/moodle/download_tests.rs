//! Moodle in: the fake class's download ([`super::fake`]) read as a folder and as a zip, names
//! in every encoding a zip may carry, and the roster binding participants to students.

use std::path::Path;

use cg_core::lang::{Lang, Text};
use cg_sandbox::Isolation;

use super::fake;
use super::input::{Entry, entries};
use crate::{Config, Options, result, roster};

/// What an entry reads as: its student number and a1's text, or why it is refused.
type Outcome = Result<(String, String), String>;

/// Each entry's name and [`Outcome`].
fn read_all(list: &[Entry]) -> Vec<(String, Outcome)> {
    list.iter()
        .map(|e| {
            let got = e.read().map_err(|t| t.en).map(|f| {
                let toml = String::from_utf8(f.student_toml.unwrap_or_default()).unwrap();
                let number = toml.split('"').nth(1).unwrap_or("").to_owned();
                let a1 = String::from_utf8(f.modules.get("a1").cloned().unwrap_or_default());
                (number, a1.unwrap().trim().to_owned())
            });
            (e.name.clone(), got)
        })
        .collect()
}

fn expect_class(list: &[Entry]) {
    let got = read_all(list);
    let names: Vec<&str> = got.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "Jane Roe_1002_assignsubmission_file_",
            "John Smith_1003_assignsubmission_file_",
            "Mallory_1007_assignsubmission_file",
            "Participant 1005_1005_assignsubmission_file_",
            "Participant_1004_assignsubmission_file",
            "Twice Over_1008_assignsubmission_file",
            "山田 太郎_1001_assignsubmission_file",
            "鈴木 花子_1006_assignsubmission_file",
        ]
    );
    for (name, result) in &got {
        let id = super::Name::parse(name).unwrap().participant;
        match id.as_str() {
            "1007" => {
                let why = result.as_ref().unwrap_err();
                assert!(why.contains("../../x.rs") && why.contains("unsafe path"), "{why}");
            }
            "1008" => {
                let why = result.as_ref().unwrap_err();
                assert!(why.contains("a1.rs is there more than once"), "{why}");
                assert!(why.contains("old/a1.rs"), "{why}");
            }
            _ => {
                let n: u32 = id.parse().unwrap();
                let number = if id == "1006" {
                    "20260099".to_owned()
                } else {
                    format!("2026{:04}", n - 1000)
                };
                let (n, a1) = result.as_ref().unwrap_or_else(|e| panic!("{name}: {e}"));
                assert_eq!(n, &number, "{name}");
                assert_eq!(a1, &format!("// a1 of {number}"), "{name}");
            }
        }
    }
    // The participant of each entry: blind marking told apart.
    let blind: Vec<bool> = list.iter().map(|e| e.participant().unwrap().is_blind()).collect();
    assert_eq!(blind, [false, false, false, true, true, false, false, false]);
}

#[test]
fn a_moodle_download_is_read_as_a_folder_and_as_a_zip() {
    let dir = fake::scratch("download");
    let items = fake::class();
    fake::unpack(&items, &dir.join("unpacked"));
    expect_class(&entries(&dir.join("unpacked")).unwrap());
    // Unpacked into a folder of its own.
    fake::unpack(&items, &dir.join("outer/Course-Assignment-42"));
    expect_class(&entries(&dir.join("outer")).unwrap());
    // The zip as Moodle gives it (UTF-8 names, flagged).
    std::fs::write(dir.join("download.zip"), fake::zip_of(&items)).unwrap();
    expect_class(&entries(&dir.join("download.zip")).unwrap());
    // The instructor's own path given through a link (to the folder, to the zip): followed.
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(dir.join("unpacked"), dir.join("folder-link")).unwrap();
        expect_class(&entries(&dir.join("folder-link")).unwrap());
        std::os::unix::fs::symlink(dir.join("download.zip"), dir.join("zip-link.zip")).unwrap();
        expect_class(&entries(&dir.join("zip-link.zip")).unwrap());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn zip_names_are_read_as_utf8_with_or_without_the_flag_and_as_shift_jis() {
    let dir = fake::scratch("names");
    let sjis_suzuki = vec![0x97, 0xe9, 0x96, 0xd8, 0x20, 0x89, 0xd4, 0x8e, 0x71];
    // ソ is 83 5C in Shift_JIS: the 5C is no path separator.
    let sjis_sora = vec![0x83, 0x5c, 0x83, 0x89, 0x20, 0x91, 0xbe, 0x98, 0x59];
    let entry = |name: Vec<u8>, tail: &str, student: &str| {
        let mut n = name;
        n.extend(tail.as_bytes());
        (n, fake::toml(student))
    };
    for flag in [false, true] {
        let zip = fake::raw_zip(
            &[entry(
                "山田 太郎".as_bytes().to_vec(),
                "_1001_assignsubmission_file/exercises/student.toml",
                "20260001",
            )],
            flag,
        );
        std::fs::write(dir.join("utf8.zip"), zip).unwrap();
        let list = entries(&dir.join("utf8.zip")).unwrap();
        assert_eq!(list[0].name, "山田 太郎_1001_assignsubmission_file", "flag {flag}");
        assert!(list[0].read().unwrap().student_toml.is_some());
    }
    let zip = fake::raw_zip(
        &[
            entry(sjis_suzuki, "_1006_assignsubmission_file/exercises/student.toml", "20260006"),
            entry(sjis_sora, "_1010_assignsubmission_file/student.toml", "20260010"),
        ],
        false,
    );
    std::fs::write(dir.join("sjis.zip"), zip).unwrap();
    let list = entries(&dir.join("sjis.zip")).unwrap();
    let names: Vec<&str> = list.iter().map(|e| e.name.as_str()).collect();
    assert_eq!(
        names,
        ["ソラ 太郎_1010_assignsubmission_file", "鈴木 花子_1006_assignsubmission_file"]
    );
    for e in &list {
        assert!(e.read().unwrap().student_toml.is_some(), "{}", e.name);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn what_is_not_a_participant_is_listed_and_a_hostile_download_refused() {
    let dir = fake::scratch("strays");
    let mut items = fake::six("Ann_1_assignsubmission_file/exercises/", "src/", "20260001");
    items.push(("notes.txt".into(), b"hi".to_vec()));
    items.push(("__MACOSX/._x".into(), b"".to_vec()));
    std::fs::write(dir.join("d.zip"), fake::zip_of(&items)).unwrap();
    let list = entries(&dir.join("d.zip")).unwrap();
    let got = read_all(&list);
    assert_eq!(got[0].0, "Ann_1_assignsubmission_file");
    assert!(got[0].1.is_ok());
    assert_eq!(got[1].0, "notes.txt");
    assert!(got[1].1.as_ref().unwrap_err().contains("not a participant's folder"));
    assert_eq!(got.len(), 2);
    // A zip slip in the download itself: nothing is graded.
    items.push(("../evil.rs".into(), b"x".to_vec()));
    std::fs::write(dir.join("slip.zip"), fake::zip_of(&items)).unwrap();
    let why = entries(&dir.join("slip.zip")).unwrap_err();
    assert!(why.en.contains("../evil.rs") && why.en.contains("unsafe path"), "{}", why.en);
    assert!(why.ja.contains("Moodle"), "{}", why.ja);
    // A zip that is no Moodle download.
    std::fs::write(dir.join("plain.zip"), fake::zip_of(&fake::six("exercises/", "src/", "1")))
        .unwrap();
    let why = entries(&dir.join("plain.zip")).unwrap_err();
    assert!(why.en.contains("no participant's folder"), "{}", why.en);
    // A link in a participant's folder is refused.
    #[cfg(unix)]
    {
        let sub = dir.join("folder/Bob_2_assignsubmission_file");
        std::fs::create_dir_all(&sub).unwrap();
        std::os::unix::fs::symlink("/etc", sub.join("exercises")).unwrap();
        let list = entries(&dir.join("folder")).unwrap();
        let why = list[0].read().unwrap_err();
        assert!(why.en.contains("exercises is a symbolic link"), "{}", why.en);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// An upload of thousands of the exercises' files (a 4 MB zip of megabyte-sized `a1.rs`, which
/// took 3 GB before its duplicates were seen) is refused at the limit, with the reason.
#[test]
fn an_upload_of_thousands_of_exercise_files_is_refused_at_the_limit() {
    let dir = fake::scratch("many");
    let mut items = fake::six("Ann_1_assignsubmission_file/exercises/", "src/", "20260001");
    for k in 0..(super::input::MAX_CANDIDATES + 10) {
        items.push((format!("Ann_1_assignsubmission_file/copy{k}/a1.rs"), b"fn f() {}".to_vec()));
    }
    std::fs::write(dir.join("d.zip"), fake::zip_of(&items)).unwrap();
    let list = entries(&dir.join("d.zip")).unwrap();
    let why = list[0].read().unwrap_err();
    assert!(why.en.contains("too many of the exercises' files"), "{}", why.en);
    assert!(why.ja.contains("多すぎます"), "{}", why.ja);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The refusal of an upload with its files many times over names the first few, each shortened
/// (it goes to the feedback, Moodle's comment and the instructor's terminal), and counts the rest.
#[test]
fn a_refusal_names_a_few_shortened_names() {
    let dir = fake::scratch("dupes");
    let long = "x".repeat(300);
    let items: Vec<(String, Vec<u8>)> = (0..7)
        .map(|k| {
            (format!("Ann_1_assignsubmission_file/{long}{k}\u{1b}/a1.rs"), b"fn f() {}".to_vec())
        })
        .collect();
    std::fs::write(dir.join("d.zip"), fake::zip_of(&items)).unwrap();
    let list = entries(&dir.join("d.zip")).unwrap();
    let why = list[0].read().unwrap_err();
    assert!(why.en.contains("is there more than once") && why.en.contains("… (+2)"), "{}", why.en);
    assert!(why.en.len() < 1000 && !why.en.contains('\u{1b}'), "{}", why.en);
    let _ = std::fs::remove_dir_all(&dir);
}

fn options(root: &Path, submissions: &Path, roster: Option<roster::Roster>) -> Options {
    crate::test_options(root, submissions, roster)
}

#[test]
fn the_roster_binds_participants_and_a_mismatch_is_flagged() {
    let root = fake::scratch("roster");
    std::fs::write(root.join("download.zip"), fake::zip_of(&fake::class())).unwrap();
    let roster = roster::Roster::parse(fake::ROSTER).unwrap();
    let opts = options(&root, &root.join("download.zip"), Some(roster));
    let pending = crate::collect(&opts, "kit", None).unwrap();
    let got: Vec<(&str, &str)> =
        pending.iter().map(|p| (p.entry.as_str(), p.name.as_str())).collect();
    assert_eq!(
        got,
        [
            ("Jane Roe_1002_assignsubmission_file_", "20260002"),
            ("John Smith_1003_assignsubmission_file_", "20260003"),
            // Refused, and still the roster's student's result.
            ("Mallory_1007_assignsubmission_file", "20260007"),
            ("Participant 1005_1005_assignsubmission_file_", "20260005"),
            ("Participant_1004_assignsubmission_file", "20260004"),
            ("Twice Over_1008_assignsubmission_file", "20260008"),
            ("山田 太郎_1001_assignsubmission_file", "20260001"),
            // Graded as the roster's student; the claim is kept.
            ("鈴木 花子_1006_assignsubmission_file", "20260006"),
        ]
    );
    let results: Vec<serde_json::Value> = pending
        .iter()
        .map(|p| {
            let student = p.files.as_ref().ok().map(|(_, s)| s.student.to_string());
            let meta = result::Meta {
                entry: &p.entry,
                student: student.as_deref(),
                table: p.files.as_ref().ok().map(|(_, s)| s.table),
                hash: "",
                isolation: Isolation::Bubblewrap,
                same_number: &p.same_number,
                roster: p.roster.as_ref(),
                total: std::time::Duration::ZERO,
            };
            result::build(&meta, &result::Facts::default(), &Config::default(), Lang::En)
        })
        .collect();
    let flags: Vec<Option<Text>> = results.iter().map(result::flag).collect();
    let expected = "student.toml claims 20260099, the roster says 20260006";
    assert_eq!(flags[7].as_ref().map(|f| f.en.as_str()), Some(expected));
    assert_eq!(
        flags[7].as_ref().map(|f| f.ja.as_str()),
        Some("student.toml は 20260099、名簿では 20260006")
    );
    assert!(flags[..7].iter().all(Option::is_none), "{flags:?}");
    let csv_ja = result::class_csv(&results, Lang::Ja);
    assert!(csv_ja.contains(",student.toml は 20260099、名簿では 20260006\n"), "{csv_ja}");
    let csv = result::class_csv(&results, Lang::En);
    assert!(
        csv.starts_with(
            "student,submission,a1,a2,a3,a4,s,score,max_score,report,report_checked,report_mistakes,report_not_checked,flag\n"
        ),
        "{csv}"
    );
    let row = csv.lines().find(|l| l.contains("鈴木")).unwrap();
    assert!(row.starts_with("20260006,鈴木 花子_1006_assignsubmission_file,"), "{row}");
    assert!(row.ends_with(&format!(",\"{expected}\"")), "{row}");
    let md = result::summary_md(&results, &[("20260010".into(), "Absent".into())], Lang::En);
    assert!(
        md.contains(
            "- `鈴木 花子_1006_assignsubmission_file`: student.toml claims `20260099`, the roster says 20260006 (鈴木 花子)"
        ),
        "{md}"
    );
    // Reading is deterministic, and the zip and its unpacked folder are the same class: the
    // same entries with the same hashes (so a resumed run keeps their results).
    let hashes = |list: &[crate::Pending]| -> Vec<(String, String)> {
        list.iter().map(|p| (p.entry.clone(), p.hash.clone())).collect()
    };
    assert_eq!(hashes(&crate::collect(&opts, "kit", None).unwrap()), hashes(&pending));
    fake::unpack(&fake::class(), &root.join("unpacked"));
    let unpacked = Options { submissions: root.join("unpacked"), ..opts.clone() };
    assert_eq!(hashes(&crate::collect(&unpacked, "kit", None).unwrap()), hashes(&pending));
    // Without a roster the participant is who its student.toml says.
    let opts = options(&root, &root.join("download.zip"), None);
    let pending = crate::collect(&opts, "kit", None).unwrap();
    assert!(pending.iter().any(|p| p.name == "20260099"));
    let _ = std::fs::remove_dir_all(&root);
}

/// One exercises/ path twice in a participant's upload (`exercises/src/a1.rs` and
/// `exercises\src\a1.rs`, one path once a zip's `\` is read as `/`): refused, as a submission
/// read from a folder or a zip is; one copy was taken silently.
#[test]
fn one_path_twice_in_an_upload_is_refused() {
    let dir = fake::scratch("twice");
    let items: Vec<(String, Vec<u8>)> = [
        ("Ann_1_assignsubmission_file/exercises/src/a1.rs", b"fn mine() {}".to_vec()),
        ("Ann_1_assignsubmission_file/exercises\\src\\a1.rs", b"fn other() {}".to_vec()),
    ]
    .into_iter()
    .map(|(name, bytes)| (name.to_owned(), bytes))
    .chain(std::iter::once((
        "Ann_1_assignsubmission_file/exercises/student.toml".to_owned(),
        b"student = \"12345678\"\n".to_vec(),
    )))
    .collect();
    std::fs::write(dir.join("d.zip"), fake::zip_of(&items)).unwrap();
    let list = entries(&dir.join("d.zip")).unwrap();
    let why = list[0].read().unwrap_err();
    assert!(why.en.contains("exercises/src/a1.rs is there more than once"), "{}", why.en);
    assert!(why.ja.contains("2 つ以上あります"), "{}", why.ja);
    let _ = std::fs::remove_dir_all(&dir);
}

/// What one participant's upload reads as, from a download of it alone.
fn upload(name: &str, inside: Vec<(String, Vec<u8>)>) -> Outcome {
    let dir = fake::scratch(name);
    let items: Vec<(String, Vec<u8>)> =
        inside.into_iter().map(|(n, b)| (format!("Ann_1_assignsubmission_file/{n}"), b)).collect();
    std::fs::write(dir.join("d.zip"), fake::zip_of(&items)).unwrap();
    let got = read_all(&entries(&dir.join("d.zip")).unwrap()).remove(0).1;
    let _ = std::fs::remove_dir_all(&dir);
    got
}

/// Two complete submissions from one participant (two zips of `exercises/`) that differ are
/// refused naming both (the shorter path was graded without a word); a corrected `a1.rs`
/// uploaded beside the zip is refused when it differs from the zip's (it was ignored), is
/// nothing when it is the same text, and fills a file the zip lacks.
#[test]
fn two_versions_in_one_upload_are_refused_naming_both() {
    let zip = |prefix: &str, a1: &str| {
        let mut files = fake::six(prefix, "src/", "20260001");
        files.retain(|(n, _)| !n.ends_with("a1.rs"));
        files.push((format!("{prefix}src/a1.rs"), a1.as_bytes().to_vec()));
        fake::zip_of(&files)
    };
    let why = upload(
        "versions",
        vec![
            ("exercises-v1.zip".into(), zip("exercises/", "// v1")),
            ("exercises-v2.zip".into(), zip("exercises/", "// v2")),
        ],
    )
    .unwrap_err();
    assert!(
        why.contains("exercises/ is in 2 places with different files (exercises-v1.zip/exercises/ and exercises-v2.zip/exercises/: src/a1.rs differs)"),
        "{why}"
    );
    // The same zip twice (uploaded again): one submission.
    let same = upload(
        "same",
        vec![
            ("exercises.zip".into(), zip("exercises/", "// v1")),
            ("copy.zip".into(), zip("exercises/", "// v1")),
        ],
    );
    assert_eq!(same.unwrap().1, "// v1");
    // A loose a1.rs beside the zip.
    let beside = |a1: &str| {
        upload(
            "beside",
            vec![
                ("exercises.zip".into(), zip("exercises/", "// in the zip")),
                ("a1.rs".into(), a1.as_bytes().to_vec()),
            ],
        )
    };
    let why = beside("// corrected").unwrap_err();
    assert!(
        why.contains("a1.rs is both in exercises/ (exercises.zip/exercises/src/a1.rs) and outside it (a1.rs), with different text"),
        "{why}"
    );
    assert_eq!(beside("// in the zip").unwrap().1, "// in the zip");
    // A whole kit uploaded: the kit's own crates/student/src/a1.rs is not beside the tree (it
    // was refused as a second, different a1.rs); nor is a backup folder's.
    let mut kit = fake::six("cg-kit/exercises/", "src/", "20260001");
    kit.push(("cg-kit/crates/student/src/a1.rs".into(), b"// the kit's own".to_vec()));
    let got = upload(
        "kit",
        vec![("cg-kit.zip".into(), fake::zip_of(&kit)), ("old/a1.rs".into(), b"// old".to_vec())],
    );
    assert_eq!(got.unwrap().1, "// a1 of 20260001");
    // What macOS writes beside a zip on a USB stick (`._exercises.zip`, no zip) is no file of
    // the upload's (it refused the upload as a broken zip).
    let got = upload(
        "appledouble",
        vec![
            ("exercises.zip".into(), zip("exercises/", "// mine")),
            ("._exercises.zip".into(), b"\0\x05\x16\x07 not a zip".to_vec()),
            ("__MACOSX/._a1.rs".into(), b"\0\x05\x16\x07".to_vec()),
        ],
    );
    assert_eq!(got.unwrap().1, "// mine");
    // The zip without student.toml, uploaded beside it: taken.
    let mut files = fake::six("exercises/", "src/", "20260001");
    files.retain(|(n, _)| !n.ends_with("student.toml"));
    let got = upload(
        "toml",
        vec![
            ("e.zip".into(), fake::zip_of(&files)),
            ("student.toml".into(), fake::toml("20260001")),
        ],
    );
    assert_eq!(got.unwrap().0, "20260001");
}

/// A download unpacked and zipped again on macOS (`download/…`, with `__MACOSX/download/._…`
/// and a `.DS_Store` beside it) is read: those names made it "no participant's folder".
#[test]
fn a_download_zipped_again_on_macos_is_read() {
    let dir = fake::scratch("macos");
    let mut items: Vec<(String, Vec<u8>)> =
        fake::six("download/Ann_1_assignsubmission_file/exercises/", "src/", "20260001");
    items.push((
        "__MACOSX/download/._Ann_1_assignsubmission_file".into(),
        b"\0\x05\x16\x07".to_vec(),
    ));
    items.push((".DS_Store".into(), b"Bud1".to_vec()));
    items.push(("download/.DS_Store".into(), b"Bud1".to_vec()));
    std::fs::write(dir.join("d.zip"), fake::zip_of(&items)).unwrap();
    let got = read_all(&entries(&dir.join("d.zip")).unwrap());
    assert_eq!(got.len(), 1, "{got:?}");
    assert_eq!(got[0].0, "Ann_1_assignsubmission_file");
    assert_eq!(got[0].1.as_ref().unwrap().0, "20260001");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A download unzipped on macOS (`download/` beside `__MACOSX/` and `.DS_Store`) is looked
/// through; a folder that holds a download beside other things (the zip, a roster) refuses each
/// download as no one student's: it was graded as the one participant whose `exercises/` lay
/// two levels down, with full marks and exit 0.
#[test]
fn a_download_inside_a_folder_is_not_graded_as_one_student() {
    let dir = fake::scratch("inside");
    let items = fake::class();
    fake::unpack(&items, &dir.join("mac/download"));
    std::fs::create_dir_all(dir.join("mac/__MACOSX/download")).unwrap();
    std::fs::write(dir.join("mac/__MACOSX/download/._x"), b"\0\x05").unwrap();
    std::fs::write(dir.join("mac/.DS_Store"), b"Bud1").unwrap();
    expect_class(&entries(&dir.join("mac")).unwrap());

    fake::unpack(&items, &dir.join("beside/download"));
    std::fs::write(dir.join("beside/download.zip"), fake::zip_of(&items)).unwrap();
    std::fs::write(dir.join("beside/roster.csv"), fake::ROSTER).unwrap();
    let got = read_all(&entries(&dir.join("beside")).unwrap());
    let names: Vec<&str> = got.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["download", "download.zip", "roster.csv"]);
    for (name, outcome) in &got[..2] {
        let why = outcome.as_ref().unwrap_err();
        assert!(
            why.contains("is a Moodle download") && why.contains("give it itself"),
            "{name}: {why}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// An upload with none of the six files is refused naming what it holds (the first five, then
/// how many more) and, where it can be told, why it was not read: another kind of archive, a
/// name that hides `.txt`, a zip inside a zip, an empty zip, `.rs` files of other names. Every
/// such upload was refused with the same sentence, which named nothing.
#[test]
fn an_upload_without_the_six_files_is_refused_naming_what_it_holds() {
    let refused = |name: &str, items: Vec<(String, Vec<u8>)>| -> Text {
        let dir = fake::scratch(name);
        let items: Vec<(String, Vec<u8>)> = items
            .into_iter()
            .map(|(n, b)| (format!("Ann_1_assignsubmission_file/{n}"), b))
            .collect();
        std::fs::write(dir.join("d.zip"), fake::zip_of(&items)).unwrap();
        let from_zip = entries(&dir.join("d.zip")).unwrap()[0].read().unwrap_err();
        // The unpacked download says the same.
        fake::unpack(&items, &dir.join("unpacked"));
        let from_folder = entries(&dir.join("unpacked")).unwrap()[0].read().unwrap_err();
        assert_eq!(from_zip, from_folder, "{name}");
        let _ = std::fs::remove_dir_all(&dir);
        assert!(!from_zip.en.contains('\n') && !from_zip.ja.contains('\n'), "{from_zip:?}");
        from_zip
    };
    let file = |n: &str| (n.to_owned(), b"x".to_vec());
    let lead = "neither exercises/ nor a1.rs … s.rs and student.toml found";

    // 7-Zip, WinRAR, a tar: no zip.
    for (upload, kind) in [("exercises.7z", ".7z"), ("kadai.RAR", ".rar"), ("ex.tar.gz", ".tar.gz")]
    {
        let why = refused("seven", vec![file(upload)]);
        assert!(
            why.en.starts_with(&format!(
                "{lead}; it holds {upload}: {upload} is a {kind} archive, not a zip, and is not read: zip the exercises/ folder instead (in Windows' Explorer, right-click it → Send to → Compressed (zipped) folder; on macOS, Compress)"
            )),
            "{}",
            why.en
        );
        assert!(
            why.ja.starts_with(&format!(
                "exercises/ も a1.rs … s.rs・student.toml も見つかりません。中身: {upload}。{upload} は {kind} の圧縮ファイルで、zip ではないので読めません。"
            )),
            "{}",
            why.ja
        );
        assert!(why.ja.contains("［送る］→［圧縮 (zip 形式) フォルダー］"), "{}", why.ja);
    }

    // A PDF only: named, with the usual advice.
    let why = refused("pdf", vec![file("report.pdf")]);
    assert_eq!(
        why.en,
        format!("{lead}; it holds report.pdf: hand in the exercises/ folder as a zip")
    );
    assert_eq!(
        why.ja,
        "exercises/ も a1.rs … s.rs・student.toml も見つかりません。中身: report.pdf。exercises/ フォルダを zip にして提出してください"
    );

    // Windows hid `.txt`: a1.rs.txt is no a1.rs.
    let why = refused("txt", vec![file("a1.rs.txt"), file("student.toml.txt")]);
    assert!(
        why.en.ends_with("; it holds a1.rs.txt, student.toml.txt: a1.rs.txt is a text file whose name hides .txt (and 1 more like it): rename it a1.rs (Explorer shows the .txt once View → File name extensions is on)"),
        "{}",
        why.en
    );
    assert!(
        why.ja.ends_with("中身: a1.rs.txt、student.toml.txt。a1.rs.txt は名前の最後の .txt が隠れたテキストファイルです（ほか 1 個も同じです）。名前を a1.rs に変えてください（エクスプローラーの［表示］で［ファイル名拡張子］を入れると .txt が見えます）"),
        "{}",
        why.ja
    );

    // A zip inside the zip is not opened (a zip in the upload is).
    let inner = fake::zip_of(&fake::six("exercises/", "src/", "20260001"));
    let why =
        refused("nested", vec![("outer.zip".into(), fake::zip_of(&[("inner.zip".into(), inner)]))]);
    assert!(
        why.en.ends_with("; it holds outer.zip, outer.zip/inner.zip: outer.zip/inner.zip is a zip inside a zip, which is not opened: zip the exercises/ folder itself, once"),
        "{}",
        why.en
    );
    assert!(
        why.ja.ends_with("outer.zip/inner.zip は zip の中の zip なので開きません。exercises/ フォルダそのものを 1 回だけ zip にしてください"),
        "{}",
        why.ja
    );

    // An empty zip.
    let why = refused("empty", vec![("exercises.zip".into(), fake::zip_of(&[]))]);
    assert!(
        why.en.ends_with(
            "; it holds exercises.zip: exercises.zip holds no file: zip the exercises/ folder again"
        ),
        "{}",
        why.en
    );
    assert!(why.ja.ends_with("exercises.zip にはファイルが入っていません。exercises/ フォルダを zip にし直してください"), "{}", why.ja);

    // A project of the student's own, its .rs files named otherwise.
    let why = refused(
        "other",
        vec![file("kadai/src/main.rs"), file("kadai/src/lib.rs"), file("kadai/Cargo.toml")],
    );
    assert!(
        why.en.ends_with("; it holds kadai/Cargo.toml, kadai/src/lib.rs, kadai/src/main.rs: no .rs file in it is named a1.rs … s.rs (only those, in exercises/src/, are graded)"),
        "{}",
        why.en
    );
    assert!(
        why.ja.contains("中身: kadai/Cargo.toml、kadai/src/lib.rs、kadai/src/main.rs。"),
        "{}",
        why.ja
    );

    // Many files: the first five, and how many more; hidden ones are none of them.
    let mut many: Vec<(String, Vec<u8>)> =
        (1..=8).map(|k| file(&format!("photo{k}.jpg"))).collect();
    many.push(file(".DS_Store"));
    let why = refused("many-names", many);
    assert!(
        why.en.contains(
            "; it holds photo1.jpg, photo2.jpg, photo3.jpg, photo4.jpg, photo5.jpg and 3 more: "
        ),
        "{}",
        why.en
    );
    assert!(
        why.ja.contains(
            "中身: photo1.jpg、photo2.jpg、photo3.jpg、photo4.jpg、photo5.jpg ほか 3 個。"
        ),
        "{}",
        why.ja
    );
}
