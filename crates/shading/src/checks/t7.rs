//! s.t7: the mirror direction (reflection) against [`cg_core::optics::reflect`] (docs/numerics.md
//! row 12).
//!
//! Tolerance: 1e-5·(1 + |i|) per component.

use cg_core::glam::Vec3;
use cg_core::optics;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::Impl;
use crate::inputs::{Inputs, case_at, max_diff, random_case, vec};

pub(super) fn reflect(imp: &Impl) -> Result<(), Failure> {
    let mut cases: Vec<(Text, Vec3, Vec3)> = vec![
        (t("垂直入射 (i = -n)", "normal incidence (i = -n)"), Vec3::NEG_Y, Vec3::Y),
        (t("かすめる入射 (i ⟂ n)", "grazing (i ⟂ n)"), Vec3::X, Vec3::Y),
        ("45°".into(), Vec3::new(1.0, -1.0, 0.0).normalize(), Vec3::Y),
        (
            t("n が反対側", "n on the other side"),
            Vec3::new(1.0, -1.0, 0.0).normalize(),
            Vec3::NEG_Y,
        ),
        ("|i| = 2.5".into(), Vec3::new(1.5, -2.0, 0.0), Vec3::Y),
    ];
    let mut r = Inputs::new(0x5_0007);
    for k in 0..40 {
        let n = r.unit_vector();
        let i = r.unit_vector() * r.range(0.5, 2.0);
        cases.push((random_case(k), i, n));
    }
    for (name, i, n) in cases {
        let expected = optics::reflect(i, n);
        let actual = (imp.reflect)(i, n);
        if max_diff(actual, expected) <= 1e-5 * (1.0 + i.length()) {
            continue;
        }
        let (cause, hint) = if max_diff(actual, i + 2.0 * i.dot(n) * n) <= 1e-5 * (1.0 + i.length())
        {
            (
                t(
                    "符号が逆です: i + 2(i·n)n になっています。",
                    "the sign is wrong: this is i + 2(i·n)n.",
                ),
                t(
                    "r = i − 2(i·n)n。i は面へ向かう向き、r は面から離れる向きです（n·r = −n·i）。",
                    "r = i − 2(i·n)n: i travels towards the surface, r away from it (n·r = −n·i).",
                ),
            )
        } else {
            (
                t(
                    "正反射方向 i − 2(i·n)n になっていません。",
                    "this is not the mirror direction i − 2(i·n)n.",
                ),
                t(
                    "n は単位ベクトル。i の長さは変えません（正規化しない）。",
                    "n is unit length; keep the length of i (do not normalise).",
                ),
            )
        };
        return Err(Failure::new(vec(expected), vec(actual))
            .at(case_at(&name, &format!("i = {}, n = {}", vec(i), vec(n))))
            .cause(cause)
            .hint(hint));
    }
    Ok(())
}
