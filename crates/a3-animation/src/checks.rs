//! The checks of `a3`: each runs the student's `idle` / `display` / `warmup_display` inside
//! [`check::run`], reads what the recording context [`Gl`] saw (every draw's model-view matrix,
//! the light, stack errors) and compares each object's pose with the f64 oracle of
//! [`crate::oracle`].
//!
//! A pose is the model matrix `M = V⁻¹ · (model-view at the draw)` with the common camera
//! `V = T(0, 0, -15) · Rx(30°)` taken off in f64. Two poses agree when their rotation parts
//! differ by at most `tol` (‖R₁ − R₂‖_F / √2, about the angle between them in radians) and their
//! origins by at most `tol` scene units.
//!
//! | check | tolerance | why |
//! |---|---|---|
//! | poses, warm-up, periods | 1e-3 | far above f32 rounding (≈ 1e-6 here), far below one frame of the slowest motion (≥ 5e-3) |
//! | drift after 10⁶ frames | 1e-5 | NUMERICS.md row 11; an angle rebuilt from the frame count is within ≈ 1e-6 |

use cg_core::gl::{Draw, Gl};
use cg_core::glam::{DMat3, DMat4, DVec3, Vec3};
use cg_core::lang::Lang;
use cg_core::product::{MatrixProduct, format_number};
use cg_harness::check::{self, CheckResult, Failure};
use cg_harness::text::{Text, t};

use crate::describe::shape_text;
use crate::oracle::{Variation, expected_model_with, warmup_model_with};
use crate::pose::{draws_named, model_of, name_matches, pose_error, seconds, view};
use crate::{
    DRIFT_FRAMES, FPS, Impl, LIGHT0_POSITION, Motion, Object, ShapeExt, Spec, SpecExt, State,
    camera_product, model_product, warmup_frame, warmup_objects,
};

/// The frames at which poses are compared (after that many calls of `idle`): spread over the
/// first 10.5 s so every phase of every motion is hit at different points.
const POSE_FRAMES: [u64; 10] = [1, 9, 23, 37, 60, 97, 151, 240, 389, 631];
/// The times (s) at which the warm-up's boxes are compared.
const WARMUP_TIMES: [f64; 7] = [0.1, 0.35, 0.8, 1.25, 1.7, 2.6, 3.3];
/// Pose tolerance (radians for the rotation part, scene units for the origin).
const POSE_TOL: f64 = 1e-3;
/// Drift tolerance after 10⁶ frames (NUMERICS.md row 11).
const DRIFT_TOL: f64 = 1e-5;
/// The reference frames a repetition must hold at: pose(n + L) = pose(n) for each.
const REPEAT_REFS: [u64; 4] = [1, 5, 12, 30];

/// Every check of this assignment for `spec`, run against `imp`.
#[must_use]
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    vec![
        check::run("a3.t0.box1", t("box 1 の回転運動", "box 1's rotation"), || {
            warmup_box(imp, 0)
        }),
        check::run(
            "a3.t0.box2",
            t("box 2 の往復回転運動", "box 2's back-and-forth rotation"),
            || warmup_box(imp, 1),
        ),
        check::run(
            "a3.t0.box3",
            t("box 3 の放物往復移動運動", "box 3's parabolic back-and-forth motion"),
            || warmup_box(imp, 2),
        ),
        check::run(
            "a3.t0.stack",
            t("演習課題の glPushMatrix / glPopMatrix の対応", "the warm-up's push/pop balance"),
            || warmup_stack(imp),
        ),
        check::run("a3.t1.periods", t("各物体の周期", "each object's period"), || {
            periods(spec, imp)
        }),
        check::run(
            "a3.t1.ratios",
            t("物体同士の周期の比", "the ratio of the periods"),
            || ratios(spec, imp),
        ),
        check::run(
            "a3.t1.drift",
            t("10⁶ フレーム後のずれ", "no drift after 10⁶ frames"),
            || drift(spec, imp),
        ),
        check::run(
            "a3.t2.objects",
            t("すべての物体を 1 回ずつ描く", "every object drawn once"),
            || objects(spec, imp),
        ),
        check::run(
            "a3.t2.light",
            t("光源をカメラの変換の直後に設定", "the light set right after the camera"),
            || light(spec, imp),
        ),
        check::run(
            "a3.t2.stack",
            t("glPushMatrix / glPopMatrix の対応", "push/pop balanced, no GL errors"),
            || stack(spec, imp),
        ),
        check::run(
            "a3.t2.poses",
            t("各時刻の各物体の位置と向き", "each object's pose over time"),
            || poses(spec, imp),
        ),
        check::run(
            "a3.t2.independent",
            t("独立した物体の変換が他に影響しない", "independent objects stay independent"),
            || independent(spec, imp),
        ),
        check::run(
            "a3.t2.hierarchy",
            t("子が親の座標系で動く（階層）", "the child moves in its parent's coordinates"),
            || hierarchy(spec, imp),
        ),
    ]
}

// ---------------------------------------------------------------------------------------------
// Poses and their comparison
// ---------------------------------------------------------------------------------------------

fn close(found: DMat4, expected: DMat4, tol: f64) -> bool {
    let (r, p) = pose_error(found, expected);
    r <= tol && p <= tol
}

fn is_identity(m: DMat4) -> bool {
    close(m, DMat4::IDENTITY, POSE_TOL)
}

fn v3(v: DVec3) -> String {
    let f = |x: f64| format_number(x as f32);
    format!("({}, {}, {})", f(v.x), f(v.y), f(v.z))
}

fn origin(m: DMat4) -> DVec3 {
    m.w_axis.truncate()
}

/// `t = 2.5 s、フレーム 150` / `t = 2.5 s, frame 150`.
fn at_frame(frame: u64) -> Text {
    let t = seconds(frame as f64 / f64::from(FPS));
    Text::new(format!("t = {t} s、フレーム {frame}"), format!("t = {t} s, frame {frame}"))
}

/// `物体2` / `object 2` (the name it is drawn with).
fn object_label(spec: &Spec, i: usize) -> Text {
    let name = spec.objects.get(i).map_or("?", |o| o.name.as_str());
    Text::new(format!("物体{}", i + 1), name)
}

/// `a` and `b` joined by `sep_ja` / `sep_en`.
fn pair(a: &Text, sep_ja: &str, sep_en: &str, b: &Text) -> Text {
    Text::new(format!("{}{sep_ja}{}", a.ja, b.ja), format!("{}{sep_en}{}", a.en, b.en))
}

/// `texts` joined by `sep` in each language.
fn joined(texts: &[Text], sep: &str) -> Text {
    let join = |lang| texts.iter().map(|t| t.get(lang)).collect::<Vec<_>>().join(sep);
    Text::new(join(Lang::Ja), join(Lang::En))
}

fn names_drawn(gl: &Gl) -> Text {
    if gl.draws().is_empty() {
        return t("何も描かれていない", "nothing drawn");
    }
    let names: Vec<String> = gl.draws().iter().map(|d| format!("\"{}\"", d.name)).collect();
    let names = names.join(", ");
    Text::new(format!("描かれたもの: {names}"), format!("drawn: {names}"))
}

/// `1 フレームに 1 回 gl.draw("object 1", …)` / `gl.draw("object 1", …) once per frame`.
fn once_per_frame(object: &Object) -> Text {
    Text::new(
        format!("1 フレームに 1 回 gl.draw(\"{}\", …)", object.name),
        format!("gl.draw(\"{}\", …) once per frame", object.name),
    )
}

/// The one draw of `object` in `gl`, or why there is not exactly one.
fn the_draw<'a>(gl: &'a Gl, object: &Object, location: &Text) -> Result<&'a Draw, Failure> {
    let found = draws_named(gl, &object.name);
    match found.len() {
        1 => Ok(found[0]),
        0 => Err(Failure::new(once_per_frame(object), names_drawn(gl))
            .at(location.clone())
            .cause(Text::new(
                format!(
                    "\"{}\" が描かれていません（名前の綴りが違うか、まだ描いていない）",
                    object.name
                ),
                format!("\"{}\" is not drawn (a different name, or not drawn yet)", object.name),
            ))
            .hint(t(
                "各物体を gl.draw(&object.name, &object.mesh) で描いてください",
                "draw each object with gl.draw(&object.name, &object.mesh)",
            ))),
        n => Err(Failure::new(
            once_per_frame(object),
            Text::new(
                format!("\"{}\" という名前の描画が {n} 回", object.name),
                format!("{n} draws named \"{}\"", object.name),
            ),
        )
        .at(location.clone())
        .cause(t(
            "同じ物体を 1 フレームに何度も描いています",
            "the same object is drawn more than once in one frame",
        ))
        .hint(t(
            "ループの中で描いていないか確認してください",
            "check for a draw call inside a loop",
        ))),
    }
}

// ---------------------------------------------------------------------------------------------
// Running the student's code
// ---------------------------------------------------------------------------------------------

/// Runs `idle` from the start and, after each frame count in `frames` (ascending), records
/// `display` and hands the frame to `visit`; stops at the first error `visit` returns.
fn each_frame(
    spec: &Spec,
    imp: &Impl,
    frames: impl IntoIterator<Item = u64>,
    mut visit: impl FnMut(u64, &Gl) -> Result<(), Failure>,
) -> Result<(), Failure> {
    let mut state = State::new();
    let mut done = 0;
    for frame in frames {
        while done < frame {
            (imp.idle)(spec, &mut state);
            done += 1;
        }
        let mut rec = cg_student::gl::Gl::new();
        (imp.display)(spec, &state, &mut rec);
        visit(frame, &crate::replay(&rec))?;
    }
    Ok(())
}

fn nothing_drawn(location: Text, task: &str) -> Failure {
    Failure::new(
        t("物体が描かれている", "the objects drawn"),
        t("何も描かれていない", "nothing drawn"),
    )
    .at(location)
    .cause(Text::new(
        format!("{task} がまだできていません（何も描かれていません）"),
        format!("{task} is not done yet: nothing is drawn"),
    ))
    .hint(t(
        "display() でカメラ、光源、各物体を描いてください",
        "write display(): the camera, the light, then each object",
    ))
}

// ---------------------------------------------------------------------------------------------
// Naming a mistake
// ---------------------------------------------------------------------------------------------

/// What a wrong pose most likely comes from: (cause, hint).
struct Diagnosis {
    cause: Text,
    hint: Text,
}

impl Diagnosis {
    fn new(cause: Text, hint: Text) -> Diagnosis {
        Diagnosis { cause, hint }
    }
}

/// Ways to evaluate the expected pose for comparison with a wrong one.
#[derive(Clone, Copy)]
enum Shift {
    Exact,
    OneLate,
    OneEarly,
    Twice,
    Half,
}

/// Names the likely mistake behind `found` ≠ `expected` for a draw: a leak from an earlier draw,
/// the camera missing or twice, radians, the wrong way round, the order reversed, a frame late,
/// the wrong time base, a wrong parabola.
fn diagnose(
    found: DMat4,
    expected: DMat4,
    gl: &Gl,
    draw: &Draw,
    motion: &Motion,
    parent: Option<&str>,
    eval: &dyn Fn(Variation, Shift) -> Option<DMat4>,
) -> Diagnosis {
    let v = view();
    if close(found, v.inverse() * expected, POSE_TOL) {
        return Diagnosis::new(
            t(
                "カメラの変換 T(0, 0, -15)·Rx(30°) がかかっていません",
                "the camera transform T(0, 0, -15)·Rx(30°) is missing",
            ),
            t(
                "display() の最初に glLoadIdentity、カメラの変換を置き、その後に物体を描いてください",
                "start display() with glLoadIdentity and the camera transform, then draw the objects",
            ),
        );
    }
    if close(found, v * expected, POSE_TOL) {
        return Diagnosis::new(
            t("カメラの変換が 2 回かかっています", "the camera transform is applied twice"),
            t(
                "カメラの変換は 1 回だけ（glLoadIdentity の直後に）",
                "apply the camera once, right after glLoadIdentity",
            ),
        );
    }
    if let Some(earlier) = leaked_from(found, expected, gl, draw, parent) {
        return leak_diagnosis(&earlier);
    }
    let checks: [(Variation, Shift, Text, Text); 7] = [
        (
            Variation::RADIANS,
            Shift::Exact,
            t(
                "角度をラジアンで渡しています（glRotatef は度）",
                "the angle is in radians (glRotatef takes degrees)",
            ),
            t(
                "角度は度で: θ = 360°·t/T。sin には度をラジアンに直して渡します",
                "use degrees: θ = 360°·t/T; convert to radians only for sin",
            ),
        ),
        (
            Variation::MIRRORED,
            Shift::Exact,
            t("回る向き（振れ始める向き）が逆です", "it turns (or starts swinging) the wrong way"),
            t(
                "角度の符号を確認してください（反時計回りは + の角度）",
                "check the angle's sign (counter-clockwise is a positive angle)",
            ),
        ),
        (
            Variation::REVERSED,
            Shift::Exact,
            t("回転と平行移動の順番が逆です", "rotation and translation are in the wrong order"),
            t(
                "公転は T(中心)·Ry(θ)·T(0, 0, r)、振り子は T(支点)·R(θ)·T(0, −腕, 0)、自転は T(位置)·R(θ) の順に呼びます",
                "an orbit is T(centre)·Ry(θ)·T(0, 0, r), a pendulum T(pivot)·R(θ)·T(0, −arm, 0), a spin T(position)·R(θ), called in that order",
            ),
        ),
        (
            Variation::EXACT,
            Shift::OneLate,
            t("1 フレーム遅れています", "it is one frame late"),
            t(
                "idle() では先に state.frame に 1 を足し、その新しい state.frame から変数を求めてください",
                "in idle(), add 1 to state.frame first, then compute the parameters from the new frame",
            ),
        ),
        (
            Variation::EXACT,
            Shift::OneEarly,
            t("1 フレーム進んでいます", "it is one frame early"),
            t(
                "t = state.frame/60 秒です。state.frame + 1 を使っていないか確認してください",
                "t = frame/60 s: check that you do not use frame + 1",
            ),
        ),
        (
            Variation::EXACT,
            Shift::Twice,
            t("時間が 2 倍の速さで進んでいます", "time runs twice as fast"),
            t(
                "1 フレームは 1/60 秒です（t = state.frame/60）",
                "one frame is 1/60 s (t = frame/60)",
            ),
        ),
        (
            Variation::EXACT,
            Shift::Half,
            t(
                "時間が半分の速さで進んでいます（30 fps として計算？）",
                "time runs at half speed (computed for 30 fps?)",
            ),
            t(
                "1 フレームは 1/60 秒です（t = state.frame/60）",
                "one frame is 1/60 s (t = frame/60)",
            ),
        ),
    ];
    for (variation, shift, cause, hint) in checks {
        if let Some(m) = eval(variation, shift)
            && !close(m, expected, POSE_TOL)
            && close(found, m, POSE_TOL)
        {
            return Diagnosis::new(cause, hint);
        }
    }
    if let Motion::Hop { along, height, span, .. } = *motion {
        let a = along.vector().as_dvec3();
        let (f, e) = (origin(found), origin(expected));
        if ((f - e) - a * (f - e).dot(a)).dot(DVec3::Y).abs() > POSE_TOL
            && (f - e).dot(a).abs() <= POSE_TOL
        {
            let h = format_number(height);
            let y = crate::describe::parabola_text(height, span, "s");
            return Diagnosis::new(
                Text::new(
                    format!(
                        "水平方向の位置は正しいのに、高さが違います（高さ {h} の放物線になっていない）"
                    ),
                    format!(
                        "the horizontal position is right but the height is not (not a parabola of height {h})"
                    ),
                ),
                Text::new(
                    format!(
                        "高さは中心からのずれ s の 2 次式 y = {y} です（直線的な上下や、高さの取り違えに注意）"
                    ),
                    format!(
                        "the height is quadratic in the offset s: y = {y} (not a linear up-and-down, not a different height)"
                    ),
                ),
            );
        }
    }
    Diagnosis::new(
        t(
            "この時刻の位置・向きが指定と違います（変数の式、周期、回転軸、平行移動の値を確認）",
            "the position or orientation at this time is not the specified one (check the formula of the variables, the period, the axis and the translation)",
        ),
        t(
            "期待する変換の積と、あなたの積を 1 因子ずつ比べてください",
            "compare the expected product with yours, factor by factor",
        ),
    )
}

/// An earlier draw whose transform `found` still carries: its factors are a prefix of this
/// draw's (the transforms were never popped), or numerically `found ≈ M_earlier · expected`.
/// The draw's `parent` (whose transforms it must carry) does not count.
fn leaked_from(
    found: DMat4,
    expected: DMat4,
    gl: &Gl,
    draw: &Draw,
    parent: Option<&str>,
) -> Option<String> {
    let camera_len = camera_factors(draw);
    gl.draws()
        .iter()
        .filter(|d| d.call < draw.call && parent.is_none_or(|p| !name_matches(&d.name, p)))
        .rev()
        .find(|d| {
            let m = model_of(d);
            let numeric = !is_identity(m) && close(found, m * expected, POSE_TOL);
            let structural = !is_identity(m)
                && d.model_view.factors.len() > camera_len
                && d.model_view.factors.len() < draw.model_view.factors.len()
                && draw.model_view.factors.starts_with(&d.model_view.factors);
            numeric || structural
        })
        .map(|d| d.name.clone())
}

/// How many leading factors of a draw's product are the camera (0 when they are not the
/// common camera's two factors).
fn camera_factors(draw: &Draw) -> usize {
    let cam = camera_product();
    let n = cam.factors.len();
    let head = MatrixProduct { factors: draw.model_view.factors.iter().take(n).cloned().collect() };
    match head.matrix() {
        Ok(m) if head.factors.len() == n && cam.matrix().is_ok_and(|c| c.abs_diff_eq(m, 1e-5)) => n,
        _ => 0,
    }
}

fn leak_diagnosis(earlier: &str) -> Diagnosis {
    Diagnosis::new(
        Text::new(
            format!(
                "前に描いた \"{earlier}\" の変換が残ったまま描いています（glPushMatrix / glPopMatrix が足りない）"
            ),
            format!(
                "\"{earlier}\"'s transforms still apply (a glPushMatrix / glPopMatrix is missing)"
            ),
        ),
        Text::new(
            format!(
                "\"{earlier}\" の変換の前に glPushMatrix、描いた後に glPopMatrix を入れてください"
            ),
            format!(
                "put glPushMatrix before \"{earlier}\"'s transforms and glPopMatrix after drawing it"
            ),
        ),
    )
}

/// The failure for a wrong pose: the expected and found products and origins.
fn pose_failure(
    expected_product: &MatrixProduct,
    expected: DMat4,
    found: DMat4,
    draw: &Draw,
    location: Text,
    diagnosis: Diagnosis,
    others: &[Text],
) -> Failure {
    let (rot, pos) = pose_error(found, expected);
    let (also_ja, also_en) = if others.is_empty() {
        (String::new(), String::new())
    } else {
        let others = joined(others, ", ");
        (format!("; ほかに違う物体: {}", others.ja), format!("; also wrong: {}", others.en))
    };
    let product = camera_product().concat(expected_product).numeric();
    let (o_expected, o_found) = (v3(origin(expected)), v3(origin(found)));
    let (mv, rot, pos) = (draw.model_view.numeric(), rot.to_degrees(), format_number(pos as f32));
    Failure::new(
        Text::new(
            format!("{product} → 原点 {o_expected}"),
            format!("{product} → origin {o_expected}"),
        ),
        Text::new(
            format!("{mv} → 原点 {o_found}（回転のずれ {rot:.3}°、位置のずれ {pos}{also_ja}）"),
            format!("{mv} → origin {o_found} (off by {rot:.3}° and {pos} units{also_en})"),
        ),
    )
    .at(location)
    .cause(diagnosis.cause)
    .hint(diagnosis.hint)
}

// ---------------------------------------------------------------------------------------------
// a3.t0: the warm-up
// ---------------------------------------------------------------------------------------------

fn warmup_box(imp: &Impl, k: usize) -> Result<(), Failure> {
    let boxes = warmup_objects();
    let object = &boxes[k];
    for &time in &WARMUP_TIMES {
        let gl = warmup_frame(imp, time);
        let location = Text::from(format!("{}, t = {} s", object.name, seconds(time)));
        if gl.draws().is_empty() {
            return Err(Failure::new(
                format!("gl.draw(\"{}\", …)", object.name),
                names_drawn(&gl),
            )
            .at(location)
            .cause(t(
                "a3.t0 がまだできていません（何も描かれていません）",
                "a3.t0 is not done yet: nothing is drawn",
            ))
            .hint(t(
                "warmup_display() で 3 つの直方体を gl.draw(\"box 1\", &warmup_box()) などで描いてください",
                "draw the three boxes in warmup_display() with gl.draw(\"box 1\", &warmup_box()) and so on",
            )));
        }
        let draw = the_draw(&gl, object, &location)?;
        let expected = warmup_model_with(object, time, Variation::EXACT);
        let found = model_of(draw);
        if !close(found, expected, POSE_TOL) {
            let eval = |v: Variation, s: Shift| {
                let dt = 1.0 / f64::from(FPS);
                let time = match s {
                    Shift::Exact => time,
                    Shift::OneLate => time - dt,
                    Shift::OneEarly => time + dt,
                    Shift::Twice => 2.0 * time,
                    Shift::Half => time / 2.0,
                };
                Some(warmup_model_with(object, time, v))
            };
            let diagnosis = diagnose(found, expected, &gl, draw, &object.motion, None, &eval);
            let product = warmup_product(object, k, time);
            return Err(pose_failure(&product, expected, found, draw, location, diagnosis, &[]));
        }
    }
    Ok(())
}

/// A warm-up box's transform as named factors at time `t` (box `k`, 0-based).
fn warmup_product(object: &Object, k: usize, time: f64) -> MatrixProduct {
    let u = (time / f64::from(object.motion.period_s())).rem_euclid(1.0);
    crate::oracle::local_product(&object.motion, k + 1, if u >= 1.0 { 0.0 } else { u })
}

fn stack_failure(gl: &Gl, location: Text, task: &str) -> Option<Failure> {
    if let Some(e) = gl.errors().first() {
        let msg_ja = e.error.message(Lang::Ja);
        let msg_en = e.error.message(Lang::En);
        return Some(
            Failure::new(
                t("GL のエラーなし", "no GL errors"),
                Text::new(
                    format!("{}（{} 回目の呼び出し）: {msg_ja}", e.function, e.call),
                    format!("{} (call {}): {msg_en}", e.function, e.call),
                ),
            )
            .at(location)
            .cause(Text::new(
                format!("{} が {} 回目の呼び出しでエラー: {msg_ja}", e.function, e.call),
                format!("{} failed at call {}: {msg_en}", e.function, e.call),
            ))
            .hint(Text::new(
                format!("{task}: glPushMatrix と glPopMatrix は同じ数だけ、push → 変換 → 描画 → pop の順に"),
                format!("{task}: as many glPopMatrix as glPushMatrix, in the order push → transforms → draw → pop"),
            )),
        );
    }
    if gl.depth() != 1 {
        let extra = gl.depth() - 1;
        return Some(
            Failure::new(
                t(
                    "フレームの終わりで行列スタックの深さが 1",
                    "stack depth 1 at the end of the frame",
                ),
                Text::new(
                    format!(
                        "深さ {}（glPopMatrix と対になっていない glPushMatrix が {extra} 個）",
                        gl.depth()
                    ),
                    format!("depth {} ({extra} glPushMatrix without glPopMatrix)", gl.depth()),
                ),
            )
            .at(location)
            .cause(Text::new(
                format!("glPopMatrix が {extra} 個足りません（push したまま）"),
                format!("{extra} glPopMatrix missing (pushed and never popped)"),
            ))
            .hint(Text::new(
                format!("{task}: 各 glPushMatrix に対応する glPopMatrix を入れてください"),
                format!("{task}: give every glPushMatrix its glPopMatrix"),
            )),
        );
    }
    None
}

fn warmup_stack(imp: &Impl) -> Result<(), Failure> {
    for &time in &WARMUP_TIMES {
        let gl = warmup_frame(imp, time);
        let location = Text::from(format!("warmup_display, t = {} s", seconds(time)));
        if gl.draws().is_empty() {
            return Err(Failure::new(
                t("3 つの直方体を描く", "the three boxes drawn"),
                names_drawn(&gl),
            )
            .at(location)
            .cause(t(
                "a3.t0 がまだできていません（何も描かれていません）",
                "a3.t0 is not done yet: nothing is drawn",
            ))
            .hint(t(
                "warmup_display() で 3 つの直方体を描いてください",
                "draw the three boxes in warmup_display()",
            )));
        }
        if let Some(f) = stack_failure(&gl, location, "a3.t0") {
            return Err(f);
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// a3.t2: display
// ---------------------------------------------------------------------------------------------

fn objects(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    each_frame(spec, imp, [1, 60], |frame, gl| {
        for (i, object) in spec.objects.iter().enumerate() {
            let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
            let draw = the_draw(gl, object, &location)?;
            let (want, got) =
                (bounds(&object.shape.mesh().positions), bounds(&draw.mesh.positions));
            let same = match (want, got) {
                (Some((a0, a1)), Some((b0, b1))) => {
                    (a0 - b0).abs().max_element() <= 1e-4 && (a1 - b1).abs().max_element() <= 1e-4
                }
                _ => false,
            };
            if !same {
                let show = |b: Option<(Vec3, Vec3)>| {
                    b.map_or(t("頂点なし", "no vertices"), |(lo, hi)| {
                        format!("{} … {}", v3(lo.as_dvec3()), v3(hi.as_dvec3())).into()
                    })
                };
                let (want, got) = (show(want), show(got));
                return Err(Failure::new(
                    Text::new(
                        format!("{}: 範囲 {}", shape_text(&object.shape, Lang::Ja), want.ja),
                        format!("{}: bounds {}", shape_text(&object.shape, Lang::En), want.en),
                    ),
                    Text::new(format!("範囲 {}", got.ja), format!("bounds {}", got.en)),
                )
                .at(location)
                .cause(t(
                    "描いたメッシュの大きさか中心の位置が指定と違います",
                    "the mesh drawn has a different size or is not centred on its origin",
                ))
                .hint(t(
                    "メッシュは spec.objects[i].mesh を使い、glScalef は使わないでください",
                    "draw spec.objects[i].mesh and do not scale it",
                )));
            }
        }
        Ok(())
    })
}

/// The axis-aligned bounds of some points, `None` for none or a non-finite one.
fn bounds(points: &[Vec3]) -> Option<(Vec3, Vec3)> {
    let first = *points.first()?;
    let (lo, hi) = points.iter().fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

fn light(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    each_frame(spec, imp, [1], |frame, gl| {
        let location = pair(&"GL_LIGHT0".into(), "、", ", ", &at_frame(frame));
        let given = cg_core::glam::Vec4::from_array(LIGHT0_POSITION);
        let expected = view() * given.as_dvec4();
        let show = |p: cg_core::glam::DVec4| {
            let f = |x: f64| format_number(x as f32);
            format!("({}, {}, {}, {})", f(p.x), f(p.y), f(p.z), f(p.w))
        };
        let Some(l) = gl.lights().iter().find(|l| l.light == 0) else {
            return Err(Failure::new(
                Text::new(
                    format!("gl.light_position(0, [10, 10, 10, 1]) → 視点座標で {}", show(expected)),
                    format!("gl.light_position(0, [10, 10, 10, 1]) → eye {}", show(expected)),
                ),
                t("光源の位置が設定されていない", "no light set"),
            )
            .at(location)
            .cause(t("display() で光源の位置を設定していません", "display() does not set the light's position"))
            .hint(t(
                "カメラの変換の直後に gl.light_position(0, [10.0, 10.0, 10.0, 1.0]) を呼んでください",
                "call gl.light_position(0, [10.0, 10.0, 10.0, 1.0]) right after the camera transform",
            )));
        };
        let eye = l.eye.as_dvec4();
        if (eye - expected).abs().max_element() <= 1e-4 {
            return Ok(());
        }
        let before = (eye - given.as_dvec4()).abs().max_element() <= 1e-4;
        let cause = if before {
            t(
                "光源をカメラの変換の前に設定しています（光源がカメラと一緒に動き、ワールドに固定されない）",
                "the light is set before the camera transform (it moves with the camera instead of staying in the world)",
            )
        } else if l.given.as_dvec4() != given.as_dvec4() {
            t(
                "光源の位置の値が (10, 10, 10, 1) ではありません",
                "the light's position is not (10, 10, 10, 1)",
            )
        } else {
            t(
                "光源を設定したときの変換がカメラの変換だけではありません（物体の変換の後に設定している？）",
                "the model-view matrix when the light is set is not just the camera's (set after an object's transforms?)",
            )
        };
        let (expected, eye, mv) = (show(expected), show(eye), l.model_view.numeric());
        Err(Failure::new(
            Text::new(
                format!("視点座標で {expected}（= V · (10, 10, 10, 1)）"),
                format!("eye {expected} (= V · (10, 10, 10, 1))"),
            ),
            Text::new(
                format!("視点座標で {eye}（モデルビュー行列 {mv}）"),
                format!("eye {eye} (model-view {mv})"),
            ),
        )
        .at(location)
        .cause(cause)
        .hint(t(
            "glLoadIdentity → カメラの変換 → gl.light_position(0, …) → 物体、の順にしてください",
            "use the order glLoadIdentity → camera transform → gl.light_position(0, …) → objects",
        )))
    })
}

fn stack(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    each_frame(spec, imp, POSE_FRAMES[..4].iter().copied(), |frame, gl| {
        let location = pair(&"display()".into(), "、", ", ", &at_frame(frame));
        if gl.draws().is_empty() {
            return Err(nothing_drawn(location, "a3.t2"));
        }
        stack_failure(gl, location, "a3.t2").map_or(Ok(()), Err)
    })
}

/// Shifts a frame count as a hypothesis about the student's time base says; `None` where it
/// has no such frame.
fn shifted(frame: u64, s: Shift) -> Option<u64> {
    match s {
        Shift::Exact => Some(frame),
        Shift::OneLate => frame.checked_sub(1),
        Shift::OneEarly => Some(frame + 1),
        Shift::Twice => Some(2 * frame),
        Shift::Half if frame.is_multiple_of(2) => Some(frame / 2),
        Shift::Half => None,
    }
}

/// Compares every object's pose with the spec's at every pose frame. The failure names the
/// first wrong object at its first wrong frame, the other wrong objects, and a mistake that
/// explains that object's poses at *every* frame (a hypothesis that fits one frame only, such as
/// "one frame early" against "twice as fast" at frame 1, is not offered).
fn poses(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let mut found: Vec<Vec<(u64, DMat4)>> = vec![Vec::new(); spec.objects.len()];
    let mut first: Option<(u64, usize, Gl)> = None;
    let mut wrong: Vec<usize> = Vec::new();
    each_frame(spec, imp, POSE_FRAMES, |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t2"));
        }
        for (i, object) in spec.objects.iter().enumerate() {
            let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
            let m = model_of(the_draw(gl, object, &location)?);
            found[i].push((frame, m));
            if !close(m, expected_model_with(spec, i, frame, Variation::EXACT, 0), POSE_TOL) {
                if first.is_none() {
                    first = Some((frame, i, gl.clone()));
                }
                if !wrong.contains(&i) {
                    wrong.push(i);
                }
            }
        }
        Ok(())
    })?;
    let Some((frame, i, gl)) = first else { return Ok(()) };
    let object = &spec.objects[i];
    let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
    let draw = the_draw(&gl, object, &location)?;
    let (found_now, expected) =
        (model_of(draw), expected_model_with(spec, i, frame, Variation::EXACT, 0));
    let eval = |v: Variation, s: Shift| {
        let fits_everywhere = found[i].iter().all(|&(f, m)| {
            shifted(f, s).is_none_or(|g| close(m, expected_model_with(spec, i, g, v, 0), POSE_TOL))
        });
        if fits_everywhere {
            Some(expected_model_with(spec, i, shifted(frame, s)?, v, 0))
        } else {
            None
        }
    };
    let parent = object.motion.parent().and_then(|p| spec.objects.get(p)).map(|p| p.name.as_str());
    let own_period = object.motion.period_frames();
    // Another period that explains every frame: another object's, or twice or half its own.
    let mut periods: Vec<u64> = spec.objects.iter().map(|o| o.motion.period_frames()).collect();
    periods.extend([2 * own_period, own_period / 2]);
    // (A wrong time base explains it as well, and better: every object is off then.)
    let time_base = eval(Variation::EXACT, Shift::Twice).is_some()
        || eval(Variation::EXACT, Shift::Half).is_some();
    let other_period =
        periods.into_iter().filter(|&p| !time_base && p > 1 && p != own_period).find(|&p| {
            let v = Variation { period: Some(p), ..Variation::EXACT };
            found[i].iter().all(|&(f, m)| close(m, expected_model_with(spec, i, f, v, 0), POSE_TOL))
        });
    let diagnosis = match other_period {
        Some(p) => {
            let (got, want) = (seconds(p as f64 / 60.0), seconds(own_period as f64 / 60.0));
            Diagnosis::new(
                Text::new(
                    format!(
                        "周期が {got} 秒になっています（指定は {want} 秒。ほかの物体の周期と取り違えていないか）"
                    ),
                    format!(
                        "it moves with a period of {got} s instead of {want} s (another object's period?)"
                    ),
                ),
                t(
                    "この物体の周期 T を使って θ = 360°·t/T などを計算してください",
                    "compute θ = 360°·t/T and the like with this object's own period T",
                ),
            )
        }
        None => diagnose(found_now, expected, &gl, draw, &object.motion, parent, &eval),
    };
    let others: Vec<Text> =
        wrong.iter().filter(|&&j| j != i).map(|&j| object_label(spec, j)).collect();
    Err(pose_failure(
        &model_product(spec, i, frame),
        expected,
        found_now,
        draw,
        location,
        diagnosis,
        &others,
    ))
}

fn independent(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    each_frame(spec, imp, POSE_FRAMES, |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t2"));
        }
        for (i, object) in spec.objects.iter().enumerate() {
            if object.motion.parent().is_some() {
                continue; // a child depends on its parent: a3.t2.hierarchy
            }
            let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
            let draw = the_draw(gl, object, &location)?;
            let expected = expected_model_with(spec, i, frame, Variation::EXACT, 0);
            let found = model_of(draw);
            if close(found, expected, POSE_TOL) {
                continue;
            }
            if let Some(earlier) = leaked_from(found, expected, gl, draw, None) {
                let d = leak_diagnosis(&earlier);
                let mv = draw.model_view.numeric();
                return Err(Failure::new(
                    Text::new(
                        format!(
                            "{} は前に描いた物体の変換の影響を受けない",
                            object_label(spec, i).ja
                        ),
                        format!("{} independent of the objects drawn before it", object.name),
                    ),
                    Text::new(
                        format!("{mv}: \"{earlier}\" の変換が残っている"),
                        format!("{mv}: starts with \"{earlier}\"'s transforms"),
                    ),
                )
                .at(location)
                .cause(d.cause)
                .hint(d.hint));
            }
        }
        Ok(())
    })
}

/// One recorded frame of a parent and its child: (frame, parent's model, child's model, the
/// child's product as drawn).
type PairFrame = (u64, DMat4, DMat4, String);

/// A guess at how the child's model matrix was built, from the frame and the parent's model
/// matrix, with the cause and hint it stands for.
type ChildHypothesis<'a> = (&'a dyn Fn(u64, DMat4) -> DMat4, Text, Text);

fn hierarchy(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let pairs: Vec<(usize, usize)> = (0..spec.objects.len())
        .filter_map(|c| spec.objects[c].motion.parent().map(|p| (p, c)))
        .filter(|&(p, c)| p < spec.objects.len() && p != c)
        .collect();
    let mut recorded: Vec<Vec<PairFrame>> = vec![Vec::new(); pairs.len()];
    each_frame(spec, imp, POSE_FRAMES, |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t2"));
        }
        for (k, &(p, c)) in pairs.iter().enumerate() {
            let location = child_location(spec, c, p, frame);
            let pd = the_draw(gl, &spec.objects[p], &location)?;
            let cd = the_draw(gl, &spec.objects[c], &location)?;
            recorded[k].push((frame, model_of(pd), model_of(cd), cd.model_view.numeric()));
        }
        Ok(())
    })?;
    for (k, &(p, c)) in pairs.iter().enumerate() {
        let child = &spec.objects[c];
        let rel_of = |mp: DMat4, mc: DMat4| {
            if mp.determinant().abs() > 1e-9 { mp.inverse() * mc } else { DMat4::NAN }
        };
        // The child's own motion at a (possibly fractional) frame.
        let own_at = |frame: f64, v: Variation| {
            let p = child.motion.period_frames() as f64;
            crate::oracle::local(&child.motion, frame.rem_euclid(p) / p, v)
        };
        let own = |frame: u64, v: Variation| own_at(frame as f64, v);
        let Some((frame, mp, mc, product)) = recorded[k]
            .iter()
            .find(|(f, mp, mc, _)| !close(rel_of(*mp, *mc), own(*f, Variation::EXACT), POSE_TOL))
            .cloned()
        else {
            continue;
        };
        // A hypothesis about the child's model matrix, tried at every recorded frame.
        let fits = |h: &dyn Fn(u64, DMat4) -> DMat4| {
            recorded[k].iter().all(|(f, mp, mc, _)| close(*mc, h(*f, *mp), POSE_TOL))
        };
        let hypotheses: [ChildHypothesis<'_>; 8] = [
            (
                &|f, mp| mp * own_at(2.0 * f as f64, Variation::EXACT),
                t("時間が 2 倍の速さで進んでいます", "time runs twice as fast"),
                t(
                    "1 フレームは 1/60 秒です（t = state.frame/60）",
                    "one frame is 1/60 s (t = frame/60)",
                ),
            ),
            (
                &|f, mp| mp * own_at(f as f64 / 2.0, Variation::EXACT),
                t(
                    "時間が半分の速さで進んでいます（30 fps として計算？）",
                    "time runs at half speed (computed for 30 fps?)",
                ),
                t(
                    "1 フレームは 1/60 秒です（t = state.frame/60）",
                    "one frame is 1/60 s (t = frame/60)",
                ),
            ),
            (
                &|f, mp| mp * own_at(f as f64 - 1.0, Variation::EXACT),
                t("子が 1 フレーム遅れています", "the child is one frame late"),
                t(
                    "idle() では先に state.frame に 1 を足し、その新しい state.frame から変数を求めてください",
                    "in idle(), add 1 to state.frame first, then compute the parameters from the new frame",
                ),
            ),
            (
                &|f, mp| mp * own(f, Variation::REVERSED),
                t(
                    "子の回転と平行移動の順番が逆です（T·R）: 子は親のまわりを回らず、離れた所でその場で回ります",
                    "the child's rotation and translation are reversed (T·R): it spins in place away from the parent instead of going round it",
                ),
                t(
                    "親の変換の後に Ry(θ) → T(0, 0, r) の順に呼んでください（回転を先に書くと、平行移動したベクトルが回る）",
                    "after the parent's transforms call Ry(θ), then T(0, 0, r) (the rotation first turns the offset)",
                ),
            ),
            (
                &|f, _| own(f, Variation::EXACT),
                t(
                    "子が親の座標系ではなくワールドの原点のまわりを回っています（親の glPopMatrix の後に描いている？）",
                    "the child goes round the world's origin, not its parent (drawn after the parent's glPopMatrix?)",
                ),
                t(
                    "子は親の変換の後、親の glPopMatrix の前に、glPushMatrix / glPopMatrix を入れ子にして描いてください",
                    "draw the child after the parent's transforms and before the parent's glPopMatrix, inside its own nested glPushMatrix / glPopMatrix",
                ),
            ),
            (
                &|f, mp| DMat4::from_translation(origin(mp)) * own(f, Variation::EXACT),
                t(
                    "子が親の位置には付いていきますが、親の回転には付いていきません",
                    "the child follows the parent's position but not its rotation",
                ),
                t(
                    "親の変換（回転を含む）をすべてかけた後に子の変換をかけてください",
                    "apply all of the parent's transforms, its rotation included, before the child's",
                ),
            ),
            (
                &|f, mp| mp * own(f, Variation::RADIANS),
                t(
                    "子の角度をラジアンで渡しています（glRotatef は度）",
                    "the child's angle is in radians (glRotatef takes degrees)",
                ),
                t("角度は度で: θ = 360°·t/T", "use degrees: θ = 360°·t/T"),
            ),
            (
                &|f, mp| mp * own(f, Variation::MIRRORED),
                t("子の回る向きが逆です", "the child turns the wrong way"),
                t("角度の符号を確認してください", "check the angle's sign"),
            ),
        ];
        let (cause, hint) = hypotheses
            .into_iter()
            .find(|(h, _, _)| fits(*h))
            .map(|(_, c, h)| (c, h))
            .unwrap_or_else(|| {
                (
                    t(
                        "親から見た子の位置・向きが指定と違います（半径、周期、回転軸、t = 0 の位置を確認）",
                        "the child's pose relative to its parent is not the specified one (check the radius, period, axis and start)",
                    ),
                    t(
                        "親の変換の後に、子の Ry(θ)·T(0, 0, r) を続けてください",
                        "follow the parent's transforms with the child's Ry(θ)·T(0, 0, r)",
                    ),
                )
            });
        let (rel, rel_expected) = (rel_of(mp, mc), own(frame, Variation::EXACT));
        let (rot, pos) = pose_error(rel, rel_expected);
        let radius = match child.motion {
            Motion::Satellite { radius, .. } => radius,
            _ => 0.0,
        };
        let (radius, o_expected) = (format_number(radius), v3(origin(rel_expected)));
        let (o_found, rot, pos) = (v3(origin(rel)), rot.to_degrees(), format_number(pos as f32));
        return Err(Failure::new(
            Text::new(
                format!(
                    "M_parent⁻¹ · M_child = Ry(θ)·T(0, 0, {radius}) → {}の座標系で原点 {o_expected}",
                    object_label(spec, p).ja
                ),
                format!(
                    "M_parent⁻¹ · M_child = Ry(θ)·T(0, 0, {radius}) → origin {o_expected} in {}'s coordinates",
                    spec.objects[p].name
                ),
            ),
            Text::new(
                format!(
                    "原点 {o_found}（回転のずれ {rot:.3}°、位置のずれ {pos}）; 子の変換 {product}"
                ),
                format!(
                    "origin {o_found} (off by {rot:.3}° and {pos} units); child drawn with {product}"
                ),
            ),
        )
        .at(child_location(spec, c, p, frame))
        .cause(cause)
        .hint(hint));
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// a3.t1: idle (periods, ratios, drift)
// ---------------------------------------------------------------------------------------------

/// Each object's measured period in frames: the smallest `L ≤ 2·P_max` with
/// `pose(n + L) = pose(n)` at every reference frame `n` (a child's pose taken relative to its
/// parent). `Err` when an object is not drawn.
fn measure_periods(spec: &Spec, imp: &Impl) -> Result<Vec<Option<u64>>, Failure> {
    let periods: Vec<u64> = spec.objects.iter().map(|o| o.motion.period_frames()).collect();
    let longest = periods.iter().copied().max().unwrap_or(1);
    let last = REPEAT_REFS[REPEAT_REFS.len() - 1] + 2 * longest;
    // signals[i][frame]
    let mut signals: Vec<Vec<Option<DMat4>>> =
        vec![vec![None; last as usize + 1]; spec.objects.len()];
    each_frame(spec, imp, 1..=last, |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t1 / a3.t2"));
        }
        for (i, object) in spec.objects.iter().enumerate() {
            let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
            let draw = the_draw(gl, object, &location)?;
            let mut m = model_of(draw);
            if let Some(p) = object.motion.parent()
                && let Some(po) = spec.objects.get(p)
            {
                let pm = model_of(the_draw(gl, po, &location)?);
                m = if pm.determinant().abs() > 1e-9 { pm.inverse() * m } else { DMat4::NAN };
            }
            signals[i][frame as usize] = Some(m);
        }
        Ok(())
    })?;
    Ok(signals
        .iter()
        .map(|signal| {
            (1..=2 * longest).find(|&l| {
                REPEAT_REFS.iter().all(|&n| match (signal[n as usize], signal[(n + l) as usize]) {
                    (Some(a), Some(b)) => close(a, b, POSE_TOL),
                    _ => false,
                })
            })
        })
        .collect())
}

fn frames_text(frames: u64) -> Text {
    let s = seconds(frames as f64 / f64::from(FPS));
    Text::new(format!("{frames} フレーム（{s} 秒）"), format!("{frames} frames ({s} s)"))
}

/// `物体2 の子の物体3、t = …` / `object 3 in object 2, t = …`: child `c` of parent `p`.
fn child_location(spec: &Spec, c: usize, p: usize, frame: u64) -> Text {
    let (c, p, at) = (object_label(spec, c), object_label(spec, p), at_frame(frame));
    Text::new(
        format!("{} の子の{}、{}", p.ja, c.ja, at.ja),
        format!("{} in {}, {}", c.en, p.en, at.en),
    )
}

fn periods(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let measured = measure_periods(spec, imp)?;
    let longest = spec.objects.iter().map(|o| o.motion.period_frames()).max().unwrap_or(1);
    for (i, (object, found)) in spec.objects.iter().zip(&measured).enumerate() {
        let expected = object.motion.period_frames();
        if *found == Some(expected) {
            continue;
        }
        let relative = if object.motion.parent().is_some() {
            ["（親に対して）", " (relative to its parent)"]
        } else {
            ["", ""]
        };
        let (actual, cause, hint) = match *found {
            Some(1) => (
                t(
                    "動いていない（1 フレームあたり 0.06° または 0.001 未満）",
                    "does not move (less than 0.06° or 0.001 per frame)",
                ),
                t(
                    "物体が動いていません、またはごくわずかしか動きません（idle() で変数を更新していない、角度をラジアンで渡している、など）",
                    "the object does not move, or hardly (idle() does not update its parameters, an angle in radians, …)",
                ),
                t(
                    "idle() で state.frame に 1 を足し、変数を state.frame から求めてください",
                    "in idle(), add 1 to state.frame and compute the parameters from it",
                ),
            ),
            Some(l) => (
                Text::new(
                    format!("{}ごとに繰り返す", frames_text(l).ja),
                    format!("repeats every {}", frames_text(l).en),
                ),
                Text::new(
                    format!(
                        "周期が {} 秒になっています（指定は {} 秒）",
                        seconds(l as f64 / 60.0),
                        seconds(expected as f64 / 60.0)
                    ),
                    format!(
                        "the period is {} s instead of {} s",
                        seconds(l as f64 / 60.0),
                        seconds(expected as f64 / 60.0)
                    ),
                ),
                t(
                    "この物体の周期 T を使っているか（ほかの物体の T と取り違えていないか）、1 フレーム = 1/60 秒か確認してください",
                    "check that this object's own T is used (not another object's) and that one frame is 1/60 s",
                ),
            ),
            None => (
                Text::new(
                    format!("{}以内に繰り返さない", frames_text(2 * longest).ja),
                    format!("does not repeat within {}", frames_text(2 * longest).en),
                ),
                t(
                    "周期的に繰り返していません（角度をラジアンで渡している、周期の式が違う、ほかの物体の変換が残っている、など）",
                    "the motion does not repeat (an angle in radians, a wrong period formula, another object's transforms still applied, …)",
                ),
                t(
                    "θ = 360°·(state.frame mod P)/P（P = 60·T フレーム）のように、周期で割った余りから作ってください",
                    "build it from the remainder by the period: θ = 360°·(frame mod P)/P with P = 60·T frames",
                ),
            ),
        };
        let cause = if object.motion.parent().is_some() {
            Text::new(
                format!(
                    "{}（子の周期は親に対する動きの周期です。a3.t2.hierarchy も参照）",
                    cause.ja
                ),
                format!(
                    "{} (a child's period is that of its motion relative to its parent; see a3.t2.hierarchy too)",
                    cause.en
                ),
            )
        } else {
            cause
        };
        return Err(Failure::new(
            Text::new(
                format!("{}ごとに繰り返す{}", frames_text(expected).ja, relative[0]),
                format!("repeats every {}{}", frames_text(expected).en, relative[1]),
            ),
            actual,
        )
        .at(object_label(spec, i))
        .cause(cause)
        .hint(hint));
    }
    Ok(())
}

fn ratios(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let measured = measure_periods(spec, imp)?;
    let expected = spec.period_ratios();
    let names: Vec<Text> = (0..spec.objects.len()).map(|i| object_label(spec, i)).collect();
    let join = |v: &[u64]| v.iter().map(u64::to_string).collect::<Vec<_>>().join(" : ");
    let all = joined(&names, " : ");
    let expected_text = Text::new(
        format!("{} = {}", all.ja, join(&expected)),
        format!("{} = {}", all.en, join(&expected)),
    );
    if let Some(i) = measured.iter().position(|m| m.is_none_or(|l| l <= 1)) {
        return Err(Failure::new(
            expected_text,
            Text::new(
                format!("{}: 周期が測れない", names[i].ja),
                format!("{}: no period measured", names[i].en),
            ),
        )
        .at(object_label(spec, i))
        .cause(t(
            "この物体の動きが周期的でない（または動かない）ので、周期の比が測れません",
            "this object's motion does not repeat (or does not move), so no ratio can be measured",
        ))
        .hint(t("先に a3.t1.periods を直してください", "fix a3.t1.periods first")));
    }
    let found: Vec<u64> = measured.iter().map(|m| m.unwrap_or(1)).collect();
    let g = found.iter().copied().fold(0, crate::gcd).max(1);
    let found_ratio: Vec<u64> = found.iter().map(|f| f / g).collect();
    if found_ratio == expected {
        return Ok(());
    }
    let periods = joined(&found.iter().map(|&f| frames_text(f)).collect::<Vec<_>>(), ", ");
    Err(Failure::new(
        expected_text,
        Text::new(
            format!("{} = {}（周期 {}）", all.ja, join(&found_ratio), periods.ja),
            format!("{} = {} (periods {})", all.en, join(&found_ratio), periods.en),
        ),
    )
    .at(joined(&names, ", "))
    .cause(t(
        "物体同士の周期の比が指定と違います（「動きの周期（物体同士の回転周期）が異なる」はよくある間違い）",
        "the ratio of the objects' periods is not the specified one (a common mistake in this assignment)",
    ))
    .hint(t(
        "各物体の周期 T を指定の通りにし、同じ時刻 t から全部の変数を求めてください",
        "give each object its own specified period T and compute every variable from the same time t",
    )))
}

/// The drift check: `idle` run 10⁶ times, then every object's pose against the exact pose at
/// t = 10⁶/60 s. When it is off, the same comparison at the frame with the same phase early on
/// (10⁶ mod the common period) tells drift (right then, wrong now) from a motion that is wrong
/// from the start.
fn drift(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let common = spec.objects.iter().map(|o| o.motion.period_frames()).fold(1, crate::lcm).max(1);
    let early = match DRIFT_FRAMES % common {
        0 => common,
        r => r,
    };
    let mut wrong_early: Vec<usize> = Vec::new();
    each_frame(spec, imp, [early, DRIFT_FRAMES], |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t2"));
        }
        let mut worst: Option<(usize, f64, f64, f64)> = None;
        for (i, object) in spec.objects.iter().enumerate() {
            let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
            let draw = the_draw(gl, object, &location)?;
            let found = model_of(draw);
            let expected = expected_model_with(spec, i, frame, Variation::EXACT, 0);
            let (rot, pos) = pose_error(found, expected);
            if frame == early {
                if !close(found, expected, POSE_TOL) {
                    wrong_early.push(i);
                }
                continue;
            }
            let det = (DMat3::from_mat4(found).determinant() - 1.0).abs();
            let det = if det.is_finite() { det } else { f64::INFINITY };
            let score = rot.max(pos).max(det);
            if score > DRIFT_TOL && worst.is_none_or(|w| score > w.1.max(w.2).max(w.3)) {
                worst = Some((i, rot, pos, det));
            }
        }
        let Some((i, rot, pos, det)) = worst else { return Ok(()) };
        let e = |x: f64| if x.is_finite() { format!("{x:.1e}") } else { "∞".to_owned() };
        let (cause, hint) = if wrong_early.contains(&i) {
            (
                Text::new(
                    format!(
                        "ずれではなく、最初から動きが違います（同じ位相の {} でもすでに違う）",
                        at_frame(early).ja
                    ),
                    format!(
                        "this is not drift: the motion is wrong from the start (already wrong at {}, the same phase)",
                        at_frame(early).en
                    ),
                ),
                t("先に a3.t2.poses を直してください", "fix a3.t2.poses first"),
            )
        } else {
            (
                Text::new(
                    format!(
                        "{} では正しいのに 10⁶ フレーム後にずれています: 角度や位置を毎フレーム f32 で足し続けているため、丸め誤差がたまっています（または周期で割った余りを使っていない）",
                        at_frame(early).ja
                    ),
                    format!(
                        "right at {} (the same phase) but off after 10⁶ frames: the angle or position is accumulated in f32 every frame, so rounding errors pile up (or it is not reduced by the period)",
                        at_frame(early).en
                    ),
                ),
                t(
                    "毎フレーム state.frame（整数）から作り直してください: P = 60·T として θ = 360·(state.frame % P) as f64 / P as f64",
                    "rebuild it every frame from state.frame (an integer): with P = 60·T, θ = 360·(state.frame % P) as f64 / P as f64",
                ),
            )
        };
        let product = camera_product().concat(&model_product(spec, i, frame)).numeric();
        let (rot_e, deg, pos, det) = (e(rot), rot.to_degrees(), e(pos), e(det));
        Err(Failure::new(
            Text::new(
                format!(
                    "{DRIFT_FRAMES} フレーム後: 回転と位置のずれ < {DRIFT_TOL:.0e}、|det(R) − 1| < {DRIFT_TOL:.0e}; 期待する変換 {product}"
                ),
                format!(
                    "after {DRIFT_FRAMES} frames: pose error < {DRIFT_TOL:.0e} rad and units, |det(R) − 1| < {DRIFT_TOL:.0e}; expected {product}"
                ),
            ),
            Text::new(
                format!("回転のずれ {rot_e} rad（{deg:.4}°）、原点のずれ {pos}、|det(R) − 1| = {det}"),
                format!("rotation {rot_e} rad ({deg:.4}°), origin {pos} units, |det(R) − 1| = {det}"),
            ),
        )
        .at(pair(&object_label(spec, i), "、", ", ", &at_frame(frame)))
        .cause(cause)
        .hint(hint))
    })
}
