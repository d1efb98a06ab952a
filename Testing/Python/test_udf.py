# SPDX-License-Identifier: GPL-3.0-or-later
"""Surfaces from unsigned distance fields: vtkUnsignedDistanceSource and
vtkUnsignedDistanceSurfaceExtractor on open, non-orientable and
non-manifold truths (128^3 grids), and their errors on bad input."""
import unittest

import numpy as np
import vtk
from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

import medialaxis
from error_events import errors_of
import udf_shapes


def unsigned_distance(surface, dimensions=128):
    source = medialaxis.vtkUnsignedDistanceSource()
    source.SetInputData(surface)
    source.SetSamplingDimensions(dimensions, dimensions, dimensions)
    source.Update()
    return source


class UnsignedDistanceTest(unittest.TestCase):
    def test_the_source_is_exact(self):
        # Distances to a unit square in z = 0, at grid points, in closed form.
        square = udf_shapes.polydata([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0)],
                                     [(0, 1, 2), (0, 2, 3)])
        source = unsigned_distance(square, 24)
        image = source.GetOutput()
        self.assertEqual(image.GetDimensions(), (24, 24, 24))
        spacing = image.GetSpacing()
        self.assertTrue(spacing[0] == spacing[1] == spacing[2] > 0)
        values = image.GetPointData().GetArray("UnsignedDistance")
        self.assertIsNotNone(values)
        for i in range(0, image.GetNumberOfPoints(), 97):
            x, y, z = image.GetPoint(i)
            dx, dy = max(0, -x, x - 1), max(0, -y, y - 1)
            self.assertAlmostEqual(values.GetValue(i), (dx * dx + dy * dy + z * z) ** 0.5,
                                   delta=1e-6)
        # 6 free cells around the square's bounds along x and y.
        bounds = image.GetBounds()
        self.assertAlmostEqual(-bounds[0], 6 * spacing[0], delta=1e-9)

    def extract(self, name, dimensions=128):
        truth = udf_shapes.SHAPES[name]()
        source = unsigned_distance(truth, dimensions)
        extractor = medialaxis.vtkUnsignedDistanceSurfaceExtractor()
        extractor.SetInputConnection(source.GetOutputPort())
        extractor.Update()
        return truth, extractor, source.GetOutput().GetSpacing()[0]

    def check_case(self, name, junctions=False, dimensions=128):
        truth, extractor, spacing = self.extract(name, dimensions)
        surface = extractor.GetOutput()
        epsilon = extractor.GetUsedEpsilon()
        self.assertAlmostEqual(epsilon, 2 * spacing)
        self.assertGreater(surface.GetNumberOfPolys(), 1000)
        hausdorff, chamfer = udf_shapes.compare(surface, truth)
        self.assertLessEqual(hausdorff, spacing, name)
        self.assertLessEqual(chamfer, 0.25 * spacing, name)
        loops, junction_edges = udf_shapes.edge_counts(surface)
        truth_loops, _ = udf_shapes.edge_counts(truth)
        self.assertEqual(loops, truth_loops, name)
        self.assertEqual(surface.GetFieldData().GetArray("BoundaryLoops").GetValue(0), loops)
        if junctions:
            # The junction line, on the truth's and as long (its edges are finer).
            self.assertLessEqual(udf_shapes.junction_offset(surface, truth), spacing)
            self.assertAlmostEqual(udf_shapes.junction_length(surface),
                                   udf_shapes.junction_length(truth), delta=4 * spacing)
        else:
            self.assertEqual(junction_edges, 0, name)
        doubled, probed = udf_shapes.double_layer_triangles(surface, epsilon)
        self.assertGreater(probed, 0.5 * surface.GetNumberOfPolys())
        self.assertEqual(doubled, 0, name)
        # Spheres of radius epsilon around the surface (larger at junctions,
        # where the shell's sides meet farther out).
        radius = vtk_to_numpy(surface.GetPointData().GetArray("ShellRadius"))
        self.assertGreaterEqual(radius.min(), 0.5 * epsilon)
        self.assertAlmostEqual(np.median(radius) / epsilon, 1.0, delta=0.05)
        return surface

    def test_disk(self):
        self.check_case("disk")

    def test_hemisphere(self):
        self.check_case("hemisphere")

    def test_moebius_strip(self):
        self.check_case("moebius")

    def test_three_half_planes(self):
        self.check_case("half_planes", junctions=True)

    def test_garment(self):
        self.check_case("garment")

    def test_cap_past_the_equator(self):
        self.check_case("cap", dimensions=96)

    def test_disk_with_a_hole(self):
        self.check_case("annulus", dimensions=96)

    def test_a_field_that_is_not_a_distance_is_named(self):
        # Values made too large at a few grid points, as a distance sampled
        # by several threads through a function that is not safe for them
        # (vtkImplicitPolyDataDistance under vtkSampleFunction) comes out.
        source = unsigned_distance(udf_shapes.disk(), 48)
        image = vtk.vtkImageData()
        image.DeepCopy(source.GetOutput())
        values = vtk_to_numpy(image.GetPointData().GetArray("UnsignedDistance"))
        spacing = image.GetSpacing()[0]
        for i in range(0, len(values), 997):
            values[i] += 5 * spacing
        extractor = medialaxis.vtkUnsignedDistanceSurfaceExtractor()
        extractor.SetInputData(image)
        extractor.Update()
        self.assertGreater(extractor.GetNumberOfNonDistanceNeighbours(), 0)
        self.assertEqual(extractor.GetOutput().GetFieldData().GetArray(
            "NonDistanceNeighbours").GetValue(0), extractor.GetNumberOfNonDistanceNeighbours())
        extractor.SetInputData(source.GetOutput())
        extractor.Update()
        self.assertEqual(extractor.GetNumberOfNonDistanceNeighbours(), 0)

    def test_the_layer_measure_sees_two_layers(self):
        # A disk and a copy of it one epsilon above: every probed triangle
        # has a second layer; the disk alone has none.
        disk = udf_shapes.disk()
        lifted = vtk.vtkTransform()
        lifted.Translate(0, 0, 0.03)
        moved = vtk.vtkTransformPolyDataFilter()
        moved.SetInputData(disk)
        moved.SetTransform(lifted)
        both = vtk.vtkAppendPolyData()
        both.AddInputData(disk)
        both.AddInputConnection(moved.GetOutputPort())
        both.Update()
        doubled, probed = udf_shapes.double_layer_triangles(both.GetOutput(), 0.03)
        self.assertGreater(probed, 0)
        self.assertEqual(doubled, probed)
        self.assertEqual(udf_shapes.double_layer_triangles(disk, 0.03)[0], 0)

    def test_other_data_sets_are_resampled(self):
        # The disk's field as a structured grid and as an unstructured grid:
        # resampled onto the same cubic cells, the same surface as from the
        # image, within a spacing of the truth.
        truth = udf_shapes.disk()
        source = unsigned_distance(truth, 96)
        spacing = source.GetOutput().GetSpacing()[0]
        structured = vtk.vtkImageDataToPointSet()
        structured.SetInputConnection(source.GetOutputPort())
        unstructured = vtk.vtkAppendFilter()
        unstructured.SetInputConnection(source.GetOutputPort())
        for grid in (structured, unstructured):
            extractor = medialaxis.vtkUnsignedDistanceSurfaceExtractor()
            extractor.SetInputConnection(grid.GetOutputPort())
            extractor.SetResampleDimension(96)
            extractor.Update()
            surface = extractor.GetOutput()
            self.assertGreater(surface.GetNumberOfPolys(), 1000)
            self.assertEqual(udf_shapes.edge_counts(surface), (1, 0))
            hausdorff, chamfer = udf_shapes.compare(surface, truth)
            self.assertLessEqual(hausdorff, spacing)
            self.assertLessEqual(chamfer, 0.25 * spacing)

    def test_same_result_every_run(self):
        first = self.extract("disk")[1].GetOutput()
        second = self.extract("disk")[1].GetOutput()
        a = first.GetPoints().GetData()
        b = second.GetPoints().GetData()
        self.assertEqual(a.GetNumberOfTuples(), b.GetNumberOfTuples())
        self.assertTrue(all(a.GetTuple3(i) == b.GetTuple3(i) for i in range(a.GetNumberOfTuples())))

    def test_distance_as_a_python_function(self):
        # The half-planes' closed-form distance as a Python function: the
        # same targets as from a sampled field. Snapping moves every point
        # but the junction's onto the exact zero set: closer to the truth.
        truth = udf_shapes.half_planes()
        distance, bounds = udf_shapes.EXACT_DISTANCES["half_planes"]
        errors = {}
        for snap in (False, True):
            extractor = medialaxis.vtkUnsignedDistanceSurfaceExtractor()
            medialaxis.set_distance_function(extractor, distance, bounds)
            self.assertTrue(extractor.HasDistanceFunction())
            extractor.SetSnapToZeroSet(snap)
            extractor.Update()
            surface = extractor.GetOutput()
            spacing = extractor.GetUsedEpsilon() / 2
            self.assertGreater(surface.GetNumberOfPolys(), 1000)
            errors[snap] = udf_shapes.compare(surface, truth)
            self.assertLessEqual(errors[snap][0], spacing)
            self.assertLessEqual(errors[snap][1], 0.25 * spacing)
            self.assertEqual(udf_shapes.edge_counts(surface)[0], 1)
            self.assertLessEqual(udf_shapes.junction_offset(surface, truth), spacing)
        self.assertLess(errors[True][0], 0.75 * errors[False][0])
        self.assertLess(errors[True][1], errors[False][1])

    def test_bad_distance_functions(self):
        extractor = medialaxis.vtkUnsignedDistanceSurfaceExtractor()
        extractor.SetResampleDimension(32)
        medialaxis.set_distance_function(
            extractor, lambda p: udf_shapes.disk_distance(p)[:-1], (-1, 1, -1, 1, 0, 0))
        self.assertIn("filled 0 values of QueryDistances", errors_of(extractor))

        def fails(points):
            raise RuntimeError("no network loaded")
        medialaxis.set_distance_function(extractor, fails, (-1, 1, -1, 1, 0, 0))
        self.assertIn("the distance function failed", errors_of(extractor))

        medialaxis.set_distance_function(extractor, udf_shapes.disk_distance, (-1, 1, -1, 1, 0, 0))
        extractor.SetInputData(vtk.vtkImageData())
        self.assertIn("both an input and a distance function", errors_of(extractor))
        extractor.RemoveAllInputs()
        extractor.Update()
        self.assertGreater(extractor.GetOutput().GetNumberOfPolys(), 100)
        medialaxis.set_distance_function(extractor, None, ())
        self.assertFalse(extractor.HasDistanceFunction())

    def test_bad_input(self):
        image = vtk.vtkImageData()
        image.SetDimensions(16, 16, 16)
        extractor = medialaxis.vtkUnsignedDistanceSurfaceExtractor()
        extractor.SetInputData(image)
        self.assertIn("no unsigned distance array", errors_of(extractor))

        # A signed distance (a sphere's) is refused.
        values = np.array([np.linalg.norm(image.GetPoint(i)[:3] - np.array([7.5, 7.5, 7.5])) - 4
                           for i in range(image.GetNumberOfPoints())])
        array = numpy_to_vtk(values, deep=1)
        array.SetName("Distance")
        image.GetPointData().SetScalars(array)
        extractor.Modified()
        self.assertIn("negative values", errors_of(extractor))

        # Its absolute value is an unsigned distance: Epsilon below the
        # spacing is refused, and so is a shell cut by the grid's border.
        image.GetPointData().SetScalars(numpy_to_vtk(np.abs(values), deep=1))
        extractor.SetEpsilon(0.5)
        extractor.Modified()
        self.assertIn("below the grid's spacing", errors_of(extractor))
        extractor.SetEpsilon(4.0)
        self.assertIn("reaches the grid's border", errors_of(extractor))

        source = medialaxis.vtkUnsignedDistanceSource()
        source.SetInputData(vtk.vtkPolyData())
        self.assertIn("no polygons", errors_of(source))


if __name__ == "__main__":
    unittest.main()
