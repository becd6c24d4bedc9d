//! Lighting in spans of sixteen (issue 18): the scene's own light model ([`crate::SceneLighting`])
//! evaluated for sixteen points at once, in structure-of-arrays form, so the compiler vectorises
//! it — Phong's pixels and Gouraud's vertices.
//!
//! **The same bits.** Every lane computes what [`cg_core::light::shade_with_visibility_counted`]
//! computes for its point, operation for operation, in the same precision and order: the normal
//! interpolated and renormalised in f64 as [`cg_core::normals::interpolate_normal`] does, V and L
//! normalised in f64 as [`LightModel::view_vector`] and [`Light::direction_from`] do, the terms
//! summed in f32 in the light model's order. No fused multiply-add is introduced (Rust never
//! contracts `a * b + c`), so the image is bit for bit the one the point-by-point path draws, on
//! every CPU (`tests/spans.rs` compares the two on every kind of light and material). What it
//! saves is the work around the arithmetic: no light list expanded and no material copied per
//! point, the scene's constant terms made once per frame, and every term the scene does not use
//! skipped for the whole span.
//!
//! **Why sixteen.** Each lane's f64 normalisations are a chain of a square root and a division
//! whose latency, not their count, bounds a span: sixteen lanes give the core two independent
//! chains of AVX2 vectors to overlap. Measured side by side on the course scene in Phong (one
//! thread, the whole frame): spans of sixteen took 0.75 of the time of spans of eight; spans of
//! thirty-two were no faster than sixteen (docs/performance.md §2).
//!
//! **A triangle with one normal** (a face normal, every triangle of a flat object) gives every
//! fragment the same normal: [`queue::certified`] proves, once per triangle, that the
//! per-fragment f64 interpolation and renormalisation would round to that normal's bits, and the
//! span then skips that work.
//!
//! The light model's counts ([`LightCounts`]) are the ones the point-by-point path makes. The
//! queue of fragments waiting for their span, [`PhongSpan`], is `span/queue.rs`.

// Lane loops index several arrays by the lane, the structure-of-arrays idiom the vectoriser
// reads best.
#![allow(clippy::needless_range_loop)]

use cg_core::Rgb;
use cg_core::glam::{DVec3, Vec3};
use cg_core::light::{
    Light, LightCounts, LightKind, LightModel, Material, Specular, attenuation, spot_factor,
};
use cg_core::math::{DIRECT_UNIT_MIN, try_normalize, try_unit_and_length_f64};
use multiversion::multiversion;

mod queue;
#[cfg(target_arch = "x86_64")]
mod v3;
#[cfg(test)]
use queue::certified;
pub(crate) use queue::{PhongSpan, Texturing, Triangle};

/// Points lit at once.
pub(crate) const LANES: usize = 16;

/// `2⁻²⁶`: [`cg_core::normals::interpolate_normal`]'s cancellation threshold (a sum shorter than
/// this fraction of `Σ |wᵢ|·|Nᵢ|` is rounding noise, and the face normal is used).
const CANCEL_FRACTION: f64 = 1.0 / (1u64 << 26) as f64;

/// One light as the spans use it: a point light of [`Light::point_lights`] (an area light is
/// already its grid of samples).
struct SpanLight {
    light: Light,
    /// Where it is, in f64 (point and spot lights); `None` for a directional light.
    position: Option<DVec3>,
    /// A directional light's `(L, d)`, the same for every point ([`Light::direction_from`]).
    directional: Option<(Vec3, f32)>,
    /// [`Light::needs_attenuation`].
    attenuates: bool,
}

impl SpanLight {
    /// The unit vector L towards the light from each point `p`, whether it exists, and the
    /// distances where `d` asks for them (a directional light: its own, the same everywhere).
    #[inline(always)]
    fn to_light(&self, p: &V3, l: &mut V3, d: Option<&mut Lanes>, valid: &mut [bool; LANES]) {
        match (self.directional, self.position) {
            (Some((dl, dd)), _) => {
                *l = V3::splat(dl);
                if let Some(d) = d {
                    *d = [dd; LANES];
                }
                *valid = [!dl.is_nan(); LANES];
            }
            (_, Some(position)) => directions(position, p, l, d, valid),
            (None, None) => *valid = [false; LANES],
        }
    }
}

/// The scene's lights and light model, made ready once per frame.
pub(crate) struct SpanLights {
    lecture: bool,
    specular: Specular,
    /// The ambient intensity before `k_a`: the lecture's `Ia + Σ Iₐ` (every light's, once), or
    /// OpenGL's global `Ia` (each light's own is attenuated and spot-scaled per point).
    ambient: Rgb,
    lights: Vec<SpanLight>,
    local_viewer: bool,
    eye: DVec3,
    backward: Vec3,
    /// No light attenuates and none is a spot light (nor an area light: its samples are spot
    /// lights): every light's scale is 1 at every point
    /// ([`light_lanes_plain`] when the material has no specular term either).
    plain: bool,
}

impl SpanLights {
    /// The lights of a scene lit by `model` with the global ambient `global_ambient`, seen from
    /// `eye` (a local viewer) or along `backward` (the infinite viewer's V).
    pub(crate) fn new(
        model: LightModel,
        global_ambient: Rgb,
        lights: &[Light],
        eye: Vec3,
        backward: Vec3,
    ) -> SpanLights {
        let (lecture, specular) = match model {
            LightModel::Lecture { specular, .. } => (true, specular),
            LightModel::OpenGl { .. } => (false, Specular::Blinn),
        };
        let ambient = if lecture {
            lights.iter().fold(global_ambient, |sum, light| sum + light.ambient)
        } else {
            global_ambient
        };
        let lights: Vec<SpanLight> = lights
            .iter()
            .flat_map(Light::point_lights)
            .map(|light| SpanLight {
                position: match light.kind {
                    LightKind::Point { position } | LightKind::Spot { position, .. } => {
                        Some(position.as_dvec3())
                    }
                    // `point_lights` gives no area light; a directional one has no position.
                    _ => None,
                },
                directional: match light.kind {
                    LightKind::Directional { .. } => Some(
                        light.direction_from(Vec3::ZERO).map_or((Vec3::NAN, 0.0), |(l, d)| (l, d)),
                    ),
                    _ => None,
                },
                attenuates: light.needs_attenuation(),
                light,
            })
            .collect();
        let plain =
            lights.iter().all(|l| !l.attenuates && !matches!(l.light.kind, LightKind::Spot { .. }));
        SpanLights {
            plain,
            lecture,
            specular,
            ambient,
            lights,
            local_viewer: model.local_viewer(),
            eye: eye.as_dvec3(),
            backward,
        }
    }
}

/// One `f32` per lane.
pub(crate) type Lanes = [f32; LANES];
/// One `f64` per lane.
type Lanes64 = [f64; LANES];

/// `N` 3-vectors, structure of arrays: `x[i], y[i], z[i]` is lane `i`'s vector.
#[derive(Clone, Copy, Debug)]
pub(crate) struct V3N<const N: usize> {
    pub(crate) x: [f32; N],
    pub(crate) y: [f32; N],
    pub(crate) z: [f32; N],
}

/// [`LANES`] 3-vectors, the spans' points.
pub(crate) type V3 = V3N<LANES>;

impl<const N: usize> Default for V3N<N> {
    #[inline(always)]
    fn default() -> Self {
        V3N { x: [0.0; N], y: [0.0; N], z: [0.0; N] }
    }
}

impl<const N: usize> V3N<N> {
    #[inline(always)]
    pub(crate) fn set(&mut self, i: usize, v: Vec3) {
        (self.x[i], self.y[i], self.z[i]) = (v.x, v.y, v.z);
    }

    #[inline(always)]
    pub(crate) fn get(&self, i: usize) -> Vec3 {
        Vec3::new(self.x[i], self.y[i], self.z[i])
    }

    #[inline(always)]
    pub(crate) fn splat(v: Vec3) -> Self {
        V3N { x: [v.x; N], y: [v.y; N], z: [v.z; N] }
    }
}

/// [`LANES`] f64 3-vectors, structure of arrays.
#[derive(Clone, Copy, Debug, Default)]
struct D3 {
    x: Lanes64,
    y: Lanes64,
    z: Lanes64,
}

/// [`LANES`] points (fewer in the last span) to light: where, with which unit normal, and the colour
/// material where the mesh has per-vertex colours.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Points {
    pub(crate) len: usize,
    pub(crate) p: V3,
    pub(crate) n: V3,
    /// k_a = k_d per point (glColor under GL_COLOR_MATERIAL); read only when colored.
    pub(crate) color: V3,
}

/// `|v|` as glam's `DVec3::length` computes it: `√((x·x + y·y) + z·z)`.
#[inline(always)]
fn length64(x: f64, y: f64, z: f64) -> f64 {
    (x * x + y * y + z * z).sqrt()
}

/// [`cg_core::math::try_unit_and_length_f64`] lane by lane, with its arithmetic (`v · (1/√(v·v))`):
/// the unit vectors, the lengths, and whether each exists (`false` for a zero or non-finite
/// vector, whose lane then holds garbage).
#[inline(always)]
fn units64(v: &D3, unit: &mut D3, length: &mut Lanes64, valid: &mut [bool; LANES]) {
    for i in 0..LANES {
        let (x, y, z) = (v.x[i], v.y[i], v.z[i]);
        let squared = x * x + y * y + z * z;
        valid[i] = (DIRECT_UNIT_MIN..f64::INFINITY).contains(&squared);
        let l = squared.sqrt();
        let inverse = 1.0 / l;
        (unit.x[i], unit.y[i], unit.z[i]) = (x * inverse, y * inverse, z * inverse);
        length[i] = l;
    }
    if !valid.iter().fold(true, |all, &v| all & v) {
        units64_rest(v, unit, length, valid);
    }
}

/// The lanes [`units64`] left: zero or non-finite vectors (`None`), or ones too short or too long
/// for its shortcut, which no span's vector is (see [`try_unit_and_length_f64`]).
#[cold]
#[inline(never)]
fn units64_rest(v: &D3, unit: &mut D3, length: &mut Lanes64, valid: &mut [bool; LANES]) {
    for i in 0..LANES {
        if !valid[i]
            && let Some((u, l)) = try_unit_and_length_f64(DVec3::new(v.x[i], v.y[i], v.z[i]))
        {
            (unit.x[i], unit.y[i], unit.z[i], length[i], valid[i]) = (u.x, u.y, u.z, l, true);
        }
    }
}

/// [`cg_core::normals::interpolate_normal`] for each lane, with its arithmetic: `b` the
/// perspective-correct barycentrics, `normals` the corners' normals and `lengths` theirs. Gives
/// whether each lane's normal is usable; where it is not (the corners' normals cancel, NUMERICS
/// row 18), the caller puts the face normal in its place.
#[inline(always)]
fn interpolate_normals(
    b: &V3,
    normals: &[V3; 3],
    lengths: &[Lanes64; 3],
    out: &mut V3,
) -> [bool; LANES] {
    let mut sum = D3::default();
    let mut magnitude = [0.0f64; LANES];
    for i in 0..LANES {
        let w = [f64::from(b.x[i]), f64::from(b.y[i]), f64::from(b.z[i])];
        let n = normals.map(|n| [f64::from(n.x[i]), f64::from(n.y[i]), f64::from(n.z[i])]);
        sum.x[i] = n[0][0] * w[0] + n[1][0] * w[1] + n[2][0] * w[2];
        sum.y[i] = n[0][1] * w[0] + n[1][1] * w[1] + n[2][1] * w[2];
        sum.z[i] = n[0][2] * w[0] + n[1][2] * w[1] + n[2][2] * w[2];
        magnitude[i] =
            w[0].abs() * lengths[0][i] + w[1].abs() * lengths[1][i] + w[2].abs() * lengths[2][i];
    }
    let mut unit = D3::default();
    let mut length = [0.0f64; LANES];
    let mut keep = [false; LANES];
    units64(&sum, &mut unit, &mut length, &mut keep);
    for i in 0..LANES {
        keep[i] &= length[i] > CANCEL_FRACTION * magnitude[i];
        out.x[i] = unit.x[i] as f32;
        out.y[i] = unit.y[i] as f32;
        out.z[i] = unit.z[i] as f32;
    }
    keep
}

/// Unit vectors from each point `p` to `to` in f64, as [`Light::direction_from`] and
/// [`LightModel::view_vector`] compute them, whether each exists, and the distances (f32) where
/// `d` asks for them (only attenuation reads them: a square root per point saved otherwise).
#[inline(always)]
fn directions(to: DVec3, p: &V3, l: &mut V3, d: Option<&mut Lanes>, valid: &mut [bool; LANES]) {
    let mut v = D3::default();
    for i in 0..LANES {
        v.x[i] = to.x - f64::from(p.x[i]);
        v.y[i] = to.y - f64::from(p.y[i]);
        v.z[i] = to.z - f64::from(p.z[i]);
    }
    let mut unit = D3::default();
    let mut length = [0.0f64; LANES];
    units64(&v, &mut unit, &mut length, valid);
    for i in 0..LANES {
        l.x[i] = unit.x[i] as f32;
        l.y[i] = unit.y[i] as f32;
        l.z[i] = unit.z[i] as f32;
    }
    if let Some(d) = d {
        for i in 0..LANES {
            d[i] = length[i] as f32;
        }
    }
}

/// `a·b` lane by lane, as glam's `Vec3::dot`: `(ax·bx + ay·by) + az·bz`.
#[inline(always)]
fn dot(a: &V3, b: &V3) -> Lanes {
    std::array::from_fn(|i| a.x[i] * b.x[i] + a.y[i] * b.y[i] + a.z[i] * b.z[i])
}

/// `max(x, 0)`, NaN taken as 0 (the light model's `positive_part`).
#[inline(always)]
fn positive_part(x: f32) -> f32 {
    if x > 0.0 { x } else { 0.0 }
}

/// The light model's `specular_power`.
#[inline(always)]
fn specular_power(cos: f32, shininess: f32) -> f32 {
    if cos > 0.0 { cos.min(1.0).powf(positive_part(shininess)) } else { 0.0 }
}

/// `sum += s · (c ⊙ k)` per channel, as the light model adds a term (`scale * (I * k * f)`
/// with `f` folded into `c` by the caller where it has one), skipped where `s = 0`.
#[inline(always)]
fn add_term(sum: &mut V3, s: &Lanes, c: Vec3, k: &V3, f: &Lanes) {
    for i in 0..LANES {
        let on = s[i] != 0.0;
        let (x, y, z) = (
            sum.x[i] + s[i] * (c.x * k.x[i] * f[i]),
            sum.y[i] + s[i] * (c.y * k.y[i] * f[i]),
            sum.z[i] + s[i] * (c.z * k.z[i] * f[i]),
        );
        sum.x[i] = if on { x } else { sum.x[i] };
        sum.y[i] = if on { y } else { sum.y[i] };
        sum.z[i] = if on { z } else { sum.z[i] };
    }
}

/// The light model at each point of `points` with `material` (k_a = k_d = the point's colour when
/// `colored`): the unclamped colour into `out`, the work into `counts`. Lane `i` gives
/// `shade(…).total()` of its point, bit for bit.
#[multiversion(targets("x86_64+avx2+fma"))]
pub(crate) fn light<'a>(
    stage: &Stage<'a>,
    points: &Points,
    out: &mut V3,
    counts: &mut LightCounts,
) {
    light_lanes(stage, points, out, counts);
}

/// [`light`]'s body, inlined where it is called (so that the fragment stage and the light model
/// are compiled as one, see [`shade_fragments`]).
#[inline(always)]
fn light_lanes(stage: &Stage<'_>, points: &Points, out: &mut V3, counts: &mut LightCounts) {
    if stage.lights.plain && stage.material.ks == Rgb::ZERO {
        light_lanes_plain(stage, points, out, counts);
        return;
    }
    let Stage { lights, material, .. } = *stage;
    let len = points.len;
    let lanes = len as u64;
    counts.evaluations += lanes;
    let (ka, kd) = reflectances(stage, points);
    let n = &points.n;
    // V (LightModel::view_vector): towards the eye, or the camera's backward axis.
    let mut v = V3::splat(lights.backward);
    if lights.local_viewer {
        let mut unit = V3::default();
        let mut valid = [false; LANES];
        directions(lights.eye, &points.p, &mut unit, None, &mut valid);
        select(&valid, &unit, &mut v);
    }

    let ones = [1.0f32; LANES];
    let mut ambient = times(lights.ambient, &ka);
    let mut diffuse = V3::default();
    let mut specular = V3::default();
    let with_specular = material.ks != Rgb::ZERO;
    let mut l = V3::default();
    let mut d = [0.0f32; LANES];
    let mut valid = [true; LANES];
    for span_light in &lights.lights {
        let light = &span_light.light;
        counts.lights += lanes;
        // (L, d) per point; L = N and d = 0 where the light has no direction from the point.
        let distances = span_light.attenuates.then_some(&mut d);
        span_light.to_light(&points.p, &mut l, distances, &mut valid);
        // L = N, d = 0 where there is no direction.
        if !valid.iter().all(|&v| v) {
            let mut fallback = *n;
            select(&valid, &l, &mut fallback);
            l = fallback;
            for i in 0..LANES {
                d[i] = if valid[i] { d[i] } else { 0.0 };
            }
        }
        let mut scale = [1.0f32; LANES];
        if span_light.attenuates {
            counts.attenuations += lanes;
            for i in 0..LANES {
                scale[i] = attenuation(light.attenuation, d[i]);
            }
        }
        if let LightKind::Spot { direction, cutoff_deg, exponent, inner_deg, .. } = light.kind {
            counts.spot_factors += lanes;
            let inner = inner_deg.filter(|_| lights.lecture);
            for i in 0..len {
                scale[i] *= spot_factor(l.get(i), direction, cutoff_deg, exponent, inner);
            }
        }
        let lit = scale[..len].iter().filter(|&&s| s != 0.0).count() as u64;
        counts.visibility_queries += lit;
        counts.diffuse += lit;
        if !lights.lecture {
            add_term(&mut ambient, &scale, light.ambient, &ka, &ones);
        }
        let nl = dot(n, &l);
        add_term(&mut diffuse, &scale, light.diffuse, &kd, &nl.map(positive_part));
        if with_specular {
            counts.specular += lit;
            let (ks, shininess) = (V3::splat(material.ks), material.shininess);
            let mut power = [0.0f32; LANES];
            match lights.specular {
                Specular::Phong => {
                    // R = reflect(−L, N) = −L − 2(−L·N)N.
                    for i in 0..len {
                        if nl[i] > 0.0 {
                            let (li, ni) = (l.get(i), n.get(i));
                            let r = -li - 2.0 * (-li).dot(ni) * ni;
                            power[i] = specular_power(r.dot(v.get(i)), shininess);
                        }
                    }
                }
                Specular::Blinn => {
                    for i in 0..len {
                        if nl[i] > 0.0
                            && let Some(h) = try_normalize(l.get(i) + v.get(i))
                        {
                            power[i] = specular_power(n.get(i).dot(h), shininess);
                        }
                    }
                }
            }
            add_term(&mut specular, &scale, light.specular, &ks, &power);
        }
    }
    let e = material.emission;
    for i in 0..LANES {
        out.x[i] = e.x + ambient.x[i] + diffuse.x[i] + specular.x[i];
        out.y[i] = e.y + ambient.y[i] + diffuse.y[i] + specular.y[i];
        out.z[i] = e.z + ambient.z[i] + diffuse.z[i] + specular.z[i];
    }
}

/// k_a and k_d at each point: the point's colour where the points have their own
/// (`stage.colored`), else the material's.
#[inline(always)]
fn reflectances(stage: &Stage<'_>, points: &Points) -> (V3, V3) {
    if stage.colored {
        (points.color, points.color)
    } else {
        (V3::splat(stage.material.ka), V3::splat(stage.material.kd))
    }
}

/// `c ⊙ k` lane by lane (the ambient term before any light's).
#[inline(always)]
fn times(c: Rgb, k: &V3) -> V3 {
    let mut out = V3::default();
    for i in 0..LANES {
        out.x[i] = c.x * k.x[i];
        out.y[i] = c.y * k.y[i];
        out.z[i] = c.z * k.z[i];
    }
    out
}

/// [`light_lanes`] where every light's scale is 1 and there is no specular term
/// ([`SpanLights::plain`], `k_s = 0`): the same arithmetic lane by lane, each light's terms in
/// one pass over the lanes (no scale, no view vector, no specular sum to keep).
#[inline(always)]
fn light_lanes_plain(stage: &Stage<'_>, points: &Points, out: &mut V3, counts: &mut LightCounts) {
    let Stage { lights, material, .. } = *stage;
    let lanes = points.len as u64;
    counts.evaluations += lanes;
    let (ka, kd) = reflectances(stage, points);
    let n = &points.n;
    let mut ambient = times(lights.ambient, &ka);
    let mut diffuse = V3::default();
    let mut l = V3::default();
    let mut valid = [true; LANES];
    for span_light in &lights.lights {
        let light = &span_light.light;
        // Every point is lit (scale 1): each counts once.
        counts.lights += lanes;
        counts.visibility_queries += lanes;
        counts.diffuse += lanes;
        span_light.to_light(&points.p, &mut l, None, &mut valid);
        let (ca, cd, opengl) = (light.ambient, light.diffuse, !lights.lecture);
        for i in 0..LANES {
            // L = N where the light has no direction from the point.
            let (lx, ly, lz) =
                if valid[i] { (l.x[i], l.y[i], l.z[i]) } else { (n.x[i], n.y[i], n.z[i]) };
            if opengl {
                ambient.x[i] += ca.x * ka.x[i];
                ambient.y[i] += ca.y * ka.y[i];
                ambient.z[i] += ca.z * ka.z[i];
            }
            // `dot`, then `add_term` with the scale 1.
            let f = positive_part(n.x[i] * lx + n.y[i] * ly + n.z[i] * lz);
            diffuse.x[i] += cd.x * kd.x[i] * f;
            diffuse.y[i] += cd.y * kd.y[i] * f;
            diffuse.z[i] += cd.z * kd.z[i] * f;
        }
    }
    // `+ 0.0`: the specular sum, as `light_lanes` adds it (it turns a −0 into +0).
    let e = material.emission;
    for i in 0..LANES {
        out.x[i] = e.x + ambient.x[i] + diffuse.x[i] + 0.0;
        out.y[i] = e.y + ambient.y[i] + diffuse.y[i] + 0.0;
        out.z[i] = e.z + ambient.z[i] + diffuse.z[i] + 0.0;
    }
}

/// `into[i] = from[i]` where `take[i]`, per lane.
#[inline(always)]
fn select(take: &[bool; LANES], from: &V3, into: &mut V3) {
    for i in 0..LANES {
        into.x[i] = if take[i] { from.x[i] } else { into.x[i] };
        into.y[i] = if take[i] { from.y[i] } else { into.y[i] };
        into.z[i] = if take[i] { from.z[i] } else { into.z[i] };
    }
}

/// The lanes' triangle attributes, gathered into structure-of-arrays form.
#[derive(Clone, Copy, Default)]
struct Gathered {
    inv_w: [Lanes; 3],
    p: [V3; 3],
    color: [V3; 3],
    /// Each lane's triangle's [`Triangle::unit`], where it has one.
    unit: V3,
    certified: [bool; LANES],
}

/// What lights a span: the scene's lights, the object's material, and whether the points have
/// their own colours.
#[derive(Clone, Copy)]
pub(crate) struct Stage<'a> {
    pub(crate) lights: &'a SpanLights,
    pub(crate) material: &'a Material,
    pub(crate) colored: bool,
}

/// The fragment stage of a span and its light model, compiled as one (the points stay where the
/// light model reads them at the width they were written): [`fragments`] (with the corners'
/// normals from `normals`), the face normal `face(lane)` where a lane's normals cancel, then
/// [`light`] into `lit`, clamped to `[0, 1]` as [`saturate`] clamps. Where `aos` is given for a
/// whole span and the kernel in registers (`span/v3.rs`) lit it, the colours are in `aos`
/// instead, interleaved, and this gives `true`.
#[multiversion(targets("x86_64+avx2+fma"))]
#[allow(clippy::too_many_arguments)]
fn shade_fragments<'a>(
    stage: &Stage<'a>,
    screen: &V3,
    g: &Gathered,
    b: &mut V3,
    points: &mut Points,
    face: &mut dyn FnMut(usize) -> Vec3,
    normals: &mut dyn FnMut(&mut [V3; 3]),
    lit: &mut V3,
    #[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))] aos: Option<
        &mut [Rgb; LANES],
    >,
    counts: &mut LightCounts,
) -> bool {
    // The course scene's case (certified normals, plain lights, no specular term) in registers.
    #[cfg(target_arch = "x86_64")]
    if stage.lights.plain
        && stage.material.ks == Rgb::ZERO
        && let Some(simd) = pulp::x86::V3::try_new()
    {
        let aos = aos.filter(|_| points.len == LANES);
        let interleaved = aos.is_some();
        let len = points.len;
        let plain = v3::Plain { stage, screen, g, len, b, lit, aos, counts };
        if plain.shade(simd) {
            return interleaved;
        }
    }
    let keep = fragments(screen, g, stage.colored, b, points, normals);
    for i in 0..points.len {
        if !keep[i] {
            points.n.set(i, face(i));
        }
    }
    light_lanes(stage, points, lit, counts);
    // Clamped as `saturate` clamps, all lanes at once.
    for channel in [&mut lit.x, &mut lit.y, &mut lit.z] {
        channel.iter_mut().for_each(|x| *x = clamp_channel(*x));
    }
    false
}

/// The fragment stage before lighting, for each lane: perspective-correct barycentrics `b` from
/// the screen-space `screen`, then the position, the colour (when `colored`) and the normal
/// interpolated into `points`. Gives which normals are usable ([`interpolate_normals`]).
/// `normals(n)` puts each lane's corners' normals into `n`, where they are needed (not for a
/// span of certified triangles: gathering them is a good part of a mixed span's cost).
#[inline(always)]
fn fragments(
    screen: &V3,
    g: &Gathered,
    colored: bool,
    b: &mut V3,
    points: &mut Points,
    normals: &mut dyn FnMut(&mut [V3; 3]),
) -> [bool; LANES] {
    perspective(screen, &g.inv_w, b);
    interpolate(b, &g.p, &mut points.p);
    if colored {
        interpolate(b, &g.color, &mut points.color);
    }
    // A span whose every lane is a certified triangle's, with weights ≥ 0 and not all zero (as
    // the rasterizer's always are), takes the triangles' normals: the same bits, no f64 work.
    // Lane by lane without branches (`&`, `|` on bools), the lanes past `len` counting as such.
    let mut constant = true;
    for i in 0..LANES {
        let (x, y, z) = (b.x[i], b.y[i], b.z[i]);
        let weights = (x >= 0.0) & (y >= 0.0) & (z >= 0.0) & ((x > 0.0) | (y > 0.0) | (z > 0.0));
        constant &= (g.certified[i] & weights) | (i >= points.len);
    }
    if constant {
        points.n = g.unit;
        return [true; LANES];
    }
    // `|nᵢ|` in f64 (`DVec3::length`), here rather than per triangle: a dense mesh's triangle
    // has one or two fragments, and sixteen lanes take the square roots four at a time.
    let mut corners = [V3::default(); 3];
    normals(&mut corners);
    let lengths: [Lanes64; 3] = std::array::from_fn(|k| {
        let n = &corners[k];
        std::array::from_fn(|i| length64(f64::from(n.x[i]), f64::from(n.y[i]), f64::from(n.z[i])))
    });
    interpolate_normals(b, &corners, &lengths, &mut points.n)
}

/// Perspective-correct barycentrics from screen-space ones, as the fragment stage computes them:
/// each corner weighted by its 1/w, the weights divided by their sum (the screen-space ones
/// where that sum is not positive and finite).
#[inline(always)]
pub(crate) fn perspective<const N: usize>(
    screen: &V3N<N>,
    inv_w: &[[f32; N]; 3],
    out: &mut V3N<N>,
) {
    for i in 0..N {
        let (x, y, z) =
            (screen.x[i] * inv_w[0][i], screen.y[i] * inv_w[1][i], screen.z[i] * inv_w[2][i]);
        let sum = x + y + z;
        let ok = sum > 0.0 && sum.is_finite();
        out.x[i] = if ok { x / sum } else { screen.x[i] };
        out.y[i] = if ok { y / sum } else { screen.y[i] };
        out.z[i] = if ok { z / sum } else { screen.z[i] };
    }
}

/// `b.x·a₀ + b.y·a₁ + b.z·a₂` per lane and channel, in glam's order.
#[inline(always)]
pub(crate) fn interpolate<const N: usize>(b: &V3N<N>, a: &[V3N<N>; 3], out: &mut V3N<N>) {
    for i in 0..N {
        out.x[i] = b.x[i] * a[0].x[i] + b.y[i] * a[1].x[i] + b.z[i] * a[2].x[i];
        out.y[i] = b.x[i] * a[0].y[i] + b.y[i] * a[1].y[i] + b.z[i] * a[2].y[i];
        out.z[i] = b.x[i] * a[0].z[i] + b.y[i] * a[1].z[i] + b.z[i] * a[2].z[i];
    }
}

/// A colour clamped to `[0, 1]` per channel, NaN taken as 0 (OpenGL's clamp of the lit colour).
#[inline]
pub(crate) fn saturate(c: Rgb) -> Rgb {
    Rgb::new(clamp_channel(c.x), clamp_channel(c.y), clamp_channel(c.z))
}

/// One channel clamped to `[0, 1]`, NaN taken as 0 ([`saturate`]).
#[inline(always)]
fn clamp_channel(x: f32) -> f32 {
    if x > 0.0 { x.min(1.0) } else { 0.0 }
}

#[cfg(test)]
#[path = "span_tests.rs"]
pub(crate) mod tests;
