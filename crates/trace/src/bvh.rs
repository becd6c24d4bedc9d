//! A bounding volume hierarchy (BVH, 境界ボリューム階層) over triangles, built by the *binned*
//! surface area heuristic and traversed front to back.
//!
//! ## Build: binned SAH
//!
//! A node's triangles are sorted into [`BINS`] equal bins along each of the three axes by the
//! centre of their bounding box; for each of the `BINS − 1` planes between bins the surface area
//! heuristic estimates the cost of splitting there,
//!
//! ```text
//! cost = C_trav + (N_left·A_left + N_right·A_right) / A_node      (C_trav = 0.5, one triangle test = 1)
//! ```
//!
//! (`A` the surface area of the bounding box: the chance that a ray through the node meets the
//! child), and the cheapest plane of the three axes wins. A node becomes a leaf when it holds one
//! triangle, or at most [`MAX_LEAF`] and testing them all (cost `N`) is not dearer than the best
//! split, or when all its triangle centres coincide. Below depth [`SAH_DEPTH`] nodes split at the
//! median instead, so no input makes the tree deeper than `SAH_DEPTH + 32` (the traversal stack
//! has room for that). Binning is Wald's "On fast construction of SAH-based bounding volume
//! hierarchies" (2007), as in pbrt (3rd ed., section 4.3.2): O(N) per level instead of the
//! O(N log N) of a full sweep, for trees within a few per cent of the full SAH's quality.
//! Nodes of at least 4096 triangles build their two halves on two threads (`rayon::join`); the
//! tree is the same as a one-thread build.
//!
//! ## Traversal
//!
//! Nodes are stored depth first (a node's first child follows it; the node records the second);
//! the child on the near side of the node's split axis is visited first and the ray's `t_max`
//! shrinks with each hit, so far subtrees are culled by the slab test. The slab test enlarges
//! the far distance by `1 + 2γ₃` (pbrt 3.9.2), so rounding never loses a box the ray touches.

use cg_core::glam::Vec3;

use crate::ray::{Ray, gamma};
use crate::triangle::{RaySetup, TriangleHit, intersect_triangle};

/// Bins per axis of the binned SAH build.
pub const BINS: usize = 16;
/// The most triangles a leaf holds unless they cannot be split apart (coincident centres).
pub const MAX_LEAF: usize = 4;
/// Depth below which nodes split at the median rather than by the SAH (bounds the tree depth).
pub const SAH_DEPTH: usize = 64;
/// The relative cost of visiting a node, against 1 for a triangle test.
const TRAVERSAL_COST: f32 = 0.5;
/// Nodes with at least this many triangles build their two subtrees on two threads.
const PARALLEL_MIN: usize = 4096;
/// Entries of the traversal stack: enough for `SAH_DEPTH + 32` levels.
const STACK: usize = SAH_DEPTH + 40;

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Aabb {
    min: Vec3,
    max: Vec3,
}

impl Aabb {
    const EMPTY: Aabb = Aabb { min: Vec3::INFINITY, max: Vec3::NEG_INFINITY };

    fn union(self, other: Aabb) -> Aabb {
        Aabb { min: self.min.min(other.min), max: self.max.max(other.max) }
    }

    fn grow(self, p: Vec3) -> Aabb {
        Aabb { min: self.min.min(p), max: self.max.max(p) }
    }

    fn surface_area(self) -> f32 {
        let d = self.max - self.min;
        if d.x < 0.0 { 0.0 } else { 2.0 * (d.x * d.y + d.y * d.z + d.z * d.x) }
    }

    /// The slab test (pbrt 3.9.2): whether the ray meets the box within `(t_min, t_max)`.
    #[inline]
    fn hit(self, origin: Vec3, inv_dir: Vec3, t_min: f32, t_max: f32) -> bool {
        let t0 = (self.min - origin) * inv_dir;
        let t1 = (self.max - origin) * inv_dir;
        // `min`/`max` ignore a NaN (0·∞: a ray in a slab's plane), which keeps the test conservative.
        let near = t0.min(t1).max_element().max(t_min);
        let far = (t0.max(t1) * (1.0 + 2.0 * gamma(3))).min_element().min(t_max);
        near <= far
    }
}

#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    /// Leaf: the first of its triangles. Interior: the index of the second child.
    offset: u32,
    /// Leaf: how many triangles (≥ 1). Interior: 0.
    count: u32,
    /// Interior: the split axis (0, 1, 2).
    axis: u8,
}

/// A BVH over a list of triangles, which it keeps (reordered) for the tests. Indices in results
/// are positions in the list given to [`Bvh::build`].
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    /// The triangles in leaf order.
    triangles: Vec<[Vec3; 3]>,
    /// The index each of them had in the input.
    index: Vec<u32>,
}

#[derive(Clone, Copy)]
struct PrimRef {
    bounds: Aabb,
    centroid: Vec3,
    index: u32,
}

impl Bvh {
    /// Builds the hierarchy over `triangles` by the binned SAH (see the module docs).
    ///
    /// Triangles with a non-finite corner are left out (no ray can hit them); degenerate ones are
    /// kept (the triangle test never reports them). An empty list gives an empty BVH that no
    /// ray hits.
    ///
    /// # Panics
    /// When there are more than `u32::MAX` triangles.
    #[must_use]
    pub fn build(triangles: &[[Vec3; 3]]) -> Bvh {
        let mut prims: Vec<PrimRef> = triangles
            .iter()
            .enumerate()
            .filter(|(_, t)| t.iter().all(|p| p.is_finite()))
            .map(|(i, t)| {
                let bounds = Aabb::EMPTY.grow(t[0]).grow(t[1]).grow(t[2]);
                PrimRef {
                    bounds,
                    centroid: 0.5 * (bounds.min + bounds.max),
                    index: u32::try_from(i).expect("at most u32::MAX triangles"),
                }
            })
            .collect();
        if prims.is_empty() {
            return Bvh::default();
        }
        Bvh::build_parallel(&mut prims, 0, triangles)
    }

    /// Number of triangles in the hierarchy.
    #[must_use]
    pub fn len(&self) -> usize {
        self.triangles.len()
    }

    /// Whether it holds no triangle.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty()
    }

    /// Number of nodes (interior and leaves).
    #[must_use]
    pub fn node_count(&self) -> usize {
        self.nodes.len()
    }

    /// The depth of the deepest leaf (a single leaf has depth 0; an empty BVH 0).
    #[must_use]
    pub fn depth(&self) -> usize {
        fn depth(nodes: &[Node], i: usize) -> usize {
            let n = nodes[i];
            if n.count > 0 {
                0
            } else {
                1 + depth(nodes, i + 1).max(depth(nodes, n.offset as usize))
            }
        }
        if self.nodes.is_empty() { 0 } else { depth(&self.nodes, 0) }
    }

    /// Builds the subtree over `prims` into `self` (depth first), returning its root's index.
    fn build_node(&mut self, prims: &mut [PrimRef], depth: usize, source: &[[Vec3; 3]]) -> usize {
        let node = self.nodes.len();
        match decide(prims, depth) {
            Decision::Leaf(bounds) => {
                self.nodes.push(Node { bounds, offset: 0, count: 0, axis: 0 });
                self.make_leaf(node, prims, source);
            }
            Decision::Split { bounds, axis, mid } => {
                self.nodes.push(Node { bounds, offset: 0, count: 0, axis: axis as u8 });
                let (left, right) = prims.split_at_mut(mid);
                self.build_node(left, depth + 1, source);
                let second = self.build_node(right, depth + 1, source);
                self.nodes[node].offset = second as u32;
            }
        }
        node
    }

    /// Builds the tree over `prims`, the two halves of large nodes on two threads (rayon), then
    /// joined in depth-first order: the same tree as [`Bvh::build_node`] builds alone.
    fn build_parallel(prims: &mut [PrimRef], depth: usize, source: &[[Vec3; 3]]) -> Bvh {
        let mut bvh = Bvh::default();
        if prims.len() < PARALLEL_MIN {
            bvh.build_node(prims, depth, source);
            return bvh;
        }
        match decide(prims, depth) {
            Decision::Leaf(bounds) => {
                bvh.nodes.push(Node { bounds, offset: 0, count: 0, axis: 0 });
                bvh.make_leaf(0, prims, source);
            }
            Decision::Split { bounds, axis, mid } => {
                let (l, r) = prims.split_at_mut(mid);
                let (left, right) = rayon::join(
                    || Bvh::build_parallel(l, depth + 1, source),
                    || Bvh::build_parallel(r, depth + 1, source),
                );
                let second = 1 + left.nodes.len();
                bvh.nodes.reserve(second + right.nodes.len());
                bvh.nodes.push(Node { bounds, offset: second as u32, count: 0, axis: axis as u8 });
                for (part, node_shift, triangle_shift) in
                    [(&left, 1, 0), (&right, second, left.triangles.len())]
                {
                    bvh.nodes.extend(part.nodes.iter().map(|n| Node {
                        offset: n.offset
                            + if n.count > 0 { triangle_shift } else { node_shift } as u32,
                        ..*n
                    }));
                }
                bvh.triangles = [left.triangles, right.triangles].concat();
                bvh.index = [left.index, right.index].concat();
            }
        }
        bvh
    }

    fn make_leaf(&mut self, node: usize, prims: &[PrimRef], source: &[[Vec3; 3]]) {
        self.nodes[node].offset = self.triangles.len() as u32;
        self.nodes[node].count = prims.len() as u32;
        for p in prims {
            self.triangles.push(source[p.index as usize]);
            self.index.push(p.index);
        }
    }

    /// The closest hit of `ray` with a triangle that `accept(index, &hit)` accepts (used to skip
    /// culled back faces), as the triangle's index in the list given to [`Bvh::build`] and the
    /// hit. `visited` counts the nodes whose box was tested.
    ///
    /// Ties (a ray through an edge shared by two triangles, both hit at the same `t`) go to the
    /// triangle met first in the traversal.
    pub fn closest_hit(
        &self,
        ray: &Ray,
        visited: &mut u64,
        mut accept: impl FnMut(u32, &TriangleHit) -> bool,
    ) -> Option<(u32, TriangleHit)> {
        let mut best = None;
        self.traverse(ray, visited, |setup, index, hit| {
            if accept(index, &hit) {
                setup.t_max = hit.t;
                best = Some((index, hit));
            }
            false
        });
        best
    }

    /// Whether `ray` hits any triangle (a shadow ray: stops at the first hit found). `visited`
    /// counts the nodes whose box was tested.
    pub fn any_hit(&self, ray: &Ray, visited: &mut u64) -> bool {
        let mut found = false;
        self.traverse(ray, visited, |_, _, _| {
            found = true;
            true
        });
        found
    }

    /// Visits every leaf triangle the ray hits within its (shrinking) range, nearest boxes
    /// first; `on_hit` returns `true` to stop.
    fn traverse(
        &self,
        ray: &Ray,
        visited: &mut u64,
        mut on_hit: impl FnMut(&mut RaySetup, u32, TriangleHit) -> bool,
    ) {
        if self.nodes.is_empty() {
            return;
        }
        let mut setup = RaySetup::new(ray);
        let inv_dir = ray.direction.recip();
        let negative = [inv_dir.x < 0.0, inv_dir.y < 0.0, inv_dir.z < 0.0];
        let mut stack = [0u32; STACK];
        let mut top = 0;
        let mut current = 0usize;
        loop {
            let node = self.nodes[current];
            *visited += 1;
            if node.bounds.hit(ray.origin, inv_dir, ray.t_min, setup.t_max) {
                if node.count > 0 {
                    let first = node.offset as usize;
                    for i in first..first + node.count as usize {
                        let [p0, p1, p2] = self.triangles[i];
                        if let Some(hit) = intersect_triangle(&setup, p0, p1, p2)
                            && on_hit(&mut setup, self.index[i], hit)
                        {
                            return;
                        }
                    }
                } else {
                    let (near, far) = if negative[node.axis as usize] {
                        (node.offset as usize, current + 1)
                    } else {
                        (current + 1, node.offset as usize)
                    };
                    stack[top] = far as u32;
                    top += 1;
                    current = near;
                    continue;
                }
            }
            if top == 0 {
                return;
            }
            top -= 1;
            current = stack[top] as usize;
        }
    }
}

/// What to do with a node's triangles.
enum Decision {
    /// Keep them in one leaf with these bounds.
    Leaf(Aabb),
    /// Split them, already partitioned: `..mid` to the first child, `mid..` to the second.
    Split { bounds: Aabb, axis: usize, mid: usize },
}

/// Decides whether a node over `prims` at `depth` is a leaf, and if not where it splits
/// (partitioning `prims` accordingly): by the binned SAH above [`SAH_DEPTH`], at the median of
/// the longest centroid axis below it.
fn decide(prims: &mut [PrimRef], depth: usize) -> Decision {
    let (bounds, centroids) = prims
        .iter()
        .fold((Aabb::EMPTY, Aabb::EMPTY), |(b, c), p| (b.union(p.bounds), c.grow(p.centroid)));
    let n = prims.len();
    let extent = centroids.max - centroids.min;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    if n == 1 || extent[axis] <= 0.0 {
        return Decision::Leaf(bounds);
    }
    if depth >= SAH_DEPTH {
        let mid = n / 2;
        prims.select_nth_unstable_by(mid, |a, b| a.centroid[axis].total_cmp(&b.centroid[axis]));
        return Decision::Split { bounds, axis, mid };
    }
    let binner = Binner::new(centroids);
    let Some((axis, split, cost)) = best_split(prims, bounds, &binner) else {
        return Decision::Leaf(bounds);
    };
    if n <= MAX_LEAF && n as f32 <= cost {
        return Decision::Leaf(bounds);
    }
    let mut mid = 0;
    for i in 0..n {
        if binner.bin(prims[i].centroid, axis) < split {
            prims.swap(i, mid);
            mid += 1;
        }
    }
    debug_assert!(mid > 0 && mid < n, "a split leaves both sides non-empty");
    Decision::Split { bounds, axis, mid }
}

/// Maps centroids to bins along each axis of a node's centroid bounds.
struct Binner {
    min: Vec3,
    /// `BINS / extent` per axis (0 where the extent is 0).
    scale: Vec3,
}

impl Binner {
    fn new(centroids: Aabb) -> Binner {
        let extent = centroids.max - centroids.min;
        let scale = Vec3::select(extent.cmpgt(Vec3::ZERO), BINS as f32 / extent, Vec3::ZERO);
        Binner { min: centroids.min, scale }
    }

    /// The bin (0..BINS) of centroid `c` along `axis`.
    #[inline]
    fn bin(&self, c: Vec3, axis: usize) -> usize {
        (((c[axis] - self.min[axis]) * self.scale[axis]) as usize).min(BINS - 1)
    }
}

/// The cheapest SAH split over the three axes: `(axis, first bin of the right side, cost)`, or
/// `None` when no axis has a spread of centroids. One pass over the triangles bins all three
/// axes.
fn best_split(prims: &[PrimRef], bounds: Aabb, binner: &Binner) -> Option<(usize, usize, f32)> {
    let area = bounds.surface_area();
    let mut bins = [[(Aabb::EMPTY, 0usize); BINS]; 3];
    for p in prims {
        for (axis, axis_bins) in bins.iter_mut().enumerate() {
            let b = binner.bin(p.centroid, axis);
            axis_bins[b].0 = axis_bins[b].0.union(p.bounds);
            axis_bins[b].1 += 1;
        }
    }
    let mut best: Option<(usize, usize, f32)> = None;
    for (axis, bins) in bins.iter().enumerate() {
        if binner.scale[axis] == 0.0 {
            continue;
        }
        // Sweep from the right: the area and count of bins split..BINS.
        let mut right = [(0.0f32, 0usize); BINS];
        let (mut b, mut count) = (Aabb::EMPTY, 0);
        for split in (1..BINS).rev() {
            b = b.union(bins[split].0);
            count += bins[split].1;
            right[split] = (b.surface_area(), count);
        }
        let (mut b, mut count) = (Aabb::EMPTY, 0);
        for split in 1..BINS {
            b = b.union(bins[split - 1].0);
            count += bins[split - 1].1;
            let (right_area, right_count) = right[split];
            if count == 0 || right_count == 0 {
                continue;
            }
            let cost = TRAVERSAL_COST
                + if area > 0.0 {
                    (count as f32 * b.surface_area() + right_count as f32 * right_area) / area
                } else {
                    prims.len() as f32
                };
            if best.is_none_or(|(_, _, c)| cost < c) {
                best = Some((axis, split, cost));
            }
        }
    }
    best
}
