use cg_core::product::{Axis, Factor, Param};
use cg_core::texture::{Sampler, Texture};

use super::*;
use crate::derive::polygon_from_data;
use crate::model::TexRow;

/// The lecture's pyramid, normals derived by the kit.
pub(crate) fn pyramid() -> PolygonData {
    let v = vec![
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(1.0, -0.8, 1.0),
        Vec3::new(1.0, -0.8, -1.0),
        Vec3::new(-1.0, -0.8, 1.0),
        Vec3::new(-1.0, -0.8, -1.0),
    ];
    let f = vec![[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]];
    polygon_from_data(Text::new("四角すい", "pyramid"), v, f, None)
}

/// The camera of the course at its start: `T(0, 0, -15) · Rx(30°)` with symbols.
pub(crate) fn camera() -> NamedMatrix {
    let product = |d: f32, pitch: f32| {
        MatrixProduct::identity()
            .then(Factor::Translate([
                Param::num(0.0),
                Param::num(0.0),
                Param::sym("-camera_distance", d),
            ]))
            .then(Factor::rotate(Axis::X, Param::sym("-camera_pitch", pitch)))
    };
    NamedMatrix {
        id: "a2.view.start".to_owned(),
        title: Text::new(
            "視点の変換行列（初期状態、100% の_距離）",
            "view matrix (start, 100% of_distance)",
        ),
        symbolic: product(-15.0, 30.0),
        numeric: MatrixProduct::identity()
            .then(Factor::translate(Vec3::new(0.0, 0.0, -15.0)))
            .then(Factor::rotate_x_deg(30.0)),
        variables: vec![(
            "camera_pitch".to_owned(),
            Text::new(
                "右ドラッグで変化、範囲 [-90, 0]、100% は_なし",
                "right drag; range [-90, 0]; 100% no_limit",
            ),
        )],
    }
}

/// The numbers of the first `\begin{pmatrix} … \end{pmatrix}` after `tag` in `text`.
pub(crate) fn tagged_matrix(text: &str, tag: &str) -> Vec<Vec<f64>> {
    let after = &text[text.find(tag).expect("tag present") + tag.len()..];
    let start =
        after.find("\\begin{pmatrix}").expect("pmatrix after the tag") + "\\begin{pmatrix}".len();
    let end = after[start..].find("\\end{pmatrix}").expect("pmatrix closed") + start;
    after[start..end]
        .split("\\\\")
        .map(|row| {
            row.split('&').map(|x| x.trim().parse::<f64>().expect("a plain number")).collect()
        })
        .collect()
}

/// Checks that `\begin{X}`/`\end{X}` pair up in order and that unescaped braces balance.
pub(crate) fn assert_balanced(tex: &str) {
    let mut stack: Vec<String> = Vec::new();
    let mut rest = tex;
    loop {
        let next = [("\\begin{", true), ("\\end{", false)]
            .into_iter()
            .filter_map(|(word, open)| rest.find(word).map(|k| (k, word, open)))
            .min_by_key(|(k, _, _)| *k);
        let Some((k, word, open)) = next else { break };
        let after = &rest[k + word.len()..];
        let end = after.find('}').expect("environment name closed");
        let name = &after[..end];
        if open {
            stack.push(name.to_owned());
        } else {
            assert_eq!(stack.pop().as_deref(), Some(name), "unbalanced \\end{{{name}}} in\n{tex}");
        }
        rest = &after[end..];
    }
    assert!(stack.is_empty(), "unclosed environments {stack:?} in\n{tex}");
    let mut depth = 0i32;
    let mut chars = tex.lines().flat_map(|l| {
        // A `%` comment line (the tags) ends at the line's end.
        let l = if l.trim_start().starts_with('%') { "" } else { l };
        l.chars().chain(std::iter::once('\n')).collect::<Vec<_>>()
    });
    while let Some(c) = chars.next() {
        match c {
            '\\' => {
                chars.next();
            }
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                assert!(depth >= 0, "a `}}` closes nothing in\n{tex}");
            }
            _ => {}
        }
    }
    assert_eq!(depth, 0, "unbalanced braces in\n{tex}");
}

/// Every `_` and `%` of `tex` is escaped, except in `% cg:` tag lines and `_{` subscripts.
fn assert_escaped(tex: &str) {
    for line in tex.lines().filter(|l| !l.starts_with("% cg: ")) {
        let b = line.as_bytes();
        for (k, &c) in b.iter().enumerate() {
            if c == b'_' || c == b'%' {
                assert!(k > 0 && b[k - 1] == b'\\', "unescaped {:?} in {line:?}", c as char);
            }
        }
    }
}

#[test]
fn the_balance_check_fails_on_broken_latex() {
    for bad in [
        "\\begin{a}\\end{b}",
        "\\begin{a}",
        "{x",
        "x}",
        "\\{x}",
        "\\begin{a}\\begin{b}\\end{a}\\end{b}",
    ] {
        assert!(std::panic::catch_unwind(|| assert_balanced(bad)).is_err(), "{bad}");
    }
    assert_balanced("\\begin{a} \\{ x \\} {y} \\\\ \n% cg: a_b {\n\\end{a}");
}

#[test]
fn numbers_have_three_decimals_and_no_negative_zero() {
    assert_eq!(fixed(0.485_643), "0.486");
    assert_eq!(fixed(-0.8), "-0.800");
    assert_eq!(fixed(1.0), "1.000");
    assert_eq!(fixed(-0.0), "0.000");
    assert_eq!(fixed(-0.000_4), "0.000");
    assert_eq!(fixed(-0.000_6), "-0.001");
    assert_eq!(fixed(f32::NAN), "NaN");
    assert_eq!(tuple2(Vec2::new(0.3, 0.5)), "(0.300, 0.500)");
}

#[test]
fn vertex_table_has_a_row_per_vertex_in_the_notation() {
    let md = vertex_table(&pyramid(), Lang::Ja, Format::Markdown);
    let lines: Vec<&str> = md.lines().collect();
    assert_eq!(lines.len(), 2 + 5, "{md}");
    assert_eq!(lines[2], "| V0 | (0.000, 1.000, 0.000) |");
    assert_eq!(lines[5], "| V3 | (-1.000, -0.800, 1.000) |");
    assert!(lines[0].contains("頂点"));
    assert!(vertex_table(&pyramid(), Lang::En, Format::Markdown).contains("| vertex |"));
}

#[test]
fn face_table_prints_the_derived_normals() {
    let md = face_table(&pyramid(), Lang::En, Format::Markdown);
    let lines: Vec<&str> = md.lines().collect();
    assert_eq!(lines.len(), 2 + 6, "{md}");
    // (V3 − V0) × (V1 − V0) = (0, 2, 3.6), /|…| = (0, 0.4856, 0.8742): not the slide's 0.53, 0.85.
    assert_eq!(lines[2], "| F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } |");
    assert_eq!(lines[4], "| F2 | { V0, V1, V2 } | { 0.874, 0.486, 0.000 } |");
    assert_eq!(lines[6], "| F4 | { V1, V3, V2 } | { 0.000, -1.000, 0.000 } |");
    assert!(!md.contains("-0.000"), "{md}");
    assert_eq!(lines[0].matches('|').count(), 4, "no note column without the student's normals");
}

#[test]
fn face_table_notes_the_students_differing_normals() {
    let mut p = pyramid();
    // The slide's table: F0–F3 do not follow from the vertices, F4 and F5 do.
    p.student_normals = Some(vec![
        Vec3::new(0.0, 0.53, 0.85),
        Vec3::new(0.0, 0.53, -0.85),
        Vec3::new(0.85, 0.53, 0.0),
        Vec3::new(-0.85, 0.53, 0.0),
        Vec3::new(0.0, -1.0, 0.0),
        Vec3::new(0.0, -1.0, 0.0),
    ]);
    let md = face_table(&p, Lang::En, Format::Markdown);
    let lines: Vec<&str> = md.lines().collect();
    assert_eq!(lines[0].matches('|').count(), 5, "{md}");
    for (k, line) in lines[2..].iter().enumerate() {
        assert_eq!(line.contains("differs"), k < 4, "F{k}: {line}");
    }
    assert!(
        lines[2].starts_with("| F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } |"),
        "{}",
        lines[2]
    );
    assert!(lines[2].contains("[0.000, 0.530, 0.850]"), "{}", lines[2]);
    let tex = face_table(&p, Lang::Ja, Format::Latex);
    assert_balanced(&tex);
    assert!(tex.contains("違います"));
}

#[test]
fn a_face_without_a_normal_says_why() {
    let mut p = pyramid();
    p.faces.push([0, 0, 1]);
    p.faces.push([0, 1, 9]);
    p.derived_normals.push(None);
    p.derived_normals.push(None);
    let md = face_table(&p, Lang::En, Format::Markdown);
    assert!(md.contains("| F6 | { V0, V0, V1 } | no normal: degenerate face"), "{md}");
    assert!(md.contains("| F7 | { V0, V1, V9 } | no normal: vertex V9 does not exist"), "{md}");
    assert_balanced(&face_table(&p, Lang::Ja, Format::Latex));
}

#[test]
fn a_matrix_shows_its_products_and_the_tagged_result() {
    let m = camera();
    let md = matrix(&m, Lang::En, Format::Markdown);
    assert!(md.contains("`T(0, 0, -camera_distance) · Rx(-camera_pitch)`"), "{md}");
    assert!(md.contains("`T(0, 0, -15) · Rx(30°)`"), "{md}");
    assert!(md.contains("\\cos(-\\mathit{camera\\_pitch})"), "{md}");
    // The tag line, then `$$`, then the result: T(0, 0, -15) · Rx(30°) by hand.
    assert!(md.contains("<!-- cg: a2.view.start -->\n$$\n= \\begin{pmatrix}"), "{md}");
    let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    let want = [[1.0, 0.0, 0.0, 0.0], [0.0, c, -s, 0.0], [0.0, s, c, -15.0], [0.0, 0.0, 0.0, 1.0]];
    let got = tagged_matrix(&md, "<!-- cg: a2.view.start -->");
    assert_eq!(got.len(), 4);
    for (r, row) in got.iter().enumerate() {
        assert_eq!(row.len(), 4);
        for (k, x) in row.iter().enumerate() {
            assert!((x - want[r][k]).abs() < 1e-4, "({r}, {k}): {x} vs {}", want[r][k]);
        }
    }
    // Each factor appears numerically before the result, after its own tag: two symbolic
    // pmatrices, the factors' tag and two numeric ones, then the result's tag.
    let factors_tag = md.find("<!-- cg: a2.view.start.factors -->").unwrap();
    let result_tag = md.find("<!-- cg: a2.view.start -->").unwrap();
    let count = |s: &str| s.matches("\\begin{pmatrix}").count();
    assert_eq!(count(&md[..factors_tag]), 2, "two symbolic factors: {md}");
    assert_eq!(count(&md[factors_tag..result_tag]), 2, "two numeric factors: {md}");
    let tex = matrix(&m, Lang::Ja, Format::Latex);
    assert_balanced(&tex);
    assert_escaped(&tex);
    assert!(tex.contains("% cg: a2.view.start\n\\[\n= \\begin{pmatrix}"), "{tex}");
    assert_eq!(tagged_matrix(&tex, "% cg: a2.view.start\n"), got);
    let both = matrices(&[m.clone(), m], Lang::En, Format::Markdown);
    assert_eq!(both.matches("<!-- cg: a2.view.start -->").count(), 2);
}

#[test]
fn long_products_wrap_in_latex_and_stay_balanced() {
    let mut m = camera();
    for k in 0..5 {
        m.numeric.push(Factor::rotate_y_deg(10.0 * k as f32));
        m.symbolic.push(Factor::rotate(Axis::Y, Param::sym(format!("yaw_{k}"), 10.0 * k as f32)));
    }
    m.numeric.push(Factor::rotate_deg(20.0, Vec3::new(1.0, 1.0, 0.0)));
    m.symbolic.push(Factor::rotate(Axis::Any(Vec3::new(1.0, 1.0, 0.0)), Param::sym("spin", 20.0)));
    let tex = matrix(&m, Lang::En, Format::Latex);
    assert_balanced(&tex);
    assert!(tex.contains("\\begin{gathered}"), "{tex}");
    assert!(tex.contains("yaw\\_3"), "{tex}");
}

#[test]
fn the_model_transform_is_tagged_a1_transform() {
    let mut p = pyramid();
    let none = transform(&p, Lang::En, Format::Markdown);
    assert!(!none.contains("cg:"), "{none}");
    assert!(none.contains("no model transform"));
    p.transform = Some(MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, 1.0, 0.0))));
    let md = transform(&p, Lang::Ja, Format::Markdown);
    let got = tagged_matrix(&md, "<!-- cg: a1.transform -->");
    assert_eq!(got[1], vec![0.0, 1.0, 0.0, 1.0], "{md}");
    assert!(!md.contains("変数を使った積"), "no symbols, no symbolic product: {md}");
    let tex = transform(&p, Lang::Ja, Format::Latex);
    assert_balanced(&tex);
    assert!(tex.contains("% cg: a1.transform"));
}

#[test]
fn names_with_underscores_and_percent_are_escaped() {
    let m = camera();
    let tex = variables(&m.variables, Lang::En, Format::Latex);
    assert_balanced(&tex);
    assert_escaped(&tex);
    assert!(tex.contains("\\texttt{camera\\_pitch}"), "{tex}");
    assert!(tex.contains("100\\% no\\_limit"), "{tex}");
    let md = variables(&m.variables, Lang::Ja, Format::Markdown);
    assert!(md.contains("| `camera_pitch` | 右ドラッグで変化"), "{md}");
    assert!(variables(&[], Lang::En, Format::Markdown).contains("no variables"));
    let tex = matrix(&m, Lang::En, Format::Latex);
    assert!(tex.contains("100\\% of\\_distance"), "{tex}");
}

pub(crate) fn texture_data() -> TextureData {
    let rows = (0..=10)
        .flat_map(|j| (0..=10).map(move |i| (i, j)))
        .map(|(i, j)| TexRow {
            i,
            j,
            position: Vec3::new(i as f32 - 5.0, 0.0, j as f32 - 5.0),
            tex: if (i, j) == (3, 5) {
                vec![Vec2::new(0.3, 0.5), Vec2::new(1.0, 0.5)]
            } else {
                vec![Vec2::new(0.25 + 0.05 * i as f32, 0.5 + 0.05 * j as f32)]
            },
        })
        .collect();
    TextureData {
        rows,
        formula: Text::new(
            "s = 0.25 + 0.05 i, t = 0.5 + 0.05 j",
            "s = 0.25 + 0.05 i, t = 0.5 + 0.05 j",
        ),
        region: (Vec2::new(0.25, 0.5), Vec2::new(0.75, 1.0)),
        image: Texture::new(200, 100, vec![[255, 255, 255, 255]; 200 * 100])
            .expect("a valid texture"),
        sampler: Some(Sampler {
            filter: Filter::Nearest,
            wrap_u: Wrap::Clamp,
            wrap_v: Wrap::Repeat,
        }),
        texels_per_square: Vec2::new(10.0, 5.0),
    }
}

#[test]
fn the_sampler_line_names_the_opengl_modes_and_the_pixels_per_square() {
    let mut t = texture_data();
    let en = sampler(&t, Lang::En, Format::Markdown).unwrap();
    assert_eq!(
        en,
        "Filter: GL_NEAREST (Filter::Nearest). Wrap: GL_CLAMP_TO_EDGE (Wrap::Clamp) along s, \
         GL_REPEAT (Wrap::Repeat) along t. One ground square shows 10 × 5 pixels of \
         the image (across × up the image, along s × along t).\n"
    );
    let ja = sampler(&t, Lang::Ja, Format::Latex).unwrap();
    assert!(ja.contains("s 方向 GL\\_CLAMP\\_TO\\_EDGE"), "{ja}");
    assert!(ja.contains("10 × 5 ピクセル（画像の横 × 縦、s 方向 × t 方向）"), "{ja}");
    t.sampler = None;
    assert_eq!(sampler(&t, Lang::En, Format::Markdown), None);
}

#[test]
fn texture_table_has_every_grid_vertex() {
    let t = texture_data();
    let md = tex_table(&t, Lang::En, Format::Markdown);
    let lines: Vec<&str> = md.lines().collect();
    assert_eq!(lines.len(), 2 + 121);
    assert!(
        lines.contains(&"| 3 | 5 | (-2.000, 0.000, 0.000) | (0.300, 0.500) / (1.000, 0.500) |"),
        "{md}"
    );
    assert_eq!(lines[2], "| 0 | 0 | (-5.000, 0.000, -5.000) | (0.250, 0.500) |");
    assert!(!md.contains("-0.000"));
    let tex = tex_table(&t, Lang::Ja, Format::Latex);
    assert_balanced(&tex);
    assert_eq!(tex.matches(" \\\\\n").count(), 1 + 121, "header and one line per vertex");
    let f = formula(&t, Lang::En, Format::Markdown);
    assert!(f.contains("s \\in [0.250, 0.750],\\ t \\in [0.500, 1.000]"), "{f}");
    assert_balanced(&formula(&t, Lang::Ja, Format::Latex));
}

#[test]
fn latex_fragments_are_balanced() {
    let mut p = pyramid();
    p.transform = Some(MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, 1.0, 0.0))));
    for lang in [Lang::Ja, Lang::En] {
        for tex in [
            vertex_table(&p, lang, Format::Latex),
            face_table(&p, lang, Format::Latex),
            transform(&p, lang, Format::Latex),
            matrices(&[camera()], lang, Format::Latex),
            matrices(&[], lang, Format::Latex),
        ] {
            assert_balanced(&tex);
        }
    }
}
