//! A parallel slot of [`crate::grade_with`]: a copy of the kit's handout with its own cargo
//! target folder, made once (slot 0 built, the others copied from it), into which each
//! submission's files are written, built (a module that does not compile back to its stub) and
//! checked in the sandbox.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use cg_core::lang::t;
use cg_sandbox::Job;

use crate::inside::Found;
use crate::{
    AssignmentRun, Baseline, GradeError, Launcher, Options, Text, build, handout, result,
    slot_content, submission,
};

/// A parallel slot: a kit copy, its build folder, and the folder a run may write.
pub(crate) struct Slot {
    pub(crate) kit: PathBuf,
    pub(crate) target: PathBuf,
    pub(crate) run: PathBuf,
}

/// The package the grader builds in a kit copy from a submission's `exercises/`: the worker of
/// the student's functions (`cg-check-runner`), which links the submission and nothing of the
/// checks.
const WORKER_PACKAGE: &str = "cg-check-runner";

impl Slot {
    pub(crate) fn at(out: &Path, k: usize) -> Slot {
        let root = out.join(".work").join(format!("slot-{k}"));
        Slot { kit: root.join("kit"), target: root.join("target"), run: root.join("run") }
    }

    fn marker(&self) -> PathBuf {
        self.kit.with_file_name("kit-version")
    }

    fn is_current(&self, kit_hash: &str) -> bool {
        std::fs::read_to_string(self.marker()).ok().as_deref() == Some(kit_hash)
    }
}

/// Slot 0: the handout written afresh when the kit changed, and the worker built from the
/// pristine stubs (the whole kit's first build, paid once).
pub(crate) fn prepare_first(
    slot: &Slot,
    options: &Options,
    kit_hash: &str,
    stubs: &BTreeMap<String, String>,
    skip: &dyn Fn(&Path) -> bool,
) -> Result<(), GradeError> {
    if !slot.is_current(kit_hash) {
        let _ = std::fs::remove_dir_all(&slot.kit);
        let _ = std::fs::remove_file(slot.marker());
        std::fs::create_dir_all(&slot.kit).map_err(|e| GradeError::at(&slot.kit, &e))?;
        handout::write_handout_filtered(&options.kit, &slot.kit, skip).map_err(GradeError::Io)?;
    }
    for &m in submission::MODULES {
        let path = slot.kit.join(format!("exercises/src/{m}.rs"));
        write_if_changed(&path, stubs[m].as_bytes()).map_err(|e| GradeError::at(&path, &e))?;
    }
    let package = WORKER_PACKAGE;
    let b = build::cargo_build(&slot.kit, &slot.target, package, options.build_limit)
        .map_err(GradeError::Io)?;
    if !b.success {
        let shown = slot.kit.display();
        let log = format!("{}\n{}", b.other_errors.join("\n"), b.stderr_tail);
        return Err(GradeError::Io(Text::new(
            format!("キットの配布用のコピーがビルドできません（{shown}）:\n{log}"),
            format!("the kit's handout does not build ({shown}):\n{log}"),
        )));
    }
    let marker = slot.marker();
    std::fs::write(&marker, kit_hash).map_err(|e| GradeError::at(&marker, &e))
}

/// Slot K > 0: a copy of slot 0's kit and build folder (`cp -a` keeps the times cargo compares,
/// so only the student's crate rebuilds), unless it is already current.
pub(crate) fn prepare_copy(slot: &Slot, first: &Slot, kit_hash: &str) -> Result<(), Text> {
    if slot.is_current(kit_hash) {
        return Ok(());
    }
    let fail = |e: String| Text::new(format!("作業用コピー: {e}"), format!("work copy: {e}"));
    let _ = std::fs::remove_dir_all(&slot.kit);
    let _ = std::fs::remove_dir_all(&slot.target);
    if let Some(parent) = slot.kit.parent() {
        std::fs::create_dir_all(parent).map_err(|e| fail(e.to_string()))?;
    }
    for (from, to) in [(&first.kit, &slot.kit), (&first.target, &slot.target)] {
        let status = std::process::Command::new("cp")
            .arg("-a")
            .arg(from)
            .arg(to)
            .status()
            .map_err(|e| fail(format!("cp: {e}")))?;
        if !status.success() {
            return Err(fail(format!("cp -a {} {}: {status}", from.display(), to.display())));
        }
    }
    std::fs::write(slot.marker(), kit_hash).map_err(|e| fail(e.to_string()))
}

/// What [`run_checks`] gives: each assignment's run, the checks of those that died, the checks'
/// time, and the report's check.
type Runs = (BTreeMap<String, AssignmentRun>, Baseline, Duration, crate::report::Facts);

/// Runs every assignment's checks for `student` in this process, the submission's functions in
/// a worker (`cg-check-runner`, built in the slot) in the sandbox: each check's calls within
/// [`cg_sandbox::Limits::wall`], the worker within the rest of `options.limits`. Nothing the worker prints
/// is read as a result: the checks, their list and their outcomes are the kit's, here. Then the
/// `report`'s numbers, against the data the same worker's functions give ([`crate::report`]).
fn run_checks(
    slot: &Slot,
    (student, report): (&cg_assign::StudentFile, &(Option<Found>, Vec<Text>)),
    options: &Options,
    launcher: Launcher,
) -> Runs {
    let started = Instant::now();
    let a = cg_assign::Variants::for_student(&student.student, student.table);
    // The checks could not run: each assignment's list of checks still comes from the kit (its
    // checks against functions that give nothing), so the maximum score is the same.
    let (found, notes) = report;
    let died = |how: Text| {
        // A report found is said not checked, with why, before the notes on it (class.csv's
        // `report` cell shows the first).
        let mut facts = crate::report::Facts::default();
        if let Some(found) = found {
            facts.notes.push(Text::new(
                format!("{} は確かめられませんでした: {}", found.path, how.ja),
                format!("{} was not checked: {}", found.path, how.en),
            ));
        }
        facts.notes.extend(notes.iter().cloned());
        let run = AssignmentRun::Died { how, stderr: String::new() };
        let nothing = cg_assign::Impls::worker();
        let mut runs = BTreeMap::new();
        let mut baseline = Baseline::new();
        for &w in cg_assign::Which::ALL {
            let list = result::check_list(&a.report(w, &nothing).to_json());
            baseline.insert(w.id().to_owned(), list);
            runs.insert(w.id().to_owned(), run.clone());
        }
        (runs, baseline, started.elapsed(), facts)
    };
    let _ = std::fs::remove_dir_all(&slot.run);
    if let Err(e) = std::fs::create_dir_all(&slot.run) {
        let why = Text::io(&e);
        return died(Text::new(
            format!("作業フォルダ: {}", why.ja),
            format!("work folder: {}", why.en),
        ));
    }
    let job = Job {
        program: slot.target.join("release").join(WORKER_PACKAGE),
        args: Vec::new(),
        workdir: slot.run.clone(),
        // The worker reads nothing of the kit: its calls bring every input.
        read_only: Vec::new(),
        env: vec![("CG_LANG".into(), "en".into())],
        ..Job::default()
    };
    let launch = match launcher(&job, &options.limits, options.isolation) {
        Ok(l) => l,
        Err(e) => return died(e.text()),
    };
    let mut worker =
        cg_worker::Worker::new(launch.program, launch.args).clear_env().current_dir(launch.workdir);
    for (k, v) in launch.env {
        worker = worker.env(k, v);
    }
    // Each check calls the student's functions, even one that ran out of time before: it may
    // answer the check's own inputs.
    cg_worker::proxy::rerun_timed_out(true);
    let (reports, worker) = a.reports_in_worker(cg_assign::Which::ALL, worker, options.limits.wall);
    let runs = reports
        .into_iter()
        .map(|r| (r.assignment.clone(), AssignmentRun::Report(r.to_json())))
        .collect();
    let checks_time = started.elapsed();
    let checked = match found {
        Some(found) => crate::report::check(&a, (found, notes), worker, options.limits.wall),
        None => crate::report::Facts { notes: notes.clone(), ..Default::default() },
    };
    (runs, Baseline::new(), checks_time, checked)
}

/// Grades one submission in `slot`; returns the result JSON.
pub(crate) fn grade_one(
    slot: &mut Slot,
    (files, student, report): (
        &submission::Files,
        &cg_assign::StudentFile,
        &(Option<Found>, Vec<Text>),
    ),
    stubs: &BTreeMap<String, String>,
    pristine: (&str, &(dyn Fn(&Path) -> bool + Sync)),
    options: &Options,
    launcher: Launcher,
) -> result::Facts {
    let (pristine, skip) = pristine;
    let mut facts = result::Facts::default();
    // The copy of the kit as it was made, or made afresh (see `slot_content`).
    if slot_content(&slot.kit).ok().as_deref() != Some(pristine) {
        eprintln!(
            "{}",
            t(
                "作業用のキットのコピーが変わっていたので作り直します",
                "the work copy of the kit had changed: made afresh"
            )
            .get(options.lang)
        );
        let _ = std::fs::remove_dir_all(&slot.kit);
        let remade = std::fs::create_dir_all(&slot.kit)
            .map_err(|e| Text::io(&e))
            .and_then(|()| handout::write_handout_filtered(&options.kit, &slot.kit, skip));
        if remade.is_err() || slot_content(&slot.kit).ok().as_deref() != Some(pristine) {
            facts.fatal = Some(Text::new(
                "作業用のキットのコピーを作り直せません",
                "the work copy of the kit cannot be made afresh",
            ));
            facts.retry = true;
            return facts;
        }
    }
    let student_toml = files.student_toml.clone().unwrap_or_default();
    let io_fail = |facts: &mut result::Facts, e: std::io::Error| {
        let why = Text::io(&e);
        facts.fatal =
            Some(Text::new(format!("作業用コピー: {}", why.ja), format!("work copy: {}", why.en)));
        facts.retry = true;
    };
    let student_path = slot.kit.join("exercises/student.toml");
    if let Err(e) = std::fs::write(&student_path, &student_toml) {
        io_fail(&mut facts, e);
        return facts;
    }
    let mut replaced: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for &m in submission::MODULES {
        let text = files.modules.get(m).map_or_else(|| stubs[m].as_bytes().to_vec(), Clone::clone);
        if let Err(e) = write_if_changed(&slot.kit.join(format!("exercises/src/{m}.rs")), &text) {
            io_fail(&mut facts, e);
            return facts;
        }
    }
    facts.converted = files.converted.clone();
    facts.not_submitted = submission::MODULES
        .iter()
        .filter(|m| !files.modules.contains_key(**m))
        .map(|m| (*m).to_owned())
        .collect();
    let package = WORKER_PACKAGE;
    let started = Instant::now();
    // Build; replace the modules that do not compile by their stubs; build again.
    loop {
        let b = match build::cargo_build_sandboxed(
            &slot.kit,
            &slot.target,
            package,
            options.build_limit,
            options.isolation,
        ) {
            Ok(b) => b,
            Err(why) => {
                facts.fatal = Some(why);
                facts.retry = true;
                break;
            }
        };
        if b.success {
            break;
        }
        let mut blamed: Vec<(String, Vec<String>)> =
            b.module_errors.into_iter().filter(|(m, _)| !replaced.contains_key(m)).collect();
        if blamed.is_empty() && !b.timed_out {
            // Errors in the kit's files caused by a module (a changed signature): every module
            // of the submission's own that is still in is taken out.
            let mut others = b.other_errors.clone();
            if others.is_empty() {
                others.push(result::tail(&b.stderr_tail, 1500));
            }
            blamed = submission::MODULES
                .iter()
                .filter(|m| !replaced.contains_key(**m) && files.modules.contains_key(**m))
                .map(|m| ((*m).to_owned(), others.clone()))
                .collect();
        }
        if blamed.is_empty() {
            let why = if b.timed_out {
                Text::new(
                    format!("ビルドが制限時間 {} 秒を超えました", options.build_limit.as_secs()),
                    format!("the build ran over its limit of {} s", options.build_limit.as_secs()),
                )
            } else {
                Text::new(
                    format!("ビルドできません:\n{}", b.stderr_tail),
                    format!("does not build:\n{}", b.stderr_tail),
                )
            };
            facts.fatal = Some(why);
            break;
        }
        for (m, errors) in blamed {
            if let Err(e) = write_if_changed(
                &slot.kit.join(format!("exercises/src/{m}.rs")),
                stubs[&m].as_bytes(),
            ) {
                io_fail(&mut facts, e);
                return facts;
            }
            replaced.insert(m, errors);
        }
    }
    facts.build = Some(started.elapsed());
    facts.compile_errors = replaced;
    if facts.fatal.is_some() {
        return facts;
    }
    let (runs, baseline, run_time, report) = run_checks(slot, (student, report), options, launcher);
    facts.report = report;
    facts.runs = runs;
    facts.baseline = baseline;
    facts.run = Some(run_time);
    facts
}

pub(crate) fn write_if_changed(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    if std::fs::read(path).ok().as_deref() == Some(bytes) {
        return Ok(());
    }
    std::fs::write(path, bytes)
}
