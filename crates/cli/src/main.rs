//! `cg`, the kit's command line: see the `cg_cli` library, which does all of it.

fn main() -> std::process::ExitCode {
    cg_cli::main()
}
