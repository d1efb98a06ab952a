// SPDX-License-Identifier: GPL-3.0-or-later
#include "Skeleton/SkeletonExport.h"

#include "Geometry/Vec3.h"

#include <cmath>
#include <cstdio>
#include <deque>
#include <sstream>
#include <vector>

namespace medialaxis
{
namespace
{
// Shortest round-trip text of a double.
std::string Number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

const char* TypeName(SkeletonNodeType t)
{
  switch (t)
  {
    case SkeletonNodeType::End:
      return "end";
    case SkeletonNodeType::Regular:
      return "regular";
    default:
      return "junction";
  }
}
}

std::string SkeletonToSwc(const CurveSkeleton& s, const std::string& header)
{
  std::ostringstream out;
  std::istringstream lines(header);
  for (std::string line; std::getline(lines, line);)
  {
    out << "# " << line << "\n";
  }
  out << "# id type x y z radius parent\n";
  const std::size_t n = s.Nodes.size();
  std::vector<std::vector<std::pair<Index, Index>>> incident(n); // (other node, edge)
  for (std::size_t e = 0; e < s.Edges.size(); ++e)
  {
    incident[s.Edges[e][0]].emplace_back(s.Edges[e][1], static_cast<Index>(e));
    incident[s.Edges[e][1]].emplace_back(s.Edges[e][0], static_cast<Index>(e));
  }
  // Roots: the node of largest radius of each piece (the lowest id on ties).
  std::vector<Index> piece(n, -1), order;
  std::vector<Index> roots;
  for (std::size_t v = 0; v < n; ++v)
  {
    if (piece[v] >= 0)
    {
      continue;
    }
    Index best = static_cast<Index>(v);
    std::deque<Index> queue{ static_cast<Index>(v) };
    piece[v] = static_cast<Index>(roots.size());
    while (!queue.empty())
    {
      const Index u = queue.front();
      queue.pop_front();
      if (s.Radii[u] > s.Radii[best])
      {
        best = u;
      }
      for (const auto& [w, e] : incident[u])
      {
        if (piece[w] < 0)
        {
          piece[w] = piece[v];
          queue.push_back(w);
        }
      }
    }
    roots.push_back(best);
  }
  // Breadth-first trees; SWC ids in the order written.
  std::vector<Index> swcId(n, 0), parent(n, -1);
  std::vector<char> treeEdge(s.Edges.size(), 0);
  Index next = 1;
  for (Index root : roots)
  {
    std::deque<Index> queue{ root };
    swcId[root] = next++;
    while (!queue.empty())
    {
      const Index u = queue.front();
      queue.pop_front();
      order.push_back(u);
      for (const auto& [w, e] : incident[u])
      {
        if (swcId[w] == 0)
        {
          swcId[w] = next++;
          parent[w] = u;
          treeEdge[e] = 1;
          queue.push_back(w);
        }
      }
    }
  }
  for (std::size_t e = 0; e < s.Edges.size(); ++e)
  {
    if (!treeEdge[e])
    {
      out << "# loop " << swcId[s.Edges[e][0]] << " " << swcId[s.Edges[e][1]] << "\n";
    }
  }
  for (Index u : order)
  {
    const Point3& p = s.Nodes[u];
    out << swcId[u] << " " << (parent[u] < 0 ? 1 : 0) << " " << Number(p[0]) << " " << Number(p[1])
        << " " << Number(p[2]) << " " << Number(s.Radii[u]) << " "
        << (parent[u] < 0 ? -1 : swcId[parent[u]]) << "\n";
  }
  return out.str();
}

std::string SkeletonToJson(const CurveSkeleton& s)
{
  std::ostringstream out;
  out << "{\n  \"nodes\": [";
  for (std::size_t v = 0; v < s.Nodes.size(); ++v)
  {
    const Point3& p = s.Nodes[v];
    out << (v ? ",\n    " : "\n    ") << "{\"id\": " << v << ", \"position\": [" << Number(p[0])
        << ", " << Number(p[1]) << ", " << Number(p[2]) << "], \"radius\": " << Number(s.Radii[v])
        << ", \"type\": \"" << TypeName(s.Types[v])
        << "\", \"branch\": " << (v < s.NodeBranch.size() ? s.NodeBranch[v] : -1) << "}";
  }
  out << "\n  ],\n  \"edges\": [";
  for (std::size_t e = 0; e < s.Edges.size(); ++e)
  {
    const auto& [a, b] = s.Edges[e];
    out << (e ? ",\n    " : "\n    ") << "{\"source\": " << a << ", \"target\": " << b
        << ", \"length\": " << Number(std::sqrt(Distance2(s.Nodes[a], s.Nodes[b]))) << "}";
  }
  out << "\n  ],\n  \"branches\": [";
  for (std::size_t b = 0; b < s.Branches.size(); ++b)
  {
    out << (b ? ", " : "") << "[";
    for (std::size_t i = 0; i < s.Branches[b].size(); ++i)
    {
      out << (i ? ", " : "") << s.Branches[b][i];
    }
    out << "]";
  }
  out << "],\n  \"cycle_rank\": " << s.CycleRank << ",\n  \"components\": " << s.Components
      << "\n}\n";
  return out.str();
}
}
