//! What the report is about: the data derived for one student (or from a data file), shared by
//! the tables, the figures, the checker and the template.

use cg_core::glam::{Vec2, Vec3};
use cg_core::product::MatrixProduct;
use cg_core::texture::{Sampler, Texture};
use cg_harness::Text;

/// A number as a student wrote it: its value and how many decimals it has, so the checker can
/// accept correct rounding (`0.53` for 0.5299…) and nothing else.
#[derive(Clone, Debug, PartialEq)]
pub struct Written {
    /// The value.
    pub value: f64,
    /// Decimals written after the point (0 for `15`, 2 for `0.53`).
    pub decimals: u32,
    /// The text as written.
    pub text: String,
}

/// The polygon model (assignment 1, or a data file).
#[derive(Clone, Debug, PartialEq)]
pub struct PolygonData {
    /// A name for titles (`六角すい`, `pyramid`).
    pub name: Text,
    /// V0, V1, … in model space.
    pub vertices: Vec<Vec3>,
    /// F0, F1, … as vertex numbers, counter-clockwise seen from outside.
    pub faces: Vec<[u32; 3]>,
    /// Each face's normal as the kit derives it from the vertices (`None`: degenerate).
    pub derived_normals: Vec<Option<Vec3>>,
    /// The student's own face normals (a1.t3), when there are any.
    pub student_normals: Option<Vec<Vec3>>,
    /// The model transform (a1.t4), when there is one.
    pub transform: Option<MatrixProduct>,
}

/// A matrix the report must show: symbolically and at one stated state or time.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedMatrix {
    /// A stable ID, used as the tag in the template (`a2.view.start`, `a3.object2.t1.5`).
    pub id: String,
    /// What it is and at which state/time (`視野変換行列（初期状態）`).
    pub title: Text,
    /// The product with variables (`T(0, 0, -camera_distance) · Rx(-camera_pitch)`).
    pub symbolic: MatrixProduct,
    /// The product with this state's numbers.
    pub numeric: MatrixProduct,
    /// Each variable with its explanation (which operation changes it, how, its range).
    pub variables: Vec<(String, Text)>,
}

/// Assignment 2: the view transform.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraData {
    /// The view matrix at the stated mouse states.
    pub matrices: Vec<NamedMatrix>,
}

/// Assignment 3: each object's model transform.
#[derive(Clone, Debug, PartialEq)]
pub struct AnimationData {
    /// Per object, its model matrix at the stated times.
    pub objects: Vec<(String, Vec<NamedMatrix>)>,
    /// The periods and their ratios, as the report must state them.
    pub periods: Text,
}

/// One ground vertex of assignment 4.
#[derive(Clone, Debug, PartialEq)]
pub struct TexRow {
    /// Grid column, 0..=10.
    pub i: u32,
    /// Grid row, 0..=10.
    pub j: u32,
    /// Its position on the ground, `(i − 5, 0, j − 5)`.
    pub position: Vec3,
    /// Its texture coordinates: one, or two or four where the vertex lies on the edge of a
    /// repeat block (each block shows the whole region), in the order of the squares that use
    /// them (square (i, j) before (i + 1, j) …), without repeats.
    pub tex: Vec<Vec2>,
}

/// Assignment 4: the texture mapping.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureData {
    /// Every ground vertex (i, j = 0…10, j-major: (0, 0), (1, 0), …) with its coordinates.
    pub rows: Vec<TexRow>,
    /// The formula in i and j, and the range, in words.
    pub formula: Text,
    /// The mapped rectangle in texture coordinates: (min, max).
    pub region: (Vec2, Vec2),
    /// The prepared image.
    pub image: Texture,
    /// The student's sampler (a4.t3): filter and wrap modes; `None` when `sampler()` is not
    /// written or panics (the rest of the part still derives).
    pub sampler: Option<Sampler>,
    /// How many pixels of the image one ground square shows, along s and along t (square
    /// (0, 0): the spread of its corners' coordinates times the image's size).
    pub texels_per_square: Vec2,
}

/// Everything derived for one report.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Derived {
    /// The student number, when derived from a student's exercises.
    pub student: Option<String>,
    /// Assignment 1 (or a data file's model).
    pub polygon: Option<PolygonData>,
    /// Assignment 2.
    pub camera: Option<CameraData>,
    /// Assignment 3.
    pub animation: Option<AnimationData>,
    /// Assignment 4.
    pub texture: Option<TextureData>,
}
