//! The rasterizer against the kit's wgpu renderer on the same machine, in one run, both sides
//! timed the same way: the scene made ready once (the CPU's [`cg_raster::Prepared`], the GPU's
//! [`cg_gpu::Gpu::frame`]: buffers made and uploaded), then each timing draws the frame and reads
//! it back, as a window redraws (the CPU into the last frame's colour and depth buffers,
//! [`cg_raster::Prepared::draw_into`]; the GPU into its frame's depth buffer and target, copied
//! into the last frame's image, [`cg_gpu::Gpu::read_back_into`]). Four rows: the course scene at
//! 640 × 640 and an icosphere of 1.3 M triangles at 1920 × 1080, each in Gouraud and Phong
//! shading, the CPU rasterizer on all cores against `cg_gpu` (on Mesa's lavapipe where that is
//! the Vulkan driver: the same cores).
//! Prints `name value` lines, the ratios, and the CPU's Phong/Gouraud ratio at 640 × 640
//! (docs/performance.md). For each GPU row also where its time goes: `_gpu_draw_ms`, the frame
//! drawn without reading it back, and `_gpu_first_read_back_ms`, a new frame's first read-back,
//! which makes its target and read-back buffer (docs/gpu.md).
//!
//! ```text
//! VK_ICD_FILENAMES=/usr/share/vulkan/icd.d/lvp_icd.x86_64.json \
//!   cargo run --release -p cg-raster --example raster_vs_gpu -- [REPEATS]
//! ```

use std::path::Path;
use std::time::Instant;

use cg_core::scene::{Scene, Shading};
use cg_raster::{Options, Prepared, SceneLighting};

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

/// One row: `scene` at `size` in `shading`, timed on the CPU and, when there is one, the GPU.
/// Prints both and their ratio; gives the CPU's time.
fn row(
    name: &str,
    scene: &Scene,
    size: (u32, u32),
    shading: Shading,
    repeats: usize,
    gpu: Option<&cg_gpu::Gpu>,
) -> f64 {
    let options = Options { shading: Some(shading), size: Some(size), ..Options::default() };
    let ready = Prepared::new(scene, &options, &SceneLighting).expect("the scene is ready");
    // Each frame drawn into the last one's buffers, as a window redraws.
    let mut last = Some(ready.draw().expect("the CPU draws"));
    let cpu = best(repeats, || {
        let frame = ready.draw_into(last.take().expect("a frame")).expect("the CPU draws");
        last = Some(std::hint::black_box(frame));
    });
    println!("{name}_cpu_ms {:.3}", cpu * 1e3);
    if let Some(gpu) = gpu {
        let options = cg_gpu::Options { shading: Some(shading), size: Some(size) };
        let frame =
            gpu.frame(scene, &options, cg_gpu::READBACK_FORMAT).expect("the GPU makes the frame");
        // Read back into the last frame's image, through the frame's own target and buffer.
        let mut image = gpu.read_back(&frame).expect("the GPU draws");
        let t = best(repeats, || {
            gpu.read_back_into(&frame, &mut image).expect("the GPU draws");
            std::hint::black_box(&mut image);
        });
        println!("{name}_gpu_ms {:.3}", t * 1e3);
        println!("{name}_cpu_over_gpu {:.2}", cpu / t);
        gpu_parts(name, gpu, scene, &options, &frame, repeats);
    }
    cpu
}

/// Where the GPU's time goes: the frame drawn alone (into a target of its own, then a wait for
/// the GPU), and a new frame's first read-back, which makes the frame's target and read-back
/// buffer (on a real GPU, driver allocations; best of three new frames, each made untimed).
fn gpu_parts(
    name: &str,
    gpu: &cg_gpu::Gpu,
    scene: &Scene,
    options: &cg_gpu::Options,
    frame: &cg_gpu::Frame,
    repeats: usize,
) {
    use cg_gpu::wgpu;
    let device = gpu.device();
    let target = gpu.target(frame);
    let view = target.create_view(&wgpu::TextureViewDescriptor::default());
    let draw = best(repeats, || {
        gpu.render_to_view(frame, &view);
        device.poll(wgpu::PollType::wait_indefinitely()).expect("the GPU finishes");
    });
    println!("{name}_gpu_draw_ms {:.3}", draw * 1e3);
    let first = (0..3)
        .map(|_| {
            let new = gpu.frame(scene, options, frame.format).expect("the GPU makes the frame");
            let t = Instant::now();
            std::hint::black_box(gpu.read_back(&new).expect("the GPU draws"));
            t.elapsed().as_secs_f64()
        })
        .fold(f64::INFINITY, f64::min);
    println!("{name}_gpu_first_read_back_ms {:.3}", first * 1e3);
}

fn main() {
    let repeats: usize =
        std::env::args().nth(1).map_or(10, |r| r.parse().expect("REPEATS is a number"));
    let gpu = match cg_gpu::Gpu::new() {
        Ok(gpu) => {
            println!("gpu_adapter {}", gpu.adapter_info());
            Some(gpu)
        }
        Err(e) => {
            println!("gpu_unavailable {e}");
            None
        }
    };
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/scenes/course-sample.toml");
    let course = cg_scene::load(&path).expect("the course scene loads");
    let gouraud =
        row("course_640_gouraud", &course, (640, 640), Shading::Gouraud, repeats * 5, gpu.as_ref());
    let phong =
        row("course_640_phong", &course, (640, 640), Shading::Phong, repeats * 5, gpu.as_ref());
    println!("course_640_cpu_phong_over_gouraud {:.2}", phong / gouraud);
    let sphere = icosphere_scene();
    for (name, shading) in [("gouraud", Shading::Gouraud), ("phong", Shading::Phong)] {
        row(
            &format!("icosphere_1080p_{name}"),
            &sphere,
            (1920, 1080),
            shading,
            repeats,
            gpu.as_ref(),
        );
    }
    // One thread: the course scene's frame rate on a single core (the goal of issue 8).
    let one = Options { threads: Some(1), size: Some((640, 640)), ..Options::default() };
    let ready = Prepared::new(&course, &one, &SceneLighting).expect("the scene is ready");
    let t = best(repeats * 5, || {
        std::hint::black_box(ready.draw().expect("the course scene renders"));
    });
    println!("course_640_1thread_ms {:.3}\ncourse_640_1thread_fps {:.1}", t * 1e3, 1.0 / t);
}
