# SPDX-License-Identifier: GPL-3.0-or-later
"""Surfaces from unsigned distance fields against their truths: for each
generated case (disk, hemisphere, Moebius strip, three half-planes on a
line, a cut sleeve with a collar), sample the exact UDF on an N^3 grid,
extract the surface and print the two-sided Hausdorff and Chamfer distances
to the truth (in grid spacings), boundary loops and junction edges against
the truth's, second layers within 2 epsilon, and the times.

--function gives the extractor the distance as a Python function instead of
a sampled field: the closed form where there is one (disk, hemisphere,
half-planes), else the exact distance to the truth's triangles
(vtkImplicitPolyDataDistance); "UDF s" is then 0 and the function's
evaluations count in the extraction.

    PYTHONPATH=build/vtk/lib/python3/dist-packages python3 Benchmarks/udf_cases.py [--resolution N] [--snap] [--function]
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "Testing", "Python"))
import medialaxis  # noqa: E402
import udf_shapes  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--resolution", type=int, default=128)
parser.add_argument("--snap", action="store_true")
parser.add_argument("--function", action="store_true")
parser.add_argument("cases", nargs="*", default=list(udf_shapes.SHAPES))
args = parser.parse_args()

print("| case | triangles | Hausdorff (spacings) | Chamfer (spacings) | boundary loops (truth) "
      "| junction edges (truth) | junction length (truth) | junction offset (spacings) "
      "| second layers | UDF s | extraction s |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for name in args.cases:
    truth = udf_shapes.SHAPES[name]()
    start = time.perf_counter()
    extractor = medialaxis.vtkUnsignedDistanceSurfaceExtractor()
    if args.function:
        distance, bounds = udf_shapes.EXACT_DISTANCES.get(
            name, (udf_shapes.mesh_distance(truth), truth.GetBounds()))
        medialaxis.set_distance_function(extractor, distance, bounds)
        extractor.SetResampleDimension(args.resolution)
    else:
        source = medialaxis.vtkUnsignedDistanceSource()
        source.SetInputData(truth)
        source.SetSamplingDimensions(args.resolution, args.resolution, args.resolution)
        source.Update()
        extractor.SetInputConnection(source.GetOutputPort())
    sampled = time.perf_counter()
    extractor.SetSnapToZeroSet(args.snap)
    extractor.Update()
    done = time.perf_counter()
    surface = extractor.GetOutput()
    spacing = extractor.GetUsedEpsilon() / 2
    hausdorff, chamfer = udf_shapes.compare(surface, truth)
    loops, junctions = udf_shapes.edge_counts(surface)
    truth_loops, truth_junctions = udf_shapes.edge_counts(truth)
    doubled, probed = udf_shapes.double_layer_triangles(surface, extractor.GetUsedEpsilon())
    print("| %s | %d | %.3f | %.4f | %d (%d) | %d (%d) | %.3f (%.3f) | %.3f | %d of %d | %.1f "
          "| %.1f |" % (name, surface.GetNumberOfPolys(), hausdorff / spacing, chamfer / spacing,
                        loops, truth_loops, junctions, truth_junctions,
                        udf_shapes.junction_length(surface), udf_shapes.junction_length(truth),
                        udf_shapes.junction_offset(surface, truth) / spacing, doubled, probed,
                        sampled - start, done - sampled), flush=True)
