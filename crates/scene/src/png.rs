//! PNG files via the image crate: textures are read as RGBA8 and flipped so row 0 is the bottom
//! row; rendered images are written as RGBA8, row 0 at the top.

use std::io::Cursor;
use std::path::Path;

use cg_core::image::{Image, to_unorm8};
use cg_core::texture::Texture;

use crate::error::{ErrorKind, SceneError};

/// The eight bytes every PNG file starts with.
const PNG_SIGNATURE: &[u8; 8] = b"\x89PNG\r\n\x1a\n";

/// Decodes a PNG file's bytes; `path` names it in errors. See [`crate::load_texture`].
pub(crate) fn decode_png(bytes: &[u8], path: &Path) -> Result<Texture, SceneError> {
    let error = |kind| SceneError::in_file(path, kind);
    if !bytes.starts_with(PNG_SIGNATURE) {
        return Err(error(ErrorKind::NotPng));
    }
    // The size from the header, before anything is decoded or allocated.
    if let Some((width, height)) = header_size(bytes) {
        if width > crate::MAX_TEXTURE_SIDE || height > crate::MAX_TEXTURE_SIDE {
            return Err(error(ErrorKind::PngTooLarge { width, height }));
        }
        // A side of 0 is not allowed by PNG itself (the decoder calls it a format error): said
        // as what it is, an image without texels.
        if width == 0 || height == 0 {
            let e = cg_core::texture::TextureError::ZeroSize { width, height };
            return Err(error(ErrorKind::Texture(e)));
        }
    }
    let mut reader = image::ImageReader::with_format(Cursor::new(bytes), image::ImageFormat::Png);
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(crate::MAX_TEXTURE_SIDE);
    limits.max_image_height = Some(crate::MAX_TEXTURE_SIDE);
    limits.max_alloc = Some(crate::MAX_TEXTURE_BYTES * 2);
    reader.limits(limits);
    let image = reader
        .decode()
        .map_err(|e| match (&e, header_size(bytes)) {
            // The decoder refuses to allocate it: the file may be fine, it is just too large
            // to be a texture.
            (image::ImageError::Limits(_), Some((width, height))) => {
                error(ErrorKind::PngTooLarge { width, height })
            }
            _ => error(ErrorKind::Png { reason: reason(&e) }),
        })?
        .to_rgba8();
    let (width, height) = image.dimensions();
    // PNG rows run top to bottom; a texture's row 0 is the bottom one (OpenGL's (0, 0)).
    let texels = image.rows().rev().flat_map(|row| row.map(|p| p.0)).collect();
    Texture::new(width, height, texels).map_err(|e| error(ErrorKind::Texture(e)))
}

/// The decoder's message as a sentence: the image crate writes a chunk's type as Rust's debug
/// form (`ChunkType { type: IHDR, critical: true, private: false, reserved: false, safe: false }`),
/// which becomes its four letters. The type is the file's own four bytes, which may hold `}` or
/// `,` themselves (`\u{1a}`): the form's end is found after its `critical` field.
fn reason(e: &image::ImageError) -> String {
    let mut text = e.to_string();
    let mut from = 0;
    while let Some(start) = text[from..].find("ChunkType { type: ").map(|i| from + i) {
        let name_at = start + "ChunkType { type: ".len();
        let Some(fields) = text[name_at..].find(", critical: ").map(|i| name_at + i) else {
            break;
        };
        let end = text[fields..].find('}').map_or(text.len(), |i| fields + i + 1);
        let name = text[name_at..fields].to_owned();
        text.replace_range(start..end, &name);
        from = start + name.len();
    }
    cg_core::quote::visible(&text)
}

/// Width and height from the PNG header (the IHDR chunk, which must come first), if present.
fn header_size(bytes: &[u8]) -> Option<(u32, u32)> {
    if bytes.get(12..16)? != b"IHDR" {
        return None;
    }
    let be = |at: usize| Some(u32::from_be_bytes(bytes.get(at..at + 4)?.try_into().ok()?));
    Some((be(16)?, be(20)?))
}

/// Writes a rendered image as an 8-bit RGBA PNG. See [`crate::save_png`].
pub(crate) fn save_png(path: &Path, image: &Image) -> Result<(), SceneError> {
    // One 8-bit copy, written straight from the colours (not `to_rgba8` and then a flattened
    // second copy): 4 bytes a pixel beside the image.
    let bytes: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|c| [to_unorm8(c.x), to_unorm8(c.y), to_unorm8(c.z), 255])
        .collect();
    // Encoded in memory, then written with one call whose every error is seen: the image
    // crate's own `save_buffer` writes through a buffer whose last flush happens on drop, where
    // an error (a full disk, /dev/full) is lost and a small image "succeeds".
    let mut encoded = Vec::new();
    image::ImageEncoder::write_image(
        image::codecs::png::PngEncoder::new(&mut encoded),
        &bytes,
        image.width,
        image.height,
        image::ExtendedColorType::Rgba8,
    )
    .map_err(|e| {
        let reason =
            cg_core::lang::Text::new(format!("PNG に変換できません（{e}）"), e.to_string());
        SceneError::in_file(path, ErrorKind::Write { reason })
    })?;
    // A failed write (a full disk) keeps the picture that was there.
    cg_core::fs::write_atomic(path, &encoded).map_err(|e| {
        SceneError::in_file(path, ErrorKind::Write { reason: cg_core::lang::Text::io(&e) })
    })
}
