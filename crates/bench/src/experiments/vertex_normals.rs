//! Vertex-normal weights (uniform, area, angle, Max) against analytic surface normals, on a UV
//! sphere, a torus, an ellipsoid and a jittered icosphere.

use cg_core::glam::{DVec3, Vec3};
use cg_core::mesh::Mesh;
use cg_core::normals::{Weighting, vertex_normals};

use crate::measure::{Rng, mean_p99_max, median_time};
use crate::{BenchError, Column, Config, Experiment, Row};

/// A test mesh and its analytic normal at every vertex.
pub struct Surface {
    /// Name in the table.
    pub name: &'static str,
    /// The mesh.
    pub mesh: Mesh,
    /// The exact unit normal of the surface at each vertex.
    pub normals: Vec<DVec3>,
}

fn shape_error(e: cg_core::shapes::ShapeError) -> BenchError {
    BenchError::Render(e.to_string())
}

/// The four surfaces at `segments` segments around.
///
/// # Errors
/// Only for segment counts the shapes refuse.
pub fn surfaces(segments: u32) -> Result<Vec<Surface>, BenchError> {
    let n = segments.max(4);
    let sphere = cg_core::shapes::uv_sphere(1.0, n, n / 2).map_err(shape_error)?;
    let sphere_normals = sphere.positions.iter().map(|p| p.as_dvec3().normalize()).collect();

    let (big, small) = (1.0f64, 0.4f64);
    let torus = cg_core::shapes::torus(1.0, 0.4, n, n / 2).map_err(shape_error)?;
    let torus_normals = torus
        .positions
        .iter()
        .map(|p| {
            let p = p.as_dvec3();
            let ring = DVec3::new(p.x, 0.0, p.z).normalize() * big;
            let n = (p - ring).normalize();
            debug_assert!(((p - ring).length() - small).abs() < 1e-5);
            n
        })
        .collect();

    let axes = DVec3::new(1.0, 0.6, 0.35);
    let mut ellipsoid = cg_core::shapes::uv_sphere(1.0, n, n / 2).map_err(shape_error)?;
    for p in &mut ellipsoid.positions {
        *p = (p.as_dvec3() * axes).as_vec3();
    }
    let ellipsoid_normals =
        ellipsoid.positions.iter().map(|p| (p.as_dvec3() / (axes * axes)).normalize()).collect();

    // An icosphere whose vertices are moved along the sphere by up to 30 % of an edge: irregular
    // triangles, still exactly on the sphere.
    let level = (n as f64 / 8.0).log2().round().clamp(1.0, 6.0) as u32;
    let mut jittered = cg_core::shapes::icosphere(1.0, level).map_err(shape_error)?;
    let edge = 1.1 / f64::from(1u32 << level);
    let mut rng = Rng::new(0x5eed_0001);
    for p in &mut jittered.positions {
        let d = rng.direction() * (0.3 * edge * rng.unit());
        *p = (p.as_dvec3() + d).normalize().as_vec3();
    }
    let jittered_normals = jittered.positions.iter().map(|p| p.as_dvec3().normalize()).collect();

    Ok(vec![
        Surface { name: "UV sphere", mesh: sphere, normals: sphere_normals },
        Surface { name: "torus", mesh: torus, normals: torus_normals },
        Surface { name: "ellipsoid", mesh: ellipsoid, normals: ellipsoid_normals },
        Surface { name: "jittered sphere", mesh: jittered, normals: jittered_normals },
    ])
}

/// The angle between `a` and `b` in degrees (f64; `a` of zero length gives 180).
fn angle_deg(a: Vec3, b: DVec3) -> f64 {
    let a = a.as_dvec3();
    if a == DVec3::ZERO {
        return 180.0;
    }
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}

/// The name of a weighting in the tables.
#[must_use]
pub fn weighting_name(w: Weighting) -> &'static str {
    match w {
        Weighting::Uniform => "uniform",
        Weighting::Area => "area",
        Weighting::Angle => "angle",
        Weighting::Max => "Max",
    }
}

/// Runs the experiment.
///
/// # Errors
/// Only if a shape refuses the configured size.
pub fn run(config: &Config) -> Result<Experiment, BenchError> {
    let mut rows = Vec::new();
    for surface in surfaces(config.mesh_segments)? {
        for w in [Weighting::Uniform, Weighting::Area, Weighting::Angle, Weighting::Max] {
            let result = vertex_normals(&surface.mesh, w);
            let mut angles: Vec<f64> = result
                .normals
                .iter()
                .zip(&surface.normals)
                .map(|(&a, &b)| angle_deg(a, b))
                .collect();
            let (mean, p99, max) = mean_p99_max(&mut angles);
            let time = median_time(config.reps, || vertex_normals(&surface.mesh, w));
            let faces = surface.mesh.face_count() as f64;
            rows.push(Row {
                key: vec![weighting_name(w).into(), surface.name.into()],
                values: vec![mean, p99, max, time * 1e9 / faces, faces],
            });
        }
    }
    Ok(Experiment {
        id: "vertex-normals",
        title: "頂点の法線の重み / Vertex-normal weights",
        about: "各重み付けの頂点の法線 (`cg_core::normals::vertex_normals`) と解析的な曲面の法線との角度 [度]。\
                UV 球、トーラス、楕円体、頂点を球面上でずらした icosphere。時間は 1 三角形あたり。\n\n\
                The angle in degrees between `cg_core::normals::vertex_normals` under each \
                weighting and the surface's analytic normal, at every vertex: a UV sphere, a torus, \
                an ellipsoid (axes 1, 0.6, 0.35) and an icosphere whose vertices are moved along \
                the sphere by up to 30 % of an edge. Time per triangle of the whole call."
            .into(),
        keys: vec!["weighting", "mesh"],
        columns: vec![
            Column::error("mean angle [°]"),
            Column::error("p99 angle [°]"),
            Column::error("max angle [°]"),
            Column::value("time/triangle [ns]"),
            Column::value("triangles"),
        ],
        rows,
        series_key: 0,
        time_column: 3,
        error_column: 0,
    })
}
