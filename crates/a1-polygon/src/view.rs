//! The view: the student's polyhedron on the course's stage, lit with the student's own normals.

use cg_core::Rgb;
use cg_core::glam::Vec3;
use cg_core::light::Material;
use cg_core::mesh::Mesh;
use cg_core::product::MatrixProduct;
use cg_core::scene::{NormalSource, Object, Scene};
use cg_harness::check::{Outcome, guarded};
use cg_harness::text::{Text, t};

use crate::{Impl, Spec};

/// The model's colour (glColor3f with colour material): the kit's colour for the course's
/// pyramid.
pub const MODEL_COLOR: Rgb = Rgb::new(1.0, 0.6, 0.2);

/// The scene that shows `imp`'s model (time plays no part): the course's window, camera, light
/// and ground ([`cg_harness::course::ground_only`]) and the student's mesh, placed by their
/// `model_transform`, coloured [`MODEL_COLOR`], every face drawn flat with **the student's own
/// normal** at its three corners ([`NormalSource::Given`]) — so a wrong normal lights its face
/// wrongly, and a face wound the wrong way is culled (a hole) as in the course's program.
///
/// `vertices` and `faces` are called directly (a stub's `todo!()` reaches the caller, which
/// says "not done yet"). While `face_normals` is still a stub, each face gets its derived
/// normal ([`NormalSource::Face`]); while `model_transform` is, the model stands at the world's
/// origin unturned.
///
/// # Errors
/// What keeps the model from being drawn, in words for the student: a face that refers to a
/// missing vertex, a non-finite position, a normal list whose length is not the number of
/// faces, a normal without direction, a transform that is not finite, or a panic in
/// `face_normals` or `model_transform`.
pub fn view(spec: &Spec, imp: &Impl, time_s: f64) -> Result<Scene, Text> {
    let _ = time_s;
    let mesh = Mesh::new((imp.vertices)(spec), (imp.faces)(spec));
    if let Err(e) = mesh.check_indices() {
        return Err(e.text());
    }
    let normals = match guarded(|| (imp.face_normals)(spec)) {
        Ok(n) => Some(n),
        Err(Outcome::NotDone { .. }) => None,
        Err(other) => return Err(other.of_function("face_normals")),
    };
    let transform = match guarded(|| MatrixProduct::from((imp.model_transform)(spec))) {
        Ok(p) => p,
        Err(Outcome::NotDone { .. }) => MatrixProduct::identity(),
        Err(other) => return Err(other.of_function("model_transform")),
    };
    if let Err(e) = transform.matrix() {
        return Err(Text::new(
            format!("model_transform: {}", e.text().ja),
            format!("model_transform: {}", e.text().en),
        ));
    }
    model_scene(&mesh, normals.as_deref(), transform)
}

/// The course's stage with `mesh` placed by `transform`, each face lit with its `normals`
/// (its derived normal where there are none).
fn model_scene(
    mesh: &Mesh,
    normals: Option<&[Vec3]>,
    transform: MatrixProduct,
) -> Result<Scene, Text> {
    let (mesh, source) = match normals {
        None => (mesh.clone(), NormalSource::Face),
        Some(normals) => (with_given_normals(mesh, normals)?, NormalSource::Given),
    };
    let mut scene = cg_harness::course::ground_only();
    scene.name = format!("{}-view", crate::ID);
    scene.objects.push(Object {
        name: "model".to_owned(),
        mesh,
        normals: source,
        material: Material::from_color(MODEL_COLOR),
        transform,
        texture: None,
        weld: None,
        analytic: None,
    });
    Ok(scene)
}

/// `mesh` split face by face (three new vertices per face, F0's first), each corner carrying
/// its face's given normal (as one glNormal3f per face between glBegin and glEnd).
fn with_given_normals(mesh: &Mesh, normals: &[Vec3]) -> Result<Mesh, Text> {
    if normals.len() != mesh.faces.len() {
        return Err(Text::new(
            format!(
                "face_normals が {} 個の法線を返しましたが、面は {} 個です（1 面に 1 つ）",
                normals.len(),
                mesh.faces.len()
            ),
            format!(
                "face_normals returned {} normals for {} faces (one per face)",
                normals.len(),
                mesh.faces.len()
            ),
        ));
    }
    if let Some(f) = normals.iter().position(|n| !(n.is_finite() && n.length() > 0.0)) {
        return Err(t(
            &format!("F{f} の法線 {} は向きを持ちません（0 か NaN）", normals[f]),
            &format!("F{f}'s normal {} has no direction (zero or NaN)", normals[f]),
        ));
    }
    let mut split = Mesh::new(Vec::new(), Vec::new());
    let mut corner_normals = Vec::new();
    for (f, face) in mesh.faces.iter().enumerate() {
        let base = split.positions.len() as u32;
        split.positions.extend(face.iter().map(|&i| mesh.positions[i as usize]));
        corner_normals.extend([normals[f]; 3]);
        split.faces.push([base, base + 1, base + 2]);
    }
    split.normals = Some(corner_normals);
    Ok(split)
}

/// The kit's reference picture ([`cg_harness::Assignment::reference_view`]): the expected
/// vertices (the `a1.t1` oracle), the faces of their convex hull (every solid of the assignment
/// is convex; [`crate::hull`]), each face's own normal, and the placement `T(x, y, z) · Ry(θ)`
/// that `a1.t4` asks for.
#[must_use]
pub fn reference(spec: &Spec) -> Scene {
    use crate::spec::SpecExt;
    let positions = spec.expected_vertices();
    let faces = crate::hull::faces(&positions);
    let mesh = Mesh::new(positions, faces);
    let normals: Vec<Vec3> = mesh
        .faces
        .iter()
        .map(|f| {
            let [a, b, c] = f.map(|i| mesh.positions[i as usize].as_dvec3());
            (b - a).cross(c - a).normalize().as_vec3()
        })
        .collect();
    let p = spec.placement;
    let transform = MatrixProduct::identity()
        .then(cg_core::product::Factor::translate(Vec3::new(p.x, p.y, p.z)))
        .then(cg_core::product::Factor::rotate_y_deg(p.angle_deg));
    // The hull's normals have a direction and match its faces one for one.
    model_scene(&mesh, Some(&normals), transform)
        .unwrap_or_else(|_| cg_harness::course::ground_only())
}
