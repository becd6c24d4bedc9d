//! The global terms against known answers: a glass slab shifts a ray sideways by the textbook
//! amount, a ray inside glass beyond the critical angle reflects totally, a mirror sphere
//! reflects by 2(N·D)N − D, and the weights of the reflected and refracted rays share k_t by
//! F + T = 1.

mod common;

use cg_core::Rgb;
use cg_core::glam::{DVec3, Vec3};
use cg_core::light::Material;
use cg_core::product::Factor;
use cg_testkit::{Inputs, assert_approx_eq};
use cg_trace::{Fresnel, Options, Ray, Stats, Tracer, Weights};
use common::{distance_from_line, glass, mirror, plane, scene, sphere};

/// A slab of glass (η = 1.5) between y = 0 and y = −thickness, as two exact planes: the top
/// facing +Y, the bottom turned over to face −Y.
fn slab_of_planes(thickness: f32) -> cg_core::scene::Scene {
    let top = plane("top", 200.0, glass(1.5), vec![]);
    let bottom = plane(
        "bottom",
        200.0,
        glass(1.5),
        vec![Factor::translate(Vec3::new(0.0, -thickness, 0.0)), Factor::rotate_x_deg(180.0)],
    );
    scene(vec![top, bottom], Vec3::new(0.0, 5.0, 5.0), Vec3::ZERO, 64, 64)
}

/// The same slab as a thin box mesh (triangles): its top face at y = 0.
fn slab_of_triangles(thickness: f32) -> cg_core::scene::Scene {
    let mesh = cg_core::shapes::cuboid(Vec3::new(200.0, thickness, 200.0)).unwrap();
    let mut slab = common::object(
        "slab",
        mesh,
        glass(1.5),
        vec![Factor::translate(Vec3::new(0.0, -0.5 * thickness, 0.0))],
    );
    slab.normals = cg_core::scene::NormalSource::Face;
    scene(vec![slab], Vec3::new(0.0, 5.0, 5.0), Vec3::ZERO, 64, 64)
}

/// Follows a ray from above through the slab: enter, refract, leave, refract. Returns the
/// ray that comes out.
fn through_slab(tracer: &Tracer, ray: &Ray, what: &str) -> Ray {
    let mut stats = Stats::default();
    let enter =
        tracer.intersect(ray, &mut stats).unwrap_or_else(|| panic!("{what}: missed the slab"));
    assert!(enter.is_front(ray.direction), "{what}: the top is hit from outside");
    assert_approx_eq!(enter.p.y, 0.0, abs = 1e-6, "{what}: entry on the top face");
    let inside = tracer.global_rays(ray, &enter).transmission.expect("refracted ray").ray;
    let leave = tracer.intersect(&inside, &mut stats).unwrap_or_else(|| panic!("{what}: no exit"));
    assert!(!leave.is_front(inside.direction), "{what}: the bottom is hit from inside");
    let out = tracer.global_rays(&inside, &leave);
    assert!(!out.total_internal_reflection, "{what}: a slab never traps light");
    out.transmission.expect("the ray leaves the slab").ray
}

#[test]
fn a_glass_slab_shifts_a_ray_sideways_by_t_sin_of_the_angle_difference_over_cos() {
    // Textbook: a slab of thickness t shifts the ray by t·sin(θ₁ − θ₂)/cos θ₂, θ₂ from Snell.
    // Tolerance 1e-5 (absolute, scene units): the hit points carry f32 rounding (~1e-6 at these
    // magnitudes), spawned rays start ~1e-6 off the surface, and the directions are f32.
    for (thickness, build) in [
        (0.5f32, slab_of_planes as fn(f32) -> cg_core::scene::Scene),
        (2.0, slab_of_planes),
        (0.5, slab_of_triangles),
        (2.0, slab_of_triangles),
    ] {
        let s = build(thickness);
        let kind = if s.objects.len() == 2 { "planes" } else { "triangles" };
        let options = Options { analytic: kind == "planes", ..Options::default() };
        let tracer = Tracer::new(&s, &options).unwrap();
        for theta1_deg in [0.0f64, 10.0, 30.0, 45.0, 60.0, 80.0] {
            let what = format!("{kind}, thickness {thickness}, θ₁ = {theta1_deg}°");
            let theta1 = theta1_deg.to_radians();
            let d = DVec3::new(theta1.sin(), -theta1.cos(), 0.0).as_vec3();
            // Aim at (0.3, 0, 0.2) from 3 units away.
            let origin = Vec3::new(0.3, 0.0, 0.2) - 3.0 * d;
            let ray = Ray::new(origin, d);
            let out = through_slab(&tracer, &ray, &what);
            assert_approx_eq!(out.direction, d, abs = 1e-6, "{what}: leaves parallel");
            let theta2 = (theta1.sin() / 1.5).asin();
            let expected = f64::from(thickness) * (theta1 - theta2).sin() / theta2.cos();
            let shift = distance_from_line(out.origin, origin, d);
            assert_approx_eq!(shift, expected, abs = 1e-5, "{what}: sideways shift");
        }
    }
}

#[test]
fn snells_law_holds_inside_the_slab() {
    let s = slab_of_planes(1.0);
    let tracer = Tracer::new(&s, &Options::default()).unwrap();
    let mut inputs = Inputs::seeded(11);
    for _ in 0..200 {
        let theta1 = inputs.uniform(0.0, 89.0).to_radians();
        let phi = inputs.uniform(0.0, std::f64::consts::TAU);
        let d = DVec3::new(theta1.sin() * phi.cos(), -theta1.cos(), theta1.sin() * phi.sin());
        let d = d.as_vec3();
        let ray = Ray::new(Vec3::new(0.1, 2.0, -0.3), d);
        let hit = tracer.intersect(&ray, &mut Stats::default()).expect("hits the top");
        let t = tracer.global_rays(&ray, &hit).transmission.expect("refracts").ray.direction;
        // n₁ sin θ₁ = n₂ sin θ₂ with sin = |d × N|, N = +Y; the refracted ray stays in the plane
        // of incidence (d, N).
        let sin1 = d.as_dvec3().cross(DVec3::Y).length();
        let sin2 = t.as_dvec3().cross(DVec3::Y).length();
        assert_approx_eq!(sin2 * 1.5, sin1, abs = 2e-6, "θ₁ = {}°", theta1.to_degrees());
        let plane_normal = d.as_dvec3().cross(DVec3::Y);
        assert_approx_eq!(
            t.as_dvec3().dot(plane_normal),
            0.0,
            abs = 1e-6,
            "in the plane of incidence"
        );
        assert!(t.y < 0.0, "goes on downwards");
    }
}

#[test]
fn beyond_the_critical_angle_a_ray_inside_glass_reflects_totally() {
    // Inside the slab (η = 1.5 below y = 0), heading up at θ from the normal: the critical angle
    // is asin(1/1.5) = 41.81°.
    let critical = (1.0f64 / 1.5).asin().to_degrees();
    let s = slab_of_planes(1.0);
    let tracer = Tracer::new(&s, &Options::default()).unwrap();
    let ray_at = |theta_deg: f64| {
        let th = theta_deg.to_radians();
        Ray::new(Vec3::new(0.0, -0.5, 0.0), DVec3::new(th.sin(), th.cos(), 0.0).as_vec3())
    };
    for theta in [critical + 0.01, 50.0, 60.0, 89.0] {
        let ray = ray_at(theta);
        let hit = tracer.intersect(&ray, &mut Stats::default()).expect("hits the top from inside");
        assert!(!hit.is_front(ray.direction));
        let g = tracer.global_rays(&ray, &hit);
        assert!(g.total_internal_reflection, "θ = {theta}° > {critical}° must reflect totally");
        assert!(g.transmission.is_none(), "θ = {theta}°: no transmitted ray");
        assert_eq!(g.fresnel, 1.0);
        let r = g.reflection.expect("the reflected ray");
        assert_eq!(
            r.weight,
            Rgb::ONE,
            "all of k_t's share (k_r = 0, k_t = 1) goes to the mirror ray"
        );
        // The mirror direction: D − 2(D·N)N with N = −Y on the inside.
        let d = ray.direction.as_dvec3();
        let expected = d - 2.0 * d.dot(DVec3::Y) * DVec3::Y;
        assert_approx_eq!(r.ray.direction, expected.as_vec3(), abs = 1e-6, "θ = {theta}°");
        assert!(r.ray.origin.y < 0.0, "the reflected ray starts inside");
    }
    // Just below the critical angle light gets out, grazing.
    let ray = ray_at(critical - 0.01);
    let hit = tracer.intersect(&ray, &mut Stats::default()).unwrap();
    let g = tracer.global_rays(&ray, &hit);
    assert!(!g.total_internal_reflection && g.transmission.is_some(), "θ just below critical");
    assert!(g.fresnel > 0.5, "near the critical angle most light reflects: F = {}", g.fresnel);

    // Traced: the ray bounces between the faces by total internal reflection. From depth 1,
    // hits at depths 1, 2, 3, 4 spawn one mirror ray each (depth 5 = max_depth spawns none).
    let mut stats = Stats::default();
    let color = tracer.trace(&ray_at(60.0), 1, &mut stats);
    assert!(color.is_finite());
    assert_eq!(stats.total_internal_reflections, 4, "{stats:?}");
    assert_eq!(stats.reflection_rays, 4, "{stats:?}");
    assert_eq!(stats.refraction_rays, 0, "{stats:?}");
    assert_eq!(stats.deepest_ray, 5, "{stats:?}");
}

#[test]
fn a_mirror_sphere_reflects_by_2_n_dot_d_n_minus_d() {
    // Centre and radius exact in f32 (translate, then scale by 2 of a radius-0.5 sphere), so the
    // f64 oracle below intersects the very sphere the tracer sees.
    let centre = Vec3::new(0.75, 1.25, -0.5);
    let ball = sphere(
        "mirror",
        0.5,
        mirror(),
        vec![Factor::translate(centre), Factor::scale(Vec3::splat(2.0))],
    );
    let s = scene(vec![ball], Vec3::new(0.0, 2.0, 8.0), centre, 64, 64);
    let tracer = Tracer::new(&s, &Options::default()).unwrap();
    let mut inputs = Inputs::seeded(5);
    let n = if cfg!(debug_assertions) { 300 } else { 3000 };
    let c = centre.as_dvec3();
    for i in 0..n {
        let origin = centre + 4.0 * inputs.unit_vec3();
        let target = centre + 0.99 * inputs.unit_vec3();
        let d = (target - origin).normalize();
        let ray = Ray::new(origin, d);
        let hit = tracer
            .intersect(&ray, &mut Stats::default())
            .unwrap_or_else(|| panic!("ray {i} missed"));
        // Oracle: the nearer root of |o + t·d − c|² = 1 in f64 (d is unit only to f32 rounding).
        let (o, dd) = (origin.as_dvec3(), d.as_dvec3());
        let f = o - c;
        let (a, b) = (dd.length_squared(), f.dot(dd));
        let disc = b * b - a * (f.length_squared() - 1.0);
        let t = (-b - disc.sqrt()) / a;
        let p_exact = o + t * dd;
        let err = (hit.p.as_dvec3() - p_exact).abs();
        assert!(
            err.cmple(hit.p_error.as_dvec3()).all(),
            "ray {i}: hit point {} is {err} from the exact {p_exact}, beyond its error bound {}",
            hit.p,
            hit.p_error
        );
        let normal = p_exact - c;
        let view = -dd; // D: towards where the ray came from
        let expected = 2.0 * normal.dot(view) * normal - view;
        let g = tracer.global_rays(&ray, &hit);
        let r = g.reflection.expect("a mirror reflects");
        assert!(g.transmission.is_none());
        assert_eq!(r.weight, Rgb::ONE, "k_r = 1, no Fresnel without k_t");
        assert_approx_eq!(r.ray.direction, expected.as_vec3(), abs = 2e-6, "ray {i}");
    }

    // Rotated and scaled: the normal goes through the cofactor normal matrix.
    let ball = sphere(
        "mirror",
        0.5,
        mirror(),
        vec![
            Factor::translate(centre),
            Factor::rotate_deg(37.0, Vec3::new(1.0, 2.0, 3.0)),
            Factor::scale(Vec3::splat(2.0)),
        ],
    );
    let s = scene(vec![ball], Vec3::new(0.0, 2.0, 8.0), centre, 64, 64);
    let tracer = Tracer::new(&s, &Options::default()).unwrap();
    for i in 0..n {
        let origin = centre + 4.0 * inputs.unit_vec3();
        let d = (centre + 0.99 * inputs.unit_vec3() - origin).normalize();
        let ray = Ray::new(origin, d);
        let hit = tracer.intersect(&ray, &mut Stats::default()).unwrap();
        let normal = (hit.p.as_dvec3() - c).normalize();
        let view = -d.as_dvec3();
        let expected = 2.0 * normal.dot(view) * normal - view;
        let r = tracer.global_rays(&ray, &hit).reflection.unwrap();
        assert_approx_eq!(r.ray.direction, expected.as_vec3(), abs = 1e-5, "rotated, ray {i}");
    }
}

#[test]
fn fresnel_and_transmission_sum_to_one_and_the_weights_to_k_t_share() {
    // F + T = 1 with both in [0, 1], for both variants, in and out of the denser medium.
    let mut inputs = Inputs::seeded(21);
    for fresnel in [Fresnel::Exact, Fresnel::Schlick] {
        for _ in 0..20_000 {
            let cos_i = inputs.uniform_f32(0.0, 1.0);
            let eta = inputs.uniform_f32(1.0, 3.0);
            let (eta_i, eta_t) = if inputs.coin() { (1.0, eta) } else { (eta, 1.0) };
            let f = fresnel.reflectance(cos_i, eta_i, eta_t);
            let t = 1.0 - f;
            assert!((0.0..=1.0).contains(&f) && (0.0..=1.0).contains(&t), "{fresnel:?}: F = {f}");
            let kr = Rgb::new(inputs.uniform_f32(0.0, 1.0), inputs.uniform_f32(0.0, 1.0), 0.0);
            let kt = Rgb::new(inputs.uniform_f32(0.0, 1.0), 0.0, 1.0);
            let w = Weights::split(kr, kt, f);
            assert!(w.reflected.cmpge(Rgb::ZERO).all() && w.transmitted.cmpge(Rgb::ZERO).all());
            // k_t·F + k_t·(1 − F) = k_t up to three f32 roundings.
            assert_approx_eq!((w.reflected - kr) + w.transmitted, kt, abs = 4.0 * f32::EPSILON);
        }
    }
    // Total internal reflection: all of k_t goes to the reflected ray.
    let w = Weights::split(Rgb::splat(0.1), Rgb::splat(0.9), 1.0);
    assert_eq!((w.reflected, w.transmitted), (Rgb::splat(0.1) + Rgb::splat(0.9), Rgb::ZERO));
    assert_eq!(
        Weights::split(Rgb::ZERO, Rgb::ONE, f32::NAN).transmitted,
        Rgb::ZERO,
        "NaN → all reflected"
    );
}

/// The exact dielectric Fresnel reflectance in f64 (the oracle), and Schlick's with the cosine
/// on the less dense side.
fn fresnel_oracle(cos_i: f64, eta_i: f64, eta_t: f64, schlick: bool) -> f64 {
    let sin_t = eta_i / eta_t * (1.0 - cos_i * cos_i).sqrt();
    if sin_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin_t * sin_t).sqrt();
    if schlick {
        let r0 = ((eta_i - eta_t) / (eta_i + eta_t)).powi(2);
        let c = if eta_i > eta_t { cos_t } else { cos_i };
        return r0 + (1.0 - r0) * (1.0 - c).powi(5);
    }
    let rs = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    let rp = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    0.5 * (rs * rs + rp * rp)
}

#[test]
fn a_glass_sphere_applies_fresnel_from_either_side_and_its_weights_sum_to_kr_plus_kt() {
    let kr = Rgb::new(0.1, 0.2, 0.0);
    let kt = Rgb::new(0.9, 0.5, 1.0);
    let material = Material { kr, kt, eta: 1.5, ..glass(1.5) };
    let centre = Vec3::new(0.5, 0.25, -1.0);
    let ball = sphere("glass", 1.0, material, vec![Factor::translate(centre)]);
    let s = scene(vec![ball], Vec3::new(0.0, 2.0, 8.0), centre, 64, 64);
    let c = centre.as_dvec3();
    let mut inputs = Inputs::seeded(33);
    let n = if cfg!(debug_assertions) { 400 } else { 4000 };
    for fresnel in [Fresnel::Exact, Fresnel::Schlick] {
        let tracer = Tracer::new(&s, &Options { fresnel, ..Options::default() }).unwrap();
        let (mut tir, mut inside, mut outside) = (0, 0, 0);
        for i in 0..n {
            // Half the rays start outside, half inside the glass.
            let from_inside = i % 2 == 1;
            let origin = centre + inputs.unit_vec3() * if from_inside { 0.9 } else { 3.0 };
            let d = if from_inside {
                inputs.unit_vec3()
            } else {
                (centre + 0.95 * inputs.unit_vec3() - origin).normalize()
            };
            let ray = Ray::new(origin, d);
            let hit = tracer.intersect(&ray, &mut Stats::default()).unwrap();
            assert_eq!(hit.is_front(d), !from_inside);
            let g = tracer.global_rays(&ray, &hit);
            let normal = (hit.p.as_dvec3() - c).normalize();
            let cos_i = normal.dot(d.as_dvec3()).abs();
            let (eta_i, eta_t) = if from_inside { (1.5, 1.0) } else { (1.0, 1.5) };
            let oracle = fresnel_oracle(cos_i, eta_i, eta_t, fresnel == Fresnel::Schlick);
            let reflected = g.reflection.expect("k_r + k_t·F > 0").weight;
            if g.total_internal_reflection {
                tir += 1;
                assert!(from_inside, "only inside glass");
                assert!(g.transmission.is_none());
                assert_eq!(reflected, kr + kt, "TIR sends all of k_t to the mirror ray");
                assert!(oracle >= 0.999, "TIR where the oracle has F = {oracle}");
            } else {
                if from_inside {
                    inside += 1
                } else {
                    outside += 1
                }
                let transmitted = g.transmission.expect("refracted ray").weight;
                assert_approx_eq!(
                    reflected + transmitted,
                    kr + kt,
                    abs = 4.0 * f32::EPSILON,
                    "ray {i}"
                );
                // Away from the critical angle (where F is steep), F matches the f64 oracle.
                let sin_t = eta_i / eta_t * (1.0 - cos_i * cos_i).sqrt();
                if sin_t < 0.99 {
                    assert_approx_eq!(
                        f64::from(g.fresnel),
                        oracle,
                        abs = 1e-5,
                        "{fresnel:?} ray {i}, inside: {from_inside}"
                    );
                }
            }
        }
        assert!(
            tir > 10 && inside > 10 && outside > 10,
            "cases: {tir} TIR, {inside} out of glass, {outside} into glass"
        );
    }
}
