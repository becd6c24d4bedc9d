//! The tests of the check runner and its reports.

use super::*;
use crate::text::t;
use std::time::{Duration, Instant};

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
    late.checks[1].outcome = Outcome::TimedOut { limit_ms: 5000, function: None, earlier: false };
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
fn a_file_that_does_not_compile_is_one_line_with_its_errors_once_and_is_not_a_task_to_fix() {
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
        assert!(text.contains("        | exercises/src/a1.rs:20: mismatched types"), "{text}");
        assert!(text.contains("✗ a1.t3.unit"), "{text}");
    }
    // One line for the file, with how many checks it stops and which (the IDs stay visible),
    // instead of "does not compile (see above)" under each of them.
    let en = report.render(Lang::En);
    assert!(
        en.starts_with(
            "  ! exercises/src/a1.rs does not compile, so 2 checks of this assignment did not run: a1.t1.count, a1.t2.closed\n        | error: expected `;`\n"
        ),
        "{en}"
    );
    assert_eq!(en.matches("exercises/src/a1.rs does not compile").count(), 1, "{en}");
    assert!(!en.contains("see above"), "{en}");
    assert!(en.ends_with("to fix: a1.t3; does not compile: exercises/src/a1.rs\n"), "{en}");
    let ja = report.render(Lang::Ja);
    assert!(
        ja.starts_with(
            "  ! exercises/src/a1.rs がコンパイルできないため、この課題のチェック 2 個を実行していません: a1.t1.count, a1.t2.closed\n"
        ),
        "{ja}"
    );
    assert!(ja.contains("コンパイルできないファイル: exercises/src/a1.rs"));
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
    let late = Outcome::TimedOut { limit_ms: 20_000, function: None, earlier: false }
        .of_function("face_normals");
    assert!(late.ja.starts_with("face_normals: 制限時間 20 秒を超えても"), "{}", late.ja);
    assert!(!late.en.contains("panicked"), "{}", late.en);
    let stub = Outcome::NotDone { message: "a1.t3".into() }.of_function("face_normals");
    assert!(stub.en.starts_with("face_normals is not written yet"), "{}", stub.en);
    // A stub's words in their own brackets, not in a second pair.
    let stub = Outcome::NotDone { message: "a1.t3: 面の法線 / the face normals".into() }
        .of_function("face_normals");
    assert_eq!(stub.ja, "face_normals はまだ書かれていません: a1.t3（面の法線）");
    assert_eq!(stub.en, "face_normals is not written yet (a1.t3: the face normals)");
}

/// The checks of `cg check a1` with a wrong face `[0, 1, 4]` (a student's copy, 2026): the
/// face fails a1.t2.indices, and six checks that need valid faces fail with the same five lines
/// each (and the cause the same sentence as "actual"); face_normals panics in a1.t3's three.
fn wrong_face() -> Report {
    let missing = t(
        "面 F0 の 2 番目 (0 から数えて) の頂点番号 V4 は存在しません（頂点は V0–V3 の 4 個です）",
        "vertex V4 (F0, corner 2) does not exist (the vertices are V0–V3)",
    );
    let needs_indices = || {
        Err(Failure::new(
            t("a1.t2.indices に合格する面", "faces that pass a1.t2.indices"),
            missing.clone(),
        )
        .at("faces()")
        .cause(missing.clone())
        .hint(t("先に a1.t2.indices を直してください", "fix a1.t2.indices first")))
    };
    let index_out_of_bounds = || -> Result<(), Failure> {
        let v = [0u32; 4];
        let i = v.len();
        Err(Failure::new(v[i].to_string(), ""))
    };
    let mut checks = vec![
        run("a1.t1.count", t("頂点の数", "vertex count"), || Ok(())),
        run("a1.t2.indices", t("頂点番号", "indices"), || {
            Err(Failure::new("0..=3", "F0[2] = 4")
                .at("F0")
                .cause(missing.clone())
                .hint(t("頂点番号は 0 から", "vertex numbers start at 0")))
        }),
    ];
    for id in ["a1.t2.degenerate", "a1.t2.closed", "a1.t2.manifold", "a1.t2.winding"] {
        checks.push(run(id, t(id, id), needs_indices));
    }
    checks.push(run("a1.t2.count", t("面の数", "face count"), || Ok(())));
    checks.push(run("a1.t2.surface", t("表面", "surface"), needs_indices));
    for id in ["a1.t3.count", "a1.t3.unit", "a1.t3.normals"] {
        checks.push(run(id, t(id, id), index_out_of_bounds));
    }
    // The same failure again after another explanation came between.
    checks.push(run("a1.t4.placement", t("配置", "placement"), needs_indices));
    Report { assignment: "a1".into(), student: None, checks }
}

/// Each explanation is said once: a check whose explanation was just shown says "(same as
/// above)", one shown further up names the check it is under; the cause is not repeated when
/// it is what "actual" says; every ID, the counts and the JSON stay.
#[test]
fn the_same_explanation_is_said_once_and_every_check_is_still_named() {
    let report = wrong_face();
    let json = report.to_json();
    for (lang, missing, same, same_as, panicked, hint) in [
        (
            Lang::En,
            "vertex V4 (F0, corner 2) does not exist",
            "(same as above)",
            "(same as a1.t2.degenerate)",
            "your code panicked: index out of bounds",
            "hint: fix a1.t2.indices first",
        ),
        (
            Lang::Ja,
            "面 F0 の 2 番目 (0 から数えて) の頂点番号 V4 は存在しません",
            "（同上）",
            "（a1.t2.degenerate と同じ）",
            "プログラムが異常終了しました（panic）: index out of bounds",
            "ヒント: 先に a1.t2.indices を直してください",
        ),
    ] {
        let text = report.render(lang);
        for c in &report.checks {
            assert!(text.contains(&format!(" {} ", c.id)), "{} in:\n{text}", c.id);
        }
        // Under a1.t2.indices as its cause, under a1.t2.degenerate as what was found; not again
        // as the cause there, nor under the four checks after it.
        assert_eq!(text.matches(missing).count(), 2, "{text}");
        assert_eq!(text.matches(hint).count(), 1, "{text}");
        assert_eq!(text.matches(panicked).count(), 1, "{text}");
        // closed, manifold, winding, surface (after a pass, which explains nothing), and a1.t3's
        // unit and normals.
        assert_eq!(text.matches(same).count(), 6, "{text}");
        let placement = text.lines().find(|l| l.contains("a1.t4.placement")).unwrap();
        assert!(placement.ends_with(same_as), "{text}");
        let closed = text.lines().find(|l| l.contains("a1.t2.closed")).unwrap();
        assert!(closed.starts_with("  ✗ a1.t2.closed") && closed.ends_with(same), "{text}");
        // A line per check, the explanations of a1.t2.indices (5 lines), a1.t2.degenerate (4:
        // the cause is what "actual" says) and the panic (2), and the progress.
        assert_eq!(text.lines().count(), 12 + 5 + 4 + 2 + 1, "{text}");
    }
    assert_eq!((report.passed(), report.total()), (2, 12));
    assert_eq!(report.to_json(), json, "rendering changes nothing");
    assert_eq!(json["checks"][3]["cause"]["en"], json["checks"][3]["actual"]["en"]);
    assert_eq!(json["checks"].as_array().unwrap().len(), 12);
}

/// Stubs not started: one line per task, with every check's ID, instead of "not done yet" under
/// each check; a task's checks reaching another task's marker say so once.
#[test]
fn the_stubs_of_a_task_are_one_line() {
    let mut checks: Vec<CheckResult> = ["a2.t1.x", "a2.t1.y", "a2.t1.z"]
        .map(|id| {
            run(id, t(id, id), || {
                let _ = marked_stub("a2.t1");
                Ok(())
            })
        })
        .to_vec();
    checks.push(run("a2.t2.only", t("ひとつ", "only one"), || todo!("a2.t2: write it")));
    checks.extend(["a2.t3.p", "a2.t3.q"].map(|id| {
        run(id, t(id, id), || {
            let _ = marked_stub("a2.t1");
            Ok(())
        })
    }));
    let report = Report { assignment: "a2".into(), student: None, checks };
    let en = report.render(Lang::En);
    let expected = "  … a2.t1.x, a2.t1.y, a2.t1.z  not done yet: a2.t1: delete the line cg_student::not_started(\"a2.t1\"); when you start writing it
  … a2.t2.only  not done yet: a2.t2: write it
  … a2.t3.p, a2.t3.q  not done yet (same as a2.t1.x)
progress: 0/6 checks pass; not done yet: a2.t1, a2.t2, a2.t3
";
    assert_eq!(en, expected);
    let ja = report.render(Lang::Ja);
    assert!(
        ja.starts_with(
            "  … a2.t1.x, a2.t1.y, a2.t1.z  まだです: a2.t1（書き始めたら cg_student::not_started(\"a2.t1\"); の行を消します）\n"
        ),
        "{ja}"
    );
    assert!(ja.contains("\n  … a2.t3.p, a2.t3.q  まだです（a2.t1.x と同じ）\n"), "{ja}");
    assert_eq!(ja.matches("書き始めたら").count(), 1, "{ja}");
}

/// A timeout names the student's function and its file; a check that did not run it because it
/// ran out of time earlier says so; and the JSON of a timeout without a function is as before.
#[test]
fn a_timeout_names_the_function_and_a_later_check_says_it_did_not_run_it() {
    let error = CallError::TimedOut {
        limit: Duration::from_secs(20),
        function: "a1.face_normals".into(),
        earlier: false,
    };
    let late = Outcome::of_call(&error);
    let text = late.describe().unwrap();
    assert_eq!(
        text.ja,
        "exercises/src/a1.rs の face_normals が制限時間 20 秒を超えても終わらないため止めました。無限ループになっていないか確認してください。"
    );
    assert_eq!(
        text.en,
        "face_normals (exercises/src/a1.rs) was stopped after the time limit of 20 s: does it loop forever?"
    );
    assert_eq!(late.of_function("face_normals"), text, "named once");
    let skipped = Outcome::TimedOut {
        limit_ms: 20_000,
        function: Some("a1.face_normals".into()),
        earlier: true,
    };
    assert_eq!(
        skipped.describe().unwrap().en,
        "not run: face_normals (exercises/src/a1.rs) did not finish in an earlier check (above)"
    );
    assert!(
        skipped
            .describe()
            .unwrap()
            .ja
            .starts_with("実行していません: exercises/src/a1.rs の face_normals は前のチェックで")
    );
    let batch =
        Outcome::TimedOut { limit_ms: 1500, function: Some("a3.frames".into()), earlier: false };
    assert!(batch.describe().unwrap().en.starts_with(
        "idle or display (exercises/src/a3.rs) was stopped after the time limit of 1.5 s"
    ));
    // A batch whose worker said which function ran out, and at which frame (issue 10): named
    // as `cg view` names it, with the frame.
    let error = CallError::TimedOut {
        limit: Duration::from_secs(20),
        function: "a3.idle@401".into(),
        earlier: false,
    };
    let text = Outcome::of_call(&error).describe().unwrap();
    assert_eq!(
        text.en,
        "idle (exercises/src/a3.rs) was stopped at frame 401 after the time limit of 20 s: does it loop forever?"
    );
    assert_eq!(
        text.ja,
        "exercises/src/a3.rs の idle がフレーム 401 で制限時間 20 秒を超えても終わらないため止めました。無限ループになっていないか確認してください。"
    );
    let later = Outcome::TimedOut {
        limit_ms: 20_000,
        function: Some("a3.display@9".into()),
        earlier: true,
    };
    assert_eq!(
        later.describe().unwrap().en,
        "not run: display (exercises/src/a3.rs) did not finish in an earlier check (above)"
    );
    // JSON: as before, with the function when there is one; and it reads back (`cg watch`).
    let bare =
        serde_json::to_value(Outcome::TimedOut { limit_ms: 5, function: None, earlier: false })
            .unwrap();
    assert_eq!(bare, serde_json::json!({"status": "timed_out", "limit_ms": 5}));
    let json = serde_json::to_value(&skipped).unwrap();
    assert_eq!(
        json,
        serde_json::json!({"status": "timed_out", "limit_ms": 20_000, "function": "a1.face_normals", "earlier": true})
    );
    assert_eq!(serde_json::from_value::<Outcome>(json).unwrap(), skipped);
    assert_eq!(
        serde_json::from_value::<Outcome>(bare).unwrap(),
        Outcome::TimedOut { limit_ms: 5, function: None, earlier: false }
    );
}

/// A student's function that never returns (a worker that never replies: `sleep`), called by
/// three checks with a short limit: the first waits for the limit and names the function, the
/// other two do not wait again and say why; a call outside a check (a view's) still runs it.
#[cfg(unix)]
#[test]
fn a_function_that_ran_out_of_time_is_not_waited_for_again() {
    let limit = Duration::from_millis(300);
    let worker = cg_worker::Worker::new("sleep", ["30"]);
    let normals = || -> Result<(), Failure> {
        let _: Vec<f32> = cg_worker::proxy::call("a1.face_normals", &());
        Ok(())
    };
    let started = Instant::now();
    let ((checks, view), worker) = cg_worker::proxy::with_worker(worker, limit, || {
        let checks =
            ["a1.t3.count", "a1.t3.unit", "a1.t3.normals"].map(|id| run(id, t(id, id), normals));
        (checks, guarded(normals))
    });
    let took = started.elapsed();
    assert_eq!(worker.timeouts, 2, "the first check's call and the view's");
    assert!(took < limit * 2 + Duration::from_millis(1500), "{took:?}: waited once per check?");
    assert_eq!(
        checks[0].outcome,
        Outcome::TimedOut {
            limit_ms: 300,
            function: Some("a1.face_normals".into()),
            earlier: false
        }
    );
    for c in &checks[1..] {
        assert_eq!(
            c.outcome,
            Outcome::TimedOut {
                limit_ms: 300,
                function: Some("a1.face_normals".into()),
                earlier: true
            }
        );
    }
    assert!(matches!(view, Err(Outcome::TimedOut { earlier: false, .. })), "{view:?}");
    let report = Report { assignment: "a1".into(), student: None, checks: checks.to_vec() };
    assert!(report.timed_out());
    let en = report.render(Lang::En);
    assert_eq!(
        en,
        "  ! a1.t3.count    a1.t3.count
      face_normals (exercises/src/a1.rs) was stopped after the time limit of 0.3 s: does it loop forever?
  ! a1.t3.unit     a1.t3.unit
      not run: face_normals (exercises/src/a1.rs) did not finish in an earlier check (above)
  ! a1.t3.normals  a1.t3.normals  (same as above)
progress: 0/3 checks pass; to fix: a1.t3
"
    );
}
