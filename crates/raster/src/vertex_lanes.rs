//! The vertex stage sixteen vertices at a time (issue 18): model → world → view → clip, the
//! normal by the cofactor normal matrix, and each vertex's window position and outcodes, in
//! structure-of-arrays form so the compiler vectorises the matrix products and the divisions
//! (a copy compiled for AVX2 is chosen at run time).
//!
//! **The same bits.** Each lane does what the point-by-point functions do, operation for
//! operation in f32 and in their order: glam's `Mat4 * Vec4` (`((X·x + Y·y) + Z·z) + W·w` per
//! row), its `Mat3 * Vec3`, [`cg_core::math::try_normalize`] (divide by the largest magnitude,
//! then by the length), the viewport transform and the snapping to 1/256 pixel. No fused
//! multiply-add is introduced, so the result does not depend on the CPU.

// Lane loops index several arrays by the lane, the structure-of-arrays idiom the vectoriser
// reads best.
#![allow(clippy::needless_range_loop)]

use cg_core::Rgb;
use cg_core::glam::{Mat3, Mat4, Vec2, Vec3, Vec4};
use multiversion::multiversion;

use crate::span::{LANES, Lanes};

/// What the vertex stage needs of the frame and the object: the matrices, the window size in
/// pixels, whether the object's transform mirrors.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Transforms {
    pub(crate) model: Mat4,
    pub(crate) normal: Mat3,
    pub(crate) mirrored: bool,
    pub(crate) view: Mat4,
    pub(crate) projection: Mat4,
    pub(crate) width: f32,
    pub(crate) height: f32,
}

/// [`LANES`] vertices' results, structure of arrays.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Out {
    pub(crate) p_world: [Lanes; 3],
    pub(crate) n_world: [Lanes; 3],
    pub(crate) p_clip: [Lanes; 4],
    /// The window position snapped to 1/256 pixel, where the viewport transform exists.
    pub(crate) x: [i32; LANES],
    pub(crate) y: [i32; LANES],
    pub(crate) z: Lanes,
    pub(crate) inv_w: Lanes,
    pub(crate) in_window: [bool; LANES],
}

/// `M·(x, y, z, w)` for each lane, as glam's SSE `Mat4::mul_vec4`: per row
/// `((X·x + Y·y) + Z·z) + W·w`.
#[inline(always)]
fn mul4(m: &Mat4, v: [&Lanes; 4], out: &mut [Lanes; 4]) {
    let cols: [Vec4; 4] = [m.x_axis, m.y_axis, m.z_axis, m.w_axis];
    for r in 0..4 {
        let c = cols.map(|c| c[r]);
        for i in 0..LANES {
            out[r][i] = c[0] * v[0][i] + c[1] * v[1][i] + c[2] * v[2][i] + c[3] * v[3][i];
        }
    }
}

/// `M·(x, y, z)` for each lane, as glam's `Mat3::mul_vec3`.
#[inline(always)]
fn mul3(m: &Mat3, v: &[Lanes; 3], out: &mut [Lanes; 3]) {
    let cols: [Vec3; 3] = [m.x_axis, m.y_axis, m.z_axis];
    for r in 0..3 {
        let c = cols.map(|c| c[r]);
        for i in 0..LANES {
            out[r][i] = c[0] * v[0][i] + c[1] * v[1][i] + c[2] * v[2][i];
        }
    }
}

/// A window coordinate in fixed point, rounded to the nearest 1/256 pixel, half away from zero:
/// the pipeline's `snap` (`r as i32`, then ±1 by the fraction left) for every position it is used
/// for (inside the guard band, `|r| < 2³⁰`), computed in f32 so it vectorises. `r.trunc()` is
/// the integer the cast gives, the fraction `r − trunc(r)` is exact, and adding ±1 is exact
/// below 2²⁴ (above it the fraction is 0); finite positions beyond the band, whose records are
/// never used, saturate instead of overflowing.
#[inline(always)]
fn snap(v: f32) -> i32 {
    let r = v * 256.0;
    let whole = r.trunc();
    let fraction = r - whole;
    let up = if fraction >= 0.5 { 1.0 } else { 0.0 };
    let down = if fraction <= -0.5 { 1.0 } else { 0.0 };
    (whole + up - down) as i32
}

/// The vertex stage for the [`LANES`] vertices `p` (model space) with normals `n` (zero where a
/// vertex has none): world position, unit world normal (zero where it has none, flipped back
/// for a mirrored object), clip position, window position.
#[multiversion(targets("x86_64+avx2+fma"))]
pub(crate) fn transform(t: &Transforms, p: &[Lanes; 3], n: &[Lanes; 3], out: &mut Out) {
    let one = [1.0f32; LANES];
    let mut world = [[0.0f32; LANES]; 4];
    mul4(&t.model, [&p[0], &p[1], &p[2], &one], &mut world);
    let mut view = [[0.0f32; LANES]; 4];
    mul4(&t.view, [&world[0], &world[1], &world[2], &one], &mut view);
    mul4(&t.projection, [&view[0], &view[1], &view[2], &one], &mut out.p_clip);
    out.p_world = [world[0], world[1], world[2]];

    // Prepared::world_normal: try_normalize(N·n), negated for a mirror; zero where it fails.
    let mut m = [[0.0f32; LANES]; 3];
    mul3(&t.normal, n, &mut m);
    let sign = if t.mirrored { -1.0f32 } else { 1.0 };
    for i in 0..LANES {
        let (x, y, z) = (m[0][i], m[1][i], m[2][i]);
        let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
        let big = if ax > ay { ax } else { ay };
        let big = if big > az { big } else { az };
        let valid = x.is_finite() && y.is_finite() && z.is_finite() && big != 0.0;
        let (ux, uy, uz) = (x / big, y / big, z / big);
        let length = (ux * ux + uy * uy + uz * uz).sqrt();
        let (nx, ny, nz) = (ux / length, uy / length, uz / length);
        out.n_world[0][i] = if valid { nx * sign } else { 0.0 };
        out.n_world[1][i] = if valid { ny * sign } else { 0.0 };
        out.n_world[2][i] = if valid { nz * sign } else { 0.0 };
    }

    // The viewport transform (the pipeline's `viewport`): never a division by w ≤ 0.
    let (p_clip, mut sx, mut sy) = (&out.p_clip, [0.0f32; LANES], [0.0f32; LANES]);
    for i in 0..LANES {
        let (x, y, z, w) = (p_clip[0][i], p_clip[1][i], p_clip[2][i], p_clip[3][i]);
        let divisible = !(w <= 0.0 || w.is_nan());
        let inv_w = 1.0 / w;
        let (nx, ny, nz) = (x * inv_w, y * inv_w, z * inv_w);
        sx[i] = (nx + 1.0) * 0.5 * t.width;
        sy[i] = (1.0 - ny) * 0.5 * t.height;
        let sz = nz.clamp(0.0, 1.0);
        out.in_window[i] = divisible
            && sx[i].is_finite()
            && sy[i].is_finite()
            && sz.is_finite()
            && inv_w.is_finite();
        out.z[i] = sz;
        out.inv_w[i] = inv_w;
    }
    for i in 0..LANES {
        out.x[i] = snap(sx[i]);
        out.y[i] = snap(sy[i]);
    }
}

/// Gathers [`LANES`] vertices' model positions and normals (zero past `len` and where the mesh has
/// no normal) into structure-of-arrays form.
pub(crate) fn gather(
    positions: &[Vec3],
    normals: Option<&[Vec3]>,
    start: usize,
    len: usize,
) -> ([Lanes; 3], [Lanes; 3]) {
    let mut p = [[0.0f32; LANES]; 3];
    let mut n = [[0.0f32; LANES]; 3];
    for i in 0..len {
        let v = positions[start + i];
        (p[0][i], p[1][i], p[2][i]) = (v.x, v.y, v.z);
        let m = normals.and_then(|n| n.get(start + i)).copied().unwrap_or(Vec3::ZERO);
        (n[0][i], n[1][i], n[2][i]) = (m.x, m.y, m.z);
    }
    (p, n)
}

/// Lane `i`'s vectors.
pub(crate) fn lane3(a: &[Lanes; 3], i: usize) -> Vec3 {
    Vec3::new(a[0][i], a[1][i], a[2][i])
}

/// Lane `i`'s clip position.
pub(crate) fn lane4(a: &[Lanes; 4], i: usize) -> Vec4 {
    Vec4::new(a[0][i], a[1][i], a[2][i], a[3][i])
}

/// The vertex colour and texture coordinate of vertex `i` as the vertex stage passes them on:
/// the mesh's colour (white without one) and uv (zero without one).
pub(crate) fn passed_on(colors: Option<&[Rgb]>, uvs: Option<&[Vec2]>, i: usize) -> (Rgb, Vec2) {
    (
        colors.and_then(|c| c.get(i)).copied().unwrap_or(Rgb::ONE),
        uvs.and_then(|uv| uv.get(i)).copied().unwrap_or(Vec2::ZERO),
    )
}

#[cfg(test)]
mod tests {
    use cg_core::glam::{Mat3, Mat4, Quat, Vec3};
    use cg_core::normals::normal_matrix;
    use cg_core::transform::transform_point;

    use super::*;

    fn bits(v: Vec3) -> [u32; 3] {
        v.to_array().map(f32::to_bits)
    }

    /// Every lane is what the point-by-point arithmetic gives: glam's products,
    /// `Prepared::world_normal`'s normalisation and flip, the viewport transform — for ordinary,
    /// mirrored and non-uniformly scaled objects, zero normals, and points behind the eye.
    #[test]
    fn a_span_of_vertices_is_the_point_by_point_arithmetic_bit_for_bit() {
        let mut seed = 7u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 40) as f32 / (1u64 << 24) as f32 * 4.0 - 2.0
        };
        let view =
            cg_core::transform::look_at(Vec3::new(1.0, 2.0, 6.0), Vec3::ZERO, Vec3::Y).unwrap();
        let projection = cg_core::transform::perspective(45.0, 1.5, 0.5, 50.0).unwrap();
        for model in [
            Mat4::from_rotation_translation(Quat::from_rotation_y(0.7), Vec3::new(0.5, -1.0, 0.25)),
            Mat4::from_scale(Vec3::new(-2.0, 1.0, 0.5)),
            Mat4::from_scale_rotation_translation(
                Vec3::new(3.0, 0.1, 1.0),
                Quat::from_rotation_x(1.1),
                Vec3::new(0.0, 0.0, 5.5),
            ),
        ] {
            let normal: Mat3 = normal_matrix(model);
            let mirrored = model.determinant() < 0.0;
            let t = Transforms {
                model,
                normal,
                mirrored,
                view,
                projection,
                width: 640.0,
                height: 480.0,
            };
            for round in 0..50 {
                let (mut p, mut n) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3]);
                for i in 0..LANES {
                    let (pv, nv) = (
                        Vec3::new(next(), next(), next() * 4.0),
                        Vec3::new(next(), next(), next()),
                    );
                    let nv = if (round + i) % 5 == 0 { Vec3::ZERO } else { nv };
                    (p[0][i], p[1][i], p[2][i]) = (pv.x, pv.y, pv.z);
                    (n[0][i], n[1][i], n[2][i]) = (nv.x, nv.y, nv.z);
                }
                let mut out = Out::default();
                transform(&t, &p, &n, &mut out);
                for i in 0..LANES {
                    let (pv, nv) = (lane3(&p, i), lane3(&n, i));
                    let world = transform_point(model, pv);
                    assert_eq!(bits(lane3(&out.p_world, i)), bits(world));
                    let expected_n = cg_core::math::try_normalize(normal * nv)
                        .map(|n| if mirrored { -n } else { n })
                        .unwrap_or(Vec3::ZERO);
                    assert_eq!(bits(lane3(&out.n_world, i)), bits(expected_n), "lane {i}");
                    let clip = projection * transform_point(view, world).extend(1.0);
                    assert_eq!(
                        lane4(&out.p_clip, i).to_array().map(f32::to_bits),
                        clip.to_array().map(f32::to_bits)
                    );
                    if out.in_window[i] {
                        // As the pipeline's `viewport`: times the reciprocal of w.
                        let ndc = clip.truncate() * (1.0 / clip.w);
                        let sx = (ndc.x + 1.0) * 0.5 * 640.0;
                        assert_eq!(out.x[i], (sx * 256.0).round() as i32, "lane {i}");
                        assert!(clip.w > 0.0);
                    } else {
                        assert!(
                            clip.w <= 0.0 || clip.w.is_nan() || !clip.is_finite(),
                            "lane {i}: {clip}"
                        );
                    }
                }
            }
        }
    }
}
