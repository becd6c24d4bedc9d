//! The checks of `a3`: each runs the student's `idle` / `display` / `warmup_display` inside
//! [`check::run`], reads what the recording context [`Gl`] saw (every draw's model-view matrix,
//! the light, stack errors) and compares each object's pose with the f64 oracle of
//! [`crate::oracle`] — except `a3.t1.periods` and `ratios`, which measure how often the student's
//! motion repeats, and `a3.t1.drift`, which compares the student's pose at frame 10⁶ with the
//! student's own pose at the same phase early on.
//!
//! A pose is the model matrix `M = V⁻¹ · (model-view at the draw)` with the common camera
//! `V = T(0, 0, -15) · Rx(30°)` taken off in f64. Two poses agree when their rotation parts
//! differ by at most `tol` (‖R₁ − R₂‖_F / √2, about the angle between them in radians) and their
//! origins by at most `tol` scene units.
//!
//! | check | tolerance | why |
//! |---|---|---|
//! | poses, warm-up, periods | 1e-3 | far above f32 rounding (≈ 1e-6 here), far below one frame of the slowest motion (≥ 5e-3) |
//! | drift after 10⁶ frames | 1e-5 | docs/numerics.md row 11; the student's own poses at frame 10⁶ and at the same phase early on, which agree exactly for an angle rebuilt from the frame count |

use cg_core::gl::{Draw, Gl};
use cg_core::glam::{DMat4, DVec3};
use cg_core::lang::Lang;
use cg_core::product::{MatrixProduct, format_number};
use cg_harness::check::{self, CheckResult, Failure};
use cg_harness::text::{Text, t};

use crate::oracle::Variation;
use crate::pose::{draws_named, model_of, name_matches, pose_error, seconds, view};
use crate::{FPS, Impl, Motion, Object, Spec, State, camera_product};

mod t0_warmup;
mod t1;
mod t2;

/// Pose tolerance (radians for the rotation part, scene units for the origin).
const POSE_TOL: f64 = 1e-3;

/// Every check of this assignment for `spec`, run against `imp`.
#[must_use]
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    vec![
        check::run("a3.t0.box1", t("box 1 の回転運動", "box 1's rotation"), || {
            t0_warmup::warmup_box(imp, 0)
        }),
        check::run(
            "a3.t0.box2",
            t("box 2 の往復回転運動", "box 2's back-and-forth rotation"),
            || t0_warmup::warmup_box(imp, 1),
        ),
        check::run(
            "a3.t0.box3",
            t("box 3 の放物往復移動運動", "box 3's parabolic back-and-forth motion"),
            || t0_warmup::warmup_box(imp, 2),
        ),
        check::run(
            "a3.t0.stack",
            t("演習課題の glPushMatrix / glPopMatrix の対応", "the warm-up's push/pop balance"),
            || t0_warmup::warmup_stack(imp),
        ),
        check::run("a3.t1.periods", t("各物体の周期", "each object's period"), || {
            t1::periods(spec, imp)
        }),
        check::run(
            "a3.t1.ratios",
            t("物体同士の周期の比", "the ratio of the periods"),
            || t1::ratios(spec, imp),
        ),
        check::run(
            "a3.t1.drift",
            t("10⁶ フレーム後のずれ", "no drift after 10⁶ frames"),
            || t1::drift(spec, imp),
        ),
        check::run(
            "a3.t2.objects",
            t("すべての物体を 1 回ずつ描く", "every object drawn once"),
            || t2::objects(spec, imp),
        ),
        check::run(
            "a3.t2.light",
            t("光源を視点の変換の直後に設定", "the light set right after the view transform"),
            || t2::light(spec, imp),
        ),
        check::run(
            "a3.t2.stack",
            t("glPushMatrix / glPopMatrix の対応", "push/pop balanced, no GL errors"),
            || t2::stack(spec, imp),
        ),
        check::run(
            "a3.t2.poses",
            t("各時刻の各物体の位置と向き", "each object's pose over time"),
            || t2::poses(spec, imp),
        ),
        check::run(
            "a3.t2.independent",
            t("独立した物体の変換が他に影響しない", "independent objects stay independent"),
            || t2::independent(spec, imp),
        ),
        check::run(
            "a3.t2.hierarchy",
            t("子が親の座標系で動く（階層）", "the child moves in its parent's coordinates"),
            || t2::hierarchy(spec, imp),
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
    // The student's functions in a worker: every frame in one call, the same calls in the same
    // order (the worker's `a3.frames`), not one round trip per frame.
    if cg_worker::proxy::active() {
        let frames: Vec<u64> = frames.into_iter().collect();
        for (&frame, (_, rec)) in frames.iter().zip(cg_worker::proxy::a3_frames(spec, &frames)) {
            visit(frame, &crate::replay(&rec))?;
        }
        return Ok(());
    }
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
/// the camera missing or twice, radians for degrees (in glRotatef) or degrees for radians (in
/// a swing's sine), the wrong way round, the order reversed, a frame late,
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
                "視点の変換 T(0, 0, -15)·Rx(30°) がかかっていません",
                "the view transform T(0, 0, -15)·Rx(30°) is missing",
            ),
            t(
                "display() の最初に glLoadIdentity、視点の変換を置き、その後に物体を描いてください",
                "start display() with glLoadIdentity and the view transform, then draw the objects",
            ),
        );
    }
    if close(found, v * expected, POSE_TOL) {
        return Diagnosis::new(
            t("視点の変換が 2 回かかっています", "the view transform is applied twice"),
            t(
                "視点の変換は 1 回だけ（glLoadIdentity の直後に）",
                "apply the camera once, right after glLoadIdentity",
            ),
        );
    }
    if let Some(earlier) = leaked_from(found, expected, gl, draw, parent) {
        return leak_diagnosis(&earlier);
    }
    let (sine, radians) = (sine_of_degrees(), radians_for_degrees());
    let checks: [(Variation, Shift, Text, Text); 9] = [
        (Variation::SINE_OF_DEGREES_OF_TIME, Shift::Exact, sine.cause.clone(), sine.hint.clone()),
        (Variation::SINE_OF_DEGREES, Shift::Exact, sine.cause, sine.hint),
        (Variation::RADIANS, Shift::Exact, radians.cause, radians.hint),
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

/// Radians handed to glRotatef, which takes degrees ([`Variation::RADIANS`]).
fn radians_for_degrees() -> Diagnosis {
    Diagnosis::new(
        t(
            "角度をラジアンで渡しています（glRotatef は度）",
            "the angle is in radians (glRotatef takes degrees)",
        ),
        t(
            "角度は度で: θ = 360°·t/T。sin には度をラジアンに直して渡します",
            "use degrees: θ = 360°·t/T; convert to radians only for sin",
        ),
    )
}

/// Degrees handed to `sin` as radians (`(360.0 * t / T).sin()`): a swing's angle then follows
/// `A·sin(360·t/T)` read in radians ([`Variation::SINES_OF_DEGREES`]).
fn sine_of_degrees() -> Diagnosis {
    Diagnosis::new(
        t(
            "sin・cos に度のまま渡しています（ラジアンに直す: .to_radians()）",
            "degrees went into sin/cos as radians: convert with .to_radians()",
        ),
        t(
            "θ = A·sin(360°·t/T) の 360°·t/T は度ですが、f64 の sin はラジアンを受け取ります: (360.0 * t / T).to_radians().sin()（または (TAU * t / T).sin()）と書いてください",
            "the 360°·t/T in θ = A·sin(360°·t/T) is in degrees, and f64's sin takes radians: write (360.0 * t / T).to_radians().sin() (or (TAU * t / T).sin())",
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
    gl.draws()
        .iter()
        .filter(|d| d.call < draw.call && parent.is_none_or(|p| !name_matches(&d.name, p)))
        .rev()
        .find(|d| {
            let m = model_of(d);
            let numeric = !is_identity(m) && close(found, m * expected, POSE_TOL);
            numeric || carries_factors_of(draw, d)
        })
        .map(|d| d.name.clone())
}

/// Whether `draw`'s product starts with all of `earlier`'s (the camera's and more, not the
/// identity): `earlier`'s transforms were never popped before `draw`.
fn carries_factors_of(draw: &Draw, earlier: &Draw) -> bool {
    let (mine, theirs) = (&draw.model_view.factors, &earlier.model_view.factors);
    !is_identity(model_of(earlier))
        && theirs.len() > camera_factors(draw)
        && theirs.len() < mine.len()
        && mine.starts_with(theirs)
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

/// The failure for a wrong pose: the expected and found products (the camera's factors first,
/// as `display()` multiplies them) and the object's origin in the world (the model matrix's, the
/// camera taken off, as the poses are compared).
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
            format!("{product} → 物体の原点はワールド座標系で {o_expected}（カメラの因子を除いて）"),
            format!(
                "{product} → the object's origin at {o_expected} in the world (the camera's factors taken off)"
            ),
        ),
        Text::new(
            format!(
                "{mv} → 物体の原点はワールド座標系で {o_found}（回転のずれ {rot:.3}°、位置のずれ {pos}{also_ja}）"
            ),
            format!(
                "{mv} → the object's origin at {o_found} in the world (off by {rot:.3}° and {pos} units{also_en})"
            ),
        ),
    )
    .at(location)
    .cause(diagnosis.cause)
    .hint(diagnosis.hint)
}

// ---------------------------------------------------------------------------------------------
// The matrix stack (a3.t0 and a3.t2)
// ---------------------------------------------------------------------------------------------

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
