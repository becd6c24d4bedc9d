//! # 課題 / The exercises
//!
//! This crate is what you edit: one module per assignment. Each function carries its task ID
//! (`a1.t2`), its contract (inputs, outputs, units, edge cases) and a hint. A function still
//! `todo!()` is reported as "not done yet" by `cargo run --release -- check`. So is one that
//! still has its first line `cg_student::not_started("a2.t1");` (the stubs that must run so
//! the view still draws, in a2, a3 and s.t5): **delete that line when you start the function**;
//! while it is there the checks do not look at your code.
//!
//! 編集するのはこのクレートです。課題ごとにモジュールがあり、各関数には課題番号（`a1.t2` など）、
//! 入力と出力の約束、ヒントが書いてあります。`todo!()` のままの関数は、
//! `cargo run --release -- check` で「まだです」と表示されます。最初の行に
//! `cg_student::not_started("a2.t1");` がある関数（表示のために動いている a2・a3・s.t5 のスタブ）も
//! 同じです。**関数を書き始めたら、その行を消してください**。その行があるあいだ、チェックはあなたの
//! コードを判定しません。
//!
//! | module | assignment |
//! |---|---|
//! | [`a1`] | 1. ポリゴンモデルの描画 / polygon model |
//! | [`a2`] | 2. 視点操作インターフェースの拡張 / camera interface |
//! | [`a3`] | 3. アニメーション / animation |
//! | [`a4`] | 4. テクスチャマッピング / texture mapping |
//! | [`s`] | 第11回 シェーディング / shading |

// The stubs below are `todo!()`s whose parameters are not used yet: neither is a mistake here.
#![allow(unused_variables, clippy::todo)]

// A file of yours that does not compile is left out, and a stand-in takes its place, when the
// kit builds your functions for `cargo run --release -- check`, `view` and `report`: the other
// assignments still run. build.rs sets `left_out` for those builds only.
/// The stand-in of a module left out (see below).
#[allow(unused_macros)]
macro_rules! left_out {
    ($module:ident) => {
        pub mod $module {
            //! Left out: this file does not compile.
            /// Functions the kit never calls (it says the file does not compile instead).
            #[must_use]
            pub fn implementation() -> cg_student::$module::Impl {
                cg_student::$module::Impl::left_out()
            }
        }
    };
}

#[cfg(not(left_out = "a1"))]
pub mod a1;
#[cfg(left_out = "a1")]
left_out!(a1);
#[cfg(not(left_out = "a2"))]
pub mod a2;
#[cfg(left_out = "a2")]
left_out!(a2);
#[cfg(not(left_out = "a3"))]
pub mod a3;
#[cfg(left_out = "a3")]
left_out!(a3);
#[cfg(not(left_out = "a4"))]
pub mod a4;
#[cfg(left_out = "a4")]
left_out!(a4);
#[cfg(not(left_out = "s"))]
pub mod s;
#[cfg(left_out = "s")]
left_out!(s);
