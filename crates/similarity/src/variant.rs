//! What no token matcher can see: every student has their own variant, so a submission whose
//! numbers follow from *another* student's variant was copied from that student, however it
//! was reworded.
//!
//! **A variant's numbers.** Every number of the variant's spec (its JSON, as `cg assignment
//! --json` prints it) and what the kit derives from it: the expected vertices of `a1`, the
//! common period of `a3`, the texture-coordinate range of `a4` (`s = x / 512`, `t = 1 − y / 512`).
//! Numbers are compared by magnitude to 0.001 (a sign and the last digits of an `f32` are no
//! evidence either way). A field whose value is the same for every student of the class (the
//! shading light's position, …) gives nothing away and is left out, as is 0.
//!
//! **A submission's numbers.** The numeric literals of each of its files `exercises/src/<m>.rs`
//! (less those of the stub, which every student has) and every number written in its report.
//!
//! **Rare numbers only.** A number is evidence only when few variants have it in that assignment:
//! at most one in [`RARE`] (at most two in a small class). A rare number that `df` of the
//! class's `C` variants have weighs `ln(C / df)`. A round value that many variants share (a
//! period of 10 s, a radius of 0.5, a texture coordinate of 0.25) is also what any program may
//! write for reasons of its own, so it never counts.
//!
//! **The rule.** For each part (a file against that assignment's numbers, the report against
//! each assignment's numbers in turn) and each other student `S`: the *other-only* numbers are
//! the rare numbers that the part has, that `S`'s variant has and that the student's own variant
//! has not; the *own-only* numbers are the other way round. The best `S` flags the part when
//!
//! - it has at least [`MIN_NUMBERS`] other-only numbers, weighing at least [`MIN_EVIDENCE`];
//! - they weigh at least twice the own-only numbers (a student's own numbers outweigh
//!   coincidences);
//! - they weigh at least [`MIN_COVERAGE`] of all the part's rare numbers that any other variant
//!   has (numbers scattered over many variants fit none in particular).
//!
//! Other students whose variants fit within [`MARGIN`] of the best are named with it (variants
//! with the same dimensions cannot be told apart). A part with none of anyone's numbers (code
//! that reads `spec`, as the solutions do) is never flagged.
//!
//! **What it finds.** Over 200 generated variants it is the weaker rule beyond `a1`: the other
//! assignments' numbers are round values shared by many variants, which [`crate::groups`] reads
//! as groups instead. Both rules' measurement is in docs/instructor-guide.md ("Copies found").

use std::collections::{BTreeMap, BTreeSet};

use cg_assign::{Variants, Which};
use cg_harness::{StudentNumber, TableVersion};

/// The fewest other-only numbers a flag needs.
pub const MIN_NUMBERS: usize = 3;

/// The least total weight of the other-only numbers a flag needs: two numbers that one variant
/// in ten has and a third (3 · ln 10 ≈ 6.9 is well above it); in a class of 7, three numbers that
/// two variants have and one only one has.
pub const MIN_EVIDENCE: f64 = 4.0;

/// The least share of the weight of the numbers that any other variant has (and the own has
/// not) that the best match must have: numbers scattered over many variants, as a program's own
/// constants are, fit none in particular.
pub const MIN_COVERAGE: f64 = 0.6;

/// A number is evidence only when at most one variant in `RARE` has it (at most two variants in
/// a small class, and never all of them).
pub const RARE: usize = 10;

/// Other students whose variants fit within this factor of the best are named too.
pub const MARGIN: f64 = 1.5;

/// The most other students named.
pub const MAX_ALSO: usize = 5;

/// A number as compared: its magnitude in thousandths.
pub type Key = i64;

/// The key of a value (`None` for 0 and what is not finite).
#[must_use]
pub fn key(value: f64) -> Option<Key> {
    if !value.is_finite() || value.abs() > 1e12 {
        return None;
    }
    let k = (value.abs() * 1000.0).round() as i64;
    (k != 0).then_some(k)
}

/// Shows a key as the number it stands for (`0.75`, `12`).
#[must_use]
pub fn show(key: Key) -> String {
    let v = key as f64 / 1000.0;
    let s = format!("{v:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// A variant's numbers before the class is seen: assignment → `(where, value)`.
pub type RawNumbers = BTreeMap<String, Vec<(String, f64)>>;

/// One variant's numbers, part by part: key → where the variant has it (`a1.shape.radius`,
/// `a1 V3.x`).
#[derive(Clone, Debug, Default)]
pub struct VariantNumbers {
    /// `a1` … `s` → the part's numbers.
    pub parts: BTreeMap<String, BTreeMap<Key, String>>,
    /// `a1` … `s` → every labelled number (a key under each of its labels), for the groups of
    /// [`crate::groups`].
    pub labelled: BTreeMap<String, Vec<(String, Key)>>,
}

impl VariantNumbers {
    /// The numbers of `part`: `a1` … `s`, or `report:a1` … (the report, read against one
    /// assignment's numbers).
    #[must_use]
    pub fn part(&self, part: &str) -> BTreeMap<Key, String> {
        self.parts.get(assignment(part)).cloned().unwrap_or_default()
    }
}

/// The prefix of the report's parts: `report:a1` is the report against `a1`'s numbers.
pub const REPORT: &str = "report:";

/// The assignment a part is read against (`report:a1` → `a1`).
#[must_use]
pub fn assignment(part: &str) -> &str {
    part.strip_prefix(REPORT).unwrap_or(part)
}

/// Every number of `student`'s variant, labelled, before the class's constant ones are removed.
#[must_use]
pub fn raw_numbers(student: &StudentNumber, table: TableVersion) -> RawNumbers {
    let variants = Variants::for_student(student, table);
    let mut parts: BTreeMap<String, Vec<(String, f64)>> = BTreeMap::new();
    for which in Which::ALL {
        let mut numbers = Vec::new();
        json_numbers(&variants.spec_json(*which), which.id(), &mut numbers);
        parts.insert(which.id().to_owned(), numbers);
    }
    let a1 = parts.entry("a1".to_owned()).or_default();
    for (k, v) in cg_a1::SpecExt::expected_vertices(&variants.a1).iter().enumerate() {
        for (axis, c) in [("x", v.x), ("y", v.y), ("z", v.z)] {
            a1.push((format!("a1 V{k}.{axis}"), f64::from(c)));
        }
    }
    let a3 = parts.entry("a3".to_owned()).or_default();
    a3.push(("a3 common period (s)".to_owned(), cg_a3::SpecExt::common_period_s(&variants.a3)));
    let a4 = parts.entry("a4".to_owned()).or_default();
    let [x0, y0, x1, y1] = cg_a4::RegionExt::pixels(&variants.a4.region);
    let size = f64::from(cg_a4::IMAGE_PIXELS);
    for (name, v) in [
        ("s_min", f64::from(x0) / size),
        ("s_max", f64::from(x1) / size),
        ("t_min", 1.0 - f64::from(y1) / size),
        ("t_max", 1.0 - f64::from(y0) / size),
    ] {
        a4.push((format!("a4 {name}"), v));
    }
    parts
}

fn json_numbers(value: &serde_json::Value, path: &str, out: &mut Vec<(String, f64)>) {
    match value {
        serde_json::Value::Number(n) => {
            if let Some(v) = n.as_f64() {
                out.push((path.to_owned(), v));
            }
        }
        serde_json::Value::Array(items) => {
            for (i, item) in items.iter().enumerate() {
                json_numbers(item, &format!("{path}[{i}]"), out);
            }
        }
        serde_json::Value::Object(map) => {
            for (k, item) in map {
                json_numbers(item, &format!("{path}.{k}"), out);
            }
        }
        _ => {}
    }
}

/// The class's variants' numbers: each variant's raw numbers less the fields whose value is the
/// same in every variant that has them (the fourth object's colour is the palette's fourth,
/// whoever has a fourth object).
#[must_use]
pub fn class_numbers(
    raw: &BTreeMap<StudentNumber, RawNumbers>,
) -> BTreeMap<StudentNumber, VariantNumbers> {
    // label → the distinct keys it takes, and how many variants have it.
    let mut values: BTreeMap<&str, (BTreeSet<Option<Key>>, usize)> = BTreeMap::new();
    for parts in raw.values() {
        for (label, v) in parts.values().flatten() {
            let e = values.entry(label.as_str()).or_default();
            e.0.insert(key(*v));
            e.1 += 1;
        }
    }
    let constant =
        |label: &str| values.get(label).is_some_and(|(keys, n)| keys.len() == 1 && *n > 1);
    raw.iter()
        .map(|(student, parts)| {
            let mut numbers = VariantNumbers::default();
            for (part, list) in parts {
                let entry = numbers.parts.entry(part.clone()).or_default();
                let labelled = numbers.labelled.entry(part.clone()).or_default();
                for (label, v) in list {
                    if let Some(k) = key(*v).filter(|_| !constant(label)) {
                        entry.entry(k).or_insert_with(|| label.clone());
                        labelled.push((label.clone(), k));
                    }
                }
            }
            (student.clone(), numbers)
        })
        .collect()
}

/// The numbers written in a text (a report): every decimal number, signs and thousands
/// separators aside (`−1.299`, `1,000` is read as 1 and 0).
#[must_use]
pub fn text_numbers(text: &str) -> BTreeSet<Key> {
    let mut out = BTreeSet::new();
    let bytes = text.as_bytes();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_digit() && (i == 0 || !is_word(bytes[i - 1])) {
            let start = i;
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
            if i + 1 < bytes.len() && bytes[i] == b'.' && bytes[i + 1].is_ascii_digit() {
                i += 1;
                while i < bytes.len() && bytes[i].is_ascii_digit() {
                    i += 1;
                }
            }
            if let Some(k) = text[start..i].parse::<f64>().ok().and_then(key) {
                out.insert(k);
            }
        } else {
            i += 1;
        }
    }
    out
}

/// A byte that makes a digit after it part of a word (`V3`, `a1`, `x2`): no number of its own.
fn is_word(b: u8) -> bool {
    b.is_ascii_alphabetic() || b == b'_' || b == b'.'
}

/// One part of a submission that follows from another student's variant.
#[derive(Clone, Debug, PartialEq)]
pub struct Finding {
    /// `a1` … `s`, or `report:a1` … (the report, against that assignment's numbers).
    pub part: String,
    /// Whose variant it follows.
    pub matches: StudentNumber,
    /// Other students' variants that match it as well.
    pub also: Vec<StudentNumber>,
    /// Whether it cannot be told which of `matches` and `also` it follows: none of them is
    /// named alone.
    pub ambiguous: bool,
    /// The other-only numbers and where that variant has them.
    pub numbers: Vec<(Key, String)>,
    /// Their total weight.
    pub evidence: f64,
    /// The groups of [`crate::groups`] it was found by (none: by rare single numbers).
    pub groups: Vec<String>,
    /// The own-only numbers' total weight.
    pub own_evidence: f64,
}

/// Each number's weight, assignment by assignment: `ln(C / df)`, where `df` of the class's `C`
/// variants have the number in that assignment.
#[must_use]
pub fn weights(
    class: &BTreeMap<StudentNumber, VariantNumbers>,
) -> BTreeMap<String, BTreeMap<Key, f64>> {
    let mut df: BTreeMap<String, BTreeMap<Key, usize>> = BTreeMap::new();
    for v in class.values() {
        for (part, numbers) in &v.parts {
            let counts = df.entry(part.clone()).or_default();
            for k in numbers.keys() {
                *counts.entry(*k).or_default() += 1;
            }
        }
    }
    let c = class.len();
    let rare = |n: usize| n <= (c / RARE).max(2) && n < c;
    df.into_iter()
        .map(|(part, counts)| {
            let w = counts
                .into_iter()
                .filter(|(_, n)| rare(*n))
                .map(|(k, n)| (k, (c as f64 / n as f64).ln()))
                .collect();
            (part, w)
        })
        .collect()
}

/// The parts of a submission (its numbers, part by part) that follow from another variant of
/// `class` than `own`'s, by the rule of the module's documentation.
#[must_use]
pub fn findings(
    own: &StudentNumber,
    numbers: &BTreeMap<String, BTreeSet<Key>>,
    class: &BTreeMap<StudentNumber, VariantNumbers>,
    weights: &BTreeMap<String, BTreeMap<Key, f64>>,
) -> Vec<Finding> {
    let Some(own_numbers) = class.get(own) else { return Vec::new() };
    let none = BTreeMap::new();
    let mut out = Vec::new();
    for (part, found) in numbers {
        let weights = weights.get(assignment(part)).unwrap_or(&none);
        let weigh = |keys: &[Key]| {
            // `+ 0.0`: an empty sum is −0.0.
            keys.iter().map(|k| weights.get(k).copied().unwrap_or(0.0)).sum::<f64>() + 0.0
        };
        let mine = own_numbers.part(part);
        // Every other student's case: the other-only numbers, their weight, the own-only weight.
        let mut cases: Vec<Finding> = Vec::new();
        for (student, variant) in class {
            if student == own {
                continue;
            }
            let theirs = variant.part(part);
            let other_only: Vec<Key> = found
                .iter()
                .filter(|k| weights.contains_key(k))
                .filter(|k| theirs.contains_key(k) && !mine.contains_key(k))
                .copied()
                .collect();
            let own_only: Vec<Key> = found
                .iter()
                .filter(|k| weights.contains_key(k))
                .filter(|k| mine.contains_key(k) && !theirs.contains_key(k))
                .copied()
                .collect();
            cases.push(Finding {
                part: part.clone(),
                matches: student.clone(),
                also: Vec::new(),
                ambiguous: false,
                numbers: other_only.iter().map(|k| (*k, theirs[k].clone())).collect(),
                evidence: weigh(&other_only),
                groups: Vec::new(),
                own_evidence: weigh(&own_only),
            });
        }
        cases.sort_by(|a, b| b.evidence.total_cmp(&a.evidence).then(a.matches.cmp(&b.matches)));
        let Some(best) = cases.first() else { continue };
        if best.numbers.len() < MIN_NUMBERS
            || best.evidence < MIN_EVIDENCE
            || best.evidence < 2.0 * best.own_evidence
        {
            continue;
        }
        // The numbers any other variant has and the own has not: the best must explain most of
        // them. Numbers scattered over many variants (a program's own constants) fit none.
        let anyone: BTreeSet<Key> =
            cases.iter().flat_map(|c| c.numbers.iter().map(|(k, _)| *k)).collect();
        let anyone: Vec<Key> = anyone.into_iter().collect();
        if best.evidence < MIN_COVERAGE * weigh(&anyone) {
            continue;
        }
        let close: Vec<StudentNumber> = cases[1..]
            .iter()
            .take_while(|c| c.evidence * MARGIN >= best.evidence)
            .take(MAX_ALSO)
            .map(|c| c.matches.clone())
            .collect();
        let mut finding = best.clone();
        finding.ambiguous = !close.is_empty();
        finding.also = close;
        out.push(finding);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn number(s: &str) -> StudentNumber {
        s.parse().unwrap()
    }

    #[test]
    fn numbers_in_text_are_found_but_not_inside_names() {
        let found = text_numbers("V3 = (1.299, −0.750, 2) and a1 t 0.375; x2 12.5.");
        let shown: Vec<String> = found.iter().map(|k| show(*k)).collect();
        assert_eq!(shown, ["0.375", "0.75", "1.299", "2", "12.5"]);
    }

    #[test]
    fn fields_the_same_for_every_variant_are_left_out() {
        let (a, b) = (number("20260001"), number("20260002"));
        let part = |list: &[(&str, f64)]| {
            BTreeMap::from([(
                "a1".to_owned(),
                list.iter().map(|(l, v)| ((*l).to_owned(), *v)).collect::<Vec<_>>(),
            )])
        };
        let raw = BTreeMap::from([
            (a.clone(), part(&[("same", 2.5), ("differs", 1.25), ("zero", 0.0)])),
            (b.clone(), part(&[("same", 2.5), ("differs", 1.75), ("only b", 3.5)])),
        ]);
        let class = class_numbers(&raw);
        let labels = |s: &StudentNumber| class[s].parts["a1"].values().cloned().collect::<Vec<_>>();
        assert_eq!(labels(&a), ["differs"]);
        assert_eq!(labels(&b), ["differs", "only b"]);
        let w = weights(&class);
        assert!((w["a1"][&1250] - 2f64.ln()).abs() < 1e-12);
        assert!((w["a1"][&3500] - 2f64.ln()).abs() < 1e-12);
    }

    #[test]
    fn round_numbers_a_program_writes_for_itself_are_no_evidence() {
        let mut raw = BTreeMap::new();
        for i in 0..80u32 {
            let s: StudentNumber = format!("{}", 20250000 + i * 7).parse().unwrap();
            raw.insert(s.clone(), raw_numbers(&s, TableVersion::DEFAULT));
        }
        let class = class_numbers(&raw);
        let w = weights(&class);
        // The solutions' own constants (the warm-up's colours, angles and periods), in every part.
        let round: BTreeSet<Key> = [
            0.2, 0.3, 0.4, 0.5, 0.6, 0.9, 1.0, 1.5, 2.0, 3.0, 4.0, 10.0, 15.0, 30.0, 45.0, 90.0,
            360.0,
        ]
        .iter()
        .filter_map(|v| key(*v))
        .collect();
        let numbers: BTreeMap<String, BTreeSet<Key>> =
            Which::ALL.iter().map(|w| (w.id().to_owned(), round.clone())).collect();
        for s in class.keys() {
            let f = findings(s, &numbers, &class, &w);
            assert!(f.is_empty(), "{s}: {f:?}");
        }
    }

    #[test]
    fn the_rule_needs_rare_numbers_that_are_not_the_students_own() {
        let students: Vec<StudentNumber> =
            ["20260001", "20260002", "20260003", "20260004"].iter().map(|s| number(s)).collect();
        let mut raw = BTreeMap::new();
        for s in &students {
            raw.insert(s.clone(), raw_numbers(s, TableVersion::DEFAULT));
        }
        let class = class_numbers(&raw);
        let w = weights(&class);
        // The first student's a1 vertices, submitted by the second.
        let theirs: BTreeSet<Key> = class[&students[0]].parts["a1"]
            .iter()
            .filter(|(_, l)| l.starts_with("a1 V"))
            .map(|(k, _)| *k)
            .collect();
        let numbers = BTreeMap::from([("a1".to_owned(), theirs.clone())]);
        let f = findings(&students[1], &numbers, &class, &w);
        assert_eq!(f.len(), 1, "{f:?}");
        assert_eq!(f[0].matches, students[0]);
        assert!(f[0].numbers.len() >= MIN_NUMBERS && f[0].evidence >= MIN_EVIDENCE);
        // The owner is not flagged for their own numbers.
        assert!(findings(&students[0], &numbers, &class, &w).is_empty());
        // Two numbers are never enough.
        let two: BTreeSet<Key> = f[0].numbers.iter().take(2).map(|(k, _)| *k).collect();
        let few = BTreeMap::from([("a1".to_owned(), two)]);
        assert!(findings(&students[1], &few, &class, &w).is_empty());
        // The same numbers beside the student's own, as many: not clearly another's.
        let mut mixed = theirs;
        mixed.extend(class[&students[1]].parts["a1"].keys());
        let mixed = BTreeMap::from([("a1".to_owned(), mixed)]);
        let f = findings(&students[1], &mixed, &class, &w);
        assert!(f.iter().all(|f| f.evidence >= 2.0 * f.own_evidence), "{f:?}");
    }
}
