//! What a render did, counted: the proof that it did only what the scene needs.

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
    /// `hits_per_depth[d]`: rays of depth `d` (0 = primary) that hit a surface. Its length is
    /// one more than the deepest hit.
    pub hits_per_depth: Vec<u64>,
    /// The depth of the deepest ray cast (0 when only primary rays were cast).
    pub deepest_ray: u32,
    /// BVH nodes whose bounding box was tested, over all rays.
    pub bvh_nodes_visited: u64,
}

impl Stats {
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
        if self.hits_per_depth.len() < other.hits_per_depth.len() {
            self.hits_per_depth.resize(other.hits_per_depth.len(), 0);
        }
        for (a, b) in self.hits_per_depth.iter_mut().zip(&other.hits_per_depth) {
            *a += b;
        }
        self.deepest_ray = self.deepest_ray.max(other.deepest_ray);
        self.bvh_nodes_visited += other.bvh_nodes_visited;
    }

    /// All rays cast: primary, shadow, reflected and refracted.
    #[must_use]
    pub fn total_rays(&self) -> u64 {
        self.primary_rays + self.shadow_rays + self.reflection_rays + self.refraction_rays
    }
}
