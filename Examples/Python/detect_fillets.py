# SPDX-License-Identifier: GPL-3.0-or-later
"""MedialAxis from plain VTK Python: the fillets of a CAD part, found on its
Structural MAT. Prints each fillet's radius and length and writes the centre
lines and the surface coloured by fillet for ParaView.

    /usr/bin/python3 detect_fillets.py [--samples N] [--target N]
                                       [--output DIR] [mesh file]

Without a mesh file, a box with rounded edges (fillet radius 0.1) is generated:
its 12 fillets have centre lines of length 1.8 and radius 0.1.
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
    parser.add_argument("--samples", type=int, default=50000, help="surface samples")
    parser.add_argument("--target", type=int, default=5000, help="spheres to keep")
    parser.add_argument("--output", default="output", help="folder for the results")
    args = parser.parse_args()

    if args.mesh:
        surface = medialaxis.vtkSurfaceFileReader()
        surface.SetFileName(args.mesh)
    else:
        surface = medialaxis.vtkAnalyticShapeSource()
        surface.SetShapeToRoundedBox()
        surface.SetFilletRadius(0.1)

    # The stages wired by hand: the detector needs the Atlas correspondence.
    sampler = medialaxis.vtkBlueNoiseSurfaceSampler()
    sampler.SetInputConnection(surface.GetOutputPort())
    sampler.SetNumberOfSamples(args.samples)
    rvd = medialaxis.vtkRestrictedVoronoiDiagram()
    rvd.SetInputConnection(0, surface.GetOutputPort())
    rvd.SetInputConnection(1, sampler.GetOutputPort())
    voronoi = medialaxis.vtkVoronoiMedialAxis()
    voronoi.SetInputConnection(0, surface.GetOutputPort())
    voronoi.SetInputConnection(1, rvd.GetOutputPort(1))
    simplifier = medialaxis.vtkAtlasMedialAxisSimplifier()
    simplifier.SetInputConnection(0, voronoi.GetOutputPort())
    simplifier.SetInputConnection(1, rvd.GetOutputPort(0))
    simplifier.SetTargetNumberOfVertices(args.target)
    simplifier.PreserveSharpFeaturesOn()
    detector = medialaxis.vtkFilletDetector()
    detector.SetInputConnection(0, simplifier.GetOutputPort(0))
    detector.SetInputConnection(1, simplifier.GetOutputPort(1))
    detector.SetInputConnection(2, surface.GetOutputPort())
    detector.Update()

    lines = detector.GetOutput(0)
    if lines.GetFieldData().GetArray("NumberOfFillets") is None:
        sys.exit("no fillets: see the error above")
    cells = lines.GetCellData()
    count = lines.GetNumberOfCells()
    print("%d fillets" % count)
    for f in range(count):
        print("fillet %d: radius %.4f (from %.4f to %.4f), length %.4f" % (
            f, cells.GetArray("MeanRadius").GetValue(f), cells.GetArray("MinimumRadius").GetValue(f),
            cells.GetArray("MaximumRadius").GetValue(f), cells.GetArray("Length").GetValue(f)))

    os.makedirs(args.output, exist_ok=True)
    write_vtp(lines, os.path.join(args.output, "fillet_centre_lines.vtp"))
    write_vtp(detector.GetOutput(1), os.path.join(args.output, "fillet_faces.vtp"))


if __name__ == "__main__":
    main()
