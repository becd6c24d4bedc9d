//! Deriving the report's data: from the student's own exercises (each assignment's `Impl` and
//! the student's `Spec`), or from data alone (a vertex and face list).

use cg_core::glam::Vec3;
use cg_core::normals::face_normal;
use cg_harness::Text;

use crate::model::PolygonData;

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
