//! "Model only what a scene needs": which terms of the light model and which light types a scene
//! actually uses, so every renderer can skip the rest (no specular work when every k_s is 0, no
//! rays when every k_r and k_t is 0, no attenuation for lights that have none) and say what it
//! enabled.

use std::fmt::Write as _;

use crate::Rgb;
use crate::lang::{Lang, Text, t};
use crate::light::LightKind;
use crate::scene::Scene;

/// The parts of the light model and the light types a scene uses. `false` means no object, light
/// or setting of the scene can make that part non-zero, so a renderer may skip it entirely.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Features {
    /// 環境光 I_a·k_a: some k_a ≠ 0 and some ambient light (global or a light's) ≠ 0.
    pub ambient: bool,
    /// 拡散反射光 k_d (N·L): some k_d ≠ 0 and some light with a diffuse colour ≠ 0.
    pub diffuse: bool,
    /// 鏡面反射光 k_s (R·V)ⁿ: some k_s ≠ 0 and some light with a specular colour ≠ 0.
    pub specular: bool,
    /// Emission: some material emits.
    pub emission: bool,
    /// Some light is directional (平行光源).
    pub directional: bool,
    /// Some light is a point light (点光源).
    pub point: bool,
    /// Some light is a spot light (スポットライト光源).
    pub spot: bool,
    /// Some light is an area light (面光源).
    pub area: bool,
    /// Some point, spot or area light has attenuation other than (1, 0, 0).
    pub attenuation: bool,
    /// Some object is textured.
    pub textures: bool,
    /// k_r·I_r, mirror reflection by rays: some k_r ≠ 0.
    pub reflection: bool,
    /// k_t·I_t, transmission by rays: some k_t ≠ 0.
    pub transmission: bool,
    /// V points to the eye from every point (only matters with specular).
    pub local_viewer: bool,
}

fn nonzero(c: Rgb) -> bool {
    c != Rgb::ZERO
}

impl Scene {
    /// What this scene uses of the light model; see [`Features`].
    #[must_use]
    pub fn features(&self) -> Features {
        let materials = || self.objects.iter().map(|o| &o.material);
        let any_material = |f: &dyn Fn(&crate::light::Material) -> bool| materials().any(f);
        let any_light = |f: &dyn Fn(&crate::light::Light) -> bool| self.lights.iter().any(f);
        let light_ambient = nonzero(self.global_ambient) || any_light(&|l| nonzero(l.ambient));
        Features {
            ambient: light_ambient && any_material(&|m| nonzero(m.ka)),
            diffuse: any_light(&|l| nonzero(l.diffuse)) && any_material(&|m| nonzero(m.kd)),
            specular: any_light(&|l| nonzero(l.specular)) && any_material(&|m| nonzero(m.ks)),
            emission: any_material(&|m| nonzero(m.emission)),
            directional: any_light(&|l| matches!(l.kind, LightKind::Directional { .. })),
            point: any_light(&|l| matches!(l.kind, LightKind::Point { .. })),
            spot: any_light(&|l| matches!(l.kind, LightKind::Spot { .. })),
            area: any_light(&|l| matches!(l.kind, LightKind::Area { .. })),
            attenuation: any_light(&crate::light::Light::needs_attenuation),
            textures: self.objects.iter().any(|o| o.texture.is_some()),
            reflection: any_material(&|m| nonzero(m.kr)),
            transmission: any_material(&|m| nonzero(m.kt)),
            local_viewer: self.light_model.local_viewer(),
        }
    }
}

impl Features {
    /// Every feature: its name, whether it is used, and why not when it is not.
    #[must_use]
    pub fn list(&self) -> Vec<(Text, bool, Text)> {
        vec![
            (
                t("環境光", "ambient"),
                self.ambient,
                t("k_a か環境光が 0", "every k_a or every ambient light is 0"),
            ),
            (
                t("拡散反射光", "diffuse"),
                self.diffuse,
                t("k_d か光源の拡散色が 0", "every k_d or every light's diffuse colour is 0"),
            ),
            (
                t("鏡面反射光", "specular"),
                self.specular,
                t("k_s か光源の鏡面色が 0", "every k_s or every light's specular colour is 0"),
            ),
            (t("放射", "emission"), self.emission, t("放射する物体がない", "no material emits")),
            (t("平行光源", "directional lights"), self.directional, t("なし", "none")),
            (t("点光源", "point lights"), self.point, t("なし", "none")),
            (t("スポットライト光源", "spot lights"), self.spot, t("なし", "none")),
            (t("面光源", "area lights"), self.area, t("なし", "none")),
            (
                t("距離による減衰", "attenuation"),
                self.attenuation,
                t("減衰する光源がない", "no light attenuates"),
            ),
            (
                t("テクスチャ", "textures"),
                self.textures,
                t("テクスチャを貼った物体がない", "no textured object"),
            ),
            (
                t("鏡面反射 k_r·I_r", "reflection k_r·I_r"),
                self.reflection,
                t("k_r がすべて 0", "every k_r is 0"),
            ),
            (
                t("透過光 k_t·I_t", "transmission k_t·I_t"),
                self.transmission,
                t("k_t がすべて 0", "every k_t is 0"),
            ),
            (
                t("視点は有限の距離", "local viewer"),
                self.local_viewer,
                t("視点は無限遠", "infinite viewer"),
            ),
        ]
    }

    /// Two lines: what is used, and what is skipped with the reason.
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        let list = self.list();
        let mut out = String::new();
        let used: Vec<&str> = list.iter().filter(|f| f.1).map(|f| f.0.get(lang)).collect();
        let _ = writeln!(out, "{}: {}", t("使う", "enabled").get(lang), used.join(", "));
        let skipped: Vec<String> = list
            .iter()
            .filter(|f| !f.1)
            .map(|f| format!("{} ({})", f.0.get(lang), f.2.get(lang)))
            .collect();
        let _ = write!(out, "{}: {}", t("省略", "skipped").get(lang), skipped.join(", "));
        out
    }
}
