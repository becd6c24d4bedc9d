//! Winnowing (Schleimer, Wilkerson and Aiken, "Winnowing: local algorithms for document
//! fingerprinting", SIGMOD 2003; the algorithm of MOSS): hash every run of [`K`] tokens (a
//! k-gram), slide a window over [`W`] consecutive hashes and keep each window's smallest (the
//! rightmost of equal ones), each kept position once.
//!
//! The guarantee: any run of at least `W + K − 1` tokens that two files share holds a whole
//! window of `W` k-grams in both, whose smallest hash both keep, so the two share a
//! fingerprint; and no run shorter than `K` tokens is ever a match.
//!
//! The numbers. Normalised Rust has about 8 to 12 tokens a line (every `.`, `(` and `;` is
//! one). `K = 15` is about a line and a half: short enough that a copied line or two shows, long
//! enough that the idioms every solution has (`let mut v = Vec::new();` is 10 tokens,
//! `(vb - va).cross(vc - va).normalize()` 16) are rarely whole k-grams of their own. `W = 8`
//! keeps about 2 / (W + 1) ≈ 22 % of the k-grams and guarantees every shared run of
//! `W + K − 1 = 22` tokens (two to three lines) is found.

use crate::tokenize::{Kind, Token};

/// Tokens per k-gram.
pub const K: usize = 15;

/// k-grams per window.
pub const W: usize = 8;

/// A fingerprint: a k-gram's hash and where its first token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fingerprint {
    /// The k-gram's hash.
    pub hash: u64,
    /// The index of the k-gram's first token.
    pub at: usize,
}

fn code(kind: Kind) -> u64 {
    match kind {
        Kind::Ident => 1,
        Kind::Keyword(k) => 100 + u64::from(k),
        Kind::Punct(c) => 1_000 + u64::from(c),
        Kind::Open(c) => 200_000 + u64::from(c),
        Kind::Close(c) => 300_000 + u64::from(c),
        Kind::Literal(l) => 400_000 + l as u64,
    }
}

/// SplitMix64's finaliser: every bit of the input moves every bit of the output.
fn mix(mut z: u64) -> u64 {
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// The hash of every k-gram of `tokens` (`len − k + 1` of them; none when shorter than `k`).
#[must_use]
pub fn kgram_hashes(tokens: &[Token], k: usize) -> Vec<u64> {
    if k == 0 || tokens.len() < k {
        return Vec::new();
    }
    let codes: Vec<u64> = tokens.iter().map(|t| code(t.kind)).collect();
    codes
        .windows(k)
        .map(|gram| {
            // FNV-1a over the codes, then mixed.
            let h = gram
                .iter()
                .fold(0xcbf2_9ce4_8422_2325u64, |h, c| (h ^ c).wrapping_mul(0x0000_0100_0000_01b3));
            mix(h)
        })
        .collect()
}

/// The fingerprints winnowing keeps of `hashes` with windows of `w` (`w ≥ 1`): each window's
/// smallest hash, the rightmost of equal ones, each position once, in order. Fewer hashes than
/// `w` make one window.
#[must_use]
pub fn winnow(hashes: &[u64], w: usize) -> Vec<Fingerprint> {
    let w = w.max(1);
    let mut kept: Vec<Fingerprint> = Vec::new();
    if hashes.is_empty() {
        return kept;
    }
    let windows = hashes.len().saturating_sub(w) + 1;
    for start in 0..windows {
        let end = (start + w).min(hashes.len());
        let mut best = start;
        for i in start..end {
            if hashes[i] <= hashes[best] {
                best = i;
            }
        }
        if kept.last().is_none_or(|f| f.at != best) {
            kept.push(Fingerprint { hash: hashes[best], at: best });
        }
    }
    kept
}

/// The fingerprints of `tokens` with [`K`] and [`W`].
#[must_use]
pub fn fingerprints(tokens: &[Token]) -> Vec<Fingerprint> {
    winnow(&kgram_hashes(tokens, K), W)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::tokenize::tokens;
    use std::collections::HashSet;

    /// A token stream from a small alphabet of kinds, seeded.
    fn random_tokens(seed: u64, n: usize) -> Vec<Token> {
        let alphabet = [
            Kind::Ident,
            Kind::Punct('.'),
            Kind::Punct(';'),
            Kind::Open('('),
            Kind::Close(')'),
            Kind::Keyword(3),
        ];
        let mut s = seed;
        (0..n)
            .map(|i| {
                s = mix(s.wrapping_add(0x9e37_79b9_7f4a_7c15));
                Token {
                    kind: alphabet[(s % alphabet.len() as u64) as usize],
                    line: i,
                    number: None,
                }
            })
            .collect()
    }

    fn hashes_of(f: &[Fingerprint]) -> HashSet<u64> {
        f.iter().map(|f| f.hash).collect()
    }

    #[test]
    fn every_shared_run_of_w_plus_k_minus_1_tokens_yields_a_shared_fingerprint() {
        let run = W + K - 1;
        for seed in 0..200u64 {
            // Two unrelated files with the same run of exactly `run` tokens at different places.
            let shared = random_tokens(seed * 3 + 1, run);
            let mut a = random_tokens(seed * 3 + 2, 40);
            let mut b = random_tokens(seed * 3 + 3, 57);
            a.splice(13..13, shared.iter().copied());
            b.splice(31..31, shared.iter().copied());
            let (fa, fb) = (fingerprints(&a), fingerprints(&b));
            let shared_hashes = kgram_hashes(&shared, K);
            let common: Vec<u64> = hashes_of(&fa).intersection(&hashes_of(&fb)).copied().collect();
            assert!(
                common.iter().any(|h| shared_hashes.contains(h)),
                "seed {seed}: no fingerprint of the shared run in both"
            );
        }
    }

    #[test]
    fn every_window_keeps_its_smallest_hash_and_runs_shorter_than_k_never_match() {
        let hashes = [5, 3, 9, 3, 7, 8, 1, 4, 6, 2, 2];
        let kept = winnow(&hashes, 4);
        for start in 0..=hashes.len() - 4 {
            let min = *hashes[start..start + 4].iter().min().unwrap();
            assert!(
                kept.iter().any(|f| f.hash == min && (start..start + 4).contains(&f.at)),
                "window {start}"
            );
        }
        // Rightmost of equal minima, each position once.
        assert_eq!(kept.iter().map(|f| f.at).collect::<Vec<_>>(), [3, 6, 10]);
        // Fewer hashes than a window: one fingerprint, the smallest.
        assert_eq!(winnow(&[4, 2, 3], 8), [Fingerprint { hash: 2, at: 1 }]);
        // Shorter than K tokens: nothing to compare.
        assert!(fingerprints(&random_tokens(1, K - 1)).is_empty());
        assert_eq!(fingerprints(&random_tokens(1, K)).len(), 1);
    }

    #[test]
    fn renamed_code_has_the_same_fingerprints() {
        let a =
            "fn area(w: f32, h: f32) -> f32 { let s = w * h; if s < 0.0 { return -s; } s * 0.5 }";
        let b =
            "fn size(a: f32, b: f32) -> f32 { let p = a * b; if p < 1.0 { return -p; } p * 2.0 }";
        let c = "fn size(a: f32, b: f32) -> f32 { let p = a * b; while p < 1.0 { return -p; } p }";
        let (fa, fb, fc) =
            (fingerprints(&tokens(a)), fingerprints(&tokens(b)), fingerprints(&tokens(c)));
        assert!(!fa.is_empty());
        assert_eq!(fa, fb);
        assert_ne!(hashes_of(&fa), hashes_of(&fc));
    }
}
