//! A kit [`Scene`] as the command script of `tools/glref/glref.c`: the OpenGL 1.x calls the
//! course's program would make to draw it, one per line.

use std::fmt::Write as _;

use cg_core::Rgb;
use cg_core::glam::{Mat4, Vec2, Vec3};
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material};
use cg_core::math::try_normalize;
use cg_core::normals::face_normal;
use cg_core::scene::{Prepared, Scene, Shading};
use cg_core::texture::{Filter, TexEnv, Texture, TextureError, Wrap};
use cg_core::transform::perspective_gl;

use crate::error::GlRefError;

/// OpenGL's lights: GL_LIGHT0 … GL_LIGHT7 (GL_MAX_LIGHTS is 8 in Mesa).
pub const MAX_LIGHTS: usize = 8;

/// The largest image side drawn: the kit's [`cg_core::image::MAX_SIDE`], which is also what
/// OSMesa draws (OSMESA_MAX_WIDTH and OSMESA_MAX_HEIGHT in Mesa 22) and GL_MAX_TEXTURE_SIZE here.
pub const MAX_SIDE: u32 = cg_core::image::MAX_SIDE;
const _: () = assert!(MAX_SIDE == 16384, "update the texture-size message in `write_texture`");

/// The most textures one script defines (`MAX_TEXTURES` in glref.c).
const MAX_TEXTURES: usize = 4096;

/// The largest GL_SHININESS and GL_SPOT_EXPONENT OpenGL 1.x accepts.
const MAX_EXPONENT: f32 = 128.0;

/// The script being written: text, and the check that every number is finite.
struct Script {
    text: String,
}

impl Script {
    fn line(&mut self, words: &str) {
        self.text.push_str(words);
        self.text.push('\n');
    }

    /// `name` followed by `values`, each checked finite (`what` names them in the error).
    /// Rust prints the shortest decimal that reads back as the same f32, so the C program's
    /// `strtod` gets every value exactly.
    fn numbers(
        &mut self,
        name: &str,
        values: &[f32],
        what: impl Fn() -> String,
    ) -> Result<(), GlRefError> {
        if let Some(&value) = values.iter().find(|v| !v.is_finite()) {
            return Err(GlRefError::NotFinite { what: what(), value });
        }
        self.text.push_str(name);
        for v in values {
            // Writing to a String cannot fail.
            let _ = write!(self.text, " {v}");
        }
        self.text.push('\n');
        Ok(())
    }

    fn rgb(&mut self, name: &str, c: Rgb, what: impl Fn() -> String) -> Result<(), GlRefError> {
        self.numbers(name, &c.to_array(), what)
    }

    fn vec3(&mut self, name: &str, v: Vec3, what: impl Fn() -> String) -> Result<(), GlRefError> {
        self.numbers(name, &v.to_array(), what)
    }

    fn matrix(&mut self, name: &str, m: Mat4, what: impl Fn() -> String) -> Result<(), GlRefError> {
        self.numbers(name, &m.to_cols_array(), what)
    }
}

/// The command script that draws `scene` (see the top of `tools/glref/glref.c` for the commands).
///
/// What it says, in the order the course's program does it: the viewport and clear colour; the
/// projection `perspective_gl(fovy, width / height, near, far)` (gluPerspective's matrix); the view
/// matrix loaded into GL_MODELVIEW, and *then* the lights, so GL transforms their positions and
/// spot directions to eye space and they stay fixed in the world; the light model; the shade model
/// and culling; then each object between `push` (glPushMatrix + glMultMatrixf(model)) and `pop`,
/// with its material, texture and triangles.
///
/// - Lighting: [`LightModel::OpenGl`] only; the lecture's model has no GL equivalent
///   ([`GlRefError::LectureLightModel`]). Every light is sent as its
///   [`Light::point_lights`] (area lights as their samples), at most [`MAX_LIGHTS`]; a spot light
///   whose direction is zero lights nothing in the kit, and is left out. A cut-off above 90°
///   (or NaN) becomes GL's 180 (no cone); a negative or NaN spot exponent or shininess is 0 (as
///   in the kit); one above 128 is an error, as are negative attenuation coefficients. Light
///   directions are sent normalised (GL normalises them anyway, in f32).
/// - Material: `ka`, `kd`, `ks`, `shininess`, `emission` by glMaterialfv (the kit's `color` is
///   `ka = kd`, so this equals GL_COLOR_MATERIAL with glColor). A mesh with per-vertex colours
///   uses GL_COLOR_MATERIAL (GL_AMBIENT_AND_DIFFUSE) and glColor3f per vertex instead. `kr`, `kt`
///   and `eta` are the ray tracer's; OpenGL ignores them.
/// - Shading: [`Shading::Gouraud`] is GL_SMOOTH and [`Shading::Flat`] GL_FLAT, both with the
///   prepared mesh's normals (the face normal, [`face_normal`], where a vertex has none): the
///   course's program changes only glShadeModel. Under GL_FLAT GL lights each corner and colours
///   the whole triangle with its **last** (provoking) vertex's colour — lit at that vertex's
///   position with its normal and glColor — which the kit's renderers reproduce in OpenGL's
///   model (each face is one glBegin(GL_TRIANGLES) triangle here, so its provoking vertex is
///   the face's third corner); [`Shading::Phong`] has no GL equivalent
///   ([`GlRefError::PhongShading`]).
/// - Normals are given in model space and transformed by GL itself (the inverse transpose of the
///   modelview matrix, then GL_NORMALIZE). A mirroring model matrix ([`Prepared::mirrored`])
///   gets glFrontFace(GL_CW), so its outside stays the front as in the kit's renderers.
/// - Zero-area triangles are left out: they cover no pixel, and their normal does not exist.
/// - Textures: uploaded as RGBA8 with row 0 at the bottom (as glTexImage2D expects), with the
///   object's filter (GL_NEAREST / GL_LINEAR, no mipmaps), wrap (GL_REPEAT / GL_CLAMP_TO_EDGE)
///   and environment (GL_MODULATE / GL_REPLACE).
///
/// # Errors
/// The cases above; an image side of 0 or above [`MAX_SIDE`]; an invalid projection or camera;
/// an object that cannot be prepared ([`Scene::prepare`]); a texture that does not exist, or a
/// textured mesh without texture coordinates; a NaN or infinite number anywhere GL would see it.
pub fn script(scene: &Scene) -> Result<String, GlRefError> {
    let LightModel::OpenGl { local_viewer } = scene.light_model else {
        return Err(GlRefError::LectureLightModel);
    };
    let flat = match scene.shading {
        Shading::Flat => true,
        Shading::Gouraud => false,
        Shading::Phong => return Err(GlRefError::PhongShading),
    };
    // Each point light with the index of the scene's light it comes from (for messages).
    let lights: Vec<(usize, Light)> = scene
        .lights
        .iter()
        .enumerate()
        .flat_map(|(index, light)| light.point_lights().map(move |p| (index, p)))
        .collect();
    if lights.len() > MAX_LIGHTS {
        return Err(GlRefError::TooManyLights { count: lights.len() });
    }
    let (width, height) = (scene.width, scene.height);
    if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
        return Err(GlRefError::Size { width, height, max: MAX_SIDE });
    }
    let p = &scene.projection;
    let projection = perspective_gl(p.fovy_deg, scene.aspect(), p.near, p.far)
        .map_err(GlRefError::Projection)?;
    let view = scene.view_product().and_then(|v| v.matrix()).map_err(GlRefError::View)?;
    let objects = scene.prepare().map_err(GlRefError::Prepare)?;

    let mut s = Script { text: String::new() };
    s.line(&format!(
        "# scene \"{}\", drawn by OpenGL 1.x fixed-function calls",
        one_line(&scene.name)
    ));
    s.line(&format!("size {width} {height}"));
    s.rgb("clear", scene.clear_color, || "the clear colour".into())?;
    s.matrix("projection", projection, || "the projection matrix".into())?;
    s.matrix("view", view, || "the view matrix".into())?;
    s.line("lighting on");
    s.rgb("light_model_ambient", scene.global_ambient, || "the global ambient light".into())?;
    s.line(if local_viewer {
        "light_model_local_viewer on"
    } else {
        "light_model_local_viewer off"
    });
    s.line("# lights, given in world space: GL transforms them by the view matrix loaded above");
    let mut slot = 0;
    for (index, light) in &lights {
        if write_light(&mut s, slot, *index, light)? {
            slot += 1;
        }
    }
    s.line(if flat { "shade_model flat" } else { "shade_model smooth" });
    s.line(if scene.cull_back_faces { "cull_face on" } else { "cull_face off" });

    // The script's texture ID of each scene texture, given in the order of first use.
    let mut texture_ids = vec![None; scene.textures.len()];
    for object in &objects {
        write_object(&mut s, scene, object, &mut texture_ids)?;
    }
    s.line("finish");
    Ok(s.text)
}

/// GL_LIGHT`slot` from one point light (`index`: its light in the scene, for messages).
/// Returns `false` when the light lights nothing (a spot with a zero direction) and was left out.
fn write_light(
    s: &mut Script,
    slot: usize,
    index: usize,
    light: &Light,
) -> Result<bool, GlRefError> {
    let what = |name: &str| format!("light {index}: {name}");
    let (position, spot) = match light.kind {
        LightKind::Directional { to_light } => {
            // GL normalises the direction itself, in f32; the kit's try_normalize also handles
            // lengths whose square would underflow or overflow there (1e-30, 1e30).
            let Some(to_light) = try_normalize(to_light) else {
                return Err(if to_light.is_finite() {
                    GlRefError::ZeroDirection { light: index }
                } else {
                    not_finite(what("direction"), to_light)
                });
            };
            (to_light.extend(0.0), None)
        }
        LightKind::Point { position } => (position.extend(1.0), None),
        LightKind::Spot { position, direction, cutoff_deg, exponent, .. } => {
            let Some(direction) = try_normalize(direction) else {
                if !direction.is_finite() {
                    return Err(not_finite(what("spot direction"), direction));
                }
                // The kit's spot factor is 0 for a zero direction: no light at all.
                return Ok(false);
            };
            // inner_deg is the lecture model's; OpenGL has only the cut-off and the exponent.
            let cutoff =
                if cutoff_deg.is_nan() || cutoff_deg > 90.0 { 180.0 } else { cutoff_deg.max(0.0) };
            let exponent = exponent_for_gl(exponent, || what("spot exponent"))?;
            (position.extend(1.0), Some((direction, cutoff, exponent)))
        }
        // point_lights() never yields an area light.
        LightKind::Area { .. } => return Ok(false),
    };
    s.line(&format!("# GL_LIGHT{slot} from light {index}"));
    s.numbers(&format!("light {slot} position"), &position.to_array(), || what("position"))?;
    s.rgb(&format!("light {slot} ambient"), light.ambient, || what("ambient"))?;
    s.rgb(&format!("light {slot} diffuse"), light.diffuse, || what("diffuse"))?;
    s.rgb(&format!("light {slot} specular"), light.specular, || what("specular"))?;
    let (direction, cutoff, exponent) = spot.unwrap_or((Vec3::NEG_Z, 180.0, 0.0));
    s.vec3(&format!("light {slot} spot_direction"), direction, || what("spot direction"))?;
    s.numbers(&format!("light {slot} spot_cutoff"), &[cutoff], || what("spot cut-off"))?;
    s.numbers(&format!("light {slot} spot_exponent"), &[exponent], || what("spot exponent"))?;
    // GL ignores the attenuation of directional lights; send its default so no stray value of
    // the scene can raise GL_INVALID_VALUE.
    let att = match light.kind {
        LightKind::Directional { .. } => Attenuation::default(),
        _ => light.attenuation,
    };
    let coefficients = [att.constant, att.linear, att.quadratic];
    for (k, name) in coefficients.iter().zip(["constant", "linear", "quadratic"]) {
        if *k < 0.0 {
            return Err(GlRefError::OutsideGlRange {
                what: what(&format!("{name} attenuation")),
                value: *k,
                range: "values ≥ 0",
            });
        }
    }
    s.numbers(&format!("light {slot} attenuation"), &coefficients, || what("attenuation"))?;
    Ok(true)
}

/// A spot exponent or shininess as GL takes it: negative or NaN is 0 (the kit's rule), above 128
/// is an error (GL_INVALID_VALUE).
fn exponent_for_gl(value: f32, what: impl Fn() -> String) -> Result<f32, GlRefError> {
    if value > MAX_EXPONENT {
        return Err(GlRefError::OutsideGlRange { what: what(), value, range: "0 to 128" });
    }
    Ok(if value > 0.0 { value } else { 0.0 })
}

fn not_finite(what: String, v: Vec3) -> GlRefError {
    let value = v.to_array().into_iter().find(|x| !x.is_finite()).unwrap_or(f32::NAN);
    GlRefError::NotFinite { what, value }
}

/// One object: push its model matrix, set its material and texture, draw its triangles, pop.
fn write_object(
    s: &mut Script,
    scene: &Scene,
    prepared: &Prepared<'_>,
    texture_ids: &mut [Option<usize>],
) -> Result<(), GlRefError> {
    let object = prepared.object;
    let name = one_line(&object.name);
    let what = |item: &str| format!("object \"{name}\": {item}");
    let mesh = &prepared.mesh;

    // The texture first: glTexImage2D once per texture, before the object's matrix push.
    let mut texture_id = None;
    if let Some(use_) = &object.texture {
        let texture =
            scene.textures.get(use_.texture).ok_or_else(|| GlRefError::MissingTexture {
                object: object.name.clone(),
                texture: use_.texture,
                count: scene.textures.len(),
            })?;
        if mesh.uvs.is_none() {
            return Err(GlRefError::MissingTextureCoordinates { object: object.name.clone() });
        }
        let id = match texture_ids[use_.texture] {
            Some(id) => id,
            None => {
                let id = texture_ids.iter().flatten().count();
                if id >= MAX_TEXTURES {
                    return Err(GlRefError::OutsideGlRange {
                        what: "the number of textures used".into(),
                        value: (id + 1) as f32,
                        range: "at most 4096 textures",
                    });
                }
                write_texture(s, id, use_.texture, texture)?;
                texture_ids[use_.texture] = Some(id);
                id
            }
        };
        texture_id = Some((id, use_));
    }

    s.line(&format!("# object \"{name}\""));
    s.matrix("push", prepared.model, || what("model matrix"))?;
    s.line(if prepared.mirrored { "front_face cw" } else { "front_face ccw" });
    let colors = mesh.colors.as_deref();
    write_material(s, &object.material, colors.is_some(), &what)?;
    match texture_id {
        Some((id, use_)) => {
            let filter = match use_.sampler.filter {
                Filter::Nearest => "nearest",
                Filter::Bilinear => "linear",
            };
            let wrap = |w: Wrap| match w {
                Wrap::Repeat => "repeat",
                Wrap::Clamp => "clamp",
            };
            let env = match use_.env {
                TexEnv::Modulate => "modulate",
                TexEnv::Replace => "replace",
            };
            s.line(&format!(
                "texture_use {id} {filter} {} {} {env}",
                wrap(use_.sampler.wrap_u),
                wrap(use_.sampler.wrap_v)
            ));
        }
        None => s.line("texture_off"),
    }

    let normals = mesh.normals.as_deref().unwrap_or_default();
    let uvs = if object.texture.is_some() { mesh.uvs.as_deref() } else { None };
    s.line("begin");
    for (f, face) in mesh.faces.iter().enumerate() {
        let [a, b, c] = face.map(|i| mesh.positions[i as usize]);
        // Zero-area triangles cover no pixel and have no normal: leave them out.
        let Some(n_face) = face_normal(a, b, c) else { continue };
        for (corner, &i) in face.iter().enumerate() {
            let i = i as usize;
            let vertex = || what(&format!("face F{f}, corner {corner} (vertex V{i})"));
            let n = normals.get(i).copied().unwrap_or(n_face);
            s.vec3("n", n, || format!("{} normal", vertex()))?;
            if let Some(uvs) = uvs {
                let uv = uvs.get(i).copied().unwrap_or(Vec2::ZERO);
                s.numbers("t", &uv.to_array(), || format!("{} texture coordinate", vertex()))?;
            }
            if let Some(colors) = colors {
                let color = colors.get(i).copied().unwrap_or(Rgb::ONE);
                s.rgb("c", color, || format!("{} colour", vertex()))?;
            }
            s.vec3("v", mesh.positions[i], || format!("{} position", vertex()))?;
        }
    }
    s.line("end");
    s.line("pop");
    Ok(())
}

/// glMaterialfv for front and back faces; with per-vertex colours, GL_COLOR_MATERIAL sets the
/// ambient and diffuse reflectance from glColor instead.
fn write_material(
    s: &mut Script,
    m: &Material,
    vertex_colors: bool,
    what: &impl Fn(&str) -> String,
) -> Result<(), GlRefError> {
    if vertex_colors {
        s.line("color_material on");
    } else {
        s.line("color_material off");
        s.rgb("material ambient", m.ka, || what("ka"))?;
        s.rgb("material diffuse", m.kd, || what("kd"))?;
    }
    s.rgb("material specular", m.ks, || what("ks"))?;
    let shininess = exponent_for_gl(m.shininess, || what("shininess"))?;
    s.numbers("material shininess", &[shininess], || what("shininess"))?;
    s.rgb("material emission", m.emission, || what("emission"))
}

/// `texture ID W H` and its rows, the bottom row (t = 0) first, as glTexImage2D expects and as
/// [`Texture::texels`] stores them.
/// `index` is the texture's index in the scene (for messages), `id` its ID in the script.
fn write_texture(
    s: &mut Script,
    id: usize,
    index: usize,
    texture: &Texture,
) -> Result<(), GlRefError> {
    let (width, height) = (texture.width, texture.height);
    // A texture built by hand may skip Texture::new's checks: make the same ones here.
    if width == 0 || height == 0 {
        return Err(GlRefError::BadTexture {
            texture: index,
            source: TextureError::ZeroSize { width, height },
        });
    }
    let expected = u64::from(width) * u64::from(height);
    if texture.texels.len() as u64 != expected {
        let got = texture.texels.len();
        let source = TextureError::TexelCount { width, height, expected, got };
        return Err(GlRefError::BadTexture { texture: index, source });
    }
    if width > MAX_SIDE || height > MAX_SIDE {
        return Err(GlRefError::OutsideGlRange {
            what: format!("texture {index}: its size {width}×{height}"),
            value: width.max(height) as f32,
            // The number in the text is MAX_SIDE (checked at compile time below).
            range: "sides up to 16384 texels (GL_MAX_TEXTURE_SIZE)",
        });
    }
    s.line(&format!("texture {id} {width} {height}"));
    let w = width as usize;
    for row in texture.texels.chunks(w) {
        let mut line = String::with_capacity(7 + 8 * w);
        line.push_str("texels ");
        for [r, g, b, a] in row {
            let _ = write!(line, "{r:02x}{g:02x}{b:02x}{a:02x}");
        }
        s.line(&line);
    }
    Ok(())
}

/// A name made safe for a comment line.
fn one_line(name: &str) -> String {
    name.chars().map(|c| if c.is_control() { ' ' } else { c }).collect()
}
