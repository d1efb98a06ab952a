// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeletal/DualSkeleton.h"

#include <algorithm>
#include <limits>
#include <map>
#include <queue>
#include <set>
#include <tuple>

namespace medialaxis
{
MedialGraph BuildMedialGraph(const MedialMesh& medial)
{
  const MedialAdjacency adjacency = VertexAdjacency(medial);
  MedialGraph graph;
  graph.Neighbours.resize(medial.NumberOfVertices());
  for (std::size_t v = 0; v < graph.Neighbours.size(); ++v)
  {
    for (Index k = adjacency.Start[v]; k < adjacency.Start[v + 1]; ++k)
    {
      const Index w = adjacency.Next[k];
      graph.Neighbours[v].push_back({ w, Norm(medial.Centers[w] - medial.Centers[v]) });
    }
  }
  return graph;
}

SiteCells NearestSites(const MedialGraph& graph, const std::vector<Index>& sites)
{
  const std::size_t n = graph.Neighbours.size();
  SiteCells cells;
  cells.Owner.assign(n, -1);
  cells.Distance.assign(n, std::numeric_limits<double>::infinity());
  cells.Parent.assign(n, -1);
  // (distance, site position, vertex, the vertex it is reached from)
  using Entry = std::tuple<double, int, Index, Index>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (std::size_t s = 0; s < sites.size(); ++s)
  {
    queue.push({ 0.0, static_cast<int>(s), sites[s], -1 });
  }
  while (!queue.empty())
  {
    const auto [d, site, v, from] = queue.top();
    queue.pop();
    if (cells.Owner[v] >= 0)
    {
      continue;
    }
    cells.Owner[v] = site;
    cells.Distance[v] = d;
    cells.Parent[v] = from;
    for (const auto& [w, length] : graph.Neighbours[v])
    {
      if (cells.Owner[w] < 0)
      {
        queue.push({ d + length, site, w, v });
      }
    }
  }
  return cells;
}

DualSkeleton BuildDualSkeleton(const MedialMesh& medial, const TriangleLocator& locator,
  const std::vector<std::uint8_t>& bendable, const std::vector<Index>& sites,
  const SiteCells& cells)
{
  const std::vector<int>& owner = cells.Owner;
  // The cheapest medial edge where each pair of cells meets (the first one
  // on a tie), oriented from the smaller site position to the larger.
  std::map<std::array<Index, 2>, std::pair<double, std::array<Index, 2>>> meeting;
  for (const auto& e : AllEdges(medial))
  {
    const int a = owner[e[0]], b = owner[e[1]];
    if (a < 0 || b < 0 || a == b)
    {
      continue;
    }
    const double cost = cells.Distance[e[0]] + cells.Distance[e[1]] +
      Norm(medial.Centers[e[1]] - medial.Centers[e[0]]);
    const std::array<Index, 2> pair = { std::min<Index>(a, b), std::max<Index>(a, b) };
    const std::array<Index, 2> ends = a < b ? e : std::array<Index, 2>{ e[1], e[0] };
    const auto found = meeting.find(pair);
    if (found == meeting.end() || cost < found->second.first)
    {
      meeting[pair] = { cost, ends };
    }
  }

  auto chordInside = [&](Index u, Index v)
  {
    const Point3 d = medial.Centers[v] - medial.Centers[u];
    const double length = Norm(d);
    return length == 0.0 ||
      locator.FirstHit(medial.Centers[u], (1.0 / length) * d, 0.0, length).Triangle < 0;
  };

  DualSkeleton skeleton;
  for (const auto& [pair, cheapest] : meeting)
  {
    skeleton.Edges.push_back(pair);
    std::vector<Index>& route = skeleton.Routes.emplace_back();
    if (chordInside(sites[pair[0]], sites[pair[1]]))
    {
      route = { sites[pair[0]], sites[pair[1]] };
      continue;
    }
    std::vector<Index> path;
    for (Index v = cheapest.second[0]; v >= 0; v = cells.Parent[v])
    {
      path.push_back(v);
    }
    std::reverse(path.begin(), path.end());
    for (Index v = cheapest.second[1]; v >= 0; v = cells.Parent[v])
    {
      path.push_back(v);
    }
    route.push_back(path.front());
    for (std::size_t i = 0; i + 1 < path.size();)
    {
      std::size_t next = i + 1;
      for (std::size_t j = path.size() - 1; j > i + 1; --j)
      {
        if ((j + 1 == path.size() || bendable[path[j]]) && chordInside(path[i], path[j]))
        {
          next = j;
          break;
        }
      }
      route.push_back(path[next]);
      i = next;
    }
  }

  std::set<std::array<Index, 3>> triangles;
  for (const auto& f : medial.Faces)
  {
    std::array<Index, 3> c = { owner[f[0]], owner[f[1]], owner[f[2]] };
    std::sort(c.begin(), c.end());
    if (c[0] >= 0 && c[0] != c[1] && c[1] != c[2])
    {
      triangles.insert(c);
    }
  }
  skeleton.Triangles.assign(triangles.begin(), triangles.end());
  return skeleton;
}
}
