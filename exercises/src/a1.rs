//! # 課題 1: ポリゴンモデルの描画 / Assignment 1: drawing a polygon model
//!
//! Your polyhedron, its dimensions, the vertex numbering and its placement are printed by
//! `cargo run --release -- assignment --only a1`; the same numbers are in `spec` (a
//! [`cg_student::a1::Spec`]). Write the four functions below, then run
//! `cargo run --release -- check a1` (the checks explain what is wrong, and where) and
//! `cargo run --release -- view a1` (your model on the course's stage, lit with *your* normals).
//!
//! あなたの立体・寸法・頂点番号の付け方・配置は `cargo run --release -- assignment --only a1`
//! で表示されます（同じ値が `spec` に入っています）。下の 4 つの関数を書き、
//! `cargo run --release -- check a1` で確認、`cargo run --release -- view a1` で描画します
//! （描画には、あなたが書いた法線がそのまま使われます）。
//!
//! | task | function | 内容 |
//! |---|---|---|
//! | a1.t1 | [`vertices`] | 頂点の座標（モデル座標系、指定の番号順） / vertex positions |
//! | a1.t2 | [`faces`] | 三角形の面（外側から見て反時計回り） / triangles, counter-clockwise from outside |
//! | a1.t3 | [`face_normals`] | 各面の単位法線 / one unit normal per face |
//! | a1.t4 | [`model_transform`] | 配置の変換 T·Ry / the placement as a product |
//!
//! You may read the numbers from `spec` or write your own model's numbers by hand; either way
//! the report must explain where they come from.
//! `spec` から値を読んでも、自分の立体の値を直接書いてもかまいません（どちらの場合も、
//! 値の導出をレポートで説明します）。

#[allow(unused_imports)]
use cg_student::a1::{Order, RidgeAxis, Shape, Spec, Turn};
use cg_student::glam::Vec3;
#[allow(unused_imports)]
use cg_student::product::{Axis, Factor, MatrixProduct, Param};

/// **a1.t1** — the vertices of your polyhedron (各頂点の座標), in model space, numbered by the
/// assignment's rule.
///
/// - Returns: `V0, V1, …` as `Vec3` (x, y, z), exactly as many as the assignment says, in the
///   order of its numbering table. Model space (モデル座標系): the model's axis is the Y axis
///   and its lowest point (or bottom face) lies in the plane y = 0 — do *not* include the
///   placement (that is a1.t4).
/// - A regular polygon's corner k (k = 0, 1, …, n − 1) is at the angle θ = 360°·k/n from +X:
///   `(r·cos θ, y, −r·sin θ)` counter-clockwise seen from above, `(r·cos θ, y, r·sin θ)`
///   clockwise; `r` is the circumradius (the distance from the axis to a corner).
/// - Checks: `a1.t1.count`, `a1.t1.positions` (each coordinate within 0.001).
///
/// Hint: the lecture's pyramid is
/// `vec![Vec3::new(0.0, 1.0, 0.0), Vec3::new(1.0, -0.8, 1.0), …]`. `cos`/`sin` take radians:
/// `(360.0 * k as f32 / n as f32).to_radians().cos()`. Read your dimensions with
/// `if let Shape::Prism { sides, radius, height } = spec.shape { … }`, or write them by hand.
///
/// ヒント: 講義の四角すいなら `vec![Vec3::new(0.0, 1.0, 0.0), Vec3::new(1.0, -0.8, 1.0), …]`。
/// 正 n 角形の k 番目の角は θ = 360°·k/n（cos・sin にはラジアン: `.to_radians()`）。
/// 配置（平行移動・回転）は含めず、モデル座標系で書きます。
pub fn vertices(spec: &Spec) -> Vec<Vec3> {
    todo!(
        "a1.t1: 多面体の頂点 V0, V1, … をモデル座標系で並べる / list the vertices of your polyhedron (V0, V1, …) in model space"
    )
}

/// **a1.t2** — the faces (面を構成する頂点番号の配列): triangles as vertex numbers.
///
/// - Returns: `[a, b, c]` per triangle, the numbers of [`vertices`]. Every face is listed
///   **counter-clockwise seen from outside** (so `(Vb − Va) × (Vc − Va)` points outward).
///   Neighbouring faces share their edges by using the *same vertex numbers* (never a second
///   vertex at the same place); every edge belongs to exactly two faces. A closed triangle mesh
///   with V vertices has F = 2V − 4 faces.
/// - How you split quadrilaterals and other polygons into triangles (an n-gon takes n − 2), and
///   the order of the faces, are up to you.
/// - Checks: `a1.t2.indices`, `.degenerate`, `.closed`, `.manifold`, `.winding`, `.outward`,
///   `.count`, `.surface`.
///
/// Hint: draw the three views with the vertex numbers first. Looking at a face from outside,
/// go round it counter-clockwise. The lecture's pyramid: `vec![[0, 3, 1], [0, 2, 4], [0, 1, 2],
/// [0, 4, 3], [1, 3, 2], [4, 2, 3]]`.
///
/// ヒント: まず頂点番号を書き込んだ三面図を描き、各面を外側から見て反時計回りに頂点を並べます。
/// 隣の面とは同じ頂点番号で辺を共有します。
pub fn faces(spec: &Spec) -> Vec<[u32; 3]> {
    todo!(
        "a1.t2: 三角形の面を、外側から見て反時計回りに頂点番号で並べる / list the triangles as vertex numbers, counter-clockwise seen from outside"
    )
}

/// **a1.t3** — each face's unit normal (各面の法線), computed by you.
///
/// - Returns: one `Vec3` per face, in the order of [`faces`]: for face `[a, b, c]`,
///   `(Vb − Va) × (Vc − Va)` divided by its length (length 1, pointing outward). The view
///   lights each face with exactly this normal, so a wrong one shows as a wrongly lit face.
/// - Edge cases: a face without area has no normal; make sure no face is degenerate.
/// - Checks: `a1.t3.count`, `a1.t3.unit` (|n| within 0.002 of 1), `a1.t3.normals` (each
///   component within 0.001 of the normal derived from the face's vertices).
///
/// Hint: `(vb - va).cross(vc - va).normalize()`. The order of the cross product matters:
/// `(Vc − Va) × (Vb − Va)` points inward.
///
/// ヒント: `(vb - va).cross(vc - va).normalize()`。外積の順番を逆にすると内向きになります。
/// 講義の F0 { V0, V3, V1 } の法線は (V3 − V0) × (V1 − V0) = (0, 2, 3.6) を正規化した
/// { 0.0, 0.4856, 0.8742 } です。
pub fn face_normals(spec: &Spec) -> Vec<Vec3> {
    todo!(
        "a1.t3: 各面の単位法線を (Vb − Va) × (Vc − Va) の正規化で求める / compute each face's unit normal (Vb − Va) × (Vc − Va), normalised"
    )
}

/// **a1.t4** — the placement: model space → world space (モデル座標系→ワールド座標系).
///
/// - Returns: a [`MatrixProduct`], its factors in the order a program calls glTranslatef and
///   glRotatef (the last factor acts on the vertices first). Angles in **degrees**. The
///   assignment says: turn the model by θ about its own axis (Y), then move its origin to
///   (x, y, z) — as a product, `T(x, y, z) · Ry(θ)`.
/// - Check: `a1.t4.placement` (every matrix entry within 0.001 of `T(x, y, z) · Ry(θ)`).
///
/// Hint: `MatrixProduct::identity().then(Factor::translate(Vec3::new(x, y, z)))
/// .then(Factor::rotate_y_deg(theta))` — the same as `glTranslatef(x, y, z);
/// glRotatef(theta, 0, 1, 0);` in display(). `Factor::rotate(Axis::Y, Param::sym("theta",
/// theta))` prints the angle as a symbol in the report.
///
/// ヒント: display() で glTranslatef(x, y, z); glRotatef(θ, 0, 1, 0); と書く順に因子を並べます
/// （角度は度、ラジアンではありません）。
pub fn model_transform(spec: &Spec) -> MatrixProduct {
    todo!(
        "a1.t4: 配置 T(x, y, z) · Ry(θ) を角度は度で MatrixProduct にする / the placement T(x, y, z) · Ry(θ) as a MatrixProduct (degrees)"
    )
}

/// The functions of this module, for the checks and the view.
#[must_use]
pub fn implementation() -> cg_student::a1::Impl {
    cg_student::a1::Impl { vertices, faces, face_normals, model_transform }
}
