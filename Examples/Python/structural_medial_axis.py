# SPDX-License-Identifier: GPL-3.0-or-later
"""MedialAxis from plain VTK Python: the Structural MAT of a surface in one
filter, its reconstruction error, and the results written for ParaView.

    /usr/bin/python3 structural_medial_axis.py [--cad] [--samples N] [--target N]
                                               [--output DIR] [mesh file]

Without a mesh file, a box with rounded edges (fillet radius 0.2) is generated.
"""
import argparse
import os
import sys

import vtk
import medialaxis


def write_vtp(data, path):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(path)
    if writer.Write() != 1:
        sys.exit("cannot write " + path)
    print("wrote", path)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", help="OBJ, OFF, PLY, STL, VTP or VTK surface")
    parser.add_argument("--cad", action="store_true", help="the paper's CAD settings")
    parser.add_argument("--samples", type=int, help="surface samples (overrides the preset)")
    parser.add_argument("--target", type=int, help="spheres to keep (overrides the preset)")
    parser.add_argument("--output", default="output", help="folder for the results")
    args = parser.parse_args()

    if args.mesh:
        source = medialaxis.vtkSurfaceFileReader()
        source.SetFileName(args.mesh)
    else:
        source = medialaxis.vtkAnalyticShapeSource()
        source.SetShapeToRoundedBox()
        source.SetFilletRadius(0.2)

    mat = medialaxis.vtkStructuralMedialAxis()
    mat.SetInputConnection(source.GetOutputPort())
    if args.cad:
        mat.SetPresetToCAD()
    if args.samples:
        mat.SetNumberOfSamples(args.samples)
    if args.target:
        mat.SetTargetNumberOfVertices(args.target)
    mat.Update()
    medial = mat.GetOutput(0)
    if medial.GetNumberOfPoints() == 0:
        sys.exit("no medial axis: see the error above")
    fields = medial.GetFieldData()
    stages = ", ".join("%s %.2f s" % (name, fields.GetArray(name + "Seconds").GetValue(0))
                       for name in ("Sampling", "RestrictedVoronoi", "VoronoiMedialAxis",
                                    "Simplification"))
    print("medial axis: %d spheres, %d slabs (%s)" % (
        medial.GetNumberOfPoints(), medial.GetNumberOfPolys(), stages))

    error = medialaxis.vtkMedialReconstructionError()
    error.SetInputConnection(0, source.GetOutputPort())
    error.SetInputConnection(1, mat.GetOutputPort(0))
    error.SetNumberOfSamples(20000)
    error.SetNumberOfEnvelopeSamples(20000)
    error.Update()
    print("two-sided Hausdorff distance: %.3f%% of the bounding-box diagonal" %
          error.GetHausdorffPercent())

    os.makedirs(args.output, exist_ok=True)
    write_vtp(medial, os.path.join(args.output, "mat.vtp"))
    write_vtp(mat.GetOutputDataObject(1), os.path.join(args.output, "correspondence.vtp"))
    write_vtp(mat.GetOutputDataObject(3), os.path.join(args.output, "envelope.vtp"))
    write_vtp(error.GetOutput(0), os.path.join(args.output, "distance.vtp"))
    ma = medialaxis.vtkMedialAxisWriter()
    ma.SetInputData(medial)
    ma.SetFileName(os.path.join(args.output, "mat.ma"))
    if ma.Write() != 1:
        sys.exit("cannot write mat.ma")


if __name__ == "__main__":
    main()
