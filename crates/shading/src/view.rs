//! The view: the course's stage with three of the student's spheres — flat, Gouraud, Phong from
//! left to right — shaded by the student's own `shade_pixel`, vertex normals and light-model
//! terms — and the kit's reference picture ([`reference()`]): the same view drawn with the kit's
//! own light model, vertex normals and shading rule in place of the student's functions.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{self, Attenuation, LightKind};
use cg_core::mesh::Mesh;
use cg_core::normals::{Weighting, vertex_normals};
use cg_core::optics::{self, Interface};
use cg_core::scene::Scene;
use cg_harness::Text;
use cg_harness::check::guarded;
use cg_raster::{Options, RenderError};
use cg_student::mesh::Mesh as StudentMesh;

use crate::render::{compose, gbuffer, saturate, screen};
use crate::scenes::{STAGE_SPHERES, material, sphere_mesh, stage_scene};
use crate::{Impl, Shading, Spec, kit_rule};

fn text(e: &RenderError) -> Text {
    e.text()
}

/// The light model term by term, each the student's where it is written (it returns without a
/// panic on a probe), otherwise the kit's.
struct Terms {
    ambient: fn(Rgb, Rgb) -> Rgb,
    diffuse: fn(Rgb, Rgb, Vec3, Vec3) -> Rgb,
    specular: fn(Rgb, Rgb, Vec3, Vec3, Vec3, f32) -> Rgb,
}

impl Terms {
    fn of(imp: &Impl) -> Terms {
        let (n, l, v) = (Vec3::Y, Vec3::new(0.6, 0.8, 0.0), Vec3::new(-0.6, 0.8, 0.0));
        let ambient = imp.ambient;
        let diffuse = imp.diffuse;
        let specular = imp.specular;
        Terms {
            ambient: if guarded(|| ambient(Rgb::ONE, Rgb::ONE)).is_ok() {
                ambient
            } else {
                light::ambient
            },
            diffuse: if guarded(|| diffuse(Rgb::ONE, Rgb::ONE, n, l)).is_ok() {
                diffuse
            } else {
                light::diffuse
            },
            specular: if guarded(|| specular(Rgb::ONE, Rgb::ONE, n, l, v, 10.0)).is_ok() {
                specular
            } else {
                light::specular_phong
            },
        }
    }
}

pub(crate) fn view(spec: &Spec, imp: &Impl) -> Result<Scene, Text> {
    let scene = stage_scene(spec);
    let g = gbuffer(&scene, scene.width, scene.height).map_err(|e| text(&e))?;
    // The ground and the background as the kit draws them (Gouraud, the course's default).
    let base = cg_raster::render(&scene, &Options::default()).map_err(|e| text(&e))?.image;

    let mesh = sphere_mesh(spec);
    let mut normals = (imp.vertex_normals)(&StudentMesh::from(&mesh));
    normals.resize(mesh.positions.len(), Vec3::ZERO);

    let terms = Terms::of(imp);
    let m = material(spec);
    let eye = scene.camera.eye_position();
    let lamp = scene.lights.first().map(|l| (l.kind.clone(), l.diffuse, l.specular));
    let ia = scene.global_ambient;
    let lit = |p: Vec3, n: Vec3| {
        let mut c = (terms.ambient)(ia, m.ka);
        if let Some((LightKind::Point { position }, diffuse, specular)) = &lamp {
            let l = (*position - p).normalize_or(n);
            let v = (eye - p).normalize_or(Vec3::Z);
            c += (terms.diffuse)(*diffuse, m.kd, n, l);
            c += (terms.specular)(*specular, m.ks, n, l, v, m.shininess);
        }
        saturate(c)
    };
    let modes = [Shading::Flat, Shading::Gouraud, Shading::Phong];
    let first_sphere = scene.objects.len() - STAGE_SPHERES.len();
    let image = compose(
        &base,
        &g,
        |f| f.object.checked_sub(first_sphere).and_then(|k| modes.get(k).copied()),
        |mode, f, pixel| {
            let mut pixel = *pixel;
            // The spheres are translated and scaled uniformly, so model-space normals point as
            // world-space normals do: the student's, as they are (a normal that is not unit
            // length shows).
            pixel.normals =
                f.vertices.map(|v| normals.get(v as usize).copied().unwrap_or(Vec3::ZERO));
            (imp.shade_pixel)(mode, &pixel, &lit)
        },
    );
    screen(&image, "s-view").map_err(|e| e.text())
}

/// The kit's own answer to every exercise of the set, each function a trusted oracle of the
/// checks: the light-model terms of [`cg_core::light`] (s.t1–s.t4), the plain and area-weighted
/// vertex normals of [`cg_core::normals`] (s.t5), the renderer's rule [`kit_rule`] (s.t6) and
/// [`cg_core::optics`] (s.t7, s.t8, with [`Interface`] for a ray from inside). Nothing in it comes
/// from a student's or the reference solutions' code.
fn trusted() -> Impl {
    Impl {
        ambient: light::ambient,
        diffuse: light::diffuse,
        specular: light::specular_phong,
        attenuation: |kc, kl, kq, d| {
            light::attenuation(Attenuation { constant: kc, linear: kl, quadratic: kq }, d)
        },
        spot_factor: |l, s, cutoff_deg, exponent| {
            light::spot_factor(l, s, cutoff_deg, exponent, None)
        },
        vertex_normals: |mesh| vertex_normals(&Mesh::from(mesh), Weighting::Uniform).normals,
        vertex_normals_area: |mesh| vertex_normals(&Mesh::from(mesh), Weighting::Area).normals,
        shade_pixel: kit_rule,
        reflect: optics::reflect,
        refract: |i, n, n1, n2| {
            let iface = Interface::at(i, n, n1, n2)?;
            optics::refract(i, iface.n, iface.eta)
        },
    }
}

/// The kit's reference picture for `spec`: what [`view`] shows for a correct answer — the stage
/// with the flat, Gouraud and Phong spheres lit by the kit's own light model, vertex normals
/// (the plain average) and shading rule ([`kit_rule`]), never by a student's or the reference
/// solutions' code. `time_s` is not used (the view is a still picture).
///
/// Should the stage fail to draw (never for the kit's own scenes), the stage scene itself, which
/// the renderer lights its own way.
#[must_use]
pub fn reference(spec: &Spec, time_s: f64) -> Scene {
    let _ = time_s;
    view(spec, &trusted()).unwrap_or_else(|_| stage_scene(spec))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_harness::VariantRng;

    /// The picture a scene of [`view`] shows, as the CPU rasterizer draws it.
    fn pixels(scene: &Scene) -> Vec<[u8; 4]> {
        let image = cg_raster::render(scene, &Options::default()).expect("the screen draws").image;
        image.to_rgba8()
    }

    /// The stubs as a student first gets them: every vertex normal straight up, every sphere
    /// pixel magenta.
    fn stubs() -> Impl {
        Impl {
            vertex_normals: |mesh| vec![Vec3::Y; mesh.positions.len()],
            shade_pixel: |_, _, _| Rgb::new(1.0, 0.0, 1.0),
            ..trusted()
        }
    }

    #[test]
    fn the_reference_shades_every_sphere_pixel_unlike_the_stubs() {
        let spec = crate::variant(&mut VariantRng::from_seed(11));
        let kit = pixels(&reference(&spec, 0.0));
        let stubs = pixels(&view(&spec, &stubs()).expect("the stubs' view draws"));
        let magenta = |p: &[[u8; 4]]| p.iter().filter(|&&c| c == [255, 0, 255, 255]).count();
        assert!(magenta(&stubs) > 1000, "the stubs colour the spheres magenta");
        assert_eq!(magenta(&kit), 0, "the reference shades every sphere pixel");
        assert_eq!(kit, pixels(&reference(&spec, 1.6)), "a still picture");
    }
}
