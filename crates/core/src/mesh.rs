//! Indexed triangle meshes (ポリゴンモデル): positions, faces and optional per-vertex attributes,
//! with validation that names the offending faces and edges, and welding by position.
//!
//! A face `[a, b, c]` is front-facing when `a → b → c` runs counter-clockwise seen from outside;
//! its normal is `(p_b − p_a) × (p_c − p_a)` normalised (see [`crate::normals::face_normal`]).

use glam::{Vec2, Vec3};

/// An indexed triangle mesh. Vertex `i` has `positions[i]` and, where present, `normals[i]`,
/// `uvs[i]` and `colors[i]`; every attribute vector present has one entry per vertex.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions in model space (モデル座標系).
    pub positions: Vec<Vec3>,
    /// Triangles as three vertex indices, counter-clockwise seen from outside.
    pub faces: Vec<[u32; 3]>,
    /// Per-vertex unit normals, when the mesh carries them.
    pub normals: Option<Vec<Vec3>>,
    /// Per-vertex texture coordinates, `(0, 0)` = the image's bottom-left corner.
    pub uvs: Option<Vec<Vec2>>,
    /// Per-vertex colours (with colour-material they set k_a and k_d, as glColor does).
    pub colors: Option<Vec<Vec3>>,
}

impl Mesh {
    /// A mesh with positions and faces and no other attributes. Indices are not checked here:
    /// call [`Mesh::validate`] (or [`Mesh::check_indices`]) before trusting them.
    #[must_use]
    pub fn new(positions: Vec<Vec3>, faces: Vec<[u32; 3]>) -> Mesh {
        Mesh { positions, faces, normals: None, uvs: None, colors: None }
    }

    /// Number of vertices.
    #[must_use]
    pub fn vertex_count(&self) -> usize {
        self.positions.len()
    }

    /// Number of triangles.
    #[must_use]
    pub fn face_count(&self) -> usize {
        self.faces.len()
    }

    /// The three corner positions of face `f`.
    ///
    /// # Panics
    /// When `f` or one of its indices is out of range; call [`Mesh::check_indices`] first on
    /// meshes from user input.
    #[must_use]
    pub fn triangle(&self, f: usize) -> [Vec3; 3] {
        self.faces[f].map(|i| self.positions[i as usize])
    }

    /// Cheap structural check, enough to make every index-based function safe: every face index
    /// is in range, every attribute vector has one entry per vertex, every position is finite.
    ///
    /// # Errors
    /// The first [`MeshError`] found, naming the face, corner, vertex or attribute.
    pub fn check_indices(&self) -> Result<(), MeshError> {
        let n = self.positions.len();
        for (name, len) in [
            ("normals", self.normals.as_ref().map(Vec::len)),
            ("uvs", self.uvs.as_ref().map(Vec::len)),
            ("colors", self.colors.as_ref().map(Vec::len)),
        ] {
            if let Some(len) = len.filter(|&len| len != n) {
                return Err(MeshError::AttributeLength { attribute: name, len, expected: n });
            }
        }
        if let Some(vertex) = self.positions.iter().position(|p| !p.is_finite()) {
            return Err(MeshError::NonFinitePosition { vertex, position: self.positions[vertex] });
        }
        for (face, f) in self.faces.iter().enumerate() {
            for (corner, &index) in f.iter().enumerate() {
                if index as usize >= n {
                    return Err(MeshError::IndexOutOfRange {
                        face,
                        corner,
                        index,
                        vertex_count: n,
                    });
                }
            }
        }
        Ok(())
    }
}

/// A structural error that makes a mesh unusable (as opposed to a validation finding such as an
/// open boundary, which is reported by [`Mesh::validate`]).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MeshError {
    /// A face refers to a vertex that does not exist.
    #[error("face F{face} corner {corner} refers to vertex {index}, but the mesh has only {vertex_count} vertices (V0..V{})", vertex_count.saturating_sub(1))]
    IndexOutOfRange {
        /// The face (F-number).
        face: usize,
        /// Which corner of the face, 0..3.
        corner: usize,
        /// The index found there.
        index: u32,
        /// How many vertices the mesh has.
        vertex_count: usize,
    },
    /// An attribute vector does not have one entry per vertex.
    #[error("the mesh has {expected} vertices but {len} {attribute}")]
    AttributeLength {
        /// `normals`, `uvs` or `colors`.
        attribute: &'static str,
        /// How many entries it has.
        len: usize,
        /// How many it should have (the vertex count).
        expected: usize,
    },
    /// A position has an infinite or NaN coordinate.
    #[error("vertex V{vertex} has a non-finite position {position}")]
    NonFinitePosition {
        /// The vertex (V-number).
        vertex: usize,
        /// Its position.
        position: Vec3,
    },
}
