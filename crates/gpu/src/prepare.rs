//! Preparing a scene for the GPU, on the CPU and without a device: the generated shader, the
//! frame's uniforms and lights, and every object's vertices (each face expanded to three
//! vertices that carry its face normal and, for flat shading, where and with what the face is
//! lit) and uniforms, exactly as the device code ([`crate::Gpu::frame`]) uploads them. Tested
//! without a GPU.
//!
//! Flat shading lights a face once, as the rasterizer does: in the lecture's light model at its
//! centroid with its face normal and the mean of its vertex colours; in OpenGL's model as
//! glShadeModel(GL_FLAT), at its provoking vertex — the face's last corner in the prepared mesh
//! (each face is one GL_TRIANGLES triangle in `cg-glref`) — with that vertex's normal and
//! colour. All three vertices of a face carry the same point, normal and colour, so the vertex
//! shader gives each the same colour and `@interpolate(flat)` shows it whichever vertex WebGPU
//! takes as provoking (its first, where OpenGL takes the last).

use bytemuck::{Pod, Zeroable};
use cg_core::Rgb;
use cg_core::features::Features;
use cg_core::glam::{Vec2, Vec3};
use cg_core::image::check_size;
use cg_core::light::{Light, LightKind, LightModel};
use cg_core::math::try_normalize;
use cg_core::scene::{Scene, Shading};
use cg_core::texture::{Sampler, TexEnv};
use cg_core::transform::transform_point;

use crate::{GpuError, Options, shader_source};

/// The corner of a face, in the prepared mesh's order, whose lit colour OpenGL's GL_FLAT gives
/// the whole face: the provoking vertex, the last of a GL_TRIANGLES triangle.
const PROVOKING: usize = 2;

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub(crate) struct GpuVertex {
    pub(crate) position: [f32; 3],
    pub(crate) normal: [f32; 3],
    pub(crate) face_normal: [f32; 3],
    pub(crate) color: [f32; 3],
    pub(crate) uv: [f32; 2],
    /// Flat shading: where the face is lit (the centroid, or OpenGL's provoking vertex); the
    /// face's centroid in the other modes, which do not read it.
    pub(crate) flat_at: [f32; 3],
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub(crate) struct FrameUniform {
    pub(crate) view_proj: [[f32; 4]; 4],
    pub(crate) eye: [f32; 4],
    pub(crate) backward: [f32; 4],
    pub(crate) ambient: [f32; 4],
    pub(crate) light_count: [u32; 4],
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub(crate) struct GpuLight {
    pub(crate) position: [f32; 4],
    pub(crate) ambient: [f32; 4],
    pub(crate) diffuse: [f32; 4],
    /// The specular colour (WGSL `highlight`: a shader without specular code has no word for it).
    pub(crate) highlight: [f32; 4],
    pub(crate) attenuation: [f32; 4],
    pub(crate) cone_axis: [f32; 4],
    pub(crate) cone: [f32; 4],
}

#[repr(C)]
#[derive(Clone, Copy, Debug, Default, PartialEq, Pod, Zeroable)]
pub(crate) struct ObjectUniform {
    pub(crate) ka: [f32; 4],
    pub(crate) kd: [f32; 4],
    pub(crate) ks: [f32; 4],
    pub(crate) emission: [f32; 4],
    pub(crate) flags: [u32; 4],
}

/// A scene ready for the device: everything [`crate::Gpu::frame`] uploads.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Prepared {
    pub(crate) width: u32,
    pub(crate) height: u32,
    pub(crate) shading: Shading,
    /// What the scene uses (reflection and transmission cleared: they need rays).
    pub(crate) features: Features,
    /// The generated WGSL.
    pub(crate) shader: String,
    /// The frame's uniforms, the light count filled in.
    pub(crate) frame: FrameUniform,
    /// Every point light (an area light as its samples).
    pub(crate) lights: Vec<GpuLight>,
    /// The objects with at least one face, in the scene's order.
    pub(crate) objects: Vec<PreparedObject>,
}

/// One object ready for the device.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct PreparedObject {
    /// The scene object's name (for errors).
    pub(crate) name: String,
    /// Three per face, in drawing order (re-wound for a mirrored object).
    pub(crate) vertices: Vec<GpuVertex>,
    pub(crate) uniform: ObjectUniform,
    /// The scene texture it samples (an index into `scene.textures`, checked) and how.
    pub(crate) texture: Option<(usize, Sampler)>,
}

/// Whether every object's vertex buffer fits the device's `max_buffer_size` (`limit` bytes);
/// else [`GpuError::TooLarge`] for the first that does not (wgpu would refuse the buffer).
pub(crate) fn check_buffers(objects: &[PreparedObject], limit: u64) -> Result<(), GpuError> {
    for object in objects {
        let bytes = (object.vertices.len() as u64).saturating_mul(size_of::<GpuVertex>() as u64);
        if bytes > limit {
            return Err(GpuError::TooLarge {
                object: object.name.clone(),
                triangles: object.vertices.len() / 3,
                bytes,
                limit,
            });
        }
    }
    Ok(())
}

/// Prepares `scene` as [`crate::Gpu::frame`] draws it with `options`.
///
/// # Errors
/// A zero or too large size, an invalid camera or projection, an object that cannot be
/// prepared, a missing texture, a non-finite vertex.
pub(crate) fn prepare(scene: &Scene, options: &Options) -> Result<Prepared, GpuError> {
    let (width, height) = options.size.unwrap_or((scene.width, scene.height));
    check_size(width, height)?;
    let shading = options.shading.unwrap_or(scene.shading);
    let mut features = scene.features();
    features.reflection = false;
    features.transmission = false;
    let shader = shader_source(&features, shading, scene.light_model);

    let uniform = frame_uniform(scene, width, height)?;
    let lecture = matches!(scene.light_model, LightModel::Lecture { .. });
    let lights: Vec<GpuLight> =
        scene.lights.iter().flat_map(Light::point_lights).map(|l| gpu_light(&l, lecture)).collect();
    let frame = FrameUniform { light_count: [lights.len() as u32, 0, 0, 0], ..uniform };

    let mut objects = Vec::with_capacity(scene.objects.len());
    for object in &scene.objects {
        let prepared = object.prepare()?;
        let texture_use = match &object.texture {
            None => None,
            Some(t) => {
                if t.texture >= scene.textures.len() {
                    return Err(GpuError::MissingTexture {
                        object: object.name.clone(),
                        texture: t.texture,
                        count: scene.textures.len(),
                    });
                }
                Some(t)
            }
        };
        let mesh = &prepared.mesh;
        let world: Vec<Vec3> =
            mesh.positions.iter().map(|&p| transform_point(prepared.model, p)).collect();
        if let Some(i) = world.iter().position(|p| !p.is_finite()) {
            return Err(GpuError::NonFinite {
                object: object.name.clone(),
                vertex: i,
                position: world[i].to_array(),
            });
        }
        let normal = |i: usize| {
            let n = mesh.normals.as_ref().and_then(|n| n.get(i)).copied().unwrap_or(Vec3::ZERO);
            prepared.world_normal(n).unwrap_or(Vec3::ZERO)
        };
        let color =
            |i: usize| mesh.colors.as_ref().and_then(|c| c.get(i)).copied().unwrap_or(Rgb::ONE);
        let uv = |i: usize| mesh.uvs.as_ref().and_then(|u| u.get(i)).copied().unwrap_or(Vec2::ZERO);
        let mut vertices = Vec::with_capacity(mesh.faces.len() * 3);
        for face in &mesh.faces {
            let idx = face.map(|i| i as usize);
            let corners = idx.map(|i| world[i]);
            let face_normal = prepared.world_face_normal(corners).unwrap_or(Vec3::ZERO);
            let centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
            // Flat shading: the point, normal and colour the face is lit with, the same at all
            // three vertices (see the module docs).
            let flat = match (shading, scene.light_model) {
                (Shading::Flat, LightModel::OpenGl { .. }) => {
                    let p = idx[PROVOKING];
                    let n = normal(p);
                    Some((world[p], if n == Vec3::ZERO { face_normal } else { n }, color(p)))
                }
                (Shading::Flat, LightModel::Lecture { .. }) => {
                    let average = (color(idx[0]) + color(idx[1]) + color(idx[2])) / 3.0;
                    Some((centroid, face_normal, average))
                }
                _ => None,
            };
            let origin = texture_use.map_or(Vec2::ZERO, |t| t.sampler.repeat_origin(uv(idx[0])));
            // Mirrored objects: re-wound so the front face stays counter-clockwise.
            let order = if prepared.mirrored { [0, 2, 1] } else { [0, 1, 2] };
            for k in order {
                let i = idx[k];
                let (flat_at, n, c) = flat.unwrap_or((centroid, normal(i), color(i)));
                vertices.push(GpuVertex {
                    position: corners[k].to_array(),
                    normal: n.to_array(),
                    face_normal: face_normal.to_array(),
                    color: c.to_array(),
                    uv: (uv(i) - origin).to_array(),
                    flat_at: flat_at.to_array(),
                });
            }
        }
        if vertices.is_empty() {
            continue;
        }
        let mut material = object.material.clone();
        if !features.specular {
            material.ks = Rgb::ZERO;
        }
        let replace = matches!(texture_use, Some(t) if t.env == TexEnv::Replace);
        let uniform = ObjectUniform {
            ka: material.ka.extend(0.0).to_array(),
            kd: material.kd.extend(0.0).to_array(),
            ks: material.ks.extend(material.shininess.max(0.0)).to_array(),
            emission: material.emission.extend(0.0).to_array(),
            flags: [
                u32::from(mesh.colors.is_some()),
                u32::from(!replace),
                u32::from(texture_use.is_some()),
                u32::from(replace),
            ],
        };
        objects.push(PreparedObject {
            name: object.name.clone(),
            vertices,
            uniform,
            texture: texture_use.map(|t| (t.texture, t.sampler)),
        });
    }
    Ok(Prepared { width, height, shading, features, shader, frame, lights, objects })
}

/// The frame's uniforms for `scene` at `width × height` (the light count left 0): the
/// rasterizer's view, projection, eye, backward axis (the infinite viewer's V) and ambient sum.
pub(crate) fn frame_uniform(
    scene: &Scene,
    width: u32,
    height: u32,
) -> Result<FrameUniform, GpuError> {
    let view = scene.view_product().and_then(|v| v.matrix()).map_err(GpuError::Camera)?;
    let projection = scene.projection_matrix_for(width, height).map_err(GpuError::Projection)?;
    // Camera +Z in world space: the third row of the view rotation.
    let backward =
        try_normalize(Vec3::new(view.x_axis.z, view.y_axis.z, view.z_axis.z)).unwrap_or(Vec3::Z);
    // Lecture: ka·(Ia + Σ Ia,i) unattenuated; OpenGL: the global ambient here, per light in the loop.
    let ambient = if matches!(scene.light_model, LightModel::Lecture { .. }) {
        scene.lights.iter().fold(scene.global_ambient, |sum, l| sum + l.ambient)
    } else {
        scene.global_ambient
    };
    Ok(FrameUniform {
        view_proj: (projection * view).to_cols_array_2d(),
        eye: scene.camera.eye_position().extend(1.0).to_array(),
        backward: backward.extend(0.0).to_array(),
        ambient: ambient.extend(1.0).to_array(),
        light_count: [0; 4],
    })
}

/// A point light (or an area-light sample) as the shader reads it.
fn gpu_light(light: &Light, lecture: bool) -> GpuLight {
    let mut g = GpuLight {
        ambient: light.ambient.extend(0.0).to_array(),
        diffuse: light.diffuse.extend(0.0).to_array(),
        highlight: light.specular.extend(0.0).to_array(),
        ..GpuLight::default()
    };
    let a = light.attenuation;
    g.attenuation =
        [a.constant, a.linear, a.quadratic, if light.needs_attenuation() { 1.0 } else { 0.0 }];
    match light.kind {
        LightKind::Directional { to_light } => {
            g.position = try_normalize(to_light).unwrap_or(Vec3::ZERO).extend(0.0).to_array();
        }
        LightKind::Point { position } => g.position = position.extend(1.0).to_array(),
        LightKind::Spot { position, direction, cutoff_deg, exponent, inner_deg } => {
            g.position = position.extend(1.0).to_array();
            // No cone (cutoff above 90° or NaN): a point light.
            if !(cutoff_deg.is_nan() || cutoff_deg > 90.0) {
                let axis = try_normalize(direction);
                let cutoff = f64::from(cutoff_deg.max(0.0));
                let inner = inner_deg
                    .filter(|_| lecture)
                    .map(|i| f64::from(i.max(0.0)))
                    .filter(|&i| i < cutoff)
                    .map_or(2.0, |i| i.to_radians().cos() as f32);
                g.cone_axis = axis.map_or([0.0; 4], |s| s.extend(1.0).to_array());
                let exponent = if exponent > 0.0 { exponent } else { 0.0 };
                g.cone = [1.0, cutoff.to_radians().cos() as f32, exponent, inner];
            }
        }
        // `point_lights` has turned area lights into samples already.
        LightKind::Area { corner, edge_u, edge_v, .. } => {
            g.position = (corner + 0.5 * (edge_u + edge_v)).extend(1.0).to_array();
        }
    }
    g
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::lang::Lang;

    const COURSE: &str = include_str!("../../../assets/scenes/course-sample.toml");

    fn scene(text: &str) -> Scene {
        cg_scene::parse(text, std::path::Path::new("test.toml")).expect("the test scene loads")
    }

    fn v3(a: [f32; 3]) -> Vec3 {
        Vec3::from_array(a)
    }

    #[test]
    fn an_object_larger_than_the_devices_largest_buffer_is_an_error_that_names_it() {
        // The course scene's ground: 200 triangles, 600 vertices.
        let p = prepare(&scene(COURSE), &Options::default()).unwrap();
        let ground = (p.objects[0].vertices.len() * size_of::<GpuVertex>()) as u64;
        assert!(check_buffers(&p.objects, ground).is_ok(), "a buffer of exactly the limit fits");
        match check_buffers(&p.objects, ground - 1) {
            Err(e @ GpuError::TooLarge { .. }) => {
                let GpuError::TooLarge { object, triangles, bytes, limit } = &e else {
                    unreachable!()
                };
                assert_eq!(
                    (object.as_str(), *triangles, *bytes, *limit),
                    ("ground", 200, ground, ground - 1)
                );
                assert!(e.message(Lang::En).contains("--renderer raster"), "{e}");
                assert!(e.message(Lang::Ja).contains("CPU ラスタライザ"), "{e}");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn every_face_becomes_three_vertices_with_its_own_normal_and_centroid() {
        let s = scene(COURSE);
        for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let p = prepare(&s, &Options { shading: Some(shading), size: None }).unwrap();
            assert_eq!((p.width, p.height, p.shading), (640, 640, shading));
            assert_eq!(p.frame.light_count[0], 1);
            assert_eq!(p.lights.len(), 1);
            assert_eq!(p.objects.len(), 2, "ground and pyramid");
            for (object, o) in s.objects.iter().zip(&p.objects) {
                let faces = object.prepare().unwrap().mesh.faces.len();
                assert_eq!(o.vertices.len(), 3 * faces, "{}", object.name);
                for tri in o.vertices.chunks(3) {
                    let corners = tri.iter().map(|v| v3(v.position)).collect::<Vec<_>>();
                    let centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
                    let n = v3(tri[0].face_normal);
                    // The face normal is the right-hand normal of the corners as drawn.
                    let cross = (corners[1] - corners[0]).cross(corners[2] - corners[0]);
                    assert!(cross.normalize().abs_diff_eq(n, 1e-5), "{n} vs {cross}");
                    for v in tri {
                        assert_eq!(v.face_normal, tri[0].face_normal);
                        if shading != Shading::Flat {
                            assert!(v3(v.flat_at).abs_diff_eq(centroid, 1e-6));
                        }
                    }
                }
                // No specular in the course's scene: k_s is not uploaded.
                assert_eq!(o.uniform.ks[..3], [0.0; 3]);
                assert_eq!(o.texture, None);
            }
            assert!(!p.shader.contains("specular"));
        }
    }

    #[test]
    fn flat_faces_carry_the_point_normal_and_colour_their_light_model_lights() {
        // The course's pyramid with smooth normals and a colour per vertex, also mirrored (its
        // corners then drawn in the order 0, 2, 1). Every vertex of a face carries the same
        // point, normal and colour, so the face has one colour whichever vertex provokes: in
        // OpenGL's model the face's last corner in the mesh's order (GL_FLAT's provoking vertex)
        // with its own normal and colour; in the lecture's the centroid, the face normal and
        // the mean colour.
        let lecture =
            LightModel::Lecture { specular: cg_core::light::Specular::Phong, local_viewer: false };
        let opengl = LightModel::OpenGl { local_viewer: false };
        for (model, mirrored) in [(opengl, false), (opengl, true), (lecture, false)] {
            let mut s = scene(COURSE);
            s.light_model = model;
            s.objects.retain(|o| o.name == "pyramid");
            let pyramid = &mut s.objects[0];
            pyramid.normals = cg_core::scene::NormalSource::Vertex {
                weighting: cg_core::normals::Weighting::Uniform,
                crease_deg: None,
            };
            let count = pyramid.mesh.positions.len();
            pyramid.mesh.colors =
                Some((0..count).map(|i| Rgb::new(i as f32 / count as f32, 0.5, 0.25)).collect());
            if mirrored {
                pyramid.transform = std::mem::take(&mut pyramid.transform)
                    .then(cg_core::product::Factor::scale(Vec3::new(-1.0, 1.0, 1.0)));
            }
            let options = Options { shading: Some(Shading::Flat), size: None };
            let p = prepare(&s, &options).unwrap();
            let prepared = s.objects[0].prepare().unwrap();
            let mesh = &prepared.mesh;
            let (normals, colors) = (mesh.normals.as_ref().unwrap(), mesh.colors.as_ref().unwrap());
            assert_eq!(p.objects[0].vertices.len(), 3 * mesh.faces.len());
            for (face, tri) in mesh.faces.iter().zip(p.objects[0].vertices.chunks(3)) {
                let world =
                    face.map(|i| transform_point(prepared.model, mesh.positions[i as usize]));
                let (at, n, c) = if model == opengl {
                    let last = face[2] as usize;
                    (world[2], prepared.world_normal(normals[last]).unwrap(), colors[last])
                } else {
                    let c = face.iter().map(|&i| colors[i as usize]).sum::<Rgb>() / 3.0;
                    ((world[0] + world[1] + world[2]) / 3.0, v3(tri[0].face_normal), c)
                };
                for v in tri {
                    let what = format!("{model:?}, mirrored {mirrored}, face {face:?}");
                    assert!(v3(v.flat_at).abs_diff_eq(at, 1e-6), "{what}: lit at {:?}", v.flat_at);
                    assert!(v3(v.normal).abs_diff_eq(n, 1e-6), "{what}: normal {:?}", v.normal);
                    assert!(v3(v.color).abs_diff_eq(c, 1e-6), "{what}: colour {:?}", v.color);
                    assert_eq!(
                        (v.flat_at, v.normal, v.color),
                        (tri[0].flat_at, tri[0].normal, tri[0].color)
                    );
                }
                if model == opengl {
                    assert!(
                        v3(tri[0].normal).dot(v3(tri[0].face_normal)) < 0.9999,
                        "premise: the vertex normal is not the face normal"
                    );
                }
            }
        }
    }

    #[test]
    fn a_mirrored_object_is_rewound_so_its_faces_still_face_out() {
        let plain = scene(COURSE);
        let mut mirrored = plain.clone();
        let pyramid = &mut mirrored.objects[1];
        pyramid.transform = std::mem::take(&mut pyramid.transform)
            .then(cg_core::product::Factor::scale(Vec3::new(-1.0, 1.0, 1.0)));
        let plain = prepare(&plain, &Options::default()).unwrap();
        let p = prepare(&mirrored, &Options::default()).unwrap();
        assert_eq!(plain.objects[1].vertices.len(), p.objects[1].vertices.len());
        for (a, b) in plain.objects[1].vertices.chunks(3).zip(p.objects[1].vertices.chunks(3)) {
            // The same face seen in a mirror: x negated, corners 1 and 2 swapped.
            let flip = |v: &GpuVertex| v3(v.position) * Vec3::new(-1.0, 1.0, 1.0);
            assert!(flip(&b[0]).abs_diff_eq(v3(a[0].position), 1e-6));
            assert!(flip(&b[1]).abs_diff_eq(v3(a[2].position), 1e-6));
            assert!(flip(&b[2]).abs_diff_eq(v3(a[1].position), 1e-6));
            // Still pointing out: the mirror image of the plain face's normal.
            let n = v3(a[0].face_normal) * Vec3::new(-1.0, 1.0, 1.0);
            assert!(v3(b[0].face_normal).abs_diff_eq(n, 1e-5));
        }
    }

    #[test]
    fn a_missing_texture_and_a_vertex_at_infinity_are_named() {
        let mut s = scene(COURSE);
        s.objects[0].texture = Some(cg_core::scene::TextureUse {
            texture: 3,
            sampler: Sampler::default(),
            env: TexEnv::Modulate,
        });
        match prepare(&s, &Options::default()) {
            Err(GpuError::MissingTexture { object, texture: 3, count: 0 }) => {
                assert_eq!(object, "ground");
            }
            other => panic!("{other:?}"),
        }
        let mut s = scene(COURSE);
        let pyramid = &mut s.objects[1];
        pyramid.transform = std::mem::take(&mut pyramid.transform)
            .then(cg_core::product::Factor::translate(Vec3::new(3.0e38, 0.0, 0.0)))
            .then(cg_core::product::Factor::translate(Vec3::new(3.0e38, 0.0, 0.0)));
        match prepare(&s, &Options::default()) {
            Err(GpuError::NonFinite { object, .. }) => assert_eq!(object, "pyramid"),
            Err(e) => assert!(e.message(cg_core::lang::Lang::En).contains("pyramid"), "{e:?}"),
            Ok(_) => panic!("a vertex at infinity must not be drawn"),
        }
    }
}
