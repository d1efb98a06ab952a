# SPDX-License-Identifier: GPL-3.0-or-later
"""pvbatch/pvpython: an open surface from an unsigned distance field with the
plugin: sample the field of a surface (a hemisphere by default, or SURFACE),
extract the surface inside its epsilon-shell, print its counts and, with
--png, render it (triangles with their edges) inside the translucent shell.

    pvbatch udf_surface.py PLUGIN [SURFACE] [--resolution N] [--snap]
        [--png OUTPUT.png] [--size W H]

--png needs a display: run under xvfb-run -a -s "-screen 0 1024x768x24".
"""
import argparse

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("surface", nargs="?", help="an open or closed surface file")
parser.add_argument("--resolution", type=int, default=96, help="grid points per axis")
parser.add_argument("--snap", action="store_true", help="project onto the zero set")
parser.add_argument("--png", help="render into this picture")
parser.add_argument("--size", type=int, nargs=2, default=[1200, 900])
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False, ns=globals())

if args.surface:
    surface = OpenDataFile(args.surface)
else:
    surface = Triangulate(Input=Sphere(ThetaResolution=96, PhiResolution=48, EndPhi=90.0))
field = UnsignedDistanceField(Input=surface, SamplingDimensions=[args.resolution] * 3)
extracted = UDFSurface(Input=field, SnapToZeroSet=int(args.snap))
extracted.UpdatePipeline()
result = servermanager.Fetch(extracted, idx=0)
counts = result.GetFieldData()
print("UDF surface: %d triangles, %d boundary loops, %d junction edges; epsilon %g" % (
    result.GetNumberOfPolys(), counts.GetArray("BoundaryLoops").GetValue(0),
    counts.GetArray("JunctionEdges").GetValue(0), counts.GetArray("Epsilon").GetValue(0)))

if args.png:
    view = CreateView("RenderView")
    view.ViewSize = args.size
    view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    shown = Show(OutputPort(extracted, 0), view)
    shown.SetRepresentationType("Surface With Edges")
    shown.EdgeColor = [0.45, 0.55, 0.7]
    shown.ColorArrayName = ['POINTS', '']
    shown.AmbientColor = shown.DiffuseColor = [0.55, 0.75, 0.95]
    shell = Show(OutputPort(extracted, 1), view)
    shell.ColorArrayName = ['POINTS', '']
    shell.DiffuseColor = [0.95, 0.6, 0.3]
    shell.Opacity = 0.2
    view.ResetCamera()
    camera = view.GetActiveCamera()
    camera.Elevation(-30)  # from below the rim: inside and outside
    camera.Azimuth(30)
    view.ResetCamera()
    SaveScreenshot(args.png, view, ImageResolution=args.size)
    print("wrote " + args.png)
