//! Assignment `a1` — ポリゴンモデルの描画 (polygon model).
//!
//! The course's first report task: "指定されたポリゴンモデルを描画する処理を追加すること" — draw
//! the polyhedron you were given, and show in the report its vertex table, its face table with
//! each face's normal, figures of how vertices and faces connect, and how the data was derived.
//!
//! Every assignment crate has the same shape (the command line and the tests rely on it):
//! [`ID`], a per-student [`Spec`] drawn by [`variant`] and described by [`Spec::describe`], the
//! exercise API [`Impl`] (the functions a student writes, in `exercises/src/a1.rs`),
//! [`checks()`] and [`view()`].
//!
//! | task | function | what it returns | checks |
//! |---|---|---|---|
//! | `a1.t1` | `vertices(spec)` | `Vec<Vec3>`, model space, numbered by the spec's rule | `a1.t1.count`, `a1.t1.positions` |
//! | `a1.t2` | `faces(spec)` | `Vec<[u32; 3]>`, counter-clockwise seen from outside | `a1.t2.indices`, `.degenerate`, `.closed`, `.manifold`, `.winding`, `.outward`, `.count`, `.surface` |
//! | `a1.t3` | `face_normals(spec)` | `Vec<Vec3>`, one unit normal per face | `a1.t3.count`, `a1.t3.unit`, `a1.t3.normals` |
//! | `a1.t4` | `model_transform(spec)` | [`MatrixProduct`](cg_student::product::MatrixProduct) `T(x, y, z) · Ry(θ)` | `a1.t4.placement` |
//!
//! The view draws the student's mesh face by face with the student's own normals
//! ([`NormalSource::Given`](cg_core::scene::NormalSource::Given)) on the course's stage, so a
//! wrong normal lights its face wrongly and a face wound the wrong way is culled (a hole).

mod checks;
mod describe;
pub mod hull;
pub mod report;
mod spec;
mod view;

use cg_core::product::format_number;

pub use checks::{
    MATRIX_TOLERANCE, NORMAL_TOLERANCE, SURFACE_TOLERANCE, UNIT_TOLERANCE, VERTEX_TOLERANCE, checks,
};
pub use describe::SpecDescribe;
pub use spec::{
    FAMILIES, Numbering, NumberingExt, Order, Placement, RidgeAxis, Shape, ShapeExt, Spec, SpecExt,
    Turn, variant,
};
pub use view::{MODEL_COLOR, view};

/// The assignment's ID, the prefix of its task IDs (`a1.t1`, …).
pub const ID: &str = "a1";

pub use cg_student::a1::Impl;

/// An angle in degrees as the texts print it: `30`, `-22.5`.
pub(crate) fn format_deg(x: f32) -> String {
    format_number(x)
}

/// Assignment 1 as a unit of the kit: what `cg assignment`, `cg check`, `cg view`, the report and the
/// grader need of it (see [`cg_harness::Assignment`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct A1;

impl cg_harness::Assignment for A1 {
    const ID: &'static str = ID;
    const TITLE: (&'static str, &'static str) = ("ポリゴンモデルの描画", "polygon model");
    type Spec = Spec;
    type Impl = Impl;
    type Report = report::PolygonData;

    fn variant(rng: &mut cg_harness::VariantRng) -> Spec {
        variant(rng)
    }

    fn describe(spec: &Spec, lang: cg_core::lang::Lang) -> String {
        SpecDescribe::describe(spec, lang)
    }

    fn spec_json(spec: &Spec) -> cg_harness::unit::Json {
        cg_harness::unit::json(spec)
    }

    fn checks(spec: &Spec, imp: &Impl) -> Vec<cg_harness::CheckResult> {
        checks(spec, imp)
    }

    fn report(spec: &Spec, imp: &Impl) -> cg_harness::report::Part<report::PolygonData> {
        report::polygon_part(spec, imp)
    }

    fn view(
        spec: &Spec,
        imp: &Impl,
        time_s: f64,
    ) -> Result<cg_core::scene::Scene, cg_harness::Text> {
        view(spec, imp, time_s)
    }

    fn reference_view(spec: &Spec, time_s: f64) -> Option<cg_core::scene::Scene> {
        let _ = time_s;
        Some(view::reference(spec))
    }
}
