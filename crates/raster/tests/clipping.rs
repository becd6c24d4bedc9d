//! docs/numerics.md row 21: triangles crossing the near plane, or behind the camera, are clipped
//! correctly; nothing behind the eye is drawn; nothing is divided by w ≤ 0; no NaN anywhere.
//!
//! The oracle is the analytic projection, in f64, of the part of each triangle in front of the
//! near plane (clipped by hand here), compared pixel by pixel away from its edges.

mod common;

use cg_core::Rgb;
use cg_core::glam::{DVec2, DVec3, Vec2, Vec3};
use cg_raster::{Options, Output, render};
use common::{Pinhole, inside_by, looking_down_z, object, sample_f64, triangle, unlit};

const RED: Rgb = Rgb::new(1.0, 0.0, 0.0);
/// RED and black in 8 bits (colours are compared after the rounding to the framebuffer: the
/// interpolated colour of a constant-coloured triangle can differ from it in the last bit).
const RED8: [u8; 4] = [255, 0, 0, 255];
const BLACK8: [u8; 4] = [0, 0, 0, 255];

/// No NaN or infinity in the colour or depth buffer, and every depth in `[0, 1]`.
fn assert_finite(out: &Output) {
    for (i, c) in out.image.pixels.iter().enumerate() {
        assert!(
            c.is_finite() && c.min_element() >= 0.0 && c.max_element() <= 1.0,
            "pixel {i} is {c}"
        );
    }
    for (i, z) in out.depth.iter().enumerate() {
        assert!((0.0..=1.0).contains(z), "depth {i} is {z}");
    }
}

/// `polygon` (view space, z ≤ −near) cut at the near plane by hand: the part with z ≤ −near.
fn clip_near(polygon: &[DVec3], near: f64) -> Vec<DVec3> {
    let mut out = Vec::new();
    for i in 0..polygon.len() {
        let (a, b) = (polygon[i], polygon[(i + 1) % polygon.len()]);
        let (da, db) = (-a.z - near, -b.z - near);
        if da >= 0.0 {
            out.push(a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            out.push(a + (b - a) * (da / (da - db)));
        }
    }
    out
}

/// Draws `corners` (view space = world space) as one red, unlit triangle on black and checks every
/// pixel against the analytic projection of its part in front of the near plane: pixels whose
/// centres lie more than `margin` pixels inside it are red with the depth of the triangle's plane
/// there, pixels more than `margin` outside are black with depth 1.
fn assert_clipped_like_the_analytic_projection(
    name: &str,
    corners: [Vec3; 3],
    size: u32,
) -> Output {
    let mut scene = looking_down_z(size, size, 90.0);
    scene.cull_back_faces = false;
    scene.objects.push(object(name, triangle(corners[0], corners[1], corners[2]), unlit(RED)));
    let out = render(&scene, &Options::default()).unwrap();
    assert_finite(&out);

    let camera = Pinhole::of(&scene);
    let visible = clip_near(&corners.map(Vec3::as_dvec3), camera.near);
    let on_screen: Vec<DVec2> = visible.iter().map(|&p| camera.window(p)).collect();
    let [a, b, c] = corners.map(Vec3::as_dvec3);
    let normal = (b - a).cross(c - a);
    let margin = 0.01;
    let rgba = out.image.to_rgba8();
    let (mut inside, mut outside) = (0, 0);
    for y in 0..size {
        for x in 0..size {
            let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let at = (y * size + x) as usize;
            let (color, depth) = (rgba[at], out.depth[at]);
            let d = if on_screen.len() >= 3 { inside_by(&on_screen, centre) } else { -1.0 };
            if d > margin {
                inside += 1;
                // The window depth where the ray through `w` meets the triangle's plane.
                let plane_depth = |w: DVec2| {
                    let ray = camera.ray(w);
                    camera.depth((ray * (normal.dot(a) / normal.dot(ray))).z)
                };
                let expected = plane_depth(centre);
                // Corners are snapped to 1/256 pixel (up to 1/512 per axis), which moves the
                // interpolated plane: allow the depth change over 2/256 pixel, plus f32 rounding.
                let step = 2.0 / 256.0;
                let slope = (plane_depth(centre + DVec2::X * step) - expected).abs()
                    + (plane_depth(centre + DVec2::Y * step) - expected).abs();
                let tolerance = slope + 1e-6;
                assert_eq!(
                    color, RED8,
                    "{name}: pixel ({x}, {y}) is {d:.3} px inside the visible part but not drawn"
                );
                assert!(
                    (f64::from(depth) - expected).abs() < tolerance,
                    "{name}: depth at ({x}, {y}) is {depth}, the plane is at {expected} (tolerance {tolerance:.2e})"
                );
            } else if d < -margin {
                outside += 1;
                assert_eq!(
                    color, BLACK8,
                    "{name}: pixel ({x}, {y}) is {:.3} px outside the visible part but drawn",
                    -d
                );
                assert_eq!(depth, 1.0, "{name}: depth written outside at ({x}, {y})");
            }
        }
    }
    assert!(
        inside + outside > (size * size) as usize * 9 / 10,
        "{name}: premise: most pixels are decided"
    );
    out
}

#[test]
fn row21_a_triangle_crossing_the_near_plane_is_clipped_to_its_visible_part() {
    // A floor triangle (y = −1) from 4 units ahead to 3 units behind the eye: only the part at
    // z ≤ −1 is drawn; its projection reaches the bottom of the image.
    let out = assert_clipped_like_the_analytic_projection(
        "floor crossing the near plane",
        [Vec3::new(-2.0, -1.0, -4.0), Vec3::new(2.0, -1.0, -4.0), Vec3::new(0.0, -1.0, 3.0)],
        32,
    );
    assert_eq!(out.stats.triangles_clipped, 1);
    assert!(
        out.stats.triangles_drawn >= 2,
        "the clipped quadrilateral is drawn as a fan: {}",
        out.stats
    );

    // Standing up, one corner far behind and to the side: the clipped part is a thin wedge.
    assert_clipped_like_the_analytic_projection(
        "wall crossing the near plane",
        [Vec3::new(-3.0, -2.0, -6.0), Vec3::new(1.0, 3.0, -2.0), Vec3::new(4.0, -1.0, 5.0)],
        32,
    );
}

#[test]
fn row21_a_corner_exactly_at_the_eye_is_never_divided_by() {
    // w = 0 at the eye: the corner is clipped away before the perspective divide.
    let out = assert_clipped_like_the_analytic_projection(
        "corner at the eye",
        [Vec3::ZERO, Vec3::new(3.0, -1.0, -5.0), Vec3::new(-3.0, -1.0, -5.0)],
        24,
    );
    assert_eq!(out.stats.triangles_clipped, 1);
    // A corner on the eye plane (z = 0, w = 0) beside the eye.
    assert_clipped_like_the_analytic_projection(
        "corner on the eye plane",
        [Vec3::new(2.0, 0.5, 0.0), Vec3::new(1.0, -1.0, -5.0), Vec3::new(-3.0, -1.0, -4.0)],
        24,
    );
}

#[test]
fn row21_a_triangle_behind_the_eye_draws_nothing() {
    for corners in [
        // Entirely behind the eye (z > 0): its mirror image through the eye would be on screen.
        [Vec3::new(-1.0, -1.0, 4.0), Vec3::new(1.0, -1.0, 4.0), Vec3::new(0.0, 1.0, 4.0)],
        // Between the eye and the near plane.
        [Vec3::new(-1.0, -1.0, -0.5), Vec3::new(1.0, -1.0, -0.5), Vec3::new(0.0, 1.0, -0.9)],
        // Touching the eye, the rest behind.
        [Vec3::ZERO, Vec3::new(1.0, -1.0, 3.0), Vec3::new(-1.0, 1.0, 3.0)],
    ] {
        let mut scene = looking_down_z(16, 16, 90.0);
        scene.cull_back_faces = false;
        scene.objects.push(object(
            "behind",
            triangle(corners[0], corners[1], corners[2]),
            unlit(RED),
        ));
        let out = render(&scene, &Options::default()).unwrap();
        assert_finite(&out);
        assert!(
            out.image.to_rgba8().iter().all(|&c| c == BLACK8),
            "{corners:?}: something was drawn"
        );
        assert!(out.depth.iter().all(|&z| z == 1.0), "{corners:?}: a depth was written");
        assert_eq!(out.stats.fragments, 0, "{corners:?}: {}", out.stats);
        assert_eq!(out.stats.triangles_outside, 1, "{corners:?}: {}", out.stats);
    }
}

#[test]
fn row21_a_huge_floor_through_both_clip_planes_ends_at_the_far_horizon() {
    // A floor a million units wide, from behind the eye to far beyond the far plane: clipped at
    // the near plane, the far plane and the guard band (its corners would be ~10¹¹ pixels off
    // screen). It must fill exactly the rows below where the far plane cuts it: y = −1 at
    // z = −far projects to y_ndc = −f/far.
    let size = 32;
    let mut scene = looking_down_z(size, size, 90.0);
    let r = 1.0e6;
    let floor = cg_core::mesh::Mesh::new(
        vec![
            Vec3::new(-r, -1.0, r),
            Vec3::new(r, -1.0, r),
            Vec3::new(r, -1.0, -r),
            Vec3::new(-r, -1.0, -r),
        ],
        vec![[0, 1, 2], [0, 2, 3]],
    );
    scene.objects.push(object("floor", floor, unlit(RED)));
    let out = render(&scene, &Options::default()).unwrap();
    assert_finite(&out);
    let camera = Pinhole::of(&scene);
    let horizon = camera.window(DVec3::new(0.0, -1.0, -camera.far)).y;
    assert!(
        (16.0..16.5).contains(&horizon),
        "premise: the far edge lies between two rows of centres, at {horizon}"
    );
    let rgba = out.image.to_rgba8();
    for y in 0..size {
        for x in 0..size {
            let drawn = rgba[(y * size + x) as usize] == RED8;
            let expected = f64::from(y) + 0.5 > horizon;
            assert_eq!(
                drawn, expected,
                "pixel ({x}, {y}): drawn {drawn}, the far horizon is at y = {horizon:.3}"
            );
        }
    }
    assert_eq!(out.stats.triangles_clipped, 2, "{}", out.stats);
}

/// The attributes of the vertices that clipping makes: a lit, coloured, textured floor triangle
/// crossing the near plane, in Phong and Gouraud shading, against the analytic image.
///
/// Corners A, B ahead of the eye and C behind it; the near plane cuts AC and BC, so the visible
/// part is the quadrilateral A, B and two new vertices, whose position, normal, colour and
/// texture coordinate are interpolated in clip space. The oracle, per pixel centre: the ray meets
/// the floor at P; P's barycentric weights in ABC (f64, the *unclipped* triangle) blend the
/// corners' normals, colours and texture coordinates; Phong lights P with
/// `cg_core::light::shade` (the lecture's model with a local viewer and a point light, so P and
/// N both matter), Gouraud blends the corners' lit colours (clamped each); the texture is
/// sampled by the specification's bilinear formula. Every pixel more than a pixel inside the
/// visible part must match within 1e-4 (measured: 1.3e-5, from corners snapped to 1/256 pixel
/// and f32 interpolation; swapping t and 1 − t in the clipper is off by tenths).
/// Texture coordinates are offset by 0 and by 1e5 (repeat: the same texture; the clipped
/// vertices must keep their precision).
#[test]
fn row21_clipped_vertices_carry_position_normal_colour_and_texture_coordinate() {
    use cg_core::light::{Light, LightKind, LightModel, Material, Specular, shade};
    use cg_core::scene::{NormalSource, Shading, TextureUse};
    use cg_core::texture::{Filter, Sampler, TexEnv, Texture, Wrap};

    let size = 32u32;
    let corners =
        [Vec3::new(-2.0, -1.0, -4.0), Vec3::new(2.0, -1.0, -4.0), Vec3::new(0.0, -1.0, 3.0)];
    let normals = [
        Vec3::new(0.3, 1.0, 0.0).normalize(),
        Vec3::new(-0.3, 1.0, 0.2).normalize(),
        Vec3::new(0.0, 1.0, -0.4).normalize(),
    ];
    let colors = [Rgb::new(1.0, 0.3, 0.2), Rgb::new(0.2, 1.0, 0.3), Rgb::new(0.3, 0.2, 1.0)];
    let base_uvs = [Vec2::new(0.1, 0.2), Vec2::new(1.3, 0.1), Vec2::new(0.6, 2.4)];
    let texture = Texture::from_fn(2, 2, |x, y| match (x, y) {
        (0, 0) => [255, 128, 0, 255],
        (1, 0) => [0, 255, 128, 255],
        (0, 1) => [128, 0, 255, 255],
        _ => [255, 255, 255, 255],
    })
    .unwrap();
    let sampler = Sampler { filter: Filter::Bilinear, wrap_u: Wrap::Repeat, wrap_v: Wrap::Repeat };
    let material = Material { ks: Rgb::splat(0.4), shininess: 6.0, ..Material::default() };
    let light = Light {
        kind: LightKind::Point { position: Vec3::new(1.0, 1.0, -2.0) },
        ambient: Rgb::ZERO,
        diffuse: Rgb::splat(0.9),
        specular: Rgb::ONE,
        attenuation: Default::default(),
    };
    let model = LightModel::Lecture { specular: Specular::Phong, local_viewer: true };
    let ambient = Rgb::splat(0.2);
    let lit = |p: Vec3, n: Vec3, c: Rgb| {
        let v = (-p).normalize();
        let m = material.with_color(Some(c));
        shade(model, ambient, std::slice::from_ref(&light), &m, p, n, v)
            .total()
            .clamp(Rgb::ZERO, Rgb::ONE)
            .as_dvec3()
    };
    let vertex_lit = [0, 1, 2].map(|i| lit(corners[i], normals[i], colors[i]));

    for offset in [0.0f32, 1.0e5] {
        for shading in [Shading::Phong, Shading::Gouraud] {
            let mut scene = looking_down_z(size, size, 90.0);
            scene.cull_back_faces = false;
            scene.shading = shading;
            scene.light_model = model;
            scene.global_ambient = ambient;
            scene.lights = vec![light.clone()];
            let mut mesh = triangle(corners[0], corners[1], corners[2]);
            mesh.normals = Some(normals.to_vec());
            mesh.colors = Some(colors.to_vec());
            mesh.uvs = Some(base_uvs.map(|uv| uv + Vec2::splat(offset)).to_vec());
            let mut floor = object("floor", mesh, material.clone());
            floor.normals = NormalSource::Given;
            floor.texture = Some(TextureUse { texture: 0, sampler, env: TexEnv::Modulate });
            scene.objects.push(floor);
            scene.textures.push(texture.clone());
            let out = render(&scene, &Options::default()).unwrap();
            assert_finite(&out);
            assert_eq!(out.stats.triangles_clipped, 1, "premise: {}", out.stats);

            let camera = Pinhole::of(&scene);
            let visible = clip_near(&corners.map(Vec3::as_dvec3), camera.near);
            assert_eq!(visible.len(), 4, "premise: the near plane cuts two edges");
            let on_screen: Vec<DVec2> = visible.iter().map(|&p| camera.window(p)).collect();
            let [a, b, c] = corners.map(Vec3::as_dvec3);
            let area = (b - a).cross(c - a).y;
            let (mut checked, mut near_new_vertices, mut worst) = (0, 0, 0.0f64);
            for y in 0..size {
                for x in 0..size {
                    let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                    if inside_by(&on_screen, centre) < 1.0 {
                        continue;
                    }
                    let d = camera.ray(centre);
                    let p = d * (-1.0 / d.y);
                    let w = [
                        (c - b).cross(p - b).y / area,
                        (a - c).cross(p - c).y / area,
                        (b - a).cross(p - a).y / area,
                    ];
                    let blend3 = |v: [DVec3; 3]| v[0] * w[0] + v[1] * w[1] + v[2] * w[2];
                    // The coordinates as stored in f32 (near 1e5 they are multiples of 2⁻⁷),
                    // less the offset, which repeat does not see.
                    let stored = |i: usize| {
                        (base_uvs[i] + Vec2::splat(offset)).as_dvec2() - f64::from(offset)
                    };
                    let uv = stored(0) * w[0] + stored(1) * w[1] + stored(2) * w[2];
                    let color = match shading {
                        Shading::Gouraud => blend3(vertex_lit),
                        _ => {
                            let n = blend3(normals.map(Vec3::as_dvec3)).normalize();
                            let k = blend3(colors.map(Vec3::as_dvec3));
                            lit(p.as_vec3(), n.as_vec3(), k.as_vec3())
                        }
                    };
                    let expected =
                        (color * sample_f64(&texture, uv, sampler)).clamp(DVec3::ZERO, DVec3::ONE);
                    let got = out.image.pixels[(y * size + x) as usize].as_dvec3();
                    let error = (got - expected).abs().max_element();
                    worst = worst.max(error);
                    assert!(
                        error < 1e-4,
                        "{shading:?}, uv offset {offset:e}: pixel ({x}, {y}) at P = {p:.3} is {got:.4}, expected {expected:.4}"
                    );
                    checked += 1;
                    // Pixels nearer the new vertices (−z < 2: the part cut from AC and BC).
                    near_new_vertices += usize::from(p.z > -2.0);
                }
            }
            eprintln!("{shading:?}, offset {offset:e}: {checked} pixels, worst {worst:.2e}");
            assert!(
                checked > 200 && near_new_vertices > 50,
                "premise: {checked}, {near_new_vertices}"
            );
        }
    }
}
