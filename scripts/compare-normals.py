#!/usr/bin/env python3
"""Area-weighted vertex normals, side by side in one run: the kit's `vertex_normals(mesh,
Weighting::Area)` against trimesh's `Trimesh.vertex_normals` and Open3D's
`TriangleMesh.compute_vertex_normals`, on the kit's icosphere at subdivision 7 (327 680 faces)
and 8 (1 310 720 faces), plus a memory-bandwidth bound from a STREAM-like copy on all cores,
and two yardsticks of what any loop that adds face normals to vertices costs on this machine: a
naive f32 loop on all cores, and the additions alone (no arithmetic). Then the kit's
`NormalsPlan` for positions that move while the faces stay: the time to make the plan once, and
its per-frame call (the plan made outside the timing), against Open3D and the bound.

    python3 -m venv .venv && .venv/bin/pip install numpy scipy trimesh open3d
    # Open3D's wheel also needs libusb-1.0 from the system (Debian: apt install libusb-1.0-0).
    # Without a library its columns stay empty and the results say so; --strict fails instead.
    .venv/bin/python scripts/compare-normals.py [--repeats N]

The meshes come from `cargo run --release -p cg-core --example export_mesh -- export LEVEL DIR`
(.npy files), the kit's times from `... -- time LEVEL N` (ns, best of N; also the kit on one
thread, the kit with the kernel of a CPU without FMA, a naive f32 loop on one thread and on all
cores with its error, the additions alone on all cores, and the plan: made once, per frame on
all cores and on one thread; beside the plan, the plan a user would write without care — a
vertex-to-face table made once, then f32 face normals and a gather on all cores — with its
error). Notes: trimesh weights
its vertex normals by the corner angles, not the areas (its `vertex_normals` is what a user calls);
Open3D reuses triangle normals it already has, so they are cleared before each call. Both are
timed best of N like the kit. Writes nothing; prints a table (docs/performance.md).
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXAMPLE = ["cargo", "run", "--quiet", "--release", "-p", "cg-core", "--example", "export_mesh", "--"]


def kit(*args):
    out = subprocess.run(EXAMPLE + [str(a) for a in args], cwd=ROOT, check=True,
                         capture_output=True, text=True).stdout
    return dict(line.split() for line in out.splitlines())


def best(repeats, setup, call):
    times = []
    for _ in range(repeats):
        state = setup()
        t = time.perf_counter_ns()
        call(state)
        times.append(time.perf_counter_ns() - t)
    return min(times)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--levels", default="7,8")
    parser.add_argument("--strict", action="store_true",
                        help="exit with status 1 when trimesh or Open3D cannot be loaded")
    args = parser.parse_args()
    # A library that cannot be loaded leaves its columns empty ("—"); the reason is printed with
    # the results, not only on stderr, and --strict makes it a failure.
    missing = {}
    try:
        import trimesh
    except ImportError as e:
        missing["trimesh"] = str(e)
        trimesh = None
    try:
        import open3d as o3d
    except ImportError as e:
        missing["Open3D"] = str(e)
        o3d = None
    for name, why in missing.items():
        print(f"{name} not available ({why}); its columns will be empty", file=sys.stderr)
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for level in [int(x) for x in args.levels.split(",")]:
            kit("export", level, tmp)
            v = np.load(os.path.join(tmp, f"ico{level}-v.npy"))
            f = np.load(os.path.join(tmp, f"ico{level}-f.npy"))
            k = kit("time", level, args.repeats)
            row = {"level": level, "faces": len(f), "vertices": len(v),
                   "kit": float(k["kit_ns_best"]), "reference": float(k["reference_ns_best"]),
                   "one_thread": float(k["kit_one_thread_ns_best"]),
                   "without_fma": float(k["kit_without_fma_ns_best"]),
                   "naive": float(k["naive_f32_ns_best"]),
                   "naive_angle": float(k["naive_f32_max_angle_rad"]),
                   "naive_all": float(k["naive_f32_all_cores_ns_best"]),
                   "additions": float(k["additions_all_cores_ns_best"]),
                   "table": float(k["table_f32_all_cores_ns_best"]),
                   "table_angle": float(k["table_f32_all_cores_max_angle_rad"]),
                   "copy_one": float(k["copy_bytes_per_s"]),
                   "copy": float(k["copy_all_cores_bytes_per_s"]),
                   "plan_build": float(k["plan_build_ns_best"]),
                   "plan": float(k["plan_ns_best"]),
                   "plan_median": float(k["plan_ns_median"]),
                   "plan_one": float(k["plan_one_thread_ns_best"]),
                   "plan_records": float(k["plan_records_per_face"]),
                   "plan_renumbered": k["plan_renumbered"] == "1"}
            if trimesh is not None:
                row["trimesh"] = best(
                    max(3, args.repeats // 4),
                    lambda: trimesh.Trimesh(vertices=v, faces=f, process=False),
                    lambda m: m.vertex_normals)
            if o3d is not None:
                mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(v.astype(np.float64)),
                                                 o3d.utility.Vector3iVector(f.astype(np.int32)))

                def clear():
                    mesh.triangle_normals = o3d.utility.Vector3dVector()
                    mesh.vertex_normals = o3d.utility.Vector3dVector()
                    return mesh
                row["open3d"] = best(args.repeats, clear, lambda m: m.compute_vertex_normals())
            # Bandwidth bound: per face its 3 indices (12 B); per vertex its position (12 B) read
            # and its normal (12 B) written; V ≈ F/2, so ≈ 24 B per face, at the copy rate the
            # kit's threads get together (all cores; bytes read + written per second).
            row["bound"] = (12 * row["faces"] + 24 * row["vertices"]) / row["copy"] * 1e9
            rows.append(row)
    print(f"machine: {os.cpu_count()} CPUs; load average {os.getloadavg()}")
    print("| faces | kit ms | plain loop ms | trimesh ms | Open3D ms | bound ms "
          "| plain/kit | trimesh/kit | Open3D/kit | kit/bound |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        ms = lambda key: f"{r[key] / 1e6:.2f}" if key in r else "—"
        ratio = lambda key: f"{r[key] / r['kit']:.2f}" if key in r else "—"
        print(f"| {r['faces']} | {ms('kit')} | {ms('reference')} | {ms('trimesh')} | {ms('open3d')} "
              f"| {ms('bound')} | {ratio('reference')} | {ratio('trimesh')} | {ratio('open3d')} "
              f"| {r['kit'] / r['bound']:.2f} |")
    for r in rows:
        print(f"copy bandwidth ({r['faces']} faces run): {r['copy'] / 1e9:.1f} GB/s on all cores, "
              f"{r['copy_one'] / 1e9:.1f} GB/s on one (read + written)")
    print()
    print("| faces | kit ms (all cores) | kit, one thread | kit without FMA | naive f32 loop, "
          "one thread | naive f32: largest angle from the kit's normals |")
    print("|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['faces']} | {r['kit'] / 1e6:.2f} | {r['one_thread'] / 1e6:.2f} "
              f"| {r['without_fma'] / 1e6:.2f} | {r['naive'] / 1e6:.2f} "
              f"| {r['naive_angle']:.1e} rad |")
    print()
    print("| faces | bound ms | additions alone, all cores | naive f32 loop, all cores | kit "
          "| additions/bound | naive/bound | kit/bound |")
    print("|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['faces']} | {r['bound'] / 1e6:.2f} | {r['additions'] / 1e6:.2f} "
              f"| {r['naive_all'] / 1e6:.2f} | {r['kit'] / 1e6:.2f} "
              f"| {r['additions'] / r['bound']:.2f} | {r['naive_all'] / r['bound']:.2f} "
              f"| {r['kit'] / r['bound']:.2f} |")

    print()
    print("Plan (faces fixed, positions moving): made once, then per frame (best of N)")
    print("| faces | plan made once ms | per frame ms | Open3D ms | bound ms | Open3D/plan "
          "| plan/bound |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        o3d_ratio = f"{r['open3d'] / r['plan']:.2f}" if "open3d" in r else "—"
        o3d_ms = f"{r['open3d'] / 1e6:.2f}" if "open3d" in r else "—"
        print(f"| {r['faces']} | {r['plan_build'] / 1e6:.1f} | {r['plan'] / 1e6:.2f} | {o3d_ms} "
              f"| {r['bound'] / 1e6:.2f} | {o3d_ratio} | {r['plan'] / r['bound']:.2f} |")
    print()
    print("| faces | plan per frame, median ms | plan, one thread | one-shot kit | "
          "records per face | renumbered | table f32 loop ms | table/bound | its largest angle |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['faces']} | {r['plan_median'] / 1e6:.2f} | {r['plan_one'] / 1e6:.2f} "
              f"| {r['kit'] / 1e6:.2f} | {r['plan_records']:.3f} "
              f"| {'yes' if r['plan_renumbered'] else 'no'} | {r['table'] / 1e6:.2f} "
              f"| {r['table'] / r['bound']:.2f} | {r['table_angle']:.1e} rad |")
    for name, why in missing.items():
        print(f"\nNOT COMPARED: {name} could not be loaded ({why}); its columns are empty. See the "
              "set-up at the top of this script.")
    if missing and args.strict:
        sys.exit(1)


if __name__ == "__main__":
    main()
