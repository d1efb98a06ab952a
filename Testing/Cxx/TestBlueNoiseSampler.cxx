// SPDX-License-Identifier: GPL-3.0-or-later
// Blue-noise sampling: exact count, determinism, spacing quality against
// white noise, area-proportional density, samples on their triangles.
#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Support/Parallel.h"
#include "Surface/AnalyticShapes.h"
#include "Surface/SurfacePreparation.h"
#include "TestHelpers.h"
#include "vtkBlueNoiseSurfaceSampler.h"
#include "vtkSurfaceFileReader.h"
#include "vtkSurfacePreparation.h"

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

using namespace medialaxis;

namespace
{
struct Spacing
{
  double MinOverIdeal;
  double Variation; // coefficient of variation of nearest-neighbour distances
};

Spacing MeasureSpacing(const std::vector<Point3>& points, double area)
{
  const KdTree tree(points);
  std::vector<std::uint32_t> ids;
  std::vector<double> d2;
  double minimum = HUGE_VAL, sum = 0.0, sum2 = 0.0;
  for (const Point3& p : points)
  {
    tree.Nearest(p, 2, ids, d2);
    const double d = std::sqrt(d2[1]);
    minimum = std::min(minimum, d);
    sum += d;
    sum2 += d * d;
  }
  const double n = static_cast<double>(points.size());
  const double mean = sum / n;
  return { minimum / IdealSampleSpacing(area, points.size()),
    std::sqrt(std::max(0.0, sum2 / n - mean * mean)) / mean };
}

SurfaceSamples Sample(const TriangleMesh& mesh, std::size_t n, std::uint64_t seed = 1,
  double ratio = 4.0, int relax = 0)
{
  SamplingOptions options;
  options.NumberOfSamples = n;
  options.Seed = seed;
  options.CandidateRatio = ratio;
  options.RelaxationIterations = relax;
  return SampleSurface(mesh, options);
}

bool Identical(const SurfaceSamples& a, const SurfaceSamples& b)
{
  return a.Points.size() == b.Points.size() &&
    std::memcmp(a.Points.data(), b.Points.data(), a.Points.size() * sizeof(Point3)) == 0 &&
    a.TriangleIds == b.TriangleIds;
}
}

TEST(BlueNoiseSampler, ExactCountAndDeterminism)
{
  const TriangleMesh sphere = MakeSphere(1.0, 16);
  for (std::size_t n : { 1u, 7u, 1000u, 2345u })
  {
    EXPECT_EQ(Sample(sphere, n).Points.size(), n);
  }
  const SurfaceSamples a = Sample(sphere, 3000, 42);
  const SurfaceSamples b = Sample(sphere, 3000, 42);
  EXPECT_TRUE(Identical(a, b));
  EXPECT_FALSE(Identical(a, Sample(sphere, 3000, 43)));

  const SurfaceSamples one = RunWithThreads(1, [&] { return Sample(sphere, 3000, 42, 4.0, 1); });
  const SurfaceSamples two = RunWithThreads(2, [&] { return Sample(sphere, 3000, 42, 4.0, 1); });
  EXPECT_TRUE(Identical(one, two));
}

TEST(BlueNoiseSampler, SpacingOnUnitSphere)
{
  const TriangleMesh sphere = MakeSphere(1.0, 32);
  const double area = SurfaceArea(sphere);
  const Spacing blue = MeasureSpacing(Sample(sphere, 5000).Points, area);
  std::cout << "sphere: min/ideal " << blue.MinOverIdeal << ", CV " << blue.Variation << "\n";
  EXPECT_GE(blue.MinOverIdeal, 0.6);
  EXPECT_LT(blue.Variation, 0.15);
  // The same measure on white noise (no elimination) shows what it detects.
  const Spacing white = MeasureSpacing(Sample(sphere, 5000, 1, 1.0).Points, area);
  std::cout << "white noise: min/ideal " << white.MinOverIdeal << ", CV " << white.Variation
            << "\n";
  EXPECT_GT(white.Variation, 0.4);
  EXPECT_LT(white.MinOverIdeal, 0.1);
}

TEST(BlueNoiseSampler, SpacingOnRealMesh)
{
  const std::string path = std::string(MEDIALAXIS_MESH_DIR) + "/bunny.obj";
  if (!std::ifstream(path).good())
  {
    GTEST_SKIP() << "shared meshes not present";
  }
  vtkNew<vtkSurfaceFileReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  TriangleMesh bunny;
  ASSERT_TRUE(PrepareSurfaceMesh(reader->GetOutput(), bunny).Ok());
  const Spacing s = MeasureSpacing(Sample(bunny, 10000).Points, SurfaceArea(bunny));
  std::cout << "bunny: min/ideal " << s.MinOverIdeal << ", CV " << s.Variation << "\n";
  EXPECT_GE(s.MinOverIdeal, 0.6);
  EXPECT_LT(s.Variation, 0.15);
}

TEST(BlueNoiseSampler, DensityIsProportionalToArea)
{
  // Faces of a 2 x 1 x 0.5 box have areas 2, 1 and 0.5 (twice each).
  const TriangleMesh box = MakeRoundedBox({ 2.0, 1.0, 0.5 }, 0.0, 8);
  const std::size_t n = 7000;
  const SurfaceSamples samples = Sample(box, n);
  int counts[3][2] = { { 0, 0 }, { 0, 0 }, { 0, 0 } };
  const double half[3] = { 1.0, 0.5, 0.25 };
  for (const Point3& p : samples.Points)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (std::fabs(std::fabs(p[a]) - half[a]) < 1e-12)
      {
        ++counts[a][p[a] > 0 ? 1 : 0];
        break;
      }
    }
  }
  const double faceArea[3] = { 1.0 * 0.5, 2.0 * 0.5, 2.0 * 1.0 };
  for (int a = 0; a < 3; ++a)
  {
    for (int side = 0; side < 2; ++side)
    {
      const double p = faceArea[a] / 7.0;
      const double expected = n * p, sigma = std::sqrt(n * p * (1 - p));
      EXPECT_NEAR(counts[a][side], expected, 3 * sigma) << "face " << a << side;
    }
  }
}

TEST(BlueNoiseSampler, SamplesLieOnTheirTriangleWithItsNormal)
{
  const TriangleMesh torus = MakeTorus(2.0, 0.5, 8);
  const SurfaceSamples samples = Sample(torus, 2000);
  for (std::size_t i = 0; i < samples.Points.size(); ++i)
  {
    const Triangle& t = torus.Triangles[samples.TriangleIds[i]];
    const Point3 &a = torus.Points[t[0]], &b = torus.Points[t[1]], &c = torus.Points[t[2]];
    const Point3 n = Normalized(Cross(b - a, c - a));
    EXPECT_NEAR(Dot(samples.Points[i] - a, n), 0.0, 1e-12);
    EXPECT_NEAR(Dot(samples.Normals[i], n), 1.0, 1e-12);
    // Barycentric coordinates within [0, 1].
    const Point3 p = samples.Points[i] - a;
    const double area2 = Dot(Cross(b - a, c - a), n);
    const double u = Dot(Cross(p, c - a), n) / area2, v = Dot(Cross(b - a, p), n) / area2;
    EXPECT_GE(u, -1e-12);
    EXPECT_GE(v, -1e-12);
    EXPECT_LE(u + v, 1.0 + 1e-12);
  }
}

TEST(BlueNoiseSampler, RelaxationKeepsCountAndEvensSpacing)
{
  const TriangleMesh sphere = MakeSphere(1.0, 24);
  const double area = SurfaceArea(sphere);
  const SurfaceSamples relaxed = Sample(sphere, 3000, 1, 4.0, 3);
  ASSERT_EQ(relaxed.Points.size(), 3000u);
  const Spacing before = MeasureSpacing(Sample(sphere, 3000).Points, area);
  const Spacing after = MeasureSpacing(relaxed.Points, area);
  std::cout << "CV before " << before.Variation << ", after 3 Lloyd steps " << after.Variation
            << "\n";
  EXPECT_LT(after.Variation, before.Variation);
}

TEST(BlueNoiseSurfaceSampler, FilterOutputsSitesWithArrays)
{
  vtkNew<vtkBlueNoiseSurfaceSampler> sampler;
  sampler->SetInputData(test::ToPolyData(MakeCapsule(0.5, 2.0, 8)));
  sampler->SetNumberOfSamples(500);
  sampler->Update();
  vtkPolyData* sites = sampler->GetOutput();
  EXPECT_EQ(sites->GetNumberOfPoints(), 500);
  EXPECT_EQ(sites->GetNumberOfVerts(), 500);
  ASSERT_NE(sites->GetPointData()->GetNormals(), nullptr);
  ASSERT_NE(sites->GetPointData()->GetArray("TriangleId"), nullptr);
}

TEST(BlueNoiseSurfaceSampler, OpenSurfaceIsRefused)
{
  TriangleMesh cube = test::UnitCube();
  cube.Triangles.pop_back();
  vtkNew<vtkBlueNoiseSurfaceSampler> sampler;
  vtkNew<test::ErrorCatcher> errors;
  sampler->AddObserver(vtkCommand::ErrorEvent, errors);
  sampler->SetInputData(test::ToPolyData(cube));
  sampler->Update();
  EXPECT_EQ(sampler->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(errors->Count, 1);
  EXPECT_NE(errors->Last.find("not closed: 3 boundary edges"), std::string::npos) << errors->Last;
}
