//! Reference images: the course's sample scene at 160 × 160 in flat, Gouraud and Phong shading,
//! against committed PNGs. The rasterizer is deterministic, so the tolerance is 1/255 per channel
//! on every pixel (room for a compiler's different rounding of the same f32 expressions, nothing
//! more).
//!
//! The PNGs were made by the rasterizer itself (`CG_BLESS=1`); how each was checked:
//!
//! - `course-sample-gouraud.png`: against OpenGL — `tests/opengl.rs`
//!   (`the_committed_gouraud_reference_is_what_opengl_draws`) compares the committed file with
//!   Mesa's image of the scene at 160 × 160 (every pixel within 2/255, at most 2 beyond 1/255),
//!   so it is not only the program's word. Looked at: the blue-grey sky (0.5, 0.5, 0.8), the
//!   green ground square seen from above at 30°, brighter towards the light at (10, 10, 10)
//!   (front right) in a smooth gradient, and the orange pyramid on it with its lit front-right
//!   face brighter than its left face.
//! - `course-sample-flat.png`: against OpenGL — `tests/opengl.rs`
//!   (`the_committed_flat_reference_is_what_opengl_draws`) compares it with Mesa's GL_FLAT image
//!   at 160 × 160, with the Gouraud reference's tolerance. The scene is in OpenGL's light model,
//!   so each triangle has the colour lit at its last (provoking) vertex, as GL_FLAT gives it.
//!   Looked at: the same picture as the Gouraud one, but in flat shades — the ground's cells
//!   stepping brighter towards the light (the two triangles of a cell are lit at different
//!   corners, so they may differ by a shade), each pyramid face one colour.
//! - `course-sample-phong.png`: looked at — indistinguishable by eye from the Gouraud image (the
//!   course's materials have no specular term and the ground's normal is constant, so Phong and
//!   Gouraud differ only by the diffuse term's curvature across each triangle). Per-pixel
//!   lighting itself is checked analytically in `tests/shading.rs`, and against the ray tracer
//!   in `cg-trace`'s `tests/raster.rs`.

mod common;

use std::path::Path;

use cg_core::scene::Shading;
use cg_raster::{Options, render};
use cg_testkit::images::{Tolerance, assert_matches_reference};

fn assert_course_sample(shading: Shading, file: &str) {
    let scene = common::load("course-sample.toml");
    let out = render(
        &scene,
        &Options { shading: Some(shading), size: Some((160, 160)), ..Options::default() },
    )
    .unwrap();
    let reference = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reference").join(file);
    assert_matches_reference(&reference, &out.image.to_rgba8(), 160, 160, Tolerance::all_within(1));
}

#[test]
fn course_sample_flat() {
    assert_course_sample(Shading::Flat, "course-sample-flat.png");
}

#[test]
fn course_sample_gouraud() {
    assert_course_sample(Shading::Gouraud, "course-sample-gouraud.png");
}

#[test]
fn course_sample_phong() {
    assert_course_sample(Shading::Phong, "course-sample-phong.png");
}
