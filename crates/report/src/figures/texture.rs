//! The texture figure of the report's a4 section: the prepared image with the mapped region
//! outlined, each of the region's corners labelled in the margin with its `(s, t)` and the
//! ground corner `(i, j)` the student's coordinates put there, joined to it by a line, so no
//! label covers the image's cell names.

use std::fmt::Write as _;

use cg_core::glam::Vec2;
use cg_core::lang::Lang;
use cg_harness::Text;

use super::{num, xml_escape};
use crate::model::TextureData;
use crate::tables::fixed;
use crate::template::latex_escape;

/// The texture figure's geometry in image pixels (x right, y down from the image's top edge):
/// the region's corners `[(s₀, t₀), (s₁, t₀), (s₁, t₁), (s₀, t₁)]` with their pixel positions.
fn region_corners(t: &TextureData) -> Option<[(Vec2, Vec2); 4]> {
    let (w, h) = (t.image.width.max(1) as f32, t.image.height.max(1) as f32);
    let (lo, hi) = t.region;
    if !(lo.is_finite() && hi.is_finite()) {
        return None;
    }
    let px = |st: Vec2| Vec2::new(st.x * w, (1.0 - st.y) * h);
    let st = [lo, Vec2::new(hi.x, lo.y), hi, Vec2::new(lo.x, hi.y)];
    Some(st.map(|c| (c, px(c))))
}

/// The texture figure's title.
fn texture_title() -> Text {
    Text::new(
        "テクスチャ画像（赤枠: 地面に貼る範囲、t = 0 が下端）",
        "the texture image (red: the region on the ground; t = 0 at the bottom)",
    )
}

/// The ground corners (`(i, j)` with `i, j ∈ {0, 10}`) whose texture coordinates the student's
/// `tex_coords` put at the region's corner `st`: `ground (i, j) = (0, 10)`, or nothing.
fn ground_label(t: &TextureData, st: Vec2) -> Option<Text> {
    let found: Vec<String> = t
        .rows
        .iter()
        .filter(|r| matches!(r.i, 0 | 10) && matches!(r.j, 0 | 10))
        .filter(|r| r.tex.iter().any(|c| c.distance(st) < 0.005))
        .map(|r| format!("({}, {})", r.i, r.j))
        .collect();
    (!found.is_empty()).then(|| {
        let list = found.join(", ");
        Text::new(format!("地面の頂点 (i, j) = {list}"), format!("ground (i, j) = {list}"))
    })
}

/// Where a side's two labels go: at their corners' heights `ys` (y down), pushed apart to at
/// least `gap` between them, about their middle.
pub(super) fn spread(ys: [f32; 2], gap: f32) -> [f32; 2] {
    let (top, bottom) = if ys[0] <= ys[1] { (0, 1) } else { (1, 0) };
    let apart = ys[bottom] - ys[top];
    if apart >= gap {
        return ys;
    }
    let mid = (ys[0] + ys[1]) / 2.0;
    let mut out = ys;
    out[top] = mid - gap / 2.0;
    out[bottom] = mid + gap / 2.0;
    out
}

/// The region's corners by side, the `s₀` side and the `s₁` side, each `[t₀, t₁]` by index into
/// `[(s₀, t₀), (s₁, t₀), (s₁, t₁), (s₀, t₁)]`.
const SIDES: [[usize; 2]; 2] = [[0, 3], [1, 2]];

/// Whether side `side` of [`SIDES`] is labelled right of the image: the side further right
/// (`xs`: each side's x; a mirrored region's `s₀` side is on the right).
fn on_right(xs: [f32; 2], side: usize) -> bool {
    xs[side] > xs[1 - side] || (xs[side] == xs[1 - side] && side == 1)
}

/// A standalone SVG 1.1 document: the image (`image_href`, saved next to the report) at one
/// figure unit per texel, the mapped rectangle `t.region` outlined in red with a dot at each
/// corner, and each corner's label in the margin beside the image (its `(s, t)`, and below it
/// the ground corner that gets it) joined to the dot by a line (`class="leader"`). The image's
/// own corners `(0, 0)` (bottom left) and `(1, 1)` (top right) and its axes are written above and
/// below it. Texture coordinate t = 0 is the image's bottom edge, so the corner (s, t) is at
/// pixel (s·width, (1 − t)·height) from the top left.
#[must_use]
pub fn texture_svg(t: &TextureData, image_href: &str, lang: Lang) -> String {
    let (w, h) = (t.image.width.max(1) as f32, t.image.height.max(1) as f32);
    let big = w.max(h);
    let font = (big / 22.0).max(4.0);
    // The side margins hold the corner labels (about 22 characters of 0.6 em); a line of the
    // image's own labels above and below, and the title.
    let (mx, my) = (font * 14.0, font * 3.0);
    let corners = region_corners(t);
    // The viewBox holds the image, the region (even beyond the image) and the margins.
    let (mut lo, mut hi) = (Vec2::ZERO, Vec2::new(w, h));
    if let Some(c) = &corners {
        for (_, p) in c {
            lo = lo.min(*p);
            hi = hi.max(*p);
        }
    }
    let (x0, y0) = (lo.x - mx, lo.y - my);
    let (vw, vh) = (hi.x - lo.x + 2.0 * mx, hi.y - lo.y + 2.0 * my + font * 1.5);
    let display_w = 560.0;
    let display_h = display_w * vh / vw;
    let mut s = String::new();
    let _ = writeln!(s, r#"<?xml version="1.0" encoding="UTF-8"?>"#);
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" version="1.1" width="{}" height="{}" viewBox="{} {} {} {}" font-family="sans-serif" font-size="{}">"#,
        num(display_w),
        num(display_h),
        num(x0),
        num(y0),
        num(vw),
        num(vh),
        num(font)
    );
    let title = texture_title();
    let _ = writeln!(s, "<title>{}</title>", xml_escape(title.get(lang)));
    let _ = writeln!(
        s,
        r#"<rect x="{}" y="{}" width="{}" height="{}" fill="white"/>"#,
        num(x0),
        num(y0),
        num(vw),
        num(vh)
    );
    let href = xml_escape(image_href);
    let _ = writeln!(
        s,
        r#"<image class="texture" x="0" y="0" width="{}" height="{}" preserveAspectRatio="none" xlink:href="{href}"/>"#,
        num(w),
        num(h)
    );
    let _ = writeln!(
        s,
        r##"<rect class="image-border" x="0" y="0" width="{}" height="{}" fill="none" stroke="#444444" stroke-width="{}"/>"##,
        num(w),
        num(h),
        num(big / 400.0)
    );
    let gray = r##"fill="#444444""##;
    // The image's own corners and axes above and below it (the sides are the region's labels').
    let edge = |class: &str, x: f32, below: bool, end: bool, text: &str| {
        format!(
            r#"<text class="{class}" x="{}" y="{}" text-anchor="{}" {gray}>{text}</text>"#,
            num(x),
            num(if below { h + font * 1.1 } else { -font * 0.4 }),
            if end { "end" } else { "start" },
        )
    };
    let _ = writeln!(s, "{}", edge("image-corner", 0.0, true, false, "(0, 0)"));
    let _ = writeln!(s, "{}", edge("image-corner", w, false, true, "(1, 1)"));
    let _ = writeln!(s, "{}", edge("image-axis", w, true, true, "s →"));
    let _ = writeln!(s, "{}", edge("image-axis", 0.0, false, false, "t ↑"));
    if let Some(c) = corners {
        let (a, b) = (c[0].1.min(c[2].1), c[0].1.max(c[2].1));
        let _ = writeln!(
            s,
            r##"<rect class="region" x="{}" y="{}" width="{}" height="{}" fill="none" stroke="#ff0000" stroke-width="{}"/>"##,
            num(a.x),
            num(a.y),
            num(b.x - a.x),
            num(b.y - a.y),
            num(big / 150.0)
        );
        for (side, pair) in SIDES.iter().enumerate() {
            // Left of the image for the region's left corners, right of it for the right ones
            // (by the corners' pixels: a mirrored region's s₀ is on the right).
            let right = on_right([c[0].1.x, c[1].1.x], side);
            let ys = spread([c[pair[0]].1.y, c[pair[1]].1.y], font * 2.4);
            let x = if right { hi.x + font * 0.8 } else { lo.x - font * 0.8 };
            for (&k, y) in pair.iter().zip(ys) {
                let (st, p) = c[k];
                let _ = writeln!(
                    s,
                    r##"<circle cx="{}" cy="{}" r="{}" fill="#ff0000"/>"##,
                    num(p.x),
                    num(p.y),
                    num(big / 120.0)
                );
                let _ = writeln!(
                    s,
                    r##"<line class="leader" x1="{}" y1="{}" x2="{}" y2="{}" stroke="#cc0000" stroke-width="{}"/>"##,
                    num(p.x),
                    num(p.y),
                    num(if right { x - font * 0.2 } else { x + font * 0.2 }),
                    num(y),
                    num(big / 400.0)
                );
                let anchor = if right { "start" } else { "end" };
                let _ = writeln!(
                    s,
                    r##"<text class="corner" x="{}" y="{}" dy="{}" text-anchor="{anchor}" fill="#cc0000">({}, {})</text>"##,
                    num(x),
                    num(y),
                    num(-font * 0.15),
                    fixed(st.x),
                    fixed(st.y)
                );
                if let Some(ground) = ground_label(t, st) {
                    let _ = writeln!(
                        s,
                        r##"<text class="ground-corner" x="{}" y="{}" dy="{}" text-anchor="{anchor}" font-size="{}" {gray}>{}</text>"##,
                        num(x),
                        num(y),
                        num(font * 0.95),
                        num(font * 0.8),
                        xml_escape(ground.get(lang))
                    );
                }
            }
        }
    }
    let _ = writeln!(
        s,
        r#"<text class="title" x="{}" y="{}" text-anchor="middle" font-size="{}">{}</text>"#,
        num(x0 + vw / 2.0),
        num(y0 + vh - font * 0.5),
        num(font * 0.85),
        xml_escape(title.get(lang))
    );
    s.push_str("</svg>\n");
    s
}

/// A TikZ picture of the texture figure: the image (`image_path`, for `\includegraphics`)
/// 5 cm on its longer side, with the axes' unit vectors set to the image's width and height so
/// that texture coordinates are the picture's coordinates (t = 0 at the bottom edge), the
/// mapped rectangle outlined in red, and each corner's `(s, t)` and ground corner beside the
/// image, joined to the corner by a line, as [`texture_svg`] draws them.
#[must_use]
pub fn texture_tikz(t: &TextureData, image_path: &str, lang: Lang) -> String {
    let (w, h) = (t.image.width.max(1) as f32, t.image.height.max(1) as f32);
    // 5 cm, so that the labels beside it fit the text width.
    let (cw, ch) = if w >= h { (5.0, 5.0 * h / w) } else { (5.0 * w / h, 5.0) };
    let mut s = String::new();
    let _ = writeln!(
        s,
        "\\begin{{tikzpicture}}[x={}cm, y={}cm, font=\\footnotesize]",
        num(cw),
        num(ch)
    );
    let _ = writeln!(
        s,
        "\\node[anchor=south west, inner sep=0pt] at (0,0) {{\\includegraphics[width={}cm, height={}cm]{{{image_path}}}}};",
        num(cw),
        num(ch)
    );
    let _ = writeln!(s, "\\draw[gray] (0,0) rectangle (1,1);");
    // The image's own corners and axes above and below it; the sides are the region's labels'.
    let _ = writeln!(s, "\\node[anchor=north west, text=gray] at (0,0) {{$(0, 0)$}};");
    let _ = writeln!(s, "\\node[anchor=south east, text=gray] at (1,1) {{$(1, 1)$}};");
    let _ = writeln!(s, "\\node[anchor=north east, text=gray] at (1,0) {{$s \\rightarrow$}};");
    let _ = writeln!(s, "\\node[anchor=south west, text=gray] at (0,1) {{$t \\uparrow$}};");
    let (lo, hi) = t.region;
    if lo.is_finite() && hi.is_finite() {
        let _ = writeln!(
            s,
            "\\draw[red, thick] ({},{}) rectangle ({},{});",
            fixed(lo.x),
            fixed(lo.y),
            fixed(hi.x),
            fixed(hi.y)
        );
        let corners = [lo, Vec2::new(hi.x, lo.y), hi, Vec2::new(lo.x, hi.y)];
        // Two lines of \footnotesize (about 0.8 cm) between a side's two labels, in picture units.
        let gap = 0.8 / ch;
        let (left, right) = (lo.x.min(hi.x).min(0.0), lo.x.max(hi.x).max(1.0));
        for (side, pair) in SIDES.iter().enumerate() {
            let right_side = on_right([corners[0].x, corners[1].x], side);
            // In picture units y is up: spread on −y as the SVG does on y down.
            let ys = spread([-corners[pair[0]].y, -corners[pair[1]].y], gap).map(|y| -y);
            let (x, anchor, align) = if right_side {
                (right + 0.03, "west", "left")
            } else {
                (left - 0.03, "east", "right")
            };
            for (&k, y) in pair.iter().zip(ys) {
                let c = corners[k];
                let ground = ground_label(t, c)
                    .map(|g| {
                        format!("\\\\\\scriptsize\\color{{black!70}}{}", latex_escape(g.get(lang)))
                    })
                    .unwrap_or_default();
                let _ = writeln!(
                    s,
                    "\\fill[red] ({},{}) circle (1.5pt);\n\\node[anchor={anchor}, align={align}, text=red!80!black, inner sep=1pt] (c{k}) at ({},{}) {{$({}, {})${ground}}};\n\\draw[red!80!black, thin] ({},{}) -- (c{k}.{anchor});",
                    fixed(c.x),
                    fixed(c.y),
                    fixed(x),
                    fixed(y),
                    fixed(c.x),
                    fixed(c.y),
                    fixed(c.x),
                    fixed(c.y)
                );
            }
        }
    }
    let _ = writeln!(
        s,
        "\\node[anchor=north, text width={}cm, align=center] at (0.5,-0.25) {{{}}};",
        num(cw),
        latex_escape(texture_title().get(lang))
    );
    s.push_str("\\end{tikzpicture}\n");
    s
}
