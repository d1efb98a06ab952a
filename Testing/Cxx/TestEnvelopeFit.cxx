// SPDX-License-Identifier: GPL-3.0-or-later
// The final fit of a medial mesh to its surface (Fitting/EnvelopeFit.h) and
// the points it fits (Fitting/FitPoints.h).
#include "TestHelpers.h"

#include "Envelope/EnvelopeDistance.h"
#include "Envelope/ReconstructionError.h"
#include "Fitting/EnvelopeFit.h"
#include "Fitting/FitPoints.h"
#include "Mesh/MedialMeshQuality.h"
#include "Support/Parallel.h"
#include "Surface/AnalyticShapes.h"
#include "Surface/FilletedShapes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace medialaxis;

namespace
{
/// The capsule's exact medial axis (its segment, radius 0.3 throughout) as a
/// chain of `n` spheres, with every sphere moved and resized by up to about
/// 15% of the radius.
MedialMesh PerturbedCapsuleAxis(int n, double radius, double axisLength)
{
  MedialMesh mesh;
  for (int i = 0; i < n; ++i)
  {
    const double t = static_cast<double>(i) / (n - 1);
    const double wobble = std::sin(7.0 * i + 1.0);
    mesh.Centers.push_back(
      { 0.04 * wobble, -0.03 * std::cos(5.0 * i), axisLength * (t - 0.5) + 0.02 * wobble });
    mesh.Radii.push_back(radius * (1.0 + 0.15 * std::sin(3.0 * i + 2.0)));
    if (i > 0)
    {
      mesh.Edges.push_back({ i - 1, i });
    }
  }
  return mesh;
}

double LargestDistance(const MedialMesh& mesh, const std::vector<Point3>& points)
{
  const MedialEnvelope envelope(mesh);
  double largest = 0.0;
  for (const Point3& p : points)
  {
    largest = std::max(largest, std::abs(envelope.SignedDistance(p).Distance));
  }
  return largest;
}
}

// One ball moved off the centre of a sphere and shrunk: the fit puts it back.
TEST(EnvelopeFit, RecoversAPerturbedBall)
{
  const TriangleMesh sphere = MakeSphere(1.0, 12);
  MedialMesh mesh;
  mesh.Centers = { { 0.12, -0.08, 0.05 } };
  mesh.Radii = { 0.8 };
  EnvelopeFitOptions options;
  options.Iterations = 12;
  const EnvelopeFitResult result = FitMedialEnvelope(mesh, { sphere.Points, {}, {} }, {}, options);
  EXPECT_GT(result.InitialMaximum, 0.25);
  EXPECT_LT(Norm(mesh.Centers[0]), 1e-4);
  EXPECT_NEAR(mesh.Radii[0], 1.0, 1e-4);
  EXPECT_LT(result.FinalMaximum, 1e-4);
  EXPECT_GT(result.AcceptedRounds, 0);
}

// A perturbed chain of spheres along a capsule's axis (cones between them)
// is pulled back onto the exact medial axis: the largest distance from the
// capsule's vertices to the envelope falls from about a tenth of the radius
// to nearly zero, and the two-sided Hausdorff distance with it.
TEST(EnvelopeFit, PerturbedCapsuleAxisFitsNearlyExactly)
{
  const double radius = 0.3, axisLength = 1.0;
  const TriangleMesh capsule = MakeCapsule(radius, axisLength, 16);
  MedialMesh mesh = PerturbedCapsuleAxis(6, radius, axisLength);
  const double before = LargestDistance(mesh, capsule.Points);
  ReconstructionErrorOptions errorOptions;
  errorOptions.NumberOfSamples = 20000;
  errorOptions.NumberOfEnvelopeSamples = 20000;
  const ReconstructionErrorResult errorBefore =
    ComputeReconstructionError(capsule, MedialEnvelope(mesh), errorOptions);

  EnvelopeFitOptions options;
  options.Iterations = 20;
  const EnvelopeFitResult result = FitMedialEnvelope(mesh, { capsule.Points, {}, {} }, {}, options);
  const double after = LargestDistance(mesh, capsule.Points);
  EXPECT_GT(before, 0.03);
  EXPECT_LT(after, 0.02 * before) << "before " << before << ", after " << after;
  EXPECT_NEAR(result.FinalMaximum, after, 1e-12);
  for (std::size_t v = 0; v < mesh.NumberOfVertices(); ++v)
  {
    EXPECT_NEAR(mesh.Radii[v], radius, 0.01 * radius) << "sphere " << v;
    EXPECT_LT(std::hypot(mesh.Centers[v][0], mesh.Centers[v][1]), 0.01 * radius) << v;
  }
  const ReconstructionErrorResult errorAfter =
    ComputeReconstructionError(capsule, MedialEnvelope(mesh), errorOptions);
  const double hausdorffBefore =
    std::max(errorBefore.SurfaceToEnvelope.Hausdorff, errorBefore.EnvelopeToSurface.Hausdorff);
  const double hausdorffAfter =
    std::max(errorAfter.SurfaceToEnvelope.Hausdorff, errorAfter.EnvelopeToSurface.Hausdorff);
  EXPECT_LT(hausdorffAfter, 0.05 * hausdorffBefore)
    << "before " << hausdorffBefore << ", after " << hausdorffAfter;
}

// A spike edge: a ball nearly inside its neighbour on a capsule's axis,
// sticking out of it by 1% of their distance (stability ratio 0.01, below
// the paper's 0.025). With the spike term the fit moves the pair until the
// edge is no spike, without the envelope leaving the capsule; without it
// the needle stays.
TEST(EnvelopeFit, SpikeRepairPullsASpikeEdgeApart)
{
  const double radius = 0.3, axisLength = 1.0;
  const TriangleMesh capsule = MakeCapsule(radius, axisLength, 16);
  for (double weight : { 0.0, 10.0 })
  {
    MedialMesh mesh;
    for (int i = 0; i < 6; ++i)
    {
      mesh.Centers.push_back({ 0.0, 0.0, axisLength * (i / 5.0 - 0.5) });
      mesh.Radii.push_back(radius);
      if (i > 0)
      {
        mesh.Edges.push_back({ i - 1, i });
      }
    }
    const double d = 0.05, ratio = 0.01;
    mesh.Centers.push_back(mesh.Centers[2] + Point3{ d, 0.0, 0.0 });
    mesh.Radii.push_back(radius - (1.0 - ratio) * d); // inside sphere 2 but for 1% of d
    mesh.Edges.push_back({ 2, 6 });
    const auto spike = [&]
    { return StabilityRatio(mesh.Centers[2], mesh.Radii[2], mesh.Centers[6], mesh.Radii[6]); };
    ASSERT_NEAR(spike(), ratio, 1e-12);
    EnvelopeFitOptions options;
    options.Iterations = 8;
    options.SpikeRepairWeight = weight;
    FitMedialEnvelope(mesh, { capsule.Points, {}, {} }, {}, options);
    if (weight > 0.0)
    {
      EXPECT_GE(spike(), options.SpikeThreshold);
      EXPECT_LT(LargestDistance(mesh, capsule.Points), 0.01 * radius);
    }
    else
    {
      EXPECT_LT(spike(), options.SpikeThreshold);
    }
  }
}

// Fixed spheres (here two on the exact axis) do not move, bit for bit;
// radius-only spheres keep their centre; the others still fit.
TEST(EnvelopeFit, FixedSpheresStay)
{
  const TriangleMesh capsule = MakeCapsule(0.3, 1.0, 12);
  MedialMesh mesh = PerturbedCapsuleAxis(6, 0.3, 1.0);
  std::vector<SphereFreedom> freedom(mesh.NumberOfVertices(), SphereFreedom::Free);
  for (int v : { 0, 3 })
  {
    freedom[v] = SphereFreedom::Fixed;
    mesh.Centers[v] = { 0.0, 0.0, v == 0 ? -0.5 : 0.1 };
    mesh.Radii[v] = 0.3;
  }
  freedom[5] = SphereFreedom::RadiusOnly;
  mesh.Centers[5] = { 0.0, 0.0, 0.5 };
  const MedialMesh before = mesh;
  EnvelopeFitOptions options;
  options.Iterations = 10;
  const EnvelopeFitResult result =
    FitMedialEnvelope(mesh, { capsule.Points, {}, {} }, freedom, options);
  EXPECT_LT(result.FinalRms, 0.1 * result.InitialRms);
  for (std::size_t v = 0; v < mesh.NumberOfVertices(); ++v)
  {
    switch (freedom[v])
    {
      case SphereFreedom::Fixed:
        EXPECT_EQ(mesh.Centers[v], before.Centers[v]) << v;
        EXPECT_EQ(mesh.Radii[v], before.Radii[v]) << v;
        break;
      case SphereFreedom::RadiusOnly:
        EXPECT_EQ(mesh.Centers[v], before.Centers[v]) << v;
        EXPECT_NEAR(mesh.Radii[v], 0.3, 0.003) << v << " (from " << before.Radii[v] << ")";
        break;
      case SphereFreedom::Free:
        EXPECT_NE(mesh.Centers[v], before.Centers[v]) << v;
        break;
    }
  }
}

// Returning false from Progress stops before the first round: the mesh is
// as given.
TEST(EnvelopeFit, AbortLeavesTheMesh)
{
  const TriangleMesh capsule = MakeCapsule(0.3, 1.0, 12);
  MedialMesh mesh = PerturbedCapsuleAxis(6, 0.3, 1.0);
  const MedialMesh before = mesh;
  EnvelopeFitOptions options;
  options.Progress = [](double) { return false; };
  const EnvelopeFitResult result = FitMedialEnvelope(mesh, { capsule.Points, {}, {} }, {}, options);
  EXPECT_TRUE(result.Aborted);
  EXPECT_EQ(result.AcceptedRounds, 0);
  EXPECT_EQ(mesh.Centers, before.Centers);
  EXPECT_EQ(mesh.Radii, before.Radii);
}

// The corners where three cells meet: about two per site on a closed
// surface of genus 0 (a triangulation with N vertices has 2N - 4 triangles),
// each nearly equidistant from its three nearest sites, and the weights of
// all points add up to the surface area.
TEST(FitPoints, CornersWhereThreeCellsMeet)
{
  const TriangleMesh box = MakeRoundedBox({ 2.0, 1.5, 1.0 }, 0.3, 8);
  const test::SimplifiedRun run = test::InitialMedialAxis(box, 3000);
  const FitTarget points = FitPoints(run.Rvd, run.Sites.Points);
  const std::size_t sites = run.Sites.Points.size();
  const std::size_t corners = points.Points.size() - sites;
  EXPECT_GT(corners, 19 * sites / 10);
  EXPECT_LE(corners, 2 * sites);
  double weight = 0.0, area = 0.0;
  for (double w : points.Weights)
  {
    weight += w;
  }
  for (double a : run.Rvd.CellArea)
  {
    area += a;
  }
  EXPECT_NEAR(weight, area, 0.02 * area);

  // Every point is a site or lies (nearly) as close to its second and third
  // nearest sites as to its nearest.
  const KdTree tree(run.Sites.Points);
  std::vector<std::uint32_t> ids;
  std::vector<double> d2;
  std::size_t equidistant = 0;
  for (const Point3& p : points.Points)
  {
    tree.Nearest(p, 3, ids, d2);
    if (d2[0] == 0.0)
    {
      continue;
    }
    equidistant += std::sqrt(d2[2]) - std::sqrt(d2[0]) < 1e-6 * std::sqrt(d2[0]) ? 1 : 0;
  }
  EXPECT_EQ(equidistant, corners);
  // Sites only: each stands for its whole cell.
  FitPointsOptions sitesAndSurface;
  sitesAndSurface.Corners = false;
  sitesAndSurface.DenseSurface = true;
  const FitTarget sitesOnly = FitPoints(run.Rvd, run.Sites.Points, sitesAndSurface);
  ASSERT_EQ(sitesOnly.Points.size(), sites);
  for (std::size_t s = 0; s < sites; ++s)
  {
    EXPECT_NEAR(sitesOnly.Weights[s], run.Rvd.CellArea[s], 1e-9 * area) << s;
  }
  // The surface: the sites and the distinct polygon vertices (shared by two
  // or three polygons inside a triangle, by none across its edges).
  EXPECT_TRUE(points.Surface.empty());
  EXPECT_GT(sitesOnly.Surface.size(), sites + run.Rvd.Vertices.size() / 3);
  EXPECT_LT(sitesOnly.Surface.size(), sites + run.Rvd.Vertices.size());
}

// Inside the simplifier: the fit lowers the two-sided Hausdorff distance of
// an organic mesh, keeps the mesh valid (no new fold or degenerate triangle,
// the same Euler characteristic) and gives the same result at any thread
// count.
TEST(EnvelopeFit, LowersTheErrorOfASimplifiedMesh)
{
  TriangleMesh surface;
  if (!test::ReadSharedMesh("bunny.obj", surface))
  {
    GTEST_SKIP() << "shared meshes not available";
  }
  const test::SimplifiedRun run = test::InitialMedialAxis(surface, 5000);
  auto simplify = [&](bool fit, int threads)
  {
    AtlasSimplifierOptions options;
    options.TargetNumberOfVertices = 500;
    options.PreserveSharpFeatures = false;
    options.FinalFit = fit;
    return RunWithThreads(
      threads, [&] { return SimplifyMedialAxis(run.Initial, run.Rvd, run.Sites.Points, options); });
  };
  const AtlasSimplifierResult plain = simplify(false, 2);
  const AtlasSimplifierResult fitted = simplify(true, 2);
  const AtlasSimplifierResult oneThread = simplify(true, 1);
  const MedialMesh &a = plain.Medial.Mesh, &b = fitted.Medial.Mesh;
  ASSERT_EQ(a.Faces, b.Faces);
  EXPECT_TRUE(ValidateMedialMesh(b).IsValid());
  EXPECT_EQ(EulerCharacteristic(a), EulerCharacteristic(b));
  const MedialMeshQuality qa = MeasureQuality(a), qb = MeasureQuality(b);
  EXPECT_LE(qb.FoldedEdges, qa.FoldedEdges);
  EXPECT_LE(qb.DegenerateTriangles, qa.DegenerateTriangles);
  EXPECT_GT(fitted.Fit.AcceptedRounds, 0);
  EXPECT_LT(fitted.Fit.FinalRms, 0.8 * fitted.Fit.InitialRms);

  ReconstructionErrorOptions errorOptions;
  errorOptions.NumberOfSamples = 50000;
  const ReconstructionErrorResult ea =
    ComputeReconstructionError(surface, MedialEnvelope(a), errorOptions);
  const ReconstructionErrorResult eb =
    ComputeReconstructionError(surface, MedialEnvelope(b), errorOptions);
  const double ha = std::max(ea.SurfaceToEnvelope.Hausdorff, ea.EnvelopeToSurface.Hausdorff);
  const double hb = std::max(eb.SurfaceToEnvelope.Hausdorff, eb.EnvelopeToSurface.Hausdorff);
  EXPECT_LT(hb, 0.85 * ha) << "without the fit " << 100 * ha / ea.Diagonal << "%, with it "
                           << 100 * hb / eb.Diagonal << "%";
  EXPECT_LT(eb.SurfaceToEnvelope.RMS, 0.8 * ea.SurfaceToEnvelope.RMS);

  const MedialMesh& c = oneThread.Medial.Mesh;
  ASSERT_EQ(c.Centers.size(), b.Centers.size());
  EXPECT_EQ(0, std::memcmp(c.Centers.data(), b.Centers.data(), b.Centers.size() * sizeof(Point3)));
  EXPECT_EQ(c.Radii, b.Radii);
}

// CAD mode: spheres on sharp edges and on the boundary of the sheets (where
// fillet centre lines run) stay where the collapses left them; with
// FitSheetBoundaryRadii the boundary ones keep their centres only. The
// others move.
TEST(EnvelopeFit, CadModeKeepsSharpEdgesAndSheetBoundaries)
{
  // A prism with two rounded edges (a fillet each) and ten sharp ones.
  const LabelledTriangleMesh part =
    MakeFilletedPrism({ 2.0, 1.5, 1.0 }, { 0.25, 0, 0.2, 0 }, { 0.25, 0, 0.2, 0 }, 12);
  const test::SimplifiedRun run = test::InitialMedialAxis(part.Mesh, 5000);
  auto simplify = [&](bool fit, bool boundaryRadii)
  {
    AtlasSimplifierOptions options;
    options.TargetNumberOfVertices = 400;
    options.PreserveSharpFeatures = true;
    options.FinalFit = fit;
    options.FitSheetBoundaryRadii = boundaryRadii;
    return SimplifyMedialAxis(run.Initial, run.Rvd, run.Sites.Points, options);
  };
  const AtlasSimplifierResult plain = simplify(false, false), fitted = simplify(true, false),
                              radii = simplify(true, true);
  const MedialMesh &a = plain.Medial.Mesh, &b = fitted.Medial.Mesh, &c = radii.Medial.Mesh;
  ASSERT_EQ(a.Faces, b.Faces);
  ASSERT_EQ(a.Faces, c.Faces);
  std::vector<std::uint8_t> boundary(a.NumberOfVertices(), 0);
  for (const auto& e : SheetBoundaryEdges(a))
  {
    boundary[e[0]] = boundary[e[1]] = 1;
  }
  std::size_t features = 0, boundaries = 0, resized = 0, moved = 0;
  for (std::size_t v = 0; v < a.NumberOfVertices(); ++v)
  {
    if (plain.Medial.FeatureVertex[v])
    {
      ++features;
      EXPECT_EQ(a.Centers[v], b.Centers[v]) << v;
      EXPECT_EQ(a.Radii[v], b.Radii[v]) << v;
      EXPECT_EQ(a.Centers[v], c.Centers[v]) << v;
      EXPECT_EQ(a.Radii[v], c.Radii[v]) << v;
    }
    else if (boundary[v])
    {
      ++boundaries;
      EXPECT_EQ(a.Centers[v], b.Centers[v]) << v;
      EXPECT_EQ(a.Radii[v], b.Radii[v]) << v;
      EXPECT_EQ(a.Centers[v], c.Centers[v]) << v;
      resized += a.Radii[v] != c.Radii[v] ? 1 : 0;
    }
    else
    {
      moved += a.Centers[v] != b.Centers[v] ? 1 : 0;
    }
  }
  EXPECT_GT(features, 0u);
  EXPECT_GT(boundaries, 0u);
  EXPECT_GT(resized, 0u);
  EXPECT_GT(moved, 0u);
  EXPECT_GT(fitted.Fit.AcceptedRounds, 0);
}
