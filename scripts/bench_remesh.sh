#!/usr/bin/env bash
# The remeshing benchmark: installs what is missing, builds bench_remesh, runs it (ours, i.e.
# gr::remeshSurface as the uniform filter runs it, and CGAL's isotropic remeshing in one process,
# MeshLab's isotropic explicit remeshing through the system meshlabserver; same meshes, same vertex
# counts), then prints a markdown table of times, ratios and triangle quality.
#   bash scripts/bench_remesh.sh                               # everything (~9 min on 2 cores)
#   bash scripts/bench_remesh.sh --benchmark_filter=-sub3      # extra arguments go to the binary
# Output: $BUILD_DIR/bench_remesh.json (the run) and the table on stdout.
# Run it on an otherwise idle machine: the table compares times taken in this one run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh" --target bench_remesh
json="$build/bench_remesh.json"
"$build/bench/bench_remesh" --benchmark_out="$json" --benchmark_out_format=json "$@"
echo
python3 - "$json" <<'PY'
import json, statistics, sys
from collections import OrderedDict

data = json.load(open(sys.argv[1]))
ctx = data.get("context", {})
runs = OrderedDict()  # (family, mesh, target) -> iteration rows (one per repetition)
for b in data.get("benchmarks", []):
    if b.get("run_type", "iteration") != "iteration":
        continue
    family, mesh, target = b.get("run_name", b["name"]).split("/")[:3]
    runs.setdefault((family, mesh, target), []).append(b)

def med(rows, key, scale=1.0):
    vals = [r[key] * scale for r in rows if key in r]
    return statistics.median(vals) if vals else None

def ms(rows):  # CPU time per run (MeshLab: wall time minus start-up), median of the repetitions
    unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[rows[0].get("time_unit", "ns")]
    manual = rows[0].get("run_name", rows[0]["name"]).startswith("MeshLab")
    return med(rows, "real_time" if manual else "cpu_time", unit)

def t(x):
    return "—" if x is None else (f"{x / 1000:.3g} s" if x >= 1000 else f"{x:.3g} ms")

print(f"Run: {ctx.get('date', '?')} on {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs, "
      f"load average {ctx.get('load_avg', '?')}; time per run, median of the repetitions: the process's CPU "
      "time for ours and CGAL; ratio = CGAL's or MeshLab's time / our time (> 1: ours is faster); ours: "
      "gr::remeshSurface, what the uniform filter runs (its log's measures off), time = CPU time of the whole call "
      "(all threads: the engine's construction uses a helper thread); engine (FastMarcher construction), "
      "sampling, triangulation (geodesic Delaunay with its repair and flips), relaxation: each stage's wall "
      "time (RemeshStageTimes; the preparation, orientation included, is in the time only); CGAL: "
      "isotropic_remeshing, 3 iterations, on a copy of the input (copy untimed), edge length L calibrated untimed "
      "to our vertex count; MeshLab isotropic: MeshLab's "
      "Remeshing: Isotropic Explicit Remeshing through meshlabserver (bench/meshlab_isotropic_remeshing.mlx), "
      "wall time minus the start-up time (the same command without the script); quality: std of all angles, smallest angle, "
      "% of triangles with an angle under 30°, Hausdorff distance output → input (one-sided) and both ways "
      "(two-sided), and the RMS distance both ways, in % of the input's bounding-box diagonal; "
      "ours: the filter's defaults (5 rounds of relaxation); ours, no relaxation: the paper's triangulation "
      "alone (Relaxation = 0); ours + sub-vertex: FpsParams::subVertexPlacement (the filter's SubVertexPlacement).")
print()
print("| mesh | target | method | vertices | faces | added | time | engine | sampling | triangulation | relaxation | other / ours "
      "| angle std | min angle | % < 30° | Hausdorff % | two-sided % | RMS % |")
print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
shown = set()
for (family, mesh, target), rows in runs.items():
    r = rows[0]
    err = next((x.get("error_message", "error") for x in rows if x.get("error_occurred")), None)
    if mesh not in shown and "vertices_in" in r:
        shown.add(mesh)
        print(f"| {mesh} | input | — | {int(r['vertices_in']):,} | | | | | | | | | {r['in_angle_std']:.1f}° "
              f"| {r['in_angle_min']:.1f}° | {r['in_lt30_pct']:.2f} | | | |")
    if err:
        print(f"| {mesh} | {target} | {family} | error: {err} | | | | | | | | | | | | | | |")
        continue
    ours = runs.get(("Ours", mesh, target))
    ratio = ms(rows) / ms(ours) if family in ("Cgal", "MeshLabIsotropic") and ours and "vertices" in ours[0] else None
    added = f"{int(r['added']):,}" if "added" in r else ""
    ours_family = family.startswith("Ours")
    eng = t(med(rows, "engine_ms")) if ours_family else ""
    samp = t(med(rows, "sampling_ms")) if ours_family else ""
    tri = t(med(rows, "delaunay_ms")) if ours_family else ""
    rel = t(med(rows, "relax_ms")) if ours_family else ""
    label = {"Ours": "**ours**", "OursNoRelax": "ours, no relaxation",
             "OursSubVertex": "ours + sub-vertex"}.get(family)
    if label is None:
        label = (f"MeshLab isotropic (L = {r['edge_length']:.4g})" if family == "MeshLabIsotropic"
                 else f"CGAL (L = {r['edge_length']:.4g})")
    print(f"| {mesh} | {target} | {label} | {int(r['vertices']):,} | {int(r['faces']):,} | {added} "
          f"| {t(ms(rows))} | {eng} | {samp} | {tri} | {rel} | {'' if ratio is None else f'{ratio:.2f}×'} "
          f"| {r['angle_std']:.1f}° | {r['angle_min']:.1f}° | {r['lt30_pct']:.2f} | {r['hausdorff_pct']:.3f} "
          f"| {r['hausdorff2_pct']:.3f} | {r['rms2_pct']:.4f} |")
PY
