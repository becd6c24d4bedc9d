//! The scene format, version 1 (docs/scene-format.md): reading a TOML document into a
//! [`SceneSpec`] (every value checked, nothing loaded yet), then building the [`Scene`] (shape
//! meshes made, OBJ and PNG files loaded).

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use cg_core::Rgb;
use cg_core::camera::{CameraLimits, OrbitCamera};
use cg_core::glam::Vec3;
use cg_core::light::{LightModel, Material, Specular};
use cg_core::math::wrap_degrees;
use cg_core::normals::Weighting;
use cg_core::product::{Axis, Factor, MatrixProduct, Param};
use cg_core::scene::{
    Camera, NormalSource, Object, Projection, Scene, Shading, TextureUse, WeldRecord,
};
use cg_core::texture::{Filter, Sampler, TexEnv, Wrap};
use cg_core::transform::{TransformError, look_at, perspective};

use crate::error::{ErrorKind, Expected, Rule, SceneError};
use crate::load_texture;
use crate::reader::{At, Source, Table, Value};
use crate::shape::{ShapeAt, ShapeSpec};

mod lights;
use lights::{read_light, read_material, read_materials};

/// The only version of the format this kit reads.
pub(crate) const FORMAT_VERSION: i64 = 1;

/// Largest window side accepted, in pixels: the renderers' [`cg_core::image::MAX_SIDE`].
const MAX_WINDOW: i64 = cg_core::image::MAX_SIDE as i64;

/// The course's window: 640 × 640 pixels, glClearColor(0.5, 0.5, 0.8).
const COURSE_WINDOW: (u32, u32, Rgb) = (640, 640, Rgb::new(0.5, 0.5, 0.8));

/// The course's gluPerspective(45°, w/h, 1, 500).
const COURSE_PROJECTION: Projection = Projection { fovy_deg: 45.0, near: 1.0, far: 500.0 };

/// A scene read and checked, before meshes are built and files are loaded.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct SceneSpec {
    /// Everything but `objects` and `textures`, which stay empty until [`SceneSpec::build`].
    pub scene: Scene,
    /// The objects, in file order.
    pub objects: Vec<ObjectSpec>,
}

/// One `[[objects]]` entry, checked.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ObjectSpec {
    pub name: String,
    pub geometry: Geometry,
    /// `weld`: the tolerance, when the mesh is to be welded by position, and where it is.
    pub weld: Option<(f32, At)>,
    pub normals: NormalSource,
    /// Where `normals` is (or the object, when it is left out).
    pub normals_at: At,
    pub material: Material,
    pub transform: MatrixProduct,
    pub texture: Option<TextureSpec>,
}

/// Where an object's mesh comes from.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Geometry {
    /// A built-in shape, and where its table and parameters are.
    Shape(ShapeSpec, ShapeAt),
    /// An OBJ file, resolved against the scene's folder; `At` is the `mesh` value.
    Obj(PathBuf, At),
}

/// `texture = { image = "...", ... }`, checked.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct TextureSpec {
    /// The PNG file, resolved against the scene's folder.
    pub image: PathBuf,
    /// Where `image` is.
    pub image_at: At,
    /// Where the texture table is.
    pub at: At,
    pub sampler: Sampler,
    pub env: TexEnv,
}

/// [`read_root`] of the text of `src`, parsed here.
#[cfg(test)]
pub(crate) fn read(src: &Source<'_>, base: &Path) -> Result<SceneSpec, SceneError> {
    read_root(src, &Table::root(src, &parse_document(src)?), base)
}

/// The key (a bare or quoted key, one segment of a dotted key, or a table's name) that starts
/// at byte `start` of `text`, as the TOML parser's "duplicate key" error points at it.
fn key_at(text: &str, start: usize) -> Option<&str> {
    let rest = text.get(start..)?;
    let end = if rest.starts_with('"') || rest.starts_with('\'') {
        1 + rest[1..].find(&rest[..1])? + 1
    } else {
        rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_' || c == '-'))
            .unwrap_or(rest.len())
    };
    Some(&rest[..end]).filter(|k| !k.is_empty())
}

/// The last line of `before` (1-based) where `key` is written as a key: after the line's start,
/// a `[` or a `.`, and before an `=`, a `]` or a `.`.
fn line_defining(before: &str, key: &str) -> Option<usize> {
    let defines = |line: &str| {
        line.match_indices(key).any(|(i, _)| {
            let ahead = line[..i].trim_end();
            let after = line[i + key.len()..].trim_start();
            (ahead.is_empty() || ahead.ends_with(['[', '.'])) && after.starts_with(['=', ']', '.'])
        })
    };
    before.lines().enumerate().filter(|(_, line)| defines(line)).map(|(i, _)| i + 1).last()
}

/// The TOML document of `src`, with the span of every key and value; a syntax error names the
/// line and column.
pub(crate) fn parse_document<'a>(
    src: &Source<'a>,
) -> Result<toml::Spanned<toml::de::DeTable<'a>>, SceneError> {
    toml::de::DeTable::parse(src.text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        // The parser names neither the key nor where it was first: both are said here.
        if e.message() == "duplicate key"
            && let Some(key) = key_at(src.text, span.start)
        {
            let first_line = line_defining(&src.text[..span.start], key);
            let kind = ErrorKind::DuplicateKey { key: key.to_owned(), first_line };
            return src.error(&span, "", kind);
        }
        let mut message = e.message().to_owned();
        // A character that cannot be seen (a zero-width space pasted from a web page) is named,
        // or the student looks at a line that seems right.
        if let Some(c) = src.text.get(span.start..).and_then(|s| s.chars().next()) {
            let shown = cg_core::quote::visible(&c.to_string());
            if shown != c.to_string() {
                message.push_str(&format!(" ({shown})"));
            }
        }
        src.error(&span, "", ErrorKind::Syntax { message })
    })
}

/// Reads and checks a whole document: `root`, [`parse_document`] of `src`. `base` is the folder
/// relative file names start from.
pub(crate) fn read_root(
    src: &Source<'_>,
    root: &Table<'_>,
    base: &Path,
) -> Result<SceneSpec, SceneError> {
    // The version first: a newer file may have keys this reader does not know.
    let format = root.require("format")?;
    if format.integer(i64::MIN, i64::MAX)? != FORMAT_VERSION {
        return Err(format.error(ErrorKind::UnsupportedFormat { found: format.written() }));
    }
    root.only(&[
        "format",
        "name",
        "window",
        "camera",
        "projection",
        "render",
        "lights",
        "materials",
        "objects",
    ])?;

    let default_name =
        src.file.file_stem().map_or_else(String::new, |s| s.to_string_lossy().into());
    let name = root.or("name", default_name, read_name)?;

    let (width, height, clear_color) = match root.get("window") {
        Some(v) => read_window(&v.table()?)?,
        None => COURSE_WINDOW,
    };
    let camera = match root.get("camera") {
        Some(v) => read_camera(&v.table()?)?,
        None => Camera::Orbit(OrbitCamera::course_sample()),
    };
    let projection = match root.get("projection") {
        Some(v) => read_projection(&v.table()?, width as f32 / height as f32)?,
        None => COURSE_PROJECTION,
    };
    let render = match root.get("render") {
        Some(v) => read_render(&v.table()?)?,
        None => Render::default(),
    };
    let lights = match root.get("lights") {
        Some(v) => {
            let tables = tables(&v)?;
            if matches!(render.light_model, LightModel::OpenGl { .. }) {
                // OpenGL's spot light has no inner cone: an `inner_deg` would change nothing.
                for t in &tables {
                    if let Some(inner) = t.get("inner_deg") {
                        return Err(inner.error(ErrorKind::InnerConeNeedsLectureModel));
                    }
                }
            }
            tables.iter().map(read_light).collect::<Result<_, _>>()?
        }
        None => Vec::new(),
    };
    let materials = match root.get("materials") {
        Some(v) => read_materials(&v.table()?)?,
        None => HashMap::new(),
    };
    let mut objects = Vec::new();
    let mut first_line: HashMap<String, usize> = HashMap::new();
    if let Some(v) = root.get("objects") {
        for table in tables(&v)? {
            let object = read_object(&table, &materials, base)?;
            let line = src.position(table.at().span.start).line;
            if let Some(&first_line) = first_line.get(&object.name) {
                let name = table.require("name")?;
                return Err(name.error(ErrorKind::DuplicateName { name: object.name, first_line }));
            }
            first_line.insert(object.name.clone(), line);
            objects.push(object);
        }
    }

    let scene = Scene {
        name,
        width,
        height,
        clear_color,
        camera,
        projection,
        light_model: render.light_model,
        global_ambient: render.global_ambient,
        lights,
        shading: render.shading,
        cull_back_faces: render.cull_back_faces,
        objects: Vec::new(),
        textures: Vec::new(),
    };
    Ok(SceneSpec { scene, objects })
}

impl SceneSpec {
    /// Builds every mesh and loads every file the objects name; each texture file is loaded once
    /// however many objects use it.
    ///
    /// The faces of the built-in shapes are counted first, from their parameters, and each OBJ
    /// model's are added from its `f` lines, after its lines are checked and before it is loaded:
    /// more than [`crate::MAX_SCENE_FACES`] in all is an error at the shape or model that goes
    /// over, before anything more is built.
    pub(crate) fn build(self, src: &Source<'_>) -> Result<Scene, SceneError> {
        let mut faces = crate::limits::shape_faces(&self.objects, src)?;
        let mut scene = self.scene;
        let mut texture_index: HashMap<PathBuf, usize> = HashMap::new();
        for spec in self.objects {
            let analytic = match &spec.geometry {
                Geometry::Shape(shape, _) => shape.analytic(),
                Geometry::Obj(..) => None,
            };
            let mesh = match &spec.geometry {
                Geometry::Shape(shape, at) => {
                    shape.mesh().map_err(|e| at.of(e.parameter).error(src, ErrorKind::Shape(e)))?
                }
                Geometry::Obj(path, at) => {
                    let in_file = |e| at.error(src, ErrorKind::File(Box::new(e)));
                    let text = crate::read_text(path, None, false).map_err(in_file)?;
                    let model = crate::obj::check(&text, path).map_err(in_file)?;
                    // Counted from its lines, before tobj loads it (a model of too many faces
                    // took about 1 GB before it was refused); then as loaded.
                    let counted = model.faces();
                    crate::limits::add_model_faces(&mut faces, counted, at, src)?;
                    let mesh = model.load().map_err(in_file)?;
                    debug_assert!(mesh.face_count() as u64 <= counted, "the count is a bound");
                    faces = faces - counted + mesh.face_count() as u64;
                    mesh
                }
            };
            let (mesh, weld) = match spec.weld {
                None => (mesh, None),
                Some((tolerance, at)) => {
                    let before = mesh.vertex_count();
                    let faces = mesh.face_count();
                    let welded = mesh.weld_by_position(tolerance);
                    // Nothing left to draw: an error, as an OBJ file without faces is.
                    if faces > 0 && welded.mesh.face_count() == 0 {
                        return Err(
                            at.error(src, ErrorKind::WeldRemovesEveryFace { tolerance, faces })
                        );
                    }
                    // A seam's two vertices made one: the texture or the given normals would be
                    // wrong there, drawn without a word.
                    let textured = spec.texture.is_some();
                    let given = spec.normals == NormalSource::Given;
                    if let Some(kind) = seam_merged(&mesh, &welded.remap, textured, given) {
                        return Err(at.error(src, kind));
                    }
                    let record = WeldRecord {
                        tolerance,
                        merged_vertices: before - welded.mesh.vertex_count(),
                        removed_faces: welded.removed_faces.len(),
                    };
                    (welded.mesh, Some(record))
                }
            };
            if spec.normals == NormalSource::Given && mesh.normals.is_none() {
                return Err(spec.normals_at.error(src, ErrorKind::NeedsNormals));
            }
            let texture = match spec.texture {
                None => None,
                Some(t) => {
                    if mesh.uvs.is_none() {
                        return Err(t.at.error(src, ErrorKind::NeedsUvs));
                    }
                    let index = match texture_index.get(&t.image) {
                        Some(&i) => i,
                        None => {
                            let texture = load_texture(&t.image)
                                .map_err(|e| t.image_at.error(src, ErrorKind::File(Box::new(e))))?;
                            scene.textures.push(texture);
                            texture_index.insert(t.image.clone(), scene.textures.len() - 1);
                            scene.textures.len() - 1
                        }
                    };
                    Some(TextureUse { texture: index, sampler: t.sampler, env: t.env })
                }
            };
            scene.objects.push(Object {
                name: spec.name,
                mesh,
                normals: spec.normals,
                material: spec.material,
                transform: spec.transform,
                texture,
                // The exact surface a built-in shape stands for, while its mesh still covers it:
                // a weld that removed faces (a tolerance as long as the edges) leaves holes that the
                // ray tracer's exact surface would not show (every renderer draws the same mesh).
                analytic: analytic.filter(|_| weld.is_none_or(|w| w.removed_faces == 0)),
                weld,
            });
        }
        Ok(scene)
    }
}

/// The elements of an array of tables (`[[lights]]`, `[[objects]]`).
fn tables<'a>(value: &Value<'a>) -> Result<Vec<Table<'a>>, SceneError> {
    value.array(Expected::ArrayOfTables)?.iter().map(Value::table).collect()
}

fn read_window(t: &Table<'_>) -> Result<(u32, u32, Rgb), SceneError> {
    t.only(&["width", "height", "clear_color"])?;
    // In range 1..=16384, so the casts are exact.
    let side = |v: &Value<'_>| v.integer(1, MAX_WINDOW).map(|n| n as u32);
    let (width, height, clear_color) = COURSE_WINDOW;
    let (width, height) = (t.or("width", width, side)?, t.or("height", height, side)?);
    // Each side is in range (checked above); the renderers also bound the pixel count.
    if u64::from(width) * u64::from(height) > cg_core::image::MAX_PIXELS {
        let kind = ErrorKind::TooManyPixels { width, height };
        return Err(match t.get("height").or_else(|| t.get("width")) {
            Some(v) => v.error(kind),
            None => t.error(kind),
        });
    }
    Ok((width, height, t.or("clear_color", clear_color, Value::color)?))
}

#[derive(Clone, Copy)]
enum CameraKind {
    Orbit,
    LookAt,
}

fn read_camera(t: &Table<'_>) -> Result<Camera, SceneError> {
    let kind = t.or("kind", CameraKind::Orbit, |v| {
        v.choice(&[("orbit", CameraKind::Orbit), ("look_at", CameraKind::LookAt)])
    })?;
    match kind {
        CameraKind::Orbit => {
            t.only(&["kind", "distance", "pitch_deg", "yaw_deg", "target", "limits"])?;
            let course = OrbitCamera::course_sample();
            let limits = match t.get("limits") {
                Some(v) => read_limits(&v.table()?)?,
                None => course.limits,
            };
            let pitch_deg = t.or("pitch_deg", course.pitch_deg, |v| v.f32(Rule::Finite))?;
            within_limits(t, "pitch_deg", pitch_deg, limits.pitch_min_deg, limits.pitch_max_deg)?;
            let distance = t.or("distance", course.distance, |v| v.f32(Rule::Positive))?;
            within_limits(t, "distance", distance, limits.distance_min, limits.distance_max)?;
            Ok(Camera::Orbit(OrbitCamera {
                yaw_deg: wrap_degrees(t.or("yaw_deg", course.yaw_deg, |v| v.f32(Rule::Finite))?),
                pitch_deg,
                distance,
                target: t.or("target", course.target, Value::vec3)?,
                limits,
            }))
        }
        CameraKind::LookAt => {
            t.only(&["kind", "eye", "target", "up"])?;
            let eye_value = t.require("eye")?;
            let eye = eye_value.vec3()?;
            let target = t.or("target", Vec3::ZERO, Value::vec3)?;
            let up = t.or("up", Vec3::Y, Value::direction)?;
            // The core's own checks, so that every camera that loads is one gluLookAt can build
            // (an up vector within LOOK_AT_MIN_UP_ANGLE_DEG of the view is refused there).
            look_at(eye, target, up).map_err(|e| {
                let at = match e {
                    TransformError::UpParallelToView { .. } => t.get("up"),
                    _ => None,
                };
                at.unwrap_or(eye_value).error(ErrorKind::Transform(e))
            })?;
            Ok(Camera::LookAt { eye, target, up })
        }
    }
}

/// `Ok` when `x`, the value of `key` in `t` (or its default), lies in `[min, max]`.
fn within_limits(t: &Table<'_>, key: &str, x: f32, min: f32, max: f32) -> Result<(), SceneError> {
    if (min..=max).contains(&x) {
        return Ok(());
    }
    let rule = Rule::Between { min: f64::from(min), max: f64::from(max) };
    Err(match t.get(key) {
        Some(v) => v.bad(rule),
        // The default lies outside limits the file set: say so at the camera table.
        None => t.error(ErrorKind::BadValue { rule, got: format!("{key} = {x} (the default)") }),
    })
}

fn read_limits(t: &Table<'_>) -> Result<CameraLimits, SceneError> {
    t.only(&[
        "pitch_min_deg",
        "pitch_max_deg",
        "distance_min",
        "distance_max",
        "rotate_deg_per_px",
        "zoom_per_px",
        "yaw_enabled",
    ])?;
    let d = CameraLimits::default();
    let pitch = |v: &Value<'_>| v.f32(Rule::Between { min: -90.0, max: 90.0 });
    let pitch_min_deg = t.or("pitch_min_deg", d.pitch_min_deg, pitch)?;
    let pitch_max_deg = t.or("pitch_max_deg", d.pitch_max_deg, pitch)?;
    if pitch_min_deg > pitch_max_deg {
        // The defaults are in order and every allowed maximum is ≥ −90, so `pitch_min_deg` is given.
        let rule = Rule::NotAbove { key: "pitch_max_deg", value: f64::from(pitch_max_deg) };
        return Err(t.require("pitch_min_deg")?.bad(rule));
    }
    let distance_min = t.or("distance_min", d.distance_min, |v| v.f32(Rule::Positive))?;
    // May be `inf` (no limit, the default); with the default, it exceeds every finite minimum.
    let distance_max = t.or("distance_max", d.distance_max, |v| {
        v.f32(Rule::GreaterThan { key: "distance_min", value: f64::from(distance_min) })
    })?;
    Ok(CameraLimits {
        pitch_min_deg,
        pitch_max_deg,
        distance_min,
        distance_max,
        rotate_deg_per_px: t
            .or("rotate_deg_per_px", d.rotate_deg_per_px, |v| v.f32(Rule::Finite))?,
        zoom_per_px: t.or("zoom_per_px", d.zoom_per_px, |v| v.f32(Rule::Finite))?,
        yaw_enabled: t.or("yaw_enabled", d.yaw_enabled, Value::bool)?,
    })
}

/// `[projection]`; `aspect` is the window's width / height, which gluPerspective takes too.
fn read_projection(t: &Table<'_>, aspect: f32) -> Result<Projection, SceneError> {
    t.only(&["fovy_deg", "near", "far"])?;
    let d = COURSE_PROJECTION;
    // One rule for every value, with its reason: the limit of every scene (gluPerspective
    // itself takes (0, 180)).
    let fovy_deg = t.or("fovy_deg", d.fovy_deg, |v| {
        let fovy_deg = v.f32(Rule::Finite)?;
        if (crate::MIN_FOVY_DEG..=crate::MAX_FOVY_DEG).contains(&fovy_deg) {
            Ok(fovy_deg)
        } else {
            Err(v.error(ErrorKind::Limit(crate::LimitError::FieldOfView { fovy_deg })))
        }
    })?;
    let near = t.or("near", d.near, |v| v.f32(Rule::Positive))?;
    let far = t.or("far", d.far, |v| {
        let far = v.f32(Rule::Positive)?;
        if far > near {
            Ok(far)
        } else {
            Err(v.bad(Rule::GreaterThan { key: "near", value: f64::from(near) }))
        }
    })?;
    if far <= near {
        // `far` left at its default of 500 with `near` ≥ 500.
        let rule = Rule::Inside { min: 0.0, max: f64::from(far) };
        return Err(t.require("near")?.bad(rule));
    }
    // The core's own checks (a subnormal `near`, a matrix entry that over- or underflows f32), so
    // every projection that loads is one gluPerspective can build for this window.
    perspective(fovy_deg, aspect, near, far).map_err(|e| {
        let key = match e {
            TransformError::NearPlane { .. } => "near",
            TransformError::FarPlane { .. } | TransformError::DepthRange { .. } => "far",
            // The field of view, or an aspect ratio that only an extreme field of view makes
            // overflow (neither within [MIN_FOVY_DEG, MAX_FOVY_DEG], which is checked above).
            _ => "fovy_deg",
        };
        match t.get(key) {
            Some(v) => v.error(ErrorKind::Transform(e)),
            None => t.error(ErrorKind::Transform(e)),
        }
    })?;
    Ok(Projection { fovy_deg, near, far })
}

/// `[render]`.
struct Render {
    shading: Shading,
    light_model: LightModel,
    global_ambient: Rgb,
    cull_back_faces: bool,
}

impl Default for Render {
    /// The course's: Gouraud, OpenGL's lighting with an infinite viewer, global ambient 0.2, culling.
    fn default() -> Render {
        Render {
            shading: Shading::Gouraud,
            light_model: LightModel::OpenGl { local_viewer: false },
            global_ambient: Rgb::splat(0.2),
            cull_back_faces: true,
        }
    }
}

#[derive(Clone, Copy)]
enum ModelKind {
    OpenGl,
    Lecture,
}

fn read_render(t: &Table<'_>) -> Result<Render, SceneError> {
    t.only(&[
        "shading",
        "light_model",
        "specular",
        "local_viewer",
        "global_ambient",
        "cull_back_faces",
    ])?;
    let d = Render::default();
    let shading = t.or("shading", d.shading, |v| {
        v.choice(&[
            ("flat", Shading::Flat),
            ("gouraud", Shading::Gouraud),
            ("phong", Shading::Phong),
        ])
    })?;
    let model = t.or("light_model", ModelKind::OpenGl, |v| {
        v.choice(&[("opengl", ModelKind::OpenGl), ("lecture", ModelKind::Lecture)])
    })?;
    let local_viewer = t.or("local_viewer", false, Value::bool)?;
    let specular = t.get("specular");
    let light_model = match model {
        ModelKind::OpenGl => {
            if let Some(v) = specular {
                return Err(v.error(ErrorKind::SpecularNeedsLectureModel));
            }
            LightModel::OpenGl { local_viewer }
        }
        ModelKind::Lecture => LightModel::Lecture {
            specular: specular.map_or(Ok(Specular::default()), |v| {
                v.choice(&[("phong", Specular::Phong), ("blinn", Specular::Blinn)])
            })?,
            local_viewer,
        },
    };
    Ok(Render {
        shading,
        light_model,
        global_ambient: t.or("global_ambient", d.global_ambient, Value::color)?,
        cull_back_faces: t.or("cull_back_faces", d.cull_back_faces, Value::bool)?,
    })
}

/// The most characters a name (the scene's, an object's, a material's) may have: names label
/// tables, windows and messages.
pub const MAX_NAME_CHARS: usize = 64;

/// A name: a string of at most [`MAX_NAME_CHARS`] characters.
fn read_name(v: &Value<'_>) -> Result<String, SceneError> {
    checked_name(v.str()?, v)
}

/// `name` (written at `v`: the value, or the table a key names) if it has at most
/// [`MAX_NAME_CHARS`] characters and no control character (`cg inspect` printed an ESC in a
/// name to the terminal as it was: an escape sequence).
pub(super) fn checked_name(name: &str, v: &Value<'_>) -> Result<String, SceneError> {
    let chars = name.chars().count();
    if chars > MAX_NAME_CHARS {
        return Err(v.error(ErrorKind::NameTooLong { chars, max: MAX_NAME_CHARS }));
    }
    if let Some((i, c)) = name.chars().enumerate().find(|(_, c)| c.is_control()) {
        return Err(v.error(ErrorKind::NameControl { code: u32::from(c), place: i + 1 }));
    }
    Ok(name.to_owned())
}

fn read_object(
    t: &Table<'_>,
    materials: &HashMap<String, Material>,
    base: &Path,
) -> Result<ObjectSpec, SceneError> {
    t.only(&["name", "shape", "mesh", "weld", "normals", "material", "transform", "texture"])?;
    let name = read_name(&t.require("name")?)?;
    let geometry = match (t.get("shape"), t.get("mesh")) {
        (Some(_), Some(mesh)) => return Err(mesh.error(ErrorKind::ShapeAndMesh)),
        (None, None) => return Err(t.error(ErrorKind::NoGeometry)),
        (Some(shape), None) => {
            let (spec, at) = ShapeSpec::read(&shape)?;
            Geometry::Shape(spec, at)
        }
        (None, Some(mesh)) => Geometry::Obj(base.join(mesh.str()?), mesh.at()),
    };
    let normals = t.or("normals", NormalSource::Face, read_normals)?;
    let normals_at = t.get("normals").map_or_else(|| t.at(), |v| v.at());
    let material = match t.get("material") {
        None => Material::default(),
        Some(v) if v.is_str() => {
            let name = v.str()?;
            materials.get(name).cloned().ok_or_else(|| {
                v.error(ErrorKind::UnknownMaterial {
                    name: name.to_owned(),
                    suggestion: crate::error::closest(name, materials.keys().map(String::as_str))
                        .map(str::to_owned),
                })
            })?
        }
        Some(v) if v.is_table() => read_material(&v.table()?)?,
        Some(v) => return Err(v.wrong_type(Expected::Material)),
    };
    let transform = match t.get("transform") {
        None => MatrixProduct::default(),
        Some(v) => MatrixProduct {
            factors: v
                .array(Expected::ArrayOfTables)?
                .iter()
                .map(read_step)
                .collect::<Result<_, _>>()?,
        },
    };
    let texture = t.optional("texture", |v| read_texture(v, base))?;
    let weld = t.optional("weld", read_weld)?.flatten().zip(t.get("weld").map(|v| v.at()));
    Ok(ObjectSpec { name, geometry, weld, normals, normals_at, material, transform, texture })
}

/// `weld = true` (bit-equal positions), `weld = false`, or `weld = <tolerance ≥ 0>`.
fn read_weld(v: &Value<'_>) -> Result<Option<f32>, SceneError> {
    if v.is_bool() {
        return Ok(v.bool()?.then_some(0.0));
    }
    if v.is_number() {
        return v.f32(Rule::NonNegative).map(Some);
    }
    Err(v.wrong_type(Expected::Weld))
}

/// The crease angle of `normals = "smooth"` and of the table form without `crease_deg`: edges
/// whose faces meet at more than 30° stay hard (docs/numerics.md row 5). `crease_deg = 180` smooths
/// every edge.
const DEFAULT_CREASE_DEG: f32 = 30.0;

fn read_normals(v: &Value<'_>) -> Result<NormalSource, SceneError> {
    if v.is_table() {
        let t = v.table()?;
        t.only(&["weighting", "crease_deg"])?;
        return Ok(NormalSource::Vertex {
            weighting: t.or("weighting", Weighting::Angle, |w| {
                w.choice(&[
                    ("uniform", Weighting::Uniform),
                    ("area", Weighting::Area),
                    ("angle", Weighting::Angle),
                    ("max", Weighting::Max),
                ])
            })?,
            crease_deg: Some(t.or("crease_deg", DEFAULT_CREASE_DEG, |c| {
                c.f32(Rule::Between { min: 0.0, max: 180.0 })
            })?),
        });
    }
    if !v.is_str() {
        return Err(v.wrong_type(Expected::Normals));
    }
    let smooth =
        NormalSource::Vertex { weighting: Weighting::Angle, crease_deg: Some(DEFAULT_CREASE_DEG) };
    v.choice(&[("face", NormalSource::Face), ("given", NormalSource::Given), ("smooth", smooth)])
}

/// One transform step: `{ translate = [x, y, z] }`, `{ rotate_deg = a, axis = [x, y, z] }`,
/// `{ rotate_x_deg = a }` (and y, z) or `{ scale = [x, y, z] }`.
fn read_step(v: &Value<'_>) -> Result<Factor, SceneError> {
    let t = v.table()?;
    t.only(&[
        "translate",
        "rotate_deg",
        "axis",
        "rotate_x_deg",
        "rotate_y_deg",
        "rotate_z_deg",
        "scale",
    ])?;
    let keys = t.keys();
    let ops: Vec<&str> = keys.iter().copied().filter(|&k| k != "axis").collect();
    let axis_allowed = ops == ["rotate_deg"];
    if ops.len() != 1 || (t.has("axis") && !axis_allowed) {
        return Err(t.error(ErrorKind::TransformStep {
            found: keys.iter().map(|k| (*k).to_owned()).collect(),
        }));
    }
    let param = |value: f32| Param { value, symbol: None };
    let xyz = |key: &str| t.require(key)?.vec3().map(|v| v.to_array().map(param));
    let angle = |key: &str| t.require(key)?.f32(Rule::Finite).map(param);
    Ok(match ops[0] {
        "translate" => Factor::Translate(xyz("translate")?),
        "scale" => Factor::Scale(xyz("scale")?),
        // Through Factor::rotate_deg, so an axis along +X, +Y or +Z prints as Rx, Ry or Rz.
        "rotate_deg" => {
            let axis = t.require("axis")?.direction()?;
            Factor::rotate_deg(angle("rotate_deg")?.value, axis)
        }
        "rotate_x_deg" => Factor::Rotate { axis: Axis::X, angle_deg: angle("rotate_x_deg")? },
        "rotate_y_deg" => Factor::Rotate { axis: Axis::Y, angle_deg: angle("rotate_y_deg")? },
        _ => Factor::Rotate { axis: Axis::Z, angle_deg: angle("rotate_z_deg")? },
    })
}

fn read_texture(v: &Value<'_>, base: &Path) -> Result<TextureSpec, SceneError> {
    let t = v.table()?;
    t.only(&["image", "filter", "wrap", "env"])?;
    let image = t.require("image")?;
    let filter = t.or("filter", Filter::Bilinear, |f| {
        f.choice(&[("nearest", Filter::Nearest), ("bilinear", Filter::Bilinear)])
    })?;
    let wraps = [("repeat", Wrap::Repeat), ("clamp", Wrap::Clamp)];
    let (wrap_u, wrap_v) = t.or("wrap", (Wrap::Repeat, Wrap::Repeat), |w| {
        if w.is_str() {
            let both = w.choice(&wraps)?;
            return Ok((both, both));
        }
        let [u, v] = w.array_of(Expected::Wrap)?;
        Ok((u.choice(&wraps)?, v.choice(&wraps)?))
    })?;
    let env = t.or("env", TexEnv::Modulate, |e| {
        e.choice(&[("modulate", TexEnv::Modulate), ("replace", TexEnv::Replace)])
    })?;
    Ok(TextureSpec {
        image: base.join(image.str()?),
        image_at: image.at(),
        at: t.at(),
        sampler: Sampler { filter, wrap_u, wrap_v },
        env,
    })
}

#[cfg(test)]
mod tests;

/// The first two vertices `remap` makes one whose texture coordinates (when `textured`) or
/// normals (when `given`) differ, as the error that says so.
fn seam_merged(
    mesh: &cg_core::mesh::Mesh,
    remap: &[u32],
    textured: bool,
    given: bool,
) -> Option<ErrorKind> {
    // The first old vertex of each new one: the one whose attributes the welded mesh keeps.
    let mut first: Vec<Option<usize>> = vec![None; remap.len()];
    for (old, &new) in remap.iter().enumerate() {
        let kept = *first[new as usize].get_or_insert(old);
        if kept == old {
            continue;
        }
        let differs =
            |a: Option<&[cg_core::glam::Vec2]>| a.is_some_and(|a| a.get(old) != a.get(kept));
        if textured && differs(mesh.uvs.as_deref()) {
            return Some(ErrorKind::WeldMergesSeam { uvs: true, kept, merged: old });
        }
        let normals_differ = mesh.normals.as_deref().is_some_and(|n| n.get(old) != n.get(kept));
        if given && normals_differ {
            return Some(ErrorKind::WeldMergesSeam { uvs: false, kept, merged: old });
        }
    }
    None
}
