//! The report's data for `a3`: each object's model matrix at the stated times, numerically and
//! with the animation's variables named (see [`cg_harness::symbolic`]), and the periods. The
//! poses are read as the checks read them (`pose.rs`).

use cg_core::gl::{Draw, Gl};
use cg_core::lang::{Lang, t};
use cg_core::product::{Factor, MatrixProduct, format_number};
use cg_harness::Text;
use cg_harness::check::guarded;
use cg_harness::report::{Missing, NamedMatrix, Part};
use cg_harness::symbolic::{Names, Var, matrices_close, numeric, params, symbolize};

use crate::pose::{name_matches, pose_distance, seconds};
use crate::{Impl, Motion, Spec, SpecExt as _, WorldAxis, WorldAxisExt as _};

/// Assignment 3: each object's model transform.
#[derive(Clone, Debug, PartialEq)]
pub struct AnimationData {
    /// Per object, its model matrix at the stated times.
    pub objects: Vec<(String, Vec<NamedMatrix>)>,
    /// The periods and their ratios, as the report must state them.
    pub periods: Text,
}

/// The most frames the animation is run for (beyond it, t = 0 is taken at frame 0).
const MAX_FRAMES: u64 = 100_000;
/// The stated times are multiples of this (s): 15 frames.
const TIME_STEP_S: f64 = 0.25;
/// The stated times lie within this many seconds (and within one common period).
const TIME_LIMIT_S: f64 = 12.0;

/// The frame of time `t` (s).
fn frame_of(t: f64) -> u64 {
    (t * f64::from(crate::FPS)).round().max(0.0) as u64
}

/// The times (s) at which [`animation`] states each object's model matrix: `0` and two more,
/// chosen from the spec alone so that the motion shows: among the multiples of 0.25 s within the
/// first common period (at most 12 s), the earliest where every object is well away from where
/// it starts (at least 3/4 of the best such time's least distance), then the earliest where every
/// object is also well away from the first. Ascending.
#[must_use]
pub fn animation_times(spec: &Spec) -> Vec<f64> {
    let n = spec.objects.len();
    if n == 0 {
        return vec![0.0];
    }
    let pose = |i: usize, t: f64| crate::expected_model(spec, i, frame_of(t));
    let limit = spec.common_period_s().min(TIME_LIMIT_S);
    let candidates: Vec<f64> =
        (1..).map(|k| f64::from(k) * TIME_STEP_S).take_while(|t| *t < limit - 1e-9).collect();
    let least = |t: f64, from: &[f64]| -> f64 {
        (0..n)
            .map(|i| {
                from.iter()
                    .map(|&u| pose_distance(pose(i, t), pose(i, u)))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(f64::INFINITY, f64::min)
    };
    let earliest_good = |from: &[f64]| -> Option<f64> {
        let scores: Vec<(f64, f64)> = candidates
            .iter()
            .filter(|t| !from.iter().any(|u| (*u - **t).abs() < 1e-9))
            .map(|&t| (t, least(t, from)))
            .collect();
        let best = scores.iter().map(|s| s.1).fold(0.0, f64::max);
        scores.iter().find(|s| s.1 >= 0.75 * best).map(|s| s.0)
    };
    let mut times = vec![0.0];
    if let Some(a) = earliest_good(&[0.0]) {
        times.push(a);
        if let Some(b) = earliest_good(&[0.0, a]) {
            times.push(b);
        }
    }
    times.sort_by(f64::total_cmp);
    times
}

/// A spec variable's full name, `theta_2`, and which object it belongs to.
fn var_object(name: &str) -> Option<(&str, usize)> {
    let (kind, n) = name.split_once('_')?;
    let n: usize = n.parse().ok()?;
    Some((kind, n.checked_sub(1)?))
}

/// The explanation of the spec's variable `var` (`theta_2`, `x_3`, `y_3`), printed under the
/// name `shown` (the student's own, or the same): the formula, the range and the period.
fn var_text(spec: &Spec, var: &str, shown: &str) -> Text {
    let unknown = Text::new(
        format!("{shown}: 仕様の運動の変数と値が一致しません"),
        format!("{shown}: its value matches none of the spec's motion variables"),
    );
    let Some((kind, i)) = var_object(var) else { return unknown };
    let Some(object) = spec.objects.get(i) else { return unknown };
    let n = i + 1;
    let p = format_number(object.motion.period_s());
    let u = Text::new(
        format!("u = (t mod {p}) / {p}（t は秒、周期 {p} 秒）"),
        format!("u = (t mod {p}) / {p} (t in seconds, period {p} s)"),
    );
    let turn = |turn: crate::Turn| match turn {
        crate::Turn::Ccw => ("", format!("0 ≤ {shown} < 360"), "反時計回り", "counter-clockwise"),
        crate::Turn::Cw => ("-", format!("-360 < {shown} ≤ 0"), "時計回り", "clockwise"),
    };
    let axis = |a: WorldAxis| a.name();
    match (kind, object.motion) {
        ("theta", Motion::Spin { axis: a, turn: t, .. }) => {
            let (sign, range, ja, en) = turn(t);
            Text::new(
                format!(
                    "{shown}: 物体{n}の自転の角度（{} 軸まわり、{ja}）[度] = {sign}360°·u、{}。{range}",
                    axis(a),
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s spin about the {} axis ({en}), degrees: {sign}360°·u, {}; {range}",
                    axis(a),
                    u.en
                ),
            )
        }
        ("theta", Motion::Orbit { turn: t, .. }) => {
            let (sign, range, ja, en) = turn(t);
            Text::new(
                format!(
                    "{shown}: 物体{n}の公転の角度（Y 軸まわり、上から見て{ja}）[度] = {sign}360°·u、{}。{range}",
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s orbit angle about the Y axis ({en} seen from above), degrees: {sign}360°·u, {}; {range}",
                    u.en
                ),
            )
        }
        ("theta", Motion::Satellite { parent_index, turn: t, .. }) => {
            let (sign, range, ja, en) = turn(t);
            let parent = parent_index + 1;
            Text::new(
                format!(
                    "{shown}: 物体{n}が親（物体{parent}）のまわりを回る角度（親の Y 軸まわり、{ja}）[度] = {sign}360°·u、{}。{range}",
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s angle round its parent, object {parent} (about the parent's Y axis, {en}), degrees: {sign}360°·u, {}; {range}",
                    u.en
                ),
            )
        }
        ("theta", Motion::Swing { axis: a, amplitude_deg, .. }) => {
            let amp = format_number(amplitude_deg);
            Text::new(
                format!(
                    "{shown}: 物体{n}の往復回転の角度（{} 軸まわり）[度] = {amp}·sin(360°·u)、{}。-{amp} ≤ {shown} ≤ {amp}",
                    axis(a),
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s back-and-forth angle about the {} axis, degrees: {amp}·sin(360°·u), {}; -{amp} ≤ {shown} ≤ {amp}",
                    axis(a),
                    u.en
                ),
            )
        }
        ("x" | "z", Motion::Hop { along, span, .. }) => {
            let s = format_number(span);
            let half = format_number(span / 2.0);
            Text::new(
                format!(
                    "{shown}: 物体{n}の {} 方向の位置（往復の中心から）= {s}·(w − 1/2)、w = 2u（u < 1/2）、2 − 2u（u ≥ 1/2）、{}。-{half} ≤ {shown} ≤ {half}",
                    axis(along),
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s position along {} (from the middle of its path) = {s}·(w − 1/2), w = 2u (u < 1/2), 2 − 2u (u ≥ 1/2), {}; -{half} ≤ {shown} ≤ {half}",
                    axis(along),
                    u.en
                ),
            )
        }
        ("y", Motion::Hop { span, height, .. }) => {
            let (s, h) = (format_number(span), format_number(height));
            Text::new(
                format!(
                    "{shown}: 物体{n}の高さ（放物線）= 4·{h}·w·(1 − w) = {h}·(1 − (2·s/{s})²)（s は往復の中心からの位置）、w は上と同じ、{}。0 ≤ {shown} ≤ {h}",
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s height (a parabola) = 4·{h}·w·(1 − w) = {h}·(1 − (2·s/{s})²) (s: the position from the middle of the path), w as above, {}; 0 ≤ {shown} ≤ {h}",
                    u.en
                ),
            )
        }
        _ => unknown,
    }
}

/// The spec's variables and their values at `frame` (from the spec's own products), and every
/// constant they are printed with.
fn animation_vars(spec: &Spec, frame: u64) -> (Vec<Var>, Vec<f32>) {
    let mut vars: Vec<Var> = Vec::new();
    let mut constants = vec![crate::CAMERA_DISTANCE, crate::CAMERA_PITCH_DEG];
    for i in 0..spec.objects.len() {
        for f in &crate::model_product(spec, i, frame).factors {
            for p in params(f) {
                match &p.symbol {
                    Some(s) if !vars.iter().any(|v| v.name == *s) => {
                        vars.push(Var { name: s.clone(), value: p.value });
                    }
                    Some(_) => {}
                    None => constants.push(p.value),
                }
            }
        }
    }
    (vars, constants)
}

/// A frame where every variable of the spec has a value of its own: away from 0, ±1, every
/// constant and every other variable (also up to sign and whole turns), so each number of a
/// recorded product names at most one variable.
fn animation_probe(spec: &Spec) -> Option<(u64, Vec<Var>)> {
    let apart = |a: f32, b: f32| {
        let (a, b) = (f64::from(a.abs()), f64::from(b.abs()));
        (a - b).abs() > 0.02
            && ((a + b) - 360.0).abs() > 0.02
            && ((a - b).abs() - 360.0).abs() > 0.02
    };
    (7..2_000).find_map(|frame| {
        let (vars, constants) = animation_vars(spec, frame);
        let good = vars.iter().enumerate().all(|(k, v)| {
            v.value.is_finite()
                && v.value.abs() > 0.05
                && apart(v.value, 1.0)
                && apart(v.value, 0.0)
                && constants.iter().all(|&c| apart(v.value, c))
                && vars[..k].iter().all(|w| apart(v.value, w.value))
        });
        good.then_some((frame, vars))
    })
}

/// A draw's model transform (model → world): its model-view product with the common camera
/// `T(0, 0, -15) · Rx(30°)` taken off the front — the shortest leading factors that multiply to
/// it — or, when no leading factors do, `V⁻¹ ·` the whole product.
fn model_product_of(draw: &Draw) -> MatrixProduct {
    let camera = crate::camera_product();
    let Ok(view) = camera.matrix() else { return draw.model_view.clone() };
    let factors = &draw.model_view.factors;
    for k in 1..=factors.len() {
        let head = MatrixProduct { factors: factors[..k].to_vec() };
        if head.matrix().is_ok_and(|m| matrices_close(&m, &view)) {
            return MatrixProduct { factors: factors[k..].to_vec() };
        }
    }
    MatrixProduct::identity().then(Factor::named("V⁻¹", view.inverse())).concat(&draw.model_view)
}

/// `object 1` → `object1`: the ASCII letters, digits and `_` of a name (`object<n>` when none).
fn ascii_id(name: &str, n: usize) -> String {
    let id: String = name.chars().filter(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
    if id.is_empty() { format!("object{n}") } else { id }
}

/// The periods and their ratios, as the report states them.
fn periods_text(spec: &Spec) -> Text {
    let periods: Vec<Text> = spec
        .objects
        .iter()
        .enumerate()
        .map(|(i, o)| {
            let p = format_number(o.motion.period_s());
            Text::new(format!("物体{} {p} 秒", i + 1), format!("object {} {p} s", i + 1))
        })
        .collect();
    let each = |lang: Lang| {
        let sep = t("、", ", ");
        periods.iter().map(|p| p.get(lang)).collect::<Vec<_>>().join(sep.get(lang))
    };
    let names = |word: &str| {
        (1..=spec.objects.len()).map(|n| format!("{word}{n}")).collect::<Vec<_>>().join(" : ")
    };
    let ratios: Vec<String> = spec.period_ratios().iter().map(u64::to_string).collect();
    let ratios = ratios.join(" : ");
    let unit = format_number(spec.unit_s);
    let common = seconds(spec.common_period_s());
    Text::new(
        format!(
            "周期: {}。周期の比 {} = {ratios}（単位 {unit} 秒）。全体は {common} 秒ごとに同じ動きを繰り返す。",
            each(Lang::Ja),
            names("物体")
        ),
        format!(
            "Periods: {}. Ratio of the periods {} = {ratios} (unit {unit} s); the whole animation repeats every {common} s.",
            each(Lang::En),
            names("object ")
        ),
    )
}

/// Each animated object's model matrix (model → world: the model-view matrix of its draw with
/// the common camera taken off) at the times of [`animation_times`], from the student's
/// `idle()` (a3.t1) and `display()` (a3.t2): `idle()` is called `60·t` times from
/// `State::new()` and `display()` recorded. `t = 0` is taken one common period later (every
/// motion back at its start), since before the first `idle()` the parameters are not computed
/// yet. Symbolically, each number that is one of the spec's motion variables (`theta_n`, and
/// `x_n` or `z_n` and `y_n` for a hop, as a3's own products name them) is named after it, and
/// each symbol is explained (formula, range, period); `periods` states the periods and their
/// ratios.
///
/// An object not drawn exactly once is left out (the others still derive).
///
/// # Errors
/// `idle()` or `display()` panicking, or `display()` drawing none of the objects.
pub fn animation(spec: &Spec, imp: &Impl) -> Result<AnimationData, Missing> {
    animation_part(spec, imp).0
}

/// [`animation`] with the smaller parts it had to leave out: the report data of [`crate::A3`].
pub fn animation_part(spec: &Spec, imp: &Impl) -> Part<AnimationData> {
    let mut notes = Vec::new();
    let times = animation_times(spec);
    let cycle = frame_of(spec.common_period_s());
    let start_frame = if cycle <= MAX_FRAMES { cycle } else { 0 };
    let time_frames: Vec<u64> =
        times.iter().map(|&t| if t == 0.0 { start_frame } else { frame_of(t) }).collect();
    let probe = animation_probe(spec);
    let mut frames: Vec<u64> = time_frames.clone();
    frames.extend(probe.as_ref().map(|p| p.0));
    frames.sort_unstable();
    frames.dedup();

    // Run the student's idle() and record display() at each frame.
    let mut recorded: Vec<(u64, Gl)> = Vec::new();
    let mut state = crate::State::new();
    let mut done = 0;
    for &frame in &frames {
        let gap = frame - done;
        if let Err(o) = guarded(|| {
            for _ in 0..gap {
                (imp.idle)(spec, &mut state);
            }
        }) {
            return (Err(Missing::from_outcome("a3.t1", "idle()", o)), notes);
        }
        done = frame;
        match guarded(|| {
            let mut rec = cg_student::gl::Gl::new();
            (imp.display)(spec, &state, &mut rec);
            crate::replay(&rec)
        }) {
            Ok(gl) => recorded.push((frame, gl)),
            Err(o) => return (Err(Missing::from_outcome("a3.t2", "display()", o)), notes),
        }
    }
    let at = |frame: u64| recorded.iter().find(|r| r.0 == frame).map(|r| &r.1);

    let mut objects = Vec::new();
    for (i, object) in spec.objects.iter().enumerate() {
        let n = i + 1;
        // The object's one draw in each recorded frame.
        let draw_in = |gl: &Gl| -> Result<MatrixProduct, usize> {
            let found: Vec<&Draw> =
                gl.draws().iter().filter(|d| name_matches(&d.name, &object.name)).collect();
            if found.len() == 1 { Ok(model_product_of(found[0])) } else { Err(found.len()) }
        };
        let mut products = Vec::new();
        let mut failed = None;
        for &frame in &time_frames {
            match at(frame).map(draw_in) {
                Some(Ok(p)) if p.matrix().is_ok() => products.push(p),
                Some(Ok(_)) => {
                    failed = Some(Text::new(
                        format!(
                            "物体{n} \"{}\" のモデルビュー行列が有限の値になりません",
                            object.name
                        ),
                        format!("\"{}\"'s model-view matrix is not finite", object.name),
                    ))
                }
                Some(Err(0)) | None => {
                    failed = Some(Text::new(
                        format!(
                            "物体{n} \"{}\" が描かれていません（名前が違うか、まだ描いていない）",
                            object.name
                        ),
                        format!(
                            "\"{}\" is not drawn (a different name, or not drawn yet)",
                            object.name
                        ),
                    ))
                }
                Some(Err(k)) => {
                    failed = Some(Text::new(
                        format!("物体{n} \"{}\" が 1 フレームに {k} 回描かれています", object.name),
                        format!("\"{}\" is drawn {k} times in one frame", object.name),
                    ))
                }
            }
            if failed.is_some() {
                break;
            }
        }
        if let Some(why) = failed {
            notes.push(Missing::new("a3.t2", why));
            continue;
        }
        // The probe's product names the variables.
        let probe_product = probe.as_ref().and_then(|(f, vars)| {
            at(*f).and_then(|gl| draw_in(gl).ok()).map(|p| (p, vars.clone()))
        });
        let mut names: Names = Vec::new();
        let symbolic: Vec<MatrixProduct> = products
            .iter()
            .map(|p| {
                let (s, found) = match &probe_product {
                    Some((probe, vars)) => symbolize(probe, p, vars),
                    None => symbolize(p, p, &[]),
                };
                for (symbol, var) in found {
                    if !names.iter().any(|(s, _)| *s == symbol) {
                        names.push((symbol, var));
                    }
                }
                s
            })
            .collect();
        let variables: Vec<(String, Text)> = names
            .iter()
            .map(|(symbol, var)| {
                let text = match var {
                    Some(v) => var_text(spec, v, symbol),
                    None => var_text(spec, "", symbol),
                };
                (symbol.clone(), text)
            })
            .collect();
        let id = ascii_id(&object.name, n);
        let matrices: Vec<NamedMatrix> = times
            .iter()
            .zip(products.iter().zip(symbolic))
            .map(|(&t, (p, symbolic))| NamedMatrix {
                id: format!("a3.{id}.t{}", seconds(t)),
                title: Text::new(
                    format!(
                        "物体{n} \"{}\" のモデル変換行列（モデル座標系 → ワールド座標系、t = {} 秒）",
                        object.name,
                        seconds(t)
                    ),
                    format!(
                        "model matrix of \"{}\" (model → world, t = {} s)",
                        object.name,
                        seconds(t)
                    ),
                ),
                symbolic,
                numeric: numeric(p),
                variables: variables.clone(),
            })
            .collect();
        objects.push((object.name.clone(), matrices));
    }
    if objects.is_empty() {
        let drew_nothing = recorded.iter().all(|(_, gl)| gl.draws().is_empty());
        if drew_nothing || notes.is_empty() {
            let why = Text::new(
                "display() がまだどの物体も描いていません（物体は gl.draw(&object.name, &object.shape.mesh()) で描きます）",
                "display() draws none of the objects yet (draw each with gl.draw(&object.name, &object.shape.mesh()))",
            );
            return (Err(Missing::new("a3.t2", why)), Vec::new());
        }
        let first = notes.remove(0);
        return (Err(first), notes);
    }
    let still = objects.iter().all(|(_, ms)| {
        ms.windows(2).all(|w| {
            matches!((w[0].numeric.matrix(), w[1].numeric.matrix()), (Ok(a), Ok(b)) if matrices_close(&a, &b))
        })
    });
    if still && times.len() > 1 {
        notes.push(Missing::new(
            "a3.t1",
            Text::new(
                "どの物体も動いていません: idle() で state.frame に 1 を足し、運動の変数を求めてください",
                "no object moves: idle() adds 1 to state.frame and computes the motion parameters",
            ),
        ));
    }
    (Ok(AnimationData { objects, periods: periods_text(spec) }), notes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::glam::{Mat4, Vec3};
    use cg_harness::{StudentNumber, TableVersion, VariantRng};

    // --- a3 and a2 -------------------------------------------------------------------------

    #[test]
    fn the_camera_comes_off_the_front_of_a_draw() {
        let mut gl = Gl::new();
        gl.translate(0.0, 0.0, -15.0);
        gl.rotate(30.0, 1.0, 0.0, 0.0);
        gl.translate(1.0, 2.0, 3.0);
        gl.draw("a", &cg_core::shapes::lecture_pyramid());
        assert_eq!(model_product_of(&gl.draws()[0]).numeric(), "T(1, 2, 3)");
        // No camera in front: V⁻¹ times the whole product, still model → world.
        let mut gl = Gl::new();
        gl.translate(1.0, 2.0, 3.0);
        gl.draw("a", &cg_core::shapes::lecture_pyramid());
        let m = model_product_of(&gl.draws()[0]);
        assert!(m.numeric().starts_with("V⁻¹ · T(1, 2, 3)"), "{}", m.numeric());
        assert!(name_matches("物体 2", "object 2") && name_matches("Object_2", "object 2"));
        assert!(!name_matches("object 12", "object 2"));
    }

    /// Object 1 spins about Y at (1, 1, 0), once in 2 s; object 2 orbits, but is never drawn.
    fn a3_spec() -> crate::Spec {
        let object = |name: &str, motion| {
            crate::new_object(name, crate::Shape::Sphere { radius: 0.3 }, [1.0; 3], motion)
        };
        crate::Spec {
            objects: vec![
                object(
                    "object 1",
                    Motion::Spin {
                        position: [1.0, 1.0, 0.0],
                        axis: WorldAxis::Y,
                        turn: crate::Turn::Ccw,
                        period_s: 2.0,
                    },
                ),
                object(
                    "object 2",
                    Motion::Orbit {
                        center: [0.0, 1.0, 0.0],
                        radius: 2.0,
                        turn: crate::Turn::Cw,
                        period_s: 1.0,
                    },
                ),
            ],
            unit_s: 1.0,
        }
    }

    fn a3_idle(_: &crate::Spec, state: &mut crate::State) {
        state.frame += 1;
        state.params[0] = (360.0 * (state.frame % 120) as f64 / 120.0) as f32;
    }

    /// The course's camera, then object 1 only, with plain glTranslatef / glRotatef numbers.
    fn a3_display(_: &crate::Spec, state: &crate::State, gl: &mut cg_student::gl::Gl) {
        gl.load_identity();
        gl.translate(0.0, 0.0, -15.0);
        gl.rotate(30.0, 1.0, 0.0, 0.0);
        gl.light_position(0, [10.0, 10.0, 10.0, 1.0]);
        gl.push_matrix();
        gl.translate(1.0, 1.0, 0.0);
        gl.rotate(state.params[0], 0.0, 1.0, 0.0);
        gl.draw("Object_1", &(&cg_core::shapes::lecture_pyramid()).into());
        gl.pop_matrix();
    }

    fn no_warmup(_: &mut cg_student::gl::Gl, _: f64) {}

    #[test]
    fn an_object_not_drawn_is_left_out_and_the_others_derive() {
        let spec = a3_spec();
        let imp = crate::Impl { warmup_display: no_warmup, idle: a3_idle, display: a3_display };
        let (result, notes) = animation_part(&spec, &imp);
        let data = result.unwrap();
        assert_eq!(data.objects.len(), 1);
        assert_eq!(notes.len(), 1);
        assert_eq!(notes[0].task, "a3.t2");
        assert!(notes[0].why.en.contains("\"object 2\" is not drawn"), "{:?}", notes[0]);
        let times = animation_times(&spec);
        let (name, matrices) = &data.objects[0];
        assert_eq!(name, "object 1");
        for (m, &t) in matrices.iter().zip(&times) {
            // By hand: T(1, 1, 0) · Ry(360°·t/2), the angle in [0, 360).
            let angle = (180.0 * t).rem_euclid(360.0) as f32;
            let expected = Mat4::from_translation(Vec3::new(1.0, 1.0, 0.0))
                * Mat4::from_rotation_y(angle.to_radians());
            assert!(matrices_close(&m.numeric.matrix().unwrap(), &expected), "{}", m.numeric);
            assert_eq!(m.symbolic.symbolic(), "T(1, 1, 0) · Ry(theta_1)");
            assert_eq!(m.symbolic.matrix().unwrap(), m.numeric.matrix().unwrap());
            assert_eq!(m.id, format!("a3.object1.t{}", seconds(t)));
        }
        assert_eq!(matrices[0].variables.len(), 1);
        assert!(matrices[0].variables[0].1.en.contains("360°·u, u = (t mod 2) / 2"));
        assert!(data.periods.en.contains("object 1 : object 2 = 2 : 1"), "{}", data.periods);
    }

    #[test]
    fn stated_times_are_whole_frames_and_the_motion_shows() {
        for number in ["20260002", "20260005", "20260013", "20260023"] {
            let student: StudentNumber = number.parse().unwrap();
            let spec = crate::variant(&mut VariantRng::new(&student, TableVersion::V1, crate::ID));
            let times = animation_times(&spec);
            assert_eq!(times.len(), 3, "{times:?}");
            assert_eq!(times[0], 0.0);
            for &t in &times[1..] {
                assert!(t > 0.0 && (t * 4.0).fract() == 0.0, "{t}");
                for i in 0..spec.objects.len() {
                    let d = pose_distance(
                        crate::expected_model(&spec, i, frame_of(t)),
                        crate::expected_model(&spec, i, 0),
                    );
                    assert!(d > 0.1, "{number}: object {i} barely moves by t = {t}: {d}");
                }
            }
            assert!(animation_probe(&spec).is_some(), "{number}");
        }
    }
}
