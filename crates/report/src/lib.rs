//! # cg-report — the report checker
//!
//! The course's report asks for vertex tables, face tables with normals, three-view and
//! perspective figures that show how vertices and faces connect, every transform matrix as a
//! product of rotations and translations with each variable explained, and texture-coordinate
//! ranges and formulas — with the derivation, not just the result. This crate
//!
//! - **derives** all of it from the student's own code (through each assignment's `Impl`) or
//!   from data alone (a vertex and face list in the lecture's notation) — [`model`], [`mod@derive`],
//!   [`figures`], [`tables`];
//! - **reads** a student's report (Markdown) and names every number that does not follow from
//!   the data, with the derived value and the tolerance used — [`parse`], [`verify`];
//! - **fills** the report template (`report-template/`, Markdown and LaTeX, Japanese and
//!   English) with the derived tables, figures and matrices — [`template`];
//! - checks the periods of assignment 3 as a tagged table ([`periods`]) and the texture
//!   formula of assignment 4, read as arithmetic in i and j and evaluated at every ground vertex
//!   ([`formula`]);
//! - does the same for the shading section's tables (assignment `s`: the light model, the light
//!   types, vertex normals, refraction), each number next to the student's functions' output —
//!   [`shading`].

pub mod app;
pub mod derive;
pub mod figures;
pub mod fill;
pub mod formula;
pub mod model;
pub mod parse;
pub mod periods;
pub mod shading;
pub mod tables;
pub mod template;
pub mod verify;
