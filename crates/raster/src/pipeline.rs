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
//!                             bottom edges as the image is displayed); a triangle 8 pixels
//!                             wide or more in runs of 8 or 16 pixels of a row (`cover`)
//!            depth_test       GL_LESS against the tile's depth buffer, then the depth write
//!            fragment         perspective-correct attributes; Phong lights here, 16 at a
//!                             time with the scene's own light model (`span.rs`); texture
//! ```
//!
//! Each tile is drawn by one thread from start to end, its triangles in the order they were
//! submitted, so the image is the same bits whatever the thread count or the tile size.
//!
//! This file holds what every stage reads and the draw call; the stages are in `pipeline/`:
//! `vertex.rs`, `primitive.rs` (clip to bin), `tile.rs` (rasterize to fragment) and `cover.rs`
//! (rasterize and depth-test a run of a row's pixels at once).
//!
//! Spaces and names: `p_model`, `p_world` (lighting happens here), `p_view`, `p_clip` (homogeneous,
//! `[0, 1]` depth), `p_ndc`, `p_screen` (window: pixels, x right, y *down* from the image's top-left
//! corner, pixel `(x, y)` centred at `(x + ½, y + ½)`, depth in `[0, 1]`).

use cg_core::Rgb;
use cg_core::features::Features;
use cg_core::glam::{Mat4, Vec2, Vec3, Vec4};
use cg_core::image::{Image, check_size};
use cg_core::light::{LightCounts, Material};
use cg_core::math::try_normalize;
use cg_core::scene::{Prepared, Scene, Shading};
use cg_core::texture::TexEnv;
use rayon::prelude::*;
use std::sync::Mutex;

use crate::error::RenderError;
use crate::lighting::{Lighting, SurfacePoint};
use crate::output::{DEFAULT_TILE_SIZE, Options, Output, Stats};
use crate::span::{self, LANES, PhongSpan, Points, SpanLights, Texturing, V3, saturate};
use crate::vertex_lanes;

mod cover;
mod primitive;
mod tile;
mod vertex;

use primitive::{Cull, Window, outcodes, primitive_stage, snap, triangle_setup, world_face_normal};
pub(crate) use tile::coverage;
use tile::{Target, draw_tile};
use vertex::vertex_stage;

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
    /// The scene's lights made ready for lighting sixteen points at once, when `lighting` is the
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
    /// Phong: the face normal in world space, the fallback of
    /// [`cg_core::normals::interpolate_normal`] (zero under the other modes, which do not read
    /// it, and when the scene's own light model lights the fragments sixteen at a time: that path
    /// makes it only where it is needed).
    face_normal: Vec3,
    /// Flat: the face's colour, clamped to `[0, 1]`.
    flat_color: Rgb,
    /// The face it is (a part of), in its object's prepared mesh.
    face: u32,
    /// The integer shift taken off the face's texture coordinates before they are interpolated
    /// ([`cg_core::texture::Sampler::repeat_origin`] of its first corner; zero without a
    /// texture): vertices made by clipping hold shifted coordinates already, the others are
    /// shifted when the triangle is drawn (docs/numerics.md row 23).
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
    let clear_row = (vec![scene.clear_color; tile], vec![1.0f32; tile]);
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
        .map_init(PhongSpan::default, |span, (row, mut target)| {
            let column = target.x0 / frame.tile;
            let rect = frame.tile_rect(column, row);
            let index = (row * columns + column) as usize;
            if clear {
                // Copied from a cleared row (one memcpy each) rather than filled pixel by pixel.
                for (color, depth) in target.color.iter_mut().zip(&mut target.depth) {
                    color.copy_from_slice(&clear_row.0[..color.len()]);
                    depth.copy_from_slice(&clear_row.1[..depth.len()]);
                }
            }
            draw_tile(frame, draws, buffers, chunks, bins.tile(index), rect, &mut target, span)
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
