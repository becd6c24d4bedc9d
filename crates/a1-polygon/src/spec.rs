//! The per-student variant: which polyhedron, its dimensions, the vertex numbering rule and its
//! placement in the world — and the expected vertex positions the checks compare with.
//!
//! **Frozen** (table version 1): the tables and the order of the draws in [`variant`] must never
//! change; a published assignment never changes under a student.

use cg_core::glam::{DVec3, Vec3};
use cg_core::lang::{Text, t};
use cg_harness::VariantRng;
use easy_ext::ext;

pub use cg_student::a1::{Numbering, Order, Placement, RidgeAxis, Shape, Spec, Turn};

// ---------------------------------------------------------------------------------------------
// The frozen tables of version 1.

const RADII: [f32; 4] = [1.0, 1.2, 1.5, 2.0];
const HEIGHTS: [f32; 4] = [1.5, 2.0, 2.5, 3.0];
const FRUSTUM_BOTTOM: [f32; 2] = [1.5, 2.0];
const FRUSTUM_TOP: [f32; 3] = [0.5, 0.8, 1.0];
const FRUSTUM_HEIGHT: [f32; 3] = [1.0, 1.5, 2.0];
const TOWER_RADII: [f32; 3] = [0.6, 0.8, 1.0];
const TOWER_HEIGHT: [f32; 3] = [1.5, 2.0, 2.5];
const TOWER_TIP: [f32; 3] = [0.8, 1.0, 1.2];
const BIPYRAMID_RADII: [f32; 3] = [1.0, 1.2, 1.5];
const BIPYRAMID_LOWER: [f32; 2] = [0.8, 1.0];
const BIPYRAMID_UPPER: [f32; 3] = [1.5, 2.0, 2.5];
const OCTAHEDRON_RADII: [f32; 3] = [1.0, 1.2, 1.5];
const HOUSE_WIDTH: [f32; 3] = [2.0, 2.4, 3.0];
const HOUSE_DEPTH: [f32; 3] = [1.6, 2.0, 2.4];
const HOUSE_WALL: [f32; 3] = [1.2, 1.5, 2.0];
const HOUSE_ROOF: [f32; 3] = [0.6, 0.8, 1.0];
const WEDGE_WIDTH: [f32; 3] = [2.0, 2.5, 3.0];
const WEDGE_DEPTH: [f32; 2] = [1.5, 2.0];
const WEDGE_HEIGHT: [f32; 3] = [1.0, 1.5, 2.0];
/// World X and Z of the model's origin (never 0, so a forgotten translation shows).
const POSITIONS: [f32; 8] = [-2.0, -1.5, -1.0, -0.5, 0.5, 1.0, 1.5, 2.0];
/// The hover height of the models that end in a point at the bottom.
const HOVER: [f32; 2] = [0.5, 1.0];

/// The number of shape families in table version 1, in the order [`variant`] draws them.
pub const FAMILIES: [&str; 8] =
    ["pyramid", "prism", "frustum", "tower", "bipyramid", "octahedron", "house", "wedge"];

/// The student's variant, drawn from the frozen stream of their number and table version.
///
/// Draws, in this order: the family (uniform over [`FAMILIES`]); its dimensions from small
/// tables of friendly values (sides uniform in 3–8, 3–6 for a bipyramid); the numbering (order,
/// then ring direction); the placement (x, z, the angle `15°·k` with k in 1–23 except 12, so
/// never 0° or 180°; then the hover height for a bipyramid or octahedron).
#[must_use]
pub fn variant(rng: &mut VariantRng) -> Spec {
    let sides = |rng: &mut VariantRng, max: i64| rng.range(3, max) as u32;
    let shape = match rng.below(FAMILIES.len() as u64) {
        0 => Shape::Pyramid {
            sides: sides(rng, 8),
            radius: *rng.pick(&RADII),
            height: *rng.pick(&HEIGHTS),
        },
        1 => Shape::Prism {
            sides: sides(rng, 8),
            radius: *rng.pick(&RADII),
            height: *rng.pick(&HEIGHTS),
        },
        2 => Shape::Frustum {
            sides: sides(rng, 8),
            bottom_radius: *rng.pick(&FRUSTUM_BOTTOM),
            top_radius: *rng.pick(&FRUSTUM_TOP),
            height: *rng.pick(&FRUSTUM_HEIGHT),
        },
        3 => Shape::Tower {
            sides: sides(rng, 8),
            radius: *rng.pick(&TOWER_RADII),
            height: *rng.pick(&TOWER_HEIGHT),
            tip_height: *rng.pick(&TOWER_TIP),
        },
        4 => Shape::Bipyramid {
            sides: sides(rng, 6),
            radius: *rng.pick(&BIPYRAMID_RADII),
            lower_height: *rng.pick(&BIPYRAMID_LOWER),
            upper_height: *rng.pick(&BIPYRAMID_UPPER),
        },
        5 => Shape::Octahedron { radius: *rng.pick(&OCTAHEDRON_RADII) },
        6 => Shape::House {
            width: *rng.pick(&HOUSE_WIDTH),
            depth: *rng.pick(&HOUSE_DEPTH),
            wall_height: *rng.pick(&HOUSE_WALL),
            roof_height: *rng.pick(&HOUSE_ROOF),
            ridge: *rng.pick(&[RidgeAxis::X, RidgeAxis::Z]),
        },
        _ => Shape::Wedge {
            width: *rng.pick(&WEDGE_WIDTH),
            depth: *rng.pick(&WEDGE_DEPTH),
            height: *rng.pick(&WEDGE_HEIGHT),
        },
    };
    let numbering = Numbering {
        order: *rng.pick(&[Order::BottomUp, Order::TopDown]),
        ring: *rng.pick(&[Turn::Ccw, Turn::Cw]),
    };
    let x = *rng.pick(&POSITIONS);
    let z = *rng.pick(&POSITIONS);
    let k = rng.range(1, 22);
    let angle_deg = 15.0 * (if k >= 12 { k + 1 } else { k }) as f32;
    let y = if shape.pointed_bottom() { *rng.pick(&HOVER) } else { 0.0 };
    Spec { shape, numbering, placement: Placement { x, y, z, angle_deg } }
}

// ---------------------------------------------------------------------------------------------
// The shape's parts and the expected vertices (the checks' oracle).

/// What kind of part a group of vertices is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PartKind {
    /// One point (an apex).
    Point,
    /// Two points on a line parallel to an axis, the + end first.
    Pair,
    /// The corners of a regular polygon, the corner on +X first.
    Polygon,
    /// The corners of an axis-aligned rectangle, the corner at (+X, +Z) first.
    Rectangle,
}

/// One part of the model, listed bottom up, ring corners counter-clockwise seen from above.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    pub kind: PartKind,
    /// Its name, in Japanese and English.
    pub name: (&'static str, &'static str),
    /// Its height.
    pub y: f32,
    /// Its points, in the counter-clockwise order.
    pub points: Vec<Vec3>,
}

/// Japanese numerals for polygon names (三角形, 六角すい).
pub(crate) fn kanji(n: u32) -> &'static str {
    ["〇", "一", "二", "三", "四", "五", "六", "七", "八", "九"]
        .get(n as usize)
        .copied()
        .unwrap_or("多")
}

/// The ring of `n` corners at height `y` and circumradius `r`, counter-clockwise seen from
/// above, corner k at 360°·k/n from +X. Computed in f64 with exact quarter turns, like
/// [`cg_core::shapes`].
fn ring(n: u32, r: f32, y: f32) -> Vec<Vec3> {
    (0..n)
        .map(|k| {
            let (c, s) = if (4 * k) % n == 0 {
                [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][((4 * k / n) % 4) as usize]
            } else {
                let a = std::f64::consts::TAU * f64::from(k) / f64::from(n);
                (a.cos(), a.sin())
            };
            let r = f64::from(r);
            DVec3::new(r * c, f64::from(y), -r * s).as_vec3() + Vec3::ZERO
        })
        .collect()
}

/// The corners of the `width` × `depth` rectangle at height `y`, from (+X, +Z) counter-clockwise
/// seen from above.
fn rectangle(width: f32, depth: f32, y: f32) -> Vec<Vec3> {
    let (x, z) = (width / 2.0, depth / 2.0);
    vec![Vec3::new(x, y, z), Vec3::new(x, y, -z), Vec3::new(-x, y, -z), Vec3::new(-x, y, z)]
}

/// What the kit derives from a shape (trusted side): its parts, counts, height and name.
#[ext(ShapeExt)]
pub impl Shape {
    /// Whether the model ends in a point at the bottom (it hovers above the ground).
    fn pointed_bottom(&self) -> bool {
        matches!(self, Shape::Bipyramid { .. } | Shape::Octahedron { .. })
    }

    /// The shape's parts, bottom up. Regular polygons come from [`cg_core::shapes`] where the
    /// core has the shape (pyramid, prism, frustum, octahedron; shifted so the bottom is at
    /// y = 0), so the oracle does not share code with the reference solution.
    fn parts(&self) -> Vec<Part> {
        use cg_core::shapes;
        let polygon =
            |name, y: f32, points: Vec<Vec3>| Part { kind: PartKind::Polygon, name, y, points };
        let point = |name, p: Vec3| Part { kind: PartKind::Point, name, y: p.y, points: vec![p] };
        // The core centres its shapes on the origin: lift them by `dy`. (The tables only hold
        // valid sizes; should a hand-made spec not, the vertices come from `ring` instead.)
        let core = |mesh: Result<cg_core::mesh::Mesh, shapes::ShapeError>,
                    dy: f32,
                    fallback: &dyn Fn() -> Vec<Vec3>| {
            match mesh {
                Ok(m) => m.positions.iter().map(|p| *p + Vec3::new(0.0, dy, 0.0)).collect(),
                Err(_) => fallback(),
            }
        };
        match *self {
            Shape::Pyramid { sides, radius, height } => {
                let p = core(shapes::pyramid(sides, radius, height), height / 2.0, &|| {
                    ring(sides, radius, 0.0)
                });
                let n = (sides as usize).min(p.len());
                vec![
                    polygon(("底面", "the base"), 0.0, p[..n].to_vec()),
                    point(("頂点（先端）", "the apex"), Vec3::new(0.0, height, 0.0)),
                ]
            }
            Shape::Prism { sides, radius, height } => {
                let p = core(shapes::prism(sides, radius, height), height / 2.0, &|| {
                    [ring(sides, radius, 0.0), ring(sides, radius, height)].concat()
                });
                let n = (sides as usize).min(p.len());
                vec![
                    polygon(("底面", "the bottom"), 0.0, p[..n].to_vec()),
                    polygon(("上面", "the top"), height, p[n..].to_vec()),
                ]
            }
            Shape::Frustum { sides, bottom_radius, top_radius, height } => {
                let p = core(
                    shapes::frustum(sides, bottom_radius, top_radius, height),
                    height / 2.0,
                    &|| [ring(sides, bottom_radius, 0.0), ring(sides, top_radius, height)].concat(),
                );
                let n = (sides as usize).min(p.len());
                vec![
                    polygon(("底面", "the bottom"), 0.0, p[..n].to_vec()),
                    polygon(("上面", "the top"), height, p[n..].to_vec()),
                ]
            }
            Shape::Tower { sides, radius, height, tip_height } => vec![
                polygon(("底面", "the bottom"), 0.0, ring(sides, radius, 0.0)),
                polygon(("胴の上端", "the shaft's top"), height, ring(sides, radius, height)),
                point(("先端", "the tip"), Vec3::new(0.0, height + tip_height, 0.0)),
            ],
            Shape::Bipyramid { sides, radius, lower_height, upper_height } => vec![
                point(("下の頂点", "the lower apex"), Vec3::ZERO),
                polygon(("中央", "the middle"), lower_height, ring(sides, radius, lower_height)),
                point(
                    ("上の頂点", "the upper apex"),
                    Vec3::new(0.0, lower_height + upper_height, 0.0),
                ),
            ],
            Shape::Octahedron { radius } => {
                let p = core(shapes::octahedron(radius), radius, &|| {
                    let mut p = vec![Vec3::ZERO];
                    p.extend(ring(4, radius, radius));
                    p.push(Vec3::new(0.0, 2.0 * radius, 0.0));
                    p
                });
                vec![
                    point(("下の頂点", "the lower vertex"), p[0]),
                    polygon(("中央", "the middle"), radius, p[1..5].to_vec()),
                    point(("上の頂点", "the upper vertex"), p[5]),
                ]
            }
            Shape::House { width, depth, wall_height, roof_height, ridge } => {
                let top = wall_height + roof_height;
                let ends = match ridge {
                    RidgeAxis::X => {
                        vec![Vec3::new(width / 2.0, top, 0.0), Vec3::new(-width / 2.0, top, 0.0)]
                    }
                    RidgeAxis::Z => {
                        vec![Vec3::new(0.0, top, depth / 2.0), Vec3::new(0.0, top, -depth / 2.0)]
                    }
                };
                vec![
                    Part {
                        kind: PartKind::Rectangle,
                        name: ("床の四隅", "the floor corners"),
                        y: 0.0,
                        points: rectangle(width, depth, 0.0),
                    },
                    Part {
                        kind: PartKind::Rectangle,
                        name: ("軒（壁の上端）の四隅", "the eave corners (tops of the walls)"),
                        y: wall_height,
                        points: rectangle(width, depth, wall_height),
                    },
                    Part {
                        kind: PartKind::Pair,
                        name: ("棟の両端", "the ends of the ridge"),
                        y: top,
                        points: ends,
                    },
                ]
            }
            Shape::Wedge { width, depth, height } => vec![
                Part {
                    kind: PartKind::Rectangle,
                    name: ("底面の四隅", "the bottom corners"),
                    y: 0.0,
                    points: rectangle(width, depth, 0.0),
                },
                Part {
                    kind: PartKind::Pair,
                    name: (
                        "上の辺（−X 側の壁の上端）の両端",
                        "the ends of the top edge (the top of the wall on −X)",
                    ),
                    y: height,
                    points: vec![
                        Vec3::new(-width / 2.0, height, depth / 2.0),
                        Vec3::new(-width / 2.0, height, -depth / 2.0),
                    ],
                },
            ],
        }
    }

    /// The number of vertices.
    fn vertex_count(&self) -> usize {
        self.parts().iter().map(|p| p.points.len()).sum()
    }

    /// The number of triangles of any closed triangulation of the surface with these vertices:
    /// `2·V − 4` (Euler's formula V − E + F = 2 with 3F = 2E).
    fn face_count(&self) -> usize {
        (2 * self.vertex_count()).saturating_sub(4)
    }

    /// The extent of the model along Y.
    fn height(&self) -> f32 {
        self.parts().last().map_or(0.0, |p| p.y)
    }

    /// The shape's name, `六角すい` / `hexagonal pyramid`.
    fn name(&self) -> Text {
        let gon = |n: u32| match n {
            3 => "triangular",
            4 => "square",
            5 => "pentagonal",
            6 => "hexagonal",
            7 => "heptagonal",
            8 => "octagonal",
            _ => "polygonal",
        };
        match self {
            Shape::Pyramid { sides, .. } => {
                Text::new(format!("{}角すい", kanji(*sides)), format!("{} pyramid", gon(*sides)))
            }
            Shape::Prism { sides, .. } => {
                Text::new(format!("{}角柱", kanji(*sides)), format!("{} prism", gon(*sides)))
            }
            Shape::Frustum { sides, .. } => Text::new(
                format!("{}角すい台", kanji(*sides)),
                format!("{} frustum (truncated pyramid)", gon(*sides)),
            ),
            Shape::Tower { sides, .. } => {
                let (g, a) = (gon(*sides), if gon(*sides).starts_with('o') { "an" } else { "a" });
                Text::new(
                    format!("塔（{}角柱の上に{}角すいを載せた形）", kanji(*sides), kanji(*sides)),
                    format!("tower ({a} {g} prism with {a} {g} pyramid on top)"),
                )
            }
            Shape::Bipyramid { sides, .. } => Text::new(
                format!("双{}角すい", kanji(*sides)),
                format!("{} bipyramid", gon(*sides)),
            ),
            Shape::Octahedron { .. } => t("正八面体", "regular octahedron"),
            Shape::House { .. } => {
                t("家（直方体に切妻屋根を載せた形）", "house (a box with a gable roof)")
            }
            Shape::Wedge { .. } => t("くさび形（スロープ）", "wedge (a ramp)"),
        }
    }
}

/// The numbering rule applied to a shape's parts (trusted side).
#[ext(NumberingExt)]
pub impl Numbering {
    /// `parts` (bottom up, rings counter-clockwise) numbered by this rule.
    fn apply(&self, parts: &[Part]) -> Vec<Vec3> {
        let ordered: Vec<&Part> = match self.order {
            Order::BottomUp => parts.iter().collect(),
            Order::TopDown => parts.iter().rev().collect(),
        };
        let mut out = Vec::new();
        for part in ordered {
            let ring = matches!(part.kind, PartKind::Polygon | PartKind::Rectangle);
            if ring && self.ring == Turn::Cw {
                // The same first corner, the others the other way round.
                out.push(part.points[0]);
                out.extend(part.points[1..].iter().rev());
            } else {
                out.extend(&part.points);
            }
        }
        out
    }

    /// Every numbering rule there is (for diagnosing a student's order).
    fn all() -> [Numbering; 4] {
        let n = |order, ring| Numbering { order, ring };
        [
            n(Order::BottomUp, Turn::Ccw),
            n(Order::BottomUp, Turn::Cw),
            n(Order::TopDown, Turn::Ccw),
            n(Order::TopDown, Turn::Cw),
        ]
    }

    /// The rule in a few words: `bottom up, rings counter-clockwise seen from above`.
    fn short(&self) -> Text {
        let order = match self.order {
            Order::BottomUp => t("下から上へ", "bottom up"),
            Order::TopDown => t("上から下へ", "top down"),
        };
        let ring = match self.ring {
            Turn::Ccw => t("上から見て反時計回り", "counter-clockwise seen from above"),
            Turn::Cw => t("上から見て時計回り", "clockwise seen from above"),
        };
        Text::new(
            format!("{}、各周は{}", order.ja, ring.ja),
            format!("{}, rings {}", order.en, ring.en),
        )
    }
}

/// The expected vertex positions (trusted side: the checks' oracle).
#[ext(SpecExt)]
pub impl Spec {
    /// The expected vertex positions in model space, in the required numbering.
    fn expected_vertices(&self) -> Vec<Vec3> {
        self.numbering.apply(&self.shape.parts())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cg_harness::{StudentNumber, TableVersion};

    fn spec(shape: Shape, order: Order, ring: Turn) -> Spec {
        Spec {
            shape,
            numbering: Numbering { order, ring },
            placement: Placement { x: 1.0, y: 0.0, z: -1.0, angle_deg: 30.0 },
        }
    }

    #[test]
    fn english_names_take_their_article() {
        let tower = |sides| Shape::Tower { sides, radius: 1.0, height: 1.0, tip_height: 1.0 };
        assert_eq!(
            tower(8).name().en,
            "tower (an octagonal prism with an octagonal pyramid on top)"
        );
        assert_eq!(tower(6).name().en, "tower (a hexagonal prism with a hexagonal pyramid on top)");
    }

    #[test]
    fn rings_start_on_plus_x_and_turn_as_told() {
        let s =
            spec(Shape::Pyramid { sides: 4, radius: 1.0, height: 2.0 }, Order::TopDown, Turn::Ccw);
        let v = s.expected_vertices();
        assert_eq!(v[0], Vec3::new(0.0, 2.0, 0.0));
        assert_eq!(v[1], Vec3::X);
        // Counter-clockwise seen from above: +X, then −Z.
        assert_eq!(v[2], Vec3::NEG_Z);
        let s = Spec { numbering: Numbering { order: Order::BottomUp, ring: Turn::Cw }, ..s };
        let v = s.expected_vertices();
        assert_eq!(v[0], Vec3::X);
        assert_eq!(v[1], Vec3::Z);
        assert_eq!(v[4], Vec3::new(0.0, 2.0, 0.0));
    }

    #[test]
    fn json_shows_the_tables_friendly_numbers() {
        let s = spec(
            Shape::House {
                width: 2.4,
                depth: 1.6,
                wall_height: 1.2,
                roof_height: 0.6,
                ridge: RidgeAxis::Z,
            },
            Order::BottomUp,
            Turn::Cw,
        );
        let json = serde_json::to_value(s).unwrap();
        assert_eq!(json["shape"]["kind"], "house");
        assert_eq!(json["shape"]["depth"], serde_json::json!(1.6));
        assert_eq!(json["shape"]["roof_height"], serde_json::json!(0.6));
        assert_eq!(json["shape"]["ridge"], "z");
        assert_eq!(json["numbering"]["ring"], "cw");
        assert_eq!(json["placement"]["angle_deg"], serde_json::json!(30.0));
    }

    #[test]
    fn counts_follow_euler() {
        let cases = [
            (Shape::Pyramid { sides: 5, radius: 1.0, height: 2.0 }, 6, 8),
            (Shape::Prism { sides: 6, radius: 1.0, height: 2.0 }, 12, 20),
            (Shape::Tower { sides: 3, radius: 1.0, height: 2.0, tip_height: 1.0 }, 7, 10),
            (
                Shape::Bipyramid { sides: 5, radius: 1.0, lower_height: 1.0, upper_height: 2.0 },
                7,
                10,
            ),
            (Shape::Octahedron { radius: 1.0 }, 6, 8),
            (
                Shape::House {
                    width: 2.0,
                    depth: 2.0,
                    wall_height: 1.0,
                    roof_height: 1.0,
                    ridge: RidgeAxis::Z,
                },
                10,
                16,
            ),
            (Shape::Wedge { width: 2.0, depth: 1.5, height: 1.0 }, 6, 8),
        ];
        for (shape, v, f) in cases {
            assert_eq!((shape.vertex_count(), shape.face_count()), (v, f), "{shape:?}");
        }
    }

    #[test]
    fn every_option_appears_among_a_few_dozen_students() {
        let mut families = std::collections::HashSet::new();
        let mut orders = std::collections::HashSet::new();
        let mut rings = std::collections::HashSet::new();
        let mut sides = std::collections::HashSet::new();
        for n in 0..60 {
            let student: StudentNumber = format!("{:08}", 24_000_000 + n * 7).parse().unwrap();
            let s = variant(&mut VariantRng::new(&student, TableVersion::V1, crate::ID));
            let name = serde_json::to_value(s.shape).unwrap()["kind"].as_str().unwrap().to_owned();
            families.insert(name);
            orders.insert(s.numbering.order);
            rings.insert(s.numbering.ring);
            if let Shape::Prism { sides: k, .. } | Shape::Pyramid { sides: k, .. } = s.shape {
                sides.insert(k);
            }
            assert!(s.placement.angle_deg % 180.0 != 0.0);
            assert!(s.placement.x != 0.0 && s.placement.z != 0.0);
            assert_eq!(s.placement.y > 0.0, s.shape.pointed_bottom());
        }
        assert_eq!(families.len(), FAMILIES.len(), "{families:?}");
        assert_eq!((orders.len(), rings.len()), (2, 2));
        assert!(sides.len() >= 5, "{sides:?}");
    }
}
