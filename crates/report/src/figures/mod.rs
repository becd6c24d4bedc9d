//! The report's figures: the three views (xy, xz, yz) and a perspective view of the polygon
//! model with vertex and face labels — hidden vertices and faces in parentheses, as the lecture
//! does (「括弧付きの頂点・面は裏側の頂点・面を表す」) — and the texture image with the mapped
//! rectangle outlined. Each figure is laid out once ([`layout`]) and written as standalone SVG
//! ([`svg`], for Markdown) or as a TikZ picture ([`tikz`], for LaTeX) with the same geometry.
//!
//! Figure units: the drawing fits a [`SIZE`]×[`SIZE`] box with a [`MARGIN`] on every side, the
//! model's up (+y on the screen) pointing down the page as SVG's y does; a caption band of
//! [`CAPTION`] units below the box holds the title and the axes.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use cg_core::glam::{Mat4, Vec2, Vec3};
use cg_core::lang::Lang;
use cg_core::normals::face_normal;
use cg_core::transform::look_at;
use cg_harness::Text;

use crate::model::PolygonData;
use crate::template::latex_escape;

mod texture;

pub use texture::{texture_svg, texture_tikz};

/// The width and height of a view's drawing box, in figure units.
pub const SIZE: f32 = 240.0;
/// The space left on every side of the drawing box for labels.
pub const MARGIN: f32 = 36.0;
/// The height of the caption band below the drawing box (title and axes).
pub const CAPTION: f32 = 36.0;
/// One figure unit in TikZ (240 units = 6 cm).
const TIKZ_UNIT_MM: f32 = 0.25;

/// How far outside a face's outline (in figure units) a point still counts as covered by it:
/// a vertex exactly behind a visible corner or edge is hidden.
const COVER_EPS: f32 = 0.05;

/// A face counts as facing the viewer when `n · (direction to the viewer) > FACING_EPS`; a face
/// seen edge-on is not visible.
const FACING_EPS: f32 = 1e-4;

/// The most vertices a figure draws. The course's models have tens; a figure of more could not
/// be read, and its labels and edges are laid out by comparing pairs (100 000 vertex rows in a
/// `--data` file took `report fill` tens of minutes). A larger model's figure says so instead.
pub const MAX_DRAWN_VERTICES: usize = 2_000;

/// The most faces a figure draws (see [`MAX_DRAWN_VERTICES`]).
pub const MAX_DRAWN_FACES: usize = 4_000;

/// Which view of the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum View {
    /// The xy plane, seen from +z (screen right = +x, up = +y).
    Front,
    /// The xz plane, seen from +y (screen right = +x, up = −z).
    Top,
    /// The yz plane, seen from +x (screen right = −z, up = +y).
    Side,
    /// A perspective view from a fixed oblique eye, (3, 2.5, 4) times the model's size away
    /// from its centre, looking at the centre with a 30° field of view.
    Perspective,
}

impl View {
    /// The four views, in the order the report shows them.
    pub const ALL: [View; 4] = [View::Front, View::Top, View::Side, View::Perspective];

    /// The view's title: `正面図 (xy 平面)` / `front view (xy plane)`.
    #[must_use]
    pub fn title(self) -> Text {
        match self {
            View::Front => {
                Text::new("正面図 (xy 平面、+z 方向から)", "front view (xy plane, from +z)")
            }
            View::Top => Text::new("上面図 (xz 平面、+y 方向から)", "top view (xz plane, from +y)"),
            View::Side => {
                Text::new("側面図 (yz 平面、+x 方向から)", "side view (yz plane, from +x)")
            }
            View::Perspective => Text::new("透視図", "perspective view"),
        }
    }

    /// A short name for files and ids: `front`, `top`, `side`, `perspective`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            View::Front => "front",
            View::Top => "top",
            View::Side => "side",
            View::Perspective => "perspective",
        }
    }
}

/// A label in a figure: a vertex (`V0`) or a face (`F4`), in parentheses when hidden.
#[derive(Clone, Debug, PartialEq)]
pub struct Label {
    /// `V0`, or `(V3)` when hidden.
    pub text: String,
    /// Where the labelled point is, in figure units (y down).
    pub at: Vec2,
    /// Whether the vertex or face is hidden from this view.
    pub hidden: bool,
}

/// One laid-out view: everything in figure units, y pointing down.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// Which view.
    pub view: View,
    /// The drawing box's width.
    pub width: f32,
    /// The drawing box's height (the caption band comes below it).
    pub height: f32,
    /// The model's edges, hidden ones (`true`, drawn dashed) first; a hidden edge that lies
    /// exactly on a visible one is left out.
    pub edges: Vec<(Vec2, Vec2, bool)>,
    /// One label per vertex that can be drawn, at the vertex.
    pub vertices: Vec<Label>,
    /// One label per face that can be drawn, at its projected centroid.
    pub faces: Vec<Label>,
    /// The model axes as the screen shows them: a unit direction in figure units and the axis
    /// name (`x`, `y`, `z`); axes seen end-on are left out.
    pub axes: Vec<(Vec2, String)>,
    /// Why nothing is drawn, shown in the drawing's place: a model over [`MAX_DRAWN_VERTICES`]
    /// or [`MAX_DRAWN_FACES`].
    pub note: Option<Text>,
}

/// How one view projects: a point to the screen (y up, any scale) or `None` behind the eye,
/// and the direction from a point towards the viewer.
struct Projector {
    view: View,
    /// The model's size: the largest distance of a vertex from the bounding box's centre.
    size: f32,
    look: Mat4,
    eye: Vec3,
}

impl Projector {
    fn new(view: View, points: &[Vec3]) -> Projector {
        let (lo, hi) = points
            .iter()
            .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
        let centre = if points.is_empty() { Vec3::ZERO } else { (lo + hi) * 0.5 };
        let radius = points.iter().map(|p| p.distance(centre)).fold(0.0_f32, f32::max);
        let size = if radius.is_finite() && radius > 1e-6 { radius } else { 1.0 };
        let eye = centre + Vec3::new(3.0, 2.5, 4.0) * size;
        let look = look_at(eye, centre, Vec3::Y).unwrap_or(Mat4::IDENTITY);
        Projector { view, size, look, eye }
    }

    /// The screen position, y up (before fitting). The perspective divides by the distance
    /// along the view axis (a 30° field of view only scales, and the figure is fitted anyway).
    fn project(&self, p: Vec3) -> Option<Vec2> {
        let s = match self.view {
            View::Front => Vec2::new(p.x, p.y),
            View::Top => Vec2::new(p.x, -p.z),
            View::Side => Vec2::new(-p.z, p.y),
            View::Perspective => {
                let c = self.look.transform_point3(p);
                if c.z.is_nan() || c.z >= -1e-6 {
                    return None;
                }
                let focal = 1.0 / (15.0_f32.to_radians()).tan();
                Vec2::new(c.x, c.y) * (focal / -c.z)
            }
        };
        s.is_finite().then_some(s)
    }

    /// The direction from `p` towards the viewer (not normalised).
    fn towards_viewer(&self, p: Vec3) -> Vec3 {
        match self.view {
            View::Front => Vec3::Z,
            View::Top => Vec3::Y,
            View::Side => Vec3::X,
            View::Perspective => self.eye - p,
        }
    }
}

/// Whether `p` lies in the triangle `t`, edges included: at most [`COVER_EPS`] figure units
/// outside any edge.
fn in_triangle(p: Vec2, t: [Vec2; 3]) -> bool {
    let cross = |a: Vec2, b: Vec2, c: Vec2| (b - a).perp_dot(c - a);
    let area = cross(t[0], t[1], t[2]);
    if area.abs() < 1e-6 {
        return false;
    }
    (0..3).all(|k| {
        let (a, b) = (t[k], t[(k + 1) % 3]);
        let len = a.distance(b).max(1e-6);
        cross(a, b, p) * area.signum() / len >= -COVER_EPS
    })
}

/// Lays out one view of `p`: projects every vertex, decides which faces face the viewer (their
/// derived normal · the direction to the viewer > 0; edge-on faces do not), which vertices are
/// hidden (used by no visible face and covered by a visible face in front of them — a vertex on
/// the silhouette stays visible), which edges are hidden (every face along them hidden), and
/// fits the drawing into [`SIZE`]×[`SIZE`] with [`MARGIN`], model up → page up. Vertices that
/// are not finite and faces naming vertices that do not exist are left out; never panics.
#[must_use]
pub fn layout(p: &PolygonData, view: View) -> Figure {
    let (vertices, faces) = (p.vertices.len(), p.faces.len());
    if vertices > MAX_DRAWN_VERTICES || faces > MAX_DRAWN_FACES {
        return Figure {
            view,
            width: SIZE,
            height: SIZE,
            edges: Vec::new(),
            vertices: Vec::new(),
            faces: Vec::new(),
            axes: Vec::new(),
            note: Some(Text::new(
                format!(
                    "頂点 {vertices} 個・面 {faces} 枚: 図にするには多すぎます（頂点 {MAX_DRAWN_VERTICES} 個・面 {MAX_DRAWN_FACES} 枚まで）"
                ),
                format!(
                    "{vertices} vertices, {faces} faces: too many to draw (at most {MAX_DRAWN_VERTICES} vertices and {MAX_DRAWN_FACES} faces)"
                ),
            )),
        };
    }
    let finite: Vec<Vec3> = p.vertices.iter().copied().filter(|v| v.is_finite()).collect();
    let proj = Projector::new(view, &finite);
    let screen: Vec<Option<Vec2>> =
        p.vertices.iter().map(|&v| if v.is_finite() { proj.project(v) } else { None }).collect();

    // Fit: uniform scale, centred, y flipped.
    let (lo, hi) = screen
        .iter()
        .flatten()
        .fold((Vec2::INFINITY, Vec2::NEG_INFINITY), |(lo, hi), s| (lo.min(*s), hi.max(*s)));
    let (lo, hi) = if lo.x <= hi.x { (lo, hi) } else { (Vec2::ZERO, Vec2::ZERO) };
    let extent = (hi - lo).max_element();
    let scale = if extent > 1e-9 { (SIZE - 2.0 * MARGIN) / extent } else { 1.0 };
    let mid = (lo + hi) * 0.5;
    let centre = Vec2::splat(SIZE / 2.0);
    let fit =
        |s: Vec2| Vec2::new(centre.x + (s.x - mid.x) * scale, centre.y - (s.y - mid.y) * scale);
    let at: Vec<Option<Vec2>> = screen.iter().map(|s| s.map(fit)).collect();

    // Faces: corners (when every vertex exists and is finite), normal, visibility.
    let corners = |f: &[u32; 3]| -> Option<[Vec3; 3]> {
        let v = |k: usize| p.vertices.get(f[k] as usize).copied().filter(|v| v.is_finite());
        Some([v(0)?, v(1)?, v(2)?])
    };
    let faces: Vec<Option<([Vec3; 3], bool)>> = p
        .faces
        .iter()
        .enumerate()
        .map(|(k, f)| {
            let c = corners(f)?;
            let n = match p.derived_normals.get(k) {
                Some(n) => *n,
                None => face_normal(c[0], c[1], c[2]),
            };
            let visible = n.is_some_and(|n| {
                let to = proj.towards_viewer((c[0] + c[1] + c[2]) / 3.0).normalize_or_zero();
                n.dot(to) > FACING_EPS
            });
            Some((c, visible))
        })
        .collect();
    let is_visible = |k: usize| faces[k].is_some_and(|(_, v)| v);

    // Vertices.
    let mut used_by_visible = vec![false; p.vertices.len()];
    for (k, f) in p.faces.iter().enumerate() {
        if is_visible(k) {
            for &v in f {
                if let Some(u) = used_by_visible.get_mut(v as usize) {
                    *u = true;
                }
            }
        }
    }
    let world_eps = 1e-5 * finite.iter().map(|v| v.length()).fold(1.0_f32, f32::max);
    let covered = |v: Vec3, s: Vec2| {
        p.faces.iter().enumerate().any(|(k, f)| {
            let Some((c, true)) = faces[k] else { return false };
            let tri = [at[f[0] as usize], at[f[1] as usize], at[f[2] as usize]];
            let (Some(a), Some(b), Some(d)) = (tri[0], tri[1], tri[2]) else { return false };
            let Some(n) = face_normal(c[0], c[1], c[2]) else { return false };
            in_triangle(s, [a, b, d]) && n.dot(v - c[0]) < -world_eps
        })
    };
    let vertices: Vec<Label> = p
        .vertices
        .iter()
        .enumerate()
        .filter_map(|(k, &v)| {
            let s = at[k]?;
            let hidden = !used_by_visible[k] && covered(v, s);
            let text = if hidden { format!("(V{k})") } else { format!("V{k}") };
            Some(Label { text, at: s, hidden })
        })
        .collect();

    // Face labels at the projected centroid.
    let face_labels: Vec<Label> = faces
        .iter()
        .enumerate()
        .filter_map(|(k, f)| {
            let (c, visible) = (*f)?;
            let s = proj.project((c[0] + c[1] + c[2]) / 3.0).map(fit)?;
            let text = if visible { format!("F{k}") } else { format!("(F{k})") };
            Some(Label { text, at: s, hidden: !visible })
        })
        .collect();

    // Edges: hidden when every face along them is hidden.
    let mut edge_faces: BTreeMap<(u32, u32), Vec<usize>> = BTreeMap::new();
    for (k, f) in p.faces.iter().enumerate() {
        if faces[k].is_none() {
            continue;
        }
        for e in 0..3 {
            let (a, b) = (f[e], f[(e + 1) % 3]);
            edge_faces.entry((a.min(b), a.max(b))).or_default().push(k);
        }
    }
    let mut hidden_edges = Vec::new();
    let mut visible_edges = Vec::new();
    for ((a, b), fs) in &edge_faces {
        let (Some(Some(pa)), Some(Some(pb))) = (at.get(*a as usize), at.get(*b as usize)) else {
            continue;
        };
        if pa.distance(*pb) < 1e-3 {
            continue;
        }
        if fs.iter().any(|&k| is_visible(k)) {
            visible_edges.push((*pa, *pb, false));
        } else {
            hidden_edges.push((*pa, *pb, true));
        }
    }
    // A hidden edge drawn exactly over a visible one (or over another hidden one) is left out:
    // the visible line wins, as in a drawing (the front view of the pyramid is one triangle).
    let same = |a: &(Vec2, Vec2, bool), b: &(Vec2, Vec2, bool)| {
        let close = |p: Vec2, q: Vec2| p.distance(q) < 0.01;
        (close(a.0, b.0) && close(a.1, b.1)) || (close(a.0, b.1) && close(a.1, b.0))
    };
    let mut edges: Vec<(Vec2, Vec2, bool)> = Vec::new();
    for e in &hidden_edges {
        if !visible_edges.iter().chain(&edges).any(|o| same(e, o)) {
            edges.push(*e);
        }
    }
    edges.extend(visible_edges);

    // The model axes on the screen.
    let origin = if finite.is_empty() {
        Vec3::ZERO
    } else {
        finite.iter().sum::<Vec3>() / finite.len() as f32
    };
    let step = 0.1 * proj.size;
    let axes = [(Vec3::X, "x"), (Vec3::Y, "y"), (Vec3::Z, "z")]
        .into_iter()
        .filter_map(|(axis, name)| {
            let o = proj.project(origin)?;
            let e = proj.project(origin + axis * step)?;
            let d = Vec2::new(e.x - o.x, o.y - e.y); // y down
            let len = d.length();
            (len > 1e-3 * step).then(|| (d / len, name.to_owned()))
        })
        .collect();

    Figure {
        view,
        width: SIZE,
        height: SIZE,
        edges,
        vertices,
        faces: face_labels,
        axes,
        note: None,
    }
}

/// `1.50`: a coordinate with two decimals (never `-0.00`).
fn num(x: f32) -> String {
    cg_core::notation::fixed(x, 2)
}

/// Text made safe for XML content and attribute values.
fn xml_escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            c if (c as u32) < 0x20 && c != '\n' && c != '\t' => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// Where a label's text goes relative to its point: a unit direction (y down) away from the
/// drawing's centre for vertices, none for faces (centred), and a stacking index for labels
/// whose texts would overlap (points that share a place, or lie closer than a label's width
/// across and a line's height down: `V12` beside `V11`, the faces seen edge on).
struct Placement {
    dir: Vec2,
    stack: usize,
}

fn placements(labels: &[Label], centre: Vec2, outward: bool) -> Vec<Placement> {
    labels
        .iter()
        .enumerate()
        .map(|(k, l)| {
            let stack = labels[..k].iter().filter(|o| overlap(o, l)).count();
            let dir = if outward {
                let d = l.at - centre;
                if d.length() > 1e-3 { d / d.length() } else { Vec2::new(0.0, -1.0) }
            } else {
                Vec2::ZERO
            };
            Placement { dir, stack }
        })
        .collect()
}

/// Whether the texts of two labels would overlap where they are drawn: closer than the wider
/// one's width across (about 0.62 em a character, 11-unit type) and a line's height down.
fn overlap(a: &Label, b: &Label) -> bool {
    let chars = a.text.chars().count().max(b.text.chars().count()) as f32;
    (a.at.x - b.at.x).abs() < 0.62 * 11.0 * chars && (a.at.y - b.at.y).abs() < LINE
}

/// The line height used to stack labels that share a point.
const LINE: f32 = 12.0;

/// A standalone SVG 1.1 document of the figure: edges (hidden ones dashed), vertex dots, vertex
/// labels and face labels as `<text>` whose `x`, `y` are exactly the labelled point (the text is
/// moved off the point by `dx`, `dy`), and the title in `lang` with the axes below the drawing.
#[must_use]
pub fn svg(fig: &Figure, lang: Lang) -> String {
    let (w, h) = (fig.width, fig.height + CAPTION);
    let title = fig.view.title();
    let mut s = String::new();
    let _ = writeln!(s, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" version="1.1" width="{}" height="{}" viewBox="0 0 {} {}" font-family="sans-serif" font-size="11">"#,
        num(w),
        num(h),
        num(w),
        num(h)
    );
    let _ = writeln!(s, "<title>{}</title>", xml_escape(title.get(lang)));
    let _ =
        writeln!(s, r#"<rect x="0" y="0" width="{}" height="{}" fill="white"/>"#, num(w), num(h));
    let _ = writeln!(s, r#"<g class="edges" fill="none" stroke-linecap="round">"#);
    for (a, b, hidden) in &fig.edges {
        let style = if *hidden {
            r##"class="hidden" stroke="#888888" stroke-width="1" stroke-dasharray="4 3""##
        } else {
            r##"stroke="#000000" stroke-width="1.5""##
        };
        let _ = writeln!(
            s,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" {style}/>"#,
            num(a.x),
            num(a.y),
            num(b.x),
            num(b.y)
        );
    }
    let _ = writeln!(s, "</g>");
    if let Some(note) = &fig.note {
        let _ = writeln!(
            s,
            r#"<text class="note" x="{}" y="{}" text-anchor="middle">{}</text>"#,
            num(fig.width / 2.0),
            num(fig.height / 2.0),
            xml_escape(note.get(lang))
        );
    }
    let _ = writeln!(s, r#"<g class="points">"#);
    for l in &fig.vertices {
        let style = if l.hidden {
            r##"fill="#ffffff" stroke="#888888""##
        } else {
            r##"fill="#000000" stroke="none""##
        };
        let _ = writeln!(s, r#"<circle cx="{}" cy="{}" r="2" {style}/>"#, num(l.at.x), num(l.at.y));
    }
    let _ = writeln!(s, "</g>");
    let centre = Vec2::new(fig.width / 2.0, fig.height / 2.0);
    let _ = writeln!(s, r#"<g class="vertex-labels">"#);
    for (l, pl) in fig.vertices.iter().zip(placements(&fig.vertices, centre, true)) {
        let anchor = if pl.dir.x > 0.35 {
            "start"
        } else if pl.dir.x < -0.35 {
            "end"
        } else {
            "middle"
        };
        let down = pl.dir.y >= 0.0;
        let dx = pl.dir.x * 6.0;
        let base = if down { pl.dir.y * 6.0 + 9.0 } else { pl.dir.y * 6.0 - 2.0 };
        let dy = base + if down { 1.0 } else { -1.0 } * LINE * pl.stack as f32;
        let fill = if l.hidden { "#666666" } else { "#000000" };
        let _ = writeln!(
            s,
            r#"<text class="vertex" x="{}" y="{}" dx="{}" dy="{}" text-anchor="{anchor}" fill="{fill}">{}</text>"#,
            num(l.at.x),
            num(l.at.y),
            num(dx),
            num(dy),
            xml_escape(&l.text)
        );
    }
    let _ = writeln!(s, "</g>");
    let _ = writeln!(s, r#"<g class="face-labels" font-style="italic">"#);
    for (l, pl) in fig.faces.iter().zip(placements(&fig.faces, centre, false)) {
        let fill = if l.hidden { "#7777cc" } else { "#0000aa" };
        let dy = 4.0 + LINE * pl.stack as f32;
        let _ = writeln!(
            s,
            r#"<text class="face" x="{}" y="{}" dy="{}" text-anchor="middle" fill="{fill}">{}</text>"#,
            num(l.at.x),
            num(l.at.y),
            num(dy),
            xml_escape(&l.text)
        );
    }
    let _ = writeln!(s, "</g>");
    // Caption band: axes at the left, title centred.
    let o = Vec2::new(20.0, fig.height + CAPTION / 2.0);
    let _ = writeln!(s, r##"<g class="axes" stroke="#cc0000" fill="#cc0000" font-size="9">"##);
    for (d, name) in &fig.axes {
        let e = o + *d * 9.0;
        let t = o + *d * 14.0;
        let _ = writeln!(
            s,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke-width="1"/>"#,
            num(o.x),
            num(o.y),
            num(e.x),
            num(e.y)
        );
        let _ = writeln!(
            s,
            r#"<text class="axis" x="{}" y="{}" dy="3" text-anchor="middle" stroke="none">{}</text>"#,
            num(t.x),
            num(t.y),
            xml_escape(name)
        );
    }
    let _ = writeln!(s, "</g>");
    let _ = writeln!(
        s,
        r#"<text class="title" x="{}" y="{}" text-anchor="middle">{}</text>"#,
        num(fig.width / 2.0 + 14.0),
        num(fig.height + CAPTION / 2.0 + 4.0),
        xml_escape(title.get(lang))
    );
    s.push_str("</svg>\n");
    s
}

/// The TikZ anchor that puts a node on the side `dir` (y down) of its point.
fn tikz_anchor(dir: Vec2) -> &'static str {
    // The node lies towards `dir`, so its anchor is on the opposite side.
    let horiz = if dir.x > 0.35 {
        "west"
    } else if dir.x < -0.35 {
        "east"
    } else {
        ""
    };
    let vert = if dir.y > 0.35 {
        "north"
    } else if dir.y < -0.35 {
        "south"
    } else {
        ""
    };
    match (vert, horiz) {
        ("", "") => "south",
        ("", h) => h,
        (v, "") => v,
        ("north", "west") => "north west",
        ("north", _) => "north east",
        (_, "west") => "south west",
        _ => "south east",
    }
}

/// A TikZ picture of the figure with the same geometry as [`svg`]: figure units as
/// `x = 0.25 mm, y = −0.25 mm` (so the coordinates are the same numbers, y down), hidden edges
/// dashed, labels as nodes at the labelled points, the title below.
#[must_use]
pub fn tikz(fig: &Figure, lang: Lang) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\\begin{{tikzpicture}}[x={TIKZ_UNIT_MM}mm, y=-{TIKZ_UNIT_MM}mm, font=\\small]"
    );
    let _ = writeln!(
        s,
        "\\path[use as bounding box] (0,0) rectangle ({},{});",
        num(fig.width),
        num(fig.height + CAPTION)
    );
    if let Some(note) = &fig.note {
        let _ = writeln!(
            s,
            "\\node[text width={}mm, align=center] at ({},{}) {{{}}};",
            num(fig.width * TIKZ_UNIT_MM * 0.9),
            num(fig.width / 2.0),
            num(fig.height / 2.0),
            latex_escape(note.get(lang))
        );
    }
    for (a, b, hidden) in &fig.edges {
        let style = if *hidden { "gray, dashed" } else { "black, thick" };
        let _ = writeln!(
            s,
            "\\draw[{style}] ({},{}) -- ({},{});",
            num(a.x),
            num(a.y),
            num(b.x),
            num(b.y)
        );
    }
    for l in &fig.vertices {
        let style = if l.hidden { "draw=gray, fill=white" } else { "fill=black" };
        let _ =
            writeln!(s, "\\filldraw[{style}] ({},{}) circle (1.2pt);", num(l.at.x), num(l.at.y));
    }
    let centre = Vec2::new(fig.width / 2.0, fig.height / 2.0);
    for (l, pl) in fig.vertices.iter().zip(placements(&fig.vertices, centre, true)) {
        let color = if l.hidden { "gray" } else { "black" };
        let shift = if pl.dir.y >= 0.0 { -1.0 } else { 1.0 } * 9.0 * pl.stack as f32;
        let _ = writeln!(
            s,
            "\\node[anchor={}, inner sep=2pt, text={color}, yshift={}pt] at ({},{}) {{{}}};",
            tikz_anchor(pl.dir),
            num(shift),
            num(l.at.x),
            num(l.at.y),
            latex_escape(&l.text)
        );
    }
    for (l, pl) in fig.faces.iter().zip(placements(&fig.faces, centre, false)) {
        let color = if l.hidden { "blue!50" } else { "blue!70!black" };
        let shift = -9.0 * pl.stack as f32;
        let _ = writeln!(
            s,
            "\\node[inner sep=1pt, text={color}, font=\\small\\itshape, yshift={}pt] at ({},{}) {{{}}};",
            num(shift),
            num(l.at.x),
            num(l.at.y),
            latex_escape(&l.text)
        );
    }
    let o = Vec2::new(20.0, fig.height + CAPTION / 2.0);
    for (d, name) in &fig.axes {
        let e = o + *d * 9.0;
        let t = o + *d * 14.0;
        let _ = writeln!(
            s,
            "\\draw[red!80!black, ->] ({},{}) -- ({},{});\n\\node[text=red!80!black, font=\\scriptsize] at ({},{}) {{${}$}};",
            num(o.x),
            num(o.y),
            num(e.x),
            num(e.y),
            num(t.x),
            num(t.y),
            latex_escape(name)
        );
    }
    let _ = writeln!(
        s,
        "\\node at ({},{}) {{{}}};",
        num(fig.width / 2.0 + 14.0),
        num(fig.height + CAPTION / 2.0),
        latex_escape(fig.view.title().get(lang))
    );
    s.push_str("\\end{tikzpicture}\n");
    s
}

#[cfg(test)]
mod tests;
