//! The assignment text, in Japanese and English, with the student's numbers.

use std::fmt::Write as _;

use cg_core::lang::{Lang, Text, t};
use cg_core::product::format_number as n;

use crate::scenes::CHECK_EYE;
use crate::spec::{Named, Spec};

fn rgb(c: [f32; 3]) -> String {
    format!("({}, {}, {})", n(c[0]), n(c[1]), n(c[2]))
}

fn named(c: &Named, lang: Lang) -> String {
    format!("{} {}", t(c.ja, c.en).get(lang), rgb(c.rgb))
}

/// The assignment text in both languages, each written out whole.
pub(crate) fn describe(s: &Spec, lang: Lang) -> String {
    let text = Text::new(japanese(s), english(s));
    text.get(lang).to_owned()
}

fn japanese(s: &Spec) -> String {
    let mut out = String::new();
    let m = &s.material;
    let l = &s.light;
    let a = &s.attenuation;
    let sp = &s.sphere;
    let md = &s.medium;
    let eye = rgb(CHECK_EYE.to_array());
    let critical = md.critical_angle_deg();
    let _ = writeln!(out, "第11回 シェーディング（課題 s）");
    let _ = writeln!(out, "  あなたの材質と光源:");
    let _ = writeln!(
        out,
        "    物体の色 ka = kd = {}、鏡面反射係数 ks = {}、ハイライトの鋭さ n = {}",
        named(&m.color, Lang::Ja),
        n(m.ks),
        n(m.shininess)
    );
    let _ = writeln!(
        out,
        "    点光源: 位置 {}、色 Ii = {}、環境光 Ia = {}",
        rgb(l.position),
        named(&l.color, Lang::Ja),
        n(l.ambient)
    );
    let _ = writeln!(
        out,
        "    減衰係数 kc = {}, kl = {}, kq = {}　スポットライト: 広がり (cut-off) {}°、指数 {}",
        n(a.kc),
        n(a.kl),
        n(a.kq),
        n(s.spot.cutoff_deg),
        n(s.spot.exponent)
    );
    let _ = writeln!(
        out,
        "    球: 半径 1、経線 {} 本 × 緯度方向 {} 分割（{} 面、s.t5・s.t6 と画像で使う）",
        sp.slices,
        sp.stacks,
        sp.faces()
    );
    let _ = writeln!(
        out,
        "    媒質: {}（屈折率 η = {}、空気 η = 1 との境界、臨界角 {critical:.2}°）",
        md.ja,
        n(md.eta)
    );
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "  exercises/src/s.rs の関数を書くこと（光のモデル I = Ia·ka + Σ Ii·[kd (N·L) + ks (R·V)ⁿ] + kr·Ir + kt·It）:"
    );
    let _ = writeln!(out, "  s.t1 環境光: ambient(ia, ka) = Ia·ka");
    let _ = writeln!(
        out,
        "  s.t2 拡散反射光（ランバートの余弦則）: diffuse(ii, kd, n, l) = Ii·kd·max(N·L, 0)"
    );
    let _ = writeln!(
        out,
        "  s.t3 鏡面反射光（フォンのモデル）: specular(ii, ks, n, l, v, shininess) = Ii·ks·max(R·V, 0)ⁿ、R = 2(N·L)N − L。N·L ≤ 0 なら 0、powf の前に R·V を 0 以上に"
    );
    let _ = writeln!(
        out,
        "  s.t4 点光源の減衰 attenuation(kc, kl, kq, d) = 1/(kc + kl·d + kq·d²) とスポットライトの係数 spot_factor(l, spot_direction, cutoff_deg, exponent)"
    );
    let _ = writeln!(
        out,
        "  s.t5 頂点の法線: vertex_normals(mesh)（隣接する面の法線の平均）と vertex_normals_area(mesh)（面の面積に応じた加重平均）"
    );
    let _ = writeln!(
        out,
        "  s.t6 フラット／グロー／フォンシェーディング: shade_pixel(mode, pixel, light) — ピクセルの色を、面の法線・頂点の色・補間して正規化した法線のどれから決めるか"
    );
    let _ = writeln!(out, "  s.t7 鏡面反射（大域照明）の方向: reflect(i, n) = i − 2(i·n)n");
    let _ = writeln!(
        out,
        "  s.t8 透過光の屈折（スネルの法則 n₁ sin θ₁ = n₂ sin θ₂）: refract(i, n, n1, n2)、全反射なら None"
    );
    let _ = writeln!(out);
    let _ = writeln!(out, "  レポートに載せること:");
    let _ = writeln!(
        out,
        "  1. 光のモデルの式と各項（環境光・拡散反射光・鏡面反射光・大域照明）の意味。球の上の点 P = (0, 1, 0)（N = (0, 1, 0)、視点 {eye} から V = (0, 0, 1)）と、ハイライトの中の点をひとつ選び、あなたの光源と材質で L、R、N·L、R·V と各項を手計算し、関数の出力と比べた表"
    );
    let _ = writeln!(
        out,
        "  2. d = 1, 5, 10, 20 での減衰の表。スポットライトの係数を軸からの角度 α = 0°, {}°, {}°, {}° で計算した表と、度とラジアンの扱い",
        n(s.spot.cutoff_deg / 2.0),
        n(s.spot.cutoff_deg - 1.0),
        n(s.spot.cutoff_deg + 1.0)
    );
    let _ = writeln!(
        out,
        "  3. 立方体の角の頂点の法線を単純平均と面積加重平均で導出（隣接する面、各面の法線と面積を示す）。2 つを比べ、この立方体で一致する理由（三角形の面積がすべて等しい）と、異なるのはどんなときか。面積 0 の面の扱い"
    );
    let _ = writeln!(
        out,
        "  4. フラット・グロー・フォンの球の画像（cargo run --release -- view s）と違いの説明: グローでハイライトが消え、フォンで残る理由、フォンで法線の正規化 N' = N/|N| が必要な理由"
    );
    let _ = writeln!(
        out,
        "  5. {}の臨界角 sin θc = 1/η の導出、空気から θ₁ = 30° で入るときの屈折角、内側から臨界角より大きな角度で当たるとき（全反射）に何が起こるか",
        md.ja
    );
    let _ = writeln!(
        out,
        "  チェック: cargo run --release -- check s    表示: cargo run --release -- view s"
    );
    out
}

fn english(s: &Spec) -> String {
    let mut out = String::new();
    let m = &s.material;
    let l = &s.light;
    let a = &s.attenuation;
    let sp = &s.sphere;
    let md = &s.medium;
    let eye = rgb(CHECK_EYE.to_array());
    let critical = md.critical_angle_deg();
    let _ = writeln!(out, "Lecture 11: shading (assignment s)");
    let _ = writeln!(out, "  Your material and light:");
    let _ = writeln!(
        out,
        "    object colour ka = kd = {}, specular reflectance ks = {}, shininess n = {}",
        named(&m.color, Lang::En),
        n(m.ks),
        n(m.shininess)
    );
    let _ = writeln!(
        out,
        "    point light at {}, colour Ii = {}, ambient light Ia = {}",
        rgb(l.position),
        named(&l.color, Lang::En),
        n(l.ambient)
    );
    let _ = writeln!(
        out,
        "    attenuation kc = {}, kl = {}, kq = {}; spot light: cut-off {}°, exponent {}",
        n(a.kc),
        n(a.kl),
        n(a.kq),
        n(s.spot.cutoff_deg),
        n(s.spot.exponent)
    );
    let _ = writeln!(
        out,
        "    sphere: radius 1, {} meridians × {} bands ({} faces; used by s.t5, s.t6 and the images)",
        sp.slices,
        sp.stacks,
        sp.faces()
    );
    let _ = writeln!(
        out,
        "    medium: {} (refractive index η = {}, against air η = 1, critical angle {critical:.2}°)",
        md.en,
        n(md.eta)
    );
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "  Write the functions in exercises/src/s.rs (the light model I = Ia·ka + Σ Ii·[kd (N·L) + ks (R·V)ⁿ] + kr·Ir + kt·It):"
    );
    let _ = writeln!(out, "  s.t1 ambient: ambient(ia, ka) = Ia·ka");
    let _ = writeln!(
        out,
        "  s.t2 diffuse (Lambert's cosine law): diffuse(ii, kd, n, l) = Ii·kd·max(N·L, 0)"
    );
    let _ = writeln!(
        out,
        "  s.t3 specular (Phong's model): specular(ii, ks, n, l, v, shininess) = Ii·ks·max(R·V, 0)ⁿ, R = 2(N·L)N − L; 0 where N·L ≤ 0; clamp R·V before powf"
    );
    let _ = writeln!(
        out,
        "  s.t4 point-light attenuation attenuation(kc, kl, kq, d) = 1/(kc + kl·d + kq·d²) and the spot light's factor spot_factor(l, spot_direction, cutoff_deg, exponent)"
    );
    let _ = writeln!(
        out,
        "  s.t5 vertex normals: vertex_normals(mesh) (the average of the adjacent face normals) and vertex_normals_area(mesh) (weighted by face area)"
    );
    let _ = writeln!(
        out,
        "  s.t6 flat / Gouraud / Phong shading: shade_pixel(mode, pixel, light) — a pixel's colour from the face normal, the vertex colours, or the interpolated and renormalised normal"
    );
    let _ = writeln!(
        out,
        "  s.t7 the mirror direction (reflection, global illumination): reflect(i, n) = i − 2(i·n)n"
    );
    let _ = writeln!(
        out,
        "  s.t8 refraction by Snell's law n₁ sin θ₁ = n₂ sin θ₂: refract(i, n, n1, n2), None under total internal reflection"
    );
    let _ = writeln!(out);
    let _ = writeln!(out, "  The report shows:");
    let _ = writeln!(
        out,
        "  1. The light model and what each term means (ambient, diffuse, specular, global). At P = (0, 1, 0) on the sphere (N = (0, 1, 0); the eye at {eye}, so V = (0, 0, 1)) and at a point of your choice in the highlight: L, R, N·L, R·V and every term computed by hand with your light and material, in a table next to your functions' output"
    );
    let _ = writeln!(
        out,
        "  2. A table of the attenuation at d = 1, 5, 10, 20; the spot factor at α = 0°, {}°, {}°, {}° from the axis, and how degrees and radians were handled",
        n(s.spot.cutoff_deg / 2.0),
        n(s.spot.cutoff_deg - 1.0),
        n(s.spot.cutoff_deg + 1.0)
    );
    let _ = writeln!(
        out,
        "  3. The vertex normal at a cube corner derived as the plain and as the area-weighted average (the adjacent faces, their normals and areas); compare the two: why they agree on this cube (every triangle has the same area) and when they would differ; what zero-area faces do"
    );
    let _ = writeln!(
        out,
        "  4. The flat, Gouraud and Phong images of your sphere (cargo run --release -- view s) and their differences: why Gouraud loses the highlight and Phong keeps it; why Phong must renormalise N' = N/|N|"
    );
    let _ = writeln!(
        out,
        "  5. The critical angle of {} derived from sin θc = 1/η; the refraction angle for θ₁ = 30° coming from air; what happens from inside beyond the critical angle (total internal reflection)",
        md.en
    );
    let _ = writeln!(
        out,
        "  Check: cargo run --release -- check s    View: cargo run --release -- view s"
    );
    out
}
