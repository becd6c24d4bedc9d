//! The per-student spec of `a3`: the extension traits on the spec types ([`WorldAxisExt`],
//! [`ShapeExt`], [`SpecExt`]), how objects are made ([`new_object`]), the common camera
//! ([`camera_product`]), the frozen variant tables and [`variant`], and the warm-up's three boxes
//! ([`warmup_objects`]).

use cg_core::glam::Vec3;
use cg_core::mesh::Mesh;
use cg_core::product::{Factor, MatrixProduct};
use cg_core::shapes;
use cg_harness::{TableVersion, VariantRng};
use easy_ext::ext;

use crate::{
    CAMERA_DISTANCE, CAMERA_PITCH_DEG, FPS, Motion, Object, SPHERE_SLICES, SPHERE_STACKS, Shape,
    Spec, Turn, WorldAxis,
};

/// Names of the axes, for the texts.
#[ext(WorldAxisExt)]
pub impl WorldAxis {
    /// `"X"`, `"Y"` or `"Z"`.
    fn name(self) -> &'static str {
        match self {
            WorldAxis::X => "X",
            WorldAxis::Y => "Y",
            WorldAxis::Z => "Z",
        }
    }
}

/// The polygon model of a [`Shape`], built from its parameters with the core's shapes (what
/// fills [`Object::mesh`]).
#[ext(ShapeExt)]
pub impl Shape {
    /// The polygon model to draw: [`shapes::cuboid`], [`shapes::pyramid`] (base at
    /// y = −height/2, apex at +height/2), [`shapes::uv_sphere`] with [`SPHERE_SLICES`] ×
    /// [`SPHERE_STACKS`], [`shapes::octahedron`].
    ///
    /// Every shape of the variant tables is valid; a shape with an invalid parameter (only
    /// possible when built by hand) gives the lecture's pyramid instead of panicking — see
    /// [`ShapeExt::try_mesh`].
    fn mesh(&self) -> Mesh {
        self.try_mesh().unwrap_or_else(|_| shapes::lecture_pyramid())
    }

    /// The polygon model, or why its parameters are invalid.
    ///
    /// # Errors
    /// A size, radius or height not finite and positive, or too few sides.
    fn try_mesh(&self) -> Result<Mesh, shapes::ShapeError> {
        match *self {
            Shape::Box { size } => shapes::cuboid(Vec3::from_array(size)),
            Shape::Pyramid { sides, radius, height } => shapes::pyramid(sides, radius, height),
            Shape::Sphere { radius } => shapes::uv_sphere(radius, SPHERE_SLICES, SPHERE_STACKS),
            Shape::Octahedron { radius } => shapes::octahedron(radius),
        }
    }

    /// Half the shape's extent along Y (how high its centre is when it rests on the ground).
    fn half_height(&self) -> f32 {
        match *self {
            Shape::Box { size } => size[1] / 2.0,
            Shape::Pyramid { height, .. } => height / 2.0,
            Shape::Sphere { radius } | Shape::Octahedron { radius } => radius,
        }
    }
}

/// An [`Object`] with its [`Object::mesh`] built from `shape` ([`ShapeExt::mesh`]): how the
/// variant generator, the warm-up and tests make objects.
#[must_use]
pub fn new_object(
    name: impl Into<String>,
    shape: Shape,
    color: [f32; 3],
    motion: Motion,
) -> Object {
    Object { name: name.into(), shape, mesh: (&shape.mesh()).into(), color, motion }
}

/// What the kit derives from a spec's periods.
#[ext(SpecExt)]
pub impl Spec {
    /// Each object's period as a multiple of the shortest common unit: the ratios the report
    /// states (`[2, 1, 4]` for 2 : 1 : 4).
    fn period_ratios(&self) -> Vec<u64> {
        let frames: Vec<u64> = self.objects.iter().map(|o| o.motion.period_frames()).collect();
        let g = frames.iter().copied().fold(0, gcd).max(1);
        frames.iter().map(|f| f / g).collect()
    }

    /// After how many seconds the whole animation repeats (the least common multiple of the
    /// periods).
    fn common_period_s(&self) -> f64 {
        let l = self.objects.iter().map(|o| o.motion.period_frames()).fold(1, lcm);
        l as f64 / f64::from(FPS)
    }
}

/// Greatest common divisor (`gcd(0, b) = b`).
pub(crate) fn gcd(a: u64, b: u64) -> u64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

/// Least common multiple (saturating).
pub(crate) fn lcm(a: u64, b: u64) -> u64 {
    if a == 0 || b == 0 { 0 } else { (a / gcd(a, b)).saturating_mul(b) }
}

/// The common camera as the report writes it: `T(0, 0, -15) · Rx(30°)`.
#[must_use]
pub fn camera_product() -> MatrixProduct {
    MatrixProduct::identity()
        .then(Factor::translate(Vec3::new(0.0, 0.0, -CAMERA_DISTANCE)))
        .then(Factor::rotate_x_deg(-CAMERA_PITCH_DEG))
}

// ---------------------------------------------------------------------------------------------
// The variant tables (version 1). FROZEN: every draw below, its order and every table entry must
// never change, or published assignments change under students. A new table is a new version.
// ---------------------------------------------------------------------------------------------

/// The unit of time (s); periods are 1–4 units.
const UNITS_S: [f32; 4] = [1.5, 2.0, 2.5, 3.0];
/// The four corner slots of fixed-position motions (x, z).
const CORNERS: [[f32; 2]; 4] = [[-3.5, -3.5], [3.5, -3.5], [-3.5, 3.5], [3.5, 3.5]];
/// Object colours by number: orange, blue, red, yellow.
const COLORS: [[f32; 3]; 4] =
    [[1.0, 0.6, 0.2], [0.3, 0.5, 1.0], [0.9, 0.3, 0.4], [0.95, 0.85, 0.3]];

const SPIN_SHAPES: [Shape; 4] = [
    Shape::Box { size: [1.2, 0.4, 0.6] },
    Shape::Box { size: [1.0, 0.6, 0.3] },
    Shape::Pyramid { sides: 4, radius: 0.6, height: 1.0 },
    Shape::Pyramid { sides: 3, radius: 0.6, height: 1.0 },
];
const SWING_IN_PLACE_SHAPES: [Shape; 2] =
    [Shape::Box { size: [1.4, 0.3, 0.5] }, Shape::Box { size: [1.2, 0.5, 0.3] }];
const BOB_SHAPES: [Shape; 3] = [
    Shape::Box { size: [0.6, 0.6, 0.6] },
    Shape::Sphere { radius: 0.4 },
    Shape::Octahedron { radius: 0.45 },
];
const HOP_SHAPES: [Shape; 3] = [
    Shape::Sphere { radius: 0.4 },
    Shape::Box { size: [0.6, 0.6, 0.6] },
    Shape::Octahedron { radius: 0.45 },
];
const ORBIT_SHAPES: [Shape; 4] = [
    Shape::Sphere { radius: 0.4 },
    Shape::Box { size: [0.6, 0.6, 0.6] },
    Shape::Octahedron { radius: 0.45 },
    Shape::Pyramid { sides: 4, radius: 0.5, height: 0.8 },
];
const PARENT_SHAPES: [Shape; 3] = [
    Shape::Sphere { radius: 0.5 },
    Shape::Box { size: [0.7, 0.7, 0.7] },
    Shape::Octahedron { radius: 0.6 },
];
const CHILD_SHAPES: [Shape; 3] = [
    Shape::Sphere { radius: 0.25 },
    Shape::Octahedron { radius: 0.3 },
    Shape::Box { size: [0.4, 0.4, 0.4] },
];
const AXES: [WorldAxis; 3] = [WorldAxis::X, WorldAxis::Y, WorldAxis::Z];
const HORIZONTAL: [WorldAxis; 2] = [WorldAxis::X, WorldAxis::Z];
const TURNS: [Turn; 2] = [Turn::Ccw, Turn::Cw];
const AMPLITUDES_DEG: [f32; 3] = [30.0, 45.0, 60.0];
const ARMS: [f32; 2] = [1.0, 1.5];
const SPANS: [f32; 3] = [2.0, 2.5, 3.0];
const HEIGHTS: [f32; 3] = [1.0, 1.5, 2.0];
const ORBIT_RADII: [f32; 3] = [1.5, 2.0, 2.5];
const PARENT_ORBIT_RADII: [f32; 2] = [2.0, 2.5];
const SATELLITE_RADII: [f32; 3] = [1.0, 1.2, 1.4];
/// The lecture's example: two orbits about the same centre with radii 1.5 and 3.
const LECTURE_RADII: (f32, f32) = (1.5, 3.0);
/// Height of orbit centres and spinning objects.
const LIFT: f32 = 1.0;

/// The kinds of motion an independent object can have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Spin,
    Swing,
    Hop,
    Orbit,
}

/// The student's variant, drawn from the frozen stream of their number and table version:
/// version 1 below, version 2 in `table2.rs` (the objects kept apart and over the ground).
#[must_use]
pub fn variant(rng: &mut VariantRng) -> Spec {
    match rng.table() {
        TableVersion::V1 => variant_v1(rng),
        TableVersion::V2 => crate::table2::variant(rng),
    }
}

/// Table version 1's variant (frozen): [`plan`], then each object's parameters in list order
/// ([`objects`]) from version 1's tables.
fn variant_v1(rng: &mut VariantRng) -> Spec {
    let plan = plan(rng);
    let both_orbit = plan.parent_kind == Kind::Orbit && plan.independent_orbit;
    objects(rng, &plan, &V1 { both_orbit })
}

/// What both table versions draw first, in this order (frozen): the time unit; the number of
/// independent objects (1 or 2); the period multipliers (a shuffle of 1–4); the independent
/// motions (a shuffle of spin, swing, hop, orbit); the parent's motion (orbit or hop); where the
/// parent and child stand in the list; the corner slots (a shuffle).
pub(crate) struct Plan {
    unit_s: f32,
    multipliers: [u32; 4],
    /// The list: the independent kinds with the (parent, child) pair at `pair_at` (the child is
    /// `None`).
    roles: Vec<Option<Kind>>,
    pair_at: usize,
    corners: [[f32; 2]; 4],
    /// The parent's motion.
    parent_kind: Kind,
    /// Whether an independent object orbits (the centre is shared with it).
    pub(crate) independent_orbit: bool,
}

/// Draws the [`Plan`].
pub(crate) fn plan(rng: &mut VariantRng) -> Plan {
    let unit_s = *rng.pick(&UNITS_S);
    let independent = rng.range(1, 2) as usize;
    let mut multipliers = [1u32, 2, 3, 4];
    rng.shuffle(&mut multipliers);
    let mut kinds = [Kind::Spin, Kind::Swing, Kind::Hop, Kind::Orbit];
    rng.shuffle(&mut kinds);
    let parent_kind = *rng.pick(&[Kind::Orbit, Kind::Hop]);
    let pair_at = rng.range(0, independent as i64) as usize;
    let mut corners = CORNERS;
    rng.shuffle(&mut corners);
    let mut roles: Vec<Option<Kind>> = kinds[..independent].iter().map(|&k| Some(k)).collect();
    roles.insert(pair_at, Some(parent_kind));
    roles.insert(pair_at + 1, None); // the child
    let independent_orbit = kinds[..independent].contains(&Kind::Orbit);
    Plan { unit_s, multipliers, roles, pair_at, corners, parent_kind, independent_orbit }
}

/// Where a table version puts things and how far they move: the draws that differ between
/// versions. Each method draws from `rng` exactly what its version's table says (or nothing).
pub(crate) trait Layout {
    /// The child's distance from its parent.
    fn satellite_radius(&self, rng: &mut VariantRng) -> f32;
    /// A swinging bob's arm.
    fn arm(&self, rng: &mut VariantRng) -> f32;
    /// A hop's span.
    fn hop_span(&self, rng: &mut VariantRng, is_parent: bool) -> f32;
    /// Whether the parent's hop goes through the centre (else it stands at a corner).
    fn parent_hops_at_centre(&self) -> bool;
    /// An orbit's radius.
    fn orbit_radius(&self, rng: &mut VariantRng, is_parent: bool) -> f32;
}

/// Version 1's layout: everything but the orbits at the corners, the lecture's two radii when
/// both the parent and an independent object orbit.
struct V1 {
    both_orbit: bool,
}

impl Layout for V1 {
    fn satellite_radius(&self, rng: &mut VariantRng) -> f32 {
        *rng.pick(&SATELLITE_RADII)
    }
    fn arm(&self, rng: &mut VariantRng) -> f32 {
        *rng.pick(&ARMS)
    }
    fn hop_span(&self, rng: &mut VariantRng, _is_parent: bool) -> f32 {
        *rng.pick(&SPANS)
    }
    fn parent_hops_at_centre(&self) -> bool {
        false
    }
    fn orbit_radius(&self, rng: &mut VariantRng, is_parent: bool) -> f32 {
        match (self.both_orbit, is_parent) {
            (true, false) => LECTURE_RADII.0,
            (true, true) => LECTURE_RADII.1,
            (false, false) => *rng.pick(&ORBIT_RADII),
            (false, true) => *rng.pick(&PARENT_ORBIT_RADII),
        }
    }
}

/// Each object's parameters in list order, the tables that differ taken from `layout`. Frozen
/// for every published version: the order of the draws below never changes.
pub(crate) fn objects(rng: &mut VariantRng, plan: &Plan, layout: &dyn Layout) -> Spec {
    let mut next_corner = 0;
    let mut corner = |y: f32| {
        let [x, z] = plan.corners[next_corner % plan.corners.len()];
        next_corner += 1;
        [x, y, z]
    };
    let mut objects: Vec<Object> = Vec::with_capacity(plan.roles.len());
    for (i, role) in plan.roles.iter().enumerate() {
        let period_s = plan.unit_s * plan.multipliers[i] as f32;
        let is_parent = i == plan.pair_at;
        let (shape, motion) = match role {
            None => {
                let shape = *rng.pick(&CHILD_SHAPES);
                let radius = layout.satellite_radius(rng);
                let turn = *rng.pick(&TURNS);
                let parent_index = plan.pair_at;
                (shape, Motion::Satellite { parent_index, radius, turn, period_s })
            }
            Some(Kind::Spin) => {
                let shape = *rng.pick(&SPIN_SHAPES);
                let axis = *rng.pick(&AXES);
                let turn = *rng.pick(&TURNS);
                (shape, Motion::Spin { position: corner(LIFT), axis, turn, period_s })
            }
            Some(Kind::Swing) => {
                let axis = *rng.pick(&AXES);
                let amplitude_deg = *rng.pick(&AMPLITUDES_DEG);
                let (shape, arm) = if axis == WorldAxis::Y {
                    (*rng.pick(&SWING_IN_PLACE_SHAPES), 0.0)
                } else {
                    (*rng.pick(&BOB_SHAPES), layout.arm(rng))
                };
                let pivot = corner(LIFT + arm);
                (shape, Motion::Swing { pivot, axis, amplitude_deg, arm, period_s })
            }
            Some(Kind::Hop) => {
                let shape = *rng.pick(if is_parent { &PARENT_SHAPES[..] } else { &HOP_SHAPES[..] });
                let along = *rng.pick(&HORIZONTAL);
                let span = layout.hop_span(rng, is_parent);
                let height = *rng.pick(&HEIGHTS);
                let center = if is_parent && layout.parent_hops_at_centre() {
                    [0.0, shape.half_height(), 0.0]
                } else {
                    corner(shape.half_height())
                };
                (shape, Motion::Hop { center, along, span, height, period_s })
            }
            Some(Kind::Orbit) => {
                let shape =
                    *rng.pick(if is_parent { &PARENT_SHAPES[..] } else { &ORBIT_SHAPES[..] });
                let radius = layout.orbit_radius(rng, is_parent);
                let turn = *rng.pick(&TURNS);
                (shape, Motion::Orbit { center: [0.0, LIFT, 0.0], radius, turn, period_s })
            }
        };
        let name = format!("object {}", i + 1);
        objects.push(new_object(name, shape, COLORS[i % COLORS.len()], motion));
    }
    Spec { objects, unit_s: plan.unit_s }
}

/// The warm-up's three boxes (演習課題), the same for everybody: box 1 spins (回転運動), box 2
/// turns back and forth (往復回転運動), box 3 hops back and forth (放物往復移動運動).
#[must_use]
pub fn warmup_objects() -> Vec<Object> {
    let shape = Shape::Box { size: [1.2, 0.6, 0.6] };
    vec![
        new_object(
            "box 1",
            shape,
            COLORS[0],
            Motion::Spin {
                position: [-3.0, 1.0, 0.0],
                axis: WorldAxis::Y,
                turn: Turn::Ccw,
                period_s: 4.0,
            },
        ),
        new_object(
            "box 2",
            shape,
            COLORS[1],
            Motion::Swing {
                pivot: [0.0, 1.0, 0.0],
                axis: WorldAxis::Z,
                amplitude_deg: 30.0,
                arm: 0.0,
                period_s: 2.0,
            },
        ),
        new_object(
            "box 3",
            shape,
            COLORS[2],
            Motion::Hop {
                center: [3.0, 0.3, 0.0],
                along: WorldAxis::X,
                span: 2.0,
                height: 1.5,
                period_s: 2.0,
            },
        ),
    ]
}

/// Student `n`'s spec in table 1 (for the crate's tests).
#[cfg(test)]
pub(crate) fn spec_of(n: u32) -> Spec {
    spec_in(n, TableVersion::V1)
}

/// Student `n`'s spec in `table` (for the crate's tests).
#[cfg(test)]
pub(crate) fn spec_in(n: u32, table: TableVersion) -> Spec {
    let s: cg_harness::StudentNumber = format!("{n:08}").parse().unwrap();
    variant(&mut VariantRng::new(&s, table, crate::ID))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::warmup_box;

    #[test]
    fn every_variant_is_well_formed() {
        for (n, table) in (0..500).flat_map(|n| TableVersion::ALL.map(|t| (n, t))) {
            let spec = spec_in(20_260_000 + n, table);
            let k = spec.objects.len();
            assert!((3..=4).contains(&k), "{spec:?}");
            let children: Vec<usize> =
                (0..k).filter(|&i| spec.objects[i].motion.parent().is_some()).collect();
            assert_eq!(children.len(), 1, "exactly one child: {spec:?}");
            let c = children[0];
            let p = spec.objects[c].motion.parent().unwrap();
            assert_eq!(p + 1, c, "the child follows its parent");
            assert!(matches!(spec.objects[p].motion, Motion::Orbit { .. } | Motion::Hop { .. }));
            let mut periods: Vec<u64> =
                spec.objects.iter().map(|o| o.motion.period_frames()).collect();
            for (o, &f) in spec.objects.iter().zip(&periods) {
                // Every period is a whole number of frames.
                assert_eq!(f as f64, f64::from(o.motion.period_s()) * 60.0, "{o:?}");
                assert!(o.shape.try_mesh().is_ok_and(|m| m.validate().is_clean()), "{o:?}");
            }
            periods.sort_unstable();
            periods.dedup();
            assert_eq!(periods.len(), k, "distinct periods: {spec:?}");
            let ratios = spec.period_ratios();
            assert!(ratios.iter().all(|&r| (1..=4).contains(&r)), "{ratios:?}");
            // Deterministic.
            assert_eq!(spec, spec_in(20_260_000 + n, table));
        }
    }

    #[test]
    fn every_option_appears_among_a_few_dozen_students() {
        let specs: Vec<Spec> = (0..48).map(|n| spec_of(20_260_000 + n)).collect();
        let mut seen: std::collections::BTreeSet<String> = std::collections::BTreeSet::new();
        for spec in &specs {
            seen.insert(format!("n{}", spec.objects.len()));
            seen.insert(format!("unit{}", spec.unit_s));
            for (i, o) in spec.objects.iter().enumerate() {
                let parent = !spec.children(i).is_empty();
                let tag = match o.motion {
                    Motion::Spin { axis, turn, .. } => format!("spin-{axis:?}-{turn:?}"),
                    Motion::Swing { axis, amplitude_deg, .. } => {
                        seen.insert(format!("amp{amplitude_deg}"));
                        format!("swing-{axis:?}")
                    }
                    Motion::Hop { along, span, height, .. } => {
                        seen.insert(format!("span{span}"));
                        seen.insert(format!("height{height}"));
                        format!("hop-{along:?}-parent{parent}")
                    }
                    Motion::Orbit { radius, turn, .. } => {
                        seen.insert(format!("orbit-r{radius}-parent{parent}"));
                        format!("orbit-{turn:?}-parent{parent}")
                    }
                    Motion::Satellite { radius, turn, .. } => format!("sat-{radius}-{turn:?}"),
                };
                seen.insert(tag);
                seen.insert(format!("{:?}", o.shape));
            }
        }
        let expected = [
            "n3",
            "n4",
            "unit1.5",
            "unit2",
            "unit2.5",
            "unit3",
            "spin-X-Ccw",
            "spin-Y-Cw",
            "spin-Z-Ccw",
            "swing-X",
            "swing-Y",
            "swing-Z",
            "amp30",
            "amp45",
            "amp60",
            "hop-X-parentfalse",
            "hop-Z-parentfalse",
            "hop-X-parenttrue",
            "hop-Z-parenttrue",
            "span2",
            "span2.5",
            "span3",
            "height1",
            "height1.5",
            "height2",
            "orbit-Ccw-parentfalse",
            "orbit-Cw-parenttrue",
            "orbit-r1.5-parentfalse",
            "orbit-r3-parenttrue",
            "orbit-r2-parenttrue",
            "orbit-r2.5-parentfalse",
            "sat-1-Ccw",
            "sat-1.4-Cw",
            "sat-1.2-Ccw",
        ];
        for e in expected {
            assert!(seen.contains(e), "{e} never appears among 48 students: {seen:?}");
        }
        for shape in SPIN_SHAPES
            .iter()
            .chain(&PARENT_SHAPES)
            .chain(&CHILD_SHAPES)
            .chain(&HOP_SHAPES)
            .chain(&ORBIT_SHAPES)
        {
            assert!(seen.contains(&format!("{shape:?}")), "{shape:?} never appears");
        }
    }

    #[test]
    fn ratios_and_common_period() {
        let spec = Spec {
            unit_s: 1.5,
            objects: warmup_objects(), // periods 4, 2, 2 s
        };
        assert_eq!(spec.period_ratios(), vec![2, 1, 1]);
        assert_eq!(spec.common_period_s(), 4.0);
        assert_eq!(gcd(0, 7), 7);
        assert_eq!(lcm(4, 6), 12);
    }

    #[test]
    fn the_students_warmup_box_is_the_cores_cuboid() {
        let core = shapes::cuboid(Vec3::new(1.2, 0.6, 0.6)).unwrap();
        let student = warmup_box();
        assert_eq!(student.positions, core.positions);
        assert_eq!(student.faces, core.faces);
        assert!(cg_core::mesh::Mesh::from(&student).validate().is_clean());
        for object in warmup_objects() {
            assert_eq!(object.mesh, student, "{}", object.name);
        }
    }

    #[test]
    fn every_object_carries_its_shapes_mesh() {
        for n in 0..50 {
            let spec = spec_of(20_260_000 + n);
            for o in &spec.objects {
                let mesh = o.shape.mesh();
                assert_eq!(o.mesh.positions, mesh.positions, "{o:?}");
                assert_eq!(o.mesh.faces, mesh.faces, "{o:?}");
            }
        }
    }
}
