//! OBJ faces of four or more corners: the triangles cover each polygon exactly once, turned as
//! the polygon is — where tobj's fan from the first corner folds a concave face — and a face that
//! crosses itself is an error naming its line.

use std::path::Path;

use cg_core::glam::{DVec2, Quat, Vec3};
use cg_core::lang::Lang;
use cg_core::mesh::Mesh;
use cg_scene::{ErrorKind, MAX_CONCAVE_CORNERS, PolygonProblem, SceneError, parse_obj};

/// An OBJ file of the points `points` (`v` lines in order) and one face through all of them, in
/// order, after `before` (other lines).
fn one_face(before: &str, points: &[Vec3]) -> String {
    let mut text = before.to_owned();
    for p in points {
        text += &format!("v {} {} {}\n", p.x, p.y, p.z);
    }
    let first = before.lines().filter(|l| l.starts_with("v ")).count();
    let corners: Vec<String> = (1..=points.len()).map(|i| (first + i).to_string()).collect();
    text + "f " + &corners.join(" ") + "\n"
}

fn load(text: &str) -> Mesh {
    parse_obj(text, Path::new("model.obj")).unwrap_or_else(|e| panic!("{e}\n{text}"))
}

fn error(text: &str) -> SceneError {
    parse_obj(text, Path::new("model.obj")).expect_err(text)
}

/// What tobj alone makes of `text`'s faces (its fan from each polygon's first corner), as `v`
/// numbers from 0 (the files here use every `v` line once, in order).
fn tobj_fan(text: &str) -> Vec<[u32; 3]> {
    let options = tobj::LoadOptions { triangulate: true, ..Default::default() };
    let (models, _) =
        tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| Ok(Default::default())).unwrap();
    models[0].mesh.indices.chunks_exact(3).map(|f| [f[0], f[1], f[2]]).collect()
}

/// How many of `faces` (corners at `corners`, in the polygon's plane) cover the point `q`, and
/// whether each turns as the polygon does (counter-clockwise there).
fn cover_count(corners: &[DVec2], faces: &[[u32; 3]], q: DVec2) -> usize {
    faces
        .iter()
        .filter(|f| {
            let [a, b, c] = f.map(|i| corners[i as usize]);
            let side = |p: DVec2, r: DVec2| (r - p).perp_dot(q - p);
            side(a, b) > 0.0 && side(b, c) > 0.0 && side(c, a) > 0.0
        })
        .count()
}

/// Whether `q` is inside the polygon `ring` (crossing number).
fn inside(ring: &[DVec2], q: DVec2) -> bool {
    let mut odd = false;
    for (i, &a) in ring.iter().enumerate() {
        let b = ring[(i + 1) % ring.len()];
        if (a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) / (b.y - a.y) * (b.x - a.x) {
            odd = !odd;
        }
    }
    odd
}

/// The faces cover every sample point inside the polygon `ring` (counter-clockwise) exactly once
/// and every point outside it never: a fold covers some outside and some inside twice (or not at
/// all, when its triangle turns the other way). Samples on a grid offset from every corner and
/// edge; `what` names the case.
fn assert_covers_once(ring: &[DVec2], faces: &[[u32; 3]], what: &str) -> Result<(), String> {
    let (lo, hi) = ring.iter().fold((DVec2::MAX, DVec2::MIN), |(l, h), &p| (l.min(p), h.max(p)));
    let steps = 97;
    for i in 0..=steps {
        for j in 0..=steps {
            let t = DVec2::new(i as f64 + 0.137, j as f64 + 0.291) / (steps as f64 + 1.0);
            let q = lo + (hi - lo) * t;
            let (want, got) = (usize::from(inside(ring, q)), cover_count(ring, faces, q));
            if want != got {
                return Err(format!(
                    "{what}: ({:.3}, {:.3}) is covered {got} times, should be {want}: {faces:?}",
                    q.x, q.y
                ));
            }
        }
    }
    Ok(())
}

/// An L of six corners in the plane z = 0, counter-clockwise seen from +z; its corner 3, (1, 1),
/// is the reflex one.
const L: [[f64; 2]; 6] = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [1.0, 1.0], [1.0, 2.0], [0.0, 2.0]];

/// `ring` starting at corner `start`.
fn rotated(ring: &[DVec2], start: usize) -> Vec<DVec2> {
    (0..ring.len()).map(|i| ring[(start + i) % ring.len()]).collect()
}

#[test]
fn a_concave_face_is_covered_once_from_every_first_corner() {
    let l: Vec<DVec2> = L.iter().map(|&p| DVec2::from(p)).collect();
    let mut fan_folds = 0;
    for start in 0..l.len() {
        let ring = rotated(&l, start);
        let points: Vec<Vec3> =
            ring.iter().map(|q| Vec3::new(q.x as f32, q.y as f32, 0.0)).collect();
        let text = one_face("", &points);
        let mesh = load(&text);
        assert_eq!(mesh.faces.len(), 4, "start {start}: n − 2 triangles");
        assert_covers_once(&ring, &mesh.faces, &format!("start {start}")).unwrap();
        // Each triangle faces +z, as the polygon does (counter-clockwise seen from +z).
        for f in &mesh.faces {
            let [a, b, c] = f.map(|i| mesh.positions[i as usize]);
            assert!((b - a).cross(c - a).z > 0.0, "start {start}: {f:?} turns the other way");
        }
        // The premise: tobj's fan folds the L from the corners that do not see every other.
        if assert_covers_once(&ring, &tobj_fan(&text), "tobj's fan").is_err() {
            fan_folds += 1;
        }
    }
    assert!(fan_folds >= 2, "tobj's fan folds the L from {fan_folds} of its six first corners");
}

#[test]
fn a_face_its_fan_covers_keeps_tobjs_triangles() {
    // A convex pentagon, and a concave face whose first corner sees all others (the L from its
    // reflex corner): tobj's fan, triangle for triangle.
    let pentagon: Vec<Vec3> = (0..5)
        .map(|k| {
            let a = k as f32 * std::f32::consts::TAU / 5.0;
            Vec3::new(a.cos(), a.sin(), 0.0)
        })
        .collect();
    let l: Vec<DVec2> = L.iter().map(|&p| DVec2::from(p)).collect();
    let from_reflex: Vec<Vec3> =
        rotated(&l, 3).iter().map(|q| Vec3::new(q.x as f32, q.y as f32, 0.0)).collect();
    for points in [pentagon, from_reflex] {
        let text = one_face("", &points);
        let fan: Vec<[u32; 3]> = (1..points.len() as u32 - 1).map(|i| [0, i, i + 1]).collect();
        assert_eq!(load(&text).faces, fan, "{text}");
        assert_eq!(tobj_fan(&text), fan, "the premise: tobj's fan");
    }
    // Every corner on one line: no area, nothing to fold; the fan's flat triangles, as before.
    let line: Vec<Vec3> = [0.0, 1.0, 3.0, 2.0].iter().map(|&x| Vec3::new(x, x, 0.0)).collect();
    assert_eq!(load(&one_face("", &line)).faces, [[0, 1, 2], [0, 2, 3]]);
}

#[test]
fn a_tilted_concave_face_facing_away_is_covered_once() {
    // The L clockwise (its face turned away from +z), with its midpoints on two edges, turned
    // into a tilted plane and moved: split in its own plane, facing as written.
    let mut ring: Vec<DVec2> = L.iter().map(|&p| DVec2::from(p)).collect();
    ring.insert(1, DVec2::new(1.0, 0.0));
    ring.insert(6, DVec2::new(0.5, 2.0));
    ring.reverse();
    let turn = Quat::from_axis_angle(Vec3::new(1.0, 2.0, 0.5).normalize(), 1.1);
    let offset = Vec3::new(3.0, -2.0, 7.0);
    for start in 0..ring.len() {
        let r = rotated(&ring, start);
        let points: Vec<Vec3> =
            r.iter().map(|q| turn * Vec3::new(q.x as f32, q.y as f32, 0.0) + offset).collect();
        let mesh = load(&one_face("", &points));
        // In the plane z = 0, mirrored so that the polygon turns counter-clockwise (vertex `Vi`
        // is corner i).
        let ccw: Vec<DVec2> = r.iter().map(|q| DVec2::new(q.y, q.x)).collect();
        assert_covers_once(&ccw, &mesh.faces, &format!("start {start}")).unwrap();
        let normal = turn * Vec3::NEG_Z;
        for f in &mesh.faces {
            let [a, b, c] = f.map(|i| mesh.positions[i as usize]);
            let n = (b - a).cross(c - a);
            assert!(n.length() < 1e-5 || n.dot(normal) > 0.0, "start {start}: {f:?}");
        }
    }
}

#[test]
fn a_face_that_crosses_itself_names_its_line() {
    // A bow tie, a five-pointed star drawn in one stroke (every corner turns the same way), and
    // a corner on another edge; after a quad and a triangle, in a second group.
    let star: Vec<Vec3> = (0..5)
        .map(|k| {
            let a = (2 * k) as f32 * std::f32::consts::TAU / 5.0;
            Vec3::new(a.cos(), a.sin(), 0.0)
        })
        .collect();
    let bow_tie = [Vec3::ZERO, Vec3::new(1.0, 1.0, 0.0), Vec3::X, Vec3::Y].to_vec();
    let touching = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [2.0, 0.0], [0.0, 4.0]]
        .map(|[x, y]| Vec3::new(x, y, 0.0))
        .to_vec();
    // A spiral whose fan from its first corner turns the same way throughout, but more than
    // once around: 400°.
    let spiral: Vec<Vec3> = std::iter::once(Vec3::ZERO)
        .chain((1..=5).map(|k| {
            let a = (10.0 + 100.0 * (k - 1) as f32).to_radians();
            Vec3::new(a.cos(), a.sin(), 0.0) * k as f32
        }))
        .collect();
    let before = "o first\nv 0 0 5\nv 1 0 5\nv 1 1 5\nv 0 1 5\nf 1 2 3 4\nf 1 2 3\no second\n";
    let cases = [("bow tie", bow_tie), ("star", star), ("touching", touching), ("spiral", spiral)];
    for (name, points) in cases {
        let text = one_face(before, &points);
        let e = error(&text);
        let corners = points.len();
        assert_eq!(*e.kind, ErrorKind::ObjPolygon { corners, problem: PolygonProblem::Crosses });
        let line = text.lines().count();
        assert_eq!(e.position.map(|p| (p.line, p.column)), Some((line, 1)), "{name}");
        let en = e.to_string();
        assert!(en.starts_with(&format!("model.obj:{line}:1: ")), "{en}");
        assert!(en.contains("crosses or touches itself"), "{en}");
        let ja = e.describe(Lang::Ja);
        assert!(ja.contains("交わるか接して"), "{ja}");
    }
}

/// A ring of `n` corners around the origin, alternately at radius 1 and 0.6: concave (from any
/// first corner), and never crossing itself.
fn cog(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|k| {
            let a = k as f64 * std::f64::consts::TAU / n as f64;
            DVec2::from_angle(a) * if k % 2 == 0 { 1.0 } else { 0.6 }
        })
        .collect()
}

#[test]
fn corners_are_bounded_for_concave_faces_only() {
    let points = |ring: &[DVec2]| -> Vec<Vec3> {
        ring.iter().map(|q| Vec3::new(q.x as f32, q.y as f32, 0.0)).collect()
    };
    // The most a concave face may have: split, and covered once.
    let ring = cog(MAX_CONCAVE_CORNERS);
    let mesh = load(&one_face("", &points(&ring)));
    assert_eq!(mesh.faces.len(), MAX_CONCAVE_CORNERS - 2);
    let flat: Vec<DVec2> =
        mesh.positions.iter().map(|p| DVec2::new(p.x.into(), p.y.into())).collect();
    assert_covers_once(&flat, &mesh.faces, "the largest concave face").unwrap();
    // One more pair of corners: an error that says how many may be.
    let e = error(&one_face("", &points(&cog(MAX_CONCAVE_CORNERS + 2))));
    let problem = PolygonProblem::TooManyCorners { max: MAX_CONCAVE_CORNERS };
    assert_eq!(*e.kind, ErrorKind::ObjPolygon { corners: MAX_CONCAVE_CORNERS + 2, problem });
    assert!(e.to_string().contains(&format!("at most {MAX_CONCAVE_CORNERS}")), "{e}");
    // A convex face of any size is its fan.
    let n = 5000;
    let circle: Vec<DVec2> =
        (0..n).map(|k| DVec2::from_angle(k as f64 * std::f64::consts::TAU / n as f64)).collect();
    let mesh = load(&one_face("", &points(&circle)));
    assert_eq!(mesh.faces.len(), n - 2);
    assert!(mesh.faces.iter().enumerate().all(|(i, f)| *f == [0, i as u32 + 1, i as u32 + 2]));
}

/// A five-pointed star whose inner corners are within 10⁻⁸ of its centre does not cross itself,
/// but ear clipping (earcut) cannot cover it exactly: an error that names its line, not a face
/// drawn with a hole or an overlap. With its inner corners 10⁻³ out it is split and covered.
#[test]
fn a_face_ear_clipping_cannot_cover_exactly_is_an_error() {
    let star = |inner: f64| -> Vec<Vec3> {
        (0..10)
            .map(|k| {
                let q = DVec2::from_angle(k as f64 * std::f64::consts::TAU / 10.0)
                    * if k % 2 == 0 { 1.0 } else { inner };
                Vec3::new(q.x as f32, q.y as f32, 0.0)
            })
            .collect()
    };
    let text = one_face("", &star(1e-8));
    let e = error(&text);
    let problem = PolygonProblem::NotCovered;
    assert_eq!(*e.kind, ErrorKind::ObjPolygon { corners: 10, problem });
    assert_eq!(e.position.map(|p| (p.line, p.column)), Some((11, 1)));
    let en = e.to_string();
    assert!(en.starts_with("model.obj:11:1: ") && en.contains("cover it exactly"), "{en}");
    assert!(e.describe(Lang::Ja).contains("ぴったり覆う三角形に分割できませんでした"));
    let points = star(1e-3);
    let mesh = load(&one_face("", &points));
    assert_eq!(mesh.faces.len(), 8);
    let flat: Vec<DVec2> = points.iter().map(|p| DVec2::new(p.x.into(), p.y.into())).collect();
    assert_covers_once(&flat, &mesh.faces, "the star").unwrap();
}
