//! The matrix stack of OpenGL (glPushMatrix / glPopMatrix / glLoadIdentity / glMultMatrix), which
//! also keeps each matrix as a [`MatrixProduct`] of named factors for the report.
//!
//! ```
//! use cg_core::glam::Vec3;
//! use cg_core::stack::MatrixStack;
//!
//! let mut stack = MatrixStack::new();
//! stack.translate(Vec3::new(0.0, 0.0, -15.0))?;   // glTranslatef(0, 0, -15)
//! stack.push()?;                                  // glPushMatrix()
//! stack.translate(Vec3::new(0.0, 1.0, 0.0))?;     //   glTranslatef(0, 1, 0)
//! assert_eq!(stack.top_product().numeric(), "T(0, 0, -15) · T(0, 1, 0)");
//! stack.pop()?;                                   // glPopMatrix()
//! assert_eq!(stack.top_product().numeric(), "T(0, 0, -15)");
//! # Ok::<(), cg_core::stack::StackError>(())
//! ```

use glam::{Mat4, Vec3};

use crate::lang::{Lang, Text};
use crate::product::{Factor, MatrixProduct};
use crate::transform::TransformError;

/// OpenGL's minimum GL_MAX_MODELVIEW_STACK_DEPTH, the default depth limit.
pub const DEFAULT_MAX_DEPTH: usize = 32;

/// A matrix stack with the semantics of OpenGL's: it always holds at least one matrix (the
/// current one, initially the identity); push duplicates the top, pop discards it.
#[derive(Clone, Debug, PartialEq)]
pub struct MatrixStack {
    /// (matrix, product) pairs, bottom first; never empty.
    entries: Vec<(Mat4, MatrixProduct)>,
    max_depth: usize,
}

/// What went wrong on the stack, with OpenGL's error names.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum StackError {
    /// Pop with only the current matrix left: a pop without its push.
    #[error("GL_STACK_UNDERFLOW: pop with no matching push (depth is already 1)")]
    Underflow,
    /// Push beyond the depth limit: usually a push without its pop inside a loop.
    #[error("GL_STACK_OVERFLOW: push beyond the maximum depth {max_depth}")]
    Overflow {
        /// The depth limit of this stack.
        max_depth: usize,
    },
    /// A factor (or a factor of a loaded product) is invalid: a zero rotation axis, a non-finite
    /// value, a bad perspective. The stack is unchanged.
    #[error("GL_INVALID_VALUE: {0}")]
    Transform(#[from] TransformError),
}

impl StackError {
    /// The message for a student in `lang` (`Display` is the English one), with OpenGL's error
    /// name and the usual cause.
    #[must_use]
    pub fn message(&self, lang: Lang) -> String {
        self.text().get(lang).to_owned()
    }

    /// The message in both languages.
    #[must_use]
    pub fn text(&self) -> Text {
        match self {
            StackError::Underflow => Text::new(
                "GL_STACK_UNDERFLOW: 対応する push のない pop です（深さはすでに 1）。push と pop の数と位置を確認してください",
                self.to_string(),
            ),
            StackError::Overflow { max_depth } => Text::new(
                format!(
                    "GL_STACK_OVERFLOW: 最大の深さ {max_depth} を超えて push しました（ループの中で pop を忘れていませんか）"
                ),
                self.to_string(),
            ),
            StackError::Transform(e) => {
                let e = e.text();
                Text::new(
                    format!("GL_INVALID_VALUE: {}", e.ja),
                    format!("GL_INVALID_VALUE: {}", e.en),
                )
            }
        }
    }
}

impl Default for MatrixStack {
    /// [`MatrixStack::new`].
    fn default() -> MatrixStack {
        MatrixStack::new()
    }
}

impl MatrixStack {
    /// A stack holding only the identity, with the depth limit [`DEFAULT_MAX_DEPTH`].
    #[must_use]
    pub fn new() -> MatrixStack {
        MatrixStack::with_max_depth(DEFAULT_MAX_DEPTH)
    }

    /// A stack holding only the identity that allows `max_depth` matrices at most. A limit of 0 is
    /// taken as 1: the current matrix is always there.
    #[must_use]
    pub fn with_max_depth(max_depth: usize) -> MatrixStack {
        MatrixStack {
            entries: vec![(Mat4::IDENTITY, MatrixProduct::identity())],
            max_depth: max_depth.max(1),
        }
    }

    /// glPushMatrix: duplicates the current matrix, so changes until the matching [`pop`]
    /// are undone by it.
    ///
    /// # Errors
    /// [`StackError::Overflow`] when the stack already holds `max_depth` matrices (unchanged).
    ///
    /// [`pop`]: MatrixStack::pop
    pub fn push(&mut self) -> Result<(), StackError> {
        if self.entries.len() >= self.max_depth {
            return Err(StackError::Overflow { max_depth: self.max_depth });
        }
        let top = self.current().clone();
        self.entries.push(top);
        Ok(())
    }

    /// glPopMatrix: discards the current matrix; the one saved by the matching [`push`] is current
    /// again, exactly.
    ///
    /// # Errors
    /// [`StackError::Underflow`] when only the current matrix is left (unchanged; never a panic).
    ///
    /// [`push`]: MatrixStack::push
    pub fn pop(&mut self) -> Result<(), StackError> {
        if self.entries.len() <= 1 {
            return Err(StackError::Underflow);
        }
        self.entries.pop();
        Ok(())
    }

    /// glLoadIdentity: the current matrix becomes the identity (the empty product).
    pub fn load_identity(&mut self) {
        *self.current_mut() = (Mat4::IDENTITY, MatrixProduct::identity());
    }

    /// glLoadMatrix with names: the current matrix becomes `product`.
    ///
    /// # Errors
    /// [`StackError::Transform`] when a factor is invalid (the stack is unchanged).
    pub fn load(&mut self, product: MatrixProduct) -> Result<(), StackError> {
        let m = product.matrix()?;
        *self.current_mut() = (m, product);
        Ok(())
    }

    /// glMultMatrix / glTranslatef / glRotatef / glScalef: current = current · factor, so the
    /// factor acts on vertices before everything already on the stack.
    ///
    /// # Errors
    /// [`StackError::Transform`] when the factor is invalid (the stack is unchanged).
    pub fn mult(&mut self, factor: Factor) -> Result<(), StackError> {
        let m = factor.matrix()?;
        let (top, product) = self.current_mut();
        *top *= m;
        product.push(factor);
        Ok(())
    }

    /// glTranslatef(v.x, v.y, v.z).
    ///
    /// # Errors
    /// [`StackError::Transform`] for a non-finite component.
    pub fn translate(&mut self, v: Vec3) -> Result<(), StackError> {
        self.mult(Factor::translate(v))
    }

    /// glRotatef(angle_deg, axis.x, axis.y, axis.z) (exact at multiples of 90°).
    ///
    /// # Errors
    /// [`StackError::Transform`] for a zero or non-finite axis or a non-finite angle.
    pub fn rotate_deg(&mut self, angle_deg: f32, axis: Vec3) -> Result<(), StackError> {
        self.mult(Factor::rotate_deg(angle_deg, axis))
    }

    /// glScalef(v.x, v.y, v.z).
    ///
    /// # Errors
    /// [`StackError::Transform`] for a non-finite component.
    pub fn scale(&mut self, v: Vec3) -> Result<(), StackError> {
        self.mult(Factor::scale(v))
    }

    /// The current matrix (cached: O(1)).
    #[must_use]
    pub fn top(&self) -> Mat4 {
        self.current().0
    }

    /// The current matrix as the factors multiplied since the last load (or since the start);
    /// its [`MatrixProduct::matrix`] equals [`MatrixStack::top`] exactly.
    #[must_use]
    pub fn top_product(&self) -> &MatrixProduct {
        &self.current().1
    }

    /// How many matrices the stack holds (1 when nothing is pushed).
    #[must_use]
    pub fn depth(&self) -> usize {
        self.entries.len()
    }

    /// The depth limit.
    #[must_use]
    pub fn max_depth(&self) -> usize {
        self.max_depth
    }

    fn current(&self) -> &(Mat4, MatrixProduct) {
        // Invariant: `entries` is never empty (new() pushes one, pop() keeps one).
        self.entries.last().expect("a matrix stack always holds its current matrix")
    }

    fn current_mut(&mut self) -> &mut (Mat4, MatrixProduct) {
        self.entries.last_mut().expect("a matrix stack always holds its current matrix")
    }
}
