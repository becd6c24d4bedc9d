//! The report checker's share of the kit's fuzz test (issue 17): seeded edits of the shipped
//! report table (the lecture's pyramid) go through the parser and the data check.
//!
//! For each edited table: nothing panics; it is done within a bound of time (a hang detector,
//! not a speed measurement); each problem names its line (line 0, "the text", only for what
//! the whole table lacks: no vertex rows, no face rows) and quotes at most a short excerpt; each
//! finding names its line.
//!
//! The same for the tagged periods table of a3 and the tagged texture formula of a4 as `report
//! fill` writes them (both languages, both formats) and a formula in other notations: every
//! edit reads and checks without a panic and in bounded time; each finding, and each note about
//! a formula that does not read, names a line of the text.

use std::path::Path;
use std::time::{Duration, Instant};

use cg_assign::Variants;
use cg_assign::cg_a4::report::texture;
use cg_assign::cg_a4::{CORNER_STEPS, Impl, Region, Sampler, Spec, TexRange};
use cg_core::glam::Vec2;
use cg_core::lang::{Lang, Text};
use cg_harness::{StudentNumber, TableVersion};
use cg_report::model::Derived;
use cg_report::parse::{RowKind, parse_report, polygon_from_text};
use cg_report::template::Format;
use cg_report::verify::{verify_data, verify_with};
use cg_report::{formula, periods};
use cg_testkit::Inputs;

const PER_INPUT: Duration = Duration::from_secs(10);

fn cases() -> usize {
    if cfg!(debug_assertions) { 1_500 } else { 15_000 }
}

/// `text` with `edits` random edits, weighted to the table's notation.
fn mutate(rng: &mut Inputs, text: &[u8], edits: usize) -> Vec<u8> {
    mutate_with(rng, text, edits, b"VFvf{}(),.-+0123456789eE |\n#naif\xe3\x80")
}

/// `text` with `edits` random edits, weighted to the bytes of `significant`.
fn mutate_with(rng: &mut Inputs, text: &[u8], edits: usize, significant: &[u8]) -> Vec<u8> {
    let mut bytes = text.to_vec();
    for _ in 0..edits {
        if bytes.is_empty() {
            break;
        }
        let at = rng.int(0, bytes.len() as i64) as usize;
        match rng.int(0, 5) {
            0 => bytes[at] = rng.int(0, 256) as u8,
            1 => bytes[at] = significant[rng.int(0, significant.len() as i64) as usize],
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

fn range(_: &Spec) -> TexRange {
    TexRange { s_min: 0.25, s_max: 0.5, t_min: 0.375, t_max: 0.625 }
}

fn sampler() -> Sampler {
    Sampler::default()
}

/// C4–D5 turned 90°, 2 × 2 blocks: s = 0.5 − 0.05·(j mod 5), t = 0.625 − 0.05·(i mod 5).
fn coords(_: &Spec, i: u32, j: u32) -> [Vec2; 4] {
    CORNER_STEPS.map(|(di, dj)| {
        let (p, q) = ((i % 5 + di) as f32 / 5.0, (j % 5 + dj) as f32 / 5.0);
        Vec2::new(0.5 - 0.25 * q, 0.625 - 0.25 * p)
    })
}

#[test]
fn edited_periods_and_formulas_are_checked_or_noted_with_their_line() {
    let student: StudentNumber = "20260002".parse().unwrap();
    let a = Variants::for_student(&student, TableVersion::V1);
    let region = Region { column: 2, row: 3, columns: 2, rows: 2 };
    let spec = Spec { region, rotation_deg: 90, mirrored: false, repeat: 2 };
    let tex = texture(&spec, &Impl { tex_range: range, tex_coords: coords, sampler }).unwrap();
    let mut text = String::new();
    for lang in [Lang::Ja, Lang::En] {
        for format in [Format::Markdown, Format::Latex] {
            text.push_str(&periods::values(&a.a3, lang, format));
            text.push_str("\n## next\n\n");
            text.push_str(&formula::values(&tex, lang, format));
            text.push_str("\n## next\n\n");
        }
    }
    text.push_str(
        "<!-- cg: a4.formula -->\n$s = \\frac{j \\bmod 5}{-20} + 0.5$, $t(i, j) = 0.625 - 0.05 (i % 5)$\n",
    );
    let derived = Derived { a4: Some(tex), ..Derived::default() };
    let clean = verify_with(&parse_report(&text).0, &derived, Some(&a));
    assert!(clean.findings.is_empty(), "{:#?}", clean.findings);
    let lines = |t: &str| t.lines().count().max(1);
    let mut rng = Inputs::seeded(0x15);
    let (mut found, mut unread) = (0, 0);
    for i in 0..cases() / 3 {
        let bytes = mutate_with(
            &mut rng,
            text.as_bytes(),
            1 + i % 6,
            b"stij=+-*/()\\{}|&%$., 0123456789\nmodfrac",
        );
        let edited = String::from_utf8_lossy(&bytes).into_owned();
        let start = Instant::now();
        let (report, problems) = parse_report(&edited);
        for p in &problems {
            assert!((1..=lines(&edited)).contains(&p.line), "{}", p.message(Lang::En));
        }
        let v = verify_with(&report, &derived, Some(&a));
        found += v.findings.len();
        for f in &v.findings {
            assert!((1..=lines(&edited)).contains(&f.line), "{f:?}\n--- input:\n{edited}");
            assert!(!f.message(Lang::Ja).is_empty() && !f.message(Lang::En).is_empty());
        }
        for n in &v.notes {
            assert!(!n.ja.is_empty() && !n.en.is_empty());
            if let Some(rest) = n.en.strip_prefix("could not read the formula at line ") {
                unread += 1;
                let line: usize = rest.split(':').next().unwrap().parse().unwrap();
                assert!((1..=lines(&edited)).contains(&line), "{}\n--- input:\n{edited}", n.en);
            }
        }
        // Every equation that reads evaluates anywhere without a panic.
        for eq in formula::equations(&edited, 1) {
            if let Ok(e) = &eq.expr {
                let _ = e.eval(10.0, 5.0);
                let _ = e.eval(-1.0, f64::NAN);
            }
        }
        let took = start.elapsed();
        assert!(took < PER_INPUT, "one text took {took:?}\n--- input:\n{edited}");
    }
    assert!(found > 0 && unread > 0, "{found} findings, {unread} unreadable formulas");
}
