# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python package used the way users use it: in VTK pipelines."""
import os
import tempfile
import unittest

import vtk
import medialaxis


class ErrorObserver:
    """Collects VTK error events instead of printing them."""

    def __init__(self):
        self.messages = []

    def __call__(self, obj, event, data=None):
        self.messages.append(event)

    def attach(self, algorithm):
        algorithm.AddObserver("ErrorEvent", self)
        return self


class PipelineTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def test_shape_validator_and_xml_writer_chain(self):
        shape = medialaxis.vtkAnalyticShapeSource()
        shape.SetShapeToRoundedBox()
        shape.SetFilletRadius(0.25)
        validator = medialaxis.vtkMedialSurfaceValidator()
        validator.SetInputConnection(shape.GetOutputPort())
        normals = vtk.vtkPolyDataNormals()  # any VTK filter chains after ours
        normals.SetInputConnection(validator.GetOutputPort())
        writer = vtk.vtkXMLPolyDataWriter()
        writer.SetInputConnection(normals.GetOutputPort())
        writer.SetFileName(self.path("box.vtp"))
        self.assertEqual(writer.Write(), 1)
        self.assertTrue(validator.GetValid(), validator.GetErrorMessage())
        self.assertAlmostEqual(validator.GetVolume() / shape.GetExactVolume(), 1.0, delta=0.01)

        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(self.path("box.vtp"))
        reader.Update()
        self.assertEqual(reader.GetOutput().GetNumberOfCells(),
                         validator.GetOutput().GetNumberOfCells())
        area = reader.GetOutput().GetFieldData().GetArray("Area").GetValue(0)
        self.assertAlmostEqual(area, validator.GetArea())

    def test_medial_axis_round_trip(self):
        text = "4 5 1\n" \
               "v 0 0 0 0.5\nv 1 0 0 0.25\nv 0 1 0 0.125\nv 0.1 0.2 3.3 0.1\n" \
               "e 0 1\ne 1 2\ne 2 0\ne 2 3\ne 0 3\n" \
               "f 0 1 2\n"
        with open(self.path("in.ma"), "w") as f:
            f.write(text)
        reader = medialaxis.vtkMedialAxisReader()
        reader.SetFileName(self.path("in.ma"))
        reader.Update()
        mat = reader.GetOutput()
        self.assertEqual(mat.GetNumberOfPoints(), 4)
        self.assertEqual(mat.GetNumberOfPolys(), 1)
        self.assertEqual(mat.GetNumberOfLines(), 2)  # 2-3 and 0-3 bound no face
        self.assertEqual(mat.GetPointData().GetScalars().GetName(), "Radius")
        self.assertEqual(mat.GetPointData().GetArray("Radius").GetValue(3), 0.1)

        writer = medialaxis.vtkMedialAxisWriter()
        writer.SetInputConnection(reader.GetOutputPort())
        writer.SetFileName(self.path("out.ma"))
        self.assertEqual(writer.Write(), 1)
        with open(self.path("out.ma")) as f:
            lines = f.read().split("\n")
        self.assertEqual(lines[0], "4 5 1")
        self.assertIn("v 0.10000000000000001 0.20000000000000001 3.2999999999999998 "
                      "0.10000000000000001", lines)

    def test_malformed_medial_axis_file(self):
        with open(self.path("bad.ma"), "w") as f:
            f.write("2 0 0\nv 0 0 0 1\nv 1 0 0 -2\n")
        reader = medialaxis.vtkMedialAxisReader()
        errors = ErrorObserver().attach(reader)
        reader.SetFileName(self.path("bad.ma"))
        reader.Update()
        self.assertEqual(reader.GetOutput().GetNumberOfPoints(), 0)
        self.assertIn("line 3: radius -2 is negative", reader.GetErrorMessage())
        self.assertTrue(errors.messages)

    def test_off_reader_and_surface_reader(self):
        with open(self.path("tet.off"), "w") as f:
            f.write("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                    "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
        reader = medialaxis.vtkSurfaceFileReader()
        reader.SetFileName(self.path("tet.off"))
        validator = medialaxis.vtkMedialSurfaceValidator()
        validator.SetInputConnection(reader.GetOutputPort())
        validator.Update()
        self.assertTrue(validator.GetValid(), validator.GetErrorMessage())
        self.assertAlmostEqual(validator.GetVolume(), 1.0 / 6.0)

    def test_sampler_and_restricted_voronoi_pipeline(self):
        shape = medialaxis.vtkAnalyticShapeSource()
        shape.SetShapeToTorus()
        sampler = medialaxis.vtkBlueNoiseSurfaceSampler()
        sampler.SetInputConnection(shape.GetOutputPort())
        sampler.SetNumberOfSamples(1500)
        sampler.SetRandomSeed(7)
        rvd = medialaxis.vtkRestrictedVoronoiDiagram()
        rvd.SetInputConnection(0, shape.GetOutputPort())
        rvd.SetInputConnection(1, sampler.GetOutputPort())
        rvd.SetFeatureAngle(30.0)
        self.assertEqual(rvd.GetFeatureNormalFiltering(), 3)
        rvd.Update()
        sites = rvd.GetOutputDataObject(1)
        self.assertEqual(sites.GetNumberOfPoints(), 1500)
        area = sites.GetPointData().GetArray("CellArea")
        total = sum(area.GetValue(i) for i in range(area.GetNumberOfTuples()))
        self.assertAlmostEqual(total / shape.GetExactArea(), 1.0, delta=0.01)
        # A smooth torus has no sharp edges at a 30 degree tolerance.
        convex = sites.GetPointData().GetArray("ConvexFeature")
        self.assertEqual(convex.GetRange(), (0.0, 0.0))
        cells = rvd.GetOutput(0)
        self.assertEqual(cells.GetCellData().GetArray("SiteId").GetRange(), (0.0, 1499.0))

        # Same seed, same sites; the output is independent of threads.
        again = medialaxis.vtkBlueNoiseSurfaceSampler()
        again.SetInputConnection(shape.GetOutputPort())
        again.SetNumberOfSamples(1500)
        again.SetRandomSeed(7)
        again.SetNumberOfThreads(1)
        again.Update()
        a = sampler.GetOutput().GetPoints().GetData()
        b = again.GetOutput().GetPoints().GetData()
        self.assertTrue(all(a.GetTuple3(i) == b.GetTuple3(i) for i in range(1500)))

    def test_voronoi_medial_axis_of_a_torus(self):
        shape = medialaxis.vtkAnalyticShapeSource()
        shape.SetShapeToTorus()
        shape.SetResolution(24)
        sampler = medialaxis.vtkBlueNoiseSurfaceSampler()
        sampler.SetInputConnection(shape.GetOutputPort())
        sampler.SetNumberOfSamples(3000)
        rvd = medialaxis.vtkRestrictedVoronoiDiagram()
        rvd.SetInputConnection(0, shape.GetOutputPort())
        rvd.SetInputConnection(1, sampler.GetOutputPort())
        voronoi = medialaxis.vtkVoronoiMedialAxis()
        voronoi.SetInputConnection(0, shape.GetOutputPort())
        voronoi.SetInputConnection(1, rvd.GetOutputPort(1))
        voronoi.Update()
        mat = voronoi.GetOutput()
        self.assertGreater(mat.GetNumberOfPolys(), 1000)
        # Large balls of a torus (R = 2, r = 0.5) sit near the centre circle.
        radius = mat.GetPointData().GetArray("Radius")
        points = mat.GetPoints()
        for i in range(mat.GetNumberOfPoints()):
            if radius.GetValue(i) > 0.4:
                x, y, z = points.GetPoint(i)
                ring = ((x * x + y * y) ** 0.5 - 2.0) ** 2 + z * z
                self.assertLess(abs(ring ** 0.5 + radius.GetValue(i) - 0.5), 0.02)
        writer = medialaxis.vtkMedialAxisWriter()
        writer.SetInputConnection(voronoi.GetOutputPort())
        writer.SetFileName(self.path("torus.ma"))
        self.assertEqual(writer.Write(), 1)

    def test_open_surface_is_refused(self):
        sphere = vtk.vtkSphereSource()
        clip = vtk.vtkClipPolyData()  # cut a hole: the surface is open
        plane = vtk.vtkPlane()
        plane.SetNormal(0, 0, 1)
        plane.SetOrigin(0, 0, 0.4)
        clip.SetClipFunction(plane)
        clip.InsideOutOn()
        clip.SetInputConnection(sphere.GetOutputPort())
        validator = medialaxis.vtkMedialSurfaceValidator()
        errors = ErrorObserver().attach(validator)
        validator.SetInputConnection(clip.GetOutputPort())
        validator.Update()
        self.assertFalse(validator.GetValid())
        self.assertTrue(validator.GetErrorMessage().startswith("surface is not closed: "))
        self.assertGreater(validator.GetNumberOfBoundaryEdges(), 0)
        self.assertEqual(validator.GetOutput().GetNumberOfPoints(), 0)
        self.assertTrue(errors.messages)

    def test_one_click_filter_and_atlas_of_one_sphere(self):
        shape = medialaxis.vtkAnalyticShapeSource()
        shape.SetShapeToRoundedBox()
        shape.SetFilletRadius(0.2)
        shape.SetResolution(12)
        structural = medialaxis.vtkStructuralMedialAxis()
        structural.SetInputConnection(shape.GetOutputPort())
        structural.SetPresetToCAD()
        structural.SetNumberOfSamples(3000)
        structural.SetTargetNumberOfVertices(300)
        progress = []
        structural.AddObserver("ProgressEvent",
                               lambda obj, event: progress.append(obj.GetProgress()))
        structural.Update()
        mat = structural.GetOutput(0)
        self.assertEqual(mat.GetNumberOfPoints(), 300)
        self.assertGreater(mat.GetNumberOfPolys(), 0)
        fields = mat.GetFieldData()
        total = fields.GetArray("TotalSeconds").GetValue(0)
        stages = sum(fields.GetArray(name + "Seconds").GetValue(0) for name in (
            "Sampling", "RestrictedVoronoi", "VoronoiMedialAxis", "Simplification"))
        self.assertAlmostEqual(total, stages, places=12)
        self.assertEqual(fields.GetArray("Sites").GetValue(0), 3000)
        self.assertEqual(progress[-1], 1.0)
        # Fringe collapses: automatic by default, which leaves them off for
        # CAD parts and turns them on for organic shapes (targets of 200+).
        self.assertEqual(structural.GetFringeCollapses(), 2)
        self.assertEqual(fields.GetArray("FringeCollapsesUsed").GetValue(0), 0)
        organic = medialaxis.vtkStructuralMedialAxis()
        organic.SetInputConnection(shape.GetOutputPort())
        organic.SetPresetToOrganic()
        organic.SetNumberOfSamples(3000)
        organic.SetTargetNumberOfVertices(300)
        organic.Update()
        used = organic.GetOutput(0).GetFieldData().GetArray("FringeCollapsesUsed")
        self.assertEqual(used.GetValue(0), 1)
        organic.FringeCollapsesOff()
        organic.Update()
        used = organic.GetOutput(0).GetFieldData().GetArray("FringeCollapsesUsed")
        self.assertEqual(used.GetValue(0), 0)
        # The whole Atlas of sphere 0: cells of the correspondence output.
        atlas = medialaxis.vtkExtractMedialAtlas()
        atlas.SetInputConnection(0, structural.GetOutputPort(0))
        atlas.SetInputConnection(1, structural.GetOutputPort(1))
        atlas.SetMedialVertexId(0)
        atlas.Update()
        self.assertGreater(atlas.GetOutput().GetNumberOfCells(), 0)
        self.assertGreater(atlas.GetOutput().GetFieldData().GetArray("AtlasArea").GetValue(0), 0)

    def test_envelope_and_reconstruction_error(self):
        # A capsule's medial mesh: two spheres and the edge between them.
        text = "2 1 0\nv 0 0 -1 0.5\nv 0 0 1 0.5\ne 0 1\n"
        with open(self.path("capsule.ma"), "w") as f:
            f.write(text)
        mat = medialaxis.vtkMedialAxisReader()
        mat.SetFileName(self.path("capsule.ma"))

        envelope = medialaxis.vtkSlabReconstructor()
        envelope.SetInputConnection(mat.GetOutputPort())
        envelope.SetModeToBoundary()
        envelope.SetBoundaryResolution(48)
        edges = vtk.vtkFeatureEdges()  # a closed surface: no boundary edges
        edges.SetInputConnection(envelope.GetOutputPort())
        edges.BoundaryEdgesOn()
        edges.NonManifoldEdgesOn()
        edges.FeatureEdgesOff()
        edges.ManifoldEdgesOff()
        edges.Update()
        self.assertGreater(envelope.GetOutput().GetNumberOfPolys(), 1000)
        self.assertEqual(edges.GetOutput().GetNumberOfCells(), 0)
        self.assertEqual(envelope.GetModeAsString(), "boundary")
        envelope.SetModeToPrimitives()
        envelope.Update()
        kinds = envelope.GetOutput().GetCellData().GetArray("PrimitiveKind")
        self.assertEqual(kinds.GetRange(), (0.0, 1.0))  # balls and one cone

        # The capsule surface measured against a medial mesh whose radius is
        # 10% too large: the error is the radius difference, 0.05.
        shape = medialaxis.vtkAnalyticShapeSource()
        shape.SetShapeToCapsule()
        shape.SetRadius(0.5)
        shape.SetLength(2.0)
        shape.SetResolution(48)
        radius = mat.GetOutput().GetPointData().GetArray("Radius")
        wrong = vtk.vtkPolyData()
        wrong.DeepCopy(mat.GetOutput())
        wrong.GetPointData().GetArray("Radius").SetValue(0, 0.55)
        wrong.GetPointData().GetArray("Radius").SetValue(1, 0.55)
        self.assertEqual(radius.GetValue(0), 0.5)
        error = medialaxis.vtkMedialReconstructionError()
        error.SetInputConnection(0, shape.GetOutputPort())
        error.SetInputData(1, wrong)
        error.SetNumberOfSamples(20000)
        error.SetNumberOfEnvelopeSamples(20000)
        error.Update()
        self.assertAlmostEqual(error.GetHausdorff(), 0.05, delta=0.001)
        surface = error.GetOutput()
        fields = surface.GetFieldData()
        self.assertAlmostEqual(fields.GetArray("HausdorffSurfaceToEnvelope").GetValue(0), 0.05,
                               delta=0.001)
        self.assertAlmostEqual(fields.GetArray("Mean").GetValue(0), 0.05, delta=0.001)
        diagonal = fields.GetArray("BoundingBoxDiagonal").GetValue(0)
        self.assertAlmostEqual(fields.GetArray("HausdorffPercent").GetValue(0),
                               100 * error.GetHausdorff() / diagonal)
        distance = surface.GetPointData().GetArray("Distance")
        self.assertEqual(distance.GetNumberOfTuples(), surface.GetNumberOfPoints())
        self.assertAlmostEqual(distance.GetRange()[1], 0.05, delta=1e-9)
        samples = error.GetOutputDataObject(1)
        self.assertEqual(samples.GetNumberOfPoints(), 20000)
        self.assertIsNotNone(samples.GetPointData().GetArray("Distance"))
        # The envelope-to-surface maximum is raised by local searches, never
        # below the samples' own maximum, and located.
        self.assertEqual(error.GetMaximumSearches(), 16)
        self.assertGreaterEqual(fields.GetArray("HausdorffEnvelopeToSurface").GetValue(0),
                                samples.GetPointData().GetArray("Distance").GetRange()[1])
        self.assertEqual(fields.GetArray("FarthestEnvelopePoint").GetNumberOfComponents(), 3)

        # A medial mesh without radii is refused with a clear message.
        bad = vtk.vtkPolyData()
        bad.DeepCopy(mat.GetOutput())
        bad.GetPointData().RemoveArray("Radius")
        refused = medialaxis.vtkMedialReconstructionError()
        errors = ErrorObserver().attach(refused)
        refused.SetInputConnection(0, shape.GetOutputPort())
        refused.SetInputData(1, bad)
        refused.Update()
        self.assertTrue(errors.messages)
        self.assertEqual(refused.GetOutput().GetNumberOfPoints(), 0)


if __name__ == "__main__":
    unittest.main()
