// SPDX-License-Identifier: GPL-3.0-or-later
// vtkMidSurfaceExtractor on thin-walled parts whose mid-surfaces are known
// exactly (vtkAnalyticShapeSource's T-plate, L-bracket and wedge plate),
// and the wall selection's rules in Core.
#include "Geometry/Vec3.h"
#include "Structure/WallSheets.h"
#include "Surface/AnalyticShapes.h"
#include "TestHelpers.h"
#include "vtkAnalyticShapeSource.h"
#include "vtkMidSurfaceExtractor.h"
#include "vtkStructuralMedialAxis.h"

#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkMassProperties.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataConnectivityFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace
{
constexpr double Length = 2.0, Width = 2.0, Height = 1.0, Wall = 0.1;

struct MidSurfaceFigures
{
  double MaximumDeviation = 0.0;      // from the true mid-surface, over all points
  double MaximumThicknessError = 0.0; // relative to the true thickness, over all points
  double Area = 0.0;
  vtkIdType Walls = 0;
  vtkIdType JunctionEdges = 0;
  double FoldedEdges = 0.0;
  int Pieces = 0;
};

// Runs the extractor (which computes the CAD preset's medial axis) on the
// shape and measures it against the truth: the distance from a point to the
// true mid-surface, and the true thickness there.
MidSurfaceFigures Measure(vtkAnalyticShapeSource* shape,
  const std::function<double(const double*)>& deviation,
  const std::function<double(const double*)>& trueThickness)
{
  vtkNew<vtkMidSurfaceExtractor> mid;
  mid->SetInputConnection(shape->GetOutputPort());
  mid->Update();
  vtkPolyData* out = mid->GetOutput();
  MidSurfaceFigures f;
  vtkDataArray* thickness = out->GetPointData()->GetArray("Thickness");
  EXPECT_NE(thickness, nullptr);
  EXPECT_NE(out->GetPointData()->GetArray("MedialVertexId"), nullptr);
  EXPECT_NE(out->GetPointData()->GetArray("PointType"), nullptr);
  EXPECT_NE(out->GetCellData()->GetArray("WallId"), nullptr);
  for (vtkIdType i = 0; thickness && i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    f.MaximumDeviation = std::max(f.MaximumDeviation, deviation(p));
    f.MaximumThicknessError = std::max(
      f.MaximumThicknessError, std::fabs(thickness->GetComponent(i, 0) / trueThickness(p) - 1.0));
  }
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(out);
  mass->Update();
  f.Area = mass->GetSurfaceArea();
  f.Walls = mid->GetNumberOfWalls();
  f.JunctionEdges = mid->GetNumberOfJunctionEdges();
  f.FoldedEdges = out->GetFieldData()->GetArray("FoldedEdges")->GetTuple1(0);
  vtkNew<vtkPolyDataConnectivityFilter> pieces;
  pieces->SetInputData(out);
  pieces->SetExtractionModeToAllRegions();
  pieces->Update();
  f.Pieces = pieces->GetNumberOfExtractedRegions();
  EXPECT_EQ(out->GetFieldData()->GetArray("WallArea")->GetNumberOfTuples(), f.Walls);
  return f;
}

vtkSmartPointer<vtkAnalyticShapeSource> Part(int shape, double fillet)
{
  auto part = vtkSmartPointer<vtkAnalyticShapeSource>::New();
  part->SetShape(shape);
  part->SetXLength(Length);
  part->SetYLength(Width);
  part->SetZLength(Height);
  part->SetThickness(Wall);
  part->SetFilletRadius(fillet);
  return part;
}

double Constant(const double*)
{
  return Wall;
}

// The warnings or errors an object reports: how many, and the last text.
struct Messages
{
  int Count = 0;
  std::string Last;
  vtkNew<vtkCallbackCommand> Command;
  Messages(vtkObject* object, unsigned long event)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback(
      [](vtkObject*, unsigned long, void* self, void* text)
      {
        auto* messages = static_cast<Messages*>(self);
        ++messages->Count;
        messages->Last = text ? static_cast<const char*>(text) : "";
      });
    object->AddObserver(event, this->Command);
  }
};
}

// The plate's mid-plane z = 0 across its whole width and the rib's y = 0
// from there to the rib's top: two walls stitched along the line y = z = 0,
// ends extended to the lateral faces.
TEST(MidSurface, TPlateIsTwoWallsStitchedAtTheJunction)
{
  for (double fillet : { 0.0, 0.1 })
  {
    SCOPED_TRACE(fillet);
    auto part = Part(vtkAnalyticShapeSource::T_PLATE, fillet);
    const auto deviation = [](const double* p)
    {
      const double plate = std::fabs(p[1]) <= 0.5 * Width + 1e-9 ? std::fabs(p[2]) : 1e9;
      const double rib = p[2] >= -1e-9 ? std::fabs(p[1]) : 1e9;
      return std::min(plate, rib);
    };
    const MidSurfaceFigures f = Measure(part, deviation, Constant);
    EXPECT_LE(f.MaximumDeviation, 0.005 * Wall);
    EXPECT_LE(f.MaximumThicknessError, 0.01);
    const double area = Length * (Width + Height + 0.5 * Wall);
    EXPECT_NEAR(f.Area, area, 0.01 * area);
    EXPECT_EQ(f.Walls, 2);
    EXPECT_GT(f.JunctionEdges, 0);
    EXPECT_EQ(f.Pieces, 1);
    EXPECT_EQ(f.FoldedEdges, 0.0);
  }
}

// Sharp: the planes z = t/2 and y = t/2 meeting at a crease (two walls);
// filleted: one wall bending round a quarter circle of radius R + t/2.
TEST(MidSurface, LBracketBendsRoundItsCorner)
{
  for (double fillet : { 0.0, 0.1 })
  {
    SCOPED_TRACE(fillet);
    auto part = Part(vtkAnalyticShapeSource::L_BRACKET, fillet);
    const auto deviation = [fillet](const double* p)
    {
      const double c = Wall + fillet;
      if (fillet > 0.0 && p[1] < c && p[2] < c)
      {
        return std::fabs(std::hypot(p[1] - c, p[2] - c) - (fillet + 0.5 * Wall));
      }
      const double plate = p[1] >= 0.5 * Wall - 1e-9 ? std::fabs(p[2] - 0.5 * Wall) : 1e9;
      const double wall = p[2] >= 0.5 * Wall - 1e-9 ? std::fabs(p[1] - 0.5 * Wall) : 1e9;
      return std::min(plate, wall);
    };
    const MidSurfaceFigures f = Measure(part, deviation, Constant);
    // (The filleted bracket's arcs are tessellated: their triangles alone
    // stand 0.18% of t off the true cylinders.)
    EXPECT_LE(f.MaximumDeviation, 0.005 * Wall);
    EXPECT_LE(f.MaximumThicknessError, 0.01);
    const double area = fillet > 0.0
      ? Length * (Width + Height - 2.0 * (Wall + fillet) + 0.5 * M_PI * (fillet + 0.5 * Wall))
      : Length * (Width + Height - Wall);
    EXPECT_NEAR(f.Area, area, 0.01 * area);
    EXPECT_EQ(f.Walls, fillet > 0.0 ? 1 : 2);
    EXPECT_EQ(f.Pieces, 1);
    EXPECT_EQ(f.FoldedEdges, 0.0);
  }
}

// A plate tapering from 0.05 to 0.1: the mid-plane z = 0, and the
// thickness following the taper.
TEST(MidSurface, WedgePlateThicknessFollowsTheTaper)
{
  auto part = Part(vtkAnalyticShapeSource::WEDGE_PLATE, 0.0);
  part->SetThickness(0.05);
  part->SetEndThickness(0.1);
  const auto thickness = [](const double* p) { return 0.05 + 0.05 * (p[1] + 0.5 * Width) / Width; };
  const MidSurfaceFigures f = Measure(
    part, [](const double* p) { return std::fabs(p[2]); }, thickness);
  EXPECT_LE(f.MaximumDeviation, 0.005 * 0.05);
  EXPECT_LE(f.MaximumThicknessError, 0.01);
  EXPECT_NEAR(f.Area, Length * Width, 0.01 * Length * Width);
  EXPECT_EQ(f.Walls, 1);
  EXPECT_EQ(f.JunctionEdges, 0);
  EXPECT_EQ(f.Pieces, 1);
  EXPECT_EQ(f.FoldedEdges, 0.0);
}

// A hollow ball (walls curved both ways, one side convex, the other
// concave): one closed wall, the sphere halfway between the shells.
TEST(MidSurface, HollowBallIsTheMiddleSphere)
{
  const double outer = 0.5, inner = 0.4, middle = 0.45, thickness = outer - inner;
  using namespace medialaxis;
  const TriangleMesh outerShell = MakeSphere(outer, 24), innerShell = MakeSphere(inner, 24);
  // How far the shells' triangles stand inside their spheres (at their
  // centroids): the tessellation's share of the error.
  const auto sag = [](const TriangleMesh& shell, double radius)
  {
    double deepest = 0.0;
    for (const auto& t : shell.Triangles)
    {
      const Point3 c = (1.0 / 3.0) * (shell.Points[t[0]] + shell.Points[t[1]] + shell.Points[t[2]]);
      deepest = std::max(deepest, radius - Norm(c));
    }
    return deepest;
  };
  const double tessellation = 0.5 * (sag(outerShell, outer) + sag(innerShell, inner));
  const auto shells = test::ToPolyData(test::Append(outerShell, innerShell));
  vtkNew<vtkMidSurfaceExtractor> mid;
  mid->SetInputData(shells);
  mid->Update();
  vtkPolyData* out = mid->GetOutput();
  ASSERT_GT(out->GetNumberOfPoints(), 0);
  vtkDataArray* t = out->GetPointData()->GetArray("Thickness");
  vtkDataArray* types = out->GetPointData()->GetArray("PointType");
  double deviation = 0.0, thicknessError = 0.0;
  int worstType = -1;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3];
    out->GetPoint(i, p);
    const double d = std::fabs(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]) - middle);
    if (d > deviation)
    {
      deviation = d;
      worstType = static_cast<int>(types->GetComponent(i, 0));
    }
    thicknessError = std::max(thicknessError, std::fabs(t->GetComponent(i, 0) / thickness - 1.0));
  }
  EXPECT_LE(deviation, tessellation + 0.005 * thickness)
    << "tessellation " << tessellation << ", point type " << worstType;
  EXPECT_LE(thicknessError, 0.01);
  EXPECT_EQ(mid->GetNumberOfWalls(), 1);
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(out);
  mass->Update();
  const double area = 4.0 * M_PI * middle * middle;
  EXPECT_NEAR(mass->GetSurfaceArea(), area, 0.01 * area);
}

// A part without thin walls gives an empty mid-surface (and a warning, not
// an error); so does a wall thicker than the WallThickness the user sets.
TEST(MidSurface, NoWallsWhereNothingIsThin)
{
  // Progress through the medial axis it computes, to the end.
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> record;
  record->SetClientData(&progress);
  record->SetCallback([](vtkObject*, unsigned long, void* data, void* amount)
    { static_cast<std::vector<double>*>(data)->push_back(*static_cast<double*>(amount)); });

  vtkNew<vtkAnalyticShapeSource> box;
  box->SetShapeToBox();
  vtkNew<vtkMidSurfaceExtractor> mid;
  const Messages warnings(mid, vtkCommand::WarningEvent);
  mid->AddObserver(vtkCommand::ProgressEvent, record);
  mid->SetInputConnection(box->GetOutputPort());
  mid->Update();
  EXPECT_EQ(mid->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(mid->GetNumberOfWallSheets(), 0);
  EXPECT_EQ(warnings.Count, 1);
  ASSERT_GT(progress.size(), 3u);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_GT(
    std::count_if(progress.begin(), progress.end(), [](double p) { return p > 0.0 && p < 0.5; }),
    0);
  EXPECT_EQ(progress.back(), 1.0);

  auto part = Part(vtkAnalyticShapeSource::T_PLATE, 0.0);
  mid->SetInputConnection(part->GetOutputPort());
  mid->SetWallThickness(0.5 * Wall);
  mid->Update();
  EXPECT_EQ(mid->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_EQ(warnings.Count, 2);
  mid->SetWallThickness(2.0 * Wall);
  mid->Update();
  EXPECT_EQ(mid->GetNumberOfWalls(), 2);
  EXPECT_DOUBLE_EQ(mid->GetEstimatedWallThickness(), 2.0 * Wall);
}

// The same part and medial-axis settings give the same mid-surface, bit for
// bit, at any thread count.
TEST(MidSurface, SameResultAtAnyThreadCount)
{
  auto part = Part(vtkAnalyticShapeSource::T_PLATE, 0.1);
  std::vector<std::vector<double>> results;
  for (int threads : { 1, 2 })
  {
    vtkNew<vtkStructuralMedialAxis> mat;
    mat->SetInputConnection(part->GetOutputPort());
    mat->SetPresetToCAD();
    mat->SetNumberOfSamples(20000);
    mat->SetTargetNumberOfVertices(2000);
    mat->SetNumberOfThreads(threads);
    vtkNew<vtkMidSurfaceExtractor> mid;
    mid->SetInputConnection(0, part->GetOutputPort());
    mid->SetMedialAxisConnection(mat->GetOutputPort(0));
    mid->Update();
    vtkPolyData* out = mid->GetOutput();
    std::vector<double> values;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double p[3];
      out->GetPoint(i, p);
      values.insert(values.end(), p, p + 3);
      values.push_back(out->GetPointData()->GetArray("Thickness")->GetComponent(i, 0));
    }
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    for (out->GetPolys()->InitTraversal(); out->GetPolys()->GetNextCell(n, ids);)
    {
      values.insert(values.end(), ids, ids + n);
    }
    results.push_back(values);
  }
  ASSERT_FALSE(results[0].empty());
  EXPECT_EQ(results[0], results[1]);
}

// A medial mesh without radii is refused with an error naming it.
TEST(MidSurface, MedialMeshWithoutRadiusIsRefused)
{
  auto part = Part(vtkAnalyticShapeSource::T_PLATE, 0.0);
  vtkNew<vtkMidSurfaceExtractor> mid;
  const Messages errors(mid, vtkCommand::ErrorEvent);
  mid->SetInputConnection(0, part->GetOutputPort());
  mid->SetMedialAxisConnection(part->GetOutputPort()); // a surface, no radii
  mid->Update();
  EXPECT_EQ(errors.Count, 1);
  EXPECT_NE(errors.Last.find("Radius"), std::string::npos) << errors.Last;
  EXPECT_EQ(mid->GetOutput()->GetNumberOfCells(), 0);
}

// The slope of the radius on a triangle, and MidSurfer's automatic wall
// thickness: the largest value in the fullest histogram bin.
TEST(MidSurface, WallRules)
{
  using medialaxis::Point3;
  // r = 0.1 + 0.2 x on the unit right triangle: |grad r| = 0.2.
  EXPECT_NEAR(
    medialaxis::RadiusSlope(Point3{ 0, 0, 0 }, Point3{ 1, 0, 0 }, Point3{ 0, 1, 0 }, 0.1, 0.3, 0.1),
    0.2, 1e-12);
  EXPECT_EQ(
    medialaxis::RadiusSlope(Point3{ 0, 0, 0 }, Point3{ 1, 0, 0 }, Point3{ 2, 0, 0 }, 0.1, 0.2, 0.3),
    1.0);
  // Most of the area 0.1 thick (0.1 to 0.1008, one bin 5% of the median
  // wide), a little 0.3 thick.
  const std::vector<double> thickness{ 0.1, 0.1004, 0.1008, 0.3, 0.31 };
  const std::vector<double> area{ 3.0, 3.0, 3.0, 1.0, 1.0 };
  EXPECT_DOUBLE_EQ(medialaxis::WallThicknessFromHistogram(thickness, area), 0.1008);
  EXPECT_EQ(medialaxis::WallThicknessFromHistogram({}, {}), 0.0);
}
