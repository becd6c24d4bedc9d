//! The vertex stage (頂点処理): every vertex of an object transformed sixteen at a time
//! (`src/vertex_lanes.rs`), its window record made, and, under Gouraud, lit.

use cg_core::glam::Vec4;
use cg_core::light::LightCounts;
use cg_core::scene::Shading;
use cg_core::transform::transform_point;
use rayon::prelude::*;

use super::*;

/// The vertex stage over every vertex of one object, on all cores, sixteen at a time
/// (`src/vertex_lanes.rs`: model → world → view → clip, the normal, the window position and the
/// outcodes into `windows`); under Gouraud each vertex is then lit — sixteen at a time by the
/// scene's own light model, one by one by any other hook — and its colour clamped to `[0, 1]`,
/// as OpenGL clamps the lit vertex colour before interpolating it.
///
/// # Errors
/// [`RenderError::NonFinite`] naming the first vertex whose clip position is not finite.
pub(super) fn vertex_stage<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draw: &Draw<'_>,
    vertices: &mut Vec<Vertex>,
    windows: &mut Vec<Window>,
) -> Result<Stats, RenderError> {
    let prepared = &draw.prepared;
    let mesh = &prepared.mesh;
    let n = mesh.positions.len();
    let mut stats = Stats { vertices: n as u64, ..Stats::default() };
    let t = vertex_lanes::Transforms {
        model: prepared.model,
        normal: prepared.normal_matrix,
        mirrored: prepared.mirrored,
        view: frame.view,
        projection: frame.projection,
        width: frame.width as f32,
        height: frame.height as f32,
    };
    let (normals, colors, uvs) =
        (mesh.normals.as_deref(), mesh.colors.as_deref(), mesh.uvs.as_deref());
    vertices.resize(n, Vertex::default());
    windows.resize(n, Window { codes: (0, 0), screen: None });
    vertices.par_chunks_mut(LANES).zip(windows.par_chunks_mut(LANES)).enumerate().for_each(
        |(k, (vs, ws))| {
            let start = k * LANES;
            let (p, normal) = vertex_lanes::gather(&mesh.positions, normals, start, vs.len());
            let mut out = vertex_lanes::Out::default();
            vertex_lanes::transform(&t, &p, &normal, &mut out);
            for (i, (v, w)) in vs.iter_mut().zip(ws.iter_mut()).enumerate() {
                let (color, uv) = vertex_lanes::passed_on(colors, uvs, start + i);
                let p_clip = vertex_lanes::lane4(&out.p_clip, i);
                *v = Vertex {
                    p_clip,
                    p_world: vertex_lanes::lane3(&out.p_world, i),
                    n_world: vertex_lanes::lane3(&out.n_world, i),
                    color,
                    uv,
                };
                let codes = outcodes(p_clip, frame.guard);
                // Only a vertex inside the guard-band volume is ever used unclipped.
                let screen = (codes.1 == 0 && out.in_window[i]).then_some(ScreenVertex {
                    x: out.x[i],
                    y: out.y[i],
                    z: out.z[i],
                    inv_w: out.inv_w[i],
                    slot: 0,
                });
                *w = Window { codes, screen };
            }
        },
    );
    let whole_colors = colors.is_none_or(|c| c.len() == n);
    let colored = |i: usize| colors.and_then(|c| c.get(i)).copied();
    if frame.shading == Shading::Gouraud && draw.lit {
        let counts = match frame.spans.as_ref().filter(|_| whole_colors) {
            // The scene's own light model, sixteen vertices at a time (the same bits).
            Some(lights) => vertices
                .par_chunks_mut(LANES)
                .fold(LightCounts::default, |mut counts, chunk| {
                    let mut points = Points { len: chunk.len(), ..Points::default() };
                    for (i, v) in chunk.iter().enumerate() {
                        points.p.set(i, v.p_world);
                        points.n.set(i, v.n_world);
                        points.color.set(i, v.color);
                    }
                    let mut lit = V3::default();
                    let (material, has) = (&draw.material, draw.has_colors());
                    span::light(
                        &span::Stage { lights, material, colored: has },
                        &points,
                        &mut lit,
                        &mut counts,
                    );
                    for (i, v) in chunk.iter_mut().enumerate() {
                        v.color = saturate(lit.get(i));
                    }
                    counts
                })
                .reduce(LightCounts::default, |mut a, b| {
                    a += b;
                    a
                }),
            // Any other hook, one vertex at a time.
            None => vertices
                .par_iter_mut()
                .enumerate()
                .fold(LightCounts::default, |mut counts, (i, v)| {
                    let material = draw.material.with_color(colored(i));
                    v.color = saturate(frame.light(v.p_world, v.n_world, &material, &mut counts));
                    counts
                })
                .reduce(LightCounts::default, |mut a, b| {
                    a += b;
                    a
                }),
        };
        stats.add_lighting(&counts);
    }
    if let Some(i) = vertices.iter().position(|v| !v.p_clip.is_finite()) {
        // Named as the object's own mesh numbers it (the file's V-number), not as the prepared
        // mesh does (split per face for face normals, so the file's V2 may be its V4).
        let (vertex, p_clip) = first_non_finite(frame, draw).unwrap_or((i, vertices[i].p_clip));
        return Err(RenderError::NonFinite {
            object: draw.prepared.object.name.clone(),
            vertex,
            position: p_clip.to_array(),
        });
    }
    Ok(stats)
}

/// The first vertex of the object's own mesh (numbered as its file or shape numbers it) whose
/// clip position, computed as [`vertex`] computes it, is not finite; with that position. The
/// prepared mesh's positions are copies of these, so one exists whenever a prepared vertex is
/// not finite.
fn first_non_finite<L: Lighting + ?Sized>(
    frame: &Frame<'_, L>,
    draw: &Draw<'_>,
) -> Option<(usize, Vec4)> {
    let model = draw.prepared.model;
    draw.prepared.object.mesh.positions.iter().enumerate().find_map(|(i, &p_model)| {
        let p_view = transform_point(frame.view, transform_point(model, p_model));
        let p_clip = frame.projection * p_view.extend(1.0);
        (!p_clip.is_finite()).then_some((i, p_clip))
    })
}
