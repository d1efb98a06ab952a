#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Log-log plot of a scaling series written by medialaxis-benchmark --json.

    medialaxis-benchmark --scaling --counts 50000,100000,200000,500000,1000000 \\
        --threads 2 --delaunay --subdivide 3 --json scaling.json bunny.obj
    python3 Benchmarks/scaling_plot.py scaling.json docs/images/scaling.png

Plots the pipeline's total, each stage that works on the samples and the
Delaunay triangulation of the same samples against the number of samples,
and prints a Markdown table with the growth exponent of each (least-squares
slope of log time against log samples). Needs matplotlib (Debian:
python3-matplotlib).
"""
import json
import math
import sys

STAGES = ["sampling", "rvd", "voronoi", "simplify"]


def exponent(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    n = len(lx)
    mx, my = sum(lx) / n, sum(ly) / n
    sxx = sum((x - mx) ** 2 for x in lx)
    return sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / sxx if sxx > 0 else float("nan")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: scaling_plot.py RUNS.json OUT.png")
    runs = sorted(
        (r for r in json.load(open(sys.argv[1])) if r.get("samples")), key=lambda r: r["samples"]
    )
    if len(runs) < 2:
        sys.exit("need at least two runs with samples")
    samples = [r["samples"] for r in runs]
    series = {"total": [r["total_seconds"] for r in runs]}
    for name in STAGES:
        series[name] = [
            sum(s["seconds"] for s in r["stages"] if s["name"] == name) for r in runs
        ]
    if all("delaunay_seconds" in r for r in runs):
        series["Delaunay alone"] = [r["delaunay_seconds"] for r in runs]

    header = "| samples | " + " | ".join(series) + " | peak |"
    print(header)
    print("|" + "---|" * (len(series) + 2))
    for i, r in enumerate(runs):
        cells = ["%.2f s" % series[k][i] for k in series]
        print("| %s | %s | %.0f MB |" % (f"{samples[i]:,}", " | ".join(cells), r["peak_mb"]))
    print(
        "| exponent | "
        + " | ".join("%.2f" % exponent(samples, series[k]) for k in series)
        + " | %.2f |" % exponent(samples, [r["peak_mb"] for r in runs])
    )

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name, ys in series.items():
        style = "k-o" if name == "total" else ("k--" if name.startswith("Delaunay") else "-o")
        ax.loglog(samples, ys, style, label="%s (exponent %.2f)" % (name, exponent(samples, ys)),
                  markersize=4)
    ax.set_xlabel("surface samples (spheres: a tenth)")
    ax.set_ylabel("seconds (two threads)")
    ax.set_title("%s, %s triangles" % (runs[0]["mesh"], f"{runs[0]['triangles']:,}"))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=110)


if __name__ == "__main__":
    main()
