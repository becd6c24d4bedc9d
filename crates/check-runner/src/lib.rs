//! # cg-check-runner — a student's checks, and nothing else
//!
//! The grader builds this crate from each submission's `exercises/` and runs its program,
//! `cg-check-runner`, in the sandbox (cg-sandbox): it prints every assignment's check report as
//! JSON on stdout, exactly what `cg check --json` prints, using the kit's check code (the
//! `cg-a1` … `cg-shading` crates) against the submission's `cg-exercises`. It depends on
//! nothing else, so a rebuild after a submission's files change is small; it never uses the
//! network and writes no files.
//!
//! ```text
//! cg-check-runner [--student NUMBER] [--only a1|a2|a3|a4|s] [--time-limit SECONDS] [--lang ja|en]
//! ```
//!
//! Exit status: 0 every check passed; 1 some did not (the reports are printed all the same);
//! 2 the student could not be found (no `--student` and no readable `exercises/student.toml`:
//! a message on stderr, nothing on stdout); 3 a check ran past the time limit (the watchdog of
//! `cg_harness::check`; nothing on stdout).

use cg_assign::Assignment;
use cg_harness::check::Report;

/// One of the assignments.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Which {
    /// 1. ポリゴンモデルの描画 / polygon model
    A1,
    /// 2. 視点操作インターフェースの拡張 / camera interface
    A2,
    /// 3. アニメーション / animation
    A3,
    /// 4. テクスチャマッピング / texture mapping
    A4,
    /// 第11回 シェーディング / shading
    S,
}

impl Which {
    /// Every assignment, in the order reports are printed.
    pub const ALL: [Which; 5] = [Which::A1, Which::A2, Which::A3, Which::A4, Which::S];

    /// The assignment's ID (`a1` … `a4`, `s`), as in the reports.
    #[must_use]
    pub fn id(self) -> &'static str {
        match self {
            Which::A1 => cg_a1::ID,
            Which::A2 => cg_a2::ID,
            Which::A3 => cg_a3::ID,
            Which::A4 => cg_a4::ID,
            Which::S => cg_shading::ID,
        }
    }
}

/// The checks of one assignment against the student's exercises (`cg-exercises` as built).
#[must_use]
pub fn report(which: Which, a: &Assignment) -> Report {
    let checks = match which {
        Which::A1 => cg_a1::checks(&a.a1, &cg_exercises::a1::implementation()),
        Which::A2 => cg_a2::checks(&a.a2, &cg_exercises::a2::implementation()),
        Which::A3 => cg_a3::checks(&a.a3, &cg_exercises::a3::implementation()),
        Which::A4 => cg_a4::checks(&a.a4, &cg_exercises::a4::implementation()),
        Which::S => cg_shading::checks(&a.s, &cg_exercises::s::implementation()),
    };
    Report { assignment: which.id().to_owned(), student: Some(a.student.to_string()), checks }
}

/// The reports as the JSON array `cg check --json` prints.
#[must_use]
pub fn to_json(reports: &[Report]) -> serde_json::Value {
    serde_json::Value::Array(reports.iter().map(Report::to_json).collect())
}
