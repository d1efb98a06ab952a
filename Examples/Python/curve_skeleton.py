# SPDX-License-Identifier: GPL-3.0-or-later
"""A curve skeleton in Python: a surface (a torus by default, or a mesh file),
its Structural MAT, the skeleton's centre lines with their radii and loops,
written as .vtp, .swc and .json, and, where networkx is installed, the
skeleton as a graph.

    python3 curve_skeleton.py [--output DIR] [mesh]
"""
import argparse
import os

import vtk

import medialaxis

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("mesh", nargs="?", help="a closed triangle mesh (default: a torus)")
parser.add_argument("--output", default="output")
args = parser.parse_args()

if args.mesh:
    surface = medialaxis.vtkSurfaceFileReader()
    surface.SetFileName(args.mesh)
else:
    surface = medialaxis.vtkAnalyticShapeSource()
    surface.SetShapeToTorus()

mat = medialaxis.vtkStructuralMedialAxis()
mat.SetInputConnection(surface.GetOutputPort())
mat.SetGenerateEnvelope(False)
curve = medialaxis.vtkMedialCurveSkeleton()
curve.SetInputConnection(0, surface.GetOutputPort())
curve.SetInputConnection(1, mat.GetOutputPort(0))
curve.Update()
skeleton = curve.GetSkeleton()
counts = skeleton.GetFieldData()
print("curve skeleton: %d nodes, %d branches, %d junctions, %d loops" % tuple(
    counts.GetArray(name).GetValue(0) for name in ("Nodes", "Branches", "Junctions", "CycleRank")))

os.makedirs(args.output, exist_ok=True)
for name in ("curve_skeleton.swc", "curve_skeleton.json"):
    writer = medialaxis.vtkCurveSkeletonWriter()
    writer.SetInputData(skeleton)
    writer.SetFileName(os.path.join(args.output, name))
    writer.Write()
vtp = vtk.vtkXMLPolyDataWriter()
vtp.SetInputData(skeleton)
vtp.SetFileName(os.path.join(args.output, "curve_skeleton.vtp"))
vtp.Write()

try:
    graph = medialaxis.skeleton_graph(skeleton)
except ImportError as missing:
    print(missing)
else:
    radii = [data["radius"] for _, data in graph.nodes(data=True)]
    print("graph: %d nodes, %d edges, radius %.3f to %.3f" % (
        graph.number_of_nodes(), graph.number_of_edges(), min(radii), max(radii)))
