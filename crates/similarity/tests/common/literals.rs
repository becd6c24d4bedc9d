//! Programs written for a variant's numbers, shared by the numbers tests and the measurement
//! (`examples/measure_numbers.rs` includes this file by path).

use cg_harness::{StudentNumber, TableVersion};
use cg_similarity::variant;

/// The numbers of `student`'s variant whose label `pick` takes (the spec's JSON paths, `a1 V3.x`,
/// `a4 s_min`): what a program written for that variant has as literals.
pub fn picked(student: &StudentNumber, part: &str, pick: fn(&str) -> bool) -> Vec<f64> {
    let raw = variant::raw_numbers(student, TableVersion::DEFAULT);
    raw[part].iter().filter(|(l, _)| pick(l)).map(|(_, v)| *v).collect()
}

/// `source` with `values` written into it as the constants of a hand-written program.
pub fn with_literals(source: &str, values: &[f64]) -> String {
    let mut out = source.to_owned();
    for (i, v) in values.iter().enumerate() {
        out.push_str(&format!("\n#[allow(dead_code)]\nconst MINE_{i}: f32 = {:?};", *v as f32));
    }
    out
}
