# SPDX-License-Identifier: GPL-3.0-or-later
"""Generated solids of high genus, each the zero level set of a signed
distance sampled on a grid: plates with 8 and 20 holes of varied size, a
chain of 6 linked (disjoint) tori, a thick trefoil knot and a double torus."""
import math

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk


def level_set(f, bounds, n):
    """The surface f = 0 of f sampled on n points along each axis of bounds."""
    axes = [np.linspace(bounds[2 * a], bounds[2 * a + 1], n) for a in range(3)]
    x, y, z = np.meshgrid(*axes, indexing="ij")
    image = vtk.vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(bounds[0], bounds[2], bounds[4])
    image.SetSpacing(*[(bounds[2 * a + 1] - bounds[2 * a]) / (n - 1) for a in range(3)])
    values = numpy_to_vtk(f(x, y, z).ravel(order="F").copy(), deep=1)
    values.SetName("f")
    image.GetPointData().SetScalars(values)
    contour = vtk.vtkFlyingEdges3D()
    contour.SetInputData(image)
    contour.SetValue(0, 0.0)
    contour.ComputeNormalsOff()
    contour.Update()
    return contour.GetOutput()


def _box(x, y, z, hx, hy, hz):
    q = np.stack([np.abs(x) - hx, np.abs(y) - hy, np.abs(z) - hz])
    return np.linalg.norm(np.maximum(q, 0), axis=0) + np.minimum(q.max(0), 0)


def plate(holes, seed=1, n=120):
    """A 2 x 1.2 x 0.24 plate with `holes` round holes of varied radius on a
    grid: genus `holes`."""
    rng = np.random.default_rng(seed)
    columns = int(math.ceil(math.sqrt(2 * holes)))
    rows = int(math.ceil(holes / columns))
    centres = []
    for k in range(holes):
        i, j = k % columns, k // columns
        cell = min(1.0 / columns, 0.6 / rows)
        centres.append((-1 + (i + 0.5) * 2 / columns, -0.6 + (j + 0.5) * 1.2 / rows,
                        (0.3 + 0.45 * rng.random()) * cell))

    def f(x, y, z):
        d = _box(x, y, z, 1.0, 0.6, 0.12)
        for cx, cy, r in centres:
            d = np.maximum(d, r - np.hypot(x - cx, y - cy))
        return d
    return level_set(f, (-1.1, 1.1, -0.7, 0.7, -0.2, 0.2), n)


def tori_chain(count=6, n=140):
    """`count` tori (radius 0.3, tube 0.06), each linked through the next
    without touching it: `count` pieces of genus 1."""
    def f(x, y, z):
        d = None
        for k in range(count):
            cx = 0.45 * k - 0.225 * (count - 1)
            u, v, w = x - cx, y, z
            t = (np.hypot(np.hypot(u, v) - 0.3, w) if k % 2 == 0 else
                 np.hypot(np.hypot(u, w) - 0.3, v)) - 0.06
            d = t if d is None else np.minimum(d, t)
        return d
    half = 0.225 * count + 0.45
    return level_set(f, (-half, half, -0.45, 0.45, -0.45, 0.45), n)


def trefoil(n=80):
    """A tube of radius 0.15 round a trefoil knot: genus 1."""
    t = np.linspace(0, 2 * math.pi, 240, endpoint=False)
    curve = 0.3 * np.stack([np.sin(t) + 2 * np.sin(2 * t), np.cos(t) - 2 * np.cos(2 * t),
                            -np.sin(3 * t)], 1)

    def f(x, y, z):
        points = np.stack([x.ravel(), y.ravel(), z.ravel()], 1)
        nearest = np.full(len(points), np.inf)
        for start in range(0, len(curve), 60):  # bounded memory
            chunk = curve[start:start + 60]
            d = np.linalg.norm(points[:, None, :] - chunk[None, :, :], axis=2).min(1)
            nearest = np.minimum(nearest, d)
        return nearest.reshape(x.shape) - 0.15
    return level_set(f, (-1.2, 1.2, -1.2, 1.2, -0.6, 0.6), n)


def double_torus(n=100):
    """Two tori (radius 0.4, tube 0.15) side by side, overlapping: genus 2."""
    def f(x, y, z):
        left = np.hypot(np.hypot(x + 0.45, y) - 0.4, z) - 0.15
        right = np.hypot(np.hypot(x - 0.45, y) - 0.4, z) - 0.15
        return np.minimum(left, right)
    return level_set(f, (-1.1, 1.1, -0.65, 0.65, -0.25, 0.25), n)


def ball_with_thin_handles(n=240):
    """A ball of radius 0.5 with three handles: tori of radius 0.2 round
    points of its equator, their tubes 0.012, 0.014 and 0.016 thick in
    radius, each half sunk in the ball: genus 3."""
    tubes = (0.012, 0.014, 0.016)

    def f(x, y, z):
        d = np.sqrt(x * x + y * y + z * z) - 0.5
        for k, r in enumerate(tubes):
            a = 2 * math.pi * k / len(tubes)
            u = (x - 0.55 * math.cos(a)) * math.cos(a) + (y - 0.55 * math.sin(a)) * math.sin(a)
            v = -(x - 0.55 * math.cos(a)) * math.sin(a) + (y - 0.55 * math.sin(a)) * math.cos(a)
            d = np.minimum(d, np.hypot(np.hypot(u, z) - 0.2, v) - r)
        return d
    return level_set(f, (-0.85, 0.85, -0.85, 0.85, -0.6, 0.6), n)


SHAPES = {"plate with 8 holes": lambda: plate(8), "plate with 20 holes": lambda: plate(20),
          "chain of 6 tori": tori_chain, "trefoil tube": trefoil, "double torus": double_torus}
