//! End-to-end tests of `cg inspect` on the course's sample scene: the numbers the lecture's first
//! assignment asks for, derived independently here and found in the command's output.

use std::process::Output;

mod common;

fn cg(args: &[&str]) -> Output {
    common::cg(&common::root(), args)
}

fn stdout(o: &Output) -> String {
    assert!(
        o.status.success(),
        "cg failed ({}):\n{}",
        o.status,
        String::from_utf8_lossy(&o.stderr)
    );
    String::from_utf8(o.stdout.clone()).expect("utf-8 output")
}

/// The lecture's pyramid, from the slides (not from the kit).
const V: [[f64; 3]; 5] =
    [[0.0, 1.0, 0.0], [1.0, -0.8, 1.0], [1.0, -0.8, -1.0], [-1.0, -0.8, 1.0], [-1.0, -0.8, -1.0]];
const F: [[usize; 3]; 6] = [[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]];

/// normalise((Vb − Va) × (Vc − Va)) in f64, printed with 4 decimals the lecture's way.
fn expected_normal(f: [usize; 3]) -> String {
    let [a, b, c] = f.map(|i| V[i]);
    let e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let n = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    let l = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    let fmt = |x: f64| {
        let mut s = format!("{:.4}", x / l);
        while s.ends_with('0') && !s.ends_with(".0") {
            s.pop();
        }
        if s == "-0.0" { "0.0".to_owned() } else { s }
    };
    format!("{{ {}, {}, {} }}", fmt(n[0]), fmt(n[1]), fmt(n[2]))
}

#[test]
fn course_sample_prints_the_pyramid_tables_and_normals() {
    let out = stdout(&cg(&["inspect", "assets/scenes/course-sample.toml", "--lang", "en"]));
    // The issue's own number: F0's side normal (0, 0.4856, 0.8742).
    assert_eq!(expected_normal(F[0]), "{ 0.0, 0.4856, 0.8742 }");
    for (i, v) in V.iter().enumerate() {
        let line = format!("V{i} ({:.1}, {:.1}, {:.1})", v[0], v[1], v[2]);
        assert!(out.contains(&line), "vertex line {line:?} missing from:\n{out}");
    }
    for (i, f) in F.iter().enumerate() {
        let label = format!("F{i} {{ V{}, V{}, V{} }}", f[0], f[1], f[2]);
        let normal = expected_normal(*f);
        let found = out.lines().any(|l| l.contains(&label) && l.trim_end().ends_with(&normal));
        assert!(found, "face line {label} with normal {normal} missing from:\n{out}");
    }
}

#[test]
fn course_sample_prints_the_model_view_matrix_as_a_product() {
    let out = stdout(&cg(&["inspect", "--object", "pyramid", "--lang", "en"]));
    assert!(out.contains("T(0, 0, -15) · Rx(30°) · T(0, 1, 0)"), "numeric product missing:\n{out}");
    assert!(out.contains("camera_pitch"), "symbolic product missing:\n{out}");
    assert!(
        out.contains("mesh check: closed, manifold, consistent winding, orientation outward"),
        "{out}"
    );
    assert!(!out.contains("Object 1/2 \"ground\""), "--object filters:\n{out}");
}

#[test]
fn inspect_without_a_scene_inspects_the_course_sample() {
    let out = stdout(&cg(&["inspect", "--lang", "en"]));
    assert!(out.contains("Scene \"course-sample\""), "{out}");
    assert!(out.contains("ground") && out.contains("pyramid"), "{out}");
    // The ground is an open grid: 10 × 10 squares have 40 border edges, reported as what they
    // are rather than as 40 mistakes.
    assert!(out.contains("open surface: 40 border edges"), "{out}");
    assert!(!out.contains("findings"), "{out}");
}

#[test]
fn japanese_output_uses_the_lectures_terms() {
    let out = stdout(&cg(&["inspect", "--lang", "ja"]));
    for term in
        ["頂点座標", "三角面と面の法線", "モデルビュー行列", "グローシェーディング", "点光源"]
    {
        assert!(out.contains(term), "{term} missing from:\n{out}");
    }
}

#[test]
fn a_missing_scene_is_a_clear_error_not_a_panic() {
    let o = cg(&["inspect", "no/such/scene.toml", "--lang", "en"]);
    assert_eq!(o.status.code(), Some(2), "bad input: exit status 2");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("no/such/scene.toml"), "the error names the file: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn a_malformed_scene_names_the_line() {
    let dir = std::env::temp_dir().join(format!("cg-inspect-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.toml");
    std::fs::write(&path, "format = 1\nname = \"bad\"\n[window]\nwidth = \"wide\"\n").unwrap();
    let o = cg(&["inspect", path.to_str().unwrap(), "--lang", "en"]);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(o.status.code(), Some(2), "bad input: exit status 2");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad.toml:4"), "the error names file and line 4: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn an_unknown_object_lists_the_objects() {
    let o = cg(&["inspect", "--object", "teapot", "--lang", "en"]);
    assert_eq!(o.status.code(), Some(2), "bad input: exit status 2");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("teapot") && err.contains("pyramid"), "{err}");
    // The scene it was looked for in is named, in either language, and the name shown safely.
    assert!(err.contains("course-sample.toml: no object named \"teapot\""), "{err}");
    let o = cg(&["inspect", "--object", "ポット\u{1b}[2J", "--lang", "ja"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("course-sample.toml: \"ポット"), "{err}");
    assert!(err.contains("というオブジェクトはありません（あるもの: "), "{err}");
    assert!(!err.contains('\u{1b}'), "an escape sequence reaches the terminal: {err}");
}

#[test]
fn inspect_says_whether_the_mesh_was_welded() {
    let dir = std::env::temp_dir().join(format!("cg-inspect-weld-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // Two triangles of a square, each with its own copies of the shared diagonal's corners.
    std::fs::write(
        dir.join("square.obj"),
        "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 0\nv 1 0 -1\nv 0 0 -1\nf 1 2 3\nf 4 5 6\n",
    )
    .unwrap();
    let scene = |weld: &str| {
        let path = dir.join(format!("scene-{}.toml", weld.len()));
        let text =
            format!("format = 1\n[[objects]]\nname = \"sq\"\nmesh = \"square.obj\"\n{weld}\n");
        std::fs::write(&path, text).unwrap();
        stdout(&cg(&["inspect", path.to_str().unwrap(), "--lang", "en"]))
    };
    let welded = scene("weld = true");
    let plain = scene("");
    std::fs::remove_dir_all(&dir).ok();
    assert!(
        welded
            .contains("welded by position: yes, tolerance 0.0: 2 vertices merged, 0 faces removed"),
        "{welded}"
    );
    assert!(welded.contains("4 vertices, 2 faces"), "{welded}");
    assert!(plain.contains("welded by position: no"), "{plain}");
    assert!(plain.contains("6 vertices, 2 faces"), "{plain}");
}

/// The course's sample scene saved as a Japanese Windows editor saves it (Shift_JIS, with a
/// Japanese comment) reads as detected and as named with `--encoding shift_jis`; named as UTF-8
/// it is refused with its line and the advice to name its encoding.
#[test]
fn a_scene_in_shift_jis_reads_detected_and_named() {
    let dir = std::env::temp_dir().join(format!("cg-inspect-sjis-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("授業 サンプル.toml");
    let text =
        std::fs::read_to_string(common::root().join("assets/scenes/course-sample.toml")).unwrap();
    // `# 三角形のシーン` in Shift_JIS, then the scene (ASCII).
    // The sample's own comments in Japanese are UTF-8: cut off.
    let mut bytes = b"# \x8eO\x8ap\x8c`\x82\xcc\x83V\x81[\x83\x93\r\n".to_vec();
    for line in text.lines() {
        let code = if line.is_ascii() { line } else { line.split('#').next().unwrap_or("") };
        bytes.extend_from_slice(code.as_bytes());
        bytes.extend_from_slice(b"\r\n");
    }
    std::fs::write(&path, bytes).unwrap();
    let file = path.to_str().unwrap();
    let detected = stdout(&cg(&["inspect", file, "--lang", "en"]));
    let named = stdout(&cg(&["inspect", file, "--encoding", "shift_jis", "--lang", "en"]));
    assert_eq!(detected, named);
    assert!(named.contains("F0"), "{named}");
    let wrong = cg(&["inspect", file, "--encoding", "utf-8", "--lang", "en"]);
    std::fs::remove_dir_all(&dir).ok();
    assert!(!wrong.status.success());
    let err = String::from_utf8_lossy(&wrong.stderr);
    assert!(err.contains(":1") && err.contains("--encoding"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}
