//! What the report is about: the data derived for one student (or from a data file), shared by
//! the tables, the figures, the checker and the template.

/// A number as a student wrote it: its value and how many decimals it has, so the checker can
/// accept correct rounding (`0.53` for 0.5299…) and nothing else.
#[derive(Clone, Debug, PartialEq)]
pub struct Written {
    /// The value.
    pub value: f64,
    /// Decimals written after the point (0 for `15`, 2 for `0.53`).
    pub decimals: u32,
    /// The text as written.
    pub text: String,
}

// Each assignment's part is its own crate's (`report.rs` beside its checks); the report
// formats them.
pub use cg_assign::Derived;
pub use cg_assign::cg_a1::report::PolygonData;
pub use cg_assign::cg_a2::report::CameraData;
pub use cg_assign::cg_a3::report::AnimationData;
pub use cg_assign::cg_a4::report::{TexRow, TextureData};
pub use cg_assign::cg_shading::report::ShadingData;
pub use cg_harness::report::NamedMatrix;
