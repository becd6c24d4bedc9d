//! Reference images: the course's sample scene at 160 × 160 in flat, Gouraud and Phong shading,
//! against committed PNGs (created once with `CG_BLESS=1` and looked at). The rasterizer is
//! deterministic, so the tolerance is 1/255 per channel on every pixel (room for a compiler's
//! different rounding of the same f32 expressions, nothing more).

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
