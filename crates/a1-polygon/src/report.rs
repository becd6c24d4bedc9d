//! The report's data for `a1`: the polygon model (vertex table, face table with each face's
//! normal, the placement) from the student's functions, or from a data file alone.

use cg_core::glam::Vec3;
use cg_core::normals::face_normal;
use cg_core::product::MatrixProduct;
use cg_harness::Text;
use cg_harness::check::guarded;
use cg_harness::report::{Missing, Part, vec3_text};

use crate::{Impl, ShapeExt as _, Spec};

/// The polygon model (assignment 1, or a data file).
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonData {
    /// A name for titles (`六角すい`, `pyramid`).
    pub name: Text,
    /// V0, V1, … in model space.
    pub vertices: Vec<Vec3>,
    /// F0, F1, … as vertex numbers, counter-clockwise seen from outside.
    pub faces: Vec<[u32; 3]>,
    /// Each face's normal as the kit derives it from the vertices (`None`: degenerate).
    pub derived_normals: Vec<Option<Vec3>>,
    /// The student's own face normals (a1.t3), when there are any.
    pub student_normals: Option<Vec<Vec3>>,
    /// The model transform (a1.t4), when there is one.
    pub transform: Option<MatrixProduct>,
}

/// The polygon model from the student's a1 functions: vertices (a1.t1) and faces (a1.t2), the
/// normals the kit derives from them, the student's own normals (a1.t3) and the placement
/// (a1.t4) when those work. A missing or unusable a1.t3 or a1.t4 only leaves its field `None`.
///
/// # Errors
/// a1.t1 or a1.t2 not written, panicking, or returning nothing or a vertex that is not finite.
pub fn polygon(spec: &Spec, imp: &Impl) -> Result<PolygonData, Missing> {
    polygon_part(spec, imp).0
}

/// [`polygon`] with the smaller parts it had to leave out (the student's own normals, the
/// placement): the report data of [`crate::A1`].
pub fn polygon_part(spec: &Spec, imp: &Impl) -> Part<PolygonData> {
    let vertices = match guarded(|| (imp.vertices)(spec)) {
        Ok(v) => v,
        Err(o) => return (Err(Missing::from_outcome("a1.t1", "vertices()", o)), Vec::new()),
    };
    if vertices.is_empty() {
        let why = Text::new("vertices() が頂点を返していません", "vertices() returns no vertices");
        return (Err(Missing::new("a1.t1", why)), Vec::new());
    }
    if let Some(k) = vertices.iter().position(|v| !v.is_finite()) {
        let v = vec3_text(vertices[k]);
        let why = Text::new(
            format!("V{k} {v} が有限の値ではありません"),
            format!("V{k} {v} is not finite"),
        );
        return (Err(Missing::new("a1.t1", why)), Vec::new());
    }
    let faces = match guarded(|| (imp.faces)(spec)) {
        Ok(f) => f,
        Err(o) => return (Err(Missing::from_outcome("a1.t2", "faces()", o)), Vec::new()),
    };
    if faces.is_empty() {
        let why = Text::new("faces() が面を返していません", "faces() returns no faces");
        return (Err(Missing::new("a1.t2", why)), Vec::new());
    }
    let mut notes = Vec::new();
    let student_normals = match guarded(|| (imp.face_normals)(spec)) {
        Ok(n) if n.len() != faces.len() => {
            notes.push(Missing::new(
                "a1.t3",
                Text::new(
                    format!(
                        "face_normals() の法線が {} 個あります（面は {} 個）",
                        n.len(),
                        faces.len()
                    ),
                    format!("face_normals() returns {} normals for {} faces", n.len(), faces.len()),
                ),
            ));
            None
        }
        Ok(n) => match n.iter().position(|v| !v.is_finite()) {
            Some(k) => {
                let v = vec3_text(n[k]);
                notes.push(Missing::new(
                    "a1.t3",
                    Text::new(
                        format!("F{k} の法線 {v} が有限の値ではありません"),
                        format!("F{k}'s normal {v} is not finite"),
                    ),
                ));
                None
            }
            None => Some(n),
        },
        Err(o) => {
            notes.push(Missing::from_outcome("a1.t3", "face_normals()", o));
            None
        }
    };
    let transform = match guarded(|| MatrixProduct::from((imp.model_transform)(spec))) {
        Ok(p) => match p.matrix() {
            Ok(_) => Some(p),
            Err(e) => {
                notes.push(Missing::new(
                    "a1.t4",
                    Text::new(
                        format!("model_transform() の積が行列になりません: {}", e.text().ja),
                        format!("model_transform()'s product is not a matrix: {}", e.text().en),
                    ),
                ));
                None
            }
        },
        Err(o) => {
            notes.push(Missing::from_outcome("a1.t4", "model_transform()", o));
            None
        }
    };
    let name = spec.shape.name();
    let mut data = polygon_from_data(name, vertices, faces, student_normals);
    data.transform = transform;
    (Ok(data), notes)
}

/// A polygon model from data alone: the kit derives each face's normal from the vertices and
/// the order of the face's vertex numbers (`None` for a degenerate face or a vertex number out
/// of range). `student_normals` are the normals the data gives, if any.
#[must_use]
pub fn polygon_from_data(
    name: Text,
    vertices: Vec<Vec3>,
    faces: Vec<[u32; 3]>,
    student_normals: Option<Vec<Vec3>>,
) -> PolygonData {
    let derived_normals = faces
        .iter()
        .map(|f| {
            let v = |k: usize| vertices.get(f[k] as usize).copied();
            match (v(0), v(1), v(2)) {
                (Some(a), Some(b), Some(c)) => face_normal(a, b, c),
                _ => None,
            }
        })
        .collect();
    PolygonData { name, vertices, faces, derived_normals, student_normals, transform: None }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::glam::DVec3;

    // --- a1 ------------------------------------------------------------------------------

    /// A square pyramid (radius 1, height 1.5), bottom up, ring counter-clockwise from above.
    fn pyramid_spec() -> crate::Spec {
        crate::Spec {
            shape: crate::Shape::Pyramid { sides: 4, radius: 1.0, height: 1.5 },
            numbering: crate::Numbering { order: crate::Order::BottomUp, ring: crate::Turn::Ccw },
            placement: crate::Placement { x: 1.0, y: 0.0, z: -1.5, angle_deg: 30.0 },
        }
    }

    fn pyramid_vertices(_: &crate::Spec) -> Vec<Vec3> {
        vec![
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, -1.0),
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(0.0, 1.5, 0.0),
        ]
    }

    fn pyramid_faces(_: &crate::Spec) -> Vec<[u32; 3]> {
        vec![[0, 2, 1], [0, 3, 2], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
    }

    /// The student's own normals: all +Y (wrong, but theirs: the report shows them as given).
    fn up_normals(_: &crate::Spec) -> Vec<Vec3> {
        vec![Vec3::Y; 6]
    }

    fn placement(spec: &crate::Spec) -> cg_student::product::MatrixProduct {
        use cg_student::product::{Factor, MatrixProduct};
        let p = spec.placement;
        MatrixProduct::identity()
            .then(Factor::translate(Vec3::new(p.x, p.y, p.z)))
            .then(Factor::rotate_y_deg(p.angle_deg))
    }

    #[allow(clippy::todo)]
    fn normals_todo(_: &crate::Spec) -> Vec<Vec3> {
        todo!("a1.t3: compute each face's unit normal")
    }

    #[allow(clippy::panic)]
    fn transform_panics(_: &crate::Spec) -> cg_student::product::MatrixProduct {
        panic!("index out of bounds")
    }

    #[test]
    fn a_hand_written_pyramid_derives_the_f64_oracles_normals() {
        let imp = crate::Impl {
            vertices: pyramid_vertices,
            faces: pyramid_faces,
            face_normals: up_normals,
            model_transform: placement,
        };
        let spec = pyramid_spec();
        let p = polygon(&spec, &imp).unwrap();
        assert_eq!(p.name, Text::new("四角すい", "square pyramid"));
        assert_eq!(p.vertices, pyramid_vertices(&spec));
        assert_eq!(p.faces, pyramid_faces(&spec));
        assert_eq!(p.student_normals, Some(vec![Vec3::Y; 6]));
        assert_eq!(p.transform, Some(placement(&spec).into()));
        // The oracle: (Vb − Va) × (Vc − Va) / |…| in f64 from the numbers written above.
        let v = [
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 0.0, -1.0),
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(0.0, 1.5, 0.0),
        ];
        for (k, f) in pyramid_faces(&spec).iter().enumerate() {
            let (a, b, c) = (v[f[0] as usize], v[f[1] as usize], v[f[2] as usize]);
            let n = (b - a).cross(c - a);
            let n = n / n.length();
            let got = p.derived_normals[k].unwrap().as_dvec3();
            assert!((got - n).length() < 1e-6, "F{k}: {got} vs {n}");
        }
        // By hand: the bottom faces down; the side over V0–V1 faces (+x, −z) and up:
        // (V1 − V0) × (V4 − V0) = (−1, 0, −1) × (−1, 1.5, 0) = (1.5, 1, −1.5).
        assert!(p.derived_normals[0].unwrap().abs_diff_eq(Vec3::NEG_Y, 1e-6));
        let side = Vec3::new(1.5, 1.0, -1.5) / (1.5f32 * 1.5 * 2.0 + 1.0).sqrt();
        assert!(p.derived_normals[2].unwrap().abs_diff_eq(side, 1e-6));
    }

    #[test]
    fn a_missing_normal_or_transform_keeps_the_tables() {
        let imp = crate::Impl {
            vertices: pyramid_vertices,
            faces: pyramid_faces,
            face_normals: normals_todo,
            model_transform: transform_panics,
        };
        let (result, notes) = polygon_part(&pyramid_spec(), &imp);
        let p = result.unwrap();
        assert_eq!(p.vertices.len(), 5);
        assert_eq!(p.faces.len(), 6);
        assert!(p.derived_normals.iter().all(Option::is_some));
        assert_eq!((p.student_normals, p.transform), (None, None));
        let tasks: Vec<&str> = notes.iter().map(|m| m.task.as_str()).collect();
        assert_eq!(tasks, ["a1.t3", "a1.t4"]);
        assert!(notes[0].why.en.contains("not written yet"), "{:?}", notes[0]);
        assert!(notes[1].why.en.contains("panicked: index out of bounds"), "{:?}", notes[1]);
    }

    fn one_normal(_: &crate::Spec) -> Vec<Vec3> {
        vec![Vec3::Y]
    }

    fn nan_vertices(_: &crate::Spec) -> Vec<Vec3> {
        vec![Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 0.0), Vec3::X]
    }

    #[test]
    fn unusable_data_is_named() {
        let imp = crate::Impl {
            vertices: pyramid_vertices,
            faces: pyramid_faces,
            face_normals: one_normal,
            model_transform: placement,
        };
        let (result, notes) = polygon_part(&pyramid_spec(), &imp);
        assert_eq!(result.unwrap().student_normals, None);
        assert_eq!(notes[0].task, "a1.t3");
        assert!(notes[0].why.en.contains("1 normals for 6 faces"), "{:?}", notes[0]);
        let imp = crate::Impl { vertices: nan_vertices, ..imp };
        let m = polygon(&pyramid_spec(), &imp).unwrap_err();
        assert_eq!(m.task, "a1.t1");
        assert!(m.why.en.contains("V1"), "{m:?}");
    }

    #[test]
    fn data_alone_derives_the_lecture_pyramids_normals() {
        let v = vec![
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(1.0, -0.8, 1.0),
            Vec3::new(1.0, -0.8, -1.0),
            Vec3::new(-1.0, -0.8, 1.0),
            Vec3::new(-1.0, -0.8, -1.0),
        ];
        let f = vec![[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3], [0, 1, 9]];
        let p = polygon_from_data(Text::new("四角すい", "pyramid"), v, f, None);
        // F0 {V0, V3, V1}: (V3 − V0) × (V1 − V0) = (0, 2, 3.6) / |…| — the lecture's front face.
        let n = p.derived_normals[0].unwrap();
        let len = (4.0f32 + 3.6 * 3.6).sqrt();
        assert!((n - Vec3::new(0.0, 2.0 / len, 3.6 / len)).length() < 1e-6, "{n}");
        assert!(p.derived_normals[4].unwrap().abs_diff_eq(Vec3::NEG_Y, 1e-6));
        assert_eq!(p.derived_normals[6], None, "a vertex number out of range has no normal");
    }
}
