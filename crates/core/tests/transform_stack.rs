//! The matrix stack: OpenGL's push/pop/mult semantics, with the named product kept alongside.

use cg_core::glam::{Mat4, Vec3};
use cg_core::product::{Factor, MatrixProduct};
use cg_core::stack::{DEFAULT_MAX_DEPTH, MatrixStack, StackError};
use cg_core::transform::{TransformError, rotate_z_deg, transform_point, translate};
use cg_testkit::prop::vec3;
use proptest::prelude::*;

fn config(cases: u32) -> ProptestConfig {
    cg_testkit::prop::config(cases, 0x57ac_c0de)
}

fn factor() -> impl Strategy<Value = Factor> {
    prop_oneof![
        vec3(-3.0, 3.0).prop_map(Factor::translate),
        vec3(-2.0, 2.0).prop_map(Factor::scale),
        (-720.0f32..720.0).prop_map(Factor::rotate_x_deg),
        (-720.0f32..720.0).prop_map(Factor::rotate_y_deg),
        (-720.0f32..720.0, vec3(-3.0, 3.0)).prop_map(|(a, v)| Factor::rotate_deg(a, v)),
    ]
}

fn factors(max: usize) -> impl Strategy<Value = Vec<Factor>> {
    proptest::collection::vec(factor(), 0..max)
}

proptest! {
    #![proptest_config(config(128))]

    #[test]
    fn push_pop_restores_the_top_exactly(before in factors(5), inside in factors(5), nested in factors(3)) {
        let mut stack = MatrixStack::new();
        for f in before {
            stack.mult(f).unwrap();
        }
        let (top, product, depth) = (stack.top(), stack.top_product().clone(), stack.depth());
        stack.push().unwrap();
        prop_assert_eq!(stack.top(), top, "push duplicates the top");
        for f in inside {
            stack.mult(f).unwrap();
        }
        stack.push().unwrap();
        for f in nested {
            stack.mult(f).unwrap();
        }
        stack.load_identity();
        stack.pop().unwrap();
        stack.pop().unwrap();
        // Bit for bit: the saved matrix, not a recomputation.
        prop_assert_eq!(stack.top().to_cols_array().map(f32::to_bits), top.to_cols_array().map(f32::to_bits));
        prop_assert_eq!(stack.top_product(), &product);
        prop_assert_eq!(stack.depth(), depth);
    }

    #[test]
    fn stack_mult_equals_product_concat(loaded in factors(4), multiplied in factors(5)) {
        let p = MatrixProduct { factors: loaded };
        let q = MatrixProduct { factors: multiplied };
        let mut stack = MatrixStack::new();
        stack.load(p.clone()).unwrap();
        for f in q.factors.clone() {
            stack.mult(f).unwrap();
        }
        let pq = p.concat(&q);
        prop_assert_eq!(stack.top_product(), &pq);
        // Both multiply left to right in f32, so the cached top is the product's matrix exactly.
        prop_assert_eq!(stack.top(), pq.matrix().unwrap());
    }
}

#[test]
fn pop_with_only_the_current_matrix_is_underflow() {
    let mut stack = MatrixStack::new();
    stack.translate(Vec3::X).unwrap();
    let before = stack.clone();
    assert_eq!(stack.pop(), Err(StackError::Underflow));
    assert_eq!(stack, before, "a failed pop changes nothing");
    stack.push().unwrap();
    assert_eq!(stack.pop(), Ok(()));
    assert_eq!(stack.pop(), Err(StackError::Underflow), "one push allows one pop");
    assert!(StackError::Underflow.to_string().contains("GL_STACK_UNDERFLOW"));
}

#[test]
fn push_beyond_the_limit_is_overflow() {
    let mut stack = MatrixStack::new();
    for depth in 2..=DEFAULT_MAX_DEPTH {
        stack.push().unwrap();
        assert_eq!(stack.depth(), depth);
    }
    assert_eq!(stack.push(), Err(StackError::Overflow { max_depth: DEFAULT_MAX_DEPTH }));
    assert_eq!(stack.depth(), DEFAULT_MAX_DEPTH, "a failed push changes nothing");

    let mut small = MatrixStack::with_max_depth(2);
    small.push().unwrap();
    let err = small.push().unwrap_err();
    assert_eq!(err, StackError::Overflow { max_depth: 2 });
    assert!(err.to_string().contains("GL_STACK_OVERFLOW") && err.to_string().contains('2'));
    // A limit of 0 still holds the current matrix.
    let mut zero = MatrixStack::with_max_depth(0);
    assert_eq!(zero.depth(), 1);
    assert_eq!(zero.push(), Err(StackError::Overflow { max_depth: 1 }));
}

#[test]
fn invalid_factors_are_errors_and_leave_the_stack_unchanged() {
    let mut stack = MatrixStack::new();
    stack.translate(Vec3::new(0.0, 0.0, -15.0)).unwrap();
    let before = stack.clone();
    let err = stack.rotate_deg(30.0, Vec3::ZERO).unwrap_err();
    assert!(matches!(err, StackError::Transform(TransformError::RotationAxis { .. })), "{err:?}");
    assert!(err.to_string().contains("rotation axis"), "{err}");
    assert!(stack.translate(Vec3::new(f32::NAN, 0.0, 0.0)).is_err());
    assert!(stack.scale(Vec3::new(1.0, f32::INFINITY, 1.0)).is_err());
    let bad = MatrixProduct::identity().then(Factor::perspective(0.0, 1.0, 1.0, 2.0));
    assert!(matches!(
        stack.load(bad),
        Err(StackError::Transform(TransformError::InFactor { index: 0, .. }))
    ));
    assert_eq!(stack, before);
}

#[test]
fn mult_acts_on_the_right_like_gl_calls() {
    // glTranslatef(1, 0, 0); glRotatef(90, 0, 0, 1); then a vertex at (1, 0, 0):
    // the rotation acts first → (0, 1, 0), then the translation → (1, 1, 0).
    let mut stack = MatrixStack::new();
    stack.translate(Vec3::X).unwrap();
    stack.rotate_deg(90.0, Vec3::Z).unwrap();
    assert_eq!(transform_point(stack.top(), Vec3::X), Vec3::new(1.0, 1.0, 0.0));
    assert_eq!(stack.top(), translate(Vec3::X) * rotate_z_deg(90.0));
    assert_eq!(stack.top_product().numeric(), "T(1, 0, 0) · Rz(90°)");
    // Other axes keep their general form.
    stack.rotate_deg(0.0, Vec3::new(0.0, -1.0, 0.0)).unwrap();
    assert_eq!(stack.top_product().numeric(), "T(1, 0, 0) · Rz(90°) · R(0°, 0, -1, 0)");
    stack.scale(Vec3::splat(2.0)).unwrap();
    assert_eq!(transform_point(stack.top(), Vec3::X), Vec3::new(1.0, 2.0, 0.0));
}

#[test]
fn load_identity_and_load_replace_only_the_top() {
    let mut stack = MatrixStack::new();
    stack.translate(Vec3::Y).unwrap();
    stack.push().unwrap();
    stack.load_identity();
    assert_eq!(stack.top(), Mat4::IDENTITY);
    assert_eq!(stack.top_product(), &MatrixProduct::identity());
    let p = MatrixProduct::identity().then(Factor::scale(Vec3::splat(3.0)));
    stack.load(p.clone()).unwrap();
    assert_eq!(stack.top_product(), &p);
    assert_eq!(stack.top(), Mat4::from_scale(Vec3::splat(3.0)));
    stack.pop().unwrap();
    assert_eq!(stack.top(), translate(Vec3::Y));
    assert_eq!(MatrixStack::default(), MatrixStack::new());
}

#[test]
fn the_warm_up_boxes_share_the_view_through_push_and_pop() {
    // The in-class warm-up: the view, then three boxes each inside its own push/pop.
    let mut stack = MatrixStack::new();
    stack.translate(Vec3::new(0.0, 0.0, -15.0)).unwrap();
    stack.rotate_deg(30.0, Vec3::X).unwrap();
    let view = stack.top();
    let mut tops = Vec::new();
    for (i, angle) in [10.0f32, 20.0, 30.0].into_iter().enumerate() {
        stack.push().unwrap();
        stack.translate(Vec3::new(i as f32 * 2.0, 0.0, 0.0)).unwrap();
        stack.rotate_deg(angle, Vec3::Y).unwrap();
        tops.push(stack.top_product().numeric());
        stack.pop().unwrap();
        assert_eq!(stack.top(), view, "box {i} leaves the view as it was");
    }
    assert_eq!(tops[2], "T(0, 0, -15) · Rx(30°) · T(4, 0, 0) · Ry(30°)");
    assert_eq!(stack.depth(), 1);
}

#[test]
fn stack_and_transform_errors_read_in_both_languages() {
    use cg_core::lang::Lang;
    let mut stack = MatrixStack::new();
    let e = stack.pop().unwrap_err();
    assert!(e.message(Lang::Ja).contains("対応する push のない pop"), "{}", e.message(Lang::Ja));
    assert_eq!(e.message(Lang::En), e.to_string());
    let e = stack.rotate_deg(30.0, Vec3::ZERO).unwrap_err();
    let (ja, en) = (e.message(Lang::Ja), e.message(Lang::En));
    assert!(ja.contains("回転軸") && !ja.contains("rotation axis"), "{ja}");
    assert!(en.contains("rotation axis") && !en.contains("回転軸"), "{en}");
}
