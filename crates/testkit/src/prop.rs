//! Property tests, seeded: one configuration and the input strategies docs/numerics.md asks for
//! (magnitudes drawn log-uniformly with both signs).

use glam::Vec3;
use proptest::prelude::*;
use proptest::test_runner::RngSeed;

/// A proptest configuration with a fixed seed (every run tests the same cases), no failure
/// files written into the source tree, and `cases` cases in debug builds (4× in release).
#[must_use]
pub fn config(cases: u32, seed: u64) -> ProptestConfig {
    ProptestConfig {
        cases: if cfg!(debug_assertions) { cases } else { cases * 4 },
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// A magnitude `10^e` with `e` uniform in `[lo, hi]`, with either sign, rounded to f32.
pub fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f32> {
    (lo..=hi, any::<bool>()).prop_map(|(e, neg)| {
        let m = 10f64.powf(e) as f32;
        if neg { -m } else { m }
    })
}

/// A vector whose components are each [`log_uniform`].
pub fn vec3(lo: f64, hi: f64) -> impl Strategy<Value = Vec3> {
    (log_uniform(lo, hi), log_uniform(lo, hi), log_uniform(lo, hi))
        .prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;

    #[test]
    fn log_uniform_stays_in_its_decades_with_both_signs() {
        let mut runner = TestRunner::new(config(1, 1));
        let (mut pos, mut neg) = (false, false);
        for _ in 0..200 {
            let x = log_uniform(-3.0, 2.0).new_tree(&mut runner).unwrap().current();
            assert!((1e-3..=1e2).contains(&x.abs()), "{x}");
            pos |= x > 0.0;
            neg |= x < 0.0;
        }
        assert!(pos && neg, "both signs are drawn");
    }
}
