//! The view: the course's stage with the ground drawn square by square, as the course's
//! `display()` does, each corner with the student's texture coordinate, and the prepared image on
//! it — so a flipped, turned or misplaced region shows as mirrored or misplaced names and arrows.

use std::sync::OnceLock;

use cg_core::Rgb;
use cg_core::glam::{Vec2, Vec3};
use cg_core::light::Material;
use cg_core::mesh::Mesh;
use cg_core::product::MatrixProduct;
use cg_core::scene::{NormalSource, Object, Scene, TextureUse};
use cg_core::texture::{Sampler, TexEnv, Texture};
use cg_harness::Text;
use cg_harness::check::{Outcome, guarded};

use crate::prepared::prepared_image;
use crate::spec::{CORNER_STEPS, Spec};
use crate::{Impl, SQUARES};

/// The texture coordinates of every ground square's corners, `[i][j][corner]`, corners in the
/// order of [`CORNER_STEPS`]: what the report's texture-coordinate table lists.
pub type Coordinates = [[[Vec2; 4]; SQUARES as usize]; SQUARES as usize];

/// Calls the student's `tex_coords` for every square `(i, j)`, `i, j = 0…9`. Not guarded: a
/// panic in the student's code propagates (run it inside [`cg_harness::check::run`] or
/// [`guarded`]).
#[must_use]
pub fn coordinates(spec: &Spec, imp: &Impl) -> Coordinates {
    let mut table = [[[Vec2::ZERO; 4]; SQUARES as usize]; SQUARES as usize];
    for (i, column) in (0..SQUARES).zip(table.iter_mut()) {
        for (j, square) in (0..SQUARES).zip(column.iter_mut()) {
            *square = (imp.tex_coords)(spec, i, j);
        }
    }
    table
}

/// The course's ground as the course draws it: 10 × 10 squares of side 1 in the plane y = 0,
/// square `(i, j)` with its own four vertices at `(i·1 − 5, 0, j·1 − 5)` … in the order of
/// [`CORNER_STEPS`] (so corners on a block's edge can carry two texture coordinates), normal +Y,
/// split into the triangles `{0, 1, 2}` and `{0, 2, 3}` as [`cg_core::shapes::grid`] does.
#[must_use]
pub fn ground_mesh(coords: &Coordinates) -> Mesh {
    let mut positions = Vec::with_capacity(4 * (SQUARES * SQUARES) as usize);
    let mut uvs = Vec::with_capacity(positions.capacity());
    let mut faces = Vec::with_capacity(2 * (SQUARES * SQUARES) as usize);
    for j in 0..SQUARES {
        for i in 0..SQUARES {
            let base = positions.len() as u32;
            for (c, (di, dj)) in CORNER_STEPS.into_iter().enumerate() {
                let (x, z) = ((i + di) as f32 - 5.0, (j + dj) as f32 - 5.0);
                positions.push(Vec3::new(x, 0.0, z));
                uvs.push(coords[i as usize][j as usize][c]);
            }
            faces.push([base, base + 1, base + 2]);
            faces.push([base, base + 2, base + 3]);
        }
    }
    let count = positions.len();
    let mut mesh = Mesh::new(positions, faces);
    mesh.normals = Some(vec![Vec3::Y; count]);
    mesh.uvs = Some(uvs);
    mesh
}

/// The scene that shows `imp`'s result: the course's stage (window, camera, light) with the
/// ground textured by the prepared image at the student's coordinates (white ground under
/// GL_MODULATE, so the lighting shows as in the course program). `time_s` is not used.
///
/// While `tex_coords` is still a stub the ground is the course's own, untextured — the program
/// before the assignment — so there is always a picture; while `sampler` is still a stub,
/// OpenGL's default wrap mode (GL_REPEAT) and GL_LINEAR are used.
///
/// # Errors
/// A student's function that panicked, with its message.
pub fn view(spec: &Spec, imp: &Impl, time_s: f64) -> Result<Scene, Text> {
    let _ = time_s;
    let coords = match guarded(|| coordinates(spec, imp)) {
        Ok(c) => c,
        Err(Outcome::NotDone { .. }) => return Ok(cg_harness::course::ground_only()),
        Err(other) => return Err(other.of_function("a4.t2 tex_coords")),
    };
    let sampler = match guarded(imp.sampler) {
        Ok(s) => crate::core_sampler(s),
        Err(Outcome::NotDone { .. }) => Sampler::default(),
        Err(other) => return Err(other.of_function("a4.t3 sampler")),
    };
    Ok(textured_stage(&coords, sampler))
}

/// The kit's reference picture ([`cg_harness::Assignment::reference_view`]): [`view`]'s scene
/// with the coordinates of the `a4.t2` oracle (each square's corners from the region's corners,
/// blended in f64) and the sampler `a4.t3` asks for (GL_CLAMP_TO_EDGE both ways, GL_LINEAR).
#[must_use]
pub fn reference(spec: &Spec) -> Scene {
    use crate::spec::SpecOracle;
    let mut coords = [[[Vec2::ZERO; 4]; SQUARES as usize]; SQUARES as usize];
    for (i, column) in (0..SQUARES).zip(coords.iter_mut()) {
        for (j, square) in (0..SQUARES).zip(column.iter_mut()) {
            *square = spec.expected_square(i, j);
        }
    }
    let sampler = crate::Sampler {
        filter: crate::Filter::Bilinear,
        wrap_u: crate::Wrap::Clamp,
        wrap_v: crate::Wrap::Clamp,
    };
    textured_stage(&coords, crate::core_sampler(sampler))
}

/// The course's stage with the ground textured at `coords` through `sampler`.
fn textured_stage(coords: &Coordinates, sampler: Sampler) -> Scene {
    let mut scene = cg_harness::course::stage();
    scene.name = "a4-texture".to_owned();
    // Drawn once per process: a viewer calls this every frame.
    static IMAGE: OnceLock<Texture> = OnceLock::new();
    scene.textures = vec![IMAGE.get_or_init(prepared_image).clone()];
    scene.objects.push(Object {
        name: "ground".to_owned(),
        mesh: ground_mesh(coords),
        normals: NormalSource::Face,
        material: Material::from_color(Rgb::ONE),
        transform: MatrixProduct::identity(),
        texture: Some(TextureUse { texture: 0, sampler, env: TexEnv::Modulate }),
        weld: None,
        analytic: None,
    });
    scene
}
