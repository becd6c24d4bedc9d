//! The report's data for `s`: the five report items of the assignment as tables, each row with
//! the kit's own value (the trusted side: `cg_core::light`, `cg_core::optics`,
//! `cg_core::normals`, never the student's crate) and, where a function of the student's computes
//! the same quantity, the student's output for the same inputs.
//!
//! | table | what | the student's functions |
//! |---|---|---|
//! | [`LIGHT_P`], [`LIGHT_Q`] | the light model at P = (0, 1, 0) and at a point Q in the highlight: P, N, V, L, R, N·L, R·V and every term | `reflect` (R = reflect(−L, N)), `ambient`, `diffuse`, `specular` |
//! | [`ATTENUATION`] | `1/(kc + kl·d + kq·d²)` at d = 1, 5, 10, 20 | `attenuation` |
//! | [`SPOT`] | cos α and the spot factor at α = 0°, cut-off/2, cut-off ∓ 1° | `spot_factor` |
//! | [`NORMALS`] | a cube corner: its triangles' normals and areas, the plain and the area-weighted vertex normal | `vertex_normals`, `vertex_normals_area` |
//! | [`REFRACTION`] | the critical angle, refraction at 30° from air, total internal reflection at 60° from inside | `refract` |
//!
//! Every call of the student's code goes through [`guarded`] (and a stub's marker,
//! `cg_student::not_started`, counts as not written): a `todo!()` or a panic leaves that cell
//! [`Missing`], once per function, and the kit's values still derive — so a report can be checked
//! by hand before the code is written.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::product::format_number;
use cg_harness::Text;
use cg_harness::check::{Outcome, guarded, marker_message};
use cg_harness::report::{Missing, Part};

use crate::scenes::CHECK_EYE;
use crate::{Impl, Spec};

// The tables: the light model's (`light.rs`), and the light types', the cube's and
// refraction's (`items.rs`).
mod items;
mod light;

pub use items::{incident, spot_angles, spot_geometry};
pub use light::{highlight_factor, highlight_point, light_table_at};

/// The light model at P = (0, 1, 0).
pub const LIGHT_P: &str = "s.light.p";
/// The light model at a point Q in the highlight (the kit's choice, or the student's).
pub const LIGHT_Q: &str = "s.light.q";
/// Point-light attenuation.
pub const ATTENUATION: &str = "s.attenuation";
/// The spot light's factor.
pub const SPOT: &str = "s.spot";
/// Vertex normals at a cube corner.
pub const NORMALS: &str = "s.normals";
/// Refraction and total internal reflection.
pub const REFRACTION: &str = "s.refraction";
/// Every table's ID, in the report's order: the tag before the table (`<!-- cg: s.spot -->`).
pub const TABLE_IDS: [&str; 6] = [LIGHT_P, LIGHT_Q, ATTENUATION, SPOT, NORMALS, REFRACTION];

/// The distances of the attenuation table.
pub const DISTANCES: [f32; 4] = [1.0, 5.0, 10.0, 20.0];
/// The angle of incidence from air, degrees.
pub const THETA_AIR_DEG: f64 = 30.0;
/// The angle of incidence from inside, beyond every medium's critical angle, degrees.
pub const THETA_INSIDE_DEG: f64 = 60.0;
/// The cube of the vertex-normal table: 2 × 2 × 2 about the origin
/// ([`cg_core::shapes::cuboid`], the checks' cube), and the corner shown (V0, (−1, −1, 1)).
pub const CUBE_CORNER: u32 = 0;

/// A value of the report: what a cell holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    /// A number.
    Number(f64),
    /// A direction or point `(x, y, z)`.
    Vector([f64; 3]),
    /// A colour `(r, g, b)`.
    Color([f64; 3]),
    /// No value: no refracted ray (total internal reflection), `None`.
    Nothing,
}

impl Value {
    fn vector(v: Vec3) -> Value {
        Value::Vector(v.as_dvec3().to_array())
    }

    fn color(c: Rgb) -> Value {
        Value::Color(c.as_dvec3().to_array())
    }
}

/// One cell of a table.
#[derive(Clone, Debug, PartialEq)]
pub enum Cell {
    /// Shown as it is (a formula, the inputs); not checked.
    Text(Text),
    /// For the student to work out by hand; the kit's value checks what they write.
    Hand(Value),
    /// Given by the assignment (the point P); shown and checked.
    Given(Value),
    /// The kit's choice that the student may change (the point Q): shown; the kit derives the
    /// rest of the table from what is written here.
    Chosen(Value),
    /// The student's function's output, shown; the kit's value checks it.
    Yours {
        /// The kit's value.
        kit: Value,
        /// The student's output, or why there is none.
        yours: Result<Value, Missing>,
    },
    /// Nothing to write.
    Empty,
}

impl Cell {
    /// The kit's value, for a cell that holds a number to check.
    #[must_use]
    pub fn kit(&self) -> Option<Value> {
        match self {
            Cell::Hand(v) | Cell::Given(v) | Cell::Chosen(v) | Cell::Yours { kit: v, .. } => {
                Some(*v)
            }
            Cell::Text(_) | Cell::Empty => None,
        }
    }
}

/// One row: its label (the first column; the checker finds the row by it) and its cells.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// The label, as the first column shows it.
    pub label: Text,
    /// The other columns.
    pub cells: Vec<Cell>,
}

/// One table of the shading section.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// Its ID (one of [`TABLE_IDS`]), the tag before it.
    pub id: &'static str,
    /// The column headers, the label column's first.
    pub columns: Vec<Text>,
    /// The rows.
    pub rows: Vec<Row>,
}

/// The student's light and material at one point: what the light tables are derived from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSetup {
    /// The point light's position.
    pub position: Vec3,
    /// The eye.
    pub eye: Vec3,
    /// Ia, the ambient light (grey).
    pub ia: Rgb,
    /// Ii, the light's colour.
    pub ii: Rgb,
    /// ka (= kd).
    pub ka: Rgb,
    /// kd.
    pub kd: Rgb,
    /// ks (grey).
    pub ks: Rgb,
    /// n.
    pub shininess: f32,
}

impl LightSetup {
    /// The student's light and material, seen from the checks' eye.
    #[must_use]
    pub fn of(spec: &Spec) -> LightSetup {
        let c = Rgb::from(spec.material.color.rgb);
        LightSetup {
            position: Vec3::from(spec.light.position),
            eye: CHECK_EYE,
            ia: Rgb::splat(spec.light.ambient),
            ii: Rgb::from(spec.light.color.rgb),
            ka: c,
            kd: c,
            ks: Rgb::splat(spec.material.ks),
            shininess: spec.material.shininess,
        }
    }
}

/// Assignment s in the report: the six tables and the numbers their prose needs.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadingData {
    /// The light and material (to derive a light table at a point the student chooses).
    pub setup: LightSetup,
    /// The light model at P = (0, 1, 0).
    pub light_p: Table,
    /// The light model at Q.
    pub light_q: Table,
    /// The attenuation.
    pub attenuation: Table,
    /// The spot factor.
    pub spot: Table,
    /// The cube corner's normals.
    pub normals: Table,
    /// Refraction.
    pub refraction: Table,
    /// kc, kl, kq.
    pub coefficients: [f32; 3],
    /// The spot's cut-off (degrees) and exponent.
    pub spot_cone: (f32, f32),
    /// The medium's name and its refractive index η.
    pub medium: (Text, f32),
}

impl ShadingData {
    /// Every table, in the report's order ([`TABLE_IDS`]).
    #[must_use]
    pub fn tables(&self) -> [&Table; 6] {
        [
            &self.light_p,
            &self.light_q,
            &self.attenuation,
            &self.spot,
            &self.normals,
            &self.refraction,
        ]
    }

    /// The table with this ID.
    #[must_use]
    pub fn table(&self, id: &str) -> Option<&Table> {
        self.tables().into_iter().find(|t| t.id == id)
    }
}

/// Calls the student's `function` of `task` through [`guarded`]; a stub's marker for `task`
/// (`cg_student::not_started`) counts as not written. Markers reached before are put back.
fn call<T>(task: &str, function: &str, f: impl FnOnce() -> T) -> Result<T, Missing> {
    let outer = cg_student::take_not_started();
    let result = guarded(f);
    let reached = cg_student::take_not_started();
    for marker in &outer {
        cg_student::not_started(marker);
    }
    if reached.iter().any(|m| m == task)
        && let Some(message) = marker_message(task, &reached)
    {
        return Err(Missing::from_outcome(task, function, Outcome::NotDone { message }));
    }
    result.map_err(|o| Missing::from_outcome(task, function, o))
}

/// The student's functions, each failure noted once per function.
struct Student<'a> {
    imp: Option<&'a Impl>,
    notes: Vec<Missing>,
}

impl Student<'_> {
    /// `f(imp)` as the student's value of `kit`'s quantity.
    fn cell<T>(
        &mut self,
        kit: Value,
        task: &str,
        function: &str,
        f: impl FnOnce(&Impl) -> T,
        value: impl FnOnce(T) -> Result<Value, Text>,
    ) -> Cell {
        let yours = match self.imp {
            None => Err(Missing::new(task, Text::new("", ""))),
            Some(imp) => call(task, function, || f(imp))
                .and_then(|out| value(out).map_err(|why| Missing::new(task, why))),
        };
        if let Err(m) = &yours
            && self.imp.is_some()
            && !self.notes.iter().any(|n| n.task == m.task && n.why.en.starts_with(function))
        {
            self.notes.push(m.clone());
        }
        Cell::Yours { kit, yours }
    }
}

fn t(ja: &str, en: &str) -> Text {
    Text::new(ja, en)
}

fn same(s: &str) -> Text {
    Text::new(s, s)
}

/// `(x, y, z)` as the kit writes numbers in prose (`(-1, -1, 1)`).
fn point_text(v: Vec3) -> String {
    format!("({}, {}, {})", format_number(v.x), format_number(v.y), format_number(v.z))
}

/// The shading section's data for `spec`: the kit's values always (they follow from the
/// assignment alone), the student's outputs where their functions give them; each function that
/// is still a stub, panics or returns something unusable is one [`Missing`] among the notes.
pub fn report(spec: &Spec, imp: &Impl) -> Part<ShadingData> {
    let setup = LightSetup::of(spec);
    let mut student = Student { imp: Some(imp), notes: Vec::new() };
    let light_p = light::light_table(LIGHT_P, &setup, Vec3::Y, &mut student);
    let light_q = light::light_table(LIGHT_Q, &setup, highlight_point(&setup), &mut student);
    let attenuation = items::attenuation_table(spec, &mut student);
    let spot = items::spot_table(spec, &mut student);
    let normals = items::normals_table(&mut student);
    let refraction = items::refraction_table(spec, &mut student);
    let mut notes = student.notes;
    notes.sort_by(|a, b| a.task.cmp(&b.task));
    let a = spec.attenuation;
    (
        Ok(ShadingData {
            setup,
            light_p,
            light_q,
            attenuation,
            spot,
            normals,
            refraction,
            coefficients: [a.kc, a.kl, a.kq],
            spot_cone: (spec.spot.cutoff_deg, spec.spot.exponent),
            medium: (Text::new(spec.medium.ja, spec.medium.en), spec.medium.eta),
        }),
        notes,
    )
}
