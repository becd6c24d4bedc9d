//! A matrix as a product of named factors: its matrix, its simplification and the report's
//! notations. The expected strings are written by hand from the notation's rules (the lecture's
//! slides), not copied from output.

use cg_core::camera::OrbitCamera;
use cg_core::glam::{DMat4, DVec3, Mat4, Vec3};
use cg_core::product::{Axis, Factor, MatrixProduct, Param, format_number};
use cg_core::transform::{self, TransformError};
use cg_testkit::prop::vec3;
use cg_testkit::{Approx, assert_approx_eq};
use proptest::prelude::*;

fn config(cases: u32) -> ProptestConfig {
    cg_testkit::prop::config(cases, 0x9a0d_0c75)
}

/// Valid factors of moderate size (translations ≤ 10, scales in [0.1, 10] with either sign).
fn factor() -> impl Strategy<Value = Factor> {
    prop_oneof![
        vec3(-2.0, 1.0).prop_map(Factor::translate),
        vec3(-1.0, 1.0).prop_map(Factor::scale),
        (-720.0f32..720.0).prop_map(Factor::rotate_x_deg),
        (-720.0f32..720.0).prop_map(Factor::rotate_y_deg),
        (-720.0f32..720.0).prop_map(Factor::rotate_z_deg),
        (-720.0f32..720.0, vec3(-3.0, 3.0)).prop_map(|(a, v)| Factor::rotate_deg(a, v)),
    ]
}

/// The factor's matrix from f64 formulas (glam's f64 builders and f64 trigonometry): an oracle
/// independent of `cg_core::transform`.
fn factor_f64(f: &Factor) -> DMat4 {
    let v = |p: &[Param; 3]| DVec3::new(p[0].value.into(), p[1].value.into(), p[2].value.into());
    match f {
        Factor::Translate(p) => DMat4::from_translation(v(p)),
        Factor::Scale(p) => DMat4::from_scale(v(p)),
        Factor::Rotate { axis, angle_deg } => {
            let k = match axis {
                Axis::X => DVec3::X,
                Axis::Y => DVec3::Y,
                Axis::Z => DVec3::Z,
                Axis::Any(a) => a.as_dvec3().normalize(),
            };
            DMat4::from_axis_angle(k, f64::from(angle_deg.value).to_radians())
        }
        _ => unreachable!("only the generated kinds"),
    }
}

/// The infinity norm (max row sum) of a matrix.
fn norm(m: DMat4) -> f64 {
    (0..4).map(|r| m.row(r).abs().element_sum()).fold(0.0, f64::max)
}

proptest! {
    #![proptest_config(config(256))]

    #[test]
    fn product_matrix_equals_the_product_of_the_builder_matrices(
        factors in proptest::collection::vec(factor(), 0..6)
    ) {
        let product = MatrixProduct { factors: factors.clone() };
        let got = product.matrix().unwrap();
        // The same builders, multiplied left to right by hand: identical f32 arithmetic.
        let mut by_hand = Mat4::IDENTITY;
        for f in &factors {
            let m = match f {
                Factor::Translate(p) => transform::translate(Vec3::new(p[0].value, p[1].value, p[2].value)),
                Factor::Scale(p) => transform::scale(Vec3::new(p[0].value, p[1].value, p[2].value)),
                Factor::Rotate { axis: Axis::X, angle_deg } => transform::rotate_x_deg(angle_deg.value),
                Factor::Rotate { axis: Axis::Y, angle_deg } => transform::rotate_y_deg(angle_deg.value),
                Factor::Rotate { axis: Axis::Z, angle_deg } => transform::rotate_z_deg(angle_deg.value),
                Factor::Rotate { axis: Axis::Any(a), angle_deg } => transform::rotate_deg(angle_deg.value, *a).unwrap(),
                _ => unreachable!(),
            };
            by_hand *= m;
        }
        prop_assert_eq!(got, by_hand);

        // And the f64 oracle: each f32 entry is within 2⁻²⁴ relative of its factor's, and each of
        // the k products adds about 4·2⁻²⁴ times the norms of its operands, so the error is
        // bounded by (k + 1)·8·2⁻²⁴·Π‖Fᵢ‖∞.
        let oracle = factors.iter().fold(DMat4::IDENTITY, |acc, f| acc * factor_f64(f));
        let bound: f64 = factors.iter().map(|f| norm(factor_f64(f))).product();
        let tol = (factors.len() as f64 + 1.0) * 8.0 * f64::from(f32::EPSILON) * bound;
        let diff = got.as_dmat4().max_abs_diff(&oracle);
        prop_assert!(diff <= tol, "|product − f64 oracle| = {diff:e} > {tol:e} for {product}");

        // Simplification never changes the matrix.
        assert_approx_eq!(product.simplified().matrix().unwrap(), got, abs = 0.0);
    }

    #[test]
    fn concat_is_the_product_of_the_matrices(
        a in proptest::collection::vec(factor(), 0..4),
        b in proptest::collection::vec(factor(), 0..4),
    ) {
        let (a, b) = (MatrixProduct { factors: a }, MatrixProduct { factors: b });
        let ab = a.concat(&b);
        prop_assert_eq!(ab.factors.len(), a.factors.len() + b.factors.len());
        let oracle = a.matrix().unwrap().as_dmat4() * b.matrix().unwrap().as_dmat4();
        let bound = norm(a.matrix().unwrap().as_dmat4()) * norm(b.matrix().unwrap().as_dmat4());
        let tol = 64.0 * f64::from(f32::EPSILON) * bound;
        let diff = ab.matrix().unwrap().as_dmat4().max_abs_diff(&oracle);
        prop_assert!(diff <= tol, "|concat − f64 oracle| = {diff:e} > {tol:e} for {ab}");
    }
}

/// The course's view times the object's translation: `view_product() · T(0, 1, 0)`.
fn course_product() -> MatrixProduct {
    OrbitCamera::course_sample().view_product().then(Factor::translate(Vec3::new(0.0, 1.0, 0.0)))
}

#[test]
fn course_camera_prints_as_the_report_writes_it() {
    let p = course_product();
    assert_eq!(
        p.symbolic(),
        "T(0, 0, -camera_distance) · Rx(-camera_pitch) · Ry(-camera_yaw) · T(0, 1, 0)"
    );
    assert_eq!(p.numeric(), "T(0, 0, -15) · Rx(30°) · Ry(0°) · T(0, 1, 0)");
    assert_eq!(p.simplified().numeric(), "T(0, 0, -15) · Rx(30°) · T(0, 1, 0)");
    assert_eq!(p.to_string(), p.numeric(), "Display is the numeric form");
    assert_eq!(
        p.simplified().symbolic(),
        "T(0, 0, -camera_distance) · Rx(-camera_pitch) · T(0, 1, 0)"
    );
}

#[test]
fn other_factors_print_in_the_report_notation() {
    let p = MatrixProduct::identity()
        .then(Factor::perspective(45.0, 1.0, 1.0, 500.0))
        .then(Factor::perspective_gl(60.0, 1.5, 0.1, 100.0))
        .then(Factor::rotate_deg(-12.5, Vec3::new(1.0, 1.0, 0.0)))
        .then(Factor::scale(Vec3::new(2.0, 0.5, -1.0)))
        .then(Factor::rotate_z_deg(0.25))
        .then(Factor::named("M", Mat4::IDENTITY))
        .then(Factor::rotate(Axis::Y, Param::sym("theta_cycle", 10.0)));
    assert_eq!(
        p.numeric(),
        "P(45°, 1, 1, 500) · P_gl(60°, 1.5, 0.1, 100) · R(-12.5°, 1, 1, 0) · S(2, 0.5, -1) · Rz(0.25°) · M · Ry(10°)"
    );
    assert_eq!(
        p.symbolic(),
        "P(45°, 1, 1, 500) · P_gl(60°, 1.5, 0.1, 100) · R(-12.5°, 1, 1, 0) · S(2, 0.5, -1) · Rz(0.25°) · M · Ry(theta_cycle)"
    );
    assert_eq!(MatrixProduct::identity().numeric(), "I");
    // glRotatef(a, 1, 0, 0) is Rx(a) in the report; a tilted or negative axis is not.
    assert_eq!(Factor::rotate_deg(30.0, Vec3::new(2.0, 0.0, 0.0)).to_string(), "Rx(30°)");
    assert_eq!(Factor::rotate_deg(30.0, Vec3::Y).to_string(), "Ry(30°)");
    assert_eq!(Factor::rotate_deg(30.0, Vec3::new(0.0, -0.0, 1.0)).to_string(), "Rz(30°)");
    assert_eq!(Factor::rotate_deg(30.0, -Vec3::X).to_string(), "R(30°, -1, 0, 0)");
    assert_eq!(Factor::rotate_deg(30.0, Vec3::ZERO).to_string(), "R(30°, 0, 0, 0)");
    assert_eq!(MatrixProduct::identity().matrix().unwrap(), Mat4::IDENTITY);
}

#[test]
fn identity_factors_are_exactly_the_numerically_neutral_ones() {
    let identities = [
        Factor::translate(Vec3::ZERO),
        Factor::translate(Vec3::splat(-0.0)),
        Factor::rotate_x_deg(0.0),
        Factor::rotate_y_deg(-0.0),
        Factor::rotate_z_deg(360.0),
        Factor::rotate_x_deg(-720.0),
        Factor::rotate_deg(0.0, Vec3::new(1.0, 2.0, 3.0)),
        Factor::scale(Vec3::ONE),
        Factor::named("I", Mat4::IDENTITY),
    ];
    for f in identities {
        assert!(f.is_identity(), "{f} is the identity");
    }
    let others = [
        Factor::translate(Vec3::new(1e-30, 0.0, 0.0)),
        Factor::rotate_x_deg(1e-3),
        Factor::rotate_y_deg(180.0),
        Factor::scale(Vec3::new(1.0, 1.0, -1.0)),
        Factor::perspective(90.0, 1.0, 1.0, 2.0),
        // Invalid factors are not silently dropped by `simplified`.
        Factor::rotate_deg(0.0, Vec3::ZERO),
        Factor::translate(Vec3::new(f32::NAN, 0.0, 0.0)),
    ];
    for f in others {
        assert!(!f.is_identity(), "{f} is not the identity");
    }
    let p = MatrixProduct::identity()
        .then(Factor::rotate_deg(0.0, Vec3::ZERO))
        .then(Factor::scale(Vec3::ONE));
    assert_eq!(p.simplified().factors, vec![Factor::rotate_deg(0.0, Vec3::ZERO)]);
}

#[test]
fn invalid_factors_are_errors_naming_the_factor() {
    let p = MatrixProduct::identity()
        .then(Factor::translate(Vec3::ONE))
        .then(Factor::rotate_x_deg(30.0))
        .then(Factor::rotate_deg(45.0, Vec3::ZERO));
    let err = p.matrix().unwrap_err();
    match &err {
        TransformError::InFactor { index, source } => {
            assert_eq!(*index, 2);
            assert!(
                matches!(**source, TransformError::RotationAxis { axis } if axis == Vec3::ZERO)
            );
        }
        other => panic!("expected InFactor, got {other:?}"),
    }
    assert!(err.to_string().contains("factor 2"), "{err}");
    assert!(p.matrices_text().is_err() && p.latex(true).is_err() && p.latex(false).is_err());

    assert!(matches!(
        Factor::translate(Vec3::new(0.0, f32::INFINITY, 0.0)).matrix(),
        Err(TransformError::NotFinite { what: "translation", value: f32::INFINITY })
    ));
    assert!(matches!(
        Factor::scale(Vec3::new(0.0, 1.0, f32::NEG_INFINITY)).matrix(),
        Err(TransformError::NotFinite { what: "scale", .. })
    ));
    assert!(matches!(
        Factor::rotate_z_deg(f32::NAN).matrix(),
        Err(TransformError::NotFinite { what: "rotation angle", .. })
    ));
    assert!(matches!(
        Factor::perspective(45.0, 1.0, 0.0, 500.0).matrix(),
        Err(TransformError::NearPlane { near: 0.0 })
    ));
    let mut m = Mat4::IDENTITY;
    m.w_axis.x = f32::NAN;
    let err = Factor::named("V", m).matrix().unwrap_err();
    assert!(matches!(&err, TransformError::MatrixNotFinite { name, .. } if name == "V"), "{err:?}");
    // Printing the labels of invalid factors never panics.
    assert_eq!(
        Factor::translate(Vec3::new(f32::NAN, f32::INFINITY, 0.0)).to_string(),
        "T(NaN, inf, 0)"
    );
}

#[test]
fn format_number_follows_the_report_rules() {
    let cases: [(f32, &str); 20] = [
        (15.0, "15"),
        (-15.0, "-15"),
        (0.0, "0"),
        (-0.0, "0"),
        (1.0, "1"),
        (0.4856, "0.4856"),
        (0.485_56, "0.4856"),
        (-0.8, "-0.8"),
        (0.5, "0.5"),
        (0.1 + 0.2, "0.3"),
        (1.25, "1.25"),
        (-1.23456, "-1.2346"),
        (0.99996, "1"),
        (-0.00004, "0"),
        (1e-5, "0"),
        (0.866_025_4, "0.866"),
        (2.0e9, "2000000000"),
        (f32::NAN, "NaN"),
        (f32::INFINITY, "inf"),
        (f32::NEG_INFINITY, "-inf"),
    ];
    for (x, want) in cases {
        assert_eq!(format_number(x), want, "format_number({x:?})");
    }
    // Extremes never panic and stay free of exponents and trailing zeros.
    for x in [f32::MAX, f32::MIN, f32::MIN_POSITIVE, f32::EPSILON, 1e20, -123_456.79] {
        let s = format_number(x);
        assert!(!s.contains('e') && !s.ends_with(".0") && !s.is_empty(), "{x:e} → {s}");
    }
}

#[test]
fn matrices_text_prints_rows_side_by_side() {
    let p = MatrixProduct::identity()
        .then(Factor::translate(Vec3::new(1.0, 2.0, 3.0)))
        .then(Factor::scale(Vec3::splat(2.0)));
    // T·S keeps T's translation and S's diagonal.
    let want = "\
T(1, 2, 3)         S(2, 2, 2)
| 1  0  0  1 |     | 2  0  0  0 |     | 2  0  0  1 |
| 0  1  0  2 |  ·  | 0  2  0  0 |  =  | 0  2  0  2 |
| 0  0  1  3 |     | 0  0  2  0 |     | 0  0  2  3 |
| 0  0  0  1 |     | 0  0  0  1 |     | 0  0  0  1 |";
    assert_eq!(p.matrices_text().unwrap(), want);

    // Rx(90°) is exact: clean 0/±1, columns right-aligned, no "-0".
    let p = MatrixProduct::identity().then(Factor::rotate_x_deg(90.0));
    let want = "\
Rx(90°)
| 1  0   0  0 |     | 1  0   0  0 |
| 0  0  -1  0 |  =  | 0  0  -1  0 |
| 0  1   0  0 |     | 0  1   0  0 |
| 0  0   0  1 |     | 0  0   0  1 |";
    assert_eq!(p.matrices_text().unwrap(), want);

    // T(0, 0, -15)·Rx(30°): cos 30° = 0.8660… prints as 0.866.
    let p = MatrixProduct::identity()
        .then(Factor::translate(Vec3::new(0.0, 0.0, -15.0)))
        .then(Factor::rotate_x_deg(30.0));
    let want = "\
T(0, 0, -15)         Rx(30°)
| 1  0  0    0 |     | 1      0      0  0 |     | 1      0      0    0 |
| 0  1  0    0 |  ·  | 0  0.866   -0.5  0 |  =  | 0  0.866   -0.5    0 |
| 0  0  1  -15 |     | 0    0.5  0.866  0 |     | 0    0.5  0.866  -15 |
| 0  0  0    1 |     | 0      0      0  1 |     | 0      0      0    1 |";
    assert_eq!(p.matrices_text().unwrap(), want);

    assert_eq!(
        MatrixProduct::identity().matrices_text().unwrap(),
        "| 1  0  0  0 |\n| 0  1  0  0 |\n| 0  0  1  0 |\n| 0  0  0  1 |"
    );
}

#[test]
fn latex_matches_the_lecture_slide() {
    // The slide 視点操作の拡張: T(0, 0, -camera_distance) · Rx(-camera_pitch); a name of
    // several letters is one italic word (\mathit), not a product of letters.
    let p = OrbitCamera::course_sample().view_product().simplified();
    let want = concat!(
        r"\begin{pmatrix} 1 & 0 & 0 & 0 \\ 0 & 1 & 0 & 0 \\ 0 & 0 & 1 & -\mathit{camera\_distance} \\ 0 & 0 & 0 & 1 \end{pmatrix}",
        "\n",
        r"\begin{pmatrix} 1 & 0 & 0 & 0 \\ 0 & \cos(-\mathit{camera\_pitch}) & -\sin(-\mathit{camera\_pitch}) & 0 \\ 0 & \sin(-\mathit{camera\_pitch}) & \cos(-\mathit{camera\_pitch}) & 0 \\ 0 & 0 & 0 & 1 \end{pmatrix}",
    );
    assert_eq!(p.latex(true).unwrap(), want);

    // Numeric: the factors, then "=" and the product.
    let p = MatrixProduct::identity()
        .then(Factor::translate(Vec3::new(1.0, 2.0, 3.0)))
        .then(Factor::scale(Vec3::splat(2.0)));
    let want = concat!(
        r"\begin{pmatrix} 1 & 0 & 0 & 1 \\ 0 & 1 & 0 & 2 \\ 0 & 0 & 1 & 3 \\ 0 & 0 & 0 & 1 \end{pmatrix}",
        "\n",
        r"\begin{pmatrix} 2 & 0 & 0 & 0 \\ 0 & 2 & 0 & 0 \\ 0 & 0 & 2 & 0 \\ 0 & 0 & 0 & 1 \end{pmatrix}",
        "\n",
        r"= \begin{pmatrix} 2 & 0 & 0 & 1 \\ 0 & 2 & 0 & 2 \\ 0 & 0 & 2 & 3 \\ 0 & 0 & 0 & 1 \end{pmatrix}",
    );
    assert_eq!(p.latex(false).unwrap(), want);

    // The lecture's animation example: Ry(θ_cycle) in its symbolic rows [c 0 s; 0 1 0; −s 0 c].
    let p = MatrixProduct::identity().then(Factor::rotate(Axis::Y, Param::sym("theta_cycle", 0.0)));
    assert_eq!(
        p.latex(true).unwrap(),
        r"\begin{pmatrix} \cos(\theta_{\mathrm{cycle}}) & 0 & \sin(\theta_{\mathrm{cycle}}) & 0 \\ 0 & 1 & 0 & 0 \\ -\sin(\theta_{\mathrm{cycle}}) & 0 & \cos(\theta_{\mathrm{cycle}}) & 0 \\ 0 & 0 & 0 & 1 \end{pmatrix}"
    );
}

/// Checks that `s` is well-formed LaTeX for a math environment: braces balance (escaped ones
/// aside), every `\begin{…}` has its `\end{…}` in order, every `_` is escaped or opens a braced
/// subscript, and each pmatrix
/// has 4 rows of 4 entries.
fn assert_valid_latex(s: &str) {
    let bytes = s.as_bytes();
    let mut depth = 0i32;
    let mut envs: Vec<String> = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'\\' => {
                let rest = &s[i..];
                if let Some(name) = rest.strip_prefix(r"\begin{") {
                    let env = &name[..name.find('}').expect("closed \\begin")];
                    envs.push(env.to_owned());
                } else if let Some(name) = rest.strip_prefix(r"\end{") {
                    let env = &name[..name.find('}').expect("closed \\end")];
                    assert_eq!(
                        envs.pop().as_deref(),
                        Some(env),
                        "\\end{{{env}}} without its begin in {s}"
                    );
                }
                if matches!(
                    bytes.get(i + 1),
                    Some(b'{' | b'}' | b'_' | b'%' | b'&' | b'#' | b'$' | b'\\')
                ) {
                    i += 2;
                    continue;
                }
            }
            b'{' => depth += 1,
            b'}' => {
                depth -= 1;
                assert!(depth >= 0, "unbalanced }} in {s}");
            }
            // A subscript `_{…}` (as in `R_{(1, 1, 0)}`) is LaTeX; a bare `_` comes from an
            // unescaped symbol such as `camera_distance`.
            b'_' if bytes.get(i + 1) != Some(&b'{') => panic!("unescaped _ at byte {i} in {s}"),
            _ => {}
        }
        i += 1;
    }
    assert_eq!(depth, 0, "unbalanced braces in {s}");
    assert!(envs.is_empty(), "unclosed environments {envs:?} in {s}");
    for body in s.split(r"\begin{pmatrix}").skip(1) {
        let body = &body[..body.find(r"\end{pmatrix}").expect("pmatrix closed")];
        let rows: Vec<&str> = body.split(r" \\ ").collect();
        assert_eq!(rows.len(), 4, "4 rows in {body}");
        for r in rows {
            assert_eq!(r.matches(" & ").count(), 3, "4 entries in row {r}");
        }
    }
}

#[test]
fn latex_is_well_formed() {
    let products = [
        course_product(),
        MatrixProduct::identity(),
        MatrixProduct::identity()
            .then(Factor::perspective(45.0, 1.0, 1.0, 500.0))
            .then(Factor::rotate(Axis::Any(Vec3::new(1.0, 1.0, 0.0)), Param::sym("phi_1", 30.0)))
            .then(Factor::rotate(Axis::Z, Param::sym("a_{b}&%#$~^\\", 10.0)))
            .then(Factor::Scale([Param::sym("s_x", 2.0), Param::num(1.0), Param::sym("s_z", 3.0)]))
            .then(Factor::named("M_model", Mat4::IDENTITY)),
    ];
    for p in &products {
        for symbolic in [true, false] {
            let s = p.latex(symbolic).unwrap();
            assert_valid_latex(&s);
            // "= product" only for numeric output with factors (the empty product is the
            // identity alone).
            assert_eq!(s.contains("= "), !symbolic && !p.factors.is_empty(), "{s}");
        }
    }
    // The checker itself rejects broken LaTeX (so the test above can fail).
    for broken in
        [r"\begin{pmatrix} 1 \end{matrix}", "{", r"a_b", r"\begin{pmatrix} 1 & 2 \end{pmatrix}"]
    {
        assert!(std::panic::catch_unwind(|| assert_valid_latex(broken)).is_err(), "{broken}");
    }
}

#[test]
fn a_product_that_overflows_is_an_error_not_infinities() {
    use cg_core::transform::TransformError;
    let p = MatrixProduct::identity()
        .then(Factor::scale(Vec3::splat(3e38)))
        .then(Factor::translate(Vec3::new(3e38, 0.0, 0.0)));
    // Each factor alone is fine …
    assert!(p.factors.iter().all(|f| f.matrix().is_ok()));
    // … their product is 9e76 in the translation column.
    assert_eq!(p.matrix(), Err(TransformError::Overflow { what: "the product" }));
}
