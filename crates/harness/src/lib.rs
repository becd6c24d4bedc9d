//! # cg-harness — what every assignment shares
//!
//! - [`text`]: student-facing text in Japanese and English ([`Text`]).
//! - [`check`]: a check's result says what was expected, what was found, where, the usual cause
//!   and a hint; [`check::run`] turns a `todo!()` stub into "not done yet" and a panic into a
//!   report, never a crash; [`check::Report`] prints a line per check and a progress summary,
//!   or JSON.
//! - [`variant`]: the student number, the table version, and the frozen random stream each
//!   assignment draws its variant from — a published table never changes under a student.
//! - [`course`]: the course's sample scene, compiled into the kit (the base every assignment's
//!   view draws on).
//! - [`stubs`]: the student's stubs generated from the reference solutions' `BEGIN SOLUTION` /
//!   `END SOLUTION` and `BEGIN STUB` / `END STUB` markers, so the two never drift apart.
//!
//! Task IDs (`a1.t2`) name a task everywhere: the stub, its checks (`a1.t2.closed`), the
//! assignment text, the report section and the grade file.

pub mod args;
pub mod check;
pub mod course;
pub mod exit;
pub mod report;
pub mod stubs;
pub mod symbolic;
pub mod text;
pub mod unit;
pub mod variant;

pub use check::{CheckResult, Failure, Outcome, Report};

/// Rewrites every number in `value` that is exactly an f32 (as every number of the kit's specs
/// is) as the shortest decimal that reads back as that f32: `0.05000000074505806` becomes
/// `0.05`. Other numbers are left alone. For JSON a person or a tool reads.
pub fn tidy_f32_numbers(value: &mut serde_json::Value) {
    match value {
        serde_json::Value::Number(n) => {
            if let Some(x) = n.as_f64().filter(|_| n.is_f64()) {
                let single = x as f32;
                if f64::from(single) == x
                    && let Some(tidy) = single
                        .to_string()
                        .parse::<f64>()
                        .ok()
                        .and_then(serde_json::Number::from_f64)
                {
                    *n = tidy;
                }
            }
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(tidy_f32_numbers),
        serde_json::Value::Object(map) => map.values_mut().for_each(tidy_f32_numbers),
        _ => {}
    }
}

pub use text::Text;
pub use unit::Assignment;
pub use variant::{StudentNumber, TableVersion, VariantRng};

/// A path inside the kit: `default` relative to the current folder when it exists there (the
/// kit's root, where the README says to run the commands), else relative to the root of the
/// kit this program was built from. `given` (a command-line option) wins.
#[must_use]
pub fn kit_path(given: Option<&std::path::Path>, default: &str) -> std::path::PathBuf {
    if let Some(p) = given {
        return p.to_path_buf();
    }
    let here = std::path::PathBuf::from(default);
    if here.exists() {
        return here;
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let root = root.canonicalize().unwrap_or(root);
    root.join(default)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f32_numbers_print_as_their_shortest_decimal() {
        let mut v = serde_json::json!({"a": f64::from(0.05f32), "b": [f64::from(-0.02f32), 1.5, 3], "c": 0.1f64, "d": "x"});
        tidy_f32_numbers(&mut v);
        assert_eq!(v.to_string(), r#"{"a":0.05,"b":[-0.02,1.5,3],"c":0.1,"d":"x"}"#);
    }
}
