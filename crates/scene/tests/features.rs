//! "Only what the scene needs": the features each shipped scene uses, read off the scene files by
//! hand (the comments quote the keys that decide), and what a change to one key switches.

use std::path::{Path, PathBuf};

use cg_core::features::Features;
use cg_core::glam::Vec3;
use cg_core::lang::Lang;

fn scene(name: &str) -> cg_core::scene::Scene {
    let path: PathBuf =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes").join(name);
    cg_scene::load(&path).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn the_course_sample_needs_ambient_and_diffuse_from_one_point_light_only() {
    // color = [...] → k_a = k_d ≠ 0, k_s = 0 (OpenGL's default); one point light, attenuation
    // left at (1, 0, 0); global ambient 0.2; infinite viewer.
    let expected = Features { ambient: true, diffuse: true, point: true, ..Features::default() };
    assert_eq!(scene("course-sample.toml").features(), expected);
}

#[test]
fn each_shipped_scene_turns_on_what_its_keys_say() {
    // spot-specular: kind = "spot", attenuation = [1.0, 0.02, 0.005], ks = [1, 1, 1].
    let f = scene("spot-specular.toml").features();
    assert!(f.spot && f.attenuation && f.specular && !f.point && !f.reflection, "{f:?}");
    // glass-mirror: kr = 0.8 and 0.1, kt = 0.9, ks = 1, local_viewer = true.
    let f = scene("glass-mirror.toml").features();
    assert!(f.reflection && f.transmission && f.specular && f.local_viewer, "{f:?}");
    // textured-ground: texture = { image = ... } on the ground.
    let f = scene("textured-ground.toml").features();
    assert!(f.textures && !f.specular, "{f:?}");
    // sphere-phong: ks = 0.9, specular = "phong", local_viewer = true.
    let f = scene("sphere-phong.toml").features();
    assert!(f.specular && f.local_viewer && !f.textures && !f.reflection, "{f:?}");
}

#[test]
fn one_key_switches_one_feature() {
    let mut s = scene("course-sample.toml");
    s.objects[1].material.ks = Vec3::splat(0.5);
    assert!(s.features().specular, "k_s > 0 on one object turns specular on");
    s.lights[0].specular = Vec3::ZERO;
    assert!(!s.features().specular, "…unless no light has a specular colour");
    s.lights[0].attenuation.quadratic = 0.01;
    assert!(s.features().attenuation);
    s.global_ambient = Vec3::ZERO;
    s.lights[0].ambient = Vec3::ZERO;
    assert!(!s.features().ambient, "no ambient light at all");
    s.objects[0].material.emission = Vec3::splat(0.1);
    assert!(s.features().emission);
}

#[test]
fn the_description_names_what_is_enabled_and_why_the_rest_is_skipped() {
    let f = scene("course-sample.toml").features();
    let en = f.describe(Lang::En);
    let (enabled, skipped) = en.split_once('\n').unwrap();
    assert!(
        enabled.contains("ambient")
            && enabled.contains("diffuse")
            && enabled.contains("point lights"),
        "{en}"
    );
    assert!(skipped.contains("specular (every k_s or every light's specular colour is 0)"), "{en}");
    assert!(skipped.contains("reflection k_r·I_r (every k_r is 0)"), "{en}");
    let ja = f.describe(Lang::Ja);
    assert!(ja.starts_with("使う: 環境光, 拡散反射光") && ja.contains("省略: 鏡面反射光"), "{ja}");
}
