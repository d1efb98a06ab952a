// SPDX-License-Identifier: GPL-3.0-or-later
#include "Simplification/HairErosion.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <tuple>

namespace medialaxis
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

// The longest distance between two sites shared by the Atlases of a
// triangle's three vertices (-1 when fewer than two are shared).
double DualSpan(
  const AtlasMedialMesh& mesh, const std::array<Index, 3>& t, const std::vector<Point3>& sites)
{
  auto atlas = [&mesh](Index v)
  {
    return std::make_pair(mesh.AtlasSites.begin() + mesh.AtlasOffsets[v],
      mesh.AtlasSites.begin() + mesh.AtlasOffsets[v + 1]);
  };
  std::vector<Index> ab, common;
  const auto [a0, a1] = atlas(t[0]);
  const auto [b0, b1] = atlas(t[1]);
  const auto [c0, c1] = atlas(t[2]);
  std::set_intersection(a0, a1, b0, b1, std::back_inserter(ab));
  std::set_intersection(ab.begin(), ab.end(), c0, c1, std::back_inserter(common));
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
  // Every distinct edge, face edges first: (min, max, face or -1).
  std::vector<std::tuple<Index, Index, Index>> halfEdges;
  halfEdges.reserve(3 * nf + m.Edges.size());
  for (std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = m.Faces[f];
    for (int k = 0; k < 3; ++k)
    {
      const Index u = t[k], v = t[(k + 1) % 3];
      halfEdges.emplace_back(std::min(u, v), std::max(u, v), static_cast<Index>(f));
    }
  }
  for (const auto& e : m.Edges)
  {
    halfEdges.emplace_back(std::min(e[0], e[1]), std::max(e[0], e[1]), -1);
  }
  std::sort(halfEdges.begin(), halfEdges.end());
  std::vector<std::array<Index, 2>> edges;
  std::vector<int> faceCount;            // alive faces on each edge
  std::vector<char> edgeAlive, erodible; // erodible: not a line of the input
  std::vector<std::array<Index, 3>> faceEdges(nf);
  std::vector<Index> edgeFaceStart{ 0 }, edgeFaces; // every face of each edge
  for (std::size_t i = 0; i < halfEdges.size();)
  {
    std::size_t j = i;
    const Index id = static_cast<Index>(edges.size());
    int faces = 0;
    while (j < halfEdges.size() && std::get<0>(halfEdges[j]) == std::get<0>(halfEdges[i]) &&
      std::get<1>(halfEdges[j]) == std::get<1>(halfEdges[i]))
    {
      const Index f = std::get<2>(halfEdges[j]);
      if (f >= 0)
      {
        const auto& t = m.Faces[f];
        const Index u = std::get<0>(halfEdges[j]), v = std::get<1>(halfEdges[j]);
        for (int k = 0; k < 3; ++k)
        {
          if (std::min(t[k], t[(k + 1) % 3]) == u && std::max(t[k], t[(k + 1) % 3]) == v)
          {
            faceEdges[f][k] = id;
          }
        }
        edgeFaces.push_back(f);
        ++faces;
      }
      ++j;
    }
    edges.push_back({ std::get<0>(halfEdges[i]), std::get<1>(halfEdges[i]) });
    faceCount.push_back(faces);
    edgeAlive.push_back(1);
    erodible.push_back(faces > 0 ? 1 : 0);
    edgeFaceStart.push_back(static_cast<Index>(edgeFaces.size()));
    i = j;
  }
  std::vector<int> degree(nv, 0); // alive edges at each vertex
  std::vector<std::vector<Index>> vertexEdges(nv);
  for (std::size_t e = 0; e < edges.size(); ++e)
  {
    for (Index v : edges[e])
    {
      ++degree[v];
      vertexEdges[v].push_back(static_cast<Index>(e));
    }
  }
  std::vector<char> hair(nf, 0), faceAlive(nf, 1), vertexAlive(nv, 1);
  for (std::size_t f = 0; f < nf; ++f)
  {
    const auto& t = m.Faces[f];
    const double span = DualSpan(mesh, t, sites);
    const double radius = std::max({ m.Radii[t[0]], m.Radii[t[1]], m.Radii[t[2]] });
    hair[f] = span >= 0.0 && span < chord * radius ? 1 : 0;
  }
  std::vector<std::vector<Index>> atlas(nv);
  for (std::size_t v = 0; v < nv; ++v)
  {
    atlas[v].assign(mesh.AtlasSites.begin() + mesh.AtlasOffsets[v],
      mesh.AtlasSites.begin() + mesh.AtlasOffsets[v + 1]);
  }

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
        std::vector<Index> merged;
        std::set_union(atlas[w].begin(), atlas[w].end(), atlas[v].begin(), atlas[v].end(),
          std::back_inserter(merged));
        atlas[w].swap(merged);
        std::vector<Index>().swap(atlas[v]);
        for (Index next : vertexEdges[w])
        {
          edgeQueue.push_back(next);
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
  for (std::size_t v = 0; v < nv; ++v)
  {
    if (!vertexAlive[v])
    {
      continue;
    }
    newId[v] = static_cast<Index>(out.Mesh.Centers.size());
    out.Mesh.Centers.push_back(m.Centers[v]);
    out.Mesh.Radii.push_back(m.Radii[v]);
    out.AtlasSites.insert(out.AtlasSites.end(), atlas[v].begin(), atlas[v].end());
    out.AtlasOffsets.push_back(static_cast<Index>(out.AtlasSites.size()));
    if (!mesh.FeatureVertex.empty())
    {
      out.FeatureVertex.push_back(mesh.FeatureVertex[v]);
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
