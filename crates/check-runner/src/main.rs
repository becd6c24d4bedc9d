//! `cg-check-runner`: the student's functions as a worker (see the crate's documentation).

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let limit = match cg_check_runner::parse_args(&args) {
        Ok(limit) => limit,
        Err(message) => {
            eprintln!("cg-check-runner: {message}");
            return ExitCode::from(2);
        }
    };
    if let Some(mb) = limit
        && let Err(e) = cg_check_runner::limit_memory(mb)
    {
        eprintln!("cg-check-runner: --memory-mb {mb}: {e}");
        return ExitCode::from(2);
    }
    match cg_check_runner::serve() {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("cg-check-runner: {e}");
            ExitCode::FAILURE
        }
    }
}
