//! s.t5: vertex normals against [`cg_core::normals::vertex_normals`] (uniform and area weights)
//! on small meshes: a cube's corners, an uneven fan, the lecture's pyramid, the student's sphere,
//! and a fan with zero-area faces and an isolated vertex.
//!
//! Tolerance: 1e-5 per component (the student sums f32 face normals, the core f64 ones: both
//! are within a few 1e-7 of the exact average on these meshes).

use cg_core::glam::Vec3;
use cg_core::mesh::Mesh;
use cg_core::normals::{Weighting, vertex_normals};
use cg_core::shapes::{cuboid, lecture_pyramid};
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};
use cg_student::mesh::Mesh as StudentMesh;

use crate::inputs::{max_diff, num, vec};
use crate::scenes::sphere_mesh;
use crate::{Impl, Spec};

const TOLERANCE: f32 = 1e-5;

/// A vertex with six triangles of unequal size around it (a fan), counter-clockwise from above:
/// its plain and area-weighted normals differ.
#[must_use]
pub(crate) fn fan() -> Mesh {
    let ring = [
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.5, 0.25, -1.0),
        Vec3::new(-0.25, 0.0, -0.5),
        Vec3::new(-2.0, -0.5, 0.0),
        Vec3::new(-0.5, 0.0, 1.5),
        Vec3::new(0.5, 0.5, 0.75),
    ];
    let mut positions = vec![Vec3::new(0.0, 1.0, 0.0)];
    positions.extend(ring);
    let faces = (0..6u32).map(|k| [0, 1 + k, 1 + (k + 1) % 6]).collect();
    Mesh::new(positions, faces)
}

/// [`fan`] with three zero-area faces — a repeated index (`{V1, V1, V2}`), three exactly
/// collinear corners (`{V1, V7, V2}`, V7 the midpoint of V1–V2) and a face of one point
/// (`{V8, V8, V8}`) — and an isolated vertex V9. V7 and V8 touch only zero-area faces and V9 no
/// face: their normals are the zero vector.
#[must_use]
pub(crate) fn degenerate_fan() -> Mesh {
    let mut mesh = fan();
    let (v1, v2) = (mesh.positions[1], mesh.positions[2]);
    mesh.positions.push((v1 + v2) * 0.5); // V7, exactly on the edge
    mesh.positions.push(Vec3::new(2.0, 2.0, 2.0)); // V8
    mesh.positions.push(Vec3::new(-3.0, 3.0, -3.0)); // V9, isolated
    mesh.faces.push([1, 1, 2]);
    mesh.faces.push([1, 7, 2]);
    mesh.faces.push([8, 8, 8]);
    mesh
}

fn meshes(spec: &Spec) -> Vec<(Text, Mesh)> {
    let cube = cuboid(Vec3::splat(2.0)).unwrap_or_default();
    vec![
        (t("立方体", "cube"), cube),
        (t("扇形", "fan"), fan()),
        (t("講義の四角すい", "lecture pyramid"), lecture_pyramid()),
        (t("あなたの球", "your sphere"), sphere_mesh(spec)),
    ]
}

/// `メッシュ「立方体」` / `mesh "cube"`, then `rest` in each language.
fn mesh_at(name: &Text, rest_ja: &str, rest_en: &str) -> Text {
    Text::new(format!("メッシュ「{}」{rest_ja}", name.ja), format!("mesh \"{}\"{rest_en}", name.en))
}

/// Compares the student's normals of `mesh` with the core's for `weighting`.
fn compare(
    name: &Text,
    mesh: &Mesh,
    got: &[Vec3],
    weighting: Weighting,
    other: Weighting,
) -> Result<(), Failure> {
    let expected = vertex_normals(mesh, weighting).normals;
    if got.len() != expected.len() {
        let (e, g) = (expected.len(), got.len());
        return Err(Failure::new(
            Text::new(format!("法線 {e} 個（1 頂点に 1 つ）"), format!("{e} normals (one per vertex)")),
            Text::new(format!("法線 {g} 個"), format!("{g} normals")),
        )
        .at(mesh_at(name, "", ""))
        .cause(t("頂点の数だけ法線が必要です。", "every vertex needs a normal."))
        .hint(t(
            "vec![Vec3::ZERO; mesh.positions.len()] から始めて、各面の法線を 3 つの頂点に足します。",
            "start from vec![Vec3::ZERO; mesh.positions.len()] and add each face's normal to its three vertices.",
        )));
    }
    if !got.is_empty()
        && got.iter().all(|&g| g == Vec3::Y)
        && expected.iter().any(|&e| e != Vec3::Y)
    {
        let n = got.len();
        return Err(Failure::new(
            format!("V0 {} …", vec(expected[0])),
            Text::new(
                format!("{n} 個のすべての頂点で (0, 1, 0)"),
                format!("(0, 1, 0) at every vertex of the {n} vertices"),
            ),
        )
        .at(mesh_at(name, "", ""))
        .cause(t(
            "vertex_normals はまだ仮の答え（どの頂点も真上 (0, 1, 0)）を返しています。",
            "vertex_normals still returns the placeholder (every vertex straight up, (0, 1, 0)).",
        ))
        .hint(t(
            "s.t5 を書きます: 各面の法線をその 3 つの頂点に足し、最後に正規化します。",
            "write s.t5: add each face's normal to its three vertices, then normalise.",
        )));
    }
    let alternative = vertex_normals(mesh, other).normals;
    for (v, (&g, &e)) in got.iter().zip(&expected).enumerate() {
        if max_diff(g, e) <= TOLERANCE {
            continue;
        }
        let length = g.length();
        let direction_ok =
            e != Vec3::ZERO && g.is_finite() && g.normalize_or_zero().dot(e) > 1.0 - 1e-6;
        let (cause, hint) = if !g.is_finite() {
            (
                t(
                    "NaN（または無限大）です。面積 0 の面の法線（長さ 0 のベクトル）を正規化すると NaN になります。",
                    "NaN (or infinite). Normalising the normal of a zero-area face (a zero vector) gives NaN.",
                ),
                t(
                    "面の法線は外積 (b−a)×(c−a) を正規化したものです。面積 0 の面では外積がゼロベクトルなので、(b - a).cross(c - a).try_normalize() が None になります。その面は飛ばします。最後の正規化には normalize_or_zero() を使います。",
                    "the face normal is the cross product (b−a)×(c−a) normalised; for a zero-area face that cross product is the zero vector and (b - a).cross(c - a).try_normalize() gives None: skip those faces. Normalise the sums with normalize_or_zero().",
                ),
            )
        } else if e == Vec3::ZERO {
            (
                t(
                    "この頂点を使う面は面積 0 のものだけ（またはひとつもない）ので、法線はゼロベクトルです。",
                    "only zero-area faces (or none) use this vertex, so its normal is the zero vector.",
                ),
                t(
                    "面積 0 の面は何も足しません。和が 0 のままなら normalize_or_zero() は 0 を返します。",
                    "zero-area faces add nothing; a sum that stays 0 normalises to 0 with normalize_or_zero().",
                ),
            )
        } else if direction_ok {
            (
                t(
                    &format!(
                        "向きは合っていますが、長さが {} です（正規化されていません）。",
                        num(length)
                    ),
                    &format!(
                        "the direction is right but the length is {} (not normalised).",
                        num(length)
                    ),
                ),
                t("足し合わせた後で長さ 1 に正規化します。", "normalise the sum to length 1."),
            )
        } else if max_diff(g, alternative[v]) <= TOLERANCE {
            match weighting {
                Weighting::Area => (
                    t(
                        "単純平均になっています。面積に応じた加重平均では、大きい面ほど重く数えます。",
                        "this is the plain average; the area-weighted one counts larger faces more.",
                    ),
                    t(
                        "正規化する前の外積 (b−a)×(c−a) は長さが面積の 2 倍: それをそのまま足します。",
                        "the cross product (b−a)×(c−a) before normalising is twice the area long: add it as it is.",
                    ),
                ),
                _ => (
                    t(
                        "面積で重み付けされています。この関数は単純平均です。",
                        "this is weighted by area; this function is the plain average.",
                    ),
                    t(
                        "各面の単位法線（長さ 1）を足します。",
                        "add each face's unit normal (length 1).",
                    ),
                ),
            }
        } else {
            (
                t(
                    "隣接する面の法線の平均になっていません。",
                    "this is not the average of the adjacent face normals.",
                ),
                t(
                    "各面 F { a, b, c } の法線を a, b, c の 3 つの頂点に足し、最後に正規化します。法線は (b−a)×(c−a) の向き（反時計回りが表）です。",
                    "add the normal of each face F { a, b, c } to its three vertices a, b, c, then normalise; the normal is along (b−a)×(c−a) (counter-clockwise is the front).",
                ),
            )
        };
        let faces: Vec<String> = mesh
            .faces
            .iter()
            .enumerate()
            .filter(|(_, f)| f.contains(&(v as u32)))
            .map(|(i, _)| format!("F{i}"))
            .collect();
        let faces = faces.join(", ");
        return Err(Failure::new(vec(e), vec(g))
            .at(mesh_at(
                name,
                &format!("、頂点 V{v}（面 {faces}）"),
                &format!(", vertex V{v} (faces {faces})"),
            ))
            .cause(cause)
            .hint(hint));
    }
    Ok(())
}

pub(super) fn average(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    for (name, mesh) in meshes(spec) {
        let got = (imp.vertex_normals)(&StudentMesh::from(&mesh));
        compare(&name, &mesh, &got, Weighting::Uniform, Weighting::Area)?;
    }
    Ok(())
}

pub(super) fn area_weighted(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    for (name, mesh) in meshes(spec) {
        let got = (imp.vertex_normals_area)(&StudentMesh::from(&mesh));
        compare(&name, &mesh, &got, Weighting::Area, Weighting::Uniform)?;
    }
    Ok(())
}

pub(super) fn degenerate(imp: &Impl) -> Result<(), Failure> {
    let mesh = degenerate_fan();
    let got = (imp.vertex_normals)(&StudentMesh::from(&mesh));
    compare(
        &t("面積 0 の面を含む扇形（単純平均）", "fan with zero-area faces (plain average)"),
        &mesh,
        &got,
        Weighting::Uniform,
        Weighting::Area,
    )?;
    let got = (imp.vertex_normals_area)(&StudentMesh::from(&mesh));
    compare(
        &t("面積 0 の面を含む扇形（面積の加重平均）", "fan with zero-area faces (area-weighted)"),
        &mesh,
        &got,
        Weighting::Area,
        Weighting::Uniform,
    )
}
