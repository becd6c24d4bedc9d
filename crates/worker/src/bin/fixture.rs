//! `cg-worker-fixture` — a **test fixture** of cg-worker, not a tool: a worker whose functions
//! behave as students' functions do at their worst, for the crate's tests.

// A stub as a student has it: the todo!() is the point.
#![allow(clippy::todo)]

use cg_student::a3;
use cg_worker::serve::{Handler, handler, serve};

fn main() -> std::io::Result<()> {
    // `--memory-mb N`: the worker's own limit, as cg-check-runner sets it. `--a3-loop idle` or
    // `--a3-loop display`: a3's table, with that function looping from frame 5 on.
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut a3_loop = None;
    for pair in args.chunks(2) {
        match pair {
            [flag, mb] if flag == "--memory-mb" => {
                let mb: u64 = mb.parse().map_err(std::io::Error::other)?;
                cg_worker::limit_memory(mb)?;
            }
            [flag, which] if flag == "--a3-loop" => a3_loop = Some(which.clone()),
            _ => return Err(std::io::Error::other(format!("unknown arguments {pair:?}"))),
        }
    }
    let mut handlers: Vec<(&str, Handler)> = vec![
        ("add", handler(|(a, b): (i64, i64)| a + b)),
        ("todo", handler(|(): ()| -> i64 { todo!("t.t1: write it") })),
        (
            // A stub that runs, with its marker: its value comes back with the marker.
            "stub",
            handler(|x: i64| {
                cg_student::not_started("t.t2");
                x
            }),
        ),
        (
            // A marker, then a panic: the panic comes back with the marker.
            "stub_panic",
            handler(|(): ()| -> i64 {
                cg_student::not_started("t.t3");
                panic!("index out of bounds")
            }),
        ),
        (
            "loop",
            handler(|(): ()| -> i64 {
                loop {
                    std::hint::spin_loop();
                }
            }),
        ),
        ("abort", handler(|(): ()| -> i64 { std::process::abort() })),
        ("exit", handler(|code: i32| -> i64 { std::process::exit(code) })),
        ("recurse", handler(|n: u64| -> u64 { recurse(n) })),
        // A panic whose message is `n` bytes (a hostile submission's, to fill the grader).
        ("shout", handler(|n: usize| -> i64 { panic!("{}", "A".repeat(n)) })),
        (
            "print",
            handler(|x: i64| {
                println!("debugging: x = {x}");
                eprintln!("to stderr");
                x * 2
            }),
        ),
        (
            "hoard",
            // Up to `mb` MiB in 64 MiB pieces, each written (so that it is really used); the
            // count of pieces held when it returns.
            handler(|mb: u64| {
                let mut held: Vec<Vec<u8>> = Vec::new();
                while (held.len() as u64) * 64 < mb {
                    held.push(vec![1; 64 << 20]);
                }
                held.len()
            }),
        ),
        (
            "grow",
            handler(|mut v: Vec<f32>| {
                v.push(1.5);
                v
            }),
        ),
        // A list of `n` one-byte numbers (a reply of `n` items).
        ("items", handler(|n: usize| vec![0u8; n])),
        (
            // The call's own value, then a thread that writes well-formed replies of 4 MiB
            // without end, unasked (to fill the caller's memory). The thread starts writing a
            // little after the value, so that the value is the call's reply even on a loaded
            // machine (it wrote first there, and the test took the refusal one call early).
            "flood",
            handler(|(): ()| -> i64 {
                std::thread::spawn(|| {
                    std::thread::sleep(std::time::Duration::from_millis(200));
                    let value =
                        cg_worker::to_value(&vec![7u8; 4 << 20]).unwrap_or(cg_worker::Value::Null);
                    let bytes =
                        cg_worker::encode(&cg_worker::Reply::Value(value)).unwrap_or_default();
                    while cg_worker::frame::write(&mut std::io::stdout().lock(), &bytes).is_ok() {}
                });
                1
            }),
        ),
        (
            // Says it runs another batch's function (a worker's word is only a report: the
            // caller names its own function), then loops.
            "a1.faces",
            handler(|(): ()| -> i64 {
                cg_worker::serve::running("a3.display", Some(3));
                loop {
                    std::hint::spin_loop();
                }
            }),
        ),
    ];
    match a3_loop.as_deref() {
        Some("idle") => handlers.extend(cg_worker::tables::a3(a3::Impl {
            warmup_display: |_, _| {},
            idle: looping_idle,
            display: |_, _, _| {},
        })),
        Some("display") => handlers.extend(cg_worker::tables::a3(a3::Impl {
            warmup_display: |_, _| {},
            idle: |_, state| state.frame += 1,
            display: looping_display,
        })),
        _ => {}
    }
    serve(&handlers)
}

/// An `idle` that loops from frame 5 on.
fn looping_idle(_: &a3::Spec, state: &mut a3::State) {
    state.frame += 1;
    if state.frame >= 5 {
        loop {
            std::hint::spin_loop();
        }
    }
}

/// A `display` that loops from frame 5 on.
fn looping_display(_: &a3::Spec, state: &a3::State, _: &mut cg_student::gl::Gl) {
    if state.frame >= 5 {
        loop {
            std::hint::spin_loop();
        }
    }
}

/// Recursion without end in practice (each frame holds 4 KiB), to overflow the stack.
fn recurse(n: u64) -> u64 {
    let frame = std::hint::black_box([n; 512]);
    if n == 0 { frame[0] } else { recurse(n + 1).wrapping_add(frame[7]) }
}
