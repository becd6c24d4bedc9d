//! The per-student variant: a material, a light, the sphere's tessellation and a refractive index,
//! drawn from friendly tables (table version 1, frozen).

use cg_harness::VariantRng;
use serde::Serialize;

/// A named colour.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Named {
    /// 日本語の名前
    pub ja: &'static str,
    /// English name
    pub en: &'static str,
    /// RGB
    pub rgb: [f32; 3],
}

/// The object's material (物体の反射特性).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MaterialSpec {
    /// k_a = k_d, the object's colour (glColor under GL_COLOR_MATERIAL).
    pub color: Named,
    /// k_s, grey (the same in R, G and B).
    pub ks: f32,
    /// n, the specular exponent (ハイライトの鋭さ).
    pub shininess: f32,
}

/// The light (光源): a point light without attenuation, for the images.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct LightSpec {
    /// Its position in world space.
    pub position: [f32; 3],
    /// I_i, its colour (diffuse and specular intensity).
    pub color: Named,
    /// I_a, the ambient light (環境光), grey.
    pub ambient: f32,
}

/// Distance attenuation coefficients (s.t4).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AttenuationSpec {
    /// k_c
    pub kc: f32,
    /// k_l
    pub kl: f32,
    /// k_q
    pub kq: f32,
}

/// A spot light's cone (s.t4).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SpotSpec {
    /// Half-angle of the cone, degrees (GL_SPOT_CUTOFF).
    pub cutoff_deg: f32,
    /// Falloff exponent (GL_SPOT_EXPONENT).
    pub exponent: f32,
}

/// The sphere of the shading images (s.t5, s.t6): a UV sphere of radius 1
/// ([`cg_core::shapes::uv_sphere`]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct SphereSpec {
    /// Meridians (経線の数).
    pub slices: u32,
    /// Bands from pole to pole (緯度方向の分割数).
    pub stacks: u32,
}

impl SphereSpec {
    /// The number of triangles, `2·slices·(stacks − 1)`.
    #[must_use]
    pub fn faces(&self) -> u32 {
        2 * self.slices * (self.stacks - 1)
    }
}

/// A transparent medium (s.t8), seen from air (η = 1).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MediumSpec {
    /// 日本語の名前
    pub ja: &'static str,
    /// English name
    pub en: &'static str,
    /// Its refractive index η (屈折率).
    pub eta: f32,
}

impl MediumSpec {
    /// The critical angle for light leaving the medium into air, `asin(1/η)`, in degrees.
    #[must_use]
    pub fn critical_angle_deg(&self) -> f64 {
        (1.0 / f64::from(self.eta)).asin().to_degrees()
    }
}

/// What one student works with (table version 1).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Spec {
    /// The object's material.
    pub material: MaterialSpec,
    /// The light.
    pub light: LightSpec,
    /// Attenuation coefficients for s.t4.
    pub attenuation: AttenuationSpec,
    /// The spot light's cone for s.t4.
    pub spot: SpotSpec,
    /// The sphere of the images.
    pub sphere: SphereSpec,
    /// The medium for s.t8.
    pub medium: MediumSpec,
}

const fn named(ja: &'static str, en: &'static str, rgb: [f32; 3]) -> Named {
    Named { ja, en, rgb }
}

/// Object colours (k_a = k_d).
pub const COLORS: [Named; 8] = [
    named("赤", "red", [0.8, 0.2, 0.2]),
    named("橙", "orange", [0.9, 0.5, 0.1]),
    named("黄", "yellow", [0.8, 0.7, 0.1]),
    named("緑", "green", [0.2, 0.7, 0.3]),
    named("青", "blue", [0.2, 0.3, 0.8]),
    named("紫", "purple", [0.6, 0.3, 0.8]),
    named("水色", "sky blue", [0.3, 0.7, 0.9]),
    named("桃色", "pink", [0.9, 0.4, 0.6]),
];

/// k_s (grey).
pub const SPECULAR: [f32; 3] = [0.6, 0.8, 1.0];

/// Specular exponents n.
pub const SHININESS: [f32; 4] = [40.0, 60.0, 80.0, 100.0];

/// Light colours I_i.
pub const LIGHT_COLORS: [Named; 3] = [
    named("白", "white", [1.0, 1.0, 1.0]),
    named("暖色", "warm white", [1.0, 0.9, 0.7]),
    named("寒色", "cool white", [0.8, 0.9, 1.0]),
];

/// Light positions (world space; the course's is (10, 10, 10)).
pub const LIGHT_POSITIONS: [[f32; 3]; 4] =
    [[10.0, 10.0, 10.0], [-10.0, 10.0, 10.0], [5.0, 10.0, 10.0], [-5.0, 8.0, 10.0]];

/// Ambient light I_a (grey).
pub const AMBIENT: [f32; 2] = [0.1, 0.2];

/// Attenuation coefficients (k_c, k_l, k_q).
pub const ATTENUATIONS: [AttenuationSpec; 4] = [
    AttenuationSpec { kc: 1.0, kl: 0.1, kq: 0.01 },
    AttenuationSpec { kc: 1.0, kl: 0.05, kq: 0.02 },
    AttenuationSpec { kc: 0.5, kl: 0.2, kq: 0.0 },
    AttenuationSpec { kc: 1.0, kl: 0.0, kq: 0.04 },
];

/// Spot cut-off half-angles in degrees.
pub const SPOT_CUTOFFS: [f32; 4] = [15.0, 20.0, 30.0, 45.0];

/// Spot exponents.
pub const SPOT_EXPONENTS: [f32; 4] = [0.0, 1.0, 2.0, 5.0];

/// Sphere tessellations (slices, stacks).
pub const SPHERES: [SphereSpec; 4] = [
    SphereSpec { slices: 8, stacks: 6 },
    SphereSpec { slices: 12, stacks: 6 },
    SphereSpec { slices: 12, stacks: 8 },
    SphereSpec { slices: 16, stacks: 10 },
];

/// Media and their refractive indices.
pub const MEDIA: [MediumSpec; 4] = [
    MediumSpec { ja: "水", en: "water", eta: 1.33 },
    MediumSpec { ja: "ガラス", en: "glass", eta: 1.5 },
    MediumSpec { ja: "サファイア", en: "sapphire", eta: 1.77 },
    MediumSpec { ja: "ダイヤモンド", en: "diamond", eta: 2.42 },
];

/// The student's variant, drawn from their frozen stream (integer draws only).
#[must_use]
pub fn variant(rng: &mut VariantRng) -> Spec {
    let color = *rng.pick(&COLORS);
    let ks = *rng.pick(&SPECULAR);
    let shininess = *rng.pick(&SHININESS);
    let light_color = *rng.pick(&LIGHT_COLORS);
    let position = *rng.pick(&LIGHT_POSITIONS);
    let ambient = *rng.pick(&AMBIENT);
    let attenuation = *rng.pick(&ATTENUATIONS);
    let cutoff_deg = *rng.pick(&SPOT_CUTOFFS);
    let exponent = *rng.pick(&SPOT_EXPONENTS);
    let sphere = *rng.pick(&SPHERES);
    let medium = *rng.pick(&MEDIA);
    Spec {
        material: MaterialSpec { color, ks, shininess },
        light: LightSpec { position, color: light_color, ambient },
        attenuation,
        spot: SpotSpec { cutoff_deg, exponent },
        sphere,
        medium,
    }
}
