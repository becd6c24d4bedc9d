//! `a4.t3`, `sampler`: the wrap modes suit a region repeated by its coordinates (GL_CLAMP_TO_EDGE).

use cg_harness::check::Failure;
use cg_harness::text::t;

use crate::spec::{RegionOracle, Spec};
use crate::{Impl, Sampler, TexRange, Wrap};

pub(super) fn wrap(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let Sampler { filter: _, wrap_u, wrap_v } = (imp.sampler)();
    if (wrap_u, wrap_v) == (Wrap::Clamp, Wrap::Clamp) {
        return Ok(());
    }
    let name = |w: Wrap| match w {
        Wrap::Repeat => "Wrap::Repeat (GL_REPEAT)",
        Wrap::Clamp => "Wrap::Clamp (GL_CLAMP_TO_EDGE)",
    };
    let (axis, gl) = if wrap_u == Wrap::Clamp {
        ("wrap_v", "GL_TEXTURE_WRAP_T")
    } else {
        ("wrap_u", "GL_TEXTURE_WRAP_S")
    };
    let TexRange { s_min, s_max, t_min, t_max } = spec.region.range();
    let edge = |ja: &str, en: &str| Some(t(ja, en));
    let touches = if axis == "wrap_u" && s_max == 1.0 {
        edge(
            "右端（s = 1）。GL_REPEAT では列 A の色が線になって出る",
            "right edge (s = 1): with GL_REPEAT a line of column A shows along it",
        )
    } else if axis == "wrap_u" && s_min == 0.0 {
        edge(
            "左端（s = 0）。GL_LINEAR と GL_REPEAT では列 H の色が混ざる",
            "left edge (s = 0): with GL_LINEAR and GL_REPEAT column H bleeds in",
        )
    } else if axis == "wrap_v" && t_max == 1.0 {
        edge(
            "上端（t = 1）。GL_REPEAT では行 8 の色が線になって出る",
            "top edge (t = 1): with GL_REPEAT a line of row 8 shows along it",
        )
    } else if axis == "wrap_v" && t_min == 0.0 {
        edge(
            "下端（t = 0）。GL_LINEAR と GL_REPEAT では行 1 の色が混ざる",
            "bottom edge (t = 0): with GL_LINEAR and GL_REPEAT row 1 bleeds in",
        )
    } else {
        None
    };
    let mut cause = t(
        "GL_REPEAT が繰り返すのは画像全体で、画像の一部（範囲）は繰り返せない。この課題では繰り返しは座標で作り（a4.t2）、座標は範囲の中、0〜1 に収まる。GL_REPEAT のままだと、座標が画像の端（0 や 1）に来たところで反対側の端の色を拾う",
        "GL_REPEAT repeats the whole image, never a part of it: here the repeat is made by the coordinates (a4.t2), which stay inside the region, within 0…1. Left at GL_REPEAT, a coordinate on the image's edge (0 or 1) picks up the opposite edge",
    );
    if let Some(touch) = touches {
        cause.ja.push_str(&format!("。あなたの範囲は画像の{}", touch.ja));
        cause.en.push_str(&format!("; your region touches the image's {}", touch.en));
    }
    Err(Failure::new(
        "wrap_u = wrap_v = Wrap::Clamp (GL_CLAMP_TO_EDGE)",
        format!("wrap_u = {}, wrap_v = {}", name(wrap_u), name(wrap_v)),
    )
    .at(format!("sampler(): {axis} ({gl})"))
    .cause(cause)
    .hint(t(
        "Sampler { filter: …, wrap_u: Wrap::Clamp, wrap_v: Wrap::Clamp }（glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE) と T も同じ）",
        "Sampler { filter: …, wrap_u: Wrap::Clamp, wrap_v: Wrap::Clamp } (glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE), and the same for T)",
    )))
}
