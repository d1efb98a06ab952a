// SPDX-License-Identifier: GPL-3.0-or-later
#include "Simplification/HairErosion.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>

#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

namespace medialaxis
{
namespace
{
// The sorted intersection of the sorted ranges [a0, a1) and [b0, b1) into
// out (the Atlases are short: a few sites each).
template <typename A, typename B>
void Intersect(A a0, A a1, B b0, B b1, std::vector<Index>& out)
{
  out.clear();
  std::set_intersection(a0, a1, b0, b1, std::back_inserter(out));
}

// The longest distance between two sites shared by the Atlases of a
// triangle's three vertices (-1 when fewer than two are shared). `ab` and
// `common` are scratch.
double DualSpan(const AtlasMedialMesh& mesh, const std::array<Index, 3>& t,
  const std::vector<Point3>& sites, std::vector<Index>& ab, std::vector<Index>& common)
{
  const auto begin = [&mesh](Index v) { return mesh.AtlasSites.begin() + mesh.AtlasOffsets[v]; };
  const auto end = [&mesh](Index v) { return mesh.AtlasSites.begin() + mesh.AtlasOffsets[v + 1]; };
  Intersect(begin(t[0]), end(t[0]), begin(t[1]), end(t[1]), ab);
  Intersect(ab.begin(), ab.end(), begin(t[2]), end(t[2]), common);
  double span = -1.0;
  for (std::size_t i = 0; i < common.size(); ++i)
  {
    for (std::size_t j = i + 1; j < common.size(); ++j)
    {
      span = std::max(span, std::sqrt(Distance2(sites[common[i]], sites[common[j]])));
    }
  }
  return span;
}

// One side of a triangle or a line of the mesh, keyed by its sorted ends.
struct EdgeUse
{
  std::uint64_t Key; // min << 32 | max
  std::int32_t Face; // -1: a line
  std::int32_t Side; // the triangle's side k (from corner k to k + 1)
  bool operator<(const EdgeUse& o) const
  {
    return Key != o.Key ? Key < o.Key : (Face != o.Face ? Face < o.Face : Side < o.Side);
  }
};

std::uint64_t EdgeKey(Index u, Index v)
{
  return static_cast<std::uint64_t>(std::min(u, v)) << 32 |
    static_cast<std::uint64_t>(std::max(u, v));
}

// Sorts the uses as std::sort would, in linear time: each into the bucket
// of its smaller end (a counting sort), then each bucket (a few uses) on
// its own.
void SortUses(std::vector<EdgeUse>& uses, std::size_t nv)
{
  std::vector<std::size_t> start(nv + 1, 0);
  for (const EdgeUse& u : uses)
  {
    const std::uint64_t smaller = u.Key >> 32;
    if (smaller >= nv)
    {
      tbb::parallel_sort(uses.begin(), uses.end()); // (ids outside the vertices)
      return;
    }
    ++start[smaller + 1];
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    start[v + 1] += start[v];
  }
  std::vector<EdgeUse> sorted(uses.size());
  {
    std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
    for (const EdgeUse& u : uses)
    {
      sorted[cursor[u.Key >> 32]++] = u;
    }
  }
  std::vector<EdgeUse>().swap(uses);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, 4096),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      for (std::size_t v = range.begin(); v != range.end(); ++v)
      {
        std::sort(sorted.begin() + static_cast<std::ptrdiff_t>(start[v]),
          sorted.begin() + static_cast<std::ptrdiff_t>(start[v + 1]));
      }
    });
  uses.swap(sorted);
}
}

HairErosionResult ErodeHair(
  AtlasMedialMesh& mesh, const std::vector<Point3>& sites, double angleDegrees)
{
  HairErosionResult result;
  MedialMesh& m = mesh.Mesh;
  const std::size_t nv = m.NumberOfVertices(), nf = m.Faces.size();
  if (nf == 0 || !(angleDegrees > 0.0) || mesh.AtlasOffsets.size() != nv + 1)
  {
    return result;
  }
  // The chord p - q subtends the angle at a ball's centre when |p - q| =
  // 2 r sin(angle / 2).
  const double chord = 2.0 * std::sin(0.5 * std::min(angleDegrees, 180.0) * Pi / 180.0);
  // Every distinct edge, numbered in the order of its sorted ends; on each,
  // its line (if any) then its faces in increasing order. Unique sort keys:
  // the parallel sort gives the same order at any thread count.
  std::vector<EdgeUse> uses;
  uses.reserve(3 * nf + m.Edges.size());
  for (std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = m.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      uses.push_back({ EdgeKey(t[k], t[(k + 1) % 3]), static_cast<std::int32_t>(f), k });
    }
  }
  for (const auto& e : m.Edges)
  {
    uses.push_back({ EdgeKey(e[0], e[1]), -1, 0 });
  }
  SortUses(uses, nv);
  std::vector<std::array<Index, 2>> edges;
  std::vector<int> faceCount;            // alive faces on each edge
  std::vector<char> edgeAlive, erodible; // erodible: not a line of the input
  std::vector<std::array<Index, 3>> faceEdges(nf);
  std::vector<Index> edgeFaceStart{ 0 }, edgeFaces; // every face of each edge
  edgeFaces.reserve(3 * nf);
  // Most edges are on two faces: reserved for about that many.
  const std::size_t edgeGuess = 3 * nf / 2 + m.Edges.size() + 1;
  edges.reserve(edgeGuess);
  faceCount.reserve(edgeGuess);
  edgeAlive.reserve(edgeGuess);
  erodible.reserve(edgeGuess);
  edgeFaceStart.reserve(edgeGuess + 1);
  for (std::size_t i = 0; i < uses.size();)
  {
    const Index id = static_cast<Index>(edges.size());
    int faces = 0;
    std::size_t j = i;
    for (; j < uses.size() && uses[j].Key == uses[i].Key; ++j)
    {
      if (uses[j].Face >= 0)
      {
        faceEdges[uses[j].Face][uses[j].Side] = id;
        edgeFaces.push_back(uses[j].Face);
        ++faces;
      }
    }
    edges.push_back(
      { static_cast<Index>(uses[i].Key >> 32), static_cast<Index>(uses[i].Key & 0xffffffffu) });
    faceCount.push_back(faces);
    edgeAlive.push_back(1);
    erodible.push_back(faces > 0 ? 1 : 0);
    edgeFaceStart.push_back(static_cast<Index>(edgeFaces.size()));
    i = j;
  }
  std::vector<EdgeUse>().swap(uses);
  std::vector<int> degree(nv, 0); // alive edges at each vertex
  // Each vertex's edges in increasing order (compressed rows).
  std::vector<Index> vertexEdgeStart(nv + 1, 0), vertexEdges(2 * edges.size());
  for (const auto& e : edges)
  {
    ++degree[e[0]];
    ++degree[e[1]];
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    vertexEdgeStart[v + 1] = vertexEdgeStart[v] + degree[v];
  }
  {
    std::vector<Index> fill(vertexEdgeStart.begin(), vertexEdgeStart.end() - 1);
    for (std::size_t e = 0; e < edges.size(); ++e)
    {
      for (Index v : edges[e])
      {
        vertexEdges[fill[v]++] = static_cast<Index>(e);
      }
    }
  }
  std::vector<char> hair(nf, 0), faceAlive(nf, 1), vertexAlive(nv, 1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nf, 4096),
    [&](const tbb::blocked_range<std::size_t>& range)
    {
      std::vector<Index> ab, common;
      for (std::size_t f = range.begin(); f != range.end(); ++f)
      {
        const auto& t = m.Faces[f];
        const double span = DualSpan(mesh, t, sites, ab, common);
        const double radius = std::max({ m.Radii[t[0]], m.Radii[t[1]], m.Radii[t[2]] });
        hair[f] = span >= 0.0 && span < chord * radius ? 1 : 0;
      }
    });
  // The Atlases as given, except for the vertices a line end was collapsed
  // into (merged) or from (emptied).
  std::vector<std::vector<Index>> merged(nv);
  std::vector<char> ownAtlas(nv, 0);
  const auto atlasBegin = [&](Index v)
  { return ownAtlas[v] ? merged[v].data() : mesh.AtlasSites.data() + mesh.AtlasOffsets[v]; };
  const auto atlasEnd = [&](Index v)
  {
    return ownAtlas[v] ? merged[v].data() + merged[v].size()
                       : mesh.AtlasSites.data() + mesh.AtlasOffsets[v + 1];
  };

  std::deque<Index> faceQueue, edgeQueue;
  for (std::size_t f = 0; f < nf; ++f)
  {
    if (hair[f])
    {
      faceQueue.push_back(static_cast<Index>(f));
    }
  }
  // A line left by the erosion with an end on nothing else goes too, its
  // end's Atlas passed to the other end.
  std::vector<Index> both;
  auto erodeLine = [&](Index e)
  {
    if (!edgeAlive[e] || !erodible[e] || faceCount[e] != 0)
    {
      return;
    }
    for (int k = 0; k < 2; ++k)
    {
      const Index v = edges[e][k], w = edges[e][1 - k];
      if (degree[v] == 1 && degree[w] > 1)
      {
        edgeAlive[e] = 0;
        --degree[v];
        --degree[w];
        vertexAlive[v] = 0;
        ++result.RemovedVertices;
        // (w's previous list, swapped out, is the next union's room.)
        both.clear();
        std::set_union(
          atlasBegin(w), atlasEnd(w), atlasBegin(v), atlasEnd(v), std::back_inserter(both));
        merged[w].swap(both);
        ownAtlas[w] = 1;
        std::vector<Index>().swap(merged[v]);
        ownAtlas[v] = 1;
        // Only the edges erodeLine may take: no face goes while the edge
        // queue has entries, so the others would be passed over.
        for (Index k = vertexEdgeStart[w]; k < vertexEdgeStart[w + 1]; ++k)
        {
          const Index next = vertexEdges[k];
          if (edgeAlive[next] && erodible[next] && faceCount[next] == 0)
          {
            edgeQueue.push_back(next);
          }
        }
        return;
      }
    }
  };
  while (!faceQueue.empty() || !edgeQueue.empty())
  {
    if (!edgeQueue.empty())
    {
      const Index e = edgeQueue.front();
      edgeQueue.pop_front();
      erodeLine(e);
      continue;
    }
    const Index f = faceQueue.front();
    faceQueue.pop_front();
    if (!faceAlive[f])
    {
      continue;
    }
    int free = -1;
    for (int k = 0; k < 3; ++k)
    {
      if (faceCount[faceEdges[f][k]] == 1)
      {
        free = k;
        break;
      }
    }
    if (free < 0)
    {
      continue; // queued again when a neighbour goes
    }
    // No edge of f may be left bare unless it then erodes too (an end on
    // nothing else): a bare edge between two parts of the complex would
    // pinch the sheets into lines.
    bool pinches = false;
    for (int k = 0; k < 3 && !pinches; ++k)
    {
      const Index e = faceEdges[f][k];
      if (k != free && faceCount[e] == 1)
      {
        const Index u = edges[e][0], v = edges[e][1];
        const Index freeEdge = faceEdges[f][free];
        const int du = degree[u] - (edges[freeEdge][0] == u || edges[freeEdge][1] == u ? 1 : 0);
        const int dv = degree[v] - (edges[freeEdge][0] == v || edges[freeEdge][1] == v ? 1 : 0);
        pinches = du > 1 && dv > 1;
      }
    }
    if (pinches)
    {
      continue;
    }
    // The elementary collapse of f through its free edge.
    faceAlive[f] = 0;
    ++result.RemovedTriangles;
    const Index freeEdge = faceEdges[f][free];
    edgeAlive[freeEdge] = 0;
    for (Index v : edges[freeEdge])
    {
      --degree[v];
    }
    for (int k = 0; k < 3; ++k)
    {
      const Index e = faceEdges[f][k];
      --faceCount[e];
      if (e == freeEdge)
      {
        continue;
      }
      if (faceCount[e] == 1)
      {
        for (Index g = edgeFaceStart[e]; g < edgeFaceStart[e + 1]; ++g)
        {
          if (faceAlive[edgeFaces[g]] && hair[edgeFaces[g]])
          {
            faceQueue.push_back(edgeFaces[g]);
          }
        }
      }
      else if (faceCount[e] == 0)
      {
        edgeQueue.push_back(e);
      }
    }
  }

  // The eroded mesh, renumbered.
  std::vector<Index> newId(nv, -1);
  AtlasMedialMesh out;
  const std::size_t keptVertices = nv - result.RemovedVertices;
  out.Mesh.Centers.reserve(keptVertices);
  out.Mesh.Radii.reserve(keptVertices);
  out.AtlasOffsets.reserve(keptVertices + 1);
  out.AtlasSites.reserve(mesh.AtlasSites.size());
  out.Mesh.Faces.reserve(nf - result.RemovedTriangles);
  if (!mesh.FeatureVertex.empty())
  {
    out.FeatureVertex.reserve(keptVertices);
  }
  if (mesh.SiteClearance.size() == nv)
  {
    out.SiteClearance.reserve(keptVertices);
  }
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (!vertexAlive[v])
    {
      continue;
    }
    newId[v] = static_cast<Index>(out.Mesh.Centers.size());
    out.Mesh.Centers.push_back(m.Centers[v]);
    out.Mesh.Radii.push_back(m.Radii[v]);
    out.AtlasSites.insert(out.AtlasSites.end(), atlasBegin(v), atlasEnd(v));
    out.AtlasOffsets.push_back(static_cast<Index>(out.AtlasSites.size()));
    if (!mesh.FeatureVertex.empty())
    {
      out.FeatureVertex.push_back(mesh.FeatureVertex[v]);
    }
    if (mesh.SiteClearance.size() == nv)
    {
      out.SiteClearance.push_back(mesh.SiteClearance[v]);
    }
  }
  for (std::size_t f = 0; f < nf; ++f)
  {
    if (faceAlive[f])
    {
      const auto& t = m.Faces[f];
      out.Mesh.Faces.push_back({ newId[t[0]], newId[t[1]], newId[t[2]] });
    }
  }
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    if (edgeAlive[e])
    {
      out.Mesh.Edges.push_back({ newId[edges[e][0]], newId[edges[e][1]] });
    }
  }
  mesh = std::move(out);
  return result;
}
}
