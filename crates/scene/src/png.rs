//! PNG textures via the image crate, converted to RGBA8 and flipped so row 0 is the bottom row.

use std::path::Path;

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
    let image = image::load_from_memory_with_format(bytes, image::ImageFormat::Png)
        .map_err(|e| error(ErrorKind::Png { reason: e.to_string() }))?
        .to_rgba8();
    let (width, height) = image.dimensions();
    // PNG rows run top to bottom; a texture's row 0 is the bottom one (OpenGL's (0, 0)).
    let texels = image.rows().rev().flat_map(|row| row.map(|p| p.0)).collect();
    Texture::new(width, height, texels).map_err(|e| error(ErrorKind::Texture(e)))
}
