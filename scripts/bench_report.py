#!/usr/bin/env python3
"""Turns the JSON of one bench_fast_marching run into markdown tables of times and ratios.

    python3 scripts/bench_report.py build/bench_fast_marching.json [--real-time]

Benchmarks are named <Family>/<mesh>[/...]. Every ratio is competitor time / our time, taken from
the same JSON (same process, same machine state): > 1 means ours is faster. The reference is
Ours_FastMarcher (reused engine) for the single-source families and FpsStep_Ours_FullRecompute for
the farthest-point-sampling step. Times are the process's CPU time (all threads: the FastMarcher
constructor in Ours_fastMarching_oneshot runs a helper thread; the rest is single-threaded) unless
--real-time is given; the manual-time benchmarks (FpsStep_*_Incremental) are the wall time of the
step alone. With repetitions, the median of the repetitions, and "spread" = (max - min) / median.
The competitors are gr_oracles' (tests/oracles/geodesic_oracles.h).
"""
import argparse
import json
import statistics
import sys
from collections import OrderedDict

# Family -> (label, reference family for the ratio, what the "reached" counter counts).
# Unknown families are shown with their name, against Ours_FastMarcher.
FAMILIES = OrderedDict([
    ("Ours_FastMarcher", ("**Ours**: FastMarcher, reused (reset + propagate)", "Ours_FastMarcher", "field")),
    ("Ours_fastMarching_oneshot", ("Ours: fastMarching() one-shot (engine built per call)", "Ours_FastMarcher",
                                   "field")),
    ("Ours_geodesicDistance", ("Ours: geodesicDistance() (the filter's call: test, then exact propagation or "
                               "refinement + fronts where needed)", "Ours_FastMarcher", "field")),
    ("Ours_geodesicDistance_fronts", ("Ours: geodesicDistance() without exact propagation (refinement + fronts "
                                      "where needed)", "Ours_FastMarcher", "field")),
    ("Dijkstra", ("Dijkstra along edges (baseline)", "Ours_FastMarcher", "field")),
    ("Vcg_Geodesic", ("vcglib tri::Geodesic::Compute (MeshLab)", "Ours_FastMarcher", "field")),
    ("Cgal_ShortestPath", ("CGAL Surface_mesh_shortest_path (exact): build + all vertices", "Ours_FastMarcher",
                           "field")),
    ("CgalHeat_BuildQuery", ("CGAL heat, Direct: construction + 1 query", "Ours_FastMarcher", "field")),
    ("CgalHeat_Query", ("CGAL heat, Direct: 1 query (factorised)", "Ours_FastMarcher", "field")),
    ("CgalHeatIdt_BuildQuery", ("CGAL heat, intrinsic Delaunay: construction + 1 query", "Ours_FastMarcher",
                                "field")),
    ("CgalHeatIdt_Query", ("CGAL heat, intrinsic Delaunay: 1 query (factorised)", "Ours_FastMarcher", "field")),
    ("FpsStep_Ours_Incremental", ("**Ours**: addSource + propagate (incremental)", "FpsStep_Ours_Incremental",
                                  "changed")),
    ("FpsStep_Dijkstra_Incremental", ("Dijkstra, incremental U = min(U, U_x)", "FpsStep_Ours_Incremental",
                                      "changed")),
    ("FpsStep_Ours_FullRecompute", ("Ours: reset + propagate from all sources", "FpsStep_Ours_Incremental",
                                    "field")),
    ("FpsStep_Dijkstra_FullRecompute", ("Dijkstra, full recompute from all sources", "FpsStep_Ours_Incremental",
                                        "field")),
    ("FpsStep_Vcg_Geodesic", ("vcglib tri::Geodesic::Compute from all sources", "FpsStep_Ours_Incremental",
                              "field")),
    ("FpsStep_CgalHeat_Query", ("CGAL heat, Direct: 1 query with all sources (factorised)",
                                "FpsStep_Ours_Incremental", "field")),
    ("Fps1000_Ours_Incremental", ("**Ours**: FastMarcher, incremental", "Fps1000_Ours_Incremental", "visits")),
    ("Fps1000_Dijkstra_Incremental", ("Dijkstra, incremental", "Fps1000_Ours_Incremental", "visits")),
    ("Fps1000_ArgmaxScans", ("the 999 argmax scans alone (floor of both)", "Fps1000_Ours_Incremental", "reads")),
])
GROUPS = OrderedDict([
    ("single", "single source (vertex 0), full propagation"),
    ("FpsStep", "one farthest-point-sampling step"),
    ("Fps1000", "a whole farthest-point sampling of 1000 points from vertex 0"),
])
UNIT_TO_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def fmt_time(ms):
    if ms is None:
        return "—"
    if ms >= 1000:
        return f"{ms / 1000:.3g} s"
    if ms >= 1:
        return f"{ms:.3g} ms"
    if ms >= 1e-3:
        return f"{ms * 1e3:.3g} µs"
    return f"{ms * 1e6:.3g} ns"


def fmt_rate(v):
    if v is None:
        return "—"
    if v >= 1e6:
        return f"{v / 1e6:.2f} M/s"
    return f"{v / 1e3:.0f} k/s"


def fmt_ratio(r):
    if r is None:
        return "—"
    if r >= 10:
        return f"{r:.0f}×"
    if r >= 0.1:
        return f"{r:.2f}×"
    return f"{r:.2g}×"


def b_name(b):
    return b.get("run_name", b["name"])


def group_of(family):
    prefix = family.split("_")[0]
    return prefix if prefix in GROUPS else "single"


def load(path, use_real):
    with open(path) as f:
        data = json.load(f)
    # Group every row (repetitions and aggregates) by <Family>/<mesh>.
    grouped = OrderedDict()
    for b in data.get("benchmarks", []):
        parts = b.get("run_name", b["name"]).split("/")
        if len(parts) >= 2:
            grouped.setdefault((parts[0], parts[1]), []).append(b)
    field = "real_time" if use_real else "cpu_time"
    results = OrderedDict()
    for key, bs in grouped.items():
        runs = [b for b in bs if b.get("run_type", "iteration") == "iteration"]
        bad = [b for b in runs if b.get("error_occurred")]
        if bad or not runs:
            results[key] = {"error": bad[0].get("error_message", "error") if bad else "no runs"}
            continue
        # The median of the repetitions (the aggregate if the binary wrote one).
        median = next((b for b in bs if b.get("run_type") == "aggregate" and b.get("aggregate_name") == "median"),
                      None)
        # Manual-time benchmarks time a region of the loop: their real_time is that region, their
        # cpu_time the whole loop (set-up included).
        f = "real_time" if "manual_time" in b_name(runs[0]) else field
        times = [b[f] * UNIT_TO_MS[b.get("time_unit", "ns")] for b in runs]
        ms = statistics.median(times)
        b = median if median else sorted(runs, key=lambda r: r[f])[len(runs) // 2]
        results[key] = {
            "ms": ms,
            "manual": f != field,
            "rate": (b.get("reached", 0) / (ms / 1e3)) if ms > 0 and "reached" in b else None,
            "reached": b.get("reached"),
            "vertices": b.get("vertices"),
            "sources": b.get("sources"),
            "max_dist": b.get("max_dist"),
            "exact": b.get("exact"),
            "windows": b.get("windows"),
            "inserted": b.get("inserted"),
            "refined": b.get("refined"),
            "repetitions": len(runs),
            "iterations": sum(r.get("iterations", 0) for r in runs),
            "spread": (max(times) - min(times)) / ms if ms > 0 and len(times) > 1 else None,
        }
    return data.get("context", {}), results


def note_for(fam, r, ref):
    kind = FAMILIES.get(fam, (None, None, "field"))[2]
    notes = []
    if r.get("iterations") == 1:
        notes.append("1 run")
    elif r.get("repetitions", 1) > 1:
        spread = f", spread {r['spread']:.0%}" if r.get("spread") is not None else ""
        notes.append(f"median of {r['repetitions']}{spread}")
    if r.get("manual"):
        notes.append("step alone (manual time)")
    if r.get("exact"):
        notes.append(f"exact: {int(r['windows']):,} windows")
    elif r.get("refined"):
        over = f" (exact over budget at {int(r['windows']):,} windows)" if r.get("windows") else ""
        notes.append(f"refined: {int(r['inserted']):,} points inserted{over}")
    reached = r.get("reached")
    if reached is not None and kind == "changed":
        notes.append(f"{int(reached):,} vertices changed")
    elif reached is not None and kind == "visits":
        notes.append(f"{int(reached):,} vertex updates in all")
    elif reached is not None and kind == "reads":
        notes.append("rate = vertex reads/s")
    elif reached is not None and r.get("vertices") and reached < r["vertices"]:
        notes.append(f"**only {int(reached):,} of {int(r['vertices']):,} vertices got a finite distance**")
    elif ref and ref.get("max_dist") and r.get("max_dist") is not None and fam != ref.get("family"):
        dev = r["max_dist"] / ref["max_dist"] - 1
        if abs(dev) > 0.25:
            notes.append(f"max distance {dev:+.0%} vs ours: check the field")
    return "; ".join(notes)


def print_summary(res, meshes, single):
    print("### Summary: single-source full propagation, ratio to ours (time / our time)")
    print()
    print("| mesh | vertices | ours | ours vertices/s | " + " | ".join(f"`{f}`" for f in single) + " |")
    print("|---|---:|---:|---:|" + "---:|" * len(single))
    for m in meshes:
        ref = res.get(("Ours_FastMarcher", m))
        if not ref or "ms" not in ref:
            continue
        cells = []
        for f in single:
            r = res.get((f, m))
            if r is None:
                cells.append("—")
            elif "error" in r:
                cells.append("error")
            else:
                c = fmt_ratio(r["ms"] / ref["ms"])
                if r.get("reached") is not None and r.get("vertices") and r["reached"] < r["vertices"]:
                    c += " (field incomplete)"
                cells.append(c)
        print(f"| {m} | {int(ref['vertices']):,} | {fmt_time(ref['ms'])} | {fmt_rate(ref['rate'])} | "
              + " | ".join(cells) + " |")
    print()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("json")
    ap.add_argument("--real-time", action="store_true", help="use wall-clock time instead of CPU time")
    args = ap.parse_args()
    ctx, res = load(args.json, args.real_time)
    if not res:
        sys.exit(f"{args.json}: no benchmark results")

    basis = "wall-clock (real) time" if args.real_time else "the process's CPU time"
    print(f"Run: {ctx.get('date', '?')} on {ctx.get('host_name', '?')}, {ctx.get('num_cpus', '?')} CPUs "
          f"at {ctx.get('mhz_per_cpu', '?')} MHz, load average {ctx.get('load_avg', '?')}; "
          f"times are {basis} per run; ratio = method time / our time (> 1: ours is faster).")
    print()

    meshes = list(OrderedDict.fromkeys(m for _, m in res))
    known = list(FAMILIES)
    families = known + [f for f in OrderedDict.fromkeys(f for f, _ in res) if f not in FAMILIES]

    # Summary: one row per mesh, the single-source ratios.
    single = [f for f in families if group_of(f) == "single" and f != "Ours_FastMarcher"
              and any((f, m) in res for m in meshes)]
    summary_meshes = [m for m in meshes if "ms" in res.get(("Ours_FastMarcher", m), {})]
    if summary_meshes and single:
        print_summary(res, summary_meshes, single)

    for m in meshes:
        fams = [f for f in families if (f, m) in res]
        if not fams:
            continue
        verts = next((res[(f, m)].get("vertices") for f in fams if res[(f, m)].get("vertices")), None)
        groups = [(title, [f for f in fams if group_of(f) == g]) for g, title in GROUPS.items()]
        for title, group in groups:
            if not group:
                continue
            srcs = next((res[(f, m)].get("sources") for f in group if res[(f, m)].get("sources")), None)
            extra = f": field of {int(srcs) - 1} sources + 1 new source" if srcs and "step" in title else ""
            print(f"### {m} ({int(verts):,} vertices) — {title}{extra}" if verts else f"### {m} — {title}")
            print()
            print("| method | benchmark | time per run | vertices/s | ratio to ours | notes |")
            print("|---|---|---:|---:|---:|---|")
            for f in group:
                r = res[(f, m)]
                label, ref_fam, _ = FAMILIES.get(f, (f, "Ours_FastMarcher", "field"))
                if "error" in r:
                    print(f"| {label} | `{f}` | error | | | {r['error']} |")
                    continue
                ref = res.get((ref_fam, m))
                ratio = r["ms"] / ref["ms"] if ref and "ms" in ref and ref["ms"] > 0 else None
                refinfo = dict(ref or {}, family=ref_fam)
                print(f"| {label} | `{f}` | {fmt_time(r['ms'])} | {fmt_rate(r['rate'])} | {fmt_ratio(ratio)} | "
                      f"{note_for(f, r, refinfo)} |")
            print()


if __name__ == "__main__":
    main()
