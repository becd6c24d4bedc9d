//! The in-memory scene (シーン): what every renderer draws. Pure data; the TOML format that
//! describes it, and the loading of OBJ and PNG files, live in the `cg-scene` crate.

use glam::Vec3;

use crate::Rgb;
use crate::camera::OrbitCamera;
use crate::light::{Light, LightModel, Material};
use crate::mesh::Mesh;
use crate::product::MatrixProduct;
use crate::texture::{Sampler, TexEnv, Texture};

/// Flat, Gouraud or Phong shading (フラット／グロー／フォンシェーディング).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Shading {
    /// The face normal lights each face once; one colour per face.
    Flat,
    /// Vertex normals light each vertex; colours are interpolated (OpenGL's GL_SMOOTH).
    #[default]
    Gouraud,
    /// Vertex normals are interpolated and renormalised; every pixel is lit.
    Phong,
}

/// Where an object's shading normals come from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NormalSource {
    /// Each face uses its own face normal at all three corners (glNormal per face, as the course's
    /// pyramid): hard edges everywhere, whatever the shading mode.
    Face,
    /// Vertex normals averaged from face normals with `weighting`; edges whose dihedral angle
    /// exceeds `crease_deg` stay hard (`None`: no crease splitting).
    Vertex {
        /// How face normals are weighted.
        weighting: crate::normals::Weighting,
        /// Dihedral angle in degrees above which an edge stays hard; `None`: never.
        crease_deg: Option<f32>,
    },
    /// The normals stored in the mesh (from an OBJ file, or set by a student).
    Given,
}

/// The view: the course's orbit camera, or an explicit eye / target / up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Camera {
    /// The sample program's camera.
    Orbit(OrbitCamera),
    /// gluLookAt(eye, target, up).
    LookAt {
        /// Where the eye is.
        eye: Vec3,
        /// The point looked at.
        target: Vec3,
        /// Which way is up (not parallel to `target − eye`).
        up: Vec3,
    },
}

/// gluPerspective's parameters; the aspect ratio comes from the viewport.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Projection {
    /// Vertical field of view in degrees (course: 45).
    pub fovy_deg: f32,
    /// Near plane distance (course: 1).
    pub near: f32,
    /// Far plane distance (course: 500).
    pub far: f32,
}

/// A texture applied to an object.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureUse {
    /// Index into [`Scene::textures`].
    pub texture: usize,
    /// Filtering and wrapping.
    pub sampler: Sampler,
    /// How the texel combines with the lit colour.
    pub env: TexEnv,
}

/// One thing drawn in the scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// The name used in messages and reports (`pyramid`, `ground`).
    pub name: String,
    /// The mesh as authored (the vertex and face tables of the report), in model space.
    pub mesh: Mesh,
    /// Where shading normals come from.
    pub normals: NormalSource,
    /// The surface.
    pub material: Material,
    /// Model transform (モデル座標系→ワールド座標系) as named factors, in program order.
    pub transform: MatrixProduct,
    /// An optional texture.
    pub texture: Option<TextureUse>,
}

/// Everything a renderer needs to draw one image.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// A short name for messages.
    pub name: String,
    /// Image width in pixels (course: 640).
    pub width: u32,
    /// Image height in pixels (course: 640).
    pub height: u32,
    /// Background (glClearColor; course: (0.5, 0.5, 0.8)).
    pub clear_color: Rgb,
    /// The view.
    pub camera: Camera,
    /// The projection.
    pub projection: Projection,
    /// Which light equation, and its options.
    pub light_model: LightModel,
    /// Global ambient light I_a (GL_LIGHT_MODEL_AMBIENT; OpenGL's default 0.2).
    pub global_ambient: Rgb,
    /// Light sources, in world space.
    pub lights: Vec<Light>,
    /// Flat, Gouraud or Phong.
    pub shading: Shading,
    /// Cull back faces (course: on).
    pub cull_back_faces: bool,
    /// The objects, drawn in this order.
    pub objects: Vec<Object>,
    /// Textures referred to by [`TextureUse::texture`].
    pub textures: Vec<Texture>,
}
