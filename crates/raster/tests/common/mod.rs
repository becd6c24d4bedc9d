//! Shared by the rasterizer's tests: small hand-built scenes, an f64 camera model to predict where
//! things land on the screen, and coverage masks drawn as ASCII art.

#![allow(dead_code)]

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use cg_core::Rgb;
use cg_core::glam::{DVec2, DVec3, Vec2, Vec3};
use cg_core::light::{LightModel, Material};
use cg_core::mesh::Mesh;
use cg_core::product::MatrixProduct;
use cg_core::scene::{Camera, NormalSource, Object, Projection, Scene, Shading};
use cg_core::texture::{Filter, Sampler, Texture, Wrap};

/// A scene file shipped with the kit.
pub fn asset(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes").join(name)
}

/// Loads a shipped scene.
pub fn load(name: &str) -> Scene {
    let path = asset(name);
    cg_scene::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// An empty `width × height` scene: the eye at the origin looking down −Z (so view space is world
/// space), `fovy_deg`, near 1, far 100, black background, no lights, OpenGL's light model with no
/// global ambient, Gouraud shading, back faces culled.
pub fn looking_down_z(width: u32, height: u32, fovy_deg: f32) -> Scene {
    Scene {
        name: "test".into(),
        width,
        height,
        clear_color: Rgb::ZERO,
        camera: Camera::LookAt { eye: Vec3::ZERO, target: Vec3::NEG_Z, up: Vec3::Y },
        projection: Projection { fovy_deg, near: 1.0, far: 100.0 },
        light_model: LightModel::OpenGl { local_viewer: false },
        global_ambient: Rgb::ZERO,
        lights: vec![],
        shading: Shading::Gouraud,
        cull_back_faces: true,
        objects: vec![],
        textures: vec![],
    }
}

/// A material that shows exactly `color` whatever the lights: emission only.
pub fn unlit(color: Rgb) -> Material {
    Material { ka: Rgb::ZERO, kd: Rgb::ZERO, ks: Rgb::ZERO, emission: color, ..Material::default() }
}

/// An object with face normals and no transform.
pub fn object(name: &str, mesh: Mesh, material: Material) -> Object {
    Object {
        name: name.into(),
        mesh,
        normals: NormalSource::Face,
        material,
        transform: MatrixProduct::identity(),
        texture: None,
        weld: None,
        analytic: None,
    }
}

/// One triangle as a mesh.
pub fn triangle(a: Vec3, b: Vec3, c: Vec3) -> Mesh {
    Mesh::new(vec![a, b, c], vec![[0, 1, 2]])
}

/// The camera model of [`looking_down_z`] in f64: gluPerspective(fovy, width/height) and the
/// viewport (x right, y down, pixel (x, y) centred at (x + ½, y + ½)).
#[derive(Clone, Copy, Debug)]
pub struct Pinhole {
    /// cot(fovy / 2).
    pub f: f64,
    /// width / height.
    pub aspect: f64,
    /// Image size.
    pub width: f64,
    /// Image size.
    pub height: f64,
    /// Near and far planes.
    pub near: f64,
    /// Near and far planes.
    pub far: f64,
}

impl Pinhole {
    /// The camera of `scene` (which must look down −Z from the origin).
    pub fn of(scene: &Scene) -> Pinhole {
        let p = &scene.projection;
        Pinhole {
            f: 1.0 / (f64::from(p.fovy_deg) / 2.0).to_radians().tan(),
            aspect: f64::from(scene.width) / f64::from(scene.height),
            width: f64::from(scene.width),
            height: f64::from(scene.height),
            near: f64::from(p.near),
            far: f64::from(p.far),
        }
    }

    /// Window coordinates of a view-space point in front of the eye (z < 0).
    pub fn window(&self, p: DVec3) -> DVec2 {
        let x_ndc = self.f / self.aspect * p.x / -p.z;
        let y_ndc = self.f * p.y / -p.z;
        DVec2::new((x_ndc + 1.0) / 2.0 * self.width, (1.0 - y_ndc) / 2.0 * self.height)
    }

    /// The unit direction from the eye through window point `w`.
    pub fn ray(&self, w: DVec2) -> DVec3 {
        let x_ndc = 2.0 * w.x / self.width - 1.0;
        let y_ndc = 1.0 - 2.0 * w.y / self.height;
        DVec3::new(x_ndc * self.aspect / self.f, y_ndc / self.f, -1.0).normalize()
    }

    /// Window depth (`[0, 1]`, wgpu's range) of a view-space depth `z < 0`.
    pub fn depth(&self, z: f64) -> f64 {
        let (n, f) = (self.near, self.far);
        (f / (n - f) * z + f * n / (n - f)) / -z
    }
}

/// The signed distance of `p` from the directed line `a → b`: `(b − a) × (p − a) / |b − a|`.
pub fn side(a: DVec2, b: DVec2, p: DVec2) -> f64 {
    let e = b - a;
    (e.x * (p.y - a.y) - e.y * (p.x - a.x)) / e.length()
}

/// How far inside the convex polygon `poly` (either winding) the point `p` is: the smallest
/// distance to the lines of its edges, positive inside, negative outside.
pub fn inside_by(poly: &[DVec2], p: DVec2) -> f64 {
    let n = poly.len();
    let area2: f64 = (0..n).map(|i| poly[i].perp_dot(poly[(i + 1) % n])).sum();
    let orientation = area2.signum();
    (0..n).map(|i| orientation * side(poly[i], poly[(i + 1) % n], p)).fold(f64::INFINITY, f64::min)
}

/// Two masks side by side, one character per pixel (`.` for 0, the count otherwise), with the
/// pixels that differ marked `X` in a third column.
pub fn masks_side_by_side(expected: &[u32], actual: &[u32], width: u32, height: u32) -> String {
    let glyph = |n: u32| match n {
        0 => '.',
        1..=9 => char::from_digit(n, 10).unwrap_or('#'),
        _ => '#',
    };
    let w = width as usize;
    let mut out = String::new();
    let _ = writeln!(out, "{:w$}   {:w$}   {:w$}", "expected", "actual", "differs");
    for y in 0..height as usize {
        let row = |m: &[u32]| m[y * w..(y + 1) * w].iter().map(|&n| glyph(n)).collect::<String>();
        let diff: String = (0..w)
            .map(|x| if expected[y * w + x] == actual[y * w + x] { '.' } else { 'X' })
            .collect();
        let _ = writeln!(out, "{}   {}   {}", row(expected), row(actual), diff);
    }
    out
}

/// Window-space triangle from three (x, y) pairs.
pub fn tri(a: (f32, f32), b: (f32, f32), c: (f32, f32)) -> [Vec2; 3] {
    [Vec2::new(a.0, a.1), Vec2::new(b.0, b.1), Vec2::new(c.0, c.1)]
}

/// The RGBA8 value at pixel (x, y) of an output image.
pub fn rgba_at(rgba: &[[u8; 4]], width: u32, x: u32, y: u32) -> [u8; 4] {
    rgba[(y * width + x) as usize]
}

/// GL_REPEAT / GL_CLAMP_TO_EDGE on a coordinate (OpenGL 1.x spec, 3.8.7).
pub fn wrap_coordinate(s: f64, wrap: Wrap) -> f64 {
    match wrap {
        Wrap::Repeat => s - s.floor(),
        Wrap::Clamp => s.clamp(0.0, 1.0),
    }
}

/// A texel index wrapped or clamped into `0..n`.
pub fn wrap_index(i: i64, n: i64, wrap: Wrap) -> i64 {
    match wrap {
        Wrap::Repeat => i.rem_euclid(n),
        Wrap::Clamp => i.clamp(0, n - 1),
    }
}

/// The texture's RGB at (s, t) in f64, by the specification's formulas (3.8.8): nearest takes
/// texel ⌊s·w⌋; linear blends the four texels around (s·w − ½, t·h − ½).
pub fn sample_f64(tex: &Texture, st: DVec2, sampler: Sampler) -> DVec3 {
    let (w, h) = (i64::from(tex.width), i64::from(tex.height));
    let texel = |i: i64, j: i64| {
        let [r, g, b, _] = tex.texel(
            wrap_index(i, w, sampler.wrap_u) as u32,
            wrap_index(j, h, sampler.wrap_v) as u32,
        );
        DVec3::new(r.into(), g.into(), b.into()) / 255.0
    };
    let s = wrap_coordinate(st.x, sampler.wrap_u);
    let t = wrap_coordinate(st.y, sampler.wrap_v);
    match sampler.filter {
        Filter::Nearest => texel(
            ((s * w as f64).floor() as i64).min(w - 1),
            ((t * h as f64).floor() as i64).min(h - 1),
        ),
        Filter::Bilinear => {
            let (u, v) = (s * w as f64 - 0.5, t * h as f64 - 0.5);
            let (i0, j0) = (u.floor() as i64, v.floor() as i64);
            let (a, b) = (u - u.floor(), v - v.floor());
            let bottom = texel(i0, j0) * (1.0 - a) + texel(i0 + 1, j0) * a;
            let top = texel(i0, j0 + 1) * (1.0 - a) + texel(i0 + 1, j0 + 1) * a;
            bottom * (1.0 - b) + top * b
        }
    }
}

/// The world point (view space = world space) at depth `z = −2` that [`looking_down_z`]`(size,
/// size, 90°)` maps to window point `(px, py)` exactly: half-integers give pixel centres, without
/// rounding (the projection's numbers are powers of two there).
pub fn on_screen_at(size: u32, px: f32, py: f32) -> Vec3 {
    let s = size as f32;
    Vec3::new((2.0 * px / s - 1.0) * 2.0, (1.0 - 2.0 * py / s) * 2.0, -2.0)
}
