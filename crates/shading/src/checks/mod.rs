//! The checks, one [`check::run`] per property. Each calls the student's functions inside its
//! closure (so a `todo!()` is "not done yet" and a panic a report), compares with the core's own
//! functions on seeded inputs and on the hard cases of docs/numerics.md rows 12–18, with the
//! tolerances stated in each module, and explains a failure in Japanese and English.

use cg_core::Rgb;
use cg_harness::CheckResult;
use cg_harness::check;
use cg_harness::text::t;

use crate::{Impl, Spec};

mod t1;
mod t2;
mod t3;
mod t4;
mod t5;
mod t6;
mod t7;
mod t8;

pub use t6::kit_rule;

/// The student's light colour Ii, the material's colour kd, its ks (grey) and shininess n: the
/// inputs of s.t2 and s.t3 that are "of your assignment".
fn material(spec: &Spec) -> (Rgb, Rgb, Rgb, f32) {
    (
        Rgb::from(spec.light.color.rgb),
        Rgb::from(spec.material.color.rgb),
        Rgb::splat(spec.material.ks),
        spec.material.shininess,
    )
}

/// Every check, in task order.
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    let run = |id: &str, title: cg_harness::Text, body: &dyn Fn() -> Result<(), check::Failure>| {
        check::run(id, title, body)
    };
    vec![
        run("s.t1.ambient", t("環境光 Ia·ka", "ambient term Ia·ka"), &|| {
            t1::ambient(spec, imp)
        }),
        run(
            "s.t2.diffuse",
            t(
                "拡散反射光 Ii·kd·max(N·L, 0)（ランダムな入力）",
                "diffuse term Ii·kd·max(N·L, 0) (random inputs)",
            ),
            &|| t2::diffuse(imp),
        ),
        run(
            "s.t2.facing_away",
            t(
                "光が面の裏から当たるとき (N·L ≤ 0) 拡散反射光は 0",
                "no diffuse light from behind (N·L ≤ 0)",
            ),
            &|| t2::diffuse_facing_away(spec, imp),
        ),
        run(
            "s.t3.specular",
            t(
                "鏡面反射光 Ii·ks·max(R·V, 0)ⁿ（ランダムな入力）",
                "specular term Ii·ks·max(R·V, 0)ⁿ (random inputs)",
            ),
            &|| t3::specular(spec, imp),
        ),
        run(
            "s.t3.mirror",
            t(
                "視線が正反射方向 (V = R) のときハイライトが最も明るい",
                "the highlight is brightest in the mirror direction (V = R)",
            ),
            &|| t3::specular_mirror(spec, imp),
        ),
        run(
            "s.t3.hard_cases",
            t(
                "鏡面反射光の難しい場合: R·V < 0、N·L ≤ 0、n = 0、L = −V",
                "specular hard cases: R·V < 0, N·L ≤ 0, n = 0, L = −V",
            ),
            &|| t3::specular_hard(spec, imp),
        ),
        run(
            "s.t4.attenuation",
            t(
                "点光源の減衰 1/(kc + kl·d + kq·d²)",
                "point-light attenuation 1/(kc + kl·d + kq·d²)",
            ),
            &|| t4::attenuation(spec, imp),
        ),
        run(
            "s.t4.spot",
            t("スポットライトの広がり (cut-off) と指数", "the spot light's cut-off and exponent"),
            &|| t4::spot(spec, imp),
        ),
        run(
            "s.t5.average",
            t(
                "頂点の法線 = 隣接する面の法線の平均",
                "vertex normal = average of the adjacent face normals",
            ),
            &|| t5::average(spec, imp),
        ),
        run(
            "s.t5.area_weighted",
            t("頂点の法線 = 面の面積に応じた加重平均", "vertex normal = area-weighted average"),
            &|| t5::area_weighted(spec, imp),
        ),
        run(
            "s.t5.degenerate",
            t(
                "面積 0 の面は頂点の法線を乱さない（NaN にならない）",
                "zero-area faces change no vertex normal (and give no NaN)",
            ),
            &|| t5::degenerate(imp),
        ),
        run(
            "s.t6.flat",
            t(
                "フラットシェーディング: 面の法線で面の色を決める",
                "flat shading: the face normal gives the face its colour",
            ),
            &|| t6::unit(spec, imp, crate::Shading::Flat),
        ),
        run(
            "s.t6.gouraud",
            t(
                "グローシェーディング: 頂点の色を補間する",
                "Gouraud shading: the vertex colours are interpolated",
            ),
            &|| t6::unit(spec, imp, crate::Shading::Gouraud),
        ),
        run(
            "s.t6.phong",
            t(
                "フォンシェーディング: 法線を補間・正規化してピクセルごとに光源処理",
                "Phong shading: normals interpolated, renormalised and lit per pixel",
            ),
            &|| t6::unit(spec, imp, crate::Shading::Phong),
        ),
        run(
            "s.t6.image_flat",
            t("フラットシェーディングの球の画像", "the flat-shaded sphere image"),
            &|| t6::image(spec, imp, crate::Shading::Flat),
        ),
        run(
            "s.t6.image_gouraud",
            t("グローシェーディングの球の画像", "the Gouraud-shaded sphere image"),
            &|| t6::image(spec, imp, crate::Shading::Gouraud),
        ),
        run(
            "s.t6.image_phong",
            t("フォンシェーディングの球の画像", "the Phong-shaded sphere image"),
            &|| t6::image(spec, imp, crate::Shading::Phong),
        ),
        run(
            "s.t6.highlight",
            t(
                "グローで消えるハイライトがフォンでは残る",
                "Phong keeps the highlight that Gouraud loses",
            ),
            &|| t6::highlight(spec, imp),
        ),
        run(
            "s.t7.reflect",
            t("正反射方向 (鏡面反射)", "the mirror direction (reflection)"),
            &|| t7::reflect(imp),
        ),
        run(
            "s.t8.refract",
            t("スネルの法則による屈折方向", "the refracted direction by Snell's law"),
            &|| t8::refract(spec, imp),
        ),
        run(
            "s.t8.total_reflection",
            t(
                "全反射では None（NaN にしない）",
                "total internal reflection gives None (never NaN)",
            ),
            &|| t8::total_reflection(spec, imp),
        ),
        run(
            "s.t8.hard_cases",
            t(
                "屈折の難しい場合: 垂直入射、臨界角ちょうど、η = 1、内側から",
                "refraction hard cases: normal incidence, exactly the critical angle, η = 1, from inside",
            ),
            &|| t8::refract_hard(spec, imp),
        ),
    ]
}
