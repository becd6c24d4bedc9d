//! The students' API: everything `exercises/` may use, and nothing that computes an answer.
//!
//! Your crate depends on this crate alone. It holds what you need to *write* the answers:
//!
//! - [`glam`], the vector and matrix types ([`glam::Vec3`], [`glam::Mat4`], …);
//! - one module per assignment ([`a1`], [`a2`], [`a3`], [`a4`], [`s`]) with your variant's spec
//!   types and the table of functions you write (`Impl`);
//! - the [`gl::Gl`] recorder for `display()`, the [`mesh::Mesh`] data type and the named
//!   factors of [`product`] that your report prints.
//!
//! What the checks compare your answers with (expected vertices, normals, products, poses,
//! light terms, reflections) lives in the kit's own crates, which your crate cannot name: a
//! submission can only pass by computing.
//!
//! 学生用 API: `exercises/` が使えるのはこのクレートだけです。答えを計算する関数はここにはありません。

pub use glam;

pub mod a1;
pub mod a2;
pub mod a3;
pub mod a4;
pub mod gl;
pub mod mesh;
pub mod product;
pub mod s;

/// A colour: linear RGB in `[0, 1]` (`x` = red, `y` = green, `z` = blue), as
/// [`glam::Vec3`] so colours add and scale like vectors.
pub type Rgb = glam::Vec3;

/// Serialises an f32 as the f64 with the same shortest decimal digits, so JSON shows the table's
/// friendly `1.6`, not `1.600000023841858` (the f32 widened).
pub(crate) fn friendly<S: serde::Serializer>(x: &f32, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_f64(friendly_f64(*x))
}

/// The f64 nearest to `x`'s shortest decimal.
fn friendly_f64(x: f32) -> f64 {
    x.to_string().parse::<f64>().unwrap_or(f64::from(x))
}

/// Reads what [`friendly`] wrote back as the same f32 (the worker's pipe: cg-worker's
/// `tables`). Rounding the f64 to f32 is a second rounding after the decimal's to f64, and for
/// two f32s (±7.038531e-26, of all 2³²) it lands on the neighbour; so the f32 is the one whose
/// shortest decimal is the f64 read, and only a number that is no f32's shortest decimal (or
/// one a parser rounded inexactly) rounds to the nearest.
pub(crate) fn unfriendly<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f32, D::Error> {
    <f64 as serde::Deserialize>::deserialize(d).map(from_friendly)
}

/// The f32 whose [`friendly_f64`] is `v`, else `v` rounded to f32.
pub(crate) fn from_friendly(v: f64) -> f32 {
    let x = v as f32;
    [x, x.next_down(), x.next_up()].into_iter().find(|&c| friendly_f64(c) == v).unwrap_or(x)
}
