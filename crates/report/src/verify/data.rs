//! Data-alone mode ([`verify_data`]): a vertex and face list checked against the model it
//! makes itself, where "outward" comes from the geometry of the closed model.

use cg_core::normals::face_normal_f64;
use cg_harness::Text;

use super::{
    Checker, Finding, Relation, Verification, absent, face_outwardness, face_text, missing,
    relation,
};
use crate::model::PolygonData;
use crate::parse::ParsedReport;

/// Data-alone mode: checks the vertex and face rows of `report` against `polygon` (usually read
/// from the same text by [`crate::parse::polygon_from_text`]). Vertices by number; each written
/// face's normal against the normal of its written order (`(V_b − V_a) × (V_c − V_a)`); a face
/// whose written order points its normal into the closed model ([`face_outwardness`]) is an
/// `F4 order` finding with the outward order; a face whose vertices differ from the data's face
/// of that number, or name a vertex that does not exist, is an `F4 vertices` finding. Where the
/// model is not closed (so outward is undefined), a note says which faces could not be judged.
#[must_use]
pub fn verify_data(polygon: &PolygonData, report: &ParsedReport) -> Verification {
    let mut c = Checker::default();
    c.vertices(&report.vertices, &polygon.vertices);
    let outward = face_outwardness(&polygon.vertices, &polygon.faces);
    let mut unjudged = Vec::new();
    let mut absent = Vec::new();
    let n = polygon.vertices.len();
    for f in &report.faces {
        if let Some(&bad) = f.vertices.iter().find(|&&k| k as usize >= n) {
            c.out.findings.push(Finding {
                line: f.line,
                item: format!("F{} vertices", f.index),
                written: face_text(f.vertices),
                derived: format!("V0 … V{}", n.saturating_sub(1)),
                tolerance: None,
                why: Text::new(
                    format!("V{bad} という頂点はありません（頂点は {n} 個）"),
                    format!("there is no V{bad} (the data has {n} vertices)"),
                ),
            });
            continue;
        }
        let out = match polygon.faces.get(f.index as usize) {
            Some(&data) => match relation(f.vertices, data) {
                Relation::Same => outward.get(f.index as usize).copied().flatten(),
                Relation::Reversed => outward.get(f.index as usize).copied().flatten().map(|o| !o),
                Relation::Different => {
                    c.other_vertices(f, data);
                    None
                }
            },
            None => {
                absent.push((f.index, f.line));
                None
            }
        };
        match out {
            Some(false) => c.order(f),
            Some(true) => {}
            None => unjudged.push(format!("F{}", f.index)),
        }
        let [a, b, cc] = f.vertices.map(|k| polygon.vertices[k as usize]);
        c.normal(f, face_normal_f64(a, b, cc));
    }
    absent::rows(&mut c, 'F', &absent, polygon.faces.len());
    if !unjudged.is_empty() {
        // The first few faces by name and the rest counted: a large open model named every
        // face in one line (megabytes).
        let list = missing::named(&unjudged, "面");
        c.note(
            format!("{}: モデルが閉じていない（または面がつながっていない）ので、法線が外向きかどうかは判定できません", list.ja),
            format!("{}: the model is not closed (or the faces are not connected), so whether the normal points outward cannot be judged", list.en),
        );
    }
    missing::tables_missing(&mut c, report);
    c.finish()
}
