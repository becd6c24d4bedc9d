//! WGSL generated per scene (「シーンに必要なものだけ」): the shader holds code only for the terms
//! of the light model, the light types and the texturing that the scene's
//! [`Features`] say it uses, for one shading mode and one light model.
//!
//! | shading | where [`shade`](#the-shade-function) runs | what is interpolated |
//! |---|---|---|
//! | [`Shading::Flat`] | vertex shader, at the face's centroid with the face normal (all three corners of a face carry the same values) | nothing (`@interpolate(flat)`) |
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
use cg_core::light::{LightModel, Specular};
use cg_core::scene::Shading;
use std::fmt::Write as _;

/// Which parts of the light model and the pipeline a shader built for `features` contains, as
/// short English names (for `cg render --gpu` to print). Reflection and transmission are never
/// in it: they need rays.
#[must_use]
pub fn enabled(features: &Features) -> Vec<&'static str> {
    let f = features;
    let mut out = Vec::new();
    let mut add = |on: bool, name: &'static str| {
        if on {
            out.push(name);
        }
    };
    add(f.emission, "emission");
    add(f.ambient, "ambient");
    add(f.diffuse, "diffuse");
    add(f.specular, "specular");
    add(f.directional, "directional lights");
    add(f.point, "point lights");
    add(f.spot, "spot lights");
    add(f.area, "area lights (as point-light samples)");
    add(f.attenuation, "attenuation");
    add(f.textures, "textures");
    add(f.local_viewer && f.specular, "local viewer");
    out
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

/// The WGSL source of the shader for a scene with `features`, drawn with `shading` under
/// `model`. Entry points `vs_main` and `fs_main`; bind group 0 holds the frame's uniforms
/// (binding 0) and lights (binding 1, a read-only storage array); bind group 1 the object's
/// uniforms (binding 0) and, only when `features.textures`, its texture (1) and sampler (2).
/// Vertex buffer 0: world position (location 0), shading normal (1), face normal (2), colour
/// (3), texture coordinate (4), face centroid (5).
///
/// A scene without specular, spot lights or textures gets no code for them: the source then
/// contains no `spot`, no `specular` and no texture sampling.
#[must_use]
pub fn shader_source(features: &Features, shading: Shading, model: LightModel) -> String {
    let f = features;
    let mut s = String::with_capacity(8192);
    let lecture = matches!(model, LightModel::Lecture { .. });
    let phong_specular = matches!(model, LightModel::Lecture { specular: Specular::Phong, .. });
    let _ = writeln!(
        s,
        "// cg-gpu: generated for {:?} shading, {} light model; enabled: {}",
        shading,
        if lecture { "lecture" } else { "OpenGL" },
        enabled(f).join(", ")
    );
    s.push_str(
        r"
struct Frame {
    view_proj: mat4x4<f32>,
    eye: vec4<f32>,
    backward: vec4<f32>,
    ambient: vec4<f32>,
    light_count: vec4<u32>,
};

struct Light {
    position: vec4<f32>,
    ambient: vec4<f32>,
    diffuse: vec4<f32>,
    highlight: vec4<f32>,
    attenuation: vec4<f32>,
    cone_axis: vec4<f32>,
    cone: vec4<f32>,
};

struct Object {
    ka: vec4<f32>,
    kd: vec4<f32>,
    ks: vec4<f32>,
    emission: vec4<f32>,
    flags: vec4<u32>,
};

@group(0) @binding(0) var<uniform> frame: Frame;
@group(0) @binding(1) var<storage, read> lights: array<Light>;
@group(1) @binding(0) var<uniform> object: Object;
",
    );
    if f.textures {
        s.push_str(
            r"@group(1) @binding(1) var tex: texture_2d<f32>;
@group(1) @binding(2) var tex_sampler: sampler;
",
        );
    }
    s.push_str(
        r"
struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) face_normal: vec3<f32>,
    @location(3) color: vec3<f32>,
    @location(4) uv: vec2<f32>,
    @location(5) centroid: vec3<f32>,
};

fn saturate3(c: vec3<f32>) -> vec3<f32> {
    return clamp(c, vec3<f32>(0.0), vec3<f32>(1.0));
}

fn positive(x: f32) -> f32 {
    return select(0.0, x, x > 0.0);
}
",
    );
    if f.specular {
        s.push_str(
            r"
// cosⁿ with the kit's rule: 0 where the cosine is ≤ 0, whatever n.
fn specular_power(c: f32, n: f32) -> f32 {
    if c > 0.0 {
        return pow(min(c, 1.0), positive(n));
    }
    return 0.0;
}

// V: towards the eye (local viewer) or the camera's backward axis (infinite viewer).
fn view_vector(p: vec3<f32>) -> vec3<f32> {
",
        );
        if f.local_viewer {
            s.push_str(
                r"    let to_eye = frame.eye.xyz - p;
    let len = length(to_eye);
    if len > 0.0 {
        return to_eye / len;
    }
",
            );
        }
        s.push_str("    return frame.backward.xyz;\n}\n");
    }
    if needs_spot(f) {
        // cone: x = 1 for a spot light, y = cos(cutoff), z = exponent, w = cos(inner) or 2 (none).
        // cone_axis.w = 0: a zero axis, the spot lights nothing.
        s.push_str(
            r"
fn spot_factor(light: Light, l: vec3<f32>) -> f32 {
    if light.cone_axis.w == 0.0 {
        return 0.0;
    }
    let cos_alpha = -dot(l, light.cone_axis.xyz);
    if cos_alpha < light.cone.y {
        return 0.0;
    }
    var factor = 1.0;
    if light.cone.z > 0.0 {
        factor = select(0.0, pow(min(cos_alpha, 1.0), light.cone.z), cos_alpha > 0.0);
    }
",
        );
        if lecture {
            s.push_str(
                r"    if light.cone.w <= 1.0 {
        let t = clamp((cos_alpha - light.cone.y) / (light.cone.w - light.cone.y), 0.0, 1.0);
        factor = factor * t * t * (3.0 - 2.0 * t);
    }
",
            );
        }
        s.push_str("    return factor;\n}\n");
    }

    // The light model.
    s.push_str(
        r"
fn shade(p: vec3<f32>, n: vec3<f32>, ka: vec3<f32>, kd: vec3<f32>) -> vec3<f32> {
    var c = vec3<f32>(0.0);
",
    );
    if f.emission {
        s.push_str("    c += object.emission.xyz;\n");
    }
    if f.ambient {
        s.push_str("    c += frame.ambient.xyz * ka;\n");
    }
    let per_light = f.diffuse || f.specular || (f.ambient && !lecture);
    if per_light {
        if f.specular {
            s.push_str("    let v = view_vector(p);\n");
        }
        s.push_str(
            r"    for (var i = 0u; i < frame.light_count.x; i = i + 1u) {
        let light = lights[i];
        var l = n;
",
        );
        if needs_positional(f) {
            s.push_str("        var d = 0.0;\n");
        }
        match (needs_positional(f), f.directional) {
            (true, true) => s.push_str(
                r"        if light.position.w != 0.0 {
            let to_light = light.position.xyz - p;
            let len = length(to_light);
            if len > 0.0 {
                l = to_light / len;
                d = len;
            }
        } else if any(light.position.xyz != vec3<f32>(0.0)) {
            l = light.position.xyz;
        }
",
            ),
            (true, false) => s.push_str(
                r"        let to_light = light.position.xyz - p;
        let len = length(to_light);
        if len > 0.0 {
            l = to_light / len;
            d = len;
        }
",
            ),
            _ => s.push_str(
                r"        if any(light.position.xyz != vec3<f32>(0.0)) {
            l = light.position.xyz;
        }
",
            ),
        }
        s.push_str("        var scale = 1.0;\n");
        if f.attenuation && needs_positional(f) {
            s.push_str(
                r"        if light.attenuation.w != 0.0 {
            let a = light.attenuation;
            scale = 1.0 / max(a.x + a.y * d + a.z * d * d, 1e-6);
        }
",
            );
        }
        if needs_spot(f) {
            s.push_str(
                r"        if light.cone.x != 0.0 {
            scale = scale * spot_factor(light, l);
        }
",
            );
        }
        s.push_str(
            r"        if scale == 0.0 {
            continue;
        }
        let n_dot_l = dot(n, l);
",
        );
        if f.ambient && !lecture {
            s.push_str("        c += scale * light.ambient.xyz * ka;\n");
        }
        if f.diffuse {
            s.push_str("        c += scale * light.diffuse.xyz * kd * positive(n_dot_l);\n");
        }
        if f.specular {
            if phong_specular {
                s.push_str(
                    r"        if n_dot_l > 0.0 {
            let r = reflect(-l, n);
            c += scale * light.highlight.xyz * object.ks.xyz * specular_power(dot(r, v), object.ks.w);
        }
",
                );
            } else {
                s.push_str(
                    r"        let h = l + v;
        let h_len = length(h);
        if n_dot_l > 0.0 && h_len > 0.0 {
            c += scale * light.highlight.xyz * object.ks.xyz * specular_power(dot(n, h / h_len), object.ks.w);
        }
",
                );
            }
        }
        s.push_str("    }\n");
    }
    s.push_str("    return c;\n}\n");

    // ka, kd: the vertex colour under colour-material, else the object's.
    s.push_str(
        r"
fn material_ka(color: vec3<f32>) -> vec3<f32> {
    return select(object.ka.xyz, color, object.flags.x != 0u);
}

fn material_kd(color: vec3<f32>) -> vec3<f32> {
    return select(object.kd.xyz, color, object.flags.x != 0u);
}
",
    );
    // `lit`: flags.y (0 under GL_REPLACE, only with textures).
    let lit_check = if f.textures { "object.flags.y != 0u" } else { "true" };

    // Vertex output.
    s.push_str("\nstruct VertexOut {\n    @builtin(position) clip: vec4<f32>,\n");
    match shading {
        Shading::Flat => s.push_str("    @location(0) @interpolate(flat) color: vec3<f32>,\n"),
        Shading::Gouraud => s.push_str("    @location(0) color: vec3<f32>,\n"),
        Shading::Phong => s.push_str(
            r"    @location(0) color: vec3<f32>,
    @location(1) world: vec3<f32>,
    @location(2) normal: vec3<f32>,
    @location(3) @interpolate(flat) face_normal: vec3<f32>,
",
        ),
    }
    if f.textures {
        s.push_str("    @location(4) uv: vec2<f32>,\n");
    }
    s.push_str("};\n");

    s.push_str(
        r"
@vertex
fn vs_main(in: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = frame.view_proj * vec4<f32>(in.position, 1.0);
",
    );
    match shading {
        Shading::Flat => {
            let _ = writeln!(
                s,
                "    out.color = vec3<f32>(1.0);\n    if {lit_check} {{\n        out.color = saturate3(shade(in.centroid, in.normal, material_ka(in.color), material_kd(in.color)));\n    }}"
            );
        }
        Shading::Gouraud => {
            let _ = writeln!(
                s,
                "    out.color = select(vec3<f32>(1.0), in.color, object.flags.x != 0u);\n    if {lit_check} {{\n        out.color = saturate3(shade(in.position, in.normal, material_ka(in.color), material_kd(in.color)));\n    }}"
            );
        }
        Shading::Phong => s.push_str(
            r"    out.color = in.color;
    out.world = in.position;
    out.normal = in.normal;
    out.face_normal = in.face_normal;
",
        ),
    }
    if f.textures {
        s.push_str("    out.uv = in.uv;\n");
    }
    s.push_str("    return out;\n}\n");

    s.push_str(
        r"
@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
",
    );
    match shading {
        Shading::Flat | Shading::Gouraud => s.push_str("    var color = in.color;\n"),
        Shading::Phong => {
            let _ = writeln!(
                s,
                r"    var color = vec3<f32>(1.0);
    if {lit_check} {{
        // The interpolated normal, renormalised; the face normal where it vanishes.
        var n = in.normal;
        let len = length(n);
        if len > 1e-6 {{
            n = n / len;
        }} else {{
            n = in.face_normal;
        }}
        color = saturate3(shade(in.world, n, material_ka(in.color), material_kd(in.color)));
    }}"
            );
        }
    }
    if f.textures {
        // flags.z: textured; flags.w: 0 modulate, 1 replace.
        s.push_str(
            r"    if object.flags.z != 0u {
        let texel = textureSampleLevel(tex, tex_sampler, in.uv, 0.0).xyz;
        color = select(color * texel, texel, object.flags.w != 0u);
    }
",
        );
    }
    s.push_str("    return vec4<f32>(saturate3(color), 1.0);\n}\n");
    s
}
