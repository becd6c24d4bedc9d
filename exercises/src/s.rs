//! Assignment `s`. (Its tasks arrive with the assignment.)

/// The functions of this module, for the checks and the view.
#[must_use]
pub fn implementation() -> cg_shading::Impl {
    cg_shading::Impl {}
}
