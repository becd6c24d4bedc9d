use super::*;
use crate::lang::{Lang, Text};

/// Every variant of [`MeshError`] and [`Problem`], and each branch of their messages.
fn samples() -> (Vec<MeshError>, Vec<Problem>) {
    let errors = vec![
        MeshError::IndexOutOfRange { face: 6, corner: 2, index: 9, vertex_count: 5 },
        MeshError::IndexOutOfRange { face: 0, corner: 0, index: 0, vertex_count: 0 },
        MeshError::AttributeLength { attribute: "normals", len: 3, expected: 4 },
        MeshError::AttributeLength { attribute: "uvs", len: 3, expected: 4 },
        MeshError::AttributeLength { attribute: "colors", len: 3, expected: 4 },
        MeshError::NonFinitePosition { vertex: 2, position: Vec3::new(f32::NAN, 0.0, 1.0) },
    ];
    let mut problems: Vec<Problem> = errors.iter().cloned().map(Problem::Structure).collect();
    problems.extend([
        Problem::RepeatedIndex { face: 7, vertices: [1, 1, 3] },
        Problem::ZeroArea { face: 2, vertices: [0, 1, 2] },
        Problem::BoundaryEdge { edge: [1, 3], face: 4 },
        Problem::NonManifoldEdge { edge: [1, 3], faces: vec![0, 3, 6] },
        Problem::NonManifoldEdge { edge: [2, 5], faces: vec![1, 2] },
        Problem::InconsistentWinding { edge: [1, 3], faces: [0, 4] },
        Problem::NonManifoldVertex { vertex: 4, fans: 2 },
        Problem::TJunction { vertex: 5, edge: [0, 2], face: 1 },
        Problem::InwardFacing { signed_volume: -1.5 },
        Problem::ZeroVolume { signed_volume: 1e-12 },
        Problem::UnreferencedVertex { vertex: 8 },
    ]);
    // Exhaustive: a new variant does not compile until it has a sample above.
    for p in &problems {
        match p {
            Problem::Structure(
                MeshError::IndexOutOfRange { .. }
                | MeshError::AttributeLength { .. }
                | MeshError::NonFinitePosition { .. },
            )
            | Problem::RepeatedIndex { .. }
            | Problem::ZeroArea { .. }
            | Problem::BoundaryEdge { .. }
            | Problem::NonManifoldEdge { .. }
            | Problem::InconsistentWinding { .. }
            | Problem::NonManifoldVertex { .. }
            | Problem::TJunction { .. }
            | Problem::InwardFacing { .. }
            | Problem::ZeroVolume { .. }
            | Problem::UnreferencedVertex { .. } => {}
        }
    }
    (errors, problems)
}

/// Both languages' messages of `e` (and `message` gives the same).
fn error_text(e: &MeshError) -> Text {
    let text = e.text();
    assert_eq!([e.message(Lang::Ja), e.message(Lang::En)], [&*text.ja, &*text.en]);
    text
}

/// Both languages' messages of `p` (and `describe` gives the same).
fn problem_text(p: &Problem) -> Text {
    let text = p.text();
    assert_eq!([p.describe(Lang::Ja), p.describe(Lang::En)], [&*text.ja, &*text.en]);
    text
}

#[test]
fn every_message_is_one_clean_line_in_each_language() {
    let (errors, findings) = samples();
    let mut messages = Vec::new();
    for e in &errors {
        let text = error_text(e);
        assert_eq!(e.to_string(), text.en);
        messages.push((format!("{e:?}"), text.ja, text.en));
    }
    for p in &findings {
        let text = problem_text(p);
        messages.push((format!("{p:?}"), text.ja, text.en));
    }
    cg_testkit::text::assert_clean_lines(messages, false, true);
}
