// SPDX-License-Identifier: GPL-3.0-or-later
#include "Structure/MedialStructure.h"
#include "Structure/TangentComponents.h"
#include "TestHelpers.h"
#include "vtkMedialMeshConversion.h"

#include "vtkAnalyticShapeSource.h"
#include "vtkAtlasMedialAxisSimplifier.h"
#include "vtkCell.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFilletDetector.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkMath.h"
#include "vtkMedialStructure.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStructuralMedialAxis.h"
#include "vtkTrivialProducer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <vector>

namespace
{
using namespace medialaxis;
using Type = MedialVertexType;

// Three sheets hinged on one seam of two edges along x (a T of plates seen
// from its medial axis): each wing is two quads of two triangles.
MedialMesh ThreeWings()
{
  MedialMesh m;
  for (int k = 0; k < 3; ++k)
  {
    m.Centers.push_back({ static_cast<double>(k), 0, 0 });
  }
  const Point3 directions[3] = { { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 } };
  for (const Point3& d : directions)
  {
    const Index w = static_cast<Index>(m.Centers.size());
    for (int k = 0; k < 3; ++k)
    {
      m.Centers.push_back(Point3{ static_cast<double>(k), 0, 0 } + d);
    }
    m.Faces.push_back({ 0, 1, w + 1 });
    m.Faces.push_back({ 0, w + 1, w });
    m.Faces.push_back({ 1, 2, w + 2 });
    m.Faces.push_back({ 1, w + 2, w + 1 });
  }
  m.Radii.assign(m.Centers.size(), 0.5);
  return m;
}
}

TEST(MedialStructure, ThreeSheetsMeetOnOneSeam)
{
  const MedialStructure s = ClassifyMedialStructure(ThreeWings());
  for (Index v : { 0, 1, 2 })
  {
    EXPECT_EQ(s.VertexType[v], Type::Seam) << v;
  }
  for (std::size_t v = 3; v < s.VertexType.size(); ++v)
  {
    EXPECT_EQ(s.VertexType[v], Type::Rim) << v;
  }
  ASSERT_EQ(s.Sheets.size(), 3u);
  for (const MedialSheet& sheet : s.Sheets)
  {
    EXPECT_EQ(sheet.Triangles, 4u);
    EXPECT_NEAR(sheet.Area, 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(sheet.MeanRadius, 0.5);
  }
  // The two triangles of a wing's quad are in one sheet, the wings apart.
  EXPECT_EQ(s.FaceSheet[0], s.FaceSheet[3]);
  EXPECT_NE(s.FaceSheet[0], s.FaceSheet[4]);
  ASSERT_EQ(s.SeamEdges.size(), 2u);
  EXPECT_EQ(s.NumberOfSeams, 1u);
  EXPECT_EQ(s.SeamOfEdge[0], s.SeamOfEdge[1]);
  EXPECT_EQ(s.TypeCounts[static_cast<int>(Type::Seam)], 3u);
  EXPECT_EQ(s.TypeCounts[static_cast<int>(Type::Rim)], 9u);
}

// A tiny triangle hanging on a sheet's inner edge is a flap of that sheet,
// not a sheet of its own, and makes no seam; kept (fraction 0), it does.
TEST(MedialStructure, FlapsJoinTheirSheet)
{
  MedialMesh m = ThreeWings();
  const Index flap = static_cast<Index>(m.Centers.size());
  m.Centers.push_back({ 1, 0.01, 0.001 });
  m.Radii.push_back(0.5);
  m.Faces.push_back({ 1, 4, flap }); // on the first wing's inner edge (1, 4)
  const Index flapFace = static_cast<Index>(m.Faces.size()) - 1;
  MedialStructure s = ClassifyMedialStructure(m);
  EXPECT_EQ(s.Sheets.size(), 3u);
  EXPECT_EQ(s.FaceSheet[flapFace], s.FaceSheet[0]);
  EXPECT_EQ(s.SeamEdges.size(), 2u);
  EXPECT_EQ(s.VertexType[4], Type::Rim);
  EXPECT_EQ(s.VertexType[flap], Type::Rim);

  MedialStructureOptions keep;
  keep.MinimumSheetFraction = 0.0;
  s = ClassifyMedialStructure(m, keep);
  EXPECT_EQ(s.Sheets.size(), 5u); // the flap, and the wing cut in two by it
  EXPECT_EQ(s.SeamEdges.size(), 3u);
  EXPECT_EQ(s.VertexType[4], Type::Seam);
}

// A sheet that meets only itself on an edge of three faces is folded there,
// not seamed.
TEST(MedialStructure, ASheetMeetingItselfIsNoSeam)
{
  MedialMesh m;
  m.Centers = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 1, 1, 1 },
    { -1, 0, 1 } };
  m.Radii.assign(m.Centers.size(), 0.3);
  // Three faces on (0, 1), joined to each other by faces around it.
  m.Faces = { { 0, 1, 2 }, { 0, 1, 3 }, { 0, 1, 4 }, { 1, 2, 5 }, { 1, 5, 3 }, { 0, 4, 6 },
    { 0, 6, 3 } };
  MedialStructureOptions keep;
  keep.MinimumSheetFraction = 0.0;
  const MedialStructure s = ClassifyMedialStructure(m, keep);
  EXPECT_TRUE(s.SeamEdges.empty());
  EXPECT_EQ(s.Sheets.size(), 1u);
  EXPECT_EQ(s.VertexType[0], Type::Rim);
}

// Three seams from one vertex: a junction, and the seams end there.
TEST(MedialStructure, SeamsMeetAtAJunction)
{
  MedialMesh m;
  m.Centers = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, -1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 } };
  m.Radii.assign(m.Centers.size(), 0.2);
  m.Faces = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 4 }, { 0, 2, 5 }, { 0, 3, 6 } };
  const MedialStructure s = ClassifyMedialStructure(m);
  EXPECT_EQ(s.VertexType[0], Type::Junction);
  for (Index v : { 1, 2, 3 })
  {
    EXPECT_EQ(s.VertexType[v], Type::Seam) << v;
  }
  for (Index v : { 4, 5, 6 })
  {
    EXPECT_EQ(s.VertexType[v], Type::Rim) << v;
  }
  EXPECT_EQ(s.SeamEdges.size(), 3u);
  EXPECT_EQ(s.NumberOfSeams, 3u);
  EXPECT_EQ(s.Sheets.size(), 6u);
}

// Zero radius, a curve hanging off a sheet, an isolated vertex, and flags
// given by the caller.
TEST(MedialStructure, FeaturesCurvesAndFlags)
{
  MedialMesh m;
  m.Centers = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 2, 0 }, { 5, 5, 5 } };
  m.Radii = { 0.0, 1.0, 2.0, 1.0, 1.0, 1.0 };
  m.Faces = { { 0, 1, 2 }, { 0, 2, 3 } };
  m.Edges = { { 2, 4 } };
  MedialStructure s = ClassifyMedialStructure(m);
  EXPECT_EQ(s.VertexType[0], Type::Feature);
  EXPECT_EQ(s.VertexType[1], Type::Rim);
  EXPECT_EQ(s.VertexType[2], Type::Junction);
  EXPECT_EQ(s.VertexType[4], Type::Curve);
  EXPECT_EQ(s.VertexType[5], Type::Isolated);
  ASSERT_EQ(s.Sheets.size(), 1u);
  EXPECT_NEAR(s.Sheets[0].Area, 1.0, 1e-12);
  // Area-weighted, linear on each triangle: (0 + 1 + 2) / 3 and (0 + 2 + 1) / 3.
  EXPECT_NEAR(s.Sheets[0].MeanRadius, 1.0, 1e-12);
  EXPECT_EQ(s.Sheets[0].MinimumRadius, 0.0);
  EXPECT_EQ(s.Sheets[0].MaximumRadius, 2.0);

  MedialStructureOptions options;
  options.FeatureVertex = { 0, 0, 0, 1, 0, 0 };
  options.FilletVertex = { 0, 1, 0, 0, 0, 0 };
  s = ClassifyMedialStructure(m, options);
  EXPECT_EQ(s.VertexType[0], Type::Rim); // radius 0 but not flagged
  EXPECT_EQ(s.VertexType[1], Type::Fillet);
  EXPECT_EQ(s.VertexType[3], Type::Feature);
  // An edge between two feature vertices splits sheets.
  options.FeatureVertex = { 1, 0, 1, 0, 0, 0 };
  s = ClassifyMedialStructure(m, options);
  EXPECT_EQ(s.Sheets.size(), 2u);
}

// Cells as unit squares in a row on two parallel planes, each square's
// corners computed on its own (as the diagram computes every polygon): the
// Atlas pieces are the runs of touching squares.
TEST(MedialStructure, TangentComponentsAreTouchingCells)
{
  std::vector<Point3> vertices;
  std::vector<Index> offsets{ 0 }, polygonSite;
  for (int side = 0; side < 2; ++side)
  {
    for (int i = 0; i < 3; ++i)
    {
      const double x = i, z = side;
      for (const Point3& p :
        { Point3{ x, 0, z }, Point3{ x + 1, 0, z }, Point3{ x + 1, 1, z }, Point3{ x, 1, z } })
      {
        vertices.push_back(p);
      }
      offsets.push_back(static_cast<Index>(vertices.size()));
      polygonSite.push_back(3 * side + i);
    }
  }
  const SiteAdjacency adjacency = ComputeSiteAdjacency(vertices, offsets, polygonSite, 6, 1e-9);
  const std::vector<Index> expected[6] = { { 1 }, { 0, 2 }, { 1 }, { 4 }, { 3, 5 }, { 4 } };
  for (Index s = 0; s < 6; ++s)
  {
    const std::vector<Index> found(adjacency.Neighbours.begin() + adjacency.Offsets[s],
      adjacency.Neighbours.begin() + adjacency.Offsets[s + 1]);
    EXPECT_EQ(found, expected[s]) << "site " << s;
  }
  // Atlases: a sheet ball (both sides), one side, one side in two runs, a
  // junction-like four, and an empty one.
  const std::vector<Index> atlasOffsets{ 0, 4, 7, 9, 13, 13 };
  const std::vector<Index> atlasSites{ 0, 1, 3, 4, 0, 1, 2, 0, 2, 0, 2, 3, 5 };
  EXPECT_EQ(CountTangentComponents(atlasOffsets, atlasSites, adjacency),
    (std::vector<int>{ 2, 1, 2, 4, 0 }));
}

// With tangent components given, the two rules are compared, and MATFP's
// decides when asked.
TEST(MedialStructure, TangentComponentsCrossCheckTheMesh)
{
  const MedialMesh m = ThreeWings();
  MedialStructureOptions options;
  options.TangentComponents.assign(m.NumberOfVertices(), 1); // rims
  for (Index v : { 0, 1, 2 })
  {
    options.TangentComponents[v] = 3; // the seam
  }
  options.TangentComponents[1] = 2; // one seam vertex seen as a sheet
  MedialStructure s = ClassifyMedialStructure(m, options);
  EXPECT_EQ(s.ComparedVertices, m.NumberOfVertices());
  EXPECT_EQ(s.Disagreements, 1u);
  EXPECT_EQ(s.VertexType[1], Type::Seam);
  options.ByTangentComponents = true;
  s = ClassifyMedialStructure(m, options);
  EXPECT_EQ(s.VertexType[1], Type::Sheet);
  EXPECT_EQ(s.VertexType[0], Type::Seam);
  EXPECT_EQ(s.VertexType[5], Type::Rim);
  EXPECT_EQ(TypeFromTangentComponents(5), Type::Junction);
}

// The filter on a rounded box's Structural MAT with its fillet centre lines.
// The box [-1, 1]^3 with fillets of radius 0.1 has the medial axis of the
// cube [-0.9, 0.9]^3, radii 0.1 larger: twelve sheets, one per edge, each the
// triangle from the edge to the centre (area 0.9^2 sqrt 2, radius 0.1 on the
// edge to 1 at the centre, 0.4 on average by area), meeting on eight seams
// from the corners (length 0.9 sqrt 3) at one junction, the centre. Where a
// seam of the discrete mesh misses an edge, two neighbouring sheets join:
// every sheet found must be one or more whole true sheets.
TEST(MedialStructure, RoundedBoxInAPipeline)
{
  vtkNew<vtkAnalyticShapeSource> part;
  part->SetShapeToRoundedBox();
  part->SetFilletRadius(0.1);
  test::InitialMedialPipeline initial(part->GetOutputPort(), 20000);
  vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
  simplifier->SetInputConnection(0, initial.Voronoi->GetOutputPort());
  simplifier->SetInputConnection(1, initial.Rvd->GetOutputPort(0));
  simplifier->SetTargetNumberOfVertices(2000);
  vtkNew<vtkFilletDetector> detector;
  detector->SetInputConnection(0, simplifier->GetOutputPort(0));
  detector->SetInputConnection(1, simplifier->GetOutputPort(1));
  detector->SetInputConnection(2, part->GetOutputPort());
  vtkNew<vtkMedialStructure> structure;
  structure->SetInputConnection(0, simplifier->GetOutputPort(0));
  structure->SetFilletLinesConnection(detector->GetOutputPort(0));
  structure->SetCellsConnection(simplifier->GetOutputPort(1));
  structure->Update();

  vtkPolyData* out = structure->GetOutput(0);
  vtkPolyData* seams = structure->GetOutput(1);
  auto* type = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("MedialType"));
  ASSERT_NE(type, nullptr);
  ASSERT_EQ(type->GetNumberOfTuples(), out->GetNumberOfPoints());
  vtkIdType total = 0;
  for (int t = 0; t < NumberOfMedialVertexTypes; ++t)
  {
    total += structure->GetNumberOfVerticesOfType(t);
  }
  EXPECT_EQ(total, out->GetNumberOfPoints());

  // Every centre-line vertex is a fillet vertex, and only those.
  vtkDataArray* ids = detector->GetOutput(0)->GetPointData()->GetArray("MedialVertexId");
  ASSERT_NE(ids, nullptr);
  std::set<vtkIdType> onLines;
  for (vtkIdType i = 0; i < ids->GetNumberOfTuples(); ++i)
  {
    onLines.insert(static_cast<vtkIdType>(ids->GetComponent(i, 0)));
  }
  EXPECT_GT(onLines.size(), 100u);
  EXPECT_EQ(structure->GetNumberOfVerticesOfType(static_cast<int>(Type::Fillet)),
    static_cast<vtkIdType>(onLines.size()));
  for (vtkIdType v : onLines)
  {
    EXPECT_EQ(type->GetValue(v), static_cast<int>(Type::Fillet));
  }

  const double sheetArea = 0.81 * std::sqrt(2.0), seamLength = 0.9 * std::sqrt(3.0);
  vtkFieldData* fields = out->GetFieldData();
  vtkDataArray* areas = fields->GetArray("SheetArea");
  ASSERT_NE(areas, nullptr);
  ASSERT_EQ(areas->GetNumberOfTuples(), structure->GetNumberOfSheets());
  long trueSheets = 0;
  for (vtkIdType sheet = 0; sheet < areas->GetNumberOfTuples(); ++sheet)
  {
    const double area = areas->GetComponent(sheet, 0);
    const long k = std::lround(area / sheetArea);
    EXPECT_GE(k, 1) << "sheet " << sheet << " of area " << area;
    EXPECT_NEAR(area, k * sheetArea, 0.02 * k * sheetArea) << "sheet " << sheet;
    EXPECT_NEAR(fields->GetArray("SheetMeanRadius")->GetComponent(sheet, 0), 0.4, 0.012);
    // (radii within 0.3% of the diagonal, as the simplified mesh's are)
    EXPECT_NEAR(fields->GetArray("SheetMinimumRadius")->GetComponent(sheet, 0), 0.1, 0.01);
    EXPECT_NEAR(fields->GetArray("SheetMaximumRadius")->GetComponent(sheet, 0), 1.0, 0.02);
    trueSheets += k;
  }
  EXPECT_EQ(trueSheets, 12);
  EXPECT_EQ(test::FieldValue(out, "NumberOfSheets"), structure->GetNumberOfSheets());
  ASSERT_EQ(structure->GetNumberOfSeams(), 8);
  ASSERT_EQ(structure->GetNumberOfVerticesOfType(static_cast<int>(Type::Junction)), 1);
  vtkDataArray* radius = out->GetPointData()->GetArray("Radius");
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v)
  {
    if (type->GetValue(v) == static_cast<int>(Type::Junction))
    {
      double p[3];
      out->GetPoint(v, p);
      EXPECT_LT(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]), 0.02);
      EXPECT_NEAR(radius->GetComponent(v, 0), 1.0, 0.02);
    }
  }
  // MATFP's rule from the Atlas agrees: 2 pieces on sheets, 3 on seams.
  ASSERT_NE(out->GetPointData()->GetArray("TangentComponents"), nullptr);
  EXPECT_GE(test::FieldValue(out, "TangentComponentAgreement"), 0.99);
  EXPECT_EQ(test::FieldValue(out, "TypeDisagreements"), structure->GetTypeDisagreements());
  EXPECT_EQ(test::FieldValue(out, "NumberOfSheets"), structure->GetNumberOfSheets());
  ASSERT_NE(out->GetFieldData()->GetArray("SheetArea"), nullptr);
  EXPECT_EQ(out->GetFieldData()->GetArray("SheetArea")->GetNumberOfTuples(),
    structure->GetNumberOfSheets());
  vtkDataArray* sheetIds = out->GetCellData()->GetArray("SheetId");
  ASSERT_NE(sheetIds, nullptr);
  EXPECT_EQ(sheetIds->GetNumberOfTuples(), out->GetNumberOfCells());
  // The seams output: one line per seam edge, each end a seam or junction
  // vertex (or a fillet / feature one, which take precedence).
  vtkDataArray* seamIds = seams->GetCellData()->GetArray("SeamId");
  ASSERT_NE(seamIds, nullptr);
  EXPECT_EQ(seamIds->GetNumberOfTuples(), seams->GetNumberOfLines());
  for (vtkIdType c = 0; c < seams->GetNumberOfCells(); ++c)
  {
    for (vtkIdType k = 0; k < 2; ++k)
    {
      const int t = type->GetValue(seams->GetCell(c)->GetPointId(k));
      EXPECT_TRUE(t == static_cast<int>(Type::Seam) || t == static_cast<int>(Type::Junction) ||
        t == static_cast<int>(Type::Fillet) || t == static_cast<int>(Type::Feature))
        << "seam edge " << c << " has a vertex of type " << t;
    }
  }
  std::vector<double> length(8, 0.0);
  for (vtkIdType c = 0; c < seams->GetNumberOfCells(); ++c)
  {
    double p[3], q[3];
    seams->GetPoint(seams->GetCell(c)->GetPointId(0), p);
    seams->GetPoint(seams->GetCell(c)->GetPointId(1), q);
    length.at(static_cast<std::size_t>(seamIds->GetComponent(c, 0))) +=
      std::sqrt(vtkMath::Distance2BetweenPoints(p, q));
  }
  for (double l : length)
  {
    EXPECT_NEAR(l, seamLength, 0.01 * seamLength);
  }
  std::cout << "rounded box: " << structure->GetTypeDisagreements() << " disagreements, "
            << structure->GetNumberOfSheets() << " sheets, " << structure->GetNumberOfSeams()
            << " seams, types";
  for (int t = 0; t < NumberOfMedialVertexTypes; ++t)
  {
    std::cout << " " << MedialVertexTypeName(static_cast<Type>(t)) << " "
              << structure->GetNumberOfVerticesOfType(t);
  }
  std::cout << "\n";
}

// A T-plate (walls 0.1 thick, junction fillets of radius 0.1): its plate's
// and rib's mid-sheets meet on one seam along x, at the centre of the
// largest ball in the junction: y = 0, z = (t/2 + rho) / 4 = 0.0375, radius
// 0.0875 (tangent to the bottom face and both fillets). The other seams run
// round the walls' free edges, where the sharp edges fork the mid-sheets.
TEST(MedialStructure, TPlateJunctionIsOneSeam)
{
  vtkNew<vtkAnalyticShapeSource> part;
  part->SetShapeToTPlate();
  part->SetXLength(2.0);
  part->SetYLength(2.0);
  part->SetZLength(1.0);
  part->SetThickness(0.1);
  part->SetFilletRadius(0.1);
  vtkNew<vtkStructuralMedialAxis> mat;
  mat->SetInputConnection(part->GetOutputPort());
  mat->SetPresetToCAD();
  vtkNew<vtkMedialStructure> structure;
  structure->SetInputConnection(0, mat->GetOutputPort(0));
  structure->SetCellsConnection(mat->GetOutputPort(1));
  structure->Update();
  vtkPolyData* seams = structure->GetOutput(1);
  vtkDataArray* radius = structure->GetOutput(0)->GetPointData()->GetArray("Radius");
  vtkDataArray* seamIds = seams->GetCellData()->GetArray("SeamId");
  ASSERT_NE(seamIds, nullptr);
  std::vector<std::set<vtkIdType>> points(structure->GetNumberOfSeams());
  for (vtkIdType c = 0; c < seams->GetNumberOfCells(); ++c)
  {
    for (vtkIdType k = 0; k < 2; ++k)
    {
      points.at(static_cast<std::size_t>(seamIds->GetComponent(c, 0)))
        .insert(seams->GetCell(c)->GetPointId(k));
    }
  }
  int junctionSeams = 0;
  for (const auto& seam : points)
  {
    // The junction's seam stays near the plate's mid-plane under the rib.
    bool underRib = true;
    double xMin = 1e9, xMax = -1e9;
    std::vector<double> z, r;
    for (vtkIdType v : seam)
    {
      double p[3];
      seams->GetPoint(v, p);
      underRib = underRib && std::fabs(p[1]) < 0.05 && p[2] < 0.1 && p[2] > -0.05;
      xMin = std::min(xMin, p[0]);
      xMax = std::max(xMax, p[0]);
      z.push_back(p[2]);
      r.push_back(radius->GetComponent(v, 0));
    }
    if (!underRib)
    {
      continue;
    }
    ++junctionSeams;
    EXPECT_LT(xMin, -0.8);
    EXPECT_GT(xMax, 0.8);
    std::nth_element(z.begin(), z.begin() + z.size() / 2, z.end());
    std::nth_element(r.begin(), r.begin() + r.size() / 2, r.end());
    EXPECT_NEAR(z[z.size() / 2], 0.0375, 0.003); // 0.1% of the diagonal
    EXPECT_NEAR(r[r.size() / 2], 0.0875, 0.003);
  }
  EXPECT_EQ(junctionSeams, 1);
  EXPECT_GE(test::FieldValue(structure->GetOutput(0), "TangentComponentAgreement"), 0.99);
}

// A sharp box's spheres of radius 0 are its feature spheres: typed feature,
// on the box's twelve edges, and every edge has them along its length.
TEST(MedialStructure, BoxFeatureSpheresAreOnItsEdges)
{
  vtkNew<vtkAnalyticShapeSource> box;
  box->SetShapeToBox();
  vtkNew<vtkStructuralMedialAxis> mat;
  mat->SetInputConnection(box->GetOutputPort());
  mat->SetPresetToCAD();
  mat->SetNumberOfSamples(20000);
  mat->SetTargetNumberOfVertices(2000);
  vtkNew<vtkMedialStructure> structure;
  structure->SetInputConnection(0, mat->GetOutputPort(0));
  structure->Update();
  vtkPolyData* out = structure->GetOutput(0);
  auto* type = vtkIntArray::SafeDownCast(out->GetPointData()->GetArray("MedialType"));
  ASSERT_NE(type, nullptr);
  // Per edge (axis a, signs of the other two), how far along it the feature
  // spheres reach.
  std::map<std::array<int, 3>, std::array<double, 2>> reach;
  int features = 0;
  for (vtkIdType v = 0; v < out->GetNumberOfPoints(); ++v)
  {
    if (type->GetValue(v) != static_cast<int>(Type::Feature))
    {
      continue;
    }
    ++features;
    double p[3];
    out->GetPoint(v, p);
    // On an edge: two coordinates at +-1.
    int along = -1, onFaces = 0;
    for (int a = 0; a < 3; ++a)
    {
      if (std::fabs(std::fabs(p[a]) - 1.0) < 0.01)
      {
        ++onFaces;
      }
      else
      {
        along = a;
      }
    }
    EXPECT_GE(onFaces, 2) << "feature sphere " << v << " at " << p[0] << " " << p[1] << " " << p[2]
                          << " is on no edge";
    // (a corner sphere is on its three edges)
    for (int a = 0; a < 3; ++a)
    {
      if (onFaces == 3 || a == along)
      {
        const std::array<int, 3> key{ a, p[(a + 1) % 3] > 0 ? 1 : -1, p[(a + 2) % 3] > 0 ? 1 : -1 };
        auto [it, added] = reach.insert({ key, { p[a], p[a] } });
        it->second = { std::min(it->second[0], p[a]), std::max(it->second[1], p[a]) };
      }
    }
  }
  EXPECT_GT(features, 100);
  EXPECT_EQ(reach.size(), 12u);
  // (to within a tenth of the edge of its corners: at 2,000 spheres the
  // feature spheres along an edge are about that far apart)
  for (const auto& [edge, range] : reach)
  {
    EXPECT_LT(range[0], -0.8);
    EXPECT_GT(range[1], 0.8);
  }
}

// Inputs that cannot be classified give an error a user can act on.
TEST(MedialStructure, ClearErrorsOnBadInput)
{
  MedialMesh m = ThreeWings();
  vtkNew<vtkPolyData> mat;
  MedialMeshToPolyData(m, mat);
  vtkNew<vtkIntArray> wrongSize;
  wrongSize->SetName("FeatureVertex");
  wrongSize->SetNumberOfTuples(2);
  mat->GetPointData()->AddArray(wrongSize);
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(mat);
  vtkNew<vtkMedialStructure> structure;
  structure->SetInputConnection(producer->GetOutputPort());
  vtkNew<test::ErrorCatcher> errors;
  structure->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  structure->Update();
  EXPECT_NE(
    errors->Last.find("'FeatureVertex' must have one value per medial vertex"), std::string::npos)
    << errors->Last;
  EXPECT_EQ(structure->GetOutput()->GetNumberOfPoints(), 0);

  mat->GetPointData()->RemoveArray("FeatureVertex");
  vtkNew<vtkPolyData> lines; // centre lines without their vertex ids
  lines->SetPoints(mat->GetPoints());
  vtkNew<vtkTrivialProducer> lineProducer;
  lineProducer->SetOutput(lines);
  structure->SetFilletLinesConnection(lineProducer->GetOutputPort());
  mat->Modified();
  structure->Update();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_INFO);
  EXPECT_EQ(errors->Count, 2);
  EXPECT_NE(errors->Last.find("no point data 'MedialVertexId'"), std::string::npos) << errors->Last;

  structure->SetFilletLinesConnection(nullptr);
  mat->Modified();
  structure->Update();
  EXPECT_EQ(structure->GetNumberOfSheets(), 3);
  EXPECT_EQ(structure->GetNumberOfSeams(), 1);
}
