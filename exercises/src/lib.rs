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

pub mod a1;
pub mod a2;
pub mod a3;
pub mod a4;
pub mod s;
