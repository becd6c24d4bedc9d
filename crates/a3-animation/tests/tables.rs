//! Table version 2 keeps a3's objects apart and over the ground; version 1 does not (it is
//! frozen, so it stays as it is: the test shows what version 2 mends).
//!
//! Every object of a student's variant is moved through the whole animation (every frame of
//! the common period, as the oracle poses it) and stood for by its bounding sphere (its polygon
//! model's farthest vertex from the model's origin). Two objects meet only if their spheres
//! overlap, and an object leaves the ground only if its sphere reaches beyond ±5 in x or z; the
//! test asks of version 2 that neither ever happens, with room to spare.

use cg_a3::{FPS, ShapeExt, Spec, SpecExt, expected_model, variant};
use cg_core::glam::DVec3;
use cg_harness::{StudentNumber, TableVersion, VariantRng};

/// Half the ground's side (the course's 10 × 10 ground).
const GROUND: f64 = 5.0;
/// The least room version 2 leaves between two spheres, and between a sphere and the ground's
/// edge (the tables' own margin is 0.05).
const ROOM: f64 = 0.01;

/// What goes wrong in a variant: the first frame where two objects meet, and the first where one
/// leaves the ground.
#[derive(Debug, Default)]
struct Layout {
    meet: Option<String>,
    off_ground: Option<String>,
}

fn spec(n: u32, table: TableVersion) -> Spec {
    let s: StudentNumber = format!("{n:08}").parse().unwrap();
    variant(&mut VariantRng::new(&s, table, "a3"))
}

fn layout(spec: &Spec) -> Layout {
    let radii: Vec<f64> = spec
        .objects
        .iter()
        .map(|o| {
            let mesh = o.shape.mesh();
            mesh.positions.iter().map(|p| f64::from(p.length())).fold(0.0, f64::max)
        })
        .collect();
    let frames = (spec.common_period_s() * f64::from(FPS)).round() as u64;
    let mut out = Layout::default();
    for frame in 0..frames {
        let centres: Vec<DVec3> = (0..spec.objects.len())
            .map(|i| expected_model(spec, i, frame).transform_point3(DVec3::ZERO))
            .collect();
        for (i, (c, r)) in centres.iter().zip(&radii).enumerate() {
            let edge = c.x.abs().max(c.z.abs()) + r;
            if out.off_ground.is_none() && edge > GROUND - ROOM {
                out.off_ground =
                    Some(format!("object {} reaches {edge:.3} at frame {frame}", i + 1));
            }
            for j in i + 1..centres.len() {
                let gap = c.distance(centres[j]) - r - radii[j];
                if out.meet.is_none() && gap < ROOM {
                    out.meet = Some(format!(
                        "objects {} and {} {gap:.3} apart at frame {frame}",
                        i + 1,
                        j + 1
                    ));
                }
            }
        }
        if out.meet.is_some() && out.off_ground.is_some() {
            break;
        }
    }
    out
}

/// Students spread over the whole range of numbers (a fixed sequence).
fn students(count: usize) -> impl Iterator<Item = u32> {
    let mut x: u64 = 20_261_129;
    (0..count).map(move |_| {
        x = x.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        ((x >> 33) % 100_000_000) as u32
    })
}

#[test]
fn in_table_2_no_two_objects_meet_and_none_leaves_the_ground() {
    let count = std::env::var("TABLES_N").ok().and_then(|n| n.parse().ok()).unwrap_or(400);
    let mut bad = Vec::new();
    for n in students(count).chain([0, 1, 12_345_678, 99_999_999, 84_405_182, 16_718_431]) {
        let l = layout(&spec(n, TableVersion::V2));
        for what in [l.meet, l.off_ground].into_iter().flatten() {
            bad.push(format!("{n:08}: {what}"));
        }
    }
    assert!(
        bad.is_empty(),
        "{} of table 2's students: {:#?}",
        bad.len(),
        &bad[..bad.len().min(20)]
    );
}

/// The measure finds version 1's known cases (the defects version 2 mends): it can fail.
#[test]
fn in_table_1_the_known_students_have_objects_that_meet_or_leave_the_ground() {
    // Named by the sweep of every variant (objects 2 and 4 of 84405182 meet, 0.39 deep).
    let l = layout(&spec(84_405_182, TableVersion::V1));
    assert!(l.meet.as_deref().is_some_and(|m| m.contains("objects 2 and 4")), "{l:?}");
    let (mut meet, mut off) = (0, 0);
    for n in students(200) {
        let l = layout(&spec(n, TableVersion::V1));
        meet += usize::from(l.meet.is_some());
        off += usize::from(l.off_ground.is_some());
    }
    // About 15 % and 63 % of version 1's students (the sweep of 3 000).
    assert!(meet >= 10 && off >= 80, "table 1: {meet} of 200 meet, {off} of 200 off the ground");
}

/// Version 2 is still every motion, shape and period of the course: it draws from the same
/// kinds, and a few dozen students see each of them.
#[test]
fn table_2_keeps_every_kind_of_motion() {
    let mut seen = std::collections::BTreeSet::new();
    for n in students(60) {
        for o in &spec(n, TableVersion::V2).objects {
            let kind = format!("{:?}", o.motion);
            seen.insert(kind.split_whitespace().next().unwrap_or_default().to_owned());
        }
    }
    let kinds: Vec<&str> = seen.iter().map(String::as_str).collect();
    assert_eq!(kinds, ["Hop", "Orbit", "Satellite", "Spin", "Swing"]);
}
