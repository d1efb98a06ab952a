# SPDX-License-Identifier: GPL-3.0-or-later
"""Curve skeletons against CGAL's mean-curvature-flow skeleton, in one run.

For every organic mesh of ../shared/data/meshes (SOURCES.md): `medial-axis
--curve-skeleton` at the organic preset (timed from the surface: reading,
MAT and skeleton), and CGAL 5.5's extract_mean_curvature_flow_skeleton of the
same prepared surface (default parameters; timed for the extraction alone).
Per skeleton:

- loops: the cycle rank (edges - nodes + components), against the genus;
- centredness: per node with surface points in its correspondence (ours: the
  points whose medial ball is the node's, output 1's NodeId; CGAL's: its
  vertices' correspondence), |distance to the surface - mean distance to
  those points| / diagonal, median and largest over the nodes: 0 for a node
  as far from all of its points as from the nearest;
- nodes outside the surface.

Writes a Markdown table (and JSON) to --out; `--doc FILE` also replaces the
section between the markers in FILE (docs/benchmark-results.md).

    python3 Benchmarks/curve_skeleton_report.py [--meshes DIR] [--build DIR] [--out DIR]
        [--doc docs/benchmark-results.md] [--only NAME ...]
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import time

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
BEGIN, END = "<!-- curve skeletons: begin -->", "<!-- curve skeletons: end -->"


def build_mcf(build):
    """The CGAL program, compiled once next to the build (CGAL is header-only;
    it is no part of the library or its tests)."""
    binary = os.path.join(build, "bin", "medialaxis-mcf-skeleton")
    source = os.path.join(HERE, "McfSkeleton.cxx")
    if not os.path.exists(binary) or os.path.getmtime(binary) < os.path.getmtime(source):
        os.makedirs(os.path.dirname(binary), exist_ok=True)
        subprocess.run(["g++", "-std=c++17", "-O2", "-DNDEBUG", "-frounding-math",
                        "-I/usr/include/eigen3", "-DCGAL_EIGEN3_ENABLED", source, "-o", binary,
                        "-lgmp", "-lmpfr"], check=True)
    return binary


def read_vtp(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def write_off(surface, path):
    points = vtk_to_numpy(surface.GetPoints().GetData())
    polys = vtk_to_numpy(surface.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    with open(path, "w") as f:
        f.write("OFF\n%d %d 0\n" % (len(points), len(polys)))
        f.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in points)
        f.writelines("3 %d %d %d\n" % tuple(t) for t in polys)


def end_reach(surface, nodes, edges, depth, diagonal):
    """Per free end: how far the surface straight ahead of it (along its last
    edge) lies beyond its ball, (ray hit - depth) / the limb's radius (the
    largest depth over the end and the three nodes before it): 0 where the
    end's ball touches the tip, 1 a limb's radius short of it."""
    adjacent = [[] for _ in nodes]
    for a, c in edges:
        adjacent[a].append(c)
        adjacent[c].append(a)
    tree = vtk.vtkOBBTree()
    tree.SetDataSet(surface)
    tree.BuildLocator()
    hits = vtk.vtkPoints()
    reach = []
    for v, near in enumerate(adjacent):
        if len(near) != 1:
            continue
        p = np.asarray(nodes[v])
        step = p - np.asarray(nodes[near[0]])
        if not np.linalg.norm(step) > 0:
            continue
        far = p + step / np.linalg.norm(step) * 2 * diagonal
        tree.IntersectWithLine(p, far, hits, None)
        if hits.GetNumberOfPoints() == 0:
            continue
        gap = min(np.linalg.norm(np.asarray(hits.GetPoint(i)) - p)
                  for i in range(hits.GetNumberOfPoints()))
        limb, previous, current = depth[v], v, v
        for _ in range(3):
            onward = [x for x in adjacent[current] if x != previous]
            if len(adjacent[current]) > 2 or not onward:
                break
            previous, current = current, onward[0]
            limb = max(limb, depth[current])
        if limb > 0:
            reach.append((gap - depth[v]) / limb)
    return reach


def measure(surface, nodes, edges, correspondence, radii=None):
    """Loops, nodes outside, the radius error (|distance to the surface -
    radius| / diagonal, median and largest; radius: the skeleton's own where
    it has one, else the mean distance to the node's corresponding points)
    and the correspondence centredness (the same with that mean distance)."""
    distance = vtk.vtkImplicitPolyDataDistance()
    distance.SetInput(surface)
    b = surface.GetBounds()
    diagonal = ((b[1] - b[0]) ** 2 + (b[3] - b[2]) ** 2 + (b[5] - b[4]) ** 2) ** 0.5
    points = vtk_to_numpy(surface.GetPoints().GetData())
    parent = list(range(len(nodes)))

    def find(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    unique = {tuple(sorted(e)) for e in edges if e[0] != e[1]}
    for a, c in unique:
        parent[find(a)] = find(c)
    components = sum(1 for v in range(len(nodes)) if find(v) == v)
    off, radius_error, outside = [], [], 0
    depth = []
    for v, p in enumerate(nodes):
        d = distance.EvaluateFunction(p)
        depth.append(abs(d))
        outside += d > 0
        mean = None
        if correspondence[v]:
            mean = float(np.linalg.norm(points[correspondence[v]] - np.asarray(p), axis=1).mean())
            off.append(abs(abs(d) - mean) / diagonal)
        own = radii[v] if radii is not None else mean
        if own is not None:
            radius_error.append(abs(abs(d) - own) / diagonal)

    def median(values):
        return statistics.median(values) if values else float("nan")

    def largest(values):
        return max(values) if values else float("nan")
    reach = end_reach(surface, nodes, unique, depth, diagonal)
    return {"loops": len(unique) - len(nodes) + components, "nodes": len(nodes),
            "ends": len(reach), "reach_median": median(reach), "reach_max": largest(reach),
            "reach_short": sum(1 for x in reach if x > 1.0),
            "centred_median": median(off), "centred_max": largest(off),
            "radius_median": median(radius_error), "radius_max": largest(radius_error),
            "outside": outside}


def ours(tool, mesh, out):
    start = time.monotonic()
    result = subprocess.run([tool, "--preset", "organic", "--curve-skeleton", "--quiet",
                             "--threads", "2", "--report", os.path.join(out, "report.json"),
                             mesh, out], capture_output=True, text=True)
    seconds = time.monotonic() - start
    if result.returncode != 0:
        raise RuntimeError(result.stderr.strip())
    surface = read_vtp(os.path.join(out, "segmentation.vtp"))
    skeleton = read_vtp(os.path.join(out, "curve_skeleton.vtp"))
    nodes = [skeleton.GetPoint(i) for i in range(skeleton.GetNumberOfPoints())]
    edges = []
    lines = skeleton.GetLines()
    ids, offsets = (vtk_to_numpy(lines.GetConnectivityArray()),
                    vtk_to_numpy(lines.GetOffsetsArray()))
    for c in range(lines.GetNumberOfCells()):
        chain = ids[offsets[c]:offsets[c + 1]]
        edges += [(int(a), int(b)) for a, b in zip(chain, chain[1:])]
    node_of = vtk_to_numpy(surface.GetPointData().GetArray("NodeId"))
    correspondence = [[] for _ in nodes]
    for p, v in enumerate(node_of):
        if v >= 0:
            correspondence[v].append(p)
    radius = skeleton.GetPointData().GetArray("Radius")
    row = measure(surface, nodes, edges, correspondence,
                  [radius.GetValue(i) for i in range(len(nodes))])
    # From the surface: the MAT's stages and the skeleton, as CGAL's time is
    # its extraction's (the process's wall time, reading and writing files
    # included, is kept too).
    with open(os.path.join(out, "report.json")) as f:
        report = json.load(f)["seconds"]
    row["seconds"] = report["Total"] + report["CurveSkeleton"]
    row["process_seconds"] = seconds
    return surface, row


def mcf(binary, surface, out):
    off = os.path.join(out, "prepared.off")
    write_off(surface, off)
    result_path = os.path.join(out, "mcf.json")
    result = subprocess.run([binary, off, result_path], capture_output=True, text=True)
    if result.returncode != 0:
        return {"failed": result.stderr.strip()}
    with open(result_path) as f:
        data = json.load(f)
    nodes = [tuple(n["position"]) for n in data["nodes"]]
    row = measure(surface, nodes, [tuple(e) for e in data["edges"]],
                  [n["surface"] for n in data["nodes"]])
    row["seconds"] = data["seconds"]
    return row


def organic_meshes(mesh_dir):
    table = []
    with open(os.path.join(mesh_dir, "SOURCES.md"), encoding="utf-8") as f:
        for line in f:
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            if len(cells) >= 7 and cells[1] == "organic" and cells[6].isdigit():
                table.append((cells[0], int(cells[6])))
    return table


def pooled(rows, who):
    """The median over the meshes' median end reach (meshes with ends)."""
    values = [r[who]["reach_median"] for r in rows if r[who]["ends"]]
    return statistics.median(values) if values else float("nan")


def markdown(rows, stamp):
    lines = [BEGIN, "", "### Curve skeletons against CGAL's mean-curvature-flow skeleton", "",
             stamp, "",
             "Ours: `medial-axis --curve-skeleton` at the organic preset, timed from the "
             "prepared surface (the MAT's stages and the skeleton, as its report gives them); "
             "CGAL: "
             "`extract_mean_curvature_flow_skeleton` of the same prepared surface with its "
             "default parameters, timed for the extraction alone. Radius error: per node, "
             "|distance to the surface − radius| / diagonal in %, median (largest), with each "
             "skeleton's radius: ours its inscribed radius, CGAL's (which gives none) the mean "
             "distance to the node's corresponding surface points. Correspondence centredness: "
             "the same with that mean distance for both (ours: the points whose nearest node "
             "ball is the node's): how far a node's share of the surface is from one equidistant "
             "ring around it. Ends short of their tip: free ends whose ball stops more than "
             "the limb's radius (the largest over the end and the three nodes before it) "
             "before the surface straight ahead along the last edge. "
             "`python3 Benchmarks/curve_skeleton_report.py --doc "
             "docs/benchmark-results.md` made this section.", "",
             "| mesh | genus | loops ours / CGAL | nodes ours / CGAL | radius error ours / CGAL "
             "| correspondence centredness ours / CGAL | outside ours / CGAL "
             "| ends short of their tip ours / CGAL | seconds ours / CGAL |",
             "|---|---|---|---|---|---|---|---|---|"]

    def pair(row, key):
        return "%.3f (%.2f)" % (100 * row[key + "_median"], 100 * row[key + "_max"])

    def short(row):
        return "%d of %d" % (row["reach_short"], row["ends"])
    for r in rows:
        o, c = r["ours"], r["cgal"]
        if "failed" in c:
            lines.append("| %s | %d | %d / — | %d / — | %s / — | %s / — | %d / — | %s / — "
                         "| %.2f / failed |"
                         % (r["mesh"], r["genus"], o["loops"], o["nodes"], pair(o, "radius"),
                            pair(o, "centred"), o["outside"], short(o), o["seconds"]))
            continue
        lines.append("| %s | %d | %d / %d | %d / %d | %s / %s | %s / %s | %d / %d | %s / %s "
                     "| %.2f / %.2f |"
                     % (r["mesh"], r["genus"], o["loops"], c["loops"], o["nodes"], c["nodes"],
                        pair(o, "radius"), pair(c, "radius"), pair(o, "centred"),
                        pair(c, "centred"), o["outside"], c["outside"], short(o), short(c),
                        o["seconds"], c["seconds"]))
    done = [r for r in rows if "failed" not in r["cgal"]]

    def count(test):
        return sum(1 for r in done if test(r["ours"], r["cgal"]))
    lines += ["", "Loops right: ours %d of %d, CGAL %d of %d (%d failed). Smaller median radius "
              "error: ours on %d of %d; more centred by correspondence (median): ours on %d of "
              "%d. Fewer nodes outside or as few: ours on %d of %d. Ends short of their tip: "
              "ours %d of %d (median reach %.2f limb radii), CGAL %d of %d (%.2f). "
              "Faster: ours on %d of %d."
              % (sum(r["ours"]["loops"] == r["genus"] for r in rows), len(rows),
                 sum(r["cgal"]["loops"] == r["genus"] for r in done), len(rows),
                 len(rows) - len(done),
                 count(lambda o, c: o["radius_median"] < c["radius_median"]), len(done),
                 count(lambda o, c: o["centred_median"] < c["centred_median"]), len(done),
                 count(lambda o, c: o["outside"] <= c["outside"]), len(done),
                 sum(r["ours"]["reach_short"] for r in rows),
                 sum(r["ours"]["ends"] for r in rows), pooled(rows, "ours"),
                 sum(r["cgal"]["reach_short"] for r in done),
                 sum(r["cgal"]["ends"] for r in done), pooled(done, "cgal"),
                 count(lambda o, c: o["seconds"] < c["seconds"]), len(done)), "", END]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--meshes", default=os.path.join(ROOT, "..", "shared", "data", "meshes"))
    parser.add_argument("--build", default=os.path.join(ROOT, "build", "vtk"))
    parser.add_argument("--out", default=os.path.join(ROOT, "bench-results", "curve-skeletons"))
    parser.add_argument("--doc", help="replace the curve-skeleton section of this Markdown file")
    parser.add_argument("--only", nargs="*", help="mesh file names")
    args = parser.parse_args()
    tool = os.path.join(args.build, "bin", "medial-axis")
    binary = build_mcf(args.build)
    rows = []
    for name, genus in organic_meshes(args.meshes):
        if args.only and name not in args.only:
            continue
        out = os.path.join(args.out, name)
        os.makedirs(out, exist_ok=True)
        surface, mine = ours(tool, os.path.join(args.meshes, name), out)
        rows.append({"mesh": name, "genus": genus, "ours": mine, "cgal": mcf(binary, surface, out)})
        print(name, json.dumps(rows[-1]), flush=True)
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short=12", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    stamp = "Run of %s, commit %s, two threads." % (time.strftime("%Y-%m-%d"), commit)
    text = markdown(rows, stamp)
    with open(os.path.join(args.out, "curve_skeletons.json"), "w") as f:
        json.dump(rows, f, indent=1)
    with open(os.path.join(args.out, "curve_skeletons.md"), "w") as f:
        f.write(text + "\n")
    if args.doc:
        with open(args.doc, encoding="utf-8") as f:
            doc = f.read()
        if BEGIN in doc and END in doc:
            doc = doc[:doc.index(BEGIN)] + text + doc[doc.index(END) + len(END):]
        else:
            doc = doc.rstrip("\n") + "\n\n" + text + "\n"
        with open(args.doc, "w", encoding="utf-8") as f:
            f.write(doc)
    print(text)


if __name__ == "__main__":
    sys.exit(main())
