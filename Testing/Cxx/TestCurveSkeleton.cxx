// SPDX-License-Identifier: GPL-3.0-or-later
// Curve skeletons from simplified medial meshes of generated solids: one
// loop per handle, nodes inside with their distance to the surface as
// radius, simple shapes give their centre lines, and the exports.
#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"
#include "Skeleton/CurveSkeleton.h"
#include "Skeleton/MedialThinning.h"
#include "Skeleton/SkeletonExport.h"
#include "Surface/AnalyticShapes.h"

#include "TestHelpers.h"
#include "vtkAnalyticShapeSource.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCurveSkeletonWriter.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMedialCurveSkeleton.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkStructuralMedialAxis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>

using namespace medialaxis;
using medialaxis::test::Simplify;

namespace
{
double Diagonal(const TriangleMesh& surface)
{
  const auto [lo, hi] = BoundingBox(surface.Points);
  return std::sqrt(Distance2(lo, hi));
}

CurveSkeleton SkeletonOf(const TriangleMesh& surface, std::size_t samples, std::size_t spheres)
{
  const auto run = Simplify(surface, samples, spheres, false);
  EXPECT_EQ(CheckMedialMeshOfSurface(run.Result.Medial.Mesh, surface), "");
  return ComputeCurveSkeleton(run.Result.Medial.Mesh, surface);
}

// Every node inside, its radius its distance to the surface.
void ExpectCentred(const CurveSkeleton& s, const TriangleMesh& surface)
{
  const TriangleLocator locator(surface);
  for (std::size_t v = 0; v < s.Nodes.size(); ++v)
  {
    EXPECT_TRUE(locator.Inside(s.Nodes[v])) << "node " << v;
    EXPECT_NEAR(s.Radii[v], locator.Distance(s.Nodes[v]), 1e-12);
  }
}

TriangleMesh Scaled(TriangleMesh mesh, const Point3& scale)
{
  for (Point3& p : mesh.Points)
  {
    p = { p[0] * scale[0], p[1] * scale[1], p[2] * scale[2] };
  }
  return mesh;
}

// How far the end node nearest to `tip` stands from it, in that node's
// radii: 1 where its ball touches the tip.
double TipDistanceInEndRadii(const CurveSkeleton& s, const Point3& tip)
{
  double best = HUGE_VAL;
  std::size_t end = 0;
  for (std::size_t v = 0; v < s.Nodes.size(); ++v)
  {
    if (s.Types[v] == SkeletonNodeType::End && Distance2(s.Nodes[v], tip) < best)
    {
      best = Distance2(s.Nodes[v], tip);
      end = v;
    }
  }
  return std::sqrt(best) / s.Radii[end];
}
}

TEST(CurveSkeleton, ThinningKeepsTheHomotopyType)
{
  // A strip of triangles with a hole: an annulus thins to one loop.
  const auto run = Simplify(MakeTorus(1.0, 0.35, 48), 6000, 400, false);
  const MedialMesh& m = run.Result.Medial.Mesh;
  const ThinnedGraph g = ThinMedialMesh(m);
  EXPECT_EQ(g.UncollapsedTriangles, 0u);
  const long euler = static_cast<long>(m.NumberOfVertices()) -
    static_cast<long>(AllEdges(m).size()) + static_cast<long>(m.Faces.size());
  EXPECT_EQ(static_cast<long>(g.Centroid.size()) - static_cast<long>(g.Edges.size()), euler);
}

TEST(CurveSkeleton, CapsuleGivesOneStraightSegment)
{
  const TriangleMesh capsule = MakeCapsule(0.3, 1.6, 48);
  const CurveSkeleton s = SkeletonOf(capsule, 6000, 300);
  ExpectCentred(s, capsule);
  EXPECT_EQ(s.CycleRank, 0u);
  EXPECT_EQ(s.Components, 1u);
  ASSERT_EQ(s.Branches.size(), 1u);
  // On the axis (z), reaching within one radius of both tips (at +-1.1).
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Point3& p : s.Nodes)
  {
    EXPECT_LT(std::hypot(p[0], p[1]), 0.01 * Diagonal(capsule));
    lo = std::min(lo, p[2]);
    hi = std::max(hi, p[2]);
  }
  EXPECT_LT(lo, -1.1 + 0.3 + 0.01);
  EXPECT_GT(hi, 1.1 - 0.3 - 0.01);
}

TEST(CurveSkeleton, TorusGivesOneCircle)
{
  const TriangleMesh torus = MakeTorus(1.0, 0.3, 48);
  const CurveSkeleton s = SkeletonOf(torus, 8000, 400);
  ExpectCentred(s, torus);
  EXPECT_EQ(s.CycleRank, 1u);
  ASSERT_EQ(s.Branches.size(), 1u);
  EXPECT_EQ(s.Branches[0].front(), s.Branches[0].back());
  for (const Point3& p : s.Nodes)
  {
    EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 0.05);
    EXPECT_NEAR(p[2], 0.0, 0.05);
  }
}

TEST(CurveSkeleton, EllipsoidGivesASegmentOnItsLongAxis)
{
  const TriangleMesh ellipsoid = Scaled(MakeSphere(1.0, 48), { 1.0, 0.5, 0.3 });
  const CurveSkeleton s = SkeletonOf(ellipsoid, 8000, 400);
  ExpectCentred(s, ellipsoid);
  EXPECT_EQ(s.CycleRank, 0u);
  ASSERT_EQ(s.Branches.size(), 1u);
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const Point3& p : s.Nodes)
  {
    EXPECT_LT(std::abs(p[1]), 0.1);
    EXPECT_LT(std::abs(p[2]), 0.02);
    lo = std::min(lo, p[0]);
    hi = std::max(hi, p[0]);
  }
  // Along x, as far as the sheet (+-0.91, where the balls touching the tips
  // stand) and no farther: the end balls reach within a quarter of their
  // radius of the tips.
  EXPECT_GT(hi - lo, 0.3);
  EXPECT_LT(hi - lo, 1.83);
  EXPECT_LT(TipDistanceInEndRadii(s, { 1.0, 0.0, 0.0 }), 1.25);
  EXPECT_LT(TipDistanceInEndRadii(s, { -1.0, 0.0, 0.0 }), 1.25);
}

TEST(CurveSkeleton, EndsReachTheTipsOfTaperedLimbs)
{
  // A long ellipsoid narrowing towards +z to 40% of its width, round and
  // flattened: the simplified medial mesh stops short of the thin tip, the
  // skeleton's end goes on to the ball that touches it.
  for (const double flat : { 1.0, 0.6 })
  {
    const double taper = 0.6;
    TriangleMesh limb = MakeSphere(1.0, 48);
    for (Point3& p : limb.Points)
    {
      const double narrowing = 1.0 - taper * 0.5 * (p[2] + 1.0);
      p = { 0.5 * narrowing * p[0], 0.5 * flat * narrowing * p[1], 3.0 * p[2] };
    }
    const CurveSkeleton s = SkeletonOf(limb, 6000, 300);
    ExpectCentred(s, limb);
    EXPECT_EQ(s.CycleRank, 0u);
    ASSERT_EQ(s.Branches.size(), 1u);
    EXPECT_LT(TipDistanceInEndRadii(s, { 0.0, 0.0, 3.0 }), 1.25) << "taper " << taper;
    EXPECT_LT(TipDistanceInEndRadii(s, { 0.0, 0.0, -3.0 }), 1.25) << "taper " << taper;
  }
}

TEST(CurveSkeleton, CylinderGivesOneSegment)
{
  const TriangleMesh cylinder = MakeCylinder(0.3, 2.0, 48);
  const CurveSkeleton s = SkeletonOf(cylinder, 8000, 400);
  ExpectCentred(s, cylinder);
  EXPECT_EQ(s.CycleRank, 0u);
  EXPECT_EQ(s.Branches.size(), 1u);
  for (const Point3& p : s.Nodes)
  {
    EXPECT_LT(std::hypot(p[0], p[1]), 0.05);
  }
}

TEST(CurveSkeleton, ExportsListEveryNodeAndLoop)
{
  const CurveSkeleton s = SkeletonOf(MakeTorus(1.0, 0.3, 48), 8000, 400);
  const std::string swc = SkeletonToSwc(s, "torus\nunits: none");
  std::istringstream lines(swc);
  std::size_t nodes = 0, loops = 0, roots = 0;
  for (std::string line; std::getline(lines, line);)
  {
    if (line.rfind("# loop ", 0) == 0)
    {
      ++loops;
    }
    else if (!line.empty() && line[0] != '#')
    {
      ++nodes;
      roots += line.size() > 3 && line.substr(line.size() - 3) == " -1" ? 1 : 0;
    }
  }
  EXPECT_EQ(nodes, s.Nodes.size());
  EXPECT_EQ(loops, 1u);
  EXPECT_EQ(roots, 1u);
  const std::string json = SkeletonToJson(s);
  EXPECT_NE(json.find("\"cycle_rank\": 1"), std::string::npos);
  EXPECT_EQ(std::count(json.begin(), json.end(), '{'), 1 + s.Nodes.size() + s.Edges.size());
}

// The filter in a pipeline: a torus, its Structural MAT, the skeleton with
// its arrays and counts, the segmented surface, the SWC and JSON files; bad
// inputs give errors a user can act on.
TEST(MedialCurveSkeletonFilter, PipelineOutputsAndBadInputs)
{
  vtkNew<vtkAnalyticShapeSource> torus;
  torus->SetShapeToTorus();
  vtkNew<vtkStructuralMedialAxis> mat;
  mat->SetInputConnection(torus->GetOutputPort());
  mat->SetNumberOfSamples(6000);
  mat->SetTargetNumberOfVertices(300);
  mat->SetGenerateEnvelope(false);
  vtkNew<vtkMedialCurveSkeleton> curve;
  curve->SetInputConnection(0, torus->GetOutputPort());
  curve->SetMedialAxisConnection(mat->GetOutputPort(0));
  vtkNew<test::ErrorCatcher> errors;
  curve->AddObserver(vtkCommand::ErrorEvent, errors);
  curve->AddObserver(vtkCommand::WarningEvent, errors);
  curve->Update();
  EXPECT_EQ(errors->Count, 0) << errors->Last;
  vtkPolyData* skeleton = curve->GetSkeleton();
  ASSERT_GT(skeleton->GetNumberOfPoints(), 3);
  EXPECT_EQ(skeleton->GetFieldData()->GetArray("CycleRank")->GetTuple1(0), 1.0);
  EXPECT_EQ(skeleton->GetFieldData()->GetArray("Components")->GetTuple1(0), 1.0);
  EXPECT_EQ(skeleton->GetNumberOfLines(), 1);
  for (const char* name : { "Radius", "NodeType", "BranchId" })
  {
    EXPECT_NE(skeleton->GetPointData()->GetArray(name), nullptr) << name;
  }
  EXPECT_NE(skeleton->GetCellData()->GetArray("Length"), nullptr);
  vtkPolyData* parts = curve->GetSegmentation();
  EXPECT_GT(parts->GetNumberOfPolys(), 0);
  vtkDataArray* branch = parts->GetPointData()->GetArray("BranchId");
  ASSERT_NE(branch, nullptr);
  EXPECT_EQ(branch->GetRange()[0], 0.0); // every point on the one branch
  EXPECT_EQ(branch->GetRange()[1], 0.0);

  for (const char* name : { "torus_skeleton.swc", "torus_skeleton.json" })
  {
    vtkNew<vtkCurveSkeletonWriter> writer;
    writer->SetInputData(skeleton);
    writer->SetFileName(name);
    ASSERT_EQ(writer->Write(), 1) << writer->GetErrorMessage();
    std::ifstream file(name);
    const std::string text{ std::istreambuf_iterator<char>(file), {} };
    if (std::string(name).find(".swc") != std::string::npos)
    {
      EXPECT_NE(text.find("# loop "), std::string::npos);
    }
    else
    {
      EXPECT_NE(text.find("\"cycle_rank\": 1"), std::string::npos);
    }
  }
  vtkNew<vtkCurveSkeletonWriter> badWriter;
  badWriter->AddObserver(vtkCommand::ErrorEvent, errors);
  badWriter->SetInputData(parts);
  badWriter->SetFileName("not_a_skeleton.swc");
  EXPECT_EQ(badWriter->Write(), 0);
  EXPECT_NE(std::string(badWriter->GetErrorMessage()).find("Radius"), std::string::npos);

  // No medial mesh; the medial mesh of another surface; an open surface.
  const int before = errors->Count;
  vtkNew<vtkMedialCurveSkeleton> alone;
  alone->AddObserver(vtkCommand::ErrorEvent, errors);
  alone->SetInputConnection(0, torus->GetOutputPort());
  alone->Update();
  EXPECT_EQ(errors->Count, before + 1);
  EXPECT_NE(errors->Last.find("no medial mesh"), std::string::npos) << errors->Last;
  vtkNew<vtkAnalyticShapeSource> other;
  other->SetShapeToCapsule();
  vtkNew<vtkMedialCurveSkeleton> mismatched;
  mismatched->AddObserver(vtkCommand::ErrorEvent, errors);
  mismatched->SetInputConnection(0, other->GetOutputPort());
  mismatched->SetMedialAxisConnection(mat->GetOutputPort(0));
  mismatched->Update();
  EXPECT_NE(errors->Last.find("computed from this surface"), std::string::npos) << errors->Last;
  EXPECT_EQ(mismatched->GetSkeleton()->GetNumberOfPoints(), 0);
  vtkNew<vtkSphereSource> hemisphere;
  hemisphere->SetEndPhi(90.0);
  vtkNew<vtkMedialCurveSkeleton> open;
  open->AddObserver(vtkCommand::ErrorEvent, errors);
  open->SetInputConnection(0, hemisphere->GetOutputPort());
  open->SetMedialAxisConnection(mat->GetOutputPort(0));
  open->Update();
  EXPECT_NE(errors->Last.find("input port 0"), std::string::npos) << errors->Last;
}
