//! Student-facing text exists in Japanese and English: [`Text`], which lives in
//! [`cg_core::lang`] so every crate of the kit writes two languages one way.

pub use cg_core::lang::{Text, t};
