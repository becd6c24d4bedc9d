//! s.t8: refraction by Snell's law and total internal reflection against
//! [`cg_core::optics::refract`] with [`Interface`] (docs/numerics.md row 12).
//!
//! Tolerance: 1e-5 per component (unit vectors). The refraction checks leave out incidence
//! angles within 1e-3 rad of the critical angle, where f32 and the core's f64 may decide total
//! internal reflection differently; exactly at the critical angle either answer is accepted —
//! `None`, or a unit vector along the surface (|t·n| ≤ 2e-3, the f32 square root of a cosine² of
//! rounding size) — but never NaN.

use cg_core::glam::Vec3;
use cg_core::optics::{self, Interface};
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::inputs::{Inputs, max_diff, num, opt, random_case, vec};
use crate::{Impl, Spec};

/// The core's answer for the student's convention: `n` the outward normal, `n1` outside, `n2`
/// inside; a hit from inside flips the normal and swaps the indices ([`Interface::at`]).
fn oracle(i: Vec3, n: Vec3, n1: f32, n2: f32) -> Option<Vec3> {
    let iface = Interface::at(i, n, n1, n2)?;
    optics::refract(i, iface.n, iface.eta)
}

/// The angle of incidence (from the normal, on the incident side) in radians, and the critical
/// angle when the ray goes into a less dense medium.
fn angles(i: Vec3, n: Vec3, n1: f32, n2: f32) -> (f64, Option<f64>) {
    let cos = f64::from(i.dot(n)).abs().min(1.0);
    let (from, to) = if i.dot(n) > 0.0 { (n2, n1) } else { (n1, n2) };
    let critical = (from > to).then(|| (f64::from(to) / f64::from(from)).asin());
    (cos.acos(), critical)
}

/// The refraction formula applied as it is, whatever side the ray comes from: `cos θ₁ = −i·n`,
/// `k = 1 − η²(1 − cos²θ₁)`, `t = η·i + (η cos θ₁ − √k)·n` (what a student gets without the
/// inside case).
fn naive(i: Vec3, n: Vec3, eta: f32) -> Option<Vec3> {
    let cos = -i.dot(n);
    let k = 1.0 - eta * eta * (1.0 - cos * cos);
    (k >= 0.0).then(|| (eta * i + (eta * cos - k.sqrt()) * n).normalize_or_zero())
}

fn refract_failure(
    name: &Text,
    i: Vec3,
    n: Vec3,
    n1: f32,
    n2: f32,
    actual: Option<Vec3>,
) -> Failure {
    let expected = oracle(i, n, n1, n2);
    let inside = i.dot(n) > 0.0;
    let (theta, critical) = angles(i, n, n1, n2);
    let inverted = oracle(i, n, n2, n1);
    // Leaving the object without flipping n (the formula used as for a ray from outside), or
    // with n flipped but the indices not swapped.
    let not_flipped = inside.then(|| naive(i, n, n1 / n2)).flatten();
    let not_swapped = inside.then(|| optics::refract(i, n, n1 / n2)).flatten();
    let near = |a: Option<Vec3>, b: Option<Vec3>| match (a, b) {
        (Some(a), Some(b)) => max_diff(a, b) <= 1e-4,
        (None, None) => true,
        _ => false,
    };
    let (cause, hint) = if actual.is_some_and(|v| !v.is_finite()) {
        (
            t(
                "NaN です。全反射（sin θ₂ > 1）のとき平方根の中が負になります。",
                "NaN: under total internal reflection (sin θ₂ > 1) the square root gets a negative number.",
            ),
            t(
                "平方根の前に k = 1 − η²(1 − cos²θ₁) < 0 を調べ、負なら None を返します。",
                "test k = 1 − η²(1 − cos²θ₁) < 0 before the square root, and return None when it is.",
            ),
        )
    } else if expected.is_none() && actual.is_some() {
        (
            t(
                "全反射（屈折光がない）なのに方向を返しています。",
                "this is total internal reflection (there is no refracted ray), yet a direction came back.",
            ),
            t(
                "屈折率の大きい側から θ₁ > 臨界角 (sin θc = n₂/n₁) で当たると全反射: None を返します。",
                "from the denser side beyond the critical angle (sin θc = n₂/n₁) all light is reflected: return None.",
            ),
        )
    } else if inside
        && ((near(actual, not_flipped) && !near(not_flipped, expected))
            || (near(actual, not_swapped) && !near(not_swapped, expected)))
    {
        (
            t(
                "物体の内側からの光 (i·n > 0) で、法線を反転していないか、屈折率を入れ替えていません。",
                "a ray from inside (i·n > 0): the normal was not flipped or the indices not swapped.",
            ),
            t(
                "i·n > 0 なら n を −n にし、n1 と n2 を入れ替えてから計算します。",
                "when i·n > 0, use −n and swap n1 and n2 before computing.",
            ),
        )
    } else if near(actual, inverted) && !near(inverted, expected) {
        (
            t(
                "屈折率の比が逆です: η = n₂/n₁ になっています。",
                "the ratio of the indices is inverted: this uses η = n₂/n₁.",
            ),
            t(
                "スネルの法則 n₁ sin θ₁ = n₂ sin θ₂ から sin θ₂ = (n₁/n₂) sin θ₁: η = n₁/n₂（入射側 / 透過側）。",
                "Snell's law n₁ sin θ₁ = n₂ sin θ₂ gives sin θ₂ = (n₁/n₂) sin θ₁: η = n₁/n₂ (incident side over transmitted side).",
            ),
        )
    } else if expected.is_some() && actual.is_none() {
        (
            t(
                "屈折光があるのに None を返しています。",
                "there is a refracted ray, yet None came back.",
            ),
            t(
                "None は全反射 (k < 0) のときだけです。",
                "None only for total internal reflection (k < 0).",
            ),
        )
    } else {
        (
            t(
                "スネルの法則による屈折方向になっていません。",
                "this is not the refracted direction by Snell's law.",
            ),
            t(
                "η = n₁/n₂、cos θ₁ = −i·n、k = 1 − η²(1 − cos²θ₁)、t = η·i + (η cos θ₁ − √k)·n を正規化。",
                "η = n₁/n₂, cos θ₁ = −i·n, k = 1 − η²(1 − cos²θ₁), t = η·i + (η cos θ₁ − √k)·n, normalised.",
            ),
        )
    };
    let snell = actual.filter(|v| v.is_finite()).map_or_else(String::new, |v| {
        let (from, to) = if inside { (n2, n1) } else { (n1, n2) };
        let sin1 = f64::from(i.normalize().cross(n).length());
        let sin2 = f64::from(v.normalize().cross(n).length());
        format!(
            "; n₁ sin θ₁ = {:.5}, n₂ sin θ₂ = {:.5}",
            f64::from(from) * sin1,
            f64::from(to) * sin2
        )
    });
    let values = format!("i = {}, n = {}, n1 = {}, n2 = {}", vec(i), vec(n), num(n1), num(n2));
    let theta = theta.to_degrees();
    let critical = critical.map(f64::to_degrees);
    Failure::new(opt(expected), format!("{}{snell}", opt(actual)))
        .at(Text::new(
            format!(
                "{}: {values}（{}、θ₁ = {theta:.3}°{}）",
                name.ja,
                if inside { "内側から" } else { "外側から" },
                critical.map_or_else(String::new, |c| format!("、臨界角 {c:.3}°"))
            ),
            format!(
                "{}: {values} ({}, θ₁ = {theta:.3}°{})",
                name.en,
                if inside { "from inside" } else { "from outside" },
                critical.map_or_else(String::new, |c| format!(", critical angle {c:.3}°"))
            ),
        ))
        .cause(cause)
        .hint(hint)
}

fn matches(actual: Option<Vec3>, expected: Option<Vec3>) -> bool {
    match (actual, expected) {
        (Some(a), Some(e)) => max_diff(a, e) <= 1e-5,
        (None, None) => true,
        _ => false,
    }
}

/// Random rays on both sides of interfaces with the student's medium and others; rays closer
/// than 1e-3 rad to the critical angle are left out.
pub(super) fn refract(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let eta = spec.medium.eta;
    let pairs = [(1.0, eta), (1.0, 1.33), (1.0, 1.5), (1.33, 1.5), (1.0, 2.42)];
    let mut r = Inputs::new(0x5_0008);
    let mut k = 0;
    while k < 80 {
        let n = r.unit_vector();
        let i = r.unit_vector();
        let (n1, n2) = pairs[k % pairs.len()];
        let (theta, critical) = angles(i, n, n1, n2);
        if critical.is_some_and(|c| (theta - c).abs() < 1e-3) || i.dot(n).abs() < 1e-3 {
            continue;
        }
        let actual = (imp.refract)(i, n, n1, n2);
        if !matches(actual, oracle(i, n, n1, n2)) {
            return Err(refract_failure(&random_case(k), i, n, n1, n2, actual));
        }
        k += 1;
    }
    Ok(())
}

/// From inside the medium beyond the critical angle: `None`, never NaN.
pub(super) fn total_reflection(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let mut r = Inputs::new(0x5_0009);
    let n = Vec3::Y;
    for (k, eta) in [spec.medium.eta, 1.33, 1.5, 2.42].into_iter().cycle().take(24).enumerate() {
        let critical = (1.0 / f64::from(eta)).asin();
        let theta = critical
            + 0.01
            + f64::from(r.unit_interval()) * (std::f64::consts::FRAC_PI_2 - critical - 0.011);
        let phi = f64::from(r.range(0.0, std::f32::consts::TAU));
        // Travelling up and out of the medium (i·n > 0) at θ from the normal.
        let i = Vec3::new(
            (theta.sin() * phi.cos()) as f32,
            theta.cos() as f32,
            (theta.sin() * phi.sin()) as f32,
        );
        let actual = (imp.refract)(i, n, 1.0, eta);
        if actual.is_some() || oracle(i, n, 1.0, eta).is_some() {
            return Err(refract_failure(
                &Text::new(
                    format!("ケース {k}、媒質 (η = {}) から空気へ出る", num(eta)),
                    format!("case {k}, leaving the medium (η = {}) into air", num(eta)),
                ),
                i,
                n,
                1.0,
                eta,
                actual,
            ));
        }
    }
    Ok(())
}

pub(super) fn refract_hard(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let eta = spec.medium.eta;
    let n = Vec3::Y;
    let tilted = |deg: f32, up: bool| {
        let a = deg.to_radians();
        Vec3::new(a.sin(), if up { a.cos() } else { -a.cos() }, 0.0)
    };
    let cases: Vec<(Text, Vec3, f32, f32)> = vec![
        (t("外側からの垂直入射", "normal incidence from outside"), Vec3::NEG_Y, 1.0, eta),
        (t("内側からの垂直入射", "normal incidence from inside"), Vec3::Y, 1.0, eta),
        (
            t("η = 1 (n1 = n2 = 1): まっすぐ通る", "η = 1 (n1 = n2 = 1): straight through"),
            tilted(40.0, false),
            1.0,
            1.0,
        ),
        (
            t("η = 1 (n1 = n2 = 1.5)、内側から", "η = 1 (n1 = n2 = 1.5), from inside"),
            tilted(70.0, true),
            1.5,
            1.5,
        ),
        (
            t(
                "内側から 30°（n を反転し、n1 と n2 を入れ替える）",
                "30° from inside (flip n, swap n1 and n2)",
            ),
            tilted(30.0, true),
            1.0,
            eta,
        ),
        (t("外側から 30°", "30° from outside"), tilted(30.0, false), 1.0, eta),
        (
            t("外側からかすめる入射 (89.9°)", "grazing from outside (89.9°)"),
            tilted(89.9, false),
            1.0,
            eta,
        ),
        (
            t("外側からちょうどかすめる入射 (i·n = 0)", "grazing exactly (i·n = 0) from outside"),
            Vec3::X,
            1.0,
            eta,
        ),
    ];
    for (name, i, n1, n2) in cases {
        let actual = (imp.refract)(i, n, n1, n2);
        if !matches(actual, oracle(i, n, n1, n2)) {
            return Err(refract_failure(&name, i, n, n1, n2, actual));
        }
    }
    // Exactly the critical angle, leaving the medium: either answer, never NaN.
    let critical = (1.0 / f64::from(eta)).asin();
    let i = Vec3::new(critical.sin() as f32, critical.cos() as f32, 0.0);
    let actual = (imp.refract)(i, n, 1.0, eta);
    let ok = match actual {
        None => true,
        Some(v) => v.is_finite() && (v.length() - 1.0).abs() <= 1e-4 && v.dot(n).abs() <= 2e-3,
    };
    if !ok {
        let (critical, eta, i, n) = (critical.to_degrees(), num(eta), vec(i), vec(n));
        return Err(Failure::new(
            t(
                "None、または面に沿った単位ベクトル (|t·n| ≤ 0.002)",
                "None, or a unit vector along the surface (|t·n| ≤ 0.002)",
            ),
            opt(actual),
        )
        .at(Text::new(
            format!("内側から η = {eta} の臨界角 {critical:.4}° ちょうど: i = {i}, n = {n}"),
            format!(
                "exactly the critical angle {critical:.4}° of η = {eta} from inside: i = {i}, n = {n}"
            ),
        ))
        .cause(t(
            "臨界角ちょうどでは屈折光は面に沿って進みます（k = 0）。丸め誤差で k がわずかに負になることもあります。",
            "at exactly the critical angle the refracted ray runs along the surface (k = 0); rounding may make k slightly negative.",
        ))
        .hint(t(
            "k < 0 なら None、そうでなければ √k を使います。NaN は許されません。",
            "return None when k < 0, otherwise use √k; never NaN.",
        )));
    }
    Ok(())
}
