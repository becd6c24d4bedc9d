//! OpenGL's lighting, pixel for pixel, against the OpenGL 1.x equation written again in f64 in
//! `common::gl_lit_color`.
//!
//! Design: each scene is chosen so that the lit colour is the same at every vertex the
//! rasterizer interpolates between — a constant normal with a directional light and an infinite
//! viewer; a spot light on the axis of an equilateral triangle; flat-shaded triangles (one
//! provoking vertex, lit with its own normal), lit by a point light or by an area light's six
//! samples. Then every covered pixel must show that one colour, rounded to 8 bits,
//! within 1/255 (llvmpipe evaluates pow, rsqrt and the interpolation in f32), and nothing in the
//! test depends on how OpenGL interpolates.

mod common;

use cg_core::Rgb;
use cg_core::glam::{DVec3, Vec2, Vec3};
use cg_core::light::LightModel;
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{Scene, Shading};
use common::*;

/// Asserts that the image shows `expected` (within 1/255) on the projected polygon `corners`
/// (world space, convex, in order) and the background elsewhere.
fn assert_uniform(
    name: &str,
    scene: &Scene,
    pixels: &[[u8; 3]],
    corners: &[Vec3],
    expected: [u8; 3],
) {
    let (w, h) = (scene.width, scene.height);
    let screen: Vec<Vec2> = corners.iter().map(|&p| project(scene, p)).collect();
    let n = screen.len();
    let area = 0.5 * (0..n).map(|i| screen[i].perp_dot(screen[(i + 1) % n])).sum::<f32>().abs();
    let perimeter: f32 = (0..n).map(|i| (screen[(i + 1) % n] - screen[i]).length()).sum();
    let centroid = screen.iter().copied().sum::<Vec2>() / n as f32;
    let art = || {
        ascii(pixels, w, |p| {
            if channel_diff(p, expected) <= 1 {
                '#'
            } else if p == BACKGROUND {
                '.'
            } else {
                '?'
            }
        })
    };
    let mut covered = 0;
    for (i, &p) in pixels.iter().enumerate() {
        if channel_diff(p, expected) <= 1 {
            covered += 1;
        } else {
            assert_eq!(
                p,
                BACKGROUND,
                "{name}: pixel ({}, {}) is neither the lit colour {expected:?} (±1) nor the \
                 background ('#' lit, '.' background, '?' other):\n{}",
                i % w as usize,
                i / w as usize,
                art()
            );
        }
    }
    let c = pixels[centroid.y as usize * w as usize + centroid.x as usize];
    assert!(
        channel_diff(c, expected) <= 1,
        "{name}: the pixel at the centre ({centroid}) is {c:?}, expected {expected:?} (±1)"
    );
    assert!(
        covered as f32 >= area - perimeter && covered as f32 <= area + perimeter,
        "{name}: {covered} pixels lit, but the polygon covers {area:.1} px² (perimeter \
         {perimeter:.1} px) of the {w}×{h} image:\n{}",
        art()
    );
}

fn white_light(position: [f64; 4]) -> GlLight {
    GlLight {
        position,
        ambient: [0.1, 0.15, 0.05],
        diffuse: [0.9, 0.8, 0.7],
        specular: [1.0, 0.9, 0.8],
        spot: None,
        attenuation: [1.0, 0.0, 0.0],
    }
}

/// The tilted square's normal N and the infinite viewer's V (the camera's backward axis), by the
/// test's own rotations: the camera is Ry(yaw)·Rx(pitch) applied to +Z; the square is turned by a
/// further Ry(25°).
fn normal_and_view() -> (DVec3, DVec3) {
    let n = rot_y(20.0, rot_x(-30.0, rot_y(25.0, DVec3::Z)));
    let v = rot_y(20.0, rot_x(-30.0, DVec3::Z));
    (n, v)
}

/// A 3×3 square facing the orbit camera (yaw 20°, pitch −30°), then turned by 25° about its own
/// Y axis, lit by one directional light: N, L and V are the same at every vertex.
fn tilted_quad_scene(material: &GlMaterial, light: &GlLight) -> (Scene, Vec<Vec3>, DVec3) {
    let (yaw, pitch, turn) = (20.0, -30.0, 25.0);
    let mut s = scene(48, 48, orbit(yaw, pitch, 7.0));
    s.global_ambient = Rgb::new(0.2, 0.25, 0.3);
    s.lights = vec![kit_light(light)];
    let transform = MatrixProduct::identity()
        .then(Factor::rotate_y_deg(yaw))
        .then(Factor::rotate_x_deg(pitch))
        .then(Factor::rotate_y_deg(turn));
    let corners = quad(1.5).positions.iter().map(|&p| to_world(&transform, p)).collect();
    s.objects = vec![object("quad", quad(1.5), kit_material(material), transform)];
    let (n, v) = normal_and_view();
    let p = DVec3::ZERO; // irrelevant for a directional light and an infinite viewer
    let c = gl_lit_color(p, n, Viewer::Infinite(v), [0.2, 0.25, 0.3], material, &[*light]);
    (s, corners, c)
}

#[test]
fn a_directional_light_and_an_infinite_viewer_light_a_flat_square_uniformly_as_the_gl_equation_says()
 {
    if !cg_glref::require() {
        return;
    }
    let material = GlMaterial {
        ambient: [0.3, 0.5, 0.7],
        diffuse: [0.6, 0.4, 0.2],
        specular: [0.0; 3],
        emission: [0.05, 0.0, 0.1],
        shininess: 0.0,
    };
    let light = white_light([0.3, 1.0, 0.6, 0.0]);
    let (s, corners, c) = tilted_quad_scene(&material, &light);
    // Not saturated, so the value is a real test of the equation.
    assert!(c.max_element() < 0.95 && c.min_element() > 0.05, "{c}");
    let pixels = render_rgb(&s);
    assert_uniform("diffuse", &s, &pixels, &corners, to_bytes(c));
}

#[test]
fn blinn_specular_with_an_infinite_viewer_matches_the_gl_equation_and_saturates_at_255() {
    if !cg_glref::require() {
        return;
    }
    let material = GlMaterial {
        ambient: [0.2, 0.3, 0.1],
        diffuse: [0.5, 0.3, 0.2],
        specular: [0.9, 0.5, 0.3],
        emission: [0.3, 0.0, 0.0],
        shininess: 12.0,
    };
    // The light near the mirror direction of V, so N·H is near 1 and the highlight shows.
    let (n, v) = normal_and_view();
    let l = 2.0 * n.dot(v) * n - v + DVec3::new(0.2, 0.1, -0.1);
    let light = white_light([l.x, l.y, l.z, 0.0]);
    let (s, corners, c) = tilted_quad_scene(&material, &light);
    let specular_only = {
        let dark =
            GlMaterial { ambient: [0.0; 3], diffuse: [0.0; 3], emission: [0.0; 3], ..material };
        gl_lit_color(DVec3::ZERO, n, Viewer::Infinite(v), [0.0; 3], &dark, &[light])
    };
    // The highlight is strong but not saturated in green and blue; red saturates (clamp).
    assert!(specular_only.y > 0.1, "the specular term is too small to test: {specular_only}");
    assert!(c.x > 1.0 && c.y < 0.95 && c.z < 0.95, "{c}");
    let pixels = render_rgb(&s);
    assert_uniform("specular", &s, &pixels, &corners, to_bytes(c));
}

/// An equilateral triangle of circumradius 2 in the plane z = 0, facing +Z, centred on the
/// origin; corner k at angle 90° + 120°·k (counter-clockwise from +Z).
fn equilateral() -> [Vec3; 3] {
    [90.0f32, 210.0, 330.0].map(|deg| {
        let (s, c) = deg.to_radians().sin_cos();
        Vec3::new(2.0 * c, 2.0 * s, 0.0)
    })
}

#[test]
fn a_spot_light_with_attenuation_on_the_axis_of_an_equilateral_triangle_lights_it_uniformly() {
    if !cg_glref::require() {
        return;
    }
    // The spot sits on the triangle's axis and points along it, the eye too (local viewer): every
    // corner has the same distance, spot angle, N·L and N·H, so Gouraud shading gives one colour.
    let eye = DVec3::new(0.0, 0.0, 8.0);
    let light = GlLight {
        position: [0.0, 0.0, 3.0, 1.0],
        ambient: [0.2, 0.1, 0.3],
        diffuse: [1.0, 0.9, 0.8],
        specular: [1.0, 1.0, 1.0],
        spot: Some(([0.0, 0.0, -1.0], 45.0, 6.0)),
        attenuation: [0.4, 0.15, 0.03],
    };
    let material = GlMaterial {
        ambient: [0.4, 0.4, 0.4],
        diffuse: [0.7, 0.5, 0.3],
        specular: [0.6, 0.6, 0.6],
        emission: [0.0, 0.05, 0.1],
        shininess: 20.0,
    };
    let corners = equilateral();
    let mut s = scene(48, 48, look_at_origin(eye.as_vec3()));
    s.light_model = LightModel::OpenGl { local_viewer: true };
    s.global_ambient = Rgb::splat(0.1);
    s.lights = vec![kit_light(&light)];
    let mesh = triangle(corners[0], corners[1], corners[2]);
    s.objects = vec![object("triangle", mesh, kit_material(&material), MatrixProduct::identity())];
    let at = |p: Vec3| {
        gl_lit_color(p.as_dvec3(), DVec3::Z, Viewer::Local(eye), [0.1; 3], &material, &[light])
    };
    let c = at(corners[0]);
    for p in corners {
        // The corners are f32, so the symmetry holds to f32 rounding.
        assert!((at(p) - c).abs().max_element() < 1e-6, "the scene is not symmetric");
    }
    // The spot factor, the attenuation and the highlight all matter here: without them the
    // colour would be another (the centre, straight under the light, is brighter).
    let centre = at(Vec3::ZERO);
    assert!(channel_diff(to_bytes(centre), to_bytes(c)) > 10, "{centre} vs {c}");
    assert!(c.max_element() < 0.95, "{c}");
    let pixels = render_rgb(&s);
    assert_uniform("spot", &s, &pixels, &corners, to_bytes(c));
}

#[test]
fn gl_flat_colours_a_triangle_with_its_last_vertex_lit_by_a_point_light_and_a_spot() {
    if !cg_glref::require() {
        return;
    }
    // An uneven triangle and a point light off to the side: each corner gets another colour.
    // Under GL_FLAT the whole triangle takes the colour of its last (provoking) vertex.
    let eye = Vec3::new(1.0, 2.0, 9.0);
    let corners =
        [Vec3::new(-2.5, -1.5, 0.0), Vec3::new(2.0, -2.0, 0.5), Vec3::new(0.5, 2.5, -0.5)];
    let light = GlLight {
        position: [3.0, 2.0, 4.0, 1.0],
        ambient: [0.1, 0.1, 0.1],
        diffuse: [0.9, 0.9, 0.9],
        specular: [1.0, 1.0, 1.0],
        spot: Some(([-3.0, -2.5, -4.0], 60.0, 3.0)),
        attenuation: [0.5, 0.05, 0.01],
    };
    let material = GlMaterial {
        ambient: [0.3, 0.2, 0.4],
        diffuse: [0.8, 0.5, 0.3],
        specular: [0.5, 0.5, 0.5],
        emission: [0.0; 3],
        shininess: 8.0,
    };
    let mut s = scene(48, 48, look_at_origin(eye));
    s.shading = Shading::Flat;
    s.global_ambient = Rgb::splat(0.2);
    s.lights = vec![kit_light(&light)];
    let mesh = triangle(corners[0], corners[1], corners[2]);
    s.objects = vec![object("triangle", mesh, kit_material(&material), MatrixProduct::identity())];
    let [a, b, c] = corners.map(|p| p.as_dvec3());
    let n = (b - a).cross(c - a).normalize();
    // Infinite viewer: V is the camera's backward axis, from the target to the eye.
    let v = eye.as_dvec3().normalize();
    let at = |p: DVec3| gl_lit_color(p, n, Viewer::Infinite(v), [0.2; 3], &material, &[light]);
    let last = to_bytes(at(c));
    assert!(
        channel_diff(to_bytes(at(a)), last) > 3 && channel_diff(to_bytes(at(b)), last) > 3,
        "the corners must differ for this test to tell them apart: {:?} {:?} {last:?}",
        to_bytes(at(a)),
        to_bytes(at(b))
    );
    let pixels = render_rgb(&s);
    assert_uniform("flat", &s, &pixels, &corners, last);
}

#[test]
fn gl_flat_lights_the_last_vertex_with_its_own_normal() {
    if !cg_glref::require() {
        return;
    }
    // The same triangle with three different vertex normals (NormalSource::Given): the script
    // sends each vertex's own glNormal under GL_FLAT too (the course's program changes only
    // glShadeModel), and GL lights the last vertex with *its* normal — not the face normal, not
    // another corner's — which is what the kit's renderers reproduce in OpenGL's model.
    let eye = Vec3::new(1.0, 2.0, 9.0);
    let corners =
        [Vec3::new(-2.5, -1.5, 0.0), Vec3::new(2.0, -2.0, 0.5), Vec3::new(0.5, 2.5, -0.5)];
    let normals = [Vec3::new(-0.3, -0.2, 1.0), Vec3::new(0.4, -0.3, 1.0), Vec3::new(0.2, 0.6, 1.0)]
        .map(Vec3::normalize);
    let light = GlLight {
        position: [3.0, 2.0, 4.0, 1.0],
        ambient: [0.1, 0.1, 0.1],
        diffuse: [0.9, 0.9, 0.9],
        specular: [1.0, 1.0, 1.0],
        spot: None,
        attenuation: [1.0, 0.0, 0.0],
    };
    let material = GlMaterial {
        ambient: [0.3, 0.2, 0.4],
        diffuse: [0.8, 0.5, 0.3],
        specular: [0.5, 0.5, 0.5],
        emission: [0.0; 3],
        shininess: 8.0,
    };
    let mut s = scene(48, 48, look_at_origin(eye));
    s.shading = Shading::Flat;
    s.global_ambient = Rgb::splat(0.2);
    s.lights = vec![kit_light(&light)];
    let mut mesh = triangle(corners[0], corners[1], corners[2]);
    mesh.normals = Some(normals.to_vec());
    let mut o = object("triangle", mesh, kit_material(&material), MatrixProduct::identity());
    o.normals = cg_core::scene::NormalSource::Given;
    s.objects = vec![o];
    let v = eye.as_dvec3().normalize();
    let at = |p: Vec3, n: Vec3| {
        let (p, n) = (p.as_dvec3(), n.as_dvec3());
        to_bytes(gl_lit_color(p, n, Viewer::Infinite(v), [0.2; 3], &material, &[light]))
    };
    let expected = at(corners[2], normals[2]);
    let [a, b, c] = corners.map(|p| p.as_dvec3());
    let face = (b - a).cross(c - a).normalize().as_vec3();
    let others = [at(corners[2], face), at(corners[0], normals[0]), at(corners[1], normals[1])];
    assert!(
        others.iter().all(|&o| channel_diff(o, expected) > 3),
        "the rules must differ for this test to tell them apart: {others:?} vs {expected:?}"
    );
    let pixels = render_rgb(&s);
    assert_uniform("flat-vertex-normal", &s, &pixels, &corners, expected);
}

#[test]
fn an_area_light_lights_like_its_grid_of_point_lights_one_gl_light_each() {
    if !cg_glref::require() {
        return;
    }
    // A 2 × 3 area light above a flat-shaded triangle: six GL lights. The oracle places the six
    // samples itself, at the cell centres, each with 1/6 of the colours, shining to the side of
    // edge_u × edge_v only (a spot with a 90° cut-off).
    let (corner, edge_u, edge_v) =
        (DVec3::new(-2.0, 4.0, -1.0), DVec3::new(3.0, 0.0, 0.0), DVec3::new(0.0, 0.5, 2.0));
    let axis = edge_u.cross(edge_v).normalize();
    assert!(axis.y < 0.0, "the light must face the triangle below it");
    let (ambient, diffuse, specular) = ([0.3, 0.3, 0.6], [1.2, 1.0, 0.9], [0.6, 0.6, 0.6]);
    let attenuation = [0.6, 0.05, 0.02];
    let mut samples = Vec::new();
    for j in 0..3 {
        for i in 0..2 {
            let p = corner + (i as f64 + 0.5) / 2.0 * edge_u + (j as f64 + 0.5) / 3.0 * edge_v;
            samples.push(GlLight {
                position: [p.x, p.y, p.z, 1.0],
                ambient: ambient.map(|c| c / 6.0),
                diffuse: diffuse.map(|c| c / 6.0),
                specular: specular.map(|c| c / 6.0),
                spot: Some((axis.to_array(), 90.0, 0.0)),
                attenuation,
            });
        }
    }
    let material = GlMaterial {
        ambient: [0.5, 0.4, 0.3],
        diffuse: [0.7, 0.6, 0.5],
        specular: [0.4, 0.4, 0.4],
        emission: [0.0; 3],
        shininess: 16.0,
    };
    let eye = Vec3::new(0.0, 6.0, 7.0);
    let corners = [Vec3::new(-3.0, 0.0, 2.0), Vec3::new(3.0, 0.0, 2.5), Vec3::new(0.5, 0.0, -3.0)];
    let mut s = scene(48, 48, look_at_origin(eye));
    s.shading = Shading::Flat;
    s.global_ambient = Rgb::splat(0.1);
    s.lights = vec![cg_core::light::Light {
        kind: cg_core::light::LightKind::Area {
            corner: corner.as_vec3(),
            edge_u: edge_u.as_vec3(),
            edge_v: edge_v.as_vec3(),
            samples: [2, 3],
        },
        ambient: DVec3::from_array(ambient).as_vec3(),
        diffuse: DVec3::from_array(diffuse).as_vec3(),
        specular: DVec3::from_array(specular).as_vec3(),
        attenuation: cg_core::light::Attenuation { constant: 0.6, linear: 0.05, quadratic: 0.02 },
    }];
    let mesh = triangle(corners[0], corners[1], corners[2]);
    s.objects = vec![object("triangle", mesh, kit_material(&material), MatrixProduct::identity())];
    let v = eye.as_dvec3().normalize();
    let c = gl_lit_color(
        corners[2].as_dvec3(),
        DVec3::Y,
        Viewer::Infinite(v),
        [0.1; 3],
        &material,
        &samples,
    );
    let one = gl_lit_color(
        corners[2].as_dvec3(),
        DVec3::Y,
        Viewer::Infinite(v),
        [0.1; 3],
        &material,
        &samples[..1],
    );
    assert!(channel_diff(to_bytes(c), to_bytes(one)) > 10, "every sample must count: {c} vs {one}");
    assert!(c.max_element() < 0.95, "{c}");
    let pixels = render_rgb(&s);
    assert_uniform("area", &s, &pixels, &corners, to_bytes(c));
}
