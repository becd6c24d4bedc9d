//! The view: the course's stage with three of the student's spheres — flat, Gouraud, Phong from
//! left to right — shaded by the student's own `shade_pixel`, vertex normals and light-model
//! terms.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::{self, LightKind};
use cg_core::scene::Scene;
use cg_harness::Text;
use cg_harness::check::guarded;
use cg_raster::{Options, RenderError};
use cg_student::mesh::Mesh as StudentMesh;

use crate::render::{compose, gbuffer, saturate, screen};
use crate::scenes::{STAGE_SPHERES, material, sphere_mesh, stage_scene};
use crate::{Impl, Shading, Spec};

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
