//! `assets/scenes/course-sample.toml` reads to exactly the numbers of the course's sample program
//! (DESIGN.md, "The course's sample program"). The expected values are written out here from
//! DESIGN.md, not taken from the loader.

use std::path::Path;

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{Attenuation, LightKind, LightModel};
use cg_core::product::{Factor, Param};
use cg_core::scene::{Camera, NormalSource, Projection, Shading};

fn course() -> cg_core::scene::Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/course-sample.toml");
    cg_scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn window_projection_and_camera_are_the_samples() {
    let s = course();
    assert_eq!(s.name, "course-sample");
    // window 640×640, glClearColor(0.5, 0.5, 0.8)
    assert_eq!((s.width, s.height), (640, 640));
    assert_eq!(s.clear_color, Rgb::new(0.5, 0.5, 0.8));
    // gluPerspective(45°, w/h, 1, 500)
    assert_eq!(s.projection, Projection { fovy_deg: 45.0, near: 1.0, far: 500.0 });
    // translate (0, 0, −15), pitch −30°, yaw 0, around the origin; pitch clamped to [−90, 0],
    // 1° per pixel of right-drag, distance += dy·0.2 with a lower limit
    let Camera::Orbit(c) = s.camera else { panic!("the sample's camera is the orbit camera") };
    assert_eq!((c.distance, c.pitch_deg, c.yaw_deg, c.target), (15.0, -30.0, 0.0, Vec3::ZERO));
    assert_eq!((c.limits.pitch_min_deg, c.limits.pitch_max_deg), (-90.0, 0.0));
    assert_eq!((c.limits.rotate_deg_per_px, c.limits.zoom_per_px), (1.0, 0.2));
}

#[test]
fn lighting_is_opengls_with_the_samples_light() {
    let s = course();
    // OpenGL defaults: global ambient 0.2, infinite viewer, smooth shading; back faces culled
    assert_eq!(s.light_model, LightModel::OpenGl { local_viewer: false });
    assert_eq!(s.global_ambient, Rgb::splat(0.2));
    assert_eq!(s.shading, Shading::Gouraud);
    assert!(s.cull_back_faces);
    // one positional light at (10, 10, 10, 1); diffuse 0.8, specular 1.0, ambient 0.1; no attenuation
    assert_eq!(s.lights.len(), 1);
    let light = &s.lights[0];
    assert_eq!(light.kind, LightKind::Point { position: Vec3::new(10.0, 10.0, 10.0) });
    assert_eq!(light.ambient, Rgb::splat(0.1));
    assert_eq!(light.diffuse, Rgb::splat(0.8));
    assert_eq!(light.specular, Rgb::splat(1.0));
    assert_eq!(light.attenuation, Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 });
    assert!(s.textures.is_empty());
}

#[test]
fn ground_is_the_10_by_10_grid_with_the_samples_colour() {
    let s = course();
    let ground = &s.objects[0];
    assert_eq!(ground.name, "ground");
    // y = 0, ±5 square in 10 × 10 squares, normal +Y
    let m = &ground.mesh;
    assert_eq!((m.vertex_count(), m.face_count()), (11 * 11, 2 * 10 * 10));
    assert!(m.positions.iter().all(|p| p.y == 0.0 && p.x.abs() <= 5.0 && p.z.abs() <= 5.0));
    assert!(m.positions.contains(&Vec3::new(-5.0, 0.0, -5.0)));
    assert!(m.positions.contains(&Vec3::new(5.0, 0.0, 5.0)));
    assert!(m.positions.contains(&Vec3::new(-4.0, 0.0, 3.0)), "a grid line every 1.0");
    assert_eq!(ground.normals, NormalSource::Face);
    // colour-material: glColor3f(0.5, 0.8, 0.5) sets k_a and k_d; material specular 0
    assert_eq!(ground.material.ka, Rgb::new(0.5, 0.8, 0.5));
    assert_eq!(ground.material.kd, Rgb::new(0.5, 0.8, 0.5));
    assert_eq!(ground.material.ks, Rgb::ZERO);
    assert!(ground.transform.factors.is_empty());
    assert!(ground.texture.is_none());
}

#[test]
fn pyramid_is_the_lectures_after_one_translate() {
    let s = course();
    assert_eq!(s.objects.len(), 2);
    let pyramid = &s.objects[1];
    assert_eq!(pyramid.name, "pyramid");
    let v = |x, y, z| Vec3::new(x, y, z);
    assert_eq!(
        pyramid.mesh.positions,
        [
            v(0.0, 1.0, 0.0),
            v(1.0, -0.8, 1.0),
            v(1.0, -0.8, -1.0),
            v(-1.0, -0.8, 1.0),
            v(-1.0, -0.8, -1.0)
        ]
    );
    assert_eq!(
        pyramid.mesh.faces,
        [[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]]
    );
    assert_eq!(pyramid.normals, NormalSource::Face);
    // glTranslatef(0.0, 1.0, 0.0): one factor
    let p = |value| Param { value, symbol: None };
    assert_eq!(pyramid.transform.factors, [Factor::Translate([p(0.0), p(1.0), p(0.0)])]);
    assert_eq!(pyramid.material.ks, Rgb::ZERO, "no highlight in the sample");
}
