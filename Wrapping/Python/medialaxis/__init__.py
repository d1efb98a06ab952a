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


def set_distance_function(extractor, function, bounds):
    """Gives a vtkUnsignedDistanceSurfaceExtractor its distance as a Python
    function instead of an input.

    function(points) receives an (n, 3) numpy array of points and returns n
    unsigned distances (any sequence of numbers); it is called on batches of
    at most 65,536 points. bounds: (xmin, xmax, ymin, ymax, zmin, zmax), the
    box that holds the surface. An exception in the function stops the
    extractor with an error. set_distance_function(extractor, None, bounds)
    removes the function.
    """
    import weakref

    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy

    if function is None:
        extractor.RemoveDistanceFunction()
        return
    owner = weakref.ref(extractor)

    def evaluate():
        current = owner()
        points = vtk_to_numpy(current.GetQueryPoints()).reshape(-1, 3)
        distances = numpy.asarray(function(points), dtype=float).reshape(-1)
        if len(distances) != len(points):
            raise ValueError("the distance function returned %d values for %d points"
                             % (len(distances), len(points)))
        out = current.GetQueryDistances()
        out.SetNumberOfTuples(len(distances))
        vtk_to_numpy(out)[:] = distances

    extractor.SetDistanceMethod(evaluate)
    extractor.SetFunctionBounds(*bounds)


def skeleton_graph(skeleton):
    """The curve skeleton (vtkMedialCurveSkeleton's output 0, a vtkPolyData)
    as a networkx.Graph: a node per point with attributes position (x, y, z),
    radius, type ("end", "regular" or "junction") and branch; an edge per
    pair of consecutive points of a polyline with attribute length.

    Needs networkx (Debian: python3-networkx); raises ImportError saying so
    where it is missing and ValueError for a dataset that is no skeleton.
    """
    import math

    points = skeleton.GetPoints() if skeleton is not None else None
    data = skeleton.GetPointData() if skeleton is not None else None
    radius = data.GetArray("Radius") if data is not None else None
    if radius is None or skeleton.GetNumberOfPolys() > 0:
        raise ValueError("not a curve skeleton: expected points with point data 'Radius' and "
                         "polylines (vtkMedialCurveSkeleton's output 0)")
    try:
        import networkx
    except ImportError as error:
        raise ImportError("skeleton_graph needs networkx (Debian: apt-get install "
                          "python3-networkx; pip: pip install networkx)") from error
    kinds = data.GetArray("NodeType")
    branch = data.GetArray("BranchId")
    names = ("end", "regular", "junction")
    graph = networkx.Graph()
    for v in range(skeleton.GetNumberOfPoints()):
        graph.add_node(v, position=tuple(points.GetPoint(v)),
                       radius=radius.GetValue(v) if radius else None,
                       type=names[int(kinds.GetValue(v))] if kinds else None,
                       branch=int(branch.GetValue(v)) if branch else None)
    lines = skeleton.GetLines()
    ids = lines.GetConnectivityArray()
    offsets = lines.GetOffsetsArray()
    for c in range(lines.GetNumberOfCells()):
        chain = [int(ids.GetValue(k))
                 for k in range(int(offsets.GetValue(c)), int(offsets.GetValue(c + 1)))]
        for a, b in zip(chain, chain[1:]):
            if a != b:
                graph.add_edge(a, b, length=math.dist(points.GetPoint(a), points.GetPoint(b)))
    return graph
