//! `generate_ray` and `intersect` against independent oracles: primary rays project back onto
//! their pixel centres through the rasterizer's matrices; the BVH finds exactly the brute-force
//! closest hit; the watertight triangle test lets no ray through a closed mesh's edges or
//! vertices; the exact sphere and its triangle mesh cover the same pixels up to the tessellation
//! error.

mod common;

use cg_core::glam::{Vec3, Vec3Swizzles};
use cg_core::light::Material;
use cg_core::product::Factor;
use cg_core::scene::Camera;
use cg_core::transform::project_point;
use cg_testkit::{Inputs, assert_approx_eq};
use cg_trace::bvh::Bvh;
use cg_trace::triangle::{RaySetup, intersect_triangle};
use cg_trace::{Options, Ray, Stats, Tracer};
use common::{scene, sphere};

#[test]
fn primary_rays_pass_through_the_pixel_centres_of_the_rasterizers_projection() {
    // Oracle: the forward transform. A point on pixel (x, y)'s ray, projected by P·V
    // (`project_point`) and mapped by the viewport, must land on (x + ½, y + ½); the ray's ends
    // must have depth 0 (near plane) and 1 (far plane).
    let mut s = common::shipped("course-sample");
    for (w, h, camera) in [
        (64u32, 48u32, s.camera),
        (
            40,
            70,
            Camera::LookAt {
                eye: Vec3::new(3.0, -2.0, 7.0),
                target: Vec3::new(0.5, 1.0, -1.0),
                up: Vec3::new(0.1, 1.0, 0.0),
            },
        ),
    ] {
        s.camera = camera;
        (s.width, s.height) = (w, h);
        let tracer = Tracer::new(&s, &Options::default()).unwrap();
        let pv = s.projection_matrix().unwrap() * s.view_product().unwrap().matrix().unwrap();
        let eye = s.camera.eye_position();
        for y in 0..h {
            for x in 0..w {
                let ray = tracer.generate_ray(x, y);
                assert_approx_eq!(
                    ray.origin,
                    eye,
                    abs = 1e-5,
                    "every primary ray starts at the eye"
                );
                assert_approx_eq!(ray.direction.length(), 1.0, abs = 1e-6);
                for (t, depth) in [
                    (ray.t_min, Some(0.0)),
                    (0.5 * (ray.t_min + ray.t_max), None),
                    (ray.t_max, Some(1.0)),
                ] {
                    let ndc = project_point(pv, ray.at(t)).expect("in front of the eye");
                    let window = ((ndc.x + 1.0) * 0.5 * w as f32, (1.0 - ndc.y) * 0.5 * h as f32);
                    assert_approx_eq!(window.0, x as f32 + 0.5, abs = 2e-3, "pixel ({x}, {y}), x");
                    assert_approx_eq!(window.1, y as f32 + 0.5, abs = 2e-3, "pixel ({x}, {y}), y");
                    if let Some(depth) = depth {
                        assert_approx_eq!(ndc.z, depth, abs = 1e-4, "pixel ({x}, {y}) at t = {t}");
                    }
                }
            }
        }
        // The image size option sets the aspect ratio, as gluPerspective in reshape().
        let wide =
            Tracer::new(&s, &Options { size: Some((2 * w, h)), ..Options::default() }).unwrap();
        let p =
            cg_core::transform::perspective(45.0, 2.0 * w as f32 / h as f32, 1.0, 500.0).unwrap();
        let pv = p * s.view_product().unwrap().matrix().unwrap();
        let ray = wide.generate_ray(0, 0);
        let ndc = project_point(pv, ray.at(ray.t_min * 2.0)).unwrap();
        assert_approx_eq!(
            ndc.xy(),
            cg_core::glam::Vec2::new(-1.0 + 1.0 / (2 * w) as f32, 1.0 - 1.0 / h as f32),
            abs = 1e-4
        );
    }
}

/// The nearest near plane and the farthest eye the scene format allows (`cg_scene::MIN_NEAR`,
/// `cg_scene::MAX_COORDINATE`) give the primary rays of the course's near plane of 1: their
/// directions are taken from the eye in f64, not from its f32 rounding (which turned them by up
/// to 2e-3 rad, 1.5 pixels of the course's window, at near = 1e-4).
#[test]
fn primary_rays_keep_their_direction_with_a_tiny_near_plane_far_from_the_origin() {
    let mut s = common::shipped("course-sample");
    (s.width, s.height) = (64, 64);
    s.projection.far = 100.0;
    let far_away = Vec3::new(1.0, 0.0, 1.0) * (cg_scene::MAX_COORDINATE - 20.0);
    for target in [Vec3::ZERO, far_away] {
        let Camera::Orbit(orbit) = &mut s.camera else { panic!("the course's orbit camera") };
        orbit.target = target;
        s.projection.near = 1.0;
        let mut tiny_near = s.clone();
        tiny_near.projection.near = cg_scene::MIN_NEAR;
        let course = Tracer::new(&s, &Options::default()).unwrap();
        let tiny = Tracer::new(&tiny_near, &Options::default()).unwrap();
        for (x, y) in [(0, 0), (31, 17), (63, 63), (5, 60)] {
            let (a, b) = (course.generate_ray(x, y), tiny.generate_ray(x, y));
            let angle = a.direction.angle_between(b.direction);
            assert!(angle < 1e-5, "target {target}, pixel ({x}, {y}): {angle} rad apart");
            assert_approx_eq!(a.origin, b.origin, abs = 0.0);
        }
    }
}

/// Random triangle soups and meshes, far from the origin too.
fn triangle_sets(inputs: &mut Inputs) -> Vec<(String, Vec<[Vec3; 3]>)> {
    let mut sets = Vec::new();
    for k in 0..4 {
        let offset = if k % 2 == 0 { Vec3::ZERO } else { inputs.vec3_log_uniform(2.0, 4.0) };
        let soup: Vec<[Vec3; 3]> = (0..300)
            .map(|_| {
                let c = offset + inputs.vec3_in_cube(5.0);
                let size = 10f64.powf(inputs.uniform(-2.0, 0.5)) as f32;
                [
                    c + size * inputs.unit_vec3(),
                    c + size * inputs.unit_vec3(),
                    c + size * inputs.unit_vec3(),
                ]
            })
            .collect();
        sets.push((format!("soup {k} at {offset}"), soup));
    }
    for (name, mesh) in [
        ("torus", cg_core::shapes::torus(2.0, 0.7, 40, 16).unwrap()),
        ("icosphere", cg_core::shapes::icosphere(3.0, 3).unwrap()),
        ("grid", cg_core::shapes::grid(20, 8.0).unwrap()),
        // Over 4096 triangles: the top of the tree is built on several threads.
        ("fine torus", cg_core::shapes::torus(3.0, 1.0, 100, 50).unwrap()),
    ] {
        let offset = inputs.vec3_log_uniform(-1.0, 3.5);
        let tris = (0..mesh.face_count()).map(|f| mesh.triangle(f).map(|p| p + offset)).collect();
        sets.push((format!("{name} at {offset}"), tris));
    }
    sets
}

#[test]
fn the_bvh_finds_the_brute_force_closest_hit() {
    let mut inputs = Inputs::seeded(404);
    let rays_per_set = if cfg!(debug_assertions) { 400 } else { 4000 };
    for (name, tris) in triangle_sets(&mut inputs) {
        let bvh = Bvh::build(&tris);
        assert_eq!(bvh.len(), tris.len(), "{name}");
        let centre =
            tris.iter().flatten().fold(Vec3::ZERO, |a, &p| a + p) / (3 * tris.len()) as f32;
        let (mut hits, mut visited) = (0, 0u64);
        for i in 0..rays_per_set {
            let origin = centre + inputs.vec3_in_cube(12.0);
            let target = centre + inputs.vec3_in_cube(4.0);
            let mut ray = Ray::new(origin, (target - origin).normalize());
            if i % 3 == 0 {
                ray.t_max = inputs.uniform_f32(0.5, 15.0);
            }
            // Brute force: every triangle, the smallest t.
            let setup = RaySetup::new(&ray);
            let brute = tris
                .iter()
                .enumerate()
                .filter_map(|(k, t)| intersect_triangle(&setup, t[0], t[1], t[2]).map(|h| (k, h)))
                .min_by(|a, b| a.1.t.total_cmp(&b.1.t));
            let found = bvh.closest_hit(&ray, &mut visited, |_, _| true);
            match (brute, found) {
                (None, None) => {}
                (Some((k, b)), Some((j, f))) => {
                    hits += 1;
                    assert_eq!(
                        f.t, b.t,
                        "{name}, ray {i}: BVH t {} (triangle {j}) vs brute force {} (triangle {k})",
                        f.t, b.t
                    );
                    assert!(j as usize == k || f.t == b.t, "{name}, ray {i}");
                }
                (b, f) => panic!("{name}, ray {i} {ray:?}: brute force {b:?}, BVH {f:?}"),
            }
            assert_eq!(
                bvh.any_hit(&ray, &mut visited),
                brute.is_some(),
                "{name}, ray {i}: any hit"
            );
        }
        assert!(
            hits > rays_per_set / 10,
            "{name}: only {hits} of {rays_per_set} rays hit anything"
        );
        // The hierarchy prunes: far fewer nodes than a scan of all triangles would touch.
        assert!(
            visited < (rays_per_set * tris.len()) as u64 / 2,
            "{name}: {visited} nodes for {rays_per_set} rays over {} triangles",
            tris.len()
        );
    }
}

#[test]
fn the_bvh_survives_degenerate_input() {
    // Coincident triangles (one centroid), an empty list, non-finite corners, a single triangle.
    let same = vec![[Vec3::ZERO, Vec3::X, Vec3::Y]; 100];
    let bvh = Bvh::build(&same);
    assert_eq!(bvh.len(), 100);
    let ray = Ray::new(Vec3::new(0.2, 0.2, 1.0), Vec3::NEG_Z);
    let hit = bvh.closest_hit(&ray, &mut 0, |_, _| true).expect("hits the stack of triangles");
    assert_eq!(hit.1.t, 1.0);
    assert!(Bvh::build(&[]).closest_hit(&ray, &mut 0, |_, _| true).is_none());
    let bad = vec![[Vec3::NAN, Vec3::X, Vec3::Y], [Vec3::ZERO, Vec3::X, Vec3::Y]];
    let bvh = Bvh::build(&bad);
    assert_eq!(bvh.len(), 1, "the non-finite triangle is left out");
    assert_eq!(bvh.closest_hit(&ray, &mut 0, |_, _| true).unwrap().0, 1);
    // Exponentially spaced triangles: the SAH peels one off per level; the median split below
    // SAH_DEPTH keeps the tree within its traversal stack.
    let chain: Vec<[Vec3; 3]> = (0..3000)
        .map(|i| {
            let x = 1.01f32.powi(i);
            [Vec3::new(x, 0.0, 0.0), Vec3::new(x, 1.0, 0.0), Vec3::new(x, 0.0, 1.0)]
        })
        .collect();
    let bvh = Bvh::build(&chain);
    assert!(bvh.depth() <= cg_trace::bvh::SAH_DEPTH + 32, "depth {}", bvh.depth());
    let along = Ray::new(Vec3::new(-1.0, 0.25, 0.25), Vec3::X);
    assert_eq!(bvh.closest_hit(&along, &mut 0, |_, _| true).unwrap().0, 0);
}

#[test]
fn no_ray_slips_through_the_edges_and_vertices_of_a_closed_mesh() {
    // From inside a closed mesh every ray must hit it — also rays aimed exactly at its vertices
    // and at points on its edges, where a non-watertight test lets some through.
    let mut inputs = Inputs::seeded(505);
    for (name, mesh) in [
        ("icosphere", cg_core::shapes::icosphere(1.0, 2).unwrap()),
        ("uv sphere", cg_core::shapes::uv_sphere(1.0, 16, 9).unwrap()),
        ("cube", cg_core::shapes::cuboid(Vec3::new(2.0, 1.0, 0.5)).unwrap()),
    ] {
        let offset = Vec3::new(1000.5, -300.25, 17.0);
        let tris: Vec<[Vec3; 3]> =
            (0..mesh.face_count()).map(|f| mesh.triangle(f).map(|p| p + offset)).collect();
        let bvh = Bvh::build(&tris);
        let mut aims: Vec<Vec3> = mesh.positions.iter().map(|&p| p + offset).collect();
        for t in &tris {
            for e in 0..3 {
                let s = inputs.uniform_f32(0.0, 1.0);
                aims.push(t[e] + s * (t[(e + 1) % 3] - t[e]));
            }
        }
        for origin in [offset, offset + Vec3::new(0.1, -0.05, 0.02)] {
            for (k, &aim) in aims.iter().enumerate() {
                let ray = Ray::new(origin, (aim - origin).normalize());
                assert!(
                    bvh.closest_hit(&ray, &mut 0, |_, _| true).is_some(),
                    "{name}: the ray from {origin} at {aim} (aim {k}) escaped"
                );
            }
        }
    }
}

#[test]
fn the_exact_sphere_and_its_mesh_cover_the_same_pixels_up_to_the_tessellation_error() {
    // Oracle, per pixel: the distance h of the primary ray's line from the sphere's centre
    // (f64). The exact sphere covers the pixel iff h ≤ r; the 64 × 32 mesh is inscribed, its
    // faces at least r·cos²(π/64) from the centre, so it covers every pixel with
    // h < r·cos²(π/64) and none with h > r. Only the band in between may differ.
    let r = 1.0f32;
    let centre = Vec3::new(0.2, 0.1, -0.3);
    let ball = sphere("ball", r, Material::default(), vec![Factor::translate(centre)]);
    let (w, h) = (160u32, 120u32);
    let s = scene(vec![ball], Vec3::new(0.0, 1.0, 4.5), centre, w, h);
    let exact = Tracer::new(&s, &Options::default()).unwrap();
    let mesh = Tracer::new(&s, &Options { analytic: false, ..Options::default() }).unwrap();
    assert_eq!(exact.triangle_count(), 0);
    assert_eq!(mesh.triangle_count(), 64 * 31 * 2);
    let inner = f64::from(r) * (std::f64::consts::PI / 64.0).cos().powi(2);
    let mut art = String::new();
    let (mut wrong, mut band) = (Vec::new(), 0);
    for y in 0..h {
        for x in 0..w {
            let ray = exact.generate_ray(x, y);
            let dist = common::distance_from_line(centre, ray.origin, ray.direction);
            let a = exact.intersect(&ray, &mut Stats::default()).is_some();
            let m = mesh.intersect(&ray, &mut Stats::default()).is_some();
            let in_band = dist >= inner * (1.0 - 1e-6) && dist <= f64::from(r) * (1.0 + 1e-6);
            band += usize::from(in_band);
            let expected_exact = dist <= f64::from(r);
            let ok = in_band || (a == expected_exact && m == expected_exact);
            if !ok {
                wrong.push((x, y, dist, a, m));
            }
            art.push(match (ok, a, m) {
                (false, ..) => 'X',
                (true, true, true) => '#',
                (true, false, false) => '.',
                _ => '~',
            });
        }
        art.push('\n');
    }
    assert!(
        wrong.is_empty(),
        "pixels covered wrongly (X; # both, . neither, ~ band where they may differ):\n{art}\n{wrong:?}"
    );
    assert!(band < (w * h / 20) as usize, "the band is thin: {band} pixels");
    assert!(art.contains('#') && art.contains('.'));
}
