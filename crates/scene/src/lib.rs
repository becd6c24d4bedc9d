//! # cg-scene — the kit's scene format and file loading
//!
//! A scene is a TOML file (the format is documented, key by key, in `docs/scene-format.md`;
//! `assets/scenes/course-sample.toml` is the course's sample program). [`load`] reads one into a
//! [`cg_core::scene::Scene`]; [`load_obj`] and [`load_texture`] read the OBJ models and PNG
//! textures it refers to.
//!
//! Every mistake is a [`SceneError`] that names the file, the line and column and the key:
//!
//! ```text
//! assets/scenes/x.toml:23:9: objects[1].shape.radius: must be finite and > 0, got -1
//! ```
//!
//! in English (`Display`) or Japanese ([`SceneError::describe`] with [`cg_core::lang::Lang::Ja`]).
//! Nothing here panics on a file's contents.
//!
//! ```
//! let scene = cg_scene::parse(
//!     r#"
//! format = 1
//! [[objects]]
//! name = "ground"
//! shape = { kind = "grid", divisions = 10, size = 10.0 }
//! "#,
//!     std::path::Path::new("inline.toml"),
//! )
//! .unwrap();
//! assert_eq!(scene.objects[0].mesh.face_count(), 200);
//! assert_eq!(scene.width, 640); // left out: the course's values
//! ```

mod error;
mod format;
mod obj;
mod png;
mod reader;
mod shape;

use std::path::Path;

use cg_core::image::Image;
use cg_core::mesh::Mesh;
use cg_core::scene::Scene;
use cg_core::texture::Texture;

pub use error::{ErrorKind, Expected, Found, Position, Rule, SceneError};
pub use shape::{MAX_SHAPE_FACES, ShapeSpec};

/// The version of the scene format this crate reads (`format = 1`).
pub const FORMAT_VERSION: i64 = format::FORMAT_VERSION;

/// Reads a scene file, and the OBJ and PNG files it names (relative to the scene file's folder).
///
/// # Errors
/// A [`SceneError`] for the first problem found: the file cannot be read, is not TOML, has an
/// unknown key, a wrong type, a value out of range (including a camera or projection that
/// `cg_core::transform::look_at` or `perspective` refuses, and a shape with more than
/// [`MAX_SHAPE_FACES`] faces), an unknown material, or names a file that cannot be loaded.
///
/// See also [`parse`] for text already in memory.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    let text = read_text(path)?;
    parse(&text, path)
}

/// Reads a scene from `text`. `path` names the file in errors, and relative file names in the
/// scene (`mesh`, `texture.image`) start from its folder.
///
/// # Errors
/// As [`load`], except for reading the scene file itself.
pub fn parse(text: &str, path: &Path) -> Result<Scene, SceneError> {
    let src = reader::Source { text, file: path };
    let base = path.parent().unwrap_or(Path::new(""));
    format::read(&src, base)?.build(&src)
}

/// Reads a Wavefront OBJ model into one mesh: every group (`o`, `g`) merged, polygons split into
/// triangles (fans), points and 2-point lines dropped. Vertex `Vi` is the file's `v` line `i + 1`
/// when each position is used with one `vt`/`vn` pair and every `v` line is used (as in the
/// course's models); otherwise vertices follow the file's `v` order, with a position used with
/// several `vt`/`vn` pairs split into several vertices. Normals (unit length after loading) and
/// texture coordinates are kept when every face corner has them. The `.mtl` file is not read:
/// materials come from the scene.
///
/// # Errors
/// The file cannot be read; a line is malformed (a word that is not a number, too few
/// coordinates, a face corner that is not `v`, `v/vt`, `v//vn` or `v/vt/vn`, a position at
/// infinity); a face index is 0 or refers to an element not defined on the lines before the face
/// — each of these naming the line and column; the file has no faces; some corners have `vn` or
/// `vt` and others do not; or a normal or texture coordinate is not usable (zero or non-finite).
pub fn load_obj(path: &Path) -> Result<Mesh, SceneError> {
    parse_obj(&read_text(path)?, path)
}

/// [`load_obj`] for OBJ text already in memory; `path` names it in errors.
///
/// # Errors
/// As [`load_obj`], except for reading the file.
pub fn parse_obj(text: &str, path: &Path) -> Result<Mesh, SceneError> {
    obj::parse_obj(text, path)
}

/// Reads a PNG image as a texture: converted to RGBA8, rows flipped so row 0 is the image's
/// bottom row (texture coordinate `(0, 0)` is the bottom-left corner, as in OpenGL).
///
/// # Errors
/// The file cannot be read, is not a PNG ([`ErrorKind::NotPng`]), is larger than the decoder
/// will allocate ([`ErrorKind::PngTooLarge`], naming its size), or is corrupt or truncated
/// ([`ErrorKind::Png`]).
pub fn load_texture(path: &Path) -> Result<Texture, SceneError> {
    let bytes = std::fs::read(path).map_err(|e| read_error(path, &e))?;
    decode_png(&bytes, path)
}

/// [`load_texture`] for PNG bytes already in memory; `path` names them in errors.
///
/// # Errors
/// As [`load_texture`], except for reading the file.
pub fn decode_png(bytes: &[u8], path: &Path) -> Result<Texture, SceneError> {
    png::decode_png(bytes, path)
}

/// Writes a rendered [`Image`] to `path` as an 8-bit RGBA PNG (row 0 at the top; colours clamped
/// to `[0, 1]` and rounded as OpenGL does, see [`cg_core::image::to_unorm8`]).
///
/// # Errors
/// The file cannot be created or written; the error names the file and says why.
pub fn save_png(path: &Path, image: &Image) -> Result<(), SceneError> {
    png::save_png(path, image)
}

fn read_error(path: &Path, e: &std::io::Error) -> SceneError {
    SceneError::in_file(path, ErrorKind::Read { reason: e.to_string() })
}

/// A text file's contents (UTF-8).
fn read_text(path: &Path) -> Result<String, SceneError> {
    std::fs::read_to_string(path).map_err(|e| read_error(path, &e))
}
