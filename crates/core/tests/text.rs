//! `cg_core::text::read`: files in the encodings students' editors write, under Japanese folder
//! and file names with spaces, and the bound on a file's size.

use std::path::PathBuf;

use cg_core::text::{DecodeError, Encoding, MAX_TEXT_BYTES, Place, ReadError, read};

const REPORT: &str = "# レポート\r\n頂点 V0 (1, 0, 0)\r\n";

/// A fresh folder `山田 太郎` under a scratch folder of this test.
fn student_folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir()
        .join(format!("cg-core-text-{}-{name}", std::process::id()))
        .join("山田 太郎");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn shift_jis(s: &str) -> Vec<u8> {
    encoding_rs::SHIFT_JIS.encode(s).0.into_owned()
}

fn utf16le(s: &str) -> Vec<u8> {
    let mut out = vec![0xFF, 0xFE];
    out.extend(s.encode_utf16().flat_map(u16::to_le_bytes));
    out
}

#[test]
fn reads_every_encoding_under_a_japanese_path_with_spaces() {
    let dir = student_folder("jp");
    let path = dir.join("レポート 1.md");
    let mut bom = b"\xEF\xBB\xBF".to_vec();
    bom.extend_from_slice(REPORT.as_bytes());
    let cases = [
        (REPORT.as_bytes().to_vec(), Encoding::Utf8),
        (bom, Encoding::Utf8Bom),
        (shift_jis(REPORT), Encoding::ShiftJis),
        (utf16le(REPORT), Encoding::Utf16Le),
    ];
    for (bytes, encoding) in cases {
        std::fs::write(&path, &bytes).unwrap();
        assert_eq!(read(&path, None).unwrap(), (REPORT.to_owned(), encoding), "{encoding}");
    }
    // Named, Shift_JIS is read without detection; named wrongly, the place is given.
    std::fs::write(&path, shift_jis(REPORT)).unwrap();
    assert_eq!(read(&path, Some(Encoding::ShiftJis)).unwrap().1, Encoding::ShiftJis);
    let e = read(&path, Some(Encoding::Utf8)).unwrap_err();
    assert!(matches!(e, ReadError::Decode(DecodeError::NotInNamed { .. })), "{e}");
    assert_eq!(e.place().map(|p| (p.line, p.column)), Some((1, 3)));
    let _ = std::fs::remove_dir_all(dir.parent().unwrap());
}

#[test]
fn a_missing_file_and_a_folder_are_io_errors() {
    let dir = student_folder("io");
    let e = read(&dir.join("ない.md"), None).unwrap_err();
    assert!(matches!(e, ReadError::Io { .. }), "{e}");
    assert!(e.text().en.starts_with("cannot be read ("), "{e}");
    assert!(e.text().ja.starts_with("読めません（"), "{}", e.text().ja);
    // Said in Japanese, not in the system's English.
    assert_eq!(e.text().ja, "読めません（ファイルまたはフォルダがありません）");
    assert!(matches!(read(&dir, None).unwrap_err(), ReadError::Io { .. }));
    let _ = std::fs::remove_dir_all(dir.parent().unwrap());
}

/// A file one byte over the limit (sparse: no 64 MiB written) is refused before it is read; one
/// at the limit is read.
#[test]
fn a_file_over_64_mib_is_refused_by_its_size() {
    let dir = student_folder("large");
    let path = dir.join("大きい ファイル.obj");
    let file = std::fs::File::create(&path).unwrap();
    file.set_len(MAX_TEXT_BYTES + 1).unwrap();
    drop(file);
    let e = read(&path, None).unwrap_err();
    assert_eq!(e, ReadError::TooLarge { size: Some(MAX_TEXT_BYTES + 1), limit: MAX_TEXT_BYTES });
    assert!(e.text().en.contains("larger than 64 MiB (67108865 bytes)"), "{e}");

    // Exactly the limit: read, and then refused as what it is, zeros (a binary file), from the
    // first byte.
    std::fs::File::options().write(true).open(&path).unwrap().set_len(MAX_TEXT_BYTES).unwrap();
    let at = Place { line: 1, column: 1, offset: 0 };
    assert_eq!(read(&path, None).unwrap_err(), ReadError::Decode(DecodeError::Binary { at }));
    let _ = std::fs::remove_dir_all(dir.parent().unwrap());
}

/// A named pipe that nothing writes to: refused after the wait, not a hang (`cg check` with a
/// FIFO as exercises/student.toml waited for ever). A pipe that is written is read.
#[cfg(unix)]
#[test]
fn a_named_pipe_without_a_writer_is_an_error_not_a_hang() {
    let dir = student_folder("fifo");
    let fifo = dir.join("student.toml");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status().is_ok_and(|s| s.success());
    if !made {
        eprintln!("note: skipped: mkfifo is missing");
        return;
    }
    let started = std::time::Instant::now();
    let e = read(&fifo, None).unwrap_err();
    assert!(started.elapsed() < cg_core::text::PIPE_WAIT * 3, "{:?}", started.elapsed());
    assert!(e.text().en.contains("a named pipe that nothing opened for writing"), "{e}");
    assert!(e.text().ja.contains("名前付きパイプ"), "{}", e.text().ja);
    // With a writer, the pipe's text is read (another pipe: the first is still being opened
    // by the thread that gave up).
    let fifo = dir.join("written.toml");
    assert!(std::process::Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let writer = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::write(fifo, "student = \"12345678\"\n"))
    };
    let (text, _) = read(&fifo, None).unwrap();
    assert_eq!(text, "student = \"12345678\"\n");
    writer.join().unwrap().unwrap();
    let _ = std::fs::remove_dir_all(dir.parent().unwrap());
}
