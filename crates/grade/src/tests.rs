use super::*;

#[test]
fn a_changed_copy_of_the_kit_is_noticed_and_the_students_files_are_not_a_change() {
    let kit = std::env::temp_dir().join(format!("cg-grade-slot-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&kit);
    std::fs::create_dir_all(kit.join("exercises/src")).unwrap();
    std::fs::create_dir_all(kit.join("crates/a1/src")).unwrap();
    std::fs::write(kit.join("crates/a1/src/checks.rs"), "fn check() -> bool { x == y }").unwrap();
    std::fs::write(kit.join("exercises/src/a1.rs"), "todo!()").unwrap();
    let pristine = slot_content(&kit).unwrap();
    // What each submission writes is not a change of the kit.
    std::fs::write(kit.join("exercises/src/a1.rs"), "// the next student's").unwrap();
    std::fs::write(kit.join("exercises/student.toml"), "student = \"1\"").unwrap();
    assert_eq!(slot_content(&kit).unwrap(), pristine);
    // A run that patched a check (the attack without bubblewrap), added a file or a link:
    // each is noticed.
    std::fs::write(kit.join("crates/a1/src/checks.rs"), "fn check() -> bool { true }").unwrap();
    assert_ne!(slot_content(&kit).unwrap(), pristine);
    std::fs::write(kit.join("crates/a1/src/checks.rs"), "fn check() -> bool { x == y }").unwrap();
    assert_eq!(slot_content(&kit).unwrap(), pristine);
    std::fs::write(kit.join("exercises/src/lib.rs"), "mod evil;").unwrap();
    assert_ne!(slot_content(&kit).unwrap(), pristine);
    std::fs::remove_file(kit.join("exercises/src/lib.rs")).unwrap();
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink("/etc/passwd", kit.join("crates/a1/src/link.rs")).unwrap();
        assert_ne!(slot_content(&kit).unwrap(), pristine);
    }
    let _ = std::fs::remove_dir_all(&kit);
}

#[test]
fn grading_without_bubblewrap_is_refused_unless_asked_for() {
    assert_eq!(require_isolation(Isolation::Bubblewrap, false), Ok(()));
    let why = require_isolation(Isolation::Limits, false).unwrap_err();
    assert!(why.en.contains("apt-get install bubblewrap"), "{}", why.en);
    assert!(why.en.contains("--unsafe-no-sandbox") && why.ja.contains("--unsafe-no-sandbox"));
    assert_eq!(require_isolation(Isolation::Limits, true), Ok(()));
}

/// Options for [`collect`] alone, of the submissions in `root/subs`.
fn collect_options(root: &Path, roster: Option<roster::Roster>) -> Options {
    test_options(root, &root.join("subs"), roster)
}

#[test]
fn the_roster_binds_entries_and_flags_the_rest() {
    let root = std::env::temp_dir().join(format!("cg-grade-roster-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let subs = root.join("subs");
    // "a" claims another student's number; the Moodle folder is bound by its participant
    // ID; "c" is not on the roster.
    for (entry, number) in [
        ("a", "20260001"),
        ("Taro Yamada_777_assignsubmission_file_", "20260002"),
        ("c", "20260004"),
    ] {
        let ex = subs.join(entry).join("exercises");
        std::fs::create_dir_all(ex.join("src")).unwrap();
        std::fs::write(ex.join("student.toml"), format!("student = \"{number}\"\n")).unwrap();
    }
    let roster = roster::Roster::parse(
        "student,name,entry\n20260009,A,a\n20260002,山田 太郎,777\n20260003,Absent,z.zip\n",
    )
    .unwrap();
    let options = collect_options(&root, Some(roster));
    let pending = collect(&options, "kit", None).unwrap();
    let got: Vec<(&str, &str, Option<result::RosterMark>)> =
        pending.iter().map(|p| (p.entry.as_str(), p.name.as_str(), p.roster.clone())).collect();
    let mark = |listed, name: Option<&str>, claimed: Option<&str>, student: Option<&str>| {
        Some(result::RosterMark {
            listed,
            name: name.map(str::to_owned),
            claimed: claimed.map(str::to_owned),
            student: student.map(str::to_owned),
        })
    };
    assert_eq!(
        got,
        [
            (
                "Taro Yamada_777_assignsubmission_file_",
                "20260002",
                mark(true, Some("山田 太郎"), None, Some("20260002"))
            ),
            ("a", "20260009", mark(true, Some("A"), Some("20260001"), Some("20260009"))),
            ("c", "20260004", mark(false, None, None, None)),
        ]
    );
    // The variant graded is the roster's student's.
    let a = pending.iter().find(|p| p.entry == "a").unwrap();
    assert_eq!(a.files.as_ref().unwrap().1.student.to_string(), "20260009");
    // The summary lists the claim, the unlisted entry and the absent student.
    let results: Vec<serde_json::Value> = pending
        .iter()
        .map(|p| {
            let meta = result::Meta {
                entry: &p.entry,
                student: Some(p.name.as_str()),
                table: None,
                hash: "",
                isolation: Isolation::Bubblewrap,
                same_number: &[],
                roster: p.roster.as_ref(),
                total: std::time::Duration::ZERO,
            };
            result::build(&meta, &result::Facts::default(), &Config::default(), Lang::En)
        })
        .collect();
    let md = result::summary_md(&results, &[("20260003".into(), "Absent".into())], Lang::En);
    for needle in [
        "## Against the roster",
        "- `c` (`20260004`)",
        "- `a`: student.toml claims `20260001`, the roster says 20260009 (A)",
        "- 20260003 Absent",
    ] {
        assert!(md.contains(needle), "{needle:?} missing from:\n{md}");
    }
    // The results' words are in the run's language: another language is another result to
    // keep (a result kept from an English run was handed out under --lang ja).
    let mut japanese = collect_options(&root, None);
    japanese.lang = Lang::Ja;
    let mut english = collect_options(&root, None);
    english.lang = Lang::En;
    let hashes = |o: &Options| -> Vec<String> {
        collect(o, "kit", None).unwrap().into_iter().map(|p| p.hash).collect()
    };
    let (ja, en) = (hashes(&japanese), hashes(&english));
    assert_eq!(ja.len(), 3);
    assert!(ja.iter().zip(&en).all(|(a, b)| a != b), "{ja:?} {en:?}");
    assert_eq!(hashes(&japanese), ja, "stable");
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn entries_that_claim_one_number_are_all_flagged_and_none_takes_the_file() {
    let root = std::env::temp_dir().join(format!("cg-grade-claims-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let subs = root.join("subs");
    // "00-impostor" sorts before the real student's entry and claims their number.
    for (entry, number) in
        [("00-impostor", "20260001"), ("20260001-taro", "20260001"), ("b", "20260002")]
    {
        let ex = subs.join(entry).join("exercises");
        std::fs::create_dir_all(ex.join("src")).unwrap();
        std::fs::write(ex.join("student.toml"), format!("student = \"{number}\"\n")).unwrap();
        std::fs::write(ex.join("src/a1.rs"), format!("// {entry}")).unwrap();
    }
    let options = collect_options(&root, None);
    let pending = collect(&options, "kit", None).unwrap();
    let names: Vec<(&str, &str, Vec<String>)> = pending
        .iter()
        .map(|p| (p.entry.as_str(), p.name.as_str(), p.same_number.clone()))
        .collect();
    assert_eq!(
        names,
        [
            ("00-impostor", "20260001~00-impostor", vec!["20260001-taro".to_owned()]),
            ("20260001-taro", "20260001~20260001-taro", vec!["00-impostor".to_owned()]),
            ("b", "20260002", vec![]),
        ]
    );
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn entry_names_become_file_names() {
    assert_eq!(file_name("../a b.zip"), "_a_b.zip");
    assert_eq!(file_name(""), "_");
    assert_eq!(file_name("山田 太郎.zip"), "山田_太郎.zip");
    assert_eq!(file_name(&"x".repeat(300)).len(), 80);
}

/// Entries whose names are alike once made file names each get a result of their own: two
/// refused entries with names of the same length in letters the file name does not keep, and
/// one that claims a student's number with a name made alike on purpose. One result used to be
/// written over the other.
#[test]
fn entries_alike_as_file_names_get_results_of_their_own() {
    let root = std::env::temp_dir().join(format!("cg-grade-alike-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let subs = root.join("subs");
    for (entry, toml) in [
        ("a★b", None),
        ("a☆b", None),
        ("c", Some("student = \"12345678\"\n")),
        ("x★", Some("student = \"12345678\"\n")),
        ("x☆", Some("student = \"12345678\"\n")),
    ] {
        let ex = subs.join(entry).join("exercises");
        std::fs::create_dir_all(ex.join("src")).unwrap();
        if let Some(toml) = toml {
            std::fs::write(ex.join("student.toml"), toml).unwrap();
        }
    }
    let pending = collect(&collect_options(&root, None), "kit", None).unwrap();
    let names: std::collections::BTreeSet<String> =
        pending.iter().map(|p| p.name.to_lowercase()).collect();
    assert_eq!(names.len(), 5, "{:?}", pending.iter().map(|p| &p.name).collect::<Vec<_>>());
    // A name that is not alike keeps its plain form.
    assert!(
        pending.iter().any(|p| p.name == "12345678~c"),
        "{:?}",
        pending.iter().map(|p| &p.name).collect::<Vec<_>>()
    );
    let _ = std::fs::remove_dir_all(&root);
}

#[test]
fn hashes_are_stable_and_length_prefixed() {
    let mut a = Hasher::default();
    a.add(b"ab");
    a.add(b"c");
    let mut b = Hasher::default();
    b.add(b"a");
    b.add(b"bc");
    assert_ne!(a.hex(), b.hex());
    assert_eq!(Hasher::default().hex(), "cbf29ce484222325");
}

/// Grading that cannot start says why in the instructor's language: a missing submissions
/// folder (through [`collect`] and through [`grade_with`], before anything is built), and a
/// handout whose folder lies under a file. The Japanese has the system's reason translated, not
/// its English words.
#[test]
fn grading_that_cannot_start_says_why_in_both_languages() {
    let root = std::env::temp_dir().join(format!("cg-grade-start-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(&root).unwrap();
    let options = collect_options(&root, None);
    let never = |_: progress::Event<'_>| {};
    let errors = [
        collect(&options, "kit", None).map(|_| ()).unwrap_err(),
        grade_with(&options, cg_sandbox::launch, &never, None).map(|_| ()).unwrap_err(),
    ];
    for e in &errors {
        let (ja, en) = (e.message(Lang::Ja), e.message(Lang::En));
        assert!(
            ja.contains("subs") && ja.contains("ありません") && !ja.contains("os error"),
            "{ja}"
        );
        assert!(en.contains("subs") && !en.contains("ありません"), "{en}");
        assert_eq!(e.to_string(), en);
    }
    // Results in the kit's own folder, or in a file: refused before anything is read.
    std::fs::create_dir_all(root.join("subs")).unwrap();
    for out in [root.clone(), root.join("..").join(root.file_name().unwrap())] {
        let options = Options { out, ..collect_options(&root, None) };
        let e = grade_with(&options, cg_sandbox::launch, &never, None).map(|_| ()).unwrap_err();
        assert!(e.message(Lang::En).contains("is the kit's folder (or above it)"), "{e}");
        assert!(e.message(Lang::Ja).contains("キットのフォルダ"), "{e}");
    }
    std::fs::write(root.join("results.txt"), "").unwrap();
    let options = Options { out: root.join("results.txt"), ..collect_options(&root, None) };
    let e = grade_with(&options, cg_sandbox::launch, &never, None).map(|_| ()).unwrap_err();
    assert!(e.message(Lang::En).ends_with("is not a folder: give a folder for the results"), "{e}");
    // A handout into a folder whose parent is a file.
    std::fs::write(root.join("a.txt"), "kit file").unwrap();
    std::fs::write(root.join("blocker"), "a file").unwrap();
    let why = handout::write_handout(&root, &root.join("blocker/copy")).unwrap_err();
    assert!(why.ja.contains("blocker") && !why.ja.contains("os error"), "{}", why.ja);
    assert!(why.en.contains("blocker"), "{}", why.en);
    let _ = std::fs::remove_dir_all(&root);
}

/// class.csv's entry names are the students' (a zip's name, a Moodle full name): one that
/// begins like a spreadsheet formula is text (a leading `'`), never a formula.
#[test]
fn entry_names_that_look_like_formulas_are_text_in_class_csv() {
    let result = serde_json::json!({
        "score": 1.0,
        "max_score": 2.0,
        "cg": { "student": "20260001", "submission": "=HYPERLINK(\"http://evil\",\"x\")" },
    });
    let csv = result::class_csv(&[result], Lang::En);
    let row = csv.lines().nth(1).unwrap();
    assert!(row.starts_with("20260001,\"'=HYPERLINK("), "{row}");
    // A carriage return in the name would start a row (a formula first) to some readers.
    let result = serde_json::json!({
        "score": 1.0,
        "cg": { "student": "20260001", "submission": "Taro.zip\r=WEBSERVICE(A1)" },
    });
    let csv = result::class_csv(&[result], Lang::En);
    assert!(csv.contains("20260001,\"Taro.zip\r=WEBSERVICE(A1)\","), "{csv:?}");
}

/// Text from a submission reaches summary.md and the feedback as a code span: an image that
/// would load when the summary is previewed, HTML, a heading after a newline and backticks of
/// its own stay text.
#[test]
fn names_from_a_submission_are_code_in_markdown() {
    assert_eq!(result::md_code("Taro.zip", Lang::En), "`Taro.zip`");
    assert_eq!(result::md_code("<img src=x>", Lang::En), "`<img src=x>`");
    assert_eq!(result::md_code("![](http://e/t.png)", Lang::En), "`![](http://e/t.png)`");
    assert_eq!(result::md_code("a``b", Lang::En), "```a``b```");
    assert_eq!(result::md_code("`x", Lang::En), "`` `x ``");
    assert_eq!(result::md_code("a\n# heading", Lang::En), "`a<U+000A># heading`");
    let result = serde_json::json!({
        "score": 0.0,
        "cg": { "student": "?", "submission": "![](http://evil/t.png)", "refused": "no" },
    });
    let md = result::summary_md(&[result], &[], Lang::En);
    assert!(md.contains("- `![](http://evil/t.png)` (`?`): `no`"), "{md}");
    // The kit's own reason is given whole (it was cut at 64 characters, before its fix); a
    // control character in it is still shown by its code.
    let why = "a1.rs is both in exercises/ (exercises/src/a1.rs) and outside it (a1.rs), with different text: put the right one in exercises/\u{1b}";
    let result = serde_json::json!({
        "score": 0.0,
        "cg": { "student": "20260001", "submission": "x.zip", "refused": why },
    });
    let md = result::summary_md(&[result], &[], Lang::En);
    assert!(md.contains("put the right one in exercises/<U+001B>`"), "{md}");
}

/// A result's facts about a submission `a.zip` of `student`, sandboxed, taking no time.
fn meta(student: Option<&str>) -> result::Meta<'_> {
    result::Meta {
        student,
        table: Some(cg_harness::TableVersion::V1),
        entry: "a.zip",
        hash: "",
        isolation: Isolation::Bubblewrap,
        same_number: &[],
        roster: None,
        total: std::time::Duration::ZERO,
    }
}

/// Why a submission was not graded is kept in both languages: the Japanese summary and
/// Moodle's comment say it in Japanese (they gave the English), and a result written before
/// the Japanese was kept still gives its English.
#[test]
fn why_a_submission_was_not_graded_is_said_in_the_readers_language() {
    let facts = result::Facts {
        refused: Some(Text::new(
            "exercises/student.toml がありません",
            "exercises/student.toml is missing",
        )),
        ..result::Facts::default()
    };
    let meta = meta(None);
    let r = result::build(&meta, &facts, &Config::default(), Lang::Ja);
    assert_eq!(result::not_graded(&r["cg"], Lang::Ja), Some("exercises/student.toml がありません"));
    assert_eq!(result::not_graded(&r["cg"], Lang::En), Some("exercises/student.toml is missing"));
    let md = result::summary_md(std::slice::from_ref(&r), &[], Lang::Ja);
    assert!(md.contains("がありません") && !md.contains("is missing"), "{md}");
    let old = serde_json::json!({ "refused": "exercises/student.toml is missing" });
    assert_eq!(result::not_graded(&old, Lang::Ja), Some("exercises/student.toml is missing"));
}

/// A check whose call gave no value for the kit's reasons (`status: broken`) is explained in
/// the feedback's language from the outcome as the harness writes it; it had no case and was
/// shown as "expected: (nothing) found: (nothing)".
#[test]
fn a_broken_call_is_explained_in_the_feedbacks_language() {
    let outcome = cg_harness::check::Outcome::Broken {
        why: Text::new("shade_pixel: light の 0 番目の呼び出し", "shade_pixel: light query 0 was"),
    };
    let mut check = serde_json::to_value(&outcome).unwrap();
    check["id"] = "s.t9".into();
    check["title"] = serde_json::json!({ "ja": "ピクセル", "en": "pixel" });
    let facts = result::Facts {
        runs: [("s".to_owned(), AssignmentRun::Report(serde_json::json!({ "checks": [check] })))]
            .into(),
        ..result::Facts::default()
    };
    let meta = meta(Some("20260001"));
    for (lang, said) in [
        (Lang::Ja, "関数の結果を受け取れませんでした: shade_pixel: light の 0 番目の呼び出し"),
        (Lang::En, "no result came back from the function: shade_pixel: light query 0 was"),
    ] {
        let r = result::build(&meta, &facts, &Config::default(), lang);
        assert_eq!(r["tests"][0]["output"], said, "{r:#}");
    }
}

/// The summary line of an assignment that does not compile carries its first error (it was the
/// heading alone, ending in a colon: `a1: compile errors (a1.rs):`), in the output that
/// Gradescope and Moodle's feedback show first.
#[test]
fn the_summary_line_of_a_compile_error_names_the_first_error() {
    let check = serde_json::json!({
        "id": "a1.t1.count", "title": { "ja": "頂点の数", "en": "vertex count" },
        "status": "pass",
    });
    let facts = result::Facts {
        runs: [("a1".to_owned(), AssignmentRun::Report(serde_json::json!({ "checks": [check] })))]
            .into(),
        compile_errors: [(
            "a1".to_owned(),
            vec!["exercises/src/a1.rs:379: this file contains an unclosed delimiter".to_owned()],
        )]
        .into(),
        ..result::Facts::default()
    };
    let meta = meta(Some("20260001"));
    let r = result::build(&meta, &facts, &Config::default(), Lang::En);
    let output = r["output"].as_str().unwrap();
    let line = output.lines().find(|l| l.starts_with("a1: compile errors")).expect(output);
    assert_eq!(
        line,
        "a1: compile errors (a1.rs): exercises/src/a1.rs:379: this file contains an unclosed delimiter"
    );
}

/// A file the submission did not hold is graded as its stub, and each of its checks says the
/// file was not handed in (they said "delete the line cg_student::not_started(…)", advice for
/// a file the student wrote); a check that passed on the stub still scores nothing.
#[test]
fn a_file_not_handed_in_is_said_so() {
    let not_done = serde_json::json!({
        "id": "a2.t1.view", "title": { "ja": "ビュー", "en": "view" },
        "status": "not_done",
        "message": "a2.t1: delete the line cg_student::not_started(\"a2.t1\"); when you start writing it",
    });
    let passed = serde_json::json!({
        "id": "a2.t2.eye", "title": { "ja": "視点", "en": "eye" }, "status": "pass",
    });
    let facts = result::Facts {
        runs: [(
            "a2".to_owned(),
            AssignmentRun::Report(serde_json::json!({ "checks": [not_done, passed] })),
        )]
        .into(),
        not_submitted: ["a2".to_owned()].into(),
        ..result::Facts::default()
    };
    let meta = meta(Some("20260001"));
    for (lang, said) in [
        (Lang::En, "a2.rs is not in the submission (exercises/src/a2.rs)"),
        (Lang::Ja, "a2.rs は提出物にありません（exercises/src/a2.rs）"),
    ] {
        let r = result::build(&meta, &facts, &Config::default(), lang);
        assert_eq!(r["score"], 0.0, "{r:#}");
        let tests = r["tests"].as_array().unwrap();
        assert_eq!(tests.len(), 2, "{r:#}");
        for t in tests {
            assert_eq!(t["output"], said, "{r:#}");
            assert_eq!(t["status"], "failed", "{r:#}");
        }
        assert!(r["output"].as_str().unwrap().contains(&format!("a2: {said}")), "{r:#}");
    }
    // Handed in, the same report is read as it is.
    let facts = result::Facts { not_submitted: Default::default(), ..facts };
    let r = result::build(&meta, &facts, &Config::default(), Lang::En);
    assert_eq!(r["tests"][1]["status"], "passed", "{r:#}");
}

/// A module converted from Shift_JIS is said in the output, in the reader's language.
#[test]
fn a_converted_module_is_said() {
    let facts = result::Facts {
        converted: [("a1".to_owned(), "Shift_JIS".to_owned())].into(),
        ..result::Facts::default()
    };
    let meta = meta(Some("20260001"));
    let r = result::build(&meta, &facts, &Config::default(), Lang::En);
    let output = r["output"].as_str().unwrap();
    assert!(output.contains("a1.rs was saved as Shift_JIS: graded converted to UTF-8"), "{output}");
    assert_eq!(r["cg"]["converted"]["a1"], "Shift_JIS");
    let r = result::build(&meta, &facts, &Config::default(), Lang::Ja);
    assert!(r["output"].as_str().unwrap().contains("a1.rs は Shift_JIS で保存されていた"));
}

/// With `[totals]`, an assignment's checks share its total: a2 of 14 checks and of 16 are
/// both worth 20 (they were worth 14 and 16, so one student's 100 % weighed more).
#[test]
fn totals_are_shared_by_the_checks_of_each_variant() {
    let config = Config::parse("[totals]\na2 = 20\n").unwrap();
    for n in [14, 16] {
        let checks: Vec<serde_json::Value> = (0..n)
            .map(|k| {
                serde_json::json!({
                    "id": format!("a2.t1.c{k}"), "title": { "ja": "x", "en": "x" },
                    "status": if k == 0 { "pass" } else { "fail" }, "message": "",
                })
            })
            .collect();
        let facts = result::Facts {
            runs: [(
                "a2".to_owned(),
                AssignmentRun::Report(serde_json::json!({ "checks": checks })),
            )]
            .into(),
            ..result::Facts::default()
        };
        let r = result::build(&meta(Some("20260001")), &facts, &config, Lang::En);
        assert_eq!(r["max_score"], 20.0, "{n}: {r:#}");
        let one = (20.0 / f64::from(n) * 1000.0).round() / 1000.0;
        assert_eq!(r["score"], one, "{n}: {r:#}");
        assert_eq!(r["cg"]["assignments"]["a2"]["max_score"], 20.0, "{n}");
    }
}

/// summary.md names an assignment whose maximum differs between students, and how to even it
/// out; equal maxima (or `[totals]`) give no such section.
#[test]
fn the_summary_names_assignments_worth_more_for_some_students() {
    let result = |a2: f64| {
        serde_json::json!({
            "score": 1.0, "max_score": 14.0 + a2,
            "cg": { "student": "20260001", "submission": "x",
                    "assignments": { "a1": { "score": 1.0, "max_score": 14.0 },
                                     "a2": { "score": 0.0, "max_score": a2 } } },
        })
    };
    let md = result::summary_md(&[result(14.0), result(16.0)], &[], Lang::En);
    assert!(md.contains("## Assignments worth more for some students\n\n- a2: 14–16\n"), "{md}");
    assert!(md.contains("[totals]") && !md.contains("- a1:"), "{md}");
    let md = result::summary_md(&[result(14.0), result(16.0)], &[], Lang::Ja);
    assert!(md.contains("## 学生によって満点が違う課題"), "{md}");
    let md = result::summary_md(&[result(20.0), result(20.0)], &[], Lang::En);
    assert!(!md.contains("worth more"), "{md}");
}

/// The table a submission's variants came from is in its result; table 2 is said in its
/// feedback, and summary.md lists the students on the fewer tables when a class mixes them (one
/// table: no section).
#[test]
fn a_class_on_two_tables_is_said() {
    use cg_harness::TableVersion;
    let facts = result::Facts::default();
    let on = |student: &'static str, table| {
        let meta = result::Meta { table: Some(table), ..meta(Some(student)) };
        result::build(&meta, &facts, &Config::default(), Lang::En)
    };
    let (a, b, c) = (
        on("20260001", TableVersion::V1),
        on("20260002", TableVersion::V1),
        on("20260003", TableVersion::V2),
    );
    assert_eq!(
        (&a["cg"]["table"], &c["cg"]["table"]),
        (&serde_json::json!(1), &serde_json::json!(2))
    );
    assert!(!a["output"].as_str().unwrap().contains("table"), "{}", a["output"]);
    assert!(c["output"].as_str().unwrap().contains("table: 2\n"), "{}", c["output"]);
    let md = result::summary_md(&[a.clone(), b.clone(), c.clone()], &[], Lang::En);
    assert!(md.contains("## Submissions on different tables\n\n- table 1: 2\n- table 2: 1: `20260003` (`a.zip`)\n"), "{md}");
    assert!(md.contains("assignment --table 2 --save"), "{md}");
    let md = result::summary_md(&[a.clone(), b.clone(), c], &[], Lang::Ja);
    assert!(md.contains("- 課題表 2: 1 件: `20260003`"), "{md}");
    let md = result::summary_md(&[a, b], &[], Lang::En);
    assert!(!md.contains("different tables"), "{md}");
}

/// A submission whose grading failed (its build ran over the limit) with a report in it: the
/// result, its feedback and class.csv say the report was not checked and why (they said
/// nothing, as for a submission without one). Without a report, nothing is said of one.
#[test]
fn a_report_in_a_submission_not_graded_is_said_not_checked() {
    let found = inside::Found {
        path: "report/report.md".to_owned(),
        text: "# Report".to_owned(),
        encoding: cg_core::text::Encoding::Utf8,
    };
    let fatal = || result::Facts {
        fatal: Some(Text::new("ビルドが制限時間を超えました", "the build ran over its limit")),
        ..result::Facts::default()
    };
    let mut facts = fatal();
    report::not_graded(&mut facts, &(Some(found.clone()), Vec::new()));
    let meta = meta(Some("20260001"));
    let r = result::build(&meta, &facts, &Config::default(), Lang::En);
    let said = "report/report.md was not checked: grading failed";
    assert!(r["output"].as_str().unwrap().contains(said), "{}", r["output"]);
    assert_eq!(report::csv_cells(&r)[0], said);
    let feedback = moodle::output::feedback_md(&r, Lang::En);
    assert!(feedback.contains(said), "{feedback}");
    let ja = result::build(&meta, &facts, &Config::default(), Lang::Ja);
    let feedback = moodle::output::feedback_md(&ja, Lang::Ja);
    assert!(
        feedback.contains("report/report.md は採点できなかったので確かめていません"),
        "{feedback}"
    );
    // Refused: its refusal says why, and its reader looks for no report.
    let mut refused =
        result::Facts { refused: Some(Text::new("x", "x")), ..result::Facts::default() };
    report::not_graded(&mut refused, &(Some(found.clone()), Vec::new()));
    assert!(refused.report.notes.is_empty());
    // No report: nothing of one.
    let mut none = fatal();
    report::not_graded(&mut none, &(None, Vec::new()));
    let r = result::build(&meta, &none, &Config::default(), Lang::En);
    assert!(r["cg"]["report"].is_null() && report::csv_cells(&r)[0].is_empty());
    // Graded: left to the check.
    let mut graded = result::Facts::default();
    report::not_graded(&mut graded, &(Some(found), Vec::new()));
    assert!(graded.report.notes.is_empty());
}
