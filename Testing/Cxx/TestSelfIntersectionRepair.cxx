// SPDX-License-Identifier: GPL-3.0-or-later
// The self-intersection repair on generated parts whose triangles cross
// three at a point, as exported boolean unions do: three boxes overlapping
// at a corner, a cylinder through two overlapping plates, a fillet strip
// across an edge of a block. Where CGAL 5.5 cannot resolve the crossings
// exactly, the repair wraps the surface; either way the result is one
// closed solid close to the input, and its medial axis has the solid's
// topology.
#include "Geometry/ClosestPoint.h"
#include "Geometry/Vec3.h"
#include "Surface/AnalyticShapes.h"
#include "Surface/SurfacePreparation.h"
#include "TestHelpers.h"
#include "vtkCellArray.h"
#include "vtkMedialSurfaceValidator.h"
#include "vtkPolyData.h"
#include "vtkStructuralMedialAxis.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iostream>
#include <set>
#include <string>
#include <utility>
#include <vector>

using namespace medialaxis;

namespace
{
TriangleMesh Box(const Point3& lo, const Point3& hi)
{
  TriangleMesh box = test::UnitCube();
  for (Point3& p : box.Points)
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] = lo[k] + p[k] * (hi[k] - lo[k]);
    }
  }
  return box;
}

TriangleMesh Mapped(TriangleMesh mesh, const std::function<Point3(const Point3&)>& map)
{
  for (Point3& p : mesh.Points)
  {
    p = map(p);
  }
  return mesh;
}

struct Part
{
  const char* Name;
  TriangleMesh Soup;
};

std::vector<Part> PartsWithTripleCrossings()
{
  std::vector<Part> parts;
  // A face of each box passes through (2, 0.5, 1).
  parts.push_back({ "three boxes",
    test::Append(test::Append(Box({ 0, 0, 0 }, { 2, 2, 2 }), Box({ 1, 0.5, 0.5 }, { 3, 2.5, 2.5 })),
      Box({ 1.5, 0, 1 }, { 2.5, 1, 3 })) });
  // The cylinder's side crosses both plates where their faces cross.
  parts.push_back({ "cylinder through two plates",
    test::Append(
      test::Append(Box({ -1, -1, 0 }, { 1, 1, 0.2 }), Box({ -0.5, -1, 0.1 }, { 1.5, 1, 0.3 })),
      Mapped(MakeCylinder(0.3, 1.0, 24),
        [](const Point3& p) {
          return Point3{ p[0] + 0.25, p[1], p[2] + 0.15 };
        })) });
  // A strip along the block's top front edge (y = 0, z = 1) crosses the
  // top face, the front face and the edge between them.
  parts.push_back({ "fillet strip across an edge",
    test::Append(Box({ 0, 0, 0 }, { 2, 1, 1 }),
      Mapped(MakeCylinder(0.2, 1.0, 24),
        [](const Point3& p) {
          return Point3{ p[2] + 1.0, p[0], p[1] + 1.0 };
        })) });
  return parts;
}

double DistanceTo(const TriangleMesh& mesh, const Point3& p)
{
  double best = HUGE_VAL;
  for (const Triangle& t : mesh.Triangles)
  {
    const Point3 q =
      ClosestPointOnTriangle(p, mesh.Points[t[0]], mesh.Points[t[1]], mesh.Points[t[2]]);
    best = std::min(best, Norm(q - p));
  }
  return best;
}

// Distance from `p` to the box of a crossing.
double DistanceToBox(const TriangleCrossing& c, const Point3& p)
{
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double out = std::max({ c.Lo[k] - p[k], 0.0, p[k] - c.Hi[k] });
    d2 += out * out;
  }
  return std::sqrt(d2);
}

// V - E + F of a medial mesh: its points, the distinct edges of its
// triangles and lines, its triangles.
long long EulerCharacteristic(vtkPolyData* mat)
{
  std::set<std::pair<vtkIdType, vtkIdType>> edges;
  auto add = [&](vtkIdType a, vtkIdType b) { edges.insert(std::minmax(a, b)); };
  vtkIdType count;
  const vtkIdType* ids;
  for (mat->GetPolys()->InitTraversal(); mat->GetPolys()->GetNextCell(count, ids);)
  {
    for (vtkIdType k = 0; k < count; ++k)
    {
      add(ids[k], ids[(k + 1) % count]);
    }
  }
  for (mat->GetLines()->InitTraversal(); mat->GetLines()->GetNextCell(count, ids);)
  {
    for (vtkIdType k = 0; k + 1 < count; ++k)
    {
      add(ids[k], ids[k + 1]);
    }
  }
  return static_cast<long long>(mat->GetNumberOfPoints()) - static_cast<long long>(edges.size()) +
    static_cast<long long>(mat->GetNumberOfPolys());
}
}

TEST(SelfIntersectionRepair, TripleCrossingsGiveOneClosedSolidCloseToTheInput)
{
  int wrapped = 0;
  const std::vector<Part> parts = PartsWithTripleCrossings();
  for (const Part& part : parts)
  {
    SCOPED_TRACE(part.Name);
    SurfacePreparationOptions options;
    options.RepairSelfIntersections = true;
    TriangleMesh prepared;
    const SurfacePreparationReport report = PrepareSurface(part.Soup, prepared, options);
    ASSERT_TRUE(report.Ok()) << report.Error;
    ASSERT_TRUE(report.Repaired);
    ASSERT_GT(report.SelfIntersections, 0u);
    wrapped += report.RepairMethod == "alpha wrap" ? 1 : 0;
    // Closed, manifold, outward and crossing nowhere: a second preparation
    // without repair accepts it as it is.
    TriangleMesh again;
    const SurfacePreparationReport check = PrepareSurface(prepared, again);
    EXPECT_TRUE(check.Ok()) << check.Error;
    EXPECT_EQ(check.SelfIntersections, 0u);
    EXPECT_EQ(check.Components, 1u);
    // Away from the crossings (farther than twice the wrap's balls) the
    // repaired surface lies within 0.5% of the diagonal of the input.
    const double diagonal = test::Diagonal(part.Soup);
    const double nearCrossing = 2.0 * options.WrapAlpha * diagonal;
    double farthest = 0.0;
    const std::size_t stride = 1 + prepared.Points.size() / 4000; // enough points to see a bulge
    for (std::size_t i = 0; i < prepared.Points.size(); i += stride)
    {
      const Point3& p = prepared.Points[i];
      const bool near = std::any_of(report.Crossings.begin(), report.Crossings.end(),
        [&](const TriangleCrossing& c) { return DistanceToBox(c, p) < nearCrossing; });
      if (!near)
      {
        farthest = std::max(farthest, DistanceTo(part.Soup, p));
      }
    }
    std::cout << part.Name << ": " << report.SelfIntersections << " crossing pairs, "
              << report.RepairMethod << ", " << prepared.Triangles.size()
              << " triangles; farthest from the input " << 100.0 * report.RepairDeviation
              << "% of the diagonal, away from the crossings " << 100.0 * farthest / diagonal
              << "%\n";
    EXPECT_LE(farthest, 0.005 * diagonal);
    EXPECT_LE(report.RepairDeviation, 0.02);
    // The medial axis of the repaired solid (genus 0): one piece, no loop;
    // the one-click filter repairs the first part itself.
    const bool first = &part == &parts.front();
    vtkNew<vtkStructuralMedialAxis> medial;
    medial->SetInputData(test::ToPolyData(first ? part.Soup : prepared));
    medial->SetNumberOfSamples(1000);
    medial->SetTargetNumberOfVertices(50);
    medial->SetGenerateEnvelope(false);
    medial->Update();
    vtkPolyData* mat = medial->GetOutput();
    ASSERT_GT(mat->GetNumberOfPoints(), 0);
    EXPECT_EQ(EulerCharacteristic(mat), 1);
    if (first)
    {
      // (The filter repairs in a frame of its own, where the exact
      // resolution may succeed or not: either way it says which ran.)
      EXPECT_GT(test::FieldValue(mat, "RepairedCrossingPairs"), 0.0);
      EXPECT_GE(test::FieldValue(mat, "RepairWrapped"), 0.0);
    }
  }
  // At least one of them is beyond CGAL's exact resolution.
  EXPECT_GE(wrapped, 1);
}

TEST(SelfIntersectionRepair, ValidatorSaysItWrappedAndCanBeToldNotTo)
{
  const TriangleMesh soup = PartsWithTripleCrossings()[0].Soup;
  vtkNew<vtkMedialSurfaceValidator> validator;
  auto errors = vtkSmartPointer<test::ErrorCatcher>::New();
  validator->AddObserver(vtkCommand::ErrorEvent, errors);
  validator->SetInputData(test::ToPolyData(soup));
  validator->SetRepairSelfIntersections(true);
  validator->SetWrapAlpha(0.02); // coarse: the messages are what is checked
  validator->Update();
  ASSERT_TRUE(validator->GetValid()) << validator->GetErrorMessage();
  EXPECT_TRUE(validator->GetRepaired());
  if (validator->GetWrapped())
  {
    EXPECT_GT(validator->GetRepairDeviation(), 0.0);
    EXPECT_NE(std::string(validator->GetNotes()).find("wrapping"), std::string::npos);
    // Without the fallback the same input is refused, saying why.
    validator->SetWrapAlpha(0.0);
    validator->Update();
    EXPECT_FALSE(validator->GetValid());
    EXPECT_NE(
      std::string(validator->GetErrorMessage()).find("repairing it failed"), std::string::npos);
  }
}

namespace
{
// A plate 4 x 4 x 0.4 with a pyramid-shaped dent from the top whose tip, one
// top vertex moved down, pokes through the bottom face by `depth` (inside a
// bottom triangle, not over its corners): the air of the dent meets the air
// under the plate through a hole `depth` deep, far too small for a sampling.
TriangleMesh PlateWithPiercingDent(double depth, Index& tip)
{
  TriangleMesh plate = MakeRoundedBox({ 4.0, 4.0, 0.4 }, 0.0, 12);
  tip = -1;
  double best = HUGE_VAL;
  for (std::size_t v = 0; v < plate.Points.size(); ++v)
  {
    const Point3& p = plate.Points[v];
    const double d = Norm(p - Point3{ 0.3, 0.3, 0.2 });
    if (p[2] > 0.1 && d < best)
    {
      best = d;
      tip = static_cast<Index>(v);
    }
  }
  // A third of a grid step aside, so that the tip is over the inside of a
  // bottom triangle.
  plate.Points[tip] = plate.Points[tip] + Point3{ 0.11, 0.05, -0.4 - depth };
  return plate;
}
}

TEST(SelfIntersectionRepair, PullsADentsTipPokingThroughAWallBackBehindIt)
{
  Index tip = -1;
  const TriangleMesh pierced = PlateWithPiercingDent(1e-6, tip);
  ASSERT_FALSE(FindSelfIntersections(pierced.Points, pierced.Triangles).empty());
  SurfacePreparationOptions options;
  options.RepairSelfIntersections = true;
  TriangleMesh prepared;
  const SurfacePreparationReport report = PrepareSurface(pierced, prepared, options);
  ASSERT_TRUE(report.Ok()) << report.Error;
  std::cout << "pulled apart: " << report.CrossingFarApart << " pairs far apart, moved by "
            << 100.0 * report.RepairDeviation << "% of the diagonal\n";
  EXPECT_EQ(report.RepairMethod, "pulled apart");
  EXPECT_GT(report.CrossingFarApart, 0u);
  // Moved the gap behind the wall (and the depth it poked through), no more.
  EXPECT_GE(report.RepairDeviation, options.ContactGap);
  EXPECT_LE(report.RepairDeviation, options.ContactGap * 1.01);
  EXPECT_TRUE(FindSelfIntersections(prepared.Points, prepared.Triangles).empty());
  // One point moved (the tip), to the gap behind the bottom face.
  std::size_t moved = 0;
  Point3 movedTo{ 0.0, 0.0, 0.0 };
  for (const Point3& p : prepared.Points)
  {
    const bool kept = std::any_of(pierced.Points.begin(), pierced.Points.end(),
      [&p](const Point3& q) { return Norm(p - q) == 0.0; });
    moved += kept ? 0 : 1;
    movedTo = kept ? movedTo : p;
  }
  EXPECT_EQ(moved, 1u);
  const double diagonal = Norm(Point3{ 4.0, 4.0, 0.4 });
  EXPECT_NEAR(movedTo[2], -0.2 + options.ContactGap * diagonal, 1e-9);

  // Without it, exact resolution gives up on the contact and the surface
  // is refused.
  options.ContactGap = 0.0;
  const SurfacePreparationReport refused = PrepareSurface(pierced, prepared, options);
  EXPECT_FALSE(refused.Ok());
  EXPECT_NE(refused.Error.find("passes through itself"), std::string::npos) << refused.Error;
}

TEST(SelfIntersectionRepair, MedialAxisOfAPlateWithAPiercingDentHasThePlatesTopology)
{
  Index tip = -1;
  vtkNew<vtkStructuralMedialAxis> structural;
  auto warnings = vtkSmartPointer<test::ErrorCatcher>::New();
  structural->AddObserver(vtkCommand::WarningEvent, warnings);
  structural->SetInputData(test::ToPolyData(PlateWithPiercingDent(1e-6, tip)));
  structural->SetNumberOfSamples(3000);
  structural->SetTargetNumberOfVertices(300);
  structural->Update();
  vtkPolyData* mat = structural->GetOutput();
  ASSERT_GT(mat->GetNumberOfPoints(), 0);
  EXPECT_EQ(test::FieldValue(mat, "RepairPulledApart"), 1.0);
  EXPECT_GT(test::FieldValue(mat, "RepairDeviationFraction"), 0.0);
  EXPECT_NE(warnings->Last.find("contact pulled apart"), std::string::npos) << warnings->Last;
  EXPECT_EQ(EulerCharacteristic(mat), 1); // genus 0, as the mesh
}
