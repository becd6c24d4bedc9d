//! `intersect`: the scene's surfaces in world space — exact spheres and planes, and every other
//! object's triangles in one BVH — and the closest hit of a ray with them.
//!
//! ## Exact surfaces ([`Analytic`])
//!
//! A sphere of radius r about the model origin, or the square `|x|, |z| ≤ size/2` in the model's
//! plane y = 0, is intersected in *model* space: the ray is taken there by the inverse model
//! matrix (f64), the quadratic or linear equation is solved in f64 (the sphere by the
//! numerically careful form of Haines et al., *Ray Tracing Gems* ch. 7: the discriminant from the
//! ray's perpendicular offset, the far root from the near one), and the hit point is put back on
//! the surface (`p ← r·p/|p|`, `y ← 0`) and taken to world space by the model matrix (f64, rounded
//! once to f32). An affine map keeps the ray parameter, so `t` is the world ray's. A singular
//! model matrix (a zero scale) has no inverse: such an object is intersected by its triangles.
//!
//! The bound on the error of such a hit point is pbrt's for a point transformed in f32,
//! `γ₅·(|A|·|p_model| + |T|)` per coordinate (A the 3×3 part of the model matrix, T its
//! translation, |·| element-wise): it covers the one f32 rounding of the f64 result with a wide
//! margin.
//!
//! ## Triangles
//!
//! Every other object's prepared mesh ([`cg_core::scene::Scene::prepare`]) is taken to world
//! space once (positions by the model matrix in f64, vertex normals by
//! [`Prepared::world_normal`]: the cofactor normal matrix, negated back under a mirroring
//! transform, whose corners are also reordered so every face stays counter-clockwise from
//! outside). Degenerate faces (no [`face_normal`]) are left out: they have no area to hit. All
//! triangles of all objects share one [`Bvh`].
//!
//! Texture coordinates are interpolated after the integer [`Sampler::repeat_origin`] of the
//! face's first corner is taken off them (docs/numerics.md row 23: coordinates near 1e6 keep their
//! precision under repeat).
//!
//! Under flat shading a triangle is lit once ([`Hit::lit_at`]), where and with the normal the
//! rasterizer lights it: in the lecture's light model at its centroid with its face
//! normal; in OpenGL's at its provoking vertex (its last corner, GL_FLAT's rule) with that
//! vertex's normal and colour.

use cg_core::Rgb;
use cg_core::glam::{DMat4, DVec3, Vec2, Vec3};
use cg_core::light::Material;
use cg_core::normals::{face_normal, interpolate_normal};
use cg_core::scene::{Analytic, Prepared};
use cg_core::texture::{Sampler, TexEnv, Texture};

use crate::bvh::Bvh;
use crate::error::TraceError;
use crate::ray::{Ray, gamma, offset_ray_origin};

/// How far short of a light a shadow ray stops, relative to the light's distance, so a light
/// placed on a surface is not shadowed by that surface.
pub const SHADOW_EPSILON: f32 = 1.0e-4;

/// Which surface a ray hit, and where on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Primitive {
    /// An exact sphere ([`Analytic::Sphere`]).
    Sphere,
    /// An exact square in a plane ([`Analytic::Plane`]).
    Plane,
    /// A triangle of the object's prepared mesh.
    Triangle {
        /// The face (F-number) in the prepared mesh.
        face: usize,
        /// Barycentric weights of the face's three corners, in the order of the prepared mesh's
        /// face (`mesh.faces[face]`) — also for a mirrored object, whose corners the tracer
        /// reorders internally: `Σ barycentric[i]·p_world(corner i)` is the hit point.
        barycentric: Vec3,
    },
}

/// Where a ray meets a surface, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The ray parameter: the hit is at `origin + t·direction`.
    pub t: f32,
    /// The hit point.
    pub p: Vec3,
    /// Bound on the absolute error of `p` per coordinate (see [`crate::ray`] and the module
    /// docs): spawned rays start this far off the surface.
    pub p_error: Vec3,
    /// The unit geometric normal on the *outside* (counter-clockwise front) of the surface,
    /// whichever side the ray came from.
    pub geometric_normal: Vec3,
    /// The unit shading normal on the outside: the exact normal of a sphere or plane; under flat
    /// shading the face normal (the lecture's light model) or the provoking vertex's normal
    /// (OpenGL's: GL_FLAT's rule, the face's last corner); the interpolated vertex normals ([`interpolate_normal`])
    /// otherwise.
    pub shading_normal: Vec3,
    /// Where the local light model is evaluated: the hit point `p`, except for a triangle under
    /// flat shading, which is lit once — at its centroid (the lecture's light model) or at its
    /// provoking vertex (OpenGL's), as the rasterizer's flat shading lights it — so the whole
    /// face has one colour. Shadow rays still start at `p`.
    pub lit_at: Vec3,
    /// The texture coordinate, when the surface has them (a plane; a mesh with uvs).
    pub uv: Option<Vec2>,
    /// The interpolated vertex colour, when the mesh has colours (they set k_a and k_d, as
    /// glColor under GL_COLOR_MATERIAL does); under flat shading in OpenGL's light model, the
    /// provoking vertex's colour.
    pub color: Option<Rgb>,
    /// The object hit (index into the scene's objects).
    pub object: usize,
    /// The primitive hit.
    pub primitive: Primitive,
}

impl Hit {
    /// Whether a ray travelling in `direction` meets the front (outside) of the surface here.
    #[must_use]
    pub fn is_front(&self, direction: Vec3) -> bool {
        direction.dot(self.geometric_normal) <= 0.0
    }

    /// A ray leaving the hit point in the unit `direction`, its origin offset off the surface to
    /// the side `direction` leaves on ([`offset_ray_origin`]), for every `t > 0`.
    #[must_use]
    pub fn spawn_ray(&self, direction: Vec3) -> Ray {
        let origin = offset_ray_origin(self.p, self.p_error, self.geometric_normal, direction);
        Ray::new(origin, direction)
    }

    /// A shadow ray towards a light in the unit direction `l` at distance `distance` (∞ for a
    /// directional light): [`Hit::spawn_ray`] ending [`SHADOW_EPSILON`] short of the light.
    #[must_use]
    pub fn spawn_shadow_ray(&self, l: Vec3, distance: f32) -> Ray {
        let mut ray = self.spawn_ray(l);
        ray.t_max =
            if distance.is_finite() { distance * (1.0 - SHADOW_EPSILON) } else { f32::INFINITY };
        ray
    }
}

/// An exact surface placed in the world.
#[derive(Clone, Debug)]
struct Placed {
    shape: Analytic,
    model: DMat4,
    world_to_model: DMat4,
    /// `|A|` and `|T|` of the model matrix, for the error bound.
    abs_linear: [DVec3; 3],
    abs_translation: DVec3,
}

/// One scene object as the tracer sees it.
#[derive(Debug)]
pub(crate) struct Surface<'s> {
    /// The object made ready: its mesh (texture coordinates and colours are read from it), model
    /// matrix and normal transform.
    pub(crate) prepared: Prepared<'s>,
    pub(crate) texture: Option<(&'s Texture, Sampler, TexEnv)>,
    /// k_t = 0: a back-face-culled primary ray passes through its back faces.
    opaque: bool,
    placed: Option<Placed>,
    /// The prepared mesh's faces, corners reordered `[a, c, b]` for a mirrored object so that
    /// every face is counter-clockwise from outside in world space (empty for exact surfaces).
    faces: Vec<[u32; 3]>,
    /// Vertex normals in world space ([`Prepared::world_normal`]).
    normals: Vec<Vec3>,
}

impl Surface<'_> {
    pub(crate) fn material(&self) -> &Material {
        &self.prepared.object.material
    }
}

/// A triangle's owner, its face in the owner's prepared mesh, its outward unit normal, and
/// (flat shading) where it is lit.
#[derive(Clone, Copy, Debug)]
struct TriangleInfo {
    object: u32,
    face: u32,
    n_g: Vec3,
    /// Flat shading: the centroid ([`Flat::Centroid`]) or the provoking vertex
    /// ([`Flat::Provoking`]); zero otherwise.
    lit_at: Vec3,
}

/// Where and how flat shading lights a triangle (exact spheres and planes are lit at every hit
/// point whatever the mode).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Flat {
    /// Not flat: every hit point, with the interpolated vertex normals.
    Off,
    /// The lecture's light model: once, at the centroid, with the face normal
    /// ("面の法線をもとに面の色を決定").
    Centroid,
    /// OpenGL's light model, as glShadeModel(GL_FLAT): once, at the provoking vertex — the last
    /// corner of the face in the prepared mesh's order (each face is one GL_TRIANGLES triangle in
    /// `cg-glref`), whatever a mirror does to the tracer's corner order — with that vertex's own
    /// normal (the face normal where it vanishes) and colour.
    Provoking,
}

/// The corner of a face (in the prepared mesh's order) that provokes under GL_FLAT.
const PROVOKING: usize = 2;

/// Everything a ray can hit.
#[derive(Debug)]
pub(crate) struct World<'s> {
    pub(crate) surfaces: Vec<Surface<'s>>,
    /// Indices of the surfaces intersected exactly.
    exact: Vec<usize>,
    bvh: Bvh,
    triangles: Vec<TriangleInfo>,
    flat: Flat,
}

impl<'s> World<'s> {
    /// The world of `prepared` objects: exact surfaces where `analytic` allows, triangles in one
    /// BVH otherwise, lit under `flat`'s rule. `textures` are the scene's.
    pub(crate) fn build(
        prepared: Vec<Prepared<'s>>,
        textures: &'s [Texture],
        analytic: bool,
        flat: Flat,
    ) -> Result<World<'s>, TraceError> {
        let mut surfaces = Vec::with_capacity(prepared.len());
        let mut exact = Vec::new();
        let mut corners = Vec::new();
        let mut triangles = Vec::new();
        for (index, prep) in prepared.into_iter().enumerate() {
            let object = prep.object;
            let texture = match &object.texture {
                Some(t) => Some((
                    textures.get(t.texture).ok_or_else(|| TraceError::Texture {
                        object: object.name.clone(),
                        index: t.texture,
                    })?,
                    t.sampler,
                    t.env,
                )),
                None => None,
            };
            let model = prep.model.as_dmat4();
            let placed = object.analytic.filter(|_| analytic).and_then(|shape| {
                let world_to_model = model.inverse();
                (model.determinant() != 0.0 && world_to_model.is_finite()).then(|| Placed {
                    shape,
                    model,
                    world_to_model,
                    abs_linear: [
                        model.x_axis.truncate().abs(),
                        model.y_axis.truncate().abs(),
                        model.z_axis.truncate().abs(),
                    ],
                    abs_translation: model.w_axis.truncate().abs(),
                })
            });
            let mut surface = Surface {
                opaque: object.material.kt == Rgb::ZERO,
                texture,
                placed,
                faces: Vec::new(),
                normals: Vec::new(),
                prepared: prep,
            };
            if surface.placed.is_some() {
                exact.push(index);
            } else {
                let prep = &surface.prepared;
                let mesh = &prep.mesh;
                let to_world = |p: Vec3| model.transform_point3(p.as_dvec3()).as_vec3();
                let positions: Vec<Vec3> = mesh.positions.iter().map(|&p| to_world(p)).collect();
                if positions.iter().any(|p| !p.is_finite()) {
                    return Err(TraceError::Geometry { object: object.name.clone() });
                }
                let normals = mesh.normals.as_deref().unwrap_or(&[]);
                let world_normals =
                    normals.iter().map(|&n| prep.world_normal(n).unwrap_or(Vec3::ZERO)).collect();
                // A mirror turns the winding: reorder so every face is counter-clockwise again.
                let faces: Vec<[u32; 3]> = mesh
                    .faces
                    .iter()
                    .map(|&[a, b, c]| if prep.mirrored { [a, c, b] } else { [a, b, c] })
                    .collect();
                for (face, f) in faces.iter().enumerate() {
                    let p = f.map(|i| positions[i as usize]);
                    let Some(n_g) = face_normal(p[0], p[1], p[2]) else { continue };
                    let lit_at = match flat {
                        Flat::Off => Vec3::ZERO,
                        // The rasterizer's centroid: the mean of the corners in world space.
                        Flat::Centroid => (p[0] + p[1] + p[2]) / 3.0,
                        // The mesh's own order: a mirror reorders `f`, not the provoking corner.
                        Flat::Provoking => positions[mesh.faces[face][PROVOKING] as usize],
                    };
                    corners.push(p);
                    triangles.push(TriangleInfo {
                        object: index as u32,
                        face: face as u32,
                        n_g,
                        lit_at,
                    });
                }
                surface.normals = world_normals;
                surface.faces = faces;
            }
            surfaces.push(surface);
        }
        let bvh = Bvh::build(&corners);
        Ok(World { surfaces, exact, bvh, triangles, flat })
    }

    /// Triangles in the BVH.
    pub(crate) fn triangle_count(&self) -> usize {
        self.bvh.len()
    }

    /// The closest hit of `ray`; `visited` counts BVH nodes.
    pub(crate) fn intersect(&self, ray: &Ray, visited: &mut u64) -> Option<Hit> {
        let mut best: Option<(f32, usize, DVec3)> = None;
        for &index in &self.exact {
            let surface = &self.surfaces[index];
            let Some(placed) = surface.placed.as_ref() else { continue };
            let t_max = best.map_or(ray.t_max, |b| b.0);
            let cull = ray.cull_back_faces && surface.opaque;
            if let Some((t, p_model)) = placed.intersect(ray, t_max, cull) {
                best = Some((t, index, p_model));
            }
        }
        let mut clipped = *ray;
        if let Some((t, _, _)) = best {
            clipped.t_max = t;
        }
        let triangle = self.bvh.closest_hit(&clipped, visited, |i, _| {
            let info = &self.triangles[i as usize];
            !(ray.cull_back_faces
                && self.surfaces[info.object as usize].opaque
                && ray.direction.dot(info.n_g) > 0.0)
        });
        let hit = match triangle {
            Some((i, th)) => {
                let info = self.triangles[i as usize];
                let surface = &self.surfaces[info.object as usize];
                let mesh = &surface.prepared.mesh;
                // `corners` and `b` in the tracer's (counter-clockwise) order.
                let corners = surface.faces[info.face as usize];
                let b = th.barycentric;
                let weigh3 = |v: [Vec3; 3]| b.x * v[0] + b.y * v[1] + b.z * v[2];
                // GL_FLAT's provoking vertex, in the prepared mesh's order.
                let provoking = mesh.faces[info.face as usize][PROVOKING] as usize;
                let shading_normal = match self.flat {
                    Flat::Centroid => info.n_g,
                    Flat::Provoking => surface
                        .normals
                        .get(provoking)
                        .copied()
                        .filter(|&n| n != Vec3::ZERO)
                        .unwrap_or(info.n_g),
                    Flat::Off if surface.normals.is_empty() => info.n_g,
                    Flat::Off => interpolate_normal(
                        corners.map(|k| surface.normals[k as usize]),
                        b,
                        info.n_g,
                    ),
                };
                // The integer shift of the first corner (in the mesh's order) under repeat.
                let origin = |uvs: &[Vec2]| {
                    let first = uvs[mesh.faces[info.face as usize][0] as usize];
                    surface.texture.map_or(Vec2::ZERO, |(_, s, _)| s.repeat_origin(first))
                };
                // The weights in the prepared mesh's corner order (see `Primitive::Triangle`).
                let barycentric =
                    if surface.prepared.mirrored { Vec3::new(b.x, b.z, b.y) } else { b };
                Hit {
                    t: th.t,
                    p: th.p,
                    p_error: th.p_error,
                    geometric_normal: info.n_g,
                    shading_normal,
                    lit_at: if self.flat == Flat::Off { th.p } else { info.lit_at },
                    uv: mesh.uvs.as_ref().map(|uvs| {
                        let o = origin(uvs);
                        let [u0, u1, u2] = corners.map(|k| uvs[k as usize] - o);
                        b.x * u0 + b.y * u1 + b.z * u2
                    }),
                    color: mesh.colors.as_ref().map(|colors| match self.flat {
                        Flat::Provoking => colors[provoking],
                        Flat::Off | Flat::Centroid => weigh3(corners.map(|k| colors[k as usize])),
                    }),
                    object: info.object as usize,
                    primitive: Primitive::Triangle { face: info.face as usize, barycentric },
                }
            }
            None => {
                let (t, index, p_model) = best?;
                let surface = &self.surfaces[index];
                surface.placed.as_ref()?.hit(t, index, p_model, &surface.prepared)?
            }
        };
        debug_assert!(
            hit.p.is_finite() && hit.geometric_normal.is_finite() && hit.shading_normal.is_finite(),
            "intersect gave {hit:?}"
        );
        Some(hit)
    }

    /// Whether anything blocks `ray` within `(t_min, t_max]` (a shadow ray).
    pub(crate) fn occluded(&self, ray: &Ray, visited: &mut u64) -> bool {
        self.exact.iter().any(|&index| {
            self.surfaces[index]
                .placed
                .as_ref()
                .is_some_and(|p| p.intersect(ray, ray.t_max, false).is_some())
        }) || self.bvh.any_hit(ray, visited)
    }
}

impl Placed {
    /// The nearest root of the ray with the surface in `(ray.t_min, t_max]` (a back face skipped
    /// when `cull`), as `(t, hit point in model space)`.
    fn intersect(&self, ray: &Ray, t_max: f32, cull: bool) -> Option<(f32, DVec3)> {
        let o = self.world_to_model.transform_point3(ray.origin.as_dvec3());
        let d = self.world_to_model.transform_vector3(ray.direction.as_dvec3());
        let (t_min, t_max) = (f64::from(ray.t_min), f64::from(t_max));
        let accept = |t: f64| t > t_min && t > 0.0 && t <= t_max;
        match self.shape {
            Analytic::Sphere { radius } => {
                let r = f64::from(radius);
                let len = d.length();
                if !(len > 0.0 && len.is_finite()) {
                    return None;
                }
                let dn = d / len;
                // Ray Tracing Gems ch. 7: b = o·d̂, Δ = r² − |o − b·d̂|², c = |o|² − r²;
                // q = −b − sign(b)·√Δ; the roots are q and c/q (in units of |d|).
                let b = o.dot(dn);
                let perp = o - b * dn;
                let disc = r * r - perp.length_squared();
                if disc < 0.0 {
                    return None;
                }
                let c = o.length_squared() - r * r;
                let q = -b - b.signum() * disc.sqrt();
                let (u0, u1) = if q == 0.0 { (0.0, 0.0) } else { (c / q, q) };
                let (u0, u1) = if u0 <= u1 { (u0, u1) } else { (u1, u0) };
                for u in [u0, u1] {
                    let t = u / len;
                    if !accept(t) {
                        continue;
                    }
                    let p = o + u * dn;
                    // Entering from outside is the front face.
                    if cull && dn.dot(p) > 0.0 {
                        continue;
                    }
                    let p = p * (r / p.length());
                    return Some((t as f32, p)).filter(|h| h.0 > 0.0 && h.1.is_finite());
                }
                None
            }
            Analytic::Plane { size } => {
                if d.y == 0.0 {
                    return None;
                }
                let t = -o.y / d.y;
                if !accept(t) || (cull && d.y > 0.0) {
                    return None;
                }
                let half = 0.5 * f64::from(size);
                let p = DVec3::new(o.x + t * d.x, 0.0, o.z + t * d.z);
                (p.x.abs() <= half && p.z.abs() <= half)
                    .then_some((t as f32, p))
                    .filter(|h| h.0 > 0.0)
            }
        }
    }

    /// The hit at model-space point `p_model`, found at `t`, on the surface of object `object`
    /// (made ready as `prepared`).
    fn hit(&self, t: f32, object: usize, p_model: DVec3, prepared: &Prepared<'_>) -> Option<Hit> {
        let p_world = self.model.transform_point3(p_model).as_vec3();
        let a = p_model.abs();
        let bound = self.abs_linear[0] * a.x
            + self.abs_linear[1] * a.y
            + self.abs_linear[2] * a.z
            + self.abs_translation;
        let p_error = gamma(5) * bound.as_vec3();
        let (n_model, uv, primitive) = match self.shape {
            Analytic::Sphere { .. } => (p_model.as_vec3(), None, Primitive::Sphere),
            Analytic::Plane { size } => {
                let s = f64::from(size);
                let uv = Vec2::new(
                    ((p_model.x + 0.5 * s) / s) as f32,
                    ((p_model.z + 0.5 * s) / s) as f32,
                );
                (Vec3::Y, Some(uv), Primitive::Plane)
            }
        };
        let n = prepared.world_normal(n_model)?;
        Some(Hit {
            t,
            p: p_world,
            p_error,
            geometric_normal: n,
            shading_normal: n,
            lit_at: p_world,
            uv,
            color: None,
            object,
            primitive,
        })
    }
}
