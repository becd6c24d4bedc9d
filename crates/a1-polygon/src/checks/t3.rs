//! The checks of task `a1.t3` (`face_normals(spec)`): the count, unit length and values of the
//! face normals.

use cg_core::glam::Vec3;
use cg_core::mesh::Mesh;
use cg_core::normals::face_normal;
use cg_core::notation;
use cg_core::transform::rotate_y;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use crate::Impl;
use crate::spec::Spec;

use super::{NORMAL_TOLERANCE, UNIT_TOLERANCE, close, indexed_mesh, join, listed, no_faces};

fn braces(v: Vec3) -> String {
    notation::braces(v, 4)
}

pub(super) fn normal_count(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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

pub(super) fn normal_unit(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
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
    let not_finite = bad.iter().find(|&&f| !normals[f].is_finite());
    let cause = if let Some(&f) = not_finite {
        // A NaN was said to be a normal not normalised.
        NormalMistake::NotFinite.text(&[], f, normals[f])
    } else if zero {
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

pub(super) fn normal_values(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let normals = (imp.face_normals)(spec);
    let mesh = indexed_mesh(
        spec,
        imp,
        t("先に a1.t2.indices を直してください。", "fix a1.t2.indices first."),
    )?;
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
