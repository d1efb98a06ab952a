# SPDX-License-Identifier: GPL-3.0-or-later
"""Self-intersecting inputs through the repair and the one-click filter:
for each generated case (two overlapping boxes exported as one surface, a
ball pushed through a plate, a tube along a figure-eight crossing itself),
the shared meshes with crossing triangles (block.off, octopus.off: local
folds) and a spindle torus (its tube crosses itself around the axis),
print the crossing pairs, the repair's time and removed area (or, where the
crossings cannot be resolved exactly, that the surface was wrapped and how
far the wrap lies from the input), the medial
axis's Euler characteristic against the solid's (1 - genus), its two-sided
Hausdorff distance to the repaired surface and the sphere centres outside
the repaired solid.

    PYTHONPATH=build/vtk/lib/python3/dist-packages python3 Benchmarks/repair_cases.py [MESH_DIR]
"""
import os
import sys
import time

import vtk
from vtk.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "Testing", "Python"))
import medialaxis  # noqa: E402
import repair_shapes  # noqa: E402

vtk.vtkOutputWindow.SetInstance(vtk.vtkStringOutputWindow())
mesh_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.path.dirname(__file__), "..", "..", "shared", "data", "meshes")


def shared(name):
    def read():
        reader = medialaxis.vtkSurfaceFileReader()
        reader.SetFileName(os.path.join(mesh_dir, name))
        reader.Update()
        return reader.GetOutput()
    return read


def spindle_torus():
    torus = vtk.vtkParametricTorus()
    torus.SetRingRadius(0.6)
    torus.SetCrossSectionRadius(1.0)
    source = vtk.vtkParametricFunctionSource()
    source.SetParametricFunction(torus)
    source.SetUResolution(96)
    source.SetVResolution(48)
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(source.GetOutputPort())
    triangles.Update()
    return triangles.GetOutput()


cases = [(name, make, euler) for name, (make, euler) in repair_shapes.CASES.items()]
cases += [("block.off (genus 3)", shared("block.off"), -2), ("octopus.off", shared("octopus.off"), 1),
          ("spindle torus", spindle_torus, 1)]
print("| case | triangles | crossing pairs | repaired | repair s | area removed | Euler (solid) "
      "| Hausdorff % | centres outside | medial axis s |")
print("|---|---|---|---|---|---|---|---|---|---|")
for name, make, euler in cases:
    surface = make()
    validator = medialaxis.vtkMedialSurfaceValidator()
    validator.SetInputData(surface)
    validator.RepairSelfIntersectionsOn()
    start = time.perf_counter()
    validator.Update()
    repair_seconds = time.perf_counter() - start
    if not validator.GetValid():
        print("| %s | %d | %d | refused: %s | %.2f | | | | | |" % (
            name, surface.GetNumberOfCells(), validator.GetNumberOfCrossingPairs(),
            validator.GetErrorMessage().split("; ")[-1], repair_seconds), flush=True)
        continue
    medial = medialaxis.vtkStructuralMedialAxis()
    medial.SetInputData(surface)
    medial.SetGenerateEnvelope(False)
    start = time.perf_counter()
    medial.Update()
    medial_seconds = time.perf_counter() - start
    mat = medial.GetOutput()
    error = medialaxis.vtkMedialReconstructionError()
    error.SetInputData(0, validator.GetOutput())
    error.SetInputData(1, mat)
    error.Update()
    hausdorff = error.GetOutput().GetFieldData().GetArray("HausdorffPercent").GetValue(0)
    enclosed = vtk.vtkSelectEnclosedPoints()
    enclosed.SetInputData(mat)
    enclosed.SetSurfaceData(validator.GetOutput())
    enclosed.Update()
    inside = vtk_to_numpy(enclosed.GetOutput().GetPointData().GetArray("SelectedPoints"))
    area = validator.GetArea() + validator.GetRemovedArea()
    print("| %s | %d | %d | %s | %.2f | %.1f%% | %d (%d) | %.2f | %d of %d | %.1f |" % (
        name, surface.GetNumberOfCells(), validator.GetNumberOfCrossingPairs(),
        ("wrapped, within %.2f%%" % (100.0 * validator.GetRepairDeviation())
         if validator.GetWrapped() else
         "yes" if validator.GetRepaired() else "no (local folds kept)"), repair_seconds,
        100.0 * validator.GetRemovedArea() / area, repair_shapes.euler_characteristic(mat), euler,
        hausdorff, int((inside == 0).sum()), len(inside), medial_seconds), flush=True)
