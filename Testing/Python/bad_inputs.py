# SPDX-License-Identifier: GPL-3.0-or-later
"""The bad inputs of docs/robustness.md, generated: one corpus shared by the Python API test
(test_bad_inputs.py) and the command-line test (test_cli.py).

Every case is either refused, with a phrase the error message must contain
(the same through every interface), or accepted, with a check of the medial
axis computed from it. docs/robustness.md lists the documented behaviour of
each; Testing/Cxx/TestBadInputs.cxx builds the same inputs in C++.
"""
import math

import vtk

# The medial axis settings every case runs with: small and fast.
SAMPLES = 1000
TARGET = 50
RADIUS = 0.5  # of every generated sphere


def sphere(radius=RADIUS, centre=(0.0, 0.0, 0.0)):
    """A closed, outward triangulated sphere (point 0 is the north pole)."""
    source = vtk.vtkSphereSource()
    source.SetRadius(radius)
    source.SetCenter(*centre)
    source.SetThetaResolution(24)
    source.SetPhiResolution(16)
    source.SetOutputPointsPrecision(vtk.vtkAlgorithm.DOUBLE_PRECISION)
    source.Update()
    surface = vtk.vtkPolyData()
    surface.DeepCopy(source.GetOutput())
    surface.GetPointData().Initialize()
    return surface


def transformed(surface, scale=1.0, offset=(0.0, 0.0, 0.0)):
    points = surface.GetPoints()
    for i in range(points.GetNumberOfPoints()):
        p = points.GetPoint(i)
        points.SetPoint(i, *[scale * p[k] + offset[k] for k in range(3)])
    return surface


def append(*parts):
    together = vtk.vtkAppendPolyData()
    for part in parts:
        together.AddInputData(part)
    together.Update()
    return together.GetOutput()


def triangle_ids(surface, cell):
    ids = vtk.vtkIdList()
    surface.GetPolys().GetCellAtId(cell, ids)
    return [ids.GetId(k) for k in range(ids.GetNumberOfIds())]


def with_triangles(surface, triangles, drop=()):
    """The surface with some triangles dropped and others added."""
    polys = vtk.vtkCellArray()
    for cell in range(surface.GetNumberOfPolys()):
        if cell not in drop:
            polys.InsertNextCell(3, triangle_ids(surface, cell))
    for t in triangles:
        polys.InsertNextCell(3, t)
    result = vtk.vtkPolyData()
    result.SetPoints(surface.GetPoints())
    result.SetPolys(polys)
    return result


def with_point(surface, i, xyz):
    surface.GetPoints().SetPoint(i, *xyz)
    return surface


def cells_only(kind):
    surface = sphere()
    cells = vtk.vtkCellArray()
    for i in range(0, 10, 2):
        cells.InsertNextCell(2 if kind == "lines" else 1)
        cells.InsertCellPoint(i)
        if kind == "lines":
            cells.InsertCellPoint(i + 1)
    result = vtk.vtkPolyData()
    result.SetPoints(surface.GetPoints())
    (result.SetLines if kind == "lines" else result.SetVerts)(cells)
    return result


def open_cap():
    """The sphere without the triangles around its north pole."""
    surface = sphere()
    return with_triangles(surface, [], drop={c for c in range(surface.GetNumberOfPolys())
                                             if 0 in triangle_ids(surface, c)})


def fin():
    """A third triangle on one of the sphere's edges."""
    surface = sphere()
    a, b, _ = triangle_ids(surface, 0)
    extra = surface.GetPoints().InsertNextPoint(1, 1, 1)
    return with_triangles(surface, [(a, b, extra)])


def bow_tie():
    """Two spheres touching at one point: the right one's leftmost point is
    moved onto the left one's rightmost point."""
    left, right = sphere(), sphere(centre=(2 * RADIUS, 0, 0))
    def extreme(surface, sign):
        n = surface.GetNumberOfPoints()
        return max(range(n), key=lambda i: sign * surface.GetPoint(i)[0])
    return append(left, with_point(right, extreme(right, -1), left.GetPoint(extreme(left, 1))))


def flipped_one():
    surface = sphere()
    a, b, c = triangle_ids(surface, 5)
    return with_triangles(surface, [(a, c, b)], drop={5})


def inward():
    flip = vtk.vtkReverseSense()
    flip.SetInputData(sphere())
    flip.Update()
    return flip.GetOutput()


def duplicates():
    surface = sphere()
    return with_triangles(surface, [triangle_ids(surface, c) for c in (3, 40, 41)])


def zero_area():
    """Triangles with a repeated point, and a needle along an edge."""
    surface = sphere()
    a, b, c = triangle_ids(surface, 30)
    pa, pb = surface.GetPoint(a), surface.GetPoint(b)
    middle = surface.GetPoints().InsertNextPoint(*[(pa[k] + pb[k]) / 2 for k in range(3)])
    return with_triangles(surface, [(a, a, b), (b, c, c), (a, middle, b)])


def passes_through_itself():
    """The north pole pulled down through the south pole."""
    return with_point(sphere(), 0, (0.02, 0.01, -1.5 * RADIUS))


def same_as_sphere(scale=1.0, offset=(0.0, 0.0, 0.0)):
    """The repaired, scaled or offset sphere gives the clean sphere's medial
    axis (the reference), scaled and offset alike: every centre and radius
    within 1e-6 of the diagonal."""
    def check(mat, reference):
        if mat.GetNumberOfPoints() != reference.GetNumberOfPoints():
            return ["%d points, not %d" % (mat.GetNumberOfPoints(), reference.GetNumberOfPoints())]
        tolerance = 1e-6 * 2 * math.sqrt(3) * RADIUS
        radii = mat.GetPointData().GetArray("Radius")
        expected = reference.GetPointData().GetArray("Radius")
        errors = []
        for i in range(mat.GetNumberOfPoints()):
            p, q = mat.GetPoint(i), reference.GetPoint(i)
            moved = math.dist([(p[k] - offset[k]) / scale for k in range(3)], q)
            if not moved <= tolerance:
                errors.append("centre %d is %.3g away from the reference's" % (i, moved))
            if not abs(radii.GetValue(i) / scale - expected.GetValue(i)) <= tolerance:
                errors.append("radius %d is %.17g, not %.17g" % (i, radii.GetValue(i) / scale,
                                                                   expected.GetValue(i)))
        return errors
    return check


def ball_check(mat, reference):
    """A ball (the sphere, triangles in another order): every medial ball
    inside the sphere, and the largest nearly as large and at its centre."""
    radii = mat.GetPointData().GetArray("Radius")
    errors = []
    for i in range(mat.GetNumberOfPoints()):
        reach = math.dist(mat.GetPoint(i), (0, 0, 0)) + radii.GetValue(i)
        if not reach <= 1.01 * RADIUS:
            errors.append("ball %d reaches %.4f from the centre" % (i, reach))
    largest = max(range(mat.GetNumberOfPoints()), key=radii.GetValue)
    if not radii.GetValue(largest) >= 0.95 * RADIUS:
        errors.append("the largest ball's radius is %.4f" % radii.GetValue(largest))
    if not math.dist(mat.GetPoint(largest), (0, 0, 0)) <= 0.05 * RADIUS:
        errors.append("the largest ball is at %s" % (mat.GetPoint(largest),))
    return errors


def hollow_ball_check(mat, reference, outer=RADIUS, inner=RADIUS / 2):
    """A ball with a spherical cavity: the medial axis is the sphere halfway
    between the two, every ball as thick as half the wall (to a quarter and
    a tenth of the half wall: both shells are coarse polyhedra)."""
    middle, half_wall = (outer + inner) / 2, (outer - inner) / 2
    radii = mat.GetPointData().GetArray("Radius")
    errors = []
    for i in range(mat.GetNumberOfPoints()):
        distance = math.dist(mat.GetPoint(i), (0, 0, 0))
        if not abs(distance - middle) <= 0.25 * half_wall:
            errors.append("point %d at %.4f from the centre, not %.4f" % (i, distance, middle))
        if not abs(radii.GetValue(i) - half_wall) <= 0.1 * half_wall:
            errors.append("radius %d is %.4f, not %.4f" % (i, radii.GetValue(i), half_wall))
    return errors


def inside_overlapping_copies(mat, reference):
    """Two spheres crossing, repaired into their union: every ball inside the
    union (26 points on each, within 1% of the radius)."""
    radii = mat.GetPointData().GetArray("Radius")
    directions = [(x, y, z) for x in (-1, 0, 1) for y in (-1, 0, 1) for z in (-1, 0, 1)
                  if (x, y, z) != (0, 0, 0)]
    errors = []
    for i in range(mat.GetNumberOfPoints()):
        p, r = mat.GetPoint(i), radii.GetValue(i)
        for d in directions:
            length = math.sqrt(sum(c * c for c in d))
            q = [p[k] + r * d[k] / length for k in range(3)]
            outside = min(math.dist(q, (0, 0, 0)), math.dist(q, (0.3, 0, 0))) - RADIUS
            if not outside <= 0.01 * RADIUS:
                errors.append("ball %d pokes %.3g out of the union" % (i, outside))
                break
    return errors


class Case:
    def __init__(self, name, make=None, text=None, refused=None, check=None):
        self.name = name          # also the file name written for the CLI
        self.make = make          # -> vtkPolyData, or None for a text file
        self.text = text          # the file's contents
        self.refused = refused    # phrase of the error message, or None
        # (mat, the clean sphere's mat) -> list of failures, when accepted
        self.check = check


CASES = [
    Case("empty.off", text="", refused="line 0: empty file"),
    Case("header_only.off", text="OFF\n", refused="line 1: end of file before the counts"),
    Case("nan.vtp", lambda: with_point(sphere(), 3, (math.nan, 0, 0)),
         refused="surface has 1 point with NaN or infinite coordinates"),
    Case("inf.vtp", lambda: with_point(sphere(), 3, (0, math.inf, 0)),
         refused="surface has 1 point with NaN or infinite coordinates"),
    Case("tiny.vtp", lambda: transformed(sphere(), scale=1e-30), check=same_as_sphere(1e-30)),
    Case("huge.vtp", lambda: transformed(sphere(), scale=1e30), check=same_as_sphere(1e30)),
    Case("offset.vtp", lambda: transformed(sphere(), offset=(1e6, -1e6, 1e6)),
         check=same_as_sphere(offset=(1e6, -1e6, 1e6))),
    Case("one_triangle.off", text="OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
         refused="surface is not closed: 3 boundary edges"),
    Case("point_cloud.vtp", lambda: cells_only("verts"),
         refused="surface has no polygons (it has 0 line and 5 vertex cells)"),
    Case("lines_only.vtp", lambda: cells_only("lines"),
         refused="surface has no polygons (it has 5 line and 0 vertex cells)"),
    Case("open.vtp", open_cap, refused="surface is not closed: 24 boundary edges"),
    Case("missing_triangle.vtp", lambda: with_triangles(sphere(), [], drop={7}),
         refused="surface is not closed: 3 boundary edges"),
    Case("non_manifold_edge.vtp", fin, refused="1 edge is shared by more than two triangles"),
    Case("bow_tie.vtp", bow_tie,
         refused="surface is not manifold: 1 vertex joins several separate sheets of triangles"),
    Case("flipped_triangle.vtp", flipped_one, check=ball_check),
    Case("inward.vtp", inward, check=ball_check),
    Case("duplicate_triangles.vtp", duplicates, check=same_as_sphere()),
    Case("zero_area_triangles.vtp", zero_area, check=same_as_sphere()),
    Case("two_copies.vtp", lambda: append(sphere(), sphere()), check=same_as_sphere()),
    Case("overlapping_copies.vtp", lambda: append(sphere(), sphere(centre=(0.3, 0, 0))),
         check=inside_overlapping_copies),
    Case("nested_shells.vtp", lambda: append(sphere(), sphere(RADIUS / 2)),
         check=hollow_ball_check),
    Case("self_intersecting.vtp", passes_through_itself,
         refused="far apart on the surface cross"),
]


def write_surface(surface, path):
    # The default (appended) mode: in inline binary or ASCII mode VTK writes
    # inf.vtp's infinite range in a form its reader cannot parse back.
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(surface)
    writer.SetFileName(path)
    if writer.Write() != 1:
        raise IOError("cannot write " + path)


def write(case, path):
    """Writes the case's input file (text as is, surfaces as VTP)."""
    if case.make is None:
        with open(path, "w") as f:
            f.write(case.text)
        return
    write_surface(case.make(), path)
