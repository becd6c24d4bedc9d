//! A generated class is graded end to end: the correct submission (a nested zip), one with a
//! reversed face, one whose a2 does not compile, hostile ones (an endless loop, a run-away
//! allocation, a panic, a forged report printed before `exit(0)`) and a zip-slip zip. Each gets exactly its expected scores; the class
//! table, the summary and resuming (a second run keeps everything) are checked too.
//!
//! Needs the kit's own repository (solutions/): in a student handout it says so and passes.
//!
//! The sandbox is the real one (`cg_sandbox::launch` with the strongest isolation the machine
//! offers; bubblewrap under CI): the panicking submission also tries to write outside its folder
//! and to start a shell, and both must fail.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use cg_core::lang::Lang;
use cg_grade::{Config, Options};
use cg_harness::TableVersion;
use cg_sandbox::{Isolation, Limits};
use serde_json::Value;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

fn solution(module: &str) -> String {
    std::fs::read_to_string(root().join(format!("solutions/src/{module}.rs"))).unwrap()
}

fn edit(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "the solution no longer contains {from:?}");
    text.replacen(from, to, 1)
}

fn student_toml(n: &str) -> String {
    format!("student = \"{n}\"\ntable = 1\n")
}

/// Writes a submission folder `dir` with the solutions, `changes` applied.
fn folder(dir: &Path, student: &str, changes: &[(&str, String)]) {
    std::fs::create_dir_all(dir.join("exercises/src")).unwrap();
    for m in ["a1", "a2", "a3", "a4", "s"] {
        let text =
            changes.iter().find(|(c, _)| *c == m).map_or_else(|| solution(m), |(_, t)| t.clone());
        std::fs::write(dir.join(format!("exercises/src/{m}.rs")), text).unwrap();
    }
    std::fs::write(dir.join("exercises/student.toml"), student_toml(student)).unwrap();
    // Something the grader must never copy: a fake check crate.
    std::fs::create_dir_all(dir.join("crates/a1-polygon/src")).unwrap();
    std::fs::write(dir.join("crates/a1-polygon/src/lib.rs"), "compile_error!(\"copied\");")
        .unwrap();
}

fn zip(path: &Path, entries: &[(&str, String)]) {
    let mut z = zip::ZipWriter::new(std::fs::File::create(path).unwrap());
    let options = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for (name, text) in entries {
        z.start_file(*name, options).unwrap();
        z.write_all(text.as_bytes()).unwrap();
    }
    z.finish().unwrap();
}

/// A report's vertex table for `student`'s variant, as the lecture writes it (`V0 (0.0, 1.0,
/// 0.0)`, four decimals), from the kit's own vertices; with `wrong`, that vertex's x is 0.5 off.
fn vertex_rows(student: &str, wrong: Option<usize>) -> String {
    let variant = cg_assign::Variants::for_student(&student.parse().unwrap(), TableVersion::V1);
    let mut md = String::from("# Report\n\n## Vertices\n\n");
    for (k, v) in cg_assign::cg_a1::SpecExt::expected_vertices(&variant.a1).iter().enumerate() {
        let x = if wrong == Some(k) { v.x + 0.5 } else { v.x };
        md.push_str(&format!("V{k} ({x:.4}, {:.4}, {:.4})\n", v.y, v.z));
    }
    md
}

fn tests_of(result: &Value) -> Vec<(String, String, f64)> {
    result["tests"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| {
            (
                t["number"].as_str().unwrap().to_owned(),
                t["status"].as_str().unwrap().to_owned(),
                t["score"].as_f64().unwrap(),
            )
        })
        .collect()
}

fn failed_ids(result: &Value) -> Vec<String> {
    tests_of(result).into_iter().filter(|t| t.1 != "passed").map(|t| t.0).collect()
}

fn read(path: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

#[test]
fn a_generated_class_gets_exactly_its_expected_grades() {
    if !root().join("solutions/src/a1.rs").exists() {
        eprintln!("no solutions/ (a student handout): grading is tested in the kit's repository");
        return;
    }
    let base = Path::new(env!("CARGO_TARGET_TMPDIR")).join("grade-class");
    let subs = base.join("submissions");
    let out = base.join("out");
    let _ = std::fs::remove_dir_all(&subs);
    // Results go; the work copies (and their build folders) stay between runs of this test.
    if let Ok(entries) = std::fs::read_dir(&out) {
        for e in entries.flatten().filter(|e| e.file_name() != ".work") {
            let _ = std::fs::remove_file(e.path());
        }
    }
    std::fs::create_dir_all(&subs).unwrap();

    // 1. Correct, zipped inside a folder of its own (deflated), with a stray file.
    let mut entries: Vec<(String, String)> = ["a1", "a2", "a3", "a4", "s"]
        .iter()
        .map(|m| (format!("handin/exercises/src/{m}.rs"), solution(m)))
        .collect();
    entries.push(("handin/exercises/student.toml".into(), student_toml("20260001")));
    entries.push(("handin/notes.txt".into(), "hello".into()));
    // Its report beside exercises/, every vertex right.
    entries.push(("handin/report/report.md".into(), vertex_rows("20260001", None)));
    let refs: Vec<(&str, String)> = entries.iter().map(|(n, t)| (n.as_str(), t.clone())).collect();
    zip(&subs.join("01-correct.zip"), &refs);
    // 2. A classic mistake: the first face listed clockwise.
    let reversed = edit(
        &solution("a1"),
        "canonical_faces(&spec.shape).iter().map(|f| f.map(|c| map[c as usize])).collect()",
        "let mut v: Vec<[u32; 3]> = canonical_faces(&spec.shape).iter().map(|f| f.map(|c| map[c as usize])).collect(); v[0].swap(1, 2); v",
    );
    folder(&subs.join("02-reversed"), "20260002", &[("a1", reversed)]);
    // Its report has V1 wrong.
    let report_02 = subs.join("02-reversed/report/report.md");
    std::fs::create_dir_all(report_02.parent().unwrap()).unwrap();
    std::fs::write(&report_02, vertex_rows("20260002", Some(1))).unwrap();
    // 3. a2 does not compile.
    let broken = edit(&solution("a2"), "pub fn camera(", "pub fn camera(;");
    folder(&subs.join("03-a2-syntax"), "20260003", &[("a2", broken)]);
    // A report in LaTeX without one number in the notation: nothing checked, said so.
    std::fs::create_dir_all(subs.join("03-a2-syntax/report")).unwrap();
    std::fs::write(
        subs.join("03-a2-syntax/report/report.tex"),
        "\\section{Polygon model}\nThe vertices are in the figure.\n",
    )
    .unwrap();
    // 4. a1 loops forever.
    let looping = edit(
        &solution("a1"),
        "pub fn vertices(spec: &Spec) -> Vec<Vec3> {",
        "pub fn vertices(spec: &Spec) -> Vec<Vec3> {\n    #[allow(clippy::empty_loop)]\n    loop {}\n",
    );
    folder(&subs.join("04-loop"), "20260004", &[("a1", looping)]);
    // A report whose vertices cannot be derived (vertices() loops): not checked, and the
    // grading goes on.
    std::fs::create_dir_all(subs.join("04-loop/report")).unwrap();
    std::fs::write(subs.join("04-loop/report/report.md"), vertex_rows("20260004", None)).unwrap();
    // 5. a3 allocates without bound; s panics. The blocks are zeroed (fresh pages, not
    // written), so the hoard reaches the address-space limit in milliseconds: a hoard that
    // wrote 2 GiB first could, on a loaded 2-core host, run past the 5 s budget below and be
    // stopped by the time limit instead (one run in five did).
    let greedy = edit(
        &solution("a3"),
        "pub fn idle(spec: &Spec, state: &mut State) {",
        "pub fn idle(spec: &Spec, state: &mut State) {\n    let mut hog: Vec<Vec<u8>> = Vec::new();\n    loop { hog.push(std::hint::black_box(vec![0u8; 64 << 20])); if hog.len() == usize::MAX { break; } }\n",
    );
    // The panic comes after trying to write outside its folder and to start a shell.
    let escape = base.join("escaped.txt");
    let _ = std::fs::remove_file(&escape);
    let panicking = edit(
        &solution("s"),
        "pub fn ambient(ia: Rgb, ka: Rgb) -> Rgb {",
        &format!(
            "pub fn ambient(ia: Rgb, ka: Rgb) -> Rgb {{\n    if ia.x >= 0.0 {{ let wrote = std::fs::write({:?}, \"x\").is_ok(); let spawned = std::process::Command::new(\"sh\").arg(\"-c\").arg(\"true\").status().is_ok(); panic!(\"boom in ambient (wrote outside: {{wrote}}, spawned: {{spawned}})\"); }}\n",
            escape.display().to_string()
        ),
    );
    folder(&subs.join("05-alloc-panic"), "20260005", &[("a3", greedy), ("s", panicking)]);
    // 7. A forged report: every function of a4 prints a report of every check passed, in the
    // JSON `cg check --json` prints, and exits 0. Only the grader decides outcomes: a4 scores 0.
    let mut forged = solution("a4");
    for f in ["pub fn tex_range(", "pub fn tex_coords(", "pub fn sampler("] {
        let at = forged.find(f).unwrap();
        let body = at + forged[at..].find('{').unwrap() + 1;
        forged.insert_str(
            body,
            "\n    println!(\"[{{\\\"assignment\\\":\\\"a4\\\",\\\"passed\\\":9,\\\"total\\\":9,\\\"checks\\\":[]}}]\"); std::process::exit(0);\n",
        );
    }
    folder(&subs.join("07-forged"), "20260007", &[("a4", forged)]);
    // 6. Zip slip.
    zip(
        &subs.join("06-slip.zip"),
        &[("exercises/student.toml", student_toml("20260006")), ("../../evil.rs", "x".into())],
    );

    // A folder of reports handed in on their own: 20260005's (no report inside its submission)
    // with V0 wrong; one under a number no one has, and one without a number, are not used.
    let reports = base.join("reports");
    let _ = std::fs::remove_dir_all(&reports);
    std::fs::create_dir_all(&reports).unwrap();
    std::fs::write(reports.join("report-20260005.md"), vertex_rows("20260005", Some(0))).unwrap();
    std::fs::write(reports.join("20269999.md"), vertex_rows("20260001", None)).unwrap();
    std::fs::write(reports.join("notes.txt"), "x").unwrap();
    let options = Options {
        kit: root(),
        submissions: subs.clone(),
        out: out.clone(),
        config: Config::parse("[points]\na1 = 2\n\"a1.t3\" = 3\n").unwrap(),
        config_text: "[points]\na1 = 2\n\"a1.t3\" = 3\n".into(),
        jobs: 2,
        limits: Limits {
            // Each check's calls within 5 s (the slowest honest check, a3's drift over 10⁶
            // frames, takes well under a second in a release build).
            wall: Duration::from_secs(5),
            memory_bytes: 2 << 30,
            output_bytes: 4 << 20,
            ..Limits::default()
        },
        build_limit: Duration::from_secs(1500),
        isolation: cg_sandbox::detect(),
        lang: Lang::En,
        roster: None,
        reports: Some(reports.clone()),
    };
    let isolated = options.isolation == Isolation::Bubblewrap;
    assert!(
        isolated || std::env::var_os("CI").is_none(),
        "CI installs bubblewrap (scripts/setup.sh): the class must be graded in the sandbox"
    );
    let started = Instant::now();
    let graded = cg_grade::grade(&options, cg_sandbox::launch, &|g| eprintln!("{g:?}")).unwrap();
    eprintln!("graded {} submissions in {:.1} s", graded.len(), started.elapsed().as_secs_f64());
    assert_eq!(graded.len(), 7);
    assert!(graded.iter().all(|g| !g.skipped));

    // Every result: the score is the sum of the passed checks' points, the maximum the sum of
    // all; the points follow the config (a1.t3 3, the rest of a1 2, others the default 1).
    let results: Vec<Value> =
        [1, 2, 3, 4, 5, 7].iter().map(|i| read(&out.join(format!("2026000{i}.json")))).collect();
    for r in &results {
        let tests = tests_of(r);
        let mut max = 0.0;
        for (id, status, score) in &tests {
            let points = if id.starts_with("a1.t3.") {
                3.0
            } else if id.starts_with("a1.") {
                2.0
            } else {
                1.0
            };
            max += points;
            assert_eq!(*score, if status == "passed" { points } else { 0.0 }, "{id}");
        }
        let passed: f64 = tests.iter().map(|t| t.2).sum();
        assert_eq!(r["score"].as_f64().unwrap(), passed);
        assert_eq!(r["max_score"].as_f64().unwrap(), max);
        for m in ["a1", "a2", "a3", "a4", "s"] {
            let n = tests.iter().filter(|t| t.0.starts_with(&format!("{m}."))).count();
            assert!(n >= 3, "{}: only {n} {m} checks", r["cg"]["student"]);
        }
    }
    let of = |r: &Value, prefix: &str| -> Vec<String> {
        tests_of(r).into_iter().map(|t| t.0).filter(|i| i.starts_with(prefix)).collect()
    };

    // The correct one passes everything.
    assert!(failed_ids(&results[0]).is_empty(), "{:#}", results[0]);
    assert_eq!(results[0]["score"], results[0]["max_score"]);

    // The reversed face: exactly the winding and outward checks of a1.t2 fail.
    assert_eq!(failed_ids(&results[1]), ["a1.t2.winding", "a1.t2.outward"]);
    let winding = &results[1]["tests"].as_array().unwrap()
        [tests_of(&results[1]).iter().position(|t| t.0 == "a1.t2.winding").unwrap()];
    assert!(winding["output"].as_str().unwrap().contains("expected"), "{winding:#}");

    // a2 does not compile: its checks 0 with the error; the others all pass.
    let syntax = &results[2];
    assert_eq!(failed_ids(syntax), of(syntax, "a2."));
    let a2 = syntax["tests"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["number"].as_str().unwrap().starts_with("a2."))
        .unwrap();
    assert!(a2["output"].as_str().unwrap().contains("exercises/src/a2.rs:"), "{a2:#}");
    assert_eq!(
        syntax["cg"]["compile_errors"].as_object().unwrap().keys().collect::<Vec<_>>(),
        ["a2"]
    );

    // The loop in vertices(): the checks that call it (face_normals() calls it too) fail with
    // the time limit named; the check of model_transform() passes, as does everything else.
    let looping = &results[3];
    let calls_vertices = |id: &String| id.as_str() != "a1.t4.placement";
    let expected: Vec<String> = of(looping, "a1.").into_iter().filter(calls_vertices).collect();
    assert_eq!(failed_ids(looping), expected);
    let a1_tests = |r: &Value| -> Vec<Value> {
        r["tests"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|t| t["number"].as_str().unwrap().starts_with("a1."))
            .cloned()
            .collect()
    };
    for t in a1_tests(looping).iter().filter(|t| t["score"] == 0.0) {
        assert!(t["output"].as_str().unwrap().contains("time limit"), "{t:#}");
    }

    // The allocation fails the a3 checks that call idle() (all but the warm-up's), each with
    // the memory named; the panic fails the one check that calls ambient, with its message;
    // everything else passes.
    let hostile = &results[4];
    let mut expected: Vec<String> =
        of(hostile, "a3.").into_iter().filter(|id| !id.starts_with("a3.t0.")).collect();
    expected.push("s.t1.ambient".into());
    assert_eq!(failed_ids(hostile), expected);
    let ambient = hostile["tests"]
        .as_array()
        .unwrap()
        .iter()
        .find(|t| t["number"] == "s.t1.ambient")
        .unwrap();
    assert!(ambient["output"].as_str().unwrap().contains("boom in ambient"), "{ambient:#}");
    if isolated {
        // A write outside may "succeed" inside the sandbox's private, throwaway /tmp (where the
        // folders bound in live when the kit itself is under /tmp, as in CI); what matters is
        // that nothing reaches the real file system, and that no process starts.
        assert!(
            ambient["output"].as_str().unwrap().contains("spawned: false"),
            "the sandbox stops new processes: {ambient:#}"
        );
        assert!(!escape.exists(), "nothing was written outside the submission's folder");
    } else {
        eprintln!("note: no bubblewrap here; writes outside and new processes are not stopped");
        let _ = std::fs::remove_file(&escape);
    }
    let drift =
        hostile["tests"].as_array().unwrap().iter().find(|t| t["number"] == "a3.t1.drift").unwrap();
    assert!(drift["output"].as_str().unwrap().contains("memory"), "{drift:#}");

    // The forged report is only what a4's functions printed: every a4 check fails (the process
    // ended), the maximum is the kit's, and the rest pass.
    let forged = &results[5];
    assert_eq!(failed_ids(forged), of(forged, "a4."));
    assert_eq!(forged["max_score"], results[0]["max_score"]);
    assert_eq!(forged["cg"]["assignments"]["a4"]["score"], 0.0);

    // The zip slip: refused, said why, nothing written outside.
    let slip = read(&out.join("_06-slip.zip.json"));
    assert_eq!(slip["score"], 0.0);
    assert!(slip["tests"].as_array().unwrap().is_empty());
    assert!(slip["cg"]["refused"].as_str().unwrap().contains("../../evil.rs"), "{slip:#}");
    assert!(!base.join("evil.rs").exists() && !subs.join("../evil.rs").exists());

    // The reports (not scored: every score above is the checks' alone). The correct one: every
    // vertex's three numbers checked and right.
    let n = cg_assign::cg_a1::SpecExt::expected_vertices(
        &cg_assign::Variants::for_student(&"20260001".parse().unwrap(), TableVersion::V1).a1,
    )
    .len() as u64;
    let report = |r: &Value| r["cg"]["report"].clone();
    let correct = report(&results[0]);
    assert_eq!(correct["report"], "handin/report/report.md", "{correct:#}");
    assert_eq!(correct["checked"].as_u64(), Some(3 * n), "{correct:#}");
    assert_eq!((correct["mistakes"].as_u64(), &correct["ok"]), (Some(0), &Value::Bool(true)));
    assert_eq!(correct["scored"], false);
    let output = results[0]["output"].as_str().unwrap();
    assert!(
        output.contains(&format!(
            "Report (not scored): handin/report/report.md: {} numbers checked; every one follows from the data.",
            3 * n
        )),
        "{output}"
    );
    // V1 wrong: one finding, on V1, at its line (the table's second row, line 6).
    let wrong = report(&results[1]);
    assert_eq!(wrong["mistakes"].as_u64(), Some(1), "{wrong:#}");
    assert_eq!(
        (&wrong["findings"][0]["item"], &wrong["findings"][0]["line"]),
        (&"V1".into(), &6.into())
    );
    assert_eq!(wrong["ok"], false);
    // Nothing in the notation: nothing checked, said so; nothing derived for it.
    let empty = report(&results[2]);
    assert_eq!(
        (empty["report"].as_str(), empty["checked"].as_u64()),
        (Some("report/report.tex"), Some(0))
    );
    assert!(empty["summary"].as_str().unwrap().contains("no number was checked"), "{empty:#}");
    // vertices() loops: the vertex table is not checked, its part named; the grade is as above.
    let looped = report(&results[3]);
    assert_eq!(looped["checked"].as_u64(), Some(0), "{looped:#}");
    let not_checked = looped["not_checked"].as_array().unwrap();
    assert!(not_checked.iter().any(|m| m.as_str().unwrap().starts_with("a1.t1")), "{looped:#}");
    let summary = looped["summary"].as_str().unwrap();
    assert!(summary.contains("were read, but their parts could not be derived"), "{summary}");
    // From --reports: checked as one inside would be, V0 wrong.
    let given = report(&results[4]);
    assert_eq!(given["report"], "report-20260005.md", "{given:#}");
    assert_eq!(given["findings"][0]["item"], "V0", "{given:#}");
    // No report: null, and the feedback says where one would be found.
    assert!(results[5]["cg"]["report"].is_null());
    let feedback = std::fs::read_to_string(out.join("feedback/20260007/feedback-en.md")).unwrap();
    assert!(feedback.contains("The submission holds no report (report/report.md"), "{feedback}");
    let feedback = std::fs::read_to_string(out.join("feedback/20260002/feedback-ja.md")).unwrap();
    assert!(feedback.contains("## レポートの数値（点数には入りません）"), "{feedback}");
    assert!(feedback.contains("6 行目: V1:"), "{feedback}");

    // The class table and the summary.
    let csv = std::fs::read_to_string(out.join("class.csv")).unwrap();
    // UTF-8 after the byte-order mark that Excel on Japanese Windows needs.
    let csv = csv.strip_prefix('\u{feff}').expect("class.csv begins with a byte-order mark");
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0],
        "student,submission,a1,a2,a3,a4,s,score,max_score,report,report_checked,report_mistakes,report_not_checked,flag"
    );
    assert_eq!(lines.len(), 8, "{csv}");
    for r in &results {
        let a = &r["cg"]["assignments"];
        let row = format!(
            "{},{},{},{},{},{},{},{},{}",
            r["cg"]["student"].as_str().unwrap(),
            r["cg"]["submission"].as_str().unwrap(),
            a["a1"]["score"],
            a["a2"]["score"],
            a["a3"]["score"],
            a["a4"]["score"],
            a["s"]["score"],
            r["score"],
            r["max_score"]
        )
        .replace(".0,", ",");
        let rep = &r["cg"]["report"];
        let count = |k: &str| rep[k].as_u64().map(|n| n.to_string()).unwrap_or_default();
        // Nobody here is flagged: the flag column is empty.
        let parts = rep["not_checked"].as_array().map(|a| a.len().to_string()).unwrap_or_default();
        let row = format!(
            "{},{},{},{},{parts},",
            row.trim_end_matches(".0"),
            rep["report"].as_str().unwrap_or(""),
            count("checked"),
            count("mistakes")
        );
        assert!(lines.contains(&row.as_str()), "{row} not in\n{csv}");
    }
    assert!(
        lines.contains(&"20260003,03-a2-syntax,31,0,13,9,22,75,89,report/report.tex,0,0,0,"),
        "{csv}"
    );
    assert!(lines.iter().any(|l| l.starts_with(",06-slip.zip,,,,,,0,,,,,,")), "{csv}");
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    // Most failed first: a1.t2.outward and a1.t2.winding (the loop and the reversed face),
    // then the checks one submission failed; the refused zip is listed.
    let rows: Vec<&str> =
        md.lines().filter(|l| l.starts_with("| a") || l.starts_with("| s")).collect();
    assert!(rows[0].starts_with("| a1.t2.outward:") && rows[0].ends_with("| 2 | 6 |"), "{md}");
    assert!(rows[1].starts_with("| a1.t2.winding:") && rows[1].ends_with("| 2 | 6 |"), "{md}");
    assert!(rows[2].ends_with("| 1 | 6 |"), "{md}");
    assert!(rows.last().unwrap().ends_with("| 0 | 6 |"), "{md}");
    assert!(md.contains("06-slip.zip"), "{md}");
    // The reports: four of the six graded hold one, one right; V1 the item most often wrong.
    assert!(
        md.contains(
            "5 of the 6 graded submissions hold a report; 5 were read. In 0, every part was checked"
        ),
        "{md}"
    );
    // The correct one's numbers all follow, but it has only the vertex table: listed, with the
    // notes on the tables it lacks (it was counted as a whole report).
    let correct_line = md.lines().find(|l| l.starts_with("- `01-correct.zip`")).unwrap_or("");
    assert!(
        correct_line.contains("every one follows from the data.")
            && correct_line.contains(" notes)"),
        "{md}"
    );
    assert!(md.contains("| `V0` | 1 |\n| `V1` | 1 |"), "{md}");
    // The files of --reports that no one's report was.
    assert!(md.contains("## Files of --reports not used"), "{md}");
    assert!(md.contains("- `20269999.md`\n- `notes.txt`"), "{md}");
    // Each student's feedback, in both languages: the reversed face's failed checks.
    for (lang, head) in [("ja", "# 採点結果"), ("en", "# Grading results")] {
        let path = out.join(format!("feedback/20260002/feedback-{lang}.md"));
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.starts_with(head) && text.contains("### a1.t2.winding"), "{text}");
    }

    // Resuming: a second run keeps every result, byte for byte.
    let before: Vec<(String, Vec<u8>)> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .filter(|e| e.path().is_file())
        .map(|e| (e.file_name().to_string_lossy().into_owned(), std::fs::read(e.path()).unwrap()))
        .collect();
    let again = cg_grade::grade(&options, cg_sandbox::launch, &|_| {}).unwrap();
    assert!(again.iter().all(|g| g.skipped), "{again:?}");
    for (name, bytes) in before {
        assert_eq!(std::fs::read(out.join(&name)).unwrap(), bytes, "{name} changed");
    }

    // A report corrected is checked again; the other results are kept.
    std::fs::write(&report_02, vertex_rows("20260002", None)).unwrap();
    let again = cg_grade::grade(&options, cg_sandbox::launch, &|_| {}).unwrap();
    let regraded: Vec<&str> =
        again.iter().filter(|g| !g.skipped).map(|g| g.name.as_str()).collect();
    assert_eq!(regraded, ["20260002"]);
    let fixed = read(&out.join("20260002.json"));
    assert_eq!(fixed["cg"]["report"]["mistakes"].as_u64(), Some(0), "{fixed:#}");
    assert_eq!(fixed["score"], results[1]["score"]);
}
