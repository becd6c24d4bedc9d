//! # cg-trace — the kit's Whitted ray tracer (レイトレーシング)
//!
//! Lecture 11's light model has two *global* terms that a rasterizer cannot compute:
//!
//! ```text
//! I = Ia·ka + Σᵢ Iᵢ·[kd (N·L) + ks (R·V)ⁿ] + kr·Ir + kt·It
//!                                             鏡面反射光   透過光 (大域照明)
//! ```
//!
//! `Ir` is the colour seen in the mirror direction and `It` the colour seen through the surface
//! along the refracted direction (スネルの法則). This crate traces rays to find both, after
//! Whitted (1980), together with shadows, on the same scene and camera as the rasterizer:
//!
//! ```text
//! generate_ray ──▶ intersect ──▶ shade ──▶ (colour)
//!  one per pixel    closest hit    local model with shadow rays
//!                   BVH + exact    + kr·trace(reflected) + kt·trace(refracted)   ◀── trace
//! ```
//!
//! | stage | where | what |
//! |---|---|---|
//! | `generate_ray` | [`RayCamera::generate_ray`] | the primary ray through pixel centre `(x + ½, y + ½)`, row 0 at the top, unprojected by the rasterizer's `(P·V)⁻¹` and limited to the near…far range, so both images align pixel for pixel |
//! | `intersect` | [`Tracer::intersect`] | exact spheres and planes ([`cg_core::scene::Analytic`]) by the inverse model matrix; triangles through a binned-SAH [`bvh::Bvh`] with the watertight test of Woop et al. 2013 ([`triangle`]) |
//! | `shade` | [`Tracer::shade`] | [`cg_core::light::shade_with_visibility_counted`] with one shadow ray per point light or area-light sample, the texture ([`cg_core::texture::TexEnv::apply`]), and the global terms |
//! | `trace` | [`Tracer::trace`] | `intersect` then `shade`, or the background (glClearColor) for a ray that escapes |
//!
//! ## How k_r, k_t and Fresnel combine
//!
//! At a hit with reflectances k_r, k_t (RGB) and the Fresnel reflectance F of the interface
//! ([`Fresnel::Exact`] or [`Fresnel::Schlick`], from the cosine on the incident side and the two
//! refractive indices; the outside is air, η = 1):
//!
//! ```text
//! I = local + (k_r + k_t·F)·I_r + k_t·(1 − F)·I_t
//! ```
//!
//! k_r is a mirror that reflects whatever the interface does; k_t is the share of light that
//! meets the interface, which Fresnel splits into its reflected part F and its transmitted part
//! `1 − F`. So the two weights always sum to `k_r + k_t` ([`Weights::split`]). Under total
//! internal reflection (全反射, [`cg_core::optics::refract`] gives no direction) F = 1: all of
//! k_t's share goes to the reflected ray and no transmitted ray is cast. A hit from inside an
//! object (the ray travels along the outward normal) flips the normal and inverts η
//! ([`cg_core::optics::Interface::at`]). With k_t = 0 no Fresnel is evaluated: a mirror
//! reflects exactly k_r.
//!
//! ## Depth limit
//!
//! Primary rays have depth 0; a reflected or refracted ray one more than the ray it came from.
//! A hit at depth [`Options::max_depth`] (default 5) is shaded by the local model only: its
//! global terms are 0 (black), not the background, so a surface seen through too many
//! reflections darkens rather than showing the sky. A ray whose accumulated weight falls below
//! [`Options::min_weight`] is not cast either (adaptive depth control; see there).
//!
//! Each pixel may cast at most [`Options::ray_budget`] reflected and refracted rays in all
//! (default [`DEFAULT_RAY_BUDGET`], 256; the ray tree of the default depth 5 has at most 62):
//! with k_r + k_t > 1 in some channel — the scene loader refuses such materials (energy
//! conservation), a program can still build them — path weights never shrink, `min_weight`
//! cannot prune, and the tree would grow as 2^depth. Rays beyond the budget are not cast and are
//! counted in [`Stats::rays_over_budget`].
//!
//! ## Shadows and the local model
//!
//! The local terms are [`cg_core::light::shade_with_visibility_counted`]'s, with V from
//! [`cg_core::light::LightModel::view_vector`] for primary rays (as the rasterizer) and towards
//! where the ray came from (`−d`) for reflected and refracted rays. Visibility is 0 or 1: one
//! shadow ray from the hit point towards each point light and each area-light sample, ending
//! just short of the light ([`world::SHADOW_EPSILON`]), so nothing beyond a light shadows it;
//! towards a directional light it runs to infinity. Every surface blocks light, glass included
//! (Whitted's tracer scaled by k_t; this one does not).
//!
//! Lighting is **one-sided**, as in the rasterizer and in OpenGL (GL_LIGHT_MODEL_TWO_SIDE off):
//! a surface is lit with its outward normal also where a ray sees its back (a back face with
//! culling off, the inside of a glass sphere), so light from the far side adds nothing there.
//!
//! Shading modes ([`Output::shading`] says which was done): **Phong** lights every hit point
//! with the interpolated normal; **Flat** lights each triangle once — as the rasterizer does: in
//! the lecture's light model at its centroid with its face normal, in OpenGL's at its provoking
//! (last) vertex with that vertex's normal and colour, as GL_FLAT — so a face has one colour
//! (shadows still fall per point); **Gouraud** is traced as Phong (a ray tracer lights the
//! points it hits and has no vertex colours to interpolate). Exact spheres and planes have no
//! faces and are lit at every hit point in every mode.
//!
//! A shaded colour is never NaN or ±∞: NaN (0·∞ from colours beyond f32's range, which only a
//! program can set — the loader bounds colours to 1e6) becomes 0, ±∞ the largest finite f32,
//! before `shade` returns it.
//!
//! ## Only what the scene needs
//!
//! - no reflected ray where k_r and k_t are 0, no refracted ray where k_t is 0, and no Fresnel
//!   work without k_t ([`Stats::reflection_rays`], [`Stats::refraction_rays`] stay 0 for an
//!   opaque scene, and [`Output::features`] says so);
//! - no shadow ray for a light that cannot add diffuse or specular light at the point: behind the
//!   surface (`N·L ≤ 0`), or with colours that meet a zero k_d and k_s;
//! - no attenuation for directional lights (the core light model's rule), and no specular term
//!   where k_s = 0 — both counted where the light model does the work
//!   ([`Stats::specular_evaluations`], [`Stats::attenuation_evaluations`]);
//! - no triangles for spheres and the ground: they are intersected exactly (unless
//!   [`Options::analytic`] is off).
//!
//! ## Robustness
//!
//! Spawned rays start off their surface by the rounding-error bound of the hit point, scaled to
//! its magnitude ([`ray`], after pbrt), so they never hit it again; the triangle test is
//! watertight, so rays do not slip through shared edges; every stage boundary
//! `debug_assert!`s finiteness, and invalid input is a [`TraceError`] with a message in Japanese
//! and English (an image has at most [`cg_core::image::MAX_SIDE`] pixels a side and
//! [`cg_core::image::MAX_PIXELS`] in all). The image and the [`Stats`] are the same whatever the
//! thread count.
//!
//! ```
//! use cg_core::scene::Scene;
//! # fn scene() -> Scene {
//! #     cg_scene::parse("format = 1\n[[objects]]\nname = \"ball\"\nshape = { kind = \"sphere\", radius = 1.0 }\nmaterial = { kr = [0.5, 0.5, 0.5] }\n", std::path::Path::new("inline.toml")).unwrap()
//! # }
//! let scene: Scene = scene();
//! let out = cg_trace::render(&scene, &cg_trace::Options { size: Some((32, 32)), ..Default::default() })
//!     .unwrap();
//! assert_eq!(out.image.width, 32);
//! assert!(out.stats.reflection_rays > 0 && out.features.reflection);
//! assert_eq!(out.stats.refraction_rays, 0);
//! ```

pub mod bvh;
pub mod camera;
mod error;
mod options;
pub mod ray;
mod stats;
mod tracer;
pub mod triangle;
pub mod world;

pub use camera::RayCamera;
pub use error::TraceError;
pub use options::{DEFAULT_RAY_BUDGET, Fresnel, MAX_DEPTH_LIMIT, MAX_SIZE, Options};
pub use ray::Ray;
pub use stats::Stats;
pub use tracer::{GlobalRays, Output, Spawned, Tracer, Weights};
pub use world::{Hit, Primitive};

use cg_core::scene::Scene;

/// Ray-traces `scene` with `options`: [`Tracer::new`] then [`Tracer::render`].
///
/// # Errors
/// See [`Tracer::new`]: a zero or too large size (a side, or the pixel count), a bad option, an invalid camera or projection,
/// an object that cannot be prepared, placed or textured, or worker threads that cannot start.
pub fn render(scene: &Scene, options: &Options) -> Result<Output, TraceError> {
    Ok(Tracer::new(scene, options)?.render())
}

/// [`render`], calling `row_done` as each row of the image is finished ([`Tracer::render_with`]).
///
/// # Errors
/// As [`render`].
pub fn render_with(
    scene: &Scene,
    options: &Options,
    row_done: &(dyn Fn() + Sync),
) -> Result<Output, TraceError> {
    Ok(Tracer::new(scene, options)?.render_with(row_done))
}
