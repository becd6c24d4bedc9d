//! The checks of `a1`: one per property, each calling the student's functions inside its
//! closure, each failure saying what was expected, what was found, where (`V3`, `F2`,
//! `edge V1–V3`), the usual cause and a hint, in Japanese and English.
//!
//! Derived values come from the core: face normals from [`cg_core::normals::face_normal`],
//! topology from [`Mesh::validate`], matrices from [`MatrixProduct::matrix`] and
//! [`cg_core::transform`].
//!
//! [`MatrixProduct::matrix`]: cg_core::product::MatrixProduct::matrix

mod t1;
mod t2;
mod t3;
mod t4;

use cg_core::glam::{Mat4, Vec3};
use cg_core::lang::Lang;
use cg_core::mesh::{Mesh, MeshError};
use cg_core::notation;
use cg_core::transform::{rotate_y_deg, translate};
use cg_harness::check::{self, CheckResult, Failure};
use cg_harness::text::{Text, t};

use crate::Impl;
use crate::spec::Spec;

use t1::{vertex_count, vertex_positions};
use t2::{closed, degenerate, face_count, face_indices, manifold, outward, surface, winding};
use t3::{normal_count, normal_unit, normal_values};
use t4::placement;

/// How far (in each coordinate, scene units) a vertex may be from its expected position: 0.001.
/// Positions typed with three correct decimals pass, rounded or cut off (`1.299` for
/// 1.5·sin 60° = 1.29904); two decimals (`1.3`) do not; any error above 0.001 fails.
pub const VERTEX_TOLERANCE: f32 = 1e-3;

/// How far (in each component) a face normal may be from the normal derived from the face's own
/// vertices ([`face_normal`]): 0.001. A normal written with three correct decimals, rounded or
/// cut off, passes (`{ 0.0, 0.486, 0.874 }` or `{ 0.0, 0.485, 0.874 }` for the lecture's
/// F0, `(0, 0.4856, 0.8742)`); one off by more than 0.001 fails (the slide's printed
/// `{ 0.0, 0.53, 0.85 }`, which belongs to an apex at y = 0.8, not to its vertices).
///
/// [`face_normal`]: cg_core::normals::face_normal
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
    e.text()
}

/// The failure of a check that needs faces passing a1.t2.indices, for `e`, with `hint`.
fn indices_failure(e: &MeshError, hint: Text) -> Failure {
    Failure::new(t("a1.t2.indices に合格する面", "faces that pass a1.t2.indices"), message(e))
        .at("faces()")
        .cause(message(e))
        .hint(hint)
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

/// Pairs `(a, b)`: for each vertex `b`, the first vertex `a < b` at the same position (within
/// 1e-6 in every component), if any. The earlier vertices are kept in a grid of cells twice the
/// tolerance wide, so each vertex meets only those in the cells around it: a list of 300 000
/// vertices (a loop's bound gone wrong) took 4.5 · 10¹⁰ comparisons, and `cg check` hung.
fn coincident_vertices(v: &[Vec3]) -> Vec<(usize, usize)> {
    const TOL: f32 = 1e-6;
    // f64, so that two points within the tolerance are never two cells apart by rounding; a
    // coordinate too large for the cells saturates (such points only share cells).
    let cell =
        |p: Vec3| (p.as_dvec3() / (2.0 * f64::from(TOL))).floor().to_array().map(|c| c as i64);
    let mut grid: std::collections::HashMap<[i64; 3], Vec<usize>> =
        std::collections::HashMap::new();
    let mut out = Vec::new();
    for (b, &p) in v.iter().enumerate() {
        // A point that is not finite is close to nothing.
        if !p.is_finite() {
            continue;
        }
        let [x, y, z] = cell(p);
        let mut first: Option<usize> = None;
        for dx in -1..=1_i64 {
            for dy in -1..=1_i64 {
                for dz in -1..=1_i64 {
                    let key = [x.saturating_add(dx), y.saturating_add(dy), z.saturating_add(dz)];
                    for &a in grid.get(&key).map_or(&[][..], Vec::as_slice) {
                        if close(v[a], p, TOL) && first.is_none_or(|f| a < f) {
                            first = Some(a);
                        }
                    }
                }
            }
        }
        if let Some(a) = first {
            out.push((a, b));
        }
        grid.entry([x, y, z]).or_default().push(b);
    }
    out
}

/// The student's mesh: their vertices and faces.
/// The faces are asked for first, so a check of a1.t2 on a stub says "a1.t2: not done yet".
/// The student's mesh when it has faces and every index is in range, else the failure that keeps
/// a check from running, with `hint` (which check to fix first).
fn indexed_mesh(spec: &Spec, imp: &Impl, hint: Text) -> Result<Mesh, Failure> {
    let mesh = student_mesh(spec, imp);
    if mesh.faces.is_empty() {
        return Err(no_faces());
    }
    if let Err(e) = mesh.check_indices() {
        return Err(indices_failure(&e, hint));
    }
    Ok(mesh)
}

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

#[cfg(test)]
mod tests {
    use super::*;

    /// Every pair of vertices, as the check used to compare them.
    fn every_pair(v: &[Vec3]) -> Vec<(usize, usize)> {
        (0..v.len())
            .filter_map(|b| (0..b).find(|&a| close(v[a], v[b], 1e-6)).map(|a| (a, b)))
            .collect()
    }

    /// The grid finds the same twins as comparing every pair: points on and across the cells'
    /// borders, within and just past the tolerance, and points that are not finite.
    #[test]
    fn the_grid_finds_the_twins_every_pair_finds() {
        let mut state = 0x2545_F491_4F6C_DD1D_u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 40) as f32 / (1u64 << 24) as f32
        };
        let mut v = Vec::new();
        for _ in 0..2000 {
            // On a lattice of the cells' width, and nudged by up to twice the tolerance.
            let base = Vec3::new(next(), next(), next()).map(|c| (c * 8.0).round() * 2e-6);
            let nudge = Vec3::new(next(), next(), next()).map(|c| (c - 0.5) * 4e-6);
            v.push(base + nudge);
        }
        v.extend([Vec3::NAN, Vec3::INFINITY, Vec3::splat(1e30), Vec3::splat(1e30), Vec3::ZERO]);
        let expected = every_pair(&v);
        assert!(expected.len() > 100, "premise: many twins ({})", expected.len());
        assert_eq!(coincident_vertices(&v), expected);
    }

    /// A list gone wrong, 300 000 distinct vertices: done in one pass (comparing every pair
    /// would take 4.5 · 10¹⁰ comparisons, minutes).
    #[test]
    fn a_long_list_is_searched_in_one_pass() {
        let v: Vec<Vec3> = (0..300_000).map(|i| Vec3::new(i as f32 * 1e-3, 0.0, 1.0)).collect();
        assert_eq!(coincident_vertices(&v), []);
        let mut twice = v.clone();
        twice.push(v[123_456]);
        assert_eq!(coincident_vertices(&twice), [(123_456, 300_000)]);
    }
}
