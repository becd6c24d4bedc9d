//! Runs a configuration (`quick` by default; `tiny`, `full`) into a folder and prints the time.
fn main() {
    let which = std::env::args().nth(1).unwrap_or_else(|| "quick".into());
    let out = std::env::args().nth(2).unwrap_or_else(|| "/tmp/bench-out/speed-vs-error.md".into());
    let config = match which.as_str() {
        "tiny" => cg_bench::Config::tiny(),
        "full" => cg_bench::Config::full(),
        _ => cg_bench::Config::quick(),
    };
    let start = std::time::Instant::now();
    let report = cg_bench::run(&config, cg_bench::Machine::detect(None), |id| {
        eprintln!("{id} at {:.1} s", start.elapsed().as_secs_f64());
    })
    .expect("runs");
    report.write(std::path::Path::new(&out)).expect("writes");
    eprintln!("done in {:.1} s", start.elapsed().as_secs_f64());
}
