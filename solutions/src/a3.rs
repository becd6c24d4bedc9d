//! # 課題3 アニメーション / Assignment 3: animation
//!
//! 指定された通りの、複数の物体のアニメーションを実現する。Your objects, their motions and
//! periods are in your assignment text: `cargo run --release -- assignment --only a3`.
//!
//! The course's program structure, kept here:
//!
//! - `idle()` changes the motion parameters (運動を表す媒介変数) — here [`idle`] advances one
//!   frame (1/60 s) and computes them into `state.params`;
//! - `display()` sets each object's transform from them and draws it — here [`display`], with
//!   `gl` standing for OpenGL: `gl.translate` is glTranslatef, `gl.rotate` glRotatef (degrees),
//!   `gl.push_matrix` / `gl.pop_matrix` glPushMatrix / glPopMatrix, `gl.light_position(0, …)`
//!   glLightfv(GL_LIGHT0, GL_POSITION, …), `gl.color` glColor3f, `gl.draw(name, &mesh)` draws a
//!   polygon model.
//!
//! Check your work with `cargo run --release -- check a3`, look at it with
//! `cargo run --release -- view a3 --time 1.5` (any time in seconds).
//!
//! Each function starts as a stub that runs (so the view still draws the ground), with the line
//! `cg_student::not_started("a3.t1");`: while it is there, `check a3` says that task is "not done
//! yet". **Delete that line when you start the function**; from then on the checks judge it.
//! 各関数の最初の行 `cg_student::not_started(…);` は「まだ手を付けていない」印です。この行がある
//! あいだ、チェックは「まだです」になります。書き始めたらこの行を消してください。
//!
//! For the report, a transform can carry the variable's name: `gl.mult(Factor::rotate(Axis::Y,
//! Param::sym("theta_1", theta1)))` does what `gl.rotate(theta1, 0.0, 1.0, 0.0)` does and prints
//! as `Ry(theta_1)`.

use cg_student::a3::{Spec, State};
use cg_student::gl::Gl;

// BEGIN SOLUTION
use std::f64::consts::TAU;

use cg_student::a3::{Motion, Object, WorldAxis, warmup_box};
use cg_student::product::{Axis, Factor, Param};
// END SOLUTION
// BEGIN STUB
// // You will need some of these; remove `allow` once you use them.
// #[allow(unused_imports)]
// use cg_student::a3::{Motion, Object, WorldAxis, warmup_box};
// #[allow(unused_imports)]
// use cg_student::product::{Axis, Factor, Param};
// END STUB

/// **a3.t0 — 演習課題 (warm-up)**: draws the three boxes at time `t` seconds.
///
/// When this is called, the camera (`T(0, 0, -15) · Rx(30°)`) and the light are already set. Draw
/// three boxes 1.2 × 0.6 × 0.6, named `"box 1"`, `"box 2"`, `"box 3"`
/// (`let mesh = warmup_box();`, the box centred on its origin):
///
/// - box 1 (回転運動): at (−3, 1, 0), turning about the Y axis, one turn in 4 s,
///   counter-clockwise seen from above: `θ = 360°·t/4`;
/// - box 2 (往復回転運動): at (0, 1, 0), turning back and forth about the Z axis:
///   `θ = 30°·sin(360°·t/2)`;
/// - box 3 (放物往復移動運動): back and forth along X between (2, 0.3, 0) and (4, 0.3, 0), there
///   in 1 s and back in 1 s, hopping 1.5 high on the way: the offset from x = 3 goes linearly
///   −1 → 1 → −1 and the height is `1.5·(1 − offset²)` above y = 0.3.
///
/// The slide's question: where do glPushMatrix / glPopMatrix go (before and after each box), or
/// neither? Leave the stack as you found it (as many pops as pushes).
///
/// 演習課題: カメラと光源は設定済みです。3 つの直方体を描き、glPushMatrix / glPopMatrix をどこに
/// 入れるか考えてください。
///
/// Hint: `(t / 4.0).rem_euclid(1.0)` is how far (0 ≤ u < 1) into its 4-second period box 1 is.
pub fn warmup_display(gl: &mut Gl, t: f64) {
    // BEGIN SOLUTION
    let mesh = warmup_box();

    // Box 1: rotation about Y, period 4 s.
    gl.push_matrix();
    let theta1 = 360.0 * (t / 4.0).rem_euclid(1.0);
    gl.translate(-3.0, 1.0, 0.0);
    gl.rotate(theta1 as f32, 0.0, 1.0, 0.0);
    gl.color(1.0, 0.6, 0.2);
    gl.draw("box 1", &mesh);
    gl.pop_matrix();

    // Box 2: back and forth about Z, ±30°, period 2 s.
    gl.push_matrix();
    let theta2 = 30.0 * (TAU * (t / 2.0).rem_euclid(1.0)).sin();
    gl.translate(0.0, 1.0, 0.0);
    gl.rotate(theta2 as f32, 0.0, 0.0, 1.0);
    gl.color(0.3, 0.5, 1.0);
    gl.draw("box 2", &mesh);
    gl.pop_matrix();

    // Box 3: back and forth along X over a parabola, period 2 s.
    gl.push_matrix();
    let u = (t / 2.0).rem_euclid(1.0);
    let w = if u < 0.5 { 2.0 * u } else { 2.0 - 2.0 * u }; // 0 → 1 → 0
    let x3 = 2.0 * w - 1.0; // −1 → 1 → −1
    let y3 = 1.5 * (1.0 - x3 * x3);
    gl.translate((3.0 + x3) as f32, (0.3 + y3) as f32, 0.0);
    gl.color(0.9, 0.3, 0.4);
    gl.draw("box 3", &mesh);
    gl.pop_matrix();
    // END SOLUTION
    // BEGIN STUB
    // cg_student::not_started("a3.t0"); // 書き始めたらこの行を消す / delete it when you start
    // // TODO a3.t0: draw "box 1", "box 2" and "box 3" (nothing is drawn yet).
    // END STUB
}

/// **a3.t1 — idle()**: advances the animation by one frame (1/60 s) and computes every object's
/// motion parameters (運動を表す媒介変数) into `state.params` for [`display`].
///
/// - Add 1 to `state.frame` first; the time of the new frame is `t = state.frame / 60` s
///   (`state.time_s()`).
/// - Then compute each parameter *from the frame count*, reduced by the object's period (in
///   frames `P = 60·T`, `motion.period_frames()`): the phase `u = (frame % P) / P` (0 ≤ u < 1),
///   then `θ = 360°·u` for a turn, `θ = A·sin(360°·u)` for a swing, the offset and height for a
///   hop (see `cg_student::a3::Motion`'s formulas). Keep the units: degrees for angles.
/// - Do **not** add a step to an f32 angle every frame: after 10⁶ frames the rounding errors add
///   up to a visible drift (check `a3.t1.drift`). Do the arithmetic in u64 and f64 and store the
///   result as f32.
/// - `state.params` (8 numbers) is yours to lay out; say in the report which slot is which
///   variable (θ1, θ2, …).
///
/// idle(): フレームを 1 つ進め（state.frame += 1）、各物体の媒介変数を state.frame から求めて
/// state.params に入れる。f32 の角度に毎フレーム足し込まないこと（10⁶ フレーム後にずれる）。
///
/// Hint: `let p = object.motion.period_frames(); let u = (state.frame % p) as f64 / p as f64;`
pub fn idle(spec: &Spec, state: &mut State) {
    // BEGIN SOLUTION
    state.frame += 1;
    for (i, object) in spec.objects.iter().enumerate() {
        // The phase u ∈ [0, 1), exact from the integer frame count: never accumulated.
        let p = object.motion.period_frames();
        let u = (state.frame % p) as f64 / p as f64;
        let (a, b) = match object.motion {
            Motion::Spin { turn, .. }
            | Motion::Orbit { turn, .. }
            | Motion::Satellite { turn, .. } => (f64::from(turn.sign()) * 360.0 * u, 0.0),
            Motion::Swing { amplitude_deg, .. } => {
                (f64::from(amplitude_deg) * (TAU * u).sin(), 0.0)
            }
            Motion::Hop { span, height, .. } => {
                let w = if u < 0.5 { 2.0 * u } else { 2.0 - 2.0 * u }; // 0 → 1 → 0
                let s = f64::from(span) * (w - 0.5); // −span/2 → span/2 → −span/2
                let half = f64::from(span) / 2.0;
                (s, f64::from(height) * (1.0 - (s / half) * (s / half)))
            }
        };
        // params[2i]: θ (degrees) or a hop's offset; params[2i + 1]: a hop's height.
        state.params[2 * i] = a as f32;
        state.params[2 * i + 1] = b as f32;
    }
    // END SOLUTION
    // BEGIN STUB
    // cg_student::not_started("a3.t1"); // 書き始めたらこの行を消す / delete it when you start
    // // TODO a3.t1: advance state.frame and compute state.params (nothing moves yet).
    // END STUB
}

/// **a3.t2 — display()**: draws the frame of `state`.
///
/// 1. The camera: `gl.load_identity()`, `gl.translate(0.0, 0.0, -15.0)`,
///    `gl.rotate(30.0, 1.0, 0.0, 0.0)` (ワールド座標系→カメラ座標系, common to every object).
/// 2. The light, right after the camera so it stays fixed in the world:
///    `gl.light_position(0, [10.0, 10.0, 10.0, 1.0])`.
/// 3. Each object (モデル座標系→ワールド座標系): `gl.push_matrix()`, its translations and
///    rotations from `state.params`, `gl.color(r, g, b)` with `object.color`,
///    `gl.draw(&object.name, &object.mesh)`, `gl.pop_matrix()`. Do not scale.
/// 4. The child (`Motion::Satellite`) moves in its parent's coordinate system: draw it after the
///    parent's transforms and *before* the parent's `gl.pop_matrix()`, inside its own
///    push/pop: `…parent… · Ry(θ) · T(0, 0, r)`.
///
/// The checks compare each object's model-view matrix at its draw with `T(0, 0, -15) · Rx(30°) ·
/// (your spec's motion)` at sampled times.
///
/// display(): 視点の変換、光源の位置、各物体（glPushMatrix → 変換 → 描画 → glPopMatrix）。
/// 子は親の変換の後、親の glPopMatrix の前に描く。
///
/// Hint: `let [x, y, z] = position; gl.translate(x, y, z);` — glam-free. For the report, prefer
/// `gl.mult(Factor::rotate(Axis::Y, Param::sym("theta_1", theta)))` to `gl.rotate`.
pub fn display(spec: &Spec, state: &State, gl: &mut Gl) {
    // BEGIN SOLUTION
    gl.load_identity();
    gl.translate(0.0, 0.0, -15.0); // T(0, 0, -camera_distance)
    gl.rotate(30.0, 1.0, 0.0, 0.0); // Rx(-camera_pitch), camera_pitch = -30°
    gl.light_position(0, [10.0, 10.0, 10.0, 1.0]); // after the camera: fixed in the world

    for (i, object) in spec.objects.iter().enumerate() {
        if object.motion.parent().is_some() {
            continue; // drawn inside its parent's push/pop below
        }
        gl.push_matrix();
        place(gl, state, i, object);
        draw(gl, object);
        for c in spec.children(i) {
            gl.push_matrix();
            place(gl, state, c, &spec.objects[c]);
            draw(gl, &spec.objects[c]);
            gl.pop_matrix();
        }
        gl.pop_matrix();
    }
    // END SOLUTION
    // BEGIN STUB
    // cg_student::not_started("a3.t2"); // 書き始めたらこの行を消す / delete it when you start
    // // TODO a3.t2: camera, light, then every object (nothing is drawn yet).
    // END STUB
}
// BEGIN SOLUTION

/// Object `i`'s own transform (relative to its parent for a child), its variables named for
/// the report.
fn place(gl: &mut Gl, state: &State, i: usize, object: &Object) {
    let n = i + 1;
    let (a, b) = (state.params[2 * i], state.params[2 * i + 1]);
    let theta = Param::sym(format!("theta_{n}"), a);
    let axis = |w: WorldAxis| match w {
        WorldAxis::X => Axis::X,
        WorldAxis::Y => Axis::Y,
        WorldAxis::Z => Axis::Z,
    };
    match object.motion {
        Motion::Spin { position: [x, y, z], axis: w, .. } => {
            gl.translate(x, y, z);
            gl.mult(Factor::rotate(axis(w), theta));
        }
        Motion::Swing { pivot: [x, y, z], axis: w, arm, .. } => {
            gl.translate(x, y, z);
            gl.mult(Factor::rotate(axis(w), theta));
            if arm != 0.0 {
                gl.translate(0.0, -arm, 0.0);
            }
        }
        Motion::Hop { center: [x, y, z], along, .. } => {
            gl.translate(x, y, z);
            let (s, h) = (Param::sym(format!("s_{n}"), a), Param::sym(format!("y_{n}"), b));
            let zero = Param::num(0.0);
            gl.mult(Factor::Translate(match along {
                WorldAxis::Z => [zero, h, s],
                _ => [s, h, zero],
            }));
        }
        Motion::Orbit { center: [x, y, z], radius, .. } => {
            gl.translate(x, y, z);
            gl.mult(Factor::rotate(Axis::Y, theta));
            gl.translate(0.0, 0.0, radius);
        }
        Motion::Satellite { radius, .. } => {
            gl.mult(Factor::rotate(Axis::Y, theta));
            gl.translate(0.0, 0.0, radius);
        }
    }
}

/// glColor3f and the object's polygon model.
fn draw(gl: &mut Gl, object: &Object) {
    let [r, g, b] = object.color;
    gl.color(r, g, b);
    gl.draw(&object.name, &object.mesh);
}
// END SOLUTION

/// The functions of this module, for the checks and the view.
#[must_use]
pub fn implementation() -> cg_student::a3::Impl {
    cg_student::a3::Impl { warmup_display, idle, display }
}
