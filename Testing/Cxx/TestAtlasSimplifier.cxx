// SPDX-License-Identifier: GPL-3.0-or-later
// Atlas-guided simplification: ground truth on a torus, validity,
// determinism and Atlas bookkeeping, on a sphere, a capsule and a torus.
#include "Envelope/EnvelopeDistance.h"
#include "Geometry/Vec3.h"
#include "Mesh/MedialMeshQuality.h"
#include "Sampling/BlueNoiseSampler.h"
#include "Simplification/AtlasSimplifier.h"
#include "Simplification/CollapseQueue.h"
#include "Simplification/SphereQuadric.h"
#include "Support/Parallel.h"
#include "Support/Random.h"
#include "Surface/AnalyticShapes.h"
#include "Voronoi/RestrictedVoronoi.h"
#include "Voronoi/VoronoiMedialAxis.h"
#include "vtkAnalyticShapeSource.h"
#include "vtkAtlasMedialAxisSimplifier.h"
#include "vtkBlueNoiseSurfaceSampler.h"
#include "vtkExtractMedialAtlas.h"
#include "vtkMedialMeshConversion.h"
#include "vtkRestrictedVoronoiDiagram.h"
#include "vtkSurfaceFileReader.h"
#include "vtkVoronoiMedialAxis.h"

#include "TestHelpers.h"
#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkImplicitPolyDataDistance.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <tuple>
#include <utility>

using namespace medialaxis;
using medialaxis::test::InitialMedialAxis;
using medialaxis::test::SimplifiedRun;
using medialaxis::test::Simplify;

namespace
{
// Twice the area of every triangle must be clearly positive.
std::size_t DegenerateTriangles(const MedialMesh& m)
{
  std::size_t count = 0;
  for (const auto& t : m.Faces)
  {
    const Point3 n = Cross(m.Centers[t[1]] - m.Centers[t[0]], m.Centers[t[2]] - m.Centers[t[0]]);
    count += Norm(n) > 0.0 ? 0 : 1;
  }
  return count;
}
}

TEST(AtlasSimplifier, UnitSphereSimplifiesToItsCentre)
{
  const SimplifiedRun run = Simplify(MakeSphere(1.0, 32), 10000, 1, false);
  const MedialMesh& m = run.Result.Medial.Mesh;
  ASSERT_EQ(m.Centers.size(), 1u);
  std::cout << "centre " << Norm(m.Centers[0]) << " from the origin, radius " << m.Radii[0] << ", "
            << run.Result.RelaxedCollapses << " collapses past the stalled link condition\n";
  EXPECT_LT(Norm(m.Centers[0]), 0.005);
  EXPECT_NEAR(m.Radii[0], 1.0, 0.005);
}

TEST(AtlasSimplifier, CapsuleSimplifiesToItsAxis)
{
  const double radius = 0.5, axis = 2.0;
  const SimplifiedRun run = Simplify(MakeCapsule(radius, axis, 24), 10000, 20, false);
  const MedialMesh& m = run.Result.Medial.Mesh;
  ASSERT_EQ(m.Centers.size(), 20u);
  for (std::size_t v = 0; v < m.Centers.size(); ++v)
  {
    const Point3& c = m.Centers[v];
    const double z = std::clamp(c[2], -0.5 * axis, 0.5 * axis);
    EXPECT_LT(Norm(c - Point3{ 0.0, 0.0, z }), 0.01 * axis) << "vertex " << v;
    EXPECT_NEAR(m.Radii[v], radius, 0.01 * radius) << "vertex " << v;
  }
  EXPECT_TRUE(ValidateMedialMesh(m).IsValid());
}

TEST(AtlasSimplifier, TorusSimplifiesToItsCentreCircle)
{
  const double major = 2.0, minor = 0.5;
  const SimplifiedRun run = Simplify(MakeTorus(major, minor, 24), 10000, 50, false);
  const MedialMesh& m = run.Result.Medial.Mesh;
  ASSERT_EQ(m.Centers.size(), 50u);
  const double diagonal = std::sqrt(2.0) * 2.0 * major; // of the centre circle's bounding box
  for (std::size_t v = 0; v < m.Centers.size(); ++v)
  {
    const Point3& c = m.Centers[v];
    const double ring = std::hypot(std::hypot(c[0], c[1]) - major, c[2]);
    EXPECT_LT(ring, 0.01 * diagonal) << "vertex " << v;
    EXPECT_NEAR(m.Radii[v], minor, 0.01 * minor) << "vertex " << v;
  }
  EXPECT_EQ(EulerCharacteristic(m), 0);
  EXPECT_TRUE(ValidateMedialMesh(m).IsValid()) << ValidateMedialMesh(m).Message;
}

namespace
{
// Distance from p to the nearest of the 12 edges of the cube [-h, h]^3.
double DistanceToCubeEdges(const Point3& p, double h)
{
  double best = HUGE_VAL;
  for (int axis = 0; axis < 3; ++axis)
  {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (double su : { -h, h })
    {
      for (double sv : { -h, h })
      {
        Point3 q;
        q[axis] = std::clamp(p[axis], -h, h);
        q[u] = su;
        q[v] = sv;
        best = std::min(best, Norm(p - q));
      }
    }
  }
  return best;
}

}

TEST(AtlasSimplifier, BoxBoundaryReachesTheSharpEdges)
{
  // CAD mode: the medial sheets of a box end on its edges with radius 0.
  const double diagonal = 2.0 * std::sqrt(3.0);
  for (bool cad : { true, false })
  {
    const SimplifiedRun run = Simplify(MakeRoundedBox({ 2, 2, 2 }, 0.0, 32), 20000, 2000, cad);
    const MedialMesh& m = run.Result.Medial.Mesh;
    double worstRadius = 0.0, worstDistance = 0.0, meanDistance = 0.0;
    std::set<Index> boundary;
    for (const auto& e : SheetBoundaryEdges(m))
    {
      boundary.insert(e[0]);
      boundary.insert(e[1]);
    }
    ASSERT_FALSE(boundary.empty());
    for (Index v : boundary)
    {
      const double d = DistanceToCubeEdges(m.Centers[v], 1.0);
      worstRadius = std::max(worstRadius, m.Radii[v]);
      worstDistance = std::max(worstDistance, d);
      meanDistance += d / static_cast<double>(boundary.size());
    }
    std::cout << (cad ? "CAD mode" : "organic mode") << ": " << boundary.size()
              << " boundary vertices, largest radius " << worstRadius << ", farthest from an edge "
              << worstDistance << ", mean " << meanDistance << "\n";
    if (cad)
    {
      EXPECT_LT(worstRadius, 0.005 * diagonal);
      EXPECT_LT(worstDistance, 0.005 * diagonal);
    }
    else
    {
      // Without feature preservation the boundary draws back from the edges
      // (paper Fig. 16c).
      EXPECT_GT(meanDistance, 0.005 * diagonal);
    }
  }
}

// Large fillets (radius 0.25 on a side-2 box, about 12 site spacings at 50K
// sites) leave a fringe of fins along the centre lines under the strict link
// condition; Euler-neutral collapses remove it without changing the topology.
TEST(AtlasSimplifier, FringeCollapsesCleanLargeFillets)
{
  const TriangleMesh box = MakeRoundedBox({ 2, 2, 2 }, 0.25, 16);
  std::size_t boundary[2];
  for (int fringe = 0; fringe < 2; ++fringe)
  {
    const SimplifiedRun run = Simplify(box, 50000, 2000, true, true, true,
      fringe == 1 ? FringeCollapseMode::On : FringeCollapseMode::Off);
    const MedialMesh& m = run.Result.Medial.Mesh;
    std::map<std::array<Index, 2>, int> uses;
    for (const auto& t : m.Faces)
    {
      for (int k = 0; k < 3; ++k)
      {
        ++uses[{ std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]) }];
      }
    }
    boundary[fringe] =
      std::count_if(uses.begin(), uses.end(), [](const auto& u) { return u.second == 1; });
    std::cout << (fringe ? "fringe collapses: " : "strict link condition: ") << boundary[fringe]
              << " boundary edges, Euler characteristic " << EulerCharacteristic(m) << "\n";
    EXPECT_TRUE(ValidateMedialMesh(m).IsValid());
    if (fringe)
    {
      // Strict, the simplifier stalls on the fringe and finishes without the
      // link condition (measured: Euler characteristic 163).
      EXPECT_EQ(EulerCharacteristic(m), 1);
      EXPECT_EQ(run.Result.RelaxedCollapses, 0u);
    }
  }
  EXPECT_LT(boundary[1], boundary[0] / 3);
}

TEST(AtlasSimplifier, RoundedBoxBoundaryFollowsTheFilletCentreLines)
{
  // Side 2, fillet radius 0.2: the fillet centre lines are the edges of the
  // cube [-0.8, 0.8]^3, where the medial radius is 0.2.
  const double rho = 0.2, diagonal = 2.0 * std::sqrt(3.0);
  const SimplifiedRun run = Simplify(MakeRoundedBox({ 2, 2, 2 }, rho, 16), 20000, 2000, true);
  const MedialMesh& m = run.Result.Medial.Mesh;
  std::size_t checked = 0;
  double worst = 0.0;
  for (const auto& e : SheetBoundaryEdges(m))
  {
    if (std::fabs(m.Radii[e[0]] - rho) > 0.1 * rho || std::fabs(m.Radii[e[1]] - rho) > 0.1 * rho)
    {
      continue;
    }
    for (Index v : e)
    {
      worst = std::max(worst, DistanceToCubeEdges(m.Centers[v], 1.0 - rho));
      ++checked;
    }
  }
  std::cout << checked << " endpoints of fillet-radius boundary edges, farthest " << worst
            << " from a fillet centre line\n";
  EXPECT_GT(checked, 100u);
  EXPECT_LT(worst, 0.01 * diagonal);
}

TEST(AtlasSimplifier, AblationsOnAnLBlock)
{
  // Paper Fig. 16: without concave filtering, spurious structure stays at
  // the concave edge; without the distance-to-site term for cells on it,
  // spheres there fit the surface worse (they bulge out of it). Both are
  // properties of the collapses' placement, measured before the final fit.
  // (The fit then refits these spheres and lowers the bulge of both: with
  // it, measured 2.0e-4 with the site term and 1.4e-4 without, against
  // 3.8e-4 and 9.5e-4 before it.)
  const TriangleMesh block = MakeLBlock({ 2, 2, 1 }, 8);
  vtkNew<vtkImplicitPolyDataDistance> distance;
  distance->SetInput(test::ToPolyData(block));
  struct Measure
  {
    std::size_t NearEdgeTriangles = 0;
    double MeanBulge = 0.0; // radius minus distance to the surface
  };
  auto measure = [&](const MedialMesh& m)
  {
    Measure out;
    auto nearEdge = [&m](Index v) { return std::hypot(m.Centers[v][0], m.Centers[v][1]) < 0.3; };
    for (const auto& t : m.Faces)
    {
      out.NearEdgeTriangles += nearEdge(t[0]) && nearEdge(t[1]) && nearEdge(t[2]) ? 1 : 0;
    }
    for (std::size_t v = 0; v < m.Centers.size(); ++v)
    {
      double x[3] = { m.Centers[v][0], m.Centers[v][1], m.Centers[v][2] };
      const double inside = -distance->EvaluateFunction(x);
      out.MeanBulge += (m.Radii[v] - inside) / static_cast<double>(m.Centers.size());
    }
    return out;
  };
  const auto simplify = [&](bool concaveFiltering, bool invaginatedTerm)
  {
    return Simplify(block, 20000, 2000, true, concaveFiltering, invaginatedTerm,
      FringeCollapseMode::Automatic, false)
      .Result.Medial.Mesh;
  };
  const Measure full = measure(simplify(true, true));
  const Measure unfiltered = measure(simplify(false, true));
  const Measure planar = measure(simplify(true, false));
  std::cout << "triangles at the concave edge: " << full.NearEdgeTriangles << " (unfiltered "
            << unfiltered.NearEdgeTriangles << "); mean bulge " << full.MeanBulge
            << " (without the site term " << planar.MeanBulge << ")\n";
  EXPECT_GT(unfiltered.NearEdgeTriangles, full.NearEdgeTriangles);
  EXPECT_GT(planar.MeanBulge, 1.5 * full.MeanBulge);
}

TEST(AtlasSimplifier, MergedSpheresStayOutOfTheirOwnSurface)
{
  // A medial ball touches the part of the surface it stands for and never
  // crosses it. The spherical quadric alone fits its cells' tangent planes in
  // the least-squares sense and lets merged balls bulge past the samples of
  // their Atlas where it curves; ClampRadiiToAtlas keeps every sphere within
  // the nearest of them. Measured before the final fit, which moves spheres
  // by its own rules.
  const TriangleMesh dumbbell = MakeDumbbell(5.0, 1.0, 0.45, 48);
  SimplifiedRun run = InitialMedialAxis(dumbbell, 6000);
  auto deepest = [&](bool clamp)
  {
    AtlasSimplifierOptions options;
    options.TargetNumberOfVertices = 200;
    options.PreserveSharpFeatures = false;
    options.FinalFit = false;
    options.HairAngle = 0.0; // the erosion removes the rims where balls bulge
    options.ClampRadiiToAtlas = clamp;
    const AtlasMedialMesh out =
      SimplifyMedialAxis(run.Initial, run.Rvd, run.Sites.Points, options).Medial;
    double depth = 0.0; // the largest radius past the nearest own site
    for (std::size_t v = 0; v < out.Mesh.Centers.size(); ++v)
    {
      double nearest = HUGE_VAL;
      for (Index k = out.AtlasOffsets[v]; k < out.AtlasOffsets[v + 1]; ++k)
      {
        nearest = std::min(
          nearest, std::sqrt(Distance2(out.Mesh.Centers[v], run.Sites.Points[out.AtlasSites[k]])));
      }
      depth = std::max(depth, out.Mesh.Radii[v] - nearest);
    }
    return depth;
  };
  const double clamped = deepest(true), unclamped = deepest(false);
  std::cout << "deepest sphere past its own nearest site: " << clamped << " clamped, " << unclamped
            << " not\n";
  EXPECT_LE(clamped, 1e-9);
  EXPECT_GT(unclamped, 1e-3);
}

TEST(AtlasSimplifier, ErrorBoundedCollapsesKeepAThinPart)
{
  // A block with a thin fin on top (thickness 5% of the block's length):
  // simplified as far as a local error bound of 0.5% of the diagonal lets it
  // go, the fin keeps its sheet up to its top edge and no site ends farther
  // from the envelope than in the initial medial mesh plus the bound;
  // simplified further (by a vertex target), parts of the surface are left
  // far from the envelope. Measured before the final fit.
  const double thickness = 0.1, top = 0.5, finTop = 1.0;
  const TriangleMesh block = MakeBlockWithFin({ 2.0, 1.0, 1.0 }, finTop - top, thickness, 40);
  const SimplifiedRun run = InitialMedialAxis(block, 6000);
  const double bound = 0.005;
  auto simplify = [&](double errorBound, std::size_t target)
  {
    AtlasSimplifierOptions options;
    options.TargetNumberOfVertices = target;
    options.PreserveSharpFeatures = false;
    options.FringeCollapses = FringeCollapseMode::On;
    options.ErrorBound = errorBound;
    options.ErrorBands = ErrorBandMode::Off; // (a plain vertex target without a bound)
    options.FinalFit = false;                // the collapses alone
    return SimplifyMedialAxis(run.Initial, run.Rvd, run.Sites.Points, options);
  };
  const auto [lo, hi] = BoundingBox(run.Sites.Points);
  const double diagonal = std::sqrt(Distance2(lo, hi));
  // The largest distance from a site to the envelope (fraction of the
  // diagonal), and how high the fin's sheet reaches (largest z of a centre
  // in the fin's mid-plane, above the block).
  auto measure = [&](const MedialMesh& m)
  {
    const MedialEnvelope envelope(m);
    double farthest = 0.0, reach = top;
    for (const Point3& p : run.Sites.Points)
    {
      farthest = std::max(farthest, std::abs(envelope.SignedDistance(p).Distance));
    }
    for (const Point3& c : m.Centers)
    {
      if (std::abs(c[1]) < 0.25 * thickness && std::abs(c[0]) < 0.5)
      {
        reach = std::max(reach, c[2]);
      }
    }
    return std::make_pair(farthest / diagonal, reach);
  };
  // (The initial medial mesh already holds sites of the fin's concave root
  // edges inside the fin's balls.)
  const double initialError = measure(run.Initial.Mesh).first;
  const AtlasSimplifierResult bounded = simplify(bound, 1);
  const MedialMesh& mesh = bounded.Medial.Mesh;
  const std::size_t count = mesh.Centers.size();
  ASSERT_FALSE(bounded.Aborted);
  EXPECT_GT(count, 1u); // stopped at the bound, short of the target
  EXPECT_LT(count, run.Initial.Mesh.Centers.size() / 10);
  EXPECT_TRUE(ValidateMedialMesh(mesh).IsValid()) << ValidateMedialMesh(mesh).Message;
  EXPECT_EQ(bounded.FoldingAllowedCollapses, 0u);
  EXPECT_EQ(bounded.RelaxedCollapses, 0u);
  const auto [boundedError, boundedReach] = measure(mesh);
  const AtlasSimplifierResult further = simplify(0.0, count / 4);
  const auto [furtherError, furtherReach] = measure(further.Medial.Mesh);
  std::cout << "initial medial mesh: farthest site " << 100 * initialError << "%; ";
  std::cout << count << " spheres within the local bound " << 100 * bound << "%: farthest site "
            << 100 * boundedError << "%, fin sheet up to z = " << boundedReach << " of " << finTop
            << "; " << count / 4 << " spheres: " << 100 * furtherError
            << "%, up to z = " << furtherReach << "\n";
  EXPECT_LE(boundedError, initialError + bound);
  EXPECT_GT(boundedReach, finTop - thickness);
  EXPECT_GT(furtherError, 2.0 * boundedError);
}

TEST(AtlasSimplifier, OutputIsValidAndDeterministic)
{
  const TriangleMesh box = MakeRoundedBox({ 2.0, 1.5, 1.0 }, 0.2, 12);
  const SimplifiedRun a = RunWithThreads(1, [&] { return Simplify(box, 3000, 300, true); });
  const SimplifiedRun b = RunWithThreads(2, [&] { return Simplify(box, 3000, 300, true); });
  const MedialMesh &ma = a.Result.Medial.Mesh, &mb = b.Result.Medial.Mesh;
  EXPECT_EQ(ma.Centers.size(), 300u);
  EXPECT_TRUE(ValidateMedialMesh(ma).IsValid()) << ValidateMedialMesh(ma).Message;
  EXPECT_EQ(DegenerateTriangles(ma), 0u);
  ASSERT_EQ(ma.Centers.size(), mb.Centers.size());
  EXPECT_EQ(
    0, std::memcmp(ma.Centers.data(), mb.Centers.data(), ma.Centers.size() * sizeof(Point3)));
  EXPECT_EQ(ma.Faces, mb.Faces);
  EXPECT_EQ(a.Result.Medial.AtlasSites, b.Result.Medial.AtlasSites);
  for (double r : ma.Radii)
  {
    EXPECT_GE(r, 0.0);
  }
}

namespace
{
// Same spheres (bit for bit), faces and Atlases.
void ExpectBitIdentical(const AtlasMedialMesh& p, const AtlasMedialMesh& q)
{
  const MedialMesh &a = p.Mesh, &b = q.Mesh;
  ASSERT_EQ(a.Centers.size(), b.Centers.size());
  EXPECT_EQ(0, std::memcmp(a.Centers.data(), b.Centers.data(), a.Centers.size() * sizeof(Point3)));
  EXPECT_EQ(a.Radii, b.Radii);
  EXPECT_EQ(a.Faces, b.Faces);
  EXPECT_EQ(p.AtlasSites, q.AtlasSites);
}
}

// The error bands test every merged ball against the nearest site; the
// Voronoi stage's bounds on that distance, carried through the collapses,
// decide most tests without a search and must never change an answer.
TEST(AtlasSimplifier, SiteClearanceBoundsChangeNothing)
{
  const TriangleMesh shape = MakeDumbbell(2.0, 0.45, 0.2, 48);
  SimplifiedRun run = InitialMedialAxis(shape, 4000);
  ASSERT_EQ(run.Initial.SiteClearance.size(), run.Initial.Mesh.Centers.size());
  std::size_t known = 0;
  for (double c : run.Initial.SiteClearance)
  {
    known += c >= 0.0 ? 1 : 0;
  }
  EXPECT_GT(known, run.Initial.SiteClearance.size() / 2);
  AtlasSimplifierOptions options;
  options.TargetNumberOfVertices = 300;
  options.ErrorBands = ErrorBandMode::On;
  ASSERT_TRUE(UsesErrorBands(options));
  const AtlasSimplifierResult with =
    SimplifyMedialAxis(run.Initial, run.Rvd, run.Sites.Points, options);
  run.Initial.SiteClearance.clear();
  const AtlasSimplifierResult without =
    SimplifyMedialAxis(run.Initial, run.Rvd, run.Sites.Points, options);
  ExpectBitIdentical(with.Medial, without.Medial);
}

// A caller done with the initial MAT hands it over: the hair is eroded in
// place and the arrays freed early, with the same result as from a copy.
TEST(AtlasSimplifier, HandedOverInputGivesTheSameResult)
{
  const TriangleMesh shape = MakeDumbbell(2.0, 0.45, 0.2, 48);
  SimplifiedRun run = InitialMedialAxis(shape, 4000);
  AtlasSimplifierOptions options;
  options.TargetNumberOfVertices = 300;
  options.PreserveSharpFeatures = false; // organic: the erosion runs
  ASSERT_TRUE(UsesHairErosion(options));
  const AtlasSimplifierResult copied =
    SimplifyMedialAxis(run.Initial, run.Rvd, run.Sites.Points, options);
  const AtlasSimplifierResult handed =
    SimplifyMedialAxis(std::move(run.Initial), run.Rvd, run.Sites.Points, options);
  EXPECT_TRUE(run.Initial.Mesh.Centers.empty());
  EXPECT_TRUE(run.Initial.AtlasSites.empty());
  ExpectBitIdentical(copied.Medial, handed.Medial);
  EXPECT_EQ(copied.ErodedTriangles, handed.ErodedTriangles);
  EXPECT_GT(handed.ErodedTriangles + handed.Collapses, 0u);
}

// The collapses of distant edges are made in parallel batches, with sharp
// features (CAD) or without: the result must not depend on the thread
// count, and the mesh must stay valid.
class ParallelBatches : public ::testing::TestWithParam<bool>
{
};

TEST_P(ParallelBatches, AreDeterministicAndValid)
{
  const bool sharp = GetParam();
  const TriangleMesh box = MakeRoundedBox({ 2.0, 1.5, 1.0 }, 0.2, 12);
  SimplifiedRun runs[3];
  for (int threads = 1; threads <= 3; ++threads)
  {
    runs[threads - 1] = RunWithThreads(threads, [&] { return Simplify(box, 8000, 300, sharp); });
  }
  const AtlasSimplifierResult& first = runs[0].Result;
  const MedialMesh& m = first.Medial.Mesh;
  EXPECT_EQ(m.Centers.size(), 300u);
  EXPECT_TRUE(ValidateMedialMesh(m).IsValid()) << ValidateMedialMesh(m).Message;
  EXPECT_EQ(DegenerateTriangles(m), 0u);
  EXPECT_EQ(MeasureQuality(m).FoldedTriangles, 0u);
  // Batches of several collapses each.
  const std::size_t taken = first.Collapses + first.RejectedCollapses;
  EXPECT_GT(first.Batches, 0u);
  EXPECT_GE(taken, 4 * first.Batches) << taken << " candidates in " << first.Batches << " batches";
  for (int k = 1; k < 3; ++k)
  {
    const MedialMesh& other = runs[k].Result.Medial.Mesh;
    ASSERT_EQ(other.Centers.size(), m.Centers.size()) << k + 1 << " threads";
    EXPECT_EQ(
      0, std::memcmp(other.Centers.data(), m.Centers.data(), m.Centers.size() * sizeof(Point3)))
      << k + 1 << " threads";
    EXPECT_EQ(other.Radii, m.Radii);
    EXPECT_EQ(other.Faces, m.Faces);
    EXPECT_EQ(runs[k].Result.Medial.AtlasSites, first.Medial.AtlasSites);
    EXPECT_EQ(runs[k].Result.Batches, first.Batches);
  }
}

INSTANTIATE_TEST_SUITE_P(AtlasSimplifier, ParallelBatches, ::testing::Values(false, true),
  [](const ::testing::TestParamInfo<bool>& info) { return info.param ? "Sharp" : "Organic"; });

// Without parallel batches the collapses are made one at a time in the
// greedy order; with two threads the next candidate is checked ahead on the
// second one. The result must be that of the plain loop, bit for bit, at one
// thread and at two.
TEST(AtlasSimplifier, CheckingAheadKeepsTheGreedyOrder)
{
  const TriangleMesh box = MakeRoundedBox({ 2.0, 1.5, 1.0 }, 0.2, 12);
  const SimplifiedRun initial = medialaxis::test::InitialMedialAxis(box, 8000);
  auto simplify = [&](bool checkAhead)
  {
    AtlasSimplifierOptions options;
    options.TargetNumberOfVertices = 300;
    options.PreserveSharpFeatures = true;
    options.ParallelBatches = false;
    options.CheckAhead = checkAhead;
    return SimplifyMedialAxis(initial.Initial, initial.Rvd, initial.Sites.Points, options);
  };
  const AtlasSimplifierResult plain = RunWithThreads(2, [&] { return simplify(false); });
  for (int threads = 1; threads <= 2; ++threads)
  {
    const AtlasSimplifierResult ahead = RunWithThreads(threads, [&] { return simplify(true); });
    const MedialMesh &m = plain.Medial.Mesh, &other = ahead.Medial.Mesh;
    ASSERT_EQ(other.Centers.size(), m.Centers.size()) << threads << " threads";
    EXPECT_EQ(
      0, std::memcmp(other.Centers.data(), m.Centers.data(), m.Centers.size() * sizeof(Point3)))
      << threads << " threads";
    EXPECT_EQ(other.Radii, m.Radii);
    EXPECT_EQ(other.Faces, m.Faces);
    EXPECT_EQ(ahead.Medial.AtlasSites, plain.Medial.AtlasSites);
    EXPECT_EQ(ahead.Collapses, plain.Collapses);
    EXPECT_EQ(ahead.RejectedCollapses, plain.RejectedCollapses);
  }
  EXPECT_EQ(plain.Medial.Mesh.Centers.size(), 300u);
  EXPECT_TRUE(ValidateMedialMesh(plain.Medial.Mesh).IsValid());
  EXPECT_EQ(plain.Batches, plain.Collapses + plain.RejectedCollapses); // one at a time
}

TEST(AtlasSimplifier, AtlasesKeepEverySite)
{
  const SimplifiedRun run = Simplify(MakeCapsule(0.5, 2.0, 16), 3000, 100, false);
  const std::set<Index> before(run.Initial.AtlasSites.begin(), run.Initial.AtlasSites.end());
  const auto& after = run.Result.Medial;
  const std::set<Index> kept(after.AtlasSites.begin(), after.AtlasSites.end());
  EXPECT_EQ(before, kept);
  for (std::size_t v = 0; v + 1 < after.AtlasOffsets.size(); ++v)
  {
    EXPECT_TRUE(std::is_sorted(after.AtlasSites.begin() + after.AtlasOffsets[v],
      after.AtlasSites.begin() + after.AtlasOffsets[v + 1]));
  }
}

TEST(AtlasMedialAxisSimplifierFilter, PipelineAndCorrespondence)
{
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToTorus();
  shape->SetResolution(16);
  test::InitialMedialPipeline pipeline(shape->GetOutputPort(), 3000);
  vtkRestrictedVoronoiDiagram* rvd = pipeline.Rvd;
  vtkVoronoiMedialAxis* voronoi = pipeline.Voronoi;
  vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
  simplifier->SetInputConnection(0, voronoi->GetOutputPort());
  simplifier->SetInputConnection(1, rvd->GetOutputPort(0));
  simplifier->SetTargetNumberOfVertices(200);
  simplifier->PreserveSharpFeaturesOff();
  simplifier->Update();
  vtkPolyData* mat = simplifier->GetOutput();
  EXPECT_EQ(mat->GetNumberOfPoints(), 200);
  EXPECT_EQ(ValidateMedialPolyData(mat), "");
  EXPECT_NE(mat->GetPointData()->GetArray("FeatureVertex"), nullptr);
  EXPECT_NE(mat->GetCellData()->GetArray("StabilityRatio"), nullptr);
  std::vector<Index> offsets, sites;
  ASSERT_EQ(GetAtlasArrays(mat, offsets, sites), "");
  vtkPolyData* colored = vtkPolyData::SafeDownCast(simplifier->GetOutputDataObject(1));
  vtkDataArray* ids = colored->GetCellData()->GetArray("MedialVertexId");
  ASSERT_NE(ids, nullptr);
  double range[2];
  ids->GetRange(range);
  EXPECT_GE(range[0], 0.0);
  EXPECT_LT(range[1], 200.0);
}

TEST(AtlasMedialAxisSimplifierFilter, KeepsToItsThreadsAndGivesTheSameResultOnAny)
{
  // A stage's own "every core" (0) stays within an enclosing limit: the final
  // fit's searches ran on every core even when the pipeline was given one.
  EXPECT_EQ(
    RunWithThreads(
      1, [] { return RunWithThreads(0, [] { return tbb::this_task_arena::max_concurrency(); }); }),
    1);
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToTorus();
  shape->SetResolution(16);
  test::InitialMedialPipeline pipeline(shape->GetOutputPort(), 3000);
  std::vector<std::vector<double>> results;
  for (int threads : { 1, 2 })
  {
    vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
    simplifier->SetInputConnection(0, pipeline.Voronoi->GetOutputPort());
    simplifier->SetInputConnection(1, pipeline.Rvd->GetOutputPort(0));
    simplifier->SetTargetNumberOfVertices(200);
    simplifier->SetNumberOfThreads(threads);
    EXPECT_EQ(simplifier->GetNumberOfThreads(), threads);
    // The progress reports come from inside the simplification: the threads
    // it may use there.
    int widest = 0;
    vtkNew<vtkCallbackCommand> observer;
    observer->SetClientData(&widest);
    observer->SetCallback(
      [](vtkObject*, unsigned long, void* widestThreads, void* progress)
      {
        // (Reports of 0 and 1 come from the pipeline, before and after.)
        const double f = *static_cast<double*>(progress);
        if (f > 0.0 && f < 1.0)
        {
          int& w = *static_cast<int*>(widestThreads);
          w = std::max(w, tbb::this_task_arena::max_concurrency());
        }
      });
    simplifier->AddObserver(vtkCommand::ProgressEvent, observer);
    simplifier->Update();
    if (threads == 1)
    {
      EXPECT_EQ(widest, 1);
    }
    vtkPolyData* mat = simplifier->GetOutput();
    ASSERT_EQ(mat->GetNumberOfPoints(), 200);
    std::vector<double> values;
    for (vtkIdType i = 0; i < mat->GetNumberOfPoints(); ++i)
    {
      double x[3];
      mat->GetPoint(i, x);
      values.insert(values.end(), x, x + 3);
      values.push_back(mat->GetPointData()->GetArray("Radius")->GetComponent(i, 0));
    }
    results.push_back(values);
  }
  EXPECT_EQ(results[0], results[1]);
}

TEST(AtlasMedialAxisSimplifierFilter, BadInputsGiveClearErrors)
{
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToSphere();
  shape->SetResolution(8);
  test::InitialMedialPipeline pipeline(shape->GetOutputPort(), 500);
  vtkRestrictedVoronoiDiagram* rvd = pipeline.Rvd;
  vtkVoronoiMedialAxis* voronoi = pipeline.Voronoi;
  voronoi->Update();
  rvd->Update();

  auto run = [](vtkPolyData* mat, vtkPolyData* cells)
  {
    vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
    vtkNew<test::ErrorCatcher> errors;
    simplifier->AddObserver(vtkCommand::ErrorEvent, errors);
    simplifier->SetInputData(0, mat);
    simplifier->SetInputData(1, cells);
    simplifier->Update();
    EXPECT_EQ(simplifier->GetOutput()->GetNumberOfPoints(), 0);
    return errors->Last;
  };
  // A medial mesh without its Atlas (e.g. read from a .ma file).
  vtkNew<vtkPolyData> noAtlas;
  noAtlas->DeepCopy(voronoi->GetOutput());
  noAtlas->GetFieldData()->RemoveArray("AtlasSites");
  EXPECT_NE(run(noAtlas, rvd->GetOutput(0)).find("has no Atlas"), std::string::npos);
  // The sites output instead of the RVD cells on port 1.
  vtkPolyData* sites = vtkPolyData::SafeDownCast(rvd->GetOutputDataObject(1));
  EXPECT_NE(run(voronoi->GetOutput(), sites).find("must be the restricted Voronoi diagram"),
    std::string::npos);
  // A medial mesh whose radius is invalid.
  vtkNew<vtkPolyData> negative;
  negative->DeepCopy(voronoi->GetOutput());
  negative->GetPointData()->GetArray("Radius")->SetComponent(0, 0, -1.0);
  EXPECT_NE(run(negative, rvd->GetOutput(0)).find("negative"), std::string::npos);
}

TEST(ExtractMedialAtlasFilter, ShowsExactlyTheCellsOfOneVertex)
{
  vtkNew<vtkAnalyticShapeSource> shape;
  shape->SetShapeToCapsule();
  shape->SetResolution(16);
  test::InitialMedialPipeline pipeline(shape->GetOutputPort(), 2000);
  vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
  simplifier->SetInputConnection(0, pipeline.Voronoi->GetOutputPort());
  simplifier->SetInputConnection(1, pipeline.Rvd->GetOutputPort(0));
  simplifier->SetTargetNumberOfVertices(30);
  simplifier->PreserveSharpFeaturesOff();
  vtkNew<vtkExtractMedialAtlas> extractor;
  extractor->SetInputConnection(0, simplifier->GetOutputPort(0));
  extractor->SetInputConnection(1, simplifier->GetOutputPort(1));
  simplifier->Update();
  vtkPolyData* mat = simplifier->GetOutput();
  vtkPolyData* cells = vtkPolyData::SafeDownCast(simplifier->GetOutputDataObject(1));
  vtkPolyData* sitesOut = vtkPolyData::SafeDownCast(pipeline.Rvd->GetOutputDataObject(1));
  vtkDataArray* cellArea = sitesOut->GetPointData()->GetArray("CellArea");
  ASSERT_NE(cellArea, nullptr);
  std::vector<Index> offsets, sites;
  ASSERT_EQ(GetAtlasArrays(mat, offsets, sites), "");

  double totalArea = 0.0;
  for (vtkIdType v = 0; v < mat->GetNumberOfPoints(); ++v)
  {
    extractor->SetMedialVertexId(v);
    extractor->Update();
    vtkPolyData* out = extractor->GetOutput();
    std::vector<Index> atlas(sites.begin() + offsets[v], sites.begin() + offsets[v + 1]);
    std::sort(atlas.begin(), atlas.end());
    ASSERT_FALSE(atlas.empty());
    // Every polygon of the RVD whose site is in the Atlas, and no other.
    vtkDataArray* siteIds = cells->GetCellData()->GetArray("SiteId");
    vtkIdType expected = 0;
    for (vtkIdType c = 0; c < cells->GetNumberOfCells(); ++c)
    {
      expected += std::binary_search(
        atlas.begin(), atlas.end(), static_cast<Index>(siteIds->GetComponent(c, 0)));
    }
    EXPECT_EQ(out->GetNumberOfCells(), expected);
    vtkDataArray* outSites = out->GetCellData()->GetArray("SiteId");
    ASSERT_NE(outSites, nullptr);
    for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
    {
      EXPECT_TRUE(std::binary_search(
        atlas.begin(), atlas.end(), static_cast<Index>(outSites->GetComponent(c, 0))));
    }
    // Its area is that of the Atlas' restricted Voronoi cells.
    double atlasArea = 0.0;
    for (Index s : atlas)
    {
      atlasArea += cellArea->GetComponent(s, 0);
    }
    const double area = out->GetFieldData()->GetArray("AtlasArea")->GetComponent(0, 0);
    EXPECT_NEAR(area, atlasArea, 1e-9 * atlasArea);
    EXPECT_EQ(out->GetFieldData()->GetArray("SphereRadius")->GetComponent(0, 0),
      mat->GetPointData()->GetArray("Radius")->GetComponent(v, 0));
    totalArea += area;
  }
  // Atlases overlap, and together they cover the whole surface.
  double surfaceArea = 0.0;
  for (vtkIdType s = 0; s < cellArea->GetNumberOfTuples(); ++s)
  {
    surfaceArea += cellArea->GetComponent(s, 0);
  }
  EXPECT_GE(totalArea, surfaceArea * (1.0 - 1e-9));

  // An id past the last vertex is an error that says which ids exist.
  vtkNew<test::ErrorCatcher> errors;
  extractor->AddObserver(vtkCommand::ErrorEvent, errors);
  extractor->SetMedialVertexId(30);
  extractor->Update();
  EXPECT_EQ(extractor->GetOutput()->GetNumberOfCells(), 0);
  EXPECT_NE(errors->Last.find("from 0 to 29"), std::string::npos) << errors->Last;
}

// Ablation: without the fold test, collapses fold triangles onto each other
// (spike removals turn needle triangles freely); with it, none remain.
TEST(AtlasMedialAxisSimplifierFilter, PreventFoldsAblation)
{
  const std::string path = std::string(MEDIALAXIS_MESH_DIR) + "/bunny.obj";
  if (!std::ifstream(path).good())
  {
    GTEST_SKIP() << "shared meshes not present at " << MEDIALAXIS_MESH_DIR;
  }
  vtkNew<vtkSurfaceFileReader> reader;
  reader->SetFileName(path.c_str());
  test::InitialMedialPipeline pipeline(reader->GetOutputPort(), 5000);
  std::size_t folded[2] = { 0, 0 };
  for (bool prevent : { false, true })
  {
    vtkNew<vtkAtlasMedialAxisSimplifier> simplifier;
    simplifier->SetInputConnection(0, pipeline.Voronoi->GetOutputPort());
    simplifier->SetInputConnection(1, pipeline.Rvd->GetOutputPort(0));
    simplifier->SetTargetNumberOfVertices(500);
    simplifier->PreserveSharpFeaturesOff();
    simplifier->SetPreventFolds(prevent);
    simplifier->Update();
    MedialMesh m;
    ASSERT_EQ(PolyDataToMedialMesh(simplifier->GetOutput(), m), "");
    EXPECT_EQ(m.Centers.size(), 500u);
    folded[prevent] = MeasureQuality(m).FoldedTriangles;
  }
  std::cout << "bunny 5,000 sites -> 500 spheres: " << folded[0] << " folded triangles without "
            << "the fold test, " << folded[1] << " with it\n";
  EXPECT_GT(folded[0], 0u);
  EXPECT_EQ(folded[1], 0u);
}

namespace
{
// The solve as it was done with Eigen's LDLT, as the reference.
template <int N>
bool ReferenceSolve(const SphereQuadric& q, Eigen::Matrix<double, N, 1>& x)
{
  Eigen::Matrix<double, N, N> A;
  Eigen::Matrix<double, N, 1> B;
  for (int i = 0; i < N; ++i)
  {
    for (int j = 0; j < N; ++j)
    {
      A(i, j) = q.A(i, j);
    }
    B[i] = q.B(i);
  }
  const Eigen::LDLT<Eigen::Matrix<double, N, N>> ldlt(A);
  const Eigen::Matrix<double, N, 1> pivots = ldlt.vectorD().cwiseAbs();
  if (ldlt.info() != Eigen::Success || !(pivots.minCoeff() > 1e-12 * pivots.maxCoeff()))
  {
    return false;
  }
  x = ldlt.solve(B);
  return x.allFinite();
}

template <int N>
void CompareWithReference(int facets, bool expectSolvable)
{
  Random random(1000 * N + facets);
  for (int trial = 0; trial < 200; ++trial)
  {
    SphereQuadric q;
    for (int f = 0; f < facets; ++f)
    {
      const Point3 n =
        Normalized({ random.Uniform() - 0.5, random.Uniform() - 0.5, random.Uniform() - 0.5 });
      q.AddFacet(n, random.Uniform() - 0.5, 0.01 + random.Uniform());
    }
    Eigen::Matrix<double, N, 1> x, reference;
    const bool solved = SolveQuadric<N>(q, x);
    ASSERT_EQ(solved, ReferenceSolve<N>(q, reference)) << N << " " << facets << " " << trial;
    ASSERT_EQ(solved, expectSolvable) << N << " " << facets << " " << trial;
    if (solved)
    {
      // The same minimiser: the gradient A x - B vanishes.
      for (int i = 0; i < N; ++i)
      {
        double residual = -q.B(i);
        for (int j = 0; j < N; ++j)
        {
          residual += q.A(i, j) * x[j];
        }
        EXPECT_NEAR(residual, 0.0, 1e-9);
        EXPECT_NEAR(x[i], reference[i], 1e-8 * (1.0 + std::abs(reference[i])));
      }
    }
  }
}
}

// The hand-written fixed-size LDL^T gives Eigen's LDLT minimiser on
// well-posed quadrics and refuses the same rank-deficient ones.
TEST(SphereQuadric, SolveMatchesEigenLdlt)
{
  CompareWithReference<4>(8, true);
  CompareWithReference<4>(3, false); // 3 planes fix no sphere: rank 3 < 4
  CompareWithReference<3>(8, true);
  CompareWithReference<3>(2, false);
  CompareWithReference<2>(4, true);
  CompareWithReference<1>(1, true);
}

namespace
{
// Current while both endpoints keep the versions recorded in the entry.
struct EndpointsUnchanged
{
  const std::vector<std::uint32_t>* Version;
  template <typename Entry>
  bool operator()(const Entry& e) const
  {
    return (*this->Version)[e.A] == e.VersionA && (*this->Version)[e.B] == e.VersionB;
  }
};
}

// The bucketed queue pops exactly what a plain ordered set of the current
// entries gives first, through bulk loading, pushes below the open bucket,
// rising costs that outgrow the last bucket (and get split), equal costs,
// stale entries and clean-ups.
TEST(CollapseQueue, PopsTheCheapestCurrentEntryInOrder)
{
  std::vector<std::uint32_t> version(20000, 0);
  using Queue = CollapseQueue<int, EndpointsUnchanged>;
  using Entry = Queue::Entry;
  auto before = [](const Entry& p, const Entry& q)
  {
    return std::tie(p.Cost, p.A, p.B, p.VersionA, p.VersionB) <
      std::tie(q.Cost, q.A, q.B, q.VersionA, q.VersionB);
  };
  std::multiset<Entry, decltype(before)> reference(before);
  Queue queue(EndpointsUnchanged{ &version });
  Random rng(7);
  auto make = [&](double cost)
  {
    const Index a = static_cast<Index>(rng.Next() % version.size());
    const Index b = static_cast<Index>(rng.Next() % version.size());
    // Coarse costs: many ties, broken by the endpoints and versions.
    return Entry{ std::floor(cost * 64.0) / 64.0, a, b, version[a], version[b],
      static_cast<int>(rng.Next() % 1000) };
  };
  std::vector<Entry> initial;
  for (int i = 0; i < 12000; ++i)
  {
    initial.push_back(make(rng.Uniform()));
  }
  queue.PushAll(initial);
  reference.insert(initial.begin(), initial.end());
  std::size_t pops = 0, stale = 0, splitCosts = 0;
  double highest = 0.0;
  for (int round = 0; round < 20000; ++round)
  {
    // A collapse: pop the top, make its endpoints' entries stale, push new
    // ones, mostly dearer than anything so far, some cheaper than the top.
    const Entry* top = queue.TopCurrent();
    while (!reference.empty() &&
      !(version[reference.begin()->A] == reference.begin()->VersionA &&
        version[reference.begin()->B] == reference.begin()->VersionB))
    {
      reference.erase(reference.begin());
      ++stale;
    }
    ASSERT_EQ(top == nullptr, reference.empty());
    if (!top)
    {
      break;
    }
    const Entry expected = *reference.begin();
    ASSERT_EQ(top->Cost, expected.Cost) << "pop " << pops;
    ASSERT_EQ(top->A, expected.A);
    ASSERT_EQ(top->B, expected.B);
    ASSERT_EQ(top->VersionA, expected.VersionA);
    ASSERT_EQ(top->VersionB, expected.VersionB);
    ASSERT_EQ(top->Target, expected.Target);
    const Index a = top->A, b = top->B;
    const double cost = top->Cost;
    highest = std::max(highest, cost);
    queue.PopTop();
    reference.erase(reference.find(expected));
    ++pops;
    ++version[a];
    ++version[b];
    for (int k = 0; k < 4; ++k)
    {
      const double u = rng.Uniform();
      const Entry e = make(u < 0.05 ? cost + 0.1 * u : 1.0 + 4.0 * u);
      splitCosts += e.Cost >= 1.0 ? 1 : 0;
      queue.Push(e);
      reference.insert(e);
    }
  }
  EXPECT_EQ(pops, 20000u);
  EXPECT_GT(stale, 1000u);
  // The costs pushed above the initial ones outgrew the last bucket, which
  // was split and reached.
  EXPECT_GT(splitCosts, 3u * 8192u);
  EXPECT_GT(highest, 1.0);
  queue.Clear();
  EXPECT_EQ(queue.TopCurrent(), nullptr);
  EXPECT_EQ(queue.Size(), 0u);
}
