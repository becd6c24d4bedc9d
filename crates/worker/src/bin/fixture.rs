//! `cg-worker-fixture` — a **test fixture** of cg-worker, not a tool: a worker whose functions
//! behave as students' functions do at their worst, for the crate's tests.

// A stub as a student has it: the todo!() is the point.
#![allow(clippy::todo)]

use cg_worker::serve::{Handler, handler, serve};

fn main() -> std::io::Result<()> {
    let handlers: Vec<(&str, Handler)> = vec![
        ("add", handler(|(a, b): (i64, i64)| a + b)),
        ("todo", handler(|(): ()| -> i64 { todo!("t.t1: write it") })),
        (
            "loop",
            handler(|(): ()| -> i64 {
                loop {
                    std::hint::spin_loop();
                }
            }),
        ),
        ("abort", handler(|(): ()| -> i64 { std::process::abort() })),
        (
            "print",
            handler(|x: i64| {
                println!("debugging: x = {x}");
                eprintln!("to stderr");
                x * 2
            }),
        ),
        (
            "grow",
            handler(|mut v: Vec<f32>| {
                v.push(1.5);
                v
            }),
        ),
    ];
    serve(&handlers)
}
