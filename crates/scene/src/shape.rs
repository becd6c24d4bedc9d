//! `shape = { kind = "...", ... }`: the built-in shapes of `cg_core::shapes` with their
//! parameters, read and checked before any mesh is built.

use cg_core::glam::Vec3;
use cg_core::mesh::Mesh;
use cg_core::scene::Analytic;
use cg_core::shapes::{self, ShapeError};

use crate::error::{ErrorKind, Expected, Rule, SceneError};
use crate::reader::{At, Value};

/// The most faces (triangles) one built-in shape may have: 4 000 000, about 200 MB of mesh,
/// normals and texture coordinates at most, where `uv_sphere` with 4096 × 4096 segments would
/// take gigabytes. (An `icosphere` with 8 subdivisions has 1 310 720.)
pub const MAX_SHAPE_FACES: u64 = 4_000_000;

/// Where a shape's table and parameters are in the file, for the errors found when its mesh is
/// built.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ShapeAt {
    /// The shape table.
    pub table: At,
    /// Each parameter's value, by the name `cg_core::shapes` gives it in a [`ShapeError`]
    /// (`radius`, `slices`, `size.x`, …).
    pub params: Vec<(&'static str, At)>,
}

impl ShapeAt {
    /// Where `parameter` (as a [`ShapeError`] names it) is; the table if it is not known.
    pub fn of(&self, parameter: &str) -> &At {
        self.params.iter().find(|(name, _)| *name == parameter).map_or(&self.table, |(_, at)| at)
    }
}

/// A built-in shape and its parameters, as a scene file names it. Lengths are in scene units;
/// every closed shape is centred on the origin with +Y as its axis (see `cg_core::shapes`).
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeSpec {
    /// `grid`: the ground, `divisions × divisions` squares in y = 0, `size` wide.
    Grid {
        /// Squares along each side (≥ 1).
        divisions: u32,
        /// Side length (> 0).
        size: f32,
    },
    /// `lecture_pyramid`: the lecture's 四角すい V0..V4, F0..F5 (no parameters).
    LecturePyramid,
    /// `cuboid` (or `box`): a box `size.x × size.y × size.z`.
    Cuboid {
        /// The three side lengths (each > 0).
        size: Vec3,
    },
    /// `uv_sphere`: meridians and bands.
    UvSphere {
        /// Radius (> 0).
        radius: f32,
        /// Meridians (≥ 3).
        slices: u32,
        /// Bands between the poles (≥ 2).
        stacks: u32,
    },
    /// `sphere`: the exact sphere, for the ray tracer; rasterizers draw its
    /// `SPHERE_SLICES` × `SPHERE_STACKS` (64 × 32) UV tessellation.
    Sphere {
        /// Radius (> 0).
        radius: f32,
    },
    /// `icosphere`: a subdivided icosahedron.
    Icosphere {
        /// Radius (> 0).
        radius: f32,
        /// Times every triangle is split into four (≥ 0).
        subdivisions: u32,
    },
    /// `cylinder`: capped, from y = −height/2 to +height/2.
    Cylinder {
        /// Radius (> 0).
        radius: f32,
        /// Height (> 0).
        height: f32,
        /// Sides (≥ 3).
        slices: u32,
    },
    /// `cone`: capped, apex at +height/2.
    Cone {
        /// Base radius (> 0).
        radius: f32,
        /// Height (> 0).
        height: f32,
        /// Sides (≥ 3).
        slices: u32,
    },
    /// `torus`: around +Y in the XZ plane.
    Torus {
        /// Ring radius (> minor).
        major: f32,
        /// Tube radius (> 0).
        minor: f32,
        /// Segments around the ring (≥ 3).
        major_segments: u32,
        /// Segments around the tube (≥ 3).
        minor_segments: u32,
    },
    /// `prism`: a right prism over a regular polygon.
    Prism {
        /// Sides of the polygon (≥ 3).
        sides: u32,
        /// Circumradius (> 0).
        radius: f32,
        /// Height (> 0).
        height: f32,
    },
    /// `pyramid`: a pyramid over a regular polygon.
    Pyramid {
        /// Sides of the base (≥ 3).
        sides: u32,
        /// Circumradius of the base (> 0).
        radius: f32,
        /// Height (> 0).
        height: f32,
    },
    /// `frustum`: a truncated pyramid over a regular polygon.
    Frustum {
        /// Sides (≥ 3).
        sides: u32,
        /// Circumradius at the bottom (> 0).
        bottom_radius: f32,
        /// Circumradius at the top (> 0).
        top_radius: f32,
        /// Height (> 0).
        height: f32,
    },
    /// `octahedron`: six vertices on the axes.
    Octahedron {
        /// Distance of the vertices from the centre (> 0).
        radius: f32,
    },
}

/// Meridians of the mesh that stands for a `sphere` in rasterizers.
pub const SPHERE_SLICES: u32 = 64;
/// Bands of the mesh that stands for a `sphere` in rasterizers.
pub const SPHERE_STACKS: u32 = 32;

/// Every `kind` with the keys it takes besides `kind`.
pub(crate) const KINDS: &[(&str, &[&str])] = &[
    ("grid", &["divisions", "size"]),
    ("lecture_pyramid", &[]),
    ("cuboid", &["size"]),
    ("box", &["size"]),
    ("uv_sphere", &["radius", "slices", "stacks"]),
    ("sphere", &["radius"]),
    ("icosphere", &["radius", "subdivisions"]),
    ("cylinder", &["radius", "height", "slices"]),
    ("cone", &["radius", "height", "slices"]),
    ("torus", &["major", "minor", "major_segments", "minor_segments"]),
    ("prism", &["sides", "radius", "height"]),
    ("pyramid", &["sides", "radius", "height"]),
    ("frustum", &["sides", "bottom_radius", "top_radius", "height"]),
    ("octahedron", &["radius"]),
];

impl ShapeSpec {
    /// Reads `shape = { kind = "...", ... }`: the kind, then exactly the keys that kind takes,
    /// every one required; lengths finite and > 0, counts integers at or above their minimum,
    /// and at most [`MAX_SHAPE_FACES`] faces (counted before anything is built, so a huge count
    /// is an error naming the parameter, not gigabytes of memory). Returns the shape and where
    /// its parameters are.
    pub(crate) fn read(value: &Value<'_>) -> Result<(ShapeSpec, ShapeAt), SceneError> {
        let table = value.table()?;
        let kind_value = table.require("kind")?;
        let choices: Vec<(&'static str, &'static [&'static str])> = KINDS.to_vec();
        let params = kind_value.choice(&choices)?;
        let kind = kind_value.str()?;
        let mut allowed = vec!["kind"];
        allowed.extend_from_slice(params);
        table.only(&allowed)?;
        let length = |key: &str| table.require(key)?.f32(Rule::Positive);
        // Counts in the constructors' ranges (`an integer in 3..=4096`), said at the value.
        let count = |key: &str, min: u32| table.require(key)?.u32(min, shapes::MAX_SEGMENTS);
        let spec = match kind {
            "grid" => ShapeSpec::Grid { divisions: count("divisions", 1)?, size: length("size")? },
            "lecture_pyramid" => ShapeSpec::LecturePyramid,
            "cuboid" | "box" => {
                let size = table.require("size")?;
                let [x, y, z] = size.array_of(Expected::Vec3)?;
                ShapeSpec::Cuboid {
                    size: Vec3::new(
                        x.f32(Rule::Positive)?,
                        y.f32(Rule::Positive)?,
                        z.f32(Rule::Positive)?,
                    ),
                }
            }
            "uv_sphere" => ShapeSpec::UvSphere {
                radius: length("radius")?,
                slices: count("slices", 3)?,
                stacks: count("stacks", 2)?,
            },
            "sphere" => ShapeSpec::Sphere { radius: length("radius")? },
            "icosphere" => ShapeSpec::Icosphere {
                radius: length("radius")?,
                subdivisions: table.require("subdivisions")?.u32(0, shapes::MAX_SUBDIVISIONS)?,
            },
            "cylinder" => ShapeSpec::Cylinder {
                radius: length("radius")?,
                height: length("height")?,
                slices: count("slices", 3)?,
            },
            "cone" => ShapeSpec::Cone {
                radius: length("radius")?,
                height: length("height")?,
                slices: count("slices", 3)?,
            },
            "torus" => ShapeSpec::Torus {
                major: length("major")?,
                minor: length("minor")?,
                major_segments: count("major_segments", 3)?,
                minor_segments: count("minor_segments", 3)?,
            },
            "prism" => ShapeSpec::Prism {
                sides: count("sides", 3)?,
                radius: length("radius")?,
                height: length("height")?,
            },
            "pyramid" => ShapeSpec::Pyramid {
                sides: count("sides", 3)?,
                radius: length("radius")?,
                height: length("height")?,
            },
            "frustum" => ShapeSpec::Frustum {
                sides: count("sides", 3)?,
                bottom_radius: length("bottom_radius")?,
                top_radius: length("top_radius")?,
                height: length("height")?,
            },
            _ => ShapeSpec::Octahedron { radius: length("radius")? },
        };

        let faces = spec.face_count();
        if faces > MAX_SHAPE_FACES {
            // Only shapes with a count parameter can have this many faces.
            let key = spec.count_parameter().unwrap_or("kind");
            let shape = spec.kind();
            let kind = ErrorKind::TooManyFaces { shape, faces, max: MAX_SHAPE_FACES };
            return Err(table.require(key)?.error(kind));
        }

        let mut at = ShapeAt { table: table.at(), params: Vec::new() };
        for &key in params {
            let v = table.require(key)?;
            if let ShapeSpec::Cuboid { .. } = spec {
                let [x, y, z] = v.array_of(Expected::Vec3)?;
                at.params.extend([("size.x", x.at()), ("size.y", y.at()), ("size.z", z.at())]);
            } else {
                at.params.push((key, v.at()));
            }
        }
        Ok((spec, at))
    }

    /// The number of faces (triangles) the mesh of this shape has, from the formulas documented
    /// in `cg_core::shapes` (`2·divisions²` for a grid, `2·slices·(stacks − 1)` for a UV sphere,
    /// `20·4^subdivisions` for an icosphere, …), in u64 and saturating, so it can be checked
    /// before the mesh is built. Parameters out of the constructors' ranges are counted as given.
    #[must_use]
    pub fn face_count(&self) -> u64 {
        let n = |count: u32| u64::from(count);
        match *self {
            ShapeSpec::Grid { divisions, .. } => (2 * n(divisions)).saturating_mul(n(divisions)),
            ShapeSpec::LecturePyramid => 6,
            ShapeSpec::Cuboid { .. } => 12,
            ShapeSpec::UvSphere { slices, stacks, .. } => {
                (2 * n(slices)).saturating_mul(n(stacks).saturating_sub(1))
            }
            ShapeSpec::Sphere { .. } => 2 * n(SPHERE_SLICES) * (n(SPHERE_STACKS) - 1),
            ShapeSpec::Icosphere { subdivisions, .. } => {
                4u64.checked_pow(subdivisions).map_or(u64::MAX, |p| p.saturating_mul(20))
            }
            ShapeSpec::Cylinder { slices, .. } => 4 * n(slices),
            ShapeSpec::Cone { slices, .. } => 2 * n(slices),
            ShapeSpec::Torus { major_segments, minor_segments, .. } => {
                (2 * n(major_segments)).saturating_mul(n(minor_segments))
            }
            ShapeSpec::Prism { sides, .. } | ShapeSpec::Frustum { sides, .. } => {
                (4 * n(sides)).saturating_sub(4)
            }
            ShapeSpec::Pyramid { sides, .. } => (2 * n(sides)).saturating_sub(2),
            ShapeSpec::Octahedron { .. } => 8,
        }
    }

    /// The parameter that sets the face count (the larger of two), named in
    /// [`ErrorKind::TooManyFaces`]; `None` for shapes with a fixed count.
    pub(crate) fn count_parameter(&self) -> Option<&'static str> {
        match *self {
            ShapeSpec::Grid { .. } => Some("divisions"),
            ShapeSpec::UvSphere { slices, stacks, .. } => {
                Some(if slices >= stacks { "slices" } else { "stacks" })
            }
            ShapeSpec::Icosphere { .. } => Some("subdivisions"),
            ShapeSpec::Cylinder { .. } | ShapeSpec::Cone { .. } => Some("slices"),
            ShapeSpec::Torus { major_segments, minor_segments, .. } => {
                Some(if major_segments >= minor_segments {
                    "major_segments"
                } else {
                    "minor_segments"
                })
            }
            ShapeSpec::Prism { .. } | ShapeSpec::Pyramid { .. } | ShapeSpec::Frustum { .. } => {
                Some("sides")
            }
            ShapeSpec::LecturePyramid
            | ShapeSpec::Cuboid { .. }
            | ShapeSpec::Sphere { .. }
            | ShapeSpec::Octahedron { .. } => None,
        }
    }

    /// The `kind` that names this shape in a scene file.
    #[must_use]
    pub fn kind(&self) -> &'static str {
        match self {
            ShapeSpec::Grid { .. } => "grid",
            ShapeSpec::LecturePyramid => "lecture_pyramid",
            ShapeSpec::Cuboid { .. } => "cuboid",
            ShapeSpec::UvSphere { .. } => "uv_sphere",
            ShapeSpec::Sphere { .. } => "sphere",
            ShapeSpec::Icosphere { .. } => "icosphere",
            ShapeSpec::Cylinder { .. } => "cylinder",
            ShapeSpec::Cone { .. } => "cone",
            ShapeSpec::Torus { .. } => "torus",
            ShapeSpec::Prism { .. } => "prism",
            ShapeSpec::Pyramid { .. } => "pyramid",
            ShapeSpec::Frustum { .. } => "frustum",
            ShapeSpec::Octahedron { .. } => "octahedron",
        }
    }

    /// The exact surface this shape stands for, when there is one: a `sphere`, and the `grid`'s
    /// square. Other shapes are polygon models in their own right.
    #[must_use]
    pub fn analytic(&self) -> Option<Analytic> {
        match *self {
            ShapeSpec::Sphere { radius } => Some(Analytic::Sphere { radius }),
            ShapeSpec::Grid { size, .. } => Some(Analytic::Plane { size }),
            _ => None,
        }
    }

    /// The shape's mesh, from the constructor in `cg_core::shapes`.
    ///
    /// # Errors
    /// The constructor's [`ShapeError`] for parameters it rejects (counts above its limit, a torus
    /// whose tube is not thinner than its ring).
    pub fn mesh(&self) -> Result<Mesh, ShapeError> {
        match *self {
            ShapeSpec::Grid { divisions, size } => shapes::grid(divisions, size),
            ShapeSpec::LecturePyramid => Ok(shapes::lecture_pyramid()),
            ShapeSpec::Cuboid { size } => shapes::cuboid(size),
            ShapeSpec::UvSphere { radius, slices, stacks } => {
                shapes::uv_sphere(radius, slices, stacks)
            }
            ShapeSpec::Sphere { radius } => shapes::uv_sphere(radius, SPHERE_SLICES, SPHERE_STACKS),
            ShapeSpec::Icosphere { radius, subdivisions } => {
                shapes::icosphere(radius, subdivisions)
            }
            ShapeSpec::Cylinder { radius, height, slices } => {
                shapes::cylinder(radius, height, slices)
            }
            ShapeSpec::Cone { radius, height, slices } => shapes::cone(radius, height, slices),
            ShapeSpec::Torus { major, minor, major_segments, minor_segments } => {
                shapes::torus(major, minor, major_segments, minor_segments)
            }
            ShapeSpec::Prism { sides, radius, height } => shapes::prism(sides, radius, height),
            ShapeSpec::Pyramid { sides, radius, height } => shapes::pyramid(sides, radius, height),
            ShapeSpec::Frustum { sides, bottom_radius, top_radius, height } => {
                shapes::frustum(sides, bottom_radius, top_radius, height)
            }
            ShapeSpec::Octahedron { radius } => shapes::octahedron(radius),
        }
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use super::*;
    use crate::error::{ErrorKind, Expected, Found};
    use crate::reader::{Source, Table};

    /// Reads `shape = <inline>` on line 1 of a file `t.toml`.
    fn read(inline: &str) -> Result<ShapeSpec, SceneError> {
        let text = format!("shape = {inline}");
        let src = Source { text: &text, file: Path::new("t.toml") };
        let doc = toml::de::DeTable::parse(&text).expect("valid TOML");
        ShapeSpec::read(&Table::root(&src, &doc).require("shape")?).map(|(spec, _)| spec)
    }

    /// One inline table of every kind (and the alias `box`), with the shape it stands for.
    fn every_kind() -> [(&'static str, ShapeSpec); KINDS.len()] {
        [
            (
                r#"{ kind = "grid", divisions = 10, size = 10.0 }"#,
                ShapeSpec::Grid { divisions: 10, size: 10.0 },
            ),
            (r#"{ kind = "lecture_pyramid" }"#, ShapeSpec::LecturePyramid),
            (
                r#"{ kind = "cuboid", size = [1, 2.5, 3] }"#,
                ShapeSpec::Cuboid { size: Vec3::new(1.0, 2.5, 3.0) },
            ),
            (r#"{ kind = "box", size = [2, 2, 2] }"#, ShapeSpec::Cuboid { size: Vec3::splat(2.0) }),
            (
                r#"{ kind = "uv_sphere", radius = 1.5, slices = 32, stacks = 16 }"#,
                ShapeSpec::UvSphere { radius: 1.5, slices: 32, stacks: 16 },
            ),
            (r#"{ kind = "sphere", radius = 0.5 }"#, ShapeSpec::Sphere { radius: 0.5 }),
            (
                r#"{ kind = "icosphere", radius = 2, subdivisions = 0 }"#,
                ShapeSpec::Icosphere { radius: 2.0, subdivisions: 0 },
            ),
            (
                r#"{ kind = "cylinder", radius = 0.5, height = 2, slices = 3 }"#,
                ShapeSpec::Cylinder { radius: 0.5, height: 2.0, slices: 3 },
            ),
            (
                r#"{ kind = "cone", radius = 1, height = 1.5, slices = 12 }"#,
                ShapeSpec::Cone { radius: 1.0, height: 1.5, slices: 12 },
            ),
            (
                r#"{ kind = "torus", major = 2, minor = 0.5, major_segments = 24, minor_segments = 12 }"#,
                ShapeSpec::Torus { major: 2.0, minor: 0.5, major_segments: 24, minor_segments: 12 },
            ),
            (
                r#"{ kind = "prism", sides = 6, radius = 1, height = 2 }"#,
                ShapeSpec::Prism { sides: 6, radius: 1.0, height: 2.0 },
            ),
            (
                r#"{ kind = "pyramid", sides = 4, radius = 1, height = 1.8 }"#,
                ShapeSpec::Pyramid { sides: 4, radius: 1.0, height: 1.8 },
            ),
            (
                r#"{ kind = "frustum", sides = 5, bottom_radius = 2, top_radius = 1, height = 1 }"#,
                ShapeSpec::Frustum { sides: 5, bottom_radius: 2.0, top_radius: 1.0, height: 1.0 },
            ),
            (r#"{ kind = "octahedron", radius = 0.75 }"#, ShapeSpec::Octahedron { radius: 0.75 }),
        ]
    }

    #[test]
    fn every_kind_reads_its_parameters() {
        let cases = every_kind();
        for (text, expected) in &cases {
            assert_eq!(read(text).as_ref(), Ok(expected), "{text}");
            // `kind()` names the shape as the file does (`box` is an alias of `cuboid`).
            assert!(text.contains(expected.kind()) || expected.kind() == "cuboid", "{text}");
        }
        // Every kind of the table is covered above.
        assert_eq!(KINDS.len(), cases.len());
    }

    #[test]
    fn shape_mistakes_point_at_the_parameter() {
        // Column of a key or value on line 1 of "shape = { ... }".
        let col = |text: &str, needle: &str| 1 + "shape = ".len() + text.find(needle).unwrap();

        let text = r#"{ kind = "uv_sphere", radius = -1, slices = 8, stacks = 4 }"#;
        let e = read(text).unwrap_err();
        assert_eq!(e.key.as_deref(), Some("shape.radius"));
        assert_eq!(e.position.map(|p| (p.line, p.column)), Some((1, col(text, "-1"))));
        assert_eq!(*e.kind, ErrorKind::BadValue { rule: Rule::Positive, got: "-1".into() });

        let text = r#"{ kind = "uv_sphere", radius = 1, slices = 8 }"#;
        let e = read(text).unwrap_err();
        assert_eq!(*e.kind, ErrorKind::MissingKey { key: "stacks".into() });
        assert_eq!(e.key.as_deref(), Some("shape"));

        let text = r#"{ kind = "uv_sphere", radius = 1, slice = 8, stacks = 4 }"#;
        let e = read(text).unwrap_err();
        assert!(
            matches!(&*e.kind, ErrorKind::UnknownKey { key, suggestion: Some(s), .. } if key == "slice" && s == "slices"),
            "{e}"
        );
        assert_eq!(e.position.map(|p| p.column), Some(col(text, "slice")));

        let text = r#"{ kind = "cylinder", radius = 1, height = 1, slices = 2 }"#;
        let e = read(text).unwrap_err();
        assert_eq!(
            *e.kind,
            ErrorKind::BadValue { rule: Rule::Integer { min: 3, max: 4096 }, got: "2".into() }
        );

        let text = r#"{ kind = "grid", divisions = 10.0, size = 10 }"#;
        let e = read(text).unwrap_err();
        assert_eq!(
            *e.kind,
            ErrorKind::WrongType { expected: Expected::Integer, found: Found::Float }
        );

        let text = r#"{ kind = "cuboid", size = [1, 0, 1] }"#;
        assert_eq!(read(text).unwrap_err().key.as_deref(), Some("shape.size[1]"));

        let e = read(r#"{ kind = "uv_spere", radius = 1 }"#).unwrap_err();
        assert!(
            matches!(*e.kind, ErrorKind::UnknownChoice { suggestion: Some("uv_sphere"), .. }),
            "{e}"
        );
        assert_eq!(e.key.as_deref(), Some("shape.kind"));
        let e = read(r#"{ kind = "sphre", radius = 1 }"#).unwrap_err();
        assert!(
            matches!(&*e.kind, ErrorKind::UnknownChoice { allowed, .. } if allowed.len() == KINDS.len()),
            "{e}"
        );

        assert!(matches!(
            *read(r#"{ radius = 1 }"#).unwrap_err().kind,
            ErrorKind::MissingKey { .. }
        ));
        assert!(matches!(
            *read("3").unwrap_err().kind,
            ErrorKind::WrongType { expected: Expected::Table, .. }
        ));
        let e = read(r#"{ kind = "lecture_pyramid", size = 2 }"#).unwrap_err();
        assert!(matches!(*e.kind, ErrorKind::UnknownKey { .. }), "{e}");
    }

    #[test]
    fn spheres_and_grids_stand_for_exact_surfaces() {
        let sphere = read(r#"{ kind = "sphere", radius = 2 }"#).unwrap();
        assert_eq!(sphere.analytic(), Some(Analytic::Sphere { radius: 2.0 }));
        // Its mesh is the UV tessellation, every vertex on the exact sphere.
        let mesh = sphere.mesh().unwrap();
        assert_eq!(mesh, shapes::uv_sphere(2.0, SPHERE_SLICES, SPHERE_STACKS).unwrap());
        let grid = read(r#"{ kind = "grid", divisions = 4, size = 6 }"#).unwrap();
        assert_eq!(grid.analytic(), Some(Analytic::Plane { size: 6.0 }));
        let uv = read(r#"{ kind = "uv_sphere", radius = 2, slices = 8, stacks = 4 }"#).unwrap();
        assert_eq!(uv.analytic(), None, "a uv_sphere is a polygon model, not a sphere");
    }

    #[test]
    fn face_count_is_the_built_meshs() {
        for (_, spec) in every_kind() {
            assert_eq!(spec.face_count(), spec.mesh().unwrap().face_count() as u64, "{spec:?}");
        }
        // Counts beyond u64 saturate instead of wrapping round to a small number.
        let huge = ShapeSpec::Grid { divisions: u32::MAX, size: 1.0 };
        assert_eq!(huge.face_count(), u64::MAX);
        let huge = ShapeSpec::Icosphere { radius: 1.0, subdivisions: 40 };
        assert_eq!(huge.face_count(), u64::MAX);
    }

    #[test]
    fn the_face_limit_is_checked_before_building() {
        // 2·1414² = 3 998 792 faces is allowed, 2·1415² = 4 004 450 is not.
        let grid = |n: u32| read(&format!(r#"{{ kind = "grid", divisions = {n}, size = 1 }}"#));
        assert_eq!(grid(1414), Ok(ShapeSpec::Grid { divisions: 1414, size: 1.0 }));
        let e = grid(1415).unwrap_err();
        let max = MAX_SHAPE_FACES;
        assert_eq!(*e.kind, ErrorKind::TooManyFaces { shape: "grid", faces: 4_004_450, max });
        assert_eq!(e.key.as_deref(), Some("shape.divisions"));
    }

    #[test]
    fn grid_and_pyramid_meshes_come_from_the_core_constructors() {
        let grid = ShapeSpec::Grid { divisions: 10, size: 10.0 }.mesh().unwrap();
        assert_eq!(grid, shapes::grid(10, 10.0).unwrap());
        assert_eq!(ShapeSpec::LecturePyramid.mesh().unwrap(), shapes::lecture_pyramid());
        let e = ShapeSpec::Grid { divisions: 5000, size: 1.0 }.mesh().unwrap_err();
        assert_eq!(e.parameter, "divisions");
    }
}
