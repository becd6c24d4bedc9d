use super::*;
use std::fmt::Write as _;

#[test]
fn items_read_in_japanese() {
    assert_eq!(item_ja("F2 normal"), "F2 の法線");
    assert_eq!(item_ja("F4 order"), "F4 の頂点の順序");
    assert_eq!(item_ja("tex (3, 5)"), "テクスチャ座標 (3, 5)");
    assert_eq!(item_ja("tex (3, 5) position"), "テクスチャ座標 (3, 5) の位置");
    assert_eq!(item_ja("a2.view.start (row 1, column 4)"), "a2.view.start（1 行 4 列）");
    assert_eq!(item_ja("V3"), "V3");
}
use crate::derive::polygon_from_data;
use crate::model::{AnimationData, CameraData, NamedMatrix};
use crate::parse::{LECTURE_SLIDE, line_of, parse_number, parse_report, polygon_from_text};
use cg_core::product::{Factor, MatrixProduct};
use cg_core::texture::Texture;
use proptest::prelude::*;

const PYRAMID_FACES: [[u32; 3]; 6] =
    [[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3]];

fn pyramid_vertices() -> Vec<Vec3> {
    vec![
        Vec3::new(0.0, 1.0, 0.0),
        Vec3::new(1.0, -0.8, 1.0),
        Vec3::new(1.0, -0.8, -1.0),
        Vec3::new(-1.0, -0.8, 1.0),
        Vec3::new(-1.0, -0.8, -1.0),
    ]
}

fn named(id: &str, numeric: MatrixProduct) -> NamedMatrix {
    NamedMatrix {
        id: id.to_owned(),
        title: Text::new(id, id),
        symbolic: numeric.clone(),
        numeric,
        variables: Vec::new(),
    }
}

fn tex_row(i: u32, j: u32, tex: &[(f32, f32)]) -> TexRow {
    TexRow {
        i,
        j,
        position: Vec3::new(i as f32 - 5.0, 0.0, j as f32 - 5.0),
        tex: tex.iter().map(|&(s, t)| Vec2::new(s, t)).collect(),
    }
}

/// The lecture's pyramid placed by T(0, 0.8, 0); a camera at T(1, 2, 3)·Ry(30°); one object
/// at Rz(90°)·T(2, 0, 0); three grid vertices.
fn derived() -> Derived {
    let mut polygon = polygon_from_data(
        Text::new("四角すい", "pyramid"),
        pyramid_vertices(),
        PYRAMID_FACES.to_vec(),
        None,
    );
    polygon.transform =
        Some(MatrixProduct::identity().then(Factor::translate(Vec3::new(0.0, 0.8, 0.0))));
    let view = MatrixProduct::identity()
        .then(Factor::translate(Vec3::new(1.0, 2.0, 3.0)))
        .then(Factor::rotate_y_deg(30.0));
    let object = MatrixProduct::identity()
        .then(Factor::rotate_z_deg(90.0))
        .then(Factor::translate(Vec3::new(2.0, 0.0, 0.0)));
    Derived {
        student: Some("12345678".to_owned()),
        a1: Some(polygon),
        a2: Some(CameraData { matrices: vec![named("a2.view.start", view)] }),
        a3: Some(AnimationData {
            objects: vec![("object0".to_owned(), vec![named("a3.object0.t1.5", object)])],
            periods: Text::default(),
        }),
        a4: Some(TextureData {
            rows: vec![
                tex_row(0, 0, &[(0.0, 0.0)]),
                tex_row(3, 5, &[(0.3, 0.5), (1.0, 0.5)]),
                tex_row(10, 10, &[(1.0, 1.0)]),
            ],
            formula: Text::default(),
            region: (Vec2::ZERO, Vec2::ONE),
            image: Texture::new(1, 1, vec![[255; 4]]).unwrap(),
            sampler: None,
            texels_per_square: Vec2::ZERO,
        }),
        s: None,
    }
}

/// A correct report of `derived()`, every number worked out by hand: normals
/// (0, 2, 3.6)/|…| = (0, 0.4856, 0.8742) and its turns, T(1, 2, 3)·Ry(30°) with
/// cos 30° = 0.866, Rz(90°)·T(2, 0, 0) moving the origin to (0, 2, 0).
const CLEAN: &str = r"# Report

| V | position |
|---|---|
| V0 | (0.000, 1.000, 0.000) |
| V1 | (1.000, -0.800, 1.000) |
| V2 | (1.000, -0.800, -1.000) |
| V3 | (-1.000, -0.800, 1.000) |
| V4 | (-1.000, -0.800, -1.000) |

| F | vertices | normal |
|---|---|---|
| F0 | { V0, V3, V1 } | { 0.000, 0.486, 0.874 } |
| F1 | { V0, V2, V4 } | { 0.000, 0.486, -0.874 } |
| F2 | { V0, V1, V2 } | { 0.874, 0.486, 0.000 } |
| F3 | { V0, V4, V3 } | { -0.874, 0.486, 0.000 } |
| F4 | { V1, V3, V2 } | { 0.000, -1.000, 0.000 } |
| F5 | { V4, V2, V3 } | { 0.000, -1.000, 0.000 } |

<!-- cg: a1.transform -->
$$
\begin{pmatrix}
1 & 0 & 0 & 0 \\
0 & 1 & 0 & 0.8 \\
0 & 0 & 1 & 0 \\
0 & 0 & 0 & 1
\end{pmatrix}
$$

<!-- cg: a2.view.start -->
$$ \begin{pmatrix} 0.866 & 0 & 0.5 & 1 \\ 0 & 1 & 0 & 2 \\ -0.5 & 0 & 0.866 & 3 \\ 0 & 0 & 0 & 1 \end{pmatrix} $$

<!-- cg: a3.object0.t1.5 -->
$$ \begin{pmatrix} 0 & -1 & 0 & 0 \\ 1 & 0 & 0 & 2 \\ 0 & 0 & 1 & 0 \\ 0 & 0 & 0 & 1 \end{pmatrix} $$

| i | j | position | texture coordinates |
|---|---|---|---|
| 0 | 0 | (-5.000, 0.000, -5.000) | (0.000, 0.000) |
| 3 | 5 | (-2.000, 0.000, 0.000) | (1.000, 0.500) / (0.300, 0.500) |
";

fn items(v: &Verification) -> Vec<(usize, &str)> {
    v.findings.iter().map(|f| (f.line, f.item.as_str())).collect()
}

fn check(text: &str) -> Verification {
    let (report, problems) = parse_report(text);
    assert!(problems.is_empty(), "{problems:?}");
    verify(&report, &derived())
}

/// The notes besides the one every report without the texture formula gets (these reports are
/// about the other tables; the formula is checked in `crate::formula`): asserts that one is there.
fn only_the_formula_missing(v: &Verification) -> Vec<&str> {
    let missing = "no tagged texture formula found in the report: a4.formula";
    assert!(v.notes.iter().any(|n| n.en == missing), "{:?}", v.notes);
    v.notes.iter().map(|n| n.en.as_str()).filter(|n| *n != missing).collect()
}

fn w(s: &str) -> Written {
    parse_number(s).unwrap()
}

#[test]
fn tolerance_is_the_last_written_digit() {
    let ok = |s: &str, d: f64| accepts(&w(s), d);
    assert!(ok("1", 0.9995), "fewer than two decimals count as exact to 0.01");
    assert!(!ok("1", 0.53));
    assert!(!ok("0.53", 0.4856));
    assert!(ok("0.49", 0.4856), "rounded");
    assert!(ok("0.48", 0.4856), "cut off");
    assert!(ok("0.486", 0.48564), "rounded to three");
    assert!(ok("0.485", 0.48564), "cut off at three");
    assert!(!ok("0.487", 0.48564), "0.0014 off with three decimals");
    assert!(!ok("0.5", 0.4856), "0.0144 off");
    assert!(ok("-0.874", -0.87416));
    assert!(!ok("0.874", -0.87416), "the sign counts");
    assert!(ok("0.000", -1e-8), "float noise around zero");
    assert!(!ok("0.0", f64::NAN), "nothing follows from NaN");
    let t = tolerance(&w("0.53"), 0.4856);
    assert!((t - 0.01).abs() < 2e-6, "{t}");
    let t = tolerance(&w("0.4856"), 100.0);
    assert!((t - (1e-4 + 1e-4)).abs() < 1e-12, "relative noise for large values: {t}");
}

#[test]
fn a_correct_report_is_clean_and_counts_every_number() {
    let v = check(CLEAN);
    assert!(v.is_clean(), "{:#?}", v.findings);
    assert_eq!(only_the_formula_missing(&v), Vec::<&str>::new(), "{:?}", v.notes);
    // 5 vertices × 3 + 6 normals × 3 + 3 matrices × 16 + (3 + 2) + (3 + 4) for the grid rows.
    assert_eq!(v.checked, 15 + 18 + 48 + 5 + 7);
}

/// The view's block as `report fill` writes it (Markdown and LaTeX): the factors after their
/// tag `a2.view.start.factors`, then the tagged product.
fn filled_view(format: crate::template::Format) -> String {
    let d = derived();
    crate::tables::matrix(&d.a2.as_ref().unwrap().matrices[0], Lang::En, format)
}

#[test]
fn each_factor_of_a_product_is_checked_and_a_wrong_one_is_named() {
    use crate::template::Format;
    for format in [Format::Markdown, Format::Latex] {
        let block = filled_view(format);
        assert!(block.contains("cg: a2.view.start.factors"), "{block}");
        let (report, problems) = parse_report(&block);
        assert!(problems.is_empty(), "{problems:?}");
        let ids: Vec<&str> = report.matrices.iter().map(|m| m.id.as_str()).collect();
        assert_eq!(
            ids,
            ["a2.view.start.factors.1", "a2.view.start.factors.2", "a2.view.start"],
            "{block}"
        );
        let v = verify(&report, &derived());
        assert!(v.findings.is_empty(), "{:#?}", v.findings);
        assert_eq!(v.checked, 3 * 16, "two factors and the product, 16 entries each");
        // T(1, 2, 3) written with z = 2: the product is still right, the factor is not.
        let wrong = block.replacen("3 \\", "2 \\", 1);
        assert_ne!(wrong, block, "{block}");
        let (report, _) = parse_report(&wrong);
        let v = verify(&report, &derived());
        let items: Vec<&str> = v.findings.iter().map(|f| f.item.as_str()).collect();
        assert_eq!(items, ["a2.view.start.factors.1 (row 3, column 4)"], "{format:?}");
    }
}

/// The texture-coordinate table as `report fill` writes it, in both formats and languages:
/// every row reads back (Markdown `| 1 | 0 | (…) | (…) |`, LaTeX `1 & 0 & $(…)$ & $(…)$ \\`),
/// checks clean, and a wrong pair is named at its line. The LaTeX rows were not read: the
/// check said there was no table and passed a wrong value.
#[test]
fn the_filled_texture_table_reads_back_in_both_formats() {
    use crate::template::Format;
    let data = crate::tables::tests::texture_data();
    let d = Derived { a4: Some(data.clone()), ..Derived::default() };
    let pairs: usize = data.rows.iter().map(|r| r.tex.len()).sum();
    for format in [Format::Markdown, Format::Latex] {
        for lang in [Lang::Ja, Lang::En] {
            let table = crate::tables::tex_table(&data, lang, format);
            let (report, problems) = parse_report(&table);
            assert!(problems.is_empty(), "{problems:?}");
            assert_eq!(report.tex.len(), data.rows.len(), "{format:?} {lang}:\n{table}");
            let v = verify(&report, &d);
            assert!(v.findings.is_empty(), "{format:?} {lang}: {:#?}", v.findings);
            assert_eq!(v.checked, 3 * data.rows.len() + 2 * pairs);
            // Grid vertex (1, 0) has s = 0.25 + 0.05 = 0.3 and t = 0.5: written as 0.9.
            let row = match format {
                Format::Markdown => "| 1 | 0 | (-4.000, 0.000, -5.000) | (0.300, 0.500) |",
                Format::Latex => "1 & 0 & $(-4.000, 0.000, -5.000)$ & $(0.300, 0.500)$ \\\\",
            };
            assert!(table.contains(row), "{table}");
            let wrong = table.replace(row, &row.replace("(0.300, 0.500)", "(0.900, 0.500)"));
            let (report, _) = parse_report(&wrong);
            let v = verify(&report, &d);
            assert_eq!(items(&v), [(line_of(&wrong, "(0.900, 0.500)"), "tex (1, 0)")]);
            assert_eq!(v.findings[0].written, "(0.900, 0.500)");
        }
    }
}

#[test]
fn factors_beyond_the_products_are_a_note_not_a_mistake() {
    let block = filled_view(crate::template::Format::Markdown);
    let extra = "$$ \\begin{pmatrix} 1 & 0 & 0 & 0 \\\\ 0 & 1 & 0 & 0 \\\\ 0 & 0 & 1 & 0 \\\\ 0 & 0 & 0 & 1 \\end{pmatrix} $$\n";
    let at = block.find("the product (4×4 matrix)").unwrap();
    let text = format!("{}{extra}{}", &block[..at], &block[at..]);
    let (report, problems) = parse_report(&text);
    assert!(problems.is_empty(), "{problems:?}");
    let v = verify(&report, &derived());
    assert!(v.findings.is_empty(), "{:#?}", v.findings);
    assert!(
        v.notes.iter().any(|n| n.en.contains("the product `a2.view.start` has 2 factors")),
        "{:?}",
        v.notes
    );
    // Two factors too many: one note naming both, not the same note twice.
    let text = format!("{}{extra}{extra}{}", &block[..at], &block[at..]);
    let (report, _) = parse_report(&text);
    let v = verify(&report, &derived());
    let extra: Vec<&str> =
        v.notes.iter().map(|n| n.en.as_str()).filter(|n| n.contains("has 2 factors")).collect();
    assert_eq!(extra.len(), 1, "{:?}", v.notes);
    assert!(
        extra[0].starts_with("`a2.view.start.factors.3`, `a2.view.start.factors.4` (line "),
        "{extra:?}"
    );
}

/// A report copied from a larger model, or filled from functions not written yet, writes many
/// rows and tags the data does not have: one note per kind, the rows as runs with their lines
/// (a report from another student's model gave a note per row, 24 of them, and the same
/// extra-factor note twice; a report filled from the stubs listed 72 tags with "known: —").
#[test]
fn rows_and_tags_the_data_lacks_are_one_note_each() {
    let mut text = String::from("V0 (0.0, 1.0, 0.0)\n");
    for k in [9, 10, 11, 12, 20] {
        writeln!(text, "V{k} (1.0, 1.0, 1.0)").unwrap();
    }
    for k in 8..=10 {
        writeln!(text, "F{k} {{ V0, V1, V2 }}").unwrap();
    }
    let view = filled_view(crate::template::Format::Markdown);
    text.push_str(&view.replace("a2.view.start", "a3.object0.t9"));
    let (report, problems) = parse_report(&text);
    assert!(problems.is_empty(), "{problems:?}");
    let v = verify(&report, &derived());
    let notes: Vec<&str> = v.notes.iter().map(|n| n.en.as_str()).collect();
    let with = |s: &str| notes.iter().filter(|n| n.contains(s)).copied().collect::<Vec<_>>();
    assert_eq!(
        with("the data has no"),
        [
            "V9–V12, V20 (lines 2–6): the data has no such vertex (it has 5 vertices: V0–V4; is the table from another model?)",
            "F8–F10 (lines 7–9): the data has no such face (it has 6 faces: F0–F5; is the table from another model?)",
        ],
        "{notes:?}"
    );
    let tags = with("no derived matrix");
    assert_eq!(tags.len(), 1, "{notes:?}");
    assert!(
        tags[0]
            .starts_with("no derived matrix has the tag `a3.object0.t9` (or its factors) (lines "),
        "{tags:?}"
    );
    // The Japanese says the same, once each.
    let ja: Vec<&str> = v.notes.iter().map(|n| n.ja.as_str()).collect();
    assert!(
        ja.iter()
            .any(|n| n.starts_with("V9〜V12, V20（2〜6 行目）: データにこれらの頂点はありません")),
        "{ja:?}"
    );

    // A part not derived (its functions not written): its tags in one note that says so.
    let d = Derived { a2: None, ..derived() };
    let (report, _) = parse_report(&view);
    let v = verify(&report, &d);
    let notes: Vec<&str> = v.notes.iter().map(|n| n.en.as_str()).collect();
    assert_eq!(notes.len(), 6, "the tags, and the other parts' missing tables: {notes:?}");
    let a2 = notes.iter().find(|n| n.contains("a2 could not be derived")).expect("a2's note");
    assert!(a2.starts_with("`a2.view.start` and its factors (lines "), "{a2}");
    assert!(!notes.iter().any(|n| n.contains("known:")), "{notes:?}");
    assert!(v.findings.is_empty() && v.checked == 0, "{:#?}", v.findings);
}

#[test]
fn planted_mistakes_are_named_and_nothing_else() {
    let text = CLEAN
        .replace(
            "| F2 | { V0, V1, V2 } | { 0.874, 0.486, 0.000 } |",
            "| F2 | { V0, V1, V2 } | { 0.874, 0.586, 0.000 } |",
        )
        .replace("| F4 | { V1, V3, V2 }", "| F4 | { V1, V2, V3 }")
        .replace("0.866 & 0 & 0.5 & 1 \\\\", "0.866 & 0 & 0.5 & 1.5 \\\\")
        .replace("(1.000, 0.500) / (0.300, 0.500)", "(1.000, 0.500) / (0.300, 0.600)");
    let v = check(&text);
    assert_eq!(
        items(&v),
        vec![
            (line_of(&text, "| F2 |"), "F2 normal"),
            (line_of(&text, "| F4 |"), "F4 order"),
            (line_of(&text, "1.5 \\\\"), "a2.view.start (row 1, column 4)"),
            (line_of(&text, "| 3 | 5 |"), "tex (3, 5)"),
        ],
        "{:#?}",
        v.findings
    );
    assert_eq!(only_the_formula_missing(&v), Vec::<&str>::new(), "{:?}", v.notes);
    let f = &v.findings;
    assert_eq!(f[0].written, "{ 0.874, 0.586, 0.000 }");
    assert!(f[0].derived.contains("0.4856"), "{}", f[0].derived);
    assert!((f[0].tolerance.unwrap() - 0.001).abs() < 1e-5);
    assert!(f[0].why.en.contains("y is 0.586"), "{}", f[0].why);
    assert!(!f[0].why.en.contains("x is"), "only the wrong component: {}", f[0].why);
    assert_eq!(
        (f[1].written.as_str(), f[1].derived.as_str()),
        ("{ V1, V2, V3 }", "{ V1, V3, V2 }")
    );
    assert!(f[1].why.en.contains("inward") && f[1].tolerance.is_none());
    assert_eq!((f[2].written.as_str(), f[2].derived.as_str()), ("1.5", "1.0"));
    assert!(f[3].why.en.contains("(0.300, 0.600)"), "{}", f[3].why);
    for f in f {
        let (en, ja) = (f.message(Lang::En), f.message(Lang::Ja));
        assert!(en.starts_with(&format!("line {}: {}", f.line, f.item)), "{en}");
        assert!(ja.starts_with(&format!("{} 行目: {}", f.line, item_ja(&f.item))), "{ja}");
        assert!(en.contains(&f.written) && en.contains(&f.derived) && ja.contains(&f.derived));
    }
    assert!(f[0].message(Lang::En).contains("tolerance ±0.001"), "{}", f[0].message(Lang::En));
    assert!(f[0].message(Lang::Ja).contains("許容誤差 ±0.001"));
}

/// A product written as a `bmatrix`, followed by the next product's section with its symbolic
/// matrix: the wrong entry (-15 for 2) is named in the bmatrix. It was skipped: the symbolic
/// matrix was taken for it (a problem at the wrong line) and the note said the matrix was
/// missing. A matrix of `\frac{\sqrt{3}}{2}` is named at its line and not also "missing".
#[test]
fn a_product_in_brackets_is_checked_and_one_not_read_is_not_also_missing() {
    let a2 = r"$$ \begin{pmatrix} 0.866 & 0 & 0.5 & 1 \\ 0 & 1 & 0 & 2 \\";
    assert!(CLEAN.contains(a2));
    let next = "**View after the drag**\n\n$$ \\begin{pmatrix} \\cos(-\\mathit{yaw}) & 0 & 0 & 0 \\\\ 0 & 1 & 0 & 0 \\\\ 0 & 0 & 1 & 0 \\\\ 0 & 0 & 0 & 1 \\end{pmatrix} $$\n\n";
    let text = CLEAN.replace(a2, &a2.replace("0 & 2 \\\\", "0 & -15 \\\\")).replace(
        "\\end{pmatrix} $$\n\n<!-- cg: a3",
        &format!("\\end{{pmatrix}} $$\n\n{next}<!-- cg: a3"),
    );
    let text = text.replacen("{pmatrix} 0.866", "{bmatrix} 0.866", 1).replacen(
        "0 & 0 & 0 & 1 \\end{pmatrix} $$\n\n**",
        "0 & 0 & 0 & 1 \\end{bmatrix} $$\n\n**",
        1,
    );
    assert!(text.contains("\\begin{bmatrix}") && text.contains("\\end{bmatrix}"), "{text}");
    let v = check(&text);
    let line = line_of(&text, "-15");
    assert_eq!(items(&v), [(line, "a2.view.start (row 2, column 4)")], "{:#?}", v.findings);
    assert_eq!(only_the_formula_missing(&v), Vec::<&str>::new());

    let text = CLEAN.replace(a2, &a2.replace("0.866", "\\frac{\\sqrt{3}}{2}"));
    let (report, problems) = parse_report(&text);
    let lines: Vec<usize> = problems.iter().map(|p| p.line).collect();
    assert_eq!(lines, [line_of(&text, "\\sqrt{3}")], "{problems:?}");
    let v = verify(&report, &derived());
    assert!(v.findings.is_empty(), "{:#?}", v.findings);
    assert_eq!(only_the_formula_missing(&v), Vec::<&str>::new(), "no 'no tagged matrix' note");
}

/// Rows of the derived model that the report's tables leave out are a note naming them (no
/// finding: the report still passes); they passed without a word. The first ten are named and
/// the rest counted; a report with no vertex or face table gets only the notes saying so.
#[test]
fn rows_the_tables_leave_out_are_a_note_naming_them() {
    let text = CLEAN
        .replace("| V4 | (-1.000, -0.800, -1.000) |\n", "")
        .replace("| F2 | { V0, V1, V2 } | { 0.874, 0.486, 0.000 } |\n", "")
        .replace("| F5 | { V4, V2, V3 } | { 0.000, -1.000, 0.000 } |\n", "");
    assert_eq!(text.lines().count() + 3, CLEAN.lines().count());
    let v = check(&text);
    assert!(v.is_clean(), "{:#?}", v.findings);
    let rows: Vec<&Text> = v.notes.iter().filter(|n| n.en.contains("leave out")).collect();
    assert_eq!(rows.len(), 1, "{:?}", v.notes);
    assert!(rows[0].en.starts_with("V4, F2, F5: the derived model has 3 rows "), "{}", rows[0].en);
    assert!(rows[0].en.contains("not counted as mistakes"), "{}", rows[0].en);
    assert!(
        rows[0].ja.starts_with("V4, F2, F5: 導出したモデルにあるこの 3 行が"),
        "{}",
        rows[0].ja
    );
    assert_eq!(only_the_formula_missing(&check(CLEAN)), Vec::<&str>::new(), "every row: no note");

    // 15 vertices, only V0 written: V1 … V10 named, 4 more counted; no face table, so its
    // note and no face named.
    let vertices: Vec<Vec3> = (0..15).map(|i| Vec3::new(i as f32, 0.0, 0.0)).collect();
    let polygon = polygon_from_data(Text::new("点", "points"), vertices, Vec::new(), None);
    let d = Derived { a1: Some(polygon), ..Derived::default() };
    let (report, _) = parse_report("| V0 | (0.000, 0.000, 0.000) |");
    let v = verify(&report, &d);
    let notes: Vec<&str> = v.notes.iter().map(|n| n.en.as_str()).collect();
    let names = (1..=10).map(|k| format!("V{k}")).collect::<Vec<_>>().join(", ");
    let want = format!("{names} and 4 more: the derived model has 14 rows ");
    assert!(notes.iter().any(|n| n.starts_with(&want)), "{notes:?}");
    let ja = format!("{names} ほか 4 行: ");
    assert!(v.notes.iter().any(|n| n.ja.starts_with(&ja)), "{:?}", v.notes);
    assert!(notes.iter().any(|n| n.contains("no face table")), "{notes:?}");
    assert!(!notes.iter().any(|n| n.contains("F0")), "{notes:?}");

    // No vertex or face table at all: the notes saying so, and no list of rows.
    let v = check("Nothing here.");
    assert!(v.notes.iter().all(|n| !n.en.contains("leave out")), "{:?}", v.notes);
}

#[test]
fn a_rotated_face_is_fine_and_other_vertices_are_one_finding() {
    let text = CLEAN.replace("| F0 | { V0, V3, V1 }", "| F0 | { V3, V1, V0 }").replace(
        "| F1 | { V0, V2, V4 } | { 0.000, 0.486, -0.874 }",
        "| F1 | { V0, V1, V4 } | { 0.000, 0.486, 0.874 }",
    );
    let v = check(&text);
    assert_eq!(items(&v), vec![(line_of(&text, "| F1 |"), "F1 vertices")], "{:#?}", v.findings);
    assert_eq!(v.findings[0].derived, "{ V0, V2, V4 }");
}

#[test]
fn what_the_report_lacks_or_the_data_lacks_is_a_note() {
    let text = "V0 (0.0, 1.0, 0.0)\nV9 (1.0, 1.0, 1.0)\nF8 { V0, V1, V2 }\n<!-- cg: a9.unknown -->\n$$\\begin{pmatrix} 1&0&0&0\\\\0&1&0&0\\\\0&0&1&0\\\\0&0&0&1 \\end{pmatrix}$$\n| 7 | 7 | (2, 0, 2) | (0.5, 0.5) |";
    let v = check(text);
    assert!(v.is_clean(), "{:#?}", v.findings);
    assert_eq!(v.checked, 3, "only V0");
    let notes: Vec<&str> = v.notes.iter().map(|n| n.en.as_str()).collect();
    let has = |s: &str| notes.iter().any(|n| n.contains(s));
    assert!(has("no V9"), "{notes:?}");
    assert!(has("no F8"), "{notes:?}");
    assert!(
        has("`a9.unknown`") && has("known: a1.transform, a2.view.start, a3.object0.t1.5"),
        "{notes:?}"
    );
    assert!(
        has(
            "no tagged matrix found in the report for: a1.transform, a2.view.start, a3.object0.t1.5"
        ),
        "{notes:?}"
    );
    assert!(has("(7, 7)"), "{notes:?}");
    assert!(!has("no vertex table") && !has("no face table"), "{notes:?}");
    assert!(v.notes.iter().all(|n| !n.ja.is_empty() && n.ja != n.en));

    let v = check("Nothing here.");
    let notes: Vec<&str> = v.notes.iter().map(|n| n.en.as_str()).collect();
    assert!(notes.iter().any(|n| n.contains("no vertex table")), "{notes:?}");
    assert!(notes.iter().any(|n| n.contains("no face table")), "{notes:?}");
    assert!(notes.iter().any(|n| n.contains("no texture-coordinate table")), "{notes:?}");

    let (report, _) = parse_report(CLEAN);
    let v = verify(&report, &Derived::default());
    assert!(v.is_clean() && v.checked == 0);
    assert_eq!(v.notes.len(), 3, "polygon, matrices (not derived), texture: {:?}", v.notes);
    assert!(
        v.notes[1].en.starts_with(
            "`a1.transform`, `a2.view.start`, `a3.object0.t1.5` (lines 20, 30, 33): a1, a2 and a3 could not be derived"
        ),
        "{:?}",
        v.notes
    );
}

#[test]
fn data_alone_flags_exactly_the_slides_wrong_normals() {
    let polygon = polygon_from_text(LECTURE_SLIDE, Text::new("四角すい", "pyramid")).unwrap();
    let (report, _) = parse_report(LECTURE_SLIDE);
    let v = verify_data(&polygon, &report);
    let expected: Vec<(usize, String)> = (0..4)
        .map(|k| (line_of(LECTURE_SLIDE, &format!("F{k} {{")), format!("F{k} normal")))
        .collect();
    let got: Vec<(usize, String)> = v.findings.iter().map(|f| (f.line, f.item.clone())).collect();
    assert_eq!(got, expected, "{:#?}", v.findings);
    assert!(v.notes.is_empty(), "{:?}", v.notes);
    assert_eq!(v.checked, 5 * 3 + 6 * 3);
    // F0: (0, 2, 3.6)/|…| = (0, 0.4856, 0.8742); 0.53 and 0.85 are both off.
    let len = (4.0f64 + 3.6 * 3.6).sqrt();
    let f0 = &v.findings[0];
    assert_eq!(f0.written, "{ 0.0, 0.53, 0.85 }");
    assert_eq!(f0.derived, format!("{{ 0.0, {:.4}, {:.4} }}", 2.0 / len, 3.6 / len));
    assert!(f0.why.en.contains("y is 0.53") && f0.why.en.contains("z is 0.85"), "{}", f0.why);
    assert!((f0.tolerance.unwrap() - 0.01).abs() < 1e-5);
    assert_eq!(v.findings[2].derived, format!("{{ {:.4}, {:.4}, 0.0 }}", 3.6 / len, 2.0 / len));
}

fn slide_with_normals(normals: [&str; 4]) -> String {
    let mut text = LECTURE_SLIDE.to_owned();
    let old = [
        "{ 0.0, 0.53, 0.85 }",
        "{ 0.0, 0.53, -0.85 }",
        "{ 0.85, 0.53, 0.0 }",
        "{ -0.85, 0.53, 0.0 }",
    ];
    for (o, n) in old.iter().zip(normals) {
        text = text.replace(o, n);
    }
    text
}

fn data_alone(text: &str) -> Verification {
    let polygon = polygon_from_text(text, Text::default()).unwrap();
    verify_data(&polygon, &parse_report(text).0)
}

#[test]
fn data_alone_accepts_rounded_and_cut_off_normals() {
    let rounded = slide_with_normals([
        "{ 0.0, 0.49, 0.87 }",
        "{ 0.0, 0.49, -0.87 }",
        "{ 0.87, 0.49, 0.0 }",
        "{ -0.87, 0.49, 0.0 }",
    ]);
    let v = data_alone(&rounded);
    assert!(v.is_clean() && v.notes.is_empty(), "{:#?} {:?}", v.findings, v.notes);
    let cut = slide_with_normals([
        "{ 0.0, 0.485, 0.874 }",
        "{ 0.0, 0.485, -0.874 }",
        "{ 0.874, 0.485, 0.0 }",
        "{ -0.874, 0.485, 0.0 }",
    ]);
    assert!(data_alone(&cut).is_clean());
    let cut2 = slide_with_normals([
        "{ 0, 0.48, 0.87 }",
        "{ 0, 0.48, -0.87 }",
        "{ 0.87, 0.48, 0 }",
        "{ -0.87, 0.48, 0 }",
    ]);
    assert!(data_alone(&cut2).is_clean());
}

#[test]
fn data_alone_names_a_face_wound_inward_with_its_outward_order() {
    // F4 written clockwise; its normal written for the written order (pointing up) is right
    // for that order, so only the order is named.
    let text = slide_with_normals([
        "{ 0.0, 0.49, 0.87 }",
        "{ 0.0, 0.49, -0.87 }",
        "{ 0.87, 0.49, 0.0 }",
        "{ -0.87, 0.49, 0.0 }",
    ])
    .replace("| F4 { V1, V3, V2 } | { 0.0, -1.0, 0.0 }", "| F4 { V1, V2, V3 } | { 0.0, 1.0, 0.0 }");
    let v = data_alone(&text);
    assert_eq!(items(&v), vec![(line_of(&text, "F4 {"), "F4 order")], "{:#?}", v.findings);
    assert_eq!(v.findings[0].derived, "{ V1, V3, V2 }");
    // Turned inside out: every face is named.
    let mut inside_out = String::new();
    for l in LECTURE_SLIDE.lines() {
        let l = l
            .replace("{ V0, V3, V1 }", "{ V0, V1, V3 }")
            .replace("{ V0, V2, V4 }", "{ V0, V4, V2 }")
            .replace("{ V0, V1, V2 }", "{ V0, V2, V1 }")
            .replace("{ V0, V4, V3 }", "{ V0, V3, V4 }")
            .replace("{ V1, V3, V2 }", "{ V1, V2, V3 }")
            .replace("{ V4, V2, V3 }", "{ V4, V3, V2 }");
        inside_out.push_str(&l);
        inside_out.push('\n');
    }
    let v = data_alone(&inside_out);
    let orders: Vec<&str> =
        v.findings.iter().filter(|f| f.item.ends_with("order")).map(|f| f.item.as_str()).collect();
    assert_eq!(orders, ["F0 order", "F1 order", "F2 order", "F3 order", "F4 order", "F5 order"]);
}

#[test]
fn outwardness_is_judged_per_face_far_from_the_origin_and_when_not_convex() {
    let far: Vec<Vec3> = pyramid_vertices().iter().map(|&p| p + Vec3::splat(1000.0)).collect();
    let mut faces = PYRAMID_FACES.to_vec();
    faces[2] = [0, 2, 1];
    let out = face_outwardness(&far, &faces);
    assert_eq!(out, vec![Some(true), Some(true), Some(false), Some(true), Some(true), Some(true)]);
    // A non-convex closed model: the pyramid with its base dented up to V5 (0, -0.3, 0).
    let mut dented = pyramid_vertices();
    dented.push(Vec3::new(0.0, -0.3, 0.0));
    let mut faces = PYRAMID_FACES[..4].to_vec();
    faces.extend([[1, 3, 5], [4, 2, 5], [2, 1, 5], [3, 4, 5]]);
    // (V3 − V1) × (V5 − V1) = (0, -2, -1): down and away from the dent, outward. A centroid
    // test gets this face wrong: its normal points towards the model's centroid.
    let centroid = dented.iter().copied().sum::<Vec3>() / 6.0;
    let face_centroid = (dented[1] + dented[3] + dented[5]) / 3.0;
    assert!((face_centroid - centroid).dot(Vec3::new(0.0, -2.0, -1.0)) < 0.0);
    assert_eq!(face_outwardness(&dented, &faces), vec![Some(true); 8]);
    faces[5] = [4, 5, 2];
    let mut expected = vec![Some(true); 8];
    expected[5] = Some(false);
    assert_eq!(face_outwardness(&dented, &faces), expected);
    // An open model cannot be judged.
    assert_eq!(face_outwardness(&pyramid_vertices(), &PYRAMID_FACES[..4]), vec![None; 4]);
    // Degenerate and out-of-range faces are not judged and do not panic.
    let out = face_outwardness(&pyramid_vertices(), &[[0, 0, 1], [0, 1, 9]]);
    assert_eq!(out, vec![None, None]);
}

#[test]
fn data_alone_on_an_open_model_says_why_order_is_not_judged() {
    let text = "V0 (0,0,0)\nV1 (1,0,0)\nV2 (0,1,0)\nF0 { V0, V1, V2 } { 0.0, 0.0, 1.0 }";
    let v = data_alone(text);
    assert!(v.is_clean(), "{:#?}", v.findings);
    assert_eq!(v.notes.len(), 1);
    assert!(v.notes[0].en.starts_with("F0: the model is not closed"), "{}", v.notes[0]);
    // A large open model names its first faces and counts the rest (it named every face in
    // one note: megabytes for the largest data file).
    let mut text = String::new();
    for k in 0..100 {
        let x = k as f32;
        writeln!(
            text,
            "V{} ({x}, 0, 0)\nV{} ({x}, 1, 0)\nV{} ({x}, 0, 1)",
            3 * k,
            3 * k + 1,
            3 * k + 2
        )
        .unwrap();
    }
    for k in 0..100 {
        writeln!(text, "F{k} {{ V{}, V{}, V{} }}", 3 * k, 3 * k + 1, 3 * k + 2).unwrap();
    }
    let v = data_alone(&text);
    let note = v.notes.iter().find(|n| n.en.contains("not closed")).expect("the note");
    assert!(note.en.starts_with("F0, F1, F2, F3, F4, F5, F6, F7, F8, F9 and 90 more: "), "{note}");
    assert!(note.ja.starts_with("F0, F1, F2, F3, F4, F5, F6, F7, F8, F9 ほか 90 面: "), "{note}");
    assert!(!note.en.contains("F10"), "{note}");
}

proptest! {
    #![proptest_config(cg_testkit::prop::config(128, 0x5eed_0006))]

    #[test]
    fn checking_any_text_never_panics(text in "[VF0-9 (){},.|\\-−/\n]{0,200}") {
        let (report, _) = parse_report(&text);
        let v = verify(&report, &derived());
        prop_assert!(v.findings.windows(2).all(|w| w[0].line <= w[1].line));
        if let Ok(p) = polygon_from_text(&text, Text::default()) {
            let _ = verify_data(&p, &report);
        }
    }
}

/// A face with no area is a finding, with a normal written or without one; and a difference
/// smaller than 0.0001 is shown with the digits it needs, never "off by 0", its written number
/// shortened when it is long.
#[test]
fn a_face_with_no_area_is_a_mistake_and_small_differences_show() {
    for face in ["F0 { V0, V0, V1 } { 0.0, 0.49, 0.87 }", "F0 { V0, V0, V0 }"] {
        let text = format!("V0 (0,0,0)\nV1 (1,0,0)\nV2 (0,1,0)\n{face}\nF1 {{ V0, V1, V2 }}");
        let v = data_alone(&text);
        assert_eq!(items(&v), vec![(4, "F0 normal")], "{face}: {:#?}", v.findings);
        let m = v.findings[0].message(Lang::Ja);
        assert!(m.contains("面積 0 の面"), "{m}");
    }
    // F0's y is 0.48564 against 0.4856429…: the difference shows, to its digits.
    let long = format!("0.48564{}", "0".repeat(400));
    let text = slide_with_normals([
        &format!("{{ 0.0, {long}, 0.8742 }}"),
        "{ 0.0, 0.4856, -0.8742 }",
        "{ 0.8742, 0.4856, 0.0 }",
        "{ -0.8742, 0.4856, 0.0 }",
    ]);
    let v = data_alone(&text);
    assert_eq!(v.findings.len(), 1, "{:#?}", v.findings);
    let m = v.findings[0].message(Lang::En);
    assert!(!m.contains("off by 0)") && !m.contains("off by 0,"), "{m}");
    assert!(m.len() < 600, "{m}");
}
