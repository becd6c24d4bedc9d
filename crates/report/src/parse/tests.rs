use super::*;
use cg_core::glam::Vec3;
use proptest::prelude::*;

fn values(w: &[Written]) -> Vec<f64> {
    w.iter().map(|w| w.value).collect()
}

fn messages_name(p: &ParseProblem, line: usize) {
    let (en, ja) = (p.message(Lang::En), p.message(Lang::Ja));
    assert!(en.starts_with(&format!("line {line}: ")), "{en}");
    assert!(ja.starts_with(&format!("{line} 行目: ")), "{ja}");
    assert!(!p.expected.en.is_empty() && !p.expected.ja.is_empty(), "{p:?}");
    assert_ne!(p.expected.en, p.expected.ja, "both languages are written: {p:?}");
    assert!(p.found.chars().count() <= 80, "{p:?}");
}

#[test]
fn numbers_remember_their_decimals() {
    let n = |s: &str| parse_number(s).map(|w| (w.value, w.decimals));
    assert_eq!(n("0.53"), Some((0.53, 2)));
    assert_eq!(n("-0.8"), Some((-0.8, 1)));
    assert_eq!(n("−0.8"), Some((-0.8, 1)), "the Unicode minus");
    assert_eq!(n("＋1.250"), Some((1.25, 3)));
    assert_eq!(n("15"), Some((15.0, 0)));
    assert_eq!(n(" .5 "), Some((0.5, 1)));
    assert_eq!(n("5."), Some((5.0, 0)));
    assert_eq!(parse_number("−0.8").map(|w| w.text), Some("−0.8".to_owned()), "kept as written");
    for bad in ["", "-", ".", "1e-3", "0,5", "\\cos 30°", "0.8.1", "- 1", "inf", "NaN", "1/2"] {
        assert_eq!(parse_number(bad), None, "{bad:?}");
    }
    assert_eq!(parse_number(&"9".repeat(400)), None, "too large to be finite");
}

#[test]
fn the_lecture_slide_parses() {
    let (r, problems) = parse_report(LECTURE_SLIDE);
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(r.vertices.len(), 5);
    assert_eq!(r.faces.len(), 6);
    assert!(r.matrices.is_empty() && r.tex.is_empty());
    let v3 = &r.vertices[3];
    assert_eq!((v3.index, v3.line), (3, line_of(LECTURE_SLIDE, "V3 (")));
    assert_eq!(values(&v3.coords), [-1.0, -0.8, 1.0]);
    assert_eq!(v3.coords.each_ref().map(|w| w.decimals), [1, 1, 1]);
    let expected_faces = [[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]];
    for (k, f) in r.faces.iter().enumerate() {
        assert_eq!(f.index as usize, k);
        assert_eq!(f.vertices, expected_faces[k]);
        assert_eq!(f.line, line_of(LECTURE_SLIDE, &format!("F{k} {{")));
    }
    let n0 = r.faces[0].normal.as_ref().unwrap();
    assert_eq!(values(n0), [0.0, 0.53, 0.85]);
    assert_eq!(n0.each_ref().map(|w| w.decimals), [1, 2, 2]);
    assert_eq!(values(r.faces[3].normal.as_ref().unwrap()), [-0.85, 0.53, 0.0]);
}

/// Index, line, vertices and normal values of a face row.
type FaceRow = (u32, usize, [u32; 3], Option<Vec<f64>>);

#[test]
fn the_kits_tables_and_other_spellings_parse() {
    let text = "\
| V | position |
|---|---|
| V0 | (0.000, 1.000, 0.000) |
- V1 = (1, -0.8, 1)
V2 （1.0，−0.8，−1.0）
3. **V3** (-1.0, -0.8, 1.0)
頂点V4 (-1.0, -0.8, -1.0) は裏側
| F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } |
F1 ( V0, V2, V4 )   ( 0.0, 0.4856, -0.8742 )
F2 ｛V0，V1，V2｝
V5 = (cos 30°, 0, sin 30°) = (0.866, 0, 0.5)
The face F3 (the left one) and V1 (the apex's neighbour) are prose.
Edges V3–V5, F9.
V0 (the apex) is prose too, and so is
F1 (the back face).
";
    let (r, problems) = parse_report(text);
    assert!(problems.is_empty(), "{problems:?}");
    let got: Vec<(u32, usize, Vec<f64>)> =
        r.vertices.iter().map(|v| (v.index, v.line, values(&v.coords))).collect();
    assert_eq!(
        got,
        vec![
            (0, 3, vec![0.0, 1.0, 0.0]),
            (1, 4, vec![1.0, -0.8, 1.0]),
            (2, 5, vec![1.0, -0.8, -1.0]),
            (3, 6, vec![-1.0, -0.8, 1.0]),
            (4, 7, vec![-1.0, -0.8, -1.0]),
            (5, 11, vec![0.866, 0.0, 0.5]),
        ]
    );
    let faces: Vec<FaceRow> = r
        .faces
        .iter()
        .map(|f| (f.index, f.line, f.vertices, f.normal.as_ref().map(|n| values(n))))
        .collect();
    assert_eq!(
        faces,
        vec![
            (0, 8, [0, 3, 1], Some(vec![0.0, 0.486, 0.874])),
            (1, 9, [0, 2, 4], Some(vec![0.0, 0.4856, -0.8742])),
            (2, 10, [0, 1, 2], None),
        ]
    );
}

#[test]
fn latex_rows_parse() {
    let text =
        "V0 & (0.0, 1.0, 0.0) \\\\\nF0 & $\\{ V0, V3, V1 \\}$ & $\\{ 0.0, 0.49, 0.87 \\}$ \\\\\n";
    assert!(text.contains(r"$\{ V0"), "{text}");
    let (r, problems) = parse_report(text);
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(values(&r.vertices[0].coords), [0.0, 1.0, 0.0]);
    assert_eq!(r.faces[0].vertices, [0, 3, 1]);
    assert_eq!(values(r.faces[0].normal.as_ref().unwrap()), [0.0, 0.49, 0.87]);
}

#[test]
fn a_row_quoted_again_with_the_same_numbers_is_kept_once() {
    let text = "V0 (0.0, 1.0, 0.0)\nF0 { V0, V3, V1 }\nAs computed, V0 (0, 1, 0) is the apex; F0 { V0, V3, V1 } { 0.0, 0.49, 0.87 }.";
    let (r, problems) = parse_report(text);
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(r.vertices.len(), 1);
    assert_eq!(r.faces.len(), 1);
    assert_eq!(r.faces[0].line, 2);
    assert_eq!(
        values(r.faces[0].normal.as_ref().unwrap()),
        [0.0, 0.49, 0.87],
        "the later normal fills in"
    );
}

#[test]
fn tagged_matrices_and_texture_rows_parse() {
    let text = r"Intro with a matrix that has no tag: $\begin{pmatrix} a & b \end{pmatrix}$

<!-- cg: a2.view.start -->
$$
T(1, 2, 3) \cdot R_y(30°) =
\begin{pmatrix}
0.866 & 0 & 0.5 & 1 \\
0 & 1 & 0 & 2 \\
-0.5 & 0 & {0.866} & 3 \\[2pt]
0 & 0 & 0 & 1 \\
\end{pmatrix}
$$
% cg: a3.object0.t1.5
\[ \begin{pmatrix} 0 & -1 & 0 & 0 \\ 1 & 0 & 0 & 2 \\ 0 & 0 & 1 & 0 \\ 0 & 0 & 0 & 1 \end{pmatrix} \]

| i | j | position | texture coordinates |
|---|---|---|---|
| 0 | 0 | (-5.000, 0.000, -5.000) | (0.000, 0.000) |
| 3 | 5 | (-2.000, 0.000, 0.000) | (0.300, 0.500) / (1.000, 0.500) |
| 1 | 2 | 3 |
";
    let (r, problems) = parse_report(text);
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(r.matrices.len(), 2);
    let m = &r.matrices[0];
    assert_eq!((m.id.as_str(), m.line), ("a2.view.start", 3));
    let rows: Vec<Vec<f64>> = m.rows.iter().map(|r| values(r)).collect();
    assert_eq!(
        rows,
        vec![
            vec![0.866, 0.0, 0.5, 1.0],
            vec![0.0, 1.0, 0.0, 2.0],
            vec![-0.5, 0.0, 0.866, 3.0],
            vec![0.0, 0.0, 0.0, 1.0]
        ]
    );
    assert_eq!(m.entry_lines, vec![vec![7; 4], vec![8; 4], vec![9; 4], vec![10; 4]]);
    let m = &r.matrices[1];
    assert_eq!((m.id.as_str(), m.line), ("a3.object0.t1.5", 13));
    assert_eq!(values(&m.rows[1]), [1.0, 0.0, 0.0, 2.0]);
    assert_eq!(m.entry_lines[3], vec![14; 4]);
    assert_eq!(r.tex.len(), 2);
    let t = &r.tex[1];
    assert_eq!((t.i, t.j, t.line), (3, 5, 19));
    assert_eq!(values(&t.position), [-2.0, 0.0, 0.0]);
    let tex: Vec<Vec<f64>> = t.tex.iter().map(|p| values(p)).collect();
    assert_eq!(tex, vec![vec![0.3, 0.5], vec![1.0, 0.5]]);
}

#[test]
fn malformed_rows_name_their_line_and_what_was_expected() {
    let text = r"V0 (0.0, 1.0, 0.0)
V1 (1.0, -0.8)
F3 { V0, V4 }
F4 { V1, V3, 2 }
F5 { V4, V2, V3 } { 0.0, -1.0 }
V0 (0.0, 2.0, 0.0)
V2 (1.0, abc, 1.0)
| 3 | 5 | (-2.000, 0.000, 0.000) |
| 4 | 5 | (-1.000, 0.000) | (0.4, 0.5) |
| 5 | 5 | (0.000, 0.000, 0.000) | (0.5, 0.5) / 0.6 |
<!-- cg: a1.transform -->
no matrix here
<!-- cg: a2.view.start -->
$$ \begin{pmatrix} 1 & 0 & 0 \\ 0 & 1 & 0 \\ 0 & 0 & 1 \end{pmatrix} $$
<!-- cg: a2.view.drag -->
$$ \begin{pmatrix}
\cos 30° & 0 & 0 & 0 \\ 0 & 1 & 0 & 0 \\ 0 & 0 & 1 & 0 \\ 0 & 0 & 0 & 1
\end{pmatrix} $$
<!-- cg: bad id -->
V6 (1.0, 2.0, 3.0
";
    let (r, problems) = parse_report(text);
    let got: Vec<(usize, RowKind)> = problems.iter().map(|p| (p.line, p.kind)).collect();
    assert_eq!(
        got,
        vec![
            (2, RowKind::Vertex),
            (3, RowKind::Face),
            (4, RowKind::Face),
            (5, RowKind::Face),
            (6, RowKind::Vertex),
            (7, RowKind::Vertex),
            (8, RowKind::Texture),
            (9, RowKind::Texture),
            (10, RowKind::Texture),
            (11, RowKind::Matrix),
            (14, RowKind::Matrix),
            (17, RowKind::Matrix),
            (19, RowKind::Matrix),
            (20, RowKind::Vertex),
        ],
        "{problems:#?}"
    );
    for p in &problems {
        messages_name(p, p.line);
    }
    let by_line = |n: usize| problems.iter().find(|p| p.line == n).unwrap();
    assert_eq!(by_line(2).found, "V1 (1.0, -0.8)");
    assert!(by_line(2).expected.en.contains("found 2 numbers"), "{}", by_line(2).expected);
    assert_eq!(by_line(3).found, "F3 { V0, V4 }");
    assert!(by_line(3).expected.en.contains("three vertex numbers"), "{}", by_line(3).expected);
    assert!(
        by_line(3)
            .message(Lang::En)
            .starts_with("line 3: `F3 { V0, V4 }` — expected three vertex numbers")
    );
    assert!(by_line(4).expected.en.contains("`2` is not a vertex number"));
    assert!(by_line(5).expected.en.contains("normal"));
    assert!(
        by_line(6).expected.en.contains("line 1"),
        "the duplicate names the first: {}",
        by_line(6).expected
    );
    assert!(by_line(7).expected.en.contains("`abc`"));
    assert!(by_line(8).expected.en.contains("missing"));
    assert!(by_line(11).expected.en.contains("pmatrix"));
    assert!(
        by_line(14).expected.en.contains("found 3 rows of 3, 3, 3 entries"),
        "{}",
        by_line(14).expected
    );
    assert_eq!(by_line(17).found, "\\cos 30°");
    assert!(by_line(17).expected.en.contains("0.866"));
    assert!(by_line(20).expected.en.contains("not closed"));
    // Only the rows that parsed are kept: V0 (first), F-nothing, no tex, no matrix.
    assert_eq!(r.vertices.len(), 1);
    assert_eq!(values(&r.vertices[0].coords), [0.0, 1.0, 0.0]);
    assert!(r.faces.is_empty() && r.tex.is_empty() && r.matrices.is_empty(), "{r:?}");
}

#[test]
fn long_offending_text_is_clipped() {
    let text = format!("F0 {{ V0, V1, {} }}", "V2, ".repeat(40));
    let (_, problems) = parse_report(&text);
    assert_eq!(problems.len(), 1);
    assert_eq!(problems[0].found.chars().count(), 80);
    assert!(problems[0].found.ends_with('…'));
    // An invisible character pasted into a row is named where the message quotes it.
    let (_, problems) = parse_report("F0 { V0,\u{200B} V1 }");
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert!(problems[0].found.contains("<U+200B>"), "{}", problems[0].found);
}

#[test]
fn data_alone_builds_the_lectures_pyramid() {
    let p = polygon_from_text(LECTURE_SLIDE, Text::new("四角すい", "pyramid")).unwrap();
    assert_eq!(p.vertices[2], Vec3::new(1.0, -0.8, -1.0));
    assert_eq!(p.faces, vec![[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]]);
    // The kit's normal of F0 from the vertices: (V3 − V0) × (V1 − V0) = (0, 2, 3.6)/|…|.
    let len = (4.0f64 + 3.6 * 3.6).sqrt();
    let n0 = p.derived_normals[0].unwrap().as_dvec3();
    assert!((n0 - DVec3::new(0.0, 2.0 / len, 3.6 / len)).length() < 1e-6, "{n0}");
    let written = p.student_normals.as_ref().unwrap();
    assert_eq!(written[0], Vec3::new(0.0, 0.53, 0.85));
    assert_eq!(written[5], Vec3::new(0.0, -1.0, 0.0));
    // Without every normal, there are no student normals.
    let text =
        "V0 (0,0,0)\nV1 (1,0,0)\nV2 (0,1,0)\nF0 { V0, V1, V2 } { 0, 0, 1 }\nF1 { V0, V2, V1 }";
    assert_eq!(polygon_from_text(text, Text::default()).unwrap().student_normals, None);
}
use cg_core::glam::DVec3;

#[test]
fn data_alone_names_what_is_missing() {
    let err = |text: &str| polygon_from_text(text, Text::default()).unwrap_err();
    let e = err("");
    assert_eq!(e.len(), 2, "{e:?}");
    assert!(e.iter().all(|p| p.line == 0 && p.kind == RowKind::Data));
    assert!(e[0].message(Lang::En).starts_with("the text: expected at least one vertex row"));
    assert!(e[0].message(Lang::Ja).starts_with("全体: "));

    let e = err("V0 (0,0,0)\nV1 (1,0,0)\nV3 (0,1,0)\nF0 { V0, V1, V3 }\nF1 { V0, V1, V7 }");
    let got: Vec<usize> = e.iter().map(|p| p.line).collect();
    assert_eq!(got, vec![3, 5], "{e:?}");
    assert!(
        e[0].expected.en.contains("V0 to V2") && e[0].expected.en.contains("V2 is missing"),
        "{}",
        e[0].expected
    );
    assert!(e[1].expected.en.contains("no V7"), "{}", e[1].expected);
    for p in &e {
        messages_name(p, p.line);
    }

    let e = err("V0 (0,0,0)\nV1 (1,0,0)\nV2 (0,1,0)\nF0 { V0, V1, V2 }\nF2 { V0, V2, V1 }");
    assert_eq!(e.len(), 1);
    assert!(e[0].expected.en.contains("F1 is missing"), "{}", e[0].expected);

    let e =
        err(&format!("V0 ({}, 0, 0)\nV1 (1,0,0)\nV2 (0,1,0)\nF0 {{ V0, V1, V2 }}", "9".repeat(40)));
    assert_eq!(e.len(), 1);
    assert!(e[0].expected.en.contains("f32"), "{}", e[0].expected);

    // A row that does not read is named alone: not also "no face rows", nor "F0 is missing"
    // at the rows after it, nor "there is no V1" at the faces naming a vertex whose row failed.
    let e = err("V0 (0,0,0)\nV1 (1,0,0)\nV2 (0,1,0)\nF0 { V0, V1 }\n");
    assert_eq!(e.iter().map(|p| (p.line, p.kind)).collect::<Vec<_>>(), vec![(4, RowKind::Face)]);
    let e = err(
        "V0 (0,0,0)\nV1 (1,0,0,5)\nV2 (0,1,0)\nF0 { V0, V1, V2 } { 0, 0 }\nF1 { V1, V2, V0 }\n",
    );
    assert_eq!(
        e.iter().map(|p| (p.line, p.kind)).collect::<Vec<_>>(),
        vec![(2, RowKind::Vertex), (4, RowKind::Face)],
        "{e:#?}"
    );
}

/// Text built from the notation's own pieces, so random input reaches every branch.
fn notation_soup() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        Just("V".to_owned()),
        Just("F".to_owned()),
        Just("{".to_owned()),
        Just("}".to_owned()),
        Just("(".to_owned()),
        Just(")".to_owned()),
        Just(", ".to_owned()),
        Just(" | ".to_owned()),
        Just("\n".to_owned()),
        Just(" = ".to_owned()),
        Just(" / ".to_owned()),
        Just("−".to_owned()),
        Just("，".to_owned()),
        Just("（".to_owned()),
        Just("&".to_owned()),
        Just("\\\\".to_owned()),
        Just("<!-- cg: a1.transform -->".to_owned()),
        Just("<!-- cg:".to_owned()),
        Just("% cg: x\n".to_owned()),
        Just("\\begin{pmatrix}".to_owned()),
        Just("\\end{pmatrix}".to_owned()),
        Just("\\\\[".to_owned()),
        "[0-9]{1,3}".prop_map(|s| s),
        "-?[0-9]{0,2}\\.[0-9]{0,4}".prop_map(|s| s),
        "\\PC{0,3}".prop_map(|s| s),
    ];
    proptest::collection::vec(piece, 0..60).prop_map(|v| v.concat())
}

proptest! {
    #![proptest_config(cg_testkit::prop::config(256, 0x5eed_0005))]

    #[test]
    fn any_text_parses_without_panicking(text in "\\PC{0,300}") {
        let (_, problems) = parse_report(&text);
        for p in &problems {
            prop_assert!(p.found.chars().count() <= 80);
            prop_assert!(!p.message(Lang::Ja).is_empty());
        }
        let _ = polygon_from_text(&text, Text::default());
    }

    #[test]
    fn notation_soup_parses_without_panicking(text in notation_soup()) {
        let (r, problems) = parse_report(&text);
        for p in &problems {
            prop_assert!(p.line <= text.lines().count().max(1), "{p:?}");
            prop_assert!(p.found.chars().count() <= 80);
        }
        for m in &r.matrices {
            prop_assert!(m.rows.len() == 4 && m.rows.iter().all(|r| r.len() == 4));
        }
        if let Ok(p) = polygon_from_text(&text, Text::default()) {
            prop_assert_eq!(p.derived_normals.len(), p.faces.len());
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Hostile sizes: each of these reads in linear time (a fraction of a second); the reader that
// searched a list or the rest of a line once per row or token took minutes on them.

/// `clip` as it was first written (count every character, then cut): the oracle for the
/// `clip` that reads only as far as it must.
fn clip_by_counting(s: &str) -> String {
    let s = s.trim();
    if s.chars().count() <= 80 {
        cg_core::quote::visible(s)
    } else {
        let mut out = cg_core::quote::visible(&s.chars().take(79).collect::<String>());
        out.push('…');
        out
    }
}

#[test]
fn clip_reads_only_as_far_as_it_must() {
    let long = format!("{}{}", "a".repeat(80), " ".repeat(1000));
    let cases = [
        String::new(),
        "   ".to_owned(),
        "  V0 (0.0, 1.0)  ".to_owned(),
        "x".repeat(80),
        "x".repeat(81),
        format!("{}  ", "x".repeat(81)),
        format!("  {}\t\n", "あ".repeat(80)),
        format!("{}\u{3000}y", "あ".repeat(80)),
        format!("{}\u{200B}{}", "b".repeat(60), "c".repeat(40)),
        long.clone(),
        format!("{long}z"),
    ];
    for s in &cases {
        assert_eq!(clip(s), clip_by_counting(s), "{s:?}");
    }
    let line = "F0 { ".repeat(1_000_000);
    assert_eq!(clip(&line), clip_by_counting(&line));
}

proptest! {
    #![proptest_config(cg_testkit::prop::config(256, 0x5eed_0011))]

    #[test]
    fn clip_is_clip_by_counting(s in "[ a\u{3000}\u{200B}\t]{0,100}", n in 0usize..100) {
        let s = format!("{s}{}", "あ ".repeat(n));
        prop_assert_eq!(clip(&s), clip_by_counting(&s));
    }
}

#[test]
fn groups_of_a_few_hundred_characters_still_read() {
    // `longdec`: a number with hundreds of decimals is a group like any other.
    let zeros = "0".repeat(900);
    let text = format!("V0 (0.{zeros}1, 1.0, 0.0)\n");
    let (r, problems) = parse_report(&text);
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(r.vertices[0].coords[0].decimals, 901);
    // A group that does not close within its bound reads as not closed.
    let text = format!("V0 (0.{}1, 1.0, 0.0)\n", "0".repeat(2000));
    let (r, problems) = parse_report(&text);
    assert!(r.vertices.is_empty());
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert!(
        problems[0].expected.en.ends_with("(the bracket is not closed within 1024 characters)"),
        "{problems:?}"
    );
}

#[test]
fn a_line_of_unclosed_vertex_groups_is_one_problem() {
    // 5 MB: `V0 (V0 (V0 ( …`; each group was looked for up to the end of the line.
    let text = "V0 (".repeat(1_250_000);
    let (r, problems) = parse_report(&text);
    assert!(r.is_empty());
    assert_eq!(problems.len(), 1, "only the row the line starts with");
    let p = &problems[0];
    messages_name(p, 1);
    assert_eq!(p.found, format!("{}…", &text[..79]));
    assert!(p.expected.en.ends_with("(the bracket is not closed within 1024 characters)"), "{p:?}");
}

#[test]
fn a_line_of_unclosed_face_groups_names_each_with_its_text() {
    // 1 MB: `F0 { F0 { …`; each problem quoted (and counted) the rest of the line.
    let count = 200_000;
    let text = "F0 { ".repeat(count);
    let (_, problems) = parse_report(&text);
    // The first few are named; the rest are counted in one last problem.
    assert_eq!(problems.len(), MAX_PROBLEMS_PER_LINE + 1);
    let last = &problems[MAX_PROBLEMS_PER_LINE];
    let more = format!("{} more places", count - MAX_PROBLEMS_PER_LINE);
    assert!(last.line == 0 && last.expected.en.contains(&more), "{last:?}");
    for (k, p) in problems[..MAX_PROBLEMS_PER_LINE].iter().enumerate() {
        assert_eq!(p.line, 1);
        assert!(
            p.expected.en.ends_with("(the bracket is not closed within 1024 characters)"),
            "{p:?}"
        );
        let rest = text[5 * k..].trim();
        let expected =
            if rest.len() <= 80 { rest.to_owned() } else { format!("{}…", &rest[..79]) };
        assert_eq!(p.found, expected);
    }
}

#[test]
fn a_line_of_unclosed_tags_names_each_once() {
    // 1 MB: `<!-- cg: <!-- cg: …`; each tag looked for its `-->` up to the end of the line.
    let count = 110_000;
    let text = format!("{}\n<!-- cg: a1.transform -->\n", "<!-- cg: ".repeat(count));
    let (_, problems) = parse_report(&text);
    let tags: Vec<_> = problems.iter().filter(|p| p.line == 1).collect();
    assert_eq!(tags.len(), MAX_PROBLEMS_PER_LINE);
    let first = text.lines().next().unwrap_or("");
    for (k, p) in tags.iter().enumerate() {
        assert_eq!(p.kind, RowKind::Matrix);
        let rest = first[9 * k..].trim();
        let expected =
            if rest.len() <= 80 { rest.to_owned() } else { format!("{}…", &rest[..79]) };
        assert_eq!(p.found, expected);
    }
    // The tag on the next line is read (and has no matrix after it).
    assert!(problems.iter().any(|p| p.line == 2 && p.found == "<!-- cg: a1.transform -->"));
    // A `-->` at the end: the first tag reads up to it, its ID holding all the others.
    let text = format!("{}-->", "<!-- cg: ".repeat(count));
    let (_, problems) = parse_report(&text);
    assert_eq!(problems.len(), 1, "{:?}", problems.first());
    assert_eq!(problems[0].found, format!("{}…", &text[..79]));
}

#[test]
fn a_large_data_file_names_its_gap_and_its_missing_vertex() {
    // 100 000 vertices and 100 000 faces naming the last vertices: every lookup once went
    // through the whole vertex list.
    let n = 100_000u32;
    let gap = n - 10;
    let mut text = String::new();
    for k in 0..n {
        let k = if k == gap { n + 5 } else { k };
        text.push_str(&format!("V{k} (0.0, {k}.0, 1.0)\n"));
    }
    for k in 0..n {
        let (a, b, c) = (n - 1, n - 2, n - 3);
        if k == n - 1 {
            text.push_str(&format!("F{k} {{ V{a}, V{gap}, V{c} }}\n"));
        } else {
            text.push_str(&format!("F{k} {{ V{a}, V{b}, V{c} }}\n"));
        }
    }
    let errors = polygon_from_text(&text, Text::default()).unwrap_err();
    let messages: Vec<String> = errors.iter().map(|p| p.message(Lang::En)).collect();
    let (last, far, v_last, v_third) = (n - 1, n + 5, n - 1, n - 3);
    assert_eq!(
        messages,
        [
            format!(
                "line {}: `V{far} (0.0, {far}.0, 1.0)` — expected vertex numbers V0 to V{last} \
                 without gaps (V{gap} is missing)",
                gap + 1
            ),
            format!(
                "line {}: `F{last} {{ V{v_last}, V{gap}, V{v_third} }}` — expected vertex numbers \
                 that have vertex rows (there is no V{gap})",
                2 * n
            ),
        ]
    );
}

#[test]
fn many_vertices_out_of_range_name_the_same_first_gaps() {
    // Rows numbered from V1000 up: every one of the last thousand rows is out of range, and
    // each names the first five gaps.
    let mut text = String::new();
    for k in 1000..21_000 {
        text.push_str(&format!("V{k} (0.0, 0.0, 0.0)\n"));
    }
    text.push_str("F0 { V0, V1001, V1002 }\n");
    let errors = polygon_from_text(&text, Text::default()).unwrap_err();
    assert_eq!(errors.len(), 1000 + 1, "1000 rows out of range, and the face naming V0");
    for p in &errors[..1000] {
        assert!(
            p.expected.en.ends_with("V0 to V19999 without gaps (V0, V1, V2, V3, V4 is missing)"),
            "{p:?}"
        );
        assert!(p.expected.ja.contains("（V0, V1, V2, V3, V4 がありません）"), "{p:?}");
    }
    assert_eq!(errors[1000].line, 20_001);
    assert!(errors[1000].expected.en.ends_with("(there is no V0)"), "{:?}", errors[1000]);
}

#[test]
fn problems_are_named_up_to_a_limit_and_the_rest_counted() {
    // 5 000 lines that cannot be read: the first MAX_PROBLEMS are named, in order.
    let text = "F0 { V0, V1 }\n".repeat(5_000);
    let (_, problems) = parse_report(&text);
    assert_eq!(problems.len(), MAX_PROBLEMS + 1);
    assert!(problems[..MAX_PROBLEMS].iter().enumerate().all(|(k, p)| p.line == k + 1));
    let last = &problems[MAX_PROBLEMS];
    assert!(last.message(Lang::Ja).contains("ほかに 4000 か所"), "{last:?}");
}

/// A mistyped tag is a problem at its line, not a comment passed over (its table would go
/// unchecked); a table's tag mistyped asks for the tables' tags, not for a matrix.
#[test]
fn mistyped_tags_are_named_with_what_they_should_be() {
    let text = "<!-- cg s.spot -->\n| α = 15° | 0.5 |\n<!-- CG: a1.transform -->\n<!-- cg: s.spots -->\n| α = 15° | 0.5 |\n<!-- cgi: a comment -->\n<!-- any comment -->\n";
    let (_, problems) = parse_report(text);
    let lines: Vec<usize> = problems.iter().map(|p| p.line).collect();
    assert_eq!(lines, [1, 3, 4], "{problems:#?}");
    assert!(problems[0].expected.en.contains("<!-- cg: a1.transform -->"), "{:?}", problems[0]);
    assert!(
        problems[2].expected.en.contains("s.light.p")
            && problems[2].expected.ja.contains("表のタグ")
    );
    // The student's own comments in Japanese (and an emoji) are comments: no problem, and no
    // panic (byte 2 of `メモ` is inside its first character; this ended `report check` with
    // exit 101).
    let text = "<!-- メモ -->\n<!--コメント-->\n<!-- aあ -->\n<!-- 🎨 -->\n<!--x-->\n<!-- c -->\n<!---->\n| V0 | 1.0 | 0.0 | 0.0 |\n";
    let (_, problems) = parse_report(text);
    assert!(problems.is_empty(), "{problems:#?}");
}

const PYRAMID_VERTICES: &str = "V0 (0.0, 1.0, 0.0)\nV1 (1.0, -0.8, 1.0)\nV2 (1.0, -0.8, -1.0)\nV3 (-1.0, -0.8, 1.0)\nV4 (-1.0, -0.8, -1.0)\n";

/// The normal of the one face of `text` as read (no problem expected).
fn normal_read(text: &str) -> Option<Vec<f64>> {
    let (r, problems) = parse_report(text);
    assert!(problems.is_empty(), "{text:?}: {problems:#?}");
    r.faces.first().and_then(|f| f.normal.as_ref()).map(|n| values(n))
}

/// A value after `≒` (or `≈`) is read, as the student guide says: a wrong normal written that
/// way was dropped without a word (exit 0, "no normals").
#[test]
fn a_value_after_approximately_equal_is_read() {
    let want = Some(vec![1.0, 0.0, 0.0]);
    for row in [
        "F0 { V0, V3, V1 } ≒ { 1.0, 0.0, 0.0 }",
        "| F0 { V0, V3, V1 } | ≒ { 1.0, 0.0, 0.0 } |",
        "F0 { V0, V3, V1 } ≈ { 1.0, 0.0, 0.0 }",
        // A working that ends in its value: the last group of the chain.
        "F0 { V0, V3, V1 } { 0.0, 0.486, 0.874 } ≒ { 1.0, 0.0, 0.0 }",
        "F0 { V0, V3, V1 } = { 0.0, 0.486, 0.874 } ≒ { 1.0, 0.0, 0.0 }",
    ] {
        assert_eq!(normal_read(&format!("{PYRAMID_VERTICES}{row}\n")), want, "{row}");
    }
    let (r, problems) = parse_report("V1 ≒ (1.0, -0.8, 1.0)\n");
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(values(&r.vertices[0].coords), [1.0, -0.8, 1.0]);
    // And checked: a wrong one is a finding.
    let text = format!("{PYRAMID_VERTICES}F0 {{ V0, V3, V1 }} ≒ {{ 1.0, 0.0, 0.0 }}\n");
    let polygon = polygon_from_text(&text, Text::default()).unwrap();
    let v = crate::verify::verify_data(&polygon, &parse_report(&text).0);
    assert_eq!(v.findings.len(), 1, "{:#?}", v.findings);
    assert_eq!((v.findings[0].line, v.findings[0].item.as_str()), (6, "F0 normal"));
}

/// Rows written with an input method's full-width letters and digits (`Ｖ０`, `Ｆ０ ｛ Ｖ０、…｝`)
/// are read as the ASCII ones: a full-width `Ｖ０` row was passed over, and the error was blamed
/// on the rows after it.
#[test]
fn full_width_row_names_are_read() {
    let (r, problems) = parse_report("Ｖ０ （0.0, 1.0, 0.0）\nＶ１ (1.0, -0.8, 1.0)\n");
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(r.vertices.len(), 2, "{:?}", r.vertices);
    assert_eq!(values(&r.vertices[0].coords), [0.0, 1.0, 0.0]);
    let text = format!("{PYRAMID_VERTICES}Ｆ０ ｛ Ｖ０、Ｖ３、Ｖ１ ｝ {{ 0.0, 0.49, 0.87 }}\n");
    assert_eq!(normal_read(&text), Some(vec![0.0, 0.49, 0.87]));
}

/// A second normal on a face row, or one behind words, was dropped without a word; now the
/// row is a problem at its line.
#[test]
fn a_second_or_labelled_normal_is_a_problem() {
    for (row, second) in [
        ("F0 { V0, V3, V1 } { 0.0, 0.49, 0.87 } { 1.0, 0.0, 0.0 }", true),
        ("| F0 { V0, V3, V1 } | { 0.0, 0.49, 0.87 } | { 1.0, 0.0, 0.0 } |", true),
        ("F0 { V0, V3, V1 } 法線 { 1.0, 0.0, 0.0 }", false),
        ("F0 { V0, V3, V1 } normal: n = { 1.0, 0.0, 0.0 }", false),
    ] {
        let text = format!("{PYRAMID_VERTICES}{row}\n");
        let (r, problems) = parse_report(&text);
        assert!(r.faces.is_empty(), "{row}: {:?}", r.faces);
        assert_eq!(problems.len(), 1, "{row}: {problems:#?}");
        let p = &problems[0];
        messages_name(p, 6);
        assert_eq!(p.kind, RowKind::Face);
        assert!(p.expected.en.contains("{ 1.0, 0.0, 0.0 }"), "{p:?}");
        assert_eq!(p.expected.en.contains("second normal"), second, "{p:?}");
        assert!(polygon_from_text(&text, Text::default()).is_err(), "{row}");
    }
    // Two faces on a line, each with its normal, still read.
    let text = format!(
        "{PYRAMID_VERTICES}F0 {{ V0, V3, V1 }} {{ 0.0, 0.49, 0.87 }} F1 {{ V0, V2, V4 }} {{ 0.0, 0.49, -0.87 }}\n"
    );
    let (r, problems) = parse_report(&text);
    assert!(problems.is_empty(), "{problems:#?}");
    assert_eq!(r.faces.len(), 2);
}

/// `4.9e-1` is named as exponent notation, which the notation does not read, not as "not a
/// number".
#[test]
fn exponent_notation_is_named_as_not_read() {
    for (row, bad) in [
        ("F0 { V0, V3, V1 } { 0.0, 4.9e-1, 8.7e-1 }", "4.9e-1"),
        ("V1 (1e-30, 0, 0)", "1e-30"),
        ("V1 (1.0, -8E-1, 1.0)", "-8E-1"),
    ] {
        let (_, problems) = parse_report(&format!("{row}\n"));
        assert_eq!(problems.len(), 1, "{row}: {problems:#?}");
        let p = &problems[0];
        messages_name(p, 1);
        assert!(p.expected.en.contains(&format!("`{bad}` is in exponent notation")), "{p:?}");
        assert!(p.expected.ja.contains("指数表記"), "{p:?}");
    }
    for not_exponent in ["e-1", "1e", "1.2.3e4", "abc", "1e1.5"] {
        assert!(!is_exponent_notation(not_exponent), "{not_exponent}");
    }
}

/// A decimal comma (`0,5`) splits each number in two; the count found is said with a hint about
/// the comma (it was "found 5 numbers" and nothing more). Too few numbers, or too many without
/// a comma between digits, get no hint.
#[test]
fn a_decimal_comma_is_named() {
    for (row, hinted) in [
        ("V1 (1,0, -0,8, 1,0)", true),
        ("F0 { V0, V3, V1 } { 0,0, 0,49, 0,87 }", true),
        ("V1 (1.0, -0.8)", false),
        ("V1 (1.0, -0.8, 1.0, 2.0)", false),
        ("V1 (1,0)", false),
    ] {
        let (_, problems) = parse_report(&format!("{row}\n"));
        assert_eq!(problems.len(), 1, "{row}: {problems:#?}");
        let p = &problems[0];
        messages_name(p, 1);
        assert_eq!(p.expected.en.contains("comma used as the decimal point"), hinted, "{p:?}");
        assert_eq!(p.expected.ja.contains("小数点にコンマ"), hinted, "{p:?}");
    }
}

/// An old table kept in an HTML comment, or an example in a code fence, is not read (it was:
/// an old V0 clashed with the new one, a wrong normal in a comment was a finding); lines keep
/// their numbers, and tags stay.
#[test]
fn comments_and_code_fences_are_not_read() {
    let text = format!(
        "<!-- old version\nV0 (0.0, 2.0, 0.0)\nV1 (1.0, -0.8, 1.0)\n-->\n{PYRAMID_VERTICES}F0 {{ V0, V3, V1 }} {{ 0.0, 0.49, 0.87 }}\n<!--\nF1 {{ V0, V2, V4 }} {{ 1.0, 0.0, 0.0 }}\n-->\n```\nF2 {{ V0, V1, V2 }} {{ 1.0, 0.0, 0.0 }}\n```\n~~~~ text\nV7 (1, 1, 1)\n~~~~\nF1 {{ V0, V2, V4 }} <!-- {{ 1, 0, 0 }} --> {{ 0.0, 0.49, -0.87 }}\n"
    );
    let (r, problems) = parse_report(&text);
    assert!(problems.is_empty(), "{problems:#?}");
    assert_eq!(r.vertices.len(), 5);
    assert_eq!(r.vertices[0].line, 5);
    assert_eq!(values(&r.vertices[0].coords), [0.0, 1.0, 0.0]);
    let faces: Vec<(u32, usize)> = r.faces.iter().map(|f| (f.index, f.line)).collect();
    assert_eq!(faces, [(0, 10), (1, 20)]);
    assert_eq!(values(r.faces[1].normal.as_ref().unwrap()), [0.0, 0.49, -0.87]);
    // The same text without the comments and fences names the old rows.
    let (_, problems) =
        parse_report(&text.replace("<!--", "").replace("```", "").replace("~~~~", ""));
    assert!(!problems.is_empty());
    // A tag is no comment; a comment never closed is named at its line.
    let (r, problems) =
        parse_report("<!-- cg: s.spot -->\n| α = 15° | 0.5 |\n<!-- old\nV0 (1, 2, 3)\n");
    assert_eq!(r.tables.len(), 1);
    assert!(r.vertices.is_empty());
    assert_eq!(problems.len(), 1, "{problems:#?}");
    messages_name(&problems[0], 3);
    assert!(problems[0].expected.en.contains("not closed"), "{:?}", problems[0]);
    let err = polygon_from_text(
        &format!("{PYRAMID_VERTICES}F0 {{ V0, V3, V1 }}\n<!--\n"),
        Text::default(),
    )
    .unwrap_err();
    assert!(err.iter().any(|p| p.line == 7 && p.kind == RowKind::Data), "{err:#?}");
}
