//! Tests of the messages themselves: every variant, both languages, clean sentences.

use std::path::PathBuf;

use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::mesh::MeshError;
use cg_core::shapes::{Allowed, ShapeError};
use cg_core::texture::TextureError;
use cg_core::transform::TransformError;

use super::*;

/// How many variants [`ErrorKind`] has; [`kind_index`] numbers them `0..KINDS`.
const KINDS: usize = 53;

/// A number for each variant of [`ErrorKind`] (the match is exhaustive, so a new variant does not
/// compile until it is numbered here, and [`every_kind_has_a_sample`] fails until it has a
/// sample).
fn kind_index(kind: &ErrorKind) -> usize {
    match kind {
        ErrorKind::Read { .. } => 0,
        ErrorKind::Encoding { .. } => 39,
        ErrorKind::Syntax { .. } => 1,
        ErrorKind::UnsupportedFormat { .. } => 2,
        ErrorKind::UnknownKey { .. } => 3,
        ErrorKind::MissingKey { .. } => 4,
        ErrorKind::WrongType { .. } => 5,
        ErrorKind::UnknownChoice { .. } => 6,
        ErrorKind::BadValue { .. } => 7,
        ErrorKind::ReflectanceSum { .. } => 8,
        ErrorKind::TooManyPixels { .. } => 9,
        ErrorKind::ColorWithReflectance { .. } => 10,
        ErrorKind::ShapeAndMesh => 11,
        ErrorKind::NoGeometry => 12,
        ErrorKind::SpecularNeedsLectureModel => 13,
        ErrorKind::TransformStep { .. } => 14,
        ErrorKind::UnknownMaterial { .. } => 15,
        ErrorKind::DuplicateName { .. } => 16,
        ErrorKind::NeedsNormals => 17,
        ErrorKind::NeedsUvs => 18,
        ErrorKind::Shape(_) => 19,
        ErrorKind::TooManyFaces { .. } => 20,
        ErrorKind::Transform(_) => 21,
        ErrorKind::File(_) => 22,
        ErrorKind::Obj(_) => 23,
        ErrorKind::ObjIndex { .. } => 24,
        ErrorKind::ObjNumber { .. } => 25,
        ErrorKind::ObjValues { .. } => 26,
        ErrorKind::ObjCorner { .. } => 27,
        ErrorKind::ObjPosition { .. } => 28,
        ErrorKind::ObjNoFaces => 29,
        ErrorKind::ObjPartial { .. } => 30,
        ErrorKind::ObjBadNormal { .. } => 31,
        ErrorKind::ObjBadUv { .. } => 32,
        ErrorKind::Mesh(_) => 33,
        ErrorKind::NotPng => 34,
        ErrorKind::PngTooLarge { .. } => 35,
        ErrorKind::Png { .. } => 36,
        ErrorKind::Texture(_) => 37,
        ErrorKind::Write { .. } => 38,
        ErrorKind::FileTooLarge { .. } => 40,
        ErrorKind::Limit(_) => 41,
        ErrorKind::InnerConeNeedsLectureModel => 42,
        ErrorKind::WeldRemovesEveryFace { .. } => 43,
        ErrorKind::DuplicateKey { .. } => 44,
        ErrorKind::ObjPolygon { .. } => 45,
        ErrorKind::NameTooLong { .. } => 46,
        ErrorKind::WeldMergesSeam { .. } => 47,
        ErrorKind::ObjZeroNormal => 48,
        ErrorKind::ObjCornerForm { .. } => 49,
        ErrorKind::ObjRepeatedVertex { .. } => 50,
        ErrorKind::ObjFaceForm { .. } => 51,
        ErrorKind::NameControl { .. } => 52,
    }
}

/// Every [`Rule`], with sample bounds.
fn all_rules() -> Vec<Rule> {
    let rules = vec![
        Rule::Finite,
        Rule::NonNegative,
        Rule::Positive,
        Rule::Between { min: 0.0, max: 1.0 },
        Rule::Inside { min: 0.0, max: 180.0 },
        Rule::SpotCutoff,
        Rule::InnerNeedsCone,
        Rule::Integer { min: 1, max: 4096 },
        Rule::NonZeroVector,
        Rule::GreaterThan { key: "near", value: 0.5 },
        Rule::NotAbove { key: "far", value: 100.0 },
        Rule::NonZeroArea,
        Rule::SomeAttenuation,
        Rule::AtMost { max: 1e6 },
    ];
    // Exhaustive: a new rule does not compile until it is listed above.
    for rule in &rules {
        match rule {
            Rule::Finite
            | Rule::NonNegative
            | Rule::Positive
            | Rule::Between { .. }
            | Rule::Inside { .. }
            | Rule::SpotCutoff
            | Rule::InnerNeedsCone
            | Rule::Integer { .. }
            | Rule::NonZeroVector
            | Rule::GreaterThan { .. }
            | Rule::NotAbove { .. }
            | Rule::NonZeroArea
            | Rule::SomeAttenuation
            | Rule::AtMost { .. } => {}
        }
    }
    rules
}

/// Every [`Expected`].
fn all_expected() -> Vec<Expected> {
    let all = vec![
        Expected::Number,
        Expected::Integer,
        Expected::String,
        Expected::Boolean,
        Expected::Table,
        Expected::ArrayOfTables,
        Expected::Vec3,
        Expected::Color,
        Expected::Attenuation,
        Expected::Samples,
        Expected::Wrap,
        Expected::Choice,
        Expected::Normals,
        Expected::Material,
        Expected::Weld,
    ];
    for e in &all {
        match e {
            Expected::Number
            | Expected::Integer
            | Expected::String
            | Expected::Boolean
            | Expected::Table
            | Expected::ArrayOfTables
            | Expected::Vec3
            | Expected::Color
            | Expected::Attenuation
            | Expected::Samples
            | Expected::Wrap
            | Expected::Choice
            | Expected::Normals
            | Expected::Material
            | Expected::Weld => {}
        }
    }
    all
}

/// Every [`Found`] (arrays of 1 and of several values, which read differently).
fn all_found() -> Vec<Found> {
    let all = vec![
        Found::String,
        Found::Integer,
        Found::Float,
        Found::Boolean,
        Found::Datetime,
        Found::Array { len: 1 },
        Found::Array { len: 2 },
        Found::Table,
    ];
    for f in &all {
        match f {
            Found::String
            | Found::Integer
            | Found::Float
            | Found::Boolean
            | Found::Datetime
            | Found::Array { .. }
            | Found::Table => {}
        }
    }
    all
}

/// Every tobj error.
fn all_obj_errors() -> Vec<tobj::LoadError> {
    use tobj::LoadError as E;
    vec![
        E::OpenFileFailed,
        E::ReadError,
        E::UnrecognizedCharacter,
        E::PositionParseError,
        E::ScalingByZeroError,
        E::ColorParseError,
        E::NormalParseError,
        E::TexcoordParseError,
        E::FaceParseError,
        E::MaterialParseError,
        E::InvalidObjectName,
        E::InvalidPolygon,
        E::FaceVertexOutOfBounds,
        E::FaceTexCoordOutOfBounds,
        E::FaceNormalOutOfBounds,
        E::FaceColorOutOfBounds,
        E::InvalidLoadOptionConfig,
        E::GenericFailure,
    ]
}

/// Samples of every variant, and of every branch a variant's message takes (with and without a
/// suggestion, each `Rule`, `Expected` and `Found`, each OBJ element, …). The sample data is
/// ASCII, so that an English message has no Japanese at all.
fn samples() -> Vec<ErrorKind> {
    let mut kinds = vec![
        ErrorKind::Read { reason: Text::io(&std::io::Error::from(std::io::ErrorKind::NotFound)) },
        ErrorKind::Encoding {
            why: cg_core::lang::Text::new(
                "UTF-8 としても Shift_JIS としても読めません（1 行 3 列）",
                "neither UTF-8 nor Shift_JIS (line 1, column 3)",
            ),
        },
        ErrorKind::Syntax { message: "invalid string".into() },
        ErrorKind::DuplicateKey { key: "width".into(), first_line: Some(3) },
        ErrorKind::DuplicateKey { key: "width".into(), first_line: None },
        ErrorKind::UnsupportedFormat { found: "2".into() },
        ErrorKind::UnknownKey {
            key: "radiu".into(),
            suggestion: Some("radius".into()),
            allowed: vec!["kind", "radius"],
        },
        ErrorKind::UnknownKey { key: "colour".into(), suggestion: None, allowed: vec!["kind"] },
        ErrorKind::MissingKey { key: "kind".into() },
        ErrorKind::UnknownChoice {
            value: "gourad".into(),
            suggestion: Some("gouraud"),
            allowed: vec!["flat", "gouraud"],
        },
        ErrorKind::UnknownChoice { value: "x".into(), suggestion: None, allowed: vec!["flat"] },
        ErrorKind::ReflectanceSum { channel: 1, kr: 0.5, kt: 0.75 },
        ErrorKind::TooManyPixels { width: 10000, height: 10000 },
        ErrorKind::ColorWithReflectance { other: "kd" },
        ErrorKind::ShapeAndMesh,
        ErrorKind::NoGeometry,
        ErrorKind::SpecularNeedsLectureModel,
        ErrorKind::InnerConeNeedsLectureModel,
        ErrorKind::WeldRemovesEveryFace { tolerance: 10.0, faces: 6 },
        ErrorKind::WeldMergesSeam { uvs: true, kept: 3, merged: 17 },
        ErrorKind::WeldMergesSeam { uvs: false, kept: 0, merged: 1 },
        ErrorKind::TransformStep { found: vec![] },
        ErrorKind::TransformStep { found: vec!["translate".into(), "scale".into()] },
        ErrorKind::UnknownMaterial { name: "glas".into(), suggestion: Some("glass".into()) },
        ErrorKind::UnknownMaterial { name: "metal".into(), suggestion: None },
        ErrorKind::DuplicateName { name: "ball".into(), first_line: 12 },
        ErrorKind::NameTooLong { chars: 100_000, max: 64 },
        ErrorKind::NameControl { code: 0x1b, place: 3 },
        ErrorKind::NeedsNormals,
        ErrorKind::NeedsUvs,
        ErrorKind::Shape(ShapeError {
            shape: "grid",
            parameter: "divisions",
            value: "5000".into(),
            expected: Allowed::Count { min: 1, max: 4096 },
        }),
        ErrorKind::TooManyFaces { shape: "uv_sphere", faces: 33_546_240, max: 4_000_000 },
        ErrorKind::Transform(TransformError::NearPlane { near: -1.0 }),
        ErrorKind::Transform(TransformError::EyeAtTarget { eye: Vec3::ONE }),
        ErrorKind::File(Box::new(SceneError {
            file: PathBuf::from("models/x.obj"),
            position: Some(Position { line: 3, column: 5 }),
            key: None,
            kind: Box::new(ErrorKind::ObjNoFaces),
        })),
        ErrorKind::ObjIndex { element: "v", index: 9, count: 4 },
        ErrorKind::ObjIndex { element: "vt", index: -7, count: 2 },
        ErrorKind::ObjNumber { element: "f", word: "x".into() },
        ErrorKind::ObjNumber { element: "l", word: "99999999999999999999".into() },
        ErrorKind::ObjNumber { element: "v", word: "x".into() },
        ErrorKind::ObjValues { element: "f", found: 0 },
        ErrorKind::ObjValues { element: "v", found: 2 },
        ErrorKind::ObjValues { element: "vt", found: 1 },
        ErrorKind::ObjValues { element: "vn", found: 2 },
        ErrorKind::ObjCorner { corner: "1/2/3/4".into() },
        ErrorKind::ObjCornerForm {
            corner: "3".into(),
            first: "1//1".into(),
            element: "vn",
            has: false,
        },
        ErrorKind::ObjCornerForm {
            corner: "2/2".into(),
            first: "1".into(),
            element: "vt",
            has: true,
        },
        ErrorKind::ObjRepeatedVertex { corner: "1".into(), vertex: 1, first: 1 },
        ErrorKind::ObjFaceForm { element: "vn", has: false, first_line: 7 },
        ErrorKind::ObjFaceForm { element: "vt", has: true, first_line: 3 },
        ErrorKind::ObjPosition { position: [f32::INFINITY; 3], w: 0.0 },
        ErrorKind::ObjPosition { position: [1.0, f32::NAN, 0.0], w: 1.0 },
        ErrorKind::ObjPolygon { corners: 4, problem: crate::PolygonProblem::Crosses },
        ErrorKind::ObjPolygon {
            corners: 2000,
            problem: crate::PolygonProblem::TooManyCorners { max: 1024 },
        },
        ErrorKind::ObjPolygon { corners: 7, problem: crate::PolygonProblem::NotCovered },
        ErrorKind::ObjNoFaces,
        ErrorKind::ObjPartial { element: "vn" },
        ErrorKind::ObjBadNormal { vertex: 4 },
        ErrorKind::ObjZeroNormal,
        ErrorKind::ObjBadUv { vertex: 5 },
        ErrorKind::Mesh(MeshError::IndexOutOfRange {
            face: 6,
            corner: 2,
            index: 9,
            vertex_count: 5,
        }),
        ErrorKind::Mesh(MeshError::IndexOutOfRange {
            face: 0,
            corner: 0,
            index: 0,
            vertex_count: 0,
        }),
        ErrorKind::Mesh(MeshError::AttributeLength { attribute: "uvs", len: 3, expected: 4 }),
        ErrorKind::Mesh(MeshError::NonFinitePosition {
            vertex: 2,
            position: Vec3::new(f32::NAN, 0.0, 1.0),
        }),
        ErrorKind::NotPng,
        ErrorKind::PngTooLarge { width: 100_000, height: 100_000 },
        ErrorKind::FileTooLarge { size: Some(70_000_000), limit_mib: 64 },
        ErrorKind::Png { reason: "unexpected end of file".into() },
        ErrorKind::Texture(TextureError::ZeroSize { width: 0, height: 4 }),
        ErrorKind::Texture(TextureError::TexelCount { width: 2, height: 2, expected: 4, got: 3 }),
        ErrorKind::Write {
            reason: Text::io(&std::io::Error::from(std::io::ErrorKind::PermissionDenied)),
        },
    ];
    kinds.extend(crate::limits::tests::samples().into_iter().map(ErrorKind::Limit));
    kinds
        .extend(all_rules().into_iter().map(|rule| ErrorKind::BadValue { rule, got: "-1".into() }));
    for expected in all_expected() {
        for found in all_found() {
            kinds.push(ErrorKind::WrongType { expected, found });
        }
    }
    kinds.extend(all_obj_errors().into_iter().map(ErrorKind::Obj));
    kinds
}

/// Hiragana, katakana or a kanji.
fn is_japanese_letter(c: char) -> bool {
    matches!(c, '\u{3040}'..='\u{30ff}' | '\u{3400}'..='\u{4dbf}' | '\u{4e00}'..='\u{9fff}')
}

/// A Japanese letter or Japanese punctuation (`。`, `、`, `（`, `）`, full-width forms).
fn is_japanese(c: char) -> bool {
    is_japanese_letter(c) || matches!(c, '\u{3000}'..='\u{303f}' | '\u{ff00}'..='\u{ffef}')
}

/// What is wrong with `text` as a one-line message in `lang` (empty when nothing).
fn problems(what: &str, lang: Lang, text: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut complain = |why: &str| found.push(format!("{what} ({lang}): {why}: {text:?}"));
    if text.is_empty() {
        complain("empty");
    }
    if text.contains("  ") {
        complain("a run of spaces");
    }
    if text.trim() != text {
        complain("leading or trailing whitespace");
    }
    if text.contains(['\n', '\r', '\t']) {
        complain("a line break or tab");
    }
    match lang {
        Lang::Ja if !text.chars().any(is_japanese_letter) => complain("no Japanese"),
        Lang::En if text.chars().any(is_japanese) => complain("Japanese in the English text"),
        _ => {}
    }
    found
}

/// Both languages' messages of `kind`.
fn kind_texts(kind: &ErrorKind) -> [(Lang, String); 2] {
    let text = kind.text();
    assert_eq!(
        [kind.describe(Lang::Ja), kind.describe(Lang::En)],
        [text.ja.as_str(), text.en.as_str()]
    );
    [(Lang::Ja, text.ja), (Lang::En, text.en)]
}

#[test]
fn every_kind_has_a_sample() {
    let mut seen = [false; KINDS];
    for kind in samples() {
        let i = kind_index(&kind);
        assert!(i < KINDS, "KINDS = {KINDS} is too small for {kind:?}");
        seen[i] = true;
    }
    let missing: Vec<usize> = (0..KINDS).filter(|&i| !seen[i]).collect();
    assert!(missing.is_empty(), "variants without a sample (kind_index): {missing:?}");
}

#[test]
fn every_message_is_one_clean_line_in_each_language() {
    let mut found = Vec::new();
    for kind in samples() {
        for (lang, text) in kind_texts(&kind) {
            found.extend(problems(&format!("{kind:?}"), lang, &text));
        }
    }
    assert!(found.is_empty(), "{} problems:\n{}", found.len(), found.join("\n"));
}

#[test]
fn japanese_and_english_messages_differ() {
    for kind in samples() {
        let [(_, ja), (_, en)] = kind_texts(&kind);
        assert_ne!(ja, en, "{kind:?}");
    }
}

#[test]
fn rules_expected_and_found_read_cleanly_alone() {
    let mut found = Vec::new();
    let mut check = |what: String, ja: String, en: String| {
        found.extend(problems(&what, Lang::En, &en));
        // A notation (`[kc, kl, kq]`) reads the same in both languages.
        let notation = ja == en && ja.starts_with('[');
        found.extend(problems(&what, if notation { Lang::En } else { Lang::Ja }, &ja));
    };
    for rule in all_rules() {
        let [ja, en] = rule_texts(rule);
        check(format!("{rule:?}"), ja, en);
    }
    for expected in all_expected() {
        let [ja, en] = expected_texts(expected);
        check(format!("{expected:?}"), ja, en);
    }
    for f in all_found() {
        let [ja, en] = found_texts(f);
        check(format!("{f:?}"), ja, en);
    }
    assert!(found.is_empty(), "{} problems:\n{}", found.len(), found.join("\n"));
}

fn rule_texts(rule: Rule) -> [String; 2] {
    let text = rule.text();
    [text.ja, text.en]
}

fn expected_texts(e: Expected) -> [String; 2] {
    let text = e.text();
    [text.ja, text.en]
}

fn found_texts(f: Found) -> [String; 2] {
    let text = f.text();
    [text.ja, text.en]
}

#[test]
fn the_full_message_names_the_file_the_place_and_the_key() {
    for kind in samples() {
        let with_all = SceneError {
            file: PathBuf::from("scenes/x.toml"),
            position: Some(Position { line: 23, column: 9 }),
            key: Some("objects[1].shape.radius".into()),
            kind: Box::new(kind.clone()),
        };
        let file_only = SceneError { position: None, key: None, ..with_all.clone() };
        for (lang, text) in kind_texts(&kind) {
            let full = with_all.describe(lang);
            assert_eq!(full, format!("scenes/x.toml:23:9: objects[1].shape.radius: {text}"));
            assert!(problems("full", lang, &full).is_empty(), "{full:?}");
            assert_eq!(file_only.describe(lang), format!("scenes/x.toml: {text}"));
        }
        assert_eq!(with_all.to_string(), with_all.describe(Lang::En));
    }
}

#[test]
fn reflectance_sum_reads_as_one_sentence() {
    let kind = ErrorKind::ReflectanceSum { channel: 2, kr: 0.5, kt: 0.75 };
    let [(_, ja), (_, en)] = kind_texts(&kind);
    assert!(!ja.contains("  "), "{ja:?}");
    assert!(!en.contains("  "), "{en:?}");
    assert_eq!(
        en,
        "kr + kt is 0.5 + 0.75 = 1.25 in channel b: it must be at most 1 (energy conservation: a \
         surface cannot reflect and transmit more light than reaches it, and the ray tracer's \
         reflected and refracted rays would multiply without bound)"
    );
    assert_eq!(
        ja,
        "kr + kt が b 成分で 0.5 + 0.75 = 1.25 です。1 以下にしてください（エネルギー保存: \
         面が反射・透過する光は届いた光を超えられません。超えるとレイトレーシングの反射・屈折レイが\
         際限なく増えます）"
    );
}
