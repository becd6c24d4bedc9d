//! `cg inspect [SCENE]`: what the report's first assignment asks for, derived from a scene —
//! for every object the mesh check, the vertex table, the face table with face normals, and the
//! model-view matrix as a product of named factors.

use std::fmt::Write as _;
use std::path::PathBuf;

use cg_core::camera::OrbitCamera;
use cg_core::lang::{Lang, Text, t};
use cg_core::light::{LightKind, LightModel, Specular};
use cg_core::mesh::{Orientation, Problem};
use cg_core::normals::{Weighting, face_normal};
use cg_core::notation::{braces, decimal, face, tuple, vertex_line};
use cg_core::product::MatrixProduct;
use cg_core::scene::{Camera, NormalSource, Object, Scene, Shading};

/// Options of `cg inspect`.
#[derive(clap::Args)]
pub struct Args {
    /// The scene file (default: the course's sample scene) / シーンファイル
    scene: Option<PathBuf>,
    /// Only this object / このオブジェクトだけ表示
    #[arg(long, value_name = "NAME")]
    object: Option<String>,
    /// Rows per table before "… more" (0 = all) / 表の最大行数（0 で全部）
    #[arg(long, default_value_t = 24, value_name = "N", allow_negative_numbers = true)]
    max_rows: usize,
    /// Print every row of every table / 全行を表示
    #[arg(long)]
    all: bool,
    /// Decimals of printed numbers, 1 to 9 / 小数点以下の桁数（1〜9）
    #[arg(long, default_value_t = 4, value_name = "N", value_parser = clap::value_parser!(u8).range(1..=9))]
    decimals: u8,
    /// The scene file's encoding: utf-8, utf-16le, utf-16be or shift_jis (default: detected) / シーンファイルの文字コード（省略時は自動判別）
    #[arg(long, value_name = "ENCODING")]
    encoding: Option<cg_core::text::Encoding>,
}

/// Loads the scene and prints the inspection.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    let path = crate::kit_path(args.scene.as_deref(), crate::COURSE_SAMPLE);
    let scene = cg_scene::load_encoded(&path, args.encoding).map_err(|e| e.describe(lang))?;
    if let Some(name) = &args.object
        && !scene.objects.iter().any(|o| &o.name == name)
    {
        let names: Vec<&str> = scene.objects.iter().map(|o| o.name.as_str()).collect();
        let names = names.join(", ");
        let (ja, en) =
            (cg_core::quote::shown(name, Lang::Ja), cg_core::quote::shown(name, Lang::En));
        let why = Text::new(
            format!("\"{ja}\" というオブジェクトはありません（あるもの: {names}）"),
            format!("no object named \"{en}\" (there are: {names})"),
        );
        return Err(format!("{}: {}", path.display(), why.get(lang)));
    }
    let rows = if args.all || args.max_rows == 0 { usize::MAX } else { args.max_rows };
    let text = report(
        &scene,
        &path.display().to_string(),
        args.object.as_deref(),
        rows,
        usize::from(args.decimals),
        lang,
    )?;
    print!("{text}");
    Ok(())
}

/// The whole inspection as text.
fn report(
    scene: &Scene,
    path: &str,
    only: Option<&str>,
    rows: usize,
    decimals: usize,
    lang: Lang,
) -> Result<String, String> {
    let d = decimals;
    let mut out = String::new();
    let w = &mut out;
    let _ = writeln!(w, "{} \"{}\" — {path}", t("シーン", "Scene").get(lang), scene.name);
    let _ = writeln!(
        w,
        "  {}: {} × {}, {} {}",
        t("ウィンドウ", "window").get(lang),
        scene.width,
        scene.height,
        t("背景色", "clear colour").get(lang),
        tuple(scene.clear_color, d)
    );
    let _ = writeln!(
        w,
        "  {}: {}",
        t("カメラ", "camera").get(lang),
        describe_camera(&scene.camera, d, lang)
    );
    let p = &scene.projection;
    let _ = writeln!(
        w,
        "  {}: gluPerspective({}°, {}/{}, {}, {})",
        t("投影", "projection").get(lang),
        decimal(p.fovy_deg, d),
        scene.width,
        scene.height,
        decimal(p.near, d),
        decimal(p.far, d)
    );
    let _ = writeln!(
        w,
        "  {}: {}",
        t("光のモデル", "light model").get(lang),
        describe_model(scene.light_model, lang)
    );
    let _ = writeln!(
        w,
        "  {}: {}",
        t("環境光", "global ambient").get(lang),
        tuple(scene.global_ambient, d)
    );
    let shading = match scene.shading {
        Shading::Flat => t("フラットシェーディング", "flat"),
        Shading::Gouraud => t("グローシェーディング", "Gouraud"),
        Shading::Phong => t("フォンシェーディング", "Phong"),
    };
    let shading = shading.get(lang);
    let cull = if scene.cull_back_faces {
        t("裏面は描画しない", "back faces culled")
    } else {
        t("裏面も描画する", "back faces drawn")
    };
    let cull = cull.get(lang);
    let _ = writeln!(w, "  {}: {shading}, {cull}", t("シェーディング", "shading").get(lang));
    let _ = writeln!(w, "  {}:", t("光源", "lights").get(lang));
    for (i, light) in scene.lights.iter().enumerate() {
        let _ = writeln!(
            w,
            "    L{i} {}  {} {}  {} {}  {} {}",
            describe_light(&light.kind, d, lang),
            t("環境光", "ambient").get(lang),
            tuple(light.ambient, d),
            t("拡散", "diffuse").get(lang),
            tuple(light.diffuse, d),
            t("鏡面", "specular").get(lang),
            tuple(light.specular, d)
        );
    }
    let view = scene.view_product().map_err(|e| e.message(lang))?;
    let _ = writeln!(
        w,
        "  {}:",
        t("視点の変換行列（ワールド座標系→カメラ座標系）", "view matrix (world → camera)")
            .get(lang)
    );
    let _ = writeln!(w, "    V = {}", view.simplified());
    let _ = writeln!(w, "      = {}", view.symbolic());

    for (k, object) in scene.objects.iter().enumerate() {
        if only.is_some_and(|name| name != object.name) {
            continue;
        }
        let _ = writeln!(w);
        object_report(w, k, scene.objects.len(), object, &view, rows, d, lang)?;
    }
    Ok(out)
}

#[allow(clippy::too_many_arguments)]
fn object_report(
    w: &mut String,
    k: usize,
    count: usize,
    object: &Object,
    view: &MatrixProduct,
    rows: usize,
    d: usize,
    lang: Lang,
) -> Result<(), String> {
    let mesh = &object.mesh;
    let normals = match object.normals {
        NormalSource::Face => {
            t("面の法線（面ごと）", "face normals (per face)").get(lang).to_owned()
        }
        NormalSource::Vertex { weighting, crease_deg } => format!(
            "{} ({}{})",
            t("頂点の法線", "vertex normals").get(lang),
            match weighting {
                Weighting::Uniform => t("面の法線の単純平均", "uniform average of face normals"),
                Weighting::Area => t("面積で重み付け", "area-weighted"),
                Weighting::Angle => t("角度で重み付け", "angle-weighted"),
                Weighting::Max => t("Max の重み付け", "Max-weighted"),
            }
            .get(lang),
            crease_deg.map_or(String::new(), |c| format!(
                ", {} {}°",
                t("稜線とみなす角度", "crease angle").get(lang),
                decimal(c, 1)
            ))
        ),
        NormalSource::Given => t("ファイルの法線", "normals from the file").get(lang).to_owned(),
    };
    let _ = writeln!(
        w,
        "{} {}/{count} \"{}\": {} {}, {} {}; {}",
        t("オブジェクト", "Object").get(lang),
        k + 1,
        object.name,
        mesh.vertex_count(),
        t("頂点", "vertices").get(lang),
        mesh.face_count(),
        t("面", "faces").get(lang),
        normals
    );

    // Welding (docs/numerics.md row 3: say which was used)
    let weld = match object.weld {
        None => t("位置による頂点の統合: なし", "welded by position: no").get(lang).to_owned(),
        Some(r) => format!(
            "{} {}: {} {}, {} {}",
            t("位置による頂点の統合: あり 許容値", "welded by position: yes, tolerance").get(lang),
            decimal(r.tolerance, d),
            r.merged_vertices,
            t("頂点を統合", "vertices merged").get(lang),
            r.removed_faces,
            t("面を削除", "faces removed").get(lang)
        ),
    };
    let _ = writeln!(w, "  {weld}");

    // Mesh check
    let v = mesh.validate();
    let yes_no = |b: bool, ja_yes, en_yes, ja_no, en_no| {
        if b { t(ja_yes, en_yes) } else { t(ja_no, en_no) }.get(lang).to_owned()
    };
    let orientation = match v.orientation() {
        Some(Orientation::Outward) => t("外向き", "outward"),
        Some(Orientation::Inward) => {
            t("内向き（全ての面が裏返し）", "INWARD (every face reversed)")
        }
        None => t("判定なし（閉じていない）", "n/a (not closed)"),
    };
    let orientation = orientation.get(lang);
    let _ = writeln!(
        w,
        "  {}: {}, {}, {}, {} {}",
        t("メッシュの検査", "mesh check").get(lang),
        yes_no(v.is_closed(), "閉じている", "closed", "開いている", "open"),
        yes_no(v.is_manifold(), "多様体", "manifold", "非多様体", "NOT manifold"),
        yes_no(
            v.is_consistently_wound(),
            "向きが揃っている",
            "consistent winding",
            "向きが不揃い",
            "INCONSISTENT winding"
        ),
        t("面の向き", "orientation").get(lang),
        orientation
    );
    let problems = v.problems();
    let border_only = problems.iter().all(|p| matches!(p, Problem::BoundaryEdge { .. }));
    if !problems.is_empty() && border_only {
        // An open surface such as the ground: its border is not a mistake.
        let _ = writeln!(
            w,
            "  {}: {} {}",
            t("開いた面", "open surface").get(lang),
            problems.len(),
            t(
                "本の境界辺（地面のような面なら正常。閉じた立体には境界辺はありません）",
                "border edges (fine for a surface such as the ground; a closed solid has none)"
            )
            .get(lang)
        );
    } else if !problems.is_empty() {
        let _ = writeln!(w, "  {} ({}):", t("指摘", "findings").get(lang), problems.len());
        // Grouped by kind, in order of first appearance: an open grid's 40 border edges are one
        // line with a few examples, not 40 lines.
        let mut kinds: Vec<(std::mem::Discriminant<_>, Vec<&_>)> = Vec::new();
        for p in problems {
            let d = std::mem::discriminant(p);
            match kinds.iter_mut().find(|(k, _)| *k == d) {
                Some((_, list)) => list.push(p),
                None => kinds.push((d, vec![p])),
            }
        }
        let examples = if rows == usize::MAX { usize::MAX } else { 3 };
        for (_, list) in &kinds {
            for p in list.iter().take(examples) {
                let _ = writeln!(w, "    - {}", p.describe(lang));
            }
            if list.len() > examples {
                let _ = writeln!(
                    w,
                    "      … {} {}",
                    list.len() - examples,
                    t(
                        "件の同じ種類の指摘（--all で全部表示）",
                        "more of this kind (--all lists them)"
                    )
                    .get(lang)
                );
            }
            let _ = writeln!(
                w,
                "      {}: {}",
                t("よくある原因", "usual cause").get(lang),
                list[0].hint().get(lang)
            );
        }
    }

    // Vertex table
    let _ = writeln!(w, "  {}:", t("頂点座標", "vertices").get(lang));
    for (i, p) in mesh.positions.iter().enumerate().take(rows) {
        let _ = writeln!(w, "    {}", vertex_line(i, *p, d));
    }
    more(w, mesh.vertex_count(), rows, lang);

    // Face table with normals
    let _ = writeln!(
        w,
        "  {}:",
        t(
            "三角面と面の法線 normalise((Vb−Va)×(Vc−Va))",
            "faces and face normals normalise((Vb−Va)×(Vc−Va))"
        )
        .get(lang)
    );
    let width = (0..mesh.face_count().min(rows))
        .map(|f| face(f, mesh.faces[f]).chars().count())
        .max()
        .unwrap_or(0);
    for (f, &idx) in mesh.faces.iter().enumerate().take(rows) {
        let label = face(f, idx);
        let normal = if idx.iter().all(|&i| (i as usize) < mesh.vertex_count()) {
            let [a, b, c] = mesh.triangle(f);
            face_normal(a, b, c).map_or_else(
                || t("縮退（法線なし）", "degenerate (no normal)").get(lang).to_owned(),
                |n| braces(n, d),
            )
        } else {
            t("頂点番号が範囲外", "index out of range").get(lang).to_owned()
        };
        let _ = writeln!(w, "    {label:<width$}  {normal}");
    }
    more(w, mesh.face_count(), rows, lang);

    // Model and model-view matrices
    let model_view = view.concat(&object.transform);
    let _ = writeln!(
        w,
        "  {}:",
        t("モデル変換（モデル座標系→ワールド座標系）", "model transform (model → world)").get(lang)
    );
    let _ = writeln!(w, "    M = {}", object.transform.simplified());
    let _ = writeln!(
        w,
        "  {}:",
        t("モデルビュー行列（モデル座標系→カメラ座標系）", "model-view matrix (model → camera)")
            .get(lang)
    );
    let _ = writeln!(w, "    V·M = {}", model_view.simplified());
    let _ = writeln!(w, "        = {}", model_view.symbolic());
    let matrices =
        model_view.simplified().matrices_text().map_err(|e| format!("{}: {e}", object.name))?;
    for line in matrices.lines() {
        let _ = writeln!(w, "      {line}");
    }
    Ok(())
}

fn more(w: &mut String, total: usize, shown: usize, lang: Lang) {
    if total > shown {
        let _ = writeln!(
            w,
            "    … {} {}",
            total - shown,
            t("行省略（--all で全部表示）", "more (--all prints every row)").get(lang)
        );
    }
}

fn describe_camera(camera: &Camera, d: usize, lang: Lang) -> String {
    match camera {
        Camera::Orbit(OrbitCamera { yaw_deg, pitch_deg, distance, target, .. }) => format!(
            "{} — {} {}, {} {}°, {} {}°, {} {}",
            t("注視点のまわりを回るカメラ", "orbit").get(lang),
            t("距離", "distance").get(lang),
            decimal(*distance, d),
            t("仰角 pitch", "pitch").get(lang),
            decimal(*pitch_deg, d),
            t("方位角 yaw", "yaw").get(lang),
            decimal(*yaw_deg, d),
            t("注視点", "target").get(lang),
            tuple(*target, d)
        ),
        Camera::LookAt { eye, target, up } => format!(
            "gluLookAt — {} {}, {} {}, {} {}",
            t("視点", "eye").get(lang),
            tuple(*eye, d),
            t("注視点", "target").get(lang),
            tuple(*target, d),
            t("上方向", "up").get(lang),
            tuple(*up, d)
        ),
    }
}

fn describe_model(model: LightModel, lang: Lang) -> String {
    match model {
        LightModel::OpenGl { local_viewer } => format!(
            "{}, {}",
            t("OpenGL 1.x 固定機能と同じ式", "OpenGL 1.x fixed-function equation").get(lang),
            if local_viewer {
                t("視点は有限の距離", "local viewer")
            } else {
                t("視点は無限遠", "infinite viewer")
            }
            .get(lang)
        ),
        LightModel::Lecture { specular, local_viewer } => format!(
            "{} I = Ia·ka + Σ Ii·[kd (N·L) + ks ({})^n], {}",
            t("講義の式", "the lecture's").get(lang),
            match specular {
                Specular::Phong => "R·V",
                Specular::Blinn => "N·H",
            },
            if local_viewer {
                t("視点は有限の距離", "local viewer")
            } else {
                t("視点は無限遠", "infinite viewer")
            }
            .get(lang)
        ),
    }
}

fn describe_light(kind: &LightKind, d: usize, lang: Lang) -> String {
    match kind {
        LightKind::Directional { to_light } => {
            format!(
                "{} {}",
                t("平行光源 光源の方向", "directional, towards").get(lang),
                tuple(*to_light, d)
            )
        }
        LightKind::Point { position } => {
            format!("{} {}", t("点光源", "point at").get(lang), tuple(*position, d))
        }
        LightKind::Spot { position, direction, cutoff_deg, exponent, .. } => format!(
            "{} {} → {}, {} {}°, {} {}",
            t("スポットライト光源", "spot at").get(lang),
            tuple(*position, d),
            tuple(*direction, d),
            t("照射角（半角）", "cutoff").get(lang),
            decimal(*cutoff_deg, d),
            t("集光指数", "exponent").get(lang),
            decimal(*exponent, d)
        ),
        LightKind::Area { corner, edge_u, edge_v, samples } => format!(
            "{} {} + s·{} + t·{}, {}×{} {}",
            t("面光源", "area").get(lang),
            tuple(*corner, d),
            tuple(*edge_u, d),
            tuple(*edge_v, d),
            samples[0],
            samples[1],
            t("個の点光源", "point lights").get(lang)
        ),
    }
}
