//! The one error type of this crate: what went wrong, in which file, on which line and column,
//! under which key — in English (`Display`) and Japanese ([`SceneError::describe`]).

use std::fmt::{self, Write as _};
use std::path::PathBuf;

use cg_core::lang::Lang;
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
/// `Display` gives the English message; [`SceneError::describe`] gives it in either language.
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

/// What is wrong. Each variant has an English and a Japanese message ([`ErrorKind::describe`]).
#[derive(Clone, Debug, PartialEq)]
pub enum ErrorKind {
    /// The file could not be read (missing, unreadable, not UTF-8).
    Read {
        /// The operating system's reason.
        reason: String,
    },
    /// The text is not valid TOML (an unquoted string, a missing `=`, a duplicated key, …).
    Syntax {
        /// The TOML parser's message.
        message: String,
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
    /// A `v` line of an OBJ file has w = 0, or a coordinate that is not finite (after the
    /// division by w).
    ObjPosition {
        /// The position after the division by w.
        position: [f32; 3],
        /// The homogeneous w (1 when not written).
        w: f32,
    },
    /// The OBJ file has no faces.
    ObjNoFaces,
    /// Some face corners of an OBJ file have normals (or texture coordinates) and others do not.
    ObjPartial {
        /// `vn` or `vt`.
        element: &'static str,
    },
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
    /// The PNG image is larger than the decoder's memory limit allows.
    PngTooLarge {
        /// Width in pixels, from the PNG header.
        width: u32,
        /// Height in pixels, from the PNG header.
        height: u32,
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
        /// The operating system's or the encoder's reason.
        reason: String,
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
    /// `up` parallel to the view direction `target − eye`. (The reader now reports a look-at
    /// camera's problems as [`ErrorKind::Transform`], from `cg_core::transform::look_at`.)
    NotParallelToView,
    /// `eye` equal to `target`. (Reported as [`ErrorKind::Transform`] now, as above.)
    DifferentFromTarget,
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

impl SceneError {
    /// A problem with `file` as a whole (no place, no key).
    pub(crate) fn in_file(file: &std::path::Path, kind: ErrorKind) -> SceneError {
        SceneError { file: file.to_path_buf(), position: None, key: None, kind: Box::new(kind) }
    }

    /// The message in `lang`: `file:line:column: key: what is wrong`, with the parts that are
    /// known. The English one is also the `Display`.
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        let mut s = self.file.display().to_string();
        if let Some(p) = self.position {
            let _ = write!(s, ":{}:{}", p.line, p.column);
        }
        s.push_str(": ");
        if let Some(key) = &self.key {
            s.push_str(key);
            s.push_str(": ");
        }
        s.push_str(&self.kind.describe(lang));
        s
    }
}

/// `a, b, c` with each name in backquotes.
fn list(names: &[&str]) -> String {
    names.iter().map(|n| format!("`{n}`")).collect::<Vec<_>>().join(", ")
}

impl ErrorKind {
    /// What is wrong, in `lang` (without the file, place and key).
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        let ja = lang == Lang::Ja;
        match self {
            ErrorKind::Write { reason } => {
                if ja {
                    format!("ファイルに書き込めません: {reason}")
                } else {
                    format!("cannot write the file: {reason}")
                }
            }
            ErrorKind::Read { reason } => {
                if ja {
                    format!("ファイルを読めません: {reason}")
                } else {
                    format!("cannot read the file: {reason}")
                }
            }
            ErrorKind::Syntax { message } => {
                if ja {
                    format!("TOML の書き方の誤りです（構文エラー）: {message}")
                } else {
                    format!("TOML syntax error: {message}")
                }
            }
            ErrorKind::UnsupportedFormat { found } => {
                if ja {
                    format!("format = {found} は読めません。このキットが読めるのは format = 1 です")
                } else {
                    format!("format = {found} is not a version this kit reads; use format = 1")
                }
            }
            ErrorKind::UnknownKey { key, suggestion, allowed } => match (suggestion, ja) {
                (Some(s), false) => format!("unknown key `{key}` (did you mean `{s}`?)"),
                (Some(s), true) => {
                    format!("`{key}` というキーはありません（`{s}` の間違いでは？）")
                }
                (None, false) => {
                    format!("unknown key `{key}`; the keys here are {}", list(allowed))
                }
                (None, true) => {
                    format!("`{key}` というキーはありません。ここで使えるキー: {}", list(allowed))
                }
            },
            ErrorKind::MissingKey { key } => {
                if ja {
                    format!("必要なキー `{key}` がありません")
                } else {
                    format!("missing key `{key}`")
                }
            }
            ErrorKind::WrongType { expected, found } => {
                if ja {
                    format!("{}が必要ですが、{}が書かれています", expected.ja(), found.ja())
                } else {
                    format!("expected {}, found {}", expected.en(), found.en())
                }
            }
            ErrorKind::UnknownChoice { value, suggestion, allowed } => {
                let choices = allowed.iter().map(|c| format!("\"{c}\"")).collect::<Vec<_>>();
                let choices = choices.join(", ");
                match (suggestion, ja) {
                    (Some(s), false) => {
                        format!("unknown value \"{value}\" (did you mean \"{s}\"?)")
                    }
                    (Some(s), true) => {
                        format!("\"{value}\" は使えません（\"{s}\" の間違いでは？）")
                    }
                    (None, false) => format!("unknown value \"{value}\"; use one of {choices}"),
                    (None, true) => format!("\"{value}\" は使えません。使える値: {choices}"),
                }
            }
            ErrorKind::BadValue { rule, got } => {
                if ja {
                    format!("{}（書かれている値: {got}）", rule.ja())
                } else {
                    format!("{}, got {got}", rule.en())
                }
            }
            ErrorKind::ReflectanceSum { channel, kr, kt } => {
                let sum = kr + kt;
                let c = ["r", "g", "b"].get(*channel).copied().unwrap_or("?");
                if ja {
                    format!(
                        "kr + kt が {c} 成分で {kr} + {kt} = {sum} です。1 以下にしてください                         （エネルギー保存: 面が反射・透過する光は届いた光を超えられません。                         超えるとレイトレーシングの反射・屈折レイが際限なく増えます）"
                    )
                } else {
                    format!(
                        "kr + kt is {kr} + {kt} = {sum} in channel {c}: it must be at most 1                          (energy conservation: a surface cannot reflect and transmit more light than                          reaches it, and the ray tracer's reflected and refracted rays would multiply                          without bound)"
                    )
                }
            }
            ErrorKind::TooManyPixels { width, height } => {
                let e = cg_core::image::SizeError::TooManyPixels { width: *width, height: *height };
                e.message(lang)
            }
            ErrorKind::ColorWithReflectance { other } => {
                if ja {
                    format!(
                        "`color` は ka と kd の両方を決めます（GL_COLOR_MATERIAL での glColor と同じ）。\
                         `color` か `ka`/`kd` のどちらか一方だけを書いてください（`{other}` も書かれています）"
                    )
                } else {
                    format!(
                        "`color` sets both ka and kd (as glColor does under GL_COLOR_MATERIAL); \
                         give either `color` or `ka`/`kd`, not both (`{other}` is also given)"
                    )
                }
            }
            ErrorKind::ShapeAndMesh => {
                if ja {
                    "物体には `shape` か `mesh` のどちらか一方だけを書いてください".into()
                } else {
                    "an object has either `shape` or `mesh`, not both".into()
                }
            }
            ErrorKind::NoGeometry => {
                if ja {
                    "物体の形がありません: `shape = { kind = \"...\" }` か `mesh = \"ファイル.obj\"` を書いてください".into()
                } else {
                    "the object has no geometry: give `shape = { kind = \"...\" }` or `mesh = \"file.obj\"`".into()
                }
            }
            ErrorKind::SpecularNeedsLectureModel => {
                if ja {
                    "`specular` は light_model = \"lecture\" でだけ選べます（OpenGL のモデルは常に Blinn の N·H）".into()
                } else {
                    "`specular` applies only to light_model = \"lecture\" (OpenGL's model always uses Blinn's N·H)".into()
                }
            }
            ErrorKind::TransformStep { found } => {
                let ops = "`translate`, `rotate_deg` (+ `axis`), `rotate_x_deg`, `rotate_y_deg`, `rotate_z_deg`, `scale`";
                let found: Vec<&str> = found.iter().map(String::as_str).collect();
                if ja {
                    format!(
                        "変換の各ステップには操作を 1 つだけ書きます（{ops} のどれか）。書かれているキー: {}",
                        list(&found)
                    )
                } else {
                    format!(
                        "each transform step has exactly one operation ({ops}); found {}",
                        if found.is_empty() { "none".to_owned() } else { list(&found) }
                    )
                }
            }
            ErrorKind::UnknownMaterial { name, suggestion } => match (suggestion, ja) {
                (Some(s), false) => {
                    format!("no material named \"{name}\" in [materials] (did you mean \"{s}\"?)")
                }
                (Some(s), true) => {
                    format!(
                        "[materials] に \"{name}\" という材質はありません（\"{s}\" の間違いでは？）"
                    )
                }
                (None, false) => format!(
                    "no material named \"{name}\"; define it as [materials.{name}] or write the material inline"
                ),
                (None, true) => format!(
                    "\"{name}\" という材質はありません。[materials.{name}] を作るか、材質をその場に書いてください"
                ),
            },
            ErrorKind::DuplicateName { name, first_line } => {
                if ja {
                    format!("物体の名前 \"{name}\" は {first_line} 行目ですでに使われています")
                } else {
                    format!("another object (line {first_line}) is already named \"{name}\"")
                }
            }
            ErrorKind::NeedsNormals => {
                if ja {
                    "normals = \"given\" ですが、このメッシュには法線がありません（OBJ なら vn 行が必要）。\"face\" か \"smooth\" を使ってください".into()
                } else {
                    "normals = \"given\" but this mesh has no normals (an OBJ needs `vn` lines); use \"face\" or \"smooth\"".into()
                }
            }
            ErrorKind::NeedsUvs => {
                if ja {
                    "テクスチャにはテクスチャ座標が必要ですが、このメッシュにはありません（grid にはあります。OBJ なら vt 行が必要）".into()
                } else {
                    "a texture needs texture coordinates and this mesh has none (grid has them; an OBJ needs `vt` lines)".into()
                }
            }
            ErrorKind::Shape(e) => e.message(lang),
            ErrorKind::TooManyFaces { shape, faces, max } => {
                if ja {
                    format!(
                        "この {shape} は面（三角形）が {faces} 個になります。1 つの形の面は {max} 個までです。分割数を減らしてください"
                    )
                } else {
                    format!(
                        "this {shape} would have {faces} faces (triangles), more than the {max} one shape may have: use fewer segments"
                    )
                }
            }
            ErrorKind::Transform(e) => e.message(lang),
            ErrorKind::File(inner) => inner.describe(lang),
            ErrorKind::Obj(e) => {
                if ja {
                    format!("OBJ ファイルとして読めません（{}）", obj_error_ja(*e))
                } else {
                    format!("not a valid OBJ file: {e}")
                }
            }
            ErrorKind::ObjIndex { element, index, count } => {
                if ja {
                    format!(
                        "面が {element} の {index} 番を参照していますが、この行より前の {element} 行は {count} 個です（番号は 1 から、負の数はこの行から後ろ向きに数えます）"
                    )
                } else {
                    format!(
                        "a face refers to {element} number {index}, but the lines before it define {count} `{element}` (indices count from 1; negative ones count back from this line)"
                    )
                }
            }
            ErrorKind::ObjNumber { element: element @ ("f" | "l"), word } => {
                if ja {
                    format!(
                        "`{word}` は {element} 行の頂点番号として使えません（1 から数える整数か、後ろから数える負の整数を書きます）"
                    )
                } else {
                    format!(
                        "`{word}` is not a usable index on an `{element}` line (a whole number counted from 1, or a negative one counting back)"
                    )
                }
            }
            ErrorKind::ObjNumber { element, word } => {
                if ja {
                    format!("{element} 行の `{word}` は数ではありません")
                } else {
                    format!("`{word}` on a `{element}` line is not a number")
                }
            }
            ErrorKind::ObjValues { element: element @ ("f" | "l"), .. } => {
                if ja {
                    format!("{element} 行に頂点番号がありません")
                } else {
                    format!("an `{element}` line without vertex numbers")
                }
            }
            ErrorKind::ObjValues { element, found } => {
                let (en, ja_text) = match *element {
                    "v" => (
                        "3 coordinates x y z, optionally followed by w or by a colour r g b",
                        "3 つの座標 x y z（その後に w、または色 r g b を続けてもかまいません）",
                    ),
                    "vt" => ("at least 2 coordinates u v", "少なくとも 2 つの座標 u v"),
                    _ => ("3 components x y z", "3 つの成分 x y z"),
                };
                if ja {
                    format!("{element} 行には{ja_text}が必要ですが、{found} 個の値が書かれています")
                } else {
                    format!("a `{element}` line needs {en}; this one has {found} values")
                }
            }
            ErrorKind::ObjCorner { corner } => {
                if ja {
                    format!(
                        "面の頂点 `{corner}` の書き方が違います（v、v/vt、v//vn、v/vt/vn のどれかで書きます）"
                    )
                } else {
                    format!("face corner `{corner}` is not one of v, v/vt, v//vn, v/vt/vn")
                }
            }
            ErrorKind::ObjPosition { position: [x, y, z], w } => {
                if ja {
                    if *w == 0.0 {
                        "同次座標 w が 0 です（頂点が無限遠になります）".into()
                    } else {
                        format!(
                            "頂点の座標 ({x}, {y}, {z}) が有限ではありません（無限大または NaN）"
                        )
                    }
                } else if *w == 0.0 {
                    "the homogeneous coordinate w is 0: the vertex would be at infinity".into()
                } else {
                    format!("the vertex position ({x}, {y}, {z}) is not finite (infinite or NaN)")
                }
            }
            ErrorKind::ObjNoFaces => {
                if ja {
                    "OBJ ファイルに面（f 行）がありません".into()
                } else {
                    "the OBJ file has no faces (`f` lines)".into()
                }
            }
            ErrorKind::ObjPartial { element } => {
                if ja {
                    format!(
                        "{element} のある面の頂点とない面の頂点が混ざっています。すべての面に付けるか、すべて外してください"
                    )
                } else {
                    format!(
                        "some face corners have `{element}` and others do not; give it on every face or on none"
                    )
                }
            }
            ErrorKind::ObjBadNormal { vertex } => {
                if ja {
                    format!("頂点 V{vertex} の法線が 0 か有限でないベクトルです")
                } else {
                    format!("vertex V{vertex} has a zero or non-finite normal")
                }
            }
            ErrorKind::ObjBadUv { vertex } => {
                if ja {
                    format!("頂点 V{vertex} のテクスチャ座標が有限ではありません")
                } else {
                    format!("vertex V{vertex} has a non-finite texture coordinate")
                }
            }
            ErrorKind::Mesh(e) => {
                if ja {
                    format!("メッシュとして使えません: {}", e.message(lang))
                } else {
                    format!("unusable mesh: {}", e.message(lang))
                }
            }
            ErrorKind::NotPng => {
                if ja {
                    "PNG 画像ではありません（PNG の先頭 8 バイトがありません）".into()
                } else {
                    "not a PNG image (the file does not start with the PNG signature)".into()
                }
            }
            ErrorKind::PngTooLarge { width, height } => {
                if ja {
                    format!("PNG 画像が大きすぎます（{width}×{height}）")
                } else {
                    format!("PNG image too large ({width}×{height})")
                }
            }
            ErrorKind::Png { reason } => {
                if ja {
                    format!("PNG 画像が壊れているか途中で切れています: {reason}")
                } else {
                    format!("corrupt or truncated PNG image: {reason}")
                }
            }
            ErrorKind::Texture(e) => e.describe(lang),
        }
    }
}

/// tobj's error in Japanese (its `Display` is English).
fn obj_error_ja(e: tobj::LoadError) -> &'static str {
    use tobj::LoadError as E;
    match e {
        E::OpenFileFailed => "ファイルを開けません",
        E::ReadError => "読み込みに失敗しました",
        E::UnrecognizedCharacter => "読めない文字があります",
        E::PositionParseError => "頂点の座標（v 行）が読めません",
        E::ScalingByZeroError => "同次座標 w が 0 です",
        E::ColorParseError => "頂点の色（v 行の r g b）の数が合いません",
        E::NormalParseError => "法線（vn 行）が読めません",
        E::TexcoordParseError => "テクスチャ座標（vt 行）が読めません",
        E::FaceParseError => "面（f 行）が読めません",
        E::MaterialParseError => "材質（usemtl 行）が読めません",
        E::InvalidObjectName => "物体の名前（o 行）が正しくありません",
        E::InvalidPolygon => "多角形が正しくありません",
        E::FaceVertexOutOfBounds => "面が存在しない頂点を参照しています",
        E::FaceTexCoordOutOfBounds => "面が存在しないテクスチャ座標を参照しています",
        E::FaceNormalOutOfBounds => "面が存在しない法線を参照しています",
        E::FaceColorOutOfBounds => {
            "色のない頂点があります（v 行の色は全部に付けるか、全部外します）"
        }
        E::InvalidLoadOptionConfig => "読み込みの設定が矛盾しています",
        E::GenericFailure => "原因不明の失敗です",
    }
}

impl Expected {
    fn en(self) -> &'static str {
        match self {
            Expected::Number => "a number",
            Expected::Integer => "an integer",
            Expected::String => "a string",
            Expected::Boolean => "true or false",
            Expected::Table => "a table",
            Expected::ArrayOfTables => "an array of tables",
            Expected::Vec3 => "an array of 3 numbers [x, y, z]",
            Expected::Color => "an RGB colour [r, g, b]",
            Expected::Attenuation => "[kc, kl, kq]",
            Expected::Samples => "two integers [nu, nv]",
            Expected::Wrap => "\"repeat\", \"clamp\" or [u, v] of those",
            Expected::Choice => "a word in quotes",
            Expected::Normals => {
                "\"face\", \"given\", \"smooth\" or { weighting = ..., crease_deg = ... }"
            }
            Expected::Material => "a material name in quotes or an inline table { ... }",
            Expected::Weld => "true, false or a distance tolerance ≥ 0",
        }
    }

    fn ja(self) -> &'static str {
        match self {
            Expected::Number => "数",
            Expected::Integer => "整数",
            Expected::String => "文字列",
            Expected::Boolean => "true か false",
            Expected::Table => "テーブル",
            Expected::ArrayOfTables => "テーブルの配列",
            Expected::Vec3 => "3 つの数の配列 [x, y, z]",
            Expected::Color => "RGB の色 [r, g, b]",
            Expected::Attenuation => "[kc, kl, kq]",
            Expected::Samples => "2 つの整数 [nu, nv]",
            Expected::Wrap => "\"repeat\" か \"clamp\"、またはその [u, v]",
            Expected::Choice => "引用符で囲んだ語",
            Expected::Normals => {
                "\"face\", \"given\", \"smooth\" または { weighting = ..., crease_deg = ... }"
            }
            Expected::Material => "引用符で囲んだ材質名かインラインテーブル { ... }",
            Expected::Weld => "true、false、または 0 以上の距離の許容値",
        }
    }
}

impl Found {
    fn en(self) -> String {
        match self {
            Found::String => "a string".into(),
            Found::Integer => "an integer".into(),
            Found::Float => "a float".into(),
            Found::Boolean => "a boolean".into(),
            Found::Datetime => "a date-time".into(),
            Found::Array { len: 1 } => "an array of 1 value".into(),
            Found::Array { len } => format!("an array of {len} values"),
            Found::Table => "a table".into(),
        }
    }

    fn ja(self) -> String {
        match self {
            Found::String => "文字列".into(),
            Found::Integer => "整数".into(),
            Found::Float => "小数".into(),
            Found::Boolean => "真偽値".into(),
            Found::Datetime => "日時".into(),
            Found::Array { len } => format!("{len} 個の値の配列"),
            Found::Table => "テーブル".into(),
        }
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

    fn en(self) -> String {
        match self {
            Rule::Finite => "must be finite".into(),
            Rule::NonNegative => "must be finite and ≥ 0".into(),
            Rule::Positive => "must be finite and > 0".into(),
            Rule::Between { min, max } => format!("must be in [{min}, {max}]"),
            Rule::Inside { min, max } => format!("must be strictly between {min} and {max}"),
            Rule::SpotCutoff => "must be in (0, 90] or exactly 180 (no cone)".into(),
            Rule::Integer { min, max } => format!("must be an integer in {min}..={max}"),
            Rule::NonZeroVector => "must be a finite, non-zero vector".into(),
            Rule::GreaterThan { key, value } => format!("must be greater than {key} (= {value})"),
            Rule::NotAbove { key, value } => format!("must not exceed {key} (= {value})"),
            Rule::NotParallelToView => {
                "must not be parallel to the view direction target − eye".into()
            }
            Rule::DifferentFromTarget => "must differ from target".into(),
            Rule::NonZeroArea => "edge_u × edge_v is zero: the light has no area".into(),
            Rule::SomeAttenuation => "at least one of kc, kl, kq must be > 0".into(),
            Rule::AtMost { max } => format!("must be at most {max:e}"),
        }
    }

    fn ja(self) -> String {
        match self {
            Rule::Finite => "有限の数でなければなりません".into(),
            Rule::NonNegative => "0 以上の有限の数でなければなりません".into(),
            Rule::Positive => "0 より大きい有限の数でなければなりません".into(),
            Rule::Between { min, max } => format!("{min} 以上 {max} 以下でなければなりません"),
            Rule::Inside { min, max } => {
                format!("{min} より大きく {max} より小さくなければなりません")
            }
            Rule::SpotCutoff => {
                "0 より大きく 90 以下、または 180（円錐なし）でなければなりません".into()
            }
            Rule::Integer { min, max } => {
                format!("{min} 以上 {max} 以下の整数でなければなりません")
            }
            Rule::NonZeroVector => "有限で長さが 0 でないベクトルでなければなりません".into(),
            Rule::GreaterThan { key, value } => {
                format!("{key}（= {value}）より大きくなければなりません")
            }
            Rule::NotAbove { key, value } => format!("{key}（= {value}）以下でなければなりません"),
            Rule::NotParallelToView => "視線の向き target − eye と平行であってはいけません".into(),
            Rule::DifferentFromTarget => "target と違う点でなければなりません".into(),
            Rule::NonZeroArea => "edge_u × edge_v が 0 で、面光源に面積がありません".into(),
            Rule::SomeAttenuation => "kc, kl, kq のどれかは 0 より大きくなければなりません".into(),
            Rule::AtMost { max } => format!("{max:e} 以下でなければなりません"),
        }
    }
}

impl fmt::Display for Position {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}", self.line, self.column)
    }
}

/// The closest of `candidates` to `word` by edit distance (ignoring case), if it is close enough
/// to be a likely typo: at most 1 edit for short words, 2 from 6 letters, 3 from 9.
pub(crate) fn closest<'c>(
    word: &str,
    candidates: impl IntoIterator<Item = &'c str>,
) -> Option<&'c str> {
    let word = word.to_lowercase();
    candidates
        .into_iter()
        .map(|c| (edit_distance(&word, &c.to_lowercase()), c))
        .filter(|&(d, c)| d <= (c.chars().count() / 3).clamp(1, 3))
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// Levenshtein distance between two strings, in characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1).min(row[j] + 1).min(diagonal + usize::from(ca != cb));
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggestions_catch_typos_but_not_other_words() {
        let keys = ["radius", "slices", "stacks", "kind"];
        assert_eq!(closest("radiu", keys), Some("radius"));
        assert_eq!(closest("Slices", keys), Some("slices"));
        assert_eq!(closest("knd", keys), Some("kind"));
        assert_eq!(closest("colour", ["color", "ka"]), Some("color"));
        assert_eq!(closest("attenuation", keys), None);
        assert_eq!(edit_distance("gouraud", "goraud"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
    }
}
