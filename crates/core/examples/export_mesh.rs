//! Writes the kit's icosphere as `.npy` files for `scripts/compare-normals.py`, or times the
//! kit's area-weighted vertex normals on it.
//!
//! ```text
//! cargo run --release -p cg-core --example export_mesh -- export 7 DIR   # DIR/ico7-{v,f}.npy
//! cargo run --release -p cg-core --example export_mesh -- time 7 REPEATS # one line per measure
//! cargo run --release -p cg-core --example export_mesh -- time-plan 7 REPEATS # the plan only
//! cargo run --release -p cg-core --example export_mesh -- profile-plan 7 N # N frames, for perf
//! ```
//!
//! `time` prints `name value` lines: the best and median nanoseconds of
//! [`vertex_normals`]`(mesh, Weighting::Area)`, of the sequential reference kept for tests, and
//! of a STREAM-like copy of 64 MiB on one thread and on all cores (bytes per second), the
//! memory-bandwidth yardstick; then the fast path on one thread, the fast path with the kernel of
//! a CPU without FMA, a naive f32 loop on one thread and on all cores with their largest angle
//! from the kit's normals, and the additions alone (three random 16-byte read-modify-writes per
//! face, no arithmetic, on all cores), the least any loop that adds face normals to vertices
//! does, and the plan a user would write without care for the same job (a vertex-to-face table
//! made once; each frame f32 face normals, then each vertex's sum and normalisation, on all
//! cores) with its largest angle. Then the [`NormalsPlan`] for meshes whose positions move: the
//! time to make the plan (best of a few), and its per-frame call (the plan made once, outside the
//! timing; best and median, on all cores and on one thread), with how many face records a frame
//! computes per face and whether the plan renumbers the vertices.

use std::io::Write;
use std::time::Instant;

use cg_core::glam::{Vec3, Vec4};
use cg_core::mesh::Mesh;
use cg_core::normals::{
    NormalsPlan, VertexNormals, Weighting, area_vertex_normals_without_fma, vertex_normals,
    vertex_normals_reference,
};
use cg_core::shapes::icosphere;

fn npy_header(descr: &str, shape: &[usize]) -> Vec<u8> {
    let shape = match shape {
        [n] => format!("({n},)"),
        _ => format!("({})", shape.iter().map(|s| s.to_string()).collect::<Vec<_>>().join(", ")),
    };
    let mut dict = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}");
    // Magic (6) + version (2) + length (2) + dict + newline, padded to a multiple of 64.
    while (10 + dict.len() + 1) % 64 != 0 {
        dict.push(' ');
    }
    dict.push('\n');
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend_from_slice(&(dict.len() as u16).to_le_bytes());
    out.extend_from_slice(dict.as_bytes());
    out
}

fn write_npy(path: &std::path::Path, descr: &str, shape: &[usize], data: &[u8]) {
    let mut file = std::fs::File::create(path).expect("the output file can be created");
    file.write_all(&npy_header(descr, shape)).expect("write");
    file.write_all(data).expect("write");
}

/// Best and median of `repeats` timings of `f`, in nanoseconds.
fn time(repeats: usize, mut f: impl FnMut()) -> (f64, f64) {
    let mut ns: Vec<f64> = (0..repeats.max(1))
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_nanos() as f64
        })
        .collect();
    ns.sort_by(f64::total_cmp);
    (ns[0], ns[ns.len() / 2])
}

/// Area-weighted vertex normals as a first attempt computes them: f32, one loop, no care.
fn naive_f32(mesh: &Mesh) -> Vec<Vec3> {
    let mut sums = vec![Vec3::ZERO; mesh.positions.len()];
    for &[a, b, c] in &mesh.faces {
        let p = |i: u32| mesh.positions[i as usize];
        let n = (p(b) - p(a)).cross(p(c) - p(a));
        for v in [a, b, c] {
            sums[v as usize] += n;
        }
    }
    sums.into_iter().map(Vec3::normalize_or_zero).collect()
}

/// The naive loop on every core: each task adds its share of the faces to its own sums (f32,
/// 16 bytes per vertex, allocated per call as a user's loop would), then the sums are merged and
/// normalised in parallel. No care for degenerate, cancelling or non-finite faces.
fn naive_f32_all_cores(mesh: &Mesh) -> Vec<Vec3> {
    use rayon::prelude::*;
    let n = mesh.positions.len();
    let share = mesh.faces.len().div_ceil(rayon::current_num_threads()).max(1);
    let sums: Vec<Vec<Vec4>> = mesh
        .faces
        .par_chunks(share)
        .map(|faces| {
            let mut sums = vec![Vec4::ZERO; n];
            for &[a, b, c] in faces {
                let p = |i: u32| mesh.positions[i as usize];
                let normal = (p(b) - p(a)).cross(p(c) - p(a)).extend(0.0);
                for v in [a, b, c] {
                    sums[v as usize] += normal;
                }
            }
            sums
        })
        .collect();
    (0..n)
        .into_par_iter()
        .map(|v| sums.iter().map(|s| s[v]).sum::<Vec4>().truncate().normalize_or_zero())
        .collect()
}

/// The additions alone, on every core: each task adds a constant to the sums (its own, zeroed
/// beforehand) of the three corners of each of its faces. No loop that adds face normals to
/// vertices does less.
fn additions_all_cores(faces: &[[u32; 3]], sums: &mut [Vec<Vec4>]) {
    use rayon::prelude::*;
    let share = faces.len().div_ceil(sums.len()).max(1);
    faces.par_chunks(share).zip(sums.par_iter_mut()).for_each(|(faces, sums)| {
        for &[a, b, c] in faces {
            for v in [a, b, c] {
                sums[v as usize] += Vec4::ONE;
            }
        }
    });
}

/// A vertex-to-face table made once (faces of each vertex, ascending), for [`table_f32_all_cores`].
fn vertex_face_table(mesh: &Mesh) -> (Vec<u32>, Vec<u32>) {
    let mut start = vec![0u32; mesh.positions.len() + 1];
    for &v in mesh.faces.iter().flatten() {
        start[v as usize + 1] += 1;
    }
    for v in 0..mesh.positions.len() {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut faces = vec![0u32; 3 * mesh.faces.len()];
    for (f, face) in mesh.faces.iter().enumerate() {
        for &v in face {
            faces[fill[v as usize] as usize] = f as u32;
            fill[v as usize] += 1;
        }
    }
    (start, faces)
}

/// The naive loop with a vertex-to-face table made once, as a user would write a plan without
/// care: on every core, each face's f32 normal into a buffer (16 bytes per face), then each
/// vertex sums its faces' and normalises. No exactness, no degenerate or cancelling faces.
fn table_f32_all_cores(
    mesh: &Mesh,
    (start, table): &(Vec<u32>, Vec<u32>),
    face_normals: &mut [Vec4],
    out: &mut [Vec3],
) {
    use rayon::prelude::*;
    const TASK: usize = 1 << 14;
    face_normals.par_chunks_mut(TASK).zip(mesh.faces.par_chunks(TASK)).for_each(|(n, faces)| {
        for (n, &[a, b, c]) in n.iter_mut().zip(faces) {
            let p = |i: u32| mesh.positions[i as usize];
            *n = (p(b) - p(a)).cross(p(c) - p(a)).extend(0.0);
        }
    });
    out.par_chunks_mut(TASK).enumerate().for_each(|(task, out)| {
        for (i, normal) in out.iter_mut().enumerate() {
            let v = task * TASK + i;
            let faces = &table[start[v] as usize..start[v + 1] as usize];
            let sum: Vec4 = faces.iter().map(|&f| face_normals[f as usize]).sum();
            *normal = sum.truncate().normalize_or_zero();
        }
    });
}

/// The largest angle (radians, f64, as atan2(|a×b|, a·b): accurate for tiny angles, unlike the
/// arc cosine of an f32 dot product) between corresponding normals.
fn largest_angle(a: &[Vec3], b: &[Vec3]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(a, b)| {
            let (a, b) = (a.as_dvec3(), b.as_dvec3());
            a.cross(b).length().atan2(a.dot(b))
        })
        .fold(0.0f64, f64::max)
}

/// The plan for moving positions: made once (timed apart), then its per-frame call.
fn time_plan(mesh: &Mesh, reference: &VertexNormals, repeats: usize) {
    let (build, _) = time(repeats.div_ceil(4).max(3), || {
        std::hint::black_box(NormalsPlan::for_mesh(std::hint::black_box(mesh)).expect("valid"));
    });
    println!("plan_build_ns_best {build:.0}");
    let mut plan = NormalsPlan::for_mesh(mesh).expect("the icosphere's indices are in range");
    let mut out = VertexNormals::default();
    plan.area_normals_into(&mesh.positions, &mut out).expect("one position per vertex");
    assert_eq!(&out, reference, "the plan gives the reference's bits");
    let (best, median) = time(repeats, || {
        plan.area_normals_into(std::hint::black_box(&mesh.positions), &mut out).expect("valid");
        std::hint::black_box(&mut out);
    });
    println!("plan_ns_best {best:.0}\nplan_ns_median {median:.0}");
    let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a pool");
    let (best, _) = time(repeats, || {
        one.install(|| plan.area_normals_into(&mesh.positions, &mut out).expect("valid"));
    });
    println!("plan_one_thread_ns_best {best:.0}");
    let (records_per_face, renumbered) = plan.layout();
    println!(
        "plan_records_per_face {records_per_face:.3}\nplan_renumbered {}",
        u8::from(renumbered)
    );
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let usage = "usage: export_mesh export LEVEL DIR | time LEVEL REPEATS | time-plan LEVEL REPEATS \
                 | profile LEVEL N | profile-plan LEVEL N";
    let (Some(what), Some(level)) = (args.first(), args.get(1)) else {
        eprintln!("{usage}");
        std::process::exit(2);
    };
    let level: u32 = level.parse().expect("LEVEL is a number 0..=8");
    let mesh = icosphere(1.0, level).expect("the icosphere level is allowed (0..=8)");
    match what.as_str() {
        "export" => {
            let dir = std::path::PathBuf::from(args.get(2).expect(usage));
            std::fs::create_dir_all(&dir).expect("the directory can be created");
            let v: Vec<u8> = mesh
                .positions
                .iter()
                .flat_map(|p| p.to_array())
                .flat_map(f32::to_le_bytes)
                .collect();
            let f: Vec<u8> = mesh.faces.iter().flatten().flat_map(|i| i.to_le_bytes()).collect();
            write_npy(
                &dir.join(format!("ico{level}-v.npy")),
                "<f4",
                &[mesh.positions.len(), 3],
                &v,
            );
            write_npy(&dir.join(format!("ico{level}-f.npy")), "<u4", &[mesh.faces.len(), 3], &f);
            println!("faces {}\nvertices {}", mesh.faces.len(), mesh.positions.len());
        }
        "time" => {
            let repeats: usize =
                args.get(2).map_or(20, |r| r.parse().expect("REPEATS is a number"));
            let fast = vertex_normals(&mesh, Weighting::Area);
            let reference = vertex_normals_reference(&mesh, Weighting::Area);
            assert_eq!(fast, reference, "the fast path gives the reference's bits");
            let (best, median) = time(repeats, || {
                std::hint::black_box(vertex_normals(std::hint::black_box(&mesh), Weighting::Area));
            });
            println!("faces {}\nvertices {}", mesh.faces.len(), mesh.positions.len());
            println!("kit_ns_best {best:.0}\nkit_ns_median {median:.0}");
            let (best, median) = time(repeats.div_ceil(4), || {
                std::hint::black_box(vertex_normals_reference(
                    std::hint::black_box(&mesh),
                    Weighting::Area,
                ));
            });
            println!("reference_ns_best {best:.0}\nreference_ns_median {median:.0}");
            // The same fast path on one thread, and with the kernel of a CPU without FMA.
            let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a pool");
            let (best, _) = time(repeats, || {
                one.install(|| {
                    std::hint::black_box(vertex_normals(&mesh, Weighting::Area));
                });
            });
            println!("kit_one_thread_ns_best {best:.0}");
            let (best, _) = time(repeats, || {
                std::hint::black_box(area_vertex_normals_without_fma(std::hint::black_box(&mesh)));
            });
            println!("kit_without_fma_ns_best {best:.0}");
            // What a first attempt looks like: f32 throughout, no degenerate or cancelling faces
            // handled, one thread. Its largest angle from the kit's normals shows what it costs.
            let worst = largest_angle(&naive_f32(&mesh), &fast.normals);
            let (best, _) = time(repeats, || {
                std::hint::black_box(naive_f32(std::hint::black_box(&mesh)));
            });
            println!("naive_f32_ns_best {best:.0}\nnaive_f32_max_angle_rad {worst:e}");
            let worst = largest_angle(&naive_f32_all_cores(&mesh), &fast.normals);
            let (best, _) = time(repeats, || {
                std::hint::black_box(naive_f32_all_cores(std::hint::black_box(&mesh)));
            });
            println!(
                "naive_f32_all_cores_ns_best {best:.0}\nnaive_f32_all_cores_max_angle_rad {worst:e}"
            );
            let mut sums =
                vec![vec![Vec4::ZERO; mesh.positions.len()]; rayon::current_num_threads()];
            let best = (0..repeats.max(1))
                .map(|_| {
                    for s in &mut sums {
                        s.fill(Vec4::ZERO);
                    }
                    let t = Instant::now();
                    additions_all_cores(&mesh.faces, &mut sums);
                    std::hint::black_box(&mut sums);
                    t.elapsed().as_nanos() as f64
                })
                .fold(f64::INFINITY, f64::min);
            println!("additions_all_cores_ns_best {best:.0}");
            let table = vertex_face_table(&mesh);
            let mut face_normals = vec![Vec4::ZERO; mesh.faces.len()];
            let mut table_out = vec![Vec3::ZERO; mesh.positions.len()];
            table_f32_all_cores(&mesh, &table, &mut face_normals, &mut table_out);
            let worst = largest_angle(&table_out, &fast.normals);
            let (best, _) = time(repeats, || {
                table_f32_all_cores(
                    std::hint::black_box(&mesh),
                    &table,
                    &mut face_normals,
                    &mut table_out,
                );
                std::hint::black_box(&mut table_out);
            });
            println!(
                "table_f32_all_cores_ns_best {best:.0}\ntable_f32_all_cores_max_angle_rad {worst:e}"
            );
            // STREAM-like copy: 64 MiB read and 64 MiB written, far beyond the caches.
            let src = vec![1.0f64; 8 << 20];
            let mut dst = vec![0.0f64; 8 << 20];
            let (best, _) = time(repeats.max(5), || {
                dst.copy_from_slice(std::hint::black_box(&src));
                std::hint::black_box(&mut dst);
            });
            let bytes = 2.0 * (src.len() * 8) as f64;
            println!("copy_bytes_per_s {:.0}", bytes / (best * 1e-9));
            // The same copy split over every core (what the kit's threads can draw on together).
            let (best, _) = time(repeats.max(5), || {
                use rayon::prelude::*;
                let share = src.len().div_ceil(rayon::current_num_threads());
                dst.par_chunks_mut(share)
                    .zip(src.par_chunks(share))
                    .for_each(|(d, s)| d.copy_from_slice(std::hint::black_box(s)));
                std::hint::black_box(&mut dst);
            });
            println!("copy_all_cores_bytes_per_s {:.0}", bytes / (best * 1e-9));
            time_plan(&mesh, &reference, repeats);
        }
        "profile" => {
            // Only the fast path, for a profiler.
            for _ in 0..args.get(2).map_or(50, |r| r.parse().expect("REPEATS is a number")) {
                std::hint::black_box(vertex_normals(std::hint::black_box(&mesh), Weighting::Area));
            }
        }
        "time-plan" => {
            // Only the plan's per-frame call (best of REPEATS, all cores and one thread).
            let repeats = args.get(2).map_or(50, |r| r.parse().expect("REPEATS is a number"));
            let mut plan = NormalsPlan::for_mesh(&mesh).expect("valid");
            let mut out = VertexNormals::default();
            let (best, _) = time(repeats, || {
                plan.area_normals_into(std::hint::black_box(&mesh.positions), &mut out)
                    .expect("valid");
            });
            let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().expect("a pool");
            let (one_best, _) = time(repeats, || {
                one.install(|| plan.area_normals_into(&mesh.positions, &mut out).expect("valid"));
            });
            println!("plan_ns_best {best:.0}\nplan_one_thread_ns_best {one_best:.0}");
        }
        "profile-plan" => {
            // Only the plan's per-frame call, for a profiler.
            let mut plan = NormalsPlan::for_mesh(&mesh).expect("valid");
            let mut out = VertexNormals::default();
            for _ in 0..args.get(2).map_or(50, |r| r.parse().expect("REPEATS is a number")) {
                plan.area_normals_into(std::hint::black_box(&mesh.positions), &mut out)
                    .expect("valid");
            }
        }
        _ => {
            eprintln!("{usage}");
            std::process::exit(2);
        }
    }
}
