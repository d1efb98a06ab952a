# SPDX-License-Identifier: GPL-3.0-or-later
"""Structural MAT and Q-MAT side by side on the same initial medial mesh:
sampling, restricted Voronoi diagram and Voronoi medial axis run once, then
both simplifiers reduce that mesh to the same number of spheres. Prints, for
each, the time, the two-sided Hausdorff distance, the Euler characteristic
and the triangle quality, and writes both medial meshes as .ma files.

    /usr/bin/python3 compare_qmat.py [--samples N] [--target N] [--cad]
                                     [--output DIR] [mesh file]

Without a mesh file, a torus (major radius 2, minor 0.5) is generated: its
medial axis is the centre circle, Euler characteristic 0.
"""
import argparse
import os
import sys
import time

import vtk
import medialaxis


def euler_characteristic(mesh):
    edges = set()
    for c in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(c).GetPointIds()
        n = ids.GetNumberOfIds()
        for k in range(n if n > 2 else n - 1):
            a, b = ids.GetId(k), ids.GetId((k + 1) % n)
            edges.add((min(a, b), max(a, b)))
    return mesh.GetNumberOfPoints() - len(edges) + mesh.GetNumberOfPolys()


def minimum_angles(mesh):
    """Mean smallest angle of the triangles (degrees)."""
    quality = vtk.vtkMeshQuality()
    quality.SetInputData(mesh)
    quality.SetTriangleQualityMeasureToMinAngle()
    quality.Update()
    values = quality.GetOutput().GetCellData().GetArray("Quality")
    angles = [values.GetValue(c) for c in range(mesh.GetNumberOfCells())
              if mesh.GetCellType(c) == vtk.VTK_TRIANGLE]
    return sum(angles) / len(angles) if angles else float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", help="OBJ, OFF, PLY, STL, VTP or VTK surface")
    parser.add_argument("--samples", type=int, default=10000, help="surface samples")
    parser.add_argument("--target", type=int, default=1000, help="spheres to keep")
    parser.add_argument("--cad", action="store_true",
                        help="snap Structural MAT's boundary onto sharp edges")
    parser.add_argument("--output", default="output", help="folder for the .ma files")
    args = parser.parse_args()

    if args.mesh:
        surface = medialaxis.vtkSurfaceFileReader()
        surface.SetFileName(args.mesh)
    else:
        surface = medialaxis.vtkAnalyticShapeSource()
        surface.SetShapeToTorus()
    sampler = medialaxis.vtkBlueNoiseSurfaceSampler()
    sampler.SetInputConnection(surface.GetOutputPort())
    sampler.SetNumberOfSamples(args.samples)
    rvd = medialaxis.vtkRestrictedVoronoiDiagram()
    rvd.SetInputConnection(0, surface.GetOutputPort())
    rvd.SetInputConnection(1, sampler.GetOutputPort())
    voronoi = medialaxis.vtkVoronoiMedialAxis()
    voronoi.SetInputConnection(0, surface.GetOutputPort())
    voronoi.SetInputConnection(1, rvd.GetOutputPort(1))
    voronoi.Update()
    initial = voronoi.GetOutput()
    if initial.GetNumberOfPoints() == 0:
        sys.exit("no initial medial axis: see the error above")
    print("initial medial mesh: %d spheres, %d slabs" % (
        initial.GetNumberOfPoints(), initial.GetNumberOfPolys()))

    structural = medialaxis.vtkAtlasMedialAxisSimplifier()
    structural.SetInputConnection(0, voronoi.GetOutputPort())
    structural.SetInputConnection(1, rvd.GetOutputPort(0))
    structural.SetPreserveSharpFeatures(args.cad)
    qmat = medialaxis.vtkQMatSimplifier()
    qmat.SetInputConnection(voronoi.GetOutputPort())
    os.makedirs(args.output, exist_ok=True)
    for name, simplifier in (("Structural MAT", structural), ("Q-MAT", qmat)):
        simplifier.SetTargetNumberOfVertices(args.target)
        start = time.perf_counter()
        simplifier.Update()
        seconds = time.perf_counter() - start
        medial = simplifier.GetOutput(0)
        error = medialaxis.vtkMedialReconstructionError()
        error.SetInputConnection(0, surface.GetOutputPort())
        error.SetInputConnection(1, simplifier.GetOutputPort(0))
        error.SetNumberOfSamples(20000)
        error.SetNumberOfEnvelopeSamples(20000)
        error.Update()
        print("%s: %d spheres in %.2f s, two-sided Hausdorff %.3f%%, Euler characteristic %d, "
              "mean minimum angle %.1f deg" % (
                  name, medial.GetNumberOfPoints(), seconds, error.GetHausdorffPercent(),
                  euler_characteristic(medial), minimum_angles(medial)))
        writer = medialaxis.vtkMedialAxisWriter()
        writer.SetInputData(medial)
        writer.SetFileName(os.path.join(args.output, name.replace(" ", "-").lower() + ".ma"))
        if writer.Write() != 1:
            sys.exit("cannot write " + writer.GetFileName())
        print("wrote", writer.GetFileName())


if __name__ == "__main__":
    main()
