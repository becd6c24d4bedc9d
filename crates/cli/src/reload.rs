//! `cg view`'s window starts again when the student's functions are rebuilt (issue 15: "an open
//! viewer reloads the student's result on save"). `cg watch` rebuilds their worker,
//! `target/release/cg-check-runner`, on every save (`cg_assign::local`); the window, which
//! watches that program, then closes, and the view starts again with the same arguments, at the
//! same animation time, from the same camera (`CG_VIEW_RESUME`), with a fresh worker, so the
//! student's saved code is what it shows.
//!
//! On Unix the new program replaces this one (`exec`); on Windows it is started and this one
//! waits for it. A running program cannot be replaced on disk there, so the window's worker runs
//! from a copy of its own (`cg_assign::local::worker_for_a_window`) and the rebuild goes ahead.
//! (Not tried on a Windows machine: the kit's CI checks that it builds for Windows.)

use std::path::Path;
use std::process::Command;

use cg_core::lang::{Lang, t};

/// The environment variable that carries the view across a restart.
pub const RESUME: &str = "CG_VIEW_RESUME";

/// Where a view was when its program was rebuilt.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Resume {
    pub yaw_deg: f32,
    pub pitch_deg: f32,
    pub distance: f32,
}

impl Resume {
    /// The value of [`RESUME`].
    pub fn to_env(self) -> String {
        format!("{} {} {}", self.yaw_deg, self.pitch_deg, self.distance)
    }

    /// The view a restarted program takes over, when [`RESUME`] holds one (anything else is
    /// ignored: the view starts as usual).
    pub fn from_env() -> Option<Resume> {
        Resume::parse(&std::env::var(RESUME).ok()?)
    }

    fn parse(value: &str) -> Option<Resume> {
        let v: Vec<f32> =
            value.split_whitespace().map(|x| x.parse().ok()).collect::<Option<_>>()?;
        match v[..] {
            [yaw_deg, pitch_deg, distance] if v.iter().all(|x| x.is_finite()) => {
                Some(Resume { yaw_deg, pitch_deg, distance })
            }
            _ => None,
        }
    }
}

/// The arguments again, with the animation at `time` and paused or not as it was: `--time` and
/// `--paused` replaced. A time past the last one `--time` takes (a window open for over four
/// and a half hours) is taken as that last one: the reload refused it as a usage error.
pub fn arguments(args: &[String], time: f64, paused: bool) -> Vec<String> {
    let time = time.clamp(0.0, cg_assign::cg_a3::VIEW_MAX_S);
    let mut out = Vec::with_capacity(args.len() + 3);
    let mut skip = false;
    for a in args {
        if std::mem::take(&mut skip) {
            continue;
        }
        match a.as_str() {
            "--time" => skip = true,
            "--paused" => {}
            _ if a.starts_with("--time=") => {}
            _ => out.push(a.clone()),
        }
    }
    out.extend(["--time".to_owned(), format!("{time}")]);
    if paused {
        out.push("--paused".to_owned());
    }
    out
}

/// Starts `program` (`cg` itself) with `args` and the view `resume`; on Unix in place of
/// this process (it does not come back unless that fails).
///
/// # Errors
/// The program could not be started, as a message in `lang`.
pub fn restart(program: &Path, args: &[String], resume: Resume, lang: Lang) -> Result<(), String> {
    println!(
        "{}",
        t(
            "プログラムが作り直されたので、保存したコードでもう一度開きます",
            "the program was rebuilt: opening the view again with the code you saved",
        )
        .get(lang)
    );
    let mut command = Command::new(program);
    command.args(args).env(RESUME, resume.to_env());
    let failed = |e: std::io::Error| {
        let why = cg_core::lang::Text::io(&e);
        format!(
            "{} {}: {}",
            t("起動できません:", "cannot start").get(lang),
            program.display(),
            why.get(lang)
        )
    };
    #[cfg(unix)]
    {
        use std::os::unix::process::CommandExt;
        Err(failed(command.exec()))
    }
    #[cfg(not(unix))]
    {
        let status = command.status().map_err(failed)?;
        std::process::exit(status.code().unwrap_or(1));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_view_goes_through_the_environment_and_back() {
        let r = Resume { yaw_deg: 37.5, pitch_deg: -12.25, distance: 8.0 };
        assert_eq!(Resume::parse(&r.to_env()), Some(r));
        for bad in ["", "1 2", "1 2 x", "1 2 NaN", "1 2 3 4"] {
            assert_eq!(Resume::parse(bad), None, "{bad:?}");
        }
    }

    #[test]
    fn the_time_and_the_pause_are_replaced_and_nothing_else() {
        let args: Vec<String> =
            ["view", "a3", "--time", "2.5", "--paused", "--student", "20231234", "--time=4"]
                .map(String::from)
                .to_vec();
        assert_eq!(
            arguments(&args, 7.25, false),
            ["view", "a3", "--student", "20231234", "--time", "7.25"]
        );
        assert_eq!(
            arguments(&["view".to_owned(), "a1".to_owned()], 0.0, true),
            ["view", "a1", "--time", "0", "--paused"]
        );
    }

    /// The arguments a reload passes are ones `cg view` takes: a window open past the last time
    /// `--time` takes is reloaded at that last time (it was a usage error, and no window).
    #[test]
    fn a_time_past_the_last_one_is_reloaded_at_the_last_one() {
        use clap::Parser as _;
        let args: Vec<String> = ["view", "a3"].map(String::from).to_vec();
        for time in [0.0, 2.5, cg_assign::cg_a3::VIEW_MAX_S, 20_000.0, 1e12] {
            let again = arguments(&args, time, false);
            let parsed = crate::Cli::try_parse_from(std::iter::once("cg".to_owned()).chain(again));
            assert!(parsed.is_ok(), "{time}: {:?}", parsed.err());
        }
    }
}
