//! The pipeline, one function per stage, in the order a GPU runs them (read it top to bottom, as
//! tinyrenderer's `our_gl.cpp`):
//!
//! ```text
//! draw ─┬─ vertex             model → world → view → clip; Gouraud lights here, per vertex
//!       ├─ per face, in chunks of faces on all cores:
//!       │    clip             Sutherland–Hodgman in clip space: near (z ≥ 0), far, guard band
//!       │    viewport         perspective divide, then window coordinates snapped to 1/256 pixel
//!       │    triangle_setup   back-face culling by the signed area, edge orientation, bounding box
//!       │    flat_color       Flat lights here, once per face (centroid, or GL's provoking vertex)
//!       │    bin              the triangle goes to every tile its bounding box touches
//!       ├─ Bins::gather       every chunk's (tile, triangle) pairs into one list per tile
//!       └─ draw_tile, each tile a task on all cores, triangles in submission order:
//!            rasterize        edge functions in fixed point, OpenGL's fill rule (left and
//!                             bottom edges as the image is displayed)
//!            depth_test       GL_LESS against the tile's depth buffer, then the depth write
//!            fragment         perspective-correct attributes; Phong lights here; texture
//! ```
//!
//! Each tile is drawn by one thread from start to end, its triangles in the order they were
//! submitted, so the image is the same bits whatever the thread count or the tile size.
//!
//! Spaces and names: `p_model`, `p_world` (lighting happens here), `p_view`, `p_clip` (homogeneous,
//! `[0, 1]` depth), `p_ndc`, `p_screen` (window: pixels, x right, y *down* from the image's top-left
//! corner, pixel `(x, y)` centred at `(x + ½, y + ½)`, depth in `[0, 1]`).

use cg_core::Rgb;
use cg_core::features::Features;
use cg_core::glam::{Mat4, Vec2, Vec3, Vec4, Vec4Swizzles};
use cg_core::image::{Image, check_size};
use cg_core::light::{LightCounts, LightModel, Material};
use cg_core::math::try_normalize;
use cg_core::normals::interpolate_normal;
use cg_core::scene::{Prepared, Scene, Shading};
use cg_core::texture::{Sampler, TexEnv, Texture};
use cg_core::transform::transform_point;
use rayon::prelude::*;
use std::sync::Mutex;

use crate::error::RenderError;
use crate::lighting::{Lighting, SurfacePoint};
use crate::output::{DEFAULT_TILE_SIZE, Options, Output, Stats};
use crate::span::{self, LANES, PhongSpan, Points, SpanLights, V3, saturate};
use crate::vertex8;

/// Bits of sub-pixel precision: window coordinates are snapped to multiples of `1/256` pixel
/// (as Direct3D 10+ requires, and as Mesa's llvmpipe does) before the edge functions are set up.
pub const SUBPIXEL_BITS: u32 = 8;
/// One pixel in fixed point.
const ONE: i64 = 1 << SUBPIXEL_BITS;
/// A pixel centre's offset in fixed point (½ pixel).
const HALF: i64 = ONE / 2;

/// How far beyond the image edges (in pixels) a triangle may reach before it is clipped at the
/// sides: the guard band. Inside it, the bounding box clipped to the tile does the work; beyond it
/// Sutherland–Hodgman clipping keeps window coordinates below 2²¹ pixels, so fixed-point
/// coordinates fit `i32` and the edge functions (products of two 30-bit differences) fit `i64`.
pub const GUARD_BAND_PIXELS: f32 = (1u32 << 20) as f32;

/// Faces per unit of parallel work in the primitive stages.
const FACES_PER_CHUNK: usize = 8192;

/// The most vertices a triangle can have after clipping by six planes (each adds at most one).
const MAX_POLYGON: usize = 9;

// ---------------------------------------------------------------------------------------------
// What every stage reads

/// Everything fixed for one frame: the camera, the projection, the window and the scene's needs.
struct Frame<'s, L: ?Sized> {
    scene: &'s Scene,
    lighting: &'s L,
    shading: Shading,
    width: u32,
    height: u32,
    tile: u32,
    /// ワールド座標系→カメラ座標系.
    view: Mat4,
    /// カメラ座標系→クリップ座標系, `[0, 1]` depth.
    projection: Mat4,
    /// The eye in world space (for a local viewer's V).
    eye: Vec3,
    /// The camera's backward axis (+Z of camera space) in world space: the infinite viewer's V.
    backward: Vec3,
    features: Features,
    /// The guard band in NDC units along x and y (≥ 1).
    guard: Vec2,
    /// The scene's lights made ready for lighting eight points at once, when `lighting` is the
    /// scene's own light model ([`Lighting::is_scene_lighting`]).
    spans: Option<SpanLights>,
}

/// One object made ready to draw.
struct Draw<'s> {
    prepared: Prepared<'s>,
    /// The object's material, with k_s = 0 when the scene has no specular light at all.
    material: Material,
    texture: Option<Texturing<'s>>,
    /// Whether the lit colour is used at all (not under GL_REPLACE, which shows the bare texel).
    lit: bool,
}

/// A texture bound to an object.
#[derive(Clone, Copy)]
struct Texturing<'s> {
    texture: &'s Texture,
    sampler: Sampler,
    env: TexEnv,
}

/// The vertex stage's output for one vertex (a GPU's varyings plus the clip position).
#[derive(Clone, Copy, Debug, Default)]
struct Vertex {
    p_clip: Vec4,
    p_world: Vec3,
    n_world: Vec3,
    /// Gouraud: the lit colour, clamped to `[0, 1]`; otherwise the vertex colour (or white).
    color: Rgb,
    uv: Vec2,
}

impl Vertex {
    /// `self + t·(other − self)` for every attribute: linear in clip space, which is what keeps
    /// attributes of clipped vertices right under perspective.
    fn lerp(&self, other: &Vertex, t: f32) -> Vertex {
        Vertex {
            p_clip: self.p_clip + (other.p_clip - self.p_clip) * t,
            p_world: self.p_world + (other.p_world - self.p_world) * t,
            n_world: self.n_world + (other.n_world - self.n_world) * t,
            color: self.color + (other.color - self.color) * t,
            uv: self.uv + (other.uv - self.uv) * t,
        }
    }
}

/// Where a triangle's corner lives: below [`NEW_VERTEX`], an index into its object's vertex
/// buffer; from it up, an index into its chunk's vertices made by clipping.
const NEW_VERTEX: u32 = 1 << 31;

/// A triangle set up for the rasterizer.
#[derive(Clone, Copy, Debug)]
struct Triangle {
    edges: Edges,
    /// Window depth of each corner.
    z: [f32; 3],
    /// 1/w of each corner (for perspective-correct interpolation).
    inv_w: [f32; 3],
    /// The corners' vertices (see [`NEW_VERTEX`]).
    slot: [u32; 3],
    /// Phong: the face normal in world space, the fallback of [`interpolate_normal`] (zero under
    /// the other modes, which do not read it, and when the scene's own light model lights the
    /// fragments eight at a time: that path makes it only where it is needed).
    face_normal: Vec3,
    /// Flat: the face's colour, clamped to `[0, 1]`.
    flat_color: Rgb,
    /// The face it is (a part of), in its object's prepared mesh.
    face: u32,
    /// The integer shift taken off the face's texture coordinates before they are interpolated
    /// ([`Sampler::repeat_origin`] of its first corner; zero without a texture): vertices made
    /// by clipping hold shifted coordinates already, the others are shifted when the triangle is
    /// drawn (docs/numerics.md row 23).
    uv_origin: Vec2,
}

/// The fixed-point corners of a triangle, ordered so that every edge function is positive inside.
#[derive(Clone, Copy, Debug)]
struct Edges {
    /// x of each corner in 1/256 pixel.
    x: [i32; 3],
    /// y of each corner (down) in 1/256 pixel.
    y: [i32; 3],
    /// Twice the area in (1/256 pixel)², > 0.
    area2: i64,
    /// The pixels whose centres the bounding box holds, clipped to the image: `[x0, y0, x1, y1]`,
    /// inclusive.
    bbox: [u32; 4],
}

/// A corner after the viewport transform.
#[derive(Clone, Copy, Debug, Default)]
struct ScreenVertex {
    x: i32,
    y: i32,
    z: f32,
    inv_w: f32,
    slot: u32,
}

/// The output of the primitive stages for one chunk of faces of one object.
#[derive(Default)]
struct Chunk {
    object: usize,
    triangles: Vec<Triangle>,
    /// Vertices made by clipping, referred to by `NEW_VERTEX | index`.
    new_vertices: Vec<Vertex>,
    /// `(tile, triangle)` for every tile each triangle's bounding box touches, in submission
    /// order: as much memory as there is work (no list per tile per chunk).
    binned: Vec<(u32, u32)>,
    stats: Stats,
}

/// Every chunk's binned triangles, gathered into one list per tile (compressed rows: the list of
/// tile `i` is `entries[start[i]..start[i + 1]]`), each in submission order.
#[derive(Default)]
struct Bins {
    start: Vec<usize>,
    /// `(chunk, triangle)` pairs.
    entries: Vec<(u32, u32)>,
}

impl Bins {
    /// Counts, then places, every `(tile, triangle)` pair of `chunks` (in chunk order, each
    /// chunk's pairs in order), so each tile's list keeps the submission order.
    /// (Into this one's memory.)
    fn gather(&mut self, chunks: &[Chunk], tiles: usize) {
        let Bins { start, entries } = self;
        start.clear();
        start.resize(tiles + 1, 0);
        for chunk in chunks {
            for &(tile, _) in &chunk.binned {
                start[tile as usize + 1] += 1;
            }
        }
        for i in 0..tiles {
            start[i + 1] += start[i];
        }
        let mut next = start.clone();
        entries.clear();
        entries.resize(start[tiles], (0, 0));
        for (c, chunk) in chunks.iter().enumerate() {
            for &(tile, triangle) in &chunk.binned {
                entries[next[tile as usize]] = (c as u32, triangle);
                next[tile as usize] += 1;
            }
        }
    }

    /// Tile `index`'s `(chunk, triangle)` pairs, in submission order.
    fn tile(&self, index: usize) -> &[(u32, u32)] {
        &self.entries[self.start[index]..self.start[index + 1]]
    }
}

/// A rectangle of pixels `[x0, x1) × [y0, y1)`.
#[derive(Clone, Copy, Debug)]
struct Rect {
    x0: u32,
    y0: u32,
    x1: u32,
    y1: u32,
}

// ---------------------------------------------------------------------------------------------
// The draw call

/// A scene made ready to draw: the frame fixed and every object prepared (shading normals,
/// model matrix, material, texture), so each [`Ready::draw`] runs the pipeline from the vertex
/// stage on.
pub(crate) struct Ready<'s, L: ?Sized> {
    frame: Frame<'s, L>,
    draws: Vec<Draw<'s>>,
    /// The last frame's working memory, reused by the next (a frame of a large mesh needs
    /// hundreds of megabytes: taking them from the system anew, page by page, every frame
    /// costs as much as a stage).
    scratch: Mutex<Scratch>,
}

/// A frame's working memory besides its output: every object's vertices and windows, every
/// chunk's triangles, and the bins.
#[derive(Default)]
struct Scratch {
    vertices: Vec<Vec<Vertex>>,
    windows: Vec<Vec<Window>>,
    chunks: Vec<Chunk>,
    bins: Bins,
}

impl<'s, L: Lighting + ?Sized> Ready<'s, L> {
    pub(crate) fn new(
        scene: &'s Scene,
        options: &Options,
        lighting: &'s L,
    ) -> Result<Self, RenderError> {
        let frame = Frame::new(scene, options, lighting)?;
        let draws = prepare_draws(scene, &frame.features)?;
        Ok(Ready { frame, draws, scratch: Mutex::default() })
    }

    /// Draws the prepared scene, in the current thread pool, into the colour and depth buffers
    /// of `reuse` when it is given and of the right size (each tile clears its part first),
    /// into new ones otherwise.
    pub(crate) fn draw(&self, reuse: Option<Output>) -> Result<Output, RenderError> {
        // A frame drawn meanwhile on another thread keeps the working memory; this one makes
        // its own.
        match self.scratch.try_lock() {
            Ok(mut scratch) => draw_ready(&self.frame, &self.draws, reuse, &mut scratch),
            Err(_) => draw_ready(&self.frame, &self.draws, reuse, &mut Scratch::default()),
        }
    }
}

fn draw_ready<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draws: &[Draw<'_>],
    reuse: Option<Output>,
    scratch: &mut Scratch,
) -> Result<Output, RenderError> {
    let scene = frame.scene;
    let mut stats = Stats::default();
    let Scratch { vertices: buffers, windows, chunks, bins } = scratch;
    buffers.resize_with(draws.len(), Vec::new);
    windows.resize_with(draws.len(), Vec::new);
    for ((draw, vertices), windows) in draws.iter().zip(buffers.iter_mut()).zip(windows.iter_mut())
    {
        // Each vertex's outcodes and window position too, once (a vertex is a corner of about
        // six faces).
        stats += vertex_stage(frame, draw, vertices, windows)?;
    }

    let jobs: Vec<(usize, usize, usize)> = draws
        .iter()
        .enumerate()
        .flat_map(|(object, draw)| {
            let faces = draw.prepared.mesh.faces.len();
            (0..faces)
                .step_by(FACES_PER_CHUNK)
                .map(move |start| (object, start, (start + FACES_PER_CHUNK).min(faces)))
        })
        .collect();
    chunks.resize_with(jobs.len(), Chunk::default);
    chunks.truncate(jobs.len());
    let (buffers, windows) = (&*buffers, &*windows);
    chunks.par_iter_mut().zip(&jobs).for_each(|(chunk, &(object, start, end))| {
        let (vertices, windows) = (&buffers[object], &windows[object]);
        primitive_stage(frame, &draws[object], vertices, windows, object, start..end, chunk);
    });
    for chunk in chunks.iter() {
        stats += chunk.stats;
    }
    let columns = frame.width.div_ceil(frame.tile);
    bins.gather(chunks, (columns * frame.height.div_ceil(frame.tile)) as usize);
    let (chunks, bins) = (&*chunks, &*bins);

    // Each tile is one task. A band (a row of tiles) owns its rows of the colour and depth
    // buffers; its rows are cut at the tile borders, so each tile writes straight into its own
    // part of the image.
    let pixels = frame.width as usize * frame.height as usize;
    let (mut image, mut depth, clear) = match reuse {
        Some(o) if o.image.pixels.len() == pixels && o.depth.len() == pixels => {
            let image = Image { width: frame.width, height: frame.height, ..o.image };
            (image, o.depth, true)
        }
        _ => {
            (Image::new(frame.width, frame.height, scene.clear_color), vec![1.0f32; pixels], false)
        }
    };
    let (width, tile) = (frame.width as usize, frame.tile as usize);
    let tile_stats = image
        .pixels
        .par_chunks_mut(width * tile)
        .zip(depth.par_chunks_mut(width * tile))
        .enumerate()
        .flat_map(|(row, (color, depth))| {
            let mut targets: Vec<Target<'_>> = (0..columns)
                .map(|column| Target {
                    color: Vec::with_capacity(tile),
                    depth: Vec::with_capacity(tile),
                    x0: column * frame.tile,
                    y0: row as u32 * frame.tile,
                })
                .collect();
            for (color_row, depth_row) in color.chunks_mut(width).zip(depth.chunks_mut(width)) {
                let pieces = color_row.chunks_mut(tile).zip(depth_row.chunks_mut(tile));
                for (target, (c, d)) in targets.iter_mut().zip(pieces) {
                    target.color.push(c);
                    target.depth.push(d);
                }
            }
            // The band's tiles, each a task of its own (not drawn one after another).
            targets.into_iter().map(|target| (row as u32, target)).collect::<Vec<_>>()
        })
        .map(|(row, mut target)| {
            let column = target.x0 / frame.tile;
            let rect = frame.tile_rect(column, row);
            let index = (row * columns + column) as usize;
            if clear {
                for (color, depth) in target.color.iter_mut().zip(&mut target.depth) {
                    color.fill(scene.clear_color);
                    depth.fill(1.0);
                }
            }
            draw_tile(frame, draws, buffers, chunks, bins.tile(index), rect, &mut target)
        })
        .reduce(Stats::default, |mut a, b| {
            a += b;
            a
        });
    stats += tile_stats;
    debug_assert!(image.pixels.iter().all(|c| c.is_finite()), "no NaN in the image");
    debug_assert!(depth.iter().all(|z| (0.0..=1.0).contains(z)), "depths in [0, 1]");
    // Only what this renderer can compute: the global terms need rays.
    let mut features = frame.features;
    features.reflection = false;
    features.transmission = false;
    Ok(Output { image, depth, stats, features, shading: frame.shading })
}

impl<'s, L: Lighting + ?Sized> Frame<'s, L> {
    fn new(scene: &'s Scene, options: &Options, lighting: &'s L) -> Result<Self, RenderError> {
        let (width, height) = options.size.unwrap_or((scene.width, scene.height));
        check_size(width, height)?;
        let view = scene.view_product().and_then(|v| v.matrix()).map_err(RenderError::Camera)?;
        // The scene's projection, at this image's aspect ratio.
        let projection =
            scene.projection_matrix_for(width, height).map_err(RenderError::Projection)?;
        // Camera +Z in world space is the third row of the view rotation (rows of an orthonormal
        // matrix are the camera axes); a valid view is orthonormal, so this never falls back.
        let backward = try_normalize(Vec3::new(view.x_axis.z, view.y_axis.z, view.z_axis.z))
            .unwrap_or(Vec3::Z);
        let half = Vec2::new(width as f32, height as f32) * 0.5;
        Ok(Frame {
            scene,
            lighting,
            shading: options.shading.unwrap_or(scene.shading),
            width,
            height,
            tile: options.tile_size.filter(|&t| t > 0).unwrap_or(DEFAULT_TILE_SIZE).clamp(4, 1024),
            view,
            projection,
            eye: scene.camera.eye_position(),
            backward,
            features: scene.features(),
            guard: (Vec2::splat(GUARD_BAND_PIXELS) / half).max(Vec2::ONE),
            spans: lighting.is_scene_lighting().then(|| {
                let eye = scene.camera.eye_position();
                SpanLights::new(
                    scene.light_model,
                    scene.global_ambient,
                    &scene.lights,
                    eye,
                    backward,
                )
            }),
        })
    }

    /// Tile `(column, row)`, counted from the top-left; the last column and row may be narrower.
    fn tile_rect(&self, column: u32, row: u32) -> Rect {
        let t = self.tile;
        Rect {
            x0: column * t,
            y0: row * t,
            x1: ((column + 1) * t).min(self.width),
            y1: ((row + 1) * t).min(self.height),
        }
    }

    /// The lighting stage at one point (光源処理); the colour is not clamped. The light model
    /// adds what it did to `counts` ([`Lighting::light_counted`]).
    fn light(
        &self,
        p_world: Vec3,
        n_world: Vec3,
        material: &Material,
        counts: &mut LightCounts,
    ) -> Rgb {
        let v_world = self.scene.light_model.view_vector(p_world, self.eye, self.backward);
        let point = SurfacePoint { p_world, n_world, v_world, material, shading: self.shading };
        // The renderer counts the calls (whatever the hook counts there); the light model its
        // own terms.
        let calls = counts.evaluations + 1;
        let color = self.lighting.light_counted(self.scene, &point, counts);
        counts.evaluations = calls;
        color
    }
}

impl Stats {
    /// Adds the lighting stage's counts: its calls, and the specular terms and attenuations the
    /// light model computed.
    fn add_lighting(&mut self, counts: &LightCounts) {
        self.lighting_evaluations += counts.evaluations;
        self.specular_evaluations += counts.specular;
        self.attenuation_evaluations += counts.attenuations;
    }
}

/// Every object made ready: shading normals, model matrix, material, texture.
fn prepare_draws<'s>(scene: &'s Scene, features: &Features) -> Result<Vec<Draw<'s>>, RenderError> {
    scene
        .objects
        .iter()
        .map(|object| {
            let texture = match &object.texture {
                None => None,
                Some(t) => {
                    let texture = scene.textures.get(t.texture).ok_or_else(|| {
                        RenderError::MissingTexture {
                            object: object.name.clone(),
                            texture: t.texture,
                            count: scene.textures.len(),
                        }
                    })?;
                    Some(Texturing { texture, sampler: t.sampler, env: t.env })
                }
            };
            let mut material = object.material.clone();
            if !features.specular {
                // Only what the scene needs: no light has a specular colour, so no specular work.
                material.ks = Rgb::ZERO;
            }
            Ok(Draw {
                prepared: object.prepare()?,
                material,
                lit: !matches!(texture, Some(Texturing { env: TexEnv::Replace, .. })),
                texture,
            })
        })
        .collect()
}

impl Draw<'_> {
    fn has_colors(&self) -> bool {
        self.prepared.mesh.colors.is_some()
    }
}

// ---------------------------------------------------------------------------------------------
// Vertex stage (頂点処理)

/// The vertex stage over every vertex of one object, on all cores, eight at a time
/// (`src/vertex8.rs`: model → world → view → clip, the normal, the window position and the
/// outcodes into `windows`); under Gouraud each vertex is then lit — eight at a time by the
/// scene's own light model, one by one by any other hook — and its colour clamped to `[0, 1]`,
/// as OpenGL clamps the lit vertex colour before interpolating it.
///
/// # Errors
/// [`RenderError::NonFinite`] naming the first vertex whose clip position is not finite.
fn vertex_stage<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draw: &Draw<'_>,
    vertices: &mut Vec<Vertex>,
    windows: &mut Vec<Window>,
) -> Result<Stats, RenderError> {
    let prepared = &draw.prepared;
    let mesh = &prepared.mesh;
    let n = mesh.positions.len();
    let mut stats = Stats { vertices: n as u64, ..Stats::default() };
    let t = vertex8::Transforms {
        model: prepared.model,
        normal: prepared.normal_matrix,
        mirrored: prepared.mirrored,
        view: frame.view,
        projection: frame.projection,
        width: frame.width as f32,
        height: frame.height as f32,
    };
    let (normals, colors, uvs) =
        (mesh.normals.as_deref(), mesh.colors.as_deref(), mesh.uvs.as_deref());
    vertices.resize(n, Vertex::default());
    windows.resize(n, Window { codes: (0, 0), screen: None });
    vertices.par_chunks_mut(LANES).zip(windows.par_chunks_mut(LANES)).enumerate().for_each(
        |(k, (vs, ws))| {
            let start = k * LANES;
            let (p, normal) = vertex8::gather(&mesh.positions, normals, start, vs.len());
            let mut out = vertex8::Out::default();
            vertex8::transform(&t, &p, &normal, &mut out);
            for (i, (v, w)) in vs.iter_mut().zip(ws.iter_mut()).enumerate() {
                let (color, uv) = vertex8::passed_on(colors, uvs, start + i);
                let p_clip = vertex8::lane4(&out.p_clip, i);
                *v = Vertex {
                    p_clip,
                    p_world: vertex8::lane3(&out.p_world, i),
                    n_world: vertex8::lane3(&out.n_world, i),
                    color,
                    uv,
                };
                let codes = outcodes(p_clip, frame.guard);
                // Only a vertex inside the guard-band volume is ever used unclipped.
                let screen = (codes.1 == 0 && out.in_window[i]).then_some(ScreenVertex {
                    x: out.x[i],
                    y: out.y[i],
                    z: out.z[i],
                    inv_w: out.inv_w[i],
                    slot: 0,
                });
                *w = Window { codes, screen };
            }
        },
    );
    let whole_colors = colors.is_none_or(|c| c.len() == n);
    let colored = |i: usize| colors.and_then(|c| c.get(i)).copied();
    if frame.shading == Shading::Gouraud && draw.lit {
        let counts = match frame.spans.as_ref().filter(|_| whole_colors) {
            // The scene's own light model, eight vertices at a time (the same bits).
            Some(lights) => vertices
                .par_chunks_mut(LANES)
                .fold(LightCounts::default, |mut counts, chunk| {
                    let mut points = Points { len: chunk.len(), ..Points::default() };
                    for (i, v) in chunk.iter().enumerate() {
                        points.p.set(i, v.p_world);
                        points.n.set(i, v.n_world);
                        points.color.set(i, v.color);
                    }
                    let mut lit = V3::default();
                    let (material, has) = (&draw.material, draw.has_colors());
                    span::light(lights, material, has, &points, &mut lit, &mut counts);
                    for (i, v) in chunk.iter_mut().enumerate() {
                        v.color = saturate(lit.get(i));
                    }
                    counts
                })
                .reduce(LightCounts::default, |mut a, b| {
                    a += b;
                    a
                }),
            // Any other hook, one vertex at a time.
            None => vertices
                .par_iter_mut()
                .enumerate()
                .fold(LightCounts::default, |mut counts, (i, v)| {
                    let material = draw.material.with_color(colored(i));
                    v.color = saturate(frame.light(v.p_world, v.n_world, &material, &mut counts));
                    counts
                })
                .reduce(LightCounts::default, |mut a, b| {
                    a += b;
                    a
                }),
        };
        stats.add_lighting(&counts);
    }
    if let Some(i) = vertices.iter().position(|v| !v.p_clip.is_finite()) {
        // Named as the object's own mesh numbers it (the file's V-number), not as the prepared
        // mesh does (split per face for face normals, so the file's V2 may be its V4).
        let (vertex, p_clip) = first_non_finite(frame, draw).unwrap_or((i, vertices[i].p_clip));
        return Err(RenderError::NonFinite {
            object: draw.prepared.object.name.clone(),
            vertex,
            position: p_clip.to_array(),
        });
    }
    Ok(stats)
}

/// The first vertex of the object's own mesh (numbered as its file or shape numbers it) whose
/// clip position, computed as [`vertex`] computes it, is not finite; with that position. The
/// prepared mesh's positions are copies of these, so one exists whenever a prepared vertex is
/// not finite.
fn first_non_finite<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draw: &Draw<'_>,
) -> Option<(usize, Vec4)> {
    let model = draw.prepared.model;
    draw.prepared.object.mesh.positions.iter().enumerate().find_map(|(i, &p_model)| {
        let p_view = transform_point(frame.view, transform_point(model, p_model));
        let p_clip = frame.projection * p_view.extend(1.0);
        (!p_clip.is_finite()).then_some((i, p_clip))
    })
}

// ---------------------------------------------------------------------------------------------
// Primitive stages: clip, viewport, triangle setup, flat colour, binning

/// Assembles, clips, sets up and bins the faces `faces` of object `object`.
fn primitive_stage<L: Lighting + ?Sized>(
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
struct Window {
    codes: (u8, u8),
    screen: Option<ScreenVertex>,
}

/// Which planes a clip-space point lies outside, as bits (near, far, −x, +x, −y, +y): of the
/// view volume, and of the clip volume with the guard band `guard` (in NDC units) at the sides.
fn outcodes(p: Vec4, guard: Vec2) -> (u8, u8) {
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
fn snap(v: f32) -> i32 {
    let r = v * ONE as f32;
    let i = r as i32;
    let fraction = r - i as f32;
    i + i32::from(fraction >= 0.5) - i32::from(fraction <= -0.5)
}

/// Which triangles to drop by their winding.
#[derive(Clone, Copy, Debug)]
enum Cull {
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
enum Dropped {
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
fn triangle_setup(
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
fn world_face_normal(draw: &Draw<'_>, corners: [&Vertex; 3]) -> Vec3 {
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

// ---------------------------------------------------------------------------------------------
// Per tile: rasterize, depth test, fragment

/// The pixels of one tile: its part of each of its rows of the colour and depth buffers.
struct Target<'a> {
    /// Row `y − y0` of the tile, pixels `x0..x0 + len`.
    color: Vec<&'a mut [Rgb]>,
    /// The same for the depth buffer.
    depth: Vec<&'a mut [f32]>,
    /// The image column of the tile's first pixel.
    x0: u32,
    /// The image row of the tile's first row.
    y0: u32,
}

/// Draws one tile: every triangle binned to it (`bin`: `(chunk, triangle)` pairs in submission
/// order) into `target` (the tile's pixels, cleared to the clear colour and depth 1).
fn draw_tile<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draws: &[Draw<'_>],
    buffers: &[Vec<Vertex>],
    chunks: &[Chunk],
    bin: &[(u32, u32)],
    rect: Rect,
    target: &mut Target<'_>,
) -> Stats {
    let mut stats = Stats::default();
    let mut counts = LightCounts::default();
    // Phong's fragments of the scene's own light model, lit eight at a time.
    let mut span = PhongSpan::default();
    let spans = frame.spans.as_ref().filter(|_| frame.shading == Shading::Phong);
    let flush = |span: &mut PhongSpan,
                 target: &mut Target<'_>,
                 counts: &mut LightCounts,
                 stats: &mut Stats| {
        if let Some(lights) = spans {
            let draw = &draws[span.object];
            let texture = draw.texture.map(|t| span::Texturing {
                texture: t.texture,
                sampler: t.sampler,
                env: t.env,
            });
            // The face normal where the corners' normals cancel, from the face's own corners.
            let vertices = &buffers[span.object];
            let face = |face: u32| {
                let face = draw.prepared.mesh.faces[face as usize];
                world_face_normal(draw, face.map(|i| &vertices[i as usize]))
            };
            let (material, colored) = (&draw.material, draw.has_colors());
            stats.texture_samples +=
                span.flush(lights, material, colored, texture, counts, face, |row, column, c| {
                    target.color[row as usize][column as usize] = c;
                });
        }
    };
    for &(c, t) in bin {
        let chunk = &chunks[c as usize];
        let draw = &draws[chunk.object];
        if span.object != chunk.object {
            flush(&mut span, target, &mut counts, &mut stats);
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
        let inv_area = 1.0 / triangle.edges.area2 as f32;
        let z = Vec3::from(triangle.z);
        // Phong with the scene's own light model: the fragment is queued for its span, and its
        // triangle made as the span needs it when its first fragment passes (many small
        // triangles have none). Otherwise the fragment stage runs here.
        let spanned = spans.is_some() && draw.lit;
        let corners_now = (!spanned).then(|| corners(triangle));
        let mut lane_triangle = None;
        span.end_triangle();
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
            if let Some(corners) = &corners_now {
                target.color[row][column] =
                    fragment(frame, draw, triangle, corners, b, &mut stats, &mut counts);
                return;
            }
            if !span.has_triangle() {
                let t = *lane_triangle.get_or_insert_with(|| {
                    let corners = corners(triangle);
                    let corners = corners.map(|v| (v.p_world, v.n_world, v.color, v.uv));
                    span::Triangle::new(triangle.inv_w, corners, triangle.face)
                });
                span.begin(t);
            }
            if span.push((row as u32, column as u32), b) {
                flush(&mut span, target, &mut counts, &mut stats);
            }
        });
    }
    flush(&mut span, target, &mut counts, &mut stats);
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
fn rasterize(edges: &Edges, rect: Rect, mut emit: impl FnMut(u32, u32, [i64; 3])) {
    let [bx0, by0, bx1, by1] = edges.bbox;
    let (x0, y0) = (bx0.max(rect.x0), by0.max(rect.y0));
    let (x1, y1) = (bx1.min(rect.x1.saturating_sub(1)), by1.min(rect.y1.saturating_sub(1)));
    if x0 > x1 || y0 > y1 {
        return;
    }
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

/// The depth test (隠面消去, Z バッファ法): GL_LESS against the buffer cleared to 1; on a pass the
/// depth is written. It runs before the fragment stage (early depth test, as GPUs do when a
/// fragment cannot be discarded): the same image, without shading hidden fragments.
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
