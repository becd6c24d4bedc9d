//! The checks of `a1`: one per property, each calling the student's functions inside its
//! closure, each failure saying what was expected, what was found, where (`V3`, `F2`,
//! `edge V1–V3`), the usual cause and a hint, in Japanese and English.
//!
//! Derived values come from the core: face normals from [`cg_core::normals::face_normal`],
//! topology from [`Mesh::validate`], matrices from [`MatrixProduct::matrix`] and
//! [`cg_core::transform`].

use cg_core::glam::{Mat4, Vec3};
use cg_core::lang::Lang;
use cg_core::mesh::{Mesh, MeshError, Orientation, Problem, Validation};
use cg_core::normals::face_normal;
use cg_core::notation;
use cg_core::product::MatrixProduct;
use cg_core::transform::{rotate_y, rotate_y_deg, translate};
use cg_harness::check::{self, CheckResult, Failure};
use cg_harness::text::{Text, t};

use crate::spec::NumberingExt;
use crate::spec::ShapeExt;
use crate::spec::SpecExt;
use crate::spec::{Numbering, Spec, Turn};
use crate::{Impl, format_deg};

/// How far (in each coordinate, scene units) a vertex may be from its expected position: 0.001.
/// Positions typed with three correct decimals pass, rounded or cut off (`1.299` for
/// 1.5·sin 60° = 1.29904); two decimals (`1.3`) do not; any error above 0.001 fails.
pub const VERTEX_TOLERANCE: f32 = 1e-3;

/// How far (in each component) a face normal may be from the normal derived from the face's own
/// vertices ([`face_normal`]): 0.001. A normal written with three correct decimals, rounded or
/// cut off, passes (`{ 0.0, 0.486, 0.874 }` or `{ 0.0, 0.485, 0.874 }` for the lecture's
/// F0, `(0, 0.4856, 0.8742)`); one off by more than 0.001 fails (the slide's printed
/// `{ 0.0, 0.53, 0.85 }`, which belongs to an apex at y = 0.8, not to its vertices).
pub const NORMAL_TOLERANCE: f32 = 1e-3;

/// How far a normal's length may be from 1: 0.002, the most that three-decimal components can
/// move it (√3 · 0.001 ≈ 0.0017).
pub const UNIT_TOLERANCE: f32 = 2e-3;

/// How far (entry by entry) the model transform may be from `T(x, y, z) · Ry(θ)`: 0.001, so a
/// matrix typed with three correct decimals (cos 30° = 0.866) passes.
pub const MATRIX_TOLERANCE: f32 = 1e-3;

/// How far, relative to the model's size (its largest extent), a vertex may lie on the wrong
/// side of a face's plane before the face counts as cutting through the inside: 1 %. Planar
/// quadrilaterals split into two triangles stay far below it even with three-decimal
/// coordinates; a face that joins corners across the solid is far above it.
pub const SURFACE_TOLERANCE: f32 = 0.01;

/// How many items a failure lists before `…`.
const LIST: usize = 4;

fn v3(v: Vec3) -> String {
    notation::tuple(v, 4)
}

fn braces(v: Vec3) -> String {
    notation::braces(v, 4)
}

/// Whether `a` and `b` are finite and within `tol` of each other in every component.
fn close(a: Vec3, b: Vec3, tol: f32) -> bool {
    a.is_finite() && b.is_finite() && (a - b).abs().cmple(Vec3::splat(tol)).all()
}

/// `items` joined by `, `, at most [`LIST`] of them, then `…（全 N 件）` / `… (N in all)`.
fn listed<T: Clone + Into<Text>>(items: &[T]) -> Text {
    let items: Vec<Text> = items.iter().cloned().map(Into::into).collect();
    let first = |lang| items.iter().take(LIST).map(|t| t.get(lang)).collect::<Vec<_>>().join(", ");
    if items.len() <= LIST {
        Text::new(first(Lang::Ja), first(Lang::En))
    } else {
        Text::new(
            format!("{}, …（全 {} 件）", first(Lang::Ja), items.len()),
            format!("{}, … ({} in all)", first(Lang::En), items.len()),
        )
    }
}

/// The message of a core error in both languages.
fn message(e: &MeshError) -> Text {
    Text::new(e.message(Lang::Ja), e.message(Lang::En))
}

/// Sentences joined: the Japanese ones without spaces, the English ones with a space, every
/// English sentence after the first starting with a capital letter.
fn join(texts: &[Text]) -> Text {
    let ja: String = texts.iter().map(|t| t.ja.as_str()).collect();
    let en: Vec<String> = texts
        .iter()
        .map(|t| t.en.as_str())
        .filter(|s| !s.is_empty())
        .enumerate()
        .map(|(i, s)| {
            let mut chars = s.chars();
            match chars.next() {
                Some(c) if i > 0 => c.to_uppercase().chain(chars).collect(),
                _ => s.to_owned(),
            }
        })
        .collect();
    Text::new(ja, en.join(" "))
}

/// The model transform the spec asks for: `T(x, y, z) · Ry(θ)`.
fn expected_transform(spec: &Spec) -> Mat4 {
    let p = spec.placement;
    translate(Vec3::new(p.x, p.y, p.z)) * rotate_y_deg(p.angle_deg)
}

/// Every check of this assignment for `spec`, run against `imp`, in task order.
#[must_use]
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    vec![
        check::run("a1.t1.count", t("頂点の数", "vertex count"), || vertex_count(spec, imp)),
        check::run(
            "a1.t1.positions",
            t("頂点の座標と番号", "vertex positions and numbering"),
            || vertex_positions(spec, imp),
        ),
        check::run(
            "a1.t2.indices",
            t("面の頂点番号が存在する頂点を指す", "face indices refer to existing vertices"),
            || face_indices(spec, imp),
        ),
        check::run(
            "a1.t2.degenerate",
            t("面積 0 の面がない", "no face without area"),
            || degenerate(spec, imp),
        ),
        check::run(
            "a1.t2.closed",
            t("閉じている（どの辺も 2 つの面が共有）", "closed (every edge shared by two faces)"),
            || closed(spec, imp),
        ),
        check::run(
            "a1.t2.manifold",
            t("どの辺も 3 つ以上の面に使われていない", "no edge used by more than two faces"),
            || manifold(spec, imp),
        ),
        check::run(
            "a1.t2.winding",
            t("隣り合う面の向きがそろっている", "neighbouring faces wound consistently"),
            || winding(spec, imp),
        ),
        check::run(
            "a1.t2.outward",
            t(
                "どの面も外側から見て反時計回り（法線が外向き）",
                "every face counter-clockwise seen from outside (normals outward)",
            ),
            || outward(spec, imp),
        ),
        check::run(
            "a1.t2.count",
            t("面の数（オイラーの公式）", "face count (Euler's formula)"),
            || face_count(spec, imp),
        ),
        check::run(
            "a1.t2.surface",
            t(
                "どの面も立体の表面上にあり、すべての頂点を使う",
                "every face on the surface, every vertex used",
            ),
            || surface(spec, imp),
        ),
        check::run(
            "a1.t3.count",
            t("法線の数（1 面に 1 つ）", "one normal per face"),
            || normal_count(spec, imp),
        ),
        check::run("a1.t3.unit", t("法線の長さが 1", "normals of unit length"), || {
            normal_unit(spec, imp)
        }),
        check::run(
            "a1.t3.normals",
            t(
                "法線が面の頂点から求めた値と一致する",
                "normals equal the ones derived from each face's vertices",
            ),
            || normal_values(spec, imp),
        ),
        check::run(
            "a1.t4.placement",
            t("配置の変換 T(x, y, z)·Ry(θ)", "the placement T(x, y, z) · Ry(θ)"),
            || placement(spec, imp),
        ),
    ]
}

// ---------------------------------------------------------------------------------------------
// a1.t1

fn vertex_count(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

/// Pairs `(a, b)`, `a < b`, of vertices at the same position (within 1e-6).
fn coincident_vertices(v: &[Vec3]) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for b in 0..v.len() {
        for a in 0..b {
            if close(v[a], v[b], 1e-6) {
                out.push((a, b));
                break;
            }
        }
    }
    out
}

fn vertex_positions(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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
        return Ok(());
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
                            rule.short(Lang::Ja),
                            spec.numbering.short(Lang::Ja)
                        ),
                        format!(
                            "the points are right but numbered by another rule: yours is \"{}\", the assignment asks for \"{}\".",
                            rule.short(Lang::En),
                            spec.numbering.short(Lang::En)
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

// ---------------------------------------------------------------------------------------------
// a1.t2

/// The student's mesh: their vertices and faces.
/// The faces are asked for first, so a check of a1.t2 on a stub says "a1.t2: not done yet".
fn student_mesh(spec: &Spec, imp: &Impl) -> Mesh {
    let faces = (imp.faces)(spec);
    Mesh::new((imp.vertices)(spec), faces)
}

/// A failure for an empty face list.
fn no_faces() -> Failure {
    Failure::new("F0 { Va, Vb, Vc }, …", t("面なし", "no faces"))
        .at("faces()")
        .cause(t("面が 1 つもありません。", "there are no faces."))
        .hint(t(
            "vec![[0, 3, 1], …] のように三角形を頂点番号で並べてください。",
            "list the triangles as vertex numbers: vec![[0, 3, 1], …].",
        ))
}

/// The student's mesh and its validation, or the failure that keeps a topology check from
/// running (no faces, an index out of range, a non-finite position).
fn validated(spec: &Spec, imp: &Impl) -> Result<(Mesh, Validation), Failure> {
    let mesh = student_mesh(spec, imp);
    if mesh.faces.is_empty() {
        return Err(no_faces());
    }
    if let Err(e) = mesh.check_indices() {
        return Err(Failure::new(
            t("a1.t2.indices に合格する面", "faces that pass a1.t2.indices"),
            message(&e),
        )
        .at("faces()")
        .cause(message(&e))
        .hint(t(
            "先に a1.t2.indices（と a1.t1）を直してください。このチェックはそれからです。",
            "fix a1.t2.indices (and a1.t1) first; this check runs after them.",
        )));
    }
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
    let mut cause = vec![Text::new(first.describe(Lang::Ja), first.describe(Lang::En))];
    if more > 0 {
        cause.push(Text::new(format!("（ほかに {more} 件）"), format!("(and {more} more)")));
    }
    if let Some(extra) = extra {
        cause.insert(0, extra);
    }
    Failure::new(expected, listed(&actual))
        .at(listed(&locations))
        .cause(join(&cause))
        .hint(Text::new(first.hint(Lang::Ja), first.hint(Lang::En)))
}

fn face_indices(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

fn degenerate(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

fn closed(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

fn manifold(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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
    let mut twice = None;
    'outer: for j in 0..mesh.faces.len() {
        for i in 0..j {
            if key(&mesh.faces[i]) == key(&mesh.faces[j]) {
                twice = Some((i, j));
                break 'outer;
            }
        }
    }
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

fn winding(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

fn outward(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

fn face_count(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

fn surface(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

// ---------------------------------------------------------------------------------------------
// a1.t3

fn normal_count(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let normals = (imp.face_normals)(spec);
    let faces = (imp.faces)(spec);
    if faces.is_empty() {
        return Err(no_faces());
    }
    if normals.len() == faces.len() {
        return Ok(());
    }
    let vertices = (imp.vertices)(spec);
    let cause = if normals.len() == vertices.len() {
        t(
            "頂点ごとに法線を返しています。この課題は面ごと（面の法線）に 1 つです。",
            "there is one normal per vertex: this task asks for one per face (face normals).",
        )
    } else if normals.len() < faces.len() {
        t("法線が足りない面があります。", "some faces have no normal.")
    } else {
        t("法線が面より多くあります。", "there are more normals than faces.")
    };
    Err(Failure::new(
        Text::new(
            format!("法線 {} 個（1 面に 1 つ、F0–F{}）", faces.len(), faces.len() - 1),
            format!("{} normals (one per face, F0–F{})", faces.len(), faces.len() - 1),
        ),
        Text::new(format!("法線 {} 個", normals.len()), format!("{} normals", normals.len())),
    )
    .at("face_normals()")
    .cause(cause)
    .hint(t(
        "faces の i 番目の面の法線を i 番目に入れてください（faces と同じ長さ、同じ順番）。",
        "put face i's normal at index i (as long as faces, in the same order).",
    )))
}

fn normal_unit(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let normals = (imp.face_normals)(spec);
    if normals.is_empty() {
        return Err(Failure::new(
            t("1 面に 1 つの単位法線", "one unit normal per face"),
            t("法線なし", "no normals"),
        )
        .at("face_normals()")
        .cause(t("法線が 1 つもありません。", "there are no normals."))
        .hint(t("面ごとに法線を計算してください。", "compute a normal for each face.")));
    }
    let bad: Vec<usize> = (0..normals.len())
        .filter(|&f| {
            let n = normals[f];
            !(n.is_finite() && (n.length() - 1.0).abs() <= UNIT_TOLERANCE)
        })
        .collect();
    if bad.is_empty() {
        return Ok(());
    }
    let actual: Vec<String> = bad
        .iter()
        .map(|&f| format!("F{f} {} (|n| = {:.4})", braces(normals[f]), normals[f].length()))
        .collect();
    let names: Vec<String> = bad.iter().map(|f| format!("F{f}")).collect();
    let zero = bad.iter().any(|&f| normals[f] == Vec3::ZERO);
    let cause = if zero {
        t(
            "長さ 0 の法線があります（平行な 2 辺の外積か、値の入れ忘れ）。",
            "a normal is the zero vector (the cross product of parallel edges, or not filled in).",
        )
    } else {
        t(
            "法線が正規化されていません。外積の長さは面の面積の 2 倍で、1 ではありません。",
            "the normals are not normalised: a cross product's length is twice the face's area, not 1.",
        )
    };
    Err(Failure::new(format!("|n| = 1 ± {UNIT_TOLERANCE}"), listed(&actual))
        .at(listed(&names))
        .cause(cause)
        .hint(t(
            "外積を自分の長さで割ってください: n / n.length()（または n.normalize()）。",
            "divide the cross product by its own length: n / n.length() (or n.normalize()).",
        )))
}

fn normal_values(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let normals = (imp.face_normals)(spec);
    let mesh = student_mesh(spec, imp);
    if mesh.faces.is_empty() {
        return Err(no_faces());
    }
    if let Err(e) = mesh.check_indices() {
        return Err(Failure::new(
            t("a1.t2.indices に合格する面", "faces that pass a1.t2.indices"),
            message(&e),
        )
        .at("faces()")
        .cause(message(&e))
        .hint(t("先に a1.t2.indices を直してください。", "fix a1.t2.indices first.")));
    }
    if normals.is_empty() {
        return Err(Failure::new(
            t("1 面に 1 つの法線", "one normal per face"),
            t("法線なし", "no normals"),
        )
        .at("face_normals()")
        .cause(t("法線が 1 つもありません。", "there are no normals."))
        .hint(t("面ごとに法線を計算してください。", "compute a normal for each face.")));
    }
    let derived: Vec<Option<Vec3>> = (0..mesh.faces.len())
        .map(|f| {
            let [a, b, c] = mesh.triangle(f);
            face_normal(a, b, c)
        })
        .collect();
    let wrong: Vec<(usize, Vec3)> = (0..normals.len().min(derived.len()))
        .filter_map(|f| derived[f].map(|d| (f, d)))
        .filter(|&(f, d)| !close(normals[f], d, NORMAL_TOLERANCE))
        .collect();
    if wrong.is_empty() {
        return Ok(());
    }
    let expected: Vec<String> = wrong
        .iter()
        .map(|&(f, d)| format!("{} {}", notation::face(f, mesh.faces[f]), braces(d)))
        .collect();
    let actual: Vec<String> =
        wrong.iter().map(|&(f, _)| format!("F{f} {}", braces(normals[f]))).collect();
    let names: Vec<String> = wrong.iter().map(|&(f, _)| format!("F{f}")).collect();
    let mut cause = diagnose_normals(spec, &mesh, &derived, &normals, &wrong);
    if normals.len() != mesh.faces.len() {
        cause = join(&[
            Text::new(
                format!(
                    "法線が {} 個、面が {} 個で、面と法線が対応していません（a1.t3.count）。",
                    normals.len(),
                    mesh.faces.len()
                ),
                format!(
                    "there are {} normals for {} faces, so normals and faces do not line up (a1.t3.count).",
                    normals.len(),
                    mesh.faces.len()
                ),
            ),
            cause,
        ]);
    }
    Err(Failure::new(listed(&expected), listed(&actual))
        .at(listed(&names))
        .cause(cause)
        .hint(Text::new(
            format!(
                "面 {{ Va, Vb, Vc }} の法線は (Vb − Va) × (Vc − Va) を正規化したものです（各成分の許容誤差 {NORMAL_TOLERANCE}、小数 3 桁まで正しければ合格）。"
            ),
            format!(
                "the normal of face {{ Va, Vb, Vc }} is (Vb − Va) × (Vc − Va), normalised (each component within {NORMAL_TOLERANCE}: three correct decimals pass)."
            ),
        )))
}

/// The mistakes that give wrong normals, each as a test on one face (`f`, the student's normal
/// `n`, the derived normal `d`) and the explanation.
#[derive(Clone, Copy, PartialEq, Eq)]
enum NormalMistake {
    NotFinite,
    Reversed,
    NotNormalised,
    TurnedByPlacement,
    Positions,
    Copied,
}

impl NormalMistake {
    const ALL: [NormalMistake; 6] = [
        NormalMistake::NotFinite,
        NormalMistake::Reversed,
        NormalMistake::NotNormalised,
        NormalMistake::TurnedByPlacement,
        NormalMistake::Copied,
        NormalMistake::Positions,
    ];

    /// Whether this mistake turns `d` into `n` on face `f`.
    fn explains(
        self,
        spec: &Spec,
        mesh: &Mesh,
        derived: &[Option<Vec3>],
        f: usize,
        n: Vec3,
        d: Vec3,
    ) -> bool {
        let tol = NORMAL_TOLERANCE;
        match self {
            NormalMistake::NotFinite => !n.is_finite(),
            NormalMistake::Reversed => close(n, -d, tol),
            NormalMistake::NotNormalised => {
                n.is_finite() && n.length() > 0.0 && close(n / n.length(), d, tol)
            }
            NormalMistake::TurnedByPlacement => {
                let turn = rotate_y(spec.placement.angle_deg.to_radians());
                close(n, turn.transform_vector3(d), tol)
            }
            NormalMistake::Positions => {
                let [a, b, c] = mesh.triangle(f);
                [a.cross(b), b.cross(c), a.cross(c), b.cross(a), c.cross(b), c.cross(a)]
                    .iter()
                    .any(|p| p.length() > 0.0 && close(n, p.normalize(), tol))
            }
            NormalMistake::Copied => {
                (0..derived.len()).any(|g| g != f && derived[g].is_some_and(|e| close(n, e, tol)))
            }
        }
    }

    /// The explanation, naming face `f` (and the face copied from, for [`NormalMistake::Copied`]).
    fn text(self, derived: &[Option<Vec3>], f: usize, n: Vec3) -> Text {
        match self {
            NormalMistake::NotFinite => t(
                &format!(
                    "F{f} の法線に NaN か無限大があります（長さ 0 のベクトルを正規化した、など）。"
                ),
                &format!(
                    "F{f}'s normal has a NaN or infinite component (a zero vector normalised?)."
                ),
            ),
            NormalMistake::Reversed => t(
                &format!(
                    "F{f} の法線が逆向きです。外積の順番が逆 ((Vc − Va) × (Vb − Va)) か、符号を反転しています。"
                ),
                &format!(
                    "F{f}'s normal points the wrong way: the cross product's operands are swapped ((Vc − Va) × (Vb − Va)), or its sign is flipped."
                ),
            ),
            NormalMistake::NotNormalised => t(
                &format!(
                    "F{f} の法線は向きは正しいのですが、長さが {:.4} で 1 ではありません（正規化していない）。",
                    n.length()
                ),
                &format!(
                    "F{f}'s normal has the right direction but its length is {:.4}, not 1 (not normalised).",
                    n.length()
                ),
            ),
            NormalMistake::TurnedByPlacement => t(
                &format!(
                    "F{f} の法線が配置の回転で回されています。法線はモデル座標系の値を書きます。"
                ),
                &format!("F{f}'s normal is turned by the placement: write it in model space."),
            ),
            NormalMistake::Positions => t(
                &format!(
                    "F{f} の法線は頂点の位置ベクトルどうしの外積（Va × Vb など）です。辺のベクトル (Vb − Va)、(Vc − Va) の外積を使います。"
                ),
                &format!(
                    "F{f}'s normal is a cross product of position vectors (Va × Vb or the like): use the edge vectors (Vb − Va) and (Vc − Va)."
                ),
            ),
            NormalMistake::Copied => {
                let g = (0..derived.len())
                    .find(|&g| g != f && derived[g].is_some_and(|e| close(n, e, NORMAL_TOLERANCE)))
                    .unwrap_or(f);
                t(
                    &format!("F{f} の法線は F{g} の法線と同じです（隣の面の値を写した？）。"),
                    &format!("F{f}'s normal is F{g}'s (copied from a neighbouring face?)."),
                )
            }
        }
    }
}

/// The usual cause of the wrong normals `wrong` (face, derived normal): the first mistake that
/// explains every one of them, else the first that explains the first one.
fn diagnose_normals(
    spec: &Spec,
    mesh: &Mesh,
    derived: &[Option<Vec3>],
    normals: &[Vec3],
    wrong: &[(usize, Vec3)],
) -> Text {
    let explains_all = |m: NormalMistake| {
        wrong.iter().all(|&(f, d)| m.explains(spec, mesh, derived, f, normals[f], d))
    };
    let (f, d) = wrong[0];
    let first = |m: NormalMistake| m.explains(spec, mesh, derived, f, normals[f], d);
    if wrong.len() > 1
        && let Some(m) = NormalMistake::ALL.into_iter().find(|&m| explains_all(m))
    {
        let names: Vec<String> = wrong.iter().map(|(f, _)| format!("F{f}")).collect();
        return join(&[
            Text::new(
                format!("{} のすべてで同じ誤りです。", listed(&names).ja),
                format!("the same mistake on {}:", listed(&names).en),
            ),
            m.text(derived, f, normals[f]),
        ]);
    }
    NormalMistake::ALL.into_iter().find(|&m| first(m)).map_or_else(
        || {
            t(
                &format!("F{f} の法線が、その面の頂点から求めた値と一致しません。"),
                &format!("F{f}'s normal does not follow from the face's own vertices."),
            )
        },
        |m| m.text(derived, f, normals[f]),
    )
}

// ---------------------------------------------------------------------------------------------
// a1.t4

/// `[[r0], [r1], [r2], [r3]]`, the matrix by rows.
fn rows(m: Mat4) -> String {
    let r: Vec<String> = (0..4)
        .map(|i| {
            let row = m.row(i);
            format!(
                "[{}, {}, {}, {}]",
                notation::decimal(row.x, 4),
                notation::decimal(row.y, 4),
                notation::decimal(row.z, 4),
                notation::decimal(row.w, 4)
            )
        })
        .collect();
    format!("[{}]", r.join(", "))
}

fn matrices_close(a: Mat4, b: Mat4) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array())
        .all(|(x, y)| x.is_finite() && (x - y).abs() <= MATRIX_TOLERANCE)
}

fn placement(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let product: MatrixProduct = (imp.model_transform)(spec).into();
    let p = spec.placement;
    let angle = format_deg(p.angle_deg);
    let expected = expected_transform(spec);
    let expected_text = format!(
        "T({}, {}, {}) · Ry({angle}°) = {}",
        format_deg(p.x),
        format_deg(p.y),
        format_deg(p.z),
        rows(expected)
    );
    let hint = t(
        "display() で glTranslatef(x, y, z); glRotatef(θ, 0, 1, 0); と呼ぶ順に因子を並べます。MatrixProduct::identity().then(Factor::translate(…)).then(Factor::rotate_y_deg(θ)) のように書けます。最後の因子が最初に頂点に作用します。角度は度です。",
        "list the factors in the order display() would call glTranslatef(x, y, z) and glRotatef(θ, 0, 1, 0), as in MatrixProduct::identity().then(Factor::translate(…)).then(Factor::rotate_y_deg(θ)); the last factor acts on the vertices first. Angles are in degrees.",
    );
    let m = match product.matrix() {
        Ok(m) => m,
        Err(e) => {
            let message = Text::new(e.message(Lang::Ja), e.message(Lang::En));
            return Err(Failure::new(expected_text, message.clone())
                .at("model_transform()")
                .cause(message)
                .hint(hint));
        }
    };
    if matrices_close(m, expected) {
        return Ok(());
    }
    let actual = format!("{} = {}", product.numeric(), rows(m));
    let at = translate(Vec3::new(p.x, p.y, p.z));
    let turn = rotate_y_deg(p.angle_deg);
    let rad = p.angle_deg.to_radians();
    let cause = if matrices_close(m, at * rotate_y_deg(rad)) {
        Text::new(
            format!(
                "角度がラジアンで渡されています: {angle}° の代わりに {rad:.4}°（= {angle}° をラジアンにした値）だけ回っています。glRotatef や Factor::rotate_y_deg の角度は度です。"
            ),
            format!(
                "the angle is given in radians where degrees are expected: the model turns by {rad:.4}° ({angle}° converted to radians) instead of {angle}°. glRotatef and Factor::rotate_y_deg take degrees."
            ),
        )
    } else if matrices_close(m, at * rotate_y(p.angle_deg)) {
        Text::new(
            format!(
                "度の値 {angle} がラジアンとして cos・sin に渡されています（{angle} ラジアン回っています）。cos・sin には {angle}_f32.to_radians() を渡します。"
            ),
            format!(
                "the angle in degrees, {angle}, went into cos and sin as radians (the model turns by {angle} radians): pass {angle}_f32.to_radians() to cos and sin."
            ),
        )
    } else if matrices_close(m, turn * at) {
        t(
            "積の順番が逆です（回転してから平行移動の行列 Ry·T）。これではモデルがワールドの原点のまわりを回り、指定の位置からずれます。T を先（左）に、Ry を後（右）に書きます。",
            "the factors are in the wrong order (Ry · T): the model then swings about the world's origin, away from its place. Write T first (left), then Ry (right).",
        )
    } else if matrices_close(m, at * rotate_y_deg(-p.angle_deg)) {
        t(
            "回転の向きが逆です（−θ だけ回っています）。上から見て反時計回りが正の角度です。",
            "the rotation goes the wrong way (by −θ): counter-clockwise seen from above is the positive angle.",
        )
    } else if matrices_close(m, at) {
        t("回転がありません（平行移動だけ）。", "the rotation is missing (a translation only).")
    } else if matrices_close(m, turn) {
        t("平行移動がありません（回転だけ）。", "the translation is missing (a rotation only).")
    } else if (m.w_axis.truncate() - expected.w_axis.truncate()).abs().max_element()
        <= MATRIX_TOLERANCE
    {
        t(
            "平行移動の部分（4 列目）は正しいのですが、回転の部分が違います。",
            "the translation part (the 4th column) is right but the rotation part is not.",
        )
    } else {
        Text::new(
            format!(
                "モデル座標系の原点が {} に行くはずが、{} に行きます。",
                v3(expected.w_axis.truncate()),
                v3(m.w_axis.truncate())
            ),
            format!(
                "the model's origin should land on {} but lands on {}.",
                v3(expected.w_axis.truncate()),
                v3(m.w_axis.truncate())
            ),
        )
    };
    Err(Failure::new(expected_text, actual).at("model_transform()").cause(cause).hint(hint))
}
