//! Opening a zip with a bound on its entries, checked before its central directory is read.
//!
//! `zip::ZipArchive::new` reads every entry the archive's end record declares before the caller
//! can count them, about 150 bytes of memory an entry (a million entries of 53 bytes: 150 MB and
//! half a second, measured): a hostile zip of 256 MiB inside an upload, five million entries,
//! took about 1 GB before it was refused as "too many entries". [`open`] reads the
//! counts that every end record near the archive's end declares (the ones the zip crate may
//! choose: the 32-bit records in the last 64 KiB, and each zip64 record a locator points into)
//! and refuses the archive when the largest is over the bound, before the zip crate reads a
//! single entry.

use std::io::{self, Read, Seek, SeekFrom};

use crate::Text;

/// The end-of-central-directory record's signature, `PK\5\6`.
const EOCD: [u8; 4] = *b"PK\x05\x06";
/// The zip64 end record's signature, `PK\6\6`.
const EOCD64: [u8; 4] = *b"PK\x06\x06";
/// The zip64 locator's signature, `PK\6\7`.
const LOCATOR: [u8; 4] = *b"PK\x06\x07";
/// The fixed part of a 32-bit end record.
const EOCD_LEN: usize = 22;
/// A zip64 locator's length, just before the 32-bit end record.
const LOCATOR_LEN: usize = 20;
/// The longest archive comment, after the 32-bit end record.
const MAX_COMMENT: usize = 0xffff;
/// The bytes read at once while looking for zip64 end records.
const PIECE: usize = 1 << 20;

/// `reader` as a zip archive of at most `max_entries` entries.
///
/// # Errors
/// The archive declares more entries (said before anything else is read), or is not a
/// readable zip ([`crate::submission::zip_reason`]).
pub fn open<R: Read + Seek>(mut reader: R, max_entries: usize) -> Result<zip::ZipArchive<R>, Text> {
    let declared = declared_entries(&mut reader)
        .map_err(|e| crate::submission::zip_reason(&zip::result::ZipError::Io(e)))?;
    if declared > max_entries as u64 {
        return Err(too_many(declared, max_entries));
    }
    let zip = zip::ZipArchive::new(reader).map_err(|e| crate::submission::zip_reason(&e))?;
    // The records checked are the ones the zip crate reads; this holds all the same.
    if zip.len() > max_entries {
        return Err(too_many(zip.len() as u64, max_entries));
    }
    Ok(zip)
}

fn too_many(entries: u64, max: usize) -> Text {
    Text::new(
        format!("zip の項目が多すぎます（{entries}、上限 {max}）"),
        format!("too many entries in the zip ({entries}, at most {max})"),
    )
}

/// The most entries any end record near the archive's end declares (0 when there is none: the
/// zip crate then refuses the archive by itself). A zip64 record's count is taken at most as
/// the file can hold (46 bytes an entry), as the zip crate takes it.
///
/// # Errors
/// The reader failed.
pub fn declared_entries<R: Read + Seek>(reader: &mut R) -> io::Result<u64> {
    let file_len = reader.seek(SeekFrom::End(0))?;
    let tail_len = file_len.min((EOCD_LEN + MAX_COMMENT + LOCATOR_LEN + 4) as u64);
    let tail_start = file_len - tail_len;
    let tail = read_at(reader, tail_start, tail_len as usize)?;
    let mut most = 0u64;
    for at in positions(&tail, EOCD) {
        let Some(record) = tail.get(at..at + EOCD_LEN) else { continue };
        let u16_at = |i: usize| u64::from(u16::from_le_bytes([record[i], record[i + 1]]));
        most = most.max(u16_at(8)).max(u16_at(10));
        // Any field at its largest may mean zip64: the locator just before says where.
        let zip64 = [4, 6, 8, 10].iter().any(|&i| u16_at(i) == 0xffff)
            || [12, 16].iter().any(|&i| record[i..i + 4] == [0xff; 4]);
        if !zip64 || at < LOCATOR_LEN {
            continue;
        }
        let locator = &tail[at - LOCATOR_LEN..at];
        if locator[..4] != LOCATOR {
            continue;
        }
        let from = u64::from_le_bytes(locator[8..16].try_into().unwrap_or_default());
        let to = tail_start + (at - LOCATOR_LEN) as u64;
        most = most.max(zip64_entries(reader, from, to)?.min(file_len / 46));
    }
    Ok(most)
}

/// The most entries a zip64 end record between `from` and `to` declares (the zip crate tries
/// the locator's own place first, then looks for the signature in between).
fn zip64_entries<R: Read + Seek>(reader: &mut R, from: u64, to: u64) -> io::Result<u64> {
    let mut most = 0u64;
    let mut start = from;
    while start < to {
        // Each piece overlaps the next by a record's length, so no record is cut.
        let len = usize::try_from(to - start).unwrap_or(usize::MAX).min(PIECE + 56);
        let piece = read_at(reader, start, len)?;
        for at in positions(&piece, EOCD64) {
            if let Some(record) = piece.get(at..at + 56) {
                let u64_at =
                    |i: usize| u64::from_le_bytes(record[i..i + 8].try_into().unwrap_or_default());
                most = most.max(u64_at(24)).max(u64_at(32));
            }
        }
        if piece.len() < PIECE + 56 {
            break;
        }
        start += PIECE as u64;
    }
    Ok(most)
}

/// Every place `signature` starts in `bytes`.
fn positions(bytes: &[u8], signature: [u8; 4]) -> impl Iterator<Item = usize> + '_ {
    bytes.windows(4).enumerate().filter(move |(_, w)| *w == signature).map(|(i, _)| i)
}

/// At most `len` bytes from `at` (fewer at the end).
fn read_at<R: Read + Seek>(reader: &mut R, at: u64, len: usize) -> io::Result<Vec<u8>> {
    reader.seek(SeekFrom::Start(at))?;
    let mut bytes = Vec::with_capacity(len.min(PIECE + 56));
    reader.take(len as u64).read_to_end(&mut bytes)?;
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use std::io::{Cursor, Write};

    use super::*;

    fn honest(entries: usize) -> Vec<u8> {
        let mut zip = zip::ZipWriter::new(Cursor::new(Vec::new()));
        for i in 0..entries {
            zip.start_file(format!("f{i}.rs"), zip::write::SimpleFileOptions::default()).unwrap();
            zip.write_all(b"fn f() {}").unwrap();
        }
        zip.finish().unwrap().into_inner()
    }

    #[test]
    fn an_honest_zip_declares_its_entries_and_opens() {
        let bytes = honest(3);
        assert_eq!(declared_entries(&mut Cursor::new(&bytes)).unwrap(), 3);
        assert_eq!(open(Cursor::new(&bytes), 3).unwrap().len(), 3);
        let refused = open(Cursor::new(&bytes), 2).unwrap_err();
        assert!(refused.en.contains("too many entries in the zip (3, at most 2)"), "{refused:?}");
        assert!(refused.ja.contains("項目が多すぎます（3、上限 2）"), "{refused:?}");
        // No end record at all: the zip crate's own reason.
        let none = open(Cursor::new(b"not a zip".to_vec()), 10).unwrap_err();
        assert!(none.en.contains("zip"), "{none:?}");
    }

    /// A zip64 end record that declares a million entries in a file of 53 MB of central
    /// headers: refused from its end records, before the zip crate reads one.
    #[test]
    fn a_zip64_record_declaring_many_entries_is_refused_before_the_entries_are_read() {
        let entries: u64 = 1_000_000;
        let mut bytes = Vec::new();
        // The central directory: entries of 46 bytes and a 7-byte name each, as a hostile
        // upload has them.
        for i in 0..entries {
            let mut header = vec![0u8; 46];
            header[..4].copy_from_slice(b"PK\x01\x02");
            header[28..30].copy_from_slice(&7u16.to_le_bytes());
            bytes.extend_from_slice(&header);
            bytes.extend_from_slice(format!("{i:07}").as_bytes());
        }
        let cd_size = bytes.len() as u64;
        let eocd64_at = bytes.len() as u64;
        let mut eocd64 = vec![0u8; 56];
        eocd64[..4].copy_from_slice(&EOCD64);
        eocd64[4..12].copy_from_slice(&44u64.to_le_bytes());
        eocd64[24..32].copy_from_slice(&entries.to_le_bytes());
        eocd64[32..40].copy_from_slice(&entries.to_le_bytes());
        eocd64[40..48].copy_from_slice(&cd_size.to_le_bytes());
        bytes.extend_from_slice(&eocd64);
        let mut locator = vec![0u8; 20];
        locator[..4].copy_from_slice(&LOCATOR);
        locator[8..16].copy_from_slice(&eocd64_at.to_le_bytes());
        locator[16..20].copy_from_slice(&1u32.to_le_bytes());
        bytes.extend_from_slice(&locator);
        let mut eocd = vec![0u8; 22];
        eocd[..4].copy_from_slice(&EOCD);
        eocd[8..12].copy_from_slice(&[0xff; 4]);
        eocd[12..20].copy_from_slice(&[0xff; 8]);
        bytes.extend_from_slice(&eocd);

        assert_eq!(declared_entries(&mut Cursor::new(&bytes)).unwrap(), entries);
        let refused = open(Cursor::new(&bytes), 10_000).unwrap_err();
        assert!(refused.en.contains("(1000000, at most 10000)"), "{refused:?}");
        // A count past what the file can hold is taken as what it can hold.
        let file_len = bytes.len() as u64;
        let at = bytes.len() - 22 - 20 - 56;
        bytes[at + 32..at + 40].copy_from_slice(&u64::MAX.to_le_bytes());
        assert_eq!(declared_entries(&mut Cursor::new(&bytes)).unwrap(), file_len / 46);
    }
}
