//! The generated WGSL: only what the scene needs, and every variant valid (naga, no GPU needed).

use std::path::Path;

use cg_core::features::Features;
use cg_core::light::{LightModel, Specular};
use cg_core::scene::Shading;
use cg_gpu::{enabled, shader_source};

const SHADINGS: [Shading; 3] = [Shading::Flat, Shading::Gouraud, Shading::Phong];
const MODELS: [LightModel; 3] = [
    LightModel::Lecture { specular: Specular::Phong, local_viewer: false },
    LightModel::Lecture { specular: Specular::Blinn, local_viewer: true },
    LightModel::OpenGl { local_viewer: false },
];

fn validate(source: &str, what: &str) {
    let module = naga::front::wgsl::parse_str(source)
        .unwrap_or_else(|e| panic!("{what}: {}\n{source}", e.emit_to_string(source)));
    naga::valid::Validator::new(
        naga::valid::ValidationFlags::all(),
        naga::valid::Capabilities::empty(),
    )
    .validate(&module)
    .unwrap_or_else(|e| panic!("{what}: {}\n{source}", e.emit_to_string(source)));
}

fn scene(name: &str) -> cg_core::scene::Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes").join(name);
    cg_scene::load(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn a_scene_without_specular_spots_or_textures_gets_no_code_for_them() {
    // The course's sample: one point light, every k_s 0, no texture.
    let features = scene("course-sample.toml").features();
    assert!(!features.specular && !features.spot && !features.area && !features.textures);
    for shading in SHADINGS {
        for model in MODELS {
            let src = shader_source(&features, shading, model);
            for word in ["spot", "specular", "object.ks", "reflect(", "texture", "tex_sampler"] {
                assert!(!src.contains(word), "{shading:?} {model:?} contains {word:?}:\n{src}");
            }
            assert!(src.contains("light.diffuse"), "the diffuse term is there");
            validate(&src, "course-sample");
        }
    }
    let names: Vec<String> = enabled(&features).into_iter().map(|n| n.en).collect();
    let names: Vec<&str> = names.iter().map(String::as_str).collect();
    assert!(names.contains(&"diffuse") && names.contains(&"point lights"), "{names:?}");
    assert!(!names.contains(&"specular") && !names.contains(&"textures"), "{names:?}");
    // In Japanese, the words `cg render` prints for every renderer (it printed the English).
    let ja: Vec<String> = enabled(&features).into_iter().map(|n| n.ja).collect();
    assert!(ja.contains(&"拡散反射光".to_owned()) && ja.contains(&"点光源".to_owned()), "{ja:?}");
    assert!(ja.iter().all(|n| !n.chars().any(|c| c.is_ascii_lowercase())), "{ja:?}");
}

#[test]
fn with_specular_spots_and_textures_the_code_is_there() {
    let features = Features {
        ambient: true,
        diffuse: true,
        specular: true,
        spot: true,
        textures: true,
        ..Features::default()
    };
    for shading in SHADINGS {
        let src = shader_source(&features, shading, MODELS[0]);
        assert!(src.contains("spot_factor("), "{src}");
        assert!(src.contains("specular_power(dot(r, v)"), "Phong's (R·V)ⁿ: {src}");
        assert!(src.contains("textureSampleLevel(tex, tex_sampler"), "{src}");
        let blinn = shader_source(&features, shading, MODELS[2]);
        assert!(blinn.contains("specular_power(dot(n, h / h_len)"), "Blinn's (N·H)ⁿ: {blinn}");
    }
    // The scenes that ship with the kit: spot-specular has a spot light and specular.
    let spot = scene("spot-specular.toml").features();
    let src = shader_source(&spot, Shading::Phong, scene("spot-specular.toml").light_model);
    assert!(spot.spot && src.contains("spot_factor(") && src.contains("specular_power("));
    let textured = scene("textured-ground.toml");
    let src = shader_source(&textured.features(), Shading::Gouraud, textured.light_model);
    assert!(src.contains("textureSampleLevel("));
}

#[test]
fn every_generated_variant_is_valid_wgsl() {
    // Ambient, diffuse and emission always on; every subset of the rest.
    let mut count = 0;
    for bits in 0u32..1 << 8 {
        let bit = |i: u32| bits & (1 << i) != 0;
        let features = Features {
            ambient: true,
            diffuse: true,
            emission: true,
            specular: bit(0),
            spot: bit(1),
            area: bit(2),
            directional: bit(3),
            point: bit(4),
            attenuation: bit(5),
            textures: bit(6),
            local_viewer: bit(7),
            ..Features::default()
        };
        for shading in SHADINGS {
            for model in MODELS {
                validate(&shader_source(&features, shading, model), &format!("{features:?}"));
                count += 1;
            }
        }
    }
    // And a scene with nothing at all (no lights, no terms).
    for shading in SHADINGS {
        for model in MODELS {
            validate(&shader_source(&Features::default(), shading, model), "nothing");
        }
    }
    assert_eq!(count, 256 * 9);
}
