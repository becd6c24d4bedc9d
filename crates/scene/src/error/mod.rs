//! The one error type of this crate: what went wrong, in which file, on which line and column,
//! under which key — in English (`Display`) and Japanese ([`SceneError::describe`]).
//!
//! The types are here; their messages, each built in both languages at once, are in `text`; the
//! "did you mean" suggestions for typos are in `typo`.

mod text;
mod typo;

#[cfg(test)]
mod tests;

use std::fmt;
use std::path::PathBuf;

use cg_core::lang::{Lang, Text};
use cg_core::mesh::MeshError;
use cg_core::shapes::ShapeError;
use cg_core::texture::TextureError;
use cg_core::transform::TransformError;

/// A problem with a scene file or a file it refers to, naming the file, the place and the key:
///
/// ```text
/// assets/scenes/x.toml:23:9: objects[1].shape.radius: must be finite and > 0, got -1
/// ```
///
/// `Display` gives the English message; [`SceneError::describe`] gives it in either language,
/// [`SceneError::text`] in both.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{}", self.describe(Lang::En))]
pub struct SceneError {
    /// The file the problem is in (as given, or resolved against the scene file's folder).
    pub file: PathBuf,
    /// Where in the file, when the problem has a place (syntax, a key, a face line of an OBJ).
    pub position: Option<Position>,
    /// The key path (`objects[1].shape.radius`; array indices count from 0), when the problem
    /// belongs to a key.
    pub key: Option<String>,
    /// What is wrong (boxed, so results stay small on the path where nothing is wrong).
    pub kind: Box<ErrorKind>,
}

/// A place in a text file: line and column, both counted from 1; the column counts characters
/// (a Japanese comment before the mistake counts one per character, not per byte).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Position {
    /// Line, from 1.
    pub line: usize,
    /// Column in characters, from 1.
    pub column: usize,
}

/// What is wrong. Each variant has one message in Japanese and English ([`ErrorKind::text`]).
#[derive(Clone, Debug, PartialEq)]
pub enum ErrorKind {
    /// The file could not be read (missing, unreadable).
    Read {
        /// The operating system's reason ([`cg_core::lang::Text::io`]).
        reason: Text,
    },
    /// The file is not text in an encoding the kit reads (UTF-8, UTF-16 with a BOM, Shift_JIS;
    /// see `cg_core::text`).
    Encoding {
        /// Why, and where (`cg_core::text`'s message, in both languages).
        why: cg_core::lang::Text,
    },
    /// The text is not valid TOML (an unquoted string, a missing `=`, …).
    Syntax {
        /// The TOML parser's message.
        message: String,
    },
    /// A key (or a table) given twice in one table.
    DuplicateKey {
        /// The key as written.
        key: String,
        /// The line where it was given first, where it could be found.
        first_line: Option<usize>,
    },
    /// `format` names a version of the scene format this kit does not know.
    UnsupportedFormat {
        /// The value found, as written.
        found: String,
    },
    /// A key that this table does not have — usually a typo.
    UnknownKey {
        /// The key as written.
        key: String,
        /// The closest known key, when one is close.
        suggestion: Option<String>,
        /// The keys this table accepts.
        allowed: Vec<&'static str>,
    },
    /// A required key is missing (the error's key path is the table's).
    MissingKey {
        /// The missing key.
        key: String,
    },
    /// A value of the wrong type (a string where a number belongs, an array of 2 for 3 numbers).
    WrongType {
        /// What the key takes.
        expected: Expected,
        /// What was written.
        found: Found,
    },
    /// A word that is not one of the key's choices (`shading = "gourad"`).
    UnknownChoice {
        /// The word as written.
        value: String,
        /// The closest choice, when one is close.
        suggestion: Option<&'static str>,
        /// The choices.
        allowed: Vec<&'static str>,
    },
    /// A value outside its range (a negative radius, `far ≤ near`, a zero rotation axis).
    BadValue {
        /// The rule the value breaks.
        rule: Rule,
        /// The value as written in the file.
        got: String,
    },
    /// A material's k_r + k_t exceeds 1 in a channel: the surface would reflect and transmit
    /// more light than reaches it (energy conservation), and a ray tracer's tree of reflected and
    /// refracted rays would grow without bound (the error's key is `kt`, or `kr` when `kt` is not
    /// given).
    ReflectanceSum {
        /// The channel (0 red, 1 green, 2 blue).
        channel: usize,
        /// k_r in that channel.
        kr: f32,
        /// k_t in that channel.
        kt: f32,
    },
    /// A window of more than [`cg_core::image::MAX_PIXELS`] pixels (each side within range).
    TooManyPixels {
        /// The width.
        width: u32,
        /// The height.
        height: u32,
    },
    /// A material gives `color` together with `ka` or `kd`.
    ColorWithReflectance {
        /// The other key (`ka` or `kd`).
        other: &'static str,
    },
    /// An object gives both `shape` and `mesh`.
    ShapeAndMesh,
    /// An object gives neither `shape` nor `mesh`.
    NoGeometry,
    /// `render.specular` is given with `light_model = "opengl"`.
    SpecularNeedsLectureModel,
    /// `weld = <distance>` merged every face of an object away (the distance is as long as its
    /// edges): nothing would be drawn.
    WeldRemovesEveryFace {
        /// The weld distance.
        tolerance: f32,
        /// The faces before welding.
        faces: usize,
    },
    /// `weld` merged two vertices whose texture coordinates (the object has a texture) or whose
    /// given normals (`normals = "given"`) differ: a UV seam or a hard edge, which one vertex
    /// cannot keep (the texture would be squeezed into the seam's column, the edge smoothed).
    WeldMergesSeam {
        /// `true`: texture coordinates; `false`: normals.
        uvs: bool,
        /// The vertex kept and the one merged into it (0-based, in the mesh as loaded).
        kept: usize,
        /// The vertex merged into `kept`.
        merged: usize,
    },
    /// A spot light's `inner_deg` (the lecture's soft edge) with `light_model = "opengl"`, which
    /// has no inner cone.
    InnerConeNeedsLectureModel,
    /// A transform step names no operation, or more than one.
    TransformStep {
        /// The keys found in the step.
        found: Vec<String>,
    },
    /// `material = "name"` names no `[materials.name]` table.
    UnknownMaterial {
        /// The name as written.
        name: String,
        /// The closest defined name, when one is close.
        suggestion: Option<String>,
    },
    /// A scene's, object's or material's name longer than [`crate::MAX_NAME_CHARS`].
    NameTooLong {
        /// How many characters it has.
        chars: usize,
        /// [`crate::MAX_NAME_CHARS`].
        max: usize,
    },
    /// A name (the scene's, an object's, a material's) holds a control character (an escape
    /// sequence would drive the terminal that prints the name).
    NameControl {
        /// The character's code point.
        code: u32,
        /// Its place in the name, 1-based, in characters.
        place: usize,
    },
    /// Two objects have the same name.
    DuplicateName {
        /// The name.
        name: String,
        /// The line of the first object with that name.
        first_line: usize,
    },
    /// `normals = "given"` on a mesh without normals.
    NeedsNormals,
    /// A texture on a mesh without texture coordinates.
    NeedsUvs,
    /// A built-in shape rejected its parameters.
    Shape(ShapeError),
    /// A built-in shape would have more faces than one shape may have (the error's key is the
    /// parameter that sets the count).
    TooManyFaces {
        /// The shape (`grid`, `uv_sphere`, …).
        shape: &'static str,
        /// How many triangles it would have.
        faces: u64,
        /// The most a shape may have ([`crate::MAX_SHAPE_FACES`]).
        max: u64,
    },
    /// A scene beyond one of the limits that keep every scene that loads drawable, and drawn
    /// alike by every renderer ([`crate::MAX_COORDINATE`], [`crate::MAX_SCENE_FACES`], …): a
    /// point too far from the origin, a transform whose product overflows, a field of view, near
    /// plane or depth range f32 cannot draw, too many faces or point lights in all.
    Limit(crate::LimitError),
    /// The camera or the projection is one that `cg_core::transform` cannot build (`look_at`'s
    /// up nearly parallel to the view, a subnormal `near`, …).
    Transform(TransformError),
    /// A problem inside a file the scene refers to (an OBJ model, a PNG texture).
    File(Box<SceneError>),
    /// The OBJ parser (tobj) rejected the file.
    Obj(tobj::LoadError),
    /// A face of an OBJ file refers to an element that does not exist (yet): indices count the
    /// elements on the lines before the face.
    ObjIndex {
        /// `v`, `vt` or `vn`.
        element: &'static str,
        /// The index as written (1-based; negative counts back from the last one read).
        index: i64,
        /// How many such elements the lines before the face define.
        count: usize,
    },
    /// A word of an OBJ file that should be a number is not one (`v 1 0 x`, `f 1 2 x`, an
    /// index too large for any file).
    ObjNumber {
        /// The line's keyword: `v`, `vt`, `vn`, `f` or `l`.
        element: &'static str,
        /// The word as written.
        word: String,
    },
    /// A `v`, `vt` or `vn` line of an OBJ file has too few numbers (or, for `v`, a count that is
    /// neither x y z, x y z w nor x y z r g b), or an `f` or `l` line has no corners.
    ObjValues {
        /// `v`, `vt`, `vn`, `f` or `l`.
        element: &'static str,
        /// How many values the line has.
        found: usize,
    },
    /// A face corner of an OBJ file is not `v`, `v/vt`, `v//vn` or `v/vt/vn`.
    ObjCorner {
        /// The corner as written.
        corner: String,
    },
    /// A face corner of an OBJ file written unlike the face's first corner: with a `vt` or `vn`
    /// that the first does not have, or without one that it has (`f 1//1 2//2 3`).
    ObjCornerForm {
        /// The corner as written.
        corner: String,
        /// The face's first corner as written.
        first: String,
        /// `vt` or `vn`: what one has and the other has not (`vt` when both differ).
        element: &'static str,
        /// Whether `corner` has it (and `first` has not).
        has: bool,
    },
    /// A face of an OBJ file that uses one `v` at two of its corners (`f 1 2 3 4 1 2 3 4`, a face
    /// that goes round twice or touches itself; `f 1 1 2`).
    ObjRepeatedVertex {
        /// The corner that uses it again, as written.
        corner: String,
        /// The `v` (1-based, counted from the file's first `v` line, whatever was written).
        vertex: usize,
        /// Which corner of the face (1-based) used it first.
        first: usize,
    },
    /// A face of an OBJ file written unlike the file's first face: with a `vt` or `vn` that the
    /// first face's corners do not have, or without one they have (normals on some faces only).
    ObjFaceForm {
        /// `vt` or `vn`: what one face has and the other has not (`vt` when both differ).
        element: &'static str,
        /// Whether this face has it (and the first face has not).
        has: bool,
        /// The line of the file's first face.
        first_line: usize,
    },
    /// A `v` line of an OBJ file has w = 0, or a coordinate that is not finite (after the
    /// division by w).
    ObjPosition {
        /// The position after the division by w.
        position: [f32; 3],
        /// The homogeneous w (1 when not written).
        w: f32,
    },
    /// A face of four or more corners of an OBJ file that cannot be split into triangles (its
    /// first corner's fan would fold it, and it crosses itself, or has too many corners).
    ObjPolygon {
        /// How many corners the face has.
        corners: usize,
        /// What is wrong with it.
        problem: crate::PolygonProblem,
    },
    /// The OBJ file has no faces.
    ObjNoFaces,
    /// Some face corners of an OBJ file have normals (or texture coordinates) and others do not.
    ObjPartial {
        /// `vn` or `vt`.
        element: &'static str,
    },
    /// A `vn` line of an OBJ file whose vector has no direction (`vn 0 0 0`), at its line.
    ObjZeroNormal,
    /// A vertex normal of an OBJ file is zero or not finite.
    ObjBadNormal {
        /// The vertex (V-number in the loaded mesh).
        vertex: usize,
    },
    /// A texture coordinate of an OBJ file is not finite.
    ObjBadUv {
        /// The vertex (V-number in the loaded mesh).
        vertex: usize,
    },
    /// The loaded mesh is unusable (a non-finite position).
    Mesh(MeshError),
    /// The file is not a PNG image.
    NotPng,
    /// The PNG image is wider or higher than [`crate::MAX_TEXTURE_SIDE`], or decodes to more than
    /// [`crate::MAX_TEXTURE_BYTES`].
    PngTooLarge {
        /// Width in pixels, from the PNG header.
        width: u32,
        /// Height in pixels, from the PNG header.
        height: u32,
    },
    /// The file is larger than the kit reads for its kind (a PNG: [`crate::MAX_PNG_FILE_BYTES`]);
    /// nothing past the limit was read.
    FileTooLarge {
        /// Its size in bytes, when the file system says (not for a pipe or a device).
        size: Option<u64>,
        /// The limit, in MiB.
        limit_mib: u64,
    },
    /// The PNG image is corrupt or truncated.
    Png {
        /// The decoder's reason.
        reason: String,
    },
    /// The image cannot be a texture.
    Texture(TextureError),
    /// An image could not be written.
    Write {
        /// The operating system's ([`cg_core::lang::Text::io`]) or the encoder's reason.
        reason: Text,
    },
}

/// What a key takes, for [`ErrorKind::WrongType`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Expected {
    /// An integer or a float.
    Number,
    /// An integer.
    Integer,
    /// A string.
    String,
    /// `true` or `false`.
    Boolean,
    /// A table.
    Table,
    /// An array of tables (`[[objects]]`, `transform = [{ … }, …]`).
    ArrayOfTables,
    /// `[x, y, z]`.
    Vec3,
    /// `[r, g, b]`.
    Color,
    /// `[kc, kl, kq]`.
    Attenuation,
    /// `[nu, nv]` integers.
    Samples,
    /// `"repeat"`, `"clamp"` or `[u, v]` of those.
    Wrap,
    /// A word naming one of a key's choices.
    Choice,
    /// `"face"`, `"given"`, `"smooth"` or `{ weighting, crease_deg }`.
    Normals,
    /// A material's name or an inline material table.
    Material,
    /// `true`, `false` or a tolerance ≥ 0.
    Weld,
}

/// What was written, for [`ErrorKind::WrongType`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Found {
    /// A string.
    String,
    /// An integer.
    Integer,
    /// A float.
    Float,
    /// `true` or `false`.
    Boolean,
    /// A date or time.
    Datetime,
    /// An array.
    Array {
        /// How many values it has.
        len: usize,
    },
    /// A table.
    Table,
}

/// The rule a value breaks, for [`ErrorKind::BadValue`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rule {
    /// Finite (not NaN or ±∞).
    Finite,
    /// Finite and ≥ 0.
    NonNegative,
    /// Finite and > 0.
    Positive,
    /// In `[min, max]`.
    Between {
        /// Lower end (included).
        min: f64,
        /// Upper end (included).
        max: f64,
    },
    /// In `(min, max)`.
    Inside {
        /// Lower end (excluded).
        min: f64,
        /// Upper end (excluded).
        max: f64,
    },
    /// In `(0, 90]` or exactly 180 (GL_SPOT_CUTOFF).
    SpotCutoff,
    /// A spot's `inner_deg` with `cutoff_deg = 180`, which has no cone to be inside of: the
    /// light shines everywhere alike, and `inner_deg` would change nothing.
    InnerNeedsCone,
    /// An integer in `min..=max`.
    Integer {
        /// Smallest allowed.
        min: i64,
        /// Largest allowed.
        max: i64,
    },
    /// A finite, non-zero vector.
    NonZeroVector,
    /// Greater than another key's value.
    GreaterThan {
        /// The other key.
        key: &'static str,
        /// Its value.
        value: f64,
    },
    /// Not greater than another key's value.
    NotAbove {
        /// The other key.
        key: &'static str,
        /// Its value.
        value: f64,
    },
    /// `edge_u × edge_v` is zero: the area light has no area.
    NonZeroArea,
    /// `[kc, kl, kq]` all zero.
    SomeAttenuation,
    /// At most `max` (colour values and reflectances: bounded so sums of them stay finite).
    AtMost {
        /// The largest allowed.
        max: f64,
    },
}

pub(crate) use typo::closest;

impl SceneError {
    /// A problem with `file` as a whole (no place, no key).
    pub(crate) fn in_file(file: &std::path::Path, kind: ErrorKind) -> SceneError {
        SceneError { file: file.to_path_buf(), position: None, key: None, kind: Box::new(kind) }
    }

    /// The message in `lang`: `file:line:column: key: what is wrong`, with the parts that are
    /// known. The English one is also the `Display`.
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl ErrorKind {
    /// What is wrong, in `lang` (without the file, place and key).
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }
}

impl Rule {
    /// Whether `x` satisfies a rule about one number (rules about integers, vectors and other
    /// keys are checked where they are used and accept every number here).
    pub(crate) fn accepts(self, x: f64) -> bool {
        match self {
            Rule::Finite => x.is_finite(),
            Rule::NonNegative => x.is_finite() && x >= 0.0,
            Rule::Positive => x.is_finite() && x > 0.0,
            Rule::Between { min, max } => (min..=max).contains(&x),
            Rule::Inside { min, max } => min < x && x < max,
            Rule::SpotCutoff => (x > 0.0 && x <= 90.0) || x == 180.0,
            Rule::GreaterThan { value, .. } => x > value,
            Rule::NotAbove { value, .. } => x <= value,
            Rule::AtMost { max } => x <= max,
            _ => true,
        }
    }
}

impl fmt::Display for Position {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}
