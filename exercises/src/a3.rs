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

// You will need some of these; remove `allow` once you use them.
#[allow(unused_imports)]
use cg_student::a3::{Motion, Object, WorldAxis, warmup_box};
#[allow(unused_imports)]
use cg_student::product::{Axis, Factor, Param};

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
    cg_student::not_started("a3.t0"); // 書き始めたらこの行を消す / delete it when you start
    // TODO a3.t0: draw "box 1", "box 2" and "box 3" (nothing is drawn yet).
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
    cg_student::not_started("a3.t1"); // 書き始めたらこの行を消す / delete it when you start
    // TODO a3.t1: advance state.frame and compute state.params (nothing moves yet).
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
    cg_student::not_started("a3.t2"); // 書き始めたらこの行を消す / delete it when you start
    // TODO a3.t2: camera, light, then every object (nothing is drawn yet).
}

/// The functions of this module, for the checks and the view.
#[must_use]
pub fn implementation() -> cg_student::a3::Impl {
    cg_student::a3::Impl { warmup_display, idle, display }
}
