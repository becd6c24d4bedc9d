//! `cg-sandbox-hostile` — a **test fixture** of cg-sandbox, not a tool: a program that misbehaves
//! on purpose, one way per mode, so the tests can check that the sandbox stops it. Built by
//! cargo for the crate's tests (`CARGO_BIN_EXE_cg-sandbox-hostile`).
//!
//! `cg-sandbox-hostile MODE [PATH]`, MODE one of:
//! `loop` (appends a byte to `ticks` in the current folder and prints `.` every 20 ms, forever),
//! `alloc` (grows its memory until an allocation fails), `panic`, `write-outside PATH` (writes
//! PATH and `/etc/cg-sandbox-hostile`), `read PATH` (prints PATH), `spawn` (starts itself, then
//! `sh`), `net` (connects to 1.1.1.1:53), `print` (100 MB on stdout and 1 MB on stderr), `env`
//! (prints its environment), `threads` (sums on 4 threads), `ok` (writes `result.txt` and prints
//! `done`), `fill-tmp MIB` and `fill-workdir MIB` (write files of 1 MiB each, in `/tmp` or in
//! the current folder, until a write fails or MIB MiB are written, then print `wrote BYTES bytes
//! in FILES files, then: ERROR` and exit 1, or `... never stopped` and exit 0).
//! Each mode reports what it could and could not do on stdout.

use std::io::Write;
use std::time::Duration;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mode = args.get(1).map_or("", String::as_str);
    let path = args.get(2).cloned().unwrap_or_default();
    match mode {
        "loop" => loop {
            if let Ok(mut f) = std::fs::OpenOptions::new().create(true).append(true).open("ticks") {
                let _ = f.write_all(b".");
            }
            let mut out = std::io::stdout().lock();
            let _ = out.write_all(b".").and_then(|()| out.flush());
            drop(out);
            std::thread::sleep(Duration::from_millis(20));
        },
        "fill-tmp" => fill("/tmp/cg-sandbox-hostile-fill", &path),
        "fill-workdir" => fill("fill", &path),
        "alloc" => {
            let mut held: Vec<Vec<u8>> = Vec::new();
            loop {
                held.push(vec![1u8; 16 << 20]);
                println!("holding {} MiB", held.len() * 16);
            }
        }
        "panic" => panic!("hostile: panicking on purpose"),
        "write-outside" => {
            let mut wrote = false;
            for p in [path.as_str(), "/etc/cg-sandbox-hostile"] {
                match std::fs::write(p, b"escaped") {
                    Ok(()) => {
                        wrote = true;
                        println!("written: {p}");
                    }
                    Err(e) => println!("denied: {p}: {e}"),
                }
            }
            std::process::exit(i32::from(wrote));
        }
        "read" => match std::fs::read_to_string(&path) {
            Ok(s) => println!("read: {s}"),
            Err(e) => {
                println!("denied: {path}: {e}");
                std::process::exit(1);
            }
        },
        "spawn" => {
            // Itself (its path is in the sandbox: it is the program), then a shell.
            let me = args.first().cloned().unwrap_or_default();
            match std::process::Command::new(&me).arg("echo-spawned").output() {
                Ok(out) => {
                    print!("{}", String::from_utf8_lossy(&out.stdout));
                    std::process::exit(0);
                }
                Err(e) => println!("spawn failed: {me}: {e}"),
            }
            for sh in ["sh", "/bin/sh", "/usr/bin/sh"] {
                match std::process::Command::new(sh).args(["-c", "echo spawned"]).output() {
                    Ok(out) => {
                        print!("{}", String::from_utf8_lossy(&out.stdout));
                        std::process::exit(0);
                    }
                    Err(e) => println!("spawn failed: {sh}: {e}"),
                }
            }
            std::process::exit(1);
        }
        "net" => {
            let addr = std::net::SocketAddr::from(([1, 1, 1, 1], 53));
            match std::net::TcpStream::connect_timeout(&addr, Duration::from_secs(3)) {
                Ok(_) => println!("connected"),
                Err(e) => {
                    println!("net failed: {e}");
                    std::process::exit(1);
                }
            }
        }
        "print" => {
            let line = [b'x'; 1000];
            let mut out = std::io::stdout().lock();
            for _ in 0..100_000 {
                if out.write_all(&line).is_err() {
                    break;
                }
            }
            let _ = out.flush();
            let mut err = std::io::stderr().lock();
            for _ in 0..1000 {
                let _ = err.write_all(&line);
            }
        }
        "echo-spawned" => println!("spawned"),
        "threads" => {
            let handles: Vec<_> = (1..=4u64).map(|k| std::thread::spawn(move || k * 10)).collect();
            let sum: u64 = handles.into_iter().map(|h| h.join().unwrap_or(0)).sum();
            println!("threads: {sum}");
        }
        "env" => {
            for (k, v) in std::env::vars_os() {
                println!("{}={}", k.to_string_lossy(), v.to_string_lossy());
            }
        }
        "ok" => match std::fs::write("result.txt", b"fine") {
            Ok(()) => println!("done"),
            Err(e) => {
                println!("cannot write result.txt: {e}");
                std::process::exit(1);
            }
        },
        other => {
            eprintln!("unknown mode {other:?}");
            std::process::exit(2);
        }
    }
}

/// Writes files `{prefix}-0`, `{prefix}-1`, … of 1 MiB each (well under any per-file limit) in
/// 64 KiB writes until one fails or `cap_mib` MiB are written; reports the bytes written (every
/// byte a write accepted) and exits.
fn fill(prefix: &str, cap_mib: &str) -> ! {
    let cap = cap_mib.parse::<u64>().unwrap_or(64) << 20;
    let chunk = vec![0x5a_u8; 64 << 10];
    let mut total: u64 = 0;
    let mut files: u64 = 0;
    let failed = 'fill: loop {
        if total >= cap {
            break None;
        }
        let name = format!("{prefix}-{files}");
        let mut file = match std::fs::File::create(&name) {
            Ok(f) => f,
            Err(e) => break Some(format!("create {name}: {e}")),
        };
        files += 1;
        let mut in_file = 0;
        while in_file < 1 << 20 && total < cap {
            match file.write(&chunk) {
                Ok(0) => break 'fill Some(format!("write {name}: wrote nothing")),
                Ok(n) => {
                    in_file += n;
                    total += n as u64;
                }
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(e) => break 'fill Some(format!("write {name}: {e}")),
            }
        }
    };
    match failed {
        Some(e) => {
            println!("wrote {total} bytes in {files} files, then: {e}");
            std::process::exit(1);
        }
        None => {
            println!("wrote {total} bytes in {files} files, never stopped");
            std::process::exit(0);
        }
    }
}
