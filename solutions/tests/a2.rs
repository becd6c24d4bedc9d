//! Assignment a2 (camera interface): the reference answers pass every check for students whose
//! variants cover every option of the table; the pristine stubs are "not done yet" in every
//! check (their markers), and fail every check without the markers; the variant
//! table is deterministic, valid and diverse; the texts name the tasks in both languages; the
//! report's product and the view come out of the student's code.

// The assignment crates, through the kit's one list (cg-assign).
use cg_assign::cg_a2;

use std::collections::BTreeSet;

use cg_a2::SpecExt as _;
use cg_a2::{CameraState, DragAxis, Gesture, Impl, MouseButton, Spec};
use cg_core::lang::{Lang, t};
use cg_harness::check::{Outcome, Report};
use cg_harness::{StudentNumber, TableVersion, VariantRng};

/// Students whose variants together cover all 8 layouts, all 6 pitch ranges, both kinds of
/// distance drag, with and without a pan, and both signs of every operation (asserted below).
const STUDENTS: [&str; 10] = [
    "20260001", "20260002", "20260003", "20260004", "20260005", "20260007", "20260009", "20260010",
    "20260013", "20260021",
];

fn spec_of(student: &str) -> Spec {
    let n: StudentNumber = student.parse().expect("a valid student number");
    cg_a2::variant(&mut VariantRng::new(&n, TableVersion::V1, cg_a2::ID))
}

fn gesture_name(g: Gesture) -> String {
    let b = match g.button {
        MouseButton::Left => "L",
        MouseButton::Middle => "M",
        MouseButton::Right => "R",
    };
    if g.shift { format!("S{b}") } else { b.to_owned() }
}

/// The layout of a spec, as (rotate gesture, distance gesture): unique per layout of the table.
fn layout(spec: &Spec) -> (String, String) {
    (gesture_name(spec.yaw.gesture), gesture_name(spec.distance.gesture))
}

#[test]
fn the_chosen_students_cover_every_option() {
    let specs: Vec<Spec> = STUDENTS.iter().map(|s| spec_of(s)).collect();
    let layouts: BTreeSet<_> = specs.iter().map(layout).collect();
    assert_eq!(layouts.len(), 8, "{layouts:?}");
    let ranges: BTreeSet<_> =
        specs.iter().map(|s| (s.pitch_min as i32, s.pitch_max as i32)).collect();
    assert_eq!(ranges.len(), 6, "{ranges:?}");
    let has = |f: &dyn Fn(&Spec) -> bool| specs.iter().any(f) && !specs.iter().all(f);
    assert!(has(&|s| s.pan.is_some()), "with and without a pan");
    assert!(has(&|s| s.distance.axis == DragAxis::Vertical), "both distance drags");
    assert!(has(&|s| s.yaw.per_px > 0.0), "both yaw signs");
    assert!(has(&|s| s.pitch.per_px > 0.0), "both pitch signs");
    assert!(has(&|s| s.distance.per_px > 0.0), "both distance signs");
    assert!(has(&|s| s.pitch_min == -90.0), "the pole reachable and not");
}

#[test]
fn every_check_passes_on_the_reference_answers() {
    let solution = cg_solutions::a2::implementation();
    for student in STUDENTS {
        let spec = spec_of(student);
        let results = cg_a2::checks(&spec, &solution);
        let expected = if spec.pan.is_some() { 16 } else { 14 };
        assert_eq!(results.len(), expected, "{student}");
        for r in &results {
            assert!(r.passed(), "{student}: {} failed on the solution: {:?}", r.id, r.outcome);
            assert!(r.id.starts_with(&format!("{}.", r.task)), "{}", r.id);
            assert!(!r.title.ja.is_empty() && !r.title.en.is_empty(), "{}", r.id);
        }
    }
}

#[test]
fn every_check_is_not_done_yet_on_the_pristine_stubs() {
    let stub = cg_exercises::a2::implementation();
    for student in STUDENTS {
        let spec = spec_of(student);
        let report = Report {
            assignment: cg_a2::ID.into(),
            student: Some(student.into()),
            checks: cg_a2::checks(&spec, &stub),
        };
        // The stubs run (the window must still open) and carry their task's marker,
        // `cg_student::not_started("a2.t1");`: every check is "not done yet" for its own task.
        for r in &report.checks {
            let Outcome::NotDone { message } = &r.outcome else {
                panic!("{student}: {} is {:?}, not \"not done yet\"", r.id, r.outcome)
            };
            assert!(message.starts_with(&format!("{}: ", r.task)), "{}: {message}", r.id);
            let line = format!("cg_student::not_started(\"{}\");", r.task);
            assert!(message.contains(&line), "{}: {message}", r.id);
        }
        assert_eq!(report.tasks_not_done(), ["a2.t1", "a2.t2", "a2.t3"], "{student}");
        assert!(report.tasks_failing().is_empty(), "{student}");
        let en = report.render(Lang::En);
        assert!(
            en.contains("; not done yet: a2.t1, a2.t2, a2.t3\n") && !en.contains("to fix"),
            "{en}"
        );
        let ja = report.render(Lang::Ja);
        assert!(ja.contains("まだです: a2.t1（書き始めたら") && !ja.contains("直すところ"), "{ja}");
    }
}

/// The stubs' bodies without their markers: a student who deleted the lines and wrote nothing
/// (or nothing right) yet.
fn unmarked_stubs() -> Impl {
    Impl { motion: |_, _, _| {}, camera: |_, _| {}, display: |gl, _| gl.load_identity() }
}

#[test]
fn without_their_markers_the_stubs_are_judged_and_fail_with_explanations() {
    for student in STUDENTS {
        let spec = spec_of(student);
        for r in cg_a2::checks(&spec, &unmarked_stubs()) {
            // Placeholders, not `todo!()`s: they fail, never panic.
            let Outcome::Fail(f) = &r.outcome else {
                panic!("{student}: {} is {:?}, not a failure", r.id, r.outcome)
            };
            for text in [&f.cause, &f.hint] {
                assert!(!text.ja.is_empty() && !text.en.is_empty(), "{}: {f:?}", r.id);
            }
            assert!(f.location.as_ref().is_some_and(|l| !l.is_empty()), "{}: {f:?}", r.id);
        }
    }
}

/// The reference's functions with the stubs' markers left in: a student who wrote the code but
/// kept the line.
fn marked_solution() -> Impl {
    Impl {
        motion: |spec, state, drag| {
            cg_student::not_started("a2.t1");
            cg_solutions::a2::motion(spec, state, drag);
        },
        camera: |gl, state| {
            cg_student::not_started("a2.t2");
            cg_solutions::a2::camera(gl, state);
        },
        display: |gl, state| {
            cg_student::not_started("a2.t3");
            cg_solutions::a2::display(gl, state);
        },
    }
}

#[test]
fn the_marker_wins_while_it_is_there_and_only_for_the_checks_that_reach_it() {
    let spec = spec_of(STUDENTS[0]);
    // Right code or wrong code: while the line is there, its task is not done yet.
    for imp in [
        marked_solution(),
        Impl {
            motion: |_, state, _| {
                cg_student::not_started("a2.t1");
                state.camera_yaw = 1e9;
            },
            ..marked_solution()
        },
    ] {
        for r in cg_a2::checks(&spec, &imp) {
            assert!(matches!(r.outcome, Outcome::NotDone { .. }), "{}: {:?}", r.id, r.outcome);
        }
    }
    // One line deleted: that task is judged (and passes), the others are still not done.
    let started = Impl { camera: cg_solutions::a2::camera, ..marked_solution() };
    for r in cg_a2::checks(&spec, &started) {
        match r.task.as_str() {
            "a2.t2" => assert!(r.passed(), "{}: {:?}", r.id, r.outcome),
            _ => assert!(matches!(r.outcome, Outcome::NotDone { .. }), "{}: {:?}", r.id, r.outcome),
        }
    }
    // display() calls the student's camera(): a check of a2.t3 that reaches a2.t2's marker is
    // not done yet, and says which line is left.
    let display_only = Impl {
        display: |gl, state| {
            gl.load_identity();
            (marked_solution().camera)(gl, state);
            gl.light_position(0, cg_student::a2::LIGHT0_POSITION);
            cg_student::a2::draw_course_objects(gl);
        },
        ..unmarked_stubs()
    };
    for r in cg_a2::checks(&spec, &display_only).iter().filter(|r| r.task == "a2.t3") {
        let Outcome::NotDone { message } = &r.outcome else { panic!("{}: {:?}", r.id, r.outcome) };
        assert!(message.starts_with("a2.t2: "), "{}: {message}", r.id);
    }
}

#[test]
fn variants_are_deterministic_valid_and_exact() {
    for n in 0..300u32 {
        let student = format!("{:08}", 20_250_000 + n * 7);
        let spec = spec_of(&student);
        assert_eq!(spec, spec_of(&student), "deterministic");
        let s = spec.start;
        assert!((spec.pitch_min..=spec.pitch_max).contains(&s.camera_pitch), "{student}");
        assert!((spec.distance_min..=spec.distance_max).contains(&s.camera_distance), "{student}");
        assert!((0.0..360.0).contains(&s.camera_yaw), "{student}");
        assert_eq!((s.target_x, s.target_z), (0.0, 0.0));
        // Yaw and pitch share the rotate gesture, dx and dy; every gesture of a spec is distinct
        // per operation pair (the distance never shares the rotate gesture).
        assert_eq!(spec.yaw.gesture, spec.pitch.gesture);
        assert_eq!((spec.yaw.axis, spec.pitch.axis), (DragAxis::Horizontal, DragAxis::Vertical));
        assert_ne!(spec.distance.gesture, spec.yaw.gesture, "{student}");
        if let Some(pan) = spec.pan {
            assert_eq!(pan.x.gesture, pan.z.gesture);
            assert_ne!(pan.x.gesture, spec.yaw.gesture, "{student}");
            assert_ne!(pan.x.gesture, spec.distance.gesture, "{student}");
            assert!(pan.limit > 0.0 && pan.limit <= 5.0);
        }
        // Friendly numbers: every speed times a whole number of pixels is exact in quarter
        // degrees (angles) or in hundredths (lengths).
        for per_px in [spec.yaw.per_px, spec.pitch.per_px] {
            assert_eq!((per_px * 4.0).fract(), 0.0, "{student}: {per_px}");
        }
    }
}

#[test]
fn the_spec_is_json_for_tools() {
    for student in STUDENTS {
        let n: StudentNumber = student.parse().unwrap();
        let json = cg_assign::Variants::for_student(&n, TableVersion::V1).to_json();
        let a2 = &json["a2"];
        assert!(
            ["left", "middle", "right"].contains(&a2["yaw"]["gesture"]["button"].as_str().unwrap())
        );
        assert!(a2["yaw"]["per_px"].is_number() && a2["pitch_min"].is_number(), "{a2}");
        assert_eq!(a2["pan"].is_null(), spec_of(student).pan.is_none(), "{a2}");
        assert!(["horizontal", "vertical"].contains(&a2["distance"]["axis"].as_str().unwrap()));
    }
}

#[test]
fn the_table_is_diverse_among_a_few_dozen_students() {
    let specs: Vec<Spec> =
        (1..=48u32).map(|n| spec_of(&format!("{:08}", 20_260_000 + n))).collect();
    let count =
        |key: &dyn Fn(&Spec) -> String| specs.iter().map(key).collect::<BTreeSet<_>>().len();
    assert_eq!(count(&|s| format!("{:?}", layout(s))), 8, "layouts");
    assert_eq!(count(&|s| s.yaw.per_px.abs().to_string()), 5, "yaw speeds");
    assert_eq!(count(&|s| s.pitch.per_px.abs().to_string()), 5, "pitch speeds");
    assert_eq!(count(&|s| s.distance.per_px.abs().to_string()), 5, "distance speeds");
    assert_eq!(count(&|s| format!("{} {}", s.pitch_min, s.pitch_max)), 6, "pitch ranges");
    assert_eq!(count(&|s| s.distance_min.to_string()), 4, "closest distances");
    assert_eq!(count(&|s| s.distance_max.to_string()), 4, "farthest distances");
    assert_eq!(count(&|s| s.start.camera_yaw.to_string()), 6, "start yaws");
    assert_eq!(count(&|s| s.start.camera_pitch.to_string()), 4, "start pitches");
    assert_eq!(count(&|s| s.start.camera_distance.to_string()), 4, "start distances");
    let pans: Vec<_> = specs.iter().filter_map(|s| s.pan).collect();
    assert!(pans.len() >= 12, "{} pans", pans.len());
    let pan_count =
        |key: &dyn Fn(&cg_a2::Pan) -> String| pans.iter().map(key).collect::<BTreeSet<_>>().len();
    assert_eq!(pan_count(&|p| p.x.per_px.abs().to_string()), 4, "pan speeds");
    assert_eq!(pan_count(&|p| p.limit.to_string()), 3, "pan limits");
    // The whole combination differs between students far more often than not.
    let distinct: BTreeSet<String> = specs.iter().map(|s| format!("{s:?}")).collect();
    assert_eq!(distinct.len(), specs.len());
}

#[test]
fn the_text_names_every_task_and_the_students_numbers_in_both_languages() {
    for student in STUDENTS {
        let spec = spec_of(student);
        for lang in [Lang::Ja, Lang::En] {
            let text = spec.describe(lang);
            for needle in
                ["a2.t1", "a2.t2", "a2.t3", "camera_yaw", "camera_pitch", "camera_distance"]
            {
                assert!(text.contains(needle), "{student} {lang}: no {needle} in\n{text}");
            }
            let speed = cg_core::product::format_number(spec.yaw.per_px.abs());
            assert!(
                text.contains(&format!(
                    "camera_yaw {} {speed} * dx",
                    if spec.yaw.per_px < 0.0 { "-=" } else { "+=" }
                )),
                "{text}"
            );
            let range = format!(
                "{} ≤ camera_pitch ≤ {}",
                cg_core::product::format_number(spec.pitch_min),
                cg_core::product::format_number(spec.pitch_max)
            );
            assert!(text.contains(&range), "{student} {lang}: no {range} in\n{text}");
            // The target moves with the mouse exactly for the students with a pan.
            assert_eq!(
                text.contains("target_x +=") || text.contains("target_x -="),
                spec.pan.is_some()
            );
            assert!(text.contains(t("レポート", "report").get(lang)), "{text}");
        }
        let vars = spec.variables();
        assert_eq!(vars.len(), if spec.pan.is_some() { 5 } else { 3 });
        assert!(
            vars.iter().all(|(name, text)| text.ja.starts_with(name.as_str())
                && text.en.starts_with(name.as_str()))
        );
    }
}

#[test]
fn the_reports_product_comes_from_the_students_camera() {
    let product = cg_a2::camera_product(&cg_solutions::a2::implementation()).expect("solution");
    assert_eq!(
        product.symbolic(),
        "T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw) · T(-target_x, 0, -target_z)"
    );
    assert!(product.latex(true).expect("latex").contains(r"\cos(-\mathit{camera\_pitch})"));
    // The stub builds nothing: the identity.
    assert_eq!(cg_a2::camera_product(&cg_exercises::a2::implementation()).unwrap().symbolic(), "I");
    // The spec's product has the same matrix as the reference's at any state (independently of
    // the probe): checked against the core's orbit camera.
    let s = CameraState {
        camera_yaw: 123.5,
        camera_pitch: -67.25,
        camera_distance: 7.5,
        target_x: -1.5,
        target_z: 2.0,
    };
    let expected = cg_a2::expected_product(&spec_of("20260021"), &s).matrix().unwrap();
    let orbit = cg_core::camera::OrbitCamera {
        yaw_deg: s.camera_yaw,
        pitch_deg: s.camera_pitch,
        distance: s.camera_distance,
        target: cg_core::glam::Vec3::new(s.target_x, 0.0, s.target_z),
        ..cg_core::camera::OrbitCamera::course_sample()
    };
    let eye = expected.inverse() * cg_core::glam::Vec4::W;
    let oracle_eye = orbit.eye_position();
    assert!((eye.truncate() - oracle_eye).abs().max_element() < 1e-4, "{eye} vs {oracle_eye}");
}

#[test]
fn the_view_draws_the_students_frame() {
    for student in ["20260004", "20260021", "20260002"] {
        let spec = spec_of(student);
        let scene = cg_a2::view(&spec, &cg_solutions::a2::implementation(), 0.0).expect("a scene");
        let names: Vec<&str> = scene.objects.iter().map(|o| o.name.as_str()).collect();
        assert_eq!(names, ["ground", "pyramid"]);
        // The scripted drags turn the camera by 40° from the start (and 30° per second).
        let later = cg_a2::view(&spec, &cg_solutions::a2::implementation(), 2.0).expect("a scene");
        assert_ne!(scene.objects[0].transform, later.objects[0].transform, "time turns the view");
        // The stubs draw nothing yet: the view says so instead of an empty picture, as a
        // stub's `todo!()` would ("not done yet", which `cg view` ends with 0).
        let stubs = cg_exercises::a2::implementation();
        let Err(why) = cg_harness::check::guarded(|| cg_a2::view(&spec, &stubs, 0.0)) else {
            panic!("the stubs' view is not \"not done yet\"");
        };
        assert!(
            matches!(&why, Outcome::NotDone { message } if message.starts_with("a2.t3: ")),
            "{why:?}"
        );
        // Without its marker, a display() that draws nothing is a mistake, said as one.
        let empty = Impl { display: |gl, _| gl.load_identity(), ..stubs };
        let Err(why) = cg_a2::view(&spec, &empty, 0.0) else { panic!("a picture of nothing") };
        assert!(why.en.starts_with("nothing is drawn: display() (a2.t3)"), "{why:?}");
    }
}

/// A motion() that panics on a drag of the view's script: no picture (it showed the camera
/// where it started, beside the reference, and `cg view` ended with 0), and the reason names
/// motion(), its message and place, and the drag with the state it started from. A stub's
/// `todo!()` there still leaves the camera where it starts.
#[test]
fn a_motion_that_panics_gives_no_picture_and_says_on_which_drag() {
    fn too_far(spec: &Spec, s: &mut CameraState, drag: &cg_a2::Drag) {
        assert!(drag.dx.abs() <= 10.0 && drag.dy.abs() <= 10.0, "too far: {}", drag.dx);
        cg_solutions::a2::motion(spec, s, drag);
    }
    // What `todo!("a2.t1: motion")` panics with.
    fn not_yet(_: &Spec, _: &mut CameraState, _: &cg_a2::Drag) {
        panic!("not yet implemented: a2.t1: motion")
    }
    let spec = spec_of("20260021");
    let imp = Impl { motion: too_far, ..cg_solutions::a2::implementation() };
    let Ok(Err(why)) = cg_harness::check::guarded(|| cg_a2::view(&spec, &imp, 0.0)) else {
        panic!("a picture, or a panic out of the view");
    };
    let start =
        format!("from camera_yaw = {}°", cg_core::product::format_number(spec.start.camera_yaw));
    for needle in [
        "motion() panicked: too far: ",
        "solutions/tests/a2.rs:",
        "on the drag ",
        &start,
        "the view's drag 1 of ",
    ] {
        assert!(why.en.contains(needle), "{needle:?} not in {:?}", why.en);
    }
    for needle in ["motion() が異常終了しました（panic）: too far", "ドラッグ: ", "1 回目"]
    {
        assert!(why.ja.contains(needle), "{needle:?} not in {:?}", why.ja);
    }
    let stub = Impl { motion: not_yet, ..imp };
    let still = cg_a2::view(&spec, &stub, 0.0).expect("the starting camera's picture");
    let unmoved = Impl { motion: |_, _, _| {}, ..imp };
    assert_eq!(still, cg_a2::view(&spec, &unmoved, 0.0).unwrap());
}

/// A motion() call that gave no value for another reason than its own panic (out of time, a
/// worker that crashed, a file that does not compile) goes on out of the view as it came, so
/// that `cg view` says so as for display() (it was taken for a panic, and the camera stayed
/// where it started beside the reference).
#[test]
fn a_motion_call_without_a_value_goes_on_out_of_the_view_as_it_came() {
    fn not_compiled(_: &Spec, _: &mut CameraState, _: &cg_a2::Drag) {
        std::panic::panic_any(cg_worker::CallError::DoesNotCompile {
            module: "a2".to_owned(),
            errors: vec!["exercises/src/a2.rs:3: expected `;`".to_owned()],
        });
    }
    let spec = spec_of("20260021");
    let imp = Impl { motion: not_compiled, ..cg_solutions::a2::implementation() };
    let Err(outcome) = cg_harness::check::guarded(|| cg_a2::view(&spec, &imp, 0.0)) else {
        panic!("a picture, or no reason");
    };
    assert_eq!(
        outcome,
        Outcome::DoesNotCompile {
            module: "a2".into(),
            errors: vec!["exercises/src/a2.rs:3: expected `;`".into()]
        }
    );
}

/// Each variable's line in the assignment text says the drag as English says it: "drag up and
/// down (dy) with the right button and Shift held", not "drag the Shift + right button up and
/// down".
#[test]
fn the_drags_read_naturally_in_english() {
    // 20260021: camera_distance on Shift + left, left and right; camera_yaw on the left button.
    let spec = spec_of("20260021");
    let text = spec.describe(Lang::En);
    for needle in [
        "camera_distance (from the target to the camera): drag left and right (dx) with the left button and Shift held — ",
        "camera_yaw (turn about the Y axis, degrees): drag left and right (dx) with the left button — ",
    ] {
        assert!(text.contains(needle), "{needle:?} not in\n{text}");
    }
    assert!(!text.contains("drag the "), "{text}");
    let ja = spec.describe(Lang::Ja);
    assert!(ja.contains("Shift + 左ボタンで左右に（dx）ドラッグ"), "{ja}");
}
