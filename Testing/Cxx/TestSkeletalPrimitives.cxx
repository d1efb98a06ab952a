// SPDX-License-Identifier: GPL-3.0-or-later
// Generalized enveloping primitives of the Medial Skeletal Diagram: their
// templates, and their fits on shapes one element describes exactly (an
// ellipsoid from its centre, a capsule from its axis).
#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"
#include "Skeletal/PrimitiveFit.h"
#include "Skeletal/PrimitiveTemplate.h"
#include "Skeletal/PrimitiveUnion.h"
#include "Skeletal/SkeletalDiagram.h"
#include "Surface/AnalyticShapes.h"

#include "TestHelpers.h"
#include "vtkAnalyticShapeSource.h"
#include "vtkCallbackCommand.h"
#include "vtkCompositeDataSet.h"
#include "vtkDistanceGridContour.h"
#include "vtkFieldData.h"
#include "vtkGeneralizedPrimitiveFitter.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMedialReconstructionError.h"
#include "vtkMedialSkeletalDiagram.h"
#include "vtkPartitionedDataSet.h"
#include "vtkPartitionedDataSetCollection.h"
#include "vtkPointData.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfacePreparation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <stdexcept>

using namespace medialaxis;

namespace
{
// Six times the signed volume enclosed by the template at unit radius.
double SignedVolume6(const PrimitiveTemplate& shape)
{
  const std::vector<Point3> points =
    PrimitivePoints(shape, std::vector<double>(shape.Base.size(), 1.0));
  double volume = 0.0;
  for (const Triangle& t : shape.Triangles)
  {
    volume += Dot(points[t[0]], Cross(points[t[1]], points[t[2]]));
  }
  return volume;
}

// Every edge of a closed template is shared by exactly two triangles, once
// in each direction.
bool ClosedAndConsistent(const PrimitiveTemplate& shape)
{
  std::map<std::pair<Index, Index>, int> directed;
  for (const Triangle& t : shape.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      ++directed[{ t[k], t[(k + 1) % 3] }];
    }
  }
  for (const auto& [edge, count] : directed)
  {
    const auto back = directed.find({ edge.second, edge.first });
    if (count != 1 || back == directed.end() || back->second != 1)
    {
      return false;
    }
  }
  return true;
}

// How deep the surface's vertices and triangle centroids lie inside the
// closed mesh `primitive`: the largest depth (0 when none is inside).
double DeepestSurfacePoint(const TriangleMesh& surface, const TriangleMesh& primitive)
{
  const TriangleLocator locator(primitive);
  std::vector<Point3> points = surface.Points;
  for (const Triangle& t : surface.Triangles)
  {
    points.push_back(
      (1.0 / 3.0) * (surface.Points[t[0]] + surface.Points[t[1]] + surface.Points[t[2]]));
  }
  double deepest = 0.0;
  for (const Point3& p : points)
  {
    if (locator.Inside(p))
    {
      deepest = std::max(deepest, locator.Distance(p));
    }
  }
  return deepest;
}

// Enclosed volume of a closed, outward mesh.
double Volume(const TriangleMesh& mesh)
{
  double volume = 0.0;
  for (const Triangle& t : mesh.Triangles)
  {
    volume += Dot(mesh.Points[t[0]], Cross(mesh.Points[t[1]], mesh.Points[t[2]]));
  }
  return volume / 6.0;
}
}

TEST(SkeletalPrimitives, TemplatesAreClosedAndOutward)
{
  const PrimitiveTemplate sphere = MakeVertexTemplate({ 1, 2, 3 }, 3);
  EXPECT_EQ(sphere.Base.size(), 642u);
  EXPECT_EQ(sphere.Triangles.size(), 1280u);
  EXPECT_TRUE(ClosedAndConsistent(sphere));
  // The unit sphere's volume, within its tessellation.
  EXPECT_NEAR(SignedVolume6(sphere) / 6.0, 4.0 / 3.0 * M_PI, 0.02 * 4.0 / 3.0 * M_PI);

  const PrimitiveTemplate edge = MakeEdgeTemplate({ 0, 0, 0 }, { 0, 0, 2 }, 32, 0.25);
  EXPECT_TRUE(ClosedAndConsistent(edge));
  // A unit-radius capsule of axis length 2.
  const double capsule = M_PI * 2.0 + 4.0 / 3.0 * M_PI;
  EXPECT_NEAR(SignedVolume6(edge) / 6.0, capsule, 0.03 * capsule);
  for (std::size_t j = 0; j < edge.Base.size(); ++j)
  {
    EXPECT_NEAR(Norm(edge.Direction[j]), 1.0, 1e-12);
  }
  // A triangle's: Steiner's formula for the unit neighbourhood of a flat
  // convex set, 2 A + pi / 2 P + 4 / 3 pi (faces, half-cylinders, wedges).
  const Point3 a{ 0, 0, 0 }, b{ 2, 0, 0.5 }, c{ 0.3, 1.5, 0 };
  const PrimitiveTemplate triangle = MakeTriangleTemplate(a, b, c, 32, 0.2);
  EXPECT_TRUE(ClosedAndConsistent(triangle));
  const double area = 0.5 * Norm(Cross(b - a, c - a));
  const double perimeter = Norm(b - a) + Norm(c - b) + Norm(a - c);
  const double slab = 2.0 * area + 0.5 * M_PI * perimeter + 4.0 / 3.0 * M_PI;
  EXPECT_NEAR(SignedVolume6(triangle) / 6.0, slab, 0.03 * slab);
  EXPECT_THROW(MakeTriangleTemplate(a, b, 2.0 * b, 32, 0.2), std::invalid_argument);
  EXPECT_THROW(MakeEdgeTemplate({ 0, 0, 0 }, { 0, 0, 0 }, 32, 0.25), std::invalid_argument);
  EXPECT_THROW(MakeVertexTemplate({ 0, 0, 0 }, 9), std::invalid_argument);
}

// An ellipsoid is star-shaped from its centre: one vertex primitive.
TEST(SkeletalPrimitives, OneVertexPrimitiveIsAnEllipsoid)
{
  TriangleMesh ellipsoid = MakeSphere(1.0, 24);
  for (Point3& p : ellipsoid.Points)
  {
    p = { p[0], 0.7 * p[1], 0.5 * p[2] };
  }
  const TriangleLocator locator(ellipsoid);
  const PrimitiveTemplate shape = MakeVertexTemplate({ 0, 0, 0 }, 3);
  const FittedPrimitive fit = FitPrimitive(ellipsoid, locator, shape);
  ASSERT_TRUE(fit.Error.empty()) << fit.Error;
  double largestGap = 0.0, meanGap = 0.0;
  for (std::size_t j = 0; j < fit.Radius.size(); ++j)
  {
    EXPECT_LE(fit.Radius[j], fit.MaximumRadius[j]);
    const double gap = fit.MaximumRadius[j] - fit.Radius[j];
    largestGap = std::max(largestGap, gap);
    meanGap += gap / static_cast<double>(fit.Radius.size());
  }
  std::cout << "ellipsoid: " << fit.Progressions << " progressions, gap to the surface mean "
            << meanGap << ", largest " << largestGap << "\n";
  // Radii reach the surface: the gap is a small fraction of the smallest
  // semi-axis, 0.5 (measured: mean 0.00025, largest 0.0028, at the tips of
  // the long axis, where smoothness rounds the radius function).
  EXPECT_LT(meanGap, 0.001);
  EXPECT_LT(largestGap, 0.01);
}

// A capsule is the envelope of its axis: one edge primitive of constant
// radius. Its rays run through the capsule's own vertices and edges and
// along the planes of its triangles' bounding boxes (the pole ray has
// components -0): before the locator's ray test took such rays, some
// slipped through and the fit refused the capsule.
TEST(SkeletalPrimitives, OneEdgePrimitiveIsACapsule)
{
  const double radius = 0.3;
  const TriangleMesh capsule = MakeCapsule(radius, 1.0, 24);
  const TriangleLocator locator(capsule);
  const PrimitiveTemplate shape = MakeEdgeTemplate({ 0, 0, -0.5 }, { 0, 0, 0.5 }, 32, 0.1);
  const FittedPrimitive fit = FitPrimitive(capsule, locator, shape);
  ASSERT_TRUE(fit.Error.empty()) << fit.Error;
  double lo = 1e300, hi = 0.0;
  for (double r : fit.Radius)
  {
    lo = std::min(lo, r);
    hi = std::max(hi, r);
  }
  std::cout << "capsule: radii " << lo << " to " << hi << "\n";
  EXPECT_GT(lo, 0.98 * radius);
  EXPECT_LE(hi, radius * (1.0 + 1e-9));
}

// A thin box from two triangle elements on its middle plane: the faces'
// radii are half its thickness, and the union of the two primitives covers
// its surface (its walls and corners reached by the half-cylinders and the
// corner wedges).
TEST(SkeletalPrimitives, TwoTrianglePrimitivesCoverAThinBox)
{
  const double half = 1.0, thickness = 0.4, inset = 0.9;
  const TriangleMesh box = MakeRoundedBox({ 2 * half, 2 * half, thickness }, 0.0, 16);
  const TriangleLocator locator(box);
  const Point3 p00{ -inset, -inset, 0 }, p10{ inset, -inset, 0 }, p11{ inset, inset, 0 },
    p01{ -inset, inset, 0 };
  TriangleMesh united;
  for (const auto& corners :
    { std::array<Point3, 3>{ p00, p10, p11 }, std::array<Point3, 3>{ p00, p11, p01 } })
  {
    const PrimitiveTemplate shape =
      MakeTriangleTemplate(corners[0], corners[1], corners[2], 32, 0.1);
    const FittedPrimitive fit = FitPrimitive(box, locator, shape);
    ASSERT_TRUE(fit.Error.empty()) << fit.Error;
    for (std::size_t j = 0; j < shape.Base.size(); ++j)
    {
      EXPECT_LE(fit.Radius[j], fit.MaximumRadius[j]);
      if (std::abs(std::abs(shape.Direction[j][2]) - 1.0) < 1e-12)
      {
        EXPECT_NEAR(fit.Radius[j], 0.5 * thickness, 0.01 * thickness);
      }
    }
    const std::vector<Point3> points = PrimitivePoints(shape, fit.Radius);
    const Index offset = static_cast<Index>(united.Points.size());
    united.Points.insert(united.Points.end(), points.begin(), points.end());
    for (const Triangle& t : shape.Triangles)
    {
      united.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
    }
  }
  // Every point of the box's surface lies near the union's surface.
  const TriangleLocator unionLocator(united);
  // Its sharp edges are where the smooth radius functions fall short most
  // (measured: 0.019 on the rims next to the corners, 0.001 elsewhere).
  double farthest = 0.0, farthestOffEdges = 0.0;
  for (const Point3& p : box.Points)
  {
    const double d = unionLocator.Distance(p);
    farthest = std::max(farthest, d);
    const int bounds = (std::abs(std::abs(p[0]) - half) < 1e-9) +
      (std::abs(std::abs(p[1]) - half) < 1e-9) +
      (std::abs(std::abs(p[2]) - 0.5 * thickness) < 1e-9);
    farthestOffEdges = bounds >= 2 ? farthestOffEdges : std::max(farthestOffEdges, d);
  }
  std::cout << "thin box: farthest surface point from the two primitives " << farthest
            << ", off the box's edges " << farthestOffEdges << "\n";
  EXPECT_LT(farthest, 0.1 * thickness);
  EXPECT_LT(farthestOffEdges, 0.01 * thickness);
}

TEST(SkeletalPrimitives, AnElementOutsideTheSurfaceIsRefused)
{
  const TriangleMesh sphere = MakeSphere(1.0, 12);
  const TriangleLocator locator(sphere);
  const FittedPrimitive fit = FitPrimitive(sphere, locator, MakeVertexTemplate({ 3, 0, 0 }, 2));
  EXPECT_TRUE(fit.Radius.empty());
  EXPECT_NE(fit.Error.find("not inside"), std::string::npos) << fit.Error;
}

// The VTK filter as users wire it: a capsule and its axis drawn by hand (two
// points and a line) give two vertex primitives and one edge primitive of
// the capsule's radius; a point outside the surface gets an empty primitive
// and a warning; a polygon that is no triangle is refused.
TEST(SkeletalPrimitives, VtkFilterFitsEachElementOfASkeleton)
{
  const double radius = 0.3, length = 1.0;
  vtkNew<vtkAnalyticShapeSource> capsule;
  capsule->SetShapeToCapsule();
  capsule->SetRadius(radius);
  capsule->SetLength(length);
  vtkNew<vtkPolyData> skeleton;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, -0.5 * length);
  points->InsertNextPoint(0, 0, 0.5 * length);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 1 };
  lines->InsertNextCell(2, line);
  skeleton->SetPoints(points);
  skeleton->SetLines(lines);

  vtkNew<vtkGeneralizedPrimitiveFitter> fitter;
  fitter->SetInputConnection(capsule->GetOutputPort());
  fitter->SetInputDataObject(1, skeleton);
  std::vector<double> progress;
  vtkNew<vtkCallbackCommand> record;
  record->SetClientData(&progress);
  record->SetCallback([](vtkObject*, unsigned long, void* list, void* amount)
    { static_cast<std::vector<double>*>(list)->push_back(*static_cast<double*>(amount)); });
  fitter->AddObserver(vtkCommand::ProgressEvent, record);
  fitter->Update();
  vtkPartitionedDataSetCollection* out = fitter->GetOutput();
  ASSERT_EQ(out->GetNumberOfPartitionedDataSets(), 3u);
  EXPECT_EQ(fitter->GetNumberOfFailedElements(), 0);
  EXPECT_EQ(progress.back(), 1.0);
  const char* names[3] = { "vertex 0", "vertex 1", "edge 0-1" };
  for (unsigned int e = 0; e < 3; ++e)
  {
    auto* mesh = vtkPolyData::SafeDownCast(out->GetPartition(e, 0));
    ASSERT_NE(mesh, nullptr);
    EXPECT_STREQ(out->GetMetaData(e)->Get(vtkCompositeDataSet::NAME()), names[e]);
    auto* type = vtkIntArray::SafeDownCast(mesh->GetFieldData()->GetArray("ElementType"));
    ASSERT_NE(type, nullptr);
    EXPECT_EQ(type->GetValue(0), e < 2 ? 0 : 1);
    vtkDataArray* r = mesh->GetPointData()->GetArray("Radius");
    ASSERT_NE(r, nullptr);
    ASSERT_NE(mesh->GetPointData()->GetArray("MaximumRadius"), nullptr);
    EXPECT_GT(mesh->GetNumberOfCells(), 0);
    double range[2];
    r->GetRange(range);
    if (e == 2)
    {
      // The edge primitive is the capsule.
      EXPECT_GT(range[0], 0.98 * radius);
      EXPECT_LE(range[1], radius * (1.0 + 1e-6));
    }
    else
    {
      // A vertex primitive is star-shaped from its point: from one end of
      // the axis it reaches across the whole capsule.
      EXPECT_NEAR(range[1], length + radius, 0.01 * radius);
    }
  }

  // A point outside the capsule: its vertex and edge get no primitive.
  points->InsertNextPoint(0, 0, 2.0);
  const vtkIdType outside[2] = { 1, 2 };
  vtkNew<vtkCellArray> longer;
  longer->InsertNextCell(2, line);
  longer->InsertNextCell(2, outside);
  skeleton->SetLines(longer);
  vtkNew<test::ErrorCatcher> warnings;
  fitter->AddObserver(vtkCommand::WarningEvent, warnings);
  fitter->Update();
  EXPECT_EQ(out->GetNumberOfPartitionedDataSets(), 5u);
  EXPECT_EQ(fitter->GetNumberOfFailedElements(), 2);
  EXPECT_EQ(warnings->Count, 1);
  EXPECT_NE(warnings->Last.find("vertex 2"), std::string::npos) << warnings->Last;
  EXPECT_EQ(vtkPolyData::SafeDownCast(out->GetPartition(2, 0))->GetNumberOfPoints(), 0);

  // A quad is refused.
  vtkNew<vtkCellArray> quads;
  const vtkIdType quad[4] = { 0, 1, 2, 1 };
  quads->InsertNextCell(4, quad);
  skeleton->SetPolys(quads);
  vtkNew<test::ErrorCatcher> errors;
  fitter->AddObserver(vtkCommand::ErrorEvent, errors);
  fitter->Update();
  EXPECT_EQ(errors->Count, 1);
  EXPECT_NE(errors->Last.find("triangulate"), std::string::npos) << errors->Last;
}

// The sparse skeleton from a simplified MAT: sites added where the surface
// lies farthest from the primitives until it is within 0.5% of the
// diagonal. An ellipsoid needs its centre alone (it is star-shaped from
// it); a capsule and a dumbbell a few elements along their axes.
TEST(SkeletalDiagram, FewElementsCoverSimpleShapes)
{
  TriangleMesh ellipsoid = MakeSphere(1.0, 16);
  for (Point3& p : ellipsoid.Points)
  {
    p = { p[0], 0.7 * p[1], 0.5 * p[2] };
  }
  const struct
  {
    const char* Name;
    TriangleMesh Surface;
    std::size_t MaximumElements;
  } shapes[] = { { "ellipsoid", ellipsoid, 3 }, { "capsule", MakeCapsule(0.3, 1.0, 12), 3 },
    { "dumbbell", MakeDumbbell(1.2, 0.25, 0.1, 12), 5 } };
  for (const auto& shape : shapes)
  {
    SCOPED_TRACE(shape.Name);
    const test::SimplifiedRun run = test::Simplify(shape.Surface, 5000, 100, false);
    SkeletalDiagramOptions options;
    const SkeletalDiagram diagram =
      BuildSkeletalDiagram(shape.Surface, run.Result.Medial.Mesh, options);
    std::cout << shape.Name << ": " << diagram.Points.size() << " vertices, "
              << diagram.Edges.size() << " edges, " << diagram.Triangles.size()
              << " triangles after " << diagram.Insertions << " insertions; error "
              << 100.0 * diagram.Error / diagram.Diagonal << "% (mean "
              << 100.0 * diagram.MeanError / diagram.Diagonal << "%), " << diagram.FailedElements
              << " failed\n";
    EXPECT_LE(diagram.Error, options.MaximumError * diagram.Diagonal);
    EXPECT_LE(diagram.NumberOfElements(), shape.MaximumElements);
    EXPECT_EQ(diagram.Primitives.size(), diagram.NumberOfElements());
    EXPECT_EQ(diagram.FailedElements, 0);
  }

  // From its centre alone (a skeleton of one sphere), the ellipsoid is one
  // vertex primitive within the error bound, once its directions are fine
  // enough for the curvature at the tips of its long axis (radius of
  // curvature 0.25 at a distance 1: at 3 subdivisions, 642 directions 8
  // degrees apart, the chords there fall 0.56% of the diagonal short).
  MedialMesh centre;
  centre.Centers = { { 0, 0, 0 } };
  centre.Radii = { 0.5 };
  SkeletalDiagramOptions fine;
  fine.VertexSubdivisions = 4;
  const SkeletalDiagram one = BuildSkeletalDiagram(ellipsoid, centre, fine);
  std::cout << "ellipsoid from its centre: error " << 100.0 * one.Error / one.Diagonal << "%\n";
  EXPECT_EQ(one.NumberOfElements(), 1u);
  EXPECT_LE(one.Error, SkeletalDiagramOptions().MaximumError * one.Diagonal);
}

// Three sites spread round a torus (R = 1, r = 0.2): the chord between two
// of them (0.5 from the centre) crosses the hole, so each skeletal edge is
// routed along the medial ring and bends inside the tube. Every element
// gets a primitive, every straight piece stays inside, and the skeleton
// keeps the torus's one loop.
TEST(SkeletalDiagram, EdgesAcrossAHoleAreRoutedInside)
{
  const TriangleMesh torus = MakeTorus(1.0, 0.2, 48);
  const test::SimplifiedRun run = test::Simplify(torus, 5000, 200, false);
  SkeletalDiagramOptions options;
  options.InitialSites = 3;
  options.MaximumElements = 6;
  // The primitives' refinement does not bear on the routes (and on a bent
  // tube it is what takes the time).
  options.Fit.MaximumRefinements = 0;
  const SkeletalDiagram diagram = BuildSkeletalDiagram(torus, run.Result.Medial.Mesh, options);
  std::size_t bends = 0;
  for (const auto& b : diagram.EdgeBends)
  {
    bends += b.size();
  }
  std::cout << "torus: " << diagram.Points.size() << " vertices, " << diagram.Edges.size()
            << " edges with " << bends << " bends, " << diagram.Triangles.size()
            << " triangles; error " << 100.0 * diagram.Error / diagram.Diagonal << "%, "
            << diagram.FailedElements << " failed\n";
  ASSERT_EQ(diagram.Points.size(), 3u);
  ASSERT_EQ(diagram.Edges.size(), 3u);
  EXPECT_EQ(diagram.FailedElements, 0);
  EXPECT_GE(bends, 3u);
  const TriangleLocator locator(torus);
  for (std::size_t e = 0; e < diagram.Edges.size(); ++e)
  {
    const std::vector<Point3> line = diagram.EdgePolyline(e);
    for (std::size_t k = 0; k + 1 < line.size(); ++k)
    {
      const Point3 d = line[k + 1] - line[k];
      EXPECT_LT(locator.FirstHit(line[k], Normalized(d), 0.0, Norm(d)).Triangle, 0)
        << "edge " << e << " piece " << k;
      EXPECT_TRUE(locator.Inside(line[k]));
    }
  }
  // One primitive per vertex, per straight piece and per triangle, each
  // belonging to its element.
  EXPECT_EQ(diagram.Primitives.size(), diagram.PieceElement.size());
  EXPECT_EQ(diagram.Primitives.size(),
    diagram.Points.size() + diagram.Edges.size() + bends + diagram.Triangles.size());
  EXPECT_TRUE(std::is_sorted(diagram.PieceElement.begin(), diagram.PieceElement.end()));
  EXPECT_EQ(diagram.PieceElement.back(), static_cast<Index>(diagram.NumberOfElements() - 1));
  // The loop round the hole: a cycle of three edges.
  EXPECT_EQ(diagram.Triangles.size(), 0u);
}

// A vertex primitive in one arm of an L-shaped block: two neighbouring
// directions of a coarse template pass either side of the reflex edge and
// run far along the two arms, so the triangle between them cuts across the
// edge and the primitive leaves the block there. Refinement splits the
// template where surface points lie inside it and fits again, until none
// lies deeper than the tolerance.
TEST(SkeletalPrimitives, RefinementKeepsAPrimitiveInsideAReflexEdge)
{
  const TriangleMesh block = MakeLBlock({ 2, 2, 1 }, 8);
  const TriangleLocator locator(block);
  const Point3 centre{ -0.5, -0.5, 0.0 };
  const PrimitiveTemplate coarse = MakeVertexTemplate(centre, 2);
  const FittedPrimitive plain = FitPrimitive(block, locator, coarse);
  ASSERT_TRUE(plain.Error.empty()) << plain.Error;
  PrimitiveFitOptions options;
  options.RefinementTolerance = 0.01;
  PrimitiveTemplate refined = coarse;
  const FittedPrimitive fit = FitPrimitiveRefined(block, locator, refined, options);
  ASSERT_TRUE(fit.Error.empty()) << fit.Error;
  const double before = DeepestSurfacePoint(block, PrimitiveSurface(coarse, plain));
  const double after = DeepestSurfacePoint(block, PrimitiveSurface(refined, fit));
  std::cout << "L-block: surface up to " << before << " inside the primitive, " << after
            << " after refinement (" << coarse.Base.size() << " -> " << refined.Base.size()
            << " directions)\n";
  EXPECT_GT(before, 5.0 * options.RefinementTolerance);
  EXPECT_LE(after, options.RefinementTolerance);
  EXPECT_TRUE(ClosedAndConsistent(refined));
  EXPECT_GT(refined.Base.size(), coarse.Base.size());
  EXPECT_LE(refined.Base.size(), options.RefinementGrowth * coarse.Base.size());
  for (std::size_t j = 0; j < fit.Radius.size(); ++j)
  {
    EXPECT_LE(fit.Radius[j], fit.MaximumRadius[j]);
  }
}

// Exact radii on an ellipsoid from its centre: every direction's radius is
// its ray's exit, and the template is split where the surface lies between
// directions, outside or inside, farther than the tolerance. The smooth
// fit stops short wherever the radii vary (towards the long axis's tips);
// the exact one meets the surface within the tolerance both ways.
TEST(SkeletalPrimitives, ExactRadiiMeetTheSurfaceBothWays)
{
  TriangleMesh ellipsoid = MakeSphere(1.0, 48);
  for (Point3& p : ellipsoid.Points)
  {
    p = { p[0], 0.6 * p[1], 0.4 * p[2] };
  }
  const TriangleLocator locator(ellipsoid);
  PrimitiveFitOptions smooth, exact;
  smooth.RefinementTolerance = exact.RefinementTolerance = 0.005;
  exact.ExactRadii = true;
  exact.RefinementGrowth = 32;
  exact.MaximumRefinements = 16;
  auto farthest = [&](const PrimitiveFitOptions& options, double& mean, std::size_t& directions)
  {
    PrimitiveTemplate shape = MakeVertexTemplate({ 0, 0, 0 }, 2);
    const FittedPrimitive fit = FitPrimitiveRefined(ellipsoid, locator, shape, options);
    EXPECT_TRUE(fit.Error.empty()) << fit.Error;
    EXPECT_TRUE(ClosedAndConsistent(shape));
    const TriangleMesh mesh = PrimitiveSurface(shape, fit);
    const TriangleLocator primitive(mesh);
    double largest = 0.0, sum = 0.0;
    for (const Point3& p : ellipsoid.Points)
    {
      const double d = primitive.Distance(p);
      largest = std::max(largest, d);
      sum += d;
    }
    mean = sum / static_cast<double>(ellipsoid.Points.size());
    directions = shape.Base.size();
    return largest;
  };
  double smoothMean = 0.0, exactMean = 0.0;
  std::size_t smoothDirections = 0, exactDirections = 0;
  const double smoothFarthest = farthest(smooth, smoothMean, smoothDirections);
  const double exactFarthest = farthest(exact, exactMean, exactDirections);
  std::cout << "ellipsoid from its centre: smooth fit " << smoothFarthest << " (mean " << smoothMean
            << ", " << smoothDirections << " directions), exact " << exactFarthest << " (mean "
            << exactMean << ", " << exactDirections << " directions)\n";
  EXPECT_LE(exactFarthest, 2.0 * exact.RefinementTolerance);
  EXPECT_LT(exactMean, 0.25 * smoothMean);
  EXPECT_LT(exactFarthest, 0.5 * smoothFarthest);
}

// The union's F sampled block by block (LocalSignedDistance) is the same
// as point by point within the band the grid needs; a face's side decides
// the sign of TriangleLocator::SignedDistance as Inside does.
TEST(SkeletalPrimitives, LocalDistanceAgreesWithTheUnion)
{
  TriangleMesh left = MakeSphere(1.0, 24), right = MakeSphere(0.6, 16);
  for (Point3& p : right.Points)
  {
    p = p + Point3{ 1.2, 0.3, 0.0 };
  }
  const PrimitiveUnion both({ left, right });
  const TriangleLocator sphere(left);
  const double radius = 0.1;
  int compared = 0;
  for (int i = 0; i < 20; ++i)
  {
    const Point3 centre{ -1.3 + 0.16 * i, 0.05 * i - 0.4, 0.3 - 0.02 * i };
    const auto local = both.LocalSignedDistance(centre, radius);
    for (const Point3& offset : { Point3{ 0, 0, 0 }, Point3{ 0.05, -0.05, 0.03 },
           Point3{ -0.04, 0.06, -0.05 }, Point3{ 0.0, 0.0, 0.099 } })
    {
      const Point3 x = centre + offset;
      const double exact = both.SignedDistance(x), f = local(x);
      EXPECT_EQ(f < 0.0, exact < 0.0) << "at " << x[0] << " " << x[1] << " " << x[2];
      // Beyond twice the radius only a bound with the right sign is needed.
      EXPECT_NEAR(f, std::abs(exact) < 2.0 * radius ? exact : f, 1e-9);
      EXPECT_LE(std::abs(f), std::abs(exact) + 1e-9);
      EXPECT_EQ(sphere.SignedDistance(x) < 0.0, sphere.Inside(x));
      ++compared;
    }
  }
  EXPECT_EQ(compared, 80);
}

// The inside test on a mesh with a fold: a sliver of inverted triangles
// (a flat tetrahedron, 0.001 thick, turned inside out, as refinement can
// leave where radii change fast) lies on the first ray from a point outside
// a sphere. The ray meets the sliver's face that turns away first, which
// alone says "inside"; its other face, facing the other way right behind
// it, marks a fold, and the next direction decides.
TEST(SkeletalPrimitives, InsideTestLooksPastAFold)
{
  TriangleMesh mesh = MakeSphere(1.0, 16);
  const Point3 outside{ -2.0, -2.0, -2.0 };
  const Point3 ray = Normalized(Point3{ 0.5773, 0.6042, 0.5497 });
  Point3 e1 = Normalized(Cross(ray, Point3{ 1, 0, 0 })), e2 = Cross(ray, e1);
  const Point3 front = outside + 0.5 * ray, back = front + 0.001 * ray;
  const Index first = static_cast<Index>(mesh.Points.size());
  for (const Point3& p :
    { front + 0.1 * e1, front - 0.05 * e1 + 0.09 * e2, front - 0.05 * e1 - 0.09 * e2, back })
  {
    mesh.Points.push_back(p);
  }
  // Inward faces: the face towards the point (front) faces along the ray.
  const std::vector<Triangle> sliver = { { first, first + 1, first + 2 },
    { first, first + 3, first + 1 }, { first + 1, first + 3, first + 2 },
    { first + 2, first + 3, first } };
  mesh.Triangles.insert(mesh.Triangles.end(), sliver.begin(), sliver.end());
  const TriangleLocator locator(mesh);
  const auto hit = locator.FirstHit(outside, ray, 0.0, 10.0);
  ASSERT_GE(hit.Triangle, static_cast<Index>(mesh.Triangles.size() - sliver.size()));
  EXPECT_FALSE(locator.Inside(outside));
  EXPECT_TRUE(locator.Inside({ 0.1, 0.2, 0.3 }));
}

// The union of two overlapping spheres as one closed surface: F's sign and
// bounds, and the contoured surface's volume against the exact union's.
TEST(SkeletalPrimitives, UnionOfPrimitivesIsOneClosedSurface)
{
  TriangleMesh left = MakeSphere(1.0, 32), right = left;
  for (Point3& p : right.Points)
  {
    p[0] += 1.5;
  }
  const PrimitiveUnion both({ left, right, TriangleMesh() });
  EXPECT_EQ(both.NumberOfPrimitives(), 2u);
  EXPECT_NEAR(both.SignedDistance({ -2, 0, 0 }), 1.0, 0.01);
  EXPECT_NEAR(both.SignedDistance({ 0, 0, 0 }), -1.0, 0.01);
  // Inside both at depth 0.25 in each; the union's boundary is 0.66 away.
  const double middle = both.SignedDistance({ 0.75, 0, 0 });
  EXPECT_NEAR(middle, -0.25, 0.01);
  EXPECT_GE(middle, -std::sqrt(1.0 - 0.75 * 0.75));

  const DistanceGrid grid = SamplePrimitiveUnion(both, 0.02);
  ASSERT_FALSE(grid.Aborted);
  EXPECT_LT(grid.ExactPoints, grid.Values.size() / 2); // a narrow band
  const TriangleMesh surface = ContourDistanceGrid(grid);
  TriangleMesh closed;
  closed.Points = surface.Points;
  PrimitiveTemplate asTemplate;
  asTemplate.Base = surface.Points;
  asTemplate.Direction = surface.Points;
  asTemplate.Triangles = surface.Triangles;
  EXPECT_TRUE(ClosedAndConsistent(asTemplate));
  // Two unit balls 1.5 apart overlap in a lens of pi (4 + 1.5)(2 - 1.5)^2 / 12.
  const double exact = 8.0 / 3.0 * M_PI - M_PI * 5.5 * 0.25 / 12.0;
  const double volume = Volume(surface);
  std::cout << "union of two spheres: volume " << volume << " (exact " << exact << "), "
            << surface.Triangles.size() << " triangles\n";
  EXPECT_NEAR(volume, exact, 0.02 * exact);
}

// A contour's shells that enclose no skeletal point are dropped (a grid
// point a primitive's fold misled makes one); the rest is renumbered.
TEST(SkeletalPrimitives, ShellsAroundNoSkeletonAreDropped)
{
  TriangleMesh contour = MakeSphere(1.0, 16);
  const std::size_t points = contour.Points.size(), triangles = contour.Triangles.size();
  TriangleMesh bubble = MakeSphere(0.05, 4);
  const Index offset = static_cast<Index>(points);
  for (const Point3& p : bubble.Points)
  {
    contour.Points.push_back(p + Point3{ 1.5, 0, 0 });
  }
  for (const Triangle& t : bubble.Triangles)
  {
    contour.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  // The bubble first: the renumbering follows the triangles.
  std::rotate(
    contour.Triangles.begin(), contour.Triangles.begin() + triangles, contour.Triangles.end());
  EXPECT_EQ(KeepComponentsAroundSkeleton(contour, { { 0.2, 0.1, 0.0 } }), bubble.Triangles.size());
  EXPECT_EQ(contour.Triangles.size(), triangles);
  EXPECT_EQ(contour.Points.size(), points);
  for (const Point3& p : contour.Points)
  {
    EXPECT_NEAR(Norm(p), 1.0, 1e-9);
  }
  // One shell: kept as it is, even around no point.
  TriangleMesh one = MakeSphere(1.0, 8);
  EXPECT_EQ(KeepComponentsAroundSkeleton(one, {}), 0u);
  EXPECT_EQ(one.Triangles.size(), MakeSphere(1.0, 8).Triangles.size());
}

// The error filter measures a closed surface on port 1 (a reconstruction
// with no Radius) against the surface on port 0.
TEST(SkeletalPrimitives, ErrorFilterMeasuresAReconstructedSurface)
{
  vtkNew<vtkPolyData> surface, inner;
  TriangleMeshToPolyData(MakeSphere(1.05, 24), surface);
  TriangleMeshToPolyData(MakeSphere(1.0, 24), inner);
  vtkNew<vtkMedialReconstructionError> error;
  error->SetInputData(0, surface);
  error->SetInputData(1, inner);
  error->SetNumberOfSamples(20000);
  error->SetNumberOfEnvelopeSamples(20000);
  vtkNew<test::ErrorCatcher> errors;
  error->AddObserver(vtkCommand::ErrorEvent, errors);
  error->Update();
  ASSERT_EQ(errors->Count, 0) << errors->Last;
  std::cout << "sphere 1.05 against 1.0: Hausdorff " << error->GetHausdorff() << "\n";
  EXPECT_NEAR(error->GetHausdorff(), 0.05, 0.005);
  const double mean = error->GetOutput()->GetFieldData()->GetArray("Mean")->GetTuple1(0);
  EXPECT_NEAR(mean, 0.05, 0.005);
  vtkDataArray* signedDistance = error->GetOutput()->GetPointData()->GetArray("SignedDistance");
  ASSERT_NE(signedDistance, nullptr);
  EXPECT_GT(signedDistance->GetRange()[0], 0.0); // the surface lies outside the smaller sphere
  EXPECT_EQ(error->GetOutput(1)->GetPointData()->GetArray("PrimitiveKind"), nullptr);

  // The other way round (and with inward triangles, which are turned): inside.
  vtkNew<vtkPolyData> outer;
  TriangleMesh flipped = MakeSphere(1.1, 24);
  for (Triangle& t : flipped.Triangles)
  {
    std::swap(t[1], t[2]);
  }
  TriangleMeshToPolyData(flipped, outer);
  error->SetInputData(1, outer);
  error->Update();
  EXPECT_NEAR(error->GetHausdorff(), 0.05, 0.005);
  signedDistance = error->GetOutput()->GetPointData()->GetArray("SignedDistance");
  EXPECT_LT(signedDistance->GetRange()[1], 0.0);

  // Closed surfaces pass without a warning; an open one is measured, with a
  // warning that its signs mean nothing.
  vtkNew<test::ErrorCatcher> warnings;
  error->AddObserver(vtkCommand::WarningEvent, warnings);
  error->Update();
  EXPECT_EQ(warnings->Count, 0) << warnings->Last;
  TriangleMesh open = MakeSphere(1.0, 24);
  open.Triangles.pop_back();
  vtkNew<vtkPolyData> openSurface;
  TriangleMeshToPolyData(open, openSurface);
  error->SetInputData(1, openSurface);
  error->Update();
  EXPECT_EQ(errors->Count, 0) << errors->Last;
  EXPECT_EQ(warnings->Count, 1);
  EXPECT_NE(warnings->Last.find("not closed (3 triangle sides"), std::string::npos)
    << warnings->Last;
  EXPECT_NEAR(error->GetHausdorff(), 0.05, 0.005);
}

// The diagram filter in a pipeline: a dumbbell, its Structural MAT, the
// diagram's skeleton and primitives; too small an element budget warns that
// the error bound was not reached; no medial mesh is an error.
TEST(SkeletalDiagram, VtkFilterGivesSkeletonAndPrimitives)
{
  vtkNew<vtkAnalyticShapeSource> dumbbell;
  dumbbell->SetShapeToDumbbell();
  dumbbell->SetLength(1.2);
  dumbbell->SetRadius(0.25);
  dumbbell->SetMinorRadius(0.1);
  vtkNew<vtkStructuralMedialAxis> mat;
  mat->SetInputConnection(dumbbell->GetOutputPort());
  mat->SetNumberOfSamples(5000);
  mat->SetTargetNumberOfVertices(100);
  vtkNew<vtkMedialSkeletalDiagram> diagram;
  diagram->SetInputConnection(0, dumbbell->GetOutputPort());
  diagram->SetMedialAxisConnection(mat->GetOutputPort(0));
  vtkNew<test::ErrorCatcher> warnings;
  diagram->AddObserver(vtkCommand::WarningEvent, warnings);
  diagram->Update();
  vtkPolyData* skeleton = diagram->GetSkeleton();
  vtkPartitionedDataSetCollection* primitives = diagram->GetPrimitives();
  std::cout << "dumbbell diagram: " << skeleton->GetNumberOfPoints() << " vertices, "
            << skeleton->GetNumberOfLines() << " edges, " << skeleton->GetNumberOfPolys()
            << " triangles, error " << 100.0 * diagram->GetReachedError() << "%\n";
  EXPECT_EQ(warnings->Count, 0) << warnings->Last;
  EXPECT_LE(diagram->GetReachedError(), diagram->GetMaximumError());
  const vtkIdType vertices =
    static_cast<vtkIdType>(skeleton->GetFieldData()->GetArray("Vertices")->GetTuple1(0));
  EXPECT_EQ(diagram->GetNumberOfElements(),
    vertices + skeleton->GetNumberOfLines() + skeleton->GetNumberOfPolys());
  EXPECT_EQ(static_cast<vtkIdType>(primitives->GetNumberOfPartitionedDataSets()),
    diagram->GetNumberOfElements());
  ASSERT_NE(skeleton->GetPointData()->GetArray("MedialVertexId"), nullptr);
  ASSERT_NE(skeleton->GetFieldData()->GetArray("Error"), nullptr);
  EXPECT_EQ(skeleton->GetFieldData()->GetArray("FailedElements")->GetTuple1(0), 0.0);

  // The union as one closed surface, measured like any reconstruction.
  vtkPolyData* reconstruction = diagram->GetReconstruction();
  ASSERT_GT(reconstruction->GetNumberOfPolys(), 0);
  EXPECT_GT(skeleton->GetFieldData()->GetArray("ContinuousParameters")->GetTuple1(0),
    3.0 * skeleton->GetNumberOfPoints());
  vtkNew<vtkMedialReconstructionError> error;
  error->SetInputConnection(0, dumbbell->GetOutputPort());
  error->SetInputConnection(1, diagram->GetOutputPort(2));
  error->SetNumberOfSamples(20000);
  error->SetNumberOfEnvelopeSamples(20000);
  error->Update();
  const double mean = error->GetOutput()->GetFieldData()->GetArray("MeanPercent")->GetTuple1(0);
  std::cout << "dumbbell reconstruction: two-sided Hausdorff " << error->GetHausdorffPercent()
            << "%, mean " << mean << "%\n";
  EXPECT_LE(error->GetHausdorffPercent(), 2.0 * 100.0 * diagram->GetMaximumError());
  EXPECT_LE(mean, 0.25 * 100.0 * diagram->GetMaximumError());
  diagram->ReconstructOff();
  diagram->Update();
  EXPECT_EQ(diagram->GetReconstruction()->GetNumberOfPoints(), 0);
  diagram->ReconstructOn();

  diagram->SetMaximumElements(1);
  diagram->Update();
  EXPECT_EQ(diagram->GetNumberOfElements(), 1);
  EXPECT_EQ(warnings->Count, 1);
  EXPECT_NE(warnings->Last.find("raise MaximumElements"), std::string::npos) << warnings->Last;

  vtkNew<vtkMedialSkeletalDiagram> alone;
  alone->SetInputConnection(0, dumbbell->GetOutputPort());
  alone->SetInputDataObject(1, vtkNew<vtkPolyData>());
  vtkNew<test::ErrorCatcher> errors;
  alone->AddObserver(vtkCommand::ErrorEvent, errors);
  alone->Update();
  EXPECT_EQ(errors->Count, 1);
  EXPECT_EQ(alone->GetSkeleton()->GetNumberOfPoints(), 0);
}
