//! Assignment `s` — シェーディング（第11回） (shading, lecture 11): the lecture itself as exercises.
//!
//! Every assignment crate has the same shape (the command line and the tests rely on it):
//! [`ID`], a per-student [`Spec`] drawn by [`variant`] and described by [`Spec::describe`], the
//! exercise API [`Impl`] (the functions a student writes, in `exercises/src/s.rs`),
//! [`checks`] and [`view`].
//!
//! ## The tasks
//!
//! The light model of the lecture (光のモデル),
//!
//! ```text
//! I = Ia·ka + Σᵢ Iᵢ·[kd (N·L) + ks (R·V)ⁿ] + kr·Ir + kt·It
//!     環境光      拡散反射光   鏡面反射光(局所)   鏡面反射光・透過光(大域)
//! ```
//!
//! term by term, the light types, vertex normals and the three shading methods:
//!
//! | task | what the student writes | [`Impl`] field | checked against |
//! |---|---|---|---|
//! | s.t1 | 環境光 `Ia·ka` | `ambient` | [`cg_core::light::ambient`] |
//! | s.t2 | 拡散反射光 `Iᵢ·kd·max(N·L, 0)` (Lambert) | `diffuse` | [`cg_core::light::diffuse`] |
//! | s.t3 | 鏡面反射光 `Iᵢ·ks·max(R·V, 0)ⁿ` (Phong) | `specular` | [`cg_core::light::specular_phong`] |
//! | s.t4 | 減衰 `1/(kc + kl·d + kq·d²)` and the spot light's cone | `attenuation`, `spot_factor` | [`cg_core::light::attenuation`], [`cg_core::light::spot_factor`] |
//! | s.t5 | 頂点の法線: the average of the adjacent face normals, plain and area-weighted | `vertex_normals`, `vertex_normals_area` | [`cg_core::normals::vertex_normals`] |
//! | s.t6 | フラット／グロー／フォンシェーディング: what to light at a pixel | `shade_pixel` | the CPU rasterizer's own flat, Gouraud and Phong images |
//! | s.t7 | 鏡面反射 (大域照明): the mirror direction | `reflect` | [`cg_core::optics::reflect`] |
//! | s.t8 | 透過光: refraction by Snell's law, total internal reflection | `refract` | [`cg_core::optics::refract`] with [`cg_core::optics::Interface`] |
//!
//! ## How s.t6 meets the rasterizer
//!
//! The rasterizer's lighting hook ([`cg_raster::Lighting`]) is told only *how* to light a point;
//! *where* the lighting happens — once per face, per vertex or per pixel — is decided inside the
//! renderer. Since that "where" is the lecture's point, the kit asks the renderer, through the
//! same hook, which face every pixel sees and with which corner weights (a G-buffer, see
//! [`render`]), and lets the student's [`Impl::shade_pixel`] decide the colour of each pixel
//! from the shading mode, the face normal, the vertex normals and the weights. A correct
//! `shade_pixel` reproduces the renderer's own images; the checks compare them.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::mesh::Mesh;
use cg_core::scene::Scene;
use cg_harness::{CheckResult, Text, VariantRng};

mod checks;
mod describe;
mod inputs;
pub mod render;
pub mod scenes;
pub mod spec;
mod view;

pub use checks::kit_rule;

pub use cg_core::scene::Shading;
pub use spec::Spec;

/// The assignment's ID, the prefix of its task IDs (`s.t1`, …).
pub const ID: &str = "s";

/// What `shade_pixel` (s.t6) knows about one pixel of a triangle, everything in world space
/// (ワールド座標系), where the light is.
///
/// The corners are the face's corners in its own order (`F { V0, V1, V2 }` of the report); the
/// weights say how much of each corner there is at the pixel (画素と頂点の距離により決まるウェイト):
/// `w₀ + w₁ + w₂ = 1`, each in `[0, 1]`, already corrected for perspective — the weights the
/// renderer itself interpolates with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pixel {
    /// The corner positions P₀, P₁, P₂.
    pub positions: [Vec3; 3],
    /// The vertex normals N₀, N₁, N₂ at the corners (頂点の法線), unit length.
    pub normals: [Vec3; 3],
    /// The face normal (面の法線), unit length.
    pub face_normal: Vec3,
    /// The weights w₀, w₁, w₂ of the corners at this pixel.
    pub weights: [f32; 3],
}

/// The functions a student writes (see `exercises/src/s.rs`), as plain function pointers.
///
/// Every vector is in world space; colours and reflectances are RGB ([`Rgb`]); angles are in
/// degrees where the name says `_deg`.
#[derive(Clone, Copy, Debug)]
pub struct Impl {
    /// s.t1 環境光: `ambient(ia, ka) = Ia·ka`.
    pub ambient: fn(ia: Rgb, ka: Rgb) -> Rgb,
    /// s.t2 拡散反射光: `diffuse(ii, kd, n, l) = Iᵢ·kd·max(N·L, 0)`.
    pub diffuse: fn(ii: Rgb, kd: Rgb, n: Vec3, l: Vec3) -> Rgb,
    /// s.t3 鏡面反射光: `specular(ii, ks, n, l, v, shininess) = Iᵢ·ks·max(R·V, 0)ⁿ`, 0 where
    /// `N·L ≤ 0`.
    pub specular: fn(ii: Rgb, ks: Rgb, n: Vec3, l: Vec3, v: Vec3, shininess: f32) -> Rgb,
    /// s.t4 減衰: `attenuation(kc, kl, kq, d) = 1/(kc + kl·d + kq·d²)`.
    pub attenuation: fn(kc: f32, kl: f32, kq: f32, d: f32) -> f32,
    /// s.t4 スポットライト: the factor of a spot light with axis `spot_direction`, cut-off
    /// `cutoff_deg` and `exponent` for a point that sees the light in direction `l`.
    pub spot_factor: fn(l: Vec3, spot_direction: Vec3, cutoff_deg: f32, exponent: f32) -> f32,
    /// s.t5 頂点の法線: the plain average of the adjacent face normals, one per vertex.
    pub vertex_normals: fn(mesh: &Mesh) -> Vec<Vec3>,
    /// s.t5 頂点の法線: the area-weighted average (面の面積に応じて加重平均).
    pub vertex_normals_area: fn(mesh: &Mesh) -> Vec<Vec3>,
    /// s.t6 フラット／グロー／フォン: the colour of one pixel in shading mode `mode`; `light(p, n)`
    /// is the lighting stage (光源処理): the colour, clamped to `[0, 1]`, that the scene's light
    /// gives a point `p` with unit normal `n`.
    // Spelled out as the student writes it in exercises/src/s.rs (a type alias would hide it).
    #[allow(clippy::type_complexity)]
    pub shade_pixel: fn(mode: Shading, pixel: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb,
    /// s.t7 鏡面反射: the mirror direction of `i` about `n`.
    pub reflect: fn(i: Vec3, n: Vec3) -> Vec3,
    /// s.t8 屈折: the refracted direction by Snell's law, `None` under total internal reflection.
    pub refract: fn(i: Vec3, n: Vec3, n1: f32, n2: f32) -> Option<Vec3>,
}

/// The student's variant, drawn from the frozen stream of their number and table version (see
/// [`spec`] for the tables).
#[must_use]
pub fn variant(rng: &mut VariantRng) -> Spec {
    spec::variant(rng)
}

impl Spec {
    /// The assignment text for this variant, in `lang`: every task with its ID, this student's
    /// numbers, and what the report must show.
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        describe::describe(self, lang)
    }
}

/// Every check of this assignment for `spec`, run against `imp` (IDs `s.tN.name`; see
/// `docs/assignments/s.md` for the list).
#[must_use]
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    checks::all(spec, imp)
}

/// The scene that shows `imp`'s result: the course's stage (its window, camera and ground) with
/// the student's light and three of the student's spheres on the ground — flat, Gouraud and
/// Phong from left to right — each pixel of the spheres coloured by the student's
/// `shade_pixel` with the student's vertex normals and, where they are written, the student's
/// own light-model terms (s.t1–s.t3; the kit's stand in for terms still `todo!()`).
///
/// The renderer that draws a view lights scenes its own way, so the picture is composed here and
/// handed over as a screen-filling quad that shows it pixel for pixel. `time_s` is not used.
///
/// # Errors
/// What keeps the stage from being drawn (never for the kit's own scenes).
pub fn view(spec: &Spec, imp: &Impl, time_s: f64) -> Result<Scene, Text> {
    let _ = time_s;
    view::view(spec, imp)
}
