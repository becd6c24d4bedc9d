//! `cg doctor`: which renderers and windows work on this machine, and why — the system (WSL
//! too), the display, the CPU renderers, the GPU renderer, the kit's own state — each problem with
//! its fix, in Japanese or English.
//!
//! It never fails and never hangs: the CPU renderers always work (the exit status is 0), and the
//! GPU is probed in a process of its own (`cg doctor --gpu-probe`, hidden), killed after
//! `--gpu-timeout` seconds, so a driver that hangs or crashes is a line of the report, not the end
//! of the command.
//!
//! `cg doctor`: このマシンでどのレンダラとウィンドウが使えるか、使えないならその理由と対処を表示します。

use std::fmt::Write as _;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use cg_core::lang::{Lang, Text, t};
use serde_json::{Map, Value, json};

/// Options of `cg doctor`.
#[derive(clap::Args)]
pub struct Args {
    /// Print one flat JSON object of the findings, for tools / 結果を JSON で出力（ツール用）
    #[arg(long)]
    json: bool,
    /// Seconds to wait for the GPU driver before giving up on it, 1–600 / GPU ドライバを待つ秒数（1〜600）
    #[arg(long, value_name = "SECONDS", default_value_t = 20,
          value_parser = clap::value_parser!(u64).range(1..=600))]
    gpu_timeout: u64,
    /// Only open the GPU and print what was found as JSON (what `cg doctor` starts; not for use
    /// by hand)
    #[arg(long, hide = true)]
    gpu_probe: bool,
}

/// How a finding reads: works, a note, or a problem with its fix.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mark {
    Works,
    Note,
    Problem,
}

/// One line of the report, and what to do about it.
struct Finding {
    mark: Mark,
    text: String,
    fixes: Vec<String>,
}

/// A heading and its findings.
struct Section {
    title: String,
    findings: Vec<Finding>,
}

/// The whole report: the sections for people, the flat object for tools.
struct Report {
    lang: Lang,
    sections: Vec<Section>,
    json: Map<String, Value>,
}

impl Report {
    fn section(&mut self, title: Text) {
        let title = self.words(title);
        self.sections.push(Section { title, findings: Vec::new() });
    }

    fn add(&mut self, mark: Mark, text: impl Into<String>, fixes: Vec<String>) {
        let finding = Finding { mark, text: text.into(), fixes };
        if let Some(s) = self.sections.last_mut() {
            s.findings.push(finding);
        }
    }

    fn works(&mut self, text: impl Into<String>) {
        self.add(Mark::Works, text, Vec::new());
    }

    fn note(&mut self, text: impl Into<String>) {
        self.add(Mark::Note, text, Vec::new());
    }

    fn problem(&mut self, text: impl Into<String>, fixes: Vec<String>) {
        self.add(Mark::Problem, text, fixes);
    }

    fn set(&mut self, key: &str, value: impl Into<Value>) {
        self.json.insert(key.to_owned(), value.into());
    }

    /// `text` in the report's language.
    fn words(&self, text: Text) -> String {
        text.get(self.lang).to_owned()
    }

    fn problems(&self) -> Vec<&Finding> {
        self.sections.iter().flat_map(|s| &s.findings).filter(|f| f.mark == Mark::Problem).collect()
    }

    fn render(&self) -> String {
        let lang = self.lang;
        let mut out = String::new();
        let _ = writeln!(
            out,
            "cg doctor {} — {}",
            env!("CARGO_PKG_VERSION"),
            t(
                "このマシンで使えるものと、使えないものの理由",
                "what works on this machine, and why"
            )
            .get(lang)
        );
        for s in &self.sections {
            let _ = writeln!(out, "\n{}", s.title);
            for f in &s.findings {
                let mark = match f.mark {
                    Mark::Works => "✓",
                    Mark::Note => "·",
                    Mark::Problem => "✗",
                };
                let _ = writeln!(out, "  {mark} {}", f.text);
                for fix in &f.fixes {
                    let _ = writeln!(out, "      → {}: {fix}", t("対処", "fix").get(lang));
                }
            }
        }
        let n = self.problems().len();
        let _ = writeln!(
            out,
            "\n{}",
            match n {
                0 => t("問題は見つかりませんでした。", "No problems found."),
                n => Text::new(
                    format!(
                        "問題 {n} 件（上の ✗ の行と、その対処）。CPU のレンダラは使えるので、演習はすべてこのマシンでできます。"
                    ),
                    format!(
                        "{n} problem{} (the ✗ lines above, each with its fix). The CPU renderers work, so every part of the course runs on this machine.",
                        if n == 1 { "" } else { "s" }
                    ),
                ),
            }
            .get(lang)
        );
        out
    }
}

/// `cg doctor`: prints the report (or, with `--gpu-probe`, only opens the GPU).
pub fn run(args: &Args, lang: Lang) -> Result<(), String> {
    if args.gpu_probe {
        println!("{}", probe_gpu_here());
        return Ok(());
    }
    let mut r = Report { lang, sections: Vec::new(), json: Map::new() };
    r.set("version", env!("CARGO_PKG_VERSION"));
    r.set("lang", lang.to_string());
    let wsl = wsl();
    system(&mut r, wsl);
    display(&mut r, wsl);
    cpu(&mut r);
    gpu(&mut r, Duration::from_secs(args.gpu_timeout), wsl);
    kit(&mut r);
    let problems = r.problems().len();
    r.set("problems", problems);
    if args.json {
        let text = serde_json::to_string_pretty(&Value::Object(r.json.clone()))
            .map_err(|e| e.to_string())?;
        println!("{text}");
    } else {
        print!("{}", r.render());
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------
// The system

/// Which Windows Subsystem for Linux this is, if any.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Wsl {
    V1,
    V2,
    /// `WSL_DISTRO_NAME` is set, but the kernel does not say which.
    Unknown,
}

/// WSL from `/proc/version` (WSL 2's kernel is `…-microsoft-standard-WSL2`, WSL 1 reports
/// `…-Microsoft`) or `WSL_DISTRO_NAME`.
fn wsl() -> Option<Wsl> {
    if !cfg!(target_os = "linux") {
        return None;
    }
    // platform: Linux only (WSL is Linux); every other system returned above.
    let version = std::fs::read_to_string("/proc/version").unwrap_or_default().to_ascii_lowercase();
    if version.contains("microsoft-standard") || version.contains("wsl2") {
        Some(Wsl::V2)
    } else if version.contains("microsoft") {
        Some(Wsl::V1)
    } else if env("WSL_DISTRO_NAME").is_some() {
        Some(Wsl::Unknown)
    } else {
        None
    }
}

/// A variable of the environment, when it is set and not empty.
fn env(key: &str) -> Option<String> {
    std::env::var_os(key).filter(|v| !v.is_empty()).map(|v| v.to_string_lossy().into_owned())
}

/// Whether `path` is on a Windows drive as WSL mounts it (`/mnt/c/…`).
fn on_windows_drive(path: &Path) -> bool {
    let mut parts = path.components().map(|c| c.as_os_str().to_string_lossy().into_owned());
    parts.next().as_deref() == Some("/")
        && parts.next().as_deref() == Some("mnt")
        && parts.next().is_some_and(|d| d.len() == 1 && d.as_bytes()[0].is_ascii_alphabetic())
}

/// The kit's root folder (where `exercises/` is found).
fn kit_root() -> PathBuf {
    let exercises = crate::kit_path(None, "exercises");
    let exercises = std::path::absolute(&exercises).unwrap_or(exercises);
    exercises.parent().map_or_else(|| PathBuf::from("."), Path::to_path_buf)
}

fn system(r: &mut Report, wsl: Option<Wsl>) {
    r.section(t("システム", "system"));
    let os = match std::env::consts::OS {
        "linux" => "Linux",
        "macos" => "macOS",
        "windows" => "Windows",
        other => other,
    };
    let wsl_text = match wsl {
        None => String::new(),
        Some(Wsl::V1) => " (WSL 1)".to_owned(),
        Some(Wsl::V2) => " (WSL 2)".to_owned(),
        Some(Wsl::Unknown) => " (WSL)".to_owned(),
    };
    let distro = env("WSL_DISTRO_NAME").map(|d| format!(", {d}")).unwrap_or_default();
    r.note(format!("{os}{wsl_text}{distro}, {}", std::env::consts::ARCH));
    r.set("os", std::env::consts::OS);
    r.set("arch", std::env::consts::ARCH);
    r.set("wsl", wsl.is_some());
    r.set(
        "wsl_version",
        match wsl {
            Some(Wsl::V1) => json!(1),
            Some(Wsl::V2) => json!(2),
            _ => Value::Null,
        },
    );
    let here = std::env::current_dir().ok();
    let root = kit_root();
    r.note(format!("{}: {}", r.words(t("キットのフォルダ", "the kit's folder")), root.display()));
    r.set("kit_root", root.display().to_string());
    let windows_drive = wsl.is_some_and(|w| w != Wsl::V1)
        && (on_windows_drive(&root) || here.as_deref().is_some_and(on_windows_drive));
    r.set("windows_drive", windows_drive);
    if windows_drive {
        let text = r.words(t(
            "キットが Windows のドライブ（/mnt/c など）にあります。WSL 2 からは Windows のファイルの読み書きが遅く（ビルドが数倍遅くなります）、ファイルの変更を監視するもの（VS Code、cargo watch など）が変更に気づかないことがあります",
            "the kit is on a Windows drive (/mnt/c…): from WSL 2, Windows files are slow to read and write (builds take several times longer), and file watchers (VS Code, cargo watch) may miss changes to them",
        ));
        let fixes = vec![
            r.words(t(
                "Linux 側のホームに clone し直します: cd ~ && git clone … （VS Code は WSL 拡張機能で開きます）",
                "clone the kit again into your Linux home folder: cd ~ && git clone … (open it in VS Code with the WSL extension)",
            )),
            r.words(t(
                "自分の作業（exercises/src/ と exercises/student.toml）を新しい clone にコピーします",
                "copy your work (exercises/src/ and exercises/student.toml) into the new clone",
            )),
        ];
        r.problem(text, fixes);
    }
}

// ---------------------------------------------------------------------------------------------
// The display

/// Whether this system's windows depend on `WAYLAND_DISPLAY` / `DISPLAY` (as
/// [`cg_viewer::display_available`] decides).
const UNIX_DESKTOP: bool = cfg!(any(
    target_os = "linux",
    target_os = "freebsd",
    target_os = "openbsd",
    target_os = "netbsd",
    target_os = "dragonfly"
));

/// The runtime folder a user session usually has: `/run/user/UID`, or WSLg's.
fn usual_runtime_dir() -> Option<PathBuf> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        // platform: inside #[cfg(unix)]; without /proc (macOS) there is no guess.
        if let Ok(meta) = std::fs::metadata("/proc/self") {
            let dir = PathBuf::from(format!("/run/user/{}", meta.uid()));
            if dir.is_dir() {
                return Some(dir);
            }
        }
    }
    let wslg = PathBuf::from("/mnt/wslg/runtime-dir");
    wslg.is_dir().then_some(wslg)
}

/// What to do about a missing or wrong `XDG_RUNTIME_DIR`.
fn runtime_fix(r: &Report) -> String {
    match usual_runtime_dir() {
        Some(d) => format!("export XDG_RUNTIME_DIR={}", d.display()),
        None => r.words(t(
            "デスクトップにログインした端末から実行します（ログインで設定されます）。または unset XDG_RUNTIME_DIR",
            "run from a terminal of a desktop login (the login sets it), or unset XDG_RUNTIME_DIR",
        )),
    }
}

/// The command that removes `key` from the environment of this shell.
fn unset(key: &str) -> String {
    if cfg!(windows) { format!("Remove-Item Env:{key}") } else { format!("unset {key}") }
}

fn display(r: &mut Report, wsl: Option<Wsl>) {
    r.section(t("ウィンドウ（画面）", "windows (the display)"));
    let wayland = env("WAYLAND_DISPLAY");
    let x11 = env("DISPLAY");
    let runtime = env("XDG_RUNTIME_DIR");
    r.set("wayland_display", wayland.clone());
    r.set("display", x11.clone());
    r.set("xdg_runtime_dir", runtime.clone());
    let available = cg_viewer::display_available();
    if !UNIX_DESKTOP {
        r.set("window", available);
        r.set("xdg_runtime_dir_ok", Value::Null);
        r.works(r.words(t(
            "ウィンドウはこの OS のウィンドウシステムで開きます（WAYLAND_DISPLAY・DISPLAY は不要）",
            "windows open through this system's own window system (no WAYLAND_DISPLAY or DISPLAY needed)",
        )));
        return;
    }
    let unset = r.words(t("未設定", "not set"));
    let unset_runtime = r.words(t(
        "未設定（Wayland のウィンドウにだけ必要です）",
        "not set (only Wayland windows need it)",
    ));
    for (key, value, absent) in [
        ("WAYLAND_DISPLAY", &wayland, &unset),
        ("DISPLAY", &x11, &unset),
        ("XDG_RUNTIME_DIR", &runtime, &unset_runtime),
    ] {
        r.note(format!("{key:<16} {}", value.as_deref().unwrap_or(absent)));
    }

    // XDG_RUNTIME_DIR: where the Wayland socket is (and what Mesa and others expect).
    let runtime_ok = runtime.as_deref().map(|d| Path::new(d).is_dir());
    r.set("xdg_runtime_dir_ok", runtime_ok);
    match (&runtime, runtime_ok) {
        (Some(dir), Some(false)) => {
            let text = if Path::new(dir).exists() {
                format!(
                    "XDG_RUNTIME_DIR={dir}{}",
                    r.words(t(
                        " はフォルダではありません（Wayland のウィンドウはここにソケットを探します）",
                        " is not a folder (Wayland windows look for their socket there)",
                    ))
                )
            } else {
                format!(
                    "XDG_RUNTIME_DIR={dir}{}",
                    r.words(t(
                        " のフォルダがありません（Wayland のウィンドウはここにソケットを探します）",
                        ": the folder does not exist (Wayland windows look for their socket there)"
                    ))
                )
            };
            let fixes = vec![runtime_fix(r)];
            r.problem(text, fixes);
        }
        (None, _) if wayland.as_deref().is_some_and(|w| !w.starts_with('/')) => {
            let text = r.words(t(
                "WAYLAND_DISPLAY は設定されていますが XDG_RUNTIME_DIR がないので、Wayland のソケットが見つかりません",
                "WAYLAND_DISPLAY is set but XDG_RUNTIME_DIR is not, so the Wayland socket cannot be found",
            ));
            let fixes = vec![runtime_fix(r)];
            r.problem(text, fixes);
        }
        _ => {}
    }

    // The Wayland socket and the X server's, where they can be seen: `Some(false)` when the
    // variable names a socket that is not there, `None` when unset or not checkable.
    let wsl_fix = |r: &Report| {
        r.words(t(
            "WSL: PowerShell で wsl --shutdown を実行してから端末を開き直します（WSLg が起動し直します）",
            "WSL: run wsl --shutdown in PowerShell, then open the terminal again (WSLg starts afresh)",
        ))
    };
    let wayland_there = wayland.as_deref().and_then(|w| {
        let socket = if w.starts_with('/') {
            PathBuf::from(w)
        } else {
            Path::new(runtime.as_deref().filter(|_| runtime_ok == Some(true))?).join(w)
        };
        let there = socket.exists();
        if !there {
            let text = r.words(Text::new(format!(
                    "Wayland のソケット {} がありません（コンポジタが動いていないか、別のセッションの値です）",
                    socket.display()
                ), format!(
                    "the Wayland socket {} does not exist (no compositor is running, or the value is another session's)",
                    socket.display()
                )));
            let mut fixes = vec![r.words(t(
                "デスクトップの端末から実行するか、unset WAYLAND_DISPLAY で X11（DISPLAY）を使います",
                "run from a terminal inside the desktop, or unset WAYLAND_DISPLAY to use X11 (DISPLAY)",
            ))];
            if wsl.is_some() {
                fixes.push(wsl_fix(r));
            }
            r.problem(text, fixes);
        }
        Some(there)
    });
    let x11_there = x11.as_deref().and_then(local_x_display).map(|number| {
        // platform: X11's local sockets (Unix); elsewhere the path is not there and the display
        // counts as absent, which is true.
        let socket = PathBuf::from(format!("/tmp/.X11-unix/X{number}"));
        let there = socket.exists();
        if !there {
            let text = r.words(Text::new(format!(
                    "X サーバのソケット {} がありません（DISPLAY の X サーバが動いていないかもしれません）",
                    socket.display()
                ), format!(
                    "the X server's socket {} does not exist (the X server of DISPLAY may not be running)",
                    socket.display()
                )));
            let mut fixes = vec![r.words(t(
                "デスクトップにログインした端末から実行します（DISPLAY はログインで設定されます）",
                "run from a terminal inside the desktop session (its login sets DISPLAY)",
            ))];
            if wsl.is_some() {
                fixes.push(wsl_fix(r));
            }
            r.problem(text, fixes);
        }
        there
    });
    // Every display that is named is known to be missing: no window, most likely.
    let named_but_gone = available
        && [(&wayland, wayland_there), (&x11, x11_there)]
            .iter()
            .all(|(name, there)| name.is_none() || *there == Some(false));
    r.set("window", available && !named_but_gone);

    let png_fix = r.words(t(
        "ウィンドウがなくても演習はできます: `cargo run --release` と `view` は out/ に PNG を書くので、画像ビューアで開きます",
        "the course works without a window: `cargo run --release` and `view` write PNG files to out/; open them in an image viewer",
    ));
    if named_but_gone {
        let reason = r.words(t(
            "WAYLAND_DISPLAY・DISPLAY の画面がありません",
            "the display named by WAYLAND_DISPLAY / DISPLAY is not there",
        ));
        let text = cg_viewer::no_window(&reason, r.lang);
        r.problem(text, vec![r.words(t("上の行を直します", "fix the lines above")), png_fix]);
    } else if available {
        r.works(r.words(t(
            "ウィンドウを開けます（Wayland、だめなら X11）。`view` と `cargo run --release` はウィンドウに描画します。それでも開けないときは理由を表示して PNG に描画します",
            "a window can be opened (Wayland first, then X11): `view` and `cargo run --release` draw in it; if it still fails to open, they say why and draw PNG files instead",
        )));
    } else {
        let reason = r.words(t(
            "WAYLAND_DISPLAY も DISPLAY も設定されていません",
            "neither WAYLAND_DISPLAY nor DISPLAY is set",
        ));
        let text = cg_viewer::no_window(&reason, r.lang);
        let mut fixes = Vec::new();
        if wsl.is_some() {
            fixes.push(r.words(t(
                "WSL: Windows 11（または Windows 10 21H2 以降）の WSLg がウィンドウを表示します。PowerShell で wsl --update、続けて wsl --shutdown してから端末を開き直します",
                "WSL: WSLg shows Linux windows on Windows 11 (or Windows 10 21H2 and later): in PowerShell run wsl --update, then wsl --shutdown, and open the terminal again",
            )));
        } else if env("SSH_CONNECTION").is_some() {
            fixes.push(r.words(t(
                "ssh 経由です: ssh -X（または ssh -Y）で接続し直すと X11 のウィンドウが手元に出ます",
                "this is an ssh session: connect with ssh -X (or ssh -Y) to get X11 windows on your screen",
            )));
        } else {
            fixes.push(r.words(t(
                "デスクトップ（Wayland か X11）の端末から実行します",
                "run the command from a terminal inside the desktop (Wayland or X11)",
            )));
        }
        fixes.push(png_fix);
        r.problem(text, fixes);
    }
}

/// The display number of a local X display (`:0`, `:1.0`); `None` for `host:0` (over the
/// network or ssh) and anything else.
fn local_x_display(display: &str) -> Option<u32> {
    let rest = display.strip_prefix(':')?;
    rest.split('.').next()?.parse().ok()
}

// ---------------------------------------------------------------------------------------------
// The CPU renderers

/// Runs `f`, a panic caught as its message.
fn guarded<T>(f: impl FnOnce() -> Result<T, String>) -> Result<T, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or_else(|payload| {
        let message = cg_worker::panic_message(payload.as_ref()).unwrap_or_default();
        Err(format!("panic: {message}"))
    })
}

fn cpu(r: &mut Report) {
    r.section(t("レンダラ", "renderers"));
    let threads = std::thread::available_parallelism().map_or(1, std::num::NonZero::get);
    r.set("cpu_threads", threads);
    let lang = r.lang;
    let scene = guarded(|| Ok(cg_harness::course::scene()));
    let size = Some((64, 48));
    let raster = scene.clone().and_then(|scene| {
        guarded(|| {
            let start = Instant::now();
            cg_raster::render(&scene, &cg_raster::Options { size, ..cg_raster::Options::default() })
                .map(|_| start.elapsed())
                .map_err(|e| e.message(lang))
        })
    });
    let trace = scene.and_then(|scene| {
        guarded(|| {
            let start = Instant::now();
            cg_trace::render(&scene, &cg_trace::Options { size, ..cg_trace::Options::default() })
                .map(|_| start.elapsed())
                .map_err(|e| e.message(lang))
        })
    });
    for (key, name, result) in [
        (
            "cpu_raster",
            r.words(t(
                "CPU ラスタライザ（render --renderer raster、ビューアの CPU 描画）",
                "CPU rasterizer (render --renderer raster, the viewer's CPU mode)",
            )),
            raster,
        ),
        (
            "cpu_trace",
            r.words(t(
                "レイトレーサ（render --renderer trace）",
                "ray tracer (render --renderer trace)",
            )),
            trace,
        ),
    ] {
        r.set(key, result.is_ok());
        match result {
            Ok(took) => {
                let ms = took.as_secs_f64() * 1e3;
                let text = r.words(Text::new(
                    format!("{name}: 使えます（64×48 の試し描き {ms:.1} ms、{threads} スレッド）"),
                    format!("{name}: works (a 64×48 test frame in {ms:.1} ms, {threads} threads)"),
                ));
                r.works(text);
            }
            Err(e) => {
                let text = format!("{name}: {e}");
                let fixes = vec![r.words(t(
                    "キットの不具合です。この出力を添えて TA に知らせてください",
                    "this is a bug of the kit: tell your TA, with this output",
                ))];
                r.problem(text, fixes);
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The GPU renderer

/// What the GPU probe found, as the probe process prints it (one JSON line). A panic here (a
/// driver wgpu does not expect) ends the probe process; `cg doctor` reports it with the end of its
/// error output.
#[cfg(feature = "gpu")]
fn probe_gpu_here() -> Value {
    match cg_gpu::Gpu::new() {
        Ok(gpu) => {
            let i = gpu.adapter().get_info();
            json!({
                "adapter": gpu.adapter_info(),
                "name": i.name,
                "device_type": format!("{:?}", i.device_type),
                "software": i.device_type == cg_gpu::wgpu::DeviceType::Cpu,
            })
        }
        Err(e) => json!({
            "error_en": e.message(Lang::En),
            "error_ja": e.message(Lang::Ja),
            "no_adapter": matches!(e, cg_gpu::GpuError::NoAdapter),
        }),
    }
}

/// The probe in a build without the GPU renderer: nothing to open. (`cg doctor` does not start
/// it there; [`gpu`] says why.)
#[cfg(not(feature = "gpu"))]
fn probe_gpu_here() -> Value {
    json!({ "built": false, "no_adapter": false })
}

/// How the probe ended.
enum Probe {
    /// The probe's JSON line.
    Answer(Value),
    /// It ran past the limit and was stopped.
    TimedOut,
    /// It ended without an answer: its status and the end of its error output.
    Crashed(String, String),
    /// It could not be started.
    NotStarted(Text),
}

/// Reads all of `pipe` on a thread of its own; the text comes on the channel.
fn drain(mut pipe: impl Read + Send + 'static) -> mpsc::Receiver<String> {
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let mut bytes = Vec::new();
        let _ = pipe.by_ref().take(1 << 20).read_to_end(&mut bytes);
        let _ = tx.send(String::from_utf8_lossy(&bytes).into_owned());
    });
    rx
}

/// Runs `cg doctor --gpu-probe` and waits at most `limit` for it; then it is killed.
fn probe_gpu(limit: Duration) -> Probe {
    let exe = match std::env::current_exe() {
        Ok(exe) => exe,
        Err(e) => return Probe::NotStarted(Text::io(&e)),
    };
    let child = Command::new(exe)
        .args(["doctor", "--gpu-probe"])
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let mut child = match child {
        Ok(c) => c,
        Err(e) => return Probe::NotStarted(Text::io(&e)),
    };
    let stdout = child.stdout.take().map(drain);
    let stderr = child.stderr.take().map(drain);
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if start.elapsed() < limit => std::thread::sleep(Duration::from_millis(20)),
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
        }
    };
    let take = |rx: Option<mpsc::Receiver<String>>| {
        rx.and_then(|rx| rx.recv_timeout(Duration::from_secs(2)).ok()).unwrap_or_default()
    };
    let (out, err) = (take(stdout), take(stderr));
    let Some(status) = status else { return Probe::TimedOut };
    let answer = out
        .lines()
        .rev()
        .find_map(|l| serde_json::from_str::<Value>(l).ok().filter(Value::is_object));
    match answer {
        Some(v) => Probe::Answer(v),
        None => {
            let tail: Vec<&str> = err.lines().filter(|l| !l.trim().is_empty()).collect();
            let tail = tail[tail.len().saturating_sub(3)..].join(" | ");
            Probe::Crashed(status.to_string(), tail)
        }
    }
}

/// The Vulkan loader's variables that replace its driver search (`VK_DRIVER_FILES`, and its
/// older name `VK_ICD_FILENAMES`) or add to it.
const DRIVER_VARIABLES: [&str; 3] = ["VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES"];

/// Mesa's lavapipe driver manifest, when it is installed (`lvp_icd.x86_64.json` and the like).
fn lavapipe() -> Option<PathBuf> {
    let mut found: Vec<PathBuf> = std::fs::read_dir("/usr/share/vulkan/icd.d")
        .ok()?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            p.file_name().and_then(|n| n.to_str()).is_some_and(|n| {
                n.starts_with("lvp_icd.")
                    && n.ends_with(".json")
                    && n.contains(std::env::consts::ARCH)
            })
        })
        .collect();
    found.sort();
    found.into_iter().next()
}

/// The Vulkan drivers the loader is told about on Linux: the manifests in its standard folders,
/// Mesa's lavapipe left out (`nvidia_icd.json`, `radeon_icd.x86_64.json`).
// platform: the Linux loader's folders; elsewhere they are not there and the list is empty.
fn listed_drivers() -> Vec<String> {
    let mut names: Vec<String> = ["/usr/share/vulkan/icd.d", "/etc/vulkan/icd.d"]
        .iter()
        .filter_map(|d| std::fs::read_dir(d).ok())
        .flatten()
        .filter_map(|e| e.ok().map(|e| e.file_name().to_string_lossy().into_owned()))
        .filter(|n| n.ends_with(".json") && !n.starts_with("lvp_icd."))
        .collect();
    names.sort();
    names.dedup();
    names
}

/// The fix when drivers are listed and still no adapter comes: the driver's own library lacks
/// Vulkan (a container given the GPU for computing only, or a driver older than the loader).
fn listed_but_silent(listed: &[String]) -> Option<Text> {
    if listed.is_empty() {
        return None;
    }
    let names = listed.join(", ");
    let nvidia = listed.iter().any(|n| n.contains("nvidia"));
    let container = if nvidia {
        t(
            "コンテナの中なら、GPU をグラフィックス用にも渡します（NVIDIA: NVIDIA_DRIVER_CAPABILITIES=graphics,compute,utility）",
            "in a container, give it the GPU for graphics too (NVIDIA: NVIDIA_DRIVER_CAPABILITIES=graphics,compute,utility)",
        )
    } else {
        t(
            "コンテナの中なら、GPU をグラフィックス用にも渡します",
            "in a container, give it the GPU for graphics too",
        )
    };
    Some(Text::new(
        format!(
            "Vulkan ドライバ（{names}）は登録されていますが、アダプタを返しません。ドライバを入れ直すか更新します。{}",
            container.ja
        ),
        format!(
            "a Vulkan driver is listed ({names}) but gives no adapter: reinstall or update it; {}",
            container.en
        ),
    ))
}

/// What to do when there is no adapter, for this system.
fn no_adapter_fixes(r: &Report, wsl: Option<Wsl>, broken_variable: bool) -> Vec<String> {
    let mut fixes = Vec::new();
    if broken_variable {
        fixes.push(r.words(t(
            "まず上の VK_… の行を直します（存在しないドライバの指定が原因です）",
            "first fix the VK_… line above (it names a driver that is not there)",
        )));
    }
    match std::env::consts::OS {
        "macos" => fixes.push(r.words(t(
            "キットの GPU レンダラは Vulkan 用で、macOS にはありません。CPU のレンダラ（raster・trace・ビューア）を使います",
            "the kit's GPU renderer is built for Vulkan, which macOS does not have: use the CPU renderers (raster, trace, the viewer)",
        ))),
        "windows" => fixes.push(r.words(t(
            "GPU のメーカー（Intel・AMD・NVIDIA）のサイトから最新のドライバを入れます（Vulkan が含まれます）。仮想マシンやリモートデスクトップでは Vulkan がないことがあります",
            "install the newest driver from your GPU's maker (Intel, AMD, NVIDIA): it includes Vulkan. Virtual machines and remote desktops may have no Vulkan",
        ))),
        _ => {
            if let Some(fix) = listed_but_silent(&listed_drivers()) {
                fixes.push(r.words(fix));
            }
            fixes.push(r.words(t(
                "Debian・Ubuntu: sudo apt install mesa-vulkan-drivers libvulkan1（GPU がなくても Mesa の lavapipe が CPU で動きます）。Fedora: sudo dnf install mesa-vulkan-drivers、Arch: sudo pacman -S vulkan-swrast",
                "Debian, Ubuntu: sudo apt install mesa-vulkan-drivers libvulkan1 (without a GPU, Mesa's lavapipe runs on the CPU); Fedora: sudo dnf install mesa-vulkan-drivers; Arch: sudo pacman -S vulkan-swrast",
            )));
            if wsl.is_some() {
                fixes.push(r.words(t(
                    "WSL からは Windows の GPU を Vulkan で使えないことが多いので、上の lavapipe を使います",
                    "under WSL the Windows GPU is often not reachable through Vulkan: use lavapipe as above",
                )));
            }
        }
    }
    fixes.push(r.words(t(
        "GPU がなくても演習はすべてできます。GPU が要るのは render --renderer gpu とビューアの r キーだけです",
        "every part of the course works without a GPU: only render --renderer gpu and the viewer's r key need one",
    )));
    fixes
}

/// The Vulkan loader's variables that name files that are not there, each a problem; whether
/// there was one.
fn driver_variables(r: &mut Report) -> bool {
    let mut broken = false;
    for key in DRIVER_VARIABLES {
        let value = env(key);
        r.set(&key.to_ascii_lowercase(), value.clone());
        let Some(value) = value else { continue };
        let missing: Vec<PathBuf> = std::env::split_paths(&value)
            .filter(|p| !p.as_os_str().is_empty() && !p.exists())
            .collect();
        for file in missing {
            broken = true;
            let text = r.words(Text::new(format!(
                    "{key}={value}: {} がありません（Vulkan はここに書かれたドライバだけを探します）",
                    file.display()
                ), format!(
                    "{key}={value}: {} does not exist (Vulkan looks only for the drivers named here)",
                    file.display()
                )));
            let mut fixes = vec![format!(
                "{}{}",
                unset(key),
                r.words(t(
                    "（Vulkan が自分でドライバを探します）",
                    " (Vulkan then finds its drivers itself)"
                ))
            )];
            if let Some(lvp) = lavapipe() {
                fixes.push(format!(
                    "{}export {key}={}",
                    r.words(t(
                        "または Mesa の lavapipe を指定します: ",
                        "or name Mesa's lavapipe: "
                    )),
                    lvp.display()
                ));
            }
            r.problem(text, fixes);
        }
    }
    broken
}

fn gpu(r: &mut Report, limit: Duration, wsl: Option<Wsl>) {
    let name = r.words(t(
        "GPU レンダラ（render --renderer gpu、ビューアの r キー）",
        "GPU renderer (render --renderer gpu, the viewer's r key)",
    ));
    r.set("gpu_built", cg_viewer::GPU_BUILT);
    if !cg_viewer::GPU_BUILT {
        // The students' copy: left out on purpose, so a note (not a problem) with the command
        // that builds it and runs this report again.
        let command = cg_harness::args::rerun_with_features("gpu");
        let message = r.words(cg_viewer::gpu_left_out(&command));
        for key in ["gpu_adapter", "gpu_device_type", "gpu_software"] {
            r.set(key, Value::Null);
        }
        for key in DRIVER_VARIABLES {
            r.set(&key.to_ascii_lowercase(), env(key));
        }
        r.set("gpu", false);
        r.set("gpu_error", message.clone());
        r.note(format!("{name}: {message}"));
        return;
    }
    let broken_variable = driver_variables(r);
    if let Some(b) = env("WGPU_BACKEND") {
        r.note(format!(
            "WGPU_BACKEND={b} {}",
            r.words(t(
                "（キットの GPU レンダラは Vulkan だけです。vulkan 以外を指定するとアダプタは見つかりません）",
                "(the kit's GPU renderer has Vulkan only: anything but vulkan finds no adapter)",
            ))
        ));
    }
    let probe = probe_gpu(limit);
    let answer = match &probe {
        Probe::Answer(v) => Some(v),
        _ => None,
    };
    let adapter = answer.and_then(|v| v["adapter"].as_str()).map(str::to_owned);
    let software = answer.and_then(|v| v["software"].as_bool());
    r.set("gpu", adapter.is_some());
    r.set("gpu_adapter", adapter.clone());
    r.set("gpu_device_type", answer.and_then(|v| v["device_type"].as_str()).map(str::to_owned));
    r.set("gpu_software", software);
    if let Some(adapter) = adapter {
        r.set("gpu_error", Value::Null);
        r.works(format!("{name}: {} — {adapter}", r.words(t("使えます", "works"))));
        if software == Some(true) {
            r.note(r.words(t(
                "このアダプタは CPU で動くソフトウェアの Vulkan（Mesa の lavapipe など）です。結果は正しいですが速くはありません。本物の GPU のドライバがあればそちらが選ばれます",
                "this adapter is software Vulkan running on the CPU (such as Mesa's lavapipe): correct, but not fast; a real GPU's driver is chosen instead when one is installed",
            )));
        }
        return;
    }
    let secs = limit.as_secs();
    let message = match &probe {
        Probe::Answer(v) => {
            let field = |k: &str| v[k].as_str().unwrap_or_default().to_owned();
            Text::new(field("error_ja"), field("error_en"))
        }
        Probe::TimedOut => Text::new(
            format!("GPU ドライバが {secs} 秒以内に応答しませんでした（ドライバが止まっています）"),
            format!("the GPU driver did not answer within {secs} s (it hangs)"),
        ),
        Probe::Crashed(status, tail) => Text::new(
            format!("GPU を開く途中で異常終了しました（{status}）{}", suffix(tail)),
            format!("opening the GPU crashed ({status}){}", suffix(tail)),
        ),
        Probe::NotStarted(why) => Text::new(
            format!("GPU を確かめるプロセスを起動できません: {}", why.ja),
            format!("cannot start the GPU probe: {}", why.en),
        ),
    };
    let message = r.words(message);
    r.set("gpu_error", message.clone());
    let no_adapter = answer.and_then(|v| v["no_adapter"].as_bool()) == Some(true);
    let fixes = if no_adapter {
        no_adapter_fixes(r, wsl, broken_variable)
    } else {
        let mut fixes = vec![r.words(t(
            "GPU のドライバを更新するか入れ直します（Linux では Mesa: sudo apt install mesa-vulkan-drivers）",
            "update or reinstall the GPU driver (on Linux, Mesa's: sudo apt install mesa-vulkan-drivers)",
        ))];
        if let Some(lvp) = lavapipe() {
            fixes.push(format!(
                "{}VK_DRIVER_FILES={} cargo run --release -- doctor",
                r.words(t(
                    "ソフトウェアの Vulkan（lavapipe）で試すには: ",
                    "to try software Vulkan (lavapipe) instead: "
                )),
                lvp.display()
            ));
        }
        fixes.push(r.words(t(
            "それまでは CPU のレンダラを使います（演習はすべて CPU でできます）",
            "meanwhile use the CPU renderers (every part of the course runs on them)",
        )));
        fixes
    };
    r.problem(format!("{name}: {message}"), fixes);
}

/// `: tail` when there is one.
fn suffix(tail: &str) -> String {
    if tail.is_empty() { String::new() } else { format!(": {tail}") }
}

// ---------------------------------------------------------------------------------------------
// The kit

fn kit(r: &mut Report) {
    r.section(t("キット", "the kit"));
    let path = crate::kit_path(None, "exercises").join("student.toml");
    let shown = path.display().to_string();
    r.set("student_file", shown.clone());
    match guarded(|| Ok(cg_assign::read_student_file(&path))) {
        Ok(Ok(record)) => {
            r.set("student", record.student.to_string());
            r.set("student_error", Value::Null);
            let text = format!(
                "{} {} ({} {}, {shown})",
                r.words(t("学生番号", "student number")),
                record.student,
                r.words(t("課題表", "table")),
                record.table
            );
            r.works(text);
        }
        Ok(Err(e)) => {
            r.set("student", Value::Null);
            r.set("student_error", e.message(r.lang));
            let save = r.words(t(
                "cargo run --release -- assignment --student 12345678 --save（12345678 を自分の学生番号に）",
                "cargo run --release -- assignment --student 12345678 --save (with your own number)",
            ));
            match e {
                cg_assign::StudentFileError::Missing { .. } => {
                    let text = format!(
                        "{shown} {}",
                        r.words(t(
                            "がありません（学生番号がまだ記録されていません）",
                            "does not exist (your student number is not recorded yet)"
                        ))
                    );
                    r.problem(text, vec![save]);
                }
                _ => {
                    let text = e.message(r.lang);
                    let edit = format!(
                        "{}: student = \"12345678\"",
                        r.words(t(
                            &format!("{shown} を直します（8 桁を引用符で囲みます）"),
                            &format!("edit {shown} (8 digits, in quotes)")
                        ))
                    );
                    r.problem(text, vec![edit, format!("{} {save}", r.words(t("または", "or")))]);
                }
            }
        }
        Err(e) => {
            r.set("student", Value::Null);
            r.set("student_error", e.clone());
            r.problem(format!("{shown}: {e}"), Vec::new());
        }
    }
    let release = !cfg!(debug_assertions);
    r.set("release_build", release);
    if release {
        r.works(r.words(t("リリースビルド（--release）です", "release build (--release)")));
    } else {
        let text = r.words(t(
            "デバッグビルドです: 描画もチェックも何倍も遅くなります",
            "this is a debug build: rendering and checks run many times slower",
        ));
        let fixes = vec![r.words(t(
            "いつも --release を付けます: cargo run --release -- doctor",
            "always add --release: cargo run --release -- doctor",
        ))];
        r.problem(text, fixes);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn windows_drives_and_local_x_displays_are_recognised() {
        assert!(on_windows_drive(Path::new("/mnt/c/Users/a/kit")));
        assert!(on_windows_drive(Path::new("/mnt/D")));
        assert!(!on_windows_drive(Path::new("/mnt/wslg/x")));
        assert!(!on_windows_drive(Path::new("/home/a/mnt/c")));
        assert_eq!(local_x_display(":0"), Some(0));
        assert_eq!(local_x_display(":12.0"), Some(12));
        assert_eq!(local_x_display("localhost:10.0"), None);
        assert_eq!(local_x_display(""), None);
    }

    #[test]
    fn a_listed_driver_that_gives_no_adapter_is_named_with_its_likely_cause() {
        assert!(listed_but_silent(&[]).is_none());
        let nvidia = listed_but_silent(&["nvidia_icd.json".to_owned()]).unwrap();
        assert!(nvidia.en.contains("(nvidia_icd.json)"), "{}", nvidia.en);
        assert!(nvidia.en.contains("NVIDIA_DRIVER_CAPABILITIES=graphics"), "{}", nvidia.en);
        assert!(nvidia.ja.contains("NVIDIA_DRIVER_CAPABILITIES=graphics"), "{}", nvidia.ja);
        let amd = listed_but_silent(&["radeon_icd.x86_64.json".to_owned()]).unwrap();
        assert!(!amd.en.contains("NVIDIA"), "{}", amd.en);
    }
}
