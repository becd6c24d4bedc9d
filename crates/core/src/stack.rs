//! The matrix stack of OpenGL (glPushMatrix / glPopMatrix / glLoadIdentity / glMultMatrix), which
//! also keeps each matrix as a [`MatrixProduct`] of named factors for the report.

use glam::Mat4;

use crate::product::MatrixProduct;

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
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
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
}
