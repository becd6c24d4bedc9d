//! The scenes of the shading set: the sphere the checks draw, and the course's stage for the view.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular};
use cg_core::mesh::Mesh;
use cg_core::normals::Weighting;
use cg_core::product::{Factor, MatrixProduct};
use cg_core::scene::{Camera, NormalSource, Object, Scene};
use cg_core::shapes::uv_sphere;

use crate::spec::Spec;

/// The side of the check images, in pixels.
pub const CHECK_SIZE: u32 = 160;

/// Where the checks' camera is (looking at the sphere's centre, the origin).
pub const CHECK_EYE: Vec3 = Vec3::new(0.0, 1.0, 3.5);

/// The lecture's light model: `I = Ia·ka + Σ Ii·[kd (N·L) + ks (R·V)ⁿ]`, Phong's `R·V`, V towards
/// the eye from every point.
pub const LECTURE: LightModel =
    LightModel::Lecture { specular: Specular::Phong, local_viewer: true };

/// The student's material.
#[must_use]
pub fn material(spec: &Spec) -> Material {
    let c = Rgb::from(spec.material.color.rgb);
    Material {
        ka: c,
        kd: c,
        ks: Rgb::splat(spec.material.ks),
        shininess: spec.material.shininess,
        ..Material::default()
    }
}

/// The student's light: a point light, no attenuation, no ambient of its own (I_a is global).
#[must_use]
pub fn light(spec: &Spec) -> Light {
    let c = Rgb::from(spec.light.color.rgb);
    Light {
        kind: LightKind::Point { position: Vec3::from(spec.light.position) },
        ambient: Rgb::ZERO,
        diffuse: c,
        specular: c,
        attenuation: Attenuation::default(),
    }
}

/// The student's sphere: radius 1 about the origin, `slices × stacks`.
#[must_use]
pub fn sphere_mesh(spec: &Spec) -> Mesh {
    // The tables hold valid counts only (3 ≤ slices, 2 ≤ stacks), so this cannot fail; an empty
    // mesh would only draw nothing.
    uv_sphere(1.0, spec.sphere.slices, spec.sphere.stacks).unwrap_or_default()
}

/// A sphere object with vertex normals averaged by the lecture's plain average (単純平均),
/// moved to `at` and scaled by `scale` (glTranslatef, then glScalef).
fn sphere_object(spec: &Spec, name: &str, at: Vec3, scale: f32) -> Object {
    let mut transform = MatrixProduct::identity();
    if at != Vec3::ZERO {
        transform = transform.then(Factor::translate(at));
    }
    if scale != 1.0 {
        transform = transform.then(Factor::scale(Vec3::splat(scale)));
    }
    Object {
        name: name.to_owned(),
        mesh: sphere_mesh(spec),
        normals: NormalSource::Vertex { weighting: Weighting::Uniform, crease_deg: None },
        material: material(spec),
        transform,
        texture: None,
        weld: None,
        analytic: None,
    }
}

/// The checks' scene: the student's sphere alone, lit by the student's light with the lecture's
/// model, seen from [`CHECK_EYE`] on the course's background, `CHECK_SIZE` pixels square.
#[must_use]
pub fn check_scene(spec: &Spec) -> Scene {
    let mut s = cg_harness::course::stage();
    s.name = "s-sphere".to_owned();
    s.width = CHECK_SIZE;
    s.height = CHECK_SIZE;
    s.camera = Camera::LookAt { eye: CHECK_EYE, target: Vec3::ZERO, up: Vec3::Y };
    s.light_model = LECTURE;
    s.global_ambient = Rgb::splat(spec.light.ambient);
    s.lights = vec![light(spec)];
    s.objects = vec![sphere_object(spec, "sphere", Vec3::ZERO, 1.0)];
    s
}

/// Where the view's three spheres stand on the ground (flat, Gouraud, Phong from left to right):
/// their x; each rests on the ground with radius [`STAGE_RADIUS`].
pub const STAGE_SPHERES: [(f32, &str); 3] = [(-3.5, "flat"), (0.0, "gouraud"), (3.5, "phong")];

/// The radius of the view's spheres (the student's unit sphere scaled uniformly, so its vertex
/// normals keep their directions).
pub const STAGE_RADIUS: f32 = 1.5;

/// The view's scene: the course's stage (its window, camera and ground) with the student's light
/// and three of the student's spheres resting on the ground.
#[must_use]
pub fn stage_scene(spec: &Spec) -> Scene {
    let mut s = cg_harness::course::ground_only();
    s.name = "s-stage".to_owned();
    s.light_model = LECTURE;
    s.global_ambient = Rgb::splat(spec.light.ambient);
    s.lights = vec![light(spec)];
    for (x, name) in STAGE_SPHERES {
        s.objects.push(sphere_object(spec, name, Vec3::new(x, STAGE_RADIUS, 0.0), STAGE_RADIUS));
    }
    s
}
