//! The Japanese text of the mesh, shape and normals errors is Japanese throughout: it used to
//! embed the English `Display` text (`メッシュが使えません: vertex V4 has a non-finite position …`,
//! `grid の divisions = 5000 は範囲外です（an integer in 1..=4096）`).

use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_core::mesh::MeshError;
use cg_core::normals::{NormalsError, prepare_normals};
use cg_core::scene::NormalSource;
use cg_core::shapes::{Allowed, ShapeError, grid, lecture_pyramid, torus, uv_sphere};

use cg_testkit::text::english_fragments;

/// The Japanese message has no English fragment, and the English one does (so the check above
/// would catch the English text embedded in the Japanese one).
#[track_caller]
fn assert_japanese(ja: &str, en: &str) {
    assert!(ja.chars().any(|c| ('\u{3040}'..='\u{30ff}').contains(&c)), "no kana in {ja}");
    assert_eq!(english_fragments(ja), Vec::<String>::new(), "English inside: {ja}");
    assert!(!english_fragments(en).is_empty(), "premise: the checker sees English in {en}");
}

#[test]
fn mesh_errors_read_in_japanese() {
    let cases = [
        MeshError::IndexOutOfRange { face: 6, corner: 2, index: 9, vertex_count: 5 },
        MeshError::IndexOutOfRange { face: 0, corner: 0, index: 0, vertex_count: 0 },
        MeshError::AttributeLength { attribute: "uvs", len: 3, expected: 8 },
        MeshError::NonFinitePosition { vertex: 0, position: Vec3::new(f32::NAN, 0.0, 0.0) },
    ];
    for e in &cases {
        assert_japanese(&e.message(Lang::Ja), &e.message(Lang::En));
        assert_eq!(e.to_string(), e.message(Lang::En));
    }
    // The lecture's notation, in both languages.
    assert_eq!(
        cases[0].to_string(),
        "face F6 corner 2 refers to V9, but the mesh has only 5 vertices, V0–V4"
    );
    assert_eq!(
        cases[0].message(Lang::Ja),
        "面 F6 の頂点番号 V9（0 から数えて 2 番目）は存在しません（頂点は V0–V4 の 5 個です）"
    );
    assert!(cases[3].message(Lang::Ja).contains("頂点 V0 の座標 (NaN, 0, 0)"));
}

#[test]
fn shape_errors_read_in_japanese_with_a_structured_range() {
    let e = grid(5000, 1.0).unwrap_err();
    assert_eq!(e.expected, Allowed::Count { min: 1, max: 4096 });
    assert_eq!(e.to_string(), "grid: divisions = 5000 is out of range (an integer in 1..=4096)");
    assert_eq!(
        e.message(Lang::Ja),
        "grid の divisions = 5000 は範囲外です（1 以上 4096 以下の整数でなければなりません）"
    );

    let cases: [ShapeError; 4] = [
        e,
        uv_sphere(-1.0, 8, 4).unwrap_err(),
        uv_sphere(1.0, 8, 1).unwrap_err(),
        torus(1.0, 2.0, 8, 8).unwrap_err(),
    ];
    assert_eq!(cases[1].expected, Allowed::Positive);
    assert_eq!(cases[2].expected, Allowed::Count { min: 2, max: 4096 });
    assert_eq!(cases[3].expected, Allowed::PositiveBelow { other: "major" });
    assert!(cases[3].to_string().ends_with("(finite, > 0 and < major)"), "{}", cases[3]);
    for e in &cases {
        assert_japanese(&e.message(Lang::Ja), &e.message(Lang::En));
        assert_eq!(e.to_string(), e.message(Lang::En));
    }
}

#[test]
fn normals_errors_read_in_japanese() {
    let mut broken = lecture_pyramid();
    broken.positions[4] = Vec3::new(f32::NAN, 0.0, 0.0);
    let e = prepare_normals(&broken, NormalSource::Face).unwrap_err();
    assert!(matches!(e, NormalsError::Mesh(MeshError::NonFinitePosition { vertex: 4, .. })));
    let ja = e.message(Lang::Ja);
    assert!(
        ja.ends_with(
            &MeshError::NonFinitePosition { vertex: 4, position: broken.positions[4] }
                .message(Lang::Ja)
        )
    );

    let mut unusable = lecture_pyramid();
    unusable.normals = Some(vec![Vec3::ZERO; 5]);
    let cases =
        [e, NormalsError::Missing, prepare_normals(&unusable, NormalSource::Given).unwrap_err()];
    for e in &cases {
        assert_japanese(&e.message(Lang::Ja), &e.message(Lang::En));
    }
}
