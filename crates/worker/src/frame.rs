//! Frames on a byte stream: a newline, `\x1eCGW1 <length>\n`, then `<length>` bytes of the
//! payload (CBOR). Anything else on the stream (what the student's code printed) is passed over
//! and kept as text, at most [`MAX_PRINTED`] bytes of it per frame.

use std::io::{self, BufRead, Read as _, Write};

/// The start of every frame's header: ASCII record separator, the protocol's name and version.
/// The writer puts a newline before it, so it always starts a line, whatever was printed before.
pub const MAGIC: &[u8] = b"\x1eCGW1 ";

/// The largest frame read (a reply holds at most a mesh or a recorded frame; 256 MiB is far
/// beyond any honest one and keeps a hostile length from allocating the machine's memory).
pub const MAX_FRAME: usize = 256 << 20;

/// How much of what the student printed between two frames is kept (the rest is counted, not
/// stored: a print in an endless loop must not fill the caller's memory).
pub const MAX_PRINTED: usize = 64 << 10;

/// The longest piece read at once while looking for a header (a line without a newline is read
/// in pieces of this size, so its length costs no memory).
const PIECE: u64 = 4096;

/// Writes `payload` as one frame and flushes.
///
/// # Errors
/// The stream is closed.
pub fn write(out: &mut impl Write, payload: &[u8]) -> io::Result<()> {
    out.write_all(b"\n")?;
    out.write_all(MAGIC)?;
    out.write_all(format!("{}\n", payload.len()).as_bytes())?;
    out.write_all(payload)?;
    out.flush()
}

/// A frame's payload (`None`: the stream ended) and what was printed before it.
pub type Read = (Option<Vec<u8>>, Vec<u8>);

/// The next frame's payload (`None` at the end of the stream) and the bytes before it that were
/// not part of a frame: what the student's code printed (at most [`MAX_PRINTED`] bytes, then
/// `…`).
///
/// # Errors
/// The stream failed, or a frame's header is malformed or announces more than [`MAX_FRAME`].
pub fn read(input: &mut impl BufRead) -> io::Result<Read> {
    let mut noise = Vec::new();
    let mut cut = false;
    let mut line = Vec::new();
    loop {
        line.clear();
        if input.by_ref().take(PIECE).read_until(b'\n', &mut line)? == 0 {
            return Ok((None, finish(noise, cut, false)));
        }
        if !line.starts_with(MAGIC) {
            if noise.len() + line.len() <= MAX_PRINTED {
                noise.extend_from_slice(&line);
            } else {
                cut = true;
            }
            continue;
        }
        let header = &line[MAGIC.len()..];
        let length: usize = std::str::from_utf8(header)
            .ok()
            .filter(|h| h.ends_with('\n'))
            .and_then(|h| h.trim_end().parse().ok())
            .filter(|&n| n <= MAX_FRAME)
            .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidData, "bad frame header"))?;
        let mut payload = vec![0; length];
        input.read_exact(&mut payload)?;
        return Ok((Some(payload), finish(noise, cut, true)));
    }
}

/// What was printed, without the newline the writer put before the header.
fn finish(mut noise: Vec<u8>, cut: bool, framed: bool) -> Vec<u8> {
    if framed && noise.last() == Some(&b'\n') {
        noise.pop();
    }
    if cut {
        noise.extend_from_slice("…".as_bytes());
    }
    noise
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_round_trip_and_prints_around_them_are_kept_apart() {
        let mut stream = Vec::new();
        stream.extend_from_slice(b"debug: v = 3\n");
        write(&mut stream, b"{\"a\":1}").unwrap();
        stream.extend_from_slice(b"partial line then ");
        write(&mut stream, b"[2]").unwrap();
        let mut input = io::Cursor::new(stream);
        let (p, noise) = read(&mut input).unwrap();
        assert_eq!(p.as_deref(), Some(&b"{\"a\":1}"[..]));
        assert_eq!(noise, b"debug: v = 3\n");
        let (p, noise) = read(&mut input).unwrap();
        assert_eq!(p.as_deref(), Some(&b"[2]"[..]));
        assert_eq!(noise, b"partial line then ");
        stream_end(&mut input);
    }

    fn stream_end(input: &mut io::Cursor<Vec<u8>>) {
        assert_eq!(read(input).unwrap(), (None, Vec::new()));
    }

    #[test]
    fn a_flood_of_prints_keeps_a_bounded_part() {
        let mut stream = vec![b'x'; 3 * MAX_PRINTED];
        stream.extend_from_slice(b"\nmore\n");
        write(&mut stream, b"1").unwrap();
        let (p, noise) = read(&mut io::Cursor::new(stream)).unwrap();
        assert_eq!(p.as_deref(), Some(&b"1"[..]));
        assert!(
            noise.len() <= MAX_PRINTED + 3 && noise.ends_with("…".as_bytes()),
            "{}",
            noise.len()
        );
    }

    #[test]
    fn a_hostile_header_is_refused_without_allocating() {
        let mut input = io::Cursor::new(b"\x1eCGW1 99999999999\n".to_vec());
        assert!(read(&mut input).is_err());
        let mut input = io::Cursor::new(b"\x1eCGW1 x\n".to_vec());
        assert!(read(&mut input).is_err());
    }
}
