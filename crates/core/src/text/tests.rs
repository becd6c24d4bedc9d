use super::*;

const REPORT: &str = "# レポート\r\n頂点 V0 (1, 0, 0)\r\n";

fn utf16(s: &str, little: bool) -> Vec<u8> {
    let mut out = if little { vec![0xFF, 0xFE] } else { vec![0xFE, 0xFF] };
    for unit in s.encode_utf16() {
        out.extend(if little { unit.to_le_bytes() } else { unit.to_be_bytes() });
    }
    out
}

fn shift_jis(s: &str) -> Vec<u8> {
    let (bytes, _, unmappable) = encoding_rs::SHIFT_JIS.encode(s);
    assert!(!unmappable, "{s:?} is all in Shift_JIS");
    bytes.into_owned()
}

#[test]
fn utf16_without_a_bom_is_recognised_by_its_zero_bytes() {
    let bare = |little| utf16(REPORT, little)[2..].to_vec();
    assert_eq!(decode(&bare(true), None), Ok((REPORT.to_owned(), Encoding::Utf16Le)));
    assert_eq!(decode(&bare(false), None), Ok((REPORT.to_owned(), Encoding::Utf16Be)));
    // UTF-8 and Shift_JIS have no zero bytes: never taken for UTF-16.
    assert_eq!(utf16_without_bom(REPORT.as_bytes()), None);
    assert_eq!(utf16_without_bom(&shift_jis(REPORT)), None);
    // Kanji alone have no zero byte either: not recognised (named with --encoding).
    let kanji = utf16("頂点の法線", true)[2..].to_vec();
    assert_eq!(utf16_without_bom(&kanji), None);
    assert_eq!(utf16_without_bom(b"a"), None);
}

/// The kit's own report template: Japanese with Markdown, and 最 (U+6700) and 言 (U+8A00),
/// whose UTF-16 code units have a zero low byte.
const TEMPLATE: &str = include_str!("../../../../report-template/ja/report.md");

/// A filled-in report as Notepad writes it: CRLF, an ideographic space (U+3000) indenting a
/// paragraph, 一 (U+4E00), 最 (U+6700) and 言 (U+8A00): characters with a zero low byte.
const FILLED: &str = "# 課題 1 レポート\r\n\r\n| 頂点 | x | y | z |\r\n|---|---|---|---|\r\n\
    | V0 | 1 | 0 | 0 |\r\n\r\n\u{3000}一番最初に言いたいのは、法線 N = (0, 1, 0) のことです。\r\n\
    \u{3000}最後に一言: 面 F0 { V0, V3, V1 } は 反時計回り。\r\n";

/// UTF-16 saved without a BOM, text with 一, 最, 言 or U+3000 in it: their zero low bytes are
/// not a reason to refuse it (it was "neither UTF-8 nor Shift_JIS", exit 2), in either byte
/// order.
#[test]
fn utf16_without_a_bom_is_read_with_characters_whose_low_byte_is_zero() {
    let zero_low_byte = |s: &str| s.encode_utf16().any(|u| u > 0xFF && u & 0xFF == 0);
    assert!(zero_low_byte(TEMPLATE), "premise: the template has such a character");
    assert!(['\u{3000}', '一', '最', '言'].iter().all(|&c| FILLED.contains(c)));
    let lf = TEMPLATE.replace("\r\n", "\n");
    let crlf = lf.replace('\n', "\r\n");
    for text in [TEMPLATE, lf.as_str(), crlf.as_str(), FILLED] {
        for (little, encoding) in [(true, Encoding::Utf16Le), (false, Encoding::Utf16Be)] {
            let bare = utf16(text, little)[2..].to_vec();
            assert_eq!(
                utf16_without_bom(&bare),
                Some(encoding),
                "{encoding}: {}",
                text.lines().next().unwrap_or("")
            );
            assert_eq!(decode(&bare, None), Ok((text.to_owned(), encoding)), "{encoding}");
            assert_eq!(decode_cow(Cow::Owned(bare), None), Ok((text.to_owned(), encoding)));
        }
    }
    // The same text in UTF-8 or Shift_JIS is not taken for UTF-16.
    for text in [TEMPLATE, FILLED] {
        assert_eq!(utf16_without_bom(text.as_bytes()), None);
        assert_eq!(decode(text.as_bytes(), None), Ok((text.to_owned(), Encoding::Utf8)));
    }
    let sjis = shift_jis(FILLED);
    assert_eq!(utf16_without_bom(&sjis), None);
    assert_eq!(decode(&sjis, None), Ok((FILLED.to_owned(), Encoding::ShiftJis)));
}

/// More characters with a zero low byte than ASCII ones: the byte order whose reading is text
/// wins, not the one with more zero bytes in ASCII's place (read big-endian, little-endian
/// `一　最\n` is `N0g` and U+0A00, the byte-swapped line end).
#[test]
fn utf16_without_a_bom_is_read_in_the_byte_order_that_gives_text() {
    let text = "一\u{3000}最\n".repeat(50);
    for (little, encoding) in [(true, Encoding::Utf16Le), (false, Encoding::Utf16Be)] {
        let bare = utf16(&text, little)[2..].to_vec();
        assert_eq!(decode(&bare, None), Ok((text.clone(), encoding)), "{encoding}");
    }
}

/// Zero bytes that are not UTF-16 text: refused as before, never read as UTF-16.
#[test]
fn binary_with_zero_bytes_is_not_taken_for_utf16() {
    // A table of small 16-bit numbers (control characters read as UTF-16).
    let numbers: Vec<u8> = (1..=600u16).flat_map(u16::to_le_bytes).collect();
    let big: Vec<u8> = (1..=600u16).flat_map(u16::to_be_bytes).collect();
    // Zeros; ASCII text with a NUL in every other byte and a control character.
    let zeros = vec![0u8; 64];
    let control = utf16("V0 (1, 0, 0)\u{1}\r\n", true)[2..].to_vec();
    // An unpaired surrogate; a byte-swapped BOM (U+FFFE) in the text.
    let surrogate = [b"a\0b\0".as_slice(), b"\x00\xD8c\0\n\0"].concat();
    let swapped = [b"a\0b\0".as_slice(), b"\xFE\xFF\n\0"].concat();
    for bytes in [&numbers, &big, &zeros, &control, &surrogate, &swapped] {
        assert_eq!(utf16_without_bom(bytes), None, "{bytes:?}");
        assert!(decode(bytes, None).is_err(), "{bytes:?}");
    }
    // Odd length: never UTF-16.
    let mut odd = utf16(FILLED, true)[2..].to_vec();
    odd.pop();
    assert_eq!(utf16_without_bom(&odd), None);
}

/// The same report in every encoding the kit reads: one text, its encoding named.
#[test]
fn every_encoding_decodes_to_the_same_text_and_names_itself() {
    let mut bom = b"\xEF\xBB\xBF".to_vec();
    bom.extend_from_slice(REPORT.as_bytes());
    let sjis = shift_jis(REPORT);
    assert_ne!(sjis, REPORT.as_bytes(), "premise: Shift_JIS bytes differ from UTF-8's");
    let cases = [
        (REPORT.as_bytes().to_vec(), Encoding::Utf8),
        (bom, Encoding::Utf8Bom),
        (utf16(REPORT, true), Encoding::Utf16Le),
        (utf16(REPORT, false), Encoding::Utf16Be),
        (sjis, Encoding::ShiftJis),
    ];
    for (bytes, encoding) in &cases {
        assert_eq!(decode(bytes, None), Ok((REPORT.to_owned(), *encoding)), "{encoding}");
        // The owned path (files) gives the same.
        assert_eq!(decode_cow(Cow::Owned(bytes.clone()), None), Ok((REPORT.to_owned(), *encoding)));
        // Forced to what it is, the same again.
        let named = if *encoding == Encoding::Utf8Bom { Encoding::Utf8 } else { *encoding };
        assert_eq!(decode(bytes, Some(named)), Ok((REPORT.to_owned(), *encoding)));
    }
    assert_eq!(decode(b"", None), Ok((String::new(), Encoding::Utf8)));
}

#[test]
fn only_shift_jis_and_utf16_are_mentioned_in_a_summary() {
    assert_eq!(Encoding::Utf8.read_as(), None);
    assert_eq!(Encoding::Utf8Bom.read_as(), None);
    let said = Encoding::ShiftJis.read_as().unwrap();
    assert_eq!(said, Text::new("Shift_JIS として読みました", "read as Shift_JIS"));
    assert_eq!(Encoding::Utf16Le.read_as().unwrap().en, "read as UTF-16LE");
}

/// Seeded bytes of every value (xorshift), and a Latin-1 text: neither UTF-8 nor Shift_JIS.
#[test]
fn binary_and_latin1_are_refused_with_the_place() {
    let mut state = 0x9E37_79B9_7F4A_7C15_u64;
    let random: Vec<u8> = (0..4096)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state.to_le_bytes()[0]
        })
        .collect();
    let e = decode(&random, None).unwrap_err();
    assert!(matches!(e, DecodeError::Undetected { .. }), "{e}");

    let (latin1, _, _) = encoding_rs::WINDOWS_1252.encode("Caf\u{e9} cr\u{e8}me\r\nna\u{ef}ve\r\n");
    let e = decode(&latin1, None).unwrap_err();
    assert_eq!(
        e,
        DecodeError::Undetected {
            at: Place { line: 1, column: 4, offset: 3 },
            nearest: Encoding::Utf8
        }
    );
    let text = e.text();
    assert!(text.en.contains("neither UTF-8 nor Shift_JIS"), "{}", text.en);
    assert!(text.en.contains("line 1, column 4 (byte offset 3)"), "{}", text.en);
    assert!(
        text.en.contains("save the file as UTF-8") || text.en.contains("Save the file as UTF-8")
    );
    assert!(text.en.contains("`--encoding shift_jis`"), "{}", text.en);
    assert!(text.ja.contains("1 行 4 文字目"), "{}", text.ja);
    assert!(text.ja.contains("エンコード: UTF-8"), "{}", text.ja);
    assert!(!e.text_without_option().en.contains("--encoding"));
    assert!(!e.text_without_option().ja.contains("--encoding"));
}

/// Shift_JIS that breaks on line 2: the place is where Shift_JIS stops, not where UTF-8 did
/// (at the first Japanese character).
#[test]
fn the_reading_that_gets_further_names_the_place() {
    let mut bytes = shift_jis("# レポート\r\n頂点 ");
    let offset = bytes.len();
    bytes.push(0xFF);
    bytes.extend_from_slice(b"V0\r\n");
    let e = decode(&bytes, None).unwrap_err();
    assert_eq!(
        e,
        DecodeError::Undetected {
            at: Place { line: 2, column: 4, offset },
            nearest: Encoding::ShiftJis
        }
    );
    // Valid UTF-8 broken on line 3 after Japanese text: UTF-8's place, counted in characters.
    let mut bytes = "一\n二\n三四".as_bytes().to_vec();
    bytes.push(0xFF);
    let e = decode(&bytes, None).unwrap_err();
    assert_eq!(e.place(), Place { line: 3, column: 3, offset: bytes.len() - 1 });
}

#[test]
fn a_bom_decides_and_broken_text_after_it_is_refused() {
    // Odd length: half a UTF-16 code unit at the end.
    let mut odd = utf16("ab\n", true);
    odd.push(b'c');
    let e = decode(&odd, None).unwrap_err();
    assert_eq!(
        e,
        DecodeError::AfterBom {
            encoding: Encoding::Utf16Le,
            at: Place { line: 2, column: 1, offset: 8 }
        }
    );
    assert!(e.text().ja.contains("UTF-16LE の BOM"), "{}", e.text().ja);
    // An unpaired surrogate.
    let e = decode(b"\xFE\xFF\x00a\xD8\x00\x00b", None).unwrap_err();
    assert_eq!(e.place(), Place { line: 1, column: 2, offset: 4 });
    // A UTF-8 BOM followed by Shift_JIS.
    let mut mixed = b"\xEF\xBB\xBF".to_vec();
    mixed.extend(shift_jis("頂点"));
    let e = decode(&mixed, None).unwrap_err();
    assert!(e.text().en.starts_with("the file starts with a UTF-8 byte-order mark, but"));
    assert_eq!(
        e,
        DecodeError::AfterBom {
            encoding: Encoding::Utf8Bom,
            at: Place { line: 1, column: 1, offset: 3 }
        }
    );
}

#[test]
fn a_named_encoding_skips_detection() {
    let sjis = shift_jis(REPORT);
    assert_eq!(
        decode(&sjis, Some(Encoding::ShiftJis)),
        Ok((REPORT.to_owned(), Encoding::ShiftJis))
    );
    // ASCII is valid Shift_JIS too: named, it is read as such.
    assert_eq!(decode(b"V0\n", Some(Encoding::ShiftJis)), Ok(("V0\n".into(), Encoding::ShiftJis)));
    // Shift_JIS named as UTF-8: refused where UTF-8 stops, naming the option.
    let e = decode(&sjis, Some(Encoding::Utf8)).unwrap_err();
    assert_eq!(
        e,
        DecodeError::NotInNamed {
            encoding: Encoding::Utf8,
            at: Place { line: 1, column: 3, offset: 2 }
        }
    );
    assert!(e.text().en.contains("not UTF-8 as `--encoding` says"), "{}", e.text().en);
    // A UTF-16 file named as Shift_JIS is read as Shift_JIS (0xFF is not Shift_JIS).
    let e = decode(&utf16(REPORT, true), Some(Encoding::ShiftJis)).unwrap_err();
    assert_eq!(e.place().offset, 0);
    // UTF-8 named as UTF-16BE, odd length.
    assert!(decode(b"abc", Some(Encoding::Utf16Be)).is_err());
    // A UTF-16LE BOM is removed when UTF-16LE is named.
    assert_eq!(
        decode(&utf16("x", true), Some(Encoding::Utf16Le)),
        Ok(("x".into(), Encoding::Utf16Le))
    );
}

#[test]
fn parses_the_command_line_names() {
    for (s, e) in [
        ("utf-8", Encoding::Utf8),
        ("UTF8", Encoding::Utf8),
        ("utf-16le", Encoding::Utf16Le),
        ("UTF-16BE", Encoding::Utf16Be),
        ("shift_jis", Encoding::ShiftJis),
        ("Shift-JIS", Encoding::ShiftJis),
        ("sjis", Encoding::ShiftJis),
        ("cp932", Encoding::ShiftJis),
        ("windows-31j", Encoding::ShiftJis),
    ] {
        assert_eq!(s.parse::<Encoding>(), Ok(e), "{s}");
    }
    let e = "latin1".parse::<Encoding>().unwrap_err();
    assert!(e.to_string().contains("shift_jis") && e.to_string().contains("文字コード"));
    assert!("utf-16".parse::<Encoding>().is_err(), "UTF-16 without its byte order is ambiguous");
    for e in Encoding::ALL {
        assert_eq!(e.to_string(), e.name());
    }
}

/// Every message: one line in each language, Japanese in the Japanese one and none in the
/// English one.
#[test]
fn messages_are_one_line_in_each_language() {
    let at = Place { line: 3, column: 7, offset: 41 };
    let errors = [
        ReadError::Io { reason: Text::io(&std::io::Error::from(std::io::ErrorKind::NotFound)) },
        ReadError::TooLarge { size: Some(70_000_000), limit: MAX_TEXT_BYTES },
        ReadError::TooLarge { size: None, limit: MAX_TEXT_BYTES },
        ReadError::Decode(DecodeError::Undetected { at, nearest: Encoding::Utf8 }),
        ReadError::Decode(DecodeError::AfterBom { encoding: Encoding::Utf16Be, at }),
        ReadError::Decode(DecodeError::NotInNamed { encoding: Encoding::ShiftJis, at }),
        ReadError::Decode(DecodeError::Binary { at }),
    ];
    let japanese = |c: char| matches!(c, '\u{3000}'..='\u{30ff}' | '\u{4e00}'..='\u{9fff}' | '\u{ff00}'..='\u{ffef}');
    for e in &errors {
        for text in [e.text(), e.text_without_option()] {
            for s in [&text.ja, &text.en] {
                assert!(!s.contains(['\n', '\r', '\t']) && !s.contains("  "), "{s:?}");
                assert_eq!(s.trim(), s, "{s:?}");
            }
            assert!(text.ja.chars().any(japanese), "{}", text.ja);
            assert!(!text.en.chars().any(japanese), "{}", text.en);
        }
        assert_eq!(e.to_string(), e.text().en);
    }
    assert!(errors[1].text().en.contains("larger than 64 MiB (70000000 bytes)"));
    assert!(errors[1].text().ja.contains("70000000 バイト"), "{}", errors[1].text().ja);
}

/// A file over a smaller limit than a text file's is told that limit, not 64 MiB.
#[test]
fn the_limit_named_is_the_one_read_with() {
    let path = std::env::temp_dir().join(format!("cg-text-limit-{}.md", std::process::id()));
    std::fs::write(&path, vec![b'x'; 2048]).unwrap();
    let e = read_bounded(&path, 1 << 10).unwrap_err();
    assert!(matches!(e, ReadError::TooLarge { size: Some(2048), limit: 1024 }), "{e:?}");
    assert!(e.text().en.contains("larger than 1 KiB (2048 bytes)"), "{}", e.text().en);
    assert!(e.text().ja.contains("1 KiB を超えて"), "{}", e.text().ja);
    let _ = std::fs::remove_file(&path);
}

/// Bytes that decode, but to a NUL: a binary file (a PDF with zero bytes, a program) that passed
/// for UTF-8 or Shift_JIS, or a UTF-16 text with a U+0000 in it. Refused, with the place of the
/// first NUL in the file's bytes; they used to be read as text.
#[test]
fn a_nul_character_is_a_binary_file_not_text() {
    let pdf = b"%PDF-1.7\n%\x00\x00\x00\x01 obj\n";
    let e = decode(pdf, None).unwrap_err();
    assert_eq!(e, DecodeError::Binary { at: Place { line: 2, column: 2, offset: 10 } });
    assert!(e.text().en.starts_with("not a text file: there is a NUL character"), "{e}");
    assert!(e.text().ja.contains("2 行 2 文字目"), "{}", e.text().ja);
    // Forced to an encoding, the same.
    assert!(matches!(decode(pdf, Some(Encoding::Utf8)), Err(DecodeError::Binary { .. })));
    // In Shift_JIS: the zero byte's own offset, after a two-byte character.
    let mut sjis = shift_jis("頂点\r\n");
    sjis.extend_from_slice(b"ab\x00c");
    let e = decode(&sjis, None).unwrap_err();
    assert_eq!(e, DecodeError::Binary { at: Place { line: 2, column: 3, offset: 8 } });
    // UTF-16 with a BOM: the U+0000's two bytes, counted after the BOM.
    let e = decode(&utf16("V0\nx\0", true), None).unwrap_err();
    assert_eq!(e, DecodeError::Binary { at: Place { line: 2, column: 2, offset: 10 } });
    // The owned path (files) says the same.
    assert_eq!(
        decode_cow(Cow::Owned(pdf.to_vec()), None).unwrap_err(),
        decode(pdf, None).unwrap_err()
    );
    // UTF-16 text has zero bytes but no NUL character: still text.
    assert_eq!(decode(&utf16(REPORT, true), None), Ok((REPORT.to_owned(), Encoding::Utf16Le)));
}
