//! # cg-grade — grading a class with the kit's own checks, safely
//!
//! [`grade`] takes a folder of submissions (each a folder or a `.zip` holding an `exercises/`
//! tree) or Moodle's "Download all submissions" as it comes ([`moodle`]), builds each into a
//! copy of the kit's handout ([`handout`]) — one copy per parallel slot, each with its own cargo
//! target folder reused from submission to submission — and runs
//! the kit's checks on it in the sandbox ([`cg_sandbox`]), one run per assignment so a loop in
//! one assignment costs only that assignment. Only `exercises/src/{a1,a2,a3,a4,s}.rs` and
//! `exercises/student.toml` are taken from a submission; the check code is always the kit's.
//!
//! A module that does not compile is replaced by its pristine stub and the build retried, so the
//! other assignments are still graded; the replaced module's checks get 0 with the compiler
//! errors. Results are written atomically per student in the shape of Gradescope's
//! `results.json` ([`result`]), with a class table (`class.csv`) and the class's most common
//! mistakes (`summary.md`). A submission whose result already exists with the same hash (its
//! files, the config and the kit) is skipped, so an interrupted run picks up where it stopped.
//!
//! [`gradescope`] grades one submission the same way ([`grade_with`] with one entry) for
//! Gradescope and batch systems that run a job per submission, with Gradescope's `results.json`
//! and the autograder zip; [`progress`] tells a front end how a long run goes.

use std::collections::{BTreeMap, VecDeque};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use cg_core::lang::{Lang, t};
use cg_sandbox::{Isolation, Job, Launch, Limits, SandboxError};

pub mod build;
pub mod config;
mod entries;
pub mod gradescope;
pub mod handout;
pub mod inside;
pub mod moodle;
pub mod progress;
pub mod report;
pub mod result;
pub mod roster;
mod slot;
pub use cg_assign::screen;
pub mod submission;
mod unread;
pub mod zipfile;

pub use config::Config;
pub use entries::file_name;
use entries::{Pending, collect, collect_from};
use slot::{Slot, grade_one, prepare_copy, prepare_first};

pub use cg_core::lang::Text;

/// The function that makes the sandbox's command line for the worker of a submission's
/// functions: [`cg_sandbox::launch`], or a stand-in in tests.
pub type Launcher = fn(&Job, &Limits, Isolation) -> Result<Launch, SandboxError>;

/// What to grade and how.
#[derive(Clone, Debug)]
pub struct Options {
    /// The kit's root (with `solutions/`): the handouts are written from it.
    pub kit: PathBuf,
    /// The folder whose every entry is a submission.
    pub submissions: PathBuf,
    /// Where the results go (and the work copies, under `.work/`).
    pub out: PathBuf,
    /// Points per check.
    pub config: Config,
    /// The config's text, part of every submission's hash.
    pub config_text: String,
    /// Parallel slots (each a kit copy with its own build folder).
    pub jobs: usize,
    /// The limits of one run of the checks (one assignment).
    pub limits: Limits,
    /// The limit of one `cargo build`.
    pub build_limit: Duration,
    /// The isolation the runs use.
    pub isolation: Isolation,
    /// The language of the results' text.
    pub lang: Lang,
    /// The class roster (`--roster`): who each entry is. Without one, the number in each
    /// submission's `student.toml`.
    pub roster: Option<roster::Roster>,
    /// A folder of reports handed in on their own (`--reports`), each file named with its
    /// student number ([`inside::folder`]): checked instead of the report inside that student's
    /// submission.
    pub reports: Option<PathBuf>,
}

/// How grading one submission went, for the progress lines.
#[derive(Clone, Debug, PartialEq)]
pub struct Graded {
    /// The submission's entry name in the submissions folder.
    pub entry: String,
    /// The result file's name, without `.json` (the student number, when known).
    pub name: String,
    /// Its score.
    pub score: f64,
    /// Its maximum score, when known.
    pub max_score: Option<f64>,
    /// Whether an existing result was kept (same hash).
    pub skipped: bool,
    /// What the instructor should look at ([`result::flag`]): a `student.toml` that claims
    /// another number than the roster's, an entry not on the roster, a number claimed twice.
    pub flag: Option<Text>,
    /// Why it was not graded ([`result::problem`]): refused, or grading could not finish.
    pub problem: Option<Text>,
    /// Its report in short ([`progress::Brief::of`]); `None` when it was not graded.
    pub report: Option<progress::Brief>,
}

/// Why grading could not start (a single submission's problems go into its result instead).
#[derive(Debug, thiserror::Error)]
pub enum GradeError {
    /// A folder or file could not be read or written, or the kit itself cannot be graded with
    /// (its stubs, its handout's build): in both languages (`Display` is the English).
    #[error("{0}")]
    Io(Text),
}

impl GradeError {
    /// The message in `lang`.
    #[must_use]
    pub fn message(&self, lang: Lang) -> &str {
        match self {
            GradeError::Io(text) => text.get(lang),
        }
    }

    /// A failed file operation on `path`, with the system's reason ([`Text::io_at`]).
    #[must_use]
    pub fn at(path: &Path, e: &std::io::Error) -> GradeError {
        GradeError::Io(Text::io_at(path, e))
    }
}

/// A 64-bit FNV-1a hash, as 16 hex digits: the resume key (not a security measure: a
/// submission can only collide with its own earlier result).
#[derive(Clone, Copy, Debug)]
pub struct Hasher(u64);

impl Default for Hasher {
    fn default() -> Hasher {
        Hasher(0xcbf2_9ce4_8422_2325)
    }
}

impl Hasher {
    /// Adds bytes, prefixed by their length (so `ab`+`c` differs from `a`+`bc`).
    pub fn add(&mut self, bytes: &[u8]) {
        for &b in (bytes.len() as u64).to_le_bytes().iter().chain(bytes) {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(0x0100_0000_01b3);
        }
    }

    /// The hash so far, as hex.
    #[must_use]
    pub fn hex(&self) -> String {
        format!("{:016x}", self.0)
    }
}

/// The kit's version for the resume key: the crate version and a hash of every kit file a
/// handout is made from (so a changed check re-grades everyone).
///
/// # Errors
/// The kit's files could not be listed or read.
pub fn kit_version(kit: &Path, skip: &dyn Fn(&Path) -> bool) -> Result<String, GradeError> {
    let mut files = handout::kit_files(kit).map_err(GradeError::Io)?;
    files.retain(|f| !handout::excluded(f) || f.starts_with("solutions"));
    files.retain(|f| !skip(&kit.join(f)));
    files.sort();
    let mut h = Hasher::default();
    h.add(env!("CARGO_PKG_VERSION").as_bytes());
    for f in files {
        h.add(f.to_string_lossy().as_bytes());
        h.add(&std::fs::read(kit.join(&f)).map_err(|e| GradeError::at(&f, &e))?);
    }
    Ok(h.hex())
}

/// The content of a slot's copy of the kit, hashed: every file and link under `kit` (names and
/// bytes, a link's target), except what each submission writes (`exercises/src/<id>.rs` of
/// each assignment, `exercises/student.toml`). Checked before every build, so a run that changed the copy (only
/// possible without bubblewrap) cannot change the next submission's grade.
///
/// # Errors
/// A folder or file of the copy could not be read.
pub fn slot_content(kit: &Path) -> std::io::Result<String> {
    let mut entries = Vec::new();
    let mut stack = vec![PathBuf::new()];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(kit.join(&dir))? {
            let entry = entry?;
            let relative = dir.join(entry.file_name());
            let kind = entry.file_type()?;
            if kind.is_dir() {
                stack.push(relative);
            } else {
                entries.push((relative, kind.is_symlink()));
            }
        }
    }
    entries.sort();
    let written = |r: &Path| {
        r == Path::new("exercises/student.toml")
            || submission::MODULES.iter().any(|m| r == Path::new(&format!("exercises/src/{m}.rs")))
    };
    let mut h = Hasher::default();
    for (relative, link) in entries.iter().filter(|(r, _)| !written(r)) {
        h.add(relative.to_string_lossy().as_bytes());
        if *link {
            h.add(b"link");
            h.add(std::fs::read_link(kit.join(relative))?.to_string_lossy().as_bytes());
        } else {
            h.add(&std::fs::read(kit.join(relative))?);
        }
    }
    Ok(h.hex())
}

pub use cg_core::fs::write_atomic;

/// Whether grading may run with `isolation`: under bubblewrap, or with limits only when the
/// instructor says so (`--unsafe-no-sandbox`; every result and the summary then say it).
///
/// # Errors
/// Limits only without `unsafe_no_sandbox`: what is missing and how to install it.
pub fn require_isolation(isolation: Isolation, unsafe_no_sandbox: bool) -> Result<(), Text> {
    if isolation == Isolation::Bubblewrap || unsafe_no_sandbox {
        return Ok(());
    }
    Err(Text::new(
        "採点は学生のコードを bubblewrap のサンドボックスで動かしますが、ここでは使えません（未インストールか、ユーザー名前空間が許可されていません）。インストール: sudo apt-get install bubblewrap（Debian・Ubuntu）/ sudo dnf install bubblewrap（Fedora）。コンテナでは user namespace を許可してください。隔離なしで採点するなら --unsafe-no-sandbox（学生のコードが採点者の権限でファイルとネットワークに触れます）",
        "grading runs the students' code in bubblewrap's sandbox, which is not available here (not installed, or user namespaces are not allowed). Install it: sudo apt-get install bubblewrap (Debian, Ubuntu) or sudo dnf install bubblewrap (Fedora); in a container, allow user namespaces. To grade without isolation anyway: --unsafe-no-sandbox (the students' code then runs as you, with your files and the network)",
    ))
}

/// Whether `out/<name>.json` exists with this hash.
fn already_graded(out: &Path, name: &str, hash: &str) -> Option<serde_json::Value> {
    let text = std::fs::read_to_string(out.join(format!("{name}.json"))).ok()?;
    let v: serde_json::Value = serde_json::from_str(&text).ok()?;
    (v["cg"]["hash"] == hash).then_some(v)
}

/// The checks of each assignment, with their titles, as one run reported them.
pub type Baseline = BTreeMap<String, Vec<(String, Text)>>;

/// One assignment's run, as the result needs it.
#[derive(Clone, Debug)]
pub enum AssignmentRun {
    /// The report of its checks (`Report::to_json`), decided in the grader's process.
    Report(serde_json::Value),
    /// The checks could not run: why, and the end of what the worker wrote on stderr.
    Died {
        /// Why, in both languages.
        how: Text,
        /// The end of what it printed on stderr.
        stderr: String,
    },
}

/// The next submission in the queue (the lock is held only while taking it).
fn next(queue: &Mutex<VecDeque<Pending>>) -> Option<Pending> {
    queue.lock().ok().and_then(|mut q| q.pop_front())
}

/// Grades every submission in `options.submissions` (a folder of submissions, or Moodle's
/// "Download all submissions", zipped or not: [`moodle::input`]), each one's functions in a
/// worker started by `launcher` (the sandbox); writes `out/<student>.json`, the student's
/// feedback in both languages (`out/feedback/<student>/feedback-{ja,en}.md`), `out/class.csv`
/// and `out/summary.md`; calls `progress` after each. The files for Moodle are
/// [`moodle::output::write`]'s.
///
/// # Errors
/// The submissions folder or the kit could not be read, or the results not written.
pub fn grade(
    options: &Options,
    launcher: Launcher,
    progress: &(dyn Fn(&Graded) + Sync),
) -> Result<Vec<Graded>, GradeError> {
    let on = |e: progress::Event<'_>| {
        if let progress::Event::Graded(g) = e {
            progress(g);
        }
    };
    grade_with(options, launcher, &on, None)
}

/// [`grade`], telling `on` how it goes ([`progress::Event`]); with `single`, the one entry to
/// grade instead of the entries of `options.submissions` ([`gradescope::grade_one`]).
///
/// # Errors
/// A file of the kit's own (a result it wrote) that is not JSON.
pub(crate) fn not_json(path: &Path, e: &serde_json::Error) -> GradeError {
    let shown = path.display();
    GradeError::Io(Text::new(
        format!("{shown}: JSON として読めません: {e}"),
        format!("{shown}: not JSON: {e}"),
    ))
}

/// Every check ID of the kit, as the checks name them for a few students in every table version
/// (their lists are the same for every student; a few, so that one that depended on a variant
/// would still be named).
#[must_use]
pub fn check_ids() -> std::collections::BTreeSet<String> {
    let nothing = cg_assign::Impls::worker();
    let mut ids = std::collections::BTreeSet::new();
    for number in ["12345678", "20260001", "99999999"] {
        let Ok(student) = number.parse() else { continue };
        for table in cg_harness::TableVersion::ALL {
            let a = cg_assign::Variants::for_student(&student, table);
            for &w in cg_assign::Which::ALL {
                ids.extend(a.report(w, &nothing).checks.into_iter().map(|c| c.id));
            }
        }
    }
    ids
}

/// As [`grade`].
pub fn grade_with(
    options: &Options,
    launcher: Launcher,
    on: &(dyn Fn(progress::Event<'_>) + Sync),
    single: Option<moodle::input::Entry>,
) -> Result<Vec<Graded>, GradeError> {
    let progress = |g: &Graded| on(progress::Event::Graded(g));
    let io = |p: &Path, e: std::io::Error| GradeError::at(p, &e);
    // A rule of the config that names no check gives its points to nothing: said before a
    // single submission is built.
    let ids = check_ids();
    options.config.check_names(ids.iter().map(String::as_str)).map_err(|e| GradeError::Io(e.0))?;
    if std::fs::metadata(&options.out).is_ok_and(|m| !m.is_dir()) {
        let shown = options.out.display();
        return Err(GradeError::Io(Text::new(
            format!("{shown} はフォルダではありません。結果を書くフォルダを指定してください"),
            format!("{shown} is not a folder: give a folder for the results"),
        )));
    }
    std::fs::create_dir_all(&options.out).map_err(|e| io(&options.out, e))?;
    let out = options.out.canonicalize().map_err(|e| io(&options.out, e))?;
    // The results (and the work copies under them) in the kit's own folder, or above it: the
    // copies of the kit would leave out the whole kit as output, and grading's files would lie
    // among the kit's.
    if options.kit.canonicalize().is_ok_and(|kit| kit.starts_with(&out)) {
        let shown = options.out.display();
        return Err(GradeError::Io(Text::new(
            format!(
                "{shown} はキットのフォルダ（またはその上）です。結果には別のフォルダ（grades/ など）を指定してください"
            ),
            format!(
                "{shown} is the kit's folder (or above it): give the results a folder of their own (grades/, say)"
            ),
        )));
    }
    let subs = options.submissions.canonicalize().map_err(|e| io(&options.submissions, e))?;
    on(progress::Event::Reading);
    // Neither the results nor the submissions go into a handout or the kit's hash.
    let skip = |p: &Path| {
        let p = p.canonicalize().unwrap_or_else(|_| p.to_path_buf());
        p.starts_with(&out) || p.starts_with(&subs)
    };
    let kit_hash = kit_version(&options.kit, &skip)?;
    let stubs: BTreeMap<String, String> =
        cg_harness::stubs::generate(&options.kit.join("solutions"))
            .map_err(|e| GradeError::Io(handout::markers(&e)))?
            .into_iter()
            .filter_map(|(rel, text)| {
                let name = rel.file_stem()?.to_string_lossy().into_owned();
                submission::MODULES.contains(&name.as_str()).then_some((name, text))
            })
            .collect();
    if stubs.len() != submission::MODULES.len() {
        return Err(GradeError::Io(t(
            "解答から作った学生用の関数が課題の一部しかありません",
            "the stubs made from the solutions lack some of the assignments",
        )));
    }
    let folder = match &options.reports {
        Some(dir) => Some(inside::folder(dir, report::MAX_BYTES).map_err(GradeError::Io)?),
        None => None,
    };
    let pending = match single {
        Some(entry) => collect_from(options, &kit_hash, vec![entry], folder.as_ref())?,
        None => collect(options, &kit_hash, folder.as_ref())?,
    };
    // The reports of the folder that no entry took: said in the summary.
    let unused: Vec<String> = folder.as_ref().map_or_else(Vec::new, |f| {
        let taken = |number: &str| {
            pending
                .iter()
                .any(|p| p.files.as_ref().is_ok_and(|(_, s)| s.student.as_str() == number))
        };
        let mut names: Vec<String> = f.unnamed.clone();
        names.extend(f.by_student.iter().filter(|(n, _)| !taken(n)).map(|(_, (path, _))| {
            path.file_name().map_or_else(String::new, |n| n.to_string_lossy().into_owned())
        }));
        names.sort();
        names
    });
    // The roster's students no entry is bound to: listed in the summary.
    let absent: Vec<(String, String)> = options.roster.as_ref().map_or_else(Vec::new, |r| {
        r.rows
            .iter()
            .filter(|row| !pending.iter().any(|p| r.find(&p.entry) == Some(*row)))
            .map(|row| (row.student.to_string(), row.name.clone()))
            .collect()
    });
    let mut done = Vec::new();
    let mut queue = VecDeque::new();
    for p in pending {
        if let Some(v) = already_graded(&out, &p.name, &p.hash) {
            let g = Graded {
                entry: p.entry,
                name: p.name,
                score: v["score"].as_f64().unwrap_or(0.0),
                max_score: v["max_score"].as_f64(),
                skipped: true,
                flag: result::flag(&v),
                problem: result::problem(&v),
                report: progress::Brief::of(&v),
            };
            progress(&g);
            done.push(g);
        } else {
            queue.push_back(p);
        }
    }
    let queue = Mutex::new(queue);
    let results = Mutex::new(Vec::new());
    let failure: Mutex<Option<GradeError>> = Mutex::new(None);
    let waiting = queue.lock().map(|q| q.iter().filter(|p| p.files.is_ok()).count()).unwrap_or(0);
    let slots = options.jobs.max(1).min(waiting.max(1));
    on(progress::Event::Start {
        entries: done.len() + queue.lock().map(|q| q.len()).unwrap_or(0),
        kept: done.len(),
    });
    let first = Slot::at(&out, 0);
    let mut pristine = String::new();
    if waiting > 0 {
        on(progress::Event::Building);
        prepare_first(&first, options, &kit_hash, &stubs, &skip)?;
        pristine = slot_content(&first.kit).map_err(|e| io(&first.kit, e))?;
        // The copies are made before any slot starts building.
        for k in 1..slots {
            prepare_copy(&Slot::at(&out, k), &first, &kit_hash).map_err(GradeError::Io)?;
        }
        on(progress::Event::Built);
    }
    std::thread::scope(|scope| {
        for k in 0..slots {
            let (queue, results, failure, stubs, out, pristine, skip) =
                (&queue, &results, &failure, &stubs, &out, pristine.as_str(), &skip);
            scope.spawn(move || {
                let mut slot = Slot::at(out, k);
                while let Some(p) = next(queue) {
                    let started = Instant::now();
                    let mut facts = match &p.files {
                        Err(why) => {
                            result::Facts { refused: Some(why.clone()), ..result::Facts::default() }
                        }
                        Ok((files, student)) => grade_one(
                            &mut slot,
                            (files, student, &p.report),
                            stubs,
                            (pristine, skip),
                            options,
                            launcher,
                        ),
                    };
                    // Not graded: a report found is said not checked.
                    report::not_graded(&mut facts, &p.report);
                    // A refused entry on the roster is still its student's.
                    let student = p.files.as_ref().ok().map_or_else(
                        || p.roster.as_ref().and_then(|m| m.student.clone()),
                        |(_, s)| Some(s.student.to_string()),
                    );
                    let meta = result::Meta {
                        entry: &p.entry,
                        student: student.as_deref(),
                        table: p.files.as_ref().ok().map(|(_, s)| s.table),
                        // A machine's problem is not the submission's: not kept.
                        hash: if facts.retry { "" } else { &p.hash },
                        isolation: options.isolation,
                        same_number: &p.same_number,
                        roster: p.roster.as_ref(),
                        total: started.elapsed(),
                    };
                    let build = |lang| result::build(&meta, &facts, &options.config, lang);
                    let value = build(options.lang);
                    // The student's feedback in both languages, before the result that a
                    // resumed run keeps.
                    let feedback = out.join("feedback").join(&p.name);
                    let (ja, en) = match options.lang {
                        Lang::Ja => (value.clone(), build(Lang::En)),
                        Lang::En => (build(Lang::Ja), value.clone()),
                    };
                    if let Err(e) = moodle::output::write_feedback(&feedback, &ja, &en) {
                        if let Ok(mut f) = failure.lock() {
                            *f = Some(io(&feedback, e));
                        }
                        break;
                    }
                    let path = out.join(format!("{}.json", p.name));
                    let text = serde_json::to_string_pretty(&value).unwrap_or_default();
                    if let Err(e) = write_atomic(&path, text.as_bytes()) {
                        if let Ok(mut f) = failure.lock() {
                            *f = Some(io(&path, e));
                        }
                        break;
                    }
                    let g = Graded {
                        entry: p.entry.clone(),
                        name: p.name.clone(),
                        score: value["score"].as_f64().unwrap_or(0.0),
                        max_score: value["max_score"].as_f64(),
                        skipped: false,
                        flag: result::flag(&value),
                        problem: result::problem(&value),
                        report: progress::Brief::of(&value),
                    };
                    progress(&g);
                    if let Ok(mut r) = results.lock() {
                        r.push(g);
                    }
                }
            });
        }
    });
    if let Some(e) = failure.into_inner().ok().flatten() {
        return Err(e);
    }
    done.extend(results.into_inner().unwrap_or_default());
    done.sort_by(|a, b| a.name.cmp(&b.name));
    let all: Vec<serde_json::Value> = done
        .iter()
        .filter_map(|g| std::fs::read_to_string(out.join(format!("{}.json", g.name))).ok())
        .filter_map(|t| serde_json::from_str(&t).ok())
        .collect();
    let csv = result::class_csv(&all, options.lang);
    // Opened in Excel on Japanese Windows, where a file without the byte-order mark garbles the
    // flags' Japanese.
    write_atomic(&out.join("class.csv"), &cg_core::quote::spreadsheet_file(&csv))
        .map_err(|e| io(&out, e))?;
    let mut md = result::summary_md(&all, &absent, options.lang);
    md.push_str(&report::unused_section(&unused, options.lang));
    write_atomic(&out.join("summary.md"), md.as_bytes()).map_err(|e| io(&out, e))?;
    Ok(done)
}

/// Options for the unit tests: the kit and the output under `root`, one job, bubblewrap.
#[cfg(test)]
pub(crate) fn test_options(
    root: &Path,
    submissions: &Path,
    roster: Option<roster::Roster>,
) -> Options {
    Options {
        kit: root.to_path_buf(),
        submissions: submissions.to_path_buf(),
        out: root.join("out"),
        config: Config::default(),
        config_text: String::new(),
        jobs: 1,
        limits: Limits::default(),
        build_limit: std::time::Duration::from_secs(1),
        isolation: Isolation::Bubblewrap,
        lang: Lang::En,
        roster,
        reports: None,
    }
}

#[cfg(test)]
mod tests;
