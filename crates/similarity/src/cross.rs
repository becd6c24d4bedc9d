//! The cross-variant findings of a class: each submission's numbers, part by part (its files'
//! literals less the stub's, its report's numbers less the template's), read against every
//! variant of the class by both rules — rare single numbers ([`crate::variant`]) and groups of
//! common ones ([`crate::groups`]).

use std::collections::{BTreeMap, BTreeSet};

use cg_harness::StudentNumber;

use crate::groups::{self, ClassGroups, Part};
use crate::variant::{self, Key};
use crate::{Cross, Submission, tokenize};

/// The report templates (`report-template/`, both languages, Markdown and LaTeX), as the kit
/// compiles them into `cg report fill` (cg-report's `template::template`).
const TEMPLATES: [&str; 4] = [
    include_str!("../../../report-template/ja/report.md"),
    include_str!("../../../report-template/en/report.md"),
    include_str!("../../../report-template/ja/report.tex"),
    include_str!("../../../report-template/en/report.tex"),
];

/// Numbers that `cg report fill` writes into every student's report whatever the variant
/// (beyond the templates' own): the texture's 512 × 512 pixels in cells of 64, the course's
/// camera and light, the shading section's fixed cube corner and sphere, and the cosines and
/// sines and round values every report's tables have. Measured as the numbers in every filled
/// report of 200 generated variants, Japanese and English, Markdown and LaTeX
/// (`cargo run --release -p cg-similarity --example measure_numbers --features measure --
/// --filled` prints them).
pub const FILLED: &[f64] = &[
    0.2, 0.3, 0.333, 0.4, 0.5, 0.6, 0.667, 0.866, 0.9, 1.2, 1.5, 1.8, 3.5, 6.0, 7.0, 8.0, 9.0,
    10.0, 11.0, 15.0, 20.0, 30.0, 40.0, 60.0, 64.0, 359.0, 360.0, 512.0,
];

/// A class with at least this many files of an assignment (or reports) also treats as base what
/// at least half of them have: how everyone writes it (the course's camera, `T(0, 0, −15)` and
/// `Rx(30°)`, in every `a3`), as a fingerprint more than `--max-share` submissions have is.
pub const MIN_CLASS: usize = 4;

/// The literals of Rust source, as keys.
#[must_use]
pub fn literals(source: &str) -> BTreeSet<Key> {
    tokenize::tokens(source).iter().filter_map(|t| t.number.and_then(variant::key)).collect()
}

/// The numbers of a report: every number written in it but those inside matrices
/// (`\begin{pmatrix} … \end{pmatrix}`), whose cosines and sines of a few angles every report
/// has and many variants' vertices share (0.309, 0.588, 0.809, 0.951 are a pentagon's).
#[must_use]
pub fn report_numbers(text: &str) -> BTreeSet<Key> {
    let mut plain = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find("\\begin{") {
        plain.push_str(&rest[..at]);
        let after = &rest[at..];
        let env: String = after["\\begin{".len()..].chars().take_while(|c| *c != '}').collect();
        if env.ends_with("matrix") {
            let end = format!("\\end{{{env}}}");
            match after.find(&end) {
                Some(e) => rest = &after[e + end.len()..],
                None => rest = "",
            }
        } else {
            plain.push_str("\\begin{");
            rest = &after["\\begin{".len()..];
        }
    }
    plain.push_str(rest);
    variant::text_numbers(&plain)
}

/// What many keys sets have: the keys in at least half of `sets`, when there are at least
/// [`MIN_CLASS`] of them.
fn common(sets: &[BTreeSet<Key>]) -> BTreeSet<Key> {
    if sets.len() < MIN_CLASS {
        return BTreeSet::new();
    }
    let mut count: BTreeMap<Key, usize> = BTreeMap::new();
    for set in sets {
        for k in set {
            *count.entry(*k).or_default() += 1;
        }
    }
    count.into_iter().filter(|(_, n)| 2 * n >= sets.len()).map(|(k, _)| k).collect()
}

/// The numbers every part of a submission has, which are no one's evidence.
#[derive(Clone, Debug, Default)]
pub struct Bases {
    /// `a1` … → the stub's literals and what most of this year's files have.
    pub code: BTreeMap<String, BTreeSet<Key>>,
    /// The report's: [`report_base`].
    pub report: BTreeSet<Key>,
}

impl Bases {
    /// The bases of `class` with the stubs `stubs`.
    #[must_use]
    pub fn new(class: &[Submission], stubs: &BTreeMap<String, String>) -> Bases {
        let this_year: Vec<&Submission> = class.iter().filter(|s| !s.reference).collect();
        let mut code = BTreeMap::new();
        for m in cg_grade::submission::MODULES {
            let files: Vec<BTreeSet<Key>> =
                this_year.iter().filter_map(|s| s.modules.get(*m).map(|t| literals(t))).collect();
            let mut base = stubs.get(*m).map(|s| literals(s)).unwrap_or_default();
            base.extend(common(&files));
            code.insert((*m).to_owned(), base);
        }
        Bases { code, report: report_base(class) }
    }
}

/// The numbers every report has: the templates' own, what the fill writes for everyone
/// ([`FILLED`]) and, in a class of at least [`MIN_CLASS`] reports, what at least half of this
/// year's reports have.
#[must_use]
pub fn report_base(class: &[Submission]) -> BTreeSet<Key> {
    let mut base: BTreeSet<Key> = TEMPLATES.iter().flat_map(|t| report_numbers(t)).collect();
    base.extend(FILLED.iter().filter_map(|v| variant::key(*v)));
    let reports: Vec<BTreeSet<Key>> = class
        .iter()
        .filter(|s| !s.reference)
        .filter_map(|s| s.report.as_deref().map(report_numbers))
        .collect();
    base.extend(common(&reports));
    base
}

/// The numbers of each part of a submission: its files' numeric literals and its report's
/// numbers, less their bases; the report under `report:a1` … (one entry per assignment, for the
/// single-number rule).
#[must_use]
pub fn numbers(submission: &Submission, bases: &Bases) -> BTreeMap<String, BTreeSet<Key>> {
    let none = BTreeSet::new();
    let mut out = BTreeMap::new();
    for (module, source) in &submission.modules {
        let given = bases.code.get(module).unwrap_or(&none);
        out.insert(module.clone(), literals(source).difference(given).copied().collect());
    }
    if let Some(report) = &submission.report {
        let found: BTreeSet<Key> =
            report_numbers(report).difference(&bases.report).copied().collect();
        for m in cg_grade::submission::MODULES {
            out.insert(format!("{}{m}", variant::REPORT), found.clone());
        }
    }
    out
}

/// The parts of a submission as the group rule reads them: each file against its assignment,
/// the report against every assignment.
#[must_use]
pub fn parts(numbers: &BTreeMap<String, BTreeSet<Key>>, bases: &Bases) -> Vec<Part> {
    let mut out = Vec::new();
    for (name, found) in numbers {
        if name.starts_with(variant::REPORT) {
            continue;
        }
        out.push(Part {
            name: name.clone(),
            assignments: vec![name.clone()],
            numbers: found.clone(),
            base: bases.code.get(name).cloned().unwrap_or_default(),
            report: false,
        });
    }
    let report = numbers.iter().find(|(name, _)| name.starts_with(variant::REPORT));
    if let Some((_, found)) = report {
        out.push(Part {
            name: "report".to_owned(),
            assignments: cg_grade::submission::MODULES.iter().map(|m| (*m).to_owned()).collect(),
            numbers: found.clone(),
            base: bases.report.clone(),
            report: true,
        });
    }
    out
}

/// Every variant of a class, read once: the single-number rule's numbers and weights and the
/// group rule's groups.
pub struct Variants {
    /// Each student's numbers.
    pub numbers: BTreeMap<StudentNumber, variant::VariantNumbers>,
    /// Each number's weight, assignment by assignment.
    pub weights: BTreeMap<String, BTreeMap<Key, f64>>,
    /// Each student's groups.
    pub groups: ClassGroups,
}

impl Variants {
    /// The variants of the students whose files are given.
    #[must_use]
    pub fn new<'a>(files: impl IntoIterator<Item = &'a cg_assign::StudentFile>) -> Variants {
        let mut raw = BTreeMap::new();
        for file in files {
            raw.entry(file.student.clone())
                .or_insert_with(|| variant::raw_numbers(&file.student, file.table));
        }
        let numbers = variant::class_numbers(&raw);
        let weights = variant::weights(&numbers);
        let groups = ClassGroups::new(&numbers);
        Variants { numbers, weights, groups }
    }

    /// Both rules' findings on one submission's numbers (see [`numbers`]).
    #[must_use]
    pub fn findings(
        &self,
        own: &StudentNumber,
        numbers: &BTreeMap<String, BTreeSet<Key>>,
        bases: &Bases,
    ) -> Vec<variant::Finding> {
        if self.numbers.len() < 2 {
            return Vec::new();
        }
        // Rare single numbers in a report only when its own vertex table is not there: an honest
        // report's derived numbers (a pentagon's 0.309 and 0.951 in a turn or a normal) are
        // other variants' vertices.
        let files: BTreeMap<String, BTreeSet<Key>> = numbers
            .iter()
            .filter(|(part, n)| {
                !part.starts_with(variant::REPORT)
                    || !self.groups.own_has(own, "a1 vertices", n, &bases.report)
            })
            .map(|(p, n)| (p.clone(), n.clone()))
            .collect();
        let single = variant::findings(own, &files, &self.numbers, &self.weights);
        let grouped = groups::findings(own, &parts(numbers, bases), &self.groups);
        merge(single, grouped)
    }
}

/// Both rules' findings, one per part: where both flag a part, one finding, naming the student
/// both name, or, when they name different students, all of them and ambiguous.
fn merge(single: Vec<variant::Finding>, grouped: Vec<variant::Finding>) -> Vec<variant::Finding> {
    let mut out: Vec<variant::Finding> = Vec::new();
    for f in single.into_iter().chain(grouped) {
        let Some(same) = out.iter_mut().find(|o| o.part == f.part) else {
            out.push(f);
            continue;
        };
        let named = |x: &variant::Finding| {
            let mut all = vec![x.matches.clone()];
            all.extend(x.also.iter().cloned());
            all
        };
        let agree = !same.ambiguous && !f.ambiguous && same.matches == f.matches;
        if !agree {
            let mut all = named(same);
            all.extend(named(&f).into_iter().filter(|s| *s != same.matches));
            all.sort();
            all.dedup();
            all.retain(|s| *s != same.matches);
            same.ambiguous = same.ambiguous || f.ambiguous || !all.is_empty();
            same.also = all;
        }
        for (k, label) in f.numbers {
            if !same.numbers.iter().any(|(x, _)| *x == k) {
                same.numbers.push((k, label));
            }
        }
        same.numbers.sort();
        same.evidence = same.evidence.max(f.evidence);
        same.groups.extend(f.groups);
    }
    out
}

/// The cross-variant findings of this year's submissions, against every variant of the class
/// (references' included: a copy from an earlier year is found too).
#[must_use]
pub fn cross_variant(class: &[Submission], stubs: &BTreeMap<String, String>) -> Vec<Cross> {
    let variants = Variants::new(class.iter().filter_map(|s| s.student.as_ref()));
    let bases = Bases::new(class, stubs);
    let mut out = Vec::new();
    for (i, s) in class.iter().enumerate() {
        let Some(file) = s.student.as_ref().filter(|_| !s.reference) else { continue };
        let found = variants.findings(&file.student, &numbers(s, &bases), &bases);
        for finding in found {
            let mut sources = sources_of(class, &finding.matches);
            for also in finding.also.iter().filter(|_| finding.ambiguous) {
                sources.extend(sources_of(class, also));
            }
            out.push(Cross { submission: i, finding, sources });
        }
    }
    out
}

fn sources_of(class: &[Submission], student: &StudentNumber) -> Vec<usize> {
    class
        .iter()
        .enumerate()
        .filter(|(_, s)| s.student.as_ref().is_some_and(|f| &f.student == student))
        .map(|(i, _)| i)
        .collect()
}
