//! What OpenGL cannot draw is a clear error, never a panic or an approximation; and the test
//! policy of `require` (skip with a note on a student's machine, fail in CI).
//!
//! These tests need no C compiler and no OSMesa (the scene is checked before anything runs), so
//! they run everywhere and do not call `require` first.

mod common;

use std::process::Command;

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::light::{Light, LightKind, LightModel, Specular};
use cg_core::product::MatrixProduct;
use cg_core::scene::{Scene, Shading};
use cg_glref::GlRefError;
use common::*;

fn course_like() -> Scene {
    let mut s = scene(16, 16, orbit(0.0, -30.0, 15.0));
    s.lights = vec![point_light(Vec3::splat(10.0))];
    s.objects = vec![object(
        "pyramid",
        cg_core::shapes::lecture_pyramid(),
        cg_core::light::Material::from_color(Rgb::new(1.0, 0.6, 0.2)),
        MatrixProduct::identity(),
    )];
    s
}

fn point_light(position: Vec3) -> Light {
    Light {
        kind: LightKind::Point { position },
        ambient: Rgb::splat(0.1),
        diffuse: Rgb::splat(0.8),
        specular: Rgb::ONE,
        attenuation: Default::default(),
    }
}

/// The error `render` gives, with both messages checked to name `words` (English) and `ja`.
fn expect_error(s: &Scene, en: &[&str], ja: &[&str]) -> GlRefError {
    let e = cg_glref::render(s).expect_err("the scene must be rejected");
    let (m_en, m_ja) = (e.message(Lang::En), e.message(Lang::Ja));
    for w in en {
        assert!(m_en.contains(w), "the English message should name {w:?}: {m_en}");
    }
    for w in ja {
        assert!(m_ja.contains(w), "the Japanese message should name {w:?}: {m_ja}");
    }
    assert_eq!(m_en, e.to_string());
    e
}

#[test]
fn the_lecture_light_model_is_an_error_that_names_it() {
    let mut s = course_like();
    s.light_model = LightModel::Lecture { specular: Specular::Phong, local_viewer: false };
    let e = expect_error(&s, &["lecture", "light_model = \"opengl\""], &["講義の光のモデル"]);
    assert!(matches!(e, GlRefError::LectureLightModel), "{e:?}");
}

#[test]
fn phong_shading_is_an_error_that_names_it() {
    let mut s = course_like();
    s.shading = Shading::Phong;
    let e = expect_error(&s, &["Phong", "GL_SMOOTH"], &["フォンシェーディング"]);
    assert!(matches!(e, GlRefError::PhongShading), "{e:?}");
}

#[test]
fn more_than_eight_point_lights_are_an_error_and_area_lights_count_as_their_samples() {
    let mut s = course_like();
    s.lights = (0..8).map(|i| point_light(Vec3::new(i as f32, 5.0, 0.0))).collect();
    assert!(cg_glref::script(&s).is_ok(), "eight lights are OpenGL's limit, not above it");
    s.lights.push(point_light(Vec3::Y));
    let e = expect_error(&s, &["9 point lights", "GL_LIGHT7"], &["9 個"]);
    assert!(matches!(e, GlRefError::TooManyLights { count: 9 }), "{e:?}");
    // One area light of 3 × 3 samples is nine point lights.
    s.lights = vec![Light {
        kind: LightKind::Area {
            corner: Vec3::new(-1.0, 5.0, -1.0),
            edge_u: Vec3::new(2.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 0.0, 2.0),
            samples: [3, 3],
        },
        ..point_light(Vec3::ZERO)
    }];
    let e = expect_error(&s, &["9 point lights", "area lights"], &["面光源"]);
    assert!(matches!(e, GlRefError::TooManyLights { count: 9 }), "{e:?}");
}

#[test]
fn values_opengl_rejects_or_cannot_draw_are_errors_that_say_where() {
    let mut s = course_like();
    s.objects[0].material.shininess = 200.0;
    expect_error(&s, &["\"pyramid\"", "shininess", "200", "0 to 128"], &["\"pyramid\"", "200"]);

    let mut s = course_like();
    s.objects[0].mesh.positions[3].x = f32::NAN;
    let e = expect_error(&s, &["\"pyramid\"", "V3"], &["\"pyramid\"", "V3"]);
    assert!(matches!(e, GlRefError::Prepare(_)), "{e:?}");

    let mut s = course_like();
    s.objects[0].material.emission.y = f32::INFINITY;
    let e = expect_error(&s, &["\"pyramid\"", "emission", "not finite"], &["有限"]);
    assert!(matches!(e, GlRefError::NotFinite { .. }), "{e:?}");

    let mut s = course_like();
    s.width = 0;
    expect_error(&s, &["0×16"], &["0×16"]);

    let mut s = course_like();
    s.lights[0].kind = LightKind::Directional { to_light: Vec3::ZERO };
    expect_error(&s, &["light 0", "non-zero direction"], &["光源 0"]);
}

#[test]
fn the_not_available_message_says_what_to_run() {
    let e = GlRefError::NotAvailable { detail: "cc: not found".into() };
    for lang in [Lang::En, Lang::Ja] {
        let m = e.message(lang);
        assert!(m.contains("bash scripts/setup.sh") && m.contains("libosmesa6-dev"), "{m}");
        assert!(m.contains("cc: not found"), "{m}");
    }
}

/// Not a test by itself: run by the next test in a child process with a broken `CC`, it prints
/// what `require` returned.
#[test]
fn require_probe() {
    if std::env::var_os("CG_GLREF_PROBE").is_none() {
        return;
    }
    println!("require = {}", cg_glref::require());
}

#[test]
fn require_skips_with_a_note_on_a_students_machine_and_fails_in_ci() {
    // A child process of this test binary where the reference cannot be built: CC names no
    // compiler, and the cache is a fresh folder.
    let cache = std::env::temp_dir().join(format!("cg-glref-probe-{}", std::process::id()));
    let probe = |ci: bool| {
        let mut child = Command::new(std::env::current_exe().unwrap());
        child
            .args(["--exact", "require_probe", "--nocapture", "--test-threads=1"])
            .env("CG_GLREF_PROBE", "1")
            .env("CC", "/nonexistent/cc")
            .env("CG_GLREF_CACHE", &cache)
            .env("CG_LANG", "en");
        if ci {
            child.env("CI", "true");
        } else {
            child.env_remove("CI");
        }
        let out = child.output().unwrap();
        let text = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        (out.status.success(), text)
    };
    let (ok, text) = probe(false);
    assert!(ok, "without CI, require must not fail the test:\n{text}");
    assert!(text.contains("require = false"), "require must return false:\n{text}");
    assert!(
        text.contains("skipped: OpenGL reference not available: ")
            && text.contains("bash scripts/setup.sh")
            && text.contains("/nonexistent/cc"),
        "the note must say why and what to run:\n{text}"
    );
    let (ok, text) = probe(true);
    assert!(!ok, "with CI set, require must fail the test:\n{text}");
    assert!(
        text.contains("CI is set, so the OpenGL reference is required")
            && text.contains("bash scripts/setup.sh"),
        "the CI failure must say why:\n{text}"
    );
    let _ = std::fs::remove_dir_all(&cache);
}
