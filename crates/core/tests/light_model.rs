//! The light model against the OpenGL 1.x lighting equation (specification 2.14.1), written here
//! a second time in f64 from the specification — not by calling `cg_core::light` — and evaluated
//! on the same f32 inputs; area lights against an f64 integral; and the documented differences
//! between the lecture's model and OpenGL's.

use cg_core::Rgb;
use cg_core::glam::{DVec3, Vec3};
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular, Terms, shade};
use cg_testkit::{approx_eq, assert_approx_eq};

const EPS: f64 = f32::EPSILON as f64;

/// `|x − y| ≤ abs + rel·|y|` per component (`assert_approx_eq!` cannot take both bounds and a
/// message: its `abs = .., rel = ..` form is ambiguous to the macro parser).
fn assert_close(x: Vec3, y: Vec3, abs: f64, rel: f64, what: &str) {
    assert!(approx_eq(&x, &y, abs, rel), "{what}: {x} vs {y} (abs {abs:e}, rel {rel:e})");
}

const GL: LightModel = LightModel::OpenGl { local_viewer: false };
const PHONG: LightModel = LightModel::Lecture { specular: Specular::Phong, local_viewer: false };
const BLINN: LightModel = LightModel::Lecture { specular: Specular::Blinn, local_viewer: false };

// ---------------------------------------------------------------------------------------------
// The OpenGL 1.x lighting equation in f64, from the specification (section 2.14.1):
//
//   c = e + a_cm·a_cs + Σᵢ attᵢ·spotᵢ·[a_cm·a_cli + (n ⊙ VPᵢ)·d_cm·d_cli + fᵢ·(n ⊙ ĥᵢ)^s·s_cm·s_cli]
//
// ⊙ = max(dot, 0); fᵢ = 1 if n·VPᵢ ≠ 0 and positive, else 0; ĥᵢ = normalise(VPᵢ + VPe);
// attᵢ = 1/(k0 + k1‖VPᵢ‖ + k2‖VPᵢ‖²) for positional lights, 1 for directional ones;
// spotᵢ = (P_liV ⊙ ŝ)^s_rl inside the cone (P_liV ⊙ ŝ ≥ cos c_rl), 0 outside, 1 when c_rl = 180.

/// One GL light, in f64, as the spec's parameters.
struct GlLight {
    /// GL_POSITION (xyz, w): w = 0 for directional lights.
    position: DVec3,
    w: f64,
    ambient: DVec3,
    diffuse: DVec3,
    specular: DVec3,
    /// k0, k1, k2.
    k: [f64; 3],
    /// GL_SPOT_DIRECTION, GL_SPOT_EXPONENT, GL_SPOT_CUTOFF.
    spot: Option<(DVec3, f64, f64)>,
}

struct GlMaterial {
    emission: DVec3,
    ambient: DVec3,
    diffuse: DVec3,
    specular: DVec3,
    shininess: f64,
}

/// The spec's terms at point p with unit normal n and unit vector to the eye vp_e; returns
/// (emission, ambient, diffuse, specular) so each can be compared.
fn gl_equation(
    lights: &[GlLight],
    a_cs: DVec3,
    m: &GlMaterial,
    p: DVec3,
    n: DVec3,
    vp_e: DVec3,
) -> [DVec3; 4] {
    let dot_plus = |a: DVec3, b: DVec3| a.dot(b).max(0.0);
    let mut ambient = m.ambient * a_cs;
    let (mut diffuse, mut specular) = (DVec3::ZERO, DVec3::ZERO);
    for light in lights {
        let (vp, att) = if light.w == 0.0 {
            (light.position.normalize(), 1.0)
        } else {
            let to_light = light.position / light.w - p;
            let d = to_light.length();
            (to_light / d, 1.0 / (light.k[0] + light.k[1] * d + light.k[2] * d * d))
        };
        let spot = match light.spot {
            None => 1.0,
            Some((_, _, 180.0)) => 1.0,
            Some((direction, exponent, cutoff)) => {
                let c = dot_plus(-vp, direction.normalize());
                if c >= cutoff.to_radians().cos() { c.powf(exponent) } else { 0.0 }
            }
        };
        let f = if n.dot(vp) > 0.0 { 1.0 } else { 0.0 };
        let h = (vp + vp_e).normalize();
        ambient += att * spot * m.ambient * light.ambient;
        diffuse += att * spot * dot_plus(n, vp) * m.diffuse * light.diffuse;
        if f > 0.0 && dot_plus(n, h) > 0.0 {
            specular += att * spot * dot_plus(n, h).powf(m.shininess) * m.specular * light.specular;
        }
    }
    [m.emission, ambient, diffuse, specular]
}

/// The kit's light and material as the spec's f64 parameters (a plain field-by-field copy).
fn to_gl(light: &Light) -> GlLight {
    let c = |v: Vec3| v.as_dvec3();
    let a = &light.attenuation;
    let k = [f64::from(a.constant), f64::from(a.linear), f64::from(a.quadratic)];
    let (position, w, spot) = match &light.kind {
        LightKind::Directional { to_light } => (c(*to_light), 0.0, None),
        LightKind::Point { position } => (c(*position), 1.0, None),
        LightKind::Spot { position, direction, cutoff_deg, exponent, .. } => {
            (c(*position), 1.0, Some((c(*direction), f64::from(*exponent), f64::from(*cutoff_deg))))
        }
        LightKind::Area { .. } => unreachable!("OpenGL has no area lights"),
    };
    GlLight {
        position,
        w,
        ambient: c(light.ambient),
        diffuse: c(light.diffuse),
        specular: c(light.specular),
        k,
        spot,
    }
}

fn to_gl_material(m: &Material) -> GlMaterial {
    GlMaterial {
        emission: m.emission.as_dvec3(),
        ambient: m.ka.as_dvec3(),
        diffuse: m.kd.as_dvec3(),
        specular: m.ks.as_dvec3(),
        shininess: f64::from(m.shininess),
    }
}

fn terms_array(t: &Terms) -> [Vec3; 4] {
    [t.emission, t.ambient, t.diffuse, t.specular]
}

const TERM_NAMES: [&str; 4] = ["emission", "ambient", "diffuse", "specular"];

/// The course's light: GL_LIGHT0 at (10, 10, 10, 1), ambient 0.1, diffuse 0.8, specular 1.0.
fn course_light() -> Light {
    Light {
        kind: LightKind::Point { position: Vec3::new(10.0, 10.0, 10.0) },
        ambient: Rgb::splat(0.1),
        diffuse: Rgb::splat(0.8),
        specular: Rgb::splat(1.0),
        attenuation: Attenuation::default(),
    }
}

/// The camera's backward axis of the course's view (pitch −30°: the eye at (0, 7.5, 13.0)).
fn course_backward() -> Vec3 {
    DVec3::new(0.0, 30f64.to_radians().sin(), 30f64.to_radians().cos()).as_vec3()
}

#[test]
fn opengl_mode_reproduces_the_course_scene_term_by_term() {
    // Global ambient 0.2, infinite viewer, colour material (0.5, 0.8, 0.5) for ambient and
    // diffuse, specular 0, shininess 0: the course's defaults.
    let material = Material::from_color(Rgb::new(0.5, 0.8, 0.5));
    assert_eq!((material.ks, material.shininess), (Rgb::ZERO, 0.0), "the course's material");
    let light = course_light();
    let global = Rgb::splat(0.2);
    let v = course_backward();

    // Ground points (normal +Y) and the pyramid's faces after translate (0, 1, 0): the centroid
    // and the f64 normal (b − a) × (c − a) of each face, F4 and F5 facing down (N·L < 0).
    let corners = [
        DVec3::new(0.0, 1.0, 0.0),
        DVec3::new(1.0, -0.8, 1.0),
        DVec3::new(1.0, -0.8, -1.0),
        DVec3::new(-1.0, -0.8, 1.0),
        DVec3::new(-1.0, -0.8, -1.0),
    ]
    .map(|c| c + DVec3::Y);
    let faces = [[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]];
    let mut points: Vec<(Vec3, Vec3)> = [(0.0, 0.0), (4.0, -3.0), (-5.0, 5.0), (5.0, 5.0)]
        .iter()
        .map(|&(x, z)| (Vec3::new(x, 0.0, z), Vec3::Y))
        .collect();
    for [a, b, c] in faces {
        let (a, b, c) = (corners[a], corners[b], corners[c]);
        let centroid = (a + b + c) / 3.0;
        points.push((centroid.as_vec3(), (b - a).cross(c - a).normalize().as_vec3()));
    }

    let gl_lights = [to_gl(&light)];
    let gl_material = to_gl_material(&material);
    for (p, n) in points {
        let got = shade(GL, global, std::slice::from_ref(&light), &material, p, n, v);
        let expected = gl_equation(
            &gl_lights,
            global.as_dvec3(),
            &gl_material,
            p.as_dvec3(),
            n.as_dvec3(),
            v.as_dvec3(),
        );
        for (k, name) in TERM_NAMES.iter().enumerate() {
            // Values ≤ 1, each a handful of f32 operations (a normalisation, a dot product, two
            // products): ≤ 8ε relative ≈ 1e-6; 2e-6 absolute.
            assert_approx_eq!(
                terms_array(&got)[k].as_dvec3(),
                expected[k],
                abs = 2e-6,
                "{name} at {p} (n = {n})"
            );
        }
        assert_eq!(got.specular, Rgb::ZERO, "material specular 0");
    }

    // One number by hand, as a student would check it: the ground at the origin sees the light
    // along (1, 1, 1)/√3, so diffuse = 0.8·(1/√3)·kd and ambient = (0.2 + 0.1)·ka.
    let t = shade(GL, global, &[light], &material, Vec3::ZERO, Vec3::Y, v);
    let kd = DVec3::new(0.5, 0.8, 0.5);
    assert_approx_eq!(t.diffuse.as_dvec3(), kd * 0.8 / 3f64.sqrt(), abs = 1e-6);
    assert_approx_eq!(t.ambient.as_dvec3(), kd * 0.3, abs = 1e-6);
}

/// A scene with attenuation, a spot light, a directional light and a specular material.
fn rich_lights() -> Vec<Light> {
    vec![
        Light {
            kind: LightKind::Spot {
                position: Vec3::new(1.0, 6.0, 1.0),
                direction: Vec3::new(-0.1, -1.0, 0.05),
                cutoff_deg: 35.0,
                exponent: 4.0,
                inner_deg: None,
            },
            ambient: Rgb::splat(0.15),
            diffuse: Rgb::new(0.9, 0.7, 0.5),
            specular: Rgb::new(1.0, 1.0, 0.8),
            attenuation: Attenuation { constant: 0.5, linear: 0.05, quadratic: 0.01 },
        },
        Light {
            kind: LightKind::Point { position: Vec3::new(-4.0, 3.0, 2.0) },
            ambient: Rgb::new(0.05, 0.1, 0.05),
            diffuse: Rgb::new(0.4, 0.6, 0.8),
            specular: Rgb::splat(0.7),
            attenuation: Attenuation { constant: 1.0, linear: 0.2, quadratic: 0.0 },
        },
        Light {
            kind: LightKind::Directional { to_light: Vec3::new(-1.0, 2.0, 0.5) },
            ambient: Rgb::splat(0.05),
            diffuse: Rgb::splat(0.3),
            specular: Rgb::splat(0.5),
            // Ignored for a directional light (att = 1).
            attenuation: Attenuation { constant: 0.0, linear: 0.0, quadratic: 5.0 },
        },
    ]
}

fn rich_material() -> Material {
    Material {
        ka: Rgb::new(0.2, 0.3, 0.4),
        kd: Rgb::new(0.6, 0.5, 0.4),
        ks: Rgb::splat(0.8),
        shininess: 24.5,
        emission: Rgb::new(0.05, 0.0, 0.02),
        ..Material::default()
    }
}

/// Receivers: a grid on the ground and tilted normals, so that each light is in front of and
/// behind some of them and some points are outside the spot's cone.
fn receivers() -> Vec<(Vec3, Vec3)> {
    let mut out = Vec::new();
    for x in [-4.0f32, -1.5, 0.0, 0.7, 2.0, 4.5] {
        for z in [-3.0f32, 0.0, 1.0, 3.5] {
            let p = Vec3::new(x, 0.2 * x - 0.1 * z, z);
            for n in [DVec3::Y, DVec3::new(0.3, 1.0, -0.2), DVec3::new(-1.0, 0.4, 0.3)] {
                out.push((p, n.normalize().as_vec3()));
            }
        }
    }
    out
}

#[test]
fn opengl_mode_with_attenuation_spot_and_specular() {
    let lights = rich_lights();
    let material = rich_material();
    let global = Rgb::new(0.2, 0.2, 0.25);
    let eye = Vec3::new(3.0, 4.0, 8.0);
    let gl_lights: Vec<GlLight> = lights.iter().map(to_gl).collect();
    let gl_material = to_gl_material(&material);
    let model = LightModel::OpenGl { local_viewer: true };
    let (mut in_cone, mut out_of_cone, mut lit_specular) = (0, 0, 0);
    for (p, n) in receivers() {
        let v = model.view_vector(p, eye, Vec3::Z);
        let got = shade(model, global, &lights, &material, p, n, v);
        let expected = gl_equation(
            &gl_lights,
            global.as_dvec3(),
            &gl_material,
            p.as_dvec3(),
            n.as_dvec3(),
            v.as_dvec3(),
        );
        for (k, name) in TERM_NAMES.iter().enumerate() {
            // The specular power moves a few-ε error of N·Ĥ by the exponent s = 24.5: relative
            // (s + 4)·8ε ≈ 2.7e-5; the other terms 16ε relative; 1e-7 absolute near zero.
            let rel = if k == 3 { (24.5 + 4.0) * 8.0 * EPS } else { 16.0 * EPS };
            assert_approx_eq!(
                terms_array(&got)[k].as_dvec3(),
                expected[k],
                abs = 1e-7 + rel * expected[k].max_element(),
                "{name} at {p} (n = {n})"
            );
        }
        let to_spot = (Vec3::new(1.0, 6.0, 1.0) - p).as_dvec3().normalize();
        let cos = -to_spot.dot(DVec3::new(-0.1, -1.0, 0.05).normalize());
        if cos >= 35f64.to_radians().cos() {
            in_cone += 1
        } else {
            out_of_cone += 1
        }
        lit_specular += usize::from(got.specular.max_element() > 1e-3);
    }
    assert!(
        in_cone > 10 && out_of_cone > 10 && lit_specular > 10,
        "{in_cone} {out_of_cone} {lit_specular}"
    );
}

#[test]
fn directional_light_ignores_attenuation() {
    let base = Light {
        kind: LightKind::Directional { to_light: Vec3::new(1.0, 2.0, -0.5) },
        ambient: Rgb::splat(0.1),
        diffuse: Rgb::splat(0.8),
        specular: Rgb::ONE,
        attenuation: Attenuation::default(),
    };
    let strong = Attenuation { constant: 0.0, linear: 3.0, quadratic: 5.0 };
    let attenuated = Light { attenuation: strong, ..base.clone() };
    assert!(!attenuated.needs_attenuation(), "directional: never");
    let point = Light {
        kind: LightKind::Point { position: Vec3::new(1.0, 2.0, -0.5) },
        ..attenuated.clone()
    };
    assert!(point.needs_attenuation());
    assert!(!Light { attenuation: Attenuation::default(), ..point.clone() }.needs_attenuation());
    let material = rich_material();
    for model in [GL, PHONG, BLINN] {
        for (p, n) in receivers() {
            let v = course_backward();
            let a = shade(model, Rgb::splat(0.2), std::slice::from_ref(&base), &material, p, n, v);
            let b = shade(
                model,
                Rgb::splat(0.2),
                std::slice::from_ref(&attenuated),
                &material,
                p,
                n,
                v,
            );
            assert_eq!(a, b, "{model:?} at {p}");
            // A point light with the same attenuation is dimmed (the test's premise).
            let c = shade(model, Rgb::splat(0.2), std::slice::from_ref(&point), &material, p, n, v);
            if a.diffuse.max_element() > 0.01 {
                assert_ne!(a.diffuse, c.diffuse);
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Area lights

/// A ceiling light: the parallelogram corner + s·u + t·v faces down-ish (u × v = (0, −2, 0.8)).
fn area_light(samples: [u32; 2]) -> Light {
    Light {
        kind: LightKind::Area {
            corner: Vec3::new(-1.0, 3.0, -0.5),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.4, 1.0),
            samples,
        },
        ambient: Rgb::splat(0.1),
        diffuse: Rgb::new(0.9, 0.8, 0.7),
        specular: Rgb::ONE,
        attenuation: Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.2 },
    }
}

#[test]
fn area_light_samples_are_cell_centres_sharing_the_colour() {
    let light = area_light([3, 2]);
    let samples: Vec<Light> = light.point_lights().collect();
    assert_eq!(samples.len(), 6);
    let mut ambient = Rgb::ZERO;
    for (k, s) in samples.iter().enumerate() {
        let (i, j) = (k % 3, k / 3);
        let expected = DVec3::new(-1.0, 3.0, -0.5)
            + (i as f64 + 0.5) / 3.0 * DVec3::new(2.0, 0.0, 0.0)
            + (j as f64 + 0.5) / 2.0 * DVec3::new(0.0, 0.4, 1.0);
        let LightKind::Spot { position, direction, cutoff_deg, exponent, inner_deg } = s.kind
        else {
            panic!("a one-sided sample is a 90° spot: {:?}", s.kind);
        };
        assert_approx_eq!(position.as_dvec3(), expected, abs = 4.0 * EPS * 4.0);
        assert_approx_eq!(
            direction.as_dvec3(),
            DVec3::new(0.0, -2.0, 0.8).normalize(),
            abs = 2.0 * EPS
        );
        assert_eq!((cutoff_deg, exponent, inner_deg), (90.0, 0.0, None));
        assert_approx_eq!(s.diffuse.as_dvec3(), DVec3::new(0.9, 0.8, 0.7) / 6.0, abs = 1e-7);
        assert_eq!(s.attenuation, light.attenuation);
        ambient += s.ambient;
    }
    assert_approx_eq!(ambient, Rgb::splat(0.1), abs = 1e-7);
    // 0 samples are taken as 1; other lights stand for themselves.
    assert_eq!(area_light([0, 0]).point_lights().count(), 1);
    assert_eq!(area_light([0, 4]).point_lights().count(), 4);
    let point = course_light();
    assert_eq!(point.point_lights().collect::<Vec<_>>(), vec![point.clone()]);
    // A degenerate parallelogram (parallel edges) shines everywhere: point lights.
    let mut line = area_light([2, 1]);
    if let LightKind::Area { edge_v, .. } = &mut line.kind {
        *edge_v = Vec3::new(4.0, 0.0, 0.0);
    }
    assert!(line.point_lights().all(|s| matches!(s.kind, LightKind::Point { .. })));
}

#[test]
fn area_light_with_one_sample_equals_a_point_light_at_its_centre() {
    let area = area_light([1, 1]);
    let point =
        Light { kind: LightKind::Point { position: Vec3::new(0.0, 3.2, 0.0) }, ..area.clone() };
    let material = rich_material();
    for model in [GL, PHONG, BLINN] {
        for (p, n) in receivers() {
            let v = course_backward();
            let a = shade(model, Rgb::splat(0.2), std::slice::from_ref(&area), &material, p, n, v);
            let b = shade(model, Rgb::splat(0.2), std::slice::from_ref(&point), &material, p, n, v);
            // Below the light (in front of it): the same light within the rounding of the centre
            // (corner + ½u + ½v against (0, 3.2, 0): ≤ 2 ulp of 3.2 ≈ 5e-7 in position).
            for (x, y) in terms_array(&a).iter().zip(terms_array(&b)) {
                assert_close(*x, y, 1e-6, 1e-6, &format!("{model:?} at {p}"));
            }
        }
    }
    // Above the light (behind it) the area light gives nothing but the global ambient (lecture)
    // or nothing from the light at all (OpenGL: its ambient is spot-scaled too).
    let p = Vec3::new(0.0, 5.0, 0.0);
    let t = shade(GL, Rgb::ZERO, &[area], &material, p, Vec3::Y, Vec3::Y);
    assert_eq!(t.diffuse + t.specular + t.ambient, Rgb::ZERO);
}

/// ∫∫ over the unit square of the lecture's Phong point-light model (diffuse + specular, red
/// channel) for the area light's point x(s, t), in f64 with composite Simpson (256 × 256 cells;
/// the integrand is smooth here: the receiver is well in front of the light; error ≪ 1e-9).
fn area_integral(p: DVec3, n: DVec3, v: DVec3, material: &Material) -> f64 {
    let (corner, u, w) =
        (DVec3::new(-1.0, 3.0, -0.5), DVec3::new(2.0, 0.0, 0.0), DVec3::new(0.0, 0.4, 1.0));
    let (kd, ks, s) =
        (f64::from(material.kd.x), f64::from(material.ks.x), f64::from(material.shininess));
    let f = |a: f64, b: f64| {
        let x = corner + a * u + b * w;
        let to_light = x - p;
        let d = to_light.length();
        let l = to_light / d;
        let att = 1.0 / (1.0 + 0.2 * d * d);
        let n_dot_l = n.dot(l);
        if n_dot_l <= 0.0 {
            return 0.0;
        }
        let r = 2.0 * n_dot_l * n - l;
        att * (0.9 * kd * n_dot_l + 1.0 * ks * r.dot(v).max(0.0).powf(s))
    };
    let m = 256;
    let h = 1.0 / f64::from(m);
    let weight = |k: u32| {
        if k == 0 || k == m {
            1.0
        } else if k % 2 == 1 {
            4.0
        } else {
            2.0
        }
    };
    let mut sum = 0.0;
    for i in 0..=m {
        for j in 0..=m {
            sum += weight(i) * weight(j) * f(f64::from(i) * h, f64::from(j) * h);
        }
    }
    sum * h * h / 9.0
}

#[test]
fn area_light_converges_to_the_integral_of_its_point_lights() {
    // n × n samples are the midpoint rule of the integral above: the error falls like 1/n².
    // Measured (this scene, debug and release alike): relative errors 3.8e-2, 8.6e-3, 2.1e-3,
    // 5.2e-4, 1.3e-4, 3.3e-5, 6.5e-6 for n = 1, 2, 4, … 64 (ratio ≈ 4 per doubling; at n = 64
    // the f32 sum of 4096 lights, ~2e-6, starts to show). Asserted: each doubling divides the
    // error by ≥ 3, and n = 64 is within 1e-5 relative.
    let material = Material { ks: Rgb::splat(0.5), shininess: 8.0, ..rich_material() };
    let (p, n) = (Vec3::new(0.3, 0.0, 0.2), Vec3::Y);
    let v = DVec3::new(0.0, 0.6, 0.8).as_vec3();
    let exact = area_integral(p.as_dvec3(), n.as_dvec3(), v.as_dvec3(), &material);
    let mut previous = f64::INFINITY;
    let mut errors = Vec::new();
    for samples in [1u32, 2, 4, 8, 16, 32, 64] {
        let light = area_light([samples, samples]);
        let t = shade(PHONG, Rgb::ZERO, &[light], &material, p, n, v);
        let got = f64::from(t.diffuse.x + t.specular.x);
        let err = ((got - exact) / exact).abs();
        errors.push(err);
        assert!(err <= previous / 3.0, "n = {samples}: {err:e} after {previous:e} ({errors:?})");
        previous = err;
        // The lecture's ambient does not depend on the sampling.
        assert_approx_eq!(t.ambient, material.ka * 0.1, abs = 1e-7);
    }
    assert!(previous <= 1e-5, "{errors:?}");
}

// ---------------------------------------------------------------------------------------------
// Lecture against OpenGL

#[test]
fn lecture_and_opengl_modes_differ_exactly_where_documented() {
    let material = rich_material();
    let global = Rgb::new(0.2, 0.2, 0.25);
    let v = course_backward();
    let tol = |x: Vec3, y: Vec3, what: &str| assert_close(x, y, 1e-6, 1e-6, what);

    // 1. No attenuation, no spot lights, Blinn: the same colour, term by term.
    let plain = vec![
        course_light(),
        Light {
            kind: LightKind::Directional { to_light: Vec3::new(-1.0, 2.0, 0.5) },
            ..course_light()
        },
    ];
    for (p, n) in receivers() {
        let a = shade(GL, global, &plain, &material, p, n, v);
        let b = shade(BLINN, global, &plain, &material, p, n, v);
        for ((x, y), name) in terms_array(&a).into_iter().zip(terms_array(&b)).zip(TERM_NAMES) {
            tol(x, y, name);
        }
        // 2. Phong instead of Blinn changes the specular only, to the lecture's (R·V)ⁿ.
        let c = shade(PHONG, global, &plain, &material, p, n, v);
        tol(c.ambient, a.ambient, "ambient");
        tol(c.diffuse, a.diffuse, "diffuse");
        assert_eq!(c.emission, a.emission);
        let mut phong = DVec3::ZERO;
        for light in &plain {
            let (l, _) = light.direction_from(p).unwrap();
            let (n64, l64, v64) = (n.as_dvec3(), l.as_dvec3(), v.as_dvec3());
            if n64.dot(l64) > 0.0 {
                let r = 2.0 * n64.dot(l64) * n64 - l64;
                phong += r.dot(v64).max(0.0).powf(24.5) * 0.8 * light.specular.as_dvec3();
            }
        }
        assert_approx_eq!(
            c.specular.as_dvec3(),
            phong,
            abs = 1e-7 + 30.0 * 8.0 * EPS * phong.max_element()
        );
    }

    // 3. Attenuation: OpenGL attenuates the per-light ambient, the lecture does not:
    //    ambient_GL − ambient_lecture = ka·Ia,ᵢ·(att − 1); diffuse and (Blinn) specular agree.
    let mut attenuated = course_light();
    attenuated.attenuation = Attenuation { constant: 1.0, linear: 0.1, quadratic: 0.01 };
    for (p, n) in receivers() {
        let a = shade(GL, global, std::slice::from_ref(&attenuated), &material, p, n, v);
        let b = shade(BLINN, global, std::slice::from_ref(&attenuated), &material, p, n, v);
        let d = (Vec3::new(10.0, 10.0, 10.0) - p).as_dvec3().length();
        let att = 1.0 / (1.0 + 0.1 * d + 0.01 * d * d);
        let expected = material.ka.as_dvec3() * 0.1 * (att - 1.0);
        assert_approx_eq!((a.ambient - b.ambient).as_dvec3(), expected, abs = 1e-6);
        assert!(att < 0.9, "premise: the light is attenuated ({att})");
        tol(a.diffuse, b.diffuse, "diffuse");
        tol(a.specular, b.specular, "specular");
    }

    // 4. Spot lights: OpenGL spot-scales the per-light ambient and ignores `inner_deg`; the
    //    lecture keeps the ambient and applies the smooth step between inner and cutoff.
    let spot = Light {
        kind: LightKind::Spot {
            position: Vec3::new(0.0, 5.0, 0.0),
            direction: -Vec3::Y,
            cutoff_deg: 30.0,
            exponent: 2.0,
            inner_deg: Some(15.0),
        },
        ambient: Rgb::splat(0.1),
        diffuse: Rgb::splat(0.8),
        specular: Rgb::ONE,
        attenuation: Attenuation::default(),
    };
    for x in [0.0f32, 1.0, 1.5, 2.0, 2.5, 2.8, 3.5, 6.0] {
        let p = Vec3::new(x, 0.0, 0.0);
        let a = shade(GL, global, std::slice::from_ref(&spot), &material, p, Vec3::Y, v);
        let b = shade(BLINN, global, std::slice::from_ref(&spot), &material, p, Vec3::Y, v);
        let cos = (DVec3::new(0.0, 5.0, 0.0) - p.as_dvec3()).normalize().y;
        let gl_spot = if cos >= 30f64.to_radians().cos() { cos * cos } else { 0.0 };
        let (ci, co) = (15f64.to_radians().cos(), 30f64.to_radians().cos());
        let t = ((cos - co) / (ci - co)).clamp(0.0, 1.0);
        let step = t * t * (3.0 - 2.0 * t);
        let ka = material.ka.as_dvec3();
        assert_approx_eq!(
            a.ambient.as_dvec3(),
            ka * (global.as_dvec3() + 0.1 * gl_spot),
            abs = 1e-6
        );
        assert_approx_eq!(b.ambient.as_dvec3(), ka * (global.as_dvec3() + 0.1), abs = 1e-6);
        assert_approx_eq!(b.diffuse.as_dvec3(), a.diffuse.as_dvec3() * step, abs = 1e-6);
        assert_approx_eq!(b.specular.as_dvec3(), a.specular.as_dvec3() * step, abs = 1e-6);
    }
}

#[test]
fn view_vector_for_local_and_infinite_viewers() {
    let eye = Vec3::new(0.0, 7.5, 13.0);
    let backward = course_backward();
    let p = Vec3::new(1.0, 0.0, -2.0);
    assert_eq!(GL.view_vector(p, eye, backward), backward);
    assert_eq!(PHONG.view_vector(p, eye, backward), backward);
    let local = LightModel::OpenGl { local_viewer: true };
    assert!(local.local_viewer() && !GL.local_viewer());
    let expected = (eye.as_dvec3() - p.as_dvec3()).normalize();
    assert_approx_eq!(local.view_vector(p, eye, backward).as_dvec3(), expected, abs = 2.0 * EPS);
    // The eye on the point: the backward axis, not NaN.
    assert_eq!(local.view_vector(eye, eye, backward), backward);
}

#[test]
fn terms_total_is_the_unclamped_sum() {
    let t = Terms {
        emission: Rgb::splat(0.5),
        ambient: Rgb::splat(0.25),
        diffuse: Rgb::splat(0.5),
        specular: Rgb::splat(1.0),
    };
    assert_eq!(t.total(), Rgb::splat(2.25), "not clamped: the renderer clamps at the end");
}

#[test]
fn visibility_scales_diffuse_and_specular_but_never_ambient() {
    use cg_core::light::shade_with_visibility;
    let material = Material {
        ks: Vec3::splat(0.5),
        shininess: 10.0,
        emission: Vec3::splat(0.05),
        ..Material::from_color(Vec3::new(0.5, 0.8, 0.5))
    };
    let light = course_light();
    let (p, n) = (Vec3::new(0.5, 0.0, 0.5), Vec3::Y);
    let v = Vec3::new(0.0, 0.5, 0.866).normalize();
    for model in [GL, PHONG] {
        let full = shade(model, Vec3::splat(0.2), std::slice::from_ref(&light), &material, p, n, v);
        let mut calls = Vec::new();
        let half = shade_with_visibility(
            model,
            Vec3::splat(0.2),
            std::slice::from_ref(&light),
            &material,
            p,
            n,
            v,
            |_, l, d| {
                calls.push((l, d));
                0.5
            },
        );
        // One call, with the direction and distance to the light at (10, 10, 10).
        assert_eq!(calls.len(), 1);
        let to_light = Vec3::splat(10.0) - p;
        assert!(
            (calls[0].0 - to_light.normalize()).length() < 1e-6
                && (calls[0].1 - to_light.length()).abs() < 1e-4
        );
        assert_eq!(half.ambient, full.ambient, "ambient is never shadowed");
        assert_eq!(half.emission, full.emission);
        assert!((half.diffuse - 0.5 * full.diffuse).abs().max_element() < 1e-6);
        assert!((half.specular - 0.5 * full.specular).abs().max_element() < 1e-6);
        let dark = shade_with_visibility(
            model,
            Vec3::splat(0.2),
            std::slice::from_ref(&light),
            &material,
            p,
            n,
            v,
            |_, _, _| 0.0,
        );
        assert_eq!((dark.diffuse, dark.specular), (Vec3::ZERO, Vec3::ZERO));
        assert_eq!(dark.ambient, full.ambient);
        let nan = shade_with_visibility(
            model,
            Vec3::splat(0.2),
            std::slice::from_ref(&light),
            &material,
            p,
            n,
            v,
            |_, _, _| f32::NAN,
        );
        assert!(nan.total().is_finite(), "a NaN visibility counts as blocked");
    }
}
