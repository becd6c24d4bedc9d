//! The scene's own light model lit eight points at a time (`src/span.rs`: Phong's pixels,
//! Gouraud's vertices) gives the very image, depth buffer and counts of the point-by-point path
//! — every bit — on every kind of light, both light models, both specular terms, local and
//! infinite viewers, textures, per-vertex colours, mirrored objects, clipped faces and normals
//! that cancel.
//!
//! The point-by-point path is the same renderer with a hook that calls [`SceneLighting`] itself:
//! a closure is not the scene's light model to the renderer, so it lights one point per call.

mod common;

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular};
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{NormalSource, Scene, Shading};
use cg_core::shapes::icosphere;
use cg_raster::{Lighting, Options, Output, SceneLighting, SurfacePoint, render, render_with};
use common::{load, looking_down_z, object};

/// The point-by-point path: [`SceneLighting`] called once per point, counted.
struct OneByOne;

impl Lighting for OneByOne {
    fn light(&self, scene: &Scene, point: &SurfacePoint<'_>) -> Rgb {
        SceneLighting.light(scene, point)
    }

    fn light_counted(
        &self,
        scene: &Scene,
        point: &SurfacePoint<'_>,
        counts: &mut cg_core::light::LightCounts,
    ) -> Rgb {
        SceneLighting.light_counted(scene, point, counts)
    }
}

/// Asserts that the spans give `scene` exactly as the point-by-point path does, in every mode.
fn same_bits(name: &str, scene: &Scene) {
    for shading in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let options =
            Options { shading: Some(shading), size: Some((96, 80)), ..Options::default() };
        let spans = render(scene, &options).unwrap();
        let single = render_with(scene, &options, &OneByOne).unwrap();
        let differing = spans
            .image
            .pixels
            .iter()
            .zip(&single.image.pixels)
            .filter(|(a, b)| a.to_array().map(f32::to_bits) != b.to_array().map(f32::to_bits))
            .count();
        assert_eq!(differing, 0, "{name}, {shading:?}: {differing} pixels differ");
        assert_eq!(spans.depth, single.depth, "{name}, {shading:?}: depth");
        assert_eq!(spans.stats, single.stats, "{name}, {shading:?}: the counts");
        assert!(spans.stats.lighting_evaluations > 0, "{name}, {shading:?}: something was lit");
    }
}

#[test]
fn the_course_scenes_are_the_same_bit_for_bit() {
    for name in [
        "course-sample",
        "glass-mirror",
        "pyramid-obj",
        "sphere-phong",
        "spot-specular",
        "textured-ground",
    ] {
        same_bits(name, &load(&format!("{name}.toml")));
    }
}

/// A sphere and a ground under `lights` in `model`, with a shiny material, close enough to the
/// camera that the near plane cuts the ground.
fn stage(model: LightModel, lights: Vec<Light>, material: Material) -> Scene {
    let mut scene = looking_down_z(96, 80, 60.0);
    scene.light_model = model;
    scene.global_ambient = Rgb::splat(0.15);
    scene.lights = lights;
    let mut mesh = icosphere(1.0, 2).unwrap();
    mesh.normals = Some(mesh.positions.iter().map(|p| p.normalize()).collect());
    let mut sphere = object("sphere", mesh, material.clone());
    sphere.normals = NormalSource::Given;
    sphere.transform = MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, 0.0, -4.0)));
    let mut ground = object("ground", cg_core::shapes::grid(8, 20.0).unwrap(), material);
    ground.transform =
        MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, -1.2, -6.0)));
    scene.objects = vec![sphere, ground];
    scene
}

fn light(kind: LightKind, attenuation: Attenuation) -> Light {
    Light {
        kind,
        ambient: Rgb::new(0.1, 0.05, 0.0),
        diffuse: Rgb::new(0.9, 0.8, 0.7),
        specular: Rgb::ONE,
        attenuation,
    }
}

#[test]
fn every_light_and_model_is_the_same_bit_for_bit() {
    let shiny = Material {
        ka: Rgb::new(0.2, 0.3, 0.8),
        kd: Rgb::new(0.2, 0.3, 0.8),
        ks: Rgb::splat(0.7),
        shininess: 40.0,
        emission: Rgb::new(0.02, 0.0, 0.01),
        ..Material::default()
    };
    let falling = Attenuation { constant: 0.5, linear: 0.1, quadratic: 0.02 };
    let lights = [
        (
            "directional",
            light(
                LightKind::Directional { to_light: Vec3::new(1.0, 2.0, 1.5) },
                Attenuation::default(),
            ),
        ),
        (
            "point",
            light(LightKind::Point { position: Vec3::new(2.0, 3.0, 0.0) }, Attenuation::default()),
        ),
        (
            "attenuated point",
            light(LightKind::Point { position: Vec3::new(-2.0, 2.0, -2.0) }, falling),
        ),
        (
            "spot",
            light(
                LightKind::Spot {
                    position: Vec3::new(0.0, 4.0, -4.0),
                    direction: Vec3::NEG_Y,
                    cutoff_deg: 30.0,
                    exponent: 8.0,
                    inner_deg: Some(15.0),
                },
                falling,
            ),
        ),
        (
            "area",
            light(
                LightKind::Area {
                    corner: Vec3::new(-1.0, 3.0, -5.0),
                    edge_u: Vec3::new(2.0, 0.0, 0.0),
                    edge_v: Vec3::new(0.0, 0.0, 2.0),
                    samples: [2, 3],
                },
                Attenuation::default(),
            ),
        ),
    ];
    let models = [
        LightModel::Lecture { specular: Specular::Phong, local_viewer: false },
        LightModel::Lecture { specular: Specular::Blinn, local_viewer: true },
        LightModel::OpenGl { local_viewer: false },
        LightModel::OpenGl { local_viewer: true },
    ];
    for model in models {
        for (name, l) in &lights {
            same_bits(
                &format!("{name} in {model:?}"),
                &stage(model, vec![l.clone()], shiny.clone()),
            );
        }
        let all = lights.iter().map(|(_, l)| l.clone()).collect();
        same_bits(&format!("every light in {model:?}"), &stage(model, all, shiny.clone()));
        let matte = Material { ks: Rgb::ZERO, ..shiny.clone() };
        same_bits(
            &format!("no specular in {model:?}"),
            &stage(model, vec![lights[1].1.clone()], matte),
        );
    }
}

#[test]
fn colours_mirrors_and_cancelling_normals_are_the_same_bit_for_bit() {
    let model = LightModel::OpenGl { local_viewer: true };
    let point =
        light(LightKind::Point { position: Vec3::new(1.0, 2.0, 1.0) }, Attenuation::default());
    let material = Material { ks: Rgb::splat(0.5), shininess: 10.0, ..Material::default() };
    let mut scene = stage(model, vec![point], material);
    // Per-vertex colours (the colour material), a mirrored sphere, and normals that cancel
    // along an edge (opposite normals at neighbouring vertices: the face normal is used).
    let sphere = &mut scene.objects[0];
    let n = sphere.mesh.positions.len();
    sphere.mesh.colors = Some(
        (0..n).map(|i| Rgb::new((i % 7) as f32 / 6.0, 0.5, 1.0 - (i % 3) as f32 / 2.0)).collect(),
    );
    sphere.transform = sphere.transform.clone().then(Factor::scale(Vec3::new(-1.0, 1.0, 1.0)));
    let ground = &mut scene.objects[1];
    let normals: Vec<Vec3> = (0..ground.mesh.positions.len())
        .map(|i| if i % 2 == 0 { Vec3::Y } else { Vec3::NEG_Y })
        .collect();
    ground.mesh.normals = Some(normals);
    ground.normals = NormalSource::Given;
    same_bits("colours, mirror, cancelling normals", &scene);
}

#[test]
fn the_spans_are_what_the_renderer_takes_for_the_scene_lighting() {
    // Without this, the tests above would compare the point-by-point path with itself.
    assert!(SceneLighting.is_scene_lighting());
    assert!(!OneByOne.is_scene_lighting());
    let scene = load("sphere-phong.toml");
    let out: Output =
        render(&scene, &Options { size: Some((32, 32)), ..Options::default() }).unwrap();
    assert!(out.stats.lighting_evaluations > 0);
}
