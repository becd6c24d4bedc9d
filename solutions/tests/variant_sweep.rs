//! A sweep of the per-student variant space (table version 1): for every assignment, the
//! reference solutions pass every check on every variant (enumerated where the space is small,
//! sampled widely where it is not), the assignment texts in both languages print no odd number,
//! the report derives and fills. The space of a1 and a4 is enumerated from the frozen tables
//! (`*_the_enumeration_is_the_space` checks that every draw is in it).
//!
//! The fast tests run by default (seconds); the wide sweeps are `#[ignore]`d (minutes):
//! `cargo test -p cg-solutions --test variant_sweep -- --ignored --nocapture` (release is ~10×
//! faster: `--release`). `SWEEP_N` sets how many student numbers the sampled sweeps draw.

use std::collections::{BTreeMap, HashSet};
use std::fmt::Write as _;
use std::time::{Duration, Instant};

use cg_assign::{Impls, Variants, Which};
use cg_assign::{cg_a1, cg_a3, cg_a4, cg_shading};
use cg_core::lang::Lang;
use cg_harness::check::CheckResult;
use cg_harness::{StudentNumber, TableVersion};

fn impls() -> Impls {
    cg_assign::impls!(cg_solutions)
}

fn variants(n: u32) -> Variants {
    variants_in(n, TableVersion::V1)
}

fn variants_in(n: u32, table: TableVersion) -> Variants {
    let s: StudentNumber = format!("{n:08}").parse().unwrap();
    Variants::for_student(&s, table)
}

/// `count` student numbers spread over 00000000–99999999: the edge ones first, then a
/// permutation of the whole space (`i·K mod 10⁸`, K coprime to 10⁸) so any prefix is spread.
fn numbers(count: usize) -> Vec<u32> {
    const SPACE: u64 = 100_000_000;
    const K: u64 = 38_196_601;
    let mut out = vec![
        0, 1, 9, 10, 99, 100, 9_999_999, 10_000_000, 12_345_678, 20_250_000, 20_260_000,
        87_654_321, 99_999_998, 99_999_999, 1_000_000, 100_000, 10_000, 1000, 11_111_111,
        22_222_222, 55_555_555, 90_000_000, 99_000_000,
    ];
    let mut i = 0u64;
    while out.len() < count {
        out.push(((i * K + 7) % SPACE) as u32);
        i += 1;
    }
    out.truncate(count);
    out
}

fn sweep_n(default: usize) -> usize {
    std::env::var("SWEEP_N").ok().and_then(|s| s.parse().ok()).unwrap_or(default)
}

/// The failures of one run of the checks, as `id: outcome` lines.
fn failures(results: &[CheckResult]) -> Vec<String> {
    results.iter().filter(|c| !c.passed()).map(|c| format!("{}: {:?}", c.id, c.outcome)).collect()
}

/// Runs `checks` on each `(label, spec)`, collects the failures by check ID and the slowest run.
struct Tally {
    name: &'static str,
    runs: usize,
    failed: BTreeMap<String, (usize, Vec<String>)>,
    slowest: (Duration, String),
    total: Duration,
}

impl Tally {
    fn new(name: &'static str) -> Tally {
        Tally {
            name,
            runs: 0,
            failed: BTreeMap::new(),
            slowest: (Duration::ZERO, String::new()),
            total: Duration::ZERO,
        }
    }

    fn run(&mut self, label: &str, f: impl FnOnce() -> Vec<CheckResult>) {
        let t0 = Instant::now();
        let results = f();
        let dt = t0.elapsed();
        self.runs += 1;
        self.total += dt;
        if dt > self.slowest.0 {
            self.slowest = (dt, label.to_owned());
        }
        for c in results.iter().filter(|c| !c.passed()) {
            let e = self.failed.entry(c.id.clone()).or_default();
            e.0 += 1;
            if e.1.len() < 3 {
                e.1.push(format!("{label}: {:?}", c.outcome));
            }
        }
    }

    fn report(&self) -> String {
        let mut s = format!(
            "{}: {} runs, {:?} in all, slowest {:?} ({})\n",
            self.name, self.runs, self.total, self.slowest.0, self.slowest.1
        );
        for (id, (count, examples)) in &self.failed {
            let _ = writeln!(s, "  FAIL {id}: {count} of {} runs", self.runs);
            for e in examples {
                let _ = writeln!(s, "    {}", e.chars().take(1500).collect::<String>());
            }
        }
        s
    }

    fn assert_clean(&self) {
        println!("{}", self.report());
        assert!(self.failed.is_empty(), "{}", self.report());
    }
}

// ---------------------------------------------------------------------------------------------
// Odd things in the assignment texts.

/// What looks wrong in a text: a negative zero, NaN or infinity, a float printed with its
/// rounding noise, an exponent, a Debug-printed value, an empty placeholder, `1 times`.
fn oddities(text: &str) -> Vec<(&'static str, String)> {
    let mut found = Vec::new();
    let chars: Vec<char> = text.chars().collect();
    let line_of = |i: usize| -> String {
        let start = chars[..i].iter().rposition(|&c| c == '\n').map_or(0, |p| p + 1);
        let end = chars[i..].iter().position(|&c| c == '\n').map_or(chars.len(), |p| i + p);
        chars[start..end].iter().collect()
    };
    for i in 0..chars.len() {
        let c = chars[i];
        let prev = if i > 0 { chars[i - 1] } else { ' ' };
        // −0 / -0 / -0.0 not followed by a non-zero digit.
        if (c == '-' || c == '−') && !prev.is_alphanumeric() && chars.get(i + 1) == Some(&'0') {
            let mut j = i + 2;
            if chars.get(j) == Some(&'.') {
                j += 1;
                while chars.get(j) == Some(&'0') {
                    j += 1;
                }
            }
            if !chars.get(j).is_some_and(|d| d.is_ascii_digit() || *d == '.') {
                found.push(("negative zero", line_of(i)));
            }
        }
        // A range from a value to itself: `A–A`, `8–8`.
        if c == '–'
            && i > 0
            && prev.is_alphanumeric()
            && chars.get(i + 1) == Some(&prev)
            && !chars.get(i + 2).is_some_and(|d| d.is_alphanumeric())
            && !(i >= 2 && chars[i - 2].is_alphanumeric())
        {
            found.push(("range from a value to itself", line_of(i)));
        }
        // Long decimal fractions (rounding noise: 0.30000001, 1.2000000476837158).
        if c == '.' && prev.is_ascii_digit() {
            let digits = chars[i + 1..].iter().take_while(|d| d.is_ascii_digit()).count();
            if digits >= 6 {
                found.push(("long decimal", line_of(i)));
            }
        }
        // Exponent notation: 1e-7, 3e10.
        if (c == 'e' || c == 'E')
            && prev.is_ascii_digit()
            && chars.get(i + 1).is_some_and(|d| d.is_ascii_digit() || *d == '-' || *d == '+')
            && !chars[..i]
                .iter()
                .rev()
                .take_while(|d| d.is_ascii_alphanumeric())
                .any(|d| d.is_ascii_alphabetic())
        {
            found.push(("exponent", line_of(i)));
        }
    }
    for (what, pat) in [
        ("NaN", "NaN"),
        ("infinity", "inf"),
        ("infinity", "∞"),
        ("Debug output", "Some("),
        ("Debug output", " None,"),
        ("Debug output", "Ccw"),
        ("Debug output", "BottomUp"),
        ("Debug output", "TopDown"),
        ("Debug output", "Horizontal"),
        ("Debug output", "Vertical"),
        ("placeholder", "{}"),
        ("placeholder", "{{"),
        ("empty", "( )"),
        ("empty", "（）"),
        ("empty", ": ,"),
        ("empty", "=  "),
        ("one times", " 1 times"),
        ("one times", " 1 repeats"),
        ("one times", "1 回繰り返"),
        ("plural", " 1 pixels"),
        ("plural", " 1 frames"),
        ("plural", " 1 seconds"),
        ("plural", " 1 units"),
        ("plural", " 1 cells"),
        ("plural", " 1 columns"),
        ("plural", " 1 rows"),
        ("plural", " 1 squares"),
        ("plural", " 1 objects"),
        ("plural", " 1 blocks"),
        ("plural", " 1 degrees"),
        ("doubled sign", "+ -"),
        ("doubled sign", "- -"),
        ("doubled sign", "−−"),
        ("doubled sign", "-−"),
        ("doubled sign", "−-"),
        ("doubled sign", "+ −"),
        ("doubled sign", "- −"),
        ("doubled sign", "= --"),
        ("doubled sign", "+= -"),
        ("doubled sign", "-= -"),
        ("doubled sign", "+= −"),
        ("doubled sign", "-= −"),
        ("doubled sign", "(--"),
        ("doubled sign", " --0"),
        ("doubled sign", " --1"),
        ("doubled sign", "+-0"),
        ("doubled sign", "+-1"),
        ("multiply by zero", " 0 * "),
        ("multiply by zero", "= 0 *"),
    ] {
        let mut from = 0;
        while let Some(p) = text[from..].find(pat) {
            let at = from + p;
            let i = text[..at].chars().count();
            // `inf` inside a word (information, infinite) is fine.
            let word = pat == "inf"
                && (text[at + 3..].chars().next().is_some_and(char::is_alphabetic)
                    || text[..at].chars().next_back().is_some_and(char::is_alphabetic));
            if !word {
                found.push((what, line_of(i)));
            }
            from = at + pat.len();
        }
    }
    found
}

/// Each distinct odd line with how often it was seen and the first student who saw it.
type OddLines = BTreeMap<String, (usize, String)>;

/// Collects oddities by (assignment, kind), with the distinct lines and their counts.
#[derive(Default)]
struct Odd {
    seen: BTreeMap<(String, &'static str), OddLines>,
}

impl Odd {
    fn add(&mut self, which: &str, lang: Lang, student: &str, text: &str) {
        for (kind, line) in oddities(text) {
            let key = (format!("{which} {lang:?}"), kind);
            // The line with its digits replaced, so one template counts once.
            let shape: String = line.trim().to_owned();
            let e =
                self.seen.entry(key).or_default().entry(shape).or_insert((0, student.to_owned()));
            e.0 += 1;
        }
    }

    fn assert_clean(&self) {
        assert!(self.seen.is_empty(), "odd texts:\n{}", self.report());
    }

    fn report(&self) -> String {
        let mut s = String::new();
        for ((which, kind), lines) in &self.seen {
            let total: usize = lines.values().map(|v| v.0).sum();
            let _ = writeln!(s, "{which} [{kind}]: {total} times, {} distinct lines", lines.len());
            for (line, (count, student)) in lines.iter().take(6) {
                let _ = writeln!(
                    s,
                    "    {count}× (e.g. {student}): {}",
                    line.chars().take(220).collect::<String>()
                );
            }
        }
        s
    }
}

// ---------------------------------------------------------------------------------------------
// Fast tests (run by default).

/// A few hundred students spread over the space, every assignment: the reference passes every
/// check, the texts print no odd number, the report derives. Seconds in a debug build.
#[test]
fn a_spread_of_students_passes_everything() {
    let imp = impls();
    let mut bad = Vec::new();
    let mut odd = Odd::default();
    for (n, table) in numbers(40).into_iter().flat_map(|n| TableVersion::ALL.map(|t| (n, t))) {
        let v = variants_in(n, table);
        for &w in Which::ALL {
            if w == Which::a3 || w == Which::s {
                continue; // slow: the dedicated sweeps below
            }
            for f in failures(&v.checks(w, &imp)) {
                bad.push(format!("{n:08} table {table} {}: {f}", w.id()));
            }
        }
        for &w in Which::ALL {
            for lang in [Lang::Ja, Lang::En] {
                odd.add(w.id(), lang, &format!("{n:08}/{table}"), &v.describe_one(w, lang));
            }
        }
    }
    assert!(bad.is_empty(), "{bad:#?}");
    odd.assert_clean();
}

// ---------------------------------------------------------------------------------------------
// a1: the space enumerated (every shape of every table × numbering), placements cycled, and
// every placement for one shape of each family.

const RADII: [f32; 4] = [1.0, 1.2, 1.5, 2.0];
const HEIGHTS: [f32; 4] = [1.5, 2.0, 2.5, 3.0];
const POSITIONS: [f32; 8] = [-2.0, -1.5, -1.0, -0.5, 0.5, 1.0, 1.5, 2.0];
const HOVER: [f32; 2] = [0.5, 1.0];

fn a1_shapes() -> Vec<cg_a1::Shape> {
    use cg_a1::{RidgeAxis, Shape};
    let mut v = Vec::new();
    for sides in 3..=8 {
        for &radius in &RADII {
            for &height in &HEIGHTS {
                v.push(Shape::Pyramid { sides, radius, height });
                v.push(Shape::Prism { sides, radius, height });
            }
        }
        for bottom_radius in [1.5, 2.0] {
            for top_radius in [0.5, 0.8, 1.0] {
                for height in [1.0, 1.5, 2.0] {
                    v.push(Shape::Frustum { sides, bottom_radius, top_radius, height });
                }
            }
        }
        for radius in [0.6, 0.8, 1.0] {
            for height in [1.5, 2.0, 2.5] {
                for tip_height in [0.8, 1.0, 1.2] {
                    v.push(Shape::Tower { sides, radius, height, tip_height });
                }
            }
        }
        if sides <= 6 {
            for radius in [1.0, 1.2, 1.5] {
                for lower_height in [0.8, 1.0] {
                    for upper_height in [1.5, 2.0, 2.5] {
                        v.push(Shape::Bipyramid { sides, radius, lower_height, upper_height });
                    }
                }
            }
        }
    }
    for radius in [1.0, 1.2, 1.5] {
        v.push(Shape::Octahedron { radius });
    }
    for width in [2.0, 2.4, 3.0] {
        for depth in [1.6, 2.0, 2.4] {
            for wall_height in [1.2, 1.5, 2.0] {
                for roof_height in [0.6, 0.8, 1.0] {
                    for ridge in [RidgeAxis::X, RidgeAxis::Z] {
                        v.push(Shape::House { width, depth, wall_height, roof_height, ridge });
                    }
                }
            }
        }
    }
    for width in [2.0, 2.5, 3.0] {
        for depth in [1.5, 2.0] {
            for height in [1.0, 1.5, 2.0] {
                v.push(Shape::Wedge { width, depth, height });
            }
        }
    }
    v
}

fn a1_numberings() -> [cg_a1::Numbering; 4] {
    use cg_a1::NumberingExt as _;
    cg_a1::Numbering::all()
}

fn a1_placement(shape: &cg_a1::Shape, i: usize) -> cg_a1::Placement {
    use cg_a1::ShapeExt as _;
    let k = 1 + (i / 64) % 22;
    let angle_deg = 15.0 * (if k >= 12 { k + 1 } else { k }) as f32;
    let y = if shape.pointed_bottom() { HOVER[(i / 1408) % 2] } else { 0.0 };
    cg_a1::Placement { x: POSITIONS[i % 8], y, z: POSITIONS[(i / 8) % 8], angle_deg }
}

/// The a1 shapes the tables can draw (the same count as the sweep enumerates), and every value
/// drawn is one of them: the enumeration is the space.
#[test]
fn a1_the_enumeration_is_the_space() {
    let shapes = a1_shapes();
    assert_eq!(shapes.len(), 96 + 96 + 108 + 162 + 72 + 3 + 162 + 18);
    for n in numbers(3000) {
        let s = variants(n).a1;
        assert!(shapes.contains(&s.shape), "{n:08}: {:?}", s.shape);
        let p = s.placement;
        assert!(POSITIONS.contains(&p.x) && POSITIONS.contains(&p.z), "{n:08}");
        assert!(p.angle_deg % 15.0 == 0.0 && p.angle_deg % 180.0 != 0.0, "{n:08}");
    }
}

#[test]
fn a1_every_shape_and_numbering_passes() {
    let imp = cg_solutions::a1::implementation();
    let mut tally = Tally::new("a1 shapes × numberings");
    let mut i = 0;
    for shape in a1_shapes() {
        for numbering in a1_numberings() {
            let spec = cg_a1::Spec { shape, numbering, placement: a1_placement(&shape, i * 37) };
            i += 1;
            tally.run(&format!("{spec:?}"), || cg_a1::checks(&spec, &imp));
        }
    }
    tally.assert_clean();
}

#[test]
#[ignore]
fn a1_every_placement_passes() {
    let imp = cg_solutions::a1::implementation();
    let mut tally = Tally::new("a1 placements");
    let shapes = a1_shapes();
    // One shape per family (the first of each) and the largest 8-sided ones.
    let mut picked: Vec<cg_a1::Shape> = Vec::new();
    for s in &shapes {
        if !picked.iter().any(|p| std::mem::discriminant(p) == std::mem::discriminant(s)) {
            picked.push(*s);
        }
    }
    for (j, shape) in picked.iter().enumerate() {
        let numbering = a1_numberings()[j % 4];
        for i in 0..(64 * 22 * 2) {
            let spec = cg_a1::Spec { shape: *shape, numbering, placement: a1_placement(shape, i) };
            tally.run(&format!("{spec:?}"), || cg_a1::checks(&spec, &imp));
        }
    }
    tally.assert_clean();
}

// ---------------------------------------------------------------------------------------------
// a2: sampled (the space is ~10¹⁰).

#[test]
#[ignore]
fn a2_sampled_students_pass() {
    let imp = cg_solutions::a2::implementation();
    let mut tally = Tally::new("a2");
    let mut seen = HashSet::new();
    for n in numbers(sweep_n(200_000)) {
        let spec = variants(n).a2;
        if !seen.insert(format!("{spec:?}")) {
            continue;
        }
        tally.run(&format!("{n:08}"), || cg_assign::cg_a2::checks(&spec, &imp));
    }
    tally.assert_clean();
}

// ---------------------------------------------------------------------------------------------
// a3: sampled (slow: ~1 s a variant in debug).

/// Table 2's layouts (the parent hopping through the centre, the orbit around the pair) pass
/// every check of the reference, for a few students of each layout.
#[test]
fn a3_table_2_layouts_pass() {
    let imp = cg_solutions::a3::implementation();
    let mut tally = Tally::new("a3 table 2");
    let mut layouts = std::collections::HashMap::new();
    for n in numbers(200) {
        let spec = variants_in(n, TableVersion::V2).a3;
        let layout: Vec<String> = spec
            .objects
            .iter()
            .map(|o| format!("{:?}", o.motion).split_whitespace().next().unwrap_or("").to_owned())
            .collect();
        let seen = layouts.entry(layout.join(" ")).or_insert(0);
        *seen += 1;
        if *seen == 1 {
            tally.run(&format!("{n:08}"), || cg_a3::checks(&spec, &imp));
        }
        if layouts.len() >= 8 {
            break;
        }
    }
    tally.assert_clean();
}

#[test]
#[ignore]
fn a3_sampled_students_pass() {
    use cg_a3::SpecExt as _;
    let imp = cg_solutions::a3::implementation();
    let mut tally = Tally::new("a3");
    let mut seen = HashSet::new();
    let mut longest = (0.0, String::new());
    for (n, table) in
        numbers(sweep_n(2_000)).into_iter().flat_map(|n| TableVersion::ALL.map(|t| (n, t)))
    {
        let spec = variants_in(n, table).a3;
        let common = spec.common_period_s();
        assert!(common.is_finite() && common > 0.0 && common <= 36.0, "{n:08}: {common}");
        for o in &spec.objects {
            let f = o.motion.period_frames();
            assert_eq!(f as f64, f64::from(o.motion.period_s()) * 60.0, "{n:08}");
        }
        if common > longest.0 {
            longest = (common, format!("{n:08}"));
        }
        if !seen.insert(format!("{spec:?}")) {
            continue;
        }
        tally.run(&format!("{n:08}"), || cg_a3::checks(&spec, &imp));
    }
    println!("a3 longest common period {} s ({})", longest.0, longest.1);
    tally.assert_clean();
}

// ---------------------------------------------------------------------------------------------
// a4: the whole space enumerated (6 984 distinct specs in table 1, 20 952 in table 2).

fn a4_space(table: TableVersion) -> Vec<cg_a4::Spec> {
    let mut out = Vec::new();
    for repeat in [1u32, 2, 5] {
        let sizes: &[u32] = match (table, repeat == 5) {
            (TableVersion::V1, true) => &[1, 2],
            (TableVersion::V1, false) => &[2, 3, 4],
            (TableVersion::V2, true) => &[1, 2, 3],
            (TableVersion::V2, false) => &[1, 2, 3, 4, 5, 6],
        };
        for &columns in sizes {
            for &rows in sizes {
                for column in 0..=(8 - columns) {
                    for row in 0..=(8 - rows) {
                        for rotation_deg in [0u32, 90, 180, 270] {
                            for mirrored in [false, true] {
                                out.push(cg_a4::Spec {
                                    region: cg_a4::Region { column, row, columns, rows },
                                    rotation_deg,
                                    mirrored,
                                    repeat,
                                });
                            }
                        }
                    }
                }
            }
        }
    }
    out
}

#[test]
fn a4_the_enumeration_is_the_space() {
    for (table, size) in [(TableVersion::V1, 6984), (TableVersion::V2, 20_952)] {
        let space: HashSet<String> = a4_space(table).iter().map(|s| format!("{s:?}")).collect();
        assert_eq!(space.len(), size, "table {table}");
        let mut drawn = HashSet::new();
        for n in numbers(3000) {
            let s = format!("{:?}", variants_in(n, table).a4);
            assert!(space.contains(&s), "{n:08}, table {table}: {s}");
            drawn.insert(s);
        }
        // The draws spread over the space (table 2's is three times as wide).
        assert!(drawn.len() > 3000 * 7 / 10, "table {table}: {} distinct of 3000", drawn.len());
    }
}

/// Every a4 variant of table 1 (6 984) and every third of table 2 (6 984 of 20 952, every size,
/// place, orientation and repeat among them): the reference passes every check, and the texts
/// print no odd number. The whole of table 2: `a4_table_2_whole_space_passes` (ignored).
#[test]
fn a4_every_variant_passes() {
    a4_passes(TableVersion::V1, 1);
    a4_passes(TableVersion::V2, 3);
}

#[test]
#[ignore]
fn a4_table_2_whole_space_passes() {
    a4_passes(TableVersion::V2, 1);
}

fn a4_passes(table: TableVersion, step: usize) {
    let imp = cg_solutions::a4::implementation();
    let mut tally = Tally::new(if table == TableVersion::V1 { "a4 table 1" } else { "a4 table 2" });
    let mut odd = Odd::default();
    for spec in a4_space(table).into_iter().step_by(step) {
        tally.run(&format!("{spec:?}"), || cg_a4::checks(&spec, &imp));
        for lang in [Lang::Ja, Lang::En] {
            use cg_a4::SpecExt as _;
            odd.add("a4", lang, &format!("{spec:?}"), &spec.describe(lang));
        }
    }
    tally.assert_clean();
    odd.assert_clean();
}

// ---------------------------------------------------------------------------------------------
// s: every combination of what the images depend on (colour, ks, n, light colour, position,
// ambient, sphere: 9 216), each with one of the 256 (attenuation, spot, medium) combinations in
// turn, so every value of every check's inputs occurs.

fn s_space() -> Vec<cg_shading::Spec> {
    use cg_shading::spec::*;
    let mut out = Vec::new();
    let mut i = 0usize;
    for color in COLORS {
        for ks in SPECULAR {
            for shininess in SHININESS {
                for light_color in LIGHT_COLORS {
                    for position in LIGHT_POSITIONS {
                        for ambient in AMBIENT {
                            for sphere in SPHERES {
                                let attenuation = ATTENUATIONS[i % 4];
                                let cutoff_deg = SPOT_CUTOFFS[(i / 4) % 4];
                                let exponent = SPOT_EXPONENTS[(i / 16) % 4];
                                let medium = MEDIA[(i / 64) % 4];
                                i += 1;
                                out.push(Spec {
                                    material: MaterialSpec { color, ks, shininess },
                                    light: LightSpec { position, color: light_color, ambient },
                                    attenuation,
                                    spot: SpotSpec { cutoff_deg, exponent },
                                    sphere,
                                    medium,
                                });
                            }
                        }
                    }
                }
            }
        }
    }
    out
}

#[test]
#[ignore]
fn s_every_image_combination_passes() {
    let imp = cg_solutions::s::implementation();
    let mut tally = Tally::new("s (9216 image combinations)");
    let space = s_space();
    let limit = sweep_n(space.len()).min(space.len());
    // Spread over the space when limited.
    let step = (space.len() / limit).max(1);
    for spec in space.iter().step_by(step) {
        tally.run(&format!("{spec:?}"), || cg_shading::checks(spec, &imp));
    }
    tally.assert_clean();
}

#[test]
#[ignore]
fn s_sampled_students_pass() {
    let imp = cg_solutions::s::implementation();
    let mut tally = Tally::new("s sampled");
    for n in numbers(sweep_n(300)) {
        let spec = variants(n).s;
        tally.run(&format!("{n:08}"), || cg_shading::checks(&spec, &imp));
    }
    tally.assert_clean();
}

// ---------------------------------------------------------------------------------------------
// The texts, for many students.

#[test]
#[ignore]
fn texts_of_many_students() {
    let mut odd = Odd::default();
    for n in numbers(sweep_n(200_000)) {
        let v = variants(n);
        for &w in Which::ALL {
            for lang in [Lang::Ja, Lang::En] {
                let text = v.describe_one(w, lang);
                odd.add(w.id(), lang, &format!("{n:08}"), &text);
            }
        }
    }
    odd.assert_clean();
}

// ---------------------------------------------------------------------------------------------
// The report: derive, fill (Markdown and LaTeX, ja and en), read back and verify.

#[test]
#[ignore]
fn report_derives_and_fills_for_many_students() {
    use cg_report::fill::{self, Context};
    use cg_report::template::{self, Format};
    use cg_report::{derive, parse, verify};
    let imp = impls();
    let mut problems: BTreeMap<String, (usize, Vec<String>)> = BTreeMap::new();
    let mut note = |kind: String, what: String| {
        let e = problems.entry(kind).or_default();
        e.0 += 1;
        if e.1.len() < 3 {
            e.1.push(what.chars().take(1500).collect());
        }
    };
    let count = sweep_n(1_000);
    let t0 = Instant::now();
    // Every other student on table 2.
    for (i, n) in numbers(count).into_iter().enumerate() {
        let student = format!("{n:08}");
        let a = variants_in(n, TableVersion::ALL[i % TableVersion::ALL.len()]);
        let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| derive::derive(&a, &imp)));
        let Ok((derived, missing)) = r else {
            note("derive panicked".into(), student.clone());
            continue;
        };
        if !missing.is_empty() {
            note("missing".into(), format!("{student}: {missing:?}"));
        }
        for lang in [Lang::Ja, Lang::En] {
            for format in [Format::Markdown, Format::Latex] {
                let assignments = Which::ALL
                    .iter()
                    .filter(|w| w.in_report())
                    .map(|&w| (w.id().to_owned(), a.describe_one(w, lang)))
                    .collect();
                let ctx = Context {
                    student: Some(student.clone()),
                    assignments,
                    variants: Some(a.clone()),
                    ..Context::default()
                };
                let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    template::fill(
                        template::template(lang, format),
                        &fill::values(&derived, &ctx, lang, format),
                    )
                }));
                let text = match r {
                    Err(_) => {
                        note(format!("fill panicked {lang:?} {format:?}"), student.clone());
                        continue;
                    }
                    Ok(Err(e)) => {
                        note(
                            format!("fill error {lang:?} {format:?}"),
                            format!("{student}: {e:?}"),
                        );
                        continue;
                    }
                    Ok(Ok(text)) => text,
                };
                let (parsed, parse_problems) = parse::parse_report(&text);
                if !parse_problems.is_empty() {
                    note(
                        format!("parse problems {lang:?} {format:?}"),
                        format!("{student}: {parse_problems:?}"),
                    );
                }
                let v = verify::verify_with(&parsed, &derived, Some(&a));
                if !v.findings.is_empty() {
                    note(
                        format!("verify findings {lang:?} {format:?}"),
                        format!("{student}: {:?}", v.findings),
                    );
                }
                if !v.notes.is_empty() {
                    note(
                        format!("verify notes {lang:?} {format:?}"),
                        format!(
                            "{student}: {:?}",
                            v.notes.iter().map(|n| &n.en).collect::<Vec<_>>()
                        ),
                    );
                }
            }
        }
    }
    println!("report: {count} students in {:?}", t0.elapsed());
    for (k, (c, ex)) in &problems {
        println!("  {k}: {c}");
        for e in ex {
            println!("    {e}");
        }
    }
    assert!(problems.is_empty());
}

// ---------------------------------------------------------------------------------------------
// a1: the whole space (4 460 544 specs; minutes in release).

#[test]
#[ignore]
fn a1_the_whole_space_passes() {
    use cg_a1::ShapeExt as _;
    let imp = cg_solutions::a1::implementation();
    let mut tally = Tally::new("a1 (whole space)");
    for shape in a1_shapes() {
        let placements = if shape.pointed_bottom() { 2816 } else { 1408 };
        for numbering in a1_numberings() {
            for i in 0..placements {
                let spec = cg_a1::Spec { shape, numbering, placement: a1_placement(&shape, i) };
                tally.run(&format!("{spec:?}"), || cg_a1::checks(&spec, &imp));
            }
        }
    }
    tally.assert_clean();
}
