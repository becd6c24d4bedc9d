//! Submissions refused before any build — a zip slip, a symlink in a zip, an oversized entry, no
//! `exercises/` (naming what there is), a `.7z`, a bad student number, a submission that is a
//! symlink, a link inside a folder, `#[path]` or `option_env!` reaching outside the files — each
//! get a result that says why, a row in the class table and a line in the summary, and a second
//! run keeps them. No kit build is needed, so this runs in seconds.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Duration;

use cg_core::lang::Lang;
use cg_grade::{Config, Options};
use cg_sandbox::{Isolation, Job, Launch, Limits, SandboxError};
use serde_json::Value;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..").canonicalize().unwrap()
}

/// Never called: nothing here gets as far as running.
fn no_runs(job: &Job, _: &Limits, _: Isolation) -> Result<Launch, SandboxError> {
    panic!("a refused submission was run: {job:?}")
}

fn zip(path: &Path, files: &[(&str, &[u8])], symlink: Option<(&str, &str)>) {
    let mut z = zip::ZipWriter::new(std::fs::File::create(path).unwrap());
    let o = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    for (name, bytes) in files {
        z.start_file(*name, o).unwrap();
        z.write_all(bytes).unwrap();
    }
    if let Some((name, target)) = symlink {
        z.add_symlink(name, target, o).unwrap();
    }
    z.finish().unwrap();
}

#[test]
fn refused_submissions_say_why_and_are_kept() {
    if !root().join("solutions/src/a1.rs").exists() {
        eprintln!("no solutions/ (a student handout): grading is tested in the kit's repository");
        return;
    }
    let base = Path::new(env!("CARGO_TARGET_TMPDIR")).join("grade-refused");
    let _ = std::fs::remove_dir_all(&base);
    let subs = base.join("submissions");
    let out = base.join("out");
    std::fs::create_dir_all(&subs).unwrap();
    let toml = b"student = \"20269999\"\ntable = 1\n";
    zip(&subs.join("slip.zip"), &[("exercises/student.toml", toml), ("/etc/cron.d/x", b"x")], None);
    zip(
        &subs.join("link.zip"),
        &[("exercises/student.toml", toml)],
        Some(("exercises/src/a1.rs", "/etc/passwd")),
    );
    let big = vec![b' '; (1 << 20) + 10];
    zip(
        &subs.join("big.zip"),
        &[("exercises/student.toml", toml), ("exercises/src/a1.rs", &big)],
        None,
    );
    zip(&subs.join("empty.zip"), &[("readme.txt", b"hi")], None);
    // A 7-Zip archive handed in for a zip: said to be one.
    std::fs::write(subs.join("taro.7z"), b"7z\xbc\xaf\x27\x1c").unwrap();
    // One entry over the limit: refused from the zip's end record, with the count.
    let names: Vec<String> =
        (0..=cg_grade::submission::MAX_ZIP_ENTRIES).map(|i| format!("x/{i}.txt")).collect();
    let many: Vec<(&str, &[u8])> = names.iter().map(|n| (n.as_str(), &b""[..])).collect();
    zip(&subs.join("many.zip"), &many, None);
    std::fs::write(subs.join("notzip.zip"), b"PK but not really").unwrap();
    std::fs::create_dir_all(subs.join("badnumber/exercises/src")).unwrap();
    std::fs::write(subs.join("badnumber/exercises/student.toml"), "student = 1234\n").unwrap();
    std::os::unix::fs::symlink(root().join("solutions"), subs.join("sneaky")).unwrap();
    // Compile-time reads outside the submission (issue 14): the kit's own solutions compiled in
    // through #[path], the grader's environment leaked into the feedback, and exercises/src a
    // link to the kit's solutions. Each would score or leak without the refusal.
    let solutions_a1 = root().join("solutions/src/a1.rs");
    std::fs::create_dir_all(subs.join("pathmod/exercises/src")).unwrap();
    std::fs::write(subs.join("pathmod/exercises/student.toml"), toml).unwrap();
    std::fs::write(
        subs.join("pathmod/exercises/src/a1.rs"),
        format!("#[path = \"{}\"]\nmod r;\npub use r::*;\n", solutions_a1.display()),
    )
    .unwrap();
    zip(
        &subs.join("envleak.zip"),
        &[
            ("exercises/student.toml", toml),
            ("exercises/src/a2.rs", b"pub const H: Option<&str> = option_env!(\"HOME\");\n"),
        ],
        None,
    );
    std::fs::create_dir_all(subs.join("srclink/exercises")).unwrap();
    std::fs::write(subs.join("srclink/exercises/student.toml"), toml).unwrap();
    std::os::unix::fs::symlink(root().join("solutions/src"), subs.join("srclink/exercises/src"))
        .unwrap();

    let options = Options {
        kit: root(),
        submissions: subs.clone(),
        out: out.clone(),
        config: Config::default(),
        config_text: String::new(),
        jobs: 4,
        limits: Limits { wall: Duration::from_secs(5), ..Limits::default() },
        build_limit: Duration::from_secs(60),
        isolation: Isolation::Limits,
        lang: Lang::En,
        roster: None,
        reports: None,
    };
    let graded = cg_grade::grade(&options, no_runs, &|_| {}).unwrap();
    assert_eq!(graded.len(), 12);
    let why = |name: &str| -> String {
        let v: Value = serde_json::from_str(
            &std::fs::read_to_string(out.join(format!("_{name}.json"))).unwrap(),
        )
        .unwrap();
        assert_eq!(v["score"], 0.0, "{name}");
        assert!(v.get("max_score").is_none(), "{name}");
        assert_eq!(v["tests"], serde_json::json!([]), "{name}");
        assert!(v["output"].as_str().unwrap().contains("refused"), "{name}");
        v["cg"]["refused"].as_str().unwrap().to_owned()
    };
    assert!(why("slip.zip").contains("/etc/cron.d/x") && why("slip.zip").contains("unsafe path"));
    assert!(why("link.zip").contains("symbolic link"), "{}", why("link.zip"));
    assert!(why("big.zip").contains("too big"), "{}", why("big.zip"));
    assert!(why("empty.zip").contains("no exercises/"), "{}", why("empty.zip"));
    // What it holds is named.
    assert!(why("empty.zip").contains("; it holds readme.txt: "), "{}", why("empty.zip"));
    assert!(why("taro.7z").contains("taro.7z is a .7z archive, not a zip"), "{}", why("taro.7z"));
    assert!(why("many.zip").contains("too many entries in the zip (10001, at most 10000)"));
    assert!(why("notzip.zip").contains("not a readable zip"), "{}", why("notzip.zip"));
    assert!(why("badnumber").contains("student.toml"), "{}", why("badnumber"));
    assert!(why("sneaky").contains("symbolic link"), "{}", why("sneaky"));
    let pathmod = why("pathmod");
    assert!(pathmod.contains("exercises/src/a1.rs:1: #[path]"), "{pathmod}");
    let envleak = why("envleak.zip");
    assert!(envleak.contains("exercises/src/a2.rs:1: option_env!"), "{envleak}");
    assert!(why("srclink").contains("exercises/src is a symbolic link"), "{}", why("srclink"));
    assert!(!out.join(".work/slot-0").exists(), "nothing to build, no kit copy");

    let csv = std::fs::read_to_string(out.join("class.csv")).unwrap();
    assert!(csv.starts_with("\u{feff}student,submission,"), "{csv}");
    assert_eq!(csv.lines().count(), 13, "{csv}");
    // A refused entry's flag says so (its empty scores read as a graded 0 when sorted).
    assert!(
        csv.contains("\n,slip.zip,,,,,,0,,,,,,refused: zip entry /etc/cron.d/x has an unsafe path"),
        "{csv}"
    );
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(md.contains("submissions: 12") && md.contains("## Not graded"), "{md}");
    assert_eq!(md.matches("\n- ").count(), 12, "{md}");
    // Graded with limits only: the summary says so.
    assert!(md.contains("## Graded without a sandbox"), "{md}");

    let before = std::fs::read(out.join("_slip.zip.json")).unwrap();
    let again = cg_grade::grade(&options, no_runs, &|_| {}).unwrap();
    assert!(again.iter().all(|g| g.skipped));
    assert_eq!(std::fs::read(out.join("_slip.zip.json")).unwrap(), before);
}

/// A refused entry on the roster is still the roster's student: its result is
/// `<student>.json` (an earlier graded one would stand beside `_<entry>.json`), and class.csv
/// and summary.md name them (they said nothing, `"student": null`, and `?`); its line says it was
/// refused; a submission without student.toml is told how to make one. An empty folder of
/// submissions is an error, not empty results and exit 0.
#[test]
fn a_refused_entry_keeps_its_roster_student_and_an_empty_folder_is_said() {
    if !root().join("solutions/src/a1.rs").exists() {
        eprintln!("no solutions/ (a student handout): grading is tested in the kit's repository");
        return;
    }
    let base = Path::new(env!("CARGO_TARGET_TMPDIR")).join("grade-refused-roster");
    let _ = std::fs::remove_dir_all(&base);
    let subs = base.join("submissions");
    let out = base.join("out");
    std::fs::create_dir_all(subs.join("nostudent/exercises/src")).unwrap();
    std::fs::write(subs.join("nostudent/exercises/src/a1.rs"), "// mine\n").unwrap();
    let roster =
        cg_grade::roster::Roster::parse("student,name,entry\n20260001,山田 太郎,nostudent\n")
            .unwrap();
    let mut options = Options {
        kit: root(),
        submissions: subs.clone(),
        out: out.clone(),
        config: Config::default(),
        config_text: String::new(),
        jobs: 1,
        limits: Limits::default(),
        build_limit: Duration::from_secs(60),
        isolation: Isolation::Limits,
        lang: Lang::En,
        roster: Some(roster),
        reports: None,
    };
    let graded = cg_grade::grade(&options, no_runs, &|_| {}).unwrap();
    assert_eq!(graded.len(), 1);
    let problem = graded[0].problem.as_ref().expect("a refused entry has a problem");
    assert!(problem.en.starts_with("refused: student.toml (the record"), "{}", problem.en);
    assert!(
        problem.en.contains("cargo run --release -- assignment --student 12345678 --save"),
        "{}",
        problem.en
    );
    assert!(problem.ja.starts_with("受け付けられません: student.toml"), "{}", problem.ja);
    let v: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("20260001.json")).unwrap()).unwrap();
    assert_eq!(v["cg"]["student"], "20260001", "{v:#}");
    let csv = std::fs::read_to_string(out.join("class.csv")).unwrap();
    assert!(csv.contains("\n20260001,nostudent,"), "{csv}");
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert!(md.contains("- `nostudent` (`20260001`): `student.toml (the record"), "{md}");

    let empty = base.join("empty");
    std::fs::create_dir_all(&empty).unwrap();
    std::fs::write(empty.join(".DS_Store"), b"").unwrap();
    options.submissions = empty;
    options.roster = None;
    let e = cg_grade::grade(&options, no_runs, &|_| {}).unwrap_err();
    assert!(e.message(Lang::En).contains("holds no submission"), "{}", e.message(Lang::En));
    assert!(e.message(Lang::Ja).contains("提出物がありません"), "{}", e.message(Lang::Ja));
}
