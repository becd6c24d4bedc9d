//! What the OpenGL reference costs: writing the command script (Rust only), and a whole render
//! (starting the program, OSMesa/llvmpipe drawing, reading the image back), for the course's
//! sample scene and the spot-light scene at 640×640.
//!
//! `cargo bench -p cg-glref`. Without a C compiler or OSMesa only the script is measured.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};

fn load(name: &str) -> cg_core::scene::Scene {
    let path = format!("{}/../../assets/scenes/{name}.toml", env!("CARGO_MANIFEST_DIR"));
    cg_scene::load(Path::new(&path)).unwrap_or_else(|e| panic!("{e}"))
}

fn bench(c: &mut Criterion) {
    let available = match cg_glref::available() {
        Ok(()) => true,
        Err(e) => {
            eprintln!("skipped the renders: {e}");
            false
        }
    };
    for name in ["course-sample", "spot-specular"] {
        let scene = load(name);
        c.bench_function(&format!("script/{name}"), |b| {
            b.iter(|| cg_glref::script(black_box(&scene)).unwrap());
        });
        if available {
            let mut group = c.benchmark_group("render");
            group.sample_size(20);
            group.bench_function(name, |b| b.iter(|| cg_glref::render(black_box(&scene)).unwrap()));
            group.finish();
        }
    }
}

criterion_group!(benches, bench);
criterion_main!(benches);
