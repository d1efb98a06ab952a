// SPDX-License-Identifier: GPL-3.0-or-later
#include "Surface/DegenerateTriangles.h"

#include "Geometry/Vec3.h"
#include "Mesh/TriangleAdjacency.h"

#include <algorithm>
#include <utility>

namespace medialaxis
{
namespace
{
// A zero-area "needle": three distinct but (nearly) collinear vertices.
bool IsNeedle(const std::vector<Point3>& points, const Triangle& tri)
{
  const Point3 e0 = (points[tri[1]] - points[tri[0]]);
  const Point3 e1 = (points[tri[2]] - points[tri[0]]);
  const Point3 e2 = (points[tri[2]] - points[tri[1]]);
  const double longest = std::max({ Dot(e0, e0), Dot(e1, e1), Dot(e2, e2) });
  return Norm(Cross(e0, e1)) <= 1e-12 * longest;
}

// Replaces needles (common in CAD exports) by splitting the neighbour across
// their longest edge at the middle vertex, which keeps the surface closed.
// Returns the number of needles removed; unresolvable needles are kept.
std::size_t AbsorbNeedles(
  const std::vector<Point3>& points, std::vector<Triangle>& triangles, std::size_t& splitNeighbours)
{
  std::vector<std::size_t> needles;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (IsNeedle(points, triangles[t]))
    {
      needles.push_back(t);
    }
  }
  if (needles.empty())
  {
    return 0;
  }
  const auto halfEdges = SortedHalfEdges(triangles);
  std::vector<char> alive(triangles.size(), 1), touched(triangles.size(), 0);
  std::vector<Triangle> added;
  std::size_t removed = 0;
  for (std::size_t t : needles)
  {
    if (touched[t])
    {
      continue;
    }
    const Triangle tri = triangles[t];
    // Middle vertex c is opposite the longest edge (a, b).
    int longestK = 0;
    double longestLength = -1.0;
    for (int k = 0; k < 3; ++k)
    {
      const Point3 e = (points[tri[(k + 1) % 3]] - points[tri[k]]);
      if (Dot(e, e) > longestLength)
      {
        longestLength = Dot(e, e);
        longestK = k;
      }
    }
    const Index a = tri[longestK], b = tri[(longestK + 1) % 3], c = tri[(longestK + 2) % 3];
    const HalfEdge probe{ std::min(a, b), std::max(a, b), -1, false };
    auto first = std::lower_bound(halfEdges.begin(), halfEdges.end(), probe);
    std::vector<Index> others;
    for (auto it = first; it != halfEdges.end() && it->Lo == probe.Lo && it->Hi == probe.Hi; ++it)
    {
      if (it->Tri != static_cast<Index>(t))
      {
        others.push_back(it->Tri);
      }
    }
    if (others.size() != 1 || touched[others[0]])
    {
      continue;
    }
    const Index n = others[0];
    const Triangle nb = triangles[n];
    int pa = 0;
    while (pa < 3 && !(nb[pa] == a || nb[pa] == b))
    {
      ++pa;
    }
    // Neighbour in cyclic order (p, q, x) with {p, q} == {a, b}.
    Index p = nb[pa], q = nb[(pa + 1) % 3], x = nb[(pa + 2) % 3];
    if (!((q == a || q == b) && q != p))
    {
      p = nb[(pa + 2) % 3];
      q = nb[pa];
      x = nb[(pa + 1) % 3];
    }
    if (x == c)
    {
      continue; // the neighbour is the needle's mirror image; dedup handles it
    }
    alive[t] = 0;
    alive[n] = 0;
    touched[t] = touched[n] = 1;
    added.push_back({ p, c, x });
    added.push_back({ c, q, x });
    ++removed;
    ++splitNeighbours;
  }
  std::vector<Triangle> kept;
  kept.reserve(triangles.size() + added.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (alive[t])
    {
      kept.push_back(triangles[t]);
    }
  }
  kept.insert(kept.end(), added.begin(), added.end());
  triangles.swap(kept);
  return removed;
}
}

// Absorbs needles until none is left or no progress is made (splitting a
// neighbour that is itself nearly flat makes new needles), then drops the
// rest: no later stage may see a zero-area triangle (CGAL's intersection
// tests require non-degenerate ones). Dropping can open the surface, which
// the closedness check then reports.
std::size_t RemoveNeedles(
  const std::vector<Point3>& points, std::vector<Triangle>& triangles, std::size_t& splitNeighbours)
{
  std::size_t removed = 0;
  for (int round = 0; round < 8; ++round)
  {
    const std::size_t absorbed = AbsorbNeedles(points, triangles, splitNeighbours);
    removed += absorbed;
    if (absorbed == 0)
    {
      break;
    }
  }
  const std::size_t before = triangles.size();
  triangles.erase(std::remove_if(triangles.begin(), triangles.end(),
                    [&points](const Triangle& t) { return IsNeedle(points, t); }),
    triangles.end());
  return removed + (before - triangles.size());
}

std::size_t RemoveDuplicateTriangles(std::vector<Triangle>& triangles)
{
  std::vector<std::pair<Triangle, Index>> keys(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    Triangle k = triangles[t];
    std::sort(k.begin(), k.end());
    keys[t] = { k, static_cast<Index>(t) };
  }
  std::sort(keys.begin(), keys.end());
  std::vector<char> keep(triangles.size(), 1);
  std::size_t duplicates = 0;
  for (std::size_t i = 1; i < keys.size(); ++i)
  {
    if (keys[i].first == keys[i - 1].first)
    {
      keep[keys[i].second] = 0;
      ++duplicates;
    }
  }
  std::vector<Triangle> unique;
  unique.reserve(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (keep[t])
    {
      unique.push_back(triangles[t]);
    }
  }
  triangles.swap(unique);
  return duplicates;
}
}
