//! What a render did, counted: the proof that it did only what the scene needs.

use cg_core::lang::{Text, t};
/// Counters of one render. Every count is exact and independent of the thread count.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Rays from the eye, one per pixel.
    pub primary_rays: u64,
    /// Shadow rays towards point lights and area-light samples (directional lights: to ∞).
    pub shadow_rays: u64,
    /// Mirror-reflected rays (k_r·I_r, and the Fresnel-reflected share of k_t).
    pub reflection_rays: u64,
    /// Refracted (transmitted) rays (k_t·I_t).
    pub refraction_rays: u64,
    /// Hits on a transparent surface where refraction was impossible (全反射): all of k_t's
    /// share went into the reflected ray.
    pub total_internal_reflections: u64,
    /// Reflected or transmitted rays not cast because their path weight was below
    /// [`crate::Options::min_weight`].
    pub pruned_rays: u64,
    /// Reflected or transmitted rays not cast because their pixel had used up its
    /// [`crate::Options::ray_budget`].
    pub rays_over_budget: u64,
    /// Evaluations of the local light model (one per hit shaded).
    pub lighting_evaluations: u64,
    /// Specular terms computed by the light model (per hit, one per point light or area-light
    /// sample that reaches it and is not in shadow, when k_s ≠ 0), counted inside
    /// [`cg_core::light::shade_with_visibility_counted`].
    pub specular_evaluations: u64,
    /// Distance attenuations computed by the light model (never for directional lights or
    /// OpenGL's default (1, 0, 0)), counted inside it.
    pub attenuation_evaluations: u64,
    /// `hits_per_depth[d]`: rays of depth `d` (0 = primary) that hit a surface. Its length is
    /// one more than the deepest hit.
    pub hits_per_depth: Vec<u64>,
    /// The depth of the deepest ray cast (0 when only primary rays were cast).
    pub deepest_ray: u32,
    /// BVH nodes whose bounding box was tested, over all rays.
    pub bvh_nodes_visited: u64,
}

impl Stats {
    /// Adds what the light model counted at one hit ([`cg_core::light::LightCounts`]).
    pub(crate) fn add_lighting(&mut self, counts: &cg_core::light::LightCounts) {
        self.lighting_evaluations += counts.evaluations;
        self.specular_evaluations += counts.specular;
        self.attenuation_evaluations += counts.attenuations;
    }

    /// Counts a hit by a ray of depth `depth`.
    pub fn count_hit(&mut self, depth: u32) {
        let d = depth as usize;
        if self.hits_per_depth.len() <= d {
            self.hits_per_depth.resize(d + 1, 0);
        }
        self.hits_per_depth[d] += 1;
    }

    /// Adds `other`'s counts to these (sums; `deepest_ray` the maximum).
    pub fn merge(&mut self, other: &Stats) {
        self.primary_rays += other.primary_rays;
        self.shadow_rays += other.shadow_rays;
        self.reflection_rays += other.reflection_rays;
        self.refraction_rays += other.refraction_rays;
        self.total_internal_reflections += other.total_internal_reflections;
        self.pruned_rays += other.pruned_rays;
        self.rays_over_budget += other.rays_over_budget;
        self.lighting_evaluations += other.lighting_evaluations;
        self.specular_evaluations += other.specular_evaluations;
        self.attenuation_evaluations += other.attenuation_evaluations;
        if self.hits_per_depth.len() < other.hits_per_depth.len() {
            self.hits_per_depth.resize(other.hits_per_depth.len(), 0);
        }
        for (a, b) in self.hits_per_depth.iter_mut().zip(&other.hits_per_depth) {
            *a += b;
        }
        self.deepest_ray = self.deepest_ray.max(other.deepest_ray);
        self.bvh_nodes_visited += other.bvh_nodes_visited;
    }

    /// The counters with their names (hits per depth as one entry per depth).
    #[must_use]
    pub fn list(&self) -> Vec<(Text, u64)> {
        let mut list = vec![
            (t("一次レイ", "primary rays"), self.primary_rays),
            (t("影のレイ", "shadow rays"), self.shadow_rays),
            (t("反射レイ", "reflection rays"), self.reflection_rays),
            (t("屈折レイ", "refraction rays"), self.refraction_rays),
            (t("全反射", "total internal reflections"), self.total_internal_reflections),
            (t("省略したレイ（重みが小さい）", "pruned rays (small weight)"), self.pruned_rays),
            (
                t("省略したレイ（ピクセルごとの上限）", "rays over the per-pixel budget"),
                self.rays_over_budget,
            ),
            (t("光源処理", "lighting evaluations"), self.lighting_evaluations),
            (t("鏡面反射光", "specular evaluations"), self.specular_evaluations),
            (t("距離による減衰", "attenuation evaluations"), self.attenuation_evaluations),
            (t("最も深いレイ", "deepest ray"), u64::from(self.deepest_ray)),
            (t("BVH ノードの判定", "BVH nodes visited"), self.bvh_nodes_visited),
        ];
        for (depth, hits) in self.hits_per_depth.iter().enumerate() {
            list.push((
                Text::new(format!("交差 深さ {depth}"), format!("hits at depth {depth}")),
                *hits,
            ));
        }
        list
    }

    /// All rays cast: primary, shadow, reflected and refracted.
    #[must_use]
    pub fn total_rays(&self) -> u64 {
        self.primary_rays + self.shadow_rays + self.reflection_rays + self.refraction_rays
    }
}
