//! The report checker's share of the kit's fuzz test (issue 17): seeded edits of the shipped
//! report table (the lecture's pyramid) go through the parser and the data check.
//!
//! For each edited table: nothing panics; it is done within a bound of time (a hang detector,
//! not a speed measurement); each problem names its line (line 0, "the text", only for what
//! the whole table lacks: no vertex rows, no face rows) and quotes at most a short excerpt; each
//! finding names its line.

use std::path::Path;
use std::time::{Duration, Instant};

use cg_core::lang::{Lang, Text};
use cg_report::parse::{RowKind, polygon_from_text};
use cg_report::verify::verify_data;
use cg_testkit::Inputs;

const PER_INPUT: Duration = Duration::from_secs(10);

fn cases() -> usize {
    if cfg!(debug_assertions) { 1_500 } else { 15_000 }
}

/// `text` with `edits` random edits, weighted to the table's notation.
fn mutate(rng: &mut Inputs, text: &[u8], edits: usize) -> Vec<u8> {
    const SIGNIFICANT: &[u8] = b"VFvf{}(),.-+0123456789eE |\n#naif\xe3\x80";
    let mut bytes = text.to_vec();
    for _ in 0..edits {
        if bytes.is_empty() {
            break;
        }
        let at = rng.int(0, bytes.len() as i64) as usize;
        match rng.int(0, 5) {
            0 => bytes[at] = rng.int(0, 256) as u8,
            1 => bytes[at] = SIGNIFICANT[rng.int(0, SIGNIFICANT.len() as i64) as usize],
            2 => {
                bytes.remove(at);
            }
            3 => bytes.insert(at, bytes[at]),
            _ => bytes.insert(at, b'9'),
        }
    }
    bytes
}

#[test]
fn edited_report_tables_are_checked_or_refused_with_their_line() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/report/lecture-pyramid.md");
    let text = std::fs::read(&path).unwrap();
    let lines = |t: &str| t.lines().count().max(1);
    let mut rng = Inputs::seeded(0x2E9);
    let (mut checked, mut refused) = (0, 0);
    for i in 0..cases() {
        let edited = String::from_utf8_lossy(&mutate(&mut rng, &text, 1 + i % 4)).into_owned();
        let start = Instant::now();
        match polygon_from_text(&edited, Text::new("四角すい", "pyramid")) {
            Ok(polygon) => {
                checked += 1;
                let (report, _) = cg_report::parse::parse_report(&edited);
                let verification = verify_data(&polygon, &report);
                for f in &verification.findings {
                    assert!(
                        (1..=lines(&edited)).contains(&f.line),
                        "finding {:?} at line {}\n--- input:\n{edited}",
                        f.item,
                        f.line
                    );
                }
            }
            Err(problems) => {
                refused += 1;
                assert!(!problems.is_empty());
                for p in &problems {
                    let message = p.message(Lang::En);
                    assert!(
                        p.line >= 1 || p.kind == RowKind::Data,
                        "no line: {message}\n--- input:\n{edited}"
                    );
                    assert!(p.line <= lines(&edited), "{message}\n--- input:\n{edited}");
                    assert!(p.found.chars().count() <= 80, "{message}");
                    assert!(!p.message(Lang::Ja).is_empty());
                }
            }
        }
        let took = start.elapsed();
        assert!(took < PER_INPUT, "one table took {took:?}\n--- input:\n{edited}");
    }
    assert!(checked > 0 && refused > 0, "{checked} edited tables checked, {refused} refused");
}
