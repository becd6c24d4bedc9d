//! "Did you mean …?": the closest known word to a misspelt key, choice or material name.

/// The closest of `candidates` to `word` by edit distance (ignoring case), if it is close enough
/// to be a likely typo: at most 1 edit for short words, 2 from 6 letters, 3 from 9.
pub(crate) fn closest<'c>(
    word: &str,
    candidates: impl IntoIterator<Item = &'c str>,
) -> Option<&'c str> {
    let word: Vec<char> = word.to_lowercase().chars().collect();
    candidates
        .into_iter()
        .filter_map(|c| {
            let lower: Vec<char> = c.to_lowercase().chars().collect();
            let most = (lower.len() / 3).clamp(1, 3);
            Some((within(&word, &lower, most)?, c))
        })
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// The Levenshtein distance between `a` and `b` where it is at most `most`, else `None`; in
/// time bounded by the shorter one's length times `most` or so, however long the other is (a
/// word of a million characters against thousands of names is answered at once).
fn within(a: &[char], b: &[char], most: usize) -> Option<usize> {
    if a.len().abs_diff(b.len()) > most {
        return None;
    }
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, &ca) in a.iter().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        let mut least = row[0];
        for (j, &cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1).min(row[j] + 1).min(diagonal + usize::from(ca != cb));
            diagonal = row[j + 1];
            row[j + 1] = next;
            least = least.min(next);
        }
        // Every path through this row costs more already.
        if least > most {
            return None;
        }
    }
    Some(row[b.len()]).filter(|&d| d <= most)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggestions_catch_typos_but_not_other_words() {
        let keys = ["radius", "slices", "stacks", "kind"];
        assert_eq!(closest("radiu", keys), Some("radius"));
        assert_eq!(closest("Slices", keys), Some("slices"));
        assert_eq!(closest("knd", keys), Some("kind"));
        assert_eq!(closest("colour", ["color", "ka"]), Some("color"));
        assert_eq!(closest("attenuation", keys), None);
        let chars = |s: &str| s.chars().collect::<Vec<_>>();
        assert_eq!(within(&chars("gouraud"), &chars("goraud"), 3), Some(1));
        assert_eq!(within(&chars(""), &chars("abc"), 3), Some(3));
        assert_eq!(within(&chars("kitten"), &chars("sitting"), 3), Some(3));
        assert_eq!(within(&chars("kitten"), &chars("sitting"), 2), None);
        assert_eq!(within(&chars("abcdef"), &chars("ghijkl"), 3), None);
    }

    #[test]
    fn a_long_word_against_many_names_is_answered_at_once() {
        // Unbounded, this is 10⁴ × 10⁵ × 10² character comparisons (hours); bounded, a glance at
        // each name's length, and at most a few rows for the names of its length.
        let word = "m".repeat(100_000);
        let names: Vec<String> = (0..10_000).map(|i| format!("{i:0>100}")).collect();
        assert_eq!(closest(&word, names.iter().map(String::as_str)), None);
        // A typo is still found among names of its length.
        let near = format!("x{}", names[12]);
        let some = names[..100].iter().map(String::as_str);
        assert_eq!(closest(&near, some), Some(names[12].as_str()));
    }
}
