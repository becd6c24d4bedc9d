//! The lights (`[[lights]]`) and the materials (`[materials.<name>]`, an object's own) of a
//! scene file.

use std::collections::HashMap;

use cg_core::Rgb;
use cg_core::light::{Attenuation, Light, LightKind, Material};
use cg_core::math::{cross_f64, try_normalize};

use crate::error::{ErrorKind, Expected, Rule, SceneError};
use crate::reader::{Table, Value};

use super::checked_name;

/// Most point lights along one edge of an area light.
const MAX_AREA_SAMPLES: u32 = 256;

#[derive(Clone, Copy)]
enum LightType {
    Directional,
    Point,
    Spot,
    Area,
}

pub(super) fn read_light(t: &Table<'_>) -> Result<Light, SceneError> {
    let kind = t.require("kind")?.choice(&[
        ("directional", LightType::Directional),
        ("point", LightType::Point),
        ("spot", LightType::Spot),
        ("area", LightType::Area),
    ])?;
    let common = ["kind", "ambient", "diffuse", "specular"];
    let keys: &[&str] = match kind {
        LightType::Directional => &["to_light"],
        LightType::Point => &["position", "attenuation"],
        LightType::Spot => {
            &["position", "direction", "cutoff_deg", "exponent", "inner_deg", "attenuation"]
        }
        LightType::Area => &["corner", "edge_u", "edge_v", "samples", "attenuation"],
    };
    t.only(&[&common[..], keys].concat())?;
    let kind = match kind {
        LightType::Directional => {
            LightKind::Directional { to_light: t.require("to_light")?.direction()? }
        }
        LightType::Point => LightKind::Point { position: t.require("position")?.vec3()? },
        LightType::Spot => {
            let cutoff_deg = t.require("cutoff_deg")?.f32(Rule::SpotCutoff)?;
            let inner_deg = t.optional("inner_deg", |v| {
                let inner = v.f32(Rule::NonNegative)?;
                if cutoff_deg > 90.0 {
                    Err(v.bad(Rule::InnerNeedsCone))
                } else if inner <= cutoff_deg {
                    Ok(inner)
                } else {
                    Err(v.bad(Rule::NotAbove { key: "cutoff_deg", value: f64::from(cutoff_deg) }))
                }
            })?;
            LightKind::Spot {
                position: t.require("position")?.vec3()?,
                direction: t.require("direction")?.direction()?,
                cutoff_deg,
                exponent: t.or("exponent", 0.0, |v| v.f32(Rule::NonNegative))?,
                inner_deg,
            }
        }
        LightType::Area => {
            let edge_u = t.require("edge_u")?.vec3()?;
            let edge_v_value = t.require("edge_v")?;
            let edge_v = edge_v_value.vec3()?;
            // The renderers take the light's axis as this, in f32: edges whose cross product is
            // 0 or ∞ there (1e-23 long, or 2e19) would have no axis, and the light would shine
            // both ways without a word.
            if try_normalize(cross_f64(edge_u, edge_v)).is_none() {
                return Err(edge_v_value.bad(Rule::NonZeroArea));
            }
            let [nu, nv] = t.require("samples")?.array_of(Expected::Samples)?;
            let count = |v: Value<'_>| {
                // In 1..=MAX_AREA_SAMPLES, so the cast is exact.
                v.integer(1, MAX_AREA_SAMPLES.into()).map(|n| n as u32)
            };
            LightKind::Area {
                corner: t.require("corner")?.vec3()?,
                edge_u,
                edge_v,
                samples: [count(nu)?, count(nv)?],
            }
        }
    };
    Ok(Light {
        kind,
        // GL_LIGHT0's defaults.
        ambient: t.or("ambient", Rgb::ZERO, Value::color)?,
        diffuse: t.or("diffuse", Rgb::ONE, Value::color)?,
        specular: t.or("specular", Rgb::ONE, Value::color)?,
        attenuation: t.or("attenuation", Attenuation::default(), read_attenuation)?,
    })
}

fn read_attenuation(v: &Value<'_>) -> Result<Attenuation, SceneError> {
    let [kc, kl, kq] = v.array_of(Expected::Attenuation)?;
    let [constant, linear, quadratic] = [kc, kl, kq].map(|k| k.f32(Rule::NonNegative));
    let a = Attenuation { constant: constant?, linear: linear?, quadratic: quadratic? };
    if a.constant == 0.0 && a.linear == 0.0 && a.quadratic == 0.0 {
        return Err(v.bad(Rule::SomeAttenuation));
    }
    Ok(a)
}

pub(super) fn read_materials(t: &Table<'_>) -> Result<HashMap<String, Material>, SceneError> {
    t.entries()
        .into_iter()
        .map(|(name, v)| Ok((checked_name(name, &v)?, read_material(&v.table()?)?)))
        .collect()
}

/// A material table: `color`, or `ka`/`kd`, and the rest; [`Material::default`] elsewhere.
pub(super) fn read_material(t: &Table<'_>) -> Result<Material, SceneError> {
    t.only(&["color", "ka", "kd", "ks", "shininess", "kr", "kt", "eta", "emission"])?;
    let base = match t.get("color") {
        Some(color) => {
            if let Some((other, v)) = ["ka", "kd"].into_iter().find_map(|k| Some((k, t.get(k)?))) {
                return Err(v.error(ErrorKind::ColorWithReflectance { other }));
            }
            Material::from_color(color.color()?)
        }
        None => Material::default(),
    };
    let material = Material {
        ka: t.or("ka", base.ka, Value::color)?,
        kd: t.or("kd", base.kd, Value::color)?,
        ks: t.or("ks", base.ks, Value::color)?,
        shininess: t.or("shininess", base.shininess, |v| v.f32(Rule::NonNegative))?,
        kr: t.or("kr", base.kr, Value::color)?,
        kt: t.or("kt", base.kt, Value::color)?,
        eta: t.or("eta", base.eta, |v| v.f32(Rule::Positive))?,
        emission: t.or("emission", base.emission, Value::color)?,
    };
    check_reflectance_sum(t, &material)?;
    Ok(material)
}

/// k_r + k_t ≤ 1 in every channel (energy conservation: what a surface mirrors and transmits
/// cannot exceed what reaches it). Summed in f64 from the f32 values, with 1e-6 of room for the
/// decimal values that make exactly 1 (`kr = 0.1, kt = 0.9`) but not in binary. The error is at
/// `kt`, or at `kr` when `kt` is not written.
fn check_reflectance_sum(t: &Table<'_>, m: &Material) -> Result<(), SceneError> {
    for channel in 0..3 {
        let (kr, kt) = (m.kr[channel], m.kt[channel]);
        if f64::from(kr) + f64::from(kt) > 1.0 + 1e-6 {
            let kind = ErrorKind::ReflectanceSum { channel, kr, kt };
            return Err(match t.get("kt").or_else(|| t.get("kr")) {
                Some(v) => v.error(kind),
                None => t.error(kind),
            });
        }
    }
    Ok(())
}
