//! The kit's build of your functions leaves out a file that does not compile, so that the other
//! assignments still run: `cargo run --release -- check` (and `view`, `report`) names such files
//! in `CG_EXERCISES_LEFT_OUT` (`a1,s`), and this script turns each into `--cfg left_out="a1"`,
//! which swaps the file for a stand-in (src/lib.rs). Your own builds set nothing.

fn main() {
    const MODULES: [&str; 5] = ["a1", "a2", "a3", "a4", "s"];
    println!("cargo::rerun-if-changed=build.rs");
    println!("cargo::rerun-if-env-changed=CG_EXERCISES_LEFT_OUT");
    println!("cargo::rustc-check-cfg=cfg(left_out, values(\"a1\", \"a2\", \"a3\", \"a4\", \"s\"))");
    let left_out = std::env::var("CG_EXERCISES_LEFT_OUT").unwrap_or_default();
    for module in left_out.split(',').map(str::trim).filter(|m| MODULES.contains(m)) {
        println!("cargo::rustc-cfg=left_out=\"{module}\"");
    }
}
