//! The kit's own reference pictures (`Assignment::reference_view`, built from the trusted side's
//! oracles) are the pictures the reference solutions draw: the students' copy, which has no
//! solutions, shows them beside the student's result in `cg view`. Each is compared pixel by
//! pixel with the solutions' view, rendered the same way, for several students and times.
//!
//! Tolerance: every channel within 2/255 (the view's own difference threshold), and at most
//! 0.05 % of the pixels beyond it (a triangle edge that falls the other way when the oracle's
//! f64 arithmetic rounds differently from the solutions' f32). Failing pictures are written to
//! `target/test-images/reference-views/`.

use cg_assign::{Variants, Which};
use cg_core::image::Image;
use cg_harness::TableVersion;

const STUDENTS: [&str; 6] =
    ["12345678", "20260002", "24000007", "20231234", "19990001", "31415926"];

fn render(scene: &cg_core::scene::Scene) -> Image {
    cg_raster::render(scene, &cg_raster::Options::default()).expect("the scene renders").image
}

/// How many pixels differ by more than 2/255 in some channel, and the largest difference.
fn differ(a: &Image, b: &Image) -> (usize, u8) {
    assert_eq!((a.width, a.height), (b.width, b.height));
    let (pa, pb) = (a.to_rgba8(), b.to_rgba8());
    let mut count = 0;
    let mut worst = 0;
    for (p, q) in pa.iter().zip(&pb) {
        let d = (0..3).map(|c| p[c].abs_diff(q[c])).max().unwrap_or(0);
        worst = worst.max(d);
        if d > 2 {
            count += 1;
        }
    }
    (count, worst)
}

fn save(name: &str, image: &Image) {
    let dir =
        std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("../test-images/reference-views");
    let _ = std::fs::create_dir_all(&dir);
    let _ = cg_scene::save_png(&dir.join(name), image);
}

fn compare(which: Which) {
    let solutions = cg_assign::impls!(cg_solutions);
    let mut compared = 0;
    for number in STUDENTS {
        let a = Variants::for_student(&number.parse().unwrap(), TableVersion::V1);
        let times: Vec<f64> = match a.view_period_s(which) {
            Some(p) => vec![0.0, 0.37 * p, 0.8 * p, 1.6],
            None => vec![0.0, 1.6],
        };
        for t in times {
            let reference = a.reference_view(which, t).expect("the kit has a reference picture");
            let theirs = a.view(which, &solutions, t).expect("the solutions draw");
            let (mine, theirs) = (render(&reference), render(&theirs));
            let (count, worst) = differ(&mine, &theirs);
            let allowed = mine.pixels.len() / 2000;
            if count > allowed {
                save(&format!("{which}-{number}-{t}-kit.png"), &mine);
                save(&format!("{which}-{number}-{t}-solutions.png"), &theirs);
                panic!(
                    "{which}, student {number}, t = {t}: {count} pixels differ by more than 2/255 \
                     (at most {allowed}), worst {worst}/255"
                );
            }
            compared += 1;
        }
    }
    eprintln!("{which}: {compared} pictures compared");
}

#[test]
fn a1_reference_is_the_solutions_picture() {
    compare(Which::a1);
}

#[test]
fn a2_reference_is_the_solutions_picture() {
    compare(Which::a2);
}

#[test]
fn a3_reference_is_the_solutions_picture() {
    compare(Which::a3);
}

#[test]
fn a4_reference_is_the_solutions_picture() {
    compare(Which::a4);
}

#[test]
fn s_reference_is_the_solutions_picture() {
    compare(Which::s);
}
