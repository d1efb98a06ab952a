// SPDX-License-Identifier: GPL-3.0-or-later
#include "Voronoi/MedialTopologyRepair.h"

#include "Geometry/KdTree.h"
#include "Geometry/Vec3.h"
#include "Mesh/MedialMesh.h"
#include "Support/DisjointSets.h"
#include "Voronoi/CapPeeling.h"
#include "Voronoi/ComplexLoops.h"
#include "Voronoi/LoopCaps.h"
#include "Voronoi/MedialComplexCleanup.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <tuple>

namespace medialaxis
{
namespace
{
using repair::BoundaryLoops;
using repair::CapPeeler;
using repair::CoreCycles;
using repair::CutLoops;
using repair::EdgeId;
using repair::EdgeKey;
using repair::Key;
using repair::LoopCap;

void AppendVertex(VoronoiMedialAxisResult& result, const Point3& centre, double radius,
  const std::vector<Index>& neighbours)
{
  std::vector<Index> atlas;
  for (Index v : neighbours)
  {
    atlas.insert(atlas.end(), result.AtlasSites.begin() + result.AtlasOffsets[v],
      result.AtlasSites.begin() + result.AtlasOffsets[v + 1]);
  }
  std::sort(atlas.begin(), atlas.end());
  atlas.erase(std::unique(atlas.begin(), atlas.end()), atlas.end());
  result.AtlasSites.insert(result.AtlasSites.end(), atlas.begin(), atlas.end());
  result.AtlasOffsets.push_back(static_cast<Index>(result.AtlasSites.size()));
  if (!result.SiteClearance.empty())
  {
    result.SiteClearance.push_back(-1.0);
  }
  result.Mesh.Centers.push_back(centre);
  result.Mesh.Radii.push_back(radius);
}

// 0. A medial edge that leaves the solid and comes back bridges two parts
// across the gap between them (a Delaunay cell spanning the gap had its
// circumcentre inside): it and the faces on it go, and so do the scraps
// of the bridge that this leaves on their own (pieces as small as the
// pockets VoronoiMedialAxis.cxx drops).
std::size_t DropEdgesAcrossSurface(VoronoiMedialAxisResult& result,
  const std::vector<EdgeKey>& edges, const TopologyRepairQueries& queries)
{
  MedialMesh& mesh = result.Mesh;
  // The two open balls free of surface at an edge's ends cover it when
  // they overlap: most edges inside thick parts need no segment test.
  std::vector<double> clear(mesh.Centers.size(), 0.0);
  if (queries.DistanceLowerBound)
  {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, clear.size(), 1024),
      [&](const tbb::blocked_range<std::size_t>& r)
      {
        for (std::size_t v = r.begin(); v != r.end(); ++v)
        {
          clear[v] = std::max(0.0, queries.DistanceLowerBound(static_cast<Index>(v)));
        }
      });
  }
  std::vector<char> across(edges.size(), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, edges.size(), 512),
    [&](const tbb::blocked_range<std::size_t>& r)
    {
      for (std::size_t e = r.begin(); e != r.end(); ++e)
      {
        // The open segment: an end may lie on the surface (radius 0).
        const Point3 &a = mesh.Centers[edges[e][0]], &b = mesh.Centers[edges[e][1]];
        if (Norm(b - a) < clear[edges[e][0]] + clear[edges[e][1]])
        {
          continue;
        }
        across[e] = queries.Crosses(a + 1e-6 * (b - a), b - 1e-6 * (b - a)) ? 1 : 0;
      }
    });
  const std::size_t count = static_cast<std::size_t>(std::count(across.begin(), across.end(), 1));
  if (count == 0)
  {
    return 0;
  }
  // Only an edge between two ends of edges across is looked up (a binary
  // search per triangle side was most of this step's time).
  std::vector<char> end(mesh.Centers.size(), 0);
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    if (across[e])
    {
      end[edges[e][0]] = end[edges[e][1]] = 1;
    }
  }
  auto isAcross = [&](Index a, Index b)
  { return end[a] && end[b] && across[EdgeId(edges, a, b)] != 0; };
  std::size_t out = 0;
  for (std::size_t f = 0; f < mesh.Faces.size(); ++f)
  {
    const auto& t = mesh.Faces[f];
    if (!isAcross(t[0], t[1]) && !isAcross(t[1], t[2]) && !isAcross(t[2], t[0]))
    {
      mesh.Faces[out] = t;
      result.FaceSitePair[out] = result.FaceSitePair[f];
      ++out;
    }
  }
  mesh.Faces.resize(out);
  result.FaceSitePair.resize(out);
  mesh.Edges.erase(std::remove_if(mesh.Edges.begin(), mesh.Edges.end(),
                     [&](const std::array<Index, 2>& e) { return isAcross(e[0], e[1]); }),
    mesh.Edges.end());
  DropSmallComponents(result, std::max<std::size_t>(2, mesh.Centers.size() / 1000));
  return count;
}

// 1. Pieces beyond the expected count are joined as in Kruskal's algorithm:
// of the pairs of close vertices in different pieces, shortest first, each
// whose segment stays inside the surface joins its two pieces. Also gives
// the number of loops left (pieces - Euler characteristic: no void is left).
std::size_t JoinPieces(VoronoiMedialAxisResult& result, const std::vector<EdgeKey>& edges,
  std::size_t expected, const TopologyRepairQueries& queries, long long& loops)
{
  MedialMesh& mesh = result.Mesh;
  const std::size_t nv = mesh.Centers.size();
  DisjointSets pieces(nv);
  for (const EdgeKey& e : edges)
  {
    pieces.Union(e[0], e[1]);
  }
  std::vector<std::size_t> size(nv, 0);
  std::size_t pieceCount = 0;
  for (std::size_t v = 0; v < nv; ++v)
  {
    const Index root = pieces.Find(static_cast<Index>(v));
    pieceCount += root == static_cast<Index>(v) ? 1 : 0;
    ++size[root];
  }
  // Joining two pieces adds an edge: the loops stay as they are.
  loops = static_cast<long long>(pieceCount) -
    (static_cast<long long>(nv) - static_cast<long long>(edges.size()) +
      static_cast<long long>(mesh.Faces.size()));
  if (pieceCount <= expected)
  {
    return 0;
  }
  const Index largest =
    static_cast<Index>(std::max_element(size.begin(), size.end()) - size.begin());
  std::map<Index, std::vector<Index>> smaller; // every other piece, by root (its smallest id)
  for (std::size_t v = 0; v < nv; ++v)
  {
    const Index root = pieces.Find(static_cast<Index>(v));
    if (root != largest)
    {
      smaller[root].push_back(static_cast<Index>(v));
    }
  }
  // For each smaller piece, the nearest vertices of all the others.
  // The closest vertices of other pieces are often in a neighbouring part,
  // across the surface: look a little further.
  constexpr std::size_t neighbours = 64; // candidates per vertex of a smaller piece
  std::vector<std::tuple<double, Index, Index>> pairs;
  std::vector<std::uint32_t> ids;
  std::vector<double> d2;
  std::vector<Point3> others;
  std::vector<Index> otherId;
  for (const auto& [root, members] : smaller)
  {
    others.clear();
    otherId.clear();
    for (std::size_t v = 0; v < nv; ++v)
    {
      if (pieces.Find(static_cast<Index>(v)) != root)
      {
        others.push_back(mesh.Centers[v]);
        otherId.push_back(static_cast<Index>(v));
      }
    }
    const KdTree tree(others);
    for (Index v : members)
    {
      tree.Nearest(mesh.Centers[v], neighbours, ids, d2);
      for (std::size_t k = 0; k < ids.size(); ++k)
      {
        const Index w = otherId[ids[k]];
        pairs.emplace_back(d2[k], std::min(v, w), std::max(v, w));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::size_t joined = 0;
  for (const auto& [length2, v, w] : pairs)
  {
    if (pieceCount <= expected)
    {
      break;
    }
    if (pieces.Find(v) != pieces.Find(w) && !queries.Crosses(mesh.Centers[v], mesh.Centers[w]))
    {
      pieces.Union(v, w);
      mesh.Edges.push_back({ v, w });
      --pieceCount;
      ++joined;
    }
  }
  return joined;
}

// 3. Caps `loops` (closed chains of edges of the complex), in order, where
// the cap is inside the surface and closes no void, `excess` times at most.
std::size_t CapLoops(VoronoiMedialAxisResult& result, const std::vector<std::vector<Index>>& loops,
  long long excess, const TopologyRepairQueries& queries, std::set<std::vector<Index>>& uncappable,
  std::unique_ptr<CapPeeler> peeler)
{
  MedialMesh& mesh = result.Mesh;
  std::size_t filled = 0;
  std::vector<EdgeKey> capped; // edges of caps so far, sorted
  for (const std::vector<Index>& loop : loops)
  {
    if (excess <= 0)
    {
      break;
    }
    bool open = true; // loops can share edges with a capped one
    for (std::size_t k = 0; open && k < loop.size(); ++k)
    {
      open = !std::binary_search(
        capped.begin(), capped.end(), Key(loop[k], loop[(k + 1) % loop.size()]));
    }
    if (!open)
    {
      continue;
    }
    // Whether a cap fits depends on the loop's vertices and the surface
    // alone: a loop found uncappable in one round is not searched again.
    std::vector<Index> canonical = loop;
    CanonicalCycle(canonical);
    if (uncappable.count(canonical))
    {
      continue;
    }
    LoopCap cap;
    if (!FindCap(mesh, loop, queries, cap))
    {
      uncappable.insert(std::move(canonical));
      continue;
    }
    if (!peeler)
    {
      peeler = std::make_unique<CapPeeler>(mesh);
    }
    if (peeler->CapClosesVoid(loop))
    {
      continue;
    }
    // (A cap split by chords peels as a fan over the whole loop would: both
    // are disks on the loop, so the peeler models it as that fan.)
    for (std::size_t h = 0; h < cap.Hubs.size(); ++h)
    {
      const std::vector<Index>& fan = cap.Fans[h];
      const Index hub = static_cast<Index>(mesh.Centers.size());
      for (std::size_t k = 0; k < fan.size(); ++k)
      {
        mesh.Faces.push_back({ hub, fan[k], fan[(k + 1) % fan.size()] });
      }
      AppendVertex(result, cap.Hubs[h], queries.Distance(cap.Hubs[h]), fan);
    }
    peeler->AddCap(loop); // the complex changed: later peels include the cap
    for (std::size_t k = 0; k < loop.size(); ++k)
    {
      capped.push_back(Key(loop[k], loop[(k + 1) % loop.size()]));
    }
    std::sort(capped.begin(), capped.end());
    result.FaceSitePair.resize(mesh.Faces.size(), { -1, -1 });
    ++filled;
    --excess;
  }
  return filled;
}
}

SurfaceTopology ComputeSurfaceTopology(const TriangleMesh& surface)
{
  const std::size_t np = surface.Points.size();
  DisjointSets pieces(np);
  std::vector<char> used(np, 0);
  std::vector<EdgeKey> edges;
  edges.reserve(3 * surface.Triangles.size());
  for (const Triangle& t : surface.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      used[t[k]] = 1;
      pieces.Union(t[k], t[(k + 1) % 3]);
      edges.push_back(Key(t[k], t[(k + 1) % 3]));
    }
  }
  SortEdgeKeys(edges);
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::vector<long long> euler(np, 0); // per piece, at its root: V - E + F
  for (std::size_t p = 0; p < np; ++p)
  {
    if (used[p])
    {
      ++euler[pieces.Find(static_cast<Index>(p))];
    }
  }
  for (const EdgeKey& e : edges)
  {
    --euler[pieces.Find(e[0])];
  }
  for (const Triangle& t : surface.Triangles)
  {
    ++euler[pieces.Find(t[0])];
  }
  SurfaceTopology topology;
  for (std::size_t p = 0; p < np; ++p)
  {
    if (used[p] && pieces.Find(static_cast<Index>(p)) == static_cast<Index>(p))
    {
      ++topology.Components;
      topology.Genus += std::max(0LL, (2 - euler[p]) / 2);
    }
  }
  return topology;
}

TopologyRepairCounts RepairMedialTopology(VoronoiMedialAxisResult& result,
  const SurfaceTopology& expected, const TopologyRepairQueries& queries)
{
  TopologyRepairCounts counts;
  if (result.Mesh.Centers.empty())
  {
    return counts;
  }
  std::vector<EdgeKey> edges = AllEdges(result.Mesh);
  counts.EdgesAcrossSurface = DropEdgesAcrossSurface(result, edges, queries);
  if (counts.EdgesAcrossSurface > 0)
  {
    edges = AllEdges(result.Mesh); // faces, edges and scraps went
  }
  long long loops = 0;
  counts.JoinedPieces =
    JoinPieces(result, edges, std::max<std::size_t>(1, expected.Components), queries, loops);
  std::vector<EdgeKey>().swap(edges); // the later steps build their own
  const long long excess = loops - expected.Genus;
  counts.MissingLoops = static_cast<std::size_t>(std::max(0LL, -excess));
  counts.CutLoops = CutLoops(result.Mesh, excess);
  // Holes in sheets first; then loops of any shape, e.g. round a tube.
  long long left = excess - static_cast<long long>(counts.CutLoops);
  std::set<std::vector<Index>> uncappable;
  if (left > 0)
  {
    // (The peeling is built on the first cap that needs it.)
    counts.FilledHoles =
      CapLoops(result, BoundaryLoops(result.Mesh), left, queries, uncappable, nullptr);
    left -= static_cast<long long>(counts.FilledHoles);
  }
  // A cycle that shares an edge with one just capped waits for the next
  // round, on the cycles of the complex as the caps left it.
  while (left > 0)
  {
    auto peeling = std::make_unique<CapPeeler>(result.Mesh);
    const std::vector<std::vector<Index>> cycles = CoreCycles(result.Mesh, *peeling);
    const std::size_t filled =
      CapLoops(result, cycles, left, queries, uncappable, std::move(peeling));
    if (filled == 0)
    {
      break;
    }
    counts.FilledHoles += filled;
    left -= static_cast<long long>(filled);
  }
  if (counts.FilledHoles > 0)
  {
    // The caps grew these by doubling: the spare room would stay reserved
    // through the simplification, which sets the pipeline's peak.
    result.Mesh.Centers.shrink_to_fit();
    result.Mesh.Radii.shrink_to_fit();
    result.Mesh.Faces.shrink_to_fit();
    result.AtlasOffsets.shrink_to_fit();
    result.AtlasSites.shrink_to_fit();
    result.FaceSitePair.shrink_to_fit();
    result.SiteClearance.shrink_to_fit();
  }
  return counts;
}
}
