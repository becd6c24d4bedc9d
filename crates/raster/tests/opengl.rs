//! The rasterizer against OpenGL itself: Mesa's fixed-function pipeline through OSMesa
//! (`cg-glref`) draws the same scenes, and at least 99 % of the pixels must agree within 2/255 per
//! channel. Gouraud shading (OpenGL's GL_SMOOTH); the conventions matched are listed in the
//! crate docs (pixel centres, the fill rule in GL's y-up window, vertex colours clamped before
//! interpolation, perspective-correct colours, rounding to 8 bits).
//!
//! Each test returns early, with a note, where OSMesa or a C compiler is missing (and fails under
//! CI): see `cg_glref::require`.

mod common;

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::mesh::Mesh;
use cg_core::scene::Shading;
use cg_raster::{Options, render};
use cg_testkit::images::{Tolerance, assert_images_match};
use common::{looking_down_z, object, unlit};

fn assert_matches_opengl(file: &str) {
    let scene = common::load(file);
    let expected = cg_glref::render(&scene).unwrap_or_else(|e| panic!("{file}: OpenGL: {e}"));
    let out =
        render(&scene, &Options { shading: Some(Shading::Gouraud), ..Options::default() }).unwrap();
    let name = format!("opengl-{}", file.trim_end_matches(".toml"));
    let c = assert_images_match(
        &name,
        &out.image.to_rgba8(),
        &expected.to_rgba8(),
        scene.width,
        scene.height,
        Tolerance::percent_within(99.0, 2),
    );
    eprintln!(
        "{file}: {} of {} pixels differ by more than 2/255 ({:.3} %), max {}/255, mean {:.4}/255",
        c.pixels_over,
        scene.width * scene.height,
        100.0 * c.fraction_over,
        c.max_diff,
        c.mean_diff
    );
}

#[test]
fn the_course_sample_looks_as_opengl_draws_it() {
    if !cg_glref::require() {
        return;
    }
    assert_matches_opengl("course-sample.toml");
}

#[test]
fn the_spot_light_and_the_highlight_look_as_opengl_draws_them() {
    if !cg_glref::require() {
        return;
    }
    assert_matches_opengl("spot-specular.toml");
}

#[test]
fn pixels_on_edges_are_filled_as_opengl_fills_them() {
    if !cg_glref::require() {
        return;
    }
    // Quads whose four sides run exactly through pixel centres (coordinates that the projection
    // maps to half-integer window coordinates without rounding), split along either diagonal,
    // and a triangle with a horizontal, a vertical and a diagonal side on centres: which of the
    // centres on the sides are filled is the fill rule alone. Pixel-exact.
    let (w, h) = (16u32, 16u32);
    let mut scene = looking_down_z(w, h, 90.0);
    // At z = −2 with a 90° field of view, window x = (1 + x/2)·8: x = −0.875 ↦ 4.5.
    let at = |px: f32, py: f32| Vec3::new((px / 8.0 - 1.0) * 2.0, (1.0 - py / 8.0) * 2.0, -2.0);
    let quad = |x0: f32, y0: f32, x1: f32, y1: f32, flip: bool| {
        let faces = if flip { vec![[0, 1, 3], [1, 2, 3]] } else { vec![[0, 1, 2], [0, 2, 3]] };
        // Counter-clockwise as seen (y up): bottom-left, bottom-right, top-right, top-left.
        Mesh::new(vec![at(x0, y1), at(x1, y1), at(x1, y0), at(x0, y0)], faces)
    };
    scene.objects.push(object(
        "quad",
        quad(2.5, 1.5, 7.5, 6.5, false),
        unlit(Rgb::new(1.0, 0.0, 0.0)),
    ));
    scene.objects.push(object(
        "flipped",
        quad(9.5, 2.5, 13.5, 7.5, true),
        unlit(Rgb::new(0.0, 1.0, 0.0)),
    ));
    let corner = Mesh::new(vec![at(3.5, 14.5), at(11.5, 14.5), at(3.5, 9.5)], vec![[0, 1, 2]]);
    scene.objects.push(object("triangle", corner, unlit(Rgb::new(0.0, 0.0, 1.0))));
    let expected = cg_glref::render(&scene).unwrap();
    let out = render(&scene, &Options::default()).unwrap();
    assert_images_match(
        "opengl-fill-rule",
        &out.image.to_rgba8(),
        &expected.to_rgba8(),
        w,
        h,
        Tolerance::all_within(0),
    );
}
