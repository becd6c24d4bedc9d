//! Test helpers shared by the kit's crates (dev-dependency only; it does not depend on the kit).
//!
//! - [`assert_approx_eq!`]: compares numbers or vectors with an absolute and a relative tolerance
//!   and, on failure, prints expected, actual, the difference and the tolerance that was used.
//! - [`ulps`]: the distance between two f32 values in units in the last place.
//! - [`images`]: image comparison with stated tolerances that writes the actual, expected and
//!   difference images when it fails, and committed reference images that only a bless run
//!   (`CG_BLESS=1`) may create.
//! - [`prop`]: the seeded proptest configuration and log-uniform strategies every property test
//!   uses.
//! - [`text`]: the rules every message test checks: one clean line in each language, Japanese
//!   in the Japanese text and no English sentence inside it.
//! - [`Inputs`]: a seeded source of hard inputs — magnitudes drawn log-uniformly with both signs,
//!   unit vectors, large offsets — so every random test is reproducible from its seed.

pub mod images;
pub mod prop;
pub mod text;

/// A fresh, empty folder named as a Japanese student's (`山田 太郎`: kanji and a space) under
/// `<temp>/<group>-<pid>-<name>`, for tests of paths students really have. Remove it with
/// [`remove_student_folder`].
#[must_use]
pub fn student_folder(group: &str, name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir()
        .join(format!("{group}-{}-{name}", std::process::id()))
        .join("山田 太郎");
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    dir
}

/// Removes a [`student_folder`] with its scratch parent.
pub fn remove_student_folder(dir: &std::path::Path) {
    if let Some(parent) = dir.parent() {
        let _ = std::fs::remove_dir_all(parent);
    }
}

/// The variables that choose the kit's language, and `LANGUAGE`, which sys-locale reads on Linux.
const LANGUAGE_VARIABLES: [&str; 4] = ["CG_LANG", "LC_ALL", "LC_MESSAGES", "LANGUAGE"];

/// `command` with no language chosen by the tester's environment: the variables that choose one
/// removed, and `LANG=C.UTF-8` (English) in place of the system's language, which the kit asks
/// where no variable is set (a Japanese Mac or Windows would give Japanese). A test sets
/// `CG_LANG`, `LC_ALL` or `LANG` on top, or passes `--lang`, to choose.
pub fn no_language_from_the_tester(
    command: &mut std::process::Command,
) -> &mut std::process::Command {
    for key in LANGUAGE_VARIABLES {
        command.env_remove(key);
    }
    command.env("LANG", "C.UTF-8")
}

use glam::{DVec3, Vec3};
use rand::rngs::StdRng;
use rand::{RngExt, SeedableRng};

/// Values that [`assert_approx_eq!`] can compare: the largest component-wise absolute difference
/// and the largest magnitude of the expected value.
pub trait Approx {
    /// `max |a_i − b_i|` (f64, NaN if either side has a NaN).
    fn max_abs_diff(&self, other: &Self) -> f64;
    /// `max |a_i|`.
    fn max_abs(&self) -> f64;
}

impl Approx for f32 {
    fn max_abs_diff(&self, other: &Self) -> f64 {
        (f64::from(*self) - f64::from(*other)).abs()
    }
    fn max_abs(&self) -> f64 {
        f64::from(self.abs())
    }
}

impl Approx for f64 {
    fn max_abs_diff(&self, other: &Self) -> f64 {
        (self - other).abs()
    }
    fn max_abs(&self) -> f64 {
        self.abs()
    }
}

impl Approx for Vec3 {
    fn max_abs_diff(&self, other: &Self) -> f64 {
        self.as_dvec3().max_abs_diff(&other.as_dvec3())
    }
    fn max_abs(&self) -> f64 {
        f64::from(self.abs().max_element())
    }
}

impl Approx for DVec3 {
    fn max_abs_diff(&self, other: &Self) -> f64 {
        let d = (*self - *other).abs();
        if d.is_nan() { f64::NAN } else { d.max_element() }
    }
    fn max_abs(&self) -> f64 {
        self.abs().max_element()
    }
}

impl Approx for glam::Vec2 {
    fn max_abs_diff(&self, other: &Self) -> f64 {
        let d = (self.as_dvec2() - other.as_dvec2()).abs();
        if d.is_nan() { f64::NAN } else { d.max_element() }
    }
    fn max_abs(&self) -> f64 {
        f64::from(self.abs().max_element())
    }
}

impl Approx for glam::Vec4 {
    fn max_abs_diff(&self, other: &Self) -> f64 {
        let d = (self.as_dvec4() - other.as_dvec4()).abs();
        if d.is_nan() { f64::NAN } else { d.max_element() }
    }
    fn max_abs(&self) -> f64 {
        f64::from(self.abs().max_element())
    }
}

impl Approx for glam::DMat4 {
    fn max_abs_diff(&self, other: &Self) -> f64 {
        self.to_cols_array()
            .iter()
            .zip(other.to_cols_array().iter())
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, |m, d| if d.is_nan() || m.is_nan() { f64::NAN } else { m.max(d) })
    }
    fn max_abs(&self) -> f64 {
        self.to_cols_array().iter().map(|a| a.abs()).fold(0.0, f64::max)
    }
}

impl Approx for glam::Mat4 {
    fn max_abs_diff(&self, other: &Self) -> f64 {
        self.to_cols_array()
            .iter()
            .zip(other.to_cols_array().iter())
            .map(|(a, b)| (f64::from(*a) - f64::from(*b)).abs())
            .fold(0.0, |m, d| if d.is_nan() || m.is_nan() { f64::NAN } else { m.max(d) })
    }
    fn max_abs(&self) -> f64 {
        self.to_cols_array().iter().map(|a| f64::from(a.abs())).fold(0.0, f64::max)
    }
}

/// `true` when `|actual − expected| ≤ abs + rel·|expected|` component-wise (NaN never passes).
pub fn approx_eq<T: Approx>(actual: &T, expected: &T, abs: f64, rel: f64) -> bool {
    let d = actual.max_abs_diff(expected);
    !d.is_nan() && d <= abs + rel * expected.max_abs()
}

/// Asserts `|actual − expected| ≤ abs + rel·|expected|` (component-wise for vectors and matrices)
/// and explains a failure: expected, actual, difference, tolerance, and an optional message.
///
/// ```
/// use cg_testkit::assert_approx_eq;
/// assert_approx_eq!(0.1_f32 + 0.2, 0.3, abs = 1e-7);
/// assert_approx_eq!(1.0e6_f64 + 0.5, 1.0e6, rel = 1e-6, "offset {}", 0.5);
/// assert_approx_eq!(2.0_f32, 2.0 + 1e-6, abs = 1e-6, rel = 1e-6, "both tolerances");
/// ```
#[macro_export]
macro_rules! assert_approx_eq {
    ($actual:expr, $expected:expr, abs = $abs:expr, rel = $rel:expr $(, $fmt:literal $(, $arg:expr)*)? $(,)?) => {
        $crate::assert_approx_eq!(@impl $actual, $expected, $abs, $rel, [$($fmt $(, $arg)*)?])
    };
    ($actual:expr, $expected:expr, abs = $abs:expr $(, $fmt:literal $(, $arg:expr)*)? $(,)?) => {
        $crate::assert_approx_eq!(@impl $actual, $expected, $abs, 0.0, [$($fmt $(, $arg)*)?])
    };
    ($actual:expr, $expected:expr, rel = $rel:expr $(, $fmt:literal $(, $arg:expr)*)? $(,)?) => {
        $crate::assert_approx_eq!(@impl $actual, $expected, 0.0, $rel, [$($fmt $(, $arg)*)?])
    };
    (@impl $actual:expr, $expected:expr, $abs:expr, $rel:expr, [$($msg:tt)*]) => {{
        let (actual, expected) = (&$actual, &$expected);
        let (abs, rel): (f64, f64) = ($abs as f64, $rel as f64);
        if !$crate::approx_eq(actual, expected, abs, rel) {
            let diff = $crate::Approx::max_abs_diff(actual, expected);
            let tol = abs + rel * $crate::Approx::max_abs(expected);
            let note: String = $crate::__note!($($msg)*);
            panic!(
                "assert_approx_eq failed{}\n  expected: {:?}\n    actual: {:?}\n      diff: {:e} (max component)\n tolerance: {:e} (abs {:e} + rel {:e})\n  at {}:{}",
                note, expected, actual, diff, tol, abs, rel, file!(), line!()
            );
        }
    }};
}

#[doc(hidden)]
#[macro_export]
macro_rules! __note {
    () => {
        String::new()
    };
    ($($msg:tt)+) => {
        format!(": {}", format!($($msg)+))
    };
}

/// The distance between two finite f32 values in units in the last place (0 when equal; +0 and −0
/// are 0 apart). `u32::MAX` if either is NaN.
#[must_use]
pub fn ulps(a: f32, b: f32) -> u32 {
    if a.is_nan() || b.is_nan() {
        return u32::MAX;
    }
    // Map the float line onto the integers monotonically.
    fn key(x: f32) -> i64 {
        let bits = i64::from(x.to_bits() as i32);
        if bits < 0 { -(bits & 0x7fff_ffff) } else { bits }
    }
    let d = (key(a) - key(b)).unsigned_abs();
    u32::try_from(d).unwrap_or(u32::MAX)
}

/// The ULP distance of an f32 result from an f64 oracle, in ulps of the oracle rounded to f32
/// (fractional; 0.5 means correctly rounded).
#[must_use]
pub fn ulp_error(actual: f32, oracle: f64) -> f64 {
    let r = oracle as f32;
    let ulp = if r == 0.0 {
        f64::from(f32::from_bits(1))
    } else {
        let next = f32::from_bits(r.abs().to_bits() + 1);
        f64::from(next) - f64::from(r.abs())
    };
    (f64::from(actual) - oracle).abs() / ulp
}

/// A seeded source of test inputs. The same seed gives the same sequence on every machine.
pub struct Inputs {
    rng: StdRng,
    seed: u64,
}

impl Inputs {
    /// A source seeded with `seed` (print the seed in failure messages).
    #[must_use]
    pub fn seeded(seed: u64) -> Inputs {
        Inputs { rng: StdRng::seed_from_u64(seed), seed }
    }

    /// The seed this source started from.
    #[must_use]
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// Uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        self.rng.random_range(lo..hi)
    }

    /// Uniform f32 in `[lo, hi)`.
    pub fn uniform_f32(&mut self, lo: f32, hi: f32) -> f32 {
        self.rng.random_range(lo..hi)
    }

    /// An integer in `[lo, hi)`.
    pub fn int(&mut self, lo: i64, hi: i64) -> i64 {
        self.rng.random_range(lo..hi)
    }

    /// A coin flip.
    pub fn coin(&mut self) -> bool {
        self.rng.random_bool(0.5)
    }

    /// A magnitude `10^e` with `e` uniform in `[min_exp, max_exp]`, with a random sign.
    pub fn log_uniform(&mut self, min_exp: f64, max_exp: f64) -> f64 {
        let e = self.uniform(min_exp, max_exp);
        let m = 10f64.powf(e);
        if self.coin() { m } else { -m }
    }

    /// [`Inputs::log_uniform`] rounded to f32.
    pub fn log_uniform_f32(&mut self, min_exp: f64, max_exp: f64) -> f32 {
        self.log_uniform(min_exp, max_exp) as f32
    }

    /// A vector whose components are each drawn with [`Inputs::log_uniform_f32`].
    pub fn vec3_log_uniform(&mut self, min_exp: f64, max_exp: f64) -> Vec3 {
        Vec3::new(
            self.log_uniform_f32(min_exp, max_exp),
            self.log_uniform_f32(min_exp, max_exp),
            self.log_uniform_f32(min_exp, max_exp),
        )
    }

    /// A vector with components uniform in `[-r, r)`.
    pub fn vec3_in_cube(&mut self, r: f32) -> Vec3 {
        Vec3::new(self.uniform_f32(-r, r), self.uniform_f32(-r, r), self.uniform_f32(-r, r))
    }

    /// A uniformly distributed unit vector (f64 sampling, rounded to f32 and renormalised).
    pub fn unit_vec3(&mut self) -> Vec3 {
        loop {
            let v = DVec3::new(
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
                self.uniform(-1.0, 1.0),
            );
            let l = v.length();
            if l > 1e-3 && l <= 1.0 {
                return (v / l).as_vec3().normalize();
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ulps_counts_representable_steps() {
        assert_eq!(ulps(1.0, 1.0), 0);
        assert_eq!(ulps(1.0, 1.0 + f32::EPSILON), 1);
        assert_eq!(ulps(-0.0, 0.0), 0);
        assert_eq!(ulps(f32::from_bits(1), -f32::from_bits(1)), 2);
        assert_eq!(ulps(f32::NAN, 1.0), u32::MAX);
    }

    #[test]
    fn approx_eq_rejects_nan_and_far_values() {
        assert!(approx_eq(&1.0f32, &1.0, 0.0, 0.0));
        assert!(!approx_eq(&f32::NAN, &1.0, 1.0, 1.0));
        assert!(!approx_eq(&Vec3::new(1.0, 2.0, 3.5), &Vec3::new(1.0, 2.0, 3.0), 0.1, 0.1));
        assert!(approx_eq(&Vec3::new(1.0, 2.0, 3.2), &Vec3::new(1.0, 2.0, 3.0), 0.0, 0.1));
    }

    #[test]
    #[should_panic(expected = "expected")]
    fn assert_approx_eq_explains_failures() {
        assert_approx_eq!(1.5f32, 1.0, abs = 0.1, "a note {}", 1);
    }

    #[test]
    #[should_panic(expected = "both tolerances 3")]
    fn assert_approx_eq_takes_both_tolerances_and_a_message() {
        assert_approx_eq!(1.5f32, 1.0, abs = 0.1, rel = 0.1, "both tolerances {}", 3);
    }

    #[test]
    fn inputs_are_reproducible() {
        let a: Vec<f64> = (0..5).map(|_| Inputs::seeded(7).log_uniform(-3.0, 3.0)).collect();
        let mut s = Inputs::seeded(7);
        assert_eq!(a[0], s.log_uniform(-3.0, 3.0));
        let u = s.unit_vec3();
        assert!((u.length() - 1.0).abs() < 1e-6);
    }

    #[test]
    fn ulp_error_is_half_for_correct_rounding() {
        let oracle = 0.1f64;
        let e = ulp_error(0.1f32, oracle);
        assert!(e <= 0.5, "{e}");
    }
}
