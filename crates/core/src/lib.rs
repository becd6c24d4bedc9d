//! # cg-core — the lecture's mathematics, with no GPU or window
//!
//! Everything lecture 11 (シェーディング) and the course's sample program define, as plain
//! functions and data: transforms and the matrix stack, the orbit camera, meshes and their
//! validation, face and vertex normals, the light model (環境光・拡散反射光・鏡面反射光), optics
//! (reflection, refraction, Fresnel), textures and the in-memory scene.
//!
//! The one file reader here is [`text::read`]: a student's text (report, table, scene) in the
//! encodings their editors write, bounded in size. Loading files (TOML scenes, OBJ, PNG) lives
//! beside this crate in `cg-scene`; renderers, assignments and the command line build on both.
//!
//! ## Conventions (written once, used everywhere)
//!
//! | what | convention |
//! |---|---|
//! | handedness | right-handed, as OpenGL |
//! | up axis | +Y |
//! | front faces | counter-clockwise seen from outside (the normal is `(b−a)×(c−a)`) |
//! | matrices | glam's column-major [`glam::Mat4`]; `m * v` transforms a column vector; printed by rows |
//! | composition | `proj * view * model`; a [`product::MatrixProduct`] lists factors in glTranslatef/glRotatef call order |
//! | depth range | `[0, 1]` for wgpu ([`transform::perspective`]); `[-1, 1]` in [`transform::perspective_gl`] |
//! | angles | degrees in every user-facing text and in functions named `*_deg`; radians elsewhere |
//! | colours | linear RGB in `[0, 1]` as [`glam::Vec3`] ([`Rgb`]); renderers clamp at the end like OpenGL |
//! | texture coordinates | `(0, 0)` is the image's bottom-left corner, as in OpenGL |
//!
//! ## Numerical promises
//!
//! Fragile operations have fallible siblings that return `None`/`Err` instead of NaN:
//! [`math::try_normalize`], [`normals::face_normal`], [`transform::perspective`],
//! [`transform::look_at`], [`optics::refract`]. The hard cases of the kit's docs/numerics.md are named
//! tests in `crates/core/tests/`.
//!
//! ## Meshes that move
//!
//! For a mesh whose faces stay fixed while its positions change every frame (an animation, a
//! deforming model), [`normals::NormalsPlan`] is made once from the faces and gives each
//! frame's area-weighted vertex normals into a reused output, bit for bit
//! [`normals::vertex_normals_reference`]:
//!
//! ```
//! use cg_core::normals::{NormalsPlan, VertexNormals};
//!
//! let mut mesh = cg_core::shapes::icosphere(1.0, 2).unwrap();
//! let mut plan = NormalsPlan::for_mesh(&mesh).unwrap(); // once
//! let mut normals = VertexNormals::default();
//! for frame in 0..3 {
//!     mesh.positions.iter_mut().for_each(|p| p.x *= 1.0 + 0.1 * frame as f32);
//!     plan.area_normals_into(&mesh.positions, &mut normals).unwrap(); // each frame
//!     assert_eq!(normals.normals.len(), mesh.positions.len());
//! }
//! ```

pub mod camera;
pub mod features;
pub mod fs;
pub mod gl;
pub mod image;
pub mod lang;
pub mod light;
pub mod math;
pub mod mesh;
pub mod normals;
pub mod notation;
pub mod optics;
pub mod product;
pub mod quote;
pub mod scene;
pub mod shapes;
pub mod stack;
pub mod student;
pub mod text;
pub mod texture;
pub mod time;
pub mod toml_syntax;
pub mod transform;

pub use glam;

/// A linear RGB colour (or RGB reflectance such as k_a, k_d, k_s), each channel nominally in `[0, 1]`.
pub type Rgb = glam::Vec3;
