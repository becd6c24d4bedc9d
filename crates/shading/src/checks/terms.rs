//! s.t1–s.t4: the terms of the light model and the light types, against `cg_core::light`.
//!
//! Tolerances (absolute + relative, per channel): ambient 1e-6 (one product); diffuse 1e-5;
//! specular 1e-4 + 1e-3·|expected| (the power n ≤ 128 multiplies the rounding of R·V by up to
//! n); attenuation 1e-5 relative; spot factor 1e-4 + 1e-4·|expected|. Random cases closer than
//! 1e-3 to the switch `N·L = 0`, or than 1e-4 to the rim of a spot cone, are skipped: there the
//! student's f32 arithmetic and the core's may fall on different sides, and both are right.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{self, Attenuation};
use cg_core::optics;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::inputs::{Inputs, case_at, close, close1, num, random_case, vec};
use crate::{Impl, Spec};

fn material(spec: &Spec) -> (Rgb, Rgb, Rgb, f32) {
    (
        Rgb::from(spec.light.color.rgb),
        Rgb::from(spec.material.color.rgb),
        Rgb::splat(spec.material.ks),
        spec.material.shininess,
    )
}

// ---------------------------------------------------------------------------------------------
// s.t1

pub(super) fn ambient(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let mut cases = vec![(
        t("あなたの課題の Ia, ka", "Ia, ka of your assignment"),
        Rgb::splat(spec.light.ambient),
        Rgb::from(spec.material.color.rgb),
    )];
    let mut r = Inputs::new(0x5_0001);
    for i in 0..40 {
        cases.push((random_case(i), r.color(0.0, 1.0), r.color(0.0, 1.0)));
    }
    for (name, ia, ka) in cases {
        let expected = light::ambient(ia, ka);
        let actual = (imp.ambient)(ia, ka);
        if close(actual, expected, 1e-6, 1e-6) {
            continue;
        }
        let (cause, hint) = if close(actual, ka, 1e-6, 0.0) {
            (
                t("環境光の明るさ Ia が掛けられていません。", "the ambient light Ia is missing."),
                t("Ia·ka（チャンネルごとの積）を返します。", "return Ia·ka, channel by channel."),
            )
        } else if close(actual, ia + ka, 1e-6, 0.0) {
            (
                t("Ia と ka を足しています。", "Ia and ka are added."),
                t(
                    "光の明るさ × 反射係数: 足すのではなく掛けます (Ia * ka)。",
                    "light × reflectance: multiply (Ia * ka), do not add.",
                ),
            )
        } else {
            (
                t("Ia·ka になっていません。", "this is not Ia·ka."),
                t(
                    "R, G, B のそれぞれで Ia と ka を掛けます。glam の Vec3 同士の * はチャンネルごとの積です。",
                    "multiply Ia and ka in R, G and B separately: `*` between two glam Vec3 is per channel.",
                ),
            )
        };
        return Err(Failure::new(vec(expected), vec(actual))
            .at(case_at(&name, &format!("Ia = {}, ka = {}", vec(ia), vec(ka))))
            .cause(cause)
            .hint(hint));
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// s.t2

fn diffuse_failure(name: &Text, ii: Rgb, kd: Rgb, n: Vec3, l: Vec3, actual: Rgb) -> Failure {
    let expected = light::diffuse(ii, kd, n, l);
    let nl = n.dot(l);
    let (cause, hint) = if nl <= 0.0 && actual.min_element() < 0.0 {
        (
            t(
                "N·L < 0（光が面の裏から当たる）のに、負の光を返しています。",
                "N·L < 0 (the light is behind the surface), and the result is negative light.",
            ),
            t(
                "max(N·L, 0) として、裏から当たる光は 0 にします。",
                "use max(N·L, 0): light from behind gives 0.",
            ),
        )
    } else if nl <= 0.0 {
        (
            t(
                "光が面の裏から当たる (N·L ≤ 0) のに、0 ではありません。",
                "the light is behind the surface (N·L ≤ 0), yet the result is not 0.",
            ),
            t("max(N·L, 0) を使います。", "use max(N·L, 0)."),
        )
    } else {
        (
            t("Ii·kd·(N·L) になっていません。", "this is not Ii·kd·(N·L)."),
            t(
                "ランバートの余弦則: Id = kd·Ii·cos θ = kd·Ii·(N·L)。N と L は単位ベクトル、L は面から光源へ向かう向きです。",
                "Lambert's cosine law: Id = kd·Ii·cos θ = kd·Ii·(N·L), N and L unit, L pointing from the surface to the light.",
            ),
        )
    };
    Failure::new(vec(expected), vec(actual))
        .at(case_at(
            name,
            &format!(
                "Ii = {}, kd = {}, N = {}, L = {} (N·L = {})",
                vec(ii),
                vec(kd),
                vec(n),
                vec(l),
                num(nl)
            ),
        ))
        .cause(cause)
        .hint(hint)
}

pub(super) fn diffuse(imp: &Impl) -> Result<(), Failure> {
    let mut r = Inputs::new(0x5_0002);
    for i in 0..60 {
        let (ii, kd) = (r.color(0.2, 1.0), r.color(0.0, 1.0));
        let (n, l) = (r.unit_vector(), r.unit_vector());
        let actual = (imp.diffuse)(ii, kd, n, l);
        if !close(actual, light::diffuse(ii, kd, n, l), 1e-5, 1e-5) {
            return Err(diffuse_failure(&random_case(i), ii, kd, n, l, actual));
        }
    }
    Ok(())
}

pub(super) fn diffuse_facing_away(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (ii, kd, _, _) = material(spec);
    let n = Vec3::Y;
    let cases = [
        (t("N·L = 0（かすめる光）", "N·L = 0 (grazing light)"), Vec3::X),
        (t("N·L = -1（真裏からの光）", "N·L = -1 (light straight from behind)"), Vec3::NEG_Y),
        ("N·L = -0.7071".into(), Vec3::new(1.0, -1.0, 0.0).normalize()),
        ("N·L = -0.0001".into(), Vec3::new(1.0, -1e-4, 0.0).normalize()),
        (t("N·L = 1（正面からの光）", "N·L = 1 (light straight on)"), Vec3::Y),
    ];
    for (name, l) in cases {
        let actual = (imp.diffuse)(ii, kd, n, l);
        let expected = light::diffuse(ii, kd, n, l);
        if !close(actual, expected, 1e-6, 1e-6) {
            return Err(diffuse_failure(&name, ii, kd, n, l, actual));
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// s.t3

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

// ---------------------------------------------------------------------------------------------
// s.t4

pub(super) fn attenuation(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let a = spec.attenuation;
    let mut cases: Vec<(Text, f32, f32, f32, f32)> = [0.0, 0.5, 1.0, 2.5, 5.0, 10.0, 20.0]
        .iter()
        .map(|&d| (t("あなたの kc, kl, kq", "your kc, kl, kq"), a.kc, a.kl, a.kq, d))
        .collect();
    let mut r = Inputs::new(0x5_0005);
    for i in 0..40 {
        let (kc, kl, kq) = (r.range(0.1, 2.0), r.range(0.0, 0.5), r.range(0.0, 0.2));
        cases.push((random_case(i), kc, kl, kq, r.range(0.0, 30.0)));
    }
    cases.push((
        t("d = 0、kc = 0（光源が点の上）", "d = 0 with kc = 0 (the light on the point)"),
        0.0,
        0.5,
        1.0,
        0.0,
    ));
    cases.push((t("d = 0、kc = kl = kq = 0", "d = 0 with kc = kl = kq = 0"), 0.0, 0.0, 0.0, 0.0));
    for (name, kc, kl, kq, d) in cases {
        let expected =
            light::attenuation(Attenuation { constant: kc, linear: kl, quadratic: kq }, d);
        let actual = (imp.attenuation)(kc, kl, kq, d);
        if close1(actual, expected, 0.0, 1e-5) {
            continue;
        }
        let linear_d = 1.0 / (kc + kl * d + kq * d);
        let (cause, hint) = if !actual.is_finite() {
            (
                t(
                    "無限大か NaN になりました。光源が点の上にある (d = 0) とき kc = 0 だと分母が 0 です。",
                    "infinite or NaN: with the light on the point (d = 0) and kc = 0 the denominator is 0.",
                ),
                t(
                    "分母が 1e-6 より小さいときは 1e-6 を使います（kit の約束: 減衰は最大 1e6）。",
                    "use 1e-6 when the denominator is below 1e-6 (the kit's rule: the attenuation is at most 1e6).",
                ),
            )
        } else if close1(actual, linear_d, 0.0, 1e-5) {
            (
                t("kq に d ではなく d² を掛けます。", "kq multiplies d², not d."),
                t("分母は kc + kl·d + kq·d·d です。", "the denominator is kc + kl·d + kq·d·d."),
            )
        } else {
            (
                t("1/(kc + kl·d + kq·d²) になっていません。", "this is not 1/(kc + kl·d + kq·d²)."),
                t(
                    "距離 d の 1 次と 2 次の項を足した分母の逆数です。分母が 1e-6 より小さいときは 1e-6 を使います。",
                    "one over the sum of the constant, linear and quadratic terms; use 1e-6 for a denominator below 1e-6.",
                ),
            )
        };
        return Err(Failure::new(num(expected), num(actual))
            .at(case_at(
                &name,
                &format!("kc = {}, kl = {}, kq = {}, d = {}", num(kc), num(kl), num(kq), num(d)),
            ))
            .cause(cause)
            .hint(hint));
    }
    Ok(())
}

pub(super) fn spot(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (cutoff, exponent) = (spec.spot.cutoff_deg, spec.spot.exponent);
    // The spot hangs above the point and shines straight down; the point sees it at angle α.
    let down = Vec3::NEG_Y;
    let at = |alpha_deg: f32| {
        let a = alpha_deg.to_radians();
        // From the light to the point, at α from the axis; L points back to the light.
        -Vec3::new(a.sin(), -a.cos(), 0.0)
    };
    let mut cases: Vec<(Text, Vec3, Vec3, f32, f32)> =
        [0.0, cutoff / 2.0, cutoff - 1.0, cutoff + 1.0, 60.0, 89.0, 135.0]
            .iter()
            .map(|&alpha| {
                let name = Text::new(
                    format!("あなたのスポットライト、α = {}°", num(alpha)),
                    format!("your spot, α = {}°", num(alpha)),
                );
                (name, at(alpha), down, cutoff, exponent)
            })
            .collect();
    cases.push((
        t("カットオフ 180°（円錐なし）、α = 135°", "cut-off 180° (no cone), α = 135°"),
        at(135.0),
        down,
        180.0,
        exponent,
    ));
    let mut r = Inputs::new(0x5_0006);
    let mut i = 0;
    while i < 60 {
        let (l, s) = (r.unit_vector(), r.unit_vector());
        let c = if i % 8 == 7 { 180.0 } else { r.range(5.0, 90.0) };
        let cos_alpha = f64::from(-l.dot(s));
        if c <= 90.0 && (cos_alpha - f64::from(c).to_radians().cos()).abs() < 1e-4 {
            continue;
        }
        cases.push((random_case(i as usize), l, s, c, r.range(0.0, 10.0)));
        i += 1;
    }
    for (name, l, s, c, e) in cases {
        let expected = light::spot_factor(l, s, c, e, None);
        let actual = (imp.spot_factor)(l, s, c, e);
        if close1(actual, expected, 1e-4, 1e-4) {
            continue;
        }
        let cos_alpha = -l.dot(s);
        let degrees_as_radians = if c > 90.0 || cos_alpha < c.cos() {
            if c > 90.0 { 1.0 } else { 0.0 }
        } else {
            cos_alpha.max(0.0).powf(e)
        };
        let wrong_sign = {
            let cos = l.dot(s);
            if c > 90.0 {
                1.0
            } else if cos < c.to_radians().cos() {
                0.0
            } else {
                cos.max(0.0).powf(e)
            }
        };
        let (cause, hint) = if close1(actual, degrees_as_radians, 1e-4, 1e-4) && c <= 90.0 {
            (
                t(
                    "cutoff_deg は度です。cos に度のまま渡しています（f32::cos はラジアンを受け取ります）。",
                    "cutoff_deg is in degrees, and it went to cos as it is (f32::cos takes radians).",
                ),
                t(
                    "cutoff_deg.to_radians().cos() と比べます。",
                    "compare with cutoff_deg.to_radians().cos().",
                ),
            )
        } else if close1(actual, wrong_sign, 1e-4, 1e-4) {
            (
                t(
                    "cos α の符号が逆です。L は点から光源へ向かうので、光源から点へ向かう向きは −L です。",
                    "cos α has the wrong sign: L points from the point to the light, so the light shines along −L.",
                ),
                t("cos α = −L·S（S はスポットの向き）。", "cos α = −L·S (S the spot's direction)."),
            )
        } else {
            (
                t(
                    "スポットライトの係数になっていません: 円錐の外 (cos α < cos cutoff) では 0、内側では max(cos α, 0)^exponent、cutoff = 180° なら 1 です。",
                    "this is not the spot factor: 0 outside the cone (cos α < cos cutoff), max(cos α, 0)^exponent inside, 1 when cutoff = 180°.",
                ),
                t(
                    "cos α = −L·S を cutoff の cos と比べます。",
                    "compare cos α = −L·S with the cosine of the cut-off.",
                ),
            )
        };
        let alpha = f64::from(cos_alpha).clamp(-1.0, 1.0).acos().to_degrees();
        let (l, s, c, e) = (vec(l), vec(s), num(c), num(e));
        return Err(Failure::new(num(expected), num(actual))
            .at(Text::new(
                format!(
                    "{}: L = {l}, S = {s}, カットオフ角 {c}°、指数 {e}（α = {alpha:.2}°）",
                    name.ja
                ),
                format!(
                    "{}: L = {l}, S = {s}, cutoff = {c}°, exponent = {e} (α = {alpha:.2}°)",
                    name.en
                ),
            ))
            .cause(cause)
            .hint(hint));
    }
    Ok(())
}
