//! `a3.t1`, `idle`: each object's period measured from its poses, the ratios of the periods, and
//! no drift after [`DRIFT_FRAMES`] frames (the student's own pose then against the student's own
//! pose at the same phase early on).

use cg_core::gl::Gl;
use cg_core::glam::{DMat3, DMat4};
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use super::{
    Diagnosis, POSE_TOL, at_frame, carries_factors_of, close, each_frame, joined, leaked_from,
    nothing_drawn, object_label, pair, radians_for_degrees, sine_of_degrees, the_draw,
};
use crate::oracle::{Variation, expected_model_with, local_at, phase_at};
use crate::pose::{draws_named, model_of, pose_error, seconds};
use crate::{DRIFT_FRAMES, FPS, Impl, Spec, SpecExt};

/// Drift tolerance after 10⁶ frames (docs/numerics.md row 11): how far the pose at frame 10⁶ may be
/// from the student's own pose one whole number of common periods earlier. A motion rebuilt
/// from the frame count gives the same f32 matrices at both (a difference of 0); an f32 angle
/// accumulated every frame is off by degrees (the tests' one: 6e-2 rad).
const DRIFT_TOL: f64 = 1e-5;
/// The reference frames a repetition must hold at: pose(n + L) = pose(n) for each.
const REPEAT_REFS: [u64; 4] = [1, 5, 12, 30];

/// Object `i`'s pose in the frame `gl` drew: its model matrix, a child's taken relative to its
/// parent (`M_parent⁻¹ · M_child`, NaN when the parent's is singular), so that each object's own
/// motion is measured apart from its parent's.
fn own_pose(spec: &Spec, gl: &Gl, i: usize, frame: u64) -> Result<DMat4, Failure> {
    let object = &spec.objects[i];
    let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
    let m = model_of(the_draw(gl, object, &location)?);
    match object.motion.parent().and_then(|p| spec.objects.get(p)) {
        Some(po) => {
            let pm = model_of(the_draw(gl, po, &location)?);
            Ok(if pm.determinant().abs() > 1e-9 { pm.inverse() * m } else { DMat4::NAN })
        }
        None => Ok(m),
    }
}

/// Object `i`'s pose relative to object `j`'s draw (`M_j⁻¹ · M_i`, NaN when `M_j` is
/// singular) when `i`'s product carries all of `j`'s (`j` is not its parent), else `None`. When
/// `display()` leaves an object's transforms applied to a later one (a missing glPushMatrix /
/// glPopMatrix, `a3.t2`'s fault: the one just before, or a parent whose glPopMatrix popped its
/// child's glPushMatrix instead), the later object's model matrix is `M_j · M_i`, and this takes
/// the leak off, so `idle()`'s own motion is still measured. Only a leak seen in the products
/// counts: relative to any earlier object, a motion with a wrong period can seem to have the
/// right one (a child twice as fast, relative to an object with its parent's period).
fn pose_after(spec: &Spec, gl: &Gl, i: usize, j: usize) -> Option<DMat4> {
    if spec.objects[i].motion.parent() == Some(j) {
        return None;
    }
    let (found, earlier) =
        (draws_named(gl, &spec.objects[i].name), draws_named(gl, &spec.objects[j].name));
    let ([draw], [before]) = (found.as_slice(), earlier.as_slice()) else { return None };
    if !carries_factors_of(draw, before) {
        return None;
    }
    let pm = model_of(before);
    Some(if pm.determinant().abs() > 1e-9 { pm.inverse() * model_of(draw) } else { DMat4::NAN })
}

/// Whether object `i` is drawn in this frame with the transforms of an object drawn before it
/// still applied (not its parent's), as `a3.t2.independent` reports it: a missing glPushMatrix /
/// glPopMatrix in `display()`, which `a3.t2.stack` usually reports too.
fn carries_a_leak(spec: &Spec, gl: &Gl, i: usize, frame: u64) -> bool {
    let object = &spec.objects[i];
    let found = draws_named(gl, &object.name);
    let [draw] = found.as_slice() else { return false };
    let parent = object.motion.parent().and_then(|p| spec.objects.get(p)).map(|p| p.name.as_str());
    let (m, expected) = (model_of(draw), expected_model_with(spec, i, frame, Variation::EXACT, 0));
    !close(m, expected, POSE_TOL) && leaked_from(m, expected, gl, draw, parent).is_some()
}

/// Whether object `i`'s own poses (`own[frame]`, [`own_pose`]) are its motion evaluated with
/// `v` at every frame measured, where that is not the specified motion: degrees handed to
/// `sin` ([`Variation::SINES_OF_DEGREES`]), radians to glRotatef ([`Variation::RADIANS`]).
fn explained_at_every_frame(spec: &Spec, i: usize, own: &[Option<DMat4>], v: Variation) -> bool {
    let motion = &spec.objects[i].motion;
    let p = motion.period_frames().max(1);
    let frames: Vec<(u64, DMat4)> =
        own.iter().enumerate().filter_map(|(f, m)| m.map(|m| (f as u64, m))).collect();
    let at = |f: u64, v: Variation| local_at(motion, phase_at(f, p), f as f64 / p as f64, v);
    frames.iter().any(|&(f, _)| !close(at(f, v), at(f, Variation::EXACT), POSE_TOL))
        && frames.iter().all(|&(f, m)| close(m, at(f, v), POSE_TOL))
}

/// What the periods' measurement found besides the periods: each object's own pose at each
/// frame measured, and whether `display()` leaks transforms into it ([`carries_a_leak`]).
struct Measured {
    /// Each object's period in frames ([`measure_periods`]).
    periods: Vec<Option<u64>>,
    /// `own[i][frame]`: object `i`'s own pose ([`own_pose`]).
    own: Vec<Vec<Option<DMat4>>>,
    /// `leaked[i]`: whether object `i` carries an earlier object's transforms in some frame
    /// ([`carries_a_leak`]).
    leaked: Vec<bool>,
}

impl Measured {
    /// The likely cause of a wrong period of object `i` that is not `idle()`'s period: degrees
    /// handed to `sin`, radians to glRotatef, or `display()`'s leak into it.
    fn cause_of(&self, spec: &Spec, i: usize) -> Option<Diagnosis> {
        let explained = |v: Variation| explained_at_every_frame(spec, i, &self.own[i], v);
        if Variation::SINES_OF_DEGREES.into_iter().any(explained) {
            return Some(sine_of_degrees());
        }
        if explained(Variation::RADIANS) {
            return Some(radians_for_degrees());
        }
        self.leaked[i].then(|| {
            Diagnosis::new(
                t(
                    "display() で glPushMatrix / glPopMatrix が足りず、前に描いた物体の変換が残ったまま描いているためと思われます（a3.t2.stack・a3.t2.independent を参照）。そのせいで、ほかの物体の動きまで重なって周期が変わって見えます。idle() の周期は正しいかもしれません",
                    "most likely a glPushMatrix / glPopMatrix missing in display(): an earlier object's transforms are still applied when this one is drawn (see a3.t2.stack and a3.t2.independent), so its pose carries that object's motion too and seems to repeat with another period; idle()'s period may well be right",
                ),
                t(
                    "先に a3.t2.stack と a3.t2.independent を直してください（各物体を glPushMatrix と glPopMatrix で囲む）。そのあと、このチェックは idle() の動きだけを測ります",
                    "fix a3.t2.stack and a3.t2.independent first (each object between its own glPushMatrix and glPopMatrix); then this check measures idle()'s motion alone",
                ),
            )
        })
    }
}

/// The smallest `L ≤ max` with `pose(n + L) = pose(n)` at every reference frame `n`.
fn period_of(signal: &[Option<DMat4>], max: u64) -> Option<u64> {
    (1..=max).find(|&l| {
        REPEAT_REFS.iter().all(|&n| match (signal[n as usize], signal[(n + l) as usize]) {
            (Some(a), Some(b)) => close(a, b, POSE_TOL),
            _ => false,
        })
    })
}

/// Each object's measured period in frames: the smallest `L ≤ 2·P_max` with
/// `pose(n + L) = pose(n)` at every reference frame `n` (a child's pose taken relative to its
/// parent). Where that is not the specified period but the pose relative to an object drawn
/// before it has exactly the specified one ([`pose_after`]), `display()` leaks transforms from
/// that object to this one: that is `a3.t2`'s to report (`a3.t2.stack`, `a3.t2.independent`),
/// and `idle()`'s motion, measured past the leak, is right, so the specified period is taken.
/// `Err` when an object is not drawn.
fn measure_periods(spec: &Spec, imp: &Impl) -> Result<Measured, Failure> {
    let n = spec.objects.len();
    let periods: Vec<u64> = spec.objects.iter().map(|o| o.motion.period_frames()).collect();
    let longest = periods.iter().copied().max().unwrap_or(1);
    let last = REPEAT_REFS[REPEAT_REFS.len() - 1] + 2 * longest;
    // own[i][frame]: the own pose; after[i][j][frame]: the pose relative to object j's draw
    let empty = vec![None; last as usize + 1];
    let mut own = vec![empty.clone(); n];
    let mut after = vec![vec![empty; n]; n];
    let mut leaked = vec![false; n];
    each_frame(spec, imp, 1..=last, |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t1 / a3.t2"));
        }
        for i in 0..n {
            own[i][frame as usize] = Some(own_pose(spec, gl, i, frame)?);
            for j in (0..n).filter(|&j| j != i) {
                after[i][j][frame as usize] = pose_after(spec, gl, i, j);
            }
            leaked[i] = leaked[i] || carries_a_leak(spec, gl, i, frame);
        }
        Ok(())
    })?;
    let periods = periods
        .iter()
        .enumerate()
        .map(|(i, &expected)| {
            let found = period_of(&own[i], 2 * longest);
            let past_leak = || after[i].iter().any(|a| period_of(a, 2 * longest) == Some(expected));
            if found != Some(expected) && past_leak() { Some(expected) } else { found }
        })
        .collect();
    Ok(Measured { periods, own, leaked })
}

fn frames_text(frames: u64) -> Text {
    let s = seconds(frames as f64 / f64::from(FPS));
    Text::new(format!("{frames} フレーム（{s} 秒）"), format!("{frames} frames ({s} s)"))
}

pub(super) fn periods(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let measured = measure_periods(spec, imp)?;
    let longest = spec.objects.iter().map(|o| o.motion.period_frames()).max().unwrap_or(1);
    for (i, (object, found)) in spec.objects.iter().zip(&measured.periods).enumerate() {
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
        // Degrees or radians mixed up, or display()'s leak, before idle()'s period.
        let (cause, hint, named) = match measured.cause_of(spec, i) {
            Some(d) => (d.cause, d.hint, true),
            None => (cause, hint, false),
        };
        let cause = if object.motion.parent().is_some() && !named {
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
    let m = measure_periods(spec, imp)?;
    let measured = &m.periods;
    let expected = spec.period_ratios();
    // A likely cause that is not the periods in idle(), with the object it is that of: degrees
    // or radians mixed up, or a leak in display().
    let named_cause = |i: usize| {
        m.cause_of(spec, i).map(|d| {
            let label = object_label(spec, i);
            let (ja, en) = (d.cause.ja, d.cause.en);
            (Text::new(format!("{}: {ja}", label.ja), format!("{}: {en}", label.en)), d.hint)
        })
    };
    let names: Vec<Text> = (0..spec.objects.len()).map(|i| object_label(spec, i)).collect();
    let join = |v: &[u64]| v.iter().map(u64::to_string).collect::<Vec<_>>().join(" : ");
    let all = joined(&names, " : ");
    let expected_text = Text::new(
        format!("{} = {}", all.ja, join(&expected)),
        format!("{} = {}", all.en, join(&expected)),
    );
    if let Some(i) = measured.iter().position(|m| m.is_none_or(|l| l <= 1)) {
        let (cause, hint) = named_cause(i).unwrap_or_else(|| {
            (
                t(
                    "この物体の動きが周期的でない（または動かない）ので、周期の比が測れません",
                    "this object's motion does not repeat (or does not move), so no ratio can be measured",
                ),
                t("先に a3.t1.periods を直してください", "fix a3.t1.periods first"),
            )
        });
        return Err(Failure::new(
            expected_text,
            Text::new(
                format!("{}: 周期が測れない", names[i].ja),
                format!("{}: no period measured", names[i].en),
            ),
        )
        .at(object_label(spec, i))
        .cause(cause)
        .hint(hint));
    }
    let found: Vec<u64> = measured.iter().map(|m| m.unwrap_or(1)).collect();
    let g = found.iter().copied().fold(0, crate::gcd).max(1);
    let found_ratio: Vec<u64> = found.iter().map(|f| f / g).collect();
    if found_ratio == expected {
        return Ok(());
    }
    let periods = joined(&found.iter().map(|&f| frames_text(f)).collect::<Vec<_>>(), ", ");
    let own_periods = spec.objects.iter().map(|o| Some(o.motion.period_frames()));
    // The objects off the specified period.
    let off: Vec<usize> = own_periods
        .zip(measured)
        .enumerate()
        .filter(|(_, (want, got))| want != *got)
        .map(|(i, _)| i)
        .collect();
    let (cause, hint) = off
        .iter()
        .find_map(|&i| named_cause(i))
        .unwrap_or_else(|| {
            (
                t(
                    "物体同士の周期の比が指定と違います（「動きの周期（物体同士の回転周期）が異なる」はよくある間違い）",
                    "the ratio of the objects' periods is not the specified one (a common mistake in this assignment)",
                ),
                t(
                    "各物体の周期 T を指定の通りにし、同じ時刻 t から全部の変数を求めてください",
                    "give each object its own specified period T and compute every variable from the same time t",
                ),
            )
        });
    Err(Failure::new(
        expected_text,
        Text::new(
            format!("{} = {}（周期 {}）", all.ja, join(&found_ratio), periods.ja),
            format!("{} = {} (periods {})", all.en, join(&found_ratio), periods.en),
        ),
    )
    .at(joined(&names, ", "))
    .cause(cause)
    .hint(hint))
}

/// The longest common period [`drift`] compares over: the early frame is then at most this far
/// in, and the two frames it compares are at least 9 of these periods apart.
const MAX_COMMON: u64 = DRIFT_FRAMES / 10;

/// The drift check (docs/numerics.md row 11): `idle` run [`DRIFT_FRAMES`] times, and every object's
/// pose at that frame compared with the student's *own* pose at the frame with the same phase
/// early on, `f₀ = 10⁶ mod L` (`L` when that is 0), `L` the least common multiple of the periods
/// [`measure_periods`] measures (those of `a3.t1.periods`; for a right answer, the specified
/// ones). A child's pose is taken relative to its parent, as for the periods, so a drifting
/// parent is named, not its child.
///
/// The check never looks at the expected pose: a motion rebuilt from the frame count each frame
/// repeats exactly, so the two poses agree to the last bit, right or wrong; an angle accumulated
/// in f32 (`θ += 360°/P` every frame) is right early on and degrees off after 10⁶ frames. A pose
/// that is wrong the same way at every frame (the sign, the axis, the order of the transforms,
/// the wrong period) passes here: it fails only the checks that look at the pose or the period.
///
/// When there is no such `L` (an object whose motion does not repeat, or does not move, or
/// periods with no common multiple within [`MAX_COMMON`] frames) drift cannot be measured, and
/// the check fails saying so and naming `a3.t1.periods`. Failing, not passing, because a pass
/// would give credit for a measurement that was never made (an `idle` that does nothing would
/// pass), and the message points to the one check to fix, as `a3.t1.ratios` does; once the
/// motion repeats, this check measures drift alone, whether or not the period is the specified
/// one.
pub(super) fn drift(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let measured = measure_periods(spec, imp)?.periods;
    let common = drift_period(spec, &measured)?;
    let early = match DRIFT_FRAMES % common {
        0 => common,
        r => r,
    };
    let mut before: Vec<DMat4> = Vec::new();
    each_frame(spec, imp, [early, DRIFT_FRAMES], |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t1 / a3.t2"));
        }
        let poses = (0..spec.objects.len())
            .map(|i| own_pose(spec, gl, i, frame))
            .collect::<Result<_, _>>()?;
        if frame == early {
            before = poses;
            return Ok(());
        }
        let det = |m: DMat4| DMat3::from_mat4(m).determinant();
        let mut worst: Option<(usize, f64, f64, f64)> = None;
        for (i, (&then, &now)) in before.iter().zip(&poses).enumerate() {
            let (rot, pos) = pose_error(now, then);
            let d = (det(now) - det(then)).abs();
            let d = if d.is_finite() { d } else { f64::INFINITY };
            let score = rot.max(pos).max(d);
            if score > DRIFT_TOL && worst.is_none_or(|w| score > w.1.max(w.2).max(w.3)) {
                worst = Some((i, rot, pos, d));
            }
        }
        let Some((i, rot, pos, d)) = worst else { return Ok(()) };
        Err(drift_failure(spec, i, early, common, rot, pos, d))
    })
}

/// The common period `L` [`drift`] compares over: the least common multiple of the measured
/// periods, or why there is none.
fn drift_period(spec: &Spec, measured: &[Option<u64>]) -> Result<u64, Failure> {
    let longest = spec.objects.iter().map(|o| o.motion.period_frames()).max().unwrap_or(1);
    let expected = t(
        "周期的に繰り返す動き（10⁶ フレーム後の姿勢を、同じ位相の早いフレームの姿勢と比べるため）",
        "a motion that repeats (the pose after 10⁶ frames is compared with the pose at an early frame of the same phase)",
    );
    let cause = t(
        "動きが繰り返さない（または動かない）ので、同じ位相のフレームがなく、ずれを測れません（このチェックは a3.t1.periods が測る周期を使います）",
        "the motion does not repeat (or does not move), so there is no frame of the same phase to compare with and drift cannot be measured (this check uses the periods a3.t1.periods measures)",
    );
    let hint = t(
        "先に a3.t1.periods を直してください。直せば、このチェックはずれだけを測ります",
        "fix a3.t1.periods first; then this check measures drift alone",
    );
    let mut common: u64 = 1;
    for (i, found) in measured.iter().enumerate() {
        let actual = match *found {
            Some(l) if l > 1 => {
                common = crate::lcm(common, l);
                continue;
            }
            Some(_) => t(
                "動いていない（1 フレームあたり 0.06° または 0.001 未満）",
                "does not move (less than 0.06° or 0.001 per frame)",
            ),
            None => Text::new(
                format!("{}以内に繰り返さない", frames_text(2 * longest).ja),
                format!("does not repeat within {}", frames_text(2 * longest).en),
            ),
        };
        let actual = if spec.objects[i].motion.parent().is_some() {
            Text::new(
                format!("{}（親に対して）", actual.ja),
                format!("{} (relative to its parent)", actual.en),
            )
        } else {
            actual
        };
        return Err(Failure::new(expected, actual)
            .at(object_label(spec, i))
            .cause(cause)
            .hint(hint));
    }
    if common <= MAX_COMMON {
        return Ok(common);
    }
    let found: Vec<Text> = measured.iter().map(|m| frames_text(m.unwrap_or(1))).collect();
    let found = joined(&found, ", ");
    let names: Vec<Text> = (0..spec.objects.len()).map(|i| object_label(spec, i)).collect();
    Err(Failure::new(
        expected,
        Text::new(
            format!("周期 {} の公倍数が {MAX_COMMON} フレーム以内にない", found.ja),
            format!("the periods {} have no common multiple within {MAX_COMMON} frames", found.en),
        ),
    )
    .at(joined(&names, ", "))
    .cause(cause)
    .hint(hint))
}

/// The failure for object `i` whose pose at [`DRIFT_FRAMES`] is not its pose at `early`.
fn drift_failure(
    spec: &Spec,
    i: usize,
    early: u64,
    common: u64,
    rot: f64,
    pos: f64,
    det: f64,
) -> Failure {
    let e = |x: f64| if x.is_finite() { format!("{x:.1e}") } else { "∞".to_owned() };
    let (rot_e, deg, pos, det) = (e(rot), rot.to_degrees(), e(pos), e(det));
    let k = (DRIFT_FRAMES - early) / common;
    let relative = if spec.objects[i].motion.parent().is_some() {
        ["（親に対して）", " (relative to its parent)"]
    } else {
        ["", ""]
    };
    let (now, then) = (at_frame(DRIFT_FRAMES), at_frame(early));
    Failure::new(
        Text::new(
            format!(
                "フレーム {DRIFT_FRAMES} の姿勢{} = 同じ位相のフレーム {early} の姿勢（{common} フレームの周期の {k} 倍前）: 回転と位置の差 < {DRIFT_TOL:.0e}、det(R) の差 < {DRIFT_TOL:.0e}",
                relative[0]
            ),
            format!(
                "the pose{} at frame {DRIFT_FRAMES} = the pose at frame {early}, the same phase ({k} periods of {common} frames earlier): rotation and origin differences < {DRIFT_TOL:.0e} rad and units, det(R) difference < {DRIFT_TOL:.0e}",
                relative[1]
            ),
        ),
        Text::new(
            format!("回転の差 {rot_e} rad（{deg:.4}°）、原点の差 {pos}、det(R) の差 {det}"),
            format!("rotation differs by {rot_e} rad ({deg:.4}°), origin by {pos} units, det(R) by {det}"),
        ),
    )
    .at(Text::new(
        format!("{}、{} と {}", object_label(spec, i).ja, now.ja, then.ja),
        format!("{}, {} vs {}", object_label(spec, i).en, now.en, then.en),
    ))
    .cause(Text::new(
        format!(
            "フレーム {early} と {DRIFT_FRAMES} は同じ位相なのに姿勢が違います: 角度や位置を毎フレーム f32 で足し続けているため、丸め誤差がたまっています（または周期で割った余りを使っていない）"
        ),
        format!(
            "frames {early} and {DRIFT_FRAMES} have the same phase but not the same pose: the angle or position is accumulated in f32 every frame, so rounding errors pile up (or it is not reduced by the period)"
        ),
    ))
    .hint(t(
        "毎フレーム state.frame（整数）から作り直してください: P = 60·T として θ = 360·(state.frame % P) as f64 / P as f64",
        "rebuild it every frame from state.frame (an integer): with P = 60·T, θ = 360·(state.frame % P) as f64 / P as f64",
    ))
}
