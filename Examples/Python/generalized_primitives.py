# SPDX-License-Identifier: GPL-3.0-or-later
"""MedialAxis from plain VTK Python: generalized enveloping primitives (the
Medial Skeletal Diagram's) on a coarse medial skeleton. Simplifies the
medial axis of a shape to a few dozen spheres, fits a primitive (a radius per
direction) to each vertex, edge and triangle of it, prints how many of each
kind and how much of the surface their union reaches, and writes them for
ParaView (a .vtpc, one block per element, coloured by Radius).

    /usr/bin/python3 generalized_primitives.py [--spheres N] [--exact] [--output DIR] [mesh file]

With --exact each direction's radius is where its ray leaves the surface,
the template refined where the surface lies between directions (what the
skeletal diagram uses), instead of the paper's smooth fit.

Without a mesh file a dumbbell is generated (two balls of radius 0.25, 1.2
apart pole to pole, joined by a neck of radius 0.1).
"""
import argparse
import os
import sys

import vtk
import medialaxis


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", help="OBJ, OFF, PLY, STL, VTP or VTK surface")
    parser.add_argument("--spheres", type=int, default=30, help="skeleton vertices (default 30)")
    parser.add_argument("--exact", action="store_true",
                        help="exact radii instead of the smooth fit")
    parser.add_argument("--output", default="output", help="folder for the results")
    args = parser.parse_args()

    if args.mesh:
        surface = medialaxis.vtkSurfaceFileReader()
        surface.SetFileName(args.mesh)
    else:
        surface = medialaxis.vtkAnalyticShapeSource()
        surface.SetShapeToDumbbell()
        surface.SetLength(1.2)
        surface.SetRadius(0.25)
        surface.SetMinorRadius(0.1)

    # A coarse skeleton: the Structural MAT simplified to a few spheres.
    mat = medialaxis.vtkStructuralMedialAxis()
    mat.SetInputConnection(surface.GetOutputPort())
    mat.SetNumberOfSamples(10000)
    mat.SetTargetNumberOfVertices(args.spheres)
    fitter = medialaxis.vtkGeneralizedPrimitiveFitter()
    fitter.SetInputConnection(0, surface.GetOutputPort())
    fitter.SetSkeletonConnection(mat.GetOutputPort(0))
    fitter.SetExactRadii(args.exact)
    fitter.Update()
    primitives = fitter.GetOutput()
    if primitives.GetNumberOfPartitionedDataSets() == 0:
        sys.exit("no primitives: see the message above")

    counts = [0, 0, 0]
    union = vtk.vtkAppendPolyData()
    for e in range(primitives.GetNumberOfPartitionedDataSets()):
        mesh = primitives.GetPartition(e, 0)
        counts[mesh.GetFieldData().GetArray("ElementType").GetValue(0)] += 1
        if mesh.GetNumberOfPoints() > 0:
            union.AddInputData(mesh)
    union.Update()
    print("%d primitives: %d vertices, %d edges, %d triangles; %d failed" % (
        primitives.GetNumberOfPartitionedDataSets(), counts[0], counts[1], counts[2],
        fitter.GetNumberOfFailedElements()))

    # How far the surface's points lie from the union of the primitives
    # (every primitive is inside the surface, so this is the part it misses).
    surface.Update()
    locator = vtk.vtkStaticCellLocator()
    locator.SetDataSet(union.GetOutput())
    locator.BuildLocator()
    points = surface.GetOutput().GetPoints()
    bounds = surface.GetOutput().GetBounds()
    diagonal = sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)) ** 0.5
    closest, cell, sub, d2 = [0.0, 0.0, 0.0], vtk.reference(0), vtk.reference(0), vtk.reference(0.0)
    distances = []
    for i in range(points.GetNumberOfPoints()):
        locator.FindClosestPoint(points.GetPoint(i), closest, cell, sub, d2)
        distances.append(d2.get() ** 0.5 / diagonal)
    distances.sort()
    print("surface to primitives: mean %.3f%%, 95%% within %.3f%%, largest %.3f%% of the diagonal" % (
        100 * sum(distances) / len(distances), 100 * distances[int(0.95 * (len(distances) - 1))],
        100 * distances[-1]))

    os.makedirs(args.output, exist_ok=True)
    writer = vtk.vtkXMLPartitionedDataSetCollectionWriter()
    writer.SetInputData(primitives)
    writer.SetFileName(os.path.join(args.output, "primitives.vtpc"))
    writer.Write()
    print("wrote", writer.GetFileName())


if __name__ == "__main__":
    main()
