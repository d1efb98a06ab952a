# SPDX-License-Identifier: GPL-3.0-or-later
"""The error events of a VTK algorithm, as the tests read them."""
import vtk


def errors_of(algorithm):
    """Runs the algorithm; returns the text of its error events (and its
    executive's)."""
    messages = []

    def record(caller, event, data=None):
        messages.append(str(data))
    record.CallDataType = vtk.VTK_STRING
    algorithm.AddObserver(vtk.vtkCommand.ErrorEvent, record)
    algorithm.GetExecutive().AddObserver(vtk.vtkCommand.ErrorEvent, record)
    algorithm.Update()
    return " ".join(messages)
