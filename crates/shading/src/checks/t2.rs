//! s.t2: the diffuse term `Ii·kd·max(N·L, 0)` (Lambert) against [`cg_core::light::diffuse`].
//!
//! Tolerance (absolute + relative, per channel): 1e-5.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use super::material;
use crate::inputs::{Inputs, case_at, close, num, random_case, vec};
use crate::{Impl, Spec};

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
