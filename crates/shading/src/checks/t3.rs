//! s.t3: the specular term `Ii·ks·max(R·V, 0)ⁿ` (Phong) against
//! [`cg_core::light::specular_phong`].
//!
//! Tolerance (absolute + relative, per channel): 1e-4 + 1e-3·|expected| (the power n ≤ 128
//! multiplies the rounding of R·V by up to n). Random cases closer than 1e-3 to the switch
//! `N·L = 0` are skipped: there the student's f32 arithmetic and the core's may fall on different
//! sides, and both are right.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light;
use cg_core::optics;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use super::material;
use crate::inputs::{Inputs, case_at, close, num, random_case, vec};
use crate::{Impl, Spec};

/// Explains a specular mismatch by the usual mistakes.
fn specular_failure(
    name: &Text,
    (ii, ks, n, l, v, shininess): (Rgb, Rgb, Vec3, Vec3, Vec3, f32),
    actual: Rgb,
) -> Failure {
    let expected = light::specular_phong(ii, ks, n, l, v, shininess);
    let nl = n.dot(l);
    let r = optics::reflect(-l, n);
    let rv = r.dot(v);
    // R mirrored the wrong way: reflect(L, N) = −R.
    let flipped =
        if nl > 0.0 { ii * ks * (-rv).clamp(0.0, 1.0).powf(shininess) } else { Rgb::ZERO };
    let (cause, hint) = if !actual.is_finite() {
        (
            t(
                "NaN（または無限大）になりました。R·V < 0 のまま powf を計算すると、n が整数でないとき NaN になります（(-0.5f32).powf(2.5) は NaN）。",
                "NaN (or infinity). powf of a negative R·V is NaN when n is not an integer ((-0.5f32).powf(2.5) is NaN).",
            ),
            t(
                "powf の前に R·V を 0 以上に切り詰めます: max(R·V, 0)。",
                "clamp before powf: max(R·V, 0).",
            ),
        )
    } else if nl <= 0.0 && actual.max_element() > 0.0 {
        (
            t(
                "光が面の裏から当たる (N·L ≤ 0) のにハイライトがあります。",
                "there is a highlight although the light is behind the surface (N·L ≤ 0).",
            ),
            t("N·L ≤ 0 のときは鏡面反射光も 0 にします。", "give no specular light where N·L ≤ 0."),
        )
    } else if rv <= 0.0 && actual.max_element() > 0.0 && expected == Rgb::ZERO {
        let ja = if shininess == 0.0 {
            "R·V ≤ 0 なのにハイライトがあります。n = 0 では 0⁰ = 1 (0f32.powf(0.0) は 1) になってしまいます。"
        } else {
            "R·V < 0 なのにハイライトがあります。n が偶数だと (R·V)ⁿ > 0 になり、面の反対側に光が出ます。"
        };
        let en = if shininess == 0.0 {
            "a highlight although R·V ≤ 0: with n = 0, 0⁰ = 1 (0f32.powf(0.0) is 1)."
        } else {
            "a highlight although R·V < 0: with an even n, (R·V)ⁿ > 0 puts light on the far side."
        };
        (
            t(ja, en),
            t(
                "R·V ≤ 0 なら 0 を返し、そうでなければ (R·V).powf(n) を計算します。",
                "return 0 when R·V ≤ 0; only otherwise compute (R·V).powf(n).",
            ),
        )
    } else if close(actual, flipped, 1e-4, 1e-3) && flipped != expected {
        (
            t(
                "R が逆向きです: reflect(L, N) は −R です。L は面から光源へ向かうので、入射光の向きは −L です。",
                "R points the wrong way: reflect(L, N) is −R. L points from the surface to the light, so the incoming light travels along −L.",
            ),
            t("R = reflect(−L, N) = 2(N·L)N − L。", "R = reflect(−L, N) = 2(N·L)N − L."),
        )
    } else {
        (
            t("Ii·ks·(R·V)ⁿ になっていません。", "this is not Ii·ks·(R·V)ⁿ."),
            t(
                "フォンのモデル: R = 2(N·L)N − L（L の正反射方向）、V は面から視点へ向かう単位ベクトル、結果は Ii·ks·max(R·V, 0)ⁿ。",
                "Phong's model: R = 2(N·L)N − L (the mirror direction of L), V the unit vector from the surface to the eye, the result Ii·ks·max(R·V, 0)ⁿ.",
            ),
        )
    };
    Failure::new(vec(expected), vec(actual))
        .at(case_at(
            name,
            &format!(
                "Ii = {}, ks = {}, N = {}, L = {}, V = {}, n = {} (N·L = {}, R·V = {})",
                vec(ii),
                vec(ks),
                vec(n),
                vec(l),
                vec(v),
                num(shininess),
                num(nl),
                num(rv)
            ),
        ))
        .cause(cause)
        .hint(hint)
}

pub(super) fn specular(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let mut r = Inputs::new(0x5_0003);
    let exponents = [1.0, 2.5, 7.5, spec.material.shininess, 64.0, 128.0];
    for i in 0..96 {
        let n = r.unit_vector();
        let l = loop {
            let l = r.unit_vector();
            if n.dot(l).abs() >= 1e-3 {
                break l;
            }
        };
        // Half the cases look close to the mirror direction, where the highlight is.
        let v = if i % 2 == 0 { r.near(optics::reflect(-l, n), 0.4) } else { r.unit_vector() };
        let case = (r.color(0.5, 1.0), r.color(0.2, 1.0), n, l, v, exponents[i % exponents.len()]);
        let (ii, ks, n, l, v, e) = case;
        let actual = (imp.specular)(ii, ks, n, l, v, e);
        if !close(actual, light::specular_phong(ii, ks, n, l, v, e), 1e-4, 1e-3) {
            return Err(specular_failure(&random_case(i), case, actual));
        }
    }
    Ok(())
}

pub(super) fn specular_mirror(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (ii, _, ks, shininess) = material(spec);
    let mut r = Inputs::new(0x5_0004);
    for i in 0..20 {
        let n = r.unit_vector();
        let l = loop {
            let l = r.unit_vector();
            if n.dot(l) > 0.05 {
                break l;
            }
        };
        let v = optics::reflect(-l, n).normalize();
        let actual = (imp.specular)(ii, ks, n, l, v, shininess);
        let expected = light::specular_phong(ii, ks, n, l, v, shininess);
        if !close(actual, expected, 1e-4, 1e-3) {
            return Err(specular_failure(
                &Text::new(
                    format!("V = R（正反射方向）、ケース {i}"),
                    format!("V = R (mirror direction), case {i}"),
                ),
                (ii, ks, n, l, v, shininess),
                actual,
            ));
        }
    }
    Ok(())
}

pub(super) fn specular_hard(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (ii, _, ks, shininess) = material(spec);
    let n = Vec3::Y;
    let l45 = Vec3::new(1.0, 1.0, 0.0).normalize();
    let r45 = optics::reflect(-l45, n); // (−1, 1, 0)/√2
    let behind = Vec3::new(1.0, -0.5, 0.0).normalize();
    let cases: Vec<(Text, Vec3, Vec3, f32)> = vec![
        (
            t(
                "R·V < 0、n = 2.5（切り詰めないと NaN）",
                "R·V < 0 with n = 2.5 (NaN without the clamp)",
            ),
            l45,
            -r45,
            2.5,
        ),
        (
            t(
                "R·V < 0、n = 2（偶数: 切り詰めないと反対側にハイライト）",
                "R·V < 0 with n = 2 (even: a highlight on the far side without the clamp)",
            ),
            l45,
            -r45,
            2.0,
        ),
        (
            t("R·V = -0.5、n = 3.5", "R·V = -0.5 with n = 3.5"),
            l45,
            (-0.5 * r45 + 0.75f32.sqrt() * Vec3::Z).normalize(),
            3.5,
        ),
        (
            t("N·L = 0（かすめる光）、V = R", "N·L = 0 (grazing light), V = R"),
            Vec3::X,
            Vec3::NEG_X,
            shininess,
        ),
        (
            t("N·L < 0（裏からの光）、R·V > 0", "N·L < 0 (light from behind), R·V > 0"),
            behind,
            optics::reflect(-behind, n).normalize(),
            shininess,
        ),
        ("N·L = -1, V = N".into(), Vec3::NEG_Y, Vec3::Y, shininess),
        ("n = 0, R·V > 0".into(), l45, Vec3::new(-1.0, 2.0, 0.0).normalize(), 0.0),
        ("n = 0, R·V < 0".into(), l45, -r45, 0.0),
        ("n = 0, R·V = 0".into(), l45, Vec3::Z, 0.0),
        ("L = -V".into(), l45, -l45, shininess),
        (t("V = R ちょうど、n = 128", "V = R exactly, n = 128"), l45, r45, 128.0),
        (t("V = R ちょうど、あなたの n", "V = R exactly, your n"), l45, r45, shininess),
    ];
    for (name, l, v, e) in cases {
        let actual = (imp.specular)(ii, ks, n, l, v, e);
        let expected = light::specular_phong(ii, ks, n, l, v, e);
        if !close(actual, expected, 1e-5, 1e-4) {
            return Err(specular_failure(&name, (ii, ks, n, l, v, e), actual));
        }
    }
    Ok(())
}
