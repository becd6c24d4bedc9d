//! The kit's shader, one source for every scene. Lines between `//#if FLAGS` and `//#endif`
//! (with an optional `//#else`) stay only when every flag holds (`!flag`: when it does not);
//! shader.rs sets the flags from the scene (only what the scene needs) and drops the rest, so a
//! shader holds no code for a term, light type or sampling the scene does not use. Flags:
//! the shading mode (flat, gouraud, phong), the light model (lecture; phong_specular for the
//! lecture's (R·V)ⁿ), and the scene's features (emission, ambient, diffuse, specular,
//! local_viewer, directional, positional, spot, attenuation, textures), with per_light (some term
//! sums over the lights) and opengl_ambient (OpenGL's per-light ambient).

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
//#if textures
@group(1) @binding(1) var tex: texture_2d<f32>;
@group(1) @binding(2) var tex_sampler: sampler;
//#endif

struct VertexIn {
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) face_normal: vec3<f32>,
    @location(3) color: vec3<f32>,
    @location(4) uv: vec2<f32>,
    @location(5) flat_at: vec3<f32>,
};

fn saturate3(c: vec3<f32>) -> vec3<f32> {
    return clamp(c, vec3<f32>(0.0), vec3<f32>(1.0));
}

fn positive(x: f32) -> f32 {
    return select(0.0, x, x > 0.0);
}

// |v| where v·v would leave f32 (a point light 1e20 away, a sun: its squared distance is beyond
// f32's range and `length` would give infinity, so L would be 0): v scaled by its largest
// component first. Within 1e-18..1e18 it is `length(v)` itself.
fn far_length(v: vec3<f32>) -> f32 {
    let m = max(abs(v.x), max(abs(v.y), abs(v.z)));
    if m > 1e18 || (m < 1e-18 && m > 0.0) {
        return m * length(v / m);
    }
    return length(v);
}
//#if specular

// cosⁿ with the kit's rule: 0 where the cosine is ≤ 0, whatever n.
fn specular_power(c: f32, n: f32) -> f32 {
    if c > 0.0 {
        return pow(min(c, 1.0), positive(n));
    }
    return 0.0;
}

// V: towards the eye (local viewer) or the camera's backward axis (infinite viewer).
fn view_vector(p: vec3<f32>) -> vec3<f32> {
//#if local_viewer
    let to_eye = frame.eye.xyz - p;
    let len = far_length(to_eye);
    if len > 0.0 {
        return to_eye / len;
    }
//#endif
    return frame.backward.xyz;
}
//#endif
//#if spot

// cone: x = 1 for a spot light, y = cos(cutoff), z = exponent, w = cos(inner) or 2 (none).
// cone_axis.w = 0: a zero axis, the spot lights nothing. An area light's samples are spot
// lights with a 90° cone (they shine to the front side only).
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
//#if lecture
    // The lecture's soft edge between the inner and the outer cone (smoothstep).
    if light.cone.w <= 1.0 {
        let t = clamp((cos_alpha - light.cone.y) / (light.cone.w - light.cone.y), 0.0, 1.0);
        factor = factor * t * t * (3.0 - 2.0 * t);
    }
//#endif
    return factor;
}
//#endif

// The light model at world point p with unit normal n: the same equations as
// cg_core::light::shade, in f32.
fn shade(p: vec3<f32>, n: vec3<f32>, ka: vec3<f32>, kd: vec3<f32>) -> vec3<f32> {
    var c = vec3<f32>(0.0);
//#if emission
    c += object.emission.xyz;
//#endif
//#if ambient
    c += frame.ambient.xyz * ka;
//#endif
//#if per_light
//#if specular
    let v = view_vector(p);
//#endif
    for (var i = 0u; i < frame.light_count.x; i = i + 1u) {
        let light = lights[i];
        var l = n;
//#if positional
        var d = 0.0;
//#endif
//#if positional && directional
        if light.position.w != 0.0 {
            let to_light = light.position.xyz - p;
            let len = far_length(to_light);
            if len > 0.0 {
                l = to_light / len;
                d = len;
            }
        } else if any(light.position.xyz != vec3<f32>(0.0)) {
            l = light.position.xyz;
        }
//#endif
//#if positional && !directional
        let to_light = light.position.xyz - p;
        let len = far_length(to_light);
        if len > 0.0 {
            l = to_light / len;
            d = len;
        }
//#endif
//#if !positional
        if any(light.position.xyz != vec3<f32>(0.0)) {
            l = light.position.xyz;
        }
//#endif
        var scale = 1.0;
//#if attenuation
        if light.attenuation.w != 0.0 {
            let a = light.attenuation;
            scale = 1.0 / max(a.x + a.y * d + a.z * d * d, 1e-6);
        }
//#endif
//#if spot
        if light.cone.x != 0.0 {
            scale = scale * spot_factor(light, l);
        }
//#endif
        if scale == 0.0 {
            continue;
        }
        let n_dot_l = dot(n, l);
//#if opengl_ambient
        c += scale * light.ambient.xyz * ka;
//#endif
//#if diffuse
        c += scale * light.diffuse.xyz * kd * positive(n_dot_l);
//#endif
//#if specular && phong_specular
        // Phong: (R·V)ⁿ.
        if n_dot_l > 0.0 {
            let r = reflect(-l, n);
            c += scale * light.highlight.xyz * object.ks.xyz * specular_power(dot(r, v), object.ks.w);
        }
//#endif
//#if specular && !phong_specular
        // Blinn: (N·H)ⁿ.
        let h = l + v;
        let h_len = length(h);
        if n_dot_l > 0.0 && h_len > 0.0 {
            c += scale * light.highlight.xyz * object.ks.xyz * specular_power(dot(n, h / h_len), object.ks.w);
        }
//#endif
    }
//#endif
    return c;
}

// ka, kd: the vertex colour under colour-material (flags.x), else the object's.
fn material_ka(color: vec3<f32>) -> vec3<f32> {
    return select(object.ka.xyz, color, object.flags.x != 0u);
}

fn material_kd(color: vec3<f32>) -> vec3<f32> {
    return select(object.kd.xyz, color, object.flags.x != 0u);
}

// Whether the object is lit: flags.y is 0 under GL_REPLACE, which only an image can set.
fn lit() -> bool {
//#if textures
    return object.flags.y != 0u;
//#else
    return true;
//#endif
}

struct VertexOut {
    @builtin(position) clip: vec4<f32>,
//#if flat
    @location(0) @interpolate(flat) color: vec3<f32>,
//#endif
//#if gouraud
    @location(0) color: vec3<f32>,
//#endif
//#if phong
    @location(0) color: vec3<f32>,
    @location(1) world: vec3<f32>,
    @location(2) normal: vec3<f32>,
    @location(3) @interpolate(flat) face_normal: vec3<f32>,
//#endif
//#if textures
    @location(4) uv: vec2<f32>,
//#endif
};

@vertex
fn vs_main(in: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.clip = frame.view_proj * vec4<f32>(in.position, 1.0);
//#if flat
    // Flat: once per face. Every corner of a face carries the same point, normal and colour —
    // the lecture's model: the centroid, the face normal, the mean colour; OpenGL's (GL_FLAT):
    // the face's last corner with its own normal and colour — so the colour is the same
    // whichever corner @interpolate(flat) takes it from.
    out.color = vec3<f32>(1.0);
    if lit() {
        out.color = saturate3(shade(in.flat_at, in.normal, material_ka(in.color), material_kd(in.color)));
    }
//#endif
//#if gouraud
    // Gouraud: per vertex, clamped; the colour is interpolated.
    out.color = select(vec3<f32>(1.0), in.color, object.flags.x != 0u);
    if lit() {
        out.color = saturate3(shade(in.position, in.normal, material_ka(in.color), material_kd(in.color)));
    }
//#endif
//#if phong
    // Phong: the position and normal are interpolated and lit per pixel.
    out.color = in.color;
    out.world = in.position;
    out.normal = in.normal;
    out.face_normal = in.face_normal;
//#endif
//#if textures
    out.uv = in.uv;
//#endif
    return out;
}

@fragment
fn fs_main(in: VertexOut) -> @location(0) vec4<f32> {
//#if !phong
    var color = in.color;
//#endif
//#if phong
    var color = vec3<f32>(1.0);
    if lit() {
        // The interpolated normal, renormalised; the face normal where it vanishes.
        var n = in.normal;
        let len = length(n);
        if len > 1e-6 {
            n = n / len;
        } else {
            n = in.face_normal;
        }
        color = saturate3(shade(in.world, n, material_ka(in.color), material_kd(in.color)));
    }
//#endif
//#if textures
    // flags.z: textured; flags.w: 0 modulate, 1 replace.
    if object.flags.z != 0u {
        let texel = textureSampleLevel(tex, tex_sampler, in.uv, 0.0).xyz;
        color = select(color * texel, texel, object.flags.w != 0u);
    }
//#endif
    return vec4<f32>(saturate3(color), 1.0);
}
