//! The fixed parts of OpenGL's pipeline as the reference drives them: the clear colour, back-face
//! culling (also under a mirroring model matrix), the depth test and texture orientation.

mod common;

use cg_core::Rgb;
use cg_core::glam::{Vec2, Vec3};
use cg_core::light::{Light, LightKind, Material};
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{Scene, TextureUse};
use cg_core::texture::{Filter, Sampler, TexEnv, Texture, Wrap};
use common::*;

fn pixel_at(scene: &Scene, pixels: &[[u8; 3]], p_world: Vec3) -> [u8; 3] {
    let s = project(scene, p_world);
    pixels[s.y as usize * scene.width as usize + s.x as usize]
}

#[test]
fn the_background_is_the_clear_colour_as_gl_rounds_it() {
    if !cg_glref::require() {
        return;
    }
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../assets/scenes/course-sample.toml");
    let mut s = cg_scene::load(std::path::Path::new(path)).unwrap();
    s.objects.clear();
    (s.width, s.height) = (40, 30);
    let pixels = render_rgb(&s);
    // glClearColor(0.5, 0.5, 0.8): 0.5·255 = 127.5 → 128, 0.8·255 = 204.
    for (i, p) in pixels.iter().enumerate() {
        assert_eq!(*p, BACKGROUND, "pixel ({}, {})", i % 40, i / 40);
    }
}

#[test]
fn a_back_facing_triangle_draws_nothing_when_culling_is_on() {
    if !cg_glref::require() {
        return;
    }
    let red = Rgb::new(1.0, 0.0, 0.0);
    let (a, b, c) =
        (Vec3::new(-1.0, -1.0, 0.0), Vec3::new(1.0, -1.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
    let mut s = scene(32, 32, look_at_origin(Vec3::new(0.0, 0.0, 5.0)));
    let draw = |s: &mut Scene, mesh, cull| {
        s.cull_back_faces = cull;
        s.objects = vec![object("t", mesh, emissive(red), MatrixProduct::identity())];
        let pixels = render_rgb(s);
        let lit = pixels.iter().filter(|&&p| p == [255, 0, 0]).count();
        let other = pixels.iter().filter(|&&p| p != [255, 0, 0] && p != BACKGROUND).count();
        assert_eq!(other, 0, "only red and the background may appear");
        (lit, ascii(&pixels, 32, |p| if p == BACKGROUND { '.' } else { '#' }))
    };
    // Counter-clockwise as the camera sees it: the front.
    let (front, _) = draw(&mut s, triangle(a, b, c), true);
    assert!(front > 50, "the front-facing triangle must be drawn ({front} pixels)");
    // The same triangle clockwise: its back faces the camera.
    let (back, art) = draw(&mut s, triangle(a, c, b), true);
    assert_eq!(back, 0, "a back-facing triangle was drawn with culling on:\n{art}");
    let (unculled, _) = draw(&mut s, triangle(a, c, b), false);
    assert_eq!(unculled, front, "with culling off, the back face covers the same pixels");
}

#[test]
fn a_mirrored_object_keeps_its_outside_as_the_front_and_its_normals_outwards() {
    if !cg_glref::require() {
        return;
    }
    // A triangle facing +Z, mirrored by S(-1, 1, 1): on screen its corners run clockwise, yet it
    // is the same surface with the same outside (+Z), lit by a light from +Z.
    let (a, b, c) =
        (Vec3::new(-1.0, -1.0, 0.0), Vec3::new(1.5, -1.0, 0.0), Vec3::new(0.0, 1.0, 0.0));
    let mut s = scene(32, 32, look_at_origin(Vec3::new(0.0, 0.0, 5.0)));
    let kd = Rgb::new(0.25, 0.5, 0.75);
    s.lights = vec![Light {
        kind: LightKind::Directional { to_light: Vec3::Z },
        ambient: Rgb::ZERO,
        diffuse: Rgb::ONE,
        specular: Rgb::ZERO,
        attenuation: Default::default(),
    }];
    let material = Material { ka: Rgb::ZERO, kd, ..Material::default() };
    let mirror = MatrixProduct::identity().then(Factor::scale(Vec3::new(-1.0, 1.0, 1.0)));
    s.objects = vec![object("mirrored", triangle(a, b, c), material, mirror)];
    let pixels = render_rgb(&s);
    // N·L = 1: the colour is kd exactly (0.25·255 = 63.75 → 64, 0.5·255 → 128 (127.5), 191.25 → 191).
    let centre = pixel_at(&s, &pixels, Vec3::new(-0.15, -0.3, 0.0));
    assert!(
        channel_diff(centre, [64, 128, 191]) <= 1,
        "the mirrored triangle shows {centre:?}, expected kd = [64, 128, 191] (lit from the front):\n{}",
        ascii(&pixels, 32, |p| if p == BACKGROUND { '.' } else { '#' })
    );
}

#[test]
fn the_nearer_of_two_overlapping_triangles_wins_whatever_the_drawing_order() {
    if !cg_glref::require() {
        return;
    }
    let (red, green) = ([255, 0, 0], [0, 255, 0]);
    let near_square = object(
        "near",
        quad(0.6),
        emissive(Rgb::X),
        MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, 0.0, 0.5))),
    );
    let far_square = object(
        "far",
        quad(1.5),
        emissive(Rgb::Y),
        MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, 0.0, -0.5))),
    );
    let mut s = scene(40, 40, look_at_origin(Vec3::new(0.0, 0.0, 6.0)));
    for near_first in [true, false] {
        s.objects = if near_first {
            vec![near_square.clone(), far_square.clone()]
        } else {
            vec![far_square.clone(), near_square.clone()]
        };
        let pixels = render_rgb(&s);
        let order = if near_first { "near drawn first" } else { "far drawn first" };
        let art = || {
            ascii(&pixels, 40, |p| match p {
                [255, 0, 0] => 'N',
                [0, 255, 0] => 'F',
                _ => '.',
            })
        };
        assert_eq!(
            pixel_at(&s, &pixels, Vec3::new(0.0, 0.0, 0.5)),
            red,
            "{order}: centre\n{}",
            art()
        );
        assert_eq!(pixel_at(&s, &pixels, Vec3::new(0.3, -0.4, 0.5)), red, "{order}\n{}", art());
        assert_eq!(pixel_at(&s, &pixels, Vec3::new(1.2, 1.1, -0.5)), green, "{order}\n{}", art());
        assert_eq!(pixel_at(&s, &pixels, Vec3::new(-1.2, 0.0, -0.5)), green, "{order}\n{}", art());
    }
}

/// A 4×4 texture whose texel `(i, j)` (j = 0 the bottom row) is `(40 + 60i, 40 + 60j, 200)`.
fn coordinate_texture() -> Texture {
    Texture::from_fn(4, 4, |i, j| [40 + 60 * i as u8, 40 + 60 * j as u8, 200, 255]).unwrap()
}

/// A 2×2 square facing the camera, textured with [`coordinate_texture`], nearest filtering.
fn textured_scene(env: TexEnv, material: Material) -> Scene {
    let mut s = scene(48, 48, look_at_origin(Vec3::new(0.0, 0.0, 5.0)));
    s.projection.fovy_deg = 30.0;
    s.textures = vec![coordinate_texture()];
    let mut square = object("square", quad(1.0), material, MatrixProduct::identity());
    let sampler = Sampler { filter: Filter::Nearest, wrap_u: Wrap::Clamp, wrap_v: Wrap::Clamp };
    square.texture = Some(TextureUse { texture: 0, sampler, env });
    s.objects = vec![square];
    s
}

/// Texel `(i, j)`'s centre on the square, in world space: texture coordinate
/// `((i + ½)/4, (j + ½)/4)`, and the square maps (0, 0) to (−1, −1) and (1, 1) to (1, 1).
fn texel_centre(i: u32, j: u32) -> Vec3 {
    let uv = Vec2::new((i as f32 + 0.5) / 4.0, (j as f32 + 0.5) / 4.0);
    (2.0 * uv - Vec2::ONE).extend(0.0)
}

#[test]
fn a_textured_square_shows_texel_0_0_at_its_bottom_left_corner() {
    if !cg_glref::require() {
        return;
    }
    let s = textured_scene(TexEnv::Replace, emissive(Rgb::ZERO));
    let pixels = render_rgb(&s);
    let texture = coordinate_texture();
    let art = || {
        ascii(&pixels, 48, |p| {
            let texel = (u32::from(p[0].saturating_sub(40)) / 60)
                + 4 * (u32::from(p[1].saturating_sub(40)) / 60);
            if p == BACKGROUND { '.' } else { char::from_digit(texel, 16).unwrap_or('?') }
        })
    };
    for j in 0..4 {
        for i in 0..4 {
            let at = project(&s, texel_centre(i, j));
            let [r, g, b, _] = texture.texel(i, j);
            let got = pixels[at.y as usize * 48 + at.x as usize];
            assert_eq!(
                got,
                [r, g, b],
                "texel ({i}, {j}) should show at pixel ({}, {}) (GL_REPLACE, GL_NEAREST); the image \
                 (hex digit i + 4j of the texel seen):\n{}",
                at.x,
                at.y,
                art()
            );
        }
    }
    // Said plainly: texture coordinate (0, 0) is the bottom-left corner of the image shown.
    let bottom_left = project(&s, texel_centre(0, 0));
    assert!(bottom_left.x < 24.0 && bottom_left.y > 24.0, "{bottom_left}");
}

#[test]
fn gl_modulate_multiplies_the_lit_colour_by_the_texel() {
    if !cg_glref::require() {
        return;
    }
    let lit = [0.5, 1.0, 0.25];
    let s = textured_scene(TexEnv::Modulate, emissive(Rgb::from_array(lit.map(|x| x as f32))));
    let pixels = render_rgb(&s);
    let texture = coordinate_texture();
    for j in 0..4 {
        for i in 0..4 {
            let at = project(&s, texel_centre(i, j));
            let texel = texture.texel(i, j);
            let expected = [0, 1, 2].map(|c| (f64::from(texel[c]) * lit[c]).round() as u8);
            let got = pixels[at.y as usize * 48 + at.x as usize];
            assert!(
                channel_diff(got, expected) <= 1,
                "texel ({i}, {j}) modulated by {lit:?}: expected {expected:?} (±1), got {got:?}"
            );
        }
    }
}
