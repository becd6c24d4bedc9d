//! The commands `cg report …` and the `report-checker` binary share: one implementation, two
//! fronts.
//!
//! - `derive`: everything the report needs, derived from the student's exercises (or from a data
//!   file), written into one folder: each table, matrix and formula as a Markdown and a LaTeX
//!   fragment (`fragments/`), the three views and the perspective view as SVG, the prepared
//!   image with the mapped rectangle, and the rendered result of each assignment.
//! - `fill`: the same, plus the report template filled into `report.md` and `report.tex`.
//! - `check`: reads a report (Markdown) and names every number in it that does not follow from
//!   the data, with the derived value and the tolerance used.
//!
//! The report and the data file are read in the encoding the student's editor wrote them in
//! (UTF-8, UTF-16 with or without a BOM, or Shift_JIS, detected; `--encoding` names it), and
//! the summary says when it was not UTF-8 ("read as Shift_JIS"). Everything written is UTF-8.

use std::cell::RefCell;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Duration;

use cg_assign::Variants;
use cg_core::lang::{Lang, t};
use cg_core::text::Encoding;
use cg_harness::check::{Outcome, guarded};
use cg_harness::exit::Ending;
use cg_harness::{TableVersion, Text};

use crate::derive::{self, Missing};
use crate::figures;
use crate::fill::{self, Context, VIEWS, files};
use crate::model::{Derived, PolygonData};
use crate::parse::{self, ParseProblem};
use crate::template::{self, Format};
use crate::verify;
use cg_assign::{Impls, Which};

mod outcome;
mod written;

pub use outcome::CheckOutcome;
pub use written::Written;

/// The report commands.
#[derive(Clone, Debug, clap::Subcommand)]
pub enum Command {
    /// Derive every table, figure and matrix your report needs into one folder / レポートに必要な表・図・行列をフォルダに書き出す
    Derive(DeriveArgs),
    /// Write the report template filled with your data (report.md, report.tex) / データを埋めたレポートのひな形を書き出す
    Fill(FillArgs),
    /// Check the numbers written in your report / レポートに書いた数値を確かめる
    Check(CheckArgs),
}

/// Where the data comes from.
#[derive(Clone, Debug, Default, clap::Args)]
pub struct Source {
    /// The student number (default: exercises/student.toml) / 学生番号
    #[arg(long, value_name = "NUMBER", allow_hyphen_values = true, conflicts_with = "data")]
    pub student: Option<String>,
    /// The variant table (default: the one in exercises/student.toml) / 課題表の版
    #[arg(long, value_name = "N", allow_negative_numbers = true, conflicts_with = "data")]
    pub table: Option<TableVersion>,
    /// A vertex and face list (the lecture's notation: `V0 (0.0, 1.0, 0.0)`, `F0 { V0, V3, V1 }`)
    /// instead of the exercises / 演習のプログラムの代わりに、頂点と面の一覧のファイルを使う
    #[arg(long, value_name = "FILE")]
    pub data: Option<PathBuf>,
    /// The encoding of the report and the data file: utf-8, utf-16le, utf-16be or shift_jis
    /// (default: detected; UTF-8, UTF-16 with or without a BOM and Shift_JIS are told apart)
    /// / レポートとデータファイルの文字コード（省略時は UTF-8・UTF-16（BOM なしも）・Shift_JIS を自動判別）
    #[arg(long, value_name = "ENCODING")]
    pub encoding: Option<Encoding>,
}

/// Options of `derive`.
#[derive(Clone, Debug, clap::Args)]
pub struct DeriveArgs {
    /// Where the data comes from.
    #[command(flatten)]
    pub source: Source,
    /// The output folder / 出力先のフォルダ
    #[arg(short, long, default_value = "report")]
    pub output: PathBuf,
    /// Do not draw the assignments' results (faster) / 実行結果の画像を描画しない
    #[arg(long)]
    pub no_render: bool,
}

/// Options of `fill`.
#[derive(Clone, Debug, clap::Args)]
pub struct FillArgs {
    /// What to derive, and where.
    #[command(flatten)]
    pub derive: DeriveArgs,
    /// Overwrite report.md / report.tex when they exist (your edits are lost) / 既存の report.md・report.tex を上書きする
    #[arg(long)]
    pub force: bool,
}

/// Options of `check`.
#[derive(Clone, Debug, clap::Args)]
pub struct CheckArgs {
    /// The report to check (Markdown; default: report/report.md). With --data and no report,
    /// the data file's own normals and winding are checked / 確かめるレポート（Markdown）
    pub report: Option<PathBuf>,
    /// Where the data comes from.
    #[command(flatten)]
    pub source: Source,
    /// Print JSON for tools / JSON で出力
    #[arg(long)]
    pub json: bool,
}

/// How long one of the student's functions may run while a report command calls it
/// ([`Kit::exercises`]'s [`Kit::time_limit`]).
pub const TIME_LIMIT: std::time::Duration = cg_assign::local::CALL_LIMIT;

/// For a [`Kit`] whose functions run in this process (no [`Kit::worker`]): a student's function
/// that never returns ends the command after `limit` with exit code 3 and a message in `lang`,
/// instead of hanging. Call once, before [`run`]. (The worker of [`Kit::exercises`] stops such a
/// call by itself, and the part it was for is reported missing.)
pub fn start_watchdog(limit: std::time::Duration, lang: Lang) {
    cg_harness::check::watchdog(limit, lang);
}

/// What the commands need from the program that runs them.
#[derive(Clone, Copy, Debug)]
pub struct Kit {
    /// The student's functions.
    pub impls: Impls,
    /// `exercises/student.toml`.
    pub student_file: fn() -> PathBuf,
    /// Starts the worker that `impls` call when they are the worker's ([`Impls::worker`]);
    /// `None` when they run in this process (the kit's tests, with its reference solutions).
    pub worker: Option<fn(Lang) -> Result<cg_worker::Worker, String>>,
    /// How long one of the student's functions may run in the worker ([`TIME_LIMIT`]; the
    /// tests' worker is given less).
    pub time_limit: std::time::Duration,
}

impl Kit {
    /// The student's exercises of this kit, run in a worker built from them
    /// ([`cg_assign::local`]): a file that does not compile leaves out only its own parts.
    #[must_use]
    pub fn exercises() -> Kit {
        Kit {
            impls: Impls::worker(),
            student_file: || cg_harness::kit_path(None, "exercises").join("student.toml"),
            worker: Some(|lang| {
                cg_assign::local::worker_for_this_kit(cg_assign::local::MEMORY_MB, lang)
            }),
            time_limit: TIME_LIMIT,
        }
    }
}

/// Runs a report command: [`Ending::Mistakes`] when a check found mistakes,
/// [`Ending::TimedOut`] when one of the student's functions ran out of its time (said on
/// standard error). The assignments are derived (and drawn) one at a time, each in a session of
/// its own with the worker: a function that ran out of time leaves out the parts of its own
/// assignment that call it, and holds up no other assignment's.
///
/// # Errors
/// What could not be read or written, as a message in `lang`.
pub fn run(command: &Command, kit: &Kit, lang: Lang) -> Result<Ending, String> {
    let source = match command {
        Command::Derive(args) => &args.source,
        Command::Fill(args) => &args.derive.source,
        Command::Check(args) => &args.source,
    };
    // The student's functions are called only when the data is not a file of its own.
    match kit.worker.filter(|_| source.data.is_none()) {
        Some(start) => {
            let worker = start(lang)?;
            let (passed, timeouts) =
                with_parts(worker, kit.time_limit, || run_here(command, kit, lang));
            let passed = passed?;
            if timeouts > 0 {
                let seconds = kit.time_limit.as_secs_f64();
                eprintln!(
                    "{}",
                    Text::new(
                        format!(
                            "あなたの関数が {seconds} 秒たっても戻りませんでした。無限ループになっていないか確認してください（その関数を呼ぶ部分は導出・描画していません。ほかの部分は導出しました）"
                        ),
                        format!(
                            "one of your functions did not return within {seconds} s: does it loop forever? (the parts that call it were not derived or drawn; the others were)"
                        ),
                    )
                    .get(lang)
                );
                return Ok(Ending::TimedOut);
            }
            Ok(Ending::passed(passed))
        }
        None => run_here(command, kit, lang).map(Ending::passed),
    }
}

thread_local! {
    /// The worker of the running report command ([`with_parts`]) and its time limit, between
    /// the sessions of [`in_part`]; `None` when the student's functions run in this process.
    static WORKER: RefCell<Option<(cg_worker::Worker, Duration)>> = const { RefCell::new(None) };
}

/// Runs `f` (a report command) with `worker` at hand for [`in_part`]: its value, and how many
/// of the student's calls ran out of `limit`.
fn with_parts<T>(worker: cg_worker::Worker, limit: Duration, f: impl FnOnce() -> T) -> (T, usize) {
    /// Takes the worker back, also when `f` panics (dropping it stops it).
    struct Taken;
    impl Drop for Taken {
        fn drop(&mut self) {
            WORKER.with(|w| w.borrow_mut().take());
        }
    }
    let taken = Taken;
    WORKER.with(|w| *w.borrow_mut() = Some((worker, limit)));
    let value = f();
    let timeouts = WORKER.with(|w| w.borrow().as_ref().map_or(0, |(worker, _)| worker.timeouts));
    drop(taken);
    (value, timeouts)
}

/// Runs `f`, one part of a report command (one assignment derived and drawn), in a session of
/// its own with the worker of [`with_parts`] (`cg_worker::proxy::with_worker_until_timeout`);
/// just `f` when there is none (the functions run in this process).
///
/// The session is the part's alone: a call outside a check that comes after one of its calls
/// ran out of time fails at once, but only within the part. A function of a3 that loops leaves
/// a2's parts alone (they were "not run" because of it when the whole command was one session),
/// and the worker it stopped is started afresh by the next call.
fn in_part<T>(f: impl FnOnce() -> T) -> T {
    let Some((mut worker, limit)) = WORKER.with(|w| w.borrow_mut().take()) else {
        return f();
    };
    // The session counts this part's timeouts alone (a count above 0 fails its calls outside
    // a check at once); the command's total is kept on the worker.
    let before = std::mem::take(&mut worker.timeouts);
    let (value, mut worker) = cg_worker::proxy::with_worker_until_timeout(worker, limit, f);
    worker.timeouts += before;
    WORKER.with(|w| *w.borrow_mut() = Some((worker, limit)));
    value
}

/// [`run`], the student's functions being ready to call.
fn run_here(command: &Command, kit: &Kit, lang: Lang) -> Result<bool, String> {
    match command {
        Command::Derive(args) => {
            let written = derive_to(args, kit, lang)?;
            print!("{}", written.summary(lang));
            Ok(true)
        }
        Command::Fill(args) => {
            let written = fill_to(args, kit, lang)?;
            print!("{}", written.summary(lang));
            Ok(true)
        }
        Command::Check(args) => {
            let outcome = match check(args, kit, lang) {
                Ok(outcome) => outcome,
                // A tool reading --json gets JSON on stdout for an error too (the message is
                // also said on stderr, with exit 2).
                Err(e) if args.json => {
                    println!("{}", serde_json::json!({ "error": e }));
                    return Err(e);
                }
                Err(e) => return Err(e),
            };
            if args.json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&outcome.to_json(lang)).unwrap_or_default()
                );
            } else {
                print!("{}", outcome.render(lang));
            }
            Ok(outcome.ok())
        }
    }
}

/// The data a report is about, with what could not be derived and the template's context.
#[derive(Clone, Debug)]
pub struct Gathered {
    /// The derived data.
    pub derived: Derived,
    /// The placeholders' context (student, assignment texts, missing parts).
    pub context: Context,
    /// The assignment, when the data came from the exercises.
    pub assignment: Option<Variants>,
    /// The files read (the data file), each with the encoding it was read in.
    pub read: Vec<(PathBuf, Encoding)>,
}

/// A student's text file in `forced` or the encoding detected ([`cg_core::text::read`]).
fn read_text(
    path: &Path,
    forced: Option<Encoding>,
    lang: Lang,
) -> Result<(String, Encoding), String> {
    let said = |e: cg_core::text::ReadError| format!("{}: {}", path.display(), e.text().get(lang));
    let bytes = cg_core::text::read_bounded(path, MAX_REPORT_BYTES).map_err(said)?;
    cg_core::text::decode(&bytes, forced).map_err(|e| said(e.into()))
}

/// The most bytes of a report or a data file read: 8 MiB, far past any report (the course's are
/// tens of kilobytes; a data file of 100 000 faces is about 5 MB). Reading one costs about 30
/// times its size: 63 MiB of vertex lines (the 64 MiB every other text may have) took 1.9 GB.
pub const MAX_REPORT_BYTES: u64 = 8 << 20;

/// `  file: read as Shift_JIS` for each file not read as UTF-8, each line starting with
/// `bullet`.
fn read_notes(read: &[(PathBuf, Encoding)], bullet: &str, lang: Lang) -> String {
    let mut out = String::new();
    for (file, encoding) in read {
        if let Some(note) = encoding.read_as() {
            let _ = writeln!(out, "{bullet}{}: {}", file.display(), note.get(lang));
        }
    }
    out
}

fn problems_text(path: &Path, problems: &[ParseProblem], lang: Lang) -> String {
    let mut out = format!(
        "{}: {}\n",
        path.display(),
        t("読み取れない行があります", "some lines could not be read").get(lang)
    );
    for p in problems {
        let _ = writeln!(out, "  {}", p.message(lang));
    }
    out
}

/// A polygon model from a data file.
///
/// # Errors
/// The file cannot be read, or its rows do not parse (each problem with its line).
pub fn read_data(path: &Path, lang: Lang) -> Result<PolygonData, String> {
    read_data_in(path, None, lang).map(|(polygon, _)| polygon)
}

/// [`read_data`] in `forced` (`--encoding`) or the encoding detected; with the encoding read.
///
/// # Errors
/// As [`read_data`], and text that is not in the encoding (each with its place).
pub fn read_data_in(
    path: &Path,
    forced: Option<Encoding>,
    lang: Lang,
) -> Result<(PolygonData, Encoding), String> {
    let (text, encoding) = read_text(path, forced, lang)?;
    Ok((polygon_from(path, &text, lang)?, encoding))
}

fn polygon_from(path: &Path, text: &str, lang: Lang) -> Result<PolygonData, String> {
    let name = path.file_stem().map_or_else(|| "data".to_owned(), |s| s.to_string_lossy().into());
    parse::polygon_from_text(text, Text::new(name.clone(), name))
        .map_err(|problems| problems_text(path, &problems, lang))
}

/// Derives the data from `source`: the data file, or the student's exercises.
///
/// # Errors
/// A bad student number or student file, or an unreadable data file.
pub fn gather(source: &Source, kit: &Kit, lang: Lang) -> Result<Gathered, String> {
    gather_drawing(source, kit, None, lang)
}

/// Where [`gather_drawing`] draws each assignment's result.
struct Drawing<'a> {
    /// The output folder.
    folder: &'a Path,
    /// What was written.
    written: &'a mut Written,
}

/// [`gather`], and with `drawing`, each assignment's result drawn ([`render_one`]) right after
/// it is derived, in the same part ([`in_part`]): a function that ran out of time while it was
/// derived is not waited for again while it is drawn.
///
/// # Errors
/// As [`gather`]; an image that cannot be drawn or written.
fn gather_drawing(
    source: &Source,
    kit: &Kit,
    mut drawing: Option<Drawing<'_>>,
    lang: Lang,
) -> Result<Gathered, String> {
    if let Some(path) = &source.data {
        let (polygon, encoding) = read_data_in(path, source.encoding, lang)?;
        // The data is not the assignment's, but the report is still the student's: their
        // number when it is recorded or given (it said "not set" beside a recorded one).
        let record = cg_assign::resolve_student(
            source.student.as_deref(),
            source.table,
            &(kit.student_file)(),
            lang,
        )
        .ok();
        let context = Context {
            student: record.as_ref().map(|r| r.student.to_string()),
            table: record.as_ref().map(|r| r.table.to_string()),
            ..Context::default()
        };
        return Ok(Gathered {
            derived: Derived { a1: Some(polygon), ..Derived::default() },
            context,
            assignment: None,
            read: vec![(path.clone(), encoding)],
        });
    }
    let record = cg_assign::resolve_student(
        source.student.as_deref(),
        source.table,
        &(kit.student_file)(),
        lang,
    )?;
    let a = Variants::for_student(&record.student, record.table);
    let assignments: BTreeMap<String, String> = Which::ALL
        .iter()
        .filter(|w| w.in_report())
        .map(|&w| (w.id().to_owned(), a.describe_one(w, lang)))
        .collect();
    let context = Context {
        student: Some(record.student.to_string()),
        table: Some(record.table.to_string()),
        assignments,
        variants: Some(a.clone()),
        ..Context::default()
    };
    let derived = Derived { student: Some(record.student.to_string()), ..Derived::default() };
    let mut g = Gathered { derived, context, assignment: Some(a.clone()), read: Vec::new() };
    for which in Which::ALL.iter().copied().filter(|w| w.in_report()) {
        in_part(|| {
            let (derived, missing) = (&mut g.derived, &mut g.context.missing);
            derive::derive_one(&a, which, &kit.impls, derived, missing);
            if which == Which::a4 && g.derived.a4.is_none() {
                sampler_alone(&kit.impls, &mut g.context);
            }
            match drawing.as_mut() {
                Some(d) => render_one(&mut g, &a, which, &kit.impls, d, lang),
                None => Ok(()),
            }
        })?;
    }
    Ok(g)
}

/// a4's sampler (a4.t3) when the rest of a4 did not derive (a4's part stops before it at a
/// failing a4.t1 or a4.t2): it needs neither, so its fragment shows it, or why not, on its own.
fn sampler_alone(impls: &Impls, context: &mut Context) {
    match guarded(impls.a4.sampler) {
        Ok(s) => context.sampler = Some(cg_assign::cg_a4::core_sampler(s)),
        // A file that does not compile is said once, for the whole of a4.
        Err(Outcome::DoesNotCompile { .. }) => {}
        Err(o) => context.missing.push(Missing::from_outcome("a4.t3", "sampler()", o)),
    }
}

/// `folder` and the folders above it, made where missing; an error names it and says why in
/// `lang`.
fn make_folder(folder: &Path, lang: Lang) -> Result<(), String> {
    std::fs::create_dir_all(folder).map_err(|e| io_error(folder, &e, lang))
}

/// A failed file operation on `path`, in `lang` ([`cg_core::lang::Text::io`]).
fn io_error(path: &Path, e: &std::io::Error, lang: Lang) -> String {
    cg_core::lang::Text::io_at(path, e).get(lang).to_owned()
}

fn write(
    folder: &Path,
    name: &str,
    bytes: &[u8],
    written: &mut Written,
    lang: Lang,
) -> Result<(), String> {
    let path = folder.join(name);
    if let Some(dir) = path.parent() {
        make_folder(dir, lang)?;
    }
    std::fs::write(&path, bytes).map_err(|e| io_error(&path, &e, lang))?;
    written.files.push(name.to_owned());
    Ok(())
}

/// Draws `which`'s result to `render-aN.png`; what cannot be drawn goes to `missing`.
///
/// # Errors
/// The image cannot be rendered or written.
fn render_one(
    g: &mut Gathered,
    a: &Variants,
    which: Which,
    impls: &Impls,
    to: &mut Drawing<'_>,
    lang: Lang,
) -> Result<(), String> {
    let id = which.id();
    let scene = match drawn(|| a.view(which, impls, which.report_time())) {
        Ok(Ok(scene)) => scene,
        Ok(Err(why)) => {
            g.context.missing.push(Missing { task: id.to_owned(), why });
            return Ok(());
        }
        // A function that ran out of time above (while the part was derived): said there, and
        // not waited for again.
        Err(Outcome::TimedOut { function: Some(function), earlier: true, .. }) => {
            g.context
                .missing
                .push(Missing { task: id.to_owned(), why: timed_out_above(&function) });
            return Ok(());
        }
        Err(outcome) => {
            let why = match outcome {
                Outcome::NotDone { message } => Text::new(
                    cg_harness::check::stub_message(&message, Lang::Ja),
                    cg_harness::check::stub_message(&message, Lang::En),
                ),
                other => other
                    .describe()
                    .unwrap_or_else(|| Text::new("結果が得られませんでした", "it gave no result")),
            };
            if !g.context.missing.iter().any(|m| m.task.starts_with(id)) {
                g.context.missing.push(Missing { task: id.to_owned(), why });
            }
            return Ok(());
        }
    };
    let image = cg_raster::render(&scene, &cg_raster::Options::default())
        .map_err(|e| e.message(lang))?
        .image;
    let name = files::render_png(id);
    let path = to.folder.join(&name);
    make_folder(to.folder, lang)?;
    cg_scene::save_png(&path, &image).map_err(|e| e.describe(lang))?;
    to.written.files.push(name);
    g.context.renders.push(id.to_owned());
    Ok(())
}

/// `f` (an assignment's view) with the student's functions guarded ([`guarded`]); in a worker,
/// its calls are judged as a check's are (`cg_harness::check::run`): a call of a function that
/// already ran out of time in this part fails at once, [`Outcome::TimedOut`] with `earlier`,
/// instead of waiting the whole time limit once more. A stub's marker changes nothing, as with
/// [`guarded`]: what the stub returned is drawn.
fn drawn<T>(f: impl FnOnce() -> T) -> Result<T, Outcome> {
    if !cg_worker::proxy::active() {
        return guarded(f);
    }
    let mut value = None;
    let result = cg_harness::check::run("report.render", Text::default(), || {
        value = Some(f());
        Ok(())
    });
    value.ok_or(result.outcome)
}

/// Why a result is not drawn: the worker's `function` (`a3.idle`; a batch names the student's
/// functions it runs) ran out of time above, while its part was derived.
fn timed_out_above(function: &str) -> Text {
    let (file, names) = cg_harness::check::student_function(function);
    Text::new(
        format!("図を描いていません: {file} の {} が上で制限時間内に終わりませんでした", names.ja),
        format!("not drawn: {} ({file}) ran out of time above", names.en),
    )
}

/// A texture (rows from the bottom up) as an image (rows from the top down).
fn texture_image(t: &cg_core::texture::Texture) -> Option<cg_core::image::Image> {
    let width = usize::try_from(t.width).ok()?.max(1);
    let rows: Vec<[u8; 4]> = t.texels.chunks(width).rev().flatten().copied().collect();
    cg_core::image::Image::from_rgba8(t.width, t.height, &rows)
}

/// Every placeholder's value in each format, computed once: written as fragments, then
/// filled into the templates.
type Values = Vec<(Format, BTreeMap<String, String>)>;

/// Writes the figures and the fragments of `g` into `folder`; returns the placeholders' values.
fn write_derived(
    g: &Gathered,
    folder: &Path,
    lang: Lang,
    written: &mut Written,
) -> Result<Values, String> {
    if let Some(p) = &g.derived.a1 {
        for view in VIEWS {
            let svg = figures::svg(&figures::layout(p, view), lang);
            write(folder, files::view_svg(view), svg.as_bytes(), written, lang)?;
        }
    }
    if let Some(tex) = &g.derived.a4 {
        let png = folder.join(files::TEXTURE_PNG);
        make_folder(folder, lang)?;
        let image = texture_image(&tex.image).ok_or_else(|| {
            t("用意された画像を書き出せません", "the prepared image cannot be written")
                .get(lang)
                .to_owned()
        })?;
        cg_scene::save_png(&png, &image).map_err(|e| e.describe(lang))?;
        written.files.push(files::TEXTURE_PNG.to_owned());
        let svg = figures::texture_svg(tex, files::TEXTURE_PNG, lang);
        write(folder, files::TEXTURE_SVG, svg.as_bytes(), written, lang)?;
    }
    let mut all = Values::new();
    for format in [Format::Markdown, Format::Latex] {
        let ext = match format {
            Format::Markdown => "md",
            Format::Latex => "tex",
        };
        let values = fill::values(&g.derived, &g.context, lang, format);
        for (key, value) in &values {
            // A file of its own ends its last line (a table's does; "not derived yet" did not).
            let line_end = if value.ends_with('\n') { "" } else { "\n" };
            let text = format!("{value}{line_end}");
            write(folder, &format!("fragments/{key}.{ext}"), text.as_bytes(), written, lang)?;
        }
        all.push((format, values));
    }
    Ok(all)
}

/// `derive`: gathers and writes everything into the output folder.
///
/// # Errors
/// What could not be read or written.
pub fn derive_to(args: &DeriveArgs, kit: &Kit, lang: Lang) -> Result<Written, String> {
    let (_, written) = derive_gathered(args, kit, lang)?;
    Ok(written)
}

fn derive_gathered(args: &DeriveArgs, kit: &Kit, lang: Lang) -> Result<(Values, Written), String> {
    let mut written = Written { folder: args.output.clone(), ..Written::default() };
    let drawing =
        (!args.no_render).then(|| Drawing { folder: &args.output, written: &mut written });
    let mut g = gather_drawing(&args.source, kit, drawing, lang)?;
    // Drawing was turned off: the images' places say so, not "not derived yet".
    g.context.no_render = args.no_render;
    let values = write_derived(&g, &args.output, lang, &mut written)?;
    written.missing = g.context.missing;
    written.read = g.read;
    Ok((values, written))
}

/// `fill`: derives, then writes the filled template (`report.md`, `report.tex`), keeping
/// existing ones unless `--force`.
///
/// # Errors
/// What could not be read or written; a template placeholder the kit does not know.
pub fn fill_to(args: &FillArgs, kit: &Kit, lang: Lang) -> Result<Written, String> {
    let (values, mut written) = derive_gathered(&args.derive, kit, lang)?;
    for (format, values) in &values {
        let name = format.file_name();
        if args.derive.output.join(name).exists() && !args.force {
            written.kept.push(name.to_owned());
            continue;
        }
        let text =
            template::fill(template::template(lang, *format), values).map_err(|e| e.to_string())?;
        write(&args.derive.output, name, text.as_bytes(), &mut written, lang)?;
    }
    Ok(written)
}

/// `check`: parses the report and verifies it against the data.
///
/// # Errors
/// What could not be read; a bad student number or student file.
pub fn check(args: &CheckArgs, kit: &Kit, lang: Lang) -> Result<CheckOutcome, String> {
    let forced = args.source.encoding;
    if let (Some(data), None) = (&args.source.data, &args.report) {
        let (text, encoding) = read_text(data, forced, lang)?;
        let polygon = polygon_from(data, &text, lang)?;
        let (parsed, problems) = parse::parse_report(&text);
        let verification = verify::verify_data(&polygon, &parsed);
        return Ok(CheckOutcome {
            report: data.clone(),
            problems,
            verification,
            missing: Vec::new(),
            read: vec![(data.clone(), encoding)],
            items: parsed.items(),
        });
    }
    let report = args.report.clone().unwrap_or_else(|| PathBuf::from("report").join("report.md"));
    let (text, encoding) = read_text(&report, forced, lang)?;
    let mut read = vec![(report.clone(), encoding)];
    let (parsed, problems) = parse::parse_report(&text);
    if let Some(data) = &args.source.data {
        let (polygon, encoding) = read_data_in(data, forced, lang)?;
        read.push((data.clone(), encoding));
        let verification = verify::verify_data(&polygon, &parsed);
        let items = parsed.items();
        return Ok(CheckOutcome {
            report,
            problems,
            verification,
            missing: Vec::new(),
            read,
            items,
        });
    }
    let g = gather(&args.source, kit, lang)?;
    let verification = verify::verify_with(&parsed, &g.derived, g.assignment.as_ref());
    let items = parsed.items();
    Ok(CheckOutcome { report, problems, verification, missing: g.context.missing, read, items })
}
