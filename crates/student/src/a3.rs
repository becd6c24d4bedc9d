//! Assignment `a3` — アニメーション (animation): your objects and their motions ([`Spec`]), the
//! animation's state ([`State`]) and the three functions you write ([`Impl`]). Plain data and the
//! [`Gl`] recorder: the kit computes the expected poses on its own side, out of your crate's
//! reach.
//!
//! Time: one call of `idle` is one frame, [`FPS`] frames a second; after `n` calls the time is
//! `t = n / 60` s.
//!
//! 課題3 アニメーション: 物体とその運動（[`Spec`]）、状態（[`State`]）、書く関数の表（[`Impl`]）。

use crate::left_out;
use glam::Vec3;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

use crate::gl::Gl;
use crate::mesh::Mesh;
use crate::{friendly, from_friendly, unfriendly};

/// Serialises three f32 as the f64s with the same shortest decimal digits (see `friendly`).
fn friendly3<S: Serializer>(v: &[f32; 3], s: S) -> Result<S::Ok, S::Error> {
    s.collect_seq(v.iter().map(|&x| x.to_string().parse::<f64>().unwrap_or(f64::from(x))))
}

/// Reads what `friendly3` wrote back as the same three f32 (see `unfriendly`).
fn unfriendly3<'de, D: Deserializer<'de>>(d: D) -> Result<[f32; 3], D::Error> {
    <[f64; 3]>::deserialize(d).map(|v| v.map(from_friendly))
}

/// Frames per second: one call of `idle` advances the time by 1/60 s.
pub const FPS: u32 = 60;

/// How many frames the drift check (`a3.t1.drift`) runs `idle` for: 10⁶ frames, about 4.6 hours
/// of animation.
pub const DRIFT_FRAMES: u64 = 1_000_000;

/// How many motion parameters a [`State`] holds (two per object is enough for every motion).
pub const PARAMS: usize = 8;

/// The common camera (the sample program's): `glTranslatef(0, 0, -15)`, then
/// `glRotatef(-camera_pitch, 1, 0, 0)` with `camera_pitch = -30°`.
pub const CAMERA_DISTANCE: f32 = 15.0;

/// The camera's pitch in degrees (the sample program's `camera_pitch`); the rotation is
/// `Rx(-camera_pitch) = Rx(30°)`.
pub const CAMERA_PITCH_DEG: f32 = -30.0;

/// `GL_LIGHT0`'s position, set right after the camera so it stays fixed in the world.
pub const LIGHT0_POSITION: [f32; 4] = [10.0, 10.0, 10.0, 1.0];

/// Meridians of a [`Shape::Sphere`]'s mesh.
pub const SPHERE_SLICES: u32 = 16;
/// Bands of a [`Shape::Sphere`]'s mesh.
pub const SPHERE_STACKS: u32 = 8;

/// A coordinate axis of the world (or of a parent's coordinate system).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum WorldAxis {
    /// +X
    X,
    /// +Y (up)
    Y,
    /// +Z (towards the camera at the start)
    Z,
}

impl WorldAxis {
    /// The unit vector along the axis: `glRotatef(angle, x, y, z)` takes its components.
    #[must_use]
    pub fn vector(self) -> Vec3 {
        match self {
            WorldAxis::X => Vec3::X,
            WorldAxis::Y => Vec3::Y,
            WorldAxis::Z => Vec3::Z,
        }
    }
}

/// Which way a rotation turns, seen from the positive end of its axis looking towards the origin.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Turn {
    /// Counter-clockwise (反時計回り): the angle grows, as glRotatef with a positive angle.
    Ccw,
    /// Clockwise (時計回り): the angle shrinks.
    Cw,
}

impl Turn {
    /// `+1` for [`Turn::Ccw`], `-1` for [`Turn::Cw`]: the sign of the angle's growth.
    #[must_use]
    pub fn sign(self) -> f32 {
        match self {
            Turn::Ccw => 1.0,
            Turn::Cw => -1.0,
        }
    }
}

/// A polygon model, in model space centred on its origin. Its mesh, ready to draw, is
/// [`Object::mesh`].
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Shape {
    /// 直方体: a box with these edge lengths along X, Y, Z (8 vertices, 12 triangles).
    Box {
        /// Edge lengths along X, Y, Z.
        #[serde(serialize_with = "friendly3", deserialize_with = "unfriendly3")]
        size: [f32; 3],
    },
    /// 角すい: a pyramid, base at y = −height/2, apex at +height/2.
    Pyramid {
        /// Sides of the base polygon.
        sides: u32,
        /// Circumradius of the base.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
        /// Height.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        height: f32,
    },
    /// 球: a UV sphere of [`SPHERE_SLICES`] meridians × [`SPHERE_STACKS`] bands.
    Sphere {
        /// Radius.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
    },
    /// 正八面体: a regular octahedron.
    Octahedron {
        /// Distance of the vertices from the centre.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
    },
}

/// How an object moves. `t` is the time in seconds, `T` the period, `u = (t mod T) / T ∈ [0, 1)`
/// the phase (how far into its period the motion is). Every angle is in degrees.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Motion {
    /// 回転運動 (spin): turns about an axis through `position`, parallel to `axis`:
    /// `M = T(position) · R_axis(θ)`, `θ = ±360°·u` (0° at t = 0).
    Spin {
        /// Where the object's centre stays.
        #[serde(serialize_with = "friendly3", deserialize_with = "unfriendly3")]
        position: [f32; 3],
        /// The axis it turns about.
        axis: WorldAxis,
        /// Which way.
        turn: Turn,
        /// One turn takes this long (s).
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        period_s: f32,
    },
    /// 往復回転運動 (back-and-forth rotation): hangs `arm` below `pivot` and swings about an axis
    /// through the pivot: `M = T(pivot) · R_axis(θ) · T(0, −arm, 0)`,
    /// `θ = amplitude·sin(360°·u)` (0° at t = 0, first towards +amplitude). `arm = 0`: it turns
    /// back and forth in place.
    Swing {
        /// The point it swings about.
        #[serde(serialize_with = "friendly3", deserialize_with = "unfriendly3")]
        pivot: [f32; 3],
        /// The axis it swings about.
        axis: WorldAxis,
        /// The largest angle (°) either way.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        amplitude_deg: f32,
        /// How far below the pivot its centre hangs (0: it turns in place).
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        arm: f32,
        /// One swing there and back takes this long (s).
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        period_s: f32,
    },
    /// 放物往復移動運動 (parabolic back-and-forth motion): moves along `along` between the two
    /// ends `center ∓ span/2`, hopping over a parabola of height `height` on the way there and
    /// on the way back: `M = T(center) · T(s·along + y·Y)`, with `w = 2u` for `u < 1/2` and
    /// `w = 2 − 2u` after (0 → 1 → 0, linear in t), `s = span·(w − 1/2)` and
    /// `y = height·(1 − (2s/span)²) = 4·height·w·(1 − w)`. At t = 0 at the −end, at T/4 on top,
    /// at T/2 at the +end, at 3T/4 on top again.
    Hop {
        /// The middle of the path, on the ground (the object rests there at height 0 + half its size).
        #[serde(serialize_with = "friendly3", deserialize_with = "unfriendly3")]
        center: [f32; 3],
        /// The horizontal direction it moves along (X or Z).
        along: WorldAxis,
        /// The distance between the two ends.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        span: f32,
        /// How high it hops above `center`.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        height: f32,
        /// There and back takes this long (s).
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        period_s: f32,
    },
    /// 公転 (orbit): goes round `center` on a horizontal circle of radius `radius`, turning with
    /// it (the same face towards the centre): `M = T(center) · Ry(θ) · T(0, 0, radius)`,
    /// `θ = ±360°·u`; at t = 0 at `center + (0, 0, radius)`, the camera's side.
    Orbit {
        /// The centre of the circle.
        #[serde(serialize_with = "friendly3", deserialize_with = "unfriendly3")]
        center: [f32; 3],
        /// Its radius.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
        /// Which way, seen from above (+Y).
        turn: Turn,
        /// One round takes this long (s).
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        period_s: f32,
    },
    /// 階層的な運動 (hierarchical motion): goes round its parent in the parent's coordinate
    /// system (which moves and turns with the parent): `M = M_parent · Ry(φ) · T(0, 0, radius)`,
    /// `φ = ±360°·u`; at t = 0 at `(0, 0, radius)` in the parent's coordinates.
    Satellite {
        /// The parent's index in [`Spec::objects`] (0-based: object 1 is 0). The parent comes
        /// before its child and is never a satellite itself.
        parent_index: usize,
        /// The radius of the circle about the parent's centre.
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        radius: f32,
        /// Which way, seen from the parent's +Y.
        turn: Turn,
        /// One round (relative to the parent) takes this long (s).
        #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
        period_s: f32,
    },
}

impl Motion {
    /// The period in seconds, `T`.
    #[must_use]
    pub fn period_s(&self) -> f32 {
        match *self {
            Motion::Spin { period_s, .. }
            | Motion::Swing { period_s, .. }
            | Motion::Hop { period_s, .. }
            | Motion::Orbit { period_s, .. }
            | Motion::Satellite { period_s, .. } => period_s,
        }
    }

    /// The period in frames, `P = 60 · period_s` (every period of the tables is a whole number
    /// of frames); at least 1.
    #[must_use]
    pub fn period_frames(&self) -> u64 {
        let frames = (f64::from(self.period_s()) * f64::from(FPS)).round();
        if frames.is_finite() && frames >= 1.0 { frames as u64 } else { 1 }
    }

    /// The parent's index for a [`Motion::Satellite`], `None` otherwise.
    #[must_use]
    pub fn parent(&self) -> Option<usize> {
        match *self {
            Motion::Satellite { parent_index, .. } => Some(parent_index),
            _ => None,
        }
    }
}

/// One object of the animation.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Object {
    /// The name to draw it with: `gl.draw(&object.name, &object.mesh)` (`"object 1"` …
    /// `"object 4"`).
    pub name: String,
    /// Its polygon model, in words and numbers.
    pub shape: Shape,
    /// Its polygon model as a mesh, ready to draw: `gl.draw(&object.name, &object.mesh)`.
    #[serde(skip)]
    pub mesh: Mesh,
    /// The colour to set with `gl.color(r, g, b)` before drawing it (not checked; it tells the
    /// objects apart in the view).
    #[serde(serialize_with = "friendly3", deserialize_with = "unfriendly3")]
    pub color: [f32; 3],
    /// How it moves.
    pub motion: Motion,
}

/// What one student must build: 3 or 4 objects, one pair of them a parent and its child.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Spec {
    /// The objects, object 1 first. A child ([`Motion::Satellite`]) comes right after its parent.
    pub objects: Vec<Object>,
    /// The unit of time (s): every period is a whole multiple of it (1, 2, 3 or 4 units, each
    /// used once), so the ratios of the periods are those multiples.
    #[serde(serialize_with = "friendly", deserialize_with = "unfriendly")]
    pub unit_s: f32,
}

impl Spec {
    /// The indices of `parent`'s children (the objects whose [`Motion::parent`] is `parent`).
    #[must_use]
    pub fn children(&self, parent: usize) -> Vec<usize> {
        (0..self.objects.len())
            .filter(|&i| self.objects[i].motion.parent() == Some(parent))
            .collect()
    }
}

/// The animation's state: what `idle` changes and `display` reads (the course's global
/// variables). `State::default()` is the start: frame 0, every parameter 0.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct State {
    /// Frames since the start: `idle` adds 1 each call. The time is `frame / 60` s
    /// ([`State::time_s`]).
    pub frame: u64,
    /// The motion parameters (運動を表す媒介変数) that `idle` computes and `display` reads —
    /// yours to lay out (the reference uses `params[2·i]` and `params[2·i + 1]` for object
    /// `i + 1`: an angle in degrees, or the offset and height of a hop).
    pub params: [f32; PARAMS],
}

impl State {
    /// The start: frame 0, every parameter 0.
    #[must_use]
    pub fn new() -> State {
        State::default()
    }

    /// The time in seconds, `frame / 60`, in f64 (exact enough for 10⁶ frames and far beyond).
    #[must_use]
    pub fn time_s(&self) -> f64 {
        self.frame as f64 / f64::from(FPS)
    }
}

/// The warm-up's box (演習課題), 1.2 × 0.6 × 0.6 centred on its origin: 8 vertices, 12 triangles.
///
/// | vertex | position | | vertex | position |
/// |---|---|---|---|---|
/// | V0 | (−0.6, −0.3, +0.3) | | V4 | (−0.6, +0.3, +0.3) |
/// | V1 | (+0.6, −0.3, +0.3) | | V5 | (+0.6, +0.3, +0.3) |
/// | V2 | (+0.6, −0.3, −0.3) | | V6 | (+0.6, +0.3, −0.3) |
/// | V3 | (−0.6, −0.3, −0.3) | | V7 | (−0.6, +0.3, −0.3) |
///
/// The sides (front +Z, right, back, left) two triangles each, then the bottom and the top, all
/// counter-clockwise seen from outside.
#[must_use]
pub fn warmup_box() -> Mesh {
    let (x, y, z) = (0.6, 0.3, 0.3);
    let positions = vec![
        Vec3::new(-x, -y, z),
        Vec3::new(x, -y, z),
        Vec3::new(x, -y, -z),
        Vec3::new(-x, -y, -z),
        Vec3::new(-x, y, z),
        Vec3::new(x, y, z),
        Vec3::new(x, y, -z),
        Vec3::new(-x, y, -z),
    ];
    let faces = vec![
        [0, 1, 5],
        [0, 5, 4],
        [1, 2, 6],
        [1, 6, 5],
        [2, 3, 7],
        [2, 7, 6],
        [3, 0, 4],
        [3, 4, 7],
        [0, 2, 1],
        [0, 3, 2],
        [4, 5, 6],
        [4, 6, 7],
    ];
    Mesh::new(positions, faces)
}

/// The functions a student writes (see `exercises/src/a3.rs`).
#[derive(Clone, Copy, Debug)]
pub struct Impl {
    /// a3.t0: draws the warm-up's three boxes at time `t` (s); the camera and light are set.
    pub warmup_display: fn(&mut Gl, f64),
    /// a3.t1: advances `state` by one frame and computes its motion parameters.
    pub idle: fn(&Spec, &mut State),
    /// a3.t2: draws the frame of `state`: camera, light and every object.
    pub display: fn(&Spec, &State, &mut Gl),
}

impl Impl {
    /// For the kit, not for your code: what stands in for `exercises/src/a3.rs` while that file
    /// does not compile, so that the other assignments still build and run. The kit never calls
    /// these functions: it says the file does not compile instead.
    #[must_use]
    pub fn left_out() -> Impl {
        Impl {
            warmup_display: |_, _| left_out("a3"),
            idle: |_, _| left_out("a3"),
            display: |_, _, _| left_out("a3"),
        }
    }
}
