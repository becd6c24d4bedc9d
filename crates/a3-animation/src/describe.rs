//! The assignment text, like the course's assignment program prints it, in Japanese and English.

use std::fmt::Write as _;

use cg_core::lang::{Lang, Text, t};
use cg_core::product::format_number;

use easy_ext::ext;

use crate::{Motion, Shape, Spec, SpecExt, Turn, WorldAxisExt, warmup_objects};

fn num(x: f32) -> String {
    format_number(x)
}

fn point(p: [f32; 3]) -> String {
    format!("({}, {}, {})", num(p[0]), num(p[1]), num(p[2]))
}

fn secs(x: f64) -> String {
    format_number(x as f32)
}

/// The shape in words: `直方体 1.2 × 0.4 × 0.6` / `box 1.2 × 0.4 × 0.6`.
pub(crate) fn shape_text(shape: &Shape) -> Text {
    match *shape {
        Shape::Box { size: [x, y, z] } => {
            let size = format!("{} × {} × {}", num(x), num(y), num(z));
            Text::new(format!("直方体 {size}"), format!("box {size}"))
        }
        Shape::Pyramid { sides, radius, height } => Text::new(
            format!(
                "{}角すい（底面の外接円の半径 {}、高さ {}）",
                kanji_number(sides),
                num(radius),
                num(height)
            ),
            format!(
                "{sides}-sided pyramid (base circumradius {}, height {})",
                num(radius),
                num(height)
            ),
        ),
        Shape::Sphere { radius } => Text::new(
            format!("球（半径 {}）", num(radius)),
            format!("sphere (radius {})", num(radius)),
        ),
        Shape::Octahedron { radius } => Text::new(
            format!("正八面体（半径 {}）", num(radius)),
            format!("octahedron (radius {})", num(radius)),
        ),
    }
}

fn kanji_number(n: u32) -> String {
    match n {
        3 => "三".to_owned(),
        4 => "四".to_owned(),
        5 => "五".to_owned(),
        6 => "六".to_owned(),
        _ => n.to_string(),
    }
}

fn turn_text(turn: Turn) -> Text {
    match turn {
        Turn::Ccw => t("反時計回り", "counter-clockwise"),
        Turn::Cw => t("時計回り", "clockwise"),
    }
}

fn signed(turn: Turn) -> &'static str {
    match turn {
        Turn::Ccw => "",
        Turn::Cw => "−",
    }
}

/// The motion of object `n` (1-based) in words, with its formula.
pub(crate) fn motion_text(n: usize, motion: &Motion) -> Text {
    let t = secs(f64::from(motion.period_s()));
    match *motion {
        Motion::Spin { position, axis, turn, .. } => Text::new(
            format!(
                "回転運動: 点 {} を通り {a} 軸に平行な軸のまわりに回転する。周期 {t} 秒、+{a} 側から見て{}。\n    θ{n} = {}360°·t/{t}（t = 0 で 0°）",
                point(position),
                turn_text(turn).ja,
                signed(turn),
                a = axis.name(),
            ),
            format!(
                "spin: turns about the axis through {} parallel to {a}, period {t} s, {} seen from +{a}.\n    θ{n} = {}360°·t/{t} (0° at t = 0)",
                point(position),
                turn_text(turn).en,
                signed(turn),
                a = axis.name(),
            ),
        ),
        Motion::Swing { pivot, axis, amplitude_deg, arm, .. } if arm > 0.0 => Text::new(
            format!(
                "往復回転運動（振り子）: 支点 {} の {} 下に中心が吊り下がり、支点を通り {a} 軸に平行な軸のまわりに振れる。振幅 {A}°、周期 {t} 秒。\n    θ{n} = {A}°·sin(360°·t/{t})（t = 0 で真下、はじめは + の向き）",
                point(pivot),
                num(arm),
                a = axis.name(),
                A = num(amplitude_deg),
            ),
            format!(
                "back-and-forth rotation (pendulum): its centre hangs {} below the pivot {} and swings about the axis through the pivot parallel to {a}, amplitude {A}°, period {t} s.\n    θ{n} = {A}°·sin(360°·t/{t}) (straight down at t = 0, first towards +)",
                num(arm),
                point(pivot),
                a = axis.name(),
                A = num(amplitude_deg),
            ),
        ),
        Motion::Swing { pivot, axis, amplitude_deg, .. } => Text::new(
            format!(
                "往復回転運動: 点 {} を通り {a} 軸に平行な軸のまわりに、−{A}° と {A}° の間を往復回転する。周期 {t} 秒。\n    θ{n} = {A}°·sin(360°·t/{t})（t = 0 で 0°、はじめは + の向き）",
                point(pivot),
                a = axis.name(),
                A = num(amplitude_deg),
            ),
            format!(
                "back-and-forth rotation: turns back and forth between −{A}° and {A}° about the axis through {} parallel to {a}, period {t} s.\n    θ{n} = {A}°·sin(360°·t/{t}) (0° at t = 0, first towards +)",
                point(pivot),
                a = axis.name(),
                A = num(amplitude_deg),
            ),
        ),
        Motion::Hop { center, along, span, height, period_s } => {
            let a = along.name();
            let v = along.vector().to_array();
            let at =
                |s: f32, y: f32| point([center[0] + v[0] * s, center[1] + y, center[2] + v[2] * s]);
            let (half, quarter) =
                (secs(f64::from(period_s) / 2.0), secs(f64::from(period_s) / 4.0));
            let (s, h) = (num(span), num(height));
            let (minus, top, plus) = (at(-span / 2.0, 0.0), at(0.0, height), at(span / 2.0, 0.0));
            let sv = match along {
                crate::WorldAxis::Z => "z",
                _ => "x",
            };
            let half_span = num(span / 2.0);
            let parabola = format!("y{n} = {}", parabola_text(height, span, &format!("{sv}{n}")));
            Text::new(
                format!(
                    "放物往復移動運動: 点 {} を中心に {a} 方向の幅 {s} の区間を往復し、行きも帰りも高さ {h} の放物線を描く。周期 {t} 秒（片道 {half} 秒）。\n    t = 0 で −{a} 側の端 {minus} を出発し、t = {quarter} 秒で頂上 {top}、t = {half} 秒で +{a} 側の端 {plus}、{t} 秒で元の位置に戻る。\n    中心からのずれ {sv}{n} は時間に比例して −{half_span}〜{half_span} を往復し、高さは {parabola}",
                    point(center),
                ),
                format!(
                    "parabolic back-and-forth motion: goes back and forth along {a} over a span of {s} centred on {}, hopping over a parabola of height {h} each way, period {t} s ({half} s each way).\n    At t = 0 at the −{a} end {minus}, at t = {quarter} s on top {top}, at t = {half} s at the +{a} end {plus}, back at {t} s.\n    The offset {sv}{n} from the centre moves linearly in time between −{half_span} and {half_span}; the height is {parabola}",
                    point(center),
                ),
            )
        }
        Motion::Orbit { center, radius, turn, .. } => Text::new(
            format!(
                "公転: 点 {} を中心とする水平な半径 {r} の円周上を回る（物体の向きも一緒に回る）。周期 {t} 秒、上（+Y 側）から見て{}。\n    t = 0 で中心の +Z 側 {}。θ{n} = {}360°·t/{t}",
                point(center),
                turn_text(turn).ja,
                point([center[0], center[1], center[2] + radius]),
                signed(turn),
                r = num(radius),
            ),
            format!(
                "orbit: goes round a horizontal circle of radius {r} about {}, turning with it, period {t} s, {} seen from above (+Y).\n    At t = 0 on the centre's +Z side {}. θ{n} = {}360°·t/{t}",
                point(center),
                turn_text(turn).en,
                point([center[0], center[1], center[2] + radius]),
                signed(turn),
                r = num(radius),
            ),
        ),
        Motion::Satellite { parent_index, radius, turn, .. } => {
            let p = parent_index + 1;
            let r = num(radius);
            Text::new(
                format!(
                    "階層的な運動（物体{p} の子）: 物体{p} の座標系（物体{p} とともに移動し、回転する座標系）で、物体{p} の中心のまわりの半径 {r} の円周上を、その座標系の Y 軸のまわりに回る。周期 {t} 秒（物体{p} に対して）、物体{p} の +Y 側から見て{}。\n    t = 0 で物体{p} の座標系の (0, 0, {r})。θ{n} = {}360°·t/{t}。物体{p} の変換の後、物体{p} の glPopMatrix の前に描く（glPushMatrix / glPopMatrix の入れ子）",
                    turn_text(turn).ja,
                    signed(turn),
                ),
                format!(
                    "hierarchical motion (child of object {p}): in object {p}'s coordinate system (which moves and turns with object {p}), goes round object {p}'s centre on a circle of radius {r} about that system's Y axis, period {t} s (relative to object {p}), {} seen from object {p}'s +Y.\n    At t = 0 at (0, 0, {r}) in object {p}'s coordinates. θ{n} = {}360°·t/{t}. Draw it after object {p}'s transforms and before object {p}'s glPopMatrix (nested glPushMatrix / glPopMatrix)",
                    turn_text(turn).en,
                    signed(turn),
                ),
            )
        }
    }
}

/// `h·(1 − (s/half)²)` for a hop of `height` over `span` in the variable `s`, without factors
/// of 1: `1.5·(1 − (x3/1.5)²)`, `(1 − x3²)`.
pub(crate) fn parabola_text(height: f32, span: f32, s: &str) -> String {
    let ratio = if span == 2.0 { s.to_owned() } else { format!("{s}/{}", num(span / 2.0)) };
    let coeff = if height == 1.0 { String::new() } else { format!("{}·", num(height)) };
    if span == 2.0 {
        format!("{coeff}(1 − {ratio}²)")
    } else {
        format!("{coeff}(1 − ({ratio})²)")
    }
}

fn color_text(c: [f32; 3]) -> String {
    point(c)
}

/// The assignment text of a variant.
#[ext(SpecDescribe)]
pub impl Spec {
    /// The assignment text for this variant, in `lang`: every object with its shape, motion
    /// (formula, start, direction, period), the ratios of the periods, the warm-up, the tasks
    /// `a3.t0`–`a3.t2` and what the report must show.
    fn describe(&self, lang: Lang) -> String {
        let mut out = String::new();
        let _ = writeln!(out, "{}", t("3. アニメーション (a3)", "3. Animation (a3)").get(lang));
        let _ = writeln!(
            out,
            "{}",
            t(
                "指定された通りの、複数の物体のアニメーションを実現する。\n時間: idle() の 1 回が 1 フレーム = 1/60 秒。n 回呼んだ後の時刻は t = n/60 秒。角度はすべて度。\nカメラと光源はサンプルプログラムと同じで全物体に共通: glTranslatef(0, 0, -15)、glRotatef(30, 1, 0, 0)（camera_pitch = −30°）、その直後に GL_LIGHT0 の位置 (10, 10, 10, 1)。",
                "Animate several objects exactly as specified.\nTime: one call of idle() is one frame = 1/60 s; after n calls the time is t = n/60 s. Every angle is in degrees.\nThe camera and the light are the sample program's, common to every object: glTranslatef(0, 0, -15), glRotatef(30, 1, 0, 0) (camera_pitch = −30°), then at once GL_LIGHT0's position (10, 10, 10, 1).",
            ).get(lang)
        );
        let _ = writeln!(
            out,
            "\n{}",
            t(
                "物体（\"…\" は gl.draw に渡す名前。メッシュは spec.objects[i].mesh、色は gl.color の値）:",
                "Objects (\"…\" is the name to give gl.draw; the mesh is spec.objects[i].mesh, the colour gl.color's):",
            ).get(lang)
        );
        for (i, o) in self.objects.iter().enumerate() {
            let n = i + 1;
            let (shape, color) = (shape_text(&o.shape), color_text(o.color));
            let head = Text::new(
                format!("物体{n} \"{}\": {}、色 {color}", o.name, shape.ja),
                format!("object {n} \"{}\": {}, colour {color}", o.name, shape.en),
            );
            let _ = writeln!(out, "  {}", head.get(lang));
            let _ = writeln!(out, "    {}", motion_text(n, &o.motion).get(lang));
        }
        let ratios: Vec<String> = self.period_ratios().iter().map(u64::to_string).collect();
        let names = |word: &str, sep: &str| {
            (1..=self.objects.len()).map(|n| format!("{word}{n}")).collect::<Vec<_>>().join(sep)
        };
        let unit = secs(f64::from(self.unit_s));
        let common = secs(self.common_period_s());
        let _ = writeln!(
            out,
            "{}",
            Text::new(format!(
                    "  周期の比 {} = {}（単位 {unit} 秒。全体は {common} 秒ごとに同じ動きを繰り返す）",
                    names("物体", " : "),
                    ratios.join(" : ")
                ), format!(
                    "  Ratio of the periods {} = {} (unit {unit} s; the whole animation repeats every {common} s)",
                    names("object ", " : "),
                    ratios.join(" : ")
                )).get(lang)
        );

        let _ = writeln!(
            out,
            "\n{}",
            t(
                "a3.t0 演習課題（全員共通）: warmup_display(gl, t) で 3 つの直方体を描く（カメラと光源は設定済み、t は秒。メッシュは warmup_box()）。",
                "a3.t0 Warm-up (the same for everybody): draw three boxes in warmup_display(gl, t) (the camera and light are set; t in seconds; the mesh is warmup_box()).",
            ).get(lang)
        );
        for (i, o) in warmup_objects().iter().enumerate() {
            let _ = writeln!(out, "  \"{}\": {}", o.name, shape_text(&o.shape).get(lang));
            let _ = writeln!(out, "    {}", motion_text(i + 1, &o.motion).get(lang));
        }
        let _ = writeln!(
            out,
            "{}",
            t(
                "  各直方体の前後に glPushMatrix / glPopMatrix を入れるか、どちらも入れないかを考えること。",
                "  Decide where glPushMatrix / glPopMatrix go around each box (or neither).",
            ).get(lang)
        );
        let _ = writeln!(
            out,
            "{}",
            t(
                "a3.t1 idle(spec, state): 1 フレーム進め（state.frame に 1 を足す）、各物体の運動の媒介変数（角度・位置）を state.params に求める。\n  変数は毎フレーム state.frame（整数）から作り直し、周期で割った余りを使う（f32 で足し続けると 10⁶ フレーム後にずれる）。",
                "a3.t1 idle(spec, state): advance one frame (add 1 to state.frame) and compute each object's motion parameters (angles, positions) into state.params.\n  Rebuild them from state.frame (an integer) every frame, reduced by the period (adding to an f32 every frame drifts after 10⁶ frames).",
            ).get(lang)
        );
        let _ = writeln!(
            out,
            "{}",
            t(
                "a3.t2 display(spec, state, gl): 視点の変換、光源の位置、各物体の変換と描画。独立した物体はそれぞれ glPushMatrix / glPopMatrix で囲み、子は親の変換の後に描く。",
                "a3.t2 display(spec, state, gl): the view transform, the light's position, each object's transform and draw call. Enclose each independent object in glPushMatrix / glPopMatrix; draw the child after its parent's transforms.",
            ).get(lang)
        );
        let _ = writeln!(
            out,
            "\n{}",
            t(
                "レポートに書くこと（課題2と同様）:\n  - 各物体の変換行列を回転・平行移動の積で示す（ワールド座標系→カメラ座標系の T(0, 0, -15)·Rx(30°) は共通）。子の行列は、親の行列に続く積になる。\n  - 各物体がどのような運動をするかの説明、使用する変数（θ1 など）とそれぞれの変化（式、範囲、周期）。\n  - 物体同士の周期の比（上の比と一致すること）と、その確かめ方。\nチェック: cargo run --release -- check a3    表示: cargo run --release -- view a3 --time 1.5",
                "The report (as for assignment 2):\n  - each object's transform as a product of rotations and translations (world → camera, T(0, 0, -15)·Rx(30°), is common); the child's product continues its parent's.\n  - what motion each object makes, the variables used (θ1, …) and how each changes (formula, range, period).\n  - the ratio of the objects' periods (it must match the one above) and how you checked it.\nCheck: cargo run --release -- check a3    View: cargo run --release -- view a3 --time 1.5",
            ).get(lang)
        );
        out
    }
}
