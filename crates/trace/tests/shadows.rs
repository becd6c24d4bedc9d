//! Shadows (影) with known answers: a sphere of radius 1 centred 2 above a ground plane, lit by a
//! point, a spot, a directional and an area light, and a sphere *beyond* a point light (which
//! must cast no shadow: a shadow ray ends at its light).
//!
//! The oracle is geometry in f64: a point P of the ground is in the shadow of a light (or of one
//! area-light sample) exactly when the segment from P to the light — the ray from P along L, for a
//! directional light — passes within 1 of the sphere's centre. The ground is lit only by diffuse
//! light (k_s = 0), so the expected colour is `k_a·I_a + Σ visible·k_d·I_d·(N·L)` per light or
//! sample, written out here; the tracer must give it within 1e-4 (f32 rounding) at every point
//! whose segments clear the sphere's outline by more than 0.01 (the sphere as a 64 × 32 mesh
//! departs from the exact sphere by less than 0.003). Each case runs twice: with the exact
//! sphere and plane, and with their triangles (`analytic: false`), so both kinds of occluder are
//! tested.

mod common;

use cg_core::Rgb;
use cg_core::glam::{DVec3, Vec3};
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular};
use cg_core::product::Factor;
use cg_core::scene::Scene;
use cg_trace::{Options, Ray, Stats, Tracer};
use common::{plane, sphere};

const CENTRE: DVec3 = DVec3::new(0.0, 2.0, 0.0);
const KA: f32 = 0.5;
const KD: f32 = 0.5;
const IA: f32 = 0.2;

/// The ground (20 × 20 at y = 0), the ball, and `lights`; lecture model, no specular.
fn scene(lights: Vec<Light>, ball_at: DVec3) -> Scene {
    let ground = Material { ka: Rgb::splat(KA), kd: Rgb::splat(KD), ..Material::default() };
    let ball = Material { ka: Rgb::splat(0.3), kd: Rgb::splat(0.6), ..Material::default() };
    let mut s = common::scene(
        vec![
            plane("ground", 20.0, ground, vec![]),
            sphere("ball", 1.0, ball, vec![Factor::translate(ball_at.as_vec3())]),
        ],
        Vec3::new(0.0, 8.0, 12.0),
        Vec3::ZERO,
        16,
        16,
    );
    s.light_model = LightModel::Lecture { specular: Specular::Phong, local_viewer: true };
    s.global_ambient = Rgb::splat(IA);
    s.lights = lights;
    s
}

fn light(kind: LightKind) -> Light {
    Light {
        kind,
        ambient: Rgb::ZERO,
        diffuse: Rgb::ONE,
        specular: Rgb::ZERO,
        attenuation: Attenuation::default(),
    }
}

/// How far the segment from `p` to `q` (or the ray from `p` along `q` when `ray`) passes from
/// `c`, minus the radius 1: negative when it passes through the sphere.
fn clearance(p: DVec3, q: DVec3, ray: bool, c: DVec3) -> f64 {
    let d = if ray { q } else { q - p };
    let t = ((c - p).dot(d) / d.length_squared()).max(0.0);
    let t = if ray { t } else { t.min(1.0) };
    (p + d * t - c).length() - 1.0
}

/// One light as point lights with their share of the diffuse colour: `(position or
/// direction, is_directional, share)`.
fn samples(light: &Light) -> Vec<(DVec3, bool, f64)> {
    match light.kind {
        LightKind::Directional { to_light } => vec![(to_light.as_dvec3().normalize(), true, 1.0)],
        LightKind::Point { position } | LightKind::Spot { position, .. } => {
            vec![(position.as_dvec3(), false, 1.0)]
        }
        LightKind::Area { corner, edge_u, edge_v, samples: [nu, nv] } => {
            let mut out = Vec::new();
            for j in 0..nv {
                for i in 0..nu {
                    let s = (f64::from(i) + 0.5) / f64::from(nu);
                    let t = (f64::from(j) + 0.5) / f64::from(nv);
                    let q = corner.as_dvec3() + edge_u.as_dvec3() * s + edge_v.as_dvec3() * t;
                    out.push((q, false, 1.0 / f64::from(nu * nv)));
                }
            }
            out
        }
    }
}

/// Traces straight down onto the ground at every point of a grid over [−4, 4]² and compares with
/// the oracle; returns (points checked, points in full shadow, points in partial shadow).
fn assert_shadows(name: &str, lights: Vec<Light>, ball_at: DVec3) -> (usize, usize, usize) {
    let scene = scene(lights, ball_at);
    let mut totals = (0, 0, 0);
    for analytic in [true, false] {
        let tracer = Tracer::new(&scene, &Options { analytic, ..Options::default() }).unwrap();
        let (mut checked, mut dark, mut partial) = (0, 0, 0);
        for i in 0..=32 {
            for j in 0..=32 {
                let (x, z) = (-4.0 + 0.25 * f64::from(i), -4.0 + 0.25 * f64::from(j));
                let p = DVec3::new(x, 0.0, z);
                let (mut diffuse, mut blocked, mut all, mut unsure) = (0.0, 0.0, 0.0, false);
                for light in &scene.lights {
                    for (q, directional, share) in samples(light) {
                        let c = clearance(p, q, directional, ball_at);
                        unsure |= c.abs() < 0.01;
                        let l = if directional { q } else { (q - p).normalize() };
                        let n_dot_l = l.y.max(0.0); // N = +Y
                        all += share;
                        if c < 0.0 {
                            blocked += share;
                        } else {
                            diffuse += share * f64::from(KD) * n_dot_l;
                        }
                    }
                }
                if unsure {
                    continue;
                }
                let expected = f64::from(KA * IA) + diffuse;
                let ray = Ray::new(Vec3::new(x as f32, 0.5, z as f32), Vec3::NEG_Y);
                let got = tracer.trace(&ray, 0, &mut Stats::default());
                assert!(
                    (f64::from(got.x) - expected).abs() < 1e-4,
                    "{name} (analytic {analytic}): ground at ({x}, {z}) is {got}, expected {expected:.5} ({:.0} % of the light blocked)",
                    100.0 * blocked / all
                );
                checked += 1;
                dark += usize::from(blocked == all);
                partial += usize::from(blocked > 0.0 && blocked < all);
            }
        }
        eprintln!(
            "{name} (analytic {analytic}): {checked} points, {dark} in full shadow, {partial} partly"
        );
        totals = (totals.0 + checked, totals.1 + dark, totals.2 + partial);
    }
    totals
}

#[test]
fn a_point_light_casts_the_spheres_shadow() {
    let (checked, dark, _) = assert_shadows(
        "point",
        vec![light(LightKind::Point { position: Vec3::new(0.0, 5.0, 0.0) })],
        CENTRE,
    );
    assert!(checked > 1800 && dark > 100, "premise: {checked} points, {dark} in shadow");
}

#[test]
fn a_spot_light_casts_the_spheres_shadow() {
    // A wide cone (60°, exponent 0: factor 1 inside) over the whole test grid, from the side.
    let spot = light(LightKind::Spot {
        position: Vec3::new(1.0, 5.0, 0.5),
        direction: Vec3::new(-0.2, -1.0, -0.1),
        cutoff_deg: 60.0,
        exponent: 0.0,
        inner_deg: None,
    });
    let (checked, dark, _) = assert_shadows("spot", vec![spot], CENTRE);
    assert!(checked > 1800 && dark > 100, "premise: {checked} points, {dark} in shadow");
}

#[test]
fn a_directional_light_casts_the_spheres_shadow() {
    let sun = light(LightKind::Directional { to_light: Vec3::new(0.3, 1.0, 0.2) });
    let (checked, dark, _) = assert_shadows("directional", vec![sun], CENTRE);
    assert!(checked > 1800 && dark > 100, "premise: {checked} points, {dark} in shadow");
}

#[test]
fn an_area_light_casts_a_penumbra_with_the_blocked_fraction_of_its_samples() {
    // A 2 × 2 square light facing down at height 5, as 4 × 4 point lights: under the ball the
    // umbra (all 16 blocked), around it the penumbra, where the colour drops by the blocked
    // samples' share — each sample its own shadow ray.
    let area = light(LightKind::Area {
        corner: Vec3::new(-1.0, 5.0, -1.0),
        edge_u: Vec3::new(2.0, 0.0, 0.0),
        edge_v: Vec3::new(0.0, 0.0, 2.0),
        samples: [4, 4],
    });
    let (checked, dark, partial) = assert_shadows("area", vec![area], CENTRE);
    assert!(checked > 500 && dark > 20 && partial > 50, "premise: {checked}, {dark}, {partial}");
}

#[test]
fn an_occluder_beyond_the_light_casts_no_shadow() {
    // The light at height 0.8, the ball above it (its bottom at 1.2): every segment from the
    // ground to the light stays below the ball. A shadow ray that ran on past its light would
    // find the ball and darken the ground under it.
    let below = light(LightKind::Point { position: Vec3::new(0.0, 0.8, 0.0) });
    let (checked, dark, partial) =
        assert_shadows("beyond the light", vec![below], DVec3::new(0.0, 2.2, 0.0));
    assert!(checked > 2000 && dark == 0 && partial == 0, "{checked}, {dark}, {partial}");
}
