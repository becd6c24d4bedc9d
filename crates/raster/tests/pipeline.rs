//! The pipeline's promises: back-face culling (also for mirrored objects, which still face
//! outwards), depth-test order independence, bit-identical output for every thread count and tile
//! size, "only what the scene needs" counters, the lighting hook, and errors instead of panics.

mod common;

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::light::{Light, LightKind, shade};
use cg_core::mesh::Mesh;
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{Camera, Scene, Shading};
use cg_core::shapes::cuboid;
use cg_raster::{Options, RenderError, SurfacePoint, render, render_with};
use common::{load, looking_down_z, object, on_screen_at, triangle, unlit};

const RED: Rgb = Rgb::new(1.0, 0.0, 0.0);
const GREEN: Rgb = Rgb::new(0.0, 1.0, 0.0);

fn small(size: u32) -> Options {
    Options { size: Some((size, size)), ..Options::default() }
}

// ---------------------------------------------------------------------------------------------
// Culling and the depth test

#[test]
fn back_faces_are_culled_only_when_the_scene_says_so() {
    let (a, b, c) =
        (Vec3::new(-1.0, -1.0, -3.0), Vec3::new(1.0, -1.0, -3.0), Vec3::new(0.0, 1.0, -3.0));
    for (name, mesh, front) in
        [("counter-clockwise", triangle(a, b, c), true), ("clockwise", triangle(a, c, b), false)]
    {
        for cull in [true, false] {
            let mut scene = looking_down_z(16, 16, 60.0);
            scene.cull_back_faces = cull;
            scene.objects.push(object(name, mesh.clone(), unlit(RED)));
            let out = render(&scene, &Options::default()).unwrap();
            let drawn = out.stats.fragments_shaded > 0;
            assert_eq!(drawn, front || !cull, "{name}, culling {cull}: {}", out.stats);
            assert_eq!(out.stats.triangles_culled, u64::from(!front && cull));
        }
    }
}

#[test]
fn the_depth_test_makes_the_drawing_order_irrelevant() {
    // Two overlapping triangles at different depths, drawn in both orders: the same image, the
    // nearer one in front where they overlap.
    let near = object(
        "near",
        triangle(
            Vec3::new(-2.0, -2.0, -4.0),
            Vec3::new(2.0, -2.0, -4.0),
            Vec3::new(0.0, 2.0, -4.0),
        ),
        unlit(RED),
    );
    let far = object(
        "far",
        triangle(Vec3::new(0.0, -3.0, -5.0), Vec3::new(4.0, -3.0, -5.0), Vec3::new(0.0, 3.0, -5.0)),
        unlit(GREEN),
    );
    let draw = |objects: Vec<cg_core::scene::Object>| {
        let mut scene = looking_down_z(24, 24, 60.0);
        scene.objects = objects;
        render(&scene, &Options::default()).unwrap()
    };
    let near_first = draw(vec![near.clone(), far.clone()]);
    let far_first = draw(vec![far.clone(), near.clone()]);
    assert_eq!(near_first.image, far_first.image);
    assert_eq!(near_first.depth, far_first.depth);
    // Premise: they overlap. Near first, the far one's hidden fragments fail the depth test; far
    // first, the near one's overwrite them.
    assert!(near_first.stats.depth_rejects > 0, "{}", near_first.stats);
    assert_eq!(far_first.stats.depth_rejects, 0, "{}", far_first.stats);
    assert_eq!(
        far_first.stats.fragments_shaded,
        near_first.stats.fragments_shaded + near_first.stats.depth_rejects
    );
    // Where both cover a pixel (each drawn alone), the nearer, red one shows.
    let near_alone = draw(vec![near]);
    let far_alone = draw(vec![far]);
    let rgba = near_first.image.to_rgba8();
    let mut both = 0;
    for (i, pixel) in rgba.iter().enumerate() {
        if near_alone.depth[i] < 1.0 && far_alone.depth[i] < 1.0 {
            both += 1;
            assert_eq!(*pixel, [255, 0, 0, 255], "pixel {i}: the near triangle is in front");
        }
    }
    assert!(both >= 40, "premise: the triangles overlap on {both} pixels");
}

#[test]
fn mirrored_objects_still_face_outwards() {
    // A cube is its own mirror image: scaled by (−1, 1, 1) it must look the same, lit from the
    // same side, with culling on — in every shading mode. Its triangles turn the other way on
    // screen and its cofactor normals point inwards; the renderer flips both back.
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let draw = |mirror: bool| {
            let mut scene = looking_down_z(48, 48, 45.0);
            scene.shading = shading;
            scene.global_ambient = Rgb::splat(0.2);
            scene.lights = vec![Light {
                kind: LightKind::Directional { to_light: Vec3::new(0.3, 1.0, 0.6) },
                ambient: Rgb::ZERO,
                diffuse: Rgb::ONE,
                specular: Rgb::ZERO,
                attenuation: Default::default(),
            }];
            let mut cube = object(
                "cube",
                cuboid(Vec3::splat(1.5)).unwrap(),
                cg_core::light::Material::from_color(Rgb::new(0.9, 0.6, 0.3)),
            );
            let mut t = MatrixProduct::identity()
                .then(Factor::translate(Vec3::new(0.0, 0.0, -5.0)))
                .then(Factor::rotate_x_deg(25.0))
                .then(Factor::rotate_y_deg(35.0));
            if mirror {
                t = t.then(Factor::scale(Vec3::new(-1.0, 1.0, 1.0)));
            }
            cube.transform = t;
            scene.objects.push(cube);
            (render(&scene, &Options::default()).unwrap(), scene)
        };
        let (plain, _) = draw(false);
        let (mirrored, scene) = draw(true);
        assert!(scene.objects[0].prepare().unwrap().mirrored, "premise: det < 0");
        assert_eq!(
            mirrored.stats.triangles_culled, plain.stats.triangles_culled,
            "{shading:?}: the same faces are culled"
        );
        let (a, b) = (plain.image.to_rgba8(), mirrored.image.to_rgba8());
        let differ = a
            .iter()
            .zip(&b)
            .filter(|(p, q)| p.iter().zip(q.iter()).any(|(x, y)| x.abs_diff(*y) > 1))
            .count();
        assert!(
            differ <= 4,
            "{shading:?}: {differ} pixels differ between the cube and its mirror image"
        );
        // The top face (normal +Y turned by the rotations) is lit as an outward face: brighter
        // than the ambient-only colour an inward normal would give.
        let ambient_only = (0.2 * 0.9 * 255.0f32).round() as u8;
        let brightest = b.iter().map(|p| p[0]).max().unwrap();
        assert!(
            brightest > ambient_only + 50,
            "{shading:?}: lit faces ({brightest}) vs ambient only ({ambient_only})"
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Determinism

#[test]
fn the_output_is_bit_identical_for_every_thread_count_and_tile_size() {
    for (scene, shading) in [
        ("course-sample.toml", Shading::Gouraud),
        ("spot-specular.toml", Shading::Phong),
        ("textured-ground.toml", Shading::Flat),
    ] {
        let scene = load(scene);
        let options = |threads, tile_size| Options {
            shading: Some(shading),
            size: Some((72, 60)),
            threads,
            tile_size,
        };
        let reference = render(&scene, &options(Some(1), None)).unwrap();
        for (threads, tile) in
            [(Some(2), None), (Some(3), Some(7)), (None, Some(16)), (Some(4), Some(4))]
        {
            let out = render(&scene, &options(threads, tile)).unwrap();
            assert!(
                out.image == reference.image,
                "{}: image differs with {threads:?} threads, tiles {tile:?}",
                scene.name
            );
            assert!(
                out.depth == reference.depth,
                "{}: depth differs with {threads:?} threads, tiles {tile:?}",
                scene.name
            );
            assert_eq!(out.stats, reference.stats, "{}: statistics differ", scene.name);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Only what the scene needs

#[test]
fn only_what_the_scene_needs_is_computed() {
    // The course's scene: every k_s is 0 (glColor sets only k_a and k_d), no texture, no
    // attenuation: no specular work, no sampling, in any mode.
    let course = load("course-sample.toml");
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let out = render(&course, &Options { shading: Some(shading), ..small(48) }).unwrap();
        assert!(!out.features.specular && !out.features.textures && !out.features.attenuation);
        assert!(out.stats.lighting_evaluations > 0);
        assert_eq!(out.stats.specular_evaluations, 0, "{shading:?}: {}", out.stats);
        assert_eq!(out.stats.attenuation_evaluations, 0, "{shading:?}");
        assert_eq!(out.stats.texture_samples, 0, "{shading:?}");
        assert!(
            out.features.describe(Lang::En).contains("skipped: "),
            "{}",
            out.features.describe(Lang::En)
        );
    }
    // A shiny sphere under an attenuated spot light: both are evaluated, and the counts are
    // what the light model did (counted inside cg_core::light). Gouraud lights every vertex:
    // every evaluation attenuates the one spot light, and a specular term is computed exactly at
    // the shiny sphere's vertices inside the spot's cone, narrowed here to 5° so that it cuts
    // the sphere — counted by the cone's geometry in f64 (the ground's k_s is 0; outside the
    // cone the spot factor is 0 and the light model skips the light).
    let mut spot_scene = load("spot-specular.toml");
    let cg_core::light::LightKind::Spot { cutoff_deg, .. } = &mut spot_scene.lights[0].kind else {
        panic!("premise: a spot light")
    };
    *cutoff_deg = 5.0;
    let spot = render(&spot_scene, &small(48)).unwrap();
    assert!(spot.features.specular && spot.features.attenuation);
    assert_eq!(spot.stats.lighting_evaluations, spot.stats.vertices, "{}", spot.stats);
    assert_eq!(spot.stats.attenuation_evaluations, spot.stats.lighting_evaluations);
    let sphere = spot_scene.objects.iter().find(|o| o.name == "sphere").unwrap();
    let prepared = sphere.prepare().unwrap();
    let (light_at, axis) =
        (cg_core::glam::DVec3::new(0.0, 8.0, 4.0), cg_core::glam::DVec3::new(0.0, -8.0, -4.0));
    let in_cone = prepared
        .mesh
        .positions
        .iter()
        .map(|p| (p.as_dvec3() + cg_core::glam::DVec3::Y - light_at).angle_between(axis))
        .inspect(|a| assert!((a.to_degrees() - 5.0).abs() > 1e-3, "premise: no vertex on the rim"))
        .filter(|a| a.to_degrees() < 5.0)
        .count() as u64;
    assert!(in_cone > 10 && in_cone < prepared.mesh.positions.len() as u64, "premise: {in_cone}");
    assert_eq!(spot.stats.specular_evaluations, in_cone, "{}", spot.stats);
    // The textured ground: sampled once per shaded fragment of the ground.
    let textured = render(&load("textured-ground.toml"), &small(48)).unwrap();
    assert!(textured.stats.texture_samples > 0);
    assert!(
        textured.stats.texture_samples < textured.stats.fragments_shaded,
        "the pyramid is not textured"
    );

    // The global terms need rays: the rasterizer says it did not compute them, even for a
    // scene that has mirrors and glass.
    let glass = render(&load("glass-mirror.toml"), &small(32)).unwrap();
    assert!(!glass.features.reflection && !glass.features.transmission, "{:?}", glass.features);
    assert!(load("glass-mirror.toml").features().reflection, "premise: the scene has k_r");

    // A k_s > 0 that no light can show (every light's specular colour is 0): skipped as well.
    let mut dull = load("spot-specular.toml");
    for light in &mut dull.lights {
        light.specular = Rgb::ZERO;
    }
    let out = render(&dull, &small(48)).unwrap();
    assert!(!out.features.specular);
    assert_eq!(out.stats.specular_evaluations, 0);
}

#[test]
fn gl_replace_shows_the_bare_texel_without_lighting() {
    let mut scene = load("textured-ground.toml");
    if let Some(t) = &mut scene.objects[0].texture {
        t.env = cg_core::texture::TexEnv::Replace;
    }
    let replace = render(&scene, &Options { shading: Some(Shading::Phong), ..small(48) }).unwrap();
    let modulate = render(
        &load("textured-ground.toml"),
        &Options { shading: Some(Shading::Phong), ..small(48) },
    )
    .unwrap();
    // Phong lights every fragment: under GL_REPLACE only the pyramid's are lit.
    assert!(
        replace.stats.lighting_evaluations < modulate.stats.lighting_evaluations / 2,
        "{} vs {}",
        replace.stats,
        modulate.stats
    );
    assert_eq!(replace.stats.texture_samples, modulate.stats.texture_samples);
}

// ---------------------------------------------------------------------------------------------
// The lighting hook

#[test]
fn a_custom_lighting_hook_runs_through_the_same_pipeline() {
    let scene = load("spot-specular.toml");
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let options = Options { shading: Some(shading), ..small(40) };
        // The default lighting written out as a closure gives the very same image…
        let by_hand = |scene: &Scene, p: &SurfacePoint<'_>| {
            assert_eq!(p.shading, shading);
            assert!(
                (p.n_world.length() - 1.0).abs() < 1e-5 || p.n_world == Vec3::ZERO,
                "N is unit"
            );
            shade(
                scene.light_model,
                scene.global_ambient,
                &scene.lights,
                p.material,
                p.p_world,
                p.n_world,
                p.v_world,
            )
            .total()
        };
        let default = render(&scene, &options).unwrap();
        let custom = render_with(&scene, &options, &by_hand).unwrap();
        assert!(default.image == custom.image, "{shading:?}");
        // The same pipeline work; the light model's own counts come only from the default
        // lighting, which counts inside cg_core::light (a closure cannot report them).
        assert!(
            default.stats.specular_evaluations > 0 && default.stats.attenuation_evaluations > 0
        );
        assert_eq!(
            cg_raster::Stats {
                specular_evaluations: 0,
                attenuation_evaluations: 0,
                ..default.stats
            },
            custom.stats
        );
        // …and a different one changes every lit pixel (and a NaN never reaches the image).
        let nan = |_: &Scene, _: &SurfacePoint<'_>| Rgb::new(f32::NAN, 2.0, 0.25);
        let out = render_with(&scene, &options, &nan).unwrap();
        for (c, z) in out.image.to_rgba8().iter().zip(&out.depth) {
            if *z < 1.0 {
                assert_eq!(*c, [0, 255, 64, 255], "{shading:?}: NaN → 0, 2 → 1, 0.25 → 64/255");
            }
        }
    }
}

/// A triangle on [`looking_down_z`]`(16, 16, 90°)` whose bottom edge (as the image is seen) runs
/// through pixel centres from (3.5, 10.5) to (11.5, 10.5) and whose apex is at (7.5, 2.5): the
/// centre of pixel (7, 10) is the exact midpoint of the bottom edge (corners 0 and 1), covered by
/// the fill rule (a bottom edge), with screen barycentrics (½, ½, 0) up to one rounding — and
/// equal in its first two, as the edge functions there are equal integers. All three corners at
/// z = −2, so w = 2 and the perspective correction keeps them equal.
fn midpoint_triangle() -> (Mesh, Vec3) {
    let at = |x, y| on_screen_at(16, x, y);
    let mesh = Mesh::new(vec![at(3.5, 10.5), at(11.5, 10.5), at(7.5, 2.5)], vec![[0, 1, 2]]);
    let midpoint = (at(3.5, 10.5) + at(11.5, 10.5)) * 0.5;
    (mesh, midpoint)
}

/// Pixel (7, 10) of a 16-wide image.
const MIDPOINT_PIXEL: usize = 10 * 16 + 7;

#[test]
fn row18_cancelling_vertex_normals_fall_back_to_the_face_normal() {
    // Phong interpolation between opposite vertex normals, +X and −X at the bottom edge's ends:
    // at its midpoint their weights are equal, so N = ½·(+X) + ½·(−X) + 0·(+Z) is exactly zero
    // (interpolate_normal sums in f64). The face normal, +Z, must take over — never NaN, never
    // the zero vector. A recording lighting hook shows what the renderer passed there.
    let (mut mesh, midpoint) = midpoint_triangle();
    mesh.normals = Some(vec![Vec3::X, Vec3::NEG_X, Vec3::Z]);
    let mut scene = looking_down_z(16, 16, 90.0);
    scene.shading = Shading::Phong;
    scene.lights = vec![Light {
        kind: LightKind::Directional { to_light: Vec3::Z },
        ambient: Rgb::ZERO,
        diffuse: Rgb::ONE,
        specular: Rgb::ZERO,
        attenuation: Default::default(),
    }];
    let mut o = object("opposite", mesh, cg_core::light::Material::from_color(Rgb::ONE));
    o.normals = cg_core::scene::NormalSource::Given;
    scene.objects.push(o);
    let seen: std::sync::Mutex<Vec<(Vec3, Vec3)>> = std::sync::Mutex::new(Vec::new());
    let record = |scene: &Scene, p: &SurfacePoint<'_>| {
        seen.lock().unwrap().push((p.p_world, p.n_world));
        shade(
            scene.light_model,
            scene.global_ambient,
            &scene.lights,
            p.material,
            p.p_world,
            p.n_world,
            p.v_world,
        )
        .total()
    };
    let out = render_with(&scene, &Options::default(), &record).unwrap();
    assert!(out.image.pixels.iter().all(|c| c.is_finite()));
    let points = seen.into_inner().unwrap();
    for (_, n) in &points {
        assert!(n.is_finite() && (n.length() - 1.0).abs() < 1e-5, "every normal is unit: {n}");
    }
    let at_midpoint: Vec<_> = points.iter().filter(|(p, _)| p.distance(midpoint) < 1e-5).collect();
    assert_eq!(at_midpoint.len(), 1, "premise: pixel (7, 10) is lit once, at the midpoint");
    assert_eq!(at_midpoint[0].1, Vec3::Z, "the fallback: the face normal");
    // Lit head-on by the face normal: white (an unusable normal would leave it black).
    assert_eq!(out.image.pixels[MIDPOINT_PIXEL], Rgb::ONE);
}

#[test]
fn gouraud_clamps_each_vertex_colour_before_interpolating() {
    // Corner 0 lit to 2.0, corners 1 and 2 to 0.0: OpenGL clamps the lit vertex colours to
    // [0, 1] first, so the midpoint of the edge from corner 0 to corner 1 is ½·1 + ½·0 = 0.5 —
    // not ½·2 = 1.0, which interpolating before clamping would give.
    let (mesh, _) = midpoint_triangle();
    let corner0 = mesh.positions[0];
    let mut scene = looking_down_z(16, 16, 90.0);
    scene.objects.push(object("t", mesh, cg_core::light::Material::default()));
    let two_at_corner0 = |_: &Scene, p: &SurfacePoint<'_>| {
        assert_eq!(p.shading, Shading::Gouraud);
        if p.p_world == corner0 { Rgb::splat(2.0) } else { Rgb::ZERO }
    };
    let out = render_with(&scene, &Options::default(), &two_at_corner0).unwrap();
    let c = out.image.pixels[MIDPOINT_PIXEL];
    assert!((c - Rgb::splat(0.5)).abs().max_element() < 1e-6, "midpoint colour {c}, expected 0.5");
    assert_eq!(out.stats.lighting_evaluations, 3, "Gouraud lights the three vertices");
}

#[test]
fn of_two_coplanar_triangles_the_first_drawn_stays() {
    // GL_LESS: the same triangle twice, red then green, at bit-identical depths: the green one
    // fails the depth test at every pixel (GL_LEQUAL would paint it over the red).
    let (mesh, _) = midpoint_triangle();
    let mut scene = looking_down_z(16, 16, 90.0);
    scene.objects.push(object("first", mesh.clone(), unlit(RED)));
    scene.objects.push(object("second", mesh, unlit(GREEN)));
    let out = render(&scene, &Options::default()).unwrap();
    let drawn = out.depth.iter().filter(|&&z| z < 1.0).count() as u64;
    assert!(drawn > 20, "premise: {drawn} pixels");
    for (i, (c, z)) in out.image.to_rgba8().iter().zip(&out.depth).enumerate() {
        if *z < 1.0 {
            assert_eq!(*c, [255, 0, 0, 255], "pixel {i}: the first triangle stays");
        }
    }
    assert_eq!(out.stats.fragments, 2 * drawn);
    assert_eq!(out.stats.depth_rejects, drawn, "every fragment of the second fails");
}

// ---------------------------------------------------------------------------------------------
// Sizes and errors

#[test]
fn the_size_option_keeps_the_scene_and_follows_its_aspect() {
    let scene = load("course-sample.toml");
    let wide = render(&scene, &Options { size: Some((64, 32)), ..Options::default() }).unwrap();
    assert_eq!((wide.image.width, wide.image.height), (64, 32));
    assert_eq!(wide.depth.len(), 64 * 32);
    // The aspect follows the size: the ground is wider than tall on screen in both, and the
    // vertical extent is the same fraction of the height as in a square image of that height.
    let square = render(&scene, &small(32)).unwrap();
    let rows = |out: &cg_raster::Output, w: usize| {
        (0..out.image.height as usize)
            .filter(|y| (0..w).any(|x| out.depth[y * w + x] < 1.0))
            .count()
    };
    assert_eq!(rows(&wide, 64), rows(&square, 32), "fovy is vertical: the same rows are covered");
}

#[test]
fn bad_scenes_give_errors_that_name_the_problem() {
    let scene = load("course-sample.toml");
    let err = |scene: &Scene, options: &Options| match render(scene, options) {
        Ok(out) => panic!("rendered instead of failing: {}", out.stats),
        Err(e) => e,
    };

    let e = err(&scene, &small(0));
    assert!(matches!(e, RenderError::ZeroSize { width: 0, height: 0 }), "{e}");
    assert!(e.message(Lang::Ja).contains("ピクセル"), "{}", e.message(Lang::Ja));
    let e = err(&scene, &Options { size: Some((100_000, 10)), ..Options::default() });
    assert!(matches!(e, RenderError::TooLarge { .. }), "{e}");
    // 16384 × 4097 pixels: each side allowed, but more than 64 M pixels in all.
    let e = err(&scene, &Options { size: Some((16_384, 4097)), ..Options::default() });
    assert!(matches!(e, RenderError::TooManyPixels { width: 16_384, height: 4097 }), "{e}");
    assert!(e.message(Lang::Ja).contains("ピクセル数"), "{}", e.message(Lang::Ja));
    assert!(e.to_string().contains("too many pixels"), "{e}");

    let mut bad = scene.clone();
    bad.projection.near = 0.0;
    let e = err(&bad, &Options::default());
    assert!(matches!(e, RenderError::Projection(_)), "{e}");
    assert!(e.message(Lang::Ja).contains("投影"));

    let mut bad = scene.clone();
    bad.camera = Camera::LookAt { eye: Vec3::ONE, target: Vec3::ONE, up: Vec3::Y };
    assert!(matches!(err(&bad, &Options::default()), RenderError::Camera(_)));

    let mut bad = scene.clone();
    bad.objects[1].transform.push(Factor::rotate_deg(30.0, Vec3::ZERO));
    let e = err(&bad, &Options::default());
    assert!(matches!(e, RenderError::Prepare(_)), "{e}");
    assert!(e.to_string().contains("pyramid"), "names the object: {e}");

    let mut bad = scene.clone();
    bad.objects[0].texture = Some(cg_core::scene::TextureUse {
        texture: 3,
        sampler: Default::default(),
        env: Default::default(),
    });
    let e = err(&bad, &Options::default());
    assert!(matches!(e, RenderError::MissingTexture { texture: 3, count: 0, .. }), "{e}");
    assert!(e.message(Lang::Ja).contains("ground"));

    // A scale whose matrix is finite but overflows f32 in clip space (the projection multiplies
    // by cot(22.5°) ≈ 2.4): an error naming the vertex, not NaN pixels.
    let mut bad = scene.clone();
    bad.objects[1].transform.push(Factor::scale(Vec3::splat(3e38)));
    assert!(bad.objects[1].prepare().is_ok(), "premise: the model matrix itself is finite");
    let e = err(&bad, &Options::default());
    assert!(matches!(e, RenderError::NonFinite { ref object, .. } if object == "pyramid"), "{e}");
    assert!(e.message(Lang::Ja).contains("V"), "{}", e.message(Lang::Ja));
}

/// The vertex a clip-space error names is the object's own (the file's V-number), not the
/// prepared mesh's: under face normals every face gets its own copies of its corners, and the
/// lecture pyramid's V2 (the second corner of F1 = {0, 2, 4}) is the prepared mesh's V4.
#[test]
fn a_vertex_beyond_clip_space_is_named_as_its_file_numbers_it() {
    let mut scene = load("course-sample.toml");
    let pyramid = &mut scene.objects[1];
    assert_eq!(pyramid.mesh.faces[1], [0, 2, 4], "premise: the lecture's F1");
    pyramid.mesh.positions[2].x = 3e38;
    let prepared = pyramid.prepare().unwrap();
    assert_eq!(prepared.mesh.positions[4].x, 3e38, "premise: the prepared mesh's V4 is V2");
    assert!(prepared.mesh.positions[..4].iter().all(|p| p.x < 2.0), "premise: V4 comes first");
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let e = render(&scene, &Options { shading: Some(shading), ..small(16) }).unwrap_err();
        let RenderError::NonFinite { ref object, vertex, position } = e else { panic!("{e}") };
        assert_eq!((object.as_str(), vertex), ("pyramid", 2), "{shading:?}: {e}");
        assert!(position[0].is_infinite(), "{position:?}");
        assert!(e.to_string().contains("vertex V2 is at [inf"), "{e}");
    }
}

#[test]
fn colours_beyond_f32s_range_give_a_finite_image() {
    // Light colours of 3e38 (a program can set them; the scene loader bounds colours to 1e6):
    // the lit colours overflow to ∞ (and ∞·0 to NaN); OpenGL's clamp of the lit colour takes
    // them to [0, 1] (NaN to 0) in every shading mode, so the image stays finite.
    let mut scene = load("spot-specular.toml");
    for light in &mut scene.lights {
        light.diffuse = Rgb::splat(3e38);
        light.specular = Rgb::splat(3e38);
        light.ambient = Rgb::splat(3e38);
    }
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let out = render(&scene, &Options { shading: Some(shading), ..small(24) }).unwrap();
        assert!(
            out.image.pixels.iter().all(|c| c.is_finite() && c.max_element() <= 1.0),
            "{shading:?}"
        );
    }
}

#[test]
fn an_empty_scene_is_the_clear_colour() {
    let mut scene = load("course-sample.toml");
    scene.objects.clear();
    // Every mode: Phong's spans are flushed at each tile's end with no object to name.
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let out = render(&scene, &Options { shading: Some(shading), ..small(8) }).unwrap();
        assert!(out.image.pixels.iter().all(|&c| c == scene.clear_color), "{shading:?}");
        assert!(out.depth.iter().all(|&z| z == 1.0), "{shading:?}");
        assert_eq!(out.stats, cg_raster::Stats::default(), "{shading:?}");
    }
}
