//! How the tracer lights a hit: one-sided like the rasterizer and OpenGL, V towards where a
//! secondary ray came from, flat shading at the face's centroid (the lecture's model) or its
//! provoking vertex (OpenGL's), what it reports (the shading it
//! did, the light model's own counts), and the safety nets: a per-pixel ray budget for trees
//! that do not shrink, colours beyond f32's range, huge texture coordinates, and the barycentric
//! weights of mirrored objects in the mesh's order.

mod common;

use cg_core::Rgb;
use cg_core::glam::{Vec2, Vec3};
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular};
use cg_core::mesh::Mesh;
use cg_core::product::Factor;
use cg_core::scene::{NormalSource, Scene, Shading, TextureUse};
use cg_core::texture::{Filter, Sampler, TexEnv, Texture, Wrap};
use cg_trace::{Options, Primitive, Ray, Stats, Tracer};
use common::{glass, object, plane, scene, shipped, sphere};

fn small(size: u32) -> Options {
    Options { size: Some((size, size)), ..Options::default() }
}

fn point_light(position: Vec3, diffuse: f32, specular: f32) -> Light {
    Light {
        kind: LightKind::Point { position },
        ambient: Rgb::ZERO,
        diffuse: Rgb::splat(diffuse),
        specular: Rgb::splat(specular),
        attenuation: Attenuation::default(),
    }
}

/// The square [−1, 1]² in the plane z = 0 facing +Z (counter-clockwise from +Z), with texture
/// coordinates `from` at (−1, −1) to `to` at (1, 1).
fn quad(from: Vec2, to: Vec2) -> Mesh {
    let mut mesh = Mesh::new(
        vec![
            Vec3::new(-1.0, -1.0, 0.0),
            Vec3::new(1.0, -1.0, 0.0),
            Vec3::new(1.0, 1.0, 0.0),
            Vec3::new(-1.0, 1.0, 0.0),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    mesh.uvs = Some(vec![from, Vec2::new(to.x, from.y), to, Vec2::new(from.x, to.y)]);
    mesh
}

#[test]
fn a_back_face_is_lit_one_sided_as_the_rasterizer_and_opengl_light_it() {
    // A quad facing +Z seen from behind (z = −4), culling off, a light beside the camera. Its
    // outward normal faces away from the light: one-sided lighting (OpenGL's default,
    // GL_LIGHT_MODEL_TWO_SIDE off, and the rasterizer) leaves only the ambient term,
    // k_a·I_a = 0.3·0.5 = 0.15; two-sided lighting would add k_d·(N·L) ≈ 0.8.
    let material = Material { ka: Rgb::splat(0.3), kd: Rgb::splat(0.8), ..Material::default() };
    let mut o = object("quad", quad(Vec2::ZERO, Vec2::ONE), material, vec![]);
    o.normals = NormalSource::Face;
    let mut s = scene(vec![o], Vec3::new(0.0, 0.0, -4.0), Vec3::ZERO, 16, 16);
    s.global_ambient = Rgb::splat(0.5);
    s.lights = vec![point_light(Vec3::new(0.5, 0.5, -4.0), 1.0, 0.0)];
    let traced = cg_trace::render(&s, &small(16)).unwrap();
    let raster = cg_raster::render(
        &s,
        &cg_raster::Options { size: Some((16, 16)), ..cg_raster::Options::default() },
    )
    .unwrap();
    let centre = traced.image.get(8, 8).unwrap();
    assert!((centre - Rgb::splat(0.15)).abs().max_element() < 1e-6, "back face: {centre}");
    assert_eq!(traced.stats.shadow_rays, 0, "N·L < 0: no shadow ray either");
    assert_eq!(traced.stats.specular_evaluations + traced.stats.attenuation_evaluations, 0);
    let (a, b) = (traced.image.to_rgba8(), raster.image.to_rgba8());
    for (i, (p, q)) in a.iter().zip(&b).enumerate() {
        if raster.depth[i] < 1.0 && i % 16 > 1 && i % 16 < 14 && i / 16 > 1 && i / 16 < 14 {
            assert!(p.iter().zip(q).all(|(x, y)| x.abs_diff(*y) <= 1), "pixel {i}: {p:?} {q:?}");
        }
    }
}

#[test]
fn a_secondary_ray_sees_the_highlight_along_its_own_direction() {
    // A shiny exact plane (k_s = 1, no ambient or diffuse) and a directional light from
    // L = (1, 1, 0)/√2. A ray of depth 1 arriving along d = (1, −1, 0)/√2 has V = −d, the mirror
    // direction of L about N = +Y, so R·V = 1 and the colour is k_s·I_s = 1 exactly — whatever the
    // camera, which only primary rays (depth 0) use for V. With V = +d it would be 0.
    let shiny = Material {
        ka: Rgb::ZERO,
        kd: Rgb::ZERO,
        ks: Rgb::ONE,
        shininess: 10.0,
        ..Material::default()
    };
    let ray = Ray::new(Vec3::new(-1.0, 1.0, 0.0), Vec3::new(1.0, -1.0, 0.0).normalize());
    for eye in [Vec3::new(0.0, 5.0, 5.0), Vec3::new(3.0, 1.0, -4.0)] {
        let mut s = scene(vec![plane("floor", 10.0, shiny.clone(), vec![])], eye, Vec3::ZERO, 8, 8);
        s.light_model = LightModel::Lecture { specular: Specular::Phong, local_viewer: true };
        s.global_ambient = Rgb::ZERO;
        s.lights = vec![Light {
            kind: LightKind::Directional { to_light: Vec3::new(1.0, 1.0, 0.0) },
            ambient: Rgb::ZERO,
            diffuse: Rgb::ZERO,
            specular: Rgb::ONE,
            attenuation: Attenuation::default(),
        }];
        let tracer = Tracer::new(&s, &Options::default()).unwrap();
        let c = tracer.trace(&ray, 1, &mut Stats::default());
        assert!((c - Rgb::ONE).abs().max_element() < 1e-5, "eye {eye}: {c}");
    }
}

#[test]
fn gouraud_is_traced_as_phong_and_the_output_says_so() {
    let scene = shipped("sphere-phong");
    let gouraud =
        cg_trace::render(&scene, &Options { shading: Some(Shading::Gouraud), ..small(24) })
            .unwrap();
    let phong =
        cg_trace::render(&scene, &Options { shading: Some(Shading::Phong), ..small(24) }).unwrap();
    assert_eq!(gouraud.shading, Shading::Phong);
    assert_eq!(gouraud.image, phong.image);
    let flat =
        cg_trace::render(&scene, &Options { shading: Some(Shading::Flat), ..small(24) }).unwrap();
    assert_eq!(flat.shading, Shading::Flat);
}

#[test]
fn flat_shading_lights_each_face_once_where_the_light_model_says() {
    // The pyramid's faces under a *near* point light (where the light falls at a different
    // angle on each point of a face), with smooth vertex normals, shadows off: flat shading gives
    // each face one colour. The lecture's model lights it at its centroid with its face normal;
    // OpenGL's, as GL_FLAT, at its last (provoking) corner with that vertex's own normal — in
    // the mesh's order also when a mirror makes the tracer reorder the corners (the rasterizer's
    // rules, both).
    let lecture = LightModel::Lecture { specular: Specular::Phong, local_viewer: false };
    let opengl = LightModel::OpenGl { local_viewer: false };
    for (model, mirrored) in [(lecture, false), (opengl, false), (opengl, true)] {
        let mut scene = shipped("course-sample");
        scene.light_model = model;
        scene.objects.retain(|o| o.name == "pyramid");
        let pyramid = &mut scene.objects[0];
        pyramid.normals = NormalSource::Vertex {
            weighting: cg_core::normals::Weighting::Uniform,
            crease_deg: None,
        };
        if mirrored {
            pyramid.transform = std::mem::take(&mut pyramid.transform)
                .then(Factor::scale(Vec3::new(-1.0, 1.0, 1.0)));
        }
        scene.lights[0].kind = LightKind::Point { position: Vec3::new(1.5, 3.0, 2.0) };
        let options = Options { shading: Some(Shading::Flat), shadows: false, ..small(48) };
        let tracer = Tracer::new(&scene, &options).unwrap();
        let out = tracer.render();
        let prepared = scene.objects[0].prepare().unwrap();
        let mut seen = std::collections::HashMap::new();
        for y in 0..48 {
            for x in 0..48 {
                let Some(hit) = tracer.intersect(&tracer.generate_ray(x, y), &mut Stats::default())
                else {
                    continue;
                };
                let Primitive::Triangle { face, .. } = hit.primitive else { panic!("triangles") };
                let face = prepared.mesh.faces[face];
                let corners = face.map(|i| {
                    cg_core::transform::transform_point(
                        prepared.model,
                        prepared.mesh.positions[i as usize],
                    )
                });
                let (at, normal) = if model == lecture {
                    let centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
                    (centroid, prepared.world_face_normal(corners).unwrap())
                } else {
                    let n = prepared.mesh.normals.as_ref().unwrap()[face[2] as usize];
                    (corners[2], prepared.world_normal(n).unwrap())
                };
                let what = format!("{model:?}, mirrored {mirrored}, face {face:?}");
                assert!(hit.lit_at.distance(at) < 1e-5, "{what}: lit at {}, not {at}", hit.lit_at);
                assert!(hit.shading_normal.distance(normal) < 1e-5, "{what}: the normal");
                let color = out.image.get(x, y).unwrap();
                let first = *seen.entry(face).or_insert(color);
                assert_eq!(color, first, "{what}: one colour");
            }
        }
        assert!(seen.len() >= 2, "premise: several faces seen");
    }
}

#[test]
fn the_counts_come_from_the_light_model_and_show_only_what_the_scene_needs() {
    let hits = |s: &Stats| s.hits_per_depth.iter().sum::<u64>();
    // The course scene: k_s = 0 everywhere, no attenuation: none of either is computed.
    let course = cg_trace::render(&shipped("course-sample"), &small(32)).unwrap();
    let s = &course.stats;
    assert_eq!(s.lighting_evaluations, hits(s), "one evaluation per hit shaded");
    assert_eq!((s.specular_evaluations, s.attenuation_evaluations), (0, 0), "{s:?}");
    // The spot light: attenuated at every hit it is evaluated for; specular only where the
    // shiny sphere is lit (in the cone, not in shadow, k_s ≠ 0).
    let spot = cg_trace::render(&shipped("spot-specular"), &small(32)).unwrap();
    let s = &spot.stats;
    assert_eq!(s.attenuation_evaluations, s.lighting_evaluations, "{s:?}");
    assert!(s.specular_evaluations > 0 && s.specular_evaluations < s.lighting_evaluations);
    // Glass and mirrors: hits at every depth are shaded and counted.
    let glass_mirror = cg_trace::render(&shipped("glass-mirror"), &small(32)).unwrap();
    let s = &glass_mirror.stats;
    assert_eq!(s.lighting_evaluations, hits(s));
    assert!(s.specular_evaluations > 0 && s.attenuation_evaluations == 0, "{s:?}");
}

/// Three glass spheres one inside the other with k_r = k_t = 1 (energy from nothing: the scene
/// loader refuses it, a program can build it).
fn nested_glass(size: u32) -> Scene {
    let material = Material { kr: Rgb::ONE, ..glass(1.5) };
    let spheres =
        [1.0, 0.7, 0.4].map(|r| sphere(&format!("glass {r}"), r, material.clone(), vec![]));
    scene(spheres.to_vec(), Vec3::new(0.0, 0.0, 4.0), Vec3::ZERO, size, size)
}

#[test]
fn a_ray_tree_that_never_shrinks_stops_at_the_per_pixel_budget() {
    // k_r + k_t = 2: every hit spawns two rays of weight ≥ 1, so min_weight prunes nothing and
    // the tree would have 2^65 rays per pixel at max_depth 64. The budget stops each pixel at
    // 256 reflected and refracted rays (and the image is still finite).
    let size = 6;
    let out =
        cg_trace::render(&nested_glass(size), &Options { max_depth: 64, ..small(size) }).unwrap();
    let s = &out.stats;
    let global = s.reflection_rays + s.refraction_rays;
    assert!(s.rays_over_budget > 0, "{s:?}");
    assert!(global <= u64::from(size * size) * u64::from(cg_trace::DEFAULT_RAY_BUDGET), "{s:?}");
    assert!(out.image.pixels.iter().all(|c| c.is_finite()));
    // A smaller budget casts fewer rays; 0 casts none.
    let none = cg_trace::render(
        &nested_glass(size),
        &Options { max_depth: 64, ray_budget: 0, ..small(size) },
    )
    .unwrap();
    assert_eq!(none.stats.reflection_rays + none.stats.refraction_rays, 0);
    // At the default depth the budget never binds on the shipped scene.
    let shipped_out = cg_trace::render(&shipped("glass-mirror"), &small(32)).unwrap();
    assert_eq!(shipped_out.stats.rays_over_budget, 0);
}

#[test]
fn colours_beyond_f32s_range_give_a_finite_image() {
    // Light colours of 3e38 (a program can set them; the scene loader bounds colours to 1e6):
    // the light model overflows to ∞, and ∞·0 is NaN; every shaded colour is made finite again
    // (NaN → 0, ∞ → f32::MAX) before it leaves `shade`, and the image is clamped to [0, 1].
    let mut scene = shipped("glass-mirror");
    for light in &mut scene.lights {
        light.diffuse = Rgb::splat(3e38);
        light.specular = Rgb::splat(3e38);
        light.ambient = Rgb::splat(3e38);
    }
    let out = cg_trace::render(&scene, &small(16)).unwrap();
    assert!(out.image.pixels.iter().all(|c| c.is_finite() && c.max_element() <= 1.0));
    let tracer = Tracer::new(&scene, &small(16)).unwrap();
    let c = tracer.trace(&tracer.generate_ray(8, 12), 0, &mut Stats::default());
    assert!(c.is_finite(), "{c}");
}

#[test]
fn row23_huge_texture_coordinates_sample_like_small_ones_under_repeat() {
    // A quad facing the camera with texture coordinates from (k, k) to (k + 1, k + 1), exact in
    // f32: under repeat, the same image as from (0, 0) to (1, 1), bit for bit.
    let texture =
        Texture::from_fn(4, 4, |x, y| [40 + 50 * x as u8, 30 + 60 * y as u8, 90, 255]).unwrap();
    let image = |k: f32, filter: Filter| {
        let mut o =
            object("quad", quad(Vec2::splat(k), Vec2::splat(k + 1.0)), Material::default(), vec![]);
        o.normals = NormalSource::Face;
        o.texture = Some(TextureUse {
            texture: 0,
            sampler: Sampler { filter, wrap_u: Wrap::Repeat, wrap_v: Wrap::Repeat },
            env: TexEnv::Replace,
        });
        let mut s = scene(vec![o], Vec3::new(0.0, 0.0, 2.5), Vec3::ZERO, 16, 16);
        s.textures.push(texture.clone());
        cg_trace::render(&s, &small(16)).unwrap().image
    };
    for filter in [Filter::Nearest, Filter::Bilinear] {
        let reference = image(0.0, filter);
        let colours: std::collections::HashSet<_> = reference.to_rgba8().into_iter().collect();
        assert!(colours.len() > 10, "premise: the texture shows ({} colours)", colours.len());
        for k in [1.0e3, 1.0e5, 1.0e6, -1.0e6] {
            assert!(image(k, filter) == reference, "offset {k:e}, {filter:?}: the image differs");
        }
    }
}

#[test]
fn barycentric_weights_are_in_the_meshs_corner_order_also_when_mirrored() {
    // An uneven triangle, plain and mirrored by scale(−1, 1, 1): the weights the hit reports,
    // applied to the prepared mesh's corners of its face in that face's order (in world space),
    // give the hit point. (The tracer reorders a mirrored object's corners internally.)
    let mesh = Mesh::new(
        vec![Vec3::new(-1.0, -0.8, 0.0), Vec3::new(1.3, -0.5, 0.0), Vec3::new(-0.2, 1.1, 0.0)],
        vec![[0, 1, 2]],
    );
    for mirror in [false, true] {
        let transform =
            if mirror { vec![Factor::scale(Vec3::new(-1.0, 1.0, 1.0))] } else { vec![] };
        let mut o = object("t", mesh.clone(), Material::default(), transform);
        o.normals = NormalSource::Face;
        let s = scene(vec![o], Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, 8, 8);
        let tracer = Tracer::new(&s, &Options::default()).unwrap();
        let prepared = s.objects[0].prepare().unwrap();
        assert_eq!(prepared.mirrored, mirror);
        for target in
            [Vec3::new(0.3, -0.4, 0.0), Vec3::new(-0.5, -0.2, 0.0), Vec3::new(0.0, 0.5, 0.0)]
        {
            let origin = Vec3::new(0.0, 0.0, 3.0);
            let ray = Ray::new(origin, (target - origin).normalize());
            let hit = tracer.intersect(&ray, &mut Stats::default()).expect("a hit");
            let Primitive::Triangle { face, barycentric } = hit.primitive else { panic!() };
            let corners = prepared.mesh.faces[face].map(|i| {
                cg_core::transform::transform_point(
                    prepared.model,
                    prepared.mesh.positions[i as usize],
                )
            });
            let p = barycentric.x * corners[0]
                + barycentric.y * corners[1]
                + barycentric.z * corners[2];
            assert!(p.distance(hit.p) < 1e-5, "mirror {mirror}: Σ bᵢ·pᵢ = {p}, hit at {}", hit.p);
        }
    }
}
