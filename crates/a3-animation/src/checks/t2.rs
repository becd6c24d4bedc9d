//! `a3.t2`, `display`: every object drawn once, the light after the camera, push/pop balance, each
//! object's pose over time, independent objects and the child in its parent's coordinates.

use cg_core::gl::Gl;
use cg_core::glam::{DMat4, Vec3};
use cg_core::product::format_number;
use cg_harness::check::Failure;
use cg_harness::text::{Text, t};

use super::{
    Diagnosis, POSE_TOL, Shift, at_frame, close, diagnose, each_frame, leak_diagnosis, leaked_from,
    nothing_drawn, object_label, origin, pair, pose_failure, stack_failure, the_draw, v3,
};
use crate::describe::shape_text;
use crate::oracle::{Variation, expected_model_with};
use crate::pose::{model_of, pose_error, seconds, view};
use crate::{Impl, LIGHT0_POSITION, Motion, ShapeExt, Spec, model_product};

/// The frames at which poses are compared (after that many calls of `idle`): spread over the
/// first 10.5 s so every phase of every motion is hit at different points.
const POSE_FRAMES: [u64; 10] = [1, 9, 23, 37, 60, 97, 151, 240, 389, 631];

pub(super) fn objects(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    each_frame(spec, imp, [1, 60], |frame, gl| {
        for (i, object) in spec.objects.iter().enumerate() {
            let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
            let draw = the_draw(gl, object, &location)?;
            let (want, got) =
                (bounds(&object.shape.mesh().positions), bounds(&draw.mesh.positions));
            let same = match (want, got) {
                (Some((a0, a1)), Some((b0, b1))) => {
                    (a0 - b0).abs().max_element() <= 1e-4 && (a1 - b1).abs().max_element() <= 1e-4
                }
                _ => false,
            };
            if !same {
                let show = |b: Option<(Vec3, Vec3)>| {
                    b.map_or(t("頂点なし", "no vertices"), |(lo, hi)| {
                        format!("{} … {}", v3(lo.as_dvec3()), v3(hi.as_dvec3())).into()
                    })
                };
                let (want, got) = (show(want), show(got));
                return Err(Failure::new(
                    Text::new(
                        format!("{}: 範囲 {}", shape_text(&object.shape).ja, want.ja),
                        format!("{}: bounds {}", shape_text(&object.shape).en, want.en),
                    ),
                    Text::new(format!("範囲 {}", got.ja), format!("bounds {}", got.en)),
                )
                .at(location)
                .cause(t(
                    "描いたメッシュの大きさか中心の位置が指定と違います",
                    "the mesh drawn has a different size or is not centred on its origin",
                ))
                .hint(t(
                    "メッシュは spec.objects[i].mesh を使い、glScalef は使わないでください",
                    "draw spec.objects[i].mesh and do not scale it",
                )));
            }
        }
        Ok(())
    })
}

/// The axis-aligned bounds of some points, `None` for none or a non-finite one.
fn bounds(points: &[Vec3]) -> Option<(Vec3, Vec3)> {
    let first = *points.first()?;
    let (lo, hi) = points.iter().fold((first, first), |(lo, hi), &p| (lo.min(p), hi.max(p)));
    (lo.is_finite() && hi.is_finite()).then_some((lo, hi))
}

pub(super) fn light(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    each_frame(spec, imp, [1], |frame, gl| {
        let location = pair(&"GL_LIGHT0".into(), "、", ", ", &at_frame(frame));
        let given = cg_core::glam::Vec4::from_array(LIGHT0_POSITION);
        let expected = view() * given.as_dvec4();
        let show = |p: cg_core::glam::DVec4| {
            let f = |x: f64| format_number(x as f32);
            format!("({}, {}, {}, {})", f(p.x), f(p.y), f(p.z), f(p.w))
        };
        let Some(l) = gl.lights().iter().find(|l| l.light == 0) else {
            return Err(Failure::new(
                Text::new(
                    format!(
                        "gl.light_position(0, [10, 10, 10, 1]) → カメラ座標系で {}",
                        show(expected)
                    ),
                    format!(
                        "gl.light_position(0, [10, 10, 10, 1]) → {} in camera space",
                        show(expected)
                    ),
                ),
                t("光源の位置が設定されていない", "no light set"),
            )
            .at(location)
            .cause(t(
                "display() で光源の位置を設定していません",
                "display() does not set the light's position",
            ))
            .hint(t(
                "視点の変換の直後に gl.light_position(0, [10.0, 10.0, 10.0, 1.0]) を呼んでください",
                "call gl.light_position(0, [10.0, 10.0, 10.0, 1.0]) right after the view transform",
            )));
        };
        let eye = l.eye.as_dvec4();
        if (eye - expected).abs().max_element() <= 1e-4 {
            return Ok(());
        }
        let before = (eye - given.as_dvec4()).abs().max_element() <= 1e-4;
        let cause = if before {
            t(
                "光源を視点の変換の前に設定しています（光源がカメラと一緒に動き、ワールドに固定されない）",
                "the light is set before the view transform (it moves with the camera instead of staying in the world)",
            )
        } else if l.given.as_dvec4() != given.as_dvec4() {
            t(
                "光源の位置の値が (10, 10, 10, 1) ではありません",
                "the light's position is not (10, 10, 10, 1)",
            )
        } else {
            t(
                "光源を設定したときの変換が視点の変換だけではありません（物体の変換の後に設定している？）",
                "the model-view matrix when the light is set is not just the camera's (set after an object's transforms?)",
            )
        };
        let (expected, eye, mv) = (show(expected), show(eye), l.model_view.numeric());
        Err(Failure::new(
            Text::new(
                format!("カメラ座標系で {expected}（= V · (10, 10, 10, 1)）"),
                format!("{expected} in camera space (= V · (10, 10, 10, 1))"),
            ),
            Text::new(
                format!("カメラ座標系で {eye}（モデルビュー行列 {mv}）"),
                format!("{eye} in camera space (model-view {mv})"),
            ),
        )
        .at(location)
        .cause(cause)
        .hint(t(
            "glLoadIdentity → 視点の変換 → gl.light_position(0, …) → 物体、の順にしてください",
            "use the order glLoadIdentity → view transform → gl.light_position(0, …) → objects",
        )))
    })
}

pub(super) fn stack(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    each_frame(spec, imp, POSE_FRAMES[..4].iter().copied(), |frame, gl| {
        let location = pair(&"display()".into(), "、", ", ", &at_frame(frame));
        if gl.draws().is_empty() {
            return Err(nothing_drawn(location, "a3.t2"));
        }
        stack_failure(gl, location, "a3.t2").map_or(Ok(()), Err)
    })
}

/// Shifts a frame count as a hypothesis about the student's time base says; `None` where it
/// has no such frame.
fn shifted(frame: u64, s: Shift) -> Option<u64> {
    match s {
        Shift::Exact => Some(frame),
        Shift::OneLate => frame.checked_sub(1),
        Shift::OneEarly => Some(frame + 1),
        Shift::Twice => Some(2 * frame),
        Shift::Half if frame.is_multiple_of(2) => Some(frame / 2),
        Shift::Half => None,
    }
}

/// Compares every object's pose with the spec's at every pose frame. The failure names the
/// first wrong object at its first wrong frame, the other wrong objects, and a mistake that
/// explains that object's poses at *every* frame (a hypothesis that fits one frame only, such as
/// "one frame early" against "twice as fast" at frame 1, is not offered).
pub(super) fn poses(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let mut found: Vec<Vec<(u64, DMat4)>> = vec![Vec::new(); spec.objects.len()];
    let mut first: Option<(u64, usize, Gl)> = None;
    let mut wrong: Vec<usize> = Vec::new();
    each_frame(spec, imp, POSE_FRAMES, |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t2"));
        }
        for (i, object) in spec.objects.iter().enumerate() {
            let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
            let m = model_of(the_draw(gl, object, &location)?);
            found[i].push((frame, m));
            if !close(m, expected_model_with(spec, i, frame, Variation::EXACT, 0), POSE_TOL) {
                if first.is_none() {
                    first = Some((frame, i, gl.clone()));
                }
                if !wrong.contains(&i) {
                    wrong.push(i);
                }
            }
        }
        Ok(())
    })?;
    let Some((frame, i, gl)) = first else { return Ok(()) };
    let object = &spec.objects[i];
    let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
    let draw = the_draw(&gl, object, &location)?;
    let (found_now, expected) =
        (model_of(draw), expected_model_with(spec, i, frame, Variation::EXACT, 0));
    let eval = |v: Variation, s: Shift| {
        let fits_everywhere = found[i].iter().all(|&(f, m)| {
            shifted(f, s).is_none_or(|g| close(m, expected_model_with(spec, i, g, v, 0), POSE_TOL))
        });
        if fits_everywhere {
            Some(expected_model_with(spec, i, shifted(frame, s)?, v, 0))
        } else {
            None
        }
    };
    let parent = object.motion.parent().and_then(|p| spec.objects.get(p)).map(|p| p.name.as_str());
    let own_period = object.motion.period_frames();
    // Another period that explains every frame: another object's, or twice or half its own.
    let mut periods: Vec<u64> = spec.objects.iter().map(|o| o.motion.period_frames()).collect();
    periods.extend([2 * own_period, own_period / 2]);
    // (A wrong time base explains it as well, and better: every object is off then.)
    let time_base = eval(Variation::EXACT, Shift::Twice).is_some()
        || eval(Variation::EXACT, Shift::Half).is_some();
    let other_period =
        periods.into_iter().filter(|&p| !time_base && p > 1 && p != own_period).find(|&p| {
            let v = Variation { period: Some(p), ..Variation::EXACT };
            found[i].iter().all(|&(f, m)| close(m, expected_model_with(spec, i, f, v, 0), POSE_TOL))
        });
    let diagnosis = match other_period {
        Some(p) => {
            let (got, want) = (seconds(p as f64 / 60.0), seconds(own_period as f64 / 60.0));
            Diagnosis::new(
                Text::new(
                    format!(
                        "周期が {got} 秒になっています（指定は {want} 秒。ほかの物体の周期と取り違えていないか）"
                    ),
                    format!(
                        "it moves with a period of {got} s instead of {want} s (another object's period?)"
                    ),
                ),
                t(
                    "この物体の周期 T を使って θ = 360°·t/T などを計算してください",
                    "compute θ = 360°·t/T and the like with this object's own period T",
                ),
            )
        }
        None => diagnose(found_now, expected, &gl, draw, &object.motion, parent, &eval),
    };
    let others: Vec<Text> =
        wrong.iter().filter(|&&j| j != i).map(|&j| object_label(spec, j)).collect();
    Err(pose_failure(
        &model_product(spec, i, frame),
        expected,
        found_now,
        draw,
        location,
        diagnosis,
        &others,
    ))
}

pub(super) fn independent(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    each_frame(spec, imp, POSE_FRAMES, |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t2"));
        }
        for (i, object) in spec.objects.iter().enumerate() {
            if object.motion.parent().is_some() {
                continue; // a child depends on its parent: a3.t2.hierarchy
            }
            let location = pair(&object_label(spec, i), "、", ", ", &at_frame(frame));
            let draw = the_draw(gl, object, &location)?;
            let expected = expected_model_with(spec, i, frame, Variation::EXACT, 0);
            let found = model_of(draw);
            if close(found, expected, POSE_TOL) {
                continue;
            }
            if let Some(earlier) = leaked_from(found, expected, gl, draw, None) {
                let d = leak_diagnosis(&earlier);
                let mv = draw.model_view.numeric();
                return Err(Failure::new(
                    Text::new(
                        format!(
                            "{} は前に描いた物体の変換の影響を受けない",
                            object_label(spec, i).ja
                        ),
                        format!("{} independent of the objects drawn before it", object.name),
                    ),
                    Text::new(
                        format!("{mv}: \"{earlier}\" の変換が残っている"),
                        format!("{mv}: starts with \"{earlier}\"'s transforms"),
                    ),
                )
                .at(location)
                .cause(d.cause)
                .hint(d.hint));
            }
        }
        Ok(())
    })
}

/// `物体2 の子の物体3、t = …` / `object 3 in object 2, t = …`: child `c` of parent `p`.
fn child_location(spec: &Spec, c: usize, p: usize, frame: u64) -> Text {
    let (c, p, at) = (object_label(spec, c), object_label(spec, p), at_frame(frame));
    Text::new(
        format!("{} の子の{}、{}", p.ja, c.ja, at.ja),
        format!("{} in {}, {}", c.en, p.en, at.en),
    )
}

/// One recorded frame of a parent and its child: (frame, parent's model, child's model, the
/// child's product as drawn).
type PairFrame = (u64, DMat4, DMat4, String);

/// A guess at how the child's model matrix was built, from the frame and the parent's model
/// matrix, with the cause and hint it stands for.
type ChildHypothesis<'a> = (&'a dyn Fn(u64, DMat4) -> DMat4, Text, Text);

pub(super) fn hierarchy(spec: &Spec, imp: &Impl) -> Result<(), Failure> {
    let pairs: Vec<(usize, usize)> = (0..spec.objects.len())
        .filter_map(|c| spec.objects[c].motion.parent().map(|p| (p, c)))
        .filter(|&(p, c)| p < spec.objects.len() && p != c)
        .collect();
    let mut recorded: Vec<Vec<PairFrame>> = vec![Vec::new(); pairs.len()];
    each_frame(spec, imp, POSE_FRAMES, |frame, gl| {
        if gl.draws().is_empty() {
            return Err(nothing_drawn(at_frame(frame), "a3.t2"));
        }
        for (k, &(p, c)) in pairs.iter().enumerate() {
            let location = child_location(spec, c, p, frame);
            let pd = the_draw(gl, &spec.objects[p], &location)?;
            let cd = the_draw(gl, &spec.objects[c], &location)?;
            recorded[k].push((frame, model_of(pd), model_of(cd), cd.model_view.numeric()));
        }
        Ok(())
    })?;
    for (k, &(p, c)) in pairs.iter().enumerate() {
        let child = &spec.objects[c];
        let rel_of = |mp: DMat4, mc: DMat4| {
            if mp.determinant().abs() > 1e-9 { mp.inverse() * mc } else { DMat4::NAN }
        };
        // The child's own motion at a (possibly fractional) frame.
        let own_at = |frame: f64, v: Variation| {
            let p = child.motion.period_frames() as f64;
            crate::oracle::local(&child.motion, frame.rem_euclid(p) / p, v)
        };
        let own = |frame: u64, v: Variation| own_at(frame as f64, v);
        let Some((frame, mp, mc, product)) = recorded[k]
            .iter()
            .find(|(f, mp, mc, _)| !close(rel_of(*mp, *mc), own(*f, Variation::EXACT), POSE_TOL))
            .cloned()
        else {
            continue;
        };
        // A hypothesis about the child's model matrix, tried at every recorded frame.
        let fits = |h: &dyn Fn(u64, DMat4) -> DMat4| {
            recorded[k].iter().all(|(f, mp, mc, _)| close(*mc, h(*f, *mp), POSE_TOL))
        };
        let hypotheses: [ChildHypothesis<'_>; 8] = [
            (
                &|f, mp| mp * own_at(2.0 * f as f64, Variation::EXACT),
                t("時間が 2 倍の速さで進んでいます", "time runs twice as fast"),
                t(
                    "1 フレームは 1/60 秒です（t = state.frame/60）",
                    "one frame is 1/60 s (t = frame/60)",
                ),
            ),
            (
                &|f, mp| mp * own_at(f as f64 / 2.0, Variation::EXACT),
                t(
                    "時間が半分の速さで進んでいます（30 fps として計算？）",
                    "time runs at half speed (computed for 30 fps?)",
                ),
                t(
                    "1 フレームは 1/60 秒です（t = state.frame/60）",
                    "one frame is 1/60 s (t = frame/60)",
                ),
            ),
            (
                &|f, mp| mp * own_at(f as f64 - 1.0, Variation::EXACT),
                t("子が 1 フレーム遅れています", "the child is one frame late"),
                t(
                    "idle() では先に state.frame に 1 を足し、その新しい state.frame から変数を求めてください",
                    "in idle(), add 1 to state.frame first, then compute the parameters from the new frame",
                ),
            ),
            (
                &|f, mp| mp * own(f, Variation::REVERSED),
                t(
                    "子の回転と平行移動の順番が逆です（T·R）: 子は親のまわりを回らず、離れた所でその場で回ります",
                    "the child's rotation and translation are reversed (T·R): it spins in place away from the parent instead of going round it",
                ),
                t(
                    "親の変換の後に Ry(θ) → T(0, 0, r) の順に呼んでください（回転を先に書くと、平行移動したベクトルが回る）",
                    "after the parent's transforms call Ry(θ), then T(0, 0, r) (the rotation first turns the offset)",
                ),
            ),
            (
                &|f, _| own(f, Variation::EXACT),
                t(
                    "子が親の座標系ではなくワールドの原点のまわりを回っています（親の glPopMatrix の後に描いている？）",
                    "the child goes round the world's origin, not its parent (drawn after the parent's glPopMatrix?)",
                ),
                t(
                    "子は親の変換の後、親の glPopMatrix の前に、glPushMatrix / glPopMatrix を入れ子にして描いてください",
                    "draw the child after the parent's transforms and before the parent's glPopMatrix, inside its own nested glPushMatrix / glPopMatrix",
                ),
            ),
            (
                &|f, mp| DMat4::from_translation(origin(mp)) * own(f, Variation::EXACT),
                t(
                    "子が親の位置には付いていきますが、親の回転には付いていきません",
                    "the child follows the parent's position but not its rotation",
                ),
                t(
                    "親の変換（回転を含む）をすべてかけた後に子の変換をかけてください",
                    "apply all of the parent's transforms, its rotation included, before the child's",
                ),
            ),
            (
                &|f, mp| mp * own(f, Variation::RADIANS),
                t(
                    "子の角度をラジアンで渡しています（glRotatef は度）",
                    "the child's angle is in radians (glRotatef takes degrees)",
                ),
                t("角度は度で: θ = 360°·t/T", "use degrees: θ = 360°·t/T"),
            ),
            (
                &|f, mp| mp * own(f, Variation::MIRRORED),
                t("子の回る向きが逆です", "the child turns the wrong way"),
                t("角度の符号を確認してください", "check the angle's sign"),
            ),
        ];
        let (cause, hint) = hypotheses
            .into_iter()
            .find(|(h, _, _)| fits(*h))
            .map(|(_, c, h)| (c, h))
            .unwrap_or_else(|| {
                (
                    t(
                        "親から見た子の位置・向きが指定と違います（半径、周期、回転軸、t = 0 の位置を確認）",
                        "the child's pose relative to its parent is not the specified one (check the radius, period, axis and start)",
                    ),
                    t(
                        "親の変換の後に、子の Ry(θ)·T(0, 0, r) を続けてください",
                        "follow the parent's transforms with the child's Ry(θ)·T(0, 0, r)",
                    ),
                )
            });
        let (rel, rel_expected) = (rel_of(mp, mc), own(frame, Variation::EXACT));
        let (rot, pos) = pose_error(rel, rel_expected);
        let radius = match child.motion {
            Motion::Satellite { radius, .. } => radius,
            _ => 0.0,
        };
        let (radius, o_expected) = (format_number(radius), v3(origin(rel_expected)));
        let (o_found, rot, pos) = (v3(origin(rel)), rot.to_degrees(), format_number(pos as f32));
        return Err(Failure::new(
            Text::new(
                format!(
                    "M_親⁻¹ · M_子 = Ry(θ)·T(0, 0, {radius}) → {}の座標系で原点 {o_expected}",
                    object_label(spec, p).ja
                ),
                format!(
                    "M_parent⁻¹ · M_child = Ry(θ)·T(0, 0, {radius}) → origin {o_expected} in {}'s coordinates",
                    spec.objects[p].name
                ),
            ),
            Text::new(
                format!(
                    "原点 {o_found}（回転のずれ {rot:.3}°、位置のずれ {pos}）; 子の変換 {product}"
                ),
                format!(
                    "origin {o_found} (off by {rot:.3}° and {pos} units); child drawn with {product}"
                ),
            ),
        )
        .at(child_location(spec, c, p, frame))
        .cause(cause)
        .hint(hint));
    }
    Ok(())
}
