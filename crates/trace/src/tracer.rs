//! The tracer: `generate_ray` → `intersect` → `shade` → `trace`, and the render loop over all
//! cores.

use cg_core::Rgb;
use cg_core::features::Features;
use cg_core::glam::Vec3;
use cg_core::image::{Image, check_size};
use cg_core::light::{Light, LightCounts, LightModel, Material, shade_with_visibility_counted};
use cg_core::optics::{Interface, reflect, refract};
use cg_core::scene::{Scene, Shading};
use cg_core::transform::TransformError;
use rayon::prelude::*;

use crate::camera::RayCamera;
use crate::error::TraceError;
use crate::options::{MAX_DEPTH_LIMIT, Options};
use crate::ray::Ray;
use crate::stats::Stats;
use crate::world::{Flat, Hit, World};

/// What a render produced.
#[derive(Clone, Debug, PartialEq)]
pub struct Output {
    /// The image, each channel clamped to `[0, 1]` (row 0 at the top).
    pub image: Image,
    /// What was done, counted.
    pub stats: Stats,
    /// The parts of the light model this render used: the scene's [`Scene::features`], with
    /// reflection and transmission off when `max_depth` is 0.
    pub features: Features,
    /// The shading the tracer did: [`Shading::Flat`] (each triangle lit once, as the rasterizer
    /// lights it: at its centroid with its face normal in the lecture's light model, at its
    /// provoking vertex with that vertex's normal and colour in OpenGL's) or [`Shading::Phong`] (every hit point lit with the interpolated
    /// normal). [`Shading::Gouraud`] is traced as Phong — a ray tracer lights the points its rays
    /// hit and has no vertex colours to interpolate — so a render asked for Gouraud says Phong
    /// here.
    pub shading: Shading,
}

/// How k_r, k_t and the Fresnel reflectance F share a hit's global terms (see the crate docs):
/// the reflected ray carries `k_r + k_t·F`, the transmitted ray `k_t·(1 − F)`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Weights {
    /// The weight of I_r, the colour seen along the mirror direction.
    pub reflected: Rgb,
    /// The weight of I_t, the colour seen along the refracted direction.
    pub transmitted: Rgb,
}

impl Weights {
    /// `reflected = k_r + k_t·F`, `transmitted = k_t·(1 − F)`: k_r is all mirror, and k_t is
    /// split by F, so `reflected + transmitted = k_r + k_t` (up to one rounding per channel).
    /// `fresnel` is clamped to `[0, 1]`; NaN is taken as 1 (all reflected, never NaN out). Under
    /// total internal reflection pass `fresnel = 1`: all of k_t goes to the reflected ray.
    #[must_use]
    pub fn split(kr: Rgb, kt: Rgb, fresnel: f32) -> Weights {
        let f = if fresnel.is_nan() { 1.0 } else { fresnel.clamp(0.0, 1.0) };
        Weights { reflected: kr + kt * f, transmitted: kt * (1.0 - f) }
    }
}

/// A reflected or transmitted ray with the weight of the colour it brings back.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spawned {
    /// The ray, starting just off the surface on its side.
    pub ray: Ray,
    /// Its weight in the hit's colour (RGB).
    pub weight: Rgb,
}

/// The global terms' rays at one hit: mirror reflection (k_r·I_r plus k_t's reflected share) and
/// refraction (k_t's transmitted share).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct GlobalRays {
    /// The mirror-reflected ray, when its weight is not zero.
    pub reflection: Option<Spawned>,
    /// The refracted ray, when k_t ≠ 0, there is no total internal reflection and F < 1.
    pub transmission: Option<Spawned>,
    /// k_t ≠ 0 but refraction is impossible here (全反射): F = 1.
    pub total_internal_reflection: bool,
    /// The Fresnel reflectance F used (0 when k_t = 0; 1 under total internal reflection).
    pub fresnel: f32,
}

/// A scene made ready to trace: its geometry in world space with a BVH, its camera, and the
/// options. [`crate::render`] is `Tracer::new(scene, options)?.render()`; the stages are public
/// so tests and the report can follow single rays.
#[derive(Debug)]
pub struct Tracer<'s> {
    scene: &'s Scene,
    options: Options,
    world: World<'s>,
    camera: RayCamera,
    width: u32,
    height: u32,
    /// The eye for the local viewer's V (the rasterizer's: [`cg_core::scene::Camera::eye_position`]).
    eye: Vec3,
    features: Features,
    shading: Shading,
    pool: Option<rayon::ThreadPool>,
}

impl<'s> Tracer<'s> {
    /// Checks the options, prepares every object, takes the geometry to world space and builds
    /// the BVH, and sets up the camera.
    ///
    /// # Errors
    /// [`TraceError::ZeroSize`], [`TraceError::TooLarge`], [`TraceError::TooManyPixels`],
    /// [`TraceError::MaxDepth`], [`TraceError::MinWeight`] for bad options; [`TraceError::Camera`] and
    /// [`TraceError::Projection`] for an invalid view or projection; [`TraceError::Prepare`] for
    /// an object that cannot be prepared; [`TraceError::Geometry`] and [`TraceError::Texture`]
    /// for objects the tracer cannot place or texture; [`TraceError::Threads`] when the
    /// requested worker threads cannot start.
    pub fn new(scene: &'s Scene, options: &Options) -> Result<Tracer<'s>, TraceError> {
        let (width, height) = options.size.unwrap_or((scene.width, scene.height));
        check_size(width, height)?;
        if options.max_depth > MAX_DEPTH_LIMIT {
            return Err(TraceError::MaxDepth { max_depth: options.max_depth });
        }
        if !(options.min_weight >= 0.0 && options.min_weight.is_finite()) {
            return Err(TraceError::MinWeight { value: options.min_weight });
        }
        let view = scene.view_product().and_then(|v| v.matrix()).map_err(TraceError::Camera)?;
        // The scene's projection, at this image's aspect ratio (the rasterizer's matrix).
        let projection =
            scene.projection_matrix_for(width, height).map_err(TraceError::Projection)?;
        let camera = RayCamera::new(view, projection, width, height, scene.cull_back_faces).ok_or(
            TraceError::Camera(TransformError::Overflow {
                what: "the inverse of the view-projection matrix",
            }),
        )?;
        let prepared = scene.prepare().map_err(TraceError::Prepare)?;
        // Gouraud is traced as Phong (see `Output::shading`).
        let shading = match options.shading.unwrap_or(scene.shading) {
            Shading::Flat => Shading::Flat,
            Shading::Gouraud | Shading::Phong => Shading::Phong,
        };
        // Flat shading lights where the rasterizer does: the lecture's model at the centroid,
        // OpenGL's at GL_FLAT's provoking vertex.
        let flat = match (shading, scene.light_model) {
            (Shading::Flat, LightModel::OpenGl { .. }) => Flat::Provoking,
            (Shading::Flat, LightModel::Lecture { .. }) => Flat::Centroid,
            _ => Flat::Off,
        };
        let world = World::build(prepared, &scene.textures, options.analytic, flat)?;
        let mut features = scene.features();
        features.reflection &= options.max_depth > 0;
        features.transmission &= options.max_depth > 0;
        let pool = match options.threads {
            Some(n) if n > 0 => Some(
                rayon::ThreadPoolBuilder::new()
                    .num_threads(n)
                    .build()
                    .map_err(|e| TraceError::Threads { message: e.to_string() })?,
            ),
            _ => None,
        };
        Ok(Tracer {
            scene,
            options: options.clone(),
            world,
            camera,
            width,
            height,
            eye: scene.camera.eye_position(),
            features,
            shading,
            pool,
        })
    }

    /// The shading mode traced: Flat or Phong (Gouraud is traced as Phong; see
    /// [`Output::shading`]).
    #[must_use]
    pub fn shading(&self) -> Shading {
        self.shading
    }

    /// The image size `(width, height)`.
    #[must_use]
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Triangles in the BVH (objects intersected exactly have none there).
    #[must_use]
    pub fn triangle_count(&self) -> usize {
        self.world.triangle_count()
    }

    /// The camera that makes the primary rays.
    #[must_use]
    pub fn camera(&self) -> &RayCamera {
        &self.camera
    }

    /// `generate_ray`: the primary ray through the centre of pixel `(x, y)`, row 0 at the top
    /// (see [`RayCamera::generate_ray`]).
    #[must_use]
    pub fn generate_ray(&self, x: u32, y: u32) -> Ray {
        self.camera.generate_ray(x, y)
    }

    /// `intersect`: the closest hit of `ray` with the scene, `None` when it escapes.
    /// Counts BVH nodes in `stats`.
    pub fn intersect(&self, ray: &Ray, stats: &mut Stats) -> Option<Hit> {
        self.world.intersect(ray, &mut stats.bvh_nodes_visited)
    }

    /// `trace`: the colour seen along `ray`, a ray of depth `depth` (0 = primary): the
    /// background (glClearColor) when it escapes, else [`Tracer::shade`] at its closest hit.
    /// Not clamped; finite (see [`Tracer::shade`]). Its reflected and refracted rays share one
    /// [`Options::ray_budget`].
    pub fn trace(&self, ray: &Ray, depth: u32, stats: &mut Stats) -> Rgb {
        let mut budget = self.options.ray_budget;
        self.trace_path(ray, depth, Rgb::ONE, &mut budget, stats)
    }

    /// `shade`: the colour at `hit` seen along `ray` (of depth `depth`): the local light model
    /// with shadow rays, textured, plus the global terms `k_r·I_r + k_t·I_t` traced one level
    /// deeper while `depth < max_depth` (see the crate docs), at most [`Options::ray_budget`]
    /// reflected and refracted rays in all. Not clamped, but never NaN or ±∞: a NaN channel
    /// (0·∞ from colours beyond f32's range) becomes 0 and ±∞ the largest finite f32.
    pub fn shade(&self, ray: &Ray, hit: &Hit, depth: u32, stats: &mut Stats) -> Rgb {
        let mut budget = self.options.ray_budget;
        self.shade_path(ray, hit, depth, Rgb::ONE, &mut budget, stats)
    }

    fn trace_path(
        &self,
        ray: &Ray,
        depth: u32,
        weight: Rgb,
        budget: &mut u32,
        stats: &mut Stats,
    ) -> Rgb {
        stats.deepest_ray = stats.deepest_ray.max(depth);
        match self.intersect(ray, stats) {
            None => self.scene.clear_color,
            Some(hit) => {
                stats.count_hit(depth);
                self.shade_path(ray, &hit, depth, weight, budget, stats)
            }
        }
    }

    fn shade_path(
        &self,
        ray: &Ray,
        hit: &Hit,
        depth: u32,
        weight: Rgb,
        budget: &mut u32,
        stats: &mut Stats,
    ) -> Rgb {
        let surface = &self.world.surfaces[hit.object];
        // Vertex colours set k_a and k_d (glColor under GL_COLOR_MATERIAL).
        let material = &surface.material().with_color(hit.color);
        // One-sided lighting, as the rasterizer and OpenGL (GL_LIGHT_MODEL_TWO_SIDE off): the
        // outward normal also where a ray sees the back of a surface.
        let n = hit.shading_normal;
        // V: the rasterizer's for primary rays; towards where the ray came from for the others.
        let v = if depth == 0 {
            self.scene.light_model.view_vector(hit.lit_at, self.eye, self.camera.backward())
        } else {
            -ray.direction
        };
        let mut counts = LightCounts::default();
        let terms = shade_with_visibility_counted(
            self.scene.light_model,
            self.scene.global_ambient,
            &self.scene.lights,
            material,
            hit.lit_at,
            n,
            v,
            |light, l, distance| self.visibility(hit, n, material, light, l, distance, stats),
            &mut counts,
        );
        stats.add_lighting(&counts);
        let mut color = terms.total();
        if let (Some((texture, sampler, env)), Some(uv)) = (surface.texture, hit.uv) {
            color = env.apply(color, texture.sample(uv, sampler));
        }
        if depth < self.options.max_depth {
            let global = self.global_rays(ray, hit);
            stats.total_internal_reflections += u64::from(global.total_internal_reflection);
            for (spawned, reflection) in [(global.reflection, true), (global.transmission, false)] {
                let Some(spawned) = spawned else { continue };
                let path = weight * spawned.weight;
                if path.max_element() < self.options.min_weight {
                    stats.pruned_rays += 1;
                    continue;
                }
                if *budget == 0 {
                    stats.rays_over_budget += 1;
                    continue;
                }
                *budget -= 1;
                if reflection {
                    stats.reflection_rays += 1;
                } else {
                    stats.refraction_rays += 1;
                }
                let seen = self.trace_path(&spawned.ray, depth + 1, path, budget, stats);
                color += spawned.weight * seen;
            }
        }
        let color = finite(color);
        debug_assert!(color.is_finite(), "shade gave {color} at {hit:?}");
        color
    }

    /// The visibility of one point light (or area-light sample) from `hit`, for
    /// [`shade_with_visibility_counted`]: 1 or 0 by a shadow ray from the hit point up to the
    /// light (to ∞ for a directional light). No ray is cast when shadows are off (1), or when the
    /// light cannot add diffuse or specular light here — it is behind the surface (`N·L ≤ 0`:
    /// both terms are 0 there) or its colours meet a zero k_d and k_s — (0, which changes
    /// nothing). `l` and `distance` are as the light model sees the light from [`Hit::lit_at`];
    /// the shadow ray itself starts at the hit point and aims at the light from there.
    #[allow(clippy::too_many_arguments)]
    fn visibility(
        &self,
        hit: &Hit,
        n: Vec3,
        material: &Material,
        light: &Light,
        l: Vec3,
        distance: f32,
        stats: &mut Stats,
    ) -> f32 {
        if !self.options.shadows {
            return 1.0;
        }
        let contributes = n.dot(l) > 0.0
            && (light.diffuse * material.kd != Rgb::ZERO
                || light.specular * material.ks != Rgb::ZERO);
        if !contributes {
            return 0.0;
        }
        stats.shadow_rays += 1;
        // From the hit point (the same as from `lit_at`, bit for bit, except under flat shading).
        let (l, distance) = light.direction_from(hit.p).unwrap_or((l, distance));
        let ray = hit.spawn_shadow_ray(l, distance);
        if self.world.occluded(&ray, &mut stats.bvh_nodes_visited) { 0.0 } else { 1.0 }
    }

    /// The reflected and refracted rays at `hit` for a ray travelling along `ray.direction`,
    /// with their weights ([`Weights::split`]):
    ///
    /// - k_r = k_t = 0: none.
    /// - k_t = 0: the mirror ray `reflect(d, N)` with weight k_r.
    /// - k_t ≠ 0: the interface from [`Interface::at`] (outside η = 1, inside the material's η;
    ///   a hit from inside flips N and inverts η). When [`refract`] finds no direction (total
    ///   internal reflection) F = 1 and the mirror ray carries k_r + k_t; otherwise F comes from
    ///   [`crate::Fresnel`] and the rays carry k_r + k_t·F and k_t·(1 − F).
    ///
    /// N is the shading normal; where it disagrees with the geometric normal about which side
    /// the ray is on, or would send a ray to the wrong side of the surface (smooth normals near
    /// a silhouette), the geometric normal is used instead. Rays with a zero weight are left out.
    #[must_use]
    pub fn global_rays(&self, ray: &Ray, hit: &Hit) -> GlobalRays {
        let material = self.world.surfaces[hit.object].material();
        let (kr, kt) = (material.kr, material.kt);
        if kr == Rgb::ZERO && kt == Rgb::ZERO {
            return GlobalRays::default();
        }
        let d = ray.direction;
        let n_g = hit.geometric_normal;
        let n_s = hit.shading_normal;
        let front = hit.is_front(d);
        let same_side = (d.dot(n_s) <= 0.0) == front;
        let first = if same_side { self.scatter(d, n_s, material, front, n_g) } else { None };
        let (reflected, transmitted, fresnel, tir) = first
            .or_else(|| self.scatter(d, n_g, material, front, n_g))
            .unwrap_or((reflect(d, n_g), None, 1.0, kt != Rgb::ZERO));
        let weights =
            if tir { Weights::split(kr, kt, 1.0) } else { Weights::split(kr, kt, fresnel) };
        let spawn = |dir: Vec3, weight: Rgb| {
            (weight != Rgb::ZERO).then(|| Spawned { ray: hit.spawn_ray(dir), weight })
        };
        GlobalRays {
            reflection: spawn(reflected, weights.reflected),
            transmission: transmitted.and_then(|t| spawn(t, weights.transmitted)),
            total_internal_reflection: tir,
            fresnel: if kt == Rgb::ZERO {
                0.0
            } else if tir {
                1.0
            } else {
                fresnel
            },
        }
    }

    /// Reflection and refraction about the normal `n`: `(reflected, refracted, F, TIR)`, or
    /// `None` when a direction lands on the wrong side of the geometric surface.
    fn scatter(
        &self,
        d: Vec3,
        n: Vec3,
        material: &Material,
        front: bool,
        n_g: Vec3,
    ) -> Option<(Vec3, Option<Vec3>, f32, bool)> {
        // The side the ray came from: +1 outside (front), −1 inside.
        let side = if front { 1.0 } else { -1.0 };
        let reflected = reflect(d, n);
        if side * reflected.dot(n_g) <= 0.0 {
            return None;
        }
        if material.kt == Rgb::ZERO {
            return Some((reflected, None, 0.0, false));
        }
        let interface = Interface::at(d, n, 1.0, material.eta)?;
        match refract(d, interface.n, interface.eta) {
            None => Some((reflected, None, 1.0, true)),
            Some(t) => {
                if side * t.dot(n_g) >= 0.0 {
                    return None;
                }
                let f = self.options.fresnel.reflectance(
                    interface.cos_i,
                    interface.eta_i,
                    interface.eta_t,
                );
                Some((reflected, Some(t), f, false))
            }
        }
    }

    /// Renders the whole image: every pixel's primary ray traced, rows spread over the worker
    /// threads (the image and the counts do not depend on how many). Each pixel has its own
    /// [`Options::ray_budget`].
    #[must_use]
    pub fn render(&self) -> Output {
        self.render_with(&|| {})
    }

    /// [`Tracer::render`], calling `row_done` (from the worker threads) as each row of the
    /// image is finished: a caller's progress bar, for a scene that takes minutes.
    #[must_use]
    pub fn render_with(&self, row_done: &(dyn Fn() + Sync)) -> Output {
        let run = || {
            let (w, h) = (self.width as usize, self.height as usize);
            let mut pixels = vec![Rgb::ZERO; w * h];
            let stats = pixels
                .par_chunks_mut(w)
                .enumerate()
                .map(|(y, row)| {
                    let mut stats = Stats::default();
                    for (x, pixel) in row.iter_mut().enumerate() {
                        let ray = self.generate_ray(x as u32, y as u32);
                        stats.primary_rays += 1;
                        let color = self.trace(&ray, 0, &mut stats);
                        *pixel = color.clamp(Rgb::ZERO, Rgb::ONE);
                    }
                    row_done();
                    stats
                })
                .reduce(Stats::default, |mut a, b| {
                    a.merge(&b);
                    a
                });
            (pixels, stats)
        };
        let (pixels, stats) = match &self.pool {
            Some(pool) => pool.install(run),
            None => run(),
        };
        Output {
            image: Image { width: self.width, height: self.height, pixels },
            stats,
            features: self.features,
            shading: self.shading,
        }
    }
}

/// `c` with every channel finite: NaN becomes 0, ±∞ the largest finite f32 of its sign (the
/// image clamps to `[0, 1]` at the end anyway). Colours beyond f32's range come only from scenes
/// built in code (the scene loader bounds colours to `1e6`).
fn finite(c: Rgb) -> Rgb {
    let channel = |x: f32| if x.is_nan() { 0.0 } else { x.clamp(-f32::MAX, f32::MAX) };
    Rgb::new(channel(c.x), channel(c.y), channel(c.z))
}
