//! Flat, Gouraud and Phong shading (フラット／グロー／フォンシェーディング) of a coarse sphere with
//! a specular highlight, against an analytic per-pixel reference computed here: a ray–sphere
//! intersection and `cg_core::light::shade` at every pixel centre.
//!
//! The lecture's claims, measured: Phong keeps the highlight that Gouraud loses (Gouraud can
//! only interpolate the vertex colours, and the highlight lies between vertices); flat shading
//! gives one colour per face.

mod common;

use cg_core::Rgb;
use cg_core::glam::{DVec2, DVec3, Vec3};
use cg_core::image::to_unorm8;
use cg_core::light::{Light, LightKind, LightModel, Material, Specular, shade};
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{NormalSource, Scene, Shading};
use cg_core::shapes::icosphere;
use cg_raster::{Options, Output, render};
use common::{Pinhole, inside_by, looking_down_z, object};

const SIZE: u32 = 96;
/// The sphere's centre (the eye is at the origin, looking down −Z).
const CENTRE: Vec3 = Vec3::new(0.0, 0.0, -4.0);

/// A unit icosphere of 80 faces with its exact normals at the vertices, lit by one directional
/// light placed so that the mirror highlight sits exactly at the centre of the face that looks
/// most directly at the camera (N* = that face's centroid direction, L = 2(N*·V)N* − V with the
/// infinite viewer's V = +Z), under the lecture's model with Phong's (R·V)ⁿ.
fn sphere_scene() -> (Scene, Vec3) {
    let mut mesh = icosphere(1.0, 1).unwrap();
    mesh.normals = Some(mesh.positions.iter().map(|p| p.normalize()).collect());
    let centroid_direction = |f: &[u32; 3]| {
        (f.iter().map(|&i| mesh.positions[i as usize].as_dvec3()).sum::<DVec3>()).normalize()
    };
    let facing =
        mesh.faces.iter().map(centroid_direction).max_by(|a, b| a.z.total_cmp(&b.z)).unwrap();
    let v = DVec3::Z;
    let to_light = (2.0 * facing.dot(v) * facing - v).as_vec3();

    let mut scene = looking_down_z(SIZE, SIZE, 45.0);
    scene.clear_color = Rgb::new(0.5, 0.5, 0.8);
    scene.light_model = LightModel::Lecture { specular: Specular::Phong, local_viewer: false };
    scene.global_ambient = Rgb::splat(0.2);
    scene.lights = vec![Light {
        kind: LightKind::Directional { to_light },
        ambient: Rgb::ZERO,
        diffuse: Rgb::ONE,
        specular: Rgb::ONE,
        attenuation: Default::default(),
    }];
    // Peak ≈ 0.02 + 0.4 + 0.5 < 1: nothing clamps, so peaks can be compared.
    let material = Material {
        ka: Rgb::splat(0.1),
        kd: Rgb::splat(0.4),
        ks: Rgb::splat(0.5),
        shininess: 32.0,
        ..Material::default()
    };
    let mut sphere = object("sphere", mesh, material);
    sphere.normals = NormalSource::Given;
    sphere.transform = MatrixProduct::identity().then(Factor::translate(CENTRE));
    scene.objects.push(sphere);
    (scene, to_light)
}

/// The scene's light model at a point with normal `n` (infinite viewer), clamped.
fn lit(scene: &Scene, p: Vec3, n: Vec3) -> Rgb {
    let m = &scene.objects[0].material;
    shade(scene.light_model, scene.global_ambient, &scene.lights, m, p, n, Vec3::Z)
        .total()
        .clamp(Rgb::ZERO, Rgb::ONE)
}

/// The analytic image: for each pixel centre whose ray meets the exact unit sphere, the lit
/// colour there, and how far inside the sphere's outline the centre is (pixels).
fn analytic(scene: &Scene) -> Vec<Option<(Rgb, f64)>> {
    let camera = Pinhole::of(scene);
    let c = CENTRE.as_dvec3();
    let mut out = Vec::new();
    for y in 0..SIZE {
        for x in 0..SIZE {
            let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
            let d = camera.ray(centre);
            // |t·d − c|² = 1 with |d| = 1: t² − 2t(d·c) + |c|² − 1 = 0, the nearer root.
            let (b, k) = (d.dot(c), c.length_squared() - 1.0);
            let disc = b * b - k;
            if disc <= 0.0 {
                out.push(None);
                continue;
            }
            let p = d * (b - disc.sqrt());
            let n = p - c;
            // Distance of the pixel centre inside the outline, in pixels, from the angle to the
            // sphere's silhouette cone (half-angle asin(1/|c|)).
            let to_edge = (1.0 / c.length()).asin() - d.angle_between(c.normalize());
            let pixels_per_radian = camera.height / 2.0 * camera.f;
            out.push(Some((lit(scene, p.as_vec3(), n.as_vec3()), to_edge * pixels_per_radian)));
        }
    }
    out
}

fn draw(scene: &Scene, shading: Shading) -> Output {
    render(scene, &Options { shading: Some(shading), ..Options::default() }).unwrap()
}

/// Peak red value and RMS error (all channels) against the reference, over pixels at least
/// `margin` pixels inside the sphere's outline.
fn compare(out: &Output, reference: &[Option<(Rgb, f64)>], margin: f64) -> (f32, f64, f32) {
    let (mut peak, mut reference_peak, mut sum, mut n) = (0f32, 0f32, 0f64, 0usize);
    for (i, r) in reference.iter().enumerate() {
        if let Some((expected, inside)) = r
            && *inside > margin
        {
            let got = out.image.pixels[i];
            peak = peak.max(got.x);
            reference_peak = reference_peak.max(expected.x);
            sum += f64::from((got - *expected).length_squared());
            n += 1;
        }
    }
    (peak, (sum / (3 * n.max(1)) as f64).sqrt(), reference_peak)
}

#[test]
fn phong_keeps_the_highlight_that_gouraud_loses() {
    let (scene, _) = sphere_scene();
    let reference = analytic(&scene);
    let margin = 2.0;
    let (phong_peak, phong_rms, reference_peak) =
        compare(&draw(&scene, Shading::Phong), &reference, margin);
    let gouraud = draw(&scene, Shading::Gouraud);
    let (gouraud_peak, gouraud_rms, _) = compare(&gouraud, &reference, margin);

    // Gouraud interpolates vertex colours, so no pixel can be brighter than the brightest front
    // vertex; here that is far below the true peak (premise: the highlight lies between vertices).
    let mesh = &scene.objects[0].mesh;
    let vertex_peak = mesh
        .positions
        .iter()
        .map(|&p| (p + CENTRE, p.normalize()))
        .filter(|(p, n)| n.dot(-*p) > 0.0)
        .map(|(p, n)| lit(&scene, p, n).x)
        .fold(0f32, f32::max);
    assert!(
        vertex_peak < reference_peak - 0.3,
        "premise: the brightest vertex ({vertex_peak:.3}) is far below the highlight ({reference_peak:.3})"
    );
    let drawn = gouraud.image.pixels.iter().zip(&gouraud.depth).filter(|(_, z)| **z < 1.0);
    let gouraud_max = drawn.map(|(c, _)| c.x).fold(0f32, f32::max);
    assert!(
        gouraud_max <= vertex_peak + 1e-5,
        "Gouraud: no pixel ({gouraud_max}) above the brightest vertex ({vertex_peak})"
    );
    assert!(
        gouraud_peak < reference_peak - 0.3,
        "Gouraud loses the highlight: {gouraud_peak:.3} vs {reference_peak:.3}"
    );

    // Phong lights every pixel with the interpolated normal: the peak is kept.
    assert!(
        (phong_peak - reference_peak).abs() < 0.03,
        "Phong keeps the highlight: peak {phong_peak:.3}, analytic {reference_peak:.3}"
    );
    eprintln!(
        "peak: analytic {reference_peak:.4}, Phong {phong_peak:.4}, Gouraud {gouraud_peak:.4}; RMS: Phong {phong_rms:.4}, Gouraud {gouraud_rms:.4}"
    );
    assert!(
        phong_rms < gouraud_rms / 2.0,
        "Phong is closer to the analytic image than Gouraud: RMS {phong_rms:.4} vs {gouraud_rms:.4}"
    );
}

#[test]
fn flat_shading_gives_each_face_one_colour_lit_with_its_face_normal() {
    let (scene, _) = sphere_scene();
    let out = draw(&scene, Shading::Flat);
    let rgba = out.image.to_rgba8();
    let camera = Pinhole::of(&scene);
    let mesh = &scene.objects[0].mesh;
    let mut faces_checked = 0;
    for (f, face) in mesh.faces.iter().enumerate() {
        let corners = face.map(|i| (mesh.positions[i as usize] + CENTRE).as_dvec3());
        let normal = (corners[1] - corners[0]).cross(corners[2] - corners[0]).normalize();
        if normal.dot(-corners[0]) <= 0.0 {
            continue; // a back face
        }
        // With a directional light and an infinite viewer the face's colour does not depend on
        // where on the face it is lit: shade(face normal) is the oracle.
        let expected =
            lit(&scene, corners[0].as_vec3(), normal.as_vec3()).to_array().map(to_unorm8);
        let on_screen: Vec<DVec2> = corners.iter().map(|&c| camera.window(c)).collect();
        let mut pixels = 0;
        for y in 0..SIZE {
            for x in 0..SIZE {
                let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                if inside_by(&on_screen, centre) < 1.0 {
                    continue;
                }
                pixels += 1;
                let got = rgba[(y * SIZE + x) as usize];
                for c in 0..3 {
                    assert!(
                        got[c].abs_diff(expected[c]) <= 1,
                        "face F{f}: pixel ({x}, {y}) is {got:?}, the face's colour is {expected:?}"
                    );
                }
            }
        }
        faces_checked += usize::from(pixels > 0);
    }
    assert!(faces_checked >= 20, "premise: most front faces have inner pixels ({faces_checked})");
    assert_eq!(
        out.stats.lighting_evaluations, out.stats.triangles_drawn,
        "one lighting evaluation per face"
    );
}

#[test]
fn the_three_modes_light_at_faces_vertices_and_pixels() {
    let (scene, _) = sphere_scene();
    let flat = draw(&scene, Shading::Flat).stats;
    let gouraud = draw(&scene, Shading::Gouraud).stats;
    let phong = draw(&scene, Shading::Phong).stats;
    assert_eq!(gouraud.lighting_evaluations, gouraud.vertices, "Gouraud: once per vertex");
    assert_eq!(phong.lighting_evaluations, phong.fragments_shaded, "Phong: once per pixel");
    assert!(flat.lighting_evaluations < gouraud.lighting_evaluations);
    assert!(phong.lighting_evaluations > 20 * gouraud.lighting_evaluations, "{phong}");
}

#[test]
fn vertex_colours_set_ka_and_kd_and_are_interpolated_perspective_correctly() {
    // A receding floor triangle with red, green and blue corners (glColor under
    // GL_COLOR_MATERIAL: k_a = k_d = the colour), lit by a global ambient 0.5 and a light straight
    // above with diffuse 0.5: every point's colour is 0.5·c + 0.5·c·(N·L) = its vertex-colour
    // blend c. The oracle: the ray through each pixel centre meets the floor at P, and c(P) is
    // the blend of the corner colours by P's barycentric coordinates on the floor (in f64). Gouraud
    // and Phong must show c(P) (perspective-correct, not the screen-space blend); flat shading
    // the last corner's colour in OpenGL's model (GL_FLAT's provoking vertex, lit with its own
    // glColor) and the mean of the three corners in the lecture's (lit at the centroid). The
    // lecture's model gives every point the same c here: no light has an ambient term.
    let size = 64u32;
    let mut scene = looking_down_z(size, size, 60.0);
    scene.light_model = LightModel::OpenGl { local_viewer: false };
    scene.global_ambient = Rgb::splat(0.5);
    scene.lights = vec![Light {
        kind: LightKind::Directional { to_light: Vec3::Y },
        ambient: Rgb::ZERO,
        diffuse: Rgb::splat(0.5),
        specular: Rgb::ZERO,
        attenuation: Default::default(),
    }];
    let corners =
        [Vec3::new(-5.0, -1.0, -2.5), Vec3::new(5.0, -1.0, -2.5), Vec3::new(0.0, -1.0, -20.0)];
    let colors = [Rgb::new(1.0, 0.0, 0.0), Rgb::new(0.0, 1.0, 0.0), Rgb::new(0.0, 0.0, 1.0)];
    let mut mesh = cg_core::mesh::Mesh::new(corners.to_vec(), vec![[0, 1, 2]]);
    mesh.colors = Some(colors.to_vec());
    scene.objects.push(object("floor", mesh, Material::default()));
    let camera = Pinhole::of(&scene);
    let on_screen: Vec<DVec2> = corners.iter().map(|c| camera.window(c.as_dvec3())).collect();
    let [a, b, c] = corners.map(Vec3::as_dvec3);
    let area = (b - a).cross(c - a).y;
    let blend = |p: DVec3| {
        let w = [
            (c - b).cross(p - b).y / area,
            (a - c).cross(p - c).y / area,
            (b - a).cross(p - a).y / area,
        ];
        colors.iter().zip(w).map(|(k, w)| k.as_dvec3() * w).sum::<DVec3>()
    };
    let lecture = LightModel::Lecture { specular: Specular::Phong, local_viewer: false };
    let runs = [
        (scene.light_model, Shading::Gouraud),
        (scene.light_model, Shading::Phong),
        (scene.light_model, Shading::Flat),
        (lecture, Shading::Flat),
    ];
    for (model, shading) in runs {
        let out = draw(&Scene { light_model: model, ..scene.clone() }, shading);
        let (mut checked, mut screen_blend_differs) = (0, 0);
        for y in 0..size {
            for x in 0..size {
                let w = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                if inside_by(&on_screen, w) < 1.0 {
                    continue;
                }
                let d = camera.ray(w);
                let expected = match (shading, model) {
                    (Shading::Flat, LightModel::OpenGl { .. }) => colors[2].as_dvec3(),
                    (Shading::Flat, LightModel::Lecture { .. }) => {
                        colors.iter().map(|k| k.as_dvec3()).sum::<DVec3>() / 3.0
                    }
                    _ => blend(d * (-1.0 / d.y)),
                };
                let got = out.image.pixels[(y * size + x) as usize].as_dvec3();
                // Snapping corners to 1/256 pixel and f32 interpolation: well under 1e-3.
                assert!(
                    (got - expected).abs().max_element() < 1e-3,
                    "{shading:?} ({model:?}): pixel ({x}, {y}) is {got}, expected {expected}"
                );
                checked += 1;
                // Premise: the screen-space blend differs (a perspective effect to be found).
                let [sa, sb, sc] = [on_screen[0], on_screen[1], on_screen[2]];
                let s_area = (sb - sa).perp_dot(sc - sa);
                let sw = [
                    (sc - sb).perp_dot(w - sb),
                    (sa - sc).perp_dot(w - sc),
                    (sb - sa).perp_dot(w - sa),
                ];
                let screen =
                    colors.iter().zip(sw).map(|(k, x)| k.as_dvec3() * (x / s_area)).sum::<DVec3>();
                screen_blend_differs += usize::from((screen - expected).abs().max_element() > 0.02);
            }
        }
        assert!(checked > 300, "premise: {checked} pixels");
        if shading != Shading::Flat {
            assert!(
                screen_blend_differs * 2 > checked,
                "premise: perspective matters ({screen_blend_differs} of {checked})"
            );
        }
    }
}
