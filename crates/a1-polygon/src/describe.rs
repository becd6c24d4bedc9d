//! The assignment text, like the course's assignment program prints it, in Japanese and English.

use easy_ext::ext;
use std::fmt::Write as _;

use cg_core::lang::{Lang, Text, t};
use cg_core::notation::decimal;

use crate::spec::ShapeExt;
use crate::spec::{Order, Part, PartKind, RidgeAxis, Shape, Spec, Turn, kanji};

/// A length as the text prints it: `1.5`, `2.0`.
fn num(x: f32) -> String {
    decimal(x, 4)
}

/// `hexagon` for 6.
fn gon(n: u32) -> &'static str {
    match n {
        3 => "triangle",
        4 => "square",
        5 => "pentagon",
        6 => "hexagon",
        7 => "heptagon",
        8 => "octagon",
        _ => "polygon",
    }
}

/// A shape's dimensions and parts in words.
#[ext(ShapeDescribe)]
pub(crate) impl Shape {
    /// The dimensions in words.
    fn dimensions(&self) -> Text {
        match *self {
            Shape::Pyramid { sides, radius, height } => Text::new(
                format!(
                    "底面は正{}角形で外接円の半径 {}（軸から各角までの距離）、頂点（先端）の高さ {}",
                    kanji(sides),
                    num(radius),
                    num(height)
                ),
                format!(
                    "the base is a regular {} with circumradius {} (the distance from the axis to each corner); the apex is {} high",
                    gon(sides),
                    num(radius),
                    num(height)
                ),
            ),
            Shape::Prism { sides, radius, height } => Text::new(
                format!(
                    "底面と上面は正{}角形で外接円の半径 {}（軸から各角までの距離）、高さ {}",
                    kanji(sides),
                    num(radius),
                    num(height)
                ),
                format!(
                    "the bottom and the top are regular {}s with circumradius {} (the distance from the axis to each corner); height {}",
                    gon(sides),
                    num(radius),
                    num(height)
                ),
            ),
            Shape::Frustum { sides, bottom_radius, top_radius, height } => Text::new(
                format!(
                    "底面は外接円の半径 {} の正{}角形、上面は外接円の半径 {} の正{}角形（各角は底面の角の真上）、高さ {}",
                    num(bottom_radius),
                    kanji(sides),
                    num(top_radius),
                    kanji(sides),
                    num(height)
                ),
                format!(
                    "the bottom is a regular {} with circumradius {}, the top one with circumradius {} (each corner right above a bottom corner); height {}",
                    gon(sides),
                    num(bottom_radius),
                    num(top_radius),
                    num(height)
                ),
            ),
            Shape::Tower { sides, radius, height, tip_height } => Text::new(
                format!(
                    "胴は外接円の半径 {} の正{}角柱で高さ {}、その上に高さ {} の{}角すい（先端の高さ {}）",
                    num(radius),
                    kanji(sides),
                    num(height),
                    num(tip_height),
                    kanji(sides),
                    num(height + tip_height)
                ),
                format!(
                    "the shaft is a regular {} prism with circumradius {} and height {}; on top, a pyramid {} high (the tip is at height {})",
                    gon(sides),
                    num(radius),
                    num(height),
                    num(tip_height),
                    num(height + tip_height)
                ),
            ),
            Shape::Bipyramid { sides, radius, lower_height, upper_height } => Text::new(
                format!(
                    "下の頂点は原点、中央の正{}角形（外接円の半径 {}）は高さ {}、上の頂点はその {} 上（高さ {}）",
                    kanji(sides),
                    num(radius),
                    num(lower_height),
                    num(upper_height),
                    num(lower_height + upper_height)
                ),
                format!(
                    "the lower apex at the origin; the middle regular {} (circumradius {}) at height {}; the upper apex {} above it (at height {})",
                    gon(sides),
                    num(radius),
                    num(lower_height),
                    num(upper_height),
                    num(lower_height + upper_height)
                ),
            ),
            Shape::Octahedron { radius } => Text::new(
                format!(
                    "中心から各頂点までの距離 {}（中心は高さ {}、下の頂点は原点）",
                    num(radius),
                    num(radius)
                ),
                format!(
                    "every vertex is {} from the centre (the centre at height {}, the lower vertex at the origin)",
                    num(radius),
                    num(radius)
                ),
            ),
            Shape::House { width, depth, wall_height, roof_height, ridge } => {
                let axis = match ridge {
                    RidgeAxis::X => "X",
                    RidgeAxis::Z => "Z",
                };
                Text::new(
                    format!(
                        "幅（X 方向）{}、奥行き（Z 方向）{}、壁の高さ {}。屋根の棟は {axis} 軸に平行で真ん中を通り、軒より {} 高い（棟の高さ {}）",
                        num(width),
                        num(depth),
                        num(wall_height),
                        num(roof_height),
                        num(wall_height + roof_height)
                    ),
                    format!(
                        "width (along X) {}, depth (along Z) {}, walls {} high; the ridge runs along {axis} through the middle, {} above the eaves (at height {})",
                        num(width),
                        num(depth),
                        num(wall_height),
                        num(roof_height),
                        num(wall_height + roof_height)
                    ),
                )
            }
            Shape::Wedge { width, depth, height } => Text::new(
                format!(
                    "底面は幅（X 方向）{}・奥行き（Z 方向）{} の長方形。−X 側の辺の上に高さ {} の垂直な壁が立ち、斜面は +X 側の辺から壁の上端まで",
                    num(width),
                    num(depth),
                    num(height)
                ),
                format!(
                    "the bottom is a rectangle {} wide (along X) and {} deep (along Z); a vertical wall {} high stands on its −X edge, and the slope runs from the +X edge up to the top of that wall",
                    num(width),
                    num(depth),
                    num(height)
                ),
            ),
        }
    }
}

/// One part of the numbering rule: `底面の正六角形 (y = 0.0): +X 軸上の角から上から見て反時計回り`.
fn part_rule(part: &Part, ring: Turn) -> Text {
    let turn = match ring {
        Turn::Ccw => t("上から見て反時計回り", "counter-clockwise seen from above"),
        Turn::Cw => t("上から見て時計回り", "clockwise seen from above"),
    };
    let (turn_ja, turn_en) = (&turn.ja, &turn.en);
    let (name_ja, name_en) = part.name;
    let y = num(part.y);
    match part.kind {
        PartKind::Point => {
            let p = part.points[0];
            Text::new(
                format!("{name_ja} ({}, {}, {})", num(p.x), num(p.y), num(p.z)),
                format!("{name_en} ({}, {}, {})", num(p.x), num(p.y), num(p.z)),
            )
        }
        PartKind::Polygon => {
            let n = part.points.len() as u32;
            Text::new(
                format!("{name_ja}の正{}角形 (y = {y}): +X 軸上の角から、{turn_ja}", kanji(n)),
                format!("{name_en} {} (y = {y}): from its corner on +X, {turn_en}", gon(n)),
            )
        }
        PartKind::Rectangle => Text::new(
            format!("{name_ja} (y = {y}): (+X, +Z) の角から、{turn_ja}"),
            format!("{name_en} (y = {y}): from the corner at (+X, +Z), {turn_en}"),
        ),
        PartKind::Pair => {
            let d = part.points[0] - part.points[1];
            let axis = if d.x.abs() > d.z.abs() { "X" } else { "Z" };
            Text::new(
                format!("{name_ja} (y = {y}): +{axis} 側の端が先"),
                format!("{name_en} (y = {y}): the end on +{axis} first"),
            )
        }
    }
}

/// The assignment text of a variant.
#[ext(SpecDescribe)]
pub impl Spec {
    /// The numbering rule as lines `V0–V5: …`.
    fn numbering_lines(&self, lang: Lang) -> Vec<String> {
        let parts = self.shape.parts();
        let ordered: Vec<&Part> = match self.numbering.order {
            Order::BottomUp => parts.iter().collect(),
            Order::TopDown => parts.iter().rev().collect(),
        };
        let mut first = 0;
        let mut lines = Vec::new();
        for part in ordered {
            let n = part.points.len();
            let range =
                if n == 1 { format!("V{first}") } else { format!("V{first}–V{}", first + n - 1) };
            lines.push(format!("{range}: {}", part_rule(part, self.numbering.ring).get(lang)));
            first += n;
        }
        lines
    }

    /// The placement in words.
    fn placement_text(&self) -> Text {
        let p = self.placement;
        let at = format!("({}, {}, {})", num(p.x), num(p.y), num(p.z));
        let angle = crate::format_deg(p.angle_deg);
        let rest = if p.y == 0.0 {
            t("（地面に立つ）", " (it stands on the ground)")
        } else {
            Text::new(
                format!("（地面から {} 浮いている）", num(p.y)),
                format!(" (it hovers {} above the ground)", num(p.y)),
            )
        };
        Text::new(
            format!(
                "モデルを自分の軸（Y 軸）のまわりに {angle}° 回転させ（上から見て反時計回り）、モデル座標系の原点がワールド座標系の {at} に来るように置く{}",
                rest.ja
            ),
            format!(
                "turn the model by {angle}° about its own axis (Y; counter-clockwise seen from above), then move it so that its model-space origin lands on {at} in world space{}",
                rest.en
            ),
        )
    }

    /// The assignment text for this variant, in `lang`: the model, its dimensions, the
    /// numbering rule, the placement, the tasks `a1.t1`–`a1.t4` with their functions, and what
    /// the report must show.
    fn describe(&self, lang: Lang) -> String {
        let (v, f) = (self.shape.vertex_count(), self.shape.face_count());
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{}",
            t("1. ポリゴンモデルの描画 (a1)", "1. Drawing a polygon model (a1)").get(lang)
        );
        let _ = writeln!(
            out,
            "  {}",
            t(
                "指定されたポリゴンモデルを描画する処理を追加すること。",
                "Add the code that draws the polygon model given below."
            )
            .get(lang)
        );
        let _ =
            writeln!(out, "  {}: {}", t("モデル", "Model").get(lang), self.shape.name().get(lang));
        let _ = writeln!(
            out,
            "    {}: {}",
            t("寸法", "Dimensions").get(lang),
            self.shape.dimensions().get(lang)
        );
        let _ = writeln!(
            out,
            "    {}",
            t(
                "モデル座標系: モデルの軸は Y 軸、いちばん下の点（底面）は y = 0 の平面上（原点は底の中心）",
                "Model space: the model's axis is the Y axis and its lowest point (or bottom face) lies in the plane y = 0 (the origin is the centre of its bottom)",
            ).get(lang)
        );
        let numbering = Text::new(
            format!("  頂点番号の付け方（全部で {v} 個）:"),
            format!("  Vertex numbering ({v} vertices):"),
        );
        let _ = writeln!(out, "{}", numbering.get(lang));
        for line in self.numbering_lines(lang) {
            let _ = writeln!(out, "    {line}");
        }
        let _ = writeln!(
            out,
            "  {}: {}",
            t("配置", "Placement").get(lang),
            self.placement_text().get(lang)
        );
        let _ = writeln!(out, "  {}", t("課題", "Tasks").get(lang));
        let tasks: [(&str, Text); 4] = [
            (
                "a1.t1",
                Text::new(
                    format!(
                        "頂点 — vertices(spec): 各頂点のモデル座標を、上の番号の順に返す（{v} 個）。"
                    ),
                    format!(
                        "vertices — vertices(spec): each vertex's model-space position, in the order above ({v} vertices)."
                    ),
                ),
            ),
            (
                "a1.t2",
                Text::new(
                    format!(
                        "面 — faces(spec): 三角形の面を頂点番号 [a, b, c] で返す。どの面も外側から見て反時計回り。隣り合う面は辺（頂点番号）を共有し、どの辺もちょうど 2 つの面に使われる（閉じた三角形メッシュなので F = 2V − 4 = {f} 個）。三角形への分け方と面の順番は自由。"
                    ),
                    format!(
                        "faces — faces(spec): the triangles as vertex numbers [a, b, c], each counter-clockwise seen from outside. Neighbouring faces share their edges (the same vertex numbers) and every edge belongs to exactly two faces (a closed triangle mesh has F = 2V − 4 = {f} faces). How you split the surface into triangles, and their order, is up to you."
                    ),
                ),
            ),
            (
                "a1.t3",
                t(
                    "法線 — face_normals(spec): 各面の単位法線を、faces と同じ順番で 1 面に 1 つ返す。(V_b − V_a) × (V_c − V_a) を正規化して自分で求める（描画にはこの法線がそのまま使われる）。",
                    "normals — face_normals(spec): each face's unit normal, one per face in the order of faces, computed by you: (V_b − V_a) × (V_c − V_a), normalised. The view lights each face with exactly this normal.",
                ),
            ),
            (
                "a1.t4",
                t(
                    "配置 — model_transform(spec): モデル座標系→ワールド座標系の変換を、平行移動と回転の積として返す（glTranslatef・glRotatef を呼ぶ順、角度は度）。",
                    "placement — model_transform(spec): the transform from model space to world space as a product of a translation and a rotation (in the order a program calls glTranslatef and glRotatef; angles in degrees).",
                ),
            ),
        ];
        for (id, text) in tasks {
            let _ = writeln!(out, "    {id} {}", text.get(lang));
        }
        let _ = writeln!(out, "  {}", t("レポートに載せるもの", "The report must show").get(lang));
        let report = [
            t(
                "頂点の表 V0 (x, y, z) … と、寸法からその座標を求めた過程（角度と cos・sin の計算など）",
                "the vertex table V0 (x, y, z) … and how each position follows from the dimensions (the angles, the cos and sin)",
            ),
            t(
                "面の表（講義の書き方 Fi { Va, Vb, Vc }）と各面の法線 { nx, ny, nz }（外積の計算の過程も）",
                "the face table (the lecture's notation Fi { Va, Vb, Vc }) with each face's normal { nx, ny, nz } (and how the cross product gives it)",
            ),
            t(
                "頂点と面のつながりが分かる三面図（xy・xz・yz 平面）や透視図。頂点番号と面番号を書き込み、裏側の頂点・面は括弧付きで",
                "three views (the xy, xz and yz planes) or a perspective view that show how vertices and faces connect, with the vertex and face numbers; hidden vertices and faces in parentheses",
            ),
            t(
                "配置の変換行列を、平行移動と回転の行列の積として（各変数の説明つき）",
                "the placement as a product of translation and rotation matrices, each variable explained",
            ),
            t(
                "配列のデータを示すだけでは不十分: 何故そのようなデータになったのか、結果だけでなく導出の過程を説明する図",
                "tables alone are not enough: figures that explain how the data was derived, not only the result",
            ),
        ];
        for line in report {
            let _ = writeln!(out, "    - {}", line.get(lang));
        }
        let _ = writeln!(
            out,
            "  {}: cargo run --release -- check a1    {}: cargo run --release -- view a1",
            t("チェック", "Check").get(lang),
            t("表示", "View").get(lang)
        );
        out
    }
}
