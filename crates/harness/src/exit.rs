//! The exit status of every command of the kit (`cg`, `report-checker`, `cg-viewer`), one table
//! for all (docs/student-guide.md, "Exit status"):
//!
//! | status | meaning |
//! |---|---|
//! | 0 | done, and nothing wrong |
//! | 1 | done, and mistakes found (a check failed, a report number is wrong) |
//! | 2 | bad input or usage: a file that cannot be read, a wrong option (clap's own code too) |
//! | 3 | the student's code ran out of time |
//!
//! 終了コード: 0 成功、1 間違いあり、2 入力・使い方の誤り、3 学生のコードが時間切れ。

use std::process::ExitCode;

use cg_core::lang::{Lang, t};

/// How a command ended. The discriminant is the exit status.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum Ending {
    /// Done, nothing wrong: 0.
    Ok = 0,
    /// Done, mistakes found: 1.
    Mistakes = 1,
    /// Bad input or usage: 2.
    BadInput = 2,
    /// The student's code ran out of time: 3.
    TimedOut = 3,
}

impl Ending {
    /// `Ok` when `passed`, else `Mistakes`.
    #[must_use]
    pub fn passed(passed: bool) -> Ending {
        if passed { Ending::Ok } else { Ending::Mistakes }
    }

    /// The exit status.
    #[must_use]
    pub fn code(self) -> u8 {
        self as u8
    }
}

impl From<Ending> for ExitCode {
    fn from(e: Ending) -> ExitCode {
        ExitCode::from(e.code())
    }
}

/// A command's result as its exit status: an error is printed (`error: …` / `エラー: …`) and
/// is bad input (2).
pub fn finish(result: Result<Ending, String>, lang: Lang) -> ExitCode {
    match result {
        Ok(ending) => ending.into(),
        Err(message) => {
            eprintln!("{}: {message}", t("エラー", "error").get(lang));
            Ending::BadInput.into()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_statuses_are_the_documented_ones() {
        let codes: Vec<u8> = [Ending::Ok, Ending::Mistakes, Ending::BadInput, Ending::TimedOut]
            .map(Ending::code)
            .to_vec();
        assert_eq!(codes, [0, 1, 2, 3]);
        assert_eq!(Ending::passed(true), Ending::Ok);
        assert_eq!(Ending::passed(false), Ending::Mistakes);
        // clap's usage errors are 2 as well (cg_harness::args::parse exits with its code).
        let usage = clap::Command::new("x").try_get_matches_from(["x", "--nope"]).unwrap_err();
        assert_eq!(usage.exit_code(), i32::from(Ending::BadInput.code()));
    }
}
