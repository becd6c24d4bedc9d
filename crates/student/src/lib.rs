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

use std::cell::RefCell;

pub use glam;

pub mod a1;
pub mod a2;
pub mod a3;
pub mod a4;
pub mod gl;
pub mod mesh;
pub mod product;
pub mod s;

/// The marker of a stub you have not started: `cg_student::not_started("a2.t1");` as the first
/// line of a function the kit hands out unfinished. It changes nothing your function does (the
/// stub still runs, so `cargo run --release -- view a2` still draws), but while this line is
/// there, every check that reaches it says **not done yet** for the task instead of judging
/// your code. **Delete the line when you start writing the function**: from then on the checks
/// judge what you wrote. A function that still has its marker is "not done yet" even when the
/// rest of it is right.
///
/// まだ手を付けていないスタブの印です。この行があるあいだ、この行を通るチェックは「まだです」に
/// なります（関数の中身は判定されません）。関数を書き始めたら、この行を消してください。
///
/// The marker is kept on the thread that calls it; the kit reads it with [`take_not_started`].
pub fn not_started(task: &str) {
    NOT_STARTED.with(|marks| {
        let mut marks = marks.borrow_mut();
        if marks.len() < MAX_MARKS && !marks.iter().any(|m| m == task) {
            marks.push(task.chars().take(MAX_MARK_CHARS).collect());
        }
    });
}

/// For the kit, not for your code: the tasks whose [`not_started`] markers were reached on this
/// thread since the last call, in the order first reached, and forgets them.
///
/// ```
/// cg_student::not_started("a2.t1");
/// cg_student::not_started("a2.t2");
/// cg_student::not_started("a2.t1");
/// assert_eq!(cg_student::take_not_started(), ["a2.t1", "a2.t2"]);
/// assert!(cg_student::take_not_started().is_empty());
/// ```
#[must_use]
pub fn take_not_started() -> Vec<String> {
    NOT_STARTED.with(|marks| std::mem::take(&mut *marks.borrow_mut()))
}

/// How many different markers [`not_started`] keeps (the first ones reached).
const MAX_MARKS: usize = 8;
/// How much of a marker's task [`not_started`] keeps, in characters.
const MAX_MARK_CHARS: usize = 40;

thread_local! {
    /// The markers reached on this thread (see [`not_started`]).
    static NOT_STARTED: RefCell<Vec<String>> = const { RefCell::new(Vec::new()) };
}

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

/// The body of every function of [`a1::Impl::left_out`] and its kind: the module did not
/// compile. The kit answers such a call itself and never sends it here.
fn left_out(module: &str) -> ! {
    panic!(
        "exercises/src/{module}.rs does not compile / exercises/src/{module}.rs がコンパイルできません"
    )
}
