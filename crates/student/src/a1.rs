//! Assignment `a1` — ポリゴンモデルの描画 (polygon model): your variant ([`Spec`]) and the four
//! functions you write ([`Impl`]). Plain data: the kit computes the expected answers on its own
//! side, out of your crate's reach.

use crate::left_out;
use glam::Vec3;
use serde::{Deserialize, Serialize};

use crate::product::MatrixProduct;
use crate::{friendly, unfriendly};

/// Which way a ring of vertices runs, seen from above (from +Y, looking down).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Turn {
    /// Counter-clockwise seen from above: +X → −Z → −X → +Z (angle θ: `(r·cos θ, y, −r·sin θ)`,
    /// the direction of glRotatef(θ, 0, 1, 0)).
    Ccw,
    /// Clockwise seen from above: +X → +Z → −X → −Z (`(r·cos θ, y, r·sin θ)`).
    Cw,
}

/// In which order the parts of the model (apexes, rings, ridge ends) are numbered.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Order {
    /// From the bottom up: the lowest part gets V0.
    BottomUp,
    /// From the top down: the highest part gets V0.
    TopDown,
}

/// The required vertex numbering (頂点番号の付け方), so that vertex `Vi` can be compared with the
/// expected position `i`.
///
/// The model is made of *parts* stacked along the Y axis: single points (an apex), pairs of
/// points (the two ends of a ridge), and *rings* (the corners of a regular polygon or of a
/// rectangle at one height). Parts are numbered in `order`; inside a ring the first vertex is
/// the corner on +X (a regular polygon) or the corner at (+X, +Z) (a rectangle), and the others
/// follow in the direction `ring`. A pair lists the end on the + side of its axis first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Numbering {
    /// Bottom up or top down.
    pub order: Order,
    /// The direction of every ring, seen from above.
    pub ring: Turn,
}

/// The axis a house's ridge (棟) runs along.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RidgeAxis {
    /// Along X: the gable walls (妻壁, with the triangles) face ±X.
    X,
    /// Along Z: the gable walls face ±Z.
    Z,
}

/// The polyhedron, in model space (モデル座標系): its axis is the Y axis and its lowest point (or
/// bottom face) lies in the plane y = 0. Lengths in scene units; a `radius` is the circumradius
/// of a regular polygon (the distance from the axis to each corner), whose first corner is on +X.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Shape {
    /// A pyramid (角すい): a regular `sides`-gon of circumradius `radius` at y = 0, the apex at
    /// (0, `height`, 0).
    Pyramid {
        /// Corners of the base, 3–8.
        sides: u32,
        /// Circumradius of the base.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
        /// Height of the apex.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        height: f32,
    },
    /// A prism (角柱): regular `sides`-gons of circumradius `radius` at y = 0 and y = `height`.
    Prism {
        /// Corners of each cap, 3–8.
        sides: u32,
        /// Circumradius of the caps.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
        /// Height.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        height: f32,
    },
    /// A frustum (角すい台): a regular `sides`-gon of circumradius `bottom_radius` at y = 0 and
    /// one of circumradius `top_radius` at y = `height`, corners above corners.
    Frustum {
        /// Corners of each cap, 3–8.
        sides: u32,
        /// Circumradius of the bottom.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        bottom_radius: f32,
        /// Circumradius of the top (smaller).
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        top_radius: f32,
        /// Height.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        height: f32,
    },
    /// A tower (塔, a pencil): a prism of height `height` with a pyramid of height `tip_height`
    /// on top (apex at (0, `height` + `tip_height`, 0)).
    Tower {
        /// Corners of each ring, 3–8.
        sides: u32,
        /// Circumradius of the rings.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
        /// Height of the prism part.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        height: f32,
        /// Height of the pyramid on top.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        tip_height: f32,
    },
    /// A bipyramid (双角すい): the lower apex at the origin, a regular `sides`-gon of circumradius
    /// `radius` at y = `lower_height`, the upper apex at (0, `lower_height` + `upper_height`, 0).
    Bipyramid {
        /// Corners of the middle ring, 3–6.
        sides: u32,
        /// Circumradius of the middle ring.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
        /// Height of the ring above the lower apex.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        lower_height: f32,
        /// Height of the upper apex above the ring.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        upper_height: f32,
    },
    /// A regular octahedron (正八面体): the lower vertex at the origin, the square of corners
    /// (distance `radius` from the axis) at y = `radius`, the upper vertex at (0, 2·`radius`, 0).
    Octahedron {
        /// Distance from the centre to each vertex.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
    },
    /// A house (家): a box `width` (X) × `depth` (Z) × `wall_height` with a gable roof (切妻屋根)
    /// whose ridge runs along `ridge` through the middle, `roof_height` above the walls.
    House {
        /// Size along X.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        width: f32,
        /// Size along Z.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        depth: f32,
        /// Height of the walls (the eaves, 軒).
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        wall_height: f32,
        /// Height of the ridge above the eaves.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        roof_height: f32,
        /// The axis the ridge runs along.
        ridge: RidgeAxis,
    },
    /// A wedge (くさび形, a ramp): a `width` (X) × `depth` (Z) rectangle at y = 0 with a vertical
    /// rectangle `height` high standing on its −X edge; the slope runs from the +X edge up to the
    /// top of that wall.
    Wedge {
        /// Size along X.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        width: f32,
        /// Size along Z.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        depth: f32,
        /// Height of the vertical wall on the −X side.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        height: f32,
    },
}

/// Where the model stands in the world (ワールド座標系): first turned by `angle_deg` about its own
/// axis (Y, counter-clockwise seen from above, as glRotatef(angle_deg, 0, 1, 0)), then moved so
/// that its model-space origin lands on (`x`, `y`, `z`). As a product in program order:
/// `T(x, y, z) · Ry(angle_deg)`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Placement {
    /// World X of the model's origin.
    #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
    pub x: f32,
    /// World Y of the model's origin: 0 (standing on the ground) or, for the models that end in
    /// a point at the bottom, the height it hovers at.
    #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
    pub y: f32,
    /// World Z of the model's origin.
    #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
    pub z: f32,
    /// The turn about Y, in degrees (a multiple of 15°).
    #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
    pub angle_deg: f32,
}

/// What one student must build.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Spec {
    /// The polyhedron and its dimensions, in model space.
    pub shape: Shape,
    /// The required vertex numbering.
    pub numbering: Numbering,
    /// Where it stands in the world.
    pub placement: Placement,
}

/// The functions a student writes (see `exercises/src/a1.rs`). Each gets the student's
/// [`Spec`]; a student may read the numbers from it or write their own numbers by hand.
#[derive(Clone, Copy, Debug)]
pub struct Impl {
    /// `a1.t1`: the vertex positions in model space, numbered by `spec.numbering`.
    pub vertices: fn(&Spec) -> Vec<Vec3>,
    /// `a1.t2`: the triangles as vertex numbers, counter-clockwise seen from outside.
    pub faces: fn(&Spec) -> Vec<[u32; 3]>,
    /// `a1.t3`: one unit normal per face, in the order of `faces`.
    pub face_normals: fn(&Spec) -> Vec<Vec3>,
    /// `a1.t4`: model space → world space as a product of named factors, in glTranslatef /
    /// glRotatef order (degrees).
    pub model_transform: fn(&Spec) -> MatrixProduct,
}

impl Impl {
    /// For the kit, not for your code: what stands in for `exercises/src/a1.rs` while that file
    /// does not compile, so that the other assignments still build and run. The kit never calls
    /// these functions: it says the file does not compile instead.
    #[must_use]
    pub fn left_out() -> Impl {
        Impl {
            vertices: |_| left_out("a1"),
            faces: |_| left_out("a1"),
            face_normals: |_| left_out("a1"),
            model_transform: |_| left_out("a1"),
        }
    }
}
