//! # 課題 2: 視点操作インターフェースの拡張 / Assignment 2: the camera interface
//!
//! Your own mouse operations are in your assignment text (`cargo run --release -- assignment
//! --only a2`) and in `spec` (`spec.yaw`, `spec.pitch`, `spec.distance`, `spec.pan`). You write
//! the three parts of the sample program that change:
//!
//! | task | function | the sample program's |
//! |---|---|---|
//! | a2.t1 | [`motion`] | `motion()`: the variables change while a button is dragged |
//! | a2.t2 | [`camera`] | the view transform at the top of `display()` |
//! | a2.t3 | [`display`] | `display()`: identity, camera, light, objects |
//!
//! Each function starts as a stub that runs (so `view a2` still opens), with the line
//! `cg_student::not_started("a2.t1");`: while it is there, `check a2` says that task is "not done
//! yet". **Delete that line when you start the function**; from then on the checks judge it.
//!
//! 自分のマウス操作は課題文（`cargo run --release -- assignment --only a2`）と `spec` にあります。
//! サンプルプログラムのうち変更する 3 か所を書きます。確かめ方: `cargo run --release -- check a2`、
//! 絵で見る: `cargo run --release -- view a2`。各関数の最初の行
//! `cg_student::not_started("a2.t1");` は「まだ手を付けていない」印です。この行があるあいだ、
//! チェックは「まだです」になります。書き始めたらこの行を消してください。

use cg_student::a2::{CameraState, Drag, Spec};
use cg_student::gl::Gl;
// What your code will need: buttons and directions (a2.t1), the light and the objects (a2.t3).
#[allow(unused_imports)]
use cg_student::a2::{DragAxis, LIGHT0_POSITION, MouseButton, draw_course_objects};

/// **a2.t1** — GLUT's `motion()`: changes the camera variables in `state` for one `drag`, as
/// your spec says.
///
/// - `drag.button` and `drag.shift`: the button held and whether Shift was held. An operation
///   applies only when **both** match its `gesture` (a Shift + left drag is not a left drag).
/// - `drag.dx` (pixels to the right) and `drag.dy` (pixels **down**) since the last call.
/// - Each operation: `variable += per_px * dx` (or `dy`, by its `axis`); `per_px` carries the
///   sign. Degrees for the angles (no radians anywhere).
/// - Then `camera_yaw` wraps into `[0, 360)` (360 → 0, −1 → 359); `camera_pitch` is clamped to
///   `[spec.pitch_min, spec.pitch_max]`, `camera_distance` to
///   `[spec.distance_min, spec.distance_max]`, the target to `[−limit, limit]`.
/// - A drag that is no operation's changes nothing. A diagonal drag changes both variables of
///   its button (dx one, dy the other): no `else if`.
///
/// Hint: the sample's right-drag is
/// `if drag.button == MouseButton::Right && !drag.shift { state.camera_pitch -= 1.0 * drag.dy; }`
/// then `state.camera_pitch = state.camera_pitch.clamp(-90.0, 0.0);`. Write one such block per
/// variable, with your numbers (or with `spec.pitch.per_px`, …). `rem_euclid(360.0)` wraps.
///
/// **a2.t1** — GLUT の `motion()`: ドラッグ 1 回分だけ、仕様どおりに `state` の変数を変えます。
/// ボタン（`drag.button`）と Shift（`drag.shift`）の両方が操作の `gesture` と一致したときだけ、
/// `変数 += per_px * dx`（または `dy`）。`dx` は右、`dy` は**下**が正。角度は度。そのあと
/// `camera_yaw` は `[0, 360)` に折り返し、ほかは範囲に収めます（`clamp`）。斜めのドラッグでは dx と
/// dy の両方が効きます（`else if` にしない）。
pub fn motion(spec: &Spec, state: &mut CameraState, drag: &Drag) {
    cg_student::not_started("a2.t1"); // 書き始めたらこの行を消す / delete it when you start
    // TODO a2.t1: change the variables for this drag (see the comment above).
    // While this is empty the camera does not move when you drag.
}

/// **a2.t2** — the view transform (ワールド座標系 → カメラ座標系): multiply the current matrix by
/// the camera's transform with `gl.translate(x, y, z)` (glTranslatef) and
/// `gl.rotate(angle_deg, x, y, z)` (glRotatef, degrees). Do not call `gl.load_identity()` here
/// ([`display`] does).
///
/// The camera looks at the target `(target_x, 0, target_z)` from `camera_distance` away, raised
/// by `camera_pitch` (negative: from above) and turned by `camera_yaw` about +Y. Every pitch
/// must work, ±90° included (no look-at with an up vector).
///
/// Hint: the sample has `glTranslatef(0, 0, -camera_distance)` then
/// `glRotatef(-camera_pitch, 1, 0, 0)`. The yaw turns about Y; the target's translation moves the
/// target to the origin. Which factor comes first? The call made last acts on the vertices
/// first. Your report writes exactly this product (the kit prints it into your report:
/// `{{a2.matrices}}`).
///
/// **a2.t2** — 視点の変換: `gl.translate`（glTranslatef）と `gl.rotate`（glRotatef、角度は度）で、
/// 現在の行列に視点の変換を掛けます（`gl.load_identity()` は display で呼ぶのでここでは呼ばない）。
/// サンプルは `glTranslatef(0, 0, -camera_distance)` → `glRotatef(-camera_pitch, 1, 0, 0)`。
/// これに camera_yaw（Y 軸まわり）と注視点の平行移動を加えます。後に呼んだ変換ほど先に頂点に
/// 作用します。camera_pitch = ±90° でも正しく動くこと。
pub fn camera(gl: &mut Gl, state: &CameraState) {
    cg_student::not_started("a2.t2"); // 書き始めたらこの行を消す / delete it when you start
    // TODO a2.t2: the view transform. While this is empty the camera sits at the origin.
}

/// **a2.t3** — `display()`, called every frame: start from the identity
/// (`gl.load_identity()`), set the camera ([`camera`]), then the light
/// (`gl.light_position(0, LIGHT0_POSITION)`, glLightfv(GL_LIGHT0, GL_POSITION, …)), then draw
/// the course's ground and pyramid (`draw_course_objects(gl)`).
///
/// OpenGL stores a light position multiplied by the model-view matrix *of the moment*: set
/// after the camera, the light stays fixed in the world; set before it, the light moves with
/// the camera. Leave the matrix stack as deep as you found it (every push with its pop).
///
/// **a2.t3** — 毎フレーム呼ばれる `display()`: 単位行列（`gl.load_identity()`）→ 視点の変換
/// （[`camera`]）→ 光源の位置（`gl.light_position(0, LIGHT0_POSITION)`）→ 地面と四角すい
/// （`draw_course_objects(gl)`）。光源の位置はその時点のモデルビュー行列を掛けて保存されるので、
/// 視点の変換の後に設定するとワールド座標系に固定されます。
pub fn display(gl: &mut Gl, state: &CameraState) {
    cg_student::not_started("a2.t3"); // 書き始めたらこの行を消す / delete it when you start
    // TODO a2.t3: identity, camera, light, objects. While this is empty nothing is drawn.
    gl.load_identity();
}

/// The functions of this module, for the checks and the view.
#[must_use]
pub fn implementation() -> cg_student::a2::Impl {
    cg_student::a2::Impl { motion, camera, display }
}
