//! OBJ models and PNG textures: what loads, what is kept, and what each broken file says.

use std::path::{Path, PathBuf};

use cg_core::glam::{Vec2, Vec3};
use cg_core::lang::Lang;
use cg_scene::{ErrorKind, SceneError, load_obj, load_texture, parse_obj};

/// A fresh folder for this test's files.
fn folder(test: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("cg-scene-files").join(test);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn obj_error(text: &str) -> SceneError {
    parse_obj(text, Path::new("model.obj")).expect_err(text)
}

/// A unit square in y = 0 facing +Y, as a quad with texture coordinates and normals.
const QUAD: &str = "\
v 0 0 0
v 1 0 0
v 1 0 -1
v 0 0 -1
vt 0 0
vt 1 0
vt 1 1
vt 0 1
vn 0 2 0
f 1/1/1 2/2/1 3/3/1 4/4/1
";

#[test]
fn quads_are_split_and_attributes_kept() {
    let m = parse_obj(QUAD, Path::new("quad.obj")).unwrap();
    assert_eq!(m.positions, [Vec3::ZERO, Vec3::X, Vec3::new(1.0, 0.0, -1.0), Vec3::NEG_Z]);
    // A fan from the first corner, counter-clockwise as written.
    assert_eq!(m.faces, [[0, 1, 2], [0, 2, 3]]);
    assert_eq!(m.uvs.as_deref(), Some(&[Vec2::ZERO, Vec2::X, Vec2::ONE, Vec2::Y][..]));
    // Normals come back unit length.
    assert_eq!(m.normals.as_deref(), Some(&[Vec3::Y; 4][..]));
    m.check_indices().unwrap();
}

#[test]
fn points_and_lines_are_not_surfaces() {
    // A wire outline of four points (`l`), points (`p`), and one triangle: only the triangle,
    // and only its vertices (tobj alone makes the outline a filled quad).
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nl 1 2 3 4\np 1 2 3\nl 1 3\nf 2 3 5\n";
    let m = parse_obj(text, Path::new("wire.obj")).unwrap();
    assert_eq!(m.positions, [Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Z]);
    assert_eq!(m.faces, [[0, 1, 2]]);
    m.check_indices().unwrap();
    // Only lines and points: no surface, as a file without faces.
    let e = parse_obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3 1\n", Path::new("wire.obj")).unwrap_err();
    assert!(matches!(*e.kind, cg_scene::ErrorKind::ObjNoFaces), "{e}");
}

#[test]
fn groups_merge_into_one_mesh_in_the_files_vertex_order() {
    // Two groups whose faces use the vertices out of order; the second reuses vertex 1.
    let text = "\
o first
v 0 0 0
v 1 0 0
v 0 1 0
v 0 0 1
f 3 1 2
o second
f 4 1 3
";
    let m = parse_obj(text, Path::new("two.obj")).unwrap();
    // File vertices 1 and 3 are used by both groups: they appear once per group, both copies
    // where their `v` line puts them.
    assert_eq!(m.positions, [Vec3::ZERO, Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Y, Vec3::Z]);
    let triangles: Vec<[Vec3; 3]> = (0..m.face_count()).map(|f| m.triangle(f)).collect();
    assert_eq!(triangles, [[Vec3::Y, Vec3::ZERO, Vec3::X], [Vec3::Z, Vec3::ZERO, Vec3::Y]]);
    assert_eq!(m.normals, None);
    assert_eq!(m.uvs, None);

    // One position with two texture coordinates becomes two vertices, next to each other.
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\nf 1/1 2/2 3/3\nf 1/4 3/3 2/2\n";
    let m = parse_obj(text, Path::new("seam.obj")).unwrap();
    assert_eq!(m.positions, [Vec3::ZERO, Vec3::ZERO, Vec3::X, Vec3::Y]);
    assert_eq!(m.uvs.unwrap()[..2], [Vec2::ZERO, Vec2::splat(0.5)]);
    assert_eq!(m.faces, [[0, 2, 3], [1, 3, 2]]);
}

#[test]
fn negative_indices_count_back() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n";
    let m = parse_obj(text, Path::new("relative.obj")).unwrap();
    assert_eq!(m.faces, [[0, 1, 2]]);
}

#[test]
fn face_indices_out_of_range_are_errors_naming_the_line() {
    let cases = [
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", 4, 7, "v", 9, 3),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 2 3\n", 4, 3, "v", -4, 3),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, 3, "v", 0, 3),
        // Negative indices count only what came before the face.
        ("v 0 0 0\nv 1 0 0\nf 1 2 -3\nv 0 1 0\n", 3, 7, "v", -3, 2),
        // Texture coordinates and normals are checked too, even when the file has none.
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n", 5, 8, "vn", 2, 1),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n", 4, 3, "vt", 1, 0),
        // Huge numbers: tobj 4.0.5 alone panics on this one in debug builds (`vn * 3` overflows).
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//9223372036854775807 2//1 3//1\n",
            5,
            3,
            "vn",
            i64::MAX,
            1,
        ),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9223372036854775807\n", 4, 7, "v", i64::MAX, 3),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/-9223372036854775808 2 3\n", 4, 3, "vt", i64::MIN, 0),
        // Points and lines are dropped, but their indices are still checked.
        ("v 0 0 0\nl 1 5\n", 2, 5, "v", 5, 1),
    ];
    for (text, line, column, element, index, count) in cases {
        let e = obj_error(text);
        assert_eq!(*e.kind, ErrorKind::ObjIndex { element, index, count }, "{text}");
        assert_eq!(e.position.map(|p| (p.line, p.column)), Some((line, column)), "{text}");
        let message = e.to_string();
        assert!(message.starts_with(&format!("model.obj:{line}:{column}: ")), "{e}");
        assert!(message.len() < 400, "a message stays short: {} bytes", message.len());
        assert!(!message.contains('\u{200B}'), "invisible characters are named: {message}");
    }
}

#[test]
fn malformed_obj_files_say_what_is_wrong() {
    assert_eq!(*obj_error("v 0 0 0\nv 1 0 0\n").kind, ErrorKind::ObjNoFaces);
    assert_eq!(*obj_error("").kind, ErrorKind::ObjNoFaces);
    assert_eq!(*obj_error("v 0 0 0\nf 1 1\n").kind, ErrorKind::ObjNoFaces, "a line is not a face");
    // Normals on some faces only: at the first face written otherwise, with the first face's
    // line (it was "some face corners have vn and others do not", with no line).
    let e = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n");
    assert_eq!(*e.kind, ErrorKind::ObjFaceForm { element: "vn", has: false, first_line: 6 });
    assert_eq!(e.position.map(|p| (p.line, p.column)), Some((7, 3)), "{e}");
    assert!(e.to_string().contains("but the first face (line 6) has one"), "{e}");
    assert!(e.describe(Lang::Ja).contains("6 行目の（最初の）面にはあります"), "{e}");
    let e = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\nf 1/1 2/1 3/1\n");
    assert_eq!(*e.kind, ErrorKind::ObjFaceForm { element: "vt", has: true, first_line: 5 });
    // Values that parse but cannot be used: a normal with no direction, at its line and word
    // (it was "vertex V0 has a zero normal", with no line).
    let e = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n");
    assert_eq!(*e.kind, ErrorKind::ObjZeroNormal);
    assert_eq!(e.position.map(|p| (p.line, p.column)), Some((4, 4)), "{e}");
    assert!(e.to_string().starts_with("model.obj:4:4: "), "{e}");
}

/// What tobj alone makes of `text`: its error has no line (and sometimes names the wrong cause).
fn tobj_alone(text: &str) -> Result<usize, tobj::LoadError> {
    let options = tobj::LoadOptions { triangulate: true, single_index: true, ..Default::default() };
    let (models, _) =
        tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| Ok(Default::default()))?;
    Ok(models.len())
}

#[test]
fn lines_tobj_rejects_are_named_with_their_line_and_column() {
    const TRI: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    // (text, line, column, what is wrong)
    let cases: Vec<(String, usize, usize, ErrorKind)> = vec![
        // An index too large for any file: tobj says "face parse error".
        (
            format!("{TRI}f 1 2 99999999999999999999\n"),
            4,
            7,
            ErrorKind::ObjNumber { element: "f", word: "99999999999999999999".into() },
        ),
        (format!("{TRI}f 1 2 x\n"), 4, 7, ErrorKind::ObjNumber { element: "f", word: "x".into() }),
        (
            format!("{TRI}f 1/x 2 3\n"),
            4,
            5,
            ErrorKind::ObjNumber { element: "f", word: "x".into() },
        ),
        (format!("{TRI}l 1 y\n"), 4, 5, ErrorKind::ObjNumber { element: "l", word: "y".into() }),
        // Too few coordinates: tobj says "position parse error".
        (
            "v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n".into(),
            1,
            1,
            ErrorKind::ObjValues { element: "v", found: 2 },
        ),
        (
            "v 0 0 0\nv 1 0 x\nv 0 1 0\nf 1 2 3\n".into(),
            2,
            7,
            ErrorKind::ObjNumber { element: "v", word: "x".into() },
        ),
        (
            format!("{TRI}vt 0.5\nf 1/1 2/1 3/1\n"),
            4,
            1,
            ErrorKind::ObjValues { element: "vt", found: 1 },
        ),
        (
            format!("{TRI}vn 0 0 z\nf 1//1 2//1 3//1\n"),
            4,
            8,
            ErrorKind::ObjNumber { element: "vn", word: "z".into() },
        ),
        // x y z w r? tobj: "color parse error".
        (
            format!("{TRI}v 0 0 0 1 1\nf 1 2 3\n"),
            4,
            1,
            ErrorKind::ObjValues { element: "v", found: 5 },
        ),
        // Positions at infinity.
        (
            format!("{TRI}v 1 2 3 0\nf 1 2 3\n"),
            4,
            3,
            ErrorKind::ObjPosition {
                position: [f32::INFINITY, f32::INFINITY, f32::INFINITY],
                w: 0.0,
            },
        ),
        (
            "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n".into(),
            2,
            3,
            ErrorKind::ObjNumber { element: "v", word: "inf".into() },
        ),
        // A NaN texture coordinate or normal is named at its word, with its line.
        (
            format!("{TRI}vt 0 nan\nf 1/1 2/1 3/1\n"),
            4,
            6,
            ErrorKind::ObjNumber { element: "vt", word: "nan".into() },
        ),
        (
            format!("{TRI}vn 0 1e39 0\nf 1//1 2//1 3//1\n"),
            4,
            6,
            ErrorKind::ObjNumber { element: "vn", word: "1e39".into() },
        ),
        // A huge word is cut short in the message, and an invisible character is named.
        (
            format!("{TRI}v 0 {} 0\n", "9".repeat(100_000) + "x"),
            4,
            5,
            ErrorKind::ObjNumber { element: "v", word: "9".repeat(100_000) + "x" },
        ),
        (
            format!("{TRI}f 1 2 3\u{200B}\n"),
            4,
            7,
            ErrorKind::ObjNumber { element: "f", word: "3\u{200B}".into() },
        ),
        // 1e30 / 1e-30 overflows f32, as tobj computes it.
        (
            format!("{TRI}v 1e30 0 0 1e-30\nf 1 2 3\n"),
            4,
            3,
            ErrorKind::ObjPosition { position: [f32::INFINITY, 0.0, 0.0], w: 1e-30 },
        ),
        // Corners that are not v, v/vt, v//vn or v/vt/vn.
        (
            format!("{TRI}vt 0 0\nvn 0 0 1\nf 1/1/1/1 2/1/1 3/1/1\n"),
            6,
            3,
            ErrorKind::ObjCorner { corner: "1/1/1/1".into() },
        ),
        (format!("{TRI}f /1 2 3\n"), 4, 3, ErrorKind::ObjCorner { corner: "/1".into() }),
        (format!("{TRI}f\n"), 4, 1, ErrorKind::ObjValues { element: "f", found: 0 }),
        // A face referring forward, past an `o` line: tobj says "face vertex index out of bounds".
        (
            "o first\nv 0 0 0\nv 1 0 0\nf 1 2 3\no second\nv 0 1 0\n".into(),
            4,
            7,
            ErrorKind::ObjIndex { element: "v", index: 3, count: 2 },
        ),
        // A normal referred to forward across `o`: tobj drops it from the first group, and the
        // loader used to say "some face corners have vn and others do not".
        (
            format!("{TRI}o first\nf 1//1 2//1 3//1\no second\nvn 0 0 1\nf 1//1 2//1 3//1\n"),
            5,
            3,
            ErrorKind::ObjIndex { element: "vn", index: 1, count: 0 },
        ),
        // Forward within one group is an error too (indices count what the lines before define).
        (
            "v 0 0 0\nv 1 0 0\nf 1 2 3\nv 0 1 0\n".into(),
            3,
            7,
            ErrorKind::ObjIndex { element: "v", index: 3, count: 2 },
        ),
    ];
    for (text, line, column, kind) in cases {
        let e = obj_error(&text);
        assert_eq!(*e.kind, kind, "{text}");
        assert_eq!(e.position.map(|p| (p.line, p.column)), Some((line, column)), "{text}");
        let message = e.to_string();
        assert!(message.starts_with(&format!("model.obj:{line}:{column}: ")), "{e}");
        assert!(message.len() < 400, "a message stays short: {} bytes", message.len());
        assert!(!message.contains('\u{200B}'), "invisible characters are named: {message}");
        let ja = e.describe(Lang::Ja);
        assert!(ja.starts_with(&format!("model.obj:{line}:{column}: ")), "{ja}");
        assert!(ja.chars().any(|c| ('\u{3040}'..='\u{30ff}').contains(&c)), "{ja}");
    }

    // The premise: tobj alone names no line for these, or the wrong cause.
    let forward = "o first\nv 0 0 0\nv 1 0 0\nf 1 2 3\no second\nv 0 1 0\n";
    assert_eq!(tobj_alone(forward), Err(tobj::LoadError::FaceVertexOutOfBounds));
    assert_eq!(
        tobj_alone(&format!("{TRI}f 1 2 99999999999999999999\n")),
        Err(tobj::LoadError::FaceParseError)
    );
    assert_eq!(
        tobj_alone("v 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
        Err(tobj::LoadError::PositionParseError)
    );
    let normal_forward =
        format!("{TRI}o first\nf 1//1 2//1 3//1\no second\nvn 0 0 1\nf 1//1 2//1 3//1\n");
    assert_eq!(
        tobj_alone(&normal_forward),
        Ok(2),
        "tobj loads it, the first group without normals"
    );
}

/// Checks that `e` is `kind` at `line` and `column` of model.obj, and that both languages name
/// the place and `word`.
#[track_caller]
fn assert_named(e: &SceneError, kind: &ErrorKind, line: usize, column: usize, word: &str) {
    assert_eq!(*e.kind, *kind, "{e}");
    assert_eq!(e.position.map(|p| (p.line, p.column)), Some((line, column)), "{e}");
    for message in [e.describe(Lang::En), e.describe(Lang::Ja)] {
        assert!(message.starts_with(&format!("model.obj:{line}:{column}: ")), "{message}");
        assert!(message.contains(&format!("`{word}`")), "{message}");
    }
}

#[test]
fn face_corners_written_unlike_the_first_are_named() {
    // Some corners with a normal or texture coordinate and others without, in one face: tobj
    // loads it with normals for some vertices only, and the loader said "some face corners have
    // vn and others do not", with no line.
    const TRI: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    let cases = [
        ("f 1//1 2//1 3", 13, "3", "1//1", "vn", false),
        ("f 1/1 2/1 3", 11, "3", "1/1", "vt", false),
        ("f 1 2//1 3//1", 5, "2//1", "1", "vn", true),
        ("f 1/1/1 2/1/1 3//1", 15, "3//1", "1/1/1", "vt", false),
    ];
    for (face, column, corner, first, element, has) in cases {
        let e = obj_error(&format!("{TRI}{face}\n"));
        let kind =
            ErrorKind::ObjCornerForm { corner: corner.into(), first: first.into(), element, has };
        assert_named(&e, &kind, 6, column, corner);
        assert!(e.to_string().contains(&format!("first corner `{first}`")), "{e}");
    }
    // The premise: tobj alone loads the first.
    assert_eq!(tobj_alone(&format!("{TRI}f 1//1 2//1 3\n")), Ok(1));
}

#[test]
fn a_face_that_uses_a_vertex_twice_is_named() {
    const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 1\n";
    // The corner that comes again, with the `v` it uses and the corner that used it first.
    let cases = [
        // A square gone round twice: it was accepted, each triangle drawn twice.
        ("f 1 2 3 4 1 2 3 4", 11, "1", 1, 1),
        ("f 1 2 3 -3", 9, "-3", 2, 2),
        // The same `v` with another `vt` is still the same vertex.
        ("f 1/1 2/1 3/1 4/1 2/2", 19, "2/2", 2, 2),
        ("f 1 1 2", 5, "1", 1, 1),
    ];
    for (face, column, corner, vertex, first) in cases {
        let e = obj_error(&format!("{SQUARE}{face}\n"));
        let kind = ErrorKind::ObjRepeatedVertex { corner: corner.into(), vertex, first };
        assert_named(&e, &kind, 7, column, corner);
        assert!(e.to_string().contains(&format!("v number {vertex}")), "{e}");
    }
    // Two `v` lines at one place are two vertices: a corner on top of another is accepted, as
    // before (its triangle has no area), and so is a face of fewer than three corners (dropped).
    let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nf 1 2 3 4\nf 1 1\n";
    assert_eq!(parse_obj(text, Path::new("model.obj")).unwrap().face_count(), 2);
}

#[test]
fn vertex_colours_are_read_and_ignored() {
    // `v x y z r g b` on some lines and `v x y z` (or `v x y z w`) on others: tobj refused the
    // file ("face vertex color index out of bounds", no line). The kit uses no vertex colours.
    let text = "v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 1 0\nv 0 0 2 2\nl 1 2\nf 1 2 3\nf 1 2 4\n";
    assert_eq!(tobj_alone(text), Err(tobj::LoadError::FaceColorOutOfBounds));
    let m = parse_obj(text, Path::new("model.obj")).unwrap();
    assert_eq!(m.positions, [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z]);
    assert_eq!(m.faces, [[0, 1, 2], [0, 1, 3]]);
    // Plain lines first, then coloured ones.
    let text = "v 0 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n";
    assert_eq!(tobj_alone(text), Err(tobj::LoadError::FaceColorOutOfBounds));
    let m = parse_obj(text, Path::new("model.obj")).unwrap();
    assert_eq!(m.positions, [Vec3::ZERO, Vec3::X, Vec3::Y]);
    // Every line coloured: loaded as before.
    let text = "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n";
    assert_eq!(parse_obj(text, Path::new("model.obj")).unwrap().faces, [[0, 1, 2]]);
}

#[test]
fn missing_obj_file_is_named() {
    let dir = folder("missing_obj");
    let path = dir.join("nowhere.obj");
    let e = load_obj(&path).unwrap_err();
    assert_eq!(e.file, path);
    assert!(matches!(*e.kind, ErrorKind::Read { .. }));
    assert!(e.to_string().contains("nowhere.obj: cannot read the file"), "{e}");
}

#[test]
fn missing_or_broken_mtl_files_do_not_stop_the_model() {
    let dir = folder("mtl");
    let body = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n";
    std::fs::write(dir.join("missing.obj"), format!("mtllib nowhere.mtl\n{body}")).unwrap();
    std::fs::write(dir.join("broken.mtl"), "newmtl red\nKd 1 x\n\u{0}\u{1}garbage\n").unwrap();
    std::fs::write(dir.join("broken.obj"), format!("mtllib broken.mtl\n{body}")).unwrap();
    for name in ["missing.obj", "broken.obj"] {
        let m = load_obj(&dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(m.face_count(), 1, "{name}");
    }
}

#[test]
fn scene_names_the_obj_error_inside_the_model_file() {
    let dir = folder("scene_obj");
    std::fs::write(dir.join("bad.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n").unwrap();
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, "format = 1\n[[objects]]\nname = \"m\"\nmesh = \"bad.obj\"\n").unwrap();
    let e = cg_scene::load(&scene).unwrap_err();
    assert_eq!((e.position.unwrap().line, e.key.as_deref()), (4, Some("objects[0].mesh")));
    let ErrorKind::File(inner) = &*e.kind else { panic!("{e}") };
    assert_eq!(inner.file, dir.join("bad.obj"));
    assert_eq!(inner.position.map(|p| p.line), Some(4));
    let shown = e.to_string();
    assert!(
        shown.contains("scene.toml:4:8: objects[0].mesh: ") && shown.contains("bad.obj:4:7: "),
        "{shown}"
    );
}

/// A cube stored as six separate quads, each with its own four `v` lines, as exporters that split
/// vertices at every hard edge write it: 24 vertices where 8 positions are meant (docs/numerics.md row 3).
fn split_cube_obj() -> String {
    let corner = |i: u32| [(i & 1) as f32, ((i >> 1) & 1) as f32, ((i >> 2) & 1) as f32];
    // Corners of each face, counter-clockwise seen from outside (bit 0 = x, 1 = y, 2 = z).
    let faces =
        [[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]];
    let mut text = String::new();
    for (f, quad) in faces.iter().enumerate() {
        for &c in quad {
            let [x, y, z] = corner(c);
            text += &format!("v {x} {y} {z}\n");
        }
        let b = 4 * f + 1;
        text += &format!("f {} {} {} {}\n", b, b + 1, b + 2, b + 3);
    }
    text
}

#[test]
fn weld_merges_split_vertices_and_the_scene_records_it() {
    let dir = folder("weld");
    std::fs::write(dir.join("cube.obj"), split_cube_obj()).unwrap();
    let scene_with = |weld: &str| {
        let path = dir.join("scene.toml");
        let text =
            format!("format = 1\n[[objects]]\nname = \"cube\"\nmesh = \"cube.obj\"\n{weld}\n");
        std::fs::write(&path, text).unwrap();
        cg_scene::load(&path)
    };
    // Not welded: every face is an island, so the cube is open along all 12 edges (twice).
    let plain = scene_with("").unwrap();
    let o = &plain.objects[0];
    assert_eq!((o.mesh.vertex_count(), o.weld), (24, None));
    assert!(!o.mesh.validate().is_closed());
    assert_eq!(scene_with("weld = false").unwrap().objects[0].weld, None);
    // Welded exactly: 8 corners, closed, and the scene says what welding did.
    for key in ["weld = true", "weld = 0", "weld = 1e-4"] {
        let s = scene_with(key).unwrap();
        let o = &s.objects[0];
        assert_eq!(o.mesh.vertex_count(), 8, "{key}");
        assert!(o.mesh.validate().is_clean(), "{key}: {:?}", o.mesh.validate().problems());
        let record = o.weld.unwrap_or_else(|| panic!("{key}: no weld record"));
        assert_eq!((record.merged_vertices, record.removed_faces), (16, 0), "{key}");
    }
    // Mistakes name line 5, the key and what is allowed.
    for (key, needle) in [("weld = -1", "weld"), ("weld = \"yes\"", "true, false or a distance")] {
        let e = scene_with(key).unwrap_err();
        assert_eq!(e.position.map(|p| p.line), Some(5), "{key}: {e}");
        assert_eq!(e.key.as_deref(), Some("objects[0].weld"), "{key}: {e}");
        assert!(e.to_string().contains(needle), "{key}: {e}");
    }
}

/// A weld that makes a texture seam's two vertices one (their `vt` differ) on a textured object,
/// or a hard edge's (their `vn` differ) with `normals = "given"`: an error at `weld`; it kept the
/// first vertex's coordinates and squeezed the texture into the seam's column, with exit 0.
/// Without the texture (or with the kit's own normals) the seam is welded as before.
#[test]
fn a_weld_that_would_join_a_seam_is_an_error() {
    let dir = folder("weld-seam");
    std::fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/textures/orientation.png"),
        dir.join("t.png"),
    )
    .unwrap();
    // Two triangles side by side whose shared edge is a seam: V1 and V2 at the same place as
    // V3 and V5, with other texture coordinates and normals.
    let obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 1 0 0\nv 2 0 0\nv 1 1 0\n\
               vt 0 0\nvt 1 0\nvt 1 1\nvt 0 0\nvt 1 0\nvt 0 1\n\
               vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 1 0\nvn 0 0 1\nvn 0 0 1\n\
               f 1/1/1 2/2/2 3/3/3\nf 4/4/4 5/5/5 6/6/6\n";
    std::fs::write(dir.join("m.obj"), obj).unwrap();
    let scene_with = |extra: &str| {
        let path = dir.join("scene.toml");
        let text = format!(
            "format = 1\n[[objects]]\nname = \"m\"\nmesh = \"m.obj\"\nweld = true\n{extra}\n"
        );
        std::fs::write(&path, text).unwrap();
        cg_scene::load(&path)
    };
    for (extra, said) in [
        ("texture = { image = \"t.png\" }", "texture coordinates differ"),
        ("normals = \"given\"", "normals (normals = \"given\") differ"),
    ] {
        let e = scene_with(extra).unwrap_err();
        assert_eq!(e.key.as_deref(), Some("objects[0].weld"), "{extra}: {e}");
        assert_eq!(e.position.map(|p| p.line), Some(5), "{extra}: {e}");
        assert!(e.to_string().contains(said) && e.to_string().contains("V3 into V1"), "{e}");
        assert!(e.describe(cg_core::lang::Lang::Ja).contains("1 つの頂点では保てません"));
    }
    // Neither: welded, as a seam is for smooth shading.
    let s = scene_with("").unwrap();
    assert_eq!(s.objects[0].weld.map(|w| w.merged_vertices), Some(2));
}

#[test]
fn a_weld_that_removes_faces_of_a_built_in_shape_leaves_no_exact_surface() {
    let scene = |weld: &str| {
        let text = format!(
            "format = 1\n[[objects]]\nname = \"ground\"\nshape = {{ kind = \"grid\", divisions = 10, size = 10.0 }}\n{weld}\n"
        );
        cg_scene::parse(&text, Path::new("scene.toml")).unwrap()
    };
    let plane = Some(cg_core::scene::Analytic::Plane { size: 10.0 });
    // Welded without losing a face: still the exact plane (the ray tracer intersects it).
    for weld in ["", "weld = true", "weld = 0.5"] {
        let s = scene(weld);
        assert_eq!(s.objects[0].analytic, plane, "{weld}");
    }
    // A tolerance as long as the squares' sides collapses faces: the mesh has holes, and the
    // tracer must draw that mesh as the rasterizers do, not the whole plane.
    let s = scene("weld = 1");
    let record = s.objects[0].weld.expect("welded");
    assert!(record.removed_faces > 0, "{record:?}");
    assert_eq!(s.objects[0].analytic, None);
    // A distance that merges every face away: nothing left to draw, an error at `weld`.
    let text = "format = 1\n[[objects]]\nname = \"ground\"\nshape = { kind = \"grid\", divisions = 10, size = 10.0 }\nweld = 100\n";
    let e = cg_scene::parse(text, Path::new("scene.toml")).unwrap_err();
    assert_eq!(e.position.map(|p| p.line), Some(5), "{e}");
    assert_eq!(e.key.as_deref(), Some("objects[0].weld"), "{e}");
    assert!(matches!(*e.kind, cg_scene::ErrorKind::WeldRemovesEveryFace { faces: 200, .. }), "{e}");
}

/// Writes an RGBA image, rows listed top to bottom as PNG stores them.
fn write_png(path: &Path, width: u32, rows_top_down: &[[u8; 4]]) {
    let height = rows_top_down.len() as u32 / width;
    let bytes: Vec<u8> = rows_top_down.iter().flatten().copied().collect();
    image::save_buffer(path, &bytes, width, height, image::ColorType::Rgba8).unwrap();
}

#[test]
fn png_rows_are_flipped_so_row_0_is_the_bottom() {
    let dir = folder("png_flip");
    let path = dir.join("two-by-three.png");
    let (red, green, blue, white, black, grey) = (
        [255, 0, 0, 255],
        [0, 255, 0, 255],
        [0, 0, 255, 255],
        [255; 4],
        [0, 0, 0, 255],
        [9, 9, 9, 128],
    );
    // As an image: red green / blue white / black grey, the top row first.
    write_png(&path, 2, &[red, green, blue, white, black, grey]);
    let t = load_texture(&path).unwrap();
    assert_eq!((t.width, t.height), (2, 3));
    assert_eq!(t.texel(0, 2), red, "the image's top-left corner is texture coordinate (0, 1)");
    assert_eq!(t.texel(1, 2), green);
    assert_eq!(t.texel(0, 0), black, "the image's bottom-left corner is (0, 0)");
    assert_eq!(t.texel(1, 0), grey);
}

#[test]
fn png_colour_types_become_rgba8() {
    let dir = folder("png_types");
    let path = dir.join("grey.png");
    image::save_buffer(&path, &[0, 128, 255, 7], 2, 2, image::ColorType::L8).unwrap();
    let t = load_texture(&path).unwrap();
    assert_eq!(
        t.texels,
        [[255, 255, 255, 255], [7, 7, 7, 255], [0, 0, 0, 255], [128, 128, 128, 255]]
    );
    let path = dir.join("deep.png");
    let rgb16: Vec<u8> = [0xffffu16, 0x8080, 0x0000].iter().flat_map(|c| c.to_be_bytes()).collect();
    image::save_buffer(&path, &rgb16, 1, 1, image::ColorType::Rgb16).unwrap();
    assert_eq!(load_texture(&path).unwrap().texels, [[255, 128, 0, 255]]);
}

#[test]
fn broken_images_say_so_and_name_the_file() {
    let dir = folder("png_broken");
    let good = dir.join("good.png");
    write_png(&good, 4, &[[1, 2, 3, 4]; 16]);
    let bytes = std::fs::read(&good).unwrap();

    let truncated = dir.join("truncated.png");
    std::fs::write(&truncated, &bytes[..bytes.len() / 2]).unwrap();
    let e = load_texture(&truncated).unwrap_err();
    assert!(matches!(*e.kind, ErrorKind::Png { .. }), "{e}");
    assert!(
        e.to_string()
            .starts_with(&format!("{}: corrupt or truncated PNG image: ", truncated.display())),
        "{e}"
    );

    let corrupt = dir.join("corrupt.png");
    let mut flipped = bytes.clone();
    for b in &mut flipped[16..] {
        *b ^= 0x5a;
    }
    std::fs::write(&corrupt, &flipped).unwrap();
    // (The flipped header claims a size far above the limit.)
    let e = load_texture(&corrupt).unwrap_err();
    assert!(matches!(*e.kind, ErrorKind::Png { .. } | ErrorKind::PngTooLarge { .. }), "{e}");

    let not_png = dir.join("photo.png");
    std::fs::write(&not_png, b"\xff\xd8\xff\xe0\x00\x10JFIF\x00").unwrap();
    let e = load_texture(&not_png).unwrap_err();
    assert_eq!(*e.kind, ErrorKind::NotPng);
    assert!(e.to_string().starts_with(&format!("{}: not a PNG image", not_png.display())), "{e}");
    assert!(e.describe(cg_core::lang::Lang::Ja).contains("PNG 画像ではありません"));

    let e = load_texture(&dir.join("absent.png")).unwrap_err();
    assert!(matches!(*e.kind, ErrorKind::Read { .. }));

    // A bad checksum: the chunk is named by its four letters, not by a Rust debug struct.
    let mut bad_crc = bytes.clone();
    bad_crc[29] ^= 0xff; // the IHDR chunk's CRC
    let e = cg_scene::decode_png(&bad_crc, Path::new("crc.png")).unwrap_err();
    let message = e.to_string();
    assert!(matches!(*e.kind, ErrorKind::Png { .. }), "{message}");
    assert!(message.contains("IHDR") && !message.contains("ChunkType {"), "{message}");
    // The decoder's words are English: the Japanese message says so.
    let ja = e.describe(cg_core::lang::Lang::Ja);
    assert!(ja.contains("画像デコーダの英語の説明: "), "{ja}");
    // A chunk type of bytes that are no letters, one of them written `\u{1a}` with a `}` of its
    // own (the signature where the first chunk belongs): still one name, the rest of the
    // message kept.
    let mut twice = bytes[..8].to_vec();
    twice.extend(&bytes[..30]);
    let e = cg_scene::decode_png(&twice, Path::new("twice.png")).unwrap_err();
    let message = e.to_string();
    assert!(!message.contains("critical") && !message.contains("ChunkType"), "{message}");
    assert!(message.ends_with("chunk appeared before IHDR chunk"), "{message}");
}

#[test]
fn a_texture_file_is_bounded_before_it_is_read() {
    // /dev/zero never ends: the read stops at the limit instead of filling the memory.
    if Path::new("/dev/zero").exists() {
        let e = load_texture(Path::new("/dev/zero")).unwrap_err();
        assert_eq!(*e.kind, ErrorKind::FileTooLarge { size: None, limit_mib: 64 }, "{e}");
        assert!(e.to_string().contains("larger than 64 MiB"), "{e}");
        assert!(e.describe(Lang::Ja).contains("64 MiB を超えています"), "{e}");
    }
    // A sparse file larger than the limit is refused from its size, before reading.
    let dir = folder("png_size");
    let big = dir.join("big.png");
    let file = std::fs::File::create(&big).unwrap();
    file.set_len(cg_scene::MAX_PNG_FILE_BYTES + 1).unwrap();
    let e = load_texture(&big).unwrap_err();
    assert_eq!(
        *e.kind,
        ErrorKind::FileTooLarge { size: Some(cg_scene::MAX_PNG_FILE_BYTES + 1), limit_mib: 64 }
    );
}

/// CRC-32 of a PNG chunk's type and data (ISO 3309, the polynomial PNG uses), bit by bit.
fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = !0u32;
    for &b in bytes {
        crc ^= u32::from(b);
        for _ in 0..8 {
            crc = if crc & 1 == 1 { (crc >> 1) ^ 0xEDB8_8320 } else { crc >> 1 };
        }
    }
    !crc
}

/// A PNG file whose header claims `width × height` RGBA pixels, with one (empty) data chunk.
fn png_claiming(width: u32, height: u32) -> Vec<u8> {
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunk = |kind: &[u8; 4], data: &[u8]| {
        png.extend((data.len() as u32).to_be_bytes());
        let typed: Vec<u8> = kind.iter().chain(data).copied().collect();
        png.extend(&typed);
        png.extend(crc32(&typed).to_be_bytes());
    };
    let mut ihdr = [width.to_be_bytes(), height.to_be_bytes()].concat();
    ihdr.extend([8, 6, 0, 0, 0]); // 8 bits, RGBA, deflate, no filter, no interlace
    chunk(b"IHDR", &ihdr);
    chunk(b"IDAT", &[0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01]); // zlib of nothing
    chunk(b"IEND", &[]);
    png
}

#[test]
fn a_png_too_large_to_decode_says_so_with_its_size() {
    // 100 000 × 100 000 RGBA is 40 GB, far above the decoder's 512 MiB limit.
    let e =
        cg_scene::decode_png(&png_claiming(100_000, 100_000), Path::new("huge.png")).unwrap_err();
    assert_eq!(*e.kind, ErrorKind::PngTooLarge { width: 100_000, height: 100_000 });
    assert_eq!(
        e.to_string(),
        "huge.png: PNG image too large (100000×100000; a texture is at most 8192 pixels each way)"
    );
    assert_eq!(
        e.describe(Lang::Ja),
        "huge.png: PNG 画像が大きすぎます（100000×100000。テクスチャは縦横とも 8192 ピクセルまで）"
    );
    // Over the side limit one way only, and a size whose pixels fit the side limit but whose
    // header lies about the data: refused from the header, nothing decoded.
    let e = cg_scene::decode_png(&png_claiming(8193, 1), Path::new("wide.png")).unwrap_err();
    assert_eq!(*e.kind, ErrorKind::PngTooLarge { width: 8193, height: 1 });
    // Premise: the image crate reports this as a limit, not as corrupt data (its message,
    // "Memory limit exceeded", used to be shown as "corrupt or truncated PNG image").
    let raw = image::load_from_memory_with_format(
        &png_claiming(100_000, 100_000),
        image::ImageFormat::Png,
    );
    assert!(matches!(raw, Err(image::ImageError::Limits(_))), "{raw:?}");
    // The same file with a small size in its header is merely truncated (no pixel data).
    let e = cg_scene::decode_png(&png_claiming(4, 4), Path::new("small.png")).unwrap_err();
    assert!(matches!(*e.kind, ErrorKind::Png { .. }), "{e}");
}

#[test]
fn a_png_of_no_pixels_says_so_not_corrupt() {
    use cg_core::texture::TextureError;
    for (width, height) in [(0, 0), (0, 4), (4, 0)] {
        let e =
            cg_scene::decode_png(&png_claiming(width, height), Path::new("empty.png")).unwrap_err();
        assert_eq!(*e.kind, ErrorKind::Texture(TextureError::ZeroSize { width, height }));
        assert!(e.to_string().starts_with("empty.png: "), "{e}");
        assert!(!e.to_string().contains("corrupt"), "{e}");
        assert!(e.describe(Lang::Ja).contains(&format!("{width}×{height}")), "{e}");
    }
    // Premise: the decoder alone calls it a format error ("Invalid image dimensions").
    let raw = image::load_from_memory_with_format(&png_claiming(0, 0), image::ImageFormat::Png);
    assert!(matches!(raw, Err(image::ImageError::Decoding(_))), "{raw:?}");
}

#[test]
fn rendered_images_are_saved_as_png_top_row_first() {
    use cg_core::image::Image;
    let dir = folder("save_png");
    let mut image = Image::new(2, 3, Vec3::new(0.5, 0.5, 0.8));
    image.set(1, 0, Vec3::new(1.0, 0.0, 0.0)); // top right
    image.set(0, 2, Vec3::new(2.0, -1.0, 0.2)); // bottom left, clamped
    let path = dir.join("out.png");
    cg_scene::save_png(&path, &image).unwrap();
    let back = ::image::open(&path).unwrap().to_rgba8();
    assert_eq!(back.dimensions(), (2, 3));
    assert_eq!(back.get_pixel(1, 0).0, [255, 0, 0, 255], "row 0 of the PNG is the image's top");
    assert_eq!(back.get_pixel(0, 2).0, [255, 0, 51, 255]);
    assert_eq!(back.get_pixel(0, 0).0, [128, 128, 204, 255]);
    // A folder that does not exist: an error naming the file, not a panic.
    let missing = dir.join("no/such/dir/out.png");
    let e = cg_scene::save_png(&missing, &image).unwrap_err();
    assert!(matches!(*e.kind, ErrorKind::Write { .. }), "{e}");
    assert!(e.to_string().contains("out.png"), "{e}");
}
