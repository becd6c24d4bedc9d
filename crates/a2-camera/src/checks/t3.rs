//! Checks of a2.t3, `display()`: the light's eye-space position is `V · (10, 10, 10, 1)` (set
//! after the camera), the ground is drawn with `V` and the pyramid with `V · T(0, 1, 0)` (the
//! course's positions, stated here independently of [`crate::draw_course_objects`]), push and
//! pop are balanced without GL errors, and each frame starts from the identity.

use cg_core::glam::{Mat4, Vec3, Vec4};
use cg_core::lang::Lang;
use cg_core::transform::translate;
use cg_harness::Text;
use cg_harness::check::Failure;
use cg_harness::text::t;
use cg_student::gl::Gl as Recorder;

use crate::oracle::{self, matrices_close};
use crate::show;
use crate::{CameraState, Gl, Impl, LIGHT0_POSITION, Spec};

use super::student_view;

/// The states the display checks draw: the spec's start and two turned ones.
fn display_states(spec: &Spec) -> Vec<CameraState> {
    let pan = spec.pan.is_some();
    let target = |x: f32, z: f32| if pan { (x, z) } else { (0.0, 0.0) };
    let s = |yaw: f32, pitch: f32, distance: f32, (target_x, target_z): (f32, f32)| CameraState {
        camera_yaw: yaw,
        camera_pitch: pitch,
        camera_distance: distance,
        target_x,
        target_z,
    };
    vec![
        spec.start,
        s(120.0, -50.0, 9.0, target(1.0, -1.0)),
        s(250.0, -15.0, 20.0, target(-2.0, 0.5)),
    ]
}

/// One frame of the student's display() on a fresh context.
fn frame(imp: &Impl, s: &CameraState) -> Gl {
    let mut rec = Recorder::new();
    display(imp, &mut rec, s);
    crate::replay(&rec)
}

/// The student's display() at `s` on `gl` (a panic names the state: [`super::calling`]).
fn display(imp: &Impl, gl: &mut Recorder, s: &CameraState) {
    super::calling(|| format!("display(gl, &{s:?})"), || (imp.display)(gl, s));
}

/// Component-wise within `1e-4 · (1 + |expected|)`.
fn vec_close(a: Vec4, e: Vec4) -> bool {
    (a - e).abs().cmple(1e-4 * (Vec4::ONE + e.abs())).all()
}

/// The light's course position as a vector.
fn light0() -> Vec4 {
    Vec4::from_array(LIGHT0_POSITION)
}

/// The pyramid's model transform in the course: glTranslatef(0, 1, 0).
fn pyramid_model() -> Mat4 {
    translate(Vec3::new(0.0, 1.0, 0.0))
}

/// A note when the student's own camera() differs from the spec's view: the display checks
/// compare with the spec's view, so a2.t2 comes first.
fn camera_note(imp: &Impl, s: &CameraState) -> Option<Text> {
    match student_view(imp, s) {
        Ok(c) if matrices_close(&c, &oracle::view_matrix(s)) => None,
        _ => Some(t(
            "あなたの camera()（a2.t2）がまだ仕様の視点の変換になっていません。先に a2.t2 を直してください",
            "your camera() (a2.t2) does not give the spec's view yet: fix a2.t2 first",
        )),
    }
}

/// a2.t3.light: GL_LIGHT0 at (10, 10, 10, 1), stored in eye space as `V · (10, 10, 10, 1)`.
pub(super) fn light_after_camera(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let with_target = spec.pan.is_some();
    for s in display_states(spec) {
        let gl = frame(imp, &s);
        let at = show::state(&s, with_target);
        let v = oracle::view_matrix(&s);
        let p = light0();
        let expected = v * p;
        let Some(light) = gl.lights().iter().find(|l| l.light == 0) else {
            let others: Vec<String> =
                gl.lights().iter().map(|l| format!("GL_LIGHT{}", l.light)).collect();
            return Err(Failure::new(
                Text::new(
                    format!("カメラ座標系で GL_LIGHT0 の位置が {}", show::vec4(expected)),
                    format!("GL_LIGHT0 at {} in camera space", show::vec4(expected)),
                ),
                if others.is_empty() {
                    t("光源の位置の設定なし", "no light position set")
                } else {
                    let others = others.join(", ");
                    Text::new(format!("{others} だけ設定"), format!("only {others} set"))
                },
            )
            .at(at)
            .cause(t(
                "display() で光源 0 の位置を設定していません",
                "display() does not set light 0's position",
            ))
            .hint(t(
                "視点の変換のすぐ後に gl.light_position(0, LIGHT0_POSITION); を呼びます（glLightfv(GL_LIGHT0, GL_POSITION, light0_position)）",
                "right after the camera, call gl.light_position(0, LIGHT0_POSITION); (glLightfv(GL_LIGHT0, GL_POSITION, light0_position))",
            )));
        };
        if !vec_close(light.given, p) {
            return Err(Failure::new(
                format!("light0_position = {}", show::vec4(p)),
                format!("light0_position = {}", show::vec4(light.given)),
            )
            .at(at)
            .cause(t(
                "光源の位置がサンプルの (10, 10, 10, 1) ではありません（w = 1 は点光源、w = 0 は平行光源）",
                "the light's position is not the sample's (10, 10, 10, 1) (w = 1: a point light; w = 0: a directional one)",
            ))
            .hint(t("LIGHT0_POSITION を使ってください", "use LIGHT0_POSITION")));
        }
        if vec_close(light.eye, expected) {
            continue;
        }
        let cause = if vec_close(light.eye, p) {
            t(
                "光源の位置を視点の変換の前（または視点の変換なし）で設定しています。OpenGL は glLightfv の時点のモデルビュー行列を位置に掛けて保存するので、単位行列のときに設定すると光源はカメラに固定され、視点を動かすと光源も一緒に動きます。視点の変換の後に設定すると V · (10, 10, 10, 1) となり、ワールド座標系に固定されます",
                "the light is set before the camera (or without one). OpenGL multiplies the position by the model-view matrix current at glLightfv and keeps the result; set under the identity, the light is fixed to the camera and moves with it whenever the view changes. Set after the view transform it is stored as V · (10, 10, 10, 1): fixed in the world",
            )
        } else if vec_close(light.eye, v * pyramid_model() * p) {
            t(
                "光源を四角すいの glTranslatef(0, 1, 0) の後に設定しています。視点の変換の直後、物体の変換の前に設定します",
                "the light is set after the pyramid's glTranslatef(0, 1, 0): set it right after the view transform, before any object's transform",
            )
        } else if let Some(note) = camera_note(imp, &s) {
            note
        } else {
            t(
                "光源の位置を設定したときのモデルビュー行列が視点の変換 V ではありません",
                "the model-view matrix when the light is set is not the view transform V",
            )
        };
        let (eye, model_view) = (show::vec4(light.eye), light.model_view.numeric());
        return Err(Failure::new(
            Text::new(
                format!("カメラ座標系での位置 V · (10, 10, 10, 1) = {}", show::vec4(expected)),
                format!("camera-space position V · (10, 10, 10, 1) = {}", show::vec4(expected)),
            ),
            Text::new(
                format!("{eye}（設定したときのモデルビュー行列は {model_view}）"),
                format!("{eye}, set when the model-view matrix was {model_view}"),
            ),
        )
        .at(at)
        .cause(cause)
        .hint(t(
            "display() の順序: gl.load_identity() → camera(gl, state) → gl.light_position(0, LIGHT0_POSITION) → draw_course_objects(gl)",
            "the order in display(): gl.load_identity() → camera(gl, state) → gl.light_position(0, LIGHT0_POSITION) → draw_course_objects(gl)",
        )));
    }
    Ok(())
}

/// a2.t3.objects: one ground drawn with `V`, one pyramid with `V · T(0, 1, 0)`.
pub(super) fn objects_in_place(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let with_target = spec.pan.is_some();
    for s in display_states(spec) {
        let gl = frame(imp, &s);
        let v = oracle::view_matrix(&s);
        for (name, name_ja, model, model_text) in [
            ("ground", "地面", Mat4::IDENTITY, "V"),
            ("pyramid", "四角すい", pyramid_model(), "V · T(0, 1, 0)"),
        ] {
            let draws: Vec<_> = gl.draws().iter().filter(|d| d.name == name).collect();
            let state = show::state(&s, with_target);
            let at = Text::new(format!("{name_ja}、{state}"), format!("{name}, {state}"));
            if draws.len() != 1 {
                let n = draws.len();
                return Err(Failure::new(
                    Text::new(format!("{name_ja}を 1 回描く"), format!("{name} drawn once")),
                    Text::new(
                        format!("{name_ja}を {n} 回描いた"),
                        format!("{name} drawn {n} times"),
                    ),
                )
                .at(at)
                .cause(t(
                    "地面と四角すいは draw_course_objects(gl) で 1 回ずつ描きます",
                    "draw_course_objects(gl) draws the ground and the pyramid once each",
                ))
                .hint(t(
                    "display() の最後で draw_course_objects(gl) を 1 回呼びます",
                    "call draw_course_objects(gl) once, at the end of display()",
                )));
            }
            let d = draws[0];
            let expected = v * model;
            if matrices_close(&d.matrix, &expected) {
                continue;
            }
            let cause = if matrices_close(&d.matrix, &model) {
                t(
                    "物体が視点の変換なしに描かれています。視点の変換（camera）は物体を描く前に設定します",
                    "the object is drawn without the view transform: set the camera before drawing",
                )
            } else if let Some(note) = camera_note(imp, &s) {
                note
            } else {
                t(
                    "物体を描くときのモデルビュー行列が 視点の変換 × 物体の変換 になっていません（視点の変換の後、物体の前に余計な変換がありませんか）",
                    "the model-view matrix at the draw is not view × model (an extra transform between the camera and the objects?)",
                )
            };
            return Err(Failure::new(
                format!("{model_text} = {}", show::matrix(&expected)),
                format!("{} = {}", d.model_view.numeric(), show::matrix(&d.matrix)),
            )
            .at(at)
            .cause(cause)
            .hint(t(
                "display() の順序: gl.load_identity() → camera(gl, state) → 光源 → draw_course_objects(gl)",
                "the order in display(): gl.load_identity() → camera(gl, state) → the light → draw_course_objects(gl)",
            )));
        }
    }
    Ok(())
}

/// a2.t3.stack: a frame draws something, ends at stack depth 1, and records no GL error.
pub(super) fn stack_balanced(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let s = spec.start;
    let gl = frame(imp, &s);
    let at = show::state(&s, spec.pan.is_some());
    if gl.draws().is_empty() {
        return Err(Failure::new(
            t("地面と四角すいを描く", "the ground and the pyramid drawn"),
            t("何も描かれていない", "nothing drawn"),
        )
        .at(at)
        .cause(t("display() がまだ何も描いていません", "display() draws nothing yet"))
        .hint(t(
            "display() の最後で draw_course_objects(gl) を呼びます",
            "call draw_course_objects(gl) at the end of display()",
        )));
    }
    if let Some(e) = gl.errors().first() {
        return Err(Failure::new(
            t("GL のエラーなし", "no GL error"),
            Text::new(
                format!("{}: {}", e.function, e.error.message(Lang::Ja)),
                format!("{}: {}", e.function, e.error.message(Lang::En)),
            ),
        )
        .at(Text::new(
            format!("{at}; display() の {} 番目の呼び出し", e.call + 1),
            format!("{at}; call {} of display()", e.call + 1),
        ))
            .cause(Text::new(
                format!("{} がエラーです: {}", e.function, e.error.message(Lang::Ja)),
                format!("{} is an error: {}", e.function, e.error.message(Lang::En)),
            ))
            .hint(t(
                "gl.push_matrix() と gl.pop_matrix() を対にし、回転軸に 0 ベクトルを使わないでください",
                "pair every gl.push_matrix() with a gl.pop_matrix(), and never rotate about a zero axis",
            )));
    }
    if gl.depth() != 1 {
        return Err(Failure::new(
            t(
                "display() の終わりで行列スタックの深さが 1",
                "matrix stack depth 1 at the end of display()",
            ),
            Text::new(format!("深さ {}", gl.depth()), format!("depth {}", gl.depth())),
        )
            .at(at)
            .cause(t(
                "gl.pop_matrix() と対になっていない gl.push_matrix() があります。フレームごとに行列スタックが深くなり、やがてオーバーフローします",
                "a push without its pop: the matrix stack grows every frame until it overflows",
            ))
            .hint(t(
                "gl.push_matrix() ごとに対応する gl.pop_matrix() を呼びます",
                "match every gl.push_matrix() with a gl.pop_matrix()",
            )));
    }
    Ok(())
}

/// The ground's matrix and light 0's eye position of a frame, if drawn and set.
fn fingerprint(gl: &Gl, from_draw: usize) -> (Option<Mat4>, Option<Vec4>) {
    let ground = gl.draws()[from_draw..].iter().find(|d| d.name == "ground").map(|d| d.matrix);
    let light = gl.lights().iter().find(|l| l.light == 0).map(|l| l.eye);
    (ground, light)
}

/// a2.t3.identity: a frame drawn over a leftover model-view matrix, and a second frame on the
/// same context, are the same as a frame on a fresh context.
pub(super) fn starts_from_identity(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let s = display_states(spec)[1];
    let at = show::state(&s, spec.pan.is_some());
    let fresh = frame(imp, &s);
    let (Some(ground), light) = fingerprint(&fresh, 0) else {
        return Err(Failure::new(
            t("地面を描く", "the ground drawn"),
            t("地面が描かれていない", "no ground drawn"),
        )
        .at(at)
        .cause(t("display() がまだ地面を描いていません", "display() does not draw the ground yet"))
        .hint(t(
            "display() の最後で draw_course_objects(gl) を呼びます",
            "call draw_course_objects(gl) at the end of display()",
        )));
    };
    // The previous frame left a transform on the stack; a second frame runs on the same context.
    let mut leftover = Recorder::new();
    leftover.translate(3.0, -2.0, 7.0);
    leftover.rotate(25.0, 0.0, 0.0, 1.0);
    display(imp, &mut leftover, &s);
    let leftover = crate::replay(&leftover);
    let mut twice = Recorder::new();
    display(imp, &mut twice, &s);
    let first_draws = crate::replay(&twice).draws().len();
    display(imp, &mut twice, &s);
    let twice = crate::replay(&twice);
    for (gl, from, situation) in [
        (
            &leftover,
            0,
            t(
                "モデルビュー行列が T(3, -2, 7) · Rz(25°) のまま描いたとき",
                "drawn after the model-view was T(3, -2, 7) · Rz(25°)",
            ),
        ),
        (
            &twice,
            first_draws,
            t(
                "同じコンテキストで 2 フレーム目を描いたとき",
                "the second frame drawn on the same context",
            ),
        ),
    ] {
        let (g, l) = fingerprint(gl, from);
        let same_ground = g.is_some_and(|g| matrices_close(&g, &ground));
        let same_light = match (l, light) {
            (Some(a), Some(b)) => vec_close(a, b),
            (None, None) => true,
            _ => false,
        };
        if same_ground && same_light {
            continue;
        }
        let ground = show::matrix(&ground);
        return Err(Failure::new(
            Text::new(
                format!("地面の行列 {ground}（新しいコンテキストで描いたときと同じ）"),
                format!("ground at {ground} (as on a fresh context)"),
            ),
            g.map_or_else(
                || t("地面が描かれていない", "no ground drawn"),
                |g| {
                    let g = show::matrix(&g);
                    Text::new(format!("地面の行列 {g}"), format!("ground at {g}"))
                },
            ),
        )
        .at(Text::new(format!("{}; {at}", situation.ja), format!("{}; {at}", situation.en)))
        .cause(t(
            "display() が gl.load_identity() で始まっていません。GLUT は display() を毎フレーム呼ぶので、前のフレームの行列に視点の変換が掛け重なり、視点がずれていきます",
            "display() does not start with gl.load_identity(): GLUT calls display() every frame, so the view transform piles up on the previous frame's matrix and the view drifts",
        ))
        .hint(t(
            "display() の最初で gl.load_identity() を呼びます（glLoadIdentity）",
            "call gl.load_identity() first in display() (glLoadIdentity)",
        )));
    }
    Ok(())
}
