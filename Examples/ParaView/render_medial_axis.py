# SPDX-License-Identifier: GPL-3.0-or-later
"""pvbatch/pvpython: compute the Structural MAT of a surface with the plugin and
render it (spheres' centres coloured by radius) inside the semi-transparent
surface, to a PNG.

    xvfb-run -a -s "-screen 0 1024x768x24" pvbatch render_medial_axis.py \\
        PLUGIN OUTPUT.png [SURFACE] [--cad] [--samples N] [--target N]

Without SURFACE it uses a generated box with rounded edges.
"""
import argparse

from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("output")
parser.add_argument("surface", nargs="?")
parser.add_argument("--cad", action="store_true", help="the paper's CAD settings")
parser.add_argument("--samples", type=int)
parser.add_argument("--target", type=int)
parser.add_argument("--size", type=int, nargs=2, default=[1200, 900])
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False, ns=globals())

if args.surface:
    surface = OpenDataFile(args.surface)
else:
    surface = MedialTestShape(Shape="Rounded Box")
mat = StructuralMedialAxis(Input=surface,
                           NumberOfSamples=args.samples or (50000 if args.cad else 10000),
                           TargetNumberOfVertices=args.target or (5000 if args.cad else 1000),
                           PreserveSharpFeatures=1 if args.cad else 0)

view = CreateView("RenderView")
view.ViewSize = args.size
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]
view.OrientationAxesVisibility = 0
shell = Show(surface, view)
shell.Representation = "Surface"
shell.DiffuseColor = [0.75, 0.78, 0.85]
shell.Opacity = 0.25
shell.ColorArrayName = ["POINTS", ""]
axis = Show(OutputPort(mat, 0), view)
axis.Representation = "Surface With Edges"
axis.EdgeColor = [0.15, 0.15, 0.15]
ColorBy(axis, ("POINTS", "Radius"))
radius = GetColorTransferFunction("Radius")
radius.ApplyPreset("Viridis (matplotlib)", True)
axis.SetScalarBarVisibility(view, True)
view.ResetCamera()
camera = view.GetActiveCamera()
camera.Elevation(25)
camera.Azimuth(35)
view.ResetCamera()
Render(view)
SaveScreenshot(args.output, view, ImageResolution=args.size)
result = servermanager.Fetch(OutputPort(mat, 0))
print("rendered %d spheres, %d slabs to %s" % (
    result.GetNumberOfPoints(), result.GetNumberOfPolys(), args.output))
