//! Timing, statistics and a seeded random source for the experiments.

use std::hint::black_box;
use std::time::Instant;

/// The median wall-clock time of `f` over `reps` runs (at least one), in seconds. One extra run
/// first warms caches and is not counted.
pub fn median_time<T>(reps: usize, mut f: impl FnMut() -> T) -> f64 {
    black_box(f());
    let mut times: Vec<f64> = (0..reps.max(1))
        .map(|_| {
            let start = Instant::now();
            black_box(f());
            start.elapsed().as_secs_f64()
        })
        .collect();
    median(&mut times)
}

/// The median of `values` (the mean of the middle two for an even count); 0 for none. NaN sorts
/// last.
pub fn median(values: &mut [f64]) -> f64 {
    if values.is_empty() {
        return 0.0;
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n % 2 == 1 { values[n / 2] } else { 0.5 * (values[n / 2 - 1] + values[n / 2]) }
}

/// Mean, 99th percentile (nearest rank) and maximum of `values`; zeros for none.
pub fn mean_p99_max(values: &mut [f64]) -> (f64, f64, f64) {
    if values.is_empty() {
        return (0.0, 0.0, 0.0);
    }
    values.sort_by(f64::total_cmp);
    let n = values.len();
    let mean = values.iter().sum::<f64>() / n as f64;
    let rank = ((0.99 * n as f64).ceil() as usize).clamp(1, n) - 1;
    (mean, values[rank], values[n - 1])
}

/// A small seeded generator (SplitMix64): the experiments' inputs are the same on every run.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator started from `seed`.
    #[must_use]
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// A uniformly distributed unit vector.
    pub fn direction(&mut self) -> cg_core::glam::DVec3 {
        let z = self.range(-1.0, 1.0);
        let phi = self.range(0.0, std::f64::consts::TAU);
        let r = (1.0 - z * z).max(0.0).sqrt();
        cg_core::glam::DVec3::new(r * phi.cos(), r * phi.sin(), z)
    }
}

/// Which points are on the Pareto front of (time, error), both smaller-is-better: no other point
/// is at least as fast *and* at least as accurate while better in one. Non-finite points are never
/// on it.
#[must_use]
pub fn pareto_front(points: &[(f64, f64)]) -> Vec<bool> {
    points
        .iter()
        .map(|&(t, e)| {
            t.is_finite()
                && e.is_finite()
                && !points.iter().any(|&(t2, e2)| {
                    t2.is_finite() && e2.is_finite() && t2 <= t && e2 <= e && (t2 < t || e2 < e)
                })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn median_and_percentiles() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 2.0, 3.0]), 2.5);
        let mut v: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(mean_p99_max(&mut v), (50.5, 99.0, 100.0));
    }

    #[test]
    fn the_pareto_front_keeps_only_undominated_points() {
        let pts = [(1.0, 5.0), (2.0, 1.0), (2.0, 2.0), (3.0, 1.0), (0.5, 9.0), (f64::NAN, 0.0)];
        assert_eq!(pareto_front(&pts), vec![true, true, false, false, true, false]);
    }
}
