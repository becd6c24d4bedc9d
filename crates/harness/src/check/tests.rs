//! The tests of the check runner and its reports.

use super::*;
use crate::text::t;

#[test]
fn outcomes_are_told_apart() {
    let pass = run("x.t1.a", t("a", "a"), || Ok(()));
    assert!(pass.passed());
    let fail = run("x.t1.b", t("b", "b"), || Err(Failure::new("1", "2").at("V3")));
    assert!(matches!(&fail.outcome, Outcome::Fail(f) if f.location == Some("V3".into())));
    let stub = run("x.t2.c", t("c", "c"), || todo!("x.t2: write it"));
    assert_eq!(stub.outcome, Outcome::NotDone { message: "x.t2: write it".into() });
    let bare = run("x.t2.d", t("d", "d"), || unimplemented!());
    assert!(matches!(bare.outcome, Outcome::NotDone { .. }), "{bare:?}");
    let oops = run("x.t3.e", t("e", "e"), || {
        let v: Vec<u32> = Vec::new();
        let i = v.len() + 2;
        Err(Failure::new(v[i].to_string(), ""))
    });
    match &oops.outcome {
        Outcome::Panicked { message, location } => {
            assert!(message.contains("index out of bounds"), "{message}");
            assert!(
                location.as_deref().is_some_and(|l| l.contains("check/tests.rs")),
                "{location:?}"
            );
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn stub_messages_are_shown_in_one_language() {
    let both = "s.t1: 環境光 Ia·ka を返す / return the ambient term Ia·ka";
    assert_eq!(stub_message(both, Lang::Ja), "s.t1（環境光 Ia·ka を返す）");
    assert_eq!(stub_message(both, Lang::En), "s.t1: return the ambient term Ia·ka");
    let english = "a1.t1: list the vertices";
    assert_eq!(stub_message(english, Lang::Ja), "a1.t1");
    assert_eq!(stub_message(english, Lang::En), "a1.t1: list the vertices");
    assert_eq!(stub_message("a2.t1", Lang::Ja), "a2.t1");
    // Formulas keep their slashes; text without an ID is shown as it is.
    let formula = "s.t4: return 1/(kc + kl·d + kq·d²)";
    assert_eq!(stub_message(formula, Lang::En), "s.t4: return 1/(kc + kl·d + kq·d²)");
    assert_eq!(stub_message("", Lang::En), "");
}

/// A stub that runs: the marker's line, then what the stub does.
fn marked_stub(task: &str) -> u32 {
    cg_student::not_started(task);
    0
}

#[test]
fn a_stubs_marker_makes_its_checks_not_done_whatever_they_found() {
    // Passed, failed or panicked: the marker wins while it is there.
    let pass = run("x.t1.a", t("a", "a"), || {
        let _ = marked_stub("x.t1");
        Ok(())
    });
    let fail =
        run("x.t1.b", t("b", "b"), || Err(Failure::new("1", marked_stub("x.t1").to_string())));
    let oops = run("x.t1.c", t("c", "c"), || {
        let _ = marked_stub("x.t1");
        panic!("index out of bounds")
    });
    for r in [&pass, &fail, &oops] {
        let Outcome::NotDone { message } = &r.outcome else { panic!("{r:?}") };
        assert!(message.starts_with("x.t1: "), "{message}");
        assert!(message.contains("cg_student::not_started(\"x.t1\");"), "{message}");
        assert_eq!(
            stub_message(message, Lang::En),
            "x.t1: delete the line cg_student::not_started(\"x.t1\"); when you start writing it"
        );
        assert!(stub_message(message, Lang::Ja).starts_with("x.t1（書き始めたら"), "{message}");
    }
    // The marker of the check's own task is named, else the first reached.
    let own = run("x.t2.d", t("d", "d"), || {
        let _ = marked_stub("x.t1") + marked_stub("x.t2");
        Ok(())
    });
    assert!(matches!(&own.outcome, Outcome::NotDone { message } if message.starts_with("x.t2:")));
    let other =
        run("x.t3.e", t("e", "e"), || Err(Failure::new("1", marked_stub("x.t1").to_string())));
    assert!(matches!(&other.outcome, Outcome::NotDone { message } if message.starts_with("x.t1:")));
    // The marker counts for the check that reached it only: the next check is judged.
    let _ = marked_stub("x.t1");
    let later = run("x.t1.f", t("f", "f"), || Err(Failure::new("1", "2")));
    assert!(matches!(later.outcome, Outcome::Fail(_)), "{later:?}");
    assert!(cg_student::take_not_started() == ["x.t1"], "what came before is put back");
    // Without the marker (the student deleted it), the code is judged.
    let written = run("x.t1.g", t("g", "g"), || Err(Failure::new("1", "2")));
    assert!(matches!(written.outcome, Outcome::Fail(_)), "{written:?}");
}

#[test]
fn guarded_calls_ignore_the_markers_and_leave_them_to_the_check() {
    assert_eq!(guarded(|| marked_stub("x.t1")), Ok(0), "the view draws what the stub gives");
    assert_eq!(cg_student::take_not_started(), ["x.t1"]);
    let check = run("x.t1.a", t("a", "a"), || {
        let _ = guarded(|| marked_stub("x.t1"));
        Ok(())
    });
    assert!(matches!(check.outcome, Outcome::NotDone { .. }), "{check:?}");
    assert_eq!(marker_message("x.t1", &[]), None);
}

#[test]
fn guarded_calls_return_values_or_outcomes() {
    assert_eq!(guarded(|| 41 + 1), Ok(42));
    assert!(matches!(guarded(|| -> u32 { todo!("x.t1: later") }), Err(Outcome::NotDone { .. })));
    assert!(matches!(guarded(|| -> u32 { panic!("boom") }), Err(Outcome::Panicked { .. })));
}

#[test]
fn a_selection_names_an_id_or_what_is_under_it() {
    assert!(selects("a1.t1", "a1.t1.count") && selects("a1.t1.count", "a1.t1.count"));
    assert!(selects("a1", "a1.t2.winding"));
    assert!(!selects("a1.t1", "a1.t10.count"), "t1 is not t10");
    assert!(!selects("a1.t2.count", "a1.t2.counted") && !selects("a2", "a1.t2.x"));
    // Under run_only, a check not selected is not run; keep_only drops it.
    let ran = std::cell::Cell::new(0);
    let checks = run_only(Some("x.t1"), || {
        ["x.t1.a", "x.t2.b", "x.t1.c"].map(|id| {
            run(id, t("", ""), || {
                ran.set(ran.get() + 1);
                Err(Failure::new("1", "2"))
            })
        })
    });
    assert_eq!(ran.get(), 2, "x.t2.b did not run");
    let mut report = Report { assignment: "x".into(), student: None, checks: checks.to_vec() };
    assert_eq!(report.keep_only("x.t1"), ["x.t1", "x.t2"]);
    let kept: Vec<&str> = report.checks.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(kept, ["x.t1.a", "x.t1.c"]);
    // Afterwards every check runs again.
    assert!(!run("x.t2.b", t("", ""), || Err(Failure::new("1", "2"))).passed());
}

#[test]
fn the_report_explains_and_summarises() {
    let report = Report {
        assignment: "a1".into(),
        student: Some("12345678".into()),
        checks: vec![
            run("a1.t1.count", t("頂点の数", "vertex count"), || Ok(())),
            run("a1.t2.closed", t("閉じている", "closed"), || {
                Err(Failure::new("every edge in two faces", "V1–V3 in F2 only")
                    .at("edge V1–V3")
                    .cause(t("面が足りない", "a missing face"))
                    .hint(t("F2 の隣を見る", "look next to F2")))
            }),
            run("a1.t3.normals", t("法線", "normals"), || todo!("a1.t3: normals")),
        ],
    };
    assert_eq!((report.passed(), report.total()), (1, 3));
    assert!(!report.timed_out(), "a failure and a stub are not a timeout");
    let mut late = report.clone();
    late.checks[1].outcome = Outcome::TimedOut { limit_ms: 5000 };
    assert!(late.timed_out(), "exit status 3 for `cg check`");
    let en = report.render(Lang::En);
    for needle in [
        "✓ a1.t1.count",
        "✗ a1.t2.closed",
        "expected: every edge",
        "actual  : V1–V3",
        "where   : edge V1–V3",
        "usual cause: a missing face",
        "hint: look next to F2",
        "… a1.t3.normals",
        "not done yet: a1.t3: normals",
        "progress: 1/3 checks pass; not done yet: a1.t3; to fix: a1.t2",
    ] {
        assert!(en.contains(needle), "{needle:?} missing from:\n{en}");
    }
    let ja = report.render(Lang::Ja);
    assert!(
        ja.contains("期待する値")
            && ja.contains("よくある原因: 面が足りない")
            && ja.contains("進み具合: 1/3"),
        "{ja}"
    );
    let json = report.to_json();
    assert_eq!(json["passed"], 1);
    assert_eq!(json["checks"][1]["status"], "fail");
    assert_eq!(json["checks"][1]["where"]["en"], "edge V1–V3");
    assert_eq!(json["checks"][1]["cause"]["ja"], "面が足りない");
    assert_eq!(json["checks"][2]["status"], "not_done");
    assert_eq!(json["checks"][2]["message"], "a1.t3: normals");
}

#[test]
fn a_file_that_does_not_compile_shows_its_errors_once_and_is_not_a_task_to_fix() {
    let errors = vec![
        "error: expected `;`\n  --> exercises/src/a1.rs:12:5".to_owned(),
        "exercises/src/a1.rs:20: mismatched types".to_owned(),
    ];
    let broken = CallError::DoesNotCompile { module: "a1".into(), errors };
    let checks = ["a1.t1.count", "a1.t2.closed"].map(|id| {
        run(id, t("", id), || -> Result<(), Failure> { std::panic::panic_any(broken.clone()) })
    });
    assert!(matches!(&checks[0].outcome, Outcome::DoesNotCompile { module, .. } if module == "a1"));
    let mut all = checks.to_vec();
    all.push(run("a1.t3.unit", t("", "unit"), || Err(Failure::new("1", "2"))));
    let report = Report { assignment: "a1".into(), student: None, checks: all };
    assert_eq!(report.tasks_failing(), ["a1.t3"], "a file that does not compile is not a task");
    assert_eq!(report.files_not_compiling(), ["exercises/src/a1.rs"]);
    for lang in [Lang::En, Lang::Ja] {
        let text = report.render(lang);
        assert_eq!(text.matches("expected `;`").count(), 1, "the errors once:\n{text}");
        assert!(text.contains("| exercises/src/a1.rs:20: mismatched types"), "{text}");
        assert!(text.contains("! a1.t2.closed"), "{text}");
    }
    let en = report.render(Lang::En);
    assert!(en.contains("exercises/src/a1.rs does not compile (see above)"), "{en}");
    assert!(en.ends_with("to fix: a1.t3; does not compile: exercises/src/a1.rs\n"), "{en}");
    assert!(report.render(Lang::Ja).contains("コンパイルできないファイル: exercises/src/a1.rs"));
    let json = report.to_json();
    assert_eq!(json["checks"][0]["status"], "does_not_compile");
    assert_eq!(json["checks"][0]["module"], "a1");
    assert_eq!(json["checks"][0]["errors"][1], "exercises/src/a1.rs:20: mismatched types");
}

/// A call that gave no value for the kit's reasons (`CallError::Broken`) is said as such, in
/// the reader's language: it used to be "the process ended (exit(), a stack overflow?)" with
/// the reason in English only. And a view's function that ran out of time is said so with its
/// name (a1's view used to say "face_normals panicked: " with nothing after it).
#[test]
fn a_call_that_gave_no_value_is_said_in_the_readers_language() {
    let why = cg_worker::Reason::new(
        "ワーカーに関数 a9.x がありません",
        "the worker has no function a9.x",
    );
    let outcome = Outcome::of_call(&CallError::Broken(why));
    let text = outcome.describe().unwrap();
    assert_eq!(
        text.ja,
        "あなたの関数の結果を受け取れませんでした: ワーカーに関数 a9.x がありません"
    );
    assert_eq!(text.en, "no result came back from your function: the worker has no function a9.x");
    assert_eq!(
        serde_json::to_value(&outcome).unwrap()["why"]["ja"],
        "ワーカーに関数 a9.x がありません"
    );
    let late = Outcome::TimedOut { limit_ms: 20_000 }.of_function("face_normals");
    assert!(late.ja.starts_with("face_normals: 制限時間 20 秒を超えても"), "{}", late.ja);
    assert!(!late.en.contains("panicked"), "{}", late.en);
    let stub = Outcome::NotDone { message: "a1.t3".into() }.of_function("face_normals");
    assert!(stub.en.starts_with("face_normals is not written yet"), "{}", stub.en);
}
