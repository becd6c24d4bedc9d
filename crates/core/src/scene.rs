//! The in-memory scene (シーン): what every renderer draws. Pure data; the TOML format that
//! describes it, and the loading of OBJ and PNG files, live in the `cg-scene` crate.

use glam::{Mat3, Mat4, Vec3};

use crate::Rgb;
use crate::camera::OrbitCamera;
use crate::lang::{Lang, Text};
use crate::light::{Light, LightModel, Material};
use crate::math::try_normalize;
use crate::mesh::Mesh;
use crate::normals::{NormalsError, face_normal, normal_matrix, prepare_normals};
use crate::product::{Factor, MatrixProduct, format_number};
use crate::texture::{Sampler, TexEnv, Texture};
use crate::transform::{TransformError, look_at};

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
    /// Whether the mesh was welded by position when it was loaded, and what that did
    /// (docs/numerics.md row 3: an unwelded seam shows a crease; the report says which was used).
    pub weld: Option<WeldRecord>,
    /// The exact surface the mesh approximates, when there is one: the ray tracer intersects it
    /// instead of the triangles; rasterizers draw the mesh.
    pub analytic: Option<Analytic>,
}

/// An exact surface in model space, for renderers that can draw it without triangles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Analytic {
    /// The sphere of this radius about the model-space origin (the mesh is a tessellation of it).
    Sphere {
        /// Radius (> 0).
        radius: f32,
    },
    /// The square `[-size/2, size/2]²` in the plane y = 0, facing +Y, with texture coordinate
    /// `((x + size/2)/size, (z + size/2)/size)`, exactly as [`crate::shapes::grid`] lays it out.
    Plane {
        /// Side length (> 0).
        size: f32,
    },
}

/// What welding by position ([`Mesh::weld_by_position`]) did to an object's mesh.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WeldRecord {
    /// Vertices closer than this were merged (0 = only bit-equal positions).
    pub tolerance: f32,
    /// How many vertices disappeared into others.
    pub merged_vertices: usize,
    /// How many faces collapsed and were removed.
    pub removed_faces: usize,
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

impl Camera {
    /// The view transform (ワールド座標系→カメラ座標系) as named factors: the orbit camera's
    /// `T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw)`, or one `LookAt(…)` factor.
    ///
    /// # Errors
    /// A look-at camera whose eye equals its target, whose up is parallel to the view direction,
    /// or with non-finite input (see [`crate::transform::look_at`]).
    pub fn view_product(&self) -> Result<MatrixProduct, TransformError> {
        match self {
            Camera::Orbit(orbit) => Ok(orbit.view_product()),
            Camera::LookAt { eye, target, up } => {
                let matrix = look_at(*eye, *target, *up)?;
                let v = |v: &Vec3| {
                    format!(
                        "{}, {}, {}",
                        format_number(v.x),
                        format_number(v.y),
                        format_number(v.z)
                    )
                };
                let name = format!("LookAt(eye {}; target {}; up {})", v(eye), v(target), v(up));
                Ok(MatrixProduct::identity().then(Factor::named(name, matrix)))
            }
        }
    }

    /// Where the eye is, in world space.
    #[must_use]
    pub fn eye_position(&self) -> Vec3 {
        match self {
            Camera::Orbit(orbit) => orbit.eye_position(),
            Camera::LookAt { eye, .. } => *eye,
        }
    }
}

impl Scene {
    /// Width / height of the image (gluPerspective's aspect). A zero height counts as 1.
    #[must_use]
    pub fn aspect(&self) -> f32 {
        self.width as f32 / self.height.max(1) as f32
    }

    /// The projection as a factor, `P(fovy°, aspect, near, far)` with wgpu's `[0, 1]` depth.
    #[must_use]
    pub fn projection_factor(&self) -> Factor {
        self.projection_factor_for(self.width, self.height)
    }

    /// The projection for an image of `width × height` pixels instead of the scene's: the same
    /// fovy, near and far with that image's aspect ratio (as the course's `reshape` callback
    /// calls gluPerspective again when the window changes size). A zero height counts as 1.
    #[must_use]
    pub fn projection_factor_for(&self, width: u32, height: u32) -> Factor {
        let p = &self.projection;
        Factor::perspective(p.fovy_deg, width as f32 / height.max(1) as f32, p.near, p.far)
    }

    /// The projection matrix (`[0, 1]` depth).
    ///
    /// # Errors
    /// An invalid projection (near ≤ 0, far ≤ near, fovy outside (0°, 180°), zero aspect).
    pub fn projection_matrix(&self) -> Result<Mat4, TransformError> {
        self.projection_factor().matrix()
    }

    /// [`Scene::projection_matrix`] for an image of `width × height` pixels; see
    /// [`Scene::projection_factor_for`].
    ///
    /// # Errors
    /// As [`Scene::projection_matrix`].
    pub fn projection_matrix_for(&self, width: u32, height: u32) -> Result<Mat4, TransformError> {
        self.projection_factor_for(width, height).matrix()
    }

    /// The view transform as named factors; see [`Camera::view_product`].
    ///
    /// # Errors
    /// As [`Camera::view_product`].
    pub fn view_product(&self) -> Result<MatrixProduct, TransformError> {
        self.camera.view_product()
    }

    /// The model-view transform of `object` (モデル座標系→カメラ座標系): the view product followed
    /// by the object's own factors.
    ///
    /// # Errors
    /// As [`Camera::view_product`].
    pub fn model_view_product(&self, object: &Object) -> Result<MatrixProduct, TransformError> {
        Ok(self.view_product()?.concat(&object.transform))
    }
}

/// An object made ready to draw: its shading normals made (per [`Object::normals`]) and its
/// model matrix multiplied out. Every renderer starts from these.
#[derive(Clone, Debug, PartialEq)]
pub struct Prepared<'a> {
    /// The object as the scene gives it.
    pub object: &'a Object,
    /// The mesh to draw, in model space, with `normals` set (face normals split per face,
    /// smoothed vertex normals, or the given ones checked and normalised).
    pub mesh: Mesh,
    /// Model matrix (モデル座標系→ワールド座標系).
    pub model: Mat4,
    /// The cofactor matrix of `model`'s upper 3×3: transforms normals to world space, correct
    /// under mirroring and non-uniform scale (normalise after use).
    pub normal_matrix: Mat3,
    /// `det(model) < 0`: the model transform mirrors, so counter-clockwise faces become clockwise
    /// on screen and the cofactor normals point inwards; renderers flip both back.
    pub mirrored: bool,
}

/// Why an object could not be made ready to draw, naming it.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum PrepareError {
    /// Its transform has an invalid factor.
    #[error("object \"{object}\": {source}")]
    Transform {
        /// The object's name.
        object: String,
        /// What is wrong with the transform.
        source: TransformError,
    },
    /// Its shading normals cannot be made.
    #[error("object \"{object}\": {source}")]
    Normals {
        /// The object's name.
        object: String,
        /// What is wrong with the normals.
        source: NormalsError,
    },
}

impl PrepareError {
    /// The message for a student in `lang`.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        let (object, source) = match self {
            PrepareError::Transform { object, source } => (object, source.text()),
            PrepareError::Normals { object, source } => (object, source.text()),
        };
        Text::new(
            format!("オブジェクト \"{object}\": {}", source.ja),
            format!("object \"{object}\": {}", source.en),
        )
    }
}

impl Prepared<'_> {
    /// A shading normal of the prepared mesh (model space) in world space: by the cofactor
    /// [`Prepared::normal_matrix`], normalised, and negated for a mirrored object (whose cofactor
    /// normals point inwards), so it points out of the front face as in model space.
    ///
    /// `None` when the transformed normal is zero or not finite (a zero normal, a singular
    /// scale along it).
    ///
    /// See also [`Prepared::world_face_normal`].
    #[must_use]
    #[inline]
    pub fn world_normal(&self, n_model: Vec3) -> Option<Vec3> {
        try_normalize(self.normal_matrix * n_model).map(|n| if self.mirrored { -n } else { n })
    }

    /// The unit face normal (面の法線) of a face whose corners, *in the mesh's order*, are at
    /// the world positions `corners`: [`face_normal`] of them, negated for a mirrored object
    /// (its transform turned the counter-clockwise corners clockwise), so it points out of the
    /// front face.
    ///
    /// `None` for a degenerate (zero-area) face.
    ///
    /// See also [`Prepared::world_normal`].
    #[must_use]
    #[inline]
    pub fn world_face_normal(&self, corners: [Vec3; 3]) -> Option<Vec3> {
        let [a, b, c] = corners;
        face_normal(a, b, c).map(|n| if self.mirrored { -n } else { n })
    }
}

impl Object {
    /// This object made ready to draw; see [`Prepared`].
    ///
    /// # Errors
    /// An invalid transform factor, or normals that cannot be made (see [`prepare_normals`]).
    pub fn prepare(&self) -> Result<Prepared<'_>, PrepareError> {
        let model = self
            .transform
            .matrix()
            .map_err(|source| PrepareError::Transform { object: self.name.clone(), source })?;
        let mesh = prepare_normals(&self.mesh, self.normals)
            .map_err(|source| PrepareError::Normals { object: self.name.clone(), source })?;
        Ok(Prepared {
            object: self,
            mesh,
            model,
            normal_matrix: normal_matrix(model),
            mirrored: model.determinant() < 0.0,
        })
    }
}

impl Scene {
    /// Every object made ready to draw, in drawing order.
    ///
    /// # Errors
    /// The first object that cannot be prepared, named.
    pub fn prepare(&self) -> Result<Vec<Prepared<'_>>, PrepareError> {
        self.objects.iter().map(Object::prepare).collect()
    }
}

/// Scenes for the core's own unit tests.
#[cfg(test)]
pub(crate) mod tests_support {
    use super::*;
    use crate::camera::OrbitCamera;
    use crate::light::{Attenuation, Light, LightKind, Material};

    /// A 640 × 480 scene with the given camera, OpenGL lighting, no lights, and one empty object
    /// translated by (0, 1, 0).
    pub(crate) fn scene(camera: Camera) -> Scene {
        Scene {
            name: "t".into(),
            width: 640,
            height: 480,
            clear_color: Rgb::ZERO,
            camera,
            projection: Projection { fovy_deg: 45.0, near: 1.0, far: 500.0 },
            light_model: LightModel::OpenGl { local_viewer: false },
            global_ambient: Rgb::splat(0.2),
            lights: vec![],
            shading: Shading::Gouraud,
            cull_back_faces: true,
            objects: vec![Object {
                name: "o".into(),
                mesh: Mesh::default(),
                normals: NormalSource::Face,
                material: Material::default(),
                transform: MatrixProduct::identity().then(Factor::translate(Vec3::Y)),
                texture: None,
                weld: None,
                analytic: None,
            }],
            textures: vec![],
        }
    }

    /// The course's camera and GL_LIGHT0 (ambient 0.1, diffuse 0.8, specular 1.0 at (10, 10, 10)).
    pub(crate) fn course_like_scene() -> Scene {
        let mut s = scene(Camera::Orbit(OrbitCamera::course_sample()));
        s.lights.push(Light {
            kind: LightKind::Point { position: Vec3::splat(10.0) },
            ambient: Rgb::splat(0.1),
            diffuse: Rgb::splat(0.8),
            specular: Rgb::ONE,
            attenuation: Attenuation::default(),
        });
        s
    }
}

#[cfg(test)]
mod tests {
    use super::tests_support::scene;
    use super::*;
    use crate::camera::OrbitCamera;
    use crate::transform::{perspective, rotate_x_deg, translate};

    #[test]
    fn the_course_camera_gives_the_sample_programs_matrices() {
        let s = scene(Camera::Orbit(OrbitCamera::course_sample()));
        // glTranslatef(0, 0, -15); glRotatef(30, 1, 0, 0); glTranslatef(0, 1, 0)
        let expected =
            translate(Vec3::new(0.0, 0.0, -15.0)) * rotate_x_deg(30.0) * translate(Vec3::Y);
        let mv = s.model_view_product(&s.objects[0]).unwrap().matrix().unwrap();
        assert!(mv.abs_diff_eq(expected, 1e-6), "{mv} vs {expected}");
        let p = s.projection_matrix().unwrap();
        assert_eq!(p, perspective(45.0, 640.0 / 480.0, 1.0, 500.0).unwrap());
        assert_eq!(s.projection_matrix_for(640, 480).unwrap(), p, "the scene's own size");
        let wide = perspective(45.0, 2.0, 1.0, 500.0).unwrap();
        assert_eq!(s.projection_matrix_for(320, 160).unwrap(), wide, "reshape: aspect 2");
        assert!((s.aspect() - 4.0 / 3.0).abs() < 1e-7);
    }

    #[test]
    fn prepared_objects_carry_normals_and_the_model_matrix() {
        let mut s = scene(Camera::Orbit(OrbitCamera::course_sample()));
        s.objects[0].mesh = crate::shapes::lecture_pyramid();
        s.objects[0].transform.push(Factor::scale(Vec3::new(-1.0, 1.0, 1.0)));
        let p = s.objects[0].prepare().unwrap();
        // Face normals: every face gets its own three vertices.
        assert_eq!(p.mesh.vertex_count(), 18);
        assert!(p.mesh.normals.is_some());
        let expected = translate(Vec3::Y) * crate::transform::scale(Vec3::new(-1.0, 1.0, 1.0));
        assert_eq!(p.model, expected);
        assert!(p.mirrored, "a negative scale mirrors");
        // The cofactor of diag(-1, 1, 1) is diag(1, -1, -1).
        assert_eq!(p.normal_matrix, Mat3::from_diagonal(Vec3::new(1.0, -1.0, -1.0)));
        s.objects[0].normals = NormalSource::Given;
        let e = s.prepare().unwrap_err();
        assert!(matches!(e, PrepareError::Normals { ref object, .. } if object == "o"), "{e}");
        assert!(e.message(Lang::Ja).contains("オブジェクト \"o\""));
        s.objects[0].transform.push(Factor::rotate_deg(30.0, Vec3::ZERO));
        assert!(matches!(s.prepare(), Err(PrepareError::Transform { .. })));
    }

    #[test]
    fn world_normals_point_outwards_also_under_a_mirror() {
        let mut s = scene(Camera::Orbit(OrbitCamera::course_sample()));
        s.objects[0].mesh = crate::shapes::lecture_pyramid();
        for mirror in [false, true] {
            let mut o = s.objects[0].clone();
            o.transform = MatrixProduct::identity().then(Factor::scale(Vec3::new(
                if mirror { -2.0 } else { 2.0 },
                1.0,
                1.0,
            )));
            let p = o.prepare().unwrap();
            assert_eq!(p.mirrored, mirror);
            // The +Y face normal of the pyramid's base is −Y, outwards, in both.
            let n = p.world_normal(Vec3::NEG_Y).unwrap();
            assert!(n.abs_diff_eq(Vec3::NEG_Y, 1e-6), "mirror {mirror}: {n}");
            // A face normal from world corners in the mesh's order points outwards: the apex
            // face {0, 3, 1} of the pyramid faces +Z in model space, and still does (x scaled).
            let face = p.mesh.faces[0];
            let corners = face
                .map(|i| crate::transform::transform_point(p.model, p.mesh.positions[i as usize]));
            let n = p.world_face_normal(corners).unwrap();
            assert!(n.z > 0.5, "mirror {mirror}: {n}");
            assert_eq!(p.world_face_normal([Vec3::ZERO; 3]), None, "degenerate");
            assert_eq!(p.world_normal(Vec3::ZERO), None);
        }
    }

    #[test]
    fn a_look_at_camera_is_one_named_factor_and_fails_cleanly() {
        let s = scene(Camera::LookAt {
            eye: Vec3::new(0.0, 0.0, 5.0),
            target: Vec3::ZERO,
            up: Vec3::Y,
        });
        let v = s.view_product().unwrap();
        assert_eq!(v.factors.len(), 1);
        assert!(v.symbolic().starts_with("LookAt(eye 0, 0, 5"), "{}", v.symbolic());
        assert!(v.matrix().unwrap().abs_diff_eq(translate(Vec3::new(0.0, 0.0, -5.0)), 1e-6));
        assert_eq!(s.camera.eye_position(), Vec3::new(0.0, 0.0, 5.0));
        let bad = scene(Camera::LookAt { eye: Vec3::ONE, target: Vec3::ONE, up: Vec3::Y });
        assert!(bad.view_product().is_err(), "eye == target is an error, not NaN");
    }
}
