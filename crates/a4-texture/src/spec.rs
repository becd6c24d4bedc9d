//! The variant: which part of the prepared image goes onto the ground, turned which way, and how
//! many times it repeats (the assignment text that says so is in `describe.rs`).

use cg_core::glam::{DVec2, Vec2};
use cg_core::lang::Lang;
use cg_harness::text::{Text, t};
use cg_harness::{TableVersion, VariantRng};
use easy_ext::ext;
use serde::Serialize;

pub use cg_student::a4::{CORNER_STEPS, Region, Spec};

use crate::prepared::{CELL_PIXELS, CELLS, IMAGE_PIXELS, cell_name};
use crate::{SQUARES, TexRange};

/// How many times the region repeats along each side of the ground, as drawn (table version 1,
/// frozen): once for half the students, 2 × 2 or 5 × 5 for a quarter each. Each value divides
/// the 10 squares, so every block of squares shows the whole region.
const REPEATS: [u32; 4] = [1, 1, 2, 5];

/// Region sizes in cells (each side drawn separately): smaller regions when there are 5 × 5
/// blocks, so the names stay readable. Frozen (table version 1).
const SIZES: [u32; 3] = [2, 3, 4];
/// See [`SIZES`].
const SIZES_SMALL: [u32; 2] = [1, 2];

/// Orientations `(rotation_deg, mirrored)` as drawn (table version 1, frozen): every rotation
/// twice unmirrored and once mirrored.
const ORIENTATIONS: [(u32, bool); 12] = [
    (0, false),
    (90, false),
    (180, false),
    (270, false),
    (0, false),
    (90, false),
    (180, false),
    (270, false),
    (0, true),
    (90, true),
    (180, true),
    (270, true),
];

/// Table version 2's repeat counts, each as likely; its region sizes (1–6 cells, 1–3 with 5 × 5
/// blocks); its orientations, each of the eight once. Version 2 draws from three times as many
/// variants as version 1 (20 952 against 6 984): in a class of 100, two students have the same a4
/// with a chance of about 27 % (59 % in version 1). Frozen once published.
const REPEATS_V2: [u32; 3] = [1, 2, 5];
/// See [`REPEATS_V2`].
const SIZES_V2: [u32; 6] = [1, 2, 3, 4, 5, 6];
/// See [`REPEATS_V2`].
const SIZES_SMALL_V2: [u32; 3] = [1, 2, 3];
/// See [`REPEATS_V2`].
const ORIENTATIONS_V2: [(u32, bool); 8] = [
    (0, false),
    (90, false),
    (180, false),
    (270, false),
    (0, true),
    (90, true),
    (180, true),
    (270, true),
];

/// The region's cell names and pixels, worked out from its plain data
/// ([`cg_student::a4::Region`]): what the assignment text and the messages print.
#[ext(RegionExt)]
pub impl Region {
    /// The top-left cell's name (`C4`).
    fn first(&self) -> String {
        cell_name(self.column, self.row)
    }

    /// The bottom-right cell's name (`D5`).
    fn last(&self) -> String {
        cell_name(self.column + self.columns - 1, self.row + self.rows - 1)
    }

    /// The region as a spreadsheet range, `C4–D5` (one cell: `C4`).
    fn name(&self) -> String {
        if self.columns == 1 && self.rows == 1 {
            self.first()
        } else {
            format!("{}–{}", self.first(), self.last())
        }
    }

    /// The cell at one of the region's corners.
    fn corner_cell(&self, corner: Corner) -> String {
        let (x, y) = corner.xy();
        let column = self.column + x * (self.columns - 1);
        // Up in the image (y = 1) is the region's *top* row.
        let row = self.row + (1 - y) * (self.rows - 1);
        cell_name(column, row)
    }

    /// The region in pixels, measured from the image's **top-left** corner as image viewers do:
    /// `[x_from, y_from, x_to, y_to]` (pixel edges; `x_to − x_from` pixels wide).
    fn pixels(&self) -> [u32; 4] {
        [
            self.column * CELL_PIXELS,
            self.row * CELL_PIXELS,
            (self.column + self.columns) * CELL_PIXELS,
            (self.row + self.rows) * CELL_PIXELS,
        ]
    }
}

/// The oracle of `a4.t1`, for the checks only.
#[ext(RegionOracle)]
pub(crate) impl Region {
    /// The region's texture-coordinate range, exact (multiples of 1/8): the oracle of `a4.t1`,
    /// worked from the pixels (`s = x / 512`, `t = 1 − y / 512` since `y` counts from the top).
    fn range(&self) -> TexRange {
        let [x0, y0, x1, y1] = self.pixels();
        let size = f64::from(IMAGE_PIXELS);
        let s = |x: u32| (f64::from(x) / size) as f32;
        let t = |y: u32| (1.0 - f64::from(y) / size) as f32;
        TexRange { s_min: s(x0), s_max: s(x1), t_min: t(y1), t_max: t(y0) }
    }
}

/// A corner of the region, as the image shows it (bottom = towards the image's bottom edge).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Corner {
    /// 左下
    BottomLeft,
    /// 右下
    BottomRight,
    /// 右上
    TopRight,
    /// 左上
    TopLeft,
}

impl Corner {
    /// All four, counter-clockwise from the bottom-left.
    pub const ALL: [Corner; 4] =
        [Corner::BottomLeft, Corner::BottomRight, Corner::TopRight, Corner::TopLeft];

    /// `(x, y)` in the region: `(0, 0)` bottom-left, `(1, 1)` top-right.
    #[must_use]
    pub fn xy(self) -> (u32, u32) {
        match self {
            Corner::BottomLeft => (0, 0),
            Corner::BottomRight => (1, 0),
            Corner::TopRight => (1, 1),
            Corner::TopLeft => (0, 1),
        }
    }

    /// 左下 / bottom-left, …
    #[must_use]
    pub fn name(self) -> Text {
        match self {
            Corner::BottomLeft => t("左下", "bottom-left"),
            Corner::BottomRight => t("右下", "bottom-right"),
            Corner::TopRight => t("右上", "top-right"),
            Corner::TopLeft => t("左上", "top-left"),
        }
    }
}

/// A corner of the ground: ground vertex `(i, j)` with `i, j ∈ {0, 10}`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum GroundCorner {
    /// Vertex (0, 0) at (−5, 0, −5): far left, seen from the course's camera.
    FarLeft,
    /// Vertex (10, 0) at (5, 0, −5): far right.
    FarRight,
    /// Vertex (10, 10) at (5, 0, 5): near right.
    NearRight,
    /// Vertex (0, 10) at (−5, 0, 5): near left.
    NearLeft,
}

impl GroundCorner {
    /// All four, in the order vertex (0, 0), (10, 0), (10, 10), (0, 10).
    pub const ALL: [GroundCorner; 4] = [
        GroundCorner::FarLeft,
        GroundCorner::FarRight,
        GroundCorner::NearRight,
        GroundCorner::NearLeft,
    ];

    /// `(p, q)` on the ground or a block: `0` or `1` along i and along j.
    #[must_use]
    pub fn pq(self) -> (u32, u32) {
        match self {
            GroundCorner::FarLeft => (0, 0),
            GroundCorner::FarRight => (1, 0),
            GroundCorner::NearRight => (1, 1),
            GroundCorner::NearLeft => (0, 1),
        }
    }

    /// The ground vertex `(i, j)`.
    #[must_use]
    pub fn vertex(self) -> (u32, u32) {
        let (p, q) = self.pq();
        (p * SQUARES, q * SQUARES)
    }

    /// The vertex's position `(x, z)` = `(i·1 − 5, j·1 − 5)`.
    #[must_use]
    pub fn position(self) -> (i32, i32) {
        let (i, j) = self.vertex();
        (i as i32 - 5, j as i32 - 5)
    }

    /// 奥の左 / far left, … as seen from the course's camera (in front, above, looking at −z).
    #[must_use]
    pub fn name(self) -> Text {
        match self {
            GroundCorner::FarLeft => t("奥の左", "far left"),
            GroundCorner::FarRight => t("奥の右", "far right"),
            GroundCorner::NearRight => t("手前の右", "near right"),
            GroundCorner::NearLeft => t("手前の左", "near left"),
        }
    }

    /// `vertex (i, j) = (0, 10) at (−5, 0, 5), near left seen from the camera`.
    #[must_use]
    pub fn text(self) -> Text {
        let (i, j) = self.vertex();
        let (x, z) = self.position();
        let name = self.name();
        Text::new(
            format!("頂点 (i, j) = ({i}, {j})、位置 ({x}, 0, {z})、カメラから見て{}", name.ja),
            format!(
                "vertex (i, j) = ({i}, {j}) at ({x}, 0, {z}), {} seen from the camera",
                name.en
            ),
        )
    }
}

/// The student's variant, drawn from the frozen stream of their number and table version.
///
/// Both versions draw, in this order: the repeat count; the region's width and then its height
/// in cells; its left column and then its top row, uniformly where it fits; then the
/// orientation. Table version 1 draws the repeat from [1, 1, 2, 5], the sizes from [2, 3, 4]
/// (from [1, 2] with 5 × 5 blocks) and the orientation from the 12 entries of every rotation
/// twice unmirrored and once mirrored; version 2 the repeat from [1, 2, 5], the sizes from 1–6
/// (1–3 with 5 × 5 blocks) and the orientation from the eight, each once. Never change either.
#[must_use]
pub fn variant(rng: &mut VariantRng) -> Spec {
    let v1 = rng.table() == TableVersion::V1;
    let repeat = if v1 { *rng.pick(&REPEATS) } else { *rng.pick(&REPEATS_V2) };
    let sizes: &[u32] = match (v1, repeat == 5) {
        (true, true) => &SIZES_SMALL,
        (true, false) => &SIZES,
        (false, true) => &SIZES_SMALL_V2,
        (false, false) => &SIZES_V2,
    };
    let columns = *rng.pick(sizes);
    let rows = *rng.pick(sizes);
    let column = rng.below(u64::from(CELLS - columns + 1)) as u32;
    let row = rng.below(u64::from(CELLS - rows + 1)) as u32;
    let (rotation_deg, mirrored) =
        if v1 { *rng.pick(&ORIENTATIONS) } else { *rng.pick(&ORIENTATIONS_V2) };
    Spec { region: Region { column, row, columns, rows }, rotation_deg, mirrored, repeat }
}

/// What the spec's plain data ([`cg_student::a4::Spec`]) means: where each corner of the region
/// lands, and the assignment text.
#[ext(SpecExt)]
pub impl Spec {
    /// The ground corner (of the ground, and of every block) where the region's `corner` lands:
    /// the table of the assignment text.
    ///
    /// Worked forwards, independently of the solutions: the corner as a vector from the
    /// region's centre `(±1, ±1)` is mirrored (x → −x), then turned counter-clockwise in quarter
    /// turns `(x, y) → (−y, x)`, as the camera sees the ground: screen right is +x (i grows),
    /// screen up is −z (j shrinks).
    fn ground_corner_of(&self, corner: Corner) -> GroundCorner {
        let (x, y) = corner.xy();
        let (mut dx, mut dy) = (2 * x as i32 - 1, 2 * y as i32 - 1);
        if self.mirrored {
            dx = -dx;
        }
        for _ in 0..(self.rotation_deg / 90) % 4 {
            (dx, dy) = (-dy, dx);
        }
        let p = u32::from(dx > 0);
        let q = u32::from(dy < 0); // screen up is j = 0
        GroundCorner::ALL.into_iter().find(|g| g.pq() == (p, q)).unwrap_or(GroundCorner::FarLeft)
    }

    /// The region's corner that lands on ground corner `g` (and on that corner of every block).
    fn corner_at(&self, g: GroundCorner) -> Corner {
        Corner::ALL
            .into_iter()
            .find(|&c| self.ground_corner_of(c) == g)
            .unwrap_or(Corner::BottomLeft)
    }

    /// The assignment text for this variant, in `lang`.
    fn describe(&self, lang: Lang) -> String {
        crate::describe::describe(self, lang)
    }
}

/// The oracle of `a4.t2`, for the checks and the kit's reference picture.
#[ext(SpecOracle)]
pub(crate) impl Spec {
    /// Ground squares along each side of one block (`10 / repeat`).
    fn block(&self) -> u32 {
        SQUARES / self.repeat.clamp(1, SQUARES)
    }

    /// The texture coordinate of the region's `corner`.
    fn corner_coord(&self, corner: Corner) -> Vec2 {
        let r = self.region.range();
        let (x, y) = corner.xy();
        Vec2::new(if x == 0 { r.s_min } else { r.s_max }, if y == 0 { r.t_min } else { r.t_max })
    }

    /// The expected texture coordinate at `(p, q)` of a block (`0..=1` along i and j), in f64:
    /// the bilinear blend of the coordinates its four corners must have.
    fn expected_at(&self, p: f64, q: f64) -> DVec2 {
        let at = |g: GroundCorner| self.corner_coord(self.corner_at(g)).as_dvec2();
        let (c00, c10, c11, c01) = (
            at(GroundCorner::FarLeft),
            at(GroundCorner::FarRight),
            at(GroundCorner::NearRight),
            at(GroundCorner::NearLeft),
        );
        c00 * ((1.0 - p) * (1.0 - q))
            + c10 * (p * (1.0 - q))
            + c11 * (p * q)
            + c01 * ((1.0 - p) * q)
    }

    /// What `a4.t2` must return for square `(i, j)`: its corners in drawing order, from the
    /// f64 oracle.
    fn expected_square(&self, i: u32, j: u32) -> [Vec2; 4] {
        let k = f64::from(self.block());
        CORNER_STEPS.map(|(di, dj)| {
            let p = f64::from(i % self.block() + di) / k;
            let q = f64::from(j % self.block() + dj) / k;
            self.expected_at(p, q).as_vec2()
        })
    }
}

/// The region C4–D5 (columns C–D, rows 4–5 from the top: s ∈ [2/8, 4/8], t ∈ [3/8, 5/8]) with
/// these settings (for the crate's tests).
#[cfg(test)]
pub(crate) fn spec(rotation_deg: u32, mirrored: bool, repeat: u32) -> Spec {
    let region = Region { column: 2, row: 3, columns: 2, rows: 2 };
    Spec { region, rotation_deg, mirrored, repeat }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_region_in_cells_pixels_and_texture_coordinates() {
        let r = spec(0, false, 1).region;
        assert_eq!((r.first(), r.last(), r.name()), ("C4".into(), "D5".into(), "C4–D5".into()));
        assert_eq!(r.pixels(), [128, 192, 256, 320]);
        assert_eq!(r.range(), TexRange { s_min: 0.25, s_max: 0.5, t_min: 0.375, t_max: 0.625 });
        assert_eq!(r.corner_cell(Corner::BottomLeft), "C5");
        assert_eq!(r.corner_cell(Corner::TopRight), "D4");
        let a8 = Region { column: 0, row: 7, columns: 1, rows: 1 };
        assert_eq!(a8.range(), TexRange { s_min: 0.0, s_max: 0.125, t_min: 0.0, t_max: 0.125 });
        assert_eq!(a8.name(), "A8");
    }

    /// Worked by hand from the picture of the ground seen from the camera (far edge j = 0 at
    /// the top of the screen, i growing to the right).
    #[test]
    fn corners_land_where_the_pictures_say() {
        use Corner::*;
        use GroundCorner::*;
        let cases = [
            // upright: the region's bottom-left at the near left
            ((0, false), [(BottomLeft, NearLeft), (TopLeft, FarLeft), (TopRight, FarRight)]),
            // a quarter turn counter-clockwise: its top points left, its bottom-left near right
            ((90, false), [(BottomLeft, NearRight), (TopLeft, NearLeft), (TopRight, FarLeft)]),
            ((180, false), [(BottomLeft, FarRight), (TopLeft, NearRight), (TopRight, NearLeft)]),
            ((270, false), [(BottomLeft, FarLeft), (TopLeft, FarRight), (TopRight, NearRight)]),
            // mirrored: left and right swap, top stays away from the camera
            ((0, true), [(BottomLeft, NearRight), (TopLeft, FarRight), (TopRight, FarLeft)]),
            // mirrored, then the top turned to the left
            ((90, true), [(BottomLeft, FarRight), (TopLeft, FarLeft), (TopRight, NearLeft)]),
        ];
        for ((rotation, mirrored), pairs) in cases {
            let s = spec(rotation, mirrored, 1);
            for (corner, ground) in pairs {
                assert_eq!(
                    s.ground_corner_of(corner),
                    ground,
                    "{rotation}° {mirrored}: {corner:?}"
                );
                assert_eq!(s.corner_at(ground), corner);
            }
        }
    }

    #[test]
    fn the_oracle_interpolates_each_block() {
        let s = spec(0, false, 2);
        // Upright, 2 × 2 blocks of 5 squares: vertex (0, 10) is a block's near-left corner,
        // vertex (5, 0) a block's far-left corner and the previous block's far-right one.
        assert_eq!(s.expected_square(0, 9)[1], Vec2::new(0.25, 0.375));
        assert_eq!(s.expected_square(5, 0)[0], Vec2::new(0.25, 0.625));
        assert_eq!(s.expected_square(4, 0)[3], Vec2::new(0.5, 0.625));
        // The middle of the first block, vertex (2.5, 2.5) — between squares: square (2, 2)'s
        // corner (3, 3) is 3/5 of the way.
        let c = s.expected_square(2, 2)[2];
        assert!((c - Vec2::new(0.25 + 0.6 * 0.25, 0.625 - 0.6 * 0.25)).abs().max_element() < 1e-7);
    }

    #[test]
    fn variants_are_deterministic_and_within_the_table() {
        for seed in 0..500 {
            let s = variant(&mut VariantRng::from_seed(seed));
            assert_eq!(s, variant(&mut VariantRng::from_seed(seed)));
            assert!(REPEATS.contains(&s.repeat));
            assert!(SQUARES.is_multiple_of(s.repeat));
            let r = s.region;
            assert!(r.columns >= 1 && r.rows >= 1 && r.columns <= 4 && r.rows <= 4);
            assert!(r.column + r.columns <= CELLS && r.row + r.rows <= CELLS);
            assert!(r.columns * r.rows < CELLS * CELLS, "never the whole image");
            assert!(s.rotation_deg.is_multiple_of(90) && s.rotation_deg < 360);
        }
    }
}
