//! Assignment `s` — シェーディング（第11回） (shading, lecture 11): the lecture itself as exercises.
//!
//! Every assignment crate has the same shape (the command line and the tests rely on it):
//! [`ID`], a per-student [`Spec`] drawn by [`variant`] and described by [`Spec::describe`], the
//! exercise API [`Impl`] (the functions a student writes, in `exercises/src/s.rs`),
//! [`checks()`] and [`view()`]. [`Impl`], [`Pixel`] and [`Shading`] are the students' own types
//! (`cg_student::s`), re-exported; [`kit_shading`] gives the renderer's
//! [`cg_core::scene::Shading`] for a student's mode.
//!
//! ## The tasks
//!
//! The light model of the lecture (光のモデル),
//!
//! ```text
//! I = Ia·ka + Σᵢ Iᵢ·[kd (N·L) + ks (R·V)ⁿ] + kr·Ir + kt·It
//!     環境光      拡散反射光   鏡面反射光(局所)   鏡面反射光・透過光(大域)
//! ```
//!
//! term by term, the light types, vertex normals and the three shading methods:
//!
//! | task | what the student writes | [`Impl`] field | checked against |
//! |---|---|---|---|
//! | s.t1 | 環境光 `Ia·ka` | `ambient` | [`cg_core::light::ambient`] |
//! | s.t2 | 拡散反射光 `Iᵢ·kd·max(N·L, 0)` (Lambert) | `diffuse` | [`cg_core::light::diffuse`] |
//! | s.t3 | 鏡面反射光 `Iᵢ·ks·max(R·V, 0)ⁿ` (Phong) | `specular` | [`cg_core::light::specular_phong`] |
//! | s.t4 | 減衰 `1/(kc + kl·d + kq·d²)` and the spot light's cone | `attenuation`, `spot_factor` | [`cg_core::light::attenuation`], [`cg_core::light::spot_factor`] |
//! | s.t5 | 頂点の法線: the average of the adjacent face normals, plain and area-weighted | `vertex_normals`, `vertex_normals_area` | [`cg_core::normals::vertex_normals`] |
//! | s.t6 | フラット／グロー／フォンシェーディング: what to light at a pixel | `shade_pixel` | the CPU rasterizer's own flat, Gouraud and Phong images |
//! | s.t7 | 鏡面反射 (大域照明): the mirror direction | `reflect` | [`cg_core::optics::reflect`] |
//! | s.t8 | 透過光: refraction by Snell's law, total internal reflection | `refract` | [`cg_core::optics::refract`] with [`cg_core::optics::Interface`] |
//!
//! ## How s.t6 meets the rasterizer
//!
//! The rasterizer's lighting hook ([`cg_raster::Lighting`]) is told only *how* to light a point;
//! *where* the lighting happens — once per face, per vertex or per pixel — is decided inside the
//! renderer. Since that "where" is the lecture's point, the kit asks the renderer, through the
//! same hook, which face every pixel sees and with which corner weights (a G-buffer, see
//! [`render`]), and lets the student's [`Impl::shade_pixel`] decide the colour of each pixel
//! from the shading mode, the face normal, the vertex normals and the weights. A correct
//! `shade_pixel` reproduces the renderer's own images; the checks compare them.

use cg_core::lang::Lang;
use cg_core::scene::Scene;
use cg_harness::{CheckResult, Text, VariantRng};

mod checks;
mod describe;
mod inputs;
pub mod render;
pub mod report;
pub mod scenes;
pub mod spec;
mod view;

pub use checks::kit_rule;

pub use cg_student::s::{Impl, Pixel, Shading};
pub use spec::Spec;

/// The assignment's ID, the prefix of its task IDs (`s.t1`, …).
pub const ID: &str = "s";

/// The kit's shading mode (the renderer's [`cg_core::scene::Shading`]) for the student's `mode`.
#[must_use]
pub fn kit_shading(mode: Shading) -> cg_core::scene::Shading {
    match mode {
        Shading::Flat => cg_core::scene::Shading::Flat,
        Shading::Gouraud => cg_core::scene::Shading::Gouraud,
        Shading::Phong => cg_core::scene::Shading::Phong,
    }
}

/// The student's variant, drawn from the frozen stream of their number and table version (see
/// [`spec`] for the tables).
#[must_use]
pub fn variant(rng: &mut VariantRng) -> Spec {
    spec::variant(rng)
}

impl Spec {
    /// The assignment text for this variant, in `lang`: every task with its ID, this student's
    /// numbers, and what the report must show.
    #[must_use]
    pub fn describe(&self, lang: Lang) -> String {
        describe::describe(self, lang)
    }
}

/// Every check of this assignment for `spec`, run against `imp` (IDs `s.tN.name`; see
/// `docs/assignments/s.md` for the list).
#[must_use]
pub fn checks(spec: &Spec, imp: &Impl) -> Vec<CheckResult> {
    checks::checks(spec, imp)
}

/// The scene that shows `imp`'s result: the course's stage (its window, camera and ground) with
/// the student's light and three of the student's spheres on the ground — flat, Gouraud and
/// Phong from left to right — each pixel of the spheres coloured by the student's
/// `shade_pixel` with the student's vertex normals and, where they are written, the student's
/// own light-model terms (s.t1–s.t3; the kit's stand in for terms still `todo!()`).
///
/// The renderer that draws a view lights scenes its own way, so the picture is composed here and
/// handed over as a screen-filling quad that shows it pixel for pixel. `time_s` is not used.
///
/// # Errors
/// What keeps the stage from being drawn (never for the kit's own scenes).
pub fn view(spec: &Spec, imp: &Impl, time_s: f64) -> Result<Scene, Text> {
    let _ = time_s;
    view::view(spec, imp)
}

/// The shading set (lecture 11) as a unit of the kit: what `cg assignment`, `cg check`, `cg view`, the report and the
/// grader need of it (see [`cg_harness::Assignment`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct S;

impl cg_harness::Assignment for S {
    const ID: &'static str = ID;
    const TITLE: (&'static str, &'static str) = ("第11回 シェーディング", "shading");
    type Spec = Spec;
    type Impl = Impl;
    type Report = report::ShadingData;

    fn variant(rng: &mut cg_harness::VariantRng) -> Spec {
        variant(rng)
    }

    fn describe(spec: &Spec, lang: cg_core::lang::Lang) -> String {
        spec.describe(lang)
    }

    fn spec_json(spec: &Spec) -> cg_harness::unit::Json {
        cg_harness::unit::json(spec)
    }

    fn checks(spec: &Spec, imp: &Impl) -> Vec<cg_harness::CheckResult> {
        checks(spec, imp)
    }

    fn report(spec: &Spec, imp: &Impl) -> cg_harness::report::Part<report::ShadingData> {
        report::report(spec, imp)
    }

    fn view(
        spec: &Spec,
        imp: &Impl,
        time_s: f64,
    ) -> Result<cg_core::scene::Scene, cg_harness::Text> {
        view(spec, imp, time_s)
    }

    /// The view a correct answer gives, drawn with the kit's own light model
    /// ([`cg_core::light`]), vertex normals ([`cg_core::normals`]) and shading rule
    /// ([`kit_rule`]) in place of the student's functions.
    fn reference_view(spec: &Spec, time_s: f64) -> Option<cg_core::scene::Scene> {
        Some(view::reference(spec, time_s))
    }

    /// Each sphere's name on the ground in front of it, as the stage's camera sees it (the
    /// spheres are flat, Gouraud and Phong from left to right).
    fn view_labels(spec: &Spec) -> Vec<([f32; 2], &'static str)> {
        let stage = scenes::stage_scene(spec);
        let (Ok(view), Ok(projection)) =
            (stage.view_product().and_then(|v| v.matrix()), stage.projection_matrix())
        else {
            return Vec::new();
        };
        let names = ["FLAT", "GOURAUD", "PHONG"];
        scenes::STAGE_SPHERES
            .iter()
            .zip(names)
            .filter_map(|(&(x, _), name)| {
                let at = cg_core::glam::Vec3::new(x, 0.0, scenes::STAGE_RADIUS);
                let clip = projection * view * at.extend(1.0);
                (clip.w > 0.0)
                    .then(|| ([(clip.x / clip.w + 1.0) * 0.5, (1.0 - clip.y / clip.w) * 0.5], name))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_students_shading_mode_is_the_kits_mode_of_the_same_name() {
        for mode in [Shading::Flat, Shading::Gouraud, Shading::Phong] {
            assert_eq!(format!("{:?}", kit_shading(mode)), format!("{mode:?}"));
        }
    }
}
