//! Gradescope, and any batch system that runs one container per submission: `cg grade-one`
//! grades one submission with the same pipeline as `cg grade` ([`crate::grade_with`]) and
//! writes `results.json` in the format of Gradescope's autograder specification
//! (<https://gradescope-autograders.readthedocs.io/en/latest/specs/>) beside the kit's usual
//! per-student files; `cg autograder` writes the zip Gradescope runs ([`package`]).
//!
//! The mapping from the kit's result ([`crate::result::build`]) is [`results_json`]: the
//! score, the tests (one per check: `score`, `max_score`, `status`, `name`, `number` = the
//! check ID, `output` in Markdown, `tags` = the assignment, `visibility` from [`visibility`]),
//! `execution_time`, and everything else of the kit's (the maximum score, the `cg` object)
//! under `extra_data`.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use serde_json::{Value, json};

use crate::{GradeError, Graded, Launcher, Options, moodle, progress, write_atomic};

pub mod package;
#[cfg(test)]
mod tests;

/// The visibility values Gradescope accepts, for the whole result and for each test.
pub const VISIBILITIES: &[&str] = &["hidden", "after_due_date", "after_published", "visible"];

/// A check's visibility on Gradescope. The kit has no hidden checks: every check is
/// `"visible"` (a student sees each check's outcome as `cg check` shows it). Making some hidden
/// is this one function.
#[must_use]
pub fn visibility(_check_id: &str) -> &'static str {
    "visible"
}

/// `text` as a Markdown code block, whatever it holds: a fence longer than any run of
/// backticks inside, so a student's panic message cannot end it (nor be read as Markdown or
/// HTML). Empty text stays empty.
#[must_use]
pub fn fenced(text: &str) -> String {
    if text.trim_end().is_empty() {
        return String::new();
    }
    crate::result::code_block(text)
}

/// The check's assignment (`a1` of `a1.t3.unit`), for the test's tags.
fn assignment(id: &str) -> &str {
    id.split('.').next().unwrap_or(id)
}

/// Gradescope's `results.json` of the kit's result `result` ([`crate::result::build`]),
/// graded in `execution_time`.
#[must_use]
pub fn results_json(result: &Value, execution_time: Duration) -> Value {
    let tests: Vec<Value> = result["tests"]
        .as_array()
        .map(Vec::as_slice)
        .unwrap_or_default()
        .iter()
        .map(|t| {
            let id = t["number"].as_str().unwrap_or("?");
            json!({
                "score": t["score"].as_f64().unwrap_or(0.0),
                "max_score": t["max_score"].as_f64().unwrap_or(0.0),
                "status": if t["status"] == "passed" { "passed" } else { "failed" },
                "name": t["name"].as_str().unwrap_or(id),
                "number": id,
                "output": fenced(t["output"].as_str().unwrap_or("")),
                "output_format": "md",
                "tags": [assignment(id)],
                "visibility": visibility(id),
            })
        })
        .collect();
    let score = result["score"].as_f64().unwrap_or(0.0);
    let mut output = String::new();
    if let Some(max) = result["max_score"].as_f64() {
        output = format!("**{score} / {max}**\n\n");
    }
    output.push_str(&fenced(result["output"].as_str().unwrap_or("")));
    json!({
        "score": score,
        "execution_time": execution_time.as_secs_f64().ceil() as u64,
        "output": output,
        "output_format": "md",
        "test_output_format": "md",
        "visibility": "visible",
        // The autograder's stdout is the kit's build log and paths: for the instructor.
        "stdout_visibility": "hidden",
        "extra_data": {
            "max_score": result["max_score"],
            "cg": result["cg"],
        },
        "tests": tests,
    })
}

/// Gradescope's `results.json` of a run that could not grade: score 0 and `why` in `output`.
#[must_use]
pub fn failure_json(why: &str, execution_time: Duration) -> Value {
    json!({
        "score": 0.0,
        "execution_time": execution_time.as_secs_f64().ceil() as u64,
        "output": fenced(why),
        "output_format": "md",
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "extra_data": { "error": why },
        "tests": [],
    })
}

/// What [`grade_one`] wrote.
#[derive(Clone, Debug)]
pub struct One {
    /// How it went (the result's name: the student number, when known).
    pub graded: Graded,
    /// The `results.json` written.
    pub results: Value,
    /// Its path.
    pub path: PathBuf,
}

/// Grades the one submission `submission` (a folder or a `.zip`, as an entry of `cg grade`'s
/// submissions folder) with `options` (its `out` is the work folder: the slot, the class of one,
/// the kept results; its `submissions` is ignored), and writes into `results`:
/// `results.json` (Gradescope's format), `<student>.json` and `feedback/<student>/` (the
/// kit's). `on` hears how it goes.
///
/// # Errors
/// The kit could not be read, or the results not written (then write [`failure_json`]).
pub fn grade_one(
    options: &Options,
    submission: &Path,
    results: &Path,
    launcher: Launcher,
    on: &(dyn Fn(progress::Event<'_>) + Sync),
) -> Result<One, GradeError> {
    let started = Instant::now();
    let io = |p: &Path, e: std::io::Error| GradeError::at(p, &e);
    let mut options = options.clone();
    options.submissions = submission.to_path_buf();
    options.jobs = 1;
    let entry = moodle::input::Entry::single(submission);
    let graded = crate::grade_with(&options, launcher, on, Some(entry))?;
    let graded = graded.into_iter().next().ok_or_else(|| {
        GradeError::Io(crate::t("提出物の結果がありません", "no result for the submission"))
    })?;
    let name = format!("{}.json", graded.name);
    let kit_result = options.out.join(&name);
    let text = std::fs::read_to_string(&kit_result).map_err(|e| io(&kit_result, e))?;
    let value: Value = serde_json::from_str(&text).map_err(|e| crate::not_json(&kit_result, &e))?;
    std::fs::create_dir_all(results).map_err(|e| io(results, e))?;
    let same = |a: &Path, b: &Path| match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if !same(&options.out, results) {
        write_atomic(&results.join(&name), text.as_bytes()).map_err(|e| io(results, e))?;
        let from = options.out.join("feedback").join(&graded.name);
        let to = results.join("feedback").join(&graded.name);
        std::fs::create_dir_all(&to).map_err(|e| io(&to, e))?;
        for file in std::fs::read_dir(&from).map_err(|e| io(&from, e))?.flatten() {
            if file.path().is_file() {
                std::fs::copy(file.path(), to.join(file.file_name()))
                    .map_err(|e| io(&file.path(), e))?;
            }
        }
    }
    let gradescope = results_json(&value, started.elapsed());
    let path = results.join("results.json");
    let pretty = serde_json::to_string_pretty(&gradescope).unwrap_or_default();
    write_atomic(&path, pretty.as_bytes()).map_err(|e| io(&path, e))?;
    Ok(One { graded, results: gradescope, path })
}

/// Problems of `results` against Gradescope's specification (empty: none): the types of the
/// known keys, the visibility values, each test's score within its maximum and the tests'
/// scores adding up to the total. Used by the tests, and by `cg grade-one` before it writes.
#[must_use]
pub fn problems(results: &Value) -> Vec<String> {
    let mut out = Vec::new();
    let Some(top) = results.as_object() else {
        return vec!["results.json is not an object".to_owned()];
    };
    let known = [
        "score",
        "execution_time",
        "output",
        "output_format",
        "test_output_format",
        "test_name_format",
        "visibility",
        "stdout_visibility",
        "extra_data",
        "tests",
        "leaderboard",
    ];
    for k in top.keys() {
        if !known.contains(&k.as_str()) {
            out.push(format!("unknown key {k}"));
        }
    }
    let formats = ["text", "html", "simple_format", "md", "ansi"];
    let check_format = |v: &Value, at: &str, out: &mut Vec<String>| {
        if !v.is_null() && !v.as_str().is_some_and(|f| formats.contains(&f)) {
            out.push(format!("{at}: output format {v}"));
        }
    };
    let check_visibility = |v: &Value, at: &str, out: &mut Vec<String>| {
        if !v.is_null() && !v.as_str().is_some_and(|f| VISIBILITIES.contains(&f)) {
            out.push(format!("{at}: visibility {v}"));
        }
    };
    let tests = results["tests"].as_array().cloned().unwrap_or_default();
    if !results["tests"].is_null() && !results["tests"].is_array() {
        out.push("tests is not an array".to_owned());
    }
    if !results["score"].is_number() && tests.iter().any(|t| !t["score"].is_number()) {
        out.push("no score: neither at the top nor on every test".to_owned());
    }
    if !results["execution_time"].is_null() && !results["execution_time"].is_u64() {
        out.push("execution_time is not a whole number of seconds".to_owned());
    }
    for k in ["output", "output_format", "test_output_format", "test_name_format"] {
        if !results[k].is_null() && !results[k].is_string() {
            out.push(format!("{k} is not a string"));
        }
    }
    if !results["extra_data"].is_null() && !results["extra_data"].is_object() {
        out.push("extra_data is not an object".to_owned());
    }
    check_format(&results["output_format"], "top", &mut out);
    check_format(&results["test_output_format"], "top (tests)", &mut out);
    check_visibility(&results["visibility"], "top", &mut out);
    check_visibility(&results["stdout_visibility"], "top (stdout)", &mut out);
    let mut sum = 0.0;
    for (i, t) in tests.iter().enumerate() {
        let at = format!("test {i}");
        let Some(test) = t.as_object() else {
            out.push(format!("{at} is not an object"));
            continue;
        };
        for k in test.keys() {
            let allowed = [
                "score",
                "max_score",
                "status",
                "name",
                "name_format",
                "number",
                "output",
                "output_format",
                "tags",
                "visibility",
                "extra_data",
            ];
            if !allowed.contains(&k.as_str()) {
                out.push(format!("{at}: unknown key {k}"));
            }
        }
        for k in ["name", "number", "output", "name_format"] {
            if !t[k].is_null() && !t[k].is_string() {
                out.push(format!("{at}: {k} is not a string"));
            }
        }
        if !t["status"].is_null() && !matches!(t["status"].as_str(), Some("passed" | "failed")) {
            out.push(format!("{at}: status {}", t["status"]));
        }
        if !t["tags"].is_null()
            && !t["tags"].as_array().is_some_and(|a| a.iter().all(Value::is_string))
        {
            out.push(format!("{at}: tags is not a list of strings"));
        }
        check_format(&t["output_format"], &at, &mut out);
        check_visibility(&t["visibility"], &at, &mut out);
        match (t["score"].as_f64(), t["max_score"].as_f64()) {
            (Some(s), Some(m)) if s > m + 1e-9 || s < 0.0 => {
                out.push(format!("{at}: score {s} outside 0..={m}"));
            }
            (Some(s), _) => sum += s,
            (None, _) => {}
        }
        if !t["max_score"].is_null() && !t["max_score"].is_number() {
            out.push(format!("{at}: max_score is not a number"));
        }
    }
    if let Some(score) = results["score"].as_f64()
        && !tests.is_empty()
        && (score - sum).abs() > 1e-3 * tests.len() as f64
    {
        out.push(format!("score {score} is not the tests' sum {sum}"));
    }
    out
}
