//! Per tile: rasterize, depth test, fragment (and the rasterizer alone, for the coverage tests).

use cg_core::Rgb;
use cg_core::glam::{Vec2, Vec3};
use cg_core::light::LightCounts;
use cg_core::normals::interpolate_normal;
use cg_core::scene::Shading;

use super::cover::{Gouraud, Kernels, Run, SIMPLE, STAGED, Simple, cover};
use super::*;

/// The pixels of one tile: its part of each of its rows of the colour and depth buffers.
pub(super) struct Target<'a> {
    /// Row `y − y0` of the tile, pixels `x0..x0 + len`.
    pub(super) color: Vec<&'a mut [Rgb]>,
    /// The same for the depth buffer.
    pub(super) depth: Vec<&'a mut [f32]>,
    /// The image column of the tile's first pixel.
    pub(super) x0: u32,
    /// The image row of the tile's first row.
    pub(super) y0: u32,
}

/// Draws one tile: every triangle binned to it (`bin`: `(chunk, triangle)` pairs in submission
/// order) into `target` (the tile's pixels, cleared to the clear colour and depth 1). `span` is
/// the thread's Phong span, reused from tile to tile (a new one is several kilobytes to clear).
#[inline]
#[allow(clippy::too_many_arguments)]
pub(super) fn draw_tile<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draws: &[Draw<'_>],
    buffers: &[Vec<Vertex>],
    chunks: &[Chunk],
    bin: &[(u32, u32)],
    rect: Rect,
    target: &mut Target<'_>,
    span: &mut PhongSpan,
) -> Stats {
    let mut stats = Stats::default();
    let mut counts = LightCounts::default();
    // Phong's fragments of the scene's own light model, lit sixteen at a time.
    span.reset();
    // Runs of sixteen pixels that passed the depth test and still need their fragment stage.
    let mut runs = Vec::new();
    let spans = frame.spans.as_ref().filter(|_| frame.shading == Shading::Phong);
    // The face normal where the corners' normals cancel, from the face's own corners.
    let face = |object: usize| {
        let (draw, vertices) = (&draws[object], &buffers[object]);
        move |face: u32| {
            let face = draw.prepared.mesh.faces[face as usize];
            world_face_normal(draw, face.map(|i| &vertices[i as usize]))
        }
    };
    // What lights an object's spans, and its texture.
    let stage = |lights, object: usize| {
        let draw = &draws[object];
        let stage = span::Stage { lights, material: &draw.material, colored: draw.has_colors() };
        (stage, draw.texture)
    };
    let flush = |span: &mut PhongSpan,
                 target: &mut Target<'_>,
                 counts: &mut LightCounts,
                 stats: &mut Stats| {
        // An empty span may name no object: a scene without any, or a tile none reaches.
        if let Some(lights) = spans.filter(|_| !span.is_empty()) {
            let (stage, texture) = stage(lights, span.object);
            let face = face(span.object);
            stats.texture_samples += span.flush(&stage, texture, counts, face, |row, column, c| {
                target.color[row as usize][column as usize] = c;
            });
        }
    };
    // A whole run of the current triangle, lit at once where the span holds no other
    // triangle's fragments (`PhongSpan::light_run`); `false` where it was not.
    let light_run = |span: &mut PhongSpan,
                     target: &mut Target<'_>,
                     counts: &mut LightCounts,
                     stats: &mut Stats,
                     run: &Run<STAGED>| {
        let (row, column) = ((run.y - target.y0) as usize, (run.x - target.x0) as usize);
        let whole = run.passed == u32::MAX >> (u32::BITS - STAGED as u32);
        let (Some(lights), true, true) = (spans, whole, span.only_current()) else {
            return false;
        };
        let Some(out) = target.color[row][column..].first_chunk_mut::<STAGED>() else {
            return false;
        };
        let (stage, texture) = stage(lights, span.object);
        let face = face(span.object);
        stats.texture_samples += span.light_run(&stage, texture, counts, face, &run.b, out);
        true
    };
    for &(c, t) in bin {
        let chunk = &chunks[c as usize];
        let draw = &draws[chunk.object];
        if span.object != chunk.object {
            flush(span, target, &mut counts, &mut stats);
            span.object = chunk.object;
        }
        let vertices = &buffers[chunk.object];
        let triangle = &chunk.triangles[t as usize];
        // Vertices made by clipping hold shifted texture coordinates already (see `uv_origin`).
        let corners = |triangle: &Triangle| {
            triangle.slot.map(|slot| {
                if slot & NEW_VERTEX == 0 {
                    let v = vertices[slot as usize];
                    Vertex { uv: v.uv - triangle.uv_origin, ..v }
                } else {
                    chunk.new_vertices[(slot & !NEW_VERTEX) as usize]
                }
            })
        };
        // Phong with the scene's own light model: the fragment is queued for its span, and its
        // triangle made as the span needs it when its first fragment passes (many small
        // triangles have none). Otherwise the fragment stage runs here.
        let spanned = spans.is_some() && draw.lit;
        let corners_now = (!spanned).then(|| corners(triangle));
        span.end_triangle();
        // The triangle's attributes for Phong's spans, at its first fragment that passed: made
        // once (a flush in its middle keeps it registered).
        macro_rules! register {
            () => {
                if !span.has_triangle() {
                    let corners = corners(triangle);
                    let corners = corners.map(|v| (v.p_world, v.n_world, v.color, v.uv));
                    span.begin(span::Triangle::new(triangle.inv_w, corners, triangle.face));
                }
            };
        }
        // One fragment's stage after the depth test, where `simple` does not give its colour
        // (a macro: the same code in both loops, inlined).
        macro_rules! stage {
            ($row:expr, $column:expr, $b:expr) => {{
                let (row, column, b) = ($row, $column, $b);
                if let Some(corners) = &corners_now {
                    target.color[row][column] =
                        fragment(frame, draw, triangle, corners, b, &mut stats, &mut counts);
                } else {
                    register!();
                    if span.push((row as u32, column as u32), b) {
                        flush(span, target, &mut counts, &mut stats);
                    }
                }
            }};
        }
        let [x0, _, x1, _] = triangle.edges.bbox;
        if x1.min(rect.x1) < x0.max(rect.x0) + NARROW {
            // A narrow triangle (most of a dense mesh's): pixel by pixel.
            let inv_area = 1.0 / triangle.edges.area2 as f32;
            let z = Vec3::from(triangle.z);
            rasterize(&triangle.edges, rect, |x, y, e| {
                stats.fragments += 1;
                let (row, column) = ((y - target.y0) as usize, (x - target.x0) as usize);
                // Screen-space (linear) barycentrics: window depth is linear on the screen.
                let b = Vec3::new(e[0] as f32, e[1] as f32, e[2] as f32) * inv_area;
                if !depth_test(b.dot(z).clamp(0.0, 1.0), &mut target.depth[row][column]) {
                    stats.depth_rejects += 1;
                    return;
                }
                stats.fragments_shaded += 1;
                stage!(row, column, b);
            });
            continue;
        }
        // Flat and Gouraud without a texture: the colour of eight pixels at once ([`SIMPLE`]).
        let simple = match (frame.shading, &corners_now) {
            (Shading::Flat, _) if draw.texture.is_none() => {
                Simple::Flat(saturate(triangle.flat_color))
            }
            (Shading::Gouraud, Some(c)) if draw.texture.is_none() => {
                Simple::Gouraud(Gouraud::new(triangle.inv_w, c.each_ref().map(|v| v.color)))
            }
            _ => Simple::No,
        };
        runs.clear();
        let (covered, passed) = match simple {
            Simple::No => cover::<STAGED>(
                &triangle.edges,
                rect,
                triangle.z,
                &simple,
                target,
                &mut runs,
                Kernels::Best,
            ),
            _ => cover::<SIMPLE>(
                &triangle.edges,
                rect,
                triangle.z,
                &simple,
                target,
                &mut Vec::new(),
                Kernels::Best,
            ),
        };
        stats.fragments += covered;
        stats.depth_rejects += covered - passed;
        stats.fragments_shaded += passed;
        for run in &runs {
            let (row, column) = ((run.y - target.y0) as usize, (run.x - target.x0) as usize);
            if corners_now.is_none() {
                // Phong's spans: the run's pixels that passed go in together, left to right,
                // flushing each time the span fills (a whole run inside a large triangle is one
                // span when it comes to an empty one).
                register!();
                if light_run(span, target, &mut counts, &mut stats, run) {
                    continue;
                }
                let mut left = run.passed;
                while left != 0 {
                    left = span.push_run((row as u32, column as u32), &run.b, left);
                    if span.is_full() {
                        flush(span, target, &mut counts, &mut stats);
                    }
                }
                continue;
            }
            // The pixels that passed, lowest bit first (left to right).
            let mut left = run.passed;
            while left != 0 {
                let k = left.trailing_zeros() as usize;
                left &= left - 1;
                stage!(row, column + k, run.b.get(k));
            }
        }
    }
    flush(span, target, &mut counts, &mut stats);
    stats.add_lighting(&counts);
    stats
}

/// Perspective-correct barycentrics from the screen-space ones `screen_barycentric`: attributes
/// are linear in the plane of the triangle, not on the screen, so each corner is weighted by
/// 1/w and the weights renormalised.
#[inline]
fn perspective(triangle: &Triangle, screen_barycentric: Vec3) -> Vec3 {
    let weighted = screen_barycentric * Vec3::from(triangle.inv_w);
    let sum = weighted.x + weighted.y + weighted.z;
    if sum > 0.0 && sum.is_finite() { weighted / sum } else { screen_barycentric }
}

/// The rasterizer (ラスタライズ): calls `emit(x, y, e)` for every pixel of `rect` whose centre
/// `(x + ½, y + ½)` the triangle covers, row by row, with `e` the three edge functions there
/// (`e[i]` is twice the area of the sub-triangle opposite corner `i`, in (1/256 pixel)²; they sum
/// to `area2`).
///
/// The edge functions are exact integers on the 1/256-pixel grid (no rounding, so the answer
/// does not depend on where a tile starts). The fill rule: a pixel whose centre is exactly on an
/// edge belongs to the triangle when the edge is a left edge (the triangle to its right) or a
/// bottom edge (horizontal, the triangle above it) as the image is displayed — what Mesa's
/// llvmpipe does (OpenGL's top-left rule in its y-up window coordinates). So a pixel on an edge
/// shared by two triangles is drawn exactly once, none is missed (docs/numerics.md row 22), and the ties
/// fall as in the course's OpenGL (`tests/opengl.rs` checks it pixel by pixel).
#[inline]
pub(super) fn rasterize(edges: &Edges, rect: Rect, mut emit: impl FnMut(u32, u32, [i64; 3])) {
    let [bx0, by0, bx1, by1] = edges.bbox;
    let (x0, y0) = (bx0.max(rect.x0), by0.max(rect.y0));
    let (x1, y1) = (bx1.min(rect.x1.saturating_sub(1)), by1.min(rect.y1.saturating_sub(1)));
    if x0 > x1 || y0 > y1 {
        return;
    }
    let (mut row, step_x, step_y, bias) = edge_setup(edges, x0, y0);
    for py in y0..=y1 {
        let mut e = row;
        for px in x0..=x1 {
            // Inside: every biased edge function ≥ 0 (the sign bits of all three are clear).
            if (e[0] | e[1] | e[2]) >= 0 {
                emit(px, py, [e[0] - bias[0], e[1] - bias[1], e[2] - bias[2]]);
            }
            for i in 0..3 {
                e[i] += step_x[i];
            }
        }
        for i in 0..3 {
            row[i] += step_y[i];
        }
    }
}

/// The edge functions at pixel `(x0, y0)`'s centre, biased by the fill rule (so a pixel is
/// covered where all three are ≥ 0), their steps to the next pixel right and down, and the biases.
#[inline]
pub(super) fn edge_setup(
    edges: &Edges,
    x0: u32,
    y0: u32,
) -> ([i64; 3], [i64; 3], [i64; 3], [i64; 3]) {
    let (x, y) = (edges.x.map(i64::from), edges.y.map(i64::from));
    let (px, py) = (i64::from(x0) * ONE + HALF, i64::from(y0) * ONE + HALF);
    let mut row = [0i64; 3];
    let mut step_x = [0i64; 3];
    let mut step_y = [0i64; 3];
    let mut bias = [0i64; 3];
    for i in 0..3 {
        // Edge i runs from corner j to corner k and faces corner i.
        let (j, k) = ((i + 1) % 3, (i + 2) % 3);
        let (dx, dy) = (x[k] - x[j], y[k] - y[j]);
        // E(p) = (k − j) × (p − j), positive inside (the corners run clockwise as seen, y down):
        // a left edge runs up (dy < 0), a bottom edge runs right to left (dy = 0, dx < 0).
        // Their centres are kept (E ≥ 0); on other edges E must be > 0, i.e. E − 1 ≥ 0.
        let left_or_bottom = dy < 0 || (dy == 0 && dx < 0);
        bias[i] = if left_or_bottom { 0 } else { -1 };
        row[i] = dx * (py - y[j]) - dy * (px - x[j]) + bias[i];
        step_x[i] = -dy * ONE;
        step_y[i] = dx * ONE;
    }
    (row, step_x, step_y, bias)
}

/// Below this many pixels' width (within the tile), a triangle is drawn pixel by pixel; wider
/// ones eight or sixteen pixels at a time ([`cover()`]).
const NARROW: u32 = 8;

/// The depth test (隠面消去, Z バッファ法): GL_LESS against the buffer cleared to 1; on a pass the
/// depth is written. It runs before the fragment stage (early depth test, as GPUs do when a
/// fragment cannot be discarded): the same image, without shading hidden fragments.
#[inline]
fn depth_test(z: f32, stored: &mut f32) -> bool {
    if z < *stored {
        *stored = z;
        true
    } else {
        false
    }
}

/// The fragment stage: perspective-correct barycentrics from the screen-space ones, then the
/// colour by the shading mode — flat: the face's colour; Gouraud: the vertex colours
/// interpolated; Phong: the normal (and position) interpolated, renormalised with
/// [`interpolate_normal`] (falling back to the face normal, docs/numerics.md row 18) and lit here — and
/// the texture applied after lighting as OpenGL does (GL_MODULATE: colour × texel; GL_REPLACE:
/// the texel). The result is clamped to `[0, 1]`.
#[inline(always)]
fn fragment<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draw: &Draw<'_>,
    triangle: &Triangle,
    corners: &[Vertex; 3],
    screen_barycentric: Vec3,
    stats: &mut Stats,
    counts: &mut LightCounts,
) -> Rgb {
    let b = perspective(triangle, screen_barycentric);
    let interpolate3 =
        |f: fn(&Vertex) -> Vec3| b.x * f(&corners[0]) + b.y * f(&corners[1]) + b.z * f(&corners[2]);
    let lit = match frame.shading {
        Shading::Flat => triangle.flat_color,
        Shading::Gouraud => interpolate3(|v| v.color),
        Shading::Phong if draw.lit => {
            let n_world = interpolate_normal(corners.map(|v| v.n_world), b, triangle.face_normal);
            let p_world = interpolate3(|v| v.p_world);
            let color = draw.has_colors().then(|| interpolate3(|v| v.color));
            let material = draw.material.with_color(color);
            saturate(frame.light(p_world, n_world, &material, counts))
        }
        Shading::Phong => Rgb::ONE,
    };
    let color = match &draw.texture {
        None => lit,
        Some(t) => {
            // Shifted by the triangle's `uv_origin` (an integer under repeat): small numbers.
            let uv = b.x * corners[0].uv + b.y * corners[1].uv + b.z * corners[2].uv;
            stats.texture_samples += 1;
            t.env.apply(lit, t.texture.sample(uv, t.sampler))
        }
    };
    debug_assert!(color.is_finite(), "fragment colour {color}");
    saturate(color)
}

// ---------------------------------------------------------------------------------------------
// The rasterizer alone, for coverage tests

/// How many times each pixel of a `width × height` raster is covered by `triangles`, given in
/// window coordinates (pixels, x right, y down from the top-left corner; pixel `(x, y)` has its
/// centre at `(x + ½, y + ½)`), drawn through the renderer's own snapping, triangle setup (both
/// windings, no culling), tiling (`tile` × `tile` pixels) and rasterizer. Row by row from the top.
///
/// # Errors
/// A size that [`check_size`] rejects; [`RenderError::OutsideGuardBand`] for the first corner
/// that is not finite or lies beyond ±[`GUARD_BAND_PIXELS`] (where [`snap`] would saturate and
/// the edge functions could overflow `i64`).
pub(crate) fn coverage(
    width: u32,
    height: u32,
    tile: u32,
    triangles: &[[Vec2; 3]],
) -> Result<Vec<u32>, RenderError> {
    check_size(width, height)?;
    for (triangle, corners) in triangles.iter().enumerate() {
        for (corner, p) in corners.iter().enumerate() {
            if !(p.is_finite() && p.abs().max_element() <= GUARD_BAND_PIXELS) {
                return Err(RenderError::OutsideGuardBand {
                    triangle,
                    corner,
                    position: p.to_array(),
                });
            }
        }
    }
    let mut counts = vec![0u32; width as usize * height as usize];
    let set_up: Vec<Edges> = triangles
        .iter()
        .filter_map(|t| {
            let s =
                t.map(|p| ScreenVertex { x: snap(p.x), y: snap(p.y), ..ScreenVertex::default() });
            triangle_setup(s, Cull::None, width, height).ok().map(|(edges, _)| edges)
        })
        .collect();
    let tile = tile.max(1);
    for ty in (0..height).step_by(tile as usize) {
        for tx in (0..width).step_by(tile as usize) {
            let rect =
                Rect { x0: tx, y0: ty, x1: (tx + tile).min(width), y1: (ty + tile).min(height) };
            for edges in &set_up {
                rasterize(edges, rect, |x, y, _| {
                    counts[y as usize * width as usize + x as usize] += 1
                });
            }
        }
    }
    Ok(counts)
}
