//! "Did you mean …?": the closest known word to a misspelt key, choice or material name.

/// The closest of `candidates` to `word` by edit distance (ignoring case), if it is close enough
/// to be a likely typo: at most 1 edit for short words, 2 from 6 letters, 3 from 9.
pub(crate) fn closest<'c>(
    word: &str,
    candidates: impl IntoIterator<Item = &'c str>,
) -> Option<&'c str> {
    let word = word.to_lowercase();
    candidates
        .into_iter()
        .map(|c| (edit_distance(&word, &c.to_lowercase()), c))
        .filter(|&(d, c)| d <= (c.chars().count() / 3).clamp(1, 3))
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// Levenshtein distance between two strings, in characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diagonal = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1).min(row[j] + 1).min(diagonal + usize::from(ca != cb));
            diagonal = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
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
        assert_eq!(edit_distance("gouraud", "goraud"), 1);
        assert_eq!(edit_distance("", "abc"), 3);
    }
}
