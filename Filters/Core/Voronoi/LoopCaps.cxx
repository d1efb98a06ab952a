// SPDX-License-Identifier: GPL-3.0-or-later
#include "Voronoi/LoopCaps.h"

#include "Geometry/Vec3.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace medialaxis
{
namespace repair
{
namespace
{
// A point of the segment from a to b strictly inside the surface, where both
// ends are outside but the segment crosses the surface (a wall thinner than
// the segment): the middles of ever shorter pieces that cross, shortest
// last (breadth first), 64 pieces at most.
bool InsideBetween(
  const Point3& a, const Point3& b, const TopologyRepairQueries& queries, Point3& inside)
{
  constexpr std::size_t maxPieces = 64;
  std::vector<std::pair<Point3, Point3>> pieces{ { a, b } };
  for (std::size_t k = 0; k < pieces.size() && k < maxPieces; ++k)
  {
    const auto [from, to] = pieces[k];
    const Point3 middle = 0.5 * (from + to);
    if (queries.Inside(middle))
    {
      inside = middle;
      return true;
    }
    for (const auto& [p, q] : { std::pair(from, middle), std::pair(middle, to) })
    {
      if (queries.Crosses(p, q))
      {
        pieces.emplace_back(p, q);
      }
    }
  }
  return false;
}

// Points of the first stretch of the segment from a (outside the surface)
// to b inside the surface, nearest a first: the inside ones of 64 steps
// along it, or where a step whose ends are outside crosses the surface (a
// wall thinner than a step), a point inside that wall. The hub of a cup lies
// just past a pocket's tip: farther stretches are not searched.
std::vector<Point3> InsidePointsAlong(
  const Point3& a, const Point3& b, const TopologyRepairQueries& queries)
{
  constexpr int steps = 64;
  std::vector<Point3> points;
  Point3 previous = a;
  for (int i = 1; i <= steps; ++i)
  {
    const Point3 p = a + (i / double(steps)) * (b - a);
    if (queries.Inside(p))
    {
      points.push_back(p);
    }
    else if (!points.empty())
    {
      break;
    }
    else if (queries.Crosses(previous, p))
    {
      Point3 wall;
      if (InsideBetween(previous, p, queries, wall))
      {
        points.push_back(wall);
        break;
      }
    }
    previous = p;
  }
  return points;
}

// The hub of a fan over `loop`: a point inside the surface from which every
// loop vertex (and, with `edgeMiddles`, the middle of every loop edge) is
// seen without crossing it. False if none of the candidates is.
bool FindHub(const MedialMesh& mesh, const std::vector<Index>& loop,
  const TopologyRepairQueries& queries, bool edgeMiddles, Point3& hub)
{
  Point3 centroid{ 0.0, 0.0, 0.0 };
  for (Index v : loop)
  {
    centroid = centroid + mesh.Centers[v];
  }
  centroid = (1.0 / static_cast<double>(loop.size())) * centroid;
  std::vector<Point3> targets;
  for (std::size_t k = 0; k < loop.size(); ++k)
  {
    targets.push_back(mesh.Centers[loop[k]]);
  }
  if (edgeMiddles)
  {
    for (std::size_t k = 0; k < loop.size(); ++k)
    {
      targets.push_back(0.5 * (targets[k] + targets[(k + 1) % loop.size()]));
    }
  }
  // Candidates that fail mostly fail on the target the last one failed on:
  // it is tested first (the answer does not depend on the order).
  std::size_t blocker = 0;
  auto seesAll = [&](const Point3& p)
  {
    if (!queries.Inside(p) || queries.Crosses(p, targets[blocker]))
    {
      return false;
    }
    for (std::size_t k = 0; k < targets.size(); ++k)
    {
      if (k != blocker && queries.Crosses(p, targets[k]))
      {
        blocker = k;
        return false;
      }
    }
    return true;
  };
  if (seesAll(centroid))
  {
    hub = centroid;
    return true;
  }
  for (Index v : loop)
  {
    for (double t : { 1.0 / 3.0, 2.0 / 3.0, 0.95 })
    {
      const Point3 p = centroid + t * (mesh.Centers[v] - centroid);
      if (seesAll(p))
      {
        hub = p;
        return true;
      }
    }
  }
  // A cup: round a pocket of outside space (a dent whose tip stops short of
  // the far side of a thin part; the loop's centroid is in it) every flat
  // disk on the loop crosses the pocket, but one bulging past the pocket's
  // tip does not. Its hub is a point inside the surface on a ray from the
  // centroid: along the loop's axis both ways, and tilted off it (a pocket
  // need not point along the axis), as far as 8 times the loop's reach; a
  // wall thinner than the sampling (past the tip) is found where a step of
  // the ray crosses the surface. (Loops whose centroid is inside keep flat
  // caps: a cup there would span a part of the solid, not a pocket.)
  if (edgeMiddles || queries.Inside(centroid))
  {
    return false;
  }
  double reach = 0.0;
  for (Index v : loop)
  {
    reach = std::max(reach, Norm(mesh.Centers[v] - centroid));
  }

  Point3 axis{ 0.0, 0.0, 0.0 };
  for (std::size_t k = 0; k < loop.size(); ++k)
  {
    axis = axis + Cross(targets[k] - centroid, targets[(k + 1) % loop.size()] - centroid);
  }
  if (!(Norm(axis) > 0.0) || !(reach > 0.0))
  {
    return false;
  }
  axis = (1.0 / Norm(axis)) * axis;
  const Point3 helper =
    std::fabs(axis[0]) < 0.6 ? Point3{ 1.0, 0.0, 0.0 } : Point3{ 0.0, 1.0, 0.0 };
  const Point3 across = (1.0 / Norm(Cross(axis, helper))) * Cross(axis, helper);
  const Point3 across2 = Cross(axis, across);
  for (double tilt : { 0.0, 15.0, 30.0, 45.0 })
  {
    const int azimuths = tilt == 0.0 ? 1 : 8;
    for (int k = 0; k < azimuths; ++k)
    {
      const double phi = 2.0 * Pi * k / azimuths, theta = tilt * Pi / 180.0;
      const Point3 off = std::cos(phi) * across + std::sin(phi) * across2;
      for (double side : { 1.0, -1.0 })
      {
        const Point3 direction = std::cos(theta) * (side * axis) + std::sin(theta) * off;
        for (const Point3& p :
          InsidePointsAlong(centroid, centroid + (8.0 * reach) * direction, queries))
        {
          if (seesAll(p))
          {
            hub = p;
            return true;
          }
        }
      }
    }
  }
  return false;
}

bool FindSplitCap(const MedialMesh& mesh, const std::vector<Index>& loop,
  const TopologyRepairQueries& queries, bool split, LoopCap& cap, int depth, int& hubSearches)
{
  if (hubSearches <= 0)
  {
    return false;
  }
  --hubSearches;
  Point3 hub;
  if (FindHub(mesh, loop, queries, split, hub))
  {
    cap.Hubs.push_back(hub);
    cap.Fans.push_back(loop);
    return true;
  }
  const std::size_t n = loop.size();
  if (depth <= 0 || n < 6)
  {
    return false;
  }
  // Chords across the middle of the loop, from a few starting vertices.
  for (std::size_t start : { std::size_t(0), n / 4, n / 8, 3 * n / 8 })
  {
    const std::size_t end = start + n / 2;
    if (queries.Crosses(mesh.Centers[loop[start]], mesh.Centers[loop[end]]))
    {
      continue;
    }
    const std::vector<Index> first(loop.begin() + static_cast<std::ptrdiff_t>(start),
      loop.begin() + static_cast<std::ptrdiff_t>(end + 1));
    std::vector<Index> second(loop.begin() + static_cast<std::ptrdiff_t>(end), loop.end());
    second.insert(
      second.end(), loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>(start + 1));
    const std::size_t hubs = cap.Hubs.size();
    if (FindSplitCap(mesh, first, queries, true, cap, depth - 1, hubSearches) &&
      FindSplitCap(mesh, second, queries, true, cap, depth - 1, hubSearches))
    {
      return true;
    }
    cap.Hubs.resize(hubs);
    cap.Fans.resize(hubs);
  }
  return false;
}
}

bool FindCap(const MedialMesh& mesh, const std::vector<Index>& loop,
  const TopologyRepairQueries& queries, LoopCap& cap, int depth)
{
  cap.Hubs.clear();
  cap.Fans.clear();
  // A hub search tests O(n^2) segments on a loop of n vertices: a loop round
  // a handle of the solid, which no cap fits, must not cost hundreds.
  int hubSearches = 64;
  return FindSplitCap(mesh, loop, queries, false, cap, depth, hubSearches);
}
}
}
