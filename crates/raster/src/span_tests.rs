//! The span kernels against the point-by-point functions they stand for, lane by lane, bit for
//! bit — on ordinary points and on the hard cases (a light or the eye on the point, normals that
//! cancel, zero normals).

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{Attenuation, Light, LightCounts, LightKind, LightModel, Material, Specular};
use cg_core::normals::interpolate_normal;

use super::*;

/// A small deterministic generator (xorshift), so the cases are the same on every run.
pub(crate) struct Cases(pub(crate) u64);

impl Cases {
    /// In `[-1, 1)`.
    pub(crate) fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 40) as f32 / (1u64 << 24) as f32 * 2.0 - 1.0
    }

    pub(crate) fn vec(&mut self) -> Vec3 {
        Vec3::new(self.next(), self.next(), self.next())
    }
}

fn bits(v: Vec3) -> [u32; 3] {
    v.to_array().map(f32::to_bits)
}

#[test]
fn interpolated_normals_are_the_reference_bit_for_bit_and_cancelling_ones_fall_back() {
    let mut cases = Cases(0x9e37_79b9_7f4a_7c15);
    for round in 0..400 {
        let (mut b, mut normals) = (V3::default(), [V3::default(); 3]);
        let mut lengths = [[0.0; LANES]; 3];
        let mut given = [[Vec3::ZERO; 3]; LANES];
        let mut weights = [Vec3::ZERO; LANES];
        for i in 0..LANES {
            let w = cases.vec().abs();
            let w = w / (w.x + w.y + w.z);
            let mut n = [cases.vec().normalize(), cases.vec().normalize(), cases.vec().normalize()];
            match (round + i) % 4 {
                // Opposite normals at the ends of an edge, halfway along it: an exact zero sum.
                0 => (n[1], weights[i]) = (-n[0], Vec3::new(0.5, 0.5, 0.0)),
                // Nearly opposite: the smallest coordinate one f32 step off, so the sum is a
                // few 2⁻³⁰ long, not zero, and still below the cancellation threshold.
                3 if round % 2 == 0 => {
                    n[0] = Vec3::new(n[0].x, n[0].y, 1e-3).normalize();
                    let mut m = -n[0];
                    let axis = (0..3).min_by(|&a, &b| m[a].abs().total_cmp(&m[b].abs())).unwrap();
                    m[axis] = f32::from_bits(m[axis].to_bits() + 1);
                    (n[1], weights[i]) = (m, Vec3::new(0.5, 0.5, 0.0));
                }
                // A zero normal (a vertex without a usable one) among ordinary ones.
                1 => (n[2], weights[i]) = (Vec3::ZERO, w),
                _ => weights[i] = w,
            }
            given[i] = n;
            b.set(i, weights[i]);
            for k in 0..3 {
                normals[k].set(i, n[k]);
                lengths[k][i] = n[k].as_dvec3().length();
            }
        }
        let mut out = V3::default();
        let keep = interpolate_normals(&b, &normals, &lengths, &mut out);
        let face = Vec3::new(0.0, 0.0, 7.0);
        for i in 0..LANES {
            let expected = interpolate_normal(given[i], weights[i], face);
            let got = if keep[i] { out.get(i) } else { face };
            assert_eq!(bits(got), bits(expected), "round {round}, lane {i}");
            if (round + i) % 4 == 0 || ((round + i) % 4 == 3 && round % 2 == 0) {
                assert!(!keep[i], "round {round}, lane {i}: a cancelling sum falls back");
            }
        }
    }
}

#[test]
fn the_light_model_is_the_reference_bit_for_bit() {
    let attenuation = Attenuation { constant: 0.3, linear: 0.2, quadratic: 0.05 };
    let light = |kind| Light {
        kind,
        ambient: Rgb::new(0.1, 0.2, 0.05),
        diffuse: Rgb::new(0.9, 0.7, 0.8),
        specular: Rgb::new(1.0, 0.9, 0.8),
        attenuation,
    };
    let lights = vec![
        light(LightKind::Directional { to_light: Vec3::new(1.0, 1.0, 0.5) }),
        // On the first point of every span (a light without a direction from it).
        light(LightKind::Point { position: Vec3::new(0.25, 0.5, -0.75) }),
        light(LightKind::Spot {
            position: Vec3::new(0.0, 2.0, 0.0),
            direction: Vec3::NEG_Y,
            cutoff_deg: 50.0,
            exponent: 3.0,
            inner_deg: Some(20.0),
        }),
        light(LightKind::Area {
            corner: Vec3::new(-1.0, 2.0, -1.0),
            edge_u: Vec3::X,
            edge_v: Vec3::Z,
            samples: [2, 2],
        }),
    ];
    let material = Material {
        ka: Rgb::new(0.3, 0.2, 0.1),
        kd: Rgb::new(0.6, 0.5, 0.4),
        ks: Rgb::splat(0.5),
        shininess: 12.5,
        emission: Rgb::new(0.01, 0.02, 0.03),
        ..Material::default()
    };
    assert_lanes_are_the_reference(&lights, &material, false);
    // Every light's scale 1 (no attenuation, no spot or area light) and no specular term: the
    // course scene's case, computed by `light_lanes_plain`.
    let plain: Vec<Light> = lights[..2]
        .iter()
        .chain(&[light(LightKind::Point { position: Vec3::new(0.0, 2.0, 0.0) })])
        .map(|l| Light { attenuation: Attenuation::default(), ..l.clone() })
        .collect();
    let no_specular = Material { ks: Rgb::ZERO, ..material };
    assert_lanes_are_the_reference(&plain, &no_specular, true);
}

/// [`light`] on spans of random points, in every light model, with and without the points' own
/// colours, at 16, 5 and 1 lanes, against `shade(…).total()` point by point; `plain`: whether
/// the lights and material take [`light_lanes_plain`].
fn assert_lanes_are_the_reference(lights: &[Light], material: &Material, plain: bool) {
    let eye = Vec3::new(0.5, 0.25, 0.125);
    let backward = Vec3::new(0.0, 0.6, 0.8);
    let mut cases = Cases(42);
    for model in [
        LightModel::Lecture { specular: Specular::Phong, local_viewer: true },
        LightModel::Lecture { specular: Specular::Blinn, local_viewer: false },
        LightModel::OpenGl { local_viewer: true },
        LightModel::OpenGl { local_viewer: false },
    ] {
        let global_ambient = Rgb::splat(0.1);
        let spans = SpanLights::new(model, global_ambient, lights, eye, backward);
        assert_eq!(spans.plain && material.ks == Rgb::ZERO, plain, "{model:?}: the path taken");
        for colored in [false, true] {
            for len in [LANES, 5, 1] {
                let mut points = Points { len, ..Points::default() };
                for i in 0..LANES {
                    let p = if i == 0 { Vec3::new(0.25, 0.5, -0.75) } else { cases.vec() };
                    // The eye on the third point (the local viewer's V has no direction there).
                    let p = if i == 2 { eye } else { p };
                    let n = if i == 3 { Vec3::ZERO } else { cases.vec().normalize() };
                    points.p.set(i, p);
                    points.n.set(i, n);
                    points.color.set(i, cases.vec().abs());
                }
                let mut out = V3::default();
                let mut counts = LightCounts::default();
                let stage = super::Stage { lights: &spans, material, colored };
                super::light(&stage, &points, &mut out, &mut counts);
                let mut expected_counts = LightCounts::default();
                for i in 0..len {
                    let p = points.p.get(i);
                    let material = material.with_color(colored.then(|| points.color.get(i)));
                    let v = model.view_vector(p, eye, backward);
                    let expected = cg_core::light::shade_with_visibility_counted(
                        model,
                        global_ambient,
                        lights,
                        &material,
                        p,
                        points.n.get(i),
                        v,
                        |_, _, _| 1.0,
                        &mut expected_counts,
                    )
                    .total();
                    assert_eq!(bits(out.get(i)), bits(expected), "{model:?}, lane {i} of {len}");
                }
                assert_eq!(counts, expected_counts, "{model:?}, {len} lanes: the counts");
            }
        }
    }
}

#[test]
fn a_certified_normal_is_what_every_fragment_of_its_triangle_gets_bit_for_bit() {
    let mut cases = Cases(0x2545_f491_4f6c_dd1d);
    let face = Vec3::new(0.0, 0.0, 7.0);
    let (mut certified_count, mut total) = (0, 0);
    for round in 0..3000 {
        // Unit normals (as a mesh's) and unnormalised ones of every scale.
        let n = match round % 3 {
            0 => cases.vec().normalize(),
            1 => cases.vec() * 1e-3,
            _ => cases.vec() * 1e3,
        };
        total += 1;
        let Some(unit) = certified(n) else { continue };
        certified_count += 1;
        for _ in 0..40 {
            // Weights ≥ 0, not all zero, as the fragment stage makes them: some exactly zero,
            // some tiny, not summing to one.
            let mut w = cases.vec().abs();
            match round % 5 {
                0 => w.x = 0.0,
                1 => (w.y, w.z) = (0.0, 1e-30),
                2 => w *= 1e-20,
                _ => {}
            }
            if w == Vec3::ZERO {
                continue;
            }
            let expected = interpolate_normal([n; 3], w, face);
            assert_eq!(bits(unit), bits(expected), "round {round}: n {n}, w {w}");
            // And through the span kernel, as `fragments` would take it without the shortcut.
            let (mut b, mut normals) = (V3::default(), [V3::default(); 3]);
            b.set(0, w);
            for normal in &mut normals {
                normal.set(0, n);
            }
            let lengths = [[n.as_dvec3().length(); LANES]; 3];
            let mut out = V3::default();
            let keep = interpolate_normals(&b, &normals, &lengths, &mut out);
            assert!(keep[0] && bits(out.get(0)) == bits(unit), "round {round}: n {n}, w {w}");
        }
    }
    // The shortcut is taken for nearly every triangle (a normal near an f32 rounding boundary is
    // refused, about one in 10⁵), and never for a normal that cannot be normalised.
    assert!(certified_count * 1000 >= total * 999, "{certified_count} of {total} certified");
    for bad in [Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 1.0), Vec3::new(f32::INFINITY, 0.0, 0.0)] {
        assert_eq!(certified(bad), None, "{bad}");
    }
}

#[test]
fn the_certified_shortcut_is_taken_only_for_weights_that_interpolate() {
    // Every lane a certified triangle's; one lane's weights all zero, or with a negative one
    // (which the rasterizer never makes): there `interpolate_normal` may fall back to the face
    // normal, so the span must not take the triangle's normal.
    let n = Vec3::new(0.3, 0.4, 0.5);
    let unit = certified(n).expect("a certified normal");
    let face = Vec3::new(0.0, 0.0, 7.0);
    let mut g = Gathered::default();
    for k in 0..3 {
        g.inv_w[k] = [1.0; LANES];
    }
    (g.unit, g.certified) = (V3::splat(unit), [true; LANES]);
    for (case, w) in [
        ("all zero", Vec3::ZERO),
        ("cancelling", Vec3::new(-0.5, 0.25, 0.25)),
        ("one negative", Vec3::new(-0.25, 0.75, 0.5)),
    ] {
        for len in [LANES, 6] {
            let mut screen = V3::splat(Vec3::new(0.2, 0.3, 0.5));
            screen.set(5, w);
            let mut points = Points { len, ..Points::default() };
            let mut b = V3::default();
            let mut normals = |corners: &mut [V3; 3]| *corners = [V3::splat(n); 3];
            let keep = fragments(&screen, &g, false, &mut b, &mut points, &mut normals);
            for i in 0..len {
                let expected = interpolate_normal([n; 3], b.get(i), face);
                let got = if keep[i] { points.n.get(i) } else { face };
                assert_eq!(bits(got), bits(expected), "{case}, {len} lanes: lane {i}");
            }
        }
    }
}
