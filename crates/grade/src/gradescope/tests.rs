//! Gradescope's `results.json` against the specification's fields, and `run_autograder`'s
//! fallback when `cg` cannot grade.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::time::Duration;

use cg_core::lang::Lang;
use cg_sandbox::Isolation;
use serde_json::{Value, json};

use super::*;
use crate::result::{Facts, Meta, build};
use crate::{AssignmentRun, Config, Text};

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cg-gradescope-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// A graded submission in memory: a1 with a passed and a failed check (its message with
/// backticks), a2 replaced for a compile error, a3's worker dead.
fn kit_result() -> Value {
    let mut runs = BTreeMap::new();
    runs.insert(
        "a1".to_owned(),
        AssignmentRun::Report(json!({"assignment": "a1", "checks": [
            {"id": "a1.t1.count", "title": {"ja": "頂点の数", "en": "vertex count"}, "status": "pass"},
            {"id": "a1.t2.normal", "title": {"ja": "法線", "en": "normals"}, "status": "fail",
             "expected": "(0, 0, 1)", "actual": "```</pre><script>", "hint": "cross product"},
        ]})),
    );
    runs.insert(
        "a2".to_owned(),
        AssignmentRun::Report(json!({"assignment": "a2", "checks": [
            {"id": "a2.t1.faces", "title": "faces", "status": "not_done", "message": "a2.t1"},
        ]})),
    );
    runs.insert(
        "a3".to_owned(),
        AssignmentRun::Died { how: Text::new("落ちました", "it died"), stderr: "boom".into() },
    );
    let mut baseline = BTreeMap::new();
    baseline.insert("a3".to_owned(), vec![("a3.t1.push".to_owned(), Text::new("push", "push"))]);
    let mut compile_errors = BTreeMap::new();
    compile_errors.insert("a2".to_owned(), vec!["exercises/src/a2.rs:3: expected `;`".to_owned()]);
    let facts = Facts {
        runs,
        baseline,
        compile_errors,
        build: Some(Duration::from_secs(3)),
        run: Some(Duration::from_millis(400)),
        ..Facts::default()
    };
    let meta = Meta {
        entry: "taro.zip",
        student: Some("20260001"),
        table: Some(cg_harness::TableVersion::V1),
        hash: "h",
        isolation: Isolation::Bubblewrap,
        same_number: &[],
        roster: None,
        total: Duration::from_secs(4),
    };
    let config = Config::parse("default = 1\n[points]\n\"a1.t2\" = 2.5\n").unwrap();
    build(&meta, &facts, &config, Lang::En)
}

#[test]
fn a_graded_result_follows_the_specification() {
    let kit = kit_result();
    let r = results_json(&kit, Duration::from_millis(4200));
    assert_eq!(problems(&r), Vec::<String>::new(), "{r:#}");
    // Required and typed keys at the top.
    assert_eq!(r["score"], json!(1.0));
    assert_eq!(r["execution_time"], json!(5));
    assert_eq!(r["output_format"], "md");
    assert!(VISIBILITIES.contains(&r["visibility"].as_str().unwrap()));
    assert!(VISIBILITIES.contains(&r["stdout_visibility"].as_str().unwrap()));
    assert!(r["output"].as_str().unwrap().starts_with("**1 / 5.5**"), "{}", r["output"]);
    // The kit's own data in extra_data, none of it at the top.
    assert_eq!(r["extra_data"]["max_score"], json!(5.5));
    assert_eq!(r["extra_data"]["cg"]["student"], "20260001");
    assert!(r.get("cg").is_none() && r.get("max_score").is_none());
    let tests = r["tests"].as_array().unwrap();
    let ids: Vec<&str> = tests.iter().map(|t| t["number"].as_str().unwrap()).collect();
    assert_eq!(ids, ["a1.t1.count", "a1.t2.normal", "a2.t1.faces", "a3.t1.push"]);
    let mut sum = 0.0;
    let mut max = 0.0;
    for t in tests {
        for k in [
            "score",
            "max_score",
            "status",
            "name",
            "number",
            "output",
            "output_format",
            "tags",
            "visibility",
        ] {
            assert!(!t[k].is_null(), "{k} missing in {t}");
        }
        assert!(t["score"].as_f64().unwrap() <= t["max_score"].as_f64().unwrap());
        assert_eq!(t["output_format"], "md");
        assert_eq!(t["visibility"], visibility(t["number"].as_str().unwrap()));
        assert_eq!(t["tags"][0].as_str(), t["number"].as_str().unwrap().split('.').next());
        sum += t["score"].as_f64().unwrap();
        max += t["max_score"].as_f64().unwrap();
    }
    assert_eq!((sum, max), (1.0, 5.5));
    assert_eq!(tests[0]["status"], "passed");
    assert_eq!(tests[0]["output"], "");
    // A failure's text is fenced: the student's backticks cannot end the block.
    let normal = tests[1]["output"].as_str().unwrap();
    assert!(normal.starts_with("````text\n") && normal.ends_with("\n````"), "{normal}");
    assert!(normal.contains("</pre><script>"));
    assert!(tests[2]["output"].as_str().unwrap().contains("compile errors"));
    assert!(tests[3]["output"].as_str().unwrap().contains("it died"));
}

#[test]
fn problems_are_found() {
    let kit = kit_result();
    let mut r = results_json(&kit, Duration::ZERO);
    r["visibility"] = json!("public");
    r["tests"][0]["score"] = json!(9.0);
    r["tests"][1]["status"] = json!("ok");
    r["execution_time"] = json!(1.5);
    r["cg"] = json!({});
    let found = problems(&r);
    for needle in [
        "top: visibility",
        "test 0: score 9 outside",
        "test 1: status",
        "execution_time",
        "unknown key cg",
        "is not the tests' sum",
    ] {
        assert!(found.iter().any(|p| p.contains(needle)), "{needle} not in {found:?}");
    }
}

#[test]
fn a_failure_is_score_zero_with_the_reason() {
    let r = failure_json("exercises/ not found", Duration::from_millis(10));
    assert_eq!(problems(&r), Vec::<String>::new());
    assert_eq!(r["score"], json!(0.0));
    assert!(r["output"].as_str().unwrap().contains("exercises/ not found"));
}

#[test]
fn fences_outlast_the_text() {
    assert_eq!(fenced(""), "");
    assert_eq!(fenced("a\n"), "```text\na\n```");
    assert_eq!(fenced("x ````` y"), "``````text\nx ````` y\n``````");
}

#[test]
fn the_zip_holds_the_scripts_and_the_kit_with_solutions() {
    let root = temp("zip");
    let kit = root.join("kit");
    for (f, text) in [
        ("Cargo.toml", "[workspace]\n"),
        ("solutions/Cargo.toml", "[package]\n"),
        ("exercises/src/a1.rs", "todo!()\n"),
        ("exercises/student.toml", "student = \"1\"\n"),
        ("target/release/cg", "binary"),
        ("scripts/test.sh", "#!/bin/sh\n"),
        // What the kit's .gitignore names at its top stays out of a copy without git: a
        // grading's results.
        (".gitignore", "/target\n/results/\n"),
        ("results/12345678.json", "{}"),
    ] {
        std::fs::create_dir_all(kit.join(f).parent().unwrap()).unwrap();
        std::fs::write(kit.join(f), text).unwrap();
    }
    // A link back up is not followed (it copied the kit into itself until the names ran out).
    std::os::unix::fs::symlink("..", kit.join("scripts/loop")).unwrap();
    // An old autograder (an empty zip) is replaced; a file that is no zip, or a folder, is not.
    let out = kit.join("autograder.zip");
    std::fs::write(&out, b"PK\x05\x06\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0\0").unwrap();
    for (not_zip, said) in [
        (kit.join("scripts/test.sh"), "is a file that is not a zip"),
        (kit.join("scripts"), "is a folder"),
        (root.join("new/"), "is a folder"),
    ] {
        let e = package::write_zip(&kit, &not_zip, Lang::En).unwrap_err();
        assert!(e.en.contains(said), "{}: {}", not_zip.display(), e.en);
    }
    assert_eq!(std::fs::read_to_string(kit.join("scripts/test.sh")).unwrap(), "#!/bin/sh\n");
    package::write_zip(&kit, &out, Lang::En).unwrap();
    let mut z = zip::ZipArchive::new(std::fs::File::open(&out).unwrap()).unwrap();
    let mut names: Vec<String> = z.file_names().map(|n| n.unwrap().into_owned()).collect();
    names.sort();
    assert_eq!(
        names,
        [
            ".gitignore",
            "Cargo.toml",
            "exercises/src/a1.rs",
            "run_autograder",
            "scripts/test.sh",
            "setup.sh",
            "solutions/Cargo.toml",
        ]
    );
    for name in ["run_autograder", "setup.sh"] {
        assert_eq!(z.by_name(name).unwrap().unix_mode().unwrap() & 0o777, 0o755, "{name}");
    }
    let mut script = String::new();
    std::io::Read::read_to_string(&mut z.by_name("run_autograder").unwrap(), &mut script).unwrap();
    assert!(script.contains("grade-one \"$ROOT/submission\" --out \"$RESULTS\""));
    assert!(script.contains("${CG_LANG:-en}"));
    // Both scripts parse as bash.
    for (name, text) in [("setup.sh", package::SETUP_SH.to_owned()), ("run_autograder", script)] {
        let path = root.join(name);
        std::fs::write(&path, text).unwrap();
        let status = std::process::Command::new("bash").arg("-n").arg(&path).status().unwrap();
        assert!(status.success(), "{name} does not parse");
    }
    let _ = std::fs::remove_dir_all(&root);
}

/// `setup.sh` builds `cg` with what grading needs (the reference, the instructors' commands) and
/// without the GPU renderer, whose tree (wgpu and the rest) would only lengthen every
/// autograder's setup: cg-cli's default features are switched off, and every feature named is
/// one of cg-cli's.
#[test]
fn setup_builds_cg_without_the_gpu_renderer() {
    let line = package::SETUP_SH
        .lines()
        .find(|l| l.starts_with("cargo build"))
        .expect("setup.sh builds cg");
    let words: Vec<&str> = line.split_whitespace().collect();
    assert!(words.contains(&"-p") && words.contains(&"cg-cli"), "{line}");
    assert!(words.contains(&"--no-default-features"), "{line}");
    let at = words.iter().position(|w| *w == "--features").expect(line);
    let features: Vec<&str> = words[at + 1].split(',').collect();
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR")).join("../cli/Cargo.toml");
    let manifest: toml::Table = std::fs::read_to_string(manifest).unwrap().parse().unwrap();
    let known = manifest["features"].as_table().unwrap();
    for feature in &features {
        assert!(known.contains_key(*feature), "cg-cli has no feature {feature}: {line}");
    }
    for needed in ["reference", "instructor"] {
        assert!(features.contains(&needed), "grading needs {needed}: {line}");
    }
    assert!(!features.contains(&"gpu"), "{line}");
}

/// Runs `run_autograder` in the fake tree `root` with `cg` at `cg`.
fn run_autograder(root: &Path, cg: &Path) -> Value {
    let script = root.join("source/run_autograder");
    std::fs::create_dir_all(script.parent().unwrap()).unwrap();
    std::fs::write(&script, package::run_autograder(Lang::En)).unwrap();
    let status = std::process::Command::new("bash")
        .arg(&script)
        .env("AUTOGRADER_ROOT", root)
        .env("CG_BIN", cg)
        .status()
        .unwrap();
    assert!(status.success(), "run_autograder always exits 0");
    let text = std::fs::read_to_string(root.join("results/results.json")).unwrap();
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

#[test]
fn run_autograder_writes_a_result_even_when_cg_cannot_start() {
    let root = temp("fallback");
    std::fs::create_dir_all(root.join("submission")).unwrap();
    // A `cg` that fails with quotes, a backslash, a tab and a percent sign in its message.
    let cg = root.join("fake-cg");
    std::fs::write(&cg, "#!/bin/sh\nprintf 'no \"kit\" here \\\\ 100%%\\tnow\\n' >&2\nexit 3\n")
        .unwrap();
    let mut perm = std::fs::metadata(&cg).unwrap().permissions();
    std::os::unix::fs::PermissionsExt::set_mode(&mut perm, 0o755);
    std::fs::set_permissions(&cg, perm).unwrap();
    let r = run_autograder(&root, &cg);
    assert_eq!(problems(&r), Vec::<String>::new(), "{r:#}");
    assert_eq!(r["score"], json!(0.0));
    let output = r["output"].as_str().unwrap();
    assert!(output.contains("exit 3") && output.contains("no \"kit\" here \\ 100%"), "{output}");
    // Japanese output cut by its last 3000 bytes inside a character, at each of the three
    // places a character of three bytes can be cut: still UTF-8, so still JSON.
    for extra in 0..3 {
        let line = "採点できません: 行\n";
        let script = format!(
            "#!/bin/sh\ni=0\nwhile [ $i -lt 300 ]; do printf '{line}'; i=$((i+1)); done\nprintf '{}'\nexit 101\n",
            "x".repeat(extra)
        );
        std::fs::write(&cg, script).unwrap();
        let r = run_autograder(&root, &cg);
        let output = r["output"].as_str().unwrap();
        assert!(output.contains("exit 101") && output.contains("採点できません: 行"), "{output}");
    }
    // Not even a program.
    let r = run_autograder(&root, &root.join("missing"));
    assert_eq!(r["score"], json!(0.0));
    assert!(r["output"].as_str().unwrap().contains("exit 127"), "{r}");
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn an_upload_is_read_as_a_tree_or_as_loose_files() {
    let root = temp("upload");
    let put = |rel: &str, text: &str| {
        let path = root.join(rel);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    };
    // Loose files, as Gradescope's upload form leaves them.
    put("loose/a1.rs", "// a1");
    put("loose/s.rs", "// s");
    put("loose/student.toml", "student = \"20260001\"\n");
    let files = crate::moodle::input::Entry::single(&root.join("loose")).read().unwrap();
    assert_eq!(files.modules.keys().collect::<Vec<_>>(), ["a1", "s"]);
    assert!(files.student_toml.is_some());
    // An exercises/ tree a folder down.
    put("tree/kit/exercises/src/a2.rs", "// a2");
    put("tree/kit/exercises/student.toml", "student = \"20260001\"\n");
    let entry = crate::moodle::input::Entry::single(&root.join("tree"));
    assert_eq!(entry.name, "tree");
    assert_eq!(entry.read().unwrap().modules.keys().collect::<Vec<_>>(), ["a2"]);
    // Nothing of the kind: refused with the reason.
    put("none/README.txt", "hi");
    let why = crate::moodle::input::Entry::single(&root.join("none")).read().unwrap_err();
    assert!(why.en.contains("exercises/"), "{}", why.en);
    let _ = std::fs::remove_dir_all(&root);
}
