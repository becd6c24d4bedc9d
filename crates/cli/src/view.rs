//! `cg view`: the student's picture beside the kit's reference, in a window or as PNG files
//! (with their difference), and the exit status of what could not be drawn.

use std::path::PathBuf;

use cg_assign::{Impls, Variants, Which};
use cg_core::image::Image;
use cg_core::lang::{Lang, t};
use cg_core::scene::Scene;
use cg_harness::Text;
use cg_harness::check::{Outcome, guarded};
use cg_harness::exit::Ending;

use crate::assignments::student;
use crate::reload;

/// Options of `cg view`.
#[derive(clap::Args)]
pub struct ViewArgs {
    /// Which assignment / 課題
    #[arg(value_enum)]
    which: Which,
    /// The student number (default: exercises/student.toml) / 学生番号
    #[arg(long, value_name = "NUMBER", allow_hyphen_values = true)]
    student: Option<String>,
    /// The time in seconds, for animations, 0–16667 / 時刻（秒、アニメーション用、0〜16667）
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = seconds)]
    time: f64,
    /// a3 only: the in-class warm-up (three boxes) instead of your assignment / a3 のみ: 演習課題（3 つの直方体）を表示
    #[arg(long)]
    warmup: bool,
    /// The folder for the PNG files / PNG を保存するフォルダ
    #[arg(short, long, default_value = "out")]
    output: PathBuf,
    /// Draw PNG files even when a window could be opened / ウィンドウを開けても PNG に描画する
    #[arg(long)]
    png: bool,
    /// Window: close after this many frames / ウィンドウ: このフレーム数で閉じる
    #[arg(long, value_name = "N", conflicts_with_all = PNG_ONLY)]
    frames: Option<u64>,
    /// Window: save the last frame (and the s key's) here / ウィンドウ: 最後のフレーム（と s キー）の保存先
    #[arg(long, value_name = "PNG", conflicts_with_all = PNG_ONLY)]
    screenshot: Option<PathBuf>,
    /// Window: start with the animation paused / ウィンドウ: アニメーションを止めて始める
    #[arg(long, conflicts_with_all = PNG_ONLY)]
    paused: bool,
    /// PNG: N frames over one period of the animation in one picture (a3), 2–16 / PNG: アニメーションの 1 周期を N 枚並べた図（a3、2〜16）
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(2..=16))]
    strip: Option<u32>,
    /// PNG from another side: the orbit camera's yaw in degrees (a turn about +Y) / 別の向きから PNG に描画: カメラの方位角（度、+Y 軸まわり）
    #[arg(long, value_name = "DEG", allow_hyphen_values = true, value_parser = degrees(-360.0, 360.0))]
    yaw: Option<f32>,
    /// PNG from another side: the pitch in degrees, −90 (from above) to 90 (from below) / 別の向きから PNG に描画: 仰角（度、−90 で真上から、90 で真下から）
    #[arg(long, value_name = "DEG", allow_hyphen_values = true, value_parser = degrees(-90.0, 90.0))]
    pitch: Option<f32>,
    /// PNG from another side: the distance from the target, 0.1–1000 / 別の向きから PNG に描画: 注視点からの距離（0.1〜1000）
    #[arg(long, value_name = "D", value_parser = degrees(0.1, 1000.0))]
    distance: Option<f32>,
}

/// The options that draw PNG files whatever the display: the window's options cannot go with
/// them (`--png --screenshot x.png` wrote no screenshot, with exit 0).
const PNG_ONLY: [&str; 5] = ["png", "strip", "yaw", "pitch", "distance"];

/// A value parser for a number in `[min, max]` (an angle or a distance on the command line).
fn degrees(min: f32, max: f32) -> impl Fn(&str) -> Result<f32, String> + Clone {
    move |s: &str| match s.parse::<f32>() {
        Ok(x) if x.is_finite() && (min..=max).contains(&x) => Ok(x),
        _ => Err(format!("{min} … {max}")),
    }
}

/// `--time`: a finite number of seconds from 0 to the longest time an animation is drawn at
/// ([`cg_assign::cg_a3::VIEW_MAX_S`]), so that both pictures are drawn at the time asked for
/// (NaN or a time past it drew the reference at its first frame).
fn seconds(s: &str) -> Result<f64, String> {
    let max = cg_assign::cg_a3::VIEW_MAX_S;
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() && (0.0..=max).contains(&x) => Ok(x),
        _ => Err(format!("0 … {max:.0}")),
    }
}

impl ViewArgs {
    /// Whether the camera was moved on the command line (then the view is drawn to PNG files).
    fn camera_moved(&self) -> bool {
        self.yaw.is_some() || self.pitch.is_some() || self.distance.is_some()
    }

    /// Whether the view is drawn to PNG files whatever the display (`--png`, a moved camera, a
    /// strip).
    fn png_only(&self) -> bool {
        self.png || self.camera_moved() || self.strip.is_some()
    }

    /// The window's options given (`--frames`, `--screenshot`, `--paused`), by name: without a
    /// window they would do nothing.
    fn window_options(&self) -> Vec<&'static str> {
        [
            ("--frames", self.frames.is_some()),
            ("--screenshot", self.screenshot.is_some()),
            ("--paused", self.paused),
        ]
        .into_iter()
        .filter_map(|(name, given)| given.then_some(name))
        .collect()
    }

    /// The scene's orbit camera moved as `--yaw`, `--pitch` and `--distance` say (an option not
    /// given stays as it was). A view whose camera the student's display() sets cannot move.
    fn move_camera(&self, scene: &mut Scene, lang: Lang) -> Result<(), String> {
        use cg_core::scene::Camera;
        if !self.camera_moved() {
            return Ok(());
        }
        match &mut scene.camera {
            Camera::Orbit(orbit) => {
                if let Some(yaw) = self.yaw {
                    orbit.yaw_deg = yaw.rem_euclid(360.0);
                }
                if let Some(pitch) = self.pitch {
                    // From below too (the course's mouse keeps the camera above the ground).
                    orbit.limits.pitch_min_deg = orbit.limits.pitch_min_deg.min(pitch);
                    orbit.limits.pitch_max_deg = orbit.limits.pitch_max_deg.max(pitch);
                    orbit.pitch_deg = pitch;
                }
                if let Some(distance) = self.distance {
                    orbit.limits.distance_min = orbit.limits.distance_min.min(distance);
                    orbit.limits.distance_max = orbit.limits.distance_max.max(distance);
                    orbit.distance = distance;
                }
            }
            // The view comes from the student's own display() (gluLookAt, or a view recorded
            // into the modelview): there is no orbit to move.
            Camera::LookAt { .. } => {
                return Err(t(
                    "--yaw・--pitch・--distance は周回カメラ（a1、a4 など）を動かします。この図の視点はあなたの display() が決めているので動かせません",
                    "--yaw, --pitch and --distance move the orbit camera (a1, a4, …); this view's camera is set by your own display(), so they cannot move it",
                ).get(lang)
                    .to_owned());
            }
        }
        Ok(())
    }
}

/// The functions a side of `cg view` draws: the student's, in the worker current on this thread
/// (`view` starts it), or the reference solutions' when they are part of this kit (for a view
/// the kit has no reference picture of its own for: the warm-up).
fn impls(reference: bool) -> Impls {
    let _ = reference;
    #[cfg(feature = "reference")]
    if reference {
        return cg_assign::impls!(cg_solutions);
    }
    Impls::worker()
}

fn view_scene(
    which: Which,
    a: &Variants,
    reference: bool,
    time: f64,
    warmup: bool,
) -> Result<Result<Scene, Text>, Outcome> {
    // The reference: the kit's own picture, built from its oracles (the students' copy has it
    // too); the reference solutions only where the kit has none (the warm-up).
    if reference
        && !warmup
        && let Some(scene) = a.reference_view(which, time)
    {
        return Ok(Ok(scene));
    }
    let impls = impls(reference);
    if warmup {
        return guarded(|| Variants::warmup(which, &impls, time).ok_or_else(|| no_warmup(which)));
    }
    guarded(|| a.view(which, &impls, time))
}

/// Why a side has no picture: the student's function is a stub, panicked, ran out of time, or
/// its file does not compile (then with the compiler's first error).
fn not_drawn(outcome: &Outcome, lang: Lang) -> String {
    match outcome {
        Outcome::NotDone { message } => format!(
            "{}: {}",
            t("まだです", "not done yet").get(lang),
            cg_harness::check::stub_message(message, lang)
        ),
        Outcome::DoesNotCompile { errors, .. } => {
            let first = errors.first().map(|e| e.lines().take(8).collect::<Vec<_>>().join("\n"));
            let head = outcome.describe().map(|d| d.get(lang).to_owned()).unwrap_or_default();
            first.map_or_else(|| head.clone(), |e| format!("{head}\n{e}"))
        }
        other => other.describe().map_or_else(|| format!("{other:?}"), |d| d.get(lang).to_owned()),
    }
}

/// Why `--warmup` does not apply to `which`, naming the assignments it applies to.
fn no_warmup(which: Which) -> Text {
    let with: Vec<&str> = Which::ALL.iter().filter(|w| w.has_warmup()).map(|w| w.id()).collect();
    let with = with.join(", ");
    Text::new(
        format!("--warmup は {with} だけの設定です（{which} には演習課題がありません）"),
        format!("--warmup belongs to {with} only ({which} has no warm-up)"),
    )
}

/// `cg view`: draws the student's result and the kit's reference picture beside it
/// (`Assignment::reference_view`, in the students' copy too), in a window or to PNG files, with
/// their difference. The student's functions run in a worker.
///
/// It ends as every command of the kit (`cg_harness::exit`): 3 when the student's code ran out
/// of time (any call of the worker, whatever the assignment's view made of it), 1 when a side
/// has no picture because the code panicked, crashed, does not compile or gave something that
/// cannot be drawn, else 0 — with a stub not done yet, too. What can be drawn is drawn first.
pub fn run(args: &ViewArgs, lang: Lang) -> Result<Ending, String> {
    use cg_assign::local;
    let worker = local::worker_for_a_window(local::MEMORY_MB, lang)?;
    let (ending, worker) =
        cg_worker::proxy::with_worker(worker, local::CALL_LIMIT, || view_in_worker(args, lang));
    ending.map(|ending| if worker.timeouts > 0 { Ending::TimedOut } else { ending })
}

/// How a side of `cg view` ended, for the exit status: [`Ending::TimedOut`] for a call that ran
/// out of time, [`Ending::Mistakes`] for no picture because of the student's code (a panic, a
/// crash, a file that does not compile, a result that cannot be drawn), [`Ending::Ok`] for a
/// picture or a stub not done yet.
fn side_ending<T>(side: &Result<Result<T, Text>, Outcome>) -> Ending {
    match side {
        Ok(Ok(_)) | Err(Outcome::NotDone { .. }) => Ending::Ok,
        Err(Outcome::TimedOut { .. }) => Ending::TimedOut,
        Ok(Err(_)) | Err(_) => Ending::Mistakes,
    }
}

/// The worse of two endings (the higher status: a time-out over mistakes over none).
fn worse(a: Ending, b: Ending) -> Ending {
    if b.code() > a.code() { b } else { a }
}

/// Without a window, the window's options would be passed over (no screenshot written, with
/// exit 0): an error that names them instead, before any PNG file is drawn.
fn no_window_for(args: &ViewArgs, lang: Lang) -> Result<(), String> {
    let options = args.window_options();
    if options.is_empty() {
        return Ok(());
    }
    let options = options.join(", ");
    Err(cg_core::lang::Text::new(
        format!(
            "{options} はウィンドウのためのオプションですが、ウィンドウを開けません（画面がありません）。外すと PNG に描画します"
        ),
        format!(
            "{options}: for the window, and no window can open (no display); leave them out to draw PNG files"
        ),
    )
    .get(lang)
    .to_owned())
}

fn view_in_worker(args: &ViewArgs, lang: Lang) -> Result<Ending, String> {
    let record = student(args.student.as_deref(), None, lang)?;
    let a = Variants::for_student(&record.student, record.table);
    if args.warmup && !args.which.has_warmup() {
        return Err(no_warmup(args.which).get(lang).to_owned());
    }
    let mut sides = vec![(false, t("あなたの結果", "yours"), "yours")];
    let kit_reference = !args.warmup && a.reference_view(args.which, args.time).is_some();
    if kit_reference || cfg!(feature = "reference") {
        sides.push((true, t("参考解答", "reference"), "reference"));
    }
    if !args.png_only()
        && cg_viewer::display_available()
        && std::env::var_os("CG_NO_WINDOW").is_none()
    {
        // A window that cannot open (a display named but dead): the same PNG files as --png.
        match view_window(args, &a, &sides, lang)? {
            Ok(ending) => return Ok(ending),
            Err(reason) => {
                eprintln!("{}", cg_viewer::no_window(&reason, lang));
                no_window_for(args, lang)?;
            }
        }
    } else if !args.png_only() {
        no_window_for(args, lang)?;
    }
    println!(
        "{}",
        t(
            "PNG に描画します（ウィンドウは画面（WAYLAND_DISPLAY か DISPLAY）があるときに --png なしで開きます）:",
            "Drawing to PNG files (a window opens when there is a display (WAYLAND_DISPLAY or DISPLAY) and no --png):",
        ).get(lang)
    );
    if std::fs::metadata(&args.output).is_ok_and(|m| !m.is_dir()) {
        let shown = args.output.display();
        return Err(cg_core::lang::Text::new(
            format!(
                "-o {shown} はフォルダではなくファイルです。PNG を書くフォルダを指定してください"
            ),
            format!("-o {shown} is a file, not a folder: give a folder for the PNG files"),
        )
        .get(lang)
        .to_owned());
    }
    let mut name =
        if args.warmup { format!("{}-warmup", args.which) } else { args.which.to_string() };
    // A strip has names of its own: it does not replace the single frame's pictures.
    if args.strip.is_some() {
        name.push_str("-strip");
    }
    let times = strip_times(args, &a, lang)?;
    let mut drawn = Vec::new();
    let mut ending = Ending::Ok;
    for (reference, label, file) in sides {
        let label = label.get(lang);
        let path = args.output.join(format!("view-{name}-{file}.png"));
        // No picture left from an earlier run beside this run's words.
        let _ = std::fs::remove_file(&path);
        let picture = view_picture(args, &a, reference, &times, lang)?;
        ending = worse(ending, side_ending(&picture));
        match picture {
            Ok(Ok(image)) => {
                if let Some(dir) = path.parent() {
                    std::fs::create_dir_all(dir)
                        .map_err(|e| cg_core::lang::Text::io_at(dir, &e).get(lang).to_owned())?;
                }
                cg_scene::save_png(&path, &image).map_err(|e| e.describe(lang))?;
                println!("  {label}: {}", path.display());
                drawn.push(image);
            }
            Ok(Err(why)) => println!("  {label}: {}", why.get(lang)),
            Err(outcome) => {
                println!("  {label}: {}", not_drawn(&outcome, lang).replace('\n', "\n    "));
            }
        }
    }
    let diff_path = args.output.join(format!("view-{name}-diff.png"));
    let _ = std::fs::remove_file(&diff_path);
    if let [yours, reference] = drawn.as_slice()
        && let Some((diff, differ)) = difference(yours, reference)
    {
        cg_scene::save_png(&diff_path, &diff).map_err(|e| e.describe(lang))?;
        let total = diff.pixels.len();
        println!(
            "  {}: {}",
            t("違い", "difference").get(lang),
            if differ == 0 {
                t("参考解答と同じ絵です", "the same picture as the reference").get(lang).to_owned()
            } else {
                t(
                    &format!(
                        "{total} ピクセル中 {differ} ピクセルが 2/255 より違います（4 倍に強調して {}）",
                        diff_path.display()
                    ),
                    &format!(
                        "{differ} of {total} pixels differ by more than 2/255 (×4 in {})",
                        diff_path.display()
                    ),
                )
                .get(lang)
                .to_owned()
            }
        );
    }
    Ok(ending)
}

/// The times the view is drawn at: `--time`, or with `--strip N` the N frames of one period
/// from `--time` on.
fn strip_times(args: &ViewArgs, a: &Variants, lang: Lang) -> Result<Vec<f64>, String> {
    let Some(n) = args.strip else { return Ok(vec![args.time]) };
    let period = a.view_period_s(args.which).filter(|_| !args.warmup).ok_or_else(|| {
        t(
            "--strip は動く課題（a3）の 1 周期を並べます。この図は動きません",
            "--strip lays out one period of an animation (a3); this view does not move",
        )
        .get(lang)
        .to_owned()
    })?;
    Ok((0..n).map(|k| args.time + period * f64::from(k) / f64::from(n)).collect())
}

/// One side's picture: the view at each of `times` (one time: the picture itself; more: a
/// grid of half-size frames, each labelled with its time), the camera moved as asked, labels
/// written. The inner results are why there is no picture.
fn view_picture(
    args: &ViewArgs,
    a: &Variants,
    reference: bool,
    times: &[f64],
    lang: Lang,
) -> Result<Result<Result<Image, Text>, Outcome>, String> {
    let mut frames = Vec::new();
    for &t in times {
        let mut scene = match view_scene(args.which, a, reference, t, args.warmup) {
            Ok(Ok(scene)) => scene,
            Ok(Err(why)) => return Ok(Ok(Err(why))),
            Err(outcome) => return Ok(Err(outcome)),
        };
        args.move_camera(&mut scene, lang)?;
        let size = (times.len() > 1).then_some((scene.width / 2, scene.height / 2));
        let options = cg_raster::Options { size, ..cg_raster::Options::default() };
        let mut image = cg_raster::render(&scene, &options).map_err(|e| e.message(lang))?.image;
        // The shading set names its three spheres.
        crate::label::at_places(&mut image, &a.view_labels(args.which));
        frames.push((image, format!("t = {t:.2} s")));
    }
    if frames.len() == 1 {
        return Ok(Ok(Ok(frames.remove(0).0)));
    }
    let labelled: Vec<(&Image, &str)> = frames.iter().map(|(i, l)| (i, l.as_str())).collect();
    Ok(Ok(Ok(crate::label::labelled_grid(&labelled, 4, 2))))
}

/// The difference of two pictures of one size, each channel's `|a − b|` times 4 (so a small
/// difference shows), and how many pixels differ by more than 2/255 in some channel. `None` for
/// pictures of different sizes.
fn difference(a: &Image, b: &Image) -> Option<(Image, usize)> {
    if (a.width, a.height) != (b.width, b.height) {
        return None;
    }
    let (pa, pb) = (a.to_rgba8(), b.to_rgba8());
    let mut differ = 0;
    let pixels = pa
        .iter()
        .zip(&pb)
        .map(|(p, q)| {
            let d = [0, 1, 2].map(|c| p[c].abs_diff(q[c]));
            if d.iter().any(|&x| x > 2) {
                differ += 1;
            }
            cg_core::Rgb::from_array(d.map(|x| (f32::from(x) * 4.0 / 255.0).min(1.0)))
        })
        .collect();
    Some((Image { width: a.width, height: a.height, pixels }, differ))
}

/// `cg view` in a window: the student's result and the reference side by side, at the same time
/// and from the same camera (assignment 2's camera is the student's own), animated: how it
/// ended once closed (the worst of every frame drawn, as [`side_ending`] says), or `Err(why)`
/// when no window could be opened.
fn view_window(
    args: &ViewArgs,
    a: &Variants,
    sides: &[(bool, Text, &str)],
    lang: Lang,
) -> Result<Result<Ending, String>, String> {
    let (which, warmup) = (args.which, args.warmup);
    // The worst ending of any frame of any side, for the exit status once the window closes.
    let ending = std::rc::Rc::new(std::cell::Cell::new(Ending::Ok));
    let sources: Vec<cg_viewer::Source> = sides
        .iter()
        .map(|(reference, label, _)| {
            let (a, reference, ending) = (a.clone(), *reference, ending.clone());
            cg_viewer::Source {
                label: label.get(lang).to_owned(),
                scene_at: Box::new(move |time| {
                    let scene = view_scene(which, &a, reference, time, warmup);
                    ending.set(worse(ending.get(), side_ending(&scene)));
                    match scene {
                        Ok(Ok(scene)) => Ok(scene),
                        Ok(Err(why)) => Err(why.get(lang).to_owned()),
                        Err(outcome) => Err(not_drawn(&outcome, lang)),
                    }
                }),
                own_camera: which.own_camera() && !warmup,
            }
        })
        .collect();
    let name = if warmup { format!("{which}-warmup") } else { which.to_string() };
    let mut app = cg_viewer::SideBySide::new(&name, sources, args.time)?;
    app.view.paused = args.paused;
    // Started again after a rebuild: the same camera.
    if let Some(r) = reload::Resume::from_env() {
        let camera = &mut app.view.camera;
        (camera.yaw_deg, camera.pitch_deg, camera.distance) = (r.yaw_deg, r.pitch_deg, r.distance);
    }
    // An interactive window watches the program of the student's functions, which `cg watch`
    // rebuilds on every save; it then starts this one again.
    let program = std::env::current_exe().ok().filter(|_| args.frames.is_none());
    let options = cg_viewer::ViewerOptions {
        frames: args.frames,
        screenshot: args.screenshot.clone(),
        out_dir: Some(args.output.clone()),
        paused: args.paused,
        lang,
        reload_on_change: program.as_ref().map(|_| cg_assign::local::worker_program()),
        ..cg_viewer::ViewerOptions::default()
    };
    cg_viewer::print_keys(lang);
    let backends = cg_viewer::default_backends(None, lang);
    match cg_viewer::run_window(&mut app, backends, &options).map_err(|e| e.message(lang))? {
        cg_viewer::WindowEnd::Closed => Ok(Ok(ending.get())),
        cg_viewer::WindowEnd::NoWindow(reason) => Ok(Err(reason)),
        cg_viewer::WindowEnd::Changed => {
            let camera = &app.view.camera;
            let resume = reload::Resume {
                yaw_deg: camera.yaw_deg,
                pitch_deg: camera.pitch_deg,
                distance: camera.distance,
            };
            let args: Vec<String> = std::env::args().skip(1).collect();
            let args = reload::arguments(&args, app.time, app.view.paused);
            let program = program.unwrap_or_default();
            reload::restart(&program, &args, resume, lang).map(|()| Ok(ending.get()))
        }
    }
}

#[cfg(test)]
mod tests {
    use clap::Parser as _;

    use crate::Cli;

    /// `--time` is a finite number of seconds an animation is drawn at: NaN, an infinity, a
    /// negative time or one past the last drawn frame is a usage error before anything runs
    /// (they drew the reference at its first frame beside an error, and ended with 0).
    #[test]
    fn a_time_is_a_number_of_seconds_the_animation_is_drawn_at() {
        let parse = |time: &str| Cli::try_parse_from(["cg", "view", "a3", "--time", time]);
        for ok in ["0", "2.5", "16666"] {
            assert!(parse(ok).is_ok(), "{ok}");
        }
        for bad in ["nan", "inf", "-inf", "-1", "-0.5", "1e9", "16668", "x"] {
            let e = parse(bad).err().unwrap_or_else(|| panic!("{bad} was taken"));
            assert_eq!(e.kind(), clap::error::ErrorKind::ValueValidation, "{bad}: {e}");
        }
        // The help's range is the limit's.
        assert_eq!(cg_assign::cg_a3::VIEW_MAX_S.round(), 16667.0);
    }

    /// `cg view` ends as `check` does: 3 when the student's code ran out of time, 1 when a side
    /// has no picture because of it (a panic, a crash, a file that does not compile, a result
    /// that cannot be drawn), 0 for pictures and for stubs not done yet; the worst side wins.
    /// (A time-out or a panic printed its explanation and ended with 0.)
    #[test]
    fn a_view_ends_3_for_a_time_out_and_1_for_a_panic() {
        use cg_harness::Text;
        use cg_harness::check::Outcome;
        use cg_harness::exit::Ending;
        type Side = Result<Result<(), Text>, Outcome>;
        let timed_out: Side = Err(Outcome::TimedOut {
            limit_ms: 20_000,
            function: Some("a3.idle".into()),
            earlier: false,
        });
        let panicked: Side = Err(Outcome::Panicked { message: "too far".into(), location: None });
        let not_drawable: Side = Ok(Err(Text::new("描けません", "cannot be drawn")));
        let not_done: Side = Err(Outcome::NotDone { message: "a1.t1: write it".into() });
        let compile: Side = Err(Outcome::DoesNotCompile { module: "a2".into(), errors: vec![] });
        let cases = [
            (&timed_out, Ending::TimedOut),
            (&panicked, Ending::Mistakes),
            (&not_drawable, Ending::Mistakes),
            (&compile, Ending::Mistakes),
            (&not_done, Ending::Ok),
            (&Ok(Ok(())), Ending::Ok),
        ];
        for (side, ending) in cases {
            assert_eq!(super::side_ending(side), ending, "{side:?}");
        }
        let worst = [Ending::Ok, Ending::TimedOut, Ending::Mistakes]
            .into_iter()
            .fold(Ending::Ok, super::worse);
        assert_eq!(worst, Ending::TimedOut);
        assert_eq!(super::worse(Ending::Mistakes, Ending::Ok), Ending::Mistakes);
    }
}
