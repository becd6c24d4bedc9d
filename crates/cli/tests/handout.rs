//! `cg handout`: the student's copy has no solutions, its stubs are the pristine ones, and it
//! builds, runs and checks on its own (every check "not done yet" or failing, none passing),
//! without the GPU renderer and the instructors' commands, which say how to build them when asked
//! for.
//! Then the student's whole day in that copy, on the reference answers: `assignment --save`,
//! `check` (all pass), `view` of each assignment beside the kit's own reference picture, `report fill`, `report check` (exit status 0,
//! no false positive) and LuaLaTeX on the filled templates, English and Japanese. Last, two files that do not compile
//! stop only their own assignments in `check`, `view` and `report`.

use std::path::Path;
use std::process::Command;

mod common;
use common::root;

/// What the students' copy builds without (cargo's target names): the GPU renderer (wgpu, its
/// shader translator and Vulkan bindings) and the instructors' commands (grading, its sandbox,
/// the copy finder, zip, the progress bar). `cargo run --release --features gpu` and
/// `--features instructor` build them.
const LEFT_OUT: [&str; 11] = [
    "wgpu",
    "wgpu_core",
    "wgpu_hal",
    "naga",
    "ash",
    "cg_gpu",
    "cg_grade",
    "cg_sandbox",
    "cg_similarity",
    "zip",
    "indicatif",
];

#[test]
fn the_handout_builds_and_checks_on_its_own_and_a_students_day_runs_in_it() {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("handout-copy");
    let _ = std::fs::remove_dir_all(&dir);
    let o = common::cg(&root(), &["handout", dir.to_str().unwrap(), "--lang", "en"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The next command it prints names this folder, runnable as printed.
    let out = String::from_utf8_lossy(&o.stdout);
    let cd = format!("  cd {}\n  cargo run --release -- check", dir.display());
    assert!(out.contains(&cd) && !out.contains("<DIR>"), "{out}");

    // No solutions anywhere: not the folder, not the manifests, not the lock file.
    assert!(!dir.join("solutions").exists());
    for file in ["Cargo.toml", "Cargo.lock", "crates/cli/Cargo.toml"] {
        let text = std::fs::read_to_string(dir.join(file)).unwrap();
        assert!(
            !text.contains("cg-solutions") && !text.contains("BEGIN SOLUTION"),
            "{file}:\n{text}"
        );
    }
    // The stubs are exactly what the solutions generate.
    for (relative, text) in cg_harness::stubs::generate(&root().join("solutions")).unwrap() {
        let got = std::fs::read_to_string(dir.join("exercises").join(&relative)).unwrap();
        assert_eq!(got, text, "exercises/{}", relative.display());
    }
    assert!(!dir.join("exercises/student.toml").exists(), "no one's student number goes out");

    // It builds offline with the committed lock file, and checks: nothing passes yet.
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("../handout");
    let cargo = |args: &[&str]| {
        Command::new(env!("CARGO"))
            .args(args)
            .current_dir(&dir)
            .env("CARGO_TARGET_DIR", &target)
            // A one-off build: no debug info and no incremental cache to write (faster, and
            // what is tested — that the copy builds and checks — does not depend on either).
            .env("CARGO_PROFILE_DEV_DEBUG", "0")
            .env("CARGO_INCREMENTAL", "0")
            .output()
            .unwrap()
    };
    let run = |args: &[&str]| {
        let mut all = vec!["run", "--offline", "--locked", "--quiet", "--"];
        all.extend_from_slice(args);
        all.extend_from_slice(&["--lang", "en"]);
        let o = cargo(&all);
        let text = format!(
            "{}\n{}",
            String::from_utf8_lossy(&o.stdout),
            String::from_utf8_lossy(&o.stderr)
        );
        (o.status.code(), text)
    };
    let build =
        cargo(&["build", "--offline", "--locked", "--message-format=json-render-diagnostics"]);
    assert!(
        build.status.success(),
        "the handout does not build:\n{}",
        String::from_utf8_lossy(&build.stderr)
    );
    // Without the GPU renderer and the instructors' commands (issue 18: the students' first
    // build is the shortest it can be; docs/performance.md §3). Cargo names every unit of the
    // build, compiled or fresh.
    let built: Vec<String> = String::from_utf8_lossy(&build.stdout)
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter(|m| m["reason"] == "compiler-artifact")
        .filter_map(|m| m["target"]["name"].as_str().map(str::to_owned))
        .collect();
    for present in ["cg", "cg_viewer", "softbuffer", "winit", "cg_raster"] {
        assert!(built.iter().any(|n| n == present), "{present} is built: {built:?}");
    }
    for absent in LEFT_OUT {
        assert!(!built.iter().any(|n| n == absent), "{absent} is built: {built:?}");
    }
    // What the students' copy prints to build them resolves with its lock file, offline.
    let tree = cargo(&[
        "tree",
        "--offline",
        "--locked",
        "-e",
        "normal",
        "--prefix",
        "none",
        "-p",
        "cg-cli",
        "--features",
        "gpu,instructor",
    ]);
    let tree = String::from_utf8_lossy(&tree.stdout);
    for needed in ["wgpu v", "cg-gpu v", "cg-grade v", "cg-similarity v", "indicatif v"] {
        assert!(tree.contains(needed), "{needed} with --features gpu,instructor:\n{tree}");
    }
    let check = cargo(&[
        "run",
        "--offline",
        "--locked",
        "--quiet",
        "--",
        "check",
        "--student",
        "12345678",
        "--json",
    ]);
    assert!(!check.status.success(), "pristine stubs must not pass every check");
    let reports: serde_json::Value = serde_json::from_slice(&check.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&check.stdout)));
    let reports = reports.as_array().unwrap();
    assert_eq!(reports.len(), 5, "a1, a2, a3, a4 and s");
    for r in reports {
        assert!(r["total"].as_u64().unwrap() > 0, "{}: no checks", r["assignment"]);
        assert_eq!(r["passed"], 0, "{}: a pristine stub passed a check", r["assignment"]);
    }

    // Asking for what the copy left out says so, with the command that builds it, as the
    // student typed it (and nothing is drawn).
    let (code, text) = run(&["render", "--renderer", "gpu", "-o", "out/gpu.png"]);
    assert_eq!(code, Some(2), "{text}");
    assert!(text.contains("built without the GPU renderer"), "{text}");
    let command = "cargo run --release --features gpu -- render --renderer gpu -o out/gpu.png";
    assert!(text.contains(command), "{command}\n{text}");
    assert!(!dir.join("out/gpu.png").exists(), "{text}");
    let (code, text) = run(&["grade", "submissions/", "--out", "grades"]);
    assert_eq!(code, Some(2), "{text}");
    assert!(text.contains("`grade` is an instructors' command"), "{text}");
    let command = "cargo run --release --features instructor -- grade submissions/ --out grades";
    assert!(text.contains(command), "{command}\n{text}");
    let (code, text) = run(&["--help"]);
    assert_eq!(code, Some(0), "{text}");
    // The kit maintainers' commands too: sync-stubs needs solutions/, bench writes docs/.
    for hidden in ["handout", "grade", "similarity", "autograder", "sync-stubs", "bench"] {
        assert!(!text.contains(&format!("\n  {hidden} ")), "{hidden} in cg --help:\n{text}");
    }

    // The student's day, on the reference answers: the solutions' files in place of the stubs
    // (their stub blocks are comments), then every command the day needs, as a student runs
    // them in the copy.
    for id in ["a1", "a2", "a3", "a4", "s"] {
        let file = format!("{id}.rs");
        std::fs::copy(
            root().join("solutions/src").join(&file),
            dir.join("exercises/src").join(&file),
        )
        .unwrap();
    }
    // 2. The student number, recorded once.
    let (code, text) = run(&["assignment", "--student", "12345678", "--save"]);
    assert_eq!(code, Some(0), "{text}");
    assert!(dir.join("exercises/student.toml").exists(), "{text}");
    // 3. Every check passes (exit status 0), with no student number on the command line.
    let (code, text) = run(&["check"]);
    assert_eq!(code, Some(0), "the reference answers must pass every check:\n{text}");
    assert!(!text.contains('✗') && !text.contains("not done yet"), "{text}");
    // 4. Every view draws the student's picture and, beside it, the kit's own reference picture
    // (the copy has no solutions: the kit draws it from its oracles), which the reference
    // answers match: at most 0.05 % of the pixels differ by more than 2/255.
    for id in ["a1", "a2", "a3", "a4", "s"] {
        let (code, text) = run(&["view", id, "--png", "-o", "out"]);
        assert_eq!(code, Some(0), "{text}");
        for side in ["yours", "reference", "diff"] {
            let png = dir.join(format!("out/view-{id}-{side}.png"));
            assert!(png.exists(), "{id}: {}: {text}", png.display());
        }
        let same = text.contains("the same picture as the reference");
        let few = text.split("difference: ").nth(1).and_then(|rest| {
            let words: Vec<&str> = rest.split_whitespace().collect();
            let (differ, total) =
                (words.first()?.parse::<usize>().ok()?, words.get(2)?.parse::<usize>().ok()?);
            Some(differ * 2000 <= total)
        });
        assert!(same || few == Some(true), "{id}: yours and the kit's reference differ:\n{text}");
    }
    // 5–6. The report filled from the student's own results, then checked: no false positive.
    let (code, text) = run(&["report", "fill"]);
    assert_eq!(code, Some(0), "{text}");
    for file in ["report/report.md", "report/report.tex"] {
        assert!(dir.join(file).exists(), "{file}: {text}");
    }
    let (code, text) = run(&["report", "check"]);
    assert_eq!(code, Some(0), "the untouched filled report must check clean:\n{text}");
    // Handing in: the checks run as grading runs them, then the zip.
    let (code, text) = run(&["handin"]);
    assert_eq!(code, Some(0), "{text}");
    for needle in ["  a1  14/14 checks pass\n", "  s   ", "wrote handin/12345678.zip"] {
        assert!(text.contains(needle), "{needle:?} in:\n{text}");
    }
    assert!(!text.contains("not done yet") && !text.contains("does not compile"), "{text}");
    // The Japanese template too, filled into a folder of its own.
    let o = cargo(&[
        "run",
        "--offline",
        "--locked",
        "--quiet",
        "--",
        "report",
        "fill",
        "-o",
        "report-ja",
        "--lang",
        "ja",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let ja = std::fs::read_to_string(dir.join("report-ja/report.tex")).unwrap();
    assert!(ja.contains("luatexja") || ja.contains("ltjs"), "the Japanese template");
    // 7. Both LaTeX templates compile (where LuaLaTeX is installed; CI installs it).
    let lualatex =
        Command::new("lualatex").arg("--version").output().is_ok_and(|o| o.status.success());
    if lualatex {
        for folder in ["report", "report-ja"] {
            let o = Command::new("lualatex")
                .args(["-interaction=nonstopmode", "-halt-on-error", "report.tex"])
                .current_dir(dir.join(folder))
                .output()
                .unwrap();
            let log = String::from_utf8_lossy(&o.stdout);
            let skip = log.chars().count().saturating_sub(3000);
            let end: String = log.chars().skip(skip).collect();
            assert!(o.status.success(), "lualatex in {folder}:\n{end}");
            assert!(dir.join(folder).join("report.pdf").exists());
        }
    } else {
        assert!(std::env::var_os("CI").is_none(), "CI installs LuaLaTeX (scripts/setup.sh)");
        eprintln!("note: lualatex is not on PATH; the report's LaTeX is not compiled here");
    }

    // 8. A file that does not compile stops only its own assignment. a1.rs cannot be parsed;
    // a3.rs parses but does not type-check, which the compiler finds only once a1.rs is left
    // out. Every command still runs: `cg` does not link the exercises, and their worker is
    // built without the two files.
    let a1 = dir.join("exercises/src/a1.rs");
    let mut text = std::fs::read_to_string(&a1).unwrap();
    text.push_str("\nfn half_written( {\n");
    std::fs::write(&a1, text).unwrap();
    let a3 = dir.join("exercises/src/a3.rs");
    let mut text = std::fs::read_to_string(&a3).unwrap();
    text.push_str("\npub fn wrong_type() -> u32 { \"three\" }\n");
    std::fs::write(&a3, text).unwrap();
    let (code, text) = run(&["check"]);
    assert_eq!(code, Some(1), "{text}");
    for needle in [
        "exercises/src/a1.rs does not compile",
        "unclosed delimiter",
        "exercises/src/a3.rs does not compile",
        "mismatched types",
        "does not compile: exercises/src/a1.rs",
    ] {
        assert!(text.contains(needle), "{needle:?} in:\n{text}");
    }
    let o = cargo(&["run", "--offline", "--locked", "--quiet", "--", "check", "--json"]);
    let json: serde_json::Value = serde_json::from_slice(&o.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&o.stdout)));
    for r in json.as_array().unwrap() {
        let broken = matches!(r["assignment"].as_str(), Some("a1" | "a3"));
        for c in r["checks"].as_array().unwrap() {
            let want = if broken { "does_not_compile" } else { "pass" };
            assert_eq!(c["status"], want, "{c}");
        }
    }
    // Handing in says which assignments grading would score 0, and ends 1, the zip written.
    let (code, text) = run(&["handin", "--out", "out-broken/handin.zip"]);
    assert_eq!(code, Some(1), "{text}");
    for needle in [
        "  a1  exercises/src/a1.rs does not compile: grading scores this assignment 0. `cargo run --release -- check a1` shows where",
        "  a3  exercises/src/a3.rs does not compile",
        "  a2  ",
        "a file does not compile: its assignment scores 0 in grading",
    ] {
        assert!(text.contains(needle), "{needle:?} in:\n{text}");
    }
    assert!(dir.join("out-broken/handin.zip").exists(), "{text}");
    // The view draws the assignments that compile and says why it cannot draw a1.
    let (code, text) = run(&["view", "a4", "--png", "-o", "out-broken"]);
    assert_eq!(code, Some(0), "{text}");
    assert!(dir.join("out-broken/view-a4-yours.png").exists(), "{text}");
    // No picture of the student's side: exit status 1, as for a panic.
    let (code, text) = run(&["view", "a1", "--png", "-o", "out-broken"]);
    assert_eq!(code, Some(1), "{text}");
    assert!(text.contains("exercises/src/a1.rs does not compile"), "{text}");
    assert!(!dir.join("out-broken/view-a1-yours.png").exists(), "{text}");
    // The report derives every other part, and names the two files.
    let (code, text) = run(&["report", "derive", "-o", "out-broken/report"]);
    assert_eq!(code, Some(0), "{text}");
    assert!(text.contains("a1.t1: vertices(): exercises/src/a1.rs does not compile"), "{text}");
    assert!(text.contains("exercises/src/a3.rs does not compile"), "{text}");
    assert!(!text.contains("a4.t1"), "a4 derives: {text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `cg handout --table 2`: the copy's students get table 2 when they record their number
/// (exercises/course.toml), the same variants as `--table 2` gives in the kit; without it, 1.
#[test]
fn a_handout_for_table_2_gives_its_students_table_2() {
    let dir = common::scratch("handout", "table_2");
    let copy = dir.join("copy");
    let out = common::cg(&dir, &["handout", "--table", "2", copy.to_str().unwrap()]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{stdout}{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("table 2 is what this copy's students get"), "{stdout}");
    let course = std::fs::read_to_string(copy.join("exercises/course.toml")).unwrap();
    assert!(course.ends_with("\ntable = 2\n"), "{course}");
    let save = ["assignment", "--student", "20261234", "--save", "--only", "a3", "--json"];
    let out = common::cg(&copy, &save);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let record = std::fs::read_to_string(copy.join("exercises/student.toml")).unwrap();
    assert!(record.contains("student = \"20261234\"\ntable = 2\n"), "{record}");
    let kit = ["assignment", "--student", "20261234", "--table", "2", "--only", "a3", "--json"];
    assert_eq!(out.stdout, common::cg(&root(), &kit).stdout);
    // Without `--table`, no course file: the students get table 1.
    let plain = dir.join("plain");
    assert!(common::cg(&dir, &["handout", plain.to_str().unwrap()]).status.success());
    assert!(!plain.join("exercises/course.toml").exists());
    let out = common::cg(&plain, &["assignment", "--student", "20261234", "--only", "a3"]);
    assert!(
        String::from_utf8_lossy(&out.stdout).starts_with("Student number: 20261234  (table 1)")
    );
}
