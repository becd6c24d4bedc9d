//! The assignment text of `a2`, like the course's assignment program prints it, in Japanese and
//! English ([`SpecExt::describe`]).

use std::fmt::Write as _;

use cg_core::lang::{Lang, Text, t};

use crate::show;
use crate::{Spec, SpecExt};

/// The assignment text for `spec`, in `lang`: what [`SpecExt::describe`] returns.
pub(crate) fn describe(spec: &Spec, lang: Lang) -> String {
    let mut out = String::new();
    let s = &spec.start;
    let start = show::state(s, spec.pan.is_some());
    let intro = t(
        "2. 視点操作インターフェースの拡張 (a2)\n\n\
         サンプルプログラムの視点操作を拡張し、次のマウス操作でカメラを動かせるようにすること。\n\
         dx, dy は motion() が呼ばれるたびの、前回の位置からのマウスの移動量（ピクセル）: \
         dx は右が正、dy は下が正（GLUT のウィンドウ座標）。\n\n",
        "2. Camera interface (a2)\n\n\
         Extend the sample program's camera so that these mouse operations move it.\n\
         dx and dy are how far the mouse moved since the last call of motion(), in \
         pixels: dx positive to the right, dy positive down (GLUT's window coordinates).\n\n",
    );
    out.push_str(intro.get(lang));
    for (_, text) in spec.variables() {
        let _ = writeln!(out, "  - {}", text.get(lang));
    }
    let unused = show::unused_gestures(spec, lang);
    let not_listed = Text::new(
        format!(
            "  - 上にない組み合わせ（{unused}、Shift の有無の違い、上にない方向）のドラッグでは、どの変数も変わらない。"
        ),
        format!(
            "  - A drag not listed above ({unused}, with Shift where it is not listed or without it where it is, \
             or in a direction not listed) changes no variable."
        ),
    );
    let _ = writeln!(out, "{}", not_listed.get(lang));
    if spec.pan.is_none() {
        let origin = t(
            "  - 注視点は原点 (0, 0, 0) のまま（target_x = target_z = 0）。\n",
            "  - The target stays at the origin (0, 0, 0) (target_x = target_z = 0).\n",
        );
        out.push_str(origin.get(lang));
    }
    let _ = writeln!(out, "  - {}: {start}\n", t("初期値", "At start").get(lang));
    let tasks = t(
        "課題:\n\
                 \x20 a2.t1  motion(spec, state, drag): 上のとおりに変数を変える（範囲の制限と折り返しを含む）。\n\
                 \x20 a2.t2  camera(gl, state): 視点の変換（ワールド座標系 → カメラ座標系）を gl.translate / gl.rotate\n\
                 \x20        （glTranslatef / glRotatef）で設定する。カメラは注視点から camera_distance だけ離れ、\n\
                 \x20        camera_pitch（仰角）と camera_yaw（Y 軸まわり）だけ回った位置から注視点を見る。\n\
                 \x20 a2.t3  display(gl, state): 単位行列 → 視点の変換（camera）→ 光源の位置 (10, 10, 10, 1)\n\
                 \x20        → 地面と四角すい（draw_course_objects）。光源の位置は視点の変換の後に設定して、\n\
                 \x20        ワールド座標系に固定すること。\n\n\
                 レポートに書くこと:\n\
                 \x20 - 視点操作のための変換行列を、回転変換・平行移動変換の積の形で示す（4×4 行列を並べて、\n\
                 \x20   (x, y, z, 1) → (x', y', z', 1)）。どの行列が何をするかも説明する。\n\
                 \x20 - 各変数の説明: どのような操作により、どのように変化する変数か（上の各行、範囲を含む）。\n\
                 \x20 - 光源の位置を視点の変換の後に設定する理由。\n\
                 チェック: cargo run --release -- check a2    表示: cargo run --release -- view a2\n",
        "Tasks:\n\
                 \x20 a2.t1  motion(spec, state, drag): change the variables as listed (clamps and wrap included).\n\
                 \x20 a2.t2  camera(gl, state): the view transform (world → camera space) with gl.translate /\n\
                 \x20        gl.rotate (glTranslatef / glRotatef). The camera looks at the target from camera_distance\n\
                 \x20        away, raised by camera_pitch and turned by camera_yaw about the Y axis.\n\
                 \x20 a2.t3  display(gl, state): identity → the view transform (camera) → the light position\n\
                 \x20        (10, 10, 10, 1) → the ground and the pyramid (draw_course_objects). Set the light after\n\
                 \x20        the view transform, so it stays fixed in world space.\n\n\
                 The report shows:\n\
                 \x20 - the view transform as a product of rotations and translations (the 4×4 matrices side by\n\
                 \x20   side, (x, y, z, 1) → (x', y', z', 1)), and what each factor does;\n\
                 \x20 - each variable: which operation changes it and how (each line above, with its range);\n\
                 \x20 - why the light position is set after the view transform.\n\
                 Check: cargo run --release -- check a2    View: cargo run --release -- view a2\n",
    );
    out.push_str(tasks.get(lang));
    out
}
