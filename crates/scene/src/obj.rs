//! Wavefront OBJ models via tobj: positions, and normals and texture coordinates when every face
//! corner has them (vertex colours, `v x y z r g b`, are read and ignored); all groups merged into
//! one mesh, in the file's vertex order.

use std::collections::HashSet;
use std::path::Path;

use cg_core::glam::{Vec2, Vec3};
use cg_core::math::try_normalize;
use cg_core::mesh::Mesh;

use crate::error::{ErrorKind, Position, SceneError};

pub(crate) mod polygon;

/// Reads an OBJ model from text; `path` names it in errors. See [`crate::load_obj`].
pub(crate) fn parse_obj(text: &str, path: &Path) -> Result<Mesh, SceneError> {
    check(text, path)?.load()
}

/// An OBJ file whose every line has been checked ([`check`]), and its faces counted, before
/// tobj loads it.
pub(crate) struct Checked<'a> {
    text: &'a str,
    path: &'a Path,
    scan: Scan,
}

/// Checks every line of an OBJ file and counts its faces (see [`scan`]), without loading it; an
/// error names the line and column.
pub(crate) fn check<'a>(text: &'a str, path: &'a Path) -> Result<Checked<'a>, SceneError> {
    // Before tobj sees the file: tobj's own errors name no line, and huge face indices make
    // tobj 4.0.5's index arithmetic overflow (`vn * 3 + 2`, a panic in debug builds); here every
    // line tobj would reject is an error that names the line and column.
    let scan = scan(text).map_err(|(position, kind)| SceneError {
        position: Some(position),
        ..SceneError::in_file(path, kind)
    })?;
    Ok(Checked { text, path, scan })
}

impl Checked<'_> {
    /// The faces (triangles) the model will have at most: each `f` line of n ≥ 3 corners counts
    /// n − 2, as its fan has. Exact, except that ear clipping gives fewer for a concave face with
    /// corners at one place, which it drops.
    pub(crate) fn faces(&self) -> u64 {
        self.scan.faces
    }

    /// Loads the checked file with tobj into one mesh.
    pub(crate) fn load(self) -> Result<Mesh, SceneError> {
        load(self.text, self.path, self.scan)
    }
}

/// [`Checked::load`].
fn load(text: &str, path: &Path, scan: Scan) -> Result<Mesh, SceneError> {
    let error = |position: Option<Position>, kind| SceneError {
        position,
        ..SceneError::in_file(path, kind)
    };
    let options = tobj::LoadOptions {
        // Polygons are split here (`polygon`): tobj's fan folds a concave one.
        triangulate: false,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    // Lines are given to tobj as `for_tobj` makes them, when that changes any (`scan` has
    // checked them all first).
    let surfaces: std::borrow::Cow<'_, str> = if scan.rewrite {
        text.lines().map(for_tobj).collect::<Vec<_>>().join("\n").into()
    } else {
        text.into()
    };
    // Materials come from the scene, so the `.mtl` file is never read: a missing or broken one
    // cannot stop the model from loading.
    let (models, _) =
        tobj::load_obj_buf(&mut surfaces.as_bytes(), &options, |_| Ok(Default::default()))
            .map_err(|e| error(None, ErrorKind::Obj(e)))?;
    let file_order = scan.file_order;

    let mut positions = Vec::new();
    let mut normals = Attribute::new("vn");
    let mut uvs = Attribute::new("vt");
    let mut faces = Vec::new();
    let mut splitter = polygon::Splitter::default();
    // Faces of four or more corners so far, to find the line of one that cannot be split.
    let mut polygons = 0;
    let mut corners = Vec::new();
    for model in &models {
        let m = &model.mesh;
        let base = positions.len() as u32;
        let count = m.positions.len() / 3;
        positions.extend(m.positions.chunks_exact(3).map(|p| Vec3::new(p[0], p[1], p[2])));
        normals.add(count, m.normals.chunks_exact(3).map(|n| Vec3::new(n[0], n[1], n[2])));
        uvs.add(count, m.texcoords.chunks_exact(2).map(|t| Vec2::new(t[0], t[1])));
        if m.face_arities.is_empty() {
            // Triangles only.
            faces
                .extend(m.indices.chunks_exact(3).map(|f| [f[0] + base, f[1] + base, f[2] + base]));
            continue;
        }
        let mut start = 0;
        for &arity in &m.face_arities {
            let face = &m.indices[start..start + arity as usize];
            start += arity as usize;
            corners.clear();
            corners.extend(face.iter().map(|&i| i + base));
            match corners[..] {
                // Points and lines are left out (`ignore_points`, `ignore_lines`).
                [] | [_] | [_, _] => {}
                [a, b, c] => faces.push([a, b, c]),
                _ => {
                    splitter.split(&corners, &positions, &mut faces).map_err(|problem| {
                        let kind = ErrorKind::ObjPolygon { corners: corners.len(), problem };
                        error(polygon_line(text, polygons), kind)
                    })?;
                    polygons += 1;
                }
            }
        }
    }
    if faces.is_empty() {
        return Err(error(None, ErrorKind::ObjNoFaces));
    }
    let mut mesh = Mesh::new(positions, faces);
    mesh.normals = normals.finish().map_err(|kind| error(None, kind))?;
    mesh.uvs = uvs.finish().map_err(|kind| error(None, kind))?;
    // Before the faces are renumbered (which indexes with them).
    mesh.check_indices().map_err(|e| error(None, ErrorKind::Mesh(e)))?;
    if file_order.len() == mesh.vertex_count() {
        mesh = in_file_order(mesh, &file_order);
    }
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

/// Where the face of four or more corners number `index` (0-based, in file order) begins: its
/// `f`. Looked for again only when such a face is an error.
fn polygon_line(text: &str, index: usize) -> Option<Position> {
    text.lines()
        .enumerate()
        .filter_map(|(line_index, line)| {
            let mut words = line.split_whitespace();
            let keyword = words.next().filter(|&k| k == "f")?;
            (words.count() >= 4).then(|| place(line_index, line, keyword))
        })
        .nth(index)
}

/// The place of `word`, a slice of the line `line_index` (0-based) `line`.
fn place(line_index: usize, line: &str, word: &str) -> Position {
    let offset = word.as_ptr() as usize - line.as_ptr() as usize;
    Position { line: line_index + 1, column: 1 + line[..offset].chars().count() }
}

/// The elements that face corners refer to, in the order `v/vt/vn`.
const ELEMENTS: [&str; 3] = ["v", "vt", "vn"];

/// An OBJ line as tobj is given it: a point or line element (`p`, `l`) blanked — not surfaces:
/// tobj's options drop a two-point line, but it would triangulate `l 1 2 3 4`, a wire outline,
/// into a filled polygon — and a `v` line's colour (`r g b`) cut off. The kit does not use
/// vertex colours, and tobj refuses a file where some `v` lines have one and others do not.
fn for_tobj(line: &str) -> &str {
    let mut words = line.split_whitespace();
    match words.next() {
        Some("p" | "l") => "",
        Some("v") => match (words.nth(2), words.count()) {
            // x y z r g b (`scan` has checked that there are 3, 4 or 6 values).
            (Some(z), 3) => &line[..z.as_ptr() as usize - line.as_ptr() as usize + z.len()],
            _ => line,
        },
        _ => line,
    }
}

/// An error of [`scan`]: where, and what.
type ScanError = (Position, ErrorKind);

/// What [`scan`] learns of a file on the way.
struct Scan {
    /// For each vertex tobj will create, the 0-based `v` line it takes its position from.
    file_order: Vec<usize>,
    /// The faces (triangles) of the `f` lines of three or more corners: n − 2 for n corners.
    faces: u64,
    /// Whether [`for_tobj`] changes a line (a `p` or `l` line, a `v` line with a colour).
    rewrite: bool,
}

/// Reads the file as tobj will, line by line, and reports with its line and column every line
/// that tobj would reject (or mis-read) without saying where: `v`, `vt` and `vn` lines with too
/// few numbers or a word that is not a number, a position at infinity (w = 0, or a coordinate
/// that is not finite), face corners that are not `v`, `v/vt`, `v//vn` or `v/vt/vn`, indices
/// that are not numbers, and indices that refer to no element read so far (1-based; negative
/// ones count back from the last element read; 0 does not exist; an element defined further
/// down the file does not count, as in the OBJ specification). A face of three or more corners
/// must also write every corner alike (one corner `1//1` and another `3` left tobj with normals
/// for some vertices only) and use each `v` once (`f 1 2 3 4 1 2 3 4` goes round twice).
///
/// Counts the faces on the way, without keeping anything per face, so that a model with too many
/// can be refused before tobj loads it. tobj creates one vertex per distinct `v/vt/vn` triple of
/// each group (`o`/`g`), in order of first use: [`Scan::file_order`].
fn scan(text: &str) -> Result<Scan, ScanError> {
    let mut read = [0usize; 3];
    let mut out = Scan { file_order: Vec::new(), faces: 0, rewrite: false };
    let mut seen: HashSet<[usize; 3]> = HashSet::new();
    let mut group_has_faces = false;
    // The corners of one face line, and their `v` indices sorted; kept from line to line.
    let mut corners: Vec<([usize; 3], &str)> = Vec::new();
    let mut sorted: Vec<(usize, usize)> = Vec::new();
    // Whether the first face's corners have `vt` and `vn`, and its line (1-based).
    let mut first_face: Option<([bool; 2], usize)> = None;
    for (line_index, line) in text.lines().enumerate() {
        let at = |word: &str| place(line_index, line, word);
        let mut words = line.split_whitespace();
        let Some(keyword) = words.next() else { continue };
        match keyword {
            "v" | "vt" | "vn" => {
                let k = ELEMENTS.iter().position(|e| *e == keyword).unwrap_or(0);
                let values: Vec<&str> = words.collect();
                check_values(ELEMENTS[k], keyword, &values)
                    .map_err(|(word, kind)| (at(word), kind))?;
                read[k] += 1;
                out.rewrite |= keyword == "v" && values.len() == 6;
            }
            "o" | "g" if group_has_faces => {
                seen.clear();
                group_has_faces = false;
            }
            "p" => out.rewrite = true,
            "f" | "l" => {
                let element = if keyword == "f" { "f" } else { "l" };
                out.rewrite |= keyword == "l";
                corners.clear();
                for corner in words {
                    let triple =
                        resolve(element, corner, &read).map_err(|(word, kind)| (at(word), kind))?;
                    corners.push((triple, corner));
                }
                if corners.is_empty() {
                    return Err((at(keyword), ErrorKind::ObjValues { element, found: 0 }));
                }
                group_has_faces = true;
                // Lines are left out (`for_tobj`), as are faces of fewer than three corners.
                if keyword != "f" || corners.len() < 3 {
                    continue;
                }
                check_face(&corners, &mut sorted).map_err(|(word, kind)| (at(word), kind))?;
                // Every face written as the first one is (its corners are alike by now).
                let (triple, word) = corners[0];
                let form = [triple[1] != usize::MAX, triple[2] != usize::MAX];
                let (first, first_line) = *first_face.get_or_insert((form, line_index + 1));
                if let Some(k) = (0..2).find(|&k| form[k] != first[k]) {
                    let kind = ErrorKind::ObjFaceForm {
                        element: ELEMENTS[k + 1],
                        has: form[k],
                        first_line,
                    };
                    return Err((at(word), kind));
                }
                out.faces += corners.len() as u64 - 2;
                for &(triple, _) in &corners {
                    if seen.insert(triple) {
                        out.file_order.push(triple[0]);
                    }
                }
            }
            _ => {}
        }
    }
    Ok(out)
}

/// Checks that the corners of a face (each its `v/vt/vn` indices, as [`resolve`] gives them, and
/// the word) are written alike, with or without `vt` and `vn` as the first one is, and that no
/// `v` comes twice; an error names the word of the corner that differs or comes again.
/// `sorted` is a buffer.
fn check_face<'a>(
    corners: &[([usize; 3], &'a str)],
    sorted: &mut Vec<(usize, usize)>,
) -> Result<(), (&'a str, ErrorKind)> {
    let (first, first_word) = corners[0];
    for &(triple, word) in &corners[1..] {
        for k in 1..3 {
            let has = triple[k] != usize::MAX;
            if has != (first[k] != usize::MAX) {
                let kind = ErrorKind::ObjCornerForm {
                    corner: word.to_owned(),
                    first: first_word.to_owned(),
                    element: ELEMENTS[k],
                    has,
                };
                return Err((word, kind));
            }
        }
    }
    // The first corner that repeats a `v` of an earlier one: sorted by `v`, then by corner, the
    // second of each run of equal `v`.
    sorted.clear();
    sorted.extend(corners.iter().enumerate().map(|(i, (triple, _))| (triple[0], i)));
    sorted.sort_unstable();
    let repeat = sorted.windows(2).filter(|w| w[0].0 == w[1].0).min_by_key(|w| w[1].1);
    if let Some(&[(v, first), (_, again)]) = repeat {
        let word = corners[again].1;
        let kind = ErrorKind::ObjRepeatedVertex {
            corner: word.to_owned(),
            vertex: v + 1,
            first: first + 1,
        };
        return Err((word, kind));
    }
    Ok(())
}

/// Checks the values of a `v`, `vt` or `vn` line (`keyword` is the line's first word); an error
/// names the word it is about. tobj reads `x y z` (then `w`, or `r g b`) for `v`, the first two
/// for `vt` and the first three for `vn`, ignoring the rest of those two.
fn check_values<'a>(
    element: &'static str,
    keyword: &'a str,
    values: &[&'a str],
) -> Result<(), (&'a str, ErrorKind)> {
    // A NaN or an infinity (`nan`, `inf`, `1e39`) is refused here, where the line is known.
    let number = |word: &'a str| {
        word.parse::<f32>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| (word, ErrorKind::ObjNumber { element, word: word.to_owned() }))
    };
    let needed = if element == "vt" { 2 } else { 3 };
    let read: Vec<f32> = values.iter().take(needed).map(|w| number(w)).collect::<Result<_, _>>()?;
    let too_few_or_many = || (keyword, ErrorKind::ObjValues { element, found: values.len() });
    if read.len() < needed {
        return Err(too_few_or_many());
    }
    // A normal with no direction, said at its line (it was said later as the normal of a
    // renumbered vertex, with no line).
    if element == "vn" && try_normalize(Vec3::new(read[0], read[1], read[2])).is_none() {
        return Err((values[0], ErrorKind::ObjZeroNormal));
    }
    if element != "v" {
        return Ok(());
    }
    let w = match values.len() {
        3 => 1.0,
        4 => number(values[3])?,
        6 => {
            values[3..].iter().try_for_each(|c| number(c).map(|_| ()))?;
            1.0
        }
        _ => return Err(too_few_or_many()),
    };
    // As tobj does it: each coordinate divided by w, in f32.
    let position = [read[0] / w, read[1] / w, read[2] / w];
    if w == 0.0 || !position.iter().all(|c| c.is_finite()) {
        return Err((values[0], ErrorKind::ObjPosition { position, w }));
    }
    Ok(())
}

/// The `v`, `vt` and `vn` indices (0-based, `usize::MAX` when left out) of one face corner
/// `v/vt/vn`, checked against the elements `read` so far; an error names the word it is about.
fn resolve<'a>(
    element: &'static str,
    corner: &'a str,
    read: &[usize; 3],
) -> Result<[usize; 3], (&'a str, ErrorKind)> {
    let parts: Vec<&str> = corner.split('/').collect();
    if parts.len() > 3 || parts[0].is_empty() {
        return Err((corner, ErrorKind::ObjCorner { corner: corner.to_owned() }));
    }
    let mut triple = [usize::MAX; 3];
    for (k, part) in parts.into_iter().enumerate() {
        if part.is_empty() {
            continue;
        }
        let index: i64 = part
            .parse()
            .map_err(|_| (part, ErrorKind::ObjNumber { element, word: part.to_owned() }))?;
        let count = read[k];
        let resolved = if index < 0 {
            usize::try_from(index.unsigned_abs()).ok().and_then(|back| count.checked_sub(back))
        } else {
            usize::try_from(index).ok().and_then(|i| i.checked_sub(1)).filter(|&i| i < count)
        };
        triple[k] =
            resolved.ok_or((corner, ErrorKind::ObjIndex { element: ELEMENTS[k], index, count }))?;
    }
    Ok(triple)
}
