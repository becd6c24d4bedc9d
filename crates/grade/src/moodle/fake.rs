//! A fake Moodle "Download all submissions" for the tests: the kit's test class handed in
//! through Moodle in every form the download takes — both folder conventions, a zip in a
//! folder, loose files, the flat form, a Japanese name, blind marking — plus hostile and
//! mistaken uploads. Written as a folder, then zipped as Moodle zips it.

use std::io::Write as _;
use std::path::{Path, PathBuf};

/// One participant's item in the download: its path (from the download's root) and bytes.
pub type Item = (String, Vec<u8>);

/// `student.toml` of a number.
pub fn toml(student: &str) -> Vec<u8> {
    format!("student = \"{student}\"\ntable = 1\n").into_bytes()
}

/// The six files under `prefix` (`""` for loose files, `"x/exercises/"`-style for a tree):
/// each module a comment naming the student, so the tests can tell whose file was read.
pub fn six(prefix: &str, src: &str, student: &str) -> Vec<Item> {
    let mut v: Vec<Item> = crate::submission::MODULES
        .iter()
        .map(|m| (format!("{prefix}{src}{m}.rs"), format!("// {m} of {student}\n").into_bytes()))
        .collect();
    v.push((format!("{prefix}student.toml"), toml(student)));
    v
}

/// A zip in memory of `items`.
pub fn zip_of(items: &[Item]) -> Vec<u8> {
    let mut z = zip::ZipWriter::new(std::io::Cursor::new(Vec::new()));
    let o = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for (name, bytes) in items {
        if name.ends_with('/') {
            z.add_directory(name.as_str(), o).unwrap();
        } else {
            z.start_file(name.as_str(), o).unwrap();
            z.write_all(bytes).unwrap();
        }
    }
    z.finish().unwrap().into_inner()
}

/// The fake class, as `(participant ID, what it tests)` and the download's items.
///
/// | ID | participant | form | upload | student.toml |
/// |---|---|---|---|---|
/// | 1001 | 山田 太郎 | 4.1 folder (and an online text) | a zip with `exercises/` | 20260001 |
/// | 1002 | Jane Roe | 3.1 folder | loose `a1.rs` … `student.toml` | 20260002 |
/// | 1003 | John Smith | flat | a zip with `myproject/exercises/` | 20260003 |
/// | 1004 | Participant (blind, 4.1) | folder | `exercises/` unpacked | 20260004 |
/// | 1005 | Participant 1005 (blind, 3.1) | folder | a zip of loose files | 20260005 |
/// | 1006 | 鈴木 花子 | 4.1 folder | a zip with `exercises/` | 20260099 (the roster: 20260006) |
/// | 1007 | Mallory | 4.1 folder | a zip slip | — |
/// | 1008 | Twice Over | 4.1 folder | `a1.rs` twice | 20260008 |
pub fn class() -> Vec<Item> {
    let mut items: Vec<Item> = Vec::new();
    let mut put = |folder: &str, inside: Vec<Item>| {
        for (name, bytes) in inside {
            items.push((format!("{folder}{name}"), bytes));
        }
    };
    put(
        "山田 太郎_1001_assignsubmission_file/",
        vec![("handin.zip".into(), zip_of(&six("handin/exercises/", "src/", "20260001")))],
    );
    put(
        "山田 太郎_1001_assignsubmission_onlinetext/",
        vec![("onlinetext.html".into(), b"<p>see the zip</p>".to_vec())],
    );
    put("Jane Roe_1002_assignsubmission_file_/", six("", "", "20260002"));
    put(
        "John Smith_1003_assignsubmission_file_",
        vec![("submission.zip".into(), zip_of(&six("myproject/exercises/", "src/", "20260003")))],
    );
    put("Participant_1004_assignsubmission_file/", six("exercises/", "src/", "20260004"));
    put(
        "Participant 1005_1005_assignsubmission_file_/",
        vec![("upload.zip".into(), zip_of(&six("", "", "20260005")))],
    );
    put(
        "鈴木 花子_1006_assignsubmission_file/",
        vec![("課題.zip".into(), zip_of(&six("exercises/", "src/", "20260099")))],
    );
    put(
        "Mallory_1007_assignsubmission_file/",
        vec![(
            "evil.zip".into(),
            zip_of(&[
                ("exercises/student.toml".into(), toml("20260007")),
                ("../../x.rs".into(), b"x".to_vec()),
            ]),
        )],
    );
    let mut twice = six("", "", "20260008");
    twice.push(("old/a1.rs".into(), b"// old".to_vec()));
    put("Twice Over_1008_assignsubmission_file/", twice);
    items
}

/// The roster of the class (the participant IDs in `entry`; 1006's number is not what its
/// `student.toml` says, 1009 handed nothing in).
pub const ROSTER: &str = "student,name,entry\n20260001,山田 太郎,1001\n20260002,Jane Roe,1002\n20260003,John Smith,1003\n20260004,Blind One,1004\n20260005,Blind Two,1005\n20260006,鈴木 花子,1006\n20260007,Mallory,1007\n20260008,Twice Over,1008\n20260010,Absent,1009\n";

/// A fresh scratch folder.
pub fn scratch(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cg-moodle-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Writes the items as the folder the download unpacks to.
pub fn unpack(items: &[Item], dir: &Path) {
    for (name, bytes) in items {
        let path = dir.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, bytes).unwrap();
    }
}

/// A zip written by hand, every entry stored, with names as raw bytes and the UTF-8 flag as
/// given: what an archiver that does not set the flag (or writes Shift_JIS) leaves.
pub fn raw_zip(entries: &[(Vec<u8>, Vec<u8>)], utf8_flag: bool) -> Vec<u8> {
    fn crc32(bytes: &[u8]) -> u32 {
        let mut crc = !0u32;
        for &b in bytes {
            crc ^= u32::from(b);
            for _ in 0..8 {
                crc = if crc & 1 == 1 { (crc >> 1) ^ 0xEDB8_8320 } else { crc >> 1 };
            }
        }
        !crc
    }
    let flag: u16 = if utf8_flag { 0x0800 } else { 0 };
    let mut out = Vec::new();
    let mut central = Vec::new();
    for (name, data) in entries {
        let offset = out.len() as u32;
        let (crc, size, len) = (crc32(data), data.len() as u32, name.len() as u16);
        let header = |sig: u32, central: bool| {
            let mut h = sig.to_le_bytes().to_vec();
            if central {
                h.extend(20u16.to_le_bytes());
            }
            for v in [20u16, flag, 0, 0, 0x21] {
                h.extend(v.to_le_bytes());
            }
            h.extend(crc.to_le_bytes());
            h.extend(size.to_le_bytes());
            h.extend(size.to_le_bytes());
            h.extend(len.to_le_bytes());
            h.extend(0u16.to_le_bytes());
            if central {
                for v in [0u16, 0, 0] {
                    h.extend(v.to_le_bytes());
                }
                h.extend(0u32.to_le_bytes());
                h.extend(offset.to_le_bytes());
            }
            h
        };
        out.extend(header(0x0403_4b50, false));
        out.extend(name);
        out.extend(data);
        central.extend(header(0x0201_4b50, true));
        central.extend(name);
    }
    let at = out.len() as u32;
    out.extend(&central);
    out.extend(0x0605_4b50u32.to_le_bytes());
    for v in [0u16, 0, entries.len() as u16, entries.len() as u16] {
        out.extend(v.to_le_bytes());
    }
    out.extend((central.len() as u32).to_le_bytes());
    out.extend(at.to_le_bytes());
    out.extend(0u16.to_le_bytes());
    out
}
