#!/usr/bin/env python3
"""Approximation error versus vertex count (paper Fig. 14) from one run of bench_adaptive.

    python3 scripts/plot_adaptive_error.py build/bench_adaptive.json docs/adaptive_error.png

Reads the Google Benchmark JSON written by scripts/bench_adaptive.sh; draws, for each mesh (one
column), the two-sided Hausdorff distance (top row) and the RMS distance (bottom row), in % of the
input's bounding-box diagonal, against the output vertex count, one line per method (uniform and
adaptive geodesic remeshing, CGAL's isotropic remeshing, MeshLab's quadric edge collapse), on
log-log axes. Needs matplotlib (python3-matplotlib, installed by scripts/setup.sh).
"""
import json
import sys
from collections import OrderedDict, defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FuncFormatter  # noqa: E402

METHODS = OrderedDict([
    ("Uniform", ("uniform geodesic (ours)", "tab:blue", "o", "-")),
    ("Adaptive", ("adaptive geodesic, curvature (ours)", "tab:red", "s", "-")),
    ("Cgal", ("CGAL isotropic remeshing", "tab:green", "^", "--")),
    ("MeshLabQECD", ("MeshLab quadric edge collapse", "tab:purple", "D", ":")),
])
METRICS = [("hausdorff2_pct", "two-sided Hausdorff (% of diagonal)"), ("rms2_pct", "RMS distance (% of diagonal)")]


def load(path):
    """(family, mesh) -> sorted [(vertices, hausdorff, rms)], one point per case (first repetition)."""
    data = json.load(open(path))
    points = defaultdict(dict)
    meshes = []
    for b in data.get("benchmarks", []):
        if b.get("run_type", "iteration") != "iteration" or b.get("error_occurred"):
            continue
        family, mesh, target = b.get("run_name", b["name"]).split("/")[:3]
        if mesh not in meshes:
            meshes.append(mesh)
        if "vertices" in b and target not in points[(family, mesh)]:
            points[(family, mesh)][target] = (b["vertices"], b["hausdorff2_pct"], b["rms2_pct"])
    return meshes, {k: sorted(v.values()) for k, v in points.items()}, data.get("context", {})


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    meshes, points, ctx = load(argv[1])
    if not meshes:
        sys.exit(f"{argv[1]}: no benchmark results")
    fig, axes = plt.subplots(len(METRICS), len(meshes), figsize=(5.2 * len(meshes), 7.6), squeeze=False)
    for col, mesh in enumerate(meshes):
        for row, (key, ylabel) in enumerate(METRICS):
            ax = axes[row][col]
            for family, (label, color, marker, style) in METHODS.items():
                pts = points.get((family, mesh))
                if not pts:
                    continue
                xs = [p[0] for p in pts]
                ys = [p[1 if key == "hausdorff2_pct" else 2] for p in pts]
                ax.plot(xs, ys, marker=marker, linestyle=style, color=color, label=label)
            ax.set_xscale("log")
            ax.set_yscale("log")
            for axis in (ax.xaxis, ax.yaxis):  # plain numbers; minor ticks labelled at 2, 3, 5 only
                axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
                axis.set_minor_formatter(FuncFormatter(
                    lambda v, _: f"{v:g}" if v > 0 and f"{v:.0e}"[0] in "235" else ""))
            ax.grid(True, which="both", alpha=0.3)
            ax.set_xlabel("output vertices")
            ax.set_ylabel(ylabel)
            if row == 0:
                ax.set_title(mesh)
    axes[0][0].legend(fontsize=8)
    fig.suptitle("Approximation error vs vertex count (bench_adaptive, " + ctx.get("date", "?")[:10] + ")")
    fig.tight_layout()
    fig.savefig(argv[2], dpi=110)
    print(f"wrote {argv[2]}")


if __name__ == "__main__":
    main(sys.argv)
