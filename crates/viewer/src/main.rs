//! `cg-viewer`: the course's sample scene (or a scene file) in a window, or in PNG files when
//! there is no display.

use std::path::PathBuf;
use std::process::ExitCode;

use cg_core::lang::Lang;
use cg_core::scene::Shading;
use cg_viewer::RendererChoice;
use clap::Parser;

/// The kit's viewer: the course's sample program in a window (PNG files when there is no
/// display).
#[derive(Parser)]
#[command(name = "cg-viewer", version)]
struct Args {
    /// The scene file (default: the course's sample scene)
    scene: Option<PathBuf>,
    /// Shading mode at start: flat, gouraud or phong (default: the scene's)
    #[arg(long, value_parser = parse_shading)]
    shading: Option<Shading>,
    /// Window width in pixels, 1–8192 (default: the scene's)
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=8192), requires = "height")]
    width: Option<u32>,
    /// Window height in pixels, 1–8192
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=8192), requires = "width")]
    height: Option<u32>,
    /// Exit after N frames have been shown
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..))]
    frames: Option<u64>,
    /// Save the last frame to this PNG file (the `s` key saves here too)
    #[arg(long, value_name = "PNG")]
    screenshot: Option<PathBuf>,
    /// Folder for PNG files (screenshots, the view without a display)
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Start with the animation paused
    #[arg(long)]
    paused: bool,
    /// Never open a window: render to PNG files
    #[arg(long)]
    headless: bool,
    /// Which renderer draws first: auto (a real GPU, else the CPU), cpu or gpu; `r` switches
    #[arg(long, value_name = "auto|cpu|gpu", value_parser = RendererChoice::parse, default_value = "auto")]
    renderer: RendererChoice,
    /// Threads for the CPU rasterizer (default: all cores)
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
    threads: Option<u16>,
    /// Language of messages: ja or en (default: from CG_LANG or LANG, else the system's language) / メッセージの言語（省略時は CG_LANG・LANG、なければシステムの言語）
    #[arg(long, value_name = "ja|en")]
    lang: Option<Lang>,
}

fn parse_shading(s: &str) -> Result<Shading, String> {
    match s.to_ascii_lowercase().as_str() {
        "flat" => Ok(Shading::Flat),
        "gouraud" => Ok(Shading::Gouraud),
        "phong" => Ok(Shading::Phong),
        _ => Err(format!(
            "「{s}」はシェーディングの方式ではありません（flat, gouraud, phong のどれか） / '{s}' is not a shading mode: flat, gouraud or phong"
        )),
    }
}

fn main() -> ExitCode {
    let args: Args = cg_harness::args::parse();
    let lang = args.lang.unwrap_or_else(Lang::from_env);
    let options = cg_viewer::ViewerOptions {
        scene: args.scene,
        shading: args.shading,
        size: args.width.zip(args.height),
        frames: args.frames,
        screenshot: args.screenshot,
        out_dir: args.out,
        paused: args.paused,
        headless: args.headless,
        threads: args.threads.map(usize::from),
        renderer: args.renderer,
        lang,
        reload_on_change: None,
    };
    // The kit's exit statuses: 0 ok, 2 bad input (cg_harness::exit).
    let result = cg_viewer::run(&options).map(|()| cg_harness::exit::Ending::Ok);
    cg_harness::exit::finish(result.map_err(|e| e.message(lang)), lang)
}
