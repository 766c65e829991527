#!/usr/bin/env bash
# The adaptive remeshing benchmark (paper Fig. 14): installs what is missing, builds bench_adaptive,
# runs it (uniform and curvature-adaptive remeshing, gr::remeshSurface and gr::remeshAdaptive as the
# filters run them, CGAL's isotropic remeshing and MeshLab's quadric edge collapse at the same
# vertex counts, in one run), prints a markdown table, and writes the
# error-versus-vertex-count plot docs/adaptive_error.png from the same JSON.
#   bash scripts/bench_adaptive.sh                               # everything (~1.5 min on 2 cores)
#   bash scripts/bench_adaptive.sh --benchmark_filter='/bunny00/'  # extra arguments go to the binary
# Output: $BUILD_DIR/bench_adaptive.json (the run), the table on stdout, docs/adaptive_error.png
# (PLOT=path to write it elsewhere, PLOT= to skip it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build}
plot=${PLOT-$root/docs/adaptive_error.png}
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh" --target bench_adaptive
json="$build/bench_adaptive.json"
# Repetitions of the families interleaved at random: on this noisy VM the time ratios between
# methods are then taken over the same stretch of time.
"$build/bench/bench_adaptive" --benchmark_out="$json" --benchmark_out_format=json \
  --benchmark_enable_random_interleaving=true "$@"
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

def med(rows, key):
    vals = [r[key] for r in rows if key in r]
    return statistics.median(vals) if vals else None

def ms(rows, family):  # per run, median of the repetitions: CPU time, MeshLab: wall time (manual)
    unit = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[rows[0].get("time_unit", "ns")]
    return med(rows, "real_time" if family == "MeshLabQECD" else "cpu_time") * unit

def t(x):
    return "" if x is None else (f"{x / 1000:.3g} s" if x >= 1000 else f"{x:.3g} ms")

labels = {"Uniform": "uniform (ours)", "Adaptive": "**adaptive (ours)**",
          "AdaptiveDefaults": "adaptive, filter defaults", "UniformFilter": "uniform, filter defaults",
          "Cgal": "CGAL isotropic",
          "MeshLabQECD": "MeshLab QECD"}
# Legend and header: the counters bench/bench_adaptive.cpp sets. metric_ms is gr::remeshAdaptive's wall
# time minus the remesh's stages, i.e. building the adaptive metric (total curvature, speed, P = 1/F).
print(f"Run: {ctx.get('date', '?')} on {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs, "
      f"load average {ctx.get('load_avg', '?')}. Time per run, median of 3 repetitions: the process's CPU time "
      "for ours (the whole gr::remeshSurface or gr::remeshAdaptive call, all threads) and CGAL; wall time of the "
      "whole `xvfb-run -a meshlabserver ...` command for MeshLab (process start, plugin loading and OFF I/O "
      "included). Stages of ours, each one's wall time: metric = building the adaptive metric (total curvature "
      "over a ball, Attractive speed, P = 1/F: the call's wall time minus the remesh's stages), sampling, "
      "triangulation (geodesic Delaunay with its repair and flips); the preparation (orientation, metric transfer) and the "
      "engine's construction are in the time only. Adaptive (ours): curvature radius 2 mean edge lengths, target "
      "calibrated untimed to at most the uniform result's vertex count; filter defaults: the adaptive filter's "
      "(curvature radius half the target spacing, strength 4) and the uniform filter's (relaxation included), at the "
      "uniform target, not calibrated. Errors: two-sided Hausdorff and RMS "
      "distance to the input in % of its bounding-box diagonal. vs uniform: this method's error / the uniform "
      "result's (below 1: lower).")
print()
print("| mesh | target | method | vertices | time | metric | sampling | triangulation | Hausdorff % "
      "| RMS % | H vs uniform | RMS vs uniform | min angle | % < 30° |")
print("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
# Interleaved repetitions come in random order: print by mesh, count, then method.
family_order = ["Uniform", "Adaptive", "AdaptiveDefaults", "UniformFilter", "Cgal", "MeshLabQECD"]
mesh_order = ["fandisk", "bunny00"]
def row_key(key):
    family, mesh, target = key
    return (mesh_order.index(mesh) if mesh in mesh_order else len(mesh_order), mesh,
            int("".join(ch for ch in target if ch.isdigit()) or 0),
            family_order.index(family) if family in family_order else len(family_order))
for (family, mesh, target), rows in sorted(runs.items(), key=lambda kv: row_key(kv[0])):
    if mesh not in mesh_order:
        continue  # the CAD cases: the table after this one
    r = rows[0]
    err = next((x.get("error_message", "error") for x in rows if x.get("error_occurred")), None)
    if err:
        print(f"| {mesh} | {target} | {labels.get(family, family)} | error: {err} | | | | | | | | | | |")
        continue
    u = runs.get(("Uniform", mesh, target), [{}])[0]
    ours = family in ("Uniform", "Adaptive", "AdaptiveDefaults", "UniformFilter")
    metric = t(med(rows, "metric_ms")) if family.startswith("Adaptive") else ""
    hu = f"{r['hausdorff2_pct'] / u['hausdorff2_pct']:.2f}" if "hausdorff2_pct" in u else ""
    ru = f"{r['rms2_pct'] / u['rms2_pct']:.2f}" if "rms2_pct" in u else ""
    print(f"| {mesh} | {target} | {labels.get(family, family)} | {int(r['vertices']):,} | {t(ms(rows, family))} "
          f"| {metric} | {t(med(rows, 'sampling_ms')) if ours else ''} | {t(med(rows, 'delaunay_ms')) if ours else ''} "
          f"| {r['hausdorff2_pct']:.3f} | {r['rms2_pct']:.4f} | {hu} | {ru} "
          f"| {r['angle_min']:.1f}° | {r['lt30_pct']:.1f} |")
print()
for mesh, target in sorted({(m, tg) for (_, m, tg) in runs}, key=lambda mt: row_key(("Uniform",) + mt)):
    u = runs.get(("Uniform", mesh, target))
    if mesh not in mesh_order:
        continue
    for fam, what in (("Adaptive", "radius 2 edges"), ("AdaptiveDefaults", "the filter's defaults")):
        a = runs.get((fam, mesh, target))
        if a and u and not any(x.get("error_occurred") for x in a + u):
            print(f"- adaptive ({what}) / uniform time, {mesh} {target}: {ms(a, fam) / ms(u, 'Uniform'):.2f}×")
# Adaptive defaults against the uniform filter, every case both ran (issue 20's acceptance).
print()
print("| mesh | target | vertices uniform / adaptive | Hausdorff % uniform / adaptive | change | RMS % uniform / adaptive "
      "| change | min angle adaptive |")
print("|---|---|---:|---:|---:|---:|---:|---:|")
changes = []
for (family, mesh, target), a in sorted(runs.items(), key=lambda kv: (kv[0][1], kv[0][2])):
    u = runs.get(("UniformFilter", mesh, target))
    if family != "AdaptiveDefaults" or not u or any(x.get("error_occurred") for x in a + u):
        continue
    a, u = a[0], u[0]
    dh, dr = a["hausdorff2_pct"] / u["hausdorff2_pct"] - 1, a["rms2_pct"] / u["rms2_pct"] - 1
    changes.append(dr)
    print(f"| {mesh} | {target} | {int(u['vertices']):,} / {int(a['vertices']):,} "
          f"| {u['hausdorff2_pct']:.3f} / {a['hausdorff2_pct']:.3f} | {100 * dh:+.0f}% "
          f"| {u['rms2_pct']:.4f} / {a['rms2_pct']:.4f} | {100 * dr:+.0f}% | {a['angle_min']:.1f}° |")
if changes:
    print(f"\nRMS change, mean over the {len(changes)} cases above: {100 * statistics.mean(changes):+.0f}%")
PY
if [ -n "$plot" ]; then
  # matplotlib comes from Debian (python3-matplotlib, scripts/setup.sh): use the system python when
  # the python3 on the PATH (e.g. a pyenv shim) does not have it.
  py=python3
  "$py" -c 'import matplotlib' 2>/dev/null || py=/usr/bin/python3
  "$py" "$root/scripts/plot_adaptive_error.py" "$json" "$plot"
fi
