// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/ShellOrientation.h"

#include "Mesh/TriangleAdjacency.h"
#include "Support/DisjointSets.h"

#include <utility>

namespace medialaxis
{
EdgePairing PairTriangleEdges(const std::vector<Triangle>& triangles)
{
  const std::vector<HalfEdge> halfEdges = SortedHalfEdges(triangles);
  EdgePairing pairing;
  pairing.Adjacencies.reserve(halfEdges.size() / 2);
  for (std::size_t i = 0; i < halfEdges.size();)
  {
    std::size_t j = i + 1;
    while (j < halfEdges.size() && halfEdges[j].Lo == halfEdges[i].Lo &&
      halfEdges[j].Hi == halfEdges[i].Hi)
    {
      ++j;
    }
    if (j - i == 1)
    {
      ++pairing.BoundaryEdges;
    }
    else if (j - i > 2)
    {
      ++pairing.NonManifoldEdges;
    }
    else
    {
      pairing.Adjacencies.push_back({ halfEdges[i].Tri, halfEdges[i + 1].Tri, halfEdges[i].Lo,
        halfEdges[i].Hi, halfEdges[i].Forward != halfEdges[i + 1].Forward });
    }
    i = j;
  }
  return pairing;
}

std::size_t CountNonManifoldVertices(const std::vector<Triangle>& triangles,
  const std::vector<EdgeAdjacency>& adjacencies, std::size_t pointCount)
{
  DisjointSets corners(3 * triangles.size());
  auto cornerOf = [&triangles](Index t, Index v)
  {
    const Triangle& tri = triangles[t];
    return 3 * t + (tri[0] == v ? 0 : (tri[1] == v ? 1 : 2));
  };
  for (const EdgeAdjacency& adj : adjacencies)
  {
    corners.Union(cornerOf(adj.A, adj.U), cornerOf(adj.B, adj.U));
    corners.Union(cornerOf(adj.A, adj.V), cornerOf(adj.B, adj.V));
  }
  std::vector<Index> fanRoot(pointCount, -1);
  std::vector<char> counted(pointCount, 0);
  std::size_t nonManifold = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      const Index v = triangles[t][k];
      const Index root = corners.Find(static_cast<Index>(3 * t + k));
      if (fanRoot[v] < 0)
      {
        fanRoot[v] = root;
      }
      else if (fanRoot[v] != root && !counted[v])
      {
        counted[v] = 1;
        ++nonManifold;
      }
    }
  }
  return nonManifold;
}

ShellOrientation OrientShells(
  std::size_t triangleCount, const std::vector<EdgeAdjacency>& adjacencies)
{
  const std::size_t nt = triangleCount;
  // Each triangle's neighbours, in the order of `adjacencies` (one flat
  // array: a list per triangle costs an allocation each).
  std::vector<std::size_t> firstNeighbour(nt + 1, 0);
  for (const EdgeAdjacency& adj : adjacencies)
  {
    ++firstNeighbour[adj.A + 1];
    ++firstNeighbour[adj.B + 1];
  }
  for (std::size_t t = 0; t < nt; ++t)
  {
    firstNeighbour[t + 1] += firstNeighbour[t];
  }
  std::vector<std::pair<Index, bool>> neighbourList(firstNeighbour[nt]);
  {
    std::vector<std::size_t> next(firstNeighbour.begin(), firstNeighbour.end() - 1);
    for (const EdgeAdjacency& adj : adjacencies)
    {
      neighbourList[next[adj.A]++] = { adj.B, adj.Consistent };
      neighbourList[next[adj.B]++] = { adj.A, adj.Consistent };
    }
  }
  ShellOrientation shells;
  std::vector<Index>& component = shells.Component;
  std::vector<char>& flip = shells.Flip;
  std::vector<std::vector<Index>>& members = shells.Members;
  component.assign(nt, -1);
  flip.assign(nt, 0);
  for (std::size_t seed = 0; seed < nt; ++seed)
  {
    if (component[seed] >= 0)
    {
      continue;
    }
    const Index id = static_cast<Index>(members.size());
    members.emplace_back();
    std::vector<Index> queue{ static_cast<Index>(seed) };
    component[seed] = id;
    for (std::size_t head = 0; head < queue.size(); ++head)
    {
      const Index t = queue[head];
      members[id].push_back(t);
      for (std::size_t e = firstNeighbour[t]; e < firstNeighbour[t + 1]; ++e)
      {
        const auto& [n, consistent] = neighbourList[e];
        const char wanted = flip[t] ^ (consistent ? 0 : 1);
        if (component[n] < 0)
        {
          component[n] = id;
          flip[n] = wanted;
          queue.push_back(n);
        }
        else if (flip[n] != wanted)
        {
          ++shells.NonOrientable;
        }
      }
    }
    // Flip the smaller side so that the reported count is the real defect.
    std::size_t flipped = 0;
    for (Index t : members[id])
    {
      flipped += flip[t];
    }
    if (2 * flipped > members[id].size())
    {
      for (Index t : members[id])
      {
        flip[t] ^= 1;
      }
      flipped = members[id].size() - flipped;
    }
    shells.Flipped += flipped;
  }
  return shells;
}
}
