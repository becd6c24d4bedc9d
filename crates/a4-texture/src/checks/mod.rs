//! The checks of assignment 4, one property each, every one calling the student's code inside its
//! closure. Expected values come from the f64 oracle in [`crate::spec`] (the region worked from
//! its pixels; each block's coordinates as the bilinear blend of the four corner coordinates the
//! orientation puts there, the orientation worked forwards with quarter turns of integer
//! vectors) — never from the reference solution.
//!
//! Tolerances: `a4.t1` is exact up to 1e-6 (the answers are multiples of 1/8, exact in f32; a
//! division may round). `a4.t2` compares within 1e-5: a formula in f32 rounds by a few ulp of 1
//! (≈ 1e-7) per operation, and one texel is 1/512 ≈ 2e-3, so 1e-5 accepts every honest formula
//! and refuses every mistake a viewer could see.

use cg_harness::CheckResult;
use cg_harness::check::{self, Failure, Outcome};
use cg_harness::text::{Text, t};

use crate::Impl;
use crate::spec::Spec;

mod t1;
mod t2;
mod t3;

/// An `a4.t2` failure while `a4.t1` fails too (`t1_right` false): `tex_coords` usually takes the
/// region's corners from `tex_range`, so the hint says to fix a4.t1 first (every a4.t2 failure of
/// a student whose t range was upside down came from it).
fn after_t1(t1_right: bool, result: Result<(), Failure>) -> Result<(), Failure> {
    result.map_err(|f| {
        if t1_right {
            return f;
        }
        let hint = Text::new(
            format!(
                "あなたの tex_range（a4.t1）がまだ正しくありません。tex_coords がそれを使っているなら、先に a4.t1 を直してください。{}",
                f.hint.ja
            ),
            format!(
                "your tex_range (a4.t1) is not right yet: if tex_coords uses it, fix a4.t1 first. {}",
                f.hint.en
            ),
        );
        f.hint(hint)
    })
}

/// Every check of this assignment for `spec`, run against `imp`.
#[must_use]
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    let s_range = check::run(
        "a4.t1.s_range",
        t("s の範囲（左右）", "the range of s (left to right)"),
        || t1::s_range(spec, imp),
    );
    let t_range = check::run(
        "a4.t1.t_range",
        t("t の範囲（上下）", "the range of t (bottom to top)"),
        || t1::t_range(spec, imp),
    );
    let t1_right = s_range.outcome == Outcome::Pass && t_range.outcome == Outcome::Pass;
    vec![
        s_range,
        t_range,
        check::run(
            "a4.t2.corners",
            t(
                "地面の 4 隅に範囲の正しい角が来る",
                "the ground's 4 corners get the right corners of the region",
            ),
            || after_t1(t1_right, t2::corners(spec, imp)),
        ),
        check::run(
            "a4.t2.range",
            t("まとまりごとに範囲をちょうど覆う", "each block covers exactly the region"),
            || after_t1(t1_right, t2::block_range(spec, imp)),
        ),
        check::run(
            "a4.t2.shared",
            t("共有する頂点は同じ座標", "shared vertices share coordinates"),
            || after_t1(t1_right, t2::shared(spec, imp)),
        ),
        check::run(
            "a4.t2.linear",
            t("i と j の 1 次式（特別扱いなし）", "a linear formula in i and j (no special cases)"),
            || after_t1(t1_right, t2::linear(spec, imp)),
        ),
        check::run(
            "a4.t2.orientation",
            t("向き（回転・反転）", "orientation (turn and mirror)"),
            || after_t1(t1_right, t2::orientation(spec, imp)),
        ),
        check::run(
            "a4.t2.cells",
            t(
                "どの四角形にも範囲の正しい場所が映る",
                "every square shows the right place of the region",
            ),
            || after_t1(t1_right, t2::cells(spec, imp)),
        ),
        check::run(
            "a4.t3.wrap",
            t("折り返しが繰り返しの作り方に合う", "the wrap modes suit how the region repeats"),
            || t3::wrap(spec, imp),
        ),
    ]
}
