# SPDX-License-Identifier: GPL-3.0-or-later
"""MedialAxis: structure-aware medial axis transforms of closed triangle meshes.

The classes are VTK algorithms and chain with any VTK pipeline::

    import vtk
    import medialaxis

    shape = medialaxis.vtkAnalyticShapeSource()
    shape.SetShapeToRoundedBox()
    check = medialaxis.vtkMedialSurfaceValidator()
    check.SetInputConnection(shape.GetOutputPort())
    check.Update()
"""

# VTK's base classes must be importable before the wrapped module loads.
import vtkmodules.vtkCommonCore  # noqa: F401
import vtkmodules.vtkCommonDataModel  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401
import vtkmodules.vtkIOCore  # noqa: F401

from .vtkMedialAxisFilters import *  # noqa: F401,F403

__version__ = "0.1.0"
