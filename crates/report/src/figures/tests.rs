use super::*;

#[test]
fn labels_that_would_overlap_are_stacked_and_the_others_are_not() {
    let label = |text: &str, x: f32, y: f32| Label {
        text: text.into(),
        at: Vec2::new(x, y),
        hidden: false,
    };
    // V12 four units right of V11 (one vertex behind the other, nearly): "V12V11" before.
    let near = [label("V11", 100.0, 100.0), label("V12", 104.0, 100.0), label("V3", 200.0, 100.0)];
    let stacks: Vec<usize> =
        placements(&near, Vec2::splat(120.0), true).iter().map(|p| p.stack).collect();
    assert_eq!(stacks, [0, 1, 0]);
    // Four faces seen edge on, their centroids in a row: each on its own line.
    let edge_on: Vec<Label> =
        (22..26).map(|k| label(&format!("F{k}"), 50.0 + k as f32, 80.0)).collect();
    let stacks: Vec<usize> =
        placements(&edge_on, Vec2::splat(120.0), false).iter().map(|p| p.stack).collect();
    assert_eq!(stacks, [0, 1, 2, 3]);
    // A line's height apart: no overlap.
    assert!(!overlap(&label("V1", 0.0, 0.0), &label("V2", 0.0, LINE)));
}
use crate::tables::tests::{assert_balanced, pyramid, texture_data};

/// Every `<text>` of a class: its text and its `x`, `y`, after checking the SVG is XML.
fn texts(svg: &str, class: &str) -> Vec<(String, f32, f32)> {
    let doc = roxmltree::Document::parse(svg).unwrap_or_else(|e| panic!("not XML: {e}\n{svg}"));
    assert_eq!(doc.root_element().tag_name().name(), "svg");
    assert_eq!(doc.root_element().attribute("version"), Some("1.1"));
    doc.descendants()
        .filter(|n| n.has_tag_name("text") && n.attribute("class") == Some(class))
        .map(|n| {
            let num =
                |a: &str| n.attribute(a).and_then(|v| v.parse::<f32>().ok()).expect("x and y");
            (n.text().unwrap_or("").to_owned(), num("x"), num("y"))
        })
        .collect()
}

/// Orthographic projection by hand, then the fit: scale (SIZE − 2·MARGIN) / extent about the
/// centre of the bounding box, model up → page up.
fn by_hand(points: &[(f32, f32)], p: (f32, f32)) -> (f32, f32) {
    let (mut lo, mut hi) = ((f32::MAX, f32::MAX), (f32::MIN, f32::MIN));
    for &(x, y) in points {
        lo = (lo.0.min(x), lo.1.min(y));
        hi = (hi.0.max(x), hi.1.max(y));
    }
    let s = (SIZE - 2.0 * MARGIN) / (hi.0 - lo.0).max(hi.1 - lo.1);
    let mid = ((lo.0 + hi.0) / 2.0, (lo.1 + hi.1) / 2.0);
    (SIZE / 2.0 + (p.0 - mid.0) * s, SIZE / 2.0 - (p.1 - mid.1) * s)
}

fn find<'a>(labels: &'a [(String, f32, f32)], text: &str) -> &'a (String, f32, f32) {
    labels.iter().find(|l| l.0 == text).unwrap_or_else(|| panic!("no label {text} in {labels:?}"))
}

fn assert_at(labels: &[(String, f32, f32)], text: &str, want: (f32, f32)) {
    let l = find(labels, text);
    assert!(
        (l.1 - want.0).abs() < 0.01 && (l.2 - want.1).abs() < 0.01,
        "{text} at ({}, {}), want {want:?}",
        l.1,
        l.2
    );
}

// The pyramid: V0 (0, 1, 0), V1 (1, −0.8, 1), V2 (1, −0.8, −1), V3 (−1, −0.8, 1), V4 (−1, −0.8, −1).

#[test]
fn front_view_shows_v1_and_v3_and_hides_v2_and_v4_behind_them() {
    let svg = svg(&layout(&pyramid(), View::Front), Lang::Ja);
    let v = texts(&svg, "vertex");
    assert_eq!(v.len(), 5);
    // Seen from +z: (x, y).
    let pts = [(0.0, 1.0), (1.0, -0.8), (1.0, -0.8), (-1.0, -0.8), (-1.0, -0.8)];
    assert_at(&v, "V0", by_hand(&pts, pts[0]));
    assert_at(&v, "V1", by_hand(&pts, pts[1]));
    assert_at(&v, "(V2)", by_hand(&pts, pts[2]));
    assert_at(&v, "V3", by_hand(&pts, pts[3]));
    assert_at(&v, "(V4)", by_hand(&pts, pts[4]));
    // The numbers themselves: scale 168 / 2 = 84, V0 at (120, 120 − 0.1·84 − … ) = (120, 44.4).
    assert_at(&v, "V0", (120.0, 44.4));
    assert_at(&v, "V1", (204.0, 195.6));
    // Only F0 faces +z; F1 faces away, F2–F5 are edge-on.
    let f = texts(&svg, "face");
    let names: Vec<&str> = f.iter().map(|l| l.0.as_str()).collect();
    assert_eq!(names, ["F0", "(F1)", "(F2)", "(F3)", "(F4)", "(F5)"]);
    // F0's centroid (0, −0.2, 0.667) → (0, −0.2).
    assert_at(&f, "F0", by_hand(&pts, (0.0, -0.2)));
    assert!(svg.contains("<title>正面図"));
}

#[test]
fn hidden_edges_are_dashed_unless_a_visible_edge_covers_them() {
    // 9 edges: V0–V1, V0–V2, V0–V3, V0–V4, V1–V2, V1–V3, V2–V3 (the base's diagonal), V2–V4,
    // V3–V4. Front: only F0 faces +z, so its three edges are solid; V1–V2 and V3–V4 project
    // to points, and V0–V2, V0–V4, V2–V3, V2–V4 lie exactly under F0's edges: one triangle.
    let count = |fig: &Figure| {
        (fig.edges.iter().filter(|e| !e.2).count(), fig.edges.iter().filter(|e| e.2).count())
    };
    let front = layout(&pyramid(), View::Front);
    assert_eq!(count(&front), (3, 0), "{:?}", front.edges);
    // Top: every side face is visible, so only the base's diagonal V2–V3 (F4, F5) is hidden.
    let top = layout(&pyramid(), View::Top);
    assert_eq!(count(&top), (8, 1), "{:?}", top.edges);
    // Perspective: F0 and F2 face the eye; V0–V4, V2–V3, V2–V4, V3–V4 touch hidden faces only.
    let persp = layout(&pyramid(), View::Perspective);
    assert_eq!(count(&persp), (5, 4), "{:?}", persp.edges);
    assert!(persp.edges.iter().take(4).all(|e| e.2), "hidden edges come first (drawn below)");
    let svg = svg(&persp, Lang::En);
    assert_eq!(svg.matches("stroke-dasharray").count(), 4);
    texts(&svg, "vertex");
}

#[test]
fn top_view_hides_the_bottom_faces() {
    let svg = svg(&layout(&pyramid(), View::Top), Lang::En);
    // Seen from +y, screen up = −z: (x, −z).
    let pts = [(0.0, 0.0), (1.0, -1.0), (1.0, 1.0), (-1.0, -1.0), (-1.0, 1.0)];
    let v = texts(&svg, "vertex");
    for (k, p) in pts.iter().enumerate() {
        assert_at(&v, &format!("V{k}"), by_hand(&pts, *p));
    }
    assert_at(&v, "V2", (204.0, 36.0));
    let f = texts(&svg, "face");
    let names: Vec<&str> = f.iter().map(|l| l.0.as_str()).collect();
    assert_eq!(names, ["F0", "F1", "F2", "F3", "(F4)", "(F5)"]);
    // F4 {V1, V3, V2}: centroid (1/3, −0.8, 1/3) → (1/3, −1/3).
    assert_at(&f, "(F4)", by_hand(&pts, (1.0 / 3.0, -1.0 / 3.0)));
    assert!(svg.contains("<title>top view"));
}

#[test]
fn side_view_sees_f2_only() {
    let fig = layout(&pyramid(), View::Side);
    let svg = svg(&fig, Lang::En);
    // Seen from +x, screen right = −z: (−z, y).
    let pts = [(0.0, 1.0), (-1.0, -0.8), (1.0, -0.8), (-1.0, -0.8), (1.0, -0.8)];
    let v = texts(&svg, "vertex");
    for (k, name) in ["V0", "V1", "V2", "(V3)", "(V4)"].iter().enumerate() {
        assert_at(&v, name, by_hand(&pts, pts[k]));
    }
    let hidden: Vec<bool> = fig.faces.iter().map(|l| l.hidden).collect();
    assert_eq!(hidden, [true, true, false, true, true, true]);
    // The axes: z points left, y up.
    assert!(fig.axes.iter().any(|(d, n)| n == "z" && d.abs_diff_eq(Vec2::new(-1.0, 0.0), 1e-6)));
    assert!(fig.axes.iter().any(|(d, n)| n == "y" && d.abs_diff_eq(Vec2::new(0.0, -1.0), 1e-6)));
}

#[test]
fn perspective_from_the_front_right_hides_the_back_left() {
    let fig = layout(&pyramid(), View::Perspective);
    let svg = svg(&fig, Lang::Ja);
    let v = texts(&svg, "vertex");
    let names: Vec<&str> = v.iter().map(|l| l.0.as_str()).collect();
    // The eye is at (3, 2.5, 4)·size from the centre: F0 (+z) and F2 (+x) face it, so
    // V0–V3 are on visible faces and V4 (−1, −0.8, −1) is behind.
    assert_eq!(names, ["V0", "V1", "V2", "V3", "(V4)"]);
    let hidden: Vec<bool> = fig.faces.iter().map(|l| l.hidden).collect();
    assert_eq!(hidden, [false, true, false, true, true, true]);
    // A perspective: the near bottom corner V1 is drawn farther below the apex than the far
    // one V4, and every point lies in the box.
    let y = |name: &str| find(&v, name).2;
    assert!(y("V1") > y("(V4)"));
    for l in &v {
        assert!((0.0..=SIZE).contains(&l.1) && (0.0..=SIZE).contains(&l.2), "{l:?}");
    }
    assert!(svg.contains("<title>透視図</title>"));
}

#[test]
fn a_vertex_is_hidden_only_when_a_visible_face_covers_it() {
    // A corner of a cube-like tetrahedron: V0 at the origin, V1–V3 on the axes. From +z only
    // the slanted face {V1, V2, V3} (normal (1, 1, 1)/√3) is visible; the three faces at V0
    // face −x, −y (edge-on) and −z (away). V0 lies exactly behind V3: hidden.
    let v = vec![Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
    let f = vec![[1, 2, 3], [0, 2, 1], [0, 3, 2], [0, 1, 3]];
    let p = crate::derive::polygon_from_data(Text::from("corner"), v, f, None);
    let front = layout(&p, View::Front);
    let names: Vec<&str> = front.vertices.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(names, ["(V0)", "V1", "V2", "V3"]);
    // From +x the slanted face is visible too; V0 is again behind the corner V1.
    let side = layout(&p, View::Side);
    assert_eq!(side.vertices[0].text, "(V0)");
    // A single triangle seen from behind: the face is hidden, but nothing covers its
    // vertices, so they are on the silhouette and stay visible.
    let back = crate::derive::polygon_from_data(
        Text::from("back"),
        vec![Vec3::ZERO, Vec3::Y, Vec3::X],
        vec![[0, 1, 2]],
        None,
    );
    let fig = layout(&back, View::Front);
    let names: Vec<&str> = fig.vertices.iter().map(|l| l.text.as_str()).collect();
    assert_eq!(names, ["V0", "V1", "V2"]);
    assert_eq!(fig.faces[0].text, "(F0)");
    assert!(fig.edges.iter().all(|e| e.2), "every edge of a hidden face is hidden");
}

#[test]
fn bad_data_lays_out_without_panics_or_nan() {
    let mut p = pyramid();
    p.vertices.push(Vec3::new(f32::NAN, 0.0, 0.0));
    p.faces.push([0, 1, 9]);
    p.faces.push([5, 1, 2]);
    p.faces.push([0, 0, 1]);
    p.derived_normals.extend([None, None, None]);
    for view in View::ALL {
        let fig = layout(&p, view);
        assert_eq!(fig.vertices.len(), 5, "the NaN vertex is left out");
        assert_eq!(fig.faces.len(), 7, "faces naming missing or NaN vertices are left out");
        assert_eq!(fig.faces[6].text, "(F8)", "a degenerate face is not visible");
        for lang in [Lang::Ja, Lang::En] {
            let s = svg(&fig, lang);
            texts(&s, "vertex");
            assert!(!s.contains("NaN") && !s.contains("inf"), "{s}");
            assert_balanced(&tikz(&fig, lang));
        }
    }
    let empty =
        PolygonData { vertices: vec![], faces: vec![], derived_normals: vec![], ..pyramid() };
    let fig = layout(&empty, View::Perspective);
    assert!(fig.vertices.is_empty() && fig.edges.is_empty());
    texts(&svg(&fig, Lang::En), "vertex");
}

#[test]
fn tikz_has_the_same_geometry() {
    let fig = layout(&pyramid(), View::Front);
    let tex = tikz(&fig, Lang::Ja);
    assert_balanced(&tex);
    assert!(tex.starts_with("\\begin{tikzpicture}[x=0.25mm, y=-0.25mm"));
    assert!(tex.contains("at (120.00,44.40) {V0};"), "{tex}");
    assert!(tex.contains("at (204.00,195.60) {(V2)};"), "{tex}");
    assert_eq!(tex.matches("dashed").count(), 0, "the front view is one triangle");
    assert_eq!(tikz(&layout(&pyramid(), View::Top), Lang::En).matches("dashed").count(), 1);
    assert!(tex.contains("正面図"));
}

#[test]
fn texture_figure_outlines_the_region_at_its_pixels() {
    // A 200 × 100 image, region s ∈ [0.25, 0.75], t ∈ [0.5, 1]: t = 1 is the top edge, so the
    // rectangle spans x 50…150, y 0…50 (SVG y down from the top).
    let t = texture_data();
    let svg = texture_svg(&t, "texture & <1>.png", Lang::En);
    let doc = roxmltree::Document::parse(&svg).expect("XML");
    let rect = doc
        .descendants()
        .find(|n| n.attribute("class") == Some("region"))
        .expect("the region's outline");
    let a = |k: &str| rect.attribute(k).and_then(|v| v.parse::<f32>().ok()).expect("number");
    assert_eq!((a("x"), a("y"), a("width"), a("height")), (50.0, 0.0, 100.0, 50.0));
    let image = doc.descendants().find(|n| n.has_tag_name("image")).expect("the image");
    assert_eq!(
        image.attribute(("http://www.w3.org/1999/xlink", "href")),
        Some("texture & <1>.png")
    );
    // Each corner's label is beside the image, on the corner's side and at its height (they
    // are far enough apart here), joined to the corner's dot by a line; none covers the image.
    let c = texts(&svg, "corner");
    assert_eq!(c.len(), 4);
    for (text, corner, right) in [
        ("(0.250, 0.500)", (50.0, 50.0), false),
        ("(0.750, 0.500)", (150.0, 50.0), true),
        ("(0.750, 1.000)", (150.0, 0.0), true),
        ("(0.250, 1.000)", (50.0, 0.0), false),
    ] {
        let l = find(&c, text);
        assert!(if right { l.1 > 200.0 } else { l.1 < 0.0 }, "{text} at x {}", l.1);
        assert!((l.2 - corner.1).abs() < 0.01, "{text} at y {}", l.2);
        let leader = doc.descendants().any(|n| {
            let a = |k: &str| n.attribute(k).and_then(|v| v.parse::<f32>().ok());
            n.attribute("class") == Some("leader")
                && a("x1") == Some(corner.0)
                && a("y1") == Some(corner.1)
                && a("y2") == Some(l.2)
        });
        assert!(leader, "no line from {corner:?} to {text}");
    }
    // Which ground corner gets which region corner: (0, 0) is the far left, at t₀ and s₀.
    let g = texts(&svg, "ground-corner");
    assert_eq!(g.len(), 4);
    assert_at(&g, "ground (i, j) = (0, 0)", (find(&c, "(0.250, 0.500)").1, 50.0));
    assert_at(&g, "ground (i, j) = (10, 10)", (find(&c, "(0.750, 1.000)").1, 0.0));
    assert!(g.iter().chain(&c).all(|l| l.1 < 0.0 || l.1 > 200.0), "{g:?}");
    let ja = texture_svg(&t, "texture.png", Lang::Ja);
    assert!(texts(&ja, "title")[0].0.contains("下端"));
    let tex = texture_tikz(&t, "texture.png", Lang::En);
    assert_balanced(&tex);
    assert!(tex.contains("ground (i, j) = (10, 0)"), "{tex}");
    assert!(tex.contains("\\draw[red!80!black, thin] (0.250,0.500) -- (c0.east);"), "{tex}");
    assert!(tex.contains("(c2) at (1.030,1.000)"), "{tex}");
    assert!(tex.contains("\\draw[red, thick] (0.250,0.500) rectangle (0.750,1.000);"), "{tex}");
    assert!(tex.contains("x=5.00cm, y=2.50cm"), "{tex}");
}

#[test]
fn a_sides_labels_that_would_overlap_are_pushed_apart_about_their_middle() {
    assert_eq!(texture::spread([10.0, 50.0], 20.0), [10.0, 50.0]);
    assert_eq!(texture::spread([12.0, 10.0], 20.0), [21.0, 1.0]);
    assert_eq!(texture::spread([5.0, 5.0], 4.0), [3.0, 7.0]);
}

/// Compiles the TikZ figures and the LaTeX tables with LuaLaTeX (`ltjsarticle`, as the
/// template does) when `lualatex` is on PATH; prints a note and passes otherwise.
#[test]
fn tikz_and_tables_compile_with_lualatex() {
    use crate::model::PolygonData;
    use crate::tables;
    use crate::template::Format;
    let found = std::process::Command::new("lualatex")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if !found {
        eprintln!("note: lualatex is not on PATH; the LaTeX compile test is skipped");
        return;
    }
    let dir = std::env::temp_dir().join(format!("cg-report-tikz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let t = texture_data();
    let image = cg_core::image::Image::new(
        t.image.width,
        t.image.height,
        cg_core::glam::Vec3::new(0.2, 0.6, 0.9),
    );
    cg_scene::save_png(&dir.join("texture.png"), &image).expect("png");
    let mut p: PolygonData = pyramid();
    p.transform = Some(
        cg_core::product::MatrixProduct::identity()
            .then(cg_core::product::Factor::translate(Vec3::new(0.0, 1.0, 0.0))),
    );
    let cam = crate::tables::tests::camera();
    let mut body = String::new();
    for lang in [Lang::Ja, Lang::En] {
        for view in View::ALL {
            body += &tikz(&layout(&p, view), lang);
            body += "\n";
        }
        body += &texture_tikz(&t, "texture.png", lang);
        body += "\n";
        body += &tables::vertex_table(&p, lang, Format::Latex);
        body += &tables::face_table(&p, lang, Format::Latex);
        body += &tables::transform(&p, lang, Format::Latex);
        body += &tables::matrices(std::slice::from_ref(&cam), lang, Format::Latex);
        body += &tables::variables(&cam.variables, lang, Format::Latex);
        body += &tables::formula(&t, lang, Format::Latex);
        body += &tables::tex_table(&t, lang, Format::Latex);
    }
    let doc = format!(
        "\\documentclass[a4paper,11pt]{{ltjsarticle}}\n\\usepackage{{amsmath}}\n\\usepackage{{graphicx}}\n\\usepackage{{booktabs}}\n\\usepackage{{longtable}}\n\\usepackage{{tikz}}\n\\setcounter{{MaxMatrixCols}}{{20}}\n\\begin{{document}}\n{body}\\end{{document}}\n"
    );
    std::fs::write(dir.join("figures.tex"), doc).expect("write tex");
    let out = std::process::Command::new("lualatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "figures.tex"])
        .current_dir(&dir)
        .output()
        .expect("lualatex runs");
    let log = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "lualatex failed:\n{}", &log[log.len().saturating_sub(3000)..]);
    assert!(dir.join("figures.pdf").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// A model too large to draw (100 000 vertex rows in a `--data` file, a `vertices()` gone
/// wrong): the figure says so in its place, at once; its labels and edges, laid out by
/// comparing pairs, took `report fill` tens of minutes.
#[test]
fn a_model_too_large_to_draw_says_so_in_the_figure() {
    let small = pyramid();
    let v: Vec<Vec3> = (0..100_000).map(|i| Vec3::new(i as f32, (i % 7) as f32, 0.0)).collect();
    let big = crate::derive::polygon_from_data(
        Text::new("多すぎる", "too many"),
        v,
        small.faces.clone(),
        None,
    );
    for view in [View::Front, View::Perspective] {
        let fig = layout(&big, view);
        assert!(fig.vertices.is_empty() && fig.edges.is_empty(), "{view:?}");
        let svg = svg(&fig, Lang::En);
        let note = texts(&svg, "note");
        assert_eq!(note.len(), 1, "{svg}");
        assert!(note[0].0.starts_with("100000 vertices, 6 faces: too many to draw"), "{note:?}");
        let tikz = tikz(&fig, Lang::Ja);
        assert!(tikz.contains("図にするには多すぎます"), "{tikz}");
        assert_balanced(&tikz);
    }
    // The course's model is drawn, with no note.
    let fig = layout(&small, View::Front);
    assert!(fig.note.is_none() && !fig.vertices.is_empty());
}
