# SPDX-License-Identifier: GPL-3.0-or-later
"""Self-intersecting inputs: crossing shells and a surface passing through
itself are resolved into the outer boundary of the solid (on by default in
vtkStructuralMedialAxis, off in the bare validator); other bad surfaces stay
refused."""
import unittest

import vtk
from vtk.util.numpy_support import vtk_to_numpy

import medialaxis
from error_events import errors_of
import repair_shapes


def validate(surface, repair):
    validator = medialaxis.vtkMedialSurfaceValidator()
    validator.SetInputData(surface)
    validator.SetRepairSelfIntersections(repair)
    return validator, errors_of(validator)


class SelfIntersectionRepairTest(unittest.TestCase):
    def test_the_validator_refuses_unless_asked(self):
        boxes = repair_shapes.overlapping_boxes()
        validator, errors = validate(boxes, False)
        self.assertIn("of separate shells cross", errors)
        self.assertFalse(validator.GetValid())

        validator, errors = validate(boxes, True)
        self.assertEqual(errors, "")
        self.assertTrue(validator.GetValid())
        self.assertTrue(validator.GetRepaired())
        self.assertEqual(validator.GetNumberOfCrossingPairs(), 18)
        # The union of the two boxes, exactly.
        self.assertAlmostEqual(validator.GetRemovedArea(), 2.5, places=9)
        self.assertAlmostEqual(validator.GetArea(), 14.5, places=9)
        self.assertAlmostEqual(validator.GetVolume(), 2.75, places=9)
        self.assertEqual(validator.GetNumberOfComponents(), 1)
        self.assertIn("self-intersections repaired", validator.GetNotes())
        # The output passes the validator again, untouched.
        again, errors = validate(validator.GetOutput(), False)
        self.assertEqual(errors, "")
        self.assertFalse(again.GetRepaired())

    def test_medial_axes_of_the_repaired_solids(self):
        for name, (make, euler) in repair_shapes.CASES.items():
            surface = make()
            repaired, _ = validate(surface, True)
            self.assertTrue(repaired.GetRepaired(), name)
            medial = medialaxis.vtkStructuralMedialAxis()
            medial.SetInputData(surface)
            medial.SetGenerateEnvelope(False)
            medial.Update()
            mat = medial.GetOutput()
            self.assertGreater(mat.GetNumberOfPoints(), 100, name)
            self.assertEqual(repair_shapes.euler_characteristic(mat), euler, name)
            fields = mat.GetFieldData()
            self.assertEqual(fields.GetArray("RepairedCrossingPairs").GetValue(0),
                             repaired.GetNumberOfCrossingPairs(), name)
            # Every sphere centre inside the repaired solid.
            enclosed = vtk.vtkSelectEnclosedPoints()
            enclosed.SetInputData(mat)
            enclosed.SetSurfaceData(repaired.GetOutput())
            enclosed.Update()
            inside = vtk_to_numpy(enclosed.GetOutput().GetPointData().GetArray("SelectedPoints"))
            self.assertEqual(int((inside == 0).sum()), 0, name)
            # Close to the repaired surface, both ways.
            error = medialaxis.vtkMedialReconstructionError()
            error.SetInputData(0, repaired.GetOutput())
            error.SetInputData(1, mat)
            error.Update()
            hausdorff = error.GetOutput().GetFieldData().GetArray("HausdorffPercent").GetValue(0)
            self.assertLess(hausdorff, 2.0, name)
            # The correspondence names the input's triangles.
            cells = medial.GetOutput(1).GetCellData().GetArray("InputTriangleId")
            self.assertIsNotNone(cells, name)
            ids = vtk_to_numpy(cells)
            self.assertGreaterEqual(ids.min(), 0, name)
            self.assertLess(ids.max(), surface.GetNumberOfCells(), name)

    def test_bad_input_stays_bad(self):
        boxes = repair_shapes.overlapping_boxes()
        medial = medialaxis.vtkStructuralMedialAxis()
        medial.SetInputData(boxes)
        medial.RepairSelfIntersectionsOff()
        medial.SetNumberOfSamples(2000)
        medial.SetTargetNumberOfVertices(100)
        self.assertIn("of separate shells cross", errors_of(medial))

        # Open: a box with one face missing, crossing another box.
        open_box = vtk.vtkPolyData()
        open_box.DeepCopy(boxes)
        open_box.BuildLinks()
        open_box.DeleteCell(0)
        open_box.RemoveDeletedCells()
        _, errors = validate(open_box, True)
        self.assertIn("not closed", errors)

        # Non-manifold: two tetrahedra sharing an edge only.
        points = vtk.vtkPoints()
        for p in [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (0, -1, 0), (0, 0, -1)]:
            points.InsertNextPoint(p)
        cells = vtk.vtkCellArray()
        for t in [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3),
                  (0, 1, 4), (0, 5, 1), (0, 4, 5), (1, 5, 4)]:
            cells.InsertNextCell(3, t)
        pair = vtk.vtkPolyData()
        pair.SetPoints(points)
        pair.SetPolys(cells)
        _, errors = validate(pair, True)
        self.assertIn("not manifold", errors)


if __name__ == "__main__":
    unittest.main()
