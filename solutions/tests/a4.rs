//! Assignment a4 (texture mapping), the instructor's proof: the reference passes every check for
//! students of every variant family, the pristine stubs fail every check, and the answers
//! students really hand in fail the checks meant to catch them — with messages in both languages
//! that say where.

// The assignment crates, through the kit's one list (cg-assign).
use cg_assign::cg_a4;

use std::collections::BTreeSet;

use cg_a4::RegionExt as _;
use cg_a4::SpecExt as _;
use cg_a4::{Filter, Sampler, Wrap};
use cg_a4::{Impl, Spec, TexRange};
use cg_core::glam::Vec2;
use cg_harness::check::{CheckResult, Outcome};
use cg_harness::{TableVersion, VariantRng};

mod common;

/// Students chosen so that every option occurs (asserted below): repeat 1, 2 and 5; turns of 0,
/// 90, 180 and 270°; mirrored and not; regions of 1 × 1 to 4 × 4 cells, touching the image's
/// edge and not.
const STUDENTS: [&str; 10] = [
    "20250001", "20250002", "20250003", "20250006", "20250012", "20250014", "20250015", "20250020",
    "20250022", "20250024",
];

fn spec_of(student: &str) -> Spec {
    let number = student.parse().expect("a valid student number");
    cg_assign::Variants::for_student(&number, TableVersion::V1).a4
}

fn specs() -> Vec<(String, Spec)> {
    STUDENTS.iter().map(|s| ((*s).to_owned(), spec_of(s))).collect()
}

/// Every check ID, from the checks themselves.
fn all_ids() -> BTreeSet<String> {
    let spec = spec_of(STUDENTS[0]);
    cg_a4::checks(&spec, &cg_solutions::a4::implementation()).into_iter().map(|c| c.id).collect()
}

#[test]
fn the_students_cover_every_option() {
    let specs = specs();
    let has = |f: &dyn Fn(&Spec) -> bool| specs.iter().any(|(_, s)| f(s));
    for repeat in [1, 2, 5] {
        assert!(has(&|s| s.repeat == repeat), "repeat {repeat}");
    }
    for rotation in [0, 90, 180, 270] {
        assert!(has(&|s| s.rotation_deg == rotation), "rotation {rotation}");
    }
    for mirrored in [false, true] {
        assert!(has(&|s| s.mirrored == mirrored), "mirrored {mirrored}");
    }
    assert!(has(&|s| s.region.columns == 1 && s.region.rows == 1), "a single cell");
    assert!(has(&|s| s.region.columns == 4), "four columns");
    let r = |s: &Spec| s.region;
    assert!(has(&|s| r(s).column + r(s).columns == 8 || r(s).row == 0), "touching the edge");
    assert!(
        has(&|s| r(s).column > 0
            && r(s).column + r(s).columns < 8
            && r(s).row > 0
            && r(s).row + r(s).rows < 8),
        "inside"
    );
}

#[test]
fn the_reference_passes_every_check() {
    let imp = cg_solutions::a4::implementation();
    let mut specs = specs();
    // And a few hundred more variants drawn from the same table.
    for seed in 0..300 {
        specs.push((format!("seed {seed}"), cg_a4::variant(&mut VariantRng::from_seed(seed))));
    }
    for (who, spec) in specs {
        for c in cg_a4::checks(&spec, &imp) {
            assert!(c.passed(), "{who} {spec:?}: {} {:?}", c.id, c.outcome);
        }
    }
}

#[test]
fn the_pristine_stubs_pass_nothing() {
    let imp = cg_exercises::a4::implementation();
    for (who, spec) in specs() {
        let results = cg_a4::checks(&spec, &imp);
        assert_eq!(results.len(), all_ids().len());
        for c in results {
            assert!(
                matches!(c.outcome, Outcome::NotDone { ref message } if message.starts_with(&c.task)),
                "{who}: {} {:?}",
                c.id,
                c.outcome
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Broken answers: the reference's way of working with one mistake each, as students make them.

const FLIPPED_ROWS: u8 = 1; // t1: rows counted from the top used as t
const PIXELS: u8 = 2; // t1: pixels, not divided by 512
const WHOLE_RANGE: u8 = 3; // t1: the whole image
const NO_T_FLIP: u8 = 10; // t2: t not inverted (image bottom-left origin forgotten)
const SWAPPED: u8 = 11; // t2: s and t swapped
const OFF_BY_ONE: u8 = 12; // t2: (i + 1)·0.1, "i*0.1 + 0.1"
const WHOLE_IMAGE: u8 = 13; // t2: 0…1 instead of the region
const PER_SQUARE: u8 = 14; // t2: every square gets the whole region
const NO_REPEAT: u8 = 15; // t2: the repeat count ignored
const NO_MIRROR: u8 = 16; // t2: the mirror forgotten
const CLOCKWISE: u8 = 17; // t2: turned the other way
const INT_DIVISION: u8 = 18; // t2: (a / k) in integers
const VERTEX_MODULO: u8 = 19; // t2: (i + 1) % k per vertex: a block's far edge wraps to 0
const GL_REPEAT_STYLE: u8 = 20; // t2: coordinates run 0…n, hoping GL_REPEAT repeats the region

fn tex_range_with<const BUG: u8>(spec: &Spec) -> TexRange {
    let r = &spec.region;
    let n = 8.0;
    match BUG {
        FLIPPED_ROWS => TexRange {
            s_min: r.column as f32 / n,
            s_max: (r.column + r.columns) as f32 / n,
            t_min: r.row as f32 / n,
            t_max: (r.row + r.rows) as f32 / n,
        },
        PIXELS => {
            let [x0, y0, x1, y1] = r.pixels();
            TexRange {
                s_min: x0 as f32,
                s_max: x1 as f32,
                t_min: 512.0 - y1 as f32,
                t_max: 512.0 - y0 as f32,
            }
        }
        WHOLE_RANGE => TexRange { s_min: 0.0, s_max: 1.0, t_min: 0.0, t_max: 1.0 },
        _ => cg_solutions::a4::tex_range(spec),
    }
}

fn tex_coords_with<const BUG: u8>(spec: &Spec, i: u32, j: u32) -> [Vec2; 4] {
    let range = if BUG == WHOLE_IMAGE {
        TexRange { s_min: 0.0, s_max: 1.0, t_min: 0.0, t_max: 1.0 }
    } else {
        cg_solutions::a4::tex_range(spec)
    };
    let repeat = if BUG == NO_REPEAT { 1 } else { spec.repeat };
    let k = 10 / repeat;
    let (a, b) = (i % k, j % k);
    let corner = |di: u32, dj: u32| {
        let (p, q) = match BUG {
            OFF_BY_ONE => (
                (a + di) as f32 * (1.0 / k as f32) + 1.0 / k as f32,
                (b + dj) as f32 / k as f32 + 1.0 / k as f32,
            ),
            PER_SQUARE => (di as f32, dj as f32),
            INT_DIVISION => (((a + di) / k) as f32, ((b + dj) / k) as f32),
            VERTEX_MODULO => (((i + di) % k) as f32 / k as f32, ((j + dj) % k) as f32 / k as f32),
            GL_REPEAT_STYLE => {
                let n = spec.repeat as f32;
                ((i + di) as f32 / 10.0 * n, (j + dj) as f32 / 10.0 * n)
            }
            _ => ((a + di) as f32 / k as f32, (b + dj) as f32 / k as f32),
        };
        let rotation = match (BUG, spec.rotation_deg) {
            (CLOCKWISE, 90) => 270,
            (CLOCKWISE, 270) => 90,
            (_, r) => r,
        };
        let (x, y) = match rotation {
            90 => (1.0 - q, 1.0 - p),
            180 => (1.0 - p, q),
            270 => (q, p),
            _ => (p, 1.0 - q),
        };
        let x = if spec.mirrored && BUG != NO_MIRROR { 1.0 - x } else { x };
        let y = if BUG == NO_T_FLIP { 1.0 - y } else { y };
        let (x, y) = if BUG == SWAPPED { (y, x) } else { (x, y) };
        Vec2::new(
            range.s_min + x * (range.s_max - range.s_min),
            range.t_min + y * (range.t_max - range.t_min),
        )
    };
    [corner(0, 0), corner(0, 1), corner(1, 1), corner(1, 0)]
}

fn sampler_repeat() -> Sampler {
    Sampler { filter: Filter::Bilinear, wrap_u: Wrap::Repeat, wrap_v: Wrap::Repeat }
}

fn sampler_repeat_t() -> Sampler {
    Sampler { filter: Filter::Nearest, wrap_u: Wrap::Clamp, wrap_v: Wrap::Repeat }
}

fn reference() -> Impl {
    cg_solutions::a4::implementation()
}

/// A broken answer: its name, the implementation, which specs show the bug, the checks that must
/// fail there, and words its messages must contain (check ID, needle in the English text).
struct Broken {
    name: &'static str,
    imp: Impl,
    applies: fn(&Spec) -> bool,
    fails: &'static [&'static str],
    says: &'static [(&'static str, &'static str)],
}

fn always(_: &Spec) -> bool {
    true
}

fn broken_answers() -> Vec<Broken> {
    let with_t2 = |f: fn(&Spec, u32, u32) -> [Vec2; 4]| Impl { tex_coords: f, ..reference() };
    let with_t1 = |f: fn(&Spec) -> TexRange| Impl { tex_range: f, ..reference() };
    vec![
        Broken {
            name: "t1: rows counted from the top used as t (flipped)",
            imp: with_t1(tex_range_with::<FLIPPED_ROWS>),
            // A region centred top to bottom (2·row + rows = 8) has the same range either way.
            applies: |s| 2 * s.region.row + s.region.rows != 8,
            fails: &["a4.t1.t_range"],
            says: &[("a4.t1.t_range", "counted from the top")],
        },
        Broken {
            name: "t1: pixels",
            imp: with_t1(tex_range_with::<PIXELS>),
            applies: always,
            fails: &["a4.t1.s_range", "a4.t1.t_range"],
            says: &[("a4.t1.s_range", "pixels"), ("a4.t1.t_range", "pixels")],
        },
        Broken {
            name: "t1: the whole image",
            imp: with_t1(tex_range_with::<WHOLE_RANGE>),
            applies: always,
            fails: &["a4.t1.s_range", "a4.t1.t_range"],
            says: &[("a4.t1.s_range", "whole image")],
        },
        Broken {
            name: "t2: t not inverted (flipped texture)",
            imp: with_t2(tex_coords_with::<NO_T_FLIP>),
            applies: always,
            fails: &["a4.t2.corners", "a4.t2.orientation", "a4.t2.cells"],
            says: &[("a4.t2.corners", "another corner of the region")],
        },
        Broken {
            name: "t2: s and t swapped",
            imp: with_t2(tex_coords_with::<SWAPPED>),
            applies: always,
            fails: &["a4.t2.corners", "a4.t2.orientation", "a4.t2.cells"],
            says: &[("a4.t2.orientation", "swapped")],
        },
        Broken {
            name: "t2: off by one (i*0.1 + 0.1)",
            imp: with_t2(tex_coords_with::<OFF_BY_ONE>),
            applies: always,
            fails: &["a4.t2.corners", "a4.t2.range", "a4.t2.cells"],
            says: &[("a4.t2.range", "off by one")],
        },
        Broken {
            name: "t2: the whole image instead of the region",
            imp: with_t2(tex_coords_with::<WHOLE_IMAGE>),
            applies: always,
            fails: &["a4.t2.corners", "a4.t2.range", "a4.t2.cells"],
            says: &[("a4.t2.range", "whole image")],
        },
        Broken {
            name: "t2: every square mapped to the whole region",
            imp: with_t2(tex_coords_with::<PER_SQUARE>),
            applies: always,
            fails: &["a4.t2.shared", "a4.t2.linear", "a4.t2.cells"],
            says: &[("a4.t2.shared", "each square")],
        },
        Broken {
            name: "t2: the repeat count ignored",
            imp: with_t2(tex_coords_with::<NO_REPEAT>),
            applies: |s| s.repeat > 1,
            fails: &["a4.t2.range", "a4.t2.cells"],
            says: &[("a4.t2.range", "repeat count")],
        },
        Broken {
            name: "t2: the mirror forgotten",
            imp: with_t2(tex_coords_with::<NO_MIRROR>),
            applies: |s| s.mirrored,
            fails: &["a4.t2.corners", "a4.t2.orientation", "a4.t2.cells"],
            says: &[("a4.t2.orientation", "mirror")],
        },
        Broken {
            name: "t2: turned clockwise instead of counter-clockwise",
            imp: with_t2(tex_coords_with::<CLOCKWISE>),
            applies: |s| s.rotation_deg % 180 == 90,
            fails: &["a4.t2.corners", "a4.t2.orientation", "a4.t2.cells"],
            says: &[],
        },
        Broken {
            name: "t2: integer division",
            imp: with_t2(tex_coords_with::<INT_DIVISION>),
            applies: always,
            fails: &["a4.t2.linear", "a4.t2.cells"],
            says: &[("a4.t2.linear", "integer division")],
        },
        Broken {
            name: "t2: (i + 1) % k per vertex",
            imp: with_t2(tex_coords_with::<VERTEX_MODULO>),
            applies: always,
            fails: &["a4.t2.corners", "a4.t2.linear", "a4.t2.cells"],
            says: &[("a4.t2.linear", "wraps back to 0")],
        },
        Broken {
            name: "t2: coordinates 0…n for GL_REPEAT",
            imp: with_t2(tex_coords_with::<GL_REPEAT_STYLE>),
            applies: |s| s.repeat > 1,
            fails: &["a4.t2.corners", "a4.t2.range", "a4.t2.cells"],
            says: &[("a4.t2.range", "GL_REPEAT repeats the whole image")],
        },
        Broken {
            name: "t3: GL_REPEAT",
            imp: Impl { sampler: sampler_repeat, ..reference() },
            applies: always,
            fails: &["a4.t3.wrap"],
            says: &[("a4.t3.wrap", "GL_REPEAT repeats the whole image")],
        },
        Broken {
            name: "t3: GL_REPEAT along t only",
            imp: Impl { sampler: sampler_repeat_t, ..reference() },
            applies: always,
            fails: &["a4.t3.wrap"],
            says: &[],
        },
    ]
}

fn failure_text(c: &CheckResult) -> String {
    match &c.outcome {
        Outcome::Fail(f) => format!(
            "{} | {} | {:?} | {} | {} | {} | {}",
            f.expected, f.actual, f.location, f.cause.en, f.cause.ja, f.hint.en, f.hint.ja
        ),
        other => format!("{other:?}"),
    }
}

#[test]
fn broken_answers_fail_the_checks_meant_for_them() {
    let mut caught: BTreeSet<String> = BTreeSet::new();
    for broken in broken_answers() {
        let mut shown = 0;
        for (who, spec) in specs().into_iter().filter(|(_, s)| (broken.applies)(s)) {
            shown += 1;
            let results = cg_a4::checks(&spec, &broken.imp);
            for id in broken.fails {
                let c = results.iter().find(|c| c.id == *id).expect("the check exists");
                assert!(
                    matches!(c.outcome, Outcome::Fail(_)),
                    "{}: {id} should fail for {who} {spec:?}, got {:?}",
                    broken.name,
                    c.outcome
                );
                caught.insert((*id).to_owned());
            }
            for (id, needle) in broken.says {
                let c = results.iter().find(|c| c.id == *id).expect("the check exists");
                assert!(
                    failure_text(c).contains(needle),
                    "{}: {id} for {who} should say {needle:?}: {}",
                    broken.name,
                    failure_text(c)
                );
            }
            // A mistake in one task never fails another task's checks.
            let task = broken.fails[0].rsplit_once('.').map(|(t, _)| t).unwrap_or_default();
            for c in &results {
                if c.task != task {
                    assert!(
                        c.passed(),
                        "{}: {} fails for {who}: {}",
                        broken.name,
                        c.id,
                        failure_text(c)
                    );
                }
            }
        }
        assert!(shown >= 2, "{}: only {shown} of the test students show it", broken.name);
    }
    assert_eq!(caught, all_ids(), "every check catches at least one broken answer");
}

#[test]
fn failures_explain_themselves_in_both_languages_and_say_where() {
    for broken in broken_answers() {
        for (who, spec) in specs() {
            for c in cg_a4::checks(&spec, &broken.imp) {
                match &c.outcome {
                    Outcome::Pass => {}
                    Outcome::Fail(f) => {
                        let ctx = format!("{} / {who} / {}", broken.name, c.id);
                        assert!(!f.expected.is_empty() && !f.actual.is_empty(), "{ctx}");
                        assert!(f.location.as_ref().is_some_and(|l| !l.is_empty()), "{ctx}");
                        for text in [&f.cause, &f.hint, &c.title] {
                            assert!(!text.ja.is_empty() && !text.en.is_empty(), "{ctx}: {text:?}");
                            assert!(
                                text.ja.chars().any(|ch| ('\u{3040}'..='\u{30ff}').contains(&ch)
                                    || ('\u{4e00}'..='\u{9fff}').contains(&ch)),
                                "{ctx}: not Japanese: {}",
                                text.ja
                            );
                        }
                    }
                    other => panic!("{} / {who} / {}: {other:?}", broken.name, c.id),
                }
            }
        }
    }
}

/// a4.t1 wrong, and tex_coords built on it (as the hint of the stub says to): the a4.t2 checks
/// that fail say to fix a4.t1 first; with a4.t1 right, an a4.t2 failure does not; with a4.t1 not
/// written yet, the a4.t2 checks still judge tex_coords.
#[test]
fn a4_t2_failures_that_follow_from_a4_t1_say_so() {
    fn range_flipped(spec: &Spec, i: u32, j: u32) -> [Vec2; 4] {
        let (right, flipped) =
            (cg_solutions::a4::tex_range(spec), tex_range_with::<FLIPPED_ROWS>(spec));
        cg_solutions::a4::tex_coords(spec, i, j).map(|v| {
            let y = (v.y - right.t_min) / (right.t_max - right.t_min);
            Vec2::new(v.x, flipped.t_min + y * (flipped.t_max - flipped.t_min))
        })
    }
    let both = Impl {
        tex_range: tex_range_with::<FLIPPED_ROWS>,
        tex_coords: range_flipped,
        ..reference()
    };
    let only_t2 = Impl { tex_coords: tex_coords_with::<OFF_BY_ONE>, ..reference() };
    let stubs = cg_exercises::a4::implementation();
    let mut shown = 0;
    for (who, spec) in specs().into_iter().filter(|(_, s)| 2 * s.region.row + s.region.rows != 8) {
        let t2: Vec<CheckResult> =
            cg_a4::checks(&spec, &both).into_iter().filter(|c| c.task == "a4.t2").collect();
        let failing: Vec<&CheckResult> = t2.iter().filter(|c| !c.passed()).collect();
        assert!(!failing.is_empty(), "{who}: no a4.t2 check fails");
        for c in failing {
            let text = failure_text(c);
            assert!(text.contains("fix a4.t1 first"), "{who}: {}: {text}", c.id);
            assert!(text.contains("先に a4.t1 を直してください"), "{who}: {}: {text}", c.id);
        }
        for c in cg_a4::checks(&spec, &only_t2).iter().filter(|c| !c.passed()) {
            assert!(!failure_text(c).contains("a4.t1"), "{who}: {}: {}", c.id, failure_text(c));
        }
        // tex_range not written yet, tex_coords written (wrong) without it: each a4.t2 check is
        // judged on tex_coords alone, with the hint, not "a4.t1 is not written yet".
        let t1_stub = Impl { tex_range: stubs.tex_range, ..only_t2 };
        let t2: Vec<CheckResult> =
            cg_a4::checks(&spec, &t1_stub).into_iter().filter(|c| c.task == "a4.t2").collect();
        assert!(t2.iter().any(|c| !c.passed()), "{who}: no a4.t2 check fails");
        for c in t2.iter().filter(|c| !c.passed()) {
            assert!(matches!(c.outcome, Outcome::Fail(_)), "{who}: {}: {:?}", c.id, c.outcome);
            assert!(failure_text(c).contains("fix a4.t1 first"), "{who}: {}", c.id);
        }
        shown += 1;
    }
    assert!(shown >= 2, "only {shown} students show it");
}

/// What the orientation check says the viewer sees, for mistakes whose picture is known.
#[test]
fn the_orientation_check_says_what_the_viewer_sees() {
    let upright: Vec<Spec> = specs()
        .into_iter()
        .map(|(_, s)| s)
        .filter(|s| s.rotation_deg == 0 && !s.mirrored)
        .collect();
    assert!(!upright.is_empty());
    let flipped = Impl { tex_coords: tex_coords_with::<NO_T_FLIP>, ..reference() };
    for spec in &upright {
        let c = cg_a4::checks(spec, &flipped)
            .into_iter()
            .find(|c| c.id == "a4.t2.orientation")
            .unwrap();
        let text = failure_text(&c);
        assert!(text.contains("flipped top to bottom"), "{text}");
        assert!(text.contains("its top (+t) towards the camera (+z)"), "{text}");
        assert!(text.contains("t was not inverted"), "{text}");
    }
    let mirrored: Vec<Spec> = specs().into_iter().map(|(_, s)| s).filter(|s| s.mirrored).collect();
    let forgot = Impl { tex_coords: tex_coords_with::<NO_MIRROR>, ..reference() };
    for spec in &mirrored {
        let c =
            cg_a4::checks(spec, &forgot).into_iter().find(|c| c.id == "a4.t2.orientation").unwrap();
        assert!(failure_text(&c).contains("mirror writing"), "{}", failure_text(&c));
    }
}

#[test]
fn the_view_draws_the_students_coordinates_on_the_course_stage() {
    for (who, spec) in specs() {
        let scene =
            cg_a4::view(&spec, &reference(), 0.0).unwrap_or_else(|e| panic!("{who}: {e:?}"));
        assert_eq!(scene.objects.len(), 1, "{who}: the ground alone");
        let ground = &scene.objects[0];
        let used = ground.texture.as_ref().expect("textured");
        assert_eq!(scene.textures[used.texture], cg_a4::prepared_image());
        assert_eq!(used.sampler, cg_a4::core_sampler(cg_solutions::a4::sampler()));
        assert_eq!(ground.mesh.face_count(), 200);
        let uvs = ground.mesh.uvs.as_ref().expect("texture coordinates");
        let coords = cg_a4::coordinates(&spec, &reference());
        // Square (i, j)'s corners follow each other, row by row of j.
        assert_eq!(uvs[4 * (3 * 10 + 7)..4 * (3 * 10 + 7) + 4], coords[7][3]);
        assert_eq!(scene.camera, cg_harness::course::stage().camera);
    }
    // The pristine stubs: the course's own, untextured ground — there is always a picture.
    let spec = spec_of(STUDENTS[0]);
    let stub = cg_a4::view(&spec, &cg_exercises::a4::implementation(), 0.0).unwrap();
    assert_eq!(stub, cg_harness::course::ground_only());
}

fn panicking(_: &Spec, i: u32, _: u32) -> [Vec2; 4] {
    let table = [Vec2::ZERO; 4];
    [table[i as usize + 10]; 4]
}

#[test]
fn a_panicking_answer_is_reported_not_raised() {
    let spec = spec_of(STUDENTS[0]);
    let imp = Impl { tex_coords: panicking, ..reference() };
    let error = cg_a4::view(&spec, &imp, 0.0).unwrap_err();
    assert!(
        error.en.contains("tex_coords panicked") && error.en.contains("index out of bounds"),
        "{error:?}"
    );
    assert!(error.ja.contains("異常終了"), "{error:?}");
    for c in cg_a4::checks(&spec, &imp).into_iter().filter(|c| c.task == "a4.t2") {
        assert!(matches!(c.outcome, Outcome::Panicked { .. }), "{}: {:?}", c.id, c.outcome);
    }
}

#[test]
fn every_student_reads_the_tasks_in_both_languages() {
    for (who, spec) in specs() {
        for lang in [cg_core::lang::Lang::Ja, cg_core::lang::Lang::En] {
            let text = spec.describe(lang);
            for needle in ["a4.t1", "a4.t2", "a4.t3", &spec.region.name()] {
                assert!(text.contains(needle), "{who} {lang}: {needle:?} missing:\n{text}");
            }
        }
    }
}

/// The identifiers that are plain words and that the Japanese report and assignment text
/// really use, as code: the student's `sampler()` and the `Sampler { filter: … }` it returns,
/// and the prepared image's path `assets/textures/a4-prepared.png`. (Identifiers shaped like
/// code — `tex_range`, `wrap_u`, `Wrap::Clamp`, `GL_REPEAT` — need no listing; see
/// `common::english_words`.)
const CODE_WORDS: &[&str] = &["sampler", "Sampler", "filter", "assets", "textures"];

#[test]
fn reports_read_in_one_language() {
    let mut problems = Vec::new();
    let answers = [("the stubs", cg_exercises::a4::implementation())]
        .into_iter()
        .chain(broken_answers().into_iter().map(|b| (b.name, b.imp)))
        .chain([("a panicking tex_coords", Impl { tex_coords: panicking, ..reference() })]);
    for (name, imp) in answers {
        for (who, spec) in specs() {
            let report = cg_harness::check::Report {
                assignment: cg_a4::ID.into(),
                student: Some(who.clone()),
                checks: cg_a4::checks(&spec, &imp),
            };
            let context = format!("{name} / {who}");
            problems.extend(common::report_problems(&context, &report, CODE_WORDS));
            if let Err(why) = cg_a4::view(&spec, &imp, 0.0) {
                // The panic's own message is Rust's, after the words of the view.
                let (ja, en) = (
                    common::without_panic_message(&why.ja),
                    common::without_panic_message(&why.en),
                );
                problems.extend(common::language_problems(
                    &format!("view: {context}"),
                    ja,
                    en,
                    CODE_WORDS,
                ));
            }
        }
    }
    for (who, spec) in specs() {
        problems.extend(common::language_problems(
            &format!("describe / {who}"),
            &spec.describe(cg_core::lang::Lang::Ja),
            &spec.describe(cg_core::lang::Lang::En),
            CODE_WORDS,
        ));
    }
    common::assert_no_problems(&problems);
}
