//! Deriving the report's data: from the student's own exercises (each assignment's `Impl` and
//! the student's `Spec`), or from data alone (a vertex and face list).
//!
//! [`derive()`] runs every part on its own — the polygon model (a1), the view matrix (a2), each
//! animated object's model matrix (a3), the texture-coordinate table (a4) — so a part whose
//! function is still a stub (or panics, or returns unusable data) is [`Missing`] while the
//! others still derive. Every call of the student's code goes through
//! [`cg_harness::check::guarded`]: a `todo!()` or a panic becomes a message, never a crash.
//!
//! Matrices come from the student's own calls, recorded by [`Gl`] (the products are the
//! student's factors, in the student's order). The *symbolic* form names each number that is a
//! variable: the student's code runs once more at a *probe* — a mouse state (a2) or a frame (a3)
//! where every variable has a value of its own — and each factor parameter that equals a
//! variable there (or its negative; an angle also up to whole turns) is named after it
//! (`Rx(-camera_pitch)`, `Ry(theta_2)`), keeping the value it has at the stated state, so the
//! symbolic and the numeric product are the same matrix. Constants stay numbers; names the
//! student gave (`Param::sym`) are kept.

use cg_a2::{CameraState, Drag, DragAxis, Gesture, MouseButton, Operation};
use cg_a3::{Motion, WorldAxis};
use cg_assign::Assignment;
use cg_core::gl::{Draw, Gl};
use cg_core::glam::{DMat3, DMat4, Mat4, Vec2, Vec3};
use cg_core::lang::Lang;
use cg_core::normals::face_normal;
use cg_core::product::{Factor, MatrixProduct, Param, format_number};
use cg_harness::Text;
use cg_harness::check::{Outcome, guarded, stub_message};

use crate::model::{
    AnimationData, CameraData, Derived, NamedMatrix, PolygonData, TexRow, TextureData,
};
use cg_a1::ShapeExt as _;
use cg_a2::SpecExt as _;
use cg_a3::SpecExt as _;
use cg_a3::WorldAxisExt as _;
use cg_a4::RegionExt as _;
use cg_a4::SpecExt as _;

// ---------------------------------------------------------------------------------------------
// The student's functions, and what could not be derived
// ---------------------------------------------------------------------------------------------

/// The functions a student writes, one `Impl` per assignment.
#[derive(Clone, Copy, Debug)]
pub struct Impls {
    /// Assignment 1: the polygon model.
    pub a1: cg_a1::Impl,
    /// Assignment 2: the camera.
    pub a2: cg_a2::Impl,
    /// Assignment 3: the animation.
    pub a3: cg_a3::Impl,
    /// Assignment 4: the texture mapping.
    pub a4: cg_a4::Impl,
}

impl Impls {
    /// The student's own functions, from `exercises/`.
    #[must_use]
    pub fn exercises() -> Impls {
        Impls {
            a1: cg_exercises::a1::implementation(),
            a2: cg_exercises::a2::implementation(),
            a3: cg_exercises::a3::implementation(),
            a4: cg_exercises::a4::implementation(),
        }
    }
}

/// A part of the report that could not be derived: the student's function is still a stub,
/// panicked, or returned data the report cannot use.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Missing {
    /// The task whose function is at fault (`a1.t2`).
    pub task: String,
    /// Why, for the student.
    pub why: Text,
}

impl Missing {
    /// A missing part of `task`, and why.
    #[must_use]
    pub fn new(task: impl Into<String>, why: Text) -> Missing {
        Missing { task: task.into(), why }
    }

    /// `a1.t2: …` in `lang`.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        format!("{}: {}", self.task, self.why.get(lang))
    }

    /// What a guarded call of `function` (`faces()`) ended with, as a missing part of `task`.
    fn from_outcome(task: &str, function: &str, outcome: Outcome) -> Missing {
        let why = match outcome {
            Outcome::NotDone { message } => Text::new(
                format!(
                    "{function} はまだ書かれていません（{}）",
                    stub_message(&message, Lang::Ja)
                ),
                format!("{function} is not written yet ({})", stub_message(&message, Lang::En)),
            ),
            Outcome::Panicked { message, location } => {
                let at = location.map(|l| format!(" ({l})")).unwrap_or_default();
                Text::new(
                    format!("{function} が異常終了しました（panic）: {message}{at}"),
                    format!("{function} panicked: {message}{at}"),
                )
            }
            Outcome::Pass | Outcome::Fail(_) => Text::new(
                format!("{function} の結果が得られませんでした"),
                format!("{function} gave no result"),
            ),
        };
        Missing::new(task, why)
    }
}

/// A part's data (or why there is none) and the smaller parts it had to leave out.
type Part<T> = (Result<T, Missing>, Vec<Missing>);

/// Everything the report needs from `assignment`'s student, from `impls`: each part on its own,
/// so a missing part leaves its field `None` while the others derive. The list names every part
/// (and every smaller piece, such as the student's own normals) that could not be derived.
#[must_use]
pub fn derive(assignment: &Assignment, impls: &Impls) -> (Derived, Vec<Missing>) {
    fn take<T>((result, notes): Part<T>, missing: &mut Vec<Missing>) -> Option<T> {
        let value = match result {
            Ok(value) => Some(value),
            Err(m) => {
                missing.push(m);
                None
            }
        };
        missing.extend(notes);
        value
    }
    let mut missing = Vec::new();
    let derived = Derived {
        student: Some(assignment.student.to_string()),
        polygon: take(polygon_part(&assignment.a1, &impls.a1), &mut missing),
        camera: take(camera_part(&assignment.a2, &impls.a2), &mut missing),
        animation: take(animation_part(&assignment.a3, &impls.a3), &mut missing),
        texture: take(texture_part(&assignment.a4, &impls.a4), &mut missing),
    };
    (derived, missing)
}

// ---------------------------------------------------------------------------------------------
// a1: the polygon model
// ---------------------------------------------------------------------------------------------

/// The polygon model from the student's a1 functions: vertices (a1.t1) and faces (a1.t2), the
/// normals the kit derives from them, the student's own normals (a1.t3) and the placement
/// (a1.t4) when those work. A missing or unusable a1.t3 or a1.t4 only leaves its field `None`.
///
/// # Errors
/// a1.t1 or a1.t2 not written, panicking, or returning nothing or a vertex that is not finite.
pub fn polygon(spec: &cg_a1::Spec, imp: &cg_a1::Impl) -> Result<PolygonData, Missing> {
    polygon_part(spec, imp).0
}

fn polygon_part(spec: &cg_a1::Spec, imp: &cg_a1::Impl) -> Part<PolygonData> {
    let vertices = match guarded(|| (imp.vertices)(spec)) {
        Ok(v) => v,
        Err(o) => return (Err(Missing::from_outcome("a1.t1", "vertices()", o)), Vec::new()),
    };
    if vertices.is_empty() {
        let why = Text::new("vertices() が頂点を返していません", "vertices() returns no vertices");
        return (Err(Missing::new("a1.t1", why)), Vec::new());
    }
    if let Some(k) = vertices.iter().position(|v| !v.is_finite()) {
        let v = vec3_text(vertices[k]);
        let why = Text::new(
            format!("V{k} {v} が有限の値ではありません"),
            format!("V{k} {v} is not finite"),
        );
        return (Err(Missing::new("a1.t1", why)), Vec::new());
    }
    let faces = match guarded(|| (imp.faces)(spec)) {
        Ok(f) => f,
        Err(o) => return (Err(Missing::from_outcome("a1.t2", "faces()", o)), Vec::new()),
    };
    if faces.is_empty() {
        let why = Text::new("faces() が面を返していません", "faces() returns no faces");
        return (Err(Missing::new("a1.t2", why)), Vec::new());
    }
    let mut notes = Vec::new();
    let student_normals = match guarded(|| (imp.face_normals)(spec)) {
        Ok(n) if n.len() != faces.len() => {
            notes.push(Missing::new(
                "a1.t3",
                Text::new(
                    format!(
                        "face_normals() の法線が {} 個あります（面は {} 個）",
                        n.len(),
                        faces.len()
                    ),
                    format!("face_normals() returns {} normals for {} faces", n.len(), faces.len()),
                ),
            ));
            None
        }
        Ok(n) => match n.iter().position(|v| !v.is_finite()) {
            Some(k) => {
                let v = vec3_text(n[k]);
                notes.push(Missing::new(
                    "a1.t3",
                    Text::new(
                        format!("F{k} の法線 {v} が有限の値ではありません"),
                        format!("F{k}'s normal {v} is not finite"),
                    ),
                ));
                None
            }
            None => Some(n),
        },
        Err(o) => {
            notes.push(Missing::from_outcome("a1.t3", "face_normals()", o));
            None
        }
    };
    let transform = match guarded(|| MatrixProduct::from((imp.model_transform)(spec))) {
        Ok(p) => match p.matrix() {
            Ok(_) => Some(p),
            Err(e) => {
                notes.push(Missing::new(
                    "a1.t4",
                    Text::new(
                        format!(
                            "model_transform() の積が行列になりません: {}",
                            e.message(Lang::Ja)
                        ),
                        format!(
                            "model_transform()'s product is not a matrix: {}",
                            e.message(Lang::En)
                        ),
                    ),
                ));
                None
            }
        },
        Err(o) => {
            notes.push(Missing::from_outcome("a1.t4", "model_transform()", o));
            None
        }
    };
    let name = Text::new(spec.shape.name(Lang::Ja), spec.shape.name(Lang::En));
    let mut data = polygon_from_data(name, vertices, faces, student_normals);
    data.transform = transform;
    (Ok(data), notes)
}

// ---------------------------------------------------------------------------------------------
// Data alone
// ---------------------------------------------------------------------------------------------

/// A polygon model from data alone: the kit derives each face's normal from the vertices and
/// the order of the face's vertex numbers (`None` for a degenerate face or a vertex number out
/// of range). `student_normals` are the normals the data gives, if any.
#[must_use]
pub fn polygon_from_data(
    name: Text,
    vertices: Vec<Vec3>,
    faces: Vec<[u32; 3]>,
    student_normals: Option<Vec<Vec3>>,
) -> PolygonData {
    let derived_normals = faces
        .iter()
        .map(|f| {
            let v = |k: usize| vertices.get(f[k] as usize).copied();
            match (v(0), v(1), v(2)) {
                (Some(a), Some(b), Some(c)) => face_normal(a, b, c),
                _ => None,
            }
        })
        .collect();
    PolygonData { name, vertices, faces, derived_normals, student_normals, transform: None }
}

// ---------------------------------------------------------------------------------------------
// Naming the variables of a recorded product
// ---------------------------------------------------------------------------------------------

/// A variable and its value at the probe.
#[derive(Clone, Debug, PartialEq)]
struct Var {
    name: String,
    value: f32,
}

/// Whether `x` is `v` within `1e-4` relative (absolute below 1).
fn close(x: f32, v: f32) -> bool {
    (x - v).abs() <= 1e-4 * v.abs().max(1.0)
}

/// Whether the angles `x` and `v` (degrees) differ by whole turns only.
fn close_turns(x: f32, v: f32) -> bool {
    let d = (f64::from(x) - f64::from(v)).rem_euclid(360.0);
    d <= 1e-3 || 360.0 - d <= 1e-3
}

/// The variable `x` is (`camera_pitch`) or is the negative of (`-camera_pitch`); an angle may
/// also differ by whole turns.
fn match_var(x: f32, vars: &[Var], angle: bool) -> Option<String> {
    if !x.is_finite() {
        return None;
    }
    for v in vars {
        if close(x, v.value) {
            return Some(v.name.clone());
        }
        if close(x, -v.value) {
            return Some(format!("-{}", v.name));
        }
    }
    if angle {
        for v in vars {
            if close_turns(x, v.value) {
                return Some(v.name.clone());
            }
            if close_turns(x, -v.value) {
                return Some(format!("-{}", v.name));
            }
        }
    }
    None
}

/// Whether two factors are the same kind of call (translate, rotate about the same axis, …), so
/// that their parameters correspond.
fn same_kind(a: &Factor, b: &Factor) -> bool {
    match (a, b) {
        (Factor::Translate(_), Factor::Translate(_)) | (Factor::Scale(_), Factor::Scale(_)) => true,
        (Factor::Rotate { axis: x, .. }, Factor::Rotate { axis: y, .. }) => x == y,
        (Factor::Perspective { .. }, Factor::Perspective { .. }) => a == b,
        (Factor::Matrix { name: m, .. }, Factor::Matrix { name: n, .. }) => m == n,
        _ => false,
    }
}

/// Whether `a` and `b` are the same calls in the same order (their numbers may differ).
fn aligned(a: &MatrixProduct, b: &MatrixProduct) -> bool {
    a.factors.len() == b.factors.len()
        && a.factors.iter().zip(&b.factors).all(|(x, y)| same_kind(x, y))
}

/// The symbols of a symbolized product, each with the variable it was found to be (`None`: a
/// name of the student's own that matches no variable).
type Names = Vec<(String, Option<String>)>;

/// `at` with each parameter named after the variable its counterpart in `probe` equals (the
/// value stays `at`'s); the student's own symbols are kept. `at` unchanged when the two are not
/// the same calls. Also returns every symbol used, sign stripped, with the variable it is.
fn symbolize(probe: &MatrixProduct, at: &MatrixProduct, vars: &[Var]) -> (MatrixProduct, Names) {
    let mut names: Names = Vec::new();
    let mut note = |symbol: &str, var: Option<String>| {
        let symbol = symbol.trim_start_matches('-').to_owned();
        let var = var.map(|v| v.trim_start_matches('-').to_owned());
        if !names.iter().any(|(s, _)| *s == symbol) {
            names.push((symbol, var));
        }
    };
    if !aligned(probe, at) {
        for f in &at.factors {
            for p in params(f) {
                if let Some(s) = &p.symbol {
                    note(s, None);
                }
            }
        }
        return (at.clone(), names);
    }
    let mut name = |p: &Param, a: &Param, angle: bool| -> Param {
        let found = match_var(p.value, vars, angle);
        match &a.symbol {
            Some(s) => {
                note(s, found);
                a.clone()
            }
            None => match found {
                Some(n) => {
                    note(&n, Some(n.clone()));
                    Param::sym(n, a.value)
                }
                None => Param::num(a.value),
            },
        }
    };
    let factors = probe
        .factors
        .iter()
        .zip(&at.factors)
        .map(|(p, a)| match (p, a) {
            (Factor::Translate(p), Factor::Translate(a)) => Factor::Translate([
                name(&p[0], &a[0], false),
                name(&p[1], &a[1], false),
                name(&p[2], &a[2], false),
            ]),
            (Factor::Scale(p), Factor::Scale(a)) => Factor::Scale([
                name(&p[0], &a[0], false),
                name(&p[1], &a[1], false),
                name(&p[2], &a[2], false),
            ]),
            (Factor::Rotate { angle_deg: p, .. }, Factor::Rotate { axis, angle_deg: a }) => {
                Factor::Rotate { axis: *axis, angle_deg: name(p, a, true) }
            }
            (_, other) => other.clone(),
        })
        .collect();
    (MatrixProduct { factors }, names)
}

/// A factor's parameters.
fn params(f: &Factor) -> Vec<&Param> {
    match f {
        Factor::Translate(p) | Factor::Scale(p) => p.iter().collect(),
        Factor::Rotate { angle_deg, .. } => vec![angle_deg],
        Factor::Perspective { .. } | Factor::Matrix { .. } => Vec::new(),
    }
}

/// `p` with every parameter a plain number.
fn numeric(p: &MatrixProduct) -> MatrixProduct {
    let num = |x: &Param| Param::num(x.value);
    let factors = p
        .factors
        .iter()
        .map(|f| match f {
            Factor::Translate(p) => Factor::Translate([num(&p[0]), num(&p[1]), num(&p[2])]),
            Factor::Scale(p) => Factor::Scale([num(&p[0]), num(&p[1]), num(&p[2])]),
            Factor::Rotate { axis, angle_deg } => {
                Factor::Rotate { axis: *axis, angle_deg: num(angle_deg) }
            }
            other => other.clone(),
        })
        .collect();
    MatrixProduct { factors }
}

/// Drops the factors that are the identity in every one of `products` (a translation by the
/// target that stays at the origin), when all are the same calls; otherwise changes nothing.
fn drop_constant_identities(products: &mut [MatrixProduct]) {
    let Some(first) = products.first() else { return };
    if !products.iter().all(|p| aligned(first, p)) {
        return;
    }
    let keep: Vec<bool> = (0..first.factors.len())
        .map(|k| !products.iter().all(|p| p.factors[k].is_identity()))
        .collect();
    for p in products.iter_mut() {
        let factors = std::mem::take(&mut p.factors);
        p.factors = factors.into_iter().zip(&keep).filter(|(_, k)| **k).map(|(f, _)| f).collect();
    }
}

/// Whether two matrices agree entry by entry within `1e-4 · (1 + |b|)`.
fn matrices_close(a: &Mat4, b: &Mat4) -> bool {
    a.to_cols_array()
        .iter()
        .zip(b.to_cols_array().iter())
        .all(|(x, y)| (x - y).abs() <= 1e-4 * (1.0 + y.abs()))
}

/// `(x, y, z)` with the kit's numbers.
fn vec3_text(v: Vec3) -> String {
    format!("({}, {}, {})", format_number(v.x), format_number(v.y), format_number(v.z))
}

// ---------------------------------------------------------------------------------------------
// a2: the view matrix
// ---------------------------------------------------------------------------------------------

/// Pixels per call of `motion()` in the stated drags (GLUT calls it every few pixels).
const DRAG_STEP_PX: f32 = 10.0;

/// The mouse state the camera is probed at: every value (and its negative) distinct, and
/// distinct from 0 and ±1, inside every spec's ranges. The target stays at the origin for a spec
/// without a pan.
fn camera_probe(spec: &cg_a2::Spec) -> CameraState {
    let pan = spec.pan.is_some();
    CameraState {
        camera_yaw: 37.0,
        camera_pitch: -23.0,
        camera_distance: 13.5,
        target_x: if pan { 1.25 } else { 0.0 },
        target_z: if pan { -0.75 } else { 0.0 },
    }
}

/// The camera variables of `spec` with their values in `s`.
fn camera_vars(spec: &cg_a2::Spec, s: &CameraState) -> Vec<Var> {
    let var = |name: &str, value| Var { name: name.to_owned(), value };
    let mut vars = vec![
        var("camera_yaw", s.camera_yaw),
        var("camera_pitch", s.camera_pitch),
        var("camera_distance", s.camera_distance),
    ];
    if spec.pan.is_some() {
        vars.push(var("target_x", s.target_x));
        vars.push(var("target_z", s.target_z));
    }
    vars
}

/// `右ボタン` / `the right button`, with Shift.
fn gesture_words(g: Gesture) -> Text {
    let (ja, en) = match g.button {
        MouseButton::Left => ("左ボタン", "left button"),
        MouseButton::Middle => ("中ボタン", "middle button"),
        MouseButton::Right => ("右ボタン", "right button"),
    };
    if g.shift {
        Text::new(format!("Shift + {ja}"), format!("Shift + {en}"))
    } else {
        Text::new(ja, en)
    }
}

/// One stated drag: `px` pixels along `op`'s drag direction (right for dx, down for dy), in
/// calls of `motion()` of at most [`DRAG_STEP_PX`] pixels.
fn drag_along(op: &Operation, px: f32) -> (Vec<Drag>, Text) {
    let steps = (px.abs() / DRAG_STEP_PX).ceil().max(1.0);
    let each = px / steps;
    let (dx, dy, ja, en) = match op.axis {
        DragAxis::Horizontal => (each, 0.0, "右へ", "right"),
        DragAxis::Vertical => (0.0, each, "下へ", "down"),
    };
    let drag = Drag { button: op.gesture.button, shift: op.gesture.shift, dx, dy };
    let n = format_number(px);
    (vec![drag; steps as usize], Text::new(format!("{ja} {n} ピクセル"), format!("{n} px {en}")))
}

/// A stated state: its ID, the drags from the start that reach it, and those drags in words.
struct CameraStep {
    id: &'static str,
    drags: Vec<Drag>,
    words: Option<Text>,
}

/// The stated mouse states of `spec`: the start; the rotation drag (40 px along yaw's drag,
/// then 20 px along pitch's); the distance drag (20 px); with a pan, 40 px along each of the
/// target's drags. Each is reached from the start.
fn camera_steps(spec: &cg_a2::Spec) -> Vec<CameraStep> {
    // "右ボタンで右へ 40 ピクセル、下へ 20 ピクセル" from (operation, pixels) pairs.
    let step = |id: &'static str, moves: &[(&Operation, f32)]| {
        let mut drags = Vec::new();
        let (mut ja, mut en): (Vec<String>, Vec<String>) = (Vec::new(), Vec::new());
        let mut last: Option<Gesture> = None;
        for (op, px) in moves {
            let (d, words) = drag_along(op, *px);
            drags.extend(d);
            if last == Some(op.gesture) {
                ja.push(words.ja);
                en.push(words.en);
            } else {
                let g = gesture_words(op.gesture);
                ja.push(format!("{}で{}", g.ja, words.ja));
                en.push(format!("{} with the {}", words.en, g.en));
            }
            last = Some(op.gesture);
        }
        let words = Text::new(ja.join("、"), en.join(", then "));
        CameraStep { id, drags, words: Some(words) }
    };
    let mut steps = vec![
        CameraStep { id: "a2.view.start", drags: Vec::new(), words: None },
        step("a2.view.rotate", &[(&spec.yaw, 40.0), (&spec.pitch, 20.0)]),
        step("a2.view.zoom", &[(&spec.distance, 20.0)]),
    ];
    if let Some(pan) = &spec.pan {
        steps.push(step("a2.view.pan", &[(&pan.x, 40.0), (&pan.z, 40.0)]));
    }
    steps
}

/// The stated mouse states of the view matrices [`camera`] derives: each ID (`a2.view.start`,
/// `a2.view.rotate`, `a2.view.zoom`, and `a2.view.pan` with a pan) with the calls of `motion()`
/// that reach it from `spec.start` (none for the start).
#[must_use]
pub fn camera_drags(spec: &cg_a2::Spec) -> Vec<(String, Vec<Drag>)> {
    camera_steps(spec).into_iter().map(|s| (s.id.to_owned(), s.drags)).collect()
}

/// `camera_yaw = 30°, camera_pitch = -30°, camera_distance = 15[, target_x = …, target_z = …]`.
fn camera_state_text(spec: &cg_a2::Spec, s: &CameraState) -> String {
    let n = format_number;
    let mut out = format!(
        "camera_yaw = {}°, camera_pitch = {}°, camera_distance = {}",
        n(s.camera_yaw),
        n(s.camera_pitch),
        n(s.camera_distance)
    );
    if spec.pan.is_some() {
        out.push_str(&format!(", target_x = {}, target_z = {}", n(s.target_x), n(s.target_z)));
    }
    out
}

fn state_finite(s: &CameraState) -> bool {
    [s.camera_yaw, s.camera_pitch, s.camera_distance, s.target_x, s.target_z]
        .iter()
        .all(|x| x.is_finite())
}

/// The student's view matrix at `state`: what `camera()` multiplies onto a fresh context.
fn record_camera(imp: &cg_a2::Impl, state: &CameraState) -> Result<MatrixProduct, Outcome> {
    guarded(|| {
        let mut rec = cg_student::gl::Gl::new();
        (imp.camera)(&mut rec, state);
        cg_a2::replay(&rec).model_view().clone()
    })
}

/// The view matrix (world → camera) the student's `camera()` (a2.t2) multiplies, at the stated
/// mouse states: the start, and the states the student's `motion()` (a2.t1) reaches by the
/// drags of [`camera_drags`] (each stated in the title, with the variables it reaches). Each
/// matrix is given numerically and symbolically (each number that is a camera variable named
/// after it), with every variable of the spec explained, its range included.
///
/// A `motion()` not written yet (or panicking, or moving nothing) leaves the start alone.
///
/// # Errors
/// `camera()` not written, panicking, or giving no usable matrix at the start.
pub fn camera(spec: &cg_a2::Spec, imp: &cg_a2::Impl) -> Result<CameraData, Missing> {
    camera_part(spec, imp).0
}

fn camera_part(spec: &cg_a2::Spec, imp: &cg_a2::Impl) -> Part<CameraData> {
    let mut notes = Vec::new();
    let fail = |why: Text| (Err(Missing::new("a2.t2", why)), Vec::new());
    let start_product = match record_camera(imp, &spec.start) {
        Ok(p) => p,
        Err(o) => return (Err(Missing::from_outcome("a2.t2", "camera()", o)), Vec::new()),
    };
    let probe_state = camera_probe(spec);
    let probe = match record_camera(imp, &probe_state) {
        Ok(p) => p,
        Err(o) => return (Err(Missing::from_outcome("a2.t2", "camera()", o)), Vec::new()),
    };
    match (start_product.matrix(), probe.matrix()) {
        (Ok(a), Ok(b)) if a == Mat4::IDENTITY && b == Mat4::IDENTITY => {
            return fail(Text::new(
                "camera() がまだ行列を変えていません（カメラが原点にあるのと同じです）",
                "camera() does not change the matrix yet (as if the camera sat at the origin)",
            ));
        }
        (Ok(_), Ok(_)) => {}
        (Err(e), _) | (_, Err(e)) => {
            return fail(Text::new(
                format!("camera() の積が行列になりません: {}", e.message(Lang::Ja)),
                format!("camera()'s product is not a matrix: {}", e.message(Lang::En)),
            ));
        }
    }

    // The states, through the student's motion().
    let mut states: Vec<(&'static str, Option<Text>, CameraState)> = Vec::new();
    let mut motion_failed = false;
    for step in camera_steps(spec) {
        if step.drags.is_empty() {
            states.push((step.id, step.words, spec.start));
            continue;
        }
        if motion_failed {
            continue;
        }
        let reached = guarded(|| {
            let mut s = spec.start;
            for d in &step.drags {
                (imp.motion)(spec, &mut s, d);
            }
            s
        });
        match reached {
            Ok(s) if state_finite(&s) => states.push((step.id, step.words, s)),
            Ok(s) => notes.push(Missing::new(
                "a2.t1",
                Text::new(
                    format!(
                        "motion() の後の変数が有限の値ではありません: {}",
                        camera_state_text(spec, &s)
                    ),
                    format!(
                        "motion() leaves variables that are not finite: {}",
                        camera_state_text(spec, &s)
                    ),
                ),
            )),
            Err(o) => {
                notes.push(Missing::from_outcome("a2.t1", "motion()", o));
                motion_failed = true;
            }
        }
    }
    if states.len() > 1 && states.iter().all(|(_, _, s)| *s == spec.start) {
        notes.push(Missing::new(
            "a2.t1",
            Text::new(
                "motion() がどの変数も変えていません: ドラッグしても初期状態のままなので、初期状態の行列だけを示します",
                "motion() changes no variable: every drag leaves the start, so only the start's matrix is shown",
            ),
        ));
        states.truncate(1);
    }

    // The student's products at each state; a state whose product is no matrix is left out.
    let mut recorded: Vec<(&'static str, Option<Text>, CameraState, MatrixProduct)> = Vec::new();
    for (id, words, s) in states {
        let product =
            if id == "a2.view.start" { Ok(start_product.clone()) } else { record_camera(imp, &s) };
        match product {
            Ok(p) if p.matrix().is_ok() => recorded.push((id, words, s, p)),
            Ok(_) => notes.push(Missing::new(
                "a2.t2",
                Text::new(
                    format!("camera() の積が {} で行列になりません", camera_state_text(spec, &s)),
                    format!(
                        "camera()'s product is not a matrix at {}",
                        camera_state_text(spec, &s)
                    ),
                ),
            )),
            Err(o) => notes.push(Missing::from_outcome("a2.t2", "camera()", o)),
        }
    }

    let mut products: Vec<MatrixProduct> = vec![probe];
    products.extend(recorded.iter().map(|r| r.3.clone()));
    drop_constant_identities(&mut products);
    let vars = camera_vars(spec, &probe_state);
    let variables: Vec<(String, Text)> = spec
        .variables(Lang::Ja)
        .into_iter()
        .zip(spec.variables(Lang::En))
        .map(|((name, ja), (_, en))| (name, Text::new(ja, en)))
        .collect();
    let matrices = recorded
        .iter()
        .zip(&products[1..])
        .map(|((id, words, s, _), product)| {
            let (symbolic, _) = symbolize(&products[0], product, &vars);
            let state = camera_state_text(spec, s);
            let title = match words {
                None => Text::new(
                    format!("視野変換行列（初期状態: {state}）"),
                    format!("view matrix (at the start: {state})"),
                ),
                Some(w) => Text::new(
                    format!("視野変換行列（初期状態から{}ドラッグした後: {state}）", w.ja),
                    format!("view matrix (after dragging {} from the start: {state})", w.en),
                ),
            };
            NamedMatrix {
                id: (*id).to_owned(),
                title,
                symbolic,
                numeric: numeric(product),
                variables: variables.clone(),
            }
        })
        .collect();
    (Ok(CameraData { matrices }), notes)
}

// ---------------------------------------------------------------------------------------------
// a3: each object's model matrix
// ---------------------------------------------------------------------------------------------

/// The most frames the animation is run for (beyond it, t = 0 is taken at frame 0).
const MAX_FRAMES: u64 = 100_000;
/// The stated times are multiples of this (s): 15 frames.
const TIME_STEP_S: f64 = 0.25;
/// The stated times lie within this many seconds (and within one common period).
const TIME_LIMIT_S: f64 = 12.0;

/// How far apart two poses are: the rotation parts' `‖R₁ − R₂‖_F / √2` plus the distance of the
/// origins.
fn pose_distance(a: &DMat4, b: &DMat4) -> f64 {
    let d = DMat3::from_mat4(*a) - DMat3::from_mat4(*b);
    let rot = (d.x_axis.length_squared() + d.y_axis.length_squared() + d.z_axis.length_squared())
        .sqrt()
        / std::f64::consts::SQRT_2;
    rot + (a.w_axis.truncate() - b.w_axis.truncate()).length()
}

/// The frame of time `t` (s).
fn frame_of(t: f64) -> u64 {
    (t * f64::from(cg_a3::FPS)).round().max(0.0) as u64
}

/// The times (s) at which [`animation`] states each object's model matrix: `0` and two more,
/// chosen from the spec alone so that the motion shows: among the multiples of 0.25 s within the
/// first common period (at most 12 s), the earliest where every object is well away from where
/// it starts (at least 3/4 of the best such time's least distance), then the earliest where every
/// object is also well away from the first. Ascending.
#[must_use]
pub fn animation_times(spec: &cg_a3::Spec) -> Vec<f64> {
    let n = spec.objects.len();
    if n == 0 {
        return vec![0.0];
    }
    let pose = |i: usize, t: f64| cg_a3::expected_model(spec, i, frame_of(t));
    let limit = spec.common_period_s().min(TIME_LIMIT_S);
    let candidates: Vec<f64> =
        (1..).map(|k| f64::from(k) * TIME_STEP_S).take_while(|t| *t < limit - 1e-9).collect();
    let least = |t: f64, from: &[f64]| -> f64 {
        (0..n)
            .map(|i| {
                from.iter()
                    .map(|&u| pose_distance(&pose(i, t), &pose(i, u)))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(f64::INFINITY, f64::min)
    };
    let earliest_good = |from: &[f64]| -> Option<f64> {
        let scores: Vec<(f64, f64)> = candidates
            .iter()
            .filter(|t| !from.iter().any(|u| (*u - **t).abs() < 1e-9))
            .map(|&t| (t, least(t, from)))
            .collect();
        let best = scores.iter().map(|s| s.1).fold(0.0, f64::max);
        scores.iter().find(|s| s.1 >= 0.75 * best).map(|s| s.0)
    };
    let mut times = vec![0.0];
    if let Some(a) = earliest_good(&[0.0]) {
        times.push(a);
        if let Some(b) = earliest_good(&[0.0, a]) {
            times.push(b);
        }
    }
    times.sort_by(f64::total_cmp);
    times
}

/// A spec variable's full name, `theta_2`, and which object it belongs to.
fn var_object(name: &str) -> Option<(&str, usize)> {
    let (kind, n) = name.split_once('_')?;
    let n: usize = n.parse().ok()?;
    Some((kind, n.checked_sub(1)?))
}

/// The explanation of the spec's variable `var` (`theta_2`, `x_3`, `y_3`), printed under the
/// name `shown` (the student's own, or the same): the formula, the range and the period.
fn var_text(spec: &cg_a3::Spec, var: &str, shown: &str) -> Text {
    let unknown = Text::new(
        format!("{shown}: 仕様の運動の変数と値が一致しません"),
        format!("{shown}: its value matches none of the spec's motion variables"),
    );
    let Some((kind, i)) = var_object(var) else { return unknown };
    let Some(object) = spec.objects.get(i) else { return unknown };
    let n = i + 1;
    let p = format_number(object.motion.period_s());
    let u = Text::new(
        format!("u = (t mod {p}) / {p}（t は秒、周期 {p} 秒）"),
        format!("u = (t mod {p}) / {p} (t in seconds, period {p} s)"),
    );
    let turn = |turn: cg_a3::Turn| match turn {
        cg_a3::Turn::Ccw => ("", format!("0 ≤ {shown} < 360"), "反時計回り", "counter-clockwise"),
        cg_a3::Turn::Cw => ("-", format!("-360 < {shown} ≤ 0"), "時計回り", "clockwise"),
    };
    let axis = |a: WorldAxis| a.name();
    match (kind, object.motion) {
        ("theta", Motion::Spin { axis: a, turn: t, .. }) => {
            let (sign, range, ja, en) = turn(t);
            Text::new(
                format!(
                    "{shown}: 物体{n}の自転の角度（{} 軸まわり、{ja}）[度] = {sign}360°·u、{}。{range}",
                    axis(a),
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s spin about the {} axis ({en}), degrees: {sign}360°·u, {}; {range}",
                    axis(a),
                    u.en
                ),
            )
        }
        ("theta", Motion::Orbit { turn: t, .. }) => {
            let (sign, range, ja, en) = turn(t);
            Text::new(
                format!(
                    "{shown}: 物体{n}の公転の角度（Y 軸まわり、上から見て{ja}）[度] = {sign}360°·u、{}。{range}",
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s orbit angle about the Y axis ({en} seen from above), degrees: {sign}360°·u, {}; {range}",
                    u.en
                ),
            )
        }
        ("theta", Motion::Satellite { parent_index, turn: t, .. }) => {
            let (sign, range, ja, en) = turn(t);
            let parent = parent_index + 1;
            Text::new(
                format!(
                    "{shown}: 物体{n}が親（物体{parent}）のまわりを回る角度（親の Y 軸まわり、{ja}）[度] = {sign}360°·u、{}。{range}",
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s angle round its parent, object {parent} (about the parent's Y axis, {en}), degrees: {sign}360°·u, {}; {range}",
                    u.en
                ),
            )
        }
        ("theta", Motion::Swing { axis: a, amplitude_deg, .. }) => {
            let amp = format_number(amplitude_deg);
            Text::new(
                format!(
                    "{shown}: 物体{n}の往復回転の角度（{} 軸まわり）[度] = {amp}·sin(360°·u)、{}。-{amp} ≤ {shown} ≤ {amp}",
                    axis(a),
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s back-and-forth angle about the {} axis, degrees: {amp}·sin(360°·u), {}; -{amp} ≤ {shown} ≤ {amp}",
                    axis(a),
                    u.en
                ),
            )
        }
        ("x" | "z", Motion::Hop { along, span, .. }) => {
            let s = format_number(span);
            let half = format_number(span / 2.0);
            Text::new(
                format!(
                    "{shown}: 物体{n}の {} 方向の位置（往復の中心から）= {s}·(w − 1/2)、w = 2u（u < 1/2）、2 − 2u（u ≥ 1/2）、{}。-{half} ≤ {shown} ≤ {half}",
                    axis(along),
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s position along {} (from the middle of its path) = {s}·(w − 1/2), w = 2u (u < 1/2), 2 − 2u (u ≥ 1/2), {}; -{half} ≤ {shown} ≤ {half}",
                    axis(along),
                    u.en
                ),
            )
        }
        ("y", Motion::Hop { span, height, .. }) => {
            let (s, h) = (format_number(span), format_number(height));
            Text::new(
                format!(
                    "{shown}: 物体{n}の高さ（放物線）= 4·{h}·w·(1 − w) = {h}·(1 − (2·s/{s})²)（s は往復の中心からの位置）、w は上と同じ、{}。0 ≤ {shown} ≤ {h}",
                    u.ja
                ),
                format!(
                    "{shown}: object {n}'s height (a parabola) = 4·{h}·w·(1 − w) = {h}·(1 − (2·s/{s})²) (s: the position from the middle of the path), w as above, {}; 0 ≤ {shown} ≤ {h}",
                    u.en
                ),
            )
        }
        _ => unknown,
    }
}

/// The spec's variables and their values at `frame` (from the spec's own products), and every
/// constant they are printed with.
fn animation_vars(spec: &cg_a3::Spec, frame: u64) -> (Vec<Var>, Vec<f32>) {
    let mut vars: Vec<Var> = Vec::new();
    let mut constants = vec![cg_a3::CAMERA_DISTANCE, cg_a3::CAMERA_PITCH_DEG];
    for i in 0..spec.objects.len() {
        for f in &cg_a3::model_product(spec, i, frame).factors {
            for p in params(f) {
                match &p.symbol {
                    Some(s) if !vars.iter().any(|v| v.name == *s) => {
                        vars.push(Var { name: s.clone(), value: p.value });
                    }
                    Some(_) => {}
                    None => constants.push(p.value),
                }
            }
        }
    }
    (vars, constants)
}

/// A frame where every variable of the spec has a value of its own: away from 0, ±1, every
/// constant and every other variable (also up to sign and whole turns), so each number of a
/// recorded product names at most one variable.
fn animation_probe(spec: &cg_a3::Spec) -> Option<(u64, Vec<Var>)> {
    let apart = |a: f32, b: f32| {
        let (a, b) = (f64::from(a.abs()), f64::from(b.abs()));
        (a - b).abs() > 0.02
            && ((a + b) - 360.0).abs() > 0.02
            && ((a - b).abs() - 360.0).abs() > 0.02
    };
    (7..2_000).find_map(|frame| {
        let (vars, constants) = animation_vars(spec, frame);
        let good = vars.iter().enumerate().all(|(k, v)| {
            v.value.is_finite()
                && v.value.abs() > 0.05
                && apart(v.value, 1.0)
                && apart(v.value, 0.0)
                && constants.iter().all(|&c| apart(v.value, c))
                && vars[..k].iter().all(|w| apart(v.value, w.value))
        });
        good.then_some((frame, vars))
    })
}

/// Whether a draw's name means `object`: the same ignoring case, spaces, `_` and `-`; `物体2`
/// also means `object 2` (as a3's checks read it).
fn name_matches(drawn: &str, object: &str) -> bool {
    let norm = |s: &str| -> String {
        s.chars()
            .filter(|c| !c.is_whitespace() && *c != '_' && *c != '-')
            .flat_map(char::to_lowercase)
            .collect::<String>()
            .replace("物体", "object")
    };
    norm(drawn) == norm(object)
}

/// A draw's model transform (model → world): its model-view product with the common camera
/// `T(0, 0, -15) · Rx(30°)` taken off the front — the shortest leading factors that multiply to
/// it — or, when no leading factors do, `V⁻¹ ·` the whole product.
fn model_of(draw: &Draw) -> MatrixProduct {
    let camera = cg_a3::camera_product();
    let Ok(view) = camera.matrix() else { return draw.model_view.clone() };
    let factors = &draw.model_view.factors;
    for k in 1..=factors.len() {
        let head = MatrixProduct { factors: factors[..k].to_vec() };
        if head.matrix().is_ok_and(|m| matrices_close(&m, &view)) {
            return MatrixProduct { factors: factors[k..].to_vec() };
        }
    }
    MatrixProduct::identity().then(Factor::named("V⁻¹", view.inverse())).concat(&draw.model_view)
}

/// `t = 0.75` as the IDs and titles print it.
fn seconds(t: f64) -> String {
    format_number(t as f32)
}

/// `object 1` → `object1`: the ASCII letters, digits and `_` of a name (`object<n>` when none).
fn ascii_id(name: &str, n: usize) -> String {
    let id: String = name.chars().filter(|c| c.is_ascii_alphanumeric() || *c == '_').collect();
    if id.is_empty() { format!("object{n}") } else { id }
}

/// The periods and their ratios, as the report states them.
fn periods_text(spec: &cg_a3::Spec) -> Text {
    let each = |ja: bool| -> String {
        let parts: Vec<String> = spec
            .objects
            .iter()
            .enumerate()
            .map(|(i, o)| {
                let p = format_number(o.motion.period_s());
                if ja {
                    format!("物体{} {p} 秒", i + 1)
                } else {
                    format!("object {} {p} s", i + 1)
                }
            })
            .collect();
        parts.join(if ja { "、" } else { ", " })
    };
    let names = |ja: bool| -> String {
        let names: Vec<String> = (1..=spec.objects.len())
            .map(|n| if ja { format!("物体{n}") } else { format!("object {n}") })
            .collect();
        names.join(" : ")
    };
    let ratios: Vec<String> = spec.period_ratios().iter().map(u64::to_string).collect();
    let ratios = ratios.join(" : ");
    let unit = format_number(spec.unit_s);
    let common = seconds(spec.common_period_s());
    Text::new(
        format!(
            "周期: {}。周期の比 {} = {ratios}（単位 {unit} 秒）。全体は {common} 秒ごとに同じ動きを繰り返す。",
            each(true),
            names(true)
        ),
        format!(
            "Periods: {}. Ratio of the periods {} = {ratios} (unit {unit} s); the whole animation repeats every {common} s.",
            each(false),
            names(false)
        ),
    )
}

/// Each animated object's model matrix (model → world: the model-view matrix of its draw with
/// the common camera taken off) at the times of [`animation_times`], from the student's
/// `idle()` (a3.t1) and `display()` (a3.t2): `idle()` is called `60·t` times from
/// `State::new()` and `display()` recorded. `t = 0` is taken one common period later (every
/// motion back at its start), since before the first `idle()` the parameters are not computed
/// yet. Symbolically, each number that is one of the spec's motion variables (`theta_n`, and
/// `x_n` or `z_n` and `y_n` for a hop, as a3's own products name them) is named after it, and
/// each symbol is explained (formula, range, period); `periods` states the periods and their
/// ratios.
///
/// An object not drawn exactly once is left out (the others still derive).
///
/// # Errors
/// `idle()` or `display()` panicking, or `display()` drawing none of the objects.
pub fn animation(spec: &cg_a3::Spec, imp: &cg_a3::Impl) -> Result<AnimationData, Missing> {
    animation_part(spec, imp).0
}

fn animation_part(spec: &cg_a3::Spec, imp: &cg_a3::Impl) -> Part<AnimationData> {
    let mut notes = Vec::new();
    let times = animation_times(spec);
    let cycle = frame_of(spec.common_period_s());
    let start_frame = if cycle <= MAX_FRAMES { cycle } else { 0 };
    let time_frames: Vec<u64> =
        times.iter().map(|&t| if t == 0.0 { start_frame } else { frame_of(t) }).collect();
    let probe = animation_probe(spec);
    let mut frames: Vec<u64> = time_frames.clone();
    frames.extend(probe.as_ref().map(|p| p.0));
    frames.sort_unstable();
    frames.dedup();

    // Run the student's idle() and record display() at each frame.
    let mut recorded: Vec<(u64, Gl)> = Vec::new();
    let mut state = cg_a3::State::new();
    let mut done = 0;
    for &frame in &frames {
        let gap = frame - done;
        if let Err(o) = guarded(|| {
            for _ in 0..gap {
                (imp.idle)(spec, &mut state);
            }
        }) {
            return (Err(Missing::from_outcome("a3.t1", "idle()", o)), notes);
        }
        done = frame;
        match guarded(|| {
            let mut rec = cg_student::gl::Gl::new();
            (imp.display)(spec, &state, &mut rec);
            cg_a3::replay(&rec)
        }) {
            Ok(gl) => recorded.push((frame, gl)),
            Err(o) => return (Err(Missing::from_outcome("a3.t2", "display()", o)), notes),
        }
    }
    let at = |frame: u64| recorded.iter().find(|r| r.0 == frame).map(|r| &r.1);

    let mut objects = Vec::new();
    for (i, object) in spec.objects.iter().enumerate() {
        let n = i + 1;
        // The object's one draw in each recorded frame.
        let draw_in = |gl: &Gl| -> Result<MatrixProduct, usize> {
            let found: Vec<&Draw> =
                gl.draws().iter().filter(|d| name_matches(&d.name, &object.name)).collect();
            if found.len() == 1 { Ok(model_of(found[0])) } else { Err(found.len()) }
        };
        let mut products = Vec::new();
        let mut failed = None;
        for &frame in &time_frames {
            match at(frame).map(draw_in) {
                Some(Ok(p)) if p.matrix().is_ok() => products.push(p),
                Some(Ok(_)) => {
                    failed = Some(Text::new(
                        format!(
                            "物体{n} \"{}\" のモデルビュー行列が有限の値になりません",
                            object.name
                        ),
                        format!("\"{}\"'s model-view matrix is not finite", object.name),
                    ))
                }
                Some(Err(0)) | None => {
                    failed = Some(Text::new(
                        format!(
                            "物体{n} \"{}\" が描かれていません（名前が違うか、まだ描いていない）",
                            object.name
                        ),
                        format!(
                            "\"{}\" is not drawn (a different name, or not drawn yet)",
                            object.name
                        ),
                    ))
                }
                Some(Err(k)) => {
                    failed = Some(Text::new(
                        format!("物体{n} \"{}\" が 1 フレームに {k} 回描かれています", object.name),
                        format!("\"{}\" is drawn {k} times in one frame", object.name),
                    ))
                }
            }
            if failed.is_some() {
                break;
            }
        }
        if let Some(why) = failed {
            notes.push(Missing::new("a3.t2", why));
            continue;
        }
        // The probe's product names the variables.
        let probe_product = probe.as_ref().and_then(|(f, vars)| {
            at(*f).and_then(|gl| draw_in(gl).ok()).map(|p| (p, vars.clone()))
        });
        let mut names: Names = Vec::new();
        let symbolic: Vec<MatrixProduct> = products
            .iter()
            .map(|p| {
                let (s, found) = match &probe_product {
                    Some((probe, vars)) => symbolize(probe, p, vars),
                    None => symbolize(p, p, &[]),
                };
                for (symbol, var) in found {
                    if !names.iter().any(|(s, _)| *s == symbol) {
                        names.push((symbol, var));
                    }
                }
                s
            })
            .collect();
        let variables: Vec<(String, Text)> = names
            .iter()
            .map(|(symbol, var)| {
                let text = match var {
                    Some(v) => var_text(spec, v, symbol),
                    None => var_text(spec, "", symbol),
                };
                (symbol.clone(), text)
            })
            .collect();
        let id = ascii_id(&object.name, n);
        let matrices: Vec<NamedMatrix> = times
            .iter()
            .zip(products.iter().zip(symbolic))
            .map(|(&t, (p, symbolic))| NamedMatrix {
                id: format!("a3.{id}.t{}", seconds(t)),
                title: Text::new(
                    format!(
                        "物体{n} \"{}\" のモデル変換行列（モデル座標系 → ワールド座標系、t = {} 秒）",
                        object.name,
                        seconds(t)
                    ),
                    format!(
                        "model matrix of \"{}\" (model → world, t = {} s)",
                        object.name,
                        seconds(t)
                    ),
                ),
                symbolic,
                numeric: numeric(p),
                variables: variables.clone(),
            })
            .collect();
        objects.push((object.name.clone(), matrices));
    }
    if objects.is_empty() {
        let drew_nothing = recorded.iter().all(|(_, gl)| gl.draws().is_empty());
        if drew_nothing || notes.is_empty() {
            let why = Text::new(
                "display() がまだどの物体も描いていません（物体は gl.draw(&object.name, &object.shape.mesh()) で描きます）",
                "display() draws none of the objects yet (draw each with gl.draw(&object.name, &object.shape.mesh()))",
            );
            return (Err(Missing::new("a3.t2", why)), Vec::new());
        }
        let first = notes.remove(0);
        return (Err(first), notes);
    }
    let still = objects.iter().all(|(_, ms)| {
        ms.windows(2).all(|w| {
            matches!((w[0].numeric.matrix(), w[1].numeric.matrix()), (Ok(a), Ok(b)) if matrices_close(&a, &b))
        })
    });
    if still && times.len() > 1 {
        notes.push(Missing::new(
            "a3.t1",
            Text::new(
                "どの物体も動いていません: idle() で state.frame に 1 を足し、運動の変数を求めてください",
                "no object moves: idle() adds 1 to state.frame and computes the motion parameters",
            ),
        ));
    }
    (Ok(AnimationData { objects, periods: periods_text(spec) }), notes)
}

// ---------------------------------------------------------------------------------------------
// a4: the texture-coordinate table
// ---------------------------------------------------------------------------------------------

/// Two texture coordinates of one vertex closer than this (each component) are the same one
/// (a4's own tolerance: an honest f32 formula rounds far below it, a visible mistake far above).
const TEX_SAME: f32 = 1e-5;

/// Every ground vertex `(i, j)`, `i, j = 0…10`, j-major, with the distinct coordinates the
/// squares that use it give it, in the squares' drawing order (`j` outer, `i` inner).
fn texture_rows(coords: &cg_a4::Coordinates) -> Vec<TexRow> {
    let n = cg_a4::SQUARES;
    let mut rows = Vec::with_capacity(((n + 1) * (n + 1)) as usize);
    for j in 0..=n {
        for i in 0..=n {
            // (square j, square i, corner) for each square with a corner at (i, j).
            let mut uses: Vec<(u32, u32, usize)> = cg_a4::CORNER_STEPS
                .iter()
                .enumerate()
                .filter_map(|(c, &(di, dj))| {
                    let (si, sj) = (i.checked_sub(di)?, j.checked_sub(dj)?);
                    (si < n && sj < n).then_some((sj, si, c))
                })
                .collect();
            uses.sort_unstable();
            let mut tex: Vec<Vec2> = Vec::new();
            for (sj, si, c) in uses {
                let uv = coords[si as usize][sj as usize][c];
                if !tex.iter().any(|t| (*t - uv).abs().max_element() <= TEX_SAME) {
                    tex.push(uv);
                }
            }
            let position = Vec3::new(i as f32 - 5.0, 0.0, j as f32 - 5.0);
            rows.push(TexRow { i, j, position, tex });
        }
    }
    rows
}

/// `a + b·x + …` as text: `0.25 + 0.025·i`, `0.625 − 0.025·j`, `0.025·i` (no constant 0),
/// `0.5` (no term with a zero factor).
fn linear_text(a: f32, terms: &[(f32, &str)]) -> String {
    let mut out = String::new();
    if a != 0.0 || terms.iter().all(|t| t.0 == 0.0) {
        out = format_number(a);
    }
    for &(b, x) in terms {
        if b == 0.0 {
            continue;
        }
        let magnitude = format_number(b.abs());
        out = match (out.is_empty(), b < 0.0) {
            (true, false) => format!("{magnitude}·{x}"),
            (true, true) => format!("−{magnitude}·{x}"),
            (false, false) => format!("{out} + {magnitude}·{x}"),
            (false, true) => format!("{out} − {magnitude}·{x}"),
        };
    }
    out
}

/// The formula of the texture coordinates in `i` and `j` and their range, from the spec alone:
/// the region (worked from its pixels), the orientation (where each of its corners lands) and
/// the repeat.
fn texture_formula(spec: &cg_a4::Spec) -> Text {
    use cg_a4::GroundCorner;
    let size = cg_a4::IMAGE_PIXELS as f32;
    let [x0, y0, x1, y1] = spec.region.pixels();
    let (s_min, s_max) = (x0 as f32 / size, x1 as f32 / size);
    let (t_min, t_max) = (1.0 - y1 as f32 / size, 1.0 - y0 as f32 / size);
    // Where in the region (0…1 to its right, 0…1 to its top) each block corner (p, q) shows.
    let xy = |g: GroundCorner| {
        let (x, y) = spec.corner_at(g).xy();
        (x as f32, y as f32)
    };
    let (c00, c10, c01) =
        (xy(GroundCorner::FarLeft), xy(GroundCorner::FarRight), xy(GroundCorner::NearLeft));
    // x = c00.x + (c10.x − c00.x)·p + (c01.x − c00.x)·q, and the same for y.
    let (sw, th) = (s_max - s_min, t_max - t_min);
    let s0 = s_min + sw * c00.0;
    let (sp, sq) = (sw * (c10.0 - c00.0), sw * (c01.0 - c00.0));
    let t0 = t_min + th * c00.1;
    let (tp, tq) = (th * (c10.1 - c00.1), th * (c01.1 - c00.1));
    let repeat = spec.repeat.clamp(1, cg_a4::SQUARES);
    let k = cg_a4::SQUARES / repeat;
    let kf = k as f32;
    let (a, b) = if repeat == 1 {
        ("i".to_owned(), "j".to_owned())
    } else {
        (format!("(i mod {k})"), format!("(j mod {k})"))
    };
    let s_pq = linear_text(s0, &[(sp, "p"), (sq, "q")]);
    let t_pq = linear_text(t0, &[(tp, "p"), (tq, "q")]);
    let s_ij = linear_text(s0, &[(sp / kf, &a), (sq / kf, &b)]);
    let t_ij = linear_text(t0, &[(tp / kf, &a), (tq / kf, &b)]);
    let n = format_number;
    let region = spec.region.name();
    let turn = match spec.rotation_deg % 360 {
        90 => ("反時計回りに 90° 回す", "turned 90° counter-clockwise"),
        180 => ("180° 回す", "turned 180°"),
        270 => ("時計回りに 90° 回す", "turned 90° clockwise"),
        _ => ("回さない", "not turned"),
    };
    let (mirror_ja, mirror_en) =
        if spec.mirrored { ("左右反転してから", "mirrored, then ") } else { ("", "") };
    let (pq_ja, pq_en, repeat_ja, repeat_en) = if repeat == 1 {
        (
            format!("p = i / {k}、q = j / {k}（地面の上の位置、0〜1）"),
            format!("p = i / {k}, q = j / {k} (where on the ground, 0…1)"),
            "繰り返しなし".to_owned(),
            "no repeat".to_owned(),
        )
    } else {
        (
            format!(
                "p = (i mod {k}) / {k}、q = (j mod {k}) / {k}（{k} × {k} マスのまとまりの中の位置、0〜1。まとまりの右端・手前の端の頂点は隣のまとまりにも属し、そちらの四角形では p = 1、q = 1 を使う）"
            ),
            format!(
                "p = (i mod {k}) / {k}, q = (j mod {k}) / {k} (where in the block of {k} × {k} squares, 0…1; a vertex on a block's right or near edge belongs to the next block too, and the squares of this block use p = 1 or q = 1 there)"
            ),
            format!("{repeat} × {repeat} 回繰り返す"),
            format!("repeated {repeat} × {repeat} times"),
        )
    };
    Text::new(
        format!(
            "頂点 (i, j)（位置 (i − 5, 0, j − 5)）のテクスチャ座標: s = {s_pq}、t = {t_pq}、{pq_ja}。i と j で書くと s = {s_ij}、t = {t_ij}。範囲: {} ≤ s ≤ {}、{} ≤ t ≤ {}（マス {region}、画素 x = {x0}〜{x1}、y = {y0}〜{y1}、{mirror_ja}{}、{repeat_ja}）",
            n(s_min),
            n(s_max),
            n(t_min),
            n(t_max),
            turn.0
        ),
        format!(
            "Texture coordinates of vertex (i, j) (at (i − 5, 0, j − 5)): s = {s_pq}, t = {t_pq}, {pq_en}. In i and j: s = {s_ij}, t = {t_ij}. Range: {} ≤ s ≤ {}, {} ≤ t ≤ {} (cells {region}, pixels x = {x0}…{x1}, y = {y0}…{y1}, {mirror_en}{}, {repeat_en})",
            n(s_min),
            n(s_max),
            n(t_min),
            n(t_max),
            turn.1
        ),
    )
}

/// The texture mapping from the student's a4 functions: every ground vertex `(i, j)` (j-major)
/// with its position and the distinct texture coordinates the squares that use it give it
/// (a4.t2, square by square in the order of `cg_a4::CORNER_STEPS`); the region as the student's
/// `tex_range()` (a4.t1) gives it; the formula in `i` and `j` and the range in words, from the
/// spec; and the prepared image.
///
/// # Errors
/// a4.t1 or a4.t2 not written, panicking or giving a coordinate that is not finite.
pub fn texture(spec: &cg_a4::Spec, imp: &cg_a4::Impl) -> Result<TextureData, Missing> {
    texture_part(spec, imp).0
}

fn texture_part(spec: &cg_a4::Spec, imp: &cg_a4::Impl) -> Part<TextureData> {
    let fail = |task: &str, why: Text| (Err(Missing::new(task, why)), Vec::new());
    let range = match guarded(|| (imp.tex_range)(spec)) {
        Ok(r) => r,
        Err(o) => return (Err(Missing::from_outcome("a4.t1", "tex_range()", o)), Vec::new()),
    };
    if ![range.s_min, range.s_max, range.t_min, range.t_max].iter().all(|x| x.is_finite()) {
        return fail(
            "a4.t1",
            Text::new(
                "tex_range() の範囲が有限の値ではありません",
                "tex_range() gives a range that is not finite",
            ),
        );
    }
    let coords = match guarded(|| cg_a4::coordinates(spec, imp)) {
        Ok(c) => c,
        Err(o) => return (Err(Missing::from_outcome("a4.t2", "tex_coords()", o)), Vec::new()),
    };
    for (i, column) in coords.iter().enumerate() {
        for (j, square) in column.iter().enumerate() {
            if !square.iter().all(|uv| uv.is_finite()) {
                return fail(
                    "a4.t2",
                    Text::new(
                        format!("四角形 ({i}, {j}) のテクスチャ座標が有限の値ではありません"),
                        format!("square ({i}, {j})'s texture coordinates are not finite"),
                    ),
                );
            }
        }
    }
    // a4.t3 is reported on its own: without it the coordinates and the figure still derive.
    let mut missing = Vec::new();
    let sampler = guarded(|| (imp.sampler)())
        .map_err(|o| missing.push(Missing::from_outcome("a4.t3", "sampler()", o)))
        .ok();
    let image = cg_a4::prepared_image();
    let square = coords[0][0];
    let spread = |axis: fn(Vec2) -> f32| {
        let values = square.map(axis);
        values.iter().copied().fold(f32::MIN, f32::max)
            - values.iter().copied().fold(f32::MAX, f32::min)
    };
    let texels_per_square =
        Vec2::new(spread(|v| v.x) * image.width as f32, spread(|v| v.y) * image.height as f32);
    (
        Ok(TextureData {
            rows: texture_rows(&coords),
            formula: texture_formula(spec),
            region: (Vec2::new(range.s_min, range.t_min), Vec2::new(range.s_max, range.t_max)),
            image,
            sampler: sampler.map(cg_a4::core_sampler),
            texels_per_square,
        }),
        missing,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    use cg_core::glam::DVec3;
    use cg_harness::{StudentNumber, TableVersion};

    // --- the pristine stubs --------------------------------------------------------------

    #[test]
    fn the_stubs_leave_every_part_missing_with_its_task_and_nothing_panics() {
        for number in ["12345678", "20260002", "24000007"] {
            let student: StudentNumber = number.parse().unwrap();
            let assignment = Assignment::for_student(&student, TableVersion::V1);
            let (derived, missing) = derive(&assignment, &Impls::exercises());
            assert_eq!(derived.student.as_deref(), Some(number));
            assert!(derived.polygon.is_none() && derived.camera.is_none());
            assert!(derived.animation.is_none() && derived.texture.is_none());
            let tasks: Vec<&str> = missing.iter().map(|m| m.task.as_str()).collect();
            // Vertices are todo!(), camera() does nothing, display() draws nothing,
            // tex_range() is todo!().
            assert_eq!(tasks, ["a1.t1", "a2.t2", "a3.t2", "a4.t1"], "{missing:?}");
            for m in &missing {
                assert!(m.message(Lang::En).starts_with(&format!("{}: ", m.task)));
                assert!(!m.why.ja.is_empty() && !m.why.en.is_empty(), "{m:?}");
            }
            assert!(missing[0].why.en.contains("not written yet"), "{:?}", missing[0]);
            assert!(missing[0].why.ja.contains("まだ書かれていません"), "{:?}", missing[0]);
        }
    }

    // --- a1 ------------------------------------------------------------------------------

    /// A square pyramid (radius 1, height 1.5), bottom up, ring counter-clockwise from above.
    fn pyramid_spec() -> cg_a1::Spec {
        cg_a1::Spec {
            shape: cg_a1::Shape::Pyramid { sides: 4, radius: 1.0, height: 1.5 },
            numbering: cg_a1::Numbering { order: cg_a1::Order::BottomUp, ring: cg_a1::Turn::Ccw },
            placement: cg_a1::Placement { x: 1.0, y: 0.0, z: -1.5, angle_deg: 30.0 },
        }
    }

    fn pyramid_vertices(_: &cg_a1::Spec) -> Vec<Vec3> {
        vec![
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, -1.0),
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
            Vec3::new(0.0, 1.5, 0.0),
        ]
    }

    fn pyramid_faces(_: &cg_a1::Spec) -> Vec<[u32; 3]> {
        vec![[0, 2, 1], [0, 3, 2], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
    }

    /// The student's own normals: all +Y (wrong, but theirs: the report shows them as given).
    fn up_normals(_: &cg_a1::Spec) -> Vec<Vec3> {
        vec![Vec3::Y; 6]
    }

    fn placement(spec: &cg_a1::Spec) -> cg_student::product::MatrixProduct {
        use cg_student::product::{Factor, MatrixProduct};
        let p = spec.placement;
        MatrixProduct::identity()
            .then(Factor::translate(Vec3::new(p.x, p.y, p.z)))
            .then(Factor::rotate_y_deg(p.angle_deg))
    }

    #[allow(clippy::todo)]
    fn normals_todo(_: &cg_a1::Spec) -> Vec<Vec3> {
        todo!("a1.t3: compute each face's unit normal")
    }

    #[allow(clippy::panic)]
    fn transform_panics(_: &cg_a1::Spec) -> cg_student::product::MatrixProduct {
        panic!("index out of bounds")
    }

    #[test]
    fn a_hand_written_pyramid_derives_the_f64_oracles_normals() {
        let imp = cg_a1::Impl {
            vertices: pyramid_vertices,
            faces: pyramid_faces,
            face_normals: up_normals,
            model_transform: placement,
        };
        let spec = pyramid_spec();
        let p = polygon(&spec, &imp).unwrap();
        assert_eq!(p.name, Text::new("四角すい", "square pyramid"));
        assert_eq!(p.vertices, pyramid_vertices(&spec));
        assert_eq!(p.faces, pyramid_faces(&spec));
        assert_eq!(p.student_normals, Some(vec![Vec3::Y; 6]));
        assert_eq!(p.transform, Some(placement(&spec).into()));
        // The oracle: (Vb − Va) × (Vc − Va) / |…| in f64 from the numbers written above.
        let v = [
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(0.0, 0.0, -1.0),
            DVec3::new(-1.0, 0.0, 0.0),
            DVec3::new(0.0, 0.0, 1.0),
            DVec3::new(0.0, 1.5, 0.0),
        ];
        for (k, f) in pyramid_faces(&spec).iter().enumerate() {
            let (a, b, c) = (v[f[0] as usize], v[f[1] as usize], v[f[2] as usize]);
            let n = (b - a).cross(c - a);
            let n = n / n.length();
            let got = p.derived_normals[k].unwrap().as_dvec3();
            assert!((got - n).length() < 1e-6, "F{k}: {got} vs {n}");
        }
        // By hand: the bottom faces down; the side over V0–V1 faces (+x, −z) and up:
        // (V1 − V0) × (V4 − V0) = (−1, 0, −1) × (−1, 1.5, 0) = (1.5, 1, −1.5).
        assert!(p.derived_normals[0].unwrap().abs_diff_eq(Vec3::NEG_Y, 1e-6));
        let side = Vec3::new(1.5, 1.0, -1.5) / (1.5f32 * 1.5 * 2.0 + 1.0).sqrt();
        assert!(p.derived_normals[2].unwrap().abs_diff_eq(side, 1e-6));
    }

    #[test]
    fn a_missing_normal_or_transform_keeps_the_tables() {
        let imp = cg_a1::Impl {
            vertices: pyramid_vertices,
            faces: pyramid_faces,
            face_normals: normals_todo,
            model_transform: transform_panics,
        };
        let (result, notes) = polygon_part(&pyramid_spec(), &imp);
        let p = result.unwrap();
        assert_eq!(p.vertices.len(), 5);
        assert_eq!(p.faces.len(), 6);
        assert!(p.derived_normals.iter().all(Option::is_some));
        assert_eq!((p.student_normals, p.transform), (None, None));
        let tasks: Vec<&str> = notes.iter().map(|m| m.task.as_str()).collect();
        assert_eq!(tasks, ["a1.t3", "a1.t4"]);
        assert!(notes[0].why.en.contains("not written yet"), "{:?}", notes[0]);
        assert!(notes[1].why.en.contains("panicked: index out of bounds"), "{:?}", notes[1]);
    }

    fn one_normal(_: &cg_a1::Spec) -> Vec<Vec3> {
        vec![Vec3::Y]
    }

    fn nan_vertices(_: &cg_a1::Spec) -> Vec<Vec3> {
        vec![Vec3::ZERO, Vec3::new(f32::NAN, 0.0, 0.0), Vec3::X]
    }

    #[test]
    fn unusable_data_is_named() {
        let imp = cg_a1::Impl {
            vertices: pyramid_vertices,
            faces: pyramid_faces,
            face_normals: one_normal,
            model_transform: placement,
        };
        let (result, notes) = polygon_part(&pyramid_spec(), &imp);
        assert_eq!(result.unwrap().student_normals, None);
        assert_eq!(notes[0].task, "a1.t3");
        assert!(notes[0].why.en.contains("1 normals for 6 faces"), "{:?}", notes[0]);
        let imp = cg_a1::Impl { vertices: nan_vertices, ..imp };
        let m = polygon(&pyramid_spec(), &imp).unwrap_err();
        assert_eq!(m.task, "a1.t1");
        assert!(m.why.en.contains("V1"), "{m:?}");
    }

    // --- naming the variables -------------------------------------------------------------

    #[test]
    fn symbols_name_variables_keep_constants_and_evaluate_to_the_numbers() {
        let vars = [
            Var { name: "camera_pitch".into(), value: -23.0 },
            Var { name: "camera_distance".into(), value: 13.5 },
        ];
        let record = |pitch: f32, distance: f32| {
            let mut gl = Gl::new();
            gl.translate(0.0, 0.0, -distance);
            gl.rotate(-pitch, 1.0, 0.0, 0.0);
            gl.rotate(pitch.to_radians(), 0.0, 1.0, 0.0); // radians: matches no variable
            gl.translate(0.0, 1.0, 0.0);
            gl.model_view().clone()
        };
        let probe = record(-23.0, 13.5);
        let at = record(-30.0, 15.0);
        let (s, names) = symbolize(&probe, &at, &vars);
        assert_eq!(
            s.symbolic(),
            "T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-0.5236°) · T(0, 1, 0)"
        );
        assert_eq!(s.matrix().unwrap(), at.matrix().unwrap());
        assert_eq!(
            names,
            vec![
                ("camera_distance".to_owned(), Some("camera_distance".to_owned())),
                ("camera_pitch".to_owned(), Some("camera_pitch".to_owned()))
            ]
        );
        // An angle a whole turn off is still the variable.
        let turned = Param::num(337.0);
        assert_eq!(match_var(turned.value, &vars, true).as_deref(), Some("camera_pitch"));
        assert_eq!(match_var(turned.value, &vars, false), None);
        // Not the same calls: the product stays as recorded.
        let other = MatrixProduct::identity().then(Factor::rotate_x_deg(30.0));
        assert_eq!(symbolize(&probe, &other, &vars).0, other);
    }

    // --- a4 ------------------------------------------------------------------------------

    fn range_quarter(_: &cg_a4::Spec) -> cg_a4::TexRange {
        cg_a4::TexRange { s_min: 0.25, s_max: 0.5, t_min: 0.375, t_max: 0.625 }
    }

    /// Each vertex's coordinate is its own grid numbers: one coordinate per vertex.
    fn by_vertex(_: &cg_a4::Spec, i: u32, j: u32) -> [Vec2; 4] {
        cg_a4::CORNER_STEPS.map(|(di, dj)| Vec2::new((i + di) as f32, (j + dj) as f32))
    }

    /// Each square's corners get (10·i + j, corner): every square gives its own.
    fn by_square(_: &cg_a4::Spec, i: u32, j: u32) -> [Vec2; 4] {
        [0.0, 1.0, 2.0, 3.0].map(|c| Vec2::new((10 * i + j) as f32, c))
    }

    fn sampler() -> cg_a4::Sampler {
        cg_a4::Sampler::default()
    }

    fn a4_spec() -> cg_a4::Spec {
        // C4–D5, upright, no repeat.
        let region = cg_a4::Region { column: 2, row: 3, columns: 2, rows: 2 };
        cg_a4::Spec { region, rotation_deg: 0, mirrored: false, repeat: 1 }
    }

    #[test]
    fn texture_rows_list_every_vertex_with_the_coordinates_of_its_squares() {
        let spec = a4_spec();
        let imp = cg_a4::Impl { tex_range: range_quarter, tex_coords: by_vertex, sampler };
        let t = texture(&spec, &imp).unwrap();
        assert_eq!(t.rows.len(), 121);
        assert_eq!(t.region, (Vec2::new(0.25, 0.375), Vec2::new(0.5, 0.625)));
        for (k, row) in t.rows.iter().enumerate() {
            // j-major: (0, 0), (1, 0), …, (10, 0), (0, 1), …
            assert_eq!((row.i, row.j), (k as u32 % 11, k as u32 / 11));
            assert_eq!(row.position, Vec3::new(row.i as f32 - 5.0, 0.0, row.j as f32 - 5.0));
            assert_eq!(row.tex, vec![Vec2::new(row.i as f32, row.j as f32)], "{row:?}");
        }
        assert_eq!(t.image.width, cg_a4::IMAGE_PIXELS);

        let imp = cg_a4::Impl { tex_coords: by_square, ..imp };
        let t = texture(&spec, &imp).unwrap();
        let row = |i: u32, j: u32| &t.rows[(j * 11 + i) as usize];
        // Vertex (5, 5) is corner 2 of square (4, 4), corner 1 of (5, 4), corner 3 of (4, 5)
        // and corner 0 of (5, 5) — in drawing order (j outer, i inner).
        assert_eq!(
            row(5, 5).tex,
            vec![
                Vec2::new(44.0, 2.0),
                Vec2::new(54.0, 1.0),
                Vec2::new(45.0, 3.0),
                Vec2::new(55.0, 0.0)
            ]
        );
        assert_eq!(row(0, 0).tex, vec![Vec2::new(0.0, 0.0)]);
        assert_eq!(row(10, 10).tex, vec![Vec2::new(99.0, 2.0)]);
        // An edge vertex: (10, 3) is corner 2 of square (9, 2) and corner 3 of (9, 3).
        assert_eq!(row(10, 3).tex, vec![Vec2::new(92.0, 2.0), Vec2::new(93.0, 3.0)]);
    }

    #[test]
    fn the_formula_reads_the_spec() {
        // Upright C4–D5 (s 0.25…0.5, t 0.375…0.625) over the 10 squares: s grows with i, t
        // shrinks with j (the image's top is away from the camera).
        let f = texture_formula(&a4_spec());
        assert!(f.en.contains("s = 0.25 + 0.025·i, t = 0.625 − 0.025·j"), "{}", f.en);
        assert!(f.en.contains("0.25 ≤ s ≤ 0.5, 0.375 ≤ t ≤ 0.625"), "{}", f.en);
        assert!(f.ja.contains("s = 0.25 + 0.025·i、t = 0.625 − 0.025·j"), "{}", f.ja);
        // A quarter turn counter-clockwise, 2 × 2 blocks of 5: the region's top points to −x,
        // so s follows j backwards... worked by hand: corner (p, q) shows region point
        // (1 − q, 1 − p): s = 0.5 − 0.25·q, t = 0.625 − 0.25·p.
        let spec = cg_a4::Spec { rotation_deg: 90, repeat: 2, ..a4_spec() };
        let f = texture_formula(&spec);
        assert!(f.en.contains("s = 0.5 − 0.25·q, t = 0.625 − 0.25·p"), "{}", f.en);
        assert!(f.en.contains("s = 0.5 − 0.05·(j mod 5), t = 0.625 − 0.05·(i mod 5)"), "{}", f.en);
        // G7–H8 (s 0.75…1, t 0…0.25) turned 90° clockwise: the region's top points to +x (t
        // grows with i), its right towards the camera (s grows with j); no constant 0.
        let region = cg_a4::Region { column: 6, row: 6, columns: 2, rows: 2 };
        let spec = cg_a4::Spec { region, rotation_deg: 270, ..a4_spec() };
        let f = texture_formula(&spec);
        assert!(f.en.contains("s = 0.75 + 0.025·j, t = 0.025·i"), "{}", f.en);
        assert_eq!(linear_text(0.0, &[(-0.5, "p"), (0.0, "q")]), "−0.5·p");
        assert_eq!(linear_text(0.0, &[(0.0, "p")]), "0");
    }

    #[allow(clippy::todo)]
    fn coords_todo(_: &cg_a4::Spec, _: u32, _: u32) -> [Vec2; 4] {
        todo!("a4.t2: the texture coordinates")
    }

    #[allow(clippy::todo)]
    fn sampler_todo() -> cg_a4::Sampler {
        todo!("a4.t3: the sampler")
    }

    #[test]
    fn the_sampler_and_the_pixels_per_square_derive_and_a_missing_sampler_is_named() {
        // by_vertex gives square (0, 0) the corners (0, 0)…(1, 1): one unit of s and t, times the
        // prepared image's size.
        let imp = cg_a4::Impl { tex_range: range_quarter, tex_coords: by_vertex, sampler };
        let (t, missing) = texture_part(&a4_spec(), &imp);
        let t = t.unwrap();
        assert!(missing.is_empty(), "{missing:?}");
        assert_eq!(t.sampler, Some(cg_core::texture::Sampler::default()));
        let image = cg_a4::prepared_image();
        assert_eq!(t.texels_per_square, Vec2::new(image.width as f32, image.height as f32));
        // Without a4.t3 the coordinates still derive; the sampler is named as missing.
        let imp = cg_a4::Impl { sampler: sampler_todo, ..imp };
        let (t, missing) = texture_part(&a4_spec(), &imp);
        assert_eq!(t.unwrap().sampler, None);
        assert_eq!(missing.iter().map(|m| m.task.as_str()).collect::<Vec<_>>(), ["a4.t3"]);
        assert!(missing[0].message(Lang::En).contains("sampler()"), "{:?}", missing[0]);
    }

    #[test]
    fn a_stub_coordinate_function_is_missing() {
        let imp = cg_a4::Impl { tex_range: range_quarter, tex_coords: coords_todo, sampler };
        let m = texture(&a4_spec(), &imp).unwrap_err();
        assert_eq!(m.task, "a4.t2");
    }

    // --- a3 and a2 -------------------------------------------------------------------------

    #[test]
    fn the_camera_comes_off_the_front_of_a_draw() {
        let mut gl = Gl::new();
        gl.translate(0.0, 0.0, -15.0);
        gl.rotate(30.0, 1.0, 0.0, 0.0);
        gl.translate(1.0, 2.0, 3.0);
        gl.draw("a", &cg_core::shapes::lecture_pyramid());
        assert_eq!(model_of(&gl.draws()[0]).numeric(), "T(1, 2, 3)");
        // No camera in front: V⁻¹ times the whole product, still model → world.
        let mut gl = Gl::new();
        gl.translate(1.0, 2.0, 3.0);
        gl.draw("a", &cg_core::shapes::lecture_pyramid());
        let m = model_of(&gl.draws()[0]);
        assert!(m.numeric().starts_with("V⁻¹ · T(1, 2, 3)"), "{}", m.numeric());
        assert!(name_matches("物体 2", "object 2") && name_matches("Object_2", "object 2"));
        assert!(!name_matches("object 12", "object 2"));
    }

    /// Object 1 spins about Y at (1, 1, 0), once in 2 s; object 2 orbits, but is never drawn.
    fn a3_spec() -> cg_a3::Spec {
        let object = |name: &str, motion| {
            cg_a3::new_object(name, cg_a3::Shape::Sphere { radius: 0.3 }, [1.0; 3], motion)
        };
        cg_a3::Spec {
            objects: vec![
                object(
                    "object 1",
                    Motion::Spin {
                        position: [1.0, 1.0, 0.0],
                        axis: WorldAxis::Y,
                        turn: cg_a3::Turn::Ccw,
                        period_s: 2.0,
                    },
                ),
                object(
                    "object 2",
                    Motion::Orbit {
                        center: [0.0, 1.0, 0.0],
                        radius: 2.0,
                        turn: cg_a3::Turn::Cw,
                        period_s: 1.0,
                    },
                ),
            ],
            unit_s: 1.0,
        }
    }

    fn a3_idle(_: &cg_a3::Spec, state: &mut cg_a3::State) {
        state.frame += 1;
        state.params[0] = (360.0 * (state.frame % 120) as f64 / 120.0) as f32;
    }

    /// The course's camera, then object 1 only, with plain glTranslatef / glRotatef numbers.
    fn a3_display(_: &cg_a3::Spec, state: &cg_a3::State, gl: &mut cg_student::gl::Gl) {
        gl.load_identity();
        gl.translate(0.0, 0.0, -15.0);
        gl.rotate(30.0, 1.0, 0.0, 0.0);
        gl.light_position(0, [10.0, 10.0, 10.0, 1.0]);
        gl.push_matrix();
        gl.translate(1.0, 1.0, 0.0);
        gl.rotate(state.params[0], 0.0, 1.0, 0.0);
        gl.draw("Object_1", &(&cg_core::shapes::lecture_pyramid()).into());
        gl.pop_matrix();
    }

    fn no_warmup(_: &mut cg_student::gl::Gl, _: f64) {}

    #[test]
    fn an_object_not_drawn_is_left_out_and_the_others_derive() {
        let spec = a3_spec();
        let imp = cg_a3::Impl { warmup_display: no_warmup, idle: a3_idle, display: a3_display };
        let (result, notes) = animation_part(&spec, &imp);
        let data = result.unwrap();
        assert_eq!(data.objects.len(), 1);
        assert_eq!(notes.len(), 1);
        assert_eq!(notes[0].task, "a3.t2");
        assert!(notes[0].why.en.contains("\"object 2\" is not drawn"), "{:?}", notes[0]);
        let times = animation_times(&spec);
        let (name, matrices) = &data.objects[0];
        assert_eq!(name, "object 1");
        for (m, &t) in matrices.iter().zip(&times) {
            // By hand: T(1, 1, 0) · Ry(360°·t/2), the angle in [0, 360).
            let angle = (180.0 * t).rem_euclid(360.0) as f32;
            let expected = Mat4::from_translation(Vec3::new(1.0, 1.0, 0.0))
                * Mat4::from_rotation_y(angle.to_radians());
            assert!(matrices_close(&m.numeric.matrix().unwrap(), &expected), "{}", m.numeric);
            assert_eq!(m.symbolic.symbolic(), "T(1, 1, 0) · Ry(theta_1)");
            assert_eq!(m.symbolic.matrix().unwrap(), m.numeric.matrix().unwrap());
            assert_eq!(m.id, format!("a3.object1.t{}", format_number(t as f32)));
        }
        assert_eq!(matrices[0].variables.len(), 1);
        assert!(matrices[0].variables[0].1.en.contains("360°·u, u = (t mod 2) / 2"));
        assert!(data.periods.en.contains("object 1 : object 2 = 2 : 1"), "{}", data.periods);
    }

    #[test]
    fn stated_times_are_whole_frames_and_the_motion_shows() {
        for number in ["20260002", "20260005", "20260013", "20260023"] {
            let student: StudentNumber = number.parse().unwrap();
            let spec = Assignment::for_student(&student, TableVersion::V1).a3;
            let times = animation_times(&spec);
            assert_eq!(times.len(), 3, "{times:?}");
            assert_eq!(times[0], 0.0);
            for &t in &times[1..] {
                assert!(t > 0.0 && (t * 4.0).fract() == 0.0, "{t}");
                for i in 0..spec.objects.len() {
                    let d = pose_distance(
                        &cg_a3::expected_model(&spec, i, frame_of(t)),
                        &cg_a3::expected_model(&spec, i, 0),
                    );
                    assert!(d > 0.1, "{number}: object {i} barely moves by t = {t}: {d}");
                }
            }
            assert!(animation_probe(&spec).is_some(), "{number}");
        }
    }

    #[test]
    fn camera_drags_state_each_state() {
        let student: StudentNumber = "12345678".parse().unwrap();
        let spec = Assignment::for_student(&student, TableVersion::V1).a2;
        let drags = camera_drags(&spec);
        assert_eq!(drags[0], ("a2.view.start".to_owned(), Vec::new()));
        assert_eq!(drags.len(), if spec.pan.is_some() { 4 } else { 3 });
        // 40 px along yaw's drag then 20 px along pitch's, 10 px per motion() call.
        let rotate = &drags[1].1;
        assert_eq!(rotate.len(), 6);
        let total = |f: fn(&Drag) -> f32| rotate.iter().map(f).sum::<f32>();
        assert_eq!((total(|d| d.dx), total(|d| d.dy)), (40.0, 20.0));
    }

    #[test]
    fn data_alone_derives_the_lecture_pyramids_normals() {
        let v = vec![
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(1.0, -0.8, 1.0),
            Vec3::new(1.0, -0.8, -1.0),
            Vec3::new(-1.0, -0.8, 1.0),
            Vec3::new(-1.0, -0.8, -1.0),
        ];
        let f = vec![[0, 3, 1], [0, 2, 4], [0, 1, 2], [0, 4, 3], [1, 3, 2], [4, 2, 3], [0, 1, 9]];
        let p = polygon_from_data(Text::new("四角すい", "pyramid"), v, f, None);
        // F0 {V0, V3, V1}: (V3 − V0) × (V1 − V0) = (0, 2, 3.6) / |…| — the lecture's front face.
        let n = p.derived_normals[0].unwrap();
        let len = (4.0f32 + 3.6 * 3.6).sqrt();
        assert!((n - Vec3::new(0.0, 2.0 / len, 3.6 / len)).length() < 1e-6, "{n}");
        assert!(p.derived_normals[4].unwrap().abs_diff_eq(Vec3::NEG_Y, 1e-6));
        assert_eq!(p.derived_normals[6], None, "a vertex number out of range has no normal");
    }
}
