//! The shading images (s.t6): the kit's CPU rasterizer finds, for every pixel, which face it sees
//! and the weights of that face's corners there; the student's `shade_pixel` decides the colour.
//!
//! The rasterizer's hook ([`cg_raster::Lighting`]) decides only *how* a point is lit: *where* the
//! lighting happens (per face, per vertex, per pixel) is the renderer's business. The lecture's
//! point — flat lights the face normal, Gouraud the vertices and interpolates colours, Phong
//! interpolates normals and lights every pixel — is that "where". So the kit draws two extra
//! images through the hook, without lighting (a G-buffer):
//!
//! 1. every face on its own three vertices, coloured with its number, drawn flat: the face seen
//!    through each pixel;
//! 2. the same faces with the colours (1, 0, 0), (0, 1, 0), (0, 0, 1) at their corners, drawn
//!    Gouraud: the rasterizer interpolates them perspective-correctly, so each pixel's colour *is*
//!    the weights (w₀, w₁, w₂) that the renderer's own Phong and Gouraud shading use there.
//!
//! The hook returns the material's colour unchanged, so both images come out exactly (the
//! weights are interpolated from one-hot colours: no rounding; the face numbers are multiples of
//! 1/255). Coverage, depth test and the fill rule are the renderer's, triangle for triangle, so a
//! correct `shade_pixel` reproduces the renderer's own flat, Gouraud and Phong images (the checks
//! compare them).

use cg_core::Rgb;
use cg_core::glam::{Vec2, Vec3};
use cg_core::image::Image;
use cg_core::light::{LightModel, Material, shade};
use cg_core::math::try_normalize;
use cg_core::mesh::Mesh;
use cg_core::normals::{face_normal, face_split};
use cg_core::scene::{Camera, NormalSource, Object, Projection, Scene, TextureUse};
use cg_core::texture::{Filter, Sampler, TexEnv, Texture, Wrap};
use cg_core::transform::transform_point;
use cg_raster::{Options, RenderError, SurfacePoint};

use crate::{Pixel, Shading, kit_shading};

/// One face as the renderer sees it, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceData {
    /// Which object of the scene (its index).
    pub object: usize,
    /// The face's number within the object (F-number).
    pub face: u32,
    /// The vertex numbers of its corners in the object's drawn mesh (V-numbers).
    pub vertices: [u32; 3],
    /// Corner positions.
    pub positions: [Vec3; 3],
    /// Vertex normals at the corners, as the renderer transforms them (unit, or zero).
    pub normals: [Vec3; 3],
    /// The face normal (unit, or zero for a degenerate face).
    pub face_normal: Vec3,
}

/// What every pixel of an image sees: a face and the corner weights, or nothing.
#[derive(Clone, Debug, PartialEq)]
pub struct GBuffer {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Every face of every object, objects in scene order.
    pub faces: Vec<FaceData>,
    /// Per pixel, row by row from the top: the index into `faces` and the weights.
    pub texels: Vec<Option<(u32, [f32; 3])>>,
}

impl GBuffer {
    /// The pixel's inputs for `shade_pixel`, or `None` where no face is seen.
    #[must_use]
    pub fn pixel(&self, x: u32, y: u32) -> Option<(&FaceData, Pixel)> {
        let (face, weights) =
            self.texels.get(y as usize * self.width as usize + x as usize)?.as_ref()?;
        let f = self.faces.get(*face as usize)?;
        Some((
            f,
            Pixel {
                positions: f.positions,
                normals: f.normals,
                face_normal: f.face_normal,
                weights: *weights,
            },
        ))
    }
}

fn encode(id: u32) -> Rgb {
    let c = |k: u32| ((id >> (8 * k)) & 0xff) as f32 / 255.0;
    Rgb::new(c(0), c(1), c(2))
}

fn decode(c: Rgb) -> u32 {
    let b = |x: f32| (x * 255.0).round().clamp(0.0, 255.0) as u32;
    b(c.x) | b(c.y) << 8 | b(c.z) << 16
}

/// The G-buffer of `scene` at `width × height` (see the module docs).
///
/// # Errors
/// What keeps the scene from being drawn ([`RenderError`]).
pub fn gbuffer(scene: &Scene, width: u32, height: u32) -> Result<GBuffer, RenderError> {
    let mut faces = Vec::new();
    let mut ids = scene.clone();
    ids.clear_color = Rgb::ZERO;
    let mut weights = ids.clone();
    for (o, object) in scene.objects.iter().enumerate() {
        let prepared = object.prepare().map_err(RenderError::Prepare)?;
        let mesh = &prepared.mesh;
        let normals = mesh.normals.clone().unwrap_or_default();
        let p_world: Vec<Vec3> =
            mesh.positions.iter().map(|&p| transform_point(prepared.model, p)).collect();
        let n_world: Vec<Vec3> = (0..mesh.positions.len())
            .map(|i| {
                let n = normals.get(i).copied().unwrap_or(Vec3::ZERO);
                try_normalize(prepared.normal_matrix * n)
                    .map_or(Vec3::ZERO, |n| if prepared.mirrored { -n } else { n })
            })
            .collect();
        let first = faces.len() as u32;
        for (f, face) in mesh.faces.iter().enumerate() {
            let positions = face.map(|v| p_world[v as usize]);
            let [a, b, c] = positions;
            let n =
                face_normal(a, b, c).map_or(Vec3::ZERO, |n| if prepared.mirrored { -n } else { n });
            faces.push(FaceData {
                object: o,
                face: f as u32,
                vertices: *face,
                positions,
                normals: face.map(|v| n_world[v as usize]),
                face_normal: n,
            });
        }
        let split = face_split(&Mesh { normals: None, uvs: None, colors: None, ..mesh.clone() });
        let count = split.faces.len() as u32;
        let id_colors = (0..count).flat_map(|f| [encode(first + f + 1); 3]).collect();
        let corner_colors = (0..count).flat_map(|_| [Rgb::X, Rgb::Y, Rgb::Z]).collect();
        let plain = |colors| Object {
            mesh: Mesh { colors: Some(colors), ..split.clone() },
            normals: NormalSource::Face,
            material: Material::default(),
            texture: None,
            ..object.clone()
        };
        ids.objects[o] = plain(id_colors);
        weights.objects[o] = plain(corner_colors);
    }
    let unlit = |_: &Scene, point: &SurfacePoint<'_>| point.material.kd;
    let options = |shading| Options {
        shading: Some(kit_shading(shading)),
        size: Some((width, height)),
        ..Options::default()
    };
    let id_image = cg_raster::render_with(&ids, &options(Shading::Flat), &unlit)?.image;
    let weight_image = cg_raster::render_with(&weights, &options(Shading::Gouraud), &unlit)?.image;
    let texels = id_image
        .pixels
        .iter()
        .zip(&weight_image.pixels)
        .map(|(&id, &w)| match decode(id) {
            0 => None,
            k => Some((k - 1, w.to_array())),
        })
        .collect();
    Ok(GBuffer { width, height, faces, texels })
}

/// The renderer's own image of `scene`, lit by the scene's light model
/// ([`cg_raster::SceneLighting`]), in shading mode `mode` (`None`: the scene's), at the scene's
/// size. `mode` is the student's [`Shading`], converted with [`kit_shading`].
///
/// # Errors
/// What keeps the scene from being drawn ([`RenderError`]).
pub fn kit_image(scene: &Scene, mode: Option<Shading>) -> Result<Image, RenderError> {
    let shading = mode.map(kit_shading);
    cg_raster::render(scene, &Options { shading, ..Options::default() }).map(|o| o.image)
}

/// The lighting stage of the kit for one material of `scene`: `light(p, n)` is the scene's
/// light model at `p` with unit normal `n`, clamped to `[0, 1]` — what the renderer's
/// [`cg_raster::SceneLighting`] gives, with V as the renderer takes it.
pub struct KitLight<'a> {
    scene: &'a Scene,
    material: Material,
    eye: Vec3,
    backward: Vec3,
}

impl<'a> KitLight<'a> {
    /// The kit's lighting of `material` in `scene`.
    ///
    /// # Errors
    /// An invalid camera.
    pub fn new(scene: &'a Scene, material: &Material) -> Result<KitLight<'a>, RenderError> {
        let view = scene.view_product().and_then(|v| v.matrix()).map_err(RenderError::Camera)?;
        let backward = try_normalize(Vec3::new(view.x_axis.z, view.y_axis.z, view.z_axis.z))
            .unwrap_or(Vec3::Z);
        let mut material = material.clone();
        if !scene.features().specular {
            material.ks = Rgb::ZERO;
        }
        Ok(KitLight { scene, material, eye: scene.camera.eye_position(), backward })
    }

    /// The view vector V at `p`.
    #[must_use]
    pub fn view_vector(&self, p: Vec3) -> Vec3 {
        self.scene.light_model.view_vector(p, self.eye, self.backward)
    }

    /// The lit colour at `p` with normal `n`, clamped to `[0, 1]` (NaN → 0).
    #[must_use]
    pub fn light(&self, p: Vec3, n: Vec3) -> Rgb {
        let s = self.scene;
        let v = self.view_vector(p);
        saturate(shade(s.light_model, s.global_ambient, &s.lights, &self.material, p, n, v).total())
    }
}

/// A colour clamped to `[0, 1]` per channel, NaN taken as 0 (as the renderer clamps).
#[must_use]
pub fn saturate(c: Rgb) -> Rgb {
    let channel = |x: f32| if x > 0.0 { x.min(1.0) } else { 0.0 };
    Rgb::new(channel(c.x), channel(c.y), channel(c.z))
}

/// `base` with every pixel that sees a face of an object for which `mode` gives a shading mode
/// coloured by `shade(mode, pixel)` (clamped to `[0, 1]`).
pub fn compose(
    base: &Image,
    g: &GBuffer,
    mut mode: impl FnMut(&FaceData) -> Option<Shading>,
    mut shade: impl FnMut(Shading, &FaceData, &Pixel) -> Rgb,
) -> Image {
    let mut out = base.clone();
    for y in 0..g.height {
        for x in 0..g.width {
            if let Some((face, pixel)) = g.pixel(x, y)
                && let Some(m) = mode(face)
            {
                out.set(x, y, saturate(shade(m, face, &pixel)));
            }
        }
    }
    out
}

/// A scene that shows `image` as it is: a camera looking straight at a quad that fills the view,
/// textured with the image (nearest texel, GL_REPLACE), so the renderer's output is `image`
/// pixel for pixel (to 8 bits).
///
/// # Errors
/// An image with a zero side.
pub fn screen(image: &Image, name: &str) -> Result<Scene, cg_core::texture::TextureError> {
    let (w, h) = (image.width, image.height);
    let rgba = image.to_rgba8();
    // Texture rows run from the bottom up, image rows from the top down.
    let texture =
        Texture::from_fn(w, h, |x, y| rgba[(h - 1 - y) as usize * w as usize + x as usize])?;
    let a = w as f32 / h.max(1) as f32;
    // fovy 90° at distance 2: the view is 4 high and 4·aspect wide there.
    let mesh = Mesh {
        positions: vec![
            Vec3::new(-2.0 * a, -2.0, -2.0),
            Vec3::new(2.0 * a, -2.0, -2.0),
            Vec3::new(2.0 * a, 2.0, -2.0),
            Vec3::new(-2.0 * a, 2.0, -2.0),
        ],
        faces: vec![[0, 1, 2], [0, 2, 3]],
        normals: None,
        uvs: Some(vec![
            Vec2::new(0.0, 0.0),
            Vec2::new(1.0, 0.0),
            Vec2::new(1.0, 1.0),
            Vec2::new(0.0, 1.0),
        ]),
        colors: None,
    };
    Ok(Scene {
        name: name.to_owned(),
        width: w,
        height: h,
        clear_color: Rgb::ZERO,
        camera: Camera::LookAt { eye: Vec3::ZERO, target: Vec3::NEG_Z, up: Vec3::Y },
        projection: Projection { fovy_deg: 90.0, near: 1.0, far: 10.0 },
        light_model: LightModel::OpenGl { local_viewer: false },
        global_ambient: Rgb::ZERO,
        lights: Vec::new(),
        shading: cg_core::scene::Shading::Flat,
        cull_back_faces: true,
        objects: vec![Object {
            name: "screen".to_owned(),
            mesh,
            normals: NormalSource::Face,
            material: Material::default(),
            transform: cg_core::product::MatrixProduct::identity(),
            texture: Some(TextureUse {
                texture: 0,
                sampler: Sampler {
                    filter: Filter::Nearest,
                    wrap_u: Wrap::Clamp,
                    wrap_v: Wrap::Clamp,
                },
                env: TexEnv::Replace,
            }),
            weld: None,
            analytic: None,
        }],
        textures: vec![texture],
    })
}
