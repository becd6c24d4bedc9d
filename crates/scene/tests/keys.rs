//! Every key of the scene format reads into the field it names (docs/scene-format.md), and every
//! key left out takes its documented default. The shapes' own keys are tested beside `ShapeSpec`.

use std::path::{Path, PathBuf};

use cg_core::Rgb;
use cg_core::camera::CameraLimits;
use cg_core::glam::Vec3;
use cg_core::light::{Attenuation, Light, LightKind, LightModel, Material, Specular};
use cg_core::normals::Weighting;
use cg_core::product::{Axis, Factor, Param};
use cg_core::scene::{Camera, NormalSource, Projection, Shading, TextureUse};
use cg_core::shapes;
use cg_core::texture::{Filter, Sampler, TexEnv, Wrap};

/// A file beside the shipped scenes, so `../models/…` and `../textures/…` resolve.
fn scene_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/every-key.toml")
}

const EVERY_KEY: &str = r#"
format = 1
name = "every key"

[window]
width = 320
height = 200
clear_color = [0.1, 0.2, 0.3]

[camera]
kind = "orbit"
distance = 7.5
pitch_deg = -45
yaw_deg = 370.0
target = [1, 2, 3]
limits = { pitch_min_deg = -80, pitch_max_deg = 10, distance_min = 1.5, distance_max = 50, rotate_deg_per_px = 0.5, zoom_per_px = 0.1, yaw_enabled = false }

[projection]
fovy_deg = 60
near = 0.5
far = 100

[render]
shading = "flat"
light_model = "lecture"
specular = "blinn"
local_viewer = true
global_ambient = [0.3, 0.3, 0.3]
cull_back_faces = false

[[lights]]
kind = "directional"
to_light = [0, 2, 0]
ambient = [0.01, 0.02, 0.03]
diffuse = [0.4, 0.5, 0.6]
specular = [0.7, 0.8, 0.9]

[[lights]]
kind = "point"
position = [1, 2, 3]
attenuation = [1, 0.1, 0.01]

[[lights]]
kind = "spot"
position = [0, 5, 0]
direction = [0, -1, 0]
cutoff_deg = 30
exponent = 4
inner_deg = 20
attenuation = [0.5, 0, 0]

[[lights]]
kind = "area"
corner = [-1, 4, -1]
edge_u = [2, 0, 0]
edge_v = [0, 0, 2]
samples = [3, 4]

[materials.plain]
color = [0.5, 0.8, 0.5]

[materials.full]
ka = [0.1, 0.1, 0.1]
kd = [0.2, 0.2, 0.2]
ks = [0.3, 0.3, 0.3]
shininess = 32
kr = [0.4, 0.4, 0.4]
kt = [0.5, 0.5, 0.5]
eta = 1.33
emission = [0.6, 0.6, 0.6]

[materials.shiny_colour]
color = [1, 0, 0]
ks = [1, 1, 1]
shininess = 8

[[objects]]
name = "ground"
shape = { kind = "grid", divisions = 4, size = 2 }
normals = { weighting = "max", crease_deg = 45 }
material = "plain"
texture = { image = "../textures/orientation.png", filter = "nearest", wrap = ["repeat", "clamp"], env = "replace" }
transform = [
  { translate = [1, 2, 3] },
  { rotate_deg = 90, axis = [0, 0, 2] },
  { rotate_x_deg = 10 },
  { rotate_y_deg = 20 },
  { rotate_z_deg = -30 },
  { scale = [2, 2, -1] },
]

[[objects]]
name = "pyramid"
mesh = "../models/pyramid.obj"
normals = "smooth"
material = { kd = [0, 0, 1] }

[[objects]]
name = "again"
shape = { kind = "lecture_pyramid" }
normals = { weighting = "uniform" }
material = "full"

[[objects]]
name = "red"
shape = { kind = "lecture_pyramid" }
material = "shiny_colour"
"#;

#[test]
fn every_key_reads_into_its_field() {
    let s = cg_scene::parse(EVERY_KEY, &scene_path()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.name, "every key");
    assert_eq!((s.width, s.height, s.clear_color), (320, 200, Rgb::new(0.1, 0.2, 0.3)));

    let Camera::Orbit(c) = s.camera else { panic!("orbit") };
    assert_eq!((c.distance, c.pitch_deg, c.target), (7.5, -45.0, Vec3::new(1.0, 2.0, 3.0)));
    assert_eq!(c.yaw_deg, 10.0, "yaw is kept in [0, 360)");
    let limits = CameraLimits {
        pitch_min_deg: -80.0,
        pitch_max_deg: 10.0,
        distance_min: 1.5,
        distance_max: 50.0,
        rotate_deg_per_px: 0.5,
        zoom_per_px: 0.1,
        yaw_enabled: false,
    };
    assert_eq!(c.limits, limits);

    assert_eq!(s.projection, Projection { fovy_deg: 60.0, near: 0.5, far: 100.0 });
    assert_eq!(s.shading, Shading::Flat);
    assert_eq!(
        s.light_model,
        LightModel::Lecture { specular: Specular::Blinn, local_viewer: true }
    );
    assert_eq!(s.global_ambient, Rgb::splat(0.3));
    assert!(!s.cull_back_faces);

    let gl_light0 = |kind| Light {
        kind,
        ambient: Rgb::ZERO,
        diffuse: Rgb::ONE,
        specular: Rgb::ONE,
        attenuation: Attenuation::default(),
    };
    let attenuation = |constant, linear, quadratic| Attenuation { constant, linear, quadratic };
    let lights = [
        Light {
            ambient: Rgb::new(0.01, 0.02, 0.03),
            diffuse: Rgb::new(0.4, 0.5, 0.6),
            specular: Rgb::new(0.7, 0.8, 0.9),
            ..gl_light0(LightKind::Directional { to_light: Vec3::new(0.0, 2.0, 0.0) })
        },
        Light {
            attenuation: attenuation(1.0, 0.1, 0.01),
            ..gl_light0(LightKind::Point { position: Vec3::new(1.0, 2.0, 3.0) })
        },
        Light {
            attenuation: attenuation(0.5, 0.0, 0.0),
            ..gl_light0(LightKind::Spot {
                position: Vec3::new(0.0, 5.0, 0.0),
                direction: Vec3::NEG_Y,
                cutoff_deg: 30.0,
                exponent: 4.0,
                inner_deg: Some(20.0),
            })
        },
        gl_light0(LightKind::Area {
            corner: Vec3::new(-1.0, 4.0, -1.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 2.0),
            samples: [3, 4],
        }),
    ];
    assert_eq!(s.lights, lights);

    let [ground, pyramid, again, red] = &s.objects[..] else { panic!("4 objects") };
    assert_eq!(ground.name, "ground");
    assert_eq!(ground.mesh, shapes::grid(4, 2.0).unwrap());
    assert_eq!(
        ground.normals,
        NormalSource::Vertex { weighting: Weighting::Max, crease_deg: Some(45.0) }
    );
    assert_eq!(ground.material, Material::from_color(Rgb::new(0.5, 0.8, 0.5)));
    let sampler = Sampler { filter: Filter::Nearest, wrap_u: Wrap::Repeat, wrap_v: Wrap::Clamp };
    assert_eq!(ground.texture, Some(TextureUse { texture: 0, sampler, env: TexEnv::Replace }));
    let p = |value| Param { value, symbol: None };
    let factors = [
        Factor::Translate([p(1.0), p(2.0), p(3.0)]),
        // glRotatef(90, 0, 0, 2) is a rotation about +Z, so the report prints Rz(90°).
        Factor::Rotate { axis: Axis::Z, angle_deg: p(90.0) },
        Factor::Rotate { axis: Axis::X, angle_deg: p(10.0) },
        Factor::Rotate { axis: Axis::Y, angle_deg: p(20.0) },
        Factor::Rotate { axis: Axis::Z, angle_deg: p(-30.0) },
        Factor::Scale([p(2.0), p(2.0), p(-1.0)]),
    ];
    assert_eq!(ground.transform.factors, factors, "in the order written: first = leftmost");

    assert_eq!(pyramid.mesh, shapes::lecture_pyramid(), "from the OBJ file");
    assert_eq!(
        // "smooth" and the table without crease_deg keep edges over 30° hard (docs/numerics.md row 5).
        pyramid.normals,
        NormalSource::Vertex { weighting: Weighting::Angle, crease_deg: Some(30.0) }
    );
    assert_eq!(pyramid.material, Material { kd: Vec3::new(0.0, 0.0, 1.0), ..Material::default() });
    assert!(pyramid.transform.factors.is_empty());

    assert_eq!(
        again.normals,
        NormalSource::Vertex { weighting: Weighting::Uniform, crease_deg: Some(30.0) }
    );
    let full = Material {
        ka: Rgb::splat(0.1),
        kd: Rgb::splat(0.2),
        ks: Rgb::splat(0.3),
        shininess: 32.0,
        kr: Rgb::splat(0.4),
        kt: Rgb::splat(0.5),
        eta: 1.33,
        emission: Rgb::splat(0.6),
    };
    assert_eq!(again.material, full);

    // `color` with the other keys: k_a = k_d = color, the rest as given.
    let shiny =
        Material { ks: Rgb::ONE, shininess: 8.0, ..Material::from_color(Rgb::new(1.0, 0.0, 0.0)) };
    assert_eq!(red.material, shiny);
    assert_eq!(red.normals, NormalSource::Face, "the default");
    assert_eq!(red.texture, None);
}

#[test]
fn texture_defaults_and_one_image_shared_by_two_objects() {
    let text = r#"
format = 1
[[objects]]
name = "a"
shape = { kind = "grid", divisions = 1, size = 1 }
texture = { image = "../textures/orientation.png" }
[[objects]]
name = "b"
shape = { kind = "grid", divisions = 2, size = 1 }
texture = { image = "../textures/orientation.png", wrap = "clamp" }
"#;
    let s = cg_scene::parse(text, &scene_path()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.textures.len(), 1, "the same file is loaded once");
    let defaults = Sampler { filter: Filter::Bilinear, wrap_u: Wrap::Repeat, wrap_v: Wrap::Repeat };
    assert_eq!(
        s.objects[0].texture,
        Some(TextureUse { texture: 0, sampler: defaults, env: TexEnv::Modulate })
    );
    let clamp = Sampler { filter: Filter::Bilinear, wrap_u: Wrap::Clamp, wrap_v: Wrap::Clamp };
    assert_eq!(s.objects[1].texture.as_ref().map(|t| (t.texture, t.sampler)), Some((0, clamp)));
}

#[test]
fn look_at_camera_reads_eye_target_and_up() {
    let text = r#"
format = 1
[camera]
kind = "look_at"
eye = [0, 5, 10]
target = [0, 1, 0]
up = [0, 2, 0]
"#;
    let s = cg_scene::parse(text, &scene_path()).unwrap_or_else(|e| panic!("{e}"));
    let eye = Vec3::new(0.0, 5.0, 10.0);
    assert_eq!(s.camera, Camera::LookAt { eye, target: Vec3::Y, up: Vec3::new(0.0, 2.0, 0.0) });
    // target and up default to the origin and +Y
    let text = "format = 1\n[camera]\nkind = \"look_at\"\neye = [0, 5, 10]\n";
    let s = cg_scene::parse(text, &scene_path()).unwrap();
    assert_eq!(s.camera, Camera::LookAt { eye, target: Vec3::ZERO, up: Vec3::Y });
}

#[test]
fn left_out_keys_take_the_course_defaults() {
    let s = cg_scene::parse("format = 1\n", Path::new("dir/minimal.toml")).unwrap();
    assert_eq!(s.name, "minimal", "the file's stem");
    assert_eq!((s.width, s.height, s.clear_color), (640, 640, Rgb::new(0.5, 0.5, 0.8)));
    let Camera::Orbit(c) = s.camera else { panic!("orbit") };
    assert_eq!((c.distance, c.pitch_deg, c.yaw_deg, c.target), (15.0, -30.0, 0.0, Vec3::ZERO));
    assert_eq!(c.limits, CameraLimits::default());
    assert_eq!(s.projection, Projection { fovy_deg: 45.0, near: 1.0, far: 500.0 });
    assert_eq!(s.light_model, LightModel::OpenGl { local_viewer: false });
    assert_eq!(s.global_ambient, Rgb::splat(0.2));
    assert_eq!(s.shading, Shading::Gouraud);
    assert!(s.cull_back_faces);
    assert!(s.lights.is_empty() && s.objects.is_empty() && s.textures.is_empty());

    // Sections given but empty: the same defaults. `[camera]` alone is the orbit camera.
    let text = "format = 1\n[window]\n[camera]\n[projection]\n[render]\n";
    let t = cg_scene::parse(text, Path::new("dir/minimal.toml")).unwrap();
    assert_eq!(t, s);

    // The lecture model's specular defaults to Phong; a light's colours to GL_LIGHT0's.
    let text = "format = 1\n[render]\nlight_model = \"lecture\"\n[[lights]]\nkind = \"point\"\nposition = [0, 1, 0]\n";
    let s = cg_scene::parse(text, Path::new("x.toml")).unwrap();
    assert_eq!(
        s.light_model,
        LightModel::Lecture { specular: Specular::Phong, local_viewer: false }
    );
    let light = &s.lights[0];
    assert_eq!((light.ambient, light.diffuse, light.specular), (Rgb::ZERO, Rgb::ONE, Rgb::ONE));
    assert_eq!(light.attenuation, Attenuation::default());

    // An object without `material` gets OpenGL's default material; a spot's exponent is 0 and
    // `inner_deg` absent; infinite `distance_max` is written `inf`.
    let text = r#"
format = 1
camera = { limits = { distance_max = inf } }
[[lights]]
kind = "spot"
position = [0, 5, 0]
direction = [0, -1, 0]
cutoff_deg = 180
[[objects]]
name = "p"
shape = { kind = "lecture_pyramid" }
"#;
    let s = cg_scene::parse(text, Path::new("x.toml")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.objects[0].material, Material::default());
    assert!(matches!(
        s.lights[0].kind,
        LightKind::Spot { exponent: 0.0, inner_deg: None, cutoff_deg: 180.0, .. }
    ));
    assert!(matches!(s.camera, Camera::Orbit(c) if c.limits.distance_max == f32::INFINITY));
}
