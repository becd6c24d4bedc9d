//! `a3.t1`, `idle`: each object's period measured from its poses, the ratios of the periods, and
//! no drift after [`DRIFT_FRAMES`] frames.

use cg_core::glam::{DMat3, DMat4};
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use super::{
    POSE_TOL, at_frame, close, each_frame, joined, nothing_drawn, object_label, pair, the_draw,
};
use crate::oracle::{Variation, expected_model_with};
use crate::pose::{model_of, pose_error, seconds};
use crate::{DRIFT_FRAMES, FPS, Impl, Spec, SpecExt, camera_product, model_product};

/// Drift tolerance after 10⁶ frames (NUMERICS.md row 11).
const DRIFT_TOL: f64 = 1e-5;
/// The reference frames a repetition must hold at: pose(n + L) = pose(n) for each.
const REPEAT_REFS: [u64; 4] = [1, 5, 12, 30];

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

pub(super) fn periods(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

pub(super) fn ratios(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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
pub(super) fn drift(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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
