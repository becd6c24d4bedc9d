//! Wavefront OBJ models via tobj: positions, and normals and texture coordinates when every face
//! corner has them; all groups merged into one mesh, in the file's vertex order.

use std::collections::HashSet;
use std::path::Path;

use cg_core::glam::{Vec2, Vec3};
use cg_core::math::try_normalize;
use cg_core::mesh::Mesh;

use crate::error::{ErrorKind, Position, SceneError};

/// Reads an OBJ model from text; `path` names it in errors. See [`crate::load_obj`].
pub(crate) fn parse_obj(text: &str, path: &Path) -> Result<Mesh, SceneError> {
    let error = |position: Option<Position>, kind| SceneError {
        position,
        ..SceneError::in_file(path, kind)
    };
    // Before tobj sees the file: huge face indices make tobj 4.0.5's index arithmetic overflow
    // (`vn * 3 + 2`, a panic in debug builds); here every out-of-range index is an error that
    // names the line.
    let file_order = scan_faces(text).map_err(|(position, kind)| error(Some(position), kind))?;

    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    // Materials come from the scene, so the `.mtl` file is never read: a missing or broken one
    // cannot stop the model from loading.
    let (models, _) =
        tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| Ok(Default::default()))
            .map_err(|e| error(None, ErrorKind::Obj(e)))?;

    let mut positions = Vec::new();
    let mut normals = Attribute::new("vn");
    let mut uvs = Attribute::new("vt");
    let mut faces = Vec::new();
    for model in &models {
        let m = &model.mesh;
        let base = positions.len() as u32;
        let count = m.positions.len() / 3;
        positions.extend(m.positions.chunks_exact(3).map(|p| Vec3::new(p[0], p[1], p[2])));
        normals.add(count, m.normals.chunks_exact(3).map(|n| Vec3::new(n[0], n[1], n[2])));
        uvs.add(count, m.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0], t[1])));
        faces.extend(m.indices.chunks_exact(3).map(|f| [f[0] + base, f[1] + base, f[2] + base]));
    }
    if faces.is_empty() {
        return Err(error(None, ErrorKind::ObjNoFaces));
    }
    let mut mesh = Mesh::new(positions, faces);
    mesh.normals = normals.finish().map_err(|kind| error(None, kind))?;
    mesh.uvs = uvs.finish().map_err(|kind| error(None, kind))?;
    if file_order.len() == mesh.vertex_count() {
        mesh = in_file_order(mesh, &file_order);
    }
    mesh.check_indices().map_err(|e| error(None, ErrorKind::Mesh(e)))?;
    if let Some(normals) = &mut mesh.normals {
        for (vertex, n) in normals.iter_mut().enumerate() {
            *n =
                try_normalize(*n).ok_or_else(|| error(None, ErrorKind::ObjBadNormal { vertex }))?;
        }
    }
    if let Some(vertex) = mesh.uvs.as_ref().and_then(|uvs| uvs.iter().position(|t| !t.is_finite()))
    {
        return Err(error(None, ErrorKind::ObjBadUv { vertex }));
    }
    Ok(mesh)
}

/// A per-vertex attribute gathered over the models: present for every vertex or for none.
struct Attribute<T> {
    element: &'static str,
    values: Vec<T>,
    vertices: usize,
}

impl<T> Attribute<T> {
    fn new(element: &'static str) -> Self {
        Attribute { element, values: Vec::new(), vertices: 0 }
    }

    fn add(&mut self, vertices: usize, values: impl Iterator<Item = T>) {
        self.vertices += vertices;
        self.values.extend(values);
    }

    fn finish(self) -> Result<Option<Vec<T>>, ErrorKind> {
        match self.values.len() {
            0 => Ok(None),
            n if n == self.vertices => Ok(Some(self.values)),
            _ => Err(ErrorKind::ObjPartial { element: self.element }),
        }
    }
}

/// The mesh with its vertices sorted by the `v` line they come from (ties keep tobj's order), so
/// vertex `Vi` of the mesh is line `v` number `i + 1` of the file whenever each position is used
/// with one normal and one texture coordinate — as in the report's vertex tables.
fn in_file_order(mesh: Mesh, file_order: &[usize]) -> Mesh {
    let mut old_of_new: Vec<usize> = (0..mesh.vertex_count()).collect();
    old_of_new.sort_by_key(|&old| (file_order[old], old));
    let mut new_of_old = vec![0u32; old_of_new.len()];
    for (new, &old) in old_of_new.iter().enumerate() {
        new_of_old[old] = new as u32;
    }
    fn permute<T: Copy>(values: &[T], old_of_new: &[usize]) -> Vec<T> {
        old_of_new.iter().map(|&old| values[old]).collect()
    }
    let faces = mesh.faces.iter().map(|f| f.map(|i| new_of_old[i as usize])).collect();
    let mut out = Mesh::new(permute(&mesh.positions, &old_of_new), faces);
    out.normals = mesh.normals.as_deref().map(|n| permute(n, &old_of_new));
    out.uvs = mesh.uvs.as_deref().map(|t| permute(t, &old_of_new));
    out
}

/// What tobj does with face lines, in the order it does it: checks every index of every `f` and
/// `l` line (1-based; negative ones count back from the elements read so far; 0 does not exist),
/// and returns, for each vertex tobj will create, the 0-based `v` line it takes its position
/// from. tobj creates one vertex per distinct `v/vt/vn` triple of each group (`o`/`g`), in order
/// of first use.
fn scan_faces(text: &str) -> Result<Vec<usize>, (Position, ErrorKind)> {
    const ELEMENTS: [&str; 3] = ["v", "vt", "vn"];
    let mut totals = [0usize; 3];
    for line in text.lines() {
        if let Some(k) =
            line.split_whitespace().next().and_then(|w| ELEMENTS.iter().position(|e| *e == w))
        {
            totals[k] += 1;
        }
    }

    let mut read = [0usize; 3];
    let mut file_order = Vec::new();
    let mut seen: HashSet<[usize; 3]> = HashSet::new();
    let mut group_has_faces = false;
    for (line_index, line) in text.lines().enumerate() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some(word @ ("v" | "vt" | "vn")) => {
                // Lines tobj cannot parse stop the whole load, so counting every one is right.
                let k = ELEMENTS.iter().position(|e| *e == word).unwrap_or(0);
                read[k] += 1;
            }
            Some("o" | "g") if group_has_faces => {
                seen.clear();
                group_has_faces = false;
            }
            Some("f" | "l") => {
                group_has_faces = true;
                let corners: Vec<&str> = words.collect();
                let mut triples = Vec::with_capacity(corners.len());
                for corner in &corners {
                    let mut triple = [usize::MAX; 3];
                    for (k, part) in corner.split('/').enumerate().take(3) {
                        // Malformed numbers are tobj's to report (FaceParseError).
                        let Ok(index) = part.parse::<i64>() else { continue };
                        let count = if index < 0 { read[k] } else { totals[k] };
                        let resolved = if index < 0 {
                            count.checked_sub(index.unsigned_abs() as usize)
                        } else {
                            (index as usize).checked_sub(1).filter(|&i| i < count)
                        };
                        let Some(resolved) = resolved else {
                            let offset = corner.as_ptr() as usize - line.as_ptr() as usize;
                            let column = 1 + line[..offset].chars().count();
                            let position = Position { line: line_index + 1, column };
                            return Err((
                                position,
                                ErrorKind::ObjIndex { element: ELEMENTS[k], index, count },
                            ));
                        };
                        triple[k] = resolved;
                    }
                    triples.push(triple);
                }
                // Points and 2-point lines are ignored (LoadOptions::ignore_points/ignore_lines).
                if triples.len() >= 3 {
                    for triple in triples {
                        if seen.insert(triple) {
                            file_order.push(triple[0]);
                        }
                    }
                }
            }
            _ => {}
        }
    }
    Ok(file_order)
}
