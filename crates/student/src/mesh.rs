//! A polygon model as plain data: vertex positions and triangles (ポリゴンモデル).

use glam::Vec3;
use serde::{Deserialize, Serialize};

/// A triangle mesh: `positions[i]` is vertex `Vi`; each face `[a, b, c]` lists three vertex
/// numbers, counter-clockwise seen from outside.
///
/// Plain data: nothing here checks or computes anything (the kit's checks do that).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Mesh {
    /// The vertex positions `V0, V1, …`, in model space.
    pub positions: Vec<Vec3>,
    /// The triangles as vertex numbers.
    pub faces: Vec<[u32; 3]>,
}

impl Mesh {
    /// A mesh from its positions and faces, as given.
    #[must_use]
    pub fn new(positions: Vec<Vec3>, faces: Vec<[u32; 3]>) -> Mesh {
        Mesh { positions, faces }
    }
}
