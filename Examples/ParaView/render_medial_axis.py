# SPDX-License-Identifier: GPL-3.0-or-later
"""pvbatch/pvpython: compute the Structural MAT of a surface with the plugin and
render it (coloured by radius, or with --structure by sphere type: sheet,
seam, junction, rim, feature, fillet, curve; or with --mid-surface the
thin walls' mid-surface by thickness) inside the semi-transparent surface,
to a PNG.

    xvfb-run -a -s "-screen 0 1024x768x24" pvbatch render_medial_axis.py \\
        PLUGIN OUTPUT.png [SURFACE] [--cad] [--structure | --mid-surface]
        [--samples N] [--target N]

Without SURFACE it uses a generated box with rounded edges (with
--mid-surface a T-plate: walls 0.1 thick, plate 2 x 2, rib 1 high).
"""
import argparse

from paraview.simple import *  # noqa: F401,F403

parser = argparse.ArgumentParser()
parser.add_argument("plugin")
parser.add_argument("output")
parser.add_argument("surface", nargs="?")
parser.add_argument("--cad", action="store_true", help="the paper's CAD settings")
parser.add_argument("--structure", action="store_true", help="colour the spheres by type")
parser.add_argument("--mid-surface", action="store_true", help="show the walls' mid-surface")
parser.add_argument("--samples", type=int)
parser.add_argument("--target", type=int)
parser.add_argument("--size", type=int, nargs=2, default=[1200, 900])
args = parser.parse_args()
LoadPlugin(args.plugin, remote=False, ns=globals())

if args.surface:
    surface = OpenDataFile(args.surface)
elif args.mid_surface:
    surface = MedialTestShape(Shape="T Plate", XLength=2.0, YLength=2.0, ZLength=1.0,
                              Thickness=0.1, FilletRadius=0.0)
else:
    surface = MedialTestShape(Shape="Rounded Box")
mat = StructuralMedialAxis(Input=surface,
                           NumberOfSamples=args.samples or (50000 if args.cad else 10000),
                           TargetNumberOfVertices=args.target or (5000 if args.cad else 1000),
                           PreserveSharpFeatures=1 if args.cad else 0,
                           AdaptiveSampling=0 if args.cad else 1)

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
shown = OutputPort(mat, 0)
if args.structure:
    # The restricted Voronoi cells (port 1) give each sphere's tangent
    # components, MATFP's cross-check of the types.
    shown = MedialStructure(Input=OutputPort(mat, 0), Cells=OutputPort(mat, 1))
elif args.mid_surface:
    shown = MidSurface(Input=surface, MedialAxis=OutputPort(mat, 0))
axis = Show(shown, view)
axis.Representation = "Surface With Edges"
axis.EdgeColor = [0.15, 0.15, 0.15]
array = "MedialType" if args.structure else "Thickness" if args.mid_surface else "Radius"
ColorBy(axis, ("POINTS", array))
colours = GetColorTransferFunction(array)
if args.structure:
    colours.InterpretValuesAsCategories = 1
    colours.Annotations = ["0", "sheet", "1", "seam", "2", "junction", "3", "rim", "4", "feature",
                           "5", "fillet", "6", "curve", "7", "isolated"]
    colours.ApplyPreset("Brewer Qualitative Set1", True)
else:
    colours.ApplyPreset("Viridis (matplotlib)", True)
axis.SetScalarBarVisibility(view, True)
view.ResetCamera()
camera = view.GetActiveCamera()
camera.Elevation(25)
camera.Azimuth(35)
view.ResetCamera()
Render(view)
SaveScreenshot(args.output, view, ImageResolution=args.size)
result = servermanager.Fetch(shown)
print("rendered %d spheres, %d slabs to %s" % (
    result.GetNumberOfPoints(), result.GetNumberOfPolys(), args.output))
if args.structure:
    fields = result.GetFieldData()
    print("structure: %d sheets, %d seams, %d junction spheres" % (
        fields.GetArray("NumberOfSheets").GetValue(0), fields.GetArray("NumberOfSeams").GetValue(0),
        fields.GetArray("NumberOfJunctionVertices").GetValue(0)))
if args.mid_surface:
    fields = result.GetFieldData()
    print("mid-surface: %d walls, wall thickness %.4f" % (
        fields.GetArray("NumberOfWalls").GetValue(0), fields.GetArray("WallThickness").GetValue(0)))
