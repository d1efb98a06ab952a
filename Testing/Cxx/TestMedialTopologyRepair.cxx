// SPDX-License-Identifier: GPL-3.0-or-later
// The topology repair of the initial medial mesh on small hand-built
// complexes whose defects are known: a tube (one spurious loop round a
// hole), a loop of face-less edges, a piece cut off, an edge bridging two
// solids, and a sheet whose rim must not be capped into a closed bubble;
// and the peeling that tells whether a cap closes a void.
#include "Geometry/Vec3.h"
#include "Mesh/MedialMesh.h"
#include "Surface/AnalyticShapes.h"
#include "Voronoi/CapPeeling.h"
#include "Voronoi/MedialTopologyRepair.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>

using namespace medialaxis;

namespace
{
// A ball of radius 10 round the origin stands for the solid.
TopologyRepairQueries BigBall()
{
  return { [](const Point3& p) { return Norm(p) < 10.0; },
    [](const Point3& p) { return 10.0 - Norm(p); },
    [](const Point3&, const Point3&) { return false; } };
}

// The segment test of a solid given by its inside test: a segment crosses
// the surface where one of `steps` + 1 points along it is outside.
template <typename Inside>
std::function<bool(const Point3&, const Point3&)> CrossesBySampling(Inside inside, int steps)
{
  return [inside, steps](const Point3& a, const Point3& b)
  {
    for (int k = 0; k <= steps; ++k)
    {
      if (!inside(a + (static_cast<double>(k) / steps) * (b - a)))
      {
        return true;
      }
    }
    return false;
  };
}

// Adds vertices with radius 0.1 and one Atlas site each.
Index AddVertex(VoronoiMedialAxisResult& result, const Point3& p)
{
  result.Mesh.Centers.push_back(p);
  result.Mesh.Radii.push_back(0.1);
  result.AtlasSites.push_back(static_cast<Index>(result.AtlasSites.size()));
  result.AtlasOffsets.push_back(static_cast<Index>(result.AtlasSites.size()));
  return static_cast<Index>(result.Mesh.Centers.size() - 1);
}

void AddFace(VoronoiMedialAxisResult& result, Index a, Index b, Index c)
{
  result.Mesh.Faces.push_back({ a, b, c });
  result.FaceSitePair.push_back({ a, b });
}

// An open tube of `n` quads round the z axis, z in [z0, z0 + 1], radius `r`:
// Euler characteristic 0, one loop, two rims.
void AddTube(VoronoiMedialAxisResult& result, int n, double r, double z0)
{
  std::vector<Index> low, high;
  for (int k = 0; k < n; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * k / n;
    low.push_back(AddVertex(result, { r * std::cos(a), r * std::sin(a), z0 }));
    high.push_back(AddVertex(result, { r * std::cos(a), r * std::sin(a), z0 + 1.0 }));
  }
  for (int k = 0; k < n; ++k)
  {
    const int j = (k + 1) % n;
    AddFace(result, low[k], low[j], high[j]);
    AddFace(result, low[k], high[j], high[k]);
  }
}

// A flat disk, a fan of `n` triangles round `centre`, normal z.
void AddDisk(VoronoiMedialAxisResult& result, int n, double r, const Point3& centre)
{
  const Index hub = AddVertex(result, centre);
  std::vector<Index> rim;
  for (int k = 0; k < n; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * k / n;
    rim.push_back(AddVertex(result, centre + Point3{ r * std::cos(a), r * std::sin(a), 0.0 }));
  }
  for (int k = 0; k < n; ++k)
  {
    AddFace(result, hub, rim[k], rim[(k + 1) % n]);
  }
}

std::size_t Pieces(const MedialMesh& mesh)
{
  std::vector<Index> root(mesh.Centers.size());
  for (std::size_t v = 0; v < root.size(); ++v)
  {
    root[v] = static_cast<Index>(v);
  }
  auto find = [&](Index v)
  {
    while (root[v] != v)
    {
      v = root[v] = root[root[v]];
    }
    return v;
  };
  for (const auto& e : AllEdges(mesh))
  {
    root[find(e[0])] = find(e[1]);
  }
  std::size_t count = 0;
  for (std::size_t v = 0; v < root.size(); ++v)
  {
    count += find(static_cast<Index>(v)) == static_cast<Index>(v) ? 1 : 0;
  }
  return count;
}
}

TEST(SurfaceTopology, CountsPiecesAndHandles)
{
  const SurfaceTopology sphere = ComputeSurfaceTopology(MakeSphere(1.0, 16));
  EXPECT_EQ(sphere.Components, 1u);
  EXPECT_EQ(sphere.Genus, 0);
  const SurfaceTopology torus = ComputeSurfaceTopology(MakeTorus(1.0, 0.3, 24));
  EXPECT_EQ(torus.Components, 1u);
  EXPECT_EQ(torus.Genus, 1);
  TriangleMesh two = MakeSphere(1.0, 8);
  const TriangleMesh other = MakeTorus(1.0, 0.3, 12);
  const Index offset = static_cast<Index>(two.Points.size());
  for (const Point3& p : other.Points)
  {
    two.Points.push_back(p + Point3{ 5.0, 0.0, 0.0 });
  }
  for (const Triangle& t : other.Triangles)
  {
    two.Triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  const SurfaceTopology both = ComputeSurfaceTopology(two);
  EXPECT_EQ(both.Components, 2u);
  EXPECT_EQ(both.Genus, 1);
}

TEST(MedialTopologyRepair, CapsOneRimOfATubeInABall)
{
  VoronoiMedialAxisResult result;
  AddTube(result, 12, 1.0, 0.0);
  ASSERT_EQ(EulerCharacteristic(result.Mesh), 0);
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 1, 0 }, BigBall());
  EXPECT_EQ(counts.FilledHoles, 1u);
  EXPECT_EQ(counts.CutLoops, 0u);
  EXPECT_EQ(EulerCharacteristic(result.Mesh), 1);
  ASSERT_EQ(result.Mesh.Centers.size(), 25u);
  // The cap's hub is the centre of one rim, its radius the distance to the surface.
  const Point3& hub = result.Mesh.Centers.back();
  EXPECT_NEAR(std::hypot(hub[0], hub[1]), 0.0, 1e-12);
  EXPECT_NEAR(result.Mesh.Radii.back(), 10.0 - Norm(hub), 1e-12);
  EXPECT_EQ(result.AtlasOffsets.size(), 26u);
  EXPECT_EQ(result.AtlasOffsets.back() - result.AtlasOffsets[24], 12); // its rim's sites
  EXPECT_EQ(result.FaceSitePair.size(), result.Mesh.Faces.size());
  EXPECT_EQ(result.FaceSitePair.back()[0], -1);
  EXPECT_TRUE(ValidateMedialMesh(result.Mesh).IsValid()) << ValidateMedialMesh(result.Mesh).Message;
}

TEST(MedialTopologyRepair, LeavesTheLoopOfAHandle)
{
  VoronoiMedialAxisResult result;
  AddTube(result, 12, 1.0, 0.0);
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 1, 1 }, BigBall());
  EXPECT_EQ(counts.FilledHoles + counts.CutLoops + counts.JoinedPieces, 0u);
  EXPECT_EQ(EulerCharacteristic(result.Mesh), 0);
}

TEST(MedialTopologyRepair, NeverCapsARimIntoABubble)
{
  // A disk, whose rim is shorter than the tube's, joined to the tube: capping
  // the disk's rim would close a void and leave the tube's loop. The tube's
  // rim is capped.
  VoronoiMedialAxisResult result;
  AddTube(result, 12, 1.0, 0.0);
  AddDisk(result, 6, 0.3, { 0.0, 0.0, 3.0 });
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 1, 0 }, BigBall());
  EXPECT_EQ(counts.JoinedPieces, 1u);
  EXPECT_EQ(counts.FilledHoles, 1u);
  EXPECT_EQ(EulerCharacteristic(result.Mesh), 1);
  const Point3& hub = result.Mesh.Centers.back();
  EXPECT_NEAR(std::hypot(hub[0], hub[1]), 0.0, 1e-12);
  EXPECT_LT(std::min(std::fabs(hub[2]), std::fabs(hub[2] - 1.0)), 1e-12)
    << hub[2]; // a rim of the tube, not the disk's
  EXPECT_TRUE(ValidateMedialMesh(result.Mesh).IsValid()) << ValidateMedialMesh(result.Mesh).Message;
}

TEST(MedialTopologyRepair, CutsTheShortestLoopOfEdgesOnly)
{
  // A disk with a triangle of face-less edges hanging off its hub: one
  // spurious loop, opened by removing one of its edges.
  VoronoiMedialAxisResult result;
  AddDisk(result, 8, 1.0, { 0.0, 0.0, 0.0 });
  const Index a = AddVertex(result, { 0.0, 0.0, 0.5 });
  const Index b = AddVertex(result, { 0.2, 0.0, 0.7 });
  result.Mesh.Edges = { { 0, a }, { 0, b }, { a, b } };
  ASSERT_EQ(EulerCharacteristic(result.Mesh), 0);
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 1, 0 }, BigBall());
  EXPECT_EQ(counts.CutLoops, 1u);
  EXPECT_EQ(counts.FilledHoles, 0u);
  EXPECT_EQ(result.Mesh.Edges.size(), 2u);
  EXPECT_EQ(EulerCharacteristic(result.Mesh), 1);
  EXPECT_EQ(Pieces(result.Mesh), 1u);
}

TEST(MedialTopologyRepair, JoinsAPieceCutOffInsideTheSolid)
{
  VoronoiMedialAxisResult result;
  AddDisk(result, 8, 1.0, { 0.0, 0.0, 0.0 });
  AddDisk(result, 8, 1.0, { 3.0, 0.0, 0.0 });
  ASSERT_EQ(Pieces(result.Mesh), 2u);
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 1, 0 }, BigBall());
  EXPECT_EQ(counts.JoinedPieces, 1u);
  EXPECT_EQ(Pieces(result.Mesh), 1u);
  EXPECT_EQ(EulerCharacteristic(result.Mesh), 1);
  ASSERT_EQ(result.Mesh.Edges.size(), 1u);
  // The closest pair: the disks' rims at x = 1 and x = 2.
  EXPECT_NEAR(Norm(result.Mesh.Centers[result.Mesh.Edges[0][0]] -
                result.Mesh.Centers[result.Mesh.Edges[0][1]]),
    1.0, 1e-12);
}

TEST(MedialTopologyRepair, DropsAnEdgeBridgingTwoSolids)
{
  // Two balls of radius 1.5 at x = -2 and x = 2: a medial edge from one to
  // the other leaves the solid and goes; the two pieces stay apart.
  auto insideEither = [](const Point3& p) {
    return Norm(p - Point3{ -2.0, 0.0, 0.0 }) < 1.5 || Norm(p - Point3{ 2.0, 0.0, 0.0 }) < 1.5;
  };
  const TopologyRepairQueries twoBalls{ insideEither,
    [](const Point3& p) {
      return 1.5 - std::min(Norm(p - Point3{ -2.0, 0.0, 0.0 }), Norm(p - Point3{ 2.0, 0.0, 0.0 }));
    },
    CrossesBySampling(insideEither, 1000) };
  VoronoiMedialAxisResult result;
  AddDisk(result, 8, 0.5, { -2.0, 0.0, 0.0 });
  AddDisk(result, 8, 0.5, { 2.0, 0.0, 0.0 });
  result.Mesh.Edges = { { 0, 9 } }; // hub to hub
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 2, 0 }, twoBalls);
  EXPECT_EQ(counts.EdgesAcrossSurface, 1u);
  EXPECT_EQ(counts.JoinedPieces, 0u);
  EXPECT_TRUE(result.Mesh.Edges.empty());
  EXPECT_EQ(Pieces(result.Mesh), 2u);
  EXPECT_EQ(result.Mesh.Faces.size(), 16u);
}

TEST(MedialTopologyRepair, TestsOnlyEdgesTheBallsFreeOfSurfaceLeaveOpen)
{
  // The same two balls, with the distance to their surface as the lower
  // bound: every disk edge (at most 0.5 long, its ends 1 or more deep) is
  // covered by its ends' balls and skips the segment test; the edge from
  // hub to hub (4 long, its ends 1.5 deep) is tested, and goes.
  auto depth = [](const Point3& p) {
    return 1.5 - std::min(Norm(p - Point3{ -2.0, 0.0, 0.0 }), Norm(p - Point3{ 2.0, 0.0, 0.0 }));
  };
  std::size_t tests = 0;
  TopologyRepairQueries twoBalls{ [depth](const Point3& p) { return depth(p) > 0.0; }, depth,
    [&tests, depth](const Point3& a, const Point3& b)
    {
      ++tests;
      for (int k = 0; k <= 1000; ++k)
      {
        if (depth(a + (k / 1000.0) * (b - a)) <= 0.0)
        {
          return true;
        }
      }
      return false;
    },
    {} };
  VoronoiMedialAxisResult result;
  AddDisk(result, 8, 0.5, { -2.0, 0.0, 0.0 });
  AddDisk(result, 8, 0.5, { 2.0, 0.0, 0.0 });
  result.Mesh.Edges = { { 0, 9 } };
  twoBalls.DistanceLowerBound = [&result, depth](Index v) { return depth(result.Mesh.Centers[v]); };
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 2, 0 }, twoBalls);
  EXPECT_EQ(tests, 1u);
  EXPECT_EQ(counts.EdgesAcrossSurface, 1u);
  EXPECT_TRUE(result.Mesh.Edges.empty());
  EXPECT_EQ(Pieces(result.Mesh), 2u);
}

TEST(MedialTopologyRepair, CapsTwoLoopsThatShareEdges)
{
  // Two open tubes side by side, sharing the column of edges where they
  // touch: one piece with two loops, both spurious in a ball. Both go, and
  // the caps leave a valid complex.
  VoronoiMedialAxisResult result;
  constexpr int n = 8;
  std::vector<Index> low[2], high[2];
  for (int tube = 0; tube < 2; ++tube)
  {
    const double cx = tube == 0 ? -1.0 : 1.0;
    for (int k = 0; k < n; ++k)
    {
      // Tube 0's angle 0 and tube 1's angle pi are the same place: shared.
      if (tube == 1 && k == n / 2)
      {
        low[1].push_back(low[0][0]);
        high[1].push_back(high[0][0]);
        continue;
      }
      const double a = 2.0 * 3.14159265358979 * k / n;
      low[tube].push_back(AddVertex(result, { cx + std::cos(a), std::sin(a), 0.0 }));
      high[tube].push_back(AddVertex(result, { cx + std::cos(a), std::sin(a), 1.0 }));
    }
    for (int k = 0; k < n; ++k)
    {
      const int j = (k + 1) % n;
      AddFace(result, low[tube][k], low[tube][j], high[tube][j]);
      AddFace(result, low[tube][k], high[tube][j], high[tube][k]);
    }
  }
  ASSERT_EQ(EulerCharacteristic(result.Mesh), -1); // one piece, two loops
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 1, 0 }, BigBall());
  EXPECT_EQ(counts.FilledHoles, 2u);
  EXPECT_EQ(EulerCharacteristic(result.Mesh), 1);
  EXPECT_TRUE(ValidateMedialMesh(result.Mesh).IsValid());
}

TEST(MedialTopologyRepair, CapsALoopBentRoundAConcavePartInSeveralFans)
{
  // A C-shaped slab (radii 4 to 6 round the z axis, angles within 150
  // degrees of the x axis, |z| < 1) and, inside it, a band of quads whose
  // two rims follow the C: a spurious loop in a solid of genus 0. No point
  // sees a whole rim without leaving the slab (segments across the C's
  // mouth or its inner side leave it), so the rim is capped by fans over the
  // parts that chords inside the slab split it into.
  const double degree = 3.14159265358979 / 180.0;
  auto inside = [degree](const Point3& p)
  {
    const double rho = std::hypot(p[0], p[1]);
    return rho > 4.0 && rho < 6.0 && std::abs(p[2]) < 1.0 &&
      std::abs(std::atan2(p[1], p[0])) < 150.0 * degree;
  };
  std::size_t outside = 0; // cap vertices the test finds outside the slab
  const TopologyRepairQueries slab{ inside,
    [](const Point3& p)
    {
      const double rho = std::hypot(p[0], p[1]);
      return std::min({ rho - 4.0, 6.0 - rho, 1.0 - std::abs(p[2]) });
    },
    CrossesBySampling(inside, 2000) };
  std::vector<Point3> path;
  for (int a = -140; a <= 140; a += 10)
  {
    path.push_back({ 4.5 * std::cos(a * degree), 4.5 * std::sin(a * degree), 0.0 });
  }
  for (int a = 140; a >= -140; a -= 10)
  {
    path.push_back({ 5.5 * std::cos(a * degree), 5.5 * std::sin(a * degree), 0.0 });
  }
  VoronoiMedialAxisResult result;
  std::vector<Index> low, high;
  for (const Point3& p : path)
  {
    low.push_back(AddVertex(result, p + Point3{ 0.0, 0.0, -0.5 }));
    high.push_back(AddVertex(result, p + Point3{ 0.0, 0.0, 0.5 }));
  }
  const std::size_t n = path.size();
  for (std::size_t k = 0; k < n; ++k)
  {
    const std::size_t j = (k + 1) % n;
    AddFace(result, low[k], low[j], high[j]);
    AddFace(result, low[k], high[j], high[k]);
  }
  ASSERT_EQ(EulerCharacteristic(result.Mesh), 0);
  const std::size_t before = result.Mesh.Centers.size();
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 1, 0 }, slab);
  const std::size_t hubs = result.Mesh.Centers.size() - before;
  for (std::size_t v = before; v < result.Mesh.Centers.size(); ++v)
  {
    outside += inside(result.Mesh.Centers[v]) ? 0 : 1;
  }
  std::cout << counts.FilledHoles << " loop capped with " << hubs << " fans\n";
  EXPECT_EQ(counts.FilledHoles, 1u);
  EXPECT_GT(hubs, 1u);
  EXPECT_EQ(outside, 0u);
  EXPECT_EQ(EulerCharacteristic(result.Mesh), 1);
  EXPECT_TRUE(ValidateMedialMesh(result.Mesh).IsValid()) << ValidateMedialMesh(result.Mesh).Message;
}

TEST(MedialTopologyRepair, CapsALoopRoundAPocketWithACupPastItsTip)
{
  // A slab (|x|, |y| < 5, |z| < 1) with a conical pocket from its top face
  // (radius 0.5 there) down to a tip at z = -0.9, 0.1 above the bottom face,
  // and round the pocket a tube (radius 1, |z| < 0.5): a spurious loop in a
  // solid of genus 0. Every flat disk on a rim crosses the pocket; a cup
  // whose hub lies in the thin wall under the tip (which the complex does
  // not reach) closes it.
  auto inPocket = [](const Point3& p)
  { return p[2] > -0.9 && std::hypot(p[0], p[1]) < 0.5 * (p[2] + 0.9) / 1.9; };
  auto inside = [inPocket](const Point3& p)
  { return std::abs(p[0]) < 5.0 && std::abs(p[1]) < 5.0 && std::abs(p[2]) < 1.0 && !inPocket(p); };
  const TopologyRepairQueries slab{ inside, [](const Point3& p) { return 1.0 - std::abs(p[2]); },
    CrossesBySampling(inside, 2000) };
  VoronoiMedialAxisResult result;
  AddTube(result, 16, 1.0, -0.5);
  ASSERT_EQ(EulerCharacteristic(result.Mesh), 0);
  const std::size_t before = result.Mesh.Centers.size();
  const TopologyRepairCounts counts = RepairMedialTopology(result, { 1, 0 }, slab);
  EXPECT_EQ(counts.FilledHoles, 1u);
  EXPECT_EQ(EulerCharacteristic(result.Mesh), 1);
  ASSERT_EQ(result.Mesh.Centers.size(), before + 1);
  const Point3 hub = result.Mesh.Centers.back();
  std::cout << "cup hub at (" << hub[0] << ", " << hub[1] << ", " << hub[2] << ")\n";
  EXPECT_TRUE(inside(hub));
  EXPECT_LT(hub[2], -0.9); // past the tip
  EXPECT_TRUE(ValidateMedialMesh(result.Mesh).IsValid()) << ValidateMedialMesh(result.Mesh).Message;
}

namespace
{
// Whether any of the triangles from `first` on survives peeling `faces`
// (removing, until none is left, every triangle with an edge on no other
// live triangle), by the definition: the reference for CapPeeler.
bool SurvivesPeelingFromScratch(const std::vector<std::array<Index, 3>>& faces, std::size_t first)
{
  std::vector<char> alive(faces.size(), 1);
  for (bool removed = true; removed;)
  {
    removed = false;
    std::map<std::pair<Index, Index>, int> count;
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
      for (int k = 0; alive[f] && k < 3; ++k)
      {
        ++count[std::minmax(faces[f][k], faces[f][(k + 1) % 3])];
      }
    }
    for (std::size_t f = 0; f < faces.size(); ++f)
    {
      for (int k = 0; alive[f] && k < 3; ++k)
      {
        if (count[std::minmax(faces[f][k], faces[f][(k + 1) % 3])] == 1)
        {
          alive[f] = 0;
          removed = true;
        }
      }
    }
  }
  return std::any_of(
    alive.begin() + static_cast<std::ptrdiff_t>(first), alive.end(), [](char a) { return a != 0; });
}
}

TEST(CapPeeling, AgreesWithPeelingTheCappedComplexFromScratch)
{
  // The surface of a 4 x 4 x 8 box in unit squares with three windows (in
  // its top, its bottom and one side high up) and loops round it: rings at
  // heights 1, 2 and 3 and the windows' rims. Capped one after the other
  // where the cap closes no void, each answer depends on the caps before.
  constexpr int width = 4, height = 8;
  MedialMesh mesh;
  std::map<std::array<int, 3>, Index> id;
  auto vertex = [&](int x, int y, int z)
  {
    const auto [it, added] = id.emplace(std::array<int, 3>{ x, y, z }, 0);
    if (added)
    {
      it->second = static_cast<Index>(mesh.Centers.size());
      mesh.Centers.push_back({ double(x), double(y), double(z) });
      mesh.Radii.push_back(0.1);
    }
    return it->second;
  };
  auto quad = [&](Index a, Index b, Index c, Index d)
  {
    mesh.Faces.push_back({ a, b, c });
    mesh.Faces.push_back({ a, c, d });
  };
  auto window = [](int u, int v, int lo, int hi) { return u >= lo && u < hi && v >= lo && v < hi; };
  for (int u = 0; u < width; ++u)
  {
    for (int v = 0; v < width; ++v)
    {
      if (!window(u, v, 1, 3)) // top and bottom, each with a 2 x 2 window
      {
        quad(vertex(u, v, height), vertex(u + 1, v, height), vertex(u + 1, v + 1, height),
          vertex(u, v + 1, height));
        quad(vertex(u, v, 0), vertex(u, v + 1, 0), vertex(u + 1, v + 1, 0), vertex(u + 1, v, 0));
      }
    }
  }
  for (int z = 0; z < height; ++z)
  {
    for (int u = 0; u < width; ++u)
    {
      quad(vertex(u, 0, z), vertex(u + 1, 0, z), vertex(u + 1, 0, z + 1), vertex(u, 0, z + 1));
      quad(vertex(u, width, z), vertex(u, width, z + 1), vertex(u + 1, width, z + 1),
        vertex(u + 1, width, z));
      quad(vertex(width, u, z), vertex(width, u + 1, z), vertex(width, u + 1, z + 1),
        vertex(width, u, z + 1));
      if (!(u >= 1 && u < 3 && z >= 5 && z < 7)) // the side window, on x = 0
      {
        quad(vertex(0, u, z), vertex(0, u, z + 1), vertex(0, u + 1, z + 1), vertex(0, u + 1, z));
      }
    }
  }
  // A square ring, counter-clockwise: `square(t)` walks its perimeter.
  auto ring = [&](int lo, int hi, auto&& square)
  {
    std::vector<Index> loop;
    for (int t = lo; t < hi; ++t)
      loop.push_back(square(t, lo));
    for (int t = lo; t < hi; ++t)
      loop.push_back(square(hi, t));
    for (int t = hi; t > lo; --t)
      loop.push_back(square(t, hi));
    for (int t = hi; t > lo; --t)
      loop.push_back(square(lo, t));
    return loop;
  };
  auto atHeight = [&](int z)
  { return ring(0, width, [&, z](int x, int y) { return vertex(x, y, z); }); };
  const std::vector<Index> top = ring(1, 3, [&](int x, int y) { return vertex(x, y, height); });
  const std::vector<Index> bottom = ring(1, 3, [&](int x, int y) { return vertex(x, y, 0); });
  const std::vector<Index> side = ring(1, 3, [&](int y, int z) { return vertex(0, y, z + 4); });
  const std::size_t nv = mesh.Centers.size();

  repair::CapPeeler peeler(mesh);
  EXPECT_TRUE(peeler.PeelsAway());
  std::vector<std::array<Index, 3>> complex = mesh.Faces; // with the caps made
  Index hub = static_cast<Index>(nv);
  std::vector<int> answers;
  for (const std::vector<Index>& loop :
    { top, atHeight(2), bottom, atHeight(1), side, atHeight(3) })
  {
    std::vector<std::array<Index, 3>> capped = complex;
    for (std::size_t k = 0; k < loop.size(); ++k)
    {
      capped.push_back({ hub, loop[k], loop[(k + 1) % loop.size()] });
    }
    const bool closes = SurvivesPeelingFromScratch(capped, complex.size());
    EXPECT_EQ(peeler.CapClosesVoid(loop), closes) << "loop " << answers.size();
    answers.push_back(closes ? 1 : 0);
    if (!closes)
    {
      peeler.AddCap(loop);
      complex = capped;
      ++hub;
    }
  }
  // The top, then the ring at height 2 (the side window still open):
  // nothing closed; every later cap closes a void with those two.
  EXPECT_EQ(answers, (std::vector<int>{ 0, 0, 1, 1, 1, 1 }));
  EXPECT_TRUE(peeler.PeelsAway()); // the side window is still open
}
