# SPDX-License-Identifier: GPL-3.0-or-later
"""MedialAxis from plain VTK Python: the structure of a part's Structural MAT,
which spheres are sheets, seams, junctions, rims, features or fillets, its
sheets and its seams. Prints the counts and each sheet's area and radii, and
writes the typed MAT and the seams for ParaView.

    /usr/bin/python3 medial_structure.py [--samples N] [--target N]
                                         [--output DIR] [mesh file]

Without a mesh file a T-plate is generated (a plate with a rib, walls 0.1
thick, the junction rounded by fillets of radius 0.1): the mid-sheets of
its plate and rib meet on one seam under the rib, at height 0.0375 with balls
of radius 0.0875.
"""
import argparse
import os
import statistics
import sys

import vtk
import medialaxis

TYPES = ["sheet", "seam", "junction", "rim", "feature", "fillet", "curve", "isolated"]


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
        surface.SetShapeToTPlate()
        surface.SetXLength(2.0)
        surface.SetYLength(2.0)
        surface.SetZLength(1.0)
        surface.SetThickness(0.1)
        surface.SetFilletRadius(0.1)

    # The one-click filter with the CAD settings; its port 1, the restricted
    # Voronoi cells of the sites, gives each sphere's tangent components.
    mat = medialaxis.vtkStructuralMedialAxis()
    mat.SetInputConnection(surface.GetOutputPort())
    mat.SetPresetToCAD()
    mat.SetNumberOfSamples(args.samples)
    mat.SetTargetNumberOfVertices(args.target)
    structure = medialaxis.vtkMedialStructure()
    structure.SetInputConnection(0, mat.GetOutputPort(0))
    structure.SetCellsConnection(mat.GetOutputPort(1))
    structure.Update()
    typed = structure.GetOutput(0)
    if typed.GetPointData().GetArray("MedialType") is None:
        sys.exit("no structure: see the error above")

    print("%d sheets, %d seams" % (structure.GetNumberOfSheets(), structure.GetNumberOfSeams()))
    print("spheres: " + ", ".join("%d %s" % (structure.GetNumberOfVerticesOfType(t), name)
                                  for t, name in enumerate(TYPES)))
    fields = typed.GetFieldData()
    print("tangent components agree with the mesh on %.1f%% of the spheres"
          % (100.0 * fields.GetArray("TangentComponentAgreement").GetValue(0)))
    for s in range(structure.GetNumberOfSheets()):
        print("sheet %d: area %.4f, radius %.4f (from %.4f to %.4f)" % (
            s, fields.GetArray("SheetArea").GetValue(s), fields.GetArray("SheetMeanRadius").GetValue(s),
            fields.GetArray("SheetMinimumRadius").GetValue(s),
            fields.GetArray("SheetMaximumRadius").GetValue(s)))

    if not args.mesh:
        # The seams lying under the rib, near the plate's mid-plane.
        seams = structure.GetOutput(1)
        ids = seams.GetCellData().GetArray("SeamId")
        radius = typed.GetPointData().GetArray("Radius")
        points = {}
        for c in range(seams.GetNumberOfCells()):
            cell = seams.GetCell(c)
            points.setdefault(int(ids.GetValue(c)), set()).update(
                (cell.GetPointId(0), cell.GetPointId(1)))
        under = [p for p in points.values()
                 if all(abs(seams.GetPoint(v)[1]) < 0.05 and -0.05 < seams.GetPoint(v)[2] < 0.1
                        for v in p)]
        for p in under:
            print("seams under the rib: %d (median height %.4f, radius %.4f)" % (
                len(under), statistics.median(seams.GetPoint(v)[2] for v in p),
                statistics.median(radius.GetValue(v) for v in p)))

    os.makedirs(args.output, exist_ok=True)
    write_vtp(typed, os.path.join(args.output, "structure.vtp"))
    write_vtp(structure.GetOutput(1), os.path.join(args.output, "seams.vtp"))


if __name__ == "__main__":
    main()
