//! Fingerprints of whole submissions, base code taken out, and the pairs they share.

use std::collections::{BTreeMap, BTreeSet, HashMap, HashSet};

use crate::tokenize::{Token, comment_code, tokens};
use crate::winnow::{K, W, fingerprints, kgram_hashes};

/// Where one fingerprint of a submission is: its file and its k-gram's lines.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Place {
    /// `a1` … `s`.
    pub module: String,
    /// The index of the k-gram's first token in the file.
    pub at: usize,
    /// The lines of the k-gram's tokens, 1-based, ascending (comments between them are not
    /// part of the match).
    pub lines: Vec<usize>,
}

/// A submission's fingerprints: hash → where (a hash may occur more than once).
#[derive(Clone, Debug, Default)]
pub struct Prints {
    /// Every kept fingerprint's places.
    pub places: HashMap<u64, Vec<Place>>,
}

impl Prints {
    /// The distinct hashes.
    #[must_use]
    pub fn len(&self) -> usize {
        self.places.len()
    }

    /// Whether there is none.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.places.is_empty()
    }
}

/// Base code: every k-gram (not only the winnowed ones) of the stubs and of the code in their
/// comments (the hints), so that nothing a student was given counts as a match.
#[must_use]
pub fn base_hashes(stubs: &BTreeMap<String, String>) -> HashSet<u64> {
    let mut base = HashSet::new();
    for source in stubs.values() {
        base.extend(kgram_hashes(&tokens(source), K));
        for snippet in comment_code(source) {
            base.extend(kgram_hashes(&tokens(&snippet), K));
        }
    }
    base
}

/// The fingerprints of a submission's files, less base code.
#[must_use]
pub fn prints(modules: &BTreeMap<String, String>, base: &HashSet<u64>) -> Prints {
    let mut p = Prints::default();
    for (module, source) in modules {
        let toks: Vec<Token> = tokens(source);
        for f in fingerprints(&toks) {
            if base.contains(&f.hash) {
                continue;
            }
            let mut lines: Vec<usize> =
                toks[f.at..(f.at + K).min(toks.len())].iter().map(|t| t.line).collect();
            lines.sort_unstable();
            lines.dedup();
            p.places.entry(f.hash).or_default().push(Place {
                module: module.clone(),
                at: f.at,
                lines,
            });
        }
    }
    p
}

/// Drops the fingerprints more than `max_share` submissions have (MOSS's `-m`): code that
/// common is how everyone writes it, not a copy.
pub fn drop_common(all: &mut [Prints], max_share: usize) {
    let mut df: HashMap<u64, usize> = HashMap::new();
    for p in all.iter() {
        for h in p.places.keys() {
            *df.entry(*h).or_default() += 1;
        }
    }
    for p in all.iter_mut() {
        p.places.retain(|h, _| df[h] <= max_share);
    }
}

/// How many distinct fingerprints each pair `(i, j)`, `i < j`, shares; pairs of two
/// references (`reference[i] && reference[j]`) are never counted.
#[must_use]
pub fn shared_counts(all: &[Prints], reference: &[bool]) -> BTreeMap<(usize, usize), usize> {
    let mut holders: HashMap<u64, Vec<usize>> = HashMap::new();
    for (i, p) in all.iter().enumerate() {
        for h in p.places.keys() {
            holders.entry(*h).or_default().push(i);
        }
    }
    let mut counts = BTreeMap::new();
    for list in holders.values() {
        for (x, &i) in list.iter().enumerate() {
            for &j in &list[x + 1..] {
                if reference[i] && reference[j] {
                    continue;
                }
                *counts.entry((i.min(j), i.max(j))).or_insert(0) += 1;
            }
        }
    }
    counts
}

/// One matching region of a pair: a run of shared fingerprints in the same order in both.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Region {
    /// The file in the first submission.
    pub module_a: String,
    /// Its lines, first and last.
    pub lines_a: (usize, usize),
    /// The lines of its matching tokens.
    pub marked_a: BTreeSet<usize>,
    /// The file in the second submission.
    pub module_b: String,
    /// Its lines, first and last.
    pub lines_b: (usize, usize),
    /// The lines of its matching tokens.
    pub marked_b: BTreeSet<usize>,
    /// How many shared fingerprints it holds.
    pub fingerprints: usize,
}

/// Lines of a submission: `(module, line)`.
pub type Lines = BTreeSet<(String, usize)>;

/// The matching regions of two submissions and the lines of each that shared k-grams' tokens
/// are on.
#[must_use]
pub fn regions(a: &Prints, b: &Prints) -> (Vec<Region>, Lines, Lines) {
    // Every pairing of a shared hash's places (a few at most: a hash rarely repeats in a file).
    let mut matches: Vec<(&Place, &Place)> = Vec::new();
    for (h, pa) in &a.places {
        if let Some(pb) = b.places.get(h) {
            for x in pa.iter().take(4) {
                for y in pb.iter().take(4) {
                    matches.push((x, y));
                }
            }
        }
    }
    matches.sort_by(|x, y| {
        (&x.0.module, x.0.at, &x.1.module, x.1.at).cmp(&(&y.0.module, y.0.at, &y.1.module, y.1.at))
    });
    let mut lines_a = BTreeSet::new();
    let mut lines_b = BTreeSet::new();
    for (x, y) in &matches {
        lines_a.extend(x.lines.iter().map(|l| (x.module.clone(), *l)));
        lines_b.extend(y.lines.iter().map(|l| (y.module.clone(), *l)));
    }
    // Chain the matches: the next one continues a region when it follows closely in both files.
    let gap = K + W;
    let mut out: Vec<(Region, usize, usize)> = Vec::new();
    for (x, y) in matches {
        let continues = out.iter_mut().rev().take(8).find(|(r, last_a, last_b)| {
            r.module_a == x.module
                && r.module_b == y.module
                && x.at > *last_a
                && x.at <= *last_a + gap
                && y.at > *last_b
                && y.at <= *last_b + gap
        });
        match continues {
            Some((r, last_a, last_b)) => {
                r.marked_a.extend(&x.lines);
                r.marked_b.extend(&y.lines);
                r.fingerprints += 1;
                (*last_a, *last_b) = (x.at, y.at);
            }
            None => out.push((
                Region {
                    module_a: x.module.clone(),
                    lines_a: (0, 0),
                    marked_a: x.lines.iter().copied().collect(),
                    module_b: y.module.clone(),
                    lines_b: (0, 0),
                    marked_b: y.lines.iter().copied().collect(),
                    fingerprints: 1,
                },
                x.at,
                y.at,
            )),
        }
    }
    // The largest first; a region inside a larger one's lines (on either side) is the same code
    // paired again through a repeated k-gram, and a region of one fingerprint beside longer ones
    // is mostly chance.
    let span = |m: &BTreeSet<usize>| {
        (m.first().copied().unwrap_or_default(), m.last().copied().unwrap_or_default())
    };
    let mut found: Vec<Region> = out
        .into_iter()
        .map(|(mut r, _, _)| {
            (r.lines_a, r.lines_b) = (span(&r.marked_a), span(&r.marked_b));
            r
        })
        .collect();
    found.sort_by_key(|r| std::cmp::Reverse(r.fingerprints));
    let inside =
        |m: &str, l: (usize, usize), n: &str, k: (usize, usize)| m == n && k.0 <= l.0 && l.1 <= k.1;
    let longer = found.iter().any(|r| r.fingerprints > 1);
    let mut regions: Vec<Region> = Vec::new();
    for r in found {
        let covered = regions.iter().any(|k| {
            inside(&r.module_a, r.lines_a, &k.module_a, k.lines_a)
                || inside(&r.module_b, r.lines_b, &k.module_b, k.lines_b)
        });
        if !covered && (r.fingerprints > 1 || !longer) {
            regions.push(r);
        }
    }
    regions.sort_by(|x, y| (&x.module_a, x.lines_a).cmp(&(&y.module_a, y.lines_a)));
    (regions, lines_a, lines_b)
}

/// The connected components (of two or more) of `edges` over `n` nodes, each sorted, the
/// components in the order of their smallest node.
#[must_use]
pub fn clusters(n: usize, edges: &[(usize, usize)]) -> Vec<Vec<usize>> {
    let mut parent: Vec<usize> = (0..n).collect();
    fn root(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }
    for &(a, b) in edges {
        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
        if ra != rb {
            parent[ra.max(rb)] = ra.min(rb);
        }
    }
    let mut groups: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
    for x in 0..n {
        let r = root(&mut parent, x);
        groups.entry(r).or_default().push(x);
    }
    groups.into_values().filter(|g| g.len() > 1).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clusters_are_the_connected_components() {
        assert_eq!(clusters(6, &[(0, 3), (3, 5), (1, 2)]), [vec![0, 3, 5], vec![1, 2]]);
        assert!(clusters(3, &[]).is_empty());
    }

    #[test]
    fn two_references_are_never_a_pair_but_a_reference_and_a_submission_are() {
        let source =
            "fn f(a: f32) -> f32 { let b = a * 2.0; let c = b + a; if c > 1.0 { c } else { b } }";
        let modules = BTreeMap::from([("a1".to_owned(), source.to_owned())]);
        let p = prints(&modules, &HashSet::new());
        assert!(!p.is_empty());
        let all = [p.clone(), p.clone(), p];
        let counts = shared_counts(&all, &[true, true, false]);
        assert!(!counts.contains_key(&(0, 1)));
        assert!(counts[&(0, 2)] > 0 && counts[&(1, 2)] > 0);
        // Base code is no match.
        let base = base_hashes(&modules);
        assert!(prints(&modules, &base).is_empty());
    }
}
