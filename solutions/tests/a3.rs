//! The instructor's proof for assignment a3 (animation): every check passes on the reference
//! solution for students covering every variant family, every check is "not done yet" on the
//! pristine stubs (their markers) and fails without the markers,
//! and each broken answer of a kind students really hand in fails the checks it should (and the
//! ones that name its mistake) — while every check ID fails for at least one of them.

// The assignment crates, through the kit's one list (cg-assign).
use cg_assign::cg_a3;

use std::collections::{BTreeMap, BTreeSet};
use std::f64::consts::TAU;
use std::sync::OnceLock;

use cg_a3::SpecDescribe as _;
use cg_a3::{Impl, Motion, Object, Spec, State, WorldAxis};
use cg_core::glam::Vec3;
use cg_core::lang::Lang;
use cg_harness::check::{CheckResult, Outcome, Report};
use cg_harness::{StudentNumber, TableVersion, VariantRng};
use cg_student::gl::Gl;

mod common;

/// Students whose variants together hold every family: 3 and 4 objects; the parent orbiting
/// or hopping; independent spins about X, Y and Z, swings about X, Y and Z, hops and orbits
/// (the lecture's 1.5 and 3 radii once); every time unit.
const STUDENTS: [&str; 8] = [
    "20260002", "20260005", "20260008", "20260009", "20260013", "20260018", "20260020", "20260023",
];

fn spec_for(student: &str) -> Spec {
    let s: StudentNumber = student.parse().unwrap();
    cg_a3::variant(&mut VariantRng::new(&s, TableVersion::V1, cg_a3::ID))
}

fn family(spec: &Spec, i: usize) -> String {
    let o = &spec.objects[i];
    let parent = if spec.children(i).is_empty() { "" } else { "-parent" };
    match o.motion {
        Motion::Spin { axis, .. } => format!("spin-{axis:?}"),
        Motion::Swing { axis, .. } => format!("swing-{axis:?}"),
        Motion::Hop { .. } => format!("hop{parent}"),
        Motion::Orbit { radius: 3.0, .. } => format!("orbit{parent}-lecture"),
        Motion::Orbit { .. } => format!("orbit{parent}"),
        Motion::Satellite { .. } => "satellite".to_owned(),
    }
}

#[test]
fn the_sample_students_cover_every_family() {
    let mut seen = BTreeSet::new();
    for s in STUDENTS {
        let spec = spec_for(s);
        seen.insert(format!("n{}", spec.objects.len()));
        seen.insert(format!("unit{}", spec.unit_s));
        for i in 0..spec.objects.len() {
            seen.insert(family(&spec, i));
        }
    }
    for f in [
        "n3",
        "n4",
        "unit1.5",
        "unit2",
        "unit2.5",
        "unit3",
        "spin-X",
        "spin-Y",
        "spin-Z",
        "swing-X",
        "swing-Y",
        "swing-Z",
        "hop",
        "hop-parent",
        "orbit",
        "orbit-parent",
        "orbit-parent-lecture",
        "satellite",
    ] {
        assert!(seen.contains(f), "{f} is not among the sample students: {seen:?}");
    }
}

fn run(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    cg_a3::checks(spec, imp)
}

fn failed(results: &[CheckResult]) -> BTreeSet<String> {
    results.iter().filter(|c| !c.passed()).map(|c| c.id.clone()).collect()
}

fn report(student: &str, results: &[CheckResult]) -> String {
    Report { assignment: "a3".into(), student: Some(student.into()), checks: results.to_vec() }
        .render(Lang::En)
}

/// Runs `f` for every student on its own thread (each check run spends most of its time on the
/// 10⁶ frames of the drift check).
fn for_students<T: Send>(students: &[&str], f: impl Fn(&str) -> T + Sync) -> Vec<T> {
    std::thread::scope(|s| {
        let handles: Vec<_> = students.iter().map(|&st| s.spawn(|| f(st))).collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    })
}

#[test]
fn every_check_passes_on_the_solution() {
    let imp = cg_solutions::a3::implementation();
    for_students(&STUDENTS, |s| {
        let results = run(&spec_for(s), &imp);
        assert_eq!(results.len(), 13);
        assert!(failed(&results).is_empty(), "student {s}:\n{}", report(s, &results));
    });
}

#[test]
fn every_check_is_not_done_yet_on_the_pristine_stubs() {
    let imp = cg_exercises::a3::implementation();
    for_students(&STUDENTS[..2], |s| {
        let report = Report {
            assignment: "a3".into(),
            student: Some(s.into()),
            checks: run(&spec_for(s), &imp),
        };
        // The stubs run (the view draws the ground) and carry their task's marker,
        // `cg_student::not_started("a3.t1");`: every check is "not done yet", naming its own task.
        for c in &report.checks {
            let Outcome::NotDone { message } = &c.outcome else {
                panic!("{s}: {} is {:?}, not \"not done yet\"", c.id, c.outcome)
            };
            let line = format!("{}: 書き始めたら cg_student::not_started(\"{}\");", c.task, c.task);
            assert!(message.starts_with(&line), "{s}: {}: {message}", c.id);
        }
        assert_eq!(report.tasks_not_done(), ["a3.t0", "a3.t1", "a3.t2"], "{s}");
        assert!(report.tasks_failing().is_empty(), "{s}");
        let en = report.render(Lang::En);
        assert!(
            en.contains("; not done yet: a3.t0, a3.t1, a3.t2\n") && !en.contains("to fix"),
            "{en}"
        );
    });
}

/// The stubs' bodies without their markers: a student who deleted the lines and wrote nothing
/// yet.
fn unmarked_stubs() -> Impl {
    Impl { warmup_display: |_, _| {}, idle: |_, _| {}, display: |_, _, _| {} }
}

#[test]
fn without_their_markers_the_stubs_are_judged_and_fail() {
    let imp = unmarked_stubs();
    for_students(&STUDENTS[..2], |s| {
        let results = run(&spec_for(s), &imp);
        for c in &results {
            assert!(matches!(c.outcome, Outcome::Fail(_)), "{s}: {} is {:?}", c.id, c.outcome);
        }
        // Drift says the task is not done yet (nothing is drawn), not that anything drifts.
        let Outcome::Fail(f) = check_of(&results, "a3.t1.drift").outcome else { unreachable!() };
        assert!(f.cause.en.contains("not done yet"), "{f:?}");
    });
}

#[test]
fn the_marker_wins_while_it_is_there_and_only_for_the_checks_that_reach_it() {
    let spec = spec_for(STUDENTS[0]);
    // The reference's functions with their markers left in: every check is not done yet.
    let marked = Impl {
        warmup_display: |gl, t| {
            cg_student::not_started("a3.t0");
            cg_solutions::a3::warmup_display(gl, t);
        },
        idle: |spec, state| {
            cg_student::not_started("a3.t1");
            cg_solutions::a3::idle(spec, state);
        },
        display: |spec, state, gl| {
            cg_student::not_started("a3.t2");
            cg_solutions::a3::display(spec, state, gl);
        },
    };
    for c in run(&spec, &marked) {
        assert!(matches!(c.outcome, Outcome::NotDone { .. }), "{}: {:?}", c.id, c.outcome);
    }
    // The warm-up's line deleted: a3.t0 is judged (and passes); the rest is still not done.
    let warmed_up = Impl { warmup_display: cg_solutions::a3::warmup_display, ..marked };
    for c in run(&spec, &warmed_up) {
        if c.task == "a3.t0" {
            assert!(c.passed(), "{}: {:?}", c.id, c.outcome);
        } else {
            assert!(matches!(c.outcome, Outcome::NotDone { .. }), "{}: {:?}", c.id, c.outcome);
        }
    }
}

mod a3_bugs;
use a3_bugs::*;

/// The student each broken answer is run for: 20260002 has the lecture's two orbits (the outer
/// one the parent), a spin and periods whose f32 steps are inexact (unit 2.5 s); 20260005 has a
/// hopping parent, a swing and a second hop.
fn student_for(bug: Bug) -> &'static str {
    match bug {
        Bug::LinearHop | Bug::SineOfDegrees | Bug::WarmupNoPushPop | Bug::WarmupWrongHeight => {
            "20260005"
        }
        _ => "20260002",
    }
}

/// The checks of every broken answer for its student, run once (each on its own thread) for
/// the tests below.
fn broken_outcomes() -> &'static [(Bug, &'static str, Vec<CheckResult>)] {
    static OUTCOMES: OnceLock<Vec<(Bug, &'static str, Vec<CheckResult>)>> = OnceLock::new();
    OUTCOMES.get_or_init(|| {
        let answers = broken_answers();
        std::thread::scope(|s| {
            let handles: Vec<_> = answers
                .iter()
                .map(|(bug, imp, _, _)| {
                    let st = student_for(*bug);
                    s.spawn(move || (*bug, st, run(&spec_for(st), imp)))
                })
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        })
    })
}

#[test]
fn broken_answers_fail_the_checks_that_name_their_mistake() {
    let answers = broken_answers();
    let all_ids: BTreeSet<String> =
        run(&spec_for(STUDENTS[0]), &cg_solutions::a3::implementation())
            .into_iter()
            .map(|c| c.id)
            .collect();
    let outcomes = broken_outcomes();
    let mut caught: BTreeMap<String, Vec<Bug>> = BTreeMap::new();
    for (bug, student, results) in outcomes {
        let (_, _, must_fail, must_pass) = answers.iter().find(|a| a.0 == *bug).unwrap();
        let failing = failed(results);
        for id in *must_fail {
            assert!(
                failing.contains(*id),
                "{bug:?} ({student}) should fail {id}:\n{}",
                report(student, results)
            );
        }
        for id in *must_pass {
            assert!(
                !failing.contains(*id),
                "{bug:?} ({student}) should pass {id}:\n{}",
                report(student, results)
            );
        }
        if *bug == Bug::None {
            assert!(
                failing.is_empty(),
                "the test's own clean answer fails:\n{}",
                report(student, results)
            );
        }
        for id in failing {
            caught.entry(id).or_default().push(*bug);
        }
        // Every failure explains itself in both languages and says where.
        for c in results {
            if let Outcome::Fail(f) = &c.outcome {
                assert!(!f.expected.is_empty() && !f.actual.is_empty(), "{}: {f:?}", c.id);
                assert!(
                    f.location.as_ref().is_some_and(|l| !l.is_empty()),
                    "{} has no location: {f:?}",
                    c.id
                );
                for text in [&f.cause, &f.hint] {
                    assert!(!text.ja.is_empty() && !text.en.is_empty(), "{}: {f:?}", c.id);
                }
            } else {
                assert!(c.passed(), "{} neither passed nor failed: {:?}", c.id, c.outcome);
            }
        }
    }
    for id in &all_ids {
        assert!(caught.contains_key(id), "no broken answer fails {id}: {caught:?}");
    }
    // The messages name the mistake and the place: (answer, check, words in the cause, expected
    // or actual, words in the location).
    let named: [(Bug, &str, &str, &str); 25] = [
        (Bug::NoPushPop, "a3.t2.independent", "still apply", "object"),
        (Bug::ExtraPop, "a3.t2.stack", "GL_STACK_UNDERFLOW", "display()"),
        (Bug::MissingPop, "a3.t2.stack", "glPopMatrix missing", "display()"),
        (Bug::Radians, "a3.t2.poses", "radians", "t = "),
        (Bug::F32Accumulate, "a3.t1.drift", "accumulated in f32", "frame 1000000"),
        (Bug::Radians, "a3.t1.drift", "drift cannot be measured", "object"),
        (Bug::ChildIgnoresParentRotation, "a3.t2.hierarchy", "not its rotation", "object 3"),
        (Bug::ThirtyFps, "a3.t2.hierarchy", "twice as fast", "object 3"),
        (Bug::ChildReversed, "a3.t2.hierarchy", "reversed", "object 3"),
        (Bug::ChildOutsideParent, "a3.t2.hierarchy", "world's origin", "object 3"),
        (Bug::LightBeforeCamera, "a3.t2.light", "before the view transform", "GL_LIGHT0"),
        (Bug::OneFrameLate, "a3.t2.poses", "one frame late", "frame"),
        // The origin shown beside a product with the camera is the world's (the camera taken
        // off), and says so.
        (Bug::OneFrameLate, "a3.t2.poses", "in the world (the camera's factors taken off)", "t = "),
        (Bug::WrongPeriod, "a3.t1.periods", "the period is 10 s instead of 2.5 s", "object 1"),
        (Bug::WrongPeriod, "a3.t2.poses", "period of 10 s instead of 2.5 s", "object 1"),
        (Bug::ThirtyFps, "a3.t2.poses", "twice as fast", "t = "),
        (Bug::WarmupLinearHop, "a3.t0.box3", "parabola", "box 3, t = "),
        // Degrees into sin (issue 7): said where the period, the ratio and the pose are off.
        (Bug::SineOfDegrees, "a3.t1.periods", "degrees went into sin/cos as radians", "object 1"),
        (Bug::SineOfDegrees, "a3.t1.ratios", "object 1: degrees went into sin/cos", "object 1"),
        (Bug::SineOfDegrees, "a3.t2.poses", "degrees went into sin/cos as radians", "object 1"),
        (Bug::WarmupSineOfDegrees, "a3.t0.box2", "degrees went into sin/cos", "box 2, t = "),
        // Radians into glRotatef: the same words in the period and ratio checks as in the poses'.
        (Bug::Radians, "a3.t1.periods", "the angle is in radians (glRotatef", "object 2"),
        (Bug::Radians, "a3.t1.ratios", "object 2: the angle is in radians", "object 2"),
        // A wrong period measured through display()'s leak (issue 6): the leak is named first.
        (
            Bug::LeakAndWrongPeriod,
            "a3.t1.periods",
            "see a3.t2.stack and a3.t2.independent",
            "object 4",
        ),
        (
            Bug::LeakAndWrongPeriod,
            "a3.t1.ratios",
            "object 4: most likely a glPushMatrix / glPopMatrix missing",
            "object 4",
        ),
    ];
    for (bug, id, words, place) in named {
        let (_, _, results) = outcomes.iter().find(|o| o.0 == bug).unwrap();
        let c = results.iter().find(|c| c.id == id).unwrap();
        let Outcome::Fail(f) = &c.outcome else {
            panic!("{bug:?}: {id} does not fail: {:?}", c.outcome)
        };
        let text = format!("{} | {} | {}", f.cause.en, f.expected, f.actual);
        assert!(text.contains(words), "{bug:?}: {id}: {words:?} not in {text:?}");
        let at = f.location.as_ref().map_or("", |l| l.en.as_str());
        assert!(at.contains(place), "{bug:?}: {id}: {place:?} not in the location {at:?}");
        assert!(f.cause.ja != f.cause.en && f.hint.ja != f.hint.en, "{id}: {f:?}");
    }
}

// `a3.t1.drift` measures drift alone (issue 14): it compares the student's own pose at frame
// 10⁶ with the student's own pose at the frame of the same phase early on, not with the
// expected pose, so a mistake in the pose is not counted twice.

/// The numbers right after each `word` in `text` (`frame 1000` in `…, frame 1000000 vs frame
/// 1000` gives 1000000 and 1000).
fn frames_named(text: &str, word: &str) -> Vec<u64> {
    text.split(word)
        .skip(1)
        .filter_map(|rest| {
            let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
            digits.parse().ok()
        })
        .collect()
}

/// The result of check `id` in `results`.
fn check_of(results: &[CheckResult], id: &str) -> CheckResult {
    results.iter().find(|c| c.id == id).unwrap().clone()
}

/// The checks of broken answer `bug`, from [`broken_outcomes`].
fn outcome_of(bug: Bug) -> &'static [CheckResult] {
    &broken_outcomes().iter().find(|o| o.0 == bug).unwrap().2
}

#[test]
fn drift_passes_the_reference() {
    let imp = cg_solutions::a3::implementation();
    for_students(&STUDENTS[..2], |s| {
        let results = run(&spec_for(s), &imp);
        assert!(check_of(&results, "a3.t1.drift").passed(), "{}", report(s, &results));
    });
}

/// An angle accumulated in f32 every frame (`θ += 360°/P`) fails, and the message says which two
/// frames it compared: 10⁶ and 10⁶ mod the common period.
#[test]
fn drift_fails_an_angle_accumulated_in_f32_and_names_both_frames() {
    use cg_a3::SpecExt as _;
    let student = student_for(Bug::F32Accumulate);
    let spec = spec_for(student);
    let common = (spec.common_period_s() * f64::from(cg_a3::FPS)).round() as u64;
    let early = match cg_a3::DRIFT_FRAMES % common {
        0 => common,
        r => r,
    };
    let results = outcome_of(Bug::F32Accumulate);
    let Outcome::Fail(f) = check_of(results, "a3.t1.drift").outcome else {
        panic!("f32 accumulation passes drift:\n{}", report(student, results))
    };
    let at = f.location.as_ref().unwrap();
    for (text, word) in [
        (&at.en, "frame "),
        (&at.ja, "フレーム "),
        (&f.expected.en, "frame "),
        (&f.expected.ja, "フレーム "),
    ] {
        let named = frames_named(text, word);
        for frame in [cg_a3::DRIFT_FRAMES, early] {
            assert!(named.contains(&frame), "frame {frame} not in {text:?}");
        }
    }
    assert!(f.cause.en.contains("accumulated in f32"), "{f:?}");
}

/// Every angle's sign flipped, at every frame and exactly: the pose checks fail, drift passes
/// (the pose at frame 10⁶ is the same wrong pose as one common period in).
#[test]
fn drift_passes_a_pose_wrong_the_same_way_at_every_frame() {
    let student = student_for(Bug::MirroredTurn);
    let results = outcome_of(Bug::MirroredTurn);
    assert!(!check_of(results, "a3.t2.poses").passed(), "{}", report(student, results));
    assert!(check_of(results, "a3.t1.drift").passed(), "{}", report(student, results));
}

/// The hierarchy's message writes the child's pose relative to its parent as the docs do in each
/// language (issue 16): `M_親⁻¹ · M_子` in Japanese, `M_parent⁻¹ · M_child` in English.
#[test]
fn the_hierarchy_writes_the_relative_pose_as_the_docs_do() {
    let docs = include_str!("../../docs/assignments/a3.md");
    let (ja_docs, en_docs) = docs.split_once("## English").unwrap();
    let results = outcome_of(Bug::ChildReversed);
    let Outcome::Fail(f) = check_of(results, "a3.t2.hierarchy").outcome else {
        panic!("{}", report(student_for(Bug::ChildReversed), results))
    };
    for (text, docs, notation) in [
        (&f.expected.ja, ja_docs, "M_親⁻¹ · M_子"),
        (&f.expected.en, en_docs, "M_parent⁻¹ · M_child"),
    ] {
        assert!(text.starts_with(notation), "{text:?}");
        assert!(docs.contains(notation), "{notation} is not in the docs");
    }
    assert!(!f.expected.ja.contains("parent") && !f.expected.ja.contains("child"), "{f:?}");
}

/// The docs' table of usual mistakes quotes what the checks say about degrees and radians
/// (issue 7), in each language.
#[test]
fn the_docs_quote_the_degrees_and_radians_messages() {
    let docs = include_str!("../../docs/assignments/a3.md");
    let (ja_docs, en_docs) = docs.split_once("## English").unwrap();
    for (bug, id) in [
        (Bug::SineOfDegrees, "a3.t1.periods"),
        (Bug::SineOfDegrees, "a3.t2.poses"),
        (Bug::WarmupSineOfDegrees, "a3.t0.box2"),
        (Bug::Radians, "a3.t1.periods"),
        (Bug::Radians, "a3.t2.poses"),
    ] {
        let Outcome::Fail(f) = check_of(outcome_of(bug), id).outcome else {
            panic!("{bug:?}: {id} passes")
        };
        assert!(ja_docs.contains(&format!("「{}」", f.cause.ja)), "{bug:?} {id}: {}", f.cause.ja);
        assert!(en_docs.contains(&f.cause.en), "{bug:?} {id}: {}", f.cause.en);
    }
}

#[test]
fn the_view_draws_the_objects_on_the_ground() {
    let spec = spec_for(STUDENTS[0]);
    let scene = cg_a3::view(&spec, &cg_solutions::a3::implementation(), 1.5).unwrap();
    let names: Vec<&str> = scene.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names[0], "ground");
    assert_eq!(names.len(), 1 + spec.objects.len(), "{names:?}");
    // The stubs draw the ground alone (a window still opens).
    let stub = cg_a3::view(&spec, &cg_exercises::a3::implementation(), 1.5).unwrap();
    assert_eq!(stub.objects.len(), 1);
    // Object 2 (the lecture's outer orbit) at t = 1.5 s sits where the oracle puts it.
    let at = scene.objects[2].transform.matrix().unwrap().as_dmat4().w_axis.truncate();
    let model = cg_a3::expected_model(&spec, 1, 90);
    let camera = cg_a3::camera_product().matrix().unwrap().as_dmat4();
    let want = (camera * model).w_axis.truncate();
    assert!((at - want).length() < 1e-4, "{at} vs {want}");
    assert_eq!(cg_a3::warmup_view(&cg_solutions::a3::implementation(), 0.5).objects.len(), 4);
    // The reference's frames carry the variables' names for the report.
    let gl = cg_a3::record_frame(&spec, &cg_solutions::a3::implementation(), 90);
    let child = gl.draws().iter().find(|d| d.name == "object 3").unwrap();
    assert_eq!(
        child.model_view.symbolic(),
        "T(0, 0, -15) · Rx(30°) · T(0, 1, 0) · Ry(theta_2) · T(0, 0, 3) · Ry(theta_3) · T(0, 0, 1.2)"
    );
    assert_eq!(
        cg_a3::model_product(&spec, 2, 90).symbolic(),
        "T(0, 1, 0) · Ry(theta_2) · T(0, 0, 3) · Ry(theta_3) · T(0, 0, 1.2)"
    );
}

/// The spec's JSON carries the table's numbers (`0.6`, not f32's widening `0.6000000238418579`).
#[test]
fn the_spec_json_has_the_tables_numbers() {
    for s in STUDENTS {
        let student: StudentNumber = s.parse().unwrap();
        let json = cg_assign::Variants::for_student(&student, TableVersion::V1).to_json()["a3"]
            .to_string();
        assert!(!json.contains("0000000") && !json.contains("9999999"), "{json}");
        assert!(json.contains("\"period_s\"") && json.contains("\"unit_s\""), "{json}");
    }
}

// ---------------------------------------------------------------------------------------------
// One language at a time
// ---------------------------------------------------------------------------------------------

/// The identifiers that are plain words and that the Japanese report and assignment text
/// really use, as code: the student's functions and their parameters (`idle(spec, state)`,
/// `display()`, `gl.draw("box 1", &mesh)`), the names the objects are drawn with
/// (`"object 1"`), and `push` in the core's message for GL_STACK_UNDERFLOW (「対応する push のない
/// pop です」). (Identifiers shaped like code — `warmup_display`, `state.frame`, `glPushMatrix`,
/// `to_radians` — need no listing; see `common::english_words`.)
const CODE_WORDS: &[&str] = &["display", "idle", "spec", "state", "mesh", "object", "push"];

#[test]
fn reports_read_in_one_language() {
    let mut problems = Vec::new();
    for (bug, student, results) in broken_outcomes() {
        let report = Report {
            assignment: "a3".into(),
            student: Some((*student).into()),
            checks: results.clone(),
        };
        problems.extend(common::report_problems(
            &format!("{bug:?} / {student}"),
            &report,
            CODE_WORDS,
        ));
    }
    let stubs = cg_exercises::a3::implementation();
    let stub_reports = for_students(&STUDENTS[..2], |s| Report {
        assignment: "a3".into(),
        student: Some(s.into()),
        checks: run(&spec_for(s), &stubs),
    });
    for report in &stub_reports {
        let context = format!("the stubs / {}", report.student.as_deref().unwrap_or_default());
        problems.extend(common::report_problems(&context, report, CODE_WORDS));
    }
    for s in STUDENTS {
        let spec = spec_for(s);
        problems.extend(common::language_problems(
            &format!("describe / {s}"),
            &spec.describe(Lang::Ja),
            &spec.describe(Lang::En),
            CODE_WORDS,
        ));
        if let Err(why) = cg_a3::view(&spec, &stubs, -1.0) {
            problems.extend(common::language_problems("view", &why.ja, &why.en, CODE_WORDS));
        }
    }
    common::assert_no_problems(&problems);
}
