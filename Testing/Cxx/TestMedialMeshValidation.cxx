// SPDX-License-Identifier: GPL-3.0-or-later
// The shared medial-mesh validity check, on plain meshes and on poly data.
#include "MedialMesh.h"
#include "vtkMedialMeshConversion.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>

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

TEST(MedialMeshValidation, RadiusDefects)
{
  MedialMesh m = TwoTriangles();
  m.Radii[2] = -1.0;
  EXPECT_NE(Check(m).find("1 radius that are negative"), std::string::npos) << Check(m);
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
  EXPECT_NE(Check(m).find("NaN or infinite coordinates"), std::string::npos) << Check(m);
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
  EXPECT_NE(ValidateMedialPolyData(pd).find("duplicating an edge of a triangle"), std::string::npos);

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
