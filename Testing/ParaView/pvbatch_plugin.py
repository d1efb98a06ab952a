# SPDX-License-Identifier: GPL-3.0-or-later
"""pvbatch: load the MedialAxis plugin, read a .ma file, run its filters."""
import os
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

plugin, data_dir, mesh_dir = sys.argv[1], sys.argv[2], sys.argv[3]
LoadPlugin(plugin, remote=False, ns=globals())


def check(condition, message):
    if not condition:
        raise AssertionError(message)


# The reader is registered for *.ma: OpenDataFile picks it by extension.
ma_path = os.path.join(data_dir, "slab_and_cone.ma")
reader = OpenDataFile(ma_path)
check(reader is not None, "no reader registered for .ma")
check(reader.GetXMLName() == "MedialAxisReader", "wrong reader: " + reader.GetXMLName())
reader.UpdatePipeline()
mat = servermanager.Fetch(reader)
check(mat.GetNumberOfPoints() == 5, "expected 5 spheres, got %d" % mat.GetNumberOfPoints())
check(mat.GetNumberOfPolys() == 1, "expected 1 slab")
check(mat.GetNumberOfLines() == 1, "expected 1 cone")
check(mat.GetNumberOfVerts() == 1, "expected 1 isolated sphere")
radius = mat.GetPointData().GetArray("Radius")
check(radius is not None and radius.GetRange() == (0.2, 1.0), "Radius array wrong")
check(reader.PointData["Radius"].GetRange() == (0.2, 1.0), "Radius not exposed to ParaView")

# The writer is registered for *.ma too: write, read back, compare.
with tempfile.TemporaryDirectory() as tmp:
    out = os.path.join(tmp, "copy.ma")
    SaveData(out, proxy=reader)
    again = servermanager.Fetch(MedialAxisReader(FileName=out))
    check(again.GetNumberOfPoints() == 5 and again.GetNumberOfPolys() == 1,
          "write-then-read changed the mesh")

    off = os.path.join(tmp, "tet.off")
    with open(off, "w") as f:
        f.write("OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")
    tet = OpenDataFile(off)
    check(tet.GetXMLName() == "OFFReader", "wrong reader for .off: " + tet.GetXMLName())
    check(servermanager.Fetch(tet).GetNumberOfPolys() == 4, "OFF reader lost faces")

# Source and filter from the plugin, as a user would chain them.
shape = MedialTestShape(Shape="Rounded Box", FilletRadius=0.3, Resolution=8)
validated = ValidateSurface(Input=shape)
validated.UpdatePipeline()
surface = servermanager.Fetch(validated)
check(surface.GetNumberOfPolys() > 0, "validated surface is empty")
volume = surface.GetFieldData().GetArray("Volume").GetValue(0)
# Minkowski sum of a 1.4-cube with a 0.3-ball: V = a^3 + 6 r a^2 + 3 pi r^2 a + 4/3 pi r^3.
a, r, pi = 1.4, 0.3, 3.141592653589793
exact = a ** 3 + 6 * r * a ** 2 + 3 * pi * r ** 2 * a + 4.0 / 3.0 * pi * r ** 3
check(abs(volume / exact - 1) < 0.01, "rounded box volume %g, exact %g" % (volume, exact))
# Sampling and the restricted Voronoi diagram, with its two outputs.
sampler = BlueNoiseSurfaceSampler(Input=shape, NumberOfSamples=600, RandomSeed=3)
rvd = RestrictedVoronoiDiagram(Input=shape, Sites=sampler)
rvd.UpdatePipeline()
cells = servermanager.Fetch(rvd, idx=0)
sites = servermanager.Fetch(rvd, idx=1)
check(sites.GetNumberOfPoints() == 600, "expected 600 sites, got %d" % sites.GetNumberOfPoints())
check(cells.GetCellData().GetArray("SiteId") is not None, "RVD lacks SiteId")
area = sites.GetPointData().GetArray("CellArea")
total = sum(area.GetValue(i) for i in range(area.GetNumberOfTuples()))
check(abs(total / surface.GetFieldData().GetArray("Area").GetValue(0) - 1) < 1e-9,
      "RVD cell areas do not add up to the surface area")
# The fillets are smooth (each facet turns by under 12 degrees): no sharp edges.
check(sites.GetPointData().GetArray("ConvexFeature").GetRange() == (0, 0),
      "sharp edges reported on a filleted box")
# Adaptive sampling on a dumbbell: its neck is thin, and the sites say so.
dumbbell = MedialTestShape(Shape="Dumbbell", Length=1.0, Radius=0.2, MinorRadius=0.02)
adaptive = BlueNoiseSurfaceSampler(Input=dumbbell, NumberOfSamples=1000, Adaptive=1)
adaptive.UpdatePipeline()
thin = servermanager.Fetch(adaptive)
check(thin.GetNumberOfPoints() == 1000, "adaptive sampling gave %d sites" % thin.GetNumberOfPoints())
thickness = thin.GetPointData().GetArray("LocalThickness")
check(thickness is not None and abs(thickness.GetRange()[0] - 0.04) < 0.01,
      "LocalThickness does not show the dumbbell's neck (0.04 thick)")
# The initial medial mesh from the restricted Voronoi diagram's sites.
voronoi = VoronoiMedialAxis(Input=shape, Sites=OutputPort(rvd, 1))
voronoi.UpdatePipeline()
mat = servermanager.Fetch(voronoi)
check(mat.GetNumberOfPolys() > 0, "empty initial medial mesh")
check(mat.GetPointData().GetArray("Radius") is not None, "medial mesh lacks Radius")
check(mat.GetFieldData().GetArray("AtlasSites") is not None, "medial mesh lacks its Atlas")
with tempfile.TemporaryDirectory() as tmp:
    SaveData(os.path.join(tmp, "initial.ma"), proxy=voronoi)
    back = servermanager.Fetch(MedialAxisReader(FileName=os.path.join(tmp, "initial.ma")))
    check(back.GetNumberOfPoints() == mat.GetNumberOfPoints(), "initial MAT did not survive .ma")
    # Q-MAT on the medial mesh read from the .ma file (no Atlas needed).
    qmat = QMATSimplifier(Input=MedialAxisReader(FileName=os.path.join(tmp, "initial.ma")),
                          TargetNumberOfVertices=100)
    qmat.UpdatePipeline()
    qsmall = servermanager.Fetch(qmat)
    check(qsmall.GetNumberOfPoints() == 100, "Q-MAT: expected 100 spheres, got %d" % qsmall.GetNumberOfPoints())
    check(qsmall.GetCellData().GetArray("StabilityRatio") is not None, "Q-MAT output lacks StabilityRatio")
# Atlas-guided simplification with its correspondence output.
simplified = AtlasMedialAxisSimplifier(Input=voronoi, RestrictedVoronoiDiagram=OutputPort(rvd, 0),
                                       TargetNumberOfVertices=100, PreserveSharpFeatures=0)
simplified.UpdatePipeline()
small = servermanager.Fetch(simplified, idx=0)
check(small.GetNumberOfPoints() == 100, "expected 100 spheres, got %d" % small.GetNumberOfPoints())
colored = servermanager.Fetch(simplified, idx=1)
check(colored.GetCellData().GetArray("MedialVertexId") is not None, "no correspondence output")
# The whole Atlas of one picked sphere.
atlas = ExtractMedialAtlas(Input=OutputPort(simplified, 0),
                           RestrictedVoronoiDiagram=OutputPort(simplified, 1), MedialVertexId=7)
cells = servermanager.Fetch(atlas)
check(cells.GetNumberOfCells() > 0, "the Atlas of sphere 7 is empty")
check(cells.GetFieldData().GetArray("AtlasArea").GetValue(0) > 0, "the Atlas has no area")
# Fillets of a box with rounded edges: 12 centre lines of radius 0.1.
box = MedialTestShape(Shape="Rounded Box", FilletRadius=0.1, Resolution=16)
boxSites = BlueNoiseSurfaceSampler(Input=box, NumberOfSamples=50000)
boxCells = RestrictedVoronoiDiagram(Input=box, Sites=boxSites)
boxInitial = VoronoiMedialAxis(Input=box, Sites=OutputPort(boxCells, 1))
boxMat = AtlasMedialAxisSimplifier(Input=boxInitial, RestrictedVoronoiDiagram=OutputPort(boxCells, 0),
                                   TargetNumberOfVertices=5000, PreserveSharpFeatures=1)
fillets = FilletDetector(Input=OutputPort(boxMat, 0), RestrictedVoronoiDiagram=OutputPort(boxMat, 1),
                         Surface=box)
fillets.UpdatePipeline()
centreLines = servermanager.Fetch(fillets, idx=0)
check(centreLines.GetNumberOfCells() == 12, "expected 12 fillets, got %d" % centreLines.GetNumberOfCells())
meanRadius = centreLines.GetCellData().GetArray("MeanRadius")
check(all(abs(meanRadius.GetValue(f) - 0.1) < 0.003 for f in range(12)), "fillet radii are not 0.1")
faces = servermanager.Fetch(fillets, idx=1)
check(faces.GetCellData().GetArray("FilletId").GetRange() == (-1.0, 11.0), "fillet faces not labelled")
# Its structure: eight seams from the corners meet at one junction; the
# centre lines are fillet spheres; the Atlas agrees with the mesh.
structure = MedialStructure(Input=OutputPort(boxMat, 0), FilletLines=OutputPort(fillets, 0),
                            Cells=OutputPort(boxMat, 1))
structure.UpdatePipeline()
typed = servermanager.Fetch(structure, idx=0)
fields = typed.GetFieldData()
check(fields.GetArray("NumberOfSeams").GetValue(0) == 8,
      "expected 8 seams, got %d" % fields.GetArray("NumberOfSeams").GetValue(0))
check(fields.GetArray("NumberOfJunctionVertices").GetValue(0) == 1, "expected one junction")
check(fields.GetArray("NumberOfFilletVertices").GetValue(0) > 100, "fillet spheres not typed")
check(fields.GetArray("TangentComponentAgreement").GetValue(0) > 0.99, "Atlas and mesh disagree")
check(typed.GetPointData().GetArray("MedialType") is not None, "no MedialType")
# The one-click filter on a real CAD part.
fandisk = os.path.join(mesh_dir, "fandisk.off")
if os.path.exists(fandisk):
    part = OpenDataFile(fandisk)
    structural = StructuralMedialAxis(Input=part, NumberOfSamples=5000,
                                      TargetNumberOfVertices=500, PreserveSharpFeatures=1)
    structural.UpdatePipeline()
    result = servermanager.Fetch(structural, idx=0)
    check(result.GetNumberOfPoints() == 500, "expected 500 spheres, got %d" % result.GetNumberOfPoints())
    check(result.GetNumberOfPolys() > 0, "the medial axis of fandisk has no slabs")
    check(result.GetFieldData().GetArray("TotalSeconds").GetValue(0) > 0, "no stage times")
    check(result.GetFieldData().GetArray("Sites").GetValue(0) == 5000, "wrong number of sites")
    corr = servermanager.Fetch(structural, idx=1)
    check(corr.GetCellData().GetArray("MedialVertexId") is not None, "no correspondence output")
    shell = servermanager.Fetch(structural, idx=3)
    check(shell.GetCellData().GetArray("PrimitiveKind") is not None, "no envelope output")
    structural.Strategy = "Q-MAT"
    structural.UpdatePipeline()
    qresult = servermanager.Fetch(structural, idx=0)
    check(qresult.GetNumberOfPoints() == 500, "Q-MAT strategy: expected 500 spheres")
    check(qresult.GetFieldData().GetArray("NestedCones") is not None, "Q-MAT strategy did not run")
else:
    print("skipped the one-click filter: %s not found" % fandisk)
# The envelope of a medial mesh, overlapping primitives and closed boundary.
envelope = MedialEnvelope(Input=reader, Mode="Primitives")
envelope.UpdatePipeline()
pieces = servermanager.Fetch(envelope)
check(pieces.GetNumberOfPolys() > 0, "empty primitives envelope")
kinds = pieces.GetCellData().GetArray("PrimitiveKind")
check(kinds is not None and kinds.GetRange() == (0.0, 2.0), "PrimitiveKind missing or incomplete")
envelope.Mode = "Boundary"
envelope.BoundaryResolution = 48
envelope.UpdatePipeline()
boundary = servermanager.Fetch(envelope)
from vtkmodules.vtkFiltersCore import vtkFeatureEdges  # noqa: E402
edges = vtkFeatureEdges()
edges.SetInputData(boundary)
edges.BoundaryEdgesOn()
edges.NonManifoldEdgesOn()
edges.FeatureEdgesOff()
edges.ManifoldEdgesOff()
edges.Update()
check(boundary.GetNumberOfPolys() > 0, "empty boundary envelope")
check(edges.GetOutput().GetNumberOfCells() == 0, "boundary envelope is not closed")
# The reconstruction error of the simplified medial mesh against its surface.
error = MedialReconstructionError(Input=shape, MedialMesh=OutputPort(simplified, 0),
                                  NumberOfSamples=20000, NumberOfEnvelopeSamples=20000)
error.UpdatePipeline()
measured = servermanager.Fetch(error, idx=0)
check(measured.GetPointData().GetArray("Distance") is not None, "no Distance on the surface")
hausdorff = measured.GetFieldData().GetArray("HausdorffPercent")
check(hausdorff is not None and 0 < hausdorff.GetValue(0) < 20,
      "implausible Hausdorff distance %s" % (hausdorff and hausdorff.GetValue(0)))
envelope_samples = servermanager.Fetch(error, idx=1)
check(envelope_samples.GetNumberOfPoints() == 20000, "expected 20000 envelope samples")
# Generalized primitives on a capsule and its axis (a line drawn by hand):
# two vertex primitives and one edge primitive, the latter of the capsule's radius.
capsule = MedialTestShape(Shape="Capsule", Radius=0.3, Length=1.0)
axis = Line(Point1=[0, 0, -0.5], Point2=[0, 0, 0.5], Resolution=1)
primitives = GeneralizedPrimitives(Input=capsule, Skeleton=axis)
primitives.UpdatePipeline()
# (Fetch cannot gather a partitioned dataset collection in ParaView 5.11: the
# data information says what the server holds.)
count = primitives.GetDataInformation().GetNumberOfDataSets()
check(count == 3, "expected 3 primitives, got %d" % count)
# Every direction from the axis reaches at least the capsule's radius 0.3;
# from an end of the axis the farthest is the other cap, 1.3 away.
radii = primitives.PointData["Radius"].GetRange()
check(0.29 < radii[0] and radii[1] <= 1.3 + 1e-6, "primitive radii %s" % (radii,))
# The Medial Skeletal Diagram of a dumbbell from its Structural MAT.
bell = MedialTestShape(Shape="Dumbbell", Length=1.2, Radius=0.25, MinorRadius=0.1)
bell_mat = StructuralMedialAxis(Input=bell, NumberOfSamples=5000, TargetNumberOfVertices=100)
msd = MedialSkeletalDiagram(Input=bell, MedialAxis=OutputPort(bell_mat, 0))
msd.UpdatePipeline()
msd_skeleton = servermanager.Fetch(msd, idx=0)
msd_error = msd_skeleton.GetFieldData().GetArray("Error").GetValue(0)
check(msd_skeleton.GetNumberOfPoints() >= 2 and msd_error <= 0.005,
      "dumbbell diagram: %d vertices, error %g" % (msd_skeleton.GetNumberOfPoints(), msd_error))
msd_vertices = msd_skeleton.GetFieldData().GetArray("Vertices").GetValue(0)
check(msd.GetDataInformation(1).GetNumberOfDataSets() == msd_vertices
      + msd_skeleton.GetNumberOfLines() + msd_skeleton.GetNumberOfPolys(),
      "one primitive per element")
check(msd_skeleton.GetFieldData().GetArray("FailedElements").GetValue(0) == 0,
      "every element of the dumbbell's diagram has a primitive")
# The dumbbell's curve skeleton: one branch along its axis, saved as SWC.
curve = CurveSkeleton(Input=bell, MedialAxis=OutputPort(bell_mat, 0))
curve.UpdatePipeline()
curve_skeleton = servermanager.Fetch(curve, idx=0)
check(curve_skeleton.GetFieldData().GetArray("CycleRank").GetValue(0) == 0 and
      curve_skeleton.GetNumberOfLines() == 1,
      "dumbbell skeleton: %d lines" % curve_skeleton.GetNumberOfLines())
check(servermanager.Fetch(curve, idx=1).GetPointData().GetArray("BranchId") is not None,
      "no segmentation")
SaveData("dumbbell.swc", proxy=curve)
with open("dumbbell.swc") as swc:
    rows = [line for line in swc if line.strip() and not line.startswith("#")]
check(len(rows) == curve_skeleton.GetNumberOfPoints(), "SWC rows: %d" % len(rows))
# An open surface from its unsigned distance: a disk has one boundary.
disk = Triangulate(Input=Disk(InnerRadius=0.0, OuterRadius=1.0, CircumferentialResolution=64,
                              RadialResolution=16))
udf = UnsignedDistanceField(Input=disk, SamplingDimensions=[64, 64, 64])
sheet = UDFSurface(Input=udf)
sheet.UpdatePipeline()
extracted = servermanager.Fetch(sheet, idx=0)
check(extracted.GetNumberOfPolys() > 100 and
      extracted.GetFieldData().GetArray("BoundaryLoops").GetValue(0) == 1,
      "UDF surface of a disk: %d triangles" % extracted.GetNumberOfPolys())
check(servermanager.Fetch(sheet, idx=1).GetNumberOfPolys() > extracted.GetNumberOfPolys(),
      "the shell is missing")
print("pvbatch plugin test passed")
