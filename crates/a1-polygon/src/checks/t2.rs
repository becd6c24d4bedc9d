//! The checks of task `a1.t2` (`faces(spec)`): indices, topology (closed, manifold, winding),
//! orientation, face count and surface.

use cg_core::glam::Vec3;
use cg_core::mesh::{Mesh, MeshError, Orientation, Problem, Validation};
use cg_core::normals::face_normal;
use cg_core::notation;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::Impl;
use crate::spec::ShapeExt;
use crate::spec::Spec;

use super::{
    SURFACE_TOLERANCE, coincident_vertices, indexed_mesh, join, listed, message, no_faces,
    student_mesh,
};

/// The student's mesh and its validation, or the failure that keeps a topology check from
/// running (no faces, an index out of range, a non-finite position).
fn validated(spec: &Spec, imp: &Impl) -> Result<(Mesh, Validation), Failure> {
    let mesh = indexed_mesh(
        spec,
        imp,
        t(
            "先に a1.t2.indices（と a1.t1）を直してください。このチェックはそれからです。",
            "fix a1.t2.indices (and a1.t1) first; this check runs after them.",
        ),
    )?;
    let validation = mesh.validate();
    Ok((mesh, validation))
}

/// `辺 V1–V3` / `edge V1–V3`.
fn edge_at(edge: [u32; 2]) -> Text {
    let e = notation::edge(edge[0], edge[1]);
    Text::new(format!("辺 {e}"), format!("edge {e}"))
}

/// A problem in compact notation (numbers and names, with a few words in each language), and
/// where it is.
fn compact(p: &Problem) -> (Text, Text) {
    match p {
        Problem::Structure(MeshError::IndexOutOfRange { face, corner, index, .. }) => {
            (format!("F{face}[{corner}] = {index}").into(), format!("F{face}").into())
        }
        Problem::Structure(e) => (message(e), "faces()".into()),
        Problem::RepeatedIndex { face, vertices } | Problem::ZeroArea { face, vertices } => {
            (notation::face(*face, *vertices).into(), format!("F{face}").into())
        }
        Problem::BoundaryEdge { edge, face } => {
            let e = notation::edge(edge[0], edge[1]);
            (
                Text::new(format!("{e}（F{face} のみ）"), format!("{e} (F{face} only)")),
                edge_at(*edge),
            )
        }
        Problem::TJunction { vertex, edge, face } => {
            let e = notation::edge(edge[0], edge[1]);
            (
                Text::new(
                    format!("{e} 上の V{vertex}（F{face}）"),
                    format!("V{vertex} on {e} (F{face})"),
                ),
                format!("V{vertex}").into(),
            )
        }
        Problem::NonManifoldEdge { edge, faces } => {
            let f: Vec<String> = faces.iter().map(|f| format!("F{f}")).collect();
            (
                format!("{} ({})", notation::edge(edge[0], edge[1]), f.join(", ")).into(),
                edge_at(*edge),
            )
        }
        Problem::NonManifoldVertex { vertex, fans } => (
            Text::new(
                format!("V{vertex}（周りの面が {fans} 組に分かれる）"),
                format!("V{vertex} ({fans} fans)"),
            ),
            format!("V{vertex}").into(),
        ),
        Problem::InconsistentWinding { edge, faces } => (
            Text::new(
                format!("F{} と F{} の両方で V{}→V{}", faces[0], faces[1], edge[0], edge[1]),
                format!("V{}→V{} in F{} and F{}", edge[0], edge[1], faces[0], faces[1]),
            ),
            edge_at(*edge),
        ),
        Problem::InwardFacing { signed_volume } | Problem::ZeroVolume { signed_volume } => (
            Text::new(
                format!("符号付き体積 {signed_volume:.4}"),
                format!("signed volume {signed_volume:.4}"),
            ),
            "faces()".into(),
        ),
        Problem::UnreferencedVertex { vertex } => (
            Text::new(format!("V{vertex}（どの面にもない）"), format!("V{vertex} (no face)")),
            format!("V{vertex}").into(),
        ),
    }
}

/// A failure listing `problems` (not empty): compact notation as the actual value, the first
/// problem's location, its description as the cause (plus `extra`), and its hint.
fn problems_failure(expected: Text, problems: &[&Problem], extra: Option<Text>) -> Failure {
    let items: Vec<(Text, Text)> = problems.iter().map(|p| compact(p)).collect();
    let actual: Vec<Text> = items.iter().map(|(a, _)| a.clone()).collect();
    let mut locations: Vec<Text> = items.iter().map(|(_, l)| l.clone()).collect();
    locations.dedup();
    let first = problems[0];
    let more = problems.len() - 1;
    let mut cause = vec![first.text()];
    if more > 0 {
        cause.push(Text::new(format!("（ほかに {more} 件）"), format!("(and {more} more)")));
    }
    if let Some(extra) = extra {
        cause.insert(0, extra);
    }
    Failure::new(expected, listed(&actual))
        .at(listed(&locations))
        .cause(join(&cause))
        .hint(first.hint())
}

pub(super) fn face_indices(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let mesh = student_mesh(spec, imp);
    if mesh.faces.is_empty() {
        return Err(no_faces());
    }
    let validation = mesh.validate();
    let problems: Vec<&Problem> =
        validation.problems().iter().filter(|p| matches!(p, Problem::Structure(_))).collect();
    if problems.is_empty() {
        return Ok(());
    }
    let n = mesh.positions.len() as u32;
    let indices = mesh.faces.iter().flatten();
    let from_one =
        n > 0 && indices.clone().all(|&i| (1..=n).contains(&i)) && indices.clone().any(|&i| i == n);
    let extra = from_one.then(|| {
        t(
            "頂点番号が 1 から数えられているようです（V0 がなく、最大が頂点の個数と同じ）。",
            "the vertex numbers seem to count from 1 (no V0, and the largest equals the number of vertices).",
        )
    });
    let last = n.saturating_sub(1);
    let expected = Text::new(format!("頂点番号 0..={last}"), format!("indices in 0..={last}"));
    Err(problems_failure(expected, &problems, extra))
}

pub(super) fn degenerate(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (_, validation) = validated(spec, imp)?;
    let problems: Vec<&Problem> = validation
        .problems()
        .iter()
        .filter(|p| matches!(p, Problem::RepeatedIndex { .. } | Problem::ZeroArea { .. }))
        .collect();
    if problems.is_empty() {
        Ok(())
    } else {
        Err(problems_failure(
            t(
                "各面に、一直線上にない異なる 3 頂点",
                "three different, non-collinear vertices per face",
            ),
            &problems,
            None,
        ))
    }
}

pub(super) fn closed(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (mesh, validation) = validated(spec, imp)?;
    let problems: Vec<&Problem> = validation
        .problems()
        .iter()
        .filter(|p| matches!(p, Problem::BoundaryEdge { .. } | Problem::TJunction { .. }))
        .collect();
    if problems.is_empty() {
        return Ok(());
    }
    // Duplicated vertices on the open edges? Else one missing triangle?
    let on_boundary: Vec<u32> = problems
        .iter()
        .filter_map(|p| match p {
            Problem::BoundaryEdge { edge, .. } => Some(*edge),
            _ => None,
        })
        .flatten()
        .collect();
    let twins: Vec<(usize, usize)> = coincident_vertices(&mesh.positions)
        .into_iter()
        .filter(|&(a, b)| on_boundary.contains(&(a as u32)) || on_boundary.contains(&(b as u32)))
        .collect();
    let extra = if let Some(&(a, b)) = twins.first() {
        Some(t(
            &format!(
                "V{b} は V{a} と同じ位置にある別の頂点です（頂点の複製）。V{b} を使う面は V{a} を使う面と辺を共有しません。"
            ),
            &format!(
                "V{b} is a second vertex at V{a}'s position (a duplicated vertex): a face that uses V{b} shares no edge with a face that uses V{a}."
            ),
        ))
    } else {
        missing_triangle(&problems).map(|[a, b, c]| {
            t(
                &format!("面 {{ V{a}, V{b}, V{c} }} が抜けているようです。"),
                &format!("the face {{ V{a}, V{b}, V{c} }} seems to be missing."),
            )
        })
    };
    Err(problems_failure(
        t("どの辺もちょうど 2 つの面に属する", "every edge in exactly two faces"),
        &problems,
        extra,
    ))
}

/// When the open edges form exactly one triangle, the face that closes it (wound so that it
/// traverses each edge opposite to its neighbour).
fn missing_triangle(problems: &[&Problem]) -> Option<[u32; 3]> {
    let edges: Vec<[u32; 2]> = problems
        .iter()
        .filter_map(|p| match p {
            Problem::BoundaryEdge { edge, .. } => Some(*edge),
            _ => None,
        })
        .collect();
    if edges.len() != 3 || edges.len() != problems.len() {
        return None;
    }
    let [a, b] = edges[0];
    let next = edges.iter().find(|e| e[0] == b)?;
    let c = next[1];
    edges.contains(&[c, a]).then_some([b, a, c])
}

pub(super) fn manifold(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (mesh, validation) = validated(spec, imp)?;
    let problems: Vec<&Problem> = validation
        .problems()
        .iter()
        .filter(|p| {
            matches!(p, Problem::NonManifoldEdge { .. } | Problem::NonManifoldVertex { .. })
        })
        .collect();
    if problems.is_empty() {
        return Ok(());
    }
    // A face listed twice?
    let key = |f: &[u32; 3]| {
        let mut k = *f;
        k.sort_unstable();
        k
    };
    // The first face whose three vertices an earlier face has, with that face: by a map of the
    // faces seen (comparing every pair took minutes on a list gone wrong).
    let mut seen = std::collections::HashMap::new();
    let twice = mesh.faces.iter().enumerate().find_map(|(j, f)| match seen.entry(key(f)) {
        std::collections::hash_map::Entry::Occupied(first) => Some((*first.get(), j)),
        std::collections::hash_map::Entry::Vacant(slot) => {
            slot.insert(j);
            None
        }
    });
    let extra = twice.map(|(i, j)| {
        t(
            &format!("F{i} と F{j} は同じ 3 頂点の面です（同じ面を 2 回定義）。"),
            &format!("F{i} and F{j} have the same three vertices (one face defined twice)."),
        )
    });
    Err(problems_failure(
        t("3 つ以上の面に属する辺がない", "no edge in more than two faces"),
        &problems,
        extra,
    ))
}

/// The faces whose normal points towards the inside: for these convex models, towards the
/// centroid of the vertices.
fn inward_faces(mesh: &Mesh) -> Vec<usize> {
    if mesh.positions.is_empty() {
        return Vec::new();
    }
    let centre = mesh.positions.iter().copied().sum::<Vec3>() / mesh.positions.len() as f32;
    (0..mesh.faces.len())
        .filter(|&f| {
            let [a, b, c] = mesh.triangle(f);
            face_normal(a, b, c).is_some_and(|n| n.dot((a + b + c) / 3.0 - centre) < 0.0)
        })
        .collect()
}

pub(super) fn winding(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (mesh, validation) = validated(spec, imp)?;
    let problems: Vec<&Problem> = validation
        .problems()
        .iter()
        .filter(|p| matches!(p, Problem::InconsistentWinding { .. }))
        .collect();
    if problems.is_empty() {
        return Ok(());
    }
    let inward = inward_faces(&mesh);
    let extra = (!inward.is_empty() && inward.len() * 2 < mesh.faces.len()).then(|| {
        let f: Vec<String> = inward.iter().map(|f| format!("F{f}")).collect();
        Text::new(
            format!("向きが逆なのはおそらく {} です（法線が内側を向いています）。", listed(&f).ja),
            if inward.len() == 1 {
                format!(
                    "the face wound the wrong way is probably {} (its normal points inward).",
                    f[0]
                )
            } else {
                format!(
                    "the faces wound the wrong way are probably {} (their normals point inward).",
                    listed(&f).en
                )
            },
        )
    });
    Err(problems_failure(
        t(
            "共有する辺を 2 つの面が互いに逆向きにたどる",
            "each shared edge traversed in opposite directions by its two faces",
        ),
        &problems,
        extra,
    ))
}

pub(super) fn outward(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (mesh, validation) = validated(spec, imp)?;
    let hint = t(
        "外側から面を見て、頂点が反時計回りに並ぶように書きます（右手の指を頂点の順に曲げたとき親指が外を向く）。逆向きの面は 2 つの頂点番号を入れ替えてください。",
        "list each face's vertices counter-clockwise as seen from outside (curl the fingers of your right hand along them: the thumb points out). Swap two numbers of a face that is the wrong way round.",
    );
    match validation.orientation() {
        Some(Orientation::Inward) => {
            let volume = validation.signed_volume().unwrap_or(0.0);
            return Err(Failure::new(
                t(
                    "符号付き体積 > 0（面が外側から見て反時計回り）",
                    "signed volume > 0 (faces counter-clockwise seen from outside)",
                ),
                Text::new(
                    format!("符号付き体積 {volume:.4} < 0"),
                    format!("signed volume {volume:.4} < 0"),
                ),
            )
            .at(format!("F0–F{}", mesh.faces.len().saturating_sub(1)))
            .cause(t(
                "すべての面が外側から見て時計回りです（法線がすべて内向き）。",
                "every face is clockwise seen from outside (every normal points inward).",
            ))
            .hint(hint));
        }
        None if validation.problems().iter().any(|p| matches!(p, Problem::ZeroVolume { .. })) => {
            return Err(problems_failure(
                t("体積を囲む閉じた曲面", "a closed surface around a volume"),
                &validation
                    .problems()
                    .iter()
                    .filter(|p| matches!(p, Problem::ZeroVolume { .. }))
                    .collect::<Vec<_>>(),
                None,
            ));
        }
        _ => {}
    }
    let inward = inward_faces(&mesh);
    if inward.is_empty() {
        return Ok(());
    }
    let faces: Vec<String> = inward.iter().map(|&f| notation::face(f, mesh.faces[f])).collect();
    let names: Vec<String> = inward.iter().map(|f| format!("F{f}")).collect();
    Err(Failure::new(
        t("どの面の法線も立体の外側を向く", "every face's normal pointing away from the inside"),
        listed(&faces),
    )
        .at(listed(&names))
        .cause(Text::new(
            format!(
                "{} は外側から見て時計回りです（法線 (V_b − V_a) × (V_c − V_a) が立体の内側を向いています）。",
                listed(&names).ja
            ),
            format!(
                "{} {} clockwise seen from outside (the normal (V_b − V_a) × (V_c − V_a) points into the solid).",
                listed(&names).en,
                if inward.len() == 1 { "is" } else { "are" }
            ),
        ))
        .hint(hint))
}

pub(super) fn face_count(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let mesh = student_mesh(spec, imp);
    let (v, f) = (spec.shape.vertex_count(), spec.shape.face_count());
    let got = mesh.faces.len();
    if got == f {
        return Ok(());
    }
    let euler = if mesh.check_indices().is_ok() && !mesh.faces.is_empty() {
        let e = mesh.validate().edge_count();
        format!(
            " (V − E + F = {} − {e} + {got} = {})",
            mesh.positions.len(),
            mesh.positions.len() as i64 - e as i64 + got as i64
        )
    } else {
        String::new()
    };
    let cause = if got < f {
        Text::new(
            format!(
                "面が {} 個足りません。四角形は三角形 2 つ、五角形は 3 つ、n 角形は n − 2 個の三角形に分けます。",
                f - got
            ),
            format!(
                "{} face(s) missing: a quadrilateral takes two triangles, a pentagon three, an n-gon n − 2.",
                f - got
            ),
        )
    } else {
        Text::new(
            format!("面が {} 個多すぎます。同じ面を 2 回書いていないか確認してください。", got - f),
            format!("{} face(s) too many: is a face listed twice?", got - f),
        )
    };
    Err(Failure::new(format!("F = 2·V − 4 = 2·{v} − 4 = {f}"), format!("F = {got}{euler}"))
        .at("faces()")
        .cause(cause)
        .hint(t(
            "頂点 V 個の閉じた三角形メッシュ（穴のない立体）では、オイラーの公式 V − E + F = 2 と 3F = 2E から F = 2V − 4 です。",
            "a closed triangle mesh (a solid without holes) with V vertices has F = 2V − 4 faces, from Euler's formula V − E + F = 2 and 3F = 2E.",
        )))
}

pub(super) fn surface(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let (mesh, validation) = validated(spec, imp)?;
    let (lo, hi) = mesh
        .positions
        .iter()
        .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), p| (lo.min(*p), hi.max(*p)));
    let tol = SURFACE_TOLERANCE * (hi - lo).max_element();
    // A face on the surface of a convex solid has every vertex on one side of its plane.
    let mut cutting = Vec::new();
    for f in 0..mesh.faces.len() {
        let [a, b, c] = mesh.triangle(f);
        let Some(n) = face_normal(a, b, c) else { continue };
        let d: Vec<f32> = mesh.positions.iter().map(|p| n.dot(*p - a)).collect();
        let front = (0..d.len()).filter(|&i| d[i] > tol).max_by(|&i, &j| d[i].total_cmp(&d[j]));
        let back = (0..d.len()).filter(|&i| d[i] < -tol).min_by(|&i, &j| d[i].total_cmp(&d[j]));
        if let (Some(i), Some(j)) = (front, back) {
            cutting.push((f, i, d[i], j, d[j]));
        }
    }
    if let Some(&(f, i, di, j, dj)) = cutting.first() {
        let faces: Vec<String> =
            cutting.iter().map(|&(f, ..)| notation::face(f, mesh.faces[f])).collect();
        let names: Vec<String> = cutting.iter().map(|&(f, ..)| format!("F{f}")).collect();
        return Err(Failure::new(
            t(
                "立体の表面上の面（どの面でも、すべての頂点が面の片側にある）",
                "faces on the surface of the solid (every vertex on one side of each face)",
            ),
            listed(&faces),
        )
        .at(listed(&names))
        .cause(Text::new(
            format!(
                "{} は立体の内部を横切っています: V{i} は面の表側に {:.3}、V{j} は裏側に {:.3} 離れています。隣り合う角どうしでない頂点を結んでいます（頂点番号の付け方を変えたのに面を直していない、など）。",
                notation::face(f, mesh.faces[f]),
                di,
                -dj
            ),
            format!(
                "{} cuts through the inside of the solid: V{i} lies {:.3} in front of its plane and V{j} {:.3} behind it. It joins vertices that are not neighbouring corners (the numbering changed but the faces did not, say).",
                notation::face(f, mesh.faces[f]),
                di,
                -dj
            ),
        ))
        .hint(t(
            "三面図に頂点番号を書き込み、各面が立体の表面の多角形（底面・側面など）の一部であることを確かめてください。",
            "draw the three views with the vertex numbers and make sure each face is part of one polygon of the surface (the bottom, a side, …).",
        )));
    }
    let unused: Vec<&Problem> = validation
        .problems()
        .iter()
        .filter(|p| matches!(p, Problem::UnreferencedVertex { .. }))
        .collect();
    if unused.is_empty() {
        Ok(())
    } else {
        Err(problems_failure(
            t("どの頂点もいずれかの面が使う", "every vertex used by a face"),
            &unused,
            None,
        ))
    }
}
