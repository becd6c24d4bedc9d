//! WGSL per scene (「シーンに必要なものだけ」): one readable source, `shader.wgsl` beside this
//! file, from which [`shader_source`] keeps only the code for the terms of the light model, the
//! light types and the texturing that the scene's [`Features`] say it uses, for one shading
//! mode and one light model. The file marks each optional part with `//#if FLAGS` …
//! (optionally `//#else` …) `//#endif` (WGSL comments, so a TA reads it as WGSL); [`Flags`]
//! says which flag holds for a scene.
//!
//! | shading | where [`shade`](#the-shade-function) runs | what is interpolated |
//! |---|---|---|
//! | [`Shading::Flat`] | vertex shader, once per face: the lecture's model at its centroid with the face normal; OpenGL's at its provoking (last) vertex with that vertex's normal and colour, as GL_FLAT (all three corners of a face carry the same values, so WebGPU's first provoking vertex shows OpenGL's last one's colour) | nothing (`@interpolate(flat)`) |
//! | [`Shading::Gouraud`] | vertex shader, per vertex with the vertex normal; clamped to `[0, 1]` | the colour, perspective-correct |
//! | [`Shading::Phong`] | fragment shader, per pixel with the interpolated, renormalised normal | world position, normal, colour |
//!
//! ## The `shade` function
//!
//! The same equations as [`cg_core::light::shade`] (see its module for both models), in f32:
//! emission, `ka·Ia` (the CPU sums the global and, in the lecture's model, the per-light ambient
//! into one uniform), and per light (an area light arrives as its point-light samples, spot
//! lights facing out of the front side): attenuation `1 / max(kc + kl·d + kq·d², 1e-6)`, the
//! spot factor, OpenGL's attenuated per-light ambient, the diffuse term, and the specular term
//! (Phong `(R·V)ⁿ` or Blinn `(N·H)ⁿ`, zero where `N·L ≤ 0` or the cosine is ≤ 0).

use cg_core::features::Features;
use cg_core::lang::{Text, t};
use cg_core::light::{LightModel, Specular};
use cg_core::scene::Shading;

/// Which parts of the light model and the pipeline a shader built for `features` contains, as
/// short names in both languages, worded as [`Features::list`] words them (for `cg render
/// --renderer gpu` to print). Reflection and transmission are never in it: they need rays.
#[must_use]
pub fn enabled(features: &Features) -> Vec<Text> {
    let f = features;
    [
        (f.emission, t("放射", "emission")),
        (f.ambient, t("環境光", "ambient")),
        (f.diffuse, t("拡散反射光", "diffuse")),
        (f.specular, t("鏡面反射光", "specular")),
        (f.directional, t("平行光源", "directional lights")),
        (f.point, t("点光源", "point lights")),
        (f.spot, t("スポットライト光源", "spot lights")),
        (f.area, t("面光源（点光源の標本として）", "area lights (as point-light samples)")),
        (f.attenuation, t("距離による減衰", "attenuation")),
        (f.textures, t("テクスチャ", "textures")),
        (f.local_viewer && f.specular, t("視点は有限の距離", "local viewer")),
    ]
    .into_iter()
    .filter_map(|(on, name)| on.then_some(name))
    .collect()
}

/// Whether the shader needs the spot-light code: spot lights, and area lights (whose samples
/// shine only to the front side, as spot lights with a 90° cone).
fn needs_spot(f: &Features) -> bool {
    f.spot || f.area
}

/// Whether the shader needs the positional-light code (point, spot, area).
fn needs_positional(f: &Features) -> bool {
    f.point || f.spot || f.area
}

/// The shader's template, as a TA reads it.
pub const TEMPLATE: &str = include_str!("shader.wgsl");

/// The flags of `shader.wgsl`'s `//#if` lines for one scene: its features, shading mode and
/// light model.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Flags(Vec<(&'static str, bool)>);

impl Flags {
    /// The flags for a scene with `features`, drawn with `shading` under `model`.
    #[must_use]
    pub fn new(features: &Features, shading: Shading, model: LightModel) -> Flags {
        let f = features;
        let lecture = matches!(model, LightModel::Lecture { .. });
        Flags(vec![
            ("flat", shading == Shading::Flat),
            ("gouraud", shading == Shading::Gouraud),
            ("phong", shading == Shading::Phong),
            ("lecture", lecture),
            (
                "phong_specular",
                matches!(model, LightModel::Lecture { specular: Specular::Phong, .. }),
            ),
            ("emission", f.emission),
            ("ambient", f.ambient),
            ("diffuse", f.diffuse),
            ("specular", f.specular),
            ("local_viewer", f.local_viewer),
            ("directional", f.directional),
            ("positional", needs_positional(f)),
            ("spot", needs_spot(f)),
            ("attenuation", f.attenuation && needs_positional(f)),
            ("textures", f.textures),
            ("per_light", f.diffuse || f.specular || (f.ambient && !lecture)),
            ("opengl_ambient", f.ambient && !lecture),
        ])
    }

    /// Whether `name` holds.
    ///
    /// # Panics
    /// On a name that is no flag: a mistake in `shader.wgsl`, caught by the tests.
    #[must_use]
    pub fn get(&self, name: &str) -> bool {
        match self.0.iter().find(|(n, _)| *n == name) {
            Some(&(_, on)) => on,
            None => panic!("shader.wgsl: unknown flag {name:?}"),
        }
    }
}

/// `template` with the lines of every `//#if` block whose condition fails dropped, the
/// directive lines and the template's own documentation (`//!` lines) removed. A condition is
/// flags joined by `&&`, each possibly negated with `!`; blocks nest; `//#else` flips the
/// innermost block.
///
/// # Panics
/// On an unknown flag, an `//#else` or `//#endif` without its `//#if`, or an `//#if` left open:
/// mistakes in the template, caught by the tests.
#[must_use]
pub fn preprocess(template: &str, flags: &Flags) -> String {
    let mut out = String::with_capacity(template.len());
    // Per open block: (its condition holds, the enclosing blocks all hold).
    let mut open: Vec<(bool, bool)> = Vec::new();
    let on = |open: &[(bool, bool)]| open.last().is_none_or(|&(cond, outer)| cond && outer);
    for (n, line) in template.lines().enumerate() {
        let trimmed = line.trim_start();
        if let Some(condition) = trimmed.strip_prefix("//#if ") {
            let holds = condition.split("&&").all(|term| {
                let term = term.trim();
                match term.strip_prefix('!') {
                    Some(name) => !flags.get(name.trim()),
                    None => flags.get(term),
                }
            });
            let outer = on(&open);
            open.push((holds, outer));
        } else if trimmed.starts_with("//#else") {
            let Some(last) = open.last_mut() else {
                panic!("shader.wgsl line {}: //#else without //#if", n + 1)
            };
            last.0 = !last.0;
        } else if trimmed.starts_with("//#endif") {
            assert!(open.pop().is_some(), "shader.wgsl line {}: //#endif without //#if", n + 1);
        } else if !trimmed.starts_with("//!") && on(&open) {
            out.push_str(line);
            out.push('\n');
        }
    }
    assert!(open.is_empty(), "shader.wgsl: an //#if is not closed");
    out
}

/// The WGSL source of the shader for a scene with `features`, drawn with `shading` under
/// `model`: `shader.wgsl` with only the parts this scene needs ([`preprocess`]), after a first
/// line that names them. Entry points `vs_main` and `fs_main`; bind group 0 holds the frame's
/// uniforms (binding 0) and lights (binding 1, a read-only storage array); bind group 1 the
/// object's uniforms (binding 0) and, only when `features.textures`, its texture (1) and
/// sampler (2). Vertex buffer 0: world position (location 0), shading normal (1), face normal
/// (2), colour (3), texture coordinate (4), where flat shading lights the face (5: its centroid,
/// or OpenGL's provoking vertex: `prepare.rs`).
///
/// A scene without specular, spot lights or textures gets no code for them: the source then
/// contains no `spot`, no `specular` and no texture sampling.
#[must_use]
pub fn shader_source(features: &Features, shading: Shading, model: LightModel) -> String {
    let lecture = matches!(model, LightModel::Lecture { .. });
    format!(
        "// cg-gpu: generated for {:?} shading, {} light model; enabled: {}\n{}",
        shading,
        if lecture { "lecture" } else { "OpenGL" },
        enabled(features).iter().map(|n| n.en.as_str()).collect::<Vec<_>>().join(", "),
        preprocess(TEMPLATE, &Flags::new(features, shading, model))
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flags(on: &[&'static str]) -> Flags {
        Flags(["a", "b", "c"].into_iter().map(|n| (n, on.contains(&n))).collect())
    }

    #[test]
    fn blocks_keep_their_lines_only_when_their_condition_holds() {
        let template =
            "//! doc\nx\n//#if a\nA\n//#if b && !c\nAB\n//#else\nnot AB\n//#endif\n//#endif\ny\n";
        assert_eq!(preprocess(template, &flags(&["a", "b"])), "x\nA\nAB\ny\n");
        assert_eq!(preprocess(template, &flags(&["a", "b", "c"])), "x\nA\nnot AB\ny\n");
        // An inner //#else never revives lines of an outer block that is off.
        assert_eq!(preprocess(template, &flags(&["b"])), "x\ny\n");
    }

    #[test]
    #[should_panic(expected = "unknown flag \"d\"")]
    fn an_unknown_flag_is_a_mistake_in_the_template() {
        let _ = preprocess("//#if d\n//#endif\n", &flags(&[]));
    }

    #[test]
    #[should_panic(expected = "not closed")]
    fn an_open_block_is_a_mistake_in_the_template() {
        let _ = preprocess("//#if a\n", &flags(&["a"]));
    }

    #[test]
    fn every_flag_of_the_template_is_known_and_every_known_flag_is_used() {
        let all = Flags::new(
            &Features::default(),
            Shading::Phong,
            LightModel::OpenGl { local_viewer: false },
        );
        let used: Vec<&str> = TEMPLATE
            .lines()
            .filter_map(|l| l.trim_start().strip_prefix("//#if "))
            .flat_map(|c| c.split("&&").map(|t| t.trim().trim_start_matches('!')))
            .collect();
        for name in &used {
            let _ = all.get(name); // panics on an unknown one
        }
        for (name, _) in &all.0 {
            assert!(used.contains(name), "flag {name} is never used in shader.wgsl");
        }
    }
}
