//! The checks of task `a1.t1` (`vertices(spec)`): the vertex count and the positions in the
//! spec's numbering.

use cg_core::glam::Vec3;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::Impl;
use crate::spec::NumberingExt;
use crate::spec::ShapeExt;
use crate::spec::SpecExt;
use crate::spec::{Numbering, Spec, Turn};

use super::{VERTEX_TOLERANCE, close, coincident_vertices, expected_transform, listed, v3};

pub(super) fn vertex_count(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let v = (imp.vertices)(spec);
    let n = spec.shape.vertex_count();
    if v.len() == n {
        return Ok(());
    }
    let twins = coincident_vertices(&v);
    let cause = if let Some(&(a, b)) = twins.first() {
        t(
            &format!(
                "V{b} は V{a} と同じ位置にあります。同じ頂点を 2 回定義しています（面どうしは頂点番号を共有します）。"
            ),
            &format!(
                "V{b} is at the same position as V{a}: the vertex is defined twice (faces share a vertex by its number)."
            ),
        )
    } else if v.len() > n {
        t(
            "頂点が多すぎます。中心点など余分な頂点を加えていないか確認してください。",
            "there are too many vertices: an extra point such as a centre has been added.",
        )
    } else {
        t(
            "頂点が足りません。どこかの角が抜けています。",
            "there are too few vertices: a corner is missing.",
        )
    };
    Err(Failure::new(format!("V = {n} (V0–V{})", n.saturating_sub(1)), format!("V = {}", v.len()))
        .at("vertices()")
        .cause(cause)
        .hint(Text::new(
            format!(
                "課題の頂点番号の表のとおり、V0 から V{} までちょうど {n} 個を返してください。",
                n.saturating_sub(1)
            ),
            format!(
                "list exactly the vertices of the numbering table, V0 to V{}, {n} in all.",
                n.saturating_sub(1)
            ),
        )))
}

pub(super) fn vertex_positions(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let v = (imp.vertices)(spec);
    let e = spec.expected_vertices();
    if v.is_empty() {
        return Err(Failure::new(format!("V0 {}", v3(e[0])), t("頂点なし", "no vertices"))
            .at("vertices()")
            .cause(t("頂点が 1 つもありません。", "there are no vertices."))
            .hint(t(
                "vec![Vec3::new(x, y, z), …] で頂点を番号順に並べてください。",
                "list the vertices in order: vec![Vec3::new(x, y, z), …].",
            )));
    }
    let n = v.len().min(e.len());
    let wrong: Vec<usize> = (0..n).filter(|&i| !close(v[i], e[i], VERTEX_TOLERANCE)).collect();
    if wrong.is_empty() {
        return if v.len() == e.len() { Ok(()) } else { Err(past_the_end(&v, &e)) };
    }
    let expected: Vec<String> = wrong.iter().map(|&i| format!("V{i} {}", v3(e[i]))).collect();
    let actual: Vec<String> = wrong.iter().map(|&i| format!("V{i} {}", v3(v[i]))).collect();
    let location: Vec<String> = wrong.iter().map(|&i| format!("V{i}")).collect();
    let cause = diagnose_positions(spec, &v, &e);
    let ring = match spec.numbering.ring {
        Turn::Ccw => "(r·cos θ, y, −r·sin θ)",
        Turn::Cw => "(r·cos θ, y, r·sin θ)",
    };
    Err(Failure::new(listed(&expected), listed(&actual))
        .at(listed(&location))
        .cause(cause)
        .hint(Text::new(
            format!(
                "寸法から各頂点を計算してください（各座標の許容誤差 {VERTEX_TOLERANCE}）。正 n 角形の k 番目の角は角度 θ = 360°·k/n の位置 {ring} です（cos・sin にはラジアンを渡す: θ.to_radians()）。番号は課題の表の順に。"
            ),
            format!(
                "compute each vertex from the dimensions (each coordinate within {VERTEX_TOLERANCE}). Corner k of a regular n-gon is at the angle θ = 360°·k/n: {ring} (cos and sin take radians: θ.to_radians()). Number them as the table in the assignment says."
            ),
        )))
}

/// The failure for vertices that are right as far as they go, but too few or too many: the
/// positions cannot pass while a corner is missing or an extra point is listed.
fn past_the_end(v: &[Vec3], e: &[Vec3]) -> Failure {
    let n = v.len().min(e.len());
    let last = n.saturating_sub(1);
    let right = if n == 1 { "V0".to_string() } else { format!("V0–V{last}") };
    let (expected, actual, cause): (Vec<Text>, Vec<Text>, Text) = if v.len() < e.len() {
        (
            (n..e.len()).map(|i| format!("V{i} {}", v3(e[i])).into()).collect(),
            (n..e.len()).map(|i| t(&format!("V{i} なし"), &format!("no V{i}"))).collect(),
            Text::new(
                format!(
                    "{right} の位置は正しいのですが、V{n} から先が返されていません（V{} まで {} 個の角があります）。",
                    e.len() - 1,
                    e.len()
                ),
                format!(
                    "{right} are in the right places, but nothing from V{n} on is returned (the table goes on to V{}, {} corners in all).",
                    e.len() - 1,
                    e.len()
                ),
            ),
        )
    } else {
        (
            (n..v.len()).map(|i| t(&format!("V{i} なし"), &format!("no V{i}"))).collect(),
            (n..v.len()).map(|i| format!("V{i} {}", v3(v[i])).into()).collect(),
            match coincident_vertices(v).into_iter().find(|&(_, b)| b >= n) {
                Some((a, b)) => Text::new(
                    format!(
                        "{right} の位置は正しいのですが、表にない V{b} が V{a} と同じ位置にあります（同じ頂点を 2 回定義しています）。"
                    ),
                    format!(
                        "{right} are in the right places, but V{b}, not in the table, is at the same position as V{a} (the vertex is defined twice)."
                    ),
                ),
                None => Text::new(
                    format!(
                        "{right} の位置は正しいのですが、課題の表にない頂点 V{n} から先が加わっています（中心点など）。"
                    ),
                    format!(
                        "{right} are in the right places, but V{n} on are not in the table (an extra point such as a centre?)."
                    ),
                ),
            },
        )
    };
    let location: Vec<String> = (n..v.len().max(e.len())).map(|i| format!("V{i}")).collect();
    Failure::new(listed(&expected), listed(&actual)).at(listed(&location)).cause(cause).hint(
        Text::new(
            format!("課題の頂点番号の表のとおり、V0 から V{} までを返してください。", e.len() - 1),
            format!("list the vertices of the numbering table, V0 to V{}.", e.len() - 1),
        ),
    )
}

/// The usual cause of wrong vertex positions, found by comparing with what common mistakes give.
fn diagnose_positions(spec: &Spec, v: &[Vec3], e: &[Vec3]) -> Text {
    if let Some(i) = v.iter().position(|p| !p.is_finite()) {
        return t(
            &format!("V{i} に NaN か無限大があります（0 での割り算など）。"),
            &format!("V{i} has a NaN or infinite coordinate (a division by zero?)."),
        );
    }
    let tol = VERTEX_TOLERANCE;
    if v.len() == e.len() {
        // The right points in another order?
        let parts = spec.shape.parts();
        for rule in Numbering::all() {
            if rule != spec.numbering {
                let other = rule.apply(&parts);
                if v.iter().zip(&other).all(|(a, b)| close(*a, *b, tol)) {
                    return Text::new(
                        format!(
                            "点の位置は正しいのですが、番号の付け方が違います。あなたの番号は「{}」、課題の指定は「{}」です。",
                            rule.short().ja,
                            spec.numbering.short().ja
                        ),
                        format!(
                            "the points are right but numbered by another rule: yours is \"{}\", the assignment asks for \"{}\".",
                            rule.short().en,
                            spec.numbering.short().en
                        ),
                    );
                }
            }
        }
        let matches: Vec<Option<usize>> =
            v.iter().map(|p| e.iter().position(|q| close(*p, *q, tol))).collect();
        if matches.iter().all(Option::is_some) {
            let mut seen = matches.iter().flatten().copied().collect::<Vec<_>>();
            seen.sort_unstable();
            seen.dedup();
            if seen.len() == e.len()
                && let Some((i, Some(j))) = matches.iter().enumerate().find(|&(i, m)| *m != Some(i))
            {
                return t(
                    &format!(
                        "点の位置は正しいのですが、番号の順番が違います（たとえばあなたの V{i} は課題の V{j} の位置です）。"
                    ),
                    &format!(
                        "the points are right but in another order (your V{i}, for one, is where V{j} should be)."
                    ),
                );
            }
        }
        // The whole model moved?
        let d = v[0] - e[0];
        if v.iter().zip(e).all(|(a, b)| close(*a - *b, d, tol)) {
            let p = spec.placement;
            if close(d, Vec3::new(p.x, p.y, p.z), tol) {
                return t(
                    "頂点に配置（平行移動）が含まれています。頂点はモデル座標系で書き、配置は a1.t4 の変換で行います。",
                    "the vertices include the placement's translation: write them in model space; the placement is a1.t4's transform.",
                );
            }
            if close(d, Vec3::new(0.0, -spec.shape.height() / 2.0, 0.0), tol) {
                return t(
                    "モデルが原点を中心に置かれています。課題のモデル座標系では、いちばん下の点（底面）が y = 0 です。",
                    "the model is centred on the origin: in the assignment's model space its lowest point (or bottom face) lies on y = 0.",
                );
            }
            return Text::new(
                format!("モデル全体が {} だけずれています。", v3(d)),
                format!("the whole model is shifted by {}.", v3(d)),
            );
        }
        // Placed in the world (turned and moved)?
        let m = expected_transform(spec);
        if v.iter().zip(e).all(|(a, b)| close(*a, m.transform_point3(*b), tol)) {
            return t(
                "頂点がワールド座標系に置かれています（回転と平行移動を含む）。頂点はモデル座標系で書き、配置は a1.t4 の変換で行います。",
                "the vertices are placed in the world (turned and moved): write them in model space; the placement is a1.t4's transform.",
            );
        }
    }
    // The size?
    let extent = |p: &[Vec3]| {
        let (lo, hi) = p
            .iter()
            .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), q| (lo.min(*q), hi.max(*q)));
        hi - lo
    };
    let (ev, ee) = (extent(v), extent(e));
    if !close(ev, ee, 2.0 * tol) {
        return Text::new(
            format!(
                "モデルの大きさが違います。X・Y・Z 方向の幅: あなた {}、課題 {}。寸法（半径は外接円の半径 = 軸から角までの距離、直径や辺の長さではない）を確認してください。",
                v3(ev),
                v3(ee)
            ),
            format!(
                "the model's size differs: its extents along X, Y and Z are {}, the assignment's {}. Check the dimensions (a radius is the circumradius, the distance from the axis to a corner, not a diameter or a side length).",
                v3(ev),
                v3(ee)
            ),
        );
    }
    // Right heights and distances from the axis, wrong angles?
    let polar = |p: &Vec3| (p.y, Vec3::new(p.x, 0.0, p.z).length());
    if v.len() == e.len()
        && v.iter().zip(e).all(|(a, b)| {
            let ((ya, ra), (yb, rb)) = (polar(a), polar(b));
            (ya - yb).abs() <= tol && (ra - rb).abs() <= 2.0 * tol
        })
    {
        return t(
            "高さと軸からの距離は正しいのですが、角度（向き）が違います。最初の角が +X 軸上にあるか、回る向き、cos・sin にラジアンを渡しているかを確認してください。",
            "the heights and the distances from the axis are right but the angles are not: check that the first corner is on +X, the direction of the turn, and that cos and sin get radians.",
        );
    }
    t(
        "寸法・番号の付け方・モデル座標系（底が y = 0、軸が Y 軸）を確認してください。",
        "check the dimensions, the numbering rule and the model space (bottom on y = 0, the Y axis as the axis).",
    )
}
