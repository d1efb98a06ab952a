// SPDX-License-Identifier: GPL-3.0-or-later
// The bad inputs of docs/robustness.md through the C++ API: each is either computed by
// vtkStructuralMedialAxis (the result checked) or refused with an error
// event naming the defect. The same inputs as Testing/Python/bad_inputs.py,
// built here in code; docs/robustness.md documents the behaviour.
#include "Geometry/Vec3.h"
#include "Surface/AnalyticShapes.h"
#include "TestHelpers.h"
#include "vtkMedialSurfaceValidator.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkSurfaceFileReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using namespace medialaxis;

namespace
{
constexpr double Radius = 0.5;
constexpr vtkIdType Samples = 1000, Target = 50;

TriangleMesh Sphere(double radius = Radius, const Point3& centre = { 0, 0, 0 })
{
  TriangleMesh mesh = MakeSphere(radius, 8);
  for (Point3& p : mesh.Points)
  {
    p = p + centre;
  }
  return mesh;
}

TriangleMesh Transformed(TriangleMesh mesh, double scale, const Point3& offset)
{
  for (Point3& p : mesh.Points)
  {
    p = scale * p + offset;
  }
  return mesh;
}

Index Extreme(const TriangleMesh& mesh, int axis, double sign)
{
  Index best = 0;
  for (std::size_t i = 1; i < mesh.Points.size(); ++i)
  {
    best = sign * mesh.Points[i][axis] > sign * mesh.Points[best][axis] ? Index(i) : best;
  }
  return best;
}

struct MedialRun
{
  vtkSmartPointer<vtkPolyData> Mat;
  vtkSmartPointer<test::ErrorCatcher> Errors = vtkSmartPointer<test::ErrorCatcher>::New();
};

MedialRun MedialAxis(vtkPolyData* surface, bool repair = true)
{
  vtkNew<vtkStructuralMedialAxis> filter;
  MedialRun run;
  filter->AddObserver(vtkCommand::ErrorEvent, run.Errors);
  filter->SetInputData(surface);
  filter->SetRepairSelfIntersections(repair);
  filter->SetNumberOfSamples(Samples);
  filter->SetTargetNumberOfVertices(Target);
  filter->SetGenerateEnvelope(false);
  filter->Update();
  run.Mat = filter->GetOutput();
  return run;
}

MedialRun MedialAxis(const TriangleMesh& mesh, bool repair = true)
{
  return MedialAxis(test::ToPolyData(mesh), repair);
}

// Every centre and radius of `mat` is the reference's, scaled and offset,
// to 1e-6 of the diagonal.
void ExpectSameAsSphere(
  vtkPolyData* mat, vtkPolyData* reference, double scale = 1.0, const Point3& offset = {})
{
  ASSERT_EQ(mat->GetNumberOfPoints(), reference->GetNumberOfPoints());
  const double tolerance = 1e-6 * 2 * std::sqrt(3.0) * Radius;
  vtkDataArray* radii = mat->GetPointData()->GetArray("Radius");
  vtkDataArray* expected = reference->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < mat->GetNumberOfPoints(); ++i)
  {
    Point3 p, q;
    mat->GetPoint(i, p.data());
    reference->GetPoint(i, q.data());
    EXPECT_LE(Norm((1.0 / scale) * (p - offset) - q), tolerance) << i;
    EXPECT_LE(std::fabs(radii->GetTuple1(i) / scale - expected->GetTuple1(i)), tolerance) << i;
  }
}

// A ball: every medial ball inside the sphere, the largest nearly as large
// and at its centre.
void ExpectBall(vtkPolyData* mat)
{
  vtkDataArray* radii = mat->GetPointData()->GetArray("Radius");
  vtkIdType largest = 0;
  for (vtkIdType i = 0; i < mat->GetNumberOfPoints(); ++i)
  {
    Point3 p;
    mat->GetPoint(i, p.data());
    EXPECT_LE(Norm(p) + radii->GetTuple1(i), 1.01 * Radius) << i;
    largest = radii->GetTuple1(i) > radii->GetTuple1(largest) ? i : largest;
  }
  Point3 centre;
  mat->GetPoint(largest, centre.data());
  EXPECT_GE(radii->GetTuple1(largest), 0.95 * Radius);
  EXPECT_LE(Norm(centre), 0.05 * Radius);
}

// A ball with a spherical cavity of half its radius: the medial axis is the
// sphere halfway between, every ball half the wall thick (to a quarter and a
// tenth of that: both shells are coarse polyhedra).
void ExpectHollowBall(vtkPolyData* mat)
{
  const double middle = 0.75 * Radius, halfWall = 0.25 * Radius;
  vtkDataArray* radii = mat->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < mat->GetNumberOfPoints(); ++i)
  {
    Point3 p;
    mat->GetPoint(i, p.data());
    EXPECT_NEAR(Norm(p), middle, 0.25 * halfWall) << i;
    EXPECT_NEAR(radii->GetTuple1(i), halfWall, 0.1 * halfWall) << i;
  }
}

std::string Validate(vtkPolyData* surface)
{
  vtkNew<vtkMedialSurfaceValidator> validator;
  vtkNew<test::ErrorCatcher> errors;
  validator->AddObserver(vtkCommand::ErrorEvent, errors);
  validator->SetInputData(surface);
  validator->Update();
  return validator->GetValid() ? "" : validator->GetErrorMessage();
}

void ExpectRefused(vtkPolyData* surface, const std::string& phrase, bool repair = true)
{
  const MedialRun run = MedialAxis(surface, repair);
  EXPECT_EQ(run.Mat->GetNumberOfPoints(), 0);
  EXPECT_EQ(run.Errors->Count, 1);
  EXPECT_NE(run.Errors->Last.find(phrase), std::string::npos) << run.Errors->Last;
  EXPECT_NE(Validate(surface).find(phrase), std::string::npos) << Validate(surface);
}

void ExpectRefused(const TriangleMesh& mesh, const std::string& phrase, bool repair = true)
{
  ExpectRefused(test::ToPolyData(mesh), phrase, repair);
}

vtkSmartPointer<vtkPolyData> Accepted(const TriangleMesh& mesh)
{
  auto surface = test::ToPolyData(mesh);
  EXPECT_EQ(Validate(surface), "");
  const MedialRun run = MedialAxis(surface);
  EXPECT_EQ(run.Errors->Count, 0) << run.Errors->Last;
  EXPECT_EQ(run.Mat->GetNumberOfPoints(), Target);
  return run.Mat;
}

// A file read by vtkSurfaceFileReader: refused by the reader, naming the line.
std::string ReadError(const std::string& name, const std::string& text)
{
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  vtkNew<vtkSurfaceFileReader> reader;
  vtkNew<test::ErrorCatcher> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(path.c_str());
  reader->Update();
  std::remove(path.c_str());
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_GT(errors->Count, 0);
  return reader->GetErrorMessage();
}
}

TEST(BadInputs, MalformedFilesAreRefusedNamingTheLine)
{
  EXPECT_NE(ReadError("empty.off", "").find("line 0: empty file"), std::string::npos);
  EXPECT_NE(ReadError("header_only.off", "OFF\n").find("line 1: end of file before the counts"),
    std::string::npos);
}

TEST(BadInputs, DefectsThatCannotBeRepairedAreRefused)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  TriangleMesh mesh = Sphere();
  mesh.Points[3] = { nan, 0, 0 };
  ExpectRefused(mesh, "surface has 1 point with NaN or infinite coordinates");
  mesh.Points[3] = { 0, inf, 0 };
  ExpectRefused(mesh, "surface has 1 point with NaN or infinite coordinates");

  TriangleMesh triangle;
  triangle.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  triangle.Triangles = { { 0, 1, 2 } };
  ExpectRefused(triangle, "surface is not closed: 3 boundary edges");

  // A point cloud and a set of lines: no polygons at all.
  for (bool lines : { false, true })
  {
    auto surface = test::ToPolyData(Sphere());
    vtkNew<vtkCellArray> cells;
    for (vtkIdType i = 0; i < 10; i += 2)
    {
      const vtkIdType ids[2] = { i, i + 1 };
      cells->InsertNextCell(lines ? 2 : 1, ids);
    }
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(surface->GetPoints());
    lines ? cloud->SetLines(cells) : cloud->SetVerts(cells);
    ExpectRefused(cloud,
      lines ? "surface has no polygons (it has 5 line and 0 vertex cells)"
            : "surface has no polygons (it has 0 line and 5 vertex cells)");
  }

  // Open: a cap of triangles around the north pole removed; one triangle removed.
  mesh = Sphere();
  const Index pole = Extreme(mesh, 2, 1.0);
  std::vector<Triangle> kept;
  for (const Triangle& t : mesh.Triangles)
  {
    if (t[0] != pole && t[1] != pole && t[2] != pole)
    {
      kept.push_back(t);
    }
  }
  const std::size_t fan = mesh.Triangles.size() - kept.size();
  mesh.Triangles = kept;
  ExpectRefused(mesh, "surface is not closed: " + std::to_string(fan) + " boundary edges");
  mesh = Sphere();
  mesh.Triangles.erase(mesh.Triangles.begin() + 7);
  ExpectRefused(mesh, "surface is not closed: 3 boundary edges");

  // A fin: a third triangle on an edge.
  mesh = Sphere();
  mesh.Points.push_back({ 1, 1, 1 });
  mesh.Triangles.push_back(
    { mesh.Triangles[0][0], mesh.Triangles[0][1], Index(mesh.Points.size() - 1) });
  ExpectRefused(mesh, "1 edge is shared by more than two triangles");

  // A bow tie: two spheres touching at one point.
  TriangleMesh right = Sphere(Radius, { 2 * Radius, 0, 0 });
  const TriangleMesh left = Sphere();
  right.Points[Extreme(right, 0, -1.0)] = left.Points[Extreme(left, 0, 1.0)];
  ExpectRefused(test::Append(left, right),
    "surface is not manifold: 1 vertex joins several separate sheets of triangles");

  // Two overlapping spheres, unless repaired (see SelfIntersectionsAreRepaired);
  // a sphere whose north pole is pulled through its south pole, which bounds
  // no solid, even with the repair.
  ExpectRefused(test::Append(Sphere(), Sphere(Radius, { 0.3, 0, 0 })),
    "pairs of triangles of separate shells cross", false);
  mesh = Sphere();
  mesh.Points[pole] = { 0.02, 0.01, -1.5 * Radius };
  ExpectRefused(mesh, "far apart on the surface cross");
  EXPECT_NE(MedialAxis(mesh).Errors->Last.find("repairing it failed: the crossings do not "
                                               "resolve into the boundary of one solid"),
    std::string::npos);
}

TEST(BadInputs, SelfIntersectionsAreRepaired)
{
  // Two overlapping spheres: the medial axis of their union, every ball
  // inside it (to 1% of the radius, at 26 points of each ball).
  const MedialRun run = MedialAxis(test::Append(Sphere(), Sphere(Radius, { 0.3, 0, 0 })));
  ASSERT_EQ(run.Errors->Count, 0) << run.Errors->Last;
  ASSERT_EQ(run.Mat->GetNumberOfPoints(), Target);
  vtkDataArray* radii = run.Mat->GetPointData()->GetArray("Radius");
  for (vtkIdType i = 0; i < run.Mat->GetNumberOfPoints(); ++i)
  {
    Point3 c;
    run.Mat->GetPoint(i, c.data());
    for (int d = 0; d < 27; ++d)
    {
      const Point3 direction{ double(d % 3 - 1), double(d / 3 % 3 - 1), double(d / 9 - 1) };
      if (d == 13)
      {
        continue; // (0, 0, 0)
      }
      const Point3 q = c + (radii->GetTuple1(i) / Norm(direction)) * direction;
      const double outside = std::min(Norm(q), Norm(q - Point3{ 0.3, 0, 0 })) - Radius;
      EXPECT_LE(outside, 0.01 * Radius) << i;
    }
  }
  EXPECT_GT(run.Mat->GetFieldData()->GetArray("RepairedCrossingPairs")->GetTuple1(0), 0);
}

TEST(BadInputs, RepairableDefectsAndExtremeCoordinatesGiveTheRightResult)
{
  const MedialRun clean = MedialAxis(Sphere());
  ASSERT_EQ(clean.Errors->Count, 0) << clean.Errors->Last;
  ASSERT_EQ(clean.Mat->GetNumberOfPoints(), Target);
  vtkPolyData* reference = clean.Mat;
  // The error bands and the final fit take part: the sphere's medial axis
  // is a cluster of nearly concentric balls, on which the fit's pull of a
  // ball back into the surface must not depend on rounding.
  EXPECT_EQ(test::FieldValue(reference, "ErrorBandsUsed"), 1.0);
  EXPECT_GT(test::FieldValue(reference, "FitRounds"), 0.0);

  // Scaled and moved far away: the same medial axis, scaled and moved.
  ExpectSameAsSphere(Accepted(Transformed(Sphere(), 1e-30, {})), reference, 1e-30);
  ExpectSameAsSphere(Accepted(Transformed(Sphere(), 1e30, {})), reference, 1e30);
  const Point3 far{ 1e6, -1e6, 1e6 };
  ExpectSameAsSphere(Accepted(Transformed(Sphere(), 1.0, far)), reference, 1.0, far);

  // Repairs that give back exactly the clean surface: the same result.
  TriangleMesh mesh = Sphere();
  for (int t : { 3, 40, 41 })
  {
    mesh.Triangles.push_back(mesh.Triangles[t]); // duplicates
  }
  ExpectSameAsSphere(Accepted(mesh), reference);
  mesh = Sphere();
  const Triangle t = mesh.Triangles[30];
  mesh.Points.push_back(0.5 * (mesh.Points[t[0]] + mesh.Points[t[1]]));
  mesh.Triangles.push_back({ t[0], t[0], t[1] });
  mesh.Triangles.push_back({ t[1], t[2], t[2] });
  mesh.Triangles.push_back({ t[0], Index(mesh.Points.size() - 1), t[1] }); // a needle
  ExpectSameAsSphere(Accepted(mesh), reference);
  ExpectSameAsSphere(Accepted(test::Append(Sphere(), Sphere())), reference);

  // Orientation repairs: the ball, its triangles in another order.
  mesh = Sphere();
  std::swap(mesh.Triangles[5][1], mesh.Triangles[5][2]);
  ExpectBall(Accepted(mesh));
  mesh = Sphere();
  for (Triangle& u : mesh.Triangles)
  {
    std::swap(u[1], u[2]); // all inward
  }
  ExpectBall(Accepted(mesh));

  // Nested shells: a hollow ball, whichever way the inner shell faces.
  ExpectHollowBall(Accepted(test::Append(Sphere(), Sphere(0.5 * Radius))));
}
