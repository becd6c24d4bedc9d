//! Numbers that are common one by one but rare together. Beyond `a1`, a variant's numbers are
//! round values that many variants share (a period of 3 s, a drag of 0.25° per pixel, a texture
//! coordinate of 0.375), so no single one of them is evidence ([`crate::variant`]). A *group* of
//! them — every drag speed and limit of `a2`, every period of `a3`, the texture range of `a4` —
//! is another matter: few variants have the same group, so a submission that has another
//! student's whole group has most likely taken it from that student.
//!
//! **Groups.** Each variant's numbers, by where the variant has them ([`GROUPS`]): the spec's
//! values by their path in its JSON (`a2.pitch.per_px`, `a3.objects[1].motion.period_s`), and
//! what the kit derives from it (`a1 V3.x`, `a4 s_min`). Fields the same for the whole class and
//! 0 are left out (as in [`crate::variant`]), and so are the numbers every submission of that
//! part has anyway: the stub's literals for a file, the report template's for a report
//! ([`crate::report_base`]). A group of fewer than [`MIN_GROUP`] numbers is no group.
//!
//! **The rule.** A part (a file, read against its assignment's groups; or the report, against
//! every assignment's) *has* a variant's group when it has all of its numbers but at most one in
//! five. That counts for another student `S` only when
//!
//! - (a) the group is not the student's own: at least [`MIN_DISTINCT`] of its numbers, and half
//!   of them, are not in the student's own variant (the same values in the own variant are what
//!   an honest student writes), and the part does not have the student's own group of that kind
//!   (then it is their own work there).
//!
//! **The weight.** Each number is as likely to be in the part by chance as the share of the
//! class's variants that have it, times how densely the part has that assignment's other numbers
//! (at least [`MIN_DENSITY`]): a report full of numbers has many variants' groups by chance, a
//! short program few. A student's fit is −ln of the chance of their best group in each
//! assignment, less ln of the number of variants and groups looked at. The best is flagged when
//! that is at least [`MIN_WEIGHT`] and no other student comes within [`RIVAL_GAP`] — unless that
//! student's numbers are a strict part of the best's (a variant whose group is a part of
//! another's fits any copy of the other). When another does come close, the finding names them
//! all and says it cannot tell which: a miss is better than a wrong name. Files are read against
//! the groups a program has ([`Group::code`]); a report against every group but `a1`'s vertices.

use std::collections::{BTreeMap, BTreeSet};

use cg_harness::StudentNumber;

use crate::variant::{Finding, Key, VariantNumbers};

/// One group: its name, its assignment and which labels belong to it.
pub struct Group {
    /// What it is, as the findings name it.
    pub name: &'static str,
    /// The assignment whose numbers it groups.
    pub assignment: &'static str,
    /// Whether a label of that assignment's numbers is in it.
    pub member: fn(&str) -> bool,
    /// Whether a file is read against it (a program has these numbers); a report, which quotes
    /// the assignment, is read against every group.
    pub code: bool,
}

/// The groups, assignment by assignment (a wide group after the narrower ones it holds: a copy
/// of code has the narrow one, a copy of a report quoting the assignment the wide one).
pub const GROUPS: &[Group] = &[
    Group { name: "a1 vertices", assignment: "a1", member: |l| l.starts_with("a1 V"), code: true },
    Group { name: "a1 spec", assignment: "a1", member: |l| l.starts_with("a1."), code: false },
    Group {
        name: "a2 drags and limits",
        assignment: "a2",
        member: |l| {
            l.ends_with("per_px")
                || l.ends_with("_min")
                || l.ends_with("_max")
                || l.ends_with("limit")
        },
        code: true,
    },
    Group { name: "a2 spec", assignment: "a2", member: |l| l.starts_with("a2."), code: false },
    Group { name: "a3 periods", assignment: "a3", member: |l| l.ends_with("period_s"), code: true },
    Group { name: "a3 motions", assignment: "a3", member: |l| l.contains(".motion."), code: true },
    Group { name: "a3 spec", assignment: "a3", member: |l| l.starts_with("a3."), code: false },
    Group {
        name: "a4 texture range",
        assignment: "a4",
        member: |l| l.starts_with("a4 "),
        code: true,
    },
    Group {
        name: "a4 range and pixels",
        assignment: "a4",
        member: |l| l.starts_with("a4 ") || l.starts_with("a4.region.pixels"),
        code: true,
    },
    Group { name: "a4 spec", assignment: "a4", member: |l| l.starts_with("a4"), code: false },
    Group {
        name: "s material",
        assignment: "s",
        member: |l| l.starts_with("s.material"),
        code: true,
    },
    Group { name: "s spec", assignment: "s", member: |l| l.starts_with("s."), code: true },
];

/// The fewest numbers (after the part's base) a group needs.
pub const MIN_GROUP: usize = 3;

/// The fewest numbers of a group that the student's own variant must not have.
pub const MIN_DISTINCT: usize = 2;

/// The least density assumed for a part (see `Chance`).
pub const MIN_DENSITY: f64 = 0.2;

/// The least weight of a flag: −ln of the chance (after every variant and group looked at) that
/// the part has the groups without a copy (5: about 1 in 150).
pub const MIN_WEIGHT: f64 = 5.0;

/// Another student whose weight is within this of the best's makes the finding ambiguous.
pub const RIVAL_GAP: f64 = 2.0;

/// The most students an ambiguous finding names.
pub const MAX_NAMED: usize = 6;

/// One part as the rule reads it.
#[derive(Clone, Debug)]
pub struct Part {
    /// Its name: `a2` (the file), or `report`.
    pub name: String,
    /// The assignments whose groups it is read against.
    pub assignments: Vec<String>,
    /// Its numbers (less its base).
    pub numbers: BTreeSet<Key>,
    /// The numbers every such part has (the stub's literals, the template's numbers).
    pub base: BTreeSet<Key>,
    /// A report (read against every group), not a file.
    pub report: bool,
}

/// Each variant's groups: [`GROUPS`]' order, the keys with their labels.
#[derive(Clone, Debug, Default)]
pub struct ClassGroups {
    sets: BTreeMap<StudentNumber, Vec<BTreeMap<Key, String>>>,
    own: BTreeMap<StudentNumber, BTreeMap<String, BTreeSet<Key>>>,
}

impl ClassGroups {
    /// The groups of every variant of `class`.
    #[must_use]
    pub fn new(class: &BTreeMap<StudentNumber, VariantNumbers>) -> ClassGroups {
        let mut out = ClassGroups::default();
        for (student, v) in class {
            let sets = GROUPS
                .iter()
                .map(|g| {
                    let mut set = BTreeMap::new();
                    for (label, k) in v.labelled.get(g.assignment).into_iter().flatten() {
                        if (g.member)(label) {
                            set.entry(*k).or_insert_with(|| label.clone());
                        }
                    }
                    set
                })
                .collect();
            out.sets.insert(student.clone(), sets);
            let own = v
                .labelled
                .iter()
                .map(|(a, list)| (a.clone(), list.iter().map(|(_, k)| *k).collect()))
                .collect();
            out.own.insert(student.clone(), own);
        }
        out
    }
}

impl ClassGroups {
    /// Whether `numbers` (less `base`) has `own`'s group named `group` (its own work is there).
    #[must_use]
    pub fn own_has(
        &self,
        own: &StudentNumber,
        group: &str,
        numbers: &BTreeSet<Key>,
        base: &BTreeSet<Key>,
    ) -> bool {
        let Some(gi) = GROUPS.iter().position(|g| g.name == group) else { return false };
        self.sets.get(own).is_some_and(|sets| has(&less_base(&sets[gi], base), numbers))
    }
}

/// One student's fit to a part: weight, the numbers it explains, and the groups.
#[derive(Clone, Debug, Default)]
struct Fit {
    weight: f64,
    explained: BTreeMap<Key, String>,
    groups: Vec<&'static str>,
}

/// Whether `part` is read against `g`: a file against the groups a program has, a report against
/// every group but `a1`'s vertices (a report's own turns and normals have the cosines and sines
/// that many variants' vertices are: measured, they named the wrong student).
fn reads(part: &Part, g: &Group) -> bool {
    if part.report { g.name != "a1 vertices" } else { g.code }
}

/// `set` less the numbers of `base`.
fn less_base<'a>(
    set: &'a BTreeMap<Key, String>,
    base: &BTreeSet<Key>,
) -> BTreeMap<Key, &'a String> {
    set.iter().filter(|(k, _)| !base.contains(k)).map(|(k, l)| (*k, l)).collect()
}

/// Whether `part` has `set` but at most one in five of its numbers.
fn has(set: &BTreeMap<Key, &String>, numbers: &BTreeSet<Key>) -> bool {
    let missing = set.keys().filter(|k| !numbers.contains(k)).count();
    set.len() >= MIN_GROUP && missing <= set.len() / 5
}

/// How likely a part is to have a number by chance: an assignment's numbers, each with the
/// share of the class's variants that have it, and how many of them the part has.
struct Chance {
    /// Key → the share of variants that have it (in that assignment, less the base).
    share: BTreeMap<Key, f64>,
    /// The sum of the shares: how many of them a variant has, on average.
    total: f64,
}

impl Chance {
    fn new(class: &ClassGroups, assignment: &str, base: &BTreeSet<Key>) -> Chance {
        let mut count: BTreeMap<Key, usize> = BTreeMap::new();
        for own in class.own.values() {
            for k in own.get(assignment).into_iter().flatten().filter(|k| !base.contains(k)) {
                *count.entry(*k).or_default() += 1;
            }
        }
        let c = class.own.len().max(1) as f64;
        let share: BTreeMap<Key, f64> = count.into_iter().map(|(k, n)| (k, n as f64 / c)).collect();
        let total = share.values().sum();
        Chance { share, total }
    }

    /// −ln of the chance that `numbers` has all of `these` without copying them from `theirs`
    /// (that variant's numbers of the assignment): each number as likely as its share of the
    /// variants times how densely the part has the assignment's other numbers.
    fn surprise(&self, numbers: &BTreeSet<Key>, theirs: &BTreeSet<Key>, these: &[Key]) -> f64 {
        let outside = |k: &Key| !theirs.contains(k);
        let hits = self.share.keys().filter(|k| outside(k) && numbers.contains(k)).count();
        let total: f64 = self.total
            - self.share.iter().filter(|(k, _)| !outside(k)).map(|(_, s)| s).sum::<f64>();
        let density = (hits as f64 / total.max(1.0)).max(MIN_DENSITY);
        these
            .iter()
            .map(|k| -(density * self.share.get(k).copied().unwrap_or(0.0)).clamp(1e-6, 1.0).ln())
            .sum()
    }
}

/// The parts of a submission that have another student's groups, by the module's rule.
#[must_use]
pub fn findings(own: &StudentNumber, parts: &[Part], class: &ClassGroups) -> Vec<Finding> {
    let Some(own_numbers) = class.own.get(own) else { return Vec::new() };
    let Some(own_sets) = class.sets.get(own) else { return Vec::new() };
    let others = class.sets.len().saturating_sub(1);
    if others == 0 {
        return Vec::new();
    }
    let none = BTreeSet::new();
    let mut out = Vec::new();
    for part in parts {
        let mut fits: BTreeMap<&StudentNumber, Fit> = BTreeMap::new();
        let mut tried = 0usize;
        for assignment in &part.assignments {
            let mine = own_numbers.get(assignment).unwrap_or(&none);
            let chance = Chance::new(class, assignment, &part.base);
            // Student → (surprise, group, explained) of this assignment's heaviest group.
            let mut best: BTreeMap<&StudentNumber, (f64, &'static str, BTreeMap<Key, String>)> =
                BTreeMap::new();
            for (gi, g) in GROUPS
                .iter()
                .enumerate()
                .filter(|(_, g)| g.assignment == assignment && reads(part, g))
            {
                // (a) The student's own group is there: the part is their own work here.
                if has(&less_base(&own_sets[gi], &part.base), &part.numbers) {
                    continue;
                }
                tried += 1;
                for (student, sets) in &class.sets {
                    if student == own {
                        continue;
                    }
                    let set = less_base(&sets[gi], &part.base);
                    if !has(&set, &part.numbers) {
                        continue;
                    }
                    let distinct: BTreeMap<Key, String> = set
                        .iter()
                        .filter(|(k, _)| part.numbers.contains(k) && !mine.contains(k))
                        .map(|(k, l)| (*k, (*l).clone()))
                        .collect();
                    if distinct.len() < MIN_DISTINCT || 2 * distinct.len() < set.len() {
                        continue;
                    }
                    let theirs = class.own[student].get(assignment).unwrap_or(&none);
                    let keys: Vec<Key> = distinct.keys().copied().collect();
                    let surprise = chance.surprise(&part.numbers, theirs, &keys);
                    let e = best.entry(student).or_insert((0.0, g.name, BTreeMap::new()));
                    if surprise > e.0 {
                        *e = (surprise, g.name, distinct);
                    }
                }
            }
            for (student, (surprise, group, distinct)) in best {
                let fit = fits.entry(student).or_default();
                fit.weight += surprise;
                fit.explained.extend(distinct);
                fit.groups.push(group);
            }
        }
        // Every other variant and every group tried: the best fit of them all by chance.
        let looked = (others * tried.max(1)) as f64;
        for fit in fits.values_mut() {
            fit.weight -= looked.ln();
        }
        if let Some(finding) = judge(part, fits) {
            out.push(finding);
        }
    }
    out
}

/// The finding of one part from every student's fit: the best, alone or with its rivals.
fn judge(part: &Part, fits: BTreeMap<&StudentNumber, Fit>) -> Option<Finding> {
    let mut fits: Vec<(&StudentNumber, Fit)> = fits.into_iter().collect();
    fits.sort_by(|a, b| {
        b.1.weight
            .total_cmp(&a.1.weight)
            .then(b.1.explained.len().cmp(&a.1.explained.len()))
            .then(a.0.cmp(b.0))
    });
    let (best, fit) = fits.first()?;
    if fit.weight < MIN_WEIGHT {
        return None;
    }
    let rivals: Vec<StudentNumber> = fits[1..]
        .iter()
        .filter(|(_, f)| f.weight + RIVAL_GAP > fit.weight)
        .filter(|(_, f)| {
            // A fit whose numbers are a strict part of the best's is explained by it.
            let inside = f.explained.keys().all(|k| fit.explained.contains_key(k));
            !(inside && f.explained.len() < fit.explained.len())
        })
        .take(MAX_NAMED - 1)
        .map(|(s, _)| (*s).clone())
        .collect();
    let name = if part.name == "report" {
        let mut ids: Vec<&str> = fit.groups.iter().filter_map(|g| g.split(' ').next()).collect();
        ids.dedup();
        format!("{}{}", crate::variant::REPORT, ids.join("+"))
    } else {
        part.name.clone()
    };
    Some(Finding {
        part: name,
        matches: (*best).clone(),
        ambiguous: !rivals.is_empty(),
        also: rivals,
        numbers: fit.explained.iter().map(|(k, l)| (*k, l.clone())).collect(),
        evidence: fit.weight,
        groups: fit.groups.iter().map(|g| (*g).to_owned()).collect(),
        own_evidence: 0.0,
    })
}
