//! Every class of mistake names the file, the line and column, and the key path — in English and
//! in Japanese. Line numbers are counted by hand from the fixture texts below (line 1 is the line
//! with `format = 1`); columns are found by searching the fixture's own line for the offending text.

use std::path::{Path, PathBuf};

use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::mesh::MeshError;
use cg_core::transform::{LOOK_AT_MIN_UP_ANGLE_DEG, TransformError};
use cg_scene::{ErrorKind, Expected, Found, MAX_SHAPE_FACES, Rule, SceneError};

const FILE: &str = "fixtures/mistake.toml";

fn error(text: &str) -> SceneError {
    match cg_scene::parse(text, Path::new(FILE)) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e,
    }
}

/// Checks the place and key of `e`: `line` as counted by hand, the column of `needle`'s first
/// occurrence on that line (in characters, from 1), and the key path.
#[track_caller]
fn assert_at(e: &SceneError, text: &str, line: usize, needle: &str, key: Option<&str>) {
    let line_text = text.lines().nth(line - 1).unwrap_or_else(|| panic!("no line {line}"));
    let byte = line_text.find(needle).unwrap_or_else(|| panic!("{needle:?} not on line {line}"));
    let column = 1 + line_text[..byte].chars().count();
    let p = e.position.unwrap_or_else(|| panic!("no position in {e}"));
    assert_eq!((p.line, p.column), (line, column), "{e}");
    assert_eq!(e.key.as_deref(), key, "{e}");
    assert_eq!(e.file, Path::new(FILE));
    // Both languages name the same place and key; the Japanese text is Japanese.
    let prefix = match key {
        Some(k) => format!("{FILE}:{line}:{column}: {k}: "),
        None => format!("{FILE}:{line}:{column}: "),
    };
    assert!(e.to_string().starts_with(&prefix), "{e}\nshould start with {prefix}");
    let ja = e.describe(Lang::Ja);
    assert!(ja.starts_with(&prefix), "{ja}");
    assert!(ja.chars().any(|c| ('\u{3040}'..='\u{30ff}').contains(&c)), "no kana in {ja}");
    assert_eq!(e.describe(Lang::En), e.to_string());
}

#[test]
fn syntax_errors_name_the_line() {
    let text = r#"format = 1
[camera]
distance = 15.0
pitch_deg = -30.0 x
"#;
    let e = error(text);
    assert_at(&e, text, 4, "-30.0", None);
    assert!(matches!(*e.kind, ErrorKind::Syntax { .. }), "{e}");

    let text = "format = 1\nname = \"unclosed\n";
    let e = error(text);
    assert_eq!(e.position.map(|p| p.line), Some(2), "{e}");
    assert!(matches!(*e.kind, ErrorKind::Syntax { .. }), "{e}");
    // The parser's English is said in Japanese too (cg_core::toml_syntax).
    let ja = e.describe(Lang::Ja);
    assert!(ja.contains("構文エラー）: 文字列（\"…\"）が正しくありません"), "{ja}");
    assert!(!ja.contains("invalid basic string"), "{ja}");
    assert!(e.describe(Lang::En).contains("invalid basic string"), "{e}");

    // A key given twice: which key, and where it was first (the TOML parser says neither).
    let text = "format = 1\n[window]\nwidth = 640\n  height = 480\n  width = 320\n";
    let e = error(text);
    assert_at(&e, text, 5, "width", None);
    let first = Some(3);
    assert_eq!(*e.kind, ErrorKind::DuplicateKey { key: "width".into(), first_line: first });
    assert!(e.to_string().contains("`width` is given twice (first on line 3)"), "{e}");
    assert!(e.describe(Lang::Ja).contains("1 回目は 3 行目"), "{}", e.describe(Lang::Ja));
    // A table given twice, a dotted key, a quoted key.
    for (text, key, line) in [
        ("format = 1\n[window]\nwidth = 640\n[window]\n", "window", 2),
        ("format = 1\nwindow.width = 640\nwindow.width = 320\n", "width", 2),
        ("format = 1\n[window]\n\"width\" = 640\n\"width\" = 320\n", "\"width\"", 3),
    ] {
        let e = error(text);
        let kind = ErrorKind::DuplicateKey { key: key.into(), first_line: Some(line) };
        assert_eq!(*e.kind, kind, "{text}");
    }
}

#[test]
fn unknown_keys_are_errors_with_the_closest_key_suggested() {
    let text = r#"format = 1
[[objects]]
name = "ball"
shape = { kind = "grid", divisions = 2, size = 1 }
materal = "green"
"#;
    let e = error(text);
    assert_at(&e, text, 5, "materal", Some("objects[0].materal"));
    assert!(
        matches!(&*e.kind, ErrorKind::UnknownKey { key, suggestion: Some(s), .. } if key == "materal" && s == "material"),
        "{e}"
    );
    assert!(e.to_string().ends_with("unknown key `materal` (did you mean `material`?)"), "{e}");

    // With nothing close, the message lists the keys of the table instead.
    let text = "format = 1\n[[lights]]\nkind = \"directional\"\nto_light = [0, 1, 0]\nattenuation = [1, 0, 0]\n";
    let e = error(text);
    assert_at(&e, text, 5, "attenuation", Some("lights[0].attenuation"));
    assert!(e.to_string().contains("`to_light`"), "{e}");

    // At the top level and in a section header's table.
    let text = "format = 1\nwindows = {}\n";
    assert_at(&error(text), text, 2, "windows", Some("windows"));
    let text = "format = 1\n[render]\nshadding = \"flat\"\n";
    let e = error(text);
    assert_at(&e, text, 3, "shadding", Some("render.shadding"));
    assert!(
        matches!(*e.kind, ErrorKind::UnknownKey { suggestion: Some(ref s), .. } if s == "shading")
    );
}

#[test]
fn wrong_types_name_what_the_key_takes() {
    let text = r#"format = 1
[camera]
kind = "orbit"
distance = "far"
"#;
    let e = error(text);
    assert_at(&e, text, 4, "\"far\"", Some("camera.distance"));
    assert_eq!(*e.kind, ErrorKind::WrongType { expected: Expected::Number, found: Found::String });
    assert!(e.to_string().ends_with("expected a number, found a string"), "{e}");

    // An element of an array is named by its index.
    let text = "format = 1\n[[lights]]\nkind = \"point\"\nposition = [1, \"2\", 3]\n";
    let e = error(text);
    assert_at(&e, text, 4, "\"2\"", Some("lights[0].position[1]"));
    // Two numbers where three belong.
    let text = "format = 1\n[window]\nclear_color = [0.5, 0.5]\n";
    let e = error(text);
    assert_at(&e, text, 3, "[0.5", Some("window.clear_color"));
    assert_eq!(
        *e.kind,
        ErrorKind::WrongType { expected: Expected::Color, found: Found::Array { len: 2 } }
    );
    // A float where an integer belongs.
    let text = "format = 1\n[window]\nwidth = 640.0\n";
    let e = error(text);
    assert_at(&e, text, 3, "640.0", Some("window.width"));
    assert_eq!(*e.kind, ErrorKind::WrongType { expected: Expected::Integer, found: Found::Float });
    // `[[objects]]` written as `[objects]`.
    let text = "format = 1\n[objects]\nname = \"x\"\n";
    let e = error(text);
    assert_at(&e, text, 2, "[objects]", Some("objects"));
    assert!(matches!(
        *e.kind,
        ErrorKind::WrongType { expected: Expected::ArrayOfTables, found: Found::Table }
    ));
    // A word where a choice belongs, and a number where a word belongs.
    let text = "format = 1\n[render]\ncull_back_faces = \"yes\"\n";
    assert_at(&error(text), text, 3, "\"yes\"", Some("render.cull_back_faces"));
    let text = "format = 1\n[render]\nshading = 2\n";
    assert_at(&error(text), text, 3, "2", Some("render.shading"));
}

#[test]
fn bad_values_say_the_rule_and_quote_the_value() {
    // The example of the brief, character for character.
    let text = r#"format = 1
[[objects]]
name = "ground"
shape = { kind = "grid", divisions = 10, size = 10.0 }

[[objects]]
name = "ball"
shape = { kind = "uv_sphere", radius = -1, slices = 16, stacks = 8 }
"#;
    let e = error(text);
    assert_at(&e, text, 8, "-1", Some("objects[1].shape.radius"));
    assert_eq!(
        e.to_string(),
        "fixtures/mistake.toml:8:40: objects[1].shape.radius: must be finite and > 0, got -1"
    );
    assert_eq!(
        e.describe(Lang::Ja),
        "fixtures/mistake.toml:8:40: objects[1].shape.radius: 0 より大きい有限の数でなければなりません（書かれている値: -1）"
    );

    let cases: &[(&str, usize, &str, &str, Rule)] = &[
        (
            "format = 1\n[projection]\nnear = 10\nfar = 5\n",
            4,
            "5",
            "projection.far",
            Rule::GreaterThan { key: "near", value: 10.0 },
        ),
        ("format = 1\n[projection]\nnear = nan\n", 3, "nan", "projection.near", Rule::Positive),
        (
            "format = 1\n[window]\nwidth = 0\n",
            3,
            "0",
            "window.width",
            Rule::Integer { min: 1, max: 16384 },
        ),
        (
            "format = 1\n[window]\nclear_color = [0.5, -0.5, 0.8]\n",
            3,
            "-0.5",
            "window.clear_color[1]",
            Rule::NonNegative,
        ),
        (
            "format = 1\n[render]\nglobal_ambient = [inf, 0, 0]\n",
            3,
            "inf",
            "render.global_ambient[0]",
            Rule::NonNegative,
        ),
        (
            "format = 1\n[camera]\npitch_deg = 10\n",
            3,
            "10",
            "camera.pitch_deg",
            Rule::Between { min: -90.0, max: 0.0 },
        ),
        ("format = 1\n[camera]\ndistance = 1e39\n", 3, "1e39", "camera.distance", Rule::Positive),
        // Limits that leave out the default pitch (−30°) are reported at the camera table.
        (
            "format = 1\n[camera]\nlimits = { pitch_max_deg = -40 }\n",
            2,
            "[camera]",
            "camera",
            Rule::Between { min: -90.0, max: -40.0 },
        ),
        (
            "format = 1\n[camera]\nlimits = { pitch_min_deg = 20, pitch_max_deg = 10 }\n",
            3,
            "20",
            "camera.limits.pitch_min_deg",
            Rule::NotAbove { key: "pitch_max_deg", value: 10.0 },
        ),
        (
            "format = 1\n[camera]\nlimits = { distance_min = 5, distance_max = 3 }\n",
            3,
            "3 }",
            "camera.limits.distance_max",
            Rule::GreaterThan { key: "distance_min", value: 5.0 },
        ),
        (
            "format = 1\n[projection]\nnear = 600\n",
            3,
            "600",
            "projection.near",
            Rule::Inside { min: 0.0, max: 500.0 },
        ),
        (
            "format = 1\n[[lights]]\nkind = \"directional\"\nto_light = [0, 0, 0]\n",
            4,
            "[0, 0, 0]",
            "lights[0].to_light",
            Rule::NonZeroVector,
        ),
        (
            "format = 1\n[[lights]]\nkind = \"spot\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0]\ncutoff_deg = 95\n",
            6,
            "95",
            "lights[0].cutoff_deg",
            Rule::SpotCutoff,
        ),
        (
            "format = 1\n[render]\nlight_model = \"lecture\"\n[[lights]]\nkind = \"spot\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0]\ncutoff_deg = 30\ninner_deg = 40\n",
            9,
            "40",
            "lights[0].inner_deg",
            Rule::NotAbove { key: "cutoff_deg", value: 30.0 },
        ),
        (
            // No cone to be inside of: inner_deg was passed over without a word.
            "format = 1\n[render]\nlight_model = \"lecture\"\n[[lights]]\nkind = \"spot\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0]\ncutoff_deg = 180\ninner_deg = 20\n",
            9,
            "20",
            "lights[0].inner_deg",
            Rule::InnerNeedsCone,
        ),
        (
            "format = 1\n[[lights]]\nkind = \"point\"\nposition = [0, 1, 0]\nattenuation = [0, 0, 0]\n",
            5,
            "[0, 0, 0]",
            "lights[0].attenuation",
            Rule::SomeAttenuation,
        ),
        (
            "format = 1\n[[lights]]\nkind = \"area\"\ncorner = [0, 4, 0]\nedge_u = [1, 0, 0]\nedge_v = [2, 0, 0]\nsamples = [2, 2]\n",
            6,
            "[2, 0, 0]",
            "lights[0].edge_v",
            Rule::NonZeroArea,
        ),
        (
            // An area the renderers' f32 cannot hold (the cross product underflows to 0): no
            // axis, so the light shone both ways; and one that overflows to ∞.
            "format = 1\n[[lights]]\nkind = \"area\"\ncorner = [0, 4, 0]\nedge_u = [1e-23, 0, 0]\nedge_v = [0, 0, 1e-23]\nsamples = [2, 2]\n",
            6,
            "[0, 0, 1e-23]",
            "lights[0].edge_v",
            Rule::NonZeroArea,
        ),
        (
            "format = 1\n[[lights]]\nkind = \"area\"\ncorner = [0, 4, 0]\nedge_u = [2e19, 0, 0]\nedge_v = [0, 0, 2e19]\nsamples = [2, 2]\n",
            6,
            "[0, 0, 2e19]",
            "lights[0].edge_v",
            Rule::NonZeroArea,
        ),
        (
            "format = 1\n[[lights]]\nkind = \"area\"\ncorner = [0, 4, 0]\nedge_u = [1, 0, 0]\nedge_v = [0, 0, 1]\nsamples = [0, 2]\n",
            7,
            "0",
            "lights[0].samples[0]",
            Rule::Integer { min: 1, max: 256 },
        ),
        ("format = 1\n[materials.m]\neta = 0\n", 3, "0", "materials.m.eta", Rule::Positive),
        (
            "format = 1\n[materials.m]\nshininess = -2\n",
            3,
            "-2",
            "materials.m.shininess",
            Rule::NonNegative,
        ),
        (
            "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\ntransform = [{ rotate_deg = 30, axis = [0, 0, 0] }]\n",
            5,
            "[0, 0, 0]",
            "objects[0].transform[0].axis",
            Rule::NonZeroVector,
        ),
        (
            "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\ntransform = [{ scale = [1, nan, 1] }]\n",
            5,
            "nan",
            "objects[0].transform[0].scale[1]",
            Rule::Finite,
        ),
        (
            "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\nnormals = { crease_deg = 200 }\n",
            5,
            "200",
            "objects[0].normals.crease_deg",
            Rule::Between { min: 0.0, max: 180.0 },
        ),
    ];
    for &(text, line, needle, key, rule) in cases {
        let e = error(text);
        assert_at(&e, text, line, needle, Some(key));
        assert!(
            matches!(*e.kind, ErrorKind::BadValue { rule: r, .. } if r == rule),
            "{e}\nexpected {rule:?}"
        );
    }
}

#[test]
fn material_mistakes() {
    let text = r#"format = 1
[materials.ground]
color = [0.5, 0.8, 0.5]

[[objects]]
name = "ground"
shape = { kind = "grid", divisions = 10, size = 10.0 }
material = "grund"
"#;
    let e = error(text);
    assert_at(&e, text, 8, "\"grund\"", Some("objects[0].material"));
    assert_eq!(
        *e.kind,
        ErrorKind::UnknownMaterial { name: "grund".into(), suggestion: Some("ground".into()) }
    );

    // `color` and `ka` together: the error says why.
    let text = "format = 1\n[materials.m]\ncolor = [1, 1, 1]\nka = [0.2, 0.2, 0.2]\n";
    let e = error(text);
    assert_at(&e, text, 4, "[0.2", Some("materials.m.ka"));
    assert_eq!(*e.kind, ErrorKind::ColorWithReflectance { other: "ka" });
    assert!(e.to_string().contains("sets both ka and kd"), "{e}");

    // An inline material is checked like a named one.
    let text = "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\nmaterial = { colour = [1, 0, 0] }\n";
    let e = error(text);
    assert_at(&e, text, 5, "colour", Some("objects[0].material.colour"));
    assert!(
        matches!(*e.kind, ErrorKind::UnknownKey { suggestion: Some(ref s), .. } if s == "color")
    );
    let text = "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\nmaterial = 3\n";
    let e = error(text);
    assert_at(&e, text, 5, "3", Some("objects[0].material"));
    assert!(matches!(*e.kind, ErrorKind::WrongType { expected: Expected::Material, .. }));
}

fn beside_assets() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/mistake.toml")
}

#[test]
fn files_that_cannot_be_loaded_are_named_with_the_scene_line() {
    let text = r#"format = 1
[[objects]]
name = "model"
mesh = "models/missing.obj"
"#;
    let e = error(text);
    assert_at(&e, text, 4, "\"models/missing.obj\"", Some("objects[0].mesh"));
    let ErrorKind::File(inner) = &*e.kind else { panic!("{e}") };
    assert_eq!(
        inner.file,
        Path::new("fixtures/models/missing.obj"),
        "relative to the scene's folder"
    );
    assert!(matches!(*inner.kind, ErrorKind::Read { .. }), "{e}");
    assert!(e.to_string().contains("fixtures/models/missing.obj: cannot read the file"), "{e}");
    assert!(e.describe(Lang::Ja).contains("ファイルを読めません"), "{}", e.describe(Lang::Ja));

    // A texture image that is missing: the line of `image`.
    let text = "format = 1\n[[objects]]\nname = \"地面\"\nshape = { kind = \"grid\", divisions = 1, size = 1 }\ntexture = { filter = \"nearest\", image = \"テクスチャ.png\" }\n";
    let e = error(text);
    assert_at(&e, text, 5, "\"テクスチャ.png\"", Some("objects[0].texture.image"));
    assert!(
        matches!(&*e.kind, ErrorKind::File(inner) if matches!(*inner.kind, ErrorKind::Read { .. }))
    );
    // Columns count characters: the Japanese file name before the mistake counts 6, not 18 bytes.
    let text = "format = 1\n[[objects]]\nname = \"地面\"\nshape = { kind = \"grid\", divisions = 1, size = 1 }\ntexture = { image = \"テクスチャ.png\", filter = \"nearst\" }\n";
    let e = error(text);
    assert_at(&e, text, 5, "\"nearst\"", Some("objects[0].texture.filter"));
    assert_eq!(e.position.map(|p| p.column), Some(43));

    // The texture needs texture coordinates; `normals = "given"` needs normals.
    let text = "format = 1\n[[objects]]\nname = \"p\"\nmesh = \"../models/pyramid.obj\"\ntexture = { image = \"../textures/orientation.png\" }\n";
    let e = cg_scene::parse(text, &beside_assets()).unwrap_err();
    assert_eq!((e.position.unwrap().line, e.key.as_deref()), (5, Some("objects[0].texture")));
    assert_eq!(*e.kind, ErrorKind::NeedsUvs);
    let text = "format = 1\n[[objects]]\nname = \"p\"\nmesh = \"../models/pyramid.obj\"\nnormals = \"given\"\n";
    let e = cg_scene::parse(text, &beside_assets()).unwrap_err();
    assert_eq!((e.position.unwrap().line, e.key.as_deref()), (5, Some("objects[0].normals")));
    assert_eq!(*e.kind, ErrorKind::NeedsNormals);
}

#[test]
fn structural_mistakes() {
    // A missing key points at its table.
    let text = "format = 1\n[[objects]]\nshape = { kind = \"lecture_pyramid\" }\n";
    let e = error(text);
    assert_at(&e, text, 2, "[[objects]]", Some("objects[0]"));
    assert_eq!(*e.kind, ErrorKind::MissingKey { key: "name".into() });
    let e = error("name = \"no version\"\n");
    assert_eq!((e.position.map(|p| (p.line, p.column)), e.key.as_deref()), (Some((1, 1)), None));
    assert_eq!(*e.kind, ErrorKind::MissingKey { key: "format".into() });

    // An unknown version is refused before anything else is looked at.
    let text = "format = 2\nsomething_new = true\n";
    let e = error(text);
    assert_at(&e, text, 1, "2", Some("format"));
    assert_eq!(*e.kind, ErrorKind::UnsupportedFormat { found: "2".into() });

    // A misspelt choice.
    let text = "format = 1\n[render]\nshading = \"goraud\"\n";
    let e = error(text);
    assert_at(&e, text, 3, "\"goraud\"", Some("render.shading"));
    assert!(matches!(*e.kind, ErrorKind::UnknownChoice { suggestion: Some("gouraud"), .. }), "{e}");

    // Conflicting keys.
    let text = "format = 1\n[render]\nspecular = \"blinn\"\n";
    let e = error(text);
    assert_at(&e, text, 3, "\"blinn\"", Some("render.specular"));
    assert_eq!(*e.kind, ErrorKind::SpecularNeedsLectureModel);
    // A spot light's inner cone in OpenGL's model (the default), which has none: it would be
    // ignored, the picture the same as without it.
    let text = "format = 1\n[[lights]]\nkind = \"spot\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0]\ncutoff_deg = 30\ninner_deg = 10\n";
    let e = error(text);
    assert_at(&e, text, 7, "10", Some("lights[0].inner_deg"));
    assert_eq!(*e.kind, ErrorKind::InnerConeNeedsLectureModel);
    let lecture = text.replace("format = 1\n", "format = 1\n[render]\nlight_model = \"lecture\"\n");
    assert!(
        cg_scene::parse(&lecture, std::path::Path::new("a.toml")).is_ok(),
        "the lecture's model takes it"
    );
    let text = "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\nmesh = \"a.obj\"\n";
    let e = error(text);
    assert_at(&e, text, 5, "\"a.obj\"", Some("objects[0].mesh"));
    assert_eq!(*e.kind, ErrorKind::ShapeAndMesh);
    let text = "format = 1\n[[objects]]\nname = \"x\"\n";
    let e = error(text);
    assert_at(&e, text, 2, "[[objects]]", Some("objects[0]"));
    assert_eq!(*e.kind, ErrorKind::NoGeometry);

    // Transform steps hold exactly one operation; `axis` belongs to `rotate_deg`.
    let text = "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\ntransform = [{ translate = [0, 1, 0] }, { translate = [1, 0, 0], scale = [2, 2, 2] }]\n";
    let e = error(text);
    assert_at(&e, text, 5, "{ translate = [1", Some("objects[0].transform[1]"));
    assert_eq!(
        *e.kind,
        ErrorKind::TransformStep { found: vec!["translate".into(), "scale".into()] }
    );
    let text = "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\ntransform = [{ rotate_x_deg = 30, axis = [1, 0, 0] }]\n";
    assert!(matches!(*error(text).kind, ErrorKind::TransformStep { .. }));
    let text = "format = 1\n[[objects]]\nname = \"x\"\nshape = { kind = \"lecture_pyramid\" }\ntransform = [{ rotate_deg = 30 }]\n";
    let e = error(text);
    assert_at(&e, text, 5, "{ rotate_deg", Some("objects[0].transform[0]"));
    assert_eq!(*e.kind, ErrorKind::MissingKey { key: "axis".into() });

    // Two objects with one name.
    let text = "format = 1\n[[objects]]\nname = \"a\"\nshape = { kind = \"lecture_pyramid\" }\n[[objects]]\nname = \"a\"\nshape = { kind = \"lecture_pyramid\" }\n";
    let e = error(text);
    assert_at(&e, text, 6, "\"a\"", Some("objects[1].name"));
    assert_eq!(*e.kind, ErrorKind::DuplicateName { name: "a".into(), first_line: 2 });
}

#[test]
fn reading_a_missing_scene_file_names_it() {
    let e = cg_scene::load(Path::new("fixtures/does-not-exist.toml")).unwrap_err();
    assert_eq!(e.file, Path::new("fixtures/does-not-exist.toml"));
    assert_eq!((e.position, e.key.as_deref()), (None, None));
    assert!(matches!(*e.kind, ErrorKind::Read { .. }));
    assert!(
        e.to_string().starts_with("fixtures/does-not-exist.toml: cannot read the file: "),
        "{e}"
    );
    // In Japanese, what happened in Japanese, not the system's English words.
    let ja = e.describe(Lang::Ja);
    assert!(ja.ends_with("ファイルまたはフォルダがありません"), "{ja}");
    assert!(!ja.contains("No such file"), "{ja}");
}

#[test]
fn spot_cutoff_accepts_exactly_0_to_90_and_180() {
    let scene = |cutoff: &str| {
        let text = format!(
            "format = 1\n[[lights]]\nkind = \"spot\"\nposition = [0, 1, 0]\ndirection = [0, -1, 0]\ncutoff_deg = {cutoff}\n"
        );
        cg_scene::parse(&text, std::path::Path::new("spot.toml"))
    };
    for ok in ["0.001", "45", "90", "180"] {
        assert!(scene(ok).is_ok(), "cutoff {ok} is allowed: {:?}", scene(ok).err());
    }
    // 0 is no cone at all (nothing lit), between 90 and 180 OpenGL rejects, above 180 is meaningless.
    for bad in ["0", "-1", "90.0001", "179.9", "180.1", "nan"] {
        let e = scene(bad).expect_err(bad);
        assert_eq!(e.position.map(|p| p.line), Some(6), "{bad}: {e}");
        assert_eq!(e.key.as_deref(), Some("lights[0].cutoff_deg"), "{bad}: {e}");
    }
}

/// The error of `text`, which must be a [`ErrorKind::Transform`] at `line`, at `needle`, under
/// `key`, whose Japanese text is the core's `TransformError::message(Ja)` after the place.
#[track_caller]
fn assert_transform_error(text: &str, line: usize, needle: &str, key: &str) -> TransformError {
    let e = error(text);
    assert_at(&e, text, line, needle, Some(key));
    let ErrorKind::Transform(t) = &*e.kind else { panic!("not a transform error: {e}") };
    let ja = e.describe(Lang::Ja);
    assert!(ja.ends_with(&format!("{key}: {}", t.message(Lang::Ja))), "{ja}");
    assert!(e.to_string().ends_with(&format!("{key}: {}", t.message(Lang::En))), "{e}");
    t.clone()
}

#[test]
fn cameras_and_projections_are_checked_as_the_core_builds_them() {
    // gluLookAt has no answer when eye = target, or up is parallel to the view.
    let text = "format = 1\n[camera]\nkind = \"look_at\"\neye = [0, 0, 0]\n";
    let t = assert_transform_error(text, 4, "[0, 0, 0]", "camera.eye");
    assert_eq!(t, TransformError::EyeAtTarget { eye: Vec3::ZERO });
    let text = "format = 1\n[camera]\nkind = \"look_at\"\neye = [0, 5, 0]\nup = [0, -3, 0]\n";
    let t = assert_transform_error(text, 5, "[0, -3, 0]", "camera.up");
    assert!(matches!(t, TransformError::UpParallelToView { .. }), "{t}");
    // With up left out (+Y), the eye straight above the target is the mistake.
    let text = "format = 1\n[camera]\nkind = \"look_at\"\neye = [0, 5, 0]\n";
    assert_transform_error(text, 4, "[0, 5, 0]", "camera.eye");

    // Not exactly parallel, but within LOOK_AT_MIN_UP_ANGLE_DEG: atan(1e-4) = 0.0057° < 0.01°.
    // (The scene reader used to accept it, its cross product with the view being non-zero, and
    // the renderer's look_at then failed with no file, line or key.)
    let up_angle_deg = |x: f64| x.atan().to_degrees();
    assert!(up_angle_deg(1e-4) < LOOK_AT_MIN_UP_ANGLE_DEG);
    let text = "format = 1\n[camera]\nkind = \"look_at\"\neye = [0, 5, 0]\nup = [0.0001, 1, 0]\n";
    let t = assert_transform_error(text, 5, "[0.0001", "camera.up");
    let TransformError::UpParallelToView { angle_deg, .. } = t else { panic!("{t}") };
    assert!((angle_deg - up_angle_deg(1e-4)).abs() < 1e-6, "{angle_deg}");
    // Ten times farther from the view (0.057°) it loads.
    assert!(up_angle_deg(1e-3) > LOOK_AT_MIN_UP_ANGLE_DEG);
    let text = "format = 1\n[camera]\nkind = \"look_at\"\neye = [0, 5, 0]\nup = [0.001, 1, 0]\n";
    assert!(cg_scene::parse(text, Path::new(FILE)).is_ok());

    // A subnormal near plane is > 0, but gluPerspective's matrix cannot be built from it.
    let text = "format = 1\n[projection]\nnear = 1e-45\n";
    let t = assert_transform_error(text, 3, "1e-45", "projection.near");
    assert_eq!(t, TransformError::NearPlane { near: 1e-45 });
    assert!(!1e-45f32.is_normal() && 1e-45f32 > 0.0, "premise: 1e-45 is a positive subnormal");
    // A field of view whose matrix cannot be built (cot(fovy/2) overflows f32 at 1e-40°: 1/tan(0.5e-40°)
    // ≈ 1.1e42), or can only in a square window (at 1e-33° divided by the aspect ratio 1/16384 it
    // is 1.9e39), or can but no renderer draws alike: all below cg_scene::MIN_FOVY_DEG, the one
    // rule they are told (tests/limits.rs), at the same key, before gluPerspective is tried.
    let fovy = 1e-33f64;
    let f = 1.0 / (fovy / 2.0).to_radians().tan();
    assert!(f < f64::from(f32::MAX) && f * 16384.0 > f64::from(f32::MAX), "premise: {f:e}");
    for text in [
        "format = 1\n[projection]\nfovy_deg = 1e-40\n",
        "format = 1\n[window]\nwidth = 1\nheight = 16384\n[projection]\nfovy_deg = 1e-33\n",
        "format = 1\n[projection]\nfovy_deg = 1e-33\n",
    ] {
        let e = error(text);
        let limit = matches!(*e.kind, ErrorKind::Limit(cg_scene::LimitError::FieldOfView { .. }));
        assert!(limit, "{e}");
        assert_eq!(e.key.as_deref(), Some("projection.fovy_deg"));
    }
    // far a few percent beyond a near of 3e38: the depth entry far·near/(near − far) overflows.
    let text = "format = 1\n[projection]\nnear = 3e38\nfar = 3.1e38\n";
    let t = assert_transform_error(text, 4, "3.1e38", "projection.far");
    assert!(matches!(t, TransformError::DepthRange { .. }), "{t}");
}

#[test]
fn shape_errors_point_at_the_bad_value() {
    // A count above the constructors' limit (4096), or below their least: the range they take.
    let text = "format = 1\n[[objects]]\nname = \"c\"\nshape = { kind = \"cylinder\", radius = 1,\n  height = 2, slices = 5000 }\n";
    let e = error(text);
    assert_at(&e, text, 5, "5000", Some("objects[0].shape.slices"));
    assert_eq!(
        *e.kind,
        ErrorKind::BadValue { rule: Rule::Integer { min: 3, max: 4096 }, got: "5000".into() }
    );
    assert!(e.to_string().contains("an integer in 3..=4096"), "{e}");
    // A grid of 4097 divisions is out of range, not 'too many faces'.
    let text = "format = 1\n[[objects]]\nname = \"g\"\nshape = { kind = \"grid\", divisions = 4097, size = 1 }\n";
    let e = error(text);
    assert_eq!(
        *e.kind,
        ErrorKind::BadValue { rule: Rule::Integer { min: 1, max: 4096 }, got: "4097".into() }
    );
    let text = "format = 1\n[[objects]]\nname = \"i\"\nshape = { kind = \"icosphere\", radius = 1, subdivisions = 9 }\n";
    let e = error(text);
    assert_eq!(
        *e.kind,
        ErrorKind::BadValue { rule: Rule::Integer { min: 0, max: 8 }, got: "9".into() }
    );
    // A parameter valid alone but not with another: the torus's tube must be thinner than its ring.
    let text = "format = 1\n[[objects]]\nname = \"t\"\nshape = { kind = \"torus\", major = 1, minor = 2, major_segments = 8, minor_segments = 8 }\n";
    let e = error(text);
    assert_at(&e, text, 4, "2,", Some("objects[0].shape.minor"));
    assert!(
        e.describe(Lang::Ja).ends_with(
            ": objects[0].shape.minor: torus の minor = 2 は範囲外です（0 より大きく major より小さい有限の数でなければなりません）"
        ),
        "{e}"
    );
}

#[test]
fn shapes_with_too_many_faces_are_refused_before_anything_is_built() {
    // Four lines that used to take gigabytes: 2·4096·4095 = 33 546 240 triangles.
    let text = "format = 1\n[[objects]]\nname = \"ball\"\nshape = { kind = \"uv_sphere\", radius = 1, slices = 4096, stacks = 4096 }\n";
    let e = error(text);
    assert_at(&e, text, 4, "4096,", Some("objects[0].shape.slices"));
    let expected =
        ErrorKind::TooManyFaces { shape: "uv_sphere", faces: 33_546_240, max: 4_000_000 };
    assert_eq!(*e.kind, expected);
    assert_eq!(MAX_SHAPE_FACES, 4_000_000);
    assert!(e.to_string().contains("33546240 faces"), "{e}");
    assert!(e.describe(Lang::Ja).contains("33546240 個"), "{e}");

    // The parameter named is the one that sets the count (the larger of two).
    let cases = [
        ("{ kind = \"grid\", divisions = 4096, size = 1 }", "divisions", "grid", 2 * 4096 * 4096),
        (
            "{ kind = \"uv_sphere\", radius = 1, slices = 600, stacks = 4096 }",
            "stacks",
            "uv_sphere",
            2 * 600 * 4095,
        ),
        (
            "{ kind = \"torus\", major = 2, minor = 1, major_segments = 500, minor_segments = 4096 }",
            "minor_segments",
            "torus",
            2 * 500 * 4096,
        ),
        // An icosphere's subdivisions above 8 are out of range where they are read
        // (`shape_errors_point_at_the_bad_value`); the count's u64 saturation is unit-tested.
    ];
    for (shape, key, kind, faces) in cases {
        let text = format!("format = 1\n[[objects]]\nname = \"x\"\nshape = {shape}\n");
        let e = error(&text);
        let value = &shape[shape.find(&format!("{key} = ")).unwrap() + key.len() + 3..];
        assert_at(&e, &text, 4, value, Some(&format!("objects[0].shape.{key}")));
        assert_eq!(
            *e.kind,
            ErrorKind::TooManyFaces { shape: kind, faces, max: MAX_SHAPE_FACES },
            "{shape}"
        );
    }
}

use cg_testkit::text::english_fragments;

#[test]
fn japanese_messages_have_no_english_fragments() {
    let shape = cg_core::shapes::grid(5000, 1.0).unwrap_err();
    let position = Vec3::new(f32::NAN, 0.0, 0.0);
    let kinds = [
        // These two embedded the English Display text of the core's errors.
        ErrorKind::Shape(shape),
        ErrorKind::Mesh(MeshError::NonFinitePosition { vertex: 0, position }),
        ErrorKind::Transform(TransformError::NearPlane { near: 1e-45 }),
        ErrorKind::TooManyFaces { shape: "grid", faces: 33_554_432, max: MAX_SHAPE_FACES },
        ErrorKind::PngTooLarge { width: 100_000, height: 100_000 },
        ErrorKind::Obj(tobj::LoadError::ColorParseError),
        ErrorKind::ObjIndex { element: "vn", index: 2, count: 1 },
        ErrorKind::ObjNumber { element: "f", word: "x".into() },
        ErrorKind::ObjNumber { element: "v", word: "x".into() },
        ErrorKind::ObjValues { element: "v", found: 2 },
        ErrorKind::ObjCorner { corner: "1/1/1/1".into() },
        ErrorKind::ObjPosition { position: [f32::INFINITY, 0.0, 0.0], w: 1.0 },
    ];
    for kind in &kinds {
        let (ja, en) = (kind.describe(Lang::Ja), kind.describe(Lang::En));
        assert_eq!(english_fragments(&ja), Vec::<String>::new(), "English inside: {ja}");
        assert!(ja.chars().any(|c| ('\u{3040}'..='\u{30ff}').contains(&c)), "no kana in {ja}");
        // The check would catch the English text.
        assert!(!english_fragments(&en).is_empty(), "premise: {en}");
    }
    assert_eq!(
        kinds[0].describe(Lang::Ja),
        "grid の divisions = 5000 は範囲外です（1 以上 4096 以下の整数でなければなりません）"
    );
    assert_eq!(
        kinds[1].describe(Lang::Ja),
        "メッシュとして使えません: 頂点 V0 の座標 (NaN, 0, 0) に無限大または NaN が含まれています"
    );
}

#[test]
fn a_huge_or_invisible_word_is_shown_short_and_visible() {
    // A 2 MB key: the message quotes its start and says how long it is.
    let key = "k".repeat(2_000_000);
    let text = format!("format = 1\nname = \"x\"\n[window]\n{key} = 1\n");
    let e = error(&text);
    assert!(matches!(*e.kind, ErrorKind::UnknownKey { .. }), "{:?}", e.kind);
    let (en, ja) = (e.to_string(), e.describe(Lang::Ja));
    assert!(en.len() < 2_000 && ja.len() < 2_000, "{} / {} bytes", en.len(), ja.len());
    assert!(en.contains("… (2000000 characters)"), "{en}");
    assert!(ja.contains("…（全 2000000 文字）"), "{ja}");
    // A zero-width space pasted into a key is named, not hidden: in a bare key (a syntax error
    // at its column) and in a quoted one (an unknown key).
    for text in [
        "format = 1\nname = \"x\"\n[window]\nwid\u{200B}th = 64\n",
        "format = 1\nname = \"x\"\n[window]\n\"wid\u{200B}th\" = 64\n",
    ] {
        let e = error(text);
        assert_eq!(e.position.map(|p| p.line), Some(4), "{e}");
        let (en, ja) = (e.to_string(), e.describe(Lang::Ja));
        assert!(en.contains("<U+200B>") && !en.contains('\u{200B}'), "{en}");
        assert!(ja.contains("<U+200B>") && !ja.contains('\u{200B}'), "{ja}");
    }
}

#[test]
fn names_are_bounded_and_said_so_at_the_name() {
    let max = cg_scene::MAX_NAME_CHARS;
    let object = |name: &str| {
        format!(
            "format = 1\n[[objects]]\nname = \"{name}\"\nshape = {{ kind = \"lecture_pyramid\" }}\n"
        )
    };
    // At the limit, in characters (not bytes): 64 kana are 192 bytes.
    for name in ["a".repeat(max), "あ".repeat(max)] {
        let scene = cg_scene::parse(&object(&name), Path::new(FILE)).unwrap();
        assert_eq!(scene.objects[0].name, name);
    }
    let long = "b".repeat(max + 1);
    let text = object(&long);
    let e = error(&text);
    assert_at(&e, &text, 3, "\"bbb", Some("objects[0].name"));
    assert_eq!(*e.kind, ErrorKind::NameTooLong { chars: max + 1, max });
    assert!(e.to_string().ends_with("a name of 65 characters is too long: a name has at most 64"));
    // The scene's own name, and a material's (its key), however long: one short message.
    let huge = "c".repeat(100_000);
    let text = format!("format = 1\nname = \"{huge}\"\n");
    let e = error(&text);
    assert_at(&e, &text, 2, "\"ccc", Some("name"));
    assert_eq!(*e.kind, ErrorKind::NameTooLong { chars: 100_000, max });
    let text = format!("format = 1\n[materials.{huge}]\ncolor = [1, 1, 1]\n");
    let e = error(&text);
    assert_eq!(*e.kind, ErrorKind::NameTooLong { chars: 100_000, max });
    assert_eq!(e.position.map(|p| p.line), Some(2), "{e}");
    assert!(e.to_string().len() < 400, "{} bytes", e.to_string().len());
    assert!(e.describe(Lang::Ja).len() < 600, "{} bytes", e.describe(Lang::Ja).len());
    // A number finite in f64 but not in the renderers' f32 says how large a number may be.
    let e = error("format = 1\n[camera]\nyaw_deg = 1e300\n");
    assert!(e.to_string().contains("must be finite (at most 3.4e38 in absolute value)"), "{e}");
    assert!(e.describe(Lang::Ja).contains("絶対値 3.4e38 まで"), "{}", e.describe(Lang::Ja));
    // A control character (an escape sequence, which `cg inspect` printed to the terminal as
    // it was), in an object's name, the scene's or a material's key: at the name, with its code.
    let text = object("ab\\u001b]52;c;x\\u0007");
    let e = error(&text);
    assert_at(&e, &text, 3, "\"ab", Some("objects[0].name"));
    assert_eq!(*e.kind, ErrorKind::NameControl { code: 0x1b, place: 3 });
    assert!(e.to_string().contains("control character, U+001B, at character 3"), "{e}");
    assert!(!e.to_string().contains('\u{1b}'), "{e}");
    let e = error("format = 1\nname = \"a\\tb\"\n");
    assert_eq!(*e.kind, ErrorKind::NameControl { code: 9, place: 2 });
    let e = error("format = 1\n[materials.\"x\\u007f\"]\ncolor = [1, 1, 1]\n");
    assert_eq!(*e.kind, ErrorKind::NameControl { code: 0x7f, place: 2 });
}
