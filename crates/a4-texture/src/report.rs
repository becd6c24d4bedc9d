//! The report's data for `a4`: the texture-coordinate table of every ground vertex, the
//! formula, the region, the prepared image, the student's sampler and the pixels per square.

use cg_core::glam::{Vec2, Vec3};
use cg_core::product::format_number;
use cg_core::texture::{Sampler, Texture};
use cg_harness::Text;
use cg_harness::check::guarded;
use cg_harness::report::{Missing, Part};

use crate::{Impl, RegionExt as _, Spec, SpecExt as _};

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
/// Two texture coordinates of one vertex closer than this (each component) are the same one
/// (a4's own tolerance: an honest f32 formula rounds far below it, a visible mistake far above).
const TEX_SAME: f32 = 1e-5;

/// Every ground vertex `(i, j)`, `i, j = 0…10`, j-major, with the distinct coordinates the
/// squares that use it give it, in the squares' drawing order (`j` outer, `i` inner).
fn texture_rows(coords: &crate::Coordinates) -> Vec<TexRow> {
    let n = crate::SQUARES;
    let mut rows = Vec::with_capacity(((n + 1) * (n + 1)) as usize);
    for j in 0..=n {
        for i in 0..=n {
            // (square j, square i, corner) for each square with a corner at (i, j).
            let mut uses: Vec<(u32, u32, usize)> = crate::CORNER_STEPS
                .iter()
                .enumerate()
                .filter_map(|(c, &(di, dj))| {
                    let (si, sj) = (i.checked_sub(di)?, j.checked_sub(dj)?);
                    (si < n && sj < n).then_some((sj, si, c))
                })
                .collect();
            uses.sort_unstable();
            let mut tex: Vec<Vec2> = Vec::new();
            for (sj, si, c) in uses {
                let uv = coords[si as usize][sj as usize][c];
                if !tex.iter().any(|t| (*t - uv).abs().max_element() <= TEX_SAME) {
                    tex.push(uv);
                }
            }
            let position = Vec3::new(i as f32 - 5.0, 0.0, j as f32 - 5.0);
            rows.push(TexRow { i, j, position, tex });
        }
    }
    rows
}

/// `a + b·x + …` as text: `0.25 + 0.025·i`, `0.625 − 0.025·j`, `0.025·i` (no constant 0),
/// `0.5` (no term with a zero factor).
fn linear_text(a: f32, terms: &[(f32, &str)]) -> String {
    let mut out = String::new();
    if a != 0.0 || terms.iter().all(|t| t.0 == 0.0) {
        out = format_number(a);
    }
    for &(b, x) in terms {
        if b == 0.0 {
            continue;
        }
        let magnitude = format_number(b.abs());
        out = match (out.is_empty(), b < 0.0) {
            (true, false) => format!("{magnitude}·{x}"),
            (true, true) => format!("−{magnitude}·{x}"),
            (false, false) => format!("{out} + {magnitude}·{x}"),
            (false, true) => format!("{out} − {magnitude}·{x}"),
        };
    }
    out
}

/// The formula of the texture coordinates in `i` and `j` and their range, from the spec alone:
/// the region (worked from its pixels), the orientation (where each of its corners lands) and
/// the repeat.
fn texture_formula(spec: &Spec) -> Text {
    use crate::GroundCorner;
    let size = crate::IMAGE_PIXELS as f32;
    let [x0, y0, x1, y1] = spec.region.pixels();
    let (s_min, s_max) = (x0 as f32 / size, x1 as f32 / size);
    let (t_min, t_max) = (1.0 - y1 as f32 / size, 1.0 - y0 as f32 / size);
    // Where in the region (0…1 to its right, 0…1 to its top) each block corner (p, q) shows.
    let xy = |g: GroundCorner| {
        let (x, y) = spec.corner_at(g).xy();
        (x as f32, y as f32)
    };
    let (c00, c10, c01) =
        (xy(GroundCorner::FarLeft), xy(GroundCorner::FarRight), xy(GroundCorner::NearLeft));
    // x = c00.x + (c10.x − c00.x)·p + (c01.x − c00.x)·q, and the same for y.
    let (sw, th) = (s_max - s_min, t_max - t_min);
    let s0 = s_min + sw * c00.0;
    let (sp, sq) = (sw * (c10.0 - c00.0), sw * (c01.0 - c00.0));
    let t0 = t_min + th * c00.1;
    let (tp, tq) = (th * (c10.1 - c00.1), th * (c01.1 - c00.1));
    let repeat = spec.repeat.clamp(1, crate::SQUARES);
    let k = crate::SQUARES / repeat;
    let kf = k as f32;
    let (a, b) = if repeat == 1 {
        ("i".to_owned(), "j".to_owned())
    } else {
        (format!("(i mod {k})"), format!("(j mod {k})"))
    };
    let s_pq = linear_text(s0, &[(sp, "p"), (sq, "q")]);
    let t_pq = linear_text(t0, &[(tp, "p"), (tq, "q")]);
    let s_ij = linear_text(s0, &[(sp / kf, &a), (sq / kf, &b)]);
    let t_ij = linear_text(t0, &[(tp / kf, &a), (tq / kf, &b)]);
    let n = format_number;
    let region = spec.region.name();
    let turn = match spec.rotation_deg % 360 {
        90 => ("反時計回りに 90° 回す", "turned 90° counter-clockwise"),
        180 => ("180° 回す", "turned 180°"),
        270 => ("時計回りに 90° 回す", "turned 90° clockwise"),
        _ => ("回さない", "not turned"),
    };
    let (mirror_ja, mirror_en) =
        if spec.mirrored { ("左右反転してから", "mirrored, then ") } else { ("", "") };
    let (pq_ja, pq_en, repeat_ja, repeat_en) = if repeat == 1 {
        (
            format!("p = i / {k}、q = j / {k}（地面の上の位置、0〜1）"),
            format!("p = i / {k}, q = j / {k} (where on the ground, 0…1)"),
            "繰り返しなし".to_owned(),
            "no repeat".to_owned(),
        )
    } else {
        (
            format!(
                "p = (i mod {k}) / {k}、q = (j mod {k}) / {k}（{k} × {k} マスのまとまりの中の位置、0〜1。まとまりの右端・手前の端の頂点は隣のまとまりにも属し、そちらの四角形では p = 1、q = 1 を使う）"
            ),
            format!(
                "p = (i mod {k}) / {k}, q = (j mod {k}) / {k} (where in the block of {k} × {k} squares, 0…1; a vertex on a block's right or near edge belongs to the next block too, and the squares of this block use p = 1 or q = 1 there)"
            ),
            format!("{repeat} × {repeat} 回繰り返す"),
            format!("repeated {repeat} × {repeat} times"),
        )
    };
    Text::new(
        format!(
            "頂点 (i, j)（位置 (i − 5, 0, j − 5)）のテクスチャ座標: s = {s_pq}、t = {t_pq}、{pq_ja}。i と j で書くと s = {s_ij}、t = {t_ij}。範囲: {} ≤ s ≤ {}、{} ≤ t ≤ {}（マス {region}、ピクセル x = {x0}〜{x1}、y = {y0}〜{y1}、{mirror_ja}{}、{repeat_ja}）",
            n(s_min),
            n(s_max),
            n(t_min),
            n(t_max),
            turn.0
        ),
        format!(
            "Texture coordinates of vertex (i, j) (at (i − 5, 0, j − 5)): s = {s_pq}, t = {t_pq}, {pq_en}. In i and j: s = {s_ij}, t = {t_ij}. Range: {} ≤ s ≤ {}, {} ≤ t ≤ {} (cells {region}, pixels x = {x0}…{x1}, y = {y0}…{y1}, {mirror_en}{}, {repeat_en})",
            n(s_min),
            n(s_max),
            n(t_min),
            n(t_max),
            turn.1
        ),
    )
}

/// The texture mapping from the student's a4 functions: every ground vertex `(i, j)` (j-major)
/// with its position and the distinct texture coordinates the squares that use it give it
/// (a4.t2, square by square in the order of `crate::CORNER_STEPS`); the region as the student's
/// `tex_range()` (a4.t1) gives it; the formula in `i` and `j` and the range in words, from the
/// spec; and the prepared image.
///
/// # Errors
/// a4.t1 or a4.t2 not written, panicking or giving a coordinate that is not finite.
pub fn texture(spec: &Spec, imp: &Impl) -> Result<TextureData, Missing> {
    texture_part(spec, imp).0
}

/// [`texture`] with the smaller parts it had to leave out (the sampler): the report data of
/// [`crate::A4`].
pub fn texture_part(spec: &Spec, imp: &Impl) -> Part<TextureData> {
    let fail = |task: &str, why: Text| (Err(Missing::new(task, why)), Vec::new());
    let range = match guarded(|| (imp.tex_range)(spec)) {
        Ok(r) => r,
        Err(o) => return (Err(Missing::from_outcome("a4.t1", "tex_range()", o)), Vec::new()),
    };
    if ![range.s_min, range.s_max, range.t_min, range.t_max].iter().all(|x| x.is_finite()) {
        return fail(
            "a4.t1",
            Text::new(
                "tex_range() の範囲が有限の値ではありません",
                "tex_range() gives a range that is not finite",
            ),
        );
    }
    let coords = match guarded(|| crate::coordinates(spec, imp)) {
        Ok(c) => c,
        Err(o) => return (Err(Missing::from_outcome("a4.t2", "tex_coords()", o)), Vec::new()),
    };
    for (i, column) in coords.iter().enumerate() {
        for (j, square) in column.iter().enumerate() {
            if !square.iter().all(|uv| uv.is_finite()) {
                return fail(
                    "a4.t2",
                    Text::new(
                        format!("四角形 ({i}, {j}) のテクスチャ座標が有限の値ではありません"),
                        format!("square ({i}, {j})'s texture coordinates are not finite"),
                    ),
                );
            }
        }
    }
    // a4.t3 is reported on its own: without it the coordinates and the figure still derive.
    let mut missing = Vec::new();
    let sampler = guarded(|| (imp.sampler)())
        .map_err(|o| missing.push(Missing::from_outcome("a4.t3", "sampler()", o)))
        .ok();
    let image = crate::prepared_image();
    let square = coords[0][0];
    let spread = |axis: fn(Vec2) -> f32| {
        let values = square.map(axis);
        values.iter().copied().fold(f32::MIN, f32::max)
            - values.iter().copied().fold(f32::MAX, f32::min)
    };
    let texels_per_square =
        Vec2::new(spread(|v| v.x) * image.width as f32, spread(|v| v.y) * image.height as f32);
    (
        Ok(TextureData {
            rows: texture_rows(&coords),
            formula: texture_formula(spec),
            region: (Vec2::new(range.s_min, range.t_min), Vec2::new(range.s_max, range.t_max)),
            image,
            sampler: sampler.map(crate::core_sampler),
            texels_per_square,
        }),
        missing,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_core::lang::Lang;

    // --- a4 ------------------------------------------------------------------------------

    fn range_quarter(_: &crate::Spec) -> crate::TexRange {
        crate::TexRange { s_min: 0.25, s_max: 0.5, t_min: 0.375, t_max: 0.625 }
    }

    /// Each vertex's coordinate is its own grid numbers: one coordinate per vertex.
    fn by_vertex(_: &crate::Spec, i: u32, j: u32) -> [Vec2; 4] {
        crate::CORNER_STEPS.map(|(di, dj)| Vec2::new((i + di) as f32, (j + dj) as f32))
    }

    /// Each square's corners get (10·i + j, corner): every square gives its own.
    fn by_square(_: &crate::Spec, i: u32, j: u32) -> [Vec2; 4] {
        [0.0, 1.0, 2.0, 3.0].map(|c| Vec2::new((10 * i + j) as f32, c))
    }

    fn sampler() -> crate::Sampler {
        crate::Sampler::default()
    }

    fn a4_spec() -> crate::Spec {
        // C4–D5, upright, no repeat.
        let region = crate::Region { column: 2, row: 3, columns: 2, rows: 2 };
        crate::Spec { region, rotation_deg: 0, mirrored: false, repeat: 1 }
    }

    #[test]
    fn texture_rows_list_every_vertex_with_the_coordinates_of_its_squares() {
        let spec = a4_spec();
        let imp = crate::Impl { tex_range: range_quarter, tex_coords: by_vertex, sampler };
        let t = texture(&spec, &imp).unwrap();
        assert_eq!(t.rows.len(), 121);
        assert_eq!(t.region, (Vec2::new(0.25, 0.375), Vec2::new(0.5, 0.625)));
        for (k, row) in t.rows.iter().enumerate() {
            // j-major: (0, 0), (1, 0), …, (10, 0), (0, 1), …
            assert_eq!((row.i, row.j), (k as u32 % 11, k as u32 / 11));
            assert_eq!(row.position, Vec3::new(row.i as f32 - 5.0, 0.0, row.j as f32 - 5.0));
            assert_eq!(row.tex, vec![Vec2::new(row.i as f32, row.j as f32)], "{row:?}");
        }
        assert_eq!(t.image.width, crate::IMAGE_PIXELS);

        let imp = crate::Impl { tex_coords: by_square, ..imp };
        let t = texture(&spec, &imp).unwrap();
        let row = |i: u32, j: u32| &t.rows[(j * 11 + i) as usize];
        // Vertex (5, 5) is corner 2 of square (4, 4), corner 1 of (5, 4), corner 3 of (4, 5)
        // and corner 0 of (5, 5) — in drawing order (j outer, i inner).
        assert_eq!(
            row(5, 5).tex,
            vec![
                Vec2::new(44.0, 2.0),
                Vec2::new(54.0, 1.0),
                Vec2::new(45.0, 3.0),
                Vec2::new(55.0, 0.0)
            ]
        );
        assert_eq!(row(0, 0).tex, vec![Vec2::new(0.0, 0.0)]);
        assert_eq!(row(10, 10).tex, vec![Vec2::new(99.0, 2.0)]);
        // An edge vertex: (10, 3) is corner 2 of square (9, 2) and corner 3 of (9, 3).
        assert_eq!(row(10, 3).tex, vec![Vec2::new(92.0, 2.0), Vec2::new(93.0, 3.0)]);
    }

    #[test]
    fn the_formula_reads_the_spec() {
        // Upright C4–D5 (s 0.25…0.5, t 0.375…0.625) over the 10 squares: s grows with i, t
        // shrinks with j (the image's top is away from the camera).
        let f = texture_formula(&a4_spec());
        assert!(f.en.contains("s = 0.25 + 0.025·i, t = 0.625 − 0.025·j"), "{}", f.en);
        assert!(f.en.contains("0.25 ≤ s ≤ 0.5, 0.375 ≤ t ≤ 0.625"), "{}", f.en);
        assert!(f.ja.contains("s = 0.25 + 0.025·i、t = 0.625 − 0.025·j"), "{}", f.ja);
        // A quarter turn counter-clockwise, 2 × 2 blocks of 5: the region's top points to −x,
        // so s follows j backwards... worked by hand: corner (p, q) shows region point
        // (1 − q, 1 − p): s = 0.5 − 0.25·q, t = 0.625 − 0.25·p.
        let spec = crate::Spec { rotation_deg: 90, repeat: 2, ..a4_spec() };
        let f = texture_formula(&spec);
        assert!(f.en.contains("s = 0.5 − 0.25·q, t = 0.625 − 0.25·p"), "{}", f.en);
        assert!(f.en.contains("s = 0.5 − 0.05·(j mod 5), t = 0.625 − 0.05·(i mod 5)"), "{}", f.en);
        // G7–H8 (s 0.75…1, t 0…0.25) turned 90° clockwise: the region's top points to +x (t
        // grows with i), its right towards the camera (s grows with j); no constant 0.
        let region = crate::Region { column: 6, row: 6, columns: 2, rows: 2 };
        let spec = crate::Spec { region, rotation_deg: 270, ..a4_spec() };
        let f = texture_formula(&spec);
        assert!(f.en.contains("s = 0.75 + 0.025·j, t = 0.025·i"), "{}", f.en);
        assert_eq!(linear_text(0.0, &[(-0.5, "p"), (0.0, "q")]), "−0.5·p");
        assert_eq!(linear_text(0.0, &[(0.0, "p")]), "0");
    }

    #[allow(clippy::todo)]
    fn coords_todo(_: &crate::Spec, _: u32, _: u32) -> [Vec2; 4] {
        todo!("a4.t2: the texture coordinates")
    }

    #[allow(clippy::todo)]
    fn sampler_todo() -> crate::Sampler {
        todo!("a4.t3: the sampler")
    }

    #[test]
    fn the_sampler_and_the_pixels_per_square_derive_and_a_missing_sampler_is_named() {
        // by_vertex gives square (0, 0) the corners (0, 0)…(1, 1): one unit of s and t, times the
        // prepared image's size.
        let imp = crate::Impl { tex_range: range_quarter, tex_coords: by_vertex, sampler };
        let (t, missing) = texture_part(&a4_spec(), &imp);
        let t = t.unwrap();
        assert!(missing.is_empty(), "{missing:?}");
        assert_eq!(t.sampler, Some(cg_core::texture::Sampler::default()));
        let image = crate::prepared_image();
        assert_eq!(t.texels_per_square, Vec2::new(image.width as f32, image.height as f32));
        // Without a4.t3 the coordinates still derive; the sampler is named as missing.
        let imp = crate::Impl { sampler: sampler_todo, ..imp };
        let (t, missing) = texture_part(&a4_spec(), &imp);
        assert_eq!(t.unwrap().sampler, None);
        assert_eq!(missing.iter().map(|m| m.task.as_str()).collect::<Vec<_>>(), ["a4.t3"]);
        assert!(missing[0].message(Lang::En).contains("sampler()"), "{:?}", missing[0]);
    }

    #[test]
    fn a_stub_coordinate_function_is_missing() {
        let imp = crate::Impl { tex_range: range_quarter, tex_coords: coords_todo, sampler };
        let m = texture(&a4_spec(), &imp).unwrap_err();
        assert_eq!(m.task, "a4.t2");
    }
}
