# SPDX-License-Identifier: GPL-3.0-or-later
"""Open, non-orientable and non-manifold test surfaces with their exact
geometry, for the unsigned-distance extraction, and the measures that
compare an extracted surface with its truth."""
import math

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy


def polydata(points, triangles):
    """Triangles on points, coincident points merged."""
    surface = vtk.vtkPolyData()
    coordinates = vtk.vtkPoints()
    coordinates.SetData(numpy_to_vtk(np.asarray(points, dtype=float), deep=1))
    surface.SetPoints(coordinates)
    cells = vtk.vtkCellArray()
    for t in triangles:
        cells.InsertNextCell(3, [int(v) for v in t])
    surface.SetPolys(cells)
    clean = vtk.vtkCleanPolyData()
    clean.SetInputData(surface)
    clean.SetTolerance(1e-9)
    clean.Update()
    # Triangles whose corners merged (at a pole, a disk's centre) became
    # lines and vertices: only the triangles are the surface.
    merged = clean.GetOutput()
    surface = vtk.vtkPolyData()
    surface.SetPoints(merged.GetPoints())
    surface.SetPolys(merged.GetPolys())
    return surface


def parametric(f, nu, nv, closed_u=False, flip_at_seam=False):
    """Points f(s, t) for s, t in [0, 1] on an nu x nv grid of quads, two
    triangles each; closed_u joins s = 1 to s = 0 (flip_at_seam: with t
    reversed, a Moebius strip)."""
    columns = nu if closed_u else nu + 1
    points = [f(i / nu, j / nv) for i in range(columns) for j in range(nv + 1)]

    def index(i, j):
        return (i % columns) * (nv + 1) + j
    triangles = []
    for i in range(nu):
        for j in range(nv):
            if closed_u and flip_at_seam and i == nu - 1:
                b, c = index(0, nv - j), index(0, nv - j - 1)
            else:
                b, c = index(i + 1, j), index(i + 1, j + 1)
            a, d = index(i, j), index(i, j + 1)
            triangles += [(a, b, c), (a, c, d)]
    return points, triangles


def disk():
    """Unit disk in z = 0: one boundary."""
    return polydata(*parametric(
        lambda s, t: (t * math.cos(2 * math.pi * s), t * math.sin(2 * math.pi * s), 0.0),
        128, 32, closed_u=True))


def hemisphere():
    """Unit upper hemisphere: open, one boundary."""
    return polydata(*parametric(
        lambda s, t: (math.sin(0.5 * math.pi * t) * math.cos(2 * math.pi * s),
                      math.sin(0.5 * math.pi * t) * math.sin(2 * math.pi * s),
                      math.cos(0.5 * math.pi * t)), 128, 32, closed_u=True))


def moebius():
    """Moebius strip (radius 1, width 0.6): non-orientable, one boundary."""
    def f(s, t):
        v = 0.6 * (t - 0.5)
        r = 1 + v * math.cos(math.pi * s)
        return (r * math.cos(2 * math.pi * s), r * math.sin(2 * math.pi * s),
                v * math.sin(math.pi * s))
    return polydata(*parametric(f, 160, 16, closed_u=True, flip_at_seam=True))


def half_planes():
    """Three unit squares meeting along the z axis at 120 degrees: a
    non-manifold junction (20 edges)."""
    points, triangles = [], []
    for fin in range(3):
        angle = 2 * math.pi * fin / 3
        p, t = parametric(lambda s, u: (s * math.cos(angle), s * math.sin(angle), 2 * u - 1),
                          10, 20)
        triangles += [tuple(v + len(points) for v in tri) for tri in t]
        points += p
    return polydata(points, triangles)


def garment():
    """A sleeve: a tube (radius 0.5, height 1.2) cut open along 30 degrees,
    with a flat collar 0.2 wide around its top: open, one boundary, a sharp
    fold."""
    gap = math.radians(30.0)

    def angle(s):
        return 0.5 * gap + s * (2 * math.pi - gap)
    tube = parametric(lambda s, t: (0.5 * math.cos(angle(s)), 0.5 * math.sin(angle(s)), 1.2 * t),
                      96, 24)
    collar = parametric(lambda s, t: ((0.5 + 0.2 * t) * math.cos(angle(s)),
                                      (0.5 + 0.2 * t) * math.sin(angle(s)), 1.2), 96, 6)
    offset = len(tube[0])
    return polydata(tube[0] + collar[0],
                    tube[1] + [tuple(v + offset for v in t) for t in collar[1]])


def cap():
    """A spherical cap past the equator (polar angle 0 to 110 degrees, radius
    0.7): open, one boundary narrower than the widest circle."""
    reach = math.radians(110.0)
    return polydata(*parametric(
        lambda s, t: (0.7 * math.sin(reach * t) * math.cos(2 * math.pi * s),
                      0.7 * math.sin(reach * t) * math.sin(2 * math.pi * s),
                      0.7 * math.cos(reach * t)), 160, 48, closed_u=True))


def annulus():
    """A disk with a hole (radii 0.3 and 1) in z = 0: two boundaries."""
    return polydata(*parametric(
        lambda s, t: ((0.3 + 0.7 * t) * math.cos(2 * math.pi * s),
                      (0.3 + 0.7 * t) * math.sin(2 * math.pi * s), 0.0), 128, 24, closed_u=True))


SHAPES = {"disk": disk, "hemisphere": hemisphere, "moebius": moebius,
          "half_planes": half_planes, "garment": garment, "cap": cap, "annulus": annulus}


def disk_distance(p):
    """Exact distance from the points p (n x 3) to the unit disk in z = 0."""
    outside = np.maximum(np.hypot(p[:, 0], p[:, 1]) - 1.0, 0.0)
    return np.hypot(outside, p[:, 2])


def hemisphere_distance(p):
    """Exact distance to the unit upper hemisphere: radial above z = 0,
    to its rim below."""
    rim = np.hypot(np.hypot(p[:, 0], p[:, 1]) - 1.0, p[:, 2])
    return np.where(p[:, 2] >= 0, np.abs(np.linalg.norm(p, axis=1) - 1.0), rim)


def half_planes_distance(p):
    """Exact distance to the three unit squares of half_planes()."""
    best = np.full(len(p), np.inf)
    for fin in range(3):
        angle = 2 * math.pi * fin / 3
        along = p[:, 0] * math.cos(angle) + p[:, 1] * math.sin(angle)
        across = -p[:, 0] * math.sin(angle) + p[:, 1] * math.cos(angle)
        beyond = along - np.clip(along, 0.0, 1.0)
        above = p[:, 2] - np.clip(p[:, 2], -1.0, 1.0)
        best = np.minimum(best, np.sqrt(beyond ** 2 + across ** 2 + above ** 2))
    return best


# Closed-form distances and the boxes that hold their surfaces.
EXACT_DISTANCES = {
    "disk": (disk_distance, (-1, 1, -1, 1, 0, 0)),
    "hemisphere": (hemisphere_distance, (-1, 1, -1, 1, 0, 1)),
    "half_planes": (half_planes_distance,
                    (-0.5, 1, -math.sin(2 * math.pi / 3), math.sin(2 * math.pi / 3), -1, 1)),
}


def mesh_distance(surface):
    """The exact distance to a triangle surface as a function of an (n, 3)
    array of points: the magnitude of vtkImplicitPolyDataDistance."""
    implicit = vtk.vtkImplicitPolyDataDistance()
    implicit.SetInput(surface)

    def distance(points):
        values = vtk.vtkDoubleArray()
        implicit.EvaluateFunction(numpy_to_vtk(np.ascontiguousarray(points), deep=1), values)
        return np.abs(vtk_to_numpy(values))
    return distance


def triangles_of(surface):
    return vtk_to_numpy(surface.GetPolys().GetData()).reshape(-1, 4)[:, 1:]


def edge_counts(surface):
    """(boundary loops, junction edges): connected groups of edges of one
    triangle, and edges of three or more."""
    uses = {}
    for t in triangles_of(surface):
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            key = (min(a, b), max(a, b))
            uses[key] = uses.get(key, 0) + 1
    parent = {}

    def find(x):
        while parent.setdefault(x, x) != x:
            x = parent[x]
        return x
    for (a, b), count in uses.items():
        if count == 1:
            parent[find(a)] = find(b)
    loops = len({find(a) for (a, b), count in uses.items() if count == 1})
    return loops, sum(1 for count in uses.values() if count > 2)


def junction_edges(surface):
    """The edges of three or more triangles, as line cells."""
    uses = {}
    for t in triangles_of(surface):
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            key = (min(a, b), max(a, b))
            uses[key] = uses.get(key, 0) + 1
    lines = vtk.vtkCellArray()
    for (a, b), count in uses.items():
        if count > 2:
            lines.InsertNextCell(2, [int(a), int(b)])
    junction = vtk.vtkPolyData()
    junction.SetPoints(surface.GetPoints())
    junction.SetLines(lines)
    return junction


def junction_length(surface):
    """Total length of the edges of three or more triangles."""
    p = vtk_to_numpy(surface.GetPoints().GetData())
    lines = vtk_to_numpy(junction_edges(surface).GetLines().GetData()).reshape(-1, 3)[:, 1:]
    return float(np.linalg.norm(p[lines[:, 0]] - p[lines[:, 1]], axis=1).sum())


def junction_offset(surface, truth):
    """Farthest distance from a junction edge's midpoint of `surface` to the
    junction edges of `truth`."""
    p = vtk_to_numpy(surface.GetPoints().GetData())
    lines = vtk_to_numpy(junction_edges(surface).GetLines().GetData()).reshape(-1, 3)[:, 1:]
    if len(lines) == 0:
        return 0.0
    return float(Distance(junction_edges(truth))(0.5 * (p[lines[:, 0]] + p[lines[:, 1]])).max())


def sample_points(surface):
    """Vertices, triangle centroids and edge midpoints."""
    p = vtk_to_numpy(surface.GetPoints().GetData())
    t = triangles_of(surface)
    return np.r_[p, p[t].mean(axis=1), 0.5 * (p[t[:, 0]] + p[t[:, 1]]),
                 0.5 * (p[t[:, 1]] + p[t[:, 2]]), 0.5 * (p[t[:, 2]] + p[t[:, 0]])]


class Distance:
    """Distances from points to a triangle surface."""

    def __init__(self, surface):
        self.locator = vtk.vtkStaticCellLocator()
        self.locator.SetDataSet(surface)
        self.locator.BuildLocator()

    def __call__(self, points):
        closest, cell, sub, d2 = [0.0] * 3, vtk.reference(0), vtk.reference(0), vtk.reference(0.0)
        out = np.empty(len(points))
        for i, p in enumerate(points):
            self.locator.FindClosestPoint(p, closest, cell, sub, d2)
            out[i] = math.sqrt(d2.get())
        return out


def compare(extracted, truth):
    """(two-sided Hausdorff, Chamfer) between two surfaces, from dense
    samples of each (vertices, centroids, edge midpoints)."""
    to_truth = Distance(truth)(sample_points(extracted))
    to_extracted = Distance(extracted)(sample_points(truth))
    return (max(to_truth.max(), to_extracted.max()),
            0.5 * (to_truth.mean() + to_extracted.mean()))


def double_layer_triangles(surface, epsilon):
    """Triangles with a second layer of the surface within 2 epsilon above or
    below them: the segment from the centroid along the normal, both ways,
    from 0.05 to 2 epsilon, must cross no triangle parallel to it (within
    30 degrees) beyond its two rings of neighbours. Triangles within 2 epsilon of
    a boundary or junction edge are not probed (other sheets meet there by
    right). Returns (flagged, probed)."""
    p = vtk_to_numpy(surface.GetPoints().GetData())
    t = triangles_of(surface)
    uses = {}
    for tri in t:
        for a, b in ((tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])):
            key = (min(a, b), max(a, b))
            uses[key] = uses.get(key, 0) + 1
    edge_points = np.array([0.5 * (p[a] + p[b]) for (a, b), c in uses.items() if c != 2])
    centroids = p[t].mean(axis=1)
    normals = np.cross(p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    near = np.zeros(len(t), dtype=bool)
    if len(edge_points):
        cloud = vtk.vtkPolyData()
        cloud_points = vtk.vtkPoints()
        cloud_points.SetData(numpy_to_vtk(edge_points, deep=1))
        cloud.SetPoints(cloud_points)
        locator = vtk.vtkStaticPointLocator()
        locator.SetDataSet(cloud)
        locator.BuildLocator()
        for i, c in enumerate(centroids):
            nearest = edge_points[locator.FindClosestPoint(c)]
            near[i] = np.linalg.norm(nearest - c) < 2 * epsilon
    tree = vtk.vtkOBBTree()
    tree.SetDataSet(surface)
    tree.BuildLocator()
    hits, cells = vtk.vtkPoints(), vtk.vtkIdList()
    around = [[] for _ in range(len(p))]  # the triangles at each vertex
    for k, tri in enumerate(t):
        for v in tri:
            around[v].append(k)
    flagged = 0
    for i in np.flatnonzero(~near):
        for side in (1, -1):
            start = centroids[i] + side * 0.05 * epsilon * normals[i]
            end = centroids[i] + side * 2 * epsilon * normals[i]
            tree.IntersectWithLine(start, end, hits, cells)
            # A second layer runs alongside (normals within 30 degrees) and
            # apart (no vertex within two rings: a triangle folded over a
            # neighbour at a sharp fold is not a layer); a fold's other side
            # or a corner cut across it is not one either.
            ring = set(v for u in t[i] for w in around[u] for v in t[w])
            if any(abs(np.dot(normals[j], normals[i])) > 0.866 and not set(t[j]) & ring
                   for j in (cells.GetId(k) for k in range(cells.GetNumberOfIds()))):
                flagged += 1
                break
    return flagged, int(np.count_nonzero(~near))
