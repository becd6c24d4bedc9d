//! A polygon model from a vertex and face list alone ([`polygon_from_text`]): the rows the
//! reader found, numbered without gaps, as the data of the report's checks.

use std::collections::HashSet;

use cg_core::glam::Vec3;
use cg_harness::Text;

use super::{
    ParseProblem, ParsedFace, ParsedVertex, RowKind, clip, expected_number_size, parse_report,
};
use crate::derive::polygon_from_data;
use crate::model::{PolygonData, Written};

/// A vertex row's text as written, for problems: `V3 (-1.0, -0.8, 1.0)`.
fn vertex_text(v: &ParsedVertex) -> String {
    format!("V{} ({}, {}, {})", v.index, v.coords[0].text, v.coords[1].text, v.coords[2].text)
}

fn face_text(f: &ParsedFace) -> String {
    format!("F{} {{ V{}, V{}, V{} }}", f.index, f.vertices[0], f.vertices[1], f.vertices[2])
}

fn as_f32(w: &[Written; 3]) -> Option<Vec3> {
    let v = Vec3::new(w[0].value as f32, w[1].value as f32, w[2].value as f32);
    v.is_finite().then_some(v)
}

/// A polygon model from a vertex and face list alone (a data file, or the tables of a report):
/// the vertex rows and face rows of [`parse_report`] become a [`PolygonData`] through
/// [`polygon_from_data`] (the kit derives each face's normal from the written vertex order), with
/// the written normals as `student_normals` when every face has one.
///
/// # Errors
/// Every problem found: the vertex and face rows' [`ParseProblem`]s, no vertex rows, no face
/// rows, vertex or face numbers that do not run 0, 1, … without gaps, a face naming a vertex that
/// does not exist, a number outside f32's range.
pub fn polygon_from_text(text: &str, name: Text) -> Result<PolygonData, Vec<ParseProblem>> {
    let (report, problems) = parse_report(text);
    let mut errors: Vec<ParseProblem> = problems
        .into_iter()
        .filter(|p| matches!(p.kind, RowKind::Vertex | RowKind::Face | RowKind::Data))
        .collect();
    // A row that did not read is the mistake to name: the checks of the whole list below
    // would blame the rows after it (`F5: F0 is missing` where F0 is written with a NaN).
    if !errors.is_empty() {
        return Err(errors);
    }
    let mut push = |line: usize, found: String, expected: Text| {
        errors.push(ParseProblem { line, found: clip(&found), expected, kind: RowKind::Data });
    };
    if report.vertices.is_empty() {
        push(
            0,
            String::new(),
            Text::new(
                "`V0 (0.0, 1.0, 0.0)` のような頂点の行が 1 つ以上",
                "at least one vertex row like `V0 (0.0, 1.0, 0.0)`",
            ),
        );
    }
    if report.faces.is_empty() {
        push(
            0,
            String::new(),
            Text::new(
                "`F0 { V0, V3, V1 }` のような面の行が 1 つ以上",
                "at least one face row like `F0 { V0, V3, V1 }`",
            ),
        );
    }
    let n = report.vertices.len();
    let m = report.faces.len();
    // The numbers present, as sets: a face names three vertices and every row is looked up
    // once, so the lookups stay O(1) however long the lists are.
    let vertex_numbers: HashSet<u32> = report.vertices.iter().map(|v| v.index).collect();
    let face_numbers: HashSet<u32> = report.faces.iter().map(|f| f.index).collect();
    let has_vertex = |k: u32| vertex_numbers.contains(&k);
    // The first gaps (at most 5) of `0..count`, computed once: the same for every row out of range.
    let missing = |present: &HashSet<u32>, count: usize, letter: char| -> String {
        let gaps: Vec<String> = (0..count)
            .filter_map(|k| u32::try_from(k).ok())
            .filter(|k| !present.contains(k))
            .take(5)
            .map(|k| format!("{letter}{k}"))
            .collect();
        gaps.join(", ")
    };
    let mut missing_vertices: Option<String> = None;
    let mut missing_faces: Option<String> = None;
    let mut vertices = vec![Vec3::ZERO; n];
    for v in &report.vertices {
        if v.index as usize >= n {
            let gaps = missing_vertices.get_or_insert_with(|| missing(&vertex_numbers, n, 'V'));
            push(
                v.line,
                vertex_text(v),
                Text::new(
                    format!("V0 から V{} まで欠けのない頂点番号（{} がありません）", n - 1, gaps),
                    format!("vertex numbers V0 to V{} without gaps ({} is missing)", n - 1, gaps),
                ),
            );
            continue;
        }
        match as_f32(&v.coords) {
            Some(p) => vertices[v.index as usize] = p,
            None => push(v.line, vertex_text(v), expected_number_size()),
        }
    }
    let mut faces = vec![[0u32; 3]; m];
    let mut normals: Vec<Option<Vec3>> = vec![None; m];
    for f in &report.faces {
        if f.index as usize >= m {
            let gaps = missing_faces.get_or_insert_with(|| missing(&face_numbers, m, 'F'));
            push(
                f.line,
                face_text(f),
                Text::new(
                    format!("F0 から F{} まで欠けのない面番号（{} がありません）", m - 1, gaps),
                    format!("face numbers F0 to F{} without gaps ({} is missing)", m - 1, gaps),
                ),
            );
            continue;
        }
        if let Some(&bad) = f.vertices.iter().find(|&&k| !has_vertex(k)) {
            push(
                f.line,
                face_text(f),
                Text::new(
                    format!("頂点の行にある頂点番号（V{bad} という頂点はありません）"),
                    format!("vertex numbers that have vertex rows (there is no V{bad})"),
                ),
            );
            continue;
        }
        faces[f.index as usize] = f.vertices;
        if let Some(w) = &f.normal {
            match as_f32(w) {
                Some(nrm) => normals[f.index as usize] = Some(nrm),
                None => push(f.line, face_text(f), expected_number_size()),
            }
        }
    }
    if !errors.is_empty() {
        errors.sort_by_key(|p| p.line);
        return Err(errors);
    }
    let student_normals = normals.iter().copied().collect::<Option<Vec<Vec3>>>();
    Ok(polygon_from_data(name, vertices, faces, student_normals))
}

/// The lecture's slide (lecture 11, ポリゴンモデルの情報の例 (1) and (2)), verbatim.
#[cfg(test)]
pub(crate) const LECTURE_SLIDE: &str = r"## 頂点座標

V0 (0.0, 1.0, 0.0)

V1 (1.0, -0.8, 1.0)

V2 (1.0, -0.8, -1.0)

V3 (-1.0, -0.8, 1.0)

V4 (-1.0, -0.8, -1.0)

# ポリゴンモデルの情報の例(2)

- 四角すいを構成する頂点と三角面
  - 頂点座標
  - 三角面の頂点、面の法線



| 三角面               | 法線                   |
|-------------------|----------------------|
| F0 { V0, V3, V1 } | { 0.0, 0.53, 0.85 }  |
| F1 { V0, V2, V4 } | { 0.0, 0.53, -0.85 } |
| F2 { V0, V1, V2 } | { 0.85, 0.53, 0.0 }  |
| F3 { V0, V4, V3 } | { -0.85, 0.53, 0.0 } |
| F4 { V1, V3, V2 } | { 0.0, -1.0, 0.0 }   |
| F5 { V4, V2, V3 } | { 0.0, -1.0, 0.0 }   |";

/// The 1-based line of the first line of `text` that contains `needle` (a test oracle that does
/// not use the parser).
#[cfg(test)]
pub(crate) fn line_of(text: &str, needle: &str) -> usize {
    text.lines()
        .position(|l| l.contains(needle))
        .map(|k| k + 1)
        .unwrap_or_else(|| panic!("{needle:?} not in the text"))
}
