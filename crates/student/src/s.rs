//! Assignment `s` — シェーディング（第11回） (shading, lecture 11): the shading modes
//! ([`Shading`]), what one pixel of a triangle knows ([`Pixel`]) and the functions you write
//! ([`Impl`]). Plain data: the kit computes the expected light terms, normals, images and
//! directions on its own side, out of your crate's reach.
//!
//! 課題 `s`（シェーディング）: シェーディングの種類、ピクセルの情報、あなたが書く関数の表。
//! 答えを計算する関数はここにはありません。

use crate::left_out;
use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::Rgb;
use crate::mesh::Mesh;

/// Flat, Gouraud or Phong shading (フラット／グロー／フォンシェーディング): which one
/// `shade_pixel` (s.t6) is asked for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Shading {
    /// The face normal lights each face once; one colour per face.
    Flat,
    /// Vertex normals light each vertex; colours are interpolated (OpenGL's GL_SMOOTH).
    Gouraud,
    /// Vertex normals are interpolated and renormalised; every pixel is lit.
    Phong,
}

/// What `shade_pixel` (s.t6) knows about one pixel of a triangle, everything in world space
/// (ワールド座標系), where the light is.
///
/// The corners are the face's corners in its own order (`F { V0, V1, V2 }` of the report); the
/// weights say how much of each corner there is at the pixel (ピクセルと頂点の距離により決まるウェイト):
/// `w₀ + w₁ + w₂ = 1`, each in `[0, 1]`, already corrected for perspective — the weights the
/// renderer itself interpolates with.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
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

impl Impl {
    /// For the kit, not for your code: what stands in for `exercises/src/s.rs` while that file
    /// does not compile, so that the other assignments still build and run. The kit never calls
    /// these functions: it says the file does not compile instead.
    #[must_use]
    pub fn left_out() -> Impl {
        Impl {
            ambient: |_, _| left_out("s"),
            diffuse: |_, _, _, _| left_out("s"),
            specular: |_, _, _, _, _, _| left_out("s"),
            attenuation: |_, _, _, _| left_out("s"),
            spot_factor: |_, _, _, _| left_out("s"),
            vertex_normals: |_| left_out("s"),
            vertex_normals_area: |_| left_out("s"),
            shade_pixel: |_, _, _| left_out("s"),
            reflect: |_, _| left_out("s"),
            refract: |_, _, _, _| left_out("s"),
        }
    }
}
