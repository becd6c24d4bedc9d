//! The queue of Phong's fragments waiting to be lit ([`PhongSpan`]): their triangles'
//! attributes ([`Triangle`], with the normal [`certified`] for a triangle that has one), gathered
//! into lanes and lit sixteen at a time by [`super::shade_fragments`], then written back in the
//! order they passed the depth test.

use super::*;

/// What a Phong fragment needs of its triangle: its corners' attributes (texture coordinates
/// already shifted by the triangle's origin), made once when its first fragment passes.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Triangle {
    /// 1/w of each corner (perspective correction).
    inv_w: [f32; 3],
    p: [Vec3; 3],
    n: [Vec3; 3],
    color: [Rgb; 3],
    uv: [cg_core::glam::Vec2; 3],
    /// The face it belongs to, in its object's prepared mesh (for its face normal).
    face: u32,
    /// The normal every fragment gets, where the corners share one normal and it is
    /// [`certified`] (a face normal, a flat object's triangles).
    unit: Option<Vec3>,
}

/// The unit normal that [`interpolate_normals`] gives **every** fragment of a triangle whose three
/// corners have the normal `n` (bit for bit), or `None` where that cannot be vouched for.
///
/// With weights `w ≥ 0`, not all zero, each `nᶜ·wₖ` is exact in f64 (two f32s' product fits in
/// 48 bits) and the three have one sign, so the sum is `nᶜ·Σw` times `1 + δ`, `|δ| ≤ 2⁻⁵²`, per
/// component; normalising divides out `Σw`, and the whole fragment's arithmetic puts each
/// component within `9 · 2⁻⁵³` (relative) of the exact unit vector's, and so within `2⁻⁴⁹` of
/// `try_normalize_f64(n)`'s (itself within `6 · 2⁻⁵³`). Where that component is
/// farther than `2⁻⁴⁰` (relative) from a rounding boundary of f32, every fragment's rounding to
/// f32 gives the same value; otherwise (about one triangle in 10⁵) the fragments go the usual way.
/// The cancellation test cannot fail either: `|Σ| = Σw·|n|·(1 ± 2⁻⁵⁰)`.
pub(super) fn certified(n: Vec3) -> Option<Vec3> {
    const MARGIN: f64 = 1.0 / (1u64 << 40) as f64;
    let t = cg_core::math::try_normalize_f64(n.as_dvec3())?;
    let r = t.as_vec3();
    let sure =
        |t: f64, r: f32| (t * (1.0 + MARGIN)) as f32 == r && (t * (1.0 - MARGIN)) as f32 == r;
    (sure(t.x, r.x) && sure(t.y, r.y) && sure(t.z, r.z)).then_some(r)
}

impl Triangle {
    pub(crate) fn new(
        inv_w: [f32; 3],
        corners: [(Vec3, Vec3, Rgb, cg_core::glam::Vec2); 3],
        face: u32,
    ) -> Triangle {
        let n = corners.map(|c| c.1);
        let same =
            |a: Vec3, b: Vec3| a.to_array().map(f32::to_bits) == b.to_array().map(f32::to_bits);
        let unit = (same(n[0], n[1]) && same(n[1], n[2])).then(|| certified(n[0])).flatten();
        Triangle {
            inv_w,
            p: corners.map(|c| c.0),
            n,
            color: corners.map(|c| c.2),
            uv: corners.map(|c| c.3),
            face,
            unit,
        }
    }
}

/// A texture bound to an object, as the fragment stage applies it.
#[derive(Clone, Copy)]
pub(crate) struct Texturing<'a> {
    pub(crate) texture: &'a cg_core::texture::Texture,
    pub(crate) sampler: cg_core::texture::Sampler,
    pub(crate) env: cg_core::texture::TexEnv,
}

/// Phong's fragments waiting to be lit, up to [`LANES`] of them, all of one object, in the order
/// they passed the depth test (a later one may cover an earlier one's pixel: they are written in
/// that order, so the later wins, as drawn one by one). Each lane refers to one of the span's
/// triangles (at most one per lane).
#[derive(Default)]
pub(crate) struct PhongSpan {
    /// The object they belong to (the draw's index).
    pub(crate) object: usize,
    len: usize,
    /// Screen-space barycentrics.
    b: V3,
    /// Which of `triangles` each lane belongs to.
    slot: [u8; LANES],
    triangles: [Triangle; LANES],
    count: usize,
    /// The slot of the triangle being drawn, while it is in this span.
    current: Option<u8>,
    /// Where each goes: row and column within the tile.
    at: [(u32, u32); LANES],
    /// The attributes gathered at the last flush.
    gathered: Gathered,
    /// Whether `gathered` holds slot 0's triangle in every lane (a large triangle's spans follow
    /// one another: gathered once).
    gathered_slot_0: bool,
    /// The points to light, made at each flush (kept: nothing to clear).
    points: Points,
}

impl PhongSpan {
    /// Empty, for a new tile: as [`PhongSpan::default`], keeping the arrays (each lane's entries
    /// are written before they are read) so that nothing is cleared.
    #[inline]
    pub(crate) fn reset(&mut self) {
        self.object = 0;
        self.len = 0;
        self.count = 0;
        self.current = None;
        self.gathered_slot_0 = false;
    }

    /// A new triangle's fragments follow.
    #[inline]
    pub(crate) fn end_triangle(&mut self) {
        self.current = None;
        if self.len == 0 {
            // Only the last triangle, kept by a flush in its middle: not needed any more.
            self.count = 0;
        }
    }

    /// Whether the triangle being drawn is in the span already (else [`PhongSpan::begin`]).
    #[inline]
    pub(crate) fn has_triangle(&self) -> bool {
        self.current.is_some()
    }

    /// Registers the triangle whose fragments come next.
    pub(crate) fn begin(&mut self, triangle: Triangle) {
        if self.count == 0 {
            self.gathered_slot_0 = false;
        }
        self.triangles[self.count] = triangle;
        self.current = Some(self.count as u8);
        self.count += 1;
    }

    /// Adds a fragment of the current triangle with its screen-space barycentrics; `true` when
    /// the span is full.
    #[inline]
    pub(crate) fn push(&mut self, at: (u32, u32), b: Vec3) -> bool {
        let i = self.len;
        self.at[i] = at;
        self.b.set(i, b);
        self.slot[i] = self.current.unwrap_or(0);
        self.len += 1;
        self.len == LANES
    }

    /// Adds the fragments of a run of the current triangle — the lanes of `passed` (bit `k`:
    /// the pixel `(row, column + k)`, screen-space barycentrics lane `k` of `b`), lowest first —
    /// until the span is full: what [`PhongSpan::push`] would do pixel by pixel. Gives the lanes
    /// it did not take (none unless the span is full).
    #[inline]
    pub(crate) fn push_run(&mut self, (row, column): (u32, u32), b: &V3, passed: u32) -> u32 {
        let slot = self.current.unwrap_or(0);
        let mut left = passed;
        while left != 0 && self.len < LANES {
            let k = left.trailing_zeros() as usize;
            left &= left - 1;
            let i = self.len;
            self.at[i] = (row, column + k as u32);
            (self.b.x[i], self.b.y[i], self.b.z[i]) = (b.x[k], b.y[k], b.z[k]);
            self.slot[i] = slot;
            self.len += 1;
        }
        left
    }

    /// Whether no fragment waits (nothing to flush: the span may not name an object yet).
    #[inline]
    pub(crate) fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Whether the span holds [`LANES`] fragments (flush it before adding more).
    #[inline]
    pub(crate) fn is_full(&self) -> bool {
        self.len == LANES
    }

    /// Lights the waiting fragments and gives each its final colour — the lit colour clamped,
    /// the texture applied (when the object has one), clamped again, as the fragment stage does
    /// — through `write(row, column, colour)`, in order. `face(face)` is a face's normal.
    /// Empties the span; the triangle being drawn stays registered, as the next span's first.
    /// Gives the texture samples taken.
    #[inline]
    pub(crate) fn flush(
        &mut self,
        stage: &Stage<'_>,
        texture: Option<Texturing<'_>>,
        counts: &mut LightCounts,
        face: impl Fn(u32) -> Vec3,
        mut write: impl FnMut(u32, u32, Rgb),
    ) -> u64 {
        let len = self.len;
        if len == 0 {
            return 0;
        }
        self.gather(stage.colored);
        let (triangles, slot, at) = (&self.triangles, &self.slot, &self.at);
        light(
            stage,
            &self.b,
            len,
            &self.gathered,
            &mut self.points,
            counts,
            texture,
            |i| &triangles[usize::from(slot[i])],
            &face,
            Out::Lanes(|i, c| write(at[i].0, at[i].1, c)),
        );
        self.len = 0;
        // The triangle being drawn stays, as the next span's first: its fragments go on.
        match self.current {
            Some(k) => {
                let k = usize::from(k);
                self.triangles[0] = self.triangles[k];
                self.count = 1;
                self.current = Some(0);
                if k != 0 {
                    self.gathered_slot_0 = false;
                }
            }
            None => self.count = 0,
        }
        if texture.is_some() { len as u64 } else { 0 }
    }

    /// Whether the span holds no other triangle's fragments than the current one's (then a
    /// whole run of it may be lit at once, [`PhongSpan::light_run`]).
    #[inline]
    pub(crate) fn only_current(&self) -> bool {
        self.count == 1 && self.current == Some(0)
    }

    /// Lights a whole run of [`LANES`] fragments of the current triangle at once, without
    /// queueing it, when [`PhongSpan::only_current`] (the waiting fragments are then the same
    /// triangle's, on other pixels, so the order of the writes does not matter): screen-space
    /// barycentrics `b`, colours into `out` as [`PhongSpan::flush`] makes them. The waiting
    /// fragments stay. Gives the texture samples taken.
    pub(crate) fn light_run(
        &mut self,
        stage: &Stage<'_>,
        texture: Option<Texturing<'_>>,
        counts: &mut LightCounts,
        face: impl Fn(u32) -> Vec3,
        b: &V3,
        out: &mut [Rgb; LANES],
    ) -> u64 {
        debug_assert!(self.only_current());
        self.gather(stage.colored);
        let triangle = &self.triangles[0];
        light(
            stage,
            b,
            LANES,
            &self.gathered,
            &mut self.points,
            counts,
            texture,
            |_| triangle,
            &face,
            Out::<fn(usize, Rgb)>::Run(out),
        );
        if texture.is_some() { LANES as u64 } else { 0 }
    }

    /// The lanes' triangles' attributes into `gathered`: slot 0's in every lane where it is the
    /// only triangle (kept from the last time while it stays so), else each lane's own.
    #[inline(always)]
    fn gather(&mut self, colored: bool) {
        let g = &mut self.gathered;
        if self.count == 1 {
            // One triangle (the common case for large ones): its attributes in every lane, as
            // the last flush left them when it was the same triangle.
            if !self.gathered_slot_0 {
                self.gathered_slot_0 = true;
                let t = &self.triangles[0];
                for k in 0..3 {
                    g.inv_w[k] = [t.inv_w[k]; LANES];
                    g.p[k] = V3::splat(t.p[k]);
                    if colored {
                        g.color[k] = V3::splat(t.color[k]);
                    }
                }
                g.unit = V3::splat(t.unit.unwrap_or_default());
                g.certified = [t.unit.is_some(); LANES];
            }
        } else {
            self.gathered_slot_0 = false;
            for i in 0..LANES {
                let t = &self.triangles[usize::from(self.slot[i])];
                for k in 0..3 {
                    g.inv_w[k][i] = t.inv_w[k];
                    g.p[k].set(i, t.p[k]);
                    if colored {
                        g.color[k].set(i, t.color[k]);
                    }
                }
                g.unit.set(i, t.unit.unwrap_or_default());
                g.certified[i] = t.unit.is_some();
            }
        }
    }
}

/// Where [`light`] puts the colours.
enum Out<'a, W: FnMut(usize, Rgb)> {
    /// Lane by lane, `write(lane, colour)`.
    Lanes(W),
    /// A whole span's, in order.
    Run(&'a mut [Rgb; LANES]),
}

/// Lights the first `len` lanes at screen-space barycentrics `screen` (their triangles'
/// attributes `gathered`, lane `i`'s triangle `triangle(i)`) and gives each its final colour
/// through `out`: the lit colour clamped, the texture applied (when there is one), clamped
/// again, as the fragment stage does. `face(face)` is a face's normal.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn light<'t, W: FnMut(usize, Rgb)>(
    stage: &Stage<'_>,
    screen: &V3,
    len: usize,
    gathered: &Gathered,
    points: &mut Points,
    counts: &mut LightCounts,
    texture: Option<Texturing<'_>>,
    triangle: impl Fn(usize) -> &'t Triangle,
    face: impl Fn(u32) -> Vec3,
    mut out: Out<'_, W>,
) {
    let mut b = V3::default();
    points.len = len;
    let mut lit = V3::default();
    let mut face = |i: usize| face(triangle(i).face);
    // Each lane's corners' normals, where the fragment stage needs them.
    let mut normals = |n: &mut [V3; 3]| {
        for i in 0..LANES {
            let t = triangle(i);
            for k in 0..3 {
                n[k].set(i, t.n[k]);
            }
        }
    };
    // Without a texture, a whole span's colours may come interleaved from the kernel.
    let aos = match &mut out {
        Out::Run(run) if texture.is_none() => Some(&mut **run),
        _ => None,
    };
    let (face, normals) = (&mut face, &mut normals);
    if shade_fragments(
        stage, screen, gathered, &mut b, points, face, normals, &mut lit, aos, counts,
    ) {
        return;
    }
    let mut write = |i: usize, c: Rgb| match &mut out {
        Out::Lanes(write) => write(i, c),
        Out::Run(run) => run[i] = c,
    };
    // `lit` is clamped already (`shade_fragments`).
    match texture {
        None => {
            for i in 0..len {
                write(i, lit.get(i));
            }
        }
        Some(t) => {
            for i in 0..len {
                // Shifted by the triangle's origin (an integer under repeat): small numbers.
                let uv = &triangle(i).uv;
                let bi = b.get(i);
                let uv = bi.x * uv[0] + bi.y * uv[1] + bi.z * uv[2];
                let color = t.env.apply(lit.get(i), t.texture.sample(uv, t.sampler));
                write(i, saturate(color));
            }
        }
    }
}
