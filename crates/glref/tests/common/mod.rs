//! Scenes, an independent OpenGL lighting oracle and image helpers for the reference's tests.
#![allow(dead_code)] // each test binary uses a part of this module

use cg_core::Rgb;
use cg_core::camera::OrbitCamera;
use cg_core::glam::{DVec3, Vec2, Vec3, Vec4};
use cg_core::light::{Light, LightModel, Material};
use cg_core::mesh::Mesh;
use cg_core::product::MatrixProduct;
use cg_core::scene::{Camera, NormalSource, Object, Projection, Scene, Shading};

/// The course's background, glClearColor(0.5, 0.5, 0.8), as an 8-bit framebuffer holds it:
/// 0.5·255 = 127.5 rounds to 128, 0.8·255 = 204 exactly.
pub const BACKGROUND: [u8; 3] = [128, 128, 204];

/// A scene with the course's background and projection, OpenGL lighting with no global ambient,
/// no lights and no objects.
pub fn scene(width: u32, height: u32, camera: Camera) -> Scene {
    Scene {
        name: "test".into(),
        width,
        height,
        clear_color: Rgb::new(0.5, 0.5, 0.8),
        camera,
        projection: Projection { fovy_deg: 45.0, near: 1.0, far: 500.0 },
        light_model: LightModel::OpenGl { local_viewer: false },
        global_ambient: Rgb::ZERO,
        lights: vec![],
        shading: Shading::Gouraud,
        cull_back_faces: true,
        objects: vec![],
        textures: vec![],
    }
}

/// A camera at `eye` looking at the origin, +Y up.
pub fn look_at_origin(eye: Vec3) -> Camera {
    Camera::LookAt { eye, target: Vec3::ZERO, up: Vec3::Y }
}

/// The orbit camera with these angles and distance, looking at the origin.
pub fn orbit(yaw_deg: f32, pitch_deg: f32, distance: f32) -> Camera {
    Camera::Orbit(OrbitCamera { yaw_deg, pitch_deg, distance, ..OrbitCamera::course_sample() })
}

/// A material that only glows: no ambient, diffuse or specular reflectance, emission `color`.
pub fn emissive(color: Rgb) -> Material {
    Material { ka: Rgb::ZERO, kd: Rgb::ZERO, ks: Rgb::ZERO, emission: color, ..Material::default() }
}

/// An object with face normals.
pub fn object(name: &str, mesh: Mesh, material: Material, transform: MatrixProduct) -> Object {
    Object {
        name: name.into(),
        mesh,
        normals: NormalSource::Face,
        material,
        transform,
        texture: None,
        weld: None,
        analytic: None,
    }
}

/// The square `[-half, half]²` in the plane z = 0 facing +Z, as two counter-clockwise triangles,
/// with texture coordinates `(0, 0)` at `(-half, -half)` and `(1, 1)` at `(half, half)`.
pub fn quad(half: f32) -> Mesh {
    let mut mesh = Mesh::new(
        vec![
            Vec3::new(-half, -half, 0.0),
            Vec3::new(half, -half, 0.0),
            Vec3::new(half, half, 0.0),
            Vec3::new(-half, half, 0.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    mesh.uvs = Some(vec![Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::ONE, Vec2::new(0.0, 1.0)]);
    mesh
}

/// One triangle with corners `a`, `b`, `c` in this order.
pub fn triangle(a: Vec3, b: Vec3, c: Vec3) -> Mesh {
    Mesh::new(vec![a, b, c], vec![[0, 1, 2]])
}

/// The scene drawn by the reference, as RGB bytes, row 0 at the top.
pub fn render_rgb(scene: &Scene) -> Vec<[u8; 3]> {
    let image = cg_glref::render(scene).unwrap_or_else(|e| panic!("render failed: {e}"));
    assert_eq!((image.width, image.height), (scene.width, scene.height));
    image.to_rgba8().into_iter().map(|[r, g, b, _]| [r, g, b]).collect()
}

/// Where `p_world` lands on the screen, in pixels from the image's top-left corner (pixel
/// `(x, y)` covers `[x, x+1) × [y, y+1)`), by the kit's own view and projection matrices.
pub fn project(scene: &Scene, p_world: Vec3) -> Vec2 {
    let view = scene.view_product().unwrap().matrix().unwrap();
    let projection = scene.projection_matrix().unwrap();
    let p_clip = projection * view * p_world.extend(1.0);
    assert!(p_clip.w > 0.0, "{p_world} is behind the camera");
    let p_ndc = p_clip.truncate() / p_clip.w;
    Vec2::new(
        (p_ndc.x + 1.0) * 0.5 * scene.width as f32,
        (1.0 - p_ndc.y) * 0.5 * scene.height as f32,
    )
}

/// `p` transformed by an object's model matrix.
pub fn to_world(transform: &MatrixProduct, p: Vec3) -> Vec3 {
    let m = transform.matrix().unwrap();
    (m * Vec4::new(p.x, p.y, p.z, 1.0)).truncate()
}

/// The image as ASCII art, one character per pixel from `classify`, for failure messages.
pub fn ascii(pixels: &[[u8; 3]], width: u32, classify: impl Fn([u8; 3]) -> char) -> String {
    pixels
        .chunks(width as usize)
        .map(|row| row.iter().map(|&p| classify(p)).collect::<String>())
        .collect::<Vec<_>>()
        .join("\n")
}

/// Signed area (×2) of the screen triangle `a, b, c`: positive when it runs clockwise on the
/// screen (y down), i.e. counter-clockwise as seen by the viewer.
pub fn screen_area2(a: Vec2, b: Vec2, c: Vec2) -> f32 {
    -((b - a).perp_dot(c - a))
}

/// Distances of `p` inside each edge of the screen triangle `t` (positive inside); the
/// triangle's orientation does not matter.
pub fn inside_distances(t: [Vec2; 3], p: Vec2) -> [f32; 3] {
    let sign = if (t[1] - t[0]).perp_dot(t[2] - t[0]) > 0.0 { 1.0 } else { -1.0 };
    [0, 1, 2].map(|i| {
        let (a, b) = (t[i], t[(i + 1) % 3]);
        sign * (b - a).perp_dot(p - a) / (b - a).length()
    })
}

// ---------------------------------------------------------------------------------------------
// The OpenGL 1.x lighting equation (OpenGL 2.1 specification, section 2.14.1), written here
// again in f64 from the specification, independently of cg-core's `shade`:
//
//   c = e + a_m·a_s + Σᵢ attᵢ·spotᵢ·[a_m·a_i + (n⊙L)·d_m·d_i + fᵢ·(n⊙ĥ)^s·s_m·s_i]
//
// with x⊙y = max(x·y, 0), L the unit vector from the vertex to the light, fᵢ = 1 when n⊙L ≠ 0,
// ĥ = normalise(L + V) where V = (0, 0, 1) in eye space (infinite viewer) or the unit vector
// to the eye (local viewer), attᵢ = 1/(k0 + k1·d + k2·d²) for positional lights (1 for
// directional ones), spotᵢ = (−L·ŝ)^e inside the cone −L·ŝ ≥ cos(cutoff), 0 outside, 1 for
// cutoff 180. Everything is in world space: the view matrix is a rotation and a translation,
// which keep every dot product and distance.

/// A GL light for the oracle (world space).
#[derive(Clone, Copy, Debug)]
pub struct GlLight {
    /// GL_POSITION: w = 0 for a direction towards the light.
    pub position: [f64; 4],
    /// GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR.
    pub ambient: [f64; 3],
    /// GL_DIFFUSE.
    pub diffuse: [f64; 3],
    /// GL_SPECULAR.
    pub specular: [f64; 3],
    /// GL_SPOT_DIRECTION, GL_SPOT_CUTOFF (degrees), GL_SPOT_EXPONENT.
    pub spot: Option<([f64; 3], f64, f64)>,
    /// GL_CONSTANT / LINEAR / QUADRATIC_ATTENUATION.
    pub attenuation: [f64; 3],
}

/// A GL material for the oracle.
#[derive(Clone, Copy, Debug)]
pub struct GlMaterial {
    /// GL_AMBIENT, GL_DIFFUSE, GL_SPECULAR, GL_EMISSION.
    pub ambient: [f64; 3],
    /// GL_DIFFUSE.
    pub diffuse: [f64; 3],
    /// GL_SPECULAR.
    pub specular: [f64; 3],
    /// GL_EMISSION.
    pub emission: [f64; 3],
    /// GL_SHININESS.
    pub shininess: f64,
}

/// The viewer for the oracle.
#[derive(Clone, Copy, Debug)]
pub enum Viewer {
    /// Infinite viewer: V is this unit vector (the camera's backward axis in world space).
    Infinite(DVec3),
    /// Local viewer at this eye position.
    Local(DVec3),
}

fn d3(v: [f64; 3]) -> DVec3 {
    DVec3::from_array(v)
}

/// The colour OpenGL computes at a vertex `p` with unit normal `n` (not clamped).
pub fn gl_lit_color(
    p: DVec3,
    n: DVec3,
    viewer: Viewer,
    global_ambient: [f64; 3],
    m: &GlMaterial,
    lights: &[GlLight],
) -> DVec3 {
    let mut c = d3(m.emission) + d3(m.ambient) * d3(global_ambient);
    let v = match viewer {
        Viewer::Infinite(v) => v,
        Viewer::Local(eye) => (eye - p).normalize(),
    };
    for light in lights {
        let q = light.position;
        let (l, att) = if q[3] == 0.0 {
            (DVec3::new(q[0], q[1], q[2]).normalize(), 1.0)
        } else {
            let to_light = DVec3::new(q[0], q[1], q[2]) / q[3] - p;
            let d = to_light.length();
            let [k0, k1, k2] = light.attenuation;
            (to_light / d, 1.0 / (k0 + k1 * d + k2 * d * d))
        };
        let spot = match light.spot {
            None => 1.0,
            Some((_, 180.0, _)) => 1.0,
            Some((direction, cutoff, exponent)) => {
                let cos_alpha = (-l).dot(d3(direction).normalize());
                if cos_alpha >= cutoff.to_radians().cos() {
                    cos_alpha.max(0.0).powf(exponent)
                } else {
                    0.0
                }
            }
        };
        let n_dot_l = n.dot(l).max(0.0);
        let h = (l + v).normalize();
        let specular = if n_dot_l != 0.0 { n.dot(h).max(0.0).powf(m.shininess) } else { 0.0 };
        c += att
            * spot
            * (d3(m.ambient) * d3(light.ambient)
                + n_dot_l * d3(m.diffuse) * d3(light.diffuse)
                + specular * d3(m.specular) * d3(light.specular));
    }
    c
}

/// `round(255 · clamp(c, 0, 1))` per channel: the byte an 8-bit framebuffer holds.
pub fn to_bytes(c: DVec3) -> [u8; 3] {
    c.to_array().map(|x| (x.clamp(0.0, 1.0) * 255.0).round() as u8)
}

/// The kit's light for a [`GlLight`] (positional → point or spot, w = 0 → directional).
pub fn kit_light(l: &GlLight) -> Light {
    use cg_core::light::{Attenuation, LightKind};
    let v = |a: [f64; 3]| DVec3::from_array(a).as_vec3();
    let [x, y, z, w] = l.position;
    let kind = if w == 0.0 {
        LightKind::Directional { to_light: v([x, y, z]) }
    } else {
        let position = v([x / w, y / w, z / w]);
        match l.spot {
            None => LightKind::Point { position },
            Some((direction, cutoff, exponent)) => LightKind::Spot {
                position,
                direction: v(direction),
                cutoff_deg: cutoff as f32,
                exponent: exponent as f32,
                inner_deg: None,
            },
        }
    };
    Light {
        kind,
        ambient: v(l.ambient),
        diffuse: v(l.diffuse),
        specular: v(l.specular),
        attenuation: Attenuation {
            constant: l.attenuation[0] as f32,
            linear: l.attenuation[1] as f32,
            quadratic: l.attenuation[2] as f32,
        },
    }
}

/// The kit's material for a [`GlMaterial`].
pub fn kit_material(m: &GlMaterial) -> Material {
    let v = |a: [f64; 3]| DVec3::from_array(a).as_vec3();
    Material {
        ka: v(m.ambient),
        kd: v(m.diffuse),
        ks: v(m.specular),
        shininess: m.shininess as f32,
        emission: v(m.emission),
        ..Material::default()
    }
}

/// Rotation about X by `deg` degrees (counter-clockwise looking from +X), f64.
pub fn rot_x(deg: f64, v: DVec3) -> DVec3 {
    let (s, c) = deg.to_radians().sin_cos();
    DVec3::new(v.x, c * v.y - s * v.z, s * v.y + c * v.z)
}

/// Rotation about Y by `deg` degrees (counter-clockwise looking from +Y), f64.
pub fn rot_y(deg: f64, v: DVec3) -> DVec3 {
    let (s, c) = deg.to_radians().sin_cos();
    DVec3::new(c * v.x + s * v.z, v.y, -s * v.x + c * v.z)
}

/// Largest channel difference between two colours.
pub fn channel_diff(a: [u8; 3], b: [u8; 3]) -> u8 {
    (0..3).map(|i| a[i].abs_diff(b[i])).max().unwrap_or(0)
}
