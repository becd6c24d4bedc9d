//! Per-student variants (like the course's `opengl_report2019.exe`): every assignment's variant is
//! a deterministic function of the 8-digit student number, the table version and the
//! assignment's name.
//!
//! **Frozen**: the hash ([FNV-1a], 64 bit) and the generator ([SplitMix64]) below, the way a
//! seed is formed, and every draw an assignment makes for a given [`TableVersion`] must never
//! change, so a published table never changes under a student. A new table is a new version,
//! which students opt into.
//!
//! [FNV-1a]: http://www.isthe.com/chongo/tech/comp/fnv/
//! [SplitMix64]: https://prng.di.unimi.it/splitmix64.c

use std::fmt;
use std::str::FromStr;

use cg_core::lang::{Lang, Text};
use serde::Serialize;

/// A student number: exactly 8 ASCII digits (leading zeros allowed).
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize)]
#[serde(transparent)]
pub struct StudentNumber(String);

impl StudentNumber {
    /// The 8 digits.
    #[must_use]
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl fmt::Display for StudentNumber {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// A student number that is not 8 digits.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}", self.message(Lang::En))]
pub struct StudentNumberError {
    /// What was given.
    pub given: String,
}

impl StudentNumberError {
    /// The message in `lang`: what a student number looks like and what was wrong.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        use cg_core::quote::{shown, visible};
        let chars = self.given.chars().count();
        // A value pasted by mistake (a whole file) is shortened; an invisible character (a
        // zero-width space pasted with the number) is named by its code.
        let (ja, en) = (shown(&self.given, Lang::Ja), shown(&self.given, Lang::En));
        // Full-width digits are digits here, as `from_str` takes them.
        let digit = |c: char| cg_core::text::ascii_digit(c).is_ascii_digit();
        match self.given.chars().find(|&c| !digit(c)) {
            Some(c) => {
                let c = visible(&c.to_string());
                Text::new(
                    format!(
                        "学生番号は 8 桁の数字です。\"{ja}\" には数字でない文字 '{c}' があります"
                    ),
                    format!(
                        "a student number is 8 digits; \"{en}\" has a character that is not a digit: '{c}'"
                    ),
                )
            }
            None => Text::new(
                format!("学生番号は 8 桁の数字です。\"{ja}\" は {chars} 桁です"),
                format!("a student number is 8 digits; \"{en}\" has {chars}"),
            ),
        }
    }
}

impl FromStr for StudentNumber {
    type Err = StudentNumberError;
    /// Accepts exactly 8 digits after trimming surrounding white space: ASCII digits, or the
    /// full-width ones a Japanese input method types (`１２３４５６７８` is `12345678`).
    fn from_str(s: &str) -> Result<StudentNumber, StudentNumberError> {
        let s = s.trim();
        let ascii: String = s.chars().map(cg_core::text::ascii_digit).collect();
        if ascii.len() == 8 && ascii.bytes().all(|b| b.is_ascii_digit()) {
            Ok(StudentNumber(ascii))
        } else {
            Err(StudentNumberError { given: s.to_owned() })
        }
    }
}

/// A version of the variant tables. A published version never changes; a new one is opt-in
/// (`table = 2` in `exercises/student.toml`, or `--table 2`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
pub enum TableVersion {
    /// The first table (2026).
    #[default]
    #[serde(rename = "1")]
    V1,
    /// The second table (2026-11): a3's objects keep apart and stay over the ground (in version
    /// 1 about 15 % of the students' children pass through another object, and hops and
    /// satellites reach up to 6.6 beyond the ±5 ground); a4 draws from 20 952 variants (6 984
    /// in version 1). a1, a2 and s draw as in version 1, from their own streams of this version.
    #[serde(rename = "2")]
    V2,
}

impl TableVersion {
    /// What a student gets when they do not name a version: version 1, the tables every
    /// published assignment was drawn from. A newer version is opt-in.
    pub const DEFAULT: TableVersion = TableVersion::V1;

    /// Every version, oldest first.
    pub const ALL: [TableVersion; 2] = [TableVersion::V1, TableVersion::V2];

    /// The version's number.
    #[must_use]
    pub fn number(self) -> u32 {
        match self {
            TableVersion::V1 => 1,
            TableVersion::V2 => 2,
        }
    }
}

impl fmt::Display for TableVersion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.number())
    }
}

impl FromStr for TableVersion {
    type Err = String;
    fn from_str(s: &str) -> Result<TableVersion, String> {
        let n = s.trim().trim_start_matches(['v', 'V']);
        TableVersion::ALL.into_iter().find(|v| v.number().to_string() == n).ok_or_else(|| {
            let known: Vec<String> = TableVersion::ALL.iter().map(ToString::to_string).collect();
            format!(
                "unknown table version {s:?} (known: {}) / 課題表の版 {s:?} はありません",
                known.join(", ")
            )
        })
    }
}

/// FNV-1a, 64 bit. Frozen.
#[must_use]
pub fn fnv1a64(bytes: &[u8]) -> u64 {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for &b in bytes {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    h
}

/// The random stream an assignment draws a student's variant from: SplitMix64 seeded with
/// FNV-1a of `"cg-kit/v<version>/<assignment>/<student number>"`. Frozen; integer arithmetic
/// only, so every machine draws the same variant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VariantRng {
    state: u64,
    table: TableVersion,
}

impl VariantRng {
    /// The stream for `student`'s variant of `assignment` (`"a1"`, …) in table `version`.
    #[must_use]
    pub fn new(student: &StudentNumber, version: TableVersion, assignment: &str) -> VariantRng {
        let key = format!("cg-kit/v{}/{assignment}/{}", version.number(), student.as_str());
        VariantRng { state: fnv1a64(key.as_bytes()), table: version }
    }

    /// A stream from a raw seed (tests), drawing as table version 1.
    #[must_use]
    pub fn from_seed(seed: u64) -> VariantRng {
        VariantRng { state: seed, table: TableVersion::V1 }
    }

    /// The table version the stream draws for: an assignment whose tables differ between
    /// versions draws by this.
    #[must_use]
    pub fn table(&self) -> TableVersion {
        self.table
    }

    /// The next 64 random bits (SplitMix64).
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `0..n` without bias (rejection sampling); `n = 0` gives 0.
    pub fn below(&mut self, n: u64) -> u64 {
        if n == 0 {
            return 0;
        }
        let zone = u64::MAX - (u64::MAX % n);
        loop {
            let x = self.next_u64();
            if x < zone {
                return x % n;
            }
        }
    }

    /// Uniform in `lo..=hi` (`lo > hi` gives `lo`).
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        if hi <= lo {
            return lo;
        }
        let span = hi.abs_diff(lo) + 1;
        lo.wrapping_add_unsigned(self.below(span))
    }

    /// One of `items`, uniformly.
    ///
    /// # Panics
    /// When `items` is empty (a bug in a variant table, not user input).
    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        assert!(!items.is_empty(), "pick from an empty table");
        &items[self.below(items.len() as u64) as usize]
    }

    /// `items` in a uniformly random order (Fisher–Yates).
    pub fn shuffle<T>(&mut self, items: &mut [T]) {
        for i in (1..items.len()).rev() {
            let j = self.below(i as u64 + 1) as usize;
            items.swap(i, j);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn student_numbers_are_exactly_eight_digits() {
        assert_eq!("12345678".parse::<StudentNumber>().unwrap().as_str(), "12345678");
        assert_eq!(" 00000001\n".parse::<StudentNumber>().unwrap().as_str(), "00000001");
        // The full-width digits a Japanese input method types are the same number.
        assert_eq!("１２３４５６７８".parse::<StudentNumber>().unwrap().as_str(), "12345678");
        assert_eq!("　０１２３４５６7 ".parse::<StudentNumber>().unwrap().as_str(), "01234567");
        for bad in [
            "1234567",
            "123456789",
            "1234567a",
            "",
            "１２３４５６７",
            "12 45678",
            "１２３４５６７８９",
        ] {
            let e = bad.parse::<StudentNumber>().unwrap_err();
            assert!(e.message(Lang::Ja).contains("8 桁"), "{bad}: {}", e.message(Lang::Ja));
            assert!(e.message(Lang::En).contains("8 digits"), "{bad}");
        }
        let e = "1234567a".parse::<StudentNumber>().unwrap_err();
        assert!(e.message(Lang::En).contains("'a'"), "{e}");
        let e = "1234567".parse::<StudentNumber>().unwrap_err();
        assert!(e.message(Lang::En).contains("has 7"), "{e}");
        // Nine full-width digits are nine digits (it said '１' is not a digit).
        let e = "１２３４５６７８９".parse::<StudentNumber>().unwrap_err();
        assert!(e.message(Lang::Ja).contains("は 9 桁です"), "{}", e.message(Lang::Ja));
        // An invisible character by its code; a long value shortened, not echoed whole.
        let e = "1234\u{200b}5678".parse::<StudentNumber>().unwrap_err();
        assert!(e.message(Lang::Ja).contains("U+200B"), "{e}");
        let e = "1".repeat(100_000).parse::<StudentNumber>().unwrap_err();
        assert!(
            e.message(Lang::Ja).len() < 200 && e.message(Lang::En).contains("has 100000"),
            "{e}"
        );
    }

    #[test]
    fn the_hash_and_the_generator_are_the_published_ones() {
        // FNV-1a's published test vectors.
        assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a64(b"foobar"), 0x8594_4171_f739_67e8);
        // SplitMix64 from seed 0, as in the reference implementation (prng.di.unimi.it).
        let mut r = VariantRng::from_seed(0);
        assert_eq!(r.next_u64(), 0xe220_a839_7b1d_cdaf);
        assert_eq!(r.next_u64(), 0x6e78_9e6a_a1b9_65f4);
        assert_eq!(r.next_u64(), 0x06c4_5d18_8009_454f);
    }

    #[test]
    fn streams_differ_by_student_assignment_and_version_only() {
        let s: StudentNumber = "12345678".parse().unwrap();
        let t: StudentNumber = "12345679".parse().unwrap();
        let a = VariantRng::new(&s, TableVersion::V1, "a1");
        assert_eq!(a, VariantRng::new(&s, TableVersion::V1, "a1"), "deterministic");
        assert_ne!(a, VariantRng::new(&t, TableVersion::V1, "a1"));
        assert_ne!(a, VariantRng::new(&s, TableVersion::V1, "a2"));
        // Each version its own stream; the version travels with it.
        let v2 = VariantRng::new(&s, TableVersion::V2, "a1");
        assert_ne!(a, v2);
        assert_eq!((a.table(), v2.table()), (TableVersion::V1, TableVersion::V2));
        assert_eq!("2".parse::<TableVersion>(), Ok(TableVersion::V2));
        assert_eq!(VariantRng::from_seed(1).table(), TableVersion::DEFAULT);
    }

    #[test]
    fn draws_are_uniform_and_in_range() {
        let mut r = VariantRng::from_seed(42);
        let mut counts = [0u32; 6];
        for _ in 0..60_000 {
            let k = r.range(3, 8);
            assert!((3..=8).contains(&k));
            counts[(k - 3) as usize] += 1;
        }
        // χ² with 5 degrees of freedom; 20.5 is the 0.1 % critical value: a uniform draw fails
        // this with probability 0.001 (the seed is fixed, so the test is deterministic).
        let chi2: f64 = counts.iter().map(|&c| (f64::from(c) - 10_000.0).powi(2) / 10_000.0).sum();
        assert!(chi2 < 20.5, "χ² = {chi2}, counts {counts:?}");
        let mut v = [1, 2, 3, 4, 5];
        r.shuffle(&mut v);
        let mut sorted = v;
        sorted.sort_unstable();
        assert_eq!(sorted, [1, 2, 3, 4, 5]);
        assert_eq!(r.below(0), 0);
        assert_eq!(r.range(5, 5), 5);
        assert_eq!("v1".parse::<TableVersion>(), Ok(TableVersion::V1));
        assert!("7".parse::<TableVersion>().is_err());
    }
}
