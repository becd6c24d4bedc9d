//! Checks of a2.t2, `camera()`: the view matrix it leaves on the stack equals
//! `T(0, 0, −camera_distance) · Rx(−camera_pitch) · Ry(−camera_yaw) · T(−target_x, 0, −target_z)`
//! (by `cg_core::camera::OrbitCamera::view_matrix`) at many states, the poles included; a
//! mismatch is explained by the usual wrong products ([`oracle::diagnose_view`]).

use cg_core::glam::{Mat4, Vec4};
use cg_harness::check::Failure;
use cg_harness::text::t;
use cg_harness::{Text, VariantRng};

use crate::oracle;
use crate::show;
use crate::{CameraState, Impl, Spec};

use super::student_view;

fn state(yaw: f32, pitch: f32, distance: f32, target: (f32, f32)) -> CameraState {
    CameraState {
        camera_yaw: yaw,
        camera_pitch: pitch,
        camera_distance: distance,
        target_x: target.0,
        target_z: target.1,
    }
}

/// The states of a2.t2.view: the spec's start, the course's camera, hand-picked ones (every
/// quadrant of yaw, up to 359.75°, pitch from −60° to +20°) and 8 seeded ones, all in quarter
/// degrees; with a pan the target moves too, without one it stays at the origin.
pub(crate) fn view_states(spec: &Spec) -> Vec<CameraState> {
    let pan = spec.pan.is_some();
    let target = |x: f32, z: f32| if pan { (x, z) } else { (0.0, 0.0) };
    let mut states = vec![
        spec.start,
        state(0.0, -30.0, 15.0, (0.0, 0.0)),
        state(30.0, -30.0, 15.0, target(1.5, -2.0)),
        state(135.0, -60.0, 8.0, target(-3.0, 0.5)),
        state(200.0, -10.0, 25.0, target(0.25, 4.0)),
        state(270.0, 20.0, 12.5, target(-1.0, -1.0)),
        state(359.75, -45.0, 3.0, target(2.0, 2.5)),
        state(90.0, 0.0, 40.0, target(-4.5, 1.0)),
    ];
    let mut rng = VariantRng::from_seed(0x0A27_EE00);
    for _ in 0..8 {
        let quarter = |rng: &mut VariantRng, lo: i64, hi: i64| rng.range(lo, hi) as f32 * 0.25;
        let yaw = quarter(&mut rng, 0, 1439);
        let pitch = quarter(&mut rng, -356, 356);
        let distance = quarter(&mut rng, 8, 200);
        let (x, z) = (quarter(&mut rng, -20, 20), quarter(&mut rng, -20, 20));
        states.push(state(yaw, pitch, distance, target(x, z)));
    }
    states
}

/// The states of a2.t2.pole: pitch −90° and +90° at several yaws, and just beside the pole.
pub(crate) fn pole_states(spec: &Spec) -> Vec<CameraState> {
    let pan = spec.pan.is_some();
    let target = |x: f32, z: f32| if pan { (x, z) } else { (0.0, 0.0) };
    vec![
        state(0.0, -90.0, 15.0, (0.0, 0.0)),
        state(45.0, -90.0, 10.0, target(1.0, -2.0)),
        state(180.0, -90.0, 20.0, target(-0.5, 0.5)),
        state(300.0, 90.0, 12.0, target(2.0, 1.0)),
        state(0.0, 90.0, 15.0, (0.0, 0.0)),
        state(120.0, -89.75, 15.0, target(0.0, 3.0)),
    ]
}

/// Where the camera is in world space for a view matrix `m` (`m⁻¹ · (0, 0, 0, 1)`), if `m` is
/// invertible and a view transform at all (its bottom row (0, 0, 0, 1): a transposed matrix's
/// "eye" would be a point of no meaning).
fn eye(m: &Mat4) -> Option<String> {
    let det = m.determinant();
    if !det.is_finite() || det.abs() < 1e-6 || !oracle::bottom_row_is_0001(m) {
        return None;
    }
    let p = m.inverse() * Vec4::W;
    Some(format!("({}, {}, {})", show::num(p.x), show::num(p.y), show::num(p.z)))
}

/// The student's camera gives the spec's view at every state of `states`.
pub(super) fn view_matches(spec: &Spec, imp: &Impl, states: &[CameraState]) -> Result<(), Failure> {
    let with_target = spec.pan.is_some();
    let mut matrices = Vec::with_capacity(states.len());
    for s in states {
        match student_view(imp, s) {
            Ok(m) => matrices.push(m),
            Err((actual, cause)) => {
                return Err(Failure::new(t("有効な視点の変換", "a valid view transform"), actual)
                    .at(show::state(s, with_target))
                    .cause(cause)
                    .hint(hint()));
            }
        }
    }
    let Some((k, (s, m))) = states
        .iter()
        .zip(&matrices)
        .enumerate()
        .find(|(_, (s, m))| !oracle::matrices_close(m, &oracle::view_matrix(s)))
    else {
        return Ok(());
    };
    let expected = oracle::view_matrix(s);
    let product = oracle::view_product(with_target, s);
    // The student's product at the state named in "where" (the report's names where the
    // probe's run finds them): its numbers are the ones the student can work out by hand.
    let written = show::camera_product_at(imp, s).map_or_else(
        |e| e,
        |p| {
            let (symbolic, numeric) = (p.symbolic(), p.numeric());
            if symbolic == numeric { symbolic } else { format!("{symbolic} = {numeric}") }.into()
        },
    );
    let mut cause = oracle::diagnose_view(states, &matrices);
    if !m.is_finite() {
        cause = t(
            "行列に NaN か無限大があります。上方向ベクトルを使う look-at は真上・真下（camera_pitch = ±90°）で定まりません。回転と平行移動の積で作ってください",
            "the matrix has NaN or infinity: a look-at with an up vector is undefined looking straight down or up (camera_pitch = ±90°); build the view from rotations and translations",
        );
    }
    let v = format!(
        "V = {} = {} = {}",
        product.symbolic(),
        product.simplified().numeric(),
        show::matrix(&expected)
    );
    let eye_expected = eye(&expected).unwrap_or_default();
    // No eye for a matrix that is no view transform: its bottom row says what it is instead.
    let eye_actual = if oracle::bottom_row_is_0001(m) {
        let at = eye(m).unwrap_or_else(|| "-".to_owned());
        Text::new(format!("視点の位置 {at}"), format!("eye at {at}"))
    } else {
        let row = show::vec4(m.row(3));
        Text::new(
            format!("下の行が {row} で (0, 0, 0, 1) ではない"),
            format!("bottom row {row}, not (0, 0, 0, 1)"),
        )
    };
    let (state, n) = (show::state(s, with_target), states.len());
    Err(Failure::new(
        Text::new(format!("{v}; 視点の位置 {eye_expected}"), format!("{v}; eye at {eye_expected}")),
        Text::new(
            format!(
                "{}; {}; この状態であなたの camera() が作る変換は {}",
                show::matrix(m),
                eye_actual.ja,
                written.ja
            ),
            format!(
                "{}; {}; at this state your camera() builds {}",
                show::matrix(m),
                eye_actual.en,
                written.en
            ),
        ),
    )
    .at(Text::new(
        format!("状態 {}/{n}: {state}", k + 1),
        format!("state {} of {n}: {state}", k + 1),
    ))
    .cause(cause)
    .hint(hint()))
}

fn hint() -> Text {
    t(
        "視点の変換は T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw)（注視点があれば · T(-target_x, 0, -target_z)）: この順に左から gl.translate / gl.rotate を呼びます（角度は度、最後に呼んだ変換が最初に頂点に作用）",
        "the view is T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw) (with a target, · T(-target_x, 0, -target_z)): call gl.translate / gl.rotate in this order, left to right (angles in degrees; the call made last acts on the vertices first)",
    )
}
