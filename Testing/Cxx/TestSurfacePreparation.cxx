// SPDX-License-Identifier: GPL-3.0-or-later
// Surface validation and preparation, one defect per small hand-built mesh.
#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"
#include "Surface/AnalyticShapes.h"
#include "Surface/FeatureNormals.h"
#include "Surface/SelfIntersection.h"
#include "Surface/SharpEdgeContent.h"
#include "Surface/SurfacePreparation.h"
#include "TestHelpers.h"
#include "vtkMedialSurfaceValidator.h"
#include "vtkSurfacePreparation.h"

#include "vtkCellArray.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

using namespace medialaxis;
using test::Append;
using test::Tetrahedron;
using test::UnitCube;

namespace
{
SurfacePreparationReport Prepare(const TriangleMesh& in, TriangleMesh& out, bool fix = true)
{
  SurfacePreparationOptions options;
  options.FixOrientation = fix;
  return PrepareSurface(in, out, options);
}

bool Contains(const std::string& text, const std::string& phrase)
{
  return text.find(phrase) != std::string::npos;
}
}

TEST(SurfacePreparation, CleanCubePassesUnchanged)
{
  TriangleMesh out;
  const auto r = Prepare(UnitCube(), out, false);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(out.Triangles.size(), 12u);
  EXPECT_EQ(out.Points.size(), 8u);
  EXPECT_NEAR(r.Volume, 1.0, 1e-12);
  EXPECT_NEAR(r.Area, 6.0, 1e-12);
  EXPECT_EQ(r.Components, 1u);
  EXPECT_TRUE(r.Notes.empty());
}

TEST(SurfacePreparation, EmptyInput)
{
  TriangleMesh out;
  EXPECT_TRUE(Contains(Prepare(TriangleMesh(), out).Error, "surface is empty"));
}

TEST(SurfacePreparation, NonFiniteCoordinates)
{
  TriangleMesh cube = UnitCube();
  cube.Points[3][1] = std::nan("");
  cube.Points[5][0] = INFINITY;
  TriangleMesh out;
  const auto r = Prepare(cube, out);
  EXPECT_EQ(r.Error, "surface has 2 points with NaN or infinite coordinates");
}

TEST(SurfacePreparation, OpenBoundaryIsCounted)
{
  TriangleMesh cube = UnitCube();
  cube.Triangles.pop_back(); // one missing triangle: 3 boundary edges
  TriangleMesh out;
  const auto r = Prepare(cube, out);
  EXPECT_EQ(r.Error, "surface is not closed: 3 boundary edges");
  EXPECT_EQ(r.BoundaryEdges, 3u);
}

TEST(SurfacePreparation, NonManifoldEdge)
{
  // Two tetrahedra glued along one edge (0-1 of both): that edge has 4 triangles.
  TriangleMesh a = Tetrahedron({ 0, 0, 0 }, 1.0);
  TriangleMesh b = a;
  for (auto& p : b.Points)
  {
    p = { p[0], -p[1], -p[2] }; // rotate 180 degrees about x: shares edge 0-1
  }
  TriangleMesh both = Append(a, b);
  TriangleMesh out;
  const auto r = Prepare(both, out);
  EXPECT_EQ(r.NonManifoldEdges, 1u);
  EXPECT_EQ(r.Error, "surface is not manifold: 1 edge is shared by more than two triangles");
}

TEST(SurfacePreparation, ThreeTrianglesOnAnEdge)
{
  TriangleMesh cube = UnitCube();
  cube.Points.push_back({ 0.5, 0.5, 0.5 });
  cube.Triangles.push_back({ 0, 1, 8 }); // a fin on edge 0-1
  TriangleMesh out;
  const auto r = Prepare(cube, out);
  EXPECT_TRUE(Contains(r.Error, "1 edge is shared by more than two triangles")) << r.Error;
  EXPECT_TRUE(Contains(r.Error, "not closed: 2 boundary edges")) << r.Error;
}

TEST(SurfacePreparation, BowTieVertex)
{
  // Two tetrahedra touching at one vertex only.
  TriangleMesh a = Tetrahedron({ 0, 0, 0 }, 1.0);
  TriangleMesh b = a;
  for (auto& p : b.Points)
  {
    p = { -p[0], -p[1], -p[2] };
  }
  TriangleMesh out;
  const auto r = Prepare(Append(a, b), out);
  EXPECT_EQ(r.NonManifoldVertices, 1u);
  EXPECT_EQ(
    r.Error, "surface is not manifold: 1 vertex joins several separate sheets of triangles");
}

TEST(SurfacePreparation, InconsistentOrientationIsFixed)
{
  TriangleMesh cube = UnitCube();
  std::swap(cube.Triangles[4][1], cube.Triangles[4][2]);
  TriangleMesh out;
  const auto r = Prepare(cube, out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.ReorientedTriangles, 1u);
  EXPECT_NEAR(SignedVolume(out), 1.0, 1e-12);
  TriangleMesh again;
  EXPECT_TRUE(Prepare(out, again, false).Ok()); // the result is consistent

  const auto refused = Prepare(cube, out, false);
  EXPECT_EQ(
    refused.Error, "surface orientation is inconsistent: 1 triangle disagrees with its neighbours");
}

TEST(SurfacePreparation, InwardOrientationIsFlipped)
{
  TriangleMesh cube = UnitCube();
  for (auto& t : cube.Triangles)
  {
    std::swap(t[1], t[2]);
  }
  TriangleMesh out;
  const auto r = Prepare(cube, out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.InwardComponents, 1u);
  EXPECT_EQ(r.ReorientedTriangles, 0u);
  EXPECT_NEAR(r.Volume, 1.0, 1e-12);
  EXPECT_TRUE(Contains(Prepare(cube, out, false).Error, "oriented inward"));
}

TEST(SurfacePreparation, TriangleSoupBecomesClosed)
{
  // Every triangle with its own three points, as OBJ files with per-corner
  // normals load; one copy slightly perturbed below the merge tolerance.
  const TriangleMesh cube = UnitCube({ 10, 10, 10 }, 2.0);
  TriangleMesh soup;
  for (const auto& t : cube.Triangles)
  {
    const Index base = static_cast<Index>(soup.Points.size());
    for (Index v : t)
    {
      soup.Points.push_back(cube.Points[v]);
    }
    soup.Triangles.push_back({ base, base + 1, base + 2 });
  }
  soup.Points[0][0] += 1e-13;
  TriangleMesh out;
  const auto r = Prepare(soup, out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(out.Points.size(), 8u);
  EXPECT_EQ(r.MergedPoints, 36u - 8u);
  EXPECT_NEAR(r.Volume, 8.0, 1e-9);

  SurfacePreparationOptions exact;
  exact.RelativeMergeTolerance = 0.0; // the perturbed copy then stays apart
  EXPECT_TRUE(Contains(PrepareSurface(soup, out, exact).Error, "not closed"));
}

TEST(SurfacePreparation, DegenerateAndDuplicateTrianglesAreDropped)
{
  TriangleMesh cube = UnitCube();
  cube.Triangles.push_back({ 0, 0, 1 });       // repeated vertex
  cube.Triangles.push_back(cube.Triangles[0]); // exact duplicate
  cube.Triangles.push_back({ 3, 0, 2 });       // same triangle, rotated
  TriangleMesh out;
  const auto r = Prepare(cube, out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.DegenerateTriangles, 1u);
  EXPECT_EQ(r.DuplicateTriangles, 2u);
  EXPECT_EQ(out.Triangles.size(), 12u);
}

TEST(SurfacePreparation, ZeroAreaNeedleIsAbsorbed)
{
  // Split the cube's bottom edge 0-1 at its midpoint 8 on the y = 0 side
  // only: the bottom face keeps the long edge, so a needle (0, 8, 1)-shaped
  // gap must be closed by a zero-area triangle, which preparation removes by
  // splitting the bottom triangle instead.
  TriangleMesh cube = UnitCube();
  cube.Points.push_back({ 0.5, 0.0, 0.0 });
  // y = 0 face was {0,1,5},{0,5,4}: use point 8 on edge 0-1.
  cube.Triangles[4] = { 0, 8, 5 };
  cube.Triangles.push_back({ 8, 1, 5 });
  cube.Triangles.push_back({ 0, 1, 8 }); // the zero-area needle
  TriangleMesh out;
  const auto r = Prepare(cube, out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.DegenerateTriangles, 1u);
  EXPECT_EQ(r.SplitNeighbours, 1u);
  EXPECT_EQ(out.Triangles.size(), 14u);
  EXPECT_NEAR(r.Volume, 1.0, 1e-12);
  EXPECT_NEAR(r.Area, 6.0, 1e-12);
}

// Found by fuzzing: four vertices on one line (0, 0, z) make two needles
// that share their longest edge, so neither can absorb the other, and
// splitting one made new needles. Zero-area triangles reached CGAL, whose
// intersection tests require non-degenerate ones. Now none is ever kept.
TEST(SurfacePreparation, NeedlesThatCannotBeAbsorbedAreNotKept)
{
  TriangleMesh mesh;
  mesh.Points = { { 1, 1.984375, 0 }, { 0, 0, 2.109375 }, { 0, 0, 0 }, { 4.21875, 0, 0 },
    { 0, 0, 1 }, { 0, 0, -1 } };
  mesh.Triangles = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 }, { 2, 0, 5 }, { 1, 2, 5 },
    { 3, 1, 5 }, { 0, 3, 5 } };
  TriangleMesh out;
  const auto r = Prepare(mesh, out);
  // Without its flat triangles the rest is open: a clear error, not a
  // surface with zero-area triangles.
  EXPECT_EQ(r.DegenerateTriangles, 3u);
  EXPECT_FALSE(r.Ok());
  EXPECT_NE(r.Error.find("surface is not closed: 2 boundary edges"), std::string::npos) << r.Error;
}

TEST(SurfacePreparation, SeveralComponentsAreAllowed)
{
  TriangleMesh out;
  const auto r = Prepare(Append(UnitCube(), UnitCube({ 3, 0, 0 })), out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.Components, 2u);
  EXPECT_NEAR(r.Volume, 2.0, 1e-12);
}

TEST(SurfacePreparation, NestedShellBecomesACavity)
{
  // A sphere inside a sphere, both outward as given: the inner one bounds a
  // cavity and must face inward; the enclosed volume is the shell's.
  const TriangleMesh outer = MakeSphere(2.0, 8);
  const TriangleMesh inner = MakeSphere(1.0, 8);
  TriangleMesh out;
  const auto r = Prepare(Append(outer, inner), out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_EQ(r.Components, 2u);
  EXPECT_EQ(r.InwardComponents, 1u);
  EXPECT_NEAR(r.Volume, SignedVolume(outer) - SignedVolume(inner), 1e-9);
}

TEST(SurfacePreparation, OverlappingShellsAreRefusedAsSelfIntersecting)
{
  // Two spheres that overlap bound no solid as given: their union would have
  // to be computed first. Without the test the second one would be read as a
  // cavity of the first.
  TriangleMesh shifted = MakeSphere(1.0, 8);
  for (Point3& p : shifted.Points)
  {
    p[0] += 0.5;
  }
  TriangleMesh out;
  const auto r = Prepare(Append(MakeSphere(1.0, 8), shifted), out);
  EXPECT_GT(r.SelfIntersections, 0u);
  EXPECT_TRUE(Contains(r.Error, "surface intersects itself: ")) << r.Error;
  EXPECT_EQ(r.CrossingShells, r.SelfIntersections);
  EXPECT_TRUE(Contains(r.Error, "pairs of triangles of separate shells cross, e.g. near ("))
    << r.Error;
  EXPECT_TRUE(Contains(r.Error, "(overlapping shells must be merged into one surface first)"))
    << r.Error;

  // Two exact copies are one surface: the copies' triangles are duplicates.
  const auto copies = Prepare(Append(MakeSphere(1.0, 8), MakeSphere(1.0, 8)), out);
  ASSERT_TRUE(copies.Ok()) << copies.Error;
  EXPECT_EQ(copies.Components, 1u);
  EXPECT_EQ(copies.DuplicateTriangles, MakeSphere(1.0, 8).Triangles.size());
  EXPECT_EQ(copies.SelfIntersections, 0u);
}

TEST(SurfacePreparation, SurfaceThroughItselfIsRefused)
{
  // A sphere whose north pole is pulled down through the south pole: the
  // triangles around it cross the southern cap.
  TriangleMesh sphere = MakeSphere(1.0, 8);
  std::size_t north = 0;
  for (std::size_t i = 1; i < sphere.Points.size(); ++i)
  {
    north = sphere.Points[i][2] > sphere.Points[north][2] ? i : north;
  }
  sphere.Points[north] = { 0.05, 0.03, -1.5 };
  TriangleMesh out;
  const auto r = Prepare(sphere, out);
  EXPECT_GT(r.SelfIntersections, 0u);
  EXPECT_TRUE(Contains(r.Error, "surface intersects itself: ")) << r.Error;
  EXPECT_TRUE(Contains(r.Error, "far apart on the surface cross, e.g. near (")) << r.Error;
  EXPECT_TRUE(Contains(r.Error, "(the surface passes through itself)")) << r.Error;
  EXPECT_GT(r.CrossingFarApart, 0u);

  // Touching along shared edges and vertices is not crossing.
  const auto clean = Prepare(MakeSphere(1.0, 8), out);
  EXPECT_TRUE(clean.Ok()) << clean.Error;
  EXPECT_EQ(clean.SelfIntersections, 0u);
}

TEST(SurfacePreparation, LocalFoldIsKeptWithANote)
{
  // One vertex dragged over its neighbour: the two fans overlap, a fold of a
  // few neighbouring triangles as scanned and decimated meshes have them.
  TriangleMesh sphere = MakeSphere(1.0, 16);
  const Triangle& t = sphere.Triangles[sphere.Triangles.size() / 2];
  const Point3 moved = sphere.Points[t[0]], neighbour = sphere.Points[t[1]];
  sphere.Points[t[0]] = neighbour + 0.3 * (neighbour - moved);
  TriangleMesh out;
  const auto r = Prepare(sphere, out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_GT(r.SelfIntersections, 0u);
  EXPECT_EQ(r.CrossingFarApart, 0u);
  bool noted = false;
  for (const std::string& note : r.Notes)
  {
    noted = noted || Contains(note, "neighbouring triangles overlap (local folds): kept");
  }
  EXPECT_TRUE(noted);
}

TEST(SurfacePreparation, NonOrientableSurfaceIsRefused)
{
  // A combinatorial Klein bottle: an n x m torus grid whose last column is
  // glued to the first with the rows reversed.
  const int n = 6, m = 6;
  TriangleMesh k;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      k.Points.push_back({ double(i), double(j), double((i * 7 + j * 3) % 5) });
    }
  }
  auto id = [&](int i, int j)
  {
    if (i == n)
    {
      i = 0;
      j = (m - j) % m;
    }
    return static_cast<Index>(i * m + (j % m));
  };
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < m; ++j)
    {
      k.Triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      k.Triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  TriangleMesh out;
  const auto r = Prepare(k, out);
  EXPECT_TRUE(Contains(r.Error, "not orientable")) << r.Error;
}

TEST(SurfacePreparation, DoublyCoveredSheetIsRefused)
{
  TriangleMesh sheet;
  sheet.Points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  sheet.Triangles = { { 0, 1, 2 } };
  sheet.Points.push_back({ 0.3, 0.3, 0 });
  sheet.Triangles = { { 0, 1, 3 }, { 1, 2, 3 }, { 2, 0, 3 }, { 0, 3, 1 }, { 1, 3, 2 },
    { 2, 3, 0 } };
  TriangleMesh out;
  const auto r = Prepare(sheet, out);
  // The back side repeats the front's triangles: dropping the duplicates
  // leaves an open sheet.
  EXPECT_EQ(r.DuplicateTriangles, 3u);
  EXPECT_EQ(r.Error, "surface is not closed: 3 boundary edges");
}

TEST(SurfacePreparation, FarFromOriginAndTinyScale)
{
  for (double scale : { 1e-30, 1e30 })
  {
    TriangleMesh out;
    const auto r = Prepare(UnitCube({ 0, 0, 0 }, scale), out);
    ASSERT_TRUE(r.Ok()) << scale << ": " << r.Error;
    EXPECT_NEAR(r.Volume / (scale * scale * scale), 1.0, 1e-9);
  }
  TriangleMesh out;
  const auto r = Prepare(UnitCube({ 1e6, -1e6, 1e6 }, 1.0), out);
  ASSERT_TRUE(r.Ok()) << r.Error;
  EXPECT_NEAR(r.Volume, 1.0, 1e-6);
}

// The VTK filter: polygons are triangulated, points/lines refused, counts reported.
TEST(MedialSurfaceValidator, TriangulatesPolygonsAndReports)
{
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 8; ++i)
  {
    points->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  }
  vtkNew<vtkCellArray> quads;
  const vtkIdType faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (const auto& f : faces)
  {
    quads->InsertNextCell(4, f);
  }
  vtkNew<vtkPolyData> cube;
  cube->SetPoints(points);
  cube->SetPolys(quads);
  vtkNew<vtkMedialSurfaceValidator> validator;
  validator->SetInputData(cube);
  validator->Update();
  EXPECT_TRUE(validator->GetValid()) << validator->GetErrorMessage();
  EXPECT_EQ(validator->GetOutput()->GetNumberOfPolys(), 12);
  EXPECT_NEAR(validator->GetVolume(), 1.0, 1e-12);
  EXPECT_EQ(validator->GetNumberOfComponents(), 1);
}

TEST(MedialSurfaceValidator, RefusesLinesOnlyWithAClearMessage)
{
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 1 };
  lines->InsertNextCell(2, line);
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetLines(lines);
  vtkNew<vtkMedialSurfaceValidator> validator;
  vtkNew<test::ErrorCatcher> errors;
  validator->AddObserver(vtkCommand::ErrorEvent, errors);
  validator->SetInputData(pd);
  validator->Update();
  EXPECT_FALSE(validator->GetValid());
  EXPECT_EQ(std::string(validator->GetErrorMessage()),
    "surface has no polygons (it has 1 line and 0 vertex cells): a closed triangle mesh is needed");
  EXPECT_EQ(validator->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(errors->Count, 1);
}

TEST(MedialSurfaceValidator, OpenMeshIsRefused)
{
  TriangleMesh cube = UnitCube();
  cube.Triangles.resize(10);
  vtkNew<vtkMedialSurfaceValidator> validator;
  vtkNew<test::ErrorCatcher> errors;
  validator->AddObserver(vtkCommand::ErrorEvent, errors);
  validator->SetInputData(test::ToPolyData(cube));
  validator->Update();
  EXPECT_FALSE(validator->GetValid());
  EXPECT_EQ(validator->GetNumberOfBoundaryEdges(), 4);
  EXPECT_EQ(std::string(validator->GetErrorMessage()), "surface is not closed: 4 boundary edges");
}

TEST(MedialSurfaceValidator, RemembersSelfIntersectionsOnlyForAnUnchangedInput)
{
  // Stages that prepare the same poly data one after another reuse the
  // self-intersection test; any change to the points gives a fresh test.
  const TriangleMesh sphere = MakeSphere(1.0, 8);
  auto surface = test::ToPolyData(sphere);
  vtkNew<vtkPolyData> out;
  SurfacePreparationReport first = PrepareSurfacePolyData(surface, out);
  SurfacePreparationReport again = PrepareSurfacePolyData(surface, out);
  ASSERT_TRUE(first.Ok()) << first.Error;
  EXPECT_TRUE(again.Ok()) << again.Error;

  vtkIdType pole = 0;
  for (vtkIdType i = 1; i < surface->GetNumberOfPoints(); ++i)
  {
    pole = surface->GetPoint(i)[2] > surface->GetPoint(pole)[2] ? i : pole;
  }
  surface->GetPoints()->SetPoint(pole, 0.05, 0.03, -1.5);
  surface->GetPoints()->Modified();
  first = PrepareSurfacePolyData(surface, out);
  again = PrepareSurfacePolyData(surface, out);
  EXPECT_TRUE(Contains(first.Error, "the surface passes through itself")) << first.Error;
  EXPECT_EQ(again.Error, first.Error);
  EXPECT_EQ(again.CrossingFarApart, first.CrossingFarApart);
}

TEST(MedialSurfaceValidator, RemembersPreparationOnlyWhereTheRepairOptionCannotMatter)
{
  // The one-click filter prepares with repair allowed, its stages without. A
  // surface that needed no repair is the same either way; one that was
  // repaired must still be refused where repair is not allowed.
  TriangleMesh shifted = MakeSphere(1.0, 8);
  for (Point3& p : shifted.Points)
  {
    p[0] += 0.5;
  }
  auto overlapping = test::ToPolyData(Append(MakeSphere(1.0, 8), shifted));
  SurfacePreparationOptions repair;
  repair.RepairSelfIntersections = true;
  vtkNew<vtkPolyData> out;
  const SurfacePreparationReport repaired = PrepareSurfacePolyData(overlapping, out, repair);
  ASSERT_TRUE(repaired.Ok()) << repaired.Error;
  EXPECT_TRUE(repaired.Repaired);
  const SurfacePreparationReport refused = PrepareSurfacePolyData(overlapping, out);
  EXPECT_TRUE(Contains(refused.Error, "surface intersects itself: ")) << refused.Error;
  EXPECT_EQ(out->GetNumberOfPolys(), 0);

  auto sphere = test::ToPolyData(MakeSphere(1.0, 8));
  const SurfacePreparationReport clean = PrepareSurfacePolyData(sphere, out, repair);
  ASSERT_TRUE(clean.Ok()) << clean.Error;
  EXPECT_FALSE(clean.Repaired);
  vtkNew<vtkPolyData> again;
  const SurfacePreparationReport same = PrepareSurfacePolyData(sphere, again);
  ASSERT_TRUE(same.Ok()) << same.Error;
  EXPECT_EQ(again->GetNumberOfPolys(), out->GetNumberOfPolys());
  EXPECT_EQ(again->GetNumberOfPoints(), out->GetNumberOfPoints());
}

TEST(SelfIntersection, RemembersAnswersByContent)
{
  // Answers are kept by the content tested: a soup of the same size with one
  // point moved is tested afresh, and the first soup still gets its answer.
  const TriangleMesh sphere = MakeSphere(1.0, 8);
  TriangleMesh pulled = sphere;
  std::size_t north = 0;
  for (std::size_t i = 1; i < pulled.Points.size(); ++i)
  {
    north = pulled.Points[i][2] > pulled.Points[north][2] ? i : north;
  }
  pulled.Points[north] = { 0.05, 0.03, -1.5 };
  EXPECT_TRUE(FindSelfIntersections(sphere.Points, sphere.Triangles).empty());
  EXPECT_FALSE(FindSelfIntersections(pulled.Points, pulled.Triangles).empty());
  EXPECT_TRUE(FindSelfIntersections(sphere.Points, sphere.Triangles).empty());
  EXPECT_EQ(FindSelfIntersections(pulled.Points, pulled.Triangles).size(),
    FindSelfIntersections(pulled.Points, pulled.Triangles).size());
}

// The automatic preset's measure: creases of a machined part count, smooth
// and noisy organic surfaces have none.
TEST(SharpEdgeContent, CubeCylinderSphereAndNoise)
{
  const double angle = 0.25 * 3.14159265358979;
  const SharpEdgeContent cube = MeasureSharpEdgeContent(UnitCube(), angle);
  EXPECT_NEAR(cube.SharpLength, 12.0, 1e-12); // the face diagonals are flat
  EXPECT_EQ(cube.Creases, 12);                // corner to corner
  EXPECT_NEAR(cube.Ratio(), 12.0 / std::sqrt(6.0), 1e-12);
  EXPECT_TRUE(LooksLikeCad(cube));

  // Two rims of length 2 pi r; area 2 pi r (r + h).
  const SharpEdgeContent cylinder = MeasureSharpEdgeContent(MakeCylinder(1.0, 2.0, 64), angle);
  EXPECT_EQ(cylinder.Creases, 2);
  EXPECT_NEAR(cylinder.Ratio(), 4.0 * M_PI / std::sqrt(6.0 * M_PI), 0.02);
  EXPECT_TRUE(LooksLikeCad(cylinder));

  const TriangleMesh sphere = MakeSphere(1.0, 48);
  EXPECT_EQ(MeasureSharpEdgeContent(sphere, angle).SharpLength, 0.0);
  // Scan-like noise makes some raw normals differ by more than 45 degrees;
  // the filtered normals do not confirm them, and no crease is long.
  const TriangleMesh noisy = test::WithNoise(sphere, 0.005, 20261205);
  const SharpEdgeContent rough = MeasureSharpEdgeContent(noisy, angle, 0);
  const SharpEdgeContent filtered = MeasureSharpEdgeContent(noisy, angle);
  EXPECT_GT(rough.SharpLength, 0.0);
  EXPECT_LT(filtered.SharpLength, 0.5 * rough.SharpLength);
  EXPECT_FALSE(LooksLikeCad(filtered));

  // A filleted box has no sharp edge: its fillets are smooth.
  EXPECT_FALSE(LooksLikeCad(MeasureSharpEdgeContent(MakeRoundedBox({ 2, 1, 1 }, 0.2, 8), angle)));
}

// The filter visits only the rings the flagged triangles depend on, and
// gives them the values the filter of every triangle gives; the feature
// adjacency built on it is the one the full filter confirms.
TEST(FeatureNormals, FilteredWhereNeededAsEverywhere)
{
  const double angle = 0.25 * 3.14159265358979;
  const int iterations = 3;
  const TriangleMesh noisy = test::WithNoise(MakeCylinder(1.0, 2.0, 64), 0.01, 20261207);
  const std::size_t nt = noisy.Triangles.size();
  const std::vector<Point3> own = BilateralFaceNormals(noisy, 0);
  const std::vector<Point3> everywhere = BilateralFaceNormals(noisy, iterations);
  std::vector<std::uint8_t> needed(nt, 0);
  for (std::size_t t = 0; t < nt; t += 37)
  {
    needed[t] = 1;
  }
  const std::vector<Point3> some = BilateralFaceNormals(noisy, iterations, 0.35, &needed);
  ASSERT_EQ(some.size(), nt);
  for (std::size_t t = 0; t < nt; ++t)
  {
    const Point3& expected = needed[t] ? everywhere[t] : own[t];
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_EQ(some[t][c], expected[c]) << "triangle " << t;
    }
  }

  // The raw test, then convex edges the full filter smooths away dropped.
  TriangleAdjacency expected = ComputeTriangleAdjacency(noisy, angle);
  int dropped = 0, kept = 0;
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      EdgeFeature& f = expected.Feature[t][k];
      if (f != EdgeFeature::Convex)
      {
        continue;
      }
      const Index across = expected.Neighbour[t][k];
      if (Dot(everywhere[t], everywhere[across]) >= std::cos(angle))
      {
        f = EdgeFeature::None;
        ++dropped;
      }
      else
      {
        ++kept;
      }
    }
  }
  EXPECT_GT(dropped, 0); // the noise makes raw ridges the filter does not confirm
  EXPECT_GT(kept, 0);    // the rims stay
  std::vector<Point3> filtered;
  const TriangleAdjacency adjacency = FeatureAdjacency(noisy, angle, iterations, &filtered);
  EXPECT_EQ(adjacency.Neighbour, expected.Neighbour);
  EXPECT_EQ(adjacency.Feature, expected.Feature);
  ASSERT_EQ(filtered.size(), nt);
}
