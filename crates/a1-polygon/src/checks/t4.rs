//! The checks of task `a1.t4` (`model_transform(spec)`): the placement `T(x, y, z) · Ry(θ)`.

use cg_core::glam::{Mat4, Vec3};
use cg_core::notation;
use cg_core::product::MatrixProduct;
use cg_core::transform::{rotate_y, rotate_y_deg, translate};
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::spec::Spec;
use crate::{Impl, format_deg};

use super::{MATRIX_TOLERANCE, expected_transform, v3};

/// `[[r0], [r1], [r2], [r3]]`, the matrix by rows.
fn rows(m: Mat4) -> String {
    let r: Vec<String> = (0..4)
        .map(|i| {
            let row = m.row(i);
            format!(
                "[{}, {}, {}, {}]",
                notation::decimal(row.x, 4),
                notation::decimal(row.y, 4),
                notation::decimal(row.z, 4),
                notation::decimal(row.w, 4)
            )
        })
        .collect();
    format!("[{}]", r.join(", "))
}

fn matrices_close(a: Mat4, b: Mat4) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array())
        .all(|(x, y)| x.is_finite() && (x - y).abs() <= MATRIX_TOLERANCE)
}

pub(super) fn placement(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let product: MatrixProduct = (imp.model_transform)(spec).into();
    let p = spec.placement;
    let angle = format_deg(p.angle_deg);
    let expected = expected_transform(spec);
    let expected_text = format!(
        "T({}, {}, {}) · Ry({angle}°) = {}",
        format_deg(p.x),
        format_deg(p.y),
        format_deg(p.z),
        rows(expected)
    );
    let hint = t(
        "display() で glTranslatef(x, y, z); glRotatef(θ, 0, 1, 0); と呼ぶ順に因子を並べます。MatrixProduct::identity().then(Factor::translate(…)).then(Factor::rotate_y_deg(θ)) のように書けます。最後の因子が最初に頂点に作用します。角度は度です。",
        "list the factors in the order display() would call glTranslatef(x, y, z) and glRotatef(θ, 0, 1, 0), as in MatrixProduct::identity().then(Factor::translate(…)).then(Factor::rotate_y_deg(θ)); the last factor acts on the vertices first. Angles are in degrees.",
    );
    let m = match product.matrix() {
        Ok(m) => m,
        Err(e) => {
            let message = e.text();
            return Err(Failure::new(expected_text, message.clone())
                .at("model_transform()")
                .cause(message)
                .hint(hint));
        }
    };
    if matrices_close(m, expected) {
        return Ok(());
    }
    let actual = format!("{} = {}", product.numeric(), rows(m));
    let at = translate(Vec3::new(p.x, p.y, p.z));
    let turn = rotate_y_deg(p.angle_deg);
    let rad = p.angle_deg.to_radians();
    let cause = if matrices_close(m, at * rotate_y_deg(rad)) {
        Text::new(
            format!(
                "角度がラジアンで渡されています: {angle}° の代わりに {rad:.4}°（= {angle}° をラジアンにした値）だけ回っています。glRotatef や Factor::rotate_y_deg の角度は度です。"
            ),
            format!(
                "the angle is given in radians where degrees are expected: the model turns by {rad:.4}° ({angle}° converted to radians) instead of {angle}°. glRotatef and Factor::rotate_y_deg take degrees."
            ),
        )
    } else if matrices_close(m, at * rotate_y(p.angle_deg)) {
        Text::new(
            format!(
                "度の値 {angle} がラジアンとして cos・sin に渡されています（{angle} ラジアン回っています）。cos・sin には {angle}_f32.to_radians() を渡します。"
            ),
            format!(
                "the angle in degrees, {angle}, went into cos and sin as radians (the model turns by {angle} radians): pass {angle}_f32.to_radians() to cos and sin."
            ),
        )
    } else if matrices_close(m, turn * at) {
        t(
            "積の順番が逆です（回転してから平行移動の行列 Ry·T）。これではモデルがワールドの原点のまわりを回り、指定の位置からずれます。T を先（左）に、Ry を後（右）に書きます。",
            "the factors are in the wrong order (Ry · T): the model then swings about the world's origin, away from its place. Write T first (left), then Ry (right).",
        )
    } else if matrices_close(m, at * rotate_y_deg(-p.angle_deg)) {
        t(
            "回転の向きが逆です（−θ だけ回っています）。上から見て反時計回りが正の角度です。",
            "the rotation goes the wrong way (by −θ): counter-clockwise seen from above is the positive angle.",
        )
    } else if matrices_close(m, at) {
        t("回転がありません（平行移動だけ）。", "the rotation is missing (a translation only).")
    } else if matrices_close(m, turn) {
        t("平行移動がありません（回転だけ）。", "the translation is missing (a rotation only).")
    } else if (m.w_axis.truncate() - expected.w_axis.truncate()).abs().max_element()
        <= MATRIX_TOLERANCE
    {
        t(
            "平行移動の部分（4 列目）は正しいのですが、回転の部分が違います。",
            "the translation part (the 4th column) is right but the rotation part is not.",
        )
    } else {
        Text::new(
            format!(
                "モデル座標系の原点が {} に行くはずが、{} に行きます。",
                v3(expected.w_axis.truncate()),
                v3(m.w_axis.truncate())
            ),
            format!(
                "the model's origin should land on {} but lands on {}.",
                v3(expected.w_axis.truncate()),
                v3(m.w_axis.truncate())
            ),
        )
    };
    Err(Failure::new(expected_text, actual).at("model_transform()").cause(cause).hint(hint))
}
