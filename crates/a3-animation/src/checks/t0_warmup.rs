//! `a3.t0`, the warm-up (演習課題): the three boxes of `warmup_display` at [`WARMUP_TIMES`] against
//! the oracle, and its push/pop balance.

use cg_core::product::MatrixProduct;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use super::{POSE_TOL, Shift, close, diagnose, names_drawn, pose_failure, stack_failure, the_draw};
use crate::oracle::{Variation, warmup_model_with};
use crate::pose::{model_of, seconds};
use crate::{FPS, Impl, Object, warmup_frame, warmup_objects};

/// The times (s) at which the warm-up's boxes are compared.
const WARMUP_TIMES: [f64; 7] = [0.1, 0.35, 0.8, 1.25, 1.7, 2.6, 3.3];

pub(super) fn warmup_box(imp: &Impl, k: usize) -> Result<(), Failure> {
    let boxes = warmup_objects();
    let object = &boxes[k];
    for &time in &WARMUP_TIMES {
        let gl = warmup_frame(imp, time);
        let location = Text::from(format!("{}, t = {} s", object.name, seconds(time)));
        if gl.draws().is_empty() {
            return Err(Failure::new(
                format!("gl.draw(\"{}\", …)", object.name),
                names_drawn(&gl),
            )
            .at(location)
            .cause(t(
                "a3.t0 がまだできていません（何も描かれていません）",
                "a3.t0 is not done yet: nothing is drawn",
            ))
            .hint(t(
                "warmup_display() で 3 つの直方体を gl.draw(\"box 1\", &warmup_box()) などで描いてください",
                "draw the three boxes in warmup_display() with gl.draw(\"box 1\", &warmup_box()) and so on",
            )));
        }
        let draw = the_draw(&gl, object, &location)?;
        let expected = warmup_model_with(object, time, Variation::EXACT);
        let found = model_of(draw);
        if !close(found, expected, POSE_TOL) {
            let eval = |v: Variation, s: Shift| {
                let dt = 1.0 / f64::from(FPS);
                let time = match s {
                    Shift::Exact => time,
                    Shift::OneLate => time - dt,
                    Shift::OneEarly => time + dt,
                    Shift::Twice => 2.0 * time,
                    Shift::Half => time / 2.0,
                };
                Some(warmup_model_with(object, time, v))
            };
            let diagnosis = diagnose(found, expected, &gl, draw, &object.motion, None, &eval);
            let product = warmup_product(object, k, time);
            return Err(pose_failure(&product, expected, found, draw, location, diagnosis, &[]));
        }
    }
    Ok(())
}

/// A warm-up box's transform as named factors at time `t` (box `k`, 0-based).
fn warmup_product(object: &Object, k: usize, time: f64) -> MatrixProduct {
    let u = (time / f64::from(object.motion.period_s())).rem_euclid(1.0);
    crate::oracle::local_product(&object.motion, k + 1, if u >= 1.0 { 0.0 } else { u })
}

pub(super) fn warmup_stack(imp: &Impl) -> Result<(), Failure> {
    for &time in &WARMUP_TIMES {
        let gl = warmup_frame(imp, time);
        let location = Text::from(format!("warmup_display, t = {} s", seconds(time)));
        if gl.draws().is_empty() {
            return Err(Failure::new(
                t("3 つの直方体を描く", "the three boxes drawn"),
                names_drawn(&gl),
            )
            .at(location)
            .cause(t(
                "a3.t0 がまだできていません（何も描かれていません）",
                "a3.t0 is not done yet: nothing is drawn",
            ))
            .hint(t(
                "warmup_display() で 3 つの直方体を描いてください",
                "draw the three boxes in warmup_display()",
            )));
        }
        if let Some(f) = stack_failure(&gl, location, "a3.t0") {
            return Err(f);
        }
    }
    Ok(())
}
