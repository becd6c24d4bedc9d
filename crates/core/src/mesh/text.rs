//! The messages of a mesh's errors and findings, in the lecture's V/F notation, in both
//! languages.

use crate::lang::{Lang, Text, t};
use crate::notation;

use super::{MeshError, Problem};

impl MeshError {
    /// The message for a student in `lang`, in the lecture's V/F notation: `face F6 corner 2
    /// refers to V9, but the mesh has only 5 vertices, V0–V4` / `面 F6 の 2 番目 …`. The English
    /// one is the `Display` text.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message for a student in both languages (see [`MeshError::message`]).
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            MeshError::IndexOutOfRange { face, corner, index, vertex_count } => {
                let range = match vertex_count {
                    0 => t("頂点が 1 つもありません", "the mesh has no vertices"),
                    n => Text::new(
                        format!("頂点は V0–V{} の {n} 個です", n - 1),
                        format!("the mesh has only {n} vertices, V0–V{}", n - 1),
                    ),
                };
                Text::new(
                    format!(
                        "面 F{face} の頂点番号 V{index}（0 から数えて {corner} 番目）は存在しません（{}）",
                        range.ja
                    ),
                    format!("face F{face} corner {corner} refers to V{index}, but {}", range.en),
                )
            }
            MeshError::AttributeLength { attribute, len, expected } => {
                let name = match *attribute {
                    "normals" => "法線",
                    "uvs" => "テクスチャ座標",
                    "colors" => "色",
                    other => other,
                };
                Text::new(
                    format!("頂点は {expected} 個ですが、{name} ({attribute}) が {len} 個あります"),
                    format!("the mesh has {expected} vertices but {len} {attribute}"),
                )
            }
            MeshError::NonFinitePosition { vertex, position } => {
                let p = format!("({}, {}, {})", position.x, position.y, position.z);
                Text::new(
                    format!("頂点 V{vertex} の座標 {p} に無限大または NaN が含まれています"),
                    format!("vertex V{vertex} has a non-finite position {p}"),
                )
            }
        }
    }
}

impl std::fmt::Display for MeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.message(Lang::En))
    }
}

impl std::error::Error for MeshError {}

/// `F0, F3 and F6` / `F0・F3・F6`
fn face_list(faces: &[usize]) -> Text {
    let names: Vec<String> = faces.iter().map(|f| format!("F{f}")).collect();
    let en = match names.split_last() {
        None => String::new(),
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
    };
    Text::new(names.join("・"), en)
}

impl Problem {
    /// What is wrong, in the lecture's V/F notation, e.g. `edge V1–V3 is used by F0 and F4 in
    /// the same direction: one of them is wound the wrong way`.
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// What is wrong, in both languages (see [`Problem::describe`]).
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            Problem::Structure(e) => e.text(),
            Problem::RepeatedIndex { face, vertices } => {
                let f = notation::face(*face, *vertices);
                Text::new(
                    format!("面 {f} は同じ頂点を 2 回使っています（面積 0 の面）"),
                    format!("face {f} uses the same vertex twice: it has no area"),
                )
            }
            Problem::ZeroArea { face, vertices } => {
                let f = notation::face(*face, *vertices);
                Text::new(
                    format!(
                        "面 {f} の面積が 0 です（3 頂点が一致するか、座標の精度の範囲で一直線上にあります）"
                    ),
                    format!(
                        "face {f} has zero area: its vertices coincide or lie on one line (within the precision of their coordinates)"
                    ),
                )
            }
            Problem::BoundaryEdge { edge, face } => {
                let e = notation::edge(edge[0], edge[1]);
                Text::new(
                    format!(
                        "面 F{face} の辺 {e} を共有する面がありません（モデルがここで閉じていません）"
                    ),
                    format!(
                        "edge {e} of F{face} is not shared with any other face: the model is not closed there"
                    ),
                )
            }
            Problem::NonManifoldEdge { edge, faces } => {
                let e = notation::edge(edge[0], edge[1]);
                let n = faces.len();
                Text::new(
                    format!(
                        "辺 {e} を {n} 個の面 ({}) が共有しています（閉じたモデルでは 1 つの辺を共有する面はちょうど 2 つです）",
                        face_list(faces).ja
                    ),
                    format!(
                        "edge {e} is used by {n} faces ({}): an edge of a closed model belongs to exactly two",
                        face_list(faces).en
                    ),
                )
            }
            Problem::InconsistentWinding { edge, faces } => {
                let e = notation::edge(edge[0], edge[1]);
                let [f, g] = faces;
                Text::new(
                    format!(
                        "辺 {e} を F{f} と F{g} が同じ向きにたどっています: どちらかの頂点の順番（回る向き）が逆です"
                    ),
                    format!(
                        "edge {e} is used by F{f} and F{g} in the same direction: one of them is wound the wrong way"
                    ),
                )
            }
            Problem::NonManifoldVertex { vertex, fans } => Text::new(
                format!(
                    "頂点 V{vertex} で {fans} 組の面が点だけで接しています（蝶ネクタイ形: 頂点のまわりの面が 1 つの扇になっていません）"
                ),
                format!(
                    "vertex V{vertex} joins {fans} separate fans of faces (a bow-tie): the parts touch only at this vertex"
                ),
            ),
            Problem::TJunction { vertex, edge, face } => {
                let e = notation::edge(edge[0], edge[1]);
                Text::new(
                    format!(
                        "頂点 V{vertex} が面 F{face} の辺 {e} の途中にありますが、F{face} はこの頂点を使っていません（T 字接合: 隣接する面が辺を共有していません）"
                    ),
                    format!(
                        "vertex V{vertex} lies on edge {e} of F{face}, but F{face} does not use it (a T-junction): the neighbouring faces do not share their edges"
                    ),
                )
            }
            Problem::InwardFacing { signed_volume } => Text::new(
                format!(
                    "すべての面が外から見て時計回りです（符号付き体積 {signed_volume:.6e} < 0）: 面の法線が内側を向いています"
                ),
                format!(
                    "every face is wound clockwise seen from outside (signed volume {signed_volume:.6e} < 0): the normals point inward"
                ),
            ),
            Problem::ZeroVolume { signed_volume } => Text::new(
                format!(
                    "閉じた面が体積を囲んでいません（符号付き体積 {signed_volume:.3e}）: 面の向き（表裏）が決まりません"
                ),
                format!(
                    "the closed surface encloses no volume (signed volume {signed_volume:.3e}): which side is outside is undefined"
                ),
            ),
            Problem::UnreferencedVertex { vertex } => Text::new(
                format!("頂点 V{vertex} はどの面にも使われていません"),
                format!("vertex V{vertex} is used by no face"),
            ),
        }
    }

    /// The usual cause of this finding and how to fix it.
    #[must_use]
    pub fn hint(&self) -> Text {
        match self {
            Problem::Structure(MeshError::IndexOutOfRange { .. }) => t(
                "頂点番号は 0 から始まります (V0)。1 から数えていないか（OBJ ファイルは 1 から）、頂点の定義が抜けていないか確認してください",
                "vertex numbers start at 0 (V0): check for numbers counted from 1 (as in OBJ files) or a vertex missing from the vertex table",
            ),
            Problem::Structure(MeshError::AttributeLength { .. }) => t(
                "法線・テクスチャ座標・色は頂点ごとに 1 つずつ（または全く無し）にしてください",
                "give exactly one normal, texture coordinate or colour per vertex, or none at all",
            ),
            Problem::Structure(MeshError::NonFinitePosition { .. }) => t(
                "0 での割り算や、値を入れ忘れた変数から座標を計算していないか確認してください",
                "look for a division by zero or an uninitialised value in the code that computes this position",
            ),
            Problem::RepeatedIndex { .. } => t(
                "三角形には異なる 3 つの頂点が必要です。面の頂点番号の打ち間違いか、四角形を三角形に分けるときの誤りです",
                "a triangle needs three different vertices: a typo in the face table, or a mistake when splitting a quadrilateral",
            ),
            Problem::ZeroArea { .. } => t(
                "頂点座標を確認し、この面を削除するか頂点を動かしてください",
                "check the vertex positions; remove the face or move a vertex",
            ),
            Problem::BoundaryEdge { .. } => t(
                "この辺の隣の面が抜けているか、隣の面が同じ位置に別番号で複製した頂点を使っています（頂点は番号で共有します: weld_by_position で統合できます）",
                "a face next to this edge is missing, or the neighbouring face uses a duplicated vertex (same position, another number) instead of sharing this one: share the index, or weld by position",
            ),
            Problem::NonManifoldEdge { .. } => t(
                "同じ面を 2 回定義しているか、余分な面（ひれ）が辺から出ています",
                "a face is defined twice, or an extra face (a fin) hangs off this edge",
            ),
            Problem::InconsistentWinding { .. } => t(
                "外側から見て反時計回りになるように、向きが逆の面の頂点の順番を入れ替えてください（隣り合う面は共有する辺を逆向きにたどります）",
                "list the wrong face's vertices the other way round, counter-clockwise seen from outside (neighbouring faces traverse their shared edge in opposite directions)",
            ),
            Problem::NonManifoldVertex { .. } => t(
                "2 つの部分が 1 点だけで接しています。部分ごとに別の頂点を使うか、面でつないでください",
                "two parts touch at a single point: give each part its own vertex, or connect them with faces",
            ),
            Problem::TJunction { .. } => t(
                "辺の途中の頂点で、その辺を使う面も 2 つの三角形に分割してください（隣接するポリゴンは辺全体を共有します）",
                "split the face that uses the long edge into two triangles at that vertex (adjacent polygons must share whole edges)",
            ),
            Problem::InwardFacing { .. } => t(
                "すべての面の頂点の順番を逆にしてください（各面の 2 つの頂点番号を入れ替える）。外側から見て反時計回りが表です",
                "reverse the vertex order of every face (swap two indices in each): counter-clockwise seen from outside is the front",
            ),
            Problem::ZeroVolume { .. } => t(
                "面が裏表に重なっているか、モデルが平らです。厚みのある立体にしてください",
                "faces lie back to back or the model is flat: give it some thickness",
            ),
            Problem::UnreferencedVertex { .. } => t(
                "使わない頂点を削除するか、抜けている面を追加してください（描画には影響しません）",
                "remove the unused vertex or add the missing face (it does not change what is drawn)",
            ),
        }
    }

    /// `true` for findings that change nothing drawn: unreferenced vertices.
    #[must_use]
    pub fn is_minor(&self) -> bool {
        matches!(self, Problem::UnreferencedVertex { .. })
    }
}

impl std::fmt::Display for Problem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.describe(Lang::En))
    }
}
