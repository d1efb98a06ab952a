// SPDX-License-Identifier: GPL-3.0-or-later
// Q-MAT simplification on the shared edge-collapse framework: the paper's
// unit-sphere and spike-removal tests, boundary preservation, validity,
// determinism, and input read from a .ma file (no Atlases).
#include "Format/MaFormat.h"
#include "Geometry/Vec3.h"
#include "Mesh/MedialMeshQuality.h"
#include "Simplification/QMatSimplifier.h"
#include "Support/Parallel.h"
#include "Support/Random.h"
#include "Surface/AnalyticShapes.h"

#include "vtkAnalyticShapeSource.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkQMatSimplifier.h"
#include "vtkStructuralMedialAxis.h"

#include "TestHelpers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

using namespace medialaxis;
using medialaxis::test::InitialMedialAxis;
using medialaxis::test::SimplifiedRun;
namespace test = medialaxis::test;

namespace
{
QMatSimplifierResult QMat(const AtlasMedialMesh& initial, std::size_t target, double k0 = 0.1)
{
  QMatSimplifierOptions options;
  options.TargetNumberOfVertices = target;
  options.BoundaryWeight = k0;
  return SimplifyMedialAxisQMat(initial, options);
}

// Every vertex moved by a uniform random vector of length up to `amplitude`.
TriangleMesh WithVertexNoise(TriangleMesh mesh, double amplitude, std::uint64_t seed)
{
  Random random(seed);
  for (Point3& p : mesh.Points)
  {
    Point3 d;
    do
    {
      d = { 2.0 * random.Uniform() - 1.0, 2.0 * random.Uniform() - 1.0,
        2.0 * random.Uniform() - 1.0 };
    } while (Dot(d, d) > 1.0);
    p = p + amplitude * d;
  }
  return mesh;
}
}

TEST(QMatSimplifier, UnitSphereSimplifiesToItsCentre)
{
  const SimplifiedRun initial = InitialMedialAxis(MakeSphere(1.0, 32), 10000);
  const QMatSimplifierResult result = QMat(initial.Initial, 1);
  const MedialMesh& m = result.Medial.Mesh;
  ASSERT_EQ(m.Centers.size(), 1u);
  std::cout << "centre " << Norm(m.Centers[0]) << " from the origin, radius " << m.Radii[0]
            << " (from " << initial.Initial.Mesh.Centers.size() << " spheres)\n";
  EXPECT_LT(Norm(m.Centers[0]), 0.005);
  EXPECT_NEAR(m.Radii[0], 1.0, 0.005);
}

TEST(QMatSimplifier, NoisySphereLosesItsSpikes)
{
  // Vertex noise of 0.5% of the bounding-box diagonal (2 sqrt 3) on a coarse
  // sphere (2,402 vertices, like the paper's 2,562) and a finer one.
  for (int resolution : { 20, 32 })
  {
    const TriangleMesh noisy =
      WithVertexNoise(MakeSphere(1.0, resolution), 0.005 * 2.0 * std::sqrt(3.0), 7);
    const SimplifiedRun initial = InitialMedialAxis(noisy, 10000);
    const auto& radiiBefore = initial.Initial.Mesh.Radii;
    const QMatSimplifierResult result = QMat(initial.Initial, 50);
    const MedialMesh& m = result.Medial.Mesh;
    ASSERT_EQ(m.Centers.size(), 50u);
    const double smallest = *std::min_element(m.Radii.begin(), m.Radii.end());
    // The paper's own settings: no spike merge, strict link condition.
    QMatSimplifierOptions paper;
    paper.TargetNumberOfVertices = 50;
    paper.SpikeRatio = 0.0;
    paper.EulerNeutralCollapses = false;
    const MedialMesh strict = SimplifyMedialAxisQMat(initial.Initial, paper).Medial.Mesh;
    const double smallestStrict = *std::min_element(strict.Radii.begin(), strict.Radii.end());
    std::cout << "resolution " << resolution << ": smallest radius "
              << *std::min_element(radiiBefore.begin(), radiiBefore.end()) << " before, "
              << smallest << " after (" << smallestStrict << " with the paper's settings)\n";
    EXPECT_LT(*std::min_element(radiiBefore.begin(), radiiBefore.end()), 0.5); // spikes
    EXPECT_GE(smallest, 0.5);
    EXPECT_LT(smallestStrict, smallest);
    EXPECT_TRUE(ValidateMedialMesh(m).IsValid()) << ValidateMedialMesh(m).Message;
    EXPECT_EQ(MeasureQuality(m).DegenerateTriangles, 0u);
  }
}

TEST(QMatSimplifier, CapsuleSimplifiesToItsAxis)
{
  const double radius = 0.5, axis = 2.0;
  const SimplifiedRun initial = InitialMedialAxis(MakeCapsule(radius, axis, 24), 10000);
  const QMatSimplifierResult result = QMat(initial.Initial, 20);
  const MedialMesh& m = result.Medial.Mesh;
  ASSERT_EQ(m.Centers.size(), 20u);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (std::size_t v = 0; v < m.Centers.size(); ++v)
  {
    const Point3& c = m.Centers[v];
    lo = std::min(lo, c[2]);
    hi = std::max(hi, c[2]);
    const double z = std::clamp(c[2], -0.5 * axis, 0.5 * axis);
    EXPECT_LT(Norm(c - Point3{ 0.0, 0.0, z }), 0.01 * axis) << "vertex " << v;
    EXPECT_NEAR(m.Radii[v], radius, 0.01 * radius) << "vertex " << v;
  }
  std::cout << "axis covered from z = " << lo << " to " << hi << "\n";
  EXPECT_TRUE(ValidateMedialMesh(m).IsValid()) << ValidateMedialMesh(m).Message;
}

TEST(QMatSimplifier, OutputIsValidAndDeterministic)
{
  const TriangleMesh box = MakeRoundedBox({ 2.0, 1.5, 1.0 }, 0.2, 12);
  const SimplifiedRun initial = InitialMedialAxis(box, 3000);
  const QMatSimplifierResult a = RunWithThreads(1, [&] { return QMat(initial.Initial, 300); });
  const QMatSimplifierResult b = RunWithThreads(2, [&] { return QMat(initial.Initial, 300); });
  const MedialMesh &ma = a.Medial.Mesh, &mb = b.Medial.Mesh;
  EXPECT_EQ(ma.Centers.size(), 300u);
  EXPECT_TRUE(ValidateMedialMesh(ma).IsValid()) << ValidateMedialMesh(ma).Message;
  EXPECT_EQ(MeasureQuality(ma).DegenerateTriangles, 0u);
  ASSERT_EQ(ma.Centers.size(), mb.Centers.size());
  EXPECT_EQ(
    0, std::memcmp(ma.Centers.data(), mb.Centers.data(), ma.Centers.size() * sizeof(Point3)));
  EXPECT_EQ(ma.Faces, mb.Faces);
  // The Atlases of the input merge along: every site is kept exactly once
  // per vertex that stands for it, and none is lost.
  std::vector<Index> sites(a.Medial.AtlasSites);
  std::sort(sites.begin(), sites.end());
  sites.erase(std::unique(sites.begin(), sites.end()), sites.end());
  std::vector<Index> before(initial.Initial.AtlasSites);
  std::sort(before.begin(), before.end());
  before.erase(std::unique(before.begin(), before.end()), before.end());
  EXPECT_EQ(sites, before);
  for (double r : ma.Radii)
  {
    EXPECT_GE(r, 0.0);
  }
}

TEST(QMatSimplifier, SimplifiesAMeshReadFromAnMaFile)
{
  const SimplifiedRun initial = InitialMedialAxis(MakeCapsule(0.5, 2.0, 16), 3000);
  std::stringstream text;
  ASSERT_TRUE(WriteMa(text, initial.Initial.Mesh));
  const MaReadResult read = ParseMa(text);
  ASSERT_TRUE(read.Ok()) << read.Error;
  AtlasMedialMesh fromFile;
  fromFile.Mesh = read.Mesh;
  fromFile.AtlasOffsets.clear(); // a .ma file has no Atlases
  const QMatSimplifierResult result = QMat(fromFile, 20);
  const MedialMesh& m = result.Medial.Mesh;
  ASSERT_EQ(m.Centers.size(), 20u);
  EXPECT_TRUE(result.Medial.AtlasSites.empty());
  for (std::size_t v = 0; v < m.Centers.size(); ++v)
  {
    EXPECT_LT(std::hypot(m.Centers[v][0], m.Centers[v][1]), 0.04) << "vertex " << v;
  }
  // Exactly what the in-memory mesh gives (the file keeps 17 digits).
  const QMatSimplifierResult direct = QMat(initial.Initial, 20);
  EXPECT_EQ(direct.Medial.Mesh.Centers, m.Centers);
}

TEST(QMatSimplifier, EmptyAndTinyInputs)
{
  AtlasMedialMesh empty;
  EXPECT_TRUE(SimplifyMedialAxisQMat(empty).Medial.Mesh.Centers.empty());
  AtlasMedialMesh two;
  two.Mesh.Centers = { { 0, 0, 0 }, { 1, 0, 0 } };
  two.Mesh.Radii = { 0.5, 0.5 };
  two.Mesh.Edges = { { 0, 1 } };
  two.AtlasOffsets.clear();
  QMatSimplifierOptions options;
  options.TargetNumberOfVertices = 1;
  // The cone's SQE alone fits any ball of radius 0.5 on the axis (singular:
  // the best of the ends and the midpoint); the soft planes at both ends
  // pull the merged ball outwards a little.
  options.BoundaryWeight = 0.0;
  const QMatSimplifierResult one = SimplifyMedialAxisQMat(two, options);
  ASSERT_EQ(one.Medial.Mesh.Centers.size(), 1u);
  EXPECT_NEAR(one.Medial.Mesh.Radii[0], 0.5, 1e-12);
  options.BoundaryWeight = 0.1;
  const QMatSimplifierResult soft = SimplifyMedialAxisQMat(two, options);
  ASSERT_EQ(soft.Medial.Mesh.Centers.size(), 1u);
  EXPECT_GT(soft.Medial.Mesh.Radii[0], 0.5);
  EXPECT_LT(soft.Medial.Mesh.Radii[0], 0.55);
  EXPECT_NEAR(soft.Medial.Mesh.Centers[0][0], 0.5, 1e-9);
}

TEST(QMatSimplifierFilter, PipelineOneClickAndBadInput)
{
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToTorus();
  shape->SetResolution(16);
  test::InitialMedialPipeline pipeline(shape->GetOutputPort(), 3000);
  vtkNew<vtkQMatSimplifier> qmat;
  qmat->SetInputConnection(pipeline.Voronoi->GetOutputPort());
  qmat->SetTargetNumberOfVertices(100);
  qmat->Update();
  vtkPolyData* out = qmat->GetOutput();
  EXPECT_EQ(out->GetNumberOfPoints(), 100);
  ASSERT_NE(out->GetPointData()->GetArray("Radius"), nullptr);
  ASSERT_NE(out->GetCellData()->GetArray("StabilityRatio"), nullptr);
  ASSERT_NE(out->GetFieldData()->GetArray("AtlasSites"), nullptr); // merged along
  EXPECT_GT(test::FieldValue(out, "Collapses"), 0.0);

  // The one-click filter with the Q-MAT strategy: same target, correspondence
  // on port 1.
  vtkNew<vtkStructuralMedialAxis> structural;
  structural->SetInputConnection(shape->GetOutputPort());
  structural->SetNumberOfSamples(3000);
  structural->SetTargetNumberOfVertices(100);
  structural->SetStrategyToQMat();
  structural->Update();
  EXPECT_EQ(structural->GetOutput(0)->GetNumberOfPoints(), 100);
  vtkDataArray* ids = vtkPolyData::SafeDownCast(structural->GetOutputDataObject(1))
                        ->GetCellData()
                        ->GetArray("MedialVertexId");
  ASSERT_NE(ids, nullptr);
  EXPECT_GE(ids->GetRange()[0], 0.0);
  EXPECT_LT(ids->GetRange()[1], 100.0);

  // No radii: a clear error and an empty output.
  vtkNew<vtkPolyData> bare;
  bare->ShallowCopy(shape->GetOutput());
  vtkNew<vtkQMatSimplifier> bad;
  bad->SetInputData(bare);
  vtkNew<test::ErrorCatcher> errors;
  bad->AddObserver(vtkCommand::ErrorEvent, errors);
  bad->Update();
  EXPECT_NE(errors->Last.find("Radius"), std::string::npos) << errors->Last;
  EXPECT_EQ(bad->GetOutput()->GetNumberOfPoints(), 0);
}
