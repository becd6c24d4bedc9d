//! Text files in the encodings students' editors write: UTF-8 with or without a byte-order mark
//! (BOM), UTF-16 with a BOM (old Windows Notepad's "Unicode") and Shift_JIS (CP932, a Japanese
//! Windows editor's "ANSI"). Everything the kit reads from a student or a TA (scenes, OBJ
//! models, reports, data tables) goes through [`read`] or [`decode`]; everything it writes is
//! UTF-8 without a BOM.
//!
//! Detection, when no encoding is named: a BOM decides (and is removed from the text); else
//! UTF-16 without a BOM is recognised by its zero bytes, when it reads as text in that byte
//! order ([`utf16_without_bom`]: some editors save "Unicode" without a BOM; text in UTF-8 or
//! Shift_JIS has no zero bytes); else valid UTF-8 is UTF-8; else the text is Shift_JIS when it
//! decodes as Shift_JIS without an error; else it is refused with a [`DecodeError`] that says
//! where (line, column, byte offset) and what to do. Line endings are left as they are (`\r\n`
//! included); the kit's parsers accept both.
//!
//! The decoders are `encoding_rs`'s (the WHATWG Encoding Standard's): its Shift_JIS is
//! Windows' CP932, NEC and IBM extensions included.

use std::borrow::Cow;
use std::fmt;
use std::io::Read as _;
use std::path::Path;
use std::str::FromStr;

use crate::lang::Text;

/// The largest text file [`read`] reads: 64 MiB (the course's models and reports are a few KiB
/// to a few MiB).
pub const MAX_TEXT_BYTES: u64 = 64 << 20;

/// An encoding the kit reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Encoding {
    /// UTF-8 without a byte-order mark (what the kit writes).
    Utf8,
    /// UTF-8 with a byte-order mark (`EF BB BF`; Notepad's "UTF-8 (BOM 付き)").
    Utf8Bom,
    /// UTF-16, little-endian (`FF FE`; Notepad's "Unicode").
    Utf16Le,
    /// UTF-16, big-endian (`FE FF`).
    Utf16Be,
    /// Shift_JIS as Windows writes it (CP932, Windows-31J; a Japanese Windows editor's "ANSI").
    ShiftJis,
}

impl Encoding {
    /// Every encoding, in the order of [`Encoding::name`]'s list in messages.
    pub const ALL: [Encoding; 5] = [
        Encoding::Utf8,
        Encoding::Utf8Bom,
        Encoding::Utf16Le,
        Encoding::Utf16Be,
        Encoding::ShiftJis,
    ];

    /// The name a student's editor shows: `UTF-8`, `UTF-8 (BOM)`, `UTF-16LE`, `UTF-16BE`,
    /// `Shift_JIS`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Encoding::Utf8 => "UTF-8",
            Encoding::Utf8Bom => "UTF-8 (BOM)",
            Encoding::Utf16Le => "UTF-16LE",
            Encoding::Utf16Be => "UTF-16BE",
            Encoding::ShiftJis => "Shift_JIS",
        }
    }

    /// Whether the text was UTF-8 (with or without a BOM): what the kit writes, so nothing to
    /// tell the student.
    #[must_use]
    pub fn is_utf8(self) -> bool {
        matches!(self, Encoding::Utf8 | Encoding::Utf8Bom)
    }

    /// `read as Shift_JIS` / `Shift_JIS として読みました`, for a command's summary; `None` for
    /// UTF-8 (with or without a BOM), which needs no mention.
    #[must_use]
    pub fn read_as(self) -> Option<Text> {
        (!self.is_utf8()).then(|| {
            Text::new(
                format!("{} として読みました", self.name()),
                format!("read as {}", self.name()),
            )
        })
    }

    fn decoder(self) -> &'static encoding_rs::Encoding {
        match self {
            Encoding::Utf8 | Encoding::Utf8Bom => encoding_rs::UTF_8,
            Encoding::Utf16Le => encoding_rs::UTF_16LE,
            Encoding::Utf16Be => encoding_rs::UTF_16BE,
            Encoding::ShiftJis => encoding_rs::SHIFT_JIS,
        }
    }

    /// The byte-order mark this encoding may start with.
    fn bom(self) -> &'static [u8] {
        match self {
            Encoding::Utf8 | Encoding::Utf8Bom => b"\xEF\xBB\xBF",
            Encoding::Utf16Le => b"\xFF\xFE",
            Encoding::Utf16Be => b"\xFE\xFF",
            Encoding::ShiftJis => b"",
        }
    }
}

impl fmt::Display for Encoding {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The error of parsing an [`Encoding`] from a command line's `--encoding`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error(
    "unknown encoding {0:?}: use utf-8, utf-16le, utf-16be or shift_jis / 文字コード {0:?} は使えません。utf-8・utf-16le・utf-16be・shift_jis のどれかを指定してください"
)]
pub struct UnknownEncoding(pub String);

impl FromStr for Encoding {
    type Err = UnknownEncoding;

    /// `utf-8`, `utf-16le`, `utf-16be`, `shift_jis` (also `sjis`, `cp932`, `windows-31j`), in
    /// any case, with `-`, `_` or nothing between the parts.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let key: String =
            s.chars().filter(|c| !matches!(c, '-' | '_')).collect::<String>().to_ascii_lowercase();
        match key.as_str() {
            "utf8" => Ok(Encoding::Utf8),
            "utf16le" => Ok(Encoding::Utf16Le),
            "utf16be" => Ok(Encoding::Utf16Be),
            "shiftjis" | "sjis" | "cp932" | "windows31j" | "ms932" => Ok(Encoding::ShiftJis),
            _ => Err(UnknownEncoding(s.to_owned())),
        }
    }
}

/// A place in a file that could not be decoded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Place {
    /// Line, from 1.
    pub line: usize,
    /// Column in characters, from 1 (the first byte that could not be read is this column).
    pub column: usize,
    /// Byte offset in the file, from 0 (the BOM included), of the first byte that could not be
    /// read.
    pub offset: usize,
}

impl Place {
    /// The place after `decoded`, the text decoded before the error, at byte `offset`.
    fn after(decoded: &str, offset: usize) -> Place {
        let line_start = decoded.rfind('\n').map_or(0, |i| i + 1);
        Place {
            line: 1 + decoded.bytes().filter(|&b| b == b'\n').count(),
            column: 1 + decoded[line_start..].chars().count(),
            offset,
        }
    }

    fn text(self) -> Text {
        let Place { line, column, offset } = self;
        Text::new(
            format!("{line} 行 {column} 文字目（先頭から {offset} バイトの位置）"),
            format!("line {line}, column {column} (byte offset {offset})"),
        )
    }
}

/// Bytes that are not text in the encoding they were read as. Each variant has one message in
/// Japanese and English ([`DecodeError::text`]).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}", self.text().en)]
pub enum DecodeError {
    /// No byte-order mark, and the bytes are neither UTF-8 nor Shift_JIS.
    Undetected {
        /// Where the reading that got further (`nearest`) stops.
        at: Place,
        /// [`Encoding::Utf8`] or [`Encoding::ShiftJis`], whichever read further (UTF-8 on a tie).
        nearest: Encoding,
    },
    /// The file starts with the byte-order mark of `encoding`, but what follows is not valid
    /// `encoding` (a UTF-16 file of an odd length, an unpaired surrogate, a stray byte after a
    /// UTF-8 BOM).
    AfterBom {
        /// The encoding the BOM names.
        encoding: Encoding,
        /// Where the text stops being valid.
        at: Place,
    },
    /// The text is not valid in the encoding named by the caller (`--encoding`).
    NotInNamed {
        /// The encoding named.
        encoding: Encoding,
        /// Where the text stops being valid.
        at: Place,
    },
    /// The bytes decode, but to a NUL character: a binary file (a PDF, an image, a program)
    /// that passed for text. No text file the students' editors write has one.
    Binary {
        /// Where the first NUL is.
        at: Place,
    },
}

impl DecodeError {
    /// Where the text stops being readable.
    #[must_use]
    pub fn place(&self) -> Place {
        match self {
            DecodeError::Undetected { at, .. }
            | DecodeError::AfterBom { at, .. }
            | DecodeError::NotInNamed { at, .. }
            | DecodeError::Binary { at } => *at,
        }
    }

    /// The message in both languages, for a command that has `--encoding`: what is wrong, where,
    /// and what to do (save the file as UTF-8, or name the encoding with `--encoding`).
    #[must_use]
    pub fn text(&self) -> Text {
        self.message(true)
    }

    /// [`DecodeError::text`] for a command without `--encoding` (`cg render`, `cg inspect`):
    /// the same, advising only to save the file as UTF-8.
    #[must_use]
    pub fn text_without_option(&self) -> Text {
        self.message(false)
    }

    fn message(&self, option: bool) -> Text {
        let save = Text::new(
            "エディタで文字コードを UTF-8 にして保存し直してください（名前を付けて保存 → エンコード: UTF-8）",
            "save the file as UTF-8 in your editor (Save As, Encoding: UTF-8)",
        );
        match self {
            DecodeError::Undetected { at, nearest } => {
                let at = at.text();
                let what = Text::new(
                    format!(
                        "UTF-8 としても Shift_JIS としても読めません。{nearest} として読むと {}が読めません",
                        at.ja
                    ),
                    format!(
                        "the text is neither UTF-8 nor Shift_JIS: read as {nearest}, {} cannot be read",
                        at.en
                    ),
                );
                if option {
                    Text::new(
                        format!(
                            "{}。{}。文字コードが分かっているときは `--encoding shift_jis` のように指定することもできます（utf-8・utf-16le・utf-16be・shift_jis）",
                            what.ja, save.ja
                        ),
                        format!(
                            "{}. {}, or name its encoding with `--encoding shift_jis` (or utf-8, utf-16le, utf-16be)",
                            what.en,
                            capitalized(&save.en)
                        ),
                    )
                } else {
                    Text::new(
                        format!("{}。{}", what.ja, save.ja),
                        format!("{}. {}", what.en, capitalized(&save.en)),
                    )
                }
            }
            DecodeError::AfterBom { encoding, at } => {
                let at = at.text();
                // `UTF-8 (BOM)` names the file's encoding; the mark itself is UTF-8's.
                let encoding = if encoding.is_utf8() { "UTF-8" } else { encoding.name() };
                Text::new(
                    format!(
                        "ファイルの先頭に {encoding} の BOM がありますが、{}が {encoding} として読めません。{}",
                        at.ja, save.ja
                    ),
                    format!(
                        "the file starts with a {encoding} byte-order mark, but {} is not valid {encoding}. {}",
                        at.en,
                        capitalized(&save.en)
                    ),
                )
            }
            DecodeError::Binary { at } => {
                let at = at.text();
                Text::new(
                    format!(
                        "テキストのファイルではありません: {}に NUL 文字（値が 0 のバイト）があります。PDF・画像・実行ファイルではなく、テキストのファイルを指定してください",
                        at.ja
                    ),
                    format!(
                        "not a text file: there is a NUL character (a zero byte) at {}. Give a text file, not a PDF, an image or a program",
                        at.en
                    ),
                )
            }
            DecodeError::NotInNamed { encoding, at } => {
                let at = at.text();
                Text::new(
                    format!(
                        "`--encoding` で指定された {encoding} として読めません（{}）。`--encoding` を付けなければ UTF-8・BOM 付き UTF-16・Shift_JIS を自動で判別します。または{}",
                        at.ja, save.ja
                    ),
                    format!(
                        "the file is not {encoding} as `--encoding` says: {} cannot be read. Leave out `--encoding` to let the kit tell UTF-8, UTF-16 with a BOM and Shift_JIS apart, or {}",
                        at.en, save.en
                    ),
                )
            }
        }
    }
}

fn capitalized(s: &str) -> String {
    let mut chars = s.chars();
    chars.next().map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}

/// A text file that could not be read. Each variant has one message in Japanese and English
/// ([`ReadError::text`]); the caller names the file.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}", self.text().en)]
pub enum ReadError {
    /// The operating system refused (no such file, no permission, a folder).
    Io {
        /// The operating system's reason ([`Text::io`]).
        reason: Text,
    },
    /// The file is larger than [`MAX_TEXT_BYTES`]; nothing past the limit was read.
    TooLarge {
        /// Its size in bytes, when the file system says (not for a pipe).
        size: Option<u64>,
        /// The limit it is over, in bytes ([`MAX_TEXT_BYTES`] for [`read`]).
        limit: u64,
    },
    /// The bytes are not text in an encoding the kit reads.
    Decode(DecodeError),
}

impl ReadError {
    /// The message in both languages, for a command that has `--encoding`.
    #[must_use]
    pub fn text(&self) -> Text {
        self.message(true)
    }

    /// The message in both languages, for a command without `--encoding` (see
    /// [`DecodeError::text_without_option`]).
    #[must_use]
    pub fn text_without_option(&self) -> Text {
        self.message(false)
    }

    /// Where the text stops being readable, when it is the encoding that is wrong.
    #[must_use]
    pub fn place(&self) -> Option<Place> {
        match self {
            ReadError::Decode(e) => Some(e.place()),
            ReadError::Io { .. } | ReadError::TooLarge { .. } => None,
        }
    }

    fn message(&self, option: bool) -> Text {
        match self {
            ReadError::Io { reason } => Text::new(
                format!("読めません（{}）", reason.ja),
                format!("cannot be read ({})", reason.en),
            ),
            ReadError::TooLarge { size, limit } => {
                let (ja, en) = size.map_or_else(
                    || (String::new(), String::new()),
                    |n| (format!("（{n} バイト）"), format!(" ({n} bytes)")),
                );
                // The limit it was read with: 64 MiB for a text file, less for a report.
                let (max_ja, max_en) = match *limit {
                    n if n % (1 << 20) == 0 => {
                        (format!("{} MiB", n >> 20), format!("{} MiB", n >> 20))
                    }
                    n if n % (1 << 10) == 0 => {
                        (format!("{} KiB", n >> 10), format!("{} KiB", n >> 10))
                    }
                    n => (format!("{n} バイト"), format!("{n} bytes")),
                };
                Text::new(
                    format!(
                        "ファイルが {max_ja} を超えていて{ja}、テキストファイルとしては大きすぎます。指定したファイルが正しいか確かめてください"
                    ),
                    format!(
                        "the file is larger than {max_en}{en}, too large for a text file: check that you named the right file"
                    ),
                )
            }
            ReadError::Decode(e) => e.message(option),
        }
    }
}

impl From<DecodeError> for ReadError {
    fn from(e: DecodeError) -> ReadError {
        ReadError::Decode(e)
    }
}

/// `c` as an ASCII digit when it is a full-width one (`１` → `1`, what a Japanese input method
/// types), else `c` itself.
#[must_use]
pub fn ascii_digit(c: char) -> char {
    match c {
        '０'..='９' => char::from_digit(u32::from(c) - u32::from('０'), 10).unwrap_or(c),
        _ => c,
    }
}

/// Decodes a text file's bytes: in `forced` when given (a BOM of that encoding is removed),
/// else in the encoding detected as the module documentation says. Returns the text, without a
/// BOM and with its line endings as they were, and the encoding it was read in
/// ([`Encoding::Utf8Bom`] for UTF-8 that started with a BOM).
///
/// # Errors
/// A [`DecodeError`] naming the line, column and byte offset of the first byte that cannot be
/// read.
pub fn decode(bytes: &[u8], forced: Option<Encoding>) -> Result<(String, Encoding), DecodeError> {
    decode_cow(Cow::Borrowed(bytes), forced)
}

/// Reads a text file of at most [`MAX_TEXT_BYTES`] and [`decode`]s it. A larger file is refused
/// without reading (or allocating) more than the limit.
///
/// # Errors
/// The file cannot be opened or read, is too large, or is not text ([`ReadError`]).
pub fn read(path: &Path, forced: Option<Encoding>) -> Result<(String, Encoding), ReadError> {
    let bytes = read_bounded(path, MAX_TEXT_BYTES)?;
    Ok(decode_cow(Cow::Owned(bytes), forced)?)
}

/// The file's bytes, refusing more than `limit` ([`ReadError::TooLarge`], checked against the
/// file's size before reading when the file system gives one); the buffer never grows past
/// `limit`, so `/dev/zero` or a pipe cannot fill the memory.
///
/// # Errors
/// The file cannot be opened or read ([`ReadError::Io`]), or is larger than `limit`.
pub fn read_bounded(path: &Path, limit: u64) -> Result<Vec<u8>, ReadError> {
    let io = |e: std::io::Error| ReadError::Io { reason: Text::io(&e) };
    let mut file = open_waiting(path)?;
    let size = file.metadata().ok().filter(std::fs::Metadata::is_file).map(|m| m.len());
    if let Some(size) = size
        && size > limit
    {
        return Err(ReadError::TooLarge { size: Some(size), limit });
    }
    let max = usize::try_from(limit).unwrap_or(usize::MAX);
    let expected = size.and_then(|n| usize::try_from(n).ok()).unwrap_or(0);
    let mut bytes = Vec::with_capacity(expected.min(max));
    let mut chunk = vec![0u8; 64 << 10];
    loop {
        let n = match file.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(io(e)),
        };
        if bytes.len() + n > max {
            return Err(ReadError::TooLarge { size, limit });
        }
        if bytes.capacity() - bytes.len() < n {
            let grown = bytes.capacity().saturating_mul(2).max(bytes.len() + n).min(max);
            bytes.reserve_exact(grown - bytes.len());
        }
        bytes.extend_from_slice(&chunk[..n]);
    }
    Ok(bytes)
}

/// How long [`read_bounded`] waits for a named pipe to be opened for writing.
pub const PIPE_WAIT: std::time::Duration = std::time::Duration::from_secs(5);

/// `path` opened for reading. A named pipe (`mkfifo`) opens only once something opens it for
/// writing, which may be never: it is opened on a thread of its own and given up after
/// [`PIPE_WAIT`] (the thread stays blocked until the process ends). A pipe that is written
/// (`<(command)`) opens at once.
fn open_waiting(path: &Path) -> Result<std::fs::File, ReadError> {
    let io = |e: std::io::Error| ReadError::Io { reason: Text::io(&e) };
    #[cfg(unix)]
    {
        // platform: named pipes whose opening blocks are Unix's.
        use std::os::unix::fs::FileTypeExt as _;
        if std::fs::metadata(path).is_ok_and(|m| m.file_type().is_fifo()) {
            let (send, receive) = std::sync::mpsc::channel();
            let owned = path.to_path_buf();
            std::thread::spawn(move || {
                let _ = send.send(std::fs::File::open(owned));
            });
            return match receive.recv_timeout(PIPE_WAIT) {
                Ok(opened) => opened.map_err(io),
                Err(_) => Err(ReadError::Io {
                    reason: Text::new(
                        format!(
                            "名前付きパイプで、{} 秒待っても書き込む側が開きません",
                            PIPE_WAIT.as_secs()
                        ),
                        format!(
                            "a named pipe that nothing opened for writing in {} s",
                            PIPE_WAIT.as_secs()
                        ),
                    ),
                }),
            };
        }
    }
    std::fs::File::open(path).map_err(io)
}

fn decode_cow(
    bytes: Cow<'_, [u8]>,
    forced: Option<Encoding>,
) -> Result<(String, Encoding), DecodeError> {
    // The first zero byte, before the bytes are taken: where a NUL is in UTF-8 or Shift_JIS
    // (whose trail bytes are never zero).
    let zero = bytes.iter().position(|&b| b == 0);
    let utf16_bom =
        bytes.starts_with(Encoding::Utf16Le.bom()) || bytes.starts_with(Encoding::Utf16Be.bom());
    let (text, encoding) = decode_detected(bytes, forced)?;
    let Some(i) = zero.and_then(|_| text.find('\0')) else {
        return Ok((text, encoding));
    };
    let offset = if matches!(encoding, Encoding::Utf16Le | Encoding::Utf16Be) {
        2 * text[..i].encode_utf16().count() + if utf16_bom { 2 } else { 0 }
    } else {
        zero.unwrap_or(i)
    };
    Err(DecodeError::Binary { at: Place::after(&text[..i], offset) })
}

fn decode_detected(
    bytes: Cow<'_, [u8]>,
    forced: Option<Encoding>,
) -> Result<(String, Encoding), DecodeError> {
    if let Some(encoding) = forced {
        let bom = encoding.bom();
        let skip = if bytes.starts_with(bom) { bom.len() } else { 0 };
        let read_as = if encoding.is_utf8() && skip > 0 {
            Encoding::Utf8Bom
        } else if encoding.is_utf8() {
            Encoding::Utf8
        } else {
            encoding
        };
        return decode_as(bytes, skip, read_as)
            .map(|text| (text, read_as))
            .map_err(|at| DecodeError::NotInNamed { encoding, at });
    }
    for encoding in [Encoding::Utf8Bom, Encoding::Utf16Le, Encoding::Utf16Be] {
        let bom = encoding.bom();
        if bytes.starts_with(bom) {
            return decode_as(bytes, bom.len(), encoding)
                .map(|text| (text, encoding))
                .map_err(|at| DecodeError::AfterBom { encoding, at });
        }
    }
    if let Some(encoding) = utf16_without_bom(&bytes) {
        return decode_as(bytes, 0, encoding)
            .map(|text| (text, encoding))
            .map_err(|at| DecodeError::Undetected { at, nearest: encoding });
    }
    let not_utf8 = match std::str::from_utf8(&bytes) {
        Ok(_) => None,
        Err(e) => Some(e.valid_up_to()),
    };
    let Some(valid_up_to) = not_utf8 else {
        return decode_as(bytes, 0, Encoding::Utf8)
            .map(|text| (text, Encoding::Utf8))
            .map_err(|at| DecodeError::Undetected { at, nearest: Encoding::Utf8 });
    };
    match decode_with(Encoding::ShiftJis.decoder(), &bytes, 0) {
        Ok(text) => Ok((text, Encoding::ShiftJis)),
        Err(sjis) if sjis.offset > valid_up_to => {
            Err(DecodeError::Undetected { at: sjis, nearest: Encoding::ShiftJis })
        }
        Err(_) => {
            let prefix = std::str::from_utf8(&bytes[..valid_up_to]).unwrap_or_default();
            Err(DecodeError::Undetected {
                at: Place::after(prefix, valid_up_to),
                nearest: Encoding::Utf8,
            })
        }
    }
}

/// UTF-16 without a BOM, by its zero bytes and by reading it: an even number of bytes, and,
/// among the first 4,096 code units, at least a quarter with a zero high byte (ASCII and
/// Latin-1: digits, spaces, line ends, Markdown) — the second byte of each pair for
/// little-endian, the first for big-endian — and those units read in that byte order as text:
/// no unpaired surrogate, no control character but the tab, the line ends and the form feed,
/// no noncharacter U+FFFE or U+FFFF (a byte-swapped BOM), and no U+0A00 (a byte-swapped line
/// end). Of the two byte orders, the one with more zero bytes in ASCII's place is tried first.
///
/// Characters whose code unit has a zero *low* byte — 一 (U+4E00), 最 (U+6700), 言 (U+8A00),
/// the ideographic space U+3000 — put zero bytes in the other place too: they do not stop the
/// detection, the reading decides. Text that is UTF-8 or Shift_JIS has no zero bytes at all, so
/// neither is taken for UTF-16; a binary file's zero bytes read as control characters (`00 00`
/// is U+0000) or broken surrogates. UTF-16 text with little ASCII in it (under a quarter of its
/// characters) is not recognised (then `--encoding utf-16le` names it).
#[must_use]
pub fn utf16_without_bom(bytes: &[u8]) -> Option<Encoding> {
    const SAMPLE: usize = 4096;
    if bytes.len() < 2 || !bytes.len().is_multiple_of(2) {
        return None;
    }
    let pairs: Vec<[u8; 2]> = bytes.chunks_exact(2).take(SAMPLE).map(|c| [c[0], c[1]]).collect();
    let zeros = |k: usize| pairs.iter().filter(|p| p[k] == 0).count();
    // ASCII's zero high byte is the second of a little-endian pair, the first of a big-endian.
    let mut orders = [(Encoding::Utf16Le, zeros(1)), (Encoding::Utf16Be, zeros(0))];
    orders.sort_by_key(|&(_, ascii)| std::cmp::Reverse(ascii));
    let truncated = bytes.len() / 2 > pairs.len();
    orders.into_iter().find_map(|(encoding, ascii)| {
        (ascii * 4 >= pairs.len() && reads_as_text(&pairs, encoding, truncated)).then_some(encoding)
    })
}

/// Whether the code units `pairs`, in `encoding`'s byte order, are text (see
/// [`utf16_without_bom`]); when `truncated` (the sample of a longer file), a high surrogate at
/// the end is the first half of a pair cut by the sample.
fn reads_as_text(pairs: &[[u8; 2]], encoding: Encoding, truncated: bool) -> bool {
    let unit = |p: &[u8; 2]| match encoding {
        Encoding::Utf16Be => u16::from_be_bytes(*p),
        _ => u16::from_le_bytes(*p),
    };
    let mut units: Vec<u16> = pairs.iter().map(unit).collect();
    if truncated && units.last().is_some_and(|u| (0xD800..0xDC00).contains(u)) {
        units.pop();
    }
    char::decode_utf16(units).all(|c| match c {
        Ok('\t' | '\n' | '\r' | '\u{c}') => true,
        // A byte-swapped BOM, the other noncharacter, a byte-swapped line end; a surrogate
        // without its pair.
        Ok('\u{FFFE}' | '\u{FFFF}' | '\u{0A00}') | Err(_) => false,
        Ok(c) => !c.is_control(),
    })
}

/// `bytes[skip..]` decoded as `encoding`; the place of the first byte that is not.
fn decode_as(bytes: Cow<'_, [u8]>, skip: usize, encoding: Encoding) -> Result<String, Place> {
    if !encoding.is_utf8() {
        return decode_with(encoding.decoder(), &bytes, skip);
    }
    let utf8_error = |valid_up_to: usize, body: &[u8]| {
        let prefix = std::str::from_utf8(&body[..valid_up_to]).unwrap_or_default();
        Place::after(prefix, skip + valid_up_to)
    };
    match bytes {
        // The file's own buffer becomes the string: no copy.
        Cow::Owned(mut v) => {
            v.drain(..skip);
            String::from_utf8(v).map_err(|e| utf8_error(e.utf8_error().valid_up_to(), e.as_bytes()))
        }
        Cow::Borrowed(b) => std::str::from_utf8(&b[skip..])
            .map(str::to_owned)
            .map_err(|e| utf8_error(e.valid_up_to(), &b[skip..])),
    }
}

/// `bytes[skip..]` decoded by `encoding_rs` without replacement characters; the place of the
/// first malformed sequence (line and column counted in the text decoded before it).
fn decode_with(
    encoding: &'static encoding_rs::Encoding,
    bytes: &[u8],
    skip: usize,
) -> Result<String, Place> {
    let body = &bytes[skip..];
    let mut decoder = encoding.new_decoder_without_bom_handling();
    let mut text = String::with_capacity(
        decoder.max_utf8_buffer_length_without_replacement(body.len()).unwrap_or(body.len()),
    );
    let mut done = 0;
    loop {
        let (result, read) =
            decoder.decode_to_string_without_replacement(&body[done..], &mut text, true);
        done += read;
        match result {
            encoding_rs::DecoderResult::InputEmpty => return Ok(text),
            encoding_rs::DecoderResult::OutputFull => {
                let rest = body.len() - done;
                text.reserve(
                    decoder.max_utf8_buffer_length_without_replacement(rest).unwrap_or(rest).max(4),
                );
            }
            encoding_rs::DecoderResult::Malformed(bad, after) => {
                let start = done.saturating_sub(usize::from(bad) + usize::from(after));
                return Err(Place::after(&text, skip + start));
            }
        }
    }
}

#[cfg(test)]
mod tests;
