// SPDX-License-Identifier: GPL-3.0-or-later
// The shared medial-mesh validity check, on plain meshes and on poly data.
#include "Mesh/MedialMesh.h"
#include "Mesh/MedialMeshQuality.h"
#include "Mesh/MedialSheets.h"
#include "vtkMedialMeshConversion.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

using namespace medialaxis;

namespace
{
MedialMesh TwoTriangles()
{
  MedialMesh m;
  m.Centers = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 3, 3, 3 } };
  m.Radii = { 0.5, 0.5, 0.5, 0.5, 0.1 };
  m.Faces = { { 0, 1, 2 }, { 1, 3, 2 } };
  m.Edges = { { 3, 4 } };
  return m;
}

std::string Check(const MedialMesh& m)
{
  return ValidateMedialMesh(m).Message;
}
}

TEST(MedialMeshValidation, ValidMeshPasses)
{
  EXPECT_EQ(Check(TwoTriangles()), "");
}

TEST(MedialMeshValidation, VertexAdjacencyListsEveryEdgeBothWays)
{
  // Two triangles sharing the edge 1-2 (listed by both) and a line 3-4.
  const MedialAdjacency a = VertexAdjacency(TwoTriangles());
  ASSERT_EQ(a.Start.size(), 6u);
  const auto row = [&](Index v)
  { return std::vector<Index>(a.Next.begin() + a.Start[v], a.Next.begin() + a.Start[v + 1]); };
  EXPECT_EQ(row(0), (std::vector<Index>{ 1, 2 }));
  EXPECT_EQ(row(1), (std::vector<Index>{ 0, 2, 3 }));
  EXPECT_EQ(row(2), (std::vector<Index>{ 0, 1, 3 }));
  EXPECT_EQ(row(3), (std::vector<Index>{ 1, 2, 4 }));
  EXPECT_EQ(row(4), (std::vector<Index>{ 3 }));
  EXPECT_EQ(a.Next.size(), 2 * AllEdges(TwoTriangles()).size());
}

TEST(MedialMeshValidation, RadiusDefects)
{
  MedialMesh m = TwoTriangles();
  m.Radii[2] = -1.0;
  EXPECT_NE(Check(m).find("has 1 radius that is negative"), std::string::npos) << Check(m);
  m.Radii[1] = std::nan("");
  EXPECT_NE(Check(m).find("has 2 radii that are negative, NaN or infinite"), std::string::npos)
    << Check(m);
  m.Radii[1] = 1.0;
  m.Radii[2] = std::nan("");
  EXPECT_NE(Check(m).find("negative, NaN or infinite"), std::string::npos);
  m.Radii.pop_back();
  EXPECT_NE(Check(m).find("4 radii for 5 vertices"), std::string::npos) << Check(m);
}

TEST(MedialMeshValidation, CellDefects)
{
  MedialMesh m = TwoTriangles();
  m.Faces.push_back({ 2, 0, 1 }); // same triangle, rotated
  EXPECT_NE(Check(m).find("1 duplicate triangle"), std::string::npos) << Check(m);

  m = TwoTriangles();
  m.Edges.push_back({ 4, 3 });
  EXPECT_NE(Check(m).find("1 duplicate edge"), std::string::npos) << Check(m);

  m = TwoTriangles();
  m.Faces.push_back({ 0, 0, 1 });
  EXPECT_NE(Check(m).find("degenerate"), std::string::npos) << Check(m);

  m = TwoTriangles();
  m.Faces.push_back({ 0, 1, 9 });
  EXPECT_NE(Check(m).find("outside [0, 5)"), std::string::npos) << Check(m);

  m = TwoTriangles();
  m.Centers[1][0] = INFINITY;
  EXPECT_NE(Check(m).find("has 1 vertex with NaN or infinite coordinates"), std::string::npos)
    << Check(m);
  m.Centers[2][1] = std::nan("");
  EXPECT_NE(Check(m).find("has 2 vertices with NaN or infinite coordinates"), std::string::npos)
    << Check(m);
}

TEST(MedialMeshValidation, PolyDataContract)
{
  vtkNew<vtkPolyData> pd;
  MedialMeshToPolyData(TwoTriangles(), pd);
  EXPECT_EQ(pd->GetNumberOfPolys(), 2);
  EXPECT_EQ(pd->GetNumberOfLines(), 1);
  EXPECT_EQ(pd->GetNumberOfVerts(), 0);
  EXPECT_EQ(ValidateMedialPolyData(pd), "");

  // A line cell that repeats a triangle edge breaks the contract.
  const vtkIdType edge[2] = { 0, 1 };
  pd->GetLines()->InsertNextCell(2, edge);
  EXPECT_NE(
    ValidateMedialPolyData(pd).find("duplicating an edge of a triangle"), std::string::npos);

  vtkNew<vtkPolyData> quad;
  MedialMeshToPolyData(TwoTriangles(), quad);
  const vtkIdType four[4] = { 0, 1, 3, 2 };
  quad->GetPolys()->InsertNextCell(4, four);
  EXPECT_NE(ValidateMedialPolyData(quad).find("not triangles"), std::string::npos);

  vtkNew<vtkPolyData> noRadius;
  MedialMeshToPolyData(TwoTriangles(), noRadius);
  noRadius->GetPointData()->RemoveArray("Radius");
  EXPECT_NE(ValidateMedialPolyData(noRadius).find("'Radius'"), std::string::npos);

  vtkNew<vtkPolyData> twoComponents;
  MedialMeshToPolyData(TwoTriangles(), twoComponents);
  vtkNew<vtkDoubleArray> bad;
  bad->SetName("Radius");
  bad->SetNumberOfComponents(2);
  bad->SetNumberOfTuples(5);
  twoComponents->GetPointData()->AddArray(bad);
  EXPECT_NE(ValidateMedialPolyData(twoComponents).find("one component"), std::string::npos);
}

TEST(MedialMeshQuality, AnglesQualityDegenerateAndFolds)
{
  using medialaxis::MedialMesh;
  const double h = std::sqrt(3.0) / 2.0;
  // Two equilateral triangles sharing the edge 0-1, flat: no fold, Q = 1.
  MedialMesh flat;
  flat.Centers = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, h, 0 }, { 0.5, -h, 0 } };
  flat.Radii.assign(4, 0.1);
  flat.Faces = { { 0, 1, 2 }, { 1, 0, 3 } };
  medialaxis::MedialMeshQuality q = medialaxis::MeasureQuality(flat);
  EXPECT_EQ(q.Triangles, 2u);
  EXPECT_EQ(q.FoldedEdges, 0u);
  EXPECT_EQ(q.DegenerateTriangles, 0u);
  EXPECT_NEAR(q.MeanMinimumAngle, 60.0, 1e-9);
  EXPECT_NEAR(q.MeanQuality, 1.0, 1e-12);
  EXPECT_EQ(q.PercentMinimumAngleBelow30, 0.0);

  // A right angle between the two (a medial junction-like crease): no fold.
  MedialMesh crease = flat;
  crease.Centers[3] = { 0.5, 0, h };
  EXPECT_EQ(medialaxis::MeasureQuality(crease).FoldedEdges, 0u);
  // The second triangle turned back onto the first (5 degrees apart): a fold
  // of both triangles, whatever the order of their vertices.
  MedialMesh folded = flat;
  const double t = 5.0 * 3.14159265358979323846 / 180.0;
  folded.Centers[3] = { 0.5, h * std::cos(t), h * std::sin(t) };
  for (const auto& second : { std::array<medialaxis::Index, 3>{ 1, 0, 3 },
         std::array<medialaxis::Index, 3>{ 0, 1, 3 }, std::array<medialaxis::Index, 3>{ 3, 1, 0 } })
  {
    folded.Faces[1] = second;
    q = medialaxis::MeasureQuality(folded);
    EXPECT_EQ(q.FoldedEdges, 1u);
    EXPECT_EQ(q.FoldedTriangles, 2u);
  }
  // 15 degrees apart is a sharp crease, not a fold.
  const double wide = 15.0 * 3.14159265358979323846 / 180.0;
  folded.Centers[3] = { 0.5, h * std::cos(wide), h * std::sin(wide) };
  EXPECT_EQ(medialaxis::MeasureQuality(folded).FoldedEdges, 0u);
  // A third triangle on the edge makes it non-manifold: folds are not
  // defined there. A collinear triangle is degenerate and left out.
  folded.Centers.push_back({ 2, 0, 0 });
  folded.Radii.push_back(0.1);
  folded.Faces.push_back({ 0, 1, 4 });
  q = medialaxis::MeasureQuality(folded);
  EXPECT_EQ(q.DegenerateTriangles, 1u);
  EXPECT_EQ(q.FoldedEdges, 0u);
  EXPECT_EQ(q.Triangles, 3u);
}

namespace
{
// A flat n x n grid of unit squares in z = 0, two triangles each; vertex
// (i, j) has id i + (n + 1) j.
MedialMesh FlatGrid(int n)
{
  MedialMesh m;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      m.Centers.push_back({ double(i), double(j), 0.0 });
      m.Radii.push_back(1.0);
    }
  }
  const auto id = [n](int i, int j) { return static_cast<Index>(i + (n + 1) * j); };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      m.Faces.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      m.Faces.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return m;
}

// A fin standing on the grid edges (i, j) .. (i + length, j): a strip of
// two triangles per edge up to a row of vertices at height `height`.
void AddFin(MedialMesh& m, int n, int i, int j, int length, double height)
{
  const Index top = static_cast<Index>(m.Centers.size());
  for (int k = 0; k <= length; ++k)
  {
    m.Centers.push_back({ double(i + k), double(j), height });
    m.Radii.push_back(0.5);
  }
  for (int k = 0; k < length; ++k)
  {
    const Index a = static_cast<Index>(i + k + (n + 1) * j), b = a + 1;
    m.Faces.push_back({ a, b, top + k + 1 });
    m.Faces.push_back({ a, top + k + 1, top + k });
  }
}
}

TEST(MedialSheets, FlatSheetIsOneCleanSheet)
{
  const MedialCleanliness c = MeasureCleanliness(FlatGrid(10), 2.0);
  EXPECT_EQ(c.Sheets, 1u);
  EXPECT_EQ(c.SheetsFor80PercentArea, 1u);
  EXPECT_DOUBLE_EQ(c.LargestSheetAreaFraction, 1.0);
  EXPECT_EQ(c.FinAreaFraction, 0.0);
  EXPECT_EQ(c.FoldedEdgeFraction, 0.0);
  EXPECT_EQ(c.JunctionEdges, 0u);
  EXPECT_NEAR(c.BoundaryLength, 40.0 / 2.0, 1e-12); // the perimeter, in diagonals
  EXPECT_EQ(c.JunctionLength, 0.0);
}

TEST(MedialSheets, OneFinOnAFlatSheet)
{
  // A fin on one inner edge: the sheet goes on around the edge.
  MedialMesh m = FlatGrid(10);
  AddFin(m, 10, 4, 5, 1, 0.5);
  MedialCleanliness c = MeasureCleanliness(m);
  EXPECT_EQ(c.Sheets, 2u);
  EXPECT_EQ(c.SheetsFor80PercentArea, 1u);
  EXPECT_EQ(c.JunctionEdges, 1u);
  EXPECT_NEAR(c.JunctionLength, 1.0, 1e-12);
  const double fin = 0.5; // 1 x 0.5
  EXPECT_NEAR(c.FinAreaFraction, fin / (100.0 + fin), 1e-12);
  EXPECT_NEAR(c.LargestSheetAreaFraction, 100.0 / (100.0 + fin), 1e-12);
  EXPECT_EQ(c.FoldedEdgeFraction, 0.0);
  // The fin's two sides and its top join the boundary.
  EXPECT_NEAR(c.BoundaryLength, 40.0 + 2.0, 1e-12);

  // A fin across the whole sheet cuts it in two: three sheets, the two
  // halves holding 80% together, and a fin too large (9% of the area) to
  // count as one.
  m = FlatGrid(10);
  AddFin(m, 10, 0, 4, 10, 1.0);
  c = MeasureCleanliness(m);
  EXPECT_EQ(c.Sheets, 3u);
  EXPECT_EQ(c.SheetsFor80PercentArea, 2u);
  EXPECT_EQ(c.JunctionEdges, 10u);
  EXPECT_NEAR(c.LargestSheetAreaFraction, 60.0 / 110.0, 1e-12);
  EXPECT_EQ(c.FinAreaFraction, 0.0);
}

TEST(MedialSheets, PleatsAreSharpHinges)
{
  MedialMesh m;
  m.Centers = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, 0.3, 0.5 } };
  m.Radii = { 1, 1, 1, 1 };
  m.Faces = { { 0, 1, 2 }, { 1, 0, 3 } };
  // The half-planes meet at atan2(0.5, 0.3) = 59 degrees: a pleat.
  MedialCleanliness c = MeasureCleanliness(m);
  EXPECT_EQ(c.Sheets, 1u);
  EXPECT_DOUBLE_EQ(c.FoldedEdgeFraction, 1.0);
  // At 121 degrees (y = -0.3): a bend, not a pleat; flat: none either.
  for (double y : { -0.3, -1.0 })
  {
    m.Centers[3] = { 0.5, y, y == -1.0 ? 0.0 : 0.5 };
    c = MeasureCleanliness(m);
    EXPECT_EQ(c.FoldedEdgeFraction, 0.0) << y;
  }
  // A grid crumpled like an egg box (every other vertex one unit up): the
  // 16 diagonals among its 40 inner edges pleat; half a unit only bends it.
  m = FlatGrid(4);
  for (std::size_t v = 0; v < m.Centers.size(); ++v)
  {
    m.Centers[v][2] = (v % 5 + v / 5) % 2 == 1 ? 1.0 : 0.0;
  }
  c = MeasureCleanliness(m);
  EXPECT_EQ(c.Sheets, 1u);
  EXPECT_DOUBLE_EQ(c.FoldedEdgeFraction, 16.0 / 40.0);
  for (auto& p : m.Centers)
  {
    p[2] *= 0.5;
  }
  EXPECT_EQ(MeasureCleanliness(m).FoldedEdgeFraction, 0.0);
  const SheetDecomposition sheets = DecomposeIntoSheets(m);
  EXPECT_EQ(sheets.NumberOfSheets, 1u);
}
