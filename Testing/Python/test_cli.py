# SPDX-License-Identifier: GPL-3.0-or-later
"""The medial-axis command-line tool: options, exit codes, outputs, report."""
import json
import os
import subprocess
import tempfile
import unittest

import vtk

import medialaxis

TOOL = os.environ["MEDIALAXIS_TOOL"]


def run(*args):
    return subprocess.run([TOOL, *args], capture_output=True, text=True, timeout=600)


class CommandLineTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def path(self, name):
        return os.path.join(self.tmp.name, name)

    def write_sphere(self, name, open_surface=False):
        sphere = vtk.vtkSphereSource()
        sphere.SetThetaResolution(32)
        sphere.SetPhiResolution(24)
        sphere.Update()
        surface = sphere.GetOutput()
        if open_surface:
            surface.BuildCells()
            surface.DeleteCell(0)
            surface.RemoveDeletedCells()
        writer = vtk.vtkXMLPolyDataWriter()
        writer.SetInputData(surface)
        writer.SetFileName(self.path(name))
        self.assertEqual(writer.Write(), 1)
        return self.path(name)

    def test_help_and_bad_arguments(self):
        result = run("--help")
        self.assertEqual(result.returncode, 0)
        for option in ("--preset", "--samples", "--target", "--envelope", "--error", "--report"):
            self.assertIn(option, result.stdout)
        self.assertEqual(run().returncode, 2)
        result = run("--frobnicate", "a", "b")
        self.assertEqual(result.returncode, 2)
        self.assertIn("unknown option --frobnicate", result.stderr)
        result = run("--samples", "many", "a", "b")
        self.assertEqual(result.returncode, 2)
        self.assertIn("--samples needs a number", result.stderr)
        self.assertEqual(run("--preset", "blob", "a", "b").returncode, 2)

    def test_unreadable_and_invalid_input(self):
        result = run(self.path("missing.obj"), self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("no such file", result.stderr)
        result = run(self.write_sphere("open.vtp", open_surface=True), self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("not closed", result.stderr)
        self.assertNotIn("vtkExecutive", result.stderr)  # no VTK log noise

    def test_outputs_and_report(self):
        out = self.path("out")
        report = self.path("report.json")
        result = run("--samples", "3000", "--target", "50", "--envelope", "--correspondence",
                     "--error", "--report", report, self.write_sphere("sphere.vtp"), out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertEqual(result.stderr, "")  # no progress bar when not on a terminal
        for name in ("mat.ma", "mat.vtp", "envelope.vtp", "correspondence.vtp", "distance.vtp"):
            self.assertTrue(os.path.getsize(os.path.join(out, name)) > 0, name)
        with open(os.path.join(out, "mat.ma")) as f:
            self.assertEqual(f.readline().split()[0], "50")
        with open(report) as f:
            data = json.load(f)
        self.assertEqual(data["parameters"]["samples"], 3000)
        self.assertEqual(data["counts"]["sites"], 3000)
        self.assertEqual(data["counts"]["vertices"], 50)
        self.assertEqual(data["triangle_quality"]["degenerate"], 0)
        self.assertGreater(data["seconds"]["Total"], 0.0)
        self.assertGreater(data["peak_memory_mb"], 10.0)
        # A sphere's medial axis is its centre: the envelope of 50 spheres
        # around it stays within a few percent of the diagonal.
        self.assertLess(data["hausdorff"]["two_sided_percent"], 5.0)
        self.assertGreater(data["hausdorff"]["two_sided_percent"], 0.0)

    def test_fillets(self):
        # A box with rounded edges (radius 0.1, side 2): 12 fillets, each a
        # centre line of length 1.8 with radius 0.1.
        box = vtk.vtkXMLPolyDataWriter()
        source = medialaxis.vtkAnalyticShapeSource()
        source.SetShapeToRoundedBox()
        source.SetFilletRadius(0.1)
        box.SetInputConnection(source.GetOutputPort())
        box.SetFileName(self.path("box.vtp"))
        self.assertEqual(box.Write(), 1)
        out = self.path("out")
        report = self.path("report.json")
        picture = self.path("box.png")
        result = run("--preset", "cad", "--fillets", "--report", report, "--screenshot", picture,
                     self.path("box.vtp"), out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("12 fillets", result.stdout)
        for name in ("fillets.vtp", "fillet_faces.vtp"):
            self.assertTrue(os.path.getsize(os.path.join(out, name)) > 0, name)
        with open(report) as f:
            data = json.load(f)
        self.assertEqual(len(data["fillets"]), 12)
        for fillet in data["fillets"]:
            self.assertAlmostEqual(fillet["mean_radius"], 0.1, delta=0.003)
            self.assertAlmostEqual(fillet["length"], 1.8, delta=0.06)
        self.assertGreater(data["seconds"]["Fillets"], 0.0)
        # The picture: a PNG of the requested size, not blank.
        reader = vtk.vtkPNGReader()
        reader.SetFileName(picture)
        reader.Update()
        self.assertEqual(reader.GetOutput().GetDimensions()[:2], (1200, 900))
        scalars = reader.GetOutput().GetPointData().GetScalars()
        self.assertGreater(scalars.GetRange(0)[1] - scalars.GetRange(0)[0], 100)


if __name__ == "__main__":
    unittest.main()
