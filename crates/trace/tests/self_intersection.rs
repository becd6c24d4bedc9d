//! Spawned rays never hit their own surface at t ≈ 0: 10⁶ rays in release (72 000 in
//! debug) leave random points on exact spheres, exact planes and far-offset triangle meshes
//! (coordinates up to 1e4, sizes from 1 to 100), in random directions.
//!
//! - Leaving on the outside of a convex surface (a sphere, a convex mesh) or to either side of a
//!   plane, a ray must hit nothing at all (the scene holds only that surface).
//! - Going into a sphere, it must hit the far side, at no less than half the exact chord
//!   `−2(p − c)·d` (rays within 1e-3 of grazing are skipped: their chord is too short to tell).
//! - Going into a convex mesh, it must hit the inside of a *different* face (the mesh is closed
//!   and the test watertight, so it cannot escape).

mod common;

use cg_core::glam::Vec3;
use cg_core::light::Material;
use cg_core::product::Factor;
use cg_core::scene::Scene;
use cg_testkit::Inputs;
use cg_trace::{Options, Primitive, Ray, Stats, Tracer};
use common::{object, plane, scene, sphere};

/// Surfaces per kind, points per surface, rays per point.
fn counts() -> (usize, usize, usize) {
    if cfg!(debug_assertions) { (10, 40, 60) } else { (40, 100, 84) }
}

/// A random far-away position (each coordinate up to 1e4 in magnitude, log-uniform).
fn far(inputs: &mut Inputs) -> Vec3 {
    inputs.vec3_log_uniform(-1.0, 4.0)
}

fn lone(object: cg_core::scene::Object) -> Scene {
    scene(vec![object], Vec3::new(0.0, 0.0, 10.0), Vec3::ZERO, 8, 8)
}

fn random_direction_on_side(inputs: &mut Inputs, n: Vec3, outwards: bool) -> Vec3 {
    loop {
        let d = inputs.unit_vec3();
        let c = d.dot(n);
        if c != 0.0 && (c > 0.0) == outwards {
            return d;
        }
    }
}

#[test]
fn rays_spawned_from_exact_spheres_never_hit_them_at_t_near_zero() {
    let (surfaces, points, rays) = counts();
    let mut inputs = Inputs::seeded(101);
    let mut cast = 0usize;
    for s in 0..surfaces {
        let centre = far(&mut inputs);
        let radius = 10f64.powf(inputs.uniform(0.0, 2.0)) as f32;
        let ball = sphere("ball", radius, Material::default(), vec![Factor::translate(centre)]);
        let sc = lone(ball);
        let tracer = Tracer::new(&sc, &Options::default()).unwrap();
        let c = centre.as_dvec3();
        for _ in 0..points {
            let from = centre + 3.0 * radius * inputs.unit_vec3();
            let towards = centre + 0.9 * radius * inputs.unit_vec3();
            let ray = Ray::new(from, (towards - from).normalize());
            let Some(hit) = tracer.intersect(&ray, &mut Stats::default()) else {
                panic!("sphere {s} (centre {centre}, radius {radius}): a ray at it missed")
            };
            for _ in 0..rays {
                cast += 1;
                let outwards = inputs.coin();
                let d = random_direction_on_side(&mut inputs, hit.geometric_normal, outwards);
                let spawned = hit.spawn_ray(d);
                let again = tracer.intersect(&spawned, &mut Stats::default());
                let what = || {
                    format!(
                        "sphere {s} (centre {centre}, radius {radius}), from {} ({}) along {d}",
                        hit.p,
                        if outwards { "outwards" } else { "inwards" }
                    )
                };
                if outwards {
                    assert!(again.is_none(), "{}: hit itself again: {again:?}", what());
                    continue;
                }
                let chord = -2.0 * (hit.p.as_dvec3() - c).dot(d.as_dvec3());
                if chord < 1e-3 * f64::from(radius) {
                    continue;
                }
                let again =
                    again.unwrap_or_else(|| panic!("{}: escaped through the sphere", what()));
                assert!(
                    f64::from(again.t) >= 0.5 * chord && !again.is_front(d),
                    "{}: hit at t = {} (front: {}), the far side is at {chord}",
                    what(),
                    again.t,
                    again.is_front(d)
                );
            }
        }
    }
    eprintln!("{cast} rays spawned from spheres");
}

#[test]
fn rays_spawned_from_exact_planes_never_hit_them() {
    let (surfaces, points, rays) = counts();
    let mut inputs = Inputs::seeded(202);
    let mut cast = 0usize;
    for s in 0..surfaces {
        let place = far(&mut inputs);
        let axis = inputs.unit_vec3();
        let angle = inputs.uniform_f32(0.0, 360.0);
        let scale = Vec3::new(
            inputs.uniform_f32(1.0, 100.0),
            inputs.uniform_f32(1.0, 100.0),
            inputs.uniform_f32(1.0, 100.0),
        );
        let transform =
            vec![Factor::translate(place), Factor::rotate_deg(angle, axis), Factor::scale(scale)];
        let sc = lone(plane("plane", 2.0, Material::default(), transform));
        let tracer = Tracer::new(&sc, &Options::default()).unwrap();
        let model = sc.objects[0].transform.matrix().unwrap();
        for _ in 0..points {
            // A random point of the square, in world space, seen from a random point above it.
            let on = Vec3::new(inputs.uniform_f32(-0.9, 0.9), 0.0, inputs.uniform_f32(-0.9, 0.9));
            let target = model.transform_point3(on);
            let up = if inputs.coin() { 1.0 } else { -1.0 };
            let from = model.transform_point3(on + Vec3::new(0.3, up, -0.2));
            let ray = Ray::new(from, (target - from).normalize());
            let Some(hit) = tracer.intersect(&ray, &mut Stats::default()) else {
                panic!("plane {s}: a ray at it missed")
            };
            for _ in 0..rays {
                cast += 1;
                let outwards = inputs.coin();
                let d = random_direction_on_side(&mut inputs, hit.geometric_normal, outwards);
                let again = tracer.intersect(&hit.spawn_ray(d), &mut Stats::default());
                assert!(
                    again.is_none(),
                    "plane {s} (at {place}, scale {scale}): a ray from {} along {d} hit it again: {again:?}",
                    hit.p
                );
            }
        }
    }
    eprintln!("{cast} rays spawned from planes");
}

#[test]
fn rays_spawned_from_far_offset_meshes_never_hit_their_own_face() {
    let (surfaces, points, rays) = counts();
    let mut inputs = Inputs::seeded(303);
    let mut cast = 0usize;
    for s in 0..surfaces {
        let place = far(&mut inputs);
        let radius = 10f64.powf(inputs.uniform(0.0, 2.0)) as f32;
        let mesh = if s % 2 == 0 {
            cg_core::shapes::icosphere(radius, 2).unwrap()
        } else {
            cg_core::shapes::uv_sphere(radius, 24, 12).unwrap()
        };
        let axis = inputs.unit_vec3();
        let transform = vec![
            Factor::translate(place),
            Factor::rotate_deg(inputs.uniform_f32(0.0, 360.0), axis),
        ];
        let sc = lone(object("mesh", mesh, Material::default(), transform));
        let tracer = Tracer::new(&sc, &Options::default()).unwrap();
        assert!(tracer.triangle_count() > 0);
        for _ in 0..points {
            let from = place + 3.0 * radius * inputs.unit_vec3();
            let towards = place + 0.8 * radius * inputs.unit_vec3();
            let ray = Ray::new(from, (towards - from).normalize());
            let Some(hit) = tracer.intersect(&ray, &mut Stats::default()) else {
                panic!("mesh {s} (at {place}, radius {radius}): a ray at it missed")
            };
            let Primitive::Triangle { face, .. } = hit.primitive else { unreachable!() };
            for _ in 0..rays {
                cast += 1;
                let outwards = inputs.coin();
                let d = random_direction_on_side(&mut inputs, hit.geometric_normal, outwards);
                let again = tracer.intersect(&hit.spawn_ray(d), &mut Stats::default());
                let what = format!(
                    "mesh {s} (at {place}, radius {radius}), face F{face}, from {} {} along {d}",
                    hit.p,
                    if outwards { "outwards" } else { "inwards" }
                );
                if outwards {
                    assert!(again.is_none(), "{what}: hit the convex mesh again: {again:?}");
                    continue;
                }
                let again = again.unwrap_or_else(|| panic!("{what}: escaped the closed mesh"));
                let Primitive::Triangle { face: other, .. } = again.primitive else {
                    unreachable!()
                };
                assert!(
                    other != face && !again.is_front(d) && again.t > 0.0,
                    "{what}: hit F{other} at t = {} (front: {})",
                    again.t,
                    again.is_front(d)
                );
            }
        }
    }
    eprintln!("{cast} rays spawned from meshes");
}

#[test]
fn a_million_rays_in_release() {
    let (surfaces, points, rays) = counts();
    let total = 3 * surfaces * points * rays;
    if !cfg!(debug_assertions) {
        assert!(total >= 1_000_000, "the three tests above spawn {total} rays");
    }
}
