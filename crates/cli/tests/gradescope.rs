//! Gradescope: `cg autograder` writes the zip Gradescope runs, and its `run_autograder`, run in
//! a fake `/autograder` tree (`AUTOGRADER_ROOT`) with the real `cg grade-one`, writes a
//! `results.json` in Gradescope's format — score 0 and the reason for a submission that is
//! refused (no `exercises/`), so no build is needed.

use std::io::Read as _;
use std::process::Command;

use serde_json::Value;

mod common;
use common::{root, scratch};

#[test]
fn the_autograder_zip_and_its_run_grade_a_refused_submission_to_zero_with_the_reason() {
    let dir = scratch("gradescope", "run");
    let zip_path = dir.join("autograder.zip");
    let o =
        common::cg(&root(), &["autograder", "--out", zip_path.to_str().unwrap(), "--lang", "en"]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut z = zip::ZipArchive::new(std::fs::File::open(&zip_path).unwrap()).unwrap();
    let names: Vec<String> = z.file_names().map(|n| n.unwrap().into_owned()).collect();
    for needed in [
        "setup.sh",
        "run_autograder",
        "solutions/Cargo.toml",
        "Cargo.lock",
        "crates/grade/src/lib.rs",
    ] {
        assert!(names.iter().any(|n| n == needed), "{needed} missing");
    }
    assert!(!names.iter().any(|n| n.starts_with("target/") || n.starts_with(".git/")));
    let mut script = String::new();
    z.by_name("run_autograder").unwrap().read_to_string(&mut script).unwrap();

    // The fake /autograder: the kit as its source, a submission with no exercises/.
    let fake = dir.join("autograder");
    std::fs::create_dir_all(fake.join("submission")).unwrap();
    std::fs::write(fake.join("submission/README.txt"), "my homework").unwrap();
    std::os::unix::fs::symlink(root(), fake.join("source")).unwrap();
    std::fs::write(fake.join("run_autograder"), &script).unwrap();
    let o = Command::new("bash")
        .arg(fake.join("run_autograder"))
        .env("AUTOGRADER_ROOT", &fake)
        .env("CG_BIN", env!("CARGO_BIN_EXE_cg"))
        .env("CG_UNSAFE_NO_SANDBOX", "1")
        .env("CG_LANG", "en")
        .output()
        .unwrap();
    let log =
        format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "{log}");
    let text = std::fs::read_to_string(fake.join("results/results.json")).unwrap();
    let r: Value = serde_json::from_str(&text).unwrap();
    assert_eq!(cg_grade::gradescope::problems(&r), Vec::<String>::new(), "{text}");
    assert_eq!(r["score"].as_f64(), Some(0.0), "{text}");
    assert_eq!(r["output_format"], "md");
    assert!(r["execution_time"].is_u64());
    let output = r["output"].as_str().unwrap();
    assert!(output.contains("refused") && output.contains("exercises/"), "{output}\n{log}");
    assert!(r["extra_data"]["cg"]["refused"].as_str().unwrap().contains("exercises/"));
    // The kit's usual per-student files beside it.
    assert!(fake.join("results/_submission.json").exists(), "{log}");
    assert!(fake.join("results/feedback/_submission/feedback-en.md").exists());
}
