# SPDX-License-Identifier: GPL-3.0-or-later
"""The medial-axis command-line tool: options, exit codes, outputs, report."""
import json
import os
import subprocess
import tempfile
import unittest

import vtk

import medialaxis
import bad_inputs

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
        result = run("--feature-filtering", "1.5", "a", "b")
        self.assertEqual(result.returncode, 2)
        self.assertIn("--feature-filtering must be a whole number from 0 to 100", result.stderr)
        for bad in ("0", "-1%", "150%", "half"):
            result = run("--max-error", bad, "a", "b")
            self.assertEqual(result.returncode, 2, bad)
            self.assertIn("--max-error", result.stderr)
        for option, bad in (("--hair-angle", "-1"), ("--hair-angle", "91"),
                            ("--pleat-angle", "5"), ("--fin-budget", "11%"),
                            ("--fin-budget", "wide")):
            result = run(option, bad, "a", "b")
            self.assertEqual(result.returncode, 2, (option, bad))
            self.assertIn(option, result.stderr)

    def run_on_sphere(self, *options, target):
        """Runs the tool on a tessellated sphere with `options`; checks that it
        succeeds with a valid medial mesh of `target` spheres and returns
        the report."""
        report = self.path("report.json")
        result = run("--quiet", *options, "--samples", "2000", "--target", str(target),
                     "--report", report, self.write_sphere("sphere.vtp"), self.path("out"))
        self.assertEqual(result.returncode, 0, result.stderr)
        with open(report) as f:
            data = json.load(f)
        self.assertEqual(data["counts"]["vertices"], target)
        self.assertTrue(data["valid"])
        # The report names the code that made it, as --version does.
        version = run("--version")
        self.assertEqual(version.returncode, 0)
        self.assertRegex(version.stdout, r"^medial-axis \d+\.\d+\.\d+ \(commit [0-9a-z-]+\)$")
        self.assertIn("medial-axis %s (commit %s)" % (data["version"], data["commit"]),
                      version.stdout)
        return data

    def test_qmat_strategy(self):
        data = self.run_on_sphere("--strategy", "qmat", target=50)
        self.assertEqual(data["parameters"]["strategy"], "qmat")
        self.assertTrue(os.path.exists(self.path("out/mat.ma")))
        result = run("--strategy", "qem", self.path("sphere.vtp"), self.path("out2"))
        self.assertEqual(result.returncode, 2)
        self.assertIn("--strategy must be structural or qmat", result.stderr)

    def test_clamp_radii_and_absorb_spikes(self):
        # The options reach the simplifier and are reported.
        data = self.run_on_sphere("--clamp-radii", "--no-fit", target=20)
        self.assertTrue(data["parameters"]["clamp_radii_to_atlas"])
        self.assertFalse(data["parameters"]["absorb_spikes"])
        data = self.run_on_sphere("--absorb-spikes", target=20)
        self.assertTrue(data["parameters"]["absorb_spikes"])
        self.assertFalse(data["parameters"]["clamp_radii_to_atlas"])

    def test_unreadable_and_invalid_input(self):
        result = run(self.path("missing.obj"), self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("no such file", result.stderr)
        result = run(self.write_sphere("open.vtp", open_surface=True), self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("not closed", result.stderr)
        self.assertNotIn("vtkExecutive", result.stderr)  # no VTK log noise

    def test_self_intersecting_input(self):
        # Two boxes exported as one surface: resolved into their union by
        # default (the report says so; the correspondence names the input's
        # triangles), refused with --no-repair.
        import repair_shapes
        path = self.path("boxes.vtp")
        writer = vtk.vtkXMLPolyDataWriter()
        writer.SetInputData(repair_shapes.overlapping_boxes())
        writer.SetFileName(path)
        self.assertEqual(writer.Write(), 1)
        report = self.path("boxes.json")
        result = run("--samples", "3000", "--target", "200", "--correspondence", "--report",
                     report, path, self.path("out"))
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("18 pairs of crossing triangles resolved", result.stdout)
        self.assertIn("Euler characteristic 1", result.stdout)
        with open(report) as f:
            data = json.load(f)
        self.assertEqual(data["repair"], {"repaired": True, "crossing_pairs": 18,
                                          "removed_area": 2.5, "method": "resolved crossings",
                                          "deviation": 0})
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(self.path("out/correspondence.vtp"))
        reader.Update()
        ids = reader.GetOutput().GetCellData().GetArray("InputTriangleId")
        self.assertIsNotNone(ids)
        self.assertEqual(ids.GetRange(), (0.0, 23.0))
        result = run("--no-repair", path, self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("of separate shells cross", result.stderr)

    def test_every_documented_bad_input(self):
        # Each gives exit code 3 and one line naming the problem; none crashes.
        cube_v = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
        cube_f = ("f 1 3 4\nf 1 4 2\nf 5 6 8\nf 5 8 7\nf 1 2 6\nf 1 6 5\n"
                  "f 3 7 8\nf 3 8 4\nf 1 5 7\nf 1 7 3\nf 2 4 8\nf 2 8 6\n")
        cases = {
            "empty.obj": ("", "no points"),
            "open.obj": (cube_v + cube_f.rsplit("f", 1)[0], "not closed"),
            # A fin: a third triangle on the cube's edge 1-2.
            "fin.obj": (cube_v + "v 0.5 -1 0\n" + cube_f + "f 1 2 9\n", "more than two triangles"),
            "nan.obj": (cube_v.replace("v 1 1 1", "v nan 1 1") + cube_f, "NaN"),
            "bad.off": ("OFF\n8 12\n0 0 0\n", "line"),
            "bad.obj": (cube_v + "f 1 x 4\n", "line"),
            "surface.xyz": (cube_v, "extension"),
        }
        for name, (text, expected) in cases.items():
            with open(self.path(name), "w") as f:
                f.write(text)
            result = run(self.path(name), self.path("out"))
            self.assertEqual(result.returncode, 3, name + ": " + result.stderr)
            self.assertEqual(len(result.stderr.strip().splitlines()), 1, name + ": " + result.stderr)
            self.assertIn(expected.lower(), result.stderr.lower(), name + ": " + result.stderr)
        result = run(self.path("does-not-exist.stl"), self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("no such file", result.stderr)

    def test_bad_inputs_give_a_result_or_a_clear_error(self):
        """The bad inputs of docs/robustness.md (the corpus in bad_inputs.py, shared with the
        Python API test) through the tool: each is either computed (exit 0,
        the medial mesh checked) or refused (exit 3) with a message naming
        the defect."""
        settings = ["--samples", str(bad_inputs.SAMPLES), "--target", str(bad_inputs.TARGET),
                    "--quiet"]

        def medial_axis(name):
            out = self.path("out_" + name)
            result = run(*settings, self.path(name), out)
            self.assertEqual(result.returncode, 0, result.stderr)
            reader = medialaxis.vtkMedialAxisReader()
            reader.SetFileName(os.path.join(out, "mat.ma"))
            reader.Update()
            return reader.GetOutput()

        bad_inputs.write_surface(bad_inputs.sphere(), self.path("sphere.vtp"))
        reference = medial_axis("sphere.vtp")
        self.assertEqual(reference.GetNumberOfPoints(), bad_inputs.TARGET)
        for case in bad_inputs.CASES:
            with self.subTest(case.name):
                bad_inputs.write(case, self.path(case.name))
                if case.refused:
                    result = run(*settings, self.path(case.name), self.path("out"))
                    self.assertEqual(result.returncode, 3, result.stderr)
                    self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)
                    self.assertIn(case.refused, result.stderr)
                else:
                    mat = medial_axis(case.name)
                    self.assertEqual(mat.GetNumberOfPoints(), bad_inputs.TARGET)
                    self.assertEqual(case.check(mat, reference), [])
        # A surface of flat triangles that cannot be absorbed (four vertices
        # on one line) is left open.
        with open(self.path("collinear.off"), "w") as f:
            f.write("OFF\n6 8 0\n1 1.984375 0\n0 0 2.109375\n0 0 0\n4.21875 0 0\n"
                    "0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n"
                    "3 3 1 5\n3 0 3 5\n")
        result = run(*settings, self.path("collinear.off"), self.path("out"))
        self.assertEqual(result.returncode, 3, result.stderr)
        self.assertIn("surface is not closed", result.stderr)

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
        self.assertEqual(data["parameters"]["feature_normal_filtering"], 3)
        self.assertTrue(data["parameters"]["adaptive_sampling"])  # the organic preset's
        self.assertEqual(data["parameters"]["max_error"], 0)  # the vertex target
        self.assertEqual(data["counts"]["error_target_evaluations"], 0)
        self.assertEqual(data["counts"]["sites"], 3000)
        self.assertEqual(data["counts"]["vertices"], 50)
        self.assertEqual(data["triangle_quality"]["degenerate"], 0)
        clean = data["cleanliness"]
        for key in ("sheets", "n80", "largest_sheet_area_percent", "fin_area_percent",
                    "folds_percent", "junction_edges", "boundary_length_diagonals",
                    "junction_length_diagonals"):
            self.assertIn(key, clean)
        self.assertLessEqual(clean["n80"], clean["sheets"])
        self.assertEqual(data["parameters"]["hair_angle"], 45)
        self.assertEqual(data["parameters"]["pleat_angle"], 90)
        self.assertIn("sheets:", result.stdout)
        self.assertGreater(data["seconds"]["Total"], 0.0)
        self.assertGreater(data["peak_memory_mb"], 10.0)
        # A sphere's medial axis is its centre: the envelope of 50 spheres
        # around it stays within a few percent of the diagonal.
        self.assertLess(data["hausdorff"]["two_sided_percent"], 5.0)
        self.assertGreater(data["hausdorff"]["two_sided_percent"], 0.0)

    def test_automatic_preset(self):
        # A sharp box is a CAD part (its 12 edges: 12 / sqrt(area) = 4.9 for a
        # cube); a sphere is organic. The choice and its measure are reported.
        cube = vtk.vtkCubeSource()
        cube.Update()
        triangles = vtk.vtkTriangleFilter()
        triangles.SetInputConnection(cube.GetOutputPort())
        clean = vtk.vtkCleanPolyData()  # the cube source's faces have their own points
        clean.SetInputConnection(triangles.GetOutputPort())
        writer = vtk.vtkXMLPolyDataWriter()
        writer.SetInputConnection(clean.GetOutputPort())
        writer.SetFileName(self.path("cube.vtp"))
        self.assertEqual(writer.Write(), 1)
        for surface, preset, sharp in ((self.path("cube.vtp"), "cad", True),
                                       (self.write_sphere("sphere.vtp"), "organic", False)):
            report = self.path("report.json")
            result = run("--quiet", "--preset", "auto", "--samples", "1000", "--target", "50",
                         "--report", report, surface, self.path("out"))
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("preset: " + preset, result.stdout)
            with open(report) as f:
                data = json.load(f)
            self.assertEqual(data["preset"], preset)
            self.assertEqual(data["preset_chosen"], "auto")
            self.assertEqual(data["parameters"]["preserve_sharp_features"], sharp)
            self.assertEqual(data["surface"]["triangles"] == 12, sharp)
            ratio = data["sharp_edges"]["crease_ratio"]
            self.assertAlmostEqual(ratio, 12 / 6 ** 0.5 if sharp else 0.0, delta=1e-6)
        result = run("--preset", "cad", "--samples", "1000", "--target", "50", "--report",
                     report, self.path("cube.vtp"), self.path("out"))
        with open(report) as f:
            data = json.load(f)
        self.assertEqual((data["preset"], data["preset_chosen"]), ("cad", "given"))
        self.assertNotIn("sharp_edges", data)

    def test_unsigned_distance_field(self):
        # A disk's unsigned distance as .vti and as .npy (a[i, j, k], x along
        # i): the same surface from both, one boundary loop.
        import numpy as np
        from vtk.util.numpy_support import vtk_to_numpy
        disk = vtk.vtkDiskSource()
        disk.SetInnerRadius(0.0)
        disk.SetCircumferentialResolution(64)
        disk.SetRadialResolution(16)
        source = medialaxis.vtkUnsignedDistanceSource()
        source.SetInputConnection(disk.GetOutputPort())
        source.SetSamplingDimensions(48, 48, 48)
        source.Update()
        image = source.GetOutput()
        writer = vtk.vtkXMLImageDataWriter()
        writer.SetInputData(image)
        writer.SetFileName(self.path("disk.vti"))
        self.assertEqual(writer.Write(), 1)
        values = vtk_to_numpy(image.GetPointData().GetArray("UnsignedDistance"))
        np.save(self.path("disk.npy"), values.reshape(48, 48, 48).transpose(2, 1, 0))
        spacing = image.GetSpacing()[0]
        origin = [str(x) for x in image.GetOrigin()]
        counts = []
        for field, extra in (("disk.vti", []),
                             ("disk.npy", ["--spacing", repr(spacing), "--origin"] + origin)):
            report = self.path("udf.json")
            result = run("--udf", *extra, "--report", report, self.path(field), self.path("out"))
            self.assertEqual(result.returncode, 0, result.stderr)
            self.assertIn("1 boundary loops", result.stdout)
            with open(report) as f:
                data = json.load(f)
            self.assertAlmostEqual(data["epsilon"], 2 * spacing, delta=1e-9)
            self.assertEqual(data["counts"]["boundary_loops"], 1)
            # No flap left folded on a junction edge along the coarse rim.
            self.assertEqual(data["counts"]["junction_edges"], 0)
            self.assertTrue(os.path.getsize(self.path("out/surface.vtp")) > 0)
            counts.append(data["counts"]["triangles"])
        self.assertEqual(counts[0], counts[1])
        # Bad fields and arguments.
        result = run("--udf", self.path("disk.npy"), self.path("out"))
        self.assertEqual(result.returncode, 2)
        self.assertIn("--spacing", result.stderr)
        result = run("--udf", "--epsilon", repr(0.5 * spacing), self.path("disk.vti"),
                     self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("below the grid's spacing", result.stderr)
        np.save(self.path("signed.npy"), values.reshape(48, 48, 48) - 0.1)
        result = run("--udf", "--spacing", "0.1", self.path("signed.npy"), self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("negative values", result.stderr)
        np.save(self.path("flat.npy"), values.reshape(48, 2304))
        result = run("--udf", "--spacing", "0.1", self.path("flat.npy"), self.path("out"))
        self.assertEqual(result.returncode, 3)
        self.assertIn("a 3-D array is needed", result.stderr)

    def test_mid_surface(self):
        # A T-plate (plate 2 x 2, rib 1 high, walls 0.1 thick): two walls, the
        # plate's and the rib's, 0.1 thick, stitched along the junction.
        writer = vtk.vtkXMLPolyDataWriter()
        source = medialaxis.vtkAnalyticShapeSource()
        source.SetShapeToTPlate()
        source.SetXLength(2.0)
        source.SetYLength(2.0)
        source.SetZLength(1.0)
        source.SetThickness(0.1)
        source.SetFilletRadius(0.0)  # sharp: the same thickness everywhere
        writer.SetInputConnection(source.GetOutputPort())
        writer.SetFileName(self.path("tplate.vtp"))
        self.assertEqual(writer.Write(), 1)
        out = self.path("out")
        report = self.path("report.json")
        result = run("--preset", "cad", "--mid-surface", "--report", report,
                     self.path("tplate.vtp"), out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("mid-surface: 2 walls", result.stdout)
        with open(report) as f:
            data = json.load(f)
        mid = data["mid_surface"]
        self.assertEqual(mid["walls"], 2)
        self.assertAlmostEqual(mid["wall_thickness"], 0.1, delta=0.01)
        self.assertGreater(mid["junction_edges"], 0)
        self.assertGreater(data["seconds"]["MidSurface"], 0.0)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(out, "mid_surface.vtp"))
        reader.Update()
        surface = reader.GetOutput()
        self.assertEqual(surface.GetNumberOfPolys(), mid["triangles"])
        thickness = surface.GetPointData().GetArray("Thickness")
        self.assertAlmostEqual(thickness.GetRange()[0], 0.1, delta=0.001)
        self.assertAlmostEqual(thickness.GetRange()[1], 0.1, delta=0.001)
        self.assertIsNotNone(surface.GetCellData().GetArray("WallId"))

    def test_skeletal_diagram(self):
        # A dumbbell (balls of radius 0.25, 1.2 pole to pole, neck 0.1): a
        # few skeletal elements along its axis cover it within 0.5%.
        writer = vtk.vtkXMLPolyDataWriter()
        source = medialaxis.vtkAnalyticShapeSource()
        source.SetShapeToDumbbell()
        source.SetLength(1.2)
        source.SetRadius(0.25)
        source.SetMinorRadius(0.1)
        writer.SetInputConnection(source.GetOutputPort())
        writer.SetFileName(self.path("dumbbell.vtp"))
        self.assertEqual(writer.Write(), 1)
        out = self.path("out")
        report = self.path("report.json")
        result = run("--samples", "5000", "--target", "100", "--skeletal-diagram", "20",
                     "--curve-skeleton", "--error", "--report", report,
                     self.path("dumbbell.vtp"), out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("skeletal diagram:", result.stdout)
        with open(report) as f:
            data = json.load(f)
        diagram = data["skeletal_diagram"]
        self.assertGreaterEqual(diagram["vertices"], 2)
        self.assertLessEqual(diagram["vertices"] + diagram["edges"] + diagram["triangles"], 20)
        self.assertLessEqual(diagram["error"], 0.005)
        self.assertEqual(diagram["failed_elements"], 0)
        self.assertGreater(data["seconds"]["SkeletalDiagram"], 0.0)
        reader = vtk.vtkXMLPolyDataReader()
        reader.SetFileName(os.path.join(out, "primitives.vtp"))
        reader.Update()
        element_type = reader.GetOutput().GetCellData().GetArray("ElementType")
        self.assertEqual(element_type.GetRange()[0], 0)
        self.assertEqual(reader.GetOutput().GetPointData().GetArray("Radius").GetNumberOfTuples(),
                         reader.GetOutput().GetNumberOfPoints())
        skeleton = vtk.vtkXMLPolyDataReader()
        skeleton.SetFileName(os.path.join(out, "skeleton.vtp"))
        skeleton.Update()
        # Its points: the vertices, then the bends of edges routed inside.
        self.assertEqual(skeleton.GetOutput().GetFieldData().GetArray("Vertices").GetValue(0),
                         diagram["vertices"])
        self.assertGreaterEqual(skeleton.GetOutput().GetNumberOfPoints(), diagram["vertices"])
        self.assertEqual(diagram["omitted_triangles"], 0)
        # The primitives' union as one closed surface, measured against the
        # dumbbell like the MAT's envelope.
        union = vtk.vtkXMLPolyDataReader()
        union.SetFileName(os.path.join(out, "reconstruction.vtp"))
        union.Update()
        self.assertGreater(union.GetOutput().GetNumberOfPolys(), 0)
        self.assertLessEqual(diagram["hausdorff"]["two_sided_percent"], 1.0)
        self.assertLess(diagram["hausdorff"]["mean_two_sided_percent"],
                        diagram["hausdorff"]["two_sided_percent"])
        self.assertGreater(diagram["continuous_parameters"], 3 * diagram["vertices"])
        self.assertGreater(data["hausdorff"]["mean_two_sided"], 0.0)
        # The curve skeleton: one branch along the axis, no loop, as files
        # and as a graph.
        curve = data["curve_skeleton"]
        self.assertEqual((curve["cycle_rank"], curve["components"]), (0, 1))
        self.assertIn("curve skeleton:", result.stdout)
        with open(os.path.join(out, "curve_skeleton.swc")) as f:
            nodes = [line.split() for line in f if line.strip() and not line.startswith("#")]
        self.assertEqual(len(nodes), curve["nodes"])
        self.assertEqual(sum(1 for n in nodes if n[6] == "-1"), 1)
        self.assertTrue(all(float(n[5]) > 0.0 for n in nodes))
        with open(os.path.join(out, "curve_skeleton.json")) as f:
            self.assertEqual(len(json.load(f)["nodes"]), curve["nodes"])
        lines = vtk.vtkXMLPolyDataReader()
        lines.SetFileName(os.path.join(out, "curve_skeleton.vtp"))
        lines.Update()
        try:
            import networkx
        except ImportError:
            with self.assertRaisesRegex(ImportError, "python3-networkx"):
                medialaxis.skeleton_graph(lines.GetOutput())
        else:
            graph = medialaxis.skeleton_graph(lines.GetOutput())
            self.assertEqual(graph.number_of_nodes(), curve["nodes"])
            self.assertTrue(networkx.is_tree(graph))
            self.assertGreater(graph.nodes[0]["radius"], 0.0)
        with self.assertRaisesRegex(ValueError, "not a curve skeleton"):
            medialaxis.skeleton_graph(union.GetOutput())
        # A count that is no whole number is refused.
        refused = run("--skeletal-diagram", "0", self.path("dumbbell.vtp"), out)
        self.assertNotEqual(refused.returncode, 0)
        self.assertIn("--skeletal-diagram must be a whole number", refused.stderr)

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
        result = run("--preset", "cad", "--fillets", "--structure", "--report", report,
                     "--screenshot", picture, self.path("box.vtp"), out)
        self.assertEqual(result.returncode, 0, result.stderr)
        self.assertIn("12 fillets", result.stdout)
        for name in ("fillets.vtp", "fillet_faces.vtp"):
            self.assertTrue(os.path.getsize(os.path.join(out, name)) > 0, name)
        with open(report) as f:
            data = json.load(f)
        self.assertEqual(len(data["fillets"]), 12)
        self.assertFalse(data["parameters"]["adaptive_sampling"])  # the CAD preset's
        for fillet in data["fillets"]:
            self.assertAlmostEqual(fillet["mean_radius"], 0.1, delta=0.003)
            self.assertAlmostEqual(fillet["length"], 1.8, delta=0.06)
        self.assertGreater(data["seconds"]["Fillets"], 0.0)
        # Its structure: the cube's twelve sheets (one per edge) meet on eight
        # seams from the corners at one junction; the centre lines are fillets.
        for name in ("structure.vtp", "seams.vtp"):
            self.assertTrue(os.path.getsize(os.path.join(out, name)) > 0, name)
        structure = data["structure"]
        self.assertEqual((structure["sheets"], structure["seams"]), (12, 8))
        self.assertEqual(structure["spheres"]["junction"], 1)
        self.assertGreater(structure["spheres"]["fillet"], 100)
        self.assertEqual(sum(structure["spheres"].values()), data["counts"]["vertices"])
        self.assertGreater(structure["tangent_component_agreement"], 0.99)
        self.assertIn("12 sheets, 8 seams", result.stdout)
        # The picture: a PNG of the requested size, not blank.
        reader = vtk.vtkPNGReader()
        reader.SetFileName(picture)
        reader.Update()
        self.assertEqual(reader.GetOutput().GetDimensions()[:2], (1200, 900))
        scalars = reader.GetOutput().GetPointData().GetScalars()
        self.assertGreater(scalars.GetRange(0)[1] - scalars.GetRange(0)[0], 100)


if __name__ == "__main__":
    unittest.main()
