//! # cg-raster — the kit's CPU rasterizer, the renderer the tests trust
//!
//! Draws a [`cg_core::scene::Scene`] as OpenGL 1.x would (the course's sample program), on the
//! CPU, on all cores, deterministically: flat, Gouraud and Phong shading
//! (フラット／グロー／フォンシェーディング), a z-buffer, clipping at the near plane, OpenGL's fill
//! rule, perspective-correct attributes, textures, back-face culling.
//!
//! **Fill rule.** A pixel whose centre is exactly on an edge belongs to the triangle when the
//! edge is a left edge or a bottom edge as the image is displayed — what Mesa's llvmpipe does
//! (OpenGL's top-left rule in its y-up window coordinates). So a pixel on an edge shared by two
//! triangles is drawn exactly once, and none is missed (docs/numerics.md row 22).
//!
//! ```
//! use cg_core::lang::Lang;
//! use cg_raster::{Options, render};
//!
//! let scene = cg_scene::load(std::path::Path::new("../../assets/scenes/course-sample.toml")).unwrap();
//! let out = render(&scene, &Options { size: Some((64, 64)), ..Options::default() }).unwrap();
//! assert_eq!(out.image.width, 64);
//! assert_eq!(out.stats.specular_evaluations, 0); // every k_s is 0: no specular work
//! println!("{}", out.features.describe(Lang::Ja));
//! ```
//!
//! ## The pipeline
//!
//! The stages are one function each, in `src/pipeline.rs` and `src/pipeline/` (`vertex.rs`,
//! `primitive.rs`, `tile.rs`), named as a GPU's:
//!
//! | stage | what it does |
//! |---|---|
//! | `vertex` | model → world (normals by the cofactor normal matrix, normalised, flipped back for mirrored objects) → view → clip (`[0, 1]` depth); Gouraud lights each vertex here |
//! | `clip` | Sutherland–Hodgman in homogeneous clip space against the near plane `z ≥ 0`, the far plane and a guard band ±2²⁰ pixels wide; attributes linear in clip space; never a division by `w ≤ 0` |
//! | `viewport` | perspective divide; window x right, y down from the top-left corner, pixel centres at `(x + ½, y + ½)`, depth `[0, 1]`; coordinates snapped to **1/256 pixel** (8 sub-pixel bits) |
//! | `triangle_setup` | back-face culling by the sign of the window-space area (counter-clockwise in OpenGL's y-up window = front; the other way for mirrored objects), bounding box |
//! | `flat_color` | flat shading: one lighting evaluation per face — in the lecture's light model at its **centroid** with the face normal; in OpenGL's model as GL_FLAT, at its **provoking vertex** (the last corner) with that vertex's normal, position and colour |
//! | `bin` | each triangle into the tiles (32 × 32 pixels) its bounding box touches, as `(tile, triangle)` pairs gathered into one list per tile (memory proportional to the pairs); each tile is one task for a thread |
//! | `rasterize` | exact integer edge functions and the fill rule above |
//! | `depth_test` | GL_LESS against a depth buffer cleared to 1, then the write (early: before shading; the same image) |
//! | `fragment` | perspective-correct barycentrics for colour, normal, position and uv (uv less the integer [`cg_core::texture::Sampler::repeat_origin`] of the face's first corner, so coordinates near 1e6 keep their precision: docs/numerics.md row 23); Phong lights each pixel here; texture after lighting ([`cg_core::texture::TexEnv::apply`]); clamp to `[0, 1]` |
//!
//! The vertex stage also computes each vertex's outcodes and window position once, so a face
//! whose corners are all inside is culled from three precomputed records, before its vertices
//! are read. With the scene's own light model ([`SceneLighting`]) the lighting stage runs in
//! spans of sixteen points — Gouraud's vertices, Phong's fragments in the order they pass the
//! depth test — in structure-of-arrays form (`src/span.rs`, a copy compiled for AVX2 chosen at
//! run time), operation for operation what [`cg_core::light::shade`] computes: the same bits
//! (`tests/spans.rs` compares with the point-by-point path on every kind of light). Where the
//! CPU has AVX2, two loops are written out in its registers (with pulp, as cg-core's normals):
//! rasterizing and depth-testing a run of eight or sixteen pixels with flat and Gouraud colours
//! (`src/pipeline/cover/v3.rs`), and a span of certified triangles lit by plain lights, the
//! course scene's case (`src/span/v3.rs`); each is tested bit for bit against the compiler's
//! copy of the same loop. A
//! [`Prepared`] scene keeps its working memory between frames, and
//! [`Prepared::draw_into`] redraws into the last frame's buffers.
//!
//! Triangles are set up once and binned; each tile is drawn by one task from start to end, its
//! triangles in submission order, so the output is bit-identical for every thread count and tile
//! size (a 160 × 160 image is 25 tasks of 32 × 32).
//!
//! An image has at most [`cg_core::image::MAX_SIDE`] pixels a side and
//! [`cg_core::image::MAX_PIXELS`] (64 M) in all: the colour buffer (12 bytes a pixel) and the
//! depth buffer (4) of the largest image take 1 GB.
//!
//! ## Shading and lighting
//!
//! Lighting happens in world space through the [`Lighting`] hook; the default,
//! [`SceneLighting`], is the scene's light model by [`cg_core::light::shade`], with V from
//! [`cg_core::light::LightModel::view_vector`] (the infinite viewer's V is the camera's +Z).
//! Colours are clamped where OpenGL clamps them: the lit colour per vertex (Gouraud), per face
//! (flat) or per pixel (Phong), and the final colour. With per-vertex colours in the mesh,
//! k_a = k_d = the colour (glColor under GL_COLOR_MATERIAL).
//!
//! ## As OpenGL draws it
//!
//! The conventions follow what Mesa's OpenGL (llvmpipe, through `cg-glref`) does, so the
//! course's scenes come out as OpenGL draws them, in Gouraud (GL_SMOOTH) and flat (GL_FLAT)
//! shading (`tests/opengl.rs`: at least 99.99 % of the pixels within 1/255, and all but 0.005 %
//! — pixel centres within rounding of an edge or a texel border — within 2/255; measured on
//! course-sample and spot-specular, smooth and flat: every pixel within 1/255): pixel centres at
//! half-integers; 8 sub-pixel bits; the fill rule above (pixel-exact
//! against OpenGL on edges through pixel centres); lit vertex colours clamped to `[0, 1]` before
//! they are interpolated; colours and texture coordinates interpolated perspective-correctly;
//! GL_LESS (of two equal depths the first drawn stays); GL_MODULATE on
//! the whole lit colour; 8-bit output by [`cg_core::image::to_unorm8`] (OpenGL rounds exact
//! halves to even, the kit up: they differ on exact ties only); GL_FLAT's rule in OpenGL's light
//! model: a flat face has the colour lit at its provoking vertex, the last of its three corners
//! (each face is one GL_TRIANGLES triangle in `cg-glref`), with that vertex's normal and colour —
//! the same evaluation Gouraud makes there — so flat shading matches OpenGL as closely as Gouraud
//! does. One documented difference: lighting happens in world space (OpenGL's eye space gives
//! the same colours up to rounding, for a rigid view).
//!
//! The lecture's light model keeps the lecture's flat shading: one evaluation at the face's
//! centroid with the face normal ("面の法線をもとに面の色を決定"), every corner treated alike.
//!
//! ## Only what the scene needs
//!
//! [`Scene::features`](cg_core::scene::Scene::features) decides what is computed: no specular
//! term when no light or no material has one (k_s is passed as 0), no texture sampling for
//! untextured objects, no lighting under GL_REPLACE. [`Output::stats`] counts what each stage
//! did — the specular terms and attenuations as the light model computes them
//! ([`cg_core::light::LightCounts`], counted inside
//! [`cg_core::light::shade_with_visibility_counted`]), not as predicted; [`Output::features`]
//! says what was enabled (never reflection or transmission: they need rays).

mod error;
mod lighting;
mod output;
mod pipeline;
#[cfg(target_arch = "x86_64")]
mod simd;
mod span;
mod vertex_lanes;

use cg_core::glam::Vec2;
use cg_core::scene::Scene;

pub use error::RenderError;
pub use lighting::{Lighting, SceneLighting, SurfacePoint};
pub use output::{DEFAULT_TILE_SIZE, MAX_SIZE, Options, Output, Stats};
pub use pipeline::{GUARD_BAND_PIXELS, SUBPIXEL_BITS};

/// Renders `scene` with its own light model ([`SceneLighting`]).
///
/// # Errors
/// A [`RenderError`] for a zero or too large image size, an invalid camera or projection, an
/// object that cannot be prepared (transform, normals, mesh), a missing texture, or a vertex
/// whose transformed position is not finite. Nothing in the scene makes it panic.
///
/// See also [`render_with`].
pub fn render(scene: &Scene, options: &Options) -> Result<Output, RenderError> {
    render_with(scene, options, &SceneLighting)
}

/// Renders `scene`, lighting every point with `lighting` (the hook of the shading exercises):
/// the same pipeline as [`render`], which is `render_with(scene, options, &SceneLighting)`.
///
/// # Errors
/// As [`render`], and [`RenderError::Threads`] when `options.threads` threads cannot be started.
pub fn render_with<L: Lighting + ?Sized>(
    scene: &Scene,
    options: &Options,
    lighting: &L,
) -> Result<Output, RenderError> {
    Prepared::new(scene, options, lighting)?.draw()
}

/// A scene made ready to draw once — the frame fixed and every object prepared (shading normals,
/// model matrix, material, texture) — and drawn as often as needed, as a window redraws: each
/// [`Prepared::draw`] runs the pipeline from the vertex stage on and gives the image
/// [`render_with`] gives.
///
/// ```
/// use cg_raster::{Options, Prepared, SceneLighting};
///
/// let scene = cg_scene::load(std::path::Path::new("../../assets/scenes/course-sample.toml")).unwrap();
/// let options = Options { size: Some((64, 64)), ..Options::default() };
/// let ready = Prepared::new(&scene, &options, &SceneLighting).unwrap();
/// let first = ready.draw().unwrap();
/// assert_eq!(first, cg_raster::render(&scene, &options).unwrap());
/// assert_eq!(first, ready.draw().unwrap());
/// // Again into the first frame's buffers, as a window redraws.
/// assert_eq!(ready.draw_into(first.clone()).unwrap(), first);
/// ```
pub struct Prepared<'s, L: Lighting + ?Sized> {
    ready: pipeline::Ready<'s, L>,
    pool: Option<rayon::ThreadPool>,
}

impl<'s, L: Lighting + ?Sized> Prepared<'s, L> {
    /// Makes `scene` ready to draw with `options`, lit by `lighting`.
    ///
    /// # Errors
    /// As [`render_with`], for everything but a non-finite vertex (found when drawing).
    pub fn new(scene: &'s Scene, options: &Options, lighting: &'s L) -> Result<Self, RenderError> {
        let pool = match options.threads {
            None | Some(0) => None,
            Some(threads) => Some(
                rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .map_err(|e| RenderError::Threads { threads, message: e.to_string() })?,
            ),
        };
        Ok(Prepared { ready: pipeline::Ready::new(scene, options, lighting)?, pool })
    }

    /// Draws the prepared scene.
    ///
    /// # Errors
    /// [`RenderError::NonFinite`] naming the first vertex whose transformed position is not
    /// finite.
    pub fn draw(&self) -> Result<Output, RenderError> {
        self.draw_reusing(None)
    }

    /// [`Prepared::draw`] into the colour and depth buffers of an earlier frame's `output`,
    /// as a window redraws into its framebuffer: the same image, without allocating (and, for a
    /// large image, without the operating system clearing fresh pages) on every frame. Buffers
    /// of another size are replaced.
    ///
    /// # Errors
    /// As [`Prepared::draw`].
    pub fn draw_into(&self, output: Output) -> Result<Output, RenderError> {
        self.draw_reusing(Some(output))
    }

    fn draw_reusing(&self, reuse: Option<Output>) -> Result<Output, RenderError> {
        match &self.pool {
            None => self.ready.draw(reuse),
            Some(pool) => pool.install(|| self.ready.draw(reuse)),
        }
    }
}

/// The rasterizer alone, for coverage tests: how many of `triangles` cover each pixel of a
/// `width × height` raster (row by row from the top), through the renderer's own sub-pixel
/// snapping, triangle setup, tiling (`tile` × `tile` pixels) and fill rule. Triangles are in
/// window coordinates — pixels, x right, y down from the top-left corner, pixel `(x, y)`
/// centred at `(x + ½, y + ½)` — of either winding (nothing is culled); zero-area ones cover
/// nothing, and parts outside the raster are cut off.
///
/// With the fill rule — a pixel whose centre is exactly on an edge belongs to the triangle when
/// the edge is a left edge or a bottom edge as the image is displayed — triangles that tile a
/// region cover each pixel centre of its interior exactly once, and a centre on the region's own
/// border when the border there is a left or a bottom edge.
///
/// # Errors
/// A size the renderer refuses ([`RenderError::ZeroSize`], [`RenderError::TooLarge`],
/// [`RenderError::TooManyPixels`]); [`RenderError::OutsideGuardBand`] naming the first corner that
/// is not finite or lies beyond ±[`GUARD_BAND_PIXELS`] (the renderer clips to that band before it
/// rasterizes; beyond it the fixed-point coordinates would overflow).
pub fn coverage(
    width: u32,
    height: u32,
    tile: u32,
    triangles: &[[Vec2; 3]],
) -> Result<Vec<u32>, RenderError> {
    pipeline::coverage(width, height, tile, triangles)
}
