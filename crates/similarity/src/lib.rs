//! # cg-similarity — copies found (`cg similarity`)
//!
//! The course warns that copying another student's program or report is cheating. This crate
//! looks for copies in a class, read as `cg grade` reads it (a folder, a zip, Moodle's
//! "download all submissions": [`read`]):
//!
//! - **Code.** Each student-written file `exercises/src/<m>.rs` is read as Rust tokens with
//!   identifiers and literals normalised ([`tokenize`]) and fingerprinted by winnowing
//!   ([`winnow`]), as MOSS and JPlag do, so renaming, rewording and reordering functions hide
//!   nothing. The stubs as handed out, and the code in their hints, are base code: no match.
//!   A fingerprint more than [`Settings::max_share`] submissions have is how everyone writes it.
//!   A pair's score is the share of the smaller submission's fingerprints that the other has;
//!   the pairs at or above [`Settings::threshold`] with at least [`Settings::min_shared`] shared
//!   fingerprints are listed, with their matching regions and their clusters (the connected
//!   groups of such pairs). Earlier years' submissions come in as references: each is compared
//!   with this year's, never with another reference.
//! - **Numbers.** Every student has their own variant, so a file or report whose numbers
//!   follow from *another* student's variant is flagged, with whose and which numbers
//!   ([`variant`]).
//!
//! A student's report comes from the `--reports` folder ([`read::reports`]) or from inside the
//! submission, where `cg report fill` writes it ([`inside`]); the first when both are there.
//!
//! What it writes: `similarity.csv` and `similarity.html` ([`output`]).

use std::collections::BTreeMap;

use cg_core::lang::Text;

/// The report inside a submission, found as `cg grade` finds it (its module: one finder for both).
pub use cg_grade::inside;
pub mod compare;
pub mod cross;
pub mod groups;
pub mod html;
pub mod output;
pub mod read;
pub mod tokenize;
pub mod variant;
pub mod winnow;

pub use compare::Region;
pub use cross::{numbers, report_base};
pub use variant::Finding;

/// One submission as compared.
#[derive(Clone, Debug, Default)]
pub struct Submission {
    /// The entry's name (its folder or zip, or the Moodle participant's folder).
    pub name: String,
    /// Its `exercises/student.toml`, when readable.
    pub student: Option<cg_assign::StudentFile>,
    /// `a1` … `s` → the text of `exercises/src/<m>.rs`.
    pub modules: BTreeMap<String, String>,
    /// The student's report (Markdown, LaTeX or text), when given: from `--reports`
    /// ([`read::reports`]), else the one inside the submission ([`inside`]).
    pub report: Option<String>,
    /// Where `report` is inside the submission (`report/report.md`), when it came from there.
    pub report_inside: Option<String>,
    /// A report inside the submission that was set aside for the one `--reports` has.
    pub report_set_aside: Option<String>,
    /// The `--reports` file `report` came from, when it came from there.
    pub report_file: Option<String>,
    /// What was skipped while reading it (a report too big or not text), to be shown.
    pub notes: Vec<Text>,
    /// An earlier year's submission: compared with this year's only.
    pub reference: bool,
    /// Why it could not be read, if it could not.
    pub refused: Option<Text>,
    /// Whether `refused` is about `exercises/student.toml` alone (missing, not text, not the
    /// kit's form): the roster can stand in for it ([`read::bind`]).
    pub refused_student_toml: bool,
}

impl Submission {
    /// The student number, or `-`.
    #[must_use]
    pub fn number(&self) -> String {
        self.student.as_ref().map_or_else(|| "-".to_owned(), |s| s.student.to_string())
    }
}

/// The settings of a comparison.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// The least score (shared fingerprints / the smaller submission's) of a listed pair.
    pub threshold: f64,
    /// The fewest shared fingerprints of a listed pair (about 5 tokens each: a short function).
    pub min_shared: usize,
    /// A fingerprint more submissions than this have is common code, not a copy.
    pub max_share: usize,
}

impl Default for Settings {
    /// Threshold 0.5: a copy, renamed and reordered, keeps nearly all its fingerprints (only the
    /// k-grams across a moved function's edges change), while two solutions written apart share
    /// a few idioms (under 7% in the kit's tests). At least 8 shared fingerprints (a
    /// function of about 40 tokens, 4 to 5 lines), and MOSS's default of 10 for `max_share`.
    fn default() -> Settings {
        Settings { threshold: 0.5, min_shared: 8, max_share: 10 }
    }
}

/// A pair of submissions and what they share.
#[derive(Clone, Debug, PartialEq)]
pub struct Pair {
    /// The first submission (an index into the class), the smaller index.
    pub a: usize,
    /// The second.
    pub b: usize,
    /// Shared fingerprints / the smaller submission's fingerprints.
    pub score: f64,
    /// Shared fingerprints.
    pub shared: usize,
    /// The lines of `a` in shared k-grams.
    pub lines_a: usize,
    /// The lines of `b` in shared k-grams.
    pub lines_b: usize,
    /// The matching regions.
    pub regions: Vec<Region>,
    /// Its cluster (1-based), for a listed pair.
    pub cluster: Option<usize>,
}

/// A submission whose numbers follow from another student's variant.
#[derive(Clone, Debug, PartialEq)]
pub struct Cross {
    /// The submission (an index into the class).
    pub submission: usize,
    /// What was found.
    pub finding: Finding,
    /// The submissions of the student whose variant it follows (this year's and references).
    pub sources: Vec<usize>,
}

/// What a comparison found.
#[derive(Clone, Debug, Default)]
pub struct Analysis {
    /// The settings it ran with.
    pub settings: Option<Settings>,
    /// Each submission's fingerprints (after base and common code), in the class's order.
    pub fingerprints: Vec<usize>,
    /// The pairs at or above the threshold, best first.
    pub pairs: Vec<Pair>,
    /// The closest pairs below it (at most 10), best first, for scale.
    pub near: Vec<Pair>,
    /// The clusters: connected groups of listed pairs, as indices into the class.
    pub clusters: Vec<Vec<usize>>,
    /// The cross-variant findings.
    pub cross: Vec<Cross>,
    /// This year's submissions that lost most of their fingerprints (at least half of 20 or
    /// more) as common code, held by more than `max_share` submissions: what a ring of more
    /// copies than `max_share` looks like, which no pair then shows. Said, for a look.
    pub mostly_common: Vec<usize>,
}

impl Analysis {
    /// Whether anything was found (a listed pair or a cross-variant finding).
    #[must_use]
    pub fn found(&self) -> bool {
        !self.pairs.is_empty() || !self.cross.is_empty()
    }
}

/// Compares `class` (this year's submissions and references) with the stubs `stubs` (`a1` … →
/// the text handed out) as base code.
#[must_use]
pub fn analyse(
    class: &[Submission],
    stubs: &BTreeMap<String, String>,
    settings: Settings,
) -> Analysis {
    let base = compare::base_hashes(stubs);
    let mut prints: Vec<compare::Prints> =
        class.iter().map(|s| compare::prints(&s.modules, &base)).collect();
    let before: Vec<usize> = prints.iter().map(compare::Prints::len).collect();
    compare::drop_common(&mut prints, settings.max_share);
    let mostly_common: Vec<usize> = (0..class.len())
        .filter(|&i| !class[i].reference && before[i] >= 20 && prints[i].len() * 2 < before[i])
        .collect();
    let reference: Vec<bool> = class.iter().map(|s| s.reference).collect();
    let counts = compare::shared_counts(&prints, &reference);

    let mut all: Vec<(usize, usize, usize, f64)> = counts
        .into_iter()
        .map(|((a, b), shared)| {
            let smaller = prints[a].len().min(prints[b].len()).max(1);
            (a, b, shared, shared as f64 / smaller as f64)
        })
        .collect();
    all.sort_by(|x, y| y.3.total_cmp(&x.3).then(y.2.cmp(&x.2)).then((x.0, x.1).cmp(&(y.0, y.1))));
    let listed = |&(_, _, shared, score): &(usize, usize, usize, f64)| {
        score >= settings.threshold && shared >= settings.min_shared
    };
    let pair = |&(a, b, shared, score): &(usize, usize, usize, f64)| {
        let (regions, lines_a, lines_b) = compare::regions(&prints[a], &prints[b]);
        Pair {
            a,
            b,
            score,
            shared,
            lines_a: lines_a.len(),
            lines_b: lines_b.len(),
            regions,
            cluster: None,
        }
    };
    let mut pairs: Vec<Pair> = all.iter().filter(|p| listed(p)).map(pair).collect();
    let near: Vec<Pair> = all.iter().filter(|p| !listed(p)).take(10).map(pair).collect();
    let edges: Vec<(usize, usize)> = pairs.iter().map(|p| (p.a, p.b)).collect();
    let clusters = compare::clusters(class.len(), &edges);
    for p in &mut pairs {
        p.cluster = clusters.iter().position(|c| c.contains(&p.a)).map(|c| c + 1);
    }

    Analysis {
        settings: Some(settings),
        fingerprints: prints.iter().map(compare::Prints::len).collect(),
        pairs,
        near,
        clusters,
        cross: cross::cross_variant(class, stubs),
        mostly_common,
    }
}
