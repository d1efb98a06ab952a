# SPDX-License-Identifier: GPL-3.0-or-later
"""The bad inputs of docs/robustness.md through the Python API: each is either computed by
vtkStructuralMedialAxis (the result checked) or refused with an error event
and a message naming the defect. The corpus is bad_inputs.py, shared with
the command-line test."""
import os
import tempfile
import unittest

import vtk

import medialaxis
import bad_inputs


class ErrorMessages:
    """Collects the text of VTK error events instead of printing them."""

    def __init__(self, algorithm):
        self.messages = []
        algorithm.AddObserver("ErrorEvent", self.record)

    @vtk.calldata_type(vtk.VTK_STRING)
    def record(self, obj, event, text):
        self.messages.append(text)


def medial_axis(surface=None, port=None):
    """The one-click filter on a surface or a pipeline port, with the
    corpus' settings; returns the medial mesh and the error messages."""
    medial = medialaxis.vtkStructuralMedialAxis()
    errors = ErrorMessages(medial)
    if port is not None:
        medial.SetInputConnection(port)
    else:
        medial.SetInputData(surface)
    medial.SetNumberOfSamples(bad_inputs.SAMPLES)
    medial.SetTargetNumberOfVertices(bad_inputs.TARGET)
    medial.SetGenerateEnvelope(False)
    medial.Update()
    return medial.GetOutput(), errors.messages


class BadInputTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.reference, errors = medial_axis(bad_inputs.sphere())
        assert not errors and cls.reference.GetNumberOfPoints() == bad_inputs.TARGET, errors

    def test_every_bad_input(self):
        with tempfile.TemporaryDirectory() as folder:
            for case in bad_inputs.CASES:
                with self.subTest(case.name):
                    self.check(case, folder)

    def check(self, case, folder):
        if case.make is None:
            # A file: a malformed one is refused by the reader, naming the
            # line, and the medial axis filter behind it refuses its empty
            # output; a well-formed one is checked like any surface.
            path = os.path.join(folder, case.name)
            bad_inputs.write(case, path)
            reader = medialaxis.vtkSurfaceFileReader()
            reader.SetFileName(path)
            read_errors = ErrorMessages(reader)
            mat, errors = medial_axis(port=reader.GetOutputPort())
            if reader.GetErrorMessage():
                self.assertIn(case.refused, reader.GetErrorMessage())
                self.assertTrue(read_errors.messages)
                self.assertEqual(mat.GetNumberOfPoints(), 0)
                return
            surface = reader.GetOutput()
        else:
            surface = case.make()
            mat, errors = medial_axis(surface)
        # The validator as the one-click filter prepares: crossings repaired.
        validator = medialaxis.vtkMedialSurfaceValidator()
        ErrorMessages(validator)
        validator.RepairSelfIntersectionsOn()
        validator.SetInputData(surface)
        validator.Update()
        if case.refused:
            self.assertEqual(mat.GetNumberOfPoints(), 0)
            self.assertEqual(len(errors), 1, errors)
            self.assertIn(case.refused, errors[0])
            self.assertFalse(validator.GetValid())
            self.assertIn(case.refused, validator.GetErrorMessage())
        else:
            self.assertEqual(errors, [])
            self.assertTrue(validator.GetValid(), validator.GetErrorMessage())
            self.assertEqual(mat.GetNumberOfPoints(), bad_inputs.TARGET)
            self.assertEqual(case.check(mat, self.reference), [])


if __name__ == "__main__":
    # Expected errors are checked through their events, not printed.
    vtk.vtkOutputWindow.SetInstance(vtk.vtkStringOutputWindow())
    unittest.main()
