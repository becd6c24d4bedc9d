//! Assignment `a4` — テクスチャマッピング (texture mapping).
//!
//! 「指定された通りに、あらかじめ用意されている画像を読み込み、その一部を、地面にマッピングする。
//! レポートには、テクスチャ座標の範囲や計算方法を示すこと。」 Each student gets a region of the
//! [prepared image](prepared_image) (a rectangle of its named cells), an orientation (turned by
//! quarter turns, perhaps mirrored) and a repeat count, and writes:
//!
//! | task | function (`exercises/src/a4.rs`) | what |
//! |---|---|---|
//! | `a4.t1` | `tex_range(spec) -> TexRange` | the region's texture-coordinate range |
//! | `a4.t2` | `tex_coords(spec, i, j) -> [Vec2; 4]` | the coordinates of the corners of ground square `(i, j)` |
//! | `a4.t3` | `sampler() -> Sampler` | filter and wrap modes |
//!
//! ## Conventions
//!
//! | what | convention |
//! |---|---|
//! | texture coordinates | `(s, t) = (0, 0)` is the image's bottom-left corner, `(1, 1)` its top-right (OpenGL, [`cg_core::texture`]) |
//! | cells | spreadsheet names: columns `A`–`H` left to right, rows `1`–`8` **top to bottom**; pixels from the top-left corner |
//! | ground | the course's 10 × 10 squares: vertex `(i, j)`, `i, j = 0…10`, at `(i·1 − 5, 0, j·1 − 5)`; square `(i, j)` has the corners `(i, j), (i, j+1), (i+1, j+1), (i+1, j)` ([`CORNER_STEPS`]), the triangles of [`cg_core::shapes::grid`] |
//! | orientation | as the course's camera sees the ground (from +z, above): screen right = +x (i grows), screen up = −z (j shrinks); turns counter-clockwise as seen from there; a mirror is left–right, before the turn |
//! | repeat | by the coordinates: `repeat × repeat` blocks of `10 / repeat` squares, each showing the whole region; the vertices on a block's edge belong to two blocks and so to two coordinates. GL_REPEAT cannot do this (it repeats the *whole* image), so the wrap mode is GL_CLAMP_TO_EDGE |
//!
//! Every assignment crate has the same shape (the command line and the tests rely on it):
//! [`ID`], a per-student [`Spec`] drawn by [`variant`] and described by [`SpecExt::describe`], the
//! exercise API [`Impl`], [`checks()`] and [`view()`].
//!
//! The plain data a student sees ([`Spec`], [`Region`], [`TexRange`], [`Sampler`], [`Impl`], the
//! constants [`CELLS`], [`SQUARES`], [`CORNER_STEPS`]) lives in [`cg_student::a4`] and is
//! re-exported here; what is worked out from it (cell names, pixels, where each corner lands, the
//! assignment text) is this crate's, as the extension traits [`RegionExt`] and [`SpecExt`], and
//! `cg assignment --json` shows the spec through [`Presented`] / [`serialize_spec`].

mod checks;
mod describe;
mod json;
mod prepared;
pub mod report;
mod spec;
mod view;

pub use cg_student::a4::{Filter, Impl, SQUARES, Sampler, TexRange, Wrap};
pub use checks::checks;
pub use json::{Presented, serialize_spec};
pub use prepared::{
    CELL_PIXELS, CELLS, FRAME_COLOR, IMAGE_PIXELS, INK_COLOR, cell_color, cell_name, column_name,
    prepared_image,
};
pub use spec::{CORNER_STEPS, Corner, GroundCorner, Region, RegionExt, Spec, SpecExt, variant};
pub use view::{Coordinates, coordinates, ground_mesh, view};

/// The assignment's ID, the prefix of its task IDs (`a4.t1`, …).
pub const ID: &str = "a4";

/// The kit's sampler for a student's [`Sampler`] (`a4.t3`): the same filter and wrap modes as
/// [`cg_core::texture::Sampler`], which the renderer and the report use.
#[must_use]
pub fn core_sampler(s: Sampler) -> cg_core::texture::Sampler {
    let filter = match s.filter {
        Filter::Nearest => cg_core::texture::Filter::Nearest,
        Filter::Bilinear => cg_core::texture::Filter::Bilinear,
    };
    let wrap = |w: Wrap| match w {
        Wrap::Repeat => cg_core::texture::Wrap::Repeat,
        Wrap::Clamp => cg_core::texture::Wrap::Clamp,
    };
    cg_core::texture::Sampler { filter, wrap_u: wrap(s.wrap_u), wrap_v: wrap(s.wrap_v) }
}

/// Assignment 4 as a unit of the kit: what `cg assignment`, `cg check`, `cg view`, the report and the
/// grader need of it (see [`cg_harness::Assignment`]).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct A4;

impl cg_harness::Assignment for A4 {
    const ID: &'static str = ID;
    const TITLE: (&'static str, &'static str) = ("テクスチャマッピング", "texture mapping");
    type Spec = Spec;
    type Impl = Impl;
    type Report = report::TextureData;

    fn variant(rng: &mut cg_harness::VariantRng) -> Spec {
        variant(rng)
    }

    fn describe(spec: &Spec, lang: cg_core::lang::Lang) -> String {
        SpecExt::describe(spec, lang)
    }

    fn checks(spec: &Spec, imp: &Impl) -> Vec<cg_harness::CheckResult> {
        checks(spec, imp)
    }

    fn report(spec: &Spec, imp: &Impl) -> cg_harness::report::Part<report::TextureData> {
        report::texture_part(spec, imp)
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

    fn spec_json(spec: &Spec) -> cg_harness::unit::Json {
        cg_harness::unit::json(&Presented(spec))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::texture as core;

    #[test]
    fn the_students_sampler_becomes_the_kits_mode_for_mode() {
        assert_eq!(core_sampler(Sampler::default()), core::Sampler::default());
        let s = Sampler { filter: Filter::Nearest, wrap_u: Wrap::Clamp, wrap_v: Wrap::Repeat };
        let want = core::Sampler {
            filter: core::Filter::Nearest,
            wrap_u: core::Wrap::Clamp,
            wrap_v: core::Wrap::Repeat,
        };
        assert_eq!(core_sampler(s), want);
        let s = Sampler { filter: Filter::Bilinear, wrap_u: Wrap::Repeat, wrap_v: Wrap::Clamp };
        assert_eq!(core_sampler(s).filter, core::Filter::Bilinear);
        assert_eq!(
            (core_sampler(s).wrap_u, core_sampler(s).wrap_v),
            (core::Wrap::Repeat, core::Wrap::Clamp)
        );
    }
}
