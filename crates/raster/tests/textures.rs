//! Texture mapping: perspective-correct texture coordinates (the checkerboard of a receding floor
//! lands where the projection of its grid lines says, not where screen-linear interpolation would
//! put it), and sampling on a screen-aligned quad — nearest and bilinear, repeat and clamp,
//! GL_MODULATE and GL_REPLACE — against the OpenGL specification's formulas written out here.

mod common;

use cg_core::Rgb;
use cg_core::glam::{DVec2, Vec2, Vec3};
use cg_core::mesh::Mesh;
use cg_core::scene::{Scene, TextureUse};
use cg_core::texture::{Filter, Sampler, TexEnv, Texture, Wrap};
use cg_raster::{Options, render};
use common::{Pinhole, inside_by, looking_down_z, object, sample_f64, unlit};

/// `scene` with `mesh` textured by `texture`.
fn textured(
    mut scene: Scene,
    mesh: Mesh,
    lit: Rgb,
    texture: Texture,
    sampler: Sampler,
    env: TexEnv,
) -> Scene {
    let mut o = object("textured", mesh, unlit(lit));
    o.texture = Some(TextureUse { texture: 0, sampler, env });
    scene.objects.push(o);
    scene.textures.push(texture);
    scene
}

// ---------------------------------------------------------------------------------------------
// Perspective correctness

#[test]
fn a_checkerboard_on_a_receding_floor_lands_where_the_projection_of_its_grid_lines_says() {
    // A floor quad (y = −1, x in [−4, 4], z from −3 to −19) with an 8 × 8 checkerboard (nearest),
    // u = (x + 4)/8 across and v = (−3 − z)/16 into the distance. The oracle, per pixel centre:
    // the ray through it meets the floor at P, whose (u, v) give the checker cell. Every pixel
    // whose centre is more than 1/8 pixel from a projected grid line must show that cell's
    // colour — so the checker edges land within 1/8 pixel of the projected grid lines.
    let size = 128u32;
    let scene = looking_down_z(size, size, 60.0);
    let camera = Pinhole::of(&scene);
    let corners = [
        Vec3::new(-4.0, -1.0, -3.0),
        Vec3::new(4.0, -1.0, -3.0),
        Vec3::new(4.0, -1.0, -19.0),
        Vec3::new(-4.0, -1.0, -19.0),
    ];
    let uvs = [Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), Vec2::new(1.0, 1.0), Vec2::new(0.0, 1.0)];
    let faces = [[0usize, 1, 2], [0, 2, 3]];
    let mut floor =
        Mesh::new(corners.to_vec(), faces.iter().map(|f| f.map(|i| i as u32)).collect());
    floor.uvs = Some(uvs.to_vec());
    let checker =
        Texture::from_fn(8, 8, |x, y| if (x + y) % 2 == 0 { [255; 4] } else { [0, 0, 0, 255] })
            .unwrap();
    let sampler = Sampler { filter: Filter::Nearest, wrap_u: Wrap::Clamp, wrap_v: Wrap::Clamp };
    let scene = textured(scene, floor, Rgb::ONE, checker, sampler, TexEnv::Replace);
    let out = render(&scene, &Options::default()).unwrap();
    let rgba = out.image.to_rgba8();

    // The checker cell seen through window point w, by the projection (the oracle).
    let cell = |w: DVec2| {
        let d = camera.ray(w);
        let p = d * (-1.0 / d.y);
        let (u, v) = ((p.x + 4.0) / 8.0, (-3.0 - p.z) / 16.0);
        ((u * 8.0).floor() as i64, (v * 8.0).floor() as i64)
    };
    let white = |(i, j): (i64, i64)| (i + j) % 2 == 0;
    let on_screen: Vec<DVec2> = corners.iter().map(|c| camera.window(c.as_dvec3())).collect();
    // What screen-linear (affine) interpolation of (u, v) inside each triangle would show.
    let affine_white = |w: DVec2| {
        for face in faces {
            let [a, b, c] = face.map(|i| on_screen[i]);
            let area = (b - a).perp_dot(c - a);
            let weights =
                [(c - b).perp_dot(w - b), (a - c).perp_dot(w - c), (b - a).perp_dot(w - a)]
                    .map(|x| x / area);
            if weights.iter().all(|&x| x >= 0.0) {
                let uv =
                    face.iter().zip(weights).map(|(&i, x)| uvs[i].as_dvec2() * x).sum::<DVec2>();
                return white(((uv.x * 8.0).floor() as i64, (uv.y * 8.0).floor() as i64));
            }
        }
        false
    };
    let (mut checked, mut affine_wrong) = (0, 0);
    for y in 0..size {
        for x in 0..size {
            let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            if inside_by(&on_screen, centre) < 1.0 {
                continue;
            }
            let here = cell(centre);
            let eighth = 1.0 / 8.0;
            let offsets =
                [DVec2::X * eighth, -DVec2::X * eighth, DVec2::Y * eighth, -DVec2::Y * eighth];
            if offsets.iter().any(|&o| cell(centre + o) != here) {
                continue; // within 1/8 pixel of a grid line
            }
            checked += 1;
            let got = rgba[(y * size + x) as usize];
            assert_eq!(
                got[0] == 255,
                white(here),
                "pixel ({x}, {y}): checker cell {here:?} is {}, got {got:?}",
                if white(here) { "white" } else { "black" }
            );
            affine_wrong += usize::from(affine_white(centre) != white(here));
        }
    }
    assert!(checked > 2000, "premise: many pixels checked ({checked})");
    // The premise: screen-linear interpolation would put many checker edges elsewhere.
    assert!(
        affine_wrong * 5 > checked,
        "premise: affine interpolation would show other cells ({affine_wrong} of {checked} pixels)"
    );
}

// ---------------------------------------------------------------------------------------------
// Sampling on a screen-aligned quad

/// A 4 × 4 texture with a different colour in every texel, row 0 at the bottom.
fn texture4() -> Texture {
    Texture::from_fn(4, 4, |x, y| {
        [40 + 50 * x as u8, 30 + 60 * y as u8, 200 - 30 * (x + y) as u8, 255]
    })
    .unwrap()
}

/// A 16 × 16 image exactly covered by a quad facing the camera (at z = −2, half-size 2, with a
/// 90° field of view), whose texture coordinates run from `from` (bottom-left) to `to`
/// (top-right).
fn quad_scene(from: Vec2, to: Vec2, lit: Rgb, sampler: Sampler, env: TexEnv) -> Scene {
    let scene = looking_down_z(16, 16, 90.0);
    let mut quad = Mesh::new(
        vec![
            Vec3::new(-2.0, -2.0, -2.0),
            Vec3::new(2.0, -2.0, -2.0),
            Vec3::new(2.0, 2.0, -2.0),
            Vec3::new(-2.0, 2.0, -2.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    quad.uvs = Some(vec![from, Vec2::new(to.x, from.y), to, Vec2::new(from.x, to.y)]);
    textured(scene, quad, lit, texture4(), sampler, env)
}

/// Renders the quad and compares every pixel with the formula: texture coordinates at pixel
/// centres are `from + (x + ½)/16·(to − from)` across and the same upwards (row 0 at the top);
/// `env` combines the texel with the lit colour `lit`. Tolerance: 1/255 for bilinear (f32 against
/// f64 weights), exact for nearest (no pixel centre falls on a texel edge in these cases).
fn assert_quad(name: &str, from: Vec2, to: Vec2, sampler: Sampler, env: TexEnv) {
    let lit = Rgb::new(0.5, 1.0, 0.25);
    let scene = quad_scene(from, to, lit, sampler, env);
    let out = render(&scene, &Options::default()).unwrap();
    assert_eq!(out.stats.texture_samples, 256, "{name}: one sample per pixel");
    let rgba = out.image.to_rgba8();
    let tolerance = if sampler.filter == Filter::Nearest { 0 } else { 1 };
    let (from, to) = (from.as_dvec2(), to.as_dvec2());
    for y in 0..16u32 {
        for x in 0..16u32 {
            let across = (f64::from(x) + 0.5) / 16.0;
            let up = 1.0 - (f64::from(y) + 0.5) / 16.0;
            let st = DVec2::new(from.x + across * (to.x - from.x), from.y + up * (to.y - from.y));
            let texel = sample_f64(&scene.textures[0], st, sampler);
            let color = match env {
                TexEnv::Modulate => texel * lit.as_dvec3(),
                TexEnv::Replace => texel,
            };
            let expected = color.to_array().map(|c| (c * 255.0).round() as i32);
            let got = rgba[(y * 16 + x) as usize];
            for c in 0..3 {
                assert!(
                    (i32::from(got[c]) - expected[c]).abs() <= tolerance,
                    "{name}: pixel ({x}, {y}) at (s, t) = ({:.4}, {:.4}) is {got:?}, expected {expected:?} (±{tolerance})",
                    st.x,
                    st.y
                );
            }
        }
    }
}

#[test]
fn nearest_sampling_repeats_and_clamps() {
    let nearest = |wrap_u, wrap_v| Sampler { filter: Filter::Nearest, wrap_u, wrap_v };
    let (zero, one) = (Vec2::ZERO, Vec2::ONE);
    assert_quad("nearest once", zero, one, nearest(Wrap::Repeat, Wrap::Repeat), TexEnv::Replace);
    assert_quad(
        "nearest twice over",
        zero,
        Vec2::splat(2.0),
        nearest(Wrap::Repeat, Wrap::Repeat),
        TexEnv::Replace,
    );
    assert_quad(
        "nearest shifted",
        Vec2::splat(-0.5),
        Vec2::splat(1.5),
        nearest(Wrap::Repeat, Wrap::Repeat),
        TexEnv::Replace,
    );
    assert_quad(
        "nearest clamped",
        Vec2::splat(-0.5),
        Vec2::splat(1.5),
        nearest(Wrap::Clamp, Wrap::Clamp),
        TexEnv::Replace,
    );
    assert_quad(
        "nearest repeat × clamp",
        Vec2::splat(-0.5),
        Vec2::splat(1.5),
        nearest(Wrap::Repeat, Wrap::Clamp),
        TexEnv::Modulate,
    );
}

#[test]
fn bilinear_sampling_repeats_and_clamps() {
    let bilinear = |wrap_u, wrap_v| Sampler { filter: Filter::Bilinear, wrap_u, wrap_v };
    // Over [0, 1] the outer half texels blend with the opposite edge under repeat, not under clamp.
    assert_quad(
        "bilinear repeat",
        Vec2::ZERO,
        Vec2::ONE,
        bilinear(Wrap::Repeat, Wrap::Repeat),
        TexEnv::Replace,
    );
    assert_quad(
        "bilinear clamp",
        Vec2::ZERO,
        Vec2::ONE,
        bilinear(Wrap::Clamp, Wrap::Clamp),
        TexEnv::Replace,
    );
    assert_quad(
        "bilinear clamp outside",
        Vec2::splat(-0.5),
        Vec2::splat(1.5),
        bilinear(Wrap::Clamp, Wrap::Clamp),
        TexEnv::Modulate,
    );
    assert_quad(
        "bilinear twice over",
        Vec2::ZERO,
        Vec2::splat(2.0),
        bilinear(Wrap::Repeat, Wrap::Repeat),
        TexEnv::Modulate,
    );
}

#[test]
fn modulate_multiplies_the_lit_colour_and_replace_ignores_it() {
    let sampler = Sampler { filter: Filter::Nearest, wrap_u: Wrap::Repeat, wrap_v: Wrap::Repeat };
    assert_quad("modulate", Vec2::ZERO, Vec2::ONE, sampler, TexEnv::Modulate);
    assert_quad("replace", Vec2::ZERO, Vec2::ONE, sampler, TexEnv::Replace);
    // Premise: the two differ (the lit colour is not white).
    let render_env = |env| {
        render(
            &quad_scene(Vec2::ZERO, Vec2::ONE, Rgb::new(0.5, 1.0, 0.25), sampler, env),
            &Options::default(),
        )
        .unwrap()
        .image
        .to_rgba8()
    };
    assert_ne!(render_env(TexEnv::Modulate), render_env(TexEnv::Replace));
}

#[test]
fn row23_huge_texture_coordinates_sample_like_small_ones_under_repeat() {
    // docs/numerics.md row 23: the quad's coordinates run from (k, k) to (k + 1, k + 1). Under repeat
    // that is the same texture as from (0, 0) to (1, 1) — and every one of these coordinates is
    // exact in f32 (a multiple of 2⁻⁴ near 1e6) — so the image must be the specification's,
    // pixel for pixel. Interpolated as they are, coordinates near 1e6 lose everything below
    // ~0.06 to the rounding of the barycentric weights (92 of 256 pixels wrong); the rasterizer
    // takes the integer ⌊uv⌋ of the first corner off first.
    for k in [1.0e3f32, 1.0e5, 1.0e6, -1.0e6] {
        for filter in [Filter::Nearest, Filter::Bilinear] {
            let sampler = Sampler { filter, wrap_u: Wrap::Repeat, wrap_v: Wrap::Repeat };
            let (from, to) = (Vec2::splat(k), Vec2::splat(k + 1.0));
            assert_eq!(to - from, Vec2::ONE, "premise: exact in f32");
            assert_quad(&format!("offset {k:e}, {filter:?}"), from, to, sampler, TexEnv::Replace);
            let at = |from: Vec2, to: Vec2| {
                render(
                    &quad_scene(from, to, Rgb::ONE, sampler, TexEnv::Replace),
                    &Options::default(),
                )
                .unwrap()
                .image
            };
            assert!(
                at(from, to) == at(Vec2::ZERO, Vec2::ONE),
                "offset {k:e}, {filter:?}: not bit-identical to the offset-0 image"
            );
        }
    }
}
