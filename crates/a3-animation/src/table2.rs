//! a3's variant tables, version 2: the objects keep apart and stay over the ground.
//!
//! In version 1 (frozen, [`crate::spec`]) about 15 % of the students' children pass through
//! another object (a satellite of 1.0–1.4 around a parent whose orbit or hop comes near another
//! orbit or a corner), and 63 % of the variants have a vertex beyond the ±5 ground (hops of span
//! 3 at a corner reach 5.4, a satellite around them 6.6). Version 2 keeps version 1's motions,
//! shapes, periods and draw order and lays the scene out so that no two objects can meet, by
//! construction:
//!
//! - **The corners** (±3.5, ±3.5) hold the independent spins, swings and hops. Each stays
//!   within 1.45 of its corner, its shape's bounding sphere included (a swing's arm 0.8 or 1.0
//!   at up to 60° moves its bob ≤ 0.87, a hop's span is at most 1.8), so within the ground
//!   (3.5 + 1.45 = 4.95) and at least 4.95 − 1.45 = 3.5 from the centre.
//! - **The centre** holds the parent with its child, and the independent orbit when there is
//!   one: everything there stays within 3.40 of the vertical through the origin, 0.1 short of
//!   the corners. The parent orbits the centre or hops through it (in version 1 it hopped at a
//!   corner); its child goes round it at 1.0 or 1.2, clear of it (parent ≤ 0.61 + child ≤ 0.35 <
//!   1.0).
//! - **An independent orbit with the pair**: the orbit is the outer ring (radius 2.75, its
//!   shape within 0.64: from 2.11 to 3.39) and the pair keeps within 2.06 inside it (a parent
//!   orbit of 0.7, or a hop of span 1.2, with its child at 1.0), like the lecture's two orbits
//!   about one centre.
//!
//! The bounds are bounding spheres, so the real gaps are wider; `tests/tables.rs` moves every
//! object of thousands of students through their whole common period and checks both. FROZEN
//! once published, as version 1.

use cg_harness::VariantRng;

use crate::Spec;
use crate::spec::{Layout, objects, plan};

/// A swinging bob's arm (version 1: 1.0 and 1.5).
const ARMS: [f32; 2] = [0.8, 1.0];
/// The span of a hop at a corner (version 1: 2.0–3.0, for every hop).
const CORNER_SPANS: [f32; 3] = [1.2, 1.5, 1.8];
/// The span of the parent's hop through the centre, alone there.
const CENTRE_SPANS: [f32; 3] = [2.0, 2.5, 3.0];
/// The radius of the parent's orbit, alone in the centre.
const PARENT_ORBIT_RADII: [f32; 2] = [1.5, 1.8];
/// The child's distance from the parent, the pair alone in the centre.
const SATELLITE_RADII: [f32; 2] = [1.0, 1.2];
/// With an independent orbit: its radius, the parent's orbit or hop span, the child's radius.
const RING: f32 = 2.75;
const INNER_PARENT_ORBIT: f32 = 0.7;
const INNER_HOP_SPAN: f32 = 1.2;
const INNER_SATELLITE: f32 = 1.0;

/// The student's variant in table version 2: version 1's draws in version 1's order
/// ([`plan`], then [`objects`]), from this version's layout.
pub(crate) fn variant(rng: &mut VariantRng) -> Spec {
    let plan = plan(rng);
    objects(rng, &plan, &V2 { ring: plan.independent_orbit })
}

/// Version 2's layout; `ring`: an independent orbit shares the centre with the pair, as the
/// outer ring.
struct V2 {
    ring: bool,
}

impl Layout for V2 {
    fn satellite_radius(&self, rng: &mut VariantRng) -> f32 {
        if self.ring { INNER_SATELLITE } else { *rng.pick(&SATELLITE_RADII) }
    }
    fn arm(&self, rng: &mut VariantRng) -> f32 {
        *rng.pick(&ARMS)
    }
    fn hop_span(&self, rng: &mut VariantRng, is_parent: bool) -> f32 {
        match (is_parent, self.ring) {
            (false, _) => *rng.pick(&CORNER_SPANS),
            (true, false) => *rng.pick(&CENTRE_SPANS),
            (true, true) => INNER_HOP_SPAN,
        }
    }
    fn parent_hops_at_centre(&self) -> bool {
        true
    }
    fn orbit_radius(&self, rng: &mut VariantRng, is_parent: bool) -> f32 {
        match (is_parent, self.ring) {
            (false, _) => RING,
            (true, false) => *rng.pick(&PARENT_ORBIT_RADII),
            (true, true) => INNER_PARENT_ORBIT,
        }
    }
}

#[cfg(test)]
mod tests {
    use cg_harness::TableVersion;

    use crate::Motion;
    use crate::spec::spec_in;

    /// Every entry of version 2's own tables is drawn for somebody, and each of the three
    /// layouts of the centre (the pair alone, with an orbit around it; the parent orbiting or
    /// hopping) occurs.
    #[test]
    fn every_entry_of_the_second_table_is_drawn() {
        let mut seen = std::collections::BTreeSet::new();
        for n in 0..200 {
            let spec = spec_in(20_260_000 + n, TableVersion::V2);
            for (i, o) in spec.objects.iter().enumerate() {
                let parent = !spec.children(i).is_empty();
                seen.insert(match o.motion {
                    Motion::Swing { arm, .. } => format!("arm{arm}"),
                    Motion::Hop { span, center, .. } => {
                        let at =
                            if center[0] == 0.0 && center[2] == 0.0 { "centre" } else { "corner" };
                        format!("hop{span}-parent{parent}-{at}")
                    }
                    Motion::Orbit { radius, .. } => format!("orbit{radius}-parent{parent}"),
                    Motion::Satellite { radius, .. } => format!("sat{radius}"),
                    Motion::Spin { .. } => "spin".to_owned(),
                });
            }
        }
        for e in [
            "arm0",
            "arm0.8",
            "arm1",
            "sat1",
            "sat1.2",
            "orbit2.75-parentfalse",
            "orbit0.7-parenttrue",
            "orbit1.5-parenttrue",
            "orbit1.8-parenttrue",
            "hop1.2-parentfalse-corner",
            "hop1.5-parentfalse-corner",
            "hop1.8-parentfalse-corner",
            // The parent hops through the centre: 2, 2.5 or 3 alone there, 1.2 inside the orbit.
            "hop1.2-parenttrue-centre",
            "hop2-parenttrue-centre",
            "hop2.5-parenttrue-centre",
            "hop3-parenttrue-centre",
        ] {
            assert!(seen.contains(e), "{e} never drawn: {seen:?}");
        }
    }
}
