//! s.t4: the light types — point-light attenuation against [`cg_core::light::attenuation`] and
//! the spot light's cone against [`cg_core::light::spot_factor`].
//!
//! Tolerances: attenuation 1e-5 relative; spot factor 1e-4 + 1e-4·|expected|. Random cases closer
//! than 1e-4 to the rim of a spot cone are skipped: there the student's f32 arithmetic and the
//! core's may fall on different sides, and both are right.

use cg_core::glam::Vec3;
use cg_core::light::{self, Attenuation};
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::inputs::{Inputs, case_at, close1, num, random_case, vec};
use crate::{Impl, Spec};

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
        t("広がり 180°（円錐なし）、α = 135°", "cut-off 180° (no cone), α = 135°"),
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
                format!("{}: L = {l}, S = {s}, 広がり {c}°、指数 {e}（α = {alpha:.2}°）", name.ja),
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
