//! s.t1: the ambient term `Ia·ka` against [`cg_core::light::ambient`].
//!
//! Tolerance (absolute + relative, per channel): 1e-6 (one product).

use cg_core::Rgb;
use cg_core::light;
use cg_harness::check::Failure;
use cg_harness::text::t;

use crate::inputs::{Inputs, case_at, close, random_case, vec};
use crate::{Impl, Spec};

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
