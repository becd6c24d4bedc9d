//! Where the GPU's time per frame goes, for `raster_vs_gpu`'s four rows: the frame drawn alone
//! (`render_to_view` into a target of its own, then a wait for the GPU), drawn and read back
//! (`Gpu::read_back_into`, the frame's kept target and buffer, into the last frame's image), and
//! what a new target and read-back buffer would cost on each frame (made, dropped, waited for):
//! on a real GPU these are driver allocations. Best of REPEATS (course: of 5 × REPEATS), after a
//! warm-up. Prints `name value` lines (docs/gpu.md).
//!
//! ```text
//! cargo run --release -p cg-raster --example gpu_frame_parts -- [REPEATS]
//! ```

use std::path::Path;
use std::time::Instant;

use cg_core::scene::{Scene, Shading};
use cg_gpu::wgpu;

#[path = "../benches/common/mod.rs"]
mod common;
use common::icosphere_scene;

/// Best of `repeats` timings of `f` in seconds, after one untimed call.
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

/// Times one row's parts; prints them.
fn parts(
    name: &str,
    gpu: &cg_gpu::Gpu,
    scene: &Scene,
    size: (u32, u32),
    shading: Shading,
    n: usize,
) {
    let options = cg_gpu::Options { shading: Some(shading), size: Some(size) };
    let frame = gpu.frame(scene, &options, cg_gpu::READBACK_FORMAT).expect("the GPU makes it");
    let device = gpu.device();
    let extent = wgpu::Extent3d { width: size.0, height: size.1, depth_or_array_layers: 1 };
    // A target and a read-back buffer as `read_back` makes them.
    let new_target_and_buffer = || {
        let target = device.create_texture(&wgpu::TextureDescriptor {
            label: None,
            size: extent,
            mip_level_count: 1,
            sample_count: 1,
            dimension: wgpu::TextureDimension::D2,
            format: frame.format,
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
            view_formats: &[],
        });
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: None,
            size: u64::from((size.0 * 4).div_ceil(256) * 256) * u64::from(size.1),
            usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
            mapped_at_creation: false,
        });
        (target, buffer)
    };
    let wait = || {
        device.poll(wgpu::PollType::wait_indefinitely()).expect("the GPU finishes");
    };
    let (target, _) = new_target_and_buffer();
    let view = target.create_view(&wgpu::TextureViewDescriptor::default());
    let draw = best(n, || {
        gpu.render_to_view(&frame, &view);
        wait();
    });
    let mut image = gpu.read_back(&frame).expect("the GPU draws");
    let read_back = best(n, || gpu.read_back_into(&frame, &mut image).expect("the GPU draws"));
    let allocation = best(n, || {
        drop(new_target_and_buffer());
        wait();
    });
    println!("{name}_draw_ms {:.3}", draw * 1e3);
    println!("{name}_read_back_ms {:.3}", read_back * 1e3);
    println!("{name}_new_target_and_buffer_ms {:.3}", allocation * 1e3);
}

fn name(s: Shading) -> &'static str {
    if s == Shading::Phong { "phong" } else { "gouraud" }
}

fn main() {
    let n: usize = std::env::args().nth(1).map_or(20, |r| r.parse().expect("REPEATS is a number"));
    let gpu = match cg_gpu::Gpu::new() {
        Ok(gpu) => gpu,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(1);
        }
    };
    println!("gpu_adapter {}", gpu.adapter_info());
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/course-sample.toml");
    let course = cg_scene::load(&path).expect("the course scene loads");
    for s in [Shading::Gouraud, Shading::Phong] {
        parts(&format!("course_640_{}", name(s)), &gpu, &course, (640, 640), s, n * 5);
    }
    let sphere = icosphere_scene();
    for s in [Shading::Gouraud, Shading::Phong] {
        parts(&format!("icosphere_1080p_{}", name(s)), &gpu, &sphere, (1920, 1080), s, n);
    }
}
