//! The rasterizer against the kit's wgpu renderer on the same machine, in one run: the course
//! scene at 640 × 640 on one thread (frames per second), and an icosphere of 1.3 M triangles at
//! 1920 × 1080 with Phong shading, the CPU rasterizer on all cores against `cg_gpu::Gpu::render`
//! (on Mesa's lavapipe where that is the Vulkan driver: the same cores). Prints `name value` lines
//! and the ratios (docs/performance.md).
//!
//! ```text
//! VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json \
//!   cargo run --release -p cg-raster --example raster_vs_gpu -- [REPEATS]
//! ```

use std::path::Path;
use std::time::Instant;

use cg_raster::{Options, render};

#[path = "../benches/common/mod.rs"]
mod common;
use common::icosphere_scene;

/// Best of `repeats` timings of `f` in seconds, after one untimed warm-up call.
fn best(repeats: usize, mut f: impl FnMut()) -> f64 {
    f();
    (0..repeats.max(1))
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min)
}

fn main() {
    let repeats: usize =
        std::env::args().nth(1).map_or(10, |r| r.parse().expect("REPEATS is a number"));
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/course-sample.toml");
    let course = cg_scene::load(&path).expect("the course scene loads");
    let one = Options { threads: Some(1), ..Options::default() };
    let t = best(repeats * 5, || {
        std::hint::black_box(render(&course, &one).expect("the course scene renders"));
    });
    println!("course_640_1thread_ms {:.3}\ncourse_640_1thread_fps {:.1}", t * 1e3, 1.0 / t);

    let scene = icosphere_scene();
    let all = Options::default();
    let cpu = best(repeats, || {
        std::hint::black_box(render(&scene, &all).expect("the icosphere renders"));
    });
    let cpu_one = best(repeats.div_ceil(2), || {
        std::hint::black_box(render(&scene, &one).expect("the icosphere renders"));
    });
    println!("icosphere_1080p_cpu_all_cores_ms {:.2}", cpu * 1e3);
    println!("icosphere_1080p_cpu_1thread_ms {:.2}", cpu_one * 1e3);
    match cg_gpu::Gpu::new() {
        Ok(gpu) => {
            let options = cg_gpu::Options::default();
            let t = best(repeats, || {
                std::hint::black_box(gpu.render(&scene, &options).expect("the GPU renders"));
            });
            println!("gpu_adapter {}", gpu.adapter_info());
            println!("icosphere_1080p_gpu_ms {:.2}", t * 1e3);
            println!("ratio_cpu_over_gpu {:.2}", cpu / t);
        }
        Err(e) => println!("gpu_unavailable {e}"),
    }
}
