# SPDX-License-Identifier: GPL-3.0-or-later
"""MedialAxis from plain VTK Python: check and repair a surface, write .vtp.

    /usr/bin/python3 prepare_surface.py [--output DIR] [mesh file]

Without a mesh file, a torus is generated.
"""
import argparse
import os
import sys

import vtk
import medialaxis


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh", nargs="?", help="OBJ, OFF, PLY, STL, VTP or VTK surface")
    parser.add_argument("--output", default="output", help="folder for the .vtp result")
    args = parser.parse_args()

    if args.mesh:
        source = medialaxis.vtkSurfaceFileReader()
        source.SetFileName(args.mesh)
        stem = os.path.splitext(os.path.basename(args.mesh))[0]
    else:
        source = medialaxis.vtkAnalyticShapeSource()
        source.SetShapeToTorus()
        source.SetMajorRadius(2.0)
        source.SetMinorRadius(0.5)
        stem = "torus"

    validator = medialaxis.vtkMedialSurfaceValidator()
    validator.SetInputConnection(source.GetOutputPort())
    validator.Update()
    if not validator.GetValid():
        print("surface is invalid:", validator.GetErrorMessage(), file=sys.stderr)
        return 3
    surface = validator.GetOutput()
    print("surface is valid: %d points, %d triangles, area %.6g, volume %.6g"
          % (surface.GetNumberOfPoints(), surface.GetNumberOfPolys(),
             validator.GetArea(), validator.GetVolume()))

    os.makedirs(args.output, exist_ok=True)
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(surface)
    writer.SetFileName(os.path.join(args.output, stem + "_prepared.vtp"))
    writer.Write()
    print("wrote", writer.GetFileName())
    return 0


if __name__ == "__main__":
    sys.exit(main())
