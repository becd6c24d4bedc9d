use super::*;

fn light(kind: LightKind, attenuation: Attenuation) -> Light {
    Light { kind, ambient: Rgb::splat(0.1), diffuse: Rgb::ONE, specular: Rgb::ONE, attenuation }
}

/// Counts what `shade_with_visibility_counted` does for one point lit from above.
fn counted(lights: &[Light], material: &Material, visible: f32) -> (Terms, LightCounts) {
    let mut counts = LightCounts::default();
    let terms = shade_with_visibility_counted(
        LightModel::OpenGl { local_viewer: false },
        Rgb::splat(0.2),
        lights,
        material,
        Vec3::ZERO,
        Vec3::Y,
        Vec3::Y,
        |_, _, _| visible,
        &mut counts,
    );
    (terms, counts)
}

#[test]
fn counts_are_what_the_light_model_did() {
    let attenuated = Attenuation { constant: 1.0, linear: 0.1, quadratic: 0.0 };
    let lights = [
        light(LightKind::Directional { to_light: Vec3::Y }, attenuated),
        light(LightKind::Point { position: Vec3::new(0.0, 4.0, 0.0) }, Attenuation::default()),
        light(LightKind::Point { position: Vec3::new(1.0, 4.0, 0.0) }, attenuated),
        light(
            LightKind::Area {
                corner: Vec3::new(-1.0, 5.0, -1.0),
                edge_u: Vec3::X * 2.0,
                edge_v: Vec3::Z * 2.0,
                samples: [2, 3],
            },
            attenuated,
        ),
    ];
    let shiny = Material { ks: Rgb::ONE, shininess: 8.0, ..Material::default() };
    let (terms, c) = counted(&lights, &shiny, 1.0);
    assert_eq!(c.evaluations, 1);
    assert_eq!(c.lights, 3 + 6, "an area light counts its 2 × 3 samples");
    assert_eq!(c.attenuations, 1 + 6, "not the directional light, not the default (1, 0, 0)");
    assert_eq!(c.spot_factors, 6, "area-light samples are spot lights facing down");
    assert_eq!((c.visibility_queries, c.diffuse, c.specular), (9, 9, 9));
    // The same terms as the uncounted function.
    let plain = shade(
        LightModel::OpenGl { local_viewer: false },
        Rgb::splat(0.2),
        &lights,
        &shiny,
        Vec3::ZERO,
        Vec3::Y,
        Vec3::Y,
    );
    assert_eq!(terms, plain);

    // k_s = 0: no specular term is computed at all.
    let (_, c) = counted(&lights, &Material::default(), 1.0);
    assert_eq!((c.diffuse, c.specular), (9, 0));
    // Shadowed: asked, but neither term is computed.
    let (_, c) = counted(&lights, &shiny, 0.0);
    assert_eq!((c.visibility_queries, c.diffuse, c.specular), (9, 0, 0));
    // A spot light pointing away: its factor is 0, so it is never asked about.
    let away = light(
        LightKind::Spot {
            position: Vec3::new(0.0, 4.0, 0.0),
            direction: Vec3::Y,
            cutoff_deg: 30.0,
            exponent: 0.0,
            inner_deg: None,
        },
        Attenuation::default(),
    );
    let (_, c) = counted(&[away], &shiny, 1.0);
    assert_eq!((c.spot_factors, c.visibility_queries, c.specular), (1, 0, 0));
    // Counts add up.
    let mut sum = c;
    sum += c;
    assert_eq!(sum.spot_factors, 2);
}

#[test]
fn with_color_sets_ka_and_kd_and_keeps_the_rest() {
    let m = Material { ks: Rgb::ONE, shininess: 5.0, kr: Rgb::splat(0.5), ..Material::default() };
    let c = Rgb::new(0.1, 0.2, 0.3);
    let colored = m.with_color(Some(c));
    assert_eq!((colored.ka, colored.kd), (c, c));
    assert_eq!((colored.ks, colored.shininess, colored.kr), (m.ks, m.shininess, m.kr));
    assert_eq!(m.with_color(None), m);
}
