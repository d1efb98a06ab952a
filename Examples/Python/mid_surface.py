# SPDX-License-Identifier: GPL-3.0-or-later
"""MedialAxis from plain VTK Python: the mid-surface of a thin-walled part
with its thickness, the sheet a CAE shell mesh is made from. Prints the wall
thickness found, each wall's area and thickness, and writes the mid-surface
for ParaView (colour it by Thickness or WallId).

    /usr/bin/python3 mid_surface.py [--wall-thickness T] [--output DIR] [mesh file]

Without a mesh file a T-plate is generated (a plate 2 x 2 with a rib 1 high,
walls 0.1 thick, the junction rounded by fillets of radius 0.1): its
mid-surface is the plate's mid-plane and the rib's, two walls meeting along
the junction, of area 2 x (2 + 1 + 0.05) = 6.1.
"""
import argparse
import os
import sys

import vtk
import medialaxis


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", help="OBJ, OFF, PLY, STL, VTP or VTK surface")
    parser.add_argument("--wall-thickness", type=float, default=0.0,
                        help="the thickest wall (default: automatic)")
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

    # The medial axis with the CAD settings, then its walls' mid-surface.
    mat = medialaxis.vtkStructuralMedialAxis()
    mat.SetInputConnection(surface.GetOutputPort())
    mat.SetPresetToCAD()
    mid = medialaxis.vtkMidSurfaceExtractor()
    mid.SetInputConnection(0, surface.GetOutputPort())
    mid.SetMedialAxisConnection(mat.GetOutputPort(0))
    mid.SetWallThickness(args.wall_thickness)
    mid.Update()
    result = mid.GetOutput()
    if result.GetNumberOfPolys() == 0:
        sys.exit("no mid-surface: see the message above")

    area = vtk.vtkMassProperties()
    area.SetInputData(result)
    area.Update()
    fields = result.GetFieldData()
    print("wall thickness %.4f: %d walls from %d medial sheets, %d junction edges, area %.4f" % (
        mid.GetEstimatedWallThickness(), mid.GetNumberOfWalls(), mid.GetNumberOfWallSheets(),
        mid.GetNumberOfJunctionEdges(), area.GetSurfaceArea()))
    for w in range(mid.GetNumberOfWalls()):
        print("wall %d: area %.4f, thickness %.4f (from %.4f to %.4f)" % (
            w, fields.GetArray("WallArea").GetValue(w),
            fields.GetArray("WallMeanThickness").GetValue(w),
            fields.GetArray("WallMinimumThickness").GetValue(w),
            fields.GetArray("WallMaximumThickness").GetValue(w)))

    os.makedirs(args.output, exist_ok=True)
    path = os.path.join(args.output, "mid_surface.vtp")
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(result)
    writer.SetFileName(path)
    if writer.Write() != 1:
        sys.exit("cannot write " + path)
    print("wrote", path)


if __name__ == "__main__":
    main()
