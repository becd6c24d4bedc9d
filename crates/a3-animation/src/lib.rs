//! Assignment `a3` — アニメーション (animation).
//!
//! 「指定された通りの、複数の物体のアニメーションを実現する。レポートには、課題2と同様、どのような
//! 変換行列を使用したかを示すこと」: every student animates 3 or 4 objects, each with its own
//! motion — 回転運動 (spin), 往復回転運動 (back-and-forth rotation), 放物往復移動運動 (parabolic
//! back-and-forth motion), 公転 (orbit) — one of them carrying a child that moves in its
//! coordinate system (階層的な運動, which needs nested glPushMatrix/glPopMatrix). The periods are
//! whole multiples of one unit, so the report can state their ratios (1 : 2, 2 : 3, …).
//!
//! Every assignment crate has the same shape (the command line and the tests rely on it):
//! [`ID`], a per-student [`Spec`] drawn by [`variant`] and described by [`SpecDescribe::describe`], the
//! exercise API [`Impl`] (the functions a student writes, in `exercises/src/a3.rs`),
//! [`checks()`] and [`view()`].
//!
//! The tasks:
//!
//! | task | function | what |
//! |---|---|---|
//! | `a3.t0` | `warmup_display(gl, t)` | 演習課題: three boxes, the same for everybody ([`warmup_objects`]) |
//! | `a3.t1` | `idle(spec, state)` | one frame (1/60 s) on: the motion parameters (媒介変数) from the frame count |
//! | `a3.t2` | `display(spec, state, gl)` | camera, light, every object with its transform |
//!
//! Time: one call of `idle` is one frame, [`FPS`] frames a second; after `n` calls the time is
//! `t = n / 60` s. docs/numerics.md row 11: the parameters are rebuilt from the integer frame count
//! each frame and reduced by the period, never accumulated in f32 ([`checks()`] runs `idle`
//! [`DRIFT_FRAMES`] times and compares).

mod checks;
mod describe;
mod oracle;
mod pose;
pub mod report;
mod spec;
mod table2;
mod view;

pub use cg_student::a3::{
    CAMERA_DISTANCE, CAMERA_PITCH_DEG, DRIFT_FRAMES, FPS, Impl, LIGHT0_POSITION, Motion, Object,
    PARAMS, SPHERE_SLICES, SPHERE_STACKS, Shape, Spec, State, Turn, WorldAxis, warmup_box,
};
pub use checks::checks;
pub use describe::SpecDescribe;
pub use oracle::{expected_model, model_product, warmup_model};
pub use spec::{
    ShapeExt, SpecExt, WorldAxisExt, camera_product, new_object, variant, warmup_objects,
};
pub(crate) use spec::{gcd, lcm};
pub use view::{VIEW_MAX_S, record_frame, reference, replay, view, warmup_frame, warmup_view};

/// The assignment's ID, the prefix of its task IDs (`a3.t1`, …).
pub const ID: &str = "a3";

/// Assignment 3 as a unit of the kit: what `cg assignment`, `cg check`, `cg view`, the report and the
/// grader need of it (see [`cg_harness::Assignment`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct A3;

impl cg_harness::Assignment for A3 {
    const ID: &'static str = ID;
    const TITLE: (&'static str, &'static str) = ("アニメーション", "animation");
    const REPORT_TIME: f64 = 1.0;
    const WARMUP: bool = true;
    type Spec = Spec;
    type Impl = Impl;
    type Report = report::AnimationData;

    fn variant(rng: &mut cg_harness::VariantRng) -> Spec {
        variant(rng)
    }

    fn describe(spec: &Spec, lang: cg_core::lang::Lang) -> String {
        SpecDescribe::describe(spec, lang)
    }

    fn spec_json(spec: &Spec) -> cg_harness::unit::Json {
        cg_harness::unit::json(spec)
    }

    fn checks(spec: &Spec, imp: &Impl) -> Vec<cg_harness::CheckResult> {
        checks(spec, imp)
    }

    fn report(spec: &Spec, imp: &Impl) -> cg_harness::report::Part<report::AnimationData> {
        report::animation_part(spec, imp)
    }

    fn view(
        spec: &Spec,
        imp: &Impl,
        time_s: f64,
    ) -> Result<cg_core::scene::Scene, cg_harness::Text> {
        view(spec, imp, time_s)
    }

    /// The whole animation repeats after the least common multiple of the periods.
    fn view_period_s(spec: &Spec) -> Option<f64> {
        Some(spec.common_period_s())
    }

    fn reference_view(spec: &Spec, time_s: f64) -> Option<cg_core::scene::Scene> {
        Some(view::reference(spec, time_s))
    }

    fn warmup(imp: &Impl, time_s: f64) -> Option<cg_core::scene::Scene> {
        Some(warmup_view(imp, time_s))
    }
}
