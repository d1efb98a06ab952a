// SPDX-License-Identifier: GPL-3.0-or-later
// Restricted Voronoi diagram: area conservation, brute-force cell checks,
// disconnected cells of a thin plate, feature flags, determinism.
#include "Geometry/Vec3.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Support/Parallel.h"
#include "Support/Random.h"
#include "Surface/AnalyticShapes.h"
#include "Surface/SurfacePreparation.h"
#include "TestHelpers.h"
#include "Voronoi/RestrictedVoronoi.h"
#include "vtkAnalyticShapeSource.h"
#include "vtkBlueNoiseSurfaceSampler.h"
#include "vtkRestrictedVoronoiDiagram.h"
#include "vtkSurfaceFileReader.h"
#include "vtkSurfacePreparation.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

using namespace medialaxis;

namespace
{
std::vector<Point3> SitesOn(const TriangleMesh& mesh, std::size_t n, std::uint64_t seed = 3)
{
  SamplingOptions options;
  options.NumberOfSamples = n;
  options.Seed = seed;
  return SampleSurface(mesh, options).Points;
}

// Every polygon vertex is at least as close to its own site as to any other.
void ExpectVerticesInOwnCells(
  const RestrictedVoronoiDiagram& rvd, const std::vector<Point3>& sites, double tolerance)
{
  std::size_t bad = 0;
  for (std::size_t p = 0; p < rvd.NumberOfPolygons(); ++p)
  {
    const Point3& own = sites[rvd.PolygonSite[p]];
    for (Index v = rvd.Offsets[p]; v < rvd.Offsets[p + 1]; ++v)
    {
      const double dOwn = Norm(rvd.Vertices[v] - own);
      for (const Point3& s : sites)
      {
        if (Norm(rvd.Vertices[v] - s) < dOwn - tolerance)
        {
          ++bad;
          break;
        }
      }
    }
  }
  EXPECT_EQ(bad, 0u);
}

// Random surface points lie in the polygon (of their triangle) whose site is
// their nearest site.
void ExpectRandomPointsInNearestCell(const TriangleMesh& mesh, const RestrictedVoronoiDiagram& rvd,
  const std::vector<Point3>& sites, double tolerance, int count)
{
  std::vector<Index> first(mesh.Triangles.size() + 1, 0);
  for (Index t : rvd.PolygonTriangle)
  {
    ++first[t + 1];
  }
  for (std::size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    first[t + 1] += first[t];
  }
  Random random(99);
  int misplaced = 0, unfound = 0;
  for (int trial = 0; trial < count; ++trial)
  {
    const Index t = static_cast<Index>(random.Uniform() * mesh.Triangles.size());
    const Triangle& tri = mesh.Triangles[t];
    const double r1 = std::sqrt(random.Uniform()), r2 = random.Uniform();
    const Point3 x = (1 - r1) * mesh.Points[tri[0]] + (r1 * (1 - r2)) * mesh.Points[tri[1]] +
      (r1 * r2) * mesh.Points[tri[2]];
    const Point3 normal = Normalized(
      Cross(mesh.Points[tri[1]] - mesh.Points[tri[0]], mesh.Points[tri[2]] - mesh.Points[tri[0]]));
    double best = HUGE_VAL;
    for (const Point3& s : sites)
    {
      best = std::min(best, Norm(x - s));
    }
    bool found = false;
    for (Index p = first[t]; p < first[t + 1] && !found; ++p)
    {
      bool inside = true;
      const Index n = rvd.Offsets[p + 1] - rvd.Offsets[p];
      for (Index k = 0; k < n && inside; ++k)
      {
        const Point3& a = rvd.Vertices[rvd.Offsets[p] + k];
        const Point3& b = rvd.Vertices[rvd.Offsets[p] + (k + 1) % n];
        inside = Dot(Cross(b - a, x - a), normal) >= -tolerance * Norm(b - a);
      }
      if (inside)
      {
        found = true;
        if (Norm(x - sites[rvd.PolygonSite[p]]) > best + tolerance)
        {
          ++misplaced;
        }
      }
    }
    unfound += found ? 0 : 1;
  }
  EXPECT_EQ(unfound, 0);
  EXPECT_EQ(misplaced, 0);
}

double RelativeAreaError(const RestrictedVoronoiDiagram& rvd, const TriangleMesh& mesh)
{
  double total = 0.0;
  for (double a : rvd.CellArea)
  {
    total += a;
  }
  return std::fabs(total / SurfaceArea(mesh) - 1.0);
}
}

TEST(RestrictedVoronoi, AreaIsConserved)
{
  for (const TriangleMesh& mesh : { MakeSphere(1.0, 16), MakeTorus(2.0, 0.5, 8),
         MakeRoundedBox({ 2, 1, 1 }, 0.2, 8), MakeLBlock({ 2, 2, 1 }, 4) })
  {
    const RestrictedVoronoiDiagram rvd = ComputeRestrictedVoronoi(mesh, SitesOn(mesh, 3000));
    EXPECT_LT(RelativeAreaError(rvd, mesh), 1e-9);
    for (double a : rvd.CellArea)
    {
      EXPECT_GT(a, 0.0);
    }
  }
}

TEST(RestrictedVoronoi, BruteForceCellsOnSmallMeshes)
{
  for (const TriangleMesh& mesh : { MakeSphere(1.0, 6), MakeLBlock({ 2, 2, 1 }, 2) })
  {
    const std::vector<Point3> sites = SitesOn(mesh, 400);
    const RestrictedVoronoiDiagram rvd = ComputeRestrictedVoronoi(mesh, sites);
    const double tolerance = 1e-9 * test::Diagonal(mesh);
    ExpectVerticesInOwnCells(rvd, sites, tolerance);
    ExpectRandomPointsInNearestCell(mesh, rvd, sites, tolerance, 3000);
  }
}

TEST(RestrictedVoronoi, RealMeshAreaAndCells)
{
  TriangleMesh mesh;
  if (!test::ReadSharedMesh("fandisk.off", mesh))
  {
    GTEST_SKIP() << "shared meshes not present";
  }
  const std::vector<Point3> sites = SitesOn(mesh, 2000);
  const RestrictedVoronoiDiagram rvd = ComputeRestrictedVoronoi(mesh, sites);
  EXPECT_LT(RelativeAreaError(rvd, mesh), 1e-9);
  ExpectRandomPointsInNearestCell(mesh, rvd, sites, 1e-9 * test::Diagonal(mesh), 2000);
}

TEST(RestrictedVoronoi, ThinPlateCellsKeepBothPieces)
{
  // A 2 x 2 plate 0.02 thick; sites on a grid on the top face and on a
  // shifted grid on the bottom face. Each site is nearer to the face below
  // or above it than any site of that face, so its cell has two pieces.
  const TriangleMesh plate = MakeRoundedBox({ 2.0, 2.0, 0.02 }, 0.0, 40);
  std::vector<Point3> sites;
  const int n = 10;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const double x = -0.9 + 0.2 * i, y = -0.9 + 0.2 * j;
      sites.push_back({ x, y, 0.01 });
      sites.push_back({ x + 0.1 - 1e-3, y + 0.1 - 2e-3, -0.01 });
    }
  }
  const RestrictedVoronoiDiagram rvd = ComputeRestrictedVoronoi(plate, sites);
  EXPECT_LT(RelativeAreaError(rvd, plate), 1e-9);
  // Away from the plate's rim (where a cell wraps around the side and its two
  // pieces join), every cell has exactly two pieces.
  int interior = 0, twoPieces = 0;
  for (std::size_t s = 0; s < sites.size(); ++s)
  {
    if (std::fabs(sites[s][0]) < 0.75 && std::fabs(sites[s][1]) < 0.75)
    {
      ++interior;
      twoPieces += rvd.CellComponents[s] == 2 ? 1 : 0;
    }
  }
  std::cout << twoPieces << " of " << interior << " interior cells have two pieces\n";
  EXPECT_GT(interior, 100);
  EXPECT_EQ(twoPieces, interior);
  ExpectRandomPointsInNearestCell(plate, rvd, sites, 1e-9 * test::Diagonal(plate), 5000);
  // Both faces of every piece are found: each top site owns area on the bottom.
  std::vector<double> bottomArea(sites.size(), 0.0);
  for (std::size_t p = 0; p < rvd.NumberOfPolygons(); ++p)
  {
    if (rvd.Vertices[rvd.Offsets[p]][2] < -0.0099 &&
      rvd.Vertices[rvd.Offsets[p] + 1][2] < -0.0099 &&
      rvd.Vertices[rvd.Offsets[p] + 2][2] < -0.0099)
    {
      bottomArea[rvd.PolygonSite[p]] += 1.0;
    }
  }
  int topSitesReachingBottom = 0;
  for (std::size_t s = 0; s < sites.size(); s += 2)
  {
    topSitesReachingBottom += bottomArea[s] > 0 ? 1 : 0;
  }
  EXPECT_EQ(topSitesReachingBottom, n * n);
}

namespace
{
// Sites flagged convex against their distance to the nearest edge of the
// box [-1, 1]^3, in units of the ideal sample spacing.
struct BoxFeatureFlags
{
  int Missed = 0;   // within 0.25 spacings of an edge and not flagged
  int Spurious = 0; // over 2 spacings from every edge and flagged
  int Concave = 0;  // flagged concave (the box has no concave edge)
};

BoxFeatureFlags CheckBoxFeatures(
  const std::vector<Point3>& sites, const RestrictedVoronoiDiagram& rvd)
{
  const double spacing = IdealSampleSpacing(24.0, sites.size());
  BoxFeatureFlags flags;
  for (std::size_t i = 0; i < sites.size(); ++i)
  {
    // Distance to the nearest box edge: the second-largest gap to a face.
    double gaps[3];
    for (int k = 0; k < 3; ++k)
    {
      gaps[k] = 1.0 - std::fabs(sites[i][k]);
    }
    std::sort(gaps, gaps + 3);
    const double toEdge = std::hypot(gaps[0], gaps[1]);
    flags.Missed += toEdge < 0.25 * spacing && !rvd.ConvexFeature[i];
    flags.Spurious += toEdge > 2.0 * spacing && rvd.ConvexFeature[i];
    flags.Concave += rvd.ConcaveFeature[i];
  }
  return flags;
}
}

TEST(RestrictedVoronoi, ConvexFeaturesOnABox)
{
  const TriangleMesh box = MakeRoundedBox({ 2.0, 2.0, 2.0 }, 0.0, 8);
  const std::vector<Point3> sites = SitesOn(box, 3000);
  const BoxFeatureFlags flags = CheckBoxFeatures(sites, ComputeRestrictedVoronoi(box, sites));
  EXPECT_EQ(flags.Missed, 0);
  EXPECT_EQ(flags.Spurious, 0);
  EXPECT_EQ(flags.Concave, 0);
}

// Every vertex of a finely meshed box (grid spacing 0.125) moved by up to
// 0.04 (1.2% of the diagonal) in a random direction: the raw normals take the noise for sharp edges
// all over the faces; with the bilateral filter confirming them only the box edges stay.
TEST(RestrictedVoronoi, NoiseDoesNotPassForSharpEdges)
{
  TriangleMesh box = MakeRoundedBox({ 2.0, 2.0, 2.0 }, 0.0, 16);
  Random random(29);
  for (Point3& p : box.Points)
  {
    Point3 d;
    do
    {
      d = { 2.0 * random.Uniform() - 1.0, 2.0 * random.Uniform() - 1.0,
        2.0 * random.Uniform() - 1.0 };
    } while (Dot(d, d) > 1.0);
    p = p + 0.04 * d;
  }
  const std::vector<Point3> sites = SitesOn(box, 3000);
  RestrictedVoronoiOptions rawOptions;
  rawOptions.FeatureNormalFiltering = 0;
  const BoxFeatureFlags raw =
    CheckBoxFeatures(sites, ComputeRestrictedVoronoi(box, sites, rawOptions));
  const BoxFeatureFlags filtered = CheckBoxFeatures(sites, ComputeRestrictedVoronoi(box, sites));
  std::printf("raw normals: %d missed, %d spurious, %d concave; filtered: %d, %d, %d\n", raw.Missed,
    raw.Spurious, raw.Concave, filtered.Missed, filtered.Spurious, filtered.Concave);
  EXPECT_GT(raw.Spurious, 50); // the noise does fool the raw test
  EXPECT_EQ(filtered.Missed, 0);
  EXPECT_EQ(filtered.Spurious, 0);
  EXPECT_EQ(filtered.Concave, raw.Concave);
}

TEST(RestrictedVoronoi, ConcaveFeaturesOnAnLBlock)
{
  const TriangleMesh block = MakeLBlock({ 2.0, 2.0, 1.0 }, 4);
  const std::vector<Point3> sites = SitesOn(block, 3000);
  const RestrictedVoronoiDiagram rvd = ComputeRestrictedVoronoi(block, sites);
  const double spacing = IdealSampleSpacing(SurfaceArea(block), sites.size());
  int nearInner = 0, flaggedNearInner = 0, spurious = 0;
  for (std::size_t i = 0; i < sites.size(); ++i)
  {
    // The concave edge is the z axis segment inside the block.
    const double toInnerEdge = std::hypot(sites[i][0], sites[i][1]);
    if (toInnerEdge < 0.25 * spacing)
    {
      ++nearInner;
      flaggedNearInner += rvd.ConcaveFeature[i];
    }
    if (toInnerEdge > 2.0 * spacing && rvd.ConcaveFeature[i])
    {
      ++spurious;
    }
  }
  EXPECT_GT(nearInner, 0);
  EXPECT_EQ(flaggedNearInner, nearInner);
  EXPECT_EQ(spurious, 0);
}

TEST(RestrictedVoronoi, IdenticalWithOneOrTwoThreads)
{
  const TriangleMesh mesh = MakeTorus(2.0, 0.5, 12);
  const std::vector<Point3> sites = SitesOn(mesh, 5000);
  const auto one = RunWithThreads(1, [&] { return ComputeRestrictedVoronoi(mesh, sites); });
  const auto two = RunWithThreads(2, [&] { return ComputeRestrictedVoronoi(mesh, sites); });
  ASSERT_EQ(one.Vertices.size(), two.Vertices.size());
  EXPECT_EQ(
    0, std::memcmp(one.Vertices.data(), two.Vertices.data(), one.Vertices.size() * sizeof(Point3)));
  EXPECT_EQ(one.PolygonSite, two.PolygonSite);
  EXPECT_EQ(one.PolygonTriangle, two.PolygonTriangle);
  EXPECT_EQ(
    0, std::memcmp(one.CellArea.data(), two.CellArea.data(), one.CellArea.size() * sizeof(double)));
  EXPECT_EQ(one.CellComponents, two.CellComponents);
  EXPECT_EQ(one.ConvexFeature, two.ConvexFeature);
  EXPECT_EQ(one.ConcaveFeature, two.ConcaveFeature);
}

TEST(RestrictedVoronoiDiagram, FilterPipelineAndArrays)
{
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToLBlock();
  shape->SetResolution(3);
  vtkNew<vtkBlueNoiseSurfaceSampler> sampler;
  sampler->SetInputConnection(shape->GetOutputPort());
  sampler->SetNumberOfSamples(800);
  vtkNew<vtkRestrictedVoronoiDiagram> rvd;
  rvd->SetInputConnection(0, shape->GetOutputPort());
  rvd->SetInputConnection(1, sampler->GetOutputPort());
  rvd->Update();
  vtkPolyData* cells = rvd->GetOutput(0);
  vtkPolyData* sites = vtkPolyData::SafeDownCast(rvd->GetOutputDataObject(1));
  ASSERT_GT(cells->GetNumberOfPolys(), 800);
  ASSERT_NE(cells->GetCellData()->GetArray("SiteId"), nullptr);
  ASSERT_NE(cells->GetCellData()->GetArray("TriangleId"), nullptr);
  ASSERT_EQ(sites->GetNumberOfPoints(), 800);
  for (const char* name : { "CellArea", "CellCentroid", "ConvexFeature", "ConcaveFeature",
         "CellComponents", "Normals", "TriangleId" })
  {
    EXPECT_NE(sites->GetPointData()->GetArray(name), nullptr) << name;
  }
  double total = 0.0;
  vtkDataArray* area = sites->GetPointData()->GetArray("CellArea");
  for (vtkIdType i = 0; i < area->GetNumberOfTuples(); ++i)
  {
    total += area->GetComponent(i, 0);
  }
  EXPECT_NEAR(total / shape->GetExactArea(), 1.0, 1e-9);
}
