//! Every handler of every assignment's table, called the way the worker calls it (arguments
//! encoded as the pipe encodes them, the reply too), gives exactly what calling the reference solution
//! directly gives: equal values, floats equal bit for bit. And every field of each `Impl` has its
//! handler.
//!
//! Bit-equality is checked on the `Debug` text: Rust prints an `f32` as the shortest decimal that
//! reads back as the same bits (and `-0.0` as `-0.0`), so two values print alike exactly when
//! every float in them has the same bits (NaN aside: none of the values compared so is NaN).

use std::fmt::Debug;

use cg_student::Rgb;
use cg_student::a1::{Numbering, Order, Placement, RidgeAxis, Shape, Spec as A1Spec, Turn};
use cg_student::a2::{
    CameraState, Drag, DragAxis, Gesture, MouseButton, Operation, Pan, Spec as A2Spec,
};
use cg_student::a3::{self, Motion, Object, State, WorldAxis};
use cg_student::a4::{Region, Spec as A4Spec};
use cg_student::gl::Gl;
use cg_student::glam::{Vec2, Vec3};
use cg_student::mesh::Mesh;
use cg_student::s::{Pixel, Shading};
use cg_worker::serve::Handler;
use cg_worker::tables::{self, A3Spec, Queries};
use cg_worker::{Call, Reply};
use serde::Serialize;
use serde::de::DeserializeOwned;

// ---------------------------------------------------------------------------------------------
// The pipe, in process
// ---------------------------------------------------------------------------------------------

/// What `Worker::call` and `serve` do with one call, without the process: the call encoded as
/// a frame's bytes, read back, handed to the handler of that name; the reply encoded, read back
/// and read as `R`.
fn pipe<A: Serialize, R: DeserializeOwned>(
    table: &[(&str, Handler)],
    function: &str,
    args: &A,
) -> R {
    let call = Call { function: function.to_owned(), args: cg_worker::to_value(args).unwrap() };
    let sent = cg_worker::encode(&call).unwrap();
    let call: Call = cg_worker::decode(&sent).unwrap();
    let (_, handler) = table
        .iter()
        .find(|(name, _)| *name == call.function)
        .unwrap_or_else(|| panic!("no handler {function}"));
    let reply = match handler(call.args) {
        Ok(value) => Reply::Value(value),
        Err(why) => Reply::BadArguments(why),
    };
    let back = cg_worker::encode(&reply).unwrap();
    match cg_worker::decode::<Reply>(&back).unwrap() {
        Reply::Value(v) => cg_worker::from_value(&v)
            .unwrap_or_else(|e| panic!("{function}: the reply does not read: {e}")),
        other => panic!("{function}: {other:?}"),
    }
}

/// The same value, bit for bit (see the module docs).
#[track_caller]
fn same<T: Debug + PartialEq>(what: &str, direct: &T, piped: &T) {
    assert_eq!(format!("{direct:?}"), format!("{piped:?}"), "{what}");
    assert!(direct == piped, "{what}");
}

fn names(table: &[(&'static str, Handler)]) -> Vec<&'static str> {
    table.iter().map(|(name, _)| *name).collect()
}

/// `<id>.<field>` for each field, then `<id>.<batch>` for each batch operation.
fn expected(id: &str, fields: &[&str], batch: &[&str]) -> Vec<String> {
    fields.iter().chain(batch).map(|f| format!("{id}.{f}")).collect()
}

/// A fixed pseudo-random sequence (64-bit LCG): the same numbers on every run.
struct Lcg(u64);

impl Lcg {
    fn next(&mut self) -> u32 {
        self.0 =
            self.0.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 32) as u32
    }

    /// In `[lo, hi)`.
    fn f(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * (self.next() >> 8) as f32 / (1u32 << 24) as f32
    }

    fn v(&mut self) -> Vec3 {
        Vec3::new(self.f(-2.0, 2.0), self.f(-2.0, 2.0), self.f(-2.0, 2.0))
    }

    fn unit(&mut self) -> Vec3 {
        loop {
            let v = self.v();
            if v.length() > 0.1 {
                return v.normalize();
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Every field has its handler
// ---------------------------------------------------------------------------------------------

#[test]
fn every_field_of_every_impl_has_its_handler_and_nothing_else_is_offered() {
    let a1 = tables::a1(cg_solutions::a1::implementation());
    assert_eq!(names(&a1), expected("a1", tables::A1_FIELDS, &[]));
    let a2 = tables::a2(cg_solutions::a2::implementation());
    assert_eq!(names(&a2), expected("a2", tables::A2_FIELDS, &[]));
    let a3 = tables::a3(cg_solutions::a3::implementation());
    assert_eq!(names(&a3), expected("a3", tables::A3_FIELDS, tables::A3_BATCH));
    let a4 = tables::a4(cg_solutions::a4::implementation());
    assert_eq!(names(&a4), expected("a4", tables::A4_FIELDS, &[]));
    let s = tables::s(cg_solutions::s::implementation());
    assert_eq!(names(&s), expected("s", tables::S_FIELDS, tables::S_BATCH));
}

/// The lists of fields above are the `Impl`s' fields: each destructuring names every field and
/// has no `..`, so a field added to an `Impl` fails to compile here until it is listed (and
/// `tables.rs`'s own destructuring fails the same way until it has a handler).
#[test]
fn the_lists_of_fields_are_the_impls_fields() {
    let cg_student::a1::Impl { vertices: _, faces: _, face_normals: _, model_transform: _ } =
        cg_solutions::a1::implementation();
    assert_eq!(tables::A1_FIELDS, ["vertices", "faces", "face_normals", "model_transform"]);
    let cg_student::a2::Impl { motion: _, camera: _, display: _ } =
        cg_solutions::a2::implementation();
    assert_eq!(tables::A2_FIELDS, ["motion", "camera", "display"]);
    let cg_student::a3::Impl { warmup_display: _, idle: _, display: _ } =
        cg_solutions::a3::implementation();
    assert_eq!(tables::A3_FIELDS, ["warmup_display", "idle", "display"]);
    let cg_student::a4::Impl { tex_range: _, tex_coords: _, sampler: _ } =
        cg_solutions::a4::implementation();
    assert_eq!(tables::A4_FIELDS, ["tex_range", "tex_coords", "sampler"]);
    let cg_student::s::Impl {
        ambient: _,
        diffuse: _,
        specular: _,
        attenuation: _,
        spot_factor: _,
        vertex_normals: _,
        vertex_normals_area: _,
        shade_pixel: _,
        reflect: _,
        refract: _,
    } = cg_solutions::s::implementation();
    assert_eq!(
        tables::S_FIELDS,
        [
            "ambient",
            "diffuse",
            "specular",
            "attenuation",
            "spot_factor",
            "vertex_normals",
            "vertex_normals_area",
            "shade_pixel",
            "reflect",
            "refract"
        ]
    );
}

// ---------------------------------------------------------------------------------------------
// a1
// ---------------------------------------------------------------------------------------------

fn a1_specs() -> Vec<A1Spec> {
    let shapes = [
        Shape::Pyramid { sides: 5, radius: 1.6, height: 2.4 },
        Shape::Prism { sides: 6, radius: 1.2, height: 0.8 },
        Shape::Frustum { sides: 4, bottom_radius: 2.0, top_radius: 0.7, height: 1.5 },
        Shape::Tower { sides: 8, radius: 0.6, height: 2.2, tip_height: 0.9 },
        Shape::Bipyramid { sides: 3, radius: 1.1, lower_height: 1.3, upper_height: 0.6 },
        Shape::Octahedron { radius: 1.4 },
        Shape::House {
            width: 2.4,
            depth: 1.8,
            wall_height: 1.5,
            roof_height: 0.8,
            ridge: RidgeAxis::X,
        },
        Shape::House {
            width: 1.6,
            depth: 2.2,
            wall_height: 1.1,
            roof_height: 0.7,
            ridge: RidgeAxis::Z,
        },
        Shape::Wedge { width: 2.1, depth: 1.3, height: 0.9 },
    ];
    let numberings = [
        Numbering { order: Order::BottomUp, ring: Turn::Ccw },
        Numbering { order: Order::TopDown, ring: Turn::Cw },
        Numbering { order: Order::TopDown, ring: Turn::Ccw },
        Numbering { order: Order::BottomUp, ring: Turn::Cw },
    ];
    shapes
        .iter()
        .enumerate()
        .map(|(i, &shape)| A1Spec {
            shape,
            numbering: numberings[i % numberings.len()],
            placement: Placement {
                x: -1.0 + 0.5 * i as f32,
                y: if i % 3 == 0 { 0.3 } else { 0.0 },
                z: 1.0 - 0.3 * i as f32,
                angle_deg: 15.0 * (i * 7 % 24) as f32,
            },
        })
        .collect()
}

#[test]
fn a1_through_the_pipe_is_the_direct_call() {
    let imp = cg_solutions::a1::implementation();
    let table = tables::a1(imp);
    for spec in a1_specs() {
        let what = format!("{spec:?}");
        same(&what, &(imp.vertices)(&spec), &pipe(&table, "a1.vertices", &spec));
        same(&what, &(imp.faces)(&spec), &pipe(&table, "a1.faces", &spec));
        same(&what, &(imp.face_normals)(&spec), &pipe(&table, "a1.face_normals", &spec));
        same(&what, &(imp.model_transform)(&spec), &pipe(&table, "a1.model_transform", &spec));
    }
}

// ---------------------------------------------------------------------------------------------
// a2
// ---------------------------------------------------------------------------------------------

fn operation(button: MouseButton, shift: bool, axis: DragAxis, per_px: f32) -> Operation {
    Operation { gesture: Gesture { button, shift }, axis, per_px }
}

fn a2_specs() -> Vec<A2Spec> {
    use DragAxis::{Horizontal, Vertical};
    use MouseButton::{Left, Middle, Right};
    let sample = A2Spec {
        start: CameraState {
            camera_yaw: 0.0,
            camera_pitch: -30.0,
            camera_distance: 15.0,
            target_x: 0.0,
            target_z: 0.0,
        },
        yaw: operation(Left, false, Horizontal, 1.0),
        pitch: operation(Right, false, Vertical, -1.0),
        pitch_min: -90.0,
        pitch_max: 0.0,
        distance: operation(Middle, false, Vertical, 0.1),
        distance_min: 2.0,
        distance_max: 25.0,
        pan: None,
    };
    let panning = A2Spec {
        start: CameraState {
            camera_yaw: 45.0,
            camera_pitch: -30.0,
            camera_distance: 20.0,
            target_x: 0.5,
            target_z: -1.5,
        },
        yaw: operation(Left, false, Horizontal, 0.5),
        pitch: operation(Left, false, Vertical, 1.0),
        pitch_min: -80.0,
        pitch_max: -10.0,
        distance: operation(Right, false, Horizontal, 0.2),
        distance_min: 3.0,
        distance_max: 30.0,
        pan: Some(Pan {
            x: operation(Middle, false, Horizontal, -0.01),
            z: operation(Middle, false, Vertical, -0.02),
            limit: 3.0,
        }),
    };
    let shifted = A2Spec {
        yaw: operation(Right, true, Horizontal, -0.7),
        pitch: operation(Left, true, Vertical, 0.3),
        distance: operation(Left, false, Vertical, 0.05),
        pan: Some(Pan {
            x: operation(Right, false, Horizontal, 0.03),
            z: operation(Right, false, Vertical, 0.04),
            limit: 4.5,
        }),
        ..panning.clone()
    };
    vec![sample, panning, shifted]
}

fn drags(rng: &mut Lcg, n: usize) -> Vec<Drag> {
    let buttons = [MouseButton::Left, MouseButton::Middle, MouseButton::Right];
    (0..n)
        .map(|_| Drag {
            button: buttons[(rng.next() % 3) as usize],
            shift: rng.next().is_multiple_of(2),
            dx: (rng.next() % 81) as f32 - 40.0,
            dy: (rng.next() % 81) as f32 - 40.0,
        })
        .collect()
}

#[test]
fn a2_through_the_pipe_is_the_direct_call() {
    let imp = cg_solutions::a2::implementation();
    let table = tables::a2(imp);
    let mut rng = Lcg(2);
    for spec in a2_specs() {
        // A run of drags, each from the state the last one left (so the limits are reached).
        let (mut direct, mut piped) = (spec.start, spec.start);
        for drag in drags(&mut rng, 60) {
            (imp.motion)(&spec, &mut direct, &drag);
            piped = pipe(&table, "a2.motion", &(&spec, piped, drag));
            same(&format!("{drag:?}"), &direct, &piped);
        }
        // The recorder comes back as it was after the call, whatever it held before.
        let mut before = Gl::new();
        before.color(0.1, 0.2, 0.3);
        for state in [spec.start, direct] {
            for field in ["camera", "display"] {
                let mut gl = before.clone();
                if field == "camera" {
                    (imp.camera)(&mut gl, &state);
                } else {
                    (imp.display)(&mut gl, &state);
                }
                let name = format!("a2.{field}");
                same(&name, &gl, &pipe(&table, &name, &(&before, state)));
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// a3
// ---------------------------------------------------------------------------------------------

fn octahedron(r: f32) -> Mesh {
    Mesh::new(
        vec![
            Vec3::new(0.0, -r, 0.0),
            Vec3::new(r, 0.0, 0.0),
            Vec3::new(0.0, 0.0, -r),
            Vec3::new(-r, 0.0, 0.0),
            Vec3::new(0.0, 0.0, r),
            Vec3::new(0.0, r, 0.0),
        ],
        vec![
            [0, 2, 1],
            [0, 3, 2],
            [0, 4, 3],
            [0, 1, 4],
            [5, 1, 2],
            [5, 2, 3],
            [5, 3, 4],
            [5, 4, 1],
        ],
    )
}

fn object(n: usize, shape: a3::Shape, mesh: Mesh, motion: Motion) -> Object {
    Object { name: format!("object {n}"), shape, mesh, color: [1.0, 0.6, 0.2], motion }
}

fn a3_specs() -> Vec<a3::Spec> {
    let cube = a3::Shape::Box { size: [1.2, 0.6, 0.6] };
    let octa = a3::Shape::Octahedron { radius: 0.6 };
    let one = a3::Spec {
        objects: vec![
            object(
                1,
                cube,
                a3::warmup_box(),
                Motion::Swing {
                    pivot: [-3.5, 1.0, 3.5],
                    axis: WorldAxis::Y,
                    amplitude_deg: 45.0,
                    arm: 0.0,
                    period_s: 2.5,
                },
            ),
            object(
                2,
                octa,
                octahedron(0.6),
                Motion::Orbit {
                    center: [0.0, 1.0, 0.0],
                    radius: 2.0,
                    turn: a3::Turn::Cw,
                    period_s: 5.0,
                },
            ),
            object(
                3,
                octa,
                octahedron(0.3),
                Motion::Satellite {
                    parent_index: 1,
                    radius: 1.0,
                    turn: a3::Turn::Cw,
                    period_s: 10.0,
                },
            ),
            object(
                4,
                cube,
                a3::warmup_box(),
                Motion::Hop {
                    center: [3.0, 0.3, 0.0],
                    along: WorldAxis::X,
                    span: 2.0,
                    height: 1.5,
                    period_s: 7.5,
                },
            ),
        ],
        unit_s: 2.5,
    };
    let two = a3::Spec {
        objects: vec![
            object(
                1,
                octa,
                octahedron(0.8),
                Motion::Spin {
                    position: [-2.0, 1.2, 0.5],
                    axis: WorldAxis::Z,
                    turn: a3::Turn::Ccw,
                    period_s: 1.6,
                },
            ),
            object(
                2,
                cube,
                a3::warmup_box(),
                Motion::Swing {
                    pivot: [2.0, 3.0, -1.0],
                    axis: WorldAxis::X,
                    amplitude_deg: 30.0,
                    arm: 1.5,
                    period_s: 3.2,
                },
            ),
            object(
                3,
                cube,
                a3::warmup_box(),
                Motion::Hop {
                    center: [0.0, 0.3, 2.0],
                    along: WorldAxis::Z,
                    span: 3.0,
                    height: 1.0,
                    period_s: 4.8,
                },
            ),
        ],
        unit_s: 1.6,
    };
    vec![one, two]
}

#[test]
fn a3s_meshes_cross_the_pipe_beside_the_spec_as_json_writes_it() {
    for spec in a3_specs() {
        let wire = serde_json::to_value(A3Spec(spec.clone())).unwrap();
        assert_eq!(wire["spec"], serde_json::to_value(&spec).unwrap(), "the --json form");
        assert!(wire["spec"]["objects"][0].get("mesh").is_none());
        let back: A3Spec = serde_json::from_slice(&serde_json::to_vec(&wire).unwrap()).unwrap();
        same("a3 spec", &spec, &back.0);
        // Without the meshes, a3's spec would read back with empty ones.
        let plain: a3::Spec = serde_json::from_value(wire["spec"].clone()).unwrap();
        assert!(plain.objects.iter().all(|o| o.mesh == Mesh::default()));
    }
    let mut short = serde_json::to_value(A3Spec(a3_specs().remove(0))).unwrap();
    short["meshes"].as_array_mut().unwrap().pop();
    assert!(serde_json::from_value::<A3Spec>(short).is_err(), "a mesh missing is no spec");
}

#[test]
fn a3_through_the_pipe_is_the_direct_call() {
    let imp = cg_solutions::a3::implementation();
    let table = tables::a3(imp);
    for t in [0.0, 0.25, 1.0 / 3.0, 2.0, 3.999, 17.5, 1e4] {
        let mut gl = Gl::new();
        (imp.warmup_display)(&mut gl, t);
        same(&format!("t = {t}"), &gl, &pipe(&table, "a3.warmup_display", &(Gl::new(), t)));
    }
    for spec in a3_specs() {
        let wire = A3Spec(spec.clone());
        // idle, one frame at a time, and display at each.
        let (mut direct, mut piped) = (State::new(), State::new());
        for frame in 1..=200u64 {
            (imp.idle)(&spec, &mut direct);
            piped = pipe(&table, "a3.idle", &(&wire, &piped));
            same(&format!("frame {frame}"), &direct, &piped);
            if frame % 37 == 0 {
                let mut gl = Gl::new();
                (imp.display)(&spec, &direct, &mut gl);
                same("a3.display", &gl, &pipe(&table, "a3.display", &(&wire, &direct, Gl::new())));
            }
        }
        // frames: the checks' each_frame, mirrored.
        let frames = vec![0u64, 1, 2, 59, 60, 61, 150, 1000, 1000, 4321];
        let mut state = State::new();
        let mut done = 0;
        let mut direct = Vec::new();
        for &frame in &frames {
            while done < frame {
                (imp.idle)(&spec, &mut state);
                done += 1;
            }
            let mut gl = Gl::new();
            (imp.display)(&spec, &state, &mut gl);
            direct.push((state.clone(), gl));
        }
        let piped: Vec<(State, Gl)> = pipe(&table, "a3.frames", &(&wire, &frames));
        same("a3.frames", &direct, &piped);
    }
}

// ---------------------------------------------------------------------------------------------
// a4
// ---------------------------------------------------------------------------------------------

#[test]
fn a4_through_the_pipe_is_the_direct_call() {
    let imp = cg_solutions::a4::implementation();
    let table = tables::a4(imp);
    let regions = [
        Region { column: 0, row: 0, columns: 1, rows: 1 },
        Region { column: 2, row: 3, columns: 3, rows: 2 },
        Region { column: 5, row: 1, columns: 2, rows: 4 },
        Region { column: 0, row: 0, columns: 8, rows: 8 },
    ];
    let mut n = 0;
    for region in regions {
        for rotation_deg in [0, 90, 180, 270] {
            for mirrored in [false, true] {
                n += 1;
                let spec = A4Spec { region, rotation_deg, mirrored, repeat: [1, 2, 5][n % 3] };
                let what = format!("{spec:?}");
                same(&what, &(imp.tex_range)(&spec), &pipe(&table, "a4.tex_range", &spec));
                for i in 0..10 {
                    for j in 0..10 {
                        let piped: [Vec2; 4] = pipe(&table, "a4.tex_coords", &(spec, i, j));
                        same(&what, &(imp.tex_coords)(&spec, i, j), &piped);
                    }
                }
            }
        }
    }
    same("a4.sampler", &(imp.sampler)(), &pipe(&table, "a4.sampler", &()));
}

// ---------------------------------------------------------------------------------------------
// s
// ---------------------------------------------------------------------------------------------

#[test]
fn s_through_the_pipe_is_the_direct_call() {
    let imp = cg_solutions::s::implementation();
    let table = tables::s(imp);
    let mut rng = Lcg(5);
    for _ in 0..300 {
        let (ia, ka, kd) = (rng.v().abs(), rng.v().abs(), rng.v().abs());
        let (n, l, v) = (rng.unit(), rng.unit(), rng.unit());
        let shininess = rng.f(1.0, 128.0);
        same("ambient", &(imp.ambient)(ia, ka), &pipe(&table, "s.ambient", &(ia, ka)));
        same("diffuse", &(imp.diffuse)(ia, kd, n, l), &pipe(&table, "s.diffuse", &(ia, kd, n, l)));
        same(
            "specular",
            &(imp.specular)(ia, ka, n, l, v, shininess),
            &pipe(&table, "s.specular", &(ia, ka, n, l, v, shininess)),
        );
        let (kc, kl, kq, d) = (rng.f(0.5, 2.0), rng.f(0.0, 1.0), rng.f(0.0, 0.5), rng.f(0.0, 20.0));
        same(
            "attenuation",
            &(imp.attenuation)(kc, kl, kq, d),
            &pipe(&table, "s.attenuation", &(kc, kl, kq, d)),
        );
        let (cutoff, exponent) = (rng.f(5.0, 90.0), rng.f(0.0, 20.0));
        same(
            "spot_factor",
            &(imp.spot_factor)(l, n, cutoff, exponent),
            &pipe(&table, "s.spot_factor", &(l, n, cutoff, exponent)),
        );
        same("reflect", &(imp.reflect)(v, n), &pipe(&table, "s.reflect", &(v, n)));
        // Both ways through the surface, so total internal reflection (None) comes up too.
        let (n1, n2) = if rng.next().is_multiple_of(2) { (1.0, 1.5) } else { (1.5, 1.0) };
        same("refract", &(imp.refract)(v, n, n1, n2), &pipe(&table, "s.refract", &(v, n, n1, n2)));
    }
    for mesh in [a3::warmup_box(), octahedron(0.7), skewed(&mut rng)] {
        same(
            "vertex_normals",
            &(imp.vertex_normals)(&mesh),
            &pipe(&table, "s.vertex_normals", &mesh),
        );
        same(
            "vertex_normals_area",
            &(imp.vertex_normals_area)(&mesh),
            &pipe(&table, "s.vertex_normals_area", &mesh),
        );
    }
}

/// A closed mesh with triangles of different sizes (the two averages differ).
fn skewed(rng: &mut Lcg) -> Mesh {
    let mut mesh = octahedron(1.0);
    for p in &mut mesh.positions {
        *p += 0.3 * rng.v();
    }
    mesh
}

fn pixels(rng: &mut Lcg, n: usize) -> Vec<Pixel> {
    (0..n)
        .map(|_| {
            let positions = [rng.v(), rng.v(), rng.v()];
            let face_normal = (positions[1] - positions[0])
                .cross(positions[2] - positions[0])
                .normalize_or(Vec3::Y);
            let (a, b) = (rng.f(0.0, 1.0), rng.f(0.0, 1.0));
            let (a, b) = if a + b > 1.0 { (1.0 - a, 1.0 - b) } else { (a, b) };
            Pixel {
                positions,
                normals: [rng.unit(), rng.unit(), rng.unit()],
                face_normal,
                weights: [1.0 - a - b, a, b],
            }
        })
        .collect()
}

/// The trusted side's light in these tests: a point light at (4, 5, 6), Lambert's term,
/// clamped to `[0, 1]`.
fn lambert(p: Vec3, n: Vec3) -> Rgb {
    let l = (Vec3::new(4.0, 5.0, 6.0) - p).normalize_or_zero();
    (Vec3::new(0.9, 0.8, 0.7) * n.dot(l).max(0.0)).clamp(Vec3::ZERO, Vec3::ONE)
}

#[test]
fn shade_pixel_in_two_phases_is_the_direct_call_with_the_same_light() {
    let imp = cg_solutions::s::implementation();
    let table = tables::s(imp);
    let mut rng = Lcg(11);
    let pixels = pixels(&mut rng, 500);
    for mode in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
        let queries: Vec<Queries> = pipe(&table, "s.shade_pixels_queries", &(mode, &pixels));
        assert_eq!(queries.len(), pixels.len());
        let asked = if mode == Shading::Gouraud { 3 } else { 1 };
        assert!(queries.iter().all(|q| q.len() == asked), "{mode:?}");
        let answers: Vec<Vec<Rgb>> =
            queries.iter().map(|q| q.iter().map(|&(p, n)| lambert(p, n)).collect()).collect();
        let piped: Result<Vec<Rgb>, cg_worker::Reason> =
            pipe(&table, "s.shade_pixels", &(mode, &pixels, &queries, &answers));
        let direct: Vec<Rgb> =
            pixels.iter().map(|p| (imp.shade_pixel)(mode, p, &lambert)).collect();
        same(&format!("{mode:?}"), &Ok(direct.clone()), &piped);
        // One pixel at a time: the same.
        for (i, pixel) in pixels.iter().enumerate().take(20) {
            let one: Result<Rgb, cg_worker::Reason> =
                pipe(&table, "s.shade_pixel", &(mode, pixel, &queries[i], &answers[i]));
            same(&format!("{mode:?} pixel {i}"), &Ok(direct[i]), &one);
        }
    }
}

/// `shade_pixel`'s type in `s::Impl`.
type ShadePixel = fn(Shading, &Pixel, &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb;

/// Asks once more when the answer is not the recording light's colour.
fn asks_again(_: Shading, pixel: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    let c = light(pixel.positions[0], pixel.normals[0]);
    if c == tables::QUERY_COLOUR { c } else { c + light(pixel.positions[1], pixel.normals[1]) }
}

/// Its second query's point depends on the first answer.
fn asks_elsewhere(_: Shading, pixel: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    let c = light(pixel.positions[0], pixel.normals[0]);
    light(pixel.positions[0] + c, pixel.normals[0])
}

/// Asks only the first of its usual two queries when the first answer is dark.
fn asks_less(_: Shading, pixel: &Pixel, light: &dyn Fn(Vec3, Vec3) -> Rgb) -> Rgb {
    let c = light(pixel.positions[0], pixel.normals[0]);
    if c.x < 0.5 { c } else { c + light(pixel.positions[1], pixel.normals[1]) }
}

#[test]
fn a_function_that_asks_the_light_otherwise_the_second_time_is_told_not_answered() {
    let mut rng = Lcg(13);
    let pixels = pixels(&mut rng, 4);
    let dark = |_: Vec3, _: Vec3| Vec3::splat(0.25);
    let answer = |queries: &[Queries]| -> Vec<Vec<Rgb>> {
        queries.iter().map(|q| q.iter().map(|&(p, n)| dark(p, n)).collect()).collect()
    };
    for (shade, wrong) in [
        (asks_again as ShadePixel, Some("asked 2 times or more, 1 times the first time")),
        (asks_elsewhere, Some("light query 1 was light(")),
        (asks_less, None),
    ] {
        let imp = cg_student::s::Impl { shade_pixel: shade, ..cg_solutions::s::implementation() };
        let table = tables::s(imp);
        let queries: Vec<Queries> =
            pipe(&table, "s.shade_pixels_queries", &(Shading::Phong, &pixels));
        let answers = answer(&queries);
        let piped: Result<Vec<Rgb>, cg_worker::Reason> =
            pipe(&table, "s.shade_pixels", &(Shading::Phong, &pixels, &queries, &answers));
        match wrong {
            Some(why) => {
                let err = piped.expect_err("a different question is no answer");
                assert!(err.en.starts_with("pixel 0: ") && err.en.contains(why), "{err:?}");
                assert!(
                    err.ja.starts_with("ピクセル 0: ") && err.ja.contains("同じピクセルで 2 回"),
                    "{err:?}"
                );
            }
            // Fewer questions: each one asked was answered for what it asked.
            None => {
                let direct: Vec<Rgb> =
                    pixels.iter().map(|p| shade(Shading::Phong, p, &dark)).collect();
                same("asks_less", &Ok(direct), &piped);
            }
        }
    }
    // Answers that do not fit the pixels are refused, not guessed.
    let table = tables::s(cg_solutions::s::implementation());
    let short: Result<Vec<Rgb>, cg_worker::Reason> = pipe(
        &table,
        "s.shade_pixels",
        &(Shading::Flat, &pixels, Vec::<Queries>::new(), Vec::<Vec<Rgb>>::new()),
    );
    assert!(short.is_err());
}

// ---------------------------------------------------------------------------------------------
// Floats on the wire
// ---------------------------------------------------------------------------------------------

/// A spec's f32 fields marked `serialize_with = "friendly"` are written as the f64 nearest to the
/// f32's shortest decimal (`1.6`, not `1.600000023841858`); rounding that f64 to f32 is a second
/// rounding, and an exhaustive run over all 2³² bit patterns found one magnitude where it lands on
/// the neighbour ([`FRIENDLY_CORNER_CASES`]). So those fields read back with
/// `deserialize_with = "unfriendly"` (the f32 whose shortest decimal was written). This runs a
/// spread of f32 values (every sign and exponent: a stride through all bit patterns; the decimals
/// of the tables; the corner cases) through a friendly field and the pipe's JSON and counts those
/// that come back with other bits.
#[test]
fn friendly_f32_fields_cross_the_pipe_bit_for_bit() {
    let mut values: Vec<f32> = (0..=u32::MAX).step_by(4099).map(f32::from_bits).collect();
    values.extend((0..=100_000).map(|i| i as f32 / 1000.0)); // 0.000 … 100.000, the tables' kind
    values.extend((0..=100_000).map(|i| -(i as f32) / 100.0));
    values.extend(FRIENDLY_CORNER_CASES.iter().map(|&b| f32::from_bits(b)));
    values.retain(|x| x.is_finite());
    let mut differ = Vec::new();
    let mut corner_cases_seen = 0;
    for chunk in values.chunks(4) {
        let &[x, y, z, angle_deg] = chunk else { continue };
        let placement = Placement { x, y, z, angle_deg };
        let text = serde_json::to_vec(&serde_json::to_value(placement).unwrap()).unwrap();
        let value: serde_json::Value = serde_json::from_slice(&text).unwrap();
        let back: Placement = serde_json::from_value(value).unwrap();
        for (a, b) in [(x, back.x), (y, back.y), (z, back.z), (angle_deg, back.angle_deg)] {
            corner_cases_seen += usize::from(FRIENDLY_CORNER_CASES.contains(&a.to_bits()));
            if a.to_bits() != b.to_bits() {
                differ.push((a, b));
            }
        }
    }
    assert_eq!(corner_cases_seen, FRIENDLY_CORNER_CASES.len());
    assert!(
        differ.is_empty(),
        "{} of {} f32 values changed crossing the pipe through a friendly field, e.g. {:?}",
        differ.len(),
        values.len(),
        &differ[..differ.len().min(10)]
    );
    // a3's three at a time (`friendly3`), the corner cases among them.
    for chunk in values.chunks(3).rev().take(50_000) {
        let &[x, y, z] = chunk else { continue };
        let shape = a3::Shape::Box { size: [x, y, z] };
        let text = serde_json::to_vec(&serde_json::to_value(shape).unwrap()).unwrap();
        let back: a3::Shape = serde_json::from_slice(&text).unwrap();
        same("a3 box", &shape, &back);
    }
}

/// Where reading the friendly f64 as the nearest f32 is wrong: rounding the shortest decimal to
/// f64 (correctly), then to f32, lands on the neighbour, so a plain f32 field would read another
/// number; `unfriendly` reads the f32 back. (serde_json's own parser, which rounds these
/// exponents less carefully, happens to land right: an exhaustive run of every finite f32
/// through friendly, serde_json's text and a plain f32 read found no difference. A correctly
/// rounding parser, such as serde_json's `float_roundtrip` feature, would.)
#[test]
fn the_corner_cases_are_double_roundings_and_read_back() {
    for &bits in FRIENDLY_CORNER_CASES {
        let x = f32::from_bits(bits);
        let v = x.to_string().parse::<f64>().unwrap();
        assert_ne!((v as f32).to_bits(), bits, "{x:e}");
        // The correctly rounded f64, as a JSON number without a parser in between.
        let value = serde_json::json!({ "x": v, "y": v, "z": v, "angle_deg": v });
        let back: Placement = serde_json::from_value(value).unwrap();
        same(&format!("{x:e}"), &Placement { x, y: x, z: x, angle_deg: x }, &back);
        let shape: a3::Shape =
            serde_json::from_value(serde_json::json!({ "kind": "box", "size": [v, v, v] }))
                .unwrap();
        same(&format!("{x:e}"), &a3::Shape::Box { size: [x; 3] }, &shape);
    }
}

/// The f32 bit patterns whose shortest decimal, read as f64 (correctly rounded) and then as
/// f32, is another f32: an exhaustive run over all 2³² patterns found these two (±7.038531e-26).
const FRIENDLY_CORNER_CASES: &[u32] = &[0x15ae_43fd, 0x95ae_43fd];

/// Every other f32 (the recorder's numbers, glam's vectors, every result) is written as the f64
/// of the same value and read back exactly.
#[test]
fn every_f32_crosses_the_pipe_bit_for_bit() {
    let mut values: Vec<f32> = (0..=u32::MAX).step_by(4099).map(f32::from_bits).collect();
    values.extend([0.1, -0.0, f32::MIN_POSITIVE, f32::MAX, f32::MIN, f32::EPSILON, 1e-45]);
    values.extend([f32::INFINITY, f32::NEG_INFINITY, f32::NAN]);
    let bytes = cg_worker::encode(&cg_worker::to_value(&values).unwrap()).unwrap();
    let value: cg_worker::Value = cg_worker::decode(&bytes).unwrap();
    let back: Vec<f32> = cg_worker::from_value(&value).unwrap();
    assert_eq!(back.len(), values.len());
    for (a, b) in values.iter().zip(&back) {
        // NaN stays NaN (its payload may not); every other value keeps its bits.
        assert!(a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()), "{a:?} came back {b:?}");
    }
}

/// A function may return NaN or ±∞ (a zero vector normalised, a division by zero): the checks
/// must see exactly that, as they do when the function runs in their own process (JSON, which
/// has neither, would have turned the reply into an error).
#[test]
fn a_non_finite_float_crosses_the_pipe_as_itself() {
    let imp = cg_student::s::Impl {
        reflect: |_, _| Vec3::new(f32::NAN, 1.0, 2.0),
        refract: |_, _, _, _| Some(Vec3::new(0.0, f32::INFINITY, 0.0)),
        attenuation: |_, _, _, _| f32::NEG_INFINITY,
        ..cg_solutions::s::implementation()
    };
    let table = tables::s(imp);
    let reflect: Vec3 = pipe(&table, "s.reflect", &(Vec3::X, Vec3::Y));
    assert!(reflect.x.is_nan() && reflect.y == 1.0 && reflect.z == 2.0, "{reflect:?}");
    let refract: Option<Vec3> = pipe(&table, "s.refract", &(Vec3::X, Vec3::Y, 1.0, 1.5));
    assert_eq!(refract, Some(Vec3::new(0.0, f32::INFINITY, 0.0)));
    let attenuation: f32 = pipe(&table, "s.attenuation", &(1.0, 0.0, 0.0, 1.0));
    assert_eq!(attenuation, f32::NEG_INFINITY);
}
