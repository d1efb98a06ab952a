// SPDX-License-Identifier: GPL-3.0-or-later
// Blue-noise sampling: exact count, determinism, spacing quality against
// white noise, area-proportional density, samples on their triangles.
#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Mesh/TriangleLocator.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Sampling/LocalThickness.h"
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
  TriangleMesh bunny;
  if (!test::ReadSharedMesh("bunny.obj", bunny))
  {
    GTEST_SKIP() << "shared meshes not present";
  }
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

namespace
{
SurfaceSamples SampleAdaptively(const TriangleMesh& mesh, std::size_t n, std::uint64_t seed = 1)
{
  SamplingOptions options;
  options.NumberOfSamples = n;
  options.Seed = seed;
  options.Adaptive = true;
  return SampleSurface(mesh, options);
}

// The dumbbell's neck (radius 0.02, visible for |z| < ~0.1) is thinner than
// the uniform spacing of 1,500 samples (~0.028).
const TriangleMesh& Dumbbell()
{
  static const TriangleMesh mesh = MakeDumbbell(1.0, 0.2, 0.02, 12);
  return mesh;
}

bool OnNeck(const Point3& p)
{
  return std::fabs(p[2]) < 0.08 && std::hypot(p[0], p[1]) < 0.021;
}
}

TEST(LocalThickness, RaysFindTheFarSide)
{
  // A 2 x 1 x 0.1 plate: 0.1 behind its large faces (away from the rim),
  // and a ball of radius 1: the median ray, 25 degrees off the normal,
  // crosses a chord of 2 cos(25 deg), 1.64 deep along the normal.
  const TriangleMesh plate = MakeRoundedBox({ 2.0, 1.0, 0.1 }, 0.0, 16);
  const TriangleMesh ball = MakeSphere(1.0, 16);
  for (const TriangleMesh* mesh : { &plate, &ball })
  {
    const TriangleLocator locator(*mesh);
    const SurfaceSamples s = Sample(*mesh, 400);
    const std::vector<double> t = EstimateLocalThickness(*mesh, locator, s.Points, s.TriangleIds);
    ASSERT_EQ(t.size(), s.Points.size());
    for (std::size_t i = 0; i < t.size(); ++i)
    {
      const Point3& p = s.Points[i];
      if (mesh == &ball)
      {
        EXPECT_NEAR(t[i], 2.0 * std::pow(std::cos(25.0 * M_PI / 180.0), 2), 0.04); // facets
      }
      else if (std::fabs(std::fabs(p[2]) - 0.05) < 1e-12 && std::fabs(p[0]) < 0.8 &&
        std::fabs(p[1]) < 0.3)
      {
        EXPECT_NEAR(t[i], 0.1, 1e-9) << "at " << p[0] << " " << p[1];
      }
    }
  }
  // Rays stop at MaximumThickness, which is then the answer.
  const TriangleLocator locator(ball);
  ThicknessOptions capped;
  capped.MaximumThickness = 0.5;
  const std::vector<double> t =
    EstimateLocalThickness(ball, locator, { ball.Points[ball.Triangles[0][0]] }, { 0 }, capped);
  EXPECT_EQ(t[0], 0.5);
}

TEST(BlueNoiseSampler, AdaptiveDensityFollowsThickness)
{
  const std::size_t n = 1000; // uniform spacing 0.034, above the neck's diameter
  const SurfaceSamples uniform = Sample(Dumbbell(), n);
  const SurfaceSamples adaptive = SampleAdaptively(Dumbbell(), n);
  ASSERT_EQ(adaptive.Points.size(), n);
  ASSERT_EQ(adaptive.LocalThickness.size(), n);
  auto neckCount = [](const SurfaceSamples& s)
  { return std::count_if(s.Points.begin(), s.Points.end(), OnNeck); };
  std::cout << "samples on the neck: uniform " << neckCount(uniform) << ", adaptive "
            << neckCount(adaptive) << "\n";
  // Spacing half the neck's diameter instead of 0.034: (0.034 / 0.02)^2 = 2.9
  // times denser.
  EXPECT_GE(neckCount(adaptive), 2.4 * neckCount(uniform));
  for (std::size_t i = 0; i < n; ++i)
  {
    if (OnNeck(adaptive.Points[i]))
    {
      EXPECT_NEAR(adaptive.LocalThickness[i], 0.04, 0.004);
      EXPECT_LE(adaptive.Spacing[i], 0.5 * adaptive.LocalThickness[i]);
    }
  }
}

TEST(BlueNoiseSampler, AdaptiveIsBlueNoiseAtTheLocalSpacing)
{
  // Nearest-neighbour distances against the spacing the field asked for.
  const SurfaceSamples s = SampleAdaptively(Dumbbell(), 1500);
  const KdTree tree(s.Points);
  std::vector<std::uint32_t> ids;
  std::vector<double> d2;
  double worst = HUGE_VAL, worstOwn = HUGE_VAL;
  for (std::size_t i = 0; i < s.Points.size(); ++i)
  {
    tree.Nearest(s.Points[i], 2, ids, d2);
    worst = std::min(worst, std::sqrt(d2[1]) / std::min(s.Spacing[i], s.Spacing[ids[1]]));
    worstOwn = std::min(worstOwn, std::sqrt(d2[1]) / s.Spacing[i]);
  }
  std::cout << "adaptive: min nearest / local ideal " << worst << ", own " << worstOwn << "\n";
  EXPECT_GE(worst, 0.6);
}

TEST(BlueNoiseSampler, AdaptiveIsDeterministicAndUniformWithoutThinParts)
{
  const SurfaceSamples a = SampleAdaptively(Dumbbell(), 1500, 7);
  EXPECT_TRUE(Identical(a, SampleAdaptively(Dumbbell(), 1500, 7)));
  const SurfaceSamples one =
    RunWithThreads(1, [&] { return SampleAdaptively(Dumbbell(), 1500, 7); });
  const SurfaceSamples two =
    RunWithThreads(2, [&] { return SampleAdaptively(Dumbbell(), 1500, 7); });
  EXPECT_TRUE(Identical(a, one));
  EXPECT_TRUE(Identical(a, two));
  EXPECT_EQ(one.Spacing, two.Spacing);
  // Nothing on a ball is thin: the samples are the uniform ones.
  const TriangleMesh ball = MakeSphere(1.0, 16);
  EXPECT_TRUE(Identical(SampleAdaptively(ball, 2000), Sample(ball, 2000)));
}

TEST(BlueNoiseSampler, ThinPartsFinerThanTheFinestRatioGrowTheCount)
{
  // With the finest spacing held at half the thick parts' (about 0.027 at
  // 400 samples), the neck's wanted spacing (0.02, half its diameter) is out
  // of reach within the budget; ExtraSampleFraction pays for it beyond.
  auto sample = [](double extra)
  {
    SamplingOptions options;
    options.NumberOfSamples = 400;
    options.Seed = 3;
    options.Adaptive = true;
    options.Sizing.FinestSpacingRatio = 0.5;
    options.Sizing.ExtraSampleFraction = extra;
    return SampleSurface(Dumbbell(), options);
  };
  const SurfaceSamples capped = sample(0.0), grown = sample(0.5);
  EXPECT_EQ(capped.Points.size(), 400u);
  EXPECT_EQ(capped.AddedSamples, 0u);
  EXPECT_GT(grown.AddedSamples, 0u);
  EXPECT_LE(grown.AddedSamples, 200u);
  EXPECT_EQ(grown.Points.size(), 400u + grown.AddedSamples);
  auto neckCount = [](const SurfaceSamples& s)
  { return std::count_if(s.Points.begin(), s.Points.end(), OnNeck); };
  std::cout << "samples on the neck: within the budget " << neckCount(capped) << ", with "
            << grown.AddedSamples << " more " << neckCount(grown) << "\n";
  // Spacing 0.02 instead of about 0.027: (0.027 / 0.02)^2 = 1.8 times denser.
  EXPECT_GE(neckCount(grown), 1.5 * neckCount(capped));
  for (std::size_t i = 0; i < grown.Points.size(); ++i)
  {
    if (OnNeck(grown.Points[i]))
    {
      EXPECT_LE(grown.Spacing[i], 0.5 * grown.LocalThickness[i] + 1e-12);
    }
  }
  EXPECT_TRUE(Identical(grown, RunWithThreads(1, [&] { return sample(0.5); })));
  // Each round of DenserOnThinParts halves the thin parts' spacing and
  // allows as many samples again as the round's number.
  SizingOptions sizing;
  EXPECT_FALSE(DenserOnThinParts(sizing, 0));
  EXPECT_TRUE(DenserOnThinParts(sizing, 1));
  EXPECT_EQ(sizing.SpacingPerThickness, 0.25);
  EXPECT_EQ(sizing.ExtraSampleFraction, 1.0);
  EXPECT_TRUE(DenserOnThinParts(sizing, 3));
  EXPECT_FALSE(DenserOnThinParts(sizing, 4));
}

TEST(BlueNoiseSurfaceSampler, AdaptiveOutputsThicknessAndSpacing)
{
  vtkNew<vtkBlueNoiseSurfaceSampler> sampler;
  sampler->SetInputData(test::ToPolyData(Dumbbell()));
  sampler->SetNumberOfSamples(800);
  sampler->AdaptiveOn();
  sampler->Update();
  vtkPolyData* sites = sampler->GetOutput();
  EXPECT_EQ(sites->GetNumberOfPoints(), 800);
  vtkDataArray* thickness = sites->GetPointData()->GetArray("LocalThickness");
  vtkDataArray* spacing = sites->GetPointData()->GetArray("Spacing");
  ASSERT_NE(thickness, nullptr);
  ASSERT_NE(spacing, nullptr);
  double range[2];
  thickness->GetRange(range);
  EXPECT_NEAR(range[0], 0.04, 0.01); // the neck
  EXPECT_GT(range[1], 0.2);          // the balls, thick enough to stop the rays
}
