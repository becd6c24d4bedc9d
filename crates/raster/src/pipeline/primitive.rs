//! The primitive stages, per face in chunks of faces on all cores: clip, viewport, triangle setup,
//! flat colour, binning.

use cg_core::Rgb;
use cg_core::glam::{Vec2, Vec3, Vec4, Vec4Swizzles};
use cg_core::light::{LightCounts, LightModel};
use cg_core::scene::Shading;

use super::*;

/// Assembles, clips, sets up and bins the faces `faces` of object `object`.
pub(super) fn primitive_stage<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draw: &Draw<'_>,
    vertices: &[Vertex],
    windows: &[Window],
    object: usize,
    faces: std::ops::Range<usize>,
    chunk: &mut Chunk,
) {
    chunk.object = object;
    chunk.triangles.clear();
    chunk.new_vertices.clear();
    chunk.binned.clear();
    chunk.stats = Stats::default();
    let cull = if frame.scene.cull_back_faces {
        Cull::Back { mirrored: draw.prepared.mirrored }
    } else {
        Cull::None
    };
    let guard_band = planes(frame.guard);
    let first = faces.start;
    for (f, face) in draw.prepared.mesh.faces[faces].iter().enumerate() {
        let f = first + f;
        let stats = &mut chunk.stats;
        stats.triangles_in += 1;
        let w = face.map(|i| &windows[i as usize]);
        if w[0].codes.0 & w[1].codes.0 & w[2].codes.0 != 0 {
            stats.triangles_outside += 1;
            continue;
        }
        // The corners in window coordinates: the triangle itself, or the polygon that clipping
        // leaves of it.
        let mut screen = [ScreenVertex::default(); MAX_POLYGON];
        let mut len = 0;
        let unclipped = w[0].codes.1 | w[1].codes.1 | w[2].codes.1 == 0;
        if unclipped {
            if let [Some(a), Some(b), Some(c)] = w.map(|w| w.screen) {
                // A whole triangle (the common case): culled before its vertices are read.
                let mut fan = [a, b, c];
                for (v, &slot) in fan.iter_mut().zip(face) {
                    v.slot = slot;
                }
                match triangle_setup(fan, cull, frame.width, frame.height) {
                    Ok((edges, order)) => {
                        let corners = face.map(|i| &vertices[i as usize]);
                        let uv_origin = draw
                            .texture
                            .map_or(Vec2::ZERO, |t| t.sampler.repeat_origin(corners[0].uv));
                        let parts = face_parts(frame, draw, corners, stats);
                        stats.triangles_drawn += 1;
                        let s = order.map(|i| fan[i]);
                        let (triangles, binned) = (&mut chunk.triangles, &mut chunk.binned);
                        emit(frame, triangles, binned, edges, s, parts, f as u32, uv_origin);
                    }
                    Err(dropped) => stats.drop(dropped),
                }
            } else {
                // A corner at w ≤ 0 through rounding, or not finite: never divided by.
                stats.triangles_outside += 1;
            }
            continue;
        }
        let corners = face.map(|i| &vertices[i as usize]);
        let uv_origin = draw.texture.map_or(Vec2::ZERO, |t| t.sampler.repeat_origin(corners[0].uv));
        let mut visible = true;
        let mut to_window = |p_clip: Vec4, slot: u32| match viewport(frame, p_clip) {
            Some(v) => {
                screen[len] = ScreenVertex { slot, ..v };
                len += 1;
            }
            None => visible = false,
        };
        stats.triangles_clipped += 1;
        // Clipped with shifted texture coordinates, so the new vertices keep their precision.
        let shifted = corners.map(|v| Vertex { uv: v.uv - uv_origin, ..*v });
        let polygon = clip(&Polygon::triangle(shifted, *face), &guard_band);
        for corner in &polygon.corners[..polygon.len] {
            let mut slot = corner.slot;
            if slot == NEW_VERTEX {
                slot = NEW_VERTEX | chunk.new_vertices.len() as u32;
                chunk.new_vertices.push(corner.vertex);
            }
            to_window(corner.vertex.p_clip, slot);
        }
        if !visible || len < 3 {
            // Clipping left nothing (or, through rounding, a corner at w ≤ 0: never divided by).
            stats.triangles_outside += 1;
            continue;
        }
        // The face's normal (flat, and Phong's fallback) and its lighting (flat), made once when
        // a part of it is drawn.
        let mut face_parts: Option<(Vec3, Rgb)> = None;
        for k in 1..len - 1 {
            let fan = [screen[0], screen[k], screen[k + 1]];
            let (edges, order) = match triangle_setup(fan, cull, frame.width, frame.height) {
                Ok(t) => t,
                Err(dropped) => {
                    stats.drop(dropped);
                    continue;
                }
            };
            let parts =
                *face_parts.get_or_insert_with(|| self::face_parts(frame, draw, corners, stats));
            stats.triangles_drawn += 1;
            let s = order.map(|i| fan[i]);
            emit(
                frame,
                &mut chunk.triangles,
                &mut chunk.binned,
                edges,
                s,
                parts,
                f as u32,
                uv_origin,
            );
        }
    }
}

/// A triangle set up (`s` its corners in the edges' order) into the chunk's list, and binned.
#[allow(clippy::too_many_arguments)]
fn emit<L: ?Sized>(
    frame: &Frame<'_, L>,
    triangles: &mut Vec<Triangle>,
    binned: &mut Vec<(u32, u32)>,
    edges: Edges,
    s: [ScreenVertex; 3],
    (face_normal, flat_color): (Vec3, Rgb),
    face: u32,
    uv_origin: Vec2,
) {
    triangles.push(Triangle {
        edges,
        z: s.map(|v| v.z),
        inv_w: s.map(|v| v.inv_w),
        slot: s.map(|v| v.slot),
        face_normal,
        flat_color,
        face,
        uv_origin,
    });
    bin(frame, binned, triangles.len() - 1, &edges.bbox);
}

impl Stats {
    /// Counts a triangle that triangle setup dropped.
    fn drop(&mut self, dropped: Dropped) {
        match dropped {
            Dropped::Degenerate => self.triangles_degenerate += 1,
            Dropped::Culled => self.triangles_culled += 1,
            Dropped::TooSmall => self.triangles_too_small += 1,
        }
    }
}

/// The face's normal (flat, and Phong's fallback) and its lighting (flat), made once per face
/// when a part of it is drawn.
fn face_parts<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draw: &Draw<'_>,
    corners: [&Vertex; 3],
    stats: &mut Stats,
) -> (Vec3, Rgb) {
    match frame.shading {
        Shading::Flat => {
            let n = world_face_normal(draw, corners);
            (n, flat_color(frame, draw, corners, n, stats))
        }
        // The spans make it where they need it.
        Shading::Phong if frame.spans.is_some() && draw.lit => (Vec3::ZERO, Rgb::ONE),
        Shading::Phong => (world_face_normal(draw, corners), Rgb::ONE),
        Shading::Gouraud => (Vec3::ZERO, Rgb::ONE),
    }
}

/// A vertex as the primitive stages first need it: its outcodes ([`outcodes`]) and, when it
/// can be divided by its w, its window position ([`viewport`]).
#[derive(Clone, Copy, Debug)]
pub(super) struct Window {
    pub(super) codes: (u8, u8),
    pub(super) screen: Option<ScreenVertex>,
}

/// Which planes a clip-space point lies outside, as bits (near, far, −x, +x, −y, +y): of the
/// view volume, and of the clip volume with the guard band `guard` (in NDC units) at the sides.
#[inline]
pub(super) fn outcodes(p: Vec4, guard: Vec2) -> (u8, u8) {
    let [x, y, z, w] = p.to_array();
    let depth = u8::from(z < 0.0) | u8::from(z > w) << 1;
    let sides = |gx: f32, gy: f32| {
        u8::from(x < -gx * w) << 2
            | u8::from(x > gx * w) << 3
            | u8::from(y < -gy * w) << 4
            | u8::from(y > gy * w) << 5
    };
    (depth | sides(1.0, 1.0), depth | sides(guard.x, guard.y))
}

/// The six clip planes as `(a, b, c, d)` with `a·x + b·y + c·z + d·w ≥ 0` inside: near `z ≥ 0`,
/// far `z ≤ w`, and `|x| ≤ g.x·w`, `|y| ≤ g.y·w` (the view volume for `g = 1`, the guard band
/// for larger `g`).
fn planes(g: Vec2) -> [Vec4; 6] {
    [
        Vec4::new(0.0, 0.0, 1.0, 0.0),
        Vec4::new(0.0, 0.0, -1.0, 1.0),
        Vec4::new(1.0, 0.0, 0.0, g.x),
        Vec4::new(-1.0, 0.0, 0.0, g.x),
        Vec4::new(0.0, 1.0, 0.0, g.y),
        Vec4::new(0.0, -1.0, 0.0, g.y),
    ]
}

/// A corner of a polygon in clip space and where its vertex lives.
#[derive(Clone, Copy, Debug, Default)]
struct Corner {
    vertex: Vertex,
    slot: u32,
}

/// A convex polygon in clip space of at most [`MAX_POLYGON`] corners.
#[derive(Clone, Copy, Debug)]
struct Polygon {
    corners: [Corner; MAX_POLYGON],
    len: usize,
}

impl Polygon {
    fn triangle(vertices: [Vertex; 3], indices: [u32; 3]) -> Polygon {
        let mut corners = [Corner::default(); MAX_POLYGON];
        for k in 0..3 {
            corners[k] = Corner { vertex: vertices[k], slot: indices[k] };
        }
        Polygon { corners, len: 3 }
    }

    fn push(&mut self, corner: Corner) {
        // Clipping a convex polygon by a plane adds at most one corner: never full here.
        if self.len < MAX_POLYGON {
            self.corners[self.len] = corner;
            self.len += 1;
        }
    }
}

/// The clipper (クリッピング): Sutherland–Hodgman against each plane in turn, in homogeneous clip
/// space, so nothing is ever divided by `w ≤ 0` (docs/numerics.md row 21). New corners interpolate every
/// attribute linearly in clip space, from the inside corner towards the outside one — so an edge
/// shared by two triangles is cut at bit-identical points in both, and no crack opens between
/// them. Corners made here get the slot [`NEW_VERTEX`].
fn clip(polygon: &Polygon, planes: &[Vec4; 6]) -> Polygon {
    let mut current = *polygon;
    for plane in planes {
        let mut next = Polygon { corners: [Corner::default(); MAX_POLYGON], len: 0 };
        for i in 0..current.len {
            let a = current.corners[i];
            let b = current.corners[(i + 1) % current.len];
            let (da, db) = (plane.dot(a.vertex.p_clip), plane.dot(b.vertex.p_clip));
            if da >= 0.0 {
                next.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                let (inside, outside, d_in, d_out) =
                    if da >= 0.0 { (a, b, da, db) } else { (b, a, db, da) };
                // d_in ≥ 0 > d_out: t in [0, 1).
                let t = d_in / (d_in - d_out);
                next.push(Corner {
                    vertex: inside.vertex.lerp(&outside.vertex, t),
                    slot: NEW_VERTEX,
                });
            }
        }
        current = next;
        if current.len < 3 {
            break;
        }
    }
    current
}

/// The perspective divide (透視除算) and the viewport transform: window coordinates of a clip-space
/// point, x right and y down from the image's top-left corner in pixels, snapped to
/// `1/256` pixel, and the depth `z_ndc` (glDepthRange(0, 1), clamped to `[0, 1]` against
/// rounding). `None` for `w ≤ 0` or a non-finite result — never a division by `w ≤ 0`.
fn viewport<L: ?Sized>(frame: &Frame<'_, L>, p_clip: Vec4) -> Option<ScreenVertex> {
    if p_clip.w <= 0.0 || p_clip.w.is_nan() {
        return None;
    }
    let inv_w = 1.0 / p_clip.w;
    let p_ndc = p_clip.xyz() * inv_w;
    let p_screen = Vec3::new(
        (p_ndc.x + 1.0) * 0.5 * frame.width as f32,
        (1.0 - p_ndc.y) * 0.5 * frame.height as f32,
        p_ndc.z.clamp(0.0, 1.0),
    );
    if !(p_screen.is_finite() && inv_w.is_finite()) {
        return None;
    }
    Some(ScreenVertex { x: snap(p_screen.x), y: snap(p_screen.y), z: p_screen.z, inv_w, slot: 0 })
}

/// A window coordinate in fixed point, rounded to the nearest `1/256` pixel.
///
/// Rounds half away from zero, like `f32::round`, without a library call: `|v| ≤
/// GUARD_BAND_PIXELS + MAX_SIZE` after clipping, so `v · 256 < 2²⁹` and the truncating cast and
/// the fraction are exact.
#[inline]
pub(super) fn snap(v: f32) -> i32 {
    let r = v * ONE as f32;
    let i = r as i32;
    let fraction = r - i as f32;
    i + i32::from(fraction >= 0.5) - i32::from(fraction <= -0.5)
}

/// Which triangles to drop by their winding.
#[derive(Clone, Copy, Debug)]
pub(super) enum Cull {
    /// Draw both sides.
    None,
    /// Drop back faces (clockwise on screen; counter-clockwise for a mirrored object).
    Back {
        /// The object's model transform mirrors (det < 0).
        mirrored: bool,
    },
}

/// Why a triangle is not drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Dropped {
    Degenerate,
    Culled,
    TooSmall,
}

/// Triangle setup: the signed area, back-face culling (裏面の除去), the corners reordered so the
/// edge functions are positive inside (the returned `order` says how), and the bounding box of
/// pixel centres within `width × height`.
///
/// Counter-clockwise in OpenGL's y-up window is the front. Here y runs down, which mirrors the
/// winding: the front has a *negative* `(b − a) × (c − a)` (flipped again for a mirrored object,
/// whose model transform turned its counter-clockwise faces clockwise).
#[inline]
pub(super) fn triangle_setup(
    s: [ScreenVertex; 3],
    cull: Cull,
    width: u32,
    height: u32,
) -> Result<(Edges, [usize; 3]), Dropped> {
    let [a, b, c] = s.map(|v| (i64::from(v.x), i64::from(v.y)));
    let area2 = (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0);
    if area2 == 0 {
        return Err(Dropped::Degenerate);
    }
    if let Cull::Back { mirrored } = cull
        && (area2 < 0) == mirrored
    {
        return Err(Dropped::Culled);
    }
    let order = if area2 > 0 { [0, 1, 2] } else { [0, 2, 1] };
    let x = order.map(|i| s[i].x);
    let y = order.map(|i| s[i].y);
    // Pixel p's centre is p·256 + 128: the first centre at or after min, the last at or before max.
    // ⌈(min − ½)/1⌉ and ⌊(max − ½)/1⌋ in pixels, as ⌈a/b⌉ = −⌊−a/b⌋.
    let first = |min: i32| -(HALF - i64::from(min)).div_euclid(ONE);
    let last = |max: i32| (i64::from(max) - HALF).div_euclid(ONE);
    let x0 = first(*x.iter().min().unwrap_or(&0)).max(0);
    let y0 = first(*y.iter().min().unwrap_or(&0)).max(0);
    let x1 = last(*x.iter().max().unwrap_or(&0)).min(i64::from(width) - 1);
    let y1 = last(*y.iter().max().unwrap_or(&0)).min(i64::from(height) - 1);
    if x0 > x1 || y0 > y1 {
        return Err(Dropped::TooSmall);
    }
    // All four lie in 0..MAX_SIZE here.
    let bbox = [x0 as u32, y0 as u32, x1 as u32, y1 as u32];
    Ok((Edges { x, y, area2: area2.abs(), bbox }, order))
}

/// The face normal (面の法線) in world space, from the face's world positions (before clipping),
/// pointing out of the front face; zero for a degenerate face.
pub(super) fn world_face_normal(draw: &Draw<'_>, corners: [&Vertex; 3]) -> Vec3 {
    draw.prepared.world_face_normal(corners.map(|v| v.p_world)).unwrap_or(Vec3::ZERO)
}

/// The corner of a face whose lit colour OpenGL's GL_FLAT gives the whole face: its *provoking
/// vertex*, the last of each triangle under glBegin(GL_TRIANGLES), which is how `cg-glref` submits
/// every face of the prepared mesh (quads and polygons, whose provoking vertex GL picks otherwise,
/// are triangles by then).
const PROVOKING: usize = 2;

/// Flat shading (フラットシェーディング): the face is lit once and the colour clamped to `[0, 1]`;
/// where, and with which normal, is the light model's rule:
///
/// - the lecture's model: at the face's centroid in world space with the face normal
///   ("面の法線をもとに面の色を決定"; every corner treated alike); with per-vertex colours the
///   colour material is the mean of the three;
/// - OpenGL's model: as glShadeModel(GL_FLAT) — at the face's provoking vertex ([`PROVOKING`],
///   the last corner), with that vertex's own normal, position and colour, exactly as Gouraud
///   lights that vertex (the face normal only where the vertex's normal vanishes). Clipping
///   changes nothing: the original corner is lit, so every piece keeps its colour, as in OpenGL.
fn flat_color<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draw: &Draw<'_>,
    corners: [&Vertex; 3],
    face_normal: Vec3,
    stats: &mut Stats,
) -> Rgb {
    if !draw.lit {
        return Rgb::ONE;
    }
    let (p_world, n_world, color) = match frame.scene.light_model {
        LightModel::OpenGl { .. } => {
            let v = corners[PROVOKING];
            let n = if v.n_world == Vec3::ZERO { face_normal } else { v.n_world };
            (v.p_world, n, draw.has_colors().then_some(v.color))
        }
        LightModel::Lecture { .. } => {
            let centroid = (corners[0].p_world + corners[1].p_world + corners[2].p_world) / 3.0;
            let mean = (corners[0].color + corners[1].color + corners[2].color) / 3.0;
            (centroid, face_normal, draw.has_colors().then_some(mean))
        }
    };
    let material = draw.material.with_color(color);
    let mut counts = LightCounts::default();
    let lit = saturate(frame.light(p_world, n_world, &material, &mut counts));
    stats.add_lighting(&counts);
    lit
}

/// Binning: a `(tile, triangle)` pair for every tile the triangle's bounding box touches.
fn bin<L: ?Sized>(
    frame: &Frame<'_, L>,
    binned: &mut Vec<(u32, u32)>,
    triangle: usize,
    bbox: &[u32; 4],
) {
    let columns = frame.width.div_ceil(frame.tile);
    for ty in bbox[1] / frame.tile..=bbox[3] / frame.tile {
        for tx in bbox[0] / frame.tile..=bbox[2] / frame.tile {
            binned.push((ty * columns + tx, triangle as u32));
        }
    }
}
