#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Cleaner or closer: the two-sided Hausdorff distance against N80 (the fewest
sheets holding 80% of the medial triangle area) for the Structural MAT at
several hair angles (--hair-angle), with Q-MAT on the same initial medial
mesh, on organic shared meshes (organic preset, 10,000 samples -> 1,000
spheres by default). Prints a Markdown table and draws the plot
docs/images/cleanliness-tradeoff.png (matplotlib, Debian's python3-matplotlib).

    Benchmarks/cleanliness_tradeoff.py --tool build/vtk/bin/medial-axis \\
        [--meshes ../shared/data/meshes] [--names bunny.obj,igea.ply] [--angles 0,15,30,45,60]
"""
import argparse
import datetime
import os
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import run_suite  # noqa: E402

DEFAULT_NAMES = "bunny.obj,armadillo.off,igea.ply,spot.obj,kitten.obj,dragon.obj"


def commit():
    try:
        return subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                              capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def measure(args, tmp, name, angle):
    """(N80, two-sided Hausdorff %) of one run; angle None: Q-MAT. The hair angle
    reaches the tool through run_suite's extra arguments."""
    out = os.path.join(tmp, "%s.%s" % (name, "qmat" if angle is None else angle))
    run_suite.EXTRA_ARGS = [] if angle is None else ["--hair-angle", str(angle)]
    data = run_suite.run_tool(args.tool, os.path.join(args.meshes, name), out, args.samples, args.target,
                    False, True, args.threads, "qmat" if angle is None else "structural")
    if data["exit_code"] != 0:
        raise SystemExit("%s failed: %s" % (name, data["message"]))
    return data["cleanliness"]["n80"], data["hausdorff"]["two_sided_percent"]


def plot(results, angles, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for name, row in results.items():
        xs = [row[a][0] for a in angles]
        ys = [row[a][1] for a in angles]
        line, = ax.plot(xs, ys, "o-", label=name)
        for a, x, y in zip(angles, xs, ys):
            ax.annotate("%g°" % a, (x, y), textcoords="offset points", xytext=(3, 3), fontsize=7)
        ax.plot([row[None][0]], [row[None][1]], "s", color=line.get_color(), markersize=8,
                markerfacecolor="none")
    ax.set_xscale("log")
    ax.set_xlabel("N80: sheets holding 80% of the medial area (log scale; fewer is cleaner)")
    ax.set_ylabel("two-sided Hausdorff distance, % of the diagonal")
    ax.set_title("Cleaner or closer: hair angle 0°–%g° (circles), Q-MAT (squares)" % angles[-1])
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--tool", default=os.path.join(ROOT, "build", "vtk", "bin", "medial-axis"))
    parser.add_argument("--meshes", default=os.path.join(ROOT, "..", "shared", "data", "meshes"))
    parser.add_argument("--names", default=DEFAULT_NAMES)
    parser.add_argument("--angles", default="0,15,30,45,60")
    parser.add_argument("--samples", type=int, default=10000)
    parser.add_argument("--target", type=int, default=1000)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--plot", default=os.path.join(ROOT, "docs", "images",
                                                       "cleanliness-tradeoff.png"))
    args = parser.parse_args()
    angles = [float(a) for a in args.angles.split(",")]
    if not os.path.isfile(args.tool):
        raise SystemExit("no medial-axis at %s (build first, or pass --tool)" % args.tool)
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.names.split(","):
            results[name] = {a: measure(args, tmp, name, a) for a in angles + [None]}
            print("%s: %s" % (name, ", ".join(
                "%s N80 %d HD %.3f%%" % ("Q-MAT" if a is None else "%g°" % a, *results[name][a])
                for a in angles + [None])), flush=True)
    print("\nRun %s, commit %s, %d samples -> %d spheres, organic preset.\n" % (
        datetime.date.today().isoformat(), commit(), args.samples, args.target))
    print("| hair angle | N80 median | two-sided Hausdorff median |")
    print("|---|---|---|")
    for a in angles + [None]:
        print("| %s | %g | %.3f%% |" % (
            "Q-MAT" if a is None else "%g°" % a,
            statistics.median(r[a][0] for r in results.values()),
            statistics.median(r[a][1] for r in results.values())))
    try:
        plot(results, angles, args.plot)
        print("\nplot: %s" % args.plot)
    except ImportError:
        print("\nno plot: matplotlib is missing (apt-get install python3-matplotlib)")


if __name__ == "__main__":
    main()
