//! The light model (光のモデル) of lecture 11:
//!
//! ```text
//! I = Ia·ka + Σᵢ Iᵢ·[kd (N·L) + ks (R·V)ⁿ] + kr·Ir + kt·It
//!     環境光      拡散反射光   鏡面反射光(局所)   鏡面反射光・透過光(大域)
//! ```
//!
//! Materials, the four light types of the lecture (平行光源, 点光源, スポットライト光源, 面光源), and
//! the per-term evaluation of the local model. The global terms `kr·Ir` and `kt·It` need rays and
//! are added by the ray tracer.

use glam::Vec3;

use crate::Rgb;

/// The reflection properties of a surface (物体の反射特性). Every `k` is RGB.
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// k_a, ambient reflectance (環境光の反射係数).
    pub ka: Rgb,
    /// k_d, diffuse reflectance (拡散反射係数).
    pub kd: Rgb,
    /// k_s, specular reflectance (鏡面反射係数).
    pub ks: Rgb,
    /// n, the specular exponent (shininess, ハイライトの鋭さ), ≥ 0.
    pub shininess: f32,
    /// k_r, the weight of the mirror-reflected colour I_r (ray tracer only).
    pub kr: Rgb,
    /// k_t, the weight of the transmitted colour I_t (ray tracer only).
    pub kt: Rgb,
    /// η, the refractive index of the inside of the object (屈折率), ≥ 1 for real materials.
    pub eta: f32,
    /// Emitted colour (GL_EMISSION), added unlit.
    pub emission: Rgb,
}

/// Distance attenuation `1 / (kc + kl·d + kq·d²)` of point, spot and area lights.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attenuation {
    /// kc, GL_CONSTANT_ATTENUATION (default 1).
    pub constant: f32,
    /// kl, GL_LINEAR_ATTENUATION (default 0).
    pub linear: f32,
    /// kq, GL_QUADRATIC_ATTENUATION (default 0).
    pub quadratic: f32,
}

/// Where light comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind {
    /// 平行光源: light from one direction, infinitely far away (GL position `(x, y, z, 0)`).
    /// `to_light` points from the surface *towards* the light; it need not be unit length.
    Directional {
        /// From the surface towards the light (GL_POSITION's xyz with w = 0).
        to_light: Vec3,
    },
    /// 点光源: light from a position, in all directions, attenuated with distance.
    Point {
        /// Where the light is.
        position: Vec3,
    },
    /// スポットライト光源: a point light that shines only inside a cone around `direction`.
    Spot {
        /// Where the light is.
        position: Vec3,
        /// The direction the spot points to (need not be unit length).
        direction: Vec3,
        /// Half-angle of the cone in degrees, `(0, 90]`, or 180 for no cone (GL_SPOT_CUTOFF).
        cutoff_deg: f32,
        /// Falloff exponent towards the rim, ≥ 0 (GL_SPOT_EXPONENT).
        exponent: f32,
        /// Optional inner half-angle in degrees: full intensity inside it, a smooth step between it
        /// and `cutoff_deg`; equal angles give a hard step. Ignored in OpenGL-compatible mode.
        inner_deg: Option<f32>,
    },
    /// 面光源: a parallelogram `corner + s·edge_u + t·edge_v` (s, t in [0, 1]) approximated, as the
    /// lecture says, by a grid of `samples[0] × samples[1]` point lights, each carrying
    /// `1 / (samples[0]·samples[1])` of the light's colours.
    Area {
        /// One corner of the parallelogram.
        corner: Vec3,
        /// The first edge from `corner`.
        edge_u: Vec3,
        /// The second edge from `corner`; the light shines to the side of `edge_u × edge_v`.
        edge_v: Vec3,
        /// Point lights along `edge_u` and `edge_v` (each ≥ 1).
        samples: [u32; 2],
    },
}

/// A light source in world space (the course sets the light after the camera, so it stays fixed in
/// the world). Colours follow OpenGL: separate ambient, diffuse and specular intensities I_i.
#[derive(Clone, Debug, PartialEq)]
pub struct Light {
    /// Type and geometry.
    pub kind: LightKind,
    /// Ambient intensity this light adds (GL_AMBIENT).
    pub ambient: Rgb,
    /// Diffuse intensity I_i (GL_DIFFUSE).
    pub diffuse: Rgb,
    /// Specular intensity I_i (GL_SPECULAR).
    pub specular: Rgb,
    /// Distance attenuation (ignored for directional lights).
    pub attenuation: Attenuation,
}

/// The specular term of the lecture's model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Specular {
    /// Phong: `(R·V)ⁿ`, R the mirror direction of L (the lecture's formula).
    #[default]
    Phong,
    /// Blinn: `(N·H)ⁿ`, H = normalise(L + V) (what OpenGL computes).
    Blinn,
}

/// Which equation lights the scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LightModel {
    /// The lecture's model, term by term (see the module docs).
    Lecture {
        /// Phong (R·V) or Blinn (N·H) specular.
        specular: Specular,
        /// `true`: V points to the eye from each point; `false`: V is the camera's backward axis.
        local_viewer: bool,
    },
    /// OpenGL 1.x fixed-function lighting, exactly as its specification (section 2.14.1) states:
    /// Blinn specular with H = normalise(L + V), global ambient, per-light ambient
    /// attenuated and spot-scaled, specular only where N·L > 0, infinite viewer unless
    /// `local_viewer` (GL_LIGHT_MODEL_LOCAL_VIEWER).
    OpenGl {
        /// GL_LIGHT_MODEL_LOCAL_VIEWER.
        local_viewer: bool,
    },
}

impl Default for Material {
    /// OpenGL's default material: k_a 0.2, k_d 0.8, k_s 0, n 0, no emission; and the kit's
    /// defaults for the global terms: k_r = k_t = 0, η = 1.
    fn default() -> Material {
        Material {
            ka: Rgb::splat(0.2),
            kd: Rgb::splat(0.8),
            ks: Rgb::ZERO,
            shininess: 0.0,
            kr: Rgb::ZERO,
            kt: Rgb::ZERO,
            eta: 1.0,
            emission: Rgb::ZERO,
        }
    }
}

impl Material {
    /// The material glColor3f gives under GL_COLOR_MATERIAL (GL_AMBIENT_AND_DIFFUSE): k_a = k_d =
    /// `color`, everything else [`Material::default`].
    #[must_use]
    pub fn from_color(color: Rgb) -> Material {
        Material { ka: color, kd: color, ..Material::default() }
    }
}

impl Default for Attenuation {
    /// No attenuation: kc = 1, kl = kq = 0 (OpenGL's default).
    fn default() -> Attenuation {
        Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 }
    }
}
