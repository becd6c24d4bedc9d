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
mod limits;
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
pub use format::MAX_NAME_CHARS;
pub use limits::{
    LimitError, MAX_COORDINATE, MAX_DEPTH_RATIO, MAX_FOVY_DEG, MAX_POINT_LIGHTS, MAX_SCENE_FACES,
    MIN_FOVY_DEG, MIN_NEAR, Matrix, WorldPoint,
};
pub use obj::polygon::{MAX_CONCAVE_CORNERS, PolygonProblem};
pub use shape::{MAX_SHAPE_FACES, ShapeSpec};

/// The version of the scene format this crate reads (`format = 1`).
pub const FORMAT_VERSION: i64 = format::FORMAT_VERSION;

/// Reads a scene file, and the OBJ and PNG files it names (relative to the scene file's folder).
///
/// # Errors
/// A [`SceneError`] for the first problem found: the file cannot be read, is not TOML, has an
/// unknown key, a wrong type, a value out of range (including a camera or projection that
/// `cg_core::transform::look_at` or `perspective` refuses, and a shape with more than
/// [`MAX_SHAPE_FACES`] faces), an unknown material, or names a file that cannot be loaded; or a
/// scene beyond the limits that keep it drawable, and drawn alike, by every renderer
/// ([`ErrorKind::Limit`]): a point beyond [`MAX_COORDINATE`] in world space, a transform whose
/// product overflows f32 (at the step), `fovy_deg` outside [[`MIN_FOVY_DEG`], [`MAX_FOVY_DEG`]],
/// `near` below [`MIN_NEAR`], `far / near` above [`MAX_DEPTH_RATIO`], more than
/// [`MAX_SCENE_FACES`] faces or [`MAX_POINT_LIGHTS`] point lights in all (an area light counting its samples).
///
/// See also [`parse`] for text already in memory.
pub fn load(path: &Path) -> Result<Scene, SceneError> {
    load_encoded(path, None)
}

/// [`load`] with the scene file read in `encoding` when given (`--encoding` of `cg render` and
/// `cg inspect`), else in the encoding detected. The OBJ files it names are detected as always.
///
/// # Errors
/// As [`load`]; a file that is not text in `encoding` names the line and column.
pub fn load_encoded(
    path: &Path,
    encoding: Option<cg_core::text::Encoding>,
) -> Result<Scene, SceneError> {
    let text = read_text(path, encoding, true)?;
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
    let doc = format::parse_document(&src)?;
    let root = reader::Table::root(&src, &doc);
    let spec = format::read_root(&src, &root, base)?;
    limits::check_spec(&spec, &root)?;
    let scene = spec.build(&src)?;
    limits::check_scene(&scene, &root)?;
    Ok(scene)
}

/// Reads a Wavefront OBJ model into one mesh: every group (`o`, `g`) merged, polygons split into
/// triangles (the fan from the first corner where it covers the polygon exactly, as tobj and
/// OpenGL split a convex one; ear clipping in the polygon's plane where the fan would fold a
/// concave one), points and 2-point lines dropped. Vertex `Vi` is the file's `v` line `i + 1`
/// when each position is used with one `vt`/`vn` pair and every `v` line is used (as in the
/// course's models); otherwise vertices follow the file's `v` order, with a position used with
/// several `vt`/`vn` pairs split into several vertices. Normals (unit length after loading) and
/// texture coordinates are kept when every face corner has them; vertex colours
/// (`v x y z r g b`, on some `v` lines or all) are read and ignored. The `.mtl` file is not read:
/// materials come from the scene.
///
/// # Errors
/// The file cannot be read; a line is malformed (a word that is not a number, too few
/// coordinates, a face corner that is not `v`, `v/vt`, `v//vn` or `v/vt/vn`, a position at
/// infinity); a face index is 0 or refers to an element not defined on the lines before the face;
/// a face's corners are not written alike (`f 1//1 2//2 3`) or use one `v` twice
/// (`f 1 2 3 4 1 2 3 4`) — each of these naming the line and column; a face of four or more corners that crosses itself,
/// or is concave with more than [`MAX_CONCAVE_CORNERS`] corners (naming its line and column); the
/// file has no faces; some corners have `vn` or
/// `vt` and others do not; or a normal or texture coordinate is not usable (zero or non-finite).
pub fn load_obj(path: &Path) -> Result<Mesh, SceneError> {
    parse_obj(&read_text(path, None, false)?, path)
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
/// The file cannot be read or is larger than [`MAX_PNG_FILE_BYTES`] ([`ErrorKind::FileTooLarge`]),
/// is not a PNG ([`ErrorKind::NotPng`]), is larger than [`MAX_TEXTURE_SIDE`] either way or
/// decodes to more than [`MAX_TEXTURE_BYTES`] ([`ErrorKind::PngTooLarge`], naming its size), or
/// is corrupt or truncated ([`ErrorKind::Png`]).
pub fn load_texture(path: &Path) -> Result<Texture, SceneError> {
    let bytes = cg_core::text::read_bounded(path, MAX_PNG_FILE_BYTES).map_err(|e| match e {
        cg_core::text::ReadError::TooLarge { size, limit } => {
            SceneError::in_file(path, ErrorKind::FileTooLarge { size, limit_mib: limit >> 20 })
        }
        cg_core::text::ReadError::Io { reason } => {
            SceneError::in_file(path, ErrorKind::Read { reason })
        }
        e => SceneError::in_file(path, ErrorKind::Read { reason: e.text() }),
    })?;
    decode_png(&bytes, path)
}

/// The largest PNG file read as a texture: 64 MiB (checked before reading; a texture the
/// course uses is a few hundred KiB).
pub const MAX_PNG_FILE_BYTES: u64 = 64 << 20;
/// The widest and highest texture: 8192 pixels, as OpenGL's `GL_MAX_TEXTURE_SIZE` on most
/// hardware (checked from the PNG header before decoding).
pub const MAX_TEXTURE_SIDE: u32 = 8192;
/// The most bytes a PNG may decode to: one 8192 × 8192 RGBA8 image.
pub const MAX_TEXTURE_BYTES: u64 = 8192 * 8192 * 4;

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

/// A text file's contents, in `forced` or in the encoding a student's editor wrote it in: UTF-8
/// (a BOM removed), UTF-16 or Shift_JIS ([`cg_core::text::read`]; at most 64 MiB). Line endings
/// are kept: the TOML parser and the OBJ scan both take `\r\n`.
///
/// A file that is not text in any of these is an [`ErrorKind::Encoding`] at the line and column
/// where it stops being readable, in English and Japanese, with the advice to save it as UTF-8,
/// or (`option`: a scene file, for `cg render` and `cg inspect` take `--encoding`) to name its
/// encoding.
fn read_text(
    path: &Path,
    forced: Option<cg_core::text::Encoding>,
    option: bool,
) -> Result<String, SceneError> {
    use cg_core::text::ReadError;
    match cg_core::text::read(path, forced) {
        Ok((text, _)) => Ok(text),
        Err(ReadError::Io { reason }) => Err(SceneError::in_file(path, ErrorKind::Read { reason })),
        Err(e) => Err(SceneError {
            position: e.place().map(|p| Position { line: p.line, column: p.column }),
            ..SceneError::in_file(
                path,
                ErrorKind::Encoding {
                    why: if option { e.text() } else { e.text_without_option() },
                },
            )
        }),
    }
}

#[cfg(test)]
mod encoding_tests {
    //! Scenes and OBJ models saved by students' editors: Shift_JIS, UTF-16 and UTF-8 with a BOM,
    //! CRLF line endings, under Japanese folder and file names with spaces.

    use std::path::{Path, PathBuf};

    use cg_core::lang::Lang;

    use super::{ErrorKind, Position, load, load_encoded, load_obj};

    /// `# 三角形のシーン` in Shift_JIS (CP932).
    const SJIS_COMMENT: &[u8] = b"# \x8eO\x8ap\x8c`\x82\xcc\x83V\x81[\x83\x93";

    /// A fresh folder `山田 太郎` under a scratch folder of this test.
    fn student_folder(name: &str) -> PathBuf {
        cg_testkit::student_folder("cg-scene-encoding", name)
    }

    fn remove(dir: &Path) {
        cg_testkit::remove_student_folder(dir);
    }

    fn utf16le(s: &str) -> Vec<u8> {
        let mut out = vec![0xFF, 0xFE];
        out.extend(s.encode_utf16().flat_map(u16::to_le_bytes));
        out
    }

    const OBJ: &str = "# 三角形\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3\r\n";

    #[test]
    fn a_shift_jis_scene_with_crlf_names_a_utf16_model_under_a_japanese_path() {
        let dir = student_folder("scene");
        std::fs::write(dir.join("モデル 1.obj"), utf16le(OBJ)).unwrap();
        let mut scene = SJIS_COMMENT.to_vec();
        scene.extend_from_slice(
            b"\r\nformat = 1\r\n[[objects]]\r\nname = \"tri\"\r\nmesh = \"\x83\x82\x83f\x83\x8b 1.obj\"\r\n",
        );
        let path = dir.join("シーン 1.toml");
        std::fs::write(&path, &scene).unwrap();
        let loaded = load(&path).unwrap();
        assert_eq!(loaded.objects[0].mesh.face_count(), 1);
        assert_eq!(loaded.objects[0].mesh.vertex_count(), 3);

        // The same scene in UTF-8 with a BOM, the model in UTF-8 with CRLF.
        let mut bom = b"\xEF\xBB\xBF".to_vec();
        bom.extend_from_slice(
            "# 三角形のシーン\r\nformat = 1\r\n[[objects]]\r\nname = \"tri\"\r\nmesh = \"モデル 1.obj\"\r\n"
                .as_bytes(),
        );
        std::fs::write(&path, bom).unwrap();
        std::fs::write(dir.join("モデル 1.obj"), OBJ).unwrap();
        assert_eq!(load(&path).unwrap().objects[0].mesh.face_count(), 1);
        remove(&dir);
    }

    /// A CRLF scene's mistakes are still named at the right line and column.
    #[test]
    fn crlf_keeps_lines_and_columns() {
        let dir = student_folder("crlf");
        let path = dir.join("シーン.toml");
        std::fs::write(&path, "format = 1\r\n[window]\r\nwidht = 3\r\n").unwrap();
        let e = load(&path).unwrap_err();
        assert_eq!(e.position, Some(Position { line: 3, column: 1 }), "{e}");
        remove(&dir);
    }

    /// Latin-1 is neither UTF-8 nor Shift_JIS: the place, and advice: for an OBJ file without
    /// `--encoding` (it is read as detected), for a scene file with it (`cg render` and
    /// `cg inspect` take it), and a scene named in its encoding reads.
    #[test]
    fn a_file_that_is_not_text_names_the_place_and_what_to_do() {
        let dir = student_folder("latin1");
        let path = dir.join("scène.obj");
        std::fs::write(&path, b"v 0 0 0\r\n# caf\xE9 au lait\r\n").unwrap();
        let e = load_obj(&path).unwrap_err();
        assert!(matches!(*e.kind, ErrorKind::Encoding { .. }), "{e}");
        assert_eq!(e.position, Some(Position { line: 2, column: 6 }), "{e}");
        let en = e.describe(Lang::En);
        assert!(
            en.contains("neither UTF-8 nor Shift_JIS") && en.contains("Save the file as UTF-8")
        );
        assert!(!en.contains("--encoding"), "{en}");
        let ja = e.describe(Lang::Ja);
        assert!(ja.contains("エンコード: UTF-8"), "{ja}");
        // Each language its own sentence: no English in the Japanese text.
        assert!(!ja.contains("Save the file"), "{ja}");
        let scene = dir.join("scène.toml");
        std::fs::write(&scene, b"# caf\xE9\n").unwrap();
        let e = load(&scene).unwrap_err();
        assert!(e.describe(Lang::En).contains("--encoding"), "{e}");
        // Shift_JIS named: read as such (and then judged as a scene: no `version`).
        std::fs::write(&scene, [SJIS_COMMENT, b"\n"].concat()).unwrap();
        let named = load_encoded(&scene, Some(cg_core::text::Encoding::ShiftJis)).unwrap_err();
        assert!(!matches!(*named.kind, ErrorKind::Encoding { .. }), "{named}");
        let wrong = load_encoded(&scene, Some(cg_core::text::Encoding::Utf8)).unwrap_err();
        assert!(matches!(*wrong.kind, ErrorKind::Encoding { .. }), "{wrong}");
        remove(&dir);
    }
}
