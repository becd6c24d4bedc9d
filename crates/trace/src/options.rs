//! What [`crate::render`] is asked to do.

use cg_core::scene::Shading;

/// The deepest [`Options::max_depth`] the tracer accepts: deeper requests are an error rather
/// than a stack overflow or a run that never ends.
pub const MAX_DEPTH_LIMIT: u32 = 64;

/// The largest image side the tracer renders, in pixels: [`cg_core::image::MAX_SIDE`]. An image
/// also has at most [`cg_core::image::MAX_PIXELS`] pixels in all.
pub const MAX_SIZE: u32 = cg_core::image::MAX_SIDE;

/// The default [`Options::ray_budget`]: 256 reflected and refracted rays per pixel. At the
/// default depth 5 a pixel's tree has at most 2 + 4 + … + 32 = 62 of them, so the budget never
/// binds there; it stops trees that would otherwise grow as 2^depth.
pub const DEFAULT_RAY_BUDGET: u32 = 256;

/// Which Fresnel reflectance splits k_t's share between reflection and transmission.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Fresnel {
    /// The exact dielectric formula, [`cg_core::optics::fresnel_dielectric`].
    #[default]
    Exact,
    /// Schlick's approximation, [`cg_core::optics::schlick`].
    Schlick,
}

impl Fresnel {
    /// The reflectance F at an interface with `cos θ_i = cos_i` from a medium of index `eta_i`
    /// into one of index `eta_t`; in `[0, 1]`, 1 under total internal reflection.
    #[must_use]
    pub fn reflectance(self, cos_i: f32, eta_i: f32, eta_t: f32) -> f32 {
        match self {
            Fresnel::Exact => cg_core::optics::fresnel_dielectric(cos_i, eta_i, eta_t),
            Fresnel::Schlick => cg_core::optics::schlick(cos_i, eta_i, eta_t),
        }
    }
}

/// How to trace a scene. [`Options::default`] traces the scene as it is, at its own size.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Image size `(width, height)` in pixels; `None`: the scene's own. The projection's aspect
    /// ratio follows this size, as gluPerspective's does in the reshape callback.
    pub size: Option<(u32, u32)>,
    /// How many times rays may be reflected or refracted: primary rays have depth 0, and a hit
    /// at depth `max_depth` gets no global terms (k_r·I_r = k_t·I_t = 0 there; see the crate
    /// docs). At most [`MAX_DEPTH_LIMIT`]. Default 5.
    pub max_depth: u32,
    /// Exact Fresnel or Schlick's approximation. Default exact.
    pub fresnel: Fresnel,
    /// Cast shadow rays (影). `false`: every light is visible from every point. Default `true`.
    pub shadows: bool,
    /// Intersect objects that have an exact surface ([`cg_core::scene::Object::analytic`]:
    /// spheres, the ground square) exactly; `false`: always their triangles, as a rasterizer
    /// draws them. Default `true`.
    pub analytic: bool,
    /// Worker threads; `None` (or `Some(0)`): rayon's global pool, one per core. The image is
    /// the same whatever the count.
    pub threads: Option<usize>,
    /// Override the scene's shading mode. `Flat` lights each triangle once, as the rasterizer:
    /// at its centroid with its face normal in the lecture's light model, at its provoking
    /// (last) vertex with that vertex's normal and colour in OpenGL's (GL_FLAT); `Gouraud` and
    /// `Phong` light every hit point with the interpolated vertex normals (a ray tracer has no
    /// vertex colours to interpolate, so Gouraud is traced as Phong, and
    /// [`crate::Output::shading`] says so). Exact spheres and planes have no faces: they are lit
    /// at every hit point in every mode.
    pub shading: Option<Shading>,
    /// Adaptive depth control (Hall and Greenberg, 1983): a reflected or transmitted ray whose
    /// weight along its path (the product of the k_r / k_t·F factors that lead to it, largest
    /// channel) is below this is not cast, and counted in [`crate::Stats::pruned_rays`]. The
    /// default `1/1024` is a quarter of one 8-bit step, so what is left out changes a pixel by at
    /// most a quarter step per pruned ray (for colours ≤ 1). `0`: prune nothing, pure Whitted.
    pub min_weight: f32,
    /// The most reflected and refracted rays one pixel may cast, over its whole ray tree
    /// (default [`DEFAULT_RAY_BUDGET`]). The tree is traced depth first, the reflected ray before
    /// the refracted one at each hit; once a pixel's budget is spent, its remaining global rays
    /// are not cast (their terms are 0, counted in [`crate::Stats::rays_over_budget`]). This
    /// bounds the work per pixel whatever the scene: with k_r + k_t > 1 (scenes built in code;
    /// the scene loader refuses them) path weights do not shrink, [`Options::min_weight`] cannot
    /// prune, and the tree would grow as 2^depth. `0`: no global rays at all.
    pub ray_budget: u32,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            size: None,
            max_depth: 5,
            fresnel: Fresnel::Exact,
            shadows: true,
            analytic: true,
            threads: None,
            shading: None,
            min_weight: 1.0 / 1024.0,
            ray_budget: DEFAULT_RAY_BUDGET,
        }
    }
}
