//! The foundations of s.t6 and the view: the G-buffer drawn through the rasterizer's hook gives
//! the renderer's own weights and faces (so its flat, Gouraud and Phong rules, applied per pixel
//! here, reproduce the renderer's images), and the screen quad shows an image pixel for pixel.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::image::Image;
use cg_harness::VariantRng;
use cg_shading::Shading;
use cg_shading::render::{KitLight, compose, gbuffer, kit_image, screen};
use cg_shading::scenes::{CHECK_SIZE, check_scene, material, stage_scene};
use cg_shading::spec::{SPHERES, variant};

fn max_diff_8bit(a: &Image, b: &Image) -> u8 {
    a.to_rgba8()
        .iter()
        .zip(b.to_rgba8())
        .flat_map(|(p, q)| (0..3).map(move |k| p[k].abs_diff(q[k])))
        .max()
        .unwrap_or(0)
}

#[test]
fn the_gbuffer_reproduces_the_renderers_own_images() {
    for (k, sphere) in SPHERES.into_iter().enumerate() {
        let mut spec = variant(&mut VariantRng::from_seed(k as u64));
        spec.sphere = sphere;
        let scene = check_scene(&spec);
        let g = gbuffer(&scene, CHECK_SIZE, CHECK_SIZE).unwrap();
        assert_eq!(g.faces.len() as u32, sphere.faces());
        let seen = g.texels.iter().filter(|t| t.is_some()).count();
        assert!(seen > 5000, "the sphere covers {seen} pixels");
        for (_, w) in g.texels.iter().flatten() {
            let sum = w[0] + w[1] + w[2];
            assert!(w.iter().all(|x| (0.0..=1.0).contains(x)) && (sum - 1.0).abs() < 1e-5, "{w:?}");
        }
        let kit = KitLight::new(&scene, &material(&spec)).unwrap();
        let light = |p: Vec3, n: Vec3| kit.light(p, n);
        for mode in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            let reference = kit_image(&scene, Some(mode)).unwrap();
            let background = Image::new(CHECK_SIZE, CHECK_SIZE, scene.clear_color);
            let mine = compose(
                &background,
                &g,
                |_| Some(mode),
                |m, _, px| cg_shading::kit_rule(m, px, &light),
            );
            // Same faces, same weights, same lighting: only float rounding differs.
            let d = max_diff_8bit(&mine, &reference);
            assert!(d <= 1, "{mode:?} with a {}×{} sphere: {d}/255", sphere.slices, sphere.stacks);
        }
    }
}

#[test]
fn the_stage_gbuffer_tells_the_objects_apart() {
    let spec = variant(&mut VariantRng::from_seed(7));
    let scene = stage_scene(&spec);
    let g = gbuffer(&scene, 160, 160).unwrap();
    let mut seen = [0usize; 4];
    for (face, _) in g.texels.iter().flatten() {
        seen[g.faces[*face as usize].object] += 1;
    }
    assert!(seen.iter().all(|&n| n > 100), "ground and three spheres: {seen:?}");
}

#[test]
fn the_screen_quad_shows_an_image_pixel_for_pixel() {
    for (w, h) in [(640, 640), (97, 61), (1, 1)] {
        let mut image = Image::new(w, h, Rgb::ZERO);
        for y in 0..h {
            for x in 0..w {
                let c = Rgb::new(
                    (x % 256) as f32 / 255.0,
                    (y % 256) as f32 / 255.0,
                    ((x * 7 + y * 13) % 256) as f32 / 255.0,
                );
                image.set(x, y, c);
            }
        }
        let shown = kit_image(&screen(&image, "t").unwrap(), None).unwrap();
        assert_eq!((shown.width, shown.height), (w, h));
        assert_eq!(shown.to_rgba8(), image.to_rgba8(), "{w}×{h}");
    }
}
