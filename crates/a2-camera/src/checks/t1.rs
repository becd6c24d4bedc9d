//! Checks of a2.t1, `motion()`: every variable changes by its operation's amount, only its
//! operation changes it, yaw wraps, the others are clamped, and a long mixed drag sequence ends
//! where the spec says.
//!
//! States are compared within [`TOL`] (degrees or scene units): the drags use whole pixels and
//! speeds like 0.25°/px, so angles stay exact in f32; lengths such as 0.1/px round by about 1e-6
//! per drag. The smallest real mistake (a speed off by one table step on a 1-pixel drag) is
//! 0.01 or more.

use cg_harness::check::Failure;
use cg_harness::text::t;
use cg_harness::{Text, VariantRng};

use crate::oracle;
use crate::show::{self, ALL_GESTURES, Var};
use crate::spec::SpecVars;
use crate::{CameraState, Drag, DragAxis, Gesture, Impl, Operation, Spec};

/// Tolerance for camera variables after a drag (degrees or scene units).
pub(crate) const TOL: f32 = 1e-3;

/// The student's `motion()` applied to a copy of `s` (a panic names the state and the drag:
/// [`super::calling`]).
fn motion(spec: &Spec, imp: &Impl, s: &CameraState, drag: &Drag) -> CameraState {
    let mut out = *s;
    super::calling(
        || format!("motion(spec, &mut {s:?}, &{drag:?})"),
        || (imp.motion)(spec, &mut out, drag),
    );
    out
}

/// Whether `var` agrees within [`TOL`]; yaw around the circle (380 and 20 agree: the checks of
/// the amounts leave the wrap to a2.t1.wrap).
fn same(var: Var, actual: f32, expected: f32) -> bool {
    if var == Var::Yaw {
        let d = (actual - expected).rem_euclid(360.0);
        d.min(360.0 - d) <= TOL
    } else {
        (actual - expected).abs() <= TOL
    }
}

/// Whether `var` agrees within [`TOL`], yaw as a number in `[0, 360)` (across the seam only
/// values inside it agree, such as 359.9995 and 0): the state must be exactly the spec's.
fn same_exactly(var: Var, actual: f32, expected: f32) -> bool {
    let d = (actual - expected).abs();
    let in_range = |x: f32| (0.0..360.0).contains(&x);
    d <= TOL
        || (var == Var::Yaw && in_range(actual) && in_range(expected) && (d - 360.0).abs() <= TOL)
}

/// `actual − before`, for yaw the short way around the circle.
fn difference(var: Var, after: f32, before: f32) -> f32 {
    let d = after - before;
    if var == Var::Yaw { d - 360.0 * (d / 360.0).round() } else { d }
}

/// A state in the middle of every range, where drags of up to 20°/5 units stay inside:
/// yaw 100°, pitch at the middle of its range, distance 15, target at the origin.
fn middle(spec: &Spec) -> CameraState {
    CameraState {
        camera_yaw: 100.0,
        camera_pitch: (spec.pitch_min + spec.pitch_max) / 2.0,
        camera_distance: 15.0,
        target_x: 0.0,
        target_z: 0.0,
    }
}

/// A drag of `op`'s gesture by `px` pixels along `axis`.
fn drag_along(g: Gesture, axis: DragAxis, px: f32) -> Drag {
    let (dx, dy) = match axis {
        DragAxis::Horizontal => (px, 0.0),
        DragAxis::Vertical => (0.0, px),
    };
    Drag { button: g.button, shift: g.shift, dx, dy }
}

fn other_axis(axis: DragAxis) -> DragAxis {
    match axis {
        DragAxis::Horizontal => DragAxis::Vertical,
        DragAxis::Vertical => DragAxis::Horizontal,
    }
}

/// a2.t1.yaw / pitch / distance / pan: `var` changes by `per_px · d` for its own drag.
pub(super) fn changes_by_amount(
    spec: &Spec,
    imp: &Impl,
    var: Var,
    op: &Operation,
) -> Result<(), Failure> {
    let mut s = middle(spec);
    for (k, px) in [10.0f32, -4.0, 1.0].into_iter().enumerate() {
        let drag = drag_along(op.gesture, op.axis, px);
        let mut expected = s;
        oracle::motion(spec, &mut expected, &drag);
        let after = motion(spec, imp, &s, &drag);
        let (a, e) = (var.get(&after), var.get(&expected));
        if !same(var, a, e) {
            let actual_change = difference(var, a, var.get(&s));
            let expected_change = op.per_px * px;
            return Err(Failure::new(
                format!(
                    "{} = {}  ({}, {} = {})",
                    var.name(),
                    show::value(var, e),
                    show::formula(var, op),
                    show::axis_symbol(op.axis),
                    show::signed_num(px)
                ),
                Text::new(
                    format!(
                        "{} = {}（変化量 {}{}）",
                        var.name(),
                        show::value(var, a),
                        show::signed_num(actual_change),
                        var.unit()
                    ),
                    format!(
                        "{} = {}  (changed by {}{})",
                        var.name(),
                        show::value(var, a),
                        show::signed_num(actual_change),
                        var.unit()
                    ),
                ),
            )
            .at(Text::new(
                format!(
                    "{} = {} からのドラッグ {}（{}）",
                    var.name(),
                    show::value(var, var.get(&s)),
                    k + 1,
                    show::drag(&drag).ja
                ),
                format!(
                    "drag {} ({}) from {} = {}",
                    k + 1,
                    show::drag(&drag).en,
                    var.name(),
                    show::value(var, var.get(&s))
                ),
            ))
            .cause(amount_cause(spec, imp, var, op, &s, actual_change, expected_change))
            .hint(t(
                &format!(
                    "motion() で {} のドラッグのときに {} としてください（課題文: cargo run --release -- assignment --only a2）",
                    show::gesture(op.gesture).ja,
                    show::formula(var, op)
                ),
                &format!(
                    "in motion(), on a {} drag do {} (your assignment text: cargo run --release -- assignment --only a2)",
                    show::gesture(op.gesture).en,
                    show::formula(var, op)
                ),
            )));
        }
        s = after;
    }
    Ok(())
}

/// Why `var` changed by `actual` instead of `expected` on `op`'s drag from `s`.
fn amount_cause(
    spec: &Spec,
    imp: &Impl,
    var: Var,
    op: &Operation,
    s: &CameraState,
    actual: f32,
    expected: f32,
) -> Text {
    let close = |a: f32, b: f32| (a - b).abs() <= 1e-3 * b.abs().max(1e-3);
    let name = var.name();
    if actual.abs() <= TOL {
        // Nothing changed: does the other direction, or another button, change it?
        let other = drag_along(op.gesture, other_axis(op.axis), 10.0);
        if !same(var, var.get(&motion(spec, imp, s, &other)), var.get(s)) {
            return t(
                &format!(
                    "{name} が {} ではなく {} で変わっています（dx と dy の取り違え）",
                    show::axis_symbol(op.axis),
                    show::axis_symbol(other_axis(op.axis))
                ),
                &format!(
                    "{name} changes with {} instead of {} (dx and dy mixed up)",
                    show::axis_symbol(other_axis(op.axis)),
                    show::axis_symbol(op.axis)
                ),
            );
        }
        for g in ALL_GESTURES.into_iter().filter(|g| *g != op.gesture) {
            let d = drag_along(g, op.axis, 10.0);
            if !same(var, var.get(&motion(spec, imp, s, &d)), var.get(s)) {
                return t(
                    &format!(
                        "{name} が {} ではなく {} のドラッグで変わっています（ボタンか Shift の判定の間違い）",
                        show::gesture(op.gesture).ja,
                        show::gesture(g).ja
                    ),
                    &format!(
                        "{name} changes with the {} instead of the {} (the button or Shift test is wrong)",
                        show::gesture(g).en,
                        show::gesture(op.gesture).en
                    ),
                );
            }
        }
        // Not "not yet": the code may be there and never reached.
        return t(
            &format!(
                "{name} がどのドラッグでも変わりません: motion() が {name} を変えるところに一度も来ていません（その処理が else if の後ろや、先にそのドラッグを受け取るもっと広い if の中にありませんか）"
            ),
            &format!(
                "{name} does not change with any drag: motion() never changes it (is the code for it behind an else if, or a broader if that catches the drag first?)"
            ),
        );
    }
    if close(actual, -expected) {
        return t(
            &format!(
                "{name} の変化の向き（符号）が逆です: {} のはず（dx は右、dy は下が正）",
                show::formula(var, op)
            ),
            &format!(
                "{name} changes the wrong way (sign): it is {} (dx is positive to the right, dy down)",
                show::formula(var, op)
            ),
        );
    }
    let ratio = actual / expected;
    if close(ratio, std::f32::consts::PI / 180.0) || close(ratio, -std::f32::consts::PI / 180.0) {
        return t(
            &format!("{name} をラジアンで変えています。{name} の単位は度です（to_radians は不要）"),
            &format!("{name} is changed in radians: its unit is degrees (no to_radians)"),
        );
    }
    if close(ratio, 180.0 / std::f32::consts::PI) || close(ratio, -180.0 / std::f32::consts::PI) {
        return t(
            &format!(
                "{name} の変化量に to_degrees が掛かっています。1 ピクセルあたりの量はすでに度です"
            ),
            &format!(
                "{name}'s change is multiplied by to_degrees: the amount per pixel is already in degrees"
            ),
        );
    }
    let px = if expected == 0.0 { 1.0 } else { expected / op.per_px };
    let speed = (actual / px).abs();
    let wrong_sign = ratio < 0.0;
    t(
        &format!(
            "{name} の 1 ピクセルあたりの変化量が {} です（{} のはず）{}",
            show::num(speed),
            show::num(op.per_px.abs()),
            if wrong_sign { "。向き（符号）も逆です" } else { "" }
        ),
        &format!(
            "{name} changes by {} per pixel instead of {}{}",
            show::num(speed),
            show::num(op.per_px.abs()),
            if wrong_sign { ", and the wrong way (sign)" } else { "" }
        ),
    )
}

/// a2.t1.buttons: for every button (with and without Shift) and each direction, the variables
/// the spec does not give that drag stay unchanged — and some listed drag does change something
/// (or a `motion()` that does nothing would pass).
pub(super) fn only_listed_drags(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let base = middle(spec);
    let moves_anything = spec
        .operations()
        .iter()
        .any(|(_, op)| motion(spec, imp, &base, &drag_along(op.gesture, op.axis, 12.0)) != base);
    if !moves_anything {
        return Err(Failure::new(
            t("指定のドラッグでそれぞれの変数が変わる", "the listed drags change their variables"),
            t("motion() がどのドラッグでも何も変えない", "motion() changes nothing for any drag"),
        )
        .at(t("指定のすべてのドラッグ（12 px）", "every listed drag, 12 px"))
        .cause(t("motion() がまだ何もしていません", "motion() does not do anything yet"))
        .hint(t(
            "まず a2.t1.yaw などの変化量のチェックを通してください",
            "first make the checks of the amounts (a2.t1.yaw, …) pass",
        )));
    }
    for g in ALL_GESTURES {
        for axis in [DragAxis::Horizontal, DragAxis::Vertical] {
            for px in [12.0f32, -12.0] {
                let drag = drag_along(g, axis, px);
                let mut expected = base;
                oracle::motion(spec, &mut expected, &drag);
                let after = motion(spec, imp, &base, &drag);
                for var in Var::ALL {
                    if var.get(&expected) != var.get(&base) {
                        continue; // this drag is the variable's own: a2.t1.<variable> checks it
                    }
                    if same(var, var.get(&after), var.get(&base)) {
                        continue;
                    }
                    let listed: Vec<String> = spec
                        .operations()
                        .iter()
                        .filter(|(_, op)| op.gesture == g && op.axis == axis)
                        .map(|(v, _)| v.name().to_owned())
                        .collect();
                    let (name, stays) = (var.name(), show::value(var, var.get(&base)));
                    let expected = if listed.is_empty() {
                        Text::new(
                            format!("{name} は {stays} のまま（このドラッグでは何も変わりません）"),
                            format!("{name} stays {stays} (this drag changes nothing)"),
                        )
                    } else {
                        let listed = listed.join(", ");
                        Text::new(
                            format!(
                                "{name} は {stays} のまま（このドラッグで変わるのは {listed} だけ）"
                            ),
                            format!("{name} stays {stays} (this drag changes only: {listed})"),
                        )
                    };
                    let from = show::state(&base, spec.pan.is_some());
                    return Err(Failure::new(
                        expected,
                        format!("{} = {}", var.name(), show::value(var, var.get(&after))),
                    )
                    .at(Text::new(
                        format!("{from} からの {}", show::drag(&drag).ja),
                        format!("{} from {from}", show::drag(&drag).en),
                    ))
                    .cause(buttons_cause(spec, var, g, axis))
                    .hint(t(
                        "ドラッグのボタンと Shift の両方（drag.button と drag.shift）を、変数ごとに決められた組み合わせと比べてから変えてください",
                        "compare both drag.button and drag.shift with the combination listed for each variable before changing it",
                    )));
                }
            }
        }
    }
    Ok(())
}

/// Why `var` changed on a `g`/`axis` drag that is not its own.
fn buttons_cause(spec: &Spec, var: Var, g: Gesture, axis: DragAxis) -> Text {
    let own = spec.operations().into_iter().find(|(v, _)| *v == var).map(|(_, op)| op);
    let name = var.name();
    match own {
        Some(op) if op.gesture == g && op.axis != axis => t(
            &format!(
                "{name} は {} だけで変わるはずが、{} でも変わっています",
                show::axis_symbol(op.axis),
                show::axis_symbol(axis)
            ),
            &format!(
                "{name} should change with {} only, and also changes with {}",
                show::axis_symbol(op.axis),
                show::axis_symbol(axis)
            ),
        ),
        Some(op) if op.gesture.button == g.button => t(
            &format!(
                "Shift の有無を見ていません: {name} は {} のドラッグで変わり、{} では変わりません",
                show::gesture(op.gesture).ja,
                show::gesture(g).ja
            ),
            &format!(
                "Shift is not tested: {name} changes on a {} drag, not on a {} drag",
                show::gesture(op.gesture).en,
                show::gesture(g).en
            ),
        ),
        Some(op) => t(
            &format!(
                "ボタンが違います: {name} は {} のドラッグで変わり、{} では変わりません",
                show::gesture(op.gesture).ja,
                show::gesture(g).ja
            ),
            &format!(
                "the wrong button: {name} changes on a {} drag, not on a {} drag",
                show::gesture(op.gesture).en,
                show::gesture(g).en
            ),
        ),
        None => t(
            &format!("{name} はこの課題ではマウスで変わりません（注視点は原点のまま）"),
            &format!(
                "{name} is not changed by the mouse in your assignment (the target stays at the origin)"
            ),
        ),
    }
}

/// Whole-pixel drags of `op` that change its variable by `amount` for a correct answer, at
/// most `max_step` (in the variable's unit) per drag. `amount / per_px` is a whole number for
/// the amounts used here.
fn drags_of(op: &Operation, amount: f32, max_step: f32) -> Vec<Drag> {
    let steps = (amount.abs() / max_step).ceil().max(1.0);
    let px = (amount / op.per_px / steps).round();
    vec![drag_along(op.gesture, op.axis, px); steps as usize]
}

/// a2.t1.wrap: yaw drags across 360 and 0, several turns, and one ending exactly on 360
/// (which must read 0). Each drag turns by less than 360°, as real mouse drags do.
pub(super) fn yaw_wraps(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let op = spec.yaw;
    let mut s = CameraState { camera_yaw: 354.0, ..middle(spec) };
    // Every amount is a multiple of 6°, so the pixels are whole for every table speed.
    let mut drags = Vec::new();
    for (amount, max_step) in
        [(30.0, 30.0), (-60.0, 60.0), (1110.0, 222.0), (-750.0, 150.0), (36.0, 36.0), (-6.0, 6.0)]
    {
        drags.extend(drags_of(&op, amount, max_step));
    }
    for (k, drag) in drags.iter().enumerate() {
        let mut expected = s;
        oracle::motion(spec, &mut expected, drag);
        let after = motion(spec, imp, &s, drag);
        let (a, e) = (after.camera_yaw, expected.camera_yaw);
        let in_range = (0.0..360.0).contains(&a);
        if !in_range || !same(Var::Yaw, a, e) || (a - e).abs() > TOL {
            let unwrapped = s.camera_yaw
                + op.per_px * if op.axis == DragAxis::Horizontal { drag.dx } else { drag.dy };
            let cause = if !same(Var::Yaw, a, e) {
                t(
                    "camera_yaw の変化量そのものが違います（まず a2.t1.yaw を通してください）",
                    "camera_yaw itself changes by the wrong amount (make a2.t1.yaw pass first)",
                )
            } else if a == 360.0 {
                t(
                    "ちょうど 360 になったときに 0 に戻していません（>= 360 で折り返す、または rem_euclid）",
                    "exactly 360 is not turned into 0 (wrap when >= 360, or use rem_euclid)",
                )
            } else if a < 0.0 {
                t(
                    "負になったときに折り返していません。Rust の % は符号を残す（-36 % 360 = -36）ので rem_euclid(360.0) を使うか、0 未満なら 360 を足します",
                    "negative values are not wrapped: Rust's % keeps the sign (-36 % 360 = -36); use rem_euclid(360.0), or add 360 below 0",
                )
            } else {
                t(
                    "360 以上になったときに折り返していません（360 を引く、または rem_euclid(360.0)）",
                    "values of 360 and more are not wrapped (subtract 360, or use rem_euclid(360.0))",
                )
            };
            let (e, unwrapped) = (show::num(e), show::num(unwrapped));
            return Err(Failure::new(
                Text::new(
                    format!("camera_yaw = {e}°（0 ≤ camera_yaw < 360。{unwrapped} を折り返した値）"),
                    format!("camera_yaw = {e}° (0 ≤ camera_yaw < 360; {unwrapped} wrapped)"),
                ),
                format!("camera_yaw = {}°", show::num(a)),
            )
            .at(Text::new(
                format!(
                    "camera_yaw = {}° からの camera_yaw のドラッグ {}（{}）",
                    show::num(s.camera_yaw),
                    k + 1,
                    show::drag(drag).ja
                ),
                format!(
                    "yaw drag {} ({}) from camera_yaw = {}°",
                    k + 1,
                    show::drag(drag).en,
                    show::num(s.camera_yaw)
                ),
            ))
            .cause(cause)
            .hint(t(
                "camera_yaw = (camera_yaw + 変化量).rem_euclid(360.0); で折り返します（丸めで 360.0 になったら 0）",
                "camera_yaw = (camera_yaw + change).rem_euclid(360.0); wraps it (make a rounded 360.0 a 0)",
            )));
        }
        s = after;
    }
    Ok(())
}

/// a2.t1.*_range: from the middle, drags far past `lo` (in three drags) must stop exactly at
/// `lo`, and a short drag back must move away from it at once; the same at `hi`.
pub(super) fn clamped(
    spec: &Spec,
    imp: &Impl,
    var: Var,
    op: &Operation,
    lo: f32,
    hi: f32,
) -> Result<(), Failure> {
    let name = var.name();
    let mut s = middle(spec);
    let speed = op.per_px.abs();
    let back = 5.0 * speed;
    // Each drag with what it is for (in Japanese and English), and whether it goes back.
    let mut script: Vec<(Drag, [&str; 2], bool)> = Vec::new();
    let push_far = |script: &mut Vec<(Drag, [&str; 2], bool)>,
                    from: f32,
                    to: f32,
                    label: [&'static str; 2]| {
        // Past the limit by the range's width again, in three whole-pixel drags.
        let amount = (to - from) + (to - from).signum() * (hi - lo);
        let px = (amount / op.per_px / 3.0).round();
        for _ in 0..3 {
            script.push((drag_along(op.gesture, op.axis, px), label, false));
        }
    };
    push_far(&mut script, var.get(&s), lo, ["下限に向かう", "towards the lower limit"]);
    script.push((
        drag_along(op.gesture, op.axis, (back / op.per_px).round()),
        ["下限から戻す", "back from the lower limit"],
        true,
    ));
    push_far(&mut script, lo + back, hi, ["上限に向かう", "towards the upper limit"]);
    script.push((
        drag_along(op.gesture, op.axis, (-back / op.per_px).round()),
        ["上限から戻す", "back from the upper limit"],
        true,
    ));
    for (k, (drag, [label_ja, label_en], back)) in script.iter().enumerate() {
        let mut expected = s;
        oracle::motion(spec, &mut expected, drag);
        let after = motion(spec, imp, &s, drag);
        let (a, e) = (var.get(&after), var.get(&expected));
        if !same(var, a, e) {
            let pole = if var == Var::Pitch && (e == -90.0 || e == 90.0) {
                ["（極: 真下・真上を見る向き）", " (the pole: looking straight down/up)"]
            } else {
                ["", ""]
            };
            let cause = if a < lo - TOL || a > hi + TOL {
                t(
                    &format!(
                        "{name} が範囲 {} 〜 {} の外に出ています（制限していない、または片側だけ）",
                        show::num(lo),
                        show::num(hi)
                    ),
                    &format!(
                        "{name} leaves its range {} … {} (not clamped, or only at one end)",
                        show::num(lo),
                        show::num(hi)
                    ),
                )
            } else if *back && (a == lo || a == hi) {
                t(
                    &format!("限界から戻すドラッグで {name} が動きません"),
                    &format!("dragging back from the limit does not move {name}"),
                )
            } else if changes_by_amount(spec, imp, var, op).is_ok() {
                t(
                    &format!(
                        "{name} が限界の値 {} ちょうどで止まっていません（制限の値の間違いか、変化を足す前に制限している）",
                        show::num(e)
                    ),
                    &format!(
                        "{name} does not stop exactly at its limit {} (a wrong limit, or clamping before adding the change)",
                        show::num(e)
                    ),
                )
            } else {
                t(
                    &format!(
                        "{name} の変化量そのものが違います（先に変化量のチェックを通してください）"
                    ),
                    &format!(
                        "{name} itself changes by the wrong amount (make its amount check pass first)"
                    ),
                )
            };
            return Err(Failure::new(
                Text::new(
                    format!("{name} = {}{}", show::value(var, e), pole[0]),
                    format!("{name} = {}{}", show::value(var, e), pole[1]),
                ),
                format!("{name} = {}", show::value(var, a)),
            )
            .at(Text::new(
                format!(
                    "{name} = {} から{label_ja}ドラッグ {}（{}）",
                    show::value(var, var.get(&s)),
                    k + 1,
                    show::drag(drag).ja
                ),
                format!(
                    "drag {} {label_en} ({}) from {name} = {}",
                    k + 1,
                    show::drag(drag).en,
                    show::value(var, var.get(&s))
                ),
            ))
            .cause(cause)
            .hint(t(
                &format!(
                    "変化量を足したあとで {name} = {name}.clamp({}, {}) のように範囲に収めて、その値を変数に残します",
                    show::num(lo),
                    show::num(hi)
                ),
                &format!(
                    "after adding the change, keep it in range, e.g. {name} = {name}.clamp({}, {}), and store that value",
                    show::num(lo),
                    show::num(hi)
                ),
            )));
        }
        s = after;
    }
    Ok(())
}

/// The range `var` is kept in (yaw: `[0, 360)`).
fn range_of(spec: &Spec, var: Var) -> (f32, f32) {
    let limit = spec.pan.map_or(0.0, |p| p.limit);
    match var {
        Var::Yaw => (0.0, 360.0),
        Var::Pitch => (spec.pitch_min, spec.pitch_max),
        Var::Distance => (spec.distance_min, spec.distance_max),
        Var::TargetX | Var::TargetZ => (-limit, limit),
    }
}

/// a2.t1.sequence: 150 seeded drags from the spec's start — listed and unlisted buttons,
/// diagonal drags, and long ones that reach the limits — give the spec's state after each.
pub(super) fn sequence(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let mut rng = VariantRng::from_seed(0x0A25_E90E);
    let listed: Vec<Gesture> = spec.operations().iter().map(|(_, op)| op.gesture).collect();
    let mut s = spec.start;
    let mut expected = spec.start;
    for k in 0..150 {
        let g = if rng.below(10) < 7 { *rng.pick(&listed) } else { *rng.pick(&ALL_GESTURES) };
        let long = rng.below(10) == 0;
        let mut px = || {
            let v = if long { rng.range(100, 400) } else { rng.range(-25, 25) };
            let sign = if long && rng.below(2) == 0 { -1 } else { 1 };
            (v * sign) as f32
        };
        let drag = Drag { button: g.button, shift: g.shift, dx: px(), dy: px() };
        let before = s;
        oracle::motion(spec, &mut expected, &drag);
        s = motion(spec, imp, &s, &drag);
        let off: Vec<Var> = Var::ALL
            .into_iter()
            .filter(|v| !same_exactly(*v, v.get(&s), v.get(&expected)))
            .collect();
        if off.is_empty() {
            continue;
        }
        // Diagonal drags: does the student apply only one of dx and dy?
        let only = |dx: f32, dy: f32| {
            let mut e = before;
            oracle::motion(spec, &mut e, &Drag { dx, dy, ..drag });
            Var::ALL.into_iter().all(|v| same_exactly(v, v.get(&s), v.get(&e)))
        };
        // Only a button with an operation on dx and one on dy can lose one of them.
        let both_axes = [DragAxis::Horizontal, DragAxis::Vertical].iter().all(|axis| {
            spec.operations().iter().any(|(_, op)| op.gesture == g && op.axis == *axis)
        });
        let cause = if both_axes
            && drag.dx != 0.0
            && drag.dy != 0.0
            && (only(drag.dx, 0.0) || only(0.0, drag.dy))
        {
            t(
                "斜めのドラッグで dx と dy の片方しか使っていません（else if にしていませんか）。同じボタンの dx と dy は両方とも効きます",
                "a diagonal drag uses only one of dx and dy (an else-if?): both apply for the same button",
            )
        } else if off == [Var::Yaw] && same(Var::Yaw, s.camera_yaw, expected.camera_yaw) {
            t(
                "camera_yaw が 0〜360 に折り返されていません（a2.t1.wrap も見てください）",
                "camera_yaw is not wrapped into [0, 360) (see a2.t1.wrap too)",
            )
        } else if let Some(v) = off.iter().find(|v| {
            let (lo, hi) = range_of(spec, **v);
            v.get(&s) < lo - TOL || v.get(&s) > hi + TOL
        }) {
            t(
                &format!(
                    "{} が範囲の外に出ています（範囲の制限のチェックも見てください）",
                    v.name()
                ),
                &format!("{} leaves its range (see its range check too)", v.name()),
            )
        } else {
            t(
                "1 回のドラッグの結果が仕様と違います（上の個別のチェックも見てください）",
                "one drag does not give the spec's result (see the individual checks above too)",
            )
        };
        let names: Vec<&str> = off.iter().map(|v| v.name()).collect();
        return Err(Failure::new(
            show::state(&expected, spec.pan.is_some()),
            show::state(&s, spec.pan.is_some()),
        )
        .at(Text::new(
            format!(
                "150 回中 {} 回目のドラッグ（{}）、開始時 {}; ずれた変数: {}",
                k + 1,
                show::drag(&drag).ja,
                show::state(&before, spec.pan.is_some()),
                names.join(", ")
            ),
            format!(
                "drag {} of 150 ({}) from {}; off: {}",
                k + 1,
                show::drag(&drag).en,
                show::state(&before, spec.pan.is_some()),
                names.join(", ")
            ),
        ))
        .cause(cause)
        .hint(t(
            "変数ごとに「ボタン・Shift が合えば、dx か dy × 1 ピクセルあたりの量を足し、範囲に収める（yaw は折り返す）」を、else を使わずに並べます",
            "for each variable on its own (no else): if the button and Shift match, add dx or dy times its amount per pixel, then clamp (wrap the yaw)",
        )));
    }
    Ok(())
}
