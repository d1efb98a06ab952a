# SPDX-License-Identifier: GPL-3.0-or-later
"""Closed surfaces that pass through themselves or whose shells cross, with
the Euler characteristic of the medial axis of the solid they enclose
(1 - genus of its union), for the self-intersection repair."""
import math

import numpy as np
import vtk


def _triangles(algorithm):
    triangles = vtk.vtkTriangleFilter()
    triangles.SetInputConnection(algorithm.GetOutputPort())
    triangles.Update()
    return triangles.GetOutput()


def _together(*parts):
    append = vtk.vtkAppendPolyData()
    for part in parts:
        append.AddInputData(part)
    append.Update()
    return append.GetOutput()


def overlapping_boxes():
    """Two boxes exported as one surface, overlapping in a 1 x 0.5 x 0.5
    block: union volume 2.75, area 14.5 (2.5 of the 17 inside)."""
    a = vtk.vtkCubeSource()
    a.SetBounds(0, 2, 0, 1, 0, 1)
    b = vtk.vtkCubeSource()
    b.SetBounds(1, 3, 0.5, 1.5, 0.25, 0.75)
    return _together(_triangles(a), _triangles(b))


def sphere_through_plate():
    """A ball (radius 0.6) pushed through a plate 0.2 thick."""
    ball = vtk.vtkSphereSource()
    ball.SetRadius(0.6)
    ball.SetThetaResolution(48)
    ball.SetPhiResolution(24)
    plate = vtk.vtkCubeSource()
    plate.SetBounds(-1, 1, -1, 1, -0.1, 0.1)
    return _together(_triangles(ball), _triangles(plate))


def figure_eight_tube(rings=160, sides=24, radius=0.25):
    """A closed tube along a figure-eight curve in z = 0 that crosses itself
    at the origin: one shell passing through itself. Its solid has two
    holes (genus 2)."""
    def centre(t):
        return 1.5 * np.array([math.sin(t), math.sin(t) * math.cos(t), 0.0])
    points = vtk.vtkPoints()
    for i in range(rings):
        t = 2 * math.pi * (i + 0.5) / rings  # no ring at the crossing
        c = centre(t)
        along = centre(t + 1e-4) - centre(t - 1e-4)
        along /= np.linalg.norm(along)
        across = np.array([-along[1], along[0], 0.0]) / math.hypot(along[0], along[1])
        up = np.cross(along, across)
        for j in range(sides):
            a = 2 * math.pi * j / sides
            points.InsertNextPoint(*(c + radius * (math.cos(a) * across + math.sin(a) * up)))
    cells = vtk.vtkCellArray()
    for i in range(rings):
        for j in range(sides):
            a, b = i * sides + j, ((i + 1) % rings) * sides + j
            c, d = ((i + 1) % rings) * sides + (j + 1) % sides, i * sides + (j + 1) % sides
            cells.InsertNextCell(3, [a, b, c])
            cells.InsertNextCell(3, [a, c, d])
    surface = vtk.vtkPolyData()
    surface.SetPoints(points)
    surface.SetPolys(cells)
    return surface


# name: (surface, Euler characteristic of the union's medial axis)
CASES = {
    "overlapping_boxes": (overlapping_boxes, 1),
    "sphere_through_plate": (sphere_through_plate, 1),
    "figure_eight_tube": (figure_eight_tube, -1),
}


def euler_characteristic(mat):
    """V - E + F of a medial mesh (edges of its triangles and its lines)."""
    edges = set()
    faces = 0
    ids = vtk.vtkIdList()
    polys = mat.GetPolys()
    polys.InitTraversal()
    while polys.GetNextCell(ids):
        faces += 1
        n = ids.GetNumberOfIds()
        for k in range(n):
            u, v = ids.GetId(k), ids.GetId((k + 1) % n)
            edges.add((min(u, v), max(u, v)))
    lines = mat.GetLines()
    lines.InitTraversal()
    while lines.GetNextCell(ids):
        for k in range(ids.GetNumberOfIds() - 1):
            u, v = ids.GetId(k), ids.GetId(k + 1)
            edges.add((min(u, v), max(u, v)))
    return mat.GetNumberOfPoints() - len(edges) + faces
