//! `cg bench [--quick] [--out docs/speed-vs-error.md]`: the speed-against-error report
//! (the design's speed-against-error experiments), measured on this machine (see the `cg-bench` crate).

use std::path::PathBuf;
use std::time::Instant;

use cg_core::lang::{Lang, t};

/// Where the report goes by default, relative to the kit's root.
const DEFAULT_OUT: &str = "docs/speed-vs-error.md";

/// Options of `cg bench`.
#[derive(clap::Args)]
pub struct Args {
    /// Small sizes and few repetitions: under a minute in a release build / 小さな設定で短時間に
    #[arg(long)]
    quick: bool,
    /// The Markdown file to write; the SVG plots go to the folder beside it named after it
    /// (default docs/speed-vs-error.md) / 出力する Markdown ファイル
    #[arg(long, value_name = "FILE")]
    out: Option<PathBuf>,
}

/// Runs every experiment and writes the report.
///
/// # Errors
/// A message in `lang` when a renderer refuses a scene or a file cannot be written.
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    let out = args.out.clone().unwrap_or_else(|| super::kit_path(None, DEFAULT_OUT));
    cg_bench::check_out(&out).map_err(|e| e.message(lang))?;
    let config = if args.quick { cg_bench::Config::quick() } else { cg_bench::Config::full() };
    let repo = out.parent().filter(|p| p.is_dir()).map(PathBuf::from);
    let machine = cg_bench::Machine::detect(repo.as_deref());
    if cfg!(debug_assertions) {
        eprintln!(
            "{}",
            t(
                "注意: デバッグビルドです。時間は `cargo run --release -- bench` で測ってください。",
                "note: a debug build; measure times with `cargo run --release -- bench`.",
            ).get(lang)
        );
    }
    if !cg_viewer::GPU_BUILT {
        let command = cg_harness::args::rerun_with_features("gpu");
        eprintln!(
            "{} {}",
            t("注意: GPU の行はありません。", "note: the report has no GPU rows:").get(lang),
            cg_viewer::gpu_left_out(&command).get(lang)
        );
    }
    let start = Instant::now();
    let report = cg_bench::run(&config, machine, |id| {
        eprintln!("[{:6.1} s] {id}", start.elapsed().as_secs_f64());
    })
    .map_err(|e| e.message(lang))?;
    let written = report.write(&out).map_err(|e| e.message(lang))?;
    println!(
        "{} ({:.1} s):",
        t("速度と誤差のレポートを書きました", "wrote the speed-against-error report").get(lang),
        start.elapsed().as_secs_f64()
    );
    for path in written {
        println!("  {}", path.display());
    }
    Ok(())
}
