//! The limits that keep a scene that loads drawable, and drawn alike by the three renderers
//! (issue 17, "Nothing accepted that draws wrong"): each scene below used to load and then fail
//! in a renderer without a line number, or draw differently in each. Now each is an error at
//! load naming the file, the line and column, and the key, in English and Japanese. Line numbers
//! are counted by hand from the fixture texts (line 1 is `format = 1`).

use std::path::Path;

use cg_core::lang::Lang;
use cg_scene::{
    ErrorKind, LimitError, MAX_COORDINATE, MAX_DEPTH_RATIO, MAX_FOVY_DEG, MAX_POINT_LIGHTS,
    MAX_SCENE_FACES, MIN_FOVY_DEG, MIN_NEAR, Matrix, Rule, SceneError, WorldPoint,
};

const FILE: &str = "fixtures/limits.toml";

fn load(text: &str) -> Result<cg_core::scene::Scene, SceneError> {
    cg_scene::parse(text, Path::new(FILE))
}

fn error(text: &str) -> SceneError {
    match load(text) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e,
    }
}

/// The limit `e` reports.
#[track_caller]
fn limit(e: &SceneError) -> &LimitError {
    match &*e.kind {
        ErrorKind::Limit(l) => l,
        _ => panic!("not a limit: {e}"),
    }
}

/// Checks the place and key of `e`: `line` as counted by hand, the column of `needle`'s first
/// occurrence on that line, the key path; and that both languages name them, the Japanese in
/// Japanese.
#[track_caller]
fn assert_at(e: &SceneError, text: &str, line: usize, needle: &str, key: &str) {
    let line_text = text.lines().nth(line - 1).unwrap_or_else(|| panic!("no line {line}"));
    let byte = line_text.find(needle).unwrap_or_else(|| panic!("{needle:?} not on line {line}"));
    let column = 1 + line_text[..byte].chars().count();
    let p = e.position.unwrap_or_else(|| panic!("no position in {e}"));
    assert_eq!((p.line, p.column), (line, column), "{e}");
    assert_eq!(e.key.as_deref(), Some(key), "{e}");
    let prefix = format!("{FILE}:{line}:{column}: {key}: ");
    assert!(e.to_string().starts_with(&prefix), "{e}\nshould start with {prefix}");
    let ja = e.describe(Lang::Ja);
    assert!(ja.starts_with(&prefix), "{ja}");
    assert!(ja.chars().any(|c| ('\u{3040}'..='\u{30ff}').contains(&c)), "no kana in {ja}");
    assert_ne!(ja, e.to_string());
}

// ---------------------------------------------------------------------------------------------
// 1. Transform products that overflow f32: at the step that makes them overflow

#[test]
fn a_product_that_overflows_is_an_error_at_the_step() {
    // Used to be `object "pyramid": the product overflows f32`, with no line.
    let text = r#"format = 1
[[objects]]
name = "pyramid"
shape = { kind = "lecture_pyramid" }
transform = [
  { scale = [1e30, 1, 1] },
  { scale = [1e30, 1, 1] },
]
"#;
    let e = error(text);
    assert_at(&e, text, 7, "[1e30", "objects[0].transform[1].scale");
    assert_eq!(*limit(&e), LimitError::StepOverflow { matrix: Matrix::Model });
    assert!(e.to_string().contains("overflows f32"), "{e}");
    assert!(e.describe(Lang::Ja).contains("f32 の範囲"), "{}", e.describe(Lang::Ja));

    // The camera's view times a translation of 3e38 along (1, 1, 1) overflows (the course's
    // view turns it by 30° about X: 1.37 × 3e38), though the model matrix does not.
    // (S(2) · T(1.5e38): the translation scaled to 3e38.)
    let text = "format = 1\n[[objects]]\nname = \"p\"\nshape = { kind = \"lecture_pyramid\" }\ntransform = [{ scale = [2, 2, 2] }, { translate = [1.5e38, 1.5e38, 1.5e38] }]\n";
    let e = error(text);
    assert_at(&e, text, 5, "[1.5e38", "objects[0].transform[1].translate");
    assert_eq!(*limit(&e), LimitError::StepOverflow { matrix: Matrix::ModelView });

    // A scale of 1e20 × 1e20 turns normals by its cofactor, 1e40: beyond f32.
    let text = "format = 1\n[[objects]]\nname = \"p\"\nshape = { kind = \"sphere\", radius = 1e-20 }\ntransform = [{ scale = [1e20, 1e20, 1] }]\n";
    let e = error(text);
    assert_at(&e, text, 5, "[1e20", "objects[0].transform[0].scale");
    assert_eq!(*limit(&e), LimitError::StepOverflow { matrix: Matrix::Normal });
    assert!(e.to_string().contains("normal matrix"), "{e}");

    // Over at the third step, after a rotation.
    let text = "format = 1\n[[objects]]\nname = \"p\"\nshape = { kind = \"sphere\", radius = 1e-30 }\ntransform = [{ scale = [1e10, 1e10, 1e10] }, { axis = [0, 1, 0], rotate_deg = 30 }, { scale = [1e30, 1, 1] }]\n";
    let e = error(text);
    assert_at(&e, text, 5, "[1e30, 1, 1]", "objects[0].transform[2].scale");
    assert_eq!(*limit(&e), LimitError::StepOverflow { matrix: Matrix::Model });
}

// ---------------------------------------------------------------------------------------------
// 2., 7. Vertices beyond MAX_COORDINATE in world space

#[test]
fn a_translation_beyond_the_world_is_an_error_at_the_step() {
    // Used to be: inspect "the product overflows f32", raster "vertex V0 is at [inf, …] in clip
    // space", and the ray tracer drew a picture without it.
    let text = r#"format = 1
[[objects]]
name = "pyramid"
shape = { kind = "lecture_pyramid" }
transform = [{ translate = [3.4e38, 0, 0] }]
"#;
    let e = error(text);
    assert_at(&e, text, 5, "[3.4e38", "objects[0].transform[0].translate");
    let position = [3.4e38, 1.0, 0.0];
    assert_eq!(*limit(&e), LimitError::Coordinate { point: WorldPoint::Vertex(0), position });
    let en = e.to_string();
    assert!(en.contains("vertex V0 of this object is at [3.4e38, 1, 0] in world space"), "{en}");
    assert!(en.contains("±10000"), "{en}");
    let ja = e.describe(Lang::Ja);
    assert!(ja.contains("頂点 V0 がワールド座標で [3.4e38, 1, 0]"), "{ja}");
}

#[test]
fn a_unit_triangle_far_away_is_an_error_naming_where_it_is() {
    // A unit box at 8e6: neighbouring f32 values are 1 apart there, so it collapses (inspect
    // called it degenerate, the rasterizer drew it unlit, the ray tracer dropped it).
    let text = r#"format = 1
[[objects]]
name = "box"
shape = { kind = "cuboid", size = [1, 1, 1] }
transform = [
  { translate = [8e6, 0, 0] },
  { rotate_y_deg = 30 },
]
"#;
    let e = error(text);
    assert_at(&e, text, 6, "[8e6", "objects[0].transform[0].translate");
    let LimitError::Coordinate { point: WorldPoint::Vertex(0), position } = *limit(&e) else {
        panic!("{e}")
    };
    assert!((position[0] - 8e6).abs() < 1.0, "{position:?}");

    // At 9999 it is within the limit and loads.
    let near = text.replace("8e6", "9999");
    load(&near).unwrap_or_else(|e| panic!("{e}"));

    // The same triangle in an OBJ file, at 8e6 in the file itself: at the `mesh` key.
    let dir = cg_testkit::student_folder("cg-scene-limits", "obj");
    std::fs::write(dir.join("far.obj"), "v 8e6 0 0\nv 8000001 0 0\nv 8e6 1 0\nf 1 2 3\n").unwrap();
    let text = "format = 1\n[[objects]]\nname = \"far\"\nmesh = \"far.obj\"\n";
    let e = cg_scene::parse(text, &dir.join("scene.toml")).unwrap_err();
    assert_eq!(e.position.map(|p| (p.line, p.column)), Some((4, 8)), "{e}");
    assert_eq!(e.key.as_deref(), Some("objects[0].mesh"), "{e}");
    let position = [8e6, 0.0, 0.0];
    assert_eq!(*limit(&e), LimitError::Coordinate { point: WorldPoint::Vertex(0), position });
    assert!(e.describe(Lang::Ja).contains("頂点 V0"), "{}", e.describe(Lang::Ja));
    // Scaled down and moved near the origin, the same model loads.
    let text = "format = 1\n[[objects]]\nname = \"far\"\nmesh = \"far.obj\"\ntransform = [{ translate = [-8e6, 0, 0] }]\n";
    cg_scene::parse(text, &dir.join("scene.toml")).unwrap_or_else(|e| panic!("{e}"));
    cg_testkit::remove_student_folder(&dir);

    // A shape too large by its own parameters: at the shape.
    let text = "format = 1\n[[objects]]\nname = \"ground\"\nshape = { kind = \"grid\", divisions = 1, size = 3e4 }\n";
    let e = error(text);
    assert_at(&e, text, 4, "{", "objects[0].shape");
    assert!(matches!(limit(&e), LimitError::Coordinate { point: WorldPoint::Vertex(_), .. }));
    // ... and so is a shape that a step brings near but a later step takes away again.
    let text = "format = 1\n[[objects]]\nname = \"ground\"\nshape = { kind = \"grid\", divisions = 1, size = 3e4 }\ntransform = [{ translate = [0, 0, 2e4] }, { scale = [0.1, 1, 0.1] }]\n";
    let e = error(text);
    assert_at(&e, text, 5, "[0, 0, 2e4]", "objects[0].transform[0].translate");
    // A rotation that turns a corner at (9000, 9000) onto the Y axis, at 12728: at the step, named
    // by its angle (not by `axis`, written first).
    let text = "format = 1\n[[objects]]\nname = \"box\"\nshape = { kind = \"cuboid\", size = [1, 1, 1] }\ntransform = [{ axis = [0, 0, 1], rotate_deg = 45 }, { translate = [9000, 9000, 0] }]\n";
    let e = error(text);
    assert_at(&e, text, 5, "45", "objects[0].transform[0].rotate_deg");
    assert_eq!(MAX_COORDINATE, 1e4);
}

// ---------------------------------------------------------------------------------------------
// 3. The camera

#[test]
fn a_camera_beyond_the_world_is_an_error_at_its_key() {
    // Used to be: inspect blamed the ground, the rasterizer failed in clip space, the ray tracer
    // drew a picture.
    let text = "format = 1\n[camera]\ntarget = [3.4e38, 0, 0]\n";
    let e = error(text);
    assert_at(&e, text, 3, "[3.4e38", "camera.target");
    let position = [3.4e38, 0.0, 0.0];
    assert_eq!(*limit(&e), LimitError::Coordinate { point: WorldPoint::Target, position });
    assert!(e.describe(Lang::Ja).contains("注視点"), "{}", e.describe(Lang::Ja));

    // The eye of an orbit camera 2e4 away: at `distance`.
    let text = "format = 1\n[camera]\npitch_deg = -30\ndistance = 2e4\n";
    let e = error(text);
    assert_at(&e, text, 4, "2e4", "camera.distance");
    assert!(matches!(limit(&e), LimitError::Coordinate { point: WorldPoint::Eye, .. }), "{e}");
    assert!(e.to_string().contains("the eye would be at [0, 10000, 17320.5"), "{e}");
    // A target near the limit puts the eye (15 away, the default) beyond it: at `target`.
    let text = "format = 1\n[camera]\ntarget = [0, 0, 9990]\n";
    let e = error(text);
    assert_at(&e, text, 3, "[0, 0, 9990]", "camera.target");
    assert!(matches!(limit(&e), LimitError::Coordinate { point: WorldPoint::Eye, .. }), "{e}");
    load("format = 1\n[camera]\ntarget = [0, 0, 9980]\n").unwrap();
    // A look-at camera's eye and target.
    let text = "format = 1\n[camera]\nkind = \"look_at\"\neye = [0, 1, 2e4]\n";
    let e = error(text);
    assert_at(&e, text, 4, "[0, 1, 2e4]", "camera.eye");
    let text = "format = 1\n[camera]\nkind = \"look_at\"\neye = [0, 1, 5]\ntarget = [-1e5, 0, 0]\n";
    let e = error(text);
    assert_at(&e, text, 5, "[-1e5", "camera.target");
}

// ---------------------------------------------------------------------------------------------
// 4.–6. The projection

#[test]
fn a_near_plane_too_near_is_an_error_at_near() {
    // near = 1e-20, far = 1e20: it rasterized, but the ray tracer failed with "the inverse of
    // the view-projection matrix overflows f32" and no line.
    let text = "format = 1\n[projection]\nnear = 1e-20\nfar = 1e20\n";
    let e = error(text);
    assert_at(&e, text, 3, "1e-20", "projection.near");
    assert_eq!(*limit(&e), LimitError::Near { near: 1e-20 });
    assert!(e.to_string().contains("near = 1e-20 must be at least 1e-4"), "{e}");
    // near = 1e-10, far = 3.4e38: the rasterizer drew 2 pixels, the others nothing.
    let text = "format = 1\n[projection]\nnear = 1e-10\nfar = 3.4e38\n";
    assert_at(&error(text), text, 3, "1e-10", "projection.near");
    load(&format!("format = 1\n[projection]\nnear = {MIN_NEAR}\nfar = 1\n")).unwrap();
}

#[test]
fn a_depth_range_too_deep_is_an_error_at_far() {
    let text = "format = 1\n[projection]\nnear = 0.01\nfar = 1e5\n";
    let e = error(text);
    assert_at(&e, text, 4, "1e5", "projection.far");
    assert_eq!(*limit(&e), LimitError::DepthRatio { near: 0.01, far: 1e5 });
    let en = e.to_string();
    assert!(en.contains("far / near = 100000 / 0.01 = 1e7 is more than 1e6"), "{en}");
    assert!(e.describe(Lang::Ja).contains("Z ファイティング"), "{}", e.describe(Lang::Ja));
    // near = 1 with far = 3.4e38.
    let text = "format = 1\n[projection]\nfar = 3.4e38\n";
    assert_at(&error(text), text, 3, "3.4e38", "projection.far");
    // far left at 500: the ratio is `near`'s doing.
    let text = "format = 1\n[projection]\nnear = 0.0001\n";
    assert_at(&error(text), text, 3, "0.0001", "projection.near");
    // Exactly the limit, written in decimal (0.0001 is not exact in binary): loads.
    assert_eq!(MAX_DEPTH_RATIO, 1e6);
    load("format = 1\n[projection]\nnear = 0.0001\nfar = 100\n").unwrap();
    load("format = 1\n[projection]\nnear = 0.001\nfar = 1000\n").unwrap();
}

#[test]
fn a_field_of_view_out_of_range_is_an_error_at_fovy() {
    // fovy = 1e-15°: the rasterizer filled the top half, the ray tracer everything, the GPU
    // renderer a block at the bottom left — all without an error.
    let text = "format = 1\n[window]\nwidth = 320\n[projection]\nfovy_deg = 1e-15\n";
    let e = error(text);
    assert_at(&e, text, 5, "1e-15", "projection.fovy_deg");
    assert_eq!(*limit(&e), LimitError::FieldOfView { fovy_deg: 1e-15 });
    assert!(e.to_string().contains("fovy_deg = 1e-15 must be in [1, 179]"), "{e}");
    assert!(e.describe(Lang::Ja).contains("視野角"), "{}", e.describe(Lang::Ja));
    let text = "format = 1\n[projection]\nfovy_deg = 179.5\n";
    assert_at(&error(text), text, 3, "179.5", "projection.fovy_deg");
    for fovy in [MIN_FOVY_DEG, MAX_FOVY_DEG] {
        load(&format!("format = 1\n[projection]\nfovy_deg = {fovy}\n")).unwrap();
    }
    let text = "format = 1\n[projection]\nfovy_deg = 0.99\n";
    assert_at(&error(text), text, 3, "0.99", "projection.fovy_deg");
    // One rule, whatever the value: those gluPerspective cannot take (0, 180, beyond) are told
    // the same range as those no renderer draws alike, not a wider one first.
    for fovy in ["0", "-3", "180", "200", "179.01"] {
        let text = format!("format = 1\n[projection]\nfovy_deg = {fovy}\n");
        let e = error(&text);
        assert_at(&e, &text, 3, fovy, "projection.fovy_deg");
        assert!(matches!(limit(&e), LimitError::FieldOfView { .. }), "{e}");
        assert!(e.to_string().contains(&format!("fovy_deg = {fovy} must be in [1, 179]")), "{e}");
        assert!(e.describe(Lang::Ja).contains("1 以上 179 以下"), "{e}");
    }
    // A value that is no number at all is told so.
    let text = "format = 1\n[projection]\nfovy_deg = nan\n";
    assert!(matches!(*error(text).kind, ErrorKind::BadValue { rule: Rule::Finite, .. }));
}

// ---------------------------------------------------------------------------------------------
// 8. Faces and area-light samples in all

#[test]
fn too_many_faces_in_all_are_refused_before_any_is_built() {
    // Four shapes of 4 000 000 faces each used to take 4.6 GB and 20 s: refused at the second,
    // from the shapes' parameters, before a single mesh is built.
    let mut text = String::from("format = 1\n");
    for i in 0..4 {
        text.push_str(&format!(
            "[[objects]]\nname = \"g{i}\"\nshape = {{ kind = \"grid\", divisions = 1414, size = 10 }}\n"
        ));
    }
    let e = error(&text);
    assert_at(&e, &text, 7, "1414", "objects[1].shape.divisions");
    assert_eq!(*limit(&e), LimitError::SceneFaces { faces: 2 * 3_998_792 });
    assert!(e.to_string().contains("7997584 faces (triangles) in all"), "{e}");
    assert!(e.to_string().contains("5000000 a scene may have"), "{e}");
    assert!(e.describe(Lang::Ja).contains("合わせて 7997584 個"), "{}", e.describe(Lang::Ja));
    assert_eq!(MAX_SCENE_FACES, 5_000_000);

    // An OBJ model of 1001 faces that goes over, after shapes of 4 999 042 faces
    // (3 998 792 + 1 000 250, counted, none built): at its `mesh` key.
    let dir = cg_testkit::student_folder("cg-scene-limits", "faces");
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    obj.push_str(&"f 1 2 3\n".repeat(1001));
    std::fs::write(dir.join("many.obj"), obj).unwrap();
    let text = "format = 1\n[[objects]]\nname = \"m\"\nmesh = \"many.obj\"\n[[objects]]\nname = \"g\"\nshape = { kind = \"grid\", divisions = 1414, size = 10 }\n[[objects]]\nname = \"t\"\nshape = { kind = \"torus\", major = 2, minor = 1, major_segments = 4001, minor_segments = 125 }\n";
    let e = cg_scene::parse(text, &dir.join("scene.toml")).unwrap_err();
    assert_eq!(e.position.map(|p| p.line), Some(4), "{e}");
    assert_eq!(e.key.as_deref(), Some("objects[0].mesh"), "{e}");
    assert_eq!(*limit(&e), LimitError::SceneFaces { faces: 3_998_792 + 1_000_250 + 1001 });
    cg_testkit::remove_student_folder(&dir);
}

#[test]
fn an_obj_model_over_the_face_limit_is_refused_before_it_is_loaded() {
    // A model's faces are counted from its `f` lines (n − 2 for n corners) while its lines are
    // checked, and the limit is applied before tobj loads it: a 64 MiB model of too many faces
    // took about 1 GB before it was refused. Nothing found only while loading (here a bow tie,
    // a quad that crosses itself, on the last line) comes first: the model was never loaded.
    let dir = cg_testkit::student_folder("cg-scene-limits", "faces-before-loading");
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n");
    obj.push_str(&"f 1 2 3\n".repeat(1000));
    obj.push_str("f 1 2 3 4\n");
    std::fs::write(dir.join("many.obj"), &obj).unwrap();
    // Alone it is the bow tie's error, at its line, once loaded.
    let e = cg_scene::parse_obj(&obj, Path::new("many.obj")).unwrap_err();
    assert!(matches!(*e.kind, ErrorKind::ObjPolygon { corners: 4, .. }), "{e}");
    assert_eq!(e.position.map(|p| p.line), Some(1005), "{e}");
    // After shapes of 4 999 042 faces (counted, none built): the limit, at its `mesh` key.
    let text = "format = 1\n[[objects]]\nname = \"m\"\nmesh = \"many.obj\"\n[[objects]]\nname = \"g\"\nshape = { kind = \"grid\", divisions = 1414, size = 10 }\n[[objects]]\nname = \"t\"\nshape = { kind = \"torus\", major = 2, minor = 1, major_segments = 4001, minor_segments = 125 }\n";
    let e = cg_scene::parse(text, &dir.join("scene.toml")).unwrap_err();
    assert_eq!(e.position.map(|p| p.line), Some(4), "{e}");
    assert_eq!(e.key.as_deref(), Some("objects[0].mesh"), "{e}");
    assert_eq!(*limit(&e), LimitError::SceneFaces { faces: 4_999_042 + 1000 + 2 });
    assert!(e.to_string().contains("5000044 faces (triangles) in all"), "{e}");
    assert!(e.describe(Lang::Ja).contains("合わせて 5000044 個"), "{}", e.describe(Lang::Ja));
    cg_testkit::remove_student_folder(&dir);
}

#[test]
fn too_many_point_lights_in_all_are_refused() {
    let light = |samples: &str| {
        format!(
            "[[lights]]\nkind = \"area\"\ncorner = [-1, 6, -1]\nedge_u = [2, 0, 0]\nedge_v = [0, 0, 2]\nsamples = {samples}\n"
        )
    };
    // Four lights of 16 × 16: 1024 samples, the most a scene may have.
    let four = format!("format = 1\n{}", light("[16, 16]").repeat(4));
    load(&four).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(MAX_POINT_LIGHTS, 1024);
    // One more sample, in a fifth light: at its `samples` (line 1 + 4·6 + 6).
    let text = format!("{four}{}", light("[1, 1]"));
    let e = error(&text);
    assert_at(&e, &text, 31, "[1, 1]", "lights[4].samples");
    assert_eq!(*limit(&e), LimitError::PointLights { lights: 1025 });
    // Four lights of 256 × 256 took 8 s at 32 × 32 pixels with no warning: the first is over.
    let text = format!("format = 1\n{}", light("[256, 256]").repeat(4));
    let e = error(&text);
    assert_at(&e, &text, 7, "[256, 256]", "lights[0].samples");
    assert!(e.to_string().contains("65536 point lights in all"), "{e}");
    assert!(e.describe(Lang::Ja).contains("65536 個"), "{}", e.describe(Lang::Ja));
    // Point lights count one each, with the area lights' samples: four of 16 × 16 and one point
    // light are over, at the point light (line 1 + 4·6 + 1, its table). 10 000 point lights
    // took the ray tracer past a minute.
    let point = "[[lights]]\nkind = \"point\"\nposition = [10, 10, 10]\n";
    let text = format!("{four}{point}");
    let e = error(&text);
    assert_eq!(e.key.as_deref(), Some("lights[4]"), "{e}");
    assert_eq!(e.position.map(|p| p.line), Some(26), "{e}");
    assert_eq!(*limit(&e), LimitError::PointLights { lights: 1025 });
    let text = format!("format = 1\n{}", point.repeat(1024));
    load(&text).unwrap_or_else(|e| panic!("{e}"));
    let text = format!("format = 1\n{}", point.repeat(1025));
    assert_eq!(*limit(&error(&text)), LimitError::PointLights { lights: 1025 });
}

// ---------------------------------------------------------------------------------------------
// The issue's reproductions on the course's sample scene, and the scenes that must still load

/// Each of the issue's edits of `assets/scenes/course-sample.toml` is now an error at the edited
/// line, of the key edited.
#[test]
fn the_reported_edits_of_the_course_scene_are_errors_at_their_line() {
    let course = include_str!("../../../assets/scenes/course-sample.toml");
    let cases = [
        (
            "transform = ",
            "transform = [{ scale = [1e30, 1, 1] }, { scale = [1e30, 1, 1] }]",
            57,
            "objects[1].transform[1].scale",
        ),
        (
            "transform = ",
            "transform = [{ translate = [3.4e38, 0, 0] }]",
            57,
            "objects[1].transform[0].translate",
        ),
        ("target = ", "target = [3.4e38, 0, 0]", 17, "camera.target"),
        ("near = ", "near = 1e-20", 21, "projection.near"),
        ("fovy_deg = ", "fovy_deg = 1e-15", 20, "projection.fovy_deg"),
        ("far = ", "far = 3.4e38", 22, "projection.far"),
    ];
    for (start, new, line, key) in cases {
        let text: String = course
            .lines()
            .map(|l| if l.starts_with(start) { new } else { l })
            .collect::<Vec<_>>()
            .join("\n");
        let e = error(&text);
        assert_eq!(e.position.map(|p| p.line), Some(line), "{new}: {e}");
        assert_eq!(e.key.as_deref(), Some(key), "{new}: {e}");
        limit(&e);
    }
    // The sample itself is well within every limit.
    load(course).unwrap();
}
