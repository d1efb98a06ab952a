# SPDX-License-Identifier: GPL-3.0-or-later
"""Fillets of CAD parts: runs `medial-axis --preset cad --fillets` on each mesh,
renders the part with its fillet faces coloured and the centre lines drawn,
and prints what was found.

    /usr/bin/python3 fillet_report.py --tool build/vtk/bin/medial-axis \\
        --output fillet-report [mesh ...]

Without meshes: fandisk, rocker-arm, casting and abc_00000068 from
../shared/data/meshes. Writes per mesh a folder with the tool's outputs,
report.json and fillets.png, and prints a summary table. Rendering needs a
display; without one the script runs itself again under xvfb-run.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

DEFAULT_MESHES = ["fandisk.off", "rocker-arm.obj", "casting.off", "abc_00000068.obj"]


def render(surface_path, lines_path, png_path):
    import vtk

    def read(path):
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(path)
        reader.Update()
        return reader.GetOutput()

    surface = read(surface_path)
    lines = read(lines_path)
    fillets = max(1, lines.GetNumberOfCells())
    table = vtk.vtkLookupTable()
    table.SetNumberOfTableValues(fillets + 1)
    table.SetTableRange(-1, fillets - 1)
    table.SetTableValue(0, 0.82, 0.82, 0.80, 1.0)  # no fillet: light grey
    colors = vtk.vtkNamedColors()
    palette = ["Tomato", "DodgerBlue", "Gold", "MediumSeaGreen", "Orchid", "DarkOrange",
               "Turquoise", "SlateBlue", "YellowGreen", "HotPink", "Sienna", "SteelBlue"]
    for f in range(fillets):
        rgb = colors.GetColor3d(palette[f % len(palette)])
        table.SetTableValue(f + 1, rgb[0], rgb[1], rgb[2], 1.0)
    table.Build()

    surface_mapper = vtk.vtkPolyDataMapper()
    surface_mapper.SetInputData(surface)
    surface_mapper.SetScalarModeToUseCellFieldData()
    surface_mapper.SelectColorArray("FilletId")
    surface_mapper.SetLookupTable(table)
    surface_mapper.SetScalarRange(-1, fillets - 1)
    surface_mapper.SetColorModeToMapScalars()
    surface_mapper.ScalarVisibilityOn()
    surface_actor = vtk.vtkActor()
    surface_actor.SetMapper(surface_mapper)
    surface_actor.GetProperty().SetOpacity(0.55)

    tubes = vtk.vtkTubeFilter()
    tubes.SetInputData(lines)
    bounds = surface.GetBounds()
    diagonal = ((bounds[1] - bounds[0]) ** 2 + (bounds[3] - bounds[2]) ** 2 +
                (bounds[5] - bounds[4]) ** 2) ** 0.5
    tubes.SetRadius(0.004 * diagonal)
    tubes.SetNumberOfSides(12)
    line_mapper = vtk.vtkPolyDataMapper()
    line_mapper.SetInputConnection(tubes.GetOutputPort())
    line_mapper.ScalarVisibilityOff()
    line_actor = vtk.vtkActor()
    line_actor.SetMapper(line_mapper)
    line_actor.GetProperty().SetColor(0.1, 0.1, 0.1)

    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(surface_actor)
    renderer.AddActor(line_actor)
    renderer.SetUseDepthPeeling(1)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetAlphaBitPlanes(1)
    window.SetMultiSamples(0)
    window.AddRenderer(renderer)
    window.SetSize(1200, 900)
    camera = renderer.GetActiveCamera()
    camera.Azimuth(35)
    camera.Elevation(25)
    renderer.ResetCamera()
    window.Render()
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    writer = vtk.vtkPNGWriter()
    writer.SetFileName(png_path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("meshes", nargs="*", help="mesh files (default: four CAD meshes)")
    parser.add_argument("--tool", required=True, help="path of the medial-axis program")
    parser.add_argument("--output", default="fillet-report", help="folder for the results")
    parser.add_argument("--mesh-dir", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared", "data", "meshes"))
    args = parser.parse_args()

    if not os.environ.get("DISPLAY") and shutil.which("xvfb-run") and \
            not os.environ.get("MEDIALAXIS_UNDER_XVFB"):
        env = dict(os.environ, MEDIALAXIS_UNDER_XVFB="1")
        sys.exit(subprocess.call(["xvfb-run", "-a", "-s", "-screen 0 1280x1024x24",
                                  sys.executable] + sys.argv, env=env))

    meshes = args.meshes or [os.path.join(args.mesh_dir, m) for m in DEFAULT_MESHES]
    rows = []
    for mesh in meshes:
        if not os.path.exists(mesh):
            print("skipped (absent):", mesh)
            continue
        name = os.path.splitext(os.path.basename(mesh))[0]
        out = os.path.join(args.output, name)
        os.makedirs(out, exist_ok=True)
        report = os.path.join(out, "report.json")
        run = subprocess.run([args.tool, "--preset", "cad", "--fillets", "--quiet", "--report",
                              report, mesh, out], capture_output=True, text=True)
        if run.returncode != 0:
            print(name, "failed:", run.stderr.strip())
            rows.append((name, "failed", "", "", ""))
            continue
        with open(report) as f:
            data = json.load(f)
        png = os.path.join(out, "fillets.png")
        render(os.path.join(out, "fillet_faces.vtp"), os.path.join(out, "fillets.vtp"), png)
        found = data.get("fillets", [])
        print("%s: %d fillets (%.2f s detection, %.2f s total)" % (
            name, len(found), data["seconds"]["Fillets"], data["seconds"]["wall"]))
        for i, fillet in enumerate(found):
            print("  fillet %d: radius %.4g (%.4g to %.4g), length %.4g, faces %.4g" % (
                i, fillet["mean_radius"], fillet["minimum_radius"], fillet["maximum_radius"],
                fillet["length"], fillet["surface_area"]))
        print("  picture:", png)
        rows.append((name, str(len(found)), "%.2f" % data["seconds"]["Fillets"],
                     "%.2f" % data["seconds"]["wall"], png))
    print("\n| mesh | fillets | detection s | total s | picture |")
    print("|---|---|---|---|---|")
    for row in rows:
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
