//! The matrix reader: a `bmatrix`, `Bmatrix`, `matrix` or `smallmatrix` is read as a `pmatrix`
//! is; a tag's matrix is never taken from past the next tag or section; a matrix written but
//! not read is a problem at its line and is listed as unread, not as missing.

use super::super::{RowKind, parse_report};

const ROWS: &str =
    "0.866 & 0 & 0.5 & 1 \\\\ 0 & 1 & 0 & 2 \\\\ -0.5 & 0 & 0.866 & 3 \\\\ 0 & 0 & 0 & 1";

fn tagged(env: &str) -> String {
    format!("<!-- cg: a2.view.start -->\n$$\n= \\begin{{{env}}} {ROWS} \\end{{{env}}}\n$$\n")
}

#[test]
fn other_brackets_read_as_pmatrix_does() {
    for env in ["pmatrix", "bmatrix", "Bmatrix", "matrix", "smallmatrix"] {
        let (r, problems) = parse_report(&tagged(env));
        assert!(problems.is_empty(), "{env}: {problems:?}");
        assert_eq!(r.matrices.len(), 1, "{env}");
        let m = &r.matrices[0];
        assert_eq!(m.id, "a2.view.start");
        let third: Vec<f64> = m.rows[2].iter().map(|w| w.value).collect();
        assert_eq!(third, [-0.5, 0.0, 0.866, 3.0], "{env}");
        assert_eq!(m.entry_lines[0], [3; 4]);
        assert!(r.unread_matrices.is_empty(), "{env}");
    }
    // A determinant is no matrix: the tag is named as having none.
    let (r, problems) = parse_report(&tagged("vmatrix"));
    assert!(r.matrices.is_empty());
    let got: Vec<(usize, RowKind)> = problems.iter().map(|p| (p.line, p.kind)).collect();
    assert_eq!(got, [(1, RowKind::Matrix)], "{problems:?}");
    assert_eq!(r.unread_matrices, ["a2.view.start"]);
    // … and says why the bars are not read (it said only "no matrix after the tag").
    let said = &problems[0].expected;
    assert!(
        said.en.contains("a `vmatrix` is a determinant's bars")
            && said.en.contains("write `pmatrix` or `bmatrix`"),
        "{said:?}"
    );
    assert!(said.ja.contains("`vmatrix` は行列式の記号"), "{said:?}");
    // Each factor in brackets of its own kind, closed by its own `\end`.
    let text = format!(
        "<!-- cg: a2.view.start.factors -->\n$$ \\begin{{bmatrix}} {ROWS} \\end{{bmatrix}}\n\\begin{{matrix}} {ROWS} \\end{{matrix}} $$\n"
    );
    let (r, problems) = parse_report(&text);
    assert!(problems.is_empty(), "{problems:?}");
    let ids: Vec<&str> = r.matrices.iter().map(|m| m.id.as_str()).collect();
    assert_eq!(ids, ["a2.view.start.factors.1", "a2.view.start.factors.2"]);
}

/// The next product's symbolic matrix (`\cos(-\mathit{camera\_yaw})`, line 7) was taken for a
/// tag whose own matrix was not read: the problem named line 7 and not the tag.
#[test]
fn a_tag_never_takes_the_next_sections_matrix() {
    let symbolic = "\\begin{pmatrix} \\cos(-\\mathit{yaw}) & 0 & 0 & 0 \\\\ 0 & 1 & 0 & 0 \\\\ 0 & 0 & 1 & 0 \\\\ 0 & 0 & 0 & 1 \\end{pmatrix}";
    for title in ["**View after the drag**", "## a3", "\\paragraph{View after the drag}"] {
        let text = format!(
            "<!-- cg: a2.view.start -->\n$$\n= \\left[\\begin{{array}}{{cccc}} {ROWS} \\end{{array}}\\right]\n$$\n\n{title}\n$$\n{symbolic}\n$$\n"
        );
        let (r, problems) = parse_report(&text);
        assert!(r.matrices.is_empty(), "{title}");
        let got: Vec<(usize, RowKind)> = problems.iter().map(|p| (p.line, p.kind)).collect();
        assert_eq!(got, [(1, RowKind::Matrix)], "{title}: {problems:?}");
        assert!(problems[0].expected.en.contains("after the tag"), "{problems:?}");
        assert_eq!(r.unread_matrices, ["a2.view.start"]);
    }
    // With the bmatrix read, the next section's matrix is not looked at.
    let text = format!(
        "{}\n**View after the drag**\n$$\n{symbolic}\n$$\n",
        tagged("bmatrix").replace("0 & 2", "0 & -15")
    );
    let (r, problems) = parse_report(&text);
    assert!(problems.is_empty(), "{problems:?}");
    assert_eq!(r.matrices.len(), 1);
    assert_eq!(r.matrices[0].rows[1][3].text, "-15");
}

/// Entries that are not plain numbers are named at their line, and the tag is listed as read
/// but unreadable (so the check does not also say there is no tagged matrix).
#[test]
fn a_matrix_not_read_is_named_and_listed_as_unread() {
    let text = tagged("pmatrix").replacen("0.866", "\\frac{\\sqrt{3}}{2}", 1);
    let (r, problems) = parse_report(&text);
    assert!(r.matrices.is_empty());
    let got: Vec<(usize, &str)> = problems.iter().map(|p| (p.line, p.found.as_str())).collect();
    assert_eq!(got, [(3, "\\frac{\\sqrt{3}}{2}")], "{problems:?}");
    assert_eq!(r.unread_matrices, ["a2.view.start"]);
    // Not closed before the next tag: named with the `\end` its own environment needs.
    let text = "<!-- cg: a1.transform -->\n$$ \\begin{bmatrix} 1 & 0 \\\\\n$$\n<!-- cg: a2.view.start -->\n";
    let (r, problems) = parse_report(text);
    assert!(problems.iter().any(|p| p.line == 2 && p.expected.en.contains("`\\end{bmatrix}`")));
    assert_eq!(r.unread_matrices, ["a1.transform", "a2.view.start"]);
}
